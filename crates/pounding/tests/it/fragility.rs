//! Fragility fitting (issue 13): Φ accuracy, the stripe MLE against closed form and brute force,
//! the no-MLE statuses, bootstrap coverage and determinism, bad input, the writers.

#![allow(clippy::excessive_precision)] // reference values keep the digits mpmath printed

use pounding::fragility::normal::{cdf, ln_cdf, ln_pdf, pdf, quantile};
use pounding::fragility::{
    Bootstrap, BootstrapSettings, Fit, FragilityError, FragilityRow, IdaData, NoMle, StripeData,
    bootstrap_ida, bootstrap_stripes, fit_ida, fit_stripes, fragility_csv, fragility_json,
    stripe_log_likelihood,
};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};

/// Stripe data with `z[j]` of `n[j]` records exceeding at `im[j]` (records ordered so that record
/// `r` exceeds at stripe `j` iff `r < z[j]`).
fn stripes(im: &[f64], n: &[usize], z: &[usize]) -> StripeData {
    let rows = *n.iter().max().unwrap();
    let exceeded = (0..rows)
        .map(|r| {
            (0..im.len())
                .map(|j| (r < n[j]).then_some(r < z[j]))
                .collect()
        })
        .collect();
    StripeData {
        im: im.to_vec(),
        exceeded,
    }
}

