//! Sharing a joint's law among the corner contacts of the joint.
//!
//! A law's parameters describe the **joint as a whole** (e.g. `K1`, `K2` of OpenSees'
//! `ImpactMaterial` for the whole deck-end face). The rigid-body model resolves the joint into
//! `N` corner contacts (in the spec's joint: one per end of the face, `N = 2`); when `k ≤ N` of
//! them are closed, each closed corner `i` with penetration `δ_i`, rate `δ̇_i` and its own
//! committed [`LawState`] carries
//! ```text
//! F_i = (1/N) · F_law(δ_i, δ̇_i; state_i)            (fixed equal share, N = all corners)
//! ```
//! and the tangents are scaled alike. When the joint closes uniformly (all `δ_i = δ`, `δ̇_i = δ̇`,
//! equal histories) the corner states evolve identically and `Σ F_i = F_law(δ, δ̇)`: the joint
//! gives exactly the law's force, for every law (linear, nonlinear, history-dependent) — the
//! property the tests check. A joint touching at one corner only (a rotated deck) carries
//! `F_law(δ_1)/N`: the face's stiffness is distributed over the face, as the usual practice of
//! several gap elements of stiffness `K/N` across the deck width.
//!
//! Why a fixed share and not `1/k` of the **closed** corners (or a penetration-weighted split of
//! a joint force): with `1/k` the stiffness of a corner jumps when another corner closes or opens
//! while it is compressed. The force is then discontinuous in time, and even an elastic law
//! (Hertz, a linear spring) is no longer conservative: a cycle in which corner 2 closes and opens
//! while corner 1 is compressed does non-zero net work (the test `one_over_k_sharing_is_not_conservative`
//! measures it), whereas the fixed share derives from the potential `Σ_i U_law(δ_i)/N` and is
//! exactly conservative for elastic laws. A penetration-weighted split `F_i = F_law(max δ) δ_i/Σδ_j`
//! is continuous but also has no potential (its Jacobian is not symmetric). The fixed share keeps
//! each corner an independent copy of the law (each with its own state), which is also what the
//! simulator needs for history-dependent laws.

use super::{ContactLaw, ContactLawError, Evaluation, LawState, invalid};
use crate::math::Real;

/// A joint law shared equally among the joint's `N` corner contacts (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointLaw {
    law: ContactLaw,
    corners: usize,
}

impl JointLaw {
    /// Validates `corners ≥ 1` (the number of corner contacts the joint can close, 2 for the
    /// spec's joint).
    pub fn new(law: ContactLaw, corners: usize) -> Result<Self, ContactLawError> {
        if corners == 0 {
            return Err(invalid("corners", 0.0, "must be >= 1"));
        }
        Ok(JointLaw { law, corners })
    }
    /// The joint's law.
    pub fn law(&self) -> &ContactLaw {
        &self.law
    }
    /// Number of corner contacts `N`.
    pub fn corners(&self) -> usize {
        self.corners
    }
    /// Each corner's share `1/N`.
    pub fn share(&self) -> Real {
        1.0 / self.corners as Real
    }
    /// Corner evaluation: the law's evaluation at the corner's `δ_i`, `δ̇_i` from its committed
    /// `state`, with force, stiffness and damping scaled by `1/N`. The returned trial state is the
    /// law's (unscaled) state; commit it per corner.
    pub fn corner_evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        let s = self.share();
        let mut ev = self.law.evaluate(state, delta, delta_dot);
        ev.force *= s;
        ev.stiffness *= s;
        ev.damping *= s;
        ev
    }
}
