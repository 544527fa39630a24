//! Whole bridges: `N ≥ 1` deck segments in a row, joints between them, optional abutments at the
//! start and the end (issue 11), simulated by the same driver and steppers as the two-deck model.
//!
//! # Layout and frames **\[C\]**
//! Segment 1 is at the start of the bridge, segment `N` at its end; joint `k` (array index
//! `k − 1`) lies between segments `k` and `k + 1`. Every segment is one of the deck shapes of
//! [`crate::shape`] in its body frame (origin at the midpoint of the shape's *joint* face, that
//! face on the x-axis, the deck in `y > 0`), optionally mirrored (`x → −x`, [`Segment::mirrored`]:
//! a curved deck then curves the other way). The segments are placed end to end in the global
//! frame of the two-deck model (spec §4), anchored at joint 1:
//!
//! * segment 1 is its body frame (mirrored or not) translated by `(0, g_1)`: its shape's joint
//!   face is its **end** face, on the line `y = g_1`, and the segment lies in `y ≥ g_1`;
//! * every later segment has its shape's joint face as its **start** face; it is turned (and
//!   translated) so that this face is parallel to the previous segment's end face, at the joint's
//!   gap `g_k` from it along that face's normal, facing it, midpoints aligned. For two segments
//!   this is exactly the two-deck arrangement (segment 2 = the body frame turned by π).
//!
//! So a straight chain runs along `−y` from the start abutment to the end one: "joint `k` closes
//! as `x_k − x_{k+1}` grows" of issue 11 reads `y_{k+1} − y_k` here, and a ground acceleration
//! toward the end abutment is `a_g` along `−y` (`scale_y = -1` for a record positive toward the
//! end). A curved segment with [`Segment::mirrored`] `= false` curves **left** when segment 1 and
//! **right** when a later segment, walking from the start to the end; the paper's S is two
//! unmirrored segments.
//!
//! Displacements `q = (x_j, y_j, θ_j)` are those of each segment's centroid relative to the
//! ground and its rotation about the centroid, as in the two-deck model.
//!
//! # Model
//! Bearings tie each segment to the ground, or to the cap of a pier under its joint ([`Pier`]; the
//! module `pier`) ([`Bearing`]: linear springs of equal stiffness in x and y at body points,
//! linearised kinematics, with optional dashpots); damping is Rayleigh per segment or
//! translational dashpots ([`DampingModel`]). Without piers or backwalls `M`, `K`, `C` are block
//! diagonal; with them the system is coupled and runs on its dense matrices. An abutment may have
//! a backwall on backfill and piles ([`Backwall`]) and exterior shear keys. The contacts are those of the
//! two-deck model at every joint (four corner-against-face candidates, at most two realised) and
//! the outer-face corners at each abutment. With the rigid law the contacts active in one step
//! are solved together (one impact LCP over the bridge); with a compliance law every joint and
//! abutment carries its own law (shared by its two corners) and the Newton iteration couples
//! them. Rigid and compliance sites may be mixed (`super::mixed`).

pub use super::solution::{
    AbutmentSummary, BridgeSolution, BridgeSummary, JointSummary, SeatSummary, SegmentSummary,
};

use super::contact::JointGeom;
use super::dofs::Dofs;
use super::model::{EndFace, SegmentBody, deck_frequencies, rayleigh_coefficients};
use super::param::{BridgeKey, BridgeTable, ParamPath};
use super::scheme::BodySystem;
use super::support::{Attachment, Support};
use super::view::{AbutmentFace, Bridge, SeatEnd, SeatSupport};
use super::{Bearing, DampingModel, JointContact, SimError};
use crate::geometry::MassProperties;
use crate::ground_motion::GroundMotion;
use crate::math::{Real, Vector, cross};
use crate::shape::{DeckEnd, DeckShape};
use nalgebra::{Matrix2x3, Matrix3, Vector3};

mod backwall;
mod build;
mod geometry;
mod pier;
mod supports;
pub use backwall::{Backwall, Piles};
pub(crate) use geometry::placement;
use geometry::*;
pub use pier::{Pier, PierColumn};

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

