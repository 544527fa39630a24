//! The `[fragility]` table and the `[[limit_state]]` tables of a bridge scenario, read and
//! validated (unknown keys refused; errors name the key and its line).

use super::AssessmentError;
use crate::math::Real;
use crate::toml_schema::{Table, line_col};
use serde::Deserialize;
use std::path::PathBuf;
use toml::Spanned;

type Sp<T> = Option<Spanned<T>>;

/// The intensity measure of the stripes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImKind {
    /// Peak ground acceleration (g).
    Pga,
    /// Pseudo-spectral acceleration `Sa(T, ζ)` (g) of [`crate::spectrum`].
    Sa,
}

/// How the IM of a horizontal pair combines its components.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairIm {
    /// `√(IM_x · IM_y)`.
    GeoMean,
    /// The median over 180 rotation angles (Boore 2010), [`crate::spectrum::rotd`] for `Sa`.
    RotD50,
}

/// Largest `period_s` of `Sa` \[s\]: response spectra of engineering practice end at 10 s
/// (NGA-West2 ground-motion models; design spectra), so 20 s leaves room while refusing a
/// period that no record's spectrum describes (the spectrum module itself accepts any period
/// its arithmetic can handle, [`crate::spectrum::PERIOD_RANGE`]).
pub const MAX_PERIOD_S: Real = 20.0;

/// The period of `Sa`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PeriodChoice {
    /// Given \[s\].
    Given(Real),
    /// The bridge's fundamental period ([`super::im::fundamental_period`]).
    Model,
}

/// What the runs of a record are.
#[derive(Debug, Clone, PartialEq)]
pub enum Stripes {
    /// Multiple-stripe analysis: every record scaled so that its IM equals each level \[g\].
    Levels(Vec<Real>),
    /// Plain scale-factor IDA: each record times each factor (IM = factor × the record's IM).
    Scales(Vec<Real>),
}

/// What a limit state checks ([`super::limit`]).
#[derive(Debug, Clone, PartialEq)]
pub enum LimitKind {
    /// Any seat unseated.
    Unseating,
    /// Peak contact force at any joint above `capacity_n` (compliance laws), or peak impulse above
    /// `capacity_ns` (rigid law).
    JointForce {
        /// \[N\].
        capacity_n: Option<Real>,
        /// \[N s\].
        capacity_ns: Option<Real>,
    },
    /// Peak bearing deformation of any segment above `limit_m` \[m\].
    BearingDeformation(Real),
    /// Peak rotation of any segment above `limit_deg` \[deg\].
    Rotation(Real),
    /// Peak opening of any joint above `limit_m` \[m\].
    JointOpening(Real),
    /// Peak drift (cap displacement magnitude) of any pier above `limit_m` \[m\].
    PierDrift(Real),
    /// Peak displacement of any backwall into the soil above `limit_m` \[m\].
    Backwall(Real),
    /// Any shear key reaches its capacity (yields).
    ShearKey,
}

/// A named limit state.
#[derive(Debug, Clone, PartialEq)]
pub struct LimitState {
    /// Its name (columns `<name>_exceeded`, `<name>_ratio`).
    pub name: String,
    /// What it checks.
    pub kind: LimitKind,
    /// Where it is written, for messages: `limit_state[i]` and the file and line.
    pub at: (String, Option<usize>),
}

/// The settings of a fragility study.
#[derive(Debug, Clone, PartialEq)]
pub struct FragilitySettings {
    /// The manifest, relative to the scenario's directory (`None`: not given).
    pub records: Option<PathBuf>,
    /// The line of `records` in the scenario.
    pub records_line: Option<usize>,
    /// The intensity measure.
    pub im: ImKind,
    /// The period of `Sa`.
    pub period: PeriodChoice,
    /// Damping ratio of `Sa`.
    pub damping: Real,
    /// The IM of pairs.
    pub pair_im: PairIm,
    /// Stripes or scales.
    pub stripes: Stripes,
    /// Bootstrap resamples (0: no intervals).
    pub bootstrap: usize,
    /// Seed of the bootstrap.
    pub seed: u64,
    /// Confidence level of the intervals, in (0, 1).
    pub level: Real,
    /// The limit states, in the file's order.
    pub limit_states: Vec<LimitState>,
}

