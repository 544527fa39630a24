//! [`Scenario::build`]: the model, the ground motion and the settings from the sections, every
//! value validated with errors located at its key.
//!
//! `decks.rs` builds the two-deck model, `settings.rs` the `[time]` settings; the bridge form
//! (`super::bridge`) shares the ground and the settings.

mod decks;
mod settings;

use super::error::{ParamKey, ScenarioError, Section};
pub(super) use super::ground::build_ground;
use super::model_keys::scaled_mass_error;
pub(super) use super::model_keys::sim_error;
use super::{Scenario, SimSetup};
use crate::sim::SimProblem;
use decks::build_model;
pub(super) use settings::build_settings;

/// A deck whose bearings leave it free to slide or spin (lowest natural frequency zero, or below
/// `1e-6` of its highest: a singular bearing stiffness) is an error naming the deck and its
/// bearing key, unless `[bearings] allow_mechanism = true`.
fn check_mechanism(sc: &Scenario, frequencies: &[[f64; 3]; 2]) -> Result<(), ScenarioError> {
    let (src, b) = (&sc.src, &sc.raw.bearings);
    if b.allow_mechanism {
        return Ok(());
    }
    for (j, w) in frequencies.iter().enumerate() {
        if w[0] > 1e-6 * w[2] {
            continue;
        }
        let deck = j as u8 + 1;
        let name = if j == 0 { "points1" } else { "points2" };
        let pts = ParamKey::of_deck(Section::Bearings, name, deck);
        let key = if src.is_set(pts) {
            pts
        } else {
            ParamKey::of_deck(
                Section::Bearings,
                if j == 0 { "stiffness1" } else { "stiffness2" },
                deck,
            )
        };
        let allow = ParamKey::new(Section::Bearings, "allow_mechanism");
        return Err(src.key_error(
            format!(
                "deck{deck}: its bearings ({}) leave it free to slide or spin (a mechanism: a natural \
                 frequency of zero, a singular bearing stiffness); give bearings that hold it in x, y \
                 and rotation (at least two points, not all at one point), or set {} = true to \
                 simulate it anyway",
                src.at(key),
                allow
            ),
            &[key],
        ));
    }
    Ok(())
}

/// [`Scenario::build`].
pub(super) fn build(sc: &Scenario) -> Result<SimSetup, ScenarioError> {
    let src = &sc.src;
    let model = build_model(sc)?;
    super::supports::refuse_apart(sc)?;
    let (ground, records, units) = build_ground(sc)?;
    let bearings = model.bearings1.len() + model.bearings2.len();
    let size = crate::sim::options::RunSize {
        segments: 2,
        bearings,
    };
    let settings = build_settings(sc, &ground, &records, size, || {
        model.validate().map_err(|e| scaled_mass_error(src, e))?;
        let frequencies = model.check().map_err(|e| sim_error(src, e))?;
        check_mechanism(sc, &frequencies)
    })?;
    Ok(SimSetup {
        problem: SimProblem::at_rest(model, ground),
        settings,
        records,
        units,
    })
}
