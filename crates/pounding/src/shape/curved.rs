//! The curved deck (spec §2–§3): an annular sector of centre-line radius `R`, width `W` and curve
//! angle `β`, in the body frame of [`crate::shape`]: body points `(R − r cos φ, r sin φ)` with
//! `r ∈ [R − W/2, R + W/2]`, `φ ∈ [0, β]` (spec §4, deck 1).
//!
//! Corners: joint face `c0` = inner `(W/2, 0)`, `c1` = outer `(−W/2, 0)`, `n_out = (0, −1)`; far
//! face (the radial face at `φ = β`) `c0` = outer, `c1` = inner, `n_out = (sin β, cos β)`. All four
//! interior angles are right angles.

use super::{DeckEnd, EndFace, Shape};
use crate::geometry::{GeometryError, MassProperties, ShapeParam, check_derived};
use crate::math::{Real, Vector};

/// A curved deck: the plane annular sector of centre-line radius `radius` spanning `angle` (spec §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Deck {
    /// Centre-line radius `R` \[m\]; requires `R > W/2`. The centre of curvature is at `(R, 0)` in
    /// the body frame (to the **right** of the joint-face midpoint, so `c0 = (W/2, 0)` is the inner
    /// corner); in the S arrangement deck 2's is at `(−R_2, 0)` (spec §4).
    pub radius: Real,
    /// Subtended (curve) angle `β` \[rad\], `0 < β < 2π`, measured counter-clockwise about the centre
    /// of curvature from the joint face (`φ = 0`) to the far face (`φ = β`).
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
                ShapeParam::Width,
                width,
                "must be finite and > 0",
            ));
        }
        if !(radius.is_finite() && radius > 0.5 * width) {
            return Err(GeometryError::invalid(
                ShapeParam::Radius,
                radius,
                &format!(
                    "the centre-line radius must be finite and > W/2 = {}",
                    0.5 * width
                ),
            ));
        }
        if !(angle.is_finite() && angle > 0.0 && angle < std::f64::consts::TAU) {
            return Err(GeometryError::invalid(
                ShapeParam::Angle,
                angle,
                "the curve angle must lie in (0, 360) degrees",
            ));
        }
        if !(thickness.is_finite() && thickness > 0.0) {
            return Err(GeometryError::invalid(
                ShapeParam::Thickness,
                thickness,
                "must be finite and > 0",
            ));
        }
        if !(density.is_finite() && density > 0.0) {
            return Err(GeometryError::invalid(
                ShapeParam::Density,
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
            (ShapeParam::Radius, radius, radius),
            (ShapeParam::Angle, angle, angle),
            (ShapeParam::Width, width, width),
            (ShapeParam::Thickness, thickness, thickness),
            (ShapeParam::Density, density, density),
        );
        check_derived("area", p.area, &[r, b, w])?;
        check_derived("mass", p.mass, &[t, d, r, b, w])?;
        check_derived("inertia", p.inertia, &[r, w, b, t, d])?;
        Ok(deck)
    }

    /// The sector's centroid in its polar description (spec §3):
    /// `r_c = (R + W²/(12 R)) · sin(β/2)/(β/2)`, `X_m = r_c cos(β/2)`, `Y_m = r_c sin(β/2)`.
    pub fn sector_centroid(&self) -> SectorCentroid {
        let (r, w, b) = (self.radius, self.width, self.angle);
        let half = 0.5 * b;
        let (s, c) = half.sin_cos();
        let rc = (r + w * w / (12.0 * r)) * s / half;
        SectorCentroid {
            centroid_radius: rc,
            x_m: rc * c,
            y_m: rc * s,
        }
    }

    /// Mass properties (spec §3), with `ρ t` = `density · thickness`:
    ///
    /// * `A = β R W`, `m = ρ t A`;
    /// * centroid `G = (R − X_m, Y_m)` in the body frame ([`Deck::sector_centroid`]);
    /// * `I = m (R² + W²/4 − r_c²)` (polar moment about the centroid).
    pub fn mass_properties(&self) -> MassProperties {
        let (r, w, b) = (self.radius, self.width, self.angle);
        let area = b * r * w;
        let mass = self.density * self.thickness * area;
        let sc = self.sector_centroid();
        let rc = sc.centroid_radius;
        MassProperties {
            area,
            mass,
            centroid: Vector::new(r - sc.x_m, sc.y_m),
            inertia: mass * (r * r + 0.25 * w * w - rc * rc),
        }
    }
}

/// The centroid of an annular sector in the polar description of spec §3 (measured from the
/// centre of curvature and the joint-face line), as the paper tabulates it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectorCentroid {
    /// Distance of the centroid from the centre of curvature `r_c` \[m\].
    pub centroid_radius: Real,
    /// `X_m = r_c cos(β/2)`: centroid coordinate along the face line from the centre \[m\].
    pub x_m: Real,
    /// `Y_m = r_c sin(β/2)`: centroid distance from the face line \[m\].
    pub y_m: Real,
}

impl Shape for Deck {
    fn name(&self) -> &'static str {
        "curved"
    }

    fn width(&self) -> Real {
        self.width
    }

    fn length(&self) -> Option<Real> {
        None
    }

    fn mass_properties(&self) -> MassProperties {
        Deck::mass_properties(self)
    }

    fn end_face(&self, end: DeckEnd) -> EndFace {
        let (r, w) = (self.radius, self.width);
        match end {
            DeckEnd::Joint => EndFace {
                corners: [Vector::new(0.5 * w, 0.0), Vector::new(-0.5 * w, 0.0)],
                outward_normal: Vector::new(0.0, -1.0),
            },
            DeckEnd::Far => {
                let (s, c) = self.angle.sin_cos();
                let at = |rr: Real| Vector::new(r - rr * c, rr * s);
                EndFace {
                    corners: [at(r + 0.5 * w), at(r - 0.5 * w)],
                    outward_normal: Vector::new(s, c),
                }
            }
        }
    }

    /// The end face's outward normal: the centre line meets the radial faces at right angles.
    fn axis_direction(&self, end: DeckEnd) -> Vector {
        self.end_face(end).outward_normal
    }

    fn corner_names(&self, end: DeckEnd) -> [&'static str; 2] {
        match end {
            DeckEnd::Joint => ["inner", "outer"],
            DeckEnd::Far => ["outer", "inner"],
        }
    }

    fn validate(&self) -> Result<(), GeometryError> {
        Deck::new(
            self.radius,
            self.angle,
            self.width,
            self.thickness,
            self.density,
        )
        .map(|_| ())
    }

    fn scale_density(&mut self, factor: Real) {
        self.density *= factor;
    }
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
}
