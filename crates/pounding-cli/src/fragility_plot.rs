//! `fragility.png` and `report.html` of `pounding fragility`: per limit state the fitted
//! lognormal curve, the empirical fraction of exceedance per stripe (points; IDA: the
//! fraction of records exceeded at each scale's median IM) and the bootstrap band; one
//! self-contained page (inline CSS, no scripts, no timestamps) with the study, the table of fits
//! and the figure.

use crate::fragility_study::{Fits, Study, boot_failed};
use crate::plot_style::{
    BLUE, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_png, series_legend,
};
use crate::report::{CSS, esc};
use plotters::prelude::*;
use pounding::assessment::run::{Plan, RunRow};
use pounding::math::Real;
use std::fmt::Write;
use std::path::Path;

const COLOURS: [RGBColor; 5] = [BLUE, RED, GREEN, ORANGE, PURPLE];

pub(crate) use pounding::assessment::study::empirical;

/// Draws `fragility.png`: P(exceed) against the IM (log axis) for every limit state.
pub(crate) fn plot(
    path: &Path,
    st: &Study,
    plan: &Plan,
    rows: &[RunRow],
    fits: &Fits,
) -> DrawResult {
    register();
    let (lo, hi) = (
        fits.band_im.first().copied().unwrap_or(0.01),
        fits.band_im.last().copied().unwrap_or(1.0),
    );
    let (lo, hi) = if hi > lo {
        (lo / 1.3, hi * 1.3)
    } else {
        (lo / 2.0, lo * 2.0)
    };
    save_png(path, (1100, 720), |root| {
        root.fill(&WHITE).map_err(e)?;
        let mut chart = ChartBuilder::on(root)
            .caption(
                "Fragility curves: P(limit state exceeded | IM)",
                (FAMILY, 24),
            )
            .margin(14)
            .x_label_area_size(48)
            .y_label_area_size(64)
            .build_cartesian_2d((lo..hi).log_scale(), 0.0..1.0)
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc(format!("{} [g]", st.spec.label()))
            .y_desc("probability of exceedance")
            .x_label_formatter(&|v| {
                let t = format!("{v:.3}");
                t.trim_end_matches('0').trim_end_matches('.').to_string()
            })
            .y_label_formatter(&|v| format!("{v:.1}"))
            .label_style((FAMILY, 15))
            .axis_desc_style((FAMILY, 17))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(e)?;
        for (l, f) in fits.rows.iter().enumerate() {
            let c = COLOURS[l % COLOURS.len()];
            if let Some(b) = &f.bootstrap {
                let band: Vec<(Real, Real, Real)> = b
                    .band
                    .iter()
                    .filter_map(|p| p.interval.map(|(a, z)| (p.im, a, z)))
                    .collect();
                if band.len() > 1 {
                    let mut poly: Vec<(Real, Real)> = band.iter().map(|p| (p.0, p.2)).collect();
                    poly.extend(band.iter().rev().map(|p| (p.0, p.1)));
                    chart
                        .draw_series(std::iter::once(Polygon::new(poly, c.mix(0.15))))
                        .map_err(e)?;
                }
            }
            let label = format!("{} ({})", f.limit_state, f.fit.status());
            match f.fit.params() {
                Some(_) => {
                    let pts: Vec<(Real, Real)> = fits
                        .band_im
                        .iter()
                        .filter_map(|&x| f.fit.probability(x).map(|p| (x, p)))
                        .collect();
                    chart
                        .draw_series(LineSeries::new(pts, c.stroke_width(3)))
                        .map_err(e)?
                        .label(label)
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(3))
                        });
                }
                None => {
                    chart
                        .draw_series(std::iter::empty::<Circle<(Real, Real), i32>>())
                        .map_err(e)?
                        .label(label)
                        .legend(move |(x, y)| Circle::new((x + 10, y), 5, c.filled()));
                }
            }
            chart
                .draw_series(
                    empirical(plan, rows, l)
                        .into_iter()
                        // decreasing sizes: coinciding points of several limit states stay visible
                        .map(|(x, p, _)| Circle::new((x, p), 8 - 2 * (l as i32 % 3), c.filled())),
                )
                .map_err(e)?;
        }
        series_legend(
            &mut chart,
            SeriesLabelPosition::UpperLeft,
            BLACK.mix(0.4),
            16,
        )
    })
}

/// `x` to 4 significant digits, `-` when absent.
fn g4(x: Option<Real>) -> String {
    x.map_or("-".into(), |v| format!("{v:.4}"))
}

/// `report.html`: the study, the table of fits, the figure and the exclusions.
pub(crate) fn report(st: &Study, plan: &Plan, rows: &[RunRow], fits: &Fits) -> String {
    let mut h = String::with_capacity(1 << 14);
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
    let excluded = rows.iter().filter(|r| !r.trusted()).count();
    let _ = writeln!(h, "<h2>Study</h2>\n<table>");
    let mut row = |k: &str, v: String| {
        let _ = writeln!(h, "<tr><th>{}</th><td>{}</td></tr>", esc(k), esc(&v));
    };
    row(
        "record set",
        format!(
            "{} ({} entries) {}",
            st.set_path.display(),
            st.set.records.len(),
            st.set.name
        ),
    );
    row("intensity measure", st.spec.label());
    if let Some(p) = &st.period {
        row("period", p.describe());
    }
    row(
        match plan.stripes {
            pounding::assessment::Stripes::Levels(_) => "IM levels [g] (multiple stripes)",
            pounding::assessment::Stripes::Scales(_) => "scale factors (IDA)",
        },
        plan.values()
            .iter()
            .map(|v| pounding::output::float_token(*v))
            .collect::<Vec<_>>()
            .join(", "),
    );
    row(
        "runs",
        format!(
            "{} ({excluded} excluded: failed or not trustworthy)",
            rows.len()
        ),
    );
    row(
        "bootstrap",
        format!(
            "{} resamples over records, seed {}, level {}",
            st.settings.bootstrap, st.settings.seed, st.settings.level
        ),
    );
    h.push_str("</table>\n<h2>Fits</h2>\n<table>\n<tr><th>limit state</th><th>method</th><th>status</th><th>θ [g]</th><th>β</th><th>θ interval</th><th>β interval</th><th>bootstrap failed</th><th>records</th><th>runs</th></tr>\n");
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
    h.push_str("</table>\n");
    let warnings: Vec<String> = fits
        .rows
        .iter()
        .flat_map(pounding::fragility::FragilityRow::interval_warnings)
        .collect();
    if !warnings.is_empty() {
        h.push_str("<h2>Warnings</h2>\n<ul>\n");
        for w in &warnings {
            let _ = writeln!(h, "<li>{}</li>", esc(w));
        }
        h.push_str("</ul>\n");
    }
    h.push_str("<h2>Figure</h2>\n<p><img src=\"fragility.png\" alt=\"fragility curves\" width=\"1100\"></p>\n");
    h.push_str("<p>Lines: fitted lognormal curves; points: the fraction of runs exceeding per stripe; bands: pointwise bootstrap intervals over records. A status other than <code>ok</code> means the data have no finite fit, and no curve is drawn.</p>\n</body>\n</html>\n");
    h
}
