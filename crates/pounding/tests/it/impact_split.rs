//! Generic impacts whose tangential split is not unique report the minimum-norm split, flagged.

use pounding::impact::{self, ContactSpec, ImpactProblem, ImpactSettings, ImpactStatus, RigidBody};
use pounding::impact_report::problem_report;
use pounding::math::Vector;

/// A square block (m = I = 1) sliding into a wall at x = −1 and striking it with its two left
/// corners `(−1, ±1)`; the wall's normal is `+x`. Both contacts share the tangential column
/// (the moment arm of a `y` impulse about the centroid is `x = −1` at both corners), so only the
/// sum of the two friction impulses is determined.
fn block_on_wall(vx: f64, vy: f64, omega: f64, corners: &[f64]) -> ImpactProblem {
    let body = RigidBody {
        name: "block".into(),
        mass: 1.0,
        inertia: 1.0,
        position: Vector::new(0.0, 0.0),
        velocity: Vector::new(vx, vy),
        omega,
    };
    let corner = |y: f64| ContactSpec {
        body_a: "block".into(),
        body_b: None,
        point: Vector::new(-1.0, y),
        normal: Vector::new(1.0, 0.0),
        mu: 1.0,
        restitution: 0.5,
    };
    ImpactProblem::new(vec![body], corners.iter().map(|&y| corner(y)).collect()).unwrap()
}

/// Two symmetric contacts, both sticking: the equal split (each carries half of the total
/// friction impulse), flagged non-unique; the velocities are those of the LCP solution (they do
/// not depend on the split), and the momentum balance holds.
#[test]
fn two_symmetric_contacts_report_the_equal_split_flagged() {
    let p = block_on_wall(-1.0, 0.3, 0.0, &[1.0, -1.0]);
    let s = impact::solve(&p, &ImpactSettings::default());
    assert_eq!(s.status, ImpactStatus::Solved);
    assert!(!s.tangential_split_unique);
    let (c0, c1) = (s.contacts[0], s.contacts[1]);
    assert_eq!(c0.mode.name(), "stick");
    assert_eq!(c1.mode.name(), "stick");
    let total = c0.tangential_impulse + c1.tangential_impulse;
    assert!(total.abs() > 0.1, "friction acts: {total}");
    assert!(
        (c0.tangential_impulse - c1.tangential_impulse).abs() <= 1e-12 * total.abs(),
        "{c0:?} {c1:?}"
    );
    // Independent check by hand: both corners active with γ_N⁺ = −ε γ_N⁻ = 0.5 at `y = ±1`
    // (γ_N = v_x − ω y) give ω⁺ = 0; sticking corners (γ_T = v_y − ω) then give v_y⁺ = 0, so
    // the total friction impulse is m |v_y⁻| = 0.3 whatever the split.
    let b = s.bodies[0];
    assert!(b.omega.abs() < 1e-12, "{b:?}");
    assert!(b.velocity.y.abs() < 1e-12, "{b:?}");
    assert!((total.abs() - 0.3).abs() < 1e-12, "{total}");
    let r = problem_report(&p);
    assert_eq!(r.tangential_split_unique, Some(false));
    let json = serde_json::to_value(&r).unwrap();
    assert_eq!(json["tangential_split_unique"], serde_json::json!(false));
    assert!(
        r.summary()
            .iter()
            .any(|l| l.contains("tangential split: NOT unique"))
    );
}

/// A non-degenerate pair of contacts (a corner on the wall and the opposite corner on a floor:
/// the two friction columns differ) and a single contact: unique, flagged so.
#[test]
fn a_generic_problem_keeps_its_split_and_is_flagged_unique() {
    let mut two = block_on_wall(-1.0, -1.0, 0.0, &[1.0]);
    let floor = ContactSpec {
        body_a: "block".into(),
        body_b: None,
        point: Vector::new(1.0, -1.0),
        normal: Vector::new(0.0, 1.0),
        mu: 0.3,
        restitution: 0.5,
    };
    let (bodies, mut contacts) = (two.bodies().to_vec(), vec![]);
    contacts.push(ContactSpec {
        body_a: "block".into(),
        body_b: None,
        point: Vector::new(-1.0, 1.0),
        normal: Vector::new(1.0, 0.0),
        mu: 1.0,
        restitution: 0.5,
    });
    contacts.push(floor);
    two = ImpactProblem::new(bodies, contacts).unwrap();
    for p in [two, block_on_wall(-1.0, 0.3, 0.0, &[1.0])] {
        let s = impact::solve(&p, &ImpactSettings::default());
        assert_eq!(s.status, ImpactStatus::Solved);
        assert!(s.tangential_split_unique, "{s:?}");
        assert_eq!(problem_report(&p).tangential_split_unique, Some(true));
        assert!(
            !problem_report(&p)
                .summary()
                .iter()
                .any(|l| l.contains("tangential split"))
        );
    }
}
