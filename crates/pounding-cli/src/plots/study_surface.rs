//! `surface_*.png`: the lower and upper stick surfaces over θ1 × θ2 for the four cases.

use super::study_style::{LOWER, SINGLE, Tri, UPPER, case_title, geom_title, legend, tick, tok};
use crate::plot_style::{DrawResult, e, font};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::geometry::ContactCase;
use pounding::math::Real;
use pounding::study::RowKey;
use pounding::study::Study;

pub(crate) fn surface<DB: DrawingBackend>(
    study: &Study,
    geom: [usize; 4],
    mu: usize,
    eps: usize,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let s = &study.scenario;
    let (top, body) = root.split_vertically(70);
    top.draw(&Text::new(
        format!(
            "{}, μ = {}, ε_N = {}  —  z = r = γ_T⁻/γ_N⁻ (pre-impact ratio)",
            geom_title(study, geom),
            tok(s.mu[mu]),
            tok(s.eps[eps])
        ),
        (20, 8),
        font(20),
    ))
    .map_err(e)?;
    let layout = pounding::study::Layout::of(s);
    let block = |ci: usize| {
        let first = layout.index(&RowKey {
            beta1: geom[0],
            beta2: geom[1],
            r1: geom[2],
            r2: geom[3],
            mu,
            eps,
            case: ci,
            i: 0,
            j: 0,
        });
        &study.rows[first..first + layout.block_len()]
    };
    // μ = 0 (or any law giving L = U everywhere): one dividing surface, drawn once.
    let single = (0..s.cases.len()).all(|ci| {
        block(ci)
            .iter()
            .all(|r| r.cell.lower.is_nan() || r.cell.lower == r.cell.upper)
    });
    if single {
        legend(
            &top,
            &[
                (
                    SINGLE.to_rgba(),
                    "L = U: one dividing surface (outward slip below, inward slip above)",
                ),
                (SINGLE.mix(0.18), "pale: not the first contact"),
            ],
            40,
        )?;
    } else {
        legend(
            &top,
            &[
                (LOWER.to_rgba(), "lower bound L (outward slip below)"),
                (UPPER.to_rgba(), "upper bound U (inward slip above)"),
                (LOWER.mix(0.18), "pale: not the first contact"),
            ],
            40,
        )?;
    }
    let panels = body.split_evenly((2, 2));
    for (p, case) in ContactCase::ALL.into_iter().enumerate() {
        let area = &panels[p];
        let Some(ci) = s.cases.iter().position(|&c| c == case) else {
            area.draw(&Text::new(
                format!("{} — not in this scenario", case.name()),
                (20, 20),
                font(16),
            ))
            .map_err(e)?;
            continue;
        };
        surface_panel(study, case, block(ci), single, area)?;
    }
    Ok(())
}

pub(crate) fn surface_panel<DB: DrawingBackend>(
    study: &Study,
    case: ContactCase,
    rows: &[pounding::study::Row],
    single: bool,
    area: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let s = &study.scenario;
    let (n1, n2) = (s.theta1.len(), s.theta2.len());
    let t1: Vec<Real> = s.theta1.values();
    let t2: Vec<Real> = s.theta2.values();
    let (x0, x1) = (
        t1[0],
        *t1.last().unwrap_or(&t1[0]) + if n1 == 1 { 1.0 } else { 0.0 },
    );
    let (z0, z1) = (
        t2[0],
        *t2.last().unwrap_or(&t2[0]) + if n2 == 1 { 1.0 } else { 0.0 },
    );
    let (rmin, rmax) = (s.ratio_min, s.ratio_max);
    let mut chart = ChartBuilder::on(area)
        .caption(case_title(case), font(17))
        .margin(8)
        .build_cartesian_3d(x0..x1, rmin..rmax, z0..z1)
        .map_err(e)?;
    chart.with_projection(|mut pb| {
        pb.yaw = 0.6;
        pb.pitch = 0.35;
        pb.scale = 0.74;
        pb.into_matrix()
    });
    chart
        .configure_axes()
        .x_formatter(&tick)
        .y_formatter(&tick)
        .z_formatter(&tick)
        .label_style(font(13))
        .light_grid_style(BLACK.mix(0.08))
        .max_light_lines(1)
        .x_labels(5)
        .y_labels(7)
        .z_labels(5)
        .draw()
        .map_err(e)?;
    // Axis names at the ends of the axes.
    let name_style = font(15);
    chart
        .draw_series([
            Text::new(
                "θ1 [deg]".to_string(),
                (0.5 * (x0 + x1), rmin, z1 + 0.48 * (z1 - z0)),
                name_style.clone(),
            ),
            Text::new(
                "θ2 [deg]".to_string(),
                (x1 + 0.2 * (x1 - x0), rmin, 0.5 * (z0 + z1)),
                name_style.clone(),
            ),
            Text::new(
                "r = γ_T⁻/γ_N⁻".to_string(),
                (x0, rmax + 0.06 * (rmax - rmin), z0),
                name_style,
            ),
        ])
        .map_err(e)?;
    // Triangles of both surfaces, painter-sorted by projected depth (farthest first).
    let at = |i: usize, j: usize| &rows[i * n2 + j].cell;
    let mut tris: Vec<(i32, Tri, RGBAColor)> = Vec::new();
    let coord = chart.as_coord_spec().clone();
    for i in 0..n1.saturating_sub(1) {
        for j in 0..n2.saturating_sub(1) {
            for tri in [
                [(i, j), (i + 1, j), (i, j + 1)],
                [(i + 1, j), (i + 1, j + 1), (i, j + 1)],
            ] {
                let cells = tri.map(|(a, b)| at(a, b));
                if cells
                    .iter()
                    .any(|c| !(c.lower.is_finite() && c.upper.is_finite()))
                {
                    continue;
                }
                let fc = cells.iter().all(|c| c.first_contact);
                let surfaces: &[(bool, RGBColor)] = if single {
                    &[(false, SINGLE)]
                } else {
                    &[(false, LOWER), (true, UPPER)]
                };
                for &(upper, base) in surfaces {
                    let pts = tri.map(|(a, b)| {
                        let c = at(a, b);
                        let v = if upper { c.upper } else { c.lower };
                        (t1[a], v.clamp(rmin, rmax), t2[b])
                    });
                    let cx = (pts[0].0 + pts[1].0 + pts[2].0) / 3.0;
                    let cy = (pts[0].1 + pts[1].1 + pts[2].1) / 3.0;
                    let cz = (pts[0].2 + pts[1].2 + pts[2].2) / 3.0;
                    let depth = coord.projected_depth(&cx, &cy, &cz);
                    let col = if fc { base.mix(0.85) } else { base.mix(0.18) };
                    tris.push((depth, pts, col));
                }
            }
        }
    }
    tris.sort_by_key(|t| std::cmp::Reverse(t.0));
    chart
        .draw_series(
            tris.into_iter()
                .map(|(_, pts, col)| Polygon::new(pts.to_vec(), col.filled())),
        )
        .map_err(e)?;
    Ok(())
}
