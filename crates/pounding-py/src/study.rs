//! `pounding.study`: the parametric stick/slip study (as `pounding study`), its rows as numpy
//! columns in `bounds.csv`'s order and its summaries as the text of `summary.csv` /
//! `summary.json`.

use crate::value_error;
use numpy::PyArray1;
use pounding::input::{SCENARIO_LIMIT, read_text};
use pounding::study::csv::bounds_header;
use pounding::study::scenario::StudyShape;
use pounding::study::{DEFAULT_SCENARIO_TOML, Scenario, Study};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::path::Path;

/// Upper bound of the rows one call holds in memory (the CLI's limit of one run).
const MAX_ROWS: usize = 20_000_000;

/// The scenario text and its name in messages: the file `path` (read as the CLI reads it), the
/// TOML `text` (named `origin`), or the built-in default.
pub(crate) fn scenario_source(
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
    default: &str,
) -> PyResult<(String, String)> {
    match (path, text) {
        (Some(p), _) => {
            let t = read_text(Path::new(p), "scenario file", SCENARIO_LIMIT)
                .map_err(|e| value_error(format!("cannot read scenario file {p}: {e}")))?;
            Ok((t, p.to_string()))
        }
        (None, Some(t)) => Ok((t, origin.to_string())),
        (None, None) => Ok((default.to_string(), "built-in default".to_string())),
    }
}

/// Adds the bounds.csv columns of `study` to `cols` (a dict, in the header's order).
fn columns<'py>(py: Python<'py>, study: &Study, cols: &Bound<'py, PyDict>) -> PyResult<()> {
    let sc = &study.scenario;
    let rows = &study.rows;
    let theta = [sc.theta1.values(), sc.theta2.values()];
    let params: Vec<_> = rows.iter().map(|r| sc.params(&r.key)).collect();
    let f = |g: &dyn Fn(usize) -> f64| -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, (0..rows.len()).map(g).collect())
    };
    let b = |g: &dyn Fn(usize) -> bool| -> Bound<'py, PyArray1<bool>> {
        PyArray1::from_vec(py, (0..rows.len()).map(g).collect())
    };
    cols.set_item("beta1_deg", f(&|k| params[k].beta1_deg))?;
    cols.set_item("beta2_deg", f(&|k| params[k].beta2_deg))?;
    cols.set_item("r1_m", f(&|k| params[k].r1_m))?;
    cols.set_item("r2_m", f(&|k| params[k].r2_m))?;
    cols.set_item("mu", f(&|k| params[k].mu))?;
    cols.set_item("eps", f(&|k| params[k].eps))?;
    let cases: Vec<&str> = params.iter().map(|p| p.case.name()).collect();
    cols.set_item("case", PyList::new(py, cases)?)?;
    cols.set_item("theta1_deg", f(&|k| theta[0][rows[k].key.i]))?;
    cols.set_item("theta2_deg", f(&|k| theta[1][rows[k].key.j]))?;
    cols.set_item("first_contact", b(&|k| rows[k].cell.first_contact))?;
    cols.set_item("end_closes", b(&|k| rows[k].cell.end_closes))?;
    cols.set_item("sigma_m", f(&|k| rows[k].cell.sigma_m))?;
    cols.set_item("g_nn", f(&|k| rows[k].cell.g_nn))?;
    cols.set_item("g_nt", f(&|k| rows[k].cell.g_nt))?;
    cols.set_item("g_tt", f(&|k| rows[k].cell.g_tt))?;
    cols.set_item("kappa", f(&|k| rows[k].cell.kappa))?;
    cols.set_item("varrho", f(&|k| rows[k].cell.varrho))?;
    cols.set_item("lower", f(&|k| rows[k].cell.lower))?;
    cols.set_item("upper", f(&|k| rows[k].cell.upper))?;
    cols.set_item("lcp_agrees", b(&|k| rows[k].cell.lcp_agrees))?;
    if sc.shape != StudyShape::Curved {
        cols.set_item("shape", PyList::new(py, vec![sc.shape.name(); rows.len()])?)?;
        cols.set_item("l1_m", f(&|k| params[k].l1_m))?;
        cols.set_item("l2_m", f(&|k| params[k].l2_m))?;
        cols.set_item("skew_deg", f(&|k| params[k].skew_deg))?;
    }
    Ok(())
}

/// Runs a study: `path` (a scenario file), else `text` (TOML named `origin`), else the
/// built-in default. Returns a dict with `header` (bounds.csv's header line), `columns` (name →
/// array or list, in the header's order), `summary_csv`, `summary_json`, `notes`,
/// `lcp_disagreements` and `scenario_text`.
#[pyfunction]
#[pyo3(signature = (path=None, text=None, origin="scenario", threads=None))]
fn study<'py>(
    py: Python<'py>,
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let (text, origin) = scenario_source(path, text, origin, DEFAULT_SCENARIO_TOML)?;
    let (scenario, notes) = Scenario::from_toml_with_notes(&text, &origin).map_err(value_error)?;
    let total = scenario.row_count();
    if total > MAX_ROWS {
        return Err(value_error(format!(
            "the scenario gives {total} rows; one run holds at most {MAX_ROWS} rows in memory \
             (about 0.5 KB each): use a coarser grid, fewer parameter values, or the CLI's \
             --shard K/N"
        )));
    }
    let pool = crate::pool(threads)?;
    let study = crate::interruptible(py, move || {
        pool.install(|| Study::compute(text, scenario, &|_| {}))
    })?
    .map_err(value_error)?;
    let d = PyDict::new(py);
    d.set_item("header", bounds_header(&study.scenario))?;
    let cols = PyDict::new(py);
    columns(py, &study, &cols)?;
    d.set_item("columns", cols)?;
    d.set_item("summary_csv", study.summary_csv())?;
    d.set_item("summary_json", study.summary_json())?;
    d.set_item(
        "notes",
        notes.iter().map(|n| n.to_string()).collect::<Vec<_>>(),
    )?;
    d.set_item("lcp_disagreements", study.lcp_disagreements())?;
    d.set_item("rows", study.rows.len())?;
    d.set_item("scenario_text", &study.scenario_text)?;
    Ok(d)
}

/// Registers the study functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(study, m)?)?;
    Ok(())
}
