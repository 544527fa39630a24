//! The `simulate` scenario as a library API (`pounding::sim::scenario`) and its writers
//! (`pounding::sim::output`): defaults, typed error keys with file and line, overrides, and the
//! shape of the written files.

use pounding::sim::output::{
    BATCH_HEADER, COMPARE_HEADER, History, Layout, batch_csv, compare_tables, impacts_csv,
};
use pounding::sim::scenario::{
    DEFAULT_SCENARIO_TOML, LAW_NAMES, ParamKey, Scenario, ScenarioError, Section,
};
use pounding::sim::{JointContact, simulate};

fn err(text: &str) -> ScenarioError {
    match Scenario::from_toml(text, "t.toml").and_then(|s| s.build()) {
        Ok(_) => panic!("{text}: built without error"),
        Err(e) => e,
    }
}

/// The serde defaults of every section and the commented default text are written separately:
/// an empty file and the default text must build the same run.
#[test]
fn empty_file_and_default_text_build_the_same_run() {
    let a = Scenario::from_toml("", "empty").unwrap().build().unwrap();
    let b = Scenario::default().build().unwrap();
    assert_eq!(a.problem, b.problem);
    assert_eq!(a.settings, b.settings);
    assert_eq!(a.records, b.records);
    assert_eq!(
        Scenario::from_toml(DEFAULT_SCENARIO_TOML, "x")
            .unwrap()
            .build()
            .unwrap()
            .problem,
        b.problem
    );
    assert!(matches!(b.problem.model.contact, JointContact::Rigid));
    assert_eq!(b.records, ["builtin:ELC180", "builtin:ELC270"]);
}

#[test]
fn errors_carry_typed_keys_and_lines() {
    let e = err("[joint]\nmu = 0.5\ngap = -1.0\n");
    assert_eq!(e.keys(), vec![ParamKey::new(Section::Joint, "gap")]);
    let ScenarioError::Invalid { at, .. } = &e else {
        panic!("{e:?}")
    };
    assert_eq!(at[0].line, Some(3));
    assert!(e.to_string().contains("`[joint] gap` (t.toml:3)"), "{e}");

    // a per-deck key names its deck
    let e = err("[bearings]\nstiffness2 = -5.0\n");
    assert_eq!(
        e.keys(),
        vec![ParamKey::of_deck(Section::Bearings, "stiffness2", 2)]
    );
    // a key left at its default says so
    let e = err("[decks]\nwidth = 300.0\n");
    assert!(
        e.keys()
            .iter()
            .all(|k| k.section == Section::Decks && k.deck.is_some()),
        "{e}"
    );
    let e = err("[time]\nhistory_every = 0\n");
    assert_eq!(
        e.keys(),
        vec![ParamKey::new(Section::Time, "history_every")]
    );
    // an unknown law names `[contact] law`
    let e = err("[contact]\nlaw = \"glue\"\n");
    assert_eq!(e.keys(), vec![ParamKey::new(Section::Contact, "law")]);
    assert!(e.to_string().contains("(t.toml:2)"), "{e}");
    // a contact-law parameter names its `[contact]` key; the default restitution says where
    // it comes from
    let e = err("[contact]\nlaw = \"kelvin\"\nk = -1.0\n");
    assert_eq!(e.keys(), vec![ParamKey::new(Section::Contact, "k")]);
    let e = err("[joint]\neps_n = 0.0\n[contact]\nlaw = \"hertz-damp\"\n");
    assert!(e.to_string().contains("`[joint] eps_n`"), "{e}");
    // syntax errors and unknown keys
    assert!(matches!(
        err("[decks]\nR3 = 1.0\n"),
        ScenarioError::Syntax { .. }
    ));
    assert!(matches!(
        err("decks = [1, 2]\n"),
        ScenarioError::Syntax { .. }
    ));
}

/// A deck mass that overflows the frequencies is set by `massJ` when given, else by `density`.
#[test]
fn deck_mass_errors_name_mass_or_density() {
    let e = err("[decks]\nmass1 = 1e-310\n");
    assert_eq!(
        e.keys(),
        vec![ParamKey::of_deck(Section::Decks, "mass1", 1)],
        "{e}"
    );
    let e = err("[decks]\ndensity = 1e-310\n");
    assert!(
        e.keys().iter().all(|k| k.key == "density"),
        "{e}: {:?}",
        e.keys()
    );
}

