//! Deck shapes (straight, skewed, curved in one body frame) and deck–abutment impacts.
//!
//! Independent evidence: shoelace integration of the outline formed by the shapes' own corners
//! (curved: a fine polygon of the two arcs), closed forms of rectangles and parallelograms,
//! geometric identities (interior angles, widths, face lengths), the analytic single-impact
//! solution of spec §9, and the hand derivation of the frictionless double impact.

use pounding::analytic::{self, ImpactLaw, SlipMode};
use pounding::geometry::GeometryError;
use pounding::impact::{self, ContactMode, ImpactProblem, ImpactSettings, ImpactStatus, RigidBody};
use pounding::math::{Vector, cross, rotate};
use pounding::shape::Deck;
use pounding::shape::{
    Abutment, DeckEnd, DeckShape, SkewedDeck, StraightDeck, abutment_contact, abutment_delassus,
    abutment_problem, frictionless_pivot,
};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

/// Area, centroid and polar moment about the centroid of a simple polygon (either orientation),
/// by the shoelace formulas.
fn shoelace(poly: &[Vector]) -> (f64, Vector, f64) {
    let (mut a, mut cx, mut cy, mut j0) = (0.0, 0.0, 0.0, 0.0);
    for i in 0..poly.len() {
        let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
        let c = p.x * q.y - q.x * p.y;
        a += c;
        cx += (p.x + q.x) * c;
        cy += (p.y + q.y) * c;
        j0 += c * (p.x * p.x + p.x * q.x + q.x * q.x + p.y * p.y + p.y * q.y + q.y * q.y);
    }
    let area = a / 2.0;
    let g = Vector::new(cx / (6.0 * area), cy / (6.0 * area));
    let j_origin = j0 / 12.0;
    (area.abs(), g, (j_origin - area * g.norm_squared()).abs())
}

fn outline(shape: &DeckShape) -> Vec<Vector> {
    let j = shape.end_face(DeckEnd::Joint);
    let f = shape.end_face(DeckEnd::Far);
    vec![j.corners[0], j.corners[1], f.corners[0], f.corners[1]]
}

fn skewed(l: f64, w: f64, deg: f64) -> SkewedDeck {
    SkewedDeck::new(l, w, deg.to_radians(), 0.5, 2500.0).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Parallelogram mass properties (closed forms) against shoelace integration of the outline
    /// built from the shape's own corners, and the outline's geometry against its definition.
    #[test]
    fn skewed_mass_properties_match_shoelace(l in 5.0f64..200.0, w in 2.0f64..40.0,
                                             deg in 0.0f64..80.0, rho_t in 0.1f64..3000.0) {
        let d = SkewedDeck::new(l, w, deg.to_radians(), 1.0, rho_t).unwrap();
        let shape = DeckShape::Skewed(d);
        let p = shape.mass_properties();
        let (area, g, j) = shoelace(&outline(&shape));
        prop_assert!(rel(p.area, area) < 1e-12);
        prop_assert!(rel(p.mass, rho_t * area) < 1e-12);
        prop_assert!((p.centroid - g).norm() < 1e-9 * l);
        prop_assert!(rel(p.inertia, rho_t * j) < 1e-10);
        // geometry: face length W/cos, side length L, perpendicular width W, interior angles
        let (jf, ff) = (shape.end_face(DeckEnd::Joint), shape.end_face(DeckEnd::Far));
        let c = deg.to_radians().cos();
        prop_assert!(rel(jf.length(), w / c) < 1e-12 && rel(ff.length(), w / c) < 1e-12);
        prop_assert!(rel((ff.midpoint() - jf.midpoint()).norm(), l) < 1e-12);
        let axis = d.axis();
        let side = ff.corners[1] - jf.corners[0];
        prop_assert!(rel(side.norm(), l) < 1e-12 && (side.normalize() - axis).norm() < 1e-12);
        // distance between the two side lines (through jc0 and jc1, direction e) is W
        let dist = cross(&axis, &(jf.corners[1] - jf.corners[0])).abs();
        prop_assert!(rel(dist, w) < 1e-12);
        let poly = outline(&shape);
        for (i, want) in [(0usize, FRAC_PI_2 - deg.to_radians()), (1, FRAC_PI_2 + deg.to_radians()),
                          (2, FRAC_PI_2 - deg.to_radians()), (3, FRAC_PI_2 + deg.to_radians())] {
            let (prev, here, next) = (poly[(i + 3) % 4], poly[i], poly[(i + 1) % 4]);
            let (u, v) = (prev - here, next - here);
            let ang = cross(&u, &v).abs().atan2(u.dot(&v));
            prop_assert!((ang - want).abs() < 1e-10, "corner {i}: {ang} vs {want}");
            let (end, k) = if i < 2 { (DeckEnd::Joint, i) } else { (DeckEnd::Far, i - 2) };
            prop_assert!((shape.corner_angle(end, k) - want).abs() < 1e-12);
        }
        // outward normals: unit, perpendicular to the face, pointing away from the centroid
        for f in [jf, ff] {
            let t = f.corners[1] - f.corners[0];
            prop_assert!((f.outward_normal.norm() - 1.0).abs() < 1e-12);
            prop_assert!(f.outward_normal.dot(&t).abs() < 1e-9 * t.norm());
            prop_assert!((f.midpoint() - p.centroid).dot(&f.outward_normal) > 0.0);
        }
        // clockwise outline (body to the right of c0 -> c1): negative signed area
        let signed: f64 = (0..4).map(|i| cross(&poly[i], &poly[(i + 1) % 4])).sum::<f64>() / 2.0;
        prop_assert!(signed < 0.0);
    }
}

