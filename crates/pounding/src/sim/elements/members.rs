//! The nonlinear members of a bridge and their kinematics: yielding bearings and pier columns,
//! restrainer cables, backfills behind backwalls and exterior shear keys.

use crate::element::backfill::BackfillElement;
use crate::element::bearing::{BearingState, BilinearBearing};
use crate::element::restrainer::RestrainerElement;
use crate::element::shear_key::ShearKeyElement;
use crate::math::{Real, Vector, cross};
use crate::sim::contact::{Pose, State};
use crate::sim::dofs::Dofs;
use crate::sim::model::SegmentBody;
use crate::sim::support::Attachment;

/// One yielding bearing of a segment, or a yielding pier column: a bilinear spring from a point
/// of `body` to a point of `base` (another body: a pier cap) or to the ground.
#[derive(Debug, Clone)]
pub(crate) struct YieldingBearing {
    /// The body it carries (a segment, or the cap of a column).
    pub body: usize,
    /// Its index among the segment's bearings (a column: its pier).
    pub slot: usize,
    /// Lever arm `r = p − G⁰` (reference pose).
    pub arm: Vector,
    /// The body under it and the arm of its point there (`None`: the ground).
    pub base: Option<(usize, Vector)>,
    /// A member acting along one plan direction only (a pier column's yielding per axis, OpenSees
    /// `Steel01` along that axis): its deformation is the projection `(u·a) a` (`None`: the plan
    /// deformation, a yield circle).
    pub axis: Option<Vector>,
    /// Its law.
    pub law: BilinearBearing,
    /// Committed state.
    pub state: BearingState,
    /// The support line under it when it stands on the ground (`None`: on a body, or on ground
    /// that moves with the reference: a backwall's piles).
    pub line: Option<usize>,
    /// That support's current offset from the reference ground (zero when the supports move
    /// together; set per step by the driver, [`super::Elements::set_ground`]).
    pub ground: Vector,
}

impl YieldingBearing {
    /// The part of its deformation that its support's offset takes away: the offset (on its
    /// axis, for a member along one), zero on a body or on ground that moves with the reference.
    #[inline]
    pub fn ground_offset(&self) -> Vector {
        match (self.line, self.base, self.axis) {
            (Some(_), None, None) => self.ground,
            (Some(_), None, Some(a)) => a * self.ground.dot(&a),
            _ => Vector::zeros(),
        }
    }

    /// Its linearised deformation at `q`: its point on [`Self::body`] relative to its point on
    /// [`Self::base`] (or the ground).
    #[inline]
    pub fn deformation(&self, dofs: &Dofs, q: &State) -> Vector {
        let u = deformation(dofs, q, self.body, &self.arm);
        let u = match self.base {
            None if self.line.is_some() => u - self.ground,
            None => u,
            Some((c, arm)) => u - deformation(dofs, q, c, &arm),
        };
        match self.axis {
            None => u,
            Some(a) => a * u.dot(&a),
        }
    }
}

/// Linearised deformation `u = (x − θ r_y, y + θ r_x)` of a bearing with arm `r` on `body`.
pub(crate) fn deformation(dofs: &Dofs, q: &State, body: usize, r: &Vector) -> Vector {
    let [x, y, th] = dofs.plan_of(body, q.as_slice());
    Vector::new(x - th * r.y, y + th * r.x)
}

/// One restrainer: a tension-only cable between two attachments (today across a joint, from
/// segment `k` to segment `k + 1`; an end on a support stays put, [`crate::sim::support`]).
#[derive(Debug, Clone)]
pub(crate) struct Cable {
    /// The joint it crosses.
    pub joint: usize,
    /// First anchor (reference pose, global).
    pub a: Attachment,
    /// Second anchor.
    pub b: Attachment,
    /// Reference length `L_0 = |P_b⁰ − P_a⁰|`.
    pub length: Real,
    /// The cable.
    pub element: RestrainerElement,
}

impl Cable {
    /// Elongation `e = |P_b − P_a| − L_0` in `pose` (exact anchor positions).
    pub fn elongation(&self, pose: &Pose, bodies: &[SegmentBody]) -> Real {
        let (pa, pb, _, _) = cable_points(self, pose, bodies);
        (pb - pa).norm() - self.length
    }
}

/// The cable's anchors and the current centroids of their bodies in `pose`.
pub(super) fn cable_points(
    c: &Cable,
    pose: &Pose,
    bodies: &[SegmentBody],
) -> (Vector, Vector, Vector, Vector) {
    let ((pa, ga), (pb, gb)) = (c.a.place(pose, bodies), c.b.place(pose, bodies));
    (pa, pb, ga, gb)
}

/// The backfill behind an abutment's backwall: a force `−F(s)` on the wall's coordinate `s`
/// (into the soil), held over each step as the cables' forces are.
#[derive(Debug, Clone)]
pub(crate) struct BackfillAt {
    /// The wall's body.
    pub body: usize,
    /// The backfill spring.
    pub element: BackfillElement,
    /// The abutment's support line.
    pub line: usize,
    /// That support's offset along the wall's coordinate (zero when the supports move together;
    /// [`super::Elements::set_ground`]): the soil behind the wall moves with it.
    pub ground: Real,
}

/// Exterior shear keys at an abutment: a force `−F(v) t` at the segment's outer-face midpoint,
/// `v = u·t` its linearised transverse displacement (relative to the ground), held over each step
/// as the cables' forces are.
#[derive(Debug, Clone)]
pub(crate) struct KeyAt {
    /// The abutment side.
    pub side: usize,
    /// The segment.
    pub body: usize,
    /// Arm `r = M − G⁰` of the face midpoint.
    pub arm: Vector,
    /// The face's tangent `t`.
    pub tangent: Vector,
    /// The keys.
    pub element: ShearKeyElement,
    /// The committed force `F` \[N\].
    pub force: Real,
    /// The abutment's support line.
    pub line: usize,
    /// That support's offset along `t` (zero when the supports move together;
    /// [`super::Elements::set_ground`]): the keys stand on the abutment.
    pub ground: Real,
}

impl KeyAt {
    /// `v = u·t` at `q`.
    #[inline]
    pub fn deformation(&self, dofs: &Dofs, q: &[Real]) -> Real {
        let [x, y, th] = dofs.plan_of(self.body, q);
        let u = Vector::new(x - th * self.arm.y, y + th * self.arm.x);
        u.dot(&self.tangent) - self.ground
    }

    /// Adds the force `−F t` on the segment to `r`.
    pub(super) fn add_force(&self, dofs: &Dofs, f: Real, r: &mut State) {
        let t = self.tangent;
        dofs.add_plan(
            self.body,
            r.as_mut_slice(),
            [-f * t.x, -f * t.y, -f * cross(&self.arm, &t)],
        );
    }
}
