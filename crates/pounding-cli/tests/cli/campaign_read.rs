//! Reading a campaign store through its spec: `fragility --from-store --campaign` fits a
//! variant's runs as the campaign made them (its own record set and stripes, the variant's
//! bridge) and equals the direct study of that bridge; `check --from-store` counts the stored
//! seat demands against the provided and the codes' seats, and the counts equal those taken
//! from the direct study's `runs.csv`.

use crate::{run_capture, scratch_with};

const VIADUCT: &str = include_str!("../../../../examples/fragility/viaduct.toml");
const LEVELS: &str = "levels_g = [0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.4]";

/// The example viaduct with 2 s runs and a small bootstrap (its own 3 stripes), a suite of 3
/// pairs the campaign uses instead of the scenario's, and a spec with its own 2 stripes and 2
/// variants (one with short seats, so that some ends lose their seat).
fn files() -> Vec<(&'static str, String)> {
    let scenario = VIADUCT
        .replace("duration = 15.0", "duration = 2.0")
        .replace(LEVELS, "levels_g = [0.2, 0.5, 1.0]")
        .replace("bootstrap = 500", "bootstrap = 40");
    assert!(
        scenario.contains("[code_check]"),
        "the example has its code check"
    );
    assert!(scenario.contains("levels_g = [0.2, 0.5, 1.0]"));
    let suite = "[synth]\ncount = 3\nseed = 7\npairs = true\nduration = 3.0\n".to_string();
    let spec = "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"suite3.toml\"\n\
                levels_g = [0.4, 1.2]\nruns_per_part = 4\n\n\
                [[variant]]\nname = \"as-built\"\n[variant.set]\n\"bridge.gap\" = 0.02\n\n\
                [[variant]]\nname = \"short-seats\"\n[variant.set]\n\"bridge.seat_length\" = 0.02\n"
        .to_string();
    // the short-seat variant's scenario written by hand, with the campaign's stripes
    let short = scenario
        .replace("seat_length = 0.25\n", "seat_length = 0.02\n")
        .replace("levels_g = [0.2, 0.5, 1.0]", "levels_g = [0.4, 1.2]");
    assert!(short.contains("\nseat_length = 0.02\n"));
    vec![
        ("viaduct.toml", scenario),
        ("suite.toml", suite.clone()), // the scenario's own record set
        ("suite3.toml", suite),
        ("spec.toml", spec),
        ("short.toml", short),
    ]
}

fn ok(args: &[&str]) -> String {
    let (code, out, err) = run_capture(args);
    assert!(code == Some(0) || code == Some(1), "{args:?}: {out}\n{err}");
    out
}

fn csv(path: &std::path::Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let head = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (head, rows)
}

fn col(head: &[String], name: &str) -> usize {
    head.iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {head:?}"))
}

