//! `layout.png`: plan view of the two decks, bearings, joint, abutments and axes (reference pose),
//! the two-deck form's own figure ([`super::two_deck`]); and the plan chart every plan view
//! draws on ([`plan_chart`]).

use crate::plot_style::{BLUE, DrawResult, FAMILY, GREEN, RED, e, series_legend};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use pounding::math::Real;
use pounding::sim::SimModel;

const GREY: RGBColor = RGBColor(120, 120, 120);

/// Plan view of the reference pose (spec §4): deck outlines, bearings, joint, axes.
pub(crate) fn layout<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    m: &SimModel,
) -> DrawResult {
    let g = m.gap;
    let bodies = m.deck_bodies();
    let (o1, o2) = (deck_outline(m, 1), deck_outline(m, 2));
    let abut_polys = abutment_polygons(m);
    let (mut chart, (cx, cy, half_x, half_y)) = plan_chart(
        root,
        o1.iter().chain(&o2).chain(abut_polys.iter().flatten()),
        &format!(
            "Plan view (reference pose): joint opening g = {g} m at y = 0, {} + {} bearings",
            m.bearings1.len(),
            m.bearings2.len()
        ),
        (
            "x [m] (along the joint)",
            "y [m] (normal to the joint, into deck 1)",
        ),
    )?;
    for (o, c, name) in [(&o1, BLUE, "deck 1"), (&o2, RED, "deck 2")] {
        chart
            .draw_series(std::iter::once(Polygon::new(o.clone(), c.mix(0.15))))
            .map_err(e)?;
        chart
            .draw_series(LineSeries::new(o.iter().copied(), c.stroke_width(2)))
            .map_err(e)?
            .label(name)
            .legend(move |(x, y)| {
                Rectangle::new([(x, y - 5), (x + 20, y + 5)], c.mix(0.5).filled())
            });
    }
    let bearings: Vec<(Real, Real)> = m
        .bearings1
        .iter()
        .map(|b| (b.point.x, b.point.y + g))
        .chain(m.bearings2.iter().map(|b| (b.point.x, b.point.y)))
        .collect();
    chart
        .draw_series(
            bearings
                .iter()
                .map(|&p| TriangleMarker::new(p, 8, BLACK.filled())),
        )
        .map_err(e)?
        .label("bearing (seat)")
        .legend(|(x, y)| TriangleMarker::new((x + 10, y), 6, BLACK.filled()));
    for (k, poly) in abut_polys.iter().enumerate() {
        let s = chart
            .draw_series(std::iter::once(Polygon::new(poly.clone(), GREY.filled())))
            .map_err(e)?;
        if k == 0 {
            s.label("abutment (rigid)")
                .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], GREY.filled()));
        }
    }
    let w2 = bodies[0].joint_face(1).half;
    chart
        .draw_series(std::iter::once(PathElement::new(
            vec![(-w2 * 3.0, 0.0), (w2 * 3.0, 0.0)],
            GREEN.stroke_width(3),
        )))
        .map_err(e)?
        .label("expansion joint (contacts at the face ends x = ±b/2, b = face length)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], GREEN.stroke_width(3)));
    let style = TextStyle::from((FAMILY, 15).into_font()).color(&BLACK);
    for (txt, x, y) in [
        ("deck 1 (y > 0)", 0.45 * (cx + half_x), 0.35 * (cy + half_y)),
        ("deck 2 (y < 0)", 0.45 * (cx - half_x), 0.35 * (cy - half_y)),
    ] {
        chart
            .draw_series(std::iter::once(Text::new(
                txt.to_string(),
                (x, y),
                style.clone(),
            )))
            .map_err(e)?;
    }
    let position = if m.shapes.is_some() {
        SeriesLabelPosition::UpperRight
    } else {
        SeriesLabelPosition::UpperLeft
    };
    series_legend(&mut chart, position, BLACK, 15)
}

/// A plan-view chart on `root` with equal scales showing `points` ([`view_box`]), the
/// `caption` and the axis descriptions `(x, y)`, its mesh drawn; and the view
/// `(cx, cy, half_x, half_y)`.
pub(crate) fn plan_chart<'a, 'p, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    points: impl Iterator<Item = &'p (Real, Real)>,
    caption: &str,
    (x_desc, y_desc): (&str, &str),
) -> DrawResult<(PlanChart<'a, DB>, View)> {
    let (w, h) = root.dim_in_pixel();
    let (cx, cy, half_x, half_y) = view_box(points, (w as Real - 80.0) / (h as Real - 100.0));
    let mut chart = ChartBuilder::on(root)
        .caption(caption, (FAMILY, 20))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d((cx - half_x)..(cx + half_x), (cy - half_y)..(cy + half_y))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 15))
        .light_line_style(RGBColor(240, 240, 240))
        .draw()
        .map_err(e)?;
    Ok((chart, (cx, cy, half_x, half_y)))
}

