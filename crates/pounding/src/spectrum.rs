//! Elastic response spectra of ground-motion records (issue 13).
//!
//! # The oscillator
//! A linear single-degree-of-freedom oscillator of natural period `T` (`ω = 2π/T`) and damping
//! ratio `ζ ∈ [0, 1)` (a fraction of critical) on the moving ground, in its displacement `u`
//! relative to the ground:
//!
//! ```text
//! ü + 2ζω u̇ + ω² u = −a_g(t),     u(t₀) = u̇(t₀) = 0,
//! ```
//!
//! with `a_g` the record, linear between its samples and zero after the last one (the
//! convention of [`crate::ground_motion::Record`]). The spectral ordinates are
//! `S_d = max_t |u(t)|` \[m\], the pseudo-velocity `S_pv = ω S_d` \[m/s\] and the
//! pseudo-acceleration `S_pa = ω² S_d`, reported in g (`/ 9.80665`).
//!
//! # Exact piecewise-linear solution
//! On a sample interval `τ ∈ [0, h]` the load is `a(τ) = a₀ + s τ` (`s = (a₁ − a₀)/h`) and the
//! motion is known in closed form (Nigam & Jennings 1969, "Calculation of response spectra from
//! strong-motion earthquake records", BSSA 59(2)):
//!
//! ```text
//! u(τ) = e^{−ζωτ} (c₁ cos ω_d τ + c₂ sin ω_d τ) + p₀ + p₁ τ,      ω_d = ω √(1 − ζ²),
//! p₁ = −s/ω²,   p₀ = −(a₀ + 2ζω p₁)/ω²,   c₁ = u₀ − p₀,   c₂ = (u̇₀ − p₁ + ζω c₁)/ω_d,
//! ```
//!
//! so the recurrence is exact for any `h` (no time-step error). The peak is taken over
//! **continuous time**: inside every interval the extrema of `u` are the zeros of `u̇(τ)`,
//! bracketed by sign changes of `u̇` on a sub-grid of spacing at most `T_d / 8` and found by
//! bisection on the closed form (a sampled peak can be several % low when `T` is a few samples
//! long). After the record ends the oscillator vibrates freely; that is followed for at least `2T`
//! (with damping the later free peaks are smaller; without, they repeat).
//!
//! # Precision and cost at extreme `ωh`
//! Where `ωh <` [`SERIES_BELOW`] (periods far longer than the sample interval) the form above
//! cancels catastrophically (`p₀ ≈ −a₀/ω²`); there the same motion is evaluated by power series
//! in `τ` (error a few ulps). An interval longer than 64 damped periods (a far-off sample time,
//! periods far below the sample interval) is searched on its first three and last periods only,
//! which provably hold its peak; the work per interval is bounded whatever `h/T`. Periods must
//! lie in [`PERIOD_RANGE`]. At periods far beyond the record's duration the mass drifts after
//! the record with its residual relative velocity `v_end = −∫a_g dt`, so `S_d ≈ |v_end|/ω`:
//! that is physics, but `v_end` is a sum computed to about `ε Σ|a_i| h_i` (`ε = 2⁻⁵³`), so
//! `S_d` is accurate only while `|v_end|` is well above that (El Centro: `v_end ≈ 9·10⁻⁶ m/s`,
//! rounding `~10⁻¹⁴ m/s`). Derivations, switch point and error bounds: the kernel's source
//! doc (`spectrum/oscillator.rs`).
//!
//! # Rotated pairs (RotD50, RotD100)
//! For two horizontal components `x`, `y` (Boore 2010, "Orientation-independent,
//! nongeometric-mean measures of seismic intensity from two horizontal components of motion",
//! BSSA 100(4)), the oscillator's response to the pair turned by `α` is
//! `u_α(t) = u_x(t) cos α + u_y(t) sin α` at every instant (the oscillator is linear). For
//! `α = 0°, 1°, …, 179°` the peak `max_t |u_α|` is taken over continuous time as above;
//! **RotD50** is the median of the 180 peaks (the mean of the two middle ones) and **RotD100**
//! the largest. The two records are put on the union of their sample times (both stay exactly
//! linear there); each is zero outside its own span, with the same jumps at its first and last
//! sample as alone, so the responses at 0° and 90° are those of `x` and `y` alone.

