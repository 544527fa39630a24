//! The scenario key of a library error: [`sim_error`] maps the typed path every model, settings,
//! geometry and ground-motion error carries ([`crate::sim::param::ParamPath`], [`ShapeParam`],
//! [`MotionParam`]) to the two-deck key that sets the parameter, by matching it (no message is
//! read back).

use super::Src;
use super::error::{ParamKey, ScenarioError, Section};
use crate::geometry::{GeometryError, ShapeParam};
use crate::ground_motion::{GroundMotionError, MotionParam};
use crate::sim::SimError;
use crate::sim::param::{ParamPath, Setting, TwoDeckParam};

/// The `[time]` key `key`.
pub(super) const fn time(key: &'static str) -> ParamKey {
    ParamKey::new(Section::Time, key)
}

/// A library error located at the scenario key that sets the parameter it concerns (its typed
/// path, [`key_of_error`]).
pub(super) fn sim_error(src: &Src, e: SimError) -> ScenarioError {
    match key_of_error(src, &e) {
        Some(key) => src.invalid(e.to_string(), key),
        None => ScenarioError::Model(Box::new(e)),
    }
}

/// The two-deck scenario key that sets the parameter of a library error, from the error's typed
/// path ([`ParamPath`], [`ShapeParam`], [`MotionParam`]); `None` for parameters no key sets.
fn key_of_error(src: &Src, e: &SimError) -> Option<ParamKey> {
    use Section::{Abutments, Bearings, Decks, Joint};
    let of = ParamKey::of_deck;
    // the two keys of a per-deck parameter, by deck
    let per_deck = |section, keys: [&'static str; 2], deck: Option<u8>| match deck {
        Some(d @ (1 | 2)) => Some(of(section, keys[d as usize - 1], d)),
        _ => None,
    };
    match e {
        SimError::InvalidParameter { path, .. } | SimError::InvalidArgument { path, .. } => {
            match path {
                ParamPath::Setting(s) => Some(time(match s {
                    Setting::Dt => "dt",
                    Setting::Duration => "duration",
                    Setting::HistoryStride => "history_every",
                })),
                &ParamPath::TwoDeck { param, deck, .. } => match param {
                    TwoDeckParam::Gap => Some(ParamKey::new(Joint, "gap")),
                    TwoDeckParam::SeatLength => Some(ParamKey::new(Joint, "seat_length")),
                    TwoDeckParam::Mu => Some(ParamKey::new(Joint, "mu")),
                    TwoDeckParam::EpsN => Some(ParamKey::new(Joint, "eps_n")),
                    TwoDeckParam::DampingRatio => Some(ParamKey::new(Bearings, "damping_ratio")),
                    TwoDeckParam::Width | TwoDeckParam::JointFace => Some(ParamKey {
                        section: Decks,
                        key: "width",
                        deck,
                    }),
                    // a deck's mass is set by `massJ` when given, else derived from its density
                    TwoDeckParam::Mass => deck
                        .filter(|d| matches!(d, 1 | 2))
                        .map(|d| mass_key(src, d)),
                    TwoDeckParam::AbutmentGap => per_deck(Abutments, ["gap1", "gap2"], deck),
                    TwoDeckParam::AbutmentSeat => {
                        per_deck(Abutments, ["seat_length1", "seat_length2"], deck)
                    }
                    TwoDeckParam::BearingStiffness => {
                        per_deck(Bearings, ["stiffness1", "stiffness2"], deck)
                    }
                    TwoDeckParam::BearingPoint => per_deck(Bearings, ["points1", "points2"], deck),
                },
                _ => None,
            }
        }
        SimError::Geometry(GeometryError::InvalidParameter { param, deck, .. }) => {
            let deck = deck.and_then(|d| u8::try_from(d).ok());
            match param {
                ShapeParam::Radius => per_deck(Decks, ["R1", "R2"], deck),
                ShapeParam::Angle => per_deck(Decks, ["beta1_deg", "beta2_deg"], deck),
                ShapeParam::Length => per_deck(Decks, ["L1", "L2"], deck),
                ShapeParam::Skew => per_deck(Decks, ["skew_deg", "skew_deg"], deck),
                ShapeParam::Width => Some(ParamKey::new(Decks, "width")),
                ShapeParam::Thickness => Some(ParamKey::new(Decks, "thickness")),
                ShapeParam::Density => Some(ParamKey::new(Decks, "density")),
                ShapeParam::Gap => Some(ParamKey::new(Joint, "gap")),
                ShapeParam::Other => None,
            }
        }
        SimError::GroundMotion(GroundMotionError::InvalidParameter { param, .. }) => match param {
            MotionParam::ScaleY => Some(ParamKey::new(Section::GroundMotion, "scale_y")),
            MotionParam::ScaleX => Some(ParamKey::new(Section::GroundMotion, "scale_x")),
            MotionParam::Incidence => Some(ParamKey::new(Section::GroundMotion, "incidence_deg")),
            MotionParam::Other => None,
        },
        _ => None,
    }
}

/// [`sim_error`] for the model after `massJ` scaled the densities: a density that is no longer a
/// normal number comes from the mass given, not from `density`.
pub(super) fn scaled_mass_error(src: &Src, e: SimError) -> ScenarioError {
    let mut err = sim_error(src, e);
    if let ScenarioError::Invalid { at, .. } = &mut err
        && at.len() == 1
        && at[0]
            .key
            .param()
            .is_some_and(|k| k.section == Section::Decks && k.key == "density")
    {
        let given: Vec<_> = [1, 2]
            .into_iter()
            .map(|j| ParamKey::of_deck(Section::Decks, if j == 1 { "mass1" } else { "mass2" }, j))
            .filter(|&k| src.is_set(k))
            .map(|k| src.at(k))
            .collect();
        if !given.is_empty() {
            *at = given;
        }
    }
    err
}

fn mass_key(src: &Src, deck: u8) -> ParamKey {
    let key = ParamKey::of_deck(
        Section::Decks,
        if deck == 1 { "mass1" } else { "mass2" },
        deck,
    );
    if src.is_set(key) {
        key
    } else {
        ParamKey::of_deck(Section::Decks, "density", deck)
    }
}
