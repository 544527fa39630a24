//! The straight deck: the rectangle `[−W/2, W/2] × [0, L]` in the body frame of
//! [`crate::shape`], axis along `+y`. It is the skewed deck with `θ_s = 0`
//! ([`StraightDeck::as_skewed`]), from which it takes its mass properties and faces; its corners
//! are named `c0` (joint face: `(W/2, 0)`) and `c1`.

use super::{DeckEnd, EndFace, Shape, SkewedDeck, positive};
use crate::geometry::{GeometryError, MassProperties, ShapeParam};
use crate::math::{Real, Vector};

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
        positive(ShapeParam::Length, length)?;
        positive(ShapeParam::Width, width)?;
        positive(ShapeParam::Thickness, thickness)?;
        positive(ShapeParam::Density, density)?;
        let deck = Self {
            length,
            width,
            thickness,
            density,
        };
        deck.as_skewed().check_mass_properties()?;
        Ok(deck)
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

impl Shape for StraightDeck {
    fn name(&self) -> &'static str {
        "straight"
    }

    fn width(&self) -> Real {
        self.width
    }

    fn length(&self) -> Option<Real> {
        Some(self.length)
    }

    /// `A = LW`, `G = (0, L/2)`, `I = m (L² + W²)/12` (the skewed formulas at `θ_s = 0`).
    fn mass_properties(&self) -> MassProperties {
        self.as_skewed().mass_properties()
    }

    fn end_face(&self, end: DeckEnd) -> EndFace {
        self.as_skewed().end_face(end)
    }

    fn axis_direction(&self, end: DeckEnd) -> Vector {
        self.as_skewed().axis_direction(end)
    }

    fn corner_names(&self, _end: DeckEnd) -> [&'static str; 2] {
        ["c0", "c1"]
    }

    fn validate(&self) -> Result<(), GeometryError> {
        Self::new(self.length, self.width, self.thickness, self.density).map(|_| ())
    }

    fn scale_density(&mut self, factor: Real) {
        self.density *= factor;
    }
}
