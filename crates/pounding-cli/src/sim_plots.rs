//! PNG plots of `pounding simulate` (plotters, embedded DejaVu Sans font).
//!
//! * `displacements.png` — ground acceleration and both decks' centroid displacements;
//! * `rotations.png` — plan rotations θ1, θ2;
//! * `joint_gap.png` — the joint gap at both ends of the joint, with the impacts marked;
//! * `impulses.png` — normal and tangential impulse of every impacting contact, by mode;
//! * `energy.png` — the energy balance (input, stored, dissipated);
//! * `abutment_gap.png` — with abutments: the gap of each far end face to its abutment;
//! * `layout.png` — plan view of the two decks, bearings, joint, abutments and axes (reference pose).

use crate::figures::sane_range;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::{FontStyle, register_font};
use pounding::analytic::SlipMode;
use pounding::math::Real;
use pounding::sim::{SimProblem, SimSolution};
use std::path::Path;
use std::sync::Once;

static FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();
const FAMILY: &str = "sans-serif";

fn register() {
    REGISTER.call_once(|| {
        for style in [FontStyle::Normal, FontStyle::Bold] {
            // The bytes are a valid TrueType font shipped with the repository.
            let _ = register_font(FAMILY, style, FONT);
        }
    });
}

type R<T = ()> = Result<T, String>;

fn e<E: std::fmt::Display>(err: E) -> String {
    err.to_string()
}

const BLUE: RGBColor = RGBColor(31, 97, 180);
const RED: RGBColor = RGBColor(200, 40, 40);
const GREEN: RGBColor = RGBColor(39, 150, 80);
const ORANGE: RGBColor = RGBColor(230, 126, 34);
const PURPLE: RGBColor = RGBColor(142, 68, 173);
const GREY: RGBColor = RGBColor(120, 120, 120);

struct Series<'a> {
    label: &'a str,
    pts: Vec<(Real, Real)>,
    color: RGBColor,
}

/// One line panel with a title, axis labels, legend and optional dashed horizontal lines.
fn line_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    ylabel: &str,
    t_end: Real,
    series: &[Series],
    hlines: &[(Real, &str, RGBColor)],
    legend: SeriesLabelPosition,
) -> R {
    let mut lo = Real::INFINITY;
    let mut hi = Real::NEG_INFINITY;
    for s in series {
        for &(_, y) in &s.pts {
            if y.is_finite() {
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
    }
    for (y, _, _) in hlines.iter().filter(|h| h.0.is_finite()) {
        lo = lo.min(*y);
        hi = hi.max(*y);
    }
    let (lo, hi) = sane_range(lo, hi, (-1.0, 1.0));
    let pad = ((hi - lo) * 0.08).max(1e-12);
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FAMILY, 22))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d(0.0..t_end, (lo - pad)..(hi + pad))
        .map_err(e)?;
    let span = hi - lo + 2.0 * pad;
    chart
        .configure_mesh()
        .x_desc("time t [s]")
        .y_desc(ylabel)
        .y_label_formatter(&|v| tick(*v, span))
        .label_style((FAMILY, 15))
        .axis_desc_style((FAMILY, 16))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    for (y, label, c) in hlines {
        let c = *c;
        let drawn = chart
            .draw_series(DashedLineSeries::new(
                vec![(0.0, *y), (t_end, *y)],
                6,
                4,
                c.stroke_width(1),
            ))
            .map_err(e)?;
        if !label.is_empty() {
            drawn.label(*label).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(1))
            });
        }
    }
    for s in series {
        let c = s.color;
        chart
            .draw_series(LineSeries::new(
                s.pts.iter().copied().filter(|p| p.1.is_finite()),
                c.stroke_width(1),
            ))
            .map_err(e)?
            .label(s.label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(legend)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FAMILY, 15))
        .draw()
        .map_err(e)?;
    Ok(())
}

