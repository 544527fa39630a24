//! What an observer sees and what it keeps: the [`Snapshot`] of a kept step, the [`Observer`]
//! trait, and the [`TableSource`] a run returns of each.

use super::bearings_table::BearingsTable;
use crate::math::Real;
use crate::sim::dofs::Dofs;
use crate::sim::elements::Elements;
use crate::sim::step_loads::StepLoads;
use crate::sim::table::Table;
use crate::sim::view::{Bridge, Frame};

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
    pub loads: &'a StepLoads,
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
