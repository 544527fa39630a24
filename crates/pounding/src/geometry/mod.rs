//! The shape-independent vocabulary of a joint between two decks (spec §4–§5): parameter errors,
//! the one mass-property type, candidate contacts, σ modes, degeneracies, the impact
//! configuration and the first-contact rules.
//!
//! Conventions (spec §4, §5): origin at the midpoint `M_2` of deck 2's joint face, x along the
//! joint line, y normal to the joint pointing into deck 1, counter-clockwise angles positive.
//! Deck 1 lies in `y > 0`, deck 2 in `y < 0`. Impact configurations use the *joint-anchored
//! placement* (spec §5.2): deck `j` is rotated by `θ_j` about its own face midpoint `M_j`;
//! `M_2 = (0, 0)` stays and deck 1 is moved along y to `M_1 = (0, h)` until the candidate corner
//! lies on the struck face. The deck shapes live in [`crate::shape`], the configuration of a pair
//! of decks (and the curved S arrangement, its preset) in [`crate::pair`].

use crate::math::{Real, Vector};

mod error;
pub(crate) use error::check_derived;
pub use error::{GeometryError, ShapeParam};

/// Mass properties of a plane rigid body (a deck) in its body frame: the one mass-property type
/// of the crate (like parry's `MassProperties`). Every deck shape returns it
/// ([`Shape::mass_properties`](crate::shape::Shape::mass_properties)); the generic pair
/// ([`crate::pair`]) and the Delassus matrix ([`crate::contact`]) consume it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    /// Plan area `A` \[m²\].
    pub area: Real,
    /// Mass `m = ρ t A` \[kg\].
    pub mass: Real,
    /// Centroid `G` in the body frame of [`crate::shape`] (origin at the joint-face midpoint, joint
    /// face on the x-axis, deck in `y > 0`) \[m\]. For a curved deck `G = (R − X_m, Y_m)` (spec §3–§4).
    pub centroid: Vector,
    /// Polar moment of inertia about the centroid `I` \[kg m²\].
    pub inertia: Real,
}

impl MassProperties {
    /// Radius of gyration `k = √(I/m)` \[m\].
    pub fn radius_of_gyration(&self) -> Real {
        (self.inertia / self.mass).sqrt()
    }
}

/// Which deck.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DeckId {
    /// Deck 1 (in `y > 0`).
    One,
    /// Deck 2 (in `y < 0`).
    Two,
}

/// Which corner of a deck's joint face (spec §2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Corner {
    /// The face end at radius `R − W/2`.
    Inner,
    /// The face end at radius `R + W/2`.
    Outer,
}

/// The four candidate contacts (spec §5.3), in the study's output order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactCase {
    /// Deck 1's inner corner on deck 2's face.
    Deck1Inner,
    /// Deck 1's outer corner on deck 2's face.
    Deck1Outer,
    /// Deck 2's inner corner on deck 1's face.
    Deck2Inner,
    /// Deck 2's outer corner on deck 1's face.
    Deck2Outer,
}

impl ContactCase {
    /// All four, in output order.
    pub const ALL: [ContactCase; 4] = [
        Self::Deck1Inner,
        Self::Deck1Outer,
        Self::Deck2Inner,
        Self::Deck2Outer,
    ];
    /// The CLI/CSV name: `deck1-inner`, `deck1-outer`, `deck2-inner`, `deck2-outer`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Deck1Inner => "deck1-inner",
            Self::Deck1Outer => "deck1-outer",
            Self::Deck2Inner => "deck2-inner",
            Self::Deck2Outer => "deck2-outer",
        }
    }
    /// Parses a CLI/CSV name.
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.name() == s)
    }
    /// The striking deck `a` (owner of the corner).
    pub fn striking(self) -> DeckId {
        match self {
            Self::Deck1Inner | Self::Deck1Outer => DeckId::One,
            Self::Deck2Inner | Self::Deck2Outer => DeckId::Two,
        }
    }
    /// The struck deck `b` (owner of the face).
    pub fn struck(self) -> DeckId {
        match self {
            Self::Deck1Inner | Self::Deck1Outer => DeckId::Two,
            Self::Deck2Inner | Self::Deck2Outer => DeckId::One,
        }
    }
    /// The striking corner.
    pub fn corner(self) -> Corner {
        match self {
            Self::Deck1Inner | Self::Deck2Inner => Corner::Inner,
            Self::Deck1Outer | Self::Deck2Outer => Corner::Outer,
        }
    }
}

/// Where on the struck face the contact point lies (spec §6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum SigmaMode {
    /// σ from the exact corner position (default).
    #[default]
    Exact,
    /// The paper's idealisation: struck point at the face end, `σ_b = ±W/2`.
    End,
}

impl SigmaMode {
    /// Output name: `exact` or `end`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Exact => "exact",
            Self::End => "end",
        }
    }
    /// Parses `exact` / `end`.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "exact" => Some(Self::Exact),
            "end" => Some(Self::End),
            _ => None,
        }
    }
}

/// Degenerate poses where the single-impact model does not apply (spec §5.4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Degeneracy {
    /// `θ1 = θ2`: the faces are parallel (line / double contact).
    ParallelFaces,
    /// `θ1 = −θ2 ≠ 0`: corner meets corner (normal not unique).
    CornerCorner,
}

impl Degeneracy {
    /// Output name: `parallel-faces` or `corner-corner`.
    pub fn name(self) -> &'static str {
        match self {
            Self::ParallelFaces => "parallel-faces",
            Self::CornerCorner => "corner-corner",
        }
    }
}

/// Absolute tolerance \[rad\] under which `θ1 = θ2` (or `θ1 = −θ2`) counts as degenerate.
///
/// It only absorbs the rounding of grids such as `−10° + i·Δ` converted to radians; any pose
/// further from a diagonal is treated as a regular single impact.
pub const DEGENERACY_TOLERANCE: Real = 1e-12;

