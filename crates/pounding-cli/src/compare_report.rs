//! `report.html` of `pounding compare` (two decks or a bridge): one self-contained page (inline
//! CSS, relative links only, no scripts) answering first whether the contact laws agree
//! ([`pounding::sim::compare::agreement`]: per law pounded or not, peak force — computed, or the
//! rigid law's estimate from the impulse —, closing, penetration, governing seat; the spread
//! between the laws), then the comparison tables (the CSV files' rows, numbers to 6 significant
//! digits), the overlay figures, every law's warnings (with every contact that created energy)
//! and the skipped laws with their reasons, the wall time per law and the scenario.
//!
//! The wall times are the page's only non-deterministic bytes; each stands between `<!--wall-->`
//! and `<!--/wall-->` (the golden tests mask them).

use crate::report::{CSS, esc};
use crate::sim_report::sig6_of;
use pounding::sim::compare::LawRun;
use pounding::sim::compare::agreement;
use std::fmt::Write;
use std::path::Path;
use std::time::Instant;

/// What the writers of either form need: the output directory, the runs, the scenario (name
/// and text) and flags as given, the start time.
pub(crate) struct Job<'a> {
    pub(crate) out: &'a Path,
    pub(crate) runs: &'a [LawRun],
    pub(crate) scenario: (&'a str, &'a str),
    pub(crate) flags: Vec<String>,
    pub(crate) t_start: Instant,
}

/// What the page shows besides the runs.
pub(crate) struct Page<'a> {
    /// The command's runs, output directory, scenario and flags.
    pub ctx: &'a Job<'a>,
    /// Data files written beside the page.
    pub files: &'a [&'a str],
    /// `(title, CSV text)` of each comparison table.
    pub tables: Vec<(&'a str, String)>,
    /// `(file, caption)` of each figure.
    pub figures: &'a [(&'a str, &'a str)],
}

/// CSS of this page only, after [`CSS`].
const PAGE_CSS: &str = ".fit{max-width:100%;overflow-x:auto}table.t td:first-child{text-align:left}\
ul.laws li{margin:.2em 0}td.skip{color:#888;text-align:left}";

/// A CSV cell for the page: numbers to 6 significant digits, text as it is, empty as `–`.
fn cell(token: &str) -> String {
    if token.is_empty() {
        return "–".into();
    }
    let numeric = token.parse::<f64>().ok().filter(|_| {
        token
            .bytes()
            .all(|b| b.is_ascii_digit() || b".-+eE".contains(&b))
            || matches!(token, "nan" | "inf" | "-inf")
    });
    match numeric {
        Some(x) if token.contains(['.', 'e']) => sig6_of(x),
        _ => esc(token),
    }
}

/// A CSV as a table: transposed (one column per row of the file, one row per column) when it
/// has at most 8 rows, so that a wide comparison fits the page; else as it is, scrolling
/// sideways within the page if it must.
fn csv_table(h: &mut String, csv: &str) {
    // the library's CSV (fields with a comma or a quote are quoted), read back by the csv crate
    let rows: Vec<Vec<String>> = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_reader(csv.as_bytes())
        .records()
        .filter_map(Result::ok)
        .map(|r| r.iter().map(String::from).collect())
        .collect();
    let Some((head, body)) = rows.split_first() else {
        return;
    };
    h.push_str("<div class=\"fit\"><table class=\"t\">\n");
    if body.len() <= 8 {
        let _ = write!(h, "<tr><th class=\"l\">{}</th>", esc(&head[0]));
        for r in body {
            let _ = write!(h, "<th>{}</th>", esc(&r[0]));
        }
        h.push_str("</tr>\n");
        for (c, name) in head.iter().enumerate().skip(1) {
            let _ = write!(h, "<tr><td>{}</td>", esc(name));
            for r in body {
                let v = r.get(c).map_or("", String::as_str);
                if name == "skipped_reason" && !v.is_empty() {
                    let _ = write!(h, "<td class=\"skip\">see Skipped laws</td>");
                } else {
                    let _ = write!(h, "<td>{}</td>", cell(v));
                }
            }
            h.push_str("</tr>\n");
        }
    } else {
        h.push_str("<tr>");
        for name in head {
            let _ = write!(h, "<th>{}</th>", esc(name));
        }
        h.push_str("</tr>\n");
        for r in body {
            h.push_str("<tr>");
            for v in r {
                let _ = write!(h, "<td>{}</td>", cell(v));
            }
            h.push_str("</tr>\n");
        }
    }
    h.push_str("</table></div>\n");
}

