//! `pounding compare`: one scenario, several joint contact laws, side by side.
//!
//! Builds the scenario exactly as `pounding simulate` does (same TOML, same validation), replaces
//! its `[contact] law` by each law of `--laws` in turn (the other `[contact]` keys apply to every
//! law that reads them; one section serves all laws, so a key is refused only when no law of
//! `--laws` reads it: `Scenario::with_compared_laws`), runs [`pounding::sim::simulate`] and
//! writes `compare.csv`, a readable table on stdout, `timing.json` (wall time per law) and two
//! overlay plots: `joint_gap.png` (the smaller joint gap of the two ends) and `contact_force.png`
//! (total joint force of the compliance laws), each with a full-duration panel and a zoom around
//! the largest contact event.

use crate::cmd_simulate;
use crate::plot_style::{
    BLUE, DARK, DrawResult, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_white_png,
    series_legend,
};
use anyhow::{Context, Result, anyhow, bail};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::contact_law::registry::law_names;
use pounding::math::Real;
use pounding::output::{float_token, write_atomic};
use pounding::sim::output::{COMPARE_OUTPUTS, compare_csv, compare_table};
use pounding::sim::scenario::LAW_NAMES;
use pounding::sim::{SimSolution, simulate};
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `pounding compare`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario file (TOML, as for `pounding simulate`); without it the built-in default runs.
    pub scenario: Option<PathBuf>,
    /// Contact laws to run, comma separated: rigid, kelvin, hertz, hertz-damp, bilinear, jankowski, linear.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "LAW,...",
        default_value = "rigid,kelvin,hertz,hertz-damp,bilinear,jankowski"
    )]
    pub laws: Vec<String>,
    /// Override the scenario's time step `[time] dt` for every law \[s\].
    #[arg(long, value_name = "DT")]
    pub dt: Option<f64>,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "out/compare")]
    pub out: PathBuf,
}

/// One law's run.
struct Run {
    law: String,
    sol: SimSolution,
    secs: f64,
    gap0: Real,
}