use crate::ground_motion::{G0, Record};
use crate::math::Real;
use oscillator::{Oscillator, Piece};
use recurrence::{Bounds, Lengths, Step, Tables};
use std::f64::consts::PI;
use thiserror::Error;

mod oscillator;
mod recurrence;
mod request;
pub use oscillator::SERIES_BELOW;
pub use request::{RequestError, SpectrumInputs, SpectrumRequest};

/// Bad spectrum input (a parameter out of range); the message names it.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SpectrumError {
    /// A parameter is out of range or not finite.
    #[error("invalid {name} = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// `damping` or `period`.
        name: String,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
}

/// One spectral ordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ordinate {
    /// Natural period `T` \[s\] as given.
    pub period: Real,
    /// Damping ratio `ζ` as given.
    pub damping: Real,
    /// Spectral displacement `S_d = max |u|` \[m\].
    pub sd: Real,
    /// Pseudo-spectral velocity `ω S_d` \[m/s\].
    pub psv: Real,
    /// Pseudo-spectral acceleration `ω² S_d / g` \[g\].
    pub psa_g: Real,
}

impl Ordinate {
    fn new(period: Real, damping: Real, sd: Real) -> Self {
        let w = 2.0 * PI / period;
        Ordinate {
            period,
            damping,
            sd,
            psv: w * sd,
            psa_g: w * w * sd / G0,
        }
    }
}

/// Shortest and longest period accepted \[s\]: `ω² = (2π/T)²` stays within `4·10^{±200}`, so
/// `ω²`, `a/ω²` and `ω² S_d` are normal floats (no overflow to `inf`, no loss to subnormals)
/// for any record value of normal size. Within it the results are accurate for every `ωh`
/// (module doc of the kernel: series form for small `ωh`, long intervals in closed form).
pub const PERIOD_RANGE: (Real, Real) = (1e-100, 1e100);

/// Checks `damping ∈ [0, 1)` and every period finite and within [`PERIOD_RANGE`].
pub fn check(damping: Real, periods: &[Real]) -> Result<(), SpectrumError> {
    if !(damping.is_finite() && (0.0..1.0).contains(&damping)) {
        return Err(SpectrumError::InvalidParameter {
            name: "damping".into(),
            value: damping,
            reason: "must lie in [0, 1) (a fraction of critical: 0.05 = 5 %)".into(),
        });
    }
    if let Some(&t) = periods.iter().find(|t| !(t.is_finite() && **t > 0.0)) {
        return Err(SpectrumError::InvalidParameter {
            name: "period".into(),
            value: t,
            reason: "must be finite and > 0 s".into(),
        });
    }
    let (lo, hi) = PERIOD_RANGE;
    if let Some(&t) = periods.iter().find(|t| !(lo..=hi).contains(*t)) {
        return Err(SpectrumError::InvalidParameter {
            name: "period".into(),
            value: t,
            reason: "must lie in [1e-100, 1e100] s (beyond it ω² = (2π/T)² leaves the range \
                     where ω², a/ω² and ω² S_d are normal floating-point numbers)"
                .into(),
        });
    }
    Ok(())
}

