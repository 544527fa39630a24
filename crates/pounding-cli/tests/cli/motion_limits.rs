//! Limits of synthetic suites found by a fresh-clone trial: a suite too large to generate in
//! memory is refused up front (count × components × samples), a seed the written manifest
//! could not hold is refused, and exactly the minimum number of steps is accepted despite
//! rounding; each refusal exits 2 naming the flag or key, with nothing written.

use crate::motion::synth;
use crate::{run_capture, scratch_dir};
use pounding::ground_motion::synth::{MAX_SEED, MAX_SUITE_VALUES};
use std::path::Path;

/// The shipped fragility example (scenario and `[synth]` suite) copied to a scratch dir, the
/// suite's `[synth]` lines after `count` replaced by `synth`.
fn fragility_with_suite(name: &str, synth: &str) -> crate::Scratch {
    let d = scratch_dir("motionlim", name);
    let ex = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fragility");
    std::fs::copy(ex.join("viaduct.toml"), d.join("viaduct.toml")).unwrap();
    let suite = std::fs::read_to_string(ex.join("suite.toml")).unwrap();
    let head = &suite[..suite
        .find("count = 20")
        .expect("count in the example suite")];
    std::fs::write(d.join("suite.toml"), format!("{head}{synth}")).unwrap();
    d
}

fn fragility(d: &Path) -> (Option<i32>, String) {
    let (code, _, err) = run_capture(&[
        "fragility",
        d.join("viaduct.toml").to_str().unwrap(),
        "--out",
        d.join("out").to_str().unwrap(),
    ]);
    (code, err)
}

#[test]
fn a_suite_too_large_for_memory_is_refused_naming_count_and_the_product() {
    let d = scratch_dir("motionlim", "huge");
    // 100 x 1 x 9999001 samples: about 8 GB of f64 (it aborted out of memory)
    let (code, err, out) = synth(
        &d,
        "huge",
        &["--count", "100", "--dt", "0.001", "--duration", "9999"],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(!err.contains("panicked") && !err.contains("memory allocation"));
    let product = 100u64 * 9_999_001;
    for needle in [
        "--count = 100".to_string(),
        format!("{product} values"),
        MAX_SUITE_VALUES.to_string(),
    ] {
        assert!(err.contains(&needle), "{needle:?} not in {err}");
    }
    assert!(!out.exists(), "something was written");
    // the bound counts both components of a pair: a count of singles within it is refused
    // as pairs (5001 samples at the default dt over 50 s)
    let singles = MAX_SUITE_VALUES / 5001;
    assert!(singles <= 10_000 && singles * 2 * 5001 > MAX_SUITE_VALUES);
    let (code, err, _) = synth(
        &d,
        "pairs",
        &[
            "--count",
            &singles.to_string(),
            "--pairs",
            "--duration",
            "50",
        ],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("x 2 component(s)"), "{err}");

    // the same in a fragility study's [synth]: synth.count, nothing written
    let d = fragility_with_suite(
        "frag",
        "count = 10000\nseed = 1\npairs = true\ndt = 0.001\nduration = 9999.0\n",
    );
    let (code, err) = fragility(&d);
    assert_eq!(code, Some(2), "{err}");
    let product = 10_000u64 * 2 * 9_999_001;
    for needle in [
        "synth.count".to_string(),
        "count = 10000".to_string(),
        format!("{product} values"),
    ] {
        assert!(err.contains(&needle), "{needle:?} not in {err}");
    }
    assert!(!err.contains("--count") && !err.contains("--dt"), "{err}");
    assert!(!d.join("out").exists(), "something was written");
}

#[test]
fn a_seed_the_manifest_cannot_hold_is_refused() {
    let d = scratch_dir("motionlim", "seed");
    let over = (MAX_SEED + 1).to_string();
    assert_eq!(MAX_SEED, i64::MAX as u64);
    for (sub, extra) in [
        ("synth", &["--count", "1", "--duration", "2"][..]),
        (
            "svgm",
            &[
                "--count",
                "1",
                "--supports",
                "0,30",
                "--v-app",
                "250",
                "--duration",
                "2",
            ][..],
        ),
    ] {
        for seed in [over.as_str(), "18446744073709551615"] {
            let out = d.join(format!("{sub}{seed}"));
            let mut a = vec![
                "motion",
                sub,
                "--seed",
                seed,
                "--out",
                out.to_str().unwrap(),
            ];
            a.extend_from_slice(extra);
            let (code, _, err) = run_capture(&a);
            assert_eq!(code, Some(2), "{sub} {seed}: {err}");
            assert!(err.contains(&format!("--seed = {seed}")), "{err}");
            assert!(err.contains(&MAX_SEED.to_string()), "{err}");
            assert!(!out.exists(), "{sub} {seed}: something was written");
        }
    }
    // the largest seed is written and read back by a study
    let max = MAX_SEED.to_string();
    let out = d.join("max");
    let (code, _, err) = run_capture(&[
        "motion",
        "synth",
        "--seed",
        &max,
        "--count",
        "1",
        "--duration",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let set = pounding::ground_motion::set::RecordSet::load(&out.join("suite.toml"))
        .unwrap_or_else(|e| panic!("the written suite does not read back: {e}"));
    let seed = set.records[0]
        .meta
        .iter()
        .find(|(k, _)| k == "seed")
        .unwrap();
    assert_eq!(seed.1.csv_cell(), max);
}

#[test]
fn exactly_the_minimum_number_of_steps_is_accepted() {
    // 0.7 / 0.007 is 100.00000000000001 in floating point and 100 x 0.007 is
    // 0.7000000000000001: 100 steps were refused as fewer than 100
    let d = scratch_dir("motionlim", "steps");
    let (code, err, out) = synth(
        &d,
        "ok",
        &["--count", "1", "--dt", "0.007", "--duration", "0.7"],
    );
    assert_eq!(code, Some(0), "{err}");
    let at2 = std::fs::read_to_string(out.join("SYN001_x.AT2")).unwrap();
    assert!(at2.contains("NPTS= 101,"), "{at2}");
    // one step fewer is still refused
    let (code, err, _) = synth(
        &d,
        "short",
        &["--count", "1", "--dt", "0.007", "--duration", "0.693"],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("at least 100 steps"), "{err}");
}
