//! Deck shapes (curved, straight, skewed), their mass properties, end faces and corners, and the
//! impact of a deck's end-face corners against a rigid abutment.
//!
//! # Body frame **\[C\]**
//!
//! Every shape is described in one body frame, the *deck-1 frame* of the spec (spec §4): the origin
//! is the midpoint `M` of the deck's **joint face**, the joint face lies on the x-axis, and the deck
//! extends into `y > 0`. So deck 1 in its reference pose (spec §4, opening `g`) is the body frame
//! translated by `(0, g)`, and deck 2 is the body frame **turned by π** about the origin (the
//! point symmetry of spec §4). Counter-clockwise angles are positive.
//!
//! * **Curved** ([`Deck`], spec §2–§3): the annular sector with centre of curvature `(R, 0)`; body
//!   points `(R − r cos φ, r sin φ)`, `r ∈ [R − W/2, R + W/2]`, `φ ∈ [0, β]` (spec §4, deck 1).
//! * **Straight** ([`StraightDeck`]): the rectangle `[−W/2, W/2] × [0, L]`. Axis along `+y`.
//! * **Skewed** ([`SkewedDeck`]): the parallelogram whose two end faces are parallel to the x-axis
//!   (the joint line) and whose axis is turned counter-clockwise by the skew angle `θ_s` from `+y`:
//!   axis direction `e = (−sin θ_s, cos θ_s)`. `L` is the length along the axis (distance between
//!   the end-face midpoints, also the length of the side edges), `W` the width **perpendicular to
//!   the axis**; each end face is therefore `W / cos θ_s` long. The joint face runs from
//!   `(W/(2 cos θ_s), 0)` to `(−W/(2 cos θ_s), 0)`, the far face is the joint face shifted by `L e`.
//!   The straight deck is the skewed deck with `θ_s = 0`.
//!
//! Decks in a row meet face to face: deck 2 (turned by π) has the axis `−e`, collinear with deck 1's,
//! so two skewed decks form one parallelogram strip cut by the joint line; at each joint end an
//! acute corner of one deck meets an obtuse corner of the other.
//!
//! # End faces and corners **\[C\]**
//!
//! Each deck has two end faces, [`DeckEnd::Joint`] and [`DeckEnd::Far`]. The corners of a face are
//! ordered `[c0, c1]` so that the body lies to the **right** of `c0 → c1` (clockwise traversal of
//! the outline); the outward unit normal is `n_out = perp(c1 − c0)/|c1 − c0|` with
//! `perp(v) = (−v_y, v_x)`.
//!
//! * Straight/skewed: `c0` is the **acute** corner (interior angle `90° − θ_s`), `c1` the **obtuse**
//!   one (`90° + θ_s`), on both faces (diagonally opposite corners of a parallelogram are equal).
//!   Joint face: `c0 = (W/(2c), 0)`, `c1 = (−W/(2c), 0)`, `n_out = (0, −1)`; far face:
//!   `c0 = (−W/(2c), 0) + L e`, `c1 = (W/(2c), 0) + L e`, `n_out = (0, 1)` (`c = cos θ_s`).
//! * Curved: joint face `c0` = inner corner `(W/2, 0)`, `c1` = outer corner `(−W/2, 0)` (spec §4),
//!   `n_out = (0, −1)`; far face (the radial face at `φ = β`) `c0` = outer, `c1` = inner corner,
//!   `n_out = (sin β, cos β)`. All four interior angles are right angles.
//!
//! # Abutment impact **\[M\]**
//!
//! A rigid abutment (the fixed ground) faces one end of the deck across a gap `g ≥ 0` measured along
//! that face's outward normal; its face is parallel to the deck's end face. A corner touching the
//! abutment face is a contact of the generic [`impact`](crate::impact) module with body `a` = the
//! deck, body `b` = ground, contact point = the corner, normal `n = −n_out` (into the deck) and
//! tangent `t = perp(n)`. With the lever arm `r = c_k − G` from the centroid, the single-contact
//! Delassus matrix (ground: infinite mass) is
//! ```text
//! G_NN = 1/m + (r × n)²/I,   G_NT = (r × n)(r × t)/I,   G_TT = 1/m + (r × t)²/I .
//! ```

use crate::analytic::ImpactLaw;
use crate::contact::Delassus;
use crate::geometry::{Deck, GeometryError};
use crate::impact::{ContactSpec, ImpactError, ImpactProblem, RigidBody};
use crate::math::{Real, Vector, cross, perp};

