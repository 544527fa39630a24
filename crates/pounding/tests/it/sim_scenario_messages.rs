//! Scenario errors name the key as the user wrote it: a joint's restrainer placement inherited
//! from `[bridge]` is `bridge.restrainer_offsets` (with the joint it failed at), not the joint's
//! own key; a value that is not a number (`nan`, `inf`) is said to have to be finite, in both
//! scenario forms.

use crate::common::scenario_error as error;

const TWO_SEGMENTS: &str = r#"
[[segment]]
shape = "straight"
L = 30.0
period_s = 1.0

[[segment]]
shape = "straight"
L = 30.0
period_s = 1.0
"#;

#[test]
fn restrainer_placement_errors_name_the_key_as_written() {
    // inherited from [bridge] (line 3): named there, with the joint
    for (key, value, other) in [
        (
            "restrainer_offsets",
            "[100.0]",
            "joint[0].restrainer_offsets",
        ),
        ("restrainer_depth", "40.0", "joint[0].restrainer_depth"),
    ] {
        let text = format!("[bridge]\nrestrainer_k = 5.0e7\n{key} = {value}\n{TWO_SEGMENTS}");
        let e = error(&text);
        assert!(
            e.contains(&format!("set by `bridge.{key}` (f.toml:3)")),
            "{e}"
        );
        assert!(e.contains(&format!("invalid bridge.{key} = ")), "{e}");
        assert!(e.contains("at joint[0]"), "{e}");
        assert!(!e.contains(other), "{e}");
        // the joint's own key: named as the joint's
        let text =
            format!("[bridge]\nrestrainer_k = 5.0e7\n{TWO_SEGMENTS}\n[[joint]]\n{key} = {value}\n");
        let e = error(&text);
        assert!(e.contains(&format!("set by `{other}` (f.toml:15)")), "{e}");
    }
}

#[test]
fn a_value_that_is_not_a_number_must_be_finite_in_both_forms() {
    let bridge = [
        (format!("[bridge]\nmu = nan\n{TWO_SEGMENTS}"), "bridge.mu"),
        (
            format!("{TWO_SEGMENTS}\n[[joint]]\nmu = nan\n"),
            "joint[0].mu",
        ),
        (
            format!("{TWO_SEGMENTS}\n[abutment.start]\nmu = inf\n"),
            "abutment.start.mu",
        ),
    ];
    for (text, key) in &bridge {
        let e = error(text);
        assert!(e.contains(&format!("invalid {key} = ")), "{e}");
        assert!(e.contains("must be finite and >= 0"), "{e}");
    }
    let e = error(&format!("[bridge]\ngap = -inf\n{TWO_SEGMENTS}"));
    assert!(
        e.contains("invalid bridge.gap = -inf: must be finite and lie in [0, 1e3] m"),
        "{e}"
    );
    // the two-deck form: `[joint] mu` (checked by the two-deck model)
    for value in ["nan", "inf", "-inf"] {
        let e = error(&format!("[joint]\nmu = {value}\n"));
        assert!(e.contains("invalid mu = "), "{e}");
        assert!(e.contains("must be finite and >= 0"), "{e}");
        assert!(e.contains("`[joint] mu` (f.toml:2)"), "{e}");
    }
    // a finite value out of range keeps its reason
    let e = error("[joint]\nmu = -1.0\n");
    assert!(e.contains("invalid mu = -1: must be >= 0"), "{e}");
}
