//! Scenario variants: overrides applied to a scenario's text, checked by the scenario's reading,
//! errors naming the variants file, the variant, the key and its line.

use pounding::assessment::variant::{Variant, VariantError, Variants};
use pounding::sim::scenario::Scenario;

const BASE: &str = include_str!("../../../../examples/fragility/viaduct.toml");

/// The scenario's own reading: parse, build the bridge, the assessment tables.
fn check(text: &str) -> Result<(), String> {
    let sc = Scenario::from_toml(text, "viaduct.toml").map_err(|e| e.to_string())?;
    sc.build_bridge().map_err(|e| e.to_string())?;
    pounding::assessment::check_tables(&sc, None).map_err(|e| e.to_string())
}

fn one(text: &str) -> Variant {
    let v = Variants::parse(text, "design.toml").expect("variants read");
    assert_eq!(v.list.len(), 1);
    v.list[0].clone()
}

fn table(text: &str) -> toml::Table {
    toml::from_str(text).expect("merged text is TOML")
}

#[test]
fn replaces_in_place_and_keeps_the_base_lines() {
    let v = one(
        "[[variant]]\nname = \"stiff\"\n[variant.set]\n\"bridge.restrainer_k\" = 1.0e8\nsegment = [{}, {}, { period_s = 1.0 }]\n",
    );
    // an array in `set` is a value, not a path: refused by the base (an array of tables)
    let e = v.apply(BASE, "design.toml").unwrap_err();
    assert!(e.to_string().contains("array of tables"), "{e}");

    let v = one(
        "[[variant]]\nname = \"stiff\"\n[variant.set]\n\"bridge.restrainer_k\" = 1.0e8\n\"segment[2].period_s\" = 1.0\n",
    );
    let a = v
        .apply_checked(BASE, "viaduct.toml", "design.toml", check)
        .expect("applies");
    assert_eq!(a.text.lines().count(), BASE.lines().count());
    let t = table(&a.text);
    assert_eq!(t["bridge"]["restrainer_k"].as_float(), Some(1.0e8));
    assert_eq!(t["segment"][2]["period_s"].as_float(), Some(1.0));
    assert_eq!(t["segment"][1]["period_s"].as_float(), Some(0.5));
    // every other line is the base's
    let changed = BASE
        .lines()
        .zip(a.text.lines())
        .filter(|(x, y)| x != y)
        .count();
    assert_eq!(changed, 2);
}

#[test]
fn adds_keys_and_missing_tables() {
    let v = one(
        "[[variant]]\nname = \"bumper\"\ndescription = \"softer contact at the end abutment\"\n\
         [variant.set]\nbridge.restrainer_fy = 2.0e6\n\"abutment.end.contact.law\" = \"hertz\"\n\
         \"abutment.end.contact.k_h\" = 5.0e9\n",
    );
    assert_eq!(v.overrides.len(), 3);
    let a = v
        .apply_checked(BASE, "viaduct.toml", "design.toml", check)
        .expect("applies");
    let t = table(&a.text);
    assert_eq!(t["bridge"]["restrainer_fy"].as_float(), Some(2.0e6));
    assert_eq!(
        t["abutment"]["end"]["contact"]["law"].as_str(),
        Some("hertz")
    );
    assert_eq!(
        t["abutment"]["end"]["contact"]["k_h"].as_float(),
        Some(5.0e9)
    );
    assert_eq!(t["abutment"]["end"]["gap"].as_float(), Some(0.04));
    assert_eq!(a.text.lines().count(), BASE.lines().count() + 2);
}

fn err_of(set: &str) -> String {
    let v = one(&format!(
        "# design\n[[variant]]\nname = \"x\"\n[variant.set]\n{set}\n"
    ));
    match v.apply_checked(BASE, "viaduct.toml", "design.toml", check) {
        Ok(_) => panic!("{set}: accepted"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn refuses_unknown_keys_and_bad_values_naming_the_variant_line() {
    // an unknown key: refused by the scenario's strict reading, never a silent no-op
    let e = err_of("\"bridge.restrainer_kk\" = 1.0e8");
    assert!(
        e.starts_with("design.toml:5: variant \"x\": `bridge.restrainer_kk`"),
        "{e}"
    );
    assert!(e.contains("restrainer_kk"), "{e}");
    // the TOML reader's own line of the merged text is relabelled to the variants file's
    assert!(e.contains("at design.toml:5, column"), "{e}");
    // a value out of range: the scenario's message, its line relabelled to the variants file
    let e = err_of("\"bridge.gap\" = -1.0");
    assert!(
        e.starts_with("design.toml:5: variant \"x\": `bridge.gap`"),
        "{e}"
    );
    assert!(
        !e.contains("viaduct.toml:21"),
        "base line of the variant's value: {e}"
    );
    // an index beyond the base's segments
    let e = err_of("\"segment[3].L\" = 10.0");
    assert!(
        e.contains("design.toml:5") && e.contains("3 entries"),
        "{e}"
    );
    // a path through a value
    let e = err_of("\"bridge.gap.x\" = 1.0");
    assert!(e.contains("not a table"), "{e}");
    // a whole table
    let e = err_of("\"contact\" = 1.0");
    assert!(e.contains("is a table"), "{e}");
    // malformed paths
    for p in [
        "\"bridge..gap\" = 1.0",
        "\"joint[x].gap\" = 1.0",
        "\"a b\" = 1",
    ] {
        let e = Variants::parse(
            &format!("[[variant]]\nname = \"x\"\n[variant.set]\n{p}\n"),
            "design.toml",
        )
        .unwrap_err();
        assert!(matches!(e, VariantError::Key { line: 4, .. }), "{p}: {e}");
    }
}

#[test]
fn refuses_bad_variant_tables() {
    let cases = [
        (
            "[[variant]]\nname = \"a\"\n[[variant]]\nname = \"a\"\n",
            4,
            "duplicate",
        ),
        ("[[variant]]\nnam = \"a\"\n", 2, "unknown key"),
        ("[[variant]]\nname = \"a b\"\n", 2, "letters"),
        ("[[variant]]\nname = \"a\"\nset = 3\n", 3, "table"),
        ("[x]\n", 1, "no [[variant]]"),
        (
            "[[variant]]\nname = \"a\"\n[variant.set]\nbridge.gap = 1.0\n\"bridge.gap\" = 2.0\n",
            5,
            "set twice",
        ),
    ];
    for (text, line, what) in cases {
        match Variants::parse(text, "design.toml") {
            Err(VariantError::Key {
                line: l, message, ..
            }) => {
                assert_eq!(l, line, "{text}: {message}");
                assert!(message.contains(what), "{text}: {message}");
            }
            other => panic!("{text}: {other:?}"),
        }
    }
}
