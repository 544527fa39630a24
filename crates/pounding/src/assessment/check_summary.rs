//! The code check of one run, in words and in `summary.json`: a scenario with a `[code_check]`
//! table gets, beside the run's seat margins, its verdict (seated ends and joint gaps that fail,
//! and how many ends each code fails), each end's governing code seat next to the run's peak,
//! each joint's required gaps, and what the check leaves out. `simulate` (its `summary.json`,
//! stderr and report) and Python's `pounding.simulate` take it from here.

use super::check::{CODES, CheckReport, Code};
use super::check_run::against_run;
use super::check_write::{ec8_sections_json, omissions, overall};
use super::{CodeCheckInput, check_bridge};
use crate::output::json_float;
use crate::sim::bridge::{BridgeModel, SeatSummary};
use crate::sim::scenario::Setup;
use serde_json::{Value, json};

/// The code check of a run's scenario: `None` without a `[code_check]` table, `Some(Err)` with
/// the reason when it cannot be evaluated (its input is checked before the run, so this is a
/// formula's refusal of a value the model derives).
pub fn scenario_check(
    model: &BridgeModel,
    (origin, text): (&str, &str),
) -> Option<Result<CheckReport, String>> {
    if !CodeCheckInput::is_present(text) {
        return None;
    }
    Some(
        CodeCheckInput::from_scenario(text, origin)
            .and_then(|input| check_bridge(model, &input, origin))
            .map_err(|e| e.to_string()),
    )
}

/// `(failing, evaluated)` seated ends of `code`.
pub fn code_counts(r: &CheckReport, code: Code) -> (usize, usize) {
    let vals: Vec<bool> = r
        .ends
        .iter()
        .filter_map(|e| {
            let q = e.codes.iter().find(|(c, _)| *c == code)?.1.value()?;
            Some(e.at.seat_length < q)
        })
        .collect();
    (vals.iter().filter(|&&f| f).count(), vals.len())
}

/// The verdict in one sentence: `FAIL: 8 of 8 seated ends are shorter than a code requires
/// (EN 1998-2 §6.6.4 8/8, …); 3 of 3 joint gaps are narrower than the double-difference rule
/// requires; at 2 end(s) the run's peak exceeds the design displacement the codes were given.`
pub fn verdict_sentence(r: &CheckReport, seats: &[SeatSummary]) -> String {
    let per_code: Vec<String> = CODES
        .iter()
        .filter_map(|&c| {
            let (f, n) = code_counts(r, c);
            (n > 0).then(|| format!("{} {f}/{n}", c.title()))
        })
        .collect();
    let mut s = format!(
        "{}: {} of {} seated ends are shorter than a code requires",
        overall(r),
        r.failing_ends(),
        r.ends.len()
    );
    if !per_code.is_empty() {
        s += &format!(" ({})", per_code.join(", "));
    }
    let gaps = r.gaps.iter().filter(|g| g.pass().is_some()).count();
    if gaps > 0 {
        s += &format!(
            "; {} of {gaps} joint gaps are narrower than the double-difference rule requires",
            r.failing_gaps()
        );
    }
    let missing: Vec<String> = r
        .not_evaluated()
        .iter()
        .map(|(c, why)| format!("{} ({why})", c.title()))
        .collect();
    if !missing.is_empty() {
        // a PASS of the codes evaluated is not a PASS of the others
        s += &format!("; not evaluated: {}", missing.join(", "));
    }
    let beyond = against_run(r, seats)
        .iter()
        .filter(|e| e.beyond_design == Some(true))
        .count();
    if beyond > 0 {
        s += &format!(
            "; at {beyond} end(s) the run's peak seat displacement exceeds the design \
             displacement the codes were given"
        );
    }
    s + "."
}

/// `summary.json`'s `code_check`: the verdict, the counts, per code its failing ends, per end
/// the provided and governing seat beside the run's peak, per joint the gap and its two
/// requirements, and the omissions.
pub fn summary_json(r: &CheckReport, seats: &[SeatSummary]) -> Value {
    let codes: serde_json::Map<String, Value> = CODES
        .iter()
        .map(|&c| {
            let (f, n) = code_counts(r, c);
            (
                c.name().to_string(),
                json!({"failing_ends": f, "evaluated_ends": n}),
            )
        })
        .collect();
    let opt = |x: Option<f64>| x.map_or(Value::Null, json_float);
    let ends: Vec<Value> = against_run(r, seats)
        .iter()
        .map(|e| {
            let g = e.check.governing();
            json!({
                "end": e.check.at.end,
                "seat_length_m": json_float(e.check.at.seat_length),
                "governing_code": g.map(|(c, _)| c.name()),
                "governing_m": opt(g.map(|(_, v)| v)),
                "margin_m": opt(e.check.margin()),
                "peak_seat_displacement_m": json_float(e.peak),
                "ec8_sections": ec8_sections_json(e.check.ec8.as_ref()),
                "beyond_design_displacement": e.beyond_design,
            })
        })
        .collect();
    let gaps: Vec<Value> = r
        .gaps
        .iter()
        .map(|g| {
            json!({
                "joint": g.joint + 1,
                "gap_m": json_float(g.gap),
                "srss_m": opt(g.srss.value()),
                "ddc_m": opt(g.ddc.value()),
                "pass": g.pass(),
            })
        })
        .collect();
    json!({
        "verdict": overall(r),
        "sentence": verdict_sentence(r, seats),
        "failing_ends": r.failing_ends(),
        "seated_ends": r.ends.len(),
        "failing_gaps": r.failing_gaps(),
        "joints": r.gaps.len(),
        "codes": codes,
        "ends": ends,
        "gaps": gaps,
        "omissions": omissions(r),
    })
}

/// The text of `summary.json` of a run of `setup` whose scenario is `(origin, text)`: the run's
/// summary, with `code_check` (this module) when the scenario of a bridge has a `[code_check]`
/// table — `{"not_evaluated": reason}` when it cannot be evaluated.
pub fn run_summary_json_text(
    setup: &Setup,
    sol: &crate::sim::bridge::BridgeSolution,
    scenario: (&str, &str),
) -> String {
    let mut v = setup.summary_json_value(sol);
    if let (crate::sim::scenario::Form::Bridge, Value::Object(o)) = (&setup.form, &mut v)
        && let Some(c) = scenario_check(&setup.run.problem.model, scenario)
    {
        let entry = match c {
            Ok(r) => summary_json(&r, &sol.summary.seats),
            Err(e) => json!({"not_evaluated": e}),
        };
        o.insert("code_check".into(), entry);
    }
    crate::output::json_text(v)
}
