//! `report.html` of `pounding fragility`: one self-contained page (inline CSS, no scripts, no
//! timestamps) that says what was run and what it gave — a lead paragraph with the fitted
//! medians, the scenario, the record set (pairs or single components, synthetic or not), the
//! limit states in words, the fits, the figure, and, for a scenario with a `[code_check]` table,
//! each seated end's code seats beside the demand of the runs on it.

use crate::fragility_study::{Fits, Study, boot_failed};
use crate::report::{CSS, esc};
use pounding::assessment::check_run::against_runs;
use pounding::assessment::check_write::overall;
use pounding::assessment::run::{Plan, RunRow};
use pounding::assessment::{CheckReport, Stripes};
use pounding::math::Real;
use pounding::output::float_token;
use pounding::sim::JointContact;
use std::fmt::Write;

/// `x` to 4 significant digits, `-` when absent.
fn g4(x: Option<Real>) -> String {
    x.map_or("-".into(), |v| format!("{v:.4}"))
}

/// A two-column table of `(key, value)` rows (values escaped).
fn kv_table(h: &mut String, rows: &[(&str, String)]) {
    h.push_str("<table>\n");
    for (k, v) in rows {
        let _ = writeln!(
            h,
            "<tr><th>{}</th><td class=\"l\">{}</td></tr>",
            esc(k),
            esc(v)
        );
    }
    h.push_str("</table>\n");
}

/// The page.
pub(crate) fn report(st: &Study, plan: &Plan, rows: &[RunRow], fits: &Fits) -> String {
    let mut h = String::with_capacity(1 << 15);
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>pounding \
         fragility report</title>\n<style>{CSS}</style>\n</head>\n<body>\n<h1>Fragility study — \
         {}</h1>\n<p>Produced by <code>pounding fragility</code>, pounding version {}. Data: \
         <a href=\"runs.csv\">runs.csv</a>, <a href=\"fragility.csv\">fragility.csv</a>, <a \
         href=\"fragility.json\">fragility.json</a>.</p>\n",
        esc(st.scenario_origin()),
        env!("CARGO_PKG_VERSION")
    );
    lead(&mut h, st, plan, rows, fits);
    scenario(&mut h, st);
    record_set(&mut h, st, plan, rows);
    limit_states(&mut h, st);
    fit_table(&mut h, rows, fits);
    h.push_str("<h2>Figure</h2>\n<p><img src=\"fragility.png\" alt=\"fragility curves\" width=\"1100\"></p>\n");
    h.push_str("<p>Lines: fitted lognormal curves; points: the fraction of runs exceeding per stripe; bands: pointwise bootstrap intervals over records. A status other than <code>ok</code> means the data have no finite fit, and no curve is drawn.</p>\n");
    if let (Some(hz), Some(m)) = (&st.hazard, st.maf(fits)) {
        let w = pounding::assessment::hazard_study::maf_warnings(&m);
        crate::hazard_report::section(&mut h, hz, &m, &w);
    }
    if let Some(c) = &st.code_check {
        code_check(&mut h, st, c, rows);
    }
    h.push_str("</body>\n</html>\n");
    h
}

/// The answer first: per limit state its median θ (or why there is none) and how often the
/// runs of the highest stripe exceeded it.
fn lead(h: &mut String, st: &Study, plan: &Plan, rows: &[RunRow], fits: &Fits) {
    let excluded = rows.iter().filter(|r| !r.trusted()).count();
    let top = plan.values().len().saturating_sub(1);
    let _ = write!(
        h,
        "<h2 id=\"answer\">Answer</h2>\n<p>{} runs ({} records × {} {}), {excluded} excluded \
         (failed or not trustworthy). ",
        rows.len(),
        st.set.records.len(),
        plan.values().len(),
        match plan.stripes {
            Stripes::Levels(_) => "IM levels",
            Stripes::Scales(_) => "scale factors",
        }
    );
    h.push_str("</p>\n<ul>\n");
    for (l, f) in fits.rows.iter().enumerate() {
        let at_top: Vec<bool> = rows
            .iter()
            .filter(|r| r.stripe == top)
            .filter_map(|r| r.limits[l].0)
            .collect();
        let exceeded = at_top.iter().filter(|&&x| x).count();
        let fit = match f.fit.params() {
            Some((t, b)) => format!(
                "half of the records exceed it at {} = {t:.3} g (median θ), dispersion β = \
                 {b:.2}",
                st.spec.label()
            ),
            None => format!("no finite fit ({})", f.fit.status()),
        };
        let _ = writeln!(
            h,
            "<li><strong>{}</strong>: {}; at the highest {} ({}{}) {exceeded} of {} counted runs \
             exceed it.</li>",
            esc(&f.limit_state),
            esc(&fit),
            match plan.stripes {
                Stripes::Levels(_) => "level",
                Stripes::Scales(_) => "scale",
            },
            plan.values()
                .get(top)
                .map_or("-".into(), |v| float_token(*v)),
            match plan.stripes {
                Stripes::Levels(_) => " g",
                Stripes::Scales(_) => "",
            },
            at_top.len()
        );
    }
    h.push_str("</ul>\n");
}

