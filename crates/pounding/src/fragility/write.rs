//! `fragility.csv` and `fragility.json`: one row (object) per limit state and method.
//!
//! CSV columns: `limit_state, method, status, theta, beta, theta_lo, theta_hi, beta_lo, beta_hi,
//! level, n_records, n_runs, bootstrap_samples, bootstrap_failed`, and for a study
//! ([`fragility_csv_study`]) `im, im_unit` at the end (e.g. `Sa(1.5 s, 5 %)`, `g`). Numbers in the project's
//! shortest round-trip form ([`crate::output::float_token`]); a number that does not exist (no fit,
//! no bootstrap) is `nan` in CSV and `null` in JSON, and `status` says why (`ok` or a
//! [`super::NoMle`] word; `bootstrap_failed` is `nan` / `null` when the data have no fit, as no
//! replicate then means anything, and `0` without a bootstrap: `no_exceedance`, `all_exceeded`, `perfectly_separated`,
//! `not_increasing`, `too_few_points`, `censored` (IDA records never exceeding within the IMs
//! run, given without their bound), `exceeded_at_first` (IDA records exceeding already at the first
//! IM, no longer given by the workflow), `no_dispersion`, `out_of_range`, `not_converged`). The JSON adds the pointwise band of each bootstrap.

use serde_json::{Value, json};

use super::{Bootstrap, Fit};
use crate::math::Real;
use crate::output::{csv_field, float_token, json_float};

/// How a fit was made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Maximum likelihood on multiple-stripe counts (`mle_stripes`).
    MleStripes,
    /// Method of moments on IDA data (`moments_ida`): IDA data without a censored record.
    MomentsIda,
    /// Maximum likelihood of the censored lognormal on IDA data with censored records
    /// (`mle_censored_ida`, [`super::censored`]); the counts are written to `fragility.json`.
    MleCensoredIda {
        /// Records never exceeding within the IMs run (right-censored).
        right: usize,
        /// Records exceeding already at the first IM (left-censored).
        left: usize,
    },
}

impl Method {
    /// The word written in outputs.
    pub fn as_str(&self) -> &'static str {
        match self {
            Method::MleStripes => "mle_stripes",
            Method::MomentsIda => "moments_ida",
            Method::MleCensoredIda { .. } => "mle_censored_ida",
        }
    }
}

/// One fitted limit state, as written.
#[derive(Debug, Clone, PartialEq)]
pub struct FragilityRow {
    /// The limit state's name.
    pub limit_state: String,
    /// How it was fitted.
    pub method: Method,
    /// The fit to the data.
    pub fit: Fit,
    /// The bootstrap, when one was run (its `fit` equals `fit`).
    pub bootstrap: Option<Bootstrap>,
    /// Number of records.
    pub n_records: usize,
    /// Number of runs counted (with an outcome).
    pub n_runs: usize,
}

impl FragilityRow {
    /// The row of a multiple-stripe fit: the fit (or the bootstrap's fit), the record and run
    /// counts of `d`. Errors only for bad input.
    pub fn from_stripes(
        limit_state: &str,
        d: &super::StripeData,
        bootstrap: Option<Bootstrap>,
    ) -> Result<Self, super::FragilityError> {
        let fit = match &bootstrap {
            Some(b) => b.fit,
            None => super::fit_stripes(d)?,
        };
        Ok(FragilityRow {
            limit_state: limit_state.to_string(),
            method: Method::MleStripes,
            fit,
            bootstrap,
            n_records: d.exceeded.len(),
            n_runs: d.runs(),
        })
    }

    /// The row of an IDA fit (`n_runs` = records with an exceedance IM).
    pub fn from_ida(
        limit_state: &str,
        d: &super::IdaData,
        bootstrap: Option<Bootstrap>,
    ) -> Result<Self, super::FragilityError> {
        let fit = match &bootstrap {
            Some(b) => b.fit,
            None => super::fit_ida(d)?,
        };
        Ok(FragilityRow {
            limit_state: limit_state.to_string(),
            method: Method::MomentsIda,
            fit,
            bootstrap,
            n_records: d.im_at_exceedance.len(),
            n_runs: d.im_at_exceedance.iter().flatten().count(),
        })
    }

    /// The row of an IDA fit with censoring bounds: the estimator of
    /// [`super::CensoredIdaData::method`], the fit (or the bootstrap's fit), `n_runs` = records
    /// that exceeded (exactly or already at the first IM).
    pub fn from_ida_censored(
        limit_state: &str,
        d: &super::CensoredIdaData,
        bootstrap: Option<Bootstrap>,
    ) -> Result<Self, super::FragilityError> {
        let (method, fit) = super::fit_ida_censored(d)?;
        let (exact, _, left) = d.counts();
        Ok(FragilityRow {
            limit_state: limit_state.to_string(),
            method,
            fit: bootstrap.as_ref().map_or(fit, |b| b.fit),
            bootstrap,
            n_records: d.records.len(),
            n_runs: exact + left,
        })
    }
}