#[test]
fn a_store_read_through_its_spec_equals_the_direct_study_and_counts_seat_demands() {
    let f = files();
    let refs: Vec<(&str, &str)> = f.iter().map(|(a, b)| (*a, b.as_str())).collect();
    let d = scratch_with("campaign-read", "spec", &refs);
    let p = |s: &str| d.join(s).display().to_string();
    let out = ok(&["campaign", "run", &p("spec.toml"), "--out", &p("store")]);
    assert!(out.contains("merged 12 runs"), "{out}");

    // without the spec the scenario's own stripes do not match the store: refused
    let (code, _, err) = run_capture(&[
        "fragility",
        &p("viaduct.toml"),
        "--from-store",
        &p("store"),
        "--variant",
        "short-seats",
        "--out",
        &p("f0"),
    ]);
    assert_ne!(code, Some(0), "{err}");
    // through the spec: the variant's study, equal to the hand-edited scenario run directly
    ok(&[
        "fragility",
        &p("viaduct.toml"),
        "--from-store",
        &p("store"),
        "--campaign",
        &p("spec.toml"),
        "--variant",
        "short-seats",
        "--out",
        &p("f1"),
    ]);
    ok(&[
        "fragility",
        &p("short.toml"),
        "--set",
        &p("suite3.toml"),
        "--out",
        &p("f2"),
    ]);
    for name in ["runs.csv", "fragility.csv"] {
        assert_eq!(
            std::fs::read(d.join("f1").join(name)).unwrap(),
            std::fs::read(d.join("f2").join(name)).unwrap(),
            "{name}"
        );
    }

    // the code check of the variant's bridge against the stored demands
    let out = ok(&[
        "check",
        &p("viaduct.toml"),
        "--from-store",
        &p("store"),
        "--campaign",
        &p("spec.toml"),
        "--variant",
        "short-seats",
        "--out",
        &p("c1"),
    ]);
    assert!(out.contains("variant short-seats"), "{out}");
    ok(&["check", &p("short.toml"), "--out", &p("c2")]);
    assert_eq!(
        std::fs::read(d.join("c1/check.csv")).unwrap(),
        std::fs::read(d.join("c2/check.csv")).unwrap(),
        "the variant's code check is the hand-edited bridge's"
    );
    let (rh, runs) = csv(&d.join("f2/runs.csv"));
    let (ch, check) = csv(&d.join("c2/check.csv"));
    let (sh, stored) = csv(&d.join("c1/check_store.csv"));
    let (level, status) = (col(&rh, "level_g"), col(&rh, "status"));
    let mut some_exceeded = false;
    for c in &check {
        let end = &c[col(&ch, "end")];
        let seat: f64 = c[col(&ch, "seat_length_m")].parse().unwrap();
        let governing: Option<f64> = c[col(&ch, "governing_m")].parse().ok();
        let ratio = col(&rh, &format!("seat_ratio_{}", end.replace('-', "_")));
        for (basis, length) in [("provided", Some(seat)), ("governing", governing)] {
            let Some(length) = length else { continue };
            for (b, level_g) in ["0.4", "1.2"].iter().enumerate() {
                let trusted: Vec<&Vec<String>> = runs
                    .iter()
                    .filter(|r| r[level] == *level_g && r[status] == "Completed")
                    .collect();
                let exceeded = trusted
                    .iter()
                    .filter(|r| r[ratio].parse::<f64>().unwrap() * seat > length)
                    .count();
                let row = stored
                    .iter()
                    .find(|r| {
                        r[col(&sh, "end")] == *end
                            && r[col(&sh, "seat")] == basis
                            && r[col(&sh, "stripe")] == b.to_string()
                    })
                    .unwrap_or_else(|| panic!("no row {end} {basis} {b}"));
                assert_eq!(row[col(&sh, "seat_m")].parse::<f64>().unwrap(), length);
                assert_eq!(row[col(&sh, "level_g")], *level_g);
                assert_eq!(
                    row[col(&sh, "runs")],
                    trusted.len().to_string(),
                    "{end} {basis}"
                );
                assert_eq!(
                    row[col(&sh, "exceeded")],
                    exceeded.to_string(),
                    "{end} {basis}"
                );
                let lo: f64 = row[col(&sh, "fraction_lo_95")].parse().unwrap();
                let hi: f64 = row[col(&sh, "fraction_hi_95")].parse().unwrap();
                let frac = exceeded as f64 / trusted.len() as f64;
                assert!(lo <= frac && frac <= hi && 0.0 <= lo && hi <= 1.0);
                some_exceeded |= basis == "provided" && exceeded > 0;
            }
        }
    }
    assert!(
        some_exceeded,
        "the short seats are lost in some runs: the test has teeth"
    );

    // refusals: a variant without the spec; a scenario that is not the spec's; another store
    let (code, _, err) = run_capture(&[
        "check",
        &p("viaduct.toml"),
        "--from-store",
        &p("store"),
        "--variant",
        "short-seats",
    ]);
    assert_eq!(code, Some(2), "{err}");
    let (code, _, err) = run_capture(&[
        "check",
        &p("short.toml"),
        "--from-store",
        &p("store"),
        "--campaign",
        &p("spec.toml"),
        "--variant",
        "short-seats",
    ]);
    assert_ne!(code, Some(0));
    assert!(err.contains("is not the scenario of the campaign"), "{err}");
    let (code, _, err) = run_capture(&[
        "check",
        &p("viaduct.toml"),
        "--from-store",
        &p("store"),
        "--campaign",
        &p("spec.toml"),
    ]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("2 variants") && err.contains("--variant"),
        "{err}"
    );
    std::fs::write(
        d.join("other.toml"),
        f[3].1
            .replace("levels_g = [0.4, 1.2]", "levels_g = [0.4, 1.3]"),
    )
    .unwrap();
    let (code, _, err) = run_capture(&[
        "check",
        &p("viaduct.toml"),
        "--from-store",
        &p("store"),
        "--campaign",
        &p("other.toml"),
        "--variant",
        "short-seats",
    ]);
    assert_ne!(code, Some(0));
    assert!(err.contains("another campaign"), "{err}");
}

