//! The structural model of a simulation: segment bodies in the reference pose (the two-deck
//! model's decks among them), bearings, natural frequencies and Rayleigh coefficients.

use super::SimError;
use crate::geometry::MassProperties;
use crate::math::{Real, Vector};
use crate::shape::{Deck, DeckEnd, DeckShape};
use nalgebra::Matrix3;

/// One discrete elastic bearing: a linear spring of equal stiffness `k` in x and y, attached to a
/// body point of a deck and to the ground (pier / abutment).
///
/// Linearised kinematics: the bearing displacement is `u_p = (u_x − θ r_y, u_y + θ r_x)` with
/// `r = p − G⁰` the lever arm from the deck's reference centroid, so its force on the deck is
/// `−k u_p` and its moment about G is `r × (−k u_p)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bearing {
    /// Attachment point in the reference pose, relative to the deck's own face midpoint `M_j`
    /// (spec §4 coordinates: deck 1's body lies in `y ≥ 0`, deck 2's in `y ≤ 0`) \[m\].
    pub point: Vector,
    /// Stiffness `k ≥ 0` in each horizontal direction \[N/m\].
    pub stiffness: Real,
}

/// Checks one deck's parameters via [`Deck::new`]; `j` (1 or 2) suffixes the names (`R1`, `beta2`, ...).
pub(crate) fn validate_deck(deck: &Deck, j: usize) -> Result<(), SimError> {
    Deck::new(
        deck.radius,
        deck.angle,
        deck.width,
        deck.thickness,
        deck.density,
    )
    .map_err(|e| SimError::Geometry(e.for_deck(j)))?;
    Ok(())
}

impl SegmentBody {
    /// Reference-pose body of curved deck `j ∈ {1, 2}` of the two-deck model with joint opening
    /// `gap` (deck 1 points `M_1 + (R_1 − r cos φ, r sin φ)`, deck 2 points
    /// `M_2 + (−R_2 + r cos φ, −r sin φ)`, `r ∈ [R − W/2, R + W/2]`, `φ ∈ [0, β]`, `M_1 = (0, g)`,
    /// `M_2 = 0`). Its joint face ([`SegmentBody::joint_face`]) is deck 1's end face and deck 2's
    /// start face.
    pub fn of_curved_deck(deck: &Deck, j: usize, gap: Real) -> Self {
        let mp = deck.mass_properties();
        let (r, w, b) = (deck.radius, deck.width, deck.angle);
        let s = if j == 1 { 1.0 } else { -1.0 };
        let face_mid = if j == 1 {
            Vector::new(0.0, gap)
        } else {
            Vector::zeros()
        };
        // body point at (radius ρ, angle φ), relative to M_j
        let pt = |rho: Real, phi: Real| Vector::new(s * (r - rho * phi.cos()), s * rho * phi.sin());
        let ri = r - w / 2.0;
        let ro = r + w / 2.0;
        let joint = EndFace {
            corners: [face_mid + pt(ri, 0.0), face_mid + pt(ro, 0.0)],
            mid: face_mid,
            dir: Vector::new(-s, 0.0),
            inward: Vector::new(0.0, s),
            half: w / 2.0,
        };
        // d/dφ of the body point: s (ρ sin φ, ρ cos φ) points into the deck at φ = 0 and out of
        // it at φ = β.
        let far_inward = -Vector::new(s * b.sin(), s * b.cos());
        let far = far_face([face_mid + pt(ri, b), face_mid + pt(ro, b)], far_inward);
        Self::of_deck_faces(mp, face_mid + mp.centroid * s, j, joint, far)
    }

