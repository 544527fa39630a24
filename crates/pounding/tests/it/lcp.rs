//! LCP solvers against independent evidence: the 20 Siconos files with exact rational reference
//! solutions, the `LCPSET` sample with two independent solvers' solutions, brute-force enumeration
//! vs Lemke on random P-matrix and impact LCPs, the closed-form single-impact solution, bad input.

use crate::common::shared_dir;
use pounding::lcp::io::{self, LcpIoError};
use pounding::lcp::{
    LcpProblem, LcpStatus, Lemke, LemkeSettings, enumerate, enumerate_with, solve_fixed,
};
use proptest::prelude::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Independent check of all LCP conditions (not the library's own verification), relative to
/// `max(1, ‖q‖∞, ‖M‖∞‖z‖∞)` (the rounding scale of `M z + q`).
fn check_lcp(p: &LcpProblem, z: &[f64], tol: f64) -> Result<(), String> {
    let n = p.dim();
    let mnorm = (0..n)
        .map(|i| (0..n).map(|j| p.m(i, j).abs()).sum::<f64>())
        .fold(0.0f64, f64::max);
    let qn = p
        .q()
        .iter()
        .fold(1.0f64, |a, &x| a.max(x.abs()))
        .max(mnorm * inf_norm(z));
    for i in 0..n {
        let w: f64 = p.q()[i] + (0..n).map(|j| p.m(i, j) * z[j]).sum::<f64>();
        let ok = z[i] >= -tol * qn && w >= -tol * qn && z[i].min(w).abs() <= tol * qn;
        if !ok {
            return Err(format!("row {i}: z = {}, w = {w}", z[i]));
        }
    }
    Ok(())
}

fn inf_norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |a, &x| a.max(x.abs()))
}

fn close(a: &[f64], b: &[f64], rel: f64) -> bool {
    let s = inf_norm(b).max(1.0);
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= rel * s)
}

// ---------------------------------------------------------------------------------------------
// Siconos collection

/// A value of `reference_solutions.txt`: an integer, a rational `a/b` or a decimal.
fn parse_value(s: &str) -> f64 {
    match s.split_once('/') {
        Some((a, b)) => a.trim().parse::<f64>().unwrap() / b.trim().parse::<f64>().unwrap(),
        None => s.trim().parse::<f64>().unwrap(),
    }
}

fn parse_vec(s: &str) -> Vec<f64> {
    let s = s.trim();
    let inner = s.strip_prefix('[').unwrap().strip_suffix(']').unwrap();
    inner.split(',').map(parse_value).collect()
}

#[derive(Debug, Default)]
struct Reference {
    ray: bool,
    pivots: usize,
    z: Option<Vec<f64>>,
    basic: Vec<Vec<f64>>,
    enumerated: bool,
}

/// Parses the LCP part of `reference_solutions.txt`.
fn parse_references(text: &str) -> BTreeMap<String, Reference> {
    let mut out = BTreeMap::new();
    let mut current: Option<String> = None;
    for line in text.lines() {
        if line.starts_with("# Output of") {
            break;
        }
        if line.starts_with("lcp_") {
            let (name, rest) = line.split_once(": ").unwrap();
            let mut r = Reference::default();
            for tok in rest.split_whitespace() {
                if let Some(v) = tok.strip_prefix("lemke_lex=") {
                    r.ray = v == "ray";
                }
                if let Some(v) = tok.strip_prefix("pivots=") {
                    r.pivots = v.parse().unwrap();
                }
            }
            if let Some((_, z)) = rest.split_once("z=") {
                r.z = Some(parse_vec(z));
            }
            out.insert(name.to_string(), r);
            current = Some(name.to_string());
        } else if line.trim_start().starts_with("enumeration:") {
            out.get_mut(current.as_ref().unwrap()).unwrap().enumerated = true;
        } else if let Some(z) = line.trim_start().strip_prefix("z=") {
            out.get_mut(current.as_ref().unwrap())
                .unwrap()
                .basic
                .push(parse_vec(z));
        }
    }
    out
}

fn siconos_dir() -> Option<PathBuf> {
    let d = shared_dir()?.join("data/lcp/siconos");
    if d.is_dir() {
        Some(d)
    } else {
        crate::common::skipped(&format!("{} is absent", d.display()));
        None
    }
}

fn siconos_files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "dat"))
        .collect();
    v.sort();
    v
}

