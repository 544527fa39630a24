//! Time-history simulation: linear response against an exact solution, Rayleigh damping,
//! isolated impacts against the single-impact law, energy balance, bad input.
#![allow(clippy::needless_range_loop)]

use nalgebra::{SMatrix, SVector};
use pounding::geometry::{Deck, SArrangement};
use pounding::ground_motion::{GroundMotion, Record, el_centro_1940};
use pounding::sim::{SimError, SimModel, SimProblem, SimSettings, SimStatus, simulate};

type M10 = SMatrix<f64, 10, 10>;
type V10 = SVector<f64, 10>;

/// Exact response of one deck (3 DOF, `M q'' + C q' + K q = −M r a_g`) to a ground acceleration
/// that is piecewise linear on the grid `t_i = i Δ`: the state `z = (q, u, a_x, a_y, ȧ_x, ȧ_y)`
/// obeys `z' = A z` on each interval, so `z(t_{i+1}) = exp(Δ A) z(t_i)` with the slopes reset at
/// every grid point. Returns `q(t_i)` for `i = 0..=n`.
fn exact_deck_response(
    m: &SMatrix<f64, 3, 3>,
    k: &SMatrix<f64, 3, 3>,
    c: &SMatrix<f64, 3, 3>,
    ax: &[f64],
    ay: &[f64],
    delta: f64,
    n: usize,
) -> Vec<[f64; 3]> {
    let minv = m.try_inverse().unwrap();
    let mut a = M10::zeros();
    for i in 0..3 {
        a[(i, 3 + i)] = 1.0;
    }
    let mk = -(minv * k);
    let mc = -(minv * c);
    for i in 0..3 {
        for j in 0..3 {
            a[(3 + i, j)] = mk[(i, j)];
            a[(3 + i, 3 + j)] = mc[(i, j)];
        }
    }
    a[(3, 6)] = -1.0; // ü_x gets −a_x
    a[(4, 7)] = -1.0; // ü_y gets −a_y
    a[(6, 8)] = 1.0;
    a[(7, 9)] = 1.0;
    let phi = (a * delta).exp();
    let mut out = vec![[0.0; 3]];
    let mut z = V10::zeros();
    for i in 0..n {
        z[6] = ax[i];
        z[7] = ay[i];
        z[8] = (ax[i + 1] - ax[i]) / delta;
        z[9] = (ay[i + 1] - ay[i]) / delta;
        z = phi * z;
        out.push([z[0], z[1], z[2]]);
    }
    out
}

fn block(m: &nalgebra::Matrix6<f64>, j: usize) -> SMatrix<f64, 3, 3> {
    m.fixed_view::<3, 3>(3 * j, 3 * j).into_owned()
}

/// Simulated q on the record grid vs the exact solution: per-DOF max error / per-DOF peak, and
/// per-DOF relative error of the peak.
fn compare_with_exact(
    model: &SimModel,
    gm: &GroundMotion,
    dt: f64,
    duration: f64,
) -> ([f64; 6], [f64; 6]) {
    let delta = 0.01;
    let n = (duration / delta).round() as usize;
    let stride = (delta / dt).round() as usize;
    let settings = SimSettings {
        dt,
        duration: Some(duration),
        history_stride: stride,
        ..SimSettings::default()
    };
    let sol = simulate(&SimProblem::at_rest(model.clone(), gm.clone()), &settings).unwrap();
    assert_eq!(sol.status, SimStatus::Completed);
    assert_eq!(sol.lcp_solves, 0, "the large gap must keep the decks apart");
    assert_eq!(sol.history.t.len(), n + 1);
    let sys = model.linear_system().unwrap();
    let grid: Vec<f64> = (0..=n).map(|i| i as f64 * delta).collect();
    let ax: Vec<f64> = grid.iter().map(|&t| gm.accel(t).x).collect();
    let ay: Vec<f64> = grid.iter().map(|&t| gm.accel(t).y).collect();
    let mut err = [0.0f64; 6];
    let mut peak_err = [0.0f64; 6];
    for j in 0..2 {
        let ex = exact_deck_response(
            &block(&sys.mass, j),
            &block(&sys.stiffness, j),
            &block(&sys.damping, j),
            &ax,
            &ay,
            delta,
            n,
        );
        for d in 0..3 {
            let mut pe: f64 = 0.0;
            let mut ps: f64 = 0.0;
            let mut e: f64 = 0.0;
            for i in 0..=n {
                assert!((sol.history.t[i] - grid[i]).abs() < 1e-9);
                let s = sol.history.q[i][3 * j + d];
                pe = pe.max(ex[i][d].abs());
                ps = ps.max(s.abs());
                e = e.max((s - ex[i][d]).abs());
            }
            err[3 * j + d] = e / pe;
            peak_err[3 * j + d] = (ps - pe).abs() / pe;
        }
    }
    (err, peak_err)
}

