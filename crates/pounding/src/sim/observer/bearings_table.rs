//! `bearings.csv` as a function of a run's kept `q` rows and the yielding bearings' recorded
//! plastic displacements ([`super::BearingForces`] records what `q` does not hold).

use crate::math::{Real, Vector};
use crate::sim::dofs::Dofs;
use crate::sim::table::{Column, Table};

/// One bearing of [`BearingsTable`]: a bearing from a segment to the ground (its arm from the
/// segment's centroid, its stiffness) and its yielding element (index, `k₀`, `b`).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingRecipe {
    pub(super) segment: usize,
    /// The support line under it.
    pub(super) line: usize,
    /// The body under it (a pier cap; `None`: the ground).
    pub(super) base: Option<usize>,
    pub(super) arm: Vector,
    pub(super) stiffness: Real,
    pub(super) yielding: Option<(usize, Real, Real)>,
}

/// `bearings.csv` derived from a run's `q` rows and the recorded plastic displacements of its
/// yielding bearings (module doc's formulas, the same operations as at the kept step).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingsTable {
    pub(super) columns: Vec<Column>,
    pub(super) bearings: Vec<BearingRecipe>,
    /// Yielding bearings of the bridge.
    pub(super) n_yielding: usize,
    /// Per kept row: `u_p` of every yielding bearing.
    pub(super) plastic: Vec<Real>,
    /// Per kept row: the support lines' offsets `(d_x, d_y)` (empty when the supports move
    /// together): a bearing on the ground deforms relative to its own support.
    pub(super) ground: Vec<Real>,
}

impl BearingsTable {
    /// The table over the kept rows `t` (with `q` rows laid out by `dofs`).
    pub(super) fn table(&self, t: &[Real], q: &[Real], dofs: &Dofs) -> Table {
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
