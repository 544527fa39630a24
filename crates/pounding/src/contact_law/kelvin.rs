//! The Kelvin–Voigt law (linear spring and dashpot): `law = "kelvin"`.

use super::*;
use crate::math::Real;
use crate::output::json_float;
use calibration::KelvinCalibration;
use registry::{BuildError, DEFAULT_K, LawEntry, LawInputs, reads};

/// Linear spring and dashpot in parallel (Kelvin–Voigt), without tension:
/// ```text
/// F = max(0, k δ + c δ̇)   for δ > 0,      F = 0 for δ ≤ 0
/// ```
/// The dashpot gives a force jump `c δ̇` at contact onset, and the clamp ends the contact when
/// `k δ + c δ̇` returns to zero (with `δ > 0`). `c` from a target restitution: see
/// [`KelvinVoigt::from_restitution`] (Anagnostopoulos 1988, or numerically).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KelvinVoigt {
    k: Real,
    c: Real,
}

impl KelvinVoigt {
    /// Validates `k > 0` \[N/m\] and `c ≥ 0` \[N s/m\] (finite).
    pub fn new(k: Real, c: Real) -> Result<Self, ContactLawError> {
        Ok(KelvinVoigt {
            k: positive("k", k)?,
            c: non_negative("c", c)?,
        })
    }
    /// The law whose isolated collision of two free masses `m1`, `m2` rebounds with restitution
    /// `e ∈ (0, 1]`: `c = 2 ξ √(k m_eff)`, `m_eff = m1 m2/(m1 + m2)`, with the damping ratio `ξ`
    /// of [`calibration::kelvin_damping_ratio`]. Independent of the impact velocity (the law is
    /// linear), but dependent on the masses.
    pub fn from_restitution(
        k: Real,
        e: Real,
        m1: Real,
        m2: Real,
        method: calibration::KelvinCalibration,
    ) -> Result<Self, ContactLawError> {
        let k = positive("k", k)?;
        let m = effective_mass(m1, m2)?;
        let xi = calibration::kelvin_damping_ratio(e, method)?;
        KelvinVoigt::new(k, 2.0 * xi * (k * m).sqrt())
    }
    /// Spring stiffness `k` \[N/m\].
    pub fn k(&self) -> Real {
        self.k
    }
    /// Dashpot coefficient `c` \[N s/m\].
    pub fn c(&self) -> Real {
        self.c
    }
}

impl ContactForceLaw for KelvinVoigt {
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let f = self.k * delta + self.c * delta_dot;
        Evaluation::closed(state, delta, delta_dot, f, self.k, self.c)
    }
    fn name(&self) -> &'static str {
        "kelvin"
    }
    fn backbone_stiffness(&self, _delta: Real) -> Real {
        self.k
    }
    fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        v.abs() * (m_eff / self.k).sqrt()
    }
    fn describe(&self) -> serde_json::Value {
        serde_json::json!({"law": "kelvin", "k": json_float(self.k()), "c": json_float(self.c())})
    }
}

/// The law's entry in [`registry::LAWS`] (name, `[contact]` keys and those read, description,
/// builder).
pub(crate) const ENTRY: LawEntry = LawEntry {
    name: "kelvin",
    keys: &["k", "c", "restitution", "calibration"],
    reads: |given| match given("c") {
        true => reads(&["k", "c"], " with c given"),
        false => reads(&["k", "restitution", "calibration"], " without c"),
    },
    description: "linear spring and dashpot (Kelvin-Voigt)",
    build,
};

/// Builds the law from `[contact] k` (default [`DEFAULT_K`]) and `c`, or `c` calibrated from
/// `restitution` by `calibration` (`numerical`, `anagnostopoulos`).
fn build(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    let k = p.get("k").unwrap_or(DEFAULT_K);
    Ok(match p.get("c") {
        Some(c) => KelvinVoigt::new(k, c)?.into(),
        None => {
            let m = match p.calibration {
                "numerical" => KelvinCalibration::Numerical,
                "anagnostopoulos" => KelvinCalibration::Anagnostopoulos,
                _ => {
                    return Err(BuildError::Calibration {
                        allowed: "\"numerical\" or \"anagnostopoulos\"",
                    });
                }
            };
            let [m1, m2] = p.masses;
            KelvinVoigt::from_restitution(k, p.restitution, m1, m2, m)?.into()
        }
    })
}