/// Runs `pounding compare`.
pub fn run(args: Args) -> Result<ExitCode> {
    let t_start = Instant::now();
    let mut laws: Vec<String> = Vec::new();
    for l in &args.laws {
        let l = l.trim().to_string();
        if !law_names().contains(&l.as_str()) {
            let names = law_names().join(", ");
            bail!("unknown contact law {l:?} in --laws: use one of {names}");
        }
        if laws.contains(&l) {
            bail!("contact law {l:?} is given twice in --laws");
        }
        laws.push(l);
    }
    if laws.is_empty() {
        bail!("--laws is empty");
    }
    if let Some(dt) = args.dt
        && !(dt.is_finite() && dt > 0.0)
    {
        bail!("invalid --dt {}: must be finite and > 0", float_token(dt));
    }
    // Build (and validate) every law's setup before running anything.
    let base = cmd_simulate::load_scenario(args.scenario.as_deref())?.with_compared_laws(&laws);
    base.check_contact_keys()?;
    let mut setups = Vec::new();
    let mut memory = 0u64;
    for l in &laws {
        let mut s = base
            .clone()
            .with_law(l)
            .build()
            .with_context(|| format!("contact law {l:?}"))?;
        if let Some(dt) = args.dt {
            s.settings.dt = dt;
        }
        // history resolution for the plots: at least one sample per 0.5 ms
        s.settings.history_stride = ((5e-4 / s.settings.dt).floor() as usize).max(1);
        s.settings.validate().map_err(|e| anyhow!("{e} (--dt)"))?;
        // Same rules as `simulate`: a step no longer than the run, and not too many steps.
        let d = s
            .settings
            .duration
            .unwrap_or_else(|| s.problem.ground.end_time());
        if s.settings.dt > d {
            bail!(
                "invalid dt = {}: must not exceed the duration {} s{}",
                float_token(s.settings.dt),
                float_token(d),
                if args.dt.is_some() { " (--dt)" } else { "" }
            );
        }
        let n = s
            .settings
            .step_count(d)
            .map_err(|e| anyhow!("{e} (--dt)"))?;
        memory += pounding::sim::options::run_memory_bytes(n, s.settings.history_stride);
        setups.push(s);
    }
    // every law's history is kept for the plots: the runs together must fit
    let limit = pounding::sim::options::MAX_RUN_MEMORY_BYTES;
    if memory > limit {
        bail!(
            "run too large: the {} runs need an estimated {:.1} GiB of memory (history every \
             0.5 ms), more than the limit {:.0} GiB: shorten [time] duration, compare fewer laws \
             or use a larger --dt",
            setups.len(),
            memory as Real / (1u64 << 30) as Real,
            limit as Real / (1u64 << 30) as Real
        );
    }
    pounding::output::check_output_dir_free(&args.out)?;
    let mut runs = Vec::new();
    for (l, s) in laws.iter().zip(&setups) {
        let t = Instant::now();
        let sol = simulate(&s.problem, &s.settings).map_err(|e| anyhow!("law {l:?}: {e}"))?;
        let secs = t.elapsed().as_secs_f64();
        if let Some(a) = &sol.time_step_advice
            && !a.adequate
        {
            eprintln!("law {l}:");
        }
        cmd_simulate::warn_time_step(&sol);
        eprintln!(
            "{l}: {} steps in {:.1} ms ({:?})",
            sol.steps,
            secs * 1e3,
            sol.status
        );
        runs.push(Run {
            law: l.clone(),
            sol,
            secs,
            gap0: s.problem.model.gap,
        });
    }

    let out = &args.out;
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, COMPARE_OUTPUTS)?;
    let rows: Vec<(&str, &SimSolution)> = runs.iter().map(|r| (r.law.as_str(), &r.sol)).collect();
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("compare.csv", compare_csv(&rows).as_bytes())?;
    print!("{}", compare_table(&rows));
    plots(out, &runs).map_err(|e| anyhow!("plotting: {e}"))?;
    let mut timing = serde_json::Map::new();
    for r in &runs {
        timing.insert(
            r.law.clone(),
            json!({"simulate_s": r.secs, "steps": r.sol.steps}),
        );
    }
    let timing = json!({"laws": timing, "wall_time_s": t_start.elapsed().as_secs_f64()});
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;
    eprintln!("outputs in {}", out.display());
    // Like `simulate`: a law whose run did not complete is written, then reported with exit 1.
    let bad: Vec<String> = runs
        .iter()
        .filter(|r| r.sol.status != pounding::sim::SimStatus::Completed)
        .map(|r| format!("{} ({:?})", r.law, r.sol.status))
        .collect();
    if !bad.is_empty() {
        eprintln!(
            "error: {} of {} laws ended with a status other than Completed: {}; their results are not \
             trustworthy (see compare.csv, column status)",
            bad.len(),
            runs.len(),
            bad.join(", ")
        );
        return Ok(ExitCode::FAILURE);
    }
    Ok(ExitCode::SUCCESS)
}

// ---------------------------------------------------------------- plots

type R = DrawResult;

const COLORS: [RGBColor; 6] = [DARK, BLUE, GREEN, RED, ORANGE, PURPLE];

fn color_of(law: &str) -> RGBColor {
    let i = LAW_NAMES.iter().position(|l| *l == law).unwrap_or(0);
    COLORS[i % COLORS.len()]
}

/// `(t, smaller end gap)` and `(t, total joint force)` series of one run.
type Pts = Vec<(Real, Real)>;

fn series(r: &Run) -> (Pts, Pts) {
    let h = &r.sol.history;
    let gap =
        h.t.iter()
            .zip(&h.end_gaps)
            .map(|(t, g)| {
                let m = g
                    .iter()
                    .copied()
                    .filter(|x| x.is_finite())
                    .fold(Real::INFINITY, Real::min);
                (*t, if m.is_finite() { m } else { Real::NAN })
            })
            .collect();
    let force =
        h.t.iter()
            .zip(&h.contact_force)
            .map(|(t, f)| (*t, (f[0] + f[1]) / 1e6))
            .collect();
    (gap, force)
}

