//! Abutment backwalls: the scenario's refusals (key and line), the step check of the backfill,
//! and the wall's equilibrium in the histories.

use pounding::sim::scenario::Scenario;

const BRIDGE_P_FULL: &str = include_str!("../../../../examples/bridge-piers-1d.toml");

/// `BRIDGE_P_FULL` with the start abutment's backwall table replaced by `table`.
fn with_start_wall(table: &str) -> String {
    let start = BRIDGE_P_FULL.find("[abutment.start.backwall]").unwrap();
    let end = BRIDGE_P_FULL[start..].find("\n\n").unwrap() + start;
    format!(
        "{}[abutment.start.backwall]\n{table}{}",
        &BRIDGE_P_FULL[..start],
        &BRIDGE_P_FULL[end..]
    )
}

/// Builds and runs a bridge file.
fn run(text: &str, name: &str) -> pounding::sim::bridge::BridgeSolution {
    Scenario::from_toml(text, name)
        .unwrap()
        .build_bridge()
        .unwrap()
        .run()
        .unwrap()
}

fn error(text: &str) -> String {
    Scenario::from_toml(text, "walls.toml")
        .and_then(|s| s.build_bridge())
        .expect_err("refused")
        .to_string()
}

/// Bad backwalls are refused naming the key and the line of the offending value.
#[test]
fn bad_backwalls_are_refused_with_key_and_line() {
    let cases = [
        (
            "kmax = 1e8\nfult = 1e6\n",
            "backwall.mass",
            "is required",
            "[abutment.start.backwall]",
        ),
        (
            "mass = -1.0\npiles_k = 1e7\npiles_fy = 1e5\n",
            "backwall.mass",
            "> 0",
            "mass = -1.0",
        ),
        (
            "mass = 1e5\nkmax = 1e8\nfult = 1e6\nrf = 1.2\n",
            "backwall.rf",
            "(0, 1)",
            "rf = 1.2",
        ),
        (
            "mass = 1e5\nkmax = 1e8\nfult = 1e6\nheight = 2.0\n",
            "backwall.height",
            "not both",
            "height = 2.0",
        ),
        (
            "mass = 1e5\n",
            "backwall.mass",
            "something behind it",
            "[abutment.start.backwall]",
        ),
        (
            "mass = 1e5\npiles_k = 1e7\n",
            "backwall.piles_fy",
            "is required",
            "[abutment.start.backwall]",
        ),
        (
            "mass = 1e5\nkmax = 1e8\n",
            "backwall.fult",
            "is required",
            "[abutment.start.backwall]",
        ),
        (
            "mass = 1e5\npiles_k = 1e7\npiles_fy = 1e5\nrf = 0.5\n",
            "backwall.rf",
            "applies to a backfill",
            "rf = 0.5",
        ),
        (
            "mass = 1e5\nheight = 2.0\nwidth = 12.0\nskew_deg = 95.0\n",
            "backwall.skew_deg",
            "[0, 90)",
            "skew_deg = 95.0",
        ),
        (
            "mass = 1e5\nkmax = nan\nfult = 1e6\n",
            "backwall.kmax",
            "> 0",
            "kmax = nan",
        ),
        (
            "mass = 1e5\nheight = 2.0\nwidth = 12.0\nsoil = 1.0\n",
            "soil",
            "unknown",
            "soil = 1.0",
        ),
    ];
    for (table, key, why, bad) in cases {
        let text = with_start_wall(table);
        let err = error(&text);
        assert!(err.contains(key) && err.contains(why), "{table}: {err}");
        let line = text.lines().position(|l| l == bad).unwrap() + 1;
        assert!(
            err.contains(&format!("walls.toml:{line}")) || err.contains(&format!("line {line}")),
            "{table}: not line {line} in {err}"
        );
    }
    // the backfill is held over each step: a step that does not resolve it is refused naming dt
    let coarse = BRIDGE_P_FULL.replace("dt = 5e-5 ", "dt = 0.05 ");
    let err = error(&coarse);
    assert!(
        err.contains("dt") && err.contains("backfill of abutment.start"),
        "{err}"
    );
}

