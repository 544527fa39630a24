//! The substructure laws (`pounding::element::{backfill, shear_key}` and the bilinear bearing
//! with `b = 0` as a pile) alone: backbone points and unloading/reloading by hand, the gap
//! opening and closing, the Caltrans preset's unit conversions by hand, parameter errors, and
//! the energy balance `W = ΔE + D` to 1e-9 over random cyclic paths, with `W` the integral of
//! the law's force along each step by Gauss–Legendre quadrature (split at the law's kinks).
//! The comparison with OpenSees itself is in `element_substructure_opensees`.

use pounding::element::restrainer::SlackGrowth;
use pounding::element::{
    BackfillElement, CaltransBackwall, HyperbolicGap, ShearKey, ShearKeyElement,
};
use proptest::prelude::*;

/// `n`-point Gauss–Legendre nodes and weights on [−1, 1] (Newton on `P_n`).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    (p0, p1) = (p1, p2);
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// 10-point Gauss–Legendre on [a, b].
fn gl10(f: &impl Fn(f64) -> f64, gl: &[(f64, f64)], a: f64, b: f64) -> f64 {
    let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
    gl.iter().map(|&(x, w)| w * f(m + h * x)).sum::<f64>() * h
}

/// Adaptive bisection of one smooth piece until the halves agree to `tol`.
fn adaptive(
    f: &impl Fn(f64) -> f64,
    gl: &[(f64, f64)],
    a: f64,
    b: f64,
    tol: f64,
    depth: u32,
) -> f64 {
    let m = 0.5 * (a + b);
    let (whole, halves) = (gl10(f, gl, a, b), gl10(f, gl, a, m) + gl10(f, gl, m, b));
    if (whole - halves).abs() <= tol || depth > 60 {
        halves
    } else {
        adaptive(f, gl, a, m, 0.5 * tol, depth + 1) + adaptive(f, gl, m, b, 0.5 * tol, depth + 1)
    }
}

/// `∫_a^b f` (either order) with the domain cut at `kinks`, each smooth piece by adaptive
/// 10-point Gauss–Legendre to 1e-14 of `(b − a) · max |f|` (sampled).
pub fn path_work(f: impl Fn(f64) -> f64, a: f64, b: f64, kinks: &[f64]) -> f64 {
    let (lo, hi, sign) = if a <= b { (a, b, 1.0) } else { (b, a, -1.0) };
    let mut cuts: Vec<f64> = std::iter::once(lo)
        .chain(kinks.iter().copied().filter(|&k| k > lo && k < hi))
        .chain(std::iter::once(hi))
        .collect();
    cuts.sort_by(f64::total_cmp);
    let gl = gauss_legendre(10);
    let peak = (0..=16)
        .map(|i| f(lo + (hi - lo) * i as f64 / 16.0).abs())
        .fold(0.0, f64::max);
    let tol = 1e-14 * (hi - lo) * peak;
    let sum: f64 = cuts
        .windows(2)
        .map(|w| adaptive(&f, &gl, w[0], w[1], tol, 0))
        .sum();
    sign * sum
}

/// Kmax = Kur = 2e7 N/m, Rf = 0.7, Fult = 3e5 N, gap = 1 cm (the OpenSees comparison's law).
fn law() -> HyperbolicGap {
    HyperbolicGap::new(2.0e7, 2.0e7, 0.7, 3.0e5, 0.01).unwrap()
}

