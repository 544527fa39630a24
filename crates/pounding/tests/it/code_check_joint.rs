//! EN 1998-2 §6.6.4(4) through `pounding check`: at an intermediate separation joint the overlap
//! is the SRSS of expression (6.11) of each deck section (segment) alone, with its own design
//! displacement and its own `L_eff` (the distance from the joint to the section's far end: the
//! segment's length), and every output reports both sections' terms.

use pounding::assessment::check::{Code, check_scenario};
use pounding::assessment::check_summary::summary_json;
use pounding::assessment::check_write::{check_csv, check_json};
use pounding::sim::bridge::SeatSummary;
use pounding::sim::scenario::Scenario;

/// Two straight segments of 30 m and 50 m on outer seats, design displacements 0.08 m and
/// 0.15 m, ground C, a_gR = 3.0 m/s², class II.
fn bridge(extra: &str) -> String {
    format!(
        r#"
[bridge]
outer_seat_length = 0.7
seat_length = 0.5
[[segment]]
shape = "straight"
L = 30.0
period_s = 1.0
[[segment]]
shape = "straight"
L = 50.0
period_s = 0.5
[code_check]
ground = "C"
a_gr_ms2 = 3.0
displacement_m = [0.08, 0.15]
{extra}
[ground_motion]
record_y = "builtin:ELC180"
"#
    )
}

fn close(a: f64, b: f64) {
    assert!((a - b).abs() <= 1e-9, "{a} vs {b}");
}

fn ec8(r: &pounding::assessment::check::CheckReport, end: &str) -> f64 {
    let e = r.ends.iter().find(|e| e.at.end == end).unwrap();
    e.codes
        .iter()
        .find(|(c, _)| *c == Code::Ec8)
        .unwrap()
        .1
        .value()
        .unwrap()
}

/// Worked by hand (EN 1998-1 Table 3.2, ground C type 1: S = 1.15, T_C = 0.6 s, T_D = 2 s;
/// EN 1998-2 Table 3.1N: L_g = 400 m): a_g = 3.0, d_g = 0.025·3.0·1.15·0.6·2.0 = 0.1035 m,
/// ε_s = 2 d_g / L_g = 5.175e-4, l_m = 0.40 m.
/// - segment 1 (L = 30 m, d = 0.08 m): d_eg = 0.015525, l_ov,1 = 0.40 + 0.015525 + 0.08 = 0.495525;
/// - segment 2 (L = 50 m, d = 0.15 m): d_eg = 0.025875, l_ov,2 = 0.40 + 0.025875 + 0.15 = 0.575875;
/// - the outer seats take their own section: 0.495525 (segment1-start), 0.575875 (segment2-end);
/// - both ends at joint 1: √(0.495525² + 0.575875²) = √(0.245545025625 + 0.331632015625)
///   = √0.57717704125 = 0.759721686705.
///
/// With `l_eff_m = 40` both sections take L_eff = 40 m: d_eg = 0.0207, l_ov,1 = 0.5007,
/// l_ov,2 = 0.5707, joint √(0.25070049 + 0.32569849) = √0.57639898 = 0.759209444093.
#[test]
fn intermediate_joint_is_the_srss_of_each_sections_overlap() {
    let r = check_scenario(&Scenario::from_toml(&bridge(""), "s.toml").unwrap()).unwrap();
    close(ec8(&r, "segment1-start"), 0.495525);
    close(ec8(&r, "segment2-end"), 0.575875);
    close(ec8(&r, "segment1-end"), 0.759721686705);
    close(ec8(&r, "segment2-start"), 0.759721686705);
    // both ends of the joint get the same bits
    assert_eq!(ec8(&r, "segment1-end"), ec8(&r, "segment2-start"));
    // the terms: own section first, then the other
    let j = r
        .ends
        .iter()
        .find(|e| e.at.end == "segment2-start")
        .unwrap();
    let t = j.ec8.unwrap();
    assert_eq!((t.own.segment, t.other.unwrap().segment), (1, 0));
    close(t.own.l_eff, 50.0);
    close(t.own.terms.d_g, 0.1035);
    close(t.own.terms.d_eg, 0.025875);
    close(t.own.terms.d_es, 0.15);
    close(t.own.terms.l_ov, 0.575875);
    close(t.other.unwrap().l_eff, 30.0);
    close(t.other.unwrap().terms.l_ov, 0.495525);
    assert!(r.ends[0].ec8.unwrap().other.is_none());

    let given =
        check_scenario(&Scenario::from_toml(&bridge("l_eff_m = 40.0"), "s.toml").unwrap()).unwrap();
    close(ec8(&given, "segment1-start"), 0.5007);
    close(ec8(&given, "segment2-end"), 0.5707);
    close(ec8(&given, "segment1-end"), 0.759209444093);
}

