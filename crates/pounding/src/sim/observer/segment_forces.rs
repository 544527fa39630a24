//! [`SegmentForces`] (`segment_forces.csv`): per segment and member kind, the mean force over the
//! steps since the previous row, from the driver's [`StepLoads`](crate::sim::step_loads::StepLoads) (whose doc gives each force and
//! the balance they close).

use super::observe::{Observer, Snapshot, TableSource};
use crate::sim::step_loads::{KINDS, recorded_kinds};
use crate::sim::table::{Column, Table};
use crate::sim::view::Bridge;

/// `segment_forces.csv`: per segment and member kind, the mean force `(F_x, F_y, M_z)` over the
/// steps since the previous row (module doc).
pub(crate) struct SegmentForces {
    table: Table,
}

impl SegmentForces {
    /// The columns of the segments of `bridge`, for the kinds its `StepLoads` records (the
    /// order of `StepLoads::row`).
    pub fn new(bridge: &Bridge) -> Self {
        let mut columns = Vec::new();
        for i in 1..=bridge.bodies.len() {
            for &k in &recorded_kinds(bridge) {
                let p = format!("segment{i}_{}", KINDS[k]);
                columns.push(Column::new(format!("{p}_fx"), "N"));
                columns.push(Column::new(format!("{p}_fy"), "N"));
                columns.push(Column::new(format!("{p}_mz"), "Nm"));
            }
        }
        SegmentForces {
            table: Table::with_time("segment_forces", columns),
        }
    }
}

impl Observer for SegmentForces {
    fn reserve(&mut self, rows: usize) {
        self.table.reserve_rows(rows);
    }

    fn observe(&mut self, s: &Snapshot<'_>) {
        let v = &mut self.table.values;
        v.push(s.t);
        v.extend_from_slice(s.loads.row());
    }

    fn into_source(self: Box<Self>) -> TableSource {
        TableSource::Recorded(self.table)
    }
}

/// The values per kept row of [`SegmentForces`] for a bridge of `segments` segments (with shear
/// keys or not): for the memory estimate.
pub(crate) fn values_per_row(segments: usize, shear_keys: bool) -> usize {
    segments * 3 * (KINDS.len() - usize::from(!shear_keys))
}
