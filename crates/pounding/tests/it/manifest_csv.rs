//! Record-set manifests in CSV (issue 13): the same record set as the equivalent TOML manifest
//! (whatever the line endings, byte-order mark, quoting, blank rows and spaces a spreadsheet
//! writes), metadata cells kept as written, and every bad input refused naming the file, the
//! line and the column.

use pounding::ground_motion::set::{MetaValue, RecordSet};
use std::path::Path;

fn scratch(name: &str) -> crate::scratch::Scratch {
    let d = crate::scratch::scratch_dir("mcsv", name);
    // a one-column file (needs dt) and a CSV `t, a` pair with equal sample intervals
    std::fs::write(d.join("a.txt"), "0.0\n1.0\n-2.0\n0.5\n").unwrap();
    std::fs::write(d.join("b.csv"), "0,0\n0.02,0.1\n0.04,-0.2\n").unwrap();
    std::fs::write(d.join("c.csv"), "0,0\n0.02,0.3\n0.04,0.1\n").unwrap();
    d
}

/// A TOML manifest without `[set]` and its CSV equivalent (as a spreadsheet saves it).
const TOML: &str = r#"[[record]]
id = "A"
x = "a.txt"
dt = 0.01
units = "m/s2"
[record.meta]
event = "Imperial Valley, 1940"
magnitude = 6.95
station = "007"
soft = true

[[record]]
id = "P"
x = "builtin:ELC180"
y = "builtin:ELC270"
[record.meta]
magnitude = 7
note = 'say "hi"' 

[[record]]
id = "Q"
x = "b.csv"
y = "c.csv"
units = "g"
[record.meta]
magnitude = 6.5
"#;

const CSV: &str = "id,x,y,dt,units,event,magnitude,station,soft,note\n\
A,a.txt,,0.01,m/s2,\"Imperial Valley, 1940\",6.95,007,true,\n\
P,builtin:ELC180,builtin:ELC270,,,,7,,,\"say \"\"hi\"\"\"\n\
Q,b.csv,c.csv,,g,,6.5,,,\n";

