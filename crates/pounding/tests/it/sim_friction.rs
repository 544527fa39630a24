//! Friction in the simulator: a sliding (and a sticking) corner impact of a free straight deck on
//! its abutment against the closed form of spec §9 with a Delassus matrix assembled by hand from
//! the rectangle's `m = ρ t L W`, `I = m (L² + W²)/12`; and `|P_T| = μ P_N` (opposite to the slip)
//! in every slipping impact of strong-motion runs.

use pounding::ground_motion::{GroundMotion, el_centro_1940};
use pounding::shape::{DeckShape, StraightDeck};
use pounding::sim::{
    SimAbutment, SimContact, SimModel, SimProblem, SimSettings, SimStatus, simulate,
};

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// Closed form of spec §9 for one contact: `(Λ_N, Λ_T, γ_T⁺)`.
fn closed_form(g: [f64; 3], mu: f64, eps: f64, gn: f64, gt: f64) -> (f64, f64, f64) {
    let [nn, nt, tt] = g;
    let (n, r, a) = (-gn, gt / gn, 1.0 + eps);
    let det = nn * tt - nt * nt;
    let (dm, dp) = (nn - mu * nt, nn + mu * nt);
    let l = if dm > 0.0 {
        a * (nt - mu * tt) / dm
    } else {
        f64::NEG_INFINITY
    };
    let u = if dp > 0.0 {
        a * (nt + mu * tt) / dp
    } else {
        f64::INFINITY
    };
    if r < l {
        let ln = a * n / dm;
        (ln, -mu * ln, n * (l - r))
    } else if r > u {
        let ln = a * n / dp;
        (ln, mu * ln, n * (u - r))
    } else {
        (
            n * (a * tt - nt * r) / det,
            n * (nn * r - a * nt) / det,
            0.0,
        )
    }
}

