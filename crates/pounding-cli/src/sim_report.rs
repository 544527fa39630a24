//! `report.html` of `pounding simulate` (two decks or a bridge): one self-contained page (inline
//! CSS, relative links only, no timestamps; scripts only in a bridge run's plan animation,
//! [`crate::sim_anim`]) with the run's status, its verdict first
//! ([`pounding::sim::output::verdict`]: pounding, governing seat, rotation, unseating, status,
//! warnings, code check), the model (the
//! scenario as run and the command-line replacements), the ground motion, the warnings, the
//! summary (the scalars of `summary.json` and one table per array: joints, abutments,
//! segments) and every figure the run drew.
//!
//! It is rendered from the `summary.json` text the run wrote, so every key there appears here
//! with the same value.

use crate::report::{CSS, esc};
use pounding::sim::table::Table;
use serde_json::Value;
use std::fmt::Write;

/// What the page shows besides `summary.json`.
pub struct ReportInput<'a> {
    /// `two decks` or `a bridge of N segments`.
    pub what: String,
    /// The scenario's name (path or `built-in default`) and text.
    pub scenario: (&'a str, &'a str),
    /// Command-line replacements as given (`--dt 1e-4`, `--law hertz`, ...).
    pub flags: Vec<String>,
    /// Figures (file names in the output directory), in the order drawn.
    pub figures: Vec<&'a str>,
    /// Data files written beside the page.
    pub files: &'a [&'a str],
    /// The trajectories JSON of a bridge run: the page then shows the plan animation
    /// ([`crate::sim_anim`]).
    pub animation: Option<&'a str>,
    /// The run's tables (`bearings`, `restrainers`, `joint_slip`, `segment_forces`, …): their
    /// peaks are shown.
    pub tables: &'a [Table],
    /// The code-check section of a bridge with `[code_check]` ([`crate::sim_report_check`]).
    pub code_check: Option<crate::sim_report_check::CodeCheckSection>,
    /// The run's answer in a few lines ([`pounding::sim::output::verdict`]), shown first.
    pub verdict: &'a [pounding::sim::output::VerdictLine],
}

