//! The two-deck model of a scenario: the deck shapes of `[decks]`, the joint, abutments,
//! bearings, damping and contact law, every value validated with errors located at its key.

use crate::math::Vector;
use crate::output::float_token;
use crate::pair::SArrangement;
use crate::shape::Deck;
use crate::shape::{DeckShape, SkewedDeck, StraightDeck};
use crate::sim::scenario::contact::{FileKeys, build_contact};
use crate::sim::scenario::error::{ParamKey, ScenarioError, Section};
use crate::sim::scenario::model_keys::sim_error;
use crate::sim::scenario::sections::{DecksSec, Raw};
use crate::sim::scenario::{Scenario, Src};
use crate::sim::{Bearing, DampingModel, JointContact, SimAbutment, SimModel};

const fn decks(key: &'static str) -> ParamKey {
    ParamKey::new(Section::Decks, key)
}

/// The deck shapes of `[decks]`: `None` for `shape = "curved"` (the S arrangement of `R1 R2
/// beta1_deg beta2_deg`), else two straight / skewed decks of lengths `L1`, `L2` (values are
/// validated later by the model, with errors naming `L1`, `skew_deg`, …).
fn deck_shapes(src: &Src, d: &DecksSec) -> Result<Option<[DeckShape; 2]>, ScenarioError> {
    let shape = d.shape.trim();
    let only = |key: &'static str, for_shape: &str| -> Result<(), ScenarioError> {
        let k = decks(key);
        if src.is_set(k) {
            return Err(src.key_error(
                format!(
                    "{} applies to shape = \"{for_shape}\" only (shape is \"{shape}\")",
                    src.at(k)
                ),
                &[k],
            ));
        }
        Ok(())
    };
    match shape {
        "curved" => {
            for k in ["L1", "L2"] {
                only(k, "straight\" or \"skew")?;
            }
            only("skew_deg", "skew")?;
            Ok(None)
        }
        "straight" | "skew" => {
            for k in ["R1", "R2", "beta1_deg", "beta2_deg"] {
                only(k, "curved")?;
            }
            if shape == "straight" {
                only("skew_deg", "skew")?;
            }
            let len = |v: Option<f64>, key: &'static str| {
                v.ok_or_else(|| {
                    src.key_error(
                        format!(
                            "shape = \"{shape}\" needs {} (deck length along its axis, m)",
                            src.at(decks(key))
                        ),
                        &[decks(key)],
                    )
                })
            };
            let (l1, l2) = (len(d.L1, "L1")?, len(d.L2, "L2")?);
            let skew = match d.skew_deg {
                // checked in degrees, so that the message shows the user's value
                Some(s) if !(s.is_finite() && (0.0..90.0).contains(&s)) => {
                    return Err(src.invalid(
                        format!(
                            "invalid skew_deg = {}: the skew angle must lie in [0, 90) degrees",
                            crate::output::float_token(s)
                        ),
                        decks("skew_deg"),
                    ));
                }
                Some(s) => s.to_radians(),
                None if shape == "skew" => {
                    return Err(src.key_error(
                        format!(
                            "shape = \"skew\" needs skew_deg (the skew angle in [0, 90) deg, in \
                             [decks]; use shape = \"straight\" for 0) — set by {}",
                            src.at(decks("shape"))
                        ),
                        &[decks("shape")],
                    ));
                }
                None => 0.0,
            };
            let mk = |l: f64| {
                if shape == "straight" {
                    DeckShape::Straight(StraightDeck {
                        length: l,
                        width: d.width,
                        thickness: d.thickness,
                        density: d.density,
                    })
                } else {
                    DeckShape::Skewed(SkewedDeck {
                        length: l,
                        width: d.width,
                        skew,
                        thickness: d.thickness,
                        density: d.density,
                    })
                }
            };
            Ok(Some([mk(l1), mk(l2)]))
        }
        other => Err(src.key_error(
            format!(
                "invalid shape {other:?} at {}: use \"curved\", \"straight\" or \"skew\"",
                src.at(decks("shape"))
            ),
            &[decks("shape")],
        )),
    }
}