/// The plain (uncached) walk of [`peak_displacement_reference`]: the pieces of the oscillator's motion under the piecewise-linear load `(times, accel)`
/// (from rest at `times[0]`, the load zero after the last sample), followed by free vibration
/// for at least `2T`: `(piece, h)` per interval.
fn pieces(osc: &Oscillator, times: &[Real], accel: &[Real], period: Real) -> Vec<(Piece, Real)> {
    let n = times.len();
    let tail_h = period / 8.0;
    let mut out = Vec::with_capacity(n + 17);
    let (mut u, mut v) = (0.0, 0.0);
    let mut push = |a0: Real, a1: Real, h: Real, u: &mut Real, v: &mut Real| {
        let p = osc.piece(*u, *v, a0, a1, h);
        (*u, *v) = osc.at(&p, h);
        out.push((p, h));
    };
    for i in 0..n.saturating_sub(1) {
        push(
            accel[i],
            accel[i + 1],
            times[i + 1] - times[i],
            &mut u,
            &mut v,
        );
    }
    for _ in 0..17 {
        push(0.0, 0.0, tail_h, &mut u, &mut v);
    }
    out
}

/// `S_d = max_t |u(t)|` of the oscillator `(period, damping)` under the piecewise-linear
/// record `(times, accel)` (m/s², `times` strictly increasing), over continuous time and the
/// free vibration after the record (module doc). Parameters are not checked (see [`check`]).
/// Computed by the matrix recurrence of `spectrum/recurrence.rs` (rows per interval length,
/// bisection only where a rigorous bound says it can raise the peak); agrees with
/// [`peak_displacement_reference`] to rounding.
pub fn peak_displacement(times: &[Real], accel: &[Real], period: Real, damping: Real) -> Real {
    peak(&Lengths::new(times), accel, period, damping)
}

/// [`peak_displacement`] on the numbered intervals of a record.
fn peak(lengths: &Lengths, accel: &[Real], period: Real, damping: Real) -> Real {
    let osc = Oscillator::new(period, damping);
    let mut tables = Tables::new(osc, lengths, period);
    recurrence::Scan::peak(&mut tables, accel)
}

/// [`peak_displacement`] by the plain search: the kernel's piece form (Nigam–Jennings'
/// transient plus particular solution) on every interval, every bracketed zero of `u̇`
/// bisected. An independent formulation, kept for tests of the fast path.
#[doc(hidden)]
pub fn peak_displacement_reference(
    times: &[Real],
    accel: &[Real],
    period: Real,
    damping: Real,
) -> Real {
    let osc = Oscillator::new(period, damping);
    pieces(&osc, times, accel, period)
        .iter()
        .map(|(p, h)| osc.peak(p, *h))
        .fold(0.0, Real::max)
}

/// The spectrum of one record at `periods` with damping ratio `damping`.
pub fn spectrum(
    record: &Record,
    damping: Real,
    periods: &[Real],
) -> Result<Vec<Ordinate>, SpectrumError> {
    check(damping, periods)?;
    use rayon::prelude::*;
    let lengths = Lengths::new(record.times());
    // each period is independent: the same bits for any thread count
    Ok(periods
        .par_iter()
        .map(|&t| {
            let sd = peak(&lengths, record.values(), t, damping);
            Ordinate::new(t, damping, sd)
        })
        .collect())
}

/// RotD50 and RotD100 spectra of a horizontal pair (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct RotD {
    /// The median over the 180 rotation angles.
    pub rotd50: Vec<Ordinate>,
    /// The largest over the 180 rotation angles.
    pub rotd100: Vec<Ordinate>,
}

/// The union of the two records' sample times, and each record's loads `(a₀, a₁)` on its
/// intervals: the record's own (linear) values inside its span, zero outside it. At the first
/// and last sample the load jumps, as in the single-record spectrum (from rest at the first
/// sample, zero after the last), so the rotated response at 0° is `x`'s and at 90° `y`'s.
fn common_grid(x: &Record, y: &Record) -> (Vec<Real>, [Vec<(Real, Real)>; 2]) {
    let mut t: Vec<Real> = x.times().iter().chain(y.times()).copied().collect();
    t.sort_by(Real::total_cmp);
    t.dedup();
    let loads = |r: &Record| {
        let (first, last) = (r.times()[0], r.times()[r.times().len() - 1]);
        t.windows(2)
            .map(|w| {
                if w[0] >= first && w[1] <= last {
                    (r.accel(w[0]), r.accel(w[1]))
                } else {
                    (0.0, 0.0)
                }
            })
            .collect()
    };
    let l = [loads(x), loads(y)];
    (t, l)
}

