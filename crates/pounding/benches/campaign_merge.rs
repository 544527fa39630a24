//! Peak memory and time of merging a synthetic campaign store of 10⁶ rows (1,000 parts of 1,000
//! runs, the columns of a three-segment bridge with two limit states) into one `runs.parquet`,
//! and of reading it back row group by row group. Prints the numbers (not a divan bench: the
//! peak resident memory of the process, `VmHWM`, is reset before each step with
//! `/proc/self/clear_refs` and read after it).
//!
//! `cargo bench -p pounding --bench campaign_merge`

use pounding::campaign::store::{self, Meta, PARTS, part_name};
use pounding::campaign::table::{Columns, Values, to_bytes};
use std::time::Instant;

const PARTS_N: usize = 1000;
const ROWS: usize = 1000;

fn peak_kb() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let l = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    l.split_whitespace().nth(1)?.parse().ok()
}

fn reset_peak() {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
}

fn names() -> Vec<String> {
    let mut c: Vec<String> = [
        "run",
        "id",
        "variant",
        "record",
        "entry",
        "stripe",
        "level_g",
        "im_g",
        "scale_factor",
        "status",
        "warnings",
        "error",
        "joint_opening_exceeded",
        "joint_opening_ratio",
        "bearing_exceeded",
        "bearing_ratio",
        "governing_seat_end",
        "governing_seat_ratio",
    ]
    .map(String::from)
    .to_vec();
    for s in 1..=3 {
        c.push(format!("seat_ratio_segment{s}_start"));
        c.push(format!("seat_ratio_segment{s}_end"));
    }
    c
}

fn part(p: usize) -> Columns {
    let r = p * ROWS..(p + 1) * ROWS;
    let f = |k: usize| Values::Float(r.clone().map(|i| Some((i * 7 + k) as f64 * 1e-3)).collect());
    let t = |s: &dyn Fn(usize) -> String| Values::Text(r.clone().map(|i| Some(s(i))).collect());
    let i64s = |m: usize| Values::Int(r.clone().map(|i| Some((i % m) as i64)).collect());
    let mut v = vec![
        Values::Int(r.clone().map(|i| Some(i as i64)).collect()),
        t(&|i| format!("base/SYN{:04}/level_g={}", i / 20, i % 20)),
        t(&|_| "base".into()),
        t(&|i| format!("SYN{:04}", i / 20)),
        i64s(1 << 40),
        i64s(20),
        f(1),
        f(2),
        f(3),
        t(&|_| "Completed".into()),
        i64s(3),
        t(&|_| String::new()),
        Values::Bool(r.clone().map(|i| Some(i % 3 == 0)).collect()),
        f(4),
        Values::Bool(r.clone().map(|i| Some(i % 5 == 0)).collect()),
        f(5),
        t(&|_| "segment3-end".into()),
        f(6),
    ];
    for k in 0..6 {
        v.push(f(7 + k));
    }
    Columns {
        cols: names().into_iter().zip(v).collect(),
    }
}

fn main() {
    let dir = tempfile::tempdir().unwrap();
    let parts = dir.path().join(PARTS);
    std::fs::create_dir_all(&parts).unwrap();
    let meta = Meta {
        format: "pounding campaign store 1".into(),
        name: "synthetic".into(),
        fingerprint: "0".into(),
        scenario_fingerprint: "0".into(),
        runs: PARTS_N * ROWS,
        runs_per_part: ROWS,
        parts: PARTS_N,
        columns: names(),
        variants: vec!["base".into()],
    };
    std::fs::write(
        dir.path().join(store::META),
        serde_json::to_string(&meta).unwrap(),
    )
    .unwrap();
    let t0 = Instant::now();
    for p in 0..PARTS_N {
        std::fs::write(parts.join(part_name(p)), to_bytes(&part(p)).unwrap()).unwrap();
    }
    println!(
        "wrote {PARTS_N} parts of {ROWS} rows in {:.2} s",
        t0.elapsed().as_secs_f64()
    );
    reset_peak();
    let before = peak_kb();
    let t0 = Instant::now();
    let m = store::merge(&[dir.path().to_path_buf()], dir.path()).unwrap();
    let size = std::fs::metadata(&m.path).unwrap().len();
    println!(
        "merge of {} rows: {:.2} s, {:.1} MB file, peak resident memory {} MB (before: {} MB)",
        m.rows,
        t0.elapsed().as_secs_f64(),
        size as f64 / 1e6,
        peak_kb().map_or(-1, |k| (k / 1024) as i64),
        before.map_or(-1, |k| (k / 1024) as i64),
    );
    reset_peak();
    let t0 = Instant::now();
    let mut n = 0;
    pounding::campaign::read::for_each_group(&m.path, &mut |c| {
        n += c.rows();
        Ok(())
    })
    .unwrap();
    println!(
        "read back {n} rows by row group: {:.2} s, peak resident memory {} MB",
        t0.elapsed().as_secs_f64(),
        peak_kb().map_or(-1, |k| (k / 1024) as i64)
    );
}
