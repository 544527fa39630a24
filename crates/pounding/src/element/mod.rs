//! Structural elements between a deck and the ground or between two decks: bearings
//! ([`bearing`]: linear, or bilinear with kinematic hardening in 2-D), cable restrainers
//! ([`restrainer`]: tension-only with slack, optionally yielding), and the substructure laws:
//! abutment backfill behind a backwall ([`backfill`]: hyperbolic, compression-only with a gap,
//! with the Caltrans SDC 2019 preset), piles and piers (elastic–perfectly-plastic: the
//! bilinear bearing with `b = 0`, see [`bearing::BilinearBearing::elastic_perfectly_plastic`])
//! and exterior shear keys ([`shear_key`]: gap + elastic–perfectly-plastic on both sides).
//!
//! Each element is a *rate-independent constitutive law* in the same functional form, so a
//! time-stepping driver (or a Newton iteration inside one step) can evaluate trial states freely
//! and commit once per step:
//!
//! ```text
//! response(deformation, &committed) -> { force, tangent, trial state, step dissipation }
//! committed = response.trial                       (commit at the end of an accepted step)
//! ```
//!
//! `response` never mutates anything (safe to call in parallel, any number of times per step).
//! The state types are `Copy`; [`bearing::BearingElement`], [`restrainer::RestrainerElement`],
//! [`backfill::BackfillElement`] and [`shear_key::ShearKeyElement`] are small holders (law + committed state + accumulated dissipation) for a driver that prefers
//! `trial`/`commit` methods; the last two are the one generic holder [`Held`] of a
//! [`UniaxialLaw`].
//!
//! # Energy
//! Every law reports its *stored* (recoverable, elastic) energy `E(state)` and the *plastic
//! dissipation* of a step `D = f_p · Δu_p ≥ 0` (the return-mapping work of the yielding spring,
//! computed in closed form, never negative). For a quasi-static path in increments `Δu → 0`,
//! `Σ ½ (f_k + f_{k+1}) · Δu = ΔE + Σ D` (the tests check this converges). A time stepper with
//! the trapezoidal rule books the element work `½ (f_k + f_{k+1}) · Δu` exactly; the difference
//! `W_step − ΔE − D` is the discretisation error of the law's kinks (yield onset, a cable
//! becoming taut or slack), which vanishes as the step shrinks. A driver whose balance must
//! close to rounding should book the hysteretic energy as `W_step − ΔE` (for the bilinear
//! bearing provably in `[0, D]`, see [`bearing::BilinearBearing`]; for a cable crossing its
//! slack within a step it has either sign) and may report `Σ D` beside it. The backfill's
//! dissipation is instead the exact `W − ΔE` of each step (its envelope work is in closed form),
//! which is negative on the early envelope if `kur < kmax` (see [`backfill::HyperbolicGap`]).
//!
//! # Errors
//! Bad parameters give an [`ElementError`] naming the parameter key (`k0`, `fy`, `b`, `k`,
//! `slack`, `kmax`, `kur`, `rf`, `fult`, `gap`, `height`, `width`, `skew`) — the same key a scenario file uses — so a scenario reader can prefix file and line
//! via [`ElementError::key`].

/// Implements [`UniaxialLaw`] for a law whose inherent `initial_state`, `response` and
/// `stored_energy` have the trait's signatures and whose response has `trial` and `dissipation`.
macro_rules! uniaxial_law {
    ($law:ty, $state:ty, $response:ty) => {
        impl super::UniaxialLaw for $law {
            type State = $state;
            type Response = $response;
            fn initial_state(&self) -> $state {
                <$law>::initial_state(self)
            }
            fn response(&self, u: Real, committed: &$state) -> $response {
                <$law>::response(self, u, committed)
            }
            fn stored_energy(&self, state: &$state) -> Real {
                <$law>::stored_energy(self, state)
            }
            fn accepted(r: &$response) -> ($state, Real) {
                (r.trial, r.dissipation)
            }
        }
    };
}

pub mod backfill;
pub mod bearing;
pub mod restrainer;
pub mod shear_key;

pub use backfill::{
    BackfillElement, CaltransBackwall, HyperbolicGap, HyperbolicGapResponse, HyperbolicGapState,
};
pub use shear_key::{ShearKey, ShearKeyElement, ShearKeyResponse, ShearKeyState};

