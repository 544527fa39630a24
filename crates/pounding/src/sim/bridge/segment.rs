//! A deck segment of a bridge ([`Segment`]): its shape, mirror and bearings, and its faces and
//! points in its (mirrored) body frame.

use super::*;

/// One deck segment.
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    /// Its outline in the body frame of [`crate::shape`].
    pub shape: DeckShape,
    /// Mirror the body frame (`x → −x`) before placing the segment (module doc: a curved
    /// segment then curves the other way; a skewed one gets the opposite skew).
    pub mirrored: bool,
    /// Bearings; points in the segment's body frame (after the mirror, before placement).
    /// [`Bearing::stiffness`] is the initial stiffness `k0` of a yielding bearing.
    pub bearings: Vec<Bearing>,
    /// Yielding bearings ([`crate::element::bearing::BilinearBearing`]): `None` = linear.
    pub bearing_yield: Option<BearingYield>,
    /// A dashpot in parallel with each bearing, in each plan direction, on the bearing's
    /// deformation `c ≥ 0` \[N·s/m\] (0: none).
    pub bearing_damping: Real,
}

/// The yield of a segment's bearings: bilinear with kinematic hardening, each bearing `b` with
/// `k0 = k_b`, yield force `F_y k_b / Σ k` (so the bearings of a translating segment yield
/// together at the segment's `F_y`) and post-yield ratio `b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingYield {
    /// Yield force of all the segment's bearings together `F_y > 0` \[N\].
    pub fy: Real,
    /// Post-yield stiffness ratio `b ∈ [0, 1)`.
    pub b: Real,
}

impl Segment {
    /// A segment with one bearing of stiffness `k` at each of the four end-face corners.
    pub fn with_corner_bearings(shape: DeckShape, mirrored: bool, k: Real) -> Self {
        let mut s = Segment {
            shape,
            mirrored,
            bearings: Vec::new(),
            bearing_yield: None,
            bearing_damping: 0.0,
        };
        s.bearings = s
            .corner_points()
            .into_iter()
            .map(|point| Bearing {
                point,
                stiffness: k,
            })
            .collect();
        s
    }

    /// The four end-face corners in the (mirrored) body frame: `[joint c0, joint c1, far c0,
    /// far c1]` of the shape.
    pub fn corner_points(&self) -> [Vector; 4] {
        let m = |p: Vector| self.mirror(p);
        let j = self.shape.end_face(DeckEnd::Joint);
        let f = self.shape.end_face(DeckEnd::Far);
        [
            m(j.corners[0]),
            m(j.corners[1]),
            m(f.corners[0]),
            m(f.corners[1]),
        ]
    }

    /// [`BridgeModel::segment_point`] of this segment; `first`: it is segment 1 (whose start
    /// face is its shape's far face; later segments start with their shape's joint face).
    pub fn frame_point(&self, first: bool, along: Real, left: Real) -> Vector {
        let (start, end) = if first {
            (DeckEnd::Far, DeckEnd::Joint)
        } else {
            (DeckEnd::Joint, DeckEnd::Far)
        };
        let f = self.body_face(start);
        let axis = match self.shape.curved() {
            Some(_) => f.inward,
            None => (self.body_face(end).mid - f.mid).normalize(),
        };
        f.mid + axis * along + left_of(axis) * left
    }

    pub(super) fn mirror(&self, p: Vector) -> Vector {
        if self.mirrored {
            Vector::new(-p.x, p.y)
        } else {
            p
        }
    }

    /// A face of the (mirrored) body frame as an [`EndFace`] (corners re-ordered after a mirror so
    /// that the segment stays to the right of `c0 → c1`).
    pub(super) fn body_face(&self, end: DeckEnd) -> EndFace {
        let f = self.shape.end_face(end);
        let (c0, c1) = if self.mirrored {
            (self.mirror(f.corners[1]), self.mirror(f.corners[0]))
        } else {
            (f.corners[0], f.corners[1])
        };
        let n_out = if self.mirrored {
            Vector::new(-f.outward_normal.x, f.outward_normal.y)
        } else {
            f.outward_normal
        };
        face([c0, c1], -n_out)
    }
}

/// The [`EndFace`] with corners `c` and inward normal `inward`.
pub(super) fn face(c: [Vector; 2], inward: Vector) -> EndFace {
    EndFace {
        corners: c,
        mid: (c[0] + c[1]) * 0.5,
        dir: (c[1] - c[0]).normalize(),
        inward,
        half: 0.5 * (c[1] - c[0]).norm(),
    }
}
