//! Force directions and Delassus matrix (spec §6, §7, §15).

use crate::geometry::{Rng, deck, sector_polygon, spec_section};
use pounding::analytic::{ImpactLaw, stick_interval};
use pounding::contact::force_directions;
use pounding::geometry::{ContactCase, SigmaMode};
use pounding::math::Vector;
use pounding::pair::SArrangement;
use pounding::shape::Deck;

/// Spec §15, copied: R1 R2 β1 β2 θ1 θ2 case first σ_b G_NN G_NT G_TT L(.5) U(.5) L(1) U(1).
const TABLE15: &str = "\
| 100 | 100 | 60 | 60 | −5 | 2 | deck1-inner | yes | 4.984009614 | 2.784789492e-03 | 2.022511840e-03 | 6.619671336e-03 | −1.088778793 | 2.107066801 | −9.046230363 | 2.696580445 |
| 100 | 100 | 60 | 60 | 5 | −2 | deck1-outer | yes | −4.984009614 | 2.353427721e-03 | 1.500269571e-03 | 7.052214505e-03 | −1.895322093 | 2.429326047 | −9.761282130 | 3.328939753 |
| 100 | 100 | 60 | 60 | 2 | −5 | deck2-inner | yes | 4.984009614 | 2.784789492e-03 | 2.022511840e-03 | 6.619671336e-03 | −1.088778793 | 2.107066801 | −9.046230363 | 2.696580445 |
| 100 | 100 | 60 | 60 | −2 | 5 | deck2-outer | yes | −4.984009614 | 2.353427721e-03 | 1.500269571e-03 | 7.052214505e-03 | −1.895322093 | 2.429326047 | −9.761282130 | 3.328939753 |
| 200 | 100 | 120 | 90 | −8 | 3 | deck1-inner | yes | 4.958135296 | 1.800466485e-03 | 1.187112898e-03 | 2.499500086e-03 | −0.077848153 | 1.526841852 | −3.209536591 | 1.850969888 |
| 200 | 100 | 120 | 90 | 3 | −8 | deck2-inner | yes | 4.958135296 | 1.771056088e-03 | 1.140473087e-03 | 2.331698922e-03 | −0.031698818 | 1.477595656 | −2.833629751 | 1.788839369 |
| 100 | 200 | 90 | 60 | 6 | −1 | deck1-outer | yes | −4.973366945 | 1.600872729e-03 | 1.139298725e-03 | 3.903539079e-03 | −1.181806252 | 2.136169180 | −8.983089380 | 2.760504893 |
| 100 | 200 | 90 | 60 | 1 | 7 | deck2-outer | yes | −4.963486721 | 1.558301656e-03 | 1.059904371e-03 | 3.797643886e-03 | −1.223685522 | 2.125263406 | −8.239630105 | 2.782944623 |
| 100 | 100 | 60 | 60 | 0 | 5 | deck1-inner | no (off face) | 5.019099188 | 2.727089941e-03 | 1.955319894e-03 | 6.679043363e-03 | −1.186845252 | 2.143805278 | −9.180953875 | 2.765999847 |
| 100 | 100 | 60 | 60 | 5 | 0 | deck1-inner | no (wrong end) | 4.980973490 | 2.507682464e-03 | 1.556180477e-03 | 6.896633777e-03 | −1.640967492 | 2.284621222 | −8.418983945 | 3.119992373 |";

/// 1e-8 relative, or half a unit of the last printed digit when the table prints fewer digits.
fn close(value: f64, printed: &str, what: &str) {
    let s = printed.trim().replace('−', "-");
    let p: f64 = s.parse().unwrap();
    let (mant, exp) = match s.find('e') {
        Some(i) => (&s[..i], s[i + 1..].parse::<i32>().unwrap()),
        None => (&s[..], 0),
    };
    let decimals = mant.find('.').map_or(0, |i| mant.len() - i - 1) as i32;
    let tol = (1e-8 * p.abs()).max(0.5 * 10f64.powi(exp - decimals) * (1.0 + 1e-9));
    if (value - p).abs() > 1e-8 * p.abs() {
        eprintln!(
            "{what}: relative deviation {:.2e} exceeds 1e-8 (printed with {decimals} decimals)",
            ((value - p) / p).abs()
        );
    }
    assert!((value - p).abs() <= tol, "{what}: {value} vs {printed}");
}

