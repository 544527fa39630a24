//! Supports that move apart (wave passage, a motion per support): a linear two-span bridge on a
//! pier against an independent absolute-coordinate integration written here; the uniform limit
//! (`v_app = ∞` bit for bit, a huge `v_app` through the support path to rounding); a
//! support-motion file of delayed copies against the wave-passage rule; and the refusals.

use pounding::ground_motion::el_centro_1940;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::Scenario;

/// Two straight segments along −y (L = 30 m, W = 12 m), bearings at ±5 m at both ends (4e6 N/m
/// and 1e5 N·s/m each), an elastic pier under the joint (cap 2e5 kg, k0 = 8e7 N/m, 1e6 N·s/m);
/// no abutments, a joint gap that never closes; El Centro 180 × `scale` along the chain.
fn two_spans(ground: &str, duration: f64) -> String {
    let seg = |m: f64| {
        format!(
            "[[segment]]\nshape = \"straight\"\nL = 30.0\nwidth = 12.0\nmass = {m:e}\n\
             bearing_stiffness = 4.0e6\nbearing_damping = 1.0e5\n\
             bearing_points = [[0.0, -5.0], [0.0, 5.0], [30.0, -5.0], [30.0, 5.0]]\n\n"
        )
    };
    format!(
        "[bridge]\ndamping_ratio = 0.0\ngap = 2.0\nmu = 0.0\nseat_length = 4.0\n\
         outer_seat_length = 4.0\n\n{}{}\
         [[pier]]\njoint = 1\ncap_mass = 2.0e5\nk0 = 8.0e7\ndamping = 1.0e6\n\n\
         [contact]\nlaw = \"rigid\"\n\n[ground_motion]\n{ground}\n\n\
         [time]\ndt = 1e-3\nduration = {duration}\nhistory_every = 1\n",
        seg(1.0e6),
        seg(1.2e6)
    )
}

fn run(text: &str) -> BridgeSolution {
    let setup = Scenario::from_toml(text, "wave.toml")
        .expect("reads")
        .build_bridge()
        .expect("builds");
    let sol = pounding::sim::simulate(&setup.problem, &setup.settings).expect("runs");
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    sol
}

/// The exact double integral of a piecewise-linear record (written here, apart from the
/// library's): `(v, u)` at `t`, at rest before the first sample, `a = 0` after the last.
fn exact_vu(ts: &[f64], a: &[f64], t: f64) -> (f64, f64) {
    let (mut v, mut u) = (0.0, 0.0);
    if t < ts[0] {
        return (0.0, 0.0);
    }
    for i in 0..ts.len() - 1 {
        let d = ts[i + 1] - ts[i];
        let tau = (t - ts[i]).min(d);
        let s = (a[i + 1] - a[i]) / d;
        let u1 = u + v * tau + a[i] * tau * tau / 2.0 + s * tau.powi(3) / 6.0;
        let v1 = v + a[i] * tau + s * tau * tau / 2.0;
        (u, v) = (u1, v1);
        if t <= ts[i + 1] {
            return (v, u);
        }
    }
    let tn = ts[ts.len() - 1];
    (v, u + v * (t - tn))
}