/// `check.csv` appends the terms after the former columns (which keep their places),
/// `check.json` and `summary.json`'s `code_check` carry `ec8_sections` per end.
#[test]
fn the_outputs_carry_both_sections_terms() {
    let r = check_scenario(&Scenario::from_toml(&bridge(""), "s.toml").unwrap()).unwrap();
    let csv = check_csv(&r);
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let former = "end,segment,support,seat_length_m,deck_length_m,skew_deg,subtended_deg,\
                  pier_height_m,aashto_l_m,aashto_h_m,displacement_m,ec8_m,aashto_lrfd_m,\
                  aashto_guide_m,caltrans_m,jra_m,governing_code,governing_m,margin_m,verdict";
    assert_eq!(head[..20].join(","), former);
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert!(rows.iter().all(|r| r.len() == head.len()));
    let num = |row: &[&str], name: &str| row[col(name)].parse::<f64>().unwrap();
    let seg2_start = &rows[2];
    assert_eq!(seg2_start[0], "segment2-start");
    close(num(seg2_start, "ec8_d_g_m"), 0.1035);
    close(num(seg2_start, "ec8_l_m_m"), 0.40);
    close(num(seg2_start, "ec8_own_l_eff_m"), 50.0);
    close(num(seg2_start, "ec8_own_d_eg_m"), 0.025875);
    close(num(seg2_start, "ec8_own_d_es_m"), 0.15);
    close(num(seg2_start, "ec8_own_l_ov_m"), 0.575875);
    assert_eq!(seg2_start[col("ec8_other_segment")], "1");
    close(num(seg2_start, "ec8_other_l_eff_m"), 30.0);
    close(num(seg2_start, "ec8_other_l_ov_m"), 0.495525);
    let o = num(seg2_start, "ec8_own_l_ov_m");
    let t = num(seg2_start, "ec8_other_l_ov_m");
    close(num(seg2_start, "ec8_m"), (o * o + t * t).sqrt());
    // off a joint the other section's cells are empty
    assert_eq!(rows[0][col("ec8_other_segment")], "");
    assert_eq!(rows[0][col("ec8_other_l_ov_m")], "");

    let j: serde_json::Value = serde_json::from_str(&check_json(&r, "s.toml")).unwrap();
    let s = &j["ends"][1]["ec8_sections"];
    assert_eq!(j["ends"][1]["end"], "segment1-end");
    assert_eq!(
        (s[0]["segment"].as_u64(), s[1]["segment"].as_u64()),
        (Some(1), Some(2))
    );
    close(s[0]["l_ov_m"].as_f64().unwrap(), 0.495525);
    close(s[1]["l_ov_m"].as_f64().unwrap(), 0.575875);
    close(s[1]["d_eg_m"].as_f64().unwrap(), 0.025875);
    assert_eq!(j["ends"][0]["ec8_sections"].as_array().unwrap().len(), 1);

    let seats: Vec<SeatSummary> = r
        .ends
        .iter()
        .map(|e| SeatSummary {
            end: e.at.end.clone(),
            segment: e.at.segment + 1,
            support: e.at.support.clone(),
            seat_length: e.at.seat_length,
            peak_displacement: 0.01,
            ratio: 0.01 / e.at.seat_length,
            peak_time: 1.0,
            residual_displacement: 0.0,
            unseated: false,
        })
        .collect();
    // through text as check.json (serde_json reads a float's shortest text back approximately)
    let sum: serde_json::Value =
        serde_json::from_str(&summary_json(&r, &seats).to_string()).unwrap();
    assert_eq!(sum["ends"][1]["ec8_sections"], j["ends"][1]["ec8_sections"]);
    assert_eq!(sum["ends"][0]["ec8_sections"], j["ends"][0]["ec8_sections"]);
}

/// Without the site inputs EN 1998-2 is not evaluated and no terms are reported.
#[test]
fn no_terms_without_the_site() {
    let text = bridge("").replace("ground = \"C\"\n", "");
    let r = check_scenario(&Scenario::from_toml(&text, "s.toml").unwrap()).unwrap();
    assert!(r.ends.iter().all(|e| e.ec8.is_none()));
    let j: serde_json::Value = serde_json::from_str(&check_json(&r, "s.toml")).unwrap();
    assert!(j["ends"][1]["ec8_sections"].is_null());
}
