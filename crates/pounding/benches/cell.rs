//! The study's per-cell kernel: impact configuration → force directions `w` → Delassus `G` →
//! stick interval `L, U` → one impact LCP (3×3, `lcp::solve_fixed::<3>`), single-threaded.
//!
//! One iteration is a pass over the 21 × 21 θ-grid (−10°…10°, 1° steps) × 4 cases of one deck
//! configuration (R = 100/200 m, β = 60/120°, μ = 0.5, ε = 0.5) = 1764 cells (the 84 degenerate
//! diagonal cells are reported as such and cost almost nothing, as in the study). Divan's
//! `items/s` throughput is the number of cells per second. The ratio solved per cell cycles through
//! `L − 1e-6`, mid-interval and `U + 1e-6` (the study's `lcp_agrees` probes) so that all three modes
//! are exercised.
//!
//! * `cell_prepared` — mass properties computed once per configuration (what a study loop does);
//! * `cell_contract` — the plain `SArrangement::configuration` + `contact::delassus` calls, which
//!   recompute the mass properties for every cell.

use pounding::analytic::{ImpactLaw, stick_interval};
use pounding::contact::{delassus_with, force_directions};
use pounding::geometry::{ContactCase, SigmaMode};
use pounding::impact::solve_single;
use pounding::lcp::LemkeSettings;
use pounding::pair::SArrangement;
use pounding::shape::Deck;
use std::hint::black_box;

fn main() {
    divan::main();
}

const CELLS: usize = 21 * 21 * 4;

fn setup() -> (SArrangement, ImpactLaw, Vec<(ContactCase, f64, f64)>) {
    let d1 = Deck::new(100.0, 60f64.to_radians(), 10.0, 0.5, 2500.0).unwrap();
    let d2 = Deck::new(200.0, 120f64.to_radians(), 10.0, 0.5, 2500.0).unwrap();
    let s = SArrangement::new(d1, d2).unwrap();
    let law = ImpactLaw::new(0.5, 0.5).unwrap();
    let mut cells = Vec::with_capacity(CELLS);
    for case in ContactCase::ALL {
        for i in 0..21 {
            for j in 0..21 {
                let t1 = (-10.0 + i as f64).to_radians();
                let t2 = (-10.0 + j as f64).to_radians();
                cells.push((case, t1, t2));
            }
        }
    }
    (s, law, cells)
}

#[inline(always)]
fn probe(k: usize, lower: f64, upper: f64) -> f64 {
    match k % 3 {
        0 => lower - 1e-6 * lower.abs().max(1.0),
        1 => 0.5 * (lower + upper),
        _ => upper + 1e-6 * upper.abs().max(1.0),
    }
}

#[divan::bench]
fn cell_prepared(bencher: divan::Bencher) {
    let (s, law, cells) = setup();
    let settings = LemkeSettings::default();
    bencher
        .counter(divan::counter::ItemsCount::new(CELLS))
        .bench_local(|| {
            let (p1, p2) = (s.deck1.mass_properties(), s.deck2.mass_properties());
            let mut acc = 0.0;
            for (k, &(case, t1, t2)) in cells.iter().enumerate() {
                let Ok(c) =
                    s.configuration_with(&p1, &p2, case, black_box(t1), t2, SigmaMode::Exact)
                else {
                    continue;
                };
                let w = force_directions(&c);
                let g = delassus_with(&p1, &p2, &w);
                let b = stick_interval(&g, &law);
                let r = probe(k, b.lower, b.upper);
                let sol = solve_single(&g, &law, -1.0, -r, &settings);
                acc += sol.normal_impulse + sol.gamma_t_post;
            }
            black_box(acc)
        });
}

#[divan::bench]
fn cell_contract(bencher: divan::Bencher) {
    let (s, law, cells) = setup();
    let settings = LemkeSettings::default();
    bencher
        .counter(divan::counter::ItemsCount::new(CELLS))
        .bench_local(|| {
            let mut acc = 0.0;
            for (k, &(case, t1, t2)) in cells.iter().enumerate() {
                let Ok(c) = s.configuration(case, black_box(t1), t2, SigmaMode::Exact) else {
                    continue;
                };
                let g = s.delassus(&c);
                let b = stick_interval(&g, &law);
                let r = probe(k, b.lower, b.upper);
                let sol = solve_single(&g, &law, -1.0, -r, &settings);
                acc += sol.normal_impulse + sol.gamma_t_post;
            }
            black_box(acc)
        });
}
