//! `pounding simulate`: seismic time-history simulation of two decks (curved, straight or skewed,
//! optionally with abutments) with pounding.
//!
//! Reads an optional scenario ([`pounding::sim::scenario::Scenario`]: schema, defaults,
//! validation and record loading live in the library), runs [`pounding::sim::simulate`] and
//! writes `history.csv`, `impacts.csv`, `summary.json` ([`pounding::sim::output`]), `timing.json`
//! and PNG plots into the output directory. Every input is validated before anything is written.
//! With `--records` or `--set` it runs a batch instead ([`sim_batch`]).

use anyhow::{Context, Result};
use pounding::ground_motion::AccelUnits;
use pounding::math::Real;
use pounding::output::{float_token, write_atomic};
use pounding::sim::output::SIM_OUTPUTS;
use pounding::sim::scenario::{DEFAULT_SCENARIO_TOML, ParamKey, Scenario, Section};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[path = "sim_batch.rs"]
pub(crate) mod sim_batch;

#[path = "sim_run.rs"]
mod sim_run;

#[path = "sim_records.rs"]
pub(crate) mod sim_records;

#[path = "sim_accuracy.rs"]
mod sim_accuracy;

/// Arguments of `pounding simulate`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario file (TOML); without it the built-in default runs (see --print-default).
    pub scenario: Option<PathBuf>,
    /// Use this record (PEER .AT2, CSV `t, a`, columns `t a`, or one column with --record-dt)
    /// as the only ground-motion component, along y (normal to the joint); replaces the
    /// scenario's records.
    #[arg(long, value_name = "FILE")]
    pub record: Option<PathBuf>,
    /// Units of the text records (CSV, columns, one column) of --record / --records (and of a
    /// --set manifest's entries without `units`): g or m/s2. Default: the scenario's csv_units
    /// (g). A PEER .AT2 header names its own units.
    #[arg(long, value_name = "g|m/s2", value_parser = parse_units)]
    pub csv_units: Option<AccelUnits>,
    /// Sample interval (s) of one-column records (accelerations only, as OpenSees' timeSeries
    /// Path -dt) given by --record / --records; refused for files with their own times.
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    pub record_dt: Option<f64>,
    /// Multiply both ground-motion scale factors by S (negative: a sign flip).
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub scale: Option<f64>,
    /// Replace the scenario's time step `[time] dt` (seconds).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    pub dt: Option<f64>,
    /// Replace the scenario's `[time] duration` (seconds; default: the record's length).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    pub duration: Option<f64>,
    /// Replace the contact law (`[contact] law`; at every joint and abutment of a bridge):
    /// `rigid` or a compliance law (`pounding compare --help` lists them).
    #[arg(long, value_name = "LAW")]
    pub law: Option<String>,
    /// Project every rigid-law gap back to >= 0 at the end of each step (combined projection;
    /// `[time] projection = true`): no overlap beyond 1e-11 m, its energy in summary.json.
    #[arg(long)]
    pub projection: bool,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "out/simulate")]
    pub out: PathBuf,
    /// Print the built-in default scenario as commented TOML and exit.
    #[arg(long)]
    pub print_default: bool,
    /// Batch mode: run every record (files, or directories whose `.AT2`/`.csv`/`.txt`/`.dat`
    /// files are taken in name order; skipped files are listed) at every `--scales` factor, each
    /// as the only component along y (as `--record`); writes `batch.csv` and `batch.png`. Put the
    /// scenario file before this flag. Horizontal pairs: a record-set manifest with --set.
    #[arg(
        long,
        num_args = 1..,
        value_name = "DIR_OR_FILE",
        conflicts_with_all = ["record", "scale"],
        group = "batch"
    )]
    pub records: Vec<PathBuf>,
    /// Batch mode over a record-set manifest (`.toml` with `[[record]]` tables or `[synth]`, or
    /// `.csv`, as `pounding fragility --set`): every entry at every `--scales` factor; a pair's
    /// `x` record along y with scale_y, its `y` record along x with scale_x (incidence_deg
    /// applies), a single record as with --records. batch.csv names each entry's id, records
    /// and metadata.
    #[arg(
        long,
        value_name = "MANIFEST",
        conflicts_with_all = ["record", "scale", "records"],
        group = "batch"
    )]
    pub set: Option<PathBuf>,
    /// Batch mode: scale factors, comma separated (each multiplies the scenario's scale_y, and
    /// a pair's scale_x, as `--scale`). Default: 1.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "S1,S2,...",
        allow_hyphen_values = true,
        requires = "batch"
    )]
    pub scales: Vec<f64>,
    /// Batch mode: worker threads (default: all cores). batch.csv is identical for any value.
    #[arg(long, value_name = "N", requires = "batch")]
    pub threads: Option<usize>,
    /// Batch mode: run only the runs whose global index i (0-based, record-major) has
    /// i mod N = K − 1.
    #[arg(long, value_name = "K/N", requires = "batch")]
    pub shard: Option<String>,
    /// Estimate the time-discretisation error of every summary quantity from two reruns at
    /// dt/2 and dt/4 (accuracy.csv, accuracy.json; about 7 times the run's cost).
    #[arg(long, conflicts_with = "batch")]
    pub error_estimate: bool,
    /// Halve dt until the estimated relative error of every governing quantity (seat ratio,
    /// joint closing and opening, bearing deformation, rotation, contact force, pier drift) is at
    /// most TOL: `1%` or `0.01`. Implies --error-estimate.
    #[arg(long, value_name = "TOL", value_parser = parse_tol, conflicts_with = "batch")]
    pub tol: Option<f64>,
    /// With --tol: the most halvings of dt (default 3; the finest run is at dt / 2^(N+2)).
    #[arg(long, value_name = "N", requires = "tol", value_parser = clap::value_parser!(u32).range(0..=8))]
    pub max_refinements: Option<u32>,
}