/// Backbone by hand: δ = 3 cm → 0.03/(5e-8 + 0.7·0.03/3e5) = 0.03/1.2e-7 = 250 kN; F = Fult at
/// δ = Fult/(Kmax (1 − Rf)) = 5 cm; F → Fult/Rf far out; zero (tangent 0) inside the gap and at
/// negative u; tangent Kmax at the closure and the derivative of the backbone beyond.
#[test]
fn backfill_backbone_by_hand() {
    let l = law();
    let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs().max(1.0);
    assert!(close(l.envelope_force(0.04), 250_000.0, 1e-12));
    assert!(close(l.envelope_force(0.06), 300_000.0, 1e-12));
    assert!(close(l.envelope_force(1e3), 3.0e5 / 0.7, 1e-4));
    for u in [-0.05, 0.0, 0.005, 0.01] {
        assert_eq!(l.envelope_force(u), 0.0);
    }
    assert_eq!(l.envelope_tangent(0.005), 0.0);
    assert!(close(l.envelope_tangent(0.01), 2.0e7, 1e-12));
    for u in [0.011, 0.02, 0.05, 0.2] {
        let h = 1e-7;
        let fd = (l.envelope_force(u + h) - l.envelope_force(u - h)) / (2.0 * h);
        assert!(close(l.envelope_tangent(u), fd, 1e-7), "u = {u}");
    }
    // A monotone push from rest follows the backbone.
    let mut el = BackfillElement::new(l);
    for u in [0.005, 0.02, 0.04, 0.06] {
        let r = el.trial(u);
        assert_eq!(r.force, l.envelope_force(u));
        assert_eq!(r.tangent, l.envelope_tangent(u));
        el.commit(&r);
    }
}

/// Unloading from 4 cm (250 kN) with Kur: 150 kN at 3.5 cm, zero at 4 − 250e3/2e7 = 2.75 cm
/// (the gap has grown from 1 to 2.75 cm); pulled away and back the soil is met at 2.75 cm,
/// reloading follows Kur back onto the backbone at 4 cm, then the backbone.
#[test]
fn backfill_unloading_gap_and_reloading_by_hand() {
    let l = law();
    let mut el = BackfillElement::new(l);
    let go = |el: &mut BackfillElement, u: f64| {
        let r = el.trial(u);
        el.commit(&r);
        (r.force, r.tangent)
    };
    go(&mut el, 0.04);
    let (f, k) = go(&mut el, 0.035);
    assert!((f - 150_000.0).abs() < 1e-6 && k == 2.0e7);
    assert_eq!(go(&mut el, 0.0276).1, 2.0e7);
    assert_eq!(go(&mut el, 0.027), (0.0, 0.0));
    assert!((el.committed().reload_onset - 0.0275).abs() < 1e-15);
    assert_eq!(go(&mut el, -0.02), (0.0, 0.0));
    assert_eq!(go(&mut el, 0.0274), (0.0, 0.0));
    let (f, k) = go(&mut el, 0.03);
    assert!((f - 50_000.0).abs() < 1e-6 && k == 2.0e7);
    let (f, _) = go(&mut el, 0.04 - 1e-9);
    assert!((f - 250_000.0).abs() < 1e-1);
    let (f, k) = go(&mut el, 0.06);
    assert_eq!((f, k), (l.envelope_force(0.06), l.envelope_tangent(0.06)));
    // A second unloading starts from the new maximum.
    go(&mut el, 0.05);
    let onset = 0.06 - l.envelope_force(0.06) / 2.0e7;
    assert!((el.committed().reload_onset - onset).abs() < 1e-15);
}

/// The Caltrans SDC 2019 backwall by hand: h = 4 ft (1.2192 m), w = 10 ft (3.048 m), no skew:
/// F = 10 · 5.5 · 4^2.5 / (1 + 2.37 · 4) = 1760/10.48 = 167.938 931 kip = 747 029.584 N and
/// K = 10 · (5.5 · 4 + 20) = 420 kip/in = 420 · 4448.2216152605 N / 0.0254 m = 73 553 270.8 N/m;
/// 45° skew multiplies both by e^−1. The law: Kmax = Kur = K, Rf = 0.7, Fult = F.
#[test]
fn caltrans_preset_by_hand() {
    let c = CaltransBackwall::new(1.2192, 3.048, 0.0).unwrap();
    assert!((c.f_ult - 747_029.584_242_221_3).abs() < 1e-12 * c.f_ult);
    assert!((c.k - 73_553_270.803_520_07).abs() < 1e-12 * c.k);
    let s = CaltransBackwall::new(1.2192, 3.048, 45.0).unwrap();
    let e1 = 0.367_879_441_171_442_33;
    assert!((s.f_ult - c.f_ult * e1).abs() < 1e-12 * s.f_ult);
    assert!((s.k - c.k * e1).abs() < 1e-12 * s.k);
    let l = HyperbolicGap::caltrans_sdc_2019(1.2192, 3.048, 45.0, 0.05).unwrap();
    assert_eq!((l.kmax(), l.kur(), l.rf()), (s.k, s.k, 0.7));
    assert_eq!((l.fult(), l.gap()), (s.f_ult, 0.05));
}

