//! Code checks of seat width and joint gap: each formula against a vector worked by hand from
//! the code's own text (the clause is named at each test).

use pounding::assessment::code_check::*;

const IN: f64 = 0.0254;
const FT: f64 = 0.3048;

fn close(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b} (tol {tol})");
}

/// EN 1998-2 §6.6.4 with EN 1998-1 §3.2.2.4 and Table 3.2: ground A (S = 1, T_C = 0.4 s,
/// T_D = 2 s), a_gR = 2.35 m/s², class I (γ_I = 0.85): a_g = 1.9975, d_g = 0.025·1.9975·0.8 =
/// 0.03995 m, ε_s = 2 d_g/600, d_eg = 50 ε_s = 6.658 mm, l_ov = 400 + 6.658 + 100 = 506.66 mm.
#[test]
fn ec8_overlap_length_of_the_worked_example() {
    let r = ec8_seat(&example()).unwrap();
    close(r.l_ov * 1e3, 506.66, 0.01);
    close(r.d_g, 0.03995, 1e-12);
    // d_eg is capped at 2 d_g for a long L_eff (§6.6.4(3)).
    let long = ec8_seat(&Ec8Seat {
        l_eff: 1e5,
        ..example()
    })
    .unwrap();
    close(long.d_eg, 2.0 * long.d_g, 1e-15);
    // l_m below 0.40 m is raised to 0.40 m; the near-fault factor scales d_eg.
    let nf = ec8_seat(&Ec8Seat {
        l_m: 0.1,
        near_fault_factor: 2.0,
        ..example()
    })
    .unwrap();
    close(nf.l_m, 0.40, 0.0);
    close(nf.d_eg, 2.0 * r.d_eg, 1e-15);
    assert!(
        ec8_seat(&Ec8Seat {
            importance_class: 4,
            ..example()
        })
        .is_err()
    );
    assert!(
        ec8_seat(&Ec8Seat {
            a_gr: f64::NAN,
            ..example()
        })
        .is_err()
    );
}

/// EN 1998-2 §6.6.4(4), an intermediate separation joint between two deck sections: expression
/// (6.11) for each section alone, then the square root of the sum of their squares.
/// Ground C, type 1 (Table 3.2: S = 1.15, T_C = 0.6 s, T_D = 2 s; L_g = 400 m), a_gR = 3.0 m/s²,
/// class II (γ_I = 1): a_g = 3.0, d_g = 0.025·3.0·1.15·0.6·2.0 = 0.1035 m,
/// ε_s = 2·0.1035/400 = 5.175e-4.
/// Section 1: L_eff = 30 m, d_es = 0.08 m: d_eg = 30·5.175e-4 = 0.015525 (< 2 d_g = 0.207),
/// l_ov,1 = 0.40 + 0.015525 + 0.08 = 0.495525 m.
/// Section 2: L_eff = 50 m, d_es = 0.15 m: d_eg = 0.025875, l_ov,2 = 0.40 + 0.025875 + 0.15 =
/// 0.575875 m.
/// l_ov = √(0.495525² + 0.575875²) = √(0.245545025625 + 0.331632015625) = √0.57717704125
/// = 0.759721686705 m (the former single-section form with d_es = √(0.08² + 0.15²) = 0.17 gave
/// 0.585525 m at section 1's end).
#[test]
fn ec8_intermediate_joint_is_the_srss_of_the_two_sections() {
    let section = |l_eff: f64, d_ed: f64| Ec8Seat {
        ground: GroundType::C,
        spectrum: SpectrumType::Type1,
        a_gr: 3.0,
        importance_class: 2,
        l_eff,
        d_ed,
        l_m: 0.40,
        near_fault_factor: 1.0,
    };
    let (a, b) = (section(30.0, 0.08), section(50.0, 0.15));
    let r = ec8_joint_seat([&a, &b]).unwrap();
    close(r.sections[0].d_g, 0.1035, 1e-12);
    close(r.sections[0].d_eg, 0.015525, 1e-12);
    close(r.sections[1].d_eg, 0.025875, 1e-12);
    close(r.sections[0].l_ov, 0.495525, 1e-12);
    close(r.sections[1].l_ov, 0.575875, 1e-12);
    close(r.l_ov, 0.57717704125f64.sqrt(), 1e-12);
    close(r.l_ov, 0.759721686705, 1e-9);
    // symmetric in the two sections; a bad section is refused
    close(ec8_joint_seat([&b, &a]).unwrap().l_ov, r.l_ov, 1e-15);
    let bad = section(f64::NAN, 0.1);
    assert!(ec8_joint_seat([&a, &bad]).is_err());
}

