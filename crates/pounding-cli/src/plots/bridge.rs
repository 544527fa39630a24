//! PNG plots of a bridge run (`[[segment]]` scenarios); the numbers come from the library
//! (`pounding::sim::output::{joint_openings, segment_displacements, bridge_plan, corner_paths}`):
//!
//! * `joint_openings.png` — the opening of every joint (smaller end gap minus its reference gap)
//!   and, with abutments, the abutment gaps;
//! * `displacements.png` — every segment's centroid displacement magnitude;
//! * `plan.png` — plan view of the reference pose with each corner's path, exaggerated;
//! * `energy.png` — the energy balance;
//! * `hysteresis.png` — with piers, backwalls or shear keys: their force–deformation loops.

/// The figures [`write_all`] draws, in order.
pub const FIGURES: &[&str] = &[
    "joint_openings.png",
    "displacements.png",
    "plan.png",
    "joint_zoom.png",
    "energy.png",
];

use crate::plot_style::{
    BLUE, DARK, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_white_png,
    series_legend,
};
use crate::plots::sim_layout::plan_chart;
use crate::plots::sim_lines::{Series, energy_panel, line_panel};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::{Real, Vector};
use pounding::sim::bridge::{ABUTMENT_SIDES, BridgeModel, BridgeSolution};
use pounding::sim::output::{
    bridge_plan, corner_paths, joint_openings, plan_exaggeration, segment_displacements,
};
use std::path::Path;

type R<T = ()> = DrawResult<T>;

const GREY: RGBColor = RGBColor(120, 120, 120);

/// Line colours, cycled for many joints or segments.
const PALETTE: [RGBColor; 10] = [
    BLUE,
    RED,
    GREEN,
    ORANGE,
    PURPLE,
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(188, 189, 34),
    DARK,
];

fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// `(t, v)` pairs of a history.
fn pts(t: &[Real], v: &[Real]) -> Vec<(Real, Real)> {
    t.iter().copied().zip(v.iter().copied()).collect()
}

/// Drawn besides [`FIGURES`] for a bridge with piers, backwalls or shear keys
/// ([`crate::plots::bridge_loops`]).
pub const LOOPS: &str = "hysteresis.png";

/// Writes the bridge figures into `out`; returns their names ([`FIGURES`], then [`LOOPS`] when
/// drawn).
pub fn write_all(out: &Path, model: &BridgeModel, sol: &BridgeSolution) -> R<Vec<&'static str>> {
    write_figures(out, model, sol)?;
    let mut names = FIGURES.to_vec();
    let tables = sol.tables();
    if crate::plots::bridge_loops::has_loops(&tables) {
        let size = crate::plots::bridge_loops::size(&tables);
        save_white_png(out, LOOPS, size, |root| {
            crate::plots::bridge_loops::draw(root, &tables)
        })?;
        names.push(LOOPS);
    }
    Ok(names)
}

/// The figures of [`FIGURES`].
fn write_figures(out: &Path, model: &BridgeModel, sol: &BridgeSolution) -> R {
    register();
    let t_end = sol.t.last().copied().unwrap_or(1.0).max(1e-9);
    let pts = |v: &[Real]| pts(&sol.t, v);
    save_white_png(out, "joint_openings.png", (1400, 900), |root| {
        joint_panels(root, model, sol, t_end)
    })?;
    save_white_png(out, "displacements.png", (1400, 600), |root| {
        let labels: Vec<String> = (1..=sol.n_segments)
            .map(|i| format!("segment {i}"))
            .collect();
        let series: Vec<Series> = segment_displacements(sol)
            .iter()
            .enumerate()
            .map(|(i, d)| Series {
                label: &labels[i],
                pts: pts(d),
                color: color(i),
            })
            .collect();
        let title = if sol.supports_apart {
            "Centroid displacement of each segment relative to the reference ground motion \
             (summary.json ground_motion.supports), √(x² + y²)"
        } else {
            "Centroid displacement of each segment relative to the ground, √(x² + y²)"
        };
        line_panel(
            root,
            title,
            "displacement [m]",
            t_end,
            &series,
            &[],
            SeriesLabelPosition::UpperRight,
        )
    })?;
    let plan_size = plan_size(model);
    save_white_png(out, "plan.png", plan_size, |root| plan(root, model, sol))?;
    let zoom = crate::plots::bridge_zoom::size(model);
    save_white_png(out, "joint_zoom.png", zoom, |root| {
        crate::plots::bridge_zoom::draw(root, model, sol)
    })?;
    save_white_png(out, "energy.png", (1400, 600), |root| {
        energy(root, sol, t_end)
    })
}

