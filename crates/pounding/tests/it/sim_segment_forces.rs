//! `segment_forces.csv`: every force on a segment, by member kind, as the integrator applies it.
//! On a two-segment bridge with linear and yielding bearings, Rayleigh damping, a restrainer,
//! an abutment and a joint that pound (a compliance law, the rigid law, and both mixed), the
//! table's forces balance each segment's mass times its mean absolute acceleration over every
//! step, `m (u_{k+1} − u_k)/h + m ā_g` (x, y and the moment about the centroid), to rounding;
//! its bearing forces are the trapezoidal mean of `bearings.csv`'s.

use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::{BridgeSetup, Scenario};
use pounding::sim::simulate;
use pounding::sim::table::Table;
use pounding::sim::{SimStatus, dofs::PlanDof};

/// Segment 1 on yielding bearings, segment 2 on linear bearings placed unevenly (so that it
/// turns), Rayleigh damping, a restrainer across the joint, a start abutment, both components
/// of El Centro; `extra`: more TOML (the contact law).
fn bridge(extra: &str) -> BridgeSetup {
    let text = format!(
        r#"
[bridge]
damping = "rayleigh"
damping_ratio = 0.05
gap = 0.01
mu = 0.3
eps_n = 0.6
restrainer_k = 2.0e7
restrainer_slack = 0.004

[[segment]]
shape = "straight"
L = 30.0
mass = 1.0e6
period_s = 1.0
bearing = "bilinear"
fy = 2.5e5
b = 0.1

[[segment]]
shape = "straight"
L = 30.0
mass = 1.2e6
period_s = 0.4
bearing_points = [[0.0, -5.0], [0.0, 5.0], [30.0, -5.0], [18.0, 5.0]]

[abutment.start]
gap = 0.02

[ground_motion]
record_y = "builtin:ELC180"
record_x = "builtin:ELC270"

[time]
dt = 1e-3
duration = 8.0
history_every = 1
{extra}
"#
    );
    Scenario::from_toml(&text, "segment-forces.toml")
        .and_then(|s| s.build_bridge())
        .unwrap_or_else(|e| panic!("{e}"))
}

const BILINEAR: &str = "law = \"bilinear\"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3";

fn table(sol: &BridgeSolution, name: &str) -> Table {
    sol.tables().into_iter().find(|t| t.name == name).unwrap()
}

/// The largest residual of the balance of every segment over every step, relative to the
/// largest term (forces for x and y, moments for θ apart): `(forces, moments)`. Every column of
/// a segment is summed; `kinds`: the member kinds that must act on some segment.
fn balance(setup: &BridgeSetup, sol: &BridgeSolution, kinds: &[&str]) -> (f64, f64) {
    let f = table(sol, "segment_forces");
    let h = sol.dt;
    let bodies = setup.problem.model.layout();
    assert_eq!(f.rows(), sol.t.len());
    assert!(
        f.row(0)[1..].iter().all(|v| *v == 0.0),
        "no step before t = 0"
    );
    let quantities = ["fx_N", "fy_N", "mz_Nm"];
    // per segment and coordinate: the columns summed
    let cols: Vec<Vec<Vec<usize>>> = (1..=bodies.len())
        .map(|j| {
            let prefix = format!("segment{j}_");
            quantities
                .iter()
                .map(|q| {
                    let suffix = format!("_{q}");
                    (1..f.columns.len())
                        .filter(|&c| {
                            let head = f.columns[c].header();
                            head.starts_with(&prefix) && head.ends_with(&suffix)
                        })
                        .collect()
                })
                .collect()
        })
        .collect();
    assert_eq!(
        cols.iter().flatten().map(Vec::len).sum::<usize>(),
        f.columns.len() - 1
    );
    let n = sol.dofs.len();
    let mut worst = [0.0f64; 2];
    let mut scale = [0.0f64; 2];
    let mut acted = vec![0.0f64; kinds.len()];
    for k in 0..sol.t.len() - 1 {
        assert_eq!(f.row(k + 1)[0], sol.t[k + 1]);
        let a0 = setup.problem.ground.accel(k as f64 * h);
        let a1 = setup.problem.ground.accel((k + 1) as f64 * h);
        let ag = [0.5 * (a0.x + a1.x), 0.5 * (a0.y + a1.y), 0.0];
        for (j, b) in bodies.iter().enumerate() {
            for (d, dof) in [PlanDof::X, PlanDof::Y, PlanDof::Theta]
                .into_iter()
                .enumerate()
            {
                let i = sol.dofs.plan(j, dof);
                let mass = if d == 2 { b.mass.inertia } else { b.mass.mass };
                let du = (sol.u[n * (k + 1) + i] - sol.u[n * k + i]) / h;
                let lhs = mass * (du + ag[d]);
                let mut rhs = 0.0;
                for &c in &cols[j][d] {
                    let v = f.row(k + 1)[c];
                    rhs += v;
                    scale[d / 2] = scale[d / 2].max(v.abs());
                    let name = &f.columns[c].name;
                    for (a, kind) in acted.iter_mut().zip(kinds) {
                        if name.contains(&format!("_{kind}_")) {
                            *a = a.max(v.abs());
                        }
                    }
                }
                scale[d / 2] = scale[d / 2].max((mass * ag[d]).abs()).max(lhs.abs());
                worst[d / 2] = worst[d / 2].max((lhs - rhs).abs());
            }
        }
    }
    for (kind, a) in kinds.iter().zip(&acted) {
        assert!(*a > 1e3, "{kind} never acted: {a}");
    }
    // a moment is measured against the forces times the largest radius of gyration too (a
    // bridge that does not turn has moments of rounding size only)
    let gyration = bodies
        .iter()
        .map(|b| (b.mass.inertia / b.mass.mass).sqrt())
        .fold(0.0, f64::max);
    let moment_scale = scale[1].max(scale[0] * gyration);
    (worst[0] / scale[0], worst[1] / moment_scale)
}

