//! `pounding check` in the library: the seated ends and their terms derived from a scenario's
//! model (names, supports, seats, deck length, skew, subtended angle, periods), each code's
//! requirement equal to its formula called with those terms, and `[code_check]` errors naming
//! key and line.

use pounding::assessment::check::{CODES, Code, Requirement, check_scenario, seated_ends};
use pounding::assessment::check_write::{check_csv, check_json};
use pounding::assessment::code_check::{self as cc, AashtoZone, Ec8Seat, GroundType, SeatKind};
use pounding::assessment::{AssessmentError, CodeCheckInput};
use pounding::sim::Problem;
use pounding::sim::scenario::Scenario;
use std::f64::consts::PI;

const CURVED_5: &str = include_str!("../../../../examples/viaduct-curved-5.toml");
const STRAIGHT_1D: &str = include_str!("../../../../examples/straight-1d.toml");

fn scenario(text: &str) -> Scenario {
    Scenario::from_toml(text, "s.toml").unwrap()
}

fn model(text: &str) -> pounding::sim::bridge::BridgeModel {
    scenario(text)
        .for_batch()
        .build_setup()
        .unwrap()
        .model()
        .into_owned()
}

/// The five-segment curved example: ten seated ends, abutments at both outer ends, joints
/// between; `L = R β` of its segments (R = 150 m, β = 12°), no skew, β reported.
#[test]
fn seated_ends_of_the_curved_example() {
    let m = model(CURVED_5);
    let ends = seated_ends(&m);
    assert_eq!(ends.len(), 2 * m.segments.len());
    let d = m.segments[0].shape.curved().unwrap();
    for (n, e) in ends.iter().enumerate() {
        let (i, at_end) = (n / 2, n % 2 == 1);
        assert_eq!(e.segment, i);
        assert_eq!(
            e.end,
            format!("segment{}-{}", i + 1, if at_end { "end" } else { "start" })
        );
        let joint = match (at_end, i) {
            (false, 0) => None,
            (false, _) => Some(i - 1),
            (true, 4) => None,
            (true, _) => Some(i),
        };
        assert_eq!(e.joint, joint, "{}", e.end);
        match joint {
            Some(k) => {
                assert_eq!(e.support, format!("joint{}", k + 1));
                assert_eq!(e.kind, SeatKind::Hinge);
                assert_eq!(e.seat_length, m.joints[k].seat_length);
            }
            None => {
                assert!(e.support.starts_with("abutment-"), "{}", e.support);
                assert_eq!(e.kind, SeatKind::Abutment);
                assert_eq!(
                    e.seat_length,
                    m.abutments[usize::from(at_end)].unwrap().seat_length
                );
            }
        }
        assert!((e.deck_length - 150.0 * 12f64.to_radians()).abs() < 1e-9);
        assert!((e.deck_length - d.radius * d.angle).abs() < 1e-12);
        assert_eq!(e.skew_deg, 0.0);
        assert!((e.subtended_deg.unwrap() - 12.0).abs() < 1e-9);
    }
}

/// A skewed segment's ends carry its skew and its axis length; a bridge without abutments
/// rests its outer ends on `outer_seat_length`.
#[test]
fn skew_and_outer_seats_derived() {
    let text = r#"
[bridge]
outer_seat_length = 0.7
seat_length = 0.5
[[segment]]
shape = "skew"
L = 25.0
skew_deg = 20.0
period_s = 1.0
[[segment]]
shape = "straight"
L = 40.0
width = 10.641777724759121  # the skewed face: 10 / cos 20°
period_s = 0.5
[ground_motion]
record_y = "builtin:ELC180"
"#;
    let ends = seated_ends(&model(text));
    assert_eq!(ends.len(), 4);
    assert!((ends[0].skew_deg - 20.0).abs() < 1e-9 && (ends[1].skew_deg - 20.0).abs() < 1e-9);
    assert_eq!((ends[0].deck_length, ends[3].deck_length), (25.0, 40.0));
    assert_eq!(ends[2].skew_deg, 0.0);
    assert!(ends.iter().all(|e| e.subtended_deg.is_none()));
    assert_eq!(
        (ends[0].support.as_str(), ends[0].seat_length),
        ("outer-start", 0.7)
    );
    assert_eq!(
        (ends[1].support.as_str(), ends[1].seat_length),
        ("joint1", 0.5)
    );
    assert_eq!(ends[3].support, "outer-end");
}

fn with_check(table: &str) -> String {
    CURVED_5.replace(
        "[ground_motion]",
        &format!("[code_check]\n{table}\n[ground_motion]"),
    )
}

