//! Record sets: a TOML manifest listing ground-motion records, single or as horizontal pairs,
//! with free metadata carried into the outputs of a fragility study.
//!
//! ```toml
//! [set]
//! name = "synthetic"            # optional free text
//! source = "..."                # optional provenance
//!
//! [[record]]
//! id = "SYN001"                 # unique id used in outputs (required)
//! x = "SYN001_x.AT2"            # path relative to the manifest, or builtin:ELC180 / builtin:ELC270
//! y = "SYN001_y.AT2"            # optional second horizontal component: makes a pair
//! dt = 0.01                     # optional, for one-column files (as record_dt)
//! units = "g"                   # optional, for text files (as csv_units): "g" | "m/s2"
//!
//! [record.meta]                 # optional free metadata (strings, numbers, booleans;
//!                               # output columns in alphabetical order)
//! magnitude = 6.9
//! ```
//!
//! A metadata name must not repeat a column of `runs.csv` (`record`, `level_g`, `scale`,
//! `im_g`, `scale_factor`, `status`, `error`, or a name ending in `_exceeded` / `_ratio`): such a
//! manifest is refused, naming `record[i].meta.KEY` and the line of its table.
//!
//! Every record file is read once (a file named by several entries is shared). Errors name the
//! manifest, the key and its line, and the record file; every entry is read before the errors
//! are reported, so that all missing or bad files are named at once. Unknown keys, duplicate
//! ids, and a pair whose components have different sample intervals are refused.

use super::{
    AccelUnits, EL_CENTRO_180_AT2, EL_CENTRO_270_AT2, GroundMotionError, ReadOptions, Record,
};
use crate::math::Real;
use crate::toml_schema::line_col;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use toml::Spanned;

#[path = "set_synth.rs"]
mod synth_set;

/// A metadata value of a record (`[record.meta]`).
#[derive(Debug, Clone, PartialEq)]
pub enum MetaValue {
    /// Text.
    Text(String),
    /// A number (integers are kept as written).
    Number(Real),
    /// An integer.
    Integer(i64),
    /// A boolean.
    Bool(bool),
}

impl MetaValue {
    /// The value as a CSV cell (text quoted when needed, numbers shortest round-trip).
    pub fn csv_cell(&self) -> String {
        match self {
            MetaValue::Text(s) => crate::output::csv_field(s),
            MetaValue::Number(x) => crate::output::float_token(*x),
            MetaValue::Integer(i) => i.to_string(),
            MetaValue::Bool(b) => b.to_string(),
        }
    }
}

/// One entry of a record set: a record, or a horizontal pair.
#[derive(Debug, Clone, PartialEq)]
pub struct SetRecord {
    /// The unique id used in outputs.
    pub id: String,
    /// The first horizontal component (m/s²).
    pub x: Record,
    /// The second horizontal component of a pair (m/s²).
    pub y: Option<Record>,
    /// Metadata, in alphabetical order of the names.
    pub meta: Vec<(String, MetaValue)>,
}

/// A record set read from a manifest ([`RecordSet::load`]).
#[derive(Debug, Clone, PartialEq)]
pub struct RecordSet {
    /// `[set] name` (empty when not given).
    pub name: String,
    /// `[set] source` (empty when not given).
    pub source: String,
    /// The entries in the manifest's order.
    pub records: Vec<SetRecord>,
}