/// Fewer records than this make bootstrap intervals over records unreliable
/// ([`FragilityRow::interval_warnings`]).
pub const MIN_RECORDS_FOR_INTERVALS: usize = 10;

/// Fewer bootstrap replicates than this make the intervals unreliable
/// ([`FragilityRow::interval_warnings`]): a 95 % interval's bounds are the 2.5 % and 97.5 %
/// quantiles of the replicates, and the BCa corrections (bias and acceleration) are estimated
/// from them too; with 200 replicates each tail holds 5 of them (Efron & Tibshirani, *An
/// Introduction to the Bootstrap*, 1993, §19: about 1000 recommended for BCa).
pub const MIN_BOOTSTRAP_SAMPLES: usize = 200;

impl FragilityRow {
    /// Replicates without a fit, `None` when there is no bootstrap or the data themselves have no
    /// fit (then no replicate is meaningful: written `nan` / `null`, not `samples`).
    pub fn bootstrap_failed(&self) -> Option<usize> {
        self.fit.params()?;
        self.bootstrap.as_ref().map(|b| b.failed)
    }

    /// Why this row's bootstrap intervals are unreliable (empty when they are not, or when there
    /// are none): fewer than [`MIN_RECORDS_FOR_INTERVALS`] records, fewer than
    /// [`MIN_BOOTSTRAP_SAMPLES`] replicates, an interval that does not contain its own point
    /// estimate, or more than 10 % of the replicates without a fit (the intervals describe only
    /// the others). Printed on stderr, listed in the report and in `fragility.json`.
    pub fn interval_warnings(&self) -> Vec<String> {
        let Some(b) = self
            .bootstrap
            .as_ref()
            .filter(|_| self.fit.params().is_some())
        else {
            return Vec::new();
        };
        let mut w = Vec::new();
        if self.n_records < MIN_RECORDS_FOR_INTERVALS {
            w.push(format!(
                "limit state {}: intervals unreliable: the bootstrap resamples only {} records \
                 (use at least {MIN_RECORDS_FOR_INTERVALS})",
                self.limit_state, self.n_records
            ));
        }
        if b.samples < MIN_BOOTSTRAP_SAMPLES {
            w.push(format!(
                "limit state {}: intervals unreliable: only {} bootstrap replicates (use at least \
                 {MIN_BOOTSTRAP_SAMPLES}; about 1000 for stable 95 % bounds)",
                self.limit_state, b.samples
            ));
        }
        if let Some((theta, beta)) = self.fit.params() {
            for (name, v, i) in [("theta", theta, b.theta), ("beta", beta, b.beta)] {
                if let Some((lo, hi)) = i.filter(|(lo, hi)| !(*lo <= v && v <= *hi)) {
                    w.push(format!(
                        "limit state {}: the {name} interval [{lo:.5}, {hi:.5}] does not contain \
                         the estimate {v:.5}: the bootstrap replicates are shifted from the fit to \
                         the data (few replicates or records, or a skewed distribution); do not \
                         read it as a confidence interval",
                        self.limit_state
                    ));
                }
            }
        }
        if b.failed * 10 > b.samples {
            w.push(format!(
                "limit state {}: intervals unreliable: {} of {} bootstrap replicates had no fit \
                 (more than 10 %); the intervals describe only the others",
                self.limit_state, b.failed, b.samples
            ));
        }
        w
    }
}

/// The CSV column names, in order.
pub const CSV_COLUMNS: [&str; 14] = [
    "limit_state",
    "method",
    "status",
    "theta",
    "beta",
    "theta_lo",
    "theta_hi",
    "beta_lo",
    "beta_hi",
    "level",
    "n_records",
    "n_runs",
    "bootstrap_samples",
    "bootstrap_failed",
];

/// What a study adds to every row of its outputs ([`fragility_csv_study`],
/// [`fragility_json_study`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyColumns<'a> {
    /// The intensity measure, e.g. `Sa(1.5 s, 5 %)` or `PGA`.
    pub im: &'a str,
    /// Its unit, e.g. `g`.
    pub im_unit: &'a str,
    /// The confidence level asked for (written as `level` also without a bootstrap).
    pub level: Real,
}

/// The numbers of a row: `(θ, β, θ_lo, θ_hi, β_lo, β_hi, level)`, NaN where absent; `level`
/// without a bootstrap is `level` (the study's), else NaN.
fn numbers(r: &FragilityRow, level: Option<Real>) -> [Real; 7] {
    let (theta, beta) = r.fit.params().unwrap_or((Real::NAN, Real::NAN));
    let b = r.bootstrap.as_ref();
    let (tl, th) = b.and_then(|b| b.theta).unwrap_or((Real::NAN, Real::NAN));
    let (bl, bh) = b.and_then(|b| b.beta).unwrap_or((Real::NAN, Real::NAN));
    let level = b.map_or(level.unwrap_or(Real::NAN), |b| b.level);
    [theta, beta, tl, th, bl, bh, level]
}

