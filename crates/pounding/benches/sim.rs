//! Benchmarks of `pounding::sim::simulate`: the built-in default (El Centro 1940, 53.71 s at
//! dt = 1e-3, both horizontal components, pounding with friction), library call only.

use pounding::ground_motion::el_centro_1940;
use pounding::sim::{SimModel, SimProblem, SimSettings, simulate};

fn main() {
    divan::main();
}

fn default_problem() -> SimProblem {
    SimProblem::at_rest(SimModel::default_bridge(), el_centro_1940())
}

/// The default run, full history kept (every step).
#[divan::bench]
fn default_el_centro_full_history(bencher: divan::Bencher) {
    let p = default_problem();
    let s = SimSettings::default();
    bencher.bench(|| {
        let sol = simulate(divan::black_box(&p), &s).unwrap();
        assert!(sol.summary.impacts > 0);
        sol.summary.impacts
    });
}

/// The default run as the CLI does it (every 10th step kept).
#[divan::bench]
fn default_el_centro_history_every_10(bencher: divan::Bencher) {
    let p = default_problem();
    let s = SimSettings {
        history_stride: 10,
        ..SimSettings::default()
    };
    bencher.bench(|| simulate(divan::black_box(&p), &s).unwrap().summary.impacts);
}

/// The default run as the CLI does it, with the position projection (`--projection`).
#[divan::bench]
fn default_el_centro_history_every_10_projection(bencher: divan::Bencher) {
    let p = default_problem();
    let s = SimSettings {
        history_stride: 10,
        projection: true,
        ..SimSettings::default()
    };
    bencher.bench(|| simulate(divan::black_box(&p), &s).unwrap().summary.impacts);
}

/// Parsing the two embedded AT2 records (not part of the run above).
#[divan::bench]
fn parse_el_centro_records() -> usize {
    el_centro_1940().along_y.unwrap().values().len()
}
