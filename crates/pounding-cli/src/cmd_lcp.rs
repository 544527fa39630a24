//! `pounding lcp solve|bench`: solve or benchmark LCP files (Siconos `.dat` or `LCPSET 1`).

use anyhow::{Context, bail};
use clap::{Subcommand, ValueEnum};
use pounding::lcp::io::{self, LcpEntry, SolRecord};
use pounding::lcp::{LcpProblem, LcpSolution, LcpStatus, Lemke, LemkeSettings, enumerate};
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `pounding lcp`.
#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    cmd: LcpCmd,
}

/// Which solver to run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
enum Solver {
    /// Lexicographic Lemke (one solution or a failure status per problem).
    #[default]
    Lemke,
    /// Enumeration of complementary bases: every solution (n <= 12 only).
    Enum,
}

impl Solver {
    fn name(self) -> &'static str {
        match self {
            Solver::Lemke => "pounding-lemke",
            Solver::Enum => "pounding-enum",
        }
    }
}

/// Which clock times the bench.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Clock {
    /// Monotonic wall time.
    Wall,
    /// On-CPU time of the benchmarking thread (Linux).
    Cpu,
}

impl Clock {
    /// Seconds since an arbitrary origin.
    fn now(self, origin: Instant) -> anyhow::Result<f64> {
        match self {
            Clock::Wall => Ok(origin.elapsed().as_secs_f64()),
            Clock::Cpu => {
                let s = std::fs::read_to_string("/proc/thread-self/schedstat")
                    .context("--clock cpu needs /proc/thread-self/schedstat (Linux)")?;
                let ns: u64 = s
                    .split_whitespace()
                    .next()
                    .and_then(|x| x.parse().ok())
                    .context("unexpected /proc/thread-self/schedstat format")?;
                Ok(ns as f64 * 1e-9)
            }
        }
    }
}