fn invalid(name: &str, value: Real, reason: &str) -> GeometryError {
    GeometryError::InvalidParameter {
        name: name.to_string(),
        value,
        reason: reason.to_string(),
    }
}

fn positive(name: &str, v: Real) -> Result<(), GeometryError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(invalid(name, v, "must be finite and > 0"))
    }
}

/// A straight deck: the rectangle `[−W/2, W/2] × [0, L]` in the body frame (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StraightDeck {
    /// Length `L` along the axis (`+y`) \[m\], `> 0`.
    pub length: Real,
    /// Width `W` (along x, the joint line) \[m\], `> 0`.
    pub width: Real,
    /// Thickness `t` \[m\], `> 0`.
    pub thickness: Real,
    /// Density `ρ` \[kg/m³\], `> 0`.
    pub density: Real,
}

impl StraightDeck {
    /// A validated straight deck: all parameters finite and `> 0`. Errors name the parameter as
    /// `length`, `width`, `thickness` or `density`.
    pub fn new(
        length: Real,
        width: Real,
        thickness: Real,
        density: Real,
    ) -> Result<Self, GeometryError> {
        positive("length", length)?;
        positive("width", width)?;
        positive("thickness", thickness)?;
        positive("density", density)?;
        Ok(Self {
            length,
            width,
            thickness,
            density,
        })
    }

    /// The same rectangle as a skewed deck with `θ_s = 0`.
    pub fn as_skewed(&self) -> SkewedDeck {
        SkewedDeck {
            length: self.length,
            width: self.width,
            skew: 0.0,
            thickness: self.thickness,
            density: self.density,
        }
    }
}

/// A skewed deck: a parallelogram with end faces along the joint line (x) and the axis turned by
/// the skew angle `θ_s` from `+y` (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SkewedDeck {
    /// Length `L` along the axis (between the end-face midpoints) \[m\], `> 0`.
    pub length: Real,
    /// Width `W` perpendicular to the axis \[m\], `> 0` (each end face is `W / cos θ_s` long).
    pub width: Real,
    /// Skew angle `θ_s` \[rad\], `0 ≤ θ_s < π/2`: the angle between the end faces and the normal of
    /// the axis. Positive = axis turned counter-clockwise from `+y`, i.e. `e = (−sin θ_s, cos θ_s)`.
    pub skew: Real,
    /// Thickness `t` \[m\], `> 0`.
    pub thickness: Real,
    /// Density `ρ` \[kg/m³\], `> 0`.
    pub density: Real,
}

impl SkewedDeck {
    /// A validated skewed deck: `L, W, t, ρ` finite and `> 0`, `0 ≤ θ_s < π/2` (radians). Errors
    /// name the parameter as `length`, `width`, `skew`, `thickness` or `density` (the `skew` value
    /// is reported in degrees).
    pub fn new(
        length: Real,
        width: Real,
        skew: Real,
        thickness: Real,
        density: Real,
    ) -> Result<Self, GeometryError> {
        positive("length", length)?;
        positive("width", width)?;
        if !(skew.is_finite() && (0.0..std::f64::consts::FRAC_PI_2).contains(&skew)) {
            return Err(invalid(
                "skew",
                skew.to_degrees(),
                "the skew angle must lie in [0, 90) degrees",
            ));
        }
        positive("thickness", thickness)?;
        positive("density", density)?;
        Ok(Self {
            length,
            width,
            skew,
            thickness,
            density,
        })
    }

    /// Unit axis direction `e = (−sin θ_s, cos θ_s)` (from the joint face toward the far face).
    pub fn axis(&self) -> Vector {
        Vector::new(-self.skew.sin(), self.skew.cos())
    }

    /// End-face length `W / cos θ_s` \[m\].
    pub fn face_length(&self) -> Real {
        self.width / self.skew.cos()
    }

    /// Mass properties of the parallelogram spanned by the face vector `a` (`|a| = W/cos θ_s`) and
    /// the side vector `b = L e`:
    /// `A = L W`, `m = ρ t A`, centroid `(L/2) e`, `I = m (|a|² + |b|²)/12 = m (L² + W²/cos²θ_s)/12`.
    pub fn mass_properties(&self) -> PlanarMassProperties {
        let area = self.length * self.width;
        let mass = self.density * self.thickness * area;
        let a2 = self.face_length().powi(2);
        PlanarMassProperties {
            area,
            mass,
            centroid: 0.5 * self.length * self.axis(),
            inertia: mass * (self.length * self.length + a2) / 12.0,
        }
    }

