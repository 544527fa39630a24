//! The errors of the bridge a two-deck model expands into ([`BridgeModel::from_pair`]) under
//! the two-deck names: `segment[i]` is deck `i + 1`, `joint[0]` the joint, `abutment.start` /
//! `abutment.end` the abutments beyond deck 1 / deck 2, so that a scenario front end locates
//! them at its own keys (`[bearings] points1`, `[joint] gap`, …).
//!
//! [`BridgeModel::from_pair`]: super::bridge::BridgeModel::from_pair

use super::SimError;
use super::bridge::BridgeModel;
use super::options::DampingModel;
use super::param::{BridgeKey, BridgeTable, ParamPath, TwoDeckParam};
use crate::math::{Real, Vector};

/// The two-deck parameter of a bridge key of the expansion (`None`: the expansion has no such
/// key, e.g. a restrainer or a pier).
pub(crate) fn two_deck_path(key: &BridgeKey) -> Option<ParamPath> {
    use TwoDeckParam as P;
    let leaf = key.leaf();
    Some(match key.table {
        BridgeTable::Segment(i @ 0..=1) => {
            let deck = i as u8 + 1;
            match leaf {
                "mass" => ParamPath::deck(P::Mass, deck),
                "width" => ParamPath::deck(P::JointFace, deck),
                "bearings" => ParamPath::pair(P::DampingRatio),
                "bearing_points" => ParamPath::deck(P::BearingPoint, deck),
                "stiffness" => {
                    // `bearing[b].stiffness`, b 0-based
                    let b = key.key.strip_prefix("bearing[")?.split(']').next()?;
                    ParamPath::TwoDeck {
                        param: P::BearingStiffness,
                        deck: Some(deck),
                        bearing: Some(b.parse::<usize>().ok()? + 1),
                    }
                }
                _ => return None,
            }
        }
        BridgeTable::Joint(0) => match leaf {
            "gap" => ParamPath::pair(P::Gap),
            "mu" => ParamPath::pair(P::Mu),
            "eps_n" => ParamPath::pair(P::EpsN),
            "seat_length" => ParamPath::pair(P::SeatLength),
            "width" => ParamPath::deck(P::JointFace, 2),
            _ => return None,
        },
        BridgeTable::Abutment(s @ 0..=1) => match leaf {
            "gap" => ParamPath::deck(P::AbutmentGap, s as u8 + 1),
            "seat_length" => ParamPath::deck(P::AbutmentSeat, s as u8 + 1),
            "mu" => ParamPath::pair(P::Mu),
            "eps_n" => ParamPath::pair(P::EpsN),
            _ => return None,
        },
        BridgeTable::Bridge => match leaf {
            "outer_seat_length" => ParamPath::pair(P::SeatLength),
            "damping_ratio" => ParamPath::pair(P::DampingRatio),
            _ => return None,
        },
        _ => return None,
    })
}

