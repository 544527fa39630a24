//! A run's tables handed to Python as columns (no text in between) and, for a result rebuilt
//! from its columns (an unpickled `SimulationResult`), their CSV text again by the library's one
//! writer ([`pounding::sim::table::csv_lines`]).

use crate::value_error;
use numpy::{PyArray1, PyArray2, PyReadonlyArray1};
use pounding::sim::table::{Column, ColumnData, Table, TypedTable};
use pyo3::prelude::*;
use pyo3::types::PyList;

/// A numeric table as `(name, column headers, float64 array (rows, columns))`.
#[allow(clippy::type_complexity)]
pub(crate) fn float_table<'py>(
    py: Python<'py>,
    t: Table,
) -> PyResult<(String, Vec<String>, Bound<'py, PyArray2<f64>>)> {
    let heads: Vec<String> = t.columns.iter().map(|c| c.header()).collect();
    let a = numpy::ndarray::Array2::from_shape_vec((t.rows(), heads.len()), t.values)
        .map_err(|e| crate::SolverError::new_err(e.to_string()))?;
    Ok((t.name.to_string(), heads, PyArray2::from_owned_array(py, a)))
}

/// The columns of `t` as `(header, values)`: float64 and int64 arrays, lists of str.
pub(crate) fn typed_columns<'py>(
    py: Python<'py>,
    t: TypedTable,
) -> PyResult<Vec<(String, Bound<'py, PyAny>)>> {
    t.columns
        .iter()
        .zip(t.data)
        .map(|(c, d)| {
            let v = match d {
                ColumnData::Real(v) => PyArray1::from_vec(py, v).into_any(),
                ColumnData::Int(v) => PyArray1::from_vec(py, v).into_any(),
                ColumnData::Text(v) => PyList::new(py, v)?.into_any(),
            };
            Ok((c.header(), v))
        })
        .collect()
}

/// The CSV text of columns `values` under `headers`, by the library's one writer of a run's
/// tables (the text of `history.csv` or `impacts.csv` again from their columns): each column a
/// float64 or int64 array or a list of str, all of one length.
#[pyfunction]
pub(crate) fn table_csv(headers: Vec<String>, values: Vec<Bound<'_, PyAny>>) -> PyResult<String> {
    if headers.len() != values.len() {
        return Err(value_error(format!(
            "{} headers for {} columns",
            headers.len(),
            values.len()
        )));
    }
    let mut t = TypedTable::new("table");
    for (h, v) in headers.into_iter().zip(&values) {
        let data = if let Ok(a) = v.extract::<PyReadonlyArray1<'_, f64>>() {
            ColumnData::Real(a.as_array().iter().copied().collect())
        } else if let Ok(a) = v.extract::<PyReadonlyArray1<'_, i64>>() {
            ColumnData::Int(a.as_array().iter().copied().collect())
        } else if let Ok(a) = v.extract::<Vec<String>>() {
            ColumnData::Text(a)
        } else {
            return Err(value_error(format!(
                "column {h}: not a 1-D float64 or int64 array or a list of str"
            )));
        };
        if t.data.first().is_some_and(|d| d.len() != data.len()) {
            return Err(value_error(format!(
                "column {h} has {} values, the first {}",
                data.len(),
                t.rows()
            )));
        }
        t.push(Column::new(h, ""), data);
    }
    Ok(t.csv())
}

/// Registers [`table_csv`].
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(table_csv, m)?)?;
    Ok(())
}
