//! The linear-spring law (`law = "linear"`), added through the contact-law registry: the
//! isolated two-mass collision against its closed form, the law against Kelvin–Voigt with
//! `c = 0`, and the registry/scenario wiring.

use pounding::contact_law::collision::{
    CollisionSettings, CollisionStatus, TwoMassImpact, simulate_collision,
};
use pounding::contact_law::registry::{self, DEFAULT_K};
use pounding::contact_law::{ContactLaw, KelvinVoigt, LawState, LinearSpring};
use pounding::sim::JointContact;
use pounding::sim::scenario::{LAW_NAMES, Scenario, ScenarioError};
use std::f64::consts::PI;

/// Closed form (spring–mass half period, derived by hand, not by the code): two free masses
/// meeting through `F = k δ` stay in contact for `T = π √(m_eff/k)` and separate with the
/// approach velocity reversed (`e = 1`, no dissipation); the peak penetration is `v √(m_eff/k)`.
#[test]
fn contact_law_linear_collision_matches_the_closed_form() {
    for (k, m1, m2, v1, v2) in [
        (1.0e9, 1.0e6, 4.0e5, 0.8, -0.3),
        (2.5e10, 3.0e5, 3.0e5, 0.2, 0.0),
        (1.0e7, 10.0, 1.0e3, 1.5, 0.5),
    ] {
        let law: ContactLaw = LinearSpring::new(k).unwrap().into();
        let p = TwoMassImpact::new(m1, m2, v1, v2).unwrap();
        let r = simulate_collision(&law, &p, &CollisionSettings::default()).unwrap();
        assert_eq!(r.status, CollisionStatus::Separated);
        let m = m1 * m2 / (m1 + m2);
        let t_exact = PI * (m / k).sqrt();
        eprintln!(
            "linear k={k:e}: T = {:e} (exact {t_exact:e}, h = {:e}), e - 1 = {:e}",
            r.contact_duration,
            r.step,
            r.restitution - 1.0
        );
        // RK4 with h = T/4000 has a global error O((ω h)^4) = (π/4000)^4 ≈ 4e-13 relative and
        // the integrator refines the separation instant inside the last step (measured: 1e-14);
        // 1e-9 leaves margin and still fails for a one-step location error (2.5e-4).
        assert!(
            (r.contact_duration - t_exact).abs() <= 1e-9 * t_exact,
            "duration {} vs {t_exact} (h = {})",
            r.contact_duration,
            r.step
        );
        // Elastic: e = 1 up to the same RK4 error (measured |e - 1| ≈ 3e-15).
        assert!((r.restitution - 1.0).abs() < 1e-9, "e = {}", r.restitution);
        let dm = (v1 - v2) * (m / k).sqrt();
        assert!(
            (r.peak_penetration - dm).abs() < 1e-6 * dm,
            "peak {} vs {dm}",
            r.peak_penetration
        );
        // Momentum conserved.
        let p0 = m1 * v1 + m2 * v2;
        let p1 = m1 * r.velocities[0] + m2 * r.velocities[1];
        assert!((p1 - p0).abs() <= 1e-9 * (m1 * v1.abs() + m2 * v2.abs()));
    }
}

/// `F = k δ` is Kelvin–Voigt without its dashpot: every evaluation agrees bit for bit, and the
/// parameter checks name `k`.
#[test]
fn contact_law_linear_equals_kelvin_without_damping() {
    let k = 3.0e9;
    let lin: ContactLaw = LinearSpring::new(k).unwrap().into();
    let kel: ContactLaw = KelvinVoigt::new(k, 0.0).unwrap().into();
    let mut s = LawState::default();
    for (d, dd) in [
        (-1e-3, 0.5),
        (2e-4, 0.5),
        (5e-4, 0.1),
        (3e-4, -0.4),
        (-1e-5, -0.4),
    ] {
        let a = lin.evaluate(&s, d, dd);
        let b = kel.evaluate(&s, d, dd);
        assert_eq!(a, b);
        s = a.state;
    }
    assert_eq!(lin.name(), "linear");
    assert!(!lin.is_history_dependent());
    assert_eq!(lin.backbone_stiffness(1e-3), k);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = LinearSpring::new(bad).unwrap_err().to_string();
        assert!(e.contains("parameter k ="), "{e}");
    }
}

