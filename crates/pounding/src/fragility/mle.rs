//! Maximum-likelihood fit of a lognormal fragility function to multiple-stripe counts.
//!
//! At stripe `j` (IM level `x_j`) `z_j` of `n_j` runs exceed the limit state. Treating the runs as
//! independent Bernoulli trials with probability `p_j = Φ((ln x_j − ln θ)/β)`, the log-likelihood
//! is (Baker 2015, eq. 11, without the constant binomial coefficients)
//!
//! ```text
//! ℓ(θ, β) = Σ_j [ z_j ln Φ(u_j) + (n_j − z_j) ln Φ(−u_j) ],      u_j = (ln x_j − ln θ)/β.
//! ```
//!
//! # Optimiser
//! With `t_j = ln x_j − m` (`m` the run-weighted mean of `ln x_j`, for conditioning) and the probit
//! parameters `c₀ = (m − ln θ)/β`, `c₁ = 1/β`, `u_j = c₀ + c₁ t_j` is linear in `(c₀, c₁)` and
//! `ℓ` is **concave** there (`ln Φ` is log-concave; Pratt 1981). Newton's method with a
//! backtracking (Armijo) line search therefore converges to the unique maximum whenever it is
//! finite, from any start; the start is the weighted least-squares line through
//! `Φ⁻¹((z_j + ½)/(n_j + 1))`. Derivatives use the inverse Mills ratio `λ(u) = φ(u)/Φ(u)`:
//!
//! ```text
//! ∂ℓ/∂u_j = z_j λ(u_j) − (n_j − z_j) λ(−u_j),    ∂²ℓ/∂u_j² = z_j h(u_j) + (n_j − z_j) h(−u_j),
//! h(u) = −λ(u) (u + λ(u)) ∈ (−1, 0),
//! ```
//!
//! with `u + λ(u)` from the continued fraction of the Mills ratio for `u < −5` (no cancellation).
//! Convergence: a full Newton step taken from a point whose decrement `gᵀH⁻¹g` is below
//! `10⁻¹⁰ (1 + |ℓ|)` (quadratic convergence leaves the error at rounding level); otherwise
//! [`NoMle::NotConverged`].
//!
//! # When the maximum is not finite
//! The probit MLE exists iff the data are not (quasi-)separated (Albert & Anderson 1984). In one
//! dimension, with stripes ordered by IM and only those with runs counted:
//! no exceedance → [`NoMle::NoExceedance`]; all exceeded → [`NoMle::AllExceeded`]; fewer than two
//! stripes → [`NoMle::TooFewPoints`]; 0 % below some stripe and 100 % above it (that stripe
//! anything) → [`NoMle::PerfectlySeparated`] (`β → 0`); the mirror image (100 % below, 0 % above),
//! or a finite maximum with `c₁ ≤ 0` (flat: `c₁ (ln x_max − ln x_min) ≤ 10⁻⁹`, e.g. equal
//! fractions at every stripe) → [`NoMle::NotIncreasing`]. A maximum whose `θ` or `β` is not
//! representable as a float (a curve practically flat over the data, its median at `e^{1600}`)
//! is [`NoMle::OutOfRange`].

use super::normal::{cdf, ln_cdf, ln_pdf, quantile};
use super::{Fit, FragilityError, NoMle, StripeData};
use crate::math::Real;

/// Fits `θ, β` to the stripe counts by maximum likelihood (see the module documentation).
/// Errors only for bad input ([`StripeData::validate`]).
pub fn fit_stripes(d: &StripeData) -> Result<Fit, FragilityError> {
    d.validate()?;
    Ok(fit_counts(&d.counts()))
}

/// The log-likelihood `ℓ(θ, β)` of counts `(x_j, n_j, z_j)` (as [`StripeData::counts`] gives them).
pub fn stripe_log_likelihood(counts: &[(Real, usize, usize)], theta: Real, beta: Real) -> Real {
    counts
        .iter()
        .map(|&(x, n, z)| {
            let u = (x.ln() - theta.ln()) / beta;
            term(u, n as Real, z as Real)
        })
        .sum()
}

