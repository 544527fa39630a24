//! Outputs a designer needs (issue 12): the force pulse of each compliance-law impact against
//! closed forms, and the rigid law's peak-force estimate against a Hertz compliance run.

use pounding::contact_law::estimate::{HERTZ_CONTACT_TIME_FACTOR, rigid_peak_force};
use pounding::contact_law::registry::default_k_h;
use pounding::contact_law::{ContactLaw, Hertz, LinearSpring};
use pounding::ground_motion::GroundMotion;
use pounding::shape::{DeckShape, StraightDeck};
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::{
    ComplianceContact, DampingModel, JointContact, SimModel, SimProblem, SimSettings, SimStatus,
    simulate,
};

/// Two straight decks of 1e6 kg each (m_eff = 5e5 kg) on very soft bearings (T = 100 s, so that
/// the bearings change the contact pulse by ~1e-6), undamped, gap 0, meeting head-on at the
/// reference pose with a closing speed of 1 m/s, μ = 0, restitution `eps`, over `t_end` s.
fn head_on(contact: JointContact, eps: f64, dt: f64, t_end: f64) -> BridgeSolution {
    let m = 1.0e6;
    let deck = DeckShape::Straight(StraightDeck {
        length: 30.0,
        width: 10.0,
        thickness: 0.5,
        density: m / 150.0,
    });
    let kb = m * (2.0 * std::f64::consts::PI / 100.0).powi(2) / 4.0;
    let mut model = SimModel::with_shapes([deck, deck], 0.0, kb, kb, 0.0, 0.0, eps, 0.4);
    model.damping_model = DampingModel::TranslationalDashpots;
    model.contact = contact;
    let mut p = SimProblem::at_rest(model, GroundMotion::none());
    p.u0 = [0.0, -0.5, 0.0, 0.0, 0.5, 0.0];
    let settings = SimSettings {
        dt,
        duration: Some(t_end),
        history_stride: 1000,
        ..SimSettings::default()
    };
    simulate(&p, &settings).unwrap()
}

fn compliance(law: ContactLaw) -> JointContact {
    JointContact::Compliance(ComplianceContact::new(law))
}

/// A linear spring `k` (no damping) between two masses closing at `v`: a half-sine of
/// duration `π/ω`, `ω = √(k/m_eff)`, peak force `k v/ω` and peak penetration `v/ω`; each of the
/// joint's two corners carries half the force.
#[test]
fn compliance_impact_pulse_matches_the_linear_spring_closed_form() {
    let (k, m_eff, v, dt) = (1.0e9, 5.0e5, 1.0, 1e-4);
    let sol = head_on(
        compliance(LinearSpring::new(k).unwrap().into()),
        1.0,
        dt,
        0.1,
    );
    assert_eq!(sol.status, SimStatus::Completed);
    assert_eq!(sol.summary.impacts, 1);
    assert_eq!(sol.impacts.len(), 2, "one row per corner");
    let w = (k / m_eff).sqrt();
    let (t_c, f_max, d_max) = (std::f64::consts::PI / w, k * v / w, v / w);
    for r in &sol.impacts {
        let p = r.pulse.expect("compliance impacts carry a pulse");
        eprintln!(
            "pulse {}: F {:.6e} ({:.6e}), T {:.6e} ({:.6e}), δ {:.6e} ({:.6e})",
            r.contact.name(),
            p.peak_force,
            f_max / 2.0,
            p.duration,
            t_c,
            p.max_penetration,
            d_max
        );
        // trapezoidal rule: frequency error (ωh)²/12 ≈ 2e-6, peak sampling (ωh)²/8 ≈ 3e-6,
        // linear interpolation of the zero crossings O((ωh)²) of a step
        assert!((p.duration - t_c).abs() < 1e-3 * dt, "{}", p.duration);
        assert!((p.peak_force / (f_max / 2.0) - 1.0).abs() < 1e-4);
        assert!((p.max_penetration / d_max - 1.0).abs() < 1e-4);
        // and the impulse of the elastic impact, 2 m_eff v, shared by the two corners
        assert!((r.impulse_n / (m_eff * v) - 1.0).abs() < 1e-4);
    }
    let total = sol.summary.joints[0].peak_contact_force.unwrap();
    assert!((total / f_max - 1.0).abs() < 1e-4);
}

/// A run ending inside an impact reports the pulse so far with a NaN duration.
#[test]
fn an_impact_in_progress_at_the_end_has_no_duration() {
    let sol = head_on(
        compliance(LinearSpring::new(1.0e9).unwrap().into()),
        1.0,
        1e-4,
        0.03,
    );
    let p = sol.impacts[0].pulse.unwrap();
    assert!(p.duration.is_nan() && p.peak_force > 0.0 && p.max_penetration > 0.0);
}

