//! Property tests: random *valid* study scenarios and simulation models never panic, and a run
//! that claims success (`Completed`, a computed cell, a summary) never carries a non-finite number
//! except where documented (degenerate cells are all NaN; a stick bound may be infinite in the
//! Painlevé regime; a block without first-contact cells has NaN shares). The checks are the fuzz
//! oracles (`fuzz/src/lib.rs`: `check_study`, `check_sim`), so fuzzing and these tests agree on
//! what "valid output" means. Case counts are fixed (CI runs them with a fixed seed).

use crate::fuzz::oracle::{check_sim, check_study};
use pounding::contact_law::{ContactLaw, Hertz, KelvinVoigt};
use pounding::ground_motion::{GroundMotion, Record};
use pounding::pair::SArrangement;
use pounding::shape::Deck;
use pounding::shape::{DeckShape, SkewedDeck, StraightDeck};
use pounding::sim::{
    ComplianceContact, DampingModel, JointContact, SimAbutment, SimModel, SimProblem, SimSettings,
    SimStatus, simulate,
};
use pounding::study::{Scenario, Study};
use proptest::prelude::*;

/// A list of 1 or 2 distinct values in `[lo, hi)` as TOML.
fn list(lo: f64, hi: f64) -> impl Strategy<Value = String> {
    proptest::collection::vec(lo..hi, 1..3).prop_map(|mut v| {
        v.dedup_by(|a, b| a == b);
        let items: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
        format!("[{}]", items.join(", "))
    })
}

/// `{ start, stop, step }` with 1 to 4 values, |θ| < 90.
fn grid() -> impl Strategy<Value = String> {
    (-30.0f64..10.0, 0.25f64..8.0, 0usize..4).prop_map(|(start, step, k)| {
        let stop = start + step * k as f64;
        format!("{{ start = {start:?}, stop = {stop:?}, step = {step:?} }}")
    })
}

