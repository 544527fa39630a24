//! The library's comparison (`sim::compare`): its runs are `simulate`'s runs of each law (same
//! summary numbers, the rigid estimate equal to `summary.json`'s), the flags are checked in
//! the CLI's order with its messages, and the agreement reports what the rows hold.

use pounding::sim::compare::{CompareError, CompareFlags, Comparison, LawRun, agreement, headline};
use pounding::sim::output::compare_tables;
use pounding::sim::scenario::Scenario;

fn flags(laws: &[&str]) -> CompareFlags {
    CompareFlags {
        laws: laws.iter().map(|l| l.to_string()).collect(),
        duration: Some(3.0),
        ..CompareFlags::default()
    }
}

fn runs(laws: &[&str]) -> Vec<LawRun> {
    let cmp = Comparison::prepare(Scenario::default(), &flags(laws)).unwrap();
    cmp.run(pounding::sim::Progress::default, |_| {}).unwrap()
}

#[test]
fn each_law_runs_as_simulate_and_the_rigid_estimate_is_the_summarys() {
    let laws = ["rigid", "kelvin", "bilinear"];
    let runs = runs(&laws);
    assert_eq!(runs.len(), 3);
    for r in &runs {
        let ran = r.ran().unwrap();
        // the same run through `simulate`'s path: the scenario with the law
        let setup = Scenario::default()
            .with_duration(3.0)
            .with_law(&r.law)
            .build_setup()
            .unwrap();
        let sol = setup.run().unwrap();
        let summary: serde_json::Value =
            serde_json::from_str(&setup.summary_json_text(&sol)).unwrap();
        assert_eq!(sol.summary.impacts, ran.sol.summary.impacts, "{}", r.law);
        assert_eq!(
            sol.summary.peak_seat_displacement, ran.sol.summary.peak_seat_displacement,
            "{}",
            r.law
        );
        let est = summary.get("peak_force_estimate_n");
        match ran.peak_estimate() {
            Some(e) => {
                assert_eq!(r.law, "rigid");
                assert_eq!(est.and_then(|v| v.as_f64()), Some(e.peak_force));
                assert!(e.contact_time > 0.0);
            }
            None => assert!(est.is_none(), "{}: {est:?}", r.law),
        }
    }
    // the CSV's estimate column and the headline hold the same number
    let csv = compare_tables(&runs, false).0.remove(0).csv;
    let rigid = csv.lines().nth(1).unwrap().split(',').collect::<Vec<_>>();
    let h = headline(
        &runs[0].ran().unwrap().setup,
        &runs[0].ran().unwrap().sol,
        runs[0].ran().unwrap().peak_estimate(),
    );
    assert_eq!(
        rigid[4].parse::<f64>().unwrap(),
        h.estimate.unwrap().peak_force
    );
    assert_eq!(h.force, None);
    // bilinear is too coarse at dt = 1e-3: its warning, the others none of that kind
    let coarse = |i: usize| {
        runs[i]
            .ran()
            .unwrap()
            .warnings
            .iter()
            .any(|w| w.kind == "time_step_coarse")
    };
    assert!(coarse(2) && !coarse(0) && !coarse(1));
}

#[test]
fn the_agreement_reports_the_rows() {
    let runs = runs(&["rigid", "kelvin", "hertz"]);
    let a = agreement(&runs);
    assert_eq!(a.overall[0], "The 3 laws agree that the structure pounds.");
    assert_eq!(
        a.laws.iter().map(|l| l.0.as_str()).collect::<Vec<_>>(),
        ["rigid", "kelvin", "hertz"]
    );
    // the computed forces' range names the weaker and the stronger law of the rows
    let f = |i: usize| runs[i].ran().unwrap().sol.summary.joints[0].peak_contact_force;
    let (k, h) = (f(1).unwrap(), f(2).unwrap());
    let (lo, hi) = if k < h {
        ("kelvin", "hertz")
    } else {
        ("hertz", "kelvin")
    };
    let force = a
        .overall
        .iter()
        .find(|s| s.starts_with("Peak contact force"))
        .unwrap();
    assert!(
        force.find(&format!("({lo})")) < force.find(&format!("({hi})")),
        "{force}"
    );
    assert!(force.contains("the rigid law's estimate"), "{force}");
    assert!(
        a.laws[0].1.contains("estimate from the impulse"),
        "{:?}",
        a.laws[0]
    );
}

#[test]
fn flags_are_checked_first_with_the_cli_messages() {
    let err = |f: CompareFlags| Comparison::prepare(Scenario::default(), &f).unwrap_err();
    let e = err(flags(&["rigid", "foo"]));
    assert!(matches!(e, CompareError::UnknownLaw { .. }));
    assert!(
        e.to_string()
            .starts_with("unknown contact law \"foo\" in --laws")
    );
    assert_eq!(
        err(flags(&["kelvin", " kelvin"])).to_string(),
        "contact law \"kelvin\" is given twice in --laws"
    );
    assert_eq!(err(flags(&[])).to_string(), "--laws is empty");
    let mut f = flags(&["rigid"]);
    f.dt = Some(0.0);
    // the one check of a step, said as `simulate --dt` says it
    assert_eq!(
        err(f).to_string(),
        "invalid dt = 0: must be finite and > 0 — set by --dt (command line, in place of `[time] \
         dt`)"
    );
    // a two-deck scenario with abutments refuses a compliance law: the law is named
    let sc = Scenario::from_toml("[abutments]\ngap1 = 0.05\ngap2 = 0.05\n", "ab.toml").unwrap();
    let e = Comparison::prepare(sc, &flags(&["rigid", "kelvin"])).unwrap_err();
    assert!(
        e.to_string().starts_with("contact law \"kelvin\": ") && e.to_string().contains("gap1"),
        "{e}"
    );
}