/// A linear bridge under wave passage (v_app = 100 m/s; the joint's support line lies midway
/// across its 2 m gap, 31 m from the near end and the far end 62 m: the record reaches them
/// 0.31 s and 0.62 s after the near end) against the same bridge written in absolute
/// coordinates here: decks `y1`, `y2` and cap `yc` on springs and dashpots to the ground points
/// `u_0(t)`, `u_1(t)`, `u_2(t)` (each the record's exact displacement, delayed), integrated by
/// RK4 at a tenth of the step. The simulator's coordinates are relative to the near end's
/// motion: `q = y − u_0`. Agreement to 2e-3 of the peak relative displacement (the θ-method's
/// second-order error at h = 1e-3 s), and the pier's drift is `y_c − u_1`.
#[test]
fn linear_bridge_under_wave_passage_is_its_absolute_solution() {
    let (v_app, scale, dur) = (100.0, 0.5, 12.0);
    let ground = format!(
        "record_y = \"builtin:ELC180\"\nrecord_x = \"none\"\nscale_y = {scale}\nv_app = {v_app}"
    );
    let sol = run(&two_spans(&ground, dur));
    let rec = el_centro_1940().along_y.unwrap();
    let (ts, a): (Vec<f64>, Vec<f64>) = (
        rec.times().to_vec(),
        rec.values().iter().map(|x| x * scale).collect(),
    );
    // supports start (y = 0), joint1 (y = −31), end (y = −62): delays 0, 0.31, 0.62 s
    let sup =
        |t: f64| -> [(f64, f64); 3] { [0.0, 0.31, 0.62].map(|tau| exact_vu(&ts, &a, t - tau)) };
    let (k, c, k0, c0) = (2.0 * 4.0e6, 2.0 * 1.0e5, 8.0e7, 1.0e6);
    let m = [1.0e6, 1.2e6, 2.0e5];
    // state [y1, y2, yc, v1, v2, vc]
    let f = |t: f64, s: &[f64; 6]| -> [f64; 6] {
        let g = sup(t);
        let (y1, y2, yc, v1, v2, vc) = (s[0], s[1], s[2], s[3], s[4], s[5]);
        let a1 = (-k * (y1 - g[0].1) - c * (v1 - g[0].0) - k * (y1 - yc) - c * (v1 - vc)) / m[0];
        let a2 = (-k * (y2 - g[2].1) - c * (v2 - g[2].0) - k * (y2 - yc) - c * (v2 - vc)) / m[1];
        let ac = (-k * (yc - y1)
            - c * (vc - v1)
            - k * (yc - y2)
            - c * (vc - v2)
            - k0 * (yc - g[1].1)
            - c0 * (vc - g[1].0))
            / m[2];
        [v1, v2, vc, a1, a2, ac]
    };
    let h = 1e-4;
    let mut s = [0.0; 6];
    let mut t = 0.0;
    let mut worst = 0.0f64;
    let mut amp = 0.0f64;
    let mut drift = 0.0f64;
    let n = (dur / h).round() as usize;
    let dofs = &sol.dofs;
    let (iy1, iy2) = (dofs.start(0) + 1, dofs.start(1) + 1);
    let iyc = dofs.start(2) + 1;
    for step in 0..=n {
        if step % 10 == 0 {
            let r = step / 10;
            assert!((sol.t[r] - t).abs() < 1e-9);
            let q = sol.q_row(r);
            let u0 = sup(t)[0].1;
            for (i, y) in [(iy1, s[0]), (iy2, s[1]), (iyc, s[2])] {
                worst = worst.max((q[i] - (y - u0)).abs());
                amp = amp.max((y - u0).abs());
            }
            drift = drift.max((s[2] - sup(t)[1].1).abs());
        }
        if step == n {
            break;
        }
        let add = |s: &[f64; 6], d: &[f64; 6], w: f64| std::array::from_fn(|i| s[i] + w * d[i]);
        let k1 = f(t, &s);
        let k2 = f(t + h / 2.0, &add(&s, &k1, h / 2.0));
        let k3 = f(t + h / 2.0, &add(&s, &k2, h / 2.0));
        let k4 = f(t + h, &add(&s, &k3, h));
        s = std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        t = (step + 1) as f64 * h;
    }
    assert!(
        amp > 0.02,
        "the bridge moves relative to the near end ({amp})"
    );
    assert!(worst < 2e-3 * amp, "max |Δq| {worst:e} of {amp:e}");
    let p = &sol.summary.piers[0];
    assert!(
        (p.peak_drift_magnitude - drift).abs() < 5e-3 * drift,
        "pier drift {} vs {drift}",
        p.peak_drift_magnitude
    );
    assert!(sol.summary.energy_balance_error < 1e-9);
    // the same bridge under uniform motion moves differently: the test sees the wave
    let uni = run(&two_spans(
        &format!("record_y = \"builtin:ELC180\"\nrecord_x = \"none\"\nscale_y = {scale}"),
        dur,
    ));
    let d = (uni.summary.piers[0].peak_drift_magnitude - p.peak_drift_magnitude).abs();
    assert!(
        d > 0.05 * drift,
        "wave passage changes the pier drift ({d})"
    );
}

/// `v_app = inf` is the uniform run, bit for bit; a huge finite `v_app` (delays of 1e-10 s)
/// runs the supports' load through the dense scheme and agrees with it to rounding.
#[test]
fn uniform_limit() {
    let base = "record_y = \"builtin:ELC180\"\nrecord_x = \"none\"\nscale_y = 0.5";
    let uni = run(&two_spans(base, 6.0));
    let inf = run(&two_spans(&format!("{base}\nv_app = inf"), 6.0));
    assert!(uni.q == inf.q && uni.u == inf.u && uni.summary == inf.summary);
    let fast = run(&two_spans(&format!("{base}\nv_app = 3.0e11"), 6.0));
    let scale = uni.q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let diff = uni
        .q
        .iter()
        .zip(&fast.q)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(scale > 1e-3 && diff < 1e-9 * scale, "{diff:e} of {scale:e}");
    assert_ne!(uni.q, fast.q, "the support path ran");
}