fn example() -> Ec8Seat {
    Ec8Seat {
        ground: GroundType::A,
        spectrum: SpectrumType::Type1,
        a_gr: 2.35,
        importance_class: 1,
        l_eff: 50.0,
        d_ed: 0.100,
        l_m: 0.40,
        near_fault_factor: 1.0,
    }
}

/// AASHTO LRFD 4.7.4.4-1 and Table 4.7.4.4-1: L = 100 ft, H = 20 ft, S = 0 → N = 8 + 2 + 1.6 =
/// 11.6 in; zone 4 150 % → 17.4 in; zone 1 with A_s = 0.04 → 75 %; S = 30° multiplies by 1.1125.
#[test]
fn aashto_lrfd_seat_width() {
    close(
        aashto_base_seat(100.0 * FT, 20.0 * FT, 0.0).unwrap() / IN,
        11.6,
        1e-12,
    );
    close(
        aashto_lrfd_seat(100.0 * FT, 20.0 * FT, 0.0, AashtoZone::Z4, 0.4).unwrap() / IN,
        17.4,
        1e-12,
    );
    close(
        aashto_lrfd_seat(100.0 * FT, 20.0 * FT, 0.0, AashtoZone::Z1, 0.04).unwrap() / IN,
        8.7,
        1e-12,
    );
    close(
        aashto_lrfd_seat(100.0 * FT, 20.0 * FT, 0.0, AashtoZone::Z1, 0.05).unwrap() / IN,
        11.6,
        1e-12,
    );
    close(
        aashto_base_seat(100.0 * FT, 20.0 * FT, 30.0).unwrap() / IN,
        11.6 * 1.1125,
        1e-12,
    );
    assert!(aashto_base_seat(100.0, 6.0, 90.0).is_err());
}

/// AASHTO Guide Specifications 4.12.2 (SDC A–C) and 4.12.3-1 (SDC D): Δ_eq = 10 in gives
/// 4 + 16.5 = 20.5 in → the 24 in minimum; Δ_eq = 15 in, S = 20° gives 28.75 · 1.1 = 31.625 in.
#[test]
fn aashto_guide_spec_seat_width() {
    let (l, h) = (100.0 * FT, 20.0 * FT);
    close(
        aashto_guide_seat(Sdc::A, l, h, 0.0, 0.04, 0.0).unwrap() / IN,
        8.7,
        1e-12,
    );
    close(
        aashto_guide_seat(Sdc::A, l, h, 0.0, 0.10, 0.0).unwrap() / IN,
        11.6,
        1e-12,
    );
    close(
        aashto_guide_seat(Sdc::C, l, h, 0.0, 0.10, 0.0).unwrap() / IN,
        17.4,
        1e-12,
    );
    close(
        aashto_guide_seat(Sdc::D, l, h, 0.0, 0.4, 10.0 * IN).unwrap() / IN,
        24.0,
        1e-12,
    );
    close(
        aashto_guide_seat(Sdc::D, l, h, 20.0, 0.4, 15.0 * IN).unwrap() / IN,
        31.625,
        1e-12,
    );
}

