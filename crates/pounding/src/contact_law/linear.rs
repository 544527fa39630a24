//! The linear elastic spring: `law = "linear"`.

use super::*;
use crate::math::Real;
use crate::output::json_float;
use registry::{BuildError, DEFAULT_K, LawEntry, LawInputs, reads};

/// Linear elastic contact spring without damping:
/// ```text
/// F = k δ   for δ > 0,      F = 0 for δ ≤ 0,      ∂F/∂δ = k
/// ```
/// No dissipation: an isolated collision of two free masses rebounds with restitution `e = 1`
/// after the contact duration `π √(m_eff / k)` (half a period of the spring–mass system).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearSpring {
    k: Real,
}

impl LinearSpring {
    /// Validates `k > 0` \[N/m\] (finite).
    pub fn new(k: Real) -> Result<Self, ContactLawError> {
        Ok(LinearSpring {
            k: positive("k", k)?,
        })
    }
    /// Spring stiffness `k` \[N/m\].
    pub fn k(&self) -> Real {
        self.k
    }
}

impl ContactForceLaw for LinearSpring {
    fn name(&self) -> &'static str {
        "linear"
    }
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        Evaluation::closed(state, delta, delta_dot, self.k * delta, self.k, 0.0)
    }
    fn backbone_stiffness(&self, _delta: Real) -> Real {
        self.k
    }
    fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        v.abs() * (m_eff / self.k).sqrt()
    }
    fn describe(&self) -> serde_json::Value {
        serde_json::json!({"law": "linear", "k": json_float(self.k())})
    }
}

/// The law's entry in [`registry::LAWS`] (name, `[contact]` keys and those read, description,
/// builder).
pub(crate) const ENTRY: LawEntry = LawEntry {
    name: "linear",
    keys: &["k"],
    reads: |_| reads(&["k"], ""),
    description: "linear elastic spring k d, no damping",
    build,
};

/// Builds the law from `[contact] k` (default [`DEFAULT_K`]).
fn build(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    Ok(LinearSpring::new(p.get("k").unwrap_or(DEFAULT_K))?.into())
}
