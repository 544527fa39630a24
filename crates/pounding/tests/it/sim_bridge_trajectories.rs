//! `trajectories.json` of a bridge run (`pounding::sim::output::trajectories_json`):
//! valid JSON; at most `TRAJECTORY_MAX_FRAMES` frames, every `stride`-th kept row with its time
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
    assert_eq!(frames.len(), rows.div_ceil(stride));
    assert!(frames.len() <= TRAJECTORY_MAX_FRAMES && stride > 1);
    let n = sol.n_segments;
    for (f, fr) in frames.iter().enumerate() {
        let r = f * stride;
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
    let imp = j["impacts"].as_array().unwrap();
    assert!(!sol.impacts.is_empty());
    assert_eq!(imp.len(), sol.impacts.len());
    assert_eq!(imp[0]["t"].as_f64().unwrap(), sol.impacts[0].time);
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
