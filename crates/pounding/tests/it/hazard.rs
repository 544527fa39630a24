//! Hazard integration: the MAF of a lognormal fragility under a power-law hazard (closed form)
//! and a tabulated hazard (log-log interpolation, over the table's range), checked against
//! quadratures written here; its bootstrap interval; the `[hazard]` input's errors.

use pounding::assessment::AssessmentError;
use pounding::assessment::hazard_input::{HazardInput, read_csv};
use pounding::fragility::hazard::{HazardCurve, deaggregation, maf, maf_interval};
use pounding::fragility::{BootstrapSettings, StripeData, bootstrap_stripes};
use std::path::Path;

/// Φ by the complementary error function of a series independent of the library's (Abramowitz &
/// Stegun 7.1.26 is too coarse; use erfc by a continued fraction / Taylor as in Numerical Recipes).
fn phi(z: f64) -> f64 {
    // erfc via the Numerical Recipes Chebyshev fit (relative error < 1.2e-7 everywhere)
    let x = -z / std::f64::consts::SQRT_2;
    let t = 1.0 / (1.0 + 0.5 * x.abs());
    let y = t
        * (-x * x - 1.26551223
            + t * (1.00002368
                + t * (0.37409196
                    + t * (0.09678418
                        + t * (-0.18628806
                            + t * (0.27886807
                                + t * (-1.13520398
                                    + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277)))))))))
            .exp();
    let erfc = if x >= 0.0 { y } else { 2.0 - y };
    0.5 * erfc
}

/// Composite Simpson of `f` over `[a, b]` with `n` (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let h = (b - a) / n as f64;
    let mut s = f(a) + f(b);
    for i in 1..n {
        s += f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * h / 3.0
}

#[test]
fn power_law_matches_the_closed_form_and_a_quadrature() {
    for &(k0, k, theta, beta) in &[
        (1e-4, 2.5, 0.82, 0.26),
        (3e-3, 1.8, 0.3, 0.5),
        (2e-5, 3.2, 1.4, 0.15),
    ] {
        let h = HazardCurve::PowerLaw { k0, k };
        let m = maf(&h, theta, beta);
        let closed: f64 = k0 * theta.powf(-k) * (k * k * beta * beta / 2.0).exp();
        assert!(
            ((m.rate - closed) / closed).abs() < 1e-12,
            "{} vs {closed}",
            m.rate
        );
        // the same integral written by parts, ∫ λ(x) f(x) dx, in ln x by Simpson (independent of
        // the library's Φ and quadrature): within 1e-6
        let c = theta.ln();
        let by_parts = simpson(
            |u| {
                let z = (u - c) / beta;
                k0 * (-k * u).exp() * (-0.5 * z * z).exp()
                    / (beta * (2.0 * std::f64::consts::PI).sqrt())
            },
            c - 14.0 * beta,
            c + 14.0 * beta,
            20_000,
        );
        eprintln!(
            "power law: MAF {} closed form {closed}, by parts {by_parts} (relative {:.1e})",
            m.rate,
            ((m.rate - by_parts) / by_parts).abs()
        );
        assert!(
            ((m.rate - by_parts) / by_parts).abs() < 1e-6,
            "{} vs {by_parts}",
            m.rate
        );
        assert!(m.upper_tail.is_none() && (m.return_period() * m.rate - 1.0).abs() < 1e-15);
        // the deaggregation integrates to the MAF over ln x
        let d = |u: f64| deaggregation(&h, theta, beta, &[u.exp()])[0];
        // the density falls as exp(−k ln x) above the fragility: integrate far enough
        let total = simpson(d, c - 12.0 * beta - k * beta * beta, c + 30.0 / k, 40_000);
        assert!(
            ((total - m.rate) / m.rate).abs() < 1e-6,
            "{total} vs {}",
            m.rate
        );
    }
}

