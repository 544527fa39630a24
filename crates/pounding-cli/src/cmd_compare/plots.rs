//! The two overlay plots of `pounding compare`: `joint_gap.png` (the smaller joint gap of the two
//! ends) and `contact_force.png` (total joint force of the compliance laws), each with a
//! full-duration panel and a zoom around the largest contact event.

use super::Ran as Run;
use crate::plot_style::{
    BLUE, DARK, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_white_png,
    series_legend,
};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::Real;
use pounding::sim::scenario::LAW_NAMES;
use std::path::Path;

pub(super) type R = DrawResult;

/// The six laws of `LAW_NAMES` keep their colours; further registered laws (in registry order)
/// get the next ones, so no two laws share a colour in one figure.
const COLORS: [RGBColor; 12] = [
    DARK,
    BLUE,
    GREEN,
    RED,
    ORANGE,
    PURPLE,
    RGBColor(0, 139, 139),
    RGBColor(139, 69, 19),
    RGBColor(199, 21, 133),
    RGBColor(128, 128, 0),
    RGBColor(70, 70, 160),
    RGBColor(120, 120, 120),
];

fn color_of(law: &str) -> RGBColor {
    let extra = pounding::contact_law::registry::law_names()
        .into_iter()
        .filter(|l| !LAW_NAMES.contains(l))
        .position(|l| l == law)
        .map(|i| LAW_NAMES.len() + i);
    let i = LAW_NAMES
        .iter()
        .position(|l| *l == law)
        .or(extra)
        .unwrap_or(0);
    COLORS[i % COLORS.len()]
}

/// `(t, smaller end gap)` and `(t, total joint force)` series of one run.
type Pts = Vec<(Real, Real)>;

fn series(r: &Run) -> (Pts, Pts) {
    let sol = &r.sol;
    let gap = sol
        .t
        .iter()
        .zip(sol.end_gaps.chunks_exact(2))
        .map(|(t, g)| {
            let m = g
                .iter()
                .copied()
                .filter(|x| x.is_finite())
                .fold(Real::INFINITY, Real::min);
            (*t, if m.is_finite() { m } else { Real::NAN })
        })
        .collect();
    let force = sol
        .t
        .iter()
        .zip(sol.contact_force.chunks_exact(2))
        .map(|(t, f)| (*t, (f[0] + f[1]) / 1e6))
        .collect();
    (gap, force)
}

/// The zoom window: ±0.25 s around the instant of the largest compliance force, or around the
/// first rigid impact, or the first second.
fn zoom_window(runs: &[Run]) -> (Real, Real) {
    let mut best: Option<(Real, Real)> = None;
    for r in runs {
        let (_, f) = series(r);
        for (t, v) in f {
            if best.is_none_or(|(_, b)| v > b) {
                best = Some((t, v));
            }
        }
    }
    let tc = match best {
        Some((t, v)) if v > 0.0 => t,
        _ => runs
            .iter()
            .filter_map(|r| r.sol.impacts.first().map(|i| i.time))
            .fold(Real::INFINITY, Real::min),
    };
    if tc.is_finite() {
        ((tc - 0.25).max(0.0), tc + 0.25)
    } else {
        (0.0, 1.0)
    }
}

pub(super) fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    ylabel: &str,
    (t0, t1): (Real, Real),
    curves: &[(&str, Vec<(Real, Real)>)],
    hline: Option<(Real, &str)>,
) -> R {
    let mut lo = Real::INFINITY;
    let mut hi = Real::NEG_INFINITY;
    for (_, pts) in curves {
        for &(t, y) in pts {
            if t >= t0 && t <= t1 && y.is_finite() {
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
    }
    if let Some((y, _)) = hline.filter(|h| h.0.is_finite()) {
        lo = lo.min(y);
        hi = hi.max(y);
    }
    let (lo, hi) = crate::figures::sane_range(lo, hi, (0.0, 1.0));
    let pad = ((hi - lo) * 0.08).max(1e-9);
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FAMILY, 20))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(80)
        .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("time t [s]")
        .y_desc(ylabel)
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    if let Some((y, label)) = hline {
        chart
            .draw_series(DashedLineSeries::new(
                vec![(t0, y), (t1, y)],
                6,
                4,
                RGBColor(120, 120, 120).stroke_width(1),
            ))
            .map_err(e)?
            .label(label)
            .legend(|(x, y)| {
                PathElement::new(
                    vec![(x, y), (x + 20, y)],
                    RGBColor(120, 120, 120).stroke_width(1),
                )
            });
    }
    for (law, pts) in curves {
        let c = color_of(law);
        chart
            .draw_series(LineSeries::new(
                pts.iter()
                    .copied()
                    .filter(|&(t, y)| t >= t0 && t <= t1 && y.is_finite()),
                c.stroke_width(if *law == "rigid" { 2 } else { 1 }),
            ))
            .map_err(e)?
            .label(*law)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    series_legend(&mut chart, SeriesLabelPosition::UpperRight, BLACK, 14)
}

fn save(out: &Path, name: &str, draw: impl Fn(&DrawingArea<BitMapBackend, Shift>) -> R) -> R {
    save_white_png(out, name, (1200, 900), draw)
}

/// Draws both plots of `runs` into `out`.
pub(super) fn plots(out: &Path, runs: &[Run], gap0: Real) -> R {
    register();
    let t_end = runs
        .iter()
        .filter_map(|r| r.sol.t.last().copied())
        .fold(0.0, Real::max)
        .max(1e-9);
    let zoom = zoom_window(runs);
    let all: Vec<(&str, (Pts, Pts))> = runs.iter().map(|r| (r.law, series(r))).collect();
    let gaps: Vec<(&str, Vec<(Real, Real)>)> =
        all.iter().map(|(l, (g, _))| (*l, g.clone())).collect();
    let forces: Vec<(&str, Vec<(Real, Real)>)> = all
        .iter()
        .filter(|(_, (_, f))| !f.is_empty())
        .map(|(l, (_, f))| (*l, f.clone()))
        .collect();
    save(out, "joint_gap.png", |root| {
        let (a, b) = root.split_vertically(450);
        panel(
            &a,
            "Joint gap (smaller of the two ends) by contact law",
            "gap [m]",
            (0.0, t_end),
            &gaps,
            Some((0.0, "contact")),
        )?;
        panel(
            &b,
            &format!(
                "zoom {:.2}–{:.2} s (reference gap {} m)",
                zoom.0, zoom.1, gap0
            ),
            "gap [m]",
            zoom,
            &gaps,
            Some((0.0, "contact")),
        )
    })?;
    save(out, "contact_force.png", |root| {
        let (a, b) = root.split_vertically(450);
        panel(
            &a,
            "Total joint contact force (compliance laws; rigid contact has impulses only)",
            "force [MN]",
            (0.0, t_end),
            &forces,
            None,
        )?;
        panel(
            &b,
            &format!("zoom {:.2}–{:.2} s", zoom.0, zoom.1),
            "force [MN]",
            zoom,
            &forces,
            None,
        )
    })?;
    Ok(())
}
