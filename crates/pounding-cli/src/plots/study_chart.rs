//! The line chart of the study overview figures: one palette, a distinct marker per series,
//! dashes for a series drawn on top of an earlier one, the legend in its own strip right of the
//! plot (never over data), axes padded to a sensible minimum width (a 0.04 % spread is not drawn
//! as a steep trend) and tick labels without `-0`.

use crate::plot_style::{DrawResult, e, font};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
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
    /// Thin line (else thick).
    pub thin: bool,
}

/// The data range `[lo, hi]` widened to at least `max(min_span, 10 % of the larger magnitude)`
/// about its centre (1 when everything is 0), then padded by `pad` of the width on each side.
pub(crate) fn axis_range(lo: Real, hi: Real, min_span: Real, pad: Real) -> (Real, Real) {
    let mag = lo.abs().max(hi.abs());
    let mut floor = min_span.max(0.1 * mag);
    if floor <= 0.0 {
        floor = 1.0;
    }
    let (lo, hi) = if hi - lo < floor {
        let c = 0.5 * (lo + hi);
        (c - 0.5 * floor, c + 0.5 * floor)
    } else {
        (lo, hi)
    };
    let d = pad * (hi - lo);
    (lo - d, hi + d)
}

/// Tick label with as many decimals as ticks about `span / 8` apart need; never `-0`.
pub(crate) fn tick_label(v: Real, span: Real) -> String {
    let step = span / 8.0;
    let decimals = if step > 0.0 && step.is_finite() {
        (-step.log10().floor()).clamp(0.0, 6.0) as usize
    } else {
        0
    };
    let t = format!("{v:.decimals$}");
    match t.strip_prefix('-') {
        Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
        _ => t,
    }
}

/// Index of an earlier series that `k` coincides with (same x, y within `tol` everywhere).
fn coincides_with(series: &[Series], k: usize, tol: Real) -> Option<usize> {
    let a = &series[k].points;
    (0..k).find(|&j| {
        let b = &series[j].points;
        a.len() == b.len()
            && a.iter().zip(b).all(|(p, q)| {
                p.0 == q.0 && ((p.1 - q.1).abs() <= tol || (!p.1.is_finite() && !q.1.is_finite()))
            })
    })
}

/// Draws the marker `shape` (0 filled circle, 1 filled triangle, 2 open square, 3 cross,
/// 4 open circle) of `col` at `at` (pixels).
fn marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    at: (i32, i32),
    shape: usize,
    col: RGBColor,
) -> DrawResult {
    match shape % 5 {
        0 => area.draw(&Circle::new(at, 4, col.filled())),
        1 => area.draw(&TriangleMarker::new(at, 6, col.filled())),
        2 => area.draw(&Rectangle::new(
            [(at.0 - 5, at.1 - 5), (at.0 + 5, at.1 + 5)],
            col.stroke_width(2),
        )),
        3 => area.draw(&Cross::new(at, 5, col.stroke_width(2))),
        _ => area.draw(&Circle::new(at, 7, col.stroke_width(2))),
    }
    .map_err(e)
}

/// The markers of [`marker`] at the chart points `pts`.
fn chart_markers<DB: DrawingBackend>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    pts: &[(Real, Real)],
    shape: usize,
    col: RGBColor,
) -> DrawResult {
    let at = |p: &(Real, Real)| EmptyElement::at(*p);
    let r = match shape % 5 {
        0 => chart.draw_series(
            pts.iter()
                .map(|p| at(p) + Circle::new((0, 0), 4, col.filled())),
        ),
        1 => chart.draw_series(
            pts.iter()
                .map(|p| at(p) + TriangleMarker::new((0, 0), 6, col.filled())),
        ),
        2 => chart.draw_series(
            pts.iter()
                .map(|p| at(p) + Rectangle::new([(-5, -5), (5, 5)], col.stroke_width(2))),
        ),
        3 => chart.draw_series(
            pts.iter()
                .map(|p| at(p) + Cross::new((0, 0), 5, col.stroke_width(2))),
        ),
        _ => chart.draw_series(
            pts.iter()
                .map(|p| at(p) + Circle::new((0, 0), 7, col.stroke_width(2))),
        ),
    };
    r.map(|_| ()).map_err(e)
}