/// The scenario file `path`, or the built-in default.
pub(crate) fn load_scenario(path: Option<&Path>) -> Result<Scenario> {
    Ok(match path {
        Some(p) => Scenario::load(p)?,
        None => Scenario::default(),
    })
}

/// `--tol`: a relative tolerance, `1%` or `0.01` ([`pounding::sim::accuracy::parse_tol`]).
fn parse_tol(s: &str) -> Result<f64, String> {
    pounding::sim::accuracy::parse_tol(s)
}

/// `--csv-units`: `g` or `m/s2`.
fn parse_units(s: &str) -> Result<AccelUnits, String> {
    AccelUnits::from_name(s).ok_or_else(|| format!("invalid units {s:?}: use g or m/s2"))
}

/// `--error-estimate` / `--tol` / `--max-refinements` as the library's settings (`None`: a plain
/// run).
pub(crate) fn accuracy_settings(args: &Args) -> Option<pounding::sim::accuracy::AccuracySettings> {
    let mut a = pounding::sim::accuracy::AccuracySettings::default();
    if let Some(n) = args.max_refinements {
        a.max_refinements = n as usize;
    }
    a.tol = args.tol;
    (args.error_estimate || args.tol.is_some()).then_some(a)
}

/// The scenario with the command line's replacements (`--record`, `--csv-units`,
/// `--record-dt`, `--scale`, `--dt`, `--duration`, `--law`; `--records`: a batch).
pub(crate) fn with_flags(sc: Scenario, args: &Args) -> Scenario {
    let mut sc = sc.with_record_dt(args.record_dt);
    if let Some(p) = &args.record {
        sc = sc.with_record(p, args.csv_units);
    }
    if let Some(s) = args.scale {
        sc = sc.with_scale(s);
    }
    if let Some(dt) = args.dt {
        sc = sc.with_dt(dt);
    }
    if let Some(d) = args.duration {
        sc = sc.with_duration(d);
    }
    if args.projection {
        sc = sc.with_projection();
    }
    if let Some(l) = &args.law {
        // the file's [contact] keys of its own law stay accepted (not refused as unused)
        let file_law = sc.law().to_string();
        if file_law != *l && pounding::contact_law::registry::law_names().contains(&l.as_str()) {
            eprintln!(
                "note: --law {l} replaces the scenario's contact law {file_law:?} (at every site of \
                 a bridge); the contact keys that {l} does not read are not used"
            );
        }
        sc = sc
            .with_law_replacing(l)
            .with_flag(ParamKey::new(Section::Contact, "law"), "--law");
    }
    if is_batch(args) {
        sc = sc.for_batch();
    }
    sc
}

