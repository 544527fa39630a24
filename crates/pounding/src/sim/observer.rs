//! Observers: what a run records besides its state, one [`Table`] each.
//!
//! The driver owns the loop; at every kept step (the `history.csv` rows) it hands each observer
//! a [`Snapshot`] of the committed state, and at the end it returns what each kept, in order: a
//! recorded table, or what its table is derived from when asked for ([`TableSource`]: the
//! bearings' table is a function of the kept `q` rows and of the yielding bearings' plastic
//! displacements, the only part recorded). A new
//! output is one type here implementing [`Observer`] and one line in [`standard`]; the CLI and
//! Python write or convert every table without knowing it.
//!
//! The standard observers of a bridge:
//! - [`BearingForces`] (`bearings.csv`): each bearing's deformation `u_b = (x − θ r_y, y + θ r_x)`
//!   (`r` its arm from the segment's centroid, the linearised rotation the stiffness `K` uses;
//!   minus the cap's `(x_c, y_c)` for a bearing on a pier) and the force it exerts on its segment, `f = −k u_b` for a linear bearing and
//!   `f = −(k₀ u_b − (1 − b) k₀ u_p)` for a bilinear one (`u_p` its committed plastic
//!   displacement);
//! - [`RestrainerForces`] (`restrainers.csv`): each restrainer's elongation
//!   `e = |P_b − P_a| − L₀` (exact anchor positions) and its committed tension;
//! - [`JointSlip`] (`joint_slip.csv`): each joint's tangential slip, as the two-deck
//!   `history.csv` reports it;
//! - [`PierColumns`] (`piers.csv`, only for a bridge with piers): each pier's cap displacement
//!   and its column's force on the cap (named `pier<k>` by the joint `k` it carries);
//! - [`Backwalls`] (`backwalls.csv`) and [`ShearKeys`] (`shear_keys.csv`), for a bridge with
//!   them;
//! - [`super::segment_forces::SegmentForces`] (`segment_forces.csv`, last): every force on each
//!   segment by member kind, as the integrator applies it over the steps (the load path; its
//!   sum is the segment's mass times its absolute acceleration).

use super::dofs::Dofs;
use super::elements::Elements;
use super::table::{Column, Table};
use super::view::{Bridge, Frame};
use crate::math::{Real, Vector};

/// The committed state at a kept step, as the observers see it.
pub(crate) struct Snapshot<'a> {
    /// Time \[s\].
    pub t: Real,
    /// The geometry at `q`.
    pub frame: &'a Frame,
    /// The bridge.
    pub bridge: &'a Bridge,
    /// The nonlinear elements in their committed state at `q`.
    pub elements: &'a Elements,
    /// Slip of each joint \[m\].
    pub slip: &'a [Real],
    /// The state `q`.
    pub q: &'a [Real],
    /// The forces on the segments over the steps since the last kept row.
    pub loads: &'a super::segment_forces::StepLoads,
}

/// Records one table over a run.
pub(crate) trait Observer: Send {
    /// Appends the row of `s` (its time first).
    fn observe(&mut self, s: &Snapshot<'_>);
    /// The table recorded, or what it is derived from.
    fn into_source(self: Box<Self>) -> TableSource;
    /// Room for `rows` rows (the run's kept steps), so that recording never reallocates.
    fn reserve(&mut self, rows: usize);
}

/// The observers every bridge run records (in output order).
pub(crate) fn standard(bridge: &Bridge) -> Vec<Box<dyn Observer>> {
    let mut out: Vec<Box<dyn Observer>> = vec![
        Box::new(BearingForces::new(bridge)),
        Box::new(RestrainerForces::new(bridge)),
        Box::new(JointSlip::new(bridge)),
    ];
    if !bridge.piers.is_empty() {
        out.push(Box::new(PierColumns::new(bridge)));
    }
    if bridge.abutments.iter().any(|a| a.wall.is_some()) {
        out.push(Box::new(Backwalls::new(bridge)));
    }
    if !bridge.elements.keys.is_empty() {
        out.push(Box::new(ShearKeys::new(bridge)));
    }
    out.push(Box::new(super::segment_forces::SegmentForces::new(bridge)));
    out
}

/// Per abutment with shear keys: the deck end's transverse displacement `v` relative to the
/// abutment and the keys' force `F` (on the abutment; `−F` on the deck).
pub(crate) struct ShearKeys {
    table: Table,
}

impl ShearKeys {
    fn new(bridge: &Bridge) -> Self {
        let mut columns = Vec::new();
        for k in &bridge.elements.keys {
            let name = format!("abutment_{}", crate::sim::bridge::ABUTMENT_SIDES[k.side]);
            columns.push(Column::new(format!("{name}_shear_key_v"), "m"));
            columns.push(Column::new(format!("{name}_shear_key_force"), "N"));
        }
        ShearKeys {
            table: Table::with_time("shear_keys", columns),
        }
    }
}

impl Observer for ShearKeys {
    fn reserve(&mut self, rows: usize) {
        self.table.reserve_rows(rows);
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        let v = &mut self.table.values;
        v.push(s.t);
        for k in &s.elements.keys {
            v.extend([k.deformation(&s.bridge.dofs, s.q), k.force]);
        }
    }

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Recorded(self.table)
    }
}

