//! Maximum-likelihood fit of a lognormal fragility function to **censored** IDA data (truncated
//! incremental dynamic analysis, Baker 2015, §"Truncated IDA"; the Tobit likelihood).
//!
//! Each record of an IDA is run at increasing IMs. Its capacity `C_i` (the IM at which it first
//! exceeds the limit state) is then known in one of three ways ([`IdaRecord`]):
//!
//! * **exact** — it first exceeds between two runs: `C_i = x_i` (the interpolated crossing);
//! * **right-censored** — it never exceeds up to its largest run `r_i`: only `C_i > r_i`;
//! * **left-censored** — it exceeds already at its first (smallest) run `l_i`: only `C_i ≤ l_i`.
//!
//! With `ln C ~ N(μ, σ²)`, `μ = ln θ`, `σ = β`, the log-likelihood of `θ, β` is
//!
//! ```text
//! ℓ(θ, β) = Σ_exact [ ln φ((ln x_i − ln θ)/β) − ln β ]
//!         + Σ_right ln[ 1 − Φ((ln r_i − ln θ)/β) ]  +  Σ_left ln Φ((ln l_i − ln θ)/β),
//! ```
//!
//! the density of `ln x_i` for each exact observation and the probability of the censoring
//! interval for each censored record ([`censored_log_likelihood`]).
//!
//! # Which estimator
//! Data without a censored record keep the **method of moments** ([`super::moments`]; output
//! [`Method::MomentsIda`], bytes as before). With at least one censored record the maximum of `ℓ`
//! is used ([`Method::MleCensoredIda`]). Without censoring the maximum of `ℓ` is the closed-form
//! lognormal MLE: `ln θ̂` the mean of `ln x_i` and `β̂` their *population* standard deviation
//! (divisor `n`, where the method of moments divides by `n − 1`).
//!
//! # Optimiser
//! In `a = (μ − m)/σ`, `b = 1/σ` (`m` the mean of the exact `ln x_i`, for conditioning; Olsen
//! 1978), with `y = ln x − m` for every record,
//!
//! ```text
//! ℓ(a, b) = k ln b + Σ_exact ln φ(b y_i − a) + Σ_right ln Φ(a − b y_i) + Σ_left ln Φ(b y_i − a),
//! ```
//!
//! `k` the number of exact observations. This is **concave** (`ln b`, `−½(b y − a)²` and `ln Φ` of
//! an affine function are; Pratt 1981), strictly so when `k ≥ 1`, and is maximised by the same
//! Newton iteration with backtracking as the stripe fit ([`super::mle`]), started at the moments of
//! the exact observations; `b ≤ 0` is outside the domain (trial points there are rejected).
//!
//! # When the maximum is not finite (proof)
//! **No exact observation (`k = 0`).** `ℓ` is then exactly the binomial (probit) likelihood of one
//! run per record: a right-censored record is a run at IM `r_i` that did not exceed, a
//! left-censored one a run at `l_i` that did. It is fitted as stripe counts by [`super::mle`], whose
//! existence conditions apply: all right-censored → [`NoMle::NoExceedance`] (`θ → ∞`), all
//! left-censored → [`NoMle::AllExceeded`] (`θ → 0`), every right bound below every left bound →
//! [`NoMle::PerfectlySeparated`] (`β → 0`), one distinct IM → [`NoMle::TooFewPoints`], the
//! fraction not increasing → [`NoMle::NotIncreasing`].
//!
//! **At least one exact observation (`k ≥ 1`).** *Uniqueness:* the Hessian of `ℓ(a, b)` is at most
//! `−Σ_exact v_i v_iᵀ − (k/b²) e_b e_bᵀ`, `v_i = (−1, y_i)`; for a direction `w ≠ 0`, `wᵀHw ≤
//! −Σ (w_b y_i − w_a)² − k w_b²/b² < 0` (if `w_b = 0` the first sum is `k w_a² > 0`): strictly
//! concave, so at most one maximum, and Newton with line search finds it when it exists.
//! *Existence:* as `b → 0⁺`, `k ln b → −∞` while every other term is bounded above (`ln φ ≤
//! −½ ln 2π`, `ln Φ ≤ 0`), so `ℓ → −∞`.
//! (A) The exact `y_i` are not all equal: `Q(a, b) = Σ_exact (b y_i − a)²` is a positive-definite
//! quadratic form, `ℓ ≤ k ln b − ½ Q + const → −∞` as `|(a, b)| → ∞`. The upper level sets of
//! `ℓ` are compact in `b > 0`: a finite maximum exists.
//! (B) All exact `y_i` equal `y₀` (in particular `k = 1`). Write `a = b y₀ + d`:
//! `ℓ = k ln b − ½ k d² + Σ_right ln Φ(d − b (r_i − y₀)) + Σ_left ln Φ(b (l_i − y₀) − d) + const`.
//! (B1) Some right bound `r_j > y₀` (or some left bound `l_j < y₀`), `c = |r_j − y₀| > 0`: if
//! `|d| ≤ bc/2` that record's term is `≤ ln Φ(−bc/2) ≤ −b²c²/8` (`Φ(−x) ≤ ½ e^{−x²/2}`, `x ≥ 0`);
//! otherwise `−½ k d² < −k b² c²/8`; either way `ℓ ≤ k ln b − b²c²/8 + const → −∞` as
//! `b → ∞`, and `ℓ → −∞` as `|d| → ∞` for bounded `b`: a finite maximum exists.
//! (B2) Every right bound `r_i ≤ y₀` and every left bound `l_i ≥ y₀`: along `d = 0` each
//! censored term is `ln Φ(b c_i)` with `c_i ≥ 0`, at least `ln ½`, so
//! `ℓ ≥ k ln b − (#censored) ln 2 + const → +∞` as `b → ∞`: the likelihood grows without bound
//! as `β → 0` with `θ = e^{y₀}` — [`NoMle::NoDispersion`], no numbers. ∎
//!
//! A maximum whose `θ` or `β` is not a finite positive float is [`NoMle::OutOfRange`]; Newton not
//! reaching a stationary point is [`NoMle::NotConverged`]. Comparisons are made on `ln x`, the
//! values the optimiser sees.