/// The page, from the run's `summary.json` text.
pub fn report_html(input: &ReportInput, summary_json: &str) -> String {
    let summary: Value = serde_json::from_str(summary_json).unwrap_or(Value::Null);
    let mut h = String::with_capacity(1 << 16);
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>pounding \
         simulate report</title>\n<style>{CSS}</style>\n</head>\n<body>\n<h1>Seismic time \
         history of {} — simulate report</h1>\n",
        esc(&input.what)
    );
    let status = summary["status"].as_str().unwrap_or("unknown");
    let ok = status == "Completed";
    let _ = writeln!(
        h,
        "<p>Produced by <code>pounding simulate</code>, pounding version {}. Status: <strong \
         class=\"{}\">{}</strong>{}</p>",
        env!("CARGO_PKG_VERSION"),
        if ok { "v-reproduced" } else { "v-contradicted" },
        esc(status),
        if ok {
            String::new()
        } else {
            " — the run did not complete cleanly: its results are not trustworthy (see the \
             warnings and summary.json)."
                .to_string()
        }
    );
    let links: Vec<String> = input
        .files
        .iter()
        .map(|f| format!("<a href=\"{0}\">{0}</a>", esc(f)))
        .collect();
    let _ = writeln!(
        h,
        "<p>Data: {}. Numbers below are rounded to 6 significant digits; summary.json holds \
         them in full.</p>",
        links.join(", ")
    );

    let _ = writeln!(
        h,
        "<nav><a href=\"#verdict\">Verdict</a><a href=\"#warnings\">Warnings</a>{}{}<a href=\"#ground\">Ground motion</a><a \
         href=\"#summary\">Summary</a><a href=\"#tables\">Force histories</a><a \
         href=\"#figures\">Figures</a><a href=\"#model\">Model</a></nav>",
        match input.code_check {
            Some(_) => "<a href=\"#code-check\">Code check</a>",
            None => "",
        },
        if input.animation.is_some() {
            "<a href=\"#animation\">Animation</a>"
        } else {
            ""
        }
    );
    crate::sim_report_verdict::section(&mut h, input.verdict, input.code_check.as_ref(), &summary);
    warnings(&mut h, &summary);
    if let Some(c) = &input.code_check {
        h.push_str(&c.html);
    }
    if let Some(traj) = input.animation {
        h.push_str(&crate::sim_anim::section(traj));
    }
    let _ = writeln!(h, "<h2 id=\"ground\">Ground motion</h2>");
    object_tables(&mut h, &summary["ground_motion"]);
    let _ = writeln!(h, "<h2 id=\"summary\">Summary</h2>");
    let mut top = summary.clone();
    if let Some(m) = top.as_object_mut() {
        m.remove("ground_motion");
        m.remove("warnings");
    }
    object_tables(&mut h, &top);
    tables_section(&mut h, input.tables);
    let _ = writeln!(h, "<h2 id=\"figures\">Figures</h2>");
    if input.figures.is_empty() {
        h.push_str("<p>No figures.</p>\n");
    }
    for f in &input.figures {
        let _ = writeln!(
            h,
            "<figure><img src=\"{0}\" alt=\"{0}\"><figcaption>{0}</figcaption></figure>",
            esc(f)
        );
    }
    let _ = writeln!(h, "<h2 id=\"model\">Model</h2>");
    if input.flags.is_empty() {
        h.push_str("<p>No command-line replacements.</p>\n");
    } else {
        let _ = writeln!(
            h,
            "<p>Command-line replacements of the scenario: <code>{}</code></p>",
            esc(&input.flags.join(" "))
        );
    }
    let _ = writeln!(
        h,
        "<p>Scenario: <code>{}</code></p>\n<pre>{}</pre>\n</body>\n</html>",
        esc(input.scenario.0),
        esc(input.scenario.1)
    );
    h
}

/// `summary.json`'s `warnings` list, one sentence each.
fn warnings(h: &mut String, summary: &Value) {
    let _ = writeln!(h, "<h2 id=\"warnings\">Warnings</h2>");
    let mut items: Vec<String> = Vec::new();
    if let Some(list) = summary["warnings"].as_array() {
        items.extend(list.iter().map(|w| match w {
            Value::String(s) => esc(s),
            other => esc(&pounding::sim::output::warning_sentence(other)),
        }));
    }
    if items.is_empty() {
        let _ = writeln!(
            h,
            "<p>{}</p>",
            crate::sim_report_verdict::no_warnings(summary)
        );
    } else {
        h.push_str("<ul>\n");
        for w in items {
            let _ = writeln!(h, "<li>{w}</li>");
        }
        h.push_str("</ul>\n");
    }
}

/// A number with 6 significant digits (integers as they are).
fn sig6(n: &serde_json::Number) -> String {
    match n.as_f64() {
        Some(x) if !n.is_i64() && !n.is_u64() && x != 0.0 && x.is_finite() => sig6_of(x),
        _ => n.to_string(),
    }
}

/// `x` to 6 significant digits (positional from 1e-3 to 1e7, else exponent form); `0`, `nan`,
/// `inf` as the shortest float token.
pub(crate) fn sig6_of(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return pounding::output::float_token(x);
    }
    let e = x.abs().log10().floor() as i32;
    if (-3..7).contains(&e) {
        let t = format!("{x:.*}", (5 - e).max(0) as usize);
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    } else {
        format!("{x:.5e}")
    }
}

/// A JSON value as text: strings bare, numbers to 6 significant digits, `null` as `–`, nested
/// values as JSON.
fn cell(v: &Value) -> String {
    match v {
        Value::Null => "–".into(),
        Value::String(s) => esc(s),
        Value::Number(n) => sig6(n),
        Value::Array(a)
            if a.iter()
                .all(|x| x.is_number() || x.is_null() || x.is_array()) =>
        {
            let v: Vec<String> = a.iter().map(cell).collect();
            format!("[{}]", v.join(", "))
        }
        Value::Bool(b) => b.to_string(),
        other => esc(&other.to_string()),
    }
}

