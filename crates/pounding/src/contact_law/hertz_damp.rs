//! Hertz with nonlinear damping (Muthukumar & DesRoches 2006): `law = "hertz-damp"`.

use super::*;
use crate::math::Real;
use crate::output::json_float;
use calibration::HertzDampCalibration;
use registry::{BuildError, DEFAULT_MIN_VELOCITY, LawEntry, LawInputs, reads, default_k_h};

/// How the damping constant `ζ` of [`HertzDamp`] is set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HertzDamping {
    /// A fixed `ζ` \[N s/m^{5/2}\] for every impact (e.g. calibrated for a design impact velocity;
    /// an impact at another velocity then rebounds with another `e`).
    Constant {
        /// `ζ ≥ 0`.
        zeta: Real,
    },
    /// `ζ = χ k_h / v_i` with `v_i` the approach rate recorded at the onset of each impact
    /// (floored at `min_velocity`): every impact rebounds with the `e` the dimensionless `χ` was
    /// calibrated for, whatever its velocity (the intent of Muthukumar & DesRoches 2006).
    PerImpact {
        /// Dimensionless damping `χ = ζ v_i / k_h ≥ 0`.
        chi: Real,
        /// Floor of `v_i` \[m/s\] (`> 0`) for grazing contacts, which would otherwise get an
        /// unbounded damping constant.
        min_velocity: Real,
    },
}

/// Hertz contact with nonlinear (hysteresis) damping, in the form of Muthukumar & DesRoches
/// (2006) (after Hunt & Crossley 1975; Lankarani & Nikravesh 1990):
/// ```text
/// F = max(0, k_h δ^{3/2} + ζ δ^{3/2} δ̇) = max(0, k_h δ^{3/2} (1 + χ δ̇ / v_i))   for δ > 0
/// ```
/// with `χ = ζ v_i / k_h` dimensionless. The damping force vanishes with `δ`, so the force is
/// continuous at contact onset. For two free masses the rebound depends on `χ` only (not on
/// `k_h`, the masses, the exponent or the velocity), through the exact first integral of the
/// Hunt–Crossley equation (used by the tests as independent evidence):
/// `χ (1 + e) = ln((1 + χ) / (1 − χ e))`.
/// Calibrations of `χ` from `e`: [`calibration::hertz_damp_chi`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzDamp {
    k_h: Real,
    damping: HertzDamping,
}

impl HertzDamp {
    /// Validates `k_h > 0`, and `ζ ≥ 0`, or `χ ≥ 0` and `min_velocity > 0`.
    pub fn new(k_h: Real, damping: HertzDamping) -> Result<Self, ContactLawError> {
        let k_h = positive("k_h", k_h)?;
        let damping = match damping {
            HertzDamping::Constant { zeta } => HertzDamping::Constant {
                zeta: non_negative("zeta", zeta)?,
            },
            HertzDamping::PerImpact { chi, min_velocity } => HertzDamping::PerImpact {
                chi: non_negative("chi", chi)?,
                min_velocity: positive("min_velocity", min_velocity)?,
            },
        };
        Ok(HertzDamp { k_h, damping })
    }
    /// The law with `χ` calibrated for restitution `e` by `method`
    /// ([`calibration::hertz_damp_chi`]). With `design_velocity = Some(v)` the damping is the
    /// constant `ζ = χ k_h / v` (the published formulas' form: it depends on the impact
    /// velocity); with `None` it is [`HertzDamping::PerImpact`] with `min_velocity`.
    pub fn from_restitution(
        k_h: Real,
        e: Real,
        design_velocity: Option<Real>,
        min_velocity: Real,
        method: calibration::HertzDampCalibration,
    ) -> Result<Self, ContactLawError> {
        let k_h = positive("k_h", k_h)?;
        let chi = calibration::hertz_damp_chi(e, method)?;
        let damping = match design_velocity {
            Some(v) => HertzDamping::Constant {
                zeta: chi * k_h / positive("design_velocity", v)?,
            },
            None => HertzDamping::PerImpact { chi, min_velocity },
        };
        HertzDamp::new(k_h, damping)
    }
    /// Hertz stiffness `k_h` \[N/m^{3/2}\].
    pub fn k_h(&self) -> Real {
        self.k_h
    }
    /// The damping setting.
    pub fn damping(&self) -> HertzDamping {
        self.damping
    }
}

