//! Findings of a fresh-clone trial of `pounding fragility` / `motion synth` (issue 13), each
//! pinned: left-censored IDA data, metadata names that clash with output columns, absurd periods,
//! levels and synthetic-record settings.

use pounding::assessment::Stripes;
use pounding::assessment::run::{Plan, RunRow, fit_limit_state};
use pounding::fragility::{BootstrapSettings, Fit, NoMle};

/// A run of entry `record` at stripe `stripe` with one limit state (also used by
/// `fragility_censored`).
pub(crate) fn run(record: usize, stripe: usize, im: f64, ex: bool, ratio: f64) -> RunRow {
    RunRow {
        record,
        stripe,
        im_g: im,
        scale_factor: im,
        status: "Completed".into(),
        error: String::new(),
        limits: vec![(Some(ex), ratio)],
        warnings: 0,
        seats: Vec::new(),
        governing_seat: None,
    }
}

fn ida_plan(entries: usize) -> Plan {
    Plan {
        entry_im: vec![1.0; entries],
        stripes: Stripes::Scales(vec![1.0, 2.0, 4.0]),
    }
}

fn boot() -> BootstrapSettings {
    BootstrapSettings {
        samples: 200,
        seed: 1,
        level: 0.95,
    }
}

#[test]
fn ida_records_exceeding_at_the_first_scale_are_left_censored_in_the_fit() {
    // Three records: two exceed only at larger scales, one already at the first scale (its IM at
    // first exceedance is only an upper bound). The first trial fitted it as exact (`ok`, biased);
    // round 4 refused it (`exceeded_at_first`); now it is a left-censored record of the censored
    // MLE (`mle_censored_ida`), never an exact observation.
    let rows = vec![
        run(0, 0, 1.0, false, 0.5),
        run(0, 1, 2.0, true, 1.5),
        run(0, 2, 4.0, true, 3.0),
        run(1, 0, 1.0, false, 0.9),
        run(1, 1, 2.0, false, 0.95),
        run(1, 2, 4.0, true, 1.1),
        run(2, 0, 1.0, true, 1.2),
        run(2, 1, 2.0, true, 2.0),
        run(2, 2, 4.0, true, 3.0),
    ];
    let r = fit_limit_state("ls", &ida_plan(3), &rows, 0, &boot(), &[1.0, 2.0]).unwrap();
    use pounding::fragility::{CensoredIdaData, IdaRecord, Method, censored_mle};
    let expect = CensoredIdaData {
        records: vec![
            IdaRecord::Exceeded(1.0 + (1.0 - 0.5) / (1.5 - 0.5)),
            IdaRecord::Exceeded(2.0 + (1.0 - 0.95) / (1.1 - 0.95) * 2.0),
            IdaRecord::ExceededAtFirst(1.0),
        ],
    };
    assert_eq!(r.method, Method::MleCensoredIda { right: 0, left: 1 });
    assert_eq!(r.fit, censored_mle(&expect).unwrap());
    assert_eq!(r.fit.status(), "ok");
    let csv = pounding::fragility::fragility_csv(std::slice::from_ref(&r));
    let line = csv.lines().nth(1).unwrap();
    assert!(line.starts_with("ls,mle_censored_ida,ok,"), "{line}");
    let j = pounding::fragility::fragility_json(std::slice::from_ref(&r));
    assert_eq!(j["fits"][0]["exceeded_at_first"], 1);
    assert_eq!(j["fits"][0]["censored"], 0);
    assert!(j["fits"][0]["theta"].is_f64());

    // All three exceed at the first scale (the trial's case): no numbers (θ → 0).
    let all: Vec<RunRow> = (0..3)
        .flat_map(|a| {
            (0..3).map(move |b| run(a, b, [1.0, 2.0, 4.0][b] * (1.0 + a as f64), true, 2.0))
        })
        .collect();
    let r = fit_limit_state("ls", &ida_plan(3), &all, 0, &boot(), &[1.0]).unwrap();
    assert_eq!(r.fit, Fit::NoFiniteMle(NoMle::AllExceeded));
    assert!(r.fit.params().is_none());

    // Control: the same records with record 2 crossing between scales 1 and 2 keep the method
    // of moments.
    let mut fixed = rows.clone();
    fixed[6] = run(2, 0, 1.0, false, 0.6);
    let r = fit_limit_state("ls", &ida_plan(3), &fixed, 0, &boot(), &[1.0]).unwrap();
    assert_eq!(r.fit.status(), "ok");
    assert_eq!(r.method, Method::MomentsIda);
}

fn set_err(manifest: &str) -> String {
    let d = crate::scratch::scratch_dir("ft", &manifest.len().to_string());
    std::fs::write(d.join("a.txt"), "0.0\n1.0\n-2.0\n0.5\n").unwrap();
    std::fs::write(d.join("set.toml"), manifest).unwrap();
    pounding::ground_motion::set::RecordSet::load(&d.join("set.toml"))
        .unwrap_err()
        .to_string()
}