/// The 180 peaks `max_t |u_x cos α + u_y sin α|`, `α = 0°, 1°, …, 179°`, for one oscillator
/// from the walks `sx`, `sy` of the two components. The intervals are visited in decreasing
/// order of a rigorous bound of `|(u_x, u_y)|` (plus rounding), and the rest skipped once the
/// bound falls below every angle's peak: the result is the same.
fn rotated_peaks(osc: &Oscillator, tables: &mut Tables, sx: &[Step], sy: &[Step]) -> Vec<Real> {
    let angles: Vec<(Real, Real)> = (0..180)
        .map(|d| (d as Real).to_radians().sin_cos())
        .map(|(s, c)| (c, s))
        .collect();
    let mut peaks: Vec<Real> = vec![0.0; 180];
    let mut order: Vec<(Real, usize)> = (0..sx.len())
        .map(|i| {
            let t = tables.get(i);
            let (bx, by) = (Bounds::new(osc, &sx[i], t), Bounds::new(osc, &sy[i], t));
            ((bx.u + bx.delta).hypot(by.u + by.delta), i)
        })
        .collect();
    order.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    for (b, i) in order {
        if b < peaks.iter().copied().fold(Real::INFINITY, Real::min) {
            break;
        }
        let t = tables.get(i);
        let h = t.h();
        let (px, py) = (sx[i].piece(osc, h), sy[i].piece(osc, h));
        if t.is_long() {
            // the kernel's first and last periods, every bracketed zero of u̇ bisected
            let sy_ = osc.stretches(&py, h);
            for (k, (pxs, hs)) in osc.stretches(&px, h).iter().enumerate() {
                let m = osc.subdivisions(*hs);
                let taus: Vec<Real> = (0..=m).map(|j| hs * j as Real / m as Real).collect();
                let ux: Vec<_> = taus.iter().map(|&t| osc.at(pxs, t)).collect();
                let uy: Vec<_> = taus.iter().map(|&t| osc.at(&sy_[k].0, t)).collect();
                let pieces = (pxs, &sy_[k].0);
                angle_peaks(osc, &angles, &taus, (&ux, &uy), pieces, None, &mut peaks);
            }
            continue;
        }
        let samples = |s: &Step| {
            let mut out = vec![(s.u0, s.v0)];
            out.extend(t.rows().iter().map(|r| r.apply(s)));
            out
        };
        let (ux, uy) = (samples(&sx[i]), samples(&sy[i]));
        let bounds = (Bounds::new(osc, &sx[i], t), Bounds::new(osc, &sy[i], t));
        let (bx, by) = (&bounds.0, &bounds.1);
        angle_peaks(
            osc,
            &angles,
            t.taus(),
            (&ux, &uy),
            (&px, &py),
            Some((bx, by)),
            &mut peaks,
        );
    }
    peaks
}

/// `(u, u̇)` at one instant.
type State = (Real, Real);

/// Raises `peaks[k]` to `max |c u_x + s u_y|` over one stretch for every angle `(c, s)` of
/// `angles`, from the samples `(u, u̇)` of both components at `taus` (`τ_0` included). A
/// bracketed zero of the rotated `u̇` is bisected on the combined piece unless the bound of
/// `spectrum/recurrence.rs` (both components' [`Bounds`] weighted by `|c|`, `|s|`) is below
/// the angle's peak so far; without bounds every one is bisected.
fn angle_peaks(
    osc: &Oscillator,
    angles: &[(Real, Real)],
    taus: &[Real],
    (ux, uy): (&[State], &[State]),
    (px, py): (&Piece, &Piece),
    bounds: Option<(&Bounds, &Bounds)>,
    peaks: &mut [Real],
) {
    for (k, &(c, s)) in angles.iter().enumerate() {
        let rot = bounds.map(|(bx, by)| bx.rotated(c, by, s));
        let at = |j: usize| (c * ux[j].0 + s * uy[j].0, c * ux[j].1 + s * uy[j].1);
        let (u, mut va) = at(0);
        let mut ua = u.abs();
        let mut best = peaks[k].max(ua);
        for j in 1..taus.len() {
            let (u, vb) = at(j);
            let ub = u.abs();
            best = best.max(ub);
            let (a, b) = (taus[j - 1], taus[j]);
            if va * vb < 0.0 && rot.is_none_or(|r| r.peak(ua, ub, b - a) >= best) {
                let p = Piece::combine(px, c, py, s);
                best = best.max(osc.extremum(&p, a, b, va).abs());
            }
            (ua, va) = (ub, vb);
        }
        peaks[k] = best;
    }
}

