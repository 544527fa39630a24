//! Impact configurations of two decks of **any** shape ([`DeckShape`]): the joint-anchored
//! placement of spec §5.2 generalised from the curved S arrangement, with the force directions
//! (spec §6) and the Delassus matrix (spec §7) from each deck's actual centroid and inertia.
//!
//! This is the one configuration path of the crate ([`configuration_with`]); the curved
//! [`SArrangement`] of the paper is its preset (two [`Deck`]s of common width) with the paper's
//! API kept as thin wrappers.
//!
//! # Placement **\[C\]**
//!
//! Every shape is given in its body frame (see [`shape`](crate::shape)): joint-face midpoint at the
//! origin, joint face on the x-axis with the corners `c0 = (w, 0)` and `c1 = (−w, 0)`, the deck in
//! `y > 0`. The face half-length is `w = W/2` for curved and straight decks and `w = W/(2 cos θ_s)`
//! for a skewed deck. For curved decks `c0` is the inner and `c1` the outer corner; for straight and
//! skewed decks `c0` is the acute and `c1` the obtuse corner, and the study calls them "inner"
//! and "outer" respectively ([`ContactCase`] names are kept).
//!
//! In the global frame of spec §4 a body point `p` of deck 1 is at `M_1 + Rot(θ1) p` with
//! `M_1 = (0, h)`, and a body point `p` of deck 2 at `Rot(θ2)(−p)` (deck 2 is its body frame turned
//! by π, then rotated by `θ2` about its own face midpoint `M_2 = (0, 0)`). So the curved
//! [`SArrangement`] is the special case `w1 = w2 = W/2` with the body centroids
//! `(R_j − X_j, Y_j)` (spec §5.3 table), computed by the same function.
//!
//! # What changes when the face half-lengths differ **\[M\]**
//!
//! With `w_a` the striking deck's half-length and `w_b` the struck deck's (`s_j = sin θ_j`,
//! `c_j = cos θ_j`, `s12 = sin(θ1 − θ2)`):
//!
//! | case | `h` | exact `σ_b` | end `σ_b` |
//! |---|---|---|---|
//! | deck1-inner | `−w1 s12/c2` | `+w1 c1/c2` | `+w2` |
//! | deck1-outer | `+w1 s12/c2` | `−w1 c1/c2` | `−w2` |
//! | deck2-inner | `+w2 s12/c1` | `+w2 c2/c1` | `+w1` |
//! | deck2-outer | `−w2 s12/c1` | `−w2 c2/c1` | `−w1` |
//!
//! (`h` and the exact σ use the striking corner's distance `w_a` from its face midpoint; the `end`
//! mode's face end is the struck face's `±w_b`.) `end_closes` is still `h > 0` (both corners of the
//! striking deck are `w_a` from `M_a`, so their `h` are opposite).
//!
//! **First contact.** Closing along y, a candidate is a real contact only if the corner lands on the
//! struck face *segment*, `|σ_exact| ≤ w_b`; beyond the face end the struck deck's outline turns
//! away from the joint (convex corner), so the corner meets nothing. Deck 1's corners land on deck
//! 2's face iff `w1 c1 ≤ w2 c2`, deck 2's on deck 1's iff `w2 c2 ≤ w1 c1`. Hence
//!
//! * the striking deck is the one with the **smaller** `w_a cos θ_a` (for `w1 = w2`: the larger
//!   `|θ|`, spec §5.4), and its corner with `h > 0` is the first contact;
//! * **parallel faces**: `θ1 = θ2` (unchanged);
//! * **corner meets corner**: `w1 cos θ1 = w2 cos θ2`, which for `w1 = w2` is `θ1 = −θ2` (spec §5.4)
//!   but for `w1 ≠ w2` is a different curve — at `θ1 = −θ2` the shorter face's corner lands strictly
//!   inside the longer face, a regular single impact.
//!
//! For `w1 = w2` (every pair the study builds: common width and common skew) the flags and
//! degeneracies are exactly those of spec §5.4 and are computed by the same functions
//! ([`is_first_contact`], [`degeneracy`]).

