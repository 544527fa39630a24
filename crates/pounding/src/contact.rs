//! Generalised force directions (spec §6) and the Delassus matrix (spec §7).
//!
//! Generalised coordinates `q = (x1, y1, θ1, x2, y2, θ2)` (centroid displacements and rotations
//! about the centroids), mass matrix `M = diag(m1, m1, I1, m2, m2, I2)`, velocity
//! `u = (v1x, v1y, ω1, v2x, v2y, ω2)`.

use crate::geometry::{DeckId, ImpactConfiguration, MassProperties, SArrangement};
use crate::math::{Real, cross};

/// `w_N`, `w_T` in `q = (x1, y1, θ1, x2, y2, θ2)` coordinates plus the lever-arm moments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceDirections {
    /// `w_N = ∂g_N/∂q = (ν_x, ν_y, A_1, −ν_x, −ν_y, −A_2)`.
    pub w_n: [Real; 6],
    /// `w_T = (τ_x, τ_y, B_1, −τ_x, −τ_y, −B_2)`.
    pub w_t: [Real; 6],
}

impl ForceDirections {
    /// `γ_N = w_Nᵀ u`: normal relative velocity of deck 1's point w.r.t. deck 2's (positive = separating).
    pub fn gamma_n(&self, u: &[Real; 6]) -> Real {
        dot6(&self.w_n, u)
    }
    /// `γ_T = w_Tᵀ u`: tangential relative velocity along `τ` (positive = toward deck 1's outward side).
    pub fn gamma_t(&self, u: &[Real; 6]) -> Real {
        dot6(&self.w_t, u)
    }
}

fn dot6(a: &[Real; 6], b: &[Real; 6]) -> Real {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
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

/// Force directions at an impact configuration (spec §6):
///
/// with `r_j = C − G_j` (the struck deck's arm uses the struck point, which is the corner in the
/// exact σ mode and the face end in the `end` mode), `A_j = r_j × ν`, `B_j = r_j × τ`,
/// ```text
/// w_N = ( ν_x, ν_y, A_1, −ν_x, −ν_y, −A_2 )ᵀ
/// w_T = ( τ_x, τ_y, B_1, −τ_x, −τ_y, −B_2 )ᵀ
/// ```
/// (The configuration carries every vector needed; `arrangement` is part of the stable signature.)
pub fn force_directions(
    arrangement: &SArrangement,
    config: &ImpactConfiguration,
) -> ForceDirections {
    let _ = arrangement;
    let nu = config.normal;
    let tau = config.tangent;
    let r1 = config.lever_arm(DeckId::One);
    let r2 = config.lever_arm(DeckId::Two);
    let (a1, b1) = (cross(&r1, &nu), cross(&r1, &tau));
    let (a2, b2) = (cross(&r2, &nu), cross(&r2, &tau));
    ForceDirections {
        w_n: [nu.x, nu.y, a1, -nu.x, -nu.y, -a2],
        w_t: [tau.x, tau.y, b1, -tau.x, -tau.y, -b2],
    }
}

/// The Delassus matrix at an impact configuration (spec §7):
/// ```text
/// G_NN = 1/m_1 + 1/m_2 + A_1²/I_1 + A_2²/I_2
/// G_NT = A_1 B_1/I_1 + A_2 B_2/I_2
/// G_TT = 1/m_1 + 1/m_2 + B_1²/I_1 + B_2²/I_2
/// ```
/// for the decks' own `ρ t` (G scales as `1/(ρ t)`).
pub fn delassus(arrangement: &SArrangement, config: &ImpactConfiguration) -> Delassus {
    let p1 = arrangement.deck1.mass_properties();
    let p2 = arrangement.deck2.mass_properties();
    delassus_with(&p1, &p2, &force_directions(arrangement, config))
}

/// `G = Wᵀ M⁻¹ W` from force directions and precomputed mass properties (the fast path of
/// [`delassus`]; `ν ⊥ τ` makes the translational cross terms vanish).
#[inline]
pub fn delassus_with(
    props1: &MassProperties,
    props2: &MassProperties,
    w: &ForceDirections,
) -> Delassus {
    let inv_m = 1.0 / props1.mass + 1.0 / props2.mass;
    let (i1, i2) = (1.0 / props1.inertia, 1.0 / props2.inertia);
    let (a1, a2) = (w.w_n[2], w.w_n[5]);
    let (b1, b2) = (w.w_t[2], w.w_t[5]);
    Delassus {
        nn: inv_m + a1 * a1 * i1 + a2 * a2 * i2,
        nt: a1 * b1 * i1 + a2 * b2 * i2,
        tt: inv_m + b1 * b1 * i1 + b2 * b2 * i2,
    }
}
