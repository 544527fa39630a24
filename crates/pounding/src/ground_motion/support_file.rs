//! Support-motion files: one acceleration history per support of a bridge, as
//! `pounding motion svgm` writes them.
//!
//! ```text
//! t,start,joint1,joint2,end
//! 0,0,0,0,0
//! 0.01,0.0123,-0.0031,0.0007,0.0102
//! …
//! ```
//!
//! A header row `t,<id>,<id>,…` (ids of `[A-Za-z0-9_-]`, unique), then one row per sample: the
//! time \[s\] (finite, from `t ≥ 0`, strictly increasing) and each support's acceleration in
//! **m/s²** (finite). Every row has as many fields as the header. Each column is read as a
//! [`Record`] (linear interpolation, zero after the last sample). Errors name the file and line.

use super::{GroundMotionError, Record, parse_err};
use crate::math::Real;
use std::path::Path;

/// Files larger than this are refused (as records are).
const MAX_BYTES: u64 = 256 << 20;

/// Reads the support-motion file at `path`: `(id, record)` per support, in column order.
pub fn read_support_motions(path: &Path) -> Result<Vec<(String, Record)>, GroundMotionError> {
    let name = path.display().to_string();
    let io = |message: String| GroundMotionError::Io {
        path: name.clone(),
        message,
    };
    let meta = std::fs::metadata(path).map_err(|e| io(e.to_string()))?;
    if meta.len() > MAX_BYTES {
        return Err(io(format!(
            "the file has {} bytes, more than the limit of {MAX_BYTES}",
            meta.len()
        )));
    }
    let text = std::fs::read_to_string(path).map_err(|e| io(e.to_string()))?;
    parse_support_motions(&text, &name)
}

/// [`read_support_motions`] of `text`, named `name` in errors.
pub fn parse_support_motions(
    text: &str,
    name: &str,
) -> Result<Vec<(String, Record)>, GroundMotionError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((hl, header)) = lines.next() else {
        return Err(parse_err(
            name,
            1,
            "empty file: expected a header `t,<support id>,…`",
        ));
    };
    let cols: Vec<&str> = header.split(',').map(str::trim).collect();
    if cols.len() < 2 || !cols[0].eq_ignore_ascii_case("t") {
        return Err(parse_err(
            name,
            hl,
            format!("expected a header `t,<support id>,…`, found `{header}`"),
        ));
    }
    let ids: Vec<String> = cols[1..].iter().map(|s| s.to_string()).collect();
    for (i, id) in ids.iter().enumerate() {
        let ok = !id.is_empty()
            && id
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
        if !ok {
            return Err(parse_err(
                name,
                hl,
                format!(
                    "support id `{id}` (column {}) must be letters, digits, `_` or `-`",
                    i + 2
                ),
            ));
        }
        if ids[..i].contains(id) {
            return Err(parse_err(
                name,
                hl,
                format!("support id `{id}` appears twice"),
            ));
        }
    }
    let mut times = Vec::new();
    let mut values: Vec<Vec<Real>> = vec![Vec::new(); ids.len()];
    for (ln, line) in lines {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != cols.len() {
            return Err(parse_err(
                name,
                ln,
                format!("{} fields, the header has {}", fields.len(), cols.len()),
            ));
        }
        let mut row = Vec::with_capacity(fields.len());
        for (c, f) in fields.iter().enumerate() {
            let v: Real = f.parse().map_err(|_| {
                parse_err(
                    name,
                    ln,
                    format!("`{f}` (column {}) is not a number", c + 1),
                )
            })?;
            if !v.is_finite() {
                return Err(parse_err(
                    name,
                    ln,
                    format!("`{f}` (column {}) is not finite", c + 1),
                ));
            }
            row.push(v);
        }
        let t = row[0];
        if times.is_empty() && t < 0.0 {
            return Err(parse_err(name, ln, "the first time must be >= 0"));
        }
        if times.last().is_some_and(|&p| t <= p) {
            return Err(parse_err(name, ln, "times must increase strictly"));
        }
        times.push(t);
        for (c, v) in row[1..].iter().enumerate() {
            values[c].push(*v);
        }
    }
    if times.len() < 2 {
        return Err(parse_err(
            name,
            hl,
            "need at least two samples after the header",
        ));
    }
    ids.into_iter()
        .zip(values)
        .map(|(id, v)| {
            let r = Record::new(format!("{name}:{id}"), times.clone(), v)?;
            Ok((id, r))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_columns_and_names_bad_lines() {
        let ok = parse_support_motions("t,start,end\n0,0,0\n0.5,1,2\n1,0,-1\n", "f").unwrap();
        assert_eq!(ok.len(), 2);
        assert_eq!(ok[1].0, "end");
        assert_eq!(ok[1].1.accel(0.75), 0.5);
        for (text, line, what) in [
            ("x,start\n0,0\n1,1\n", 1, "header"),
            ("t,start,start\n0,0,0\n1,1,1\n", 1, "twice"),
            ("t,sta rt\n0,0\n1,1\n", 1, "letters"),
            ("t,a,b\n0,0,0\n1,1\n", 3, "fields"),
            ("t,a\n0,0\n0,1\n", 3, "increase"),
            ("t,a\n0,0\n1,nan\n", 3, "finite"),
            ("t,a\n0,0\n1,x\n", 3, "not a number"),
            ("t,a\n0,0\n", 1, "two samples"),
        ] {
            let e = parse_support_motions(text, "f").unwrap_err();
            let GroundMotionError::Parse {
                line: l, message, ..
            } = &e
            else {
                panic!("{e}")
            };
            assert_eq!(*l, line, "{text}: {e}");
            assert!(message.contains(what), "{text}: {e}");
        }
    }
}