fn load(d: &Path, name: &str, text: &str) -> RecordSet {
    std::fs::write(d.join(name), text).unwrap();
    RecordSet::load(&d.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn a_csv_manifest_gives_the_record_set_of_the_equivalent_toml() {
    let d = scratch("same");
    let toml = load(&d, "set.toml", TOML);
    assert_eq!(toml.records.len(), 3);
    // what a spreadsheet may write: CRLF, a byte-order mark, blank rows (empty or all commas),
    // spaces around cells, columns in another order, an upper-case extension
    let crlf = CSV.replace('\n', "\r\n");
    let bom = format!("\u{feff}{crlf}");
    let blank = CSV.replacen("\nP,", "\n,,,,,,,,,\n\nP,", 1);
    let spaced = " id , x ,y, dt,units ,event,magnitude , station,soft,note \n\
        A , a.txt,, 0.01 ,m/s2,\"Imperial Valley, 1940\", 6.95,007 , true,\n\
        P, builtin:ELC180 ,builtin:ELC270,  ,,,7,,,\"say \"\"hi\"\"\"\n\
        Q,b.csv , c.csv,, g ,,6.5,,,\n"
        .to_string();
    let reordered = "magnitude,units,dt,y,x,id,station,event,soft,note\n\
        6.95,m/s2,0.01,,a.txt,A,007,\"Imperial Valley, 1940\",true,\n\
        7,,,builtin:ELC270,builtin:ELC180,P,,,,\"say \"\"hi\"\"\"\n\
        6.5,g,,c.csv,b.csv,Q,,,,\n";
    for (name, text) in [
        ("plain.csv", CSV.to_string()),
        ("crlf.csv", crlf),
        ("bom.csv", bom),
        ("blank.csv", blank),
        ("spaced.csv", spaced),
        ("reordered.csv", reordered.to_string()),
        ("upper.CSV", CSV.to_string()),
    ] {
        let csv = load(&d, name, &text);
        assert_eq!(csv, toml, "{name}");
    }
    // the values themselves (not only equal to TOML's): the quoted comma and quote survive,
    // `007` stays text, an empty cell is no value
    let a = &toml.records[0];
    assert_eq!(a.x.values(), &[0.0, 1.0, -2.0, 0.5]);
    assert_eq!(a.x.dt(), Some(0.01));
    assert!(a.meta.contains(&(
        "event".into(),
        MetaValue::Text("Imperial Valley, 1940".into())
    )));
    assert!(
        a.meta
            .contains(&("station".into(), MetaValue::Text("007".into())))
    );
    assert!(a.meta.contains(&("soft".into(), MetaValue::Bool(true))));
    assert_eq!(toml.records[1].meta.len(), 2);
    assert_eq!(
        toml.meta_keys(),
        vec!["event", "magnitude", "note", "soft", "station"]
    );
    // a pair read with units g: times g0
    let q = &toml.records[2];
    assert!((q.x.values()[1] - 0.1 * pounding::ground_motion::G0).abs() < 1e-12);
    assert!(q.y.is_some());
}

#[test]
fn csv_metadata_cells_keep_their_text() {
    let d = scratch("cells");
    let s = load(
        &d,
        "m.csv",
        "id,x,m\nA,builtin:ELC180,6.90\nB,builtin:ELC180,6.9\nC,builtin:ELC180,42\n\
         D,builtin:ELC180,false\nE,builtin:ELC180,1e3\nF,builtin:ELC180,nan\nG,builtin:ELC180,-0\n",
    );
    let cells: Vec<String> = s.records.iter().map(|r| r.meta[0].1.csv_cell()).collect();
    // every runs.csv cell is the manifest's cell as written
    assert_eq!(cells, ["6.90", "6.9", "42", "false", "1e3", "nan", "-0"]);
    assert_eq!(s.records[1].meta[0].1, MetaValue::Number(6.9));
    assert_eq!(s.records[2].meta[0].1, MetaValue::Integer(42));
    assert_eq!(s.records[0].meta[0].1, MetaValue::Text("6.90".into()));
}

fn err(name: &str, text: &str) -> String {
    let d = scratch(&format!("err-{name}"));
    let p = d.join(name);
    std::fs::write(&p, text).unwrap();
    RecordSet::load(&p).unwrap_err().to_string()
}

/// Each bad CSV manifest and the pieces its message must hold (file:line, column, reason).
pub const BAD: &[(&str, &str, &[&str])] = &[
    (
        "look-alike column",
        "id,x,Units\nA,builtin:ELC180,g\n",
        &[
            "set.csv:1, column C",
            "\"Units\"",
            "looks like",
            "\"units\"",
        ],
    ),
    (
        "unit for units",
        "id,x,unit\nA,a.txt,g\n",
        &["set.csv:1, column C", "\"unit\"", "meta_unit"],
    ),
    (
        "format column",
        "id,x,format\nA,a.txt,at2\n",
        &["set.csv:1, column C", "format is found from its file"],
    ),
    (
        "missing x column",
        "id,file_name\nA,a.txt\n",
        &["set.csv:1", "no \"x\" column"],
    ),
    (
        "missing id column",
        "x\nbuiltin:ELC180\n",
        &["set.csv:1", "no \"id\" column"],
    ),
    (
        "semicolons",
        "id;x\nA;builtin:ELC180\n",
        &["set.csv:1", "no \"id\" column", "semicolons"],
    ),
    (
        "neither x nor y",
        "id,x,y\nA,builtin:ELC180,\nB,,\n",
        &["x (set.csv:3, column B): empty"],
    ),
    (
        "y without x",
        "id,x,y\nA,,builtin:ELC270\n",
        &["x (set.csv:2, column B)", "y is given"],
    ),
    (
        "non-numeric dt",
        "id,x,dt\nA,a.txt,0.01\nB,a.txt,abc\n",
        &["dt (set.csv:3, column C): not a number: \"abc\""],
    ),
    (
        "zero dt",
        "id,x,dt\nA,a.txt,0\n",
        &["dt (set.csv:2, column C): invalid dt = 0"],
    ),
    (
        "unknown units",
        "id,x,units\nA,a.txt,gal\n",
        &["units (set.csv:2, column C): unknown units \"gal\""],
    ),
    (
        "duplicate ids",
        "id,x\nA,builtin:ELC180\nB,builtin:ELC180\nA,builtin:ELC270\n",
        &["id (set.csv:4, column A): duplicate id \"A\" (also line 2)"],
    ),
    (
        "empty id",
        "x,id\nbuiltin:ELC180,\n",
        &["id (set.csv:2, column B): must be non-empty"],
    ),
    ("header only", "id,x,y\r\n", &["set.csv", "no records"]),
    ("empty file", "", &["set.csv", "empty file"]),
    (
        "ragged row",
        "id,x,magnitude\nA,builtin:ELC180,6.9\nB,builtin:ELC270\n",
        &[
            "set.csv:3, column C: the row has 2 cells, the header 3",
            "ragged",
        ],
    ),
    (
        "ragged long row",
        "id,x\r\nA,builtin:ELC180,6.9\r\n",
        &["set.csv:2, column C: the row has 3 cells, the header 2"],
    ),
    (
        "reserved metadata",
        "id,x,status\nA,builtin:ELC180,ok\n",
        &[
            "set.csv:1, column C",
            "\"status\" is an output column of runs.csv",
        ],
    ),
    (
        "limit-state metadata",
        "id,x,seat_ratio\nA,builtin:ELC180,1\n",
        &["set.csv:1, column C", "ending in _ratio"],
    ),
    (
        "per-end seat metadata",
        "id,x,seat_ratio_segment1_end_x\nA,builtin:ELC180,1\n",
        &["set.csv:1, column C", "starting with seat_ratio_"],
    ),
    (
        "governing seat metadata",
        "id,x,governing_seat_end\nA,builtin:ELC180,1\n",
        &[
            "set.csv:1, column C",
            "\"governing_seat_end\" is an output column of runs.csv",
        ],
    ),
    (
        "repeated column",
        "id,x,m,m\nA,builtin:ELC180,1,2\n",
        &["set.csv:1, column D", "repeats column C"],
    ),
    (
        "unnamed column with a value",
        "id,x,\nA,builtin:ELC180,\nB,builtin:ELC180,7\n",
        &["set.csv:3, column C", "no name in the header"],
    ),
    (
        "missing files, all named",
        "id,x,y\nA,nope1.AT2,\nB,builtin:ELC180,nope2.AT2\n",
        &[
            "x (set.csv:2, column B)",
            "nope1.AT2",
            "y (set.csv:3, column C)",
            "nope2.AT2",
        ],
    ),
    (
        "dt for a built-in record",
        "id,x,dt\nA,builtin:ELC180,0.01\n",
        &[
            "x (set.csv:2, column B)",
            "the dt cell applies to one-column files",
        ],
    ),
    (
        "one-column file without dt",
        "id,x\nA,a.txt\n",
        &["x (set.csv:2, column B)", "dt cell"],
    ),
    (
        "a pair with different sample intervals",
        "id,x,y\nA,b.csv,d.csv\n",
        &["y (set.csv:2, column C)", "different sample intervals"],
    ),
    (
        "line after blank lines",
        "id,x\n\n,\n\nA,\n",
        &["x (set.csv:5, column B): empty"],
    ),
    (
        "line after a quoted line break, CRLF",
        "id,x,note\r\nA,builtin:ELC180,\"two\r\nlines\"\r\nB,,\r\n",
        &["x (set.csv:4, column B): empty"],
    ),
    (
        "unterminated quote swallowing later rows",
        "id,x,dt,units,event\nA,a.txt,0.01,m/s2,\"Imp\nB,a.txt,0.01,m/s2,ev\n",
        &["set.csv:2, column E", "never closed"],
    ),
    (
        "unterminated quote on the last row",
        "id,x,dt,units,event\r\nA,a.txt,0.01,m/s2,ok\r\nB,a.txt,0.01,m/s2,\"Imp\r\n",
        &["set.csv:3, column E", "never closed"],
    ),
    (
        "unterminated quote after a closed multi-line one and an escaped quote",
        "id,x,note\nA,builtin:ELC180,\"two\nlines \"\"q\"\"\"\nB,builtin:ELC270,\"x\n",
        &["set.csv:4, column C", "never closed"],
    ),
];

#[test]
fn csv_manifest_errors_name_the_file_line_and_column() {
    for (what, text, needles) in BAD {
        let d = scratch(&format!("bad-{}", what.replace(' ', "-")));
        std::fs::write(d.join("d.csv"), "0,0\n0.01,1\n0.02,0\n").unwrap();
        std::fs::write(d.join("set.csv"), text).unwrap();
        let e = RecordSet::load(&d.join("set.csv")).unwrap_err().to_string();
        // the manifest as the user named it (here: a path in a scratch directory)
        let e = e.replace(&format!("{}/", d.display()), "");
        for n in *needles {
            assert!(e.contains(n), "{what}: {n:?} not in {e}");
        }
    }
}

#[test]
fn a_manifest_of_another_type_is_refused_not_guessed() {
    for name in ["set.txt", "set", "set.tsv", "set.toml.bak"] {
        let e = err(name, "id,x\nA,builtin:ELC180\n");
        assert!(
            e.contains(name) && e.contains("unknown manifest type") && e.contains(".csv"),
            "{name}: {e}"
        );
    }
    // a CSV text in a .toml file is read as TOML (and refused by the TOML reader)
    let e = err("set.toml", "id,x\nA,builtin:ELC180\n");
    assert!(e.contains("invalid record set"), "{e}");
}

#[test]
fn the_shipped_csv_example_lists_the_records_of_the_toml_example() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fragility");
    let t = RecordSet::load(&dir.join("el-centro.toml")).unwrap();
    let c = RecordSet::load(&dir.join("el-centro.csv")).unwrap();
    assert_eq!(c.records.len(), 3);
    assert_eq!(c.records, t.records);
    // a CSV manifest has no [set] table
    assert_eq!((c.name.as_str(), c.source.as_str()), ("", ""));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]
    /// Any text of CSV-ish characters is read or refused, never a panic; a refusal names the file.
    #[test]
    fn any_csv_text_is_read_or_refused_naming_the_file(
        body in "[,\"\r\n ax1.:b\u{feff}eé-]{0,60}",
        header in proptest::sample::select(vec!["id,x", "id,x,y,dt,units,m", "x,id,dt", "", "id"]),
    ) {
        let text = format!("{header}\n{body}");
        match RecordSet::from_csv(&text, "p.csv", Path::new("/nonexistent-dir")) {
            Ok(s) => proptest::prop_assert!(!s.records.is_empty()),
            Err(e) => proptest::prop_assert!(e.to_string().contains("p.csv"), "{e}"),
        }
    }
}

