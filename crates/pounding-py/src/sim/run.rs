//! `pounding.simulate`: one run (either form) and its result kept in Rust ([`SimRun`]), the
//! files' texts and columns made from it on demand.

use super::{ArrayRecord, Flags, array_record, check_tables, load, units};
use crate::value_error;
use numpy::PyArray2;
use pounding::output::float_token;
use pounding::sim::SimStatus;
use pounding::sim::batch::run_problem;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::output as so;
use pounding::sim::scenario::Setup;
use pyo3::prelude::*;
use std::path::PathBuf;

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
pub(super) fn simulate_run(
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
    check_tables(
        &sc,
        Some(pounding::sim::Problem::model(&setup).segments.len()),
    )?;
    let scenario = (sc.origin().to_string(), sc.text().to_string());
    if let Some(r) = &rec {
        setup = run_problem(&setup, r, s);
        *setup.records_mut() = [r.name.clone(), "none".into()];
    }
    let (setup, sol) = crate::interruptible(py, move || {
        let sol = match accuracy {
            None => setup.run().map(|s| (s, None)),
            Some(a) => {
                pounding::sim::accuracy::run_with_estimate(&setup, a, |_| Default::default()).map(
                    |(sol, run)| {
                        // the answer's step and history interval, for what is made from `setup`
                        setup.settings_mut().dt = run.dts[run.chosen];
                        setup.settings_mut().history_stride <<= run.chosen;
                        (sol, Some(run))
                    },
                )
            }
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