/// The bearings' resultant of `segment_forces` at row `k + 1` is the mean of `bearings.csv`'s
/// resultants at rows `k` and `k + 1` (θ = ½, the ground does not move); returns the largest
/// relative difference.
fn bearings_are_the_trapezoidal_mean(setup: &BridgeSetup, sol: &BridgeSolution) -> f64 {
    let (f, b) = (table(sol, "segment_forces"), table(sol, "bearings"));
    let model = &setup.problem.model;
    let bodies = model.layout();
    let points = model.bearing_points();
    let resultant = |r: usize, j: usize| {
        let mut out = [0.0; 3];
        for (m, p) in points[j].iter().enumerate() {
            let arm = p - bodies[j].centroid;
            let col = |q: &str| {
                let head = format!("segment{}_bearing{}_{q}_N", j + 1, m + 1);
                b.columns.iter().position(|c| c.header() == head).unwrap()
            };
            let (fx, fy) = (b.row(r)[col("fx")], b.row(r)[col("fy")]);
            out[0] += fx;
            out[1] += fy;
            out[2] += arm.x * fy - arm.y * fx;
        }
        out
    };
    let (mut worst, mut scale) = (0.0f64, 0.0f64);
    for k in 0..sol.t.len() - 1 {
        for j in 0..bodies.len() {
            let (r0, r1) = (resultant(k, j), resultant(k + 1, j));
            for (d, q) in ["fx_N", "fy_N", "mz_Nm"].iter().enumerate() {
                let head = format!("segment{}_bearings_{q}", j + 1);
                let col = f.columns.iter().position(|c| c.header() == head).unwrap();
                let mean = 0.5 * (r0[d] + r1[d]);
                worst = worst.max((f.row(k + 1)[col] - mean).abs());
                scale = scale.max(mean.abs());
            }
        }
    }
    worst / scale
}

fn run_and_check(extra: &str, what: &str) -> BridgeSolution {
    let setup = bridge(extra);
    let sol = simulate(&setup.problem, &setup.settings).unwrap();
    assert_eq!(sol.status, SimStatus::Completed, "{what}");
    assert!(sol.summary.impacts > 0, "{what}: the joint must pound");
    assert!(
        sol.summary.segments[0].hysteretic_energy > 0.0,
        "{what}: segment 1's bearings must yield"
    );
    let kinds = ["bearings", "dashpots", "restrainers", "contact"];
    let (forces, moments) = balance(&setup, &sol, &kinds);
    let f = table(&sol, "segment_forces");
    assert_eq!(
        f.columns.len(),
        1 + 3 * kinds.len() * 2,
        "{what}: no shear keys"
    );
    let bearings = bearings_are_the_trapezoidal_mean(&setup, &sol);
    eprintln!(
        "{what}: balance residual {forces:.2e} (forces), {moments:.2e} (moments); bearings vs \
         bearings.csv {bearings:.2e}"
    );
    assert!(forces < 1e-9, "{what}: forces {forces:e}");
    assert!(moments < 1e-9, "{what}: moments {moments:e}");
    assert!(bearings < 1e-9, "{what}: bearings {bearings:e}");
    sol
}

