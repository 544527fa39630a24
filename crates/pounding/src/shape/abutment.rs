//! A deck's end-face corners against a rigid abutment, and two decks meeting face to face at the
//! joint, as problems of the generic [`impact`](crate::impact) module.
//!
//! A rigid abutment (the fixed ground) faces one end of the deck across a gap `g ≥ 0` measured along
//! that face's outward normal; its face is parallel to the deck's end face. A corner touching the
//! abutment face is a contact with body `a` = the deck, body `b` = ground, contact point = the
//! corner, normal `n = −n_out` (into the deck) and tangent `t = perp(n)`. With the lever arm
//! `r = c_k − G` from the centroid, the single-contact Delassus matrix (ground: infinite mass) is
//! ```text
//! G_NN = 1/m + (r × n)²/I,   G_NT = (r × n)(r × t)/I,   G_TT = 1/m + (r × t)²/I .
//! ```

use super::{DeckEnd, DeckShape};
use crate::analytic::ImpactLaw;
use crate::contact::{BodyArms, Delassus, delassus_of_bodies};
use crate::geometry::{GeometryError, ShapeParam};
use crate::impact::{ContactSpec, ImpactError, ImpactProblem, RigidBody};
use crate::math::{Real, Vector, cross, perp};

/// A rigid abutment beyond one end of a deck.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Abutment {
    /// The deck end it faces.
    pub end: DeckEnd,
    /// Gap `g ≥ 0` \[m\] between the end face and the (parallel) abutment face, measured along the
    /// end face's outward normal.
    pub gap: Real,
}

impl Abutment {
    /// A validated abutment: `gap` finite and `≥ 0` (errors name `gap`).
    pub fn new(end: DeckEnd, gap: Real) -> Result<Self, GeometryError> {
        if !(gap.is_finite() && gap >= 0.0) {
            return Err(GeometryError::invalid(
                ShapeParam::Gap,
                gap,
                "the abutment gap must be finite and >= 0",
            ));
        }
        Ok(Self { end, gap })
    }

    /// A point of the abutment face in the deck's body frame (deck at rest): the end-face midpoint
    /// moved by `g` along `n_out`.
    pub fn face_point(&self, shape: &DeckShape) -> Vector {
        let f = shape.end_face(self.end);
        f.midpoint() + self.gap * f.outward_normal
    }

    /// Distance the deck travels along [`DeckShape::axis_direction`] until its end face reaches the
    /// abutment: `g / (e · n_out)` (`g / cos θ_s` for a skewed deck; `g` for straight and curved).
    pub fn travel_to_contact(&self, shape: &DeckShape) -> Real {
        let f = shape.end_face(self.end);
        self.gap / shape.axis_direction(self.end).dot(&f.outward_normal)
    }
}

/// A corner of an end face touching an abutment: point, frame and lever arms (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AbutmentContact {
    /// Contact point = the corner (body frame) \[m\].
    pub point: Vector,
    /// Normal `n = −n_out`, pointing into the deck.
    pub normal: Vector,
    /// Tangent `t = perp(n) = (−n_y, n_x)`: the unit vector from `c0` toward `c1` (`(1, 0)` on the
    /// far face and `(−1, 0)` on the joint face of a straight/skewed deck).
    pub tangent: Vector,
    /// `A = r × n` with `r = point − G` \[m\].
    pub arm_n: Real,
    /// `B = r × t` \[m\].
    pub arm_t: Real,
}

/// Corner `k ∈ {0, 1}` of `end` touching an abutment parallel to that face.
///
/// # Panics
/// If `k > 1`.
pub fn abutment_contact(shape: &DeckShape, end: DeckEnd, k: usize) -> AbutmentContact {
    let f = shape.end_face(end);
    let g = shape.mass_properties().centroid;
    let point = f.corners[k];
    let normal = -f.outward_normal;
    let tangent = perp(&normal);
    let r = point - g;
    AbutmentContact {
        point,
        normal,
        tangent,
        arm_n: cross(&r, &normal),
        arm_t: cross(&r, &tangent),
    }
}

/// Delassus matrix of corner `k` of `end` against a rigid abutment (module docs):
/// `G_NN = 1/m + A²/I`, `G_NT = A B/I`, `G_TT = 1/m + B²/I` with `A = r × n`, `B = r × t`.
///
/// For a skewed deck's far face (`n = (0, −1)`, `t = (1, 0)`), `A_0 = W/(2 cos θ_s) + (L/2) sin θ_s`
/// (acute corner), `A_1 = (L/2) sin θ_s − W/(2 cos θ_s)` (obtuse corner) and `B = −(L/2) cos θ_s`
/// for both.
pub fn abutment_delassus(shape: &DeckShape, end: DeckEnd, k: usize) -> Delassus {
    let c = abutment_contact(shape, end, k);
    let p = shape.mass_properties();
    delassus_of_bodies(&[BodyArms {
        mass: p.mass,
        inertia: p.inertia,
        arm_n: c.arm_n,
        arm_t: c.arm_t,
    }])
}

