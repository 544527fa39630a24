//! `pounding campaign`: the same stored bytes on 1 and 2 threads and from merged shards; a
//! killed campaign resumes with every run stored once; `fragility --from-store` equals
//! `fragility`; bad specs name file, key and line.

use crate::{pounding, run_capture, scratch_with};
use pounding::campaign::table::{Reader, Values};
use std::path::Path;

const VIADUCT: &str = include_str!("../../../../examples/fragility/viaduct.toml");

/// The example viaduct with short runs, 3 stripes and a small bootstrap, on `count` synthetic
/// pairs of `seconds` s.
fn files(count: usize, seconds: f64) -> [(&'static str, String); 2] {
    let scenario = VIADUCT
        .replace("duration = 15.0", &format!("duration = {seconds}"))
        .replace(
            "levels_g = [0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.4]",
            "levels_g = [0.2, 0.5, 1.0]",
        )
        .replace("bootstrap = 500", "bootstrap = 40");
    assert!(scenario.contains("levels_g = [0.2, 0.5, 1.0]"));
    let suite = format!(
        "[synth]\ncount = {count}\nseed = 3\npairs = true\nduration = {}\n",
        seconds + 1.0
    );
    [("viaduct.toml", scenario), ("suite.toml", suite)]
}

fn dir_with(name: &str, spec: &str, count: usize, seconds: f64) -> crate::Scratch {
    let [a, b] = files(count, seconds);
    scratch_with(
        "campaign",
        name,
        &[(a.0, &a.1), (b.0, &b.1), ("spec.toml", spec)],
    )
}

fn ok(args: &[&str]) -> String {
    let (code, out, err) = run_capture(args);
    assert_eq!(code, Some(0), "{args:?}: {out}\n{err}");
    out
}

/// The `run` column of a Parquet file, read by the library's reader.
fn run_column(path: &Path) -> Vec<i64> {
    let r = Reader::open(path).unwrap();
    let mut out = Vec::new();
    for g in 0..r.row_groups() {
        match r.row_group(g, Some(&["run"])).unwrap().get("run") {
            Some(Values::Int(v)) => out.extend(v.iter().map(|x| x.unwrap())),
            other => panic!("run column: {other:?}"),
        }
    }
    out
}

const SPEC: &str = "[campaign]\nscenario = \"viaduct.toml\"\nruns_per_part = 5\n";

#[test]
fn threads_and_shards_store_the_same_bytes_and_fragility_reads_the_store() {
    let d = dir_with("executors", SPEC, 4, 2.0);
    let p = |s: &str| d.join(s).display().to_string();
    ok(&[
        "campaign",
        "run",
        &p("spec.toml"),
        "--out",
        &p("t1"),
        "--threads",
        "1",
    ]);
    ok(&[
        "campaign",
        "run",
        &p("spec.toml"),
        "--out",
        &p("t2"),
        "--threads",
        "2",
    ]);
    for k in 1..=3 {
        let out = ok(&[
            "campaign",
            "run",
            &p("spec.toml"),
            "--out",
            &p(&format!("s{k}")),
            "--shard",
            &format!("{k}/3"),
        ]);
        assert!(out.contains("merge the shards"), "{out}");
    }
    // two shards are not the campaign: the merge names what is missing
    let (code, _, err) = run_capture(&["campaign", "merge", &p("s1"), &p("s2"), "--out", &p("m")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("1 of 3 parts are missing") && err.contains("part-000002"),
        "{err}"
    );
    let out = ok(&[
        "campaign",
        "merge",
        &p("s1"),
        &p("s2"),
        &p("s3"),
        "--out",
        &p("m"),
    ]);
    assert!(out.contains("merged 12 runs"), "{out}");
    let one = std::fs::read(d.join("t1/runs.parquet")).unwrap();
    for other in ["t2/runs.parquet", "m/runs.parquet"] {
        assert!(
            one == std::fs::read(d.join(other)).unwrap(),
            "{other} differs"
        );
    }
    // 4 entries × 3 stripes, each run once, in order
    assert_eq!(
        run_column(&d.join("t1/runs.parquet")),
        (0..12).collect::<Vec<_>>()
    );
    // the fit of the stored runs is the fit of the runs done by `fragility` itself
    let _ = run_capture(&["fragility", &p("viaduct.toml"), "--out", &p("direct")]);
    let _ = run_capture(&[
        "fragility",
        &p("viaduct.toml"),
        "--from-store",
        &p("t2"),
        "--out",
        &p("stored"),
    ]);
    for f in ["fragility.csv", "fragility.json", "runs.csv"] {
        let a = std::fs::read_to_string(d.join("direct").join(f)).unwrap();
        assert_eq!(
            a,
            std::fs::read_to_string(d.join("stored").join(f)).unwrap(),
            "{f}"
        );
    }
    // a store of other stripes is refused, naming the mismatch
    std::fs::write(
        d.join("other.toml"),
        format!("{SPEC}levels_g = [0.3, 0.6, 0.9]\n"),
    )
    .unwrap();
    ok(&["campaign", "run", &p("other.toml"), "--out", &p("o")]);
    let (code, _, err) = run_capture(&[
        "fragility",
        &p("viaduct.toml"),
        "--from-store",
        &p("o"),
        "--out",
        &p("bad"),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("does not match this study"), "{err}");
    // and a store of another campaign is never resumed into
    let (code, _, err) = run_capture(&["campaign", "run", &p("other.toml"), "--out", &p("t1")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("holds another campaign"), "{err}");
}

#[test]
fn a_killed_campaign_resumes_with_every_run_once() {
    let spec = "[campaign]\nscenario = \"viaduct.toml\"\nruns_per_part = 2\n";
    let d = dir_with("kill", spec, 12, 6.0);
    let p = |s: &str| d.join(s).display().to_string();
    let mut child = pounding()
        .args([
            "campaign",
            "run",
            &p("spec.toml"),
            "--out",
            &p("k"),
            "--threads",
            "1",
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let parts = d.join("k/parts");
    let count = || {
        std::fs::read_dir(&parts).map_or(0, |r| {
            r.filter(|e| {
                e.as_ref()
                    .is_ok_and(|e| e.file_name().to_string_lossy().starts_with("part-"))
            })
            .count()
        })
    };
    let t0 = std::time::Instant::now();
    while count() < 3 && t0.elapsed().as_secs() < 120 {
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    child.kill().unwrap(); // SIGKILL
    let status = child.wait().unwrap();
    let killed = !status.success();
    let stored = count();
    eprintln!("killed: {killed}, {stored} of 18 parts stored");
    assert!(stored >= 3, "{stored} parts before the kill");
    // every part present is whole: it reads and holds exactly its runs
    for e in std::fs::read_dir(&parts).unwrap() {
        let e = e.unwrap();
        let name = e.file_name().to_string_lossy().into_owned();
        if let Some(k) = name
            .strip_prefix("part-")
            .and_then(|s| s.strip_suffix(".parquet"))
        {
            let k: i64 = k.parse().unwrap();
            assert_eq!(run_column(&e.path()), vec![2 * k, 2 * k + 1], "{name}");
        }
    }
    let (code, out, err) = run_capture(&[
        "campaign",
        "run",
        &p("spec.toml"),
        "--out",
        &p("k"),
        "--threads",
        "2",
    ]);
    assert_eq!(code, Some(0), "{out}\n{err}");
    if killed {
        assert!(err.contains(&format!("{stored} parts stored")), "{err}");
    }
    assert!(out.contains("merged 36 runs"), "{out}");
    // no temporary left, and the merged file equals an uninterrupted run byte for byte
    for e in std::fs::read_dir(&parts).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(
            name.starts_with("part-") && name.ends_with(".parquet"),
            "{name}"
        );
    }
    assert_eq!(
        run_column(&d.join("k/runs.parquet")),
        (0..36).collect::<Vec<_>>()
    );
    ok(&[
        "campaign",
        "run",
        &p("spec.toml"),
        "--out",
        &p("whole"),
        "--threads",
        "2",
    ]);
    assert!(
        std::fs::read(d.join("k/runs.parquet")).unwrap()
            == std::fs::read(d.join("whole/runs.parquet")).unwrap(),
        "resumed and uninterrupted stores differ"
    );
}

#[test]
fn bad_specs_name_file_key_and_line() {
    let cases: &[(&str, &str)] = &[
        (
            "[campaign]\nscenario = \"viaduct.toml\"\nrun_per_part = 5\n",
            "run_per_part",
        ),
        (
            "[campaign]\nscenario = \"viaduct.toml\"\nruns_per_part = 0\n",
            "`campaign.runs_per_part` (",
        ),
        (
            "[campaign]\nscenario = \"viaduct.toml\"\nlevels_g = [0.5, 0.2]\n",
            "`campaign.levels_g` (",
        ),
        (
            "[campaign]\nscenario = \"viaduct.toml\"\nlevels_g = [1.0]\nscales = [1.0]\n",
            "`campaign.scales` (",
        ),
        (
            "[campaign]\nscenario = \"nothing.toml\"\n",
            "`campaign.scenario` (",
        ),
        (
            "[campaign]\nscenario = \"viaduct.toml\"\n[outputs]\nhistories = true\n",
            "`outputs.histories` (",
        ),
        ("[campaign]\nname = \"x\"\n", "`campaign.scenario` ("),
    ];
    for (i, (spec, want)) in cases.iter().enumerate() {
        let d = dir_with("bad", spec, 2, 1.0);
        let p = |s: &str| d.join(s).display().to_string();
        let (code, out, err) = run_capture(&["campaign", "run", &p("spec.toml"), "--out", &p("o")]);
        assert_eq!(code, Some(2), "case {i}: {out}\n{err}");
        assert!(err.contains(want), "case {i}: {err}");
        let line = spec.lines().count();
        assert!(
            err.contains(&format!("spec.toml:{line}"))
                || err.contains(&format!("line {line}"))
                || i == 6,
            "case {i}: {err}"
        );
        assert!(!d.join("o").exists(), "case {i}: wrote outputs");
    }
}

/// The stored columns of a file, without those naming the run (`run`, `id`, `variant`).
fn results(path: &Path) -> Vec<(String, Values)> {
    let r = Reader::open(path).unwrap();
    let mut all = pounding::campaign::table::Columns::default();
    for g in 0..r.row_groups() {
        all.append(r.row_group(g, None).unwrap()).unwrap();
    }
    all.cols
        .into_iter()
        .filter(|(n, _)| !["run", "id", "variant"].contains(&n.as_str()))
        .collect()
}

/// Keeps rows `range` of every column.
fn rows(cols: &[(String, Values)], range: std::ops::Range<usize>) -> Vec<(String, Values)> {
    let cut = |v: &Values| match v {
        Values::Int(x) => Values::Int(x[range.clone()].to_vec()),
        Values::Float(x) => Values::Float(x[range.clone()].to_vec()),
        Values::Text(x) => Values::Text(x[range.clone()].to_vec()),
        Values::Bool(x) => Values::Bool(x[range.clone()].to_vec()),
    };
    cols.iter().map(|(n, v)| (n.clone(), cut(v))).collect()
}

#[test]
fn grid_variants_run_the_overridden_scenarios() {
    let spec = "[campaign]\nscenario = \"viaduct.toml\"\nruns_per_part = 4\n\n[grid]\n\
                \"bridge.restrainer_k\" = [2.5e7, 1e8]\n\"bridge.gap\" = [0.02, 0.05]\n";
    let d = dir_with("grid", spec, 3, 2.0);
    let p = |s: &str| d.join(s).display().to_string();
    let out = ok(&["campaign", "run", &p("spec.toml"), "--out", &p("g")]);
    assert!(out.contains("merged 36 runs"), "{out}");
    let grid = results(&d.join("g/runs.parquet"));
    // grid point 2 (the last key fastest: restrainer_k = 1e8, gap = 0.02) is the campaign of
    // the scenario edited by hand
    let base = std::fs::read_to_string(d.join("viaduct.toml")).unwrap();
    let edited = base.replace("restrainer_k = 5.0e7", "restrainer_k = 1.0e8");
    assert_ne!(edited, base);
    assert!(edited.contains("gap = 0.02\n"));
    std::fs::write(d.join("edited.toml"), edited).unwrap();
    std::fs::write(
        d.join("edited-spec.toml"),
        "[campaign]\nscenario = \"edited.toml\"\nruns_per_part = 4\n",
    )
    .unwrap();
    ok(&["campaign", "run", &p("edited-spec.toml"), "--out", &p("e")]);
    let edited = results(&d.join("e/runs.parquet"));
    assert_eq!(rows(&grid, 18..27), edited);
    // and the variants differ from each other (the restrainers act)
    assert_ne!(rows(&grid, 0..9), rows(&grid, 18..27));
    // a key the scenario does not know is refused with the spec's line
    std::fs::write(
        d.join("bad.toml"),
        "[campaign]\nscenario = \"viaduct.toml\"\n[grid]\n\"bridge.restrainer_kk\" = [1.0]\n",
    )
    .unwrap();
    let (code, _, err) = run_capture(&["campaign", "run", &p("bad.toml"), "--out", &p("b")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("bad.toml:4") && err.contains("restrainer_kk"),
        "{err}"
    );
}

#[test]
fn the_example_campaign_expands_as_its_comments_say() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/campaign/viaduct-grid.toml");
    let c = pounding::campaign::Campaign::load(&path).unwrap();
    // 3 restrainer stiffnesses × 2 gaps, 20 pairs, 8 stripes
    assert_eq!(c.variants.len(), 6);
    assert_eq!(c.runs(), 960);
    assert_eq!(c.parts(), 30);
    assert_eq!(
        c.variants[1],
        "bridge.restrainer_k=25000000,bridge.gap=0.05"
    );
    let ids: std::collections::HashSet<String> = c.expand().into_iter().map(|r| r.id).collect();
    assert_eq!(ids.len(), 960);
    assert_eq!(
        c.run_spec(8 * 20 + 3).id,
        format!("{}/SYN001/level_g=0.5", c.variants[1])
    );
}

/// Findings of a fresh-clone hostile trial, each a wrong number or lost results before:
/// grids with equal values or no keys, overrides of the study's tables, a store written over by
/// a merge of another campaign, parts adopted without their description, and a variant's runs
/// fitted through another scenario.
#[test]
fn stores_and_grids_refuse_what_would_mix_or_mislabel_runs() {
    let grid = |g: &str| format!("{SPEC}[grid]\n{g}");
    let bad: &[(String, &str)] = &[
        (grid("\"bridge.gap\" = [0.03, 0.03]\n"), "listed twice"),
        (grid("\"bridge.gap\" = [0.03, 1, 1.0]\n"), "listed twice"),
        (grid(""), "an empty [grid]"),
        (
            format!(
                "{SPEC}[[variant]]\nname = \"v\"\n[variant.set]\n\"ground_motion.scale_y\" = -2.0\n"
            ),
            "[ground_motion] cannot be overridden",
        ),
        (
            grid("\"time.dt\" = [1e-3, 2e-3]\n"),
            "[time] cannot be overridden",
        ),
    ];
    for (i, (spec, want)) in bad.iter().enumerate() {
        let d = dir_with("refuse", spec, 2, 1.0);
        let p = |s: &str| d.join(s).display().to_string();
        let (code, out, err) = run_capture(&["campaign", "run", &p("spec.toml"), "--out", &p("o")]);
        assert_eq!(code, Some(2), "case {i}: {out}\n{err}");
        assert!(err.contains(want), "case {i}: {err}");
        assert!(!d.join("o").join("parts").exists(), "case {i} wrote parts");
    }
    // the keys' order is the file's, whatever a comment before them mentions
    let spec = grid(
        "# sweeps \"bridge.gap\" last\n\"bridge.restrainer_k\" = [2.5e7, 5.0e7]\n\"bridge.gap\" = [0.02, 0.05]\n",
    );
    let d = dir_with("order", &spec, 1, 1.0);
    let p = |s: &str| d.join(s).display().to_string();
    ok(&["campaign", "run", &p("spec.toml"), "--out", &p("s")]);
    let meta: serde_json::Value =
        serde_json::from_slice(&std::fs::read(d.join("s").join("campaign.json")).unwrap()).unwrap();
    let names: Vec<&str> = meta["variants"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(
        names[..2],
        [
            "bridge.restrainer_k=25000000,bridge.gap=0.02",
            "bridge.restrainer_k=25000000,bridge.gap=0.05"
        ],
        "{names:?}"
    );
    // a merge into another campaign's store is refused, the store left as it was
    let d2 = dir_with("other", SPEC, 1, 1.0);
    let q = |s: &str| d2.join(s).display().to_string();
    ok(&["campaign", "run", &q("spec.toml"), "--out", &q("base")]);
    let before = std::fs::read(d2.join("base").join("runs.parquet")).unwrap();
    let (code, _, err) = run_capture(&["campaign", "merge", &p("s"), "--out", &q("base")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("holds another campaign"), "{err}");
    assert_eq!(
        std::fs::read(d2.join("base").join("runs.parquet")).unwrap(),
        before
    );
    // parts without their description are not adopted
    std::fs::remove_file(d2.join("base").join("campaign.json")).unwrap();
    let (code, _, err) = run_capture(&["campaign", "run", &q("spec.toml"), "--out", &q("base")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("has part files but no campaign.json"), "{err}");
    // a variant's runs are fitted through the campaign's own scenario only
    let edited = std::fs::read_to_string(d.join("viaduct.toml"))
        .unwrap()
        .replace("limit_m = 0.10", "limit_m = 0.01");
    std::fs::write(d.join("edited.toml"), edited).unwrap();
    let (code, _, err) = run_capture(&[
        "fragility",
        &p("edited.toml"),
        "--from-store",
        &p("s"),
        "--variant",
        names[0],
        "--out",
        &p("f"),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("another scenario text"), "{err}");
    ok(&[
        "fragility",
        &p("viaduct.toml"),
        "--from-store",
        &p("s"),
        "--variant",
        names[0],
        "--out",
        &p("f"),
    ]);
}

/// A shard whose runs did not all complete exits 1 (a Slurm array flags the task), as the whole
/// campaign and its merge do; a shard of completed runs exits 0.
#[test]
fn a_shard_with_failed_runs_exits_1() {
    // a step far too coarse for the Hertz contact at strong stripes: Newton failures, some of
    // which remain when such a run is run again at dt/2 and dt/4 (at dt = 0.02 none remains)
    let spec =
        "[campaign]\nscenario = \"viaduct.toml\"\nruns_per_part = 4\nlevels_g = [1.0, 3.0, 6.0]\n";
    let d = dir_with("shardfail", spec, 4, 3.0);
    let text = std::fs::read_to_string(d.join("viaduct.toml"))
        .unwrap()
        .replace("dt = 2e-3", "dt = 0.09")
        .replace("seat_length = 0.25", "seat_length = 0.03");
    std::fs::write(d.join("viaduct.toml"), text).unwrap();
    std::fs::write(
        d.join("suite.toml"),
        "[synth]\ncount = 4\nseed = 1\npairs = true\ndt = 0.01\nduration = 20.0\n",
    )
    .unwrap();
    let p = |s: &str| d.join(s).display().to_string();
    let mut codes = Vec::new();
    for k in 1..=3 {
        let (code, out, err) = run_capture(&[
            "campaign",
            "run",
            &p("spec.toml"),
            "--out",
            &p(&format!("s{k}")),
            "--shard",
            &format!("{k}/3"),
        ]);
        // one part per shard: its statuses decide
        let part = d
            .join(format!("s{k}"))
            .join("parts")
            .join(format!("part-{:06}.parquet", k - 1));
        let r = Reader::open(&part).unwrap();
        let all_completed = match r.row_group(0, Some(&["status"])).unwrap().get("status") {
            Some(Values::Text(v)) => v.iter().all(|x| x.as_deref() == Some("Completed")),
            other => panic!("{other:?}"),
        };
        let want = if all_completed { 0 } else { 1 };
        assert_eq!(code, Some(want), "shard {k}: {out}\n{err}");
        codes.push(want);
    }
    assert!(
        codes.contains(&1),
        "no run failed: the test needs a coarser step"
    );
    let (code, _, err) = run_capture(&[
        "campaign",
        "merge",
        &p("s1"),
        &p("s2"),
        &p("s3"),
        "--out",
        &p("all"),
    ]);
    assert_eq!(code, Some(1), "{err}");
}
