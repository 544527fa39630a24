//! The oscillator kernel of [`super`]: the exact motion on one interval of a piecewise-linear
//! load, in two algebraically equal forms, and its peak over continuous time.
//!
//! # Two forms of one closed form
//! On `τ ∈ [0, h]` under `a(τ) = a₀ + s τ` from `(u₀, u̇₀)` the motion is
//!
//! ```text
//! u(τ) = u₀ A(τ) + u̇₀ B(τ) − a₀ G(τ) − s R(τ),
//! ```
//!
//! with `A` (free response to `u = 1`), `B` (to `u̇ = 1`), `G = ∫B = (1 − A)/ω²` (response to a
//! unit step) and `R = ∫G` (to a unit ramp); `A' = −ω² B`, `B' = A − 2ζω B`, `G' = B`, `R' = G`.
//!
//! * **Nigam–Jennings form** (`ω h ≥` [`SERIES_BELOW`]): `u = e^{−ζωτ}(c₁ cos ω_d τ + c₂ sin ω_d τ)
//!   + p₀ + p₁ τ` (module doc of [`super`]). Its particular part `p₀ ≈ −a₀/ω²`, `p₁ = −s/ω²`
//!   cancels against `c₁`, `c₂`: the rounding error of `u` is about `ε (|a₀| + |s| h)/ω²`
//!   (`ε = 2⁻⁵³`), i.e. `ε · 2/(ωh)²` relative to the load's own displacement `|a| h²/2` over a
//!   step. At the switch `ωh = 10⁻³` that is `≤ 2·10⁶ ε ≈ 4.4·10⁻¹⁰`; it falls as `(ωh)⁻²` above.
//!   (Before the switch existed, `T = 10¹⁰ s` gave `S_d = 1.4·10¹⁴ m` for El Centro.)
//! * **Series form** (`ω h <` [`SERIES_BELOW`]): `B`, `G`, `R` by their Taylor series in `τ`, whose
//!   coefficients follow from the ODE `y⁽ᵏ⁺²⁾ = −2ζω y⁽ᵏ⁺¹⁾ − ω² y⁽ᵏ⁾`; with `x = ωτ < 10⁻³` the
//!   terms `t_k` fall by at least `(2x + x²)/(k + 1) < 2.1·10⁻³` each, so the sums are the first
//!   term to within `0.3 %` and carry no cancellation: relative error a few `ε`. `A = 1 − ω² G`
//!   (no cancellation: `|ω² G| ≤ x²/2`). The combination `u₀ A + u̇₀ B − a₀ G − s R` adds
//!   physical contributions (no `1/ω²` terms): error a few `ε` of their sizes.
//!
//! The switch point `10⁻³` keeps every interval of ordinary records (`dt ≥ 0.005 s`,
//! `T ≤ 20 s`: `ωh ≥ 1.6·10⁻³`) on the Nigam–Jennings form, so their spectra are unchanged.
//!
//! # Long intervals in closed form
//! An interval much longer than the damped period `T_d = 2π/ω_d` (a far-off sample time, a huge
//! `--record-dt`, a period far below the sample interval) is not walked period by period.
//! In the Nigam–Jennings form `u = x + l` with `x(τ + T_d) = ρ x(τ)`, `ρ = e^{−ζωT_d} ∈ (0, 1]`,
//! and `l` linear. **If `h ≥ 4 T_d`, `max_{[0,h]} |u|` is attained on `[0, 3T_d] ∪ [h − T_d, h]`.**
//! Proof (for `max u`; `min u` is `−max(−u)`, the same form): write `τ = τ' + k T_d`,
//! `τ' ∈ [0, T_d)`, `k = 0 … K(τ')` with `τ' + K T_d ∈ (h − T_d, h]`. Then
//! `u = f(k) = ρᵏ x(τ') + l(τ') + k p₁ T_d`.
//! (i) `x(τ') ≥ 0`: `f` is convex in `k`, its maximum over `0 … K` is at `k = 0` or `k = K`.
//! (ii) `x(τ') < 0`, `p₁ ≥ 0`: `f` increases, maximum at `k = K`.
//! (iii) `x(τ') < 0`, `p₁ < 0`, so `f(k) ≤ l(τ')`. Let `r = √(c₁² + c₂²)`; the first period has a
//! point `τ_m` with `x(τ_m) = e^{−ζωτ_m} r ≥ ρ r` and `l(τ_m) ≥ l(τ') − |p₁| T_d`. If
//! `ρ r ≥ |p₁| T_d`, `u(τ_m) ≥ l(τ') ≥ f(k)`: the first period dominates. Otherwise `f` is concave
//! with `f'(k) = |x(τ')| ρᵏ λ − |p₁| T_d` (`λ = ζωT_d = −ln ρ`), zero at
//! `k* < ln(r λ/(|p₁| T_d))/λ < ln(λ/ρ)/λ = 1 + ln λ/λ ≤ 1 + 1/e`, so the integer maximum is at
//! `k ≤ 2`: in `[0, 3T_d)`. ∎ (With `ζ = 0`, `λ = 0` and case (iii) ends in the first period.)
//! The last period is evaluated as a piece re-based at `h − T_d` (its transient rotated by
//! `ω_d (h − T_d)` and scaled by `e^{−ζω(h − T_d)}`), so the sub-grid stays fine even where
//! `h − T_d` and `h` are one float apart. The work per interval is then at most 32 evaluations,
//! whatever `h/T`.

