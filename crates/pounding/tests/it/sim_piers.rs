//! Piers under joints: a cap body on a column, the decks' bearings on the cap, the seats
//! measured from the cap. A linear pier bridge in free vibration against its exact modal
//! solution (independent `M`, `K` written here), a yielding column's force on its bilinear
//! envelope with the energy balance closed, the seats relative to the cap from the histories,
//! and the scenario's refusals.

use nalgebra::{DMatrix, DVector};
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::Scenario;

/// Two straight segments (L = 30 m, W = 12 m), bearings at ±5 m at both ends (`k` each, no
/// dashpot), a pier under the joint; no abutments, no ground motion.
fn two_spans(pier: &str, extra: &str) -> String {
    let seg = |m: f64| {
        format!(
            "[[segment]]\nshape = \"straight\"\nL = 30.0\nwidth = 12.0\nmass = {m:e}\n\
             bearing_stiffness = 4.0e6\n\
             bearing_points = [[0.0, -5.0], [0.0, 5.0], [30.0, -5.0], [30.0, 5.0]]\n{extra}\n"
        )
    };
    format!(
        "[bridge]\ndamping_ratio = 0.0\ngap = 0.5\nmu = 0.0\nseat_length = 0.4\n\n{}{}\
         [[pier]]\ncap_mass = 2.0e5\n{pier}\n\n[contact]\nlaw = \"rigid\"\n\n\
         [ground_motion]\nrecord_y = \"none\"\nrecord_x = \"none\"\n\n\
         [time]\ndt = 1e-4\nduration = 4.0\nhistory_every = 1\n",
        seg(1.0e6),
        seg(1.2e6)
    )
}

fn run(text: &str, v0: &[(usize, f64)]) -> BridgeSolution {
    let setup = Scenario::from_toml(text, "piers.toml")
        .expect("reads")
        .build_bridge()
        .expect("builds");
    let mut problem = setup.problem.clone();
    for &(i, v) in v0 {
        problem.u0[i] = v;
    }
    let sol = pounding::sim::simulate(&problem, &setup.settings).expect("runs");
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    sol
}

/// The chain runs along −y: the y coordinates of segment 1, segment 2 and the cap are
/// `q[1]`, `q[4]`, `q[7]` (segments `(x, y, θ)`, then the cap's `(x, y)`).
const Y: [usize; 3] = [1, 4, 7];

/// Free vibration along the chain of the linear system
/// `M = diag(m1, m2, m_c)`, `K = [[4k, 0, −2k], [0, 4k, −2k], [−2k, −2k, 4k + k0]]` (two bearings
/// of each segment on the ground, two on the cap, the column `k0`), from a velocity of segment 1:
/// the exact solution `q(t) = Σ_i φ_i (φ_iᵀ M v0) sin(ω_i t) / ω_i`. The θ-method with θ = ½ is
/// second order: at h = 1e-4 s the histories agree to 2e-4 of the amplitude; the segments do not
/// turn or move across the chain.
#[test]
fn linear_pier_bridge_is_its_modal_solution() {
    let (k, k0, m): (f64, f64, [f64; 3]) = (4.0e6, 8.0e7, [1.0e6, 1.2e6, 2.0e5]);
    let sol = run(&two_spans("joint = 1\nk0 = 8.0e7", ""), &[(Y[0], 0.1)]);
    let mm = DMatrix::from_diagonal(&DVector::from_row_slice(&m));
    let kk = DMatrix::from_row_slice(
        3,
        3,
        &[
            4.0 * k,
            0.0,
            -2.0 * k,
            0.0,
            4.0 * k,
            -2.0 * k,
            -2.0 * k,
            -2.0 * k,
            4.0 * k + k0,
        ],
    );
    let s = DMatrix::from_fn(3, 3, |i, j| kk[(i, j)] / (m[i] * m[j]).sqrt());
    let eig = s.symmetric_eigen();
    let v0 = DVector::from_row_slice(&[0.1, 0.0, 0.0]);
    let exact = |t: f64| -> DVector<f64> {
        let mut q = DVector::zeros(3);
        for i in 0..3 {
            let w = eig.eigenvalues[i].sqrt();
            // mass-normalised mode φ = M^{-1/2} ψ
            let phi = DVector::from_fn(3, |r, _| eig.eigenvectors[(r, i)] / m[r].sqrt());
            let a = phi.dot(&(&mm * &v0));
            q += phi * (a * (w * t).sin() / w);
        }
        q
    };
    let mut worst = 0.0f64;
    let mut amp = 0.0f64;
    for (r, &t) in sol.t.iter().enumerate() {
        let row = sol.q_row(r);
        let e = exact(t);
        for (d, &i) in Y.iter().enumerate() {
            worst = worst.max((row[i] - e[d]).abs());
            amp = amp.max(e[d].abs());
        }
        for i in [0, 2, 3, 5, 6] {
            assert!(
                row[i].abs() < 1e-12,
                "coordinate {i} moves at t = {t}: {}",
                row[i]
            );
        }
    }
    assert!(amp > 1e-3, "the bridge moves ({amp})");
    assert!(
        worst < 2e-4 * amp,
        "max |q − q_exact| = {worst:e} of {amp:e}"
    );
    // piers.csv: the cap's displacement and the column's force −k0 u_c on it
    let tables = sol.tables();
    let piers = tables
        .iter()
        .find(|t| t.name == "piers")
        .expect("piers.csv");
    let cols = piers.columns.len();
    for (r, row) in piers.values.chunks(cols).enumerate() {
        let yc = sol.q_row(r)[Y[2]];
        assert_eq!(row[2], yc);
        assert!((row[4] + k0 * yc).abs() <= 1e-9 * k0 * amp);
    }
}

