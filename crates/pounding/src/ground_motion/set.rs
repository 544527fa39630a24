//! Record sets: a manifest listing ground-motion records, single or as horizontal pairs,
//! with free metadata carried into the outputs of a fragility study. A `.toml` manifest holds
//! `[[record]]` tables (below) or a `[synth]` table (`set_synth.rs`); a `.csv` manifest holds a
//! header row and one row per record, its columns the keys below and metadata (`set_csv.rs`).
//! Both are read into the same entries and checked and read by one function, so a CSV manifest
//! gives the record set of the equivalent TOML manifest (without `[set]`). Any other extension
//! is refused.
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
//!                               # (and an .AT2 whose header names none; else refused)
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

#[path = "set_csv.rs"]
mod csv_set;

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
    /// A motion per support of a bridge (`supports = "FILE"`, a support-motion file:
    /// [`crate::ground_motion::support_file`]), in its column order; empty for a record or a
    /// pair. `x` is then the `start` support's motion (else the first column's).
    pub supports: Vec<(String, Record)>,
}

/// The `model` metadata value that `pounding motion synth` (and a `[synth]` table) writes on
/// every record it generates: the mark by which a set's synthetic entries are known.
pub const SYNTHETIC_MODEL: &str = "kanai-tajimi-clough-penzien";

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
    /// The manifest's extension is neither `.toml` nor `.csv`.
    #[error(
        "record set {path}: unknown manifest type: the extension must be .toml ([[record]] \
         tables or [synth]) or .csv (a header row and one row per record)"
    )]
    Extension {
        /// The path as given.
        path: String,
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
    x: Option<Spanned<String>>,
    /// A support-motion file (one motion per support of a bridge) instead of `x` / `y`.
    supports: Option<Spanned<String>>,
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
    /// A CSV manifest (locations name a column; messages speak of cells, not keys).
    csv: bool,
    /// The byte offsets of the `\n`s of `text`, in order: the line of an offset is found by a
    /// binary search ([`Ctx::line`]), so that naming the line of every entry stays linear in the
    /// manifest's size (a scan from the start per entry made 20,000 entries take 40 s).
    breaks: Vec<usize>,
    /// The units of text records of entries without `units`, and where they come from (the
    /// scenario's `csv_units`): [`RecordSet::load_with_units`].
    units: (AccelUnits, String),
}

/// Where a value of a manifest entry is: its line and, in a CSV manifest, its column (0-based).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Loc {
    line: usize,
    col: Option<usize>,
}

/// A value of a manifest entry and where it is.
#[derive(Debug, Clone)]
struct Val<T> {
    v: T,
    at: Loc,
}

/// One record entry as written in the manifest, whatever its syntax (`[[record]]` table or CSV
/// row): the single path from which both kinds of manifest are checked and read ([`build`]).
struct Entry {
    id: Val<String>,
    x: Val<String>,
    /// A support-motion file instead of `x` / `y` (TOML manifests).
    supports: Option<Val<String>>,
    y: Option<Val<String>>,
    dt: Option<Val<Real>>,
    units: Option<Val<String>>,
    /// Metadata, checked (names and types) by the syntax's reader.
    meta: Vec<(String, MetaValue)>,
    /// What the syntax's reader refused in this entry's metadata.
    meta_problems: Vec<String>,
}

impl<'a> Ctx<'a> {
    fn new(origin: &'a str, text: &'a str, dir: &'a Path, csv: bool) -> Self {
        let breaks = text.bytes().enumerate().filter(|(_, b)| *b == b'\n');
        Self {
            origin,
            text,
            dir,
            csv,
            breaks: breaks.map(|(k, _)| k).collect(),
            units: (AccelUnits::G, "units default".into()),
        }
    }

    /// The 1-based line of byte offset `pos` (as [`line_col`] counts it).
    fn line(&self, pos: usize) -> usize {
        self.breaks.partition_point(|&b| b < pos) + 1
    }

