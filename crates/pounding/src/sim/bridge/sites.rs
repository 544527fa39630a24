//! The contact sites of a bridge: the joints between its segments (with their restrainer
//! cables, [`RestrainerSpec`]) and the abutments at its two ends.

use super::*;

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

/// An abutment at the start or the end of the bridge: the ground, beyond the outer face of the
/// first or last segment (as [`crate::sim::SimAbutment`]).
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
    /// abutment (`t` along the face, [`crate::sim::view::AbutmentFace::tangent`]).
    pub shear_keys: Option<crate::element::shear_key::ShearKey>,
}
