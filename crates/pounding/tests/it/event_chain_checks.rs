//! Checks of the N-deck event-exact reference ([`crate::event_chain`]) against hand-derived
//! closed forms, conservation laws, the energy balance and the two-deck reference.

use crate::event_chain::{Chain, ChainSolution, flight, viaduct_rigid_1d};
use pounding::ground_motion::Record;

/// No penetration anywhere on a grid of step `h`, and no tensile force in sustained contact.
fn assert_admissible(sol: &ChainSolution, h: f64) {
    let c = sol.chain();
    let n = c.n();
    let steps = (sol.t_end / h).round() as usize;
    let mut min_gap = f64::INFINITY;
    let mut min_force = f64::INFINITY;
    for s in 0..=steps {
        let t = (s as f64 * h).min(sol.t_end);
        let (x, _) = sol.at(t);
        for j in 0..=n {
            min_gap = min_gap.min(c.gap(j, &x));
        }
        let lam = sol.contact_forces(t);
        min_force = min_force.min(lam.iter().fold(f64::INFINITY, |a, b| a.min(*b)));
    }
    let mass: f64 = c.m.iter().sum();
    assert!(min_gap > -1e-12, "penetration {min_gap} m");
    assert!(
        min_force > -1e-9 * mass,
        "tensile contact force {min_force} N"
    );
    assert_eq!(sol.unresolved, 0, "contact LCP without a feasible set");
}

#[test]
fn chain_flight_matches_fine_rk4_with_and_without_springs() {
    for (beta, w2) in [(0.9, 81.0), (0.0, 0.0), (3.0, 400.0)] {
        let (f0, f1, u0, v0, t_end) = (0.7, -3.0, 0.02, -0.3, 0.5);
        let n = 20_000;
        let h = t_end / n as f64;
        let rhs = |t: f64, u: f64, v: f64| (v, f0 + f1 * t - beta * v - w2 * u);
        let (mut u, mut v) = (u0, v0);
        for i in 0..n {
            let t = i as f64 * h;
            let k1 = rhs(t, u, v);
            let k2 = rhs(t + h / 2.0, u + h / 2.0 * k1.0, v + h / 2.0 * k1.1);
            let k3 = rhs(t + h / 2.0, u + h / 2.0 * k2.0, v + h / 2.0 * k2.1);
            let k4 = rhs(t + h, u + h * k3.0, v + h * k3.1);
            u += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
            v += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        }
        let (uc, vc) = flight(beta, w2, u0, v0, f0, f1, t_end);
        assert!((u - uc).abs() < 1e-12, "β {beta} ω² {w2}: {u} vs {uc}");
        assert!((v - vc).abs() < 1e-11, "β {beta} ω² {w2}: {v} vs {vc}");
    }
}

#[test]
fn chain_viaduct_smoke() {
    let (chain, rec) = viaduct_rigid_1d();
    let sol = chain.solve(Some(&rec), 1.0, &[0.0; 3], &[0.0; 3], 20.0);
    eprintln!("{:?}", sol.summary());
    eprintln!(
        "{:?} joins {} releases {}",
        sol.energy(),
        sol.joins,
        sol.releases
    );
    assert_admissible(&sol, 1e-3);
}