/// Largest admissible |θ| \[rad\] (exclusive): the placement divides by `cos θ` (spec §5.3).
pub const MAX_ROTATION: Real = std::f64::consts::FRAC_PI_2;

/// Checks one rotation `theta` \[rad\]: finite and `|θ| < 90°`. `name` is the parameter's name
/// in the error (e.g. `theta1`); the error reports the value in degrees, as users give it.
pub fn validate_rotation(name: &str, theta: Real) -> Result<(), GeometryError> {
    if theta.is_finite() && theta.abs() < MAX_ROTATION {
        Ok(())
    } else {
        Err(GeometryError::named(
            &format!("{name} [deg]"),
            theta.to_degrees(),
            "the rotation must be finite with |theta| < 90 degrees",
        ))
    }
}

/// The impact configuration of one candidate case at rotations `(θ1, θ2)` (spec §5.2–§5.4),
/// joint-anchored placement, global frame of spec §4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactConfiguration {
    /// The candidate case.
    pub case: ContactCase,
    /// Rotation of deck 1 \[rad\].
    pub theta1: Real,
    /// Rotation of deck 2 \[rad\].
    pub theta2: Real,
    /// Closing distance `h`: `M_1 = (0, h)` puts the corner on the struck face line \[m\].
    pub h: Real,
    /// `σ_b` on the struck face (+ toward b's outer corner), in the chosen σ mode \[m\].
    pub sigma: Real,
    /// This candidate's `h` exceeds that of the same deck's other corner.
    pub end_closes: bool,
    /// This candidate is the real first contact (spec §5.4).
    pub first_contact: bool,
    /// Contact point `C` (global frame): the striking corner `P = M_a + Rot(θ_a) c_k`.
    pub point: Vector,
    /// Unit normal `ν` (from the deck-2 side to the deck-1 side).
    pub normal: Vector,
    /// Unit tangent `τ` (toward deck 1's radially outward side).
    pub tangent: Vector,
    /// Centroid of deck 1 in this pose.
    pub centroid1: Vector,
    /// Centroid of deck 2 in this pose.
    pub centroid2: Vector,
    /// The σ mode used for [`sigma`](Self::sigma) and [`struck_point`](Self::struck_point).
    pub sigma_mode: SigmaMode,
    /// `σ_b` from the exact corner position, whatever the mode (decides `|σ_b| ≤ W/2`) \[m\].
    pub sigma_exact: Real,
    /// The struck deck's material point: `M_b + σ_b Rot(θ_b) e_b` with the mode's σ. In the exact
    /// mode it coincides with [`point`](Self::point); in the `end` mode it is the face end.
    pub struck_point: Vector,
    /// Face midpoint of deck 1, `M_1 = (0, h)`.
    pub face_mid1: Vector,
}

impl ImpactConfiguration {
    /// Lever arm `r_j = C − G_j` of deck `j` (the struck deck's arm uses the struck point).
    pub fn lever_arm(&self, deck: DeckId) -> Vector {
        let striking = self.case.striking();
        let c = if deck == striking {
            self.point
        } else {
            self.struck_point
        };
        match deck {
            DeckId::One => c - self.centroid1,
            DeckId::Two => c - self.centroid2,
        }
    }
}

/// Which candidates are the real first contact (spec §5.4): the striking deck is the one with the
/// larger |θ| and its own rotation sign selects the corner (`deck1-inner ⟺ θ1 < −|θ2|`,
/// `deck1-outer ⟺ θ1 > |θ2|`, `deck2-inner ⟺ θ2 < −|θ1|`, `deck2-outer ⟺ θ2 > |θ1|`).
pub fn is_first_contact(case: ContactCase, theta1: Real, theta2: Real) -> bool {
    match case {
        ContactCase::Deck1Inner => theta1 < -theta2.abs(),
        ContactCase::Deck1Outer => theta1 > theta2.abs(),
        ContactCase::Deck2Inner => theta2 < -theta1.abs(),
        ContactCase::Deck2Outer => theta2 > theta1.abs(),
    }
}

/// The degeneracy of a pose, if any (`θ1 = θ2` first, then `θ1 = −θ2`), within
/// [`DEGENERACY_TOLERANCE`].
pub fn degeneracy(theta1: Real, theta2: Real) -> Option<Degeneracy> {
    degeneracy_within(theta1, theta2, DEGENERACY_TOLERANCE)
}

/// The degeneracy of a pose within `tol` (the angles and `tol` in one unit):
/// `|θ1 − θ2| ≤ tol` → parallel faces, then `|θ1 + θ2| ≤ tol` → corner meets corner.
pub fn degeneracy_within(theta1: Real, theta2: Real, tol: Real) -> Option<Degeneracy> {
    if (theta1 - theta2).abs() <= tol {
        Some(Degeneracy::ParallelFaces)
    } else if (theta1 + theta2).abs() <= tol {
        Some(Degeneracy::CornerCorner)
    } else {
        None
    }
}

/// Outcome of contact detection at a given joint opening (spec §5.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactDetection {
    /// The decks close by `closing_distance = g − h ≥ 0` along y before the first-contact candidate touches.
    Contact {
        /// The first-contact candidate.
        case: ContactCase,
        /// Closing distance `g − h_first` \[m\].
        closing_distance: Real,
    },
    /// The stated pose already overlaps: `g < h_first` by `overlap = h_first − g > 0`.
    Overlap {
        /// The first-contact candidate.
        case: ContactCase,
        /// `h_first − g` \[m\].
        overlap: Real,
    },
    /// The pose is degenerate (spec §5.4), no single first contact.
    Degenerate(Degeneracy),
}
