//! Text records: CSV `t, a`, whitespace-separated columns `t a`, and a sequence of accelerations
//! with a given sample interval (OpenSees `timeSeries Path -dt`).

use super::at2::line_units;
use super::{
    AccelUnits, GroundMotionError, Record, converted_overflow, parse_err, parse_real, push_values,
};
use crate::math::Real;
use crate::output::float_token;

impl Record {
    /// Parses a two-column CSV `t, a` (t in s, a in `units`). Blank lines and lines starting
    /// with `#` are skipped; a first non-numeric line is taken as a header. Times must increase
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
                check_csv_header_units(raw, units).map_err(|m| parse_err(source_name, k + 1, m))?;
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
    /// Blank lines and lines starting with `#` (a comment header) are skipped. Times must
    /// increase strictly. Errors carry the 1-based line number.
    pub fn from_columns_str(
        text: &str,
        source_name: &str,
        units: AccelUnits,
    ) -> Result<Self, GroundMotionError> {
        let (mut times, mut values) = (Vec::new(), Vec::new());
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

/// A CSV header that names acceleration units must agree with the units the file is read in.
fn check_csv_header_units(line: &str, units: AccelUnits) -> Result<(), String> {
    match line_units(line)? {
        Some((f, tok)) if f != units.factor() => Err(format!(
            "the header names the units {tok} but the record is read in {} (csv_units): set \
             csv_units to match (\"g\" or \"m/s2\"), or convert the file",
            units.name()
        )),
        _ => Ok(()),
    }
}
