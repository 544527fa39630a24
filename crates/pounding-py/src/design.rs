//! `pounding.design`: retrofit variants of one bridge (as `pounding design`), the texts of its
//! data files (`variants.csv`, `variants.json`, `search.csv`, each member's
//! `variants/<name>/` files) and, with `out`, those files written as the CLI writes them
//! ([`pounding::assessment::design_out`], the CLI's code path).

use pounding::assessment::design::Design;
use pounding::assessment::design_out;
use pounding::assessment::design_search::search;
use pounding::assessment::design_write::{compare, not_finite, recommendation};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

// `pounding design` has the flags of `pounding fragility` (--set, --hazard, --out, --threads):
// its errors name them as the same Python arguments
use crate::assess::input_error;

/// Runs the design file `path` (`set` instead of the scenario's record set, `hazard` instead
/// of its `[hazard]`) on `threads` workers; with `out`, writes the data files there (an earlier
/// run's variant folders removed, as the CLI does). Returns a dict: `files` (relative path →
/// text), `members` (names, the as-built bridge first), `recommendation`, `search_verdict`
/// (or None), `excluded` (or None), `maf_failure` (or None), `im`.
#[pyfunction]
#[pyo3(signature = (path, set=None, hazard=None, out=None, threads=None))]
fn design_run<'py>(
    py: Python<'py>,
    path: PathBuf,
    set: Option<PathBuf>,
    hazard: Option<PathBuf>,
    out: Option<PathBuf>,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let design = Design::read(&path, set.as_deref(), hazard.as_deref()).map_err(input_error)?;
    let pool = crate::pool(threads)?;
    let stale = match &out {
        Some(o) => {
            pounding::output::check_output_dir_free(o).map_err(input_error)?;
            design_out::stale_variant_dirs(o, &design).map_err(input_error)?
        }
        None => Vec::new(),
    };
    let done = crate::interruptible(py, move || {
        pool.install(|| -> Result<_, (bool, String)> {
            let plan = design.plan().map_err(|e| (true, e.to_string()))?;
            let rows = design.run(&plan, &|| {});
            let fits = design
                .fit(&plan, &rows)
                .map_err(|e| (false, format!("fitting: {e}")))?;
            let searched = match &design.search {
                Some(spec) => Some((
                    spec.clone(),
                    search(&design, spec, &plan, &|| {}).map_err(|e| (true, e.to_string()))?,
                )),
                None => None,
            };
            let files = design_out::data_files(
                &design,
                &plan,
                &rows,
                &fits,
                searched.as_ref().map(|(s, r)| (s, r)),
            );
            Ok((design, rows, fits, searched, files))
        })
    })?;
    let (design, rows, fits, searched, files) = done.map_err(|(input, m)| {
        if input {
            input_error(m)
        } else {
            crate::SolverError::new_err(m)
        }
    })?;
    if let Some(o) = &out {
        py.detach(|| design_out::write_locked(o, &files, &stale))
            .map_err(input_error)?;
    }
    let (stat, comps) = compare(&design, &fits);
    let d = PyDict::new(py);
    let texts = PyDict::new(py);
    for (name, text) in &files.top {
        texts.set_item(*name, text)?;
    }
    for (member, list) in &files.members {
        for (name, text) in list {
            texts.set_item(
                format!("{}/{member}/{name}", design_out::VARIANTS_DIR),
                text,
            )?;
        }
    }
    d.set_item("files", texts)?;
    let names: Vec<&str> = design.members.iter().map(|m| m.name.as_str()).collect();
    d.set_item("members", names)?;
    d.set_item(
        "recommendation",
        recommendation(&design, &fits, stat, &comps),
    )?;
    d.set_item(
        "search_verdict",
        searched.as_ref().map(|(_, r)| r.verdict.clone()),
    )?;
    d.set_item("search_found", searched.as_ref().and_then(|(_, r)| r.found))?;
    d.set_item("excluded", design_out::excluded_message(&rows))?;
    d.set_item("maf_failure", not_finite(&design, &fits, &comps))?;
    d.set_item("im", design.members[0].study.spec.label())?;
    Ok(d)
}

/// Registers the design function.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(design_run, m)?)?;
    Ok(())
}