/// The rigid law's estimate against a Hertz compliance run of the same impact (same `k_h`, the
/// default): the elastic Hertz impact lasts `t_c = C_H δ_max / v` with peak `k_h δ_max^{3/2}`;
/// the half-sine estimate `π P / (2 t_c)` is `π (4/5) / C_H = 0.8539` of that peak (module doc of
/// `contact_law::estimate`), so the honest check is that ratio, to the time-step error of the
/// compliance run (1 %), and the estimated contact time against the compliance pulse's duration.
#[test]
fn rigid_peak_force_estimate_against_a_hertz_compliance_run() {
    let k_h = default_k_h();
    let rigid = head_on(JointContact::Rigid, 1.0, 1e-4, 0.01);
    let hertz = head_on(compliance(Hertz::new(k_h).unwrap().into()), 1.0, 1e-5, 0.08);
    assert_eq!(rigid.impacts.len(), 2);
    assert_eq!(hertz.summary.impacts, 1);
    // per corner: k_h / 2 (the joint's law shared by its two corners, as the compliance law)
    let est: Vec<_> = rigid
        .impacts
        .iter()
        .map(|r| rigid_peak_force(r.impulse_n, r.gamma_n_pre, 1.0, 0.5 * k_h))
        .collect();
    let f_est: f64 = est.iter().map(|e| e.peak_force).sum();
    let f_hertz = hertz.summary.joints[0].peak_contact_force.unwrap();
    // closed form of the Hertz peak (m_eff = 5e5 kg, v = 1 m/s)
    let d_max = (5.0 * 5.0e5 / (4.0 * k_h)).powf(0.4);
    assert!((f_hertz / (k_h * d_max.powf(1.5)) - 1.0).abs() < 1e-3);
    let ratio = f_est / f_hertz;
    let expected = std::f64::consts::PI * 0.8 / HERTZ_CONTACT_TIME_FACTOR;
    eprintln!(
        "rigid estimate {f_est:.5e} N, Hertz run {f_hertz:.5e} N, ratio {ratio:.5} ({expected:.5})"
    );
    assert!((ratio / expected - 1.0).abs() < 0.01, "{ratio}");
    for (e, r) in est.iter().zip(&hertz.impacts) {
        let dur = r.pulse.unwrap().duration;
        assert!(
            (e.contact_time / dur - 1.0).abs() < 0.01,
            "{} vs {dur}",
            e.contact_time
        );
    }
}

/// `batch.csv`'s appended columns (before `error`, which stays last): the compliance run's peak
/// contact force, steps per contact and Newton failures equal the single run's values; a rigid
/// run leaves them empty.
#[test]
fn batch_csv_appends_force_time_step_and_newton_columns() {
    use pounding::sim::batch::{BatchOutcome, BatchRow};
    use pounding::sim::output::{BATCH_HEADER, BATCH_TAIL, Layout, batch_csv};
    let head: Vec<&str> = BATCH_HEADER.split(',').collect();
    assert_eq!(head.last(), Some(&"error"));
    assert!(BATCH_HEADER.ends_with(&format!(",lcp_failures,{BATCH_TAIL},error")));
    let comp = head_on(
        compliance(LinearSpring::new(1.0e9).unwrap().into()),
        1.0,
        1e-4,
        0.1,
    );
    let rigid = head_on(JointContact::Rigid, 1.0, 1e-4, 0.01);
    let row = |index: usize, sol: &BridgeSolution| BatchRow {
        index,
        record_index: index,
        record: format!("r{index}"),
        scale_index: 0,
        scale: 1.0,
        pga: 1.0,
        outcome: Ok(BatchOutcome::from(sol.clone())),
    };
    let csv = batch_csv(Layout::TwoDecks, 2, &[row(0, &comp), row(1, &rigid)]);
    let col = |line: &str, name: &str| -> String {
        let i = head.iter().position(|h| *h == name).unwrap();
        line.split(',').nth(i).unwrap().to_string()
    };
    let lines: Vec<&str> = csv.lines().collect();
    assert!(lines.iter().all(|l| l.split(',').count() == head.len()));
    let c = lines[1];
    let peak: f64 = col(c, "peak_contact_force_n").parse().unwrap();
    assert_eq!(peak, comp.summary.joints[0].peak_contact_force.unwrap());
    let spc: f64 = col(c, "steps_per_contact").parse().unwrap();
    assert_eq!(spc, comp.time_step_advice.unwrap().steps_per_contact);
    assert!(
        (spc - 702.48).abs() < 0.01,
        "T_c / dt = π √(m_eff/k) / dt: {spc}"
    );
    assert_eq!(col(c, "newton_failures"), "0");
    for name in BATCH_TAIL.split(',').filter(|n| *n != "warnings") {
        assert_eq!(col(lines[2], name), "", "rigid run: {name}");
    }
    // the warnings count is there for every law (BatchOutcome::from leaves it 0: the batch sets it)
    assert_eq!(col(lines[2], "warnings"), "0");
}

