//! Figures of `pounding study` (plotters; PNG, and SVG on request). Fonts are embedded
//! (`assets/fonts/DejaVuSans.ttf`), never taken from the system.
//!
//! * `surface_*.png` — per (β1, β2, R1, R2, μ, ε): the lower and upper stick surfaces `L`, `U` over
//!   `θ1 × θ2` for the four cases (paper Figures 3–6); first-contact cells saturated, others pale.
//! * `regions_*.png` — per (β1, β2, R1, R2, ε): region maps in the style of the paper's Figures 7–8
//!   (x: striking deck's rotation `θ_a` with the struck deck at 0; y: `r = γ_T⁻/γ_N⁻`), one row per μ.
//! * `overview_*.png` — how the stick band changes with μ, β and R1/R2 (means over first-contact cells).

use anyhow::{Result, anyhow};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::{FontStyle, register_font};
use pounding::geometry::ContactCase;
use pounding::math::Real;
use pounding::output::write_atomic;
use pounding::study::StudyShape;
use pounding::study::cell::region_samples_in;
use pounding::study::summary::shares;
use pounding::study::{RowKey, Study};
use rayon::prelude::*;
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

/// One figure file.
#[derive(Debug, Clone)]
pub struct Figure {
    /// Path of the PNG relative to the output directory (`figures/...png`).
    pub png: String,
    /// Path of the SVG relative to the output directory, when written.
    pub svg: Option<String>,
    /// Caption (plain text).
    pub caption: String,
}

/// Figures shown together in the report.
#[derive(Debug, Clone)]
pub struct FigureGroup {
    /// HTML id / anchor.
    pub id: String,
    /// Heading.
    pub title: String,
    /// The figures.
    pub figures: Vec<Figure>,
}

const OUTWARD: RGBColor = RGBColor(230, 126, 34);
const STICK: RGBColor = RGBColor(39, 174, 96);
const INWARD: RGBColor = RGBColor(142, 68, 173);
const LOWER: RGBColor = RGBColor(31, 97, 180);
const UPPER: RGBColor = RGBColor(200, 40, 40);
const GREY: RGBColor = RGBColor(200, 200, 200);
const SINGLE: RGBColor = RGBColor(110, 60, 150);

type DrawResult = Result<(), String>;
/// A triangle in chart coordinates (θ1, r, θ2).
type Tri = [(Real, Real, Real); 3];

fn e<E: std::fmt::Display>(err: E) -> String {
    err.to_string()
}

/// Draws a PNG of `size` pixels in memory with `draw` and writes it to `path` atomically
/// ([`write_atomic`]: a temporary beside it, renamed; removed on any error). Errors name `path`.
/// The bytes are those plotters' file backend writes (the same `image` PNG encoder, default
/// settings).
pub(crate) fn save_png<F>(path: &Path, (w, h): (u32, u32), draw: F) -> Result<(), String>
where
    F: FnOnce(&DrawingArea<BitMapBackend, Shift>) -> Result<(), String>,
{
    use image::ImageEncoder;
    let mut buf = vec![0u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        draw(&root).map_err(|err| format!("cannot draw {}: {err}", path.display()))?;
        root.present()
            .map_err(|err| format!("cannot draw {}: {err}", path.display()))?;
    }
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(&buf, w, h, image::ColorType::Rgb8)
        .map_err(|err| format!("cannot encode {}: {err}", path.display()))?;
    write_atomic(path, &png).map_err(|err| format!("cannot write {}: {err}", path.display()))
}

/// Largest magnitude of a plotted data bound: keeps `hi − lo`, the padding and the axis ends
/// finite (an infinite axis range makes plotters' tick search loop forever).
pub(crate) const AXIS_LIMIT: Real = 1e300;

