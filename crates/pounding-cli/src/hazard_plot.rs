//! `hazard.png`: the deaggregation of each limit state's mean annual frequency by IM — the
//! integrand `P(x) |dλ/d ln x|` over the MAF (its share per unit `ln IM`), on a log IM axis.

use crate::fragility_plot::log_key_points;
use crate::plot_style::{
    BLUE, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_png, series_legend,
};
use plotters::prelude::*;
use pounding::assessment::hazard_study::{MafRow, deaggregation_ims};
use pounding::fragility::FragilityRow;
use pounding::fragility::hazard::{HazardCurve, deaggregation};
use pounding::math::Real;
use std::path::Path;

const COLOURS: [RGBColor; 5] = [BLUE, RED, GREEN, ORANGE, PURPLE];

/// One limit state's curve: label and `(IM, share)` points.
pub(crate) type Curve = (String, Vec<(Real, Real)>);

/// The deaggregation curves of every limit state with a MAF (label `name` or `prefix name`).
pub(crate) fn curves(
    hazard: &HazardCurve,
    fits: &[FragilityRow],
    mafs: &[MafRow],
    prefix: &str,
) -> Vec<Curve> {
    fits.iter()
        .zip(mafs)
        .filter_map(|(f, m)| {
            let (t, b) = f.fit.params()?;
            let rate = m.maf?.rate;
            let xs = deaggregation_ims(hazard, t, b);
            let d = deaggregation(hazard, t, b, &xs);
            let label = format!("{prefix}{} (MAF {:.3e}/yr)", f.limit_state, rate);
            Some((
                label,
                xs.into_iter()
                    .zip(d.into_iter().map(|v| v / rate))
                    .collect(),
            ))
        })
        .collect()
}

/// Draws `hazard.png` of `curves` against the IM labelled `im_label`.
pub(crate) fn plot(path: &Path, im_label: &str, curves: &[Curve]) -> DrawResult {
    register();
    let pts = curves.iter().flat_map(|c| c.1.iter());
    let (lo, hi, top) = pts.fold(
        (Real::INFINITY, 0.0 as Real, 0.0 as Real),
        |(a, b, t), p| (a.min(p.0), b.max(p.0), t.max(p.1)),
    );
    let (lo, hi) = if hi > lo && lo > 0.0 {
        (lo, hi)
    } else {
        (0.01, 1.0)
    };
    let top = if top > 0.0 && top.is_finite() {
        top * 1.1
    } else {
        1.0
    };
    save_png(path, (1100, 620), |root| {
        root.fill(&WHITE).map_err(e)?;
        let mut chart = ChartBuilder::on(root)
            .caption(
                "Deaggregation of the mean annual frequency by IM",
                (FAMILY, 24),
            )
            .margin(14)
            .x_label_area_size(48)
            .y_label_area_size(70)
            .build_cartesian_2d(
                (lo..hi).log_scale().with_key_points(log_key_points(lo, hi)),
                0.0..top,
            )
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc(format!("{im_label} [g]"))
            .y_desc("share of the MAF per unit ln IM")
            .x_label_formatter(&|v| pounding::output::float_token(*v))
            .y_label_formatter(&|v| format!("{v:.2}"))
            .label_style((FAMILY, 15))
            .axis_desc_style((FAMILY, 17))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(e)?;
        for (l, (label, pts)) in curves.iter().enumerate() {
            let c = COLOURS[l % COLOURS.len()];
            let dash = l / COLOURS.len();
            chart
                .draw_series(LineSeries::new(
                    pts.clone(),
                    c.stroke_width(3 - dash.min(1) as u32),
                ))
                .map_err(e)?
                .label(label.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(3))
                });
        }
        series_legend(
            &mut chart,
            SeriesLabelPosition::UpperRight,
            BLACK.mix(0.4),
            15,
        )
    })
}