fn lognormal(fit: Fit) -> (f64, f64) {
    fit.params()
        .unwrap_or_else(|| panic!("expected a lognormal fit, got {fit:?}"))
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn normal_cdf_log_cdf_and_quantile_match_reference_values() {
    // Reference values: mpmath 1.3 at 40 digits (ncdf, log(ncdf), sqrt(2)·erfinv(2p − 1)).
    let cases = [
        (-5.0, 2.8665157187919391167e-7, -15.064998393988725736),
        (-10.0, 7.619853024160526066e-24, -53.231285150512470578),
        (-1.0, 0.15865525393145705141, -1.8410216450092635058),
        (-0.3, 0.38208857781104736693, -0.96210281816885065666),
        (1.5, 0.933192798731141934, -0.069143455612233982993),
        (3.0, 0.99865010196836990547, -0.0013508099647481937988),
        (8.0, 0.9999999999999993779, -6.2209605742717860585e-16),
        (-38.0, 2.8854283600687843084e-316, -726.5572160188201301),
    ];
    for (z, p, lp) in cases {
        // Subnormal Φ(−38) carries fewer digits; everything else to a few ulps.
        let tol = if p < 1e-300 { 1e-8 } else { 4e-15 };
        assert!(
            rel(cdf(z), p) < tol,
            "Φ({z}) = {:e}, expected {p:e}",
            cdf(z)
        );
        assert!(
            rel(ln_cdf(z), lp) < 4e-15,
            "ln Φ({z}) = {}, expected {lp}",
            ln_cdf(z)
        );
    }
    // ln Φ where Φ underflows.
    assert!(rel(ln_cdf(-40.0), -804.60844201375378817) < 1e-15);
    assert!(rel(ln_cdf(-100.0), -5005.5242086942050886) < 1e-15);
    let quantiles = [
        (0.975, 1.9599639845400542355),
        (1e-10, -6.3613409024040562047),
        (0.001, -3.0902323061678135415),
    ];
    for (p, z) in quantiles {
        assert!(
            rel(quantile(p), z) < 1e-14,
            "Φ⁻¹({p}) = {}, expected {z}",
            quantile(p)
        );
    }
    // Near p = ½ the accuracy is absolute: Φ⁻¹ of the double nearest 0.5000001 (exactly, in mpmath).
    assert!((quantile(0.5000001) - 2.5066282733116483012e-7).abs() < 1e-16);
    assert_eq!(quantile(0.5), 0.0);
    assert!(quantile(1.5).is_nan() && quantile(0.0) == f64::NEG_INFINITY);
    // Round trip over the whole range: relative in the lower tail; in the upper tail p = Φ(z) is
    // only known to an ulp of 1, which moves z by up to ε/φ(z).
    for k in -300..=300 {
        let z = k as f64 * 0.1;
        let back = quantile(cdf(z));
        let tol = 1e-13 * (1.0 + z.abs())
            + if z > 0.0 {
                2.0 * f64::EPSILON / pdf(z)
            } else {
                0.0
            };
        assert!((back - z).abs() < tol || cdf(z) == 1.0, "z = {z}: {back}");
    }
}

#[test]
fn mle_of_two_interior_stripes_is_the_exact_fit() {
    // 5 of 20 exceed at 0.2 g and 15 of 20 at 0.8 g: the two-parameter model fits both fractions
    // exactly, Φ((ln x − ln θ)/β) = z/n, so θ = √(0.2·0.8) = 0.4 and
    // β = ln 4 / (2 Φ⁻¹(0.75)), Φ⁻¹(0.75) = 0.6744897501960817 (tables).
    let d = stripes(&[0.2, 0.8], &[20, 20], &[5, 15]);
    let (theta, beta) = lognormal(fit_stripes(&d).unwrap());
    let beta_exact = 4f64.ln() / (2.0 * 0.6744897501960817);
    assert!(rel(theta, 0.4) < 1e-10, "θ = {theta}");
    assert!(
        rel(beta, beta_exact) < 1e-10,
        "β = {beta}, expected {beta_exact}"
    );
    // Unequal fractions, unequal counts: 3/12 and 9/10 give Φ⁻¹ of each fraction.
    let d = stripes(&[0.3, 0.7], &[12, 10], &[3, 9]);
    let (theta, beta) = lognormal(fit_stripes(&d).unwrap());
    let (q1, q2) = (-0.6744897501960817, 1.2815515655446004); // Φ⁻¹(0.25), Φ⁻¹(0.9)
    let b = (0.7f64.ln() - 0.3f64.ln()) / (q2 - q1);
    assert!(rel(beta, b) < 1e-10 && rel(theta, (0.3f64.ln() - b * q1).exp()) < 1e-10);
}

#[test]
fn mle_agrees_with_brute_force_grid_and_has_zero_gradient() {
    let im = [0.1, 0.2, 0.3, 0.45, 0.6, 0.8, 1.0];
    let d = stripes(
        &im,
        &[30, 30, 29, 30, 28, 30, 30],
        &[0, 3, 6, 14, 17, 25, 27],
    );
    let counts = d.counts();
    let (theta, beta) = lognormal(fit_stripes(&d).unwrap());
    // Brute force: a coarse grid over (ln θ, ln β), then two refinements around the best point.
    let ll = |lt: f64, lb: f64| stripe_log_likelihood(&counts, lt.exp(), lb.exp());
    let (mut ct, mut cb, mut w) = (0.5f64.ln(), 0.5f64.ln(), 2.0);
    for _ in 0..6 {
        let mut best = (f64::NEG_INFINITY, ct, cb);
        for i in 0..=200 {
            for j in 0..=200 {
                let lt = ct + w * (i as f64 / 100.0 - 1.0);
                let lb = cb + w * (j as f64 / 100.0 - 1.0);
                let v = ll(lt, lb);
                if v > best.0 {
                    best = (v, lt, lb);
                }
            }
        }
        (ct, cb) = (best.1, best.2);
        w *= 0.05;
    }
    assert!(
        rel(theta, ct.exp()) < 1e-6,
        "θ = {theta}, grid {}",
        ct.exp()
    );
    assert!(rel(beta, cb.exp()) < 1e-6, "β = {beta}, grid {}", cb.exp());
    assert!(ll(theta.ln(), beta.ln()) >= ll(ct, cb) - 1e-12);
    // Central differences of ℓ at the optimum vanish (relative to the curvature scale).
    for h in [1e-4, 1e-5] {
        let gt = (ll(theta.ln() + h, beta.ln()) - ll(theta.ln() - h, beta.ln())) / (2.0 * h);
        let gb = (ll(theta.ln(), beta.ln() + h) - ll(theta.ln(), beta.ln() - h)) / (2.0 * h);
        assert!(
            gt.abs() < 1e-5 && gb.abs() < 1e-5,
            "gradient ({gt}, {gb}) at h = {h}"
        );
    }
    // Moving away lowers ℓ in every direction.
    for (dt, db) in [(1e-3, 0.0), (-1e-3, 0.0), (0.0, 1e-3), (0.0, -1e-3)] {
        assert!(ll(theta.ln() + dt, beta.ln() + db) < ll(theta.ln(), beta.ln()));
    }
}

#[test]
fn data_without_a_finite_mle_get_a_status_not_numbers() {
    let im = [0.1, 0.2, 0.4, 0.8];
    let no = |n: NoMle| Fit::NoFiniteMle(n);
    let fit = |z: [usize; 4]| fit_stripes(&stripes(&im, &[10; 4], &z)).unwrap();
    assert_eq!(fit([0, 0, 0, 0]), no(NoMle::NoExceedance));
    assert_eq!(fit([10, 10, 10, 10]), no(NoMle::AllExceeded));
    assert_eq!(fit([0, 0, 10, 10]), no(NoMle::PerfectlySeparated));
    // Quasi-separation: one mixed stripe between 0 % and 100 % still sends β → 0.
    assert_eq!(fit([0, 4, 10, 10]), no(NoMle::PerfectlySeparated));
    assert_eq!(fit([0, 0, 0, 7]), no(NoMle::PerfectlySeparated));
    assert_eq!(fit([10, 10, 0, 0]), no(NoMle::NotIncreasing));
    // Overlapping but decreasing fractions: the finite maximum has 1/β < 0.
    assert_eq!(fit([8, 6, 5, 2]), no(NoMle::NotIncreasing));
    // One stripe, interior fraction: two parameters from one fraction.
    let one = stripes(&[0.3], &[10], &[4]);
    assert_eq!(fit_stripes(&one).unwrap(), no(NoMle::TooFewPoints));
    assert_eq!(fit_stripes(&one).unwrap().status(), "too_few_points");
    // Stripes whose runs are all missing do not count as stripes.
    let mut d = stripes(&[0.2, 0.4], &[10, 10], &[3, 6]);
    d.exceeded.iter_mut().for_each(|row| row[1] = None);
    assert_eq!(fit_stripes(&d).unwrap(), no(NoMle::TooFewPoints));
    // IDA: censored records are refused, not dropped.
    let ida = |v: Vec<Option<f64>>| {
        fit_ida(&IdaData {
            im_at_exceedance: v,
        })
        .unwrap()
    };
    assert_eq!(
        ida(vec![Some(0.3), None, Some(0.5), None]),
        no(NoMle::Censored { count: 2 })
    );
    assert_eq!(ida(vec![None, None]), no(NoMle::NoExceedance));
    assert_eq!(ida(vec![Some(0.3)]), no(NoMle::TooFewPoints));
    assert_eq!(ida(vec![Some(0.3); 5]), no(NoMle::NoDispersion));
}

#[test]
fn missing_runs_are_excluded_from_the_counts() {
    let mut d = stripes(&[0.2, 0.8], &[20, 20], &[5, 15]);
    // Two more records whose runs are all missing: same counts, same fit.
    d.exceeded.push(vec![None, None]);
    d.exceeded.push(vec![None, Some(true)]);
    assert_eq!(d.counts(), vec![(0.2, 20, 5), (0.8, 21, 16)]);
    assert_eq!(d.runs(), 41);
}

#[test]
fn ida_moments_are_the_mean_and_sample_deviation_of_log_im() {
    let v = [0.2, 0.4, 0.8];
    let (theta, beta) = lognormal(
        fit_ida(&IdaData {
            im_at_exceedance: v.iter().map(|&x| Some(x)).collect(),
        })
        .unwrap(),
    );
    // ln values: ln 0.4 ± ln 2 → mean ln 0.4, sample deviation √((2 ln²2)/2) = ln 2.
    assert!(
        rel(theta, 0.4) < 1e-14 && rel(beta, 2f64.ln()) < 1e-14,
        "{theta} {beta}"
    );
}

/// `records` latent capacities `θ e^{β ε}`; record r exceeds at IM x iff x ≥ its capacity.
fn capacities(theta: f64, beta: f64, records: usize, seed: u64) -> Vec<f64> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..records)
        .map(|_| {
            let e: f64 = StandardNormal.sample(&mut rng);
            theta * (beta * e).exp()
        })
        .collect()
}

