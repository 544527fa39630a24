//! Campaign overhead: the same short runs through the bare library (`run_one` on a 2-thread
//! pool, results dropped) and through the campaign store (`exec::run_parts`: parts of 64 runs
//! computed, encoded as Parquet and written atomically into a store), and the merge of a
//! synthetic store of 10⁶ rows (time; its peak memory is printed by `campaign_merge_memory`).
//!
//! The runs: the fragility example's viaduct on 8 of its synthetic pairs at 8 stripes
//! (64 runs), each run cut to `duration = 1 s` so that the store's share is not hidden by long
//! runs.

use pounding::assessment::run::{run_one, summary_settings};
use pounding::campaign::{Campaign, Store, exec};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

fn main() {
    divan::main();
}

/// A campaign of short runs in a scratch directory.
fn campaign(dir: &Path) -> Campaign {
    let ex = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fragility");
    let text = std::fs::read_to_string(ex.join("viaduct.toml"))
        .unwrap()
        .replace("duration = 15.0", "duration = 1.0");
    std::fs::write(dir.join("viaduct.toml"), text).unwrap();
    std::fs::write(
        dir.join("suite.toml"),
        "[synth]\ncount = 8\nseed = 1\npairs = true\nduration = 2.0\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("spec.toml"),
        "[campaign]\nscenario = \"viaduct.toml\"\nruns_per_part = 16\n",
    )
    .unwrap();
    Campaign::load(&dir.join("spec.toml")).unwrap()
}

fn pool() -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap()
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn bare_library_64_runs(bencher: divan::Bencher) {
    let dir = tempfile::tempdir().unwrap();
    let c = campaign(dir.path());
    let st = &c.study;
    let settings = summary_settings(&st.setup.settings);
    let pool = pool();
    bencher.bench(|| {
        pool.install(|| {
            (0..c.runs())
                .into_par_iter()
                .map(|i| {
                    let s = c.run_spec(i);
                    run_one(
                        &st.setup.problem,
                        &settings,
                        &st.set,
                        &c.plan,
                        &st.limits,
                        (s.entry, s.stripe),
                    )
                    .warnings
                })
                .sum::<usize>()
        })
    });
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn stored_campaign_64_runs(bencher: divan::Bencher) {
    let dir = tempfile::tempdir().unwrap();
    let c = campaign(dir.path());
    let pool = pool();
    let parts: Vec<usize> = (0..c.parts()).collect();
    let mut k = 0;
    bencher.bench_local(|| {
        k += 1;
        let out: PathBuf = dir.path().join(format!("store{k}"));
        let store = Store::open(&out, &c).unwrap();
        pool.install(|| exec::run_parts(&c, &store, &parts, &|| {}).unwrap())
    });
}
