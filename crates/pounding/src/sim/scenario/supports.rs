//! `[ground_motion]` of a bridge whose supports move apart: wave passage (`v_app`,
//! `wave_direction_deg`) or a support-motion file per component (`supports_y`, `supports_x`),
//! checked against the bridge's support lines ([`crate::sim::excitation`]).

use super::Scenario;
use super::error::{ParamKey, ScenarioError, Section};
use crate::ground_motion::GroundMotion;
use crate::ground_motion::support_file::read_support_motions;
use crate::math::Vector;
use crate::output::float_token;
use crate::sim::excitation::{SupportExcitation, SupportRecord};

const fn ground(key: &'static str) -> ParamKey {
    ParamKey::new(Section::GroundMotion, key)
}

/// The keys of `[ground_motion]` that make the supports move apart (bridge files only).
const APART_KEYS: [&str; 4] = ["v_app", "wave_direction_deg", "supports_y", "supports_x"];

/// Refuses the support-motion keys in a two-deck file.
pub(in crate::sim::scenario) fn refuse_apart(sc: &Scenario) -> Result<(), ScenarioError> {
    let src = &sc.src;
    match APART_KEYS.iter().find(|k| src.is_set(ground(k))) {
        None => Ok(()),
        Some(k) => Err(src.key_error(
            format!(
                "{} is read only in bridge files ([[segment]] tables): a two-deck file's \
                 supports all move with its ground motion",
                src.at(ground(k))
            ),
            &[ground(k)],
        )),
    }
}

/// The supports' motion of `[ground_motion]` (`v_app`, `wave_direction_deg`, `supports_y`,
/// `supports_x`) on a bridge with support lines `ids`, and the reference ground motion: with
/// support-motion files, the `start` support's motion (instead of `record_y` / `record_x`).
pub(in crate::sim::scenario) fn build_supports(
    sc: &Scenario,
    ids: &[String],
    reference: GroundMotion,
) -> Result<(GroundMotion, SupportExcitation), ScenarioError> {
    let src = &sc.src;
    let g = &sc.raw.ground_motion;
    let files = [&g.supports_y, &g.supports_x];
    if files.iter().all(|f| f.is_none()) {
        let Some(v) = g.v_app else {
            if src.is_set(ground("wave_direction_deg")) {
                return Err(src.key_error(
                    format!(
                        "{} needs v_app (the apparent velocity of the wave)",
                        src.at(ground("wave_direction_deg"))
                    ),
                    &[ground("wave_direction_deg")],
                ));
            }
            return Ok((reference, SupportExcitation::Uniform));
        };
        if v.is_nan() || v <= 0.0 {
            return Err(src.invalid(
                format!(
                    "invalid v_app = {}: the apparent velocity must be > 0 m/s (inf: no wave passage)",
                    float_token(v)
                ),
                ground("v_app"),
            ));
        }
        let direction = match g.wave_direction_deg {
            None => None,
            Some(a) if a.is_finite() && a.abs() <= 360.0 => {
                Some(Vector::new(a.to_radians().cos(), a.to_radians().sin()))
            }
            Some(a) => {
                return Err(src.invalid(
                    format!(
                        "invalid wave_direction_deg = {}: must lie in [-360, 360]",
                        float_token(a)
                    ),
                    ground("wave_direction_deg"),
                ));
            }
        };
        return Ok((
            reference,
            SupportExcitation::WavePassage {
                v_app: v,
                direction,
            },
        ));
    }
    let read = |key: &'static str, spec: &Option<String>| -> Result<_, ScenarioError> {
        let Some(spec) = spec else { return Ok(None) };
        let path = src.dir.join(spec.trim());
        read_support_motions(&path)
            .map(|c| Some((path.display().to_string(), c)))
            .map_err(|error| ScenarioError::Record {
                at: src.at(ground(key)),
                error: Box::new(error),
            })
    };
    let cols = [
        read("supports_y", &g.supports_y)?,
        read("supports_x", &g.supports_x)?,
    ];
    let mut records = Vec::with_capacity(ids.len());
    for id in ids {
        let mut own = [None, None];
        for (k, (c, key)) in cols.iter().zip(["supports_y", "supports_x"]).enumerate() {
            let Some((file, c)) = c else { continue };
            let Some((_, r)) = c.iter().find(|(i, _)| i == id) else {
                return Err(src.key_error(
                    format!(
                        "{file} (named by {}) has no column for support `{id}` (the bridge's \
                         supports: {})",
                        src.at(ground(key)),
                        ids.join(", ")
                    ),
                    &[ground(key)],
                ));
            };
            own[k] = Some(r.clone());
        }
        let [along_y, along_x] = own;
        records.push(SupportRecord {
            id: id.clone(),
            ground: GroundMotion {
                along_y,
                along_x,
                ..reference.clone()
            },
        });
    }
    for (c, key) in cols.iter().zip(["supports_y", "supports_x"]) {
        let Some((file, c)) = c else { continue };
        if let Some((extra, _)) = c.iter().find(|(i, _)| !ids.contains(i)) {
            return Err(src.key_error(
                format!(
                    "{file} (named by {}) has a column `{extra}`, which is not a support of the \
                     bridge (its supports: {})",
                    src.at(ground(key)),
                    ids.join(", ")
                ),
                &[ground(key)],
            ));
        }
    }
    let start = records[0].ground.clone();
    Ok((start, SupportExcitation::Records(records)))
}

