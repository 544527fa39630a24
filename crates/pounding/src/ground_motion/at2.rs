//! PEER NGA `.AT2` records: the header (kind, units, `NPTS`/`DT` in every style met) and the
//! values.

use super::{
    AccelUnits, G0, GroundMotionError, Record, parse_err, parse_real, push_values, quote, strip_bom,
};
use crate::math::Real;

impl Record {
    /// Parses a PEER NGA `.AT2` file (accelerations, converted to m/s²).
    ///
    /// Layout: three header lines, then either `NPTS=  5372, DT=   .0100 SEC,` (NGA-West2
    /// style; also `NPTS= 1559, DT= .02 SEC`, lower case, spaces around `=`) or the older
    /// `  5372   .0100   NPTS, DT` line (first two numbers = npts, dt), then
    /// exactly `npts` values, any number per line, whitespace separated, Fortran `E`/`D` format.
    /// The first sample is at `t = 0`. Errors carry the 1-based line number.
    ///
    /// The header is read, not assumed: a header line that says `VELOCITY` or `DISPLACEMENT`
    /// (PEER's `.VT2`/`.DT2` series) is refused whatever the file is called, and the units of a
    /// line `... IN UNITS OF <U>` are converted: `G` (PEER's usual), `CM/S/S` (also `CM/S^2`,
    /// `CM/S2`, `CM/SEC/SEC`, `GAL`) and `M/S/S` (also `M/S^2`, `M/S2`, `M/SEC/SEC`); other units
    /// are refused. A header that names no units is read in g, as PEER's files are.
    pub fn from_at2_str(text: &str, source_name: &str) -> Result<Self, GroundMotionError> {
        Self::from_at2_str_with(text, source_name, None)
    }

    /// [`Record::from_at2_str`], with units the user gave explicitly (`csv_units` or
    /// `--csv-units`, and where they came from) for a header that names none. A header that names
    /// its units keeps them (the stderr line and `summary.json` show the units as read).
    pub fn from_at2_str_with(
        text: &str,
        source_name: &str,
        given: Option<(AccelUnits, &str)>,
    ) -> Result<Self, GroundMotionError> {
        let text = strip_bom(text);
        let lines: Vec<&str> = text.lines().collect();
        if lines.len() < 4 {
            return Err(parse_err(
                source_name,
                lines.len().max(1),
                "truncated AT2 header: expected 4 header lines (the 4th giving NPTS and DT)",
            ));
        }
        let (factor, unit) =
            at2_units_factor(&lines[..4]).map_err(|(k, m)| parse_err(source_name, k, m))?;
        let factor = match (&unit, given) {
            (None, Some((units, _))) => units.factor(),
            _ => factor,
        };
        let header = lines[3];
        let header_q = quote(header);
        let (npts, dt) = parse_at2_npts_dt(header)
            .map_err(|m| parse_err(source_name, 4, format!("{m} in AT2 header line {header_q}")))?;
        // Each value needs at least one byte, so a larger NPTS cannot be honoured; refuse it
        // before allocating (an absurd NPTS would otherwise abort on allocation).
        if npts > text.len() {
            return Err(parse_err(
                source_name,
                4,
                format!(
                    "NPTS = {npts} exceeds what the file can hold ({} bytes) in AT2 header line {header_q}",
                    text.len()
                ),
            ));
        }
        let mut values = Vec::with_capacity(npts);
        for (k, line) in lines.iter().enumerate().skip(4) {
            push_values(&mut values, line, factor, Some(npts))
                .map_err(|m| parse_err(source_name, k + 1, m))?;
        }
        if values.len() != npts {
            return Err(parse_err(
                source_name,
                lines.len(),
                format!(
                    "file ends after {} values, header says NPTS = {npts}",
                    values.len()
                ),
            ));
        }
        let label = match (unit, given) {
            (Some(u), _) => format!("{u} header"),
            (None, Some((units, from))) => {
                format!("{} ({from}; the AT2 header names no units)", units.name())
            }
            (None, None) => "g (AT2 header names no units: PEER default)".to_string(),
        };
        Ok(Self::uniform(source_name, dt, values)?.with_units_label(label))
    }
}

/// The factor to m/s² of the acceleration units `token` (upper case, `**` written `^`, `SEC`
/// written `S`), or `None` if it is not a unit of acceleration this reader knows.
pub(super) fn accel_unit_factor(token: &str) -> Option<Real> {
    Some(match token {
        "G" => G0,
        "CM/S/S" | "CM/S^2" | "CM/S2" | "CM/S²" | "GAL" | "GALS" => 0.01,
        "MM/S/S" | "MM/S^2" | "MM/S2" | "MM/S²" => 0.001,
        "M/S/S" | "M/S^2" | "M/S2" | "M/S²" => 1.0,
        "IN/S/S" | "IN/S^2" | "IN/S2" | "IN/S²" => 0.0254,
        "FT/S/S" | "FT/S^2" | "FT/S2" | "FT/S²" => 0.3048,
        _ => return None,
    })
}