impl ContactForceLaw for HertzDamp {
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let zeta = match self.damping {
            HertzDamping::Constant { zeta } => zeta,
            HertzDamping::PerImpact { chi, min_velocity } => {
                let onset = if state.in_contact() {
                    state.onset_velocity.unwrap_or(delta_dot)
                } else {
                    delta_dot
                };
                chi * self.k_h / onset.max(min_velocity)
            }
        };
        let s = delta.sqrt();
        let d15 = delta * s;
        let g = self.k_h + zeta * delta_dot;
        Evaluation::closed(state, delta, delta_dot, g * d15, 1.5 * g * s, zeta * d15)
    }
    fn name(&self) -> &'static str {
        "hertz-damp"
    }
    fn is_history_dependent(&self) -> bool {
        matches!(self.damping, HertzDamping::PerImpact { .. })
    }
    fn backbone_stiffness(&self, delta: Real) -> Real {
        1.5 * self.k_h * delta.max(0.0).sqrt()
    }
    fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        super::hertz_backbone_penetration(self.k_h, m_eff, v)
    }
    fn describe(&self) -> serde_json::Value {
        let d = match self.damping() {
            HertzDamping::Constant { zeta } => {
                serde_json::json!({"zeta": json_float(zeta)})
            }
            HertzDamping::PerImpact { chi, min_velocity } => {
                serde_json::json!({"chi": json_float(chi), "min_velocity": json_float(min_velocity)})
            }
        };
        serde_json::json!({"law": "hertz-damp", "k_h": json_float(self.k_h()), "damping": d})
    }
}

/// The law's entry in [`registry::LAWS`] (name, `[contact]` keys and those read, description,
/// builder).
pub(crate) const ENTRY: LawEntry = LawEntry {
    name: "hertz-damp",
    keys: &[
        "k_h",
        "zeta",
        "chi",
        "restitution",
        "calibration",
        "design_velocity",
        "min_velocity",
    ],
    reads: |given| {
        if given("zeta") {
            reads(&["k_h", "zeta"], " with zeta given")
        } else if given("chi") {
            reads(&["k_h", "chi", "min_velocity"], " with chi given")
        } else if given("design_velocity") {
            reads(
                &["k_h", "restitution", "calibration", "design_velocity"],
                " with design_velocity given (a constant zeta)",
            )
        } else {
            reads(
                &["k_h", "restitution", "calibration", "min_velocity"],
                " without zeta, chi or design_velocity",
            )
        }
    },
    description: "Hertz with nonlinear damping (Muthukumar & DesRoches)",
    build,
};

/// Builds the law from `[contact] k_h` and `zeta` (constant), or `chi` (per impact, floored at
/// `min_velocity`), or the damping calibrated from `restitution` (and `design_velocity`) by
/// `calibration` (`numerical`, `muthukumar-desroches`, `ye`).
fn build(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    let k_h = p.get("k_h").unwrap_or_else(default_k_h);
    let vmin = p.get("min_velocity").unwrap_or(DEFAULT_MIN_VELOCITY);
    Ok(match (p.get("zeta"), p.get("chi")) {
        (Some(zeta), _) => HertzDamp::new(k_h, HertzDamping::Constant { zeta })?,
        (None, Some(chi)) => HertzDamp::new(
            k_h,
            HertzDamping::PerImpact {
                chi,
                min_velocity: vmin,
            },
        )?,
        (None, None) => {
            let m = match p.calibration {
                "numerical" => HertzDampCalibration::Numerical,
                "muthukumar-desroches" => HertzDampCalibration::MuthukumarDesRoches,
                "ye" => HertzDampCalibration::YeEtAl,
                _ => {
                    return Err(BuildError::Calibration {
                        allowed: "\"numerical\", \"muthukumar-desroches\" or \"ye\"",
                    });
                }
            };
            HertzDamp::from_restitution(k_h, p.restitution, p.get("design_velocity"), vmin, m)?
        }
    }
    .into())
}