fn check_table15(table: &str) -> usize {
    let mut n = 0;
    for line in table.lines() {
        let c: Vec<String> = line
            .trim()
            .trim_matches('|')
            .split('|')
            .map(|x| x.trim().replace('−', "-"))
            .collect();
        if c.len() != 16 || c[0].parse::<f64>().is_err() {
            continue;
        }
        let f = |i: usize| c[i].parse::<f64>().unwrap();
        let s = SArrangement::new(deck(f(0), f(2)), deck(f(1), f(3))).unwrap();
        let case = ContactCase::from_name(&c[6]).unwrap();
        let cfg = s
            .configuration(case, f(4).to_radians(), f(5).to_radians(), SigmaMode::Exact)
            .unwrap();
        let what = format!("row {line}");
        assert_eq!(cfg.first_contact, c[7].starts_with("yes"), "{what}");
        close(cfg.sigma, &c[8], &format!("{what} sigma"));
        let g = s.delassus(&cfg);
        close(g.nn, &c[9], &format!("{what} G_NN"));
        close(g.nt, &c[10], &format!("{what} G_NT"));
        close(g.tt, &c[11], &format!("{what} G_TT"));
        for (k, mu) in [(12, 0.5), (14, 1.0)] {
            let b = stick_interval(&g, &ImpactLaw::new(mu, 0.5).unwrap());
            close(b.lower, &c[k], &format!("{what} L(mu={mu})"));
            close(b.upper, &c[k + 1], &format!("{what} U(mu={mu})"));
        }
        n += 1;
    }
    n
}

#[test]
fn reference_table_of_spec_section_15() {
    assert_eq!(check_table15(TABLE15), 10);
    match spec_section(15) {
        Some(s) => assert_eq!(check_table15(&s), 10, "spec §15 rows"),
        None => crate::common::skipped(
            "the reference table of the project's shared specification (a copy in this test is checked instead)",
        ),
    }
}

/// Independent geometry of one deck for finite differences: polygon (arc) vertices relative to its
/// face midpoint, shoelace centroid, face corners. Nothing here uses the library's formulas.
struct PolyDeck {
    centroid: Vector,
    inner: Vector,
    outer: Vector,
}

