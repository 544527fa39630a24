//! Benchmarks of bridges on piers with backwalls (the substructure's speed targets), library
//! calls only (the whole process adds reading the record and writing the files):
//! * `examples/bridge-piers-1d.toml`: bridge P along its axis, the bilinear compliance law at
//!   dt = 5e-5 over the 53.7 s record (1.07 M steps); the OpenSees run of the same bridge takes
//!   about 24 s on this machine: target 20 × faster;
//! * `examples/bridge-piers.toml` in plan with the rigid law at dt = 1e-3: target < 100 ms.

use pounding::sim::scenario::{BridgeSetup, Scenario};
use std::path::Path;

fn main() {
    divan::main();
}

fn example(name: &str, edit: impl Fn(String) -> String) -> BridgeSetup {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    let text = edit(std::fs::read_to_string(&p).unwrap());
    Scenario::from_toml(&text, name)
        .unwrap()
        .build_bridge()
        .unwrap()
}

/// Bridge P along its axis with piers, backwalls, backfill and piles (compliance, dt = 5e-5).
#[divan::bench(sample_count = 3, sample_size = 1)]
fn bridge_p_1d_compliance(bencher: divan::Bencher) {
    let setup = example("bridge-piers-1d.toml", |t| t);
    bencher.bench(|| setup.run().unwrap().summary.impacts);
}

/// Bridge P in plan, rigid law at every site, dt = 1e-3.
#[divan::bench(sample_count = 10, sample_size = 1)]
fn bridge_p_plan_rigid(bencher: divan::Bencher) {
    let setup = example("bridge-piers.toml", |t| {
        t.replace("dt = 5e-5 ", "dt = 1e-3 ")
            .replace("law = \"bilinear\"", "law = \"rigid\"")
            .replace("k1 = 1.5586e10", "")
            .replace("k2 = 3.1328e9", "")
            .replace("delta_y = 2.54e-3", "")
    });
    bencher.bench(|| setup.run().unwrap().summary.impacts);
}
