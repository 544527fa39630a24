//! Batch runs: every (record, scale) pair equals the single run, row for row, whatever the thread
//! count; shards partition the runs; an unreadable record fails only its own rows.

use pounding::ground_motion::{GroundMotion, Record};
use pounding::sim::batch::{BatchRecord, BatchShard, run_batch, run_problem};
use pounding::sim::{SimError, SimModel, SimProblem, SimSettings, simulate};

/// A short synthetic record: decaying sine of frequency `f` [Hz] and amplitude `a` [m/s²], 3 s.
fn record(name: &str, f: f64, a: f64) -> Record {
    let v: Vec<f64> = (0..=300)
        .map(|k| {
            let t = k as f64 * 0.01;
            a * (2.0 * std::f64::consts::PI * f * t).sin() * (-0.3 * t).exp()
        })
        .collect();
    Record::uniform(name, 0.01, v).unwrap()
}

fn records() -> Vec<BatchRecord> {
    [("r0", 1.0, 3.0), ("r1", 1.7, 2.5), ("r2", 0.8, 4.0)]
        .into_iter()
        .map(|(n, f, a)| BatchRecord {
            name: n.into(),
            record: Ok(record(n, f, a)),
            along_x: None,
            supports: Vec::new(),
        })
        .collect()
}

fn base() -> SimProblem {
    // the scenario's scale_y = 1.5 multiplies every batch scale, as `--scale` does
    let mut g = GroundMotion::none();
    g.scale_y = 1.5;
    g.incidence = 20f64.to_radians();
    SimProblem::at_rest(SimModel::default_bridge(), g)
}

fn settings() -> SimSettings {
    SimSettings {
        dt: 2e-3,
        ..SimSettings::default()
    }
}

const SCALES: [f64; 4] = [0.5, 1.0, 2.0, 4.0];

fn pool(n: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .unwrap()
}

#[test]
fn three_records_by_four_scales_equal_twelve_single_runs() {
    let recs = records();
    let base = base();
    let counter = std::sync::atomic::AtomicUsize::new(0);
    let rows = pool(2)
        .install(|| {
            run_batch(&base, &settings(), &recs, &SCALES, BatchShard::ALL, &|n| {
                counter.fetch_add(n, std::sync::atomic::Ordering::Relaxed);
            })
        })
        .unwrap();
    assert_eq!(rows.len(), 12);
    assert_eq!(counter.into_inner(), 12, "progress called once per run");
    let mut impacts_seen = 0;
    for (i, row) in rows.iter().enumerate() {
        let (a, b) = (i / 4, i % 4);
        assert_eq!(row.index, i);
        assert_eq!((row.record_index, row.scale_index), (a, b));
        assert_eq!(row.record, recs[a].name);
        assert_eq!(row.scale, SCALES[b]);
        // the single run, built independently of run_problem
        let rec = recs[a].record.as_ref().unwrap();
        let single = SimProblem {
            ground: GroundMotion {
                along_y: Some(rec.clone()),
                scale_y: 1.5 * SCALES[b],
                along_x: None,
                scale_x: SCALES[b],
                incidence: 20f64.to_radians(),
            },
            ..base.clone()
        };
        assert_eq!(run_problem(&base, rec, SCALES[b]), single);
        let sol = simulate(&single, &settings()).unwrap();
        let out = row.outcome.as_ref().unwrap();
        assert_eq!(out.summary, sol.summary, "row {i}");
        assert_eq!(out.status, sol.status);
        assert_eq!(out.steps, sol.steps);
        assert_eq!(out.lcp_solves, sol.lcp_solves);
        // PGA of the applied component, from the samples
        let pga = rec.values().iter().fold(0.0f64, |m, v| m.max(v.abs())) * 1.5 * SCALES[b];
        assert!((row.pga - pga).abs() <= 1e-12 * pga, "{} vs {pga}", row.pga);
        impacts_seen += out.summary.impacts;
    }
    // the batch is not trivially quiet: the decks pound in some runs
    assert!(impacts_seen > 0);
    // the response grows with the scale factor for each record (linear until pounding; the joint
    // opening is dominated by the free response)
    for a in 0..3 {
        let op: Vec<f64> = (0..4)
            .map(|b| {
                rows[4 * a + b]
                    .outcome
                    .as_ref()
                    .unwrap()
                    .summary
                    .peak_seat_displacement
            })
            .collect();
        assert!(op.windows(2).all(|w| w[1] > w[0]), "record {a}: {op:?}");
    }
}

#[test]
fn rows_do_not_depend_on_the_thread_count_and_shards_partition_them() {
    let recs = records();
    let base = base();
    let all1 = pool(1)
        .install(|| run_batch(&base, &settings(), &recs, &SCALES, BatchShard::ALL, &|_| {}))
        .unwrap();
    let all2 = pool(2)
        .install(|| run_batch(&base, &settings(), &recs, &SCALES, BatchShard::ALL, &|_| {}))
        .unwrap();
    assert_eq!(all1, all2);
    let mut merged = Vec::new();
    for k in 1..=5 {
        let sh = BatchShard::new(k, 5).unwrap();
        let part = pool(2)
            .install(|| run_batch(&base, &settings(), &recs, &SCALES, sh, &|_| {}))
            .unwrap();
        assert!(part.iter().all(|r| r.index % 5 == k - 1));
        merged.extend(part);
    }
    merged.sort_by_key(|r| r.index);
    assert_eq!(merged, all1);
}

