//! `design.png` of `pounding design`: per limit state (one panel each) the fitted fragility curve
//! and bootstrap band of every variant against the IM, the as-built bridge in black.

use crate::fragility_plot::{band_polygon, log_key_points};
use crate::plot_style::{
    BLUE, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_png, series_legend,
};
use plotters::prelude::*;
use pounding::assessment::design::Design;
use pounding::assessment::study::Fits;
use pounding::math::Real;
use std::path::Path;

const COLOURS: [RGBColor; 6] = [RGBColor(20, 20, 20), BLUE, RED, GREEN, ORANGE, PURPLE];

/// Draws `design.png`.
pub(crate) fn plot(path: &Path, design: &Design, fits: &[Fits]) -> DrawResult {
    register();
    let im = &fits[0].band_im;
    let (lo, hi) = (
        im.first().copied().unwrap_or(0.01),
        im.last().copied().unwrap_or(1.0),
    );
    let (lo, hi) = if hi > lo {
        (lo / 1.3, hi * 1.3)
    } else {
        (lo / 2.0, lo * 2.0)
    };
    let nl = fits[0].rows.len().max(1);
    save_png(path, (1100, 420 * nl as u32), |root| {
        root.fill(&WHITE).map_err(e)?;
        for (l, panel) in root.split_evenly((nl, 1)).iter().enumerate() {
            let name = fits[0].rows.get(l).map_or("", |r| r.limit_state.as_str());
            let mut chart = ChartBuilder::on(panel)
                .caption(
                    format!("{name}: P(exceeded | IM) of each variant"),
                    (FAMILY, 22),
                )
                .margin(12)
                .x_label_area_size(44)
                .y_label_area_size(60)
                .build_cartesian_2d(
                    (lo..hi).log_scale().with_key_points(log_key_points(lo, hi)),
                    0.0..1.0,
                )
                .map_err(e)?;
            chart
                .configure_mesh()
                .x_desc(format!("{} [g]", design.members[0].study.spec.label()))
                .y_desc("probability of exceedance")
                .x_label_formatter(&|v| pounding::output::float_token(*v))
                .y_label_formatter(&|v| format!("{v:.1}"))
                .label_style((FAMILY, 14))
                .axis_desc_style((FAMILY, 16))
                .light_line_style(RGBColor(235, 235, 235))
                .draw()
                .map_err(e)?;
            for (m, f) in fits.iter().enumerate() {
                let Some(r) = f.rows.get(l) else { continue };
                let c = COLOURS[m % COLOURS.len()];
                if let Some(poly) = r.bootstrap.as_ref().and_then(band_polygon) {
                    chart
                        .draw_series(std::iter::once(Polygon::new(poly, c.mix(0.10))))
                        .map_err(e)?;
                }
                let label = format!("{} ({})", design.members[m].name, r.fit.status());
                let pts: Vec<(Real, Real)> = f
                    .band_im
                    .iter()
                    .filter_map(|&x| r.fit.probability(x).map(|p| (x, p)))
                    .collect();
                chart
                    .draw_series(LineSeries::new(pts, c.stroke_width(3)))
                    .map_err(e)?
                    .label(label)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(3))
                    });
            }
            series_legend(
                &mut chart,
                SeriesLabelPosition::UpperLeft,
                BLACK.mix(0.4),
                14,
            )?;
        }
        Ok(())
    })
}
