//! Generalised force directions (spec §6) and the Delassus matrix (spec §7): the one
//! implementation of each, for two decks of any shape ([`force_directions`], [`delassus_with`])
//! and for a deck against the ground ([`delassus_of_bodies`] with one body).
//!
//! Generalised coordinates `q = (x1, y1, θ1, x2, y2, θ2)` (centroid displacements and rotations
//! about the centroids), mass matrix `M = diag(m1, m1, I1, m2, m2, I2)`, velocity
//! `u = (v1x, v1y, ω1, v2x, v2y, ω2)`.

use crate::geometry::{DeckId, ImpactConfiguration, MassProperties};
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
/// The configuration carries every vector needed, whatever the decks' shapes.
pub fn force_directions(config: &ImpactConfiguration) -> ForceDirections {
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

/// One body's share in a single contact: its mass properties and the moment arms
/// `A = r × ν`, `B = r × τ` of the contact point about its centroid (signs as the body sees the
/// contact; they enter `G` squared or as the product `A B`, so a body's common sign drops out).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyArms {
    /// Mass `m` \[kg\].
    pub mass: Real,
    /// Polar moment about the centroid `I` \[kg m²\].
    pub inertia: Real,
    /// `A = r × ν` \[m\].
    pub arm_n: Real,
    /// `B = r × τ` \[m\].
    pub arm_t: Real,
}

/// The single-contact Delassus matrix `G = Wᵀ M⁻¹ W` (spec §7) of a contact between the bodies
/// listed (two decks, or one deck against the immovable ground), `ν ⊥ τ` making the
/// translational cross terms vanish:
/// ```text
/// G_NN = Σ 1/m_j + Σ A_j²/I_j,   G_NT = Σ A_j B_j/I_j,   G_TT = Σ 1/m_j + Σ B_j²/I_j .
/// ```
/// The sums run in the order given (first the inverse masses, then the rotational terms), so
/// the result is reproducible to the last bit.
///
/// # Panics
/// If `N = 0`.
#[inline]
pub fn delassus_of_bodies<const N: usize>(bodies: &[BodyArms; N]) -> Delassus {
    let (first, rest) = bodies
        .split_first()
        .expect("a contact has at least one body");
    let mut inv_m = 1.0 / first.mass;
    for b in rest {
        inv_m += 1.0 / b.mass;
    }
    let i0 = 1.0 / first.inertia;
    let (a0, b0) = (first.arm_n, first.arm_t);
    let (mut nn, mut nt, mut tt) = (inv_m + a0 * a0 * i0, a0 * b0 * i0, inv_m + b0 * b0 * i0);
    for b in rest {
        let i = 1.0 / b.inertia;
        let (a, bb) = (b.arm_n, b.arm_t);
        nn += a * a * i;
        nt += a * bb * i;
        tt += bb * bb * i;
    }
    Delassus { nn, nt, tt }
}

/// The Delassus matrix of two decks (spec §7) from their force directions and mass properties:
/// ```text
/// G_NN = 1/m_1 + 1/m_2 + A_1²/I_1 + A_2²/I_2
/// G_NT = A_1 B_1/I_1 + A_2 B_2/I_2
/// G_TT = 1/m_1 + 1/m_2 + B_1²/I_1 + B_2²/I_2
/// ```
/// for the decks' own `ρ t` (G scales as `1/(ρ t)`); [`delassus_of_bodies`] with the arms
/// `(A_1, B_1) = (w_N[2], w_T[2])`, `(A_2, B_2) = (w_N[5], w_T[5])` (the sign of deck 2's arms
/// drops out).
#[inline]
pub fn delassus_with(
    props1: &MassProperties,
    props2: &MassProperties,
    w: &ForceDirections,
) -> Delassus {
    delassus_of_bodies(&[
        BodyArms {
            mass: props1.mass,
            inertia: props1.inertia,
            arm_n: w.w_n[2],
            arm_t: w.w_t[2],
        },
        BodyArms {
            mass: props2.mass,
            inertia: props2.inertia,
            arm_n: w.w_n[5],
            arm_t: w.w_t[5],
        },
    ])
}