#[test]
fn siconos_all_twenty_lemke() {
    let Some(dir) = siconos_dir() else { return };
    let refs =
        parse_references(&std::fs::read_to_string(dir.join("reference_solutions.txt")).unwrap());
    let files = siconos_files(&dir);
    assert_eq!(files.len(), 20, "expected the 20 Siconos LCP files");
    let mut lemke = Lemke::new(LemkeSettings::default());
    for f in &files {
        let name = f.file_name().unwrap().to_str().unwrap();
        let p = io::read_siconos(f).unwrap_or_else(|e| panic!("{e}"));
        let r = &refs[name];
        let sol = lemke.solve(&p);
        let expect_ray = matches!(
            name,
            "lcp_CPS_3.dat" | "lcp_Pang_isolated_sol_perturbed.dat"
        );
        assert_eq!(r.ray, expect_ray, "reference file disagrees on {name}");
        if expect_ray {
            assert_eq!(sol.status, LcpStatus::RayTermination, "{name}: {sol:?}");
            assert!(sol.z.iter().all(|x| x.is_nan()), "{name}: z must be NaN");
            continue;
        }
        assert_eq!(sol.status, LcpStatus::Solved, "{name}: {sol:?}");
        check_lcp(&p, &sol.z, 1e-9).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(sol.residual <= 1e-9, "{name}: residual {}", sol.residual);
        // the lexicographic pivot sequence is unique, so the count matches the exact run
        assert_eq!(sol.pivots, r.pivots, "{name}: pivot count");
        let zref = r.z.as_ref().unwrap();
        let unique = !r.enumerated || r.basic.len() == 1;
        if unique {
            let s = inf_norm(zref).max(1.0);
            for (a, b) in sol.z.iter().zip(zref) {
                assert!(
                    (a - b).abs() <= 1e-9 * s,
                    "{name}: z = {:?}, ref {zref:?}",
                    sol.z
                );
            }
        }
    }
}

#[test]
fn siconos_exp_murty2_takes_64_pivots() {
    let Some(dir) = siconos_dir() else { return };
    let p = io::read_siconos(&dir.join("lcp_exp_murty2.dat")).unwrap();
    let sol = Lemke::new(LemkeSettings::default()).solve(&p);
    assert_eq!(sol.status, LcpStatus::Solved);
    assert_eq!(sol.pivots, 64);
    assert_eq!(sol.z, vec![0.0, 0.0, 0.0, 0.0, 0.0, 64.0]);
    // the same through the fixed-size kernel
    let mut m = [[0.0; 6]; 6];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = p.m(i, j);
        }
    }
    let q: [f64; 6] = p.q().try_into().unwrap();
    let f = solve_fixed(&m, &q, &LemkeSettings::default());
    assert_eq!((f.status, f.pivots), (LcpStatus::Solved, 64));
    // a pivot limit below 64 is reported as such
    let s = LemkeSettings::default().with_max_pivots(63).unwrap();
    let f = solve_fixed(&m, &q, &s);
    assert_eq!(f.status, LcpStatus::MaxPivots);
}

#[test]
fn siconos_enumeration_finds_every_basic_solution() {
    let Some(dir) = siconos_dir() else { return };
    let refs =
        parse_references(&std::fs::read_to_string(dir.join("reference_solutions.txt")).unwrap());
    let mut checked = 0;
    for f in siconos_files(&dir) {
        let name = f.file_name().unwrap().to_str().unwrap();
        let p = io::read_siconos(&f).unwrap();
        let r = &refs[name];
        let sols = enumerate(&p);
        if p.dim() > 12 {
            assert!(sols.is_err(), "{name}: n > 12 must be an error");
            continue;
        }
        let sols = sols.unwrap();
        assert!(r.enumerated, "{name}");
        for s in &sols {
            check_lcp(&p, s, 1e-9).unwrap_or_else(|e| panic!("{name}: {e}"));
        }
        for b in &r.basic {
            assert!(
                sols.iter().any(|s| close(s, b, 1e-9)),
                "{name}: basic solution {b:?} not found in {sols:?}"
            );
        }
        assert_eq!(sols.len(), r.basic.len(), "{name}: {sols:?}");
        checked += 1;
    }
    assert_eq!(checked, 18);
    let cps3 = io::read_siconos(&dir.join("lcp_CPS_3.dat")).unwrap();
    assert_eq!(enumerate(&cps3).unwrap().len(), 3);
    let cps1 = io::read_siconos(&dir.join("lcp_CPS_1.dat")).unwrap();
    assert_eq!(enumerate(&cps1).unwrap().len(), 2);
}

#[test]
fn siconos_block_storage_equals_dense() {
    let Some(dir) = siconos_dir() else { return };
    for base in ["deudeu", "ortiz", "trivial"] {
        let a = io::read_siconos(&dir.join(format!("lcp_{base}.dat"))).unwrap();
        let b = io::read_siconos(&dir.join(format!("lcp_{base}_block.dat"))).unwrap();
        assert_eq!(a, b, "{base}");
    }
    // column-major: CPS_2 prints the columns of M = [[0,-1,2],[2,0,-2],[-1,1,0]]
    let p = io::read_siconos(&dir.join("lcp_CPS_2.dat")).unwrap();
    assert_eq!(
        p.m_row_major(),
        &[0.0, -1.0, 2.0, 2.0, 0.0, -2.0, -1.0, 1.0, 0.0]
    );
}

// ---------------------------------------------------------------------------------------------
// LCPSET sample

fn data_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