/// The Caltrans preset runs and its backfill force never exceeds `F_ult`; the wall's coordinate,
/// backfill and pile forces in `backwalls.csv` match `summary.json`'s peaks.
#[test]
fn caltrans_backwall_runs_and_its_table_matches_the_summary() {
    let table = "mass = 1.0e5\nheight = 1.7\nwidth = 12.0\nskew_deg = 0.0\npiles_k = 6.3e7\n\
                 piles_fy = 1.071e6\n";
    let text = with_start_wall(table)
        .replace("dt = 5e-5 ", "dt = 1e-4 ")
        .replace("history_every = 200", "history_every = 1");
    let text = text.replace("[time]\n", "[time]\nduration = 12.0\n");
    let sol = run(&text, "walls.toml");
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    assert!(sol.summary.energy_balance_error < 1e-9);
    let c = pounding::element::backfill::CaltransBackwall::new(1.7, 12.0, 0.0).unwrap();
    let tables = sol.tables();
    let t = tables
        .iter()
        .find(|t| t.name == "backwalls")
        .expect("backwalls.csv");
    let n = t.columns.len();
    assert_eq!(n, 7, "t and three columns per wall");
    let (mut wall, mut fill, mut piles) = (0.0f64, 0.0f64, 0.0f64);
    for row in t.values.chunks(n) {
        assert!(
            row[2] >= 0.0 && row[2] <= c.f_ult * (1.0 + 1e-12),
            "{}",
            row[2]
        );
        assert!(row[3].abs() <= 1.071e6 * (1.0 + 1e-9));
        wall = wall.max(row[1]);
        fill = fill.max(row[2]);
        piles = piles.max(row[3].abs());
    }
    let w = sol.summary.abutments[0]
        .as_ref()
        .unwrap()
        .backwall
        .as_ref()
        .unwrap();
    assert!(wall > 0.0 && fill > 0.0, "the wall is pushed");
    assert_eq!(w.peak_displacement, wall);
    assert_eq!(w.peak_backfill_force, Some(fill));
    assert_eq!(w.peak_pile_force, Some(piles));
}

const BRIDGE_P_PLAN: &str = include_str!("../../../../examples/bridge-piers.toml");

/// The plan bridge with shear keys: the keys' force never exceeds their capacity, is zero while
/// the deck end is inside the gap and opposes its displacement; the summary's peaks are the
/// table's; the energy balance closes with the keys' work booked.
#[test]
fn shear_keys_stay_on_their_law_in_the_plan_bridge() {
    let text = BRIDGE_P_PLAN
        .replace("dt = 5e-5 ", "dt = 1e-4 ")
        .replace("history_every = 200", "history_every = 1")
        .replace("[time]\n", "[time]\nduration = 15.0\n");
    let sol = run(&text, "plan.toml");
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    assert!(
        sol.summary.energy_balance_error < 1e-9,
        "{}",
        sol.summary.energy_balance_error
    );
    let tables = sol.tables();
    let t = tables
        .iter()
        .find(|t| t.name == "shear_keys")
        .expect("shear_keys.csv");
    let n = t.columns.len();
    assert_eq!(n, 5);
    let (fy, gap) = (1.8e6, 0.015);
    let mut peak = [(0.0f64, 0.0f64); 2];
    for row in t.values.chunks(n) {
        for side in 0..2 {
            let (v, f) = (row[1 + 2 * side], row[2 + 2 * side]);
            assert!(f.abs() <= fy * (1.0 + 1e-12), "{f}");
            assert!(
                f * v >= 0.0,
                "the force opposes the displacement: v {v}, F {f}"
            );
            if v.abs() < gap {
                assert_eq!(f, 0.0, "inside the gap: v {v}, F {f}");
            }
            peak[side] = (peak[side].0.max(f.abs()), peak[side].1.max(v.abs()));
        }
    }
    for (k, p) in sol.summary.shear_keys.iter().zip(peak) {
        assert_eq!((k.peak_force, k.peak_deformation), p, "{}", k.side);
        assert!(k.peak_deformation > gap, "the keys engage");
    }
}

/// Bad shear-key tables are refused naming the key and its line.
#[test]
fn bad_shear_keys_are_refused_with_key_and_line() {
    let start = BRIDGE_P_PLAN.find("[abutment.start.shear_keys]").unwrap();
    let end = BRIDGE_P_PLAN[start..].find("\n\n").unwrap() + start;
    let with = |table: &str| {
        format!(
            "{}[abutment.start.shear_keys]\n{table}{}",
            &BRIDGE_P_PLAN[..start],
            &BRIDGE_P_PLAN[end..]
        )
    };
    let cases = [
        (
            "fy = 1e6\ngap = 0.01\n",
            "shear_keys.k",
            "is required",
            "[abutment.start.shear_keys]",
        ),
        ("k = 2e8\nfy = -1.0\n", "shear_keys.fy", "> 0", "fy = -1.0"),
        (
            "k = 2e8\nfy = 1e6\ngap = -0.01\n",
            "shear_keys.gap",
            "[0, 1e3]",
            "gap = -0.01",
        ),
        (
            "k = 2e8\nfy = 1e6\nafter_yield = \"brittle\"\n",
            "shear_keys.after_yield",
            "recentering",
            "after_yield = \"brittle\"",
        ),
    ];
    for (table, key, why, bad) in cases {
        let text = with(table);
        let err = error(&text);
        assert!(err.contains(key) && err.contains(why), "{table}: {err}");
        let line = text.lines().position(|l| l == bad).unwrap() + 1;
        assert!(
            err.contains(&format!("walls.toml:{line}")),
            "{table}: not line {line} in {err}"
        );
    }
}

