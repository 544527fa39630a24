//! One geometry path: the library's configuration (spec §5), force directions (spec §6), Delassus
//! matrix (spec §7) and mass properties (spec §3) agree to rounding (relative 1e-12) with a
//! reference written out here from the spec's formulas, over random curved, straight and skewed
//! decks and rotations.
//!
//! The reference is the code of the former separate paths (the curved-only
//! `SArrangement::configuration` with `contact::delassus_with` and the sector `MassProperties`,
//! and the former generic pair with `pair::delassus_planar` and `PlanarMassProperties`). These
//! tests were run against both old paths before they were merged into one
//! (`pair::configuration_with`, `contact::delassus_with`, one `geometry::MassProperties`); the
//! reference stays here as an independent oracle for the merged path, through both its
//! curved-deck wrapper (`SArrangement`) and the general `DeckPair`.

use pounding::geometry::{ContactCase, Degeneracy, ImpactConfiguration, SigmaMode};
use pounding::math::Vector;
use pounding::pair::{DeckPair, SArrangement};
use pounding::shape::{Deck, DeckShape, SkewedDeck, StraightDeck};
use proptest::prelude::*;

const TOL: f64 = 1e-12;

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= TOL * scale.max(a.abs()).max(b.abs())
}

fn close_v(a: Vector, b: Vector, scale: f64) -> bool {
    close(a.x, b.x, scale) && close(a.y, b.y, scale)
}

/// Reference body data: joint-face half-length, body centroid, mass, polar moment.
#[derive(Debug, Clone, Copy)]
struct RefBody {
    w: f64,
    g: Vector,
    m: f64,
    i: f64,
}

/// Spec §3: `A = βRW`, `m = ρtA`, `r_c = (R + W²/(12R)) sin(β/2)/(β/2)`, `X = r_c cos(β/2)`,
/// `Y = r_c sin(β/2)`, `I = m(R² + W²/4 − r_c²)`; body centroid `(R − X, Y)` (spec §4).
fn ref_curved(r: f64, b: f64, w: f64, t: f64, rho: f64) -> (RefBody, f64) {
    let area = b * r * w;
    let mass = rho * t * area;
    let half = 0.5 * b;
    let (s, c) = half.sin_cos();
    let rc = (r + w * w / (12.0 * r)) * s / half;
    let inertia = mass * (r * r + 0.25 * w * w - rc * rc);
    let body = RefBody {
        w: 0.5 * w,
        g: Vector::new(r - rc * c, rc * s),
        m: mass,
        i: inertia,
    };
    (body, area)
}

/// Parallelogram with face `W/cos θ_s`, axis `L(−sin θ_s, cos θ_s)`: `A = LW`,
/// `I = m(L² + W²/cos²θ_s)/12`, centroid `(L/2) e`.
fn ref_skewed(l: f64, w: f64, skew: f64, t: f64, rho: f64) -> (RefBody, f64) {
    let area = l * w;
    let mass = rho * t * area;
    let face = w / skew.cos();
    let body = RefBody {
        w: 0.5 * face,
        g: Vector::new(-skew.sin(), skew.cos()) * (0.5 * l),
        m: mass,
        i: mass * (l * l + face * face) / 12.0,
    };
    (body, area)
}

