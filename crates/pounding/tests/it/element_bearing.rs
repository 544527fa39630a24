//! The bilinear bearing with kinematic hardening (`pounding::element::bearing`):
//! (a) along one line it is OpenSees' `Steel01` — checked against an independent stress-based
//! re-implementation of Steel01's algorithm written here (min/max band clamp of `σ_c + E0 Δε`,
//! no isotropic hardening); (b) in 2-D the plastic force stays in its disc, unloading is
//! elastic, the flow is normal, and the tangent is the derivative of the response; (c) energy:
//! return-mapping dissipation against closed forms (1-D cycle, 2-D circular orbit) and the
//! hysteresis loop area, and the documented trapezoidal-work identity.

use pounding::element::ElementError;
use pounding::element::bearing::{
    BearingElement, BearingLaw, BearingResponse, BearingState, BilinearBearing, LinearBearing,
};
use pounding::math::{Matrix2, Vector};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Independent 1-D Steel01 (OpenSees `SRC/material/uniaxial/Steel01.cpp`, a1 = a3 = 0 so both
/// shift factors stay 1): stress-based, trial from committed stress and strain.
struct Steel01 {
    fy: f64,
    e0: f64,
    b: f64,
    c_strain: f64,
    c_stress: f64,
    c_tangent: f64,
    t_strain: f64,
    t_stress: f64,
    t_tangent: f64,
}

impl Steel01 {
    fn new(fy: f64, e0: f64, b: f64) -> Self {
        Steel01 {
            fy,
            e0,
            b,
            c_strain: 0.0,
            c_stress: 0.0,
            c_tangent: e0,
            t_strain: 0.0,
            t_stress: 0.0,
            t_tangent: e0,
        }
    }

    fn set_trial(&mut self, strain: f64) {
        self.t_strain = self.c_strain;
        self.t_stress = self.c_stress;
        self.t_tangent = self.c_tangent;
        let d = strain - self.c_strain;
        if d.abs() <= f64::EPSILON {
            return;
        }
        self.t_strain = strain;
        let esh = self.b * self.e0;
        let band = self.fy * (1.0 - self.b); // shift factors are 1
        let hardening = esh * strain;
        let elastic = self.c_stress + self.e0 * d;
        let upper = hardening + band;
        let lower = hardening - band;
        let mut s = if upper < elastic { upper } else { elastic };
        if lower > s {
            s = lower;
        }
        self.t_stress = s;
        self.t_tangent = if (s - elastic).abs() < f64::EPSILON {
            self.e0
        } else {
            esh
        };
    }

    fn commit(&mut self) {
        self.c_strain = self.t_strain;
        self.c_stress = self.t_stress;
        self.c_tangent = self.t_tangent;
    }
}

/// A path: targets in units of the yield deformation, each reached in a number of equal steps.
fn path_1d() -> impl Strategy<Value = Vec<(f64, usize)>> {
    proptest::collection::vec((-6.0f64..6.0, 1usize..6), 1..40)
}

fn expand(path: &[(f64, usize)], scale: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let mut last = 0.0;
    for &(target, n) in path {
        let t = target * scale;
        for i in 1..=n {
            out.push(last + (t - last) * i as f64 / n as f64);
        }
        last = t;
    }
    out
}

fn bearing(k0: f64, fy: f64, b: f64) -> BilinearBearing {
    BilinearBearing::new(k0, fy, b).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// (a) Along any fixed line, the 2-D bearing's force (component along the line) equals
    /// Steel01's stress to 1e-12 of max(fy, |σ|), the transverse force vanishes, and the
    /// tangent along the line equals Steel01's (E0 elastic, b E0 yielding) — on random cyclic
    /// paths up to ±6 u_y with 1–5 substeps per leg.
    #[test]
    fn along_a_line_equals_steel01(
        k0 in 1e5f64..1e9, fy in 1e3f64..1e7, b in 0.0f64..0.9, angle in 0.0f64..(2.0 * PI),
        path in path_1d(),
    ) {
        let law = bearing(k0, fy, b);
        let d = Vector::new(angle.cos(), angle.sin());
        let mut steel = Steel01::new(fy, k0, b);
        let mut state = BearingState::default();
        for eps in expand(&path, fy / k0) {
            let r = law.response(&(eps * d), &state);
            steel.set_trial(eps);
            let tol = 1e-12 * fy.max(steel.t_stress.abs());
            let along = r.force.dot(&d);
            prop_assert!((along - steel.t_stress).abs() <= tol,
                "eps {eps}: bearing {along}, Steel01 {}", steel.t_stress);
            let transverse = r.force.x * d.y - r.force.y * d.x;
            prop_assert!(transverse.abs() <= tol, "transverse force {transverse}");
            let k_line = d.dot(&(r.tangent * d));
            prop_assert!((k_line - steel.t_tangent).abs() <= 1e-9 * k0,
                "tangent {k_line} vs Steel01 {}", steel.t_tangent);
            state = r.trial;
            steel.commit();
        }
    }

    /// (b) 2-D random paths: the plastic spring's force never leaves its disc of radius
    /// (1 − b) fy; every step's dissipation is ≥ 0 and equals f_p · Δu_p; plastic flow is
    /// normal (Δu_p ∥ f_p); the tangent is symmetric, positive definite, and matches a central
    /// finite difference of the response (away from the yield surface).
    #[test]
    fn two_d_disc_normality_and_tangent(
        k0 in 1e5f64..1e9, fy in 1e3f64..1e7, b in 0.0f64..0.9,
        legs in proptest::collection::vec((-5.0f64..5.0, -5.0f64..5.0, 1usize..5), 1..30),
    ) {
        let law = bearing(k0, fy, b);
        let uy = fy / k0;
        let radius = (1.0 - b) * fy;
        let mut state = BearingState::default();
        let mut last = Vector::zeros();
        for (x, y, n) in legs {
            let target = Vector::new(x, y) * uy;
            for i in 1..=n {
                let u = last + (target - last) * (i as f64 / n as f64);
                let r = law.response(&u, &state);
                let fp = law.plastic_spring_force(&r.trial);
                prop_assert!(fp.norm() <= radius * (1.0 + 1e-12), "|f_p| = {} > R = {radius}", fp.norm());
                prop_assert!(r.dissipation >= 0.0);
                let dup = r.trial.u_p - state.u_p;
                let work = fp.dot(&dup);
                prop_assert!((work - r.dissipation).abs() <= 1e-10 * (r.dissipation + radius * uy * 1e-6),
                    "f_p·Δu_p = {work}, dissipation {}", r.dissipation);
                let cross = fp.x * dup.y - fp.y * dup.x;
                prop_assert!(cross.abs() <= 1e-10 * fp.norm() * dup.norm() + 1e-300, "flow not normal");
                // total force = hardening spring + plastic spring
                let f = b * k0 * u + fp;
                prop_assert!((f - r.force).norm() <= 1e-12 * (fy + k0 * u.norm()));
                check_tangent(&law, &u, &state, &r)?;
                state = r.trial;
            }
            last = target;
        }
    }

    /// (b) Elastic unloading: from any state reached by a random path, a deformation increment
    /// that keeps the trial plastic force inside the disc changes the force by exactly
    /// k0 · Δu, keeps u_p and dissipates nothing.
    #[test]
    fn unloading_is_elastic(
        k0 in 1e5f64..1e9, fy in 1e3f64..1e7, b in 0.0f64..0.9,
        legs in proptest::collection::vec((-5.0f64..5.0, -5.0f64..5.0), 1..10),
        back in 0.0f64..1.0, turn in -1.5f64..1.5,
    ) {
        let law = bearing(k0, fy, b);
        let uy = fy / k0;
        let mut state = BearingState::default();
        for (x, y) in legs {
            state = law.response(&(Vector::new(x, y) * uy), &state).trial;
        }
        let fp = law.plastic_spring_force(&state);
        // a step against the current plastic force, turned by up to ±1.5 rad, small enough to stay inside
        let dir = if fp.norm() > 0.0 { -fp / fp.norm() } else { Vector::new(1.0, 0.0) };
        let (s, c) = turn.sin_cos();
        let dir = Vector::new(c * dir.x - s * dir.y, s * dir.x + c * dir.y);
        let du = dir * (back * uy * (1.0 - b).min(1.0) * 0.99);
        let trial_fp = fp + (1.0 - b) * k0 * du;
        prop_assume!(trial_fp.norm() <= (1.0 - b) * fy * (1.0 - 1e-9));
        let r = law.response(&(state.u + du), &state);
        let f0 = law.force(&state);
        prop_assert!(!r.yielding);
        prop_assert_eq!(r.dissipation, 0.0);
        prop_assert_eq!(r.trial.u_p, state.u_p);
        prop_assert!((r.force - (f0 + k0 * du)).norm() <= 1e-12 * (fy + k0 * state.u.norm()));
        prop_assert_eq!(r.tangent, Matrix2::identity() * k0);
    }

    /// (c) The documented trapezoidal-work identity, per step on random 2-D paths:
    /// ½ (f_k + f_{k+1})·Δu − ΔE = ½ (|f_tr| − R)(R + f_p,k · n)/k_e ∈ [0, D] on a plastic
    /// step, 0 on an elastic one (so the work-based dissipation is never negative).
    #[test]
    fn trapezoidal_work_identity(
        k0 in 1e5f64..1e9, fy in 1e3f64..1e7, b in 0.0f64..0.9,
        legs in proptest::collection::vec((-5.0f64..5.0, -5.0f64..5.0, 1usize..5), 1..30),
    ) {
        let law = bearing(k0, fy, b);
        let uy = fy / k0;
        let (ke, radius) = ((1.0 - b) * k0, (1.0 - b) * fy);
        let mut state = BearingState::default();
        let mut last = Vector::zeros();
        for (x, y, n) in legs {
            let target = Vector::new(x, y) * uy;
            for i in 1..=n {
                let u = last + (target - last) * (i as f64 / n as f64);
                let r = law.response(&u, &state);
                let f0 = law.force(&state);
                let work = 0.5 * (f0 + r.force).dot(&(u - state.u));
                let trap = work - (law.stored_energy(&r.trial) - law.stored_energy(&state));
                let fp0 = law.plastic_spring_force(&state);
                let f_tr = ke * (u - state.u_p);
                let expected = if r.yielding {
                    let nrm = f_tr.norm();
                    0.5 * (nrm - radius) * (fp0.dot(&(f_tr / nrm)) + radius) / ke
                } else {
                    0.0
                };
                let scale = fy * (uy + u.norm() + state.u.norm());
                prop_assert!((trap - expected).abs() <= 1e-11 * scale, "W − ΔE = {trap}, formula {expected}");
                prop_assert!(expected >= 0.0 && expected <= r.dissipation * (1.0 + 1e-12));
                state = r.trial;
            }
            last = target;
        }
    }
}

/// The tangent against a central difference of the response from the same committed state,
/// skipped within 1e-4 R of the yield surface (the response has a kink there).
fn check_tangent(
    law: &BilinearBearing,
    u: &Vector,
    state: &BearingState,
    r: &BearingResponse,
) -> Result<(), TestCaseError> {
    let ke = (1.0 - law.b()) * law.k0();
    let radius = law.plastic_force_radius();
    let trial = ke * (u - state.u_p);
    if (trial.norm() - radius).abs() <= 1e-4 * radius {
        return Ok(());
    }
    let h = 1e-6 * law.yield_deformation();
    let mut fd = Matrix2::zeros();
    for j in 0..2 {
        let mut e = Vector::zeros();
        e[j] = h;
        let col =
            (law.response(&(u + e), state).force - law.response(&(u - e), state).force) / (2.0 * h);
        fd.set_column(j, &col);
    }
    prop_assert!(
        (fd - r.tangent).norm() <= 1e-6 * law.k0(),
        "tangent {:?} vs finite difference {:?}",
        r.tangent,
        fd
    );
    prop_assert!((r.tangent - r.tangent.transpose()).norm() <= 1e-12 * law.k0());
    let eig = r.tangent.symmetric_eigenvalues();
    prop_assert!(eig.min() > 0.0 || (law.b() == 0.0 && eig.min() >= -1e-9 * law.k0()));
    Ok(())
}

/// One 1-D cycle u_a → −u_a → u_a (after loading 0 → u_a) in `n` steps per half: returns
/// (return-mapping dissipation over the cycle, trapezoidal work ∮ f du over the cycle).
fn cycle_1d(law: &BilinearBearing, ua: f64, n: usize) -> (f64, f64) {
    let mut el = BearingElement::new(BearingLaw::Bilinear(*law));
    let d = Vector::new(0.6, 0.8);
    let go = |el: &mut BearingElement, from: f64, to: f64| {
        let mut work = 0.0;
        for i in 1..=n {
            let u = from + (to - from) * i as f64 / n as f64;
            let f0 = el.force();
            let u0 = el.committed().u;
            let r = el.trial(&(u * d));
            work += 0.5 * (f0 + r.force).dot(&(r.trial.u - u0));
            el.commit(&r);
        }
        work
    };
    go(&mut el, 0.0, ua);
    let d0 = el.dissipated();
    let w = go(&mut el, ua, -ua) + go(&mut el, -ua, ua);
    (el.dissipated() - d0, w)
}

/// (c) A symmetric 1-D cycle of amplitude u_a > u_y: the EPP part travels plastically
/// 2 (u_a − u_y) in each half, so D = 4 (1 − b) fy (u_a − u_y) — exactly for any step count
/// (the turning points are on the plateau) — and the loop area ∮ f du (trapezoidal) tends to
/// it from below, with an error bounded by 2·(1−b) fy·Δu (two yield onsets per cycle).
#[test]
fn one_d_cycle_dissipation_equals_closed_form_and_loop_area() {
    for &(k0, fy, b) in &[
        (2.0e7, 1.0e5, 0.0),
        (4.0e8, 6.0e5, 0.1),
        (1.0e6, 3.0e3, 0.5),
    ] {
        let law = bearing(k0, fy, b);
        let uy = fy / k0;
        for &ratio in &[1.3, 3.0, 10.0] {
            let ua = ratio * uy;
            let closed = 4.0 * (1.0 - b) * fy * (ua - uy);
            let mut last_err = f64::INFINITY;
            for &n in &[7usize, 70, 700, 7000] {
                let (diss, work) = cycle_1d(&law, ua, n);
                assert!(
                    (diss - closed).abs() <= 1e-10 * closed,
                    "b={b} ua/uy={ratio} n={n}: D = {diss}, closed form {closed}"
                );
                let du = 2.0 * ua / n as f64;
                let err = work - diss;
                assert!(
                    err <= 1e-10 * closed && -err <= 2.0 * (1.0 - b) * fy * du * (1.0 + 1e-9),
                    "b={b} ua/uy={ratio} n={n}: loop area {work} vs D {diss}"
                );
                last_err = err.abs();
            }
            assert!(
                last_err <= 1e-3 * closed,
                "at 7000 steps the loop area is off by {last_err} of {closed}"
            );
        }
    }
}

/// (c) 2-D steady circular orbit |u| = u_a: the plastic displacement circles at radius
/// ρ = √(u_a² − u_y²) with f_p ⊥ u_p, so one revolution dissipates 2π (1 − b) fy ρ. The
/// return mapping (backward Euler) converges to it at first order in the angular step, and the
/// loop area ∮ f·du over the last revolution tends to the dissipation (measured at 40 revolutions).
#[test]
fn circular_orbit_dissipation_matches_closed_form() {
    let (k0, fy, b) = (5.0e7, 2.0e5, 0.2);
    let law = bearing(k0, fy, b);
    let uy = fy / k0;
    for &ratio in &[1.5f64, 4.0] {
        let ua = ratio * uy;
        let closed = 2.0 * PI * (1.0 - b) * fy * (ua * ua - uy * uy).sqrt();
        let (mut errs, mut loop_errs) = (Vec::new(), Vec::new());
        for &n in &[200usize, 800, 3200] {
            let mut el = BearingElement::new(BearingLaw::Bilinear(law));
            for i in 1..=n {
                let r = el.trial(&(Vector::new(ua, 0.0) * (i as f64 / n as f64)));
                el.commit(&r);
            }
            let cycles = 40;
            let (mut d_last, mut w_last) = (0.0, 0.0);
            for c in 0..cycles {
                let d0 = el.dissipated();
                let mut w = 0.0;
                for i in 1..=n {
                    let th = 2.0 * PI * i as f64 / n as f64;
                    let u = Vector::new(ua * th.cos(), ua * th.sin());
                    let (f0, u0) = (el.force(), el.committed().u);
                    let r = el.trial(&u);
                    w += 0.5 * (f0 + r.force).dot(&(u - u0));
                    el.commit(&r);
                }
                if c == cycles - 1 {
                    d_last = el.dissipated() - d0;
                    w_last = w;
                }
            }
            errs.push((d_last - closed).abs() / closed);
            loop_errs.push((w_last - d_last).abs() / closed);
        }
        eprintln!(
            "circular orbit u_a/u_y = {ratio}: relative error of D per revolution {errs:?}, \
             of the loop area against D {loop_errs:?} (n = 200, 800, 3200)"
        );
        // first order in the angular step: error × n about constant, and small at n = 3200
        for k in 1..3 {
            let r = errs[k - 1] / errs[k];
            assert!((3.0..5.0).contains(&r), "D error not first order: {errs:?}");
            let r = loop_errs[k - 1] / loop_errs[k];
            assert!(r > 3.0, "loop-area error does not shrink: {loop_errs:?}");
        }
        assert!(errs[2] < 1e-3, "{errs:?}");
        assert!(loop_errs[2] < 1e-3, "{loop_errs:?}");
    }
}

/// Bad parameters are refused with an error naming the key.
#[test]
fn bad_parameters_name_the_key() {
    let cases: &[(f64, f64, f64, &str)] = &[
        (0.0, 1.0, 0.1, "k0"),
        (-1.0, 1.0, 0.1, "k0"),
        (f64::NAN, 1.0, 0.1, "k0"),
        (f64::INFINITY, 1.0, 0.1, "k0"),
        (1.0, 0.0, 0.1, "fy"),
        (1.0, -5.0, 0.1, "fy"),
        (1.0, f64::INFINITY, 0.1, "fy"),
        (1.0, 1.0, 1.0, "b"),
        (1.0, 1.0, -0.01, "b"),
        (1.0, 1.0, f64::NAN, "b"),
    ];
    for &(k0, fy, b, key) in cases {
        let e = BilinearBearing::new(k0, fy, b).unwrap_err();
        assert_eq!(e.key(), key, "{e}");
        assert!(e.to_string().contains(&format!("`{key}`")), "{e}");
    }
    assert!(BilinearBearing::new(1.0, 1.0, 0.0).is_ok());
    let e: ElementError = LinearBearing::new(-1.0).unwrap_err();
    assert_eq!(e.key(), "k");
    assert_eq!(
        BilinearBearing::new(1.0, -5.0, 0.1)
            .unwrap_err()
            .to_string(),
        "invalid bilinear bearing parameter `fy` = -5: must be finite and > 0"
    );
}

/// The linear bearing through the same interface: f = k u, tangent k I, ½ k |u|², no
/// dissipation; a bilinear bearing below yield is the linear one with k = k0.
#[test]
fn linear_bearing_and_bilinear_below_yield_agree() {
    let lin = BearingLaw::Linear(LinearBearing::new(3.0e6).unwrap());
    let bil = BearingLaw::Bilinear(bearing(3.0e6, 1.0e5, 0.1));
    let u = Vector::new(0.01, -0.02); // |u| = 0.0224 < u_y = 0.0333
    let (rl, rb) = (
        lin.force_and_tangent(&u, &BearingState::default()),
        bil.force_and_tangent(&u, &BearingState::default()),
    );
    assert!((rl.force - Vector::new(3.0e4, -6.0e4)).norm() <= 1e-9);
    assert!((rl.force - rb.force).norm() <= 1e-9 && rl.tangent == rb.tangent);
    assert_eq!(rl.dissipation, 0.0);
    assert!((lin.stored_energy(&rl.trial) - 0.5 * 3.0e6 * u.norm_squared()).abs() <= 1e-9);
    assert!((lin.stored_energy(&rl.trial) - bil.stored_energy(&rb.trial)).abs() <= 1e-9);
    assert_eq!(lin.initial_stiffness(), bil.initial_stiffness());
}