#[test]
fn tabulated_hazard_matches_the_power_law_and_an_independent_quadrature() {
    let (k0, k, theta, beta): (f64, f64, f64, f64) = (1e-4, 2.5, 0.82, 0.26);
    let closed = k0 * theta.powf(-k) * (k * k * beta * beta / 2.0).exp();
    let sampled = |top: f64| {
        let im: Vec<f64> = (0..=600)
            .map(|i| (0.01f64.ln() + i as f64 * (top / 0.01f64).ln() / 600.0).exp())
            .collect();
        let rate: Vec<f64> = im.iter().map(|x| k0 * x.powf(-k)).collect();
        HazardCurve::Table { im, rate }
    };
    // a dense table sampled from the power law up to 200 g (the tail beyond is 1e-6 of the MAF)
    let table = sampled(200.0);
    table.validate().expect("valid");
    let m = maf(&table, theta, beta);
    eprintln!(
        "dense table: MAF {} closed form {closed} (relative {:.1e})",
        m.rate,
        ((m.rate - closed) / closed).abs()
    );
    assert!(
        ((m.rate - closed) / closed).abs() < 1e-4,
        "{} vs {closed}",
        m.rate
    );
    // a table ending at 2 g leaves out a part, which its reported bounds hold
    let m = maf(&sampled(2.0), theta, beta);
    let (lo, hi) = m.upper_tail.expect("a table reports its upper tail");
    assert!(lo <= hi && (hi - k0 * 2f64.powf(-k)).abs() < 1e-15);
    assert!(
        m.rate + lo <= closed * (1.0 + 1e-6) && closed <= (m.rate + hi) * (1.0 + 1e-6),
        "{} + [{lo}, {hi}] vs {closed}",
        m.rate
    );
    assert!(m.p_first.expect("p at the first IM") < 1e-9);
    // a coarse, curved table: against Simpson on ∫ P(x) |dλ/dx| dx with λ interpolated log-log
    // here, written independently (finite differences of ln λ on each interval)
    let im = vec![0.02, 0.05, 0.1, 0.2, 0.4, 0.8, 1.6, 3.2];
    let rate = vec![0.05, 0.01, 0.003, 8e-4, 2e-4, 4e-5, 6e-6, 8e-7];
    let t = HazardCurve::Table {
        im: im.clone(),
        rate: rate.clone(),
    };
    let m = maf(&t, theta, beta).rate;
    let mut reference = 0.0;
    for i in 0..im.len() - 1 {
        let (u0, u1) = (im[i].ln(), im[i + 1].ln());
        let s = (rate[i + 1].ln() - rate[i].ln()) / (u1 - u0); // d ln λ / d ln x
        reference += simpson(
            |u| phi((u - theta.ln()) / beta) * (-s) * (rate[i].ln() + s * (u - u0)).exp(),
            u0,
            u1,
            4000,
        );
    }
    eprintln!(
        "coarse table: MAF {m} Simpson {reference} (relative {:.1e})",
        ((m - reference) / reference).abs()
    );
    assert!(
        ((m - reference) / reference).abs() < 1e-4,
        "{m} vs {reference}"
    );
}

#[test]
fn maf_interval_comes_from_the_bootstrap_replicates() {
    // 30 records, 6 stripes, outcomes from a known curve (deterministic pattern)
    let levels = vec![0.2, 0.4, 0.6, 0.8, 1.0, 1.4];
    let exceeded: Vec<Vec<Option<bool>>> = (0..30)
        .map(|r| {
            let cap = 0.3 * (1.0 + 3.0 * (r as f64 + 0.5) / 30.0);
            levels.iter().map(|&x| Some(x > cap)).collect()
        })
        .collect();
    let d = StripeData {
        im: levels,
        exceeded,
    };
    let s = BootstrapSettings {
        samples: 300,
        seed: 3,
        level: 0.9,
    };
    let b = bootstrap_stripes(&d, &s, &[]).expect("bootstrap");
    let h = HazardCurve::PowerLaw { k0: 1e-4, k: 2.5 };
    let (m, i) = maf_interval(&h, &b).expect("a fit");
    let (lo, hi) = i.expect("an interval");
    let reps: Vec<f64> = b
        .replicates
        .iter()
        .flatten()
        .map(|&(t, bb)| maf(&h, t, bb).rate)
        .collect();
    assert_eq!(reps.len() + b.failed, 300);
    let (mn, mx) = reps
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, z), &v| (a.min(v), z.max(v)));
    assert!(
        mn <= lo && lo < m.rate && m.rate < hi && hi <= mx,
        "{mn} {lo} {} {hi} {mx}",
        m.rate
    );
    // a power-law MAF of θ alone (β fixed by the fit) would map the θ interval: here check that a
    // narrower level gives a narrower interval, from the same replicates
    let b50 =
        bootstrap_stripes(&d, &BootstrapSettings { level: 0.5, ..s }, &[]).expect("bootstrap");
    let (l50, h50) = maf_interval(&h, &b50).and_then(|x| x.1).expect("interval");
    assert!(lo <= l50 && h50 <= hi);
}

