//! Deck shapes in the study: the generic pair configuration against the curved S arrangement,
//! a straight-deck cell against an independent polygon computation, the point symmetry of equal
//! straight decks, skew/length validation, and the curved study unchanged.

use nalgebra::{Matrix6, Vector6};
use pounding::analytic::{ImpactLaw, stick_interval};
use pounding::geometry::{ContactCase, SigmaMode};
use pounding::math::Vector;
use pounding::pair::SArrangement;
use pounding::pair::{DeckPair, pair_degeneracy, pair_first_contact};
use pounding::shape::Deck;
use pounding::shape::{DeckShape, SkewedDeck, StraightDeck};
use pounding::study::csv::{BOUNDS_HEADER, SHAPE_COLUMNS};
use pounding::study::run::compute_rows;
use pounding::study::{Scenario, ScenarioError, Shard, Study, StudyShape};

fn none(_: usize) {}

fn rel(a: f64, b: f64, scale: f64) -> f64 {
    (a - b).abs() / scale
}

/// The generic pair built from two curved shapes reproduces the S arrangement (configuration and
/// Delassus matrix) to ≤ 1e-14 relative, flags exactly, over all cases, both σ modes and a θ grid.
#[test]
fn curved_pair_matches_s_arrangement() {
    let mut worst: f64 = 0.0;
    for (r1, b1, r2, b2) in [
        (100.0, 60.0, 200.0, 90.0),
        (200.0, 120.0, 100.0, 60.0),
        (150.0, 30.0, 150.0, 30.0),
    ] {
        let d1 = Deck::new(r1, f64::to_radians(b1), 10.0, 0.5, 2500.0).unwrap();
        let d2 = Deck::new(r2, f64::to_radians(b2), 10.0, 0.5, 2500.0).unwrap();
        let s = SArrangement::new(d1, d2).unwrap();
        let p = DeckPair::new(DeckShape::Curved(d1), DeckShape::Curved(d2)).unwrap();
        for i in -10..=10 {
            for j in -10..=10 {
                let (t1, t2) = ((i as f64).to_radians(), (j as f64 * 0.7).to_radians());
                for case in ContactCase::ALL {
                    for mode in [SigmaMode::Exact, SigmaMode::End] {
                        let a = s.configuration(case, t1, t2, mode);
                        let b = p.configuration(case, t1, t2, mode);
                        let (a, b) = match (a, b) {
                            (Err(x), Err(y)) => {
                                assert_eq!(x, y);
                                continue;
                            }
                            (Ok(a), Ok(b)) => (a, b),
                            (a, b) => panic!("{a:?} vs {b:?}"),
                        };
                        assert_eq!(a.first_contact, b.first_contact);
                        assert_eq!(a.end_closes, b.end_closes);
                        assert_eq!(a.h, b.h);
                        assert_eq!(a.sigma, b.sigma);
                        for (u, v) in [
                            (a.centroid1, b.centroid1),
                            (a.centroid2, b.centroid2),
                            (a.point, b.point),
                            (a.struck_point, b.struck_point),
                        ] {
                            let e = (u - v).norm() / r1.max(r2);
                            worst = worst.max(e);
                            assert!(e <= 1e-14, "{u:?} vs {v:?}");
                        }
                        let (ga, gb) = (s.delassus(&a), p.delassus(&b));
                        for (x, y) in [(ga.nn, gb.nn), (ga.nt, gb.nt), (ga.tt, gb.tt)] {
                            let e = rel(x, y, ga.nn);
                            worst = worst.max(e);
                            assert!(e <= 1e-14, "{x} vs {y} ({case:?}, {i}, {j})");
                        }
                    }
                }
            }
        }
    }
    eprintln!("curved pair vs S arrangement: worst relative deviation {worst:.1e}");
}

