//! `joint_zoom.png`: every joint and abutment seen up close, at true scale — one panel per
//! corner pair (the two corners that face each other across a joint, or a segment corner and
//! the abutment face), centred on the pair's reference midpoint, showing the segments' reference
//! outlines and faces (and the abutment face) and the path of each corner over the run, not
//! magnified. The whole-bridge `plan.png` must magnify the displacements to show them at all,
//! which makes the corners illegible; here the gap, the closings and the slides along the face
//! are read in metres. Every panel has the same half-width, so panels compare.

use crate::plot_style::{BLUE, DARK, DrawResult, FAMILY, GREEN, RED, e};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::{Real, Vector};
use pounding::sim::bridge::{BridgeModel, BridgeSolution};
use pounding::sim::output::{bridge_plan, corner_paths};

/// One panel: its title, the reference midpoint, and the corner paths shown (segment, corner
/// index into `[start c0, start c1, end c0, end c1]`).
struct Site {
    title: String,
    centre: Vector,
    corners: Vec<(usize, usize)>,
}

/// The sites of `model`: per joint its two corner pairs, per abutment its two corners.
fn sites(model: &BridgeModel) -> Vec<Site> {
    let p = bridge_plan(model, 8);
    let n = p.corners.len();
    let mut out = Vec::new();
    let nearest = |a: Vector, cands: &[(usize, usize, Vector)]| {
        cands
            .iter()
            .copied()
            .min_by(|x, y| (x.2 - a).norm().total_cmp(&(y.2 - a).norm()))
    };
    for k in 0..n.saturating_sub(1) {
        let next: Vec<(usize, usize, Vector)> =
            (0..2).map(|c| (k + 1, c, p.corners[k + 1][c])).collect();
        for (side, c) in [2, 3].into_iter().enumerate() {
            let a = p.corners[k][c];
            if let Some((j, cj, b)) = nearest(a, &next) {
                out.push(Site {
                    title: format!("joint {}, side {}", k + 1, ["a", "b"][side]),
                    centre: (a + b) * 0.5,
                    corners: vec![(k, c), (j, cj)],
                });
            }
        }
    }
    for (side, face) in p.abutment_faces.iter().enumerate() {
        let Some(face) = face else { continue };
        let (seg, cs) = if side == 0 {
            (0, [0, 1])
        } else {
            (n - 1, [2, 3])
        };
        for (i, c) in cs.into_iter().enumerate() {
            let a = p.corners[seg][c];
            let f = if (face[0] - a).norm() <= (face[1] - a).norm() {
                face[0]
            } else {
                face[1]
            };
            out.push(Site {
                title: format!(
                    "{} abutment, side {}",
                    ["start", "end"][side],
                    ["a", "b"][i]
                ),
                centre: (a + f) * 0.5,
                corners: vec![(seg, c)],
            });
        }
    }
    out
}

/// The figure's pixel size for `model`: four panels a row.
pub fn size(model: &BridgeModel) -> (u32, u32) {
    let rows = sites(model).len().div_ceil(4).max(1) as u32;
    (1400, 60 + 340 * rows)
}

/// Draws `joint_zoom.png` (module doc).
pub fn draw(
    root: &DrawingArea<BitMapBackend, Shift>,
    model: &BridgeModel,
    sol: &BridgeSolution,
) -> DrawResult {
    let p = bridge_plan(model, 60);
    let paths = corner_paths(model, sol, 1.0);
    let sites = sites(model);
    let finite = |v: &&Vector| v.x.is_finite() && v.y.is_finite();
    // one half-width for every panel: the largest distance of a shown corner from its panel's
    // centre over the run, with a margin
    // a diverged run's corners can be 1e300 m away (plotters' pixel arithmetic overflows on such
    // ranges): panels reach at most 10 m, and points beyond are not drawn
    const MAX_REACH: Real = 10.0;
    let mut reach: Real = 0.0;
    for s in &sites {
        for &(i, c) in &s.corners {
            for q in paths[i][c].iter().filter(finite) {
                let d = (q - s.centre).norm();
                if d <= MAX_REACH {
                    reach = reach.max(d);
                }
            }
        }
    }
    let h = (1.3 * reach).max(0.02);
    let root = root
        .titled(
            &format!(
                "Joints and abutments up close, true scale (no magnification): reference faces and \
                 the path of each corner over the run; panels ±{h:.3} m"
            ),
            (FAMILY, 22),
        )
        .map_err(e)?;
    if sites.is_empty() {
        root.draw(&Text::new(
            "A single segment without abutments: no joint or abutment to show",
            (40, 60),
            (FAMILY, 20).into_font(),
        ))
        .map_err(e)?;
        return Ok(());
    }
    let rows = sites.len().div_ceil(4);
    let panels = root.split_evenly((rows, 4));
    let xy = |v: &Vector| (v.x, v.y);
    for (site, area) in sites.iter().zip(panels.iter()) {
        let (cx, cy) = (site.centre.x, site.centre.y);
        let mut chart = ChartBuilder::on(area)
            .caption(&site.title, (FAMILY, 17))
            .margin(8)
            .x_label_area_size(30)
            .y_label_area_size(52)
            .build_cartesian_2d(cx - h..cx + h, cy - h..cy + h)
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_labels(4)
            .y_labels(4)
            .x_label_formatter(&|v| format!("{v:.2}"))
            .y_label_formatter(&|v| format!("{v:.2}"))
            .label_style((FAMILY, 12))
            .light_line_style(RGBColor(240, 240, 240))
            .draw()
            .map_err(e)?;
        // plotters clamps points outside the range onto its border: clip to the window first
        let window = (cx - h, cx + h, cy - h, cy + h);
        for o in &p.outlines {
            let pts: Vec<(Real, Real)> = o.iter().map(xy).collect();
            let inside = clip_polygon(&pts, window);
            if inside.len() >= 3 {
                chart
                    .draw_series(std::iter::once(Polygon::new(inside, BLUE.mix(0.10))))
                    .map_err(e)?;
            }
            for run in clip_polyline(&pts, window) {
                chart
                    .draw_series(LineSeries::new(run, BLUE.stroke_width(2)))
                    .map_err(e)?;
            }
        }
        for face in p.abutment_faces.iter().flatten() {
            for run in clip_polyline(&[xy(&face[0]), xy(&face[1])], window) {
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        run,
                        RGBColor(120, 120, 120).stroke_width(5),
                    )))
                    .map_err(e)?;
            }
        }
        let colours = [RED, GREEN];
        for (n, &(i, c)) in site.corners.iter().enumerate() {
            let col = colours[n % 2];
            // the path clipped to the panel (a diverged run's points may lie far outside it)
            let pts: Vec<(Real, Real)> = paths[i][c].iter().filter(finite).map(xy).collect();
            let runs = clip_polyline(&pts, window);
            for (r, run) in runs.into_iter().enumerate() {
                let s = chart
                    .draw_series(LineSeries::new(run, col.mix(0.8).stroke_width(1)))
                    .map_err(e)?;
                if r == 0 {
                    s.label(format!("segment {} corner", i + 1))
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 16, y)], col.stroke_width(2))
                        });
                }
            }
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.85))
            .border_style(DARK.mix(0.3))
            .label_font((FAMILY, 12))
            .draw()
            .map_err(e)?;
    }
    Ok(())
}