/// A yielding column: its force stays on or inside the bilinear envelope
/// `|f − b k0 u| ≤ (1 − b) F_y` at every step, it yields and dissipates energy, the energy
/// balance closes, and each end's seat displacement on the pier is its displacement relative to
/// the cap (from the every-step histories, to rounding).
#[test]
fn yielding_column_and_seats_on_the_cap() {
    let (k0, fy, b) = (8.0e7, 3.0e5, 0.05);
    let pier = format!("joint = 1\nk0 = {k0:e}\nfy = {fy:e}\nb = {b}\ndamping = 2.0e5");
    let sol = run(
        &two_spans(&pier, "bearing_damping = 5.0e4"),
        &[(Y[0], 0.4), (Y[1], -0.2)],
    );
    let s = &sol.summary;
    assert_eq!(s.piers.len(), 1);
    let p = &s.piers[0];
    assert!(p.yielded, "the column yields");
    assert!(p.hysteretic_energy > 0.0, "{}", p.hysteretic_energy);
    assert!(s.energy_balance_error < 1e-9, "{}", s.energy_balance_error);
    let tables = sol.tables();
    let piers = tables
        .iter()
        .find(|t| t.name == "piers")
        .expect("piers.csv");
    let cols = piers.columns.len();
    let mut peak = 0.0f64;
    for row in piers.values.chunks(cols) {
        let (u, f) = (row[2], -row[4]);
        assert!(
            (f - b * k0 * u).abs() <= (1.0 - b) * fy * (1.0 + 1e-9),
            "{u} {f}"
        );
        peak = peak.max(f.abs());
    }
    assert!((peak - p.peak_column_force).abs() <= 1e-9 * peak);
    // seats: segment 1's end (inward +y) and segment 2's start (inward −y) on the cap
    let seat = |name: &str| s.seats.iter().find(|e| e.end == name).expect("seat");
    let (mut end1, mut start2) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    for r in 0..sol.t.len() {
        let q = sol.q_row(r);
        end1 = end1.max(q[Y[0]] - q[Y[2]]);
        start2 = start2.max(-(q[Y[1]] - q[Y[2]]));
    }
    for (name, ours) in [("segment1-end", end1), ("segment2-start", start2)] {
        let e = seat(name);
        assert_eq!(e.support, "joint1");
        assert!(
            (e.peak_displacement - ours).abs() <= 1e-12,
            "{name}: {} vs {ours}",
            e.peak_displacement
        );
    }
}