/// Polygon area, centroid and polar moment about the centroid (shoelace formulas), independent of
/// the shape module.
fn polygon_props(v: &[Vector], rho_t: f64) -> (f64, Vector, f64) {
    let n = v.len();
    let (mut a2, mut cx, mut cy, mut ixx, mut iyy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for k in 0..n {
        let (p, q) = (v[k], v[(k + 1) % n]);
        let c = p.x * q.y - q.x * p.y;
        a2 += c;
        cx += (p.x + q.x) * c;
        cy += (p.y + q.y) * c;
        ixx += (p.y * p.y + p.y * q.y + q.y * q.y) * c;
        iyy += (p.x * p.x + p.x * q.x + q.x * q.x) * c;
    }
    let area = 0.5 * a2;
    let g = Vector::new(cx / (3.0 * a2), cy / (3.0 * a2));
    let j_origin = (ixx + iyy) / 12.0;
    let mass = rho_t * area.abs();
    let inertia = rho_t * j_origin.abs() - mass * g.norm_squared();
    (mass, g, inertia)
}

fn rot(t: f64, p: Vector) -> Vector {
    let (s, c) = t.sin_cos();
    Vector::new(c * p.x - s * p.y, s * p.x + c * p.y)
}

const STRAIGHT: &str = r#"
[decks]
shape = "straight"
width_m = 10.0
l1_m = [30.0, 60.0]
l2_m = [30.0, 60.0]
[impact]
mu = [0.5]
[grid]
theta1_deg = { start = -4.0, stop = 4.0, step = 1.0 }
theta2_deg = { start = -4.0, stop = 4.0, step = 1.0 }
[output]
figures = false
"#;

/// A straight-deck study cell against an independent computation: the rectangles placed as
/// polygons (deck 2 turned by π), `h` from the corner-on-line condition, centroid and inertia
/// from the shoelace formulas, and `G = Wᵀ M⁻¹ W` with a 6×6 mass matrix.
#[test]
fn straight_cell_matches_polygon_computation() {
    let sc = Scenario::from_toml(STRAIGHT, "t.toml").unwrap();
    assert_eq!(sc.shape, StudyShape::Straight);
    let study = Study::compute(STRAIGHT.into(), sc.clone(), &none).unwrap();
    let rho_t = sc.rho_t();
    let w = 0.5 * sc.width;
    let mut checked = 0;
    let mut worst: f64 = 0.0;
    for row in &study.rows {
        let p = sc.params(&row.key);
        if row.cell.degeneracy.is_some() {
            assert!(row.cell.g_nn.is_nan());
            continue;
        }
        assert!(p.beta1_deg.is_nan() && p.r2_m.is_nan());
        let (t1, t2) = (p.theta1_deg.to_radians(), p.theta2_deg.to_radians());
        let rect = |l: f64| {
            vec![
                Vector::new(w, 0.0),
                Vector::new(w, l),
                Vector::new(-w, l),
                Vector::new(-w, 0.0),
            ]
        };
        // Corner (body frame) and the global position functions.
        let (deck1_strikes, corner) = match p.case {
            ContactCase::Deck1Inner => (true, Vector::new(w, 0.0)),
            ContactCase::Deck1Outer => (true, Vector::new(-w, 0.0)),
            ContactCase::Deck2Inner => (false, Vector::new(w, 0.0)),
            ContactCase::Deck2Outer => (false, Vector::new(-w, 0.0)),
        };
        // Struck face: a point on it and its unit normal (into deck 1's side) at h = 0.
        let h = if deck1_strikes {
            // ν2·((0,h) + R1 c) = 0, ν2 = R2 (0,1).
            let n2 = rot(t2, Vector::new(0.0, 1.0));
            -n2.dot(&rot(t1, corner)) / n2.y
        } else {
            // ν1·(−R2 c − (0,h)) = 0, ν1 = R1 (0,1).
            let n1 = rot(t1, Vector::new(0.0, 1.0));
            n1.dot(&rot(t2, -corner)) / n1.y
        };
        let place1 = |q: Vector| Vector::new(0.0, h) + rot(t1, q);
        let place2 = |q: Vector| rot(t2, -q);
        let poly1: Vec<Vector> = rect(p.l1_m).into_iter().map(place1).collect();
        let poly2: Vec<Vector> = rect(p.l2_m).into_iter().map(place2).collect();
        let (m1, g1, i1) = polygon_props(&poly1, rho_t);
        let (m2, g2, i2) = polygon_props(&poly2, rho_t);
        let (c, nu) = if deck1_strikes {
            (place1(corner), rot(t2, Vector::new(0.0, 1.0)))
        } else {
            (place2(corner), rot(t1, Vector::new(0.0, 1.0)))
        };
        let tau = Vector::new(-nu.y, nu.x);
        // τ = (−cos θ_b, −sin θ_b) = perp(ν) with perp(x, y) = (−y, x).
        let cr = |a: Vector, b: Vector| a.x * b.y - a.y * b.x;
        let (r1, r2) = (c - g1, c - g2);
        let wn = Vector6::new(nu.x, nu.y, cr(r1, nu), -nu.x, -nu.y, -cr(r2, nu));
        let wt = Vector6::new(tau.x, tau.y, cr(r1, tau), -tau.x, -tau.y, -cr(r2, tau));
        let minv = Matrix6::from_diagonal(&Vector6::new(
            1.0 / m1,
            1.0 / m1,
            1.0 / i1,
            1.0 / m2,
            1.0 / m2,
            1.0 / i2,
        ));
        let (gnn, gnt, gtt) = (
            wn.dot(&(minv * wn)),
            wn.dot(&(minv * wt)),
            wt.dot(&(minv * wt)),
        );
        let cell = &row.cell;
        for (x, y) in [(cell.g_nn, gnn), (cell.g_nt, gnt), (cell.g_tt, gtt)] {
            let e = rel(x, y, gnn);
            worst = worst.max(e);
            assert!(e < 1e-10, "{:?}: {x} vs {y}", p);
        }
        // σ on the struck face (+ toward the struck deck's outer corner).
        let (mb, eb) = if deck1_strikes {
            (Vector::zeros(), rot(t2, Vector::new(1.0, 0.0)))
        } else {
            (Vector::new(0.0, h), rot(t1, Vector::new(-1.0, 0.0)))
        };
        assert!((cell.sigma_m - (c - mb).dot(&eb)).abs() < 1e-10 * w);
        assert_eq!(cell.end_closes, h > 0.0);
        // First contact: the largest h among candidates whose corner lands on the face segment.
        if cell.first_contact {
            assert!(h > 0.0 && cell.sigma_m.abs() <= w);
        }
        let law = ImpactLaw::new(p.mu, p.eps).unwrap();
        let iv = stick_interval(
            &pounding::contact::Delassus {
                nn: gnn,
                nt: gnt,
                tt: gtt,
            },
            &law,
        );
        assert!((cell.lower - iv.lower).abs() < 1e-8 * iv.lower.abs().max(1.0));
        assert!((cell.upper - iv.upper).abs() < 1e-8 * iv.upper.abs().max(1.0));
        assert!(cell.lcp_agrees);
        checked += 1;
    }
    assert!(checked > 1000, "{checked}");
    eprintln!("straight cells vs polygons: {checked} cells, worst relative deviation {worst:.1e}");
}

/// Point symmetry: decks (A, B) with `deck1-k` at `(θ1, θ2)` equal decks (B, A) with `deck2-k` at
/// `(θ2, θ1)` (spec §4's turn by π swaps the decks); with `L1 = L2` this holds within one geometry.
#[test]
fn point_symmetry_of_straight_decks() {
    let sc = Scenario::from_toml(STRAIGHT, "t.toml").unwrap();
    let rows = compute_rows(&sc, Shard::ALL, &none).unwrap();
    let mut pairs = 0;
    for a in &rows {
        let pa = sc.params(&a.key);
        let mirror = match pa.case {
            ContactCase::Deck1Inner => ContactCase::Deck2Inner,
            ContactCase::Deck1Outer => ContactCase::Deck2Outer,
            _ => continue,
        };
        let b = rows
            .iter()
            .find(|b| {
                let pb = sc.params(&b.key);
                pb.case == mirror
                    && pb.l1_m == pa.l2_m
                    && pb.l2_m == pa.l1_m
                    && pb.theta1_deg == pa.theta2_deg
                    && pb.theta2_deg == pa.theta1_deg
            })
            .expect("the mirrored row exists");
        let (x, y) = (&a.cell, &b.cell);
        assert_eq!(x.degeneracy, y.degeneracy);
        assert_eq!(x.first_contact, y.first_contact);
        assert_eq!(x.end_closes, y.end_closes);
        if x.degeneracy.is_some() {
            continue;
        }
        for (u, v) in [
            (x.g_nn, y.g_nn),
            (x.g_nt, y.g_nt),
            (x.g_tt, y.g_tt),
            (x.sigma_m * 1e-6, y.sigma_m * 1e-6),
        ] {
            assert!(rel(u, v, x.g_nn) < 1e-12, "{u} vs {v}");
        }
        assert!((x.lower - y.lower).abs() < 1e-9 * x.lower.abs().max(1.0));
        pairs += 1;
    }
    assert!(pairs > 200, "{pairs}");
}

/// Scenario errors name the key and the line: skew ≥ 90°, L ≤ 0, unknown shape, keys of the
/// other shape.
#[test]
fn shape_validation_errors() {
    let err = |text: &str| Scenario::from_toml(text, "s.toml").unwrap_err();
    let check = |e: ScenarioError, key: &str, line: usize| {
        let msg = e.to_string();
        match e {
            ScenarioError::Invalid {
                key: k, line: l, ..
            } => {
                assert!(k.starts_with(key), "{msg}");
                assert_eq!(l, line, "{msg}");
            }
            other => panic!("{other:?}"),
        }
        assert!(msg.contains(key), "{msg}");
    };
    check(
        err("[decks]\nshape = \"skew\"\nskew_deg = [10.0, 90.0]\n"),
        "decks.skew_deg[1]",
        3,
    );
    check(
        err("[decks]\nshape = \"skew\"\nskew_deg = [-5.0]\n"),
        "decks.skew_deg[0]",
        3,
    );
    check(
        err("[decks]\nshape = \"straight\"\nl1_m = [30.0]\nl2_m = [0.0]\n"),
        "decks.l2_m[0]",
        4,
    );
    check(
        err("[decks]\nshape = \"straight\"\n\nl1_m = [-3.0]\n"),
        "decks.l1_m[0]",
        4,
    );
    check(err("[decks]\nshape = \"round\"\n"), "decks.shape", 2);
    check(
        err("[decks]\nshape = \"straight\"\nbeta1_deg = [60.0]\n"),
        "decks.beta1_deg",
        3,
    );
    check(
        err("[decks]\nshape = \"straight\"\nskew_deg = [10.0]\n"),
        "decks.skew_deg",
        3,
    );
    check(err("[decks]\nl1_m = [10.0]\n"), "decks.l1_m", 2);
    // Geometry errors of the decks themselves (not reachable from a valid scenario) name L1/L2.
    assert!(
        SkewedDeck::new(30.0, 10.0, f64::to_radians(90.0), 0.5, 2500.0)
            .unwrap_err()
            .to_string()
            .contains("skew")
    );
}

/// The skew study: joint faces `W/cos θ_s` long, skew 0 equals the straight study bit for bit,
/// extra columns only for non-curved shapes, and `bounds.csv` round-trips through shards.
#[test]
fn skew_study_columns_and_straight_limit() {
    let skew = r#"
[decks]
shape = "skew"
l1_m = [40.0]
l2_m = [25.0]
skew_deg = [0.0, 30.0]
[impact]
mu = [0.25]
[grid]
theta1_deg = { start = -3.0, stop = 3.0, step = 1.5 }
theta2_deg = { start = -3.0, stop = 3.0, step = 1.0 }
[output]
figures = false
"#;
    let straight = r#"
[decks]
shape = "straight"
l1_m = [40.0]
l2_m = [25.0]
[impact]
mu = [0.25]
[grid]
theta1_deg = { start = -3.0, stop = 3.0, step = 1.5 }
theta2_deg = { start = -3.0, stop = 3.0, step = 1.0 }
[output]
figures = false
"#;
    let sk = Study::compute(skew.into(), Scenario::from_toml(skew, "s").unwrap(), &none).unwrap();
    let st = Study::compute(
        straight.into(),
        Scenario::from_toml(straight, "s").unwrap(),
        &none,
    )
    .unwrap();
    // Row order: skew index outside μ/case/θ, so the first half is skew 0.
    let n = st.rows.len();
    assert_eq!(sk.rows.len(), 2 * n);
    for (a, b) in sk.rows[..n].iter().zip(&st.rows) {
        assert_eq!(a.cell.g_nn.to_bits(), b.cell.g_nn.to_bits());
        assert_eq!(a.cell.lower.to_bits(), b.cell.lower.to_bits());
    }
    // Skewed decks: |σ| on the face can exceed W/2 (the face is W/cos θ_s long).
    let w_face = 0.5 * 10.0 / f64::to_radians(30.0).cos();
    let max_sigma = sk.rows[n..]
        .iter()
        .filter(|r| r.cell.first_contact)
        .map(|r| r.cell.sigma_m.abs())
        .fold(0.0, f64::max);
    assert!(max_sigma > 5.0 && max_sigma <= w_face, "{max_sigma}");
    // A skewed deck is not a straight deck: G differs.
    assert!(
        sk.rows[n..]
            .iter()
            .zip(&st.rows)
            .any(|(a, b)| a.cell.g_nn.is_finite() && a.cell.g_nn != b.cell.g_nn)
    );
    let csv = sk.bounds_csv();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        format!("{BOUNDS_HEADER},{SHAPE_COLUMNS}")
    );
    let first = lines.next().unwrap();
    assert!(first.starts_with("nan,nan,nan,nan,0.25,"), "{first}");
    assert!(first.ends_with(",skew,40,25,0"), "{first}");
    let summary = sk.summary_csv();
    assert!(summary.lines().next().unwrap().ends_with(SHAPE_COLUMNS));
    // Shard round trip (parse_bounds_line checks the shape columns).
    let sc = Scenario::from_toml(skew, "s").unwrap();
    let mut files = Vec::new();
    for k in 1..=2 {
        let shard = Shard::new(k, 2).unwrap();
        let rows = compute_rows(&sc, shard, &none).unwrap();
        let text = pounding::study::shard::shard_rows_csv(&sc, &rows);
        files.push(pounding::study::shard::ShardFiles {
            origin: format!("shard {k}"),
            manifest: pounding::study::shard::manifest_json(
                shard,
                skew,
                sc.row_count(),
                rows.len(),
                &text,
            ),
            rows: text,
        });
    }
    let m = pounding::study::shard::merge(&files).unwrap();
    assert_eq!(
        Study::from_rows(m.scenario_text, m.scenario, m.rows).bounds_csv(),
        csv
    );
}

