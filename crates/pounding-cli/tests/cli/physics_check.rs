//! Issue 15 items 4 and 5 end to end: an ill-conditioned impact is reported as such with exit 1
//! (never `solved`), and a run whose energies overflow ends `Diverged` with exit 1 (single runs and
//! batch rows), with an energy balance error that never reads as 0.

use crate::pounding;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("phys", name)
}

fn disc(dir: &Path, inertia: &str) -> PathBuf {
    let p = dir.join(format!("disc-{inertia}.json"));
    std::fs::write(
        &p,
        format!(
            r#"{{"bodies": [{{"name": "disc", "mass": 2.0, "inertia": {inertia}, "position": [0, 0.3],
             "velocity": [1.0, -2.0], "omega": 40.0}}],
 "contacts": [{{"body_a": "disc", "body_b": null, "point": [0, 0], "normal": [0, 1],
               "mu": 0.2, "restitution": 0.5}}]}}"#
        ),
    )
    .unwrap();
    p
}

#[test]
fn tiny_inertia_impact_is_ill_conditioned_with_exit_1() {
    let d = tmp("disc");
    for (inertia, code, status) in [
        ("1e-18", 1, "ill-conditioned"),
        ("1e-100", 1, "ill-conditioned"),
        ("0.09", 0, "solved"),
    ] {
        let p = disc(&d, inertia);
        let o = pounding()
            .args(["impact", "--json", "--problem"])
            .arg(&p)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(code), "I = {inertia}");
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(v["status"], status, "I = {inertia}");
        // text form: same exit code, the violated law is named
        let o = pounding()
            .args(["impact", "--problem"])
            .arg(&p)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(code), "I = {inertia}");
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(
            out.contains("post-solve check failed"),
            code == 1,
            "I = {inertia}: {out}"
        );
    }
}

fn spike_csv(dir: &Path, g: &str) -> PathBuf {
    let p = dir.join("spike.csv");
    let mut s = String::from("t,a\n");
    for k in 0..50 {
        let a = if k == 3 { g } else { "0" };
        s.push_str(&format!("{:.2},{a}\n", k as f64 * 0.01));
    }
    std::fs::write(&p, s).unwrap();
    p
}

#[test]
fn overflowing_runs_end_diverged_with_exit_1() {
    let d = tmp("spike");
    let sc = d.join("s.toml");
    std::fs::write(&sc, "[time]\nduration = 0.3\ndt = 1e-3\n").unwrap();
    for (value, scale, code, status) in [
        ("1e300", "1", 1, "Diverged"),
        ("1", "1e200", 1, "Diverged"),
        ("0.3", "1", 0, "Completed"),
    ] {
        let rec = spike_csv(&d, value);
        let out = d.join(format!("out-{value}-{scale}"));
        let o = pounding()
            .arg("simulate")
            .arg(&sc)
            .arg("--record")
            .arg(&rec)
            .args(["--scale", scale, "--out"])
            .arg(&out)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(code), "{value} g × {scale}: {err}");
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap())
                .unwrap();
        assert_eq!(v["status"], status, "{value} g × {scale}");
        let e = &v["energy_balance_error"];
        assert!(
            e.is_null() || e.as_f64().unwrap() != 0.0 || code == 0,
            "{value} g × {scale}: balance error {e}"
        );
    }
    // batch: the diverged row is written, and the exit code is 1
    let recs = d.join("recs");
    std::fs::create_dir_all(&recs).unwrap();
    std::fs::copy(spike_csv(&d, "1"), recs.join("spike.csv")).unwrap();
    let out = d.join("batch");
    let o = pounding()
        .arg("simulate")
        .arg(&sc)
        .arg("--records")
        .arg(&recs)
        .args(["--scales", "0.3,1e300", "--threads", "1", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    let csv = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    assert!(
        csv.contains("Diverged") || csv.contains("diverged"),
        "{csv}"
    );
}
