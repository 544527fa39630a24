//! Deck shapes behind one trait, [`Shape`] (mass properties, end faces, corners), one file per
//! shape — [`curved`] ([`Deck`]), [`straight`] ([`StraightDeck`]), [`skewed`] ([`SkewedDeck`]) —
//! and the user-facing enum [`DeckShape`] that dispatches to them; plus the impact of a deck's
//! end-face corners against a rigid abutment ([`abutment`]).
//!
//! Every `match` on the kind of shape lives in this module: code elsewhere calls [`Shape`]
//! methods (or [`DeckShape::curved`] / [`DeckShape::skewed`] for the paper's shape-specific
//! quantities). A new shape is one new file implementing [`Shape`] plus one [`DeckShape`] variant
//! and its arm in [`DeckShape::as_shape`] / [`DeckShape::as_shape_mut`].
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

pub mod abutment;
pub mod curved;
pub mod skewed;
pub mod straight;

pub use abutment::{
    Abutment, AbutmentContact, abutment_contact, abutment_delassus, abutment_problem,
    frictionless_pivot, joint_problem,
};
pub use curved::{Deck, SectorCentroid};
pub use skewed::SkewedDeck;
pub use straight::StraightDeck;

use crate::geometry::{GeometryError, MassProperties, ShapeParam};
use crate::math::{Real, Vector};

/// `v` must be finite and `> 0`; the error names `name`.
pub(crate) fn positive(name: ShapeParam, v: Real) -> Result<(), GeometryError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(GeometryError::invalid(name, v, "must be finite and > 0"))
    }
}

/// A plane deck in its body frame (module docs): what the pair, the abutment problems, the
/// simulation model and the front ends need to know about a deck, whatever its outline.
///
/// Implementors: [`Deck`] (curved), [`StraightDeck`], [`SkewedDeck`], and [`DeckShape`], which
/// dispatches to them.
pub trait Shape {
    /// Output name: `curved`, `straight` or `skew`.
    fn name(&self) -> &'static str;

    /// Width `W` \[m\], perpendicular to the deck axis (for a skewed deck the end faces are
    /// `W / cos θ_s` long).
    fn width(&self) -> Real;

    /// Skew angle `θ_s` \[rad\], `0 ≤ θ_s < π/2`, positive = axis turned counter-clockwise from
    /// `+y` (see [`SkewedDeck::skew`]); `0` for straight and curved decks.
    fn skew(&self) -> Real {
        0.0
    }

    /// Length `L` along the axis \[m\] (straight / skewed), `None` for a curved deck (whose size
    /// is given by `R` and `β`).
    fn length(&self) -> Option<Real>;

    /// Mass properties in the body frame (centroid relative to the joint-face midpoint).
    fn mass_properties(&self) -> MassProperties;

    /// The end face `end`: corners `[c0, c1]` (body to the right of `c0 → c1`) and the outward unit
    /// normal (module docs).
    fn end_face(&self, end: DeckEnd) -> EndFace;

    /// Unit direction of the deck axis pointing out through `end` ("longitudinal" toward that
    /// end): straight/skewed `±e` (`+e` for the far end); curved: the end face's outward normal.
    fn axis_direction(&self, end: DeckEnd) -> Vector;

    /// Interior angle of the outline at corner `k ∈ {0, 1}` of `end` \[rad\]: `π/2 − θ_s` for
    /// `c0` and `π/2 + θ_s` for `c1` ([`Shape::skew`]; right angles for straight and curved decks,
    /// the same on both end faces for all three shapes).
    fn corner_angle(&self, end: DeckEnd, k: usize) -> Real {
        let _ = end;
        if k == 0 {
            std::f64::consts::FRAC_PI_2 - self.skew()
        } else {
            std::f64::consts::FRAC_PI_2 + self.skew()
        }
    }

