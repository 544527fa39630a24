//! Types and helpers shared by the report forms: the error, the JSON writer, the readable number
//! format and the report pieces several forms use (Delassus entries, stick interval, single
//! impact, per-corner contacts, energy).

use crate::analytic::{LawError, StickInterval};
use crate::contact::Delassus;
use crate::geometry::GeometryError;
use crate::impact::{ContactResult, ImpactError, SingleSolution};
use crate::math::Vector;
use serde::Serialize;
use thiserror::Error;

/// Why an impact report could not be computed (bad input; the message names the parameter).
#[derive(Debug, Error)]
pub enum ReportError {
    /// A parameter is out of range or inconsistent with the others.
    #[error("invalid {name} = {value}: {reason}")]
    InvalidParameter {
        /// The parameter as the user knows it (`theta1`, `corner`, `speed`, …).
        name: &'static str,
        /// The offending value, as given.
        value: String,
        /// What was expected.
        reason: String,
    },
    /// A deck or abutment could not be built.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// The contact law's coefficients are out of range.
    #[error(transparent)]
    Law(#[from] LawError),
    /// The impact problem could not be assembled.
    #[error(transparent)]
    Impact(#[from] ImpactError),
    /// The generic problem file is malformed (the message names the key).
    #[error("{0}")]
    Problem(String),
    /// The generic problem file is not valid JSON.
    #[error("the problem file is not valid JSON")]
    Json(#[source] serde_json::Error),
}

pub(super) fn invalid(name: &'static str, value: impl ToString, reason: &str) -> ReportError {
    ReportError::InvalidParameter {
        name,
        value: value.to_string(),
        reason: reason.to_string(),
    }
}

/// The report as pretty-printed JSON, exactly as `pounding impact --json` prints it: object keys
/// sorted, numbers in shortest round-trip form, non-finite numbers as `null`.
pub fn to_json_pretty<T: Serialize>(report: &T) -> Result<String, serde_json::Error> {
    let mut v = serde_json::to_value(report)?;
    crate::output::json_without_negative_zero(&mut v);
    serde_json::to_string_pretty(&v)
}

/// The summary line of a report whose friction split is not unique (the split of smallest norm is
/// reported; see `impact::ImpactSolution::tangential_split_unique`).
pub(super) const SPLIT_NOT_UNIQUE: &str = "  tangential split: NOT unique (the same velocities allow \
     other splits); the split of smallest norm is reported";

/// The summary lines of the corner contacts of an impact (`label` before each corner's name,
/// e.g. `deck 1 `), then [`SPLIT_NOT_UNIQUE`] when the friction split is not unique.
pub(super) fn corner_lines(
    label: &str,
    contacts: &[CornerContactReport],
    split_unique: bool,
    lines: &mut Vec<String>,
) {
    for c in contacts {
        lines.push(format!(
            "  {label}{} corner: {}  Λ_N = {} N s  Λ_T = {} N s  γ_N: {} → {} m/s",
            c.corner,
            c.mode,
            readable(c.normal_impulse),
            readable(c.tangential_impulse),
            readable(c.gamma_n_pre),
            readable(c.gamma_n_post)
        ));
    }
    if !split_unique {
        lines.push(SPLIT_NOT_UNIQUE.to_string());
    }
}

pub(super) fn xy(v: &Vector) -> [f64; 2] {
    [v.x, v.y]
}

/// Readable number for the summaries: 7 significant digits, positional for moderate magnitudes.
pub fn readable(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else if x.is_finite() && (1e-3..1e6).contains(&x.abs()) {
        let digits = (6 - x.abs().log10().floor() as i32).clamp(0, 9) as usize;
        format!("{x:.digits$}")
    } else if x.is_finite() {
        format!("{x:.6e}")
    } else {
        crate::output::float_token(x)
    }
}

/// The Delassus entries of one contact `\[1/kg\]` (`NaN` when undefined).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DelassusReport {
    /// `G_NN`.
    pub nn: f64,
    /// `G_NT`.
    pub nt: f64,
    /// `G_TT`.
    pub tt: f64,
}

impl DelassusReport {
    pub(super) fn of(g: &Delassus) -> Self {
        Self {
            nn: g.nn,
            nt: g.nt,
            tt: g.tt,
        }
    }
    pub(super) const UNDEFINED: Self = Self {
        nn: f64::NAN,
        nt: f64::NAN,
        tt: f64::NAN,
    };
}

/// The stick interval `\[L, U\]` in `r = γ_T⁻/γ_N⁻` (`NaN` when undefined).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct IntervalReport {
    /// `L`.
    pub lower: f64,
    /// `U`.
    pub upper: f64,
}

impl IntervalReport {
    pub(super) fn of(b: &StickInterval) -> Self {
        Self {
            lower: b.lower,
            upper: b.upper,
        }
    }
}

/// Normal and tangential impulse `\[N s\]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpulseReport {
    /// `Λ_N`.
    pub normal: f64,
    /// `Λ_T`.
    pub tangential: f64,
}

