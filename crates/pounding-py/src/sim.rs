//! `pounding.simulate` and `pounding.batch`: seismic time histories of two decks or of a bridge
//! of N segments (as `pounding simulate`), and batches of (record, scale) runs (as
//! `pounding simulate --records ... --scales ...`, or `--set MANIFEST` for pairs).

use crate::value_error;
use numpy::PyArray2;
use pounding::ground_motion::set::RecordSet;
use pounding::ground_motion::{AccelUnits, ReadOptions, Record};
use pounding::output::float_token;
use pounding::shard::Shard;
use pounding::sim::Problem;
use pounding::sim::batch::{BatchRecord, BatchRow, run_batch, run_problem};
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::output as so;
use pounding::sim::scenario::{DEFAULT_SCENARIO_TOML, ParamKey, Scenario, Section, Setup};
use pounding::sim::{SimSettings, SimStatus};
use pyo3::prelude::*;
use std::path::{Path, PathBuf};

/// A ground motion given as samples: `(name, accelerations, dt)` in the units of the call.
type ArrayRecord = (String, Vec<f64>, f64);

/// The scenario as `pounding simulate` reads it: the file `path` (record paths relative to its
/// directory), the TOML `text` (records relative to the current directory) or the default.
pub(crate) fn load(path: Option<&str>, text: Option<String>, origin: &str) -> PyResult<Scenario> {
    let sc = load_any(path, text, origin)?;
    check_tables(&sc, None)?;
    Ok(sc)
}

/// The scenario's assessment tables checked (`[fragility]`, `[[limit_state]]`, `[code_check]`,
/// against the bridge of `segments` segments when known), as every CLI command checks them.
pub(crate) fn check_tables(sc: &Scenario, segments: Option<usize>) -> PyResult<()> {
    pounding::assessment::check_tables(sc, segments).map_err(value_error)
}

fn load_any(path: Option<&str>, text: Option<String>, origin: &str) -> PyResult<Scenario> {
    match (path, text) {
        (Some(p), _) => Scenario::load(Path::new(p)).map_err(value_error),
        (None, Some(t)) => Scenario::from_toml(&t, origin).map_err(value_error),
        (None, None) => Ok(Scenario::default()),
    }
}

/// `g` or `m/s2`.
fn units(name: Option<&str>) -> PyResult<Option<AccelUnits>> {
    name.map(|s| {
        AccelUnits::from_name(s)
            .ok_or_else(|| value_error(format!("invalid csv_units {s:?}: use g or m/s2")))
    })
    .transpose()
}

/// A record from samples in `units` (converted to m/s² as the text readers convert).
fn array_record(r: ArrayRecord, units: AccelUnits) -> PyResult<Record> {
    let (name, values, dt) = r;
    let f = units.factor();
    Record::uniform(name, dt, values.into_iter().map(|v| v * f).collect())
        .map(|r| r.with_units_label(units.name()))
        .map_err(value_error)
}

/// The command-line replacements of `pounding simulate` (`with_flags` of the CLI).
struct Flags {
    record: Option<PathBuf>,
    csv_units: Option<AccelUnits>,
    record_dt: Option<f64>,
    scale: Option<f64>,
    dt: Option<f64>,
    duration: Option<f64>,
    law: Option<String>,
    batch: bool,
    /// `--projection`.
    projection: bool,
}

impl Flags {
    fn apply(&self, sc: Scenario) -> Scenario {
        let mut sc = sc.with_record_dt(self.record_dt);
        if let Some(p) = &self.record {
            sc = sc.with_record(p, self.csv_units);
        }
        if let Some(s) = self.scale {
            sc = sc.with_scale(s);
        }
        if let Some(dt) = self.dt {
            sc = sc.with_dt(dt);
        }
        if let Some(d) = self.duration {
            sc = sc.with_duration(d);
        }
        if let Some(l) = &self.law {
            sc = sc
                .with_law_replacing(l)
                .with_flag(ParamKey::new(Section::Contact, "law"), "--law");
        }
        if self.projection {
            sc = sc.with_projection();
        }
        if self.batch {
            sc = sc.for_batch();
        }
        sc.with_keyword_flags()
    }
}

/// A run: the scenario as built (either form: it names the files' columns) and its solution.
struct Run {
    setup: Setup,
    sol: BridgeSolution,
    /// The scenario's name and text (its `[code_check]` goes into the summary).
    scenario: (String, String),
}

