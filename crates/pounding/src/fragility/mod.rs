//! Fragility functions `P(exceed | IM = x) = Φ((ln x − ln θ)/β)` fitted to the outcomes of
//! dynamic analyses (issue 13), after Baker (2015), "Efficient analytical fragility function fitting
//! using dynamic structural analysis", *Earthquake Spectra* 31(1):579–599.
//!
//! A fragility function is a lognormal distribution function of the intensity measure `x`, with
//! median `θ` (same unit as `x`) and logarithmic standard deviation (dispersion) `β`:
//!
//! ```text
//! P(exceed | IM = x) = Φ( (ln x − ln θ) / β ),      θ > 0,  β > 0.
//! ```
//!
//! Two kinds of data are fitted:
//!
//! * **Multiple-stripe analysis** ([`StripeData`], [`fit_stripes`]): every record scaled to each IM
//!   level `x_j` ("stripe"); `z_j` of the `n_j` runs at stripe `j` exceed the limit state. The fit
//!   maximises the binomial likelihood (Baker 2015, eq. 11), see [`mle`].
//! * **Incremental dynamic analysis** ([`IdaData`], [`fit_ida`]): the IM at which each record
//!   first exceeds the limit state; fitted by the method of moments on `ln IM` (Baker 2015, eq. 2–3),
//!   see [`moments`].
//! * **Truncated IDA** ([`CensoredIdaData`], [`fit_ida_censored`]): IDA records that never exceed
//!   within the IMs run (right-censored) or exceed already at the first (left-censored), fitted by
//!   the maximum likelihood of the censored lognormal, see [`censored`] (data without a censored
//!   record keep the method of moments).
//!
//! Data without a finite maximum-likelihood estimate (no exceedance at all, exceedance everywhere,
//! perfectly separated stripes, too few stripes, …) give [`Fit::NoFiniteMle`] with the reason,
//! never numbers. Bad input (a non-positive IM level, ragged rows, no data) is a
//! [`FragilityError`] naming the field. Confidence intervals come from a bootstrap over records
//! ([`bootstrap`]): seeded, and the same for any thread count.

pub mod bootstrap;
pub mod censored;
pub mod hazard;
pub mod mle;
pub mod moments;
pub mod normal;
pub mod write;

pub use bootstrap::{
    BandPoint, Bootstrap, BootstrapSettings, bootstrap_ida, bootstrap_ida_censored,
    bootstrap_stripes,
};
pub use censored::{
    CensoredIdaData, IdaRecord, censored_log_likelihood, censored_mle, fit_ida_censored,
};
pub use mle::{fit_stripes, stripe_log_likelihood};
pub use moments::fit_ida;
pub use write::{
    FragilityRow, Method, StudyColumns, fragility_csv, fragility_csv_study, fragility_json,
    fragility_json_study,
};

use crate::math::Real;
use crate::output::float_token;

/// Outcomes of a multiple-stripe analysis: every record run at every IM level.
#[derive(Debug, Clone, PartialEq)]
pub struct StripeData {
    /// `im[j]`: the IM level of stripe `j` (finite, > 0, all distinct; any order).
    pub im: Vec<Real>,
    /// `exceeded[r][j]`: whether record `r` run at stripe `j` exceeded the limit state; `None` when
    /// the run is missing or not trustworthy (excluded from the counts). One row per record, each
    /// as long as `im`.
    pub exceeded: Vec<Vec<Option<bool>>>,
}

impl StripeData {
    /// Checks the data: at least one stripe and one record, every IM level finite, > 0 and
    /// distinct, every row as long as `im`.
    pub fn validate(&self) -> Result<(), FragilityError> {
        if self.im.is_empty() {
            return Err(FragilityError::Empty { field: "im" });
        }
        if self.exceeded.is_empty() {
            return Err(FragilityError::Empty { field: "exceeded" });
        }
        check_positive("im", &self.im)?;
        for (i, a) in self.im.iter().enumerate() {
            if let Some(k) = self.im[..i].iter().position(|b| b == a) {
                return Err(FragilityError::DuplicateIm {
                    first: k,
                    second: i,
                    value: *a,
                });
            }
        }
        for (r, row) in self.exceeded.iter().enumerate() {
            if row.len() != self.im.len() {
                return Err(FragilityError::Ragged {
                    record: r,
                    len: row.len(),
                    expected: self.im.len(),
                });
            }
        }
        Ok(())
    }