/// `joint_openings.png`: the joints (top) and, with abutments, the abutment gaps (bottom).
fn joint_panels(
    root: &DrawingArea<BitMapBackend, Shift>,
    model: &BridgeModel,
    sol: &BridgeSolution,
    t_end: Real,
) -> R {
    let sides: Vec<usize> = (0..2).filter(|&s| model.abutments[s].is_some()).collect();
    let nj = sol.n_segments.saturating_sub(1);
    // joints on top (3/5), abutments below; a single segment has only the abutment panel
    let (joint_area, abut_area) = match (nj > 0, sides.is_empty()) {
        (true, false) => {
            let (a, b) = root.split_vertically(root.dim_in_pixel().1 * 3 / 5);
            (Some(a), Some(b))
        }
        (true, true) => (Some(root.clone()), None),
        (false, false) => (None, Some(root.clone())),
        (false, true) => {
            root.titled(
                "A single segment without abutments: no joint or abutment gaps",
                (FAMILY, 22),
            )
            .map_err(e)?;
            return Ok(());
        }
    };
    let openings = joint_openings(model, sol);
    let labels: Vec<String> = (1..=openings.len()).map(|k| format!("joint {k}")).collect();
    let series: Vec<Series> = openings
        .iter()
        .enumerate()
        .map(|(k, o)| Series {
            label: &labels[k],
            pts: pts(&sol.t, o),
            color: color(k),
        })
        .collect();
    let title = format!(
        "Joint opening = smaller end gap − reference gap ({} impacts; < 0 closing, −gap = contact)",
        sol.summary.joints.iter().map(|j| j.impacts).sum::<usize>()
    );
    // the contact line (opening = −gap) when every joint has the same gap
    let mut hlines = vec![(0.0, "reference gap", GREY)];
    if let Some(g) = model.joints.first().map(|j| j.gap)
        && model.joints.iter().all(|j| j.gap == g)
    {
        hlines.push((-g, "contact (opening = −gap)", BLACK));
    }
    if let Some(area) = &joint_area {
        line_panel(
            area,
            &title,
            "opening [m]",
            t_end,
            &series,
            &hlines,
            SeriesLabelPosition::UpperRight,
        )?;
    }
    if let Some(area) = &abut_area {
        let labels: Vec<String> = sides
            .iter()
            .map(|&s| format!("{} abutment", ABUTMENT_SIDES[s]))
            .collect();
        let series: Vec<Series> = sides
            .iter()
            .enumerate()
            .map(|(i, &s)| Series {
                label: &labels[i],
                pts: pts(
                    &sol.t,
                    &sol.abutment_gaps.iter().map(|g| g[s]).collect::<Vec<_>>(),
                ),
                color: color(i + 3),
            })
            .collect();
        let impacts: usize = sol
            .summary
            .abutments
            .iter()
            .flatten()
            .map(|a| a.impacts)
            .sum();
        line_panel(
            area,
            &format!(
                "Gap of the outer end faces to the abutments (smaller corner gap; {impacts} impacts)"
            ),
            "gap [m]",
            t_end,
            &series,
            &[(0.0, "contact", BLACK)],
            SeriesLabelPosition::UpperRight,
        )?;
    }
    Ok(())
}

/// Pixel size of `plan.png`: wide for a bridge wider than long, tall otherwise.
fn plan_size(model: &BridgeModel) -> (u32, u32) {
    let p = bridge_plan(model, 8);
    let (mut lo, mut hi) = (
        Vector::repeat(Real::INFINITY),
        Vector::repeat(Real::NEG_INFINITY),
    );
    for v in p.outlines.iter().flatten() {
        lo = lo.inf(v);
        hi = hi.sup(v);
    }
    let d = hi - lo;
    if d.x >= d.y {
        (1400, 900)
    } else {
        (1000, 1300)
    }
}

