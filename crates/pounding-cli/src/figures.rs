//! Figures of `pounding study` (plotters; PNG, and SVG on request). Fonts are embedded
//! (`assets/fonts/DejaVuSans.ttf`), never taken from the system.
//!
//! * `surface_*.png` — per (β1, β2, R1, R2, μ, ε): the lower and upper stick surfaces `L`, `U` over
//!   `θ1 × θ2` for the four cases (paper Figures 3–6); first-contact cells saturated, others pale.
//! * `regions_*.png` — per (β1, β2, R1, R2, ε): region maps in the style of the paper's Figures 7–8
//!   (x: striking deck's rotation `θ_a` with the struck deck at 0; y: `r = γ_T⁻/γ_N⁻`), one row per μ.
//! * `overview_*.png` — how the stick band changes with μ, β and R1/R2 (means over first-contact cells).

use crate::plot_style::{DrawResult, e, register, save_png};
use crate::plots::study_overview::overview;
use crate::plots::study_regions::regions;
use crate::plots::study_style::tok;
use crate::plots::study_surface::surface;
use anyhow::{Result, anyhow};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::output::write_atomic;
use pounding::study::{Study, StudyShape};
use rayon::prelude::*;
use std::path::Path;

/// One figure file.
#[derive(Debug, Clone)]
pub struct Figure {
    /// Path of the PNG relative to the output directory (`figures/...png`).
    pub png: String,
    /// Path of the SVG relative to the output directory, when written.
    pub svg: Option<String>,
    /// Caption (plain text).
    pub caption: String,
    /// Whether this is a region map (shown beside the surfaces of its ε on a geometry page).
    pub map: bool,
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
    /// The geometry (list indices) of a geometry group; `None` for the overview.
    pub geom: Option<[usize; 4]>,
}

impl FigureGroup {
    /// The report page of a geometry group, relative to the output directory
    /// (`report/b1-60_b2-90_r1-100_r2-200.html`); `None` for the overview (shown on the index).
    pub fn page(&self, study: &Study) -> Option<String> {
        self.geom
            .map(|g| format!("report/{}.html", study.scenario.geometry_id(g)))
    }
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
        geom: None,
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
                        geom: Some([b1, b2, r1, r2]),
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
            (n.to_string(), c, (1400u32, 560u32))
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
        map: matches!(job, Job::Regions { .. }),
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

/// Largest magnitude of a plotted data bound: keeps `hi − lo`, the padding and the axis ends
/// finite (an infinite axis range makes plotters' tick search loop forever).
pub(crate) const AXIS_LIMIT: pounding::math::Real = 1e300;

/// A sane data range for an axis: `(lo, hi)` clamped to `±`[`AXIS_LIMIT`] when both are finite
/// (the callers skip non-finite values when they gather them), otherwise `default` (no finite
/// value at all). The result is finite, so any padding of it stays finite.
pub(crate) fn sane_range(
    lo: pounding::math::Real,
    hi: pounding::math::Real,
    default: (pounding::math::Real, pounding::math::Real),
) -> (pounding::math::Real, pounding::math::Real) {
    if lo.is_finite() && hi.is_finite() {
        (
            lo.clamp(-AXIS_LIMIT, AXIS_LIMIT),
            hi.clamp(-AXIS_LIMIT, AXIS_LIMIT),
        )
    } else {
        default
    }
}
