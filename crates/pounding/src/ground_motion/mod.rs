//! Ground-motion records and the two-component horizontal ground acceleration driving a simulation.
//!
//! * [`Record`]: one acceleration component, a list of samples `(t_i, a_i)` in m/s², with linear
//!   interpolation between samples and `a = 0` before the first and after the last sample.
//! * Readers (one file per format; the format of a file is decided in one place,
//!   [`format::detect`]): PEER NGA `.AT2` ([`Record::from_at2_str`], every header style, units read
//!   from the header), CSV `t, a` ([`Record::from_csv_str`]), whitespace-separated columns `t a`
//!   ([`Record::from_columns_str`]) and a sequence of accelerations with a given sample interval
//!   (OpenSees `timeSeries Path -dt`, [`Record::from_sequence_str`]). Values are converted to m/s²
//!   (`g` → ×[`G0`]); each record remembers the units it was read in ([`Record::units`]).
//! * [`GroundMotion`]: two horizontal components, one nominally along the global y axis of the
//!   spec (normal to the joint, spec §4) and one along x, each with a scale factor, both turned by an
//!   incidence angle `α` (counter-clockwise about +z):
//!   `a_g(t) = s_y a_y(t) Rot(α) ŷ + s_x a_x(t) Rot(α) x̂`.
//!   **Sign convention**: a positive sample accelerates the *ground* toward +y (resp. +x); the
//!   structure feels the effective load `−M r a_g(t)` (see [`crate::sim`]).
//! * [`el_centro_1940`]: the 1940 El Centro record (PEER NGA-West2 RSN 6, components 180 and 270),
//!   embedded in the library.

use crate::math::{Real, Vector};
use thiserror::Error;

mod at2;
pub mod format;
pub mod integral;
pub mod set;
pub mod support_file;
pub mod svgm;
pub mod synth;
mod text;
pub use format::{ACCEPTED_FORMATS, ReadOptions, RecordFormat};

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
        /// The parameter, typed ([`MotionParam::Other`] for a record's own samples).
        param: MotionParam,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
}

/// Which parameter of a [`GroundMotion`] a [`GroundMotionError::InvalidParameter`] concerns, typed
/// so that a front end maps it to its own key without reading the message.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MotionParam {
    /// [`GroundMotion::scale_y`].
    ScaleY,
    /// [`GroundMotion::scale_x`].
    ScaleX,
    /// [`GroundMotion::incidence`].
    Incidence,
    /// A record's samples or sample interval (named in the message).
    Other,
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
    /// The name as written in `csv_units` / `--csv-units`: `g` or `m/s2`.
    pub fn name(self) -> &'static str {
        match self {
            Self::G => "g",
            Self::MetresPerSecondSquared => "m/s2",
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
    /// Samples, shared between clones: a record set whose entries name the same file holds its
    /// samples once (a 200 000-row manifest copied them per entry and ran out of memory).
    times: std::sync::Arc<[Real]>,
    values: std::sync::Arc<[Real]>,
    /// The units as read (e.g. `CM/S/S header`, `g (csv_units default)`).
    units: String,
    /// The sample interval of a uniformly sampled record \[s\], `None` if irregular.
    dt: Option<Real>,
}

pub(super) fn parse_err(
    source: &str,
    line: usize,
    message: impl Into<String>,
) -> GroundMotionError {
    GroundMotionError::Parse {
        source_name: source.to_string(),
        line,
        message: message.into(),
    }
}

/// The message of a record value that is finite in the file but not once converted to m/s².
pub(super) fn converted_overflow(tok: &str, factor: Real) -> String {
    format!(
        "the value {tok} overflows when converted to m/s² (× {}): use a value of a physical \
         magnitude",
        crate::output::float_token(factor)
    )
}

/// The longest text (in characters) an error message quotes from a record file.
const QUOTE_MAX: usize = 80;

/// `text` quoted as `{:?}` for a message, cut after [`QUOTE_MAX`] characters with `…` (a line of a
/// megabyte, or of NUL bytes, is not echoed whole).
pub(crate) fn quote(text: &str) -> String {
    match text.char_indices().nth(QUOTE_MAX) {
        Some((i, _)) => format!("{:?}…", &text[..i]),
        None => format!("{text:?}"),
    }
}

/// `text` without a leading byte-order mark (U+FEFF), which some editors write at the start of
/// UTF-8 files.
pub(crate) fn strip_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

