//! `fragility.png` of `pounding fragility`: per limit state the fitted lognormal curve, the
//! empirical fraction of exceedance per stripe (points; IDA: the fraction of records exceeded
//! at each scale's median IM) and the bootstrap band, on a log IM axis labelled at 1–2–5 steps
//! (the report around it: [`crate::fragility_report`]).

use crate::fragility_study::{Fits, Study};
use crate::plot_style::{
    BLUE, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_png, series_legend,
};
use plotters::prelude::*;
use pounding::assessment::run::{Plan, RunRow};
use pounding::math::Real;
use std::path::Path;

const COLOURS: [RGBColor; 5] = [BLUE, RED, GREEN, ORANGE, PURPLE];

pub(crate) use pounding::assessment::study::empirical;

/// Labels of a log axis over `[lo, hi]`: the 1–2–5 steps of each decade, or the finer
/// 1–1.5–2–3–5–7 steps when that gives fewer than four labels (a narrow IM range was labelled
/// only at 1 and 2 g), and the range's ends when even those give fewer than three.
/// The outline of a fit's bootstrap band (upper edge left to right, lower edge back), or `None`
/// with fewer than two points with an interval.
pub(crate) fn band_polygon(b: &pounding::fragility::Bootstrap) -> Option<Vec<(Real, Real)>> {
    let band: Vec<(Real, Real, Real)> = b
        .band
        .iter()
        .filter_map(|p| p.interval.map(|(a, z)| (p.im, a, z)))
        .collect();
    (band.len() > 1).then(|| {
        let mut poly: Vec<(Real, Real)> = band.iter().map(|p| (p.0, p.2)).collect();
        poly.extend(band.iter().rev().map(|p| (p.0, p.1)));
        poly
    })
}

pub(crate) fn log_key_points(lo: Real, hi: Real) -> Vec<Real> {
    let mut out = Vec::new();
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return out;
    }
    for steps in [&[1.0, 2.0, 5.0][..], &[1.0, 1.5, 2.0, 3.0, 5.0, 7.0]] {
        out.clear();
        let mut decade = 10.0_f64.powf(lo.log10().floor());
        while decade <= hi {
            // rounded to 12 significant digits: 3 × 0.1 is 0.30000000000000004
            out.extend(
                steps
                    .iter()
                    .map(|m| {
                        format!("{:.11e}", m * decade)
                            .parse::<Real>()
                            .unwrap_or(m * decade)
                    })
                    .filter(|v| (lo..=hi).contains(v)),
            );
            decade *= 10.0;
        }
        if out.len() >= 4 {
            break;
        }
    }
    if out.len() < 3 {
        // a range narrower than the steps: label its ends too (3 significant digits, inside)
        let sig3 = |x: Real| format!("{x:.2e}").parse::<Real>().unwrap_or(x);
        out.extend(
            [sig3(lo), sig3(hi)]
                .into_iter()
                .filter(|v| (lo..=hi).contains(v)),
        );
        out.sort_by(Real::total_cmp);
        out.dedup();
    }
    out
}

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
            .build_cartesian_2d(
                (lo..hi).log_scale().with_key_points(log_key_points(lo, hi)),
                0.0..1.0,
            )
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc(format!("{} [g]", st.spec.label()))
            .y_desc("probability of exceedance")
            .x_label_formatter(&|v| pounding::output::float_token(*v))
            .y_label_formatter(&|v| format!("{v:.1}"))
            .label_style((FAMILY, 15))
            .axis_desc_style((FAMILY, 17))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(e)?;
        for (l, f) in fits.rows.iter().enumerate() {
            let c = COLOURS[l % COLOURS.len()];
            if let Some(poly) = f.bootstrap.as_ref().and_then(band_polygon) {
                chart
                    .draw_series(std::iter::once(Polygon::new(poly, c.mix(0.15))))
                    .map_err(e)?;
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

#[cfg(test)]
mod tests {
    use super::log_key_points;

    #[test]
    fn log_axis_labels_every_decade_step_in_range() {
        assert_eq!(log_key_points(0.08, 2.6), vec![0.1, 0.2, 0.5, 1.0, 2.0]);
        // a narrow range takes the finer steps
        assert_eq!(log_key_points(0.9, 2.5), vec![1.0, 1.5, 2.0]);
        assert_eq!(log_key_points(0.25, 0.8), vec![0.3, 0.5, 0.7]);
        assert_eq!(log_key_points(0.01, 0.012), vec![0.01, 0.012]);
        assert_eq!(log_key_points(0.0111, 0.0119), vec![0.0111, 0.0119]);
        assert!(log_key_points(0.0, 1.0).is_empty());
        assert!(log_key_points(1.0, f64::INFINITY).is_empty());
    }
}