/// The spec §5.3 table generalised to face half-lengths `w1`, `w2` (pair module docs), the
/// joint-anchored placement (spec §5.2) and spec §6–§7. Returns `None` off the single-impact
/// domain (degenerate poses), which the caller checks separately.
fn ref_config(
    b1: &RefBody,
    b2: &RefBody,
    case: ContactCase,
    t1: f64,
    t2: f64,
    mode: SigmaMode,
) -> (f64, f64, f64, [Vector; 6], [f64; 3]) {
    let (w1, w2) = (b1.w, b2.w);
    let (s1, c1) = t1.sin_cos();
    let (s2, c2) = t2.sin_cos();
    let s12 = (t1 - t2).sin();
    let (h, sigma_exact, corner_x, end_sigma) = match case {
        ContactCase::Deck1Inner => (-w1 * s12 / c2, w1 * c1 / c2, w1, w2),
        ContactCase::Deck1Outer => (w1 * s12 / c2, -w1 * c1 / c2, -w1, -w2),
        ContactCase::Deck2Inner => (w2 * s12 / c1, w2 * c2 / c1, -w2, w1),
        ContactCase::Deck2Outer => (-w2 * s12 / c1, -w2 * c2 / c1, w2, -w1),
    };
    let sigma = match mode {
        SigmaMode::Exact => sigma_exact,
        SigmaMode::End => end_sigma,
    };
    let rot = |s: f64, c: f64, p: Vector| Vector::new(c * p.x - s * p.y, s * p.x + c * p.y);
    let m1 = Vector::new(0.0, h);
    let g1 = m1 + rot(s1, c1, b1.g);
    let g2 = rot(s2, c2, -b2.g);
    let deck1_strikes = matches!(case, ContactCase::Deck1Inner | ContactCase::Deck1Outer);
    let (point, nu, struck) = if deck1_strikes {
        let p = m1 + rot(s1, c1, Vector::new(corner_x, 0.0));
        (p, Vector::new(-s2, c2), Vector::new(c2, s2) * sigma)
    } else {
        let p = rot(s2, c2, Vector::new(corner_x, 0.0));
        (p, Vector::new(-s1, c1), m1 + Vector::new(-c1, -s1) * sigma)
    };
    let tau = Vector::new(-nu.y, nu.x); // τ = perp(ν) = (−cos θ_b, −sin θ_b)
    let (c1p, c2p) = if deck1_strikes {
        (point, struck)
    } else {
        (struck, point)
    };
    let cr = |a: Vector, b: Vector| a.x * b.y - a.y * b.x;
    let (r1, r2) = (c1p - g1, c2p - g2);
    let (a1, bb1, a2, bb2) = (cr(r1, nu), cr(r1, tau), cr(r2, nu), cr(r2, tau));
    let inv_m = 1.0 / b1.m + 1.0 / b2.m;
    let g = [
        inv_m + a1 * a1 / b1.i + a2 * a2 / b2.i,
        a1 * bb1 / b1.i + a2 * bb2 / b2.i,
        inv_m + bb1 * bb1 / b1.i + bb2 * bb2 / b2.i,
    ];
    (h, sigma, sigma_exact, [point, struck, nu, tau, g1, g2], g)
}

/// Compares one library configuration (and its Delassus numbers `g`) with the reference.
fn check(
    lib: &ImpactConfiguration,
    g: [f64; 3],
    reference: (f64, f64, f64, [Vector; 6], [f64; 3]),
    scale: f64,
) -> Result<(), TestCaseError> {
    let (h, sigma, sigma_exact, v, gr) = reference;
    prop_assert!(close(lib.h, h, scale), "h {} vs {h}", lib.h);
    prop_assert!(close(lib.sigma, sigma, scale), "σ {} vs {sigma}", lib.sigma);
    prop_assert!(close(lib.sigma_exact, sigma_exact, scale));
    prop_assert_eq!(lib.end_closes, lib.h > 0.0);
    let lv = [
        lib.point,
        lib.struck_point,
        lib.normal,
        lib.tangent,
        lib.centroid1,
        lib.centroid2,
    ];
    for (k, (a, b)) in lv.iter().zip(v).enumerate() {
        let s = if k == 2 || k == 3 { 1.0 } else { scale };
        prop_assert!(close_v(*a, b, s), "vector {k}: {a:?} vs {b:?}");
    }
    for (k, (a, b)) in g.iter().zip(gr).enumerate() {
        prop_assert!(close(*a, b, gr[0]), "G[{k}]: {a} vs {b}");
    }
    Ok(())
}

