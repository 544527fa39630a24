//! The errors of geometric input: [`GeometryError`], the typed [`ShapeParam`] it names, and the
//! check of derived mass properties.

use crate::math::Real;
use thiserror::Error;

/// Which parameter of a deck shape a [`GeometryError`] concerns: a typed name, so that a front end
/// maps it to its own key (`R1`, `segment[2].beta_deg`, …) without reading the message.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ShapeParam {
    /// Centre-line radius `R` of a curved deck.
    Radius,
    /// Curve angle `β` of a curved deck.
    Angle,
    /// Axis length `L` of a straight or skewed deck.
    Length,
    /// Skew angle `θ_s` of a skewed deck.
    Skew,
    /// Width `W`.
    Width,
    /// Thickness `t`.
    Thickness,
    /// Density `ρ`.
    Density,
    /// The gap to an abutment.
    Gap,
    /// Any other parameter (its name is the error's `name`).
    Other,
}

impl ShapeParam {
    /// The parameter's name as the shapes know it (`R`, `beta`, `length`, `skew`, `width`,
    /// `thickness`, `density`, `gap`; `?` for [`ShapeParam::Other`]).
    pub const fn name(self) -> &'static str {
        match self {
            Self::Radius => "R",
            Self::Angle => "beta",
            Self::Length => "length",
            Self::Skew => "skew",
            Self::Width => "width",
            Self::Thickness => "thickness",
            Self::Density => "density",
            Self::Gap => "gap",
            Self::Other => "?",
        }
    }

    /// The name of deck `index`'s parameter: per-deck parameters take the deck's number (`R1`,
    /// `beta2`, `skew1`, `L2`); shared ones (`width`, `thickness`, `density`, …) keep their name.
    pub fn name_of_deck(self, index: usize) -> String {
        match self {
            Self::Radius | Self::Angle | Self::Skew => format!("{}{index}", self.name()),
            Self::Length => format!("L{index}"),
            _ => self.name().to_string(),
        }
    }
}

/// Invalid geometric input.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum GeometryError {
    /// A parameter is out of its valid range or not finite; the message names the parameter.
    #[error("invalid {name} = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// Parameter name as the user knows it (e.g. `R1`, `beta2`, `width`).
        name: String,
        /// The parameter, typed ([`ShapeParam::Other`] for names of no shape parameter).
        param: ShapeParam,
        /// The deck (1-based) it belongs to, when the caller said so ([`GeometryError::for_deck`]).
        deck: Option<usize>,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
}

impl GeometryError {
    /// An invalid shape parameter `param`.
    pub(crate) fn invalid(param: ShapeParam, value: Real, reason: &str) -> Self {
        Self::InvalidParameter {
            name: param.name().to_string(),
            param,
            deck: None,
            value,
            reason: reason.to_string(),
        }
    }

    /// An invalid parameter that is no shape parameter, known by its `name` only.
    pub(crate) fn named(name: &str, value: Real, reason: &str) -> Self {
        Self::InvalidParameter {
            name: name.to_string(),
            param: ShapeParam::Other,
            deck: None,
            value,
            reason: reason.to_string(),
        }
    }

    /// The same error of deck `index`: its `deck` is set and a per-deck parameter's name takes
    /// the deck's number ([`ShapeParam::name_of_deck`]: `R` → `R1`, `length` → `L2`).
    pub fn for_deck(self, index: usize) -> Self {
        match self {
            Self::InvalidParameter {
                name,
                param,
                value,
                reason,
                ..
            } => Self::InvalidParameter {
                name: match param {
                    ShapeParam::Other => name,
                    p => p.name_of_deck(index),
                },
                param,
                deck: Some(index),
                value,
                reason,
            },
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
    candidates: &[(ShapeParam, Real, Real)],
) -> Result<(), GeometryError> {
    if value.is_normal() && value > 0.0 {
        return Ok(());
    }
    let (name, reported, _) = candidates
        .iter()
        .copied()
        .max_by(|a, b| a.2.abs().ln().abs().total_cmp(&b.2.abs().ln().abs()))
        .unwrap_or((ShapeParam::Other, Real::NAN, 1.0));
    Err(GeometryError::invalid(
        name,
        reported,
        &format!(
            "the derived {quantity} = {value:e} is not a finite, positive, normal number (overflow or underflow); use a value of a physical magnitude"
        ),
    ))
}