/// Models that cannot stand (issue 12): two bearings at one point leave deck 1 free to spin
/// (singular bearing stiffness, a zero natural frequency); the scenario is refused naming the
/// deck, the key and its line, unless `[bearings] allow_mechanism = true` (then it runs, with an
/// infinite natural period).
#[test]
fn a_bearing_layout_that_is_a_mechanism_is_refused_unless_allowed() {
    use pounding::sim::scenario::{Scenario, ScenarioError};
    let text = "[bearings]\ndamping_ratio = 0\npoints1 = [[0.0, 0.0], [0.0, 0.0]]\n[time]\nduration = 0.1\n";
    let e = Scenario::from_toml(text, "m.toml")
        .and_then(|s| s.build())
        .unwrap_err();
    assert!(matches!(e, ScenarioError::Key { .. }), "{e:?}");
    let msg = e.to_string();
    assert!(
        msg.contains("deck1") && msg.contains("`[bearings] points1` (m.toml:3)"),
        "{msg}"
    );
    assert!(msg.contains("`[bearings] allow_mechanism`"), "{msg}");
    // deck 2 with no stiffness at all (and no damping to need it)
    let e = Scenario::from_toml(
        "[bearings]\ndamping_ratio = 0\nstiffness2 = 0\n[time]\nduration = 0.1\n",
        "m.toml",
    )
    .and_then(|s| s.build())
    .unwrap_err();
    assert!(
        e.to_string().contains("deck2") && e.to_string().contains("stiffness2"),
        "{e}"
    );
    // allowed explicitly: it builds and runs
    let allowed = text.replace("[bearings]\n", "[bearings]\nallow_mechanism = true\n");
    let setup = Scenario::from_toml(&allowed, "m.toml")
        .unwrap()
        .build()
        .unwrap();
    let sol = simulate(&setup.problem, &setup.settings).unwrap();
    assert!(
        sol.summary.segments[0].frequencies[0] <= 1e-6 * sol.summary.segments[0].frequencies[2]
    );
    // the default layout (4 corners) is not a mechanism
    assert!(Scenario::from_toml("", "d").unwrap().build().is_ok());
}

/// `impacts.csv` is one typed table (issue 22): on a bridge mixing rigid joints and bilinear
/// abutments, `impact` is an integer column (each record's number), the names are text, every
/// other column is a float; each row has either the compliance pulse or the rigid estimate (the
/// other NaN); its CSV is `impacts.csv`'s text, one line per record.
#[test]
fn impacts_table_holds_each_column_in_its_own_type() {
    use pounding::sim::scenario::Scenario;
    use pounding::sim::table::ColumnData;
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/viaduct-rigid-1d.toml"
    );
    let mut text = std::fs::read_to_string(path).unwrap();
    let law = "law = \"bilinear\"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3\n";
    for side in ["start", "end"] {
        let head = format!("[abutment.{side}]\ngap = 0.04\n");
        assert!(text.contains(&head));
        text = text.replace(&head, &format!("{head}\n[abutment.{side}.contact]\n{law}"));
    }
    let setup = Scenario::from_toml(&text, "mixed.toml")
        .unwrap()
        .with_duration(3.0)
        .build_setup()
        .unwrap();
    let sol = setup.run().unwrap();
    let t = setup.impacts(&sol);
    let csv = setup.impacts_csv(&sol);
    assert_eq!(t.csv(), csv);
    assert_eq!(t.rows(), sol.impacts.len());
    assert_eq!(csv.lines().count(), 1 + sol.impacts.len());
    let heads: Vec<String> = t.columns.iter().map(|c| c.header()).collect();
    assert_eq!(
        csv.lines().next().unwrap().split(',').collect::<Vec<_>>(),
        heads
    );
    for (h, d) in heads.iter().zip(&t.data) {
        match (h.as_str(), d) {
            ("impact", ColumnData::Int(v)) => {
                let want: Vec<i64> = sol.impacts.iter().map(|r| r.impact as i64).collect();
                assert_eq!(v, &want);
            }
            ("site" | "contact" | "mode", ColumnData::Text(v)) => {
                assert!(v.iter().all(|s| !s.is_empty()))
            }
            (_, ColumnData::Real(_))
                if !matches!(h.as_str(), "impact" | "site" | "contact" | "mode") => {}
            _ => panic!("column {h} has the wrong type: {d:?}"),
        }
    }
    let real = |h: &str| match t.column(h) {
        Some(ColumnData::Real(v)) => v.clone(),
        other => panic!("{h}: {other:?}"),
    };
    let (pulse, estimate) = (real("peak_force_n"), real("peak_force_estimate_n"));
    assert!(pulse.iter().any(|x| x.is_nan()) && estimate.iter().any(|x| x.is_nan()));
    for (p, e) in pulse.iter().zip(&estimate) {
        assert!(p.is_nan() != e.is_nan(), "{p} {e}");
    }
}