    /// Per stripe, in the order of `im`: `(x_j, n_j, z_j)`, the IM level, the number of runs with an
    /// outcome (`Some`) and how many of them exceeded. Rows shorter than `im` count only the
    /// stripes they have (call [`StripeData::validate`] first to refuse them).
    pub fn counts(&self) -> Vec<(Real, usize, usize)> {
        let mut out: Vec<(Real, usize, usize)> = self.im.iter().map(|&x| (x, 0, 0)).collect();
        for row in &self.exceeded {
            for (c, o) in out.iter_mut().zip(row) {
                if let Some(e) = o {
                    c.1 += 1;
                    c.2 += usize::from(*e);
                }
            }
        }
        out
    }

    /// Number of runs with an outcome (`Some`), over all records and stripes.
    pub fn runs(&self) -> usize {
        self.exceeded
            .iter()
            .flatten()
            .filter(|o| o.is_some())
            .count()
    }
}

/// Outcomes of an incremental dynamic analysis: per record, the IM at first exceedance.
#[derive(Debug, Clone, PartialEq)]
pub struct IdaData {
    /// Per record, the IM at which the limit state was first exceeded (finite, > 0); `None` when
    /// the record did not exceed it within the IM levels run (a censored record).
    pub im_at_exceedance: Vec<Option<Real>>,
}

impl IdaData {
    /// Checks the data: at least one record; every IM given finite and > 0.
    pub fn validate(&self) -> Result<(), FragilityError> {
        if self.im_at_exceedance.is_empty() {
            return Err(FragilityError::Empty {
                field: "im_at_exceedance",
            });
        }
        for (index, x) in self.im_at_exceedance.iter().enumerate() {
            if let Some(x) = x
                && !(x.is_finite() && *x > 0.0)
            {
                return Err(FragilityError::BadIm {
                    field: "im_at_exceedance",
                    index,
                    value: *x,
                });
            }
        }
        Ok(())
    }
}

/// The result of a fit: a lognormal fragility function, or the reason there is none.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fit {
    /// `P(exceed | x) = Φ((ln x − ln θ)/β)`.
    Lognormal {
        /// Median `θ` (the IM unit of the data).
        theta: Real,
        /// Dispersion `β` (logarithmic standard deviation).
        beta: Real,
    },
    /// The data have no finite estimate (or the optimiser did not converge): no numbers.
    NoFiniteMle(NoMle),
}

impl Fit {
    /// `(θ, β)` of a lognormal fit, `None` otherwise.
    pub fn params(&self) -> Option<(Real, Real)> {
        match *self {
            Fit::Lognormal { theta, beta } => Some((theta, beta)),
            Fit::NoFiniteMle(_) => None,
        }
    }

    /// The status word written in outputs: `ok` or the [`NoMle`] reason.
    pub fn status(&self) -> &'static str {
        match self {
            Fit::Lognormal { .. } => "ok",
            Fit::NoFiniteMle(why) => why.as_str(),
        }
    }

    /// `P(exceed | IM = x)` of a lognormal fit (`None` for no fit).
    pub fn probability(&self, x: Real) -> Option<Real> {
        self.params()
            .map(|(theta, beta)| normal::cdf((x.ln() - theta.ln()) / beta))
    }
}

