//! Lemke's anti-cycling (lexicographic ties) on degenerate LCPs shipped with the repository (no
//! dependency on the shared Siconos data): pivot counts and solutions of the library's kernels
//! against an independent exact-rational lexicographic Lemke written here.
//!
//! The exact run follows spec §8: tableau `[I, −M, −e | q]`; `z₀` enters in the row of the
//! lexicographic minimum of `[q_i | e_iᵀ]` (among equal `q_i` the largest index); ratio test over
//! rows with a positive entering-column entry, lexicographic minimum of `[rhs_i | (B⁻¹)_i] / d_i`,
//! except that `z₀` leaves whenever its row ties on `rhs_i / d_i` (the rule the library documents:
//! stop as early as possible); the complement of the leaving variable enters next. Pivots are
//! counted like [`pounding::lcp::LcpSolution::pivots`] (including the pivots in which `z₀` enters
//! and leaves). Every fixture has ties in its ratio tests, so the tie rule is exercised, and one
//! of them cycles forever under a naive (first-index) tie rule.
#![allow(clippy::needless_range_loop)]

use pounding::lcp::{LcpProblem, LcpStatus, Lemke, LemkeSettings, solve_fixed};

/// Exact rational `num/den`, `den > 0`, reduced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Q {
    n: i128,
    d: i128,
}

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 { a.abs() } else { gcd(b, a % b) }
}