/// An object's scalar entries as a two-column table, then each array of objects as a table
/// (one row per element, one column per key) and each nested object the same way.
fn object_tables(h: &mut String, v: &Value) {
    let Some(m) = v.as_object() else {
        let _ = writeln!(h, "<p>{}</p>", cell(v));
        return;
    };
    let scalars: Vec<(&String, &Value)> = m
        .iter()
        .filter(|(_, x)| {
            !(x.is_object() || x.as_array().is_some_and(|a| a.iter().any(Value::is_object)))
        })
        .collect();
    if !scalars.is_empty() {
        h.push_str("<table>\n");
        for (k, x) in scalars {
            let _ = writeln!(
                h,
                "<tr><th class=\"l\">{}</th><td class=\"l\">{}</td></tr>",
                esc(k),
                cell(x)
            );
        }
        h.push_str("</table>\n");
    }
    for (k, x) in m {
        if let Some(rows) = x.as_array().filter(|a| a.iter().any(Value::is_object)) {
            let _ = writeln!(h, "<h3>{}</h3>", esc(k));
            // the abutments are [start, end]
            let names: &[&str] = if k == "abutments" {
                &["start", "end"]
            } else {
                &[]
            };
            array_table(h, rows, names);
        } else if x.is_object() {
            let _ = writeln!(h, "<h3>{}</h3>", esc(k));
            object_tables(h, x);
        }
    }
}

/// Rows of objects (`null` rows shown as absent) as one table; the first column is the row's
/// name from `names`, else its 1-based index.
fn array_table(h: &mut String, rows: &[Value], names: &[&str]) {
    let mut keys: Vec<&String> = Vec::new();
    for r in rows.iter().filter_map(Value::as_object) {
        for k in r.keys() {
            if !keys.contains(&k) {
                keys.push(k);
            }
        }
    }
    h.push_str("<div class=\"scroll\"><table>\n<tr><th>#</th>");
    for k in &keys {
        // a key breaks after its underscores, so that a wide table fits the page
        let _ = write!(h, "<th>{}</th>", esc(k).replace('_', "_<wbr>"));
    }
    h.push_str("</tr>\n");
    for (i, r) in rows.iter().enumerate() {
        let _ = match names.get(i) {
            Some(n) => write!(h, "<tr><td>{n}</td>"),
            None => write!(h, "<tr><td>{}</td>", i + 1),
        };
        match r.as_object() {
            Some(o) => {
                for k in &keys {
                    let _ = write!(h, "<td>{}</td>", o.get(*k).map_or("–".into(), cell));
                }
            }
            None => {
                let _ = write!(
                    h,
                    "<td class=\"l\" colspan=\"{}\">absent</td>",
                    keys.len().max(1)
                );
            }
        }
        h.push_str("</tr>\n");
    }
    h.push_str("</table></div>\n");
}

