//! The position projection of Moreau–Jean (`[time] projection = true`,
//! [`pounding::sim::projection`]): every rigid-law gap `≥ −1e-10` m at every step's end on the
//! default two-deck bridge, the rigid viaduct, the curved five-segment viaduct (rotations,
//! friction, restrainers) and a yielding-bearing viaduct; without it the same runs overlap (so
//! the check can fail); the energy balance closes with the projection term; its work is reported
//! and small; the projected answer tends to the unprojected one as `dt → 0`; a mixed bridge
//! projects only its rigid sites.

use pounding::sim::SimStatus;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::Scenario;

/// The acceptance bound on an overlap with the projection \[m\].
const OVERLAP: f64 = 1e-10;

/// A scenario: `examples/<name>` (or the built-in default for `None`) with `edit` applied to
/// its text, its law replaced by `law`, cut to `duration` s at `dt` (`None`: the file's).
fn scenario(name: Option<&str>, edit: &dyn Fn(String) -> String) -> Scenario {
    match name {
        None => Scenario::default(),
        Some(n) => {
            let root = env!("CARGO_MANIFEST_DIR");
            let text = std::fs::read_to_string(format!("{root}/../../examples/{n}")).unwrap();
            Scenario::from_toml(&edit(text), n).unwrap_or_else(|e| panic!("{e}"))
        }
    }
}

/// Runs `sc` with the projection on or off, over `duration` s at `dt` (`None`: the file's).
fn run(sc: &Scenario, projection: bool, duration: f64, dt: Option<f64>) -> BridgeSolution {
    let mut sc = sc.clone().with_duration(duration);
    if let Some(dt) = dt {
        sc = sc.with_dt(dt);
    }
    if projection {
        sc = sc.with_projection();
    }
    let setup = sc.build_setup().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(setup.settings().projection, projection);
    setup.run().unwrap()
}

fn same(text: String) -> String {
    text
}

/// What a projected run must satisfy, and the unprojected run's overlap it must beat.
fn check_pair(what: &str, off: &BridgeSolution, on: &BridgeSolution, energy_bound: f64) {
    let (a, b) = (&off.summary, &on.summary);
    assert_eq!(off.status, SimStatus::Completed, "{what}");
    assert_eq!(on.status, SimStatus::Completed, "{what}");
    assert!(a.projection.is_none(), "{what}");
    assert!(a.final_energy.projection == 0.0, "{what}");
    // the check can fail: without the projection the scheme overlaps
    assert!(a.max_overlap > OVERLAP, "{what}: {:e}", a.max_overlap);
    let p = b.projection.expect("projection stats");
    assert!(b.max_overlap <= OVERLAP, "{what}: {:e}", b.max_overlap);
    assert!(p.corrected_steps > 0 && p.failures == 0, "{what}: {p:?}");
    assert!(p.max_overlap_before > OVERLAP, "{what}: {p:?}");
    // the balance closes with the projection's work in it
    assert!(
        b.energy_balance_error < 1e-12,
        "{what}: balance {:e}",
        b.energy_balance_error
    );
    let w = b.final_energy.projection;
    assert!(w != 0.0 && w.is_finite(), "{what}: {w}");
    let ratio = w.abs() / b.max_input_energy;
    assert!(ratio < energy_bound, "{what}: |W_proj| / input = {ratio:e}");
    // every kept state: the joints' end gaps above −1e-10 (the history is a sample of them)
    let min_gap = on
        .end_gaps
        .iter()
        .filter(|g| !g.is_nan())
        .fold(f64::INFINITY, |m, g| m.min(*g));
    assert!(min_gap >= -OVERLAP, "{what}: {min_gap:e}");
}

/// The two-deck default (curved decks, rotation, friction) under El Centro, 20 s at its
/// `dt = 1e-3`: the velocity-level step overlaps by 6.7e-5 m, the projection leaves < 1e-10 m.
#[test]
fn projection_closes_the_two_deck_default() {
    let sc = scenario(None, &same);
    let (off, on) = (run(&sc, false, 20.0, None), run(&sc, true, 20.0, None));
    check_pair("default", &off, &on, 1e-4);
    // the joint's peak closing is the gap itself, to the tolerance, not the gap plus the overlap
    let gap = 0.05;
    let closing = on.summary.joints[0].peak_closing;
    assert!((closing - gap).abs() <= OVERLAP, "{closing}");
    assert!(off.summary.joints[0].peak_closing - gap > 1e-5);
}

/// The rigid three-segment viaduct (joints and abutments, `dt = 1e-4`) over the whole record,
/// and the curved five-segment viaduct (rotations, friction 0.3, restrainers) at its `dt = 1e-3`.
#[test]
fn projection_closes_the_rigid_viaducts() {
    let sc = scenario(Some("viaduct-rigid-1d.toml"), &same);
    let (off, on) = (run(&sc, false, 53.71, None), run(&sc, true, 53.71, None));
    check_pair("viaduct-rigid-1d", &off, &on, 1e-5);
    let sc = scenario(Some("viaduct-curved-5.toml"), &same);
    let (off, on) = (run(&sc, false, 30.0, None), run(&sc, true, 30.0, None));
    check_pair("viaduct-curved-5", &off, &on, 1e-4);
}

