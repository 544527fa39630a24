//! Closed-form single impact (spec §9–§11), checked against impulse balance, its own definitions and
//! the spec's reference numbers. (LCP cross-checks live in `impact.rs`.)

use crate::geometry::{Rng, deck};
use pounding::analytic::{
    ImpactLaw, LawError, SlipMode, energy_change, energy_gain_predicted, is_painleve,
    single_impact, stick_gain_possible, stick_interval,
};
use pounding::contact::{Delassus, force_directions};
use pounding::geometry::{ContactCase, SigmaMode};
use pounding::pair::SArrangement;

fn random_g(rng: &mut Rng) -> Delassus {
    // a random SPD 2×2 matrix, G_NT of either sign
    let nn = rng.uniform(0.1, 3.0);
    let tt = rng.uniform(0.1, 3.0);
    let nt = rng.uniform(-0.99, 0.99) * (nn * tt).sqrt();
    Delassus { nn, nt, tt }
}

#[test]
fn law_validation() {
    assert_eq!(ImpactLaw::new(-0.1, 0.5), Err(LawError::Friction(-0.1)));
    assert!(ImpactLaw::new(f64::NAN, 0.5).is_err());
    assert!(
        ImpactLaw::new(0.5, 1.1)
            .unwrap_err()
            .to_string()
            .contains("eps")
    );
    assert!(ImpactLaw::new(0.5, f64::NAN).is_err());
    assert!(ImpactLaw::new(0.0, 0.0).is_ok() && ImpactLaw::new(2.0, 1.0).is_ok());
}

/// Every mode satisfies the impulse balance `γ⁺ = γ⁻ + GΛ`, Newton's law `γ_N⁺ = −ε_N γ_N⁻`,
/// `Λ_N > 0`, Coulomb's cone, and the mode's sign of `γ_T⁺`; the mode matches `r` vs `[L, U]`.
#[test]
fn modes_satisfy_the_impact_laws() {
    let mut rng = Rng(1);
    let mut seen = [0usize; 3];
    for _ in 0..20_000 {
        let g = random_g(&mut rng);
        let law = ImpactLaw::new(rng.uniform(0.0, 2.0), rng.uniform(0.0, 1.0)).unwrap();
        let gn = -rng.uniform(0.01, 5.0);
        let gt = rng.uniform(-20.0, 20.0);
        let s = single_impact(&g, &law, gn, gt);
        let (ln, lt) = (s.normal_impulse, s.tangential_impulse);
        let scale = gn.abs().max(gt.abs());
        let gnp = gn + g.nn * ln + g.nt * lt;
        let gtp = gt + g.nt * ln + g.tt * lt;
        assert!(
            (gnp - s.gamma_n_post).abs() < 1e-9 * scale,
            "{g:?} {law:?} {gn} {gt} {s:?}"
        );
        assert!(
            (gtp - s.gamma_t_post).abs() < 1e-9 * scale,
            "{g:?} {law:?} {gn} {gt} {s:?}"
        );
        assert!((s.gamma_n_post + law.eps() * gn).abs() < 1e-12 * scale);
        assert!(ln > 0.0);
        assert!(lt.abs() <= law.mu() * ln * (1.0 + 1e-12) + 1e-15);
        let b = stick_interval(&g, &law);
        let r = gt / gn;
        match s.mode {
            SlipMode::Stick => {
                seen[0] += 1;
                assert!(b.contains(r) && s.gamma_t_post == 0.0);
            }
            SlipMode::SlipOutward => {
                seen[1] += 1;
                assert!(r < b.lower && s.gamma_t_post > 0.0);
                assert!((lt + law.mu() * ln).abs() < 1e-12 * ln);
            }
            SlipMode::SlipInward => {
                seen[2] += 1;
                assert!(r > b.upper && s.gamma_t_post < 0.0);
                assert!((lt - law.mu() * ln).abs() < 1e-12 * ln);
            }
        }
    }
    assert!(seen.iter().all(|&k| k > 1000), "{seen:?}");
}

