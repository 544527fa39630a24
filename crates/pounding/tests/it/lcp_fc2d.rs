//! The block Gauss–Seidel solver of the 2-D frictional contact problem
//! ([`pounding::lcp::fc2d`]): hand solutions of one contact, agreement with Lemke on the
//! problem's LCP form, redundant contacts, and a stiff chain.

use pounding::lcp::fc2d::{Fc2dSettings, residual, solve_nsgs};
use pounding::lcp::{LcpProblem, LcpStatus, Lemke, LemkeSettings};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn solve(g: &[Vec<f64>], b: &[f64], mu: &[f64]) -> pounding::lcp::fc2d::Fc2dSolution {
    let s = solve_nsgs(g, b, mu, &Fc2dSettings::default());
    assert!(s.converged, "residual {:e}", s.residual);
    assert!(residual(&s.p, &s.gamma, b, mu) <= 1e-8);
    s
}

#[test]
fn one_contact_separates_sticks_or_slips_as_by_hand() {
    let g = vec![vec![2.0, 0.0], vec![0.0, 1.0]];
    // receding: no impulse
    let s = solve(&g, &[0.5, 3.0], &[0.3]);
    assert_eq!(s.p, vec![0.0, 0.0]);
    // approaching with a small tangential velocity: sticks, P = −G⁻¹ b
    let s = solve(&g, &[-1.0, 0.1], &[0.3]);
    assert!(
        (s.p[0] - 0.5).abs() < 1e-15 && (s.p[1] + 0.1).abs() < 1e-15,
        "{:?}",
        s.p
    );
    assert!(s.gamma[0].abs() < 1e-15 && s.gamma[1].abs() < 1e-15);
    // a large tangential velocity: slips, P_T = −μ P_N, γ_T = 0.5 − 0.15 > 0
    let s = solve(&g, &[-1.0, 0.5], &[0.3]);
    assert!(
        (s.p[0] - 0.5).abs() < 1e-15 && (s.p[1] + 0.15).abs() < 1e-15,
        "{:?}",
        s.p
    );
    assert!((s.gamma[1] - 0.35).abs() < 1e-15);
    // frictionless
    let s = solve(&g, &[-1.0, 0.5], &[0.0]);
    assert_eq!(s.p, vec![0.5, 0.0]);
}

/// `G = Wᵀ M⁻¹ W` of `n` random contacts on `bodies` planar bodies (3 DOF each, unit masses).
fn random_problem(rng: &mut ChaCha8Rng, n: usize, bodies: usize) -> (Vec<Vec<f64>>, Vec<f64>) {
    let m = 3 * bodies;
    let w: Vec<Vec<f64>> = (0..2 * n)
        .map(|_| (0..m).map(|_| rng.random_range(-1.0..1.0)).collect())
        .collect();
    let g = (0..2 * n)
        .map(|i| {
            (0..2 * n)
                .map(|j| (0..m).map(|d| w[i][d] * w[j][d]).sum())
                .collect()
        })
        .collect();
    let b = (0..2 * n).map(|_| rng.random_range(-1.0..1.0)).collect();
    (g, b)
}

/// The same problem as the LCP of size `3n` the rigid stepper gives Lemke: `z = (P_N, P_T + μ
/// P_N, λ)`; returns `P`.
fn lemke(g: &[Vec<f64>], b: &[f64], mu: &[f64]) -> Option<Vec<f64>> {
    let n = mu.len();
    let m = 3 * n;
    let mut a = vec![0.0; m * m];
    let mut q = vec![0.0; m];
    for i in 0..n {
        for j in 0..n {
            a[i * m + j] = g[i][j] - g[i][n + j] * mu[j];
            a[i * m + n + j] = g[i][n + j];
            a[(n + i) * m + j] = g[n + i][j] - g[n + i][n + j] * mu[j];
            a[(n + i) * m + n + j] = g[n + i][n + j];
        }
        a[(n + i) * m + 2 * n + i] = 1.0;
        a[(2 * n + i) * m + i] = 2.0 * mu[i];
        a[(2 * n + i) * m + n + i] = -1.0;
        q[i] = b[i];
        q[n + i] = b[n + i];
    }
    let s = Lemke::new(LemkeSettings::default()).solve(&LcpProblem::new(a, q).unwrap());
    (s.status == LcpStatus::Solved).then(|| {
        let mut p = s.z[..2 * n].to_vec();
        for i in 0..n {
            p[n + i] -= mu[i] * p[i];
        }
        p
    })
}

#[test]
fn it_agrees_with_lemke_on_random_well_posed_problems() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut compared = 0;
    for case in 0..200 {
        let n = 1 + case % 8;
        // more DOFs than constraints: G positive definite, the velocities unique
        let (g, b) = random_problem(&mut rng, n, n + 1);
        let mu: Vec<f64> = (0..n).map(|_| rng.random_range(0.0..0.8)).collect();
        let s = solve(&g, &b, &mu);
        let Some(p) = lemke(&g, &b, &mu) else {
            continue;
        };
        compared += 1;
        let gl: Vec<f64> = (0..2 * n)
            .map(|i| b[i] + (0..2 * n).map(|j| g[i][j] * p[j]).sum::<f64>())
            .collect();
        let scale = gl.iter().chain(&b).fold(1e-300f64, |m, v| m.max(v.abs()));
        for i in 0..2 * n {
            assert!(
                (s.gamma[i] - gl[i]).abs() <= 1e-7 * scale,
                "case {case}: γ {:?} vs Lemke {:?}",
                s.gamma,
                gl
            );
        }
    }
    assert!(compared >= 150, "Lemke solved only {compared} of 200");
}

