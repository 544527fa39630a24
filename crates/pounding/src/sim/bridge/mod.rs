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
//!
//! The parts are in `segment.rs` and `sites.rs` (joints, abutments), their validation in
//! `validate.rs`, the substructures in `pier.rs` and `backwall.rs`, the placement in
//! `geometry.rs`, the assembly of a run in `build.rs`.

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
mod segment;
mod sites;
mod supports;
mod validate;
pub use backwall::{Backwall, Piles};
pub(crate) use geometry::placement;
use geometry::*;
pub use pier::{Pier, PierColumn};
use segment::face;
pub use segment::{BearingYield, Segment};
pub use sites::{BridgeAbutment, Joint, RestrainerSpec};
use validate::seg_key;
pub(super) use validate::{abut_key, check, joint_key};

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
