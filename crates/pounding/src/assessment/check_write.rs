//! The files and the printed table of a code check ([`super::check::CheckReport`]):
//! `check.csv` (one row per seated end), `check_gaps.csv` (one row per joint), `check.json`
//! (both, the inputs and the verdict) and the text `pounding check` prints. Lengths in metres,
//! angles in degrees; an empty CSV cell (`null` in JSON) is a requirement not evaluated.

use super::check::{CODES, CheckReport, Ec8End, Ec8Section, EndCheck, Requirement};
use super::check_input::{CodeCheckInput, DEFAULTS, PerSegment, PeriodInput};
use super::code_check::{AashtoZone, JraGround, Sdc, SpectrumType};
use crate::math::Real;
use crate::output::{float_token, json_float};
use serde_json::{Map, Value, json};

/// The files a check writes (cleared from the output directory before a run).
pub const CHECK_OUTPUTS: &[&str] = &["check.csv", "check_gaps.csv", "check.json"];

fn cell(x: Option<Real>) -> String {
    x.map(float_token).unwrap_or_default()
}

fn opt(x: Option<Real>) -> Value {
    x.map_or(Value::Null, json_float)
}

/// `PASS`, `FAIL`, or `NOT EVALUATED` when no code could be evaluated.
fn verdict(pass: Option<bool>) -> &'static str {
    match pass {
        Some(true) => "PASS",
        Some(false) => "FAIL",
        None => "NOT EVALUATED",
    }
}

/// `check.csv`: one row per seated end.
pub fn check_csv(r: &CheckReport) -> String {
    let mut s = String::from(
        "end,segment,support,seat_length_m,deck_length_m,skew_deg,subtended_deg,pier_height_m,aashto_l_m,aashto_h_m,displacement_m",
    );
    for c in CODES {
        s += &format!(",{}_m", c.name());
    }
    s += ",governing_code,governing_m,margin_m,verdict";
    s += ",ec8_d_g_m,ec8_l_m_m";
    for side in ["own", "other"] {
        if side == "other" {
            s += ",ec8_other_segment";
        }
        for t in ["l_eff", "d_eg", "d_es", "l_ov"] {
            s += &format!(",ec8_{side}_{t}_m");
        }
    }
    s += "\n";
    for e in &r.ends {
        let a = &e.at;
        s += &format!(
            "{},{},{},{},{},{},{},{},{},{},{}",
            a.end,
            a.segment + 1,
            a.support,
            float_token(a.seat_length),
            float_token(a.deck_length),
            float_token(a.skew_deg),
            cell(a.subtended_deg),
            float_token(e.pier_height),
            float_token(e.aashto_l_h.0),
            float_token(e.aashto_l_h.1),
            cell(e.displacement)
        );
        for (_, req) in &e.codes {
            s += &format!(",{}", cell(req.value()));
        }
        let g = e.governing();
        s += &format!(
            ",{},{},{},{}",
            g.map_or("", |(c, _)| c.name()),
            cell(g.map(|(_, v)| v)),
            cell(e.margin()),
            verdict(e.pass())
        );
        s += &ec8_cells(e.ec8.as_ref());
        s += "\n";
    }
    s
}

/// The EN 1998-2 cells of a `check.csv` row: `d_g`, `l_m`, the own section's `L_eff`, `d_eg`,
/// `d_es`, `l_ov`, the other section's segment (1-based) and the same four (empty off a joint
/// or when EN 1998-2 is not evaluated).
fn ec8_cells(e: Option<&Ec8End>) -> String {
    let four = |x: Option<&Ec8Section>| {
        let t = |f: fn(&Ec8Section) -> Real| cell(x.map(f));
        format!(
            ",{},{},{},{}",
            t(|x| x.l_eff),
            t(|x| x.terms.d_eg),
            t(|x| x.terms.d_es),
            t(|x| x.terms.l_ov)
        )
    };
    let own = e.map(|e| &e.own);
    let other = e.and_then(|e| e.other.as_ref());
    format!(
        ",{},{}{},{}{}",
        cell(own.map(|x| x.terms.d_g)),
        cell(own.map(|x| x.terms.l_m)),
        four(own),
        other.map_or(String::new(), |x| (x.segment + 1).to_string()),
        four(other)
    )
}