/// `L < (1+ε)κ < U`; the interval grows with μ and collapses onto `(1+ε)κ` as μ → 0; the modes are
/// continuous across `r = L` and `r = U` (stick and slip coincide there).
#[test]
fn stick_interval_properties() {
    let mut rng = Rng(2);
    for _ in 0..5000 {
        let g = random_g(&mut rng);
        let eps = rng.uniform(0.0, 1.0);
        let mu = rng.uniform(0.001, 1.5);
        let law = ImpactLaw::new(mu, eps).unwrap();
        let b = stick_interval(&g, &law);
        let r0 = (1.0 + eps) * g.kappa();
        assert!(b.lower < r0 && r0 < b.upper, "{g:?} {law:?} {b:?}");
        let b2 = stick_interval(&g, &ImpactLaw::new(mu * 1.1, eps).unwrap());
        assert!(b2.lower <= b.lower && b2.upper >= b.upper);
        let b0 = stick_interval(&g, &ImpactLaw::new(0.0, eps).unwrap());
        assert!((b0.lower - r0).abs() < 1e-12 * r0.abs().max(1.0));
        assert_eq!(b0.lower, b0.upper);
        assert_eq!(
            b.lower.is_infinite() || b.upper.is_infinite(),
            is_painleve(&g, &law)
        );
        for bound in [b.lower, b.upper] {
            if bound.is_finite() {
                let a = single_impact(&g, &law, -1.0, -bound);
                let e = 1e-9 * bound.abs().max(1.0);
                let lo = single_impact(&g, &law, -1.0, -(bound - e));
                let hi = single_impact(&g, &law, -1.0, -(bound + e));
                for o in [lo, hi] {
                    assert!((o.normal_impulse - a.normal_impulse).abs() < 1e-6 * a.normal_impulse);
                    assert!(
                        (o.tangential_impulse - a.tangential_impulse).abs()
                            < 1e-6 * a.normal_impulse
                    );
                }
                assert!(
                    (a.tangential_impulse.abs() - mu * a.normal_impulse).abs()
                        < 1e-9 * a.normal_impulse
                );
            }
        }
    }
}

/// Painlevé-type regime `μ|G_NT| ≥ G_NN`: one bound is infinite and stick covers that side.
#[test]
fn painleve_regime_has_infinite_bound() {
    let g = Delassus {
        nn: 1.0,
        nt: 0.8,
        tt: 1.0,
    };
    let law = ImpactLaw::new(1.5, 0.3).unwrap();
    assert!(is_painleve(&g, &law));
    let b = stick_interval(&g, &law);
    assert_eq!(b.lower, f64::NEG_INFINITY);
    assert!(b.upper.is_finite());
    let s = single_impact(&g, &law, -1.0, 1e6); // r = −1e6
    assert_eq!(s.mode, SlipMode::Stick);
    assert!(s.normal_impulse > 0.0 && s.tangential_impulse.abs() <= 1.5 * s.normal_impulse);
    let gm = Delassus {
        nn: 1.0,
        nt: -0.8,
        tt: 1.0,
    };
    let bm = stick_interval(&gm, &law);
    assert_eq!(bm.upper, f64::INFINITY);
    assert!(bm.lower.is_finite());
}

/// No approach (`γ_N⁻ ≥ 0`): no impulse, velocities unchanged.
#[test]
fn no_approach_no_impulse() {
    let g = Delassus {
        nn: 1.0,
        nt: 0.3,
        tt: 2.0,
    };
    let law = ImpactLaw::new(0.5, 0.5).unwrap();
    for (gn, gt) in [(0.0, 1.0), (0.5, -1.0), (2.0, 0.0)] {
        let s = single_impact(&g, &law, gn, gt);
        assert_eq!((s.normal_impulse, s.tangential_impulse), (0.0, 0.0));
        assert_eq!((s.gamma_n_post, s.gamma_t_post), (gn, gt));
    }
}

/// Minimal-energy pre-impact velocity `u⁻ = M⁻¹W G⁻¹ γ⁻` with `T⁻ = ½ γ⁻ᵀ G⁻¹ γ⁻`.
fn minimal_energy(g: &Delassus, gn: f64, gt: f64) -> f64 {
    let det = g.det();
    0.5 * (g.tt * gn * gn - 2.0 * g.nt * gn * gt + g.nn * gt * gt) / det
}