/// A `units` key or cell for a record that keeps its own units (a built-in record, an `.AT2`
/// whose header names them) is refused naming the key, file and line, in TOML and CSV alike; an
/// `.AT2` whose header names no units takes them.
#[test]
fn units_for_a_record_with_its_own_units_are_refused_not_ignored() {
    let d = scratch("units-own");
    let at2 = |units: &str| {
        format!(
            "PEER NGA STRONG MOTION DATABASE RECORD\nTEST RECORD\n\
             ACCELERATION TIME SERIES{units}\nNPTS=    4, DT=   .0100 SEC\n\
             0.1 0.2 -0.1 0.0\n"
        )
    };
    std::fs::write(d.join("g.AT2"), at2(" IN UNITS OF G")).unwrap();
    std::fs::write(d.join("none.AT2"), at2("")).unwrap();
    let cases = [
        (
            "t1.toml",
            "[[record]]\nid = \"A\"\nx = \"g.AT2\"\nunits = \"m/s2\"\n",
            "record[0].units (",
            "t1.toml:4)",
        ),
        (
            "t2.toml",
            "[[record]]\nid = \"A\"\nx = \"builtin:ELC180\"\n\n[[record]]\nid = \"B\"\n\
             x = \"builtin:ELC180\"\ny = \"builtin:ELC270\"\nunits = \"g\"\n",
            "record[1].units (",
            "t2.toml:9)",
        ),
        (
            "c1.csv",
            "id,x,units\nA,none.AT2,\nB,g.AT2,m/s2\n",
            "units (",
            "c1.csv:3, column C)",
        ),
        (
            "c2.csv",
            "id,x,units\nA,builtin:ELC180,m/s2\n",
            "units (",
            "c2.csv:2, column C)",
        ),
    ];
    for (name, text, key, at) in cases {
        std::fs::write(d.join(name), text).unwrap();
        let e = RecordSet::load(&d.join(name)).unwrap_err().to_string();
        assert!(
            e.contains(key) && e.contains(at) && e.contains("does not apply; remove it"),
            "{name}: {e}"
        );
        assert!(e.contains("AT2") || e.contains("built-in"), "{name}: {e}");
    }
    // in a pair, `units` applies to the member that takes units: a text file beside a built-in
    // record is read in them (hostile campaign of issue 30: this was refused), the built-in keeps
    // its own
    std::fs::write(d.join("rec.csv"), "t,a\n0,0\n0.01,0.5\n0.02,-0.25\n").unwrap();
    let pair = load(
        &d,
        "pair.csv",
        "id,x,y,units\nP,builtin:ELC180,rec.csv,m/s2\nQ,builtin:ELC180,rec.csv,\n",
    );
    let (p, q) = (&pair.records[0], &pair.records[1]);
    let (py, qy) = (p.y.as_ref().unwrap(), q.y.as_ref().unwrap());
    assert!(py.units().contains("m/s2"), "{}", py.units());
    assert_eq!(py.values()[1], 0.5);
    assert!((qy.values()[1] / py.values()[1] - 9.80665).abs() < 1e-12);
    assert_eq!(
        p.x.values(),
        q.x.values(),
        "the built-in keeps its own units"
    );
    // an .AT2 whose header names no units takes the given units (m/s2: values as written)
    let s = load(&d, "ok.csv", "id,x,units\nA,none.AT2,m/s2\nB,none.AT2,\n");
    let (a, b) = (&s.records[0].x, &s.records[1].x);
    assert!(a.units().contains("m/s2"), "{}", a.units());
    let ratio = b.values()[1] / a.values()[1];
    assert!((ratio - 9.80665).abs() < 1e-9, "{ratio}");
}