/// A sane data range for an axis: `(lo, hi)` clamped to `±`[`AXIS_LIMIT`] when both are finite
/// (the callers skip non-finite values when they gather them), otherwise `default` (no finite
/// value at all). The result is finite, so any padding of it stays finite.
pub(crate) fn sane_range(lo: Real, hi: Real, default: (Real, Real)) -> (Real, Real) {
    if lo.is_finite() && hi.is_finite() {
        (
            lo.clamp(-AXIS_LIMIT, AXIS_LIMIT),
            hi.clamp(-AXIS_LIMIT, AXIS_LIMIT),
        )
    } else {
        default
    }
}

fn font(size: u32) -> TextStyle<'static> {
    (FAMILY, size).into_font().color(&BLACK)
}

/// Axis tick text: at most 3 decimals, trailing zeros dropped (`-10`, `2.5`, `0.25`).
fn tick(v: &Real) -> String {
    let t = format!("{v:.3}");
    let t = t.trim_end_matches('0').trim_end_matches('.');
    if t == "-0" { "0".into() } else { t.to_string() }
}

fn tok(x: Real) -> String {
    pounding::output::float_token(x)
}

enum Job {
    Surface {
        geom: [usize; 4],
        mu: usize,
        eps: usize,
    },
    Regions {
        geom: [usize; 4],
        eps: usize,
    },
    Overview(usize),
}

