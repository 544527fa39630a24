//! Ground-motion records and the two-component horizontal ground acceleration driving a simulation.
//!
//! * [`Record`]: one acceleration component, a list of samples `(t_i, a_i)` in m/s², with linear
//!   interpolation between samples and `a = 0` before the first and after the last sample.
//! * Readers: PEER NGA `.AT2` ([`Record::from_at2_str`], both header styles) and two-column CSV
//!   `t, a` ([`Record::from_csv_str`]). Record units are converted to m/s² (`g` → ×[`G0`]).
//! * [`GroundMotion`]: two horizontal components, one nominally along the global y axis of the
//!   spec (normal to the joint, spec §4) and one along x, each with a scale factor, both turned by an
//!   incidence angle `α` (counter-clockwise about +z):
//!   `a_g(t) = s_y a_y(t) Rot(α) ŷ + s_x a_x(t) Rot(α) x̂`.
//!   **Sign convention**: a positive sample accelerates the *ground* toward +y (resp. +x); the
//!   structure feels the effective load `−M r a_g(t)` (see [`crate::sim`]).
//! * [`el_centro_1940`]: the 1940 El Centro record (PEER NGA-West2 RSN 6, components 180 and 270),
//!   embedded in the library.

use crate::math::{Real, Vector};
use std::path::Path;
use thiserror::Error;

/// Standard gravity \[m/s²\]: the factor from records in `g` to m/s².
pub const G0: Real = 9.80665;

/// Bad ground-motion input.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum GroundMotionError {
    /// A record file is malformed; `line` is 1-based.
    #[error("{source_name}:{line}: {message}")]
    Parse {
        /// File name (or a description of the text's origin).
        source_name: String,
        /// 1-based line number of the offending line.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A record file could not be read.
    #[error("cannot read ground-motion record {path}: {message}")]
    Io {
        /// The path as given.
        path: String,
        /// The operating-system message.
        message: String,
    },
    /// A parameter is out of range or not finite; the message names it.
    #[error("invalid {name} = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// Parameter name.
        name: String,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
}

/// Units of the acceleration values in a record file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AccelUnits {
    /// Standard gravity; values are multiplied by [`G0`] = 9.80665.
    #[default]
    G,
    /// Already in m/s².
    MetresPerSecondSquared,
}

impl AccelUnits {
    /// The factor to m/s².
    pub fn factor(self) -> Real {
        match self {
            Self::G => G0,
            Self::MetresPerSecondSquared => 1.0,
        }
    }
    /// Parses `g` or `m/s2` (also `m/s^2`, `mps2`).
    pub fn from_name(s: &str) -> Option<Self> {
        match s.trim() {
            "g" | "G" => Some(Self::G),
            "m/s2" | "m/s^2" | "mps2" | "m/s²" => Some(Self::MetresPerSecondSquared),
            _ => None,
        }
    }
}

/// One acceleration component: samples `(t_i, a_i)`, `t` strictly increasing \[s\], `a` in m/s².
///
/// Evaluation ([`Record::accel`]) interpolates linearly between samples and is zero outside
/// `[t_0, t_last]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    /// A short name (file name or component label) for messages and outputs.
    pub name: String,
    times: Vec<Real>,
    values: Vec<Real>,
}

fn parse_err(source: &str, line: usize, message: impl Into<String>) -> GroundMotionError {
    GroundMotionError::Parse {
        source_name: source.to_string(),
        line,
        message: message.into(),
    }
}

/// The message of a record value that is finite in the file but not once converted to m/s².
fn converted_overflow(tok: &str, factor: Real) -> String {
    format!(
        "the value {tok} overflows when converted to m/s² (× {}): use a value of a physical \
         magnitude",
        crate::output::float_token(factor)
    )
}

/// Parses a Fortran-style real (`.998E-03`, `1.5D-03`, `-.17e+01`).
fn parse_real(tok: &str) -> Option<Real> {
    let v: Real = if tok.contains(['D', 'd']) {
        tok.replace(['D', 'd'], "E").parse().ok()?
    } else {
        tok.parse().ok()?
    };
    v.is_finite().then_some(v)
}