/// A quoted cell is trimmed of surrounding spaces like any other (as the guide says).
#[test]
fn quoted_csv_cells_are_trimmed() {
    let d = scratch("trim");
    let s = load(
        &d,
        "set.csv",
        "id,x,note\n\" A \",builtin:ELC180,\" padded \"\n",
    );
    assert_eq!(s.records[0].id, "A");
    assert_eq!(s.records[0].meta[0].1, MetaValue::Text("padded".into()));
}

/// 20,000 entries in one manifest: every entry's line is right (the last one's duplicate id is
/// named at its line). Naming lines by scanning the text per entry made this quadratic (40 s
/// for a TOML manifest); it is now linear (a fraction of a second; timed by the `manifest`
/// bench, not here).
#[test]
fn a_manifest_of_20000_entries_names_the_line_of_the_last() {
    let d = scratch("big");
    let n = 20_000;
    let mut toml = String::new();
    let mut csv = String::from("id,x,dt\n");
    for i in 0..n {
        let id = if i == n - 1 { 0 } else { i };
        toml.push_str(&format!(
            "[[record]]\nid = \"R{id}\"\nx = \"a.txt\"\ndt = 0.01\n\n"
        ));
        csv.push_str(&format!("R{id},a.txt,0.01\n"));
    }
    let t = err_in(&d, "big.toml", &toml);
    let last = 5 * (n - 1) + 2;
    assert!(
        t.contains(&format!(
            "record[{}].id (big.toml:{last}): duplicate id \"R0\" (also record[0])",
            n - 1
        )),
        "{t}"
    );
    let c = err_in(&d, "big.csv", &csv);
    assert!(
        c.contains(&format!(
            "id (big.csv:{}, column A): duplicate id \"R0\" (also line 2)",
            n + 1
        )),
        "{c}"
    );
    // without the duplicate: every entry read, in order
    let ok = toml.replace("[[record]]\nid = \"R0\"\nx = \"a.txt\"\ndt = 0.01\n\n", "");
    let s = load(&d, "ok.toml", &ok);
    assert_eq!(s.records.len(), n - 2);
    assert_eq!(s.records[0].id, "R1");
    assert_eq!(s.records[n - 3].id, format!("R{}", n - 2));
}