fn angle() -> impl Strategy<Value = f64> {
    (-80.0f64..80.0).prop_map(f64::to_radians)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Curved decks: the sector mass properties (spec §3) and, for every case and σ mode, the S
    /// arrangement and the generic pair of two curved shapes agree with the reference.
    #[test]
    fn curved_path_agrees_with_spec_reference(
        r1 in 6.0f64..2000.0, r2 in 6.0f64..2000.0,
        b1 in 5.0f64..300.0, b2 in 5.0f64..300.0,
        w in 1.0f64..12.0, t in 0.1f64..3.0, rho in 500.0f64..8000.0,
        t1 in angle(), t2 in angle(),
    ) {
        let (b1, b2) = (b1.to_radians(), b2.to_radians());
        let d1 = Deck::new(r1, b1, w, t, rho).unwrap();
        let d2 = Deck::new(r2, b2, w, t, rho).unwrap();
        let (ref1, area1) = ref_curved(r1, b1, w, t, rho);
        let (ref2, _) = ref_curved(r2, b2, w, t, rho);
        let p1 = DeckShape::Curved(d1).mass_properties();
        prop_assert!(close(p1.area, area1, area1));
        prop_assert!(close(p1.mass, ref1.m, ref1.m));
        prop_assert!(close(p1.inertia, ref1.i, ref1.i));
        prop_assert!(close_v(p1.centroid, ref1.g, r1));
        let s = SArrangement::new(d1, d2).unwrap();
        let pair = DeckPair::new(DeckShape::Curved(d1), DeckShape::Curved(d2)).unwrap();
        let scale = r1.max(r2);
        for case in ContactCase::ALL {
            for mode in [SigmaMode::Exact, SigmaMode::End] {
                let a = s.configuration(case, t1, t2, mode);
                let b = pair.configuration(case, t1, t2, mode);
                match (a, b) {
                    (Ok(a), Ok(b)) => {
                        prop_assert_eq!(a.first_contact, b.first_contact);
                        let r = ref_config(&ref1, &ref2, case, t1, t2, mode);
                        let ga = s.delassus(&a);
                        check(&a, [ga.nn, ga.nt, ga.tt], r, scale)?;
                        let gb = pair.delassus(&b);
                        check(&b, [gb.nn, gb.nt, gb.tt], r, scale)?;
                    }
                    (Err(x), Err(y)) => prop_assert_eq!(x, y),
                    (a, b) => prop_assert!(false, "{a:?} vs {b:?}"),
                }
            }
        }
    }

    /// Straight and skewed decks (common skew, independent lengths): mass properties of the
    /// parallelogram and the pair configuration / Delassus matrix agree with the reference.
    #[test]
    fn straight_and_skewed_path_agrees_with_reference(
        l1 in 5.0f64..200.0, l2 in 5.0f64..200.0, w in 1.0f64..30.0,
        skew_deg in 0.0f64..60.0, straight in any::<bool>(),
        t in 0.1f64..3.0, rho in 500.0f64..8000.0,
        t1 in angle(), t2 in angle(),
    ) {
        let skew = if straight { 0.0 } else { skew_deg.to_radians() };
        let mk = |l: f64| if straight {
            DeckShape::Straight(StraightDeck::new(l, w, t, rho).unwrap())
        } else {
            DeckShape::Skewed(SkewedDeck::new(l, w, skew, t, rho).unwrap())
        };
        let (s1, s2) = (mk(l1), mk(l2));
        let (ref1, area1) = ref_skewed(l1, w, skew, t, rho);
        let (ref2, _) = ref_skewed(l2, w, skew, t, rho);
        let p1 = s1.mass_properties();
        prop_assert!(close(p1.area, area1, area1));
        prop_assert!(close(p1.mass, ref1.m, ref1.m));
        prop_assert!(close(p1.inertia, ref1.i, ref1.i));
        prop_assert!(close_v(p1.centroid, ref1.g, l1));
        let pair = DeckPair::new(s1, s2).unwrap();
        let scale = l1.max(l2).max(ref1.w);
        for case in ContactCase::ALL {
            for mode in [SigmaMode::Exact, SigmaMode::End] {
                match pair.configuration(case, t1, t2, mode) {
                    Ok(c) => {
                        let r = ref_config(&ref1, &ref2, case, t1, t2, mode);
                        let g = pair.delassus(&c);
                        check(&c, [g.nn, g.nt, g.tt], r, scale)?;
                    }
                    Err(d) => prop_assert!(
                        (d == Degeneracy::ParallelFaces && (t1 - t2).abs() <= 1e-12)
                            || (d == Degeneracy::CornerCorner && (t1 + t2).abs() <= 1e-12)
                    ),
                }
            }
        }
    }
}