    /// `sin 2θ_s > 2W/L`: the frictionless rotation condition for a purely longitudinal approach
    /// of the deck against an abutment with both corners of an end face striking (see
    /// [`frictionless_pivot`]). Equivalent to `(L/2) sin θ_s > W/(2 cos θ_s)`: the foot of the
    /// perpendicular from the centroid onto the end-face line lies beyond the obtuse corner.
    pub fn rotates_on_abutment_impact(&self) -> bool {
        (2.0 * self.skew).sin() > 2.0 * self.width / self.length
    }

    /// The rotation condition with Coulomb friction (our extension, checked against the 2-contact
    /// LCP): for a longitudinal approach with both corners striking, the deck turns about its
    /// obtuse corner iff
    /// ```text
    /// sin 2θ_s − μ_eff (1 + cos 2θ_s) > 2W/L,    μ_eff = min(μ, tan θ_s/(1 + ε_N)).
    /// ```
    /// Derivation: with both corners active `ω⁺ = 0`; the corners share the tangential arm
    /// `B = −(L/2) cos θ_s`, so the moment balance has non-negative normal impulses iff the
    /// impulse ratio `T/N` satisfies `A_1 ≤ (L/2) cos θ_s · T/N`, with `T/N = μ` when the corners
    /// slide and `T/N = tan θ_s/(1+ε)` when they stick (`v⁺·t = 0`). For `μ = 0` this is
    /// [`SkewedDeck::rotates_on_abutment_impact`]; in the sticking regime it reads
    /// `sin 2θ_s · ε/(1+ε) > 2W/L` and depends on `ε_N`.
    pub fn rotates_on_abutment_impact_with(&self, law: &ImpactLaw) -> bool {
        let th = self.skew;
        let mu_eff = law.mu().min(th.tan() / (1.0 + law.eps()));
        (2.0 * th).sin() - mu_eff * (1.0 + (2.0 * th).cos()) > 2.0 * self.width / self.length
    }

    fn end_face(&self, end: DeckEnd) -> EndFace {
        let half = 0.5 * self.face_length();
        match end {
            DeckEnd::Joint => EndFace {
                corners: [Vector::new(half, 0.0), Vector::new(-half, 0.0)],
                outward_normal: Vector::new(0.0, -1.0),
            },
            DeckEnd::Far => {
                let s = self.length * self.axis();
                EndFace {
                    corners: [Vector::new(-half, 0.0) + s, Vector::new(half, 0.0) + s],
                    outward_normal: Vector::new(0.0, 1.0),
                }
            }
        }
    }
}

/// Mass properties of a plane deck in its body frame (a value type, like parry's `MassProperties`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarMassProperties {
    /// Plan area `A` \[m²\].
    pub area: Real,
    /// Mass `m = ρ t A` \[kg\].
    pub mass: Real,
    /// Centroid `G` in the body frame \[m\].
    pub centroid: Vector,
    /// Polar moment of inertia about the centroid `I` \[kg m²\].
    pub inertia: Real,
}

impl PlanarMassProperties {
    /// Radius of gyration `k = √(I/m)` \[m\].
    pub fn radius_of_gyration(&self) -> Real {
        (self.inertia / self.mass).sqrt()
    }
}

/// Which end face of a deck.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DeckEnd {
    /// The face at the expansion joint (on the x-axis of the body frame).
    Joint,
    /// The opposite end face (toward the abutment or the next joint).
    Far,
}

impl DeckEnd {
    /// Output name: `joint` or `far`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Joint => "joint",
            Self::Far => "far",
        }
    }
}

/// One end face in the body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndFace {
    /// `[c0, c1]`, ordered so the body lies to the right of `c0 → c1` (module docs).
    pub corners: [Vector; 2],
    /// Outward unit normal `n_out = perp(c1 − c0)/|c1 − c0|`.
    pub outward_normal: Vector,
}

impl EndFace {
    /// Midpoint `(c0 + c1)/2`.
    pub fn midpoint(&self) -> Vector {
        0.5 * (self.corners[0] + self.corners[1])
    }
    /// Face length `|c1 − c0|`.
    pub fn length(&self) -> Real {
        (self.corners[1] - self.corners[0]).norm()
    }
}

/// A deck of any supported shape (all in the body frame of the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DeckShape {
    /// The annular sector of spec §2 (the existing [`Deck`]).
    Curved(Deck),
    /// A rectangle.
    Straight(StraightDeck),
    /// A parallelogram.
    Skewed(SkewedDeck),
}

