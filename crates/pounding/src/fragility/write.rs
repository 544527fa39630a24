//! `fragility.csv` and `fragility.json`: one row (object) per limit state and method.
//!
//! CSV columns: `limit_state, method, status, theta, beta, theta_lo, theta_hi, beta_lo, beta_hi,
//! level, n_records, n_runs, bootstrap_samples, bootstrap_failed`. Numbers in the project's
//! shortest round-trip form ([`crate::output::float_token`]); a number that does not exist (no fit,
//! no bootstrap) is `nan` in CSV and `null` in JSON, and `status` says why (`ok` or a
//! [`super::NoMle`] word: `no_exceedance`, `all_exceeded`, `perfectly_separated`,
//! `not_increasing`, `too_few_points`, `censored` (IDA records never exceeding within the IMs
//! run), `exceeded_at_first` (IDA records exceeding already at the first IM: the IM at first
//! exceedance is only an upper bound), `no_dispersion`, `out_of_range`, `not_converged`). The JSON adds the pointwise band of each bootstrap.

use serde_json::{Value, json};

use super::{Bootstrap, Fit};
use crate::math::Real;
use crate::output::{csv_field, float_token, json_float};

/// How a fit was made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Maximum likelihood on multiple-stripe counts (`mle_stripes`).
    MleStripes,
    /// Method of moments on IDA data (`moments_ida`).
    MomentsIda,
}

impl Method {
    /// The word written in outputs.
    pub fn as_str(&self) -> &'static str {
        match self {
            Method::MleStripes => "mle_stripes",
            Method::MomentsIda => "moments_ida",
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

/// The numbers of a row: `(θ, β, θ_lo, θ_hi, β_lo, β_hi, level)`, NaN where absent.
fn numbers(r: &FragilityRow) -> [Real; 7] {
    let (theta, beta) = r.fit.params().unwrap_or((Real::NAN, Real::NAN));
    let b = r.bootstrap.as_ref();
    let (tl, th) = b.and_then(|b| b.theta).unwrap_or((Real::NAN, Real::NAN));
    let (bl, bh) = b.and_then(|b| b.beta).unwrap_or((Real::NAN, Real::NAN));
    let level = b.map_or(Real::NAN, |b| b.level);
    [theta, beta, tl, th, bl, bh, level]
}

/// `fragility.csv`: a header and one line per row (see the module documentation).
pub fn fragility_csv(rows: &[FragilityRow]) -> String {
    let mut out = CSV_COLUMNS.join(",");
    out.push('\n');
    for r in rows {
        let mut f = vec![
            csv_field(&r.limit_state),
            r.method.as_str().to_string(),
            r.fit.status().to_string(),
        ];
        f.extend(numbers(r).iter().map(|&x| float_token(x)));
        f.push(r.n_records.to_string());
        f.push(r.n_runs.to_string());
        let (samples, failed) = r
            .bootstrap
            .as_ref()
            .map_or((0, 0), |b| (b.samples, b.failed));
        f.push(samples.to_string());
        f.push(failed.to_string());
        out.push_str(&f.join(","));
        out.push('\n');
    }
    out
}

/// `fragility.json`: `{"fits": [...]}` with the CSV's keys per row (numbers or `null`), plus
/// `censored` (IDA records without exceedance, when that is the status), `exceeded_at_first`
/// (IDA records exceeding already at the first IM, when that is the status) and `band`: the bootstrap's
/// `[{"im", "p", "lo", "hi"}]` (empty without a bootstrap).
pub fn fragility_json(rows: &[FragilityRow]) -> Value {
    let fits: Vec<Value> = rows
        .iter()
        .map(|r| {
            let [theta, beta, tl, th, bl, bh, level] = numbers(r).map(json_float);
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
            let censored = match r.fit {
                Fit::NoFiniteMle(super::NoMle::Censored { count }) => json!(count),
                _ => Value::Null,
            };
            let at_first = match r.fit {
                Fit::NoFiniteMle(super::NoMle::ExceededAtFirst { count }) => json!(count),
                _ => Value::Null,
            };
            json!({
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
                "bootstrap_failed": r.bootstrap.as_ref().map_or(0, |b| b.failed),
                "censored": censored,
                "exceeded_at_first": at_first,
                "band": band,
            })
        })
        .collect();
    json!({ "fits": fits })
}
