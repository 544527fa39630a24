//! The `[search]` of a design: one continuous parameter of the bridge (e.g. the restrainers'
//! stiffness) searched for the value at which a limit state's mean annual frequency meets a
//! target, on the design's records and stripes.
//!
//! ```toml
//! [search]
//! key = "bridge.restrainer_k"    # a key path, as a variant's override
//! range = [1.0e7, 1.0e9]         # > 0; searched on a log scale
//! limit_state = "joint_opening"
//! target_maf = 5.0e-5            # per year (the design needs a hazard)
//! tolerance = 0.05               # stop when the bracket's ends are within 5 % (default)
//! ```
//!
//! Each evaluation is a full set of runs of the bridge with `key = value` (the design's records,
//! stripes and IM) and a fit. The ends of the range are run first: the MAF at the one end must
//! meet the target and at the other not (else no answer: the target is met over the whole
//! range, or nowhere in it). Bisection on `ln value` then narrows the bracket until its ends are
//! within `tolerance`; the end that meets is the answer — the **smallest** value meeting the
//! target when the MAF falls as the value rises (the largest, when it rises). A value 10 %
//! beyond it on the failing side (smaller, or larger) is run to confirm that it does not meet.
//! Every evaluation is kept. By construction every value run on the failing side of the answer
//! fails and every value from it on meets; the confirming run is the check of a second
//! crossing near the answer (if it meets too, no answer). The MAF of a finite record set may
//! wiggle between close values (one run crossing its limit moves the fit) without crossing the
//! target twice: the verdict then names the first pair of values whose MAFs go the wrong way.

use super::design::Design;
use super::design_file::DesignError;
pub use super::design_file::SearchSpec;
use super::run::Plan;
use super::variant::{Override, Variant, parse_path};
use crate::fragility::hazard::maf;
use crate::math::Real;
use crate::output::float_token;

/// One evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluation {
    /// The parameter's value.
    pub value: Real,
    /// The MAF (`None`: no fit; the status says why).
    pub maf: Option<Real>,
    /// The fit's status.
    pub status: String,
    /// Why it was run: `range`, `bisect` or `confirm`.
    pub role: &'static str,
}

/// The outcome of a search.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchResult {
    /// Every evaluation, in the order run.
    pub evaluations: Vec<Evaluation>,
    /// The value found (`None`: no answer, see `verdict`).
    pub found: Option<Real>,
    /// The verdict in words.
    pub verdict: String,
}