impl Record {
    /// A record from explicit samples (`t` strictly increasing and finite, `a` finite, in m/s²).
    pub fn new(
        name: impl Into<String>,
        times: Vec<Real>,
        values: Vec<Real>,
    ) -> Result<Self, GroundMotionError> {
        let name = name.into();
        let bad = |what: &str, v: Real, reason: &str| GroundMotionError::InvalidParameter {
            name: format!("{name}: {what}"),
            value: v,
            reason: reason.to_string(),
        };
        if times.is_empty() || times.len() != values.len() {
            return Err(bad(
                "number of samples",
                times.len() as Real,
                "need at least one sample and as many times as values",
            ));
        }
        for (i, (&t, &a)) in times.iter().zip(&values).enumerate() {
            if !t.is_finite() {
                return Err(bad(&format!("t[{i}]"), t, "must be finite"));
            }
            if !a.is_finite() {
                return Err(bad(&format!("a[{i}]"), a, "must be finite"));
            }
            if i == 0 && t < 0.0 {
                return Err(bad(
                    "t[0]",
                    t,
                    "the record must start at t >= 0 (the analysis starts at t = 0; earlier samples would be dropped)",
                ));
            }
            if i > 0 && t <= times[i - 1] {
                return Err(bad(&format!("t[{i}]"), t, "times must increase strictly"));
            }
        }
        Ok(Self {
            name,
            times,
            values,
        })
    }

    /// A uniformly sampled record `a_i` at `t_i = i dt` (values in m/s²).
    pub fn uniform(
        name: impl Into<String>,
        dt: Real,
        values: Vec<Real>,
    ) -> Result<Self, GroundMotionError> {
        let name = name.into();
        if !(dt.is_finite() && dt > 0.0) {
            return Err(GroundMotionError::InvalidParameter {
                name: format!("{name}: dt"),
                value: dt,
                reason: "must be finite and > 0".into(),
            });
        }
        let times = (0..values.len()).map(|i| i as Real * dt).collect();
        Self::new(name, times, values)
    }

    /// Parses a PEER NGA `.AT2` file (accelerations, converted to m/s²).
    ///
    /// Layout: three header lines, then either `NPTS=  5372, DT=   .0100 SEC,` (NGA-West2
    /// style) or the older `  5372   .0100   NPTS, DT` line (first two numbers = npts, dt), then
    /// exactly `npts` values, any number per line, whitespace separated, Fortran `E`/`D` format.
    /// The first sample is at `t = 0`. Errors carry the 1-based line number.
    ///
    /// The header is read, not assumed: a header line that says `VELOCITY` or `DISPLACEMENT`
    /// (PEER's `.VT2`/`.DT2` series) is refused whatever the file is called, and the units of a
    /// line `... IN UNITS OF <U>` are converted: `G` (PEER's usual), `CM/S/S` (also `CM/S^2`,
    /// `CM/S2`, `CM/SEC/SEC`, `GAL`) and `M/S/S` (also `M/S^2`, `M/S2`, `M/SEC/SEC`); other units
    /// are refused. A header that names no units is read in g, as PEER's files are.
    pub fn from_at2_str(text: &str, source_name: &str) -> Result<Self, GroundMotionError> {
        let lines: Vec<&str> = text.lines().collect();
        if lines.len() < 4 {
            return Err(parse_err(
                source_name,
                lines.len().max(1),
                "truncated AT2 header: expected 4 header lines (the 4th giving NPTS and DT)",
            ));
        }
        let factor =
            at2_units_factor(&lines[..4]).map_err(|(k, m)| parse_err(source_name, k, m))?;
        let header = lines[3];
        let (npts, dt) = parse_at2_npts_dt(header)
            .map_err(|m| parse_err(source_name, 4, format!("{m} in AT2 header line {header:?}")))?;
        // Each value needs at least one byte, so a larger NPTS cannot be honoured; refuse it
        // before allocating (an absurd NPTS would otherwise abort on allocation).
        if npts > text.len() {
            return Err(parse_err(
                source_name,
                4,
                format!(
                    "NPTS = {npts} exceeds what the file can hold ({} bytes) in AT2 header line {header:?}",
                    text.len()
                ),
            ));
        }
        let mut values = Vec::with_capacity(npts);
        for (k, line) in lines.iter().enumerate().skip(4) {
            for tok in line.split_whitespace() {
                let v = parse_real(tok).ok_or_else(|| {
                    parse_err(source_name, k + 1, format!("not a finite number: {tok:?}"))
                })?;
                if values.len() == npts {
                    return Err(parse_err(
                        source_name,
                        k + 1,
                        format!("more values than NPTS = {npts}"),
                    ));
                }
                if !(v * factor).is_finite() {
                    return Err(parse_err(
                        source_name,
                        k + 1,
                        converted_overflow(tok, factor),
                    ));
                }
                values.push(v * factor);
            }
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
        Self::uniform(source_name, dt, values)
    }

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
                (Some(t), Some(a)) => {
                    if let Some(&prev) = times.last()
                        && t <= prev
                    {
                        return Err(parse_err(
                            source_name,
                            k + 1,
                            format!(
                                "time {} does not increase (previous {})",
                                crate::output::float_token(t),
                                crate::output::float_token(prev)
                            ),
                        ));
                    }
                    if !(a * units.factor()).is_finite() {
                        return Err(parse_err(
                            source_name,
                            k + 1,
                            converted_overflow(cols[1], units.factor()),
                        ));
                    }
                    times.push(t);
                    values.push(a * units.factor());
                }
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
        Self::new(source_name, times, values)
    }

