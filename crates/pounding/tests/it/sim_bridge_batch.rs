//! Bridge batches (`pounding simulate bridge.toml --records …`): every row equals the single run
//! `--record R --scale S` built independently from the scenario, whatever the thread count;
//! shards partition the rows; `batch.csv` carries the single run's numbers in bridge order.

use pounding::ground_motion::{AccelUnits, Record};
use pounding::output::float_token;
use pounding::sim::SimStatus;
use pounding::sim::batch::{BatchRecord, BatchRow, BatchShard, run_batch};
use pounding::sim::output::{Layout, batch_csv, bridge_batch_header};
use pounding::sim::scenario::Scenario;
use std::path::PathBuf;

/// Straight, curved, straight (rigid law), a start abutment only, a restrainer across joint 1,
/// an oblique incidence so that the segments also rotate.
pub(crate) const BRIDGE: &str = r#"
[bridge]
damping = "dashpots"
damping_ratio = 0.05
gap = 0.01
mu = 0.2
eps_n = 0.6
[[segment]]
shape = "straight"
L = 30.0
mass = 1.0e6
period_s = 1.2
[[segment]]
shape = "curved"
R = 150.0
beta_deg = 12.0
mass = 1.2e6
period_s = 0.5
[[segment]]
shape = "straight"
L = 30.0
mass = 0.8e6
period_s = 1.5
[[joint]]
restrainer_k = 5.0e7
restrainer_slack = 0.005
[[joint]]
gap = 0.015
[abutment.start]
gap = 0.02
[ground_motion]
scale_y = -1.5
incidence_deg = 15.0
[time]
dt = 2e-3
"#;

/// Three short synthetic records (CSV, g) in a fresh scratch directory (returned with them: the
/// directory lives as long as its guard).
fn record_files(tag: &str) -> (crate::scratch::Scratch, Vec<PathBuf>) {
    let d = crate::scratch::scratch_dir("it-bbatch", tag);
    let paths = [(1.0, 0.3), (1.7, 0.25), (0.8, 0.4)]
        .iter()
        .enumerate()
        .map(|(i, (f, a))| {
            let mut s = String::from("t,a\n");
            for k in 0..=300 {
                let t = k as f64 * 0.01;
                let v = a * (2.0 * std::f64::consts::PI * f * t).sin() * (-0.3 * t).exp();
                s.push_str(&format!("{t:.2},{v:.6}\n"));
            }
            let p = d.join(format!("r{i}.csv"));
            std::fs::write(&p, s).unwrap();
            p
        })
        .collect();
    (d, paths)
}

fn batch_records(paths: &[PathBuf]) -> Vec<BatchRecord> {
    paths
        .iter()
        .map(|p| BatchRecord {
            name: p.display().to_string(),
            record: Record::from_path(p, AccelUnits::G).map_err(|e| e.to_string()),
            along_x: None,
            supports: Vec::new(),
        })
        .collect()
}

const SCALES: [f64; 3] = [0.5, 1.0, 2.0];

fn run(paths: &[PathBuf], threads: usize, shard: BatchShard) -> Vec<BatchRow> {
    let setup = Scenario::from_toml(BRIDGE, "bridge.toml")
        .unwrap()
        .for_batch()
        .build_bridge()
        .unwrap();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let recs = batch_records(paths);
    pool.install(|| {
        run_batch(
            &setup.problem,
            &setup.settings,
            &recs,
            &SCALES,
            shard,
            &|_| {},
        )
    })
    .unwrap()
}

