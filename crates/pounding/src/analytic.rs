//! Closed-form single-impact solution (spec §9–§11).
//!
//! CONTRACT (skeleton; the single-impact work item fills it, keeping names and signatures).

use crate::contact::Delassus;
use crate::math::Real;
use thiserror::Error;

/// Invalid impact-law parameters.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum LawError {
    /// `μ` must be finite and `≥ 0`.
    #[error("invalid friction coefficient mu = {0}: must be finite and >= 0")]
    Friction(Real),
    /// `ε_N` must lie in `[0, 1]`.
    #[error("invalid restitution coefficient eps = {0}: must lie in [0, 1]")]
    Restitution(Real),
}

/// Newton restitution + Coulomb friction parameters, validated on construction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactLaw {
    mu: Real,
    eps: Real,
}

impl ImpactLaw {
    /// Validates `μ ≥ 0` and `ε_N ∈ [0, 1]` (finite).
    pub fn new(mu: Real, eps: Real) -> Result<Self, LawError> {
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(LawError::Friction(mu));
        }
        if !(eps.is_finite() && (0.0..=1.0).contains(&eps)) {
            return Err(LawError::Restitution(eps));
        }
        Ok(Self { mu, eps })
    }
    /// Friction coefficient `μ`.
    pub fn mu(&self) -> Real {
        self.mu
    }
    /// Normal restitution coefficient `ε_N`.
    pub fn eps(&self) -> Real {
        self.eps
    }
}

/// The stick interval `[L, U]` in the pre-impact ratio `r = γ_T⁻/γ_N⁻` (infinite bounds allowed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StickInterval {
    /// `L` (`−∞` when `G_NN − μ G_NT ≤ 0`).
    pub lower: Real,
    /// `U` (`+∞` when `G_NN + μ G_NT ≤ 0`).
    pub upper: Real,
}

/// Post-impact tangential mode (spec §10).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SlipMode {
    /// `γ_T⁺ = 0`.
    Stick,
    /// `γ_T⁺ > 0`, `r < L` (bridge label `slip-outward`).
    SlipOutward,
    /// `γ_T⁺ < 0`, `r > U` (bridge label `slip-inward`).
    SlipInward,
}

/// Result of the analytic single impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnalyticImpact {
    /// Mode.
    pub mode: SlipMode,
    /// `Λ_N`.
    pub normal_impulse: Real,
    /// `Λ_T`.
    pub tangential_impulse: Real,
    /// `γ_N⁺ = −ε_N γ_N⁻`.
    pub gamma_n_post: Real,
    /// `γ_T⁺`.
    pub gamma_t_post: Real,
}

/// `L`, `U` (spec §9).
pub fn stick_interval(g: &Delassus, law: &ImpactLaw) -> StickInterval {
    let _ = (g, law);
    todo!("single-impact work item")
}

/// The analytic impact for pre-impact relative velocities `γ_N⁻ < 0`, `γ_T⁻` (spec §9).
pub fn single_impact(
    g: &Delassus,
    law: &ImpactLaw,
    gamma_n_pre: Real,
    gamma_t_pre: Real,
) -> AnalyticImpact {
    let _ = (g, law, gamma_n_pre, gamma_t_pre);
    todo!("single-impact work item")
}