/// Axis tick text: 3 significant digits relative to the axis span, no `-0`.
fn tick(v: Real, span: Real) -> String {
    if v.abs() < 1e-9 * span.abs() {
        return "0".into();
    }
    let digits = (2.0 - span.abs().log10().floor()).clamp(0.0, 12.0) as usize;
    let s = format!("{v:.digits$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".into()
    } else {
        s
    }
}

fn save(
    out: &Path,
    name: &str,
    size: (u32, u32),
    draw: impl Fn(&DrawingArea<BitMapBackend, Shift>) -> R,
) -> R {
    crate::figures::save_png(&out.join(name), size, |root| {
        root.fill(&WHITE).map_err(e)?;
        draw(root)
    })
}

const DEG: Real = 180.0 / std::f64::consts::PI;

/// Writes all plots into `out`.
pub fn write_all(out: &Path, problem: &SimProblem, sol: &SimSolution) -> R {
    register();
    let h = &sol.history;
    let t_end = h.t.last().copied().unwrap_or(1.0).max(1e-9);
    let col = |f: &dyn Fn(usize) -> Real| -> Vec<(Real, Real)> {
        (0..h.t.len()).map(|i| (h.t[i], f(i))).collect()
    };
    let g = problem.model.gap;

    save(out, "displacements.png", (1400, 1050), |root| {
        let areas = root.split_evenly((3, 1));
        let ag: Vec<_> = h.t.iter().map(|&t| problem.ground.accel(t)).collect();
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
            let o = 3 * j;
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
                        pts: col(&|i| h.q[i][o + 1]),
                        color: BLUE,
                    },
                    Series {
                        label: &format!("x{} (along joint)", j + 1),
                        pts: col(&|i| h.q[i][o]),
                        color: ORANGE,
                    },
                ],
                &[],
                SeriesLabelPosition::UpperRight,
            )?;
        }
        Ok(())
    })?;

    save(out, "layout.png", (1000, 900), |root| layout(root, problem))?;

    save(out, "rotations.png", (1400, 500), |root| {
        line_panel(
            root,
            "Plan rotation of each deck about its centroid (counter-clockwise +)",
            "rotation [deg]",
            t_end,
            &[
                Series {
                    label: "θ1 (deck 1)",
                    pts: col(&|i| h.q[i][2] * DEG),
                    color: BLUE,
                },
                Series {
                    label: "θ2 (deck 2)",
                    pts: col(&|i| h.q[i][5] * DEG),
                    color: RED,
                },
            ],
            &[(0.0, "", GREY)],
            SeriesLabelPosition::UpperRight,
        )
    })?;

    save(out, "joint_gap.png", (1400, 600), |root| {
        let w = problem.model.deck_bodies()[0].half_face;
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
                    pts: col(&|i| h.end_gaps[i][0]),
                    color: BLUE,
                },
                Series {
                    label: &format!("end x = −{w} m (deck1-outer / deck2-inner)"),
                    pts: col(&|i| h.end_gaps[i][1]),
                    color: RED,
                },
            ],
            &[(g, "initial opening g", GREY), (0.0, "contact", BLACK)],
            SeriesLabelPosition::UpperRight,
        )?;
        Ok(())
    })?;

    if problem.model.abutments.iter().any(Option::is_some) {
        save(out, "abutment_gap.png", (1400, 600), |root| {
            let mut series = Vec::new();
            let mut lines = vec![(0.0, "contact", BLACK)];
            let labels = ["deck 1 far end", "deck 2 far end"];
            let gap_labels = ["initial gap, abutment 1", "initial gap, abutment 2"];
            for (j, a) in problem.model.abutments.iter().enumerate() {
                if let Some(a) = a {
                    let c = if j == 0 { BLUE } else { RED };
                    series.push(Series {
                        label: labels[j],
                        pts: col(&|i| h.abutment_gaps[i][j]),
                        color: c,
                    });
                    lines.push((a.gap, gap_labels[j], c));
                }
            }
            line_panel(
                root,
                &format!(
                    "Gap between far end faces and abutments (smaller of the two corners; {} impacting contacts)",
                    sol.summary.abutment_impacting_contacts
                ),
                "gap [m]",
                t_end,
                &series,
                &lines,
                SeriesLabelPosition::UpperRight,
            )
        })?;
    }

    save(out, "impulses.png", (1400, 800), |root| {
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
            let (lo, hi) = sane_range(lo, hi, (0.0, 0.0));
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
    })?;

    save(out, "energy.png", (1400, 600), |root| {
        let en = |f: &dyn Fn(&pounding::sim::Energy) -> Real| col(&|i| f(&h.energy[i]) / 1e3);
        line_panel(
            root,
            &format!(
                "Energy balance (relative error {:.1e}): input = stored + dissipated",
                sol.summary.energy_balance_error
            ),
            "energy [kJ]",
            t_end,
            &[
                Series {
                    label: "seismic input W_in",
                    pts: en(&|e| e.input),
                    color: BLACK,
                },
                Series {
                    label: "viscous dissipation",
                    pts: en(&|e| e.viscous),
                    color: BLUE,
                },
                Series {
                    label: "contact dissipation",
                    pts: en(&|e| e.contact),
                    color: RED,
                },
                Series {
                    label: "kinetic + strain",
                    pts: en(&|e| e.kinetic + e.potential),
                    color: GREEN,
                },
            ],
            &[],
            SeriesLabelPosition::UpperLeft,
        )
    })?;
    Ok(())
}