/// `plan.png`.
fn plan(root: &DrawingArea<BitMapBackend, Shift>, model: &BridgeModel, sol: &BridgeSolution) -> R {
    let p = bridge_plan(model, 60);
    let xy = |v: &Vector| (v.x, v.y);
    let mut all: Vec<(Real, Real)> = p.outlines.iter().flatten().map(xy).collect();
    all.extend(p.abutment_faces.iter().flatten().flatten().map(xy));
    // extent of the bridge and the largest corner excursion of the run
    let (lo, hi) = all.iter().fold(
        (
            (Real::INFINITY, Real::INFINITY),
            (Real::NEG_INFINITY, Real::NEG_INFINITY),
        ),
        |(l, h), &(x, y)| ((l.0.min(x), l.1.min(y)), (h.0.max(x), h.1.max(y))),
    );
    let extent = (hi.0 - lo.0).max(hi.1 - lo.1);
    // a diverged run's corners can be 1e300 m away: plotters' pixel arithmetic overflows on such
    // ranges (a panic), so points farther than this from their reference corner are not drawn
    let far = 1e3 * extent.max(1.0);
    let raw = corner_paths(model, sol, 1.0);
    let peak = raw
        .iter()
        .zip(&p.corners)
        .flat_map(|(seg, c0)| {
            seg.iter()
                .zip(c0)
                .flat_map(move |(path, c)| path.iter().map(move |q| (q - c).norm()))
        })
        .filter(|d| d.is_finite() && *d <= far)
        .fold(0.0, Real::max);
    let f = plan_exaggeration(extent, peak);
    let mut paths = corner_paths(model, sol, f);
    for (seg, c0) in paths.iter_mut().zip(&p.corners) {
        for (path, c) in seg.iter_mut().zip(c0) {
            path.retain(|q| q.x.is_finite() && q.y.is_finite() && (q - c).norm() <= far * f);
        }
    }
    all.extend(
        paths
            .iter()
            .flatten()
            .flatten()
            .filter(|v| v.x.is_finite() && v.y.is_finite())
            .map(xy),
    );
    let (mut chart, _) = plan_chart(
        root,
        all.iter(),
        &format!(
            "Plan (reference pose) and the path of every corner, displacements ×{f} \
             (peak {peak:.3} m)"
        ),
        ("x [m]", "y [m]"),
    )?;
    for (i, o) in p.outlines.iter().enumerate() {
        let c = color(i);
        let pts: Vec<_> = o.iter().map(xy).collect();
        chart
            .draw_series(std::iter::once(Polygon::new(pts.clone(), c.mix(0.12))))
            .map_err(e)?;
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(2)))
            .map_err(e)?;
        for path in &paths[i] {
            let s = chart
                .draw_series(LineSeries::new(
                    path.iter()
                        .filter(|v| v.x.is_finite() && v.y.is_finite())
                        .map(xy),
                    BLACK.mix(0.7).stroke_width(1),
                ))
                .map_err(e)?;
            if i == 0 && std::ptr::eq(path, &paths[0][0]) {
                s.label(format!("corner paths (displacement ×{f})"))
                    .legend(|(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(1))
                    });
            }
        }
        let g = p.centroids[i];
        chart
            .draw_series(std::iter::once(Text::new(
                format!("{}", i + 1),
                (g.x, g.y),
                (FAMILY, 18).into_font().color(&c),
            )))
            .map_err(e)?;
    }
    for (side, face) in p.abutment_faces.iter().enumerate() {
        let Some(face) = face else { continue };
        let s = chart
            .draw_series(std::iter::once(PathElement::new(
                vec![xy(&face[0]), xy(&face[1])],
                GREY.stroke_width(5),
            )))
            .map_err(e)?;
        if side == 0 || p.abutment_faces[0].is_none() {
            s.label("abutment face")
                .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], GREY.stroke_width(5)));
        }
    }
    series_legend(&mut chart, SeriesLabelPosition::UpperRight, BLACK, 15)
}

/// `energy.png`.
fn energy(root: &DrawingArea<BitMapBackend, Shift>, sol: &BridgeSolution, t_end: Real) -> R {
    let err = sol.summary.energy_balance_error;
    energy_panel(root, err, t_end, &sol.t, &sol.energy, true)
}
