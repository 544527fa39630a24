//! A record-set manifest in CSV: a header row, then one row per record (or pair), as a
//! spreadsheet of records saves it.
//!
//! ```text
//! id,x,y,dt,units,magnitude,site
//! A,a.txt,,0.01,m/s2,6.5,rock
//! P,builtin:ELC180,builtin:ELC270,,,6.95,
//! ```
//!
//! * The columns `id`, `x`, `y`, `dt` and `units` are the keys of a TOML `[[record]]` table
//!   (`id` and `x` required, the others optional); every other column is metadata, as
//!   `[record.meta]`, with the same rules (a name repeating a `runs.csv` column is refused).
//!   A column whose name looks like one of these keys but is not one (`ID`, `Units`, `unit`,
//!   `path`, `file`, `format`, `record_dt`, …) is refused rather than taken as metadata: a typo
//!   must not silently drop a unit or a sample interval.
//! * An empty cell is "not given"; spaces around a cell are ignored, also inside quotes
//!   (`" padded "` is `padded`); a row of empty cells is skipped. A metadata cell is an
//!   integer, a number or `true` / `false` when it reads back as written (`6.95`, `42`), else
//!   text (`007`, `6.90`, `rock`): its `runs.csv` cell is the text of the manifest's cell.
//! * Quoted cells (with commas, quotes `""` or line breaks), CRLF line endings and a UTF-8
//!   byte-order mark are read as a spreadsheet writes them. A quote that opens a cell and is
//!   never closed is refused (naming the line where it opens), not read to the end of the
//!   file. A row with more or fewer cells than the header (a ragged row) is refused.
//! * Messages name the manifest, the line where the row starts (1-based: the header is line 1)
//!   and the column (its spreadsheet letter; the key is its header name).

use super::{Ctx, Entry, Loc, MetaValue, Val, column_name, meta_name_problem};
use crate::math::Real;

/// The structural columns (the keys of a TOML `[[record]]` table other than `meta`).
const KEYS: [&str; 5] = ["id", "x", "y", "dt", "units"];

/// Names that look like a structural column but are not one, and what was probably meant.
const LOOKALIKES: [(&str, &str); 9] = [
    ("unit", "units"),
    ("path", "x"),
    ("file", "x"),
    ("record", "x"),
    ("record_dt", "dt"),
    ("csv_units", "units"),
    ("dt_s", "dt"),
    ("x_path", "x"),
    ("y_path", "y"),
];

/// What the header says: the column of each key and the metadata columns.
struct Header {
    names: Vec<String>,
    key_col: [Option<usize>; 5],
    meta: Vec<usize>,
    /// Unnamed columns (tolerated while all their cells are empty).
    unnamed: Vec<usize>,
}

/// The problem with header name `h` (after the names `seen`), if any.
fn header_problem(h: &str, seen: &[String]) -> Option<String> {
    if let Some(j) = seen.iter().position(|s| s == h) {
        return Some(format!("column {:?} repeats column {}", h, column_name(j)));
    }
    if KEYS.contains(&h) {
        return None;
    }
    let norm = h.to_ascii_lowercase().replace([' ', '-'], "_");
    let meant = KEYS
        .iter()
        .find(|k| **k == norm)
        .copied()
        .or_else(|| LOOKALIKES.iter().find(|(l, _)| *l == norm).map(|(_, k)| *k));
    if let Some(k) = meant {
        return Some(format!(
            "column {h:?} looks like the manifest column {k:?} but is not one (the columns are \
             {}, lower case; every other column is metadata): rename it {k:?}, or e.g. \
             \"meta_{norm}\" to keep it as metadata",
            KEYS.join(", ")
        ));
    }
    if norm == "supports" {
        return Some(format!(
            "column {h:?}: support-motion entries (a motion per support) are read from TOML \
             manifests only ([[record]] id = \"…\" supports = \"FILE.csv\"); rename the column \
             (e.g. \"meta_supports\") to keep it as metadata"
        ));
    }
    if norm == "format" {
        return Some(format!(
            "column {h:?}: a record's format is found from its file (extension and content), \
             not given in the manifest; rename the column (e.g. \"meta_format\") to keep it as \
             metadata"
        ));
    }
    meta_name_problem(h)
}