impl Q {
    fn int(n: i128) -> Q {
        Q { n, d: 1 }
    }
    fn new(n: i128, d: i128) -> Q {
        let g = gcd(n, d).max(1) * d.signum();
        Q { n: n / g, d: d / g }
    }
    fn add(self, o: Q) -> Q {
        Q::new(self.n * o.d + o.n * self.d, self.d * o.d)
    }
    fn sub(self, o: Q) -> Q {
        self.add(Q { n: -o.n, d: o.d })
    }
    fn mul(self, o: Q) -> Q {
        Q::new(self.n * o.n, self.d * o.d)
    }
    fn div(self, o: Q) -> Q {
        Q::new(self.n * o.d, self.d * o.n)
    }
    fn cmp(self, o: Q) -> std::cmp::Ordering {
        (self.n * o.d).cmp(&(o.n * self.d))
    }
    fn pos(self) -> bool {
        self.n > 0
    }
    fn f(self) -> f64 {
        self.n as f64 / self.d as f64
    }
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Ties {
    /// Lexicographic, `z₀` first (the library's documented rule).
    Lexicographic,
    /// Naive: the first tied row (no anti-cycling).
    FirstIndex,
}

#[derive(Debug)]
struct Exact {
    solved: bool,
    pivots: usize,
    z: Vec<Q>,
    /// Ratio tests with more than one minimising row.
    ties: usize,
}

/// Exact Lemke (module doc). Variables: `0..n` = `w`, `n..2n` = `z`, `2n` = `z₀`.
fn exact_lemke(m: &[Vec<i128>], q: &[i128], rule: Ties, max_pivots: usize) -> Exact {
    let n = q.len();
    let cols = 2 * n + 1;
    let mut t: Vec<Vec<Q>> = (0..n)
        .map(|i| {
            let mut row = vec![Q::int(0); cols];
            row[i] = Q::int(1);
            for j in 0..n {
                row[n + j] = Q::int(-m[i][j]);
            }
            row[2 * n] = Q::int(-1);
            row
        })
        .collect();
    let mut rhs: Vec<Q> = q.iter().map(|&x| Q::int(x)).collect();
    let mut basis: Vec<usize> = (0..n).collect();
    let mut ties = 0;
    if q.iter().all(|&x| x >= 0) {
        return Exact {
            solved: true,
            pivots: 0,
            z: vec![Q::int(0); n],
            ties,
        };
    }
    let qmin = *q.iter().min().unwrap();
    let r0 = (0..n).rev().find(|&i| q[i] == qmin).unwrap();
    if q.iter().filter(|&&x| x == qmin).count() > 1 {
        ties += 1;
    }
    let pivot = |t: &mut Vec<Vec<Q>>, rhs: &mut Vec<Q>, r: usize, c: usize| {
        let p = t[r][c];
        for x in t[r].iter_mut() {
            *x = x.div(p);
        }
        rhs[r] = rhs[r].div(p);
        for i in 0..n {
            if i != r {
                let f = t[i][c];
                if f.n != 0 {
                    for j in 0..cols {
                        let v = t[r][j].mul(f);
                        t[i][j] = t[i][j].sub(v);
                    }
                    rhs[i] = rhs[i].sub(rhs[r].mul(f));
                }
            }
        }
    };
    pivot(&mut t, &mut rhs, r0, 2 * n);
    basis[r0] = 2 * n;
    let mut pivots = 1;
    let mut entering = n + r0;
    loop {
        if pivots >= max_pivots {
            return Exact {
                solved: false,
                pivots,
                z: vec![],
                ties,
            };
        }
        let rows: Vec<usize> = (0..n).filter(|&i| t[i][entering].pos()).collect();
        if rows.is_empty() {
            return Exact {
                solved: false,
                pivots,
                z: vec![],
                ties,
            };
        }
        let ratio = |i: usize| rhs[i].div(t[i][entering]);
        let best = rows
            .iter()
            .map(|&i| ratio(i))
            .min_by(|a, b| a.cmp(*b))
            .unwrap();
        let tied: Vec<usize> = rows.iter().copied().filter(|&i| ratio(i) == best).collect();
        if tied.len() > 1 {
            ties += 1;
        }
        let r = if tied.len() == 1 {
            tied[0]
        } else if let Some(&z0) = tied.iter().find(|&&i| basis[i] == 2 * n) {
            z0
        } else {
            match rule {
                Ties::FirstIndex => tied[0],
                Ties::Lexicographic => {
                    // lexicographic minimum of (B⁻¹)_i / d_i, B⁻¹ = the w columns
                    *tied
                        .iter()
                        .min_by(|&&a, &&b| {
                            (0..n)
                                .map(|c| {
                                    t[a][c].div(t[a][entering]).cmp(t[b][c].div(t[b][entering]))
                                })
                                .find(|o| o.is_ne())
                                .unwrap_or(std::cmp::Ordering::Equal)
                        })
                        .unwrap()
                }
            }
        };
        pivot(&mut t, &mut rhs, r, entering);
        let leaving = basis[r];
        basis[r] = entering;
        pivots += 1;
        if leaving == 2 * n {
            let mut z = vec![Q::int(0); n];
            for i in 0..n {
                if basis[i] >= n && basis[i] < 2 * n {
                    z[basis[i] - n] = rhs[i];
                }
            }
            return Exact {
                solved: true,
                pivots,
                z,
                ties,
            };
        }
        entering = if leaving < n {
            leaving + n
        } else {
            leaving - n
        };
    }
}

/// A fixture: name, integer `M` (rows), integer `q`.
type Fixture = (&'static str, Vec<Vec<i128>>, Vec<i128>);

/// Degenerate fixtures `(name, M, q)`.
fn fixtures() -> Vec<Fixture> {
    vec![
        // Murty's cyclic matrix with equal q: ties in the initial row and in the ratio tests
        (
            "murty-cyclic",
            vec![vec![1, 2, 0], vec![0, 1, 2], vec![2, 0, 1]],
            vec![-1, -1, -1],
        ),
        // the frictionless single-impact LCP of spec §8 (μ = 0, ε = 0): b has zeros
        (
            "impact-mu0",
            vec![vec![2, 1, 0], vec![1, 3, 1], vec![0, -1, 0]],
            vec![-1, 0, 0],
        ),
        // a 4×4 PSD (circulant) matrix with zero and repeated entries of q
        (
            "circulant4",
            vec![
                vec![2, 1, 0, 1],
                vec![1, 2, 1, 0],
                vec![0, 1, 2, 1],
                vec![1, 0, 1, 2],
            ],
            vec![-1, 0, -1, 0],
        ),
        // two frictional contacts on one body (6×6 impact LCP, μ = 1, integer G): repeated rows
        (
            "impact2-mu1",
            vec![
                vec![1, 0, 1, 0, 0, 0],
                vec![0, 1, 0, 1, 0, 0],
                vec![-1, -1, 2, 1, 1, 0],
                vec![-1, -1, 1, 2, 0, 1],
                vec![2, 0, -1, 0, 0, 0],
                vec![0, 2, 0, -1, 0, 0],
            ],
            vec![-2, -2, 0, 0, 0, 0],
        ),
    ]
}

#[test]
fn degenerate_fixtures_match_exact_lexicographic_lemke() {
    for (name, m, q) in fixtures() {
        let n = q.len();
        let ex = exact_lemke(&m, &q, Ties::Lexicographic, 1000);
        assert!(ex.ties > 0, "{name}: fixture has no ties, tests nothing");
        let mf: Vec<f64> = m.iter().flatten().map(|&x| x as f64).collect();
        let qf: Vec<f64> = q.iter().map(|&x| x as f64).collect();
        let p = LcpProblem::new(mf, qf).unwrap();
        let sol = Lemke::new(LemkeSettings::default()).solve(&p);
        assert_eq!(
            sol.status == LcpStatus::Solved,
            ex.solved,
            "{name}: {sol:?} vs {ex:?}"
        );
        assert_eq!(sol.pivots, ex.pivots, "{name}: pivots {sol:?} vs {ex:?}");
        if ex.solved {
            for j in 0..n {
                assert!(
                    (sol.z[j] - ex.z[j].f()).abs() <= 1e-12 * (1.0 + ex.z[j].f().abs()),
                    "{name}: z[{j}] {} vs {:?}",
                    sol.z[j],
                    ex.z[j]
                );
            }
        }
        // the fixed-size kernels agree
        let fixed = |sol_z: &[f64], piv: usize, st: LcpStatus| {
            assert_eq!(st == LcpStatus::Solved, ex.solved, "{name} fixed");
            assert_eq!(piv, ex.pivots, "{name}: fixed pivots");
            if ex.solved {
                for j in 0..n {
                    assert!((sol_z[j] - ex.z[j].f()).abs() <= 1e-12 * (1.0 + ex.z[j].f().abs()));
                }
            }
        };
        let row = |i: usize| -> Vec<f64> { m[i].iter().map(|&x| x as f64).collect() };
        match n {
            3 => {
                let a: [[f64; 3]; 3] = std::array::from_fn(|i| row(i).try_into().unwrap());
                let b: [f64; 3] = std::array::from_fn(|i| q[i] as f64);
                let f = solve_fixed(&a, &b, &LemkeSettings::default());
                fixed(&f.z, f.pivots, f.status);
            }
            4 => {
                let a: [[f64; 4]; 4] = std::array::from_fn(|i| row(i).try_into().unwrap());
                let b: [f64; 4] = std::array::from_fn(|i| q[i] as f64);
                let f = solve_fixed(&a, &b, &LemkeSettings::default());
                fixed(&f.z, f.pivots, f.status);
            }
            6 => {
                let a: [[f64; 6]; 6] = std::array::from_fn(|i| row(i).try_into().unwrap());
                let b: [f64; 6] = std::array::from_fn(|i| q[i] as f64);
                let f = solve_fixed(&a, &b, &LemkeSettings::default());
                fixed(&f.z, f.pivots, f.status);
            }
            _ => unreachable!(),
        }
    }
}

/// Evidence that the fixtures need the tie rule: under the naive first-index rule Lemke cycles
/// on Murty's cyclic example (no end within 1000 pivots, where the lexicographic rule — and the
/// library — stop after 4).
#[test]
fn naive_tie_rule_cycles_on_murty_cyclic() {
    let (_, m, q) = fixtures().remove(0);
    let naive = exact_lemke(&m, &q, Ties::FirstIndex, 1000);
    assert!(!naive.solved && naive.pivots == 1000, "{naive:?}");
    let lex = exact_lemke(&m, &q, Ties::Lexicographic, 1000);
    assert!(lex.solved && lex.pivots == 4, "{lex:?}");
    let mut differs = 0;
    for (name, m, q) in fixtures() {
        let lex = exact_lemke(&m, &q, Ties::Lexicographic, 1000);
        let naive = exact_lemke(&m, &q, Ties::FirstIndex, 1000);
        eprintln!(
            "{name}: lexicographic {} pivots (solved {}), first-index {} pivots (solved {})",
            lex.pivots, lex.solved, naive.pivots, naive.solved
        );
        if lex.pivots != naive.pivots || lex.solved != naive.solved {
            differs += 1;
        }
    }
    assert!(differs > 0, "no fixture distinguishes the tie rules");
}