/// The page.
pub(crate) fn html(page: &Page) -> String {
    let ctx = page.ctx;
    let runs = ctx.runs;
    let mut h = String::with_capacity(1 << 15);
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>pounding \
         compare report</title>\n<style>{CSS}{PAGE_CSS}</style>\n</head>\n<body>\n<h1>Contact \
         laws compared — {}</h1>\n",
        esc(ctx.scenario.0)
    );
    let links: Vec<String> = page
        .files
        .iter()
        .map(|f| format!("<a href=\"{0}\">{0}</a>", esc(f)))
        .collect();
    let _ = writeln!(
        h,
        "<p>Produced by <code>pounding compare</code>, pounding version {}: the same scenario run \
         once per contact law. Data: {}. Numbers in the tables are rounded to 6 significant \
         digits; the CSV files hold them in full.</p>",
        env!("CARGO_PKG_VERSION"),
        links.join(", ")
    );
    h.push_str(
        "<nav><a href=\"#agree\">Do the laws agree?</a><a href=\"#tables\">Comparison</a><a \
         href=\"#figures\">Figures</a><a href=\"#warnings\">Warnings</a><a \
         href=\"#skipped\">Skipped laws</a><a href=\"#timing\">Wall time</a><a \
         href=\"#model\">Model</a></nav>\n",
    );
    let a = agreement(runs);
    let _ = writeln!(
        h,
        "<h2 id=\"agree\">Do the laws agree?</h2>\n<p>{}</p>\n<ul class=\"laws\">",
        esc(&a.overall.join(" "))
    );
    for (law, text) in &a.laws {
        let _ = writeln!(h, "<li><strong>{}</strong>: {}</li>", esc(law), esc(text));
    }
    let _ = writeln!(
        h,
        "</ul>\n<p>The compliance laws compute the contact force (column \
         <code>peak_contact_force</code>). Rigid contact resolves an impact instantaneously (an \
         impulse, no force): its force is an <em>estimate</em> (column \
         <code>peak_force_estimate</code>), the peak of a half-sine pulse carrying the impulse \
         over the elastic Hertz contact duration of the impact (column \
         <code>contact_time_estimate_s</code>) for a Hertz stiffness of {} N/m<sup>1.5</sup> per \
         joint or abutment; it is never mixed with the computed forces.</p>",
        sig6_of(pounding::contact_law::registry::default_k_h())
    );
    h.push_str("<h2 id=\"tables\">Comparison</h2>\n");
    for (title, csv) in &page.tables {
        let _ = writeln!(h, "<h3>{}</h3>", esc(title));
        csv_table(&mut h, csv);
    }
    h.push_str("<h2 id=\"figures\">Figures</h2>\n");
    for (file, caption) in page.figures {
        if ctx.out.join(file).is_file() {
            let _ = writeln!(
                h,
                "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a><figcaption>{1}</figcaption></figure>",
                esc(file),
                esc(caption)
            );
        }
    }
    warnings(&mut h, ctx);
    timing(&mut h, ctx);
    let _ = writeln!(
        h,
        "<h2 id=\"model\">Model</h2>\n<p>Command line: <code>pounding compare {}</code></p>\n\
         <p>Scenario: <code>{}</code></p>\n<pre>{}</pre>\n</body>\n</html>",
        esc(&ctx.flags.join(" ")),
        esc(ctx.scenario.0),
        esc(ctx.scenario.1)
    );
    h
}

