//! `report.html` of `pounding design`: the recommendation in words, the variants and their
//! overrides, the side-by-side table (fit, statistic, change with its paired and unpaired
//! intervals) and the figures.

use crate::hazard_report::{describe, sci};
use crate::report::{CSS, esc};
use pounding::assessment::design::Design;
use pounding::assessment::design_write::{Comparison, Stat, recommendation};
use pounding::assessment::study::Fits;
use std::fmt::Write;

fn num(stat: Stat, x: Option<f64>) -> String {
    match (stat, x) {
        (_, None) => "-".into(),
        (Stat::Maf, Some(v)) => sci(v),
        (Stat::Theta, Some(v)) => format!("{v:.4}"),
    }
}

fn interval(stat: Stat, i: Option<(f64, f64)>) -> String {
    i.map_or("-".into(), |(a, b)| {
        format!("{} to {}", num(stat, Some(a)), num(stat, Some(b)))
    })
}

/// The page.
pub(crate) fn report(
    design: &Design,
    fits: &[Fits],
    (stat, comps): (Stat, &[Comparison]),
    searched: Option<&pounding::assessment::design_search::SearchResult>,
) -> String {
    let base = &design.members[0];
    let st = &base.study;
    let mut h = String::with_capacity(1 << 14);
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>pounding \
         design report</title>\n<style>{CSS}</style>\n</head>\n<body>\n<h1>Retrofit comparison \
         — {}</h1>\n<p>Produced by <code>pounding design</code>, pounding version {}. Data: <a \
         href=\"variants.csv\">variants.csv</a>, <a href=\"variants.json\">variants.json</a>; \
         each variant's runs and fits in <code>variants/&lt;name&gt;/</code>.</p>\n",
        esc(&design.origin),
        env!("CARGO_PKG_VERSION")
    );
    let level = format!(
        "{} %",
        pounding::output::float_token(100.0 * st.settings.level)
    );
    let _ = write!(
        h,
        "<h2 id=\"answer\">Answer</h2>\n<p>{} bridges ({} and {} variants of {}) run on the \
         same {} records at the same {} stripes of {} (common random numbers: every variant sees \
         identical ground motions). Compared by {}; intervals at {level} from {} bootstrap \
         replicates over records, paired (the same records resampled for the variant and the {} \
         bridge) and, for contrast, unpaired.</p>\n<ul>\n",
        design.members.len(),
        esc(&base.name),
        design.members.len() - 1,
        esc(&design.scenario_path.display().to_string()),
        st.set.records.len(),
        match &st.settings.stripes {
            pounding::assessment::Stripes::Levels(v) | pounding::assessment::Stripes::Scales(v) =>
                v.len(),
        },
        esc(&st.spec.label()),
        match stat {
            Stat::Maf => "the mean annual frequency (MAF) of each limit state",
            Stat::Theta => "the median IM θ of each limit state (no hazard given: no MAF)",
        },
        st.settings.bootstrap,
        esc(&base.name),
    );
    for s in recommendation(design, fits, stat, comps) {
        let _ = writeln!(h, "<li>{}</li>", esc(&s));
    }
    h.push_str("</ul>\n");
    if let Some(hz) = design.hazard() {
        let _ = writeln!(h, "<p>Site hazard: {}.</p>", esc(&describe(hz)));
    }
    h.push_str("<h2>Variants</h2>\n<table>\n<tr><th>name</th><th>description</th><th>overrides</th></tr>\n");
    for m in &design.members {
        let _ = writeln!(
            h,
            "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"l\"><code>{}</code></td></tr>",
            esc(&m.name),
            esc(&m.description),
            if m.overrides.is_empty() {
                "(the scenario as written)".into()
            } else {
                esc(&m.overrides.join("; "))
            }
        );
    }
    let _ = write!(
        h,
        "</table>\n<h2>Side by side</h2>\n<table>\n<tr><th>variant</th><th>limit \
         state</th><th>status</th><th>θ [g]</th><th>β</th><th>{0}</th><th>{0} \
         interval</th><th>change</th><th>paired interval</th><th>unpaired \
         interval</th></tr>\n",
        if stat == Stat::Maf {
            "MAF [1/yr]"
        } else {
            "θ [g]"
        }
    );
    for c in comps {
        let r = &fits[c.member].rows[c.limit];
        let (t, b) = r.fit.params().map_or(("-".into(), "-".into()), |(t, b)| {
            (format!("{t:.4}"), format!("{b:.3}"))
        });
        let _ = writeln!(
            h,
            "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td><td>{}</td><td>{t}</td><td>{b}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            esc(&design.members[c.member].name),
            esc(&r.limit_state),
            esc(r.fit.status()),
            num(stat, c.value),
            interval(stat, c.interval),
            num(stat, c.diff),
            interval(stat, c.paired),
            interval(stat, c.unpaired),
        );
    }
    h.push_str("</table>\n<p>The change is the variant's value minus the as-built bridge's. The paired interval takes the difference replicate by replicate over the same resampled records; the unpaired one pairs independent resamples: the difference between the two widths is what the common records buy.</p>\n");
    if let Some(r) = searched {
        let _ = write!(
            h,
            "<h2 id=\"search\">Search</h2>\n<p>{}</p>\n<p>Every value run: <a href=\"search.csv\">search.csv</a> ({} evaluations, each a full set of runs on the same records).</p>\n",
            esc(&r.verdict),
            r.evaluations.len()
        );
    }
    h.push_str("<h2>Figures</h2>\n<p><img src=\"design.png\" alt=\"fragility curves of every variant\" width=\"1100\"></p>\n");
    if design.hazard().is_some() {
        h.push_str("<p><img src=\"hazard.png\" alt=\"deaggregation of the MAF by IM, every variant\" width=\"1100\"></p>\n");
    }
    h.push_str("</body>\n</html>\n");
    h
}