/// Bad piers are refused naming the key and its line, before anything runs.
#[test]
fn bad_piers_are_refused_with_key_and_line() {
    let cases = [
        (
            "k0 = 8.0e7\njoint = 2",
            "pier[0].joint",
            "joints are numbered 1 to 1",
        ),
        ("k0 = 8.0e7", "pier[0].joint", "is required"),
        ("joint = 1\nk0 = -8.0e7", "pier[0].k0", "must be > 0"),
        (
            "joint = 1\nk0 = nan",
            "pier[0].k0",
            "must be finite and > 0",
        ),
        (
            "joint = 1\nk0 = 8.0e7\nb = 0.1",
            "pier[0].b",
            "give pier[0].fy too",
        ),
        (
            "joint = 1\nk0 = 8.0e7\nfy = 1e6\nb = 1.0",
            "pier[0].b",
            "[0, 1)",
        ),
        (
            "joint = 1\nk0 = 8.0e7\ndamping = -1.0",
            "pier[0].damping",
            ">= 0",
        ),
        ("joint = 1\nk0 = 8.0e7\nheight = 3.0", "height", "unknown"),
    ];
    for (pier, key, why) in cases {
        let text = two_spans(pier, "");
        let err = Scenario::from_toml(&text, "piers.toml")
            .and_then(|s| s.build_bridge())
            .expect_err(pier)
            .to_string();
        assert!(err.contains(key) && err.contains(why), "{pier}: {err}");
        // the line of the offending key (the table's for a missing one)
        let bad = if why == "is required" {
            "[[pier]]"
        } else {
            pier.lines().last().unwrap()
        };
        let line = text.lines().position(|l| l == bad).unwrap() + 1;
        assert!(
            err.contains(&format!("piers.toml:{line}")) || err.contains(&format!("line {line}")),
            "{pier}: not line {line} in {err}"
        );
    }
    // a cap without mass; a bearing midway between the ends of a segment at the pier
    let text = two_spans("joint = 1\nk0 = 8.0e7", "").replace("cap_mass = 2.0e5\n", "");
    let err = Scenario::from_toml(&text, "piers.toml").and_then(|s| s.build_bridge());
    assert!(
        err.expect_err("no mass")
            .to_string()
            .contains("pier[0].cap_mass is required")
    );
    let text = two_spans("joint = 1\nk0 = 8.0e7", "").replacen("[30.0, 5.0]]", "[15.0, 5.0]]", 1);
    let err = Scenario::from_toml(&text, "piers.toml")
        .and_then(|s| s.build_bridge())
        .expect_err("midway")
        .to_string();
    assert!(
        err.contains("segment[0].bearing_points") && err.contains("piers.toml:"),
        "{err}"
    );
}

/// `examples/bridge-p-1d-piers.toml` against OpenSees 3.7.1 (an independent OpenSeesPy model of
/// the same bridge written for this project: zeroLength elements, `Steel01` columns,
/// `ImpactMaterial` contacts, `Elastic` bearings with viscous dashpots, Newmark average
/// acceleration, Newton, dt = 2.5e-5 s; checked against dt = 5e-5 s). Per joint `(impacts, peak
/// force MN, peak closing m)`, per abutment `(impacts, peak force MN)`, per pier `(peak drift m,
/// peak column force MN)`. The decks' peak displacements are left out here: they depend on the
/// order of impacts (OpenSees: 0.0563, 0.0612, 0.0701 m at dt = 5e-5 s; 0.0520, 0.0611, 0.0503 m
/// at 2.5e-5 s; this example at 1e-4, 5e-5, 2.5e-5 s: 0.0528, 0.0611, 0.0580; 0.0557, 0.0611,
/// 0.0503; 0.0520, 0.0610, 0.0503 m).
/// Joints, abutments, piers of [`OS_RIGID_ABUTMENTS`].
type Figures = ([(usize, f64, f64); 2], [(usize, f64); 2], [(f64, f64); 2]);
const OS_RIGID_ABUTMENTS: Figures = (
    [(44, 43.652, 0.023837), (48, 45.257, 0.024350)],
    [(20, 45.469), (26, 42.915)],
    [(0.012869, 1.02951), (0.013231, 1.05847)],
);

/// The same bridge with gaps too wide to close (the piers, bearings and dashpots alone): per
/// pier `(peak drift m, residual drift along the chain m, peak column force MN)`, per deck the
/// peak displacement (m). OpenSees 3.7.1, dt = 2.5e-5 s; its x is the chain's direction toward
/// the end abutment, −y here.
const OS_NO_CONTACT: ([(f64, f64, f64); 2], [f64; 3]) = (
    [
        (0.053138, 0.0059455, 1.26102),
        (0.045910, 0.011825, 1.24946),
    ],
    [0.092988, 0.158552, 0.087420],
);

const BRIDGE_P: &str = include_str!("../../../../examples/bridge-p-1d-piers.toml");