fn toml_err(hazard: &str) -> String {
    let text = format!("[bridge]\ngap = 0.1\n\n[hazard]\n{hazard}\n");
    match HazardInput::from_toml(&text, "b.toml", Path::new(".")) {
        Err(e) => e.to_string(),
        Ok(h) => panic!("accepted: {h:?}"),
    }
}

#[test]
fn bad_hazard_input_names_the_key_and_line() {
    let e = toml_err("k0 = 1e-4\nk = 2.5");
    assert!(
        e.contains("hazard.im_unit") && e.contains("b.toml:4"),
        "{e}"
    );
    let e = toml_err("im_unit = \"m/s2\"\nk0 = 1e-4\nk = 2.5");
    assert!(e.contains("in g") && e.contains("b.toml:5"), "{e}");
    let e = toml_err("im_unit = \"g\"\nim = [0.1, 0.2, 0.3]\nrate = [1e-2, 2e-2, 1e-3]");
    assert!(
        e.contains("hazard.rate[1]") && e.contains("does not decrease") && e.contains("b.toml:7"),
        "{e}"
    );
    let e = toml_err("im_unit = \"g\"\nim = [0.0, 0.2]\nrate = [1e-2, 1e-3]");
    assert!(e.contains("hazard.im[0]"), "{e}");
    let e = toml_err("im_unit = \"g\"\nk0 = 1e-4\nk = 2.5\nim = [0.1, 0.2]\nrate = [1e-2, 1e-3]");
    assert!(e.contains("exactly one"), "{e}");
    let e = toml_err("im_unit = \"g\"\nk0 = -1e-4\nk = 2.5");
    assert!(e.contains("hazard.k0"), "{e}");
    let e = toml_err("im_unit = \"g\"\nk0 = 1e-4\nk = 2.5\nmeasure = \"sv\"");
    assert!(e.contains("hazard.measure"), "{e}");
    let e = toml_err("im_unit = \"g\"\nk0 = 1e-4\nkk = 2.5");
    assert!(e.contains("kk"), "{e}");

    let csv = |t: &str| read_csv(t, "h.csv").map_err(|e: AssessmentError| e.to_string());
    assert!(csv("im_g,rate\n0.1,1e-2\n0.2,1e-3\n").is_ok());
    let e = csv("# a site\nim_g,rate\n0.1,1e-2\n0.2,1e-3\n0.3,2e-3\n").unwrap_err();
    assert!(
        e.contains("h.csv:5") && e.contains("does not decrease") && e.contains("`rate`"),
        "{e}"
    );
    let e = csv("im,rate\n0.1,1e-2\n0.2,1e-3\n").unwrap_err();
    assert!(e.contains("h.csv:1") && e.contains("im_g"), "{e}");
    let e = csv("im_cm/s2,rate\n0.1,1e-2\n0.2,1e-3\n").unwrap_err();
    assert!(e.contains("in g"), "{e}");
    let e = csv("im_g,rate\n0.1,1e-2\n0.2,x\n").unwrap_err();
    assert!(e.contains("h.csv:3") && e.contains("not a number"), "{e}");
    let e = csv("im_g,rate\n0.2,1e-2\n0.1,1e-3\n").unwrap_err();
    assert!(
        e.contains("h.csv:3") && e.contains("does not increase"),
        "{e}"
    );
}