/// Every requirement equals its formula called with the derived terms: EC8 at a joint the
/// SRSS of each deck section's (6.11) (§6.6.4(4)), LRFD with `L`, `H`, the zone; the gap rules with the
/// segments' own periods `2π/ω₁`.
#[test]
fn requirements_equal_the_formulas_with_the_derived_terms() {
    let d: [f64; 5] = [0.10, 0.12, 0.15, 0.12, 0.10];
    let text = with_check(
        "ground = \"C\"\na_gr_ms2 = 3.0\ndisplacement_m = [0.10, 0.12, 0.15, 0.12, 0.10]\n\
         pier_height_m = 8.0\naashto_zone = 2\n",
    );
    let r = check_scenario(&scenario(&text)).unwrap();
    let m = model(&text);
    assert_eq!(r.ends.len(), 10);
    for e in &r.ends {
        let i = e.at.segment;
        let d_es = match e.at.joint {
            Some(k) => d[k].hypot(d[k + 1]),
            None => d[i],
        };
        // EN 1998-2: (6.11) per deck section with its own L and d; the SRSS of the two at a joint
        let section = |seg: usize| Ec8Seat {
            ground: GroundType::C,
            spectrum: cc::SpectrumType::Type1,
            a_gr: 3.0,
            importance_class: 2,
            l_eff: r.ends[2 * seg].at.deck_length,
            d_ed: d[seg],
            l_m: 0.4,
            near_fault_factor: 1.0,
        };
        let ec8 = match e.at.joint {
            Some(k) => {
                cc::ec8_joint_seat([&section(k), &section(k + 1)])
                    .unwrap()
                    .l_ov
            }
            None => cc::ec8_seat(&section(i)).unwrap().l_ov,
        };
        let lrfd = cc::aashto_lrfd_seat(e.at.deck_length, 8.0, 0.0, AashtoZone::Z2, 0.05).unwrap();
        let got = |c: Code| e.codes.iter().find(|(k, _)| *k == c).unwrap().1.value();
        assert_eq!(got(Code::Ec8), Some(ec8), "{}", e.at.end);
        assert_eq!(got(Code::AashtoLrfd), Some(lrfd));
        let kind = if e.at.joint.is_some() {
            SeatKind::Hinge
        } else {
            SeatKind::Abutment
        };
        assert_eq!(
            got(Code::Caltrans),
            Some(cc::caltrans_seat(kind, 0.0, 0.0, 0.0, d_es).unwrap())
        );
        // governing = the largest, margin = provided − governing, verdict from its sign
        let max = CODES
            .iter()
            .filter_map(|&c| got(c))
            .fold(f64::MIN, f64::max);
        assert_eq!(e.governing().unwrap().1, max);
        assert_eq!(e.margin(), Some(e.at.seat_length - max));
        assert_eq!(e.pass(), Some(e.at.seat_length >= max));
    }
    let w = m.segment_frequencies().unwrap();
    assert_eq!(r.gaps.len(), 4);
    for g in &r.gaps {
        let k = g.joint;
        let t = [2.0 * PI / w[k][0], 2.0 * PI / w[k + 1][0]];
        assert_eq!(g.periods, [Some(t[0]), Some(t[1])]);
        assert_eq!(g.srss.value(), Some(cc::gap_srss(d[k], d[k + 1]).unwrap()));
        let ddc = cc::gap_ddc(d[k], d[k + 1], t[0], t[1], m.damping_ratio).unwrap();
        assert_eq!(g.ddc.value(), Some(ddc));
        assert_eq!(g.pass(), Some(g.gap >= ddc));
    }
    assert_eq!(
        r.failing_ends(),
        r.ends.iter().filter(|e| e.pass() == Some(false)).count()
    );
    // the files carry one row per end / the verdict
    assert_eq!(check_csv(&r).lines().count(), 1 + r.ends.len());
    let j: serde_json::Value = serde_json::from_str(&check_json(&r, "s.toml")).unwrap();
    assert_eq!(j["ends"].as_array().unwrap().len(), 10);
    assert_eq!(j["failing_ends"], r.failing_ends());
}

/// Without a `[code_check]` table the codes that need site or displacement inputs say what
/// they need; the empirical AASHTO forms are evaluated; every key is at its default.
#[test]
fn missing_inputs_are_not_evaluated_and_say_why() {
    let r = check_scenario(&scenario(CURVED_5)).unwrap();
    for e in &r.ends {
        for (c, q) in &e.codes {
            match c {
                Code::AashtoLrfd | Code::AashtoGuide => assert!(q.value().is_some()),
                _ => assert!(
                    matches!(q, Requirement::NotEvaluated(m) if m.starts_with("needs")),
                    "{c:?}: {q:?}"
                ),
            }
        }
    }
    assert!(r.gaps.iter().all(|g| g.pass().is_none()));
    assert!(r.input.given.is_empty());
    // a two-deck file is checked as its two-segment bridge
    let two = check_scenario(&scenario(STRAIGHT_1D)).unwrap();
    assert_eq!(two.ends.len(), 4);
    assert_eq!(two.gaps.len(), 1);
}

