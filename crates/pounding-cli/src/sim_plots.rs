//! PNG plots of `pounding simulate` (plotters, embedded DejaVu Sans font).
//!
//! * `displacements.png` — ground acceleration and both decks' centroid displacements;
//! * `rotations.png` — plan rotations θ1, θ2;
//! * `joint_gap.png` — the joint gap at both ends of the joint, with the impacts marked;
//! * `impulses.png` — normal and tangential impulse of every impacting contact, by mode;
//! * `energy.png` — the energy balance (input, stored, dissipated);
//! * `abutment_gap.png` — with abutments: the gap of each far end face to its abutment;
//! * `layout.png` — plan view of the two decks, bearings, joint, abutments and axes (reference pose).

/// The figures [`write_all`] may draw (`abutment_gap.png` only with abutments), in order.
pub const FIGURES: &[&str] = &[
    "displacements.png",
    "layout.png",
    "rotations.png",
    "joint_gap.png",
    "abutment_gap.png",
    "impulses.png",
    "energy.png",
];

use crate::plot_style::{
    BLUE, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_white_png,
};
use crate::plots::sim_layout::layout;
use crate::plots::sim_lines::{Series, energy_panel, line_panel};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::analytic::SlipMode;
use pounding::ground_motion::GroundMotion;
use pounding::math::Real;
use pounding::sim::SimModel;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::dofs::PlanDof;
use std::path::Path;

pub use crate::plots::sim_batch::{BatchCurve, batch_plot};

type R<T = ()> = DrawResult<T>;

const GREY: RGBColor = RGBColor(120, 120, 120);

fn save(
    out: &Path,
    name: &str,
    size: (u32, u32),
    draw: impl Fn(&DrawingArea<BitMapBackend, Shift>) -> R,
) -> R {
    save_white_png(out, name, size, draw)
}

const DEG: Real = 180.0 / std::f64::consts::PI;

/// What the two-deck figures read of a run's input: the model as its file gave it and the
/// ground motion.
#[derive(Clone, Copy)]
pub struct TwoDeckRun<'a> {
    /// The two-deck model's parameters.
    pub model: &'a SimModel,
    /// The ground acceleration.
    pub ground: &'a GroundMotion,
}

/// Writes all plots into `out`.
pub fn write_all(out: &Path, problem: &TwoDeckRun, sol: &BridgeSolution) -> R {
    register();
    let c = Hist {
        problem,
        sol,
        t_end: sol.t.last().copied().unwrap_or(1.0).max(1e-9),
    };

    save(out, "displacements.png", (1400, 1050), |root| {
        displacements(&c, root)
    })?;

    save(out, "layout.png", (1000, 900), |root| layout(root, problem))?;

    save(out, "rotations.png", (1400, 500), |root| {
        rotations(&c, root)
    })?;

    save(out, "joint_gap.png", (1400, 600), |root| {
        joint_gap(&c, root)
    })?;

    if problem.model.abutments.iter().any(Option::is_some) {
        save(out, "abutment_gap.png", (1400, 600), |root| {
            abutment_gap(&c, root)
        })?;
    }

    save(out, "impulses.png", (1400, 800), |root| impulses(&c, root))?;

    save(out, "energy.png", (1400, 600), |root| energy(&c, root))?;
    Ok(())
}

/// What every time-history plot reads.
#[derive(Clone, Copy)]
struct Hist<'a> {
    problem: &'a TwoDeckRun<'a>,
    sol: &'a BridgeSolution,
    /// End of the time axis \[s\].
    t_end: Real,
}

impl Hist<'_> {
    /// `(t, f(step))` over the history.
    fn col(&self, f: &dyn Fn(usize) -> Real) -> Vec<(Real, Real)> {
        let t = &self.sol.t;
        (0..t.len()).map(|i| (t[i], f(i))).collect()
    }
}

/// `displacements.png`.
fn displacements(c: &Hist, root: &DrawingArea<BitMapBackend, Shift>) -> R {
    let Hist {
        problem,
        sol,
        t_end,
    } = *c;
    let col = |f: &dyn Fn(usize) -> Real| c.col(f);
    let areas = root.split_evenly((3, 1));
    let ag: Vec<_> = sol.t.iter().map(|&t| problem.ground.accel(t)).collect();
    line_panel(
        &areas[0],
        "Ground acceleration (positive: ground accelerates toward +x / +y)",
        "a_g [m/s²]",
        t_end,
        &[
            Series {
                label: "a_g,y (normal to joint)",
                pts: col(&|i| ag[i].y),
                color: BLUE,
            },
            Series {
                label: "a_g,x (along joint)",
                pts: col(&|i| ag[i].x),
                color: ORANGE,
            },
        ],
        &[],
        SeriesLabelPosition::UpperRight,
    )?;
    for (j, area) in areas[1..].iter().enumerate() {
        let (ix, iy) = (sol.dofs.plan(j, PlanDof::X), sol.dofs.plan(j, PlanDof::Y));
        line_panel(
            area,
            &format!(
                "Deck {} centroid displacement relative to the ground (y: + = toward deck 1)",
                j + 1
            ),
            "displacement [m]",
            t_end,
            &[
                Series {
                    label: &format!("y{} (normal to joint)", j + 1),
                    pts: col(&|i| sol.q_row(i)[iy]),
                    color: BLUE,
                },
                Series {
                    label: &format!("x{} (along joint)", j + 1),
                    pts: col(&|i| sol.q_row(i)[ix]),
                    color: ORANGE,
                },
            ],
            &[],
            SeriesLabelPosition::UpperRight,
        )?;
    }
    Ok(())
}