/// One restrainer cable across a joint: tension-only, between an anchor on each of the two
/// segments ([`crate::element::restrainer::Restrainer`], the slack growing with yield).
///
/// **Anchors \[C\]**: on each segment at the point `M + o t + d ν`, with `M` the midpoint of the
/// segment's face at the joint, `t` the unit vector along that face pointing to the **left** of a
/// walk from the start of the bridge to its end, `ν` the face's inward normal (into the segment),
/// `o` = [`RestrainerSpec::offset`] and `d` = [`RestrainerSpec::depth`]. The default
/// `o = d = 0` ties the two face midpoints. Both anchors must lie on their segments (`|o|` at most
/// half the face length, the point inside the plan outline). A joint may carry several cables
/// (e.g. one on each side of the axis), each with its own parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestrainerSpec {
    /// Stiffness `k > 0` \[N/m\].
    pub k: Real,
    /// Slack `s ≥ 0` \[m\]: the cable is taut once the joint opens by more than this.
    pub slack: Real,
    /// Yield force \[N\] (`None`: elastic).
    pub fy: Option<Real>,
    /// Position `o` of the cable across the joint, along the faces from their midpoints,
    /// positive to the left walking from the start to the end \[m\].
    pub offset: Real,
    /// Depth `d ≥ 0` of both anchors inside their segments from the joint faces \[m\].
    pub depth: Real,
}

impl RestrainerSpec {
    /// A cable between the two face midpoints (`offset = depth = 0`).
    pub fn at_midpoints(k: Real, slack: Real, fy: Option<Real>) -> Self {
        RestrainerSpec {
            k,
            slack,
            fy,
            offset: 0.0,
            depth: 0.0,
        }
    }
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

    fn mirror(&self, p: Vector) -> Vector {
        if self.mirrored {
            Vector::new(-p.x, p.y)
        } else {
            p
        }
    }

    /// A face of the (mirrored) body frame as an [`EndFace`] (corners re-ordered after a mirror so
    /// that the segment stays to the right of `c0 → c1`).
    fn body_face(&self, end: DeckEnd) -> EndFace {
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
fn face(c: [Vector; 2], inward: Vector) -> EndFace {
    EndFace {
        corners: c,
        mid: (c[0] + c[1]) * 0.5,
        dir: (c[1] - c[0]).normalize(),
        inward,
        half: 0.5 * (c[1] - c[0]).norm(),
    }
}

/// A joint between two segments.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Reference opening `g ≥ 0` \[m\].
    pub gap: Real,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub friction: Real,
    /// Newton restitution coefficient `ε_N ∈ [0, 1]` (rigid law).
    pub restitution: Real,
    /// Seat length `> 0` of the two ends at this joint \[m\].
    pub seat_length: Real,
    /// Contact law.
    pub contact: JointContact,
    /// Restrainer cables across the joint (none: no restrainer).
    pub restrainers: Vec<RestrainerSpec>,
}

/// An abutment at the start or the end of the bridge: the ground, beyond the outer face of the
/// first or last segment (as [`super::SimAbutment`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BridgeAbutment {
    /// Gap `≥ 0` between the segment's outer face and the abutment face \[m\].
    pub gap: Real,
    /// Seat length `> 0` of the segment end on the abutment \[m\].
    pub seat_length: Real,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub friction: Real,
    /// Newton restitution coefficient `ε_N ∈ [0, 1]` (rigid law).
    pub restitution: Real,
    /// Contact law.
    pub contact: JointContact,
    /// A backwall that slides into backfill and piles ([`Backwall`]; `None`: the abutment face
    /// is the ground).
    pub backwall: Option<Backwall>,
    /// Exterior shear keys across the deck end ([`crate::element::shear_key::ShearKey`]: a gap
    /// and an elastic–perfectly-plastic key on each side; `None`: none). They act on the
    /// transverse displacement `v = u·t` of the segment's outer-face midpoint relative to the
    /// abutment (`t` along the face, [`super::view::AbutmentFace::tangent`]).
    pub shear_keys: Option<crate::element::shear_key::ShearKey>,
}

pub use crate::sim::param::ABUTMENT_SIDES;

