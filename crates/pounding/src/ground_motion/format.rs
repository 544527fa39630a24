//! Which reader a record file goes to, decided in this one place ([`detect`]) from the file's
//! extension and content, and the options of reading ([`ReadOptions`]).
//!
//! | file | format |
//! |---|---|
//! | `.VT2`, `.DT2` | refused: PEER velocity / displacement series |
//! | `.AT2` (any case), or `NPTS` in one of the first four lines | PEER `.AT2` ([`Record::from_at2_str`]) |
//! | a comma in the first data line, or `.csv` with a header | CSV `t, a` ([`Record::from_csv_str`]) |
//! | a sample interval given (`record_dt`, `--record-dt`) | accelerations in order ([`Record::from_sequence_str`]) |
//! | two numbers on the first data line | columns `t a` ([`Record::from_columns_str`]) |
//! | anything else | refused, listing [`ACCEPTED_FORMATS`] |
//!
//! Data lines are those neither blank nor starting with `#`; `#` lines of the text formats are
//! read as headers (kind and units checked). A sample interval given for a file that carries its
//! own times (`.AT2`, CSV, columns `t a`) is refused, not ignored, unless it is only a default
//! ([`ReadOptions::dt_default`]: the scenario's `record_dt` for a command-line file). A leading
//! byte-order mark is ignored.

use super::{
    AccelUnits, BUILTIN_RECORDS, GroundMotionError, Record, builtin_record, data_lines, parse_err,
    parse_real, quote, strip_bom,
};
use crate::math::Real;
use std::path::Path;

/// The formats a record file may have, as listed in the error for a file that has none of them.
pub const ACCEPTED_FORMATS: &str = "accepted record formats: PEER .AT2 (a header whose 4th line \
     gives NPTS and DT); CSV `t, a` (two comma-separated columns, an optional header line); two \
     whitespace-separated columns `t a` (optional `#` comment lines); one column of \
     accelerations (any number of values a line, as OpenSees' timeSeries Path -dt reads them) \
     with its sample interval given by record_dt (scenario) or --record-dt";

/// The format of a record file ([`detect`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RecordFormat {
    /// PEER NGA `.AT2`: header with `NPTS` and `DT`, units from the header.
    At2,
    /// CSV `t, a`.
    Csv,
    /// Whitespace-separated columns `t a`.
    Columns,
    /// Accelerations in order with a given sample interval.
    Sequence,
}

/// How to read a record file: the units of text formats (CSV, columns, sequence; an `.AT2`
/// header names its own) and the sample interval of a sequence, with where each came from (for
/// the units label and messages).
#[derive(Debug, Clone, PartialEq)]
pub struct ReadOptions {
    /// Units of the values of text formats.
    pub units: AccelUnits,
    /// Where `units` came from: `csv_units default`, `csv_units`, `--csv-units`.
    pub units_from: String,
    /// The sample interval \[s\] of a one-column file (`None`: not given).
    pub dt: Option<Real>,
    /// Where `dt` came from, for messages: `record_dt` or `--record-dt`.
    pub dt_from: String,
    /// `dt` is a default (the scenario's `record_dt` applied to a `--record` / `--records` file):
    /// it reads one-column files and does not apply to files with their own times (`.AT2`, CSV,
    /// built-in records), which are then read without it instead of refused.
    pub dt_default: bool,
}

impl Default for ReadOptions {
    /// `g` (the `csv_units` default), no sample interval.
    fn default() -> Self {
        Self {
            units: AccelUnits::G,
            units_from: "csv_units default".into(),
            dt: None,
            dt_from: "record_dt".into(),
            dt_default: false,
        }
    }
}

/// The format of the record file `path` with content `text` (see the module table).
/// `dt_given`: a sample interval was given. Errors name the file and line.
pub fn detect(path: &Path, text: &str, dt_given: bool) -> Result<RecordFormat, GroundMotionError> {
    let text = strip_bom(text);
    let name = path.display().to_string();
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    let is = |e: &str| ext.eq_ignore_ascii_case(e);
    if is("VT2") || is("DT2") {
        return Err(parse_err(
            &name,
            1,
            format!(
                "a .{ext} file is a PEER velocity or displacement time series, not an \
                 acceleration record; give the .AT2 file of the same record"
            ),
        ));
    }
    let header_npts = text
        .lines()
        .take(4)
        .any(|l| l.to_ascii_uppercase().contains("NPTS"));
    let first = data_lines(text).next();
    if is("AT2") || (!is("csv") && header_npts) {
        return Ok(RecordFormat::At2);
    }
    let comma = first.is_some_and(|(_, l)| l.contains(','));
    let numeric = first.is_some_and(|(_, l)| l.split_whitespace().all(|t| parse_real(t).is_some()));
    // a `.csv` of one column of numbers goes on to the one-column rules below
    if comma || (is("csv") && !numeric) {
        return Ok(RecordFormat::Csv);
    }
    let Some((line, first)) = first else {
        return Err(parse_err(
            &name,
            1,
            format!("no samples found; {ACCEPTED_FORMATS}"),
        ));
    };
    let toks: Vec<&str> = first.split_whitespace().collect();
    if toks.iter().any(|t| parse_real(t).is_none()) {
        return Err(parse_err(
            &name,
            line,
            format!(
                "cannot recognise the format of the record from {}; {ACCEPTED_FORMATS}",
                quote(first)
            ),
        ));
    }
    match toks.len() {
        _ if dt_given => Ok(RecordFormat::Sequence),
        2 => Ok(RecordFormat::Columns),
        n => Err(parse_err(
            &name,
            line,
            format!(
                "{n} value{} a line and no sample interval: a file of accelerations without \
                 times needs its sample interval, record_dt = SECONDS in [ground_motion] or \
                 --record-dt SECONDS; {ACCEPTED_FORMATS}",
                if n == 1 { "" } else { "s" }
            ),
        )),
    }
}

