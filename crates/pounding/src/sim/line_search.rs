//! The line search of the yielding members' implicit return mapping, shared by the block
//! ([`super::yielding`]) and the dense ([`super::yielding_dense`]) forms: the Armijo step on the
//! potential `Φ` and each member's change of potential along a step.

use super::elements::YieldingBearing;
use crate::math::{Real, Vector};

/// The Armijo step `t ∈ (0, 1]` of the line search on `Φ` ([`super::yielding::Implicit`]'s damped Newton): halving `t`
/// until `ΔΦ(t) = t g·d + ½ t² dᵀŴd − Σ_b Δψ_b(t) ≤ 10⁻⁴ t g·d` (`slope = g·d < 0`, `quad =
/// dᵀŴd`, `dpsi(t)` the members' `Σ_b (Δ(dist²)/(2 k_e) − e₀ n₀·Δu)` at step `t`: the terms of
/// `Φ` linear in `x` cancel against `g·d` exactly, and the distance change is formed from
/// `Δs = k_e Δu`, no difference of two large numbers); 1 after 40 halvings.
pub(crate) fn armijo(slope: Real, quad: Real, dpsi: impl Fn(Real) -> Real) -> Real {
    let mut t = 1.0;
    for _ in 0..40 {
        let dphi = t * slope + 0.5 * t * t * quad - dpsi(t);
        if dphi <= 1e-4 * t * slope {
            return t;
        }
        t *= 0.5;
    }
    1.0
}

/// `Δψ_b − e₀ n₀·Δu` of the line search ([`super::yielding::Implicit`]'s damped Newton): the change of the member's
/// potential `ψ_b` from deformation `u0` by `du`, less its linear part, formed from
/// `Δs = k_e Δu` without a difference of two large numbers.
pub(crate) fn psi_change(b: &YieldingBearing, u0: Vector, du: Vector) -> Real {
    let (ke, rr) = ((1.0 - b.law.b()) * b.law.k0(), b.law.plastic_force_radius());
    let s0 = (u0 - b.state.u_p) * ke;
    let ds = du * ke;
    let s1 = s0 + ds;
    let (n0, n1) = (s0.norm(), s1.norm());
    let (e0, e1) = ((n0 - rr).max(0.0), (n1 - rr).max(0.0));
    let de = if e0 > 0.0 && e1 > 0.0 {
        ds.dot(&(s0 + s1)) / (n0 + n1)
    } else {
        e1 - e0
    };
    let lin0 = if e0 > 0.0 { e0 * s0.dot(&du) / n0 } else { 0.0 };
    de * (e0 + e1) / (2.0 * ke) - lin0
}