/// Whether the command runs a batch (`--records` or `--set`).
pub(crate) fn is_batch(args: &Args) -> bool {
    !args.records.is_empty() || args.set.is_some()
}

/// The command-line replacements as given, for the report.
pub(crate) fn flag_list(args: &Args) -> Vec<String> {
    let mut v = Vec::new();
    if let Some(p) = &args.record {
        v.push(format!("--record {}", p.display()));
    }
    let mut num = |flag: &str, x: Option<f64>| {
        if let Some(x) = x {
            v.push(format!("{flag} {}", float_token(x)));
        }
    };
    num("--scale", args.scale);
    num("--dt", args.dt);
    num("--duration", args.duration);
    if let Some(l) = &args.law {
        v.push(format!("--law {l}"));
    }
    if args.projection {
        v.push("--projection".into());
    }
    v
}

/// The report's sections beside `summary.json`: the trajectories JSON (plan animation), the
/// tables, the code-check section, the verdict.
pub(crate) type Sections<'a> = (
    Option<&'a str>,
    &'a [pounding::sim::table::Table],
    Option<crate::sim_report_check::CodeCheckSection>,
    &'a [pounding::sim::output::VerdictLine],
);

/// Writes `report.html` ([`crate::sim_report`]) from the `summary.json` text of the run; the
/// figures are those of `candidates` that the run drew.
pub(crate) fn write_report(
    args: &Args,
    what: String,
    scenario: (&str, &str),
    summary_json: &str,
    candidates: &[&'static str],
    files: &[&str],
    sections: Sections<'_>,
) -> Result<()> {
    let (animation, tables, code_check, verdict) = sections;
    let input = crate::sim_report::ReportInput {
        what,
        scenario,
        flags: flag_list(args),
        figures: candidates
            .iter()
            .copied()
            .filter(|f| args.out.join(f).is_file())
            .collect(),
        files,
        animation,
        tables,
        code_check,
        verdict,
    };
    let html = crate::sim_report::report_html(&input, summary_json);
    let p = args.out.join("report.html");
    write_atomic(&p, html.as_bytes()).with_context(|| format!("cannot write {}", p.display()))
}

/// Runs `pounding simulate`.
pub fn run(args: Args) -> Result<ExitCode> {
    if args.print_default {
        print!("{DEFAULT_SCENARIO_TOML}");
        return Ok(ExitCode::SUCCESS);
    }
    let t_start = Instant::now();
    sim_records::check_flags(&args)?;
    let sc = load_scenario(args.scenario.as_deref())?;
    let (origin, text) = (sc.origin().to_string(), sc.text().to_string());
    let bridge = sc.is_bridge();
    pounding::assessment::check_tables(&sc, None)?;
    let sc = with_flags(sc, &args);
    // [code_check] against the bridge (array lengths, hinge joints) before any run
    let check = |setup: &pounding::sim::scenario::Setup| {
        pounding::assessment::check_tables(
            &sc,
            Some(pounding::sim::Problem::model(setup).segments.len()),
        )
    };
    if is_batch(&args) {
        let reading = sc.override_reading(args.csv_units)?;
        let setup = sc.build_setup()?;
        check(&setup)?;
        return sim_batch::run(&args, &setup, &reading, t_start);
    }
    if !bridge {
        // the two-deck form checks the units flag against its records before it is built
        sc.override_reading(args.csv_units)?;
    }
    let setup = sc.build_setup()?;
    check(&setup)?;
    sim_run::run(&args, setup, (&origin, &text), t_start)
}

/// Locks the output directory `out` (creating it) and removes the earlier run's [`SIM_OUTPUTS`].
pub(crate) fn lock_and_clear(out: &Path) -> Result<pounding::output::OutputLock> {
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, SIM_OUTPUTS)?;
    Ok(lock)
}