use crate::contact::{Delassus, delassus_with, force_directions};
use crate::geometry::{
    ContactCase, ContactDetection, DEGENERACY_TOLERANCE, DeckId, Degeneracy, GeometryError,
    ImpactConfiguration, MassProperties, ShapeParam, SigmaMode, degeneracy, is_first_contact,
};
use crate::math::{Real, Vector};
use crate::shape::{Deck, DeckEnd, DeckShape};

/// Two decks of any shape at a joint: deck 1 on `+y`, deck 2 (its body frame turned by π) on `−y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckPair {
    /// Deck 1 (body frame = the global frame translated by `M_1 = (0, h)`, rotated by `θ1`).
    pub deck1: DeckShape,
    /// Deck 2 (body frame turned by π about `M_2 = (0, 0)`, rotated by `θ2`).
    pub deck2: DeckShape,
}

/// Precomputed body data of one deck: joint-face half-length and mass properties.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairDeckData {
    /// Joint-face half-length `w = |c0|` \[m\].
    pub half_face: Real,
    /// Mass properties in the body frame (centroid relative to the joint-face midpoint).
    pub props: MassProperties,
}

impl DeckPair {
    /// A pair of validated shapes. Each joint face must be centred on its body origin
    /// (`c0 = (w, 0)`, `c1 = (−w, 0)`, true for every [`DeckShape`]); widths and skews may differ.
    pub fn new(deck1: DeckShape, deck2: DeckShape) -> Result<Self, GeometryError> {
        for (i, d) in [(1, &deck1), (2, &deck2)] {
            let f = d.end_face(DeckEnd::Joint);
            let [c0, c1] = f.corners;
            let w = c0.x;
            let tol = 1e-12 * w.abs().max(1.0);
            if !(w > 0.0 && c0.y.abs() <= tol && c1.y.abs() <= tol && (c1.x + w).abs() <= tol) {
                return Err(GeometryError::named(
                    &format!("deck{i}"),
                    w,
                    "the joint face must be centred on the body origin along +x",
                ));
            }
        }
        Ok(Self { deck1, deck2 })
    }

    /// Body data of deck `j`.
    pub fn data(&self, deck: DeckId) -> PairDeckData {
        let d = match deck {
            DeckId::One => &self.deck1,
            DeckId::Two => &self.deck2,
        };
        PairDeckData {
            half_face: d.end_face(DeckEnd::Joint).corners[0].x,
            props: d.mass_properties(),
        }
    }

    /// The impact configuration of `case` at `(θ1, θ2)` (module docs table), or the degeneracy
    /// ([`pair_degeneracy`]). Precondition: `|θ_j| < 90°`, finite.
    pub fn configuration(
        &self,
        case: ContactCase,
        theta1: Real,
        theta2: Real,
        sigma_mode: SigmaMode,
    ) -> Result<ImpactConfiguration, Degeneracy> {
        configuration_with(
            &self.data(DeckId::One),
            &self.data(DeckId::Two),
            case,
            theta1,
            theta2,
            sigma_mode,
        )
    }

    /// [`DeckPair::configuration`] and its [`DeckPair::delassus`] with the decks' body data
    /// computed once (the study's cell kernel: the same values, half the mass-property work).
    pub fn configuration_and_delassus(
        &self,
        case: ContactCase,
        theta1: Real,
        theta2: Real,
        sigma_mode: SigmaMode,
    ) -> Result<(ImpactConfiguration, Delassus), Degeneracy> {
        let (d1, d2) = (self.data(DeckId::One), self.data(DeckId::Two));
        let c = configuration_with(&d1, &d2, case, theta1, theta2, sigma_mode)?;
        let g = delassus_with(&d1.props, &d2.props, &force_directions(&c));
        Ok((c, g))
    }

    /// The Delassus matrix of `config` (spec §7) with each deck's own mass and inertia.
    pub fn delassus(&self, config: &ImpactConfiguration) -> Delassus {
        delassus_with(
            &self.deck1.mass_properties(),
            &self.deck2.mass_properties(),
            &force_directions(config),
        )
    }
}