/// A support-motion file holding a record delayed by 0.31 s and 0.62 s at the joint and the far
/// end gives the wave-passage run of `v_app = 100` of that record. (The record is El Centro 180
/// with its first sample set to zero: the rule's delayed copy is zero up to its arrival, a file's
/// column the straight line between its samples, so they are the same function only when the
/// record starts from zero.)
#[test]
fn support_file_of_delayed_records_is_the_wave_passage() {
    let rec = el_centro_1940().along_y.unwrap();
    let dt = 0.01;
    let n = 1000; // 10 s
    let a = |t: f64| {
        if t < 0.5 * dt { 0.0 } else { rec.accel(t) }
    };
    let (mut csv, mut one) = (String::from("t,start,joint1,end\n"), String::new());
    for i in 0..=n {
        let t = i as f64 * dt;
        let d = |k: i64| a((i as i64 - k) as f64 * dt);
        csv += &format!("{t},{},{},{}\n", d(0), d(31), d(62));
        one += &format!("{t},{}\n", d(0));
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("real.csv"), csv).unwrap();
    std::fs::write(dir.path().join("rec.csv"), one).unwrap();
    let sol = |ground: &str| {
        let path = dir.path().join("s.toml");
        std::fs::write(&path, two_spans(ground, 8.0)).unwrap();
        let setup = Scenario::load(&path).unwrap().build_bridge().unwrap();
        pounding::sim::simulate(&setup.problem, &setup.settings).unwrap()
    };
    let file = sol("supports_y = \"real.csv\"\nscale_y = 0.5");
    let wave = sol(
        "record_y = \"rec.csv\"\ncsv_units = \"m/s2\"\nrecord_x = \"none\"\nscale_y = 0.5\n\
         v_app = 100.0",
    );
    let scale = wave.q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let diff = wave
        .q
        .iter()
        .zip(&file.q)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(scale > 1e-2 && diff < 1e-9 * scale, "{diff:e} of {scale:e}");
}

/// Bad support-motion input is refused naming the key.
#[test]
fn refusals_name_the_key() {
    let elc = "record_y = \"builtin:ELC180\"\nrecord_x = \"none\"";
    for (ground, extra, want) in [
        (format!("{elc}\nv_app = -250.0"), "", "v_app"),
        (format!("{elc}\nv_app = 0.0"), "", "v_app"),
        (format!("{elc}\nv_app = nan"), "", "v_app"),
        (
            format!("{elc}\nwave_direction_deg = 10.0"),
            "",
            "needs v_app",
        ),
        (
            format!("{elc}\nv_app = 250.0\nwave_direction_deg = inf"),
            "",
            "wave_direction_deg",
        ),
        (
            "supports_y = \"missing.csv\"\nrecord_y = \"builtin:ELC180\"".into(),
            "",
            "record_y",
        ),
        ("supports_y = \"missing.csv\"".into(), "", "missing.csv"),
        (format!("{elc}\nv_app = 250.0"), "", "dashpots"),
        (
            format!("{elc}\nv_app = 250.0\nwave_direction_deg = 1e300"),
            "",
            "[-360, 360]",
        ),
        (format!("{elc}\nv_app = 1e-3"), "", "longer than the record"),
        (
            format!("{elc}\nv_app = 1e-300"),
            "",
            "longer than the record",
        ),
        ("supports_y = \"\"".into(), "", "supports_y is empty"),
        (
            "supports_y = \"r.csv\"\nrecord_dt = 0.01".into(),
            "",
            "cannot be combined",
        ),
    ] {
        let mut text = two_spans(&ground, 2.0).replace("[contact]", &format!("{extra}\n[contact]"));
        if want == "dashpots" {
            text = text.replace(
                "damping_ratio = 0.0",
                "damping_ratio = 0.05\ndamping = \"dashpots\"",
            );
        }
        let e = Scenario::from_toml(&text, "w.toml")
            .and_then(|s| s.build_bridge())
            .map(|_| ());
        let Err(e) = e else {
            panic!("{ground} / {extra}: accepted")
        };
        let e = e.to_string();
        assert!(e.contains(want), "{ground} / {extra}: {e}");
        if want == "dashpots" {
            // the line that sets them
            assert!(e.contains("w.toml:3"), "{e}");
        }
    }
    // a file without a column for a support, or with one the bridge lacks
    let dir = tempfile::tempdir().unwrap();
    for (csv, want) in [
        (
            "t,start,end\n0,0,0\n1,1,1\n",
            "no column for support `joint1`",
        ),
        (
            "t,start,joint1,end,pier9\n0,0,0,0,0\n1,1,1,1,1\n",
            "`pier9`",
        ),
    ] {
        std::fs::write(dir.path().join("r.csv"), csv).unwrap();
        let path = dir.path().join("s.toml");
        std::fs::write(&path, two_spans("supports_y = \"r.csv\"", 1.0)).unwrap();
        let e = Scenario::load(&path)
            .and_then(|s| s.build_bridge())
            .map(|_| ())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains(want) && e.contains("supports_y") && e.contains("r.csv"),
            "{e}"
        );
    }
    // a byte-order mark before the header is read as text editors write it
    std::fs::write(
        dir.path().join("r.csv"),
        "\u{feff}t,start,joint1,end\n0,0,0,0\n1,1,1,1\n",
    )
    .unwrap();
    let path = dir.path().join("s.toml");
    std::fs::write(&path, two_spans("supports_y = \"r.csv\"", 1.0)).unwrap();
    assert!(Scenario::load(&path).unwrap().build_bridge().is_ok());
    // a CSV manifest's `supports` column is not silently metadata
    let e = pounding::ground_motion::set::RecordSet::from_csv(
        "id,x,supports\nA,builtin:ELC180,r.csv\n",
        "m.csv",
        dir.path(),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("supports") && e.contains("TOML"), "{e}");
    // two-deck files: the supports all move together
    let e = Scenario::from_toml("[ground_motion]\nv_app = 250.0\n", "two.toml")
        .and_then(|s| s.build().map(|_| ()))
        .unwrap_err()
        .to_string();
    assert!(e.contains("v_app") && e.contains("bridge files"), "{e}");
}