/// The result of one simulation, kept in Rust: the summary, tables and histories are made on
/// demand (`summary_json`, `history`, `impacts`, `tables` and their texts).
#[pyclass(module = "pounding._core", frozen)]
pub struct SimRun {
    run: Run,
    /// The text of `accuracy.json` (`error_estimate` / `tol`), else `None`.
    accuracy: Option<String>,
}

#[pymethods]
impl SimRun {
    /// The text of `summary.json`, as the CLI writes it.
    fn summary_json(&self) -> String {
        pounding::assessment::check_summary::run_summary_json_text(
            &self.run.setup,
            &self.run.sol,
            (&self.run.scenario.0, &self.run.scenario.1),
        )
    }
    /// The text of `accuracy.json` when the run estimated its error, else `None`.
    fn accuracy_json(&self) -> Option<String> {
        self.accuracy.clone()
    }
    /// The text of `impacts.csv`.
    fn impacts_csv(&self) -> String {
        self.run.setup.impacts_csv(&self.run.sol)
    }
    /// `impacts.csv` as columns: a list of `(header, values)`, the values a float64 or int64
    /// array or a list of str (names), handed over as they are (no text in between).
    fn impacts<'py>(&self, py: Python<'py>) -> PyResult<Vec<(String, Bound<'py, PyAny>)>> {
        crate::columns::typed_columns(py, self.run.setup.impacts(&self.run.sol))
    }
    /// The text of `history.csv`.
    fn history_csv(&self) -> String {
        self.run.setup.history(&self.run.sol).csv()
    }
    /// `history.csv` as `(column names, float64 array of shape (rows, columns))`: the same
    /// numbers, handed over without text in between.
    fn history<'py>(&self, py: Python<'py>) -> PyResult<(Vec<String>, Bound<'py, PyArray2<f64>>)> {
        let (_, names, a) =
            crate::columns::float_table(py, self.run.setup.history(&self.run.sol).table())?;
        Ok((names, a))
    }
    /// The observers' tables (`bearings`, `restrainers`, `joint_slip`, `segment_forces`, …, as
    /// the CLI's `<name>.csv`): a list of `(name, column headers, float64 array (rows, columns))`, the
    /// values handed over as they are (no text in between).
    #[allow(clippy::type_complexity)]
    fn tables<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<Vec<(String, Vec<String>, Bound<'py, PyArray2<f64>>)>> {
        self.run
            .sol
            .tables()
            .into_iter()
            .map(|t| crate::columns::float_table(py, t))
            .collect()
    }
    /// How the run ended (`Completed`, `Diverged`, ... as in summary.json).
    #[getter]
    fn status(&self) -> String {
        let s: SimStatus = self.run.sol.status;
        format!("{s:?}")
    }
    /// The CLI's warnings of the run (energy created at a contact, a time step too coarse).
    fn warnings(&self) -> Vec<String> {
        let w = self.run.setup.run_warnings(&self.run.sol);
        let sol = &self.run.sol;
        let (advice, dt) = (sol.time_step_advice.as_ref(), sol.dt);
        let mut out: Vec<String> = so::warnings_message(&w).into_iter().collect();
        if let Some(a) = advice.filter(|a| !a.adequate) {
            out.push(format!(
                "dt = {} s is too coarse for the contact law: about {} steps per contact \
                 (contact duration {} s); use dt <= {} s",
                float_token(dt),
                float_token(a.steps_per_contact.round()),
                float_token(a.contact_duration),
                float_token(a.max_step)
            ));
        }
        out
    }
}