/// The names of the built-in records, as given after `builtin:`.
pub const BUILTIN_RECORDS: &str = "builtin:ELC180 or builtin:ELC270";

/// The built-in record `name` (after `builtin:`): `ELC180` (El Centro 1940, component 180) or
/// `ELC270` (component 270), read from the embedded `.AT2` text; `None` for another name.
pub fn builtin_record(name: &str) -> Option<Record> {
    let (text, file) = match name {
        "ELC180" => (EL_CENTRO_180_AT2, "RSN6_IMPVALL.I_I-ELC180-hor1.AT2"),
        "ELC270" => (EL_CENTRO_270_AT2, "RSN6_IMPVALL.I_I-ELC270-hor2.AT2"),
        _ => return None,
    };
    Some(Record::from_at2_str(text, file).expect("embedded record parses"))
}

/// Parses a Fortran-style real (`.998E-03`, `1.5D-03`, `-.17e+01`).
pub(super) fn parse_real(tok: &str) -> Option<Real> {
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
            param: MotionParam::Other,
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
        let dt = uniform_step(&times);
        Ok(Self {
            name,
            times: times.into(),
            values: values.into(),
            units: "m/s2".into(),
            dt,
        })
    }

    /// The same record, labelled as read in `units` (as printed and written to `summary.json`).
    pub fn with_units_label(mut self, units: impl Into<String>) -> Self {
        self.units = units.into();
        self
    }

    /// The units the record was read in, and where they came from (`CM/S/S header`,
    /// `g (csv_units default)`, `m/s2 (--csv-units)`, `m/s2` for [`Record::new`]).
    pub fn units(&self) -> &str {
        &self.units
    }

    /// The sample interval \[s\] of a uniformly sampled record (every interval within 1e-6
    /// relative of the mean, shown to 12 significant digits), `None` if irregular or one sample.
    pub fn dt(&self) -> Option<Real> {
        self.dt
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
                param: MotionParam::Other,
                value: dt,
                reason: "must be finite and > 0".into(),
            });
        }
        let times = (0..values.len()).map(|i| i as Real * dt).collect();
        let mut r = Self::new(name, times, values)?;
        r.dt = (r.times.len() > 1).then_some(dt);
        Ok(r)
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

/// The common step of `times` (12 significant digits) when every interval is within 1e-6
/// relative of the mean, else `None`.
fn uniform_step(times: &[Real]) -> Option<Real> {
    let n = times.len();
    if n < 2 {
        return None;
    }
    let mean = (times[n - 1] - times[0]) / (n - 1) as Real;
    let uniform = times
        .windows(2)
        .all(|w| ((w[1] - w[0]) - mean).abs() <= 1e-6 * mean);
    let rounded: Real = format!("{mean:.11e}").parse().unwrap_or(mean);
    uniform.then_some(rounded)
}

/// What a simulation used of one ground-motion component, as read (before the scale factor):
/// printed by `simulate` and written to `summary.json` (`ground_motion.components`).
#[derive(Debug, Clone, PartialEq)]
pub struct ComponentInfo {
    /// `"y"` or `"x"`.
    pub component: &'static str,
    /// The record's name ([`Record::name`]: the file as opened, or the built-in record's file).
    pub record: String,
    /// The units as read ([`Record::units`]).
    pub units: String,
    /// Sample interval \[s\], `None` if irregular ([`Record::dt`]).
    pub dt: Option<Real>,
    /// Number of samples.
    pub npts: usize,
    /// Time of the last sample \[s\] (the record is zero afterwards).
    pub duration: Real,
    /// Peak absolute acceleration of the record as read, in g (`pga / G0`, scale not applied).
    pub pga_g: Real,
}

/// PGA as read \[g\] above which a record's units are doubted (a warning, not an error): no
/// recorded ground motion comes near it, a file in m/s² or cm/s² read as g does.
pub const PLAUSIBLE_PGA_G: Real = 2.0;

impl ComponentInfo {
    /// The warning due when the PGA as read exceeds [`PLAUSIBLE_PGA_G`] (units probably wrong),
    /// with where units come from for each kind of file.
    pub fn units_warning(&self) -> Option<String> {
        (self.pga_g > PLAUSIBLE_PGA_G).then(|| {
            format!(
                "record {} has a PGA of {} g as read in {}; check its units (a text record: \
                 csv_units / --csv-units, or its units in a record-set manifest; an AT2 record: \
                 the units of its header, or those settings when the header names none)",
                self.record,
                fixed_or_exp(self.pga_g, 3),
                self.units
            )
        })
    }