fn key_error(table: &str) -> (String, Option<usize>, String) {
    match CodeCheckInput::from_scenario(&with_check(table), "s.toml") {
        Err(AssessmentError::Key {
            key, line, message, ..
        }) => (key, line, message),
        other => panic!("{other:?}"),
    }
}

/// Bad values name `code_check.KEY` and the line; an unknown key is refused with its line.
#[test]
fn code_check_errors_name_key_and_line() {
    let line = with_check("")
        .lines()
        .position(|l| l == "[code_check]")
        .unwrap()
        + 2;
    for (table, key) in [
        ("ground = \"F\"", "code_check.ground"),
        ("a_gr_ms2 = -1.0", "code_check.a_gr_ms2"),
        ("importance_class = 4", "code_check.importance_class"),
        ("l_m_m = 0.2", "code_check.l_m_m"),
        ("displacement_m = [0.1, -0.1]", "code_check.displacement_m"),
        ("period_s = \"modal\"", "code_check.period_s"),
        ("sdc = \"E\"", "code_check.sdc"),
        ("jra_ground = \"IV\"", "code_check.jra_ground"),
        ("damping = 1.5", "code_check.damping"),
        ("in_span_hinges = [0]", "code_check.in_span_hinges"),
        ("in_span_hinges = [2, 2]", "code_check.in_span_hinges"),
        ("codes = [\"eurocode\"]", "code_check.codes"),
        ("codes = [\"ec8\", \"ec8\"]", "code_check.codes"),
        ("codes = []", "code_check.codes"),
    ] {
        let (k, l, m) = key_error(table);
        assert_eq!((k.as_str(), l), (key, Some(line)), "{table}: {m}");
    }
    // a per-segment list of the wrong length, found against the model
    let text = with_check("displacement_m = [0.1, 0.2]");
    match check_scenario(&scenario(&text)) {
        Err(AssessmentError::Key { key, line: l, .. }) => {
            assert_eq!((key.as_str(), l), ("code_check.displacement_m", Some(line)))
        }
        other => panic!("{other:?}"),
    }
    // an in-span hinge that is not a joint of the five-segment bridge (joints 1 to 4)
    match check_scenario(&scenario(&with_check("in_span_hinges = [1, 5]"))) {
        Err(AssessmentError::Key {
            key,
            line: l,
            message,
            ..
        }) => {
            assert_eq!((key.as_str(), l), ("code_check.in_span_hinges", Some(line)));
            assert!(message.contains("joints 1 to 4"), "{message}");
        }
        other => panic!("{other:?}"),
    }
    match CodeCheckInput::from_scenario(&with_check("grond = \"A\""), "s.toml") {
        Err(AssessmentError::Syntax { message, .. }) => {
            assert!(
                message.contains(&format!("line {line}")) && message.contains("grond"),
                "{message}"
            )
        }
        other => panic!("{other:?}"),
    }
    // the simulate reader accepts the table (checked by the assessment reader)
    assert!(Scenario::from_toml(&with_check("ground = \"A\""), "s.toml").is_ok());
}

/// Every key of `DEFAULTS` is accepted and recorded as given (also in an inline table), and
/// the guide's key table lists each of them.
#[test]
fn every_default_key_is_accepted_and_documented() {
    use pounding::assessment::check_input::DEFAULTS;
    let all = "ground = \"B\", a_gr_ms2 = 1.0, spectrum_type = 2, importance_class = 3, \
               near_fault_factor = 1.2, l_m_m = 0.5, l_eff_m = 20.0, displacement_m = 0.1, \
               period_s = 1.0, damping = 0.02, pier_height_m = [5, 6, 7, 8, 9], aashto_zone = 1, \
               a_s = 0.04, sdc = \"A\", delta_ps_m = 0.01, delta_crsh_m = 0.02, \
               delta_temp_m = 0.03, jra_ground = \"I\", in_span_hinges = [2], \
               codes = [\"jra\", \"ec8\", \"aashto_lrfd\", \"aashto_guide\", \"caltrans\"]";
    // an inline table, before the first table header
    let text = format!("code_check = {{ {all} }}\n{CURVED_5}");
    let input = CodeCheckInput::from_scenario(&text, "s.toml").unwrap();
    let keys: Vec<&str> = DEFAULTS.iter().map(|(k, _)| *k).collect();
    assert_eq!(input.given, keys);
    assert!(input.defaulted().is_empty());
    let r = check_scenario(&scenario(&text)).unwrap();
    assert!(
        r.ends
            .iter()
            .all(|e| e.codes.iter().all(|(_, q)| q.value().is_some()))
    );
    let guide = include_str!("../../../../docs/guide/check.md");
    for k in keys {
        assert!(
            guide.lines().any(|l| l.starts_with("| `")
                && l.split(" | ")
                    .next()
                    .is_some_and(|c| c.contains(&format!("`{k}`")))),
            "{k}"
        );
    }
}

