//! `pounding simulate SCENARIO --set MANIFEST --scales …`: batches over a record-set manifest of
//! horizontal pairs. Every row equals the single run of a scenario file naming the pair's
//! records along y and x with the scale applied (written here, independently of the batch),
//! the bytes do not depend on `--threads`, shards merge to the whole, and a bad manifest is an
//! error naming it (exit 2, nothing written).

use crate::pounding;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("pairs", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The scenario's ground-motion factors and incidence (both factors and the incidence are
/// exercised: a pair's second component takes `scale_x`).
const SCALE_Y: f64 = 0.8;
const SCALE_X: f64 = -1.1;
const INCIDENCE: &str = "incidence_deg = 20.0\n";
const SCALES: [f64; 2] = [0.6, 1.7];
const DURATION: &str = "5";

/// The example's five-segment curved viaduct with `ground` as its `[ground_motion]` table.
fn viaduct(ground: &str) -> String {
    let ex = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-curved-5.toml");
    let text = std::fs::read_to_string(ex).unwrap();
    let old = "[ground_motion]\nrecord_y = \"builtin:ELC180\"\nrecord_x = \"builtin:ELC270\"\n";
    assert!(text.contains(old), "the example's [ground_motion] changed");
    text.replace(old, &format!("[ground_motion]\n{ground}"))
}

/// The batch's scenario (its own records are replaced by the manifest's) and the manifest:
/// El Centro 180/270 as a pair, the swapped pair, and 180 alone.
fn setup(dir: &Path) -> (PathBuf, PathBuf) {
    let sc = dir.join("bridge.toml");
    std::fs::write(
        &sc,
        viaduct(&format!(
            "record_y = \"builtin:ELC180\"\nrecord_x = \"builtin:ELC270\"\n\
             scale_y = {SCALE_Y:?}\nscale_x = {SCALE_X:?}\n{INCIDENCE}"
        )),
    )
    .unwrap();
    let set = dir.join("set.toml");
    std::fs::write(
        &set,
        "[set]\nname = \"El Centro both ways\"\n\
         [[record]]\nid = \"elc-180-270\"\nx = \"builtin:ELC180\"\ny = \"builtin:ELC270\"\n\
         [record.meta]\nstation = \"El Centro, Imperial Valley\"\nmagnitude = 6.9\n\
         [[record]]\nid = \"elc-270-180\"\nx = \"builtin:ELC270\"\ny = \"builtin:ELC180\"\n\
         [[record]]\nid = \"elc-180\"\nx = \"builtin:ELC180\"\n",
    )
    .unwrap();
    (sc, set)
}

/// The entries of the manifest written by [`setup`]: id, record along y, record along x.
const ENTRIES: [(&str, &str, &str); 3] = [
    ("elc-180-270", "ELC180", "ELC270"),
    ("elc-270-180", "ELC270", "ELC180"),
    ("elc-180", "ELC180", ""),
];

/// The header and rows of a CSV text (quoted fields with commas and doubled quotes), read by
/// the csv crate.
fn rows(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(text.as_bytes());
    let mut all = reader
        .records()
        .map(|r| r.unwrap().iter().map(String::from).collect::<Vec<_>>());
    let head = all.next().unwrap();
    (head, all.collect())
}

/// Runs the batch into `out` with `extra` flags: the text of `batch.csv`.
fn batch(sc: &Path, set: &Path, out: &Path, extra: &[&str]) -> String {
    let scales = format!("{:?},{:?}", SCALES[0], SCALES[1]);
    let o = pounding()
        .args(["simulate", s(sc), "--set", s(set), "--scales", &scales])
        .args(["--duration", DURATION, "--out", s(out)])
        .args(extra)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::metadata(out.join("batch.png")).unwrap().len() > 10_000);
    std::fs::read_to_string(out.join("batch.csv")).unwrap()
}

/// The raw JSON token of `key` in pretty-printed `text`: at the top level (`within = None`),
/// in the object `within = Some((name, None))` (`"energy_J": {…}`) or in element `k` of the
/// array `within = Some((name, Some(k)))` (`"joints": [{…}, …]`).
fn token(text: &str, within: Option<(&str, Option<usize>)>, key: &str) -> String {
    let (start, indent) = match within {
        None => (0, "  "),
        Some((name, None)) => (at(text, 0, &format!("\n  \"{name}\": {{")), "    "),
        Some((name, Some(k))) => {
            let mut p = at(text, 0, &format!("\n  \"{name}\": ["));
            for _ in 0..=k {
                p = at(text, p + 1, "\n    {");
            }
            (p, "      ")
        }
    };
    let pat = format!("\n{indent}\"{key}\": ");
    let p = at(text, start, &pat) + pat.len();
    let rest = &text[p..];
    rest[..rest.find([',', '\n']).unwrap()].to_string()
}

/// The position of `pat` in `text` at or after `from`.
fn at(text: &str, from: usize, pat: &str) -> usize {
    from + text[from..]
        .find(pat)
        .unwrap_or_else(|| panic!("{pat:?} not found"))
}