/// The factor to m/s² of the AT2 header `lines` (the first three, plus the `NPTS`/`DT` line), or
/// the 1-based line and reason why the file is not an acceleration record in known units.
///
/// A unit is recognised wherever the header writes it (`IN UNITS OF G`, `(CM/SEC**2)`,
/// `UNITS: CM/S/S`, on the `NPTS` line too). `G` counts only after `OF`, `IN`, `UNITS` or in
/// parentheses (a bare `G` may be part of a station name). A header that mentions units it does not
/// understand, or two different units, is refused; a header that names none is read in g (PEER).
fn at2_units_factor(lines: &[&str]) -> Result<(Real, Option<String>), (usize, String)> {
    let mut found: Option<(Real, String)> = None;
    for (k, line) in lines.iter().enumerate() {
        let upper = line.to_ascii_uppercase();
        for kind in ["VELOCITY", "DISPLACEMENT"] {
            if upper.contains(kind) && !upper.contains("ACCELERATION") {
                return Err((
                    k + 1,
                    format!(
                        "the header says {kind}: this is a {} time series, not an acceleration \
                         record; give the acceleration file (.AT2) of the same record",
                        kind.to_ascii_lowercase()
                    ),
                ));
            }
        }
        if let Some((f, tok)) = line_units(line).map_err(|m| (k + 1, m))? {
            if let Some((g, u)) = &found
                && *g != f
            {
                return Err((
                    k + 1,
                    format!(
                        "the header names two different units, {u} and {tok}; {ACCEPTED_UNITS}"
                    ),
                ));
            }
            found = Some((f, tok));
        }
    }
    Ok(match found {
        Some((f, tok)) => (f, Some(tok)),
        None => (G0, None),
    })
}

pub(super) const ACCEPTED_UNITS: &str =
    "accepted: G, CM/S/S (CM/S^2, CM/SEC**2, GAL), MM/S/S, M/S/S (M/S^2), IN/S/S, FT/S/S";

/// The acceleration unit a header `line` names (factor to m/s² and the unit as written,
/// normalised), `None` if it names none, or an error for units it mentions but this reader does
/// not know, two different units on the line (`IN UNITS OF G (CM/S/S)`), or a scaled unit
/// (`G X 1000`, `G*1000`, `1000 TIMES G`). `G` counts only after `OF`, `IN`, `UNITS` or in
/// brackets (a bare `G` may be part of a name).
pub(super) fn line_units(line: &str) -> Result<Option<(Real, String)>, String> {
    let line_q = quote(line);
    let norm = line
        .to_ascii_uppercase()
        .replace("**", "^")
        .replace("SEC", "S")
        .replace('*', " * ")
        .replace('×', " X ");
    let seps = |c: char| c.is_whitespace() || matches!(c, ',' | ':' | '=' | ';' | '_');
    let toks: Vec<(bool, &str)> = norm
        .split(seps)
        .filter(|raw| !raw.is_empty())
        .map(|raw| {
            let bracketed = raw.starts_with(['(', '[']) || raw.ends_with([')', ']']);
            (
                bracketed,
                raw.trim_matches(|c| matches!(c, '(' | ')' | '[' | ']')),
            )
        })
        .collect();
    let mut mentions_units = false;
    let mut found: Option<(Real, String)> = None;
    for (i, &(bracketed, tok)) in toks.iter().enumerate() {
        let prev = if i > 0 { toks[i - 1].1 } else { "" };
        mentions_units |= tok.starts_with("UNIT");
        let bare_g = tok == "G" && !(bracketed || matches!(prev, "OF" | "IN" | "UNITS" | "UNIT"));
        match accel_unit_factor(tok).filter(|_| !bare_g) {
            Some(f) => {
                if let Some((g, u)) = &found
                    && *g != f
                {
                    return Err(format!(
                        "the header line {line_q} names two different units, {u} and {tok}: \
                         give one; {ACCEPTED_UNITS}"
                    ));
                }
                if is_scaled(&toks, i) {
                    return Err(format!(
                        "a scaled unit is not supported: header line {line_q} multiplies {tok} \
                         by a factor; convert the values to plain units ({ACCEPTED_UNITS})"
                    ));
                }
                found = Some((f, tok.to_string()));
            }
            None if looks_like_accel_unit(tok) => {
                return Err(format!(
                    "unknown units {} in header line {line_q}; {ACCEPTED_UNITS}",
                    quote(tok)
                ));
            }
            None => {}
        }
    }
    if mentions_units && found.is_none() {
        return Err(format!(
            "cannot read the units in header line {line_q}; {ACCEPTED_UNITS}"
        ));
    }
    Ok(found)
}