/// `rotations.png`.
fn rotations(c: &Hist, root: &DrawingArea<BitMapBackend, Shift>) -> R {
    let Hist { sol, t_end, .. } = *c;
    let col = |f: &dyn Fn(usize) -> Real| c.col(f);
    line_panel(
        root,
        "Plan rotation of each deck about its centroid (counter-clockwise +)",
        "rotation [deg]",
        t_end,
        &[
            Series {
                label: "θ1 (deck 1)",
                pts: col(&|i| sol.q_row(i)[sol.dofs.plan(0, PlanDof::Theta)] * DEG),
                color: BLUE,
            },
            Series {
                label: "θ2 (deck 2)",
                pts: col(&|i| sol.q_row(i)[sol.dofs.plan(1, PlanDof::Theta)] * DEG),
                color: RED,
            },
        ],
        &[(0.0, "", GREY)],
        SeriesLabelPosition::UpperRight,
    )
}

/// `joint_gap.png`.
fn joint_gap(c: &Hist, root: &DrawingArea<BitMapBackend, Shift>) -> R {
    let Hist {
        problem,
        sol,
        t_end,
    } = *c;
    let col = |f: &dyn Fn(usize) -> Real| c.col(f);
    let g = problem.model.gap;
    let w = problem.model.deck_bodies()[0].joint_face(1).half;
    line_panel(
        root,
        &format!(
            "Joint gap at both ends of the joint ({} impacts; gap 0 = decks in contact)",
            sol.summary.impacts
        ),
        "gap [m]",
        t_end,
        &[
            Series {
                label: &format!("end x = +{w} m (deck1-inner / deck2-outer)"),
                pts: col(&|i| sol.end_gaps_row(i)[0]),
                color: BLUE,
            },
            Series {
                label: &format!("end x = −{w} m (deck1-outer / deck2-inner)"),
                pts: col(&|i| sol.end_gaps_row(i)[1]),
                color: RED,
            },
        ],
        &[(g, "initial opening g", GREY), (0.0, "contact", BLACK)],
        SeriesLabelPosition::UpperRight,
    )?;
    Ok(())
}

/// `abutment_gap.png`.
fn abutment_gap(c: &Hist, root: &DrawingArea<BitMapBackend, Shift>) -> R {
    let Hist {
        problem,
        sol,
        t_end,
    } = *c;
    let col = |f: &dyn Fn(usize) -> Real| c.col(f);
    let mut series = Vec::new();
    let mut lines = vec![(0.0, "contact", BLACK)];
    let labels = ["deck 1 far end", "deck 2 far end"];
    let gap_labels = ["initial gap, abutment 1", "initial gap, abutment 2"];
    for (j, a) in problem.model.abutments.iter().enumerate() {
        if let Some(a) = a {
            let c = if j == 0 { BLUE } else { RED };
            series.push(Series {
                label: labels[j],
                pts: col(&|i| sol.abutment_gaps[i][j]),
                color: c,
            });
            lines.push((a.gap, gap_labels[j], c));
        }
    }
    line_panel(
        root,
        &format!(
            "Gap between far end faces and abutments (smaller of the two corners; {} impacting contacts)",
            sol.abutment_impacting_contacts()
        ),
        "gap [m]",
        t_end,
        &series,
        &lines,
        SeriesLabelPosition::UpperRight,
    )
}

/// `impulses.png`.
fn impulses(c: &Hist, root: &DrawingArea<BitMapBackend, Shift>) -> R {
    let Hist { sol, t_end, .. } = *c;
    let areas = root.split_evenly((2, 1));
    let mode_color = |m: SlipMode| match m {
        SlipMode::Stick => GREEN,
        SlipMode::SlipOutward => ORANGE,
        SlipMode::SlipInward => PURPLE,
    };
    for (k, area) in areas.iter().enumerate() {
        let val = |r: &pounding::sim::ImpactRecord| {
            if k == 0 {
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
        let title = if k == 0 {
            "Normal impulse P_N of each impacting contact (pushes the decks apart)"
        } else {
            "Tangential impulse P_T (on deck 1 along +τ, toward its radially outward side)"
        };
        let mut chart = ChartBuilder::on(area)
            .caption(title, (FAMILY, 22))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(90)
            .build_cartesian_2d(
                0.0..t_end,
                (lo - if lo < 0.0 { pad } else { 0.0 })..(hi + pad),
            )
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc("time t [s]")
            .y_desc(if k == 0 { "P_N [kN s]" } else { "P_T [kN s]" })
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
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FAMILY, 15))
            .draw()
            .map_err(e)?;
    }
    Ok(())
}

/// `energy.png`.
fn energy(c: &Hist, root: &DrawingArea<BitMapBackend, Shift>) -> R {
    let Hist { sol, t_end, .. } = *c;
    energy_panel(
        root,
        sol.summary.energy_balance_error,
        t_end,
        &sol.t,
        &sol.energy,
        false,
    )
}