#[derive(Subcommand)]
enum LcpCmd {
    /// Solve every problem of FILE (a Siconos .dat LCP or an LCPSET 1 set) and write LCPSOL 1.
    ///
    /// Lemke writes one SOL line per problem (status 1 and nan for every z when not solved);
    /// enum writes one SOL line per solution found (status 1 and nan when there is none).
    /// A one-line count per status goes to stderr.
    Solve {
        /// Problem file: Siconos .dat (dense or sparse-block) or LCPSET 1 (detected by its first line).
        file: PathBuf,
        /// Solver.
        #[arg(long, value_enum, default_value_t = Solver::Lemke)]
        solver: Solver,
        /// Output path (written atomically); default: standard output.
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Time the solver on every class of FILE; prints one JSON object to stdout.
    ///
    /// Per class: `count`, `solved`, `solves_per_s` (median of the repeats; each repeat runs the
    /// class's solve loop, including the solver's own verification, until it has taken at least
    /// --min-time seconds; parsing is outside the timer) and `max_residual`
    /// (max_i |min(z_i, w_i)| / max(1, ||q||_inf) over the solved problems; `null` when the
    /// class has no solved problem). Single-threaded.
    Bench {
        /// Problem file: Siconos .dat or LCPSET 1.
        file: PathBuf,
        /// Solver.
        #[arg(long, value_enum, default_value_t = Solver::Lemke)]
        solver: Solver,
        /// Minimum duration of one timed repeat per class, in seconds.
        #[arg(long, default_value_t = 0.5)]
        min_time: f64,
        /// Number of timed repeats per class (the median is reported).
        #[arg(long, default_value_t = 5)]
        repeats: usize,
        /// Clock: `wall` (monotonic wall time, as the issue and the Siconos harness use) or `cpu`
        /// (the thread's on-CPU time from /proc/thread-self/schedstat, Linux only: insensitive to
        /// preemption on a loaded machine).
        #[arg(long, value_enum, default_value_t = Clock::Wall)]
        clock: Clock,
    },
}

/// Runs `pounding lcp`.
pub fn run(args: Args) -> anyhow::Result<ExitCode> {
    match args.cmd {
        LcpCmd::Solve { file, solver, out } => solve(&file, solver, out.as_deref()),
        LcpCmd::Bench {
            file,
            solver,
            min_time,
            repeats,
            clock,
        } => bench(&file, solver, min_time, repeats, clock),
    }
}

fn read(file: &Path, solver: Solver) -> anyhow::Result<Vec<LcpEntry>> {
    let set = io::read_any(file)?;
    if solver == Solver::Enum
        && let Some(e) = set.iter().find(|e| e.problem.dim() > 12)
    {
        bail!(
            "{}: problem {} has n = {}; --solver enum needs n <= 12 (use --solver lemke)",
            file.display(),
            e.id,
            e.problem.dim()
        );
    }
    Ok(set)
}

fn solve(file: &Path, solver: Solver, out: Option<&Path>) -> anyhow::Result<ExitCode> {
    let set = read(file, solver)?;
    if set.is_empty() {
        bail!("{}: the file holds no problems (COUNT 0)", file.display());
    }
    let mut records = Vec::with_capacity(set.len());
    let mut counts: Vec<(&'static str, usize)> = Vec::new();
    let bump = |c: &mut Vec<(&'static str, usize)>, k: &'static str| {
        if let Some(e) = c.iter_mut().find(|e| e.0 == k) {
            e.1 += 1;
        }
    };
    match solver {
        Solver::Lemke => {
            let mut lemke = Lemke::new(LemkeSettings::default());
            for name in ["solved", "ray", "max_pivots", "ill_conditioned"] {
                counts.push((name, 0));
            }
            for e in &set {
                let s = lemke.solve(&e.problem);
                bump(&mut counts, s.status.name());
                records.push(SolRecord {
                    id: e.id,
                    solver: solver.name().into(),
                    solved: s.status == LcpStatus::Solved,
                    z: s.z,
                });
            }
        }
        Solver::Enum => {
            for name in ["solved", "multiple_solutions", "no_solution"] {
                counts.push((name, 0));
            }
            for e in &set {
                let sols = enumerate(&e.problem)
                    .with_context(|| format!("{}: problem {}", file.display(), e.id))?;
                if sols.is_empty() {
                    bump(&mut counts, "no_solution");
                    records.push(SolRecord {
                        id: e.id,
                        solver: solver.name().into(),
                        solved: false,
                        z: vec![f64::NAN; e.problem.dim()],
                    });
                } else {
                    bump(&mut counts, "solved");
                    if sols.len() > 1 {
                        bump(&mut counts, "multiple_solutions");
                    }
                    for z in sols {
                        records.push(SolRecord {
                            id: e.id,
                            solver: solver.name().into(),
                            solved: true,
                            z,
                        });
                    }
                }
            }
        }
    }
    let text = io::write_lcpsol(&records);
    match out {
        Some(p) => pounding::output::write_atomic(p, text.as_bytes())
            .with_context(|| format!("writing {}", p.display()))?,
        None => {
            use std::io::Write;
            std::io::stdout()
                .write_all(text.as_bytes())
                .context("writing to standard output")?;
        }
    }
    let parts: Vec<String> = counts.iter().map(|(k, v)| format!("{k} {v}")).collect();
    eprintln!(
        "{}: {} problems: {}",
        solver.name(),
        set.len(),
        parts.join(", ")
    );
    // Like `impact`: a problem without a solution is written (status 1, `nan`), then reported
    // with exit 1.
    let ids: std::collections::BTreeSet<_> = records.iter().map(|r| r.id).collect();
    let solved: std::collections::BTreeSet<_> =
        records.iter().filter(|r| r.solved).map(|r| r.id).collect();
    let unsolved = ids.len() - solved.len();
    if unsolved > 0 {
        eprintln!(
            "error: {unsolved} of {} problems not solved by {} (status 1 in the output)",
            set.len(),
            solver.name()
        );
        return Ok(ExitCode::FAILURE);
    }
    Ok(ExitCode::SUCCESS)
}

/// One class's solve loop: returns (solved count, max residual) — the work that is timed.
/// `max(a, b)` that keeps a NaN (`f64::max` would drop it and report a clean residual).
fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Solves every problem of a class once: the number solved and the largest residual among them
/// (NaN when none was solved: there is no residual to report, and `0.0` would claim a perfect one).
fn run_class(
    solver: Solver,
    probs: &[LcpProblem],
    lemke: &mut Lemke,
    sol: &mut LcpSolution,
) -> (usize, f64) {
    let mut solved = 0;
    let mut maxres = 0.0f64;
    match solver {
        Solver::Lemke => {
            for p in probs {
                lemke.solve_into(black_box(p), sol);
                if sol.status == LcpStatus::Solved {
                    solved += 1;
                    maxres = nan_max(maxres, sol.residual);
                }
            }
        }
        Solver::Enum => {
            for p in probs {
                // n <= 12 was checked when reading
                let sols = enumerate(black_box(p)).unwrap_or_default();
                if !sols.is_empty() {
                    solved += 1;
                }
                for z in &sols {
                    maxres = nan_max(maxres, residual(p, z));
                }
            }
        }
    }
    if solved == 0 {
        maxres = f64::NAN;
    }
    (solved, maxres)
}

/// `max_i |min(z_i, w_i)| / max(1, ||q||_inf)` with `w = M z + q`.
fn residual(p: &LcpProblem, z: &[f64]) -> f64 {
    let n = p.dim();
    let qn = p.q().iter().fold(1.0f64, |a, &x| a.max(x.abs()));
    let mut r = 0.0f64;
    for i in 0..n {
        let w = p.q()[i] + (0..n).map(|j| p.m(i, j) * z[j]).sum::<f64>();
        r = r.max(z[i].min(w).abs());
    }
    r / qn
}

fn bench(
    file: &Path,
    solver: Solver,
    min_time: f64,
    repeats: usize,
    clock: Clock,
) -> anyhow::Result<ExitCode> {
    let origin = Instant::now();
    clock.now(origin)?;
    if !(min_time.is_finite() && min_time > 0.0 && min_time <= 600.0) {
        bail!("--min-time must be in (0, 600] seconds, got {min_time}");
    }
    if !(1..=101).contains(&repeats) {
        bail!("--repeats must be in 1..=101, got {repeats}");
    }
    let set = read(file, solver)?;
    if set.is_empty() {
        bail!("{}: the file holds no problems (COUNT 0)", file.display());
    }
    // classes in order of first appearance
    let mut order: Vec<&str> = Vec::new();
    for e in &set {
        if !order.contains(&e.class.as_str()) {
            order.push(&e.class);
        }
    }
    let mut lemke = Lemke::new(LemkeSettings::default());
    let mut sol = lemke.solve(&set[0].problem); // warm the workspace and output vectors
    let mut classes = Vec::new();
    for class in order {
        // Copy the class's problems (outside the timer) so that their data lie contiguously in
        // memory, in the order they are solved, as a caller building its problems in one go would
        // have them (the parser's allocations are interleaved with its temporaries).
        let probs: Vec<LcpProblem> = set
            .iter()
            .filter(|e| e.class == class)
            .map(|e| e.problem.clone())
            .collect();
        let (solved, maxres) = run_class(solver, &probs, &mut lemke, &mut sol);
        // calibrate the number of passes so that one repeat takes >= min_time
        let mut passes = 1usize;
        loop {
            let t = clock.now(origin)?;
            for _ in 0..passes {
                black_box(run_class(solver, &probs, &mut lemke, &mut sol));
            }
            let dt = clock.now(origin)? - t;
            if dt >= min_time {
                break;
            }
            let grow = if dt > 0.0 {
                (1.25 * min_time / dt).ceil()
            } else {
                10.0
            };
            passes = passes.saturating_mul((grow as usize).clamp(2, 1000));
        }
        let mut rates = Vec::with_capacity(repeats);
        for _ in 0..repeats {
            let t = clock.now(origin)?;
            for _ in 0..passes {
                black_box(run_class(solver, &probs, &mut lemke, &mut sol));
            }
            let dt = clock.now(origin)? - t;
            rates.push((passes * probs.len()) as f64 / dt);
        }
        rates.sort_by(f64::total_cmp);
        let median = rates[rates.len() / 2];
        classes.push(serde_json::json!({
            "class": class,
            "count": probs.len(),
            "solved": solved,
            "solves_per_s": pounding::output::json_float(median),
            "max_residual": pounding::output::json_float(maxres),
        }));
    }
    let out = serde_json::json!({ "classes": classes });
    println!("{}", serde_json::to_string_pretty(&out)?);
    Ok(ExitCode::SUCCESS)
}
