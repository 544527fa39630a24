//! Per-(configuration, case) summaries: `summary.csv` and `summary.json`.
//!
//! Over the first-contact cells of a block (one configuration and case), with the scenario's ratio
//! range `[r_min, r_max]` of length `Δ = r_max − r_min`:
//!
//! * `outward_fraction` = mean of `(clamp(L) − r_min)/Δ` (the part `[r_min, L)` of the range),
//! * `stick_fraction`   = mean of `(clamp(U) − clamp(L))/Δ` (the part `[L, U]`),
//! * `inward_fraction`  = mean of `(r_max − clamp(U))/Δ` (the part `(U, r_max]`),
//!
//! with `clamp(x) = min(max(x, r_min), r_max)`, so the three fractions sum to 1; `lower_min` …
//! `upper_max` are the extremes of `L` and `U` over the same cells. With no first-contact cell the
//! fractions and extremes are NaN (`nan` in CSV, `null` in JSON). `lcp_disagreements` counts the
//! block's cells (all of them) whose `lcp_agrees` is false.

use super::run::{Layout, Row};
use super::scenario::Scenario;
use crate::geometry::ContactCase;
use crate::math::Real;
use crate::output::{float_token, json_float};
use serde_json::{Map, Value, json};

/// The header line of `summary.csv` (without newline).
pub const SUMMARY_HEADER: &str = "beta1_deg,beta2_deg,r1_m,r2_m,mu,eps,case,first_contact_cells,stick_fraction,outward_fraction,inward_fraction,lower_min,lower_max,upper_min,upper_max,lcp_disagreements";

/// One summary row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SummaryRow {
    /// `β1` \[deg\].
    pub beta1_deg: Real,
    /// `β2` \[deg\].
    pub beta2_deg: Real,
    /// `R1` \[m\].
    pub r1_m: Real,
    /// `R2` \[m\].
    pub r2_m: Real,
    /// `μ`.
    pub mu: Real,
    /// `ε_N`.
    pub eps: Real,
    /// Candidate case.
    pub case: ContactCase,
    /// Number of first-contact cells.
    pub first_contact_cells: usize,
    /// Mean stick share of the ratio range.
    pub stick_fraction: Real,
    /// Mean outward-slip share (`r < L`).
    pub outward_fraction: Real,
    /// Mean inward-slip share (`r > U`).
    pub inward_fraction: Real,
    /// Minimum of `L`.
    pub lower_min: Real,
    /// Maximum of `L`.
    pub lower_max: Real,
    /// Minimum of `U`.
    pub upper_min: Real,
    /// Maximum of `U`.
    pub upper_max: Real,
    /// Cells with `lcp_agrees = false`.
    pub lcp_disagreements: usize,
}

/// Shares `(outward, stick, inward)` of `[r_min, r_max]` for a stick interval `[L, U]`.
pub fn shares(lower: Real, upper: Real, r_min: Real, r_max: Real) -> (Real, Real, Real) {
    let d = r_max - r_min;
    let cl = lower.clamp(r_min, r_max);
    let cu = upper.clamp(r_min, r_max);
    ((cl - r_min) / d, (cu - cl) / d, (r_max - cu) / d)
}