/// The spec's worked example (§11): R = 100, β = 60°, θ = (−5°, 2°), deck1-inner, μ = 1, r = 0.726,
/// minimal-energy u⁻: ε_N = 1 → +28.5 %, 0.9 → +4.1 %, 0.5 → −68 %; and ΔT computed from body
/// velocities equals `½(γ⁺ + γ⁻)ᵀΛ`.
#[test]
fn energy_example_of_spec_section_11() {
    let s = SArrangement::new(deck(100.0, 60.0), deck(100.0, 60.0)).unwrap();
    let c = s
        .configuration(
            ContactCase::Deck1Inner,
            (-5f64).to_radians(),
            2f64.to_radians(),
            SigmaMode::Exact,
        )
        .unwrap();
    let g = s.delassus(&c);
    let w = force_directions(&c);
    let p = s.deck1.mass_properties();
    let minv = [
        1.0 / p.mass,
        1.0 / p.mass,
        1.0 / p.inertia,
        1.0 / p.mass,
        1.0 / p.mass,
        1.0 / p.inertia,
    ];
    let (gn, gt) = (-1.0, -0.726);
    for (eps, expect) in [(1.0, 0.285), (0.9, 0.041), (0.5, -0.68)] {
        let law = ImpactLaw::new(1.0, eps).unwrap();
        let imp = single_impact(&g, &law, gn, gt);
        let t_pre = minimal_energy(&g, gn, gt);
        let rel = energy_change(gn, gt, &imp) / t_pre;
        assert!((rel - expect).abs() < 0.0051, "eps {eps}: {rel}");
        assert_eq!(rel > 0.0, energy_gain_predicted(&g, &law, gt / gn));
        // body velocities: u⁻ = M⁻¹ W G⁻¹ γ⁻, u⁺ = u⁻ + M⁻¹ (w_N Λ_N + w_T Λ_T)
        let det = g.det();
        let (xn, xt) = ((g.tt * gn - g.nt * gt) / det, (g.nn * gt - g.nt * gn) / det);
        let mut t0 = 0.0;
        let mut t1 = 0.0;
        for ((mi, wn), wt) in minv.iter().zip(&w.w_n).zip(&w.w_t) {
            let u0 = mi * (wn * xn + wt * xt);
            let u1 = u0 + mi * (wn * imp.normal_impulse + wt * imp.tangential_impulse);
            t0 += 0.5 * u0 * u0 / mi;
            t1 += 0.5 * u1 * u1 / mi;
        }
        assert!((t0 - t_pre).abs() < 1e-9 * t_pre);
        let dt = energy_change(gn, gt, &imp);
        assert!(((t1 - t0) - dt).abs() < 1e-9 * t0, "{} vs {dt}", t1 - t0);
    }
}

/// Energy rises only under the §11 conditions: over random cases the sign of the exact ΔT agrees
/// with the predicted conditions, and a gain while sticking needs `G_NT² > (1−ε²) G_NN G_TT`.
#[test]
fn energy_gain_only_under_spec_conditions() {
    let mut rng = Rng(4);
    let (mut gains, mut total) = (0, 0);
    for _ in 0..20_000 {
        let g = random_g(&mut rng);
        let law = ImpactLaw::new(rng.uniform(0.0, 1.5), rng.uniform(0.0, 1.0)).unwrap();
        let r = rng.uniform(-12.0, 12.0);
        let imp = single_impact(&g, &law, -1.0, -r);
        let dt = energy_change(-1.0, -r, &imp);
        let predicted = energy_gain_predicted(&g, &law, r);
        total += 1;
        if dt.abs() < 1e-10 * imp.normal_impulse {
            continue; // on the boundary of a condition
        }
        assert_eq!(dt > 0.0, predicted, "{g:?} {law:?} r={r} dT={dt}");
        if dt > 0.0 {
            gains += 1;
            if imp.mode == SlipMode::Stick {
                assert!(stick_gain_possible(&g, &law));
            }
        }
    }
    assert!(gains > 10 && gains < total, "{gains}/{total}");
}

