//! The geometry pages of the study report, `report/<geometry id>.html`: one page per deck
//! geometry with its rows of the summary table and, per ε_N, the stick surfaces (one per μ)
//! beside the region map; navigation to the index and to the previous and next geometry. Every
//! page is self-contained like the index (inline CSS, relative links, no scripts, no timestamps).

use crate::figures::FigureGroup;
use crate::report::{esc, figure_html, page_head, summary_table};
use pounding::study::{Study, StudyShape};
use std::fmt::Write;

/// Every geometry page as `(path relative to the output directory, HTML)`, in group order.
pub fn geometry_pages(study: &Study, groups: &[FigureGroup]) -> Vec<(String, String)> {
    let geo: Vec<(&FigureGroup, String)> = groups
        .iter()
        .filter_map(|g| Some((g, g.page(study)?)))
        .collect();
    let name = |k: usize| geo[k].1.trim_start_matches("report/").to_string();
    (0..geo.len())
        .map(|k| {
            let prev = k.checked_sub(1).map(|j| (name(j), geo[j].0.title.as_str()));
            let next = (k + 1 < geo.len()).then(|| (name(k + 1), geo[k + 1].0.title.as_str()));
            let nav = nav_html(k, geo.len(), prev, next);
            (geo[k].1.clone(), page_html(study, geo[k].0, &nav))
        })
        .collect()
}

/// The navigation bar: previous geometry, index, next geometry.
fn nav_html(
    k: usize,
    n: usize,
    prev: Option<(String, &str)>,
    next: Option<(String, &str)>,
) -> String {
    let link = |target: Option<(String, &str)>, arrow_first: bool, none: &str| match target {
        Some((href, title)) if arrow_first => {
            format!("<a href=\"{}\">← {}</a>", esc(&href), esc(title))
        }
        Some((href, title)) => format!("<a href=\"{}\">{} →</a>", esc(&href), esc(title)),
        None => format!("<span>{none}</span>"),
    };
    format!(
        "<nav class=\"pages\">{}<a href=\"../report.html\">Index (geometry {} of {n})</a>{}</nav>\n",
        link(prev, true, "first geometry"),
        k + 1,
        link(next, false, "last geometry")
    )
}

/// Whether the summary row `r` belongs to geometry `g` (list indices).
fn same_geometry(study: &Study, g: [usize; 4], r: &pounding::study::summary::SummaryRow) -> bool {
    let s = &study.scenario;
    if s.shape == StudyShape::Curved {
        r.beta1_deg == s.beta1_deg[g[0]]
            && r.beta2_deg == s.beta2_deg[g[1]]
            && r.r1_m == s.r1_m[g[2]]
            && r.r2_m == s.r2_m[g[3]]
    } else {
        r.l1_m == s.l1_m[g[0]] && r.l2_m == s.l2_m[g[1]] && r.skew_deg == s.skew_deg[g[2]]
    }
}

/// One geometry page.
fn page_html(study: &Study, g: &FigureGroup, nav: &str) -> String {
    let mut h = String::with_capacity(1 << 14);
    page_head(
        &mut h,
        &format!("{} — pounding study report", g.title),
        "geometry",
    );
    h.push_str(nav);
    let _ = writeln!(h, "<h1>{}</h1>", esc(&g.title));
    let _ = writeln!(
        h,
        "<p>Width W = {} m. Surfaces (left): x = θ1, depth = θ2 (degrees), height = r = γ_T⁻/γ_N⁻; blue = lower bound L, red = upper bound U; saturated triangles are cells where that case is the real first contact, pale ones are kept for comparison; gaps lie on the degenerate diagonals θ1 = ±θ2. Region map (right, paper Figures 7–8): one row per μ, left column deck 1 strikes, right column deck 2 strikes. Click a figure for full size.</p>",
        crate::plots::study_style::tok(study.scenario.width)
    );
    if let Some(geom) = g.geom {
        h.push_str("<h2>Summary of this geometry</h2>\n");
        summary_table(&mut h, study, |r| same_geometry(study, geom, r));
    }
    let mut surfaces = Vec::new();
    for f in &g.figures {
        if !f.map {
            surfaces.push(f);
            continue;
        }
        let _ = writeln!(
            h,
            "<h2>{}</h2>\n<div class=\"pair\">\n<div>",
            esc(f.caption.rsplit(", ").next().unwrap_or(&f.caption))
        );
        for s in surfaces.drain(..) {
            figure_html(&mut h, s, "../");
        }
        h.push_str("</div>\n<div class=\"map\">\n");
        figure_html(&mut h, f, "../");
        h.push_str("</div>\n</div>\n");
    }
    h.push_str(nav);
    h.push_str("</body>\n</html>\n");
    h
}
