//! [`BearingForces`]: each bearing's deformation and force on its segment (`bearings.csv`, the
//! module doc of [`super`]).

use super::bearings_table::{BearingRecipe, BearingsTable};
use super::observe::{Observer, Snapshot, TableSource};
use crate::sim::table::Column;
use crate::sim::view::Bridge;

/// Per bearing: deformation and force on its segment (module doc). Derived from the run's `q`
/// when the table is asked for ([`BearingsTable`]); the run records only what `q` does not
/// hold, the committed plastic displacement of each yielding bearing.
pub(crate) struct BearingForces {
    recipe: BearingsTable,
}

impl BearingForces {
    pub(super) fn new(bridge: &Bridge) -> Self {
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