#[test]
fn redundant_contacts_share_an_impulse_and_give_one_velocity() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..50 {
        let (g, b) = random_problem(&mut rng, 3, 4);
        let mu = [0.2, 0.5, 0.0];
        let one = solve(&g, &b, &mu);
        // contact 0 twice (two corners at one point): a singular G
        let idx = [0usize, 0, 1, 2];
        let n2 = idx.len();
        let row = |k: usize| if k < n2 { idx[k] } else { 3 + idx[k - n2] };
        let g2: Vec<Vec<f64>> = (0..2 * n2)
            .map(|i| (0..2 * n2).map(|j| g[row(i)][row(j)]).collect())
            .collect();
        let b2: Vec<f64> = (0..2 * n2).map(|i| b[row(i)]).collect();
        let two = solve(&g2, &b2, &[0.2, 0.2, 0.5, 0.0]);
        let scale = one
            .gamma
            .iter()
            .chain(&b)
            .fold(1e-300f64, |m, v| m.max(v.abs()));
        for (k, &ik) in idx.iter().enumerate() {
            for (a, c) in [
                (two.gamma[k], one.gamma[ik]),
                (two.gamma[n2 + k], one.gamma[3 + ik]),
            ] {
                assert!((a - c).abs() <= 1e-7 * scale, "{a} vs {c}");
            }
        }
        let pn = two.p[0] + two.p[1];
        assert!(
            (pn - one.p[0]).abs() <= 1e-7 * one.p[0].abs().max(1e-12),
            "{pn} vs {}",
            one.p[0]
        );
    }
}

/// A chain of 21 unit masses on a line, the first moving at 1 m/s into the 20 others at rest and
/// in contact (frictionless, plastic): every contact closes and the chain moves as one body at
/// 1/21 m/s — the slowest case of Gauss–Seidel (the impulse crosses 20 contacts), solved.
#[test]
fn a_stiff_chain_of_twenty_contacts_moves_as_one_body() {
    let n = 20;
    // contact k between masses k and k+1: γ_k = u_k − u_{k+1} (closing positive → a sign: the
    // gap velocity is u_{k+1} − u_k), G = Wᵀ W with W_k = e_{k+1} − e_k; tangential rows apart
    let mut g = vec![vec![0.0; 2 * n]; 2 * n];
    for k in 0..n {
        g[k][k] = 2.0;
        if k + 1 < n {
            g[k][k + 1] = -1.0;
            g[k + 1][k] = -1.0;
        }
        g[n + k][n + k] = 1.0;
    }
    let mut b = vec![0.0; 2 * n];
    b[0] = -1.0; // mass 0 approaches mass 1 at 1 m/s
    let s = solve(&g, &b, &vec![0.0; n]);
    for k in 0..n {
        assert!(s.gamma[k].abs() < 1e-9, "contact {k}: γ {}", s.gamma[k]);
        // the impulse through contact k stops the masses before it: (k+1)/21 · ... exact P_k
        let want = (n - k) as f64 / (n + 1) as f64;
        assert!((s.p[k] - want).abs() < 1e-9, "P_{k} {} vs {want}", s.p[k]);
    }
}

/// A straight viaduct of `segments` segments with every joint and abutment gap zero (permanent
/// simultaneous contact at every corner: up to 4 candidates per joint) under El Centro, `mu` at
/// every contact, `duration` seconds at dt = 1 ms.
fn zero_gap_viaduct(
    segments: usize,
    mu: f64,
    duration: f64,
) -> pounding::sim::bridge::BridgeSolution {
    let mut text = format!(
        "[bridge]\ndamping = \"dashpots\"\ndamping_ratio = 0.05\ngap = 0.0\nmu = {mu}\neps_n = 0.6\n\
         seat_length = 0.4\n[abutment.start]\ngap = 0.0\n[abutment.end]\ngap = 0.0\n\
         [ground_motion]\nrecord_y = \"builtin:ELC180\"\nrecord_x = \"none\"\nscale_y = -1.0\n\
         [time]\ndt = 1e-3\nduration = {duration}\nhistory_every = 100\n"
    );
    for i in 0..segments {
        let t = [1.2, 0.5, 1.5, 0.9][i % 4];
        text.push_str(&format!(
            "[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = {}\nperiod_s = {t}\n",
            1.0e6 + 1e4 * (i % 3) as f64
        ));
    }
    let sc = pounding::sim::scenario::Scenario::from_toml(&text, "zero-gap.toml").unwrap();
    sc.build_bridge().unwrap().run().unwrap()
}

/// All gaps zero on a 20-segment straight viaduct (the degenerate impact LCPs of permanent
/// contact, where Lemke failed in about 4 of 10 steps with friction): no failure, the energy
/// balance closed.
#[test]
fn a_twenty_segment_viaduct_with_all_gaps_zero_runs_without_lcp_failures() {
    for mu in [0.0, 0.3] {
        let sol = zero_gap_viaduct(20, mu, 1.5);
        eprintln!(
            "mu {mu}: {:?}, {} solves, {} failures, {} impacts, balance {:e}",
            sol.status,
            sol.lcp_solves,
            sol.lcp_failures,
            sol.summary.impacts,
            sol.summary.energy_balance_error
        );
        assert_eq!(sol.status, pounding::sim::SimStatus::Completed, "mu {mu}");
        assert_eq!(sol.lcp_failures, 0);
        assert!(sol.lcp_solves > 1000);
        assert!(sol.summary.energy_balance_error < 1e-9);
    }
}