/// Per joint `(impacts, peak force MN, peak closing m)` of OpenSees: impacts within ±3, force
/// and closing within 3 %.
fn check_joints(s: &pounding::sim::bridge::BridgeSummary, joints: &[(usize, f64, f64)]) {
    for (k, (j, r)) in s.joints.iter().zip(joints).enumerate() {
        let n = k + 1;
        assert!(
            j.impacts.abs_diff(r.0) <= 3,
            "joint {n}: {} impacts vs {}",
            j.impacts,
            r.0
        );
        within(
            &format!("joint {n} force"),
            j.peak_contact_force.unwrap() / 1e6,
            r.1,
            0.03,
        );
        within(&format!("joint {n} closing"), j.peak_closing, r.2, 0.03);
    }
}

/// Per pier `(peak drift m, residual drift along the chain m, column force MN)` of OpenSees (its
/// x is −y here): each pier yields, drift and residual within 5 %, column force within 3 %.
fn check_yielding_piers(s: &pounding::sim::bridge::BridgeSummary, piers: &[(f64, f64, f64)]) {
    for (p, r) in s.piers.iter().zip(piers) {
        let n = p.joint;
        assert!(p.yielded, "pier {n} yields");
        within(&format!("pier {n} drift"), p.peak_drift[1], r.0, 0.05);
        within(
            &format!("pier {n} residual"),
            -p.residual_drift[1],
            r.1,
            0.05,
        );
        within(
            &format!("pier {n} column"),
            p.peak_column_force / 1e6,
            r.2,
            0.03,
        );
    }
}

fn within(what: &str, ours: f64, reference: f64, rel: f64) {
    let e = (ours - reference).abs() / reference.abs();
    assert!(
        e <= rel,
        "{what}: {ours} vs OpenSees {reference} ({:.2} %)",
        e * 100.0
    );
}

fn run_text(text: &str) -> BridgeSolution {
    let sol = Scenario::from_toml(text, "bridge-p-1d-piers.toml")
        .and_then(|s| s.build_bridge())
        .expect("builds")
        .run()
        .expect("runs");
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    assert!(sol.summary.energy_balance_error < 1e-9);
    sol
}

/// Forces and closings within 3 %, drifts within 5 %, impacts within ±3 of OpenSees.
#[test]
fn bridge_p_piers_against_opensees() {
    let s = run_text(BRIDGE_P).summary;
    let (joints, abuts, piers) = OS_RIGID_ABUTMENTS;
    check_joints(&s, &joints);
    for (side, r) in abuts.iter().enumerate() {
        let a = s.abutments[side].as_ref().expect("abutment");
        assert!(
            a.impacts.abs_diff(r.0) <= 3,
            "abutment {side}: {} vs {}",
            a.impacts,
            r.0
        );
        within(
            &format!("abutment {side} force"),
            a.peak_contact_force.unwrap() / 1e6,
            r.1,
            0.03,
        );
    }
    for (p, r) in s.piers.iter().zip(piers) {
        within(
            &format!("pier {} drift", p.joint),
            p.peak_drift[1],
            r.0,
            0.05,
        );
        within(
            &format!("pier {} column", p.joint),
            p.peak_column_force / 1e6,
            r.1,
            0.03,
        );
        // no drift across the bridge beyond rounding (four simultaneous contact terms are
        // solved by LU, which need not treat mirror-image ends bit-equally: ~1e-30 m)
        assert!(
            !p.yielded && p.peak_drift[0] <= 1e-12 * p.peak_drift[1],
            "{} {:?}",
            p.yielded,
            p.peak_drift
        );
    }
    // the piers alone: the gaps opened wide, nothing else changed
    let wide = BRIDGE_P
        .replace("gap = 0.02", "gap = 0.5")
        .replace("gap = 0.04", "gap = 1.0");
    let s = run_text(&wide).summary;
    assert_eq!(s.impacts, 0);
    let (piers, decks) = OS_NO_CONTACT;
    check_yielding_piers(&s, &piers);
    for (i, (g, r)) in s.segments.iter().zip(decks).enumerate() {
        within(&format!("deck {}", i + 1), g.peak_displacement, r, 0.05);
    }
}

const BRIDGE_P_FULL: &str = include_str!("../../../../examples/bridge-piers-1d.toml");