#[test]
fn lcpset_sample_reproduced_by_both_solvers() {
    let dir = data_dir();
    let set = io::read_lcpset(&dir.join("lcp_problems_sample.txt")).unwrap();
    assert_eq!(set.len(), 36);
    let text = std::fs::read_to_string(dir.join("lcp_solutions_sample.txt")).unwrap();
    let refs = io::parse_lcpsol(&text, "lcp_solutions_sample.txt").unwrap();
    let mut lemke = Lemke::new(LemkeSettings::default());
    let mut compared = 0;
    for e in &set {
        let rs: Vec<_> = refs.iter().filter(|r| r.id == e.id).collect();
        // impact3 and p6 have two reference solvers, p12 one (lemkelcp)
        assert!(!rs.is_empty(), "problem {}: no reference solution", e.id);
        let sol = lemke.solve(&e.problem);
        assert_eq!(sol.status, LcpStatus::Solved, "problem {}", e.id);
        let en = enumerate(&e.problem).unwrap();
        assert_eq!(en.len(), 1, "problem {}: unique solution, got {en:?}", e.id);
        for r in rs {
            assert!(r.solved);
            assert!(
                close(&sol.z, &r.z, 1e-9),
                "lemke {} vs {}: {:?} {:?}",
                e.id,
                r.solver,
                sol.z,
                r.z
            );
            assert!(close(&en[0], &r.z, 1e-9), "enum {} vs {}", e.id, r.solver);
            compared += 1;
        }
    }
    assert_eq!(compared, refs.len());
    assert_eq!(compared, 66);
    // the class mix of the README
    let count = |c: &str| set.iter().filter(|e| e.class == c).count();
    assert_eq!((count("impact3"), count("p6"), count("p12")), (20, 10, 6));
}

#[test]
fn lcpsol_round_trip() {
    let recs = vec![
        io::SolRecord {
            id: 3,
            solver: "pounding-lemke".into(),
            solved: true,
            z: vec![0.1, 0.0, 1e-7],
        },
        io::SolRecord {
            id: 4,
            solver: "pounding-lemke".into(),
            solved: false,
            z: vec![1.0, 2.0],
        },
    ];
    let s = io::write_lcpsol(&recs);
    assert!(s.starts_with("LCPSOL 1\n"));
    assert!(s.contains("SOL 4 pounding-lemke 1 nan nan\n"), "{s}");
    let back = io::parse_lcpsol(&s, "x").unwrap();
    assert_eq!(back[0], recs[0]);
    assert!(!back[1].solved && back[1].z.iter().all(|x| x.is_nan()));
}

// ---------------------------------------------------------------------------------------------
// Hand-checkable cases

