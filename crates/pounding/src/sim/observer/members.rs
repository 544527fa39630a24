//! The recorded tables of the links and substructures: restrainers ([`RestrainerForces`]), the
//! joints' slip ([`JointSlip`]), pier columns ([`PierColumns`]), backwalls ([`Backwalls`]) and
//! shear keys ([`ShearKeys`]).

use super::observe::{Observer, Snapshot, TableSource};
use crate::sim::table::{Column, Table};
use crate::sim::view::Bridge;

/// Per restrainer: elongation and tension (module doc).
pub(crate) struct RestrainerForces {
    table: Table,
}

impl RestrainerForces {
    pub(super) fn new(bridge: &Bridge) -> Self {
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
    pub(super) fn new(bridge: &Bridge) -> Self {
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
/// Per pier (a bridge with piers only): the cap's displacement relative to the ground (the
/// column's deformation) and the column's spring force on the cap, `−(k0 u − (1 − b) k0 u_p)`
/// (its dashpot left out).
pub(crate) struct PierColumns {
    table: Table,
}

impl PierColumns {
    pub(super) fn new(bridge: &Bridge) -> Self {
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

/// Per abutment with a backwall: the wall's displacement into the soil, its backfill's force
/// (≥ 0, resisting) and its piles' force along the same axis (a bridge with backwalls only).
pub(crate) struct Backwalls {
    table: Table,
}

impl Backwalls {
    pub(super) fn new(bridge: &Bridge) -> Self {
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
            let (d, fill, piles) = crate::sim::peaks::wall_forces(
                (w, a.line),
                s.q,
                s.bridge,
                s.elements,
                &s.frame.ground,
            );
            v.extend([d, fill.unwrap_or(0.0), piles.unwrap_or(0.0)]);
        }
    }

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Recorded(self.table)
    }
}

/// Per abutment with shear keys: the deck end's transverse displacement `v` relative to the
/// abutment and the keys' force `F` (on the abutment; `−F` on the deck).
pub(crate) struct ShearKeys {
    table: Table,
}

impl ShearKeys {
    pub(super) fn new(bridge: &Bridge) -> Self {
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
