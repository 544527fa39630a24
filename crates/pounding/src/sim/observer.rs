//! Observers: what a run records besides its state, one [`Table`] each.
//!
//! The driver owns the loop; at every kept step (the `history.csv` rows) it hands each observer
//! a [`Snapshot`] of the committed state, and at the end it returns their tables in order. A new
//! output is one type here implementing [`Observer`] and one line in [`standard`]; the CLI and
//! Python write or convert every table without knowing it.
//!
//! The standard observers of a bridge:
//! - [`BearingForces`] (`bearings.csv`): each bearing's deformation `u_b = (x − θ r_y, y + θ r_x)`
//!   (`r` its arm from the segment's centroid, the linearised rotation the stiffness `K` uses)
//!   and the force it exerts on its segment, `f = −k u_b` for a linear bearing and
//!   `f = −(k₀ u_b − (1 − b) k₀ u_p)` for a bilinear one (`u_p` its committed plastic
//!   displacement);
//! - [`RestrainerForces`] (`restrainers.csv`): each restrainer's elongation
//!   `e = |P_b − P_a| − L₀` (exact anchor positions) and its committed tension;
//! - [`JointSlip`] (`joint_slip.csv`): each joint's tangential slip, as the two-deck
//!   `history.csv` reports it.

use super::contact::State;
use super::driver::{Bridge, Frame};
use super::elements::Elements;
use super::table::{Column, Table};
use crate::math::Real;

/// The committed state at a kept step, as the observers see it.
pub(crate) struct Snapshot<'a> {
    /// Time \[s\].
    pub t: Real,
    /// Displacements relative to the ground.
    pub q: &'a State,
    /// The geometry at `q`.
    pub frame: &'a Frame,
    /// The bridge.
    pub bridge: &'a Bridge,
    /// The nonlinear elements in their committed state at `q`.
    pub elements: &'a Elements,
    /// Slip of each joint \[m\].
    pub slip: &'a [Real],
}

/// Records one table over a run.
pub(crate) trait Observer: Send {
    /// Appends the row of `s` (its time first).
    fn observe(&mut self, s: &Snapshot<'_>);
    /// The table recorded.
    fn into_table(self: Box<Self>) -> Table;
    /// Room for `rows` rows (the run's kept steps), so that recording never reallocates.
    fn reserve(&mut self, rows: usize);
}

/// The observers every bridge run records (in output order).
pub(crate) fn standard(bridge: &Bridge) -> Vec<Box<dyn Observer>> {
    vec![
        Box::new(BearingForces::new(bridge)),
        Box::new(RestrainerForces::new(bridge)),
        Box::new(JointSlip::new(bridge)),
    ]
}

/// Per bearing: deformation and force on its segment (module doc).
pub(crate) struct BearingForces {
    table: Table,
    /// Per segment and bearing: the index of its yielding element, if any.
    yielding: Vec<Vec<Option<usize>>>,
}

impl BearingForces {
    fn new(bridge: &Bridge) -> Self {
        let mut columns = Vec::new();
        let mut yielding: Vec<Vec<Option<usize>>> = bridge
            .bearings
            .iter()
            .map(|b| vec![None; b.len()])
            .collect();
        for (i, bs) in bridge.bearings.iter().enumerate() {
            for j in 0..bs.len() {
                let p = format!("segment{}_bearing{}", i + 1, j + 1);
                for (c, unit) in [("ux", "m"), ("uy", "m"), ("fx", "N"), ("fy", "N")] {
                    columns.push(Column::new(format!("{p}_{c}"), unit));
                }
            }
        }
        for (e, b) in bridge.elements.bearings.iter().enumerate() {
            yielding[b.body][b.slot] = Some(e);
        }
        BearingForces {
            table: Table::with_time("bearings", columns),
            yielding,
        }
    }
}

impl Observer for BearingForces {
    fn reserve(&mut self, rows: usize) {
        self.table.reserve_rows(rows);
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        let v = &mut self.table.values;
        v.push(s.t);
        for (i, bs) in s.bridge.bearings.iter().enumerate() {
            for (j, b) in bs.iter().enumerate() {
                let u = b.deformation(&s.bridge.dofs, s.q.as_slice(), &s.bridge.bodies);
                let f = match self.yielding[i][j] {
                    Some(e) => {
                        let y = &s.elements.bearings[e];
                        let k0 = y.law.k0();
                        -(u * k0 - y.state.u_p * ((1.0 - y.law.b()) * k0))
                    }
                    None => -u * b.stiffness,
                };
                v.extend([u.x, u.y, f.x, f.y]);
            }
        }
    }

    fn into_table(self: Box<Self>) -> Table {
        self.table
    }
}

/// Per restrainer: elongation and tension (module doc).
pub(crate) struct RestrainerForces {
    table: Table,
}

impl RestrainerForces {
    fn new(bridge: &Bridge) -> Self {
        let mut columns = Vec::new();
        let mut count = vec![0usize; bridge.joints.len()];
        for c in &bridge.elements.cables {
            count[c.joint] += 1;
            let p = format!("joint{}_restrainer{}", c.joint + 1, count[c.joint]);
            columns.push(Column::new(format!("{p}_elongation"), "m"));
            columns.push(Column::new(format!("{p}_force"), "N"));
        }
        RestrainerForces {
            table: Table::with_time("restrainers", columns),
        }
    }
}

impl Observer for RestrainerForces {
    fn reserve(&mut self, rows: usize) {
        self.table.reserve_rows(rows);
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        let v = &mut self.table.values;
        v.push(s.t);
        for c in &s.elements.cables {
            v.push(c.elongation(&s.frame.pose, &s.bridge.bodies));
            v.push(c.element.committed().force);
        }
    }

    fn into_table(self: Box<Self>) -> Table {
        self.table
    }
}

/// Per joint: slip.
pub(crate) struct JointSlip {
    table: Table,
}

impl JointSlip {
    fn new(bridge: &Bridge) -> Self {
        let columns = (1..=bridge.joints.len())
            .map(|k| Column::new(format!("joint{k}_slip"), "m"))
            .collect();
        JointSlip {
            table: Table::with_time("joint_slip", columns),
        }
    }
}

impl Observer for JointSlip {
    fn reserve(&mut self, rows: usize) {
        self.table.reserve_rows(rows);
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        self.table.values.push(s.t);
        self.table.values.extend_from_slice(s.slip);
    }

    fn into_table(self: Box<Self>) -> Table {
        self.table
    }
}
