//! `report.html` of `pounding study`: the index page (inline CSS, relative links only, no
//! scripts, no timestamps) with the claims of the paper next to this run's metrics, the summary
//! table, the overview figures, links to one page per geometry ([`crate::report_pages`]), the
//! scenario and the version.

use crate::figures::FigureGroup;
use pounding::output::float_token;
use pounding::study::{Study, StudyShape, Verdict};
use std::fmt::Write;

pub(crate) fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for ch in s.chars() {
        match ch {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            _ => o.push(ch),
        }
    }
    o
}

fn num(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else if x.is_infinite() {
        if x > 0.0 {
            "+∞".into()
        } else {
            "−∞".into()
        }
    } else {
        format!("{x:.3}")
    }
}

pub(crate) const CSS: &str = "body{font-family:sans-serif;max-width:1250px;margin:2em auto;padding:0 1em;color:#222;line-height:1.45}\
h1{font-size:1.6em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:2em}\
table{border-collapse:collapse;font-size:.85em}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}\
th{background:#f3f3f3;position:sticky;top:0}td.l,th.l{text-align:left}\
.v-reproduced{color:#17692f;font-weight:bold}.v-contradicted{color:#b01919;font-weight:bold}\
.v-partly{color:#9a6700;font-weight:bold}.v-not{color:#666}\
figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}figcaption{font-size:.9em;color:#444}\
pre{background:#f7f7f7;padding:1em;overflow-x:auto;font-size:.85em}\
.scroll{max-height:32em;overflow:auto;border:1px solid #ddd}nav a{margin-right:.8em}";

/// CSS of the study pages only (navigation bar, surfaces beside the region map), after [`CSS`].
const PAGES_CSS: &str = "nav.pages{display:flex;justify-content:space-between;background:#f3f3f3;padding:.4em .8em;margin:1em 0}\
nav.pages span{color:#888}body.geometry{max-width:1500px}\
.pair{display:grid;grid-template-columns:1fr 1fr;gap:1em;align-items:start}\
.pair .map{position:sticky;top:0}";

/// The start of a page: doctype, title, inline CSS.
/// `body_class` is empty or a CSS class of the body.
pub(crate) fn page_head(h: &mut String, title: &str, body_class: &str) {
    let class = if body_class.is_empty() {
        String::new()
    } else {
        format!(" class=\"{body_class}\"")
    };
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n<style>{CSS}{PAGES_CSS}</style>\n</head>\n<body{class}>\n",
        esc(title)
    );
}

/// One figure: the image linked to its full-size file, the caption and the SVG link. `up` is
/// the relative path from the page to the output directory (`""` or `"../"`).
pub(crate) fn figure_html(h: &mut String, f: &crate::figures::Figure, up: &str) {
    let svg = f
        .svg
        .as_ref()
        .map(|p| format!(" (<a href=\"{up}{}\">SVG</a>)", esc(p)))
        .unwrap_or_default();
    let _ = writeln!(
        h,
        "<figure><a href=\"{up}{p}\"><img src=\"{up}{p}\" alt=\"{c}\"></a><figcaption>{c}{svg}</figcaption></figure>",
        p = esc(&f.png),
        c = esc(&f.caption)
    );
}

/// The index page `report.html`: the claims of the paper against this run, the summary table,
/// the overview figures and links to one page per geometry ([`crate::report_pages`]).
/// `figures_drawn` is false when figures were disabled.
pub fn report_html(study: &Study, groups: &[FigureGroup], figures_drawn: bool) -> String {
    let s = &study.scenario;
    let mut h = String::with_capacity(1 << 16);
    page_head(&mut h, "pounding study report", "");
    let _ = writeln!(
        h,
        "<h1>Stick and slip at a single impact between {} bridge decks — study report</h1>",
        match s.shape {
            StudyShape::Curved => "S-curved",
            StudyShape::Straight => "straight",
            StudyShape::Skew => "skewed",
        }
    );
    let _ = writeln!(
        h,
        "<p>Produced by <code>pounding study</code>, pounding version {}. Physics as written out in the user guide, docs/guide/model.md (rigid decks, Newton restitution, Coulomb friction, ε_T = 0); the stick interval [L, U] bounds the pre-impact ratio r = γ_T⁻/γ_N⁻ for which the decks stick after impact: outward slip for r &lt; L, inward slip for r &gt; U.</p>",
        env!("CARGO_PKG_VERSION")
    );
    let dis = study.lcp_disagreements();
    let _ = writeln!(
        h,
        "<p>{} rows in <a href=\"bounds.csv\">bounds.csv</a> ({} configurations × {} cases × {} cells), {} summaries in <a href=\"summary.csv\">summary.csv</a> / <a href=\"summary.json\">summary.json</a>; scenario in <a href=\"scenario.toml\">scenario.toml</a>. Cross-check of the analytic modes against Lemke's method on the impact LCP: <strong>{}</strong>.</p>",
        study.rows.len(),
        s.configuration_count(),
        s.cases.len(),
        s.cell_count(),
        study.summaries.len(),
        if dis == 0 {
            "agrees in every cell".to_string()
        } else {
            format!("{dis} cells disagree (see lcp_agrees)")
        }
    );
    h.push_str("<nav><a href=\"#claims\">Claims of the paper</a><a href=\"#summary\">Summary table</a><a href=\"#figures\">Overview figures</a><a href=\"#geometries\">Geometries</a><a href=\"#scenario\">Scenario</a><a href=\"#conventions\">Conventions</a></nav>\n");

    claims_section(&mut h, study);
    summary_section(&mut h, study);
    figures_section(&mut h, study, groups, figures_drawn);

    // Scenario and conventions
    let _ = writeln!(
        h,
        "<h2 id=\"scenario\">Scenario</h2>\n<pre>{}</pre>",
        esc(&study.scenario_text)
    );
    h.push_str(CONVENTIONS);
    h.push_str("</body>\n</html>\n");
    h
}

