//! The code-check section of `simulate`'s `report.html` for a bridge scenario with a
//! `[code_check]` table: each seated end's code seats beside the run's demand on it
//! ([`pounding::assessment::check_run`]).

use crate::report::esc;
use pounding::assessment::CheckReport;
use pounding::assessment::check::CODES;
use pounding::assessment::check_run::against_run;
use pounding::assessment::check_write::overall;
use pounding::sim::bridge::SeatSummary;
use std::fmt::Write;

fn m3(x: Option<f64>) -> String {
    x.map_or("—".into(), |v| format!("{v:.3}"))
}

/// The code check of a run for its report: the verdict in one sentence (for the report's
/// Verdict) and the section's HTML.
pub struct CodeCheckSection {
    /// `FAIL: 10 of 10 seated ends are shorter than a code requires.` (plain text).
    pub verdict: String,
    /// The section.
    pub html: String,
}

/// The section of a run whose scenario's code check is `check`
/// ([`pounding::assessment::check_summary::scenario_check`]: `None` without `[code_check]`).
pub fn section(
    check: Option<&Result<CheckReport, String>>,
    seats: &[SeatSummary],
) -> Option<CodeCheckSection> {
    Some(match check? {
        Ok(r) => table(r, seats),
        Err(e) => CodeCheckSection {
            verdict: format!("Not evaluated: {e}."),
            html: format!(
                "<h2 id=\"code-check\">Code check</h2>\n<p>Not evaluated: {}</p>\n",
                esc(e)
            ),
        },
    })
}

/// Opens the per-end code table: the end, its support and seat, each code's seat, the governing
/// one and the verdict, then the report's own column headers `extra` (shared by the simulate
/// and fragility reports).
pub(crate) fn end_table_head(h: &mut String, extra: &str) {
    h.push_str("<div class=\"scroll\"><table>\n<tr><th>end</th><th>support</th><th>seat [m]</th>");
    for c in CODES {
        let _ = write!(h, "<th>{} [m]</th>", esc(c.title()));
    }
    let _ = writeln!(h, "<th>governing</th><th>code verdict</th>{extra}</tr>");
}

/// The cells of [`end_table_head`]'s shared columns for one end (the row is left open for the
/// report's own cells).
pub(crate) fn end_row_start(h: &mut String, c: &pounding::assessment::check::EndCheck) {
    let _ = write!(
        h,
        "<tr><td>{}</td><td>{}</td><td>{:.3}</td>",
        esc(&c.at.end),
        esc(&c.at.support),
        c.at.seat_length
    );
    for (_, q) in &c.codes {
        let _ = write!(h, "<td>{}</td>", m3(q.value()));
    }
    let verdict = match c.pass() {
        Some(true) => "PASS",
        Some(false) => "FAIL",
        None => "not evaluated",
    };
    let _ = write!(
        h,
        "<td>{}</td><td>{verdict}</td>",
        c.governing()
            .map_or("—".into(), |(k, v)| format!("{} {v:.3}", k.name()))
    );
}

/// Each joint's gap against the SRSS and double-difference requirements (a table), and what
/// the check leaves out: shared by the simulate and fragility reports.
pub(crate) fn gaps_and_omissions(r: &CheckReport) -> String {
    let mut h = String::new();
    if !r.gaps.is_empty() {
        h.push_str(
            "<p>Joint gaps (the double-difference rule decides; the SRSS, which ignores the \
             frames' correlation, beside it):</p>\n<table>\n<tr><th>joint</th><th>gap \
             [m]</th><th>SRSS [m]</th><th>double difference [m]</th><th>verdict</th></tr>\n",
        );
        for g in &r.gaps {
            let _ = writeln!(
                h,
                "<tr><td>joint{}</td><td>{:.3}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
                g.joint + 1,
                g.gap,
                m3(g.srss.value()),
                m3(g.ddc.value()),
                match g.pass() {
                    Some(true) => "PASS",
                    Some(false) => "FAIL",
                    None => "not evaluated",
                }
            );
        }
        h.push_str("</table>\n");
    }
    for o in pounding::assessment::check_write::omissions(r) {
        let _ = writeln!(h, "<p>Not included: {}.</p>", esc(&o));
    }
    h
}

fn table(r: &CheckReport, seats: &[SeatSummary]) -> CodeCheckSection {
    let rows = against_run(r, seats);
    let beyond = rows
        .iter()
        .filter(|e| e.beyond_design == Some(true))
        .count();
    let mut h = String::from("<h2 id=\"code-check\">Code check</h2>\n");
    let _ = writeln!(
        h,
        "<p>Code verdict: <strong>{}</strong> — {} of {} seated ends are shorter than a code \
         requires, {} of {} joint gaps narrower than required (<code>pounding check</code> gives \
         the full table). {}</p>",
        overall(r),
        r.failing_ends(),
        r.ends.len(),
        r.failing_gaps(),
        r.gaps.len(),
        if beyond > 0 {
            format!(
                "<strong>At {beyond} end(s) the simulated peak seat displacement exceeds the \
                 design displacement the codes were given (displacement_m)</strong>: the run's \
                 demand is beyond what their formulas allow for."
            )
        } else {
            String::new()
        }
    );
    end_table_head(
        &mut h,
        "<th>simulated peak [m]</th><th>residual [m]</th><th>peak / seat</th><th>seat left \
         [m]</th><th>peak vs design d</th>",
    );
    for e in &rows {
        end_row_start(&mut h, e.check);
        let _ = writeln!(
            h,
            "<td>{:.3}</td><td>{:.3}</td><td>{:.0} %</td><td>{:+.3}</td><td>{}</td></tr>",
            e.peak,
            e.residual,
            100.0 * e.ratio,
            e.seat_left,
            match e.beyond_design {
                Some(true) => "<strong>exceeds</strong>",
                Some(false) => "within",
                None => "no d given",
            }
        );
    }
    h.push_str("</table></div>\n");
    h.push_str(&gaps_and_omissions(r));
    let verdict = pounding::assessment::check_summary::verdict_sentence(r, seats);
    CodeCheckSection { verdict, html: h }
}