#[derive(Deserialize)]
struct File {
    fragility: Option<Spanned<Table<FragSec>>>,
    #[serde(default)]
    limit_state: Vec<Spanned<LimitSec>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct FragSec {
    records: Sp<String>,
    im: Sp<String>,
    period_s: Sp<toml::Value>,
    damping: Sp<Real>,
    pair_im: Sp<String>,
    levels_g: Sp<Vec<Real>>,
    scales: Sp<Vec<Real>>,
    bootstrap: Sp<i64>,
    seed: Sp<i64>,
    level: Sp<Real>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LimitSec {
    name: Spanned<String>,
    kind: Spanned<String>,
    capacity_n: Sp<Real>,
    capacity_ns: Sp<Real>,
    limit_m: Sp<Real>,
    limit_deg: Sp<Real>,
}

/// Error context: the scenario's name and text.
struct Cx<'a> {
    origin: &'a str,
    text: &'a str,
}

impl Cx<'_> {
    fn line<T>(&self, s: &Spanned<T>) -> Option<usize> {
        Some(line_col(self.text, s.span().start).0)
    }
    fn err<T>(&self, key: impl Into<String>, s: &Spanned<T>, msg: String) -> AssessmentError {
        AssessmentError::Key {
            message: msg,
            key: key.into(),
            origin: self.origin.to_string(),
            line: self.line(s),
        }
    }
    fn missing(&self, key: &str, msg: &str) -> AssessmentError {
        AssessmentError::Key {
            message: msg.to_string(),
            key: key.to_string(),
            origin: self.origin.to_string(),
            line: None,
        }
    }
}

impl FragilitySettings {
    /// Checks the `[fragility]` and `[[limit_state]]` tables of a scenario that has a
    /// `[fragility]` table (a run of it by `simulate` does not use them, but must not leave a
    /// typo in them unnoticed); `Ok` when there is none.
    pub fn check_if_present(text: &str, origin: &str) -> Result<(), AssessmentError> {
        let has = toml::from_str::<toml::Table>(text)
            .map(|t| t.contains_key("fragility"))
            .unwrap_or(false);
        if has {
            Self::from_scenario(text, origin)?;
        }
        Ok(())
    }

