//! Hazard integration: the mean annual frequency (MAF) of exceeding a limit state from a site
//! hazard curve `λ(x)` (annual rate of `IM > x`) and a lognormal fragility `P(x) = Φ((ln x − ln θ)/β)`:
//!
//! ```text
//! λ_LS = ∫ P(x) |dλ(x)|.
//! ```
//!
//! * **Power law** `λ(x) = k0 x^(−k)`: the closed form `λ_LS = k0 θ^(−k) exp(k² β² / 2)`
//!   (e.g. Cornell et al. 2002, J. Struct. Eng. 128(4)).
//! * **Table** of `(x_i, λ_i)`, `x` strictly increasing, `λ` strictly decreasing and > 0:
//!   between two points `λ` is interpolated linearly in `ln x`–`ln λ` (a power law on each
//!   interval, `k_i = −ln(λ_{i+1}/λ_i) / ln(x_{i+1}/x_i)`), and the integral is taken **over the
//!   table's range only** (no extrapolation): on each interval `|dλ| = k_i λ(x) d(ln x)`,
//!   integrated by Gauss–Legendre quadrature (8 points on pieces of at most `β/4` in `ln x`).
//!   What the range leaves out is reported, not guessed: above the last IM the hazard's
//!   remaining rate `λ_n` contributes between `P(x_n) λ_n` and `λ_n` ([`Maf::upper_tail`]); below
//!   the first IM the contribution is at most `P(x_1)` times the rate of the events between 0
//!   and `x_1`, which the table does not give ([`Maf::p_first`] is `P(x_1)`).
//!
//! The deaggregation by IM is the integrand's density per unit `ln x`, `P(x) k(x) λ(x)`, whose
//! integral over `ln x` is `λ_LS` ([`deaggregation`]).

use super::normal::cdf;
use crate::math::Real;

/// A site hazard curve: the annual rate of exceeding each IM (the IM in g, as the fragility's).
#[derive(Debug, Clone, PartialEq)]
pub enum HazardCurve {
    /// `λ(x) = k0 x^(−k)`.
    PowerLaw {
        /// Rate at `x = 1` g \[1/yr\] (> 0).
        k0: Real,
        /// Slope in log-log (> 0).
        k: Real,
    },
    /// Points `(x_i, λ_i)`, log-log interpolated between them.
    Table {
        /// IMs \[g\], strictly increasing, > 0.
        im: Vec<Real>,
        /// Annual rates of exceedance \[1/yr\], strictly decreasing, > 0.
        rate: Vec<Real>,
    },
}

/// Why a hazard curve is not valid (the input readers name the file, key and line).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HazardError {
    /// A parameter or point out of range.
    #[error("{0}")]
    Invalid(String),
}

/// The MAF of one limit state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Maf {
    /// `λ_LS` \[1/yr\] (a table: over its range).
    pub rate: Real,
    /// A table: bounds of what the range leaves out above its last IM, `[P(x_n) λ_n, λ_n]`;
    /// `None` for a power law (integrated over all IMs).
    pub upper_tail: Option<(Real, Real)>,
    /// A table: `P(x_1)`, the fragility at the first IM (the part below it is at most this
    /// fraction of the rate of events between 0 and `x_1`); `None` for a power law.
    pub p_first: Option<Real>,
}

impl Maf {
    /// The return period `1 / λ_LS` \[yr\].
    pub fn return_period(&self) -> Real {
        1.0 / self.rate
    }
}