fn err_in(d: &Path, name: &str, text: &str) -> String {
    std::fs::write(d.join(name), text).unwrap();
    let e = RecordSet::load(&d.join(name)).unwrap_err().to_string();
    e.replace(&format!("{}/", d.display()), "")
}

/// A manifest over its size limit is refused naming the limit and the page that lists it, and
/// that page lists it; so does it every kind of file read with a limit (`read_text(_, WHAT, _)`).
#[test]
fn the_manifest_size_limit_is_listed_where_its_message_points() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let page = std::fs::read_to_string(root.join("docs/guide/robustness.md")).unwrap();
    let rows: Vec<&str> = page.lines().filter(|l| l.starts_with("| ")).collect();
    let d = scratch("limit");
    for name in ["big.toml", "big.csv"] {
        let f = std::fs::File::create(d.join(name)).unwrap();
        f.set_len(16 * 1024 * 1024 + 1).unwrap();
        let e = RecordSet::load(&d.join(name)).unwrap_err().to_string();
        assert!(
            e.contains(name) && e.contains("16 MiB") && e.contains("docs/guide/robustness.md"),
            "{e}"
        );
    }
    assert!(
        rows.iter()
            .any(|r| r.starts_with("| record set") && r.contains("| 16 MiB |")),
        "no record-set row in robustness.md"
    );
    let mut kinds = Vec::new();
    for dir in ["crates/pounding/src", "crates/pounding-cli/src"] {
        let mut stack = vec![root.join(dir)];
        while let Some(p) = stack.pop() {
            if p.is_dir() {
                stack.extend(std::fs::read_dir(&p).unwrap().map(|e| e.unwrap().path()));
                continue;
            }
            let src = std::fs::read_to_string(&p).unwrap_or_default();
            for (k, _) in src.match_indices("read_text(") {
                let call = &src[k..(k + 200).min(src.len())];
                let call = &call[..call.find(';').unwrap_or(call.len())];
                if let Some(q) = call.split('"').nth(1)
                    && call.contains("LIMIT")
                {
                    kinds.push(q.trim_end_matches(" file").to_string());
                }
            }
        }
    }
    assert!(kinds.iter().any(|k| k == "record set"), "{kinds:?}");
    for k in kinds {
        assert!(
            rows.iter().any(|r| r.contains(&k)),
            "robustness.md lists no limit for {k:?}"
        );
    }
}

