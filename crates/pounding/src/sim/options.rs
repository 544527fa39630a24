//! Model options added for the compliance-law comparison (issue 7): straight rectangular decks,
//! translational dashpot damping, and the joint's contact law.
//!
//! Kept apart from [`super::model`] so that the curved-deck model stays untouched.
#![allow(clippy::needless_range_loop)]

use super::SimError;
use super::model::DeckBody;
use crate::contact_law::ContactLaw;
use crate::geometry::MassProperties;
use crate::math::{Real, Vector};

/// A straight rectangular deck (plan `W × L`, `W` the common joint width of the model) replacing
/// the curved deck of the same number.
///
/// Reference pose: deck 1 occupies `x ∈ [−W/2, W/2]`, `y ∈ [g, g + L]`; deck 2 occupies
/// `x ∈ [−W/2, W/2]`, `y ∈ [−L, 0]` (its joint face on `y = 0`). Mass properties:
/// `m` (given, or `ρ t L W`), centroid at the plan centre, `I = m (L² + W²)/12`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StraightDeck {
    /// Length `L > 0` normal to the joint \[m\].
    pub length: Real,
    /// Mass `m > 0` \[kg\]; `None` = `ρ t L W` from the model's curved-deck density and
    /// thickness.
    pub mass: Option<Real>,
}

impl StraightDeck {
    /// Mass properties for width `w`, thickness `t`, density `rho` (errors name `length{j}` /
    /// `mass{j}`).
    pub fn mass_properties(
        &self,
        j: usize,
        w: Real,
        t: Real,
        rho: Real,
    ) -> Result<MassProperties, SimError> {
        let l = self.length;
        if !(l.is_finite() && l > 0.0) {
            return Err(SimError::invalid(
                format!("length{j}"),
                l,
                "must be finite and > 0",
            ));
        }
        let m = match self.mass {
            Some(m) if m.is_finite() && m > 0.0 => m,
            Some(m) => {
                return Err(SimError::invalid(
                    format!("mass{j}"),
                    m,
                    "must be finite and > 0",
                ));
            }
            None => rho * t * l * w,
        };
        Ok(MassProperties {
            area: l * w,
            mass: m,
            centroid_radius: Real::NAN,
            x_m: 0.0,
            y_m: l / 2.0,
            inertia: m * (l * l + w * w) / 12.0,
        })
    }

    /// The deck's four end-face corners relative to its joint-face midpoint `M_j`:
    /// `[joint inner, joint outer, far inner, far outer]` (inner corner at `x = +W/2` for deck 1,
    /// `x = −W/2` for deck 2, as for the curved decks).
    pub fn corner_points(&self, j: usize, w: Real) -> [Vector; 4] {
        let s = if j == 1 { 1.0 } else { -1.0 };
        let l = self.length;
        [
            Vector::new(s * w / 2.0, 0.0),
            Vector::new(-s * w / 2.0, 0.0),
            Vector::new(s * w / 2.0, s * l),
            Vector::new(-s * w / 2.0, s * l),
        ]
    }

    pub(crate) fn body(&self, mass: MassProperties, j: usize, w: Real, gap: Real) -> DeckBody {
        let s = if j == 1 { 1.0 } else { -1.0 };
        let face_mid = if j == 1 {
            Vector::new(0.0, gap)
        } else {
            Vector::zeros()
        };
        let c = self.corner_points(j, w);
        DeckBody {
            mass,
            centroid: face_mid + Vector::new(0.0, s * self.length / 2.0),
            face_mid,
            joint_corners: [face_mid + c[0], face_mid + c[1]],
            far_corners: [face_mid + c[2], face_mid + c[3]],
            face_dir: Vector::new(-s, 0.0),
            joint_inward: Vector::new(0.0, s),
            far_inward: Vector::new(0.0, -s),
        }
    }
}