fn stripe_data_from(caps: &[f64], im: &[f64]) -> StripeData {
    StripeData {
        im: im.to_vec(),
        exceeded: caps
            .iter()
            .map(|c| im.iter().map(|&x| Some(x >= *c)).collect())
            .collect(),
    }
}

const TRUE_THETA: f64 = 0.5;
const TRUE_BETA: f64 = 0.4;
const STRIPE_IM: [f64; 8] = [0.2, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9, 1.2];

fn covers(b: &Bootstrap) -> (bool, bool) {
    let inside = |iv: Option<(f64, f64)>, v: f64| iv.is_some_and(|(lo, hi)| lo <= v && v <= hi);
    (inside(b.theta, TRUE_THETA), inside(b.beta, TRUE_BETA))
}

#[test]
fn stripe_bootstrap_intervals_cover_the_true_parameters() {
    let settings = |seed| BootstrapSettings {
        samples: 400,
        seed,
        level: 0.95,
    };
    let (mut ct, mut cb, mut failed, mut no_fit) = (0, 0, 0, 0);
    let reps = 200;
    for rep in 0..reps {
        let caps = capacities(TRUE_THETA, TRUE_BETA, 40, 1000 + rep);
        let d = stripe_data_from(&caps, &STRIPE_IM);
        let b = bootstrap_stripes(&d, &settings(rep), &[]).unwrap();
        no_fit += usize::from(b.fit.params().is_none());
        failed += b.failed;
        let (t, be) = covers(&b);
        ct += usize::from(t);
        cb += usize::from(be);
    }
    eprintln!(
        "stripes: θ covered {ct}/{reps}, β covered {cb}/{reps}, {failed} failed replicates, {no_fit} data sets without a fit"
    );
    assert!(ct >= 180 && cb >= 180, "coverage θ {ct}/200, β {cb}/200");
}