/// Bad parameters are refused naming their key.
#[test]
fn bad_parameters_name_their_key() {
    let bad = [
        (HyperbolicGap::new(0.0, 1.0, 0.5, 1.0, 0.0), "kmax"),
        (HyperbolicGap::new(1.0, -1.0, 0.5, 1.0, 0.0), "kur"),
        (HyperbolicGap::new(1.0, 1.0, 1.0, 1.0, 0.0), "rf"),
        (HyperbolicGap::new(1.0, 1.0, 0.0, 1.0, 0.0), "rf"),
        (HyperbolicGap::new(1.0, 1.0, 0.5, -1.0, 0.0), "fult"),
        (HyperbolicGap::new(1.0, 1.0, 0.5, 1.0, -0.01), "gap"),
        (HyperbolicGap::new(1.0, 1.0, 0.5, 1.0, f64::NAN), "gap"),
        (
            HyperbolicGap::caltrans_sdc_2019(0.0, 1.0, 0.0, 0.0),
            "height",
        ),
        (
            HyperbolicGap::caltrans_sdc_2019(1.0, f64::INFINITY, 0.0, 0.0),
            "width",
        ),
        (
            HyperbolicGap::caltrans_sdc_2019(1.0, 1.0, 90.0, 0.0),
            "skew",
        ),
        (
            HyperbolicGap::caltrans_sdc_2019(1.0, 1.0, -1.0, 0.0),
            "skew",
        ),
    ];
    for (r, key) in bad {
        assert_eq!(r.unwrap_err().key(), key);
    }
    let g = SlackGrowth::Permanent;
    for (r, key) in [
        (ShearKey::new(0.0, 1.0, 0.0, g), "k"),
        (ShearKey::new(1.0, 0.0, 0.0, g), "fy"),
        (ShearKey::new(1.0, 1.0, -1.0, g), "gap"),
    ] {
        let e = r.unwrap_err();
        assert_eq!(e.key(), key);
        assert!(e.to_string().contains("shear key"), "{e}");
    }
}

/// With Kur < Kmax the law is not dissipative: a small loop on the early backbone returns more
/// than it received (D < 0 on the loading step), as documented.
#[test]
fn backfill_with_kur_below_kmax_reports_negative_dissipation() {
    let l = HyperbolicGap::new(2.0e7, 1.0e7, 0.7, 3.0e5, 0.0).unwrap();
    let r = l.response(0.001, &l.initial_state());
    assert!(r.dissipation < 0.0, "{}", r.dissipation);
}