fn far_apart(mut m: SimModel) -> SimModel {
    m.gap = 10.0;
    m
}

#[test]
fn linear_response_converges_at_second_order_to_the_exact_solution() {
    let model = far_apart(SimModel::default_bridge());
    let gm = el_centro_1940();
    let dts = [0.01, 0.005, 0.0025];
    let errs: Vec<[f64; 6]> = dts
        .iter()
        .map(|&dt| compare_with_exact(&model, &gm, dt, 8.0).0)
        .collect();
    for d in 0..6 {
        let r1 = errs[0][d] / errs[1][d];
        let r2 = errs[1][d] / errs[2][d];
        eprintln!(
            "dof {d}: errors {:e} {:e} {:e}, ratios {r1:.3} {r2:.3}",
            errs[0][d], errs[1][d], errs[2][d]
        );
        // second order: halving dt divides the error by 4
        assert!((3.6..4.4).contains(&r1), "dof {d}: ratio {r1}");
        assert!((3.6..4.4).contains(&r2), "dof {d}: ratio {r2}");
    }
}

#[test]
fn default_dt_peaks_within_0p1_percent_of_exact_full_record() {
    let model = far_apart(SimModel::default_bridge());
    let gm = el_centro_1940();
    let (err, peak) = compare_with_exact(&model, &gm, 1e-3, 53.71);
    eprintln!("max error / peak: {err:?}\npeak rel. error: {peak:?}");
    for d in 0..6 {
        assert!(peak[d] < 1e-3, "dof {d}: peak error {}", peak[d]);
        assert!(err[d] < 1e-3, "dof {d}: history error {}", err[d]);
    }
}

#[test]
fn rayleigh_damping_gives_the_ratio_at_the_two_lowest_modes() {
    let model = SimModel::default_bridge();
    let sys = model.linear_system().unwrap();
    for j in 0..2 {
        let m = block(&sys.mass, j);
        let k = block(&sys.stiffness, j);
        let c = block(&sys.damping, j);
        // independent modal analysis: M^{-1/2} K M^{-1/2}
        let mh = SMatrix::<f64, 3, 3>::from_diagonal(&m.diagonal().map(|x| 1.0 / x.sqrt()));
        let eig = (mh * k * mh).symmetric_eigen();
        let mut modes: Vec<(f64, SVector<f64, 3>)> = (0..3)
            .map(|i| (eig.eigenvalues[i].sqrt(), mh * eig.eigenvectors.column(i)))
            .collect();
        modes.sort_by(|a, b| a.0.total_cmp(&b.0));
        for (w, phi) in modes.iter().take(2) {
            let zeta = (phi.transpose() * c * phi)[0] / (2.0 * w * (phi.transpose() * m * phi)[0]);
            assert!((zeta - 0.05).abs() < 1e-10, "deck {}: ζ = {zeta}", j + 1);
        }
        let third = &modes[2];
        let z3 = (third.1.transpose() * c * third.1)[0]
            / (2.0 * third.0 * (third.1.transpose() * m * third.1)[0]);
        assert!(
            z3 > 0.05,
            "third mode gets more than ζ with Rayleigh damping: {z3}"
        );
    }
}