/// The paper's set (ε_N = 0.5, μ ∈ {0.5, 1}, β ∈ {60, 90, 120}°, R ∈ {100, 200} m, θ ∈ [−10°, 10°]):
/// no gain is possible (spec §11): max `G_NT²/(G_NN G_TT)` < 0.75, and ΔT ≤ 0 for r ∈ [−12, 12].
#[test]
fn no_energy_gain_on_the_paper_set() {
    let mut max_ratio: f64 = 0.0;
    let mut checked = 0;
    for &(r1, r2) in &[
        (100.0, 100.0),
        (100.0, 200.0),
        (200.0, 100.0),
        (200.0, 200.0),
    ] {
        for &b1 in &[60.0, 90.0, 120.0] {
            for &b2 in &[60.0, 90.0, 120.0] {
                let s = SArrangement::new(deck(r1, b1), deck(r2, b2)).unwrap();
                for i in (-10..=10).step_by(2) {
                    for j in (-10..=10).step_by(2) {
                        let (t1, t2) = ((i as f64).to_radians(), (j as f64).to_radians());
                        for case in ContactCase::ALL {
                            let Ok(c) = s.configuration(case, t1, t2, SigmaMode::Exact) else {
                                continue;
                            };
                            let g = s.delassus(&c);
                            max_ratio = max_ratio.max(g.nt * g.nt / (g.nn * g.tt));
                            for mu in [0.5, 1.0] {
                                let law = ImpactLaw::new(mu, 0.5).unwrap();
                                assert!(!stick_gain_possible(&g, &law));
                                for k in -24..=24 {
                                    let r = k as f64 * 0.5;
                                    let imp = single_impact(&g, &law, -1.0, -r);
                                    let dt = energy_change(-1.0, -r, &imp);
                                    assert!(
                                        dt <= 0.0,
                                        "gain {dt} at {case:?} {i} {j} mu {mu} r {r}"
                                    );
                                    assert!(!energy_gain_predicted(&g, &law, r));
                                    checked += 1;
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(max_ratio < 0.75 && max_ratio > 0.3, "{max_ratio}");
    assert!(checked > 100_000);
}

/// The spec's grid statements (§9, §10, §11) for ε = 0.5 over all cells of the paper grid, taken as
/// the closure of the θ-square (1° grid plus points 1e-6° off each diagonal cell, where the extremes
/// are approached): L, U ranges for μ ∈ {0.25, 0.5, 1} to the printed 2 decimals,
/// max `G_NT²/(G_NN G_TT)` = 0.358, min `G_NN/|G_NT|` = 1.328, and for μ ∈ {0.5, 1} max L = 0.216,
/// min U = 0.968.
#[test]
fn paper_grid_statements_of_the_spec() {
    let mut lo = [[f64::MAX, f64::MIN]; 3];
    let mut up = [[f64::MAX, f64::MIN]; 3];
    let (mut maxc, mut minq) = (0.0f64, f64::MAX);
    for &(r1, r2) in &[
        (100.0, 100.0),
        (100.0, 200.0),
        (200.0, 100.0),
        (200.0, 200.0),
    ] {
        for &b1 in &[60.0, 90.0, 120.0] {
            for &b2 in &[60.0, 90.0, 120.0] {
                let s = SArrangement::new(deck(r1, b1), deck(r2, b2)).unwrap();
                for i in -10..=10 {
                    for jj in -30i32..=32 {
                        let t2d = jj.div_euclid(3) as f64 + 1e-6 * (jj.rem_euclid(3) - 1) as f64;
                        if !(-10.0..=10.0).contains(&t2d) {
                            continue;
                        }
                        let (t1, t2) = ((i as f64).to_radians(), t2d.to_radians());
                        for case in ContactCase::ALL {
                            let Ok(c) = s.configuration(case, t1, t2, SigmaMode::Exact) else {
                                continue;
                            };
                            let g = s.delassus(&c);
                            maxc = maxc.max(g.nt * g.nt / (g.nn * g.tt));
                            minq = minq.min(g.nn / g.nt.abs());
                            for (k, mu) in [0.25, 0.5, 1.0].into_iter().enumerate() {
                                let b = stick_interval(&g, &ImpactLaw::new(mu, 0.5).unwrap());
                                lo[k] = [lo[k][0].min(b.lower), lo[k][1].max(b.lower)];
                                up[k] = [up[k][0].min(b.upper), up[k][1].max(b.upper)];
                            }
                        }
                    }
                }
            }
        }
    }
    let r2 = |x: f64| (x * 100.0).round() / 100.0;
    let spec_l = [[-0.99, 0.63], [-2.60, 0.22], [-10.64, -0.70]];
    let spec_u = [[0.83, 1.84], [0.97, 2.73], [1.19, 4.29]];
    for k in 0..3 {
        assert_eq!(
            [r2(lo[k][0]), r2(lo[k][1])],
            spec_l[k],
            "L range {k}: {:?}",
            lo[k]
        );
        assert_eq!(
            [r2(up[k][0]), r2(up[k][1])],
            spec_u[k],
            "U range {k}: {:?}",
            up[k]
        );
    }
    assert_eq!((maxc * 1000.0).round() / 1000.0, 0.358);
    assert_eq!((minq * 1000.0).round() / 1000.0, 1.328);
    assert_eq!((lo[1][1].max(lo[2][1]) * 1000.0).round() / 1000.0, 0.216);
    assert_eq!((up[1][0].min(up[2][0]) * 1000.0).round() / 1000.0, 0.968);
}
