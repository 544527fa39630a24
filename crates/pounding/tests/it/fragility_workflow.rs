//! The fragility workflow (issue 13): record-set manifests, `[fragility]` / `[[limit_state]]`
//! settings, IM scaling, the fundamental period, limit states and the IDA first exceedance.

use pounding::assessment::im::{ImSpec, fundamental_period, intensity};
use pounding::assessment::limit::bind;
use pounding::assessment::run::{FirstExceedance, Plan, RunRow, first_exceedance};
use pounding::assessment::{FragilitySettings, ImKind, PairIm, Stripes};
use pounding::ground_motion::set::{MetaValue, RecordSet};
use pounding::ground_motion::{G0, GroundMotion, Record};
use pounding::sim::scenario::Scenario;
use std::path::Path;

fn scratch(name: &str) -> crate::scratch::Scratch {
    crate::scratch::scratch_dir("fw", name)
}

const MANIFEST: &str = r#"[set]
name = "test"

[[record]]
id = "A"
x = "a.txt"
dt = 0.01
units = "m/s2"
[record.meta]
magnitude = 6.5
site = "rock"

[[record]]
id = "P"
x = "builtin:ELC180"
y = "builtin:ELC270"
[record.meta]
magnitude = 6.95
"#;

#[test]
fn a_manifest_reads_records_pairs_units_and_metadata() {
    let d = scratch("manifest");
    std::fs::write(d.join("a.txt"), "0.0\n1.0\n-2.0\n0.5\n").unwrap();
    std::fs::write(d.join("set.toml"), MANIFEST).unwrap();
    let set = RecordSet::load(&d.join("set.toml")).unwrap();
    assert_eq!(set.name, "test");
    assert_eq!(set.records.len(), 2);
    let a = &set.records[0];
    assert_eq!(a.id, "A");
    assert!(a.y.is_none());
    // m/s2: taken as written (not times g); dt from the manifest
    assert_eq!(a.x.values(), &[0.0, 1.0, -2.0, 0.5]);
    assert_eq!(a.x.dt(), Some(0.01));
    assert_eq!(
        a.meta,
        vec![
            ("magnitude".into(), MetaValue::Number(6.5)),
            ("site".into(), MetaValue::Text("rock".into()))
        ]
    );
    let p = &set.records[1];
    let elc = pounding::ground_motion::el_centro_1940();
    assert_eq!(&p.x, elc.along_y.as_ref().unwrap());
    assert_eq!(p.y.as_ref(), elc.along_x.as_ref());
    assert_eq!(set.meta_keys(), vec!["magnitude", "site"]);
}

fn load_err(text: &str, files: &[(&str, &str)]) -> String {
    let d = scratch(&format!("err{}", text.len()));
    for (n, t) in files {
        std::fs::write(d.join(n), t).unwrap();
    }
    std::fs::write(d.join("set.toml"), text).unwrap();
    RecordSet::load(&d.join("set.toml"))
        .unwrap_err()
        .to_string()
}

