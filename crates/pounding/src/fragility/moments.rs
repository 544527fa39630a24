//! Method-of-moments fit of a lognormal fragility function to IDA data.
//!
//! Each record `i` of an incremental dynamic analysis first exceeds the limit state at
//! `IM_i`; the fragility function is the distribution function of these capacities. Baker (2015),
//! eq. 2–3:
//!
//! ```text
//! ln θ = (1/n) Σ_i ln IM_i,        β = √( Σ_i (ln IM_i − ln θ)² / (n − 1) ).
//! ```
//!
//! **Censored records** (`None`: the record never exceeded within the IMs run) are not given a
//! number: dropping them would bias `θ` low and setting them to the largest IM run would bias it
//! too, so any censored record gives [`NoMle::Censored`] (all censored: [`NoMle::NoExceedance`]).
//! Give the censoring bounds ([`super::CensoredIdaData`]) to fit them by the censored likelihood
//! ([`super::censored`]), or use multiple-stripe data and [`super::fit_stripes`]. Fewer than two records give
//! [`NoMle::TooFewPoints`]; identical IMs give [`NoMle::NoDispersion`].

use super::{Fit, FragilityError, IdaData, NoMle};
use crate::math::Real;

/// Fits `θ, β` by the method of moments on `ln IM` (see the module documentation). Errors only for
/// bad input ([`IdaData::validate`]).
pub fn fit_ida(d: &IdaData) -> Result<Fit, FragilityError> {
    d.validate()?;
    Ok(fit_values(&d.im_at_exceedance))
}

/// The fit of IMs at exceedance (no validation).
pub(crate) fn fit_values(im: &[Option<Real>]) -> Fit {
    let censored = im.iter().filter(|x| x.is_none()).count();
    if censored == im.len() {
        return Fit::NoFiniteMle(NoMle::NoExceedance);
    }
    if censored > 0 {
        return Fit::NoFiniteMle(NoMle::Censored { count: censored });
    }
    if im.len() < 2 {
        return Fit::NoFiniteMle(NoMle::TooFewPoints);
    }
    if im.iter().all(|x| *x == im[0]) {
        return Fit::NoFiniteMle(NoMle::NoDispersion);
    }
    let n = im.len() as Real;
    let logs = im.iter().flatten().map(|x| x.ln());
    let mean = logs.clone().sum::<Real>() / n;
    let ss: Real = logs.map(|l| (l - mean) * (l - mean)).sum();
    let beta = (ss / (n - 1.0)).sqrt();
    if beta > 0.0 && beta.is_finite() {
        Fit::Lognormal {
            theta: mean.exp(),
            beta,
        }
    } else {
        Fit::NoFiniteMle(NoMle::NoDispersion)
    }
}