/// Asserts that a `batch.csv` cell says what the summary's JSON token says: the same number
/// (both shortest round-trip texts, parsed with Rust's correctly rounded parser), the same text
/// or boolean, an empty cell for `null`.
fn same(col: &str, cell: &str, tok: &str) {
    match tok {
        "null" => assert_eq!(cell, "", "{col}"),
        "true" | "false" => assert_eq!(cell, tok, "{col}"),
        t if t.starts_with('"') => assert_eq!(cell, t.trim_matches('"'), "{col}"),
        t => assert_eq!(
            cell.parse::<f64>().unwrap(),
            t.parse::<f64>().unwrap(),
            "{col}: {cell} vs {t}"
        ),
    }
}

/// Checks every summary column of a bridge's batch row against the single run's
/// `summary.json` text `js` (each column's source in the summary written out).
fn row_equals_summary(head: &[String], row: &[String], js: &str) {
    let num = |t: String| t.parse::<f64>().unwrap();
    let top = |k: &str| token(js, None, k);
    for (col, cell) in head.iter().zip(row) {
        let (c, cell) = (col.as_str(), cell.as_str());
        let seat = c
            .strip_prefix("segment")
            .and_then(|r| r.strip_suffix("_seat_ratio"))
            .and_then(|r| r.split_once('_'));
        let tok = if let Some((i, face)) = seat {
            // seats[] are per segment [start, end], in bridge order
            let k = 2 * (i.parse::<usize>().unwrap() - 1) + usize::from(face == "end");
            token(js, Some(("seats", Some(k))), "ratio")
        } else if let Some(key) = c.strip_prefix("governing_seat_") {
            token(js, Some(("governing_seat", None)), key)
        } else if let Some(rest) = c.strip_prefix("joint") {
            let (k, key) = rest.split_once('_').unwrap();
            token(
                js,
                Some(("joints", Some(k.parse::<usize>().unwrap() - 1))),
                key,
            )
        } else if let Some(rest) = c.strip_prefix("segment") {
            let (i, key) = rest.split_once('_').unwrap();
            token(
                js,
                Some(("segments", Some(i.parse::<usize>().unwrap() - 1))),
                key,
            )
        } else if let Some(rest) = c.strip_prefix("abutment_") {
            let (side, key) = rest.split_once('_').unwrap();
            token(
                js,
                Some(("abutments", Some(usize::from(side == "end")))),
                key,
            )
        } else {
            match c {
                "index" | "record" | "record_y" | "record_x" | "scale" | "error" => continue,
                _ if c.starts_with("meta_") => continue,
                "pga_mps2" | "pga_g" => {
                    let g = Some(("ground_motion", None));
                    let pga = num(token(js, g, "pga_y_mps2")).max(num(token(js, g, "pga_x_mps2")));
                    let want = if c == "pga_g" { pga / 9.80665 } else { pga };
                    assert_eq!(cell.parse::<f64>().unwrap(), want, "{c}");
                    continue;
                }
                "peak_joint_closing_m" | "peak_joint_opening_m" => {
                    let key = c.replace("_joint", "");
                    let joints: f64 = (0..4)
                        .map(|k| num(token(js, Some(("joints", Some(k))), &key)))
                        .fold(f64::NEG_INFINITY, f64::max);
                    assert_eq!(cell.parse::<f64>().unwrap(), joints, "{c}");
                    continue;
                }
                "max_penetration_m" => top("peak_penetration_m"),
                "input_energy_J" => token(js, Some(("energy_J", None)), "input"),
                "viscous_dissipation_J"
                | "contact_dissipation_J"
                | "hysteretic_dissipation_J"
                | "restrainer_work_J" => {
                    token(js, Some(("energy_J", None)), c.trim_end_matches("_J"))
                }
                // the rigid law: no contact force, no time-step figure, no Newton iteration
                "peak_contact_force_n" | "steps_per_contact" | "newton_failures" => {
                    assert_eq!(cell, "", "{c}");
                    assert_eq!(
                        token(js, Some(("joints", Some(0))), "peak_contact_force_n"),
                        "null"
                    );
                    continue;
                }
                "warnings" => {
                    let v: serde_json::Value = serde_json::from_str(js).unwrap();
                    let n = v["warnings"].as_array().unwrap().len();
                    assert_eq!(cell.parse::<usize>().unwrap(), n, "{c}");
                    continue;
                }
                _ => top(c),
            }
        };
        same(c, cell, &tok);
    }
}

