//! `history.csv`: the run's histories as one [`Table`]-shaped view, written by the one CSV writer
//! ([`table::csv_rows`]) and handed to Python as numbers (no text in between).
//!
//! One solution ([`BridgeSolution`]) has one layout, a bridge's (`[[segment]]` files; per segment
//! `x<i>, y<i>, θ<i>` and their rates, two end gaps per joint, each joint's slip, joint forces,
//! abutment gaps, six energy terms), and the two-deck model's file is its translation
//! ([`PAIR_HISTORY_COLUMNS`]: the bridge's columns under the two-deck names, in the two-deck
//! order, plus what only the form writes: the four candidate gaps and the two end forces). A layout
//! is a list of columns, each naming the series of the solution it reads ([`Series`]); one loop
//! writes every layout.

use super::{DEG, Layout};
use crate::geometry::ContactCase;
use crate::ground_motion::GroundMotion;
use crate::math::Real;
use crate::sim::bridge::{ABUTMENT_SIDES, BridgeSolution};
use crate::sim::table::{self, Column, Table};

/// What one column of the history reads from the solution at a kept row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Series {
    /// The time.
    Time,
    /// The ground acceleration the run used (x: 0, y: 1).
    Ground(usize),
    /// `q[k]` (rotations in degrees).
    Q(usize),
    /// `u[k]` (rotations in degrees).
    U(usize),
    /// Candidate gap `k` (4 per joint).
    CandidateGap(usize),
    /// End gap `k` (2 per joint).
    EndGap(usize),
    /// Slip of joint `k`.
    Slip(usize),
    /// Energy term (input, kinetic, strain, viscous, contact, elements).
    Energy(usize),
    /// Normal force of end `k` (2 per joint).
    EndForce(usize),
    /// Total normal force of joint `k`.
    JointForce(usize),
    /// The smaller corner gap at the abutment of a side.
    AbutmentGap(usize),
}

/// The energy terms in column order (the last, the projection's work, only with the projection).
const ENERGY: [&str; 7] = [
    "input_energy",
    "kinetic_energy",
    "strain_energy",
    "viscous_dissipation",
    "contact_dissipation",
    "element_work",
    "projection_work",
];

/// A column (or columns) of the two-deck `history.csv`, in its order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairHistoryColumn {
    /// `(two-deck name, bridge name)`: the bridge column under the two-deck name (the two-deck
    /// model is the bridge of two segments; its joint is joint 1, its abutments of decks 1 and 2
    /// the start and end abutments).
    Renamed(&'static str, &'static str),
    /// Only the form writes: the joint's four candidate gaps `gap_<case>_m`
    /// ([`ContactCase::ALL`] order).
    CandidateGaps,
    /// Only the form writes (compliance laws): the normal force of each joint end,
    /// `contact_force_xplus_N`, `contact_force_xminus_N` (the bridge writes their sum,
    /// `joint1_force_N`).
    EndForces,
}

/// The two-deck `history.csv` as a translation of the bridge's.
pub const PAIR_HISTORY_COLUMNS: [PairHistoryColumn; 28] = {
    use PairHistoryColumn::{CandidateGaps, EndForces, Renamed as R};
    [
        R("t", "t"),
        R("ag_x", "ag_x"),
        R("ag_y", "ag_y"),
        R("x1", "x1"),
        R("y1", "y1"),
        R("theta1", "theta1"),
        R("x2", "x2"),
        R("y2", "y2"),
        R("theta2", "theta2"),
        R("vx1", "vx1"),
        R("vy1", "vy1"),
        R("omega1", "omega1"),
        R("vx2", "vx2"),
        R("vy2", "vy2"),
        R("omega2", "omega2"),
        CandidateGaps,
        R("joint_gap_xplus", "joint1_gap_c0"),
        R("joint_gap_xminus", "joint1_gap_c1"),
        R("slip", "joint1_slip"),
        R("input_energy", "input_energy"),
        R("kinetic_energy", "kinetic_energy"),
        R("strain_energy", "strain_energy"),
        R("viscous_dissipation", "viscous_dissipation"),
        R("contact_dissipation", "contact_dissipation"),
        R("projection_work", "projection_work"),
        EndForces,
        R("abutment_gap1", "abutment_start_gap"),
        R("abutment_gap2", "abutment_end_gap"),
    ]
};

/// A run's `history.csv`: its columns and where each reads.
pub struct History<'a> {
    sol: &'a BridgeSolution,
    ground: &'a GroundMotion,
    columns: Vec<Column>,
    series: Vec<Series>,
}

impl<'a> History<'a> {
    /// The history of `sol` in `layout`, with the ground motion the run used;
    /// `abutments[s]`: the abutment of side `s` (the two-deck model: of deck `s + 1`) is present.
    pub fn new(
        layout: Layout,
        sol: &'a BridgeSolution,
        ground: &'a GroundMotion,
        abutments: [bool; 2],
    ) -> Self {
        match layout {
            Layout::Bridge => Self::bridge(sol, ground, abutments),
            Layout::TwoDecks => Self::two_decks(sol, ground, abutments),
        }
    }

    /// The bridge layout.
    fn bridge(sol: &'a BridgeSolution, ground: &'a GroundMotion, abutments: [bool; 2]) -> Self {
        let mut h = Self::head(sol, ground);
        let n = sol.n_segments;
        let nj = n.saturating_sub(1);
        h.states(n);
        for k in 0..nj {
            for (e, c) in ["c0", "c1"].iter().enumerate() {
                h.push(
                    format!("joint{}_gap_{c}", k + 1),
                    "m",
                    Series::EndGap(2 * k + e),
                );
            }
        }
        for k in 0..nj {
            h.push(format!("joint{}_slip", k + 1), "m", Series::Slip(k));
        }
        if !sol.contact_force.is_empty() {
            for k in 0..nj {
                h.push(format!("joint{}_force", k + 1), "N", Series::JointForce(k));
            }
        }
        for side in (0..2).filter(|&s| abutments[s]) {
            let name = format!("abutment_{}_gap", ABUTMENT_SIDES[side]);
            h.push(name, "m", Series::AbutmentGap(side));
        }
        for (i, e) in ENERGY[..6].iter().enumerate() {
            h.push(*e, "J", Series::Energy(i));
        }
        h.projection_work();
        h
    }

