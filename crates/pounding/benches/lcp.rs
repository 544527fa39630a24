//! Lemke and enumeration on the `LCPSET` sample shipped in `tests/data` (the `impact3`, `p6` and
//! `p12` classes; one iteration = one pass over every problem of the class, single-threaded,
//! including the solver's own verification). Divan reports the time per pass; divide by the class
//! size (20, 10, 6) for the time per solve. `pounding lcp bench` measures solves/s on any set.

use pounding::lcp::io::{LcpEntry, read_lcpset};
use pounding::lcp::{LcpSolution, Lemke, LemkeSettings, enumerate, solve_fixed};
use std::hint::black_box;
use std::sync::OnceLock;

fn main() {
    divan::main();
}

fn sample() -> &'static [LcpEntry] {
    static SET: OnceLock<Vec<LcpEntry>> = OnceLock::new();
    SET.get_or_init(|| {
        let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data/lcp_problems_sample.txt");
        read_lcpset(&p).expect("the LCPSET sample in tests/data")
    })
}

fn class(name: &str) -> Vec<&'static LcpEntry> {
    sample().iter().filter(|e| e.class == name).collect()
}

const CLASSES: &[&str] = &["impact3", "p6", "p12"];

/// `Lemke::solve_into` (dispatches n = 3, 6, 12 to the size-specialised kernels).
#[divan::bench(args = CLASSES)]
fn lemke(bencher: divan::Bencher, name: &str) {
    let probs = class(name);
    let mut lemke = Lemke::new(LemkeSettings::default());
    let mut sol: LcpSolution = lemke.solve(&probs[0].problem);
    bencher.bench_local(|| {
        for e in &probs {
            lemke.solve_into(black_box(&e.problem), &mut sol);
            black_box(&sol);
        }
    });
}

/// `solve_fixed::<3>` on the impact3 class (the call the impact code makes).
#[divan::bench]
fn fixed3_impact3(bencher: divan::Bencher) {
    let probs: Vec<([[f64; 3]; 3], [f64; 3])> = class("impact3")
        .iter()
        .map(|e| {
            let p = &e.problem;
            (
                std::array::from_fn(|i| std::array::from_fn(|j| p.m(i, j))),
                std::array::from_fn(|i| p.q()[i]),
            )
        })
        .collect();
    let s = LemkeSettings::default();
    bencher.bench_local(|| {
        for (m, q) in &probs {
            black_box(solve_fixed(black_box(m), black_box(q), &s));
        }
    });
}

/// Enumeration of all complementary bases (for comparison).
#[divan::bench(args = CLASSES, sample_count = 20)]
fn enumeration(bencher: divan::Bencher, name: &str) {
    let probs = class(name);
    bencher.bench_local(|| {
        for e in &probs {
            black_box(enumerate(black_box(&e.problem)).unwrap());
        }
    });
}