/// Prints the run's warnings that stderr has not shown yet: the time step's (the record lines
/// and their PGA warnings came before the run) and the per-impact summary. `summary.json` lists them all (and
/// `report.html` from it).
pub(crate) fn print_run_warnings(
    ground: &pounding::ground_motion::GroundMotion,
    dt: Real,
    advice: Option<&pounding::contact_law::timestep::TimeStepAdvice>,
    impacts: &[pounding::sim::output::RunWarning],
) {
    let input = pounding::sim::output::input_warnings(ground, dt, advice);
    for w in input.iter().filter(|w| w.kind != "record_pga_implausible") {
        eprintln!("warning: {}", w.message);
    }
    if let Some(w) = pounding::sim::output::warnings_message(impacts) {
        eprintln!("{w}");
    }
}

/// Wall time after which a long run is announced, and the projected remainder that makes it
/// worth a line.
const ESTIMATE_AFTER_S: f64 = 2.0;
const ESTIMATE_WORTH_S: f64 = 30.0;

/// A progress observer that says once on stderr how long a long run will take: after
/// [`ESTIMATE_AFTER_S`] of wall time, if the steps still to go would take more than
/// [`ESTIMATE_WORTH_S`] at the rate so far (a bridge with many simultaneous contacts can take
/// hours; a user should know before waiting). The rate so far is what it is: contacts that
/// begin later may slow the run further, so the line says "at the rate so far".
pub(crate) fn time_estimate() -> pounding::sim::Progress {
    let start = Instant::now();
    let said = std::sync::atomic::AtomicBool::new(false);
    pounding::sim::Progress::new(move |done, total| {
        let elapsed = start.elapsed().as_secs_f64();
        if done == 0
            || elapsed < ESTIMATE_AFTER_S
            || said.load(std::sync::atomic::Ordering::Relaxed)
        {
            return;
        }
        let rest = elapsed * (total - done.min(total)) as f64 / done as f64;
        if rest > ESTIMATE_WORTH_S {
            said.store(true, std::sync::atomic::Ordering::Relaxed);
            eprintln!(
                "note: {done} of {total} steps in {elapsed:.0} s; at the rate so far the run needs \
                 about {} more ({:.2} ms per step)",
                human_duration(rest),
                elapsed * 1e3 / done as f64
            );
        }
    })
}

/// `s` seconds as `42 s`, `12 min` or `3.4 h`.
fn human_duration(s: f64) -> String {
    if s < 120.0 {
        format!("{s:.0} s")
    } else if s < 7200.0 {
        format!("{:.0} min", s / 60.0)
    } else {
        format!("{:.1} h", s / 3600.0)
    }
}

/// A one-line note on stderr when the given `[time] duration` is not a whole number of steps:
/// the run takes `⌈duration/dt⌉` steps, so it ends after the duration.
pub(crate) fn note_rounded_duration(settings: &pounding::sim::SimSettings) {
    let Some(d) = settings.duration else { return };
    let Ok(n) = settings.step_count(d) else {
        return;
    };
    let end = n as Real * settings.dt;
    if (end - d).abs() > 1e-9 * d {
        // 13 significant digits: 4 × 0.3 reads as 1.2
        let end: Real = format!("{end:.12e}").parse().unwrap_or(end);
        eprintln!(
            "note: duration = {} s is not a multiple of dt = {} s: the run takes {n} steps, to \
             t = {} s",
            float_token(d),
            float_token(settings.dt),
            float_token(end)
        );
    }
}