impl HazardCurve {
    /// Checks the parameters (power law) or points (table: at least two, IM > 0 strictly
    /// increasing, rates > 0 strictly decreasing, all finite); the message names the point.
    pub fn validate(&self) -> Result<(), HazardError> {
        let bad = |m: String| Err(HazardError::Invalid(m));
        match self {
            HazardCurve::PowerLaw { k0, k } => {
                if !(k0.is_finite() && *k0 > 0.0) {
                    return bad(format!("k0 = {k0} must be finite and > 0"));
                }
                if !(k.is_finite() && *k > 0.0) {
                    return bad(format!("k = {k} must be finite and > 0"));
                }
            }
            HazardCurve::Table { im, rate } => {
                if im.len() != rate.len() {
                    return bad(format!(
                        "{} IMs but {} rates: one rate per IM",
                        im.len(),
                        rate.len()
                    ));
                }
                if im.len() < 2 {
                    return bad("a hazard table needs at least two points".into());
                }
                for (i, (&x, &l)) in im.iter().zip(rate).enumerate() {
                    if !(x.is_finite() && x > 0.0) {
                        return bad(format!("point {}: IM {x} must be finite and > 0", i + 1));
                    }
                    if !(l.is_finite() && l > 0.0) {
                        return bad(format!("point {}: rate {l} must be finite and > 0", i + 1));
                    }
                    if i > 0 && x <= im[i - 1] {
                        return bad(format!(
                            "point {}: IM {x} does not increase (previous {})",
                            i + 1,
                            im[i - 1]
                        ));
                    }
                    if i > 0 && l >= rate[i - 1] {
                        return bad(format!(
                            "point {}: rate {l} does not decrease (previous {}); a hazard curve's \
                             rate of exceedance falls as the IM rises",
                            i + 1,
                            rate[i - 1]
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// `λ(x)` (a table: log-log interpolated; `None` outside its range).
    pub fn rate(&self, x: Real) -> Option<Real> {
        match self {
            HazardCurve::PowerLaw { k0, k } => Some(k0 * x.powf(-k)),
            HazardCurve::Table { im, rate } => {
                let i = segment(im, x)?;
                let kk = slope(im, rate, i);
                Some(rate[i] * (x / im[i]).powf(-kk))
            }
        }
    }

    /// The IM range to draw or deaggregate over: a table's range, or for a power law
    /// `θ exp(±4β)` around the given fragility's median.
    pub fn range(&self, theta: Real, beta: Real) -> (Real, Real) {
        match self {
            HazardCurve::PowerLaw { .. } => {
                let c = theta.ln() - self.k_mid() * beta * beta;
                ((c - 4.0 * beta).exp(), (c + 4.0 * beta).exp())
            }
            HazardCurve::Table { im, .. } => (im[0], im[im.len() - 1]),
        }
    }

    fn k_mid(&self) -> Real {
        match self {
            HazardCurve::PowerLaw { k, .. } => *k,
            HazardCurve::Table { .. } => 0.0,
        }
    }
}

/// The index `i` of the table interval `[x_i, x_{i+1}]` holding `x`.
fn segment(im: &[Real], x: Real) -> Option<usize> {
    if !(x >= im[0] && x <= im[im.len() - 1]) {
        return None;
    }
    Some(
        im.windows(2)
            .position(|w| x <= w[1])
            .unwrap_or(im.len() - 2),
    )
}

/// The log-log slope of interval `i`.
fn slope(im: &[Real], rate: &[Real], i: usize) -> Real {
    -(rate[i + 1] / rate[i]).ln() / (im[i + 1] / im[i]).ln()
}

/// 8-point Gauss–Legendre nodes and weights on [−1, 1].
const GL8: [(Real, Real); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// The MAF of the lognormal fragility `(θ, β)` under `hazard` (module documentation). The
/// hazard must be valid ([`HazardCurve::validate`]); `θ, β > 0`.
pub fn maf(hazard: &HazardCurve, theta: Real, beta: Real) -> Maf {
    match hazard {
        HazardCurve::PowerLaw { k0, k } => Maf {
            rate: k0 * theta.powf(-k) * (0.5 * k * k * beta * beta).exp(),
            upper_tail: None,
            p_first: None,
        },
        HazardCurve::Table { im, rate } => {
            let p = |x: Real| cdf((x.ln() - theta.ln()) / beta);
            let mut total = 0.0;
            for i in 0..im.len() - 1 {
                let kk = slope(im, rate, i);
                let (u0, u1) = (im[i].ln(), im[i + 1].ln());
                let pieces = ((u1 - u0) / (0.25 * beta)).ceil().max(1.0) as usize;
                let h = (u1 - u0) / pieces as Real;
                for j in 0..pieces {
                    let a = u0 + j as Real * h;
                    for (node, w) in GL8 {
                        let u = a + 0.5 * h * (node + 1.0);
                        let lam = rate[i] * (-kk * (u - u0)).exp();
                        total += 0.5 * h * w * p(u.exp()) * kk * lam;
                    }
                }
            }
            let n = im.len() - 1;
            Maf {
                rate: total,
                upper_tail: Some((p(im[n]) * rate[n], rate[n])),
                p_first: Some(p(im[0])),
            }
        }
    }
}

/// The deaggregation of the MAF by IM at `xs` (> 0): the integrand's density per unit `ln x`,
/// `P(x) k(x) λ(x)` (`k` the local log-log slope), 0 outside a table's range. Its integral over
/// `ln x` is [`maf`]'s rate.
pub fn deaggregation(hazard: &HazardCurve, theta: Real, beta: Real, xs: &[Real]) -> Vec<Real> {
    xs.iter()
        .map(|&x| {
            let p = cdf((x.ln() - theta.ln()) / beta);
            match hazard {
                HazardCurve::PowerLaw { k0, k } => p * k * k0 * x.powf(-k),
                HazardCurve::Table { im, rate } => match segment(im, x) {
                    Some(i) => {
                        let kk = slope(im, rate, i);
                        p * kk * rate[i] * (x / im[i]).powf(-kk)
                    }
                    None => 0.0,
                },
            }
        })
        .collect()
}

/// The MAF of a bootstrap's fit and its interval: the BCa interval of `λ_LS(θ_b, β_b)` over the
/// replicates ([`super::Bootstrap::interval_of`]). `None` without a fit.
pub fn maf_interval(
    hazard: &HazardCurve,
    boot: &super::Bootstrap,
) -> Option<(Maf, Option<(Real, Real)>)> {
    let (t, b) = boot.fit.params()?;
    let m = maf(hazard, t, b);
    Some((m, boot.interval_of(&|t, b| maf(hazard, t, b).rate)))
}
