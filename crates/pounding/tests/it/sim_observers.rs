//! The observers' tables of a run (`bearings`, `restrainers`, `joint_slip`): each bearing's force
//! is `−k u_b` of its own deformation recomputed here from the history, and the forces of the
//! tables balance the segment's momentum change over every step to rounding (the discrete
//! equation of motion of the trapezoidal scheme: `m (u_{k+1} − u_k)/h + m ā_g = ½ (F_k + F_{k+1})`).

use pounding::ground_motion::el_centro_1940;
use pounding::shape::{DeckShape, StraightDeck};
use pounding::sim::bridge::{
    BearingYield, BridgeModel, BridgeProblem, BridgeSolution, Joint, RestrainerSpec, Segment,
};
use pounding::sim::table::Table;
use pounding::sim::{DampingModel, JointContact, SimModel, SimProblem, SimSettings, simulate};

fn straight(l: f64) -> DeckShape {
    DeckShape::Straight(StraightDeck::new(l, 10.0, 0.5, 2500.0).unwrap())
}

/// One segment on four corner bearings of unequal stiffness (so that its rotation couples).
fn one_segment(yielding: Option<BearingYield>) -> BridgeModel {
    let mut s = Segment::with_corner_bearings(straight(30.0), false, 2.0e7);
    s.bearings[0].stiffness *= 3.0;
    s.bearings[3].stiffness *= 0.5;
    s.bearing_yield = yielding;
    BridgeModel {
        segments: vec![s],
        joints: Vec::new(),
        abutments: [None, None],
        outer_seat_length: 0.4,
        damping_ratio: 0.0,
        damping_model: DampingModel::Rayleigh,
        piers: Vec::new(),
    }
}

fn run(model: BridgeModel, duration: f64) -> (BridgeProblem, BridgeSolution, SimSettings) {
    let problem = BridgeProblem::at_rest(model, el_centro_1940());
    let settings = SimSettings {
        duration: Some(duration),
        dt: 1e-3,
        ..SimSettings::default()
    };
    let sol = simulate(&problem, &settings).unwrap();
    (problem, sol, settings)
}

fn table(tables: Vec<Table>, name: &str) -> Table {
    tables.into_iter().find(|t| t.name == name).unwrap()
}

#[test]
fn bearing_forces_are_minus_k_times_their_own_deformation() {
    let (p, sol, _) = run(one_segment(None), 3.0);
    let b = table(sol.tables(), "bearings");
    assert_eq!(b.rows(), sol.t.len());
    assert_eq!(b.columns.len(), 1 + 4 * 4);
    let points = p.model.bearing_points();
    let g = p.model.layout()[0].centroid;
    let mut peak = 0.0f64;
    for r in 0..b.rows() {
        let row = b.row(r);
        assert_eq!(row[0], sol.t[r]);
        let q = &sol.q[3 * r..3 * r + 3];
        for (j, (pt, br)) in points[0]
            .iter()
            .zip(&p.model.segments[0].bearings)
            .enumerate()
        {
            let arm = pt - g;
            let u = [q[0] - q[2] * arm.y, q[1] + q[2] * arm.x];
            let c = &row[1 + 4 * j..5 + 4 * j];
            for d in 0..2 {
                assert_eq!(c[d], u[d], "row {r} bearing {j}");
                let f = -br.stiffness * u[d];
                assert!(
                    (c[2 + d] - f).abs() <= 1e-12 * f.abs().max(1.0),
                    "{} vs {f}",
                    c[2 + d]
                );
                peak = peak.max(f.abs());
            }
        }
    }
    assert!(peak > 1e4, "the bearings must carry load: {peak}");
}

/// `m (u_{k+1} − u_k)/h + m ā_g` against the trapezoidal mean of the bearings' forces, and the
/// same for the moment about the centroid, over every step.
fn assert_momentum_balance(p: &BridgeProblem, sol: &BridgeSolution, h: f64) -> f64 {
    let b = table(sol.tables(), "bearings");
    let body = &p.model.layout()[0];
    let (m, inertia, g) = (body.mass.mass, body.mass.inertia, body.centroid);
    let arms: Vec<_> = p.model.bearing_points()[0]
        .iter()
        .map(|pt| pt - g)
        .collect();
    let resultant = |r: usize| {
        let row = b.row(r);
        let mut f = [0.0; 3];
        for (j, a) in arms.iter().enumerate() {
            let (fx, fy) = (row[3 + 4 * j], row[4 + 4 * j]);
            f[0] += fx;
            f[1] += fy;
            f[2] += a.x * fy - a.y * fx;
        }
        f
    };
    let mut worst = 0.0f64;
    let mut scale = 0.0f64;
    for k in 0..sol.t.len() - 1 {
        let (f0, f1) = (resultant(k), resultant(k + 1));
        let a0 = p.ground.accel(k as f64 * h);
        let a1 = p.ground.accel((k + 1) as f64 * h);
        let ag = [0.5 * (a0.x + a1.x), 0.5 * (a0.y + a1.y), 0.0];
        for d in 0..3 {
            let mass = if d == 2 { inertia } else { m };
            let du = (sol.u[3 * (k + 1) + d] - sol.u[3 * k + d]) / h;
            let lhs = mass * (du + ag[d]);
            let rhs = 0.5 * (f0[d] + f1[d]);
            worst = worst.max((lhs - rhs).abs());
            scale = scale.max(rhs.abs()).max((mass * ag[d]).abs());
        }
    }
    worst / scale
}