/// The zoom window: ±0.25 s around the instant of the largest compliance force, or around the
/// first rigid impact, or the first second.
fn zoom_window(runs: &[Run]) -> (Real, Real) {
    let mut best: Option<(Real, Real)> = None;
    for r in runs {
        let (_, f) = series(r);
        for (t, v) in f {
            if best.is_none_or(|(_, b)| v > b) {
                best = Some((t, v));
            }
        }
    }
    let tc = match best {
        Some((t, v)) if v > 0.0 => t,
        _ => runs
            .iter()
            .filter_map(|r| r.sol.impacts.first().map(|i| i.time))
            .fold(Real::INFINITY, Real::min),
    };
    if tc.is_finite() {
        ((tc - 0.25).max(0.0), tc + 0.25)
    } else {
        (0.0, 1.0)
    }
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    ylabel: &str,
    (t0, t1): (Real, Real),
    curves: &[(&str, Vec<(Real, Real)>)],
    hline: Option<(Real, &str)>,
) -> R {
    let mut lo = Real::INFINITY;
    let mut hi = Real::NEG_INFINITY;
    for (_, pts) in curves {
        for &(t, y) in pts {
            if t >= t0 && t <= t1 && y.is_finite() {
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
    }
    if let Some((y, _)) = hline.filter(|h| h.0.is_finite()) {
        lo = lo.min(y);
        hi = hi.max(y);
    }
    let (lo, hi) = crate::figures::sane_range(lo, hi, (0.0, 1.0));
    let pad = ((hi - lo) * 0.08).max(1e-9);
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FAMILY, 20))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(80)
        .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("time t [s]")
        .y_desc(ylabel)
        .label_style((FAMILY, 14))
        .axis_desc_style((FAMILY, 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(e)?;
    if let Some((y, label)) = hline {
        chart
            .draw_series(DashedLineSeries::new(
                vec![(t0, y), (t1, y)],
                6,
                4,
                RGBColor(120, 120, 120).stroke_width(1),
            ))
            .map_err(e)?
            .label(label)
            .legend(|(x, y)| {
                PathElement::new(
                    vec![(x, y), (x + 20, y)],
                    RGBColor(120, 120, 120).stroke_width(1),
                )
            });
    }
    for (law, pts) in curves {
        let c = color_of(law);
        chart
            .draw_series(LineSeries::new(
                pts.iter()
                    .copied()
                    .filter(|&(t, y)| t >= t0 && t <= t1 && y.is_finite()),
                c.stroke_width(if *law == "rigid" { 2 } else { 1 }),
            ))
            .map_err(e)?
            .label(*law)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    series_legend(&mut chart, SeriesLabelPosition::UpperRight, BLACK, 14)
}

fn save(out: &Path, name: &str, draw: impl Fn(&DrawingArea<BitMapBackend, Shift>) -> R) -> R {
    save_white_png(out, name, (1200, 900), draw)
}

fn plots(out: &Path, runs: &[Run]) -> R {
    register();
    let t_end = runs
        .iter()
        .filter_map(|r| r.sol.history.t.last().copied())
        .fold(0.0, Real::max)
        .max(1e-9);
    let zoom = zoom_window(runs);
    let all: Vec<(&str, (Pts, Pts))> = runs.iter().map(|r| (r.law.as_str(), series(r))).collect();
    let gaps: Vec<(&str, Vec<(Real, Real)>)> =
        all.iter().map(|(l, (g, _))| (*l, g.clone())).collect();
    let forces: Vec<(&str, Vec<(Real, Real)>)> = all
        .iter()
        .filter(|(_, (_, f))| !f.is_empty())
        .map(|(l, (_, f))| (*l, f.clone()))
        .collect();
    let gap0 = runs.first().map_or(0.0, |r| r.gap0);
    save(out, "joint_gap.png", |root| {
        let (a, b) = root.split_vertically(450);
        panel(
            &a,
            "Joint gap (smaller of the two ends) by contact law",
            "gap [m]",
            (0.0, t_end),
            &gaps,
            Some((0.0, "contact")),
        )?;
        panel(
            &b,
            &format!(
                "zoom {:.2}–{:.2} s (reference gap {} m)",
                zoom.0, zoom.1, gap0
            ),
            "gap [m]",
            zoom,
            &gaps,
            Some((0.0, "contact")),
        )
    })?;
    save(out, "contact_force.png", |root| {
        let (a, b) = root.split_vertically(450);
        panel(
            &a,
            "Total joint contact force (compliance laws; rigid contact has impulses only)",
            "force [MN]",
            (0.0, t_end),
            &forces,
            None,
        )?;
        panel(
            &b,
            &format!("zoom {:.2}–{:.2} s", zoom.0, zoom.1),
            "force [MN]",
            zoom,
            &forces,
            None,
        )
    })?;
    Ok(())
}