/// AASHTO LRFD 4.7.4.4 at a hinge within a span: `L` is the sum of the distances to either side
/// of the hinge (the two segments' lengths) and `H` the mean height of the two adjacent columns;
/// at the other joints and the abutments each segment's own `L` and `H`. Worked by hand from
/// the clause's `N = (8 + 0.02 L + 0.08 H)(1 + 0.000125 S²)` in (L, H in ft; zone 3: 150 %):
/// segments of 94.248 m (R β = 150 m × 36°), columns of 6 and 10 m.
#[test]
fn an_in_span_hinge_takes_the_sum_of_the_lengths_either_side() {
    let text = CURVED_5
        .replace("beta_deg = 12.0", "beta_deg = 36.0")
        .replace(
            "[ground_motion]",
            "[code_check]\npier_height_m = [6.0, 10.0, 6.0, 10.0, 6.0]\naashto_zone = 3\n\
         in_span_hinges = [2]\n[ground_motion]",
        );
    let r = check_scenario(&scenario(&text)).unwrap();
    let ft = 0.3048;
    let l_seg = 150.0 * 36.0_f64.to_radians();
    // N in inches, times 150 %, in metres
    let n = |l_m: f64, h_m: f64| (8.0 + 0.02 * l_m / ft + 0.08 * h_m / ft) * 1.5 * 0.0254;
    let lrfd = |end: &str| {
        let e = r.ends.iter().find(|e| e.at.end == end).unwrap();
        e.codes
            .iter()
            .find(|(c, _)| *c == Code::AashtoLrfd)
            .unwrap()
            .1
            .value()
            .unwrap()
    };
    // joint 2 (segments 2 and 3) is the hinge: L = 2 L_seg, H = (10 + 6)/2
    for end in ["segment2-end", "segment3-start"] {
        let want = n(2.0 * l_seg, 8.0);
        assert!(
            (lrfd(end) - want).abs() < 1e-12,
            "{end}: {} vs {want}",
            lrfd(end)
        );
    }
    // joint 1 and the abutments: the segment's own L and H
    assert!((lrfd("segment1-end") - n(l_seg, 6.0)).abs() < 1e-12);
    assert!((lrfd("segment2-start") - n(l_seg, 10.0)).abs() < 1e-12);
    assert!((lrfd("segment1-start") - n(l_seg, 6.0)).abs() < 1e-12);
    // a hand number: L = 188.50 m = 618.4 ft, H = 8 m = 26.25 ft: N = 22.47 in × 1.5 = 0.856 m
    assert!(
        (lrfd("segment2-end") - 0.856).abs() < 5e-4,
        "{}",
        lrfd("segment2-end")
    );
    let csv = check_csv(&r);
    let row = csv
        .lines()
        .find(|l| l.starts_with("segment3-start,"))
        .unwrap();
    assert!(
        row.contains(&format!(
            ",{},8,",
            pounding::output::float_token(2.0 * l_seg)
        )),
        "{row}"
    );
}

/// `codes` selects the codes that apply: the others are not evaluated (with the reason) and do
/// not govern, so a seat that only JRA's 0.7 m floor fails passes an AASHTO-only check.
#[test]
fn selected_codes_alone_govern() {
    let all = check_scenario(&scenario(&with_check(
        "pier_height_m = 8.0\ndisplacement_m = 0.1",
    )))
    .unwrap();
    let some = check_scenario(&scenario(&with_check(
        "pier_height_m = 8.0\ndisplacement_m = 0.1\ncodes = [\"aashto_lrfd\", \"ec8\"]",
    )))
    .unwrap();
    for (a, s) in all.ends.iter().zip(&some.ends) {
        for ((ca, qa), (cs, qs)) in a.codes.iter().zip(&s.codes) {
            assert_eq!(ca, cs);
            match cs {
                Code::AashtoLrfd | Code::Ec8 => assert_eq!(qa, qs, "{}", a.at.end),
                _ => assert!(
                    matches!(qs, Requirement::NotEvaluated(w) if w.contains("not selected")),
                    "{qs:?}"
                ),
            }
        }
        let g = s.governing().unwrap();
        assert!(matches!(g.0, Code::AashtoLrfd | Code::Ec8), "{g:?}");
        let want = [Code::AashtoLrfd, Code::Ec8]
            .iter()
            .filter_map(|&c| a.codes.iter().find(|(k, _)| *k == c).unwrap().1.value())
            .fold(f64::MIN, f64::max);
        assert_eq!(g.1, want);
    }
}
