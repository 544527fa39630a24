//! The progress observer of a run: called before the first step and every `PROGRESS_EVERY`
//! steps with the total, and the run's results do not depend on it (a front end's time
//! estimate must not change a number).

use pounding::sim::scenario::Scenario;
use pounding::sim::{PROGRESS_EVERY, Progress};
use std::sync::{Arc, Mutex};

#[test]
fn the_progress_observer_sees_the_steps_and_changes_nothing() {
    let text = "[bridge]\ngap = 0.01\n[[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 1.0\n\
                [[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 0.5\n[time]\ndt = 1e-3\n\
                duration = 1.0\n";
    let setup = Scenario::from_toml(text, "p.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let plain = setup.run().unwrap();
    let seen: Arc<Mutex<Vec<(usize, usize)>>> = Arc::default();
    let mut observed = setup.clone();
    let s = seen.clone();
    observed.settings.progress = Progress::new(move |d, t| s.lock().unwrap().push((d, t)));
    let sol = observed.run().unwrap();
    let calls = seen.lock().unwrap().clone();
    let n = sol.steps;
    assert_eq!(n, 1000);
    let want: Vec<(usize, usize)> = (0..=n).step_by(PROGRESS_EVERY).map(|k| (k, n)).collect();
    assert_eq!(calls, want);
    assert_eq!(sol.q, plain.q);
    assert_eq!(sol.u, plain.u);
    assert_eq!(format!("{:?}", sol.summary), format!("{:?}", plain.summary));
}
