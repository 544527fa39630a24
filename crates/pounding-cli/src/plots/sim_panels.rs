//! The panels of the `simulate` figures, over a run's [`BridgeSolution`] (and its
//! [`BridgeModel`] where a panel needs the geometry): the one set both scenario forms draw
//! with. A bridge's figures ([`super::bridge`]) and the two-deck model's
//! ([`super::two_deck`], a two-segment bridge) differ only in which panels they put in which
//! file and in the names they give (`deck 1` or `segment 1`, the joint's two ends, the axes).

use crate::plot_style::{
    BLUE, DARK, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, series_legend,
};
use crate::plots::sim_lines::{Series, line_panel};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::analytic::SlipMode;
use pounding::ground_motion::GroundMotion;
use pounding::math::Real;
use pounding::sim::bridge::{BridgeModel, BridgeSolution};
use pounding::sim::dofs::PlanDof;
use pounding::sim::output::{joint_openings, segment_displacements};

type R<T = ()> = DrawResult<T>;

/// The drawing area of a panel.
pub(crate) type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

pub(crate) const GREY: RGBColor = RGBColor(120, 120, 120);

const DEG: Real = 180.0 / std::f64::consts::PI;

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

/// The `i`-th line colour ([`PALETTE`], cycled).
pub(crate) fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// What every time-history panel reads: the run and the end of its time axis.
#[derive(Clone, Copy)]
pub(crate) struct Hist<'a> {
    /// The run.
    pub sol: &'a BridgeSolution,
    /// End of the time axis \[s\].
    pub t_end: Real,
}

impl<'a> Hist<'a> {
    /// The histories of `sol`, on a time axis to its last kept time.
    pub fn new(sol: &'a BridgeSolution) -> Self {
        let t_end = sol.t.last().copied().unwrap_or(1.0).max(1e-9);
        Self { sol, t_end }
    }

    /// `(t, f(kept time))` over the history.
    fn col(&self, f: impl Fn(usize) -> Real) -> Vec<(Real, Real)> {
        self.sol
            .t
            .iter()
            .enumerate()
            .map(|(i, &t)| (t, f(i)))
            .collect()
    }

    /// One line of a panel.
    fn line<'s>(&self, label: &'s str, color: RGBColor, f: impl Fn(usize) -> Real) -> Series<'s> {
        Series {
            label,
            pts: self.col(f),
            color,
        }
    }

    /// A line panel with the legend upper right ([`line_panel`]).
    fn panel(
        &self,
        area: &Area,
        title: &str,
        ylabel: &str,
        series: &[Series],
        hlines: &[(Real, &str, RGBColor)],
    ) -> R {
        let right = SeriesLabelPosition::UpperRight;
        line_panel(area, title, ylabel, self.t_end, series, hlines, right)
    }
}

/// The ground acceleration's two components, `labels` = `[y, x]`.
pub(crate) fn ground_panel(area: &Area, h: Hist, ground: &GroundMotion, labels: [&str; 2]) -> R {
    let ag: Vec<_> = h.sol.t.iter().map(|&t| ground.accel(t)).collect();
    h.panel(
        area,
        "Ground acceleration (positive: ground accelerates toward +x / +y)",
        "a_g [m/s²]",
        &[
            h.line(labels[0], BLUE, |i| ag[i].y),
            h.line(labels[1], ORANGE, |i| ag[i].x),
        ],
        &[],
    )
}

/// Segment `j`'s centroid displacement relative to the ground, `labels` = `[y, x]`.
pub(crate) fn segment_xy_panel(
    area: &Area,
    h: Hist,
    j: usize,
    title: &str,
    labels: [&str; 2],
) -> R {
    let dofs = &h.sol.dofs;
    let (ix, iy) = (dofs.plan(j, PlanDof::X), dofs.plan(j, PlanDof::Y));
    h.panel(
        area,
        title,
        "displacement [m]",
        &[
            h.line(labels[0], BLUE, |i| h.sol.q_row(i)[iy]),
            h.line(labels[1], ORANGE, |i| h.sol.q_row(i)[ix]),
        ],
        &[],
    )
}

/// Every segment's centroid displacement magnitude `√(x² + y²)`, `labels` per segment.
pub(crate) fn displacement_panel(area: &Area, h: Hist, labels: &[String]) -> R {
    let series: Vec<Series> = segment_displacements(h.sol)
        .iter()
        .zip(labels)
        .enumerate()
        .map(|(i, (d, label))| h.line(label, color(i), |r| d[r]))
        .collect();
    let title = if h.sol.supports_apart {
        "Centroid displacement of each segment relative to the reference ground motion \
         (summary.json ground_motion.supports), √(x² + y²)"
    } else {
        "Centroid displacement of each segment relative to the ground, √(x² + y²)"
    };
    h.panel(area, title, "displacement [m]", &series, &[])
}

/// Every segment's plan rotation about its centroid \[deg\], `labels` per segment.
pub(crate) fn rotation_panel(area: &Area, h: Hist, title: &str, labels: &[String]) -> R {
    let series: Vec<Series> = labels
        .iter()
        .enumerate()
        .map(|(j, label)| {
            let k = h.sol.dofs.plan(j, PlanDof::Theta);
            h.line(label, color(j), |i| h.sol.q_row(i)[k] * DEG)
        })
        .collect();
    h.panel(area, title, "rotation [deg]", &series, &[(0.0, "", GREY)])
}