use crate::math::Real;
use std::f64::consts::PI;

/// `ω h` below which an interval is evaluated in the series form (module doc).
pub const SERIES_BELOW: Real = 1e-3;

/// An interval at least this many damped periods long is evaluated on its first three and last
/// periods only (module doc; the proof needs 4, a wider margin keeps ordinary intervals on the
/// plain sub-grid).
const LONG_PERIODS: Real = 64.0;

/// The oscillator `ω`, `ζ`, `ω_d`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Oscillator {
    w: Real,
    z: Real,
    wd: Real,
    /// `[1/ω², 1/ω_d]` (for bounds only).
    inv: [Real; 2],
}

/// The closed-form motion on one interval `[0, h]`, linear in its four numbers, so responses
/// combine component-wise. Nigam–Jennings: `[c₁, c₂, p₀, p₁]`; series: `[u₀, u̇₀, a₀, s]`.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Piece {
    k: [Real; 4],
    series: bool,
}

impl Piece {
    /// `ca a + cb b` (two pieces of the same interval).
    pub(super) fn combine(a: &Piece, ca: Real, b: &Piece, cb: Real) -> Piece {
        let mut k = [0.0; 4];
        for (i, k) in k.iter_mut().enumerate() {
            *k = ca * a.k[i] + cb * b.k[i];
        }
        Piece {
            k,
            series: a.series,
        }
    }
}

/// `Σ t_k` of the Taylor series of the solution of `y'' + 2ζω y' + ω² y = 0` continued from the
/// term `t_j = first` (the terms before it zero), at `x = ωτ`: `t_{k+2} = −(2ζx t_{k+1} +
/// x² t_k/(k+1))/(k+2)`.
fn series(x: Real, z: Real, j: usize, first: Real) -> Real {
    let (mut prev, mut cur, mut sum) = (0.0, first, first);
    let mut k = j;
    while k < j + 40 {
        // t_{k+1} from t_k (cur) and t_{k-1} (prev): the recurrence at index k - 1
        let next = -(2.0 * z * x * cur + x * x * prev / k as Real) / (k + 1) as Real;
        sum += next;
        // two small terms in a row: every later one is smaller still (a zero term alone is
        // not the end: with ζ = 0 every other term vanishes)
        if next.abs() + cur.abs() <= 1e-18 * sum.abs() {
            break;
        }
        (prev, cur) = (cur, next);
        k += 1;
    }
    sum
}

impl Oscillator {
    pub(super) fn new(period: Real, damping: Real) -> Self {
        let w = 2.0 * PI / period;
        let wd = w * (1.0 - damping * damping).sqrt();
        Oscillator {
            w,
            z: damping,
            wd,
            inv: [1.0 / (w * w), 1.0 / wd],
        }
    }

    /// The damped period `T_d = 2π/ω_d`.
    fn td(&self) -> Real {
        2.0 * PI / self.wd
    }