use super::mle::{fit_counts, mills, newton};
use super::moments::fit_values;
use super::normal::{ln_cdf, ln_pdf};
use super::{Fit, FragilityError, Method, NoMle};
use crate::math::Real;

/// What the runs of one IDA record say about its capacity (the IM at first exceedance).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum IdaRecord {
    /// First exceeded at this IM (between two runs; the interpolated crossing): exact.
    Exceeded(Real),
    /// Never exceeded up to this IM, its largest run: the capacity is above it (right-censored).
    NotExceeded(Real),
    /// Exceeded already at this IM, its first (smallest) run: the capacity is at most this
    /// (left-censored).
    ExceededAtFirst(Real),
}

impl IdaRecord {
    /// The IM of the record (the crossing or the censoring bound).
    pub fn im(&self) -> Real {
        match *self {
            IdaRecord::Exceeded(x) | IdaRecord::NotExceeded(x) | IdaRecord::ExceededAtFirst(x) => x,
        }
    }
}

/// IDA outcomes with censoring bounds: one [`IdaRecord`] per record.
#[derive(Debug, Clone, PartialEq)]
pub struct CensoredIdaData {
    /// Per record, its exceedance IM or censoring bound (finite, > 0).
    pub records: Vec<IdaRecord>,
}

impl CensoredIdaData {
    /// Checks the data: at least one record; every IM finite and > 0 (named `records[i]`).
    pub fn validate(&self) -> Result<(), FragilityError> {
        if self.records.is_empty() {
            return Err(FragilityError::Empty { field: "records" });
        }
        let ims: Vec<Real> = self.records.iter().map(IdaRecord::im).collect();
        super::check_positive("records", &ims)
    }

    /// `(exact, right-censored, left-censored)` record counts.
    pub fn counts(&self) -> (usize, usize, usize) {
        counts(&self.records)
    }

    /// The estimator these data call for: [`Method::MomentsIda`] without a censored record,
    /// else [`Method::MleCensoredIda`] with the censored counts.
    pub fn method(&self) -> Method {
        let (_, right, left) = self.counts();
        if right + left == 0 {
            Method::MomentsIda
        } else {
            Method::MleCensoredIda { right, left }
        }
    }
}

fn counts(records: &[IdaRecord]) -> (usize, usize, usize) {
    records.iter().fold((0, 0, 0), |(e, r, l), x| match x {
        IdaRecord::Exceeded(_) => (e + 1, r, l),
        IdaRecord::NotExceeded(_) => (e, r + 1, l),
        IdaRecord::ExceededAtFirst(_) => (e, r, l + 1),
    })
}

/// Fits `θ, β` with the estimator the data call for ([`CensoredIdaData::method`]): the method of
/// moments without censoring, the censored MLE otherwise. Errors only for bad input.
pub fn fit_ida_censored(d: &CensoredIdaData) -> Result<(Method, Fit), FragilityError> {
    d.validate()?;
    let method = d.method();
    Ok((method, fit_by(method, &d.records)))
}

/// The censored maximum-likelihood fit (see the module documentation), whatever the censoring
/// (without censoring: the closed-form lognormal MLE). Errors only for bad input.
pub fn censored_mle(d: &CensoredIdaData) -> Result<Fit, FragilityError> {
    d.validate()?;
    Ok(fit_records(&d.records))
}

/// Fits `records` with `method` (no validation): [`Method::MomentsIda`] on the exceedance IMs
/// (a censored record then gives [`NoMle::Censored`]), anything else by the censored MLE.
pub(crate) fn fit_by(method: Method, records: &[IdaRecord]) -> Fit {
    match method {
        Method::MomentsIda => {
            let im: Vec<Option<Real>> = records
                .iter()
                .map(|r| match *r {
                    IdaRecord::Exceeded(x) => Some(x),
                    _ => None,
                })
                .collect();
            fit_values(&im)
        }
        _ => fit_records(records),
    }
}

