//! The `[contact]` keys each law reads ([`registry::LawEntry::reads`], which the scenario uses
//! to refuse keys that would be ignored) checked against what the law's `build` really does:
//! for every law and every combination of its keys given, changing the value of a key the
//! registry says is read changes the built law, and changing any other key (of this law or of
//! another one) leaves it identical. A key declared "read" that the law ignores would be
//! accepted silently; a key declared "not read" that the law uses would be refused wrongly.

use pounding::contact_law::registry::{self, LawInputs};
use pounding::contact_law::{ContactLaw, registry::BuildError};
use pounding::sim::scenario::{Scenario, ScenarioError, contact_keys};
use std::collections::BTreeMap;

/// A valid value of every numeric key, and a second valid value.
fn values(key: &str) -> (f64, f64) {
    match key {
        "k" => (2e10, 3e10),
        "c" => (1e6, 2e6),
        "k_h" => (1e9, 2e9),
        "zeta" => (0.1, 0.2),
        "chi" => (0.3, 0.4),
        "restitution" => (0.6, 0.7),
        "design_velocity" => (0.5, 0.8),
        "min_velocity" => (0.02, 0.05),
        "k1" => (1e10, 1.2e10),
        "k2" => (2e9, 3e9),
        "delta_y" => (1e-3, 2e-3),
        "delta_m" => (0.03, 0.04),
        "a" => (0.2, 0.3),
        "beta" => (2e9, 3e9),
        "xi" => (0.1, 0.2),
        other => panic!("no test value for {other}"),
    }
}

/// The calibration of `law` other than `numerical` (any name for laws without one: unread).
fn other_calibration(law: &str) -> &'static str {
    match law {
        "kelvin" => "anagnostopoulos",
        "hertz-damp" => "ye",
        "jankowski" => "jankowski2005",
        _ => "no-such-calibration",
    }
}

/// The law `name` built from `given` (key → value; `calibration` by `cal`), as the scenario
/// reader does (restitution defaults to `[joint] eps_n` = 0.5).
fn build(
    name: &str,
    given: &BTreeMap<&str, f64>,
    cal: Option<&str>,
) -> Result<ContactLaw, BuildError> {
    let entry = registry::entry(name).unwrap();
    let values = |k: &str| given.get(k).copied();
    (entry.build)(&LawInputs {
        values: &values,
        calibration: cal.unwrap_or("numerical"),
        restitution: given.get("restitution").copied().unwrap_or(0.5),
        masses: [1.3e6, 0.9e6],
    })
}

#[test]
fn contact_law_keys_declared_read_are_exactly_those_that_change_the_law() {
    let mut checked = 0;
    for entry in registry::LAWS {
        let own: Vec<&str> = entry.keys.to_vec();
        // every subset of the law's own keys, `calibration` included
        for mask in 0u32..(1 << own.len()) {
            let set: Vec<&str> = (0..own.len())
                .filter(|i| mask >> i & 1 == 1)
                .map(|i| own[i])
                .collect();
            let cal = set.contains(&"calibration").then_some("numerical");
            let given: BTreeMap<&str, f64> = set
                .iter()
                .filter(|&&k| k != "calibration")
                .map(|&k| (k, values(k).0))
                .collect();
            let reads = (entry.reads)(&|k| set.contains(&k));
            for k in reads.keys {
                assert!(own.contains(k), "{}: reads {k} not in keys", entry.name);
            }
            let Ok(base) = build(entry.name, &given, cal) else {
                continue;
            };
            // the law's own keys given, and a foreign key (any other key of `[contact]`)
            let foreign = contact_keys()
                .iter()
                .find(|k| !own.contains(k) && **k != "friction_velocity")
                .unwrap();
            for &k in set.iter().chain([foreign]) {
                let changed = if k == "calibration" {
                    build(entry.name, &given, Some(other_calibration(entry.name)))
                } else {
                    let mut g = given.clone();
                    g.insert(k, values(k).1);
                    build(entry.name, &g, cal)
                };
                let read = reads.keys.contains(&k);
                match changed {
                    Ok(law) => assert_eq!(
                        law != base,
                        read,
                        "law {} with {set:?} given: {k} declared {} but changing it {} the law",
                        entry.name,
                        if read { "read" } else { "unread" },
                        if law != base {
                            "changes"
                        } else {
                            "does not change"
                        },
                    ),
                    // a changed value that fails validation is read
                    Err(e) => assert!(read, "{}: {k} unread but fails: {e}", entry.name),
                }
                checked += 1;
            }
        }
    }
    eprintln!("{checked} key changes checked");
    assert!(checked > 500, "{checked}");
}

/// Through the scenario: a key the law does not read is refused as a `Key` error naming it; the
/// same key in a comparison that includes a law reading it is accepted.
#[test]
fn contact_law_keys_unread_are_refused_by_the_scenario() {
    let sc = Scenario::from_toml("[contact]\nlaw = \"hertz\"\nk = 1e10\n", "s.toml").unwrap();
    let e = sc.build().unwrap_err();
    assert!(matches!(e, ScenarioError::Key { .. }), "{e}");
    assert_eq!(e.keys()[0].key, "k");
    assert!(e.to_string().contains("(s.toml:3)"), "{e}");
    // compared with kelvin, which reads k: accepted, and each law builds
    let sc = sc.with_compared_laws(&["hertz", "kelvin"]);
    sc.check_contact_keys().unwrap();
    for law in ["hertz", "kelvin"] {
        sc.clone().with_law(law).build().unwrap();
    }
    // compared with laws that do not read it: refused
    let sc = sc.with_compared_laws(&["rigid", "hertz"]);
    let e = sc.check_contact_keys().unwrap_err();
    assert!(e.to_string().contains("kelvin"), "{e}");
}