#[test]
fn trivial_shortcut_and_degenerate_ties() {
    let mut l = Lemke::new(LemkeSettings::default());
    // q >= 0: z = 0 without pivoting
    let p = LcpProblem::new(vec![1.0, 2.0, 3.0, 4.0], vec![0.0, 1.0]).unwrap();
    let s = l.solve(&p);
    assert_eq!(
        (s.status, s.pivots, s.z.clone()),
        (LcpStatus::Solved, 0, vec![0.0, 0.0])
    );
    // identity with equal q: every initial ratio ties (degenerate); z = -q
    let p = LcpProblem::new(
        vec![1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
        vec![-2.0; 3],
    )
    .unwrap();
    for _ in 0..2 {
        let s = l.solve(&p);
        assert_eq!(s.status, LcpStatus::Solved);
        assert_eq!(s.z, vec![2.0; 3]);
    }
    // a 5x5 identity goes through the dynamic (non-specialised) kernel
    let mut m = vec![0.0; 25];
    for i in 0..5 {
        m[i * 6] = 1.0;
    }
    let p = LcpProblem::new(m, vec![-1.0, -1.0, -1.0, -1.0, -1.0]).unwrap();
    let s = l.solve(&p);
    assert_eq!((s.status, s.z.clone()), (LcpStatus::Solved, vec![1.0; 5]));
}

#[test]
fn settings_are_validated() {
    assert!(LemkeSettings::default().with_pivot_tol(f64::NAN).is_err());
    assert!(LemkeSettings::default().with_pivot_tol(-1.0).is_err());
    assert!(LemkeSettings::default().with_tie_tol(0.5).is_err());
    assert!(
        LemkeSettings::default()
            .with_verify_tol(f64::INFINITY)
            .is_err()
    );
    let e = LemkeSettings::new(10, 1e-12, 1e-11, 2.0).unwrap_err();
    assert!(e.to_string().contains("verify_tol"), "{e}");
    let s = LemkeSettings::new(10, 1e-10, 1e-10, 1e-8).unwrap();
    assert_eq!(s.max_pivots(), 10);
    let big = LcpProblem::new(vec![1.0; 169], vec![-1.0; 13]).unwrap();
    assert!(enumerate(&big).is_err());
    let bad = pounding::lcp::EnumSettings {
        verify_tol: f64::NAN,
        ..Default::default()
    };
    let p = LcpProblem::new(vec![1.0], vec![-1.0]).unwrap();
    assert!(enumerate_with(&p, &bad).is_err());
}

#[test]
fn fixed_kernel_rejects_non_finite_without_panic() {
    let m = [[1.0, 0.0], [0.0, f64::NAN]];
    let f = solve_fixed(&m, &[-1.0, -1.0], &LemkeSettings::default());
    assert_ne!(f.status, LcpStatus::Solved);
    let f = solve_fixed(&[[1.0]], &[f64::NAN], &LemkeSettings::default());
    assert_eq!(f.status, LcpStatus::IllConditioned);
    let f = solve_fixed(
        &[[1e308, 0.0], [0.0, 1e308]],
        &[-1e308, -1e308],
        &LemkeSettings::default(),
    );
    assert!(
        f.status != LcpStatus::Solved
            || check_lcp(
                &LcpProblem::new(vec![1e308, 0.0, 0.0, 1e308], vec![-1e308, -1e308]).unwrap(),
                &f.z,
                1e-9
            )
            .is_ok()
    );
}

// ---------------------------------------------------------------------------------------------
// Bad input

fn parse_err(text: &str) -> String {
    let dir = crate::scratch::scratch_dir("lcp-it", "bad");
    let p = dir.join("bad.txt");
    std::fs::write(&p, text).unwrap();
    match io::read_any(&p) {
        Ok(v) => panic!("accepted bad input {text:?}: {v:?}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_files_give_clear_errors() {
    // Siconos: NaN, inf, non-square, too few numbers, bad storage type, empty
    let e = parse_err("2\n0\n2\n2\n2 2\n1 0\n0 nan\n-1 -1\n");
    assert!(
        e.contains(":7:") && e.contains("finite") && e.contains("nan"),
        "{e}"
    );
    let e = parse_err("2\n0\n2\n2\n2 2\n1 0\n0 1\n-1 inf\n");
    assert!(e.contains(":8:") && e.contains("q[1]"), "{e}");
    let e = parse_err("2\n0\n2\n3\n2 3\n1 0 0\n0 1 0\n-1 -1\n");
    assert!(e.contains("square"), "{e}");
    let e = parse_err("2\n0\n2\n2\n2 2\n1 0\n0 1\n-1\n");
    assert!(e.contains("q[1]") && e.contains("end of file"), "{e}");
    let e = parse_err("2\n7\n2\n2\n");
    assert!(e.contains("storage type"), "{e}");
    let e = parse_err("");
    assert!(
        e.contains("problem size") && e.contains("end of file"),
        "{e}"
    );
    // LCPSET: wrong counts, NaN, truncated, extra problems
    let head = "LCPSET 1\nCOUNT 1\nPROBLEM 0 p6 2\nPARAMS 0\n";
    let e = parse_err(&format!("{head}M 1 0 0\nq -1 -1\n"));
    assert!(e.contains(":5:") && e.contains("n*n = 4"), "{e}");
    let e = parse_err(&format!("{head}M 1 0 0 1\nq -1 NaN\n"));
    assert!(e.contains(":6:") && e.contains("finite"), "{e}");
    let e = parse_err(&format!("{head}M 1 0 0 1\nq -1\n"));
    assert!(e.contains("n = 2 entries of q"), "{e}");
    let e = parse_err("LCPSET 1\nCOUNT 2\nPROBLEM 0 p6 1\nPARAMS 0\nM 1\nq -1\n");
    assert!(e.contains("PROBLEM 1") && e.contains("end of file"), "{e}");
    let e = parse_err("LCPSET 1\nCOUNT 1\nPROBLEM 0 p6 1\nPARAMS 2 1\nM 1\nq -1\n");
    assert!(e.contains("2 PARAMS values"), "{e}");
    // absurd sizes are refused before anything is allocated
    let e = parse_err("LCPSET 1\nCOUNT 999999999999999999\n");
    assert!(e.contains("PROBLEM 0") && e.contains("end of file"), "{e}");
    let e = parse_err("2\n1\n2\n2\n999999999999\n1\n1\n2\n2\n");
    assert!(e.contains("nbblocks"), "{e}");
    let e = parse_err("99999999999\n0\n99999999999\n99999999999\n");
    assert!(e.contains(":1:") && e.contains("4096"), "{e}");
    let e = parse_err("LCPSET 1\nCOUNT 1\nPROBLEM 0 p6 4294967297\nPARAMS 0\nM 1\nq 1\n");
    assert!(e.contains(":3:") && e.contains("4096"), "{e}");
    let e = parse_err("LCPSET 1\nCOUNT 0\nPROBLEM 0 p6 1\n");
    assert!(e.contains("end of file after COUNT"), "{e}");
    // a directory
    let d = std::env::temp_dir();
    match io::read_any(&d) {
        Err(e @ LcpIoError::Io { .. }) => assert!(e.to_string().contains("directory"), "{e}"),
        other => panic!("{other:?}"),
    }
    assert!(io::read_any(Path::new("/nonexistent/file.dat")).is_err());
    // the problem constructor itself
    assert!(LcpProblem::new(vec![1.0, 2.0, 3.0], vec![1.0, 2.0]).is_err());
    assert!(LcpProblem::new(vec![], vec![]).is_err());
    assert!(LcpProblem::new(vec![f64::INFINITY], vec![1.0]).is_err());
}

// ---------------------------------------------------------------------------------------------
// Property tests

/// A random P-matrix of one of three kinds (every principal minor positive in each case):
/// 0: `A Aᵀ + δ I + S` with `S` skew-symmetric (positive definite, hence P);
/// 1: triangular with a positive diagonal (principal minors = products of diagonal entries);
/// 2: strictly row-diagonally dominant with a positive diagonal (nonsymmetric in general).
fn p_matrix(kind: u8, n: usize, a: &[f64], skew: &[f64], delta: f64) -> Vec<f64> {
    let mut m = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            m[i * n + j] = match kind {
                0 => {
                    let mut s: f64 = (0..n).map(|k| a[i * n + k] * a[j * n + k]).sum();
                    if i == j {
                        s += delta;
                    } else if i < j {
                        s += skew[i * n + j];
                    } else {
                        s -= skew[j * n + i];
                    }
                    s
                }
                1 => match i.cmp(&j) {
                    std::cmp::Ordering::Equal => delta + a[i * n + i].abs(),
                    std::cmp::Ordering::Less => 3.0 * skew[i * n + j],
                    std::cmp::Ordering::Greater => 0.0,
                },
                _ => {
                    if i == j {
                        0.0
                    } else {
                        a[i * n + j]
                    }
                }
            };
        }
        if kind >= 2 {
            let off: f64 = (0..n).map(|j| m[i * n + j].abs()).sum();
            m[i * n + i] = off + delta;
        }
    }
    m
}

fn p_lcp() -> impl Strategy<Value = LcpProblem> {
    (2usize..=12, 0u8..3).prop_flat_map(|(n, kind)| {
        (
            prop::collection::vec(-1.0f64..1.0, n * n),
            prop::collection::vec(-1.0f64..1.0, n * n),
            prop::collection::vec(-1.0f64..1.0, n),
            0.05f64..1.0,
        )
            .prop_map(move |(a, s, q, d)| LcpProblem::new(p_matrix(kind, n, &a, &s, d), q).unwrap())
    })
}

/// The `impact3` LCP of the issue (spec §8, one contact) with `G = [[Gnn, Gnt], [Gnt, Gtt]]`.
fn impact3(mu: f64, eps: f64, gn: f64, gt: f64, g: [f64; 3]) -> LcpProblem {
    let [gnn, gnt, gtt] = g;
    LcpProblem::new(
        vec![
            gnn - mu * gnt,
            gnt,
            0.0,
            gnt - mu * gtt,
            gtt,
            1.0,
            2.0 * mu,
            -1.0,
            0.0,
        ],
        vec![(1.0 + eps) * gn, gt, 0.0],
    )
    .unwrap()
}

/// A random SPD 2x2 `G` from a lower-triangular factor.
fn spd() -> impl Strategy<Value = [f64; 3]> {
    (0.1f64..2.0, -2.0f64..2.0, 0.1f64..2.0).prop_map(|(a, b, c)| [a * a, a * b, b * b + c * c])
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn p_matrix_lemke_equals_enumeration(p in p_lcp()) {
        let sol = Lemke::new(LemkeSettings::default()).solve(&p);
        prop_assert_eq!(sol.status, LcpStatus::Solved);
        prop_assert!(check_lcp(&p, &sol.z, 1e-9).is_ok());
        let en = enumerate(&p).unwrap();
        prop_assert_eq!(en.len(), 1, "P-matrix LCP has exactly one solution: {:?}", en);
        prop_assert!(close(&sol.z, &en[0], 1e-8), "{:?} vs {:?}", sol.z, en[0]);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn impact3_regular_is_solved(mu in 0.0f64..=1.0, eps in 0.0f64..=1.0,
                                 gn in -3.0f64..-0.01, gt in -3.0f64..3.0, g in spd()) {
        let p = impact3(mu, eps, gn, gt, g);
        let m: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| p.m(i, j)));
        let q: [f64; 3] = p.q().try_into().unwrap();
        let f = solve_fixed(&m, &q, &LemkeSettings::default());
        // μ ≤ 1 includes Painlevé-type cases (μ|G_NT| ≥ G_NN when |G_NT| > G_NN): Lemke solved
        // all of 2·10⁶ random ones while developing; spec §9 allows a ray only for μ > 1 here.
        prop_assert_eq!(f.status, LcpStatus::Solved);
        if f.status == LcpStatus::Solved {
            prop_assert!(check_lcp(&p, &f.z, 1e-9).is_ok());
            // physical quantities against the analytic single-impact solution (spec §9)
            let (ln, lt, gtp) = physical(&p, &f.z, mu);
            let (an, at, agt) = analytic(mu, eps, gn, gt, g);
            let s = an.abs().max(1.0);
            prop_assert!((ln - an).abs() <= 1e-8 * s, "Λ_N {} vs {}", ln, an);
            prop_assert!((lt - at).abs() <= 1e-8 * s, "Λ_T {} vs {}", lt, at);
            prop_assert!((gtp - agt).abs() <= 1e-8 * gt.abs().max(gn.abs()).max(1.0), "γ_T⁺ {} vs {}", gtp, agt);
        }
    }

    #[test]
    fn impact3_painleve_never_wrong(over in 0.0f64..3.0, eps in 0.0f64..=1.0,
                                    gn in -3.0f64..-0.01, gt in -3.0f64..3.0,
                                    a in 0.1f64..2.0, b in 0.1f64..2.0, neg in any::<bool>(),
                                    c in 0.1f64..2.0) {
        // μ > 1 in the Painlevé-type regime μ|G_NT| ≥ G_NN by construction
        let b = if neg { -b } else { b };
        let g = [a * a, a * b, b * b + c * c];
        let mu = (g[0] / g[1].abs()).max(1.0) * (1.0 + over);
        prop_assert!(mu * g[1].abs() >= g[0]);
        let p = impact3(mu, eps, gn, gt, g);
        let sol = Lemke::new(LemkeSettings::default()).solve(&p);
        prop_assert!(matches!(sol.status, LcpStatus::Solved | LcpStatus::RayTermination), "{:?}", sol);
        if sol.status == LcpStatus::Solved {
            prop_assert!(check_lcp(&p, &sol.z, 1e-9).is_ok());
        }
        // the physical solution exists (spec §9): enumeration finds it
        let en = enumerate(&p).unwrap();
        prop_assert!(!en.is_empty());
        for z in &en {
            prop_assert!(check_lcp(&p, z, 1e-9).is_ok());
        }
    }
}

