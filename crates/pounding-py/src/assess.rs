//! `pounding.fragility`: a fragility study (as `pounding fragility`), the texts of its data files
//! (`runs.csv`, `fragility.csv`, `fragility.json`) and, with `out`, those files written as the
//! CLI writes them ([`pounding::assessment::study`], the CLI's code path).

use crate::value_error;
use pounding::assessment::hazard_study::{maf_failure, maf_warnings};
use pounding::assessment::study::{Study, excluded_message, fit_warnings, write_data_files};
use pounding::input::rename_flags;
use pounding::sim::scenario::Scenario;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::{Path, PathBuf};

/// The CLI's flags of `pounding fragility` and the Python arguments that give them.
const NAMES: &[(&str, &str)] = &[
    ("--set", "record_set"),
    ("--hazard", "hazard"),
    ("--out", "out"),
    ("--threads", "threads"),
];

/// `ValueError` with the library's message, the CLI's flags named as the Python arguments.
pub(crate) fn input_error(e: impl std::fmt::Display) -> PyErr {
    value_error(rename_flags(&e.to_string(), NAMES))
}

/// Why a study ended without a result, found off the Python thread.
enum Failure {
    /// Bad input (a record's IM, a scale factor out of range): `ValueError`.
    Input(String),
    /// The fit failed: `SolverError`.
    Fit(String),
}

/// Runs a fragility study: the scenario `path` (its `[fragility] records` relative to the
/// file) or the TOML `text` (named `origin`, records relative to the current directory), the
/// record set `set` instead of `[fragility] records`, the hazard file `hazard` instead of its
/// `[hazard]`, on `threads` workers; with `out`, writes the data files there. Returns a dict:
/// `files` (name → text of `runs.csv`, `fragility.csv`, `fragility.json`, and with a hazard
/// `maf.csv`, `hazard.csv`), `record_warnings`, `warnings`, `maf_warnings`, `excluded` (the
/// message, or None), `maf_failure` (a MAF that is not finite: the message, or None), `im`,
/// `period`, `set_path`.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (path=None, text=None, origin="scenario", set=None, hazard=None, out=None, threads=None))]
fn fragility_run<'py>(
    py: Python<'py>,
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
    set: Option<PathBuf>,
    hazard: Option<PathBuf>,
    out: Option<PathBuf>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let (scenario, dir) = match (path, text) {
        (Some(p), _) => (
            Scenario::load(Path::new(p)).map_err(input_error)?,
            Path::new(p).parent().map(Path::to_path_buf),
        ),
        (None, Some(t)) => (Scenario::from_toml(&t, origin).map_err(input_error)?, None),
        (None, None) => return Err(value_error("fragility needs a scenario")),
    };
    let mut study = Study::read(scenario, dir.as_deref(), set.as_deref()).map_err(input_error)?;
    if let Some(h) = &hazard {
        study = study.with_hazard(h).map_err(input_error)?;
    }
    let pool = crate::pool(threads)?;
    if let Some(o) = &out {
        pounding::output::check_output_dir_free(o).map_err(input_error)?;
    }
    let done = crate::interruptible(py, move || {
        pool.install(|| {
            let plan = study.plan().map_err(|e| Failure::Input(e.to_string()))?;
            let rows = study.run(&plan, &|| {});
            let fits = study
                .fit(&plan, &rows)
                .map_err(|e| Failure::Fit(format!("fitting: {e}")))?;
            let mut files: Vec<(&str, String)> = study.data_files(&plan, &rows, &fits).into();
            files.extend(study.hazard_files(&fits));
            Ok((study, rows, fits, files))
        })
    })?;
    let (study, rows, fits, files) = done.map_err(|f| match f {
        Failure::Input(m) => input_error(m),
        Failure::Fit(m) => crate::SolverError::new_err(m),
    })?;
    if let Some(o) = &out {
        py.detach(|| write_data_files(o, &files))
            .map_err(input_error)?;
    }
    let d = PyDict::new(py);
    let texts = PyDict::new(py);
    for (name, text) in &files {
        texts.set_item(*name, text)?;
    }
    d.set_item("files", texts)?;
    d.set_item("record_warnings", study.record_warnings())?;
    d.set_item("warnings", fit_warnings(&rows, &fits))?;
    d.set_item("excluded", excluded_message(&rows))?;
    let maf = study.maf(&fits);
    d.set_item(
        "maf_warnings",
        maf.as_deref().map(maf_warnings).unwrap_or_default(),
    )?;
    d.set_item("maf_failure", maf.as_deref().and_then(maf_failure))?;
    d.set_item("im", study.spec.label())?;
    d.set_item("period", study.period.as_ref().map(|p| p.describe()))?;
    d.set_item("set_path", study.set_path.display().to_string())?;
    Ok(d)
}

/// Registers the fragility functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(fragility_run, m)?)?;
    Ok(())
}