    /// `record[i].KEY (FILE:LINE)`; in a CSV manifest `KEY (FILE:LINE, column C)` (the line
    /// of the row and the spreadsheet letter of the column).
    fn at(&self, i: usize, key: &str, at: Loc) -> String {
        match at.col {
            Some(c) if self.csv => {
                format!(
                    "{key} ({}:{}, column {})",
                    self.origin,
                    at.line,
                    column_name(c)
                )
            }
            _ if self.csv => format!("{key} ({}:{})", self.origin, at.line),
            _ => format!("record[{i}].{key} ({}:{})", self.origin, at.line),
        }
    }

    /// A TOML value with its line.
    fn val<T: Clone>(&self, s: &Spanned<T>) -> Val<T> {
        let line = self.line(s.span().start);
        Val {
            v: s.get_ref().clone(),
            at: Loc { line, col: None },
        }
    }
}

/// A spreadsheet's name of the 0-based column `c`: `A`, …, `Z`, `AA`, …
pub(crate) fn column_name(c: usize) -> String {
    let mut n = c + 1;
    let mut out = Vec::new();
    while n > 0 {
        out.push(b'A' + ((n - 1) % 26) as u8);
        n = (n - 1) / 26;
    }
    out.reverse();
    String::from_utf8(out).unwrap_or_default()
}

impl RecordSet {
    /// Reads the manifest `path` and every record it names (paths relative to its directory).
    /// The syntax follows the extension: `.toml` ([`RecordSet::from_toml`]) or `.csv`
    /// ([`RecordSet::from_csv`]), in any case; any other extension is refused.
    pub fn load(path: &Path) -> Result<Self, SetError> {
        Self::load_with_units(path, AccelUnits::G, "units default")
    }

