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
//! Bearings tie each segment to the ground ([`Bearing`]: linear springs of equal stiffness in x
//! and y at body points, linearised kinematics); damping is Rayleigh per segment or translational
//! dashpots ([`DampingModel`]); `M`, `K`, `C` are block diagonal. The contacts are those of the
//! two-deck model at every joint (four corner-against-face candidates, at most two realised) and
//! the outer-face corners at each abutment. With the rigid law the contacts active in one step
//! are solved together (one impact LCP over the bridge); with a compliance law every joint and
//! abutment carries its own law (shared by its two corners) and the Newton iteration couples
//! them. All joints and abutments must use the same kind of contact (all rigid, or all
//! compliance laws); their parameters may differ.

pub use super::solution::{
    AbutmentSummary, BridgeSolution, BridgeSummary, JointSummary, SeatSummary, SegmentSummary,
};

use super::contact::JointGeom;
use super::dofs::Dofs;
use super::model::{EndFace, SegmentBody, deck_frequencies, rayleigh_coefficients};
use super::scheme::BodySystem;
use super::support::{Attachment, Support};
use super::view::{AbutmentFace, Bridge, SeatEnd, SeatSupport};
use super::{Bearing, DampingModel, JointContact, SimError};
use crate::geometry::MassProperties;
use crate::ground_motion::GroundMotion;
use crate::math::{Real, Vector, cross};
use crate::shape::{DeckEnd, DeckShape};
use nalgebra::{Matrix2x3, Matrix3, Vector3};

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
}

/// Which abutment.
pub const ABUTMENT_SIDES: [&str; 2] = ["start", "end"];

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
}

/// `segment[i].key`, `joint[k].key`, `abutment.start.key` (0-based indices, as in the arrays of
/// a scenario).
fn seg_key(i: usize, key: &str) -> String {
    format!("segment[{i}].{key}")
}
pub(super) fn joint_key(k: usize, key: &str) -> String {
    format!("joint[{k}].{key}")
}
pub(super) fn abut_key(side: usize, key: &str) -> String {
    format!("abutment.{}.{key}", ABUTMENT_SIDES[side])
}

pub(super) fn check(name: String, v: Real, ok: bool, reason: &str) -> Result<(), SimError> {
    if ok && v.is_finite() {
        Ok(())
    } else {
        Err(SimError::invalid(name, v, reason))
    }
}

