//! `pounding lcp solve|bench` end to end.

use crate::pounding;
use pounding::lcp::io::parse_lcpsol;
use std::path::PathBuf;
use std::process::Output;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../pounding/tests/data")
        .join(name)
}

fn siconos(name: &str) -> Option<PathBuf> {
    let base = match std::env::var_os("POUNDING_SHARED") {
        Some(s) => PathBuf::from(s),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared"),
    };
    let p = base.join("data/lcp/siconos").join(name);
    if p.is_file() {
        Some(p)
    } else {
        crate::skipped(&format!("{} is absent", p.display()));
        None
    }
}

fn tmpdir(name: &str) -> crate::Scratch {
    crate::scratch_dir("cli-lcp", name)
}

fn run(args: &[&str]) -> Output {
    pounding().args(args).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn close(a: &[f64], b: &[f64]) -> bool {
    let s = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-9 * s)
}

#[test]
fn solve_sample_reproduces_references() {
    let dir = tmpdir("sample");
    let out = dir.join("sample.lcpsol");
    let input = data("lcp_problems_sample.txt");
    let refs = parse_lcpsol(
        &std::fs::read_to_string(data("lcp_solutions_sample.txt")).unwrap(),
        "ref",
    )
    .unwrap();
    for solver in ["lemke", "enum"] {
        let o = run(&[
            "lcp",
            "solve",
            input.to_str().unwrap(),
            "--solver",
            solver,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(o.stdout.is_empty());
        let err = stderr(&o);
        assert!(
            err.contains("36 problems") && err.contains("solved 36"),
            "{err}"
        );
        let text = std::fs::read_to_string(&out).unwrap();
        let sols = parse_lcpsol(&text, "out").unwrap();
        assert_eq!(sols.len(), 36, "{solver}: one solution per problem");
        for (k, s) in sols.iter().enumerate() {
            assert_eq!(s.id, k);
            assert_eq!(s.solver, format!("pounding-{solver}"));
            assert!(s.solved);
            for r in refs.iter().filter(|r| r.id == s.id) {
                assert!(
                    close(&s.z, &r.z),
                    "{solver} problem {k}: {:?} vs {:?}",
                    s.z,
                    r.z
                );
            }
        }
    }
}

#[test]
fn solve_writes_stdout_by_default() {
    let o = run(&[
        "lcp",
        "solve",
        data("lcp_problems_sample.txt").to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.starts_with("LCPSOL 1\n"));
    assert_eq!(text.lines().filter(|l| l.starts_with("SOL ")).count(), 36);
}

#[test]
fn solve_siconos_files() {
    let Some(cps3) = siconos("lcp_CPS_3.dat") else {
        return;
    };
    // Lemke: ray termination -> status 1, nan, written; exit 1 (a problem not solved)
    let o = run(&["lcp", "solve", cps3.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout.clone()).unwrap();
    assert!(
        text.contains("SOL 0 pounding-lemke 1 nan nan nan nan"),
        "{text}"
    );
    assert!(stderr(&o).contains("ray 1"), "{}", stderr(&o));
    // enumeration: the three solutions of the bimatrix game
    let o = run(&["lcp", "solve", cps3.to_str().unwrap(), "--solver", "enum"]);
    assert!(o.status.success());
    let sols = parse_lcpsol(&String::from_utf8(o.stdout).unwrap(), "out").unwrap();
    assert_eq!(sols.len(), 3);
    for want in [
        [0.1, 0.0, 0.1, 0.0],
        [0.0, 1.0 / 15.0, 0.0, 1.0 / 15.0],
        [1.0 / 90.0, 2.0 / 45.0, 1.0 / 90.0, 2.0 / 45.0],
    ] {
        assert!(sols.iter().any(|s| close(&s.z, &want)), "{want:?} missing");
    }
    // an n = 26 problem: fine for Lemke, an error for enumeration
    let Some(mmc) = siconos("lcp_mmc.dat") else {
        return;
    };
    let o = run(&["lcp", "solve", mmc.to_str().unwrap()]);
    assert!(o.status.success() && stderr(&o).contains("solved 1"));
    let o = run(&["lcp", "solve", mmc.to_str().unwrap(), "--solver", "enum"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("n <= 12"), "{}", stderr(&o));
}

#[test]
fn bench_prints_json_per_class() {
    let o = run(&[
        "lcp",
        "bench",
        data("lcp_problems_sample.txt").to_str().unwrap(),
        "--min-time",
        "0.01",
        "--repeats",
        "1",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let classes = v["classes"].as_array().unwrap();
    let got: Vec<(&str, u64, u64)> = classes
        .iter()
        .map(|c| {
            (
                c["class"].as_str().unwrap(),
                c["count"].as_u64().unwrap(),
                c["solved"].as_u64().unwrap(),
            )
        })
        .collect();
    assert_eq!(got, [("impact3", 20, 20), ("p6", 10, 10), ("p12", 6, 6)]);
    for c in classes {
        assert!(c["solves_per_s"].as_f64().unwrap() > 0.0);
        assert!(c["max_residual"].as_f64().unwrap() <= 1e-9);
    }
    let o = run(&["lcp", "bench", "x", "--min-time", "0"]);
    assert!(!o.status.success() && stderr(&o).contains("--min-time"));
}

#[test]
fn bad_input_fails_cleanly() {
    let d = tmpdir("bad");
    let cases: &[(&str, &str, &str)] = &[
        ("empty.dat", "", "end of file"),
        ("nan.dat", "2\n0\n2\n2\n2 2\n1 0\n0 NaN\n-1 -1\n", "finite"),
        (
            "inf.txt",
            "LCPSET 1\nCOUNT 1\nPROBLEM 0 p6 1\nPARAMS 0\nM inf\nq -1\n",
            "finite",
        ),
        (
            "nonsquare.dat",
            "2\n0\n2\n3\n2 3\n1 0 0 1 0 0\n-1 -1\n",
            "square",
        ),
        (
            "count.txt",
            "LCPSET 1\nCOUNT 2\nPROBLEM 0 p6 1\nPARAMS 0\nM 1\nq -1\n",
            "PROBLEM 1",
        ),
        (
            "mcount.txt",
            "LCPSET 1\nCOUNT 1\nPROBLEM 0 p6 2\nPARAMS 0\nM 1 2 3\nq -1 -1\n",
            "n*n = 4",
        ),
    ];
    for (name, text, want) in cases {
        let p = d.join(name);
        std::fs::write(&p, text).unwrap();
        for sub in ["solve", "bench"] {
            let o = run(&["lcp", sub, p.to_str().unwrap()]);
            let e = stderr(&o);
            assert_eq!(o.status.code(), Some(2), "{name} {sub}: {e}");
            assert!(
                e.contains("error:") && e.contains(name) && e.contains(want),
                "{name}: {e}"
            );
            assert!(!e.contains("panicked"), "{e}");
        }
    }
    // no problems: solve and bench both refuse (bad input)
    let p = d.join("zero.txt");
    std::fs::write(&p, "LCPSET 1\nCOUNT 0\n").unwrap();
    for sub in ["solve", "bench"] {
        let o = run(&["lcp", sub, p.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{sub}");
        assert!(stderr(&o).contains("no problems"), "{}", stderr(&o));
        assert!(o.stdout.is_empty());
    }
    // a directory and a missing file
    for p in [d.to_str().unwrap(), "/nonexistent/x.dat"] {
        let o = run(&["lcp", "solve", p]);
        assert_eq!(o.status.code(), Some(2));
        assert!(stderr(&o).contains("cannot read"), "{}", stderr(&o));
    }
    // an unknown solver is a usage error
    let o = run(&["lcp", "solve", "x", "--solver", "pgs"]);
    assert!(!o.status.success());
}
