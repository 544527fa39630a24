//! `pounding.spectrum` (as `pounding spectrum`: the text of `spectrum.csv`) and
//! `pounding.motion.synth` (as `pounding motion synth`: the records, and with `out` the CLI's
//! files), through the library functions the CLI calls.

use crate::value_error;
use numpy::PyArray1;
use pounding::ground_motion::synth::{
    SynthParams, check_count, check_seed, check_suite_size, suite, synth_source, write_suite,
};
use pounding::input::rename_flags;
use pounding::spectrum::{SpectrumRequest, spectrum_csv};
use pyo3::prelude::*;
use std::path::PathBuf;

/// The CLI's flags of `pounding spectrum` and the Python arguments that give them.
const SPECTRUM_NAMES: &[(&str, &str)] = &[
    ("--pair", "pair"),
    ("--damping", "damping"),
    ("--periods", "periods"),
    ("--csv-units", "csv_units"),
    ("--record-dt", "record_dt"),
    ("--out", "out"),
];

/// The CLI's flags of `pounding motion synth` and the Python arguments that give them.
const SYNTH_NAMES: &[(&str, &str)] = &[
    ("--count", "count"),
    ("--seed", "seed"),
    ("--out", "out"),
    ("--pga", "pga"),
    ("--dt", "dt"),
    ("--duration", "duration"),
    ("--pairs", "pairs"),
];

/// The text of `spectrum.csv` for `records` (component `x` each) and `pair`s (`x`, `y`,
/// `rotd50`, `rotd100`) at `damping` and `periods` (empty: the default 100), records read as
/// `pounding spectrum` reads them (`builtin:` names, `csv_units`, `record_dt`).
#[pyfunction]
#[pyo3(signature = (records, pair, damping, periods, csv_units, record_dt=None))]
fn spectrum_run(
    py: Python<'_>,
    records: Vec<String>,
    pair: Vec<(String, String)>,
    damping: f64,
    periods: Vec<f64>,
    csv_units: String,
    record_dt: Option<f64>,
) -> PyResult<String> {
    let request = SpectrumRequest {
        records,
        pairs: pair,
        damping,
        periods,
        csv_units,
        record_dt,
    };
    let text = crate::interruptible(py, move || {
        let inputs = request.read().map_err(|e| e.to_string())?;
        let curves = inputs.curves().map_err(|e| e.to_string())?;
        Ok::<_, String>(spectrum_csv(&curves))
    })?;
    text.map_err(|m| value_error(rename_flags(&m, SPECTRUM_NAMES)))
}

/// The records of a synthetic suite as `(ids, x, y)` in g: `y` holds `None` without `pairs`.
type Suite<'py> = (
    Vec<String>,
    Vec<Bound<'py, PyArray1<f64>>>,
    Vec<Option<Bound<'py, PyArray1<f64>>>>,
);

/// A synthetic suite of `count` records (`pounding motion synth`): the same records for the same
/// `seed` and parameters. With `out`, writes the CLI's files there (the `.AT2` files,
/// `SYNTHETIC.txt`, `suite.toml` last), the same bytes. Returns `(ids, x, y)` in g.
#[pyfunction]
#[pyo3(signature = (count, seed, out=None, pga=None, dt=0.01, duration=20.0, pairs=false))]
#[allow(clippy::too_many_arguments)]
fn motion_synth<'py>(
    py: Python<'py>,
    count: usize,
    seed: u64,
    out: Option<PathBuf>,
    pga: Option<f64>,
    dt: f64,
    duration: f64,
    pairs: bool,
) -> PyResult<Suite<'py>> {
    let bad = |e: &dyn std::fmt::Display| value_error(rename_flags(&e.to_string(), SYNTH_NAMES));
    let p = SynthParams {
        dt,
        duration,
        pga_g: pga,
        ..SynthParams::default()
    };
    // every argument is checked before the directory is created or locked
    check_count(count).map_err(|e| bad(&e))?;
    check_seed(seed).map_err(|e| bad(&e))?;
    p.check().map_err(|e| bad(&e))?;
    check_suite_size(&p, count, pairs).map_err(|e| bad(&e))?;
    let records = match out {
        Some(dir) => {
            let lock = pounding::output::lock_output_dir(&dir).map_err(|e| bad(&e))?;
            let source = synth_source(&p, count, seed, pairs);
            crate::interruptible(py, move || {
                let r = write_suite(&dir, &p, count, seed, pairs, &source)
                    .map_err(|e| format!("writing the suite to {}: {e}", dir.display()));
                drop(lock);
                r
            })?
            .map_err(value_error)?
        }
        None => {
            crate::interruptible(py, move || suite(&p, count, seed, pairs))?.map_err(|e| bad(&e))?
        }
    };
    let mut ids = Vec::with_capacity(records.len());
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for r in records {
        ids.push(r.id);
        xs.push(PyArray1::from_vec(py, r.x));
        ys.push(r.y.map(|y| PyArray1::from_vec(py, y)));
    }
    Ok((ids, xs, ys))
}

/// Registers the spectrum and motion functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(spectrum_run, m)?)?;
    m.add_function(wrap_pyfunction!(motion_synth, m)?)?;
    Ok(())
}