/// The registry lists `linear` after the six names of the first release; `compare`'s default
/// list (`LAW_NAMES`) stays those six, in order.
#[test]
fn contact_law_registry_lists_linear_and_keeps_the_compare_defaults() {
    assert_eq!(
        LAW_NAMES,
        [
            "rigid",
            "kelvin",
            "hertz",
            "hertz-damp",
            "bilinear",
            "jankowski"
        ]
    );
    let names = registry::law_names();
    assert_eq!(&names[..6], &LAW_NAMES[..]);
    assert_eq!(names[6], "linear");
    let e = registry::entry("linear").unwrap();
    assert_eq!(e.keys, &["k"]);
}

/// `[contact] law = "linear"` builds the spring with `k` from the file (default `DEFAULT_K`);
/// a bad `k` is an error naming the key.
#[test]
fn contact_law_linear_from_the_scenario() {
    let s = Scenario::default().with_law("linear");
    let setup = s.build().unwrap();
    let JointContact::Compliance(cc) = &setup.problem.model.contact else {
        panic!("linear is a compliance law")
    };
    assert_eq!(
        cc.law,
        ContactLaw::Linear(LinearSpring::new(DEFAULT_K).unwrap())
    );
    assert_eq!(cc.law.describe()["law"], "linear");
}

#[test]
fn contact_law_linear_bad_k_names_the_key() {
    let s = Scenario::from_toml("[contact]\nlaw = \"linear\"\nk = 5.0e8\n", "t.toml").unwrap();
    let JointContact::Compliance(cc) = s.build().unwrap().problem.model.contact else {
        panic!("linear is a compliance law")
    };
    assert_eq!(
        cc.law,
        ContactLaw::Linear(LinearSpring::new(5.0e8).unwrap())
    );
    let s = Scenario::from_toml("[contact]\nlaw = \"linear\"\nk = -1.0\n", "t.toml").unwrap();
    let e = s.build().unwrap_err();
    let msg = e.to_string();
    assert!(matches!(e, ScenarioError::Invalid { .. }), "{msg}");
    assert!(
        msg.contains("parameter k = -1") && msg.contains("t.toml"),
        "{msg}"
    );
}

/// The registry is the one source of every law: each entry builds (with its defaults) a law of
/// its own name, and every key it lists is read by the generic `[contact]` section and handed to
/// that law. Checked per key: a value that is out of range for the law (`-1`) makes the build fail
/// quoting `= -1` or naming the key (`k1` alone: "give all of k1, k2, delta_y"), which it could
/// only do if the key reached the law's `build`.
#[test]
fn contact_law_registry_entries_build_their_laws_and_receive_their_keys() {
    for e in registry::LAWS {
        let s = Scenario::default().with_law(e.name);
        let JointContact::Compliance(cc) = s.build().unwrap().problem.model.contact else {
            panic!("{} is a compliance law", e.name)
        };
        assert_eq!(cc.law.name(), e.name);
        assert_eq!(cc.law.describe()["law"], e.name);
        for key in e.keys.iter().filter(|&&k| k != registry::CALIBRATION_KEY) {
            let text = format!("[contact]\nlaw = {:?}\n{key} = -1.0\n", e.name);
            let s = Scenario::from_toml(&text, "r.toml")
                .unwrap_or_else(|err| panic!("{}: {key} refused by the reader: {err}", e.name));
            let err = s.build().expect_err(key);
            assert!(
                err.to_string().contains("= -1") || err.keys().iter().any(|k| k.key == *key),
                "{}: {key}: {err}",
                e.name
            );
        }
    }
}

/// The `[contact]` section accepts exactly `law`, `friction_velocity` and the registry's keys:
/// an unknown key and a wrong type are refused while reading, naming the line.
#[test]
fn contact_section_keys_come_from_the_registry() {
    for k in registry::law_keys() {
        let v = if *k == registry::CALIBRATION_KEY {
            "\"numerical\""
        } else {
            "1.0"
        };
        let text = format!("[contact]\nlaw = \"kelvin\"\n{k} = {v}\n");
        assert!(Scenario::from_toml(&text, "k.toml").is_ok(), "{k}");
    }
    let e = Scenario::from_toml("[contact]\nlaw = \"kelvin\"\nfoo = 1.0\n", "u.toml").unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("line 3") && msg.contains("unknown field `foo`"),
        "{msg}"
    );
    let e = Scenario::from_toml("[contact]\nk = \"stiff\"\n", "t.toml").unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("line 2") && msg.contains("invalid type"),
        "{msg}"
    );
    let e = Scenario::from_toml("[contact]\ncalibration = 2.0\n", "c.toml").unwrap_err();
    assert!(e.to_string().contains("line 2"), "{e}");
}