    /// Reads `[fragility]` and `[[limit_state]]` from the scenario `text` named `origin`.
    pub fn from_scenario(text: &str, origin: &str) -> Result<Self, AssessmentError> {
        let f: File = toml::from_str(text).map_err(|e| AssessmentError::Syntax {
            origin: origin.to_string(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let cx = Cx { origin, text };
        let Some(sec) = f.fragility else {
            return Err(cx.missing(
                "fragility",
                "the scenario has no [fragility] table (records, im, levels_g or scales, …)",
            ));
        };
        let s = &sec.get_ref().0;
        let mut out = Self::main_keys(&cx, s)?;
        if f.limit_state.is_empty() {
            return Err(cx.missing(
                "limit_state",
                "the scenario has no [[limit_state]] tables: give at least one",
            ));
        }
        for (i, l) in f.limit_state.iter().enumerate() {
            let ls = limit_state(&cx, i, l)?;
            if out.limit_states.iter().any(|o| o.name == ls.name) {
                let l = l.get_ref();
                return Err(cx.err(
                    format!("limit_state[{i}].name"),
                    &l.name,
                    format!("duplicate limit-state name {:?}", ls.name),
                ));
            }
            out.limit_states.push(ls);
        }
        Ok(out)
    }

    fn main_keys(cx: &Cx, s: &FragSec) -> Result<Self, AssessmentError> {
        let key = |k: &str| format!("fragility.{k}");
        let im = match &s.im {
            None => ImKind::Sa,
            Some(v) => match v.get_ref().as_str() {
                "pga" => ImKind::Pga,
                "sa" => ImKind::Sa,
                o => {
                    return Err(cx.err(
                        key("im"),
                        v,
                        format!("unknown IM {o:?}: use \"pga\" or \"sa\""),
                    ));
                }
            },
        };
        let period = match &s.period_s {
            None => PeriodChoice::Model,
            Some(v) => match v.get_ref() {
                toml::Value::String(m) if m == "model" => PeriodChoice::Model,
                toml::Value::Float(_) | toml::Value::Integer(_) => {
                    let t = v
                        .get_ref()
                        .as_float()
                        .or(v.get_ref().as_integer().map(|i| i as Real))
                        .unwrap_or(Real::NAN);
                    if !(t.is_finite() && t > 0.0 && t <= MAX_PERIOD_S) {
                        return Err(cx.err(
                            key("period_s"),
                            v,
                            format!(
                                "invalid period_s = {}: must lie in (0, {MAX_PERIOD_S}] s \
                                 (the range of engineering response spectra)",
                                crate::output::float_token(t)
                            ),
                        ));
                    }
                    PeriodChoice::Given(t)
                }
                _ => {
                    return Err(cx.err(
                        key("period_s"),
                        v,
                        "must be a period in seconds or \"model\"".into(),
                    ));
                }
            },
        };
        if let (ImKind::Pga, Some(v)) = (im, &s.period_s) {
            return Err(cx.err(
                key("period_s"),
                v,
                "applies to im = \"sa\" only; remove it for im = \"pga\"".into(),
            ));
        }
        let damping = match &s.damping {
            None => 0.05,
            Some(v) => {
                let d = *v.get_ref();
                if !(d.is_finite() && (0.0..1.0).contains(&d)) {
                    return Err(cx.err(
                        key("damping"),
                        v,
                        format!(
                            "invalid damping = {}: must be in [0, 1) (a fraction of critical)",
                            crate::output::float_token(d)
                        ),
                    ));
                }
                if im == ImKind::Pga {
                    return Err(cx.err(
                        key("damping"),
                        v,
                        "applies to im = \"sa\" only; remove it for im = \"pga\"".into(),
                    ));
                }
                d
            }
        };
        let pair_im = match &s.pair_im {
            None => PairIm::RotD50,
            Some(v) => match v.get_ref().as_str() {
                "geomean" => PairIm::GeoMean,
                "rotd50" => PairIm::RotD50,
                o => {
                    return Err(cx.err(
                        key("pair_im"),
                        v,
                        format!("unknown pair IM {o:?}: use \"geomean\" or \"rotd50\""),
                    ));
                }
            },
        };
        let (stripes, bootstrap, seed, level, records) = Self::run_keys(cx, s)?;
        Ok(Self {
            records,
            records_line: s.records.as_ref().and_then(|v| cx.line(v)),
            im,
            period,
            damping,
            pair_im,
            stripes,
            bootstrap,
            seed,
            level,
            limit_states: Vec::new(),
        })
    }

    /// The stripes, the bootstrap settings and the manifest path.
    #[allow(clippy::type_complexity)]
    fn run_keys(
        cx: &Cx,
        s: &FragSec,
    ) -> Result<(Stripes, usize, u64, Real, Option<PathBuf>), AssessmentError> {
        let key = |k: &str| format!("fragility.{k}");
        let stripes = match (&s.levels_g, &s.scales) {
            (Some(l), None) => Stripes::Levels(positive_increasing(cx, &key("levels_g"), l)?),
            (None, Some(sc)) => Stripes::Scales(positive_increasing(cx, &key("scales"), sc)?),
            (Some(_), Some(sc)) => return Err(cx.err(key("scales"), sc, "give levels_g (multiple stripes) or scales (scale-factor IDA), not both".into())),
            (None, None) => return Err(cx.missing("fragility.levels_g", "[fragility] needs levels_g (IM levels in g, multiple-stripe analysis) or scales (scale factors, IDA)")),
        };
        let bootstrap = match &s.bootstrap {
            None => 500,
            Some(v) => usize::try_from(*v.get_ref())
                .ok()
                .filter(|&b| b <= 100_000)
                .ok_or_else(|| {
                    cx.err(
                        key("bootstrap"),
                        v,
                        format!(
                            "invalid bootstrap = {}: must be an integer in [0, 100000]",
                            v.get_ref()
                        ),
                    )
                })?,
        };
        let seed = match &s.seed {
            None => 1,
            Some(v) => u64::try_from(*v.get_ref()).map_err(|_| {
                cx.err(
                    key("seed"),
                    v,
                    format!("invalid seed = {}: must be >= 0", v.get_ref()),
                )
            })?,
        };
        let level = match &s.level {
            None => 0.95,
            Some(v) => {
                let l = *v.get_ref();
                if !(l > 0.0 && l < 1.0) {
                    return Err(cx.err(
                        key("level"),
                        v,
                        format!(
                            "invalid level = {}: must be in (0, 1), e.g. 0.95",
                            crate::output::float_token(l)
                        ),
                    ));
                }
                l
            }
        };
        let records = match &s.records {
            None => None,
            Some(v) if v.get_ref().trim().is_empty() => {
                return Err(cx.err(key("records"), v, "empty path".into()));
            }
            Some(v) => Some(PathBuf::from(v.get_ref().trim())),
        };
        Ok((stripes, bootstrap, seed, level, records))
    }
}

/// A list of values that must be finite, > 0 and strictly increasing.
fn positive_increasing(
    cx: &Cx,
    key: &str,
    v: &Spanned<Vec<Real>>,
) -> Result<Vec<Real>, AssessmentError> {
    let xs = v.get_ref();
    if xs.is_empty() {
        return Err(cx.err(key, v, "must list at least one value".into()));
    }
    for (i, &x) in xs.iter().enumerate() {
        if !(x.is_finite() && x > 0.0) {
            return Err(cx.err(
                key,
                v,
                format!(
                    "invalid value {} (item {}): must be finite and > 0",
                    crate::output::float_token(x),
                    i + 1
                ),
            ));
        }
        if i > 0 && x <= xs[i - 1] {
            return Err(cx.err(
                key,
                v,
                format!(
                    "values must be strictly increasing: {} after {}",
                    crate::output::float_token(x),
                    crate::output::float_token(xs[i - 1])
                ),
            ));
        }
    }
    Ok(xs.clone())
}

/// One `[[limit_state]]`.
fn limit_state(cx: &Cx, i: usize, l: &Spanned<LimitSec>) -> Result<LimitState, AssessmentError> {
    let s = l.get_ref();
    let key = |k: &str| format!("limit_state[{i}].{k}");
    let name = s.name.get_ref().trim().to_string();
    if name.is_empty() || name.contains([',', '"', '\n', '\r']) {
        return Err(cx.err(
            key("name"),
            &s.name,
            "a limit-state name becomes a column: non-empty, no commas, quotes or line breaks"
                .into(),
        ));
    }
    if name == "governing_seat" {
        return Err(cx.err(
            key("name"),
            &s.name,
            "\"governing_seat\" would give the column governing_seat_ratio, which runs.csv already \
             has (the governing seated end's ratio): choose another name"
                .into(),
        ));
    }
    let given: Vec<(&str, &Spanned<Real>)> = [
        ("capacity_n", &s.capacity_n),
        ("capacity_ns", &s.capacity_ns),
        ("limit_m", &s.limit_m),
        ("limit_deg", &s.limit_deg),
    ]
    .into_iter()
    .filter_map(|(k, v)| v.as_ref().map(|v| (k, v)))
    .collect();
    let kind_name = s.kind.get_ref().as_str();
    let allowed: &[&str] = match kind_name {
        "unseating" | "shear_key" => &[],
        "joint_force" => &["capacity_n", "capacity_ns"],
        "bearing_deformation" | "joint_opening" | "pier_drift" | "backwall" => &["limit_m"],
        "rotation" => &["limit_deg"],
        o => return Err(cx.err(key("kind"), &s.kind, format!("unknown kind {o:?}: use unseating, joint_force, bearing_deformation, rotation, joint_opening, pier_drift, backwall or shear_key"))),
    };
    for (k, v) in &given {
        if !allowed.contains(k) {
            return Err(cx.err(
                key(k),
                v,
                format!(
                    "kind = {kind_name:?} does not read {k} (it reads {})",
                    if allowed.is_empty() {
                        "no value".to_string()
                    } else {
                        allowed.join(", ")
                    }
                ),
            ));
        }
        let x = *v.get_ref();
        if !(x.is_finite() && x > 0.0) {
            return Err(cx.err(
                key(k),
                v,
                format!(
                    "invalid {k} = {}: must be finite and > 0",
                    crate::output::float_token(x)
                ),
            ));
        }
    }
    let get = |k: &str| {
        given
            .iter()
            .find(|(g, _)| *g == k)
            .map(|(_, v)| *v.get_ref())
    };
    let need = |k: &str| {
        get(k).ok_or_else(|| {
            cx.err(
                key("kind"),
                &s.kind,
                format!("kind = {kind_name:?} needs {k}"),
            )
        })
    };
    let kind = match kind_name {
        "unseating" => LimitKind::Unseating,
        "joint_force" => {
            if given.is_empty() {
                return Err(cx.err(key("kind"), &s.kind, "kind = \"joint_force\" needs capacity_n (compliance laws, peak force [N]) or capacity_ns (rigid law, peak impulse [N s])".into()));
            }
            LimitKind::JointForce {
                capacity_n: get("capacity_n"),
                capacity_ns: get("capacity_ns"),
            }
        }
        "bearing_deformation" => LimitKind::BearingDeformation(need("limit_m")?),
        "joint_opening" => LimitKind::JointOpening(need("limit_m")?),
        "pier_drift" => LimitKind::PierDrift(need("limit_m")?),
        "backwall" => LimitKind::Backwall(need("limit_m")?),
        "shear_key" => LimitKind::ShearKey,
        _ => LimitKind::Rotation(need("limit_deg")?),
    };
    Ok(LimitState {
        name,
        kind,
        at: (format!("limit_state[{i}]"), cx.line(l)),
    })
}
