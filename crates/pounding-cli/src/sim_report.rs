//! `report.html` of `pounding simulate` (two decks or a bridge): one self-contained page (inline
//! CSS, relative links only, no timestamps; scripts only in a bridge run's plan animation,
//! [`crate::sim_anim`]) with the run's status, the model (the
//! scenario as run and the command-line replacements), the ground motion, the warnings, the
//! summary (the scalars of `summary.json` and one table per array: joints, abutments,
//! segments) and every figure the run drew.
//!
//! It is rendered from the `summary.json` text the run wrote, so every key there appears here
//! with the same value.

use crate::report::{CSS, esc};
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
        "<nav><a href=\"#warnings\">Warnings</a>{}<a href=\"#ground\">Ground motion</a><a \
         href=\"#summary\">Summary</a><a href=\"#figures\">Figures</a><a \
         href=\"#model\">Model</a></nav>",
        if input.animation.is_some() {
            "<a href=\"#animation\">Animation</a>"
        } else {
            ""
        }
    );
    warnings(&mut h, &summary);
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
        h.push_str("<p>None.</p>\n");
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
        Some(x) if !n.is_i64() && !n.is_u64() && x != 0.0 && x.is_finite() => {
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
        _ => n.to_string(),
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
        let _ = write!(h, "<th>{}</th>", esc(k));
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
