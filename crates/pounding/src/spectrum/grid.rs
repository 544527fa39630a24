//! The fast path of [`super`]: the same numbers as the plain interval-by-interval search of
//! [`Oscillator::peak`], bit for bit, at a fraction of the cost.
//!
//! # Cached coefficients
//! Every transcendental value the kernel needs on an interval of length `h` — `e^{−ζωτ}`,
//! `sin ω_d τ`, `cos ω_d τ` at `τ = h` (the recurrence) and at the sub-grid points
//! `τ_j = h j / m` (the peak search) — depends on `h` only. A [`Grids`] cache keeps them per
//! exact `h` (its bits), computed by the very expressions of [`Oscillator::at`], so every
//! state and grid value is the same float as before; a record whose `h` changes (irregular
//! sampling, the free-vibration tail) just computes a new entry (the last [`CACHE`] distinct
//! `h` are kept). A uniformly sampled record has a few distinct `h` (`i·dt − (i−1)·dt` rounds
//! to a handful of floats).
//!
//! # Bisection only where it can raise the peak
//! The plain search takes, on every interval, `|u|` at the sub-grid points and, on each
//! sub-interval `[a, b]` where the computed `u̇` changes sign, `|u|` at the zero of `u̇` found by
//! bisection (60 evaluations of the closed form). `S_d` is the largest of all these numbers.
//! The fast path computes every grid value (cheap with cached coefficients), and their
//! maximum `L`. A bisection on `[a, b]` can only matter if its result can exceed `L`; it is
//! skipped when the rigorous bound
//!
//! ```text
//! |u(τ)| ≤ ½ (|u(a)| + |u(b)| + (b − a) V) + δ,    V = ω √(c₁² + c₂²) + |p₁| ≥ max |u̇|,
//! ```
//!
//! is below the largest value found so far (`≥ L`); the others run exactly as before.
//! *Proof.* For `τ ∈ [a, b]`, `|u(τ)| ≤ |u(a)| + (τ − a) V` and `|u(τ)| ≤ |u(b)| + (b − τ) V`;
//! the first bound increases in `τ`, the second decreases, so their minimum is at most their
//! common value at the crossing, `½ (|u(a)| + |u(b)| + (b − a) V)`. `V` bounds `|u̇|`: the
//! transient's velocity is `e^{−ζωτ}(V₁ cos ω_dτ + V₂ sin ω_dτ)` with
//! `V₁² + V₂² = ((ζω)² + ω_d²)(c₁² + c₂²) = ω²(c₁² + c₂²)`, and `e^{−ζωτ} ≤ 1`. The computed
//! values (grid ends, bisection result) differ from the exact closed form of the same piece by
//! a few hundred `ε` of `S = √(c₁² + c₂²) + |p₀| + |p₁| h` at most (each of `e`, `sin`, `cos`
//! within an ulp; the argument `ω_d τ ≤ 128π` rounded to `ε ω_d τ`); `δ = 10⁻⁹ (S + h V)`
//! covers that many times over. So a skipped bisection would have returned a number below the
//! final `S_d`: the maximum, hence every output byte, is unchanged. ∎
//!
//! A bisection sits near each extremum of `u`; the bound exceeds the end values by about
//! `ωh/2` of the amplitude, so only the extrema within a few % of the peak are bisected.
//! Series-form and long intervals (module doc of the kernel) take the plain search.

use super::oscillator::{Oscillator, Piece, Trig};
use crate::math::Real;

/// Number of distinct interval lengths kept by [`Grids`].
const CACHE: usize = 16;

/// How an interval of one length is searched.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    /// Series form: no transcendental coefficients, the plain search.
    Series,
    /// At least 64 damped periods: the plain search of its stretches.
    Long,
    /// The sub-grid search with cached coefficients.
    Plain,
}

/// The cached coefficients of intervals of length `h`.
#[derive(Debug, Clone)]
pub(super) struct Grid {
    h: Real,
    kind: Kind,
    /// `trig(h)` (Nigam–Jennings forms).
    end: Option<Trig>,
    /// `τ_j = h j / m`, `j = 0 … m` (plain).
    taus: Vec<Real>,
    /// `trig(τ_j)` (plain).
    trig: Vec<Trig>,
}

impl Grid {
    fn new(osc: &Oscillator, h: Real) -> Self {
        let kind = if osc.is_series(h) {
            Kind::Series
        } else if osc.is_long(h) {
            Kind::Long
        } else {
            Kind::Plain
        };
        let (mut taus, mut trig) = (Vec::new(), Vec::new());
        if kind == Kind::Plain {
            let m = osc.subdivisions(h);
            taus = (0..=m).map(|j| h * j as Real / m as Real).collect();
            trig = taus.iter().map(|&t| osc.trig(t)).collect();
        }
        Grid {
            h,
            kind,
            end: (kind != Kind::Series).then(|| osc.trig(h)),
            taus,
            trig,
        }
    }

    /// The interval length.
    pub(super) fn h(&self) -> Real {
        self.h
    }

    /// `true` for the cached sub-grid search (neither series form nor long).
    pub(super) fn is_plain(&self) -> bool {
        self.kind == Kind::Plain
    }

