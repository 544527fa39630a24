//! The fast path of [`super`]: the Nigam–Jennings recurrence in matrix form, and a peak search
//! that bisects only where a rigorous bound says the peak can rise.
//!
//! # The recurrence as a matrix
//! On an interval `τ ∈ [0, h]` with load `a(τ) = a₀ + (a₁ − a₀) τ/h` the exact motion is linear
//! in the start state and the two load samples (kernel module doc, `A`, `B`, `G`, `R` the
//! responses to `u₀ = 1`, `u̇₀ = 1`, a unit step and a unit ramp):
//!
//! ```text
//! u(τ) = A u₀ + B u̇₀ + (R/h − G) a₀ − (R/h) a₁,
//! u̇(τ) = −ω²B u₀ + (A − 2ζωB) u̇₀ + (G/h − B) a₀ − (G/h) a₁.
//! ```
//!
//! At `τ = h` this is Nigam & Jennings' own form `[u, u̇]ᵢ₊₁ = 𝐀 [u, u̇]ᵢ + 𝐁 [a]ᵢ,ᵢ₊₁`; at the
//! sub-grid points `τ_j = h j/m` it gives the samples of the peak search. The eight numbers of
//! each point (a [`Row`]) depend on `ω`, `ζ`, `h`, `τ` only: a [`Table`] holds them for one
//! interval length, computed once per period for each distinct `h` of the record, so a step
//! costs sixteen products and no transcendental function.
//!
//! **The rows are accurate to a few ulps.** With `x = ωτ < 1` the responses are summed as power
//! series (terms fall by `≤ 3/(k + 1)`: no cancellation); otherwise in closed form,
//! `A = e^{−ζωτ}(cos ω_dτ + (ζω/ω_d) sin ω_dτ)`, `B = e^{−ζωτ} sin ω_dτ / ω_d`,
//! `G = (1 − A)/ω²`, `R = (τ − B − 2ζωG)/ω²` (`R' = G`, as `B' = A − 2ζωB`), whose rounding is
//! a few ulps of the scales `1/ω²`, `τ/ω²` of the terms they multiply. The step then rounds
//! like any sum of four products. (The piece form of the kernel, kept as the reference, cancels
//! `~(ωh)⁻²` of its particular and transient parts instead.)
//!
//! # Bisection only where it can raise the peak
//! The peak search takes `|u|` at the sub-grid points and, on each sub-interval `[a, b]` where
//! the computed `u̇` changes sign, `|u|` at the zero of `u̇` found by bisection on the kernel's
//! closed form (32 halvings). A bisection is deferred, and skipped unless the bound
//!
//! ```text
//! |u(τ)| ≤ min( ½(|u(a)| + |u(b)| + d V),  max(|u(a)|, |u(b)|) + W d²/8 ) + δ,     d = b − a,
//! ```
//!
//! reaches the largest value found so far. *Proof.* `V ≥ max|u̇|` and `W ≥ max|ü|` on the
//! interval ([`Bounds`]). The peak of `|u|` on `[a, b]` is at an end or at a zero `τ*` of `u̇`.
//! From either end `|u|` grows at most by `V·(distance)`; the two linear bounds meet at most at
//! their mean. And at a zero `τ*`, `|u̇(τ)| ≤ W |τ* − τ|`, so `|u(τ*)| ≤ |u(a)| + W (τ* − a)²/2`
//! and `≤ |u(b)| + W (b − τ*)²/2`: whichever end is nearer gives at most `W d²/8` more. `δ`
//! covers the rounding of the sample values and of the bisection's own evaluations
//! ([`Bounds::delta`]). So a skipped bisection would have returned a number below the final
//! `S_d`: the maximum is that of bisecting everywhere. ∎ For a sinusoid of amplitude `A` the
//! quadratic bound exceeds the true extremum by `O((ωd)⁴) A` only, so almost only the extrema
//! that set the peak are bisected.
//!
//! Two cheaper tests come first, both upper bounds of the one above, so they only skip what it
//! would skip: a linear form `k · (|u₀|, |u̇₀|, α, |a₀|, |a₁ − a₀|)` with coefficients per table
//! bounding `W d²/8 + δ` ([`Bounds::filter`]), and, for intervals with several sub-grid points
//! (periods under 8 samples), the envelope `|c₁| + |c₂| + max(|p₀|, |p₀ + p₁h|) + δ` of the
//! whole interval ([`Table::envelope`]): below the peak so far, the interior is not sampled at
//! all (a short-period oscillator follows the load quasi-statically, far below its peak most
//! of the time).
//!
//! Intervals of at least 64 damped periods (the kernel's long form) take the kernel's own
//! search of their first and last periods.