/// `e`, an error of `bridge` (the expansion of a two-deck model with Rayleigh ratio
/// `damping_ratio` and bearing `point(deck, b)`, both 0-based), under the two-deck names: the
/// path [`two_deck_path`], the message in terms of decks. An error of a key the expansion does
/// not have is returned as it is.
pub(crate) fn pair_error(
    damping_ratio: Real,
    point: &dyn Fn(usize, usize) -> Option<Vector>,
    bridge: &BridgeModel,
    e: SimError,
) -> SimError {
    let Some(ParamPath::Bridge(key)) = e.path().cloned() else {
        return e;
    };
    let Some(path) = two_deck_path(&key) else {
        return e;
    };
    let deck = match key.table {
        BridgeTable::Segment(i) => i + 1,
        _ => 0,
    };
    match (key.leaf(), e) {
        ("mass", SimError::InvalidParameter { value, .. }) => SimError::invalid(
            path,
            value,
            "the bearing stiffness over this mass (or inertia) overflows; use physical magnitudes",
        ),
        ("bearings", _) => SimError::invalid(
            path,
            damping_ratio,
            &format!(
                "deck {deck} has no bearing stiffness (every bearing's stiffness is 0), so Rayleigh \
                 damping at its natural frequencies is undefined; set damping_ratio = 0 or damping \
                 = \"dashpots\", or give the deck bearing stiffness"
            ),
        ),
        ("bearing_points", _) => {
            let (seg, b) = bridge.bearing_outside().unwrap_or((deck - 1, 0));
            let p = point(seg, b).unwrap_or_default();
            SimError::argument(
                ParamPath::TwoDeck {
                    param: TwoDeckParam::BearingPoint,
                    deck: Some(seg as u8 + 1),
                    bearing: Some(b + 1),
                },
                format!(
                    "bearing {} at ({}, {}) m lies outside deck {} (points are relative to the \
                     deck's joint-face midpoint, reference pose)",
                    b + 1,
                    crate::output::float_token(p.x),
                    crate::output::float_token(p.y),
                    seg + 1
                ),
            )
        }
        (_, SimError::InvalidParameter { value, reason, .. }) => {
            SimError::invalid(path, value, &reason)
        }
        (_, SimError::InvalidArgument { reason, .. }) => SimError::argument(
            path,
            if deck > 0 {
                reason.replace(&format!("segment[{}]", deck - 1), &format!("deck {deck}"))
            } else {
                reason
            },
        ),
        (_, e) => e,
    }
}

/// Whether the expansion's damping needs natural frequencies (Rayleigh); dashpots do not.
pub(crate) fn needs_frequencies(model: DampingModel) -> bool {
    matches!(model, DampingModel::Rayleigh)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every bridge key the two-deck expansion can fail on has a two-deck path, and keys the
    /// expansion never has (restrainers, piers, a third segment) have none.
    #[test]
    fn every_expansion_key_has_a_two_deck_path() {
        let keys = [
            (BridgeTable::Segment(0), "mass", "mass (deck 1)"),
            (BridgeTable::Segment(1), "mass", "mass (deck 2)"),
            (
                BridgeTable::Segment(1),
                "width",
                "joint face length (deck 2)",
            ),
            (BridgeTable::Segment(0), "bearings", "damping_ratio"),
            (
                BridgeTable::Segment(0),
                "bearing_points",
                "bearing point (deck 1)",
            ),
            (
                BridgeTable::Segment(1),
                "bearing_points",
                "bearing point (deck 2)",
            ),
            (
                BridgeTable::Segment(1),
                "bearing[2].stiffness",
                "bearing stiffness (deck 2, bearing 3)",
            ),
            (BridgeTable::Joint(0), "gap", "gap"),
            (BridgeTable::Joint(0), "mu", "mu"),
            (BridgeTable::Joint(0), "eps_n", "eps_n"),
            (BridgeTable::Joint(0), "seat_length", "seat_length"),
            (BridgeTable::Joint(0), "width", "joint face length (deck 2)"),
            (BridgeTable::Abutment(0), "gap", "abutment gap (deck 1)"),
            (
                BridgeTable::Abutment(1),
                "seat_length",
                "abutment seat_length (deck 2)",
            ),
            (BridgeTable::Bridge, "outer_seat_length", "seat_length"),
            (BridgeTable::Bridge, "damping_ratio", "damping_ratio"),
        ];
        for (table, key, want) in keys {
            let k = BridgeKey::new(table, key);
            let got = two_deck_path(&k).unwrap_or_else(|| panic!("{k} has no two-deck path"));
            assert!(matches!(got, ParamPath::TwoDeck { .. }), "{k}: {got:?}");
            assert_eq!(got.to_string(), want, "{k}");
        }
        for (table, key) in [
            (BridgeTable::Segment(2), "mass"),
            (BridgeTable::Joint(0), "restrainer_k"),
            (BridgeTable::Joint(1), "gap"),
            (BridgeTable::Pier(0), "k"),
        ] {
            assert_eq!(two_deck_path(&BridgeKey::new(table, key)), None);
        }
    }
}