/// A window `(x_min, x_max, y_min, y_max)`.
type Window = (Real, Real, Real, Real);

/// `poly` (closed or not) clipped to `w` (Sutherland–Hodgman: one pass per window edge).
fn clip_polygon(poly: &[(Real, Real)], w: Window) -> Vec<(Real, Real)> {
    type Edge = (fn((Real, Real), Real) -> Real, Real);
    // signed distance inside each edge: x − x_min, x_max − x, y − y_min, y_max − y
    let edges: [Edge; 4] = [
        (|p, v| p.0 - v, w.0),
        (|p, v| v - p.0, w.1),
        (|p, v| p.1 - v, w.2),
        (|p, v| v - p.1, w.3),
    ];
    let mut out: Vec<(Real, Real)> = poly.to_vec();
    for (dist, v) in edges {
        let input = std::mem::take(&mut out);
        let Some(&last) = input.last() else { break };
        let mut prev = last;
        for &cur in &input {
            let (dp, dc) = (dist(prev, v), dist(cur, v));
            if (dp >= 0.0) != (dc >= 0.0) {
                let t = dp / (dp - dc);
                out.push((prev.0 + t * (cur.0 - prev.0), prev.1 + t * (cur.1 - prev.1)));
            }
            if dc >= 0.0 {
                out.push(cur);
            }
            prev = cur;
        }
    }
    out
}

/// The parts of the polyline `pts` inside `w` (Liang–Barsky per segment), as runs.
fn clip_polyline(pts: &[(Real, Real)], w: Window) -> Vec<Vec<(Real, Real)>> {
    let mut runs: Vec<Vec<(Real, Real)>> = Vec::new();
    let mut open = false;
    for s in pts.windows(2) {
        let (a, b) = (s[0], s[1]);
        let d = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0, 1.0);
        let mut visible = true;
        for (p, q) in [
            (-d.0, a.0 - w.0),
            (d.0, w.1 - a.0),
            (-d.1, a.1 - w.2),
            (d.1, w.3 - a.1),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    visible = false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = Real::max(t0, r);
                } else {
                    t1 = Real::min(t1, r);
                }
            }
        }
        if !visible || t0 > t1 {
            open = false;
            continue;
        }
        let at = |t: Real| (a.0 + t * d.0, a.1 + t * d.1);
        if !open || t0 > 0.0 {
            runs.push(vec![at(t0)]);
        }
        if let Some(r) = runs.last_mut() {
            r.push(at(t1));
        }
        open = t1 >= 1.0;
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::{clip_polygon, clip_polyline};

    #[test]
    fn clipping_keeps_what_is_inside_the_window() {
        let w = (0.0, 1.0, 0.0, 1.0);
        // a square twice the window, centred on its corner (0, 0): the window's quarter remains
        let sq = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        let c = clip_polygon(&sq, w);
        let area: f64 = (0..c.len())
            .map(|i| {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                a.0 * b.1 - b.0 * a.1
            })
            .sum::<f64>()
            / 2.0;
        assert!((area - 1.0).abs() < 1e-12, "{c:?}");
        // a polygon wholly outside vanishes
        assert!(clip_polygon(&[(2.0, 2.0), (3.0, 2.0), (3.0, 3.0)], w).is_empty());
        // a line through the window is cut at its edges; one outside gives nothing
        assert_eq!(
            clip_polyline(&[(-1.0, 0.5), (2.0, 0.5)], w),
            vec![vec![(0.0, 0.5), (1.0, 0.5)]]
        );
        assert!(clip_polyline(&[(-1.0, 2.0), (2.0, 2.0)], w).is_empty());
        // a polyline leaving and re-entering gives two runs
        let runs = clip_polyline(&[(0.5, 0.5), (0.5, 2.0), (0.8, 2.0), (0.8, 0.5)], w);
        assert_eq!(runs.len(), 2, "{runs:?}");
        assert_eq!(runs[0], vec![(0.5, 0.5), (0.5, 1.0)]);
        assert_eq!(runs[1], vec![(0.8, 1.0), (0.8, 0.5)]);
    }
}