impl Record {
    /// Reads a record file in the format [`detect`] finds, converting to m/s² (text formats in
    /// `opts.units`), labelled with the units as read ([`Record::units`]). A sample interval
    /// given for a file with its own times (`.AT2`, CSV, columns `t a`) is an error.
    pub fn from_path_with(path: &Path, opts: &ReadOptions) -> Result<Self, GroundMotionError> {
        let text =
            crate::input::read_text(path, "ground-motion record", crate::input::RECORD_LIMIT)
                .map_err(|e| GroundMotionError::Io {
                    path: path.display().to_string(),
                    message: e.to_string(),
                })?;
        let text = strip_bom(&text);
        let name = path.display().to_string();
        let format = detect(path, text, opts.dt.is_some())?;
        let own;
        let opts = if opts.dt_default && format != RecordFormat::Sequence {
            // the scenario's record_dt does not apply to a file with its own times
            own = ReadOptions {
                dt: None,
                dt_default: false,
                ..opts.clone()
            };
            &own
        } else {
            opts
        };
        if let Some(dt) = opts.dt
            && format != RecordFormat::Sequence
        {
            let what = match format {
                RecordFormat::At2 => "a PEER .AT2 record with its own DT",
                _ => "a CSV record with its own times (t, a)",
            };
            return Err(parse_err(
                &name,
                1,
                format!(
                    "a sample interval of {} s is given by {} but the file is {what}: it does \
                     not apply; remove it",
                    crate::output::float_token(dt),
                    opts.dt_from
                ),
            ));
        }
        let u = opts.units;
        let r = match (format, opts.dt) {
            (RecordFormat::At2, _) => {
                let given = (opts.units_from != ReadOptions::default().units_from)
                    .then_some((u, opts.units_from.as_str()));
                return Self::from_at2_str_with(text, &name, given);
            }
            (RecordFormat::Csv, _) => Self::from_csv_str(text, &name, u)?,
            (RecordFormat::Sequence, Some(dt)) => {
                Self::sequence_from(text, &name, u, (dt, &opts.dt_from))?
            }
            _ => Self::from_columns_str(text, &name, u)?,
        };
        let label = format!("{} ({})", u.name(), opts.units_from);
        Ok(r.with_units_label(label))
    }

    /// A record named on the command line or in a batch: `builtin:ELC180` / `builtin:ELC270`
    /// ([`builtin_record`]), else the file `path` ([`Record::from_path_with`]). A sample interval
    /// given explicitly (not [`ReadOptions::dt_default`]) for a built-in record is an error.
    pub fn open_with(path: &Path, opts: &ReadOptions) -> Result<Self, GroundMotionError> {
        let Some(b) = path.to_str().and_then(|s| s.strip_prefix("builtin:")) else {
            return Self::from_path_with(path, opts);
        };
        let io = |message: String| GroundMotionError::Io {
            path: path.display().to_string(),
            message,
        };
        if opts.dt.is_some() && !opts.dt_default {
            return Err(io(format!(
                "{} does not apply to a built-in record (it has its own DT)",
                opts.dt_from
            )));
        }
        builtin_record(b)
            .ok_or_else(|| io(format!("unknown built-in record: use {BUILTIN_RECORDS}")))
    }

    /// Reads a record file ([`Record::from_path_with`]) with text formats in `csv_units` and no
    /// sample interval.
    pub fn from_path(path: &Path, csv_units: AccelUnits) -> Result<Self, GroundMotionError> {
        let opts = ReadOptions {
            units: csv_units,
            units_from: "csv_units".into(),
            ..ReadOptions::default()
        };
        Self::from_path_with(path, &opts)
    }
}
