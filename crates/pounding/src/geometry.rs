//! Annular-sector decks, mass properties, the S arrangement and impact configurations (spec §2–§5).
//!
//! Conventions (spec §4, §5): origin at the midpoint `M_2` of deck 2's joint face, x along the
//! joint line, y normal to the joint pointing into deck 1, counter-clockwise angles positive.
//! Deck 1 lies in `y > 0` with its centre of curvature at `M_1 + (R_1, 0)`, deck 2 in `y < 0` with
//! its centre at `M_2 + (−R_2, 0)`. Impact configurations use the *joint-anchored placement*
//! (spec §5.2): deck `j` is rotated by `θ_j` about its own face midpoint `M_j`; `M_2 = (0, 0)` stays
//! and deck 1 is moved along y to `M_1 = (0, h)` until the candidate corner lies on the struck face.

use crate::math::{Real, Vector};
use thiserror::Error;

/// Invalid geometric input.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum GeometryError {
    /// A parameter is out of its valid range or not finite; the message names the parameter.
    #[error("invalid {name} = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// Parameter name as the user knows it (e.g. `R1`, `beta2`, `width`).
        name: String,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
}

impl GeometryError {
    fn invalid(name: &str, value: Real, reason: &str) -> Self {
        Self::InvalidParameter {
            name: name.to_string(),
            value,
            reason: reason.to_string(),
        }
    }

    /// The same error with the deck index appended to per-deck parameter names
    /// (`R` → `R1`, `beta` → `beta2`); shared parameters (`width`, `thickness`, `density`) keep their name.
    pub fn for_deck(self, index: usize) -> Self {
        match self {
            Self::InvalidParameter {
                name,
                value,
                reason,
            } => {
                let name = if name == "R" || name == "beta" {
                    format!("{name}{index}")
                } else {
                    name
                };
                Self::InvalidParameter {
                    name,
                    value,
                    reason,
                }
            }
        }
    }
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
    /// A validated deck: all parameters finite, `W > 0`, `R > W/2`, `0 < β < 2π`, `t > 0`, `ρ > 0`.
    ///
    /// Errors name the parameter as `R`, `beta`, `width`, `thickness` or `density`; use
    /// [`GeometryError::for_deck`] to get the per-deck names `R1`, `beta2`, ….
    pub fn new(
        radius: Real,
        angle: Real,
        width: Real,
        thickness: Real,
        density: Real,
    ) -> Result<Self, GeometryError> {
        if !(width.is_finite() && width > 0.0) {
            return Err(GeometryError::invalid(
                "width",
                width,
                "must be finite and > 0",
            ));
        }
        if !(radius.is_finite() && radius > 0.5 * width) {
            return Err(GeometryError::invalid(
                "R",
                radius,
                &format!(
                    "the centre-line radius must be finite and > W/2 = {}",
                    0.5 * width
                ),
            ));
        }
        if !(angle.is_finite() && angle > 0.0 && angle < std::f64::consts::TAU) {
            return Err(GeometryError::invalid(
                "beta",
                angle,
                "the curve angle must lie in (0, 360) degrees",
            ));
        }
        if !(thickness.is_finite() && thickness > 0.0) {
            return Err(GeometryError::invalid(
                "thickness",
                thickness,
                "must be finite and > 0",
            ));
        }
        if !(density.is_finite() && density > 0.0) {
            return Err(GeometryError::invalid(
                "density",
                density,
                "must be finite and > 0",
            ));
        }
        let deck = Self {
            radius,
            angle,
            width,
            thickness,
            density,
        };
        let p = deck.mass_properties();
        let (r, b, w, t, d) = (
            ("R", radius, radius),
            ("beta", angle, angle),
            ("width", width, width),
            ("thickness", thickness, thickness),
            ("density", density, density),
        );
        check_derived("area", p.area, &[r, b, w])?;
        check_derived("mass", p.mass, &[t, d, r, b, w])?;
        check_derived("inertia", p.inertia, &[r, w, b, t, d])?;
        Ok(deck)
    }

