//! The cable restrainer (`pounding::element::restrainer`) against an independent
//! re-implementation of OpenSees' `ElasticPPGap` (`EPPGapMaterial.cpp`, positive gap and
//! `fy`, `eta = 0`, both the `damage` and the default `noDamage` variants), zero force below
//! the slack, and its energy: stored ½ k (e − s)² without yield, dissipation = loop area with
//! yield (closed forms for both slack-growth rules).

use pounding::element::restrainer::{Restrainer, RestrainerElement, SlackGrowth};
use pounding::element::step_work;
use proptest::prelude::*;

/// Independent `ElasticPPGap` (fy ≥ 0 branch): the trial from the committed yield limits; the
/// limits move only at commit.
struct EppGap {
    e: f64,
    fy: f64,
    gap: f64,
    eta: f64,
    damage: bool,
    min_strain: f64,
    max_strain: f64,
    t_strain: f64,
    t_stress: f64,
    t_tangent: f64,
}

impl EppGap {
    fn new(e: f64, fy: f64, gap: f64, damage: bool) -> Self {
        EppGap {
            e,
            fy,
            gap,
            eta: 0.0,
            damage,
            min_strain: gap,
            max_strain: fy / e + gap,
            t_strain: 0.0,
            t_stress: 0.0,
            t_tangent: 0.0,
        }
    }

    fn set_trial(&mut self, strain: f64) {
        self.t_strain = strain;
        if strain > self.max_strain {
            self.t_stress = self.fy + (strain - self.gap - self.fy / self.e) * self.eta * self.e;
            self.t_tangent = self.eta * self.e;
        } else if strain < self.min_strain {
            self.t_stress = 0.0;
            self.t_tangent = 0.0;
        } else {
            self.t_stress = self.e * (strain - self.min_strain);
            self.t_tangent = self.e;
        }
    }

    fn commit(&mut self) {
        let s = self.t_strain;
        if s > self.max_strain {
            self.max_strain = s;
            self.min_strain = s - self.t_stress / self.e;
        } else if s < self.min_strain && s > self.gap && !self.damage {
            self.max_strain = (s - self.eta * self.gap) / (1.0 - self.eta) + self.fy / self.e;
            self.min_strain = s;
        }
    }
}

/// Elongations: targets in units of `unit`, each reached in 1–5 equal steps.
fn expand(path: &[(f64, usize)], unit: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let mut last = 0.0;
    for &(target, n) in path {
        let t = target * unit;
        for i in 1..=n {
            out.push(last + (t - last) * i as f64 / n as f64);
        }
        last = t;
    }
    out
}