/// Random cyclic target path of `n` points in units of `unit`, each reached in 1–4 steps.
fn steps(targets: &[(f64, usize)], unit: f64) -> Vec<f64> {
    let (mut out, mut last) = (Vec::new(), 0.0);
    for &(t, n) in targets {
        for i in 1..=n {
            out.push(last + (t * unit - last) * i as f64 / n as f64);
        }
        last = t * unit;
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Backfill: over a random cyclic path, Σ W = E_end + Σ D to 1e-9 of Σ |W|, with W the
    /// quadrature of the law's force from the committed state along each step (cut at the
    /// gap, the reload onset, the largest deformation and the unloading's zero-force point);
    /// D ≥ 0 on every step when Kur ≥ Kmax; the force is never negative.
    #[test]
    fn backfill_energy_balance(
        kmax in 1e6f64..1e9, kur_ratio in 1.0f64..3.0, rf in 0.05f64..0.95, fult in 1e4f64..1e7,
        gap_ratio in 0.0f64..3.0,
        targets in proptest::collection::vec((-1.0f64..6.0, 1usize..5), 1..40),
    ) {
        let gap = gap_ratio * fult / kmax;
        let l = HyperbolicGap::new(kmax, kur_ratio * kmax, rf, fult, gap).unwrap();
        let unit = gap + fult / kmax;
        let mut el = BackfillElement::new(l);
        let (mut work, mut abs_work) = (0.0, 0.0);
        for u in steps(&targets, unit) {
            let c = *el.committed();
            let kinks = [l.gap(), c.reload_onset, c.u_max, c.u - c.force / l.kur()];
            let w = path_work(|x| l.response(x, &c).force, c.u, u, &kinks);
            let r = el.trial(u);
            prop_assert!(r.force >= 0.0);
            prop_assert!(r.dissipation >= -1e-9 * (abs_work + w.abs()));
            el.commit(&r);
            work += w;
            abs_work += w.abs();
        }
        let balance = el.stored_energy() + el.dissipated();
        prop_assert!((work - balance).abs() <= 1e-9 * abs_work.max(1e-300),
            "work {work}, stored + dissipated {balance}");
    }

    /// Shear keys: the same balance (plastic dissipation fy · Δgap) over random paths through
    /// both keys, for both slack-growth rules; the force is zero inside the gaps.
    #[test]
    fn shear_key_energy_balance(
        k in 1e6f64..1e9, fy in 1e4f64..1e7, gap in 0.0f64..0.05, damage: bool,
        targets in proptest::collection::vec((-4.0f64..4.0, 1usize..5), 1..40),
    ) {
        let growth = if damage { SlackGrowth::Permanent } else { SlackGrowth::Recentering };
        let l = ShearKey::new(k, fy, gap, growth).unwrap();
        let unit = gap + fy / k;
        let mut el = ShearKeyElement::new(l);
        let (mut work, mut abs_work) = (0.0, 0.0);
        for v in steps(&targets, unit) {
            let c = *el.committed();
            let (p, n) = (c.positive, c.negative);
            let kinks = [p.slack, p.yield_elongation, -n.slack, -n.yield_elongation];
            let w = path_work(|x| l.response(x, &c).force, c.v(), v, &kinks);
            let r = el.trial(v);
            if v.abs() <= gap {
                prop_assert_eq!(r.force, 0.0);
            }
            prop_assert!(r.dissipation >= 0.0);
            el.commit(&r);
            work += w;
            abs_work += w.abs();
        }
        let balance = el.stored_energy() + el.dissipated();
        prop_assert!((work - balance).abs() <= 1e-9 * abs_work.max(1e-300),
            "work {work}, stored + dissipated {balance}");
    }
}

/// Shear keys by hand (k = 5e7 N/m, fy = 1 MN, gap = 2 cm, permanent): nothing inside ±2 cm;
/// 3 cm → 0.5 MN; yield at 2 + 2 = 4 cm; at 5 cm fy with the positive gap grown to 3 cm
/// (dissipation fy · 1 cm = 10 kJ); back at 2.5 cm nothing (the negative key is untouched);
/// −3 cm → −0.5 MN from the negative key.
#[test]
fn shear_key_by_hand() {
    let l = ShearKey::new(5.0e7, 1.0e6, 0.02, SlackGrowth::Permanent).unwrap();
    let mut el = ShearKeyElement::new(l);
    let mut go = |v: f64| {
        let r = el.trial(v);
        el.commit(&r);
        (r.force, r.tangent, el.dissipated())
    };
    assert_eq!(go(0.019), (0.0, 0.0, 0.0));
    assert_eq!(go(-0.019), (0.0, 0.0, 0.0));
    let (f, k, _) = go(0.03);
    assert!((f - 5.0e5).abs() < 1e-6 && k == 5.0e7);
    let (f, k, d) = go(0.05);
    assert_eq!((f, k), (1.0e6, 0.0));
    assert!((d - 1.0e4).abs() < 1e-6);
    assert_eq!(go(0.025).0, 0.0);
    let (f, k, _) = go(-0.03);
    assert!((f + 5.0e5).abs() < 1e-6 && k == 5.0e7);
}
