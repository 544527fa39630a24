//! The time-discretisation error estimate ([`pounding::sim::accuracy`]): exact on power-law
//! sequences, honest on erratic and chaotic ones, and measured against the event-exact chain
//! reference on `examples/viaduct-rigid-1d.toml` under both El Centro components.

use pounding::sim::accuracy::{
    AccuracySettings, CHAOTIC_SPREAD, Kind, Quantity, SAFETY, Trust, estimate_one, parse_tol,
    run_with_estimate,
};
use pounding::sim::scenario::Scenario;

fn q(kind: Kind) -> Quantity {
    Quantity {
        name: "x".into(),
        unit: kind.unit(),
        kind,
        governing: true,
    }
}

#[test]
fn a_power_law_gives_its_order_and_its_error_times_the_safety_factor() {
    let (star, h) = (0.3, 1e-3);
    for p in [1.0, 1.5, 2.0] {
        for c in [20.0, -7.0] {
            let v = |k: i32| star + c * (h / 2f64.powi(k)).powf(p);
            let e = estimate_one(q(Kind::Length), [v(0), v(1), v(2)]);
            assert_eq!(e.trust, Trust::Converging, "p {p}, c {c}");
            let true_error = (v(0) - star).abs();
            assert!((e.order.unwrap() - p).abs() < 1e-6, "{:?}", e.order);
            let err = e.error.unwrap();
            assert!(
                (err / (SAFETY * true_error) - 1.0).abs() < 1e-6,
                "{err} vs {true_error}"
            );
            assert!((e.relative_error.unwrap() - err / v(0).abs()).abs() < 1e-15);
        }
    }
}

#[test]
fn an_order_above_two_is_reported_but_summed_at_two() {
    let (star, h, c) = (0.3, 1e-3, 20.0);
    let v = |k: i32| star + c * (h / 2f64.powi(k)).powf(3.0);
    let e = estimate_one(q(Kind::Length), [v(0), v(1), v(2)]);
    assert!((e.order.unwrap() - 3.0).abs() < 1e-6);
    // d₁ · 4/3 · 1.25, larger than the order-3 sum d₁ · 8/7 · 1.25
    let d1 = v(0) - v(1);
    assert!((e.error.unwrap() / (SAFETY * d1 * 4.0 / 3.0) - 1.0).abs() < 1e-9);
}

#[test]
fn erratic_chaotic_converged_and_counted_quantities_are_told_apart() {
    // differences changing sign, small against the value: the spread's envelope
    let e = estimate_one(q(Kind::Length), [0.10, 0.1001, 0.0998]);
    assert_eq!(e.trust, Trust::Erratic);
    assert!((e.error.unwrap() - 2.0 * 0.0003).abs() < 1e-15);
    // differences that grow: also no order
    let e = estimate_one(q(Kind::Length), [0.10, 0.1001, 0.1005]);
    assert_eq!(e.trust, Trust::Erratic);
    assert_eq!(e.order, None);
    // the step changes the value by more than CHAOTIC_SPREAD: no number at all
    let e = estimate_one(q(Kind::Length), [0.10, 0.13, 0.09]);
    const { assert!(0.04 / 0.10 > CHAOTIC_SPREAD) };
    assert_eq!(e.trust, Trust::NotConverging);
    assert_eq!((e.error, e.relative_error), (None, None));
    assert!(!e.meets(0.99));
    // identical values
    let e = estimate_one(q(Kind::Ratio), [0.5, 0.5, 0.5]);
    assert_eq!((e.trust, e.error), (Trust::Converged, Some(0.0)));
    assert!(e.meets(1e-12));
    // q(h/2) = q(h/4): converged at h/2, the error of q(h) is the difference (times the factor)
    let e = estimate_one(q(Kind::Force), [1.01e6, 1.0e6, 1.0e6]);
    assert_eq!(e.trust, Trust::Converging);
    assert!((e.error.unwrap() - SAFETY * 1e4).abs() < 1e-6);
    // counts: a spread, never an order or a relative error
    let e = estimate_one(q(Kind::Count), [22.0, 23.0, 22.0]);
    assert_eq!(
        (e.trust, e.error, e.relative_error),
        (Trust::Counted, Some(1.0), None)
    );
    // a NaN is not converging
    let e = estimate_one(q(Kind::Length), [0.1, f64::NAN, 0.1]);
    assert_eq!(e.trust, Trust::NotConverging);
    // below the floor (1 mm), the relative error is taken against the floor
    let e = estimate_one(q(Kind::Length), [2e-6, 1e-6, 0.5e-6]);
    assert_eq!(e.trust, Trust::Converging);
    let rel = e.relative_error.unwrap();
    assert!((rel - e.error.unwrap() / 1e-3).abs() < 1e-15, "{rel}");
}

