//! Model options added for the compliance-law comparison (issue 7): straight rectangular decks,
//! translational dashpot damping, and the joint's contact law.
//!
//! Kept apart from [`super::model`] so that the curved-deck model stays untouched.
#![allow(clippy::needless_range_loop)]

use super::SimError;
use crate::contact_law::ContactLaw;
use crate::math::{Real, Vector};

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
    /// The four end-face corners of deck `j ∈ {1, 2}` relative to its joint-face midpoint (the
    /// default bearing points): `[joint c0, joint c1, far c0, far c1]`, for the curved decks of
    /// `arrangement` or the deck [`super::SimModel::shapes`].
    pub fn deck_corner_points(&self, j: usize) -> [Vector; 4] {
        match &self.shapes {
            Some(sh) => super::shape_corner_points(&sh[j - 1], j),
            None => super::end_corner_points(&self.arrangement, j),
        }
    }

    pub(crate) fn validate_options(&self) -> Result<(), SimError> {
        let JointContact::Compliance(c) = &self.contact else {
            return Ok(());
        };
        if self.abutments.iter().any(Option::is_some) {
            return Err(SimError::invalid(
                "contact_law",
                f64::NAN,
                "abutments ([abutments]) are only supported with rigid contact ([contact] law = \"rigid\")",
            ));
        }
        {
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