/// The degeneracy of a pose with face half-lengths `w1`, `w2` (module docs): `θ1 = θ2` → parallel
/// faces; then, for `w1 = w2`, `θ1 = −θ2` → corner meets corner (exactly [`degeneracy`]); for
/// `w1 ≠ w2`, `|w1 cos θ1 − w2 cos θ2| ≤ 1e−12 · max(w1, w2)` → corner meets corner.
#[inline]
pub fn pair_degeneracy(w1: Real, w2: Real, theta1: Real, theta2: Real) -> Option<Degeneracy> {
    if w1 == w2 {
        degeneracy(theta1, theta2)
    } else {
        unequal_degeneracy(w1, w2, theta1, theta2)
    }
}

/// [`pair_degeneracy`] for `w1 ≠ w2` (kept out of line: the study's pairs have equal faces).
#[cold]
#[inline(never)]
fn unequal_degeneracy(w1: Real, w2: Real, theta1: Real, theta2: Real) -> Option<Degeneracy> {
    if (theta1 - theta2).abs() <= DEGENERACY_TOLERANCE {
        Some(Degeneracy::ParallelFaces)
    } else if (w1 * theta1.cos() - w2 * theta2.cos()).abs() <= 1e-12 * w1.max(w2) {
        Some(Degeneracy::CornerCorner)
    } else {
        None
    }
}

/// Whether `case` is the real first contact with face half-lengths `w1`, `w2` (module docs): the
/// striking deck has the smaller `w_a cos θ_a` and the candidate's `h > 0`. For `w1 = w2` this is
/// exactly [`is_first_contact`].
#[inline]
pub fn pair_first_contact(
    case: ContactCase,
    w1: Real,
    w2: Real,
    theta1: Real,
    theta2: Real,
) -> bool {
    if w1 == w2 {
        is_first_contact(case, theta1, theta2)
    } else {
        unequal_first_contact(case, w1, w2, theta1, theta2)
    }
}

/// [`pair_first_contact`] for `w1 ≠ w2` (out of line, see [`unequal_degeneracy`]).
#[cold]
#[inline(never)]
fn unequal_first_contact(
    case: ContactCase,
    w1: Real,
    w2: Real,
    theta1: Real,
    theta2: Real,
) -> bool {
    let (a1, a2) = (w1 * theta1.cos(), w2 * theta2.cos());
    let s12 = (theta1 - theta2).sin();
    match case {
        ContactCase::Deck1Inner => a1 < a2 && s12 < 0.0,
        ContactCase::Deck1Outer => a1 < a2 && s12 > 0.0,
        ContactCase::Deck2Inner => a2 < a1 && s12 > 0.0,
        ContactCase::Deck2Outer => a2 < a1 && s12 < 0.0,
    }
}