/// Whether the unit at `toks[i]` carries a multiplier: followed by `X <number>`, `X<number>`,
/// `*`, `TIMES`, or preceded by `*`, `TIMES` or `<number> X` (a number alone before a unit may
/// be a component azimuth, `180 (CM/S/S)`).
fn is_scaled(toks: &[(bool, &str)], i: usize) -> bool {
    let at = |k: usize| toks.get(k).map_or("", |t| t.1);
    let number = |t: &str| parse_real(t).is_some();
    let times_word = |t: &str| matches!(t, "*" | "TIMES" | "×");
    let next = at(i + 1);
    let x_number = |t: &str| {
        t.strip_prefix('X')
            .is_some_and(|r| !r.is_empty() && number(r))
    };
    let after = times_word(next) || (next == "X" && number(at(i + 2))) || x_number(next);
    let prev = if i > 0 { at(i - 1) } else { "" };
    let before = times_word(prev) || (prev == "X" && i >= 2 && number(at(i - 2)));
    after || before
}

/// Whether `tok` looks like a unit of acceleration (`X/S/S`, `X/S^2`, `X/S2`).
pub(super) fn looks_like_accel_unit(tok: &str) -> bool {
    ["/S/S", "/S^2", "/S2", "/S²"]
        .iter()
        .any(|e| tok.ends_with(e))
}

fn parse_at2_npts_dt(line: &str) -> Result<(usize, Real), String> {
    let upper = line.to_ascii_uppercase();
    for key in ["NPTS", "DT"] {
        let n = upper
            .split(|c: char| !c.is_ascii_alphanumeric())
            .filter(|w| *w == key)
            .count();
        if n > 1 {
            return Err(format!("{key} is given {n} times"));
        }
    }
    let has_word = |key: &str| {
        upper
            .split(|c: char| !c.is_ascii_alphanumeric())
            .any(|w| w == key)
    };
    if !has_word("NPTS") && has_word("DT") {
        return Err(
            "NPTS is missing (the 4th header line gives the number of values and the \
             sample interval: NPTS= N, DT= SECONDS SEC)"
                .into(),
        );
    }
    let new_style = upper
        .find("NPTS")
        .is_some_and(|p| upper[p + 4..].trim_start().starts_with('='));
    let (npts_s, dt_s) = if new_style {
        // NGA-West2: `NPTS=   5372, DT=   .0100 SEC,`
        let grab = |key: &str| -> Option<String> {
            let p = upper.find(key)? + key.len();
            let rest = upper[p..].trim_start().strip_prefix('=')?.trim_start();
            let end = rest
                .find(|c: char| c == ',' || c.is_whitespace())
                .unwrap_or(rest.len());
            Some(rest[..end].to_string())
        };
        // DT must be in seconds: the word after its value, if any, must say so.
        if let Some(p) = upper.find("DT") {
            let after = upper[p + 2..].trim_start().strip_prefix('=').unwrap_or("");
            let mut words = after
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|w| !w.is_empty());
            let _value = words.next();
            if let Some(unit) = words.next()
                && !matches!(unit, "SEC" | "S" | "SECS" | "SECOND" | "SECONDS")
                && !unit.starts_with("NPTS")
            {
                return Err(format!(
                    "DT is given in {}: only seconds (SEC) are accepted",
                    quote(unit)
                ));
            }
        }
        (
            grab("NPTS").ok_or("cannot find NPTS=")?,
            grab("DT").ok_or("cannot find DT=")?,
        )
    } else {
        // Older style: `  5372   .0100   NPTS, DT`
        let mut toks = upper
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty());
        (
            toks.next().ok_or("empty NPTS/DT line")?.to_string(),
            toks.next().ok_or("missing DT after NPTS")?.to_string(),
        )
    };
    let npts: usize = npts_s
        .parse()
        .map_err(|_| format!("NPTS {} is not a positive integer", quote(&npts_s)))?;
    if npts == 0 {
        return Err("NPTS = 0".into());
    }
    let dt = parse_real(&dt_s).ok_or_else(|| format!("DT {} is not a number", quote(&dt_s)))?;
    if dt <= 0.0 {
        return Err(format!(
            "DT = {} must be > 0",
            crate::output::float_token(dt)
        ));
    }
    Ok((npts, dt))
}