/// Reads the header row (line `line`), or the problems with it.
fn header(cx: &Ctx, cells: &csv::StringRecord, line: usize) -> Result<Header, Vec<String>> {
    let mut problems = Vec::new();
    let mut h = Header {
        names: Vec::new(),
        key_col: [None; 5],
        meta: Vec::new(),
        unnamed: Vec::new(),
    };
    for (c, name) in cells.iter().enumerate() {
        let at = format!("{}:{line}, column {}", cx.origin, column_name(c));
        if name.is_empty() {
            h.unnamed.push(c);
        } else if let Some(why) = header_problem(name, &h.names) {
            problems.push(format!("header ({at}): {why}"));
        } else if let Some(k) = KEYS.iter().position(|k| *k == name) {
            h.key_col[k] = Some(c);
        } else {
            h.meta.push(c);
        }
        h.names.push(name.to_string());
    }
    for (k, what) in [(0, "the record's unique id"), (1, "the record file")] {
        if h.key_col[k].is_none() {
            let hint = if cells.len() == 1 && cells[0].contains([';', '\t']) {
                ": the header is one cell; is the file separated by semicolons or tabs? \
                 Save it as comma-separated CSV"
            } else {
                ""
            };
            problems.push(format!(
                "header ({}:{line}): no {:?} column ({what}): a CSV manifest needs the columns \
                 id and x (y, dt and units are optional; every other column is metadata){hint}; \
                 the header has {}",
                cx.origin,
                KEYS[k],
                cells
                    .iter()
                    .map(|s| format!("{s:?}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
    }
    if problems.is_empty() {
        Ok(h)
    } else {
        Err(problems)
    }
}

/// A metadata cell: an integer, a number or a boolean when it reads back as written, else text.
fn meta_cell(s: &str) -> MetaValue {
    match s {
        "true" => return MetaValue::Bool(true),
        "false" => return MetaValue::Bool(false),
        _ => {}
    }
    if let Ok(n) = s.parse::<i64>()
        && n.to_string() == s
    {
        return MetaValue::Integer(n);
    }
    if let Ok(x) = s.parse::<Real>()
        && x.is_finite()
        && crate::output::float_token(x) == s
    {
        return MetaValue::Number(x);
    }
    MetaValue::Text(s.to_string())
}

/// One data row (the `i`-th entry, at line `line`): the entry, or the problems with it.
fn row(
    cx: &Ctx,
    h: &Header,
    i: usize,
    cells: &csv::StringRecord,
    line: usize,
) -> Result<Entry, Vec<String>> {
    let mut problems = Vec::new();
    let cell = |k: usize| {
        h.key_col[k].and_then(|c| {
            let v = &cells[c];
            (!v.is_empty()).then(|| Val {
                v: v.to_string(),
                at: Loc { line, col: Some(c) },
            })
        })
    };
    let col_of = |k: usize| Loc {
        line,
        col: h.key_col[k],
    };
    let id = cell(0).unwrap_or(Val {
        v: String::new(),
        at: col_of(0),
    });
    let (x, y) = (cell(1), cell(2));
    let x = match (x, &y) {
        (Some(x), _) => Some(x),
        (None, None) => {
            problems.push(format!(
                "{}: empty: give the record file in x (a single record), or the two \
                 components in x and y (a pair)",
                cx.at(i, "x", col_of(1))
            ));
            None
        }
        (None, Some(_)) => {
            problems.push(format!(
                "{}: empty, but y is given: a pair's first component goes in x",
                cx.at(i, "x", col_of(1))
            ));
            None
        }
    };
    let dt = cell(3).and_then(|d| match d.v.parse::<Real>() {
        Ok(v) => Some(Val { v, at: d.at }),
        Err(_) => {
            problems.push(format!(
                "{}: not a number: {:?} (the sample interval in seconds, e.g. 0.01)",
                cx.at(i, "dt", d.at),
                d.v
            ));
            None
        }
    });
    let mut meta: Vec<(String, MetaValue)> = h
        .meta
        .iter()
        .filter(|&&c| !cells[c].is_empty())
        .map(|&c| (h.names[c].clone(), meta_cell(&cells[c])))
        .collect();
    meta.sort_by(|a, b| a.0.cmp(&b.0));
    match x {
        Some(x) if problems.is_empty() => Ok(Entry {
            id,
            x,
            supports: None,
            y,
            dt,
            units: cell(4),
            meta,
            meta_problems: Vec::new(),
        }),
        _ => Err(problems),
    }
}

/// Line numbers of byte offsets met in increasing order (the CSV reader's own count is short
/// after a CRLF, where it stops between `\r` and `\n`, and after blank lines).
struct Lines<'a> {
    text: &'a [u8],
    pos: usize,
    line: usize,
}

impl Lines<'_> {
    /// The 1-based line of the row starting at byte `b` (a line break is `\n`, `\r\n` or `\r`).
    fn at(&mut self, b: u64) -> usize {
        let mut b = (b as usize).min(self.text.len());
        // the reader's offset is where it started: before the line breaks it skipped
        while matches!(self.text.get(b), Some(b'\n' | b'\r')) {
            b += 1;
        }
        while self.pos < b {
            let c = self.text[self.pos];
            if c == b'\n' || (c == b'\r' && self.text.get(self.pos + 1) != Some(&b'\n')) {
                self.line += 1;
            }
            self.pos += 1;
        }
        self.line
    }
}

/// Where a quoted cell of `text` opens and is never closed, if one is: its 1-based line and
/// 0-based column. The CSV reader would take every later line into that cell (silently
/// dropping rows), so such a file is refused. A quote opens a cell only as its first character
/// (as the reader reads it); `""` inside quotes is an escaped quote.
fn unterminated_quote(text: &[u8]) -> Option<(usize, usize)> {
    #[derive(PartialEq)]
    enum S {
        Start,
        Field,
        Quoted,
        QuoteInQuoted,
    }
    let (mut st, mut line, mut col, mut opened) = (S::Start, 1, 0, (1, 0));
    for (k, &c) in text.iter().enumerate() {
        let newline = c == b'\n' || (c == b'\r' && text.get(k + 1) != Some(&b'\n'));
        if st == S::Quoted || (st == S::QuoteInQuoted && c == b'"') {
            st = if c == b'"' && st == S::Quoted {
                S::QuoteInQuoted
            } else {
                S::Quoted
            };
        } else if c == b',' {
            (st, col) = (S::Start, col + 1);
        } else if c == b'\n' || c == b'\r' {
            (st, col) = (S::Start, if newline { 0 } else { col });
        } else if st == S::Start && c == b'"' {
            (st, opened) = (S::Quoted, (line, col));
        } else {
            st = S::Field;
        }
        if newline {
            line += 1;
        }
    }
    (st == S::Quoted).then_some(opened)
}

/// The entries of the CSV manifest `cx.text` and the problems found while reading its rows
/// (every row is read, so that all problems are listed at once).
pub(super) fn entries(cx: &Ctx) -> (Vec<Entry>, Vec<String>) {
    let text = cx.text.strip_prefix('\u{feff}').unwrap_or(cx.text);
    if let Some((line, c)) = unterminated_quote(text.as_bytes()) {
        let problem = format!(
            "{}:{line}, column {}: a quoted cell opens here and is never closed: every later \
             line would be read into it; close the quote (a quote inside a quoted cell is \
             written \"\")",
            cx.origin,
            column_name(c)
        );
        return (Vec::new(), vec![problem]);
    }
    let mut rd = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let mut rows = rd.records();
    let mut problems = Vec::new();
    let mut out = Vec::new();
    let mut lines = Lines {
        text: text.as_bytes(),
        pos: 0,
        line: 1,
    };
    let mut line_of = |r: &csv::StringRecord| r.position().map_or(0, |p| lines.at(p.byte()));
    let Some(first) = rows.next() else {
        problems.push(
            "empty file: a CSV manifest starts with a header row naming its columns (id, x, \
             and optionally y, dt, units and metadata)"
                .to_string(),
        );
        return (out, problems);
    };
    let first = match first {
        Ok(r) => r,
        Err(e) => return (out, vec![format!("{}: {e}", cx.origin)]),
    };
    let h = match header(cx, &first, line_of(&first)) {
        Ok(h) => h,
        Err(p) => return (out, p),
    };
    let width = h.names.len();
    let mut unnamed_reported = false;
    for r in rows {
        let r = match r {
            Ok(r) => r,
            Err(e) => {
                problems.push(format!("{}: {e}", cx.origin));
                break;
            }
        };
        let line = line_of(&r);
        if r.iter().all(str::is_empty) {
            continue;
        }
        if r.len() != width {
            let c = r.len().min(width);
            problems.push(format!(
                "{}:{line}, column {}: the row has {} cells, the header {width}: every row needs \
                 one cell (possibly empty) per column (a ragged row)",
                cx.origin,
                column_name(c),
                r.len()
            ));
            continue;
        }
        if let Some(&c) = h.unnamed.iter().find(|&&c| !r[c].is_empty())
            && !unnamed_reported
        {
            unnamed_reported = true;
            problems.push(format!(
                "{}:{line}, column {}: a value under a column with no name in the header: name \
                 the column",
                cx.origin,
                column_name(c)
            ));
        }
        match row(cx, &h, out.len(), &r, line) {
            Ok(e) => out.push(e),
            Err(mut p) => problems.append(&mut p),
        }
    }
    if out.is_empty() && problems.is_empty() {
        problems
            .push("no records: the file has a header row but no record rows below it".to_string());
    }
    (out, problems)
}