    /// `(u, u̇)` of `p` at the sub-grid points `h j / m` (plain grids), the same bits as
    /// `osc.at`.
    pub(super) fn samples(&self, osc: &Oscillator, p: &Piece) -> Vec<(Real, Real)> {
        self.taus
            .iter()
            .zip(&self.trig)
            .map(|(&t, tr)| osc.at_trig(p, t, tr))
            .collect()
    }

    /// `(u(h), u̇(h))` of `p`, the same bits as `osc.at(p, h)`.
    fn end(&self, osc: &Oscillator, p: &Piece) -> (Real, Real) {
        match &self.end {
            Some(t) => osc.at_trig(p, self.h, t),
            None => osc.at(p, self.h),
        }
    }
}

/// The last [`CACHE`] distinct interval lengths' [`Grid`]s of one oscillator.
pub(super) struct Grids {
    osc: Oscillator,
    list: Vec<Grid>,
    next: usize,
    last: usize,
}

impl Grids {
    pub(super) fn new(osc: Oscillator) -> Self {
        Grids {
            osc,
            list: Vec::with_capacity(CACHE),
            next: 0,
            last: 0,
        }
    }

    pub(super) fn get(&mut self, h: Real) -> &Grid {
        // the last hit first: consecutive intervals mostly share their length
        let last = self.last;
        if self
            .list
            .get(last)
            .is_some_and(|g| g.h.to_bits() == h.to_bits())
        {
            return &self.list[last];
        }
        if let Some(i) = self.list.iter().position(|g| g.h.to_bits() == h.to_bits()) {
            self.last = i;
            return &self.list[i];
        }
        let g = Grid::new(&self.osc, h);
        let i = if self.list.len() < CACHE {
            self.list.push(g);
            self.list.len() - 1
        } else {
            let i = self.next;
            self.list[i] = g;
            self.next = (i + 1) % CACHE;
            i
        };
        self.last = i;
        &self.list[i]
    }
}

/// Walks the oscillator through the piecewise-linear load `(times, accel)` from rest, then 17
/// free intervals of `T/8` (at least `2T`), calling `f(piece, grid)` per interval. The states
/// are those of `osc.at(p, h)`, bit for bit.
pub(super) fn walk(
    osc: &Oscillator,
    times: &[Real],
    accel: &[Real],
    period: Real,
    mut f: impl FnMut(&Piece, &Grid),
) {
    let mut grids = Grids::new(*osc);
    let (mut u, mut v) = (0.0, 0.0);
    let mut step = |a0: Real, a1: Real, h: Real| {
        let g = grids.get(h);
        let p = osc.piece(u, v, a0, a1, h);
        (u, v) = g.end(osc, &p);
        f(&p, g);
    };
    for i in 0..times.len().saturating_sub(1) {
        step(accel[i], accel[i + 1], times[i + 1] - times[i]);
    }
    for _ in 0..17 {
        step(0.0, 0.0, period / 8.0);
    }
}

/// A sub-interval whose bisection may raise the peak.
struct Candidate {
    p: Piece,
    a: Real,
    b: Real,
    va: Real,
    bound: Real,
}

/// The running `max |u|` of the fast path (module doc).
pub(super) struct Scan {
    best: Real,
    candidates: Vec<Candidate>,
}

impl Scan {
    pub(super) fn new() -> Self {
        Scan {
            best: 0.0,
            candidates: Vec::new(),
        }
    }

    /// Adds the interval `p` of length `g.h`.
    pub(super) fn add(&mut self, osc: &Oscillator, p: &Piece, g: &Grid) {
        if g.kind != Kind::Plain {
            self.best = self.best.max(osc.peak(p, g.h));
            return;
        }
        let mut vmax_margin = None;
        let (u0, mut va) = osc.at_trig(p, g.taus[0], &g.trig[0]);
        let mut ua = u0.abs();
        self.best = self.best.max(ua);
        for j in 1..g.taus.len() {
            let (a, b) = (g.taus[j - 1], g.taus[j]);
            let (u1, vb) = osc.at_trig(p, b, &g.trig[j]);
            let ub = u1.abs();
            self.best = self.best.max(ub);
            if va * vb < 0.0 {
                // V and δ (module doc), computed only where u̇ changes sign
                let (vmax, margin) = *vmax_margin.get_or_insert_with(|| {
                    let vmax = osc.speed_bound(p);
                    (vmax, 1e-9 * (p.bound(g.h) + g.h * vmax))
                });
                let bound = 0.5 * (ua + ub + (b - a) * vmax) + margin;
                if bound >= self.best {
                    self.candidates.push(Candidate {
                        p: *p,
                        a,
                        b,
                        va,
                        bound,
                    });
                }
            }
            (ua, va) = (ub, vb);
        }
    }

    /// The peak: the grid maximum raised by every bisection whose bound reaches it.
    pub(super) fn finish(mut self, osc: &Oscillator) -> Real {
        self.candidates.sort_by(|x, y| y.bound.total_cmp(&x.bound));
        let mut best = self.best;
        for c in &self.candidates {
            if c.bound < best {
                break;
            }
            best = best.max(osc.extremum(&c.p, c.a, c.b, c.va).abs());
        }
        best
    }
}
