//! Bearing geometry: the assembled bearing stiffness against a hand-assembled `K` for random
//! layouts (lever arms from the spec's closed-form centroid, `K` from the potential energy by
//! polarisation), and natural periods taken from the model, checked against an independent
//! eigen-analysis.

use nalgebra::{Matrix3, Vector2, Vector3};
use pounding::pair::SArrangement;
use pounding::shape::Deck;
use pounding::sim::{Bearing, SimModel};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Spec §3 closed forms: `(m, I, X_m, Y_m)` per unit `ρ t` times `ρ t`.
fn mass_props(r: f64, beta: f64, w: f64, rho_t: f64) -> (f64, f64, f64, f64) {
    let m = rho_t * beta * r * w;
    let rc = (r + w * w / (12.0 * r)) * (beta / 2.0).sin() / (beta / 2.0);
    let i = m * (r * r + w * w / 4.0 - rc * rc);
    (m, i, rc * (beta / 2.0).cos(), rc * (beta / 2.0).sin())
}

/// `K` of one deck from the bearings' potential energy `V(q) = Σ ½ k |u + θ ẑ × r|²`
/// (`r` = bearing point − centroid, reference pose) by polarisation:
/// `K_ij = V(e_i + e_j) − V(e_i) − V(e_j)` (exact for a quadratic form), `K_ii = 2 V(e_i)`.
fn hand_k(points: &[(Vector2<f64>, f64)], centroid: Vector2<f64>) -> Matrix3<f64> {
    let v = |q: Vector3<f64>| -> f64 {
        points
            .iter()
            .map(|(p, k)| {
                let r = p - centroid;
                // ẑ × r = (−r_y, r_x)
                let up = Vector2::new(q[0] - q[2] * r.y, q[1] + q[2] * r.x);
                0.5 * k * up.norm_squared()
            })
            .sum()
    };
    let e = |i: usize| Vector3::from_fn(|k, _| if k == i { 1.0 } else { 0.0 });
    Matrix3::from_fn(|i, j| {
        if i == j {
            2.0 * v(e(i))
        } else {
            v(e(i) + e(j)) - v(e(i)) - v(e(j))
        }
    })
}

/// `ω` of `K φ = ω² M φ`, `M = diag(m, m, I)`, sorted (independent of the library's routine:
/// characteristic polynomial of `M^{-1/2} K M^{-1/2}` via nalgebra's general eigenvalues).
fn hand_omegas(k: &Matrix3<f64>, m: f64, i: f64) -> [f64; 3] {
    let s = Matrix3::from_diagonal(&Vector3::new(m.sqrt(), m.sqrt(), i.sqrt()))
        .try_inverse()
        .unwrap();
    let a = s * k * s;
    let mut ev: Vec<f64> = a
        .complex_eigenvalues()
        .iter()
        .map(|c| c.re.max(0.0).sqrt())
        .collect();
    ev.sort_by(f64::total_cmp);
    [ev[0], ev[1], ev[2]]
}

fn deck(r: f64, beta_deg: f64) -> Deck {
    Deck {
        radius: r,
        angle: beta_deg.to_radians(),
        width: 10.0,
        thickness: 0.5,
        density: 2500.0,
    }
}