/// What was analysed: the scenario file and its bridge.
fn scenario(h: &mut String, st: &Study) {
    let m = &st.setup.problem.model;
    let g = &st.setup.problem.ground;
    let laws: std::collections::BTreeSet<&str> = m
        .joints
        .iter()
        .map(|j| &j.contact)
        .chain(m.abutments.iter().flatten().map(|a| &a.contact))
        .map(|c| match c {
            JointContact::Rigid => "rigid",
            JointContact::Compliance(c) => c.law.name(),
        })
        .collect();
    let abutments = match (m.abutments[0].is_some(), m.abutments[1].is_some()) {
        (true, true) => "at both ends",
        (true, false) => "at the start",
        (false, true) => "at the end",
        (false, false) => "none",
    };
    h.push_str("<h2 id=\"scenario\">Scenario</h2>\n");
    kv_table(
        h,
        &[
            ("file", st.scenario_origin().to_string()),
            (
                "bridge",
                format!(
                    "{} segment(s), {} joint(s), abutments {abutments}",
                    m.segments.len(),
                    m.joints.len()
                ),
            ),
            (
                "contact law",
                laws.into_iter().collect::<Vec<_>>().join(", "),
            ),
            (
                "ground motion",
                format!(
                    "an entry's x record acts along the bridge's y axis (normal to the joints) and \
                     its y record along the x axis, both turned by the incidence {} deg; scaled by \
                     the scenario's factors {} and {} times each run's factor",
                    float_token(g.incidence.to_degrees()),
                    float_token(g.scale_y),
                    float_token(g.scale_x)
                ),
            ),
        ],
    );
}

/// The record set: where it came from, pairs or single components, synthetic or recorded, and
/// how the runs were sampled.
fn record_set(h: &mut String, st: &Study, plan: &Plan, rows: &[RunRow]) {
    let n = st.set.records.len();
    let pairs = st.set.pair_entries();
    let synthetic = st.set.synthetic_entries();
    // known by the `model` metadata the generator writes on every record it makes (a manifest
    // says so; the records' own headers are not kept)
    let synth = match synthetic {
        0 => "not marked: no entry carries the `model` metadata that pounding motion synth writes \
              on the records it generates (a synthetic record listed without it is not \
              recognised)"
            .to_string(),
        k if k == n => format!(
            "yes: all {n} entries are marked as generated by pounding motion synth (`model = \
             {}` metadata: a stochastic model with an envelope, no magnitude, distance or site \
             physics)",
            pounding::ground_motion::set::SYNTHETIC_MODEL
        ),
        k => format!(
            "{k} of {n} entries are marked as generated by pounding motion synth (`model` \
             metadata); the others are not marked"
        ),
    };
    let excluded = rows.iter().filter(|r| !r.trusted()).count();
    h.push_str("<h2 id=\"records\">Record set</h2>\n");
    let mut t = vec![
        ("manifest", st.set_path.display().to_string()),
        (
            "entries",
            format!(
                "{n}: {pairs} horizontal pair(s), {} single component(s)",
                n - pairs
            ),
        ),
        ("synthetic", synth),
    ];
    if !st.set.name.is_empty() {
        t.push(("name", st.set.name.clone()));
    }
    if !st.set.source.is_empty() {
        t.push(("source", st.set.source.clone()));
    }
    t.push(("intensity measure", st.spec.label()));
    if let Some(p) = &st.period {
        t.push(("period", p.describe()));
    }
    t.push((
        match plan.stripes {
            Stripes::Levels(_) => "IM levels [g] (multiple stripes)",
            Stripes::Scales(_) => "scale factors (IDA)",
        },
        plan.values()
            .iter()
            .map(|v| float_token(*v))
            .collect::<Vec<_>>()
            .join(", "),
    ));
    t.push((
        "runs",
        format!(
            "{} ({excluded} excluded: failed or not trustworthy)",
            rows.len()
        ),
    ));
    t.push((
        "bootstrap",
        format!(
            "{} resamples over records, seed {}, level {}",
            st.settings.bootstrap, st.settings.seed, st.settings.level
        ),
    ));
    kv_table(h, &t);
}

/// Each limit state in words, with its capacity.
fn limit_states(h: &mut String, st: &Study) {
    h.push_str(
        "<h2 id=\"limit-states\">Limit states</h2>\n<table>\n<tr><th class=\"l\">name</th><th \
         class=\"l\">definition (demand / capacity = the ratio of runs.csv)</th></tr>\n",
    );
    for l in &st.limits {
        let _ = writeln!(
            h,
            "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td></tr>",
            esc(&l.state.name),
            esc(&l.definition())
        );
    }
    h.push_str("</table>\n");
}

