//! The driver's view of a bridge as lists: segments (bodies), joints, abutment faces, seated
//! ends, bearings, supports, elements, and the geometry of one state ([`Frame`]). Built by
//! `BridgeModel::bridge`; read by the driver, the steppers, the observers and the solution.

use super::contact::{JointFrame, JointGeom, Pose, State, candidates};
use super::dofs::Dofs;
use super::model::SegmentBody;
use super::support::Attachment;
use crate::math::{Real, Vector};

/// An abutment face (the ground) beyond the start face of the first segment or the end face of
/// the last one ([`super::SimAbutment`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct AbutmentFace {
    /// The segment (0-based) whose outer face meets it.
    pub body: usize,
    /// 0: the start abutment, 1: the end abutment.
    pub side: usize,
    /// The segment's face corners (reference pose).
    pub corners: [Vector; 2],
    /// Normal into the segment.
    pub normal: Vector,
    /// Tangent `perp(n)`.
    pub tangent: Vector,
    /// A point of the face (reference pose).
    pub point: Vector,
    /// Reference gap.
    pub gap: Real,
    /// The backwall body whose face this is (`None`: the ground); the face moves with it along
    /// `−normal` by its coordinate `s`.
    pub wall: Option<usize>,
    /// Its support line (`start` or `end`, [`super::excitation`]).
    pub line: usize,
}

impl AbutmentFace {
    /// How far the face has moved away from the deck, `s` of its backwall at `q` (0 without).
    #[inline]
    pub fn shift(&self, dofs: &Dofs, q: &[Real]) -> Real {
        self.wall.map_or(0.0, |w| dofs.axial_displacement(w, q))
    }

    /// [`Self::shift`] with the face's support moved by `ground` (its line's offset, if the
    /// supports move apart: [`super::excitation`]).
    #[inline]
    pub fn shift_on(&self, dofs: &Dofs, q: &[Real], ground: &[Vector]) -> Real {
        let s = self.shift(dofs, q);
        match (self.wall, ground.get(self.line)) {
            // a ground face moves with its support; a backwall is a body of its own
            (None, Some(d)) => s - d.dot(&self.normal),
            _ => s,
        }
    }

    /// A contact direction at this face: `v` (with moment arm `r`) on the segment and, with a
    /// backwall, its reaction `−v` on the wall.
    pub fn direction(&self, v: Vector, r: &Vector) -> super::contact::Direction {
        super::contact::Direction {
            first: (self.body, [v.x, v.y, crate::math::cross(r, &v)]),
            second: self.wall.map(|w| (w, [-v.x, -v.y, 0.0])),
        }
    }
}

impl AbutmentFace {
    /// The abutment at `gap` beyond `side` (0: start, 1: end) of `body`, support `support`.
    pub fn new(bodies: &[SegmentBody], (body, side): (usize, usize), gap: Real) -> Self {
        let face = if side == 0 {
            &bodies[body].start
        } else {
            &bodies[body].end
        };
        let n = face.inward;
        AbutmentFace {
            body,
            side,
            corners: face.corners,
            normal: n,
            tangent: Vector::new(-n.y, n.x),
            point: face.mid - n * gap,
            gap,
            wall: None,
            line: if side == 0 { 0 } else { body + 1 },
        }
    }
}

/// What a seated end rests on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SeatSupport {
    /// The abutment of a side (0 start, 1 end).
    Abutment(usize),
    /// Joint `k` (0-based, between segments `k` and `k + 1`).
    Joint(usize),
    /// An outer seat without abutment, of a side (0 start, 1 end).
    Outer(usize),
}

/// A segment end resting on a seat.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SeatEnd {
    /// The segment.
    pub body: usize,
    /// The segment's end face (`false`: its start face).
    pub at_end: bool,
    /// What it rests on.
    pub support: SeatSupport,
    /// Its corners (reference pose).
    pub corners: [Vector; 2],
    /// Inward normal of the face.
    pub inward: Vector,
    /// Seat length.
    pub length: Real,
    /// The body it is seated on (a pier's cap; `None`: the ground): seat displacements are
    /// relative to it.
    pub base: Option<usize>,
    /// The support line under it (the ground it is seated on when `base` is `None`).
    pub line: usize,
}

/// A bearing under a segment: its point (global reference pose) and its (initial) stiffness.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BearingAt {
    /// Its top: a point of the segment it carries.
    pub top: Attachment,
    /// Its bottom: a point of the support under it ([`Bridge::supports`]; the ground).
    pub bottom: Attachment,
    /// Stiffness in each plan direction \[N/m\].
    pub stiffness: Real,
    /// The support line under it (its bottom's motion when that is the ground).
    pub line: usize,
}