/// The view `(cx, cy, half_x, half_y)` of a plan \[m\].
pub(crate) type View = (Real, Real, Real, Real);

/// A chart in metres on both axes.
pub(crate) type PlanChart<'a, DB> =
    ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Outline of deck `j` (1 or 2) in the plan view: the curved deck's arcs, or the four end-face
/// corners of a straight/skew deck (closed polygon).
fn deck_outline(m: &SimModel, j: usize) -> Vec<(Real, Real)> {
    let g = m.gap;
    let bodies = m.deck_bodies();
    let shape = m.shapes.map(|s| s[j - 1]);
    let d = match (shape, shape.as_ref().and_then(|s| s.curved())) {
        (None, _) if j == 1 => m.arrangement.deck1,
        (None, _) => m.arrangement.deck2,
        (Some(_), Some(d)) => *d,
        (Some(_), None) => {
            // straight / skewed: the four end-face corners (joint c0, c1, far c0, c1)
            let (joint, far) = (bodies[j - 1].joint_face(j), bodies[j - 1].far_face(j));
            return [
                joint.corners[0],
                joint.corners[1],
                far.corners[0],
                far.corners[1],
                joint.corners[0],
            ]
            .iter()
            .map(|p| (p.x, p.y))
            .collect();
        }
    };
    let d = &d;
    let s = if j == 1 { 1.0 } else { -1.0 };
    let off = if j == 1 { g } else { 0.0 };
    let pt = |r: Real, phi: Real| (s * (d.radius - r * phi.cos()), off + s * r * phi.sin());
    let (ri, ro) = (d.radius - d.width / 2.0, d.radius + d.width / 2.0);
    let n = 120;
    let mut v: Vec<(Real, Real)> = (0..=n)
        .map(|k| pt(ri, d.angle * k as Real / n as Real))
        .collect();
    v.extend(
        (0..=n)
            .rev()
            .map(|k| pt(ro, d.angle * k as Real / n as Real)),
    );
    v.push(v[0]);
    v
}

/// The abutment faces: the far-face line moved by the abutment gap, drawn 1.6 face lengths long.
fn abutment_polygons(m: &SimModel) -> Vec<Vec<(Real, Real)>> {
    let bodies = m.deck_bodies();
    m.abutments
        .iter()
        .enumerate()
        .filter_map(|(j, a)| {
            let a = a.as_ref()?;
            let far = bodies[j].far_face(j + 1);
            let n_out = -far.inward;
            let c = far.mid + n_out * a.gap;
            let dir = (far.corners[1] - far.corners[0]) * 0.8;
            let back = n_out * (0.06 * (far.corners[1] - far.corners[0]).norm());
            Some(
                [c - dir, c + dir, c + dir + back, c - dir + back]
                    .iter()
                    .map(|p| (p.x, p.y))
                    .collect(),
            )
        })
        .collect()
}

/// Centre and half-extents `(cx, cy, half_x, half_y)` of a view of `points` with 8 % padding and
/// equal scales: the smaller range is widened to the drawing area's aspect ratio `aspect`
/// (non-finite points are skipped, so the view is always finite).
fn view_box<'a>(
    points: impl Iterator<Item = &'a (Real, Real)>,
    aspect: Real,
) -> (Real, Real, Real, Real) {
    let (mut lo_x, mut hi_x, mut lo_y, mut hi_y) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for &(x, y) in points {
        if x.is_finite() && y.is_finite() {
            lo_x = lo_x.min(x);
            hi_x = hi_x.max(x);
            lo_y = lo_y.min(y);
            hi_y = hi_y.max(y);
        }
    }
    let ((lo_x, hi_x), (lo_y, hi_y)) = (
        crate::figures::sane_range(lo_x, hi_x, (0.0, 0.0)),
        crate::figures::sane_range(lo_y, hi_y, (0.0, 0.0)),
    );
    // equal scales: widen the smaller range to the drawing area's aspect ratio
    let pad = 0.08 * (hi_x - lo_x).max(hi_y - lo_y);
    let (cx, cy) = ((lo_x + hi_x) / 2.0, (lo_y + hi_y) / 2.0);
    let mut half_x = (hi_x - lo_x) / 2.0 + pad;
    let mut half_y = (hi_y - lo_y) / 2.0 + pad;
    if half_x / half_y < aspect {
        half_x = half_y * aspect;
    } else {
        half_y = half_x / aspect;
    }
    (cx, cy, half_x, half_y)
}
