//! The shipped design example (target: < 10 minutes on 2 cores).
//!
//! `example_800_runs_2_threads` — `examples/design/design.toml`: the five-segment viaduct as
//! built and 4 variants, each on 20 synthetic pairs × 8 stripes of Sa(T1) (800 bridge runs of
//! 15 s), through the library path of `pounding design`: the design, its studies and record
//! sets are read once outside the timing; the timing covers the IM plan, the 800 runs on a
//! 2-thread pool, the fits with their bootstrap (500 replicates per limit state and variant)
//! and the paired comparison (no files written).

use pounding::assessment::design::Design;
use pounding::assessment::design_write::compare;
use std::path::Path;

fn main() {
    divan::main();
}

#[divan::bench(sample_count = 1, sample_size = 1)]
fn example_800_runs_2_threads(bencher: divan::Bencher) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/design");
    let design = Design::read(&dir.join("design.toml"), None, None).expect("the example reads");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    bencher.bench(|| {
        pool.install(|| {
            let plan = design.plan().unwrap();
            let rows = design.run(&plan, &|| {});
            let fits = design.fit(&plan, &rows).unwrap();
            divan::black_box(compare(&design, &fits));
        })
    });
}