impl DeckShape {
    /// Output name: `curved`, `straight` or `skew`.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Curved(_) => "curved",
            Self::Straight(_) => "straight",
            Self::Skewed(_) => "skew",
        }
    }

    /// Width `W` \[m\] (perpendicular to the axis).
    pub fn width(&self) -> Real {
        match self {
            Self::Curved(d) => d.width,
            Self::Straight(d) => d.width,
            Self::Skewed(d) => d.width,
        }
    }

    /// Mass properties in the body frame. Curved: spec §3 with the centroid `(R − X_m, Y_m)`;
    /// straight: `A = LW`, `G = (0, L/2)`, `I = m (L² + W²)/12`; skewed: [`SkewedDeck::mass_properties`].
    pub fn mass_properties(&self) -> PlanarMassProperties {
        match self {
            Self::Curved(d) => {
                let p = d.mass_properties();
                PlanarMassProperties {
                    area: p.area,
                    mass: p.mass,
                    centroid: Vector::new(d.radius - p.x_m, p.y_m),
                    inertia: p.inertia,
                }
            }
            Self::Straight(d) => d.as_skewed().mass_properties(),
            Self::Skewed(d) => d.mass_properties(),
        }
    }

    /// The end face `end`: corners `[c0, c1]` and the outward unit normal (module docs).
    pub fn end_face(&self, end: DeckEnd) -> EndFace {
        match self {
            Self::Curved(d) => {
                let (r, w, b) = (d.radius, d.width, d.angle);
                match end {
                    DeckEnd::Joint => EndFace {
                        corners: [Vector::new(0.5 * w, 0.0), Vector::new(-0.5 * w, 0.0)],
                        outward_normal: Vector::new(0.0, -1.0),
                    },
                    DeckEnd::Far => {
                        let (s, c) = b.sin_cos();
                        let at = |rr: Real| Vector::new(r - rr * c, rr * s);
                        EndFace {
                            corners: [at(r + 0.5 * w), at(r - 0.5 * w)],
                            outward_normal: Vector::new(s, c),
                        }
                    }
                }
            }
            Self::Straight(d) => d.as_skewed().end_face(end),
            Self::Skewed(d) => d.end_face(end),
        }
    }

    /// Unit direction of the deck axis pointing out through `end` ("longitudinal" toward that
    /// end): straight/skewed `±e` (`+e` for the far end); curved: the end face's outward normal
    /// (the centre line meets the radial faces at right angles).
    pub fn axis_direction(&self, end: DeckEnd) -> Vector {
        match (self, end) {
            (Self::Curved(_), _) => self.end_face(end).outward_normal,
            (Self::Straight(d), e) => Self::Skewed(d.as_skewed()).axis_direction(e),
            (Self::Skewed(d), DeckEnd::Far) => d.axis(),
            (Self::Skewed(d), DeckEnd::Joint) => -d.axis(),
        }
    }

    /// Interior angle of the outline at corner `k ∈ {0, 1}` of `end` \[rad\]: `π/2 − θ_s` for
    /// `c0` and `π/2 + θ_s` for `c1` of a skewed deck, `π/2` for straight and curved decks.
    /// (The angles are the same on both end faces for all three shapes.)
    pub fn corner_angle(&self, _end: DeckEnd, k: usize) -> Real {
        let skew = match self {
            Self::Skewed(d) => d.skew,
            _ => 0.0,
        };
        if k == 0 {
            std::f64::consts::FRAC_PI_2 - skew
        } else {
            std::f64::consts::FRAC_PI_2 + skew
        }
    }
}

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
            return Err(invalid(
                "gap",
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
    let p = shape.mass_properties();
    let c = abutment_contact(shape, end, k);
    let (im, ii) = (1.0 / p.mass, 1.0 / p.inertia);
    Delassus {
        nn: im + c.arm_n * c.arm_n * ii,
        nt: c.arm_n * c.arm_t * ii,
        tt: im + c.arm_t * c.arm_t * ii,
    }
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
/// [`SkewedDeck::rotates_on_abutment_impact`] and the pivot is the obtuse corner `c1`.
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
/// frame itself, deck 2 the body frame turned by π about the origin (module docs), and **both**
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
        let skew = |d: &DeckShape| match d {
            DeckShape::Skewed(s) => s.skew,
            _ => 0.0,
        };
        let name = if deck1.width() != deck2.width() {
            "width"
        } else if skew(deck1) != skew(deck2) {
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