/// Runs one simulation. The scenario is `path`, else `text`, else the default; `record` is a
/// file (as `--record`) and `array` samples `(name, values, dt)` (in `csv_units`, default g) as
/// the only component along y. `scale`, `dt`, `duration`, `law`, `csv_units`, `record_dt` are
/// the CLI's flags.
#[pyfunction]
#[pyo3(signature = (path=None, text=None, origin="scenario", record=None, array=None, csv_units=None, record_dt=None, scale=None, dt=None, duration=None, law=None, error_estimate=false, tol=None, max_refinements=None, projection=false))]
#[allow(clippy::too_many_arguments)]
fn simulate_run(
    py: Python<'_>,
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
    record: Option<PathBuf>,
    array: Option<ArrayRecord>,
    csv_units: Option<&str>,
    record_dt: Option<f64>,
    scale: Option<f64>,
    dt: Option<f64>,
    duration: Option<f64>,
    law: Option<String>,
    error_estimate: bool,
    tol: Option<&str>,
    max_refinements: Option<usize>,
    projection: bool,
) -> PyResult<SimRun> {
    let csv_units = units(csv_units)?;
    let accuracy = accuracy_settings(error_estimate, tol, max_refinements)?;
    let sc = load(path, text, origin)?;
    let batch = array.is_some();
    let flags = Flags {
        record,
        csv_units,
        record_dt,
        scale: if batch { None } else { scale },
        dt,
        duration,
        law,
        batch,
        projection,
    };
    let sc = flags.apply(sc);
    let rec = match array {
        Some(a) => {
            let reading = sc.override_reading(csv_units).map_err(value_error)?;
            Some(array_record(a, reading.units)?)
        }
        None => None,
    };
    let s = scale.unwrap_or(1.0);
    if !sc.is_bridge() {
        sc.override_reading(csv_units).map_err(value_error)?;
    }
    let mut setup = sc.build_setup().map_err(value_error)?;
    check_tables(&sc, Some(pounding::sim::Problem::model(&setup).segments.len()))?;
    let scenario = (sc.origin().to_string(), sc.text().to_string());
    if let Some(r) = &rec {
        setup = run_problem(&setup, r, s);
        *setup.records_mut() = [r.name.clone(), "none".into()];
    }
    let (setup, sol) = crate::interruptible(py, move || {
        let sol = match accuracy {
            None => setup.run().map(|s| (s, None)),
            Some(a) => pounding::sim::accuracy::run_with_estimate(&setup, a, |_| {
                Default::default()
            })
            .map(|(sol, run)| {
                // the answer's step and history interval, for what is made from `setup`
                setup.settings_mut().dt = run.dts[run.chosen];
                setup.settings_mut().history_stride <<= run.chosen;
                (sol, Some(run))
            }),
        };
        (setup, sol)
    })?;
    let (sol, accuracy) = sol.map_err(value_error)?;
    let accuracy = accuracy
        .map(|a| serde_json::to_string_pretty(&a.json()).map(|t| t + "\n"))
        .transpose()
        .map_err(value_error)?;
    Ok(SimRun {
        run: Run {
            setup,
            sol,
            scenario,
        },
        accuracy,
    })
}

/// `error_estimate` / `tol` (`"1%"` or `"0.01"`, as `--tol`) / `max_refinements` (0 to 8) as
/// the library's settings; `None` for a plain run.
fn accuracy_settings(
    error_estimate: bool,
    tol: Option<&str>,
    max_refinements: Option<usize>,
) -> PyResult<Option<pounding::sim::accuracy::AccuracySettings>> {
    let mut a = pounding::sim::accuracy::AccuracySettings {
        tol: tol
            .map(pounding::sim::accuracy::parse_tol)
            .transpose()
            .map_err(|e| value_error(format!("tol: {e}")))?,
        ..Default::default()
    };
    match max_refinements {
        Some(_) if a.tol.is_none() => {
            return Err(value_error(
                "max_refinements applies with tol (the halvings of dt allowed to meet it)",
            ));
        }
        Some(n) if n > 8 => {
            return Err(value_error(format!(
                "max_refinements = {n}: at most 8 (the finest run at dt / 1024)"
            )));
        }
        Some(n) => a.max_refinements = n,
        None => {}
    }
    Ok((error_estimate || a.tol.is_some()).then_some(a))
}