fn study_scenario() -> impl Strategy<Value = String> {
    let decks =
        prop_oneof![
        (list(20.0, 180.0), list(20.0, 180.0), list(12.0, 400.0), list(12.0, 400.0)).prop_map(
            |(b1, b2, r1, r2)| format!(
                "shape = \"curved\"\nbeta1_deg = {b1}\nbeta2_deg = {b2}\nr1_m = {r1}\nr2_m = {r2}\n"
            )
        ),
        (list(5.0, 100.0), list(5.0, 100.0)).prop_map(|(l1, l2)| format!(
            "shape = \"straight\"\nl1_m = {l1}\nl2_m = {l2}\n"
        )),
        (list(5.0, 100.0), list(5.0, 100.0), list(0.0, 60.0)).prop_map(|(l1, l2, sk)| format!(
            "shape = \"skew\"\nl1_m = {l1}\nl2_m = {l2}\nskew_deg = {sk}\n"
        )),
    ];
    let cases = proptest::sample::subsequence(
        vec!["deck1-inner", "deck1-outer", "deck2-inner", "deck2-outer"],
        1..=4,
    );
    (
        decks,
        (2.0f64..20.0, 0.1f64..2.0, 500.0f64..5000.0),
        (list(0.0, 2.0), list(0.0, 1.0), any::<bool>()),
        (grid(), grid(), -20.0f64..0.0, 0.1f64..20.0, cases),
    )
        .prop_map(|(decks, (w, t, rho), (mu, eps, end), (g1, g2, rmin, span, cases))| {
            let cases: Vec<String> = cases.iter().map(|c| format!("\"{c}\"")).collect();
            format!(
                "[decks]\n{decks}width_m = {w:?}\nthickness_m = {t:?}\ndensity_kg_m3 = {rho:?}\n\n\
                 [impact]\nmu = {mu}\neps = {eps}\nsigma_mode = \"{}\"\n\n\
                 [grid]\ntheta1_deg = {g1}\ntheta2_deg = {g2}\nratio_min = {rmin:?}\n\
                 ratio_max = {:?}\ncases = [{}]\n\n[output]\nfigures = false\n",
                if end { "end" } else { "exact" },
                rmin + span,
                cases.join(", ")
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A random valid study scenario (curved, straight or skew decks; lists of 1–2 values; a
    /// grid of up to 4×4; any case subset; either contact-point mode) is accepted, runs without
    /// panic, and every number it claims valid is finite (see the module doc).
    #[test]
    fn prop_valid_study_scenarios_give_finite_results(text in study_scenario()) {
        let sc = Scenario::from_toml(&text, "prop.toml");
        // curved decks need r > W/2: a scenario breaking that is refused, never run
        let sc = match sc {
            Ok(sc) => sc,
            Err(e) => {
                let msg = e.to_string();
                prop_assert!(msg.contains("r1_m") || msg.contains("r2_m"), "{msg}\n{text}");
                return Ok(());
            }
        };
        prop_assert!(sc.row_count() <= 2 * 2 * 2 * 2 * 2 * 2 * 4 * 16 * 3);
        let study = Study::compute(text.clone(), sc, &|_| {});
        let study = study.map_err(|e| TestCaseError::fail(format!("{e}\n{text}")))?;
        check_study(&study);
    }
}

#[derive(Debug, Clone)]
struct SimCase {
    shape: u8,
    deck: [f64; 3],
    dims: [f64; 4],
    joint: [f64; 4],
    k: [f64; 2],
    zeta: f64,
    dashpots: bool,
    abutment: Option<(f64, f64)>,
    law: u8,
    law_k: f64,
    accel: Vec<f64>,
    scale: [f64; 2],
    incidence: f64,
    dt: f64,
    steps: usize,
}

fn sim_case() -> impl Strategy<Value = SimCase> {
    (
        (0u8..3, (2.0f64..20.0, 0.2f64..2.0, 500.0f64..5000.0)),
        (20.0f64..1000.0, 10.0f64..120.0, 5.0f64..100.0, 0.0f64..60.0),
        (0.0f64..0.1, 0.0f64..1.5, 0.0f64..1.0, 0.05f64..2.0),
        (1e5f64..1e9, 1e5f64..1e9, 0.0f64..0.3, any::<bool>()),
        (
            proptest::option::of((0.0f64..0.05, 0.05f64..2.0)),
            0u8..3,
            1e7f64..1e10,
        ),
        (
            proptest::collection::vec(-1.0f64..1.0, 2..12),
            -3.0f64..3.0,
            -3.0f64..3.0,
            -180.0f64..180.0,
        ),
        (2e-4f64..2e-3, 5usize..120),
    )
        .prop_map(
            |(
                (shape, deck),
                dims,
                joint,
                (k1, k2, zeta, dashpots),
                (abutment, law, law_k),
                (accel, sy, sx, inc),
                (dt, steps),
            )| SimCase {
                shape,
                deck: [deck.0, deck.1, deck.2],
                dims: [dims.0, dims.1, dims.2, dims.3],
                joint: [joint.0, joint.1, joint.2, joint.3],
                k: [k1, k2],
                zeta,
                dashpots,
                abutment,
                law,
                law_k,
                accel,
                scale: [sy, sx],
                incidence: inc,
                dt,
                steps,
            },
        )
}

fn sim_problem(c: &SimCase) -> (SimProblem, SimSettings) {
    let [width, thickness, density] = c.deck;
    let [radius, angle, length, skew] = c.dims;
    let [gap, mu, eps, seat] = c.joint;
    let mut model = match c.shape {
        0 => {
            let d = |r: f64| Deck {
                radius: r,
                angle: angle.to_radians(),
                width,
                thickness,
                density,
            };
            let arr = SArrangement {
                deck1: d(radius),
                deck2: d(radius * 1.3),
            };
            SimModel::with_corner_bearings(arr, gap, c.k[0], c.k[1], c.zeta, mu, eps, seat)
        }
        1 => {
            let d = |l: f64| {
                DeckShape::Straight(StraightDeck {
                    length: l,
                    width,
                    thickness,
                    density,
                })
            };
            SimModel::with_shapes(
                [d(length), d(length * 0.7)],
                gap,
                c.k[0],
                c.k[1],
                c.zeta,
                mu,
                eps,
                seat,
            )
        }
        _ => {
            let d = |l: f64| {
                DeckShape::Skewed(SkewedDeck {
                    length: l,
                    width,
                    skew: skew.to_radians(),
                    thickness,
                    density,
                })
            };
            SimModel::with_shapes(
                [d(length), d(length * 1.4)],
                gap,
                c.k[0],
                c.k[1],
                c.zeta,
                mu,
                eps,
                seat,
            )
        }
    };
    if c.dashpots {
        model.damping_model = DampingModel::TranslationalDashpots;
    }
    let law: Option<ContactLaw> = match c.law {
        1 => Some(
            KelvinVoigt::new(c.law_k, 0.05 * c.law_k.sqrt())
                .unwrap()
                .into(),
        ),
        2 => Some(Hertz::new(c.law_k * 100.0).unwrap().into()),
        _ => None,
    };
    match law {
        Some(l) => model.contact = JointContact::Compliance(ComplianceContact::new(l)),
        None => {
            if let Some((g, s)) = c.abutment {
                model.abutments[0] = Some(SimAbutment {
                    gap: g,
                    seat_length: s,
                });
            }
        }
    }
    let values: Vec<f64> = c.accel.iter().map(|a| a * 9.80665).collect();
    let rec = Record::uniform("prop", 0.01, values).unwrap();
    let ground = GroundMotion {
        along_y: Some(rec.clone()),
        scale_y: c.scale[0],
        along_x: Some(rec),
        scale_x: c.scale[1],
        incidence: c.incidence.to_radians(),
    };
    let settings = SimSettings {
        dt: c.dt,
        duration: Some(c.dt * c.steps as f64),
        history_stride: 3,
        ..SimSettings::default()
    };
    (SimProblem::at_rest(model, ground), settings)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A random valid simulation model (curved, straight or skew decks; bearings, Rayleigh or
    /// dashpot damping; rigid contact with an optional abutment, or a Kelvin/Hertz compliance
    /// law) under a random two-component ground motion runs a short history (≤ 120 steps)
    /// without panic or error; a run that ends `Completed*` has only finite numbers.
    #[test]
    fn prop_valid_sim_models_give_finite_results(c in sim_case()) {
        let (problem, settings) = sim_problem(&c);
        problem.model.validate().map_err(|e| TestCaseError::fail(format!("{e}: {c:?}")))?;
        let sol = simulate(&problem, &settings)
            .map_err(|e| TestCaseError::fail(format!("{e}: {c:?}")))?;
        prop_assert!(sol.steps >= 1);
        match sol.status {
            SimStatus::Completed
            | SimStatus::CompletedWithLcpFailures
            | SimStatus::CompletedWithNewtonFailures
            | SimStatus::CompletedWithEnergyError => check_sim(&sol),
            SimStatus::Diverged => prop_assert!(false, "a valid model diverged: {c:?}"),
        }
    }
}