#[test]
fn metadata_names_that_repeat_a_runs_csv_column_are_refused() {
    for key in [
        "status",
        "record",
        "level_g",
        "scale",
        "im_g",
        "scale_factor",
        "error",
        "unseating_ratio",
        "drift_exceeded",
    ] {
        let m = format!(
            "[[record]]\nid = \"A\"\nx = \"a.txt\"\ndt = 0.01\n\n[record.meta]\n{key} = \"x\"\n"
        );
        let e = set_err(&m);
        assert!(e.contains(&format!("record[0].meta.{key}")), "{e}");
        assert!(e.contains("set.toml: table at line 6"), "{e}");
        assert!(e.contains("runs.csv"), "{e}");
    }
    // blank or space-padded names would be blank or misleading columns (a hostile trial saw a
    // `meta_ ` column)
    for key in ["\" \"", "\" pga\""] {
        let m = format!(
            "[[record]]\nid = \"A\"\nx = \"a.txt\"\ndt = 0.01\n\n[record.meta]\n{key} = 1\n"
        );
        let e = set_err(&m);
        assert!(
            e.contains("not blank, no leading or trailing spaces"),
            "{e}"
        );
    }
    // a harmless name next to them still reads
    let d = crate::scratch::scratch_dir("ft", "ok");
    std::fs::write(d.join("a.txt"), "0.0\n1.0\n").unwrap();
    std::fs::write(
        d.join("set.toml"),
        "[[record]]\nid = \"A\"\nx = \"a.txt\"\ndt = 0.01\n[record.meta]\nstation_status = 1\n",
    )
    .unwrap();
    let s = pounding::ground_motion::set::RecordSet::load(&d.join("set.toml")).unwrap();
    assert_eq!(s.meta_keys(), vec!["station_status"]);
}

#[test]
fn a_one_column_record_in_a_manifest_names_the_manifest_key_dt() {
    let e = set_err("[[record]]\nid = \"A\"\nx = \"a.txt\"\n");
    assert!(e.contains("dt = SECONDS in this [[record]]"), "{e}");
    assert!(!e.contains("--record-dt"), "{e}");
    assert!(!e.contains("record_dt"), "{e}");
}

#[test]
fn intervals_from_few_records_or_many_failed_replicates_are_flagged() {
    use pounding::fragility::{IdaData, bootstrap_ida};
    let ims = |n: usize| IdaData {
        im_at_exceedance: (0..n).map(|i| Some(0.2 + 0.05 * i as f64)).collect(),
    };
    let row = |n: usize| {
        let d = ims(n);
        let b = bootstrap_ida(&d, &boot(), &[]).unwrap();
        pounding::fragility::FragilityRow::from_ida("ls", &d, Some(b)).unwrap()
    };
    let few = row(5);
    assert_eq!(few.fit.status(), "ok");
    let w = few.interval_warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("only 5 records"), "{w:?}");
    assert_eq!(
        few.bootstrap_failed(),
        Some(few.bootstrap.as_ref().unwrap().failed)
    );
    assert!(row(12).interval_warnings().is_empty());
    // many failed replicates: a hand-set count
    let mut many = row(12);
    many.bootstrap.as_mut().unwrap().failed = 21; // of 200: 10.5 %
    let w = many.interval_warnings();
    assert!(w.len() == 1 && w[0].contains("21 of 200"), "{w:?}");
    many.bootstrap.as_mut().unwrap().failed = 20; // exactly 10 %: not flagged
    assert!(many.interval_warnings().is_empty());
    // no fit: no failed count (not samples/samples), no warning
    let d = IdaData {
        im_at_exceedance: vec![Some(0.3), None, Some(0.4)],
    };
    let b = bootstrap_ida(&d, &boot(), &[]).unwrap();
    let none = pounding::fragility::FragilityRow::from_ida("ls", &d, Some(b)).unwrap();
    assert_eq!(none.bootstrap_failed(), None);
    assert!(none.interval_warnings().is_empty());
    let csv = pounding::fragility::fragility_csv(std::slice::from_ref(&none));
    assert!(csv.lines().nth(1).unwrap().ends_with(",200,nan"), "{csv}");
}

/// Two replicates (the hostile report: θ = 0.40337 with an interval [0.40351, 0.624]): the
/// intervals are flagged as too few replicates, and an interval that misses its own estimate
/// says so, in `interval_warnings` and in `fragility.json`.
#[test]
fn an_interval_from_too_few_replicates_or_missing_its_estimate_says_why() {
    use pounding::fragility::{IdaData, bootstrap_ida};
    let d = IdaData {
        im_at_exceedance: (0..12).map(|i| Some(0.2 + 0.05 * i as f64)).collect(),
    };
    let two = BootstrapSettings {
        samples: 2,
        ..boot()
    };
    let b = bootstrap_ida(&d, &two, &[]).unwrap();
    let mut row = pounding::fragility::FragilityRow::from_ida("ls", &d, Some(b)).unwrap();
    let w = row.interval_warnings();
    assert!(
        w.iter().any(|m| m.contains("only 2 bootstrap replicates")),
        "{w:?}"
    );
    // an interval that excludes the estimate, hand-set as in the report
    let (theta, _) = row.fit.params().unwrap();
    row.bootstrap.as_mut().unwrap().theta = Some((theta * 1.0004, theta * 1.5));
    let w = row.interval_warnings();
    assert!(
        w.iter()
            .any(|m| m.contains("theta interval") && m.contains("does not contain")),
        "{w:?}"
    );
    let j = pounding::fragility::fragility_json(std::slice::from_ref(&row));
    let listed = j["fits"][0]["interval_warnings"].as_array().unwrap();
    assert_eq!(listed.len(), w.len());
    // enough replicates and an interval around the estimate: nothing to say
    let b = bootstrap_ida(&d, &boot(), &[]).unwrap();
    let ok = pounding::fragility::FragilityRow::from_ida("ls", &d, Some(b)).unwrap();
    let (t, be) = ok.fit.params().unwrap();
    let bt = ok.bootstrap.as_ref().unwrap();
    assert!(bt.theta.unwrap().0 <= t && t <= bt.theta.unwrap().1);
    assert!(bt.beta.unwrap().0 <= be && be <= bt.beta.unwrap().1);
    assert!(
        ok.interval_warnings().is_empty(),
        "{:?}",
        ok.interval_warnings()
    );
}