    /// Reference-pose body of deck `j ∈ {1, 2}` of any [`DeckShape`] (frames of
    /// [`crate::shape`]): deck 1 is the body frame translated by `(0, g)`, deck 2 the body frame
    /// turned by π about the origin, so the two joint faces lie on `y = g` and `y = 0` and the
    /// decks meet face to face. Corner `k` of the joint face is the shape's `c_k` (curved: `c0` =
    /// inner; straight / skewed: `c0` = acute corner), so deck 1's `c0` and deck 2's `c1` lie at
    /// `x = +b/2`.
    pub fn of_deck_shape(shape: &DeckShape, j: usize, gap: Real) -> Self {
        let mass = shape.mass_properties();
        let jf = shape.end_face(DeckEnd::Joint);
        let ff = shape.end_face(DeckEnd::Far);
        let (s, off) = if j == 1 {
            (1.0, Vector::new(0.0, gap))
        } else {
            (-1.0, Vector::zeros())
        };
        let w = |p: Vector| off + p * s;
        let jc = [w(jf.corners[0]), w(jf.corners[1])];
        let joint = EndFace {
            corners: jc,
            mid: off,
            dir: (jc[1] - jc[0]).normalize(),
            inward: -jf.outward_normal * s,
            half: 0.5 * jf.length(),
        };
        let far = far_face([w(ff.corners[0]), w(ff.corners[1])], -ff.outward_normal * s);
        Self::of_deck_faces(mass, w(mass.centroid), j, joint, far)
    }

    /// Deck `j`'s joint face is its end face (deck 1) or its start face (deck 2).
    fn of_deck_faces(
        mass: MassProperties,
        centroid: Vector,
        j: usize,
        joint: EndFace,
        far: EndFace,
    ) -> Self {
        let (start, end) = if j == 1 { (far, joint) } else { (joint, far) };
        SegmentBody {
            mass,
            centroid,
            start,
            end,
        }
    }

    /// The joint face of two-deck deck `j ∈ {1, 2}` (deck 1's end face, deck 2's start face).
    pub fn joint_face(&self, j: usize) -> &EndFace {
        if j == 1 { &self.end } else { &self.start }
    }

    /// The far end face of two-deck deck `j ∈ {1, 2}` (the one an abutment faces).
    pub fn far_face(&self, j: usize) -> &EndFace {
        if j == 1 { &self.start } else { &self.end }
    }
}

/// An end face from its corners and inward normal (midpoint, direction and half length derived).
fn far_face(corners: [Vector; 2], inward: Vector) -> EndFace {
    EndFace {
        corners,
        mid: (corners[0] + corners[1]) * 0.5,
        dir: (corners[1] - corners[0]).normalize(),
        inward,
        half: 0.5 * (corners[1] - corners[0]).norm(),
    }
}

/// Natural circular frequencies `ω_1 ≤ ω_2 ≤ ω_3` \[rad/s\] of `K φ = ω² M φ` for one deck
/// (`M = diag(m, m, I)`). All three are NaN when `M^{-1/2} K M^{-1/2}` overflows.
pub fn deck_frequencies(mass: &MassProperties, k: &Matrix3<Real>) -> [Real; 3] {
    let d = nalgebra::Vector3::new(
        mass.mass.sqrt().recip(),
        mass.mass.sqrt().recip(),
        mass.inertia.sqrt().recip(),
    );
    let a = Matrix3::from_diagonal(&d) * k * Matrix3::from_diagonal(&d);
    let a = (a + a.transpose()) * 0.5;
    if a.iter().any(|x| !x.is_finite()) {
        // K/M overflows (e.g. a mass of 1e-300 kg): no frequency is meaningful.
        return [Real::NAN; 3];
    }
    let mut ev: Vec<Real> = a
        .symmetric_eigenvalues()
        .iter()
        .map(|&l| l.max(0.0).sqrt())
        .collect();
    ev.sort_by(Real::total_cmp);
    // a mechanism mode (frequency below MECHANISM_RATIO of the highest: round-off of a singular
    // stiffness) is a zero frequency, an infinite period (`null` in summary.json)
    let floor = MECHANISM_RATIO * ev[2];
    ev.iter_mut()
        .filter(|w| **w <= floor)
        .for_each(|w| *w = 0.0);
    [ev[0], ev[1], ev[2]]
}