use super::oscillator::{Oscillator, Piece};
use crate::math::Real;
use std::collections::HashMap;

/// More distinct interval lengths than this (an irregularly sampled record): tables are built
/// per interval instead of kept.
const MAX_TABLES: usize = 64;

/// Multiple of the rounding scale [`Bounds::delta`] adds to every bound: about `4.5·10⁶ ε`,
/// hundreds of times the rounding of any computed sample or closed-form value.
const ROUNDING: Real = 1e-9;

/// The state at the start of one interval and the load samples at its ends.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Step {
    /// Displacement `u₀` \[m\].
    pub u0: Real,
    /// Velocity `u̇₀` \[m/s\].
    pub v0: Real,
    /// Load at the start `a₀` \[m/s²\].
    pub a0: Real,
    /// Load at the end `a₁` \[m/s²\].
    pub a1: Real,
}

impl Step {
    /// The kernel's closed form of this interval.
    pub(super) fn piece(&self, osc: &Oscillator, h: Real) -> Piece {
        osc.piece(self.u0, self.v0, self.a0, self.a1, h)
    }
}

/// `(u, u̇)` at one `τ` as linear functions of `(u₀, u̇₀, a₀, a₁)` (module doc).
#[derive(Debug, Clone, Copy)]
pub(super) struct Row {
    u: [Real; 4],
    v: [Real; 4],
}

impl Row {
    fn new(osc: &Oscillator, tau: Real, h: Real) -> Self {
        let [a, b, g, r] = osc.unit_responses(tau);
        let (w, z) = (osc.omega(), osc.zeta());
        Row {
            u: [a, b, r / h - g, -r / h],
            v: [-w * w * b, a - 2.0 * z * w * b, g / h - b, -g / h],
        }
    }

    /// `(u(τ), u̇(τ))` from the step's start.
    #[inline(always)]
    pub(super) fn apply(&self, s: &Step) -> (Real, Real) {
        let (u, v) = (&self.u, &self.v);
        (
            (u[0] * s.u0 + u[1] * s.v0) + (u[2] * s.a0 + u[3] * s.a1),
            (v[0] * s.u0 + v[1] * s.v0) + (v[2] * s.a0 + v[3] * s.a1),
        )
    }
}

/// The rows of the intervals of one length `h`.
#[derive(Debug, Clone)]
pub(super) struct Table {
    h: Real,
    /// `τ_j = h j/m`, `j = 0 … m`, with `τ_m = h` exactly (empty for a long interval).
    taus: Vec<Real>,
    /// The rows at `τ_1 … τ_m` (empty for a long interval).
    rows: Vec<Row>,
    /// `true` if the kernel evaluates this `h` in its series form.
    series: bool,
    /// The quick filter's coefficients ([`Bounds::filter`]).
    filter: [Real; 5],
    /// `1/h`.
    inv_h: Real,
}

impl Table {
    pub(super) fn new(osc: &Oscillator, h: Real) -> Self {
        let (mut taus, mut rows) = (Vec::new(), Vec::new());
        if !osc.is_long(h) {
            let m = osc.subdivisions(h);
            taus = (0..=m).map(|j| h * j as Real / m as Real).collect();
            taus[m] = h;
            rows = taus[1..].iter().map(|&t| Row::new(osc, t, h)).collect();
        }
        let series = osc.is_series(h);
        let d_max = taus.windows(2).map(|w| w[1] - w[0]).fold(0.0, Real::max);
        Table {
            h,
            taus,
            rows,
            series,
            filter: Bounds::filter(osc, h, series, d_max),
            inv_h: 1.0 / h,
        }
    }

