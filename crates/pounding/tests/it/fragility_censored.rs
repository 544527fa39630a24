//! Censored IDA fits (truncated IDA, Baker 2015): the censored-lognormal MLE against an
//! independent grid search, its relation to the closed-form MLE and to the method of moments
//! without censoring, bootstrap coverage on truncated lognormal data, the statuses of data
//! without a finite maximum (each one checked against the likelihood itself), the workflow.

use crate::fragility_trial::run;
use pounding::assessment::Stripes;
use pounding::assessment::run::{Plan, RunRow, fit_limit_state};
use pounding::fragility::normal::{cdf, pdf};
use pounding::fragility::{
    Bootstrap, BootstrapSettings, CensoredIdaData, Fit, FragilityRow, IdaData, IdaRecord, Method,
    NoMle, StripeData, bootstrap_ida, bootstrap_ida_censored, censored_log_likelihood,
    censored_mle, fit_ida, fit_ida_censored, fit_stripes, fragility_csv, fragility_json,
};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};

use IdaRecord::{Exceeded as E, ExceededAtFirst as L, NotExceeded as R};

fn data(records: &[IdaRecord]) -> CensoredIdaData {
    CensoredIdaData {
        records: records.to_vec(),
    }
}

fn params(fit: Fit) -> (f64, f64) {
    fit.params()
        .unwrap_or_else(|| panic!("expected a lognormal fit, got {fit:?}"))
}

/// The censored log-likelihood written out independently of the library (densities and
/// probabilities, not their logarithms, from Φ and φ).
fn loglik(records: &[IdaRecord], theta: f64, beta: f64) -> f64 {
    records
        .iter()
        .map(|r| match *r {
            E(x) => (pdf((x.ln() - theta.ln()) / beta) / beta).ln(),
            R(x) => (1.0 - cdf((x.ln() - theta.ln()) / beta)).ln(),
            L(x) => cdf((x.ln() - theta.ln()) / beta).ln(),
        })
        .sum()
}

/// Maximises `loglik` over `(ln θ, ln β)` by a zooming grid search: a 41 × 41 grid around the best
/// point, moved (not shrunk) while the best point is on the edge, shrunk four-fold otherwise,
/// until the spacing is below 1e-10.
fn grid_max(records: &[IdaRecord]) -> (f64, f64) {
    let (mut c, mut w) = ((0.5f64.ln(), 0.5f64.ln()), 3.0);
    while w > 1e-10 {
        let mut best = (f64::NEG_INFINITY, c, true);
        for i in -20..=20 {
            for j in -20..=20 {
                let p = (c.0 + w * i as f64 / 20.0, c.1 + w * j as f64 / 20.0);
                let l = loglik(records, p.0.exp(), p.1.exp());
                if l > best.0 {
                    best = (l, p, i32::abs(i) == 20 || i32::abs(j) == 20);
                }
            }
        }
        c = best.1;
        if !best.2 {
            w /= 4.0;
        }
    }
    (c.0.exp(), c.1.exp())
}

const HAND: [IdaRecord; 9] = [
    E(0.31),
    E(0.42),
    E(0.47),
    E(0.55),
    E(0.68),
    R(0.8),
    R(0.8),
    R(0.9),
    L(0.25),
];

#[test]
fn censored_mle_matches_an_independent_grid_search() {
    let d = data(&HAND);
    let (theta, beta) = params(censored_mle(&d).unwrap());
    let (gt, gb) = grid_max(&HAND);
    assert!(
        (theta - gt).abs() < 1e-6 * gt && (beta - gb).abs() < 1e-6 * gb,
        "MLE ({theta}, {beta}), grid ({gt}, {gb})"
    );
    // The library's likelihood is the test's, and the fit is a stationary point of it.
    for (t, b) in [(theta, beta), (0.3, 0.2), (1.5, 1.0)] {
        let (a, e) = (censored_log_likelihood(&HAND, t, b), loglik(&HAND, t, b));
        // (the test's 1 − Φ loses digits in the far tail: 1e-9)
        assert!((a - e).abs() < 1e-9 * (1.0 + e.abs()), "{a} {e}");
    }
    let h = 1e-6;
    let dt =
        (loglik(&HAND, theta * (1.0 + h), beta) - loglik(&HAND, theta * (1.0 - h), beta)) / 2.0;
    let db =
        (loglik(&HAND, theta, beta * (1.0 + h)) - loglik(&HAND, theta, beta * (1.0 - h))) / 2.0;
    assert!(dt.abs() < 1e-9 && db.abs() < 1e-9, "{dt} {db}");
    // The censored records pull θ above the exact-only median (three records are above 0.8).
    let exact_only = (HAND[..5].iter().map(|r| r.im().ln()).sum::<f64>() / 5.0).exp();
    assert!(theta > exact_only, "{theta} vs {exact_only}");
    // The data call for the censored estimator, with its counts.
    let (m, fit) = fit_ida_censored(&d).unwrap();
    assert_eq!(m, Method::MleCensoredIda { right: 3, left: 1 });
    assert_eq!(m.as_str(), "mle_censored_ida");
    assert_eq!(fit, censored_mle(&d).unwrap());
}

