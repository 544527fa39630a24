//! `pounding fragility` on a CSV record-set manifest (issue 13): the same output bytes as on the
//! equivalent TOML manifest, by `--set` or `[fragility] records`; bad CSV manifests exit 2,
//! name the file, the line and the column, and write nothing.

use crate::{run_capture, scratch_dir};
use std::path::Path;

const SET_TOML: &str = r#"[[record]]
id = "NS"
x = "builtin:ELC180"
[record.meta]
azimuth = 180
event = "Imperial Valley, 1940"

[[record]]
id = "EW"
x = "builtin:ELC270"
[record.meta]
azimuth = 270
station = "007"

[[record]]
id = "pair"
x = "builtin:ELC180"
y = "builtin:ELC270"
"#;

/// The same set as a spreadsheet saves it: byte-order mark, CRLF, quoted comma, empty cells.
const SET_CSV: &str = "\u{feff}id,x,y,azimuth,event,station\r\n\
NS,builtin:ELC180,,180,\"Imperial Valley, 1940\",\r\n\
EW,builtin:ELC270,,270,,007\r\n\
pair,builtin:ELC180,builtin:ELC270,,,\r\n";

fn study(name: &str, records: &str) -> crate::scratch::Scratch {
    let d = scratch_dir("mcsv", name);
    // the bridge, stripes and limit states of cli::fragility (2 s runs, 3 levels)
    let scenario = crate::fragility::SCENARIO.replace(
        "records = \"set.toml\"",
        &format!("records = \"{records}\""),
    );
    std::fs::write(d.join("bridge.toml"), scenario).unwrap();
    std::fs::write(d.join("set.toml"), SET_TOML).unwrap();
    std::fs::write(d.join("set.csv"), SET_CSV).unwrap();
    d
}

fn fragility(d: &Path, set: Option<&str>, out: &str) -> (Option<i32>, String, String) {
    let scenario = d.join("bridge.toml");
    let out = d.join(out);
    let mut args = vec![
        "fragility",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "2",
    ];
    let set = set.map(|s| d.join(s));
    if let Some(s) = &set {
        args.extend(["--set", s.to_str().unwrap()]);
    }
    run_capture(&args)
}

#[test]
fn a_csv_manifest_gives_the_output_bytes_of_the_equivalent_toml() {
    let d = study("same", "set.csv");
    let (code, _, err) = fragility(&d, Some("set.toml"), "toml");
    assert_eq!(code, Some(0), "{err}");
    let (code, _, err) = fragility(&d, Some("set.csv"), "csv");
    assert_eq!(code, Some(0), "{err}");
    // `[fragility] records = "set.csv"`, relative to the scenario, without --set
    let (code, _, err) = fragility(&d, None, "records");
    assert_eq!(code, Some(0), "{err}");
    for f in [
        "runs.csv",
        "fragility.csv",
        "fragility.json",
        "fragility.png",
    ] {
        let a = std::fs::read(d.join("toml").join(f)).unwrap();
        for other in ["csv", "records"] {
            let b = std::fs::read(d.join(other).join(f)).unwrap();
            assert!(a == b, "{f} differs between set.toml and {other}");
        }
    }
    let runs = std::fs::read_to_string(d.join("csv/runs.csv")).unwrap();
    let mut lines = runs.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .starts_with("record,azimuth,event,station,level_g,"),
        "{runs}"
    );
    // 3 entries x 3 levels; the metadata cells as written in the spreadsheet
    assert_eq!(lines.clone().count(), 9, "{runs}");
    assert!(
        runs.contains("\nNS,180,\"Imperial Valley, 1940\",,0.2,"),
        "{runs}"
    );
    assert!(runs.contains("\nEW,270,,007,0.2,"), "{runs}");
    assert!(runs.contains("\npair,,,,0.2,"), "{runs}");
}

/// Bad CSV manifests: (name, text, what stderr must hold).
const BAD: &[(&str, &str, &str)] = &[
    (
        "lookalike",
        "id,x,DT\nA,builtin:ELC180,\n",
        "set.csv:1, column C",
    ),
    ("no-x", "id,path\nA,builtin:ELC180\n", "no \"x\" column"),
    (
        "neither",
        "id,x,y\nA,builtin:ELC180,\nB,,\n",
        "x (set.csv:3, column B): empty",
    ),
    (
        "dt",
        "id,x,dt\nA,a.txt,0.0l\n",
        "dt (set.csv:2, column C): not a number",
    ),
    (
        "duplicate",
        "id,x\nA,builtin:ELC180\nA,builtin:ELC270\n",
        "id (set.csv:3, column A): duplicate id \"A\" (also line 2)",
    ),
    ("header-only", "id,x\n", "no records"),
    (
        "ragged",
        "id,x,m\nA,builtin:ELC180,1\nB,builtin:ELC270\n",
        "set.csv:3, column C: the row has 2 cells",
    ),
    (
        "reserved",
        "id,x,scale\nA,builtin:ELC180,1\n",
        "set.csv:1, column C",
    ),
    (
        "missing-file",
        "id,x\nA,nope.AT2\n",
        "x (set.csv:2, column B)",
    ),
    (
        "unterminated-quote",
        "id,x,event\nA,builtin:ELC180,\"Imp\nB,builtin:ELC270,ev\n",
        "set.csv:2, column C: a quoted cell opens here and is never closed",
    ),
    (
        "units-builtin",
        "id,x,units\nA,builtin:ELC180,m/s2\n",
        "units (set.csv:2, column C)",
    ),
];

#[test]
fn bad_csv_manifests_exit_2_name_file_line_and_column_and_write_nothing() {
    for (name, text, needle) in BAD {
        let d = study(name, "set.csv");
        std::fs::write(d.join("set.csv"), text).unwrap();
        for set in [None, Some("set.csv")] {
            let (code, _, err) = fragility(&d, set, "out");
            let err = err.replace(&format!("{}/", d.display()), "");
            assert_eq!(code, Some(2), "{name}: {err}");
            assert!(err.contains(needle), "{name}: {needle:?} not in {err}");
            assert!(!d.join("out").exists(), "{name}: something was written");
        }
    }
    // an extension that is neither .toml nor .csv: refused, not guessed
    let d = study("ext", "set.txt");
    std::fs::write(d.join("set.txt"), SET_CSV).unwrap();
    let (code, _, err) = fragility(&d, None, "out");
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("set.txt") && err.contains("unknown manifest type"),
        "{err}"
    );
    assert!(!d.join("out").exists());
}