/// `(Λ_N, Λ_T, γ_T⁺)` from an impact3 solution `z = (Λ_N, Λ_TR, γ_TL)` (spec §8).
fn physical(p: &LcpProblem, z: &[f64], mu: f64) -> (f64, f64, f64) {
    let ln = z[0];
    let lt = z[1] - mu * z[0];
    // γ_T⁺ = γ_T⁻ + G_TN Λ_N + G_TT Λ_T (row 2 of the LCP without the γ_TL term)
    let gtp = p.q()[1] + p.m(1, 0) * z[0] + p.m(1, 1) * z[1];
    (ln, lt, gtp)
}

/// The closed-form single-impact solution of spec §9: `(Λ_N, Λ_T, γ_T⁺)`.
fn analytic(mu: f64, eps: f64, gn: f64, gt: f64, g: [f64; 3]) -> (f64, f64, f64) {
    let [gnn, gnt, gtt] = g;
    let n = -gn;
    let r = gt / gn;
    let a = 1.0 + eps;
    let dm = gnn - mu * gnt;
    let dp = gnn + mu * gnt;
    let l = if dm > 0.0 {
        a * (gnt - mu * gtt) / dm
    } else {
        f64::NEG_INFINITY
    };
    let u = if dp > 0.0 {
        a * (gnt + mu * gtt) / dp
    } else {
        f64::INFINITY
    };
    let det = gnn * gtt - gnt * gnt;
    if r < l {
        let ln = a * n / dm;
        (ln, -mu * ln, n * (l - r))
    } else if r > u {
        let ln = a * n / dp;
        (ln, mu * ln, n * (u - r))
    } else {
        (
            n * (a * gtt - gnt * r) / det,
            n * (gnn * r - a * gnt) / det,
            0.0,
        )
    }
}

