//! The skewed deck: the parallelogram whose two end faces are parallel to the x-axis (the joint
//! line) and whose axis is turned counter-clockwise by the skew angle `θ_s` from `+y`, in the
//! body frame of [`crate::shape`]: axis direction `e = (−sin θ_s, cos θ_s)`. `L` is the length
//! along the axis (distance between the end-face midpoints, also the length of the side edges),
//! `W` the width **perpendicular to the axis**; each end face is therefore `W / cos θ_s` long.
//!
//! Corners: `c0` is the **acute** corner (interior angle `90° − θ_s`), `c1` the **obtuse** one
//! (`90° + θ_s`), on both faces (diagonally opposite corners of a parallelogram are equal).
//! Joint face: `c0 = (W/(2c), 0)`, `c1 = (−W/(2c), 0)`, `n_out = (0, −1)`; far face:
//! `c0 = (−W/(2c), 0) + L e`, `c1 = (W/(2c), 0) + L e`, `n_out = (0, 1)` (`c = cos θ_s`).

use super::{DeckEnd, EndFace, Shape, positive};
use crate::analytic::ImpactLaw;
use crate::geometry::{GeometryError, MassProperties, ShapeParam, check_derived};
use crate::math::{Real, Vector};

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
        positive(ShapeParam::Length, length)?;
        positive(ShapeParam::Width, width)?;
        if !(skew.is_finite() && (0.0..std::f64::consts::FRAC_PI_2).contains(&skew)) {
            return Err(GeometryError::invalid(
                ShapeParam::Skew,
                skew.to_degrees(),
                "the skew angle must lie in [0, 90) degrees",
            ));
        }
        positive(ShapeParam::Thickness, thickness)?;
        positive(ShapeParam::Density, density)?;
        let deck = Self {
            length,
            width,
            skew,
            thickness,
            density,
        };
        deck.check_mass_properties()?;
        Ok(deck)
    }

    /// Area, mass and inertia must be finite, positive and normal; the error names the parameter
    /// that most likely overflowed or underflowed (`skew` when `1/cos θ_s` is extreme).
    pub(super) fn check_mass_properties(&self) -> Result<(), GeometryError> {
        let p = self.mass_properties();
        let (l, w, t, d) = (
            (ShapeParam::Length, self.length, self.length),
            (ShapeParam::Width, self.width, self.width),
            (ShapeParam::Thickness, self.thickness, self.thickness),
            (ShapeParam::Density, self.density, self.density),
        );
        let sk = (
            ShapeParam::Skew,
            self.skew.to_degrees(),
            1.0 / self.skew.cos(),
        );
        check_derived("area", p.area, &[l, w])?;
        check_derived("mass", p.mass, &[t, d, l, w])?;
        check_derived("inertia", p.inertia, &[l, w, sk, t, d])
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
    pub fn mass_properties(&self) -> MassProperties {
        let area = self.length * self.width;
        let mass = self.density * self.thickness * area;
        let a2 = self.face_length().powi(2);
        MassProperties {
            area,
            mass,
            centroid: 0.5 * self.length * self.axis(),
            inertia: mass * (self.length * self.length + a2) / 12.0,
        }
    }

    /// `sin 2θ_s > 2W/L`: the frictionless rotation condition for a purely longitudinal approach
    /// of the deck against an abutment with both corners of an end face striking (see
    /// [`frictionless_pivot`](super::frictionless_pivot)). Equivalent to `(L/2) sin θ_s > W/(2 cos θ_s)`: the foot of the
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

    /// The end face `end` (module docs).
    pub fn end_face(&self, end: DeckEnd) -> EndFace {
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

impl Shape for SkewedDeck {
    fn name(&self) -> &'static str {
        "skew"
    }

    fn width(&self) -> Real {
        self.width
    }

    fn skew(&self) -> Real {
        self.skew
    }

    fn length(&self) -> Option<Real> {
        Some(self.length)
    }

    fn mass_properties(&self) -> MassProperties {
        SkewedDeck::mass_properties(self)
    }

    fn end_face(&self, end: DeckEnd) -> EndFace {
        SkewedDeck::end_face(self, end)
    }

    /// `+e` through the far end, `−e` through the joint end.
    fn axis_direction(&self, end: DeckEnd) -> Vector {
        match end {
            DeckEnd::Far => self.axis(),
            DeckEnd::Joint => -self.axis(),
        }
    }

    fn corner_names(&self, _end: DeckEnd) -> [&'static str; 2] {
        ["acute", "obtuse"]
    }

    fn validate(&self) -> Result<(), GeometryError> {
        Self::new(
            self.length,
            self.width,
            self.skew,
            self.thickness,
            self.density,
        )
        .map(|_| ())
    }

    fn scale_density(&mut self, factor: Real) {
        self.density *= factor;
    }
}
