//! The angles `pounding check` reports are the scenario's degrees, not a round trip through
//! radians (60° is stored as `60f64.to_radians()`, whose `to_degrees()` is 59.99999999999999).

use pounding::assessment::check::{check_scenario, degrees_as_given};
use pounding::assessment::check_write::check_csv;
use pounding::sim::scenario::Scenario;

#[test]
fn skew_and_subtended_angles_are_the_scenarios_degrees() {
    // the round trip this guards against
    assert_ne!(60f64.to_radians().to_degrees(), 60.0);
    for deg in [0.0, 12.0, 30.0, 45.5, 60.0, 89.9, 33.333, 1e-7] {
        let rad = f64::to_radians(deg);
        assert_eq!(degrees_as_given(rad), deg, "{deg}");
    }
    let text = r#"
[bridge]
outer_seat_length = 0.7
seat_length = 0.5
[[segment]]
shape = "skew"
L = 25.0
skew_deg = 60.0
period_s = 1.0
[[segment]]
shape = "skew"
L = 25.0
skew_deg = 60.0
period_s = 1.0
[ground_motion]
record_y = "builtin:ELC180"
"#;
    let r = check_scenario(&Scenario::from_toml(text, "s.toml").unwrap()).unwrap();
    assert!(r.ends.iter().all(|e| e.at.skew_deg == 60.0));
    let csv = check_csv(&r);
    let col = csv
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|h| h == "skew_deg")
        .unwrap();
    for row in csv.lines().skip(1) {
        assert_eq!(row.split(',').nth(col), Some("60"), "{row}");
    }
    // a curved segment's subtended angle: the viaduct's beta_deg = 12
    let curved = include_str!("../../../../examples/viaduct-curved-5.toml");
    let r = check_scenario(&Scenario::from_toml(curved, "c.toml").unwrap()).unwrap();
    assert!(r.ends.iter().all(|e| e.at.subtended_deg == Some(12.0)));
}