/// `lcp_tobenna.dat` (n = 40) is riddled with ratio ties. The exact rational lexicographic run
/// takes 127 pivots; with ties detected within a tolerance over a wide range we follow exactly
/// that path, while exact floating-point comparisons (tie_tol = 0) leave it.
#[test]
fn tobenna_needs_tolerant_ties() {
    let Some(dir) = siconos_dir() else { return };
    let p = io::read_siconos(&dir.join("lcp_tobenna.dat")).unwrap();
    let run = |tt: f64| {
        let s = LemkeSettings::default()
            .with_tie_tol(tt)
            .unwrap()
            .with_max_pivots(5000)
            .unwrap();
        Lemke::new(s).solve(&p)
    };
    for tt in [1e-14, 1e-12, 1e-10, 1e-8, 1e-6] {
        let sol = run(tt);
        assert_eq!(
            (sol.status, sol.pivots),
            (LcpStatus::Solved, 127),
            "tie_tol {tt}"
        );
    }
    assert_ne!(run(0.0).pivots, 127);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, ..ProptestConfig::default() })]

    /// Nearly singular `G` (condition numbers up to ~1e10, impulses up to ~1e9), μ ≤ 1: always
    /// `Solved` with a verified z (2·10⁶ cases checked while developing, 59 % of them Painlevé).
    #[test]
    fn impact3_ill_conditioned_g(mu in 0.0f64..=1.0, eps in 0.0f64..=1.0, gn in -3.0f64..-0.01,
                                 gt in -30.0f64..30.0, a in 0.01f64..3.0, b in -10.0f64..10.0,
                                 c in 0.01f64..3.0) {
        let g = [a * a, a * b, b * b + c * c];
        let p = impact3(mu, eps, gn, gt, g);
        let m: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| p.m(i, j)));
        let q: [f64; 3] = p.q().try_into().unwrap();
        let f = solve_fixed(&m, &q, &LemkeSettings::default());
        prop_assert_eq!(f.status, LcpStatus::Solved);
        prop_assert!(check_lcp(&p, &f.z, 1e-9).is_ok());
    }
}