    /// The interval starting at `(u₀, u̇₀)` under `a₀ → a₁` over `h`.
    pub(super) fn piece(&self, u0: Real, v0: Real, a0: Real, a1: Real, h: Real) -> Piece {
        let (w, z, wd) = (self.w, self.z, self.wd);
        let s = if h > 0.0 { (a1 - a0) / h } else { 0.0 };
        if w * h < SERIES_BELOW {
            return Piece {
                k: [u0, v0, a0, s],
                series: true,
            };
        }
        let p1 = -s / (w * w);
        let p0 = -(a0 + 2.0 * z * w * p1) / (w * w);
        let c1 = u0 - p0;
        let c2 = (v0 - p1 + z * w * c1) / wd;
        Piece {
            k: [c1, c2, p0, p1],
            series: false,
        }
    }

    /// `(u(τ), u̇(τ))` of `p`.
    pub(super) fn at(&self, p: &Piece, tau: Real) -> (Real, Real) {
        let (w, z) = (self.w, self.z);
        if p.series {
            let [u0, v0, a0, s] = p.k;
            let x = w * tau;
            let b = series(x, z, 1, tau);
            let g = series(x, z, 2, tau * tau / 2.0);
            let r = series(x, z, 3, tau * tau * tau / 6.0);
            let a = 1.0 - w * w * g;
            let u = u0 * a + v0 * b - a0 * g - s * r;
            let v = -u0 * w * w * b + v0 * (a - 2.0 * z * w * b) - a0 * b - s * g;
            return (u, v);
        }
        let (w, z, wd) = (self.w, self.z, self.wd);
        let [c1, c2, p0, p1] = p.k;
        let e = (-z * w * tau).exp();
        let (sn, cs) = (wd * tau).sin_cos();
        let u = e * (c1 * cs + c2 * sn) + p0 + p1 * tau;
        let v = e * ((-z * w * c1 + wd * c2) * cs + (-z * w * c2 - wd * c1) * sn) + p1;
        (u, v)
    }

    /// `ω` \[rad/s\].
    pub(super) fn omega(&self) -> Real {
        self.w
    }

    /// `ζ`.
    pub(super) fn zeta(&self) -> Real {
        self.z
    }

    /// `[1/ω², 1/ω_d]`.
    pub(super) fn reciprocals(&self) -> [Real; 2] {
        self.inv
    }

    /// The unit responses `[A, B, G, R]` at `τ` (module doc): power series while `ωτ < 1`
    /// (terms fall by `≤ (2ωτ + (ωτ)²)/(k + 1) < 3/(k + 1)`, no cancellation), else
    /// `A = e^{−ζωτ}(cos ω_dτ + (ζω/ω_d) sin ω_dτ)`, `B = e^{−ζωτ} sin ω_dτ / ω_d`,
    /// `G = (1 − A)/ω²`, `R = (τ − B − 2ζωG)/ω²` (as `∫A = B + 2ζωG` from `B' = A − 2ζωB`),
    /// each within a few ulps of its scale (`1/ω`, `1/ω²`, `τ/ω²`).
    pub(super) fn unit_responses(&self, tau: Real) -> [Real; 4] {
        let (w, z, wd) = (self.w, self.z, self.wd);
        let x = w * tau;
        if x < 1.0 {
            let b = series(x, z, 1, tau);
            let g = series(x, z, 2, tau * tau / 2.0);
            let r = series(x, z, 3, tau * tau * tau / 6.0);
            return [1.0 - w * w * g, b, g, r];
        }
        let e = (-z * w * tau).exp();
        let (sn, cs) = (wd * tau).sin_cos();
        let a = e * (cs + z * w / wd * sn);
        let b = e * sn / wd;
        let g = (1.0 - a) / (w * w);
        let r = (tau - b - 2.0 * z * w * g) / (w * w);
        [a, b, g, r]
    }

    /// `true` if intervals of length `h` are evaluated in the series form.
    pub(super) fn is_series(&self, h: Real) -> bool {
        self.w * h < SERIES_BELOW
    }

    /// `true` if an interval of length `h` is searched on its first and last periods only.
    pub(super) fn is_long(&self, h: Real) -> bool {
        h >= LONG_PERIODS * self.td()
    }

