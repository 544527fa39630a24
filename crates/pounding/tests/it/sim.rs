//! Time-history simulation: linear response against an exact solution, Rayleigh damping,
//! isolated impacts against the single-impact law, energy balance, bad input.
#![allow(clippy::needless_range_loop)]

use nalgebra::{SMatrix, SVector};
use pounding::ground_motion::{GroundMotion, Record, el_centro_1940};
use pounding::pair::SArrangement;
use pounding::shape::Deck;
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
    assert_eq!(sol.t.len(), n + 1);
    let sys = crate::common::two_deck_system(model);
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
                assert!((sol.t[i] - grid[i]).abs() < 1e-9);
                let s = sol.q_row(i)[3 * j + d];
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
    let sys = crate::common::two_deck_system(&model);
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
    let sys = crate::common::two_deck_system(&model);
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
    // longest periods near 0.8 s and 1.2 s, taken from the model's eigen-analysis (see
    // sim_bearings::default_bridge_periods_come_from_the_model for the independent check)
    let t1 = 2.0 * std::f64::consts::PI / sys.frequencies[0][0];
    let t2 = 2.0 * std::f64::consts::PI / sys.frequencies[1][0];
    assert!(
        (t1 - 0.8).abs() < 0.05 * 0.8 && (t2 - 1.2).abs() < 0.05 * 1.2,
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
        SimError::Geometry(pounding::geometry::GeometryError::InvalidParameter {
            name, ..
        }) => name,
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

fn unit_deck(r: f64, beta_deg: f64) -> Deck {
    Deck {
        radius: r,
        angle: beta_deg.to_radians(),
        width: 10.0,
        thickness: 1.0,
        density: 1.0,
    }
}

/// Free decks (no bearings, no damping) in the S arrangement, ρt = 1.
fn free_model(r1: f64, b1: f64, r2: f64, b2: f64, gap: f64, mu: f64, eps: f64) -> SimModel {
    let arr = SArrangement {
        deck1: unit_deck(r1, b1),
        deck2: unit_deck(r2, b2),
    };
    SimModel::with_corner_bearings(arr, gap, 0.0, 0.0, 0.0, mu, eps, 1.0)
}

/// `q` of the joint-anchored pose (spec §5.2): deck j turned by θ_j about its face midpoint.
fn joint_anchored_q(arr: &SArrangement, th1: f64, th2: f64) -> [f64; 6] {
    let p1 = arr.deck1.mass_properties();
    let p2 = arr.deck2.mass_properties();
    let g1 = p1.centroid; // G⁰ − M⁰ = (R1 − X1, Y1) (spec §4)
    let g2 = -p2.centroid; // (−R2 + X2, −Y2)
    let d1 = pounding::math::rotate(&g1, th1) - g1;
    let d2 = pounding::math::rotate(&g2, th2) - g2;
    [d1.x, d1.y, th1, d2.x, d2.y, th2]
}

/// Isolated oblique impact: deck 1 (rotated −5°) flies with velocity (vx, −1) m/s into the
/// resting deck 2 (rotated 2°); no bearings, no ground motion. Reference: the single-impact law of
/// the `impact` work item (geometry::configuration, contact::force_directions, analytic::single_impact)
/// at the exact contact configuration. Returns (relative error of u⁺, sim mode, reference mode).
fn isolated_impact(vx: f64, dt: f64) -> (f64, String, String, f64) {
    isolated_impact_law(vx, dt, 0.5, 0.5).0
}

/// [`isolated_impact`] with friction `mu` and restitution `eps`; also the solution and the
/// reference's kinetic-energy change `ΔT`.
fn isolated_impact_law(
    vx: f64,
    dt: f64,
    mu: f64,
    eps: f64,
) -> (
    (f64, String, String, f64),
    pounding::sim::bridge::BridgeSolution,
    f64,
) {
    use pounding::analytic::{ImpactLaw, single_impact};
    use pounding::contact::{delassus_with, force_directions};
    use pounding::geometry::{ContactCase, SigmaMode};
    let (th1, th2) = ((-5f64).to_radians(), 2f64.to_radians());
    let arr = SArrangement {
        deck1: unit_deck(100.0, 60.0),
        deck2: unit_deck(100.0, 60.0),
    };
    let cfg = arr
        .configuration(ContactCase::Deck1Inner, th1, th2, SigmaMode::Exact)
        .unwrap();
    assert!(cfg.first_contact);
    let gap = cfg.h + 31.0 / 3.0 * 1e-3; // M_1 starts ~1 cm above the contact position
    let model = free_model(100.0, 60.0, 100.0, 60.0, gap, mu, eps);
    let v = nalgebra::Vector2::new(vx, -1.0);
    // Start deck 1 displaced by −v t* so that at t* its face midpoint is exactly at (0, h): the
    // contact configuration is then the spec's joint-anchored one (spec §5.2, §15 table).
    // t* = (31/3) ms lies 1/3 of a step after a grid point for every dt = 1 ms / 4^k.
    let t_star = 31.0 / 3.0 * 1e-3;
    let mut q0 = joint_anchored_q(&arr, th1, th2);
    q0[0] -= vx * t_star;
    let u0 = [v.x, v.y, 0.0, 0.0, 0.0, 0.0];
    let w = force_directions(&cfg);
    let (p1, p2) = (arr.deck1.mass_properties(), arr.deck2.mass_properties());
    let g = delassus_with(&p1, &p2, &w);
    // spec §15, first row (R = 100, β = 60°, θ = (−5°, 2°), deck1-inner, ρt = 1)
    assert!((g.nn / 2.784789492e-03 - 1.0).abs() < 1e-8);
    assert!((g.nt / 2.022511840e-03 - 1.0).abs() < 1e-8);
    assert!((g.tt / 6.619671336e-03 - 1.0).abs() < 1e-8);
    let gn = w.gamma_n(&u0);
    let gt = w.gamma_t(&u0);
    let law = ImpactLaw::new(mu, eps).unwrap();
    let refi = single_impact(&g, &law, gn, gt);
    let minv = [
        1.0 / p1.mass,
        1.0 / p1.mass,
        1.0 / p1.inertia,
        1.0 / p2.mass,
        1.0 / p2.mass,
        1.0 / p2.inertia,
    ];
    let u_ref: Vec<f64> = (0..6)
        .map(|i| {
            u0[i] + minv[i] * (w.w_n[i] * refi.normal_impulse + w.w_t[i] * refi.tangential_impulse)
        })
        .collect();
    let problem = SimProblem {
        model,
        ground: GroundMotion::none(),
        q0,
        u0,
    };
    let settings = SimSettings {
        dt,
        duration: Some(t_star + 0.003),
        history_stride: 1000000,
        ..SimSettings::default()
    };
    let sol = simulate(&problem, &settings).unwrap();
    assert_eq!(sol.status, SimStatus::Completed);
    assert_eq!(
        sol.summary.impacts, 1,
        "vx = {vx}, dt = {dt}: {:?}",
        sol.impacts
    );
    assert_eq!(sol.impacts.len(), 1);
    let imp = &sol.impacts[0];
    assert_eq!(imp.contact, ContactCase::Deck1Inner);
    assert!(
        (imp.time - t_star).abs() <= dt * 1.000001,
        "{} vs {t_star}",
        imp.time
    );
    let u_end = sol.u_rows().last().unwrap();
    // scale: per-component velocity scale (translations ~|v|, rotations ~|v|/k)
    let k = (p1.inertia / p1.mass).sqrt();
    let scale = [1.0, 1.0, 1.0 / k, 1.0, 1.0, 1.0 / k];
    let err = (0..6)
        .map(|i| (u_end[i] - u_ref[i]).abs() / (scale[i] * v.norm()))
        .fold(0.0, f64::max);
    let ln_err = (imp.impulse_n - refi.normal_impulse).abs() / refi.normal_impulse;
    // contact dissipation equals the kinetic-energy loss of the impact (no other forces)
    let dt_ref = pounding::analytic::energy_change(gn, gt, &refi);
    let e = sol.summary.final_energy;
    assert!(
        (e.contact + dt_ref).abs() <= 0.01 * dt_ref.abs() + 1e-12,
        "{} vs {}",
        e.contact,
        -dt_ref
    );
    assert!(
        sol.summary.energy_balance_error < 1e-12,
        "{}",
        sol.summary.energy_balance_error
    );
    (
        (
            err.max(ln_err),
            imp.mode.name().to_string(),
            refi.mode.name().to_string(),
            refi.normal_impulse,
        ),
        sol,
        dt_ref,
    )
}

/// Energy created at a contact (issue 12): the spec's §11 example (θ = (−5°, 2°), deck1-inner,
/// μ = 1, ε_N = 1, `γ_T⁻/γ_N⁻ = 0.726`: the Newton–Coulomb impact gains energy, by `ΔT` of the
/// closed-form single impact) through `simulate` gives exactly one `contact_energy_created`
/// warning of that amount; the same impact with ε_N = 0.5 (a loss, spec: −68 %) gives none.
#[test]
fn energy_created_at_a_contact_is_a_warning() {
    use pounding::contact::force_directions;
    use pounding::geometry::{ContactCase, SigmaMode};
    use pounding::sim::output::{Layout, run_warnings};
    let arr = SArrangement {
        deck1: unit_deck(100.0, 60.0),
        deck2: unit_deck(100.0, 60.0),
    };
    let cfg = arr
        .configuration(
            ContactCase::Deck1Inner,
            (-5f64).to_radians(),
            2f64.to_radians(),
            SigmaMode::Exact,
        )
        .unwrap();
    let w = force_directions(&cfg);
    // u⁻ = (vx, −1, 0, 0, 0, 0): γ_T = 0.726 γ_N
    let r = 0.726;
    let vx = (w.w_t[1] - r * w.w_n[1]) / (w.w_t[0] - r * w.w_n[0]);
    let (_, sol, dt_ref) = isolated_impact_law(vx, 1e-4, 1.0, 1.0);
    assert!(dt_ref > 0.0, "the closed form gains energy: {dt_ref}");
    let warn = run_warnings(Layout::TwoDecks, &sol);
    assert_eq!(warn.len(), 1, "{warn:?}");
    assert_eq!(warn[0].kind, "contact_energy_created");
    assert_eq!(warn[0].contact, "deck1-inner");
    assert!(
        (warn[0].amount / dt_ref - 1.0).abs() < 0.01,
        "{warn:?} vs {dt_ref}"
    );
    let text = pounding::sim::output::warnings_message(&warn).unwrap();
    assert!(
        text.contains("1 impacting contact ") && text.contains("deck1-inner"),
        "{text}"
    );
    let (_, lossy, dt_loss) = isolated_impact_law(vx, 1e-4, 1.0, 0.5);
    assert!(dt_loss < 0.0);
    assert!(run_warnings(Layout::TwoDecks, &lossy).is_empty());
}

#[test]
fn isolated_impact_converges_to_the_single_impact_law() {
    let mut modes = Vec::new();
    for vx in [-2.5, 0.3, 3.5] {
        let errs: Vec<f64> = [1e-3, 2.5e-4, 6.25e-5]
            .iter()
            .map(|&dt| {
                let (e, m_sim, m_ref, _) = isolated_impact(vx, dt);
                assert_eq!(m_sim, m_ref, "vx = {vx}, dt = {dt}");
                e
            })
            .collect();
        eprintln!("vx = {vx}: errors {errs:?}");
        // first order in dt (event location): dividing dt by 4 divides the error by ~4
        for w in errs.windows(2) {
            assert!((3.5..4.5).contains(&(w[0] / w[1])), "{errs:?}");
        }
        assert!(errs[2] < 2e-4, "{errs:?}");
        modes.push(isolated_impact(vx, 1e-4).2);
    }
    // the three cases exercise the three modes (spec §15: L = −1.09, U = 2.11 for μ = 0.5)
    assert_eq!(modes, ["slip-outward", "stick", "slip-inward"]);
}

#[test]
fn parallel_faces_double_impact_obeys_newton_at_both_ends() {
    // θ1 = θ2 = 0: both joint ends touch at once (spec §16, singular Delassus), frictional.
    let model = free_model(100.0, 60.0, 200.0, 90.0, 0.01, 0.5, 0.5);
    let v = 2.0;
    let problem = SimProblem {
        model: model.clone(),
        ground: GroundMotion::none(),
        q0: [0.0; 6],
        u0: [0.0, -v, 0.0, 0.0, 0.0, 0.0],
    };
    let settings = SimSettings {
        dt: 1e-4,
        duration: Some(0.0075),
        history_stride: 1,
        ..SimSettings::default()
    };
    let sol = simulate(&problem, &settings).unwrap();
    assert_eq!(sol.status, SimStatus::Completed, "{sol:?}");
    assert_eq!(sol.summary.impacts, 1);
    assert_eq!(sol.impacts.len(), 2, "{:?}", sol.impacts);
    for imp in &sol.impacts {
        assert!(imp.impulse_n > 0.0);
        assert!(
            (imp.gamma_n_post + 0.5 * imp.gamma_n_pre).abs() < 1e-9,
            "{imp:?}"
        );
    }
    // linear momentum along y is conserved (the impulses are internal)
    let sys = crate::common::two_deck_system(&model);
    let u = sol.u_rows().last().unwrap();
    let p = sys.mass[(1, 1)] * u[1] + sys.mass[(4, 4)] * u[4];
    assert!((p - sys.mass[(1, 1)] * -v).abs() < 1e-9 * sys.mass[(1, 1)] * v);
    assert!(sol.summary.energy_balance_error < 1e-12);
    assert!(sol.summary.final_energy.contact > 0.0);
    // Reference: the generic multi-contact impact solver (`pounding impact --problem`), two bodies
    // touching at both joint corners (±W/2, 0), normal +y into deck 1.
    use pounding::impact::{ContactSpec, ImpactProblem, ImpactSettings, RigidBody, solve};
    let arr = model.arrangement;
    let (p1, p2) = (arr.deck1.mass_properties(), arr.deck2.mass_properties());
    let v2 = |x: f64, y: f64| nalgebra::Vector2::new(x, y);
    let bodies = vec![
        RigidBody {
            name: "deck1".into(),
            mass: p1.mass,
            inertia: p1.inertia,
            position: p1.centroid,
            velocity: v2(0.0, -v),
            omega: 0.0,
        },
        RigidBody {
            name: "deck2".into(),
            mass: p2.mass,
            inertia: p2.inertia,
            position: -p2.centroid,
            velocity: v2(0.0, 0.0),
            omega: 0.0,
        },
    ];
    let contacts = [5.0, -5.0]
        .map(|x| ContactSpec {
            body_a: "deck1".into(),
            body_b: Some("deck2".into()),
            point: v2(x, 0.0),
            normal: v2(0.0, 1.0),
            mu: 0.5,
            restitution: 0.5,
        })
        .to_vec();
    let r = solve(
        &ImpactProblem::new(bodies, contacts).unwrap(),
        &ImpactSettings::default(),
    );
    assert!(r.post_velocity_unique);
    let u_ref = [
        r.bodies[0].velocity.x,
        r.bodies[0].velocity.y,
        r.bodies[0].omega,
        r.bodies[1].velocity.x,
        r.bodies[1].velocity.y,
        r.bodies[1].omega,
    ];
    let k = (p1.inertia / p1.mass).sqrt();
    for i in 0..6 {
        let scale = if i % 3 == 2 { v / k } else { v };
        assert!(
            (u[i] - u_ref[i]).abs() < 1e-4 * scale,
            "u[{i}] = {} vs {}",
            u[i],
            u_ref[i]
        );
    }
    assert!(
        u_ref[2].abs() > 1e-3 * v / k,
        "the curved decks turn after a straight impact"
    );
}

#[test]
fn default_scenario_runs_with_pounding_and_balanced_energy() {
    let problem = SimProblem::at_rest(SimModel::default_bridge(), el_centro_1940());
    let settings = SimSettings {
        history_stride: 10,
        ..SimSettings::default()
    };
    let sol = simulate(&problem, &settings).unwrap();
    let s = &sol.summary;
    eprintln!(
        "steps {} impacts {} rows {} lcp {} enum {} fail {} closing {} opening {} rot {:?} slip {} seat {:?} unseated {} at {:?} pen {} ebal {:e} final {:?} maxin {}",
        sol.steps,
        s.impacts,
        sol.impacts.len(),
        sol.lcp_solves,
        sol.lcp_enumeration_fallbacks,
        sol.lcp_failures,
        s.joints[0].peak_closing,
        s.joints[0].peak_opening,
        s.segments
            .iter()
            .map(|g| g.peak_rotation)
            .collect::<Vec<_>>(),
        s.joints[0].peak_slip,
        s.seats
            .iter()
            .map(|e| e.peak_displacement)
            .collect::<Vec<_>>(),
        s.unseated,
        s.unseating_time,
        s.peak_penetration,
        s.energy_balance_error,
        s.final_energy,
        s.max_input_energy
    );
    assert_eq!(sol.steps, 53710);
    assert_eq!(sol.status, SimStatus::Completed);
    assert!(s.impacts > 0, "the default scenario pounds");
    assert!(s.energy_balance_error < 1e-3, "{}", s.energy_balance_error);
    // closing exceeds g only by the O(h |γ_N⁻|) penetration of the velocity-level time stepping
    let vmax = sol
        .impacts
        .iter()
        .map(|i| -i.gamma_n_pre)
        .fold(0.0, f64::max);
    assert!(
        s.peak_penetration <= 1e-3 * vmax,
        "{} vs {vmax}",
        s.peak_penetration
    );
    assert!((s.joints[0].peak_closing - 0.05 - s.peak_penetration).abs() < 1e-12);
    assert!(
        s.joints[0].peak_closing > 0.05 - 1e-3,
        "contact means closing ≈ g"
    );
    // all impacts dissipate here (ε = 0.5, μ = 0.5: spec §11, no gain possible on the paper grid)
    assert!(s.final_energy.contact > 0.0);
}

#[test]
fn unseating_time_of_a_deck_pulling_away_from_the_joint() {
    // Deck 1 translates away from the joint (+y) at v, no bearings: its joint end slides off its
    // seat (inward normal +y) when v t = seat length; its far end moves along −(sin β, cos β)·v ŷ
    // < 0 (onto its seat); deck 2 is at rest.
    let mut model = free_model(100.0, 60.0, 100.0, 60.0, 0.05, 0.5, 0.5);
    model.seat_length = 0.0123;
    let v = 0.5;
    let p = SimProblem {
        model,
        ground: GroundMotion::none(),
        q0: [0.0; 6],
        u0: [0.0, v, 0.0, 0.0, 0.0, 0.0],
    };
    let s = SimSettings {
        dt: 1e-4,
        duration: Some(0.05),
        ..SimSettings::default()
    };
    let sol = simulate(&p, &s).unwrap();
    let sm = &sol.summary;
    assert!(sm.unseated);
    // deck 1's joint end is segment 1's end (the seats in bridge order: start, end per segment)
    assert_eq!(
        sm.unseated_end.as_deref(),
        Some("segment1-end"),
        "deck1-joint"
    );
    assert_eq!(sm.seats[1].end, "segment1-end");
    assert_eq!(sm.seats[0].end, "segment1-start");
    let t = sm.unseating_time.unwrap();
    assert!(
        t >= 0.0123 / v - 1e-9 && t <= 0.0123 / v + 1e-4 + 1e-9,
        "{t}"
    );
    assert!((sm.seats[1].peak_displacement - v * 0.05).abs() < 1e-12);
    assert!(
        (sm.seats[0].peak_displacement - 0.0).abs() < 1e-15,
        "far end moves onto its seat"
    );
    assert_eq!(sm.seats[2].peak_displacement, 0.0);
    assert!((sm.joints[0].peak_opening - v * 0.05).abs() < 1e-12);
    assert_eq!(sm.impacts, 0);
}

#[test]
fn energy_terms_agree_with_independent_quadrature_of_the_history() {
    // W_in = ∫ −(M r a_g)·u dt and D_viscous = ∫ uᵀ C u dt by the trapezoidal rule over the
    // full-resolution history, T and V from u and q: independent of the stepper's bookkeeping.
    let problem = SimProblem::at_rest(SimModel::default_bridge(), el_centro_1940());
    let sol = simulate(&problem, &SimSettings::default()).unwrap();
    let sys = crate::common::two_deck_system(&problem.model);
    let n = sol.t.len();
    assert_eq!(n, sol.steps + 1);
    let power_in = |i: usize| {
        let a = problem.ground.accel(sol.t[i]);
        let u = sol.u_row(i);
        -(sys.mass[(0, 0)] * (a.x * u[0] + a.y * u[1])
            + sys.mass[(3, 3)] * (a.x * u[3] + a.y * u[4]))
    };
    let power_visc = |i: usize| {
        let u = nalgebra::Vector6::from_column_slice(sol.u_row(i));
        u.dot(&(sys.damping * u))
    };
    let (mut w_in, mut d_v) = (0.0, 0.0);
    for i in 0..n - 1 {
        let dt = sol.t[i + 1] - sol.t[i];
        w_in += 0.5 * dt * (power_in(i) + power_in(i + 1));
        d_v += 0.5 * dt * (power_visc(i) + power_visc(i + 1));
    }
    let e = sol.summary.final_energy;
    let u = nalgebra::Vector6::from_column_slice(sol.u_rows().last().unwrap());
    let q = nalgebra::Vector6::from_column_slice(sol.q_rows().last().unwrap());
    assert!((0.5 * u.dot(&(sys.mass * u)) - e.kinetic).abs() < 1e-9 * e.input);
    assert!((0.5 * q.dot(&(sys.stiffness * q)) - e.potential).abs() < 1e-9 * e.input);
    eprintln!("W_in {} vs {w_in}; D_v {} vs {d_v}", e.input, e.viscous);
    assert!(
        (w_in - e.input).abs() < 1e-3 * e.input,
        "{w_in} vs {}",
        e.input
    );
    assert!(
        (d_v - e.viscous).abs() < 1e-3 * e.viscous,
        "{d_v} vs {}",
        e.viscous
    );
    // contact dissipation = the sum of the per-contact values in the impact list (no sustained
    // contact in this run: every LCP step is an impact)
    assert_eq!(sol.lcp_solves, sol.summary.impacts);
    let dc: f64 = sol.impacts.iter().map(|r| r.energy_dissipated).sum();
    assert!((dc - e.contact).abs() < 1e-9 * e.contact);
}

#[test]
fn plastic_impact_then_sustained_contact_stays_closed_without_drift() {
    // ε = 0, parallel faces (two contacts with a singular Delassus matrix every step), deck 2
    // four times stiffer than deck 1: after the plastic impact deck 2's bearings push deck 1, so
    // the joint stays closed for many steps (sustained contact, not impacts).
    let arr = SArrangement {
        deck1: unit_deck(100.0, 60.0),
        deck2: unit_deck(100.0, 60.0),
    };
    let m = arr.deck1.mass_properties().mass;
    let k1 = m * 4.0 * std::f64::consts::PI.powi(2) / 4.0; // T = 1 s with 4 bearings
    let model = SimModel::with_corner_bearings(arr, 0.01, k1, 4.0 * k1, 0.0, 0.5, 0.0, 1.0);
    let v = 0.2;
    let p = SimProblem {
        model,
        ground: GroundMotion::none(),
        q0: [0.0; 6],
        u0: [0.0, -v, 0.0, 0.0, 0.0, 0.0],
    };
    let dt = 1e-3;
    let s = SimSettings {
        dt,
        duration: Some(1.0),
        ..SimSettings::default()
    };
    let sol = simulate(&p, &s).unwrap();
    let sm = &sol.summary;
    assert_eq!(sol.status, SimStatus::Completed);
    assert_eq!(sol.lcp_failures, 0);
    // the first impact closes both ends at once; the curved decks then rock (a straight impact
    // turns them), so a few smaller impacts follow
    assert!(
        sol.impacts.len() >= 2 && sol.impacts[1].impact == 1,
        "{:?}",
        sol.impacts
    );
    assert!(
        sol.lcp_solves > sm.impacts + 50,
        "sustained contact: {} LCP steps",
        sol.lcp_solves
    );
    let vmax = sol
        .impacts
        .iter()
        .map(|i| -i.gamma_n_pre)
        .fold(0.0, f64::max);
    for imp in &sol.impacts {
        assert!(
            imp.gamma_n_post.abs() < 1e-9 * v,
            "plastic: γ_N⁺ = 0, got {}",
            imp.gamma_n_post
        );
    }
    // no drift into the other deck while in contact: overlap bounded by the impact step's h v / 2
    assert!(
        sm.peak_penetration <= 0.5 * dt * vmax + 1e-9,
        "{} vs {vmax}",
        sm.peak_penetration
    );
    let closed = sol
        .end_gaps
        .chunks_exact(2)
        .filter(|g| g[0].min(g[1]) < 1e-6)
        .count();
    assert!(closed > 50, "joint closed during {closed} steps");
    assert!(sm.energy_balance_error < 1e-12);
    assert!(sm.final_energy.contact > 0.0);
}

#[test]
fn varied_bridges_and_strong_motions_keep_the_invariants() {
    // Deterministic spread of geometries, laws and intensities (incl. ε = 1, μ = 1, where an
    // impact may gain energy, spec §11): every LCP solved, discrete energy balance exact,
    // overlap bounded by h |γ_N⁻|, impacts only with P_N > 0 and γ_N⁻ < −1 mm/s.
    let cases = [
        // R1, β1, R2, β2, k1, k2, mu, eps, scale, incidence°
        (100.0, 60.0, 100.0, 60.0, 2.02e7, 8.97e6, 0.5, 0.5, 3.0, 0.0),
        (200.0, 120.0, 100.0, 90.0, 3.0e7, 1.0e7, 1.0, 0.9, 2.0, 30.0),
        (
            100.0, 90.0, 200.0, 60.0, 1.0e7, 4.0e7, 0.25, 1.0, 2.5, -45.0,
        ),
        (60.0, 30.0, 60.0, 30.0, 5.0e6, 1.5e7, 0.0, 0.0, 2.0, 90.0),
        (150.0, 45.0, 80.0, 100.0, 8.0e6, 2.0e7, 1.5, 0.7, 3.0, 10.0),
    ];
    for (i, &(r1, b1, r2, b2, k1, k2, mu, eps, scale, inc)) in cases.iter().enumerate() {
        let deck = |r: f64, b: f64| Deck {
            radius: r,
            angle: f64::to_radians(b),
            width: 10.0,
            thickness: 0.5,
            density: 2500.0,
        };
        let arr = SArrangement {
            deck1: deck(r1, b1),
            deck2: deck(r2, b2),
        };
        let model = SimModel::with_corner_bearings(arr, 0.03, k1, k2, 0.05, mu, eps, 0.3);
        let mut gm = el_centro_1940();
        gm.scale_x = scale;
        gm.scale_y = scale;
        gm.incidence = f64::to_radians(inc);
        let s = SimSettings {
            dt: 2e-3,
            duration: Some(12.0),
            history_stride: 50,
            ..SimSettings::default()
        };
        let sol = simulate(&SimProblem::at_rest(model, gm), &s).unwrap();
        let sm = &sol.summary;
        eprintln!(
            "case {i}: impacts {} rows {} lcp {} enum {} fail {} pen {:.2e} ebal {:.1e} Dc {:.3e} seat {:.3} unseated {:?}",
            sm.impacts,
            sol.impacts.len(),
            sol.lcp_solves,
            sol.lcp_enumeration_fallbacks,
            sol.lcp_failures,
            sm.peak_penetration,
            sm.energy_balance_error,
            sm.final_energy.contact,
            sm.peak_seat_displacement,
            sm.unseating_time
        );
        assert_eq!(sol.status, SimStatus::Completed, "case {i}");
        assert_eq!(sol.lcp_failures, 0, "case {i}");
        assert!(sm.impacts > 0, "case {i}: strong motion, small gap");
        assert!(
            sm.energy_balance_error < 1e-10,
            "case {i}: {}",
            sm.energy_balance_error
        );
        let vmax = sol
            .impacts
            .iter()
            .map(|r| -r.gamma_n_pre)
            .fold(0.0, f64::max);
        assert!(
            sm.peak_penetration <= s.dt * vmax + 1e-6,
            "case {i}: {} vs {vmax}",
            sm.peak_penetration
        );
        for r in &sol.impacts {
            assert!(
                r.impulse_n > 0.0 && r.gamma_n_pre < -1e-3,
                "case {i}: {r:?}"
            );
            // Newton's law holds with equality for an impacting contact that receives impulse
            assert!(
                (r.gamma_n_post + eps * r.gamma_n_pre).abs() < 1e-8 * (1.0 + r.gamma_n_pre.abs()),
                "case {i}: {r:?}"
            );
            // Coulomb cone
            assert!(
                r.impulse_t.abs() <= mu * r.impulse_n * (1.0 + 1e-9) + 1e-9,
                "case {i}: {r:?}"
            );
        }
        assert_eq!(sm.unseated, sm.peak_seat_displacement > 0.3);
    }
}