    /// [`RecordSet::load`] with the units of text records whose entry gives no `units`: the
    /// scenario's `csv_units` (`units`, and `from` naming it in messages and in each record's
    /// reading line), so that a manifest reads a text record as `simulate --records` reads it
    /// under the same scenario.
    pub fn load_with_units(path: &Path, units: AccelUnits, from: &str) -> Result<Self, SetError> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        let csv = match ext.as_deref() {
            Some("toml") => false,
            Some("csv") => true,
            _ => {
                return Err(SetError::Extension {
                    path: path.display().to_string(),
                });
            }
        };
        let text = crate::input::read_text(path, "record set", crate::input::SCENARIO_LIMIT)
            .map_err(|e| SetError::Read {
                path: path.display().to_string(),
                message: e.to_string(),
            })?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let origin = path.display().to_string();
        let units = (units, from.to_string());
        if csv {
            Self::from_csv_units(&text, &origin, &dir, units)
        } else {
            Self::from_toml_units(&text, &origin, &dir, units)
        }
    }

    /// Reads a CSV manifest from `text` (a header row naming the columns `id`, `x`, and
    /// optionally `y`, `dt`, `units`; every other column is metadata; see `set_csv.rs`),
    /// named `origin` in messages, record paths relative to `dir`. The record set is the one the
    /// equivalent TOML manifest (without `[set]`) gives.
    pub fn from_csv(text: &str, origin: &str, dir: &Path) -> Result<Self, SetError> {
        Self::from_csv_units(text, origin, dir, (AccelUnits::G, "units default".into()))
    }

    /// [`RecordSet::from_csv`] with the default units of text records.
    fn from_csv_units(
        text: &str,
        origin: &str,
        dir: &Path,
        units: (AccelUnits, String),
    ) -> Result<Self, SetError> {
        let mut cx = Ctx::new(origin, text, dir, true);
        cx.units = units;
        let (entries, problems) = csv_set::entries(&cx);
        let records = build(&cx, &entries, problems).map_err(|problems| SetError::Invalid {
            origin: origin.to_string(),
            problems,
        })?;
        Ok(Self {
            name: String::new(),
            source: String::new(),
            records,
        })
    }

    /// Reads a manifest from `text`, named `origin` in messages, record paths relative to `dir`.
    pub fn from_toml(text: &str, origin: &str, dir: &Path) -> Result<Self, SetError> {
        Self::from_toml_units(text, origin, dir, (AccelUnits::G, "units default".into()))
    }

    /// [`RecordSet::from_toml`] with the default units of text records.
    fn from_toml_units(
        text: &str,
        origin: &str,
        dir: &Path,
        units: (AccelUnits, String),
    ) -> Result<Self, SetError> {
        let m: Manifest = toml::from_str(text).map_err(|e| SetError::Syntax {
            origin: origin.to_string(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let mut cx = Ctx::new(origin, text, dir, false);
        cx.units = units;
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
        let entries: Vec<Entry> = m
            .record
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let r = r.get_ref();
                let mut meta_problems = Vec::new();
                let meta = match &r.meta {
                    Some(t) => meta_values(&cx, i, t, &mut meta_problems),
                    None => Vec::new(),
                };
                let supports = r.supports.as_ref().map(|s| cx.val(s));
                let x = match (&r.x, &supports) {
                    (Some(x), _) => cx.val(x),
                    // a support-motion entry: `x` is its start support's motion
                    (None, Some(s)) => s.clone(),
                    (None, None) => {
                        meta_problems.push(format!(
                            "{}: give x (a record) or supports (a support-motion file)",
                            cx.at(i, "id", cx.val(&r.id).at)
                        ));
                        cx.val(&r.id)
                    }
                };
                Entry {
                    id: cx.val(&r.id),
                    x,
                    supports,
                    y: r.y.as_ref().map(|s| cx.val(s)),
                    dt: r.dt.as_ref().map(|s| cx.val(s)),
                    units: r.units.as_ref().map(|s| cx.val(s)),
                    meta,
                    meta_problems,
                }
            })
            .collect();
        let records = build(&cx, &entries, problems).map_err(|problems| SetError::Invalid {
            origin: origin.to_string(),
            problems,
        })?;
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

    /// The number of entries generated by the synthetic-motion generator: those whose `model`
    /// metadata is [`SYNTHETIC_MODEL`] (the generator writes it; a recorded motion has no such
    /// mark unless a user writes it).
    pub fn synthetic_entries(&self) -> usize {
        self.records
            .iter()
            .filter(|r| {
                r.meta
                    .iter()
                    .any(|(k, v)| k == "model" && *v == MetaValue::Text(SYNTHETIC_MODEL.into()))
            })
            .count()
    }

    /// The number of entries that are horizontal pairs (the others are single components).
    pub fn pair_entries(&self) -> usize {
        self.records.iter().filter(|r| r.y.is_some()).count()
    }
}

/// The entries checked and their records read (each file once), after the `problems` the
/// syntax's reader found; every entry is read before the problems are reported.
fn build(
    cx: &Ctx,
    entries: &[Entry],
    mut problems: Vec<String>,
) -> Result<Vec<SetRecord>, Vec<String>> {
    let mut cache = Cache::new();
    let mut ids: BTreeMap<String, usize> = BTreeMap::new();
    let mut records = Vec::new();
    for (i, r) in entries.iter().enumerate() {
        let id = r.id.v.trim().to_string();
        if id.is_empty() || id.contains(['\n', '\r']) {
            problems.push(format!(
                "{}: must be non-empty text on one line",
                cx.at(i, "id", r.id.at)
            ));
        } else if let Some(j) = ids.insert(id.clone(), i) {
            problems.push(format!(
                "{}: duplicate id {id:?} (also {})",
                cx.at(i, "id", r.id.at),
                if cx.csv {
                    format!("line {}", entries[j].id.at.line)
                } else {
                    format!("record[{j}]")
                }
            ));
        }
        match entry(cx, i, r, &mut cache) {
            Ok(rec) => records.push(rec),
            Err(mut p) => problems.append(&mut p),
        }
    }
    if problems.is_empty() {
        Ok(records)
    } else {
        Err(problems)
    }
}

type Cache = BTreeMap<(String, Option<String>, String), Result<Record, String>>;

/// One entry: its components read (through `cache`), checked and its metadata.
fn entry(cx: &Ctx, i: usize, r: &Entry, cache: &mut Cache) -> Result<SetRecord, Vec<String>> {
    let mut problems = Vec::new();
    let mut opts = ReadOptions {
        dt_from: if cx.csv {
            "the dt cell".into()
        } else {
            format!("record[{i}].dt")
        },
        units_from: format!("record[{i}].units"),
        ..ReadOptions::default()
    };
    if let Some(u) = &r.units {
        match AccelUnits::from_name(&u.v) {
            Some(units) => opts.units = units,
            None => problems.push(format!(
                "{}: unknown units {:?} (use \"g\" or \"m/s2\")",
                cx.at(i, "units", u.at),
                u.v
            )),
        }
    } else {
        opts.units = cx.units.0;
        opts.units_from = cx.units.1.clone();
    }
    if let Some(dt) = &r.dt {
        let v = dt.v;
        if !(v.is_finite() && v > 0.0) {
            problems.push(format!(
                "{}: invalid dt = {}: must be finite and > 0",
                cx.at(i, "dt", dt.at),
                crate::output::float_token(v)
            ));
        } else {
            opts.dt = Some(v);
        }
    }
    problems.extend(r.meta_problems.iter().cloned());
    if !problems.is_empty() {
        return Err(problems);
    }
    // a `units` that applies to no component of the entry would be silently ignored: refused;
    // in a pair it applies to the members that take units (a text file beside a built-in or
    // an .AT2 record with units in its header)
    let mut not_applying: Vec<String> = Vec::new();
    let mut read = |key: &str, s: &Val<String>| -> Option<Record> {
        let k = (
            s.v.clone(),
            opts.dt.map(|d| d.to_string()),
            opts.units_from.clone(),
        );
        let got = cache
            .entry(k)
            .or_insert_with(|| read_component(cx.dir, &s.v, &opts))
            .clone();
        let rec = got
            .map_err(|e| {
                problems.push(format!(
                    "{}: {}",
                    cx.at(i, key, s.at),
                    in_manifest(&e, cx.csv)
                ))
            })
            .ok()?;
        if r.units.is_some()
            && let Some(why) = units_do_not_apply(key, &s.v, &rec)
        {
            not_applying.push(why);
        }
        Some(rec)
    };
    if let Some(s) = &r.supports {
        return support_entry(cx, i, r, s, problems);
    }
    let x = read("x", &r.x);
    let y = r.y.as_ref().map(|y| (y, read("y", y)));
    let components = 1 + usize::from(r.y.is_some());
    if let Some(u) = &r.units
        && not_applying.len() == components
    {
        problems.push(format!(
            "{}: {}",
            cx.at(i, "units", u.at),
            not_applying.join("; and ")
        ));
        return Err(problems);
    }
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
                    cx.at(i, "y", ys.at),
                    crate::output::float_token(a),
                    crate::output::float_token(b)
                ));
                return Err(problems);
            }
            Some(yr)
        }
    };
    Ok(SetRecord {
        id: r.id.v.trim().to_string(),
        x,
        y,
        meta: r.meta.clone(),
        supports: Vec::new(),
    })
}

