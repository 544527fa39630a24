//! Limits of synthetic suites (a fresh-clone trial): the suite's total size (records ×
//! components × samples, generated in memory) is bounded before anything is generated, the seed
//! stays within what the written manifest can hold (a TOML integer), and exactly the minimum
//! number of steps is accepted despite rounding — in `motion synth`'s library calls and in a
//! manifest's `[synth]` table.

use pounding::ground_motion::set::RecordSet;
use pounding::ground_motion::synth::{
    MAX_SEED, MAX_SUITE_VALUES, MIN_STEPS, SynthParams, check_suite_size, write_suite,
};
use std::path::Path;

#[test]
fn the_suite_size_is_bounded_by_count_times_components_times_samples() {
    // 50 s at 0.01 s: 5001 samples per component
    let p = SynthParams {
        duration: 50.0,
        ..SynthParams::default()
    };
    assert_eq!(p.samples(), 5001);
    // the largest counts within the bound, from the bound itself
    let singles = MAX_SUITE_VALUES / 5001;
    let pairs = MAX_SUITE_VALUES / (2 * 5001);
    assert!(check_suite_size(&p, singles, false).is_ok());
    assert!(check_suite_size(&p, pairs, true).is_ok());
    let e = check_suite_size(&p, singles + 1, false)
        .unwrap_err()
        .to_string();
    let values = (singles + 1) * 5001;
    assert!(values > MAX_SUITE_VALUES);
    for needle in [
        format!("--count = {}", singles + 1),
        format!("{values} values"),
        MAX_SUITE_VALUES.to_string(),
    ] {
        assert!(e.contains(&needle), "{needle:?} not in {e}");
    }
    assert!(check_suite_size(&p, pairs + 1, true).is_err());
    // no overflow for absurd counts
    assert!(check_suite_size(&p, usize::MAX, true).is_err());
    // the default suite of the largest count still fits (10000 pairs of 2001 samples)
    assert!(check_suite_size(&SynthParams::default(), 10_000, true).is_ok());

    // write_suite refuses before generating or writing anything
    let scratch = crate::scratch::scratch_dir("it-synthlim", "size");
    let dir = scratch.join("suite");
    let e = write_suite(&dir, &p, pairs + 1, 1, true, "t")
        .unwrap_err()
        .to_string();
    assert!(e.contains("--count"), "{e}");
    assert!(!dir.exists());
}

#[test]
fn a_seed_beyond_a_toml_integer_is_refused_and_the_largest_reads_back() {
    assert_eq!(MAX_SEED, i64::MAX as u64);
    let p = SynthParams {
        duration: 2.0,
        ..SynthParams::default()
    };
    let scratch = crate::scratch::scratch_dir("it-synthlim", "seed");
    for seed in [MAX_SEED + 1, u64::MAX] {
        let dir = scratch.join(format!("s{seed}"));
        let e = write_suite(&dir, &p, 1, seed, false, "t")
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("--seed = {seed}")), "{e}");
        assert!(!dir.exists());
    }
    let dir = scratch.join("max");
    write_suite(&dir, &p, 1, MAX_SEED, false, "t").unwrap();
    let set = RecordSet::load(&dir.join("suite.toml")).unwrap();
    let seed = set.records[0]
        .meta
        .iter()
        .find(|(k, _)| k == "seed")
        .unwrap();
    assert_eq!(seed.1.csv_cell(), MAX_SEED.to_string());
    // and a [synth] table with the largest seed gives the same records
    let mem = RecordSet::from_toml(
        &format!("[synth]\ncount = 1\nseed = {MAX_SEED}\nduration = 2\n"),
        "m.toml",
        Path::new(""),
    )
    .unwrap();
    assert_eq!(mem.records[0].x.values(), set.records[0].x.values());
}

#[test]
fn exactly_the_minimum_number_of_steps_is_accepted() {
    // 0.7 / 0.007 = 100.00000000000001 and 100 × 0.007 = 0.7000000000000001 in floating point
    assert!(0.7 / 0.007 != MIN_STEPS as f64);
    let p = SynthParams {
        dt: 0.007,
        duration: 0.7,
        ..SynthParams::default()
    };
    p.check().unwrap();
    assert_eq!(p.samples(), MIN_STEPS + 1);
    let short = SynthParams {
        duration: 0.693,
        ..p.clone()
    };
    let e = short.check().unwrap_err().to_string();
    assert!(e.contains("at least 100 steps"), "{e}");
    // the same in a [synth] table
    let set = RecordSet::from_toml(
        "[synth]\ncount = 1\nseed = 1\ndt = 0.007\nduration = 0.7\n",
        "m.toml",
        Path::new(""),
    )
    .unwrap();
    assert_eq!(set.records[0].x.values().len(), MIN_STEPS + 1);
}

#[test]
fn synth_table_limits_name_the_key_and_its_line() {
    let err = |text: &str| {
        RecordSet::from_toml(text, "s.toml", Path::new(""))
            .unwrap_err()
            .to_string()
    };
    // 10000 × 2 × 9999001 values: refused at count, naming the product (it ran out of memory)
    let e = err("[synth]\ncount = 10000\nseed = 1\npairs = true\ndt = 0.001\nduration = 9999.0\n");
    let values = 10_000u64 * 2 * 9_999_001;
    for needle in [
        "synth.count (s.toml:2)".to_string(),
        "count = 10000".to_string(),
        format!("{values} values"),
        "dt = 0.001".to_string(),
    ] {
        assert!(e.contains(&needle), "{needle:?} not in {e}");
    }
    assert!(!e.contains("--"), "{e}");
    // a seed beyond a TOML integer: refused by the TOML reader, quoting the key's line
    let e = err("[synth]\ncount = 1\nseed = 9223372036854775808\n");
    for needle in ["s.toml", "line 3", "seed = 9223372036854775808"] {
        assert!(e.contains(needle), "{needle:?} not in {e}");
    }
}
