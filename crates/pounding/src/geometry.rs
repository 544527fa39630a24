//! Annular-sector decks, mass properties, the S arrangement and impact configurations (spec §2–§5).
//!
//! CONTRACT (skeleton; the single-impact work item replaces every `todo!()`, may add items and
//! fields, but keeps these names and signatures so that `study` can build on them).

use crate::math::{Real, Vector};
use thiserror::Error;

/// Invalid geometric input.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum GeometryError {
    /// A parameter is out of its valid range or not finite; the message names the parameter.
    #[error("invalid {name} = {value}: {reason}")]
    InvalidParameter {
        /// Parameter name as the user knows it (e.g. `R1`, `beta2`, `width`).
        name: String,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
}

/// One deck: the plane annular sector of centre-line radius `radius` spanning `angle` (spec §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Deck {
    /// Centre-line radius `R` \[m\]; requires `R > W/2`.
    pub radius: Real,
    /// Subtended (curve) angle `β` \[rad\], `0 < β < 2π`.
    pub angle: Real,
    /// Width `W` \[m\] (radial extent), `> 0`.
    pub width: Real,
    /// Thickness `t` \[m\], `> 0`.
    pub thickness: Real,
    /// Density `ρ` \[kg/m³\], `> 0`.
    pub density: Real,
}

impl Deck {
    /// A validated deck. `name` prefixes parameter names in errors (e.g. `"deck 1"` → `R1`-style messages).
    pub fn new(
        radius: Real,
        angle: Real,
        width: Real,
        thickness: Real,
        density: Real,
    ) -> Result<Self, GeometryError> {
        let _ = (radius, angle, width, thickness, density);
        todo!("single-impact work item")
    }
    /// Mass properties (spec §3).
    pub fn mass_properties(&self) -> MassProperties {
        todo!("single-impact work item")
    }
}

/// Mass properties of one deck (spec §3), a value type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    /// Plan area `A = β R W` \[m²\].
    pub area: Real,
    /// Mass `m = ρ t A` \[kg\].
    pub mass: Real,
    /// Distance of the centroid from the centre of curvature `r_c` \[m\].
    pub centroid_radius: Real,
    /// `X_m = r_c cos(β/2)`: centroid coordinate along the face line from the centre \[m\].
    pub x_m: Real,
    /// `Y_m = r_c sin(β/2)`: centroid distance from the face line \[m\].
    pub y_m: Real,
    /// Polar moment about the centroid `I = m (R² + W²/4 − r_c²)` \[kg m²\].
    pub inertia: Real,
}

/// Which deck.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DeckId {
    /// Deck 1 (in `y > 0`).
    One,
    /// Deck 2 (in `y < 0`).
    Two,
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

/// Two decks in the S arrangement (spec §4). Both share `W` and `ρ t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SArrangement {
    /// Deck 1 (on +y, centre of curvature at `M_1 + (R_1, 0)`).
    pub deck1: Deck,
    /// Deck 2 (on −y, centre of curvature at `M_2 + (−R_2, 0)`).
    pub deck2: Deck,
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
    /// Contact point `C` (global frame).
    pub point: Vector,
    /// Unit normal `ν` (from the deck-2 side to the deck-1 side).
    pub normal: Vector,
    /// Unit tangent `τ` (toward deck 1's radially outward side).
    pub tangent: Vector,
    /// Centroid of deck 1 in this pose.
    pub centroid1: Vector,
    /// Centroid of deck 2 in this pose.
    pub centroid2: Vector,
}

impl SArrangement {
    /// Validated arrangement (equal width and equal `ρ t`).
    pub fn new(deck1: Deck, deck2: Deck) -> Result<Self, GeometryError> {
        let _ = (deck1, deck2);
        todo!("single-impact work item")
    }
    /// The impact configuration of `case` at `(θ1, θ2)`, or the degeneracy when `θ1 = ±θ2`.
    pub fn configuration(
        &self,
        case: ContactCase,
        theta1: Real,
        theta2: Real,
        sigma_mode: SigmaMode,
    ) -> Result<ImpactConfiguration, Degeneracy> {
        let _ = (case, theta1, theta2, sigma_mode);
        todo!("single-impact work item")
    }
}