/// Rectangle closed forms: `A = LW`, `G = (0, L/2)`, `I = m (L² + W²)/12`, and the straight deck
/// equals the skewed deck at θ_s = 0.
#[test]
fn straight_deck_closed_forms() {
    for (l, w) in [(30.0, 10.0), (100.0, 12.5), (7.0, 20.0)] {
        let d = StraightDeck::new(l, w, 0.4, 2400.0).unwrap();
        let s = DeckShape::Straight(d);
        let p = s.mass_properties();
        let m = 0.4 * 2400.0 * l * w;
        assert!(rel(p.area, l * w) < 1e-15);
        assert!(rel(p.mass, m) < 1e-15);
        assert!((p.centroid - Vector::new(0.0, l / 2.0)).norm() < 1e-12);
        assert!(rel(p.inertia, m * (l * l + w * w) / 12.0) < 1e-14);
        let (a, g, j) = shoelace(&outline(&s));
        assert!(rel(a, l * w) < 1e-14 && (g - p.centroid).norm() < 1e-12);
        assert!(rel(0.4 * 2400.0 * j, p.inertia) < 1e-12);
        assert_eq!(
            s.mass_properties(),
            DeckShape::Skewed(d.as_skewed()).mass_properties()
        );
        let jf = s.end_face(DeckEnd::Joint);
        assert_eq!(
            jf.corners,
            [Vector::new(w / 2.0, 0.0), Vector::new(-w / 2.0, 0.0)]
        );
        assert_eq!(jf.outward_normal, Vector::new(0.0, -1.0));
        let ff = s.end_face(DeckEnd::Far);
        assert_eq!(
            ff.corners,
            [Vector::new(-w / 2.0, l), Vector::new(w / 2.0, l)]
        );
        assert_eq!(ff.outward_normal, Vector::new(0.0, 1.0));
        assert_eq!(s.axis_direction(DeckEnd::Far), Vector::new(0.0, 1.0));
    }
    // a parallelogram's polar moment is m (|a|² + |b|²)/12 with its edge vectors, not the rectangle's
    let d = skewed(40.0, 10.0, 30.0);
    let p = d.mass_properties();
    let c = 30f64.to_radians().cos();
    assert!(rel(p.inertia, p.mass * (1600.0 + 100.0 / (c * c)) / 12.0) < 1e-14);
    assert!(p.inertia > p.mass * (1600.0 + 100.0) / 12.0);
}

/// The curved deck in the common body frame: centroid `(R − X_m, Y_m)` and `I` against a
/// 20 000-segment polygon of the two arcs; far face on the radial line at `φ = β`.
#[test]
fn curved_deck_in_body_frame_matches_polygon() {
    for (r, beta_deg) in [(100.0, 60.0), (200.0, 120.0), (40.0, 250.0)] {
        let w = 10.0;
        let d = Deck::new(r, f64::to_radians(beta_deg), w, 1.0, 1.0).unwrap();
        let shape = DeckShape::Curved(d);
        let p = shape.mass_properties();
        let n = 10_000;
        let beta = d.angle;
        let pt = |rr: f64, phi: f64| Vector::new(r - rr * phi.cos(), rr * phi.sin());
        let mut poly = Vec::with_capacity(2 * n + 2);
        for i in 0..=n {
            poly.push(pt(r + w / 2.0, beta * i as f64 / n as f64));
        }
        for i in (0..=n).rev() {
            poly.push(pt(r - w / 2.0, beta * i as f64 / n as f64));
        }
        let (a, g, j) = shoelace(&poly);
        assert!(rel(a, p.area) < 1e-7, "area {a} vs {}", p.area);
        assert!((g - p.centroid).norm() < 1e-7 * r);
        assert!(rel(j, p.inertia) < 1e-6, "I {j} vs {}", p.inertia);
        let jf = shape.end_face(DeckEnd::Joint);
        assert_eq!(jf.corners[0], Vector::new(w / 2.0, 0.0)); // inner corner (spec §4)
        let ff = shape.end_face(DeckEnd::Far);
        assert!((ff.corners[0] - pt(r + w / 2.0, beta)).norm() < 1e-12);
        assert!((ff.corners[1] - pt(r - w / 2.0, beta)).norm() < 1e-12);
        let t = ff.corners[1] - ff.corners[0];
        assert!(ff.outward_normal.dot(&t).abs() < 1e-9);
        assert!((ff.midpoint() - p.centroid).dot(&ff.outward_normal) > 0.0);
        // the outward normal is the direction of increasing φ (out of the sector)
        let beyond = ff.midpoint() + 1e-3 * ff.outward_normal;
        let phi = beyond.y.atan2(r - beyond.x);
        let phi = if phi < 0.0 { phi + 2.0 * PI } else { phi };
        assert!(phi > beta, "{phi} vs {beta}");
    }
}

/// Decks in a row: deck 2 is the body frame turned by π; its joint corners coincide with deck 1's
/// (acute meets obtuse) and the axes are collinear, so the strip is one parallelogram.
#[test]
fn decks_in_a_row_meet_face_to_face() {
    let d = DeckShape::Skewed(skewed(30.0, 10.0, 25.0));
    let j = d.end_face(DeckEnd::Joint);
    let j2: Vec<Vector> = j.corners.iter().map(|c| rotate(c, PI)).collect();
    assert!((j2[0] - j.corners[1]).norm() < 1e-12 && (j2[1] - j.corners[0]).norm() < 1e-12);
    let e1 = d.axis_direction(DeckEnd::Far);
    let e2 = rotate(&e1, PI);
    assert!(cross(&e1, &e2).abs() < 1e-15 && e1.dot(&e2) < 0.0);
    // deck 2's outward joint normal is +y: the two joint faces face each other
    assert!((rotate(&j.outward_normal, PI) - Vector::new(0.0, 1.0)).norm() < 1e-15);
}