/// Per abutment with a backwall: the wall's displacement into the soil, its backfill's force
/// (≥ 0, resisting) and its piles' force along the same axis (a bridge with backwalls only).
pub(crate) struct Backwalls {
    table: Table,
}

impl Backwalls {
    fn new(bridge: &Bridge) -> Self {
        let mut columns = Vec::new();
        for a in bridge.abutments.iter().filter(|a| a.wall.is_some()) {
            let name = format!("abutment_{}", crate::sim::bridge::ABUTMENT_SIDES[a.side]);
            for (c, unit) in [("wall", "m"), ("backfill", "N"), ("piles", "N")] {
                columns.push(Column::new(format!("{name}_{c}"), unit));
            }
        }
        Backwalls {
            table: Table::with_time("backwalls", columns),
        }
    }
}

impl Observer for Backwalls {
    fn reserve(&mut self, rows: usize) {
        self.table.reserve_rows(rows);
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        let v = &mut self.table.values;
        v.push(s.t);
        for a in &s.bridge.abutments {
            let Some(w) = a.wall else { continue };
            let (d, fill, piles) =
                super::peaks::wall_forces((w, a.line), s.q, s.bridge, s.elements, &s.frame.ground);
            v.extend([d, fill.unwrap_or(0.0), piles.unwrap_or(0.0)]);
        }
    }

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Recorded(self.table)
    }
}

/// Per pier (a bridge with piers only): the cap's displacement relative to the ground (the
/// column's deformation) and the column's spring force on the cap, `−(k0 u − (1 − b) k0 u_p)`
/// (its dashpot left out).
pub(crate) struct PierColumns {
    table: Table,
}

impl PierColumns {
    fn new(bridge: &Bridge) -> Self {
        let mut columns = Vec::new();
        for p in &bridge.piers {
            let name = format!("pier{}", p.joint + 1);
            for (c, unit) in [("ux", "m"), ("uy", "m"), ("fx", "N"), ("fy", "N")] {
                columns.push(Column::new(format!("{name}_{c}"), unit));
            }
        }
        PierColumns {
            table: Table::with_time("piers", columns),
        }
    }
}

impl Observer for PierColumns {
    fn reserve(&mut self, rows: usize) {
        self.table.reserve_rows(rows);
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        let v = &mut self.table.values;
        v.push(s.t);
        for p in &s.bridge.piers {
            let (u, f) = p.drift_and_force(&s.bridge.dofs, s.q, s.elements, &s.frame.ground);
            v.extend([u.x, u.y, -f.x, -f.y]);
        }
    }

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Recorded(self.table)
    }
}

/// Per bearing: deformation and force on its segment (module doc). Derived from the run's `q`
/// when the table is asked for ([`BearingsTable`]); the run records only what `q` does not
/// hold, the committed plastic displacement of each yielding bearing.
pub(crate) struct BearingForces {
    recipe: BearingsTable,
}

impl BearingForces {
    fn new(bridge: &Bridge) -> Self {
        let mut columns = Vec::new();
        let mut yielding: Vec<Vec<Option<usize>>> = bridge
            .bearings
            .iter()
            .map(|b| vec![None; b.len()])
            .collect();
        // the segments' yielding bearings (a pier column is an element of its cap)
        for (e, b) in bridge.elements.bearings.iter().enumerate() {
            if let Some(y) = yielding.get_mut(b.body) {
                y[b.slot] = Some(e);
            }
        }
        let mut bearings = Vec::new();
        for (i, bs) in bridge.bearings.iter().enumerate() {
            for (j, b) in bs.iter().enumerate() {
                let p = format!("segment{}_bearing{}", i + 1, j + 1);
                for (c, unit) in [("ux", "m"), ("uy", "m"), ("fx", "N"), ("fy", "N")] {
                    columns.push(Column::new(format!("{p}_{c}"), unit));
                }
                bearings.push(BearingRecipe {
                    segment: i,
                    line: b.line,
                    base: b.bottom.body(),
                    arm: b.arm(&bridge.bodies),
                    stiffness: b.stiffness,
                    yielding: yielding[i][j].map(|e| {
                        let law = &bridge.elements.bearings[e].law;
                        (e, law.k0(), law.b())
                    }),
                });
            }
        }
        let n_yielding = bridge.elements.bearings.len();
        BearingForces {
            recipe: BearingsTable {
                columns,
                bearings,
                n_yielding,
                plastic: Vec::new(),
                ground: Vec::new(),
            },
        }
    }
}