fn term(u: Real, n: Real, z: Real) -> Real {
    let mut s = 0.0;
    if z > 0.0 {
        s += z * ln_cdf(u);
    }
    if n > z {
        s += (n - z) * ln_cdf(-u);
    }
    s
}

/// `(λ(u), h(u))`: `λ = φ/Φ` and `h = d²/du² ln Φ = −λ (u + λ)`.
pub(crate) fn mills(u: Real) -> (Real, Real) {
    if u < -5.0 {
        // λ(u) = w + d with w = −u and d = u + λ = 1/(w + 2/(w + 3/(w + …))).
        let w = -u;
        let mut t = w;
        for k in (2..=60).rev() {
            t = w + k as Real / t;
        }
        let d = 1.0 / t;
        let lam = w + d;
        (lam, -lam * d)
    } else {
        let lam = (ln_pdf(u) - ln_cdf(u)).exp();
        (lam, -lam * (u + lam))
    }
}

/// Stripes with runs, as `(t, n, z)` with `t = ln x`, sorted by IM.
fn stripes_with_runs(counts: &[(Real, usize, usize)]) -> Vec<(Real, Real, Real)> {
    let mut s: Vec<(Real, Real, Real)> = counts
        .iter()
        .filter(|c| c.1 > 0)
        .map(|&(x, n, z)| (x.ln(), n as Real, z as Real))
        .collect();
    s.sort_by(|a, b| a.0.total_cmp(&b.0));
    s
}

/// The reason the counts have no finite MLE, if they have none (checked before optimising).
fn no_mle_reason(s: &[(Real, Real, Real)]) -> Option<NoMle> {
    let n: Real = s.iter().map(|c| c.1).sum();
    let z: Real = s.iter().map(|c| c.2).sum();
    if z == 0.0 {
        return Some(NoMle::NoExceedance);
    }
    if z == n {
        return Some(NoMle::AllExceeded);
    }
    if s.len() < 2 {
        return Some(NoMle::TooFewPoints);
    }
    let k = s.iter().position(|c| c.2 > 0.0).unwrap_or(0);
    if s[k + 1..].iter().all(|c| c.2 == c.1) {
        return Some(NoMle::PerfectlySeparated);
    }
    let k = s.iter().position(|c| c.2 < c.1).unwrap_or(0);
    if s[k + 1..].iter().all(|c| c.2 == 0.0) {
        return Some(NoMle::NotIncreasing);
    }
    None
}

/// The fit of counts `(x_j, n_j, z_j)` (stripes with `n_j = 0` ignored); no validation.
pub(crate) fn fit_counts(counts: &[(Real, usize, usize)]) -> Fit {
    let s = stripes_with_runs(counts);
    if let Some(why) = no_mle_reason(&s) {
        return Fit::NoFiniteMle(why);
    }
    let n_tot: Real = s.iter().map(|c| c.1).sum();
    let m = s.iter().map(|c| c.0 * c.1).sum::<Real>() / n_tot;
    let pts: Vec<(Real, Real, Real)> = s.iter().map(|&(t, n, z)| (t - m, n, z)).collect();
    let range = pts[pts.len() - 1].0 - pts[0].0;
    match newton(|c| loglik(&pts, c), |c| derivs(&pts, c), start(&pts)) {
        // The probit changes by c₁·range across the stripes: below 1e-9 the fitted curve is flat
        // (equal fractions give c₁ = 0 exactly, rounding leaves ~1e-16).
        Some((c0, c1)) if c1 * range > 1e-9 => {
            let (theta, beta) = ((m - c0 / c1).exp(), 1.0 / c1);
            if theta.is_finite() && theta > 0.0 && beta.is_finite() && beta > 0.0 {
                Fit::Lognormal { theta, beta }
            } else {
                Fit::NoFiniteMle(NoMle::OutOfRange)
            }
        }
        Some(_) => Fit::NoFiniteMle(NoMle::NotIncreasing),
        None => Fit::NoFiniteMle(NoMle::NotConverged),
    }
}