#[test]
fn bad_shape_input_names_the_parameter() {
    let name = |e: GeometryError| match e {
        GeometryError::InvalidParameter { name, .. } => name,
    };
    let r = |x: f64| x.to_radians();
    let cases: Vec<(Result<SkewedDeck, GeometryError>, &str)> = vec![
        (SkewedDeck::new(0.0, 10.0, 0.2, 1.0, 1.0), "length"),
        (SkewedDeck::new(-3.0, 10.0, 0.2, 1.0, 1.0), "length"),
        (SkewedDeck::new(f64::NAN, 10.0, 0.2, 1.0, 1.0), "length"),
        (SkewedDeck::new(30.0, 0.0, 0.2, 1.0, 1.0), "width"),
        (SkewedDeck::new(30.0, f64::NAN, 0.2, 1.0, 1.0), "width"),
        (SkewedDeck::new(30.0, 10.0, r(90.0), 1.0, 1.0), "skew"),
        (SkewedDeck::new(30.0, 10.0, r(95.0), 1.0, 1.0), "skew"),
        (SkewedDeck::new(30.0, 10.0, r(-1.0), 1.0, 1.0), "skew"),
        (SkewedDeck::new(30.0, 10.0, f64::NAN, 1.0, 1.0), "skew"),
        (SkewedDeck::new(30.0, 10.0, 0.2, 0.0, 1.0), "thickness"),
        (
            SkewedDeck::new(30.0, 10.0, 0.2, 1.0, f64::INFINITY),
            "density",
        ),
    ];
    for (res, want) in cases {
        assert_eq!(name(res.unwrap_err()), want);
    }
    assert!(SkewedDeck::new(30.0, 10.0, 0.0, 1.0, 1.0).is_ok());
    assert!(SkewedDeck::new(30.0, 10.0, r(89.9), 1.0, 1.0).is_ok());
    assert_eq!(
        name(StraightDeck::new(-1.0, 10.0, 1.0, 1.0).unwrap_err()),
        "length"
    );
    assert_eq!(
        name(StraightDeck::new(10.0, f64::NAN, 1.0, 1.0).unwrap_err()),
        "width"
    );
    for g in [-0.01, f64::NAN, f64::INFINITY] {
        assert_eq!(name(Abutment::new(DeckEnd::Far, g).unwrap_err()), "gap");
    }
    let err = SkewedDeck::new(30.0, 10.0, r(90.0), 1.0, 1.0).unwrap_err();
    assert!(err.to_string().contains("skew") && err.to_string().contains("90"));
}

/// After travelling `travel_to_contact` along the axis, both corners of the end face lie on the
/// abutment face line.
#[test]
fn abutment_travel_closes_the_gap() {
    for (shape, end) in [
        (DeckShape::Skewed(skewed(30.0, 10.0, 35.0)), DeckEnd::Far),
        (DeckShape::Skewed(skewed(30.0, 10.0, 35.0)), DeckEnd::Joint),
        (
            DeckShape::Straight(StraightDeck::new(30.0, 10.0, 1.0, 1.0).unwrap()),
            DeckEnd::Far,
        ),
    ] {
        let a = Abutment::new(end, 0.08).unwrap();
        let d = a.travel_to_contact(&shape);
        let f = shape.end_face(end);
        let e = shape.axis_direction(end);
        for c in f.corners {
            let moved = c + d * e;
            assert!((moved - a.face_point(&shape)).dot(&f.outward_normal).abs() < 1e-14);
        }
        if let DeckShape::Skewed(s) = shape {
            assert!(rel(d, 0.08 / s.skew.cos()) < 1e-14);
        }
    }
}

/// Lever arms and Delassus entries of a corner against the abutment: closed forms for the far face
/// of a skewed deck and the column-by-column definition `G e_k = Δγ` for a unit impulse, computed
/// from the rigid-body velocity field `v + ω ẑ × r`.
#[test]
fn abutment_delassus_entries() {
    for deg in [0.0, 10.0, 30.0, 50.0, 75.0] {
        let sd = skewed(36.0, 11.0, deg);
        let shape = DeckShape::Skewed(sd);
        let p = shape.mass_properties();
        let (s, c) = f64::to_radians(deg).sin_cos();
        let (l, w) = (36.0, 11.0);
        let want_a = [w / (2.0 * c) + l / 2.0 * s, l / 2.0 * s - w / (2.0 * c)];
        for end in [DeckEnd::Far, DeckEnd::Joint] {
            for (k, &want) in want_a.iter().enumerate() {
                let ct = abutment_contact(&shape, end, k);
                // point symmetry of the parallelogram: both ends have the same arms
                assert!((ct.arm_n - want).abs() < 1e-12 * l, "{deg} {end:?} {k}");
                assert!((ct.arm_t + l / 2.0 * c).abs() < 1e-12 * l);
                let g = abutment_delassus(&shape, end, k);
                let r = ct.point - p.centroid;
                let dgamma = |imp: Vector| {
                    let dv = imp / p.mass;
                    let dw = cross(&r, &imp) / p.inertia;
                    let dvp = dv + dw * Vector::new(-r.y, r.x);
                    (dvp.dot(&ct.normal), dvp.dot(&ct.tangent))
                };
                let (nn, tn) = dgamma(ct.normal);
                let (nt, tt) = dgamma(ct.tangent);
                assert!(rel(g.nn, nn) < 1e-12 && rel(g.tt, tt) < 1e-12);
                assert!((g.nt - nt).abs() < 1e-12 * g.nn && (g.nt - tn).abs() < 1e-12 * g.nn);
            }
        }
    }
}