fn bearings() -> impl Strategy<Value = Vec<(f64, f64, f64)>> {
    prop::collection::vec((-150.0f64..150.0, -150.0f64..150.0, 1e5f64..1e8), 2..6)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, failure_persistence: None, ..ProptestConfig::default() })]

    /// Random decks and bearing layouts: the model's `K` blocks equal the hand-assembled `K`
    /// (a flipped lever-arm sign, a wrong centroid or a deck-2 orientation slip all show), and
    /// the model's frequencies equal an independent eigen-analysis.
    #[test]
    fn assembled_bearing_stiffness_equals_hand_assembled_k(
        r1 in 30.0f64..300.0, r2 in 30.0f64..300.0, b1 in 20.0f64..150.0, b2 in 20.0f64..150.0,
        gap in 0.0f64..0.2, l1 in bearings(), l2 in bearings(),
    ) {
        let arr = SArrangement { deck1: deck(r1, b1), deck2: deck(r2, b2) };
        let mut model = SimModel::with_corner_bearings(arr, gap, 1e7, 1e7, 0.0, 0.5, 0.5, 0.4);
        let to_b = |l: &[(f64, f64, f64)]| -> Vec<Bearing> {
            l.iter().map(|&(x, y, k)| Bearing { point: pounding::math::Vector::new(x, y), stiffness: k }).collect()
        };
        model.bearings1 = to_b(&l1);
        model.bearings2 = to_b(&l2);
        let sys = crate::common::two_deck_system(&model);
        for (j, (r, b, l)) in [(r1, b1, &l1), (r2, b2, &l2)].into_iter().enumerate() {
            let (m, inertia, xm, ym) = mass_props(r, b.to_radians(), 10.0, 2500.0 * 0.5);
            // spec §4: G⁰ relative to M_j is (R − X, +Y) for deck 1, (−R + X, −Y) for deck 2;
            // bearing points are given relative to M_j, so M_j cancels (and so does g)
            let s = if j == 0 { 1.0 } else { -1.0 };
            let g = Vector2::new(s * (r - xm), s * ym);
            let pts: Vec<(Vector2<f64>, f64)> = l.iter().map(|&(x, y, k)| (Vector2::new(x, y), k)).collect();
            let k_ref = hand_k(&pts, g);
            let k = sys.stiffness.fixed_view::<3, 3>(3 * j, 3 * j).into_owned();
            prop_assert!((k - k_ref).norm() <= 1e-9 * k_ref.norm(), "deck {}: {} vs {}", j + 1, k, k_ref);
            let mm = sys.mass.fixed_view::<3, 3>(3 * j, 3 * j).into_owned();
            prop_assert!((mm[(0, 0)] - m).abs() <= 1e-9 * m && (mm[(2, 2)] - inertia).abs() <= 1e-7 * inertia);
            let om = hand_omegas(&k_ref, m, inertia);
            for (a, b) in sys.frequencies[j].iter().zip(om) {
                prop_assert!((a - b).abs() <= 1e-6 * om[2], "deck {}: {:?} vs {:?}", j + 1, sys.frequencies[j], om);
            }
        }
    }
}

/// The default bridge's periods are taken from the model (`2π/ω` of its frequencies) and checked
/// against the eigen-analysis of the hand-assembled `K` of the spec geometry; for this layout the
/// lowest two periods lie near the 0.8 s (deck 1) and 1.2 s (deck 2) the bearings were sized for.
#[test]
fn default_bridge_periods_come_from_the_model() {
    let model = SimModel::default_bridge();
    let sys = crate::common::two_deck_system(&model);
    let b60 = 60f64.to_radians();
    for (j, kb) in [(0usize, 2.02e7), (1, 8.97e6)] {
        let (m, inertia, xm, ym) = mass_props(100.0, b60, 10.0, 1250.0);
        let s = if j == 0 { 1.0 } else { -1.0 };
        let g = Vector2::new(s * (100.0 - xm), s * ym);
        let corners = [
            Vector2::new(5.0, 0.0),
            Vector2::new(-5.0, 0.0),
            Vector2::new(100.0 - 95.0 * b60.cos(), 95.0 * b60.sin()),
            Vector2::new(100.0 - 105.0 * b60.cos(), 105.0 * b60.sin()),
        ];
        let pts: Vec<(Vector2<f64>, f64)> = corners.iter().map(|c| (c * s, kb)).collect();
        let om = hand_omegas(&hand_k(&pts, g), m, inertia);
        let periods: Vec<f64> = sys.frequencies[j].iter().map(|w| 2.0 * PI / w).collect();
        eprintln!("deck {}: periods from the model {periods:?}", j + 1);
        for (a, b) in sys.frequencies[j].iter().zip(om) {
            assert!(
                (a - b).abs() <= 1e-9 * om[2],
                "{:?} vs {om:?}",
                sys.frequencies[j]
            );
        }
        // the longest period is a translation mode sized 0.8 s / 1.2 s (within 5 %)
        let target = if j == 0 { 0.8 } else { 1.2 };
        assert!(
            (periods[0] - target).abs() < 0.05 * target,
            "deck {}: {periods:?}",
            j + 1
        );
    }
}