/// The plan bridge P against the independent OpenSeesPy 3.7.1 plan model on the figures that
/// model itself reproduces across dt = 5e-5, 2.5e-5 and 1.25e-5 s (its band `[min, max]` over the
/// three; the contact-force peaks, transverse pier drifts, rotations and counts move by up to 50 %
/// with the step there and are not compared): backfill forces, joint and abutment closings and
/// column forces within 3 % of the band, pier drifts along the bridge and deck peaks within 5 %.
/// OpenSees' x is along the bridge toward the end abutment (−y here), its y is +x here.
#[test]
fn plan_bridge_p_within_the_opensees_band() {
    let text = BRIDGE_P_PLAN.replace("history_every = 200", "history_every = 5");
    let sol = run(&text, "plan.toml");
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    let s = &sol.summary;
    let band = |what: &str, ours: f64, (lo, hi): (f64, f64), tol: f64| {
        assert!(
            ours >= lo * (1.0 - tol) && ours <= hi * (1.0 + tol),
            "{what}: {ours} outside OpenSees' [{lo}, {hi}] ± {:.0} %",
            tol * 100.0
        );
    };
    let walls = [(3.672, 3.707), (3.797, 3.840)];
    let abut_closing = [(0.04245, 0.04293), (0.04278, 0.04424)];
    for (side, a) in s.abutments.iter().flatten().enumerate() {
        let w = a.backwall.as_ref().unwrap();
        band(
            "backfill",
            w.peak_backfill_force.unwrap() / 1e6,
            walls[side],
            0.03,
        );
        band("abutment closing", a.peak_closing, abut_closing[side], 0.03);
    }
    for (j, r) in s
        .joints
        .iter()
        .zip([(0.02305, 0.02346), (0.02431, 0.02551)])
    {
        band("joint closing", j.peak_closing, r, 0.03);
    }
    // piers.csv: per pier ux, uy, fx, fy; along the bridge is y here
    let tables = sol.tables();
    let piers = tables.iter().find(|t| t.name == "piers").unwrap();
    let n = piers.columns.len();
    let peak = |c: usize| {
        piers
            .values
            .chunks(n)
            .map(|r| r[c].abs())
            .fold(0.0, f64::max)
    };
    let along = [(0.02309, 0.02383), (0.02504, 0.02697)];
    let force_along = [(1.213, 1.214), (1.216, 1.219)];
    let force_across = [(1.236, 1.256), (1.228, 1.239)];
    for p in 0..2 {
        band("pier drift along", peak(2 + 4 * p), along[p], 0.05);
        band("column along", peak(4 + 4 * p) / 1e6, force_along[p], 0.03);
        band(
            "column across",
            peak(3 + 4 * p) / 1e6,
            force_across[p],
            0.03,
        );
    }
    // decks: peak along (−y) of decks 1 and 2, peak across (x) of deck 2
    // (segment j's (x, y, θ) are q[3j..3j + 3])
    let pk = |i: usize| {
        (0..sol.t.len())
            .map(|r| sol.q_row(r)[i].abs())
            .fold(0.0, f64::max)
    };
    band("deck 1 along", pk(1), (0.08837, 0.09143), 0.05);
    band("deck 2 along", pk(4), (0.09902, 0.09994), 0.05);
    band("deck 2 across", pk(3), (0.1543, 0.1544), 0.05);
}