impl Observer for BearingForces {
    fn reserve(&mut self, rows: usize) {
        let r = &mut self.recipe;
        r.plastic.reserve(rows.saturating_mul(2 * r.n_yielding));
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        for y in &s.elements.bearings {
            self.recipe.plastic.extend([y.state.u_p.x, y.state.u_p.y]);
        }
        let g = &s.frame.ground;
        self.recipe.ground.extend(g.iter().flat_map(|d| [d.x, d.y]));
    }

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Bearings(self.recipe)
    }
}

/// One bearing of [`BearingsTable`]: a bearing from a segment to the ground (its arm from the
/// segment's centroid, its stiffness) and its yielding element (index, `k₀`, `b`).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingRecipe {
    segment: usize,
    /// The support line under it.
    line: usize,
    /// The body under it (a pier cap; `None`: the ground).
    base: Option<usize>,
    arm: Vector,
    stiffness: Real,
    yielding: Option<(usize, Real, Real)>,
}

/// `bearings.csv` derived from a run's `q` rows and the recorded plastic displacements of its
/// yielding bearings (module doc's formulas, the same operations as at the kept step).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingsTable {
    columns: Vec<Column>,
    bearings: Vec<BearingRecipe>,
    /// Yielding bearings of the bridge.
    n_yielding: usize,
    /// Per kept row: `u_p` of every yielding bearing.
    plastic: Vec<Real>,
    /// Per kept row: the support lines' offsets `(d_x, d_y)` (empty when the supports move
    /// together): a bearing on the ground deforms relative to its own support.
    ground: Vec<Real>,
}

impl BearingsTable {
    /// The table over the kept rows `t` (with `q` rows laid out by `dofs`).
    fn table(&self, t: &[Real], q: &[Real], dofs: &Dofs) -> Table {
        let mut out = Table::with_time("bearings", self.columns.clone());
        let n = dofs.len();
        let lines = if t.is_empty() {
            0
        } else {
            self.ground.len() / t.len()
        };
        out.values.reserve(t.len() * (1 + self.columns.len()));
        for (r, &tr) in t.iter().enumerate() {
            let qr = &q[n * r..n * (r + 1)];
            let plastic = &self.plastic[2 * self.n_yielding * r..2 * self.n_yielding * (r + 1)];
            out.values.push(tr);
            for b in &self.bearings {
                // (x − θ r_y, y + θ r_x) of the segment's point, relative to the cap under it
                // (the ground does not move)
                let [x, y, th] = dofs.plan_of(b.segment, qr);
                let mut u = Vector::new(x - th * b.arm.y, y + th * b.arm.x);
                if let Some(c) = b.base {
                    let [xc, yc, _] = dofs.plan_of(c, qr);
                    u -= Vector::new(xc, yc);
                } else if !self.ground.is_empty() {
                    let g = &self.ground[lines * r..lines * (r + 1)];
                    u -= Vector::new(g[2 * b.line], g[2 * b.line + 1]);
                }
                let f = match b.yielding {
                    Some((e, k0, hardening)) => {
                        let u_p = Vector::new(plastic[2 * e], plastic[2 * e + 1]);
                        -(u * k0 - u_p * ((1.0 - hardening) * k0))
                    }
                    None => -u * b.stiffness,
                };
                out.values.extend([u.x, u.y, f.x, f.y]);
            }
        }
        out
    }
}

/// What a run keeps of one observer: its recorded table, or what the table is derived from when
/// asked for (`BridgeSolution::tables`).
#[derive(Debug, Clone, PartialEq)]
pub enum TableSource {
    /// Recorded at every kept step.
    Recorded(Table),
    /// `bearings.csv`, from the `q` rows.
    Bearings(BearingsTable),
}

impl TableSource {
    /// The table, over the run's kept rows `t` and `q` (laid out by `dofs`).
    pub fn table(&self, t: &[Real], q: &[Real], dofs: &Dofs) -> Table {
        match self {
            TableSource::Recorded(table) => table.clone(),
            TableSource::Bearings(b) => b.table(t, q, dofs),
        }
    }

    /// How many values it holds (the memory it keeps during and after the run).
    pub fn kept_values(&self) -> usize {
        match self {
            TableSource::Recorded(table) => table.values.len(),
            TableSource::Bearings(b) => b.plastic.len(),
        }
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

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Recorded(self.table)
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

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Recorded(self.table)
    }
}