    /// Mass properties (spec §3), with `ρ t` = `density · thickness`:
    ///
    /// * `A = β R W`, `m = ρ t A`;
    /// * `r_c = (R + W²/(12 R)) · sin(β/2)/(β/2)` (centroid distance from the centre of curvature);
    /// * `X_m = r_c cos(β/2)`, `Y_m = r_c sin(β/2)`;
    /// * `I = m (R² + W²/4 − r_c²)` (polar moment about the centroid).
    pub fn mass_properties(&self) -> MassProperties {
        let (r, w, b) = (self.radius, self.width, self.angle);
        let area = b * r * w;
        let mass = self.density * self.thickness * area;
        let half = 0.5 * b;
        let (s, c) = half.sin_cos();
        let rc = (r + w * w / (12.0 * r)) * s / half;
        let inertia = mass * (r * r + 0.25 * w * w - rc * rc);
        MassProperties {
            area,
            mass,
            centroid_radius: rc,
            x_m: rc * c,
            y_m: rc * s,
            inertia,
        }
    }
}

/// Checks a derived mass property (`area`, `mass`, `inertia`): it must be a finite, positive,
/// normal (not subnormal) number. Otherwise the error names the parameter most likely to have
/// caused the overflow or underflow: among `candidates` `(name, reported value, magnitude)`, the
/// one whose magnitude is farthest from 1 on a log scale.
pub(crate) fn check_derived(
    quantity: &str,
    value: Real,
    candidates: &[(&str, Real, Real)],
) -> Result<(), GeometryError> {
    if value.is_normal() && value > 0.0 {
        return Ok(());
    }
    let (name, reported, _) = candidates
        .iter()
        .copied()
        .max_by(|a, b| a.2.abs().ln().abs().total_cmp(&b.2.abs().ln().abs()))
        .unwrap_or(("?", Real::NAN, 1.0));
    Err(GeometryError::invalid(
        name,
        reported,
        &format!(
            "the derived {quantity} = {value:e} is not a finite, positive, normal number (overflow or underflow); use a value of a physical magnitude"
        ),
    ))
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
        Err(GeometryError::invalid(
            &format!("{name} [deg]"),
            theta.to_degrees(),
            "the rotation must be finite with |theta| < 90 degrees",
        ))
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
    if (theta1 - theta2).abs() <= DEGENERACY_TOLERANCE {
        Some(Degeneracy::ParallelFaces)
    } else if (theta1 + theta2).abs() <= DEGENERACY_TOLERANCE {
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

impl SArrangement {
    /// Validated arrangement (equal width and equal `ρ t`).
    pub fn new(deck1: Deck, deck2: Deck) -> Result<Self, GeometryError> {
        if deck1.width != deck2.width {
            return Err(GeometryError::invalid(
                "width",
                deck2.width,
                &format!(
                    "both decks must share the width (deck 1 has {})",
                    deck1.width
                ),
            ));
        }
        let rt1 = deck1.density * deck1.thickness;
        let rt2 = deck2.density * deck2.thickness;
        if (rt1 - rt2).abs() > 1e-12 * rt1.abs().max(rt2.abs()) {
            return Err(GeometryError::invalid(
                "thickness",
                deck2.thickness,
                &format!("both decks must share density*thickness (deck 1: {rt1}, deck 2: {rt2})"),
            ));
        }
        Ok(Self { deck1, deck2 })
    }

    /// The common width `W`.
    pub fn width(&self) -> Real {
        self.deck1.width
    }

    /// The impact configuration of `case` at `(θ1, θ2)`, or the degeneracy when `θ1 = ±θ2`
    /// (within [`DEGENERACY_TOLERANCE`]).
    ///
    /// Closed forms (spec §5.3), with `W/2 =: w`:
    ///
    /// | case | `h` | `σ_b` |
    /// |---|---|---|
    /// | deck1-inner | `−w sin(θ1−θ2)/cos θ2` | `+w cos θ1/cos θ2` |
    /// | deck1-outer | `+w sin(θ1−θ2)/cos θ2` | `−w cos θ1/cos θ2` |
    /// | deck2-inner | `+w sin(θ1−θ2)/cos θ1` | `+w cos θ2/cos θ1` |
    /// | deck2-outer | `−w sin(θ1−θ2)/cos θ1` | `−w cos θ2/cos θ1` |
    ///
    /// `ν = (−sin θ_b, cos θ_b)`, `τ = (−cos θ_b, −sin θ_b)`; in the `end` mode `σ_b = ±w`.
    /// Precondition: `|θ_j| < 90°` and finite (see [`validate_rotation`]); otherwise the numbers
    /// are meaningless.
    pub fn configuration(
        &self,
        case: ContactCase,
        theta1: Real,
        theta2: Real,
        sigma_mode: SigmaMode,
    ) -> Result<ImpactConfiguration, Degeneracy> {
        let p1 = self.deck1.mass_properties();
        let p2 = self.deck2.mass_properties();
        configuration_with(self, &p1, &p2, case, theta1, theta2, sigma_mode)
    }

    /// The same as [`configuration`](Self::configuration) with precomputed mass properties
    /// (saves two `sin` evaluations per call in tight loops).
    pub fn configuration_with(
        &self,
        props1: &MassProperties,
        props2: &MassProperties,
        case: ContactCase,
        theta1: Real,
        theta2: Real,
        sigma_mode: SigmaMode,
    ) -> Result<ImpactConfiguration, Degeneracy> {
        configuration_with(self, props1, props2, case, theta1, theta2, sigma_mode)
    }

    /// Contact detection at joint opening `g` (spec §5.5): decks placed with `M_1 = (0, g)`,
    /// `M_2 = (0, 0)`; the first contact under closing along y is the first-contact candidate,
    /// reached after `g − h_first`.
    pub fn detect_contact(&self, theta1: Real, theta2: Real, opening: Real) -> ContactDetection {
        if let Some(d) = degeneracy(theta1, theta2) {
            return ContactDetection::Degenerate(d);
        }
        let case = ContactCase::ALL
            .into_iter()
            .find(|&c| is_first_contact(c, theta1, theta2))
            .expect("off the diagonals exactly one candidate is the first contact");
        let h = closing_h(self.width(), case, theta1, theta2);
        if opening >= h {
            ContactDetection::Contact {
                case,
                closing_distance: opening - h,
            }
        } else {
            ContactDetection::Overlap {
                case,
                overlap: h - opening,
            }
        }
    }
}

/// `h` of a case (spec §5.3 table).
fn closing_h(width: Real, case: ContactCase, theta1: Real, theta2: Real) -> Real {
    let w = 0.5 * width;
    let (s1, c1) = theta1.sin_cos();
    let (s2, c2) = theta2.sin_cos();
    let s12 = s1 * c2 - c1 * s2;
    match case {
        ContactCase::Deck1Inner => -w * s12 / c2,
        ContactCase::Deck1Outer => w * s12 / c2,
        ContactCase::Deck2Inner => w * s12 / c1,
        ContactCase::Deck2Outer => -w * s12 / c1,
    }
}

#[inline]
fn configuration_with(
    arr: &SArrangement,
    p1: &MassProperties,
    p2: &MassProperties,
    case: ContactCase,
    theta1: Real,
    theta2: Real,
    sigma_mode: SigmaMode,
) -> Result<ImpactConfiguration, Degeneracy> {
    if let Some(d) = degeneracy(theta1, theta2) {
        return Err(d);
    }
    let w = 0.5 * arr.width();
    let (s1, c1) = theta1.sin_cos();
    let (s2, c2) = theta2.sin_cos();
    let s12 = s1 * c2 - c1 * s2; // sin(θ1 − θ2)
    // h, exact σ_b, the corner in its own deck's reference frame relative to M_a.
    let (h, sigma_exact, corner_x, end_sigma) = match case {
        ContactCase::Deck1Inner => (-w * s12 / c2, w * c1 / c2, w, w),
        ContactCase::Deck1Outer => (w * s12 / c2, -w * c1 / c2, -w, -w),
        ContactCase::Deck2Inner => (w * s12 / c1, w * c2 / c1, -w, w),
        ContactCase::Deck2Outer => (-w * s12 / c1, -w * c2 / c1, w, -w),
    };
    let sigma = match sigma_mode {
        SigmaMode::Exact => sigma_exact,
        SigmaMode::End => end_sigma,
    };
    let m1 = Vector::new(0.0, h);
    // Centroids: G_1 = M_1 + Rot(θ1)(R1 − X1, Y1), G_2 = Rot(θ2)(−R2 + X2, −Y2).
    let g1 = m1 + rot_sc(s1, c1, arr.deck1.radius - p1.x_m, p1.y_m);
    let g2 = rot_sc(s2, c2, -arr.deck2.radius + p2.x_m, -p2.y_m);
    let (point, normal, tangent, struck_point) = match case.striking() {
        DeckId::One => {
            // corner of deck 1, face of deck 2 (e_2 = (+1, 0))
            let p = m1 + rot_sc(s1, c1, corner_x, 0.0);
            let e = Vector::new(c2, s2);
            (p, Vector::new(-s2, c2), Vector::new(-c2, -s2), e * sigma)
        }
        DeckId::Two => {
            // corner of deck 2, face of deck 1 (e_1 = (−1, 0))
            let p = rot_sc(s2, c2, corner_x, 0.0);
            let e = Vector::new(-c1, -s1);
            (
                p,
                Vector::new(-s1, c1),
                Vector::new(-c1, -s1),
                m1 + e * sigma,
            )
        }
    };
    let end_closes = h > 0.0;
    Ok(ImpactConfiguration {
        case,
        theta1,
        theta2,
        h,
        sigma,
        end_closes,
        first_contact: is_first_contact(case, theta1, theta2),
        point,
        normal,
        tangent,
        centroid1: g1,
        centroid2: g2,
        sigma_mode,
        sigma_exact,
        struck_point,
        face_mid1: m1,
    })
}

/// `Rot(θ)(x, y)` from precomputed `sin θ`, `cos θ`.
#[inline]
fn rot_sc(s: Real, c: Real, x: Real, y: Real) -> Vector {
    Vector::new(c * x - s * y, s * x + c * y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deck_validation_names_parameters() {
        let e = Deck::new(5.0, 1.0, 10.0, 1.0, 1.0).unwrap_err();
        assert!(e.clone().for_deck(1).to_string().contains("R1"), "{e}");
        let e = Deck::new(100.0, 7.0, 10.0, 1.0, 1.0).unwrap_err();
        assert!(e.for_deck(2).to_string().contains("beta2"));
        let e = Deck::new(100.0, 1.0, 10.0, f64::NAN, 1.0).unwrap_err();
        assert!(e.to_string().contains("thickness"));
        assert!(Deck::new(100.0, 1.0, 10.0, 1.0, -1.0).is_err());
        assert!(Deck::new(100.0, 0.0, 10.0, 1.0, 1.0).is_err());
    }

    #[test]
    fn degeneracies() {
        let d = Deck::new(100.0, 1.0, 10.0, 1.0, 1.0).unwrap();
        let s = SArrangement::new(d, d).unwrap();
        assert_eq!(
            s.configuration(ContactCase::Deck1Inner, 0.1, 0.1, SigmaMode::Exact),
            Err(Degeneracy::ParallelFaces)
        );
        assert_eq!(
            s.configuration(ContactCase::Deck1Inner, 0.1, -0.1, SigmaMode::Exact),
            Err(Degeneracy::CornerCorner)
        );
        assert_eq!(degeneracy(0.0, 0.0), Some(Degeneracy::ParallelFaces));
    }
}
