//! Fuzzing regressions: every input the fuzzers ever crashed on (`fuzz/regressions/TARGET/`) and
//! every seed (`fuzz/corpus/TARGET/`) replayed through the fuzz targets' own bodies and oracles
//! (`fuzz/src/lib.rs`, included here), without libFuzzer. See `fuzz/run.sh` for the fuzzers.

use pounding::lcp::io;
use std::path::PathBuf;

#[allow(dead_code)]
#[path = "../../../../fuzz/src/lib.rs"]
pub(crate) mod oracle;

fn inputs(kind: &str, target: &str) -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../fuzz")
        .join(kind)
        .join(target);
    let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|d| d.map(|e| e.unwrap().path()).collect())
        .unwrap_or_default();
    v.sort();
    v
}

fn replay(target: &str, f: fn(&[u8])) {
    let (reg, seeds) = (inputs("regressions", target), inputs("corpus", target));
    assert!(!seeds.is_empty(), "no seed corpus for {target}");
    for p in reg.iter().chain(&seeds) {
        let data = std::fs::read(p).unwrap();
        // a panic here names the input file
        let r = std::panic::catch_unwind(|| f(&data));
        assert!(r.is_ok(), "fuzz target {target} fails on {}", p.display());
    }
}

#[test]
fn fuzz_replay_lcp_io() {
    replay("lcp_io", oracle::lcp_io);
}

#[test]
fn fuzz_replay_lcp_solve() {
    replay("lcp_solve", oracle::lcp_solve);
}

#[test]
fn fuzz_replay_record() {
    replay("record", oracle::record);
}

#[test]
fn fuzz_replay_study_toml() {
    replay("study_toml", oracle::study_toml);
}

#[test]
fn fuzz_replay_sim_model() {
    replay("sim_model", oracle::sim_model);
}

/// Found by `lcp_io`: a failed `SOL` record (status 1) kept whatever numbers followed it, so the
/// writer (which writes `nan` for every failed entry) and the reader disagreed. A failed record now
/// reads as all NaN, as documented, and round-trips.
#[test]
fn lcpsol_failed_record_reads_as_nan() {
    let text = "LCPSOL 1\nSOL 0 lemke 1 0.427 0.0 5\nSOL 1 lemke 0 0.5 0\n";
    let sols = io::parse_lcpsol(text, "x").unwrap();
    assert!(!sols[0].solved);
    assert_eq!(sols[0].z.len(), 3);
    assert!(sols[0].z.iter().all(|z| z.is_nan()), "{:?}", sols[0].z);
    assert_eq!(sols[1].z, vec![0.5, 0.0]);
    let again = io::parse_lcpsol(&io::write_lcpsol(&sols), "again").unwrap();
    assert!(again[0].z.iter().all(|z| z.is_nan()) && again[1].z == sols[1].z);
}

/// The LCP oracle itself must reject a wrong `Solved` (else the fuzzers prove nothing): `z = 0`
/// for `q = (−1)` leaves `w = −1 < 0`; `z = (1)` for `M = (1), q = (0)` breaks complementarity.
#[test]
fn fuzz_lcp_oracle_rejects_wrong_solutions() {
    use pounding::lcp::{LcpProblem, LcpStatus};
    // The oracle panics on a wrong solution (a crash for libFuzzer); with `--nocapture` the
    // panic message is printed, so it is announced as expected.
    let rejects = |p: &LcpProblem, z: &[f64]| {
        eprintln!("EXPECTED: the LCP oracle rejects z = {z:?}; its panic message follows");
        std::panic::catch_unwind(|| oracle::check_lcp(p, LcpStatus::Solved, z)).is_err()
    };
    let p = LcpProblem::new(vec![1.0], vec![-1.0]).unwrap();
    assert!(rejects(&p, &[0.0]));
    oracle::check_lcp(&p, LcpStatus::Solved, &[1.0]);
    oracle::check_lcp(&p, LcpStatus::RayTermination, &[f64::NAN]);
    let p = LcpProblem::new(vec![1.0], vec![0.0]).unwrap();
    assert!(rejects(&p, &[1.0]));
    assert!(rejects(&p, &[-1e-3]));
}