/// The conventions section of the index page.
const CONVENTIONS: &str = "<h2 id=\"conventions\">Conventions</h2>\n<ul>\n\
<li>R is the centre-line radius; the decks form an S with centres of curvature on the joint line; θ counter-clockwise positive; the contact frame is attached to the struck face, the normal points from deck 2 to deck 1 and the tangent toward deck 1's radially outward side.</li>\n\
<li>Outward slip (γ_T⁺ &gt; 0, r &lt; L): after impact each deck slides away from its own centre of curvature; inward slip (r &gt; U): toward it.</li>\n\
<li>Joint-anchored placement: each deck turns about its own face midpoint; the first contact of a cell is decided geometrically (deck 1's inner corner iff θ1 &lt; −|θ2|, outer iff θ1 &gt; |θ2|, likewise for deck 2). Bounds are computed for every cell of every case; the flags mark physically possible ones.</li>\n\
<li>Degenerate cells (rows with <code>nan</code>): θ1 = θ2 is <em>parallel-faces</em> (line contact, including θ1 = θ2 = 0), θ1 = −θ2 ≠ 0 is <em>corner-corner</em> (normal not unique); the single-impact model does not apply there.</li>\n\
<li>lcp_agrees: Lemke's method on the single-contact impact LCP reproduces the analytic mode just below L, mid-interval and just above U.</li>\n</ul>\n";

/// Where the paper's Figures 3–8 are in this report (when the scenario contains their geometries).
fn paper_map(study: &Study, groups: &[FigureGroup]) -> String {
    let s = &study.scenario;
    let mut rows = String::new();
    for (fig, b1, b2) in [
        (3, 60.0, 60.0),
        (4, 60.0, 90.0),
        (5, 90.0, 60.0),
        (6, 90.0, 90.0),
    ] {
        if !(s.beta1_deg.contains(&b1) && s.beta2_deg.contains(&b2)) {
            continue;
        }
        let prefix = format!("g-b1-{}-b2-{}-", float_token(b1), float_token(b2));
        let links: Vec<String> = groups
            .iter()
            .filter(|g| g.id.starts_with(&prefix))
            .filter_map(|g| {
                let page = g.page(study)?;
                Some(format!("<a href=\"{}\">{}</a>", esc(&page), esc(&g.title)))
            })
            .collect();
        let _ = writeln!(
            rows,
            "<tr><td class=\"l\">Figure {fig} (β1 = {b1}°, β2 = {b2}°)</td><td class=\"l\">surface plots of {}</td></tr>",
            links.join(", ")
        );
    }
    if !rows.is_empty() {
        rows.push_str("<tr><td class=\"l\">Figures 7 and 8</td><td class=\"l\">the region maps on every geometry page: left column = deck 1 strikes (Figure 7), right column = deck 2 strikes (Figure 8)</td></tr>\n");
        format!(
            "<table>\n<tr><th class=\"l\">Paper</th><th class=\"l\">Here</th></tr>\n{rows}</table>\n"
        )
    } else {
        String::new()
    }
}

