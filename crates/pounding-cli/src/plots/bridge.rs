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

use crate::plot_style::{DrawResult, FAMILY, e, register, save_white_png, series_legend};
use crate::plots::sim_layout::plan_chart;
use crate::plots::sim_lines::energy_panel;
use crate::plots::sim_panels::{
    AbutmentNames, GREY, Hist, abutment_gap_panel, color, displacement_panel, joint_openings_panel,
};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::{Real, Vector};
use pounding::sim::bridge::{ABUTMENT_SIDES, BridgeModel, BridgeSolution};
use pounding::sim::output::{bridge_plan, corner_paths, plan_exaggeration};
use std::path::Path;

type R<T = ()> = DrawResult<T>;

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
    let h = Hist::new(sol);
    save_white_png(out, "joint_openings.png", (1400, 900), |root| {
        joint_panels(root, model, h)
    })?;
    save_white_png(out, "displacements.png", (1400, 600), |root| {
        let labels: Vec<String> = (1..=sol.n_segments)
            .map(|i| format!("segment {i}"))
            .collect();
        displacement_panel(root, h, &labels)
    })?;
    let plan_size = plan_size(model);
    save_white_png(out, "plan.png", plan_size, |root| plan(root, model, sol))?;
    let zoom = crate::plots::bridge_zoom::size(model);
    save_white_png(out, "joint_zoom.png", zoom, |root| {
        crate::plots::bridge_zoom::draw(root, model, sol)
    })?;
    save_white_png(out, "energy.png", (1400, 600), |root| {
        let err = sol.summary.energy_balance_error;
        energy_panel(root, err, h.t_end, &sol.t, &sol.energy, true)
    })
}

/// `joint_openings.png`: the joints (top) and, with abutments, the abutment gaps (bottom).
fn joint_panels(root: &DrawingArea<BitMapBackend, Shift>, model: &BridgeModel, h: Hist) -> R {
    let sol = h.sol;
    let abutments = model.abutments.iter().any(Option::is_some);
    let nj = sol.n_segments.saturating_sub(1);
    // joints on top (3/5), abutments below; a single segment has only the abutment panel
    let (joint_area, abut_area) = match (nj > 0, abutments) {
        (true, true) => {
            let (a, b) = root.split_vertically(root.dim_in_pixel().1 * 3 / 5);
            (Some(a), Some(b))
        }
        (true, false) => (Some(root.clone()), None),
        (false, true) => (None, Some(root.clone())),
        (false, false) => {
            root.titled(
                "A single segment without abutments: no joint or abutment gaps",
                (FAMILY, 22),
            )
            .map_err(e)?;
            return Ok(());
        }
    };
    if let Some(area) = &joint_area {
        let labels: Vec<String> = (1..=nj).map(|k| format!("joint {k}")).collect();
        joint_openings_panel(area, (model, h), &labels)?;
    }
    if let Some(area) = &abut_area {
        let impacts: usize = sol
            .summary
            .abutments
            .iter()
            .flatten()
            .map(|a| a.impacts)
            .sum();
        let gaps = ABUTMENT_SIDES.map(|s| format!("{s} abutment"));
        let initial = ABUTMENT_SIDES.map(|s| format!("initial gap, {s} abutment"));
        let names = AbutmentNames {
            title: format!(
                "Gap of the outer end faces to the abutments (smaller corner gap; {impacts} \
                 impacts)"
            ),
            gaps: [&gaps[0], &gaps[1]],
            initial: [&initial[0], &initial[1]],
            colors: [color(3), color(4)],
        };
        abutment_gap_panel(area, (model, h), &names)?;
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
