//! `batch.png`: peak response against intensity per record (`simulate` batch runs).

use super::sim_lines::tick;
use crate::plot_style::{
    BLUE, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_white_png,
    series_legend,
};
use plotters::prelude::*;
use pounding::math::Real;
use std::path::Path;

/// One record's curve in the batch plot: `(PGA [g], value)` points sorted by PGA.
pub struct BatchCurve {
    /// Record name (legend).
    pub label: String,
    /// `(x, [governing seat ratio, joint opening, rotation, impacts])` per successful run.
    pub pts: Vec<(Real, [Real; 4])>,
}

const PALETTE: [RGBColor; 8] = [
    BLUE,
    RED,
    GREEN,
    ORANGE,
    PURPLE,
    RGBColor(23, 162, 184),
    RGBColor(140, 86, 75),
    RGBColor(120, 120, 120),
];

/// Smallest y range of the batch plot's rotation panel \[deg\].
pub const ROTATION_MIN_RANGE_DEG: Real = 1e-3;

/// The data range `(lo, hi)` of panel `k` of `batch.png` (0 is always included; the seat length
/// in panel 0; at least [`ROTATION_MIN_RANGE_DEG`] in the rotation panel 2).
fn batch_panel_range(k: usize, curves: &[BatchCurve], seat_length: Real) -> (Real, Real) {
    let mut lo: Real = 0.0;
    let mut hi = Real::NEG_INFINITY;
    for c in curves {
        for p in &c.pts {
            if p.1[k].is_finite() {
                lo = lo.min(p.1[k]);
                hi = hi.max(p.1[k]);
            }
        }
    }
    if k == 0 {
        hi = hi.max(seat_length);
    }
    if k == 2 && hi.is_finite() {
        // at least 1e-3 deg, so rounding noise (~1e-17 deg in symmetric cases) reads as 0
        hi = hi.max(lo + ROTATION_MIN_RANGE_DEG);
    }
    if !(hi.is_finite() && hi > lo) {
        hi = lo + 1.0;
    }
    crate::figures::sane_range(lo, hi, (0.0, 1.0))
}

/// `batch.png`: peak response against intensity (PGA of the applied component; of a pair the
/// larger of its two) per record, four panels (the governing seat ratio with the unseating line
/// at `seat_length` = 1, joint opening, plan rotation, impacts).
pub fn batch_plot(out: &Path, name: &str, curves: &[BatchCurve], seat_length: Real) -> DrawResult {
    register();
    let titles = [
        (
            "Governing seat: peak displacement / its own seat (dashed: 1, unseating)",
            "peak / seat [-]",
        ),
        ("Peak joint opening (largest joint)", "opening [m]"),
        ("Peak plan rotation (largest segment)", "rotation [deg]"),
        ("Number of impacts", "impacts"),
    ];
    let mut xmax: Real = 0.0;
    for c in curves {
        for p in &c.pts {
            if p.0.is_finite() {
                xmax = xmax.max(p.0);
            }
        }
    }
    let xmax = if xmax > 0.0 { xmax * 1.05 } else { 1.0 };
    save_white_png(out, name, (1400, 1000), |root| {
        let areas = root.split_evenly((2, 2));
        for (k, area) in areas.iter().enumerate() {
            let (lo, hi) = batch_panel_range(k, curves, seat_length);
            let pad = (hi - lo) * 0.08;
            let span = hi - lo + 2.0 * pad;
            let mut chart = ChartBuilder::on(area)
                .caption(titles[k].0, (FAMILY, 22))
                .margin(10)
                .x_label_area_size(40)
                .y_label_area_size(80)
                .build_cartesian_2d(0.0..xmax, (lo - pad)..(hi + pad))
                .map_err(e)?;
            chart
                .configure_mesh()
                .x_desc("PGA [g] (of a pair: the larger of its two scaled components)")
                .y_desc(titles[k].1)
                .x_label_formatter(&|v| tick(*v, xmax))
                .y_label_formatter(&|v| {
                    if k == 3 {
                        format!("{v:.0}")
                    } else {
                        tick(*v, span)
                    }
                })
                .label_style((FAMILY, 15))
                .axis_desc_style((FAMILY, 16))
                .light_line_style(RGBColor(235, 235, 235))
                .draw()
                .map_err(e)?;
            if k == 0 {
                chart
                    .draw_series(DashedLineSeries::new(
                        vec![(0.0, seat_length), (xmax, seat_length)],
                        6,
                        4,
                        BLACK.stroke_width(1),
                    ))
                    .map_err(e)?;
            }
            for (ci, c) in curves.iter().enumerate() {
                let col = PALETTE[ci % PALETTE.len()];
                let pts: Vec<(Real, Real)> = c
                    .pts
                    .iter()
                    .map(|p| (p.0, p.1[k]))
                    .filter(|p| p.0.is_finite() && p.1.is_finite())
                    .collect();
                let s = chart
                    .draw_series(LineSeries::new(pts.iter().copied(), col.stroke_width(2)))
                    .map_err(e)?;
                if k == 0 {
                    s.label(c.label.as_str()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2))
                    });
                }
                chart
                    .draw_series(pts.iter().map(|&p| Circle::new(p, 4, col.filled())))
                    .map_err(e)?;
            }
            if k == 0 && !curves.is_empty() {
                series_legend(&mut chart, SeriesLabelPosition::UpperLeft, BLACK, 13)?;
            }
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_panel_of_symmetric_batches_has_readable_ticks_and_reads_as_zero() {
        // symmetric cases: peak rotations are rounding noise of ~1e-17 deg
        let curves = [BatchCurve {
            label: "r".into(),
            pts: vec![
                (0.1, [0.01, 0.0, 1e-17, 1.0]),
                (0.2, [0.02, 0.0, 3e-17, 2.0]),
            ],
        }];
        let (lo, hi) = batch_panel_range(2, &curves, 0.5);
        assert!(hi - lo >= ROTATION_MIN_RANGE_DEG, "{lo} {hi}");
        let pad = (hi - lo) * 0.08;
        let span = hi - lo + 2.0 * pad;
        // tick labels across the axis are distinct (not all "0"), and the noise reads as 0
        let labels: Vec<String> = (0..=4)
            .map(|i| tick(lo - pad + span * i as Real / 4.0, span))
            .collect();
        let mut uniq = labels.clone();
        uniq.dedup();
        assert_eq!(uniq.len(), labels.len(), "{labels:?}");
        assert_eq!(tick(3e-17, span), "0");
        // a real rotation is not clipped
        let big = [BatchCurve {
            label: "r".into(),
            pts: vec![(0.1, [0.01, 0.0, 2.5, 1.0])],
        }];
        assert_eq!(batch_panel_range(2, &big, 0.5), (0.0, 2.5));
    }
}