#[test]
fn without_censoring_the_mle_is_closed_form_and_the_method_of_moments_is_used() {
    let xs = [0.21, 0.33, 0.38, 0.52, 0.6, 0.74, 1.1];
    let recs: Vec<IdaRecord> = xs.iter().map(|&x| E(x)).collect();
    let d = data(&recs);
    let n = xs.len() as f64;
    let mean = xs.iter().map(|x| x.ln()).sum::<f64>() / n;
    let ss: f64 = xs.iter().map(|x| (x.ln() - mean).powi(2)).sum();
    let (theta, beta) = params(censored_mle(&d).unwrap());
    assert!((theta - mean.exp()).abs() < 1e-12 * theta, "{theta}");
    assert!((beta - (ss / n).sqrt()).abs() < 1e-12 * beta, "{beta}");
    // The estimator used is still the method of moments, the same numbers as `fit_ida`.
    let (m, fit) = fit_ida_censored(&d).unwrap();
    assert_eq!(m, Method::MomentsIda);
    let ida = IdaData {
        im_at_exceedance: xs.iter().map(|&x| Some(x)).collect(),
    };
    assert_eq!(fit, fit_ida(&ida).unwrap());
    let (tm, bm) = params(fit);
    assert!((tm - theta).abs() < 1e-12 * theta);
    assert!(
        (bm - beta * (n / (n - 1.0)).sqrt()).abs() < 1e-12 * bm,
        "{bm}"
    );
    // And the bootstrap is `bootstrap_ida`'s, bit for bit.
    let s = BootstrapSettings {
        samples: 200,
        seed: 9,
        level: 0.9,
    };
    let band = [0.3, 0.6];
    assert_eq!(
        bootstrap_ida_censored(&d, &s, &band).unwrap(),
        bootstrap_ida(&ida, &s, &band).unwrap()
    );
}

/// 40 capacities from the lognormal (θ = 0.5, β = 0.4), IDA truncated at IM 0.62 (about 30 %
/// right-censored) and starting at 0.25 (about 4 % left-censored).
fn truncated(seed: u64) -> CensoredIdaData {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let records = (0..40)
        .map(|_| {
            let e: f64 = StandardNormal.sample(&mut rng);
            let c = 0.5 * (0.4 * e).exp();
            if c > 0.62 {
                R(0.62)
            } else if c <= 0.25 {
                L(0.25)
            } else {
                E(c)
            }
        })
        .collect();
    CensoredIdaData { records }
}

fn covers(b: &Bootstrap) -> (bool, bool) {
    let inside = |iv: Option<(f64, f64)>, v: f64| iv.is_some_and(|(lo, hi)| lo <= v && v <= hi);
    (inside(b.theta, 0.5), inside(b.beta, 0.4))
}

#[test]
fn censored_bootstrap_intervals_cover_the_true_parameters() {
    let (mut ct, mut cb, mut failed, mut right) = (0, 0, 0, 0);
    let reps = 200;
    for rep in 0..reps {
        let d = truncated(9000 + rep);
        right += d.counts().1;
        let s = BootstrapSettings {
            samples: 400,
            seed: rep,
            level: 0.95,
        };
        let b = bootstrap_ida_censored(&d, &s, &[]).unwrap();
        failed += b.failed;
        let (t, be) = covers(&b);
        ct += usize::from(t);
        cb += usize::from(be);
    }
    let frac = right as f64 / (40.0 * reps as f64);
    eprintln!(
        "censored ida: {:.1} % right-censored, θ covered {ct}/{reps}, β covered {cb}/{reps}, \
         {failed} failed replicates",
        100.0 * frac
    );
    assert!((0.25..0.35).contains(&frac), "{frac}");
    assert!(ct >= 180 && cb >= 180, "coverage θ {ct}/200, β {cb}/200");
}