#[test]
fn every_model_parameter_of_the_scenario_maps_to_a_key() {
    for name in [
        "dt",
        "duration",
        "history_stride",
        "gap",
        "seat_length",
        "mu",
        "eps_n",
        "damping_ratio",
        "R1",
        "R2",
        "beta1",
        "beta2",
        "L1",
        "L2",
        "skew1",
        "skew2",
        "width",
        "width (deck 2)",
        "joint face length (deck 2)",
        "thickness",
        "density",
        "abutment gap (deck 1)",
        "abutment seat_length (deck 2)",
        "bearing stiffness (deck 1, bearing 3)",
        "bearing point (deck 2, bearing 1)",
        "scale_y",
        "scale_x",
        "incidence",
    ] {
        assert!(ParamKey::of_model_parameter(name).is_some(), "{name}");
    }
    assert_eq!(
        ParamKey::of_model_parameter("bearing point (deck 2, bearing 1)"),
        Some(ParamKey::of_deck(Section::Bearings, "points2", 2))
    );
    assert_eq!(
        ParamKey::of_model_parameter("abutment gap (deck 1)"),
        Some(ParamKey::of_deck(Section::Abutments, "gap1", 1))
    );
    assert_eq!(ParamKey::of_model_parameter("q0[3]"), None);
    assert_eq!(ParamKey::of_model_parameter("bearing stiffness"), None);
}

#[test]
fn overrides_law_scale_record_and_batch() {
    let base = Scenario::default();
    for law in LAW_NAMES {
        let s = base.clone().with_law(law);
        assert_eq!(s.law(), law);
        let setup = s.build().unwrap();
        assert_eq!(
            matches!(setup.problem.model.contact, JointContact::Rigid),
            law == "rigid"
        );
    }
    assert!(matches!(
        base.clone().with_law("glue").build(),
        Err(ScenarioError::Key { .. })
    ));
    let s = base.clone().with_scale(2.5).build().unwrap();
    assert_eq!(s.problem.ground.scale_y, 2.5);
    assert!(matches!(
        base.clone().with_scale(f64::NAN).build(),
        Err(ScenarioError::Scale(_))
    ));
    let b = base.clone().for_batch().build().unwrap();
    assert!(b.problem.ground.along_y.is_none() && b.problem.ground.along_x.is_none());
    assert_eq!(b.records, ["batch", "none"]);
    let e = base
        .clone()
        .with_record("no/such/record.AT2".as_ref(), None)
        .build()
        .unwrap_err();
    assert!(matches!(e, ScenarioError::RecordOverride { .. }), "{e}");
    assert!(
        e.to_string().starts_with("--record no/such/record.AT2: "),
        "{e}"
    );
}

/// The mass given by `[decks] mass1` is the model's mass (the density is scaled to it).
#[test]
fn deck_mass_override_sets_the_mass() {
    let s = Scenario::from_toml("[decks]\nmass1 = 2.0e6\n", "m")
        .unwrap()
        .build()
        .unwrap();
    let m = s.problem.model.masses();
    assert!((m[0] - 2.0e6).abs() <= 1e-9 * 2.0e6, "{m:?}");
    let d = Scenario::default().build().unwrap().problem.model.masses();
    assert_eq!(m[1], d[1]);
}

#[test]
fn load_resolves_records_relative_to_the_file_and_names_it() {
    let dir = crate::scratch::scratch_dir("scn", "load");
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("sub/r.csv"), "0, 0\n0.01, 0.1\n0.02, -0.1\n").unwrap();
    let p = dir.join("s.toml");
    std::fs::write(
        &p,
        "[ground_motion]\nrecord_y = \"sub/r.csv\"\nrecord_x = \"sub/missing.csv\"\n",
    )
    .unwrap();
    let e = Scenario::load(&p).unwrap().build().unwrap_err();
    assert_eq!(
        e.keys(),
        vec![ParamKey::new(Section::GroundMotion, "record_x")]
    );
    assert!(
        e.to_string().contains(&format!("({}:3)", p.display())),
        "{e}"
    );
    std::fs::write(
        &p,
        "[ground_motion]\nrecord_y = \"sub/r.csv\"\nrecord_x = \"none\"\n",
    )
    .unwrap();
    let s = Scenario::load(&p).unwrap().build().unwrap();
    let r = s.problem.ground.along_y.as_ref().unwrap();
    // csv_units defaults to g
    assert_eq!(r.values().len(), 3);
    assert_eq!(r.pga(), 0.1 * pounding::ground_motion::G0);
    let e = Scenario::load(&dir.join("absent.toml")).unwrap_err();
    assert!(matches!(e, ScenarioError::Read { .. }), "{e}");
}

