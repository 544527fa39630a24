//! The verdict of a run (`pounding::sim::output::verdict`): each line is read from the solution
//! — the impacts per site and the hardest, the governing seat, unseating, the status — and the
//! alarming ones are flagged.

use pounding::sim::Problem;
use pounding::sim::output::{Layout, verdict};
use pounding::sim::scenario::Scenario;

const RIGID_1D: &str = include_str!("../../../../examples/viaduct-rigid-1d.toml");

fn run(text: &str) -> (Layout, pounding::sim::bridge::BridgeSolution) {
    let setup = Scenario::from_toml(text, "v.toml")
        .unwrap()
        .build_setup()
        .unwrap();
    (setup.layout(), setup.run().unwrap())
}

#[test]
fn the_verdict_names_the_sites_the_governing_end_and_the_unseating() {
    // tiny seats: ends leave them; 6 s of El Centro
    let text = RIGID_1D
        .replace("seat_length = 0.4", "seat_length = 0.03")
        .replace("history_every = 100", "history_every = 100\nduration = 6.0");
    let (layout, sol) = run(&text);
    let s = &sol.summary;
    let v = verdict(layout, &sol);
    let line = |t: &str| v.iter().find(|l| l.topic == t).unwrap();
    let p = line("pounding");
    assert!(s.impacts > 0 && p.alert);
    assert!(
        p.text.contains(&format!("{} impacts", s.impacts)),
        "{}",
        p.text
    );
    for (k, j) in s.joints.iter().enumerate() {
        let site = format!("joint {} ({})", k + 1, j.impacts);
        assert_eq!(p.text.contains(&site), j.impacts > 0, "{site}: {}", p.text);
    }
    let g = &s.seats[s.governing_seat];
    let seats = line("seats");
    assert!(
        seats.text.contains(&format!("{} on {}", g.end, g.support)),
        "{}",
        seats.text
    );
    assert!(seats.alert && g.ratio >= 1.0);
    let u = line("unseating");
    assert!(s.unseated && u.alert);
    assert!(
        u.text
            .starts_with(&format!("UNSEATED: {}", s.unseated_end.as_deref().unwrap()))
    );
    let n = s.seats.iter().filter(|e| e.unseated).count();
    assert!(u.text.contains(&format!("({n} end")), "{}", u.text);
    assert!(!line("status").alert);
}

#[test]
fn a_quiet_run_says_so() {
    let text = RIGID_1D.replace("history_every = 100", "history_every = 100\nduration = 1.0");
    let text = text.replace("scale_y = -1.0", "scale_y = -0.001");
    let (layout, sol) = run(&text);
    assert_eq!(sol.summary.impacts, 0);
    let v = verdict(layout, &sol);
    let p = v.iter().find(|l| l.topic == "pounding").unwrap();
    assert!(!p.alert && p.text.starts_with("No impact"));
    let u = v.iter().find(|l| l.topic == "unseating").unwrap();
    assert_eq!(u.text, "No end left its seat.");
    assert!(v.iter().all(|l| !l.alert), "{v:?}");
}