#[test]
fn manifest_errors_name_the_key_its_line_and_the_file() {
    let dup = "[[record]]\nid = \"A\"\nx = \"builtin:ELC180\"\n[[record]]\nid = \"A\"\nx = \"builtin:ELC270\"\n";
    let e = load_err(dup, &[]);
    assert!(
        e.contains("record[1].id") && e.contains("set.toml:5") && e.contains("duplicate"),
        "{e}"
    );
    // two missing files: both named, each with its key and line
    let missing = "[[record]]\nid = \"A\"\nx = \"nope1.AT2\"\n[[record]]\nid = \"B\"\nx = \"builtin:ELC180\"\ny = \"nope2.AT2\"\n";
    let e = load_err(missing, &[]);
    assert!(
        e.contains("record[0].x") && e.contains("set.toml:3") && e.contains("nope1.AT2"),
        "{e}"
    );
    assert!(
        e.contains("record[1].y") && e.contains("set.toml:7") && e.contains("nope2.AT2"),
        "{e}"
    );
    let unknown = "[[record]]\nid = \"A\"\nx = \"builtin:ELC180\"\nscale = 2.0\n";
    let e = load_err(unknown, &[]);
    assert!(e.contains("scale") && e.contains("line 4"), "{e}");
    let dt = "[[record]]\nid = \"A\"\nx = \"a.txt\"\ny = \"b.txt\"\ndt = 0.01\n";
    let d = scratch("dt-ok");
    std::fs::write(d.join("a.txt"), "0\n1\n").unwrap();
    std::fs::write(d.join("b.txt"), "0\n1\n").unwrap();
    std::fs::write(d.join("set.toml"), dt).unwrap();
    // one dt for both components: accepted
    assert!(
        RecordSet::load(&d.join("set.toml")).unwrap().records[0]
            .y
            .is_some()
    );
    let dt2 = "[[record]]\nid = \"A\"\nx = \"a.csv\"\ny = \"b.csv\"\n";
    let e = load_err(
        dt2,
        &[
            ("a.csv", "0,0\n0.01,1\n0.02,0\n"),
            ("b.csv", "0,0\n0.02,1\n0.04,0\n"),
        ],
    );
    assert!(
        e.contains("record[0].y") && e.contains("different sample intervals"),
        "{e}"
    );
    let empty = "[set]\nname = \"x\"\n";
    assert!(load_err(empty, &[]).contains("no [[record]]"));
}

const BRIDGE: &str = r#"[bridge]
damping = "dashpots"
gap = 0.02
[[segment]]
shape = "straight"
L = 30.0
mass = 1.0e6
bearing_stiffness = 2.5e6
[[segment]]
shape = "straight"
L = 30.0
mass = 1.2e6
period_s = 0.5
[ground_motion]
scale_y = -1.0
[time]
dt = 2e-3
duration = 2.0
"#;

const FRAG: &str = r#"[fragility]
im = "sa"
period_s = "model"
levels_g = [0.1, 0.3]

[[limit_state]]
name = "seat"
kind = "unseating"

[[limit_state]]
name = "impulse"
kind = "joint_force"
capacity_ns = 1.0e5
"#;

#[test]
fn simulate_still_reads_a_scenario_with_fragility_tables() {
    let text = format!("{BRIDGE}{FRAG}");
    let sc = Scenario::from_toml(&text, "s.toml").unwrap();
    assert!(sc.build_bridge().is_ok());
    let f = FragilitySettings::from_scenario(&text, "s.toml").unwrap();
    assert_eq!(f.limit_states.len(), 2);
    assert_eq!(f.stripes, Stripes::Levels(vec![0.1, 0.3]));
    assert_eq!((f.bootstrap, f.seed, f.level), (500, 1, 0.95));
}

fn settings_err(frag: &str) -> String {
    let text = format!("{BRIDGE}{frag}");
    FragilitySettings::from_scenario(&text, "s.toml")
        .unwrap_err()
        .to_string()
}