fn growth(damage: bool) -> SlackGrowth {
    if damage {
        SlackGrowth::Permanent
    } else {
        SlackGrowth::Recentering
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Random elongation paths (−2 … 4 times slack + yield elongation): force, tangent and
    /// engagement equal the independent ElasticPPGap's, for both slack-growth rules, with and
    /// without a yield force (no yield = ElasticPPGap with fy = 1e300); the step dissipation is
    /// ≥ 0 and nonzero only on yielding steps; the force is never negative.
    #[test]
    fn equals_elastic_pp_gap(
        k in 1e4f64..1e9, slack in 0.0f64..0.1, fy in prop::option::of(1e3f64..1e7), damage: bool,
        path in proptest::collection::vec((-2.0f64..4.0, 1usize..6), 1..40),
    ) {
        let law = Restrainer::new(k, slack, fy, growth(damage)).unwrap();
        let fy_ref = fy.unwrap_or(1e300);
        let mut reference = EppGap::new(k, fy_ref, slack, damage);
        let unit = slack + fy.map_or(0.05, |f| f / k);
        let mut state = law.initial_state();
        for e in expand(&path, unit) {
            let r = law.response(e, &state);
            reference.set_trial(e);
            let scale = fy.unwrap_or(0.0).max(reference.t_stress.abs()).max(k * unit);
            prop_assert!((r.force - reference.t_stress).abs() <= 1e-12 * scale,
                "e = {e}: restrainer {}, ElasticPPGap {}", r.force, reference.t_stress);
            prop_assert_eq!(r.tangent, reference.t_tangent, "tangent at e = {}", e);
            prop_assert_eq!(r.engaged, reference.t_stress > 0.0);
            prop_assert!(r.force >= 0.0 && r.dissipation >= 0.0);
            if r.dissipation > 0.0 {
                prop_assert!(fy.is_some() && r.force == fy.unwrap());
            }
            state = r.trial;
            reference.commit();
            prop_assert!((state.slack - reference.min_strain).abs() <= 1e-12 * unit);
        }
    }

    /// Below the initial slack the force is exactly zero (with zero tangent) on any path,
    /// whatever has happened before: the slack never shrinks below its initial value.
    #[test]
    fn zero_force_below_the_slack(
        k in 1e4f64..1e9, slack in 0.0f64..0.1, fy in prop::option::of(1e3f64..1e7), damage: bool,
        path in proptest::collection::vec((-2.0f64..4.0, 1usize..6), 1..40),
    ) {
        let law = Restrainer::new(k, slack, fy, growth(damage)).unwrap();
        let unit = slack + fy.map_or(0.05, |f| f / k);
        let mut el = RestrainerElement::new(law);
        for e in expand(&path, unit) {
            let r = el.trial(e);
            if e < slack {
                prop_assert_eq!(r.force, 0.0);
                prop_assert_eq!(r.tangent, 0.0);
                prop_assert!(!r.engaged);
            }
            el.commit(&r);
            prop_assert!(el.committed().slack >= slack);
        }
    }

    /// Without yield the cable is elastic: stored energy ½ k (e − s)² when taut (0 when slack),
    /// no dissipation, force k (e − s)⁺.
    #[test]
    fn elastic_cable_stores_half_k_stretch_squared(
        k in 1e4f64..1e9, slack in 0.0f64..0.1,
        path in proptest::collection::vec((-2.0f64..4.0, 1usize..6), 1..40),
    ) {
        let law = Restrainer::new(k, slack, None, SlackGrowth::Permanent).unwrap();
        let mut el = RestrainerElement::new(law);
        for e in expand(&path, slack + 0.05) {
            let r = el.trial(e);
            el.commit(&r);
            let stretch = (e - slack).max(0.0);
            prop_assert!((r.force - k * stretch).abs() <= 1e-12 * k * (stretch + slack + 0.05));
            let stored = 0.5 * k * stretch * stretch;
            prop_assert!((el.stored_energy() - stored).abs() <= 1e-12 * stored);
            prop_assert_eq!(el.dissipated(), 0.0);
        }
    }
}

/// Drives the element through `cycles` (0 → e_i → 0) in `n` steps per half; returns the
/// element and the trapezoidal work ∫ F de.
fn drive(law: Restrainer, peaks: &[f64], n: usize) -> (RestrainerElement, f64) {
    let mut el = RestrainerElement::new(law);
    let mut work = 0.0;
    let mut last = 0.0;
    for &peak in peaks {
        for &(from, to) in &[(last, peak), (peak, 0.0)] {
            for i in 1..=n {
                let e = from + (to - from) * i as f64 / n as f64;
                let (f0, e0) = (el.committed().force, el.committed().e);
                let r = el.trial(e);
                work += step_work(f0, r.force, e0, e);
                el.commit(&r);
            }
        }
        last = 0.0;
    }
    (el, work)
}

/// With yield, cycles 0 → e_i → 0 of growing peaks: the dissipation equals the closed form —
/// Permanent: fy (max e_i − s − fy/k), exactly for any step (the slack only grows, by the
/// plastic elongation); Recentering (fine steps): the slack returns to ≈ s on each unloading
/// below it, so every cycle dissipates fy (e_i − s − fy/k)⁺ — and the loop area ∫ F de (the
/// cable ends slack, so no stored energy is left) tends to it as the step shrinks.
#[test]
fn yielding_dissipation_equals_closed_form_and_loop_area() {
    let (k, s, fy) = (5.0e7, 0.03, 6.0e5); // yield elongation fy/k = 0.012 m
    let peaks = [0.035, 0.05, 0.045, 0.07, 0.06];
    let plastic = |p: f64| (p - s - fy / k).max(0.0);
    for growth in [SlackGrowth::Permanent, SlackGrowth::Recentering] {
        let law = Restrainer::new(k, s, Some(fy), growth).unwrap();
        let closed = match growth {
            SlackGrowth::Permanent => fy * plastic(0.07),
            SlackGrowth::Recentering => fy * peaks.iter().map(|&p| plastic(p)).sum::<f64>(),
        };
        let mut last_gap = f64::INFINITY;
        for n in [10usize, 100, 1000, 10000] {
            let (el, work) = drive(law, &peaks, n);
            assert_eq!(el.stored_energy(), 0.0, "the cable ends slack");
            let d = el.dissipated();
            let de = 0.07 / n as f64;
            match growth {
                SlackGrowth::Permanent => assert!(
                    (d - closed).abs() <= 1e-12 * closed,
                    "Permanent n={n}: D = {d}, closed form {closed}"
                ),
                // each unloading recovers the slack only down to the last step above s
                SlackGrowth::Recentering => assert!(
                    (d - closed).abs() <= fy * de * peaks.len() as f64 * 1.000001,
                    "Recentering n={n}: D = {d}, closed form {closed}"
                ),
            }
            // loop area vs dissipation: the only discrepancy is at steps crossing the slack
            // or the yield point, each at most fy·Δe
            let gap = (work - d).abs();
            assert!(
                gap <= 4.0 * fy * de * peaks.len() as f64,
                "{growth:?} n={n}: W = {work}, D = {d}"
            );
            assert!(
                gap <= last_gap * 1.0001 || gap <= 1e-9 * closed,
                "{growth:?}: {gap} after {last_gap}"
            );
            last_gap = gap;
        }
        assert!(
            last_gap <= 1e-3 * closed,
            "{growth:?}: loop area off by {last_gap} of {closed}"
        );
    }
}

/// OpenSees' `noDamage` quirk, reproduced: a single step from taut past the initial slack
/// recovers nothing (the slack is reset only at commits strictly between the initial and the
/// current slack), whereas a step landing in between resets the slack to it.
#[test]
fn recentering_depends_on_where_the_unloading_step_lands() {
    let (k, s, fy) = (1.0e6, 0.02, 1.0e4); // fy/k = 0.01
    let law = Restrainer::new(k, s, Some(fy), SlackGrowth::Recentering).unwrap();
    let yielded = law.response(0.05, &law.initial_state()).trial;
    assert!((yielded.slack - 0.04).abs() < 1e-15);
    let jump = law.response(-0.01, &yielded).trial;
    assert_eq!(jump.slack, yielded.slack);
    let land = law.response(0.03, &yielded).trial;
    assert_eq!(land.slack, 0.03);
    assert!((land.yield_elongation - 0.04).abs() < 1e-15);
    let perm = Restrainer::new(k, s, Some(fy), SlackGrowth::Permanent).unwrap();
    let y = perm.response(0.05, &perm.initial_state()).trial;
    assert_eq!(perm.response(0.03, &y).trial.slack, y.slack);
}

/// Engagement episodes and the peak force are counted on commit; bad parameters name their key.
#[test]
fn engagements_peak_and_bad_parameters() {
    let law = Restrainer::new(1.0e6, 0.01, None, SlackGrowth::Permanent).unwrap();
    let mut el = RestrainerElement::new(law);
    for e in [
        0.0, 0.02, 0.03, 0.005, -0.01, 0.015, 0.0, 0.012, 0.011, 0.01, 0.02,
    ] {
        let r = el.trial(e);
        el.commit(&r);
    }
    // taut at 0.02–0.03, 0.015, 0.012–0.011, then (at e = 0.01 the force is 0) 0.02
    assert_eq!(el.engagements(), 4);
    assert!((el.peak_force() - 2.0e4).abs() < 1e-6);
    assert!(el.engaged());
    for (k, slack, fy, key) in [
        (0.0, 0.0, None, "k"),
        (f64::NAN, 0.0, None, "k"),
        (1.0, -0.01, None, "slack"),
        (1.0, f64::INFINITY, None, "slack"),
        (1.0, 0.0, Some(0.0), "fy"),
        (1.0, 0.0, Some(-1.0), "fy"),
        (1.0, 0.0, Some(f64::NAN), "fy"),
    ] {
        let e = Restrainer::new(k, slack, fy, SlackGrowth::default()).unwrap_err();
        assert_eq!(e.key(), key, "{e}");
        assert!(
            e.to_string().starts_with("invalid restrainer parameter `"),
            "{e}"
        );
    }
}