#[test]
fn censored_bootstrap_is_deterministic_for_any_thread_count() {
    let d = truncated(77);
    let s = BootstrapSettings {
        samples: 300,
        seed: 5,
        level: 0.9,
    };
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| bootstrap_ida_censored(&d, &s, &[0.3, 0.5]).unwrap())
    };
    let one = run(1);
    assert_eq!(one, run(2));
    let (theta, beta) = params(one.fit);
    let ((tl, th), (bl, bh)) = (one.theta.unwrap(), one.beta.unwrap());
    assert!(tl < theta && theta < th && bl < beta && beta < bh);
}

/// `records` has no fit, the status `why`, no numbers, no intervals, `nan` in the CSV.
fn no_fit(records: &[IdaRecord], why: NoMle) {
    let d = data(records);
    assert_eq!(
        censored_mle(&d).unwrap(),
        Fit::NoFiniteMle(why),
        "{records:?}"
    );
    let s = BootstrapSettings {
        samples: 50,
        seed: 1,
        level: 0.95,
    };
    let b = bootstrap_ida_censored(&d, &s, &[0.5]).unwrap();
    assert!(b.theta.is_none() && b.beta.is_none() && b.band[0].interval.is_none());
    let row = FragilityRow::from_ida_censored("ls", &d, Some(b)).unwrap();
    let csv = fragility_csv(std::slice::from_ref(&row));
    let line = csv.lines().nth(1).unwrap();
    assert!(
        line.starts_with(&format!("ls,mle_censored_ida,{},nan,nan,", why.as_str())),
        "{line}"
    );
    assert!(fragility_json(&[row])["fits"][0]["theta"].is_null());
}

#[test]
fn data_without_a_finite_censored_mle_get_a_status_not_numbers() {
    // No exact observation: the probit likelihood of one run per record.
    no_fit(&[R(0.5), R(0.7), R(0.9)], NoMle::NoExceedance);
    no_fit(&[L(0.2), L(0.3)], NoMle::AllExceeded);
    no_fit(&[R(0.2), R(0.3), L(0.5), L(0.6)], NoMle::PerfectlySeparated);
    no_fit(&[R(0.5), L(0.5)], NoMle::TooFewPoints);
    no_fit(&[L(0.2), R(0.3), L(0.4), R(0.5)], NoMle::NotIncreasing);
    // All exact observations equal and every bound on their side (case B2): ℓ → ∞ as β → 0.
    for recs in [
        &[E(0.5), R(0.4)][..],
        &[E(0.5), E(0.5), R(0.4)],
        &[E(0.5), E(0.5), R(0.5), L(0.5)],
        &[E(0.5), L(0.7), R(0.3)],
    ] {
        no_fit(recs, NoMle::NoDispersion);
        let l: Vec<f64> = [1e-1, 1e-3, 1e-6]
            .iter()
            .map(|&b| loglik(recs, 0.5, b))
            .collect();
        assert!(l[0] < l[1] && l[1] < l[2], "{recs:?}: {l:?}");
    }
}

#[test]
fn one_bound_beyond_identical_exact_observations_gives_a_finite_maximum() {
    // Case B1 of the proof: the same exact IMs, one bound on the far side: a stationary maximum.
    for recs in [
        &[E(0.5), R(0.6)][..],
        &[E(0.5), E(0.5), L(0.4), R(0.3)],
        &[E(0.5), E(0.5), E(0.5), R(0.5), R(0.5), R(0.8)],
    ] {
        let (theta, beta) = params(censored_mle(&data(recs)).unwrap());
        let (gt, gb) = grid_max(recs);
        assert!(
            (theta - gt).abs() < 1e-6 * gt && (beta - gb).abs() < 1e-6 * gb,
            "{recs:?}: MLE ({theta}, {beta}), grid ({gt}, {gb})"
        );
    }
}

#[test]
fn only_censored_records_are_fitted_as_one_run_per_record_stripes() {
    let recs = [
        R(0.2),
        L(0.3),
        R(0.3),
        R(0.4),
        L(0.5),
        R(0.6),
        L(0.6),
        L(0.8),
    ];
    let stripes = StripeData {
        im: vec![0.2, 0.3, 0.4, 0.5, 0.6, 0.8],
        exceeded: vec![
            vec![
                Some(false),
                Some(true),
                Some(false),
                Some(true),
                Some(false),
                Some(true),
            ],
            vec![None, Some(false), None, None, Some(true), None],
        ],
    };
    let (theta, beta) = params(censored_mle(&data(&recs)).unwrap());
    assert_eq!((theta, beta), params(fit_stripes(&stripes).unwrap()));
    let (gt, gb) = grid_max(&recs);
    assert!((theta - gt).abs() < 1e-6 * gt && (beta - gb).abs() < 1e-6 * gb);
}

