//! Generalised force directions (spec §6) and the Delassus matrix (spec §7).
//!
//! CONTRACT (skeleton; the single-impact work item fills it, keeping names and signatures).

use crate::geometry::{ImpactConfiguration, SArrangement};
use crate::math::Real;

/// `w_N`, `w_T` in `q = (x1, y1, θ1, x2, y2, θ2)` coordinates plus the lever-arm moments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceDirections {
    /// `w_N = ∂g_N/∂q = (ν_x, ν_y, A_1, −ν_x, −ν_y, −A_2)`.
    pub w_n: [Real; 6],
    /// `w_T = (τ_x, τ_y, B_1, −τ_x, −τ_y, −B_2)`.
    pub w_t: [Real; 6],
}

/// The single-contact Delassus matrix `G = Wᵀ M⁻¹ W` (spec §7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Delassus {
    /// `G_NN` \[1/kg\].
    pub nn: Real,
    /// `G_NT = G_TN` \[1/kg\].
    pub nt: Real,
    /// `G_TT` \[1/kg\].
    pub tt: Real,
}

impl Delassus {
    /// `κ = G_NT / G_NN`.
    pub fn kappa(&self) -> Real {
        self.nt / self.nn
    }
    /// `ϱ = G_TT / G_NN`.
    pub fn varrho(&self) -> Real {
        self.tt / self.nn
    }
    /// `det G = G_NN G_TT − G_NT²`.
    pub fn det(&self) -> Real {
        self.nn * self.tt - self.nt * self.nt
    }
}

/// Force directions at an impact configuration.
pub fn force_directions(
    arrangement: &SArrangement,
    config: &ImpactConfiguration,
) -> ForceDirections {
    let _ = (arrangement, config);
    todo!("single-impact work item")
}

/// The Delassus matrix at an impact configuration.
pub fn delassus(arrangement: &SArrangement, config: &ImpactConfiguration) -> Delassus {
    let _ = (arrangement, config);
    todo!("single-impact work item")
}
