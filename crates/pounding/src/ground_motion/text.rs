//! Text records: CSV `t, a`, whitespace-separated columns `t a`, and a sequence of accelerations
//! with a given sample interval (OpenSees `timeSeries Path -dt`).

use super::at2::{ACCEPTED_UNITS, accel_unit_factor, line_units, looks_like_accel_unit};
use super::format::ACCEPTED_FORMATS;
use super::{
    AccelUnits, GroundMotionError, Record, converted_overflow, data_lines, parse_err, parse_real,
    push_values, quote, strip_bom,
};
use crate::math::Real;
use crate::output::float_token;

impl Record {
    /// Parses a two-column CSV `t, a` (t in s, a in `units`). Blank lines and lines starting
    /// with `#` are skipped; a first non-numeric line is taken as a header. The header is read:
    /// a velocity or displacement column, a time unit other than seconds, and an acceleration
    /// unit (in brackets anywhere in a cell, `a[gal]`, `acc (cm/s^2)`, or a word, `acc_gal`) that
    /// is not an acceleration unit or differs from `units` are refused. Times must increase
    /// strictly. `#` lines are checked as comment lines are. Errors carry the
    /// 1-based line number.
    pub fn from_csv_str(
        text: &str,
        source_name: &str,
        units: AccelUnits,
    ) -> Result<Self, GroundMotionError> {
        let text = strip_bom(text);
        check_comments(text, source_name, units)?;
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
                let semicolons = if line.contains(';') {
                    " (semicolons do not separate columns: use commas)"
                } else {
                    ""
                };
                return Err(parse_err(
                    source_name,
                    k + 1,
                    format!(
                        "expected 2 comma-separated columns (t, a), found {}{semicolons}; \
                         {ACCEPTED_FORMATS}",
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
                        format!("not a pair of finite numbers: {}", quote(line)),
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
    /// as a CSV header is; every `#` line is checked as comment lines are.
    /// Times must increase strictly. Errors carry the 1-based line number.
    pub fn from_columns_str(
        text: &str,
        source_name: &str,
        units: AccelUnits,
    ) -> Result<Self, GroundMotionError> {
        let text = strip_bom(text);
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
        check_comments(text, source_name, units)?;
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
                         line), found {}",
                        quote(line)
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
    /// `timeSeries Path -dt` does. Blank lines are skipped; `#` lines are checked as
    /// comment lines are.
    ///
    /// A file in which every line holds exactly two values is refused as ambiguous: the two
    /// columns may be `t a` (then no sample interval applies) or two components (one file each).
    pub fn from_sequence_str(
        text: &str,
        source_name: &str,
        units: AccelUnits,
        dt: Real,
    ) -> Result<Self, GroundMotionError> {
        Self::sequence_from(text, source_name, units, (dt, "record_dt / --record-dt"))
    }

    /// [`Record::from_sequence_str`] with the interval's origin (`dt_from`) named in messages.
    pub(super) fn sequence_from(
        text: &str,
        source_name: &str,
        units: AccelUnits,
        (dt, dt_from): (Real, &str),
    ) -> Result<Self, GroundMotionError> {
        let text = strip_bom(text);
        check_comments(text, source_name, units)?;
        let mut values = Vec::new();
        let mut all_two = true;
        for (k, line) in data_lines(text) {
            all_two &= line.split_whitespace().count() == 2;
            push_values(&mut values, line, units.factor(), None)
                .map_err(|m| parse_err(source_name, k, m))?;
        }
        if values.is_empty() {
            return Err(parse_err(source_name, 1, "no samples found"));
        }
        if all_two {
            let line = data_lines(text).next().map_or(1, |(k, _)| k);
            return Err(parse_err(
                source_name,
                line,
                format!(
                    "every line holds two values and a sample interval of {} s is given by \
                     {dt_from}: ambiguous. If the two columns are `t a` (time, acceleration), \
                     the file has its own times: remove the interval ({dt_from}) and they are \
                     read; if they are two components, split the file into one file per \
                     component",
                    float_token(dt)
                ),
            ));
        }
        Ok(Self::uniform(source_name, dt, values)?.with_units_label(units.name()))
    }
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
            "time {} does not increase (previous {}): the first column must be the time, \
             increasing; {ACCEPTED_FORMATS}",
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
    if let [a, t] = cells
        && is_accel_name(a)
        && is_time_name(t)
    {
        return Err(format!(
            "the header names {} first and {} second: the columns look swapped; the record \
             must be time first, then acceleration (t, a): swap the columns",
            quote(a),
            quote(t)
        ));
    }
    for (i, cell) in cells.iter().enumerate() {
        let (words, bracketed) = split_cell(cell);
        for w in &words {
            if let Some(kind) = quantity_word(w) {
                return Err(format!(
                    "the header column {} is a {kind}: the record must be an acceleration \
                     time series (t, a)",
                    quote(cell)
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
            "the time column {} is in {}: only seconds (s, sec, seconds) are accepted; \
             convert the times",
            quote(cell),
            quote(u)
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
    let cell_q = quote(cell);
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
                    "the acceleration column {cell_q} is in {u}, a unit of velocity or length, \
                     not of acceleration; give the acceleration record ({ACCEPTED_UNITS})"
                ));
            }
            None if in_brackets || u == "MG" || looks_like_accel_unit(&u) => {
                return Err(format!(
                    "unknown units {u} in the acceleration column {cell_q}; {ACCEPTED_UNITS}"
                ));
            }
            None => continue,
        };
        if let Some((g, prev)) = &found
            && *g != factor
        {
            return Err(format!(
                "the acceleration column {cell_q} names two different units, {prev} and {u}"
            ));
        }
        found = Some((factor, u));
    }
    match found {
        Some((f, u)) if f != units.factor() => Err(units_disagree("the header", &u, f, units)),
        _ => Ok(()),
    }
}

/// The message for a header or comment (`what`) naming the units `named` (factor `factor` to
/// m/s²) while the file is read in `units`: what to set, or that the file must be converted
/// (the text formats are read in g or m/s² only).
pub(super) fn units_disagree(what: &str, named: &str, factor: Real, units: AccelUnits) -> String {
    let fix = match [AccelUnits::G, AccelUnits::MetresPerSecondSquared]
        .into_iter()
        .find(|u| u.factor() == factor)
    {
        Some(u) => format!(
            "set csv_units = \"{0}\" in [ground_motion] (or --csv-units {0}; in a record-set \
             manifest, the entry's units = \"{0}\") to read it in {0}",
            u.name()
        ),
        None => "the text formats (CSV, columns, one column) are read in g or m/s2 only: convert \
                 the values of the file to g or m/s2 and set csv_units / --csv-units to match"
            .to_string(),
    };
    format!(
        "{what} names the units {named} but the record is read in {} (csv_units / \
         --csv-units, or a manifest entry's units): {fix}",
        units.name()
    )
}

/// Checks every `#` comment line of a text record ([`check_comment`]), naming the file and line.
fn check_comments(
    text: &str,
    source_name: &str,
    units: AccelUnits,
) -> Result<(), GroundMotionError> {
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.starts_with('#') {
            check_comment(line, units).map_err(|m| parse_err(source_name, k + 1, m))?;
        }
    }
    Ok(())
}

/// A `#` comment line of a text record (CSV, columns, one column) is read as a header is: it is
/// refused if it names a velocity or displacement (and no acceleration), a unit of velocity in
/// brackets (`(cm/s)`), units this reader does not know (`cm/s/s` and the like, or `units`
/// followed by none it knows), or acceleration units other than the `units` the values are
/// read in (`# a (gal)` over values read in g). Units are found as in an `.AT2` header: a `g`
/// counts after `of`, `in`, `units` or in brackets only.
fn check_comment(line: &str, units: AccelUnits) -> Result<(), String> {
    let body = line.trim_start_matches('#');
    let upper = body.to_ascii_uppercase();
    let words: Vec<&str> = upper
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    if !words.iter().any(|w| w.starts_with("ACC"))
        && let Some(kind) = words.iter().find_map(|w| quantity_word(w))
    {
        return Err(format!(
            "the comment line {} says {kind}: the record must be an acceleration time series; \
             give the acceleration record",
            quote(line)
        ));
    }
    let (_, bracketed) = split_cell(body);
    if let Some(u) = bracketed
        .iter()
        .map(|b| norm_unit(b))
        .find(|u| u.contains('/') && velocity_or_length(u))
    {
        return Err(format!(
            "the comment line {} names {u}, a unit of velocity, not of acceleration; give the \
             acceleration record ({ACCEPTED_UNITS})",
            quote(line)
        ));
    }
    match line_units(body)? {
        Some((f, u)) if f != units.factor() => Err(units_disagree(
            &format!("the comment line {}", quote(line)),
            &u,
            f,
            units,
        )),
        _ => Ok(()),
    }
}

/// Whether a header cell names the time (`t`, `time`, `t_s`, `time (s)`).
fn is_time_name(cell: &str) -> bool {
    let (words, _) = split_cell(cell);
    words
        .first()
        .is_some_and(|w| matches!(w.as_str(), "T" | "TIME" | "TIMES"))
}

/// Whether a header cell names an acceleration (`a`, `acc`, `accel`, `acceleration`, `ag`).
fn is_accel_name(cell: &str) -> bool {
    let (words, _) = split_cell(cell);
    words.first().is_some_and(|w| {
        matches!(
            w.as_str(),
            "A" | "AG" | "ACC" | "ACCEL" | "ACCELERATION" | "ACCELERATIONS"
        )
    })
}

/// The cells of a `#` comment line over columns `t a` if it looks like a header of them: two
/// cells (a bracketed unit belongs to the word before it), the first `t` or `time` (or the
/// second, after an acceleration: a swapped header, refused).
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
    let looks = match &cells[..] {
        [t, a] => is_time_name(t) || (is_accel_name(t) && is_time_name(a)),
        _ => false,
    };
    looks.then_some(cells)
}
