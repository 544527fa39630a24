//! Hertz's elastic law: `law = "hertz"`.

use super::*;
use crate::math::Real;
use crate::output::json_float;
use registry::{BuildError, LawEntry, LawInputs, reads, default_k_h};

/// Hertz's elastic contact law (no dissipation):
/// ```text
/// F = k_h δ^{3/2}   for δ > 0,      ∂F/∂δ = (3/2) k_h δ^{1/2}
/// ```
/// `k_h` \[N/m^{3/2}\] lumps the contact geometry and the elastic moduli; for bridge decks the
/// literature uses `k_h ≈ 25 000 kip/in^{3/2}` (Muthukumar & DesRoches 2006;
/// [`units::kip_per_in_1_5`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    k_h: Real,
}

impl Hertz {
    /// Validates `k_h > 0` \[N/m^{3/2}\].
    pub fn new(k_h: Real) -> Result<Self, ContactLawError> {
        Ok(Hertz {
            k_h: positive("k_h", k_h)?,
        })
    }
    /// Hertz stiffness `k_h` \[N/m^{3/2}\].
    pub fn k_h(&self) -> Real {
        self.k_h
    }
}

impl ContactForceLaw for Hertz {
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let s = delta.sqrt();
        Evaluation::closed(
            state,
            delta,
            delta_dot,
            self.k_h * delta * s,
            1.5 * self.k_h * s,
            0.0,
        )
    }
    fn name(&self) -> &'static str {
        "hertz"
    }
    fn backbone_stiffness(&self, delta: Real) -> Real {
        1.5 * self.k_h * delta.max(0.0).sqrt()
    }
    fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        super::hertz_backbone_penetration(self.k_h, m_eff, v)
    }
    fn describe(&self) -> serde_json::Value {
        serde_json::json!({"law": "hertz", "k_h": json_float(self.k_h())})
    }
}

/// The law's entry in [`registry::LAWS`] (name, `[contact]` keys and those read, description,
/// builder).
pub(crate) const ENTRY: LawEntry = LawEntry {
    name: "hertz",
    keys: &["k_h"],
    reads: |_| reads(&["k_h"], ""),
    description: "Hertz elastic k_h d^1.5",
    build,
};

/// Builds the law from `[contact] k_h` (default [`default_k_h`]).
fn build(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    Ok(Hertz::new(p.get("k_h").unwrap_or_else(default_k_h))?.into())
}