/// Refuses what cannot go with `supports_y` / `supports_x` (a record of the scenario's own,
/// wave passage, `record_dt`, `--record`, a batch) and an empty path; `Ok(false)` without them.
pub(in crate::sim::scenario) fn check_support_files(sc: &Scenario) -> Result<bool, ScenarioError> {
    let (src, g) = (&sc.src, &sc.raw.ground_motion);
    let files = [("supports_y", &g.supports_y), ("supports_x", &g.supports_x)];
    let Some(key) = files.iter().find(|(_, f)| f.is_some()).map(|(k, _)| *k) else {
        return Ok(false);
    };
    for (k, f) in files {
        if f.as_ref().is_some_and(|f| f.trim().is_empty()) {
            return Err(src.key_error(
                format!(
                    "{k} is empty at {}: give a support-motion file",
                    src.at(ground(k))
                ),
                &[ground(k)],
            ));
        }
    }
    // a motion per support: no record of its own, no wave passage on top
    let none = |v: &str| v.trim().eq_ignore_ascii_case("none");
    for k in [
        "v_app",
        "wave_direction_deg",
        "record_y",
        "record_x",
        "record_dt",
    ] {
        let empty = match k {
            "record_y" => none(&g.record_y),
            "record_x" => none(&g.record_x),
            _ => false,
        };
        if src.is_set(ground(k)) && !empty {
            return Err(src.key_error(
                format!(
                    "{} cannot be combined with {key} at {} (each support's motion is in the \
                     support-motion file)",
                    src.at(ground(k)),
                    src.at(ground(key))
                ),
                &[ground(k)],
            ));
        }
    }
    if sc.record.is_some() || sc.batch {
        return Err(src.key_error(
            format!(
                "{key} at {} gives every support its own motion: --record, --records and --set \
                 do not apply to such a file",
                src.at(ground(key))
            ),
            &[ground(key)],
        ));
    }
    Ok(true)
}

/// The support-motion files as written (`[supports_y, supports_x]`, `none` for a missing one):
/// what the outputs name as the records of a run with a motion per support.
pub(in crate::sim::scenario) fn support_files(sc: &Scenario) -> [String; 2] {
    let g = &sc.raw.ground_motion;
    [&g.supports_y, &g.supports_x].map(|f| f.clone().unwrap_or_else(|| "none".into()))
}

/// The supports' motion on `model` checked before any run (a wave too slow to cross the bridge
/// within the record, a support without a motion), the error naming the `[ground_motion]` key.
pub(in crate::sim::scenario) fn check_motion(
    sc: &Scenario,
    model: &crate::sim::bridge::BridgeModel,
    reference: &GroundMotion,
    supports: &SupportExcitation,
) -> Result<(), ScenarioError> {
    let key = match supports {
        SupportExcitation::Uniform => return Ok(()),
        SupportExcitation::WavePassage { .. } => "v_app",
        SupportExcitation::Records(_) => "supports_y",
    };
    crate::sim::excitation::SupportMotion::new(&model.support_lines(), reference, supports)
        .map(|_| ())
        .map_err(|e| {
            let src = &sc.src;
            src.invalid(e.to_string(), ground(key))
        })
}