/// Runs the search of `spec` on the design's plan (on the current rayon pool).
pub fn search(
    design: &Design,
    spec: &SearchSpec,
    plan: &Plan,
    progress: &(dyn Fn() + Sync),
) -> Result<SearchResult, DesignError> {
    let base = &design.members[0].study;
    let Some(hz) = design.hazard() else {
        return Err(DesignError::Key {
            origin: design.origin.clone(),
            line: spec.line,
            key: "search".into(),
            message: "a search for a target MAF needs a hazard curve ([hazard] or --hazard)".into(),
        });
    };
    let Some(l) = base
        .limits
        .iter()
        .position(|b| b.state.name == spec.limit_state)
    else {
        return Err(DesignError::Key {
            origin: design.origin.clone(),
            line: spec.line,
            key: "search.limit_state".into(),
            message: format!(
                "no limit state named {:?} in the scenario",
                spec.limit_state
            ),
        });
    };
    let path = parse_path(&spec.key).unwrap_or_default();
    let eval = |value: Real, role: &'static str| -> Result<Evaluation, DesignError> {
        let v = Variant {
            name: format!("search-{}", float_token(value)),
            description: String::new(),
            line: spec.line,
            overrides: vec![Override {
                key: spec.key.clone(),
                path: path.clone(),
                value: toml::Value::Float(value),
                line: spec.line,
            }],
        };
        let mut st = design.study_with(&v)?;
        st.settings.bootstrap = 0;
        let rows = st.run(plan, progress);
        let fits = st
            .fit(plan, &rows)
            .map_err(|e| DesignError::Study(super::AssessmentError::Invalid(e.to_string())))?;
        let r = &fits.rows[l];
        let m = r.fit.params().map(|(t, b)| maf(&hz.curve, t, b).rate);
        let finite = m.is_none_or(Real::is_finite);
        Ok(Evaluation {
            value,
            maf: m.filter(|_| finite),
            status: if finite {
                r.fit.status().to_string()
            } else {
                super::hazard_study::MAF_NOT_FINITE.to_string()
            },
            role,
        })
    };
    let meets = |e: &Evaluation| e.maf.is_some_and(|m| m <= spec.target);
    let (lo, hi) = spec.range;
    let mut evs = vec![eval(lo, "range")?, eval(hi, "range")?];
    let no = |evs: Vec<Evaluation>, why: String| SearchResult {
        evaluations: evs,
        found: None,
        verdict: why,
    };
    if let Some(e) = evs.iter().find(|e| e.maf.is_none()) {
        let why = format!(
            "no answer: at {} = {} the fit has no MAF ({})",
            spec.key,
            float_token(e.value),
            e.status
        );
        return Ok(no(evs, why));
    }
    let decreasing = match (meets(&evs[0]), meets(&evs[1])) {
        (false, true) => true,
        (true, false) => false,
        (a, _) => {
            let why = format!(
                "no answer: the target {} per year is {} over the range {}..{} (MAF {} and {})",
                float_token(spec.target),
                if a {
                    "met at both ends"
                } else {
                    "met at neither end"
                },
                float_token(lo),
                float_token(hi),
                float_token(evs[0].maf.unwrap_or(Real::NAN)),
                float_token(evs[1].maf.unwrap_or(Real::NAN)),
            );
            return Ok(no(evs, why));
        }
    };
    // bracket: `fail` does not meet, `pass` meets
    let (mut fail, mut pass) = if decreasing { (lo, hi) } else { (hi, lo) };
    while (pass / fail).ln().abs() > (1.0 + spec.tolerance).ln() {
        let mid = (fail * pass).sqrt();
        let e = eval(mid, "bisect")?;
        if e.maf.is_none() {
            let why = format!(
                "no answer: at {} = {} the fit has no MAF ({})",
                spec.key,
                float_token(mid),
                e.status
            );
            evs.push(e);
            return Ok(no(evs, why));
        }
        if meets(&e) {
            pass = mid
        } else {
            fail = mid
        }
        evs.push(e);
    }
    let beyond = if decreasing { 0.9 * pass } else { pass / 0.9 };
    let c = eval(beyond, "confirm")?;
    let confirmed = !meets(&c);
    evs.push(c);
    // By construction every value run below the final bracket's failing end fails and every
    // value from its passing end on meets: the bisection cannot see a second crossing except
    // through the confirming run. A MAF that wiggles between values run (the noise of a finite
    // record set) is named in the verdict, not refused.
    let wiggle = non_monotone(&evs, decreasing);
    let side = if decreasing { "smallest" } else { "largest" };
    let verdict = format!(
        "{} = {} is the {side} value meeting MAF({}) <= {} per year (MAF {}; within {} %); {} = {} \
         (10 % {}) gives MAF {}: {}",
        spec.key,
        float_token(pass),
        spec.limit_state,
        float_token(spec.target),
        float_token(
            evs.iter()
                .find(|e| e.value == pass)
                .and_then(|e| e.maf)
                .unwrap_or(Real::NAN)
        ),
        float_token(100.0 * spec.tolerance),
        spec.key,
        float_token(beyond),
        if decreasing { "smaller" } else { "larger" },
        float_token(evs.last().and_then(|e| e.maf).unwrap_or(Real::NAN)),
        if confirmed {
            "does not meet the target (confirmed)"
        } else {
            "also meets the target: the answer is not confirmed"
        },
    ) + &wiggle
        .map(|(a, b)| {
            format!(
                "; note: the MAF is not monotone over the values run ({} at {} = {}, {} at {}: \
                 the noise of a finite record set), see search.csv",
                float_token(a.1),
                spec.key,
                float_token(a.0),
                float_token(b.1),
                float_token(b.0)
            )
        })
        .unwrap_or_default();
    Ok(SearchResult {
        evaluations: evs,
        found: confirmed.then_some(pass),
        verdict,
    })
}

/// The first pair of neighbouring values (in the order of the values) whose MAFs go the wrong
/// way (`(value, maf)` each), if any.
fn non_monotone(evs: &[Evaluation], decreasing: bool) -> Option<((Real, Real), (Real, Real))> {
    let mut sorted: Vec<(Real, Real)> = evs
        .iter()
        .filter_map(|e| e.maf.map(|m| (e.value, m)))
        .collect();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    sorted
        .windows(2)
        .find(|w| {
            if decreasing {
                w[1].1 > w[0].1
            } else {
                w[1].1 < w[0].1
            }
        })
        .map(|w| (w[0], w[1]))
}

/// `search.csv`: `value, maf_per_year, status, meets_target, role`.
pub fn search_csv(spec: &SearchSpec, r: &SearchResult) -> String {
    let mut out = format!(
        "{},maf_per_year,status,meets_target,role\n",
        crate::output::csv_field(&spec.key)
    );
    for e in &r.evaluations {
        out.push_str(&format!(
            "{},{},{},{},{}\n",
            float_token(e.value),
            float_token(e.maf.unwrap_or(Real::NAN)),
            e.status,
            e.maf.is_some_and(|m| m <= spec.target),
            e.role
        ));
    }
    out
}