/// The censored log-likelihood `ℓ(θ, β)` of the module documentation (with its constants).
pub fn censored_log_likelihood(records: &[IdaRecord], theta: Real, beta: Real) -> Real {
    let lt = theta.ln();
    records
        .iter()
        .map(|r| {
            let u = (r.im().ln() - lt) / beta;
            match r {
                IdaRecord::Exceeded(_) => ln_pdf(u) - beta.ln(),
                IdaRecord::NotExceeded(_) => ln_cdf(-u),
                IdaRecord::ExceededAtFirst(_) => ln_cdf(u),
            }
        })
        .sum()
}

/// A record for the optimiser: `y = ln x − m` and its kind (`0` exact, `+1` right-censored,
/// `−1` left-censored: the censored term is `ln Φ(s (a − b y))`).
type Point = (Real, Real);

/// The censored MLE of `records` (no validation).
pub(crate) fn fit_records(records: &[IdaRecord]) -> Fit {
    let pts: Vec<(Real, Real)> = records
        .iter()
        .map(|r| {
            let s = match r {
                IdaRecord::Exceeded(_) => 0.0,
                IdaRecord::NotExceeded(_) => 1.0,
                IdaRecord::ExceededAtFirst(_) => -1.0,
            };
            (r.im().ln(), s)
        })
        .collect();
    let exact: Vec<Real> = pts.iter().filter(|p| p.1 == 0.0).map(|p| p.0).collect();
    if exact.is_empty() {
        return fit_counts(&as_counts(records));
    }
    let y0 = exact[0];
    if exact.iter().all(|&y| y == y0)
        && pts
            .iter()
            .all(|&(y, s)| s == 0.0 || (s > 0.0 && y <= y0) || (s < 0.0 && y >= y0))
    {
        return Fit::NoFiniteMle(NoMle::NoDispersion);
    }
    let m = exact.iter().sum::<Real>() / exact.len() as Real;
    let pts: Vec<Point> = pts.iter().map(|&(y, s)| (y - m, s)).collect();
    let var = exact.iter().map(|y| (y - m) * (y - m)).sum::<Real>() / exact.len() as Real;
    let spread = if var > 0.0 {
        var.sqrt()
    } else {
        pts.iter().map(|p| p.0.abs()).fold(0.0, Real::max)
    };
    let start = (0.0, 1.0 / if spread > 0.0 { spread } else { 1.0 });
    match newton(|c| loglik(&pts, c), |c| derivs(&pts, c), start) {
        Some((a, b)) => {
            let (theta, beta) = ((m + a / b).exp(), 1.0 / b);
            if theta.is_finite() && theta > 0.0 && beta.is_finite() && beta > 0.0 {
                Fit::Lognormal { theta, beta }
            } else {
                Fit::NoFiniteMle(NoMle::OutOfRange)
            }
        }
        None => Fit::NoFiniteMle(NoMle::NotConverged),
    }
}

/// Only censored records: the stripe counts `(x, n, z)` of one run per record, equal IMs merged
/// (in order of first appearance).
fn as_counts(records: &[IdaRecord]) -> Vec<(Real, usize, usize)> {
    let mut out: Vec<(Real, usize, usize)> = Vec::new();
    for r in records {
        let (x, z) = (
            r.im(),
            usize::from(matches!(r, IdaRecord::ExceededAtFirst(_))),
        );
        match out.iter_mut().find(|c| c.0 == x) {
            Some(c) => {
                c.1 += 1;
                c.2 += z;
            }
            None => out.push((x, 1, z)),
        }
    }
    out
}

/// `ℓ(a, b)` (module documentation); NaN for `b ≤ 0`.
fn loglik(pts: &[Point], (a, b): (Real, Real)) -> Real {
    if b <= 0.0 {
        return Real::NAN;
    }
    let lb = b.ln();
    pts.iter()
        .map(|&(y, s)| {
            if s == 0.0 {
                ln_pdf(b * y - a) + lb
            } else {
                ln_cdf(s * (a - b * y))
            }
        })
        .sum()
}

/// Gradient and Hessian `[H_aa, H_ab, H_bb]` of `ℓ(a, b)`.
fn derivs(pts: &[Point], (a, b): (Real, Real)) -> ([Real; 2], [Real; 3]) {
    let (mut g, mut h) = ([0.0; 2], [0.0; 3]);
    for &(y, s) in pts {
        if s == 0.0 {
            // −½ e² + ln b, e = b y − a.
            let e = b * y - a;
            g[0] += e;
            g[1] += 1.0 / b - e * y;
            h[0] -= 1.0;
            h[1] += y;
            h[2] -= 1.0 / (b * b) + y * y;
        } else {
            // ln Φ(u), u = s (a − b y): du/da = s, du/db = −s y.
            let (lam, hu) = mills(s * (a - b * y));
            g[0] += lam * s;
            g[1] -= lam * s * y;
            h[0] += hu;
            h[1] -= hu * y;
            h[2] += hu * y * y;
        }
    }
    (g, h)
}
