//! The N-segment simulator against the event-exact chain reference (issue 11, rigid law):
//! `examples/viaduct-rigid-1d.toml` as shipped, and the same file with `builtin:ELC270` in
//! place of `builtin:ELC180` and nothing else changed. At dt = 1e-4 impact counts agree within
//! ±2 per joint and abutment, peak openings and segment displacements within 2 %.

use crate::event_chain::{Chain, ChainSummary};
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::Scenario;

const EXAMPLE: &str = include_str!("../../../../examples/viaduct-rigid-1d.toml");

fn run_example(text: &str) -> BridgeSolution {
    let sc = Scenario::from_toml(text, "viaduct-rigid-1d.toml").unwrap();
    assert!(sc.is_bridge());
    sc.build_bridge().unwrap().run().unwrap()
}

fn reference(record: pounding::ground_motion::Record) -> ChainSummary {
    let (chain, _): (Chain, _) = crate::event_chain::viaduct_rigid_1d();
    let t_end = record.end_time();
    chain
        .solve(Some(&record), 1.0, &[0.0; 3], &[0.0; 3], t_end)
        .summary()
}

fn compare(sol: &BridgeSolution, r: &ChainSummary) {
    let s = &sol.summary;
    let ab = |i: usize| s.abutments[i].as_ref().unwrap().impacts;
    let sim_counts = [ab(0), s.joints[0].impacts, s.joints[1].impacts, ab(1)];
    for (k, (a, b)) in sim_counts.iter().zip(&r.impacts).enumerate() {
        assert!(
            a.abs_diff(*b) <= 2,
            "impacts at contact {k}: {sim_counts:?} vs {:?}",
            r.impacts
        );
    }
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    for k in 0..2 {
        let (a, b) = (s.joints[k].peak_opening, r.peak_opening[k]);
        assert!(rel(a, b) < 0.02, "opening of joint {}: {a} vs {b}", k + 1);
        // rigid: the joint closes to its gap (plus the scheme's overlap, O(h v))
        assert!((s.joints[k].peak_closing - r.peak_closing[k]).abs() < 1e-4);
    }
    for i in 0..3 {
        let (a, b) = (s.segments[i].peak_displacement, r.peak_displacement[i]);
        assert!(
            rel(a, b) < 0.02,
            "peak displacement of segment {}: {a} vs {b}",
            i + 1
        );
        assert!(
            s.segments[i].peak_rotation < 1e-9,
            "a straight chain does not rotate"
        );
    }
    assert!(s.energy_balance_error < 1e-9, "{}", s.energy_balance_error);
}

#[test]
fn viaduct_rigid_1d_matches_the_event_exact_reference() {
    let gm = pounding::ground_motion::el_centro_1940();
    let sol = run_example(EXAMPLE);
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    compare(&sol, &reference(gm.along_y.clone().unwrap()));
    // the other component, by changing the record name only
    assert!(EXAMPLE.contains("record_y = \"builtin:ELC180\""));
    let other = EXAMPLE.replace("builtin:ELC180", "builtin:ELC270");
    let sol = run_example(&other);
    compare(&sol, &reference(gm.along_x.clone().unwrap()));
}