    /// Reads a record file: `.csv` (any case) as CSV in `csv_units`, anything else as PEER `.AT2`.
    pub fn from_path(path: &Path, csv_units: AccelUnits) -> Result<Self, GroundMotionError> {
        let text =
            crate::input::read_text(path, "ground-motion record", crate::input::RECORD_LIMIT)
                .map_err(|e| GroundMotionError::Io {
                    path: path.display().to_string(),
                    message: e.to_string(),
                })?;
        let name = path.display().to_string();
        if let Some(ext) = path.extension().and_then(|e| e.to_str())
            && ["VT2", "DT2"].iter().any(|k| ext.eq_ignore_ascii_case(k))
        {
            return Err(parse_err(
                &name,
                1,
                format!(
                    "a .{ext} file is a PEER velocity or displacement time series, not an \
                     acceleration record; give the .AT2 file of the same record"
                ),
            ));
        }
        let is_csv = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("csv"));
        if is_csv {
            Self::from_csv_str(&text, &name, csv_units)
        } else {
            Self::from_at2_str(&text, &name)
        }
    }

    /// Sample times \[s\].
    pub fn times(&self) -> &[Real] {
        &self.times
    }
    /// Sample values \[m/s²\].
    pub fn values(&self) -> &[Real] {
        &self.values
    }
    /// Time of the last sample \[s\]; the record is zero afterwards.
    pub fn end_time(&self) -> Real {
        *self.times.last().expect("non-empty by construction")
    }
    /// Peak absolute acceleration \[m/s²\].
    pub fn pga(&self) -> Real {
        self.values.iter().fold(0.0, |m: Real, v| m.max(v.abs()))
    }

    /// `a(t)`: linear interpolation between samples, 0 before `t_0` and after `t_last` \[m/s²\].
    pub fn accel(&self, t: Real) -> Real {
        let ts = &self.times;
        let n = ts.len();
        if !(t >= ts[0] && t <= ts[n - 1]) {
            return 0.0;
        }
        // Index of the last sample with t_i <= t.
        let i = ts.partition_point(|&ti| ti <= t).saturating_sub(1);
        self.interp(i, t)
    }

    #[inline]
    fn interp(&self, i: usize, t: Real) -> Real {
        let (ts, vs) = (&self.times, &self.values);
        if i + 1 >= ts.len() {
            return vs[i];
        }
        let s = (t - ts[i]) / (ts[i + 1] - ts[i]);
        vs[i] + s * (vs[i + 1] - vs[i])
    }

    /// `a(t_k)` at `t_k = k h`, `k = 0..=n_steps`, in one monotone pass (same values as
    /// [`Record::accel`]).
    pub fn sample_uniform(&self, h: Real, n_steps: usize) -> Vec<Real> {
        let ts = &self.times;
        let last = ts.len() - 1;
        let mut out = Vec::with_capacity(n_steps + 1);
        let mut i = 0usize;
        for k in 0..=n_steps {
            let t = k as Real * h;
            if !(t >= ts[0] && t <= ts[last]) {
                out.push(0.0);
                continue;
            }
            while i < last && ts[i + 1] <= t {
                i += 1;
            }
            out.push(self.interp(i, t));
        }
        out
    }
}