/// What the check does not include, for the reader: JRA's curved-bridge rotation term on a
/// bridge with curved segments.
pub fn omissions(r: &CheckReport) -> Vec<String> {
    let curved = r.ends.iter().any(|e| e.at.subtended_deg.is_some());
    let mut out = Vec::new();
    if curved {
        out.push(
            "JRA: the curved-bridge rotation term is not included (the segments' subtended \
             angles are reported only)"
                .to_string(),
        );
    }
    out
}

/// EN 1998-2's terms at an end for `check.json` and `summary.json`: per deck section (the end's
/// own first, then at a joint the other) its segment (1-based), `L_eff`, `d_g`, `d_eg`, `d_es`,
/// `l_m` and expression (6.11) `l_ov`; `null` when EN 1998-2 is not evaluated there.
pub fn ec8_sections_json(e: Option<&Ec8End>) -> Value {
    let Some(e) = e else {
        return Value::Null;
    };
    let section = |x: &Ec8Section| {
        json!({
            "segment": x.segment + 1,
            "l_eff_m": json_float(x.l_eff),
            "d_g_m": json_float(x.terms.d_g),
            "d_eg_m": json_float(x.terms.d_eg),
            "d_es_m": json_float(x.terms.d_es),
            "l_m_m": json_float(x.terms.l_m),
            "l_ov_m": json_float(x.terms.l_ov),
        })
    };
    Value::Array(
        std::iter::once(&e.own)
            .chain(&e.other)
            .map(section)
            .collect(),
    )
}

/// `check_gaps.csv`: one row per joint.
pub fn check_gaps_csv(r: &CheckReport) -> String {
    let mut s = String::from(
        "joint,gap_m,period_1_s,period_2_s,damping,srss_m,ddc_m,srss_verdict,ddc_verdict,verdict\n",
    );
    for g in &r.gaps {
        s += &format!(
            "joint{},{},{},{},{},{},{},{},{},{}\n",
            g.joint + 1,
            float_token(g.gap),
            cell(g.periods[0]),
            cell(g.periods[1]),
            float_token(g.damping),
            cell(g.srss.value()),
            cell(g.ddc.value()),
            verdict(g.pass_srss()),
            verdict(g.pass_ddc()),
            verdict(g.pass())
        );
    }
    s
}

fn requirements(e: &EndCheck) -> (Map<String, Value>, Map<String, Value>) {
    let (mut req, mut why) = (Map::new(), Map::new());
    for (c, r) in &e.codes {
        req.insert(c.name().into(), opt(r.value()));
        if let Requirement::NotEvaluated(m) = r {
            why.insert(c.name().into(), Value::String(m.clone()));
        }
    }
    (req, why)
}

fn per_segment(p: &PerSegment) -> Value {
    match p {
        PerSegment::All(x) => json_float(*x),
        PerSegment::Each(v) => Value::Array(v.iter().map(|&x| json_float(x)).collect()),
    }
}