/// A line chart with its legend in a strip on the right. `y_min_span` is the smallest y-axis
/// width (in y units) below which the axis is widened rather than stretched over the data.
pub(crate) fn line_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Series],
    y_min_span: Real,
) -> DrawResult {
    let (mut x0, mut x1, mut y0, mut y1) = (
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::INFINITY,
        Real::NEG_INFINITY,
    );
    for p in series.iter().flat_map(|s| s.points.iter()) {
        if p.0.is_finite() && p.1.is_finite() {
            (x0, x1, y0, y1) = (x0.min(p.0), x1.max(p.0), y0.min(p.1), y1.max(p.1));
        }
    }
    if !(x0.is_finite() && y0.is_finite()) {
        area.draw(&Text::new(format!("{title}: no data"), (20, 20), font(16)))
            .map_err(e)?;
        return Ok(());
    }
    let (x0, x1) = axis_range(x0, x1, 0.0, 0.05);
    let (y0, y1) = axis_range(y0, y1, y_min_span, 0.08);
    let (xs, ys) = (x1 - x0, y1 - y0);
    let longest = series.iter().map(|s| s.label.chars().count()).max();
    let legend_w = (56 + 8 * longest.unwrap_or(0) as u32).clamp(120, 240);
    let (plot, legend) = area.split_horizontally(area.dim_in_pixel().0.saturating_sub(legend_w));
    let mut chart = ChartBuilder::on(&plot)
        .caption(title, font(17))
        .margin(10)
        .x_label_area_size(42)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| tick_label(*v, xs))
        .y_label_formatter(&|v| tick_label(*v, ys))
        .label_style(font(13))
        .axis_desc_style(font(15))
        .light_line_style(BLACK.mix(0.05))
        .draw()
        .map_err(e)?;
    let mut row = 40;
    for (k, sr) in series.iter().enumerate() {
        let col = palette(sr.color);
        let pts: Vec<(Real, Real)> = sr
            .points
            .iter()
            .copied()
            .filter(|p| p.1.is_finite())
            .collect();
        let w = if sr.thin { 1 } else { 3 };
        let under = coincides_with(series, k, 0.004 * ys);
        if under.is_some() {
            chart
                .draw_series(DashedLineSeries::new(
                    pts.clone(),
                    8,
                    6,
                    col.stroke_width(w + 1),
                ))
                .map_err(e)?;
        } else {
            chart
                .draw_series(LineSeries::new(pts.clone(), col.stroke_width(w)))
                .map_err(e)?;
        }
        chart_markers(&mut chart, &pts, k, col)?;
        // Legend row: line sample with its marker, then the label (and what it covers).
        let style = col.stroke_width(w);
        let sample = vec![(8, row + 7), (40, row + 7)];
        if under.is_some() {
            legend
                .draw(&PathElement::new(vec![(8, row + 7), (18, row + 7)], style))
                .map_err(e)?;
            legend
                .draw(&PathElement::new(vec![(28, row + 7), (40, row + 7)], style))
                .map_err(e)?;
        } else {
            legend.draw(&PathElement::new(sample, style)).map_err(e)?;
        }
        marker(&legend, (24, row + 7), k, col)?;
        legend
            .draw(&Text::new(sr.label.clone(), (46, row), font(13)))
            .map_err(e)?;
        row += 20;
        if let Some(j) = under {
            let note = format!("(dashed: on {})", series[j].label);
            legend
                .draw(&Text::new(note, (46, row - 3), font(11)))
                .map_err(e)?;
            row += 16;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tiny_spread_is_not_stretched_over_the_axis() {
        // 42.00 % to 42.017 % (0.04 % relative): the axis is at least 10 % of 42 wide.
        let (lo, hi) = axis_range(42.0, 42.017, 2.0, 0.0);
        assert!(hi - lo >= 4.2 - 1e-12, "{lo} {hi}");
        assert!(lo < 42.0 && hi > 42.017);
        // One value (or all zero): a finite, non-empty axis around it.
        let (lo, hi) = axis_range(60.0, 60.0, 0.0, 0.05);
        assert!(lo < 60.0 && hi > 60.0 && hi - lo >= 6.0);
        let (lo, hi) = axis_range(0.0, 0.0, 0.0, 0.0);
        assert_eq!((lo, hi), (-0.5, 0.5));
        // A wide range is only padded.
        assert_eq!(axis_range(0.0, 50.0, 2.0, 0.1), (-5.0, 55.0));
    }

    #[test]
    fn tick_labels_never_read_minus_zero() {
        assert_eq!(tick_label(-0.0, 10.0), "0");
        assert_eq!(tick_label(-1e-17, 1.0), "0.0");
        assert_eq!(tick_label(-0.0004, 0.1), "0.00");
        assert_eq!(tick_label(-2.0, 10.0), "-2");
        // Ticks about span / 8 = 0.125 apart: one decimal.
        assert_eq!(tick_label(0.5, 1.0), "0.5");
    }

    #[test]
    fn coinciding_series_are_found() {
        let s = |y: [Real; 2]| Series {
            label: String::new(),
            points: vec![(0.0, y[0]), (1.0, y[1])],
            color: 0,
            thin: false,
        };
        let all = [
            s([1.0, 2.0]),
            s([1.0, 3.0]),
            s([1.001, 2.0]),
            s([Real::NAN, 3.0]),
        ];
        assert_eq!(coincides_with(&all, 1, 0.01), None);
        assert_eq!(coincides_with(&all, 2, 0.01), Some(0));
        assert_eq!(coincides_with(&all, 3, 0.01), None);
    }
}
