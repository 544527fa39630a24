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

impl SlipMode {
    /// Bridge label (spec §10): `stick`, `slip-outward`, `slip-inward`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Stick => "stick",
            Self::SlipOutward => "slip-outward",
            Self::SlipInward => "slip-inward",
        }
    }
    /// Classification of a post-impact tangential velocity with the spec's tolerance
    /// (`|γ_T⁺| ≤ 1e−9 n` is stick, spec §10), `n = −γ_N⁻ > 0`.
    pub fn classify(gamma_t_post: Real, n: Real) -> Self {
        if gamma_t_post.abs() <= STICK_TOLERANCE * n.abs() {
            Self::Stick
        } else if gamma_t_post > 0.0 {
            Self::SlipOutward
        } else {
            Self::SlipInward
        }
    }
}

/// Relative tolerance of the stick classification: `|γ_T⁺| ≤ 1e−9 · |γ_N⁻|` (spec §10).
pub const STICK_TOLERANCE: Real = 1e-9;

impl StickInterval {
    /// `L ≤ r ≤ U`.
    pub fn contains(&self, r: Real) -> bool {
        self.lower <= r && r <= self.upper
    }
}

/// `L`, `U` (spec §9):
/// ```text
/// L = (1+ε_N) (G_NT − μ G_TT) / (G_NN − μ G_NT)     if D₋ = G_NN − μ G_NT > 0, else −∞
/// U = (1+ε_N) (G_NT + μ G_TT) / (G_NN + μ G_NT)     if D₊ = G_NN + μ G_NT > 0, else +∞
/// ```
/// An infinite bound marks the Painlevé-type regime `μ|G_NT| ≥ G_NN`, where the slip mode on that
/// side disappears and stick extends to ∓∞.
#[inline]
pub fn stick_interval(g: &Delassus, law: &ImpactLaw) -> StickInterval {
    let a = 1.0 + law.eps;
    let mu = law.mu;
    let dm = g.nn - mu * g.nt;
    let dp = g.nn + mu * g.nt;
    StickInterval {
        lower: if dm > 0.0 {
            a * (g.nt - mu * g.tt) / dm
        } else {
            Real::NEG_INFINITY
        },
        upper: if dp > 0.0 {
            a * (g.nt + mu * g.tt) / dp
        } else {
            Real::INFINITY
        },
    }
}

/// `true` in the Painlevé-type regime `μ |G_NT| ≥ G_NN` (one stick bound is infinite, spec §9).
pub fn is_painleve(g: &Delassus, law: &ImpactLaw) -> bool {
    law.mu * g.nt.abs() >= g.nn
}

/// The analytic impact for pre-impact relative velocities `γ_N⁻ < 0`, `γ_T⁻` (spec §9).
///
/// With `n = −γ_N⁻`, `r = γ_T⁻/γ_N⁻`, `a_ε = 1 + ε_N`, `D∓ = G_NN ∓ μ G_NT`,
/// `det = G_NN G_TT − G_NT²`:
///
/// | mode | condition | `Λ_N` | `Λ_T` | `γ_T⁺` |
/// |---|---|---|---|---|
/// | outward slip | `r < L` | `a_ε n / D₋` | `−μ Λ_N` | `n (L − r)` |
/// | stick | `L ≤ r ≤ U` | `n (a_ε G_TT − G_NT r)/det` | `n (G_NN r − a_ε G_NT)/det` | `0` |
/// | inward slip | `r > U` | `a_ε n / D₊` | `+μ Λ_N` | `n (U − r)` |
///
/// and always `γ_N⁺ = −ε_N γ_N⁻`. For `γ_N⁻ ≥ 0` (no approach) the result is `Λ = 0`,
/// `γ⁺ = γ⁻`, with the mode read from the sign of `γ_T⁻`.
pub fn single_impact(
    g: &Delassus,
    law: &ImpactLaw,
    gamma_n_pre: Real,
    gamma_t_pre: Real,
) -> AnalyticImpact {
    if gamma_n_pre.is_nan() || gamma_t_pre.is_nan() || gamma_n_pre >= 0.0 {
        return AnalyticImpact {
            mode: if gamma_t_pre > 0.0 {
                SlipMode::SlipOutward
            } else if gamma_t_pre < 0.0 {
                SlipMode::SlipInward
            } else {
                SlipMode::Stick
            },
            normal_impulse: 0.0,
            tangential_impulse: 0.0,
            gamma_n_post: gamma_n_pre,
            gamma_t_post: gamma_t_pre,
        };
    }
    let bounds = stick_interval(g, law);
    let n = -gamma_n_pre;
    let r = gamma_t_pre / gamma_n_pre;
    let a = 1.0 + law.eps;
    let mu = law.mu;
    let gamma_n_post = -law.eps * gamma_n_pre;
    if r < bounds.lower {
        let ln = a * n / (g.nn - mu * g.nt);
        AnalyticImpact {
            mode: SlipMode::SlipOutward,
            normal_impulse: ln,
            tangential_impulse: -mu * ln,
            gamma_n_post,
            gamma_t_post: n * (bounds.lower - r),
        }
    } else if r > bounds.upper {
        let ln = a * n / (g.nn + mu * g.nt);
        AnalyticImpact {
            mode: SlipMode::SlipInward,
            normal_impulse: ln,
            tangential_impulse: mu * ln,
            gamma_n_post,
            gamma_t_post: n * (bounds.upper - r),
        }
    } else {
        let det = g.det();
        AnalyticImpact {
            mode: SlipMode::Stick,
            normal_impulse: n * (a * g.tt - g.nt * r) / det,
            tangential_impulse: n * (g.nn * r - a * g.nt) / det,
            gamma_n_post,
            gamma_t_post: 0.0,
        }
    }
}

/// Exact kinetic-energy change of an impact (spec §11): `ΔT = ½ (γ⁺ + γ⁻)ᵀ Λ`.
pub fn energy_change(gamma_n_pre: Real, gamma_t_pre: Real, impact: &AnalyticImpact) -> Real {
    0.5 * ((impact.gamma_n_post + gamma_n_pre) * impact.normal_impulse
        + (impact.gamma_t_post + gamma_t_pre) * impact.tangential_impulse)
}

/// The spec's §11 conditions under which the impact *gains* kinetic energy, for `n = −γ_N⁻ > 0`
/// and the pre-impact ratio `r`:
///
/// * stick (`L ≤ r ≤ U`): `G_NN r² − 2 G_NT r + (1 − ε_N²) G_TT < 0`;
/// * outward slip (`r < L`): `μ (2r − L) > 1 − ε_N`;
/// * inward slip (`r > U`): `μ (U − 2r) > 1 − ε_N`.
///
/// A gain in the stick mode needs `G_NT² > (1 − ε_N²) G_NN G_TT` (see [`stick_gain_possible`]).
pub fn energy_gain_predicted(g: &Delassus, law: &ImpactLaw, r: Real) -> bool {
    let b = stick_interval(g, law);
    let (mu, e) = (law.mu, law.eps);
    if r < b.lower {
        mu * (2.0 * r - b.lower) > 1.0 - e
    } else if r > b.upper {
        mu * (b.upper - 2.0 * r) > 1.0 - e
    } else {
        g.nn * r * r - 2.0 * g.nt * r + (1.0 - e * e) * g.tt < 0.0
    }
}

/// `G_NT² > (1 − ε_N²) G_NN G_TT`: the necessary condition for an energy gain while sticking (spec §11).
pub fn stick_gain_possible(g: &Delassus, law: &ImpactLaw) -> bool {
    g.nt * g.nt > (1.0 - law.eps * law.eps) * g.nn * g.tt
}