/// A support-motion entry: its file read (m/s², a header of support ids), no `x`, `y`, `dt`
/// or `units` beside it.
fn support_entry(
    cx: &Ctx,
    i: usize,
    r: &Entry,
    s: &Val<String>,
    mut problems: Vec<String>,
) -> Result<SetRecord, Vec<String>> {
    let here = cx.at(i, "supports", s.at);
    if r.x.at != s.at || r.y.is_some() || r.dt.is_some() || r.units.is_some() {
        problems.push(format!(
            "{here}: a support-motion file gives every support's motion (in m/s², with its own \
             times): remove x, y, dt and units from this entry"
        ));
        return Err(problems);
    }
    match super::support_file::read_support_motions(&cx.dir.join(s.v.trim())) {
        Err(e) => {
            problems.push(format!("{here}: {e}"));
            Err(problems)
        }
        Ok(cols) => {
            let start = cols
                .iter()
                .find(|(id, _)| id == "start")
                .unwrap_or(&cols[0]);
            Ok(SetRecord {
                id: r.id.v.trim().to_string(),
                x: start.1.clone(),
                y: None,
                meta: r.meta.clone(),
                supports: cols,
            })
        }
    }
}

/// `[record.meta]`: strings, numbers and booleans, in alphabetical order of their names.
fn meta_values(
    cx: &Ctx,
    i: usize,
    t: &Spanned<toml::Table>,
    problems: &mut Vec<String>,
) -> Vec<(String, MetaValue)> {
    let line = cx.line(t.span().start);
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
        if let Some(why) = meta_name_problem(k) {
            problems.push(format!("{}: {why}", at(k)));
            continue;
        }
        out.push((k.clone(), value));
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// Why `k` cannot name metadata (it becomes a column of `runs.csv`), if it cannot: empty or only
/// spaces, with leading or trailing spaces, commas, quotes or line breaks, or repeating a column
/// of `runs.csv`.
fn meta_name_problem(k: &str) -> Option<String> {
    if k.trim().is_empty() || k.trim() != k || k.contains([',', '"', '\n', '\r']) {
        return Some(
            "a metadata name becomes a column: not blank, no leading or trailing spaces, no \
             commas, quotes or line breaks"
                .to_string(),
        );
    }
    reserved_column(k).map(|why| format!("{why}; rename the metadata (e.g. meta_{k})"))
}

/// A record reader's message as it applies inside a manifest: the sample interval of a
/// one-column file is the entry's `dt` key (a TOML manifest) or cell (a CSV manifest) there,
/// not the scenario's `record_dt` or the `--record-dt` flag.
fn in_manifest(message: &str, csv: bool) -> String {
    let (given, by) = if csv {
        (
            "a dt cell in this row of the manifest",
            "given by the row's dt cell (in a CSV manifest)",
        )
    } else {
        (
            "dt = SECONDS in this [[record]] table of the manifest",
            "given by the entry's dt key (in a manifest)",
        )
    };
    message
        .replace(
            "record_dt = SECONDS in [ground_motion] or --record-dt SECONDS",
            given,
        )
        .replace("given by record_dt (scenario) or --record-dt", by)
}

/// The output columns of `runs.csv` that a metadata name must not repeat (a table reader would
/// return one of the two columns silently).
pub const RESERVED_COLUMNS: [&str; 9] = [
    "record",
    "level_g",
    "scale",
    "im_g",
    "scale_factor",
    "status",
    "warnings",
    "error",
    "governing_seat_end",
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
    if k.starts_with("seat_ratio_") {
        return Some(
            "a name starting with seat_ratio_ is reserved for the per-end seat columns of runs.csv"
                .into(),
        );
    }
    ["_exceeded", "_ratio"]
        .iter()
        .find(|s| k.ends_with(*s))
        .map(|s| {
            format!("a name ending in {s} is reserved for the limit-state columns of runs.csv")
        })
}

/// Why a `units` key (or cell) does not apply to the component `key` = `spec` read as `rec`,
/// if it does not: a built-in record, or an `.AT2` file whose header names its units (its
/// label, set by the AT2 reader, is then `UNITS header`), keeps its own units, so a `units`
/// given for it would be silently ignored. An `.AT2` whose header names no units takes them.
fn units_do_not_apply(key: &str, spec: &str, rec: &Record) -> Option<String> {
    let spec = spec.trim();
    let what = if spec.starts_with("builtin:") {
        format!("{key} = {spec} is a built-in PEER record in its header's units")
    } else if rec.units().ends_with(" header") {
        format!(
            "{key} = {spec} is a PEER .AT2 file whose header names its units ({})",
            rec.units().trim_end_matches(" header")
        )
    } else {
        return None;
    };
    Some(format!(
        "units apply to text files (and to an .AT2 file whose header names no units), but \
         {what}: it does not apply; remove it"
    ))
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