    /// The info of `record` as component `component`.
    pub fn of(component: &'static str, record: &Record) -> Self {
        Self {
            component,
            record: record.name.clone(),
            units: record.units.clone(),
            dt: record.dt,
            npts: record.times.len(),
            duration: record.end_time(),
            pga_g: record.pga() / G0,
        }
    }

    /// One line for stderr: `ground motion y: record FILE, units …, dt_s …, npts …, duration_s …,
    /// pga_g …`.
    pub fn line(&self) -> String {
        let f = crate::output::float_token;
        format!(
            "ground motion {}: record {}, units {}, dt_s {}, npts {}, duration_s {}, pga_g {}",
            self.component,
            self.record,
            self.units,
            self.dt.map_or("irregular".to_string(), f),
            self.npts,
            f(self.duration),
            fixed_or_exp(self.pga_g, 4)
        )
    }
}

/// `x` with `digits` decimals, or in scientific notation once it is too large for that to
/// be readable (`1e300 g` as 301 digits, in a trial).
fn fixed_or_exp(x: Real, digits: usize) -> String {
    if x.abs() < 1e6 || !x.is_finite() {
        format!("{x:.digits$}")
    } else {
        format!("{x:.digits$e}")
    }
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
        for (name, param, v) in [
            ("scale_y", MotionParam::ScaleY, self.scale_y),
            ("scale_x", MotionParam::ScaleX, self.scale_x),
            ("incidence", MotionParam::Incidence, self.incidence),
        ] {
            if !v.is_finite() {
                return Err(GroundMotionError::InvalidParameter {
                    name: name.into(),
                    param,
                    value: v,
                    reason: "must be finite".into(),
                });
            }
        }
        if self.incidence.abs() > 2.0 * std::f64::consts::PI * (1.0 + 1e-12) {
            return Err(GroundMotionError::InvalidParameter {
                name: "incidence".into(),
                param: MotionParam::Incidence,
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

    /// What each present component is, as read: y then x ([`ComponentInfo`]).
    pub fn components(&self) -> Vec<ComponentInfo> {
        [("y", &self.along_y), ("x", &self.along_x)]
            .into_iter()
            .filter_map(|(c, r)| r.as_ref().map(|r| ComponentInfo::of(c, r)))
            .collect()
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
    include_str!("../../../../data/records/RSN6_IMPVALL.I_I-ELC180-hor1.AT2");
/// The embedded El Centro 1940 EW component (RSN 6, azimuth 270), PEER `.AT2` text.
pub const EL_CENTRO_270_AT2: &str =
    include_str!("../../../../data/records/RSN6_IMPVALL.I_I-ELC270-hor2.AT2");

/// 1940 El Centro (Imperial Valley-02, El Centro Array #9, PEER NGA-West2 RSN 6), unscaled:
/// component 180 (NS, PGA 0.281 g) along y, component 270 (EW, PGA 0.211 g) along x, `α = 0`.
pub fn el_centro_1940() -> GroundMotion {
    GroundMotion {
        along_y: builtin_record("ELC180"),
        scale_y: 1.0,
        along_x: builtin_record("ELC270"),
        scale_x: 1.0,
        incidence: 0.0,
    }
}

/// The lines holding data (1-based number, trimmed text): not blank, not a `#` comment.
pub(super) fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(k, l)| (k + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
}

/// Appends the whitespace-separated values of `line` (Fortran `E`/`D` format) times `factor` to
/// `values`, at most `limit` values in all: the message of the first bad token.
pub(super) fn push_values(
    values: &mut Vec<Real>,
    line: &str,
    factor: Real,
    limit: Option<usize>,
) -> Result<(), String> {
    for tok in line.split_whitespace() {
        let v = parse_real(tok).ok_or_else(|| format!("not a finite number: {}", quote(tok)))?;
        if let Some(n) = limit
            && values.len() == n
        {
            return Err(format!("more values than NPTS = {n}"));
        }
        if !(v * factor).is_finite() {
            return Err(converted_overflow(tok, factor));
        }
        values.push(v * factor);
    }
    Ok(())
}