/// RotD50 and RotD100 of the pair `(x, y)` at `periods` with damping ratio `damping`.
pub fn rotd(
    x: &Record,
    y: &Record,
    damping: Real,
    periods: &[Real],
) -> Result<RotD, SpectrumError> {
    check(damping, periods)?;
    let (t, [lx, ly]) = common_grid(x, y);
    let lengths = Lengths::new(&t);
    use rayon::prelude::*;
    // each period is independent: the same bits for any thread count
    let (rotd50, rotd100) = periods
        .par_iter()
        .map(|&period| {
            let osc = Oscillator::new(period, damping);
            let mut tables = Tables::new(osc, &lengths, period);
            let mut walk = |a: &[(Real, Real)]| {
                let mut out = Vec::with_capacity(tables.len());
                recurrence::walk(&mut tables, a, |s, t| {
                    out.push(*s);
                    t.end(&osc, s)
                });
                out
            };
            let (sx, sy) = (walk(&lx), walk(&ly));
            let mut peaks = rotated_peaks(&osc, &mut tables, &sx, &sy);
            peaks.sort_by(Real::total_cmp);
            let median = 0.5 * (peaks[89] + peaks[90]);
            (
                Ordinate::new(period, damping, median),
                Ordinate::new(period, damping, peaks[179]),
            )
        })
        .unzip();
    Ok(RotD { rotd50, rotd100 })
}

/// The default periods of `pounding spectrum`: 0.01 s to 10 s, 100 values evenly spaced in
/// `log T`, each rounded to 4 significant digits.
pub fn default_periods() -> Vec<Real> {
    (0..100)
        .map(|i| {
            let t: Real = 10f64.powf(-2.0 + 3.0 * i as Real / 99.0);
            let e = t.log10().floor() as i32;
            let f = 10f64.powi(3 - e);
            (t * f).round() / f
        })
        .collect()
}

/// One curve of `spectrum.csv`: a record (or pair) and a component (`x`, `y`, `rotd50`,
/// `rotd100`).
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The record (a file name, `builtin:ELC180`, or `X+Y` for a pair).
    pub record: String,
    /// `x` (a single record or a pair's first file), `y`, `rotd50` or `rotd100`.
    pub component: String,
    /// The ordinates, one per period.
    pub ordinates: Vec<Ordinate>,
}

/// `spectrum.csv`: `record, component, period_s, damping, psa_g, psv_m_s, sd_m`, one row per
/// curve and period; numbers as shortest round-trip tokens (so `period_s` and `damping` read
/// back exactly as given); CSV quoting of names as needed.
pub fn spectrum_csv(curves: &[Curve]) -> String {
    use crate::output::{csv_field, float_token as f};
    let mut s = String::from("record,component,period_s,damping,psa_g,psv_m_s,sd_m\n");
    for c in curves {
        let (r, k) = (csv_field(&c.record), csv_field(&c.component));
        for o in &c.ordinates {
            s.push_str(&format!(
                "{r},{k},{},{},{},{},{}\n",
                f(o.period),
                f(o.damping),
                f(o.psa_g),
                f(o.psv),
                f(o.sd)
            ));
        }
    }
    s
}
