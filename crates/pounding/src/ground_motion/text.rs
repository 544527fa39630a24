//! Text records: CSV `t, a`, whitespace-separated columns `t a`, and a sequence of accelerations
//! with a given sample interval (OpenSees `timeSeries Path -dt`).

use super::at2::{ACCEPTED_UNITS, accel_unit_factor, looks_like_accel_unit};
use super::{
    AccelUnits, GroundMotionError, Record, converted_overflow, parse_err, parse_real, push_values,
};
use crate::math::Real;
use crate::output::float_token;

impl Record {
    /// Parses a two-column CSV `t, a` (t in s, a in `units`). Blank lines and lines starting
    /// with `#` are skipped; a first non-numeric line is taken as a header. The header is read:
    /// a velocity or displacement column, a time unit other than seconds, and an acceleration
    /// unit (in brackets anywhere in a cell, `a[gal]`, `acc (cm/s^2)`, or a word, `acc_gal`) that
    /// is not an acceleration unit or differs from `units` are refused. Times must increase
    /// strictly. Errors carry the 1-based line number.
    pub fn from_csv_str(
        text: &str,
        source_name: &str,
        units: AccelUnits,
    ) -> Result<Self, GroundMotionError> {
        let mut times = Vec::new();
        let mut values = Vec::new();
        let mut seen_content = false;
        for (k, raw) in text.lines().enumerate() {
            let line = raw.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let cols: Vec<&str> = line.split(',').map(str::trim).collect();
            let first = !seen_content;
            seen_content = true;
            // A header is a first line in which no column is a number (`nan`, `1e999` and
            // `0.1g`-like cells are not headers: they are refused below, naming the line).
            let is_header = first
                && cols.iter().all(|c| {
                    c.parse::<f64>().is_err()
                        && parse_real(c).is_none()
                        && !c.starts_with(|ch: char| {
                            ch.is_ascii_digit() || matches!(ch, '-' | '+' | '.')
                        })
                });
            if is_header {
                check_header_cells(&cols, units).map_err(|m| parse_err(source_name, k + 1, m))?;
            }
            if cols.len() != 2 {
                if is_header {
                    continue;
                }
                return Err(parse_err(
                    source_name,
                    k + 1,
                    format!(
                        "expected 2 comma-separated columns (t, a), found {}",
                        cols.len()
                    ),
                ));
            }
            match (parse_real(cols[0]), parse_real(cols[1])) {
                (Some(t), Some(a)) => add_pair(&mut times, &mut values, (t, a, cols[1]), units)
                    .map_err(|m| parse_err(source_name, k + 1, m))?,
                _ if is_header => continue,
                _ => {
                    return Err(parse_err(
                        source_name,
                        k + 1,
                        format!("not a pair of finite numbers: {line:?}"),
                    ));
                }
            }
        }
        if times.is_empty() {
            return Err(parse_err(source_name, 1, "no samples found"));
        }
        Ok(Self::new(source_name, times, values)?.with_units_label(units.name()))
    }

    /// Parses whitespace-separated columns `t a` (t in s, a in `units`), one sample a line.
    /// Blank lines and lines starting with `#` (a comment header) are skipped; a `#` line before
    /// the first sample that looks like a header of the columns (`# t (s)  a (gal)`) is checked
    /// as a CSV header is. Times must increase strictly. Errors carry the 1-based line number.
    pub fn from_columns_str(
        text: &str,
        source_name: &str,
        units: AccelUnits,
    ) -> Result<Self, GroundMotionError> {
        let (mut times, mut values) = (Vec::new(), Vec::new());
        // `#` lines before the first sample that look like a header (`# t (s)  a (gal)`)
        for (k, line) in text.lines().enumerate() {
            let line = line.trim();
            if !(line.is_empty() || line.starts_with('#')) {
                break;
            }
            if let Some(cells) = comment_header_cells(line) {
                let cells: Vec<&str> = cells.iter().map(String::as_str).collect();
                check_header_cells(&cells, units).map_err(|m| parse_err(source_name, k + 1, m))?;
            }
        }
        for (k, line) in data_lines(text) {
            let cols: Vec<&str> = line.split_whitespace().collect();
            let pair = match cols[..] {
                [t, a] => parse_real(t).zip(parse_real(a)).map(|(t, v)| (t, v, a)),
                _ => None,
            };
            let Some(pair) = pair else {
                return Err(parse_err(
                    source_name,
                    k,
                    format!(
                        "expected two whitespace-separated numbers `t a` (as on the first data \
                         line), found {line:?}"
                    ),
                ));
            };
            add_pair(&mut times, &mut values, pair, units)
                .map_err(|m| parse_err(source_name, k, m))?;
        }
        if times.is_empty() {
            return Err(parse_err(source_name, 1, "no samples found"));
        }
        Ok(Self::new(source_name, times, values)?.with_units_label(units.name()))
    }