/// Draws every figure of `study` into `out/figures` on `pool` and returns them grouped for the report.
pub fn draw_all(
    study: &Study,
    out: &Path,
    svg: bool,
    pool: &rayon::ThreadPool,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<FigureGroup>> {
    register();
    let dir = out.join("figures");
    std::fs::create_dir_all(&dir)
        .map_err(|err| anyhow!("cannot create {}: {err}", dir.display()))?;
    let s = &study.scenario;
    let mut groups = vec![FigureGroup {
        id: "overview".into(),
        title: if s.shape == StudyShape::Curved {
            "Overview: the stick band against μ, β and R1/R2".into()
        } else {
            format!(
                "Overview ({} decks): the stick band against μ, L and L1/L2",
                s.shape.name()
            )
        },
        figures: Vec::new(),
    }];
    let mut jobs: Vec<(usize, Job)> = (0..3).map(|k| (0, Job::Overview(k))).collect();
    let [nb1, nb2, nr1, nr2] = s.geometry_dims();
    for b1 in 0..nb1 {
        for b2 in 0..nb2 {
            for r1 in 0..nr1 {
                for r2 in 0..nr2 {
                    let g = groups.len();
                    groups.push(FigureGroup {
                        // Curved: g-b1-60-b2-90-r1-100-r2-200 (as before shapes existed).
                        id: format!("g-{}", s.geometry_id([b1, b2, r1, r2]).replace('_', "-")),
                        title: s.geometry_label([b1, b2, r1, r2]),
                        figures: Vec::new(),
                    });
                    for eps in 0..s.eps.len() {
                        for mu in 0..s.mu.len() {
                            jobs.push((
                                g,
                                Job::Surface {
                                    geom: [b1, b2, r1, r2],
                                    mu,
                                    eps,
                                },
                            ));
                        }
                        jobs.push((
                            g,
                            Job::Regions {
                                geom: [b1, b2, r1, r2],
                                eps,
                            },
                        ));
                    }
                }
            }
        }
    }
    let drawn: Vec<(usize, Result<Figure, String>)> = pool.install(|| {
        jobs.par_iter()
            .map(|(g, job)| {
                let r = draw_job(study, out, svg, job);
                progress(1, jobs.len());
                (*g, r)
            })
            .collect()
    });
    for (g, fig) in drawn {
        groups[g]
            .figures
            .push(fig.map_err(|err| anyhow!("drawing a figure failed: {err}"))?);
    }
    Ok(groups)
}

fn draw_job(study: &Study, out: &Path, svg: bool, job: &Job) -> Result<Figure, String> {
    let s = &study.scenario;
    let (name, caption, size) = match job {
        Job::Surface {
            geom: [b1, b2, r1, r2],
            mu,
            eps,
        } => (
            format!(
                "surface_{}_mu-{}_eps-{}",
                s.geometry_id([*b1, *b2, *r1, *r2]),
                tok(s.mu[*mu]),
                tok(s.eps[*eps])
            ),
            format!(
                "Stick surfaces L (lower) and U (upper) over θ1 × θ2, μ = {}, ε_N = {}",
                tok(s.mu[*mu]),
                tok(s.eps[*eps])
            ),
            (1200u32, 1000u32),
        ),
        Job::Regions {
            geom: [b1, b2, r1, r2],
            eps,
        } => (
            format!(
                "regions_{}_eps-{}",
                s.geometry_id([*b1, *b2, *r1, *r2]),
                tok(s.eps[*eps])
            ),
            format!(
                "Region maps (paper Figs 7–8): striking deck rotated by θ_a, struck deck at 0, ε_N = {}",
                tok(s.eps[*eps])
            ),
            (1200u32, 110 + 240 * s.mu.len() as u32),
        ),
        Job::Overview(k) => {
            let (n, c) = [
                (
                    "overview_mu",
                    "Stick band against μ: mean bounds per case, and mean shares of the ratio range",
                ),
                (
                    "overview_beta",
                    "Mean stick share against β1 and β2, one line per μ",
                ),
                (
                    "overview_radius",
                    "Mean stick share against R1/R2, one line per μ",
                ),
            ][*k];
            let c = if s.shape == StudyShape::Curved {
                c.to_string()
            } else {
                format!(
                    "{} decks: {}",
                    s.shape.name(),
                    c.replace("β1 and β2", "the lengths L1 and L2")
                        .replace("R1/R2", "the length ratio L1/L2")
                )
            };
            (n.to_string(), c, (1200u32, 560u32))
        }
    };
    let png_rel = format!("figures/{name}.png");
    let png = out.join(&png_rel);
    save_png(&png, size, |root| render(study, job, root))?;
    let svg_rel = if svg {
        let rel = format!("figures/{name}.svg");
        let mut text = String::new();
        {
            let root = SVGBackend::with_string(&mut text, size).into_drawing_area();
            render(study, job, &root)?;
            root.present().map_err(e)?;
        }
        write_atomic(&out.join(&rel), text.as_bytes())
            .map_err(|err| format!("cannot write {}: {err}", out.join(&rel).display()))?;
        Some(rel)
    } else {
        None
    };
    Ok(Figure {
        png: png_rel,
        svg: svg_rel,
        caption,
    })
}

fn render<DB: DrawingBackend>(
    study: &Study,
    job: &Job,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    root.fill(&WHITE).map_err(e)?;
    match job {
        Job::Surface { geom, mu, eps } => surface(study, *geom, *mu, *eps, root),
        Job::Regions { geom, eps } => regions(study, *geom, *eps, root),
        Job::Overview(k) => overview(study, *k, root),
    }
}

fn geom_title(study: &Study, geom: [usize; 4]) -> String {
    let s = &study.scenario;
    format!("{}, W = {} m", s.geometry_label(geom), tok(s.width))
}

fn case_title(c: ContactCase) -> &'static str {
    match c {
        ContactCase::Deck1Inner => "deck1-inner: deck 1's inner corner strikes deck 2",
        ContactCase::Deck1Outer => "deck1-outer: deck 1's outer corner strikes deck 2",
        ContactCase::Deck2Inner => "deck2-inner: deck 2's inner corner strikes deck 1",
        ContactCase::Deck2Outer => "deck2-outer: deck 2's outer corner strikes deck 1",
    }
}

/// Legend strip: coloured boxes with labels, left to right.
fn legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    items: &[(RGBAColor, &str)],
    y: i32,
) -> DrawResult {
    let mut x = 20;
    for (c, label) in items {
        area.draw(&Rectangle::new([(x, y), (x + 22, y + 16)], c.filled()))
            .map_err(e)?;
        area.draw(&Text::new(label.to_string(), (x + 28, y), font(16)))
            .map_err(e)?;
        x += 40 + 9 * label.chars().count() as i32;
    }
    Ok(())
}