// ---------------------------------------------------------------------------------------------
// Badly scaled data (issue 2, scaling): a Delassus matrix of a 10⁶-kg deck has entries ~1e-6.

/// Whether the closed-form answer at `r` is determined by a Lemke solution that passes
/// verification (each `w`, `z` within `verify_tol = 1e-9` of its row's rounding scale), with a
/// safety factor of 100 — a criterion on the data, independent of the solver's answer:
///
/// * next to a finite bound `B ∈ {L, U}` (`d = |r − B|`, `D = G_NN ∓ μG_NT`,
///   `det = G_NN G_TT − G_NT²`, `a = 1 + ε`), both neighbouring modes must be told apart: the slip
///   candidate violates the sign of `γ_T⁺` by `n d` against its row scale
///   `n(|r| + (|G_NT| + μG_TT) a/D)`, the stick candidate violates the cone by `n d D/det` against
///   its impulse scale `n(3μ|aG_TT − G_NT r| + |G_NN r − aG_NT|)/det`; near-Painlevé bounds
///   (`D → 0⁺`) and ratios within rounding of a bound fail this;
/// * in a slip mode `Λ_N = a n/D`: a residual `1e-9·s_N` of the normal row
///   (`s_N ≈ a n + (|G_NN ∓ μG_NT| + 2μ|G_NT|)Λ_N`) moves `Λ_N` relatively by `1e-9·amp` with
///   `amp = (D + |G_NN ∓ μG_NT| + 2μ|G_NT|)/D`; `amp ≤ 100` is required. (The verification bound
///   itself would then allow 1e-7; the errors Lemke achieves are ~3e-11·amp — the old filter
///   `D ≥ 1e-2 G_NN` let `amp ≈ 575` through and Λ_N was off by 1.6e-8 — so `amp ≤ 100` keeps
///   them below 3e-9, under the asserted 1e-8.)
fn resolvable(g: &pounding::contact::Delassus, mu: f64, eps: f64, l: f64, u: f64, r: f64) -> bool {
    let a = 1.0 + eps;
    let det = g.nn * g.tt - g.nt * g.nt;
    let (dm, dp) = (g.nn - mu * g.nt, g.nn + mu * g.nt);
    // every finite bound (the `anywhere` draws can land next to one too)
    let near = [(l, dm), (u, dp)];
    for (bound, dd) in near.into_iter().filter(|(b, _)| b.is_finite()) {
        let d = (r - bound).abs();
        if dd <= 0.0 {
            return false;
        }
        let slip_scale = r.abs() + (g.nt.abs() + mu * g.tt) * a / dd;
        let stick_scale =
            (3.0 * mu * (a * g.tt - g.nt * r).abs() + (g.nn * r - a * g.nt).abs()) / det;
        if d < 100.0 * 1e-9 * slip_scale || d * dd / det < 100.0 * 1e-9 * stick_scale {
            return false;
        }
    }
    // slip modes: sensitivity of Λ_N to the normal row's residual
    let slip_d = if l.is_finite() && r < l {
        Some(dm)
    } else if u.is_finite() && r > u {
        Some(dp)
    } else {
        None
    };
    if let Some(dd) = slip_d {
        let amp = (dd.abs()
            + (g.nn - mu * g.nt).abs().max((g.nn + mu * g.nt).abs())
            + 2.0 * mu * g.nt.abs())
            / dd;
        if !(dd > 0.0 && amp <= 100.0) {
            return false;
        }
    }
    true
}

/// Pre-impact ratio `r` for a case index: just outside / inside each finite bound of the stick
/// interval (`± 1e-6·max(1, |bound|)`), its midpoint, or `fallback`.
fn ratio_case(case: u8, l: f64, u: f64, fallback: f64) -> f64 {
    let d = |x: f64| 1e-6 * x.abs().max(1.0);
    let r = match case {
        0 => l - d(l),
        1 => l + d(l),
        2 => u - d(u),
        3 => u + d(u),
        4 => 0.5 * (l + u),
        _ => fallback,
    };
    if r.is_finite() { r } else { fallback }
}