/// The warnings: those every law that ran shares (the records' implausible PGAs, …) once, then
/// each law's own; then the skipped laws with their reasons.
fn warnings(h: &mut String, ctx: &Job) {
    h.push_str("<h2 id=\"warnings\">Warnings</h2>\n");
    let ran: Vec<(&str, Vec<&str>)> = ctx
        .runs
        .iter()
        .filter_map(|r| {
            let mut m: Vec<&str> = Vec::new();
            for w in &r.ran()?.warnings {
                if !m.contains(&w.message.as_str()) {
                    m.push(&w.message);
                }
            }
            Some((r.law.as_str(), m))
        })
        .collect();
    let shared: Vec<&str> = match ran.as_slice() {
        [(_, first), _, ..] => first
            .iter()
            .copied()
            .filter(|m| ran.iter().all(|(_, ms)| ms.contains(m)))
            .collect(),
        _ => Vec::new(),
    };
    let list = |h: &mut String, title: &str, ms: &[&str]| {
        let _ = writeln!(h, "<h3>{}</h3>\n<ul>", esc(title));
        for m in ms {
            let _ = writeln!(h, "<li>{}</li>", esc(m));
        }
        h.push_str("</ul>\n");
    };
    if !shared.is_empty() {
        list(h, "Every law", &shared);
    }
    let mut any = !shared.is_empty();
    for (law, ms) in &ran {
        let own: Vec<&str> = ms.iter().copied().filter(|m| !shared.contains(m)).collect();
        if !own.is_empty() {
            any = true;
            list(h, law, &own);
        }
    }
    any |= energy_contacts(h, ctx);
    if !any {
        h.push_str("<p>No law's run has a warning.</p>\n");
    }
    h.push_str("<h2 id=\"skipped\">Skipped laws</h2>\n");
    let skipped: Vec<_> = ctx
        .runs
        .iter()
        .filter_map(|r| Some((&r.law, r.outcome.as_ref().err()?)))
        .collect();
    if skipped.is_empty() {
        h.push_str("<p>Every law ran.</p>\n");
    } else {
        h.push_str("<ul>\n");
        for (law, why) in skipped {
            let _ = writeln!(h, "<li><strong>{}</strong>: {}</li>", esc(law), esc(why));
        }
        h.push_str("</ul>\n");
    }
}

/// Every contact that created energy, per law that ran (the entries of `simulate`'s
/// `summary.json` `"warnings"` for that law; the law's warning says only their number, total
/// and largest); whether any law had one.
fn energy_contacts(h: &mut String, ctx: &Job) -> bool {
    use pounding::output::float_token;
    let mut any = false;
    for r in ctx.runs {
        let Some(ran) = r.ran() else { continue };
        let created = ran.setup.run_warnings(&ran.sol);
        if created.is_empty() {
            continue;
        }
        any = true;
        let _ = writeln!(
            h,
            "<h3>{}: energy created, contact by contact</h3>\n<table>\n<tr><th \
             class=\"l\">contact</th><th class=\"l\">kind</th><th>impact</th><th>t [s]</th>\
             <th>energy created [J]</th></tr>",
            esc(&r.law)
        );
        for w in &created {
            let _ = writeln!(
                h,
                "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td><td>{}</td><td>{}</td>\
                 <td>{}</td></tr>",
                esc(&w.contact),
                esc(w.kind),
                w.impact,
                float_token(w.time),
                float_token(w.amount)
            );
        }
        h.push_str("</table>\n");
    }
    any
}

/// The wall time per law (between `<!--wall-->` markers: not deterministic).
fn timing(h: &mut String, ctx: &Job) {
    h.push_str(
        "<h2 id=\"timing\">Wall time</h2>\n<table>\n<tr><th class=\"l\">law</th><th>steps</th>\
         <th>wall time [s]</th></tr>\n",
    );
    for r in ctx.runs {
        if let Some(ran) = r.ran() {
            let _ = writeln!(
                h,
                "<tr><td class=\"l\">{}</td><td>{}</td><td><!--wall-->{:.3}<!--/wall--></td></tr>",
                esc(&r.law),
                ran.sol.steps,
                ran.seconds
            );
        }
    }
    let _ = writeln!(
        h,
        "</table>\n<p>The whole command so far: <!--wall-->{:.3}<!--/wall--> s (timing.json has \
         the final figure).</p>",
        ctx.t_start.elapsed().as_secs_f64()
    );
}