/// Caltrans SDC 1.7 §7.2.5.4 / §7.8.3: N = ΣΔ + 4 in, ≥ 24 in (hinge), ≥ 30 in (abutment).
#[test]
fn caltrans_seat_width() {
    close(
        caltrans_seat(SeatKind::Hinge, 0.0, 0.0, 0.0, 0.1).unwrap() / IN,
        24.0,
        1e-12,
    );
    close(
        caltrans_seat(SeatKind::Abutment, 0.0, 0.0, 0.0, 0.1).unwrap() / IN,
        30.0,
        1e-12,
    );
    close(
        caltrans_seat(SeatKind::Hinge, 0.01, 0.02, 0.03, 0.6).unwrap(),
        0.66 + 4.0 * IN,
        1e-12,
    );
    assert!(caltrans_seat(SeatKind::Hinge, -0.01, 0.0, 0.0, 0.0).is_err());
}

/// JRA Part V §16.2: ground II, u_R = 0.3 m, L = 50 m → u_G = 0.1875 m, S_E = 0.4875 m, which
/// S_EM = 0.7 + 0.005·40 = 0.9 m governs; skew 30°, L_θ = 100 m → 50 (sin 30° − sin 27.5°).
#[test]
fn jra_seat_length() {
    close(
        jra_seat(JraGround::II, 0.3, 50.0, 0.0, 0.0, 0.0).unwrap(),
        0.7,
        1e-12,
    );
    close(
        jra_seat(JraGround::II, 0.6, 50.0, 0.0, 0.0, 0.0).unwrap(),
        0.7875,
        1e-12,
    );
    close(
        jra_seat(JraGround::II, 0.3, 50.0, 40.0, 0.0, 0.0).unwrap(),
        0.9,
        1e-12,
    );
    let skew = 50.0 * (30f64.to_radians().sin() - 27.5f64.to_radians().sin());
    close(
        jra_seat(JraGround::II, 0.3, 50.0, 40.0, 30.0, 100.0).unwrap(),
        skew,
        1e-12,
    );
    assert!(skew > 0.9);
}

/// Gap: SRSS of 3 and 4 is 5; the double difference with equal periods (ρ = 1) is |u₁ − u₂|,
/// and with far-apart periods tends to the SRSS; ρ is symmetric in the periods.
#[test]
fn joint_gap_rules() {
    close(gap_srss(0.03, 0.04).unwrap(), 0.05, 1e-15);
    close(cqc_rho(1.0, 1.0, 0.05).unwrap(), 1.0, 1e-15);
    close(gap_ddc(0.03, 0.04, 1.0, 1.0, 0.05).unwrap(), 0.01, 1e-12);
    close(
        cqc_rho(0.5, 2.0, 0.05).unwrap(),
        cqc_rho(2.0, 0.5, 0.05).unwrap(),
        1e-15,
    );
    let far = gap_ddc(0.03, 0.04, 0.2, 5.0, 0.05).unwrap();
    assert!(far < 0.05 && far > 0.0499, "{far}");
    // ξ = 0.05, r = 0.9: ρ = 8·0.0025·1.9·0.9^1.5 / (0.19² + 0.01·0.9·1.9²) by hand.
    // = 0.038 · 0.853815 / 0.0685900 = 0.47302768 (hand value).
    close(
        cqc_rho(1.0, 0.9, 0.05).unwrap(),
        0.038 * 0.9f64.powf(1.5) / 0.06859,
        1e-15,
    );
    close(cqc_rho(1.0, 0.9, 0.05).unwrap(), 0.473_027_68, 1e-8);
    // undamped: equal periods are fully correlated (the 0/0 of the form; a hostile trial got a
    // NaN turned into a zero gap that passed), different ones not at all
    assert_eq!(cqc_rho(1.0, 1.0, 0.0).unwrap(), 1.0);
    assert_eq!(cqc_rho(1.0, 1.2, 0.0).unwrap(), 0.0);
    close(gap_ddc(0.1, 0.3, 1.0, 1.0, 0.0).unwrap(), 0.2, 1e-15);
    close(gap_ddc(0.1, 0.3, 1.0, 1.0, 1e-7).unwrap(), 0.2, 1e-9);
}