#[test]
fn pair_batch_rows_equal_single_runs_of_the_pairs_for_any_threads_and_shards() {
    let d = tmp("rows");
    let (sc, set) = setup(&d);
    let one = batch(&sc, &set, &d.join("t1"), &["--threads", "1"]);
    let two = batch(&sc, &set, &d.join("t2"), &["--threads", "2"]);
    assert_eq!(one, two, "batch.csv depends on --threads");
    let (head, all) = rows(&one);
    assert_eq!(all.len(), ENTRIES.len() * SCALES.len());
    assert_eq!(
        head[..7],
        [
            "index",
            "record",
            "record_y",
            "record_x",
            "meta_magnitude",
            "meta_station",
            "scale"
        ]
    );
    let mut merged = Vec::new();
    for k in 1..=2 {
        let (h, r) = rows(&batch(
            &sc,
            &set,
            &d.join(format!("s{k}")),
            &["--shard", &format!("{k}/2")],
        ));
        assert_eq!(h, head);
        merged.extend(r);
    }
    merged.sort_by_key(|r| r[0].parse::<usize>().unwrap());
    assert_eq!(merged, all, "the shards do not merge to the whole batch");

    let mut impacts = 0;
    for (i, row) in all.iter().enumerate() {
        let (a, b) = (i / SCALES.len(), i % SCALES.len());
        let (id, y, x) = ENTRIES[a];
        assert_eq!(row[0], i.to_string());
        assert_eq!(row[1], id);
        assert!(row[2].contains(y), "{}", row[2]);
        assert!(
            x.is_empty() && row[3].is_empty() || row[3].contains(x),
            "{}",
            row[3]
        );
        assert_eq!(row[4], if a == 0 { "6.9" } else { "" });
        assert_eq!(
            row[5],
            if a == 0 {
                "El Centro, Imperial Valley"
            } else {
                ""
            }
        );
        assert_eq!(row[6].parse::<f64>().unwrap(), SCALES[b]);
        // the single run: a scenario naming the pair's records and the scaled factors
        let s_ = SCALES[b];
        let record_x = if x.is_empty() {
            "none".to_string()
        } else {
            format!("builtin:{x}")
        };
        let single = d.join(format!("single{i}.toml"));
        std::fs::write(
            &single,
            viaduct(&format!(
                "record_y = \"builtin:{y}\"\nrecord_x = \"{record_x}\"\nscale_y = {:?}\n\
                 scale_x = {:?}\n{INCIDENCE}",
                SCALE_Y * s_,
                SCALE_X * s_
            )),
        )
        .unwrap();
        let out = d.join(format!("single{i}"));
        let o = pounding()
            .args([
                "simulate",
                s(&single),
                "--duration",
                DURATION,
                "--out",
                s(&out),
            ])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let js = std::fs::read_to_string(out.join("summary.json")).unwrap();
        row_equals_summary(&head, row, &js);
        impacts += row[head.iter().position(|h| h == "impacts").unwrap()]
            .parse::<usize>()
            .unwrap();
    }
    // the comparison means something: the runs pound
    assert!(impacts > 0, "no impacts in any run");
    // the second component matters: the pair and the single record differ at the same scale
    let closing = head
        .iter()
        .position(|h| h == "peak_seat_displacement_m")
        .unwrap();
    assert_ne!(all[1][closing], all[5][closing]);
}

#[test]
fn a_manifest_with_a_missing_file_or_a_bad_key_exits_2_naming_it_and_writes_nothing() {
    let d = tmp("bad");
    let (sc, _) = setup(&d);
    let cases: [(&str, &str, &[&str]); 4] = [
        (
            "missing.toml",
            "[[record]]\nid = \"a\"\nx = \"builtin:ELC180\"\n\
             [[record]]\nid = \"b\"\nx = \"builtin:ELC270\"\ny = \"nowhere.AT2\"\n",
            &[
                "missing.toml",
                "record[1].y",
                "missing.toml:7",
                "nowhere.AT2",
            ],
        ),
        (
            "badkey.toml",
            "[[record]]\nid = \"a\"\nx = \"builtin:ELC180\"\nz = \"builtin:ELC270\"\n",
            &["badkey.toml", "line 4", "`z`"],
        ),
        (
            "missing.csv",
            "id,x,y\na,builtin:ELC180,builtin:ELC270\nb,builtin:ELC270,gone.csv\n",
            &["missing.csv:3", "column C", "gone.csv"],
        ),
        ("nothere.toml", "", &["nothere.toml"]),
    ];
    for (name, text, needles) in cases {
        let m = d.join(name);
        if !text.is_empty() {
            std::fs::write(&m, text).unwrap();
        }
        let out = d.join("o");
        let o = pounding()
            .args(["simulate", s(&sc), "--set", s(&m), "--scales", "1,2"])
            .args(["--out", s(&out)])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        for n in needles {
            assert!(err.contains(n), "{name}: no {n:?} in {err}");
        }
        assert!(!out.exists(), "{name}: wrote output");
    }
    // a manifest given to --records is named as such, and --records with --set is refused
    let m = d.join("missing.toml");
    for args in [
        vec!["--records", s(&m)],
        vec!["--set", s(&m), "--records", s(&m)],
        vec!["--set", s(&m), "--record-dt", "0.01"],
    ] {
        let o = pounding()
            .args(["simulate", s(&sc)])
            .args(&args)
            .args(["--out", s(&d.join("o"))])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("--set"), "{args:?}: {err}");
        assert!(!d.join("o").exists());
    }
}