#[test]
fn ida_bootstrap_intervals_cover_the_true_parameters() {
    let (mut ct, mut cb) = (0, 0);
    let reps = 200;
    for rep in 0..reps {
        let caps = capacities(TRUE_THETA, TRUE_BETA, 40, 5000 + rep);
        let d = IdaData {
            im_at_exceedance: caps.into_iter().map(Some).collect(),
        };
        let s = BootstrapSettings {
            samples: 1000,
            seed: rep,
            level: 0.95,
        };
        let (t, be) = covers(&bootstrap_ida(&d, &s, &[]).unwrap());
        ct += usize::from(t);
        cb += usize::from(be);
    }
    eprintln!("ida: θ covered {ct}/{reps}, β covered {cb}/{reps}");
    assert!(ct >= 180 && cb >= 180, "coverage θ {ct}/200, β {cb}/200");
}

#[test]
fn bootstrap_is_deterministic_for_a_seed_and_any_thread_count() {
    let d = stripe_data_from(&capacities(0.5, 0.4, 40, 7), &STRIPE_IM);
    let s = BootstrapSettings {
        samples: 300,
        seed: 42,
        level: 0.9,
    };
    let band = [0.25, 0.5, 1.0];
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| bootstrap_stripes(&d, &s, &band).unwrap())
    };
    let one = run(1);
    assert_eq!(one, run(2));
    assert_eq!(one, run(1));
    assert_eq!(one.band.len(), 3);
    let other = bootstrap_stripes(&d, &BootstrapSettings { seed: 43, ..s }, &band).unwrap();
    assert_ne!(
        one.theta, other.theta,
        "a different seed draws different resamples"
    );
    // Intervals bracket the fit; the band brackets the fitted curve and is monotone in IM.
    let (theta, beta) = lognormal(one.fit);
    let (tl, th) = one.theta.unwrap();
    let (bl, bh) = one.beta.unwrap();
    assert!(tl < theta && theta < th && bl < beta && beta < bh);
    for p in &one.band {
        let (lo, hi) = p.interval.unwrap();
        assert!(lo <= p.p.unwrap() && p.p.unwrap() <= hi, "{p:?}");
    }
    let ida = IdaData {
        im_at_exceedance: capacities(0.5, 0.4, 30, 9).into_iter().map(Some).collect(),
    };
    let s = BootstrapSettings {
        samples: 200,
        seed: 5,
        level: 0.95,
    };
    let pool = |t: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build()
            .unwrap()
    };
    let a = pool(1).install(|| bootstrap_ida(&ida, &s, &band).unwrap());
    let b = pool(2).install(|| bootstrap_ida(&ida, &s, &band).unwrap());
    assert_eq!(a, b);
}

