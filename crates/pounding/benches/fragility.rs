//! Fragility fitting (issue 13 speed target: fitting and bootstrapping with 1,000 resamples < 1 s).
//!
//! * `fit_stripes_40x8` — maximum likelihood on 40 records × 8 stripes;
//! * `bootstrap_stripes_1000` — that fit plus 1,000 record resamples, jackknife and a 20-IM band,
//!   on the default (all-core) pool;
//! * `bootstrap_ida_1000` — method of moments on 40 records with the same bootstrap;
//! * `bootstrap_ida_censored_1000` — the censored MLE on those 40 records truncated at IM 0.6
//!   (right-censored above it, 14 records) with the same bootstrap.

use pounding::fragility::{
    BootstrapSettings, CensoredIdaData, IdaData, IdaRecord, StripeData, bootstrap_ida,
    bootstrap_ida_censored, bootstrap_stripes, fit_stripes,
};
use std::hint::black_box;

fn main() {
    divan::main();
}

/// Deterministic "capacities" 0.5 · e^{0.4 ε} with ε spread over normal scores.
fn capacities() -> Vec<f64> {
    (0..40)
        .map(|i| {
            let p = (i as f64 + 0.5) / 40.0;
            0.5 * (0.4 * pounding::fragility::normal::quantile(p)).exp()
                * (1.0 + 0.01 * ((i * 7) % 5) as f64)
        })
        .collect()
}

fn stripes() -> StripeData {
    let im = vec![0.2, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9, 1.2];
    let exceeded = capacities()
        .iter()
        .enumerate()
        .map(|(r, c)| {
            im.iter()
                .map(|&x| Some(x * (1.0 + 0.3 * ((r % 3) as f64 - 1.0)) >= *c))
                .collect()
        })
        .collect();
    StripeData { im, exceeded }
}

fn band() -> Vec<f64> {
    (1..=20).map(|i| 0.075 * i as f64).collect()
}

#[divan::bench]
fn fit_stripes_40x8(bencher: divan::Bencher) {
    let d = stripes();
    bencher.bench(|| fit_stripes(black_box(&d)).unwrap());
}

#[divan::bench(sample_count = 10)]
fn bootstrap_stripes_1000(bencher: divan::Bencher) {
    let d = stripes();
    let s = BootstrapSettings {
        samples: 1000,
        seed: 1,
        level: 0.95,
    };
    let band = band();
    bencher.bench(|| bootstrap_stripes(black_box(&d), &s, &band).unwrap());
}

#[divan::bench(sample_count = 10)]
fn bootstrap_ida_1000(bencher: divan::Bencher) {
    let d = IdaData {
        im_at_exceedance: capacities().into_iter().map(Some).collect(),
    };
    let s = BootstrapSettings {
        samples: 1000,
        seed: 1,
        level: 0.95,
    };
    let band = band();
    bencher.bench(|| bootstrap_ida(black_box(&d), &s, &band).unwrap());
}

#[divan::bench(sample_count = 10)]
fn bootstrap_ida_censored_1000(bencher: divan::Bencher) {
    let d = CensoredIdaData {
        records: capacities()
            .into_iter()
            .map(|c| {
                if c > 0.6 {
                    IdaRecord::NotExceeded(0.6)
                } else {
                    IdaRecord::Exceeded(c)
                }
            })
            .collect(),
    };
    let s = BootstrapSettings {
        samples: 1000,
        seed: 1,
        level: 0.95,
    };
    let band = band();
    bencher.bench(|| bootstrap_ida_censored(black_box(&d), &s, &band).unwrap());
}