/// Runs a batch: every record (a path, or samples `(name, values, dt)`) at every scale, or every
/// entry of the record-set manifest `record_set` (pairs along y and x, as `pounding simulate
/// --set`), in parallel on `threads` workers; returns the text of `batch.csv`.
#[pyfunction]
#[pyo3(signature = (path=None, text=None, origin="scenario", records=Vec::new(), arrays=Vec::new(), scales=Vec::new(), csv_units=None, record_dt=None, dt=None, duration=None, law=None, threads=None, record_set=None))]
#[allow(clippy::too_many_arguments)]
fn batch_run(
    py: Python<'_>,
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
    records: Vec<Option<PathBuf>>,
    arrays: Vec<Option<ArrayRecord>>,
    scales: Vec<f64>,
    csv_units: Option<&str>,
    record_dt: Option<f64>,
    dt: Option<f64>,
    duration: Option<f64>,
    law: Option<String>,
    threads: Option<usize>,
    record_set: Option<PathBuf>,
) -> PyResult<String> {
    if let Some(m) = &record_set {
        if !records.is_empty() || !arrays.is_empty() {
            return Err(value_error(
                "give records or a record_set (a manifest of pairs), not both",
            ));
        }
        if record_dt.is_some() {
            return Err(value_error(format!(
                "record_dt applies to the record files of records; the one-column records of \
                 the manifest {} give their sample interval in their entry (dt = SECONDS)",
                m.display()
            )));
        }
    }
    let csv_units = units(csv_units)?;
    let flags = Flags {
        record: None,
        csv_units,
        record_dt,
        scale: None,
        dt,
        duration,
        law,
        batch: true,
        projection: false,
    };
    let sc = flags.apply(load(path, text, origin)?);
    let reading: ReadOptions = sc.override_reading(csv_units).map_err(value_error)?;
    let (list, set) = match &record_set {
        Some(m) => {
            let set = RecordSet::load_with_units(m, reading.units, &reading.units_from)
                .map_err(value_error)?;
            (BatchRecord::of_set(&set), Some(set))
        }
        None => (record_list(records, arrays, &reading)?, None),
    };
    let pool = crate::pool(threads)?;
    let setup = sc.build_setup().map_err(value_error)?;
    let (layout, n) = (setup.layout(), setup.model().segments.len());
    check_tables(&sc, Some(n))?;
    if let Some(m) = &record_set {
        let what = match layout {
            so::Layout::TwoDecks => "a two-deck scenario".to_string(),
            so::Layout::Bridge => sc.origin().to_string(),
        };
        pounding::sim::batch_supports::check_set_supports(&setup, &list, m, &what)
            .map_err(value_error)?;
    }
    let settings = setup.settings().clone();
    let rows = batch_rows(py, pool, setup, settings, list, scales)?;
    Ok(match &set {
        Some(set) => so::batch_set_csv(layout, n, &rows, set),
        None => so::batch_csv(layout, n, &rows),
    })
}

/// The one-component entries of a batch: each record a path (read as the CLI reads it; an
/// unreadable one keeps its error) or samples.
fn record_list(
    records: Vec<Option<PathBuf>>,
    arrays: Vec<Option<ArrayRecord>>,
    reading: &ReadOptions,
) -> PyResult<Vec<BatchRecord>> {
    let mut list = Vec::with_capacity(records.len().max(arrays.len()));
    for (p, a) in records.into_iter().zip(arrays) {
        list.push(match (p, a) {
            (Some(p), _) => BatchRecord::single(
                p.display().to_string(),
                Record::open_with(&p, reading).map_err(|e| e.to_string()),
            ),
            (None, Some(a)) => BatchRecord::single(a.0.clone(), Ok(array_record(a, reading.units)?)),
            (None, None) => return Err(value_error("a record is neither a path nor an array")),
        });
    }
    Ok(list)
}

/// Runs every record of `list` at every scale on `problem` (two decks or a bridge) in `pool`, off
/// the Python thread (interruptible): the rows in input order.
fn batch_rows<P>(
    py: Python<'_>,
    pool: rayon::ThreadPool,
    problem: P,
    settings: SimSettings,
    list: Vec<BatchRecord>,
    scales: Vec<f64>,
) -> PyResult<Vec<BatchRow>>
where
    P: pounding::sim::Problem + Send + 'static,
{
    crate::interruptible(py, move || {
        pool.install(|| run_batch(&problem, &settings, &list, &scales, Shard::ALL, &|_| {}))
    })?
    .map_err(value_error)
}

/// The built-in default `simulate` scenario (commented TOML, `pounding simulate --print-default`).
#[pyfunction]
fn default_simulate_scenario() -> &'static str {
    DEFAULT_SCENARIO_TOML
}

/// The built-in default `study` scenario (`pounding study --print-default`).
#[pyfunction]
fn default_study_scenario() -> &'static str {
    pounding::study::DEFAULT_SCENARIO_TOML
}

/// Registers the simulation functions.
/// `pounding check`: the code check of a scenario's seats and joint gaps, as the texts of
/// `check.json`, `check.csv`, `check_gaps.csv` and the printed table.
#[pyfunction]
#[pyo3(signature = (path=None, text=None, origin="scenario"))]
fn check_run(
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
) -> PyResult<(String, String, String, String)> {
    use pounding::assessment::check_write::{check_csv, check_gaps_csv, check_json, check_text};
    let sc = load(path, text, origin)?;
    let report = pounding::assessment::check_scenario(&sc).map_err(value_error)?;
    let o = sc.origin();
    Ok((
        check_json(&report, o),
        check_csv(&report),
        check_gaps_csv(&report),
        check_text(&report, o),
    ))
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<SimRun>()?;
    m.add_function(wrap_pyfunction!(check_run, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_run, m)?)?;
    m.add_function(wrap_pyfunction!(batch_run, m)?)?;
    m.add_function(wrap_pyfunction!(default_simulate_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(default_study_scenario, m)?)?;
    Ok(())
}
