//! [`Scenario::build`]: the model, the ground motion and the settings from the sections, every
//! value validated with errors located at its key.

use super::contact::{FileKeys, build_contact};
use super::error::{ParamKey, ScenarioError, Section};
pub(super) use super::ground::build_ground;
pub(super) use super::model_keys::sim_error;
use super::model_keys::{scaled_mass_error, time};
use super::sections::{DecksSec, Raw};
use super::{Scenario, SimSetup, Src};
use crate::ground_motion::GroundMotion;
use crate::math::{Real, Vector};
use crate::output::float_token;
use crate::pair::SArrangement;
use crate::shape::Deck;
use crate::shape::{DeckShape, SkewedDeck, StraightDeck};
use crate::sim::{
    Bearing, DampingModel, JointContact, SimAbutment, SimModel, SimProblem, SimSettings,
};

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
fn build_model(sc: &Scenario) -> Result<SimModel, ScenarioError> {
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

/// The error of a step `dt` longer than the run `duration`. Without `[time] duration` the
/// duration is the ground motion's: the record is blamed (its name and length), and `dt` is
/// named as set (its line, or "the built-in default dt").
fn dt_beyond_duration(
    sc: &Scenario,
    settings: &SimSettings,
    duration: Real,
    records: &[String; 2],
) -> ScenarioError {
    let src = &sc.src;
    let dt_at = src.at(time("dt"));
    if settings.duration.is_some() {
        return ScenarioError::Invalid {
            message: format!(
                "invalid dt = {}: must not exceed the duration {} s",
                float_token(settings.dt),
                float_token(duration)
            ),
            at: vec![dt_at, src.at(time("duration"))],
            note: String::new(),
        };
    }
    let names: Vec<&str> = records
        .iter()
        .map(String::as_str)
        .filter(|r| !r.trim().eq_ignore_ascii_case("none"))
        .collect();
    let dt_by = match src.builtin && dt_at.flag.is_none() {
        true => "the built-in default dt".to_string(),
        false => format!("set by {dt_at}"),
    };
    ScenarioError::Key {
        message: format!(
            "the ground motion lasts only {} s (the last sample of record {}), less than one time \
             step dt = {} s ({dt_by}): check the record's sample interval, or set [time] duration",
            float_token(duration),
            names.join(" and "),
            float_token(settings.dt)
        ),
        at: vec![dt_at],
    }
}

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

/// `[time]`: the settings of a run under `ground`, checked against its duration and the memory
/// limit; `model_checks` runs once the settings themselves are valid (the order of the errors
/// a file with several mistakes reports).
pub(super) fn build_settings(
    sc: &Scenario,
    ground: &GroundMotion,
    records: &[String; 2],
    // the memory estimate's bridge (segments, and piers counted as segments; its bearings)
    size: crate::sim::options::RunSize,
    model_checks: impl FnOnce() -> Result<(), ScenarioError>,
) -> Result<SimSettings, ScenarioError> {
    let src = &sc.src;
    let t = &sc.raw.time;
    if t.history_every < 1 {
        return Err(src.invalid(
            format!("invalid history_every = {}: must be >= 1", t.history_every),
            time("history_every"),
        ));
    }
    let settings = SimSettings {
        dt: t.dt,
        duration: t.duration,
        history_stride: t.history_every as usize,
        projection: t.projection,
        ..SimSettings::default()
    };
    settings.validate().map_err(|e| sim_error(src, e))?;
    model_checks()?;
    if !sc.batch && settings.duration.is_none() && ground.end_time() <= 0.0 {
        return Err(src.key_error(
            format!(
                "no ground motion samples after t = 0: set {}",
                src.at(time("duration"))
            ),
            &[time("duration")],
        ));
    }
    // The duration of the run (batch runs without `duration` use each record's length, checked
    // there).
    let duration = settings.duration.or((!sc.batch).then(|| ground.end_time()));
    if let Some(d) = duration {
        settings.step_count(d).map_err(|e| {
            let mut at = vec![src.at(time("dt"))];
            if src.is_set(time("duration")) {
                at.push(src.at(time("duration")));
            }
            ScenarioError::Invalid {
                message: e.to_string(),
                at,
                note: String::new(),
            }
        })?;
        use crate::sim::options::{MAX_RUN_MEMORY_BYTES, min_history_stride, run_memory_bytes};
        let n = settings.step_count(d).unwrap_or(usize::MAX);
        let bytes = run_memory_bytes(n, settings.history_stride, size);
        if !sc.batch && bytes > MAX_RUN_MEMORY_BYTES {
            let gib = |b: u64| b as Real / (1u64 << 30) as Real;
            let advice = match min_history_stride(n, size) {
                Some(s) => format!("set history_every >= {s} (or shorten the run)"),
                None => "shorten the run or use a larger dt".into(),
            };
            return Err(ScenarioError::Invalid {
                message: format!(
                    "run too large: {n} steps with history_every = {} need an estimated {:.1} GiB \
                     of memory, more than the limit {:.0} GiB; {advice}",
                    settings.history_stride,
                    gib(bytes),
                    gib(MAX_RUN_MEMORY_BYTES)
                ),
                at: vec![
                    src.at(time("history_every")),
                    src.at(time("duration")),
                    src.at(time("dt")),
                ],
                note: String::new(),
            });
        }
        if settings.dt > d {
            return Err(dt_beyond_duration(sc, &settings, d, records));
        }
    }
    Ok(settings)
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