/// Fragility limit states of the substructure: `pier_drift`, `backwall` and `shear_key` read the
/// run's piers, backwalls and keys (ratio = the largest demand over the limit; a key that yields
/// exceeds), and are refused on a bridge without them, naming the limit state's kind.
#[test]
fn substructure_limit_states_read_the_members() {
    use pounding::assessment::FragilitySettings;
    use pounding::assessment::limit::bind;
    let frag = "\n[fragility]\nim = \"pga\"\nlevels_g = [0.1, 0.3]\n\n[[limit_state]]\nname = \"drift\"\n\
                kind = \"pier_drift\"\nlimit_m = 0.02\n\n[[limit_state]]\nname = \"wall\"\n\
                kind = \"backwall\"\nlimit_m = 0.03\n\n[[limit_state]]\nname = \"keys\"\n\
                kind = \"shear_key\"\n";
    let text = BRIDGE_P_PLAN
        .replace("dt = 5e-5 ", "dt = 1e-4 ")
        .replace("[time]\n", "[time]\nduration = 8.0\n")
        + frag;
    let f = FragilitySettings::from_scenario(&text, "s.toml").unwrap();
    let setup = Scenario::from_toml(&text, "s.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let lims = bind(&f.limit_states, &setup.problem.model, "s.toml").unwrap();
    let s = setup.run().unwrap().summary;
    let drift = s
        .piers
        .iter()
        .map(|p| p.peak_drift_magnitude)
        .fold(0.0, f64::max);
    let wall = s
        .abutments
        .iter()
        .flatten()
        .map(|a| a.backwall.as_ref().unwrap().peak_displacement)
        .fold(0.0, f64::max);
    let key = s
        .shear_keys
        .iter()
        .map(|k| k.peak_force)
        .fold(0.0, f64::max);
    for (l, want) in lims.iter().zip([drift / 0.02, wall / 0.03, key / 1.8e6]) {
        let (exceeded, ratio) = l.evaluate(&s);
        assert_eq!(ratio, want, "{}", l.state.name);
        let keys_yield = s.shear_keys.iter().any(|k| k.yielded);
        let want_exceeded = if l.state.name == "keys" {
            keys_yield
        } else {
            want > 1.0
        };
        assert_eq!(exceeded, Some(want_exceeded), "{}", l.state.name);
    }
    assert!(
        s.piers
            .iter()
            .all(|p| p.peak_drift_magnitude >= p.peak_drift[0].max(p.peak_drift[1]))
    );
    // on a bridge without piers, backwalls or keys: refused naming the kind
    let plain = include_str!("../../../../examples/viaduct-1d.toml").to_string() + frag;
    let f = FragilitySettings::from_scenario(&plain, "p.toml").unwrap();
    let setup = Scenario::from_toml(&plain, "p.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let e = bind(&f.limit_states, &setup.problem.model, "p.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("limit_state[0].kind") && e.contains("no piers"),
        "{e}"
    );
}

/// A backfill whose unloading is softer than its loading would create energy: refused naming
/// `kur` and its line; a wall mass too small for its backfill is refused naming `dt` with a
/// readable bound; the Caltrans/explicit clash names the key actually written.
#[test]
fn backfill_refusals_name_what_is_wrong() {
    let text = with_start_wall(
        "mass = 1.0e5\nkmax = 2.436e8\nkur = 1.0e3\nfult = 3.912e6\npiles_k = 6.3e7\npiles_fy = 1.071e6\n",
    );
    let err = error(&text);
    let line = text.lines().position(|l| l == "kur = 1.0e3").unwrap() + 1;
    assert!(
        err.contains("backwall.kur")
            && err.contains(">=")
            && err.contains(&format!("walls.toml:{line}")),
        "{err}"
    );
    let text = with_start_wall("mass = 1.0e5\nkmax = 2.436e8\nfult = 3.912e6\nskew_deg = 30.0\n");
    let err = error(&text);
    assert!(
        err.contains("backwall.skew_deg") && err.contains("not both"),
        "{err}"
    );
    let err = error(&with_start_wall(
        "mass = 1e-300\nkmax = 2.436e8\nfult = 3.912e6\npiles_k = 6.3e7\npiles_fy = 1.071e6\n",
    ));
    assert!(err.contains("dt") && !err.contains("0.000e0"), "{err}");
    let err = error(&with_start_wall(
        "mass = 1.0e5\nkmax = 1e300\nfult = 3.912e6\npiles_k = 6.3e7\npiles_fy = 1.071e6\n",
    ));
    assert!(err.contains("dt") && err.len() < 600, "{err}");
}

/// A backwall on backfill alone (compression only) is free to move toward the deck: refused as a
/// mechanism naming `piles_k`, unless `bridge.allow_mechanism = true`.
#[test]
fn a_backwall_without_piles_is_a_mechanism() {
    let text = with_start_wall("mass = 1.0e5\nkmax = 2.436e8\nfult = 3.912e6\n");
    let err = error(&text);
    assert!(
        err.contains("backwall.piles_k") && err.contains("allow_mechanism"),
        "{err}"
    );
    let allowed = text
        .replacen("[bridge]\n", "[bridge]\nallow_mechanism = true\n", 1)
        .replace("[time]\n", "[time]\nduration = 2.0\n");
    let sol = run(&allowed, "walls.toml");
    assert!(sol.summary.energy_balance_error < 1e-9);
}