#[test]
fn sliding_corner_impact_on_the_abutment_matches_the_closed_form() {
    let (len, wid, thick, rho) = (30.0, 10.0, 0.5, 2500.0);
    let deck = DeckShape::Straight(StraightDeck {
        length: len,
        width: wid,
        thickness: thick,
        density: rho,
    });
    let (mu, eps, theta) = (0.4, 0.3, 2f64.to_radians());
    let mut model = SimModel::with_shapes([deck, deck], 1.0, 0.0, 0.0, 0.0, mu, eps, 5.0);
    let gap_a = 0.3;
    model.abutments = [
        Some(SimAbutment {
            gap: gap_a,
            seat_length: 5.0,
        }),
        None,
    ];
    let body = model.deck_bodies()[0];
    let far_face = *body.far_face(1);
    let nin = far_face.inward;
    let (n, t) = ([nin.x, nin.y], [-nin.y, nin.x]);
    let nout = [-n[0], -n[1]];
    // hand mass properties and the first corner to hit after a rotation θ about the centroid
    let m = rho * thick * len * wid;
    let inertia = m * (len * len + wid * wid) / 12.0;
    let rot = |v: [f64; 2]| {
        [
            theta.cos() * v[0] - theta.sin() * v[1],
            theta.sin() * v[0] + theta.cos() * v[1],
        ]
    };
    let arms: Vec<[f64; 2]> = far_face
        .corners
        .iter()
        .map(|c| rot([c.x - body.centroid.x, c.y - body.centroid.y]))
        .collect();
    // distance to the abutment face (reference far face + gap along n_out) after the rotation
    let far = [
        far_face.mid.x - body.centroid.x,
        far_face.mid.y - body.centroid.y,
    ];
    let gaps: Vec<f64> = arms
        .iter()
        .map(|r| gap_a - ((r[0] - far[0]) * nout[0] + (r[1] - far[1]) * nout[1]))
        .collect();
    let k = if gaps[0] < gaps[1] { 0 } else { 1 };
    assert!(gaps[k] > 0.05 && gaps[1 - k] > gaps[k] + 0.1, "{gaps:?}");
    let r = arms[k];
    let (an, at) = (cross(r, n), cross(r, t));
    let g = [
        1.0 / m + an * an / inertia,
        an * at / inertia,
        1.0 / m + at * at / inertia,
    ];
    let vn = 1.5;
    let mut modes = Vec::new();
    for vt in [-4.0, -0.5, 0.0, 0.5, 4.0] {
        let v = [vn * nout[0] + vt * t[0], vn * nout[1] + vt * t[1]];
        let (gn, gt) = (v[0] * n[0] + v[1] * n[1], v[0] * t[0] + v[1] * t[1]);
        let (ln, lt, gtp) = closed_form(g, mu, eps, gn, gt);
        let mut q0 = [0.0; 6];
        q0[2] = theta;
        let p = SimProblem {
            model: model.clone(),
            ground: GroundMotion::none(),
            q0,
            u0: [v[0], v[1], 0.0, 0.0, 0.0, 0.0],
        };
        let st = SimSettings {
            dt: 1e-4,
            duration: Some(gaps[k] / vn + 0.005),
            history_stride: 1_000_000,
            ..SimSettings::default()
        };
        let sol = simulate(&p, &st).unwrap();
        assert_eq!(sol.status, SimStatus::Completed);
        assert_eq!(sol.impacts.len(), 1, "vt = {vt}: {:?}", sol.impacts);
        let imp = &sol.impacts[0];
        assert_eq!(imp.contact, SimContact::Abutment { deck: 1, corner: k });
        let rel = |a: f64, b: f64, s: f64| (a - b).abs() / s;
        assert!(rel(imp.gamma_n_pre, gn, vn) < 1e-12 && rel(imp.gamma_t_pre, gt, vn) < 1e-12);
        assert!(
            rel(imp.impulse_n, ln, ln) < 1e-9,
            "vt = {vt}: {imp:?} vs {ln}"
        );
        assert!(
            rel(imp.impulse_t, lt, ln) < 1e-9,
            "vt = {vt}: {imp:?} vs {lt}"
        );
        assert!(rel(imp.gamma_n_post, -eps * gn, vn) < 1e-9);
        assert!(
            rel(imp.gamma_t_post, gtp, vn) < 1e-9,
            "vt = {vt}: {imp:?} vs {gtp}"
        );
        if gtp.abs() > 1e-9 * vn {
            // slipping: |P_T| = μ P_N, opposite to the slip
            assert!((imp.impulse_t.abs() - mu * imp.impulse_n).abs() <= 1e-9 * imp.impulse_n);
            assert!(imp.impulse_t * imp.gamma_t_post < 0.0);
        }
        modes.push(gtp.signum() as i32 * i32::from(gtp.abs() > 1e-9 * vn));
    }
    // the cases cover sliding both ways and sticking
    assert!(
        modes.contains(&1) && modes.contains(&-1) && modes.contains(&0),
        "{modes:?}"
    );
}

/// Every slipping impact of strong-motion runs (curved S bridge, μ = 0.5 and μ = 1) obeys
/// Coulomb's sliding law; every sticking one lies in the cone.
#[test]
fn every_slipping_impact_in_a_simulation_has_p_t_equal_mu_p_n() {
    let mut slipping = 0;
    for mu in [0.5, 1.0] {
        let mut model = SimModel::default_bridge();
        model.friction = mu;
        model.gap = 0.02;
        let mut g = el_centro_1940();
        g.scale_x = 2.0;
        g.scale_y = 2.0;
        let st = SimSettings {
            dt: 1e-3,
            duration: Some(12.0),
            history_stride: 1_000_000,
            ..SimSettings::default()
        };
        let sol = simulate(&SimProblem::at_rest(model, g), &st).unwrap();
        assert_eq!(sol.status, SimStatus::Completed);
        assert!(sol.impacts.len() > 5, "{}", sol.impacts.len());
        for imp in &sol.impacts {
            let pn = imp.impulse_n;
            assert!(pn > 0.0);
            let s = imp.gamma_n_pre.abs();
            if imp.gamma_t_post.abs() > 1e-9 * s {
                slipping += 1;
                assert!(
                    (imp.impulse_t.abs() - mu * pn).abs() <= 1e-9 * pn,
                    "μ = {mu}: {imp:?}"
                );
                assert!(imp.impulse_t * imp.gamma_t_post < 0.0, "μ = {mu}: {imp:?}");
            } else {
                assert!(imp.impulse_t.abs() <= mu * pn * (1.0 + 1e-9), "{imp:?}");
            }
        }
    }
    assert!(slipping > 0, "no slipping impact: the test checks nothing");
}