/// Galilean check of the moving supports: every support given the same record X while the
/// reference ground motion is another record Y is the uniform run under X, seen from Y. With
/// rigid (impact-law) and compliance abutments and joints that pound, the histories agree
/// after shifting by `u_Y − u_X`: the supports' load, the moving abutment faces (gaps, closing
/// velocities, the impact law on the relative velocity) and the θ-point forcing together
/// reproduce the inertia load of X (to the scheme's O(h²): 2e-3 of the motion over 3 s).
#[test]
fn all_supports_on_another_record_is_that_uniform_run() {
    use pounding::ground_motion::integral::GroundKinematics;
    use pounding::sim::excitation::{SupportExcitation, SupportRecord};
    for law in ["rigid", "kelvin\nk = 2.0e9\nrestitution = 0.6"] {
        let text = two_spans("record_y = \"builtin:ELC180\"\nrecord_x = \"none\"", 3.0)
            .replace("gap = 2.0", "gap = 0.01")
            .replace(
                "[contact]\nlaw = \"rigid\"",
                &format!(
                    "[abutment.start]\ngap = 0.01\n\n[abutment.end]\ngap = 0.01\n\n\
                     [contact]\nlaw = \"{law}"
                ),
            )
            .replace("law = \"kelvin\nk", "law = \"kelvin\"\nk");
        let text = if law == "rigid" {
            text.replace("law = \"rigid\n", "law = \"rigid\"\n")
        } else {
            text
        };
        let setup = Scenario::from_toml(&text, "g.toml")
            .expect("reads")
            .build_bridge()
            .expect("builds");
        let x = setup.problem.ground.clone();
        let uni = pounding::sim::simulate(&setup.problem, &setup.settings).expect("runs");
        let mut y = el_centro_1940();
        y.along_y = None; // ELC270 along x only
        y.scale_x = 0.5;
        let lines = setup.problem.model.support_lines();
        let mut problem = setup.problem.clone();
        problem.ground = y.clone();
        problem.supports = SupportExcitation::Records(
            lines
                .iter()
                .map(|l| SupportRecord {
                    id: l.id.clone(),
                    ground: x.clone(),
                })
                .collect(),
        );
        let moved = pounding::sim::simulate(&problem, &setup.settings).expect("runs");
        assert_eq!(moved.status, pounding::sim::SimStatus::Completed, "{law}");
        assert!(moved.summary.energy_balance_error < 1e-9, "{law}");
        assert!(uni.summary.impacts > 3, "{law}: the bridge pounds");
        let (kx, ky) = (GroundKinematics::new(&x), GroundKinematics::new(&y));
        let n = uni.dofs.len();
        let (mut worst, mut amp) = (0.0f64, 0.0f64);
        for (r, &t) in uni.t.iter().enumerate() {
            let shift = ky.velocity_displacement(t).1 - kx.velocity_displacement(t).1;
            for j in 0..uni.n_segments {
                let s = uni.dofs.start(j);
                for (d, sh) in [(0, shift.x), (1, shift.y)] {
                    let a = uni.q[n * r + s + d];
                    let b = moved.q[n * r + s + d] + sh;
                    worst = worst.max((a - b).abs());
                    amp = amp.max(a.abs());
                }
            }
        }
        assert!(
            amp > 1e-2 && worst < 2e-3 * amp,
            "{law}: {worst:e} of {amp:e}"
        );
        let closing = |s: &BridgeSolution| s.summary.abutments[0].as_ref().unwrap().peak_closing;
        assert!(
            (closing(&uni) - closing(&moved)).abs() < 2e-3 * closing(&uni),
            "{law}: abutment closing {} vs {}",
            closing(&uni),
            closing(&moved)
        );
    }
}