#[test]
fn stiffness_matches_spec_geometry_and_issue_periods() {
    // Spec §3 table (R = 100, β = 60°, W = 10): X_m = 82.768250, Y_m = 47.786272, k = √(I/m) = 29.847763.
    let model = SimModel::default_bridge();
    let sys = model.linear_system().unwrap();
    let m = 2500.0 * 0.5 * 1047.197551;
    assert!((sys.mass[(0, 0)] / m - 1.0).abs() < 1e-8);
    assert!((sys.mass[(2, 2)] / (m * 29.847763f64.powi(2)) - 1.0).abs() < 1e-7);
    // bearings at the four end corners, lever arms from the spec's centroid (deck 1, M_1 = 0)
    let (xm, ym) = (82.768250, 47.786272);
    let g = nalgebra::Vector2::new(100.0 - xm, ym);
    let b60 = 60f64.to_radians();
    let corners = [
        nalgebra::Vector2::new(5.0, 0.0),
        nalgebra::Vector2::new(-5.0, 0.0),
        nalgebra::Vector2::new(100.0 - 95.0 * b60.cos(), 95.0 * b60.sin()),
        nalgebra::Vector2::new(100.0 - 105.0 * b60.cos(), 105.0 * b60.sin()),
    ];
    let kb = 2.02e7;
    let mut k_ref = SMatrix::<f64, 3, 3>::zeros();
    for p in corners {
        let r = p - g;
        // energy ½ k |(u_x − θ r_y, u_y + θ r_x)|²
        let b = SMatrix::<f64, 2, 3>::new(1.0, 0.0, -r.y, 0.0, 1.0, r.x);
        k_ref += b.transpose() * b * kb;
    }
    let k1 = block(&sys.stiffness, 0);
    assert!((k1 - k_ref).norm() / k_ref.norm() < 1e-7, "{k1} vs {k_ref}");
    // translational periods near 0.8 s and 1.2 s (pure translation: T = 2π √(m / 4k))
    let t1 = 2.0 * std::f64::consts::PI * (m / (4.0 * 2.02e7)).sqrt();
    let t2 = 2.0 * std::f64::consts::PI * (m / (4.0 * 8.97e6)).sqrt();
    assert!(
        (t1 - 0.8).abs() < 0.01 && (t2 - 1.2).abs() < 0.01,
        "{t1} {t2}"
    );
    // deck 2 is deck 1 turned by 180° (translations flip sign, θ does not): K2 = S K1 S · k2/k1
    let k2 = block(&sys.stiffness, 1);
    let s = SMatrix::<f64, 3, 3>::from_diagonal(&SVector::<f64, 3>::new(-1.0, -1.0, 1.0));
    assert!((k2 * (2.02e7 / 8.97e6) - s * k1 * s).norm() / k1.norm() < 1e-9);
    assert!(k1[(0, 2)].abs() > 1e3, "rotation couples to translation");
}

#[test]
fn bad_input_is_an_error_naming_the_parameter() {
    let gm = el_centro_1940();
    let ok = SimProblem::at_rest(SimModel::default_bridge(), gm.clone());
    let name = |e: SimError| match e {
        SimError::InvalidParameter { name, .. } => name,
        other => panic!("{other:?}"),
    };
    let s = SimSettings {
        dt: 0.0,
        ..SimSettings::default()
    };
    assert_eq!(name(simulate(&ok, &s).unwrap_err()), "dt");
    let s = SimSettings {
        dt: f64::NAN,
        ..SimSettings::default()
    };
    assert_eq!(name(simulate(&ok, &s).unwrap_err()), "dt");
    let s = SimSettings {
        theta: 0.3,
        ..SimSettings::default()
    };
    assert_eq!(name(simulate(&ok, &s).unwrap_err()), "theta");
    let mut p = ok.clone();
    p.model.bearings1[2].stiffness = -1.0;
    assert!(
        name(simulate(&p, &SimSettings::default()).unwrap_err())
            .contains("bearing stiffness (deck 1, bearing 3)")
    );
    let mut p = ok.clone();
    p.model.seat_length = 0.0;
    assert_eq!(
        name(simulate(&p, &SimSettings::default()).unwrap_err()),
        "seat_length"
    );
    let mut p = ok.clone();
    p.model.restitution = 1.5;
    assert_eq!(
        name(simulate(&p, &SimSettings::default()).unwrap_err()),
        "eps_n"
    );
    let mut p = ok.clone();
    p.model.friction = -0.1;
    assert_eq!(
        name(simulate(&p, &SimSettings::default()).unwrap_err()),
        "mu"
    );
    let mut p = ok.clone();
    p.model.arrangement.deck2.radius = 4.0;
    assert_eq!(
        name(simulate(&p, &SimSettings::default()).unwrap_err()),
        "R2"
    );
    let mut p = ok.clone();
    p.q0[4] = f64::INFINITY;
    assert_eq!(
        name(simulate(&p, &SimSettings::default()).unwrap_err()),
        "q0[4]"
    );
    // no ground motion and no duration
    let p = SimProblem::at_rest(SimModel::default_bridge(), GroundMotion::none());
    assert_eq!(
        name(simulate(&p, &SimSettings::default()).unwrap_err()),
        "duration"
    );
    let _ = Record::uniform("x", 0.01, vec![0.0]).unwrap();
}

#[allow(dead_code)]
fn deck(r: f64, beta_deg: f64) -> Deck {
    Deck {
        radius: r,
        angle: beta_deg.to_radians(),
        width: 10.0,
        thickness: 1.0,
        density: 1.0,
    }
}

#[allow(dead_code)]
fn arrangement(r1: f64, b1: f64, r2: f64, b2: f64) -> SArrangement {
    SArrangement {
        deck1: deck(r1, b1),
        deck2: deck(r2, b2),
    }
}