impl BridgeModel {
    /// Validates every parameter; errors name `segment[i].key`, `joint[k].key`,
    /// `abutment.start.key`, ….
    pub fn validate(&self) -> Result<(), SimError> {
        let n = self.segments.len();
        if n == 0 {
            return Err(SimError::InvalidArgument {
                name: "segment".into(),
                reason: "a bridge needs at least one segment".into(),
            });
        }
        if self.joints.len() + 1 != n {
            return Err(SimError::InvalidArgument {
                name: "joint".into(),
                reason: format!(
                    "{n} segments need {} joints, found {}",
                    n - 1,
                    self.joints.len()
                ),
            });
        }
        self.validate_segments()?;
        self.validate_joints()?;
        self.validate_abutments()?;
        check(
            "outer_seat_length".into(),
            self.outer_seat_length,
            self.outer_seat_length > 0.0,
            "must be > 0",
        )?;
        check(
            "damping_ratio".into(),
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
            s.shape.validate().map_err(|e| SimError::InvalidArgument {
                name: seg_key(i, "shape"),
                reason: format!("invalid shape: {e}"),
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
                .map_err(|e| SimError::InvalidArgument {
                    name: joint_key(k, &format!("restrainer_{}", e.key())),
                    reason: e.to_string(),
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
                return Err(SimError::InvalidArgument {
                    name: seg_key(k + 1, "width"),
                    reason: format!(
                        "segment[{}] meets segment[{k}] at joint[{k}] with a face {} m long, but \
                         segment[{k}]'s face there is {} m long: the two faces of a joint must have \
                         the same length (a skewed segment's end faces are width / cos(skew) long; \
                         adjust the widths so the faces match)",
                        k + 1,
                        crate::output::float_token(wb),
                        crate::output::float_token(wa)
                    ),
                });
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

    /// The contact laws of the joints and the present abutments, in that order.
    pub(crate) fn contacts(&self) -> impl Iterator<Item = (String, &JointContact)> {
        let joints = self
            .joints
            .iter()
            .enumerate()
            .map(|(k, j)| (joint_key(k, "law"), &j.contact));
        let abuts = self
            .abutments
            .iter()
            .enumerate()
            .filter_map(|(s, a)| a.as_ref().map(|a| (abut_key(s, "law"), &a.contact)));
        joints.chain(abuts)
    }

    /// The DOF map of the bridge: every segment a plan rigid body `(x, y, θ)`, in bridge order.
    pub fn dofs(&self) -> Dofs {
        Dofs::plan_rigid(self.segments.len())
    }

    /// The segments placed end to end in the global frame (module doc).
    pub fn layout(&self) -> Vec<SegmentBody> {
        let mut out: Vec<SegmentBody> = Vec::with_capacity(self.segments.len());
        for (i, s) in self.segments.iter().enumerate() {
            let mp = s.shape.mass_properties();
            let jf = s.body_face(DeckEnd::Joint);
            let ff = s.body_face(DeckEnd::Far);
            let g0 = s.mirror(mp.centroid);
            let body = if i == 0 {
                let off = Vector::new(0.0, self.joints.first().map_or(0.0, |j| j.gap));
                let t = |p: Vector| off + p;
                let mv = |f: &EndFace| face([t(f.corners[0]), t(f.corners[1])], f.inward);
                SegmentBody {
                    mass: MassProperties { centroid: g0, ..mp },
                    centroid: t(g0),
                    start: mv(&ff),
                    end: mv(&jf),
                }
            } else {
                let prev = out[i - 1].end;
                let gap = self.joints[i - 1].gap;
                // turn the joint face's outward normal (−inward) onto the previous face's inward
                // normal, then move its midpoint to the previous midpoint − gap ν
                let (a, b) = (-jf.inward, prev.inward);
                let (c, sn) = (a.dot(&b), cross(&a, &b));
                let rot = |p: Vector| Vector::new(c * p.x - sn * p.y, sn * p.x + c * p.y);
                let t = prev.mid - prev.inward * gap - rot(jf.mid);
                let tr = |p: Vector| rot(p) + t;
                let mv = |f: &EndFace| face([tr(f.corners[0]), tr(f.corners[1])], rot(f.inward));
                SegmentBody {
                    mass: MassProperties { centroid: g0, ..mp },
                    centroid: tr(g0),
                    start: mv(&jf),
                    end: mv(&ff),
                }
            };
            out.push(body);
        }
        out
    }

    /// Bearing points of every segment in the global reference pose.
    pub fn bearing_points(&self) -> Vec<Vec<Vector>> {
        let bodies = self.layout();
        self.segments
            .iter()
            .zip(&bodies)
            .enumerate()
            .map(|(i, (s, b))| {
                let place = placement(b, s, i == 0);
                s.bearings.iter().map(|br| place(br.point)).collect()
            })
            .collect()
    }

    /// Natural frequencies `ω_1 ≤ ω_2 ≤ ω_3` of every segment on its bearings \[rad/s\] (a
    /// mechanism, free to slide or spin, has `ω_1 = 0`).
    pub fn segment_frequencies(&self) -> Result<Vec<[Real; 3]>, SimError> {
        Ok(self.body_systems()?.iter().map(|b| b.frequencies).collect())
    }

    /// `M`, `K`, `C`, frequencies per segment (errors name the segment).
    pub(crate) fn body_systems(&self) -> Result<Vec<BodySystem>, SimError> {
        let bodies = self.layout();
        let points = self.bearing_points();
        let mut out = Vec::with_capacity(bodies.len());
        for (i, (b, s)) in bodies.iter().zip(&self.segments).enumerate() {
            let mp = b.mass;
            let mj = Matrix3::from_diagonal(&Vector3::new(mp.mass, mp.mass, mp.inertia));
            let mut kj = Matrix3::zeros();
            for (br, p) in s.bearings.iter().zip(&points[i]) {
                let r = p - b.centroid;
                let bm = Matrix2x3::new(1.0, 0.0, -r.y, 0.0, 1.0, r.x);
                kj += br.stiffness * bm.transpose() * bm;
            }
            let om = deck_frequencies(&mp, &kj);
            if om.iter().any(|w| !w.is_finite()) {
                return Err(SimError::invalid(
                    seg_key(i, "mass"),
                    mp.mass,
                    "the bearing stiffness over this mass (or inertia) overflows",
                ));
            }
            let (a0, a1) = rayleigh_coefficients(self.damping_ratio, &om).ok_or_else(|| {
                SimError::invalid(
                    seg_key(i, "bearings"),
                    0.0,
                    "this segment has no bearing stiffness, so its damping is undefined",
                )
            })?;
            let (cj, a0, a1) = super::options::damping_block(
                self.damping_model,
                self.damping_ratio,
                &mj,
                &kj,
                a0,
                a1,
            );
            out.push(BodySystem {
                mass: mj,
                stiffness: kj,
                damping: cj,
                frequencies: om,
                rayleigh: (a0, a1),
            });
        }
        Ok(out)
    }

    /// The names of the seated ends in the order of a run's seat outputs (`summary.json`
    /// `seats[]`): per segment `segment<i>-start`, `segment<i>-end` (1-based), in bridge order.
    pub fn seat_end_names(&self) -> Vec<String> {
        (1..=self.segments.len())
            .flat_map(|i| ["start", "end"].map(|f| format!("segment{i}-{f}")))
            .collect()
    }

    /// The driver's view of the bridge: segments, joints, abutments, seats (per segment
    /// `[start, end]`, named as [`Self::seat_end_names`]).
    pub(crate) fn bridge(&self) -> Bridge {
        let bodies = self.layout();
        let n = bodies.len();
        let joints = self
            .joints
            .iter()
            .enumerate()
            .map(|(k, j)| JointGeom::new(&bodies, k, j.gap))
            .collect();
        let supports = Support::of_bridge(self.abutments.map(|a| a.is_some()));
        let abutments = self
            .abutments
            .iter()
            .enumerate()
            .filter_map(|(side, a)| {
                let a = a.as_ref()?;
                let body = if side == 0 { 0 } else { n - 1 };
                Some(AbutmentFace::new(&bodies, (body, side), a.gap))
            })
            .collect();
        let mut seats = Vec::with_capacity(2 * n);
        for (i, b) in bodies.iter().enumerate() {
            let start = if i == 0 {
                self.abutments[0].map_or(self.outer_seat_length, |a| a.seat_length)
            } else {
                self.joints[i - 1].seat_length
            };
            let end = if i + 1 == n {
                self.abutments[1].map_or(self.outer_seat_length, |a| a.seat_length)
            } else {
                self.joints[i].seat_length
            };
            let start_support = match i {
                0 if self.abutments[0].is_some() => SeatSupport::Abutment(0),
                0 => SeatSupport::Outer(0),
                _ => SeatSupport::Joint(i - 1),
            };
            let end_support = match i + 1 == n {
                true if self.abutments[1].is_some() => SeatSupport::Abutment(1),
                true => SeatSupport::Outer(1),
                false => SeatSupport::Joint(i),
            };
            for (at_end, f, length, support) in [
                (false, &b.start, start, start_support),
                (true, &b.end, end, end_support),
            ] {
                seats.push(SeatEnd {
                    body: i,
                    at_end,
                    support,
                    corners: f.corners,
                    inward: f.inward,
                    length,
                });
            }
        }
        let dofs = self.dofs();
        let elements = self.elements(&bodies, &dofs);
        Bridge {
            dofs,
            supports,
            bodies,
            joints,
            abutments,
            seats,
            bearings: self
                .bearing_points()
                .into_iter()
                .zip(&self.segments)
                .enumerate()
                .map(|(i, (points, s))| {
                    let at = |(p, b): (Vector, &Bearing)| super::view::BearingAt {
                        top: Attachment::Body(i, p),
                        bottom: Attachment::Support(Support::GROUND, p),
                        stiffness: b.stiffness,
                    };
                    points.into_iter().zip(&s.bearings).map(at).collect()
                })
                .collect(),
            elements,
        }
    }
}

impl BridgeModel {
    /// The two-deck model as a bridge of two segments (deck 1 = segment 1, deck 2 = segment 2,
    /// abutment of deck 1 = start, of deck 2 = end); the same physics, laid out by
    /// [`BridgeModel::layout`].
    pub fn from_pair(model: &super::SimModel) -> Self {
        let shapes = model.shapes.unwrap_or([
            DeckShape::Curved(model.arrangement.deck1),
            DeckShape::Curved(model.arrangement.deck2),
        ]);
        // two-deck bearing points are relative to M_j in the global orientation: deck 2 is its
        // body frame turned by π
        let seg = |j: usize, bs: &[Bearing]| Segment {
            shape: shapes[j],
            mirrored: false,
            bearings: bs
                .iter()
                .map(|b| Bearing {
                    point: if j == 0 { b.point } else { -b.point },
                    stiffness: b.stiffness,
                })
                .collect(),
            bearing_yield: None,
        };
        let abut = |a: Option<super::SimAbutment>| {
            a.map(|a| BridgeAbutment {
                gap: a.gap,
                seat_length: a.seat_length,
                friction: model.friction,
                restitution: model.restitution,
                contact: model.contact,
            })
        };
        BridgeModel {
            segments: vec![seg(0, &model.bearings1), seg(1, &model.bearings2)],
            joints: vec![Joint {
                gap: model.gap,
                friction: model.friction,
                restitution: model.restitution,
                seat_length: model.seat_length,
                contact: model.contact,
                restrainers: Vec::new(),
            }],
            abutments: [abut(model.abutments[0]), abut(model.abutments[1])],
            outer_seat_length: model.seat_length,
            damping_ratio: model.damping_ratio,
            damping_model: model.damping_model,
        }
    }
}

impl BridgeModel {
    /// The yielding bearings and restrainers (validated parameters).
    fn elements(&self, bodies: &[SegmentBody], dofs: &Dofs) -> super::elements::Elements {
        use crate::element::bearing::{BearingState, BilinearBearing};
        use crate::element::restrainer::{Restrainer, RestrainerElement, SlackGrowth};
        let mut el = super::elements::Elements {
            dofs: dofs.clone(),
            ..Default::default()
        };
        let points = self.bearing_points();
        for (i, s) in self.segments.iter().enumerate() {
            let Some(y) = s.bearing_yield else { continue };
            let total: Real = s.bearings.iter().map(|b| b.stiffness).sum();
            for (slot, (b, p)) in s.bearings.iter().zip(&points[i]).enumerate() {
                if b.stiffness == 0.0 {
                    continue;
                }
                let law = BilinearBearing::new(b.stiffness, y.fy * (b.stiffness / total), y.b)
                    .expect("validated");
                el.bearings.push(super::elements::YieldingBearing {
                    body: i,
                    slot,
                    arm: p - bodies[i].centroid,
                    law,
                    state: BearingState::default(),
                });
            }
        }
        for (k, j) in self.joints.iter().enumerate() {
            for r in &j.restrainers {
                let law =
                    Restrainer::new(r.k, r.slack, r.fy, SlackGrowth::Permanent).expect("validated");
                let [pa, pb] = restrainer_anchors(bodies, k, r);
                el.cables.push(super::elements::Cable {
                    joint: k,
                    a: Attachment::Body(k, pa),
                    b: Attachment::Body(k + 1, pb),
                    length: (pb - pa).norm(),
                    element: RestrainerElement::new(law),
                });
            }
        }
        el
    }
}

impl BridgeModel {
    /// The step must resolve every restrainer: they act over a step as a predictor–corrector
    /// (explicit) force, stable for `ω h` well below 2. For the cables of joint `k` the bound
    /// `ω² ≤ Σ_c k_c w_cᵀ M⁻¹ w_c` is used, `w_c` the generalised direction of cable `c` on its
    /// two segments (`(n, r_a × n)` and `−(n, r_b × n)`, `n` along the cable, `r` the arms
    /// from the centroids): for one cable between the face midpoints of straight segments it is
    /// `k (1/m_a + 1/m_b)`. `h ≤ 1/ω` is required (errors name `dt` and the joint's
    /// `restrainer_k`).
    pub fn check_time_step(&self, dt: Real) -> Result<(), SimError> {
        let bodies = self.layout();
        for (k, j) in self.joints.iter().enumerate() {
            if j.restrainers.is_empty() {
                continue;
            }
            let (ba, bb) = (&bodies[k], &bodies[k + 1]);
            let w2: Real = j
                .restrainers
                .iter()
                .map(|r| {
                    let [pa, pb] = restrainer_anchors(&bodies, k, r);
                    let n = (pb - pa)
                        .try_normalize(0.0)
                        .unwrap_or(-bodies[k].end.inward);
                    let (ta, tb) = (
                        cross(&(pa - ba.centroid), &n),
                        cross(&(pb - bb.centroid), &n),
                    );
                    r.k * (1.0 / ba.mass.mass
                        + 1.0 / bb.mass.mass
                        + ta * ta / ba.mass.inertia
                        + tb * tb / bb.mass.inertia)
                })
                .sum();
            let w = w2.sqrt();
            if dt * w > 1.0 {
                let total: Real = j.restrainers.iter().map(|r| r.k).sum();
                return Err(SimError::invalid(
                    "dt",
                    dt,
                    &format!(
                        "the restrainer of {} (k = {} N/m in total between segments of {} and {} \
                         kg, frequency {} rad/s) needs dt <= {} s",
                        joint_key(k, "restrainer_k"),
                        crate::output::float_token(total),
                        crate::output::float_token(ba.mass.mass),
                        crate::output::float_token(bb.mass.mass),
                        crate::output::float_token(w),
                        crate::output::float_token(1.0 / w)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A body-frame point of segment `i` from its **segment-frame** coordinates \[C\]: origin at
    /// the midpoint of the segment's start face (the face toward the start of the bridge),
    /// `along` the segment's axis at that face (straight and skewed segments: the line through
    /// the two face midpoints, parallel to the sides; curved: the tangent of the centreline, the
    /// start face's inward normal), `left` perpendicular to it, to the left of a walk from the
    /// start to the end \[m\]. For a straight segment `(0, ±W/2)` and `(L, ±W/2)` are its
    /// corners; a skewed one has its sides at `left = ±W/2`. The result goes into
    /// [`Bearing::point`].
    pub fn segment_point(&self, i: usize, along: Real, left: Real) -> Vector {
        self.segments[i].frame_point(i == 0, along, left)
    }

    /// Every bearing and restrainer anchor must lie on its segment (inside or on its plan
    /// outline, with 64 chords per arc): errors name `segment[i].bearing_points`,
    /// `joint[k].restrainer_offsets` or `joint[k].restrainer_depth`.
    fn check_points(&self) -> Result<(), SimError> {
        let outlines = self.outlines(64);
        let bodies = self.layout();
        let points = self.bearing_points();
        for (i, pts) in points.iter().enumerate() {
            if let Some(b) = pts.iter().position(|p| !on_polygon(*p, &outlines[i])) {
                return Err(SimError::InvalidArgument {
                    name: seg_key(i, "bearing_points"),
                    reason: format!("bearing {} lies outside segment[{i}]", b + 1),
                });
            }
        }
        for (k, j) in self.joints.iter().enumerate() {
            for (c, r) in j.restrainers.iter().enumerate() {
                let half = bodies[k].end.half.min(bodies[k + 1].start.half);
                if r.offset.abs() > half * (1.0 + 1e-12) {
                    return Err(SimError::invalid(
                        joint_key(k, "restrainer_offsets"),
                        r.offset,
                        &format!(
                            "cable {} lies beside the joint: |offset| must be at most half the \
                             face length, {} m",
                            c + 1,
                            crate::output::float_token(half)
                        ),
                    ));
                }
                let [pa, pb] = restrainer_anchors(&bodies, k, r);
                for (p, seg) in [(pa, k), (pb, k + 1)] {
                    if !on_polygon(p, &outlines[seg]) {
                        return Err(SimError::invalid(
                            joint_key(k, "restrainer_depth"),
                            r.depth,
                            &format!(
                                "the anchor of cable {} lies outside segment[{seg}]: the depth \
                                 must stay within the segment",
                                c + 1
                            ),
                        ));
                    }
                }
            }
        }
        Ok(())
    }
}

/// The unit vector to the left of the direction `d` (turned by +90°).
fn left_of(d: Vector) -> Vector {
    Vector::new(-d.y, d.x)
}

/// The two anchors (global, reference pose) of cable `r` across joint `k` ([`RestrainerSpec`]).
fn restrainer_anchors(bodies: &[SegmentBody], k: usize, r: &RestrainerSpec) -> [Vector; 2] {
    // walking direction at the joint: into segment k + 1 through its start face
    let left = left_of(bodies[k + 1].start.inward);
    [bodies[k].end, bodies[k + 1].start].map(|f| {
        let t = if f.dir.dot(&left) >= 0.0 {
            f.dir
        } else {
            -f.dir
        };
        f.mid + t * r.offset + f.inward * r.depth
    })
}

/// `p` lies inside the closed polyline `poly` or within round-off of its boundary.
fn on_polygon(p: Vector, poly: &[Vector]) -> bool {
    let scale = poly.iter().fold(1.0, |m: Real, q| m.max(q.norm()));
    let near = poly.windows(2).any(|e| {
        let (a, b) = (e[0], e[1]);
        let ab = b - a;
        let t = ((p - a).dot(&ab) / ab.norm_squared().max(Real::MIN_POSITIVE)).clamp(0.0, 1.0);
        (a + ab * t - p).norm() <= 1e-9 * scale
    });
    near || point_in_polygon(p, poly)
}

/// Even–odd rule for a closed polyline.
fn point_in_polygon(p: Vector, poly: &[Vector]) -> bool {
    let mut c = false;
    for e in poly.windows(2) {
        let (u, v) = (e[0], e[1]);
        if (u.y > p.y) != (v.y > p.y) && p.x < u.x + (p.y - u.y) / (v.y - u.y) * (v.x - u.x) {
            c = !c;
        }
    }
    c
}

impl BridgeModel {
    /// Closed plan outline of every segment in the reference pose (first point repeated at the
    /// end): the four end-face corners of a straight or skewed segment; a curved segment's outer
    /// and inner arcs as polylines of `arc_chords` chords (at least 1).
    pub fn outlines(&self, arc_chords: usize) -> Vec<Vec<Vector>> {
        let bodies = self.layout();
        let n = arc_chords.max(1);
        self.segments
            .iter()
            .zip(&bodies)
            .enumerate()
            .map(|(i, (s, b))| {
                let place = placement(b, s, i == 0);
                let body: Vec<Vector> = match s.shape.curved() {
                    Some(d) => {
                        // body points (R − r cos φ, r sin φ): inner corner at φ = 0, the outer
                        // arc φ = 0 → β, the inner arc back β → 0
                        let (ri, ro) = (d.radius - d.width / 2.0, d.radius + d.width / 2.0);
                        let at = |r: Real, k: usize| {
                            let phi = d.angle * k as Real / n as Real;
                            Vector::new(d.radius - r * phi.cos(), r * phi.sin())
                        };
                        let mut v = vec![at(ri, 0)];
                        v.extend((0..=n).map(|k| at(ro, k)));
                        v.extend((0..=n).rev().map(|k| at(ri, k)));
                        v.into_iter().map(|p| s.mirror(p)).collect()
                    }
                    None => {
                        let mut v = s.corner_points().to_vec();
                        v.push(v[0]);
                        v
                    }
                };
                body.into_iter().map(place).collect()
            })
            .collect()
    }

    /// Segments that are not neighbours must not overlap in plan (a curve closing on itself):
    /// an error naming both (outlines with 32 chords per arc).
    fn check_overlaps(&self) -> Result<(), SimError> {
        let outlines = self.outlines(32);
        let bbox = |o: &[Vector]| {
            o.iter().fold(
                (
                    Real::INFINITY,
                    Real::INFINITY,
                    Real::NEG_INFINITY,
                    Real::NEG_INFINITY,
                ),
                |(a, b, c, d), p| (a.min(p.x), b.min(p.y), c.max(p.x), d.max(p.y)),
            )
        };
        let boxes: Vec<_> = outlines.iter().map(|o| bbox(o)).collect();
        for i in 0..outlines.len() {
            for j in i + 2..outlines.len() {
                let (a, b) = (boxes[i], boxes[j]);
                if a.2 < b.0 || b.2 < a.0 || a.3 < b.1 || b.3 < a.1 {
                    continue;
                }
                if polygons_overlap(&outlines[i], &outlines[j]) {
                    return Err(SimError::InvalidArgument {
                        name: seg_key(j, "shape"),
                        reason: format!(
                            "segment[{j}] overlaps segment[{i}] in plan: the bridge closes on \
                             itself (check the curve angles, radii and curve directions)"
                        ),
                    });
                }
            }
        }
        Ok(())
    }
}

/// Two closed polylines cross, or one lies inside the other.
fn polygons_overlap(a: &[Vector], b: &[Vector]) -> bool {
    let orient = |p: Vector, q: Vector, r: Vector| cross(&(q - p), &(r - p));
    let crosses = |p1: Vector, p2: Vector, q1: Vector, q2: Vector| {
        let (d1, d2) = (orient(q1, q2, p1), orient(q1, q2, p2));
        let (d3, d4) = (orient(p1, p2, q1), orient(p1, p2, q2));
        d1 * d2 < 0.0 && d3 * d4 < 0.0
    };
    for e in a.windows(2) {
        for f in b.windows(2) {
            if crosses(e[0], e[1], f[0], f[1]) {
                return true;
            }
        }
    }
    point_in_polygon(a[0], b) || point_in_polygon(b[0], a)
}

/// Maps a point of segment `s`'s (mirrored) body frame to its global reference position, given
/// the placed body `b`.
pub(crate) fn placement(
    b: &SegmentBody,
    s: &Segment,
    first: bool,
) -> impl Fn(Vector) -> Vector + use<> {
    // recover the rigid map from the placed shape face: first segment: translation only
    let jf = s.body_face(DeckEnd::Joint);
    let placed = if first { b.end } else { b.start };
    let a = -jf.inward;
    let bb = -placed.inward;
    let (c, sn) = (a.dot(&bb), cross(&a, &bb));
    let rot = move |p: Vector| Vector::new(c * p.x - sn * p.y, sn * p.x + c * p.y);
    let t = placed.mid - rot(jf.mid);
    move |p: Vector| rot(p) + t
}

/// Everything a bridge run needs besides the settings.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeProblem {
    /// The bridge.
    pub model: BridgeModel,
    /// The ground acceleration.
    pub ground: GroundMotion,
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
            q0: vec![0.0; n],
            u0: vec![0.0; n],
        }
    }
}