/// Post-impact relative velocities `\[m/s\]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RelativeVelocityReport {
    /// `γ_N⁺`.
    pub gamma_n: f64,
    /// `γ_T⁺`.
    pub gamma_t: f64,
}

/// One single-contact impact at `r = γ_T⁻/γ_N⁻` with `γ_N⁻ = −1 m/s` (flattened into its report).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SingleImpactReport {
    /// The pre-impact ratio `r`.
    pub ratio: f64,
    /// Post-impact mode (`None` when the pose is degenerate).
    pub mode: Option<&'static str>,
    /// Impulses (`NaN` when degenerate).
    pub impulse: ImpulseReport,
    /// Post-impact relative velocities (`NaN` when degenerate).
    pub post: RelativeVelocityReport,
    /// Kinetic energy change `ΔT` \[J\] (`NaN` when degenerate).
    pub energy_change: f64,
    /// Solver status (`None` when degenerate).
    pub status: Option<&'static str>,
    /// Whether the solver status allows the numbers to be used.
    #[serde(skip)]
    pub trustworthy: bool,
}

impl SingleImpactReport {
    pub(super) fn of(r: f64, sol: &SingleSolution, mode: &'static str) -> Self {
        Self {
            ratio: r,
            mode: Some(mode),
            impulse: ImpulseReport {
                normal: sol.normal_impulse,
                tangential: sol.tangential_impulse,
            },
            post: RelativeVelocityReport {
                gamma_n: sol.gamma_n_post,
                gamma_t: sol.gamma_t_post,
            },
            energy_change: sol.energy_change(-1.0, -r),
            status: Some(sol.status.name()),
            trustworthy: sol.status.is_trustworthy(),
        }
    }

    pub(super) fn undefined(r: f64) -> Self {
        Self {
            ratio: r,
            mode: None,
            impulse: ImpulseReport {
                normal: f64::NAN,
                tangential: f64::NAN,
            },
            post: RelativeVelocityReport {
                gamma_n: f64::NAN,
                gamma_t: f64::NAN,
            },
            energy_change: f64::NAN,
            status: None,
            trustworthy: true,
        }
    }

    /// The two summary lines of the impact.
    pub(super) fn summary(&self, lines: &mut Vec<String>) {
        let r = self.ratio;
        lines.push(format!(
            "Impact at r = {r} (γ_N⁻ = −1 m/s, γ_T⁻ = {} m/s): {} ({})",
            -r,
            self.mode.unwrap_or("-"),
            self.status.unwrap_or("-")
        ));
        lines.push(format!(
            "  Λ_N = {} N s  Λ_T = {} N s  γ_N⁺ = {} m/s  γ_T⁺ = {} m/s  ΔT = {} J",
            readable(self.impulse.normal),
            readable(self.impulse.tangential),
            readable(self.post.gamma_n),
            readable(self.post.gamma_t),
            readable(self.energy_change)
        ));
    }
}

/// One contact of a multi-contact impact, in the per-corner form of the shape reports.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CornerContactReport {
    /// Corner name (`c0`/`c1`, `acute`/`obtuse`, `outer`/`inner`).
    pub corner: &'static str,
    /// Corner position `\[m\]`.
    pub point: [f64; 2],
    /// `Λ_N` \[N s\].
    pub normal_impulse: f64,
    /// `Λ_T` \[N s\].
    pub tangential_impulse: f64,
    /// Post-impact mode.
    pub mode: &'static str,
    /// `γ_N⁻` \[m/s\].
    pub gamma_n_pre: f64,
    /// `γ_T⁻` \[m/s\].
    pub gamma_t_pre: f64,
    /// `γ_N⁺` \[m/s\].
    pub gamma_n_post: f64,
    /// `γ_T⁺` \[m/s\].
    pub gamma_t_post: f64,
}

pub(super) fn corner_contacts(
    contacts: &[ContactResult],
    names: &[&'static str; 2],
    corners: &[Vector; 2],
) -> Vec<CornerContactReport> {
    contacts
        .iter()
        .enumerate()
        .map(|(k, c)| CornerContactReport {
            corner: names[k],
            point: xy(&corners[k]),
            normal_impulse: c.normal_impulse,
            tangential_impulse: c.tangential_impulse,
            mode: c.mode.name(),
            gamma_n_pre: c.gamma_n_pre,
            gamma_t_pre: c.gamma_t_pre,
            gamma_n_post: c.gamma_n_post,
            gamma_t_post: c.gamma_t_post,
        })
        .collect()
}

/// Kinetic energy before and after the impact \[J\].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnergyReport {
    /// Before.
    pub before: f64,
    /// After.
    pub after: f64,
}
