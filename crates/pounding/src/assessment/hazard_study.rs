//! The hazard integration of a fragility study: per limit state its mean annual frequency with
//! the bootstrap interval and the return period (`maf.csv`), the deaggregation by IM
//! (`hazard.csv`), and the `hazard` object of `fragility.json`
//! ([`crate::fragility::hazard`] for the formulas).

use super::hazard_input::HazardInput;
use crate::fragility::FragilityRow;
use crate::fragility::hazard::{HazardCurve, Maf, deaggregation, maf, maf_interval};
use crate::math::Real;
use crate::output::{csv_field, float_token, json_float};
use serde_json::{Value, json};

/// The MAF of one limit state.
#[derive(Debug, Clone, PartialEq)]
pub struct MafRow {
    /// The limit state.
    pub limit_state: String,
    /// `ok`, or the fit's status (no fit: no MAF).
    pub status: String,
    /// The MAF of the fit.
    pub maf: Option<Maf>,
    /// Its bootstrap interval (BCa over the replicates' `λ_LS(θ_b, β_b)`).
    pub interval: Option<(Real, Real)>,
    /// The confidence level of the interval (NaN without a bootstrap).
    pub level: Real,
}

/// The status of a fitted limit state whose MAF is not a finite number (a hazard table whose
/// rates overflow the integral): no MAF is given, and the command exits 1.
pub const MAF_NOT_FINITE: &str = "maf_not_finite";

/// The error of rows whose MAF is not finite (`None`: every fitted MAF is a number).
pub fn maf_failure(rows: &[MafRow]) -> Option<String> {
    let bad: Vec<&str> = rows
        .iter()
        .filter(|r| r.status == MAF_NOT_FINITE)
        .map(|r| r.limit_state.as_str())
        .collect();
    (!bad.is_empty()).then(|| {
        format!(
            "the mean annual frequency of {} is not a finite number (status {MAF_NOT_FINITE}: \
             the hazard curve's rates overflow the integral); no MAF is given",
            bad.join(", ")
        )
    })
}

/// The MAF of every fitted limit state under `hazard`.
pub fn maf_rows(hazard: &HazardCurve, fits: &[FragilityRow]) -> Vec<MafRow> {
    fits.iter()
        .map(|r| {
            let (m, interval) = match (&r.bootstrap, r.fit.params()) {
                (Some(b), Some(_)) => {
                    maf_interval(hazard, b).unwrap_or((maf(hazard, Real::NAN, Real::NAN), None))
                }
                (None, Some((t, b))) => (maf(hazard, t, b), None),
                (_, None) => (maf(hazard, Real::NAN, Real::NAN), None),
            };
            // a hazard table spanning rates beyond the floating-point range can overflow the
            // integral: never a non-finite MAF under an `ok` status
            let finite = m.rate.is_finite()
                && interval
                    .as_ref()
                    .is_none_or(|i| i.0.is_finite() && i.1.is_finite());
            let fitted = r.fit.params().is_some();
            MafRow {
                limit_state: r.limit_state.clone(),
                status: if fitted && !finite {
                    MAF_NOT_FINITE.to_string()
                } else {
                    r.fit.status().to_string()
                },
                maf: r.fit.params().filter(|_| finite).map(|_| m),
                interval: interval.filter(|_| finite),
                level: r.bootstrap.as_ref().map_or(Real::NAN, |b| b.level),
            }
        })
        .collect()
}

/// `maf.csv` columns.
pub const MAF_COLUMNS: &str = "limit_state,status,maf_per_year,maf_lo,maf_hi,level,\
return_period_years,return_period_lo,return_period_hi,upper_tail_lo,upper_tail_hi,p_first_im,hazard";

/// `maf.csv`: per limit state the MAF \[1/yr\], its interval, the return period \[yr\] (its
/// interval: the reciprocals of the MAF's bounds), and for a table hazard the bounds of the
/// neglected part above its last IM and the fragility at its first IM (`nan` for a power law).
pub fn maf_csv(h: &HazardInput, rows: &[MafRow]) -> String {
    let mut out = String::from(MAF_COLUMNS);
    out.push('\n');
    for r in rows {
        let m = r.maf;
        let rate = m.map_or(Real::NAN, |m| m.rate);
        let (lo, hi) = r.interval.unwrap_or((Real::NAN, Real::NAN));
        let (ul, uh) = m
            .and_then(|m| m.upper_tail)
            .unwrap_or((Real::NAN, Real::NAN));
        let pf = m.and_then(|m| m.p_first).unwrap_or(Real::NAN);
        let f = [
            rate,
            lo,
            hi,
            r.level,
            1.0 / rate,
            1.0 / hi,
            1.0 / lo,
            ul,
            uh,
            pf,
        ]
        .map(float_token)
        .join(",");
        out.push_str(&format!(
            "{},{},{f},{}\n",
            csv_field(&r.limit_state),
            r.status,
            csv_field(&h.source)
        ));
    }
    out
}

