//! Hardening of inputs and outputs end to end: tampered shards, special output files, one writer
//! per output directory, input size and thread limits, stale and partial outputs, strict JSON,
//! honest benchmark residuals.

use std::path::{Path, PathBuf};

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("hio", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    crate::run_capture(args)
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

const STUDY: &str = r#"
[decks]
beta1_deg = [60.0]
beta2_deg = [90.0]
r1_m = [200.0]
r2_m = [100.0]
[impact]
mu = [0.5]
[grid]
theta1_deg = { start = -4.0, stop = 4.0, step = 2.0 }
theta2_deg = { start = -4.0, stop = 4.0, step = 2.0 }
[output]
figures = false
"#;

/// A short simulation (2 s of El Centro) for the output-directory tests.
const SIM: &str = "[time]\ndt = 2e-3\nduration = 2.0\nhistory_every = 20\n";

fn shards(d: &Path) -> [PathBuf; 2] {
    let sc = d.join("study.toml");
    std::fs::write(&sc, STUDY).unwrap();
    [1, 2].map(|k| {
        let out = d.join(format!("shard{k}"));
        let (code, _, err) = run(&[
            "study",
            s(&sc),
            "--shard",
            &format!("{k}/2"),
            "--out",
            s(&out),
        ]);
        assert_eq!(code, Some(0), "{err}");
        out
    })
}

#[test]
fn tampered_shards_are_refused_naming_the_file() {
    let d = tmp("tamper");
    let [a, b] = shards(&d);
    let merged = d.join("merged");
    let merge = |out: &Path| run(&["study", "merge", s(&a), s(&b), "--out", s(out)]);
    let (code, _, err) = merge(&merged);
    assert_eq!(code, Some(0), "{err}");
    let good = std::fs::read_to_string(b.join("rows.csv")).unwrap();
    // a number edited by hand, or made nan: the line still parses, the checksum does not match
    let line = good.lines().nth(2).unwrap();
    let last = line.rsplit(',').next().unwrap();
    for by in ["0.5", "nan"] {
        let edited_line = format!("{},{by}", &line[..line.len() - last.len() - 1]);
        assert_ne!(edited_line, line);
        std::fs::write(b.join("rows.csv"), good.replacen(line, &edited_line, 1)).unwrap();
        let out = d.join(format!("m-{by}"));
        let (code, _, err) = merge(&out);
        assert_eq!(code, Some(2), "{by}: {err}");
        let rows = format!("{}/rows.csv", s(&b));
        assert!(err.contains(&rows) && err.contains("checksum"), "{err}");
        assert!(!out.exists(), "nothing written on bad input");
    }
    std::fs::write(b.join("rows.csv"), &good).unwrap();
    // `rows` in shard.json not the number of rows in the file
    let mf = std::fs::read_to_string(a.join("shard.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&mf).unwrap();
    let n = v["rows"].as_u64().unwrap();
    std::fs::write(
        a.join("shard.json"),
        mf.replacen(
            &format!("\"rows\": {n},"),
            &format!("\"rows\": {},", n + 1),
            1,
        ),
    )
    .unwrap();
    let (code, _, err) = merge(&d.join("m-rows"));
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("rows.csv") && err.contains("declares rows"),
        "{err}"
    );
    std::fs::write(a.join("shard.json"), &mf).unwrap();
    // --out equal to or inside a shard directory is refused, and nothing is written there
    for out in [a.clone(), a.join("merged"), b.join("../shard2/x")] {
        let before = names(&a);
        let (code, _, err) = merge(&out);
        assert_eq!(code, Some(2), "{}: {err}", out.display());
        assert!(err.contains("inside") && err.contains("shard"), "{err}");
        assert_eq!(names(&a), before);
    }
    assert!(!a.join("merged").exists() && !b.join("x").exists());
    // a complete study is never written beside a shard, nor a shard beside a study
    let (code, _, err) = run(&["study", s(&d.join("study.toml")), "--out", s(&a)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("shard.json"), "{err}");
    let (code, _, err) = run(&[
        "study",
        s(&d.join("study.toml")),
        "--shard",
        "1/2",
        "--out",
        s(&merged),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("bounds.csv"), "{err}");
    assert!(!merged.join("shard.json").exists());
}

fn lcp_file(d: &Path) -> PathBuf {
    let p = d.join("p.dat");
    std::fs::write(&p, "2\n0\n2\n2\n2 2\n2 1\n1 2\n-1 -1\n").unwrap();
    p
}

#[cfg(unix)]
#[test]
fn special_output_files_are_written_through_or_refused_never_replaced() {
    use std::os::unix::fs::FileTypeExt;
    let d = tmp("special");
    let p = lcp_file(&d);
    let (code, _, err) = run(&["lcp", "solve", s(&p), "--out", "/dev/null"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        std::fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device()
    );
    if Path::new("/dev/full").exists() {
        let (code, _, err) = run(&["lcp", "solve", s(&p), "--out", "/dev/full"]);
        assert_eq!(code, Some(2), "{err}");
        assert!(
            err.contains("/dev/full") && err.contains("No space"),
            "{err}"
        );
        assert!(
            std::fs::metadata("/dev/full")
                .unwrap()
                .file_type()
                .is_char_device()
        );
    }
    // a directory is refused and left alone
    let dir = d.join("adir");
    std::fs::create_dir(&dir).unwrap();
    let (code, _, err) = run(&["lcp", "solve", s(&p), "--out", s(&dir)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("adir") && err.contains("directory"), "{err}");
    assert!(dir.is_dir());
    // a FIFO is written through (a reader gets the solution file); it stays a FIFO
    let fifo = d.join("fifo");
    let ok = std::process::Command::new("mkfifo").arg(&fifo).status();
    if ok.is_ok_and(|s| s.success()) {
        let f2 = fifo.clone();
        let reader = std::thread::spawn(move || std::fs::read_to_string(f2).unwrap());
        let (code, _, err) = run(&["lcp", "solve", s(&p), "--out", s(&fifo)]);
        assert_eq!(code, Some(0), "{err}");
        let text = reader.join().unwrap();
        assert!(text.starts_with("LCPSOL 1"), "{text}");
        assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    }
    assert_eq!(names(&d), ["adir", "fifo", "p.dat"], "no temporary left");
}

/// Holds the lock of `dir` as another run would.
fn hold_lock(dir: &Path) -> std::fs::File {
    std::fs::create_dir_all(dir).unwrap();
    let f = std::fs::OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .open(dir.join(".pounding.lock"))
        .unwrap();
    f.try_lock().unwrap();
    f
}

#[test]
fn a_second_writer_into_one_output_directory_is_refused() {
    let d = tmp("lock");
    let sc = d.join("sim.toml");
    std::fs::write(&sc, SIM).unwrap();
    let st = d.join("study.toml");
    std::fs::write(&st, STUDY).unwrap();
    let rec = d.join("rec.csv");
    std::fs::write(&rec, "t,a\n0,0\n0.5,0.1\n1,0\n").unwrap();
    let [a, b] = shards(&d);
    let out = d.join("busy");
    let commands: Vec<Vec<&str>> = vec![
        vec!["simulate", s(&sc)],
        vec!["simulate", s(&sc), "--records", s(&rec)],
        vec!["compare", s(&sc), "--laws", "rigid"],
        vec!["study", s(&st)],
        vec!["study", s(&st), "--shard", "1/2"],
        vec!["study", "merge", s(&a), s(&b)],
    ];
    let lock = hold_lock(&out);
    for c in &commands {
        let mut args = c.clone();
        args.extend(["--out", s(&out)]);
        let (code, _, err) = run(&args);
        assert_eq!(code, Some(2), "{c:?}: {err}");
        assert!(
            err.contains("in use") && err.contains(s(&out)),
            "{c:?}: {err}"
        );
        assert_eq!(
            names(&out),
            [".pounding.lock"],
            "{c:?} wrote into a locked dir"
        );
    }
    drop(lock);
    let (code, _, err) = run(&["simulate", s(&sc), "--out", s(&out)]);
    assert_eq!(code, Some(0), "{err}");
    // the lock is released, and its file removed, when the run ends
    assert!(!out.join(".pounding.lock").exists());
    hold_lock(&out);
}

#[test]
fn endless_and_oversized_inputs_are_refused_quickly() {
    let d = tmp("limits");
    let t0 = std::time::Instant::now();
    for args in [
        vec!["study", "/dev/zero"],
        vec!["simulate", "/dev/zero"],
        vec!["compare", "/dev/zero"],
        vec!["impact", "--problem", "/dev/zero"],
        vec!["lcp", "solve", "/dev/zero"],
        vec!["simulate", "--record", "/dev/zero"],
    ] {
        let t = std::time::Instant::now();
        let mut a = args.clone();
        let out = d.join("o");
        a.extend(["--out", s(&out)]);
        if args[0] == "impact" || args[0] == "lcp" {
            a.truncate(args.len());
        }
        let (code, _, err) = run(&a);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(
            err.contains("/dev/zero") && err.contains("MiB"),
            "{args:?}: {err}"
        );
        assert!(
            t.elapsed().as_secs() < 20,
            "{args:?} took {:?}",
            t.elapsed()
        );
        assert!(!out.exists(), "{args:?} wrote outputs");
    }
    eprintln!("6 endless inputs refused in {:?}", t0.elapsed());
    // a regular file over the limit is refused before reading
    let big = d.join("big.toml");
    let f = std::fs::File::create(&big).unwrap();
    f.set_len(17 << 20).unwrap();
    let (code, _, err) = run(&["study", s(&big)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("big.toml") && err.contains("16 MiB"), "{err}");
    // shard rows are bounded by the rows the manifest declares
    let [a, b] = shards(&d);
    std::fs::remove_file(b.join("rows.csv")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", b.join("rows.csv")).unwrap();
    let (code, _, err) = run(&["study", "merge", s(&a), s(&b), "--out", s(&d.join("m"))]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("rows.csv") && err.contains("limit"), "{err}");
    // thread counts: the same cap for the study and the batch
    let rec = d.join("rec.csv");
    std::fs::write(&rec, "t,a\n0,0\n0.5,0.1\n1,0\n").unwrap();
    for args in [
        vec!["study", "--threads", "100000"],
        vec!["simulate", "--records", s(&rec), "--threads", "100000"],
        vec!["simulate", "--records", s(&rec), "--threads", "0"],
    ] {
        let t = std::time::Instant::now();
        let (code, _, err) = run(&args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(
            err.contains("--threads") && err.contains("1024"),
            "{args:?}: {err}"
        );
        assert!(t.elapsed().as_secs() < 20);
    }
}

#[test]
fn simulate_and_compare_clear_stale_outputs_and_mark_completion_last() {
    let d = tmp("stale");
    let sc = d.join("sim.toml");
    std::fs::write(&sc, SIM).unwrap();
    for (cmd, stale) in [
        (
            "simulate",
            vec!["abutment_gap.png", "timing.json", "batch.csv"],
        ),
        ("compare", vec!["contact_force.png", "timing.json"]),
    ] {
        let out = d.join(cmd);
        std::fs::create_dir_all(&out).unwrap();
        for n in stale
            .iter()
            .chain(&[".joint_gap.png.4242.tmp", "notes.txt"])
        {
            std::fs::write(out.join(n), b"earlier run").unwrap();
        }
        let mut args = vec![cmd, s(&sc), "--out", s(&out)];
        if cmd == "compare" {
            args.extend(["--laws", "rigid"]);
        }
        let (code, _, err) = run(&args);
        assert_eq!(code, Some(0), "{err}");
        let after = names(&out);
        assert!(
            after.contains(&"notes.txt".to_string()),
            "foreign files are kept"
        );
        assert!(!after.iter().any(|n| n.contains(".tmp")), "{after:?}");
        for n in &stale {
            let p = out.join(n);
            assert!(
                !p.exists() || std::fs::read(&p).unwrap() != b"earlier run",
                "{cmd}: stale {n} kept"
            );
        }
        // the marker of a complete run is there
        let t: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("timing.json")).unwrap())
                .unwrap();
        assert!(t["wall_time_s"].as_f64().unwrap() > 0.0);
    }
}

/// Runs `args` with writes limited to `kib` KiB per file (`ulimit -f`; SIGXFSZ ignored, so a
/// write past it fails with EFBIG as on a full disk).
fn run_with_file_limit(kib: u32, args: &[&str]) -> (Option<i32>, String) {
    let o = std::process::Command::new("bash")
        .arg("-c")
        .arg(format!("trap '' XFSZ; ulimit -f {kib}; exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_pounding"))
        .args(args)
        .output()
        .unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn a_failed_plot_write_names_the_file_and_leaves_no_temporary_and_no_marker() {
    let d = tmp("partial");
    let sc = d.join("sim.toml");
    std::fs::write(&sc, SIM).unwrap();
    // simulate: the CSVs fit in 150 KiB, the 1400x1050 displacement plot does not
    let out = d.join("sim");
    let (code, err) = run_with_file_limit(150, &["simulate", s(&sc), "--out", s(&out)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("displacements.png") && err.contains("too large"),
        "{err}"
    );
    assert!(
        !err.contains("BackendError") && !err.contains("Custom {"),
        "{err}"
    );
    let after = names(&out);
    assert!(!after.iter().any(|n| n.contains(".tmp")), "{after:?}");
    assert!(!out.join("timing.json").exists(), "no completion marker");
    // study figures: the same
    let st = d.join("study.toml");
    std::fs::write(&st, STUDY.replace("figures = false", "figures = true")).unwrap();
    let out = d.join("study");
    let (code, err) = run_with_file_limit(20, &["study", s(&st), "--out", s(&out)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains(".png") && err.contains("too large"), "{err}");
    let figs = names(&out.join("figures"));
    assert!(!figs.iter().any(|n| n.contains(".tmp")), "{figs:?}");
    assert!(!out.join("timing.json").exists() && !out.join("report.html").exists());
}

#[test]
fn duplicate_json_keys_are_refused_with_their_line() {
    let d = tmp("dupjson");
    let p = d.join("p.json");
    std::fs::write(
        &p,
        "{\"bodies\": [{\"name\": \"disc\", \"mass\": 2, \"inertia\": 0.09,\n\
         \"mass\": 3, \"position\": [0, 0.3], \"velocity\": [1, -2], \"omega\": 40}],\n\
         \"contacts\": [{\"body_a\": \"disc\", \"body_b\": null, \"point\": [0, 0],\n\
         \"normal\": [0, 1], \"mu\": 0.2, \"restitution\": 0.5}]}\n",
    )
    .unwrap();
    let (code, _, err) = run(&["impact", "--problem", s(&p)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("p.json") && err.contains("duplicate key \"mass\"") && err.contains("line 2"),
        "{err}"
    );
}

#[test]
fn lcp_bench_reports_no_residual_when_nothing_is_solved() {
    let d = tmp("bench");
    // w = -z - 1 >= 0 has no solution with z >= 0: Lemke ends on a ray
    let p = d.join("ray.dat");
    std::fs::write(&p, "1\n0\n1\n1\n1 1\n-1\n-1\n").unwrap();
    let (code, out, err) = run(&[
        "lcp",
        "bench",
        s(&p),
        "--min-time",
        "0.001",
        "--repeats",
        "1",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let c = &v["classes"][0];
    assert_eq!(c["solved"], 0, "{v}");
    assert!(c["max_residual"].is_null(), "{v}");
}