#[test]
fn random_censored_data_get_a_maximum_or_a_status_that_the_rule_predicts() {
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    use rand::Rng;
    for case in 0..300 {
        let n = rng.random_range(2..12);
        let recs: Vec<IdaRecord> = (0..n)
            .map(|_| {
                // few distinct values, so ties and degenerate sets happen
                let x = [0.2, 0.3, 0.5, 0.8][rng.random_range(0..4)];
                match rng.random_range(0..4) {
                    0 => R(x),
                    1 => L(x),
                    _ => E(x),
                }
            })
            .collect();
        let fit = censored_mle(&data(&recs)).unwrap();
        let exact: Vec<f64> = recs
            .iter()
            .filter(|r| matches!(r, E(_)))
            .map(IdaRecord::im)
            .collect();
        if exact.is_empty() {
            continue; // the stripe rules, tested with the stripe fit
        }
        let y0 = exact[0];
        let b2 = exact.iter().all(|&x| x == y0)
            && recs.iter().all(|r| match *r {
                R(x) => x <= y0,
                L(x) => x >= y0,
                E(_) => true,
            });
        match fit {
            Fit::Lognormal { theta, beta } => {
                assert!(!b2, "case {case}: {recs:?} fitted");
                let l = loglik(&recs, theta, beta);
                for (ft, fb) in [(1.01, 1.0), (0.99, 1.0), (1.0, 1.01), (1.0, 0.99)] {
                    assert!(
                        loglik(&recs, theta * ft, beta * fb) <= l + 1e-12,
                        "case {case}: {recs:?} not a maximum"
                    );
                }
            }
            Fit::NoFiniteMle(why) => {
                assert!(
                    b2 && why == NoMle::NoDispersion,
                    "case {case}: {recs:?}: {why:?}"
                );
            }
        }
    }
}

#[test]
fn bad_censored_input_is_an_error_naming_the_record() {
    let e = censored_mle(&data(&[E(0.5), R(f64::NAN)])).unwrap_err();
    assert!(e.to_string().contains("`records[1]` = nan"), "{e}");
    let e = censored_mle(&data(&[L(-1.0)])).unwrap_err();
    assert!(e.to_string().contains("`records[0]` = -1"), "{e}");
    let e = fit_ida_censored(&data(&[])).unwrap_err();
    assert!(e.to_string().contains("`records` is empty"), "{e}");
}

#[test]
fn the_workflow_fits_records_that_never_exceed_as_right_censored() {
    // Four entries with IM 1 at unit scale, scales 1, 2, 4: two cross between scales, one never
    // exceeds (censored at IM 4), one exceeds at the first scale (at most IM 1).
    let ratios = [
        [0.5, 0.8, 1.5],
        [0.6, 1.2, 2.0],
        [0.1, 0.3, 0.6],
        [1.1, 1.5, 2.5],
    ];
    let rows: Vec<RunRow> = ratios
        .iter()
        .enumerate()
        .flat_map(|(a, rs)| {
            rs.iter()
                .enumerate()
                .map(move |(b, &r)| run(a, b, [1.0, 2.0, 4.0][b], r > 1.0, r))
        })
        .collect();
    let plan = Plan {
        entry_im: vec![1.0; 4],
        stripes: Stripes::Scales(vec![1.0, 2.0, 4.0]),
    };
    let s = BootstrapSettings {
        samples: 100,
        seed: 2,
        level: 0.95,
    };
    let r = fit_limit_state("ls", &plan, &rows, 0, &s, &[1.0, 2.0]).unwrap();
    // crossings: 2 + (1 − 0.8)/(1.5 − 0.8)·2 and 1 + (1 − 0.6)/(1.2 − 0.6)·1
    let expect = [
        E(2.0 + (1.0 - 0.8) / (1.5 - 0.8) * 2.0),
        E(1.0 + (1.0 - 0.6) / (1.2 - 0.6) * 1.0),
        R(4.0),
        L(1.0),
    ];
    assert_eq!(r.method, Method::MleCensoredIda { right: 1, left: 1 });
    assert_eq!(r.fit, censored_mle(&data(&expect)).unwrap());
    assert!(r.fit.params().is_some() && r.bootstrap.is_some());
    assert_eq!((r.n_records, r.n_runs), (4, 3));
    let j = fragility_json(std::slice::from_ref(&r));
    assert_eq!(j["fits"][0]["method"], "mle_censored_ida");
    assert_eq!(j["fits"][0]["censored"], 1);
    assert_eq!(j["fits"][0]["exceeded_at_first"], 1);
    assert_eq!(j["fits"][0]["status"], "ok");
}