impl BearingAt {
    /// The arm `r = p − G⁰` of a bearing on a segment (the segment's point from its reference
    /// centroid); `(0, 0)` for a top on a support.
    pub fn arm(&self, bodies: &[SegmentBody]) -> Vector {
        match self.top {
            Attachment::Body(i, p) => p - bodies[i].centroid,
            Attachment::Support(..) => Vector::zeros(),
        }
    }

    /// The linearised deformation `u_top − u_bottom` at `q` ([`Attachment::linear_displacement`]).
    #[inline]
    pub fn deformation(&self, dofs: &Dofs, q: &[Real], bodies: &[SegmentBody]) -> Vector {
        self.top.linear_displacement(dofs, q, bodies)
            - self.bottom.linear_displacement(dofs, q, bodies)
    }
}

/// The bridge as lists: segments, joints, abutments, seated ends.
pub(crate) struct Bridge {
    /// Reference-pose segments.
    pub bodies: Vec<SegmentBody>,
    /// Joint `k` between segments `k` and `k + 1`.
    pub joints: Vec<JointGeom>,
    /// Abutment faces (only the present ones), start before end.
    pub abutments: Vec<AbutmentFace>,
    /// Seated ends, in the order of the seat outputs.
    pub seats: Vec<SeatEnd>,
    /// The supports: the ground (0), then the present abutments ([`super::support`]).
    pub supports: Vec<super::support::Support>,
    /// Where each segment's coordinates sit in `q` and `u`.
    pub dofs: Dofs,
    /// The bearings of each segment.
    pub bearings: Vec<Vec<BearingAt>>,
    /// Yielding bearings and restrainers in their initial state.
    pub elements: super::elements::Elements,
    /// The piers.
    pub piers: Vec<PierAt>,
}

/// A pier as the driver sees it: its cap's body, its column.
#[derive(Debug, Clone)]
pub(crate) struct PierAt {
    /// The joint it carries.
    pub joint: usize,
    /// The cap's body.
    pub body: usize,
    /// The column's initial stiffness \[N/m\].
    pub k0: Real,
    /// The column's yielding members in [`super::elements::Elements::bearings`] (none:
    /// elastic; one: a yield circle; two: per axis).
    pub elements: Vec<usize>,
}

/// The offset of support line `s` in `ground` (zero when the supports move together: empty).
#[inline]
pub(crate) fn ground_at(ground: &[Vector], s: usize) -> Vector {
    ground.get(s).copied().unwrap_or_else(Vector::zeros)
}

impl PierAt {
    /// The cap's displacement `(x_c, y_c)` relative to its foundation (the column's
    /// deformation; `ground`: the support lines' offsets, empty when they move together) and the
    /// column's force on the ground side, `k0 u − (1 − b) k0 Σ u_p` (its members' committed
    /// plastic displacements in `elements`).
    pub fn drift_and_force(
        &self,
        dofs: &Dofs,
        q: &[Real],
        elements: &super::elements::Elements,
        ground: &[Vector],
    ) -> (Vector, Vector) {
        let [x, y, _] = dofs.plan_of(self.body, q);
        let mut u = Vector::new(x, y);
        if let Some(d) = ground.get(self.joint + 1) {
            u -= d;
        }
        // k0 u − Σ (1 − b) k0 u_p over its members (each u_p along its own axis)
        let mut f = u * self.k0;
        for &e in &self.elements {
            let b = &elements.bearings[e];
            f -= b.state.u_p * ((1.0 - b.law.b()) * b.law.k0());
        }
        (u, f)
    }
}

impl Bridge {
    /// The geometry at `q`.
    pub fn frame(&self, q: &State) -> Frame {
        let pose = Pose::new(&self.bodies, &self.dofs, q.as_slice());
        let joints = self
            .joints
            .iter()
            .map(|j| candidates(&self.bodies, &pose, j))
            .collect();
        Frame {
            pose,
            joints,
            ground: Vec::new(),
        }
    }

    /// [`Self::frame`] at `q` into `frame` (a frame of this bridge), reusing its storage.
    pub fn update_frame(&self, q: &State, frame: &mut Frame) {
        frame.pose.set(&self.bodies, &self.dofs, q.as_slice());
        for (jf, j) in frame.joints.iter_mut().zip(&self.joints) {
            *jf = candidates(&self.bodies, &frame.pose, j);
        }
    }
}

/// The geometry of one state: pose and the candidates of every joint.
pub(crate) struct Frame {
    /// The pose.
    pub pose: Pose,
    /// Per joint: its candidates and the realised one of each end.
    pub joints: Vec<JointFrame>,
    /// The support lines' offsets from the reference ground at this state's time (empty when
    /// the supports move together: [`super::excitation`]).
    pub ground: Vec<Vector>,
}