/// Weighted least-squares line through the probits of the smoothed fractions.
fn start(pts: &[(Real, Real, Real)]) -> (Real, Real) {
    let (mut sw, mut st, mut sy, mut stt, mut sty) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for &(t, n, z) in pts {
        let y = quantile((z + 0.5) / (n + 1.0));
        sw += n;
        st += n * t;
        sy += n * y;
        stt += n * t * t;
        sty += n * t * y;
    }
    let var = stt - st * st / sw;
    let c1 = (sty - st * sy / sw) / var;
    let c1 = if c1.is_finite() && c1 > 0.0 { c1 } else { 1.0 };
    (sy / sw - c1 * st / sw, c1)
}

fn loglik(pts: &[(Real, Real, Real)], c: (Real, Real)) -> Real {
    pts.iter().map(|&(t, n, z)| term(c.0 + c.1 * t, n, z)).sum()
}

/// Gradient `g` and Hessian `h = [H₀₀, H₀₁, H₁₁]` of the stripe `ℓ(c₀, c₁)`.
fn derivs(pts: &[(Real, Real, Real)], c: (Real, Real)) -> ([Real; 2], [Real; 3]) {
    let (mut g, mut h) = ([0.0; 2], [0.0; 3]);
    for &(t, n, z) in pts {
        let u = c.0 + c.1 * t;
        let (lp, hp) = mills(u);
        let (lm, hm) = mills(-u);
        let gu = z * lp - (n - z) * lm;
        let hu = z * hp + (n - z) * hm;
        g[0] += gu;
        g[1] += gu * t;
        h[0] += hu;
        h[1] += hu * t;
        h[2] += hu * t * t;
    }
    (g, h)
}

/// Newton's method with backtracking (Armijo) on a concave function of two parameters:
/// `loglik(c)` its value (non-finite outside its domain: such trial points are rejected),
/// `derivs(c)` its gradient and Hessian `[H₀₀, H₀₁, H₁₁]` (see the module documentation for the
/// convergence test). `None` when it does not converge or the Hessian is not negative definite.
pub(crate) fn newton<L, D>(loglik: L, derivs: D, mut c: (Real, Real)) -> Option<(Real, Real)>
where
    L: Fn((Real, Real)) -> Real,
    D: Fn((Real, Real)) -> ([Real; 2], [Real; 3]),
{
    let mut l = loglik(c);
    for _ in 0..200 {
        let (g, h) = derivs(c);
        let det = h[0] * h[2] - h[1] * h[1];
        if !(h[0] < 0.0 && det > 0.0 && det.is_finite()) {
            return None;
        }
        // Δ = −H⁻¹ g.
        let d = (
            (-h[2] * g[0] + h[1] * g[1]) / det,
            (h[1] * g[0] - h[0] * g[1]) / det,
        );
        let dec = g[0] * d.0 + g[1] * d.1;
        if !dec.is_finite() {
            return None;
        }
        if dec <= 1e-24 * (1.0 + l.abs()) {
            return Some(c);
        }
        let mut a = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let trial = (c.0 + a * d.0, c.1 + a * d.1);
            let lt = loglik(trial);
            if lt.is_finite() && lt >= l + 1e-4 * a * dec {
                c = trial;
                l = lt;
                accepted = true;
                break;
            }
            if a == 1.0 && dec <= 1e-10 * (1.0 + l.abs()) {
                // Within rounding of the top (ℓ cannot resolve the increase of a tiny step).
                return Some(trial);
            }
            a *= 0.5;
        }
        if accepted && a == 1.0 && dec <= 1e-10 * (1.0 + l.abs()) {
            // A full Newton step from within 1e-10 of the top: quadratic convergence puts the
            // new point at rounding level.
            return Some(c);
        }
        if !accepted {
            // No ascent along the Newton direction: converged only if already at the top
            // within rounding.
            return (dec <= 1e-8 * (1.0 + l.abs())).then_some(c);
        }
    }
    None
}

/// `P(exceed | x)` for a lognormal fragility `(θ, β)`.
pub fn probability(x: Real, theta: Real, beta: Real) -> Real {
    cdf((x.ln() - theta.ln()) / beta)
}