/// A natural frequency at or below this fraction of a body's highest is a mechanism mode (a
/// singular bearing stiffness): reported as zero (an infinite period), refused by the scenario
/// readers unless `allow_mechanism = true`, and left out of the Rayleigh fit.
pub const MECHANISM_RATIO: Real = 1e-6;

/// Rayleigh coefficients `(a_0, a_1)` of `C = a_0 M + a_1 K` giving damping ratio `ζ` at the two
/// lowest *distinct* frequencies `ω_a < ω_b` (relative separation > 1e-6):
/// `a_0 = 2ζ ω_a ω_b/(ω_a + ω_b)`, `a_1 = 2ζ/(ω_a + ω_b)`. With a single distinct frequency `ω`:
/// `a_0 = ζω`, `a_1 = ζ/ω`. Zero frequencies (mechanism modes, which no damping can hold) are
/// skipped: the fit is to the lowest non-zero ones. Returns `None` if `ζ > 0` and every frequency
/// is zero.
pub fn rayleigh_coefficients(zeta: Real, omega: &[Real; 3]) -> Option<(Real, Real)> {
    if zeta == 0.0 {
        return Some((0.0, 0.0));
    }
    let wa = omega.iter().copied().find(|&w| w > 0.0).unwrap_or(0.0);
    let wb = omega
        .iter()
        .copied()
        .find(|&w| w > wa * (1.0 + 1e-6) && w > 0.0);
    match wb {
        Some(wb) => Some((2.0 * zeta * wa * wb / (wa + wb), 2.0 * zeta / (wa + wb))),
        None if wa > 0.0 => Some((zeta * wa, zeta / wa)),
        None => None,
    }
}

/// One end face of a segment in the reference pose (global frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndFace {
    /// Corners `[c0, c1]` (the shape's corner order).
    pub corners: [Vector; 2],
    /// Midpoint of the face.
    pub mid: Vector,
    /// Unit direction along the face from `c0` to `c1`.
    pub dir: Vector,
    /// Unit normal pointing *into* the segment (the direction in which this end moves off its
    /// seat).
    pub inward: Vector,
    /// Half the face length \[m\]: a corner of the neighbour lies over this face iff its
    /// coordinate along [`EndFace::dir`] from [`EndFace::mid`] is at most this in magnitude.
    pub half: Real,
}

/// A segment of a bridge (a rigid deck, 3 in-plane DOF) in the reference pose, global frame.
///
/// Segments form a chain: segment `i`'s **end** face meets segment `i + 1`'s **start** face at
/// joint `i` (0-based); the start face of the first segment and the end face of the last one face
/// the abutments, if any. In the two-deck model deck 1 is segment 0 (its joint face is its end
/// face) and deck 2 is segment 1 (its joint face is its start face).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SegmentBody {
    /// Mass properties (`centroid` in the deck's body frame).
    pub mass: MassProperties,
    /// Reference centroid `G⁰` (global).
    pub centroid: Vector,
    /// The start face (toward the previous segment or the start abutment).
    pub start: EndFace,
    /// The end face (toward the next segment or the end abutment).
    pub end: EndFace,
}

impl SegmentBody {
    /// Position of the body point with reference position `p0` when the centroid is displaced by
    /// `d` and the segment turned by `θ` (given as `(sin θ, cos θ)`) about it:
    /// `p = G⁰ + d + Rot(θ)(p0 − G⁰)`.
    #[inline]
    pub fn place(&self, p0: &Vector, d: &Vector, sc: (Real, Real)) -> Vector {
        let r = p0 - self.centroid;
        let (s, c) = sc;
        self.centroid + d + Vector::new(c * r.x - s * r.y, s * r.x + c * r.y)
    }
}
