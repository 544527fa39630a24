//! Abutments with a backwall: the abutment face the deck strikes is a wall body that slides
//! into the soil behind it, held by the backfill and by piles.
//!
//! # Model
//! The backwall of an abutment is a body of mass `m_w` moving along one plan direction, `a`,
//! the abutment face's normal pointing away from the deck (into the soil): its coordinate `s` is
//! its displacement into the soil relative to the ground. The deck's outer corners strike the
//! wall's face (the abutment's contact law, rigid or compliance, acting between the corner and
//! the moving face: the gap is `(c − p_face)·n + s`, the reaction `−f` on the wall, of which the
//! wall takes the component along `a`). Behind the wall:
//! * the **backfill**, compression only, OpenSees `HyperbolicGapMaterial`
//!   ([`crate::element::backfill::HyperbolicGap`]: hyperbolic backbone `F = u / (1/K_max +
//!   R_f u / F_ult)` past its gap, unloading and reloading with `K_ur`), on `u = s`;
//! * the **piles**, elastic–perfectly-plastic both ways (OpenSees `ElasticPP`, stiffness `k`,
//!   yield force `F_y`), on `u = s`.
//!
//! The deck's own bearings at the abutment stand on the abutment (the ground), not on the wall.
//! The piles are yielding members of the implicit return mapping (their `k` in `K`); the backfill
//! is a force held over each step as the restrainers' are (the mean of its committed force and
//! its force at the predicted end of the step), which needs `h √(K_max / m_w) ≤ 1`.

use super::*;
use crate::element::backfill::HyperbolicGap;

/// The piles of a backwall: elastic–perfectly-plastic both ways.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piles {
    /// Stiffness `k > 0` \[N/m\].
    pub k: Real,
    /// Yield force `F_y > 0` \[N\].
    pub fy: Real,
}

/// An abutment's backwall (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Backwall {
    /// Mass `m_w > 0` \[kg\].
    pub mass: Real,
    /// The backfill behind it (`None`: no soil).
    pub backfill: Option<HyperbolicGap>,
    /// Its piles (`None`: none).
    pub piles: Option<Piles>,
}

impl BridgeModel {
    /// The body index of the backwall of abutment `side` (after the segments and the caps).
    pub(crate) fn wall_body(&self, side: usize) -> Option<usize> {
        let has = |s: usize| self.abutments[s].is_some_and(|a| a.backwall.is_some());
        has(side).then(|| self.segments.len() + self.piers.len() + usize::from(side == 1 && has(0)))
    }

    /// Whether some abutment has a backwall.
    pub(crate) fn has_backwalls(&self) -> bool {
        (0..2).any(|s| self.wall_body(s).is_some())
    }

    /// The direction into the soil of each backwall, start before end.
    pub(crate) fn wall_axes(&self) -> Vec<Vector> {
        if !self.has_backwalls() {
            // (no layout: the DOF map of a model not yet validated must not need one)
            return Vec::new();
        }
        let bodies = self.layout();
        let n = bodies.len();
        (0..2)
            .filter(|&s| self.wall_body(s).is_some())
            .map(|s| {
                if s == 0 {
                    -bodies[0].start.inward
                } else {
                    -bodies[n - 1].end.inward
                }
            })
            .collect()
    }

    /// Mass `> 0`, piles `k, F_y > 0`, a backwall needs something behind it, and
    /// `h √(K_max / m_w) ≤ 1` is checked with the step.
    pub(super) fn validate_backwalls(&self) -> Result<(), SimError> {
        for (side, a) in self.abutments.iter().enumerate() {
            let Some(w) = a.and_then(|a| a.backwall) else {
                continue;
            };
            let key = |k: &str| abut_key(side, &format!("backwall.{k}"));
            check(key("mass"), w.mass, w.mass > 0.0, "must be finite and > 0")?;
            if let Some(p) = w.piles {
                check(key("piles_k"), p.k, p.k > 0.0, "must be finite and > 0")?;
                check(key("piles_fy"), p.fy, p.fy > 0.0, "must be finite and > 0")?;
            }
            if let Some(b) = w.backfill
                && b.kur() < b.kmax()
            {
                return Err(SimError::invalid(
                    key("kur"),
                    b.kur(),
                    "must be >= kmax: with a softer unloading the backfill law gives back more \
                     energy than it took",
                ));
            }
            if w.backfill.is_none() && w.piles.is_none() {
                return Err(SimError::argument(
                    key("mass"),
                    "a backwall with neither backfill nor piles behind it is free to fly \
                             off: give its backfill or its piles",
                ));
            }
        }
        Ok(())
    }

    /// The step must resolve each backfill's initial stiffness on its wall (it is held over the
    /// step): `h √(K_max / m_w) ≤ 1`.
    pub(super) fn check_backfill_step(&self, dt: Real) -> Result<(), SimError> {
        let masses: Vec<Real> = self.layout().iter().map(|b| b.mass.mass).collect();
        for (side, a) in self.abutments.iter().enumerate() {
            let Some(k) = a.and_then(|a| a.shear_keys) else {
                continue;
            };
            let m = masses[if side == 0 { 0 } else { masses.len() - 1 }];
            let om = (k.k() / m).sqrt();
            if dt * om > 1.0 {
                return Err(SimError::invalid(
                    "dt",
                    dt,
                    &format!(
                        "the shear keys of abutment.{} (k {} N/m on a {} kg segment) are held \
                         over each step and need dt <= {:.3e} s",
                        ABUTMENT_SIDES[side],
                        crate::output::float_token(k.k()),
                        crate::output::float_token(m),
                        1.0 / om
                    ),
                ));
            }
        }
        for (side, a) in self.abutments.iter().enumerate() {
            let Some(w) = a.and_then(|a| a.backwall) else {
                continue;
            };
            let Some(b) = w.backfill else { continue };
            let om = (b.kmax() / w.mass).sqrt();
            if !om.is_finite() {
                return Err(SimError::invalid(
                    abut_key(side, "backwall.mass"),
                    w.mass,
                    "is too small for its backfill: kmax / mass overflows (no time step resolves \
                     it); use a physical mass",
                ));
            }
            if dt * om > 1.0 {
                return Err(SimError::invalid(
                    "dt",
                    dt,
                    &format!(
                        "the backfill of abutment.{} (kmax {} N/m on a {} kg wall, ω = {:.4e} \
                         rad/s) is held over each step and needs dt <= {:.3e} s",
                        ABUTMENT_SIDES[side],
                        crate::output::float_token(b.kmax()),
                        crate::output::float_token(w.mass),
                        om,
                        1.0 / om
                    ),
                ));
            }
        }
        Ok(())
    }
}