#[test]
fn forces_balance_mass_times_absolute_acceleration_with_a_compliance_law() {
    run_and_check(&format!("[contact]\n{BILINEAR}"), "bilinear");
}

#[test]
fn forces_balance_mass_times_absolute_acceleration_with_the_rigid_law() {
    run_and_check("", "rigid");
}

/// A rigid joint and a bilinear abutment in one bridge (the mixed stepper).
#[test]
fn forces_balance_mass_times_absolute_acceleration_with_mixed_sites() {
    run_and_check(&format!("[abutment.start.contact]\n{BILINEAR}"), "mixed");
}

/// With a history stride, a row holds the mean over the steps since the previous row: the
/// balance holds over the stride with `(u(t) − u(t_prev))/Δt`, and the stride's rows are the
/// means of the single steps' rows.
#[test]
fn a_strided_row_is_the_mean_of_its_steps() {
    let every = bridge("");
    let sol1 = simulate(&every.problem, &every.settings).unwrap();
    let mut strided = bridge("");
    strided.settings.history_stride = 10;
    let sol10 = simulate(&strided.problem, &strided.settings).unwrap();
    let (f1, f10) = (
        table(&sol1, "segment_forces"),
        table(&sol10, "segment_forces"),
    );
    assert_eq!(f10.rows(), (f1.rows() - 1) / 10 + 1);
    let mut worst = 0.0f64;
    let mut scale = 0.0f64;
    for r in 1..f10.rows() {
        for c in 1..f1.columns.len() {
            let mean = (10 * (r - 1) + 1..=10 * r)
                .map(|k| f1.row(k)[c])
                .sum::<f64>()
                / 10.0;
            worst = worst.max((f10.row(r)[c] - mean).abs());
            scale = scale.max(mean.abs());
        }
    }
    assert!(worst <= 1e-12 * scale, "{worst:e} of {scale:e}");
}

/// `examples/<name>` with its `[time]` replaced (every step kept, `duration` seconds at `dt`).
fn example(name: &str, dt: f64, duration: f64) -> BridgeSetup {
    let root = env!("CARGO_MANIFEST_DIR");
    let text = std::fs::read_to_string(format!("{root}/../../examples/{name}")).unwrap();
    let at = text.find("\n[time]").expect("a [time] section");
    let rest = text[at + 1..]
        .find("\n[")
        .map_or("", |e| &text[at + 1 + e..]);
    let text = format!(
        "{}{rest}\n[time]\ndt = {dt}\nduration = {duration}\nhistory_every = 1\n",
        &text[..at]
    );
    Scenario::from_toml(&text, name)
        .and_then(|s| s.build_bridge())
        .unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Bearings on pier caps (the dense coupled operators), backwalls, and supports that move apart
/// (the supports' load `P_K d̄ + P_C v̄` in the bearings' and dashpots' columns): the same
/// balance.
#[test]
fn forces_balance_on_piers_and_moving_supports() {
    for (name, kinds) in [
        (
            "bridge-piers-1d.toml",
            &["bearings", "dashpots", "contact"][..],
        ),
        (
            "bridge-p-1d-wave.toml",
            &["bearings", "dashpots", "contact"][..],
        ),
    ] {
        let setup = example(name, 2e-4, 6.0);
        let sol = simulate(&setup.problem, &setup.settings).unwrap();
        let (forces, moments) = balance(&setup, &sol, kinds);
        eprintln!("{name}: balance residual {forces:.2e} (forces), {moments:.2e} (moments)");
        assert!(forces < 1e-9, "{name}: forces {forces:e}");
        assert!(
            moments < 1e-9 || moments.is_nan(),
            "{name}: moments {moments:e}"
        );
    }
}
