//! Benchmarks of whole bridges (issue 11 speed targets), library calls only:
//! * the five-segment curved example `examples/viaduct-curved-5.toml` (rigid law, restrainers,
//!   both El Centro 1940 components, 53.7 s at dt = 1e-3, every 10th step kept as the file says):
//!   target < 60 ms on one core;
//! * a chain of 20 straight segments (rigid law, linear bearings, dashpots, two abutments,
//!   El Centro 1940 NS along the chain, dt = 1e-3): target < 250 ms;
//! * a batch of the five-segment example (El Centro NS and EW × 4 scales = 8 runs) on 2 threads:
//!   target ≥ 30 runs/s, i.e. < 267 ms per batch of 8.

use pounding::ground_motion::el_centro_1940;
use pounding::sim::batch::{BatchRecord, BatchShard, run_batch};
use pounding::sim::scenario::{BridgeSetup, Scenario};
use std::path::Path;

fn main() {
    divan::main();
}

fn curved_five() -> BridgeSetup {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-curved-5.toml");
    Scenario::load(&p).unwrap().build_bridge().unwrap()
}

/// `n` straight segments of 30 m (masses and periods varying along the chain), joints 0.02 m,
/// abutments 0.04 m, ε_N = 0.6, μ = 0, El Centro NS toward the end abutment.
fn straight_chain_toml(n: usize) -> String {
    let mut s = String::from(
        "[bridge]\ndamping = \"dashpots\"\ndamping_ratio = 0.05\ngap = 0.02\nmu = 0.0\n\
         eps_n = 0.6\nseat_length = 0.4\n",
    );
    for i in 0..n {
        let mass = [1.0e6, 1.2e6, 0.8e6][i % 3];
        let period = [1.2, 0.5, 1.5, 0.9][i % 4];
        s.push_str(&format!(
            "[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = {mass}\nperiod_s = {period}\n"
        ));
    }
    s.push_str(
        "[abutment.start]\ngap = 0.04\n[abutment.end]\ngap = 0.04\n[ground_motion]\n\
         record_y = \"builtin:ELC180\"\nrecord_x = \"none\"\nscale_y = -1.0\n[time]\ndt = 1e-3\n\
         history_every = 10\n",
    );
    s
}

/// The five-segment curved example, one run.
#[divan::bench(sample_count = 20, sample_size = 1)]
fn curved_five_segments_el_centro(bencher: divan::Bencher) {
    let setup = curved_five();
    bencher.bench(|| {
        let sol = setup.run().unwrap();
        assert!(sol.summary.impacts > 0);
        sol.summary.impacts
    });
}

/// Twenty straight segments, one run.
#[divan::bench(sample_count = 10, sample_size = 1)]
fn straight_twenty_segments_el_centro(bencher: divan::Bencher) {
    let setup = Scenario::from_toml(&straight_chain_toml(20), "chain-20.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    bencher.bench(|| {
        let sol = setup.run().unwrap();
        assert!(sol.summary.impacts > 0);
        sol.summary.impacts
    });
}

/// A batch of 8 runs of the five-segment example on 2 threads (runs/s = 8 / time).
#[divan::bench(sample_count = 10, sample_size = 1)]
fn batch_curved_five_8_runs_2_threads(bencher: divan::Bencher) {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-curved-5.toml");
    let setup = Scenario::load(&p)
        .unwrap()
        .for_batch()
        .build_bridge()
        .unwrap();
    let g = el_centro_1940();
    let records: Vec<BatchRecord> = [g.along_y.unwrap(), g.along_x.unwrap()]
        .into_iter()
        .enumerate()
        .map(|(i, r)| BatchRecord {
            name: format!("elcentro-{i}"),
            record: Ok(r),
            along_x: None,
            supports: Vec::new(),
        })
        .collect();
    let scales = [0.5, 1.0, 1.5, 2.0];
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    bencher.bench(|| {
        let rows = pool
            .install(|| {
                run_batch(
                    &setup.problem,
                    &setup.settings,
                    &records,
                    &scales,
                    BatchShard::ALL,
                    &|_| {},
                )
            })
            .unwrap();
        assert!(rows.iter().all(|r| r.outcome.is_ok()));
        rows.len()
    });
}