    /// The interval length.
    pub(super) fn h(&self) -> Real {
        self.h
    }

    /// `true` for an interval of at least 64 damped periods (no rows: the kernel's search).
    pub(super) fn is_long(&self) -> bool {
        self.rows.is_empty()
    }

    /// The sub-grid `τ_0 … τ_m`.
    pub(super) fn taus(&self) -> &[Real] {
        &self.taus
    }

    /// The rows at `τ_1 … τ_m` (empty for a long interval).
    pub(super) fn rows(&self) -> &[Row] {
        &self.rows
    }

    /// `k · x`: at least `W d²/8 + δ` of [`Bounds`] on each sub-interval of the step.
    #[inline(always)]
    fn excess(&self, s: &Step) -> Real {
        let (k, x) = (&self.filter, Bounds::sizes(s));
        (k[0] * x[0] + k[1] * x[1]) + (k[2] * x[2] + k[3] * x[3]) + k[4] * x[4]
    }

    /// `|c₁| + |c₂| + max(|p₀|, |p₀ + p₁h|) ≥ max |u|` over the interval: the Nigam–Jennings
    /// piece of the step (module doc of the kernel), computed with reciprocals (its rounding,
    /// a few ulps of these sizes, is inside `δ` of [`Bounds`]).
    #[inline(always)]
    fn envelope(&self, osc: &Oscillator, s: &Step) -> Real {
        let (w, z) = (osc.omega(), osc.zeta());
        let [iw2, iwd] = osc.reciprocals();
        let p1 = -(s.a1 - s.a0) * self.inv_h * iw2;
        let p0 = -(s.a0 + 2.0 * z * w * p1) * iw2;
        let c1 = s.u0 - p0;
        let c2 = (s.v0 - p1 + z * w * c1) * iwd;
        c1.abs() + c2.abs() + p0.abs().max((p0 + p1 * self.h).abs())
    }

    /// `(u(h), u̇(h))` from the step's start: the last row, or the kernel for a long interval.
    pub(super) fn end(&self, osc: &Oscillator, s: &Step) -> (Real, Real) {
        match self.rows.last() {
            Some(r) => r.apply(s),
            None => osc.at(&s.piece(osc, self.h), self.h),
        }
    }
}

/// The interval lengths of one record, each distinct one numbered (shared by every period).
#[derive(Debug, Clone)]
pub(super) struct Lengths {
    hs: Vec<Real>,
    index: Vec<u32>,
}

impl Lengths {
    /// The intervals of `times` (strictly increasing).
    pub(super) fn new(times: &[Real]) -> Self {
        let mut seen: HashMap<u64, u32> = HashMap::new();
        let mut hs = Vec::new();
        let index = times
            .windows(2)
            .map(|w| {
                let h = w[1] - w[0];
                *seen.entry(h.to_bits()).or_insert_with(|| {
                    hs.push(h);
                    (hs.len() - 1) as u32
                })
            })
            .collect();
        Lengths { hs, index }
    }

    /// Number of intervals.
    pub(super) fn len(&self) -> usize {
        self.index.len()
    }
}

/// The tables of one oscillator over one record's intervals, then the free-vibration tail.
pub(super) struct Tables<'a> {
    osc: Oscillator,
    lengths: &'a Lengths,
    /// One per distinct length (empty when there are more than [`MAX_TABLES`]).
    kept: Vec<Table>,
    scratch: Option<Table>,
    tail: Table,
}

/// Free intervals after the record: 17 of `T/8` (at least `2T`).
pub(super) const TAIL_STEPS: usize = 17;

