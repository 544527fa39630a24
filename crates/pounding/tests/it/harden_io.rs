//! Hardening of inputs and outputs: shard checksums and counts, input size limits, strict JSON,
//! atomic writes that never replace a special file.

use pounding::study::run::compute_rows;
use pounding::study::shard::{ShardFiles, manifest_json, merge, shard_rows_csv};
use pounding::study::{Scenario, Shard, Study};

const SMALL: &str = r#"
[decks]
beta1_deg = [60.0]
beta2_deg = [90.0]
r1_m = [200.0]
r2_m = [100.0]
[impact]
mu = [0.5, 0.0]
[grid]
theta1_deg = { start = -6.0, stop = 6.0, step = 3.0 }
theta2_deg = { start = -6.0, stop = 6.0, step = 3.0 }
[output]
figures = false
"#;

fn none(_: usize) {}

fn shards(n: usize) -> (Scenario, Vec<ShardFiles>) {
    let s = Scenario::from_toml(SMALL, "small.toml").unwrap();
    let parts = (1..=n)
        .map(|k| {
            let shard = Shard::new(k, n).unwrap();
            let rows = compute_rows(&s, shard, &none).unwrap();
            let csv = shard_rows_csv(&s, &rows);
            ShardFiles {
                origin: format!("dir{k}"),
                manifest: manifest_json(shard, SMALL, s.row_count(), rows.len(), &csv),
                rows: csv,
            }
        })
        .collect();
    (s, parts)
}

/// Replaces the first float field after the row index and key columns of data line `line` by `by`.
fn edit_value(rows: &str, line: usize, by: &str) -> String {
    let mut out: Vec<String> = rows.lines().map(str::to_string).collect();
    let fields: Vec<&str> = out[line].split(',').collect();
    // the last field that parses as a non-integer float (a bound or ratio)
    let j = (0..fields.len())
        .rev()
        .find(|&j| fields[j].contains('.') && fields[j].parse::<f64>().is_ok())
        .expect("a float field");
    let mut f: Vec<String> = fields.iter().map(|s| s.to_string()).collect();
    assert_ne!(f[j], by);
    f[j] = by.to_string();
    out[line] = f.join(",");
    out.join("\n") + "\n"
}

#[test]
fn untouched_shards_merge_to_the_unsharded_study() {
    let (s, parts) = shards(2);
    let whole = Study::compute(SMALL.into(), s, &none).unwrap();
    let m = merge(&parts).unwrap();
    assert_eq!(
        Study::from_rows(m.scenario_text, m.scenario, m.rows).bounds_csv(),
        whole.bounds_csv()
    );
    // the manifest carries the checksum of the exact rows bytes
    let v: serde_json::Value = serde_json::from_str(&parts[0].manifest).unwrap();
    assert_eq!(
        v["rows_fnv1a64"],
        pounding::input::fnv1a64_hex(parts[0].rows.as_bytes())
    );
}

#[test]
fn a_value_edited_by_hand_or_nan_is_refused_naming_the_rows_file() {
    for by in ["0.123456", "nan", "inf"] {
        let (_, mut parts) = shards(2);
        parts[1].rows = edit_value(&parts[1].rows, 3, by);
        // the edited row still parses: only the checksum can catch it
        let e = merge(&parts).unwrap_err().to_string();
        assert!(
            e.contains("dir2/rows.csv") && e.contains("checksum"),
            "{by}: {e}"
        );
    }
}