/// A whole bridge.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeModel {
    /// Segments from the start to the end (`N ≥ 1`).
    pub segments: Vec<Segment>,
    /// Joint `k` (0-based) between segments `k` and `k + 1` (`N − 1` of them).
    pub joints: Vec<Joint>,
    /// Abutments `[start, end]`.
    pub abutments: [Option<BridgeAbutment>; 2],
    /// Seat length of an outer end without an abutment (it rests on a pier) \[m\].
    pub outer_seat_length: Real,
    /// Damping ratio `ζ ∈ [0, 1)`.
    pub damping_ratio: Real,
    /// Damping model.
    pub damping_model: DampingModel,
    /// Piers under joints ([`Pier`]; none: every bearing stands on the ground).
    pub piers: Vec<Pier>,
}

/// `segment[i].key`, `joint[k].key`, `abutment.start.key` (0-based indices, as in the arrays of
/// a scenario).
fn seg_key(i: usize, key: &str) -> BridgeKey {
    BridgeKey::new(BridgeTable::Segment(i), key)
}
pub(super) fn joint_key(k: usize, key: &str) -> BridgeKey {
    BridgeKey::new(BridgeTable::Joint(k), key)
}
pub(super) fn abut_key(side: usize, key: &str) -> BridgeKey {
    BridgeKey::new(BridgeTable::Abutment(side), key)
}

pub(super) fn check(
    name: impl Into<ParamPath>,
    v: Real,
    ok: bool,
    reason: &str,
) -> Result<(), SimError> {
    if ok && v.is_finite() {
        Ok(())
    } else if v.is_finite() {
        Err(SimError::invalid(name, v, reason))
    } else {
        Err(SimError::invalid(name, v, &super::finite_reason(reason)))
    }
}

impl BridgeModel {
    /// Validates every parameter; errors name `segment[i].key`, `joint[k].key`,
    /// `abutment.start.key`, ….
    pub fn validate(&self) -> Result<(), SimError> {
        let n = self.segments.len();
        if n == 0 {
            return Err(SimError::argument(
                "segment",
                "a bridge needs at least one segment",
            ));
        }
        if self.joints.len() + 1 != n {
            return Err(SimError::argument(
                "joint",
                format!(
                    "{n} segments need {} joints, found {}",
                    n - 1,
                    self.joints.len()
                ),
            ));
        }
        self.validate_segments()?;
        self.validate_joints()?;
        self.validate_abutments()?;
        self.validate_backwalls()?;
        self.validate_piers()?;
        check(
            "outer_seat_length",
            self.outer_seat_length,
            self.outer_seat_length > 0.0,
            "must be > 0",
        )?;
        check(
            "damping_ratio",
            self.damping_ratio,
            (0.0..1.0).contains(&self.damping_ratio),
            "must lie in [0, 1)",
        )?;
        self.contact_kinds()?;
        self.check_overlaps()?;
        self.check_points()?;
        Ok(())
    }

    /// Shapes, bearings and yield of every segment.
    fn validate_segments(&self) -> Result<(), SimError> {
        for (i, s) in self.segments.iter().enumerate() {
            s.shape.validate().map_err(|e| {
                SimError::argument(seg_key(i, "shape"), format!("invalid shape: {e}"))
            })?;
            for (b, br) in s.bearings.iter().enumerate() {
                let kr2 = br.stiffness * br.point.norm_squared();
                check(
                    seg_key(i, &format!("bearing[{b}].stiffness")),
                    br.stiffness,
                    br.stiffness >= 0.0 && kr2.is_finite(),
                    "must be finite and >= 0",
                )?;
            }
        }
        for (i, s) in self.segments.iter().enumerate() {
            if let Some(y) = &s.bearing_yield {
                check(seg_key(i, "fy"), y.fy, y.fy > 0.0, "must be finite and > 0")?;
                // each bearing yields at fy k_b / Σk: finite and > 0 too (fy = 1e305 or 5e-324
                // would overflow or underflow there)
                let total: Real = s.bearings.iter().map(|b| b.stiffness).sum();
                for b in s.bearings.iter().filter(|b| b.stiffness > 0.0) {
                    let fb = y.fy * (b.stiffness / total);
                    check(
                        seg_key(i, "fy"),
                        y.fy,
                        fb.is_normal() && fb > 0.0,
                        "gives a per-bearing yield force that is not a normal number; use a \
                         physical magnitude",
                    )?;
                }
                check(
                    seg_key(i, "b"),
                    y.b,
                    (0.0..1.0).contains(&y.b),
                    "must lie in [0, 1)",
                )?;
                if s.bearings.iter().all(|b| b.stiffness == 0.0) {
                    return Err(SimError::invalid(
                        seg_key(i, "fy"),
                        y.fy,
                        "yielding bearings need a positive stiffness",
                    ));
                }
            }
        }
        Ok(())
    }