#[test]
fn fragility_settings_errors_name_key_and_line() {
    let line = |needle: &str| {
        let t = format!("{BRIDGE}{FRAG}");
        t.lines().position(|l| l.starts_with(needle)).unwrap() + 1
    };
    let e = settings_err(&FRAG.replace("[0.1, 0.3]", "[0.1, 0.0]"));
    assert!(
        e.contains("fragility.levels_g") && e.contains(&format!("s.toml:{}", line("levels_g"))),
        "{e}"
    );
    let e = settings_err(&FRAG.replace("im = \"sa\"", "im = \"sa\"\ndamping = 1.0"));
    assert!(
        e.contains("fragility.damping") && e.contains("[0, 1)"),
        "{e}"
    );
    let e = settings_err(&FRAG.replace("period_s = \"model\"", "period_s = -1.0"));
    assert!(e.contains("fragility.period_s"), "{e}");
    let e = settings_err(&FRAG.replace("im = \"sa\"", "im = \"sa\"\nlevel_g = [1.0]"));
    assert!(e.contains("level_g"), "{e}");
    let e = settings_err(&FRAG.replace("kind = \"unseating\"", "kind = \"collapse\""));
    assert!(
        e.contains("limit_state[0].kind")
            && e.contains(&format!("s.toml:{}", line("kind = \"unseating\""))),
        "{e}"
    );
    let e = settings_err(&FRAG.replace("capacity_ns", "limit_m"));
    assert!(e.contains("limit_state[1].limit_m"), "{e}");
    let e = settings_err(&FRAG.replace("name = \"impulse\"", "name = \"seat\""));
    assert!(e.contains("duplicate"), "{e}");
    let e = settings_err(&FRAG.replace("name = \"impulse\"", "name = \"governing_seat\""));
    assert!(
        e.contains("limit_state[1].name") && e.contains("governing_seat_ratio"),
        "{e}"
    );
    // capacity_n on a rigid bridge: refused when bound to the model
    let text = format!("{BRIDGE}{}", FRAG.replace("capacity_ns", "capacity_n"));
    let f = FragilitySettings::from_scenario(&text, "s.toml").unwrap();
    let m = Scenario::from_toml(&text, "s.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let e = bind(&f.limit_states, &m.problem.model, "s.toml")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("limit_state[1].capacity_n") && e.contains("rigid"),
        "{e}"
    );
}