#[test]
fn manifest_counts_are_checked() {
    let set = |parts: &mut Vec<ShardFiles>, k: usize, key: &str, v: serde_json::Value| {
        let mut m: serde_json::Value = serde_json::from_str(&parts[k].manifest).unwrap();
        m[key] = v;
        parts[k].manifest = serde_json::to_string_pretty(&m).unwrap();
    };
    // rows_total that is not the scenario's row count
    let (s, mut parts) = shards(2);
    set(&mut parts, 0, "rows_total", (s.row_count() + 1).into());
    let e = merge(&parts).unwrap_err().to_string();
    assert!(
        e.contains("dir1/shard.json") && e.contains("rows_total"),
        "{e}"
    );
    // `rows` that is not the number of rows in the file
    let (_, mut parts) = shards(2);
    let n: u64 = serde_json::from_str::<serde_json::Value>(&parts[1].manifest).unwrap()["rows"]
        .as_u64()
        .unwrap();
    set(&mut parts, 1, "rows", (n - 1).into());
    let e = merge(&parts).unwrap_err().to_string();
    assert!(
        e.contains("dir2/rows.csv") && e.contains("declares rows"),
        "{e}"
    );
    // rows removed from rows.csv with `rows` and the checksum made to match: the share is wrong
    let (_, mut parts) = shards(2);
    let mut lines: Vec<&str> = parts[1].rows.lines().collect();
    lines.pop();
    let cut = lines.join("\n") + "\n";
    set(&mut parts, 1, "rows", (n - 1).into());
    set(
        &mut parts,
        1,
        "rows_fnv1a64",
        pounding::input::fnv1a64_hex(cut.as_bytes()).into(),
    );
    parts[1].rows = cut;
    let e = merge(&parts).unwrap_err().to_string();
    assert!(
        e.contains("dir2/shard.json") && e.contains("rows = "),
        "{e}"
    );
    // a manifest without the checksum (older shards) is refused
    let (_, mut parts) = shards(2);
    let mut m: serde_json::Value = serde_json::from_str(&parts[0].manifest).unwrap();
    m.as_object_mut().unwrap().remove("rows_fnv1a64");
    parts[0].manifest = m.to_string();
    let e = merge(&parts).unwrap_err().to_string();
    assert!(e.contains("rows_fnv1a64"), "{e}");
    // a duplicate key in the manifest is refused with its line
    let (_, mut parts) = shards(2);
    parts[0].manifest = parts[0]
        .manifest
        .replacen("\"of\": 2,", "\"of\": 2,\n  \"of\": 2,", 1);
    let e = merge(&parts).unwrap_err().to_string();
    assert!(
        e.contains("duplicate key \"of\"") && e.contains("line"),
        "{e}"
    );
}

fn tmp(name: &str) -> crate::scratch::Scratch {
    crate::scratch::scratch_dir("it-hio", name)
}

fn names(dir: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[cfg(unix)]
#[test]
fn write_atomic_writes_through_devices_and_never_replaces_them() {
    use pounding::output::{Target, target_kind, write_atomic};
    use std::os::unix::fs::FileTypeExt;
    let full = std::path::Path::new("/dev/full");
    let null = std::path::Path::new("/dev/null");
    assert_eq!(target_kind(null).unwrap(), Target::WriteThrough);
    write_atomic(null, b"x").unwrap();
    if full.exists() {
        let e = write_atomic(full, b"x").unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::StorageFull, "{e}");
        assert!(
            std::fs::metadata(full)
                .unwrap()
                .file_type()
                .is_char_device()
        );
    }
    assert!(
        std::fs::metadata(null)
            .unwrap()
            .file_type()
            .is_char_device()
    );
    // a directory is refused and left as it is
    let d = tmp("dir");
    let sub = d.join("sub");
    std::fs::create_dir(&sub).unwrap();
    let e = write_atomic(&sub, b"x").unwrap_err();
    assert!(e.to_string().contains("directory"), "{e}");
    assert!(sub.is_dir());
    assert_eq!(names(&d), ["sub"], "no temporary left");
    // a regular file is replaced; a new path created
    write_atomic(&d.join("a"), b"1").unwrap();
    write_atomic(&d.join("a"), b"22").unwrap();
    assert_eq!(std::fs::read(d.join("a")).unwrap(), b"22");
    // a write that fails removes its temporary (the file's directory is missing)
    assert!(write_atomic(&d.join("missing/x"), b"1").is_err());
    assert_eq!(names(&d), ["a", "sub"]);
}