/// The generic impact problem of the deck (body `"deck"`, at rest pose = body frame, centroid
/// velocity `velocity`, angular velocity `omega`) against the abutment at `end`, with the corners
/// listed in `corners` (indices into `[c0, c1]`, e.g. `&[0, 1]` for both) in contact, each with `law`.
pub fn abutment_problem(
    shape: &DeckShape,
    end: DeckEnd,
    corners: &[usize],
    velocity: Vector,
    omega: Real,
    law: &ImpactLaw,
) -> Result<ImpactProblem, ImpactError> {
    let p = shape.mass_properties();
    let body = RigidBody {
        name: "deck".into(),
        mass: p.mass,
        inertia: p.inertia,
        position: p.centroid,
        velocity,
        omega,
    };
    let mut contacts = Vec::with_capacity(corners.len());
    for (j, &k) in corners.iter().enumerate() {
        if k > 1 {
            return Err(ImpactError::Invalid {
                name: format!("corners[{j}]"),
                reason: format!("{k} is not a corner index (0 or 1)"),
            });
        }
        let c = abutment_contact(shape, end, k);
        contacts.push(ContactSpec {
            body_a: "deck".into(),
            body_b: None,
            point: c.point,
            normal: c.normal,
            mu: law.mu(),
            restitution: law.eps(),
        });
    }
    ImpactProblem::new(vec![body], contacts)
}

/// Frictionless impact of a translating deck (`ω⁻ = 0`, any velocity approaching the abutment)
/// with both corners of `end` striking: the corner about which the deck rotates afterwards, or
/// `None` when both corners stay in contact and the deck does not rotate.
///
/// Derivation: both contacts share the normal `n`, so `γ_N,k⁻ = v⁻·n =: −n₀` at both corners and
/// `G_jk = 1/m + A_j A_k/I` (`A_k = r_k × n`). If both corners carry impulse, Newton's law at both
/// (`γ_N,k⁺ = ε n₀`, `A_0 ≠ A_1`) forces `ω⁺ = 0`, so the impulses are
/// `Λ_0 = −A_1 S/(A_0 − A_1)`, `Λ_1 = A_0 S/(A_0 − A_1)`, `S = m (1+ε) n₀`, both `≥ 0` iff
/// `A_0 A_1 ≤ 0`, i.e. the centroid's perpendicular foot on the face line lies on the face.
/// Otherwise the unique LCP solution (G is positive definite) has the corner with the smaller
/// `|A|` alone in contact (`Λ_k = (1+ε) n₀ / G_kk`; the other corner separates since
/// `G_jk ≥ G_kk ⟺ A_k (A_j − A_k) ≥ 0`), and the deck turns with `ω⁺ = A_k Λ_k / I`.
/// The criterion involves neither `ε_N` nor `m`, `I`. For a skewed deck it is
/// [`SkewedDeck::rotates_on_abutment_impact`](super::SkewedDeck::rotates_on_abutment_impact) and the pivot is the obtuse corner `c1`.
pub fn frictionless_pivot(shape: &DeckShape, end: DeckEnd) -> Option<usize> {
    let a0 = abutment_contact(shape, end, 0).arm_n;
    let a1 = abutment_contact(shape, end, 1).arm_n;
    if a0 * a1 > 0.0 {
        Some(if a0.abs() < a1.abs() { 0 } else { 1 })
    } else {
        None
    }
}

/// Two decks meeting face to face at the joint (reference pose, zero opening): deck 1 is the body
/// frame itself, deck 2 the body frame turned by π about the origin ([`crate::shape`] docs), and **both**
/// joint corners of deck 1 touch deck 2's joint face — the double impact of parallel faces
/// (spec §16). Bodies `"deck1"` (body a) and `"deck2"` (body b); contacts at deck 1's joint corners
/// `[c0, c1]` with the normal `(0, 1)` (from deck 2 into deck 1, the spec's `ν`), each with `law`.
/// Centroid velocities and angular velocities are given in the global frame.
///
/// The joint faces must coincide: deck 2's turned corners `−c0₂`, `−c1₂` must equal deck 1's
/// `c1₁`, `c0₁` (within `1e−9 W`), i.e. equal widths and, for skewed decks, equal skew angles
/// (errors name `width` or `skew`).
pub fn joint_problem(
    deck1: &DeckShape,
    deck2: &DeckShape,
    state1: (Vector, Real),
    state2: (Vector, Real),
    law: &ImpactLaw,
) -> Result<ImpactProblem, ImpactError> {
    let (j1, j2) = (
        deck1.end_face(DeckEnd::Joint),
        deck2.end_face(DeckEnd::Joint),
    );
    let tol = 1e-9 * deck1.width().max(deck2.width());
    if (j1.corners[1] + j2.corners[0]).norm() > tol || (j1.corners[0] + j2.corners[1]).norm() > tol
    {
        let name = if deck1.width() != deck2.width() {
            "width"
        } else if deck1.skew() != deck2.skew() {
            "skew"
        } else {
            "deck2"
        };
        return Err(ImpactError::Invalid {
            name: name.into(),
            reason: format!(
                "the joint faces do not match (deck 1 joint corners {:?}, deck 2 turned by π {:?})",
                [j1.corners[0], j1.corners[1]].map(|c| [c.x, c.y]),
                [-j2.corners[1], -j2.corners[0]].map(|c| [c.x, c.y])
            ),
        });
    }
    let (p1, p2) = (deck1.mass_properties(), deck2.mass_properties());
    let bodies = vec![
        RigidBody {
            name: "deck1".into(),
            mass: p1.mass,
            inertia: p1.inertia,
            position: p1.centroid,
            velocity: state1.0,
            omega: state1.1,
        },
        RigidBody {
            name: "deck2".into(),
            mass: p2.mass,
            inertia: p2.inertia,
            position: -p2.centroid,
            velocity: state2.0,
            omega: state2.1,
        },
    ];
    let contacts = j1
        .corners
        .iter()
        .map(|&point| ContactSpec {
            body_a: "deck1".into(),
            body_b: Some("deck2".into()),
            point,
            normal: -j1.outward_normal,
            mu: law.mu(),
            restitution: law.eps(),
        })
        .collect();
    ImpactProblem::new(bodies, contacts)
}
