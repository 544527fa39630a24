//! `pounding.batch`: every record at every scale, or every pair of a record-set manifest, run
//! in parallel; the text of `batch.csv`.

use super::{ArrayRecord, Flags, array_record, check_tables, load, units};
use crate::value_error;
use pounding::ground_motion::set::RecordSet;
use pounding::ground_motion::{ReadOptions, Record};
use pounding::shard::Shard;
use pounding::sim::Problem;
use pounding::sim::SimSettings;
use pounding::sim::batch::{BatchRecord, BatchRow, run_batch};
use pounding::sim::output as so;
use pyo3::prelude::*;
use std::path::PathBuf;

/// Runs a batch: every record (a path, or samples `(name, values, dt)`) at every scale, or every
/// entry of the record-set manifest `record_set` (pairs along y and x, as `pounding simulate
/// --set`), in parallel on `threads` workers; returns the text of `batch.csv`.
#[pyfunction]
#[pyo3(signature = (path=None, text=None, origin="scenario", records=Vec::new(), arrays=Vec::new(), scales=Vec::new(), csv_units=None, record_dt=None, dt=None, duration=None, law=None, threads=None, record_set=None))]
#[allow(clippy::too_many_arguments)]
pub(super) fn batch_run(
    py: Python<'_>,
    path: Option<&str>,
    text: Option<String>,
    origin: &str,
    records: Vec<Option<PathBuf>>,
    arrays: Vec<Option<ArrayRecord>>,
    scales: Vec<f64>,
    csv_units: Option<&str>,
    record_dt: Option<f64>,
    dt: Option<f64>,
    duration: Option<f64>,
    law: Option<String>,
    threads: Option<usize>,
    record_set: Option<PathBuf>,
) -> PyResult<String> {
    if let Some(m) = &record_set {
        if !records.is_empty() || !arrays.is_empty() {
            return Err(value_error(
                "give records or a record_set (a manifest of pairs), not both",
            ));
        }
        if record_dt.is_some() {
            return Err(value_error(format!(
                "record_dt applies to the record files of records; the one-column records of \
                 the manifest {} give their sample interval in their entry (dt = SECONDS)",
                m.display()
            )));
        }
    }
    let csv_units = units(csv_units)?;
    let flags = Flags {
        record: None,
        csv_units,
        record_dt,
        scale: None,
        dt,
        duration,
        law,
        batch: true,
        projection: false,
    };
    let sc = flags.apply(load(path, text, origin)?);
    let reading: ReadOptions = sc.override_reading(csv_units).map_err(value_error)?;
    let (list, set) = match &record_set {
        Some(m) => {
            let set = RecordSet::load_with_units(m, reading.units, &reading.units_from)
                .map_err(value_error)?;
            (BatchRecord::of_set(&set), Some(set))
        }
        None => (record_list(records, arrays, &reading)?, None),
    };
    let pool = crate::pool(threads)?;
    let setup = sc.build_setup().map_err(value_error)?;
    let (layout, n) = (setup.layout(), setup.model().segments.len());
    check_tables(&sc, Some(n))?;
    if let Some(m) = &record_set {
        let what = match layout {
            so::Layout::TwoDecks => "a two-deck scenario".to_string(),
            so::Layout::Bridge => sc.origin().to_string(),
        };
        pounding::sim::batch_supports::check_set_supports(&setup, &list, m, &what)
            .map_err(value_error)?;
    }
    let settings = setup.settings().clone();
    let rows = batch_rows(py, pool, setup, settings, list, scales)?;
    Ok(match &set {
        Some(set) => so::batch_set_csv(layout, n, &rows, set),
        None => so::batch_csv(layout, n, &rows),
    })
}

/// The one-component entries of a batch: each record a path (read as the CLI reads it; an
/// unreadable one keeps its error) or samples.
fn record_list(
    records: Vec<Option<PathBuf>>,
    arrays: Vec<Option<ArrayRecord>>,
    reading: &ReadOptions,
) -> PyResult<Vec<BatchRecord>> {
    let mut list = Vec::with_capacity(records.len().max(arrays.len()));
    for (p, a) in records.into_iter().zip(arrays) {
        list.push(match (p, a) {
            (Some(p), _) => BatchRecord::single(
                p.display().to_string(),
                Record::open_with(&p, reading).map_err(|e| e.to_string()),
            ),
            (None, Some(a)) => {
                BatchRecord::single(a.0.clone(), Ok(array_record(a, reading.units)?))
            }
            (None, None) => return Err(value_error("a record is neither a path nor an array")),
        });
    }
    Ok(list)
}

/// Runs every record of `list` at every scale on `problem` (two decks or a bridge) in `pool`, off
/// the Python thread (interruptible): the rows in input order.
fn batch_rows<P>(
    py: Python<'_>,
    pool: rayon::ThreadPool,
    problem: P,
    settings: SimSettings,
    list: Vec<BatchRecord>,
    scales: Vec<f64>,
) -> PyResult<Vec<BatchRow>>
where
    P: pounding::sim::Problem + Send + 'static,
{
    crate::interruptible(py, move || {
        pool.install(|| run_batch(&problem, &settings, &list, &scales, Shard::ALL, &|_| {}))
    })?
    .map_err(value_error)
}
