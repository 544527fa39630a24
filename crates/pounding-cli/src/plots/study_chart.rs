//! The line chart of the study overview figures (one palette, markers per series).

use crate::plot_style::{DrawResult, e, font};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::Real;

pub(crate) fn palette(k: usize) -> RGBColor {
    const P: [RGBColor; 8] = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(127, 127, 127),
    ];
    P[k % P.len()]
}

/// One line of a line chart.
pub(crate) struct Series {
    /// Legend label.
    pub label: String,
    /// `(x, y)` points.
    pub points: Vec<(Real, Real)>,
    /// Palette index.
    pub color: usize,
    /// Thin line with triangles (else thick with circles).
    pub thin: bool,
}

/// A line chart with legend.
pub(crate) fn line_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Series],
    legend_pos: SeriesLabelPosition,
) -> DrawResult {
    let pts = series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|p| p.0.is_finite() && p.1.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::INFINITY,
        Real::NEG_INFINITY,
    );
    for p in pts {
        x0 = x0.min(p.0);
        x1 = x1.max(p.0);
        y0 = y0.min(p.1);
        y1 = y1.max(p.1);
    }
    if !(x0.is_finite() && y0.is_finite()) {
        area.draw(&Text::new(format!("{title}: no data"), (20, 20), font(16)))
            .map_err(e)?;
        return Ok(());
    }
    let dx = if x1 > x0 { 0.05 * (x1 - x0) } else { 1.0 };
    let dy = if y1 > y0 { 0.08 * (y1 - y0) } else { 1.0 };
    let mut chart = ChartBuilder::on(area)
        .caption(title, font(17))
        .margin(10)
        .x_label_area_size(42)
        .y_label_area_size(60)
        .build_cartesian_2d((x0 - dx)..(x1 + dx), (y0 - dy)..(y1 + dy))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .label_style(font(13))
        .axis_desc_style(font(15))
        .light_line_style(BLACK.mix(0.05))
        .draw()
        .map_err(e)?;
    for sr in series {
        let col = palette(sr.color);
        let pts: Vec<(Real, Real)> = sr
            .points
            .iter()
            .copied()
            .filter(|p| p.1.is_finite())
            .collect();
        let w = if sr.thin { 1 } else { 3 };
        chart
            .draw_series(LineSeries::new(pts.clone(), col.stroke_width(w)))
            .map_err(e)?
            .label(sr.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(w)));
        if sr.thin {
            chart
                .draw_series(
                    pts.into_iter()
                        .map(|p| TriangleMarker::new(p, 6, col.filled())),
                )
                .map_err(e)?;
        } else {
            chart
                .draw_series(pts.into_iter().map(|p| Circle::new(p, 4, col.filled())))
                .map_err(e)?;
        }
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .position(legend_pos)
        .draw()
        .map_err(e)?;
    Ok(())
}
