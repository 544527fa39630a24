//! The `[hazard]` table of a fragility scenario (or a `--hazard` file): a site hazard curve read
//! and checked, errors naming the file, the key and its line.
//!
//! ```toml
//! [hazard]
//! im_unit = "g"          # required: the unit of the IM values (the fragility's IM is in g)
//! measure = "sa"         # optional: "sa" | "pga", checked against [fragility] im
//! period_s = 1.5         # optional with "sa": checked against the study's period (within 5 %)
//! k0 = 1.0e-4            # a power law λ(IM) = k0 · IM^(−k), IM in g, λ per year; or
//! k = 2.5
//! # im = [0.05, 0.1, 0.2, 0.4, 0.8]        # a table (IM increasing, rate decreasing), or
//! # rate = [2e-2, 8e-3, 2.5e-3, 6e-4, 1e-4]
//! # file = "hazard.csv"                    # a CSV table: header `im_g,rate`, then one point a line
//! ```

use super::AssessmentError;
use super::im::ImSpec;
use super::settings::ImKind;
use crate::fragility::hazard::HazardCurve;
use crate::math::Real;
use crate::toml_schema::{Table, line_col};
use serde::Deserialize;
use std::path::{Path, PathBuf};

use super::hazard_csv::check_points;
pub use super::hazard_csv::read_csv;
use toml::Spanned;

type Sp<T> = Option<Spanned<T>>;

/// A hazard curve and where it was read.
#[derive(Debug, Clone, PartialEq)]
pub struct HazardInput {
    /// The curve (IM in g, rates per year).
    pub curve: HazardCurve,
    /// Where it was read, e.g. `viaduct.toml [hazard]` or `hazard.csv`.
    pub source: String,
    /// The IM the hazard is of, when given (`measure`), and its period (`period_s`).
    pub measure: Option<(ImKind, Option<Real>)>,
    /// Where `measure` is written: (file, line), for a mismatch message.
    measure_at: (String, Option<usize>),
}

#[derive(Deserialize)]
struct File {
    hazard: Option<Spanned<Table<HazSec>>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct HazSec {
    im_unit: Sp<String>,
    measure: Sp<String>,
    period_s: Sp<Real>,
    k0: Sp<Real>,
    k: Sp<Real>,
    im: Sp<Vec<Real>>,
    rate: Sp<Vec<Real>>,
    file: Sp<String>,
}

struct Cx<'a> {
    origin: &'a str,
    text: &'a str,
}

impl Cx<'_> {
    fn line<T>(&self, s: &Spanned<T>) -> Option<usize> {
        Some(line_col(self.text, s.span().start).0)
    }
    fn err<T>(&self, key: &str, s: &Spanned<T>, message: String) -> AssessmentError {
        AssessmentError::Key {
            message,
            key: format!("hazard.{key}"),
            origin: self.origin.into(),
            line: self.line(s),
        }
    }
}