/// Messages a trial found unclear: the spec's own record set that cannot be read names the
/// spec's key and line; an infinite stripe is "not a finite number"; an empty name is refused.
#[test]
fn spec_messages_name_the_spec_key() {
    let f = files();
    let refs: Vec<(&str, &str)> = f.iter().map(|(a, b)| (*a, b.as_str())).collect();
    let d = scratch_with("campaign-read", "messages", &refs);
    let p = |s: &str| d.join(s).display().to_string();
    for (spec, want) in [
        (
            "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"nope.toml\"\n",
            "`campaign.records` (",
        ),
        (
            "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"suite3.toml\"\n\
             levels_g = [0.1, inf]\n",
            "inf is not a finite number",
        ),
        (
            "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"suite3.toml\"\nname = \" \"\n",
            "the name is empty",
        ),
    ] {
        std::fs::write(d.join("bad.toml"), spec).unwrap();
        let (code, _, err) = run_capture(&["campaign", "run", &p("bad.toml"), "--out", &p("o")]);
        assert_eq!(code, Some(2), "{spec}: {err}");
        assert!(
            err.contains(want) && err.contains("bad.toml:"),
            "{spec}: {err}"
        );
        assert!(!d.join("o").exists(), "nothing written");
    }
    // a bad variant name is not reported as a variant named ""
    std::fs::write(
        d.join("bad.toml"),
        "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"suite3.toml\"\n[[variant]]\n\
         name = \"x/y\"\n[variant.set]\n\"bridge.gap\" = 0.03\n",
    )
    .unwrap();
    let (code, _, err) = run_capture(&["campaign", "run", &p("bad.toml"), "--out", &p("o")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("bad.toml:5") && err.contains("variant[0].name"),
        "{err}"
    );
    assert!(!err.contains("variant \"\""), "{err}");
    // a merge of a path that is no store leaves no --out behind
    let (code, _, err) = run_capture(&["campaign", "merge", &p("nosuch"), "--out", &p("m")]);
    assert_ne!(code, Some(0), "{err}");
    assert!(!d.join("m").exists(), "{err}");
}

/// Found by a fresh-clone trial: a store of one variant that is not the scenario's own bridge
/// was read as that bridge without `--campaign` (wrong seat demands, exit 0); a store without
/// seat ratios gave counts of 0 runs; a variant could be named `base`.
#[test]
fn stores_that_are_not_the_scenarios_bridge_are_refused() {
    let f = files();
    let refs: Vec<(&str, &str)> = f.iter().map(|(a, b)| (*a, b.as_str())).collect();
    let d = scratch_with("campaign-read", "refusals", &refs);
    let p = |s: &str| d.join(s).display().to_string();
    let one = "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"suite3.toml\"\n\
               levels_g = [0.4]\n[[variant]]\nname = \"short\"\n[variant.set]\n\
               \"bridge.seat_length\" = 0.1\n";
    std::fs::write(d.join("one.toml"), one).unwrap();
    ok(&["campaign", "run", &p("one.toml"), "--out", &p("s1")]);
    for cmd in ["check", "fragility"] {
        let (code, _, err) = run_capture(&[
            cmd,
            &p("viaduct.toml"),
            "--from-store",
            &p("s1"),
            "--out",
            &p("o1"),
        ]);
        assert_ne!(code, Some(0), "{cmd}: {err}");
        assert!(
            err.contains("not the scenario's own bridge"),
            "{cmd}: {err}"
        );
    }
    // through its spec it is read
    ok(&[
        "check",
        &p("viaduct.toml"),
        "--from-store",
        &p("s1"),
        "--campaign",
        &p("one.toml"),
        "--variant",
        "short",
    ]);
    // `base` is reserved
    std::fs::write(
        d.join("base.toml"),
        one.replace("name = \"short\"", "name = \"base\""),
    )
    .unwrap();
    let (code, _, err) = run_capture(&["campaign", "run", &p("base.toml"), "--out", &p("s2")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("reserved") && err.contains("base.toml:"),
        "{err}"
    );
    // a store without seat ratios has no seat demand to count
    let noseats = "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"suite3.toml\"\n\
                   levels_g = [0.4]\n[outputs]\nseats = false\n";
    std::fs::write(d.join("noseats.toml"), noseats).unwrap();
    ok(&["campaign", "run", &p("noseats.toml"), "--out", &p("s3")]);
    let (code, _, err) = run_capture(&[
        "check",
        &p("viaduct.toml"),
        "--from-store",
        &p("s3"),
        "--campaign",
        &p("noseats.toml"),
    ]);
    assert_ne!(code, Some(0), "{err}");
    assert!(err.contains("no seat ratios"), "{err}");
    // a store path that does not exist is named
    let (code, _, err) = run_capture(&[
        "check",
        &p("viaduct.toml"),
        "--from-store",
        &p("nosuch"),
        "--campaign",
        &p("noseats.toml"),
    ]);
    assert_ne!(code, Some(0));
    assert!(
        err.contains("no campaign store at") && err.contains("nosuch"),
        "{err}"
    );
}