/// [`DeckPair::configuration`] from precomputed body data (the study's fast path).
#[inline(always)]
pub fn configuration_with(
    d1: &PairDeckData,
    d2: &PairDeckData,
    case: ContactCase,
    theta1: Real,
    theta2: Real,
    sigma_mode: SigmaMode,
) -> Result<ImpactConfiguration, Degeneracy> {
    let (w1, w2) = (d1.half_face, d2.half_face);
    if let Some(d) = pair_degeneracy(w1, w2, theta1, theta2) {
        return Err(d);
    }
    let (s1, c1) = theta1.sin_cos();
    let (s2, c2) = theta2.sin_cos();
    let s12 = s1 * c2 - c1 * s2; // sin(θ1 − θ2)
    // h, exact σ_b, the corner's body x (before deck 2's turn by π), end-mode σ_b.
    let (h, sigma_exact, corner_x, end_sigma) = match case {
        ContactCase::Deck1Inner => (-w1 * s12 / c2, w1 * c1 / c2, w1, w2),
        ContactCase::Deck1Outer => (w1 * s12 / c2, -w1 * c1 / c2, -w1, -w2),
        ContactCase::Deck2Inner => (w2 * s12 / c1, w2 * c2 / c1, -w2, w1),
        ContactCase::Deck2Outer => (-w2 * s12 / c1, -w2 * c2 / c1, w2, -w1),
    };
    let sigma = match sigma_mode {
        SigmaMode::Exact => sigma_exact,
        SigmaMode::End => end_sigma,
    };
    // M_1 = (0, h); body point p of deck 1 at M_1 + Rot(θ1) p, of deck 2 at Rot(θ2)(−p).
    let m1 = Vector::new(0.0, h);
    let (gb1, gb2) = (d1.props.centroid, d2.props.centroid);
    let g1 = m1 + rot_sc(s1, c1, gb1.x, gb1.y);
    let g2 = rot_sc(s2, c2, -gb2.x, -gb2.y);
    let (point, normal, tangent, struck_point) = match case.striking() {
        DeckId::One => {
            // corner of deck 1, face of deck 2 (e_2 = (+1, 0) turned by θ2)
            let p = m1 + rot_sc(s1, c1, corner_x, 0.0);
            let e = Vector::new(c2, s2);
            (p, Vector::new(-s2, c2), Vector::new(-c2, -s2), e * sigma)
        }
        DeckId::Two => {
            // corner of deck 2, face of deck 1 (e_1 = (−1, 0) turned by θ1)
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
    Ok(ImpactConfiguration {
        case,
        theta1,
        theta2,
        h,
        sigma,
        end_closes: h > 0.0,
        first_contact: pair_first_contact(case, w1, w2, theta1, theta2),
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

/// Two curved decks in the S arrangement (spec §4), the paper's preset of [`DeckPair`]. Both
/// share `W` and `ρ t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SArrangement {
    /// Deck 1 (on +y, centre of curvature at `M_1 + (R_1, 0)`).
    pub deck1: Deck,
    /// Deck 2 (on −y, centre of curvature at `M_2 + (−R_2, 0)`).
    pub deck2: Deck,
}

impl SArrangement {
    /// Validated arrangement (equal width and equal `ρ t`).
    pub fn new(deck1: Deck, deck2: Deck) -> Result<Self, GeometryError> {
        if deck1.width != deck2.width {
            return Err(GeometryError::invalid(
                ShapeParam::Width,
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
                ShapeParam::Thickness,
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
    /// Precondition: `|θ_j| < 90°` and finite (see [`validate_rotation`](crate::geometry::validate_rotation)); otherwise the numbers
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
        self.configuration_with(&p1, &p2, case, theta1, theta2, sigma_mode)
    }

    /// The same as [`configuration`](Self::configuration) with precomputed mass properties
    /// (saves two `sin` evaluations per call in tight loops): [`configuration_with`] with the face
    /// half-length `W/2` for both decks.
    #[inline]
    pub fn configuration_with(
        &self,
        props1: &MassProperties,
        props2: &MassProperties,
        case: ContactCase,
        theta1: Real,
        theta2: Real,
        sigma_mode: SigmaMode,
    ) -> Result<ImpactConfiguration, Degeneracy> {
        let w = 0.5 * self.width();
        let data = |props: &MassProperties| PairDeckData {
            half_face: w,
            props: *props,
        };
        configuration_with(
            &data(props1),
            &data(props2),
            case,
            theta1,
            theta2,
            sigma_mode,
        )
    }

    /// The pair of the two curved shapes (the general form of this preset).
    pub fn pair(&self) -> DeckPair {
        DeckPair {
            deck1: DeckShape::Curved(self.deck1),
            deck2: DeckShape::Curved(self.deck2),
        }
    }

    /// The Delassus matrix of `config` (spec §7), [`delassus_with`] with the decks' mass properties.
    pub fn delassus(&self, config: &ImpactConfiguration) -> Delassus {
        delassus_with(
            &self.deck1.mass_properties(),
            &self.deck2.mass_properties(),
            &force_directions(config),
        )
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

#[cfg(test)]
mod tests {
    use super::*;

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