/// The generic first-contact and degeneracy rules for unequal face half-lengths (module docs of
/// `pair`): exactly one candidate is the first contact off the degenerate curves, its corner lands
/// on the struck face, and it has the largest `h` among the candidates that land on their face.
#[test]
fn unequal_faces_first_contact_is_largest_valid_h() {
    let straight = DeckShape::Straight(StraightDeck::new(40.0, 10.0, 0.5, 2500.0).unwrap());
    let skewed =
        DeckShape::Skewed(SkewedDeck::new(40.0, 10.0, f64::to_radians(35.0), 0.5, 2500.0).unwrap());
    let pair = DeckPair::new(skewed, straight).unwrap();
    let (w1, w2) = (5.0 / f64::to_radians(35.0).cos(), 5.0);
    let mut tested = 0;
    for i in -20..=20 {
        for j in -20..=20 {
            let (t1, t2) = ((i as f64 * 0.9).to_radians(), (j as f64 * 1.3).to_radians());
            if pair_degeneracy(w1, w2, t1, t2).is_some() {
                continue;
            }
            let configs: Vec<_> = ContactCase::ALL
                .iter()
                .map(|&c| pair.configuration(c, t1, t2, SigmaMode::Exact).unwrap())
                .collect();
            let firsts: Vec<_> = configs.iter().filter(|c| c.first_contact).collect();
            assert_eq!(firsts.len(), 1, "θ = ({i}, {j})");
            let f = firsts[0];
            let wb = if f.case.striking() == pounding::geometry::DeckId::One {
                w2
            } else {
                w1
            };
            assert!(f.sigma_exact.abs() <= wb);
            let valid_max = configs
                .iter()
                .filter(|c| {
                    let wb = if c.case.striking() == pounding::geometry::DeckId::One {
                        w2
                    } else {
                        w1
                    };
                    c.sigma_exact.abs() <= wb
                })
                .map(|c| c.h)
                .fold(f64::NEG_INFINITY, f64::max);
            assert_eq!(f.h, valid_max);
            assert!(pair_first_contact(f.case, w1, w2, t1, t2));
            tested += 1;
        }
    }
    assert!(tested > 1500);
    // At θ1 = −θ2 the shorter face's corner lands strictly inside the longer face: regular.
    let t = 0.05;
    assert!(pair_degeneracy(w1, w2, t, -t).is_none());
    let d = pair_degeneracy(w1, w2, 0.0, (w2 / w1).acos());
    assert_eq!(d, None, "w1 cos 0 = w1 > w2 cos θ2 always");
    let d = pair_degeneracy(w1, w2, (w2 / w1).acos(), 0.0);
    assert_eq!(d, Some(pounding::geometry::Degeneracy::CornerCorner));
}