/// The IMs of the deaggregation of fit `(θ, β)`: 81 points evenly spaced in `ln x` over the
/// table's range, or around the fragility for a power law.
pub fn deaggregation_ims(hazard: &HazardCurve, theta: Real, beta: Real) -> Vec<Real> {
    let (lo, hi) = hazard.range(theta, beta);
    (0..=80)
        .map(|k| (lo.ln() + (hi / lo).ln() * k as Real / 80.0).exp())
        .collect()
}

/// `hazard.csv`: per limit state with a fit and per IM of [`deaggregation_ims`]: `im_g`,
/// `hazard_rate` (λ(IM) per year), `p_exceed` (the fragility) and `density` (the MAF's
/// integrand per unit `ln IM`, per year; its integral over `ln IM` is the MAF) and `share`
/// (density / MAF).
pub fn hazard_csv(h: &HazardInput, fits: &[FragilityRow], rows: &[MafRow]) -> String {
    let mut out = String::from("limit_state,im_g,hazard_rate,p_exceed,density,share\n");
    for (r, m) in fits.iter().zip(rows) {
        let (Some((t, b)), Some(mm)) = (r.fit.params(), m.maf) else {
            continue;
        };
        let xs = deaggregation_ims(&h.curve, t, b);
        let d = deaggregation(&h.curve, t, b, &xs);
        for (x, dens) in xs.iter().zip(d) {
            let p = crate::fragility::normal::cdf((x.ln() - t.ln()) / b);
            let lam = h.curve.rate(*x).unwrap_or(Real::NAN);
            out.push_str(&format!(
                "{},{}\n",
                csv_field(&r.limit_state),
                [*x, lam, p, dens, dens / mm.rate]
                    .map(float_token)
                    .join(",")
            ));
        }
    }
    out
}

/// The `hazard` object of `fragility.json`: the curve, its source and per limit state the MAF.
pub fn hazard_json(h: &HazardInput, rows: &[MafRow]) -> Value {
    let curve = match &h.curve {
        HazardCurve::PowerLaw { k0, k } => {
            json!({"kind": "power_law", "k0": json_float(*k0), "k": json_float(*k)})
        }
        HazardCurve::Table { im, rate } => json!({
            "kind": "table",
            "im_g": im.iter().map(|&x| json_float(x)).collect::<Vec<_>>(),
            "rate": rate.iter().map(|&x| json_float(x)).collect::<Vec<_>>(),
            "integration": "log-log interpolation between points, over the table's range only",
        }),
    };
    let maf: Vec<Value> = rows
        .iter()
        .map(|r| {
            let m = r.maf;
            let (lo, hi) = r.interval.unwrap_or((Real::NAN, Real::NAN));
            let (ul, uh) = m
                .and_then(|m| m.upper_tail)
                .unwrap_or((Real::NAN, Real::NAN));
            json!({
                "limit_state": r.limit_state,
                "status": r.status,
                "maf_per_year": json_float(m.map_or(Real::NAN, |m| m.rate)),
                "maf_lo": json_float(lo),
                "maf_hi": json_float(hi),
                "level": json_float(r.level),
                "return_period_years": json_float(m.map_or(Real::NAN, |m| 1.0 / m.rate)),
                "upper_tail": [json_float(ul), json_float(uh)],
                "p_first_im": json_float(m.and_then(|m| m.p_first).unwrap_or(Real::NAN)),
            })
        })
        .collect();
    json!({"source": h.source, "im_unit": "g", "curve": curve, "maf": maf})
}

/// Warnings about the MAF of a table hazard: an upper-tail bound above 1 % of the MAF, or a
/// fragility above 1 % at the first IM (the table's range leaves out a part that matters).
pub fn maf_warnings(rows: &[MafRow]) -> Vec<String> {
    let mut w = Vec::new();
    for r in rows {
        let Some(m) = r.maf else { continue };
        if let Some((_, hi)) = m.upper_tail
            && hi > 0.01 * m.rate
        {
            w.push(format!(
                "limit state {}: the hazard table ends where its rate ({}) is {:.1} % of the MAF \
                 ({}): the MAF over the table's range leaves out up to that much; extend the \
                 table to larger IMs",
                r.limit_state,
                float_token(hi),
                100.0 * hi / m.rate,
                float_token(m.rate)
            ));
        }
        if let Some(p) = m.p_first
            && p > 0.01
        {
            w.push(format!(
                "limit state {}: the fragility is already {:.1} % at the hazard table's first \
                 IM: events below it are left out of the MAF; extend the table to smaller IMs",
                r.limit_state,
                100.0 * p
            ));
        }
    }
    w
}
