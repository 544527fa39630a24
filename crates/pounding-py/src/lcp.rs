//! `pounding.lcp`: Lemke and enumeration on numpy arrays (as `pounding lcp solve`).

use crate::value_error;
use numpy::{PyArray1, PyArray2, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pounding::lcp::{LcpProblem, Lemke, LemkeSettings, enumerate};
use pyo3::prelude::*;

/// Checks the shapes of `M` (n × n) and `q` (n) and builds the problem (finite entries).
fn problem(
    m: &PyReadonlyArrayDyn<'_, f64>,
    q: &PyReadonlyArrayDyn<'_, f64>,
) -> PyResult<LcpProblem> {
    let ms = m.shape();
    if ms.len() != 2 || ms[0] != ms[1] {
        return Err(value_error(format!(
            "invalid LCP: M must be a square 2-D array (n, n), got shape {ms:?}"
        )));
    }
    let qs = q.shape();
    if qs.len() != 1 || qs[0] != ms[0] {
        return Err(value_error(format!(
            "invalid LCP: q must be a 1-D array of length n = {} (M is {}x{}), got shape {qs:?}",
            ms[0], ms[0], ms[1]
        )));
    }
    let mv: Vec<f64> = m.as_array().iter().copied().collect();
    let qv: Vec<f64> = q.as_array().iter().copied().collect();
    LcpProblem::new(mv, qv).map_err(value_error)
}

/// `(z, w, status name, pivots, residual)`.
type Solved<'py> = (
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<f64>>,
    &'static str,
    usize,
    f64,
);

/// Solves `w = M z + q, z >= 0, w >= 0, z'w = 0` with the lexicographic Lemke solver of
/// `pounding lcp solve` (default settings). Returns `(z, w, status, pivots, residual)`; a
/// failed solve is a status, not an exception.
#[pyfunction]
fn lcp_solve<'py>(
    py: Python<'py>,
    m: PyReadonlyArrayDyn<'py, f64>,
    q: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<Solved<'py>> {
    let p = problem(&m, &q)?;
    let s = if p.dim() <= 16 {
        Lemke::new(LemkeSettings::default()).solve(&p)
    } else {
        crate::heavy(py, || Lemke::new(LemkeSettings::default()).solve(&p))?
    };
    Ok((
        PyArray1::from_vec(py, s.z),
        PyArray1::from_vec(py, s.w),
        s.status.name(),
        s.pivots,
        s.residual,
    ))
}

/// Every solution of the LCP by enumeration of complementary bases (`--solver enum`, n <= 12):
/// a `(k, n)` array, `k = 0` when there is none.
#[pyfunction]
fn lcp_enumerate<'py>(
    py: Python<'py>,
    m: PyReadonlyArrayDyn<'py, f64>,
    q: PyReadonlyArrayDyn<'py, f64>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let p = problem(&m, &q)?;
    let n = p.dim();
    if n > 12 {
        return Err(value_error(format!(
            "invalid LCP: enumeration needs n <= 12, got n = {n} (use pounding.lcp.solve)"
        )));
    }
    let sols = crate::heavy(py, || enumerate(&p))?.map_err(value_error)?;
    let k = sols.len();
    let flat: Vec<f64> = sols.into_iter().flatten().collect();
    let a = numpy::ndarray::Array2::from_shape_vec((k, n), flat)
        .map_err(|e| crate::SolverError::new_err(e.to_string()))?;
    Ok(PyArray2::from_owned_array(py, a))
}

/// Registers the LCP functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(lcp_solve, m)?)?;
    m.add_function(wrap_pyfunction!(lcp_enumerate, m)?)?;
    Ok(())
}