#[test]
fn bootstrap_of_data_without_a_fit_gives_no_intervals_and_counts_failures() {
    let d = stripes(&[0.1, 0.2, 0.4], &[10; 3], &[0, 0, 10]);
    let s = BootstrapSettings {
        samples: 50,
        seed: 1,
        level: 0.95,
    };
    let b = bootstrap_stripes(&d, &s, &[0.3]).unwrap();
    assert_eq!(b.fit, Fit::NoFiniteMle(NoMle::PerfectlySeparated));
    assert_eq!(
        b.failed, 50,
        "every resample of separated data is separated"
    );
    assert!(b.theta.is_none() && b.beta.is_none() && b.band[0].interval.is_none());
    assert!(b.band[0].p.is_none());
}

#[test]
fn bad_input_is_an_error_naming_the_field() {
    let msg = |e: FragilityError| e.to_string();
    let good = stripes(&[0.2, 0.4], &[3, 3], &[1, 2]);
    let mut d = good.clone();
    d.im[1] = f64::NAN;
    assert!(msg(fit_stripes(&d).unwrap_err()).contains("`im[1]` = nan"));
    d.im[1] = 0.0;
    assert!(msg(fit_stripes(&d).unwrap_err()).contains("`im[1]` = 0 must be finite and > 0"));
    d.im[1] = 0.2;
    assert!(msg(fit_stripes(&d).unwrap_err()).contains("`im[0]` and `im[1]` are both 0.2"));
    let mut d = good.clone();
    d.exceeded[2].pop();
    assert!(
        msg(fit_stripes(&d).unwrap_err()).contains("`exceeded[2]` has 1 outcomes but `im` has 2")
    );
    let empty = StripeData {
        im: vec![],
        exceeded: vec![],
    };
    assert!(msg(fit_stripes(&empty).unwrap_err()).contains("`im` is empty"));
    let no_rows = StripeData {
        im: vec![0.1],
        exceeded: vec![],
    };
    assert!(msg(fit_stripes(&no_rows).unwrap_err()).contains("`exceeded` is empty"));
    let ida = IdaData {
        im_at_exceedance: vec![Some(0.1), Some(-1.0)],
    };
    assert!(msg(fit_ida(&ida).unwrap_err()).contains("`im_at_exceedance[1]` = -1"));
    let ida_empty = IdaData {
        im_at_exceedance: vec![],
    };
    assert!(msg(fit_ida(&ida_empty).unwrap_err()).contains("`im_at_exceedance` is empty"));
    let s = BootstrapSettings {
        samples: 0,
        seed: 1,
        level: 0.95,
    };
    assert!(msg(bootstrap_stripes(&good, &s, &[]).unwrap_err()).contains("`samples` = 0"));
    for level in [0.0, 1.0, 95.0, f64::NAN] {
        let s = BootstrapSettings {
            samples: 10,
            seed: 1,
            level,
        };
        let e = msg(bootstrap_stripes(&good, &s, &[]).unwrap_err());
        assert!(
            e.contains("`level`") && e.contains("strictly between 0 and 1"),
            "{e}"
        );
    }
    let s = BootstrapSettings {
        samples: 10,
        seed: 1,
        level: 0.9,
    };
    assert!(
        msg(bootstrap_ida(
            &IdaData {
                im_at_exceedance: vec![Some(1.0)]
            },
            &s,
            &[0.1, f64::INFINITY]
        )
        .unwrap_err())
        .contains("`band_im[1]` = inf")
    );
}