fn poly_deck(d: &Deck, which: u8) -> PolyDeck {
    // Sector about its centre of curvature, face on φ = 0, then mapped into the deck's reference frame
    // (spec §4 point sets): deck 1 (R1 − r cos φ, r sin φ), deck 2 (−R2 + r cos φ, −r sin φ).
    let pts = sector_polygon(d.radius, d.width, d.angle, 20_000);
    let map = |p: Vector| {
        if which == 1 {
            Vector::new(d.radius - p.x, p.y)
        } else {
            Vector::new(-d.radius + p.x, -p.y)
        }
    };
    let (mut a2, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..pts.len() {
        let (p0, p1) = (map(pts[i]), map(pts[(i + 1) % pts.len()]));
        let c = p0.x * p1.y - p1.x * p0.y;
        a2 += c;
        cx += (p0.x + p1.x) * c;
        cy += (p0.y + p1.y) * c;
    }
    let (ri, ro) = (d.radius - 0.5 * d.width, d.radius + 0.5 * d.width);
    PolyDeck {
        centroid: Vector::new(cx / (3.0 * a2), cy / (3.0 * a2)),
        inner: map(Vector::new(ri, 0.0)),
        outer: map(Vector::new(ro, 0.0)),
    }
}

fn rot(v: Vector, t: f64) -> Vector {
    Vector::new(t.cos() * v.x - t.sin() * v.y, t.sin() * v.x + t.cos() * v.y)
}

/// Body pose: reference point p (relative to M_j) → M_j + Rot(θ_j) p, followed by the generalised
/// displacement q_j = (dx, dy, dθ) about the current centroid.
fn place(p: Vector, mj: Vector, theta: f64, centroid_ref: Vector, q: [f64; 3]) -> Vector {
    let x0 = mj + rot(p, theta);
    let g0 = mj + rot(centroid_ref, theta);
    g0 + Vector::new(q[0], q[1]) + rot(x0 - g0, q[2])
}

#[test]
fn force_directions_match_finite_differences_of_polygon_geometry() {
    let mut rng = Rng(2024);
    let mut worst: f64 = 0.0;
    for _ in 0..60 {
        let d1 = deck(rng.uniform(20.0, 400.0), rng.uniform(5.0, 300.0));
        let d2 = deck(rng.uniform(20.0, 400.0), rng.uniform(5.0, 300.0));
        let s = SArrangement::new(d1, d2).unwrap();
        let (p1, p2) = (poly_deck(&d1, 1), poly_deck(&d2, 2));
        let t1 = rng.uniform(-20.0, 20.0).to_radians();
        let t2 = rng.uniform(-20.0, 20.0).to_radians();
        for case in ContactCase::ALL {
            let cfg = s.configuration(case, t1, t2, SigmaMode::Exact).unwrap();
            let w = force_directions(&cfg);
            let m1 = Vector::new(0.0, cfg.h);
            let m2 = Vector::new(0.0, 0.0);
            let a_is_1 = matches!(case, ContactCase::Deck1Inner | ContactCase::Deck1Outer);
            let corner_ref = match case {
                ContactCase::Deck1Inner => p1.inner,
                ContactCase::Deck1Outer => p1.outer,
                ContactCase::Deck2Inner => p2.inner,
                ContactCase::Deck2Outer => p2.outer,
            };
            // the struck face's material point under the corner, in the struck deck's reference frame
            let (mb, tb, gb) = if a_is_1 {
                (m2, t2, p2.centroid)
            } else {
                (m1, t1, p1.centroid)
            };
            let corner0 = if a_is_1 {
                place(corner_ref, m1, t1, p1.centroid, [0.0; 3])
            } else {
                place(corner_ref, m2, t2, p2.centroid, [0.0; 3])
            };
            let foot_ref = rot(corner0 - mb, -tb);
            let _ = gb;
            // g_N(q) and s_T(q) from the placed polygons
            let eval = |q: [f64; 6]| -> (f64, f64) {
                let q1 = [q[0], q[1], q[2]];
                let q2 = [q[3], q[4], q[5]];
                let (corner, face_a, face_b, foot, inside) = if a_is_1 {
                    (
                        place(corner_ref, m1, t1, p1.centroid, q1),
                        place(p2.inner, m2, t2, p2.centroid, q2),
                        place(p2.outer, m2, t2, p2.centroid, q2),
                        place(foot_ref, m2, t2, p2.centroid, q2),
                        place(p2.centroid, m2, t2, p2.centroid, q2),
                    )
                } else {
                    (
                        place(corner_ref, m2, t2, p2.centroid, q2),
                        place(p1.inner, m1, t1, p1.centroid, q1),
                        place(p1.outer, m1, t1, p1.centroid, q1),
                        place(foot_ref, m1, t1, p1.centroid, q1),
                        place(p1.centroid, m1, t1, p1.centroid, q1),
                    )
                };
                let d = (face_b - face_a).normalize();
                let mut n_out = Vector::new(-d.y, d.x);
                if (inside - face_a).dot(&n_out) > 0.0 {
                    n_out = -n_out;
                }
                let gap = (corner - face_a).dot(&n_out);
                // ν from the deck-2 side to the deck-1 side; τ = ν turned by +90°
                let nu = if a_is_1 { n_out } else { -n_out };
                let tau = Vector::new(-nu.y, nu.x);
                let (pt1, pt2) = if a_is_1 {
                    (corner, foot)
                } else {
                    (foot, corner)
                };
                (gap, (pt1 - pt2).dot(&tau))
            };
            let (g0, _) = eval([0.0; 6]);
            assert!(
                g0.abs() < 1e-9,
                "{case:?}: corner not on the face, gap {g0}"
            );
            for k in 0..6 {
                let step = if k % 3 == 2 { 1e-6 } else { 1e-4 };
                let mut qp = [0.0; 6];
                let mut qm = [0.0; 6];
                qp[k] = step;
                qm[k] = -step;
                let (gp, sp) = eval(qp);
                let (gm, sm) = eval(qm);
                let fd_n = (gp - gm) / (2.0 * step);
                let fd_t = (sp - sm) / (2.0 * step);
                let en = (fd_n - w.w_n[k]).abs() / w.w_n[k].abs().max(1.0);
                let et = (fd_t - w.w_t[k]).abs() / w.w_t[k].abs().max(1.0);
                worst = worst.max(en).max(et);
                assert!(en < 1e-6, "{case:?} w_N[{k}] fd {fd_n} vs {}", w.w_n[k]);
                assert!(et < 1e-6, "{case:?} w_T[{k}] fd {fd_t} vs {}", w.w_t[k]);
            }
        }
    }
    eprintln!("worst scaled finite-difference error of w_N, w_T: {worst:.2e}");
}

/// Closed forms of spec §6 (striking arm through the relative angle δ, struck arms fixed to the face).
#[test]
fn force_directions_match_spec_closed_forms() {
    let mut rng = Rng(99);
    for _ in 0..500 {
        let d1 = deck(rng.uniform(20.0, 400.0), rng.uniform(5.0, 300.0));
        let d2 = deck(rng.uniform(20.0, 400.0), rng.uniform(5.0, 300.0));
        let s = SArrangement::new(d1, d2).unwrap();
        let (q1, q2) = (d1.mass_properties(), d2.mass_properties());
        let (c1, c2) = (d1.sector_centroid(), d2.sector_centroid());
        let t1 = rng.uniform(-10.0, 10.0).to_radians();
        let t2 = rng.uniform(-10.0, 10.0).to_radians();
        for mode in [SigmaMode::Exact, SigmaMode::End] {
            for case in ContactCase::ALL {
                let cfg = s.configuration(case, t1, t2, mode).unwrap();
                let w = force_directions(&cfg);
                let a_is_1 = matches!(case, ContactCase::Deck1Inner | ContactCase::Deck1Outer);
                let inner = matches!(case, ContactCase::Deck1Inner | ContactCase::Deck2Inner);
                let (ra, delta) = if a_is_1 {
                    (d1.radius, t2 - t1)
                } else {
                    (d2.radius, t1 - t2)
                };
                let rho = if inner { ra - 5.0 } else { ra + 5.0 };
                let u = if a_is_1 {
                    Vector::new(c1.x_m - rho, -c1.y_m)
                } else {
                    Vector::new(rho - c2.x_m, c2.y_m)
                };
                let aa = u.x * delta.cos() + u.y * delta.sin();
                let ba = -u.x * delta.sin() + u.y * delta.cos();
                let (ab, bb) = if a_is_1 {
                    (d2.radius - c2.x_m + cfg.sigma, c2.y_m)
                } else {
                    (-(d1.radius - c1.x_m + cfg.sigma), -c1.y_m)
                };
                let (a1, b1, a2, b2) = if a_is_1 {
                    (aa, ba, ab, bb)
                } else {
                    (ab, bb, aa, ba)
                };
                let tol = |x: f64| 1e-11 * x.abs().max(1.0);
                assert!((w.w_n[2] - a1).abs() < tol(a1), "{case:?} {mode:?} A1");
                assert!((w.w_t[2] - b1).abs() < tol(b1), "{case:?} {mode:?} B1");
                assert!((w.w_n[5] + a2).abs() < tol(a2), "{case:?} {mode:?} A2");
                assert!((w.w_t[5] + b2).abs() < tol(b2), "{case:?} {mode:?} B2");
                let g = s.delassus(&cfg);
                assert!(g.det() > 0.0);
                let inv_m = 1.0 / q1.mass + 1.0 / q2.mass;
                let nn = inv_m + a1 * a1 / q1.inertia + a2 * a2 / q2.inertia;
                let nt = a1 * b1 / q1.inertia + a2 * b2 / q2.inertia;
                let tt = inv_m + b1 * b1 / q1.inertia + b2 * b2 / q2.inertia;
                assert!((g.nn - nn).abs() < 1e-12 * nn && (g.nt - nt).abs() < 1e-11 * nn);
                assert!((g.tt - tt).abs() < 1e-12 * tt, "{case:?} {mode:?} G_TT");
            }
        }
    }
}

/// `G[deck1-k; θ1, θ2; (R1, β1), (R2, β2)] = G[deck2-k; θ2, θ1; (R2, β2), (R1, β1)]` to 1e-12.
#[test]
fn point_symmetry_identity() {
    let mut rng = Rng(7);
    let mut worst: f64 = 0.0;
    for _ in 0..2000 {
        let (r1, b1) = (rng.uniform(20.0, 400.0), rng.uniform(5.0, 300.0));
        let (r2, b2) = (rng.uniform(20.0, 400.0), rng.uniform(5.0, 300.0));
        let t1 = rng.uniform(-10.0, 10.0).to_radians();
        let t2 = rng.uniform(-10.0, 10.0).to_radians();
        let s = SArrangement::new(deck(r1, b1), deck(r2, b2)).unwrap();
        let m = SArrangement::new(deck(r2, b2), deck(r1, b1)).unwrap();
        for mode in [SigmaMode::Exact, SigmaMode::End] {
            for (k1, k2) in [
                (ContactCase::Deck1Inner, ContactCase::Deck2Inner),
                (ContactCase::Deck1Outer, ContactCase::Deck2Outer),
            ] {
                let c = s.configuration(k1, t1, t2, mode).unwrap();
                let d = m.configuration(k2, t2, t1, mode).unwrap();
                let (g, h) = (s.delassus(&c), m.delassus(&d));
                for (x, y) in [(g.nn, h.nn), (g.nt, h.nt), (g.tt, h.tt)] {
                    let e = (x - y).abs() / g.nn;
                    worst = worst.max(e);
                    assert!(e < 1e-12, "{x} vs {y}");
                }
                assert_eq!(c.first_contact, d.first_contact);
                assert!((c.sigma - d.sigma).abs() < 1e-12);
            }
        }
    }
    eprintln!("point symmetry: worst relative deviation {worst:.1e}");
}

/// `G` scales as `1/(ρ t)`; `L`, `U` do not (spec §3, §15).
#[test]
fn delassus_scales_with_inverse_rho_t() {
    let a = SArrangement::new(deck(100.0, 60.0), deck(200.0, 90.0)).unwrap();
    let d = |r: f64, b: f64| Deck::new(r, b.to_radians(), 10.0, 0.5, 2500.0).unwrap();
    let b = SArrangement::new(d(100.0, 60.0), d(200.0, 90.0)).unwrap();
    let (t1, t2) = (-4f64.to_radians(), 1f64.to_radians());
    let ga = a.delassus(
        &a.configuration(ContactCase::Deck1Inner, t1, t2, SigmaMode::Exact)
            .unwrap(),
    );
    let gb = b.delassus(
        &b.configuration(ContactCase::Deck1Inner, t1, t2, SigmaMode::Exact)
            .unwrap(),
    );
    assert!((ga.nn / gb.nn - 1250.0).abs() < 1e-9);
    assert!((ga.nt / gb.nt - 1250.0).abs() < 1e-9);
    let law = ImpactLaw::new(0.5, 0.5).unwrap();
    let (ba, bb) = (stick_interval(&ga, &law), stick_interval(&gb, &law));
    assert!((ba.lower - bb.lower).abs() < 1e-12 && (ba.upper - bb.upper).abs() < 1e-12);
}

/// On the paper grid the coupling ratios lie in the spec's ranges (spec §7):
/// κ ∈ [0.050, 0.753], ϱ ∈ [0.700, 3.574] (all cases), first-contact cells κ ∈ [0.383, 0.752].
/// The extremes are approached next to the degenerate diagonals (e.g. κ → 0.0501 as θ2 → −θ1 at
/// θ1 = 10°), so the grid is the 1° grid plus the points 1e-6° off each diagonal cell; the spec's
/// printed ranges are the closure over the square.
#[test]
fn paper_grid_ratio_ranges() {
    let (mut kmin, mut kmax, mut rmin, mut rmax) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    let (mut fkmin, mut fkmax) = (f64::MAX, f64::MIN);
    for &(r1, r2) in &[
        (100.0, 100.0),
        (100.0, 200.0),
        (200.0, 100.0),
        (200.0, 200.0),
    ] {
        for &b1 in &[60.0, 90.0, 120.0] {
            for &b2 in &[60.0, 90.0, 120.0] {
                let s = SArrangement::new(deck(r1, b1), deck(r2, b2)).unwrap();
                for i in -10..=10 {
                    for jj in -30i32..=32 {
                        let (j, off) = (jj.div_euclid(3) as f64, (jj.rem_euclid(3) - 1) as f64);
                        let t2d = j + 1e-6 * off;
                        if !(-10.0..=10.0).contains(&t2d) {
                            continue;
                        }
                        let (t1, t2) = ((i as f64).to_radians(), t2d.to_radians());
                        for case in ContactCase::ALL {
                            let Ok(c) = s.configuration(case, t1, t2, SigmaMode::Exact) else {
                                continue;
                            };
                            let g = s.delassus(&c);
                            let (k, v) = (g.kappa(), g.varrho());
                            kmin = kmin.min(k);
                            kmax = kmax.max(k);
                            rmin = rmin.min(v);
                            rmax = rmax.max(v);
                            if c.first_contact {
                                fkmin = fkmin.min(k);
                                fkmax = fkmax.max(k);
                            }
                        }
                    }
                }
            }
        }
    }
    eprintln!("kappa [{kmin}, {kmax}], varrho [{rmin}, {rmax}], first kappa [{fkmin}, {fkmax}]");
    assert!(kmin > 0.0495 && kmin < 0.0505 && kmax > 0.7525 && kmax < 0.7535);
    assert!(rmin > 0.6995 && rmin < 0.7005 && rmax > 3.5735 && rmax < 3.5745);
    assert!(fkmin > 0.3825 && fkmin < 0.3835 && fkmax > 0.7515 && fkmax < 0.7525);
}
