//! `pounding.simulate` and `pounding.batch`: seismic time histories of two decks or of a bridge
//! of N segments (as `pounding simulate`), and batches of (record, scale) runs (as
//! `pounding simulate --records ... --scales ...`, or `--set MANIFEST` for pairs).
//!
//! `run.rs` holds one simulation and its result, `batch.rs` the batches; here the scenario
//! loading and the flags they share, the default scenarios and `pounding check`.

mod batch;
mod run;

pub use run::SimRun;

use crate::value_error;
use pounding::ground_motion::{AccelUnits, Record};
use pounding::sim::scenario::{DEFAULT_SCENARIO_TOML, ParamKey, Scenario, Section};
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

/// Registers the simulation functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<SimRun>()?;
    m.add_function(wrap_pyfunction!(check_run, m)?)?;
    m.add_function(wrap_pyfunction!(run::simulate_run, m)?)?;
    m.add_function(wrap_pyfunction!(batch::batch_run, m)?)?;
    m.add_function(wrap_pyfunction!(default_simulate_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(default_study_scenario, m)?)?;
    Ok(())
}
