//! Jankowski's nonlinear viscoelastic law: `law = "jankowski"`.

use super::*;
use crate::math::Real;
use crate::output::json_float;
use calibration::JankowskiCalibration;
use registry::{BuildError, LawEntry, LawInputs, reads, default_k_h};

/// Nonlinear viscoelastic law of Jankowski (2005):
/// ```text
/// F = β δ^{3/2} + c(δ) δ̇   for δ > 0, δ̇ > 0   (approach)
/// F = β δ^{3/2}            for δ > 0, δ̇ ≤ 0   (restitution)
/// c(δ) = 2 ξ √(β √δ m_eff),   m_eff = m1 m2 / (m1 + m2)
/// ```
/// Damping acts only during approach, so the force is never negative. By scaling, the rebound of
/// two free masses depends on `ξ` only (not on `β`, the masses or the velocity). Jankowski's
/// closed-form `ξ(e)` and a numerical calibration: [`calibration::jankowski_xi`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jankowski {
    beta: Real,
    xi: Real,
    m_eff: Real,
}

impl Jankowski {
    /// Validates `β > 0` \[N/m^{3/2}\], `ξ ≥ 0`, `m_eff > 0` \[kg\].
    pub fn new(beta: Real, xi: Real, m_eff: Real) -> Result<Self, ContactLawError> {
        Ok(Jankowski {
            beta: positive("beta", beta)?,
            xi: non_negative("xi", xi)?,
            m_eff: positive("m_eff", m_eff)?,
        })
    }
    /// The law for colliding masses `m1`, `m2` with `ξ` calibrated for restitution `e` by `method`.
    pub fn from_restitution(
        beta: Real,
        e: Real,
        m1: Real,
        m2: Real,
        method: calibration::JankowskiCalibration,
    ) -> Result<Self, ContactLawError> {
        let beta = positive("beta", beta)?;
        let m = effective_mass(m1, m2)?;
        Jankowski::new(beta, calibration::jankowski_xi(e, method)?, m)
    }
    /// Stiffness `β` \[N/m^{3/2}\].
    pub fn beta(&self) -> Real {
        self.beta
    }
    /// Damping ratio `ξ`.
    pub fn xi(&self) -> Real {
        self.xi
    }
    /// Effective mass `m_eff` \[kg\].
    pub fn m_eff(&self) -> Real {
        self.m_eff
    }
}

impl ContactForceLaw for Jankowski {
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let s = delta.sqrt();
        let fe = self.beta * delta * s;
        let ke = 1.5 * self.beta * s;
        if delta_dot > 0.0 {
            let c = 2.0 * self.xi * (self.beta * s * self.m_eff).sqrt();
            // dc/dδ = c / (4 δ)
            Evaluation::closed(
                state,
                delta,
                delta_dot,
                fe + c * delta_dot,
                ke + c / (4.0 * delta) * delta_dot,
                c,
            )
        } else {
            Evaluation::closed(state, delta, delta_dot, fe, ke, 0.0)
        }
    }
    fn name(&self) -> &'static str {
        "jankowski"
    }
    fn backbone_stiffness(&self, delta: Real) -> Real {
        1.5 * self.beta * delta.max(0.0).sqrt()
    }
    fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        super::hertz_backbone_penetration(self.beta, m_eff, v)
    }
    fn describe(&self) -> serde_json::Value {
        serde_json::json!({
            "law": "jankowski", "beta": json_float(self.beta()), "xi": json_float(self.xi()),
            "m_eff": json_float(self.m_eff())
        })
    }
}

/// The law's entry in [`registry::LAWS`] (name, `[contact]` keys and those read, description,
/// builder).
pub(crate) const ENTRY: LawEntry = LawEntry {
    name: "jankowski",
    keys: &["beta", "k_h", "xi", "restitution", "calibration"],
    // beta, when given, is the stiffness (k_h is its fallback)
    reads: |given| match (given("beta"), given("xi")) {
        (true, true) => reads(&["beta", "xi"], " with beta and xi given"),
        (true, false) => reads(&["beta", "restitution", "calibration"], " with beta given"),
        (false, true) => reads(&["k_h", "xi"], " with xi given"),
        (false, false) => reads(&["k_h", "restitution", "calibration"], ""),
    },
    description: "Jankowski nonlinear viscoelastic",
    build,
};

/// Builds the law from `[contact] beta` (or `k_h`) and `xi`, or `xi` calibrated from
/// `restitution` by `calibration` (`numerical`, `jankowski2005`).
fn build(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    let beta = p.get("beta").or(p.get("k_h")).unwrap_or_else(default_k_h);
    // the stiffness read from `k_h` (beta not given) is reported under that key
    let stiffness_key = if p.get("beta").is_none() && p.get("k_h").is_some() {
        "k_h"
    } else {
        "beta"
    };
    let [m1, m2] = p.masses;
    let law = match p.get("xi") {
        Some(xi) => super::effective_mass(m1, m2).and_then(|m| Jankowski::new(beta, xi, m)),
        None => {
            let m = match p.calibration {
                "numerical" => JankowskiCalibration::Numerical,
                "jankowski2005" => JankowskiCalibration::Jankowski2005,
                _ => {
                    return Err(BuildError::Calibration {
                        allowed: "\"numerical\" or \"jankowski2005\"",
                    });
                }
            };
            Jankowski::from_restitution(beta, p.restitution, m1, m2, m)
        }
    };
    Ok(law
        .map_err(|e| match e {
            ContactLawError::InvalidParameter {
                name,
                value,
                reason,
            } if name == "beta" => ContactLawError::InvalidParameter {
                name: stiffness_key.to_string(),
                value,
                reason,
            },
            e => e,
        })?
        .into())
}