/// The peaks of the run's tables: per table (linked to its CSV) one row per element (the column
/// name up to its last `_`: `segment1_bearing2`, `joint1_restrainer1`, `joint1`) and one column
/// per quantity (`ux`, `fx`, `elongation`, …): the largest `|value|` over the kept steps and
/// when it was first reached.
fn tables_section(h: &mut String, tables: &[Table]) {
    let _ = writeln!(h, "<h2 id=\"tables\">Force histories</h2>");
    if tables.is_empty() {
        h.push_str("<p>No force histories.</p>\n");
    }
    for t in tables {
        let file = t.file_name();
        let _ = writeln!(
            h,
            "<h3>{}</h3>\n<p><a href=\"{1}\">{1}</a>: {2} rows × {3} columns. Largest |value| of \
             each quantity and the time [s] it was first reached.</p>",
            esc(t.name),
            esc(&file),
            t.rows(),
            t.columns.len()
        );
        // (element, [(quantity with unit, column)])
        let mut groups: Vec<(&str, Vec<(String, usize)>)> = Vec::new();
        let mut quantities: Vec<String> = Vec::new();
        for (c, col) in t.columns.iter().enumerate().skip(1) {
            let (element, q) = col.name.rsplit_once('_').unwrap_or(("", col.name.as_str()));
            let q = if col.unit.is_empty() {
                q.to_string()
            } else {
                format!("{q} [{}]", col.unit)
            };
            if !quantities.contains(&q) {
                quantities.push(q.clone());
            }
            match groups.iter_mut().find(|(e, _)| *e == element) {
                Some((_, cols)) => cols.push((q, c)),
                None => groups.push((element, vec![(q, c)])),
            }
        }
        if groups.is_empty() {
            h.push_str("<p>No elements of this kind in the model.</p>\n");
            continue;
        }
        h.push_str("<div class=\"scroll\"><table>\n<tr><th class=\"l\">element</th>");
        for q in &quantities {
            let _ = write!(h, "<th>{}</th>", esc(q));
        }
        h.push_str("</tr>\n");
        for (element, cols) in &groups {
            let _ = write!(h, "<tr><td class=\"l\">{}</td>", esc(element));
            for q in &quantities {
                let cell = cols.iter().find(|(name, _)| name == q).map_or_else(
                    || "–".to_string(),
                    |&(_, c)| {
                        let (peak, at) = column_peak(t, c);
                        format!("{} ({})", sig6_of(peak), sig6_of(at))
                    },
                );
                let _ = write!(h, "<td>{}</td>", esc(&cell));
            }
            h.push_str("</tr>\n");
        }
        h.push_str("</table></div>\n");
    }
}

/// The largest `|value|` of column `c` of `t` and the time (column 0) it was first reached
/// (NaN values are skipped; `(NaN, NaN)` for a column without a number).
fn column_peak(t: &Table, c: usize) -> (f64, f64) {
    let mut best = (f64::NAN, f64::NAN);
    for r in 0..t.rows() {
        let row = t.row(r);
        let v = row[c].abs();
        if !v.is_nan() && (best.0.is_nan() || v > best.0) {
            best = (v, row[0]);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use pounding::sim::table::Column;

    /// Elements and quantities are split at the last `_`; each cell is the largest |value| and
    /// the first time it was reached; NaN values are skipped; a table without element columns
    /// says so.
    #[test]
    fn force_history_peaks_are_the_largest_magnitudes_and_their_times() {
        let mut t = Table::with_time(
            "bearings",
            vec![
                Column::new("segment1_bearing1_fx", "N"),
                Column::new("segment1_bearing1_ux", "m"),
                Column::new("segment2_bearing1_fx", "N"),
            ],
        );
        t.values.extend([0.0, 1.0, 0.5, f64::NAN]);
        t.values.extend([0.1, -3.0, 0.25, 2.0]);
        t.values.extend([0.2, 3.0, -0.75, 1.0]);
        assert_eq!(column_peak(&t, 1), (3.0, 0.1));
        assert_eq!(column_peak(&t, 2), (0.75, 0.2));
        assert_eq!(column_peak(&t, 3), (2.0, 0.1));
        let mut h = String::new();
        let empty = Table::with_time("restrainers", vec![]);
        tables_section(&mut h, &[t, empty]);
        assert!(h.contains("<th>fx [N]</th><th>ux [m]</th>"), "{h}");
        assert!(
            h.contains("<td class=\"l\">segment1_bearing1</td><td>3 (0.1)</td><td>0.75 (0.2)</td>"),
            "{h}"
        );
        assert!(
            h.contains("<td class=\"l\">segment2_bearing1</td><td>2 (0.1)</td><td>–</td>"),
            "{h}"
        );
        assert!(
            h.contains("<a href=\"restrainers.csv\">restrainers.csv</a>: 0 rows"),
            "{h}"
        );
        assert!(h.contains("No elements of this kind in the model."), "{h}");
    }
}