/// The fits and the study's warnings (the fits' and the runs').
fn fit_table(h: &mut String, rows: &[RunRow], fits: &Fits) {
    h.push_str("<h2 id=\"fits\">Fits</h2>\n<div class=\"scroll\"><table>\n<tr><th>limit state</th><th>method</th><th>status</th><th>θ [g]</th><th>β</th><th>θ interval</th><th>β interval</th><th>bootstrap failed</th><th>records</th><th>runs</th></tr>\n");
    for f in &fits.rows {
        let (t, b) = f.fit.params().unzip();
        let bs = f.bootstrap.as_ref();
        let iv =
            |i: Option<(Real, Real)>| i.map_or("-".into(), |(a, z)| format!("{a:.4} – {z:.4}"));
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            esc(&f.limit_state),
            esc(f.method.as_str()),
            esc(f.fit.status()),
            g4(t),
            g4(b),
            iv(bs.and_then(|b| b.theta)),
            iv(bs.and_then(|b| b.beta)),
            esc(&boot_failed(f)),
            f.n_records,
            f.n_runs
        );
    }
    h.push_str("</table></div>\n");
    let warnings = pounding::assessment::study::fit_warnings(rows, fits);
    if !warnings.is_empty() {
        h.push_str("<h2>Warnings</h2>\n<ul>\n");
        for w in &warnings {
            let _ = writeln!(h, "<li>{}</li>", esc(w));
        }
        h.push_str("</ul>\n");
    }
}

/// The code check beside the runs: per seated end the code seats, the provided seat, and how
/// many runs displaced the end beyond the seat, the governing code seat and the design
/// displacement.
fn code_check(h: &mut String, st: &Study, c: &Result<CheckReport, String>, rows: &[RunRow]) {
    h.push_str("<h2 id=\"code-check\">Code check</h2>\n");
    let r = match c {
        Ok(r) => r,
        Err(e) => {
            let _ = writeln!(h, "<p>Not evaluated: {}</p>", esc(e));
            return;
        }
    };
    let seat_ends = st.setup.problem.model.seat_end_names();
    if rows.iter().any(|r| r.trusted()) && rows.iter().all(|r| !r.trusted() || r.seats.is_empty()) {
        // a store written with `[outputs] seats = false`: no demand to set against the seats
        let _ = writeln!(
            h,
            "<p>Code verdict: <strong>{}</strong> — {} of {} seated ends are shorter than a code \
             requires (<code>pounding check</code> gives the full table). The runs' seat \
             displacements were not stored (<code>[outputs] seats = false</code>): they are not \
             compared with the seats here.</p>",
            overall(r),
            r.failing_ends(),
            r.ends.len()
        );
        return;
    }
    let ends = against_runs(r, &seat_ends, rows);
    let beyond_code: usize = ends.iter().filter_map(|e| e.beyond_code).sum();
    let _ = writeln!(
        h,
        "<p>Code verdict: <strong>{}</strong> — {} of {} seated ends are shorter than a code \
         requires (<code>pounding check</code> gives the full table). {}</p>",
        overall(r),
        r.failing_ends(),
        r.ends.len(),
        if beyond_code > 0 {
            "<strong>In some runs an end moved farther than the longest seat a code asks for \
             (column “beyond code seat”)</strong>: at those intensities the simulated demand is \
             beyond what the codes' formulas allow for."
        } else {
            "In no trusted run did an end move farther than the governing code seat."
        }
    );
    crate::sim_report_check::end_table_head(
        h,
        "<th>largest simulated peak [m] (at IM [g])</th><th>largest peak / seat</th><th>runs \
         unseated</th><th>beyond code seat</th><th>beyond design d</th>",
    );
    let of = |k: Option<usize>, n: usize| k.map_or("—".into(), |k| format!("{k} of {n}"));
    for e in &ends {
        let c = e.check;
        crate::sim_report_check::end_row_start(h, c);
        let _ = writeln!(
            h,
            "<td>{}</td><td>{}</td><td>{} of {}</td><td>{}</td><td>{}</td></tr>",
            e.largest
                .map_or("—".into(), |(p, im)| format!("{p:.3} ({im:.3})")),
            e.largest.map_or("—".into(), |(p, _)| format!(
                "{:.0} %",
                100.0 * p / c.at.seat_length
            )),
            e.unseated,
            e.runs,
            of(e.beyond_code, e.runs),
            of(e.beyond_design, e.runs),
        );
    }
    h.push_str("</table></div>\n");
    h.push_str(&crate::sim_report_check::gaps_and_omissions(r));
}