/// A manifest saved in UTF-16 (with or without a byte-order mark) is refused saying so; one in
/// Latin-1 names the line of the first byte that is not UTF-8.
#[test]
fn a_manifest_not_in_utf8_is_refused_with_a_hint() {
    let d = scratch("enc");
    let text = "id,x\nA,builtin:ELC180\n";
    let le: Vec<u8> = text.encode_utf16().flat_map(u16::to_le_bytes).collect();
    let be: Vec<u8> = text.encode_utf16().flat_map(u16::to_be_bytes).collect();
    let cases: [(&str, Vec<u8>); 3] = [
        ("le-bom.csv", [&[0xFF, 0xFE][..], &le].concat()),
        ("be-bom.toml", [&[0xFE, 0xFF][..], &be].concat()),
        ("le.csv", le.clone()),
    ];
    for (name, bytes) in cases {
        std::fs::write(d.join(name), bytes).unwrap();
        let e = RecordSet::load(&d.join(name)).unwrap_err().to_string();
        assert!(
            e.contains(name) && e.contains("looks like UTF-16") && e.contains("save it as UTF-8"),
            "{name}: {e}"
        );
    }
    let latin1 = b"id,x,event\nA,builtin:ELC180,ok\nB,builtin:ELC270,Ciudad Ju\xe1rez\n";
    std::fs::write(d.join("latin1.csv"), latin1).unwrap();
    let e = RecordSet::load(&d.join("latin1.csv"))
        .unwrap_err()
        .to_string();
    let at = latin1.iter().position(|&b| b == 0xE1).unwrap();
    assert!(
        e.contains("latin1.csv")
            && e.contains(&format!("0xE1 on line 3, at offset {at}"))
            && e.contains("save it as UTF-8"),
        "{e}"
    );
}

/// Entries naming the same file share its samples (a 200 000-row manifest copied them per
/// entry and ran out of memory): the record of every entry points at one buffer.
#[test]
fn entries_naming_one_file_share_its_samples() {
    let d = scratch("share");
    // a longer record, as real ones are (the copies were what cost memory)
    let rec: String = (0..5000)
        .map(|k| format!("{}\n", (k as f64 * 0.01).sin()))
        .collect();
    std::fs::write(d.join("long.txt"), rec).unwrap();
    let mut csv = String::from("id,x,dt\n");
    for i in 0..20_000 {
        csv.push_str(&format!("R{i},long.txt,0.01\n"));
    }
    let s = load(&d, "many.csv", &csv);
    assert_eq!(s.records.len(), 20_000);
    let first = s.records[0].x.values().as_ptr();
    assert!(
        s.records
            .iter()
            .all(|r| std::ptr::eq(r.x.values().as_ptr(), first) && r.x.values().len() == 5000),
        "every entry shares the one buffer"
    );
}