/// Plan view of the reference pose (spec §4): deck outlines, bearings, joint, axes.
fn layout<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, problem: &SimProblem) -> R {
    let m = &problem.model;
    let g = m.gap;
    let bodies = m.deck_bodies();
    let outline = |j: usize| -> Vec<(Real, Real)> {
        use pounding::shape::DeckShape;
        let d = match m.shapes.map(|s| s[j - 1]) {
            None if j == 1 => m.arrangement.deck1,
            None => m.arrangement.deck2,
            Some(DeckShape::Curved(d)) => d,
            Some(_) => {
                // straight / skewed: the four end-face corners (joint c0, c1, far c0, c1)
                let b = &bodies[j - 1];
                return [
                    b.joint_corners[0],
                    b.joint_corners[1],
                    b.far_corners[0],
                    b.far_corners[1],
                    b.joint_corners[0],
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
    };
    let (o1, o2) = (outline(1), outline(2));
    // abutment faces: the far-face line moved by the abutment gap, drawn 1.6 face lengths long
    let abut_polys: Vec<Vec<(Real, Real)>> = m
        .abutments
        .iter()
        .enumerate()
        .filter_map(|(j, a)| {
            let a = a.as_ref()?;
            let b = &bodies[j];
            let n_out = -b.far_inward;
            let c = b.far_mid() + n_out * a.gap;
            let dir = (b.far_corners[1] - b.far_corners[0]) * 0.8;
            let back = n_out * (0.06 * (b.far_corners[1] - b.far_corners[0]).norm());
            Some(
                [c - dir, c + dir, c + dir + back, c - dir + back]
                    .iter()
                    .map(|p| (p.x, p.y))
                    .collect(),
            )
        })
        .collect();
    let (mut lo_x, mut hi_x, mut lo_y, mut hi_y) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for &(x, y) in o1.iter().chain(&o2).chain(abut_polys.iter().flatten()) {
        if x.is_finite() && y.is_finite() {
            lo_x = lo_x.min(x);
            hi_x = hi_x.max(x);
            lo_y = lo_y.min(y);
            hi_y = hi_y.max(y);
        }
    }
    let ((lo_x, hi_x), (lo_y, hi_y)) = (
        sane_range(lo_x, hi_x, (0.0, 0.0)),
        sane_range(lo_y, hi_y, (0.0, 0.0)),
    );
    // equal scales: widen the smaller range to the drawing area's aspect ratio
    let (w, h) = root.dim_in_pixel();
    let pad = 0.08 * (hi_x - lo_x).max(hi_y - lo_y);
    let (cx, cy) = ((lo_x + hi_x) / 2.0, (lo_y + hi_y) / 2.0);
    let mut half_x = (hi_x - lo_x) / 2.0 + pad;
    let mut half_y = (hi_y - lo_y) / 2.0 + pad;
    let aspect = (w as Real - 80.0) / (h as Real - 100.0);
    if half_x / half_y < aspect {
        half_x = half_y * aspect;
    } else {
        half_y = half_x / aspect;
    }
    let mut chart = ChartBuilder::on(root)
        .caption(
            format!(
                "Plan view (reference pose): joint opening g = {g} m at y = 0, {} + {} bearings",
                m.bearings1.len(),
                m.bearings2.len()
            ),
            (FAMILY, 20),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d((cx - half_x)..(cx + half_x), (cy - half_y)..(cy + half_y))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("x [m] (along the joint)")
        .y_desc("y [m] (normal to the joint, into deck 1)")
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 15))
        .light_line_style(RGBColor(240, 240, 240))
        .draw()
        .map_err(e)?;
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
    let w2 = bodies[0].half_face;
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
    chart
        .configure_series_labels()
        .position(if m.shapes.is_some() {
            SeriesLabelPosition::UpperRight
        } else {
            SeriesLabelPosition::UpperLeft
        })
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font((FAMILY, 15))
        .draw()
        .map_err(e)?;
    Ok(())
}

/// One record's curve in the batch plot: `(PGA [g], value)` points sorted by PGA.
pub struct BatchCurve {
    /// Record name (legend).
    pub label: String,
    /// `(x, [seat displacement, joint opening, rotation, impacts])` per successful run.
    pub pts: Vec<(Real, [Real; 4])>,
}

const PALETTE: [RGBColor; 8] = [
    BLUE,
    RED,
    GREEN,
    ORANGE,
    PURPLE,
    RGBColor(23, 162, 184),
    RGBColor(140, 86, 75),
    GREY,
];

/// Smallest y range of the batch plot's rotation panel \[deg\].
pub const ROTATION_MIN_RANGE_DEG: Real = 1e-3;

/// The data range `(lo, hi)` of panel `k` of `batch.png` (0 is always included; the seat length
/// in panel 0; at least [`ROTATION_MIN_RANGE_DEG`] in the rotation panel 2).
fn batch_panel_range(k: usize, curves: &[BatchCurve], seat_length: Real) -> (Real, Real) {
    let mut lo: Real = 0.0;
    let mut hi = Real::NEG_INFINITY;
    for c in curves {
        for p in &c.pts {
            if p.1[k].is_finite() {
                lo = lo.min(p.1[k]);
                hi = hi.max(p.1[k]);
            }
        }
    }
    if k == 0 {
        hi = hi.max(seat_length);
    }
    if k == 2 && hi.is_finite() {
        // at least 1e-3 deg, so rounding noise (~1e-17 deg in symmetric cases) reads as 0
        hi = hi.max(lo + ROTATION_MIN_RANGE_DEG);
    }
    if !(hi.is_finite() && hi > lo) {
        hi = lo + 1.0;
    }
    sane_range(lo, hi, (0.0, 1.0))
}

/// `batch.png`: peak response against intensity (PGA of the applied component) per record, four
/// panels (seat displacement with the seat length, joint opening, plan rotation, impacts).
pub fn batch_plot(out: &Path, name: &str, curves: &[BatchCurve], seat_length: Real) -> R {
    register();
    let titles = [
        (
            "Peak seat displacement (dashed: seat length)",
            "seat displacement [m]",
        ),
        ("Peak joint opening", "opening [m]"),
        ("Peak plan rotation (either deck)", "rotation [deg]"),
        ("Number of impacts", "impacts"),
    ];
    let mut xmax: Real = 0.0;
    for c in curves {
        for p in &c.pts {
            if p.0.is_finite() {
                xmax = xmax.max(p.0);
            }
        }
    }
    let xmax = if xmax > 0.0 { xmax * 1.05 } else { 1.0 };
    save(out, name, (1400, 1000), |root| {
        let areas = root.split_evenly((2, 2));
        for (k, area) in areas.iter().enumerate() {
            let (lo, hi) = batch_panel_range(k, curves, seat_length);
            let pad = (hi - lo) * 0.08;
            let span = hi - lo + 2.0 * pad;
            let mut chart = ChartBuilder::on(area)
                .caption(titles[k].0, (FAMILY, 22))
                .margin(10)
                .x_label_area_size(40)
                .y_label_area_size(80)
                .build_cartesian_2d(0.0..xmax, (lo - pad)..(hi + pad))
                .map_err(e)?;
            chart
                .configure_mesh()
                .x_desc("PGA of the applied component [g]")
                .y_desc(titles[k].1)
                .x_label_formatter(&|v| tick(*v, xmax))
                .y_label_formatter(&|v| {
                    if k == 3 {
                        format!("{v:.0}")
                    } else {
                        tick(*v, span)
                    }
                })
                .label_style((FAMILY, 15))
                .axis_desc_style((FAMILY, 16))
                .light_line_style(RGBColor(235, 235, 235))
                .draw()
                .map_err(e)?;
            if k == 0 {
                chart
                    .draw_series(DashedLineSeries::new(
                        vec![(0.0, seat_length), (xmax, seat_length)],
                        6,
                        4,
                        BLACK.stroke_width(1),
                    ))
                    .map_err(e)?;
            }
            for (ci, c) in curves.iter().enumerate() {
                let col = PALETTE[ci % PALETTE.len()];
                let pts: Vec<(Real, Real)> = c
                    .pts
                    .iter()
                    .map(|p| (p.0, p.1[k]))
                    .filter(|p| p.0.is_finite() && p.1.is_finite())
                    .collect();
                let s = chart
                    .draw_series(LineSeries::new(pts.iter().copied(), col.stroke_width(2)))
                    .map_err(e)?;
                if k == 0 {
                    s.label(c.label.as_str()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2))
                    });
                }
                chart
                    .draw_series(pts.iter().map(|&p| Circle::new(p, 4, col.filled())))
                    .map_err(e)?;
            }
            if k == 0 && !curves.is_empty() {
                chart
                    .configure_series_labels()
                    .position(SeriesLabelPosition::UpperLeft)
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .label_font((FAMILY, 13))
                    .draw()
                    .map_err(e)?;
            }
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_panel_of_symmetric_batches_has_readable_ticks_and_reads_as_zero() {
        // symmetric cases: peak rotations are rounding noise of ~1e-17 deg
        let curves = [BatchCurve {
            label: "r".into(),
            pts: vec![
                (0.1, [0.01, 0.0, 1e-17, 1.0]),
                (0.2, [0.02, 0.0, 3e-17, 2.0]),
            ],
        }];
        let (lo, hi) = batch_panel_range(2, &curves, 0.5);
        assert!(hi - lo >= ROTATION_MIN_RANGE_DEG, "{lo} {hi}");
        let pad = (hi - lo) * 0.08;
        let span = hi - lo + 2.0 * pad;
        // tick labels across the axis are distinct (not all "0"), and the noise reads as 0
        let labels: Vec<String> = (0..=4)
            .map(|i| tick(lo - pad + span * i as Real / 4.0, span))
            .collect();
        let mut uniq = labels.clone();
        uniq.dedup();
        assert_eq!(uniq.len(), labels.len(), "{labels:?}");
        assert_eq!(tick(3e-17, span), "0");
        // a real rotation is not clipped
        let big = [BatchCurve {
            label: "r".into(),
            pts: vec![(0.1, [0.01, 0.0, 2.5, 1.0])],
        }];
        assert_eq!(batch_panel_range(2, &big, 0.5), (0.0, 2.5));
    }
}