#[test]
fn every_bridge_batch_row_equals_the_single_run_of_its_record_and_scale() {
    let (_dir, paths) = record_files("equal");
    let rows = run(&paths, 2, BatchShard::ALL);
    assert_eq!(rows.len(), 9);
    let csv = batch_csv(Layout::Bridge, 3, &rows);
    let head: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert_eq!(head.join(","), bridge_batch_header(3));
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let mut rotated = false;
    for (i, (r, line)) in rows.iter().zip(csv.lines().skip(1)).enumerate() {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells.len(), head.len());
        assert_eq!((r.index, r.record_index, r.scale_index), (i, i / 3, i % 3));
        // the single run, built independently through the scenario's --record / --scale path
        let single = Scenario::from_toml(BRIDGE, "bridge.toml")
            .unwrap()
            .with_record(&paths[i / 3], None)
            .with_scale(SCALES[i % 3])
            .build_bridge()
            .unwrap();
        let sol = single.run().unwrap();
        let o = r.outcome.as_ref().unwrap();
        assert_eq!(o.status, SimStatus::Completed);
        assert_eq!(o.summary, sol.summary, "row {i}");
        assert_eq!(o.impacting_contacts, sol.impacts.len());
        assert_eq!((o.steps, o.dt), (sol.steps, sol.dt));
        assert_eq!(
            (o.lcp_solves, o.lcp_failures),
            (sol.lcp_solves, sol.lcp_failures)
        );
        let g = &single.problem.ground;
        assert_eq!(r.pga, g.along_y.as_ref().unwrap().pga() * g.scale_y.abs());
        assert!(g.along_x.is_none());
        // the CSV cells are the single run's numbers, in bridge order
        let s = &sol.summary;
        assert_eq!(cells[col("impacts")], s.impacts.to_string());
        for k in 0..2 {
            let j = &s.joints[k];
            let c = |n: &str| cells[col(&format!("joint{}_{n}", k + 1))];
            assert_eq!(c("impacts"), j.impacts.to_string());
            assert_eq!(c("peak_closing_m"), float_token(j.peak_closing));
            assert_eq!(c("peak_opening_m"), float_token(j.peak_opening));
            assert_eq!(c("peak_impulse_ns"), float_token(j.peak_impulse));
            assert_eq!(c("peak_contact_force_n"), "", "rigid law: no force");
            assert_eq!(c("unseated"), j.unseated.to_string());
            assert_eq!(c("peak_slip_m"), float_token(j.peak_slip));
        }
        let rp = s.joints[0].restrainer_peak_force.unwrap();
        assert_eq!(
            cells[col("joint1_restrainer_peak_force_n")],
            float_token(rp)
        );
        assert_eq!(cells[col("joint2_restrainer_peak_force_n")], "");
        let a = s.abutments[0].as_ref().unwrap();
        assert_eq!(cells[col("abutment_start_impacts")], a.impacts.to_string());
        assert!(s.abutments[1].is_none());
        for n in [
            "impacts",
            "peak_closing_m",
            "peak_contact_force_n",
            "peak_impulse_ns",
        ] {
            assert_eq!(
                cells[col(&format!("abutment_end_{n}"))],
                "",
                "absent abutment"
            );
        }
        for (k, g) in s.segments.iter().enumerate() {
            let c = |n: &str| cells[col(&format!("segment{}_{n}", k + 1))];
            assert_eq!(c("peak_displacement_m"), float_token(g.peak_displacement));
            assert_eq!(
                c("peak_rotation_deg"),
                float_token(g.peak_rotation.to_degrees())
            );
            rotated |= g.peak_rotation > 0.0;
        }
        let jmax = s
            .joints
            .iter()
            .map(|j| j.peak_opening)
            .fold(f64::MIN, f64::max);
        assert_eq!(cells[col("peak_joint_opening_m")], float_token(jmax));
        assert_eq!(cells[col("error")], "");
    }
    assert!(rows.iter().any(|r| {
        let s = &r.outcome.as_ref().unwrap().summary;
        s.joints[0].impacts > 0 && s.abutments[0].as_ref().unwrap().impacts > 0
    }));
    assert!(rotated, "the curved segment rotates");
}

#[test]
fn bridge_batch_rows_do_not_depend_on_threads_and_shards_partition_them() {
    let (_dir, paths) = record_files("threads");
    let all = run(&paths, 1, BatchShard::ALL);
    assert_eq!(run(&paths, 2, BatchShard::ALL), all);
    let mut merged = Vec::new();
    for k in 1..=4 {
        let part = run(&paths, 2, BatchShard::new(k, 4).unwrap());
        assert!(part.iter().all(|r| r.index % 4 == k - 1));
        merged.extend(part);
    }
    merged.sort_by_key(|r| r.index);
    assert_eq!(merged, all);
}

#[test]
fn an_unreadable_record_fails_only_its_rows_and_bad_lists_are_errors() {
    let (_dir, mut paths) = record_files("bad");
    paths.insert(1, paths[0].with_file_name("missing.csv"));
    let rows = run(&paths, 2, BatchShard::ALL);
    let csv = batch_csv(Layout::Bridge, 3, &rows);
    for (i, (r, line)) in rows.iter().zip(csv.lines().skip(1)).enumerate() {
        let cells: Vec<&str> = line.split(',').collect();
        if i / 3 == 1 {
            assert!(r.outcome.as_ref().unwrap_err().contains("missing.csv"));
            assert_eq!(cells[5], "error");
            assert!(cells.last().unwrap().contains("missing.csv"), "{line}");
            assert!(r.pga.is_nan());
        } else {
            assert!(r.outcome.is_ok());
        }
    }
    let setup = Scenario::from_toml(BRIDGE, "bridge.toml")
        .unwrap()
        .for_batch()
        .build_bridge()
        .unwrap();
    let recs = batch_records(&paths[..1]);
    let go = |recs: &[BatchRecord], scales: &[f64]| {
        run_batch(
            &setup.problem,
            &setup.settings,
            recs,
            scales,
            BatchShard::ALL,
            &|_| {},
        )
        .unwrap_err()
        .to_string()
    };
    assert!(go(&recs, &[1.0, f64::NAN]).contains("--scales[2]"));
    assert!(go(&recs, &[]).contains("--scales"));
    assert!(go(&[], &[1.0]).contains("--records"));
}