/// `fragility.csv`: a header and one line per row (see the module documentation).
pub fn fragility_csv(rows: &[FragilityRow]) -> String {
    csv_impl(rows, None)
}

/// `fragility.csv` of a study: [`fragility_csv`] with the columns `im` and `im_unit` added at
/// the end, and `level` written as asked also without a bootstrap.
pub fn fragility_csv_study(rows: &[FragilityRow], study: &StudyColumns) -> String {
    csv_impl(rows, Some(study))
}

fn csv_impl(rows: &[FragilityRow], study: Option<&StudyColumns>) -> String {
    let mut out = CSV_COLUMNS.join(",");
    if study.is_some() {
        out.push_str(",im,im_unit");
    }
    out.push('\n');
    for r in rows {
        let mut f = vec![
            csv_field(&r.limit_state),
            r.method.as_str().to_string(),
            r.fit.status().to_string(),
        ];
        f.extend(
            numbers(r, study.map(|s| s.level))
                .iter()
                .map(|&x| float_token(x)),
        );
        f.push(r.n_records.to_string());
        f.push(r.n_runs.to_string());
        f.push(r.bootstrap.as_ref().map_or(0, |b| b.samples).to_string());
        f.push(match (&r.bootstrap, r.bootstrap_failed()) {
            (None, _) => "0".to_string(),
            (Some(_), None) => float_token(Real::NAN),
            (Some(_), Some(n)) => n.to_string(),
        });
        if let Some(s) = study {
            f.push(csv_field(s.im));
            f.push(csv_field(s.im_unit));
        }
        out.push_str(&f.join(","));
        out.push('\n');
    }
    out
}

/// `fragility.json`: `{"fits": [...]}` with the CSV's keys per row (numbers or `null`), plus
/// `censored` (IDA records without exceedance: with [`Method::MleCensoredIda`] its right-censored
/// count, or the count when that is the status), `exceeded_at_first` (IDA records exceeding already
/// at the first IM: the left-censored count, or the count with that status) and `band`: the bootstrap's
/// `[{"im", "p", "lo", "hi"}]` (empty without a bootstrap).
pub fn fragility_json(rows: &[FragilityRow]) -> Value {
    json_impl(rows, None)
}

/// `fragility.json` of a study: [`fragility_json`] with `im` and `im_unit` in every fit, and
/// `level` as asked also without a bootstrap.
pub fn fragility_json_study(rows: &[FragilityRow], study: &StudyColumns) -> Value {
    json_impl(rows, Some(study))
}

fn json_impl(rows: &[FragilityRow], study: Option<&StudyColumns>) -> Value {
    let fits: Vec<Value> = rows
        .iter()
        .map(|r| {
            let [theta, beta, tl, th, bl, bh, level] =
                numbers(r, study.map(|s| s.level)).map(json_float);
            let band: Vec<Value> = r.bootstrap.as_ref().map_or(Vec::new(), |b| {
                b.band
                    .iter()
                    .map(|p| {
                        let (lo, hi) = p.interval.unwrap_or((Real::NAN, Real::NAN));
                        json!({
                            "im": json_float(p.im),
                            "p": json_float(p.p.unwrap_or(Real::NAN)),
                            "lo": json_float(lo),
                            "hi": json_float(hi),
                        })
                    })
                    .collect()
            });
            let censored = match (r.fit, r.method) {
                (Fit::NoFiniteMle(super::NoMle::Censored { count }), _)
                | (_, Method::MleCensoredIda { right: count, .. }) => json!(count),
                _ => Value::Null,
            };
            let at_first = match (r.fit, r.method) {
                (Fit::NoFiniteMle(super::NoMle::ExceededAtFirst { count }), _)
                | (_, Method::MleCensoredIda { left: count, .. }) => json!(count),
                _ => Value::Null,
            };
            let mut o = json!({
                "limit_state": r.limit_state,
                "method": r.method.as_str(),
                "status": r.fit.status(),
                "theta": theta,
                "beta": beta,
                "theta_lo": tl,
                "theta_hi": th,
                "beta_lo": bl,
                "beta_hi": bh,
                "level": level,
                "n_records": r.n_records,
                "n_runs": r.n_runs,
                "bootstrap_samples": r.bootstrap.as_ref().map_or(0, |b| b.samples),
                "bootstrap_failed": match (&r.bootstrap, r.bootstrap_failed()) {
                    (None, _) => json!(0),
                    (Some(_), failed) => json!(failed),
                },
                "censored": censored,
                "exceeded_at_first": at_first,
                "band": band,
                "interval_warnings": r.interval_warnings(),
            });
            if let (Some(s), Some(m)) = (study, o.as_object_mut()) {
                m.insert("im".into(), json!(s.im));
                m.insert("im_unit".into(), json!(s.im_unit));
            }
            o
        })
        .collect();
    json!({ "fits": fits })
}
