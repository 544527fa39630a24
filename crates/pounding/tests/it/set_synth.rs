//! `[synth]` in a record-set manifest: the records `pounding motion synth` writes, generated in
//! memory (the same samples, ids and metadata), and its errors naming the key and its line.

use pounding::ground_motion::set::RecordSet;
use pounding::ground_motion::synth::{SynthParams, write_suite};
use std::path::Path;

fn scratch(name: &str) -> crate::scratch::Scratch {
    crate::scratch::scratch_dir("ss", name)
}

/// An entry's id, metadata as CSV cells, and the times and samples of its components.
type Entry = (String, Vec<(String, String)>, Vec<Vec<f64>>);

/// The cells of every entry.
fn entries(set: &RecordSet) -> Vec<Entry> {
    set.records
        .iter()
        .map(|r| {
            let meta = r
                .meta
                .iter()
                .map(|(k, v)| (k.clone(), v.csv_cell()))
                .collect();
            let mut comps = vec![r.x.times().to_vec(), r.x.values().to_vec()];
            if let Some(y) = &r.y {
                comps.push(y.times().to_vec());
                comps.push(y.values().to_vec());
            }
            (r.id.clone(), meta, comps)
        })
        .collect()
}

#[test]
fn a_synth_manifest_gives_exactly_the_records_motion_synth_writes() {
    for (pairs, pga) in [(true, None), (false, Some(0.35))] {
        let d = scratch(&format!("eq{pairs}"));
        let p = SynthParams {
            dt: 0.02,
            duration: 6.0,
            pga_g: pga,
            ..SynthParams::default()
        };
        write_suite(&d, &p, 4, 7, pairs, "test").unwrap();
        let files = RecordSet::load(&d.join("suite.toml")).unwrap();
        let text = format!(
            "[synth]\ncount = 4\nseed = 7\npairs = {pairs}\ndt = 0.02\nduration = 6\n{}",
            pga.map(|g| format!("pga_g = {g}\n")).unwrap_or_default()
        );
        let mem = RecordSet::from_toml(&text, "mem.toml", Path::new("")).unwrap();
        assert_eq!(mem.records.len(), 4);
        assert_eq!(mem.records[0].y.is_some(), pairs);
        // the same ids, metadata cells and samples (bit for bit) as the files
        assert_eq!(entries(&mem), entries(&files));
        assert_eq!(mem.meta_keys(), files.meta_keys());
        // the same units as read
        assert_eq!(mem.records[1].x.units(), files.records[1].x.units());
        assert_eq!(mem.records[1].x.dt(), Some(0.02));
        assert_eq!(mem.name, "synthetic");
        assert!(mem.source.contains("--count 4 --seed 7"), "{}", mem.source);
    }
    // model parameters are read: another omega_g gives other samples
    let a = RecordSet::from_toml(
        "[synth]\ncount = 1\nseed = 1\nduration = 4",
        "a",
        Path::new(""),
    )
    .unwrap();
    let b = RecordSet::from_toml(
        "[synth]\ncount = 1\nseed = 1\nduration = 4\nomega_g = 8.0",
        "b",
        Path::new(""),
    )
    .unwrap();
    assert_ne!(a.records[0].x.values(), b.records[0].x.values());
    assert_eq!(a.records[0].x.times(), b.records[0].x.times());
}

fn err(text: &str) -> String {
    RecordSet::from_toml(text, "s.toml", Path::new(""))
        .unwrap_err()
        .to_string()
}

#[test]
fn synth_manifest_errors_name_the_key_and_its_line() {
    let cases: &[(&str, &[&str])] = &[
        (
            "[synth]\ncount = 0\nseed = 1\n",
            &["synth.count (s.toml:2)", "count = 0", "1..=10000"],
        ),
        (
            "[synth]\ncount = 2\nseed = -3\n",
            &["synth.seed (s.toml:3)", "seed = -3"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\ndt = -0.01\n",
            &["synth.dt (s.toml:4)", "dt = -0.01", "> 0"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\n\nduration = 0.005\ndt = 0.01\n",
            &["synth.dt (s.toml:6)", "must not exceed duration"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\nzeta_g = 1.5\n",
            &["synth.zeta_g (s.toml:4)", "[0.01, 1)"],
        ),
        // each parameter is checked on its own range before generating, and the key at fault
        // is named: a too-long duration (it was reported at dt), an absurd filter frequency (a
        // NaN sample, reported at count), values that made the generator panic or overflow
        (
            "[synth]\ncount = 2\nseed = 1\ndt = 0.01\nduration = 1e6\n",
            &["synth.duration (s.toml:5)", "duration = 1000000", "50000"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\nomega_f = 1e6\n",
            &["synth.omega_f (s.toml:4)", "omega_f = 1000000", "Nyquist"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\ndt = 0.5\nduration = 100\n",
            &["synth.dt (s.toml:4)", "default omega_g = 15.6", "Nyquist"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\nomega_g = 1e-300\n",
            &["synth.omega_g (s.toml:4)", "[0.01, π / dt)"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\nzeta_f = 1e-40\n",
            &["synth.zeta_f (s.toml:4)", "[0.01, 1)"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\ns0 = 1e300\n",
            &["synth.s0 (s.toml:4)", "(0, 1000]"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\nepsilon = 0.99\n",
            &["synth.epsilon (s.toml:4)", "(0, 0.5]"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\neta = 1e-300\n",
            &["synth.eta (s.toml:4)", "[1e-6, 1)"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\npga_g = 0\n",
            &["synth.pga_g (s.toml:4)", "pga_g = 0"],
        ),
        (
            "[synth]\ncount = 2\nseed = 1\nbogus = 3\n",
            &["unknown field", "bogus"],
        ),
        ("[synth]\ncount = 2\n", &["seed"]),
        (
            "[synth]\ncount = 2\nseed = 1\n\n[[record]]\nid = \"A\"\nx = \"builtin:ELC180\"\n",
            &["synth (s.toml:1)", "not both"],
        ),
    ];
    for (text, wants) in cases {
        let e = err(text);
        assert!(
            e.starts_with("record set s.toml") || e.starts_with("invalid record set s.toml"),
            "{e}"
        );
        for w in *wants {
            assert!(e.contains(w), "{text:?}: {e:?} lacks {w:?}");
        }
    }
    // no records at all names both ways
    let e = err("[set]\nname = \"x\"\n");
    assert!(e.contains("[[record]]") && e.contains("[synth]"), "{e}");
}
