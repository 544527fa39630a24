//! The Verdict section of `report.html` of `pounding simulate`: the run's answers
//! ([`pounding::sim::output::verdict`]) as a table, the alarming ones in red, then the number of
//! warnings and the code check's verdict (with a link to its section).

use crate::report::esc;
use crate::sim_report_check::CodeCheckSection;
use pounding::sim::output::VerdictLine;
use serde_json::Value;
use std::fmt::Write;

/// The verdict: one row per question the run answers, the alarming ones in red, then the number
/// of warnings and whether a code check follows.
pub fn section(
    h: &mut String,
    verdict: &[VerdictLine],
    code_check: Option<&CodeCheckSection>,
    summary: &Value,
) {
    if verdict.is_empty() {
        return;
    }
    h.push_str(
        "<h2 id=\"verdict\">Verdict</h2>\n<table class=\"verdict\">\n<style>table.verdict \
         td{text-align:left}</style>\n",
    );
    for l in verdict {
        let _ = writeln!(
            h,
            "<tr><th>{}</th><td{}>{}</td></tr>",
            esc(l.topic),
            if l.alert {
                " class=\"v-contradicted\""
            } else {
                ""
            },
            esc(&l.text)
        );
    }
    let n = summary["warnings"].as_array().map_or(0, Vec::len);
    let completed = summary["status"].as_str() == Some("Completed");
    let _ = writeln!(
        h,
        "<tr><th>warnings</th><td{}>{}</td></tr>",
        if n > 0 || !completed {
            " class=\"v-contradicted\""
        } else {
            ""
        },
        if n == 0 {
            no_warnings(summary)
        } else {
            format!("{n} (see <a href=\"#warnings\">Warnings</a>).")
        }
    );
    if let Some(c) = code_check {
        let alarm = if c.verdict.starts_with("FAIL") {
            " class=\"v-contradicted\""
        } else {
            ""
        };
        let _ = writeln!(
            h,
            "<tr><th>code check</th><td{alarm}>{} See <a href=\"#code-check\">Code check</a>.</td></tr>",
            esc(&c.verdict)
        );
    }
    h.push_str("</table>\n");
}

/// The text for a run without warnings: `None.`, or, when the run did not complete, that its
/// status is the warning (a Diverged run lists no other).
pub(crate) fn no_warnings(summary: &Value) -> String {
    match summary["status"].as_str().unwrap_or("unknown") {
        "Completed" => "None.".to_string(),
        status => format!(
            "None besides the status: the run ended <strong class=\"v-contradicted\">{}</strong>, \
             so its results are not trustworthy (summary.json <code>status</code>).",
            esc(status)
        ),
    }
}