fn surface<DB: DrawingBackend>(
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

fn surface_panel<DB: DrawingBackend>(
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

fn regions<DB: DrawingBackend>(
    study: &Study,
    geom: [usize; 4],
    eps: usize,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let s = &study.scenario;
    let (top, body) = root.split_vertically(70);
    top.draw(&Text::new(
        format!(
            "{}, ε_N = {} — mode vs striking deck's θ_a (struck deck at 0)",
            geom_title(study, geom),
            tok(s.eps[eps])
        ),
        (20, 8),
        font(18),
    ))
    .map_err(e)?;
    legend(
        &top,
        &[
            (OUTWARD.to_rgba(), "outward slip (r < L)"),
            (STICK.to_rgba(), "stick (L ≤ r ≤ U)"),
            (INWARD.to_rgba(), "inward slip (r > U)"),
            (GREY.to_rgba(), "degenerate (θ_a = 0)"),
        ],
        40,
    )?;
    let arr = s.geometry(geom).map_err(|err| err.to_string())?;
    let panels = body.split_evenly((s.mu.len(), 2));
    let tol = s.degeneracy_tolerance_deg();
    for (m, &mu) in s.mu.iter().enumerate() {
        let law = s.law(m, eps).map_err(|err| err.to_string())?;
        for (col, deck1) in [(0usize, true), (1, false)] {
            let range = if deck1 { s.theta1 } else { s.theta2 };
            let samples = region_samples_in(
                &arr,
                &law,
                deck1,
                range.start,
                range.stop,
                s.output.region_map_samples,
                s.sigma_mode,
                tol,
            );
            let area = &panels[m * 2 + col];
            let title = format!(
                "{} strikes, μ = {}",
                if deck1 { "deck 1" } else { "deck 2" },
                tok(mu)
            );
            let (x0, x1) = if range.stop > range.start {
                (range.start, range.stop)
            } else {
                (range.start - 1.0, range.start + 1.0)
            };
            let mut chart = ChartBuilder::on(area)
                .caption(title, font(16))
                .margin(6)
                .x_label_area_size(38)
                .y_label_area_size(52)
                .build_cartesian_2d(x0..x1, s.ratio_min..s.ratio_max)
                .map_err(e)?;
            chart
                .configure_mesh()
                .x_label_formatter(&tick)
                .y_label_formatter(&tick)
                .x_label_formatter(&tick)
                .y_label_formatter(&tick)
                .disable_mesh()
                .x_desc(if deck1 {
                    "θ1 [deg]  (inner corner strikes < 0 < outer corner strikes)"
                } else {
                    "θ2 [deg]  (inner corner strikes < 0 < outer corner strikes)"
                })
                .y_desc("r = γ_T⁻/γ_N⁻")
                .label_style(font(13))
                .axis_desc_style(font(14))
                .draw()
                .map_err(e)?;
            let n = samples.len();
            let mut rects = Vec::with_capacity(3 * n);
            for (k, smp) in samples.iter().enumerate() {
                let left = if k == 0 {
                    smp.theta_a_deg
                } else {
                    0.5 * (smp.theta_a_deg + samples[k - 1].theta_a_deg)
                };
                let right = if k + 1 == n {
                    smp.theta_a_deg
                } else {
                    0.5 * (smp.theta_a_deg + samples[k + 1].theta_a_deg)
                };
                let c = &smp.cell;
                if c.lower.is_nan() {
                    rects.push(Rectangle::new(
                        [(left, s.ratio_min), (right, s.ratio_max)],
                        GREY.filled(),
                    ));
                    continue;
                }
                let l = c.lower.clamp(s.ratio_min, s.ratio_max);
                let u = c.upper.clamp(s.ratio_min, s.ratio_max);
                rects.push(Rectangle::new(
                    [(left, s.ratio_min), (right, l)],
                    OUTWARD.filled(),
                ));
                rects.push(Rectangle::new([(left, l), (right, u)], STICK.filled()));
                rects.push(Rectangle::new(
                    [(left, u), (right, s.ratio_max)],
                    INWARD.filled(),
                ));
            }
            chart.draw_series(rects).map_err(e)?;
            for upper in [false, true] {
                let mut seg: Vec<(Real, Real)> = Vec::new();
                let mut lines = Vec::new();
                for smp in &samples {
                    let v = if upper {
                        smp.cell.upper
                    } else {
                        smp.cell.lower
                    };
                    if v.is_finite() {
                        seg.push((smp.theta_a_deg, v.clamp(s.ratio_min, s.ratio_max)));
                    } else if !seg.is_empty() {
                        lines.push(std::mem::take(&mut seg));
                    }
                }
                if !seg.is_empty() {
                    lines.push(seg);
                }
                chart
                    .draw_series(
                        lines
                            .into_iter()
                            .map(|l| PathElement::new(l, BLACK.stroke_width(2))),
                    )
                    .map_err(e)?;
            }
        }
    }
    Ok(())
}

/// Cell-weighted mean of a per-row quantity over the first-contact rows accepted by `keep`.
fn mean_rows(
    study: &Study,
    keep: impl Fn(&pounding::study::run::RowParams) -> bool,
    f: impl Fn(&pounding::study::Cell) -> Real,
) -> Real {
    let (mut sum, mut n) = (0.0, 0usize);
    for r in &study.rows {
        if !r.cell.first_contact {
            continue;
        }
        let p = study.scenario.params(&r.key);
        if keep(&p) {
            sum += f(&r.cell);
            n += 1;
        }
    }
    if n == 0 { Real::NAN } else { sum / n as Real }
}

fn palette(k: usize) -> RGBColor {
    const P: [RGBColor; 8] = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(127, 127, 127),
    ];
    P[k % P.len()]
}

/// One line of a line chart.
struct Series {
    label: String,
    points: Vec<(Real, Real)>,
    color: usize,
    thin: bool,
}

/// A line chart with legend.
fn line_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Series],
    legend_pos: SeriesLabelPosition,
) -> DrawResult {
    let pts = series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|p| p.0.is_finite() && p.1.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::INFINITY,
        Real::NEG_INFINITY,
    );
    for p in pts {
        x0 = x0.min(p.0);
        x1 = x1.max(p.0);
        y0 = y0.min(p.1);
        y1 = y1.max(p.1);
    }
    if !(x0.is_finite() && y0.is_finite()) {
        area.draw(&Text::new(format!("{title}: no data"), (20, 20), font(16)))
            .map_err(e)?;
        return Ok(());
    }
    let (x0, x1) = sane_range(x0, x1, (0.0, 1.0));
    let (y0, y1) = sane_range(y0, y1, (0.0, 1.0));
    let dx = if x1 > x0 { 0.05 * (x1 - x0) } else { 1.0 };
    let dy = if y1 > y0 { 0.08 * (y1 - y0) } else { 1.0 };
    let mut chart = ChartBuilder::on(area)
        .caption(title, font(17))
        .margin(10)
        .x_label_area_size(42)
        .y_label_area_size(60)
        .build_cartesian_2d((x0 - dx)..(x1 + dx), (y0 - dy)..(y1 + dy))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .label_style(font(13))
        .axis_desc_style(font(15))
        .light_line_style(BLACK.mix(0.05))
        .draw()
        .map_err(e)?;
    for sr in series {
        let col = palette(sr.color);
        let pts: Vec<(Real, Real)> = sr
            .points
            .iter()
            .copied()
            .filter(|p| p.1.is_finite())
            .collect();
        let w = if sr.thin { 1 } else { 3 };
        chart
            .draw_series(LineSeries::new(pts.clone(), col.stroke_width(w)))
            .map_err(e)?
            .label(sr.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(w)));
        if sr.thin {
            chart
                .draw_series(
                    pts.into_iter()
                        .map(|p| TriangleMarker::new(p, 6, col.filled())),
                )
                .map_err(e)?;
        } else {
            chart
                .draw_series(pts.into_iter().map(|p| Circle::new(p, 4, col.filled())))
                .map_err(e)?;
        }
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .label_font(font(13))
        .position(legend_pos)
        .draw()
        .map_err(e)?;
    Ok(())
}