/// `examples/bridge-piers-1d.toml` (bridge P with backwalls, backfill and piles) against the
/// OpenSees 3.7.1 figures computed for this project (zeroLength elements, `Steel01`,
/// `ImpactMaterial`, `HyperbolicGapMaterial`, `ElasticPP`, Newmark average acceleration,
/// dt = 5e-5 s, converged against 2.5e-5 s): contact, column, backfill and pile forces and joint
/// closings within 3 %, drifts, backwall and deck displacements within 5 %, impacts within ±3.
#[test]
fn bridge_p_with_backwalls_against_opensees() {
    let s = run_text(BRIDGE_P_FULL).summary;
    let joints = [(22, 40.26, 0.0228), (31, 43.78, 0.0239)];
    check_joints(&s, &joints);
    // impacts, contact force MN, backwall into the soil m, backfill MN, piles MN
    let abuts = [
        (29, 37.61, 0.0479, 3.778, 1.071),
        (19, 40.27, 0.0552, 3.948, 1.071),
    ];
    for (side, r) in abuts.iter().enumerate() {
        let a = s.abutments[side].as_ref().expect("abutment");
        let w = a.backwall.as_ref().expect("backwall");
        assert!(
            a.impacts.abs_diff(r.0) <= 3,
            "abutment {side}: {} vs {}",
            a.impacts,
            r.0
        );
        within(
            &format!("abutment {side} force"),
            a.peak_contact_force.unwrap() / 1e6,
            r.1,
            0.03,
        );
        within(
            &format!("abutment {side} backwall"),
            w.peak_displacement,
            r.2,
            0.05,
        );
        within(
            &format!("abutment {side} backfill"),
            w.peak_backfill_force.unwrap() / 1e6,
            r.3,
            0.03,
        );
        within(
            &format!("abutment {side} piles"),
            w.peak_pile_force.unwrap() / 1e6,
            r.4,
            0.03,
        );
    }
    // peak drift m, residual drift along the chain (OpenSees x = −y here) m, column force MN
    let piers = [(0.0183, -0.0036, 1.205), (0.0192, -0.0019, 1.207)];
    check_yielding_piers(&s, &piers);
    for (i, (g, r)) in s.segments.iter().zip([0.0862, 0.0961, 0.0964]).enumerate() {
        within(&format!("deck {}", i + 1), g.peak_displacement, r, 0.05);
    }
}

/// The same file under El Centro NS × 1.5 (only `scale_y` changed) against the independent
/// OpenSeesPy 3.7.1 model of it at the same dt (5e-5 s): joints `(impacts, MN, m)`, abutments
/// `(impacts, MN, wall m, backfill MN)`, piers `(drift m, column MN)`, decks (m). (Both programs
/// move with the step alike here: OpenSees' joint forces are 47.86 / 46.57 MN at 2.5e-5 s.)
#[test]
fn bridge_p_with_backwalls_under_another_motion() {
    let text = BRIDGE_P_FULL.replace("scale_y = -1.0", "scale_y = -1.5");
    let s = run_text(&text).summary;
    check_joints(&s, &[(30, 45.328, 0.02437), (31, 47.438, 0.02505)]);
    let abuts = [(23, 40.939, 0.09516, 4.503), (26, 41.613, 0.07857, 4.3255)];
    for (a, r) in s.abutments.iter().flatten().zip(abuts) {
        let w = a.backwall.as_ref().unwrap();
        assert!(a.impacts.abs_diff(r.0) <= 3, "{} vs {}", a.impacts, r.0);
        within(
            "abutment force",
            a.peak_contact_force.unwrap() / 1e6,
            r.1,
            0.03,
        );
        within("backwall", w.peak_displacement, r.2, 0.05);
        within("backfill", w.peak_backfill_force.unwrap() / 1e6, r.3, 0.03);
    }
    for (p, r) in s.piers.iter().zip([(0.06138, 1.27421), (0.06942, 1.28707)]) {
        within("pier drift", p.peak_drift[1], r.0, 0.05);
        within("pier column", p.peak_column_force / 1e6, r.1, 0.03);
    }
    for (g, r) in s.segments.iter().zip([0.13157, 0.14161, 0.14143]) {
        within("deck", g.peak_displacement, r, 0.05);
    }
}