#[test]
fn writers_give_one_row_per_limit_state_with_nan_and_null_for_missing_numbers() {
    let d = stripe_data_from(&capacities(0.5, 0.4, 40, 11), &STRIPE_IM);
    let s = BootstrapSettings {
        samples: 100,
        seed: 3,
        level: 0.95,
    };
    let b = bootstrap_stripes(&d, &s, &[0.5]).unwrap();
    let ok = FragilityRow::from_stripes("unseating", &d, Some(b.clone())).unwrap();
    let sep = stripes(&[0.1, 0.2], &[4, 4], &[0, 4]);
    let none = FragilityRow::from_stripes("pound, \"hard\"", &sep, None).unwrap();
    let ida = IdaData {
        im_at_exceedance: vec![Some(0.3), None, Some(0.4)],
    };
    let cens = FragilityRow::from_ida("opening", &ida, None).unwrap();
    let csv = fragility_csv(&[ok, none, cens]);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "limit_state,method,status,theta,beta,theta_lo,theta_hi,beta_lo,beta_hi,level,n_records,n_runs,bootstrap_samples,bootstrap_failed"
    );
    let f: Vec<&str> = lines[1].split(',').collect();
    let (theta, beta) = lognormal(b.fit);
    assert_eq!(&f[..3], ["unseating", "mle_stripes", "ok"]);
    assert_eq!(f[3].parse::<f64>().unwrap(), theta, "θ round-trips");
    assert_eq!(f[4].parse::<f64>().unwrap(), beta);
    assert_eq!(f[5].parse::<f64>().unwrap(), b.theta.unwrap().0);
    assert_eq!(&f[9..], ["0.95", "40", "320", "100", &b.failed.to_string()]);
    assert_eq!(
        lines[2],
        "\"pound, \"\"hard\"\"\",mle_stripes,perfectly_separated,nan,nan,nan,nan,nan,nan,nan,4,8,0,0"
    );
    assert_eq!(
        lines[3],
        "opening,moments_ida,censored,nan,nan,nan,nan,nan,nan,nan,3,2,0,0"
    );
    let rows = [
        FragilityRow::from_stripes("unseating", &d, Some(b)).unwrap(),
        FragilityRow::from_ida("opening", &ida, None).unwrap(),
    ];
    let j = fragility_json(&rows);
    assert_eq!(j["fits"][0]["theta"].as_f64(), Some(theta));
    assert_eq!(j["fits"][0]["band"][0]["im"].as_f64(), Some(0.5));
    assert!(
        j["fits"][0]["band"][0]["lo"].as_f64().unwrap()
            < j["fits"][0]["band"][0]["hi"].as_f64().unwrap()
    );
    assert!(j["fits"][1]["theta"].is_null() && j["fits"][1]["theta_lo"].is_null());
    assert_eq!(j["fits"][1]["status"], "censored");
    assert_eq!(j["fits"][1]["censored"], 1);
}