#[test]
fn temporaries_are_removed_on_drop_and_recognised_by_name() {
    use pounding::output::{TempFile, is_temporary_name};
    let d = tmp("tempfile");
    let target = d.join("plot.png");
    {
        let t = TempFile::new(&target).unwrap();
        std::fs::write(t.path(), b"partial").unwrap();
        let name = t.path().file_name().unwrap().to_string_lossy().into_owned();
        assert!(is_temporary_name(&name), "{name}");
    } // dropped without commit: an error path
    assert!(names(&d).is_empty());
    let t = TempFile::new(&target).unwrap();
    std::fs::write(t.path(), b"whole").unwrap();
    t.commit().unwrap();
    assert_eq!(names(&d), ["plot.png"]);
    for n in [".plot.png.123.tmp", ".x.123.tmp.png", ".figures.7.tmp"] {
        assert!(is_temporary_name(n), "{n}");
    }
    for n in [
        "plot.png",
        ".pounding.lock",
        ".x.tmp",
        ".x.12a.tmp",
        "x.1.tmp",
        ".x.1.tmp.a.b",
    ] {
        assert!(!is_temporary_name(n), "{n}");
    }
}

#[test]
fn an_output_directory_has_one_writer_at_a_time() {
    use pounding::output::{
        LOCK_FILE, OutputError, check_output_dir_free, lock_output_dir, remove_previous_outputs,
    };
    let scratch = tmp("lock");
    let d = scratch.join("out");
    check_output_dir_free(&d).unwrap();
    assert!(!d.exists(), "the early check creates nothing");
    let first = lock_output_dir(&d).unwrap();
    assert!(d.join(LOCK_FILE).is_file());
    let e = lock_output_dir(&d).unwrap_err();
    assert!(matches!(e, OutputError::Locked { .. }), "{e}");
    let msg = e.to_string();
    assert!(
        msg.contains(d.to_str().unwrap()) && msg.contains("in use"),
        "{msg}"
    );
    assert!(check_output_dir_free(&d).is_err());
    // stale outputs and temporaries are removed under the lock; other files are kept
    for n in ["timing.json", "old.png", ".old.png.99.tmp", "mine.txt"] {
        std::fs::write(d.join(n), b"x").unwrap();
    }
    remove_previous_outputs(&first, &["timing.json", "old.png", "never-written.csv"]).unwrap();
    assert_eq!(names(&d), [LOCK_FILE, "mine.txt"]);
    drop(first);
    // released and its file removed: the directory holds only the outputs
    assert_eq!(names(&d), ["mine.txt"]);
    let again = lock_output_dir(&d).unwrap();
    drop(again);
    check_output_dir_free(&d).unwrap();
    // a lock file left by a killed run (no holder) is taken over
    std::fs::write(d.join(LOCK_FILE), b"").unwrap();
    check_output_dir_free(&d).unwrap();
    let taken = lock_output_dir(&d).unwrap();
    drop(taken);
    // a holder whose file was unlinked (a run ending) does not block; the new file is the lock
    let old = std::fs::File::create(d.join(LOCK_FILE)).unwrap();
    old.try_lock().unwrap();
    std::fs::remove_file(d.join(LOCK_FILE)).unwrap();
    let new = lock_output_dir(&d).unwrap();
    assert!(lock_output_dir(&d).is_err());
    drop((old, new));
}

#[test]
fn path_within_resolves_links_and_missing_tails() {
    use pounding::output::path_is_within;
    let d = tmp("within");
    let shard = d.join("shard1");
    std::fs::create_dir(&shard).unwrap();
    assert!(path_is_within(&shard, &shard).unwrap());
    assert!(path_is_within(&shard.join("merged/x"), &shard).unwrap());
    assert!(path_is_within(&d.join("shard1/../shard1/m"), &shard).unwrap());
    assert!(!path_is_within(&d.join("merged"), &shard).unwrap());
    assert!(!path_is_within(&d.join("shard1/../m"), &shard).unwrap());
    // `..` after a directory that does not exist yet (create_dir_all makes it real)
    assert!(path_is_within(&d.join("new/../shard1"), &shard).unwrap());
    assert!(path_is_within(&d.join("new/a/../../shard1/x"), &shard).unwrap());
    assert!(!path_is_within(&d.join("new/../other"), &shard).unwrap());
    // a sibling whose name starts with the shard's is not inside it
    assert!(!path_is_within(&d.join("shard10"), &shard).unwrap());
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(&shard, d.join("link")).unwrap();
        assert!(path_is_within(&d.join("link/m"), &shard).unwrap());
    }
}