/// The factor to m/s² of the acceleration units `token` (upper case, `**` written `^`, `SEC`
/// written `S`), or `None` if it is not a unit of acceleration this reader knows.
fn accel_unit_factor(token: &str) -> Option<Real> {
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
fn at2_units_factor(lines: &[&str]) -> Result<Real, (usize, String)> {
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
    Ok(found.map_or(G0, |(f, _)| f))
}

const ACCEPTED_UNITS: &str =
    "accepted: G, CM/S/S (CM/S^2, CM/SEC**2, GAL), MM/S/S, M/S/S (M/S^2), IN/S/S, FT/S/S";

/// The acceleration unit a header `line` names (factor to m/s² and the unit as written,
/// normalised), `None` if it names none, or an error for units it mentions but this reader does
/// not know. `G` counts only after `OF`, `IN`, `UNITS` or in brackets (a bare `G` may be part of a
/// name).
fn line_units(line: &str) -> Result<Option<(Real, String)>, String> {
    let norm = line
        .to_ascii_uppercase()
        .replace("**", "^")
        .replace("SEC", "S");
    let mut prev = "";
    let mut mentions_units = false;
    let mut found = None;
    let seps = |c: char| c.is_whitespace() || matches!(c, ',' | ':' | '=' | ';' | '_');
    for raw in norm.split(seps) {
        if raw.is_empty() {
            continue;
        }
        let bracketed = raw.starts_with(['(', '[']) || raw.ends_with([')', ']']);
        let tok = raw.trim_matches(|c| matches!(c, '(' | ')' | '[' | ']'));
        mentions_units |= tok.starts_with("UNIT");
        let bare_g = tok == "G" && !(bracketed || matches!(prev, "OF" | "IN" | "UNITS" | "UNIT"));
        match accel_unit_factor(tok).filter(|_| !bare_g) {
            Some(f) => found = Some((f, tok.to_string())),
            None if looks_like_accel_unit(tok) => {
                return Err(format!(
                    "unknown units {tok:?} in header line {line:?}; {ACCEPTED_UNITS}"
                ));
            }
            None => {}
        }
        prev = tok;
    }
    if mentions_units && found.is_none() {
        return Err(format!(
            "cannot read the units in header line {line:?}; {ACCEPTED_UNITS}"
        ));
    }
    Ok(found)
}

/// A CSV header that names acceleration units must agree with the units the file is read in.
fn check_csv_header_units(line: &str, units: AccelUnits) -> Result<(), String> {
    match line_units(line)? {
        Some((f, tok)) if f != units.factor() => Err(format!(
            "the header names the units {tok} but the record is read in {} (csv_units): set \
             csv_units to match (\"g\" or \"m/s2\"), or convert the file",
            match units {
                AccelUnits::G => "g",
                AccelUnits::MetresPerSecondSquared => "m/s2",
            }
        )),
        _ => Ok(()),
    }
}

/// Whether `tok` looks like a unit of acceleration (`X/S/S`, `X/S^2`, `X/S2`).
fn looks_like_accel_unit(tok: &str) -> bool {
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
    let (npts_s, dt_s) = if upper.contains("NPTS=") || upper.contains("NPTS =") {
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
                    "DT is given in {unit:?}: only seconds (SEC) are accepted"
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
        .map_err(|_| format!("NPTS {npts_s:?} is not a positive integer"))?;
    if npts == 0 {
        return Err("NPTS = 0".into());
    }
    let dt = parse_real(&dt_s).ok_or_else(|| format!("DT {dt_s:?} is not a number"))?;
    if dt <= 0.0 {
        return Err(format!(
            "DT = {} must be > 0",
            crate::output::float_token(dt)
        ));
    }
    Ok((npts, dt))
}

/// Two horizontal ground-acceleration components with scale factors and an incidence angle.
///
/// `a_g(t) = scale_y a_y(t) Rot(α) (0, 1) + scale_x a_x(t) Rot(α) (1, 0)` \[m/s²\], global frame of
/// spec §4 (y normal to the joint, pointing into deck 1). A positive value accelerates the ground
/// toward that direction. A missing component is zero.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundMotion {
    /// Component acting along `Rot(α) ŷ` (normal to the joint for `α = 0`).
    pub along_y: Option<Record>,
    /// Scale factor of `along_y` (any finite number).
    pub scale_y: Real,
    /// Component acting along `Rot(α) x̂` (along the joint line for `α = 0`).
    pub along_x: Option<Record>,
    /// Scale factor of `along_x` (any finite number).
    pub scale_x: Real,
    /// Incidence angle `α` \[rad\], counter-clockwise about +z.
    pub incidence: Real,
}

impl GroundMotion {
    /// No ground motion (free vibration).
    pub fn none() -> Self {
        Self {
            along_y: None,
            scale_y: 1.0,
            along_x: None,
            scale_x: 1.0,
            incidence: 0.0,
        }
    }

    /// Checks that the scale factors and the angle are finite.
    pub fn validate(&self) -> Result<(), GroundMotionError> {
        for (name, v) in [
            ("scale_y", self.scale_y),
            ("scale_x", self.scale_x),
            ("incidence", self.incidence),
        ] {
            if !v.is_finite() {
                return Err(GroundMotionError::InvalidParameter {
                    name: name.into(),
                    value: v,
                    reason: "must be finite".into(),
                });
            }
        }
        if self.incidence.abs() > 2.0 * std::f64::consts::PI * (1.0 + 1e-12) {
            return Err(GroundMotionError::InvalidParameter {
                name: "incidence".into(),
                value: self.incidence.to_degrees(),
                reason: "must lie in [-360, 360] deg".into(),
            });
        }
        Ok(())
    }

    /// Unit directions `(d_y, d_x) = (Rot(α) ŷ, Rot(α) x̂)` of the two components.
    pub fn directions(&self) -> (Vector, Vector) {
        let (s, c) = self.incidence.sin_cos();
        (Vector::new(-s, c), Vector::new(c, s))
    }

    /// Time of the last sample of the longer component (0 without components) \[s\].
    pub fn end_time(&self) -> Real {
        [&self.along_y, &self.along_x]
            .into_iter()
            .flatten()
            .map(Record::end_time)
            .fold(0.0, Real::max)
    }

    /// `a_g(t)` in the global frame \[m/s²\].
    pub fn accel(&self, t: Real) -> Vector {
        let (dy, dx) = self.directions();
        let ay = self.along_y.as_ref().map_or(0.0, |r| r.accel(t)) * self.scale_y;
        let ax = self.along_x.as_ref().map_or(0.0, |r| r.accel(t)) * self.scale_x;
        dy * ay + dx * ax
    }

    /// `a_g(k h)` for `k = 0..=n_steps` (global frame), one monotone pass per component.
    pub fn sample_uniform(&self, h: Real, n_steps: usize) -> Vec<Vector> {
        let (dy, dx) = self.directions();
        let ay = self.along_y.as_ref().map(|r| r.sample_uniform(h, n_steps));
        let ax = self.along_x.as_ref().map(|r| r.sample_uniform(h, n_steps));
        (0..=n_steps)
            .map(|k| {
                let y = ay.as_ref().map_or(0.0, |v| v[k]) * self.scale_y;
                let x = ax.as_ref().map_or(0.0, |v| v[k]) * self.scale_x;
                dy * y + dx * x
            })
            .collect()
    }
}

/// The embedded El Centro 1940 NS component (RSN 6, azimuth 180), PEER `.AT2` text.
pub const EL_CENTRO_180_AT2: &str =
    include_str!("../../../data/records/RSN6_IMPVALL.I_I-ELC180-hor1.AT2");
/// The embedded El Centro 1940 EW component (RSN 6, azimuth 270), PEER `.AT2` text.
pub const EL_CENTRO_270_AT2: &str =
    include_str!("../../../data/records/RSN6_IMPVALL.I_I-ELC270-hor2.AT2");

/// 1940 El Centro (Imperial Valley-02, El Centro Array #9, PEER NGA-West2 RSN 6), unscaled:
/// component 180 (NS, PGA 0.281 g) along y, component 270 (EW, PGA 0.211 g) along x, `α = 0`.
pub fn el_centro_1940() -> GroundMotion {
    let y = Record::from_at2_str(EL_CENTRO_180_AT2, "RSN6_IMPVALL.I_I-ELC180-hor1.AT2")
        .expect("embedded record parses");
    let x = Record::from_at2_str(EL_CENTRO_270_AT2, "RSN6_IMPVALL.I_I-ELC270-hor2.AT2")
        .expect("embedded record parses");
    GroundMotion {
        along_y: Some(y),
        scale_y: 1.0,
        along_x: Some(x),
        scale_x: 1.0,
        incidence: 0.0,
    }
}