proptest! {
    // Deterministic (fixed seed, nothing persisted to the tracked regressions file); the filter
    // `resolvable` was validated on 3.6e7 random-seed cases without a failure.
    #![proptest_config(ProptestConfig { cases: 2000, max_global_rejects: 20000, failure_persistence: None, rng_seed: proptest::test_runner::RngSeed::Fixed(0x005e_ed15), ..ProptestConfig::default() })]

    /// impact3 with `G` scaled by `10^k`, `k ∈ [−9, 5]` (bridge decks: `k ≈ −6`; known limit: in the
    /// Painlevé regime with `k ≥ 6` Lemke and enumeration can both fail verification — see README), μ, ε ∈ [0, 1], `r` just outside / inside
    /// `L` and `U`, at the midpoint or anywhere: always `Solved` by `solve_fixed` and by
    /// `Lemke::solve`, with the mode and impulses of the closed form (`pounding::analytic`,
    /// spec §9), the impulses relative to their own scale `10^−k`.
    #[test]
    fn impact3_scaled_g_is_solved(k in -9i32..=5, mu in 0.0f64..=1.0, eps in 0.0f64..=1.0,
                                  n in 0.01f64..3.0, g in spd(), case in 0u8..6,
                                  r_any in -5.0f64..5.0) {
        use pounding::analytic::{ImpactLaw, SlipMode, single_impact, stick_interval};
        use pounding::contact::Delassus;
        let s = 10f64.powi(k);
        let gs = [g[0] * s, g[1] * s, g[2] * s];
        let del = Delassus { nn: gs[0], nt: gs[1], tt: gs[2] };
        let law = ImpactLaw::new(mu, eps).unwrap();
        let b = stick_interval(&del, &law);
        let r = ratio_case(case, b.lower, b.upper, r_any);
        prop_assume!(resolvable(&del, mu, eps, b.lower, b.upper, r));
        let (gn, gt) = (-n, -n * r);
        let p = impact3(mu, eps, gn, gt, gs);
        let m: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| p.m(i, j)));
        let q: [f64; 3] = p.q().try_into().unwrap();
        let f = solve_fixed(&m, &q, &LemkeSettings::default());
        // In the Painlevé-type regime μ|G_NT| ≥ G_NN Lemke may stop without a solution (spec §9;
        // issue 2 allows it there): then enumeration must find the physical one, and a `Solved`
        // must never be wrong.
        if mu * del.nt.abs() >= del.nn && f.status != LcpStatus::Solved {
            let a = single_impact(&del, &law, gn, gt);
            let all = pounding::lcp::enumerate(&p).unwrap();
            prop_assert!(!all.is_empty(), "enumeration found nothing");
            for z in &all {
                let (ln, _, _) = physical(&p, z, mu);
                prop_assert!((ln - a.normal_impulse).abs() <= 1e-8 * a.normal_impulse.abs());
            }
            return Ok(());
        }
        prop_assert_eq!(f.status, LcpStatus::Solved, "k {} r {} [{}, {}]", k, r, b.lower, b.upper);
        let sol = Lemke::new(LemkeSettings::default()).solve(&p);
        prop_assert_eq!(sol.status, LcpStatus::Solved);
        prop_assert_eq!(&sol.z[..], &f.z[..]);
        let a = single_impact(&del, &law, gn, gt);
        let (ln, lt, gtp) = physical(&p, &f.z, mu);
        prop_assert_eq!(SlipMode::classify(gtp, n), a.mode, "γ_T⁺ {} vs {}", gtp, a.gamma_t_post);
        let li = a.normal_impulse.abs();
        prop_assert!((ln - a.normal_impulse).abs() <= 1e-8 * li, "Λ_N {} vs {}", ln, a.normal_impulse);
        prop_assert!((lt - a.tangential_impulse).abs() <= 1e-8 * li, "Λ_T {} vs {}", lt, a.tangential_impulse);
        let vs = n * r.abs().max(1.0).max(if b.lower.is_finite() { b.lower.abs() } else { 0.0 })
            .max(if b.upper.is_finite() { b.upper.abs() } else { 0.0 });
        prop_assert!((gtp - a.gamma_t_post).abs() <= 1e-8 * vs, "γ_T⁺ {} vs {}", gtp, a.gamma_t_post);
    }
}

/// A P-matrix LCP with rows and columns scaled by powers of ten: `M' = R M C`, `q' = R q`
/// (`R`, `C` positive diagonal, so `M'` is again a P-matrix) has the unique solution `z' = C⁻¹ z`.
fn scaled_p_lcp() -> impl Strategy<Value = (LcpProblem, Vec<i32>, Vec<i32>)> {
    p_lcp().prop_flat_map(|p| {
        let n = p.dim();
        (
            Just(p),
            prop::collection::vec(-4i32..=4, n),
            prop::collection::vec(-4i32..=4, n),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn p_matrix_scaled_rows_and_columns(case in scaled_p_lcp()) {
        let (p, re, ce) = case;
        let n = p.dim();
        let rs: Vec<f64> = re.iter().map(|&e| 10f64.powi(e)).collect();
        let cs: Vec<f64> = ce.iter().map(|&e| 10f64.powi(e)).collect();
        let mut m = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                m[i * n + j] = rs[i] * p.m(i, j) * cs[j];
            }
        }
        let q: Vec<f64> = (0..n).map(|i| rs[i] * p.q()[i]).collect();
        let ps = LcpProblem::new(m, q).unwrap();
        let sol = Lemke::new(LemkeSettings::default()).solve(&ps);
        prop_assert_eq!(sol.status, LcpStatus::Solved, "rows {:?} cols {:?}", re, ce);
        // the unique solution of the unscaled problem (brute force), mapped: z' = C⁻¹ z
        let en = enumerate(&p).unwrap();
        prop_assert_eq!(en.len(), 1);
        for j in 0..n {
            let want = en[0][j] / cs[j];
            let scale = inf_norm(&en[0]).max(1.0) / cs[j];
            prop_assert!((sol.z[j] - want).abs() <= 1e-7 * scale, "z[{}] {} vs {}", j, sol.z[j], want);
        }
    }
}
