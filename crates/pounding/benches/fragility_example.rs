//! The shipped fragility example (issue 13 speed target: its 160 runs on 2 threads < 10 s).
//!
//! `example_160_runs_2_threads` — `examples/fragility/viaduct.toml` on its `[synth]` suite
//! (20 pairs × 8 stripes of Sa(T1)) through the library path of `pounding fragility`: the
//! scenario, `[fragility]` settings, record set, limit states and the model's period are read
//! once outside the timing; the timing covers the IM plan (RotD50 Sa(T1) of the 20 pairs),
//! the 160 bridge runs on a 2-thread pool and the fits with their bootstrap (no files written).

use pounding::assessment::im::{ImSpec, fundamental_period};
use pounding::assessment::limit::bind;
use pounding::assessment::run::{Plan, fit_limit_state, run_all};
use pounding::assessment::{FragilitySettings, PeriodChoice};
use pounding::fragility::BootstrapSettings;
use pounding::ground_motion::set::RecordSet;
use pounding::sim::scenario::Scenario;
use std::path::Path;

fn main() {
    divan::main();
}

#[divan::bench(sample_count = 3, sample_size = 1)]
fn example_160_runs_2_threads(bencher: divan::Bencher) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fragility");
    let scenario = Scenario::load(&dir.join("viaduct.toml"))
        .expect("the example reads")
        .for_batch();
    let setup = scenario.build_bridge().expect("a bridge");
    let settings = FragilitySettings::from_scenario(scenario.text(), scenario.origin()).unwrap();
    let set = RecordSet::load(&dir.join(settings.records.as_ref().unwrap())).unwrap();
    let limits = bind(&settings.limit_states, &setup.problem.model, "bench").unwrap();
    let period = match settings.period {
        PeriodChoice::Given(t) => t,
        PeriodChoice::Model => fundamental_period(&setup.problem.model).unwrap().period,
    };
    let spec = ImSpec {
        kind: settings.im,
        period,
        damping: settings.damping,
        pair: settings.pair_im,
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let b = BootstrapSettings {
        samples: settings.bootstrap,
        seed: settings.seed,
        level: settings.level,
    };
    let band: Vec<f64> = (0..60).map(|k| 0.05 * 1.06f64.powi(k)).collect();
    bencher.bench(|| {
        pool.install(|| {
            let plan = Plan::new(&set, &spec, &settings.stripes, &setup.problem.ground).unwrap();
            let rows = run_all(
                &setup.problem,
                &setup.settings,
                &set,
                &plan,
                &limits,
                &|| {},
            );
            assert_eq!(rows.len(), 160);
            limits
                .iter()
                .enumerate()
                .map(|(l, lim)| {
                    fit_limit_state(&lim.state.name, &plan, &rows, l, &b, &band).unwrap()
                })
                .collect::<Vec<_>>()
        })
    });
}