/// The writers' rows have as many fields as their headers, and `summary.json` is JSON.
#[test]
fn writers_rows_match_their_headers() {
    let text = "[time]\nduration = 0.3\nhistory_every = 7\n[abutments]\ngap1 = 0.05\n";
    let setup = Scenario::from_toml(text, "w").unwrap().build().unwrap();
    let sol = simulate(&setup.problem, &setup.settings).unwrap();
    let ab = setup.problem.model.abutments.map(|a| a.is_some());
    let h = History::new(Layout::TwoDecks, &sol, &setup.problem.ground, ab).csv();
    let mut lines = h.lines();
    let n = lines.next().unwrap().split(',').count();
    assert!(h.lines().next().unwrap().ends_with(",abutment_gap1_m"));
    assert_eq!(h.lines().count(), sol.t.len() + 1);
    assert!(lines.all(|l| l.split(',').count() == n));
    let pair = pounding::sim::bridge::BridgeModel::from_pair(&setup.problem.model);
    let i = impacts_csv(Layout::TwoDecks, &pair, &sol);
    assert_eq!(i.lines().count(), sol.impacts.len() + 1);
    let j = pounding::sim::scenario::Setup::of_two_decks(setup.clone()).summary_json_text(&sol);
    assert!(j.ends_with("}\n"));
    let v: serde_json::Value = serde_json::from_str(&j).unwrap();
    assert_eq!(v["steps"], sol.steps);
    assert!(v["abutments"]["deck1"].is_object());
    let st = pounding::sim::scenario::Setup::of_two_decks(setup.clone());
    let ran = pounding::sim::compare::Ran {
        estimates: st.peak_force_estimates(&sol),
        setup: st,
        sol: sol.clone(),
        seconds: 0.0,
        warnings: Vec::new(),
    };
    let c = compare_tables(
        &[pounding::sim::compare::LawRun {
            law: "rigid".into(),
            outcome: Ok(ran),
        }],
        false,
    )
    .0
    .remove(0)
    .csv;
    assert_eq!(
        c.lines().nth(1).unwrap().split(',').count(),
        COMPARE_HEADER.split(',').count()
    );
    assert_eq!(
        batch_csv(Layout::TwoDecks, 2, &[]),
        format!("{BATCH_HEADER}\n")
    );
}

/// Errors carry typed parameter paths (the message's name is their text), and the scenario maps
/// them to the keys that set them, wherever the file writes the key (a dotted key included).
#[test]
fn typed_paths_name_the_keys_however_the_file_writes_them() {
    use pounding::sim::param::{ParamPath, TwoDeckParam};
    use pounding::sim::{SimError, SimModel};
    let mut m = SimModel::default_bridge();
    m.bearings2[0].stiffness = -1.0;
    let e = m.validate().unwrap_err();
    let path = ParamPath::TwoDeck {
        param: TwoDeckParam::BearingStiffness,
        deck: Some(2),
        bearing: Some(1),
    };
    assert_eq!(e.path(), Some(&path));
    let SimError::InvalidParameter { name, .. } = &e else {
        panic!("{e:?}")
    };
    assert_eq!(name, "bearing stiffness (deck 2, bearing 1)");
    assert_eq!(path.to_string(), *name);
    // the same key written three ways: a [section] line, a dotted key, an inline table
    for (text, line) in [
        ("[bearings]\nstiffness2 = -1\n", 2),
        ("# bearings\nbearings.stiffness2 = -1\n", 2),
        ("\n\nbearings = { stiffness2 = -1 }\n", 3),
    ] {
        let e = err(text);
        let ScenarioError::Invalid { at, .. } = &e else {
            panic!("{text}: {e:?}")
        };
        assert_eq!(
            at[0].key,
            ParamKey::of_deck(Section::Bearings, "stiffness2", 2)
        );
        assert_eq!(at[0].line, Some(line), "{text}: {e}");
        assert!(e.to_string().contains(&format!("(t.toml:{line})")), "{e}");
    }
    // a time step is checked once, and `compare --dt` says it as `simulate --dt` does
    let flag = Scenario::check_dt_flag(0.0).unwrap_err().to_string();
    let sim = Scenario::default()
        .with_dt(0.0)
        .build()
        .unwrap_err()
        .to_string();
    assert_eq!(flag, sim);
}
