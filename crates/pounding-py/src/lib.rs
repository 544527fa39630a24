//! Python bindings of `pounding` (the extension module `pounding._core`).
//!
//! Every function here calls the library functions the CLI calls (`pounding::lcp`,
//! `pounding::impact_report`, `pounding::study`, `pounding::sim`, `pounding::sim::compare`,
//! `pounding::assessment`, `pounding::spectrum`, `pounding::ground_motion::synth`), so that the
//! numbers are the
//! CLI's, bit for bit. Bad input raises `ValueError` with the library's message; a panic inside
//! a computation raises `pounding.SolverError` (never an interpreter crash). Heavy calls release
//! the GIL. The Python package `pounding` (python/pounding) wraps these in documented classes.
#![warn(missing_docs)]

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

mod assess;
mod campaign;
mod columns;
mod compare;
mod design;
mod impact;
mod lcp;
mod motion;
mod sim;
mod study;

pyo3::create_exception!(
    _core,
    SolverError,
    PyRuntimeError,
    "A computation failed without a result (the CLI would exit without writing outputs)."
);

/// `ValueError(message)`: bad input, with the library's message.
pub(crate) fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// [`SolverError`] of a caught panic's payload.
fn panic_error(p: Box<dyn std::any::Any + Send>) -> PyErr {
    let msg = p
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "unknown panic".into());
    SolverError::new_err(format!("internal error in pounding: {msg}"))
}

/// Runs `f` without the GIL, turning a panic into [`SolverError`] (short computations).
pub(crate) fn heavy<T: Send>(py: Python<'_>, f: impl FnOnce() -> T + Send) -> PyResult<T> {
    py.detach(|| std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)))
        .map_err(panic_error)
}

/// How often a waiting call looks for Ctrl-C.
const SIGNAL_POLL: std::time::Duration = std::time::Duration::from_millis(50);

/// Runs `f` (a long computation: a simulation, a batch, a study) on a worker thread while the
/// calling thread waits without the GIL in intervals of [`SIGNAL_POLL`], running Python's
/// signal handlers in between: Ctrl-C raises `KeyboardInterrupt` at once. The abandoned worker
/// cannot be stopped (the library has no cancellation): it finishes in the background and its
/// result is dropped, nothing of it is returned. A panic becomes [`SolverError`].
pub(crate) fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    f: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    use std::sync::mpsc::{RecvTimeoutError, sync_channel};
    let (tx, rx) = sync_channel(1);
    std::thread::Builder::new()
        .name("pounding-run".into())
        .stack_size(16 << 20)
        .spawn(move || {
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
            let _ = tx.send(r); // the caller may be gone (interrupted): drop the result
        })
        .map_err(|e| SolverError::new_err(format!("cannot start the worker thread: {e}")))?;
    let rx = std::sync::Mutex::new(rx);
    loop {
        let got = py.detach(|| {
            rx.lock()
                .map_err(|_| RecvTimeoutError::Disconnected)
                .and_then(|r| r.recv_timeout(SIGNAL_POLL))
        });
        match got {
            Ok(r) => return r.map_err(panic_error),
            Err(RecvTimeoutError::Timeout) => py.check_signals()?,
            Err(RecvTimeoutError::Disconnected) => {
                return Err(SolverError::new_err(
                    "internal error in pounding: the worker thread ended without a result",
                ));
            }
        }
    }
}

/// A rayon pool of `threads` workers (all cores when `None`), checked as the CLI's `--threads`.
pub(crate) fn pool(threads: Option<usize>) -> PyResult<rayon::ThreadPool> {
    pounding::input::check_threads(threads).map_err(value_error)?;
    let mut b = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        b = b.num_threads(n);
    }
    b.build()
        .map_err(|e| SolverError::new_err(format!("cannot start the worker threads: {e}")))
}

/// The compiled core of the `pounding` Python package.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SolverError", m.py().get_type::<SolverError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    lcp::register(m)?;
    impact::register(m)?;
    study::register(m)?;
    sim::register(m)?;
    columns::register(m)?;
    assess::register(m)?;
    design::register(m)?;
    motion::register(m)?;
    compare::register(m)?;
    campaign::register(m)?;
    Ok(())
}
