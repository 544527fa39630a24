//! `pounding.campaign`: a campaign read once per process ([`pounding::campaign::Campaign`]),
//! its store prepared, parts run and written by any process (a Dask worker), the stores merged
//! ([`pounding::campaign::store::merge`]) — the CLI's code path, the same bytes.

use crate::value_error;
use pounding::campaign::{Campaign, Store, exec, store};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// A campaign spec read and planned (every record's IM computed): `runs`, `parts`,
/// `runs_per_part`, `name`, `fingerprint`.
#[pyclass(frozen, module = "pounding._core", name = "Campaign")]
pub struct PyCampaign {
    inner: Campaign,
}

#[pymethods]
impl PyCampaign {
    /// Reads the spec at `path` (paths in it relative to its directory).
    #[new]
    fn new(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let c = crate::heavy(py, move || Campaign::load(&path))?.map_err(value_error)?;
        Ok(Self { inner: c })
    }

    /// The number of runs.
    #[getter]
    fn runs(&self) -> usize {
        self.inner.runs()
    }

    /// The number of parts.
    #[getter]
    fn parts(&self) -> usize {
        self.inner.parts()
    }

    /// Runs per part.
    #[getter]
    fn runs_per_part(&self) -> usize {
        self.inner.runs_per_part
    }

    /// The campaign's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name.clone()
    }

    /// The hash of everything the stored results depend on (hex).
    #[getter]
    fn fingerprint(&self) -> String {
        format!("{:016x}", self.inner.fingerprint)
    }

    /// The stored columns.
    fn columns(&self) -> Vec<String> {
        self.inner.column_names()
    }

    /// Opens (or creates) the store in `out` (as `campaign run` does: `campaign.json` written or
    /// checked, temporaries of an interrupted run removed) and returns the parts not yet stored.
    /// Refused while another run holds `out`'s lock, unless `lock` is this caller's lock of `out`
    /// (as `run` holds it).
    #[pyo3(signature = (out, lock=None))]
    fn prepare(
        &self,
        py: Python<'_>,
        out: PathBuf,
        lock: Option<PyRef<'_, PyStoreLock>>,
    ) -> PyResult<Vec<usize>> {
        let c = &self.inner;
        let ours = lock.is_some_and(|l| l.lock.as_ref().is_some_and(|l| l.dir() == out));
        let r = crate::heavy(py, || {
            if !ours {
                pounding::output::check_output_dir_free(&out).map_err(|e| e.to_string())?;
            }
            let st = Store::open(&out, c).map_err(|e| e.to_string())?;
            exec::pending(c, &st, pounding::shard::Shard::ALL)
                .map(|(todo, _)| todo)
                .map_err(|e| e.to_string())
        })?;
        r.map_err(value_error)
    }

    /// Runs `parts` on `threads` workers (1 by default: a Dask worker runs one task per
    /// thread) without the GIL and writes each into the store `out` (which must describe this
    /// campaign; nothing else in it is touched). Returns the number of runs.
    #[pyo3(signature = (out, parts, threads=1))]
    fn run_parts(
        &self,
        py: Python<'_>,
        out: PathBuf,
        parts: Vec<usize>,
        threads: Option<usize>,
    ) -> PyResult<usize> {
        let c = &self.inner;
        if let Some(bad) = parts.iter().find(|p| **p >= c.parts()) {
            return Err(value_error(format!(
                "part {bad} of a campaign of {} parts",
                c.parts()
            )));
        }
        let pool = crate::pool(threads)?;
        let r = crate::heavy(py, || {
            let st = Store::attach(&out, c)?;
            pool.install(|| exec::run_parts(c, &st, &parts, &|| {}))
        })?;
        r.map_err(|e| crate::SolverError::new_err(e.to_string()))
    }
}

/// Merges the parts of the stores `stores` into `out/runs.parquet`; returns a dict `path`,
/// `rows`, `statuses` (status → count).
#[pyfunction]
fn campaign_merge<'py>(
    py: Python<'py>,
    stores: Vec<PathBuf>,
    out: PathBuf,
) -> PyResult<Bound<'py, PyDict>> {
    let m = crate::heavy(py, move || store::merge(&stores, &out))?.map_err(value_error)?;
    let d = PyDict::new(py);
    d.set_item("path", m.path.display().to_string())?;
    d.set_item("rows", m.rows)?;
    d.set_item("statuses", m.statuses.into_iter().collect::<Vec<_>>())?;
    Ok(d)
}

/// The lock of an output directory (`pounding::output::lock_output_dir`, the CLI's): held while
/// a campaign runs into the store, so that a second run (another process, the CLI, or this
/// process again) is refused instead of writing the same parts. Dask workers write parts without
/// it (the driver holds it); released by `release()`, by leaving a `with` block, or when the
/// process ends.
#[pyclass(module = "pounding._core", name = "StoreLock")]
pub struct PyStoreLock {
    lock: Option<pounding::output::OutputLock>,
}

#[pymethods]
impl PyStoreLock {
    /// Locks the directory `out` (created if missing); `ValueError` when another run holds it.
    #[new]
    fn new(out: PathBuf) -> PyResult<Self> {
        pounding::output::check_output_dir_free(&out).map_err(value_error)?;
        let lock = pounding::output::lock_output_dir(&out).map_err(value_error)?;
        Ok(Self { lock: Some(lock) })
    }

    /// Whether the lock is still held.
    #[getter]
    fn held(&self) -> bool {
        self.lock.is_some()
    }

    /// Releases the lock (a second call does nothing).
    fn release(&mut self) {
        self.lock = None;
    }

    fn __enter__(slf: Py<Self>) -> Py<Self> {
        slf
    }

    #[pyo3(signature = (*_args))]
    fn __exit__(&mut self, _args: &Bound<'_, pyo3::types::PyTuple>) -> bool {
        self.release();
        false
    }
}

/// Registers the campaign functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyCampaign>()?;
    m.add_class::<PyStoreLock>()?;
    m.add_function(wrap_pyfunction!(campaign_merge, m)?)?;
    Ok(())
}