/// Why data have no finite estimate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NoMle {
    /// No run (record) exceeded the limit state: `θ → ∞`.
    NoExceedance,
    /// Every run exceeded the limit state: `θ → 0`.
    AllExceeded,
    /// 0 % of the runs exceed below some IM and 100 % above it (at most one stripe in between with
    /// a fraction strictly between): the likelihood grows without bound as `β → 0`.
    PerfectlySeparated,
    /// The exceedance fraction does not increase with the IM (the unconstrained maximum has
    /// `1/β ≤ 0`, or the stripes are 100 % below some IM and 0 % above): no fragility function fits.
    NotIncreasing,
    /// Fewer than two stripes with runs (stripes), or fewer than two records (IDA): two parameters
    /// cannot be estimated.
    TooFewPoints,
    /// IDA records that never exceeded the limit state within the IMs run (censored), given to
    /// [`fit_ida`] without their bound: the method of moments needs the IM of every record and is
    /// refused rather than biased. With their bounds ([`CensoredIdaData`]) they are fitted by the
    /// censored MLE instead, as `pounding fragility` does.
    Censored {
        /// How many records are censored.
        count: usize,
    },
    /// IDA records that exceeded the limit state already at the first (smallest) IM run
    /// (left-censored): their IM at first exceedance is only an upper bound of the crossing, so
    /// the method of moments would be biased high in θ and low in β. No longer produced by the
    /// workflow, which fits such records as left-censored ([`censored`]); kept for compatibility.
    ExceededAtFirst {
        /// How many records exceeded already at the first IM.
        count: usize,
    },
    /// Every record exceeded at the same IM (IDA; with censored records: and every censoring
    /// bound on their side, see [`censored`]): `β = 0`.
    NoDispersion,
    /// The maximum is finite but its `θ` or `β` is beyond the floating-point range: the fitted
    /// curve is practically flat over the data (e.g. fractions 1/4, 1/4, 2/4, 0/1, 1/5 rising by
    /// a probit of 0.001 over the stripes, `θ ≈ e^{1600}`).
    OutOfRange,
    /// The optimiser did not reach a stationary point (should not happen: the probit likelihood
    /// is concave; reported rather than returned as numbers).
    NotConverged,
}

impl NoMle {
    /// The status word (`no_exceedance`, `all_exceeded`, `perfectly_separated`, `not_increasing`,
    /// `too_few_points`, `censored`, `exceeded_at_first`, `no_dispersion`, `out_of_range`,
    /// `not_converged`).
    pub fn as_str(&self) -> &'static str {
        match self {
            NoMle::NoExceedance => "no_exceedance",
            NoMle::AllExceeded => "all_exceeded",
            NoMle::PerfectlySeparated => "perfectly_separated",
            NoMle::NotIncreasing => "not_increasing",
            NoMle::TooFewPoints => "too_few_points",
            NoMle::Censored { .. } => "censored",
            NoMle::ExceededAtFirst { .. } => "exceeded_at_first",
            NoMle::NoDispersion => "no_dispersion",
            NoMle::OutOfRange => "out_of_range",
            NoMle::NotConverged => "not_converged",
        }
    }
}

/// Bad input to a fit or a bootstrap (numerical outcomes are [`Fit::NoFiniteMle`], not errors).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FragilityError {
    /// A list that must not be empty is.
    #[error("fragility data: `{field}` is empty")]
    Empty {
        /// The field.
        field: &'static str,
    },
    /// An IM value that is not finite and positive.
    #[error("fragility data: `{field}[{index}]` = {} must be finite and > 0", float_token(*value))]
    BadIm {
        /// The field (`im`, `im_at_exceedance`, `band_im`).
        field: &'static str,
        /// Its index.
        index: usize,
        /// The value given.
        value: Real,
    },
    /// Two stripes at the same IM level.
    #[error("fragility data: `im[{first}]` and `im[{second}]` are both {}; IM levels must be distinct", float_token(*value))]
    DuplicateIm {
        /// The first index.
        first: usize,
        /// The second index.
        second: usize,
        /// The level.
        value: Real,
    },
    /// A record's row of outcomes is not as long as `im`.
    #[error(
        "fragility data: `exceeded[{record}]` has {len} outcomes but `im` has {expected} levels"
    )]
    Ragged {
        /// The record (row).
        record: usize,
        /// Its length.
        len: usize,
        /// The number of IM levels.
        expected: usize,
    },
    /// A bootstrap setting out of range.
    #[error("bootstrap settings: `{field}` = {value} {reason}")]
    BadSetting {
        /// `samples` or `level`.
        field: &'static str,
        /// The value given.
        value: String,
        /// What it must be.
        reason: &'static str,
    },
}

/// Refuses a non-finite or non-positive entry of `xs`, naming `field[index]`.
fn check_positive(field: &'static str, xs: &[Real]) -> Result<(), FragilityError> {
    match xs.iter().position(|x| !(x.is_finite() && *x > 0.0)) {
        Some(index) => Err(FragilityError::BadIm {
            field,
            index,
            value: xs[index],
        }),
        None => Ok(()),
    }
}
