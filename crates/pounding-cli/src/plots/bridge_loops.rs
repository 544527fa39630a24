//! `hysteresis.png` of a bridge with piers, backwalls or shear keys: the force–deformation loop
//! of every such member, from the run's tables (`piers`, `backwalls`, `shear_keys`): per pier its
//! column's force against the cap's drift (x and y), per backwall the backfill's and the piles'
//! force against the wall's displacement into the soil, per abutment with keys the keys' force
//! against the deck end's transverse displacement.

use crate::plot_style::{BLUE, DrawResult, FAMILY, ORANGE, RED, e, series_legend};
use crate::plots::sim_lines::tick;
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::Real;
use pounding::sim::table::Table;

type R<T = ()> = DrawResult<T>;

/// One loop: its label, colour and `(deformation, force)` points.
type Line = (String, RGBColor, Vec<(Real, Real)>);

/// One loop panel: a title, axis labels, and its loops.
struct Panel {
    title: String,
    x: &'static str,
    y: &'static str,
    lines: Vec<Line>,
}

/// The panels of `tables` (none without piers, backwalls or shear keys).
fn panels(tables: &[Table]) -> Vec<Panel> {
    let mut out = Vec::new();
    let col = |t: &Table, name: &str| -> Option<Vec<Real>> {
        let n = t.columns.len();
        let i = t.columns.iter().position(|c| c.header() == name)?;
        Some(t.values.chunks(n).map(|r| r[i]).collect())
    };
    let zip = |a: Vec<Real>, b: Vec<Real>| a.into_iter().zip(b).collect::<Vec<_>>();
    let neg = |v: Vec<Real>| v.into_iter().map(|x| -x).collect::<Vec<_>>();
    for t in tables {
        let names: Vec<String> = t.columns.iter().map(|c| c.header()).collect();
        match t.name {
            "piers" => {
                for head in names.iter().filter(|h| h.ends_with("_ux_m")) {
                    let p = head.trim_end_matches("_ux_m");
                    let mut lines = Vec::new();
                    for (axis, c) in [("x", BLUE), ("y", RED)] {
                        let (Some(u), Some(f)) = (
                            col(t, &format!("{p}_u{axis}_m")),
                            col(t, &format!("{p}_f{axis}_N")),
                        ) else {
                            continue;
                        };
                        // the column's force on the ground side (piers.csv holds it on the cap)
                        lines.push((format!("along {axis}"), c, zip(u, neg(f))));
                    }
                    out.push(Panel {
                        title: format!(
                            "{}: column force against the cap's drift",
                            p.replace("pier", "pier ")
                        ),
                        x: "cap drift [m]",
                        y: "column force [N]",
                        lines,
                    });
                }
            }
            "backwalls" => {
                for head in names.iter().filter(|h| h.ends_with("_wall_m")) {
                    let a = head.trim_end_matches("_wall_m");
                    let (Some(w), Some(fill), Some(piles)) = (
                        col(t, head),
                        col(t, &format!("{a}_backfill_N")),
                        col(t, &format!("{a}_piles_N")),
                    ) else {
                        continue;
                    };
                    out.push(Panel {
                        title: format!(
                            "{}: backfill and piles against the backwall",
                            a.replace('_', " ")
                        ),
                        x: "backwall into the soil [m]",
                        y: "force [N]",
                        lines: vec![
                            ("backfill".into(), BLUE, zip(w.clone(), fill)),
                            ("piles".into(), ORANGE, zip(w, piles)),
                        ],
                    });
                }
            }
            "shear_keys" => {
                for head in names.iter().filter(|h| h.ends_with("_shear_key_v_m")) {
                    let a = head.trim_end_matches("_shear_key_v_m");
                    let (Some(v), Some(f)) =
                        (col(t, head), col(t, &format!("{a}_shear_key_force_N")))
                    else {
                        continue;
                    };
                    out.push(Panel {
                        title: format!("{}: shear keys", a.replace('_', " ")),
                        x: "deck end across the abutment [m]",
                        y: "key force [N]",
                        lines: vec![("keys".into(), RED, zip(v, f))],
                    });
                }
            }
            _ => {}
        }
    }
    out
}

/// Whether the run has loops to draw.
pub fn has_loops(tables: &[Table]) -> bool {
    !panels(tables).is_empty()
}

/// The figure's size for `tables`: two panels a row.
pub fn size(tables: &[Table]) -> (u32, u32) {
    let rows = panels(tables).len().div_ceil(2).max(1) as u32;
    (1400, 420 * rows)
}

/// Draws `hysteresis.png` (module doc).
pub fn draw(root: &DrawingArea<BitMapBackend, Shift>, tables: &[Table]) -> R {
    let panels = panels(tables);
    let rows = panels.len().div_ceil(2).max(1);
    let areas = root.split_evenly((rows, 2));
    for (p, area) in panels.iter().zip(areas.iter()) {
        panel(area, p)?;
    }
    Ok(())
}

fn panel(area: &DrawingArea<BitMapBackend, Shift>, p: &Panel) -> R {
    let finite = |v: Real| v.is_finite();
    let (mut x0, mut x1, mut y0, mut y1) = (
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::INFINITY,
        Real::NEG_INFINITY,
    );
    for (_, _, pts) in &p.lines {
        for &(x, y) in pts.iter().filter(|(x, y)| finite(*x) && finite(*y)) {
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
    }
    let (x0, x1) = crate::figures::sane_range(x0, x1, (-1.0, 1.0));
    let (y0, y1) = crate::figures::sane_range(y0, y1, (-1.0, 1.0));
    let (px, py) = (((x1 - x0) * 0.06).max(1e-12), ((y1 - y0) * 0.08).max(1e-12));
    let mut chart = ChartBuilder::on(area)
        .caption(&p.title, (FAMILY, 20))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d((x0 - px)..(x1 + px), (y0 - py)..(y1 + py))
        .map_err(e)?;
    let (sx, sy) = (x1 - x0 + 2.0 * px, y1 - y0 + 2.0 * py);
    chart
        .configure_mesh()
        .x_desc(p.x)
        .y_desc(p.y)
        .x_label_formatter(&|v| tick(*v, sx))
        .y_label_formatter(&|v| tick(*v, sy))
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    for (label, c, pts) in &p.lines {
        let c = *c;
        chart
            .draw_series(LineSeries::new(
                pts.iter()
                    .copied()
                    .filter(|(x, y)| finite(*x) && finite(*y)),
                c.stroke_width(1),
            ))
            .map_err(e)?
            .label(label.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    series_legend(&mut chart, SeriesLabelPosition::UpperLeft, BLACK, 14)
}