/// The model of `[decks]`, `[joint]`, `[abutments]`, `[bearings]` and `[contact]`.
pub(super) fn build_model(sc: &Scenario) -> Result<SimModel, ScenarioError> {
    let (src, raw): (&Src, &Raw) = (&sc.src, &sc.raw);
    let d = &raw.decks;
    let deck = |r: f64, b: f64| Deck {
        radius: r,
        angle: b.to_radians(),
        width: d.width,
        thickness: d.thickness,
        density: d.density,
    };
    let (j, b) = (&raw.joint, &raw.bearings);
    let mut model = match deck_shapes(src, d)? {
        None => SimModel::with_corner_bearings(
            SArrangement {
                deck1: deck(d.R1, d.beta1_deg),
                deck2: deck(d.R2, d.beta2_deg),
            },
            j.gap,
            b.stiffness1,
            b.stiffness2,
            b.damping_ratio,
            j.mu,
            j.eps_n,
            j.seat_length,
        ),
        Some(sh) => SimModel::with_shapes(
            sh,
            j.gap,
            b.stiffness1,
            b.stiffness2,
            b.damping_ratio,
            j.mu,
            j.eps_n,
            j.seat_length,
        ),
    };
    let ab = &raw.abutments;
    for (k, gap, seat) in [(0, ab.gap1, ab.seat_length1), (1, ab.gap2, ab.seat_length2)] {
        match (gap, seat) {
            (Some(gap), seat) => {
                model.abutments[k] = Some(SimAbutment {
                    gap,
                    seat_length: seat.unwrap_or(j.seat_length),
                })
            }
            (None, Some(_)) => {
                let deck = k as u8 + 1;
                let (s, g) = if k == 0 {
                    ("seat_length1", "gap1")
                } else {
                    ("seat_length2", "gap2")
                };
                let keys = [
                    ParamKey::of_deck(Section::Abutments, s, deck),
                    ParamKey::of_deck(Section::Abutments, g, deck),
                ];
                return Err(src.key_error(
                    format!(
                        "{} is set but {} is not (an abutment needs its gap)",
                        src.at(keys[0]),
                        src.at(keys[1])
                    ),
                    &keys,
                ));
            }
            (None, None) => {}
        }
    }
    // Validate the decks before using them for the default bearing points.
    model.validate().map_err(|e| sim_error(src, e))?;
    apply_shape_and_damping(src, d, &b.damping, &mut model)?;
    sc.check_contact_keys()?;
    model.contact = build_contact(
        &FileKeys(src),
        &raw.contact,
        sc.law.as_deref(),
        j.eps_n,
        model.masses(),
    )?;
    if !matches!(model.contact, JointContact::Rigid) && model.abutments.iter().any(Option::is_some)
    {
        return Err(abutments_need_rigid_contact(sc));
    }
    for (deck_no, pts, k, key) in [
        (1, &b.points1, b.stiffness1, "points1"),
        (2, &b.points2, b.stiffness2, "points2"),
    ] {
        let Some(pts) = pts else { continue };
        if pts.is_empty() {
            let key = ParamKey::of_deck(Section::Bearings, key, deck_no);
            return Err(src.key_error(
                format!(
                    "{} is empty (omit it for the default 4 corners)",
                    src.at(key)
                ),
                &[key],
            ));
        }
        let v: Vec<Bearing> = pts
            .iter()
            .map(|p| Bearing {
                point: Vector::new(p[0], p[1]),
                stiffness: k,
            })
            .collect();
        if deck_no == 1 {
            model.bearings1 = v;
        } else {
            model.bearings2 = v;
        }
    }
    Ok(model)
}

/// The error of abutments with a compliance law (rigid contact only, for now): it names the law
/// (`[contact] law` and its line, unless [`Scenario::with_law`] replaced it) and every
/// `[abutments]` key given.
fn abutments_need_rigid_contact(sc: &Scenario) -> ScenarioError {
    let src = &sc.src;
    let law_key = ParamKey::new(Section::Contact, "law");
    let mut at = Vec::new();
    let by = match &sc.law {
        Some(l) => format!("law {l:?}"),
        None => {
            at.push(src.at(law_key));
            format!("law = {:?}, set by {},", sc.law(), at[0])
        }
    };
    let abut: Vec<_> = [
        (1, "gap1"),
        (1, "seat_length1"),
        (2, "gap2"),
        (2, "seat_length2"),
    ]
    .into_iter()
    .map(|(deck, key)| ParamKey::of_deck(Section::Abutments, key, deck))
    .filter(|&k| src.is_set(k))
    .map(|k| src.at(k))
    .collect();
    let list: Vec<String> = abut.iter().map(ToString::to_string).collect();
    at.extend(abut);
    ScenarioError::Key {
        message: format!(
            "two-deck scenarios support abutments with rigid contact only: {by} is a compliance \
             law, but {} set abutments (remove [abutments], use law = \"rigid\" (compare: \
             --laws rigid), or write the bridge as [[segment]]s, whose abutments take every law)",
            list.join(", ")
        ),
        at,
    }
}

/// `[decks] mass1`, `mass2` (the deck's mass given directly: its density becomes
/// `ρ m / m(ρ)`, any shape) and `[bearings] damping = "rayleigh" | "dashpots"`.
fn apply_shape_and_damping(
    src: &Src,
    d: &DecksSec,
    damping: &str,
    model: &mut SimModel,
) -> Result<(), ScenarioError> {
    let current = model.masses();
    for (j, m, key) in [(0, d.mass1, "mass1"), (1, d.mass2, "mass2")] {
        let Some(m) = m else { continue };
        if !(m.is_finite() && m > 0.0) {
            return Err(src.invalid(
                format!("invalid {key} = {}: must be finite and > 0", float_token(m)),
                ParamKey::of_deck(Section::Decks, key, j as u8 + 1),
            ));
        }
        let f = m / current[j];
        match &mut model.shapes {
            Some(sh) => sh[j].scale_density(f),
            None => {
                if j == 0 {
                    model.arrangement.deck1.density *= f;
                } else {
                    model.arrangement.deck2.density *= f;
                }
            }
        }
    }
    model.damping_model = match damping {
        "rayleigh" => DampingModel::Rayleigh,
        "dashpots" => DampingModel::TranslationalDashpots,
        other => {
            let key = ParamKey::new(Section::Bearings, "damping");
            return Err(src.key_error(
                format!(
                    "unknown damping {other:?} at {}: use \"rayleigh\" or \"dashpots\"",
                    src.at(key)
                ),
                &[key],
            ));
        }
    };
    Ok(())
}
