//! The code-check section of `simulate`'s `report.html` for a bridge scenario with a
//! `[code_check]` table: each seated end's code seats beside the run's demand on it
//! ([`pounding::assessment::check_run`]).

use crate::report::esc;
use pounding::assessment::check::CODES;
use pounding::assessment::check_run::against_run;
use pounding::assessment::check_write::overall;
use pounding::assessment::{CheckReport, CodeCheckInput, check_bridge};
use pounding::sim::bridge::{BridgeModel, SeatSummary};
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

/// The section, or `None` when the scenario has no `[code_check]` table (its errors were
/// reported before the run).
pub fn section(
    model: &BridgeModel,
    (origin, text): (&str, &str),
    seats: &[SeatSummary],
) -> Option<CodeCheckSection> {
    if !CodeCheckInput::is_present(text) {
        return None;
    }
    let input = CodeCheckInput::from_scenario(text, origin).ok()?;
    Some(match check_bridge(model, &input, origin) {
        Ok(r) => table(&r, seats),
        Err(e) => CodeCheckSection {
            verdict: format!("Not evaluated: {e}."),
            html: format!(
                "<h2 id=\"code-check\">Code check</h2>\n<p>Not evaluated: {}</p>\n",
                esc(&e.to_string())
            ),
        },
    })
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
         requires (<code>pounding check</code> gives the full table). {}</p>",
        overall(r),
        r.failing_ends(),
        r.ends.len(),
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
    h.push_str("<div class=\"scroll\"><table>\n<tr><th>end</th><th>support</th><th>seat [m]</th>");
    for c in CODES {
        let _ = write!(h, "<th>{} [m]</th>", esc(c.title()));
    }
    h.push_str(
        "<th>governing</th><th>code verdict</th><th>simulated peak [m]</th><th>residual \
         [m]</th><th>peak / seat</th><th>seat left [m]</th><th>peak vs design d</th></tr>\n",
    );
    for e in &rows {
        let c = e.check;
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
        let _ = writeln!(
            h,
            "<td>{}</td><td>{verdict}</td><td>{:.3}</td><td>{:.3}</td><td>{:.0} %</td>\
             <td>{:+.3}</td><td>{}</td></tr>",
            c.governing()
                .map_or("—".into(), |(k, v)| format!("{} {v:.3}", k.name())),
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
    let verdict = format!(
        "{}: {} of {} seated ends are shorter than a code requires{}.",
        overall(r),
        r.failing_ends(),
        r.ends.len(),
        if beyond > 0 {
            format!(
                "; at {beyond} end(s) the simulated peak exceeds the design displacement the \
                 codes were given"
            )
        } else {
            String::new()
        }
    );
    CodeCheckSection { verdict, html: h }
}