    /// Parses a sequence of accelerations (in `units`) sampled every `dt` seconds from `t = 0`,
    /// any number of whitespace-separated values a line, read in order as OpenSees'
    /// `timeSeries Path -dt` does. Blank lines and `#` lines are skipped.
    ///
    /// A file in which every line holds two values whose first column increases strictly from
    /// `t >= 0` carries its own times (`t a`): it is refused rather than read as accelerations.
    pub fn from_sequence_str(
        text: &str,
        source_name: &str,
        units: AccelUnits,
        dt: Real,
    ) -> Result<Self, GroundMotionError> {
        let mut values = Vec::new();
        let mut firsts: Vec<Option<Real>> = Vec::new();
        for (k, line) in data_lines(text) {
            let mut toks = line.split_whitespace();
            let two = line.split_whitespace().count() == 2;
            firsts.push(toks.next().and_then(parse_real).filter(|_| two));
            push_values(&mut values, line, units.factor(), None)
                .map_err(|m| parse_err(source_name, k, m))?;
        }
        if values.is_empty() {
            return Err(parse_err(source_name, 1, "no samples found"));
        }
        let times: Option<Vec<Real>> = firsts.iter().copied().collect();
        if let Some(t) = times
            && t.len() > 1
            && t[0] >= 0.0
            && t.windows(2).all(|w| w[1] > w[0])
        {
            return Err(parse_err(
                source_name,
                1,
                "every line holds two values and the first column increases: the file carries \
                 its own times (`t a`), so a sample interval (record_dt / --record-dt) does not \
                 apply; remove it",
            ));
        }
        Ok(Self::uniform(source_name, dt, values)?.with_units_label(units.name()))
    }
}

/// The lines holding data (1-based number, trimmed text): not blank, not a `#` comment.
pub(super) fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(k, l)| (k + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
}

/// Appends the sample `(t, a × units)` (`a_tok` as written, for messages): times must increase
/// strictly and the converted value must be finite.
fn add_pair(
    times: &mut Vec<Real>,
    values: &mut Vec<Real>,
    (t, a, a_tok): (Real, Real, &str),
    units: AccelUnits,
) -> Result<(), String> {
    if let Some(&prev) = times.last()
        && t <= prev
    {
        return Err(format!(
            "time {} does not increase (previous {})",
            float_token(t),
            float_token(prev)
        ));
    }
    if !(a * units.factor()).is_finite() {
        return Err(converted_overflow(a_tok, units.factor()));
    }
    times.push(t);
    values.push(a * units.factor());
    Ok(())
}

/// A header (CSV, or a `#` line over columns `t a`) naming `cells`: the first is time, the others
/// acceleration. Refused: a velocity or displacement column, a time unit other than seconds,
/// a velocity/length or unknown unit for the acceleration, two units in one cell, and an
/// acceleration unit that differs from the units the file is read in (`units`).
fn check_header_cells(cells: &[&str], units: AccelUnits) -> Result<(), String> {
    for (i, cell) in cells.iter().enumerate() {
        let (words, bracketed) = split_cell(cell);
        for w in &words {
            if let Some(kind) = quantity_word(w) {
                return Err(format!(
                    "the header column {cell:?} is a {kind}: the record must be an \
                     acceleration time series (t, a)"
                ));
            }
        }
        if i == 0 {
            check_time_cell(cell, &words, &bracketed)?;
        } else {
            check_accel_cell(cell, &words, &bracketed, units)?;
        }
    }
    Ok(())
}

/// The words of a header `cell` outside brackets (split at whitespace, `_`, `:`), and the
/// contents of its `(...)` / `[...]` groups, upper case.
fn split_cell(cell: &str) -> (Vec<String>, Vec<String>) {
    let upper = cell.to_ascii_uppercase();
    let (mut outside, mut inside) = (String::new(), Vec::new());
    let mut group: Option<String> = None;
    for c in upper.chars() {
        match (c, group.as_mut()) {
            ('(' | '[', None) => group = Some(String::new()),
            (')' | ']', Some(_)) => inside.extend(group.take().map(|g| g.trim().to_string())),
            (c, Some(g)) => g.push(c),
            (c, None) => outside.push(c),
        }
    }
    // an unclosed bracket: its content still counts
    inside.extend(group.map(|g| g.trim().to_string()));
    let words = outside
        .split(|c: char| c.is_whitespace() || matches!(c, '_' | ':' | '=' | ';'))
        .filter(|w| !w.is_empty())
        .map(str::to_string)
        .collect();
    (
        words,
        inside.into_iter().filter(|g| !g.is_empty()).collect(),
    )
}

/// `velocity` or `displacement` if the header word `w` names one.
fn quantity_word(w: &str) -> Option<&'static str> {
    match w {
        "VEL" | "VELO" | "VELOCITY" | "VELOCITIES" => Some("velocity"),
        "DISP" | "DISPL" | "DISPLACEMENT" | "DISPLACEMENTS" => Some("displacement"),
        _ => None,
    }
}