/// The summaries of a complete, ordered set of rows (all rows of the study).
pub fn summarize(scenario: &Scenario, rows: &[Row]) -> Vec<SummaryRow> {
    let layout = Layout::of(scenario);
    let bl = layout.block_len();
    rows.chunks(bl)
        .map(|block| {
            let p = scenario.params(&block[0].key);
            let (mut n, mut so, mut ss, mut si) = (0usize, 0.0, 0.0, 0.0);
            let (mut lmin, mut lmax, mut umin, mut umax) = (
                Real::INFINITY,
                Real::NEG_INFINITY,
                Real::INFINITY,
                Real::NEG_INFINITY,
            );
            let mut dis = 0;
            for r in block {
                let c = &r.cell;
                if !c.lcp_agrees {
                    dis += 1;
                }
                if !c.first_contact {
                    continue;
                }
                n += 1;
                let (o, s, i) = shares(c.lower, c.upper, scenario.ratio_min, scenario.ratio_max);
                so += o;
                ss += s;
                si += i;
                lmin = lmin.min(c.lower);
                lmax = lmax.max(c.lower);
                umin = umin.min(c.upper);
                umax = umax.max(c.upper);
            }
            let nan = Real::NAN;
            let (mean, ext) = if n == 0 {
                ([nan; 3], [nan; 4])
            } else {
                let k = n as Real;
                ([so / k, ss / k, si / k], [lmin, lmax, umin, umax])
            };
            SummaryRow {
                beta1_deg: p.beta1_deg,
                beta2_deg: p.beta2_deg,
                r1_m: p.r1_m,
                r2_m: p.r2_m,
                mu: p.mu,
                eps: p.eps,
                case: p.case,
                first_contact_cells: n,
                outward_fraction: mean[0],
                stick_fraction: mean[1],
                inward_fraction: mean[2],
                lower_min: ext[0],
                lower_max: ext[1],
                upper_min: ext[2],
                upper_max: ext[3],
                lcp_disagreements: dis,
            }
        })
        .collect()
}

/// `summary.csv` text.
pub fn summary_csv(rows: &[SummaryRow]) -> String {
    let mut s = String::with_capacity(rows.len() * 160 + 256);
    s.push_str(SUMMARY_HEADER);
    s.push('\n');
    for r in rows {
        let f = float_token;
        s.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            f(r.beta1_deg),
            f(r.beta2_deg),
            f(r.r1_m),
            f(r.r2_m),
            f(r.mu),
            f(r.eps),
            r.case.name(),
            r.first_contact_cells,
            f(r.stick_fraction),
            f(r.outward_fraction),
            f(r.inward_fraction),
            f(r.lower_min),
            f(r.lower_max),
            f(r.upper_min),
            f(r.upper_max),
            r.lcp_disagreements
        ));
    }
    s
}

/// `summary.json` text: `{"bounds_rows": N, "lcp_disagreements": total, "summaries": [ {column: value}… ]}`
/// (columns as in `summary.csv`; non-finite numbers `null`), pretty-printed, trailing newline.
pub fn summary_json(scenario: &Scenario, rows: &[SummaryRow]) -> String {
    let items: Vec<Value> = rows
        .iter()
        .map(|r| {
            let mut m = Map::new();
            m.insert("beta1_deg".into(), json_float(r.beta1_deg));
            m.insert("beta2_deg".into(), json_float(r.beta2_deg));
            m.insert("r1_m".into(), json_float(r.r1_m));
            m.insert("r2_m".into(), json_float(r.r2_m));
            m.insert("mu".into(), json_float(r.mu));
            m.insert("eps".into(), json_float(r.eps));
            m.insert("case".into(), json!(r.case.name()));
            m.insert("first_contact_cells".into(), json!(r.first_contact_cells));
            m.insert("stick_fraction".into(), json_float(r.stick_fraction));
            m.insert("outward_fraction".into(), json_float(r.outward_fraction));
            m.insert("inward_fraction".into(), json_float(r.inward_fraction));
            m.insert("lower_min".into(), json_float(r.lower_min));
            m.insert("lower_max".into(), json_float(r.lower_max));
            m.insert("upper_min".into(), json_float(r.upper_min));
            m.insert("upper_max".into(), json_float(r.upper_max));
            m.insert("lcp_disagreements".into(), json!(r.lcp_disagreements));
            Value::Object(m)
        })
        .collect();
    let total: usize = rows.iter().map(|r| r.lcp_disagreements).sum();
    let mut top = Map::new();
    top.insert("bounds_rows".into(), json!(scenario.row_count()));
    top.insert("lcp_disagreements".into(), json!(total));
    top.insert("summaries".into(), Value::Array(items));
    let mut s = serde_json::to_string_pretty(&Value::Object(top)).unwrap_or_default();
    s.push('\n');
    s
}
