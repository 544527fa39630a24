//! The study's cell kernel and a whole-configuration block (single-threaded).
//!
//! * `cell` — one non-degenerate cell: configuration, Delassus matrix, `[L, U]` and the LCP check
//!   (three Lemke solves), as `compute_cell` does for every row of `bounds.csv`.
//! * `lcp_check` — the three Lemke solves + analytic modes of one cell alone.
//! * `block_441` — one configuration and case on the default 21 × 21 grid (441 rows).
//! * `bounds_csv_441` — formatting those 441 rows as CSV text.

use pounding::analytic::ImpactLaw;
use pounding::geometry::{ContactCase, SigmaMode};
use pounding::study::cell::{compute_cell, lcp_agrees};
use pounding::study::csv::bounds_csv;
use pounding::study::run::compute_rows;
use pounding::study::{Scenario, Shard};
use std::hint::black_box;

fn main() {
    divan::main();
}

fn one_block() -> Scenario {
    let text = "[decks]\nbeta1_deg = [60.0]\nbeta2_deg = [90.0]\nr1_m = [100.0]\nr2_m = [200.0]\n[impact]\nmu = [0.5]\n[grid]\ncases = [\"deck1-inner\"]\n";
    Scenario::from_toml(text, "bench").expect("valid")
}

#[divan::bench]
fn cell(b: divan::Bencher) {
    let s = one_block();
    let arr = s.arrangement(0, 0, 0, 0).expect("valid");
    let law = s.law(0, 0).expect("valid");
    b.bench(|| {
        compute_cell(
            black_box(&arr),
            &law,
            ContactCase::Deck1Inner,
            black_box(-5.0),
            black_box(2.0),
            SigmaMode::Exact,
            1e-9,
        )
    });
}

#[divan::bench]
fn lcp_check(b: divan::Bencher) {
    let s = one_block();
    let arr = s.arrangement(0, 0, 0, 0).expect("valid");
    let law = ImpactLaw::new(0.5, 0.5).expect("valid");
    let cfg = arr
        .configuration(
            ContactCase::Deck1Inner,
            (-5.0f64).to_radians(),
            2.0f64.to_radians(),
            SigmaMode::Exact,
        )
        .expect("non-degenerate");
    let g = arr.delassus(&cfg);
    let iv = pounding::analytic::stick_interval(&g, &law);
    b.bench(|| lcp_agrees(black_box(&g), &law, iv.lower, iv.upper));
}

#[divan::bench]
fn block_441(b: divan::Bencher) {
    let s = one_block();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    b.bench(|| pool.install(|| compute_rows(black_box(&s), Shard::ALL, &|_| {})));
}

#[divan::bench]
fn bounds_csv_441(b: divan::Bencher) {
    let s = one_block();
    let rows = compute_rows(&s, Shard::ALL, &|_| {}).expect("rows");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    b.bench(|| pool.install(|| bounds_csv(black_box(&s), &rows)));
}