    /// Gap, friction, restitution, seat, restrainer and matching face widths of every joint.
    fn validate_joints(&self) -> Result<(), SimError> {
        for (k, j) in self.joints.iter().enumerate() {
            for r in &j.restrainers {
                check(
                    joint_key(k, "restrainer_offsets"),
                    r.offset,
                    true,
                    "must be finite",
                )?;
                check(
                    joint_key(k, "restrainer_depth"),
                    r.depth,
                    r.depth >= 0.0,
                    "must be finite and >= 0",
                )?;
                crate::element::restrainer::Restrainer::new(
                    r.k,
                    r.slack,
                    r.fy,
                    crate::element::restrainer::SlackGrowth::Permanent,
                )
                .map_err(|e| {
                    SimError::argument(
                        joint_key(k, &format!("restrainer_{}", e.key())),
                        e.to_string(),
                    )
                })?;
            }
            check(joint_key(k, "gap"), j.gap, j.gap >= 0.0, "must be >= 0")?;
            check(
                joint_key(k, "mu"),
                j.friction,
                j.friction >= 0.0,
                "must be >= 0",
            )?;
            check(
                joint_key(k, "eps_n"),
                j.restitution,
                (0.0..=1.0).contains(&j.restitution),
                "must lie in [0, 1]",
            )?;
            check(
                joint_key(k, "seat_length"),
                j.seat_length,
                j.seat_length > 0.0,
                "must be > 0",
            )?;
            let (a, b) = (&self.segments[k], &self.segments[k + 1]);
            let (wa, wb) = (
                a.shape.end_face(DeckEnd::Joint).length(),
                b.shape.end_face(DeckEnd::Joint).length(),
            );
            let wa = if k == 0 {
                wa
            } else {
                a.shape.end_face(DeckEnd::Far).length()
            };
            if (wa - wb).abs() > 1e-9 * wa.max(wb) {
                return Err(SimError::argument(
                    seg_key(k + 1, "width"),
                    format!(
                        "segment[{}] meets segment[{k}] at joint[{k}] with a face {} m long, but \
                         segment[{k}]'s face there is {} m long: the two faces of a joint must have \
                         the same length (a skewed segment's end faces are width / cos(skew) long; \
                         adjust the widths so the faces match)",
                        k + 1,
                        crate::output::float_token(wb),
                        crate::output::float_token(wa)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Gap, seat, friction and restitution of each abutment.
    fn validate_abutments(&self) -> Result<(), SimError> {
        for (side, a) in self.abutments.iter().enumerate() {
            if let Some(a) = a {
                check(abut_key(side, "gap"), a.gap, a.gap >= 0.0, "must be >= 0")?;
                check(
                    abut_key(side, "seat_length"),
                    a.seat_length,
                    a.seat_length > 0.0,
                    "must be > 0",
                )?;
                check(
                    abut_key(side, "mu"),
                    a.friction,
                    a.friction >= 0.0,
                    "must be >= 0",
                )?;
                check(
                    abut_key(side, "eps_n"),
                    a.restitution,
                    (0.0..=1.0).contains(&a.restitution),
                    "must lie in [0, 1]",
                )?;
            }
        }
        Ok(())
    }
}

/// Everything a bridge run needs besides the settings.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeProblem {
    /// The bridge.
    pub model: BridgeModel,
    /// The ground acceleration (the reference motion when the supports move apart).
    pub ground: GroundMotion,
    /// How the supports move ([`crate::sim::excitation`]; uniform by default).
    pub supports: crate::sim::excitation::SupportExcitation,
    /// Initial displacements `q(0)`, laid out by [`BridgeModel::dofs`] \[m, rad\].
    pub q0: Vec<Real>,
    /// Initial velocities `u(0)` relative to the ground \[m/s, rad/s\].
    pub u0: Vec<Real>,
}

impl BridgeProblem {
    /// At rest in the reference pose.
    pub fn at_rest(model: BridgeModel, ground: GroundMotion) -> Self {
        let n = model.dofs().len();
        Self {
            model,
            ground,
            supports: Default::default(),
            q0: vec![0.0; n],
            u0: vec![0.0; n],
        }
    }
}