/// The inputs as used, with the keys left at their defaults.
pub fn inputs_json(i: &CodeCheckInput) -> Value {
    json!({
        "ground": i.ground.map(|g| format!("{g:?}")),
        "a_gr_ms2": opt(i.a_gr),
        "spectrum_type": if i.spectrum == SpectrumType::Type1 { 1 } else { 2 },
        "importance_class": i.importance_class,
        "near_fault_factor": json_float(i.near_fault_factor),
        "l_m_m": json_float(i.l_m),
        "l_eff_m": opt(i.l_eff),
        "displacement_m": i.displacement.as_ref().map_or(Value::Null, per_segment),
        "period_s": match &i.period { PeriodInput::Model => Value::from("model"), PeriodInput::Given(p) => per_segment(p) },
        "damping": opt(i.damping),
        "pier_height_m": per_segment(&i.pier_height),
        "in_span_hinges": i.in_span_hinges.iter().map(|k| k + 1).collect::<Vec<_>>(),
        "aashto_zone": match i.aashto_zone { AashtoZone::Z1 => 1, AashtoZone::Z2 => 2, AashtoZone::Z3 => 3, AashtoZone::Z4 => 4 },
        "a_s": opt(i.a_s),
        "sdc": match i.sdc { Sdc::A => "A", Sdc::B => "B", Sdc::C => "C", Sdc::D => "D" },
        "delta_ps_m": json_float(i.caltrans[0]),
        "delta_crsh_m": json_float(i.caltrans[1]),
        "delta_temp_m": json_float(i.caltrans[2]),
        "jra_ground": match i.jra_ground { JraGround::I => "I", JraGround::II => "II", JraGround::III => "III" },
        "codes": i.codes.iter().map(|c| c.name()).collect::<Vec<_>>(),
        "at_default": i.defaulted(),
    })
}

/// The inputs as used: the damping is the one the gap rule used (the bridge's when the table
/// leaves it out), not a null.
fn inputs_used(r: &CheckReport) -> Value {
    let mut i = inputs_json(&r.input);
    if let (Some(g), Some(o)) = (r.gaps.first(), i.as_object_mut()) {
        o.insert("damping".into(), json_float(g.damping));
    }
    i
}

/// `check.json`: the scenario, the inputs, every end and joint, the counts and the verdict.
pub fn check_json(r: &CheckReport, scenario: &str) -> String {
    let ends: Vec<Value> = r
        .ends
        .iter()
        .map(|e| {
            let (req, why) = requirements(e);
            let g = e.governing();
            json!({
                "end": e.at.end, "segment": e.at.segment + 1, "support": e.at.support,
                "seat_length_m": json_float(e.at.seat_length),
                "deck_length_m": json_float(e.at.deck_length),
                "skew_deg": json_float(e.at.skew_deg),
                "subtended_deg": opt(e.at.subtended_deg),
                "pier_height_m": json_float(e.pier_height),
                "aashto_l_m": json_float(e.aashto_l_h.0),
                "aashto_h_m": json_float(e.aashto_l_h.1),
                "displacement_m": opt(e.displacement),
                "required_m": req, "not_evaluated": why,
                "ec8_sections": ec8_sections_json(e.ec8.as_ref()),
                "governing_code": g.map(|(c, _)| c.name()),
                "governing_m": opt(g.map(|(_, v)| v)),
                "margin_m": opt(e.margin()),
                "verdict": verdict(e.pass()),
            })
        })
        .collect();
    let gaps: Vec<Value> = r
        .gaps
        .iter()
        .map(|g| {
            let why = |q: &Requirement| match q {
                Requirement::NotEvaluated(m) => Value::String(m.clone()),
                Requirement::Required(_) => Value::Null,
            };
            json!({
                "joint": g.joint + 1, "gap_m": json_float(g.gap),
                "periods_s": [opt(g.periods[0]), opt(g.periods[1])],
                "damping": json_float(g.damping),
                "srss_m": opt(g.srss.value()), "ddc_m": opt(g.ddc.value()),
                "srss_not_evaluated": why(&g.srss), "ddc_not_evaluated": why(&g.ddc),
                "srss_verdict": verdict(g.pass_srss()),
                "ddc_verdict": verdict(g.pass_ddc()),
                "verdict": verdict(g.pass()),
            })
        })
        .collect();
    let mut v = json!({
        "scenario": scenario,
        "verdict": overall(r),
        "failing_ends": r.failing_ends(),
        "failing_gaps": r.failing_gaps(),
        "inputs": inputs_used(r),
        "ends": ends,
        "gaps": gaps,
        "omissions": omissions(r),
    });
    crate::output::json_without_negative_zero(&mut v);
    serde_json::to_string_pretty(&v).unwrap_or_default() + "\n"
}

