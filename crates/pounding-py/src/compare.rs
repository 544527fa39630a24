//! `pounding.compare`: one scenario under several contact laws, as `pounding compare` (the
//! library's [`pounding::sim::compare`]; no files, no figures).

use pounding::sim::compare::{CompareFlags, Comparison, LawRun, agreement};
use pounding::sim::output as so;
use pyo3::prelude::*;

/// What `compare_run` returns: the texts of `compare.csv`, of `compare_sites.csv` (a bridge;
/// `None` for two decks) and of the printed table; the skipped laws `(law, reason)`; each law's
/// warnings `(law, messages)` and wall time `(law, seconds)`; the agreement (sentences on the
/// whole comparison, `(law, sentence)` per law).
type CompareOut = (
    String,
    Option<String>,
    String,
    Vec<(String, String)>,
    Vec<(String, Vec<String>)>,
    Vec<(String, f64)>,
    (Vec<String>, Vec<(String, String)>),
);

/// An error with its causes, `: `-separated, as the CLI prints it.
fn chain(e: &dyn std::error::Error) -> String {
    let mut s = e.to_string();
    let mut src = e.source();
    while let Some(c) = src {
        s.push_str(": ");
        s.push_str(&c.to_string());
        src = c.source();
    }
    s
}

/// Runs the comparison of the scenario `path`, else `text`, else the default, under `laws`
/// (default: the CLI's six) with the CLI's `--dt`, `--scale`, `--duration`.
#[pyfunction]
#[pyo3(signature = (path=None, text=None, origin="scenario", laws=None, dt=None, scale=None, duration=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn compare_run(
    py: Python<'_>,
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
    laws: Option<Vec<String>>,
    dt: Option<f64>,
    scale: Option<f64>,
    duration: Option<f64>,
) -> PyResult<CompareOut> {
    let flags = CompareFlags {
        laws: laws.unwrap_or_else(|| {
            pounding::sim::compare::DEFAULT_LAWS
                .iter()
                .map(|l| l.to_string())
                .collect()
        }),
        dt,
        scale,
        duration,
    };
    let err = |e: &dyn std::error::Error| crate::value_error(chain(e));
    // the CLI's order: the flags, then the scenario
    flags.check().map_err(|e| err(&e))?;
    let base = crate::sim::load(path, text, origin)?;
    let tables = base.clone();
    let cmp = Comparison::prepare(base, &flags).map_err(|e| err(&e))?;
    if let Some(s) = cmp.first_setup() {
        crate::sim::check_tables(
            &tables,
            Some(pounding::sim::Problem::model(s).segments.len()),
        )?;
    }
    let bridge = cmp.bridge;
    let runs = crate::interruptible(py, move || {
        cmp.run(pounding::sim::Progress::default, |_| {})
    })?
    .map_err(|e| err(&e))?;
    Ok(outputs(&runs, bridge))
}

/// The texts and lists of [`CompareOut`] from the runs.
fn outputs(runs: &[LawRun], bridge: bool) -> CompareOut {
    // the library's one writer of either form: compare.csv, then a bridge's compare_sites.csv
    let (tables, table) = so::compare_tables(runs, bridge);
    let mut tables = tables.into_iter().map(|t| t.csv);
    let csv = tables.next().unwrap_or_default();
    let sites = tables.next();
    let mut skipped = Vec::new();
    let mut warnings = Vec::new();
    let mut seconds = Vec::new();
    for r in runs {
        match &r.outcome {
            Ok(ran) => {
                warnings.push((
                    r.law.clone(),
                    ran.warnings.iter().map(|w| w.message.clone()).collect(),
                ));
                seconds.push((r.law.clone(), ran.seconds));
            }
            Err(why) => skipped.push((r.law.clone(), why.clone())),
        }
    }
    let a = agreement(runs);
    (
        csv,
        sites,
        table,
        skipped,
        warnings,
        seconds,
        (a.overall, a.laws),
    )
}

/// Registers the comparison.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(compare_run, m)?)?;
    Ok(())
}