/// Joint `k`'s two end gaps (`labels` of its ends), with its reference gap and contact.
pub(crate) fn end_gap_panel(
    area: &Area,
    (model, h): (&BridgeModel, Hist),
    k: usize,
    title: &str,
    labels: [&str; 2],
) -> R {
    let n = 2 * h.sol.n_segments.saturating_sub(1);
    let end = |c: usize| move |i: usize| h.sol.end_gaps[n * i + 2 * k + c];
    h.panel(
        area,
        title,
        "gap [m]",
        &[
            h.line(labels[0], BLUE, end(0)),
            h.line(labels[1], RED, end(1)),
        ],
        &[
            (model.joints[k].gap, "initial opening g", GREY),
            (0.0, "contact", BLACK),
        ],
    )
}

/// Every joint's opening: its smaller end gap minus its reference gap
/// ([`joint_openings`]), `labels` per joint.
pub(crate) fn joint_openings_panel(
    area: &Area,
    (model, h): (&BridgeModel, Hist),
    labels: &[String],
) -> R {
    let openings = joint_openings(model, h.sol);
    let series: Vec<Series> = openings
        .iter()
        .zip(labels)
        .enumerate()
        .map(|(k, (o, label))| h.line(label, color(k), |r| o[r]))
        .collect();
    let title = format!(
        "Joint opening = smaller end gap − reference gap ({} impacts; < 0 closing, −gap = contact)",
        h.sol
            .summary
            .joints
            .iter()
            .map(|j| j.impacts)
            .sum::<usize>()
    );
    // the contact line (opening = −gap) when every joint has the same gap
    let mut hlines = vec![(0.0, "reference gap", GREY)];
    if let Some(g) = model.joints.first().map(|j| j.gap)
        && model.joints.iter().all(|j| j.gap == g)
    {
        hlines.push((-g, "contact (opening = −gap)", BLACK));
    }
    h.panel(area, &title, "opening [m]", &series, &hlines)
}

/// How a form names the abutment panel's lines: per side `[start, end]` its gap's label and
/// colour, and the label of its initial-gap line.
pub(crate) struct AbutmentNames<'a> {
    /// The panel's title.
    pub title: String,
    /// The gap of each side.
    pub gaps: [&'a str; 2],
    /// The initial gap of each side (a dashed line).
    pub initial: [&'a str; 2],
    /// The colour of each side.
    pub colors: [RGBColor; 2],
}

/// The gap of each outer end face to its abutment (the smaller corner gap), for the sides
/// with an abutment.
pub(crate) fn abutment_gap_panel(
    area: &Area,
    (model, h): (&BridgeModel, Hist),
    names: &AbutmentNames,
) -> R {
    let mut series = Vec::new();
    let mut lines = vec![(0.0, "contact", BLACK)];
    for (s, a) in model.abutments.iter().enumerate() {
        if let Some(a) = a {
            let c = names.colors[s];
            series.push(h.line(names.gaps[s], c, |i| h.sol.abutment_gaps[i][s]));
            lines.push((a.gap, names.initial[s], c));
        }
    }
    h.panel(area, &names.title, "gap [m]", &series, &lines)
}

/// The normal (top) and tangential (bottom) impulse of every impacting contact, by slip mode;
/// `titles` `[normal, tangential]`.
pub(crate) fn impulse_panels(area: &Area, h: Hist, titles: [&str; 2]) -> R {
    let areas = area.split_evenly((2, 1));
    for (k, area) in areas.iter().enumerate() {
        impulse_panel(area, h, k == 0, titles[k])?;
    }
    Ok(())
}

/// One panel of [`impulse_panels`]: the normal impulses, or the tangential ones \[kN s\].
fn impulse_panel(area: &Area, h: Hist, normal: bool, title: &str) -> R {
    let sol = h.sol;
    let mode_color = |m: SlipMode| match m {
        SlipMode::Stick => GREEN,
        SlipMode::SlipOutward => ORANGE,
        SlipMode::SlipInward => PURPLE,
    };
    let val = |r: &pounding::sim::ImpactRecord| {
        if normal {
            r.impulse_n / 1e3
        } else {
            r.impulse_t / 1e3
        }
    };
    let mut lo: Real = 0.0;
    let mut hi: Real = 0.0;
    for v in sol.impacts.iter().map(val).filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    // 0 is always in the range, so it is never the default
    let (lo, hi) = crate::figures::sane_range(lo, hi, (0.0, 0.0));
    let pad = ((hi - lo) * 0.1).max(1.0);
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FAMILY, 22))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d(
            0.0..h.t_end,
            (lo - if lo < 0.0 { pad } else { 0.0 })..(hi + pad),
        )
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("time t [s]")
        .y_desc(if normal { "P_N [kN s]" } else { "P_T [kN s]" })
        .label_style((FAMILY, 15))
        .axis_desc_style((FAMILY, 16))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    for m in [SlipMode::Stick, SlipMode::SlipOutward, SlipMode::SlipInward] {
        let c = mode_color(m);
        let rs: Vec<_> = sol.impacts.iter().filter(|r| r.mode == m).collect();
        chart
            .draw_series(rs.iter().filter(|r| val(r).is_finite()).map(|r| {
                PathElement::new(vec![(r.time, 0.0), (r.time, val(r))], c.stroke_width(3))
            }))
            .map_err(e)?;
        chart
            .draw_series(
                rs.iter()
                    .filter(|r| val(r).is_finite())
                    .map(|r| Circle::new((r.time, val(r)), 5, c.filled())),
            )
            .map_err(e)?
            .label(format!("{} ({})", m.name(), rs.len()))
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, c.filled()));
    }
    series_legend(&mut chart, SeriesLabelPosition::UpperRight, BLACK, 15)
}