    /// `(V, W)` with `V ≥ max |u̇|` and `W ≥ max |ü|` over `τ ≥ 0` of a Nigam–Jennings piece
    /// (`None` in the series form): the transient `e^{−ζωτ}(c₁ cos ω_dτ + c₂ sin ω_dτ)` has
    /// velocity and acceleration of the same form with amplitudes `ω r` and `ω² r`,
    /// `r = √(c₁² + c₂²)` (as `(ζω)² + ω_d² = ω²`), and the particular part `p₀ + p₁τ` adds
    /// `p₁` to the velocity and nothing to the acceleration.
    pub(super) fn transient_bounds(&self, p: &Piece) -> Option<(Real, Real)> {
        if p.series {
            return None;
        }
        let r = p.k[0].hypot(p.k[1]);
        Some((self.w * r + p.k[3].abs(), self.w * self.w * r))
    }

    /// The stretches of `p` on `[0, h]` that hold its peak: `[(p, h)]`, or for an interval of
    /// at least [`LONG_PERIODS`] damped periods its first three periods and its last period
    /// re-based at `h − T_d` (module doc).
    pub(super) fn stretches(&self, p: &Piece, h: Real) -> Vec<(Piece, Real)> {
        let td = self.td();
        if p.series || !self.is_long(h) {
            return vec![(*p, h)];
        }
        let t0 = h - td;
        let [c1, c2, p0, p1] = p.k;
        let e = (-self.z * self.w * t0).exp();
        let (sn, cs) = (self.wd * t0).sin_cos();
        // e^{−ζω(t0+σ)}(c₁ cos ω_d(t0+σ) + c₂ sin ω_d(t0+σ)) = e^{−ζωσ}(c₁' cos ω_dσ + c₂' sin ω_dσ)
        let last = Piece {
            k: [
                e * (c1 * cs + c2 * sn),
                e * (c2 * cs - c1 * sn),
                p0 + p1 * t0,
                p1,
            ],
            series: false,
        };
        vec![(*p, 3.0 * td), (last, td)]
    }

    /// Number of sub-intervals of `[0, h]` so that each is at most `T_d / 8` long.
    pub(super) fn subdivisions(&self, h: Real) -> usize {
        ((h / (self.td() / 8.0)).ceil() as usize).max(1)
    }

    /// `max |u|` of `p` over `[0, h]`: on each of its [`Oscillator::stretches`], the end values
    /// and every interior zero of `u̇` bracketed on the sub-grid, by bisection.
    pub(super) fn peak(&self, p: &Piece, h: Real) -> Real {
        self.stretches(p, h)
            .iter()
            .map(|(p, h)| self.peak_on(p, *h))
            .fold(0.0, Real::max)
    }

    fn peak_on(&self, p: &Piece, h: Real) -> Real {
        let m = self.subdivisions(h);
        let (u0, mut v0) = self.at(p, 0.0);
        let (mut best, mut t0) = (u0.abs(), 0.0);
        for j in 1..=m {
            let t1 = h * j as Real / m as Real;
            let (u1, v1) = self.at(p, t1);
            best = best.max(u1.abs());
            if v0 * v1 < 0.0 {
                best = best.max(self.extremum(p, t0, t1, v0).abs());
            }
            (t0, v0) = (t1, v1);
        }
        best
    }

    /// `u` at the zero of `u̇` in `(a, b)` (`u̇(a)` has sign of `va`, `u̇(b)` the opposite), by
    /// 32 halvings: the midpoint of the last bracket is within `d/2³³` of the zero `τ*`, so
    /// `|u(mid) − u(τ*)| ≤ W (d/2³³)²/2 = W d² 4⁻³³/2` (`u̇(τ*) = 0`, `W ≥ |ü|`). On the
    /// sub-grid (`d ≤ T_d/8`, so `W d² ≤ (ωd)² r ≤ 0.62 r` with `r` the transient's amplitude;
    /// in the series form `W d²` is a few times the piece's own size) that is below `10⁻¹⁹` of the
    /// piece's size: the rounding of `u` itself.
    pub(super) fn extremum(&self, p: &Piece, mut a: Real, mut b: Real, va: Real) -> Real {
        for _ in 0..32 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            if self.at(p, m).1 * va > 0.0 {
                a = m;
            } else {
                b = m;
            }
        }
        self.at(p, 0.5 * (a + b)).0
    }
}