impl HazardInput {
    /// The `[hazard]` table of the TOML `text` named `origin` (`None` when it has none); a
    /// `file` is relative to `dir`.
    pub fn from_toml(
        text: &str,
        origin: &str,
        dir: &Path,
    ) -> Result<Option<Self>, AssessmentError> {
        let f: File = toml::from_str(text).map_err(|e| AssessmentError::Syntax {
            origin: origin.into(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let Some(sec) = f.hazard else {
            return Ok(None);
        };
        let cx = Cx { origin, text };
        let s = &sec.get_ref().0;
        let measure = match &s.measure {
            None => None,
            Some(m) => Some(match m.get_ref().as_str() {
                "sa" => ImKind::Sa,
                "pga" => ImKind::Pga,
                other => {
                    return Err(cx.err(
                        "measure",
                        m,
                        format!("unknown measure {other:?}: \"sa\" or \"pga\""),
                    ));
                }
            }),
        };
        if let Some(p) = &s.period_s {
            if measure != Some(ImKind::Sa) {
                return Err(cx.err("period_s", p, "needs measure = \"sa\"".into()));
            }
            if !(p.get_ref().is_finite() && *p.get_ref() > 0.0) {
                return Err(cx.err("period_s", p, "must be > 0 (seconds)".into()));
            }
        }
        let at = (
            origin.to_string(),
            s.measure.as_ref().and_then(|m| cx.line(m)),
        );
        let unit_of = |u: &Sp<String>| -> Result<(), AssessmentError> {
            match u {
                None => Err(AssessmentError::key(
                    origin,
                    "hazard.im_unit",
                    cx.line(&sec),
                    "missing: name the unit of the hazard's IM values (im_unit = \"g\"; the \
                     fragility's IM is in g)"
                        .into(),
                )),
                Some(u) if u.get_ref() == "g" => Ok(()),
                Some(u) => Err(cx.err(
                    "im_unit",
                    u,
                    format!(
                        "{:?}: the fragility's IM is in g; convert the hazard's IMs to g",
                        u.get_ref()
                    ),
                )),
            }
        };
        let given = [
            s.k0.is_some() || s.k.is_some(),
            s.im.is_some() || s.rate.is_some(),
            s.file.is_some(),
        ];
        if given.iter().filter(|&&g| g).count() != 1 {
            return Err(AssessmentError::key(
                origin,
                "hazard",
                cx.line(&sec),
                "give exactly one hazard curve: a power law (k0, k), a table (im, rate) or a \
                 CSV file (file)"
                    .into(),
            ));
        }
        let (curve, source) = if let Some(file) = &s.file {
            if let Some(u) = &s.im_unit {
                return Err(cx.err(
                    "im_unit",
                    u,
                    "with a file the unit is named in its header (im_g); remove im_unit".into(),
                ));
            }
            let path: PathBuf = dir.join(file.get_ref());
            let text = crate::input::read_text(&path, "hazard file", crate::input::SCENARIO_LIMIT)
                .map_err(|e| {
                    cx.err("file", file, format!("cannot read {}: {e}", path.display()))
                })?;
            let name = path.display().to_string();
            (read_csv(&text, &name)?, name)
        } else if s.k0.is_some() || s.k.is_some() {
            unit_of(&s.im_unit)?;
            let get = |k: &str, v: &Sp<Real>| -> Result<Real, AssessmentError> {
                let Some(v) = v else {
                    return Err(AssessmentError::key(
                        origin,
                        &format!("hazard.{k}"),
                        cx.line(&sec),
                        "missing: a power law needs k0 and k".into(),
                    ));
                };
                let x = *v.get_ref();
                if !(x.is_finite() && x > 0.0) {
                    return Err(cx.err(k, v, format!("{x} must be finite and > 0")));
                }
                Ok(x)
            };
            (
                HazardCurve::PowerLaw {
                    k0: get("k0", &s.k0)?,
                    k: get("k", &s.k)?,
                },
                format!("{origin} [hazard]"),
            )
        } else {
            unit_of(&s.im_unit)?;
            let (Some(im), Some(rate)) = (&s.im, &s.rate) else {
                return Err(AssessmentError::key(
                    origin,
                    if s.im.is_none() {
                        "hazard.im"
                    } else {
                        "hazard.rate"
                    },
                    cx.line(&sec),
                    "missing: a table needs im and rate".into(),
                ));
            };
            if im.get_ref().len() != rate.get_ref().len() {
                return Err(cx.err(
                    "rate",
                    rate,
                    format!(
                        "{} rates for {} IMs: one rate per IM",
                        rate.get_ref().len(),
                        im.get_ref().len()
                    ),
                ));
            }
            let pts: Vec<(Real, Real)> = im
                .get_ref()
                .iter()
                .copied()
                .zip(rate.get_ref().iter().copied())
                .collect();
            check_points(&pts).map_err(|(col, i, m)| {
                let s = if col == "im" { im } else { rate };
                cx.err(&format!("{col}[{i}]"), s, m)
            })?;
            (
                HazardCurve::Table {
                    im: im.get_ref().clone(),
                    rate: rate.get_ref().clone(),
                },
                format!("{origin} [hazard]"),
            )
        };
        Ok(Some(HazardInput {
            curve,
            source,
            measure: measure.map(|m| (m, s.period_s.as_ref().map(|p| *p.get_ref()))),
            measure_at: at,
        }))
    }

    /// A `--hazard FILE`: a `.csv` table, or a `.toml` file with a `[hazard]` table (its `file`
    /// relative to it).
    pub fn from_path(path: &Path) -> Result<Self, AssessmentError> {
        let name = path.display().to_string();
        let text = crate::input::read_text(path, "hazard file", crate::input::SCENARIO_LIMIT)
            .map_err(|e| {
                AssessmentError::Invalid(format!("cannot read hazard file {name}: {e}"))
            })?;
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("csv") => Ok(HazardInput {
                curve: read_csv(&text, &name)?,
                source: name.clone(),
                measure: None,
                measure_at: (name, None),
            }),
            Some("toml") => {
                let dir = path.parent().unwrap_or(Path::new("."));
                Self::from_toml(&text, &name, dir)?.ok_or_else(|| {
                    AssessmentError::Invalid(format!("hazard file {name}: no [hazard] table"))
                })
            }
            _ => Err(AssessmentError::Invalid(format!(
                "hazard file {name}: unknown type; give a .csv table (header im_g,rate) or a \
                 .toml file with a [hazard] table"
            ))),
        }
    }

    /// Refuses a hazard of another measure or period than the study's IM (when the hazard
    /// names them).
    pub fn check_against(&self, spec: &ImSpec) -> Result<(), AssessmentError> {
        let Some((kind, period)) = self.measure else {
            return Ok(());
        };
        let (origin, line) = &self.measure_at;
        if kind != spec.kind {
            return Err(AssessmentError::key(
                origin,
                "hazard.measure",
                *line,
                format!(
                    "the hazard is of {} but the fragility's IM is {}: a hazard curve must be \
                     of the fragility's IM",
                    if kind == ImKind::Sa { "Sa" } else { "PGA" },
                    spec.label()
                ),
            ));
        }
        if let Some(t) = period
            && kind == ImKind::Sa
            && ((t - spec.period) / spec.period).abs() > 0.05
        {
            return Err(AssessmentError::key(
                origin,
                "hazard.period_s",
                *line,
                format!(
                    "the hazard is of Sa({t} s) but the fragility's IM is {} (more than 5 % \
                     apart): use the hazard curve at the fragility's period",
                    spec.label()
                ),
            ));
        }
        Ok(())
    }
}