/// Yielding bearings (the bilinear viaduct with rigid contacts): their return mappings take the
/// correction as a displacement increment and the balance still closes.
#[test]
fn projection_books_the_yielding_bearings_work() {
    let sc = scenario(Some("viaduct-1d.toml"), &same).with_law_replacing("rigid");
    let (off, on) = (run(&sc, false, 30.0, None), run(&sc, true, 30.0, None));
    check_pair("viaduct-1d rigid", &off, &on, 1e-5);
    assert!(
        on.summary
            .segments
            .iter()
            .any(|s| s.hysteretic_energy > 0.0)
    );
}

/// As `dt → 0` the projected run tends to the unprojected one: at `dt = 1e-4` the peaks of the
/// default bridge agree to 2e-3 (at 1e-3 the closing differs by the overlap, 1.3e-3 of it), and
/// the projection's work falls below 1e-6 of the input.
#[test]
fn projected_and_plain_runs_converge_as_dt_shrinks() {
    let sc = scenario(None, &same);
    let peaks = |s: &BridgeSolution| {
        let (j, m) = (&s.summary.joints[0], &s.summary);
        let mut v = vec![j.peak_closing, j.peak_opening, j.peak_slip];
        v.push(m.peak_seat_displacement);
        v.extend(m.segments.iter().map(|g| g.peak_rotation));
        v.extend(m.segments.iter().map(|g| g.peak_displacement));
        v
    };
    let diff = |dt: f64| {
        let (a, b) = (
            run(&sc, false, 20.0, Some(dt)),
            run(&sc, true, 20.0, Some(dt)),
        );
        let w = b.summary.final_energy.projection.abs() / b.summary.max_input_energy;
        let d = peaks(&a)
            .iter()
            .zip(peaks(&b))
            .map(|(x, y)| (x - y).abs() / x.abs())
            .fold(0.0, f64::max);
        (d, w, a.summary.max_overlap)
    };
    let (coarse, w_coarse, ov_coarse) = diff(1e-3);
    let (fine, w_fine, ov_fine) = diff(1e-4);
    assert!(fine < 2e-3, "peaks differ by {fine:e} at dt = 1e-4");
    assert!(coarse > fine, "{coarse:e} {fine:e}");
    assert!(
        w_fine < 1e-6 && w_fine < w_coarse,
        "{w_fine:e} {w_coarse:e}"
    );
    assert!(ov_fine < ov_coarse / 5.0, "{ov_fine:e} {ov_coarse:e}");
}

/// A mixed bridge (rigid joints, compliance abutments) projects its rigid joints only: the
/// abutments keep their law's penetration.
#[test]
fn a_mixed_bridge_projects_its_rigid_sites_only() {
    let law = "law = \"bilinear\"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3";
    let abut = format!("[abutment.start.contact]\n{law}\n[abutment.end.contact]\n{law}\n");
    let sc = scenario(Some("viaduct-rigid-1d.toml"), &|t| format!("{t}\n{abut}"));
    let (off, on) = (run(&sc, false, 20.0, None), run(&sc, true, 20.0, None));
    check_pair("mixed", &off, &on, 1e-5);
    let pen = on
        .summary
        .abutments
        .iter()
        .flatten()
        .map(|a| a.peak_closing - 0.04)
        .fold(0.0, f64::max);
    assert!(pen > 1e-5, "the compliance abutments' penetration {pen:e}");
}

/// Without the key the settings have no projection, and a run's summary no projection stats;
/// the key reads as a boolean.
#[test]
fn projection_key_reads_as_a_boolean() {
    let base = "[time]\ndt = 1e-3\nduration = 1.0\n";
    let sc = Scenario::from_toml(base, "a.toml").unwrap();
    assert!(!sc.build_setup().unwrap().settings().projection);
    let sc = Scenario::from_toml(&format!("{base}projection = true\n"), "b.toml").unwrap();
    assert!(sc.build_setup().unwrap().settings().projection);
    let err = Scenario::from_toml(&format!("{base}projection = \"yes\"\n"), "c.toml")
        .and_then(|s| s.build_setup().map(|_| ()))
        .expect_err("a string is refused")
        .to_string();
    assert!(
        err.contains("line 4") && err.contains("projection"),
        "{err}"
    );
}

/// A compliance-law run asked for the projection projects nothing (its penetration is the law's
/// deformation): the same histories, and its summary says no step was corrected.
#[test]
fn a_compliance_run_is_not_projected() {
    let sc = scenario(None, &same).with_law_replacing("hertz");
    let (off, on) = (run(&sc, false, 20.0, None), run(&sc, true, 20.0, None));
    assert!(off.q == on.q && off.energy == on.energy);
    let p = on.summary.projection.expect("reported");
    assert_eq!((p.corrected_steps, p.failures), (0, 0));
    assert_eq!(on.summary.max_overlap, 0.0);
    assert!(
        on.summary.peak_penetration > 1e-6,
        "{}",
        on.summary.peak_penetration
    );
}