const SECONDS: [&str; 5] = ["S", "SEC", "SECS", "SECOND", "SECONDS"];
const OTHER_TIME_UNITS: [&str; 10] = [
    "MS",
    "MSEC",
    "MILLISECONDS",
    "US",
    "MIN",
    "MINS",
    "MINUTE",
    "MINUTES",
    "HR",
    "HOURS",
];

/// The time column of a header is in seconds (bracketed unit `s`/`sec`/`seconds`, or none).
fn check_time_cell(cell: &str, words: &[String], bracketed: &[String]) -> Result<(), String> {
    let bad = bracketed
        .iter()
        .find(|b| !SECONDS.contains(&b.as_str()))
        .or_else(|| {
            words
                .iter()
                .find(|w| OTHER_TIME_UNITS.contains(&w.as_str()))
        });
    match bad {
        Some(u) => Err(format!(
            "the time column {cell:?} is in {u:?}: only seconds (s, sec, seconds) are accepted; \
             convert the times"
        )),
        None => Ok(()),
    }
}

/// Normalised unit text: upper case, no spaces, `**` written `^`, `SEC` written `S`.
fn norm_unit(u: &str) -> String {
    u.split_whitespace()
        .collect::<String>()
        .replace("**", "^")
        .replace("SEC", "S")
}

/// Whether the normalised `u` is a unit of velocity or length (not of acceleration).
fn velocity_or_length(u: &str) -> bool {
    let len = ["M", "CM", "MM", "IN", "FT", "KM"];
    len.contains(&u)
        || len
            .iter()
            .any(|l| u.strip_prefix(l).is_some_and(|r| r == "/S"))
}

/// The acceleration column of a header: its unit (in brackets, or a word such as `acc_gal`)
/// must be an acceleration unit equal to `units`.
fn check_accel_cell(
    cell: &str,
    words: &[String],
    bracketed: &[String],
    units: AccelUnits,
) -> Result<(), String> {
    let mut found: Option<(Real, String)> = None;
    // `mps2` / `ms2` words are m/s²
    let unit_word = |w: &str| match norm_unit(w).as_str() {
        "MPS2" | "MS2" | "MPSS" => "M/S2".to_string(),
        other => other.to_string(),
    };
    // a `g` word is a unit when it ends a name of several words (`acc_g`, `a_g`); alone it may
    // be a name
    let last = (words.len() > 1)
        .then(|| words.last().map(|w| unit_word(w)))
        .flatten();
    let candidates = bracketed
        .iter()
        .map(|b| (true, norm_unit(b)))
        .chain(words.iter().map(|w| (false, unit_word(w))));
    for (in_brackets, u) in candidates {
        let factor = match accel_unit_factor(&u) {
            Some(_) if u == "G" && !in_brackets && last.as_deref() != Some("G") => continue,
            Some(f) => f,
            None if velocity_or_length(&u) && (in_brackets || u.contains('/')) => {
                return Err(format!(
                    "the acceleration column {cell:?} is in {u}, a unit of velocity or length, \
                     not of acceleration; give the acceleration record ({ACCEPTED_UNITS})"
                ));
            }
            None if in_brackets || u == "MG" || looks_like_accel_unit(&u) => {
                return Err(format!(
                    "unknown units {u} in the acceleration column {cell:?}; {ACCEPTED_UNITS}"
                ));
            }
            None => continue,
        };
        if let Some((g, prev)) = &found
            && *g != factor
        {
            return Err(format!(
                "the acceleration column {cell:?} names two different units, {prev} and {u}"
            ));
        }
        found = Some((factor, u));
    }
    match found {
        Some((f, u)) if f != units.factor() => Err(format!(
            "the header names the units {u} but the record is read in {} (csv_units / \
             --csv-units): set csv_units to match (\"g\" or \"m/s2\"), or convert the file",
            units.name()
        )),
        _ => Ok(()),
    }
}

/// The cells of a `#` comment line over columns `t a` if it looks like a header of them: two
/// cells (a bracketed unit belongs to the word before it), the first `t` or `time`.
fn comment_header_cells(line: &str) -> Option<Vec<String>> {
    let body = line.trim().strip_prefix('#')?.trim();
    let mut cells: Vec<String> = Vec::new();
    for tok in body.split_whitespace() {
        match cells.last_mut() {
            Some(last) if tok.starts_with(['(', '[']) => {
                last.push(' ');
                last.push_str(tok);
            }
            _ => cells.push(tok.to_string()),
        }
    }
    let first = cells.first()?.to_ascii_lowercase();
    let name = first.split(['_', '(', '[', ' ']).next().unwrap_or("");
    (cells.len() == 2 && matches!(name, "t" | "time")).then_some(cells)
}