use crate::math::Real;
use thiserror::Error;

/// A rate-independent law of one deformation in the functional form of this module:
/// `response(u, &committed)` gives the trial state and the step's dissipation.
pub trait UniaxialLaw: Copy {
    /// The committed history variables.
    type State: Copy + PartialEq + std::fmt::Debug;
    /// A trial response (force, tangent, trial state, dissipation).
    type Response;
    /// The virgin state.
    fn initial_state(&self) -> Self::State;
    /// Trial response at deformation `u` from the committed state (pure).
    fn response(&self, u: Real, committed: &Self::State) -> Self::Response;
    /// Stored (recoverable) energy of a state \[J\].
    fn stored_energy(&self, state: &Self::State) -> Real;
    /// What committing `response` keeps: its trial state and its step dissipation \[J\].
    fn accepted(response: &Self::Response) -> (Self::State, Real);
}

/// A law as a driver holds it: the law, the committed state and the dissipation accumulated
/// over the committed steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Held<L: UniaxialLaw> {
    law: L,
    committed: L::State,
    dissipated: Real,
}

impl<L: UniaxialLaw> Held<L> {
    /// A virgin element.
    pub fn new(law: L) -> Self {
        Held {
            law,
            committed: law.initial_state(),
            dissipated: 0.0,
        }
    }
    /// The law.
    pub fn law(&self) -> &L {
        &self.law
    }
    /// The committed state.
    pub fn committed(&self) -> &L::State {
        &self.committed
    }
    /// Trial response at deformation `u` (pure).
    pub fn trial(&self, u: Real) -> L::Response {
        self.law.response(u, &self.committed)
    }
    /// Accepts a trial response computed from the current committed state.
    pub fn commit(&mut self, response: &L::Response) {
        let (state, dissipation) = L::accepted(response);
        self.committed = state;
        self.dissipated += dissipation;
    }
    /// Stored energy at the committed state \[J\].
    pub fn stored_energy(&self) -> Real {
        self.law.stored_energy(&self.committed)
    }
    /// Dissipation accumulated over the committed steps \[J\].
    pub fn dissipated(&self) -> Real {
        self.dissipated
    }
}

/// Bad element input: a parameter that is not finite or outside its range.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ElementError {
    /// A parameter is not finite or out of its range.
    #[error("invalid {element} parameter `{key}` = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// The element kind (`bilinear bearing`, `linear bearing`, `restrainer`,
        /// `hyperbolic backfill`, `Caltrans backwall`, `shear key`).
        element: &'static str,
        /// The parameter key as a scenario file spells it (`k0`, `fy`, `b`, `k`, `slack`, …).
        key: &'static str,
        /// The offending value.
        value: Real,
        /// What was expected (e.g. `must be finite and > 0`).
        reason: &'static str,
    },
}

impl ElementError {
    /// The offending parameter key (`k0`, `fy`, `b`, `k`, `slack`, …), for a caller that adds the
    /// file and line of that key.
    pub fn key(&self) -> &'static str {
        match self {
            ElementError::InvalidParameter { key, .. } => key,
        }
    }
}

/// `Ok(v)` if `v` is finite and `> 0`.
pub(crate) fn positive(
    element: &'static str,
    key: &'static str,
    v: Real,
) -> Result<Real, ElementError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(ElementError::InvalidParameter {
            element,
            key,
            value: v,
            reason: "must be finite and > 0",
        })
    }
}

/// `Ok(v)` if `v` is finite and `≥ 0`.
pub(crate) fn non_negative(
    element: &'static str,
    key: &'static str,
    v: Real,
) -> Result<Real, ElementError> {
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(ElementError::InvalidParameter {
            element,
            key,
            value: v,
            reason: "must be finite and >= 0",
        })
    }
}

/// The trapezoidal work of one step, `½ (f_k + f_{k+1}) · (u_{k+1} − u_k)`, for scalar
/// elements (restrainers); for vectors use `0.5 * (f_k + f_k1).dot(&(u_k1 - u_k))`.
pub fn step_work(f_k: Real, f_k1: Real, u_k: Real, u_k1: Real) -> Real {
    0.5 * (f_k + f_k1) * (u_k1 - u_k)
}
