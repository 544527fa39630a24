//! Supports and attachments: what the bodies of a system rest on and how elements tie to them.
//!
//! A **support** has no coordinates of its own: its motion is prescribed (the ground under the
//! bearings, an abutment). Every element (bearing, restrainer) links two **attachments**, each a
//! point of a body or a point of a support, as a joint links two bodies in a multibody code with
//! the ground one fixed body among others; contact sites are between two faces or a face and a
//! support (the abutments).
//!
//! # Coupling rule: one ground motion
//! The system is written in displacements relative to the ground, `q = q_abs − r u_g(t)`, so
//! the supports' prescribed motion enters only as the effective load `F = −M r a_g(t)` and every
//! support point stays where it is in these coordinates. That holds when **every support moves
//! with the one ground motion of the run** ([`SupportMotion::Ground`]). A support with a motion of
//! its own (wave passage, site effects) needs the quasi-static part of the response as well; the
//! driver refuses such a system ([`check_uniform`]) rather than integrate it as if it were uniform.

use super::SimError;
use super::contact::Pose;
use super::dofs::{BodyKind, Dofs};
use super::model::SegmentBody;
use crate::math::{Real, Vector};

/// The prescribed motion of a support.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SupportMotion {
    /// The run's ground motion (the uniform excitation).
    Ground,
}

/// A support of the system.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Support {
    /// What it is, as outputs name it (`ground`, `abutment-start`, `abutment-end`).
    pub name: &'static str,
    /// Its motion.
    pub motion: SupportMotion,
}

impl Support {
    /// The ground under the bearings (support 0 of every system).
    pub const GROUND: usize = 0;

    /// The supports of a bridge: the ground, then the abutment of each present side.
    pub fn of_bridge(abutments: [bool; 2]) -> Vec<Support> {
        let mut s = vec![Support {
            name: "ground",
            motion: SupportMotion::Ground,
        }];
        for (side, name) in ["abutment-start", "abutment-end"].into_iter().enumerate() {
            if abutments[side] {
                s.push(Support {
                    name,
                    motion: SupportMotion::Ground,
                });
            }
        }
        s
    }
}

/// Refuses supports that do not all move with the one ground motion (module doc).
pub(crate) fn check_uniform(supports: &[Support]) -> Result<(), SimError> {
    match supports.iter().find(|s| s.motion != SupportMotion::Ground) {
        None => Ok(()),
        Some(s) => Err(SimError::argument(
            format!("support {}", s.name),
            "has a motion of its own; only a ground motion shared by every support is \
                     supported",
        )),
    }
}

/// Where an element attaches: a point of a body or of a support (global reference pose).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Attachment {
    /// A point of body `.0`.
    Body(usize, Vector),
    /// A point of support `.0` (it does not move in the relative coordinates).
    Support(usize, Vector),
}

impl Attachment {
    /// The body it moves with, if any.
    #[inline]
    pub fn body(&self) -> Option<usize> {
        match *self {
            Attachment::Body(b, _) => Some(b),
            Attachment::Support(..) => None,
        }
    }

    /// Its displacement at `q` with linearised rotation: `(x − θ r_y, y + θ r_x)`, `r` from the
    /// body's reference centroid; a support point does not move (module doc).
    #[inline]
    pub fn linear_displacement(&self, dofs: &Dofs, q: &[Real], bodies: &[SegmentBody]) -> Vector {
        match *self {
            Attachment::Body(b, p) => {
                let [x, y, th] = dofs.plan_of(b, q);
                if dofs.kind(b) != BodyKind::PlanRigid {
                    // a body that does not turn: every point moves with it
                    return Vector::new(x, y);
                }
                let r = p - bodies[b].centroid;
                Vector::new(x - th * r.y, y + th * r.x)
            }
            Attachment::Support(..) => Vector::zeros(),
        }
    }

    /// Its current position in `pose`, and the current centroid of its body (the origin of its
    /// lever arm; the point itself for a support, which takes no moment). Only for points of
    /// segments and supports (a pose holds the segments).
    #[inline]
    pub fn place(&self, pose: &Pose, bodies: &[SegmentBody]) -> (Vector, Vector) {
        match *self {
            Attachment::Body(b, p) => (pose.place(bodies, b, &p), pose.g[b]),
            Attachment::Support(_, p) => (p, p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::bridge::BridgeModel;

    /// The ground is support 0, the present abutments follow; a support does not move and a
    /// body attachment moves with its body; a support with a motion of its own is refused.
    #[test]
    fn supports_and_attachments() {
        let s = Support::of_bridge([false, true]);
        assert_eq!(s.len(), 2);
        assert_eq!((s[0].name, s[1].name), ("ground", "abutment-end"));
        assert!(check_uniform(&s).is_ok());
        let model = BridgeModel::from_pair(&crate::sim::SimModel::default_bridge());
        let br = model.bridge();
        assert_eq!(br.supports.len(), 1);
        assert!(br.bearings.iter().flatten().all(|b| {
            matches!(b.bottom, Attachment::Support(Support::GROUND, _))
                && matches!(b.top, Attachment::Body(..))
        }));
        let bodies = &br.bodies;
        let mut q = vec![0.0; 6];
        q[0] = 0.5; // segment 1 moves 0.5 m along x
        let pose = Pose::new(bodies, &Dofs::plan_rigid(2), &q);
        let p = Vector::new(3.0, 4.0);
        let on_body = Attachment::Body(0, p).place(&pose, bodies);
        assert!((on_body.0 - (p + Vector::new(0.5, 0.0))).norm() < 1e-12);
        assert_eq!(Attachment::Support(0, p).place(&pose, bodies), (p, p));
        assert_eq!(Attachment::Support(0, p).body(), None);
    }
}