/// Study cells of skewed decks against the generic multi-contact impact solver
/// (`pounding::impact::solve`, its own Delassus assembly): with deck 2 at rest and deck 1 moving so
/// that `γ_N⁻ = −1`, `γ_T⁻ = −r`, the solver's mode is outward slip below `L`, stick inside
/// `[L, U]` and inward slip above `U`.
#[test]
fn skew_cells_agree_with_generic_impact_solver() {
    use pounding::impact::{
        ContactMode, ContactSpec, ImpactProblem, ImpactSettings, RigidBody, solve,
    };
    use pounding::study::cell::{Geometry, test_ratios};
    let text = r#"
[decks]
shape = "skew"
l1_m = [40.0]
l2_m = [25.0]
skew_deg = [35.0]
[impact]
mu = [0.5]
[grid]
theta1_deg = { start = -5.0, stop = 5.0, step = 2.5 }
theta2_deg = { start = -5.0, stop = 5.0, step = 2.0 }
"#;
    let sc = Scenario::from_toml(text, "t").unwrap();
    let Geometry::Pair(pair) = sc.geometry([0, 0, 0, 0]).unwrap() else {
        panic!("a skew study builds a deck pair")
    };
    let rows = compute_rows(&sc, Shard::ALL, &none).unwrap();
    let (p1, p2) = (pair.deck1.mass_properties(), pair.deck2.mass_properties());
    let mut checked = 0;
    for row in rows.iter().filter(|r| r.cell.first_contact) {
        let p = sc.params(&row.key);
        let cfg = pair
            .configuration(
                p.case,
                p.theta1_deg.to_radians(),
                p.theta2_deg.to_radians(),
                SigmaMode::Exact,
            )
            .unwrap();
        let law = ImpactLaw::new(p.mu, p.eps).unwrap();
        for r in test_ratios(row.cell.lower, row.cell.upper) {
            let v1 = -cfg.normal - r * cfg.tangent;
            let bodies = vec![
                RigidBody {
                    name: "deck1".into(),
                    mass: p1.mass,
                    inertia: p1.inertia,
                    position: cfg.centroid1,
                    velocity: v1,
                    omega: 0.0,
                },
                RigidBody {
                    name: "deck2".into(),
                    mass: p2.mass,
                    inertia: p2.inertia,
                    position: cfg.centroid2,
                    velocity: Vector::zeros(),
                    omega: 0.0,
                },
            ];
            let contacts = vec![ContactSpec {
                body_a: "deck1".into(),
                body_b: Some("deck2".into()),
                point: cfg.point,
                normal: cfg.normal,
                mu: law.mu(),
                restitution: law.eps(),
            }];
            let sol = solve(
                &ImpactProblem::new(bodies, contacts).unwrap(),
                &ImpactSettings::default(),
            );
            let c = &sol.contacts[0];
            assert!((c.gamma_n_pre + 1.0).abs() < 1e-12 && (c.gamma_t_pre + r).abs() < 1e-9);
            let expected = if r < row.cell.lower {
                ContactMode::SlipPositive
            } else if r > row.cell.upper {
                ContactMode::SlipNegative
            } else {
                ContactMode::Stick
            };
            assert_eq!(c.mode, expected, "{p:?} r = {r}");
            checked += 1;
        }
    }
    assert!(checked > 60, "{checked}");
}