/// A record set of support-motion files (`supports = "FILE"`, as `pounding motion svgm`
/// writes its manifest) runs in a batch: each row is the single run of the scenario naming the
/// file as `supports_y`, bit for bit; the entry's `x` is its start support's motion; an entry
/// with `x` beside `supports` is refused naming the key.
#[test]
fn support_motion_sets_run_in_batches() {
    use pounding::ground_motion::set::RecordSet;
    use pounding::sim::batch::{BatchRecord, BatchShard, run_batch};
    let rec = el_centro_1940().along_y.unwrap();
    let dir = tempfile::tempdir().unwrap();
    for (k, lag) in [(1, 20), (2, 45)] {
        let mut csv = String::from("t,start,joint1,end\n");
        for i in 0..=400 {
            let a = |j: i64| {
                if j < 1 {
                    0.0
                } else {
                    rec.accel(j as f64 * 0.01)
                }
            };
            let i = i as i64;
            csv += &format!(
                "{},{},{},{}\n",
                i as f64 * 0.01,
                a(i),
                a(i - lag),
                a(i - 2 * lag)
            );
        }
        std::fs::write(dir.path().join(format!("real_{k:04}.csv")), csv).unwrap();
    }
    let manifest = "[set]\nname = \"svgm\"\n\n[[record]]\nid = \"real_0001\"\nsupports = \
                    \"real_0001.csv\"\n\n[[record]]\nid = \"real_0002\"\nsupports = \
                    \"real_0002.csv\"\n";
    let set = RecordSet::from_toml(manifest, "manifest.toml", dir.path()).expect("reads");
    assert_eq!(set.records[1].supports.len(), 3);
    assert_eq!(set.records[1].x, set.records[1].supports[0].1);
    let base = Scenario::from_toml(
        &two_spans("record_y = \"builtin:ELC180\"\nrecord_x = \"none\"", 3.0),
        "b.toml",
    )
    .unwrap()
    .build_bridge()
    .unwrap();
    let rows = run_batch(
        &base.problem,
        &base.settings,
        &BatchRecord::of_set(&set),
        &[0.5],
        BatchShard::ALL,
        &|_| {},
    )
    .expect("runs");
    for (k, row) in rows.iter().enumerate() {
        let path = dir.path().join("s.toml");
        let file = format!("real_{:04}.csv", k + 1);
        std::fs::write(
            &path,
            two_spans(&format!("supports_y = \"{file}\"\nscale_y = 0.5"), 3.0),
        )
        .unwrap();
        let setup = Scenario::load(&path).unwrap().build_bridge().unwrap();
        let single = pounding::sim::simulate(&setup.problem, &setup.settings).unwrap();
        let out = row.outcome.as_ref().expect("a run");
        assert_eq!(out.summary, single.summary, "row {k}");
    }
    let bad = "[[record]]\nid = \"a\"\nx = \"builtin:ELC180\"\nsupports = \"real_0001.csv\"\n";
    let e = RecordSet::from_toml(bad, "m.toml", dir.path())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("record[0].supports") && e.contains("remove x"),
        "{e}"
    );
    let none = "[[record]]\nid = \"a\"\n";
    let e = RecordSet::from_toml(none, "m.toml", dir.path())
        .unwrap_err()
        .to_string();
    assert!(e.contains("give x") && e.contains("supports"), "{e}");
}