/// The paper's claims against this run (one table row per claim).
fn claims_section(h: &mut String, study: &Study) {
    h.push_str("<h2 id=\"claims\">The paper's claims against this run</h2>\n<table>\n<tr><th class=\"l\">Paper</th><th class=\"l\">This run measured</th><th class=\"l\">Verdict</th></tr>\n");
    for c in study.claims() {
        let class = match c.verdict {
            Verdict::Reproduced => "v-reproduced",
            Verdict::Contradicted => "v-contradicted",
            Verdict::Partly => "v-partly",
            Verdict::NotTested => "v-not",
        };
        let _ = writeln!(
            h,
            "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"l {class}\">{}</td></tr>",
            esc(c.claim),
            esc(&c.metric),
            esc(c.verdict.label())
        );
    }
    h.push_str("</table>\n<p>Verdicts follow from the metrics stated, computed under the project's specification (its conventions and modelling choices: joint-anchored placement, the σ mode of the scenario); where the numbers contradict the paper the table says so. The fractions are shares of the ratio range over first-contact cells only (summary.csv); stick shares do not depend on the sign convention of the tangent (reversing it maps [L, U] to [−U, −L]).</p>\n");
}

/// The summary table per configuration and case.
fn summary_section(h: &mut String, study: &Study) {
    h.push_str("<h2 id=\"summary\">Summary per configuration and case</h2>\n<p>Over first-contact cells: mean shares of the ratio range with outward slip, stick and inward slip; extremes of L and U; LCP disagreements over all cells.</p>\n");
    summary_table(h, study, |_| true);
}

/// The summary rows accepted by `keep`, as a scrolling table.
pub(crate) fn summary_table(
    h: &mut String,
    study: &Study,
    keep: impl Fn(&pounding::study::summary::SummaryRow) -> bool,
) {
    h.push_str("<div class=\"scroll\"><table>\n<tr>");
    let curved = study.scenario.shape == StudyShape::Curved;
    let geo_heads = if curved {
        ["β1 [°]", "β2 [°]", "R1 [m]", "R2 [m]"]
    } else {
        ["L1 [m]", "L2 [m]", "skew [°]", "shape"]
    };
    for c in geo_heads.into_iter().chain([
        "μ",
        "ε_N",
        "case",
        "first-contact cells",
        "stick",
        "outward",
        "inward",
        "L min",
        "L max",
        "U min",
        "U max",
        "LCP disagreements",
    ]) {
        let _ = write!(h, "<th>{c}</th>");
    }
    h.push_str("</tr>\n");
    for r in study.summaries.iter().filter(|r| keep(r)) {
        let geo = if curved {
            [r.beta1_deg, r.beta2_deg, r.r1_m, r.r2_m].map(float_token)
        } else {
            [
                float_token(r.l1_m),
                float_token(r.l2_m),
                float_token(r.skew_deg),
                r.shape.name().to_string(),
            ]
        };
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            geo[0],
            geo[1],
            geo[2],
            geo[3],
            float_token(r.mu),
            float_token(r.eps),
            r.case.name(),
            r.first_contact_cells,
            num(r.stick_fraction),
            num(r.outward_fraction),
            num(r.inward_fraction),
            num(r.lower_min),
            num(r.lower_max),
            num(r.upper_min),
            num(r.upper_max),
            r.lcp_disagreements
        );
    }
    h.push_str("</table></div>\n");
}

/// The overview figures and the list of geometry pages, or a note when figures were not drawn.
fn figures_section(h: &mut String, study: &Study, groups: &[FigureGroup], figures_drawn: bool) {
    h.push_str("<h2 id=\"figures\">Overview figures</h2>\n");
    if !figures_drawn {
        h.push_str("<p>Figures were not drawn in this run (<code>figures = false</code> or <code>--no-figures</code>), so there are no geometry pages.</p>\n<h2 id=\"geometries\">Geometries</h2>\n<p>No figures: see the summary table.</p>\n");
        return;
    }
    for g in groups.iter().filter(|g| g.geom.is_none()) {
        let _ = writeln!(h, "<p>{}. Click a figure for full size.</p>", esc(&g.title));
        for f in &g.figures {
            figure_html(h, f, "");
        }
    }
    h.push_str("<h2 id=\"geometries\">Geometries</h2>\n<p>One page per geometry: the stick surfaces L and U over θ1 × θ2 (one figure per μ) beside the region map of the same ε_N, and that geometry's rows of the summary table.</p>\n");
    h.push_str(&paper_map(study, groups));
    h.push_str("<ol>\n");
    for g in groups {
        if let Some(page) = g.page(study) {
            let _ = writeln!(
                h,
                "<li><a href=\"{}\">{}</a> ({} figures)</li>",
                esc(&page),
                esc(&g.title),
                g.figures.len()
            );
        }
    }
    h.push_str("</ol>\n");
}