/// How the decks are damped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DampingModel {
    /// Rayleigh damping per deck, `C_j = a_0 M_j + a_1 K_j`, ratio `ζ` at the deck's two lowest
    /// distinct natural frequencies (the default).
    #[default]
    Rayleigh,
    /// Viscous dashpots from each deck's centroid to the ground in x and y (none in rotation):
    /// `c_j = 2 ζ m_j ω_j` with `ω_j = √(K_j,yy / m_j)` the deck's translational frequency
    /// (`c = 2ζ m 2π/T`, the damping of the OpenSees 1-D benchmark).
    TranslationalDashpots,
}

/// The normal contact law of the joint.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum JointContact {
    /// Rigid contact: the velocity-level Newton impact law with Coulomb friction solved as an LCP
    /// (the default; [`super::simulate`]'s Moreau–Jean scheme).
    #[default]
    Rigid,
    /// A compliance law ([`crate::contact_law`]) shared by the joint's two corner contacts
    /// ([`crate::contact_law::sharing`]), with regularised Coulomb friction
    /// ([`super::compliance`]).
    Compliance(ComplianceContact),
}

/// A compliance contact of the joint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ComplianceContact {
    /// The law of the joint as a whole (each of the 2 corner contacts carries half of it).
    pub law: ContactLaw,
    /// Regularisation velocity `v_r > 0` of the friction law
    /// `f_T = −μ f_N γ_T / √(γ_T² + v_r²)` \[m/s\]. Default 1e-3.
    pub friction_velocity: Real,
}

impl ComplianceContact {
    /// The law with the default friction regularisation velocity 1e-3 m/s.
    pub fn new(law: ContactLaw) -> Self {
        Self {
            law,
            friction_velocity: 1e-3,
        }
    }
}

impl super::SimModel {
    /// Mass properties of deck `j ∈ {1, 2}` (straight override or the curved deck).
    pub fn deck_mass_properties(&self, j: usize) -> Result<MassProperties, SimError> {
        let d = if j == 1 {
            &self.arrangement.deck1
        } else {
            &self.arrangement.deck2
        };
        match &self.straight[j - 1] {
            Some(s) => s.mass_properties(j, d.width, d.thickness, d.density),
            None => Ok(d.mass_properties()),
        }
    }

    /// The four end-face corners of deck `j ∈ {1, 2}` relative to its joint-face midpoint (the
    /// default bearing points): `[joint inner, joint outer, far inner, far outer]`.
    pub fn deck_corner_points(&self, j: usize) -> [Vector; 4] {
        match &self.straight[j - 1] {
            Some(s) => s.corner_points(j, self.arrangement.deck1.width),
            None => super::end_corner_points(&self.arrangement, j),
        }
    }

    pub(crate) fn apply_straight(&self, bodies: &mut [DeckBody; 2]) {
        for j in 0..2 {
            if let Some(s) = &self.straight[j]
                && let Ok(mp) = self.deck_mass_properties(j + 1)
            {
                bodies[j] = s.body(mp, j + 1, self.arrangement.deck1.width, self.gap);
            }
        }
    }

    pub(crate) fn validate_options(&self) -> Result<(), SimError> {
        for j in 1..=2 {
            self.deck_mass_properties(j)?;
        }
        if let JointContact::Compliance(c) = &self.contact {
            let v = c.friction_velocity;
            if !(v.is_finite() && v > 0.0) {
                return Err(SimError::invalid(
                    "friction_velocity",
                    v,
                    "must be finite and > 0",
                ));
            }
        }
        Ok(())
    }

    /// `(C_j, a_0, a_1)` of one deck for the damping model (`a_0`, `a_1` the Rayleigh
    /// coefficients; zero for dashpots).
    pub(crate) fn damping_of(
        &self,
        mj: &nalgebra::Matrix3<Real>,
        kj: &nalgebra::Matrix3<Real>,
        a0: Real,
        a1: Real,
    ) -> (nalgebra::Matrix3<Real>, Real, Real) {
        match self.damping_model {
            DampingModel::Rayleigh => (mj * a0 + kj * a1, a0, a1),
            DampingModel::TranslationalDashpots => {
                let m = mj[(0, 0)];
                let c = 2.0 * self.damping_ratio * m * (kj[(1, 1)] / m).max(0.0).sqrt();
                (
                    nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(c, c, 0.0)),
                    0.0,
                    0.0,
                )
            }
        }
    }
}