    /// Names of the corners `[c0, c1]` of `end`, as reports print them: curved `inner`/`outer`
    /// (joint face) and `outer`/`inner` (far face), straight `c0`/`c1`, skewed `acute`/`obtuse`.
    fn corner_names(&self, end: DeckEnd) -> [&'static str; 2];

    /// Re-runs the shape's constructor checks on its current fields (e.g. after editing them);
    /// errors name the parameter as the constructor does (`R`, `beta`, `length`, `skew`, `width`,
    /// …; see [`GeometryError::for_deck`] for per-deck names).
    fn validate(&self) -> Result<(), GeometryError>;

    /// Multiplies the density `ρ` by `factor` (mass and inertia scale with it, the outline does not).
    fn scale_density(&mut self, factor: Real);
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
    /// The shape behind the enum (the one place that matches on the kind of shape).
    pub fn as_shape(&self) -> &dyn Shape {
        match self {
            Self::Curved(d) => d,
            Self::Straight(d) => d,
            Self::Skewed(d) => d,
        }
    }

    /// The shape behind the enum, mutably.
    pub fn as_shape_mut(&mut self) -> &mut dyn Shape {
        match self {
            Self::Curved(d) => d,
            Self::Straight(d) => d,
            Self::Skewed(d) => d,
        }
    }

    /// The curved deck, if this is one (for the paper's sector quantities `R`, `β`, `r_c`, …).
    pub fn curved(&self) -> Option<&Deck> {
        match self {
            Self::Curved(d) => Some(d),
            _ => None,
        }
    }

    /// The skewed deck, if this is one (for the skew-specific rotation criteria).
    pub fn skewed(&self) -> Option<&SkewedDeck> {
        match self {
            Self::Skewed(d) => Some(d),
            _ => None,
        }
    }

    /// The same kind of deck with the axis length `length` (other parameters kept), validated;
    /// for a curved deck (no axis length) an error naming `length`.
    pub fn with_length(&self, length: Real) -> Result<DeckShape, GeometryError> {
        match self {
            Self::Straight(d) => {
                StraightDeck::new(length, d.width, d.thickness, d.density).map(Self::Straight)
            }
            Self::Skewed(d) => {
                SkewedDeck::new(length, d.width, d.skew, d.thickness, d.density).map(Self::Skewed)
            }
            Self::Curved(_) => Err(GeometryError::invalid(
                ShapeParam::Length,
                length,
                "a curved deck has no axis length (give R and beta)",
            )),
        }
    }
}

/// The [`Shape`] methods, dispatched through [`DeckShape::as_shape`] (inherent, so callers need
/// not import the trait).
impl DeckShape {
    /// Output name: `curved`, `straight` or `skew` ([`Shape::name`]).
    pub fn name(&self) -> &'static str {
        self.as_shape().name()
    }
    /// Width `W` \[m\] ([`Shape::width`]).
    pub fn width(&self) -> Real {
        self.as_shape().width()
    }
    /// Skew angle `θ_s` \[rad\], `0` unless skewed ([`Shape::skew`]).
    pub fn skew(&self) -> Real {
        self.as_shape().skew()
    }
    /// Axis length `L` \[m\], `None` for a curved deck ([`Shape::length`]).
    pub fn length(&self) -> Option<Real> {
        self.as_shape().length()
    }
    /// Mass properties in the body frame ([`Shape::mass_properties`]).
    pub fn mass_properties(&self) -> MassProperties {
        self.as_shape().mass_properties()
    }
    /// The end face `end`: corners `[c0, c1]` and outward normal ([`Shape::end_face`]).
    pub fn end_face(&self, end: DeckEnd) -> EndFace {
        self.as_shape().end_face(end)
    }
    /// Unit axis direction out through `end` ([`Shape::axis_direction`]).
    pub fn axis_direction(&self, end: DeckEnd) -> Vector {
        self.as_shape().axis_direction(end)
    }
    /// Interior angle at corner `k` of `end` \[rad\] ([`Shape::corner_angle`]).
    pub fn corner_angle(&self, end: DeckEnd, k: usize) -> Real {
        self.as_shape().corner_angle(end, k)
    }
    /// Names of the corners `[c0, c1]` of `end` ([`Shape::corner_names`]).
    pub fn corner_names(&self, end: DeckEnd) -> [&'static str; 2] {
        self.as_shape().corner_names(end)
    }
    /// Re-runs the constructor checks ([`Shape::validate`]).
    pub fn validate(&self) -> Result<(), GeometryError> {
        self.as_shape().validate()
    }
    /// Multiplies the density by `factor` ([`Shape::scale_density`]).
    pub fn scale_density(&mut self, factor: Real) {
        self.as_shape_mut().scale_density(factor)
    }
}