/// `PASS` when every evaluated requirement is met, `FAIL` when one is not, `NOT EVALUATED`
/// when none could be evaluated.
pub fn overall(r: &CheckReport) -> &'static str {
    if r.failing_ends() + r.failing_gaps() > 0 {
        "FAIL"
    } else if r.ends.iter().any(|e| e.pass().is_some()) {
        "PASS"
    } else {
        "NOT EVALUATED"
    }
}

fn mm(x: Option<Real>) -> String {
    x.map_or("—".into(), |v| format!("{:.3}", v))
}

/// The text `pounding check` prints: the seat table (ends × codes), the reasons a code was not
/// evaluated, the gap table, the inputs left at their defaults and the verdict.
pub fn check_text(r: &CheckReport, scenario: &str) -> String {
    let mut s = format!("Code check of {scenario}: seat lengths [m]\n");
    s += &format!(
        "{:<16} {:<15} {:>6}  {:>6} {:>6} {:>6} {:>6} {:>6}  {:<12} {:>7}  verdict\n",
        "end", "support", "seat", "EC8", "LRFD", "Guide", "Caltr", "JRA", "governs", "margin"
    );
    for e in &r.ends {
        s += &format!(
            "{:<16} {:<15} {:>6.3} ",
            e.at.end, e.at.support, e.at.seat_length
        );
        for (_, q) in &e.codes {
            s += &format!(" {:>6}", mm(q.value()));
        }
        let g = e.governing();
        s += &format!(
            "  {:<12} {:>7}  {}\n",
            g.map_or("—", |(c, _)| c.name()),
            e.margin().map_or("—".into(), |m| format!("{m:+.3}")),
            verdict(e.pass())
        );
    }
    for (c, m) in r.not_evaluated() {
        s += &format!("  not evaluated — {}: {m}\n", c.title());
    }
    if !r.gaps.is_empty() {
        s += "\nJoint gaps [m] (verdict by the double-difference rule; SRSS without periods)\n";
        s += "joint     gap     T1 [s]  T2 [s]   SRSS    DDC     verdict\n";
        for g in &r.gaps {
            s += &format!(
                "joint{:<4} {:>6.3}  {:>6}  {:>6}  {:>6} {:>6}   {}\n",
                g.joint + 1,
                g.gap,
                mm(g.periods[0]),
                mm(g.periods[1]),
                mm(g.srss.value()),
                mm(g.ddc.value()),
                verdict(g.pass())
            );
        }
    }
    let d = r.input.defaulted();
    if !d.is_empty() {
        s += &format!("\nAt their defaults: {}\n", d.join(", "));
    }
    s += &format!(
        "\nVerdict: {} ({} of {} seated ends and {} of {} joint gaps fail an evaluated requirement)\n",
        overall(r),
        r.failing_ends(),
        r.ends.len(),
        r.failing_gaps(),
        r.gaps.len()
    );
    let skipped: Vec<String> = r
        .not_evaluated()
        .iter()
        .map(|(c, why)| format!("{} ({why})", c.title()))
        .collect();
    if !skipped.is_empty() {
        s += &format!("Not part of this verdict: {}\n", skipped.join(", "));
    }
    for o in omissions(r) {
        s += &format!("Not included: {o}\n");
    }
    s
}

impl CodeCheckInput {
    /// The keys of [`DEFAULTS`] that the file does not set.
    pub fn defaulted(&self) -> Vec<&'static str> {
        DEFAULTS
            .iter()
            .map(|(k, _)| *k)
            .filter(|k| !self.given.contains(k))
            .collect()
    }
}