#[test]
fn tolerances_read_as_percentages_or_fractions_and_nothing_else() {
    assert_eq!(parse_tol("1%"), Ok(0.01));
    assert_eq!(parse_tol(" 0.5 % "), Ok(0.005));
    assert_eq!(parse_tol("0.01"), Ok(0.01));
    for bad in [
        "1", "5", "0", "0%", "100%", "150%", "-1%", "abc", "nan", "inf%", "", "%",
    ] {
        let e = parse_tol(bad).unwrap_err();
        assert!(e.contains("tolerance"), "{bad}: {e}");
    }
    assert!(parse_tol("1").unwrap_err().contains("1%"));
}

/// The shipped rigid viaduct, `duration` seconds of `record` (`builtin:ELC180` or `ELC270`).
fn viaduct(record: &str, dt: f64, duration: f64) -> pounding::sim::scenario::Setup {
    let text = include_str!("../../../../examples/viaduct-rigid-1d.toml")
        .replace("builtin:ELC180", record);
    Scenario::from_toml(&text, "viaduct-rigid-1d.toml")
        .unwrap()
        .with_dt(dt)
        .with_duration(duration)
        .build_setup()
        .unwrap()
}

/// Against the event-exact reference: the estimate of every peak opening, closing and segment
/// displacement (12 quantities per record and step) bounds its true error in at least 90 % of
/// the cases, and never misses it by more than a factor of 3; a tolerance run meets its tolerance
/// in truth too.
#[test]
fn the_estimate_bounds_the_true_error_against_the_event_exact_reference() {
    let gm = pounding::ground_motion::el_centro_1940();
    let duration = 20.0;
    let (mut cases, mut bounded) = (0usize, 0usize);
    for (name, record) in [
        ("builtin:ELC180", gm.along_y.clone().unwrap()),
        ("builtin:ELC270", gm.along_x.clone().unwrap()),
    ] {
        let (chain, _) = crate::event_chain::viaduct_rigid_1d();
        let r = chain
            .solve(Some(&record), 1.0, &[0.0; 3], &[0.0; 3], duration)
            .summary();
        let mut truth = Vec::new();
        for k in 0..2 {
            truth.push((format!("joint{}.peak_opening_m", k + 1), r.peak_opening[k]));
            truth.push((format!("joint{}.peak_closing_m", k + 1), r.peak_closing[k]));
        }
        for i in 0..3 {
            let n = format!("segment{}.peak_displacement_m", i + 1);
            truth.push((n, r.peak_displacement[i]));
        }
        for dt in [4e-4, 1e-4] {
            let setup = viaduct(name, dt, duration);
            let (sol, run) =
                run_with_estimate(&setup, AccuracySettings::default(), |_| Default::default())
                    .unwrap();
            assert_eq!(sol.dt, dt);
            assert_eq!(run.dts, vec![dt, dt / 2.0, dt / 4.0]);
            for (n, t) in &truth {
                let e = run
                    .estimates
                    .iter()
                    .find(|e| &e.quantity.name == n)
                    .unwrap();
                let true_error = (e.values[0] - t).abs();
                let est = e.error.unwrap_or(f64::NAN);
                eprintln!(
                    "{name} dt {dt:e} {n}: {:?} true error {true_error:.3e}, estimate {est:.3e}",
                    e.trust
                );
                assert_ne!(e.trust, Trust::NotConverging, "{n}");
                cases += 1;
                if est >= true_error {
                    bounded += 1;
                }
                assert!(3.0 * est >= true_error, "{n}: {est:e} vs {true_error:e}");
            }
        }
    }
    eprintln!("the estimate bounds the true error in {bounded} of {cases} cases");
    assert!(bounded as f64 >= 0.9 * cases as f64, "{bounded} of {cases}");
}
