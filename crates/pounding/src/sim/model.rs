//! The structural model of a simulation: deck bodies in the reference pose, bearings, the linear
//! mass / stiffness / Rayleigh-damping matrices.

use super::SimError;
use crate::geometry::MassProperties;
use crate::math::{Real, Vector};
use crate::shape::{Deck, DeckEnd, DeckShape};
use nalgebra::{Matrix3, Matrix6};

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

/// A deck's body-fixed points in the reference pose, global frame of spec §4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckBody {
    /// Mass properties (`centroid` in the deck's body frame, see [`crate::shape`]).
    pub mass: MassProperties,
    /// Reference centroid `G⁰` (global).
    pub centroid: Vector,
    /// Reference face midpoint `M⁰` (global): `(0, g)` for deck 1, `(0, 0)` for deck 2.
    pub face_mid: Vector,
    /// Joint-face corners `[inner, outer]` (global, reference pose).
    pub joint_corners: [Vector; 2],
    /// Far-end (other end face) corners `[inner, outer]` (global, reference pose).
    pub far_corners: [Vector; 2],
    /// Unit vector along the joint face from inner to outer corner, `e_j` (spec §4).
    pub face_dir: Vector,
    /// Unit normal of the joint face pointing *into* the deck (the direction in which the end
    /// moves off its seat).
    pub joint_inward: Vector,
    /// Unit normal of the far end face pointing into the deck.
    pub far_inward: Vector,
    /// Half the joint-face length (`W/2`; `W/(2 cos θ_s)` for a skewed deck) \[m\]: a corner of
    /// the other deck lies over this face iff `|σ| ≤ half_face`.
    pub half_face: Real,
}

impl DeckBody {
    /// Reference-pose body of deck `j ∈ {1, 2}` with joint opening `gap` (spec §4):
    /// deck 1 points `M_1 + (R_1 − r cos φ, r sin φ)`, deck 2 points `M_2 + (−R_2 + r cos φ, −r sin φ)`,
    /// `r ∈ [R − W/2, R + W/2]`, `φ ∈ [0, β]`.
    pub fn new(deck: &Deck, j: usize, gap: Real) -> Self {
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
        DeckBody {
            mass: mp,
            centroid: face_mid + mp.centroid * s,
            face_mid,
            joint_corners: [face_mid + pt(ri, 0.0), face_mid + pt(ro, 0.0)],
            far_corners: [face_mid + pt(ri, b), face_mid + pt(ro, b)],
            face_dir: Vector::new(-s, 0.0),
            joint_inward: Vector::new(0.0, s),
            // d/dφ of the body point: s (ρ sin φ, ρ cos φ) points into the deck at φ = 0 and out
            // of it at φ = β.
            far_inward: -Vector::new(s * b.sin(), s * b.cos()),
            half_face: w / 2.0,
        }
    }

    /// Reference-pose body of deck `j ∈ {1, 2}` of any [`DeckShape`] (frames of [`crate::shape`]):
    /// deck 1 is the body frame translated by `(0, g)`, deck 2 the body frame turned by π about
    /// the origin, so the two joint faces lie on `y = g` and `y = 0` and the decks meet face to
    /// face. Corner `k` of the joint face is the shape's `c_k` (curved: `c0` = inner; straight /
    /// skewed: `c0` = acute corner), so deck 1's `c0` and deck 2's `c1` lie at `x = +b/2`.
    pub fn from_shape(shape: &DeckShape, j: usize, gap: Real) -> Self {
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
        DeckBody {
            mass,
            centroid: w(mass.centroid),
            face_mid: off,
            joint_corners: jc,
            far_corners: [w(ff.corners[0]), w(ff.corners[1])],
            face_dir: (jc[1] - jc[0]).normalize(),
            joint_inward: -jf.outward_normal * s,
            far_inward: -ff.outward_normal * s,
            half_face: 0.5 * jf.length(),
        }
    }

    /// Midpoint of the far end face (reference pose, global).
    pub fn far_mid(&self) -> Vector {
        (self.far_corners[0] + self.far_corners[1]) * 0.5
    }

    /// Position of the body point with reference position `p0` when the deck's centroid is
    /// displaced by `d` and the deck turned by `θ` (given as `(sin θ, cos θ)`) about it:
    /// `p = G⁰ + d + Rot(θ)(p0 − G⁰)`.
    #[inline]
    pub fn place(&self, p0: &Vector, d: &Vector, sc: (Real, Real)) -> Vector {
        let r = p0 - self.centroid;
        let (s, c) = sc;
        self.centroid + d + Vector::new(c * r.x - s * r.y, s * r.x + c * r.y)
    }
}

/// `3 × 3` stiffness of one deck's bearings in `(u_x, u_y, θ)` (linearised kinematics):
/// `K = Σ_p k_p Bᵀ B`, `B = [[1, 0, −r_y], [0, 1, r_x]]`, `r = p − G⁰`.
pub fn bearing_stiffness(body: &DeckBody, bearings: &[Bearing]) -> Matrix3<Real> {
    let mut k = Matrix3::zeros();
    for b in bearings {
        let r = body.face_mid + b.point - body.centroid;
        let bm = nalgebra::Matrix2x3::new(1.0, 0.0, -r.y, 0.0, 1.0, r.x);
        k += b.stiffness * bm.transpose() * bm;
    }
    k
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

/// The assembled linear system of both decks in `q = (x1, y1, θ1, x2, y2, θ2)` (spec §5.1).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearSystem {
    /// `M = diag(m1, m1, I1, m2, m2, I2)`.
    pub mass: Matrix6<Real>,
    /// Bearing stiffness (block diagonal).
    pub stiffness: Matrix6<Real>,
    /// Rayleigh damping (block diagonal), per deck `C_j = a_0j M_j + a_1j K_j`.
    pub damping: Matrix6<Real>,
    /// Natural frequencies of each deck \[rad/s\].
    pub frequencies: [[Real; 3]; 2],
    /// Rayleigh coefficients `(a_0, a_1)` per deck.
    pub rayleigh: [(Real, Real); 2],
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
    /// The segment of two-deck body `deck` (`j = 1` or `2`, see [`DeckBody`]): deck 1's joint face
    /// is its end face, deck 2's its start face.
    pub fn of_deck(deck: &DeckBody, j: usize) -> Self {
        let joint = EndFace {
            corners: deck.joint_corners,
            mid: deck.face_mid,
            dir: deck.face_dir,
            inward: deck.joint_inward,
            half: deck.half_face,
        };
        let fc = deck.far_corners;
        let far = EndFace {
            corners: fc,
            mid: deck.far_mid(),
            dir: (fc[1] - fc[0]).normalize(),
            inward: deck.far_inward,
            half: 0.5 * (fc[1] - fc[0]).norm(),
        };
        let (start, end) = if j == 1 { (far, joint) } else { (joint, far) };
        SegmentBody {
            mass: deck.mass,
            centroid: deck.centroid,
            start,
            end,
        }
    }

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
