//! `layout.png`: plan view of the two decks, bearings, joint, abutments and axes (reference pose)
//! of the two-segment bridge the two-deck model runs as ([`super::two_deck`]), drawn from the
//! library's plan of it ([`bridge_plan`]); and the plan chart every plan view
//! draws on ([`plan_chart`]).

use crate::plot_style::{BLUE, DrawResult, FAMILY, GREEN, RED, e, series_legend};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use pounding::math::{Real, Vector};
use pounding::sim::bridge::BridgeModel;
use pounding::sim::model::SegmentBody;
use pounding::sim::output::bridge_plan;

const GREY: RGBColor = RGBColor(120, 120, 120);

/// Plan view of the reference pose of the two-deck model's bridge `m` (two segments; spec §4):
/// deck outlines, bearings, joint, abutments, axes; the legend at `legend`.
pub(crate) fn layout<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    m: &BridgeModel,
    legend: SeriesLabelPosition,
) -> DrawResult {
    let g = m.joints.first().map_or(0.0, |j| j.gap);
    let bodies = m.layout();
    let plan = bridge_plan(m, 120);
    let xy = |v: &Vector| (v.x, v.y);
    let outlines: Vec<Vec<(Real, Real)>> = plan
        .outlines
        .iter()
        .map(|o| o.iter().map(xy).collect())
        .collect();
    let abut_polys = abutment_polygons(m, &bodies);
    let bearings = m.bearing_points();
    let (mut chart, (cx, cy, half_x, half_y)) = plan_chart(
        root,
        outlines.iter().flatten().chain(abut_polys.iter().flatten()),
        &format!(
            "Plan view (reference pose): joint opening g = {g} m at y = 0, {} bearings",
            bearings
                .iter()
                .map(|b| b.len().to_string())
                .collect::<Vec<_>>()
                .join(" + ")
        ),
        (
            "x [m] (along the joint)",
            "y [m] (normal to the joint, into deck 1)",
        ),
    )?;
    for (o, (c, name)) in outlines.iter().zip([(BLUE, "deck 1"), (RED, "deck 2")]) {
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
    chart
        .draw_series(
            bearings
                .iter()
                .flatten()
                .map(|p| TriangleMarker::new(xy(p), 8, BLACK.filled())),
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
    let w2 = bodies[0].end.half;
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
    series_legend(&mut chart, legend, BLACK, 15)
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

/// The abutments of `m` (laid out as `bodies`): each outer end face moved out by its gap,
/// drawn 1.6 face lengths long and 6 % of one deep.
fn abutment_polygons(m: &BridgeModel, bodies: &[SegmentBody]) -> Vec<Vec<(Real, Real)>> {
    let (Some(first), Some(last)) = (bodies.first(), bodies.last()) else {
        return Vec::new();
    };
    [&first.start, &last.end]
        .into_iter()
        .zip(&m.abutments)
        .filter_map(|(far, a)| {
            let a = a.as_ref()?;
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