#[test]
fn random_stripe_data_always_get_a_stationary_fit_or_a_verified_status() {
    // 3,000 small random data sets over IMs spanning 1e-6 to 1e6 (extreme tails of Φ): never
    // `NotConverged`; a fit is a local maximum of ℓ with a vanishing gradient; a status other than
    // `NotIncreasing` is checked against the counts independently.
    let mut rng = ChaCha8Rng::seed_from_u64(2024);
    use rand::Rng;
    let mut out_of_range = 0;
    for case in 0..3000 {
        let k = rng.random_range(2..7);
        let spread: f64 = [0.2, 1.0, 5.0, 27.0][case % 4];
        let mut im: Vec<f64> = (0..k)
            .map(|_| (spread * (rng.random::<f64>() - 0.5)).exp())
            .collect();
        im.sort_by(f64::total_cmp);
        im.dedup();
        let n: Vec<usize> = im.iter().map(|_| rng.random_range(1..6)).collect();
        let z: Vec<usize> = n.iter().map(|&n| rng.random_range(0..=n)).collect();
        let d = stripes(&im, &n, &z);
        let fit = fit_stripes(&d).unwrap();
        let frac: Vec<f64> = n
            .iter()
            .zip(&z)
            .map(|(&n, &z)| z as f64 / n as f64)
            .collect();
        match fit {
            Fit::Lognormal { theta, beta } => {
                let counts = d.counts();
                let ll = |lt: f64, lb: f64| stripe_log_likelihood(&counts, lt.exp(), lb.exp());
                let (lt, lb) = (theta.ln(), beta.ln());
                let top = ll(lt, lb);
                for (dt, db) in [(1e-4, 0.0), (-1e-4, 0.0), (0.0, 1e-4), (0.0, -1e-4)] {
                    assert!(
                        ll(lt + dt * beta, lb + db) <= top + 1e-12 * top.abs(),
                        "case {case}: {d:?}"
                    );
                }
            }
            Fit::NoFiniteMle(NoMle::NoExceedance) => assert!(z.iter().all(|&z| z == 0)),
            Fit::NoFiniteMle(NoMle::AllExceeded) => assert!(z == n),
            Fit::NoFiniteMle(NoMle::PerfectlySeparated) => {
                // Some stripe s: all below 0 %, all above 100 %.
                assert!(
                    (0..im.len()).any(|s| frac[..s].iter().all(|&f| f == 0.0)
                        && frac[s + 1..].iter().all(|&f| f == 1.0)),
                    "case {case}: {frac:?}"
                );
            }
            Fit::NoFiniteMle(NoMle::NotIncreasing) => {}
            Fit::NoFiniteMle(NoMle::OutOfRange) => out_of_range += 1,
            other => panic!("case {case}: {other:?} for {frac:?} at {im:?}"),
        }
    }
    assert!(out_of_range < 10, "{out_of_range} fits out of range");
    // The one found: a finite maximum with 1/β ≈ 3.6e-4, θ ≈ e^{1600}: a status, not a number.
    let im = [
        0.12873120679856964,
        0.3512179546131127,
        1.9022359548907328,
        2.3646646790419674,
        5.628512914864313,
    ];
    let d = stripes(&im, &[4, 4, 4, 1, 5], &[1, 1, 2, 0, 1]);
    assert_eq!(
        fit_stripes(&d).unwrap(),
        Fit::NoFiniteMle(NoMle::OutOfRange)
    );
    assert_eq!(fit_stripes(&d).unwrap().status(), "out_of_range");
}

#[test]
fn ln_cdf_is_smooth_across_its_branch_points() {
    // Branches of ln Φ at z = −1.25√2, −1, 1 and of erfc at x = 0.25, 0.84375, 1.25, 1/0.35, 28:
    // on either side of each the slope agrees with the inverse Mills ratio φ/Φ (no jump).
    let s2 = std::f64::consts::SQRT_2;
    for z0 in [
        -1.25 * s2,
        -1.0,
        1.0,
        -0.25 * s2,
        -0.84375 * s2,
        -s2 / 0.35,
        -28.0 * s2,
        0.84375 * s2,
    ] {
        for z in [z0 - 1e-9, z0, z0 + 1e-9] {
            let h = 1e-6;
            let slope = (ln_cdf(z + h) - ln_cdf(z - h)) / (2.0 * h);
            let mills = (ln_pdf(z) - ln_cdf(z)).exp();
            assert!(
                rel(slope, mills) < 1e-6,
                "z = {z}: slope {slope}, φ/Φ = {mills}"
            );
        }
    }
}
