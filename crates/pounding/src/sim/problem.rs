//! What the simulator runs: a [`Problem`] — the general form, a bridge ([`BridgeProblem`]), or
//! a preset that expands into one (the two-deck model [`SimProblem`], a bridge of two segments,
//! [`BridgeModel::from_pair`]) — and the one entry point [`simulate`].
//!
//! A preset is sugar: it checks its own parameters under its own names (`R1`, `beta2`, `q0[3]`)
//! and hands the integrators the bridge it stands for; nothing downstream knows which form it
//! came from except the [`Layout`] of its files (the two-deck model keeps its column names and
//! JSON keys).

use super::bridge::{BridgeModel, BridgeProblem, BridgeSolution};
use super::excitation::SupportExcitation;
use super::output::Layout;
use super::{SimError, SimProblem, SimSettings};
use crate::ground_motion::GroundMotion;
use crate::math::Real;
use std::borrow::Cow;

/// A problem the simulator runs: a model, its ground motion and its initial state.
pub trait Problem: Sync {
    /// The bridge that runs (a preset: the bridge it expands into).
    fn model(&self) -> Cow<'_, BridgeModel>;
    /// The ground acceleration (the reference motion when the supports move apart).
    fn ground(&self) -> &GroundMotion;
    /// How the supports move ([`SupportExcitation`]).
    fn supports(&self) -> &SupportExcitation;
    /// The initial displacements and velocities `(q(0), u(0))`, laid out by
    /// [`BridgeModel::dofs`] of [`Self::model`].
    fn initial(&self) -> (&[Real], &[Real]);
    /// Checks the model, naming the problem's own parameters in the error.
    fn check_model(&self) -> Result<(), SimError>;
    /// Checks the initial state (its length, finite entries), naming its entries.
    fn check_initial(&self) -> Result<(), SimError>;
    /// The same problem under another ground motion (a batch run).
    fn with_ground(&self, ground: GroundMotion) -> Self
    where
        Self: Sized;
    /// The same problem with a motion of each support's own and `ground` as the reference (a
    /// batch run of a support-motion entry); an error for a problem without supports of its
    /// own (the two-deck model).
    fn with_motion(
        &self,
        ground: GroundMotion,
        supports: SupportExcitation,
    ) -> Result<Self, SimError>
    where
        Self: Sized;
    /// How its output files are laid out.
    fn layout(&self) -> Layout;
}

/// Runs a problem: the settings, the ground motion, the model and the initial state are
/// checked (in that order), then the bridge is integrated by the Moreau–Jean driver with the
/// steppers its contact laws ask for (module doc of [`crate::sim`]).
///
/// Bad input → [`SimError`]; numerical trouble → [`BridgeSolution::status`].
pub fn simulate<P: Problem + ?Sized>(
    problem: &P,
    settings: &SimSettings,
) -> Result<BridgeSolution, SimError> {
    settings.validate()?;
    problem.ground().validate()?;
    problem.check_model()?;
    problem.check_initial()?;
    let model = problem.model();
    let view = model.bridge();
    let ground = (problem.ground(), problem.supports());
    let (result, systems, kinds) =
        super::integrate::integrate(&model, &view, ground, problem.initial(), settings)?;
    Ok(super::solution::solution(
        result,
        (&systems, settings.dt),
        &view,
        &model,
        &kinds,
    ))
}

/// The two-deck model's supports all move with its ground motion: the error of a motion per
/// support given to it.
pub(crate) fn two_deck_supports_error() -> SimError {
    SimError::argument(
        "supports",
        "a two-deck file's supports all move with its ground motion: a motion per support needs \
         a bridge file ([[segment]] tables)",
    )
}

/// Every support with the run's ground motion.
pub(crate) static UNIFORM: SupportExcitation = SupportExcitation::Uniform;

/// The first entry of `v` that is not finite, as an error naming it `name[i]`.
fn finite(name: &str, v: &[Real]) -> Result<(), SimError> {
    match v.iter().enumerate().find(|(_, x)| !x.is_finite()) {
        Some((i, x)) => Err(SimError::invalid(
            format!("{name}[{i}]"),
            *x,
            "must be finite",
        )),
        None => Ok(()),
    }
}

impl Problem for BridgeProblem {
    fn model(&self) -> Cow<'_, BridgeModel> {
        Cow::Borrowed(&self.model)
    }
    fn ground(&self) -> &GroundMotion {
        &self.ground
    }
    fn supports(&self) -> &SupportExcitation {
        &self.supports
    }
    fn initial(&self) -> (&[Real], &[Real]) {
        (&self.q0, &self.u0)
    }
    fn check_model(&self) -> Result<(), SimError> {
        self.model.validate()
    }
    fn check_initial(&self) -> Result<(), SimError> {
        let n = self.model.dofs().len();
        for (name, v) in [("q0", &self.q0), ("u0", &self.u0)] {
            if v.len() != n {
                return Err(SimError::argument(
                    name,
                    format!("must have {n} entries (3 per segment), found {}", v.len()),
                ));
            }
            finite(name, v)?;
        }
        Ok(())
    }
    fn with_ground(&self, ground: GroundMotion) -> Self {
        BridgeProblem {
            model: self.model.clone(),
            ground,
            supports: self.supports.clone(),
            q0: self.q0.clone(),
            u0: self.u0.clone(),
        }
    }
    fn with_motion(
        &self,
        ground: GroundMotion,
        supports: SupportExcitation,
    ) -> Result<Self, SimError> {
        Ok(BridgeProblem {
            supports,
            ..self.with_ground(ground)
        })
    }
    fn layout(&self) -> Layout {
        Layout::Bridge
    }
}

/// The two-deck preset: deck `j` is segment `j`, the joint is joint 1, the abutment of deck 1
/// the start abutment, of deck 2 the end one ([`BridgeModel::from_pair`]).
impl Problem for SimProblem {
    fn model(&self) -> Cow<'_, BridgeModel> {
        Cow::Owned(BridgeModel::from_pair(&self.model))
    }
    fn ground(&self) -> &GroundMotion {
        &self.ground
    }
    fn supports(&self) -> &SupportExcitation {
        &UNIFORM
    }
    fn initial(&self) -> (&[Real], &[Real]) {
        (&self.q0, &self.u0)
    }
    fn check_model(&self) -> Result<(), SimError> {
        self.model.check().map(|_| ())
    }
    fn check_initial(&self) -> Result<(), SimError> {
        finite("q0", &self.q0)?;
        finite("u0", &self.u0)
    }
    fn with_motion(&self, _: GroundMotion, _: SupportExcitation) -> Result<Self, SimError> {
        Err(two_deck_supports_error())
    }
    fn with_ground(&self, ground: GroundMotion) -> Self {
        SimProblem {
            model: self.model.clone(),
            ground,
            q0: self.q0,
            u0: self.u0,
        }
    }
    fn layout(&self) -> Layout {
        Layout::TwoDecks
    }
}