    /// `projection_work_J` (the ledger's projection term), with the projection only: the files
    /// of a run without it keep their columns.
    fn projection_work(&mut self) {
        if self.sol.summary.projection.is_some() {
            self.push(ENERGY[6], "J", Series::Energy(6));
        }
    }

    /// The two-deck model's layout: the bridge layout of its two segments translated by
    /// [`PAIR_HISTORY_COLUMNS`] (a bridge column the run does not write is left out: the
    /// projection's work without the projection, an absent abutment's gap).
    fn two_decks(sol: &'a BridgeSolution, ground: &'a GroundMotion, abutments: [bool; 2]) -> Self {
        let bridge = Self::bridge(sol, ground, abutments);
        let mut h = History {
            sol,
            ground,
            columns: Vec::new(),
            series: Vec::new(),
        };
        for col in PAIR_HISTORY_COLUMNS {
            match col {
                PairHistoryColumn::Renamed(name, from) => {
                    let i = bridge.columns.iter().position(|c| c.name == from);
                    if let Some(i) = i {
                        h.push(name, bridge.columns[i].unit, bridge.series[i]);
                    }
                }
                PairHistoryColumn::CandidateGaps => {
                    for (k, c) in ContactCase::ALL.iter().enumerate() {
                        h.push(format!("gap_{}", c.name()), "m", Series::CandidateGap(k));
                    }
                }
                PairHistoryColumn::EndForces if !sol.contact_force.is_empty() => {
                    h.push("contact_force_xplus", "N", Series::EndForce(0));
                    h.push("contact_force_xminus", "N", Series::EndForce(1));
                }
                PairHistoryColumn::EndForces => {}
            }
        }
        h
    }

    /// The time and ground-acceleration columns.
    fn head(sol: &'a BridgeSolution, ground: &'a GroundMotion) -> Self {
        let mut h = History {
            sol,
            ground,
            columns: Vec::new(),
            series: Vec::new(),
        };
        h.push("t", "s", Series::Time);
        h.push("ag_x", "mps2", Series::Ground(0));
        h.push("ag_y", "mps2", Series::Ground(1));
        h
    }

    /// `x<i>, y<i>, θ<i>` of every segment, then their rates (1-based names).
    fn states(&mut self, n: usize) {
        for (rates, names) in [
            (false, [("x", "m"), ("y", "m"), ("theta", "deg")]),
            (true, [("vx", "mps"), ("vy", "mps"), ("omega", "degps")]),
        ] {
            for i in 0..n {
                for (c, (name, unit)) in names.iter().enumerate() {
                    let k = self.sol.dofs.plan_index(i, c);
                    let s = if rates { Series::U(k) } else { Series::Q(k) };
                    self.push(format!("{name}{}", i + 1), unit, s);
                }
            }
        }
    }

    fn push(&mut self, name: impl Into<String>, unit: &'static str, s: Series) {
        self.columns.push(Column::new(name, unit));
        self.series.push(s);
    }

    /// The columns.
    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// Appends row `r` to `out`.
    fn row(&self, r: usize, rot: &[bool], out: &mut Vec<Real>) {
        let sol = self.sol;
        let t = sol.t[r];
        // the accelerations the run used, not a re-interpolation at the rounded time
        let a = self.ground.accel(crate::sim::solver_time(t, sol.dt));
        let deg = |k: usize, v: Real| if rot[k] { v * DEG } else { v };
        let nj = sol.n_segments.saturating_sub(1);
        for s in &self.series {
            out.push(match *s {
                Series::Time => t,
                Series::Ground(0) => a.x,
                Series::Ground(_) => a.y,
                Series::Q(k) => deg(k, sol.q_row(r)[k]),
                Series::U(k) => deg(k, sol.u_row(r)[k]),
                Series::CandidateGap(k) => sol.gaps[4 * nj * r + k],
                Series::EndGap(k) => sol.end_gaps_row(r)[k],
                Series::Slip(k) => sol.slip[nj * r + k],
                Series::Energy(i) => {
                    let e = &sol.energy[r];
                    [
                        e.input,
                        e.kinetic,
                        e.potential,
                        e.viscous,
                        e.contact,
                        e.elements,
                        e.projection,
                    ][i]
                }
                Series::EndForce(k) => sol.contact_force_row(r)[k],
                Series::JointForce(k) => {
                    let f = sol.contact_force_row(r);
                    f[2 * k] + f[2 * k + 1]
                }
                Series::AbutmentGap(side) => sol.abutment_gaps[r][side],
            });
        }
    }

    /// The CSV text of `history.csv`.
    pub fn csv(&self) -> String {
        let rot = self.sol.dofs.rotations();
        table::csv_rows(&self.columns, self.sol.rows(), |r, out| {
            self.row(r, &rot, out)
        })
    }

    /// The history as a [`Table`] named `history` (the same numbers as [`Self::csv`]).
    pub fn table(&self) -> Table {
        let rot = self.sol.dofs.rotations();
        let mut values = Vec::with_capacity(self.sol.rows() * self.columns.len());
        for r in 0..self.sol.rows() {
            self.row(r, &rot, &mut values);
        }
        Table {
            name: "history",
            columns: self.columns.clone(),
            values,
        }
    }
}
