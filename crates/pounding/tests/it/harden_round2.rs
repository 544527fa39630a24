//! Hardening, second round (issue 15): the memory estimate that lets front ends refuse runs too
//! large to hold in memory.

use pounding::ground_motion::el_centro_1940;
use pounding::sim::options::{
    GROUND_BYTES_PER_STEP, MAX_RUN_MEMORY_BYTES, history_row_bytes, history_rows,
    min_history_stride, run_memory_bytes,
};
use pounding::sim::{SimError, SimModel, SimProblem, SimSettings, simulate};

/// The row count of the estimate is that of a real run, and its bytes per row cover what the
/// run's solution keeps per row (every history vector and the observers' tables; the solution is
/// destructured exhaustively: a new field fails to compile here until it is counted).
#[test]
fn memory_estimate_counts_the_rows_and_bytes_a_run_keeps() {
    use pounding::sim::bridge::BridgeSolution;
    let problem = SimProblem::at_rest(SimModel::default_bridge(), el_centro_1940());
    for stride in [1usize, 7, 10, 50, 1000] {
        let settings = SimSettings {
            duration: Some(0.05),
            history_stride: stride,
            ..SimSettings::default()
        };
        let sol = simulate(&problem, &settings).unwrap();
        assert_eq!(sol.steps, 50);
        let BridgeSolution {
            status: _,
            steps: _,
            dt: _,
            n_segments: _,
            dofs: _,
            t,
            q,
            u,
            gaps,
            end_gaps,
            slip,
            contact_force,
            abutment_gaps,
            energy,
            impacts: _,
            summary: _,
            supports_apart: _,
            lcp_solves: _,
            lcp_enumeration_fallbacks: _,
            lcp_failures: _,
            newton_failures: _,
            closure_steps: _,
            time_step_advice: _,
            table_sources,
        } = &sol;
        let rows = t.len();
        assert_eq!(
            rows as u64,
            history_rows(sol.steps, stride),
            "stride {stride}"
        );
        let reals = t.len()
            + q.len()
            + u.len()
            + gaps.len()
            + end_gaps.len()
            + slip.len()
            + contact_force.len()
            + 2 * abutment_gaps.len()
            + table_sources.iter().map(|t| t.kept_values()).sum::<usize>();
        let bytes = 8 * reals + size_of_val(&energy[0]) * energy.len();
        assert!(contact_force.is_empty());
        // the estimate counts the kept row twice (a growing vector may hold twice its length)
        let per_row = bytes.div_ceil(rows) as u64;
        assert!(2 * per_row <= history_row_bytes(2), "{per_row} bytes a row");
    }
    assert_eq!(GROUND_BYTES_PER_STEP, 32);
}

/// The 5 M-step, every-step history the tester ran (> 1 GB resident) is refused with the
/// smallest stride that fits; that stride is accepted, one less is not.
#[test]
fn runs_beyond_the_memory_limit_are_refused_with_the_stride_that_fits() {
    let mut settings = SimSettings {
        dt: 1e-3,
        history_stride: 1,
        ..SimSettings::default()
    };
    let err = settings.check_memory(5000.0, 2).unwrap_err();
    let SimError::InvalidParameter { name, reason, .. } = &err else {
        panic!("{err}");
    };
    assert_eq!(name, "history_stride");
    let s = min_history_stride(5_000_000, 2).unwrap();
    assert!(s > 1 && reason.contains(&format!("at least {s}")), "{err}");
    assert!(run_memory_bytes(5_000_000, s, 2) <= MAX_RUN_MEMORY_BYTES);
    assert!(run_memory_bytes(5_000_000, s - 1, 2) > MAX_RUN_MEMORY_BYTES);
    settings.history_stride = s;
    assert!(settings.check_memory(5000.0, 2).is_ok());
    // the El Centro default run is far below the limit
    settings.history_stride = 10;
    assert!(settings.check_memory(53.76, 2).unwrap() < 100 << 20);
    // near the step limit, the ground samples alone do not fit: no stride helps
    assert_eq!(min_history_stride(pounding::sim::MAX_STEPS, 2), None);
    // the estimate never overflows
    assert_eq!(run_memory_bytes(usize::MAX, 1, 2), u64::MAX);
}

/// Compared runs held at once keep the finest history that fits: their own stride when it
/// fits, else the smallest that does (monotone), else an error naming the limit.
#[test]
fn compared_runs_keep_the_finest_history_that_fits() {
    use pounding::sim::options::{MAX_RUN_MEMORY_BYTES, check_runs_memory, runs_history_stride};
    assert_eq!(runs_history_stride(&[(10_000, 3); 6], 5), Ok(5));
    let big = [(2_000_000, 200); 6];
    let s = runs_history_stride(&big, 5).unwrap();
    assert!(s > 5);
    let at = |s: usize| big.iter().map(|&(n, g)| (n, s, g)).collect::<Vec<_>>();
    assert!(check_runs_memory(&at(s)).unwrap() <= MAX_RUN_MEMORY_BYTES);
    assert!(check_runs_memory(&at(s - 1)).is_err());
    let e = runs_history_stride(&[(30_000_000, 2); 6], 50).unwrap_err();
    assert!(e.contains("first and last"), "{e}");
}

/// Hostile round 3 campaign (F4, F9): values a shape or the model refuses after their own range
/// check (a subnormal angle, density, mass or yield force) are named by the key the user wrote,
/// at its line — not the `[[segment]]` header, not another key.
#[test]
fn values_refused_by_the_shape_or_model_name_their_own_key_and_line() {
    let base = "[[segment]]\nshape = \"curved\"\nR = 150.0\nbeta_deg = 12.0\ndensity = 2500.0\n\
                period_s = 1.0\nbearing = \"bilinear\"\nfy = 4.0e5\nb = 0.05\n\
                [[segment]]\nshape = \"skew\"\nL = 30.0\nskew_deg = 20.0\nwidth = 9.396926207859083\n\
                mass = 1.2e6\nbearing_stiffness = 1.0e8\n\
                [ground_motion]\nrecord_y = \"builtin:ELC180\"\nrecord_x = \"none\"\n";
    for (from, to, key, line) in [
        (
            "beta_deg = 12.0",
            "beta_deg = 5e-324",
            "segment[0].beta_deg",
            4,
        ),
        (
            "density = 2500.0",
            "density = 1e308",
            "segment[0].density",
            5,
        ),
        (
            "density = 2500.0",
            "density = 5e-324",
            "segment[0].density",
            5,
        ),
        ("fy = 4.0e5", "fy = 1e-320", "segment[0].fy", 8),
        ("mass = 1.2e6", "mass = 1e-300", "segment[1].mass", 15),
    ] {
        let text = base.replace(from, to);
        assert_ne!(text, base);
        let e = pounding::sim::scenario::Scenario::from_toml(&text, "s.toml")
            .and_then(|s| s.build_bridge())
            .err()
            .unwrap_or_else(|| panic!("{to} must be refused"))
            .to_string();
        assert!(e.contains(&format!("`{key}` (s.toml:{line})")), "{to}: {e}");
    }
}