#[test]
fn the_model_period_is_the_closed_form_of_a_segment_on_bearings() {
    // one segment, four corner bearings of k each: translation omega^2 = 4k/m (rotation is
    // stiffer: 12k/m for a rectangle), so T1 = 2 pi sqrt(m / 4k)
    let text =
        "[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = 1.0e6\nbearing_stiffness = 2.5e6\n";
    let m = Scenario::from_toml(text, "one.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let p = fundamental_period(&m.problem.model).unwrap();
    let exact = 2.0 * std::f64::consts::PI * (1.0e6_f64 / (4.0 * 2.5e6)).sqrt();
    assert!(
        (p.period - exact).abs() <= 1e-12 * exact,
        "{} vs {exact}",
        p.period
    );
    assert_eq!(p.segment, 1);
    // two segments: the longer period (segment 1: 1.987 s; segment 2: 0.5 s)
    let m2 = Scenario::from_toml(BRIDGE, "b.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let p2 = fundamental_period(&m2.problem.model).unwrap();
    assert_eq!(p2.segment, 1);
    assert!((p2.period - exact).abs() <= 1e-12 * exact);
}

fn scaled(r: &Record, s: f64) -> Record {
    Record::new(
        "s",
        r.times().to_vec(),
        r.values().iter().map(|a| a * s).collect(),
    )
    .unwrap()
}

#[test]
fn scaling_to_a_level_gives_that_im_exactly() {
    let elc = pounding::ground_motion::el_centro_1940();
    let (x, y) = (elc.along_y.clone().unwrap(), elc.along_x.clone().unwrap());
    let entry = |pair: bool| pounding::ground_motion::set::SetRecord {
        id: "e".into(),
        x: x.clone(),
        y: pair.then(|| y.clone()),
        meta: Vec::new(),
        supports: Vec::new(),
    };
    let set = RecordSet {
        name: String::new(),
        source: String::new(),
        records: vec![entry(false), entry(true)],
    };
    // the scenario's scale factors: the IM is that of the motion as applied
    let ground = GroundMotion {
        scale_y: -1.5,
        scale_x: 0.8,
        ..GroundMotion::none()
    };
    let levels = vec![0.2, 0.75];
    for (kind, pair) in [
        (ImKind::Pga, PairIm::GeoMean),
        (ImKind::Sa, PairIm::GeoMean),
        (ImKind::Sa, PairIm::RotD50),
        (ImKind::Pga, PairIm::RotD50),
    ] {
        let spec = ImSpec {
            kind,
            period: 0.7,
            damping: 0.05,
            pair,
        };
        let plan = Plan::new(&set, &spec, &Stripes::Levels(levels.clone()), &ground).unwrap();
        for (a, e) in set.records.iter().enumerate() {
            for (b, &level) in levels.iter().enumerate() {
                let (im, sf) = plan.point(a, b);
                assert_eq!(im, level);
                // independent: the applied components, spectra by pounding::spectrum
                let ax = scaled(&e.x, sf * ground.scale_y);
                let sa = |r: &Record| match kind {
                    ImKind::Pga => r.pga() / G0,
                    ImKind::Sa => pounding::spectrum::spectrum(r, 0.05, &[0.7]).unwrap()[0].psa_g,
                };
                let got = match &e.y {
                    None => sa(&ax),
                    Some(yr) => {
                        let ay = scaled(yr, sf * ground.scale_x);
                        match (pair, kind) {
                            (PairIm::GeoMean, _) => (sa(&ax) * sa(&ay)).sqrt(),
                            (PairIm::RotD50, ImKind::Sa) => {
                                pounding::spectrum::rotd(&ax, &ay, 0.05, &[0.7])
                                    .unwrap()
                                    .rotd50[0]
                                    .psa_g
                            }
                            (PairIm::RotD50, ImKind::Pga) => {
                                // the median over 180 angles of the rotated PGA (same grid)
                                let mut p: Vec<f64> = (0..180)
                                    .map(|d| {
                                        let (s, c) = (d as f64).to_radians().sin_cos();
                                        ax.values()
                                            .iter()
                                            .zip(ay.values())
                                            .map(|(u, v)| (c * u + s * v).abs())
                                            .fold(0.0, f64::max)
                                    })
                                    .collect();
                                p.sort_by(f64::total_cmp);
                                0.5 * (p[89] + p[90]) / G0
                            }
                        }
                    }
                };
                assert!(
                    (got - level).abs() <= 1e-12 * level,
                    "{kind:?} {pair:?} entry {a}: {got} vs {level}"
                );
            }
        }
        let _ = intensity(&spec, &set.records[0], 1.0, 1.0);
    }
}

/// A record set of the one entry `id` (one component).
fn one_record_set(id: &str, x: Record) -> RecordSet {
    RecordSet {
        name: String::new(),
        source: String::new(),
        records: vec![pounding::ground_motion::set::SetRecord {
            id: id.into(),
            x,
            y: None,
            meta: Vec::new(),
            supports: Vec::new(),
        }],
    }
}

#[test]
fn a_record_with_zero_im_is_an_error_naming_it() {
    let set = one_record_set("Z1", Record::uniform("zero", 0.01, vec![0.0; 10]).unwrap());
    let e = plan_error(&set, ImKind::Pga, 1.0);
    assert!(e.contains("Z1"), "{e}");
}

/// The error of the plan of `set` at one level of an IM of `kind`, the record along y times
/// `scale_y`.
fn plan_error(set: &RecordSet, kind: ImKind, scale_y: f64) -> String {
    let spec = ImSpec {
        kind,
        period: 1.0,
        damping: 0.05,
        pair: PairIm::GeoMean,
    };
    let ground = GroundMotion {
        scale_y,
        ..GroundMotion::none()
    };
    Plan::new(set, &spec, &Stripes::Levels(vec![0.1]), &ground)
        .unwrap_err()
        .to_string()
}

/// A scale factor that overflows a record (`scale_y = 1e308`) is an error naming the record and
/// the key, not a panic (the hostile campaign's panic in the IM of a scaled record).
#[test]
fn a_scale_factor_that_overflows_a_record_is_an_error() {
    let r = Record::uniform("big", 0.01, vec![0.0, 3.0, -2.0, 1.0]).unwrap();
    let set = one_record_set("B1", r);
    for kind in [ImKind::Pga, ImKind::Sa] {
        let e = plan_error(&set, kind, -1e308);
        assert!(
            e.contains("B1") && e.contains("scale_y") && e.contains("not finite"),
            "{e}"
        );
    }
}

#[test]
fn limit_states_on_a_hand_set_summary() {
    let text = format!("{BRIDGE}{}", FRAG.replace(
        "[[limit_state]]\nname = \"seat\"",
        "[[limit_state]]\nname = \"bear\"\nkind = \"bearing_deformation\"\nlimit_m = 0.1\n\n[[limit_state]]\nname = \"rot\"\nkind = \"rotation\"\nlimit_deg = 0.5\n\n[[limit_state]]\nname = \"open\"\nkind = \"joint_opening\"\nlimit_m = 0.05\n\n[[limit_state]]\nname = \"seat\"",
    ));
    let f = FragilitySettings::from_scenario(&text, "s.toml").unwrap();
    let setup = Scenario::from_toml(&text, "s.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let lims = bind(&f.limit_states, &setup.problem.model, "s.toml").unwrap();
    // a real summary, then hand-set demands
    let mut s = setup.run().unwrap().summary;
    s.segments[0].peak_bearing_deformation = 0.05;
    s.segments[1].peak_bearing_deformation = 0.12;
    s.segments[0].peak_rotation = 0.4_f64.to_radians();
    s.segments[1].peak_rotation = 0.1_f64.to_radians();
    s.joints[0].peak_opening = 0.04;
    s.joints[0].peak_impulse = 2.0e5;
    s.peak_seat_displacement = 0.3;
    s.peak_seat_ratio = 0.6;
    s.unseated = false;
    let got: Vec<(Option<bool>, f64)> = lims.iter().map(|l| l.evaluate(&s)).collect();
    let names: Vec<&str> = lims.iter().map(|l| l.state.name.as_str()).collect();
    assert_eq!(names, ["bear", "rot", "open", "seat", "impulse"]);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    assert_eq!(got[0].0, Some(true));
    assert!(close(got[0].1, 1.2));
    assert_eq!(got[1].0, Some(false));
    assert!(close(got[1].1, 0.8));
    assert_eq!(got[2].0, Some(false));
    assert!(close(got[2].1, 0.8));
    // unseating: the run's flag; the ratio is the summary's per-end seat ratio
    assert_eq!(got[3].0, Some(false));
    assert!(close(got[3].1, 0.6));
    s.unseated = true;
    assert_eq!(lims[3].evaluate(&s).0, Some(true));
    assert_eq!(got[4], (Some(true), 2.0));
    let _ = Path::new(".");
}

fn row(stripe: usize, im: f64, ex: Option<bool>, ratio: f64) -> RunRow {
    RunRow {
        record: 0,
        stripe,
        im_g: im,
        scale_factor: 1.0,
        status: "Completed".into(),
        error: String::new(),
        limits: vec![(ex, ratio)],
        warnings: 0,
        seats: Vec::new(),
        governing_seat: None,
    }
}

/// The first exceedance of one record run at three stripes (IM 0.1, 0.2, 0.4 g), given each
/// run's (exceeded, ratio).
fn first_of(runs: [(Option<bool>, f64); 3]) -> FirstExceedance {
    let rows: Vec<RunRow> = runs
        .iter()
        .zip([0.1, 0.2, 0.4])
        .enumerate()
        .map(|(k, (&(ex, ratio), im))| row(k, im, ex, ratio))
        .collect();
    first_exceedance(&rows, 1, 3, 0).swap_remove(0)
}

#[test]
fn ida_first_exceedance_interpolates_the_ratio_to_one() {
    // ratio 0.8 at 0.2, 1.3 at 0.4: reaches 1 at 0.2 + 0.2 * 0.2 / 0.5 = 0.28
    match first_of([(Some(false), 0.5), (Some(false), 0.8), (Some(true), 1.3)]) {
        FirstExceedance::At(x) => assert!((x - 0.28).abs() < 1e-15, "{x}"),
        o => panic!("{o:?}"),
    }
    let never = [(Some(false), 0.5), (Some(false), 0.8), (Some(false), 0.9)];
    assert_eq!(first_of(never), FirstExceedance::NotWithin);
    let unknown = [(Some(false), 0.5), (None, f64::NAN), (Some(true), 1.3)];
    assert_eq!(first_of(unknown), FirstExceedance::Unknown);
    let first = [(Some(true), 1.5), (Some(true), 2.0), (Some(true), 3.0)];
    assert_eq!(first_of(first), FirstExceedance::At(0.1));
}
