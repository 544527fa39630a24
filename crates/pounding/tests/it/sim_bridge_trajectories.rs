//! `trajectories.json` of a bridge run (`pounding::sim::output::trajectories_json`):
//! valid JSON; at most `TRAJECTORY_MAX_FRAMES` frames, every `stride`-th kept row and the last with its time
//! and `x_i, y_i, θ_i` (degrees) to the last bit or two (serde_json's reading of a
//! shortest round-trip number is not always correctly rounded); the plan of `bridge_plan`; every impact.

use pounding::sim::output::{
    TRAJECTORY_MAX_FRAMES, bridge_plan, trajectories_json, trajectory_stride,
};
use pounding::sim::scenario::Scenario;
use serde_json::Value;

const RIGID_1D: &str = include_str!("../../../../examples/viaduct-rigid-1d.toml");

#[test]
fn trajectories_hold_decimated_history_rows_exactly() {
    assert_eq!(trajectory_stride(1), 1);
    assert_eq!(trajectory_stride(TRAJECTORY_MAX_FRAMES), 1);
    assert_eq!(trajectory_stride(TRAJECTORY_MAX_FRAMES + 1), 2);
    assert_eq!(trajectory_stride(2 * TRAJECTORY_MAX_FRAMES - 1), 2);
    assert_eq!(trajectory_stride(4001), 3);
    // Every step kept over 2.2 s: 22 001 rows (stride 12), past the first impact (2.04 s).
    let text = RIGID_1D.replace("history_every = 100", "history_every = 1\nduration = 2.2");
    let setup = Scenario::from_toml(&text, "t.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let sol = setup.run().unwrap();
    let j: Value = serde_json::from_str(&trajectories_json(
        &setup.problem.model,
        &setup.problem.ground,
        &sol,
    ))
    .unwrap();
    let rows = sol.t.len();
    let stride = j["stride"].as_u64().unwrap() as usize;
    assert_eq!(stride, trajectory_stride(rows));
    let frames = j["frames"].as_array().unwrap();
    let on_grid = (rows - 1).is_multiple_of(stride);
    assert_eq!(frames.len(), rows.div_ceil(stride) + usize::from(!on_grid));
    assert!(frames.len() <= TRAJECTORY_MAX_FRAMES && stride > 1);
    let n = sol.n_segments;
    for (f, fr) in frames.iter().enumerate() {
        let r = (f * stride).min(rows - 1);
        assert_eq!(fr["t"].as_f64().unwrap(), sol.t[r]);
        let q = fr["q"].as_array().unwrap();
        assert_eq!(q.len(), 3 * n);
        for (k, v) in q.iter().enumerate() {
            let want = sol.q[3 * n * r + k]
                * if k % 3 == 2 {
                    180.0 / std::f64::consts::PI
                } else {
                    1.0
                };
            let got = v.as_f64().unwrap();
            assert!(
                (got - want).abs() <= 1e-15 * want.abs(),
                "frame {f} entry {k}: {got} vs {want}"
            );
        }
    }
    let plan = bridge_plan(&setup.problem.model, 16);
    for (i, o) in plan.outlines.iter().enumerate() {
        let got = j["outlines"][i].as_array().unwrap();
        assert_eq!(got.len(), o.len());
        assert_eq!(got[0][0].as_f64().unwrap(), o[0].x);
    }
    assert_eq!(
        frames.last().unwrap()["t"].as_f64().unwrap(),
        sol.t[rows - 1]
    );
    // one entry per impact and site, the contacts' impulses summed: their total is the run's
    let imp = j["impacts"].as_array().unwrap();
    assert!(!sol.impacts.is_empty());
    let contacts: u64 = imp.iter().map(|i| i["contacts"].as_u64().unwrap()).sum();
    assert_eq!(contacts as usize, sol.impacts.len());
    let total: f64 = imp.iter().map(|i| i["impulse_n"].as_f64().unwrap()).sum();
    let want: f64 = sol.impacts.iter().map(|i| i.impulse_n).sum();
    assert!((total - want).abs() <= 1e-12 * want, "{total} vs {want}");
    assert_eq!(imp[0]["t"].as_f64().unwrap(), sol.impacts[0].time);
    // the largest impulse of one impact at joint 1 is the summary's
    let peak = imp
        .iter()
        .filter(|i| i["site_kind"] == "joint" && i["site"] == 0)
        .map(|i| i["impulse_n"].as_f64().unwrap())
        .fold(0.0, f64::max);
    assert_eq!(peak, sol.summary.joints[0].peak_impulse);
    // the ground peak over every step: at least the record's PGA at the kept rows
    let ag_y = j["ag_peak"][1].as_f64().unwrap();
    let kept = frames
        .iter()
        .map(|f| f["ag"][1].as_f64().unwrap().abs())
        .fold(0.0, f64::max);
    assert!(ag_y >= kept && ag_y > 0.0);
    assert_eq!(
        j["events"]["first_impact"].as_f64().unwrap(),
        sol.impacts[0].time
    );
    let g = &sol.summary.seats[sol.summary.governing_seat];
    assert_eq!(
        j["events"]["peak_seat_ratio"].as_f64().unwrap(),
        g.peak_time
    );
}