#[test]
fn the_tables_forces_balance_mass_times_absolute_acceleration() {
    let (p, sol, s) = run(one_segment(None), 4.0);
    let err = assert_momentum_balance(&p, &sol, s.dt);
    assert!(err < 1e-9, "linear bearings: relative residual {err:e}");
    // yielding bearings (solved implicitly at the end of each step): the same balance
    let (p, sol, s) = run(one_segment(Some(BearingYield { fy: 2.0e5, b: 0.05 })), 4.0);
    let b = table(sol.tables(), "bearings");
    let peak_f = (0..b.rows())
        .flat_map(|r| (0..4).map(move |j| (r, j)))
        .map(|(r, j)| b.row(r)[3 + 4 * j].hypot(b.row(r)[4 + 4 * j]))
        .fold(0.0f64, f64::max);
    assert!(
        sol.summary.segments[0].hysteretic_energy > 0.0,
        "the bearings must yield"
    );
    assert!(peak_f > 2.0e5 / 4.0, "{peak_f}");
    let err = assert_momentum_balance(&p, &sol, s.dt);
    assert!(err < 1e-9, "yielding bearings: relative residual {err:e}");
}

#[test]
fn restrainer_table_gives_the_cable_law_of_its_elongation() {
    // a stiff and a soft segment: out of phase, the joint opens
    let mk = |k| Segment::with_corner_bearings(straight(30.0), false, k);
    let model = BridgeModel {
        segments: vec![mk(2.0e7), mk(1.0e6)],
        joints: vec![Joint {
            gap: 0.05,
            friction: 0.0,
            restitution: 0.6,
            seat_length: 0.4,
            contact: JointContact::Rigid,
            restrainers: vec![RestrainerSpec::at_midpoints(3.0e7, 0.01, None)],
        }],
        abutments: [None, None],
        outer_seat_length: 0.4,
        damping_ratio: 0.05,
        damping_model: DampingModel::Rayleigh,
        piers: Vec::new(),
    };
    let (_, sol, _) = run(model, 6.0);
    let t = table(sol.tables(), "restrainers");
    let heads: Vec<String> = t.columns.iter().map(|c| c.header()).collect();
    assert_eq!(
        heads,
        [
            "t_s",
            "joint1_restrainer1_elongation_m",
            "joint1_restrainer1_force_N"
        ]
    );
    let mut engaged = 0;
    for r in 0..t.rows() {
        let (e, f) = (t.row(r)[1], t.row(r)[2]);
        let expect = (3.0e7 * (e - 0.01)).max(0.0);
        assert!(
            (f - expect).abs() <= 1e-6 * expect.max(1.0),
            "row {r}: {f} vs {expect}"
        );
        engaged += usize::from(f > 0.0);
    }
    assert!(engaged > 10, "the restrainer must engage");
    let slip = table(sol.tables(), "joint_slip");
    assert_eq!(slip.columns.len(), 2);
    assert_eq!(slip.rows(), sol.t.len());
}

/// The two-deck model has the same tables (deck `j` is segment `j`).
#[test]
fn the_two_deck_model_records_the_same_tables() {
    let problem = SimProblem::at_rest(SimModel::default_bridge(), el_centro_1940());
    let settings = SimSettings {
        duration: Some(2.0),
        ..SimSettings::default()
    };
    let sol = simulate(&problem, &settings).unwrap();
    let tables = sol.tables();
    let names: Vec<&str> = tables.iter().map(|t| t.name).collect();
    assert_eq!(
        names,
        ["bearings", "restrainers", "joint_slip", "segment_forces"]
    );
    // a run into a directory clears every earlier output: each table's file is in that list
    for t in &tables {
        let f = t.file_name();
        assert!(
            pounding::sim::output::SIM_OUTPUTS.contains(&f.as_str()),
            "{f} is not in SIM_OUTPUTS"
        );
    }
    let b = table(sol.tables(), "bearings");
    assert_eq!(b.rows(), sol.t.len());
    assert_eq!(b.columns[1].header(), "segment1_bearing1_ux_m");
    let slip = table(sol.tables(), "joint_slip");
    for (r, s) in sol.slip.iter().enumerate() {
        assert_eq!(slip.row(r)[1], *s);
    }
}