impl<'a> Tables<'a> {
    pub(super) fn new(osc: Oscillator, lengths: &'a Lengths, period: Real) -> Self {
        let kept = if lengths.hs.len() <= MAX_TABLES {
            lengths.hs.iter().map(|&h| Table::new(&osc, h)).collect()
        } else {
            Vec::new()
        };
        Tables {
            osc,
            lengths,
            kept,
            scratch: None,
            tail: Table::new(&osc, period / 8.0),
        }
    }

    /// Number of intervals, the tail included.
    pub(super) fn len(&self) -> usize {
        self.lengths.len() + TAIL_STEPS
    }

    /// The table of the `k`-th distinct length.
    #[inline(always)]
    fn table(&mut self, k: u32) -> &Table {
        if self.kept.is_empty() {
            let h = self.lengths.hs[k as usize];
            return self.scratch.insert(Table::new(&self.osc, h));
        }
        &self.kept[k as usize]
    }

    /// The table of interval `i` (`i ≥` the record's intervals: the tail).
    pub(super) fn get(&mut self, i: usize) -> &Table {
        match self.lengths.index.get(i) {
            Some(&k) => self.table(k),
            None => &self.tail,
        }
    }
}

/// Walks the oscillator from rest through the loads `(a₀, a₁)` of each interval of `tables`
/// (the load linear in between; a load may jump from one interval to the next, as a record
/// does at its first and last sample) and the free tail: `f(step, table)` per interval returns
/// the state at its end.
pub(super) fn walk(
    tables: &mut Tables,
    loads: &[(Real, Real)],
    mut f: impl FnMut(&Step, &Table) -> (Real, Real),
) {
    let mut s = Step::default();
    let lengths = tables.lengths;
    for (&k, &(a0, a1)) in lengths.index.iter().zip(loads) {
        (s.a0, s.a1) = (a0, a1);
        (s.u0, s.v0) = f(&s, tables.table(k));
    }
    (s.a0, s.a1) = (0.0, 0.0);
    for _ in 0..TAIL_STEPS {
        (s.u0, s.v0) = f(&s, &tables.tail);
    }
}

/// Rigorous bounds of the exact motion on one interval from a step's start.
#[derive(Debug, Clone, Copy)]
pub(super) struct Bounds {
    /// `≥ max |u|`.
    pub u: Real,
    /// `≥ max |u̇|`.
    pub v: Real,
    /// `≥ max |ü|`.
    pub w: Real,
    /// The rounding allowance `δ` of the module doc.
    pub delta: Real,
}

impl Bounds {
    /// With `E = √(u̇₀² + ω²u₀²)` (the free energy `u̇² + ω²u²` does not grow) and
    /// `α = max(|a₀|, |a₁|)` (the forced part from rest: `|u| ≤ α τ²/2`, `|u̇| ≤ α τ`, as
    /// `|B| ≤ τ`, `|B'| ≤ 1`): `U = E/ω + α h²/2`, `V = E + α h`, `W = α + 2ζωV + ω²U`.
    /// `δ` is [`ROUNDING`] times the sizes the computed values are made of: `U`, `hV` and,
    /// in the Nigam–Jennings form, the piece's `|c₁| + |c₂| + |p₀| + |p₁| h` (bounded here
    /// without division: the same magnitudes as [`Oscillator::piece`]).
    pub(super) fn new(osc: &Oscillator, s: &Step, t: &Table) -> Self {
        let w = osc.omega();
        let e = (s.v0 * s.v0 + (w * s.u0) * (w * s.u0)).sqrt();
        Bounds::of(osc, t.h, t.series, e, Bounds::sizes(s))
    }

    /// `x = (|u₀|, |u̇₀|, α, |a₀|, |a₁ − a₀|)`, the sizes the bounds are linear in.
    #[inline(always)]
    fn sizes(s: &Step) -> [Real; 5] {
        let (a0, a1) = (s.a0.abs(), s.a1.abs());
        [s.u0.abs(), s.v0.abs(), a0.max(a1), a0, (s.a1 - s.a0).abs()]
    }