/// Yielding bearings standing on the cap of an elastic pier: the pier reports no hysteresis (the
/// bearings' dissipation is the segments'), each member's own work less what it stores adds up to
/// the bridge's hysteretic dissipation, and `period_s = "model"` of a fragility study is the
/// whole coupled bridge's first period (not a segment's on fixed caps).
#[test]
fn bearing_dissipation_stays_with_the_segments_and_the_period_is_the_bridges() {
    let text = BRIDGE_P
        .replace(
            "bearing_damping = 1.0e5\n",
            "bearing_damping = 1.0e5\nbearing = \"bilinear\"\nfy = 4.0e5\nb = 0.05\n",
        )
        .replace("fy = 1.2e6\nb = 0.02\n", "")
        .replace("[time]\n", "[time]\nduration = 12.0\n");
    let s = run_text(&text).summary;
    let segs: f64 = s.segments.iter().map(|g| g.hysteretic_energy).sum();
    assert!(segs > 1e3, "the bearings yield ({segs} J)");
    for p in &s.piers {
        assert!(!p.yielded && p.hysteretic_energy == 0.0, "{p:?}");
    }
    // the booked work of the elements = what they store + the members' dissipation
    let booked = s.final_energy.elements - s.restrainer_work - s.backfill_work - s.shear_key_work;
    let stored = booked - segs;
    assert!(
        stored >= -1e-6 * segs && stored < 0.5 * segs,
        "stored {stored} of {segs}"
    );
    // the fundamental period of the coupled bridge: its lowest mode along the chain
    let model = Scenario::from_toml(BRIDGE_P, "p.toml")
        .unwrap()
        .build_bridge()
        .unwrap()
        .problem
        .model;
    let t = pounding::assessment::im::fundamental_period(&model).unwrap();
    assert!(t.whole_bridge && t.segment == 0);
    // independent: the plan system by hand, decks (x, y, θ) 0..9 and caps (x, y) 9..13; the
    // chain runs along −y, so a bearing's arm from its deck's centroid is (±5, ±15); two bearings
    // of 4e6 N/m at each deck end, on the ground (outer ends) or on a cap (joint ends)
    let (k, kc, mc) = (4.0e6, 8.0e7, 2.0e5);
    let masses = [1.0e6, 1.2e6, 0.8e6];
    let mut mm = [0.0f64; 13];
    for (d, m) in masses.iter().enumerate() {
        mm[3 * d] = *m;
        mm[3 * d + 1] = *m;
        mm[3 * d + 2] = m * (30.0f64 * 30.0 + 12.0 * 12.0) / 12.0;
    }
    for c in 0..2 {
        mm[9 + 2 * c] = mc;
        mm[10 + 2 * c] = mc;
    }
    let mut kk = DMatrix::<f64>::zeros(13, 13);
    for d in 0..3 {
        for (ry, base) in [
            (15.0, if d == 0 { None } else { Some(d - 1) }),
            (-15.0, if d == 2 { None } else { Some(d) }),
        ] {
            for rx in [-5.0, 5.0] {
                // u = B q_d − q_c, B = [[1, 0, −r_y], [0, 1, r_x]]
                let mut rows: Vec<(usize, [f64; 2])> = vec![
                    (3 * d, [1.0, 0.0]),
                    (3 * d + 1, [0.0, 1.0]),
                    (3 * d + 2, [-ry, rx]),
                ];
                if let Some(c) = base {
                    rows.push((9 + 2 * c, [-1.0, 0.0]));
                    rows.push((10 + 2 * c, [0.0, -1.0]));
                }
                for &(i, a) in &rows {
                    for &(j, b) in &rows {
                        kk[(i, j)] += k * (a[0] * b[0] + a[1] * b[1]);
                    }
                }
            }
        }
    }
    for i in 9..13 {
        kk[(i, i)] += kc;
    }
    let sym = DMatrix::from_fn(13, 13, |i, j| kk[(i, j)] / (mm[i] * mm[j]).sqrt());
    let w1 = sym
        .symmetric_eigenvalues()
        .iter()
        .fold(f64::INFINITY, |a, &l| a.min(l))
        .sqrt();
    let t1 = 2.0 * std::f64::consts::PI / w1;
    assert!((t.period - t1).abs() <= 1e-9 * t1, "{} vs {t1}", t.period);
    // every frequency of the whole bridge (summary.json's `model.periods_s`) against the hand
    // system's
    let mut hand: Vec<f64> = sym
        .symmetric_eigenvalues()
        .iter()
        .map(|l| l.max(0.0).sqrt())
        .collect();
    hand.sort_by(f64::total_cmp);
    let ours = model
        .system_frequencies()
        .unwrap()
        .expect("a coupled bridge");
    assert_eq!(ours.len(), 13);
    for (a, b) in ours.iter().zip(&hand) {
        assert!((a - b).abs() <= 1e-9 * hand[12], "{ours:?} vs {hand:?}");
    }
}
