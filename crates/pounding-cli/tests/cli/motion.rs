//! `pounding motion synth` (issue 13): the files and `suite.toml` it writes, the same bytes for
//! the same seed, `pounding simulate --record` reads a synthetic record without flags, and bad
//! flags exit 2 naming the flag with nothing written.

use crate::{run_capture, scratch_dir};

#[test]
fn synth_writes_records_and_a_manifest_that_simulate_reads() {
    let d = scratch_dir("motion", "files");
    let out = d.join("suite");
    let args = |o: &str| {
        vec![
            "motion",
            "synth",
            "--count",
            "4",
            "--seed",
            "7",
            "--pga",
            "0.3",
            "--duration",
            "8",
            "--pairs",
            "--out",
            o,
        ]
        .into_iter()
        .map(String::from)
        .collect::<Vec<_>>()
    };
    let a = args(out.to_str().unwrap());
    let (code, _, err) = run_capture(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, Some(0), "{err}");
    for id in ["SYN001", "SYN002", "SYN003", "SYN004"] {
        for c in ["x", "y"] {
            let f = out.join(format!("{id}_{c}.AT2"));
            let text = std::fs::read_to_string(&f).unwrap();
            assert!(text.lines().nth(2).unwrap().contains("UNITS OF G"));
            assert!(
                text.lines()
                    .nth(3)
                    .unwrap()
                    .starts_with("NPTS= 801, DT= 0.01")
            );
        }
    }
    let manifest: toml::Table = std::fs::read_to_string(out.join("suite.toml"))
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(manifest["set"]["name"].as_str(), Some("synthetic"));
    assert!(
        manifest["set"]["source"]
            .as_str()
            .unwrap()
            .starts_with("pounding motion synth --count 4 --seed 7")
    );
    let recs = manifest["record"].as_array().unwrap();
    assert_eq!(recs.len(), 4);
    assert_eq!(recs[2]["y"].as_str(), Some("SYN003_y.AT2"));
    assert_eq!(recs[2]["meta"]["pga_g"].as_float(), Some(0.3));
    assert_eq!(recs[2]["meta"]["seed"].as_integer(), Some(7));
    let readme = std::fs::read_to_string(out.join("SYNTHETIC.txt")).unwrap();
    assert!(readme.starts_with("SYNTHETIC GROUND MOTIONS"));
    // the same seed elsewhere: the same bytes
    let again = d.join("again");
    let a = args(again.to_str().unwrap());
    let (code, _, _) = run_capture(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, Some(0));
    for f in ["SYN003_y.AT2", "suite.toml", "SYNTHETIC.txt"] {
        assert_eq!(
            std::fs::read(out.join(f)).unwrap(),
            std::fs::read(again.join(f)).unwrap(),
            "{f}"
        );
    }
    // simulate reads a synthetic record without any flag
    let sim = d.join("sim");
    let (code, _, err) = run_capture(&[
        "simulate",
        "--record",
        out.join("SYN002_x.AT2").to_str().unwrap(),
        "--out",
        sim.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("pga_g 0.3"), "{err}");
    assert!(sim.join("summary.json").is_file());
}

/// Runs `pounding motion synth --seed 1 --out D/NAME EXTRA...`: (exit code, stderr, the output
/// directory).
pub(crate) fn synth(
    d: &std::path::Path,
    name: &str,
    extra: &[&str],
) -> (Option<i32>, String, std::path::PathBuf) {
    let out = d.join(name);
    let mut a = vec![
        "motion",
        "synth",
        "--seed",
        "1",
        "--out",
        out.to_str().unwrap(),
    ];
    a.extend_from_slice(extra);
    let (code, _, err) = run_capture(&a);
    (code, err, out)
}

#[test]
fn bad_synth_flags_exit_2_naming_the_flag_and_write_nothing() {
    let d = scratch_dir("motion", "bad");
    for (i, (args, flag)) in [
        (&["--count", "0"][..], "--count"),
        (&["--count", "10001"], "--count"),
        (&["--count", "1", "--dt", "0"], "--dt"),
        (&["--count", "1", "--dt", "-0.01"], "--dt"),
        (&["--count", "1", "--dt", "nan"], "--dt"),
        (&["--count", "1", "--duration", "0"], "--duration"),
        (&["--count", "1", "--dt", "2", "--duration", "1"], "--dt"),
        (&["--count", "1", "--pga", "0"], "--pga"),
        (&["--count", "1", "--pga", "-0.2"], "--pga"),
        (&["--count", "1", "--pga", "nan"], "--pga"),
        (&["--count", "1", "--pga", "inf"], "--pga"),
        (&["--count", "x"], "--count"),
    ]
    .into_iter()
    .enumerate()
    {
        let (code, err, out) = synth(&d, &format!("out{i}"), args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
        assert!(!err.contains("panicked"));
        assert!(!out.exists(), "{args:?} wrote outputs");
    }
}

/// A smaller suite written where a larger one was leaves none of the larger one's records
/// (a hostile trial found SYN003–SYN005 beside a two-entry manifest, read by `--records DIR`);
/// a file the generator did not write stays.
#[test]
fn a_smaller_suite_removes_the_records_of_a_larger_one() {
    let d = scratch_dir("motion", "stale");
    let out = d.join("suite");
    let synth = |count: &str| {
        let (code, _, err) = run_capture(&[
            "motion",
            "synth",
            "--count",
            count,
            "--seed",
            "4",
            "--duration",
            "2",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, Some(0), "{err}");
    };
    synth("4");
    std::fs::write(out.join("MINE_x.AT2"), "a user's record\n").unwrap();
    synth("2");
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "MINE_x.AT2",
            "SYN001_x.AT2",
            "SYN002_x.AT2",
            "SYNTHETIC.txt",
            "suite.toml"
        ]
    );
}