/// Why a manifest cannot be used. Nothing has been computed.
#[derive(Debug, thiserror::Error)]
pub enum SetError {
    /// The manifest cannot be read.
    #[error("cannot read record set {path}: {message}")]
    Read {
        /// The path as given.
        path: String,
        /// The reason.
        message: String,
    },
    /// Syntax, an unknown key or a wrong type (the message names line and column).
    #[error("invalid record set {origin}: {message}")]
    Syntax {
        /// The manifest's name.
        origin: String,
        /// The TOML reader's message.
        message: String,
    },
    /// Bad values or unreadable record files: one line per problem, each naming the key and
    /// its line (and the record file).
    #[error("record set {origin}: {}", .problems.join("; "))]
    Invalid {
        /// The manifest's name.
        origin: String,
        /// `record[i].key (FILE:LINE): message`, one per problem.
        problems: Vec<String>,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Manifest {
    #[serde(default)]
    set: Option<crate::toml_schema::Table<SetSec>>,
    #[serde(default)]
    record: Vec<Spanned<RecordSec>>,
    #[serde(default)]
    synth: Option<Spanned<crate::toml_schema::Table<synth_set::SynthSec>>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct SetSec {
    name: Option<String>,
    source: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RecordSec {
    id: Spanned<String>,
    x: Spanned<String>,
    y: Option<Spanned<String>>,
    dt: Option<Spanned<Real>>,
    units: Option<Spanned<String>>,
    #[serde(default)]
    meta: Option<Spanned<toml::Table>>,
}

/// Reading context: the manifest's name, text and directory.
struct Ctx<'a> {
    origin: &'a str,
    text: &'a str,
    dir: &'a Path,
}

impl Ctx<'_> {
    fn at<T>(&self, i: usize, key: &str, s: &Spanned<T>) -> String {
        let (line, _) = line_col(self.text, s.span().start);
        format!("record[{i}].{key} ({}:{line})", self.origin)
    }
}

impl RecordSet {
    /// Reads the manifest `path` and every record it names (paths relative to its directory).
    pub fn load(path: &Path) -> Result<Self, SetError> {
        let text = crate::input::read_text(path, "record set", crate::input::SCENARIO_LIMIT)
            .map_err(|e| SetError::Read {
                path: path.display().to_string(),
                message: e.to_string(),
            })?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Self::from_toml(&text, &path.display().to_string(), &dir)
    }

    /// Reads a manifest from `text`, named `origin` in messages, record paths relative to `dir`.
    pub fn from_toml(text: &str, origin: &str, dir: &Path) -> Result<Self, SetError> {
        let m: Manifest = toml::from_str(text).map_err(|e| SetError::Syntax {
            origin: origin.to_string(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let cx = Ctx { origin, text, dir };
        let set = m.set.map(|s| s.0).unwrap_or_default();
        if let Some(sy) = &m.synth {
            let (line, _) = line_col(text, sy.span().start);
            let problems = if m.record.is_empty() {
                match synth_set::records(&cx, sy.get_ref(), sy.span().start) {
                    Ok((records, source)) => {
                        return Ok(Self {
                            name: set.name.unwrap_or_else(|| "synthetic".into()),
                            source: set.source.unwrap_or(source),
                            records,
                        });
                    }
                    Err(p) => p,
                }
            } else {
                vec![format!(
                    "synth ({origin}:{line}): a manifest lists [[record]]s or generates them \
                     with [synth], not both"
                )]
            };
            return Err(SetError::Invalid {
                origin: origin.to_string(),
                problems,
            });
        }
        let mut problems = Vec::new();
        if m.record.is_empty() {
            problems.push(
                "no [[record]] tables: list at least one record (or generate a synthetic \
                 suite with [synth])"
                    .to_string(),
            );
        }
        let mut cache: BTreeMap<(String, Option<String>, String), Result<Record, String>> =
            BTreeMap::new();
        let mut ids: BTreeMap<String, usize> = BTreeMap::new();
        let mut records = Vec::new();
        for (i, r) in m.record.iter().enumerate() {
            let r = r.get_ref();
            let id = r.id.get_ref().trim().to_string();
            if id.is_empty() || id.contains(['\n', '\r']) {
                problems.push(format!(
                    "{}: must be non-empty text on one line",
                    cx.at(i, "id", &r.id)
                ));
            } else if let Some(j) = ids.insert(id.clone(), i) {
                problems.push(format!(
                    "{}: duplicate id {id:?} (also record[{j}])",
                    cx.at(i, "id", &r.id)
                ));
            }
            match entry(&cx, i, r, &mut cache) {
                Ok(rec) => records.push(rec),
                Err(mut p) => problems.append(&mut p),
            }
        }
        if !problems.is_empty() {
            return Err(SetError::Invalid {
                origin: origin.to_string(),
                problems,
            });
        }
        Ok(Self {
            name: set.name.unwrap_or_default(),
            source: set.source.unwrap_or_default(),
            records,
        })
    }

    /// The metadata names of all records, sorted (the metadata columns of outputs).
    pub fn meta_keys(&self) -> Vec<String> {
        let keys: std::collections::BTreeSet<&String> = self
            .records
            .iter()
            .flat_map(|r| r.meta.iter().map(|(k, _)| k))
            .collect();
        keys.into_iter().cloned().collect()
    }
}

type Cache = BTreeMap<(String, Option<String>, String), Result<Record, String>>;

/// One `[[record]]` entry: its components read (through `cache`), checked and its metadata.
fn entry(cx: &Ctx, i: usize, r: &RecordSec, cache: &mut Cache) -> Result<SetRecord, Vec<String>> {
    let mut problems = Vec::new();
    let mut opts = ReadOptions {
        dt_from: format!("record[{i}].dt"),
        units_from: format!("record[{i}].units"),
        ..ReadOptions::default()
    };
    if let Some(u) = &r.units {
        match AccelUnits::from_name(u.get_ref()) {
            Some(units) => opts.units = units,
            None => problems.push(format!(
                "{}: unknown units {:?} (use \"g\" or \"m/s2\")",
                cx.at(i, "units", u),
                u.get_ref()
            )),
        }
    } else {
        opts.units_from = "units default".into();
    }
    if let Some(dt) = &r.dt {
        let v = *dt.get_ref();
        if !(v.is_finite() && v > 0.0) {
            problems.push(format!(
                "{}: invalid dt = {}: must be finite and > 0",
                cx.at(i, "dt", dt),
                crate::output::float_token(v)
            ));
        } else {
            opts.dt = Some(v);
        }
    }
    let meta = match &r.meta {
        Some(t) => meta_values(cx, i, t, &mut problems),
        None => Vec::new(),
    };
    if !problems.is_empty() {
        return Err(problems);
    }
    let mut read = |key: &str, s: &Spanned<String>| -> Option<Record> {
        let k = (
            s.get_ref().clone(),
            opts.dt.map(|d| d.to_string()),
            opts.units_from.clone(),
        );
        let got = cache
            .entry(k)
            .or_insert_with(|| read_component(cx.dir, s.get_ref(), &opts))
            .clone();
        got.map_err(|e| problems.push(format!("{}: {}", cx.at(i, key, s), in_manifest(&e))))
            .ok()
    };
    let x = read("x", &r.x);
    let y = r.y.as_ref().map(|y| (y, read("y", y)));
    let (Some(x), y) = (x, y) else {
        return Err(problems);
    };
    let y = match y {
        None => None,
        Some((_, None)) => return Err(problems),
        Some((ys, Some(yr))) => {
            if let (Some(a), Some(b)) = (x.dt(), yr.dt())
                && (a - b).abs() > 1e-9 * a.max(b)
            {
                problems.push(format!(
                    "{}: the pair's components have different sample intervals: x {} s, y {} s",
                    cx.at(i, "y", ys),
                    crate::output::float_token(a),
                    crate::output::float_token(b)
                ));
                return Err(problems);
            }
            Some(yr)
        }
    };
    Ok(SetRecord {
        id: r.id.get_ref().trim().to_string(),
        x,
        y,
        meta,
    })
}

/// `[record.meta]`: strings, numbers and booleans, in alphabetical order of their names.
fn meta_values(
    cx: &Ctx,
    i: usize,
    t: &Spanned<toml::Table>,
    problems: &mut Vec<String>,
) -> Vec<(String, MetaValue)> {
    let (line, _) = line_col(cx.text, t.span().start);
    let at = |k: &str| format!("record[{i}].meta.{k} ({}: table at line {line})", cx.origin);
    let mut out = Vec::new();
    for (k, v) in t.get_ref() {
        let value = match v {
            toml::Value::String(s) => MetaValue::Text(s.clone()),
            toml::Value::Integer(n) => MetaValue::Integer(*n),
            toml::Value::Float(x) if x.is_finite() => MetaValue::Number(*x),
            toml::Value::Boolean(b) => MetaValue::Bool(*b),
            _ => {
                problems.push(format!(
                    "{}: must be text, a finite number or a boolean",
                    at(k)
                ));
                continue;
            }
        };
        if k.is_empty() || k.contains([',', '"', '\n', '\r']) {
            problems.push(format!(
                "{}: a metadata name becomes a column: no commas, quotes or line breaks",
                at(k)
            ));
            continue;
        }
        if let Some(why) = reserved_column(k) {
            problems.push(format!(
                "{}: {why}; rename the metadata (e.g. meta_{k})",
                at(k)
            ));
            continue;
        }
        out.push((k.clone(), value));
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// A record reader's message as it applies inside a manifest: the sample interval of a
/// one-column file is the entry's `dt` key there, not the scenario's `record_dt` or the
/// `--record-dt` flag.
fn in_manifest(message: &str) -> String {
    message
        .replace(
            "record_dt = SECONDS in [ground_motion] or --record-dt SECONDS",
            "dt = SECONDS in this [[record]] table of the manifest",
        )
        .replace(
            "given by record_dt (scenario) or --record-dt",
            "given by the entry's dt key (in a manifest)",
        )
}

/// The output columns of `runs.csv` that a metadata name must not repeat (a table reader would
/// return one of the two columns silently).
pub const RESERVED_COLUMNS: [&str; 7] = [
    "record",
    "level_g",
    "scale",
    "im_g",
    "scale_factor",
    "status",
    "error",
];

/// Why metadata name `k` would clash with a `runs.csv` column, if it would: a fixed column
/// ([`RESERVED_COLUMNS`]) or a name ending in `_exceeded` / `_ratio` (the per-limit-state columns).
fn reserved_column(k: &str) -> Option<String> {
    if RESERVED_COLUMNS.contains(&k) {
        return Some(format!(
            "{k:?} is an output column of runs.csv (reserved: {})",
            RESERVED_COLUMNS.join(", ")
        ));
    }
    ["_exceeded", "_ratio"]
        .iter()
        .find(|s| k.ends_with(*s))
        .map(|s| {
            format!("a name ending in {s} is reserved for the limit-state columns of runs.csv")
        })
}

/// Reads one component: `builtin:ELC180` / `builtin:ELC270` or a file relative to `dir`.
fn read_component(dir: &Path, spec: &str, opts: &ReadOptions) -> Result<Record, String> {
    let spec_t = spec.trim();
    if let Some(b) = spec_t.strip_prefix("builtin:") {
        let (text, name) = match b {
            "ELC180" => (EL_CENTRO_180_AT2, "RSN6_IMPVALL.I_I-ELC180-hor1.AT2"),
            "ELC270" => (EL_CENTRO_270_AT2, "RSN6_IMPVALL.I_I-ELC270-hor2.AT2"),
            other => {
                return Err(format!(
                    "unknown built-in record {other:?} (use builtin:ELC180 or builtin:ELC270)"
                ));
            }
        };
        if opts.dt.is_some() {
            return Err(format!(
                "{} applies to one-column files, but {spec_t} has its own DT: remove it",
                opts.dt_from
            ));
        }
        return Record::from_at2_str(text, name).map_err(|e| e.to_string());
    }
    if spec_t.is_empty() {
        return Err("empty path".into());
    }
    let p: PathBuf = dir.join(spec_t);
    Record::from_path_with(&p, opts).map_err(|e: GroundMotionError| e.to_string())
}