/// Found by `impact_json`: one contact on a body of mass 7.2e117 kg and moment of inertia 2 with
/// μ = 6e43. Lemke and enumeration fail, and the closed-form fallback returned `Λ_N = −8.6e15`
/// (the Delassus determinant is lost to rounding) as `solved-by-fallback`. A negative normal
/// impulse is no solution: the impact is now `failed`. The same guard covers `solve_single`.
#[test]
fn impact_fallback_never_reports_a_negative_normal_impulse() {
    use pounding::impact::{ContactSpec, ImpactProblem, ImpactSettings, ImpactStatus, RigidBody};
    use pounding::math::Vector;
    let p = ImpactProblem::new(
        vec![RigidBody {
            name: "rod".into(),
            mass: 7.222222222222222e117,
            inertia: 2.0,
            position: Vector::new(2.0, 0.5),
            velocity: Vector::new(0.0, 0.0),
            omega: 1.0,
        }],
        vec![ContactSpec {
            body_a: "rod".into(),
            body_b: None,
            point: Vector::new(1.0, 0.0),
            normal: Vector::new(1.0, 1.0),
            mu: 5.99e43,
            restitution: 0.3,
        }],
    )
    .unwrap();
    let s = pounding::impact::solve(&p, &ImpactSettings::default());
    match s.status {
        ImpactStatus::Solved | ImpactStatus::SolvedByFallback => {
            let c = &s.contacts[0];
            assert!(c.normal_impulse >= 0.0, "{s:?}");
            oracle::check_impact(&p, &s);
        }
        ImpactStatus::NoImpact => panic!("the contact approaches: {s:?}"),
        _ => {}
    }
}

/// Issue 15 item 3, kept as a fuzz regression (`fuzz/regressions/study_toml/`): `ratio_min =
/// −1e308, ratio_max = 1e308` has an infinite width, which made every share 0 with a successful
/// run. It is now refused as bad input naming `grid.ratio_max` and its line.
#[test]
fn study_ratio_range_of_infinite_width_is_refused() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../fuzz/regressions/study_toml/ratio-range-infinite-width.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let e = pounding::study::Scenario::from_toml(&text, "wide.toml").unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("wide.toml: line 16")
            && msg.contains("grid.ratio_max")
            && msg.contains("finite"),
        "{msg}"
    );
    // a wide width within the documented limit (1e12) is still accepted
    let ok = text
        .replace("ratio_min = -1e308", "ratio_min = -5e11")
        .replace("ratio_max = 1e308", "ratio_max = 5e11");
    assert!(pounding::study::Scenario::from_toml(&ok, "x").is_ok());
}

/// Found by `lcp_solve` (`fuzz/regressions/lcp_solve/complementarity-1`): enumeration reported
/// `z = (0, 1.3e-3, 0, 0, 0)` for a problem with `q ≥ 0`, although `w₁ = 0.162` beside `z₁ > 0`.
/// The verification had set `z₁` aside as rounding noise (it is negligible in every row with
/// other content: `M₁₁ = 1e−299`, `q₂ = 1e18`) — but it is the only content of rows 0 and 4 — and
/// then reported the unverified `z`. The verified vector (noise entries at 0) is now reported.
#[test]
fn lcp_verified_solution_is_the_one_reported() {
    use pounding::lcp::{self, LcpProblem, LcpStatus, Lemke, LemkeSettings};
    #[rustfmt::skip]
    let m = vec![
        0.13, 0.241, 7.8125, 8.1875e20, -4.25,
        66.0, 1.1116129922346925e-299, 0.12, -0.8125, 2.0625e-40,
        1.000000000118, 0.5, 0.875, 6.3125, 0.0,
        0.999999999961, 0.0, 0.0, 0.0, 0.0,
        0.999999999872, -5.8125, 0.0, 0.0, 0.0,
    ];
    let q = vec![0.0, 0.162, 1e18, 2.46657e-319, 0.0];
    let p = LcpProblem::new(m, q).unwrap();
    let sols = lcp::enumerate(&p).unwrap();
    assert!(!sols.is_empty());
    for z in &sols {
        oracle::check_lcp(&p, LcpStatus::Solved, z);
    }
    assert!(sols.iter().any(|z| z.iter().all(|&x| x == 0.0)), "{sols:?}");
    let s = Lemke::new(LemkeSettings::default()).solve(&p);
    oracle::check_lcp(&p, s.status, &s.z);
}
