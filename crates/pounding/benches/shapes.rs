//! Deck–abutment impacts of a skewed deck (L = 30 m, W = 10 m), single-threaded.
//!
//! * `single_corner` — Delassus of one corner (mass properties, lever arms) + stick interval + the
//!   3×3 impact LCP (`solve_single`), cycling over 64 skew angles in [0°, 80°) and both corners;
//! * `both_corners` — the generic 2-contact problem (`abutment_problem` + `impact::solve`, 6×6 LCP,
//!   enumeration when `G` is singular) for a longitudinal approach, same angles, μ = 0.3, ε = 0.5.

use pounding::analytic::{ImpactLaw, stick_interval};
use pounding::impact::{self, ImpactSettings, solve_single};
use pounding::lcp::LemkeSettings;
use pounding::shape::{DeckEnd, DeckShape, SkewedDeck, abutment_delassus, abutment_problem};
use std::hint::black_box;

fn main() {
    divan::main();
}

fn decks() -> Vec<DeckShape> {
    (0..64)
        .map(|i| {
            let deg = 80.0 * i as f64 / 64.0;
            DeckShape::Skewed(SkewedDeck::new(30.0, 10.0, deg.to_radians(), 0.5, 2500.0).unwrap())
        })
        .collect()
}

#[divan::bench]
fn single_corner(bencher: divan::Bencher) {
    let decks = decks();
    let law = ImpactLaw::new(0.3, 0.5).unwrap();
    let settings = LemkeSettings::default();
    bencher
        .counter(divan::counter::ItemsCount::new(2 * decks.len()))
        .bench(|| {
            let mut acc = 0.0;
            for d in &decks {
                for k in 0..2 {
                    let g = abutment_delassus(black_box(d), DeckEnd::Far, k);
                    let b = stick_interval(&g, &law);
                    let s = solve_single(&g, &law, -1.0, -0.5 * (b.lower + b.upper), &settings);
                    acc += s.normal_impulse;
                }
            }
            acc
        });
}

#[divan::bench]
fn both_corners(bencher: divan::Bencher) {
    let decks = decks();
    let law = ImpactLaw::new(0.3, 0.5).unwrap();
    let settings = ImpactSettings::default();
    bencher
        .counter(divan::counter::ItemsCount::new(decks.len()))
        .bench(|| {
            let mut acc = 0.0;
            for d in &decks {
                let v = d.axis_direction(DeckEnd::Far);
                let p =
                    abutment_problem(black_box(d), DeckEnd::Far, &[0, 1], v, 0.0, &law).unwrap();
                acc += impact::solve(&p, &settings).bodies[0].omega;
            }
            acc
        });
}