    /// The bounds from the energy `E` and the sizes `x` on an interval of length `h`
    /// (`series`: in the kernel's series form). Linear in `(E, x)` with non-negative
    /// coefficients.
    fn of(osc: &Oscillator, h: Real, series: bool, e: Real, x: [Real; 5]) -> Self {
        let (w, z) = (osc.omega(), osc.zeta());
        let [u0, v0, alpha, a0, da] = x;
        let [iw2, iwd] = osc.reciprocals();
        let u = e * (w * iw2) + alpha * h * h / 2.0;
        let v = e + alpha * h;
        let acc = alpha + 2.0 * z * w * v + w * w * u;
        let mut scale = u + h * v;
        if !series {
            let p1 = da / h * iw2;
            let p0 = (a0 + 2.0 * z * w * p1) * iw2;
            let c1 = u0 + p0;
            let c2 = (v0 + p1 + z * w * c1) * iwd;
            scale += c1 + c2 + p0 + p1 * h;
        }
        Bounds {
            u,
            v,
            w: acc,
            delta: ROUNDING * 4.0 * scale,
        }
    }

    /// The coefficients `k` of a quick filter: `W d²/8 + δ ≤ k · x` on every sub-interval
    /// (`d ≤ d_max`) of an interval of length `h`, with `E ≤ |u̇₀| + ω|u₀|` (so `k · x`
    /// is [`Bounds::of`] at that `E`: linear, `k_i` its value at the `i`-th unit vector).
    fn filter(osc: &Oscillator, h: Real, series: bool, d_max: Real) -> [Real; 5] {
        let mut k = [0.0; 5];
        for (i, k) in k.iter_mut().enumerate() {
            let mut x = [0.0; 5];
            x[i] = 1.0;
            let b = Bounds::of(osc, h, series, x[1] + osc.omega() * x[0], x);
            *k = b.w * d_max * d_max / 8.0 + b.delta;
        }
        k
    }

    /// The bound of `|u|` on `[a, b]` (module doc) from `|u|` at its ends, `d = b − a`.
    pub(super) fn peak(&self, ua: Real, ub: Real, d: Real) -> Real {
        let linear = 0.5 * (ua + ub + d * self.v);
        let quadratic = ua.max(ub) + self.w * d * d / 8.0;
        linear.min(quadratic) + self.delta
    }

    /// The same bounds with `V`, `W` lowered to the piece's own where smaller
    /// ([`Oscillator::transient_bounds`]: the particular part of a ramp has no acceleration,
    /// so a quasi-static response gets a tight `W`).
    pub(super) fn refined(&self, osc: &Oscillator, p: &Piece) -> Bounds {
        match osc.transient_bounds(p) {
            Some((v, w)) => Bounds {
                v: self.v.min(v),
                w: self.w.min(w),
                ..*self
            },
            None => *self,
        }
    }

    /// `c·self + s·other` for the rotated response `c u_x + s u_y` (`|c|`, `|s|` weights).
    pub(super) fn rotated(&self, c: Real, other: &Bounds, s: Real) -> Bounds {
        let (c, s) = (c.abs(), s.abs());
        Bounds {
            u: c * self.u + s * other.u,
            v: c * self.v + s * other.v,
            w: c * self.w + s * other.w,
            delta: self.delta + other.delta,
        }
    }
}

/// A sub-interval whose bisection may raise the peak.
struct Candidate {
    step: Step,
    h: Real,
    a: Real,
    b: Real,
    va: Real,
    bound: Real,
}

