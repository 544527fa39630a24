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
//! `trial`/`commit` methods.
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