#[test]
fn an_unreadable_record_fails_only_its_rows() {
    let mut recs = records();
    let good = pool(2)
        .install(|| {
            run_batch(
                &base(),
                &settings(),
                &recs,
                &SCALES,
                BatchShard::ALL,
                &|_| {},
            )
        })
        .unwrap();
    recs.insert(
        1,
        BatchRecord {
            name: "missing.AT2".into(),
            record: Err("cannot read ground-motion record missing.AT2: not found".into()),
            along_x: None,
            supports: Vec::new(),
        },
    );
    let rows = pool(2)
        .install(|| {
            run_batch(
                &base(),
                &settings(),
                &recs,
                &SCALES,
                BatchShard::ALL,
                &|_| {},
            )
        })
        .unwrap();
    assert_eq!(rows.len(), 16);
    for r in &rows {
        if r.record_index == 1 {
            let e = r.outcome.as_ref().unwrap_err();
            assert!(e.contains("missing.AT2"), "{e}");
            assert!(r.pga.is_nan());
        } else {
            let g = &good[(r.record_index - (r.record_index > 1) as usize) * 4 + r.scale_index];
            assert_eq!(r.outcome, g.outcome);
        }
    }
}

#[test]
fn bad_batch_input_is_an_error_naming_it() {
    let recs = records();
    let run = |scales: &[f64], recs: &[BatchRecord]| {
        run_batch(&base(), &settings(), recs, scales, BatchShard::ALL, &|_| {})
    };
    let e = run(&[1.0, f64::NAN], &recs).unwrap_err();
    assert!(e.to_string().contains("--scales[2]"), "{e}");
    assert!(
        run(&[], &recs)
            .unwrap_err()
            .to_string()
            .contains("--scales")
    );
    assert!(
        run(&[1.0], &[])
            .unwrap_err()
            .to_string()
            .contains("--records")
    );
    for s in ["0/3", "4/3", "1/0", "x", "1/2/3", "-1/2"] {
        let e = BatchShard::parse(s).unwrap_err();
        assert!(e.to_string().contains("--shard"), "{s}: {e}");
    }
    assert_eq!(
        BatchShard::parse(" 2/3").unwrap(),
        BatchShard::new(2, 3).unwrap()
    );
    // an invalid model fails the whole batch before any run
    let mut b = base();
    b.model.gap = -0.1;
    let e = run_batch(&b, &settings(), &recs, &[1.0], BatchShard::ALL, &|_| {}).unwrap_err();
    assert!(matches!(e, SimError::InvalidParameter { ref name, .. } if name == "gap"));
}

/// A record-set manifest of pairs: each row equals the single run of the ground motion built
/// here by hand (the entry's `x` along y with `s · scale_y`, its `y` along x with `s · scale_x`,
/// the incidence kept), its PGA is the larger of the scaled components', and a fragility run's
/// ground motion is the same function's.
#[test]
fn pair_entries_of_a_record_set_equal_single_runs_of_both_components() {
    use pounding::ground_motion::set::RecordSet;
    use pounding::sim::batch::entry_ground;
    let set = RecordSet::from_toml(
        "[[record]]\nid = \"p\"\nx = \"builtin:ELC180\"\ny = \"builtin:ELC270\"\n\
         [[record]]\nid = \"one\"\nx = \"builtin:ELC270\"\n",
        "set.toml",
        std::path::Path::new("."),
    )
    .unwrap();
    let recs = BatchRecord::of_set(&set);
    assert_eq!(recs.len(), 2);
    assert_eq!((recs[0].name.as_str(), recs[1].name.as_str()), ("p", "one"));
    let mut base = base();
    base.ground.scale_x = -0.7;
    let settings = SimSettings {
        duration: Some(3.0),
        ..settings()
    };
    let scales = [0.5, 2.0];
    let rows = pool(2)
        .install(|| run_batch(&base, &settings, &recs, &scales, BatchShard::ALL, &|_| {}))
        .unwrap();
    assert_eq!(rows.len(), 4);
    for (i, row) in rows.iter().enumerate() {
        let (e, s) = (&set.records[i / 2], scales[i % 2]);
        let ground = GroundMotion {
            along_y: Some(e.x.clone()),
            scale_y: 1.5 * s,
            along_x: e.y.clone(),
            scale_x: -0.7 * s,
            incidence: 20f64.to_radians(),
        };
        assert_eq!(entry_ground(&base.ground, &e.x, e.y.as_ref(), s), ground);
        let single = SimProblem {
            ground,
            ..base.clone()
        };
        let sol = simulate(&single, &settings).unwrap();
        let out = row.outcome.as_ref().unwrap();
        assert_eq!(out.summary, sol.summary, "row {i}");
        // |s · scale| · max|a| of each component (the factor formed first, as documented)
        let pga_y = e.x.pga() * (1.5 * s).abs();
        let pga =
            e.y.as_ref()
                .map_or(pga_y, |y| pga_y.max(y.pga() * (-0.7 * s).abs()));
        assert_eq!(row.pga, pga, "row {i}");
    }
    // the second component matters: the pair's run differs from its x record alone
    let alone = simulate(
        &SimProblem {
            ground: entry_ground(&base.ground, &set.records[0].x, None, 2.0),
            ..base.clone()
        },
        &settings,
    )
    .unwrap();
    assert_ne!(rows[1].outcome.as_ref().unwrap().summary, alone.summary);
}