/// The running `max |u|` of one oscillator (module doc).
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

    /// Adds one interval of [`walk`] and returns the state at its end: the samples' maximum
    /// first, then, only where `u̇` changes sign, the bounds and candidates of the module doc.
    #[inline(always)]
    pub(super) fn add(&mut self, osc: &Oscillator, s: &Step, t: &Table) -> (Real, Real) {
        if t.is_long() {
            let p = s.piece(osc, t.h);
            self.best = self.best.max(osc.peak(&p, t.h));
            return osc.at(&p, t.h);
        }
        if let [row] = t.rows[..] {
            // one point (periods of at least 8 samples): no buffer
            let end = row.apply(s);
            let ub = end.0.abs();
            // (not f64::max: the samples are finite, and this is the hot path)
            if ub > self.best {
                self.best = ub;
            }
            if s.v0 * end.1 < 0.0 && s.u0.abs().max(ub) + t.excess(s) >= self.best {
                self.brackets(osc, s, t);
            }
            return end;
        }
        // several points (periods shorter than 8 samples): the end first; if the whole
        // interval's envelope cannot reach the peak so far, nothing inside can raise it
        let ex = t.excess(s);
        let mut end = t.rows[t.rows.len() - 1].apply(s);
        if end.0.abs() > self.best {
            self.best = end.0.abs();
        }
        if !t.series && t.envelope(osc, s) + ex < self.best {
            return end;
        }
        // else one pass for the maximum and the quick filter (with the running maximum, a
        // lower bound of the final one), the brackets recomputed only if one is open
        let (mut best, mut ua, mut va, mut open) = (self.best, s.u0.abs(), s.v0, false);
        for row in &t.rows {
            end = row.apply(s);
            let ub = end.0.abs();
            if ub > best {
                best = ub;
            }
            // (no short-circuit and no f64::max: branch-free, the samples are finite)
            let top = if ua > ub { ua } else { ub };
            open |= (va * end.1 < 0.0) & (top + ex >= best);
            (ua, va) = (ub, end.1);
        }
        self.best = best;
        if open {
            self.brackets(osc, s, t);
        }
        end
    }

    /// The sub-intervals of one interval where `u̇` changes sign (samples at `τ_1 … τ_m`,
    /// recomputed): candidates unless their bound is below the peak so far (module doc).
    #[inline(never)]
    fn brackets(&mut self, osc: &Oscillator, s: &Step, t: &Table) {
        let (mut bounds, mut refined) = (Bounds::new(osc, s, t), false);
        let (mut ua, mut va) = (s.u0.abs(), s.v0);
        for (j, row) in t.rows.iter().enumerate() {
            let (u, vb) = row.apply(s);
            let ub = u.abs();
            if va * vb < 0.0 {
                let (a, b) = (t.taus[j], t.taus[j + 1]);
                let mut bound = bounds.peak(ua, ub, b - a);
                if bound >= self.best && !refined {
                    // the piece only where the cheap bound fails: three divisions
                    (bounds, refined) = (bounds.refined(osc, &s.piece(osc, t.h)), true);
                    bound = bounds.peak(ua, ub, b - a);
                }
                if bound >= self.best {
                    self.candidates.push(Candidate {
                        step: *s,
                        h: t.h,
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

    /// `S_d` of the oscillator of `tables` under the record `accel` and the free tail: [`walk`]
    /// with [`Scan::add`] (written out, so the state stays in registers).
    pub(super) fn peak(tables: &mut Tables, accel: &[Real]) -> Real {
        let osc = tables.osc;
        let mut scan = Scan::new();
        let mut s = Step::default();
        let lengths = tables.lengths;
        for (&k, a) in lengths.index.iter().zip(accel.windows(2)) {
            (s.a0, s.a1) = (a[0], a[1]);
            (s.u0, s.v0) = scan.add(&osc, &s, tables.table(k));
        }
        (s.a0, s.a1) = (0.0, 0.0);
        for _ in 0..TAIL_STEPS {
            (s.u0, s.v0) = scan.add(&osc, &s, &tables.tail);
        }
        scan.finish(&osc)
    }

    /// The peak: the sample maximum raised by every bisection whose bound reaches it.
    pub(super) fn finish(mut self, osc: &Oscillator) -> Real {
        self.candidates.sort_by(|x, y| y.bound.total_cmp(&x.bound));
        let mut best = self.best;
        for c in &self.candidates {
            if c.bound < best {
                break;
            }
            let p = c.step.piece(osc, c.h);
            best = best.max(osc.extremum(&p, c.a, c.b, c.va).abs());
        }
        best
    }
}
