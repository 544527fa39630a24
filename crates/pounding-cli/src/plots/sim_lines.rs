//! The time-history line panel of the `simulate` plots and its tick labels.

use crate::plot_style::{DrawResult, FAMILY, e, series_legend};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::Real;
use pounding::sim::Energy;

/// One line of a panel.
pub(crate) struct Series<'a> {
    /// Legend label.
    pub label: &'a str,
    /// `(t, y)` points (non-finite `y` skipped).
    pub pts: Vec<(Real, Real)>,
    /// Colour.
    pub color: RGBColor,
}

/// One line panel with a title, axis labels, legend and optional dashed horizontal lines.
pub(crate) fn line_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    ylabel: &str,
    t_end: Real,
    series: &[Series],
    hlines: &[(Real, &str, RGBColor)],
    legend: SeriesLabelPosition,
) -> DrawResult {
    let mut lo = Real::INFINITY;
    let mut hi = Real::NEG_INFINITY;
    for s in series {
        for &(_, y) in &s.pts {
            if y.is_finite() {
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
    }
    for (y, _, _) in hlines.iter().filter(|h| h.0.is_finite()) {
        lo = lo.min(*y);
        hi = hi.max(*y);
    }
    // finite, clamped bounds: an infinite axis range makes plotters' tick search loop forever
    let (lo, hi) = crate::figures::sane_range(lo, hi, (-1.0, 1.0));
    let pad = ((hi - lo) * 0.08).max(1e-12);
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FAMILY, 22))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d(0.0..t_end, (lo - pad)..(hi + pad))
        .map_err(e)?;
    let span = hi - lo + 2.0 * pad;
    chart
        .configure_mesh()
        .x_desc("time t [s]")
        .y_desc(ylabel)
        .y_label_formatter(&|v| tick(*v, span))
        .label_style((FAMILY, 15))
        .axis_desc_style((FAMILY, 16))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    for (y, label, c) in hlines {
        let c = *c;
        let drawn = chart
            .draw_series(DashedLineSeries::new(
                vec![(0.0, *y), (t_end, *y)],
                6,
                4,
                c.stroke_width(1),
            ))
            .map_err(e)?;
        if !label.is_empty() {
            drawn.label(*label).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(1))
            });
        }
    }
    for s in series {
        let c = s.color;
        chart
            .draw_series(LineSeries::new(
                s.pts.iter().copied().filter(|p| p.1.is_finite()),
                c.stroke_width(1),
            ))
            .map_err(e)?
            .label(s.label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    series_legend(&mut chart, legend, BLACK, 15)
}

/// Axis tick text: 3 significant digits relative to the axis span, no `-0`.
pub(crate) fn tick(v: Real, span: Real) -> String {
    if v.abs() < 1e-9 * span.abs() {
        return "0".into();
    }
    let digits = (2.0 - span.abs().log10().floor()).clamp(0.0, 12.0) as usize;
    let s = format!("{v:.digits$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".into()
    } else {
        s
    }
}

/// The energy-balance panel of `energy.png` (two-deck and bridge runs): seismic input, viscous
/// and contact dissipation, kinetic + strain energy and, with `elements`, the work on yielding
/// bearings and restrainers, in kJ; `energy[i]` at time `t[i]`.
pub(crate) fn energy_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    balance_error: Real,
    t_end: Real,
    t: &[Real],
    energy: &[Energy],
    elements: bool,
) -> DrawResult {
    use crate::plot_style::{BLUE, GREEN, ORANGE, RED};
    let en = |f: &dyn Fn(&Energy) -> Real| -> Vec<(Real, Real)> {
        t.iter()
            .zip(energy)
            .map(|(t, x)| (*t, f(x) / 1e3))
            .collect()
    };
    let mut series = vec![
        Series {
            label: "seismic input W_in",
            pts: en(&|e| e.input),
            color: BLACK,
        },
        Series {
            label: "viscous dissipation",
            pts: en(&|e| e.viscous),
            color: BLUE,
        },
        Series {
            label: "contact dissipation",
            pts: en(&|e| e.contact),
            color: RED,
        },
        Series {
            label: "kinetic + strain",
            pts: en(&|e| e.kinetic + e.potential),
            color: GREEN,
        },
    ];
    if elements {
        series.push(Series {
            label: "yielding bearings + restrainers (stored + dissipated)",
            pts: en(&|e| e.elements),
            color: ORANGE,
        });
    }
    line_panel(
        area,
        &format!(
            "Energy balance (relative error {balance_error:.1e}): input = stored + dissipated"
        ),
        "energy [kJ]",
        t_end,
        &series,
        &[],
        SeriesLabelPosition::UpperLeft,
    )
}