/// Velocity of the deck centroid giving `γ_N⁻ = −1`, `γ_T⁻ = −r` at a corner (ω⁻ = 0).
fn approach(shape: &DeckShape, end: DeckEnd, k: usize, r: f64) -> Vector {
    let c = abutment_contact(shape, end, k);
    -c.normal - r * c.tangent
}

/// Single skew corner against the abutment: the LCP's stick/slip transitions (found by bisection
/// in r through the generic impact solver, ground = body b) are the spec §9 bounds `L`, `U`
/// computed from the Delassus entries; impulses agree with the analytic solution.
#[test]
fn single_corner_stick_interval_matches_analytic() {
    let settings = ImpactSettings::default();
    let mut checked = 0;
    for (deg, mu, eps) in [
        (20.0, 0.3, 0.5),
        (45.0, 0.5, 0.0),
        (60.0, 1.0, 0.8),
        (5.0, 0.2, 1.0),
    ] {
        let shape = DeckShape::Skewed(skewed(30.0, 12.0, deg));
        let law = ImpactLaw::new(mu, eps).unwrap();
        for end in [DeckEnd::Far, DeckEnd::Joint] {
            for k in 0..2 {
                let g = abutment_delassus(&shape, end, k);
                let b = analytic::stick_interval(&g, &law);
                let mode_at = |r: f64| {
                    let pr =
                        abutment_problem(&shape, end, &[k], approach(&shape, end, k, r), 0.0, &law)
                            .unwrap();
                    let s = impact::solve(&pr, &settings);
                    assert!(matches!(
                        s.status,
                        ImpactStatus::Solved | ImpactStatus::SolvedByFallback
                    ));
                    // γ⁻ as the module sees it
                    assert!((s.contacts[0].gamma_n_pre + 1.0).abs() < 1e-12);
                    assert!((s.contacts[0].gamma_t_pre + r).abs() < 1e-12);
                    let a = analytic::single_impact(&g, &law, -1.0, -r);
                    assert!(rel(s.contacts[0].normal_impulse, a.normal_impulse) < 1e-8);
                    assert!(
                        (s.contacts[0].tangential_impulse - a.tangential_impulse).abs()
                            < 1e-8 * a.normal_impulse
                    );
                    assert!((s.contacts[0].gamma_n_post - eps).abs() < 1e-9);
                    s.contacts[0].mode
                };
                let find = |mut lo: f64, mut hi: f64| {
                    let m_lo = mode_at(lo);
                    assert_ne!(m_lo, mode_at(hi));
                    for _ in 0..60 {
                        let mid = 0.5 * (lo + hi);
                        if mode_at(mid) == m_lo {
                            lo = mid
                        } else {
                            hi = mid
                        }
                    }
                    0.5 * (lo + hi)
                };
                assert!(b.lower.is_finite() && b.upper.is_finite());
                let mid = 0.5 * (b.lower + b.upper);
                assert_eq!(mode_at(mid), ContactMode::Stick);
                assert_eq!(mode_at(b.lower - 1.0), ContactMode::SlipPositive);
                assert_eq!(mode_at(b.upper + 1.0), ContactMode::SlipNegative);
                let l_found = find(b.lower - 1.0, mid);
                let u_found = find(mid, b.upper + 1.0);
                assert!(
                    (l_found - b.lower).abs() < 1e-7 * (1.0 + b.lower.abs()),
                    "{l_found} vs {}",
                    b.lower
                );
                assert!(
                    (u_found - b.upper).abs() < 1e-7 * (1.0 + b.upper.abs()),
                    "{u_found} vs {}",
                    b.upper
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 16);
}

/// A purely longitudinal approach of a skewed deck gives the corner ratio `r = tan θ_s`, and the
/// analytic classification of the single-corner impact at that ratio matches the LCP.
#[test]
fn longitudinal_approach_ratio_is_tan_skew() {
    let law = ImpactLaw::new(0.4, 0.5).unwrap();
    for deg in [0.0, 15.0, 40.0, 70.0] {
        let shape = DeckShape::Skewed(skewed(30.0, 10.0, deg));
        for end in [DeckEnd::Far, DeckEnd::Joint] {
            let v = 2.0 * shape.axis_direction(end);
            for k in 0..2 {
                let pr = abutment_problem(&shape, end, &[k], v, 0.0, &law).unwrap();
                let s = impact::solve(&pr, &ImpactSettings::default());
                let c = s.contacts[0];
                let r = c.gamma_t_pre / c.gamma_n_pre;
                assert!((r - f64::to_radians(deg).tan()).abs() < 1e-12, "{deg}: {r}");
                let g = abutment_delassus(&shape, end, k);
                let a = analytic::single_impact(&g, &law, c.gamma_n_pre, c.gamma_t_pre);
                let want = match a.mode {
                    SlipMode::Stick => ContactMode::Stick,
                    SlipMode::SlipOutward => ContactMode::SlipPositive,
                    SlipMode::SlipInward => ContactMode::SlipNegative,
                };
                assert_eq!(c.mode, want);
            }
        }
    }
}

/// Solves the frictionless two-corner impact of a longitudinally approaching deck, optionally with
/// the body's inertia replaced.
fn both_corners(
    shape: &DeckShape,
    end: DeckEnd,
    eps: f64,
    inertia: Option<f64>,
) -> impact::ImpactSolution {
    let law = ImpactLaw::new(0.0, eps).unwrap();
    let v = 1.5 * shape.axis_direction(end);
    let pr = abutment_problem(shape, end, &[0, 1], v, 0.0, &law).unwrap();
    let pr = match inertia {
        None => pr,
        Some(i) => {
            let mut b: RigidBody = pr.bodies()[0].clone();
            b.inertia = i;
            let specs = pr
                .contacts()
                .iter()
                .map(|c| impact::ContactSpec {
                    body_a: "deck".into(),
                    body_b: None,
                    point: c.point,
                    normal: c.normal,
                    mu: 0.0,
                    restitution: eps,
                })
                .collect();
            ImpactProblem::new(vec![b], specs).unwrap()
        }
    };
    impact::solve(&pr, &ImpactSettings::default())
}

/// The frictionless rotation condition (Dimitrakopoulos, Makris & Kappos): a skewed deck striking
/// the abutment with both corners after a purely longitudinal approach turns about its obtuse
/// corner iff `sin 2θ_s > 2W/L`; otherwise both corners keep contact and it does not rotate.
/// Checked through the 2-contact LCP just below and above the threshold angle, for ε ∈ {0, 0.5, 1},
/// both ends, three aspect ratios, and with the inertia replaced by the rectangle's (and ×0.1, ×10):
/// the condition depends on neither ε nor I.
#[test]
fn skew_rotation_condition_through_the_lcp() {
    let mut above_seen = 0;
    let mut below_seen = 0;
    let mut fallback = 0;
    for (l, w) in [(30.0, 10.0), (60.0, 12.0), (25.0, 12.0)] {
        let threshold = 0.5 * (2.0f64 * w / l).asin(); // the smaller root of sin 2θ = 2W/L
        let upper_root = FRAC_PI_2 - threshold;
        for (deg, above) in [
            (threshold.to_degrees() - 0.5, false),
            (threshold.to_degrees() + 0.5, true),
            (45.0, true),
            (upper_root.to_degrees() - 0.5, true),
            (upper_root.to_degrees() + 0.5, false),
            (0.0, false),
        ] {
            let sd = skewed(l, w, deg);
            assert_eq!(sd.rotates_on_abutment_impact(), above, "{l} {w} {deg}");
            let shape = DeckShape::Skewed(sd);
            let p = shape.mass_properties();
            let rect_i = p.mass * (l * l + w * w) / 12.0;
            for end in [DeckEnd::Far, DeckEnd::Joint] {
                assert_eq!(frictionless_pivot(&shape, end), above.then_some(1));
                for eps in [0.0, 0.5, 1.0] {
                    for inertia in [
                        None,
                        Some(rect_i),
                        Some(0.1 * p.inertia),
                        Some(10.0 * p.inertia),
                    ] {
                        let s = both_corners(&shape, end, eps, inertia);
                        let i = inertia.unwrap_or(p.inertia);
                        // μ = 0 with a shared tangent makes the tangential block singular; Lemke
                        // may stop on a ray there and enumeration then solves (counted below)
                        assert!(matches!(
                            s.status,
                            ImpactStatus::Solved | ImpactStatus::SolvedByFallback
                        ));
                        assert!(s.post_velocity_unique);
                        fallback += usize::from(s.status == ImpactStatus::SolvedByFallback);
                        let n0 = -s.contacts[0].gamma_n_pre;
                        assert!(n0 > 0.0);
                        assert!((s.contacts[1].gamma_n_pre + n0).abs() < 1e-12 * n0);
                        let [acute, obtuse] = [s.contacts[0], s.contacts[1]];
                        let omega = s.bodies[0].omega;
                        let scale = n0 / l;
                        if above {
                            // acute corner separates, obtuse corner alone carries the impulse
                            assert_eq!(
                                acute.mode,
                                ContactMode::Open,
                                "{l} {w} {deg} {end:?} {eps}"
                            );
                            assert!(acute.normal_impulse.abs() < 1e-9 * obtuse.normal_impulse);
                            assert!(obtuse.normal_impulse > 0.0);
                            assert!(acute.gamma_n_post > eps * n0 + 1e-9 * n0);
                            assert!((obtuse.gamma_n_post - eps * n0).abs() < 1e-9 * n0);
                            // closed form: Λ = (1+ε) n0 / G_11, ω⁺ = A_1 Λ / I
                            let a1 = abutment_contact(&shape, end, 1).arm_n;
                            let g11 = 1.0 / p.mass + a1 * a1 / i;
                            let lam = (1.0 + eps) * n0 / g11;
                            assert!(rel(obtuse.normal_impulse, lam) < 1e-9);
                            assert!(rel(omega, a1 * lam / i) < 1e-9);
                            assert!(omega.abs() > 1e-3 * scale);
                            above_seen += 1;
                        } else {
                            assert!(acute.normal_impulse > 0.0 && obtuse.normal_impulse > 0.0);
                            assert!(omega.abs() < 1e-9 * scale, "ω = {omega}");
                            for c in [acute, obtuse] {
                                assert!((c.gamma_n_post - eps * n0).abs() < 1e-9 * n0);
                            }
                            // total impulse reverses the normal momentum: m (1+ε) n0
                            let total = acute.normal_impulse + obtuse.normal_impulse;
                            assert!(rel(total, p.mass * (1.0 + eps) * n0) < 1e-9);
                            below_seen += 1;
                        }
                        if eps == 1.0 {
                            assert!(rel(s.energy_after, s.energy_before) < 1e-9);
                        } else {
                            assert!(s.energy_after <= s.energy_before * (1.0 + 1e-12));
                        }
                    }
                }
            }
        }
    }
    assert!(above_seen > 0 && below_seen > 0);
    eprintln!(
        "rotation condition: {above_seen} rotating, {below_seen} non-rotating cases, {fallback} solved by fallback"
    );
}

/// Straight decks (θ_s = 0) never rotate; the curved deck's far face uses the same criterion, and
/// the LCP agrees with `frictionless_pivot` for it too.
#[test]
fn pivot_criterion_for_straight_and_curved() {
    let st = DeckShape::Straight(StraightDeck::new(30.0, 10.0, 1.0, 1.0).unwrap());
    assert_eq!(frictionless_pivot(&st, DeckEnd::Far), None);
    for (r, b) in [(100.0, 30.0), (100.0, 90.0), (60.0, 200.0)] {
        let d = Deck::new(r, f64::to_radians(b), 10.0, 1.0, 1.0).unwrap();
        let shape = DeckShape::Curved(d);
        for end in [DeckEnd::Joint, DeckEnd::Far] {
            let pivot = frictionless_pivot(&shape, end);
            let s = both_corners(&shape, end, 0.5, None);
            let open: Vec<bool> = s
                .contacts
                .iter()
                .map(|c| c.mode == ContactMode::Open)
                .collect();
            match pivot {
                None => assert_eq!(open, vec![false, false], "{r} {b} {end:?}"),
                Some(k) => {
                    assert!(!open[k] && open[1 - k], "{r} {b} {end:?}: {open:?}");
                }
            }
        }
    }
}

/// Two decks face to face (parallel faces, both joint corners striking): straight decks of
/// different lengths follow the 1-D collision law without rotating; skewed decks conserve total
/// linear and angular momentum (no external impulse) and satisfy Newton's law at active corners.
#[test]
fn joint_double_impact_of_straight_and_skewed_decks() {
    use pounding::shape::joint_problem;
    let settings = ImpactSettings::default();
    for (l1, l2, eps) in [(30.0, 30.0, 0.6), (20.0, 45.0, 0.0), (40.0, 25.0, 1.0)] {
        let d1 = DeckShape::Straight(StraightDeck::new(l1, 10.0, 1.0, 1.0).unwrap());
        let d2 = DeckShape::Straight(StraightDeck::new(l2, 10.0, 1.0, 1.0).unwrap());
        let law = ImpactLaw::new(0.0, eps).unwrap();
        let v = 0.7;
        let pr = joint_problem(
            &d1,
            &d2,
            (Vector::new(0.0, -v), 0.0),
            (Vector::zeros(), 0.0),
            &law,
        )
        .unwrap();
        let s = impact::solve(&pr, &settings);
        let (m1, m2) = (l1 * 10.0, l2 * 10.0);
        let v1 = -v + (1.0 + eps) * m2 / (m1 + m2) * v;
        let v2 = -(1.0 + eps) * m1 / (m1 + m2) * v;
        assert!(
            (s.bodies[0].velocity.y - v1).abs() < 1e-9 * v,
            "{l1} {l2} {eps}"
        );
        assert!((s.bodies[1].velocity.y - v2).abs() < 1e-9 * v);
        assert!(s.bodies[0].omega.abs() < 1e-10 && s.bodies[1].omega.abs() < 1e-10);
        assert!(s.post_velocity_unique);
    }
    for (deg, mu, eps) in [
        (10.0, 0.0, 0.5),
        (30.0, 0.0, 0.0),
        (45.0, 0.3, 0.8),
        (60.0, 0.0, 1.0),
    ] {
        let d1 = DeckShape::Skewed(skewed(30.0, 10.0, deg));
        let d2 = DeckShape::Skewed(skewed(50.0, 10.0, deg));
        let law = ImpactLaw::new(mu, eps).unwrap();
        let pr = joint_problem(
            &d1,
            &d2,
            (1.2 * d1.axis_direction(DeckEnd::Joint), 0.01),
            (Vector::new(0.1, 0.0), 0.0),
            &law,
        )
        .unwrap();
        let s = impact::solve(&pr, &settings);
        assert!(matches!(
            s.status,
            ImpactStatus::Solved | ImpactStatus::SolvedByFallback
        ));
        let mom = |vel: &[(Vector, f64)]| {
            let mut p = Vector::zeros();
            let mut h = 0.0;
            for (b, (v, w)) in pr.bodies().iter().zip(vel) {
                p += b.mass * v;
                h += b.mass * cross(&b.position, v) + b.inertia * w;
            }
            (p, h)
        };
        let pre: Vec<(Vector, f64)> = pr.bodies().iter().map(|b| (b.velocity, b.omega)).collect();
        let post: Vec<(Vector, f64)> = s.bodies.iter().map(|b| (b.velocity, b.omega)).collect();
        let ((p0, h0), (p1, h1)) = (mom(&pre), mom(&post));
        let scale = pr.bodies()[0].mass * 1.2;
        assert!((p1 - p0).norm() < 1e-9 * scale, "{deg}");
        assert!((h1 - h0).abs() < 1e-9 * scale * 30.0, "{deg}: {h0} {h1}");
        for c in &s.contacts {
            if c.normal_impulse > 0.0 {
                assert!((c.gamma_n_post + eps * c.gamma_n_pre.min(0.0)).abs() < 1e-9);
            } else {
                assert!(c.gamma_n_post >= -1e-12);
            }
        }
        assert!(s.energy_after <= s.energy_before * (1.0 + 1e-12) || mu > 0.0);
    }
    // mismatched faces are rejected, naming the parameter
    let law = ImpactLaw::new(0.0, 0.5).unwrap();
    let z = (Vector::zeros(), 0.0);
    let a = DeckShape::Skewed(skewed(30.0, 10.0, 20.0));
    let name = |r: Result<ImpactProblem, impact::ImpactError>| match r.unwrap_err() {
        impact::ImpactError::Invalid { name, .. } => name,
    };
    assert_eq!(
        name(joint_problem(
            &a,
            &DeckShape::Skewed(skewed(30.0, 12.0, 20.0)),
            z,
            z,
            &law
        )),
        "width"
    );
    assert_eq!(
        name(joint_problem(
            &a,
            &DeckShape::Skewed(skewed(30.0, 10.0, 25.0)),
            z,
            z,
            &law
        )),
        "skew"
    );
    assert!(joint_problem(&a, &DeckShape::Skewed(skewed(80.0, 10.0, 20.0)), z, z, &law).is_ok());
}

/// Frictional extension (our derivation, not in the issue). If both corners carry impulse they
/// end with equal normal velocities, so `ω⁺ = 0`; the common tangential arm `B = r × t` means only
/// the total impulse `(N, T)` matters, and both normal impulses are `≥ 0` iff the moment balance
/// puts `−B T/N` between the arms `A_1 ≤ A_0`. Longitudinal approach: `n₀ = v cos θ_s`,
/// `v⁻·t = −v sin θ_s`.
/// * both corners stick (`tan θ_s ≤ μ (1+ε)`): `v⁺·t = 0` fixes `T/N = tan θ_s/(1+ε)`;
/// * both slide: `T/N = μ`.
///
/// So with `μ_eff = min(μ, tan θ_s/(1+ε))` the deck turns about its obtuse corner iff
/// `sin 2θ_s − μ_eff (1 + cos 2θ_s) > 2W/L` (for μ = 0 the condition). Friction raises the
/// threshold and, in the sticking regime, the condition `sin 2θ_s · ε/(1+ε) > 2W/L` depends on ε
/// (with ε = 0 a sticking impact never turns the deck). Compared with the 2-contact LCP over a
/// deterministic random sample.
#[test]
fn skew_rotation_condition_with_friction() {
    // deterministic sample (64-bit LCG)
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut uni = |lo: f64, hi: f64| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let (mut agree, mut total, mut rot) = (0, 0, 0);
    for _ in 0..2000 {
        let (l, w, deg, mu, eps) = (
            uni(10.0, 80.0),
            uni(4.0, 15.0),
            uni(0.0, 85.0),
            uni(0.0, 1.0),
            uni(0.0, 1.0),
        );
        let shape = DeckShape::Skewed(skewed(l, w, deg));
        let th = deg.to_radians();
        let law = ImpactLaw::new(mu, eps).unwrap();
        let mu_eff = mu.min(th.tan() / (1.0 + eps));
        let lhs = (2.0 * th).sin() - mu_eff * (1.0 + (2.0 * th).cos());
        let predicted = lhs > 2.0 * w / l;
        if (lhs - 2.0 * w / l).abs() > 1e-9 {
            assert_eq!(
                predicted,
                skewed(l, w, deg).rotates_on_abutment_impact_with(&law)
            );
        }
        let v = shape.axis_direction(DeckEnd::Far);
        let pr = abutment_problem(&shape, DeckEnd::Far, &[0, 1], v, 0.0, &law).unwrap();
        let s = impact::solve(&pr, &ImpactSettings::default());
        let n0 = -s.contacts[0].gamma_n_pre;
        let rotates = s.bodies[0].omega.abs() > 1e-9 * n0 / l;
        if (lhs - 2.0 * w / l).abs() < 1e-6 {
            continue; // too close to the threshold to classify
        }
        total += 1;
        rot += usize::from(rotates);
        if rotates == predicted {
            agree += 1;
        } else {
            eprintln!(
                "mismatch L={l} W={w} θ={deg} μ={mu} ε={eps}: LCP {rotates}, predicted {predicted}, modes {:?}",
                s.contacts.iter().map(|c| c.mode).collect::<Vec<_>>()
            );
        }
        if rotates {
            assert_eq!(s.contacts[0].mode, ContactMode::Open);
        }
    }
    eprintln!("friction condition: {agree}/{total} agree, {rot} rotating");
    assert_eq!(agree, total);
    assert!(rot > 20 && rot < total - 20);
}

/// The frictionless condition holds with `W` the width perpendicular to the axis and `L` the axis
/// length; with the end-face length `W/cos θ_s` in place of `W` it misclassifies (L = 30, W = 10,
/// θ_s = 22°: the LCP turns the deck).
#[test]
fn rotation_condition_uses_the_perpendicular_width() {
    let (l, w, deg) = (30.0, 10.0, 22.0);
    let sd = skewed(l, w, deg);
    let shape = DeckShape::Skewed(sd);
    let s = both_corners(&shape, DeckEnd::Far, 0.5, None);
    assert_eq!(s.contacts[0].mode, ContactMode::Open);
    assert!(s.bodies[0].omega.abs() > 1e-4);
    let th = f64::to_radians(deg);
    assert!((2.0 * th).sin() > 2.0 * w / l);
    assert!((2.0 * th).sin() <= 2.0 * sd.face_length() / l);
}

/// The curved `DeckShape` placed as deck 1 (shift by `(0, g)`) and deck 2 (turn by π) reproduces
/// the simulator's reference bodies (`SegmentBody::of_curved_deck`): centroid, joint and far
/// corners (`DeckShape` orders the far face `[outer, inner]`, the curved body `[inner, outer]`) and the
/// inward normals — so the simulator can switch to `DeckShape` without changing its frames.
#[test]
fn curved_shape_matches_the_simulator_bodies() {
    use pounding::sim::model::SegmentBody;
    let deck = Deck::new(150.0, f64::to_radians(75.0), 10.0, 0.5, 2500.0).unwrap();
    let shape = DeckShape::Curved(deck);
    let gap = 0.04;
    for j in [1usize, 2] {
        let body = SegmentBody::of_curved_deck(&deck, j, gap);
        let (joint, far) = (body.joint_face(j), body.far_face(j));
        let place = |p: Vector| {
            if j == 1 {
                p + Vector::new(0.0, gap)
            } else {
                rotate(&p, PI)
            }
        };
        let p = shape.mass_properties();
        assert!((place(p.centroid) - body.centroid).norm() < 1e-9);
        let jf = shape.end_face(DeckEnd::Joint);
        let ff = shape.end_face(DeckEnd::Far);
        for (a, b) in [
            (jf.corners[0], joint.corners[0]),
            (jf.corners[1], joint.corners[1]),
            (ff.corners[1], far.corners[0]),
            (ff.corners[0], far.corners[1]),
        ] {
            assert!((place(a) - b).norm() < 1e-9, "deck {j}: {a:?} vs {b:?}");
        }
        let turn = |v: Vector| if j == 1 { v } else { rotate(&v, PI) };
        assert!((turn(-jf.outward_normal) - joint.inward).norm() < 1e-12);
        assert!((turn(-ff.outward_normal) - far.inward).norm() < 1e-12);
    }
}

/// The [`Shape`](pounding::shape::Shape) trait behind `DeckShape`: the enum returns exactly what
/// each concrete shape returns (mass properties, both end faces, axes, corner angles and names),
/// `scale_density` scales mass and inertia only, `validate` re-runs the constructor checks with
/// per-deck names from `for_deck`, and `with_length` keeps the kind of deck.
#[test]
fn deck_shape_dispatches_to_each_shape() {
    use pounding::shape::Shape;
    let curved = Deck::new(100.0, 1.0, 10.0, 0.5, 2500.0).unwrap();
    let straight = StraightDeck::new(30.0, 10.0, 0.5, 2500.0).unwrap();
    let skewed = SkewedDeck::new(30.0, 10.0, 0.4, 0.5, 2500.0).unwrap();
    let concrete: [&dyn Shape; 3] = [&curved, &straight, &skewed];
    let shapes = [
        DeckShape::Curved(curved),
        DeckShape::Straight(straight),
        DeckShape::Skewed(skewed),
    ];
    let names = [
        ("curved", [["inner", "outer"], ["outer", "inner"]]),
        ("straight", [["c0", "c1"], ["c0", "c1"]]),
        ("skew", [["acute", "obtuse"], ["acute", "obtuse"]]),
    ];
    for ((s, c), (name, corner_names)) in shapes.iter().zip(concrete).zip(names) {
        assert_eq!(s.name(), name);
        assert_eq!(s.mass_properties(), c.mass_properties());
        assert_eq!(s.width(), 10.0);
        assert_eq!(s.length(), c.length());
        for (e, end) in [DeckEnd::Joint, DeckEnd::Far].into_iter().enumerate() {
            assert_eq!(s.end_face(end), c.end_face(end));
            assert_eq!(s.axis_direction(end), c.axis_direction(end));
            assert_eq!(s.corner_names(end), corner_names[e]);
            let sum = s.corner_angle(end, 0) + s.corner_angle(end, 1);
            assert!((sum - PI).abs() < 1e-15, "{name}: corner angles sum to π");
        }
        let mut heavy = *s;
        heavy.scale_density(2.0);
        let (p, q) = (s.mass_properties(), heavy.mass_properties());
        assert_eq!(q.mass, 2.0 * p.mass);
        assert_eq!(q.inertia, 2.0 * p.inertia);
        assert_eq!(q.centroid, p.centroid);
        assert!(heavy.validate().is_ok());
        heavy.scale_density(-1.0);
        let e = heavy.validate().unwrap_err();
        assert!(e.for_deck(2).to_string().contains("density"), "{name}");
    }
    assert_eq!(shapes[1].skew(), 0.0);
    assert_eq!(shapes[2].skew(), 0.4);
    assert_eq!(shapes[0].length(), None);
    let longer = shapes[2].with_length(50.0).unwrap();
    assert_eq!(
        longer.skewed().map(|d| (d.length, d.skew)),
        Some((50.0, 0.4))
    );
    assert!(shapes[0].with_length(50.0).is_err());
    let e = shapes[1].with_length(-1.0).unwrap_err().for_deck(2);
    assert!(e.to_string().contains("L2"), "{e}");
    let bad_skew = DeckShape::Skewed(SkewedDeck {
        skew: 2.0,
        ..skewed
    });
    let e = bad_skew.validate().unwrap_err().for_deck(1);
    assert!(e.to_string().contains("skew1"), "{e}");
    assert!(shapes[0].curved().is_some() && shapes[1].curved().is_none());
}