fn overview<DB: DrawingBackend>(
    study: &Study,
    k: usize,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let s = &study.scenario;
    let (rmin, rmax) = (s.ratio_min, s.ratio_max);
    let mut mus: Vec<Real> = s.mu.clone();
    mus.sort_by(Real::total_cmp);
    let panels = root.split_evenly((1, 2));
    let share = |c: &pounding::study::Cell| shares(c.lower, c.upper, rmin, rmax);
    let range_txt = format!("[{}, {}]", tok(rmin), tok(rmax));
    match k {
        0 => {
            let mut series = Vec::new();
            for (ci, case) in s.cases.iter().enumerate() {
                for upper in [false, true] {
                    let pts = mus
                        .iter()
                        .map(|&m| {
                            let v = mean_rows(
                                study,
                                |p| p.case == *case && p.mu == m,
                                |c| (if upper { c.upper } else { c.lower }).clamp(rmin, rmax),
                            );
                            (m, v)
                        })
                        .collect();
                    series.push(Series {
                        label: format!("{} {}", case.name(), if upper { "U (thin)" } else { "L" }),
                        points: pts,
                        color: ci,
                        thin: upper,
                    });
                }
            }
            line_chart(
                &panels[0],
                "Mean stick bounds L and U (first-contact cells)",
                "friction coefficient μ [-]",
                &format!("r = γ_T⁻/γ_N⁻ (clamped to {range_txt})"),
                &series,
                SeriesLabelPosition::LowerLeft,
            )?;
            let mut series = Vec::new();
            for (name, idx) in [("outward slip", 0usize), ("stick", 1), ("inward slip", 2)] {
                let pts = mus
                    .iter()
                    .map(|&m| {
                        let v = mean_rows(
                            study,
                            |p| p.mu == m,
                            |c| {
                                let t = share(c);
                                [t.0, t.1, t.2][idx]
                            },
                        );
                        (m, 100.0 * v)
                    })
                    .collect();
                series.push(Series {
                    label: name.to_string(),
                    points: pts,
                    color: idx,
                    thin: false,
                });
            }
            line_chart(
                &panels[1],
                &format!("Mean share of the ratio range {range_txt}"),
                "friction coefficient μ [-]",
                "share of ratio range [%]",
                &series,
                SeriesLabelPosition::UpperRight,
            )
        }
        1 => {
            // Striking deck a (owns the corner) and struck deck b.
            for (p, striking) in [(0usize, true), (1, false)] {
                let curved = s.shape == StudyShape::Curved;
                let mut bs: Vec<Real> = if curved {
                    s.beta1_deg.iter().chain(&s.beta2_deg).copied().collect()
                } else {
                    s.l1_m.iter().chain(&s.l2_m).copied().collect()
                };
                bs.sort_by(Real::total_cmp);
                bs.dedup();
                let series: Vec<Series> = mus
                    .iter()
                    .enumerate()
                    .map(|(mi, &m)| {
                        let pts = bs
                            .iter()
                            .map(|&b| {
                                let v = mean_rows(
                                    study,
                                    |q| {
                                        let deck1 = is_deck1(q.case);
                                        let beta = match (deck1 == striking, curved) {
                                            (true, true) => q.beta1_deg,
                                            (false, true) => q.beta2_deg,
                                            (true, false) => q.l1_m,
                                            (false, false) => q.l2_m,
                                        };
                                        q.mu == m && beta == b
                                    },
                                    |c| share(c).1,
                                );
                                (b, 100.0 * v)
                            })
                            .collect();
                        Series {
                            label: format!("μ = {}", tok(m)),
                            points: pts,
                            color: mi,
                            thin: false,
                        }
                    })
                    .collect();
                line_chart(
                    &panels[p],
                    &format!(
                        "Mean stick share against the {} deck's {}",
                        if striking { "striking" } else { "struck" },
                        if curved { "angle" } else { "length" }
                    ),
                    match (striking, curved) {
                        (true, true) => "β of the striking deck [deg]",
                        (false, true) => "β of the struck deck [deg]",
                        (true, false) => "L of the striking deck [m]",
                        (false, false) => "L of the struck deck [m]",
                    },
                    &format!("stick share of {range_txt} [%]"),
                    &series,
                    SeriesLabelPosition::UpperRight,
                )?;
            }
            Ok(())
        }
        _ => {
            let curved = s.shape == StudyShape::Curved;
            let ratio = |q: &pounding::study::run::RowParams| {
                let (a, b) = if curved {
                    (q.r1_m, q.r2_m)
                } else {
                    (q.l1_m, q.l2_m)
                };
                if is_deck1(q.case) { a / b } else { b / a }
            };
            let (list1, list2) = if curved {
                (&s.r1_m, &s.r2_m)
            } else {
                (&s.l1_m, &s.l2_m)
            };
            let (what, xlabel) = if curved {
                ("radius ratio", "R_striking / R_struck [-]")
            } else {
                ("length ratio", "L_striking / L_struck [-]")
            };
            let mut ratios: Vec<Real> = Vec::new();
            for &a in list1 {
                for &b in list2 {
                    for q in [a / b, b / a] {
                        if !ratios.contains(&q) {
                            ratios.push(q);
                        }
                    }
                }
            }
            ratios.sort_by(Real::total_cmp);
            let stick: Vec<Series> = mus
                .iter()
                .enumerate()
                .map(|(mi, &m)| Series {
                    label: format!("μ = {}", tok(m)),
                    points: ratios
                        .iter()
                        .map(|&x| {
                            (
                                x,
                                100.0
                                    * mean_rows(
                                        study,
                                        |q| q.mu == m && ratio(q) == x,
                                        |c| share(c).1,
                                    ),
                            )
                        })
                        .collect(),
                    color: mi,
                    thin: false,
                })
                .collect();
            line_chart(
                &panels[0],
                &format!("Mean stick share against the {what}"),
                xlabel,
                &format!("stick share of {range_txt} [%]"),
                &stick,
                SeriesLabelPosition::UpperRight,
            )?;
            let mut bounds = Vec::new();
            for (mi, &m) in mus.iter().enumerate() {
                for upper in [false, true] {
                    bounds.push(Series {
                        label: format!("μ = {} {}", tok(m), if upper { "U (thin)" } else { "L" }),
                        points: ratios
                            .iter()
                            .map(|&x| {
                                let v = mean_rows(
                                    study,
                                    |q| q.mu == m && ratio(q) == x,
                                    |c| (if upper { c.upper } else { c.lower }).clamp(rmin, rmax),
                                );
                                (x, v)
                            })
                            .collect(),
                        color: mi,
                        thin: upper,
                    });
                }
            }
            line_chart(
                &panels[1],
                &format!("Mean stick bounds against the {what}"),
                xlabel,
                &format!("r = γ_T⁻/γ_N⁻ (clamped to {range_txt})"),
                &bounds,
                SeriesLabelPosition::LowerRight,
            )
        }
    }
}

fn is_deck1(c: ContactCase) -> bool {
    matches!(c, ContactCase::Deck1Inner | ContactCase::Deck1Outer)
}
