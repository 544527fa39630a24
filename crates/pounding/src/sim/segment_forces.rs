//! The load path of each deck segment: every force acting on it, by member, as the integrator
//! applies it (`segment_forces.csv`).
//!
//! # What a row holds
//! One step `k → k+1` of the θ-method (θ = ½ by default) is the momentum balance of every
//! segment, `x`, `y` and the moment about its centroid:
//! ```text
//! M (u_{k+1} − u_k)/h + M r ā_g = F̄_bearings + F̄_dashpots + F̄_restrainers + F̄_shear_keys + F̄_contact
//! ```
//! (`ā_g = (1−θ) a_g,k + θ a_g,k+1`, so the left side is the mass times the segment's mean
//! *absolute* acceleration over the step), with each force the one the scheme applies over the
//! step:
//! - bearings: `−K q_θ + R̄_b` with `q_θ = q_k + θ h ū_θ` (for θ = ½ the mean of the linear
//!   bearings' forces at both ends of the step, `½ (f_k + f_{k+1})`), `R̄_b` the yielding
//!   bearings' held plastic part (solved at the end of the step, [`super::yielding`]): for
//!   θ = ½, again the mean of `bearings.csv`'s forces at `t_k` and `t_{k+1}`; on ground that moves
//!   with its own support line, plus `P_K d̄`;
//! - dashpots: `−C ū_θ` (`ū_θ = (1−θ) u_k + θ u_{k+1}`), the force of whatever the damping model
//!   is (the bearings' dashpots, or Rayleigh damping `C = a₀ M + a₁ K`), plus `P_C v̄` on moving
//!   supports;
//! - restrainers and shear keys: their held forces `(1−θ) R(q_k) + θ R̃(q_k + h u_k)`, the mean of
//!   the committed force and the trial force at the predicted end of the step
//!   ([`super::elements`]): this is **not** the mean of `restrainers.csv`'s committed forces at
//!   both ends of the step (those are taken at the actual end), so only this table balances the
//!   step exactly;
//! - contact: a compliance law's mean force `(1−θ) R_k + θ R_{k+1}` (joints and abutments); the
//!   rigid law's impulse `W P` of the step divided by `h` (the mean force the impulse stands
//!   for).
//!
//! A row at `t` holds the mean of each force over the steps since the previous row (the history
//! stride; every step with `history_every = 1`), i.e. the impulse over that interval divided by
//! its length, so that the balance holds over the interval with `(u(t) − u(t_prev))/Δt`. The
//! first row (`t = 0`, no step yet) is zero.

use super::contact::State;
use super::dofs::Dofs;
use super::elements::StepForce;
use super::excitation::Offsets;
use super::observer::{Observer, Snapshot};
use super::scheme::{Scheme, Work};
use super::table::{Column, Table, TableSource};
use super::view::Bridge;
use crate::math::Real;

/// The kinds of member a segment's forces come from, in column order (shear keys only when the
/// bridge has some).
const KINDS: [&str; 5] = [
    "bearings",
    "dashpots",
    "restrainers",
    "shear_keys",
    "contact",
];
const SHEAR_KEYS: usize = 3;

/// The forces on each segment summed over the steps since the last kept row (the driver adds
/// every step and clears it after the observers have read it).
pub(crate) struct StepLoads {
    /// The DOF map (segments are the first bodies).
    dofs: Dofs,
    segments: usize,
    /// Per segment and kind: `(F_x, F_y, M_z)` summed over [`Self::steps`] steps.
    sum: Vec<[Real; 3]>,
    /// Steps summed.
    steps: usize,
    /// Scratch: `q_θ`, `K q_θ`, a product's second part, `P_K d̄`, `P_C v̄`.
    q_th: State,
    kq: State,
    scratch: State,
    pk: State,
    pc: State,
}

impl StepLoads {
    /// Nothing summed, for the segments of `bridge`.
    pub fn new(bridge: &Bridge) -> Self {
        let n = bridge.dofs.len();
        let segments = bridge.bodies.len();
        StepLoads {
            dofs: bridge.dofs.clone(),
            segments,
            sum: vec![[0.0; 3]; segments * KINDS.len()],
            steps: 0,
            q_th: State::zeros(n),
            kq: State::zeros(n),
            scratch: State::zeros(n),
            pk: State::zeros(n),
            pc: State::zeros(n),
        }
    }

    /// Adds the forces of step `k → k+1` (module doc): `q = q_k`, `w` after the ledger's
    /// update (`ū_θ` in `w.u_th`, `C ū_θ` in `w.cv`), `el` the elements' force of the step
    /// (`None`: no elements), `impulse` the contact impulse, `offs` the supports' offsets over
    /// the step when they move apart.
    pub fn add_step(
        &mut self,
        sc: &Scheme,
        q: &State,
        w: &Work,
        el: Option<&StepForce>,
        impulse: Option<&State>,
        offs: Option<&Offsets>,
    ) {
        let (h, th) = (sc.h, sc.th);
        for i in 0..q.len() {
            self.q_th[i] = q[i] + w.u_th[i] * (th * h);
        }
        sc.stiffness_into(&self.q_th, &mut self.kq, &mut self.scratch);
        let moving = match (offs, &sc.dense) {
            (Some(o), Some(d)) => {
                d.support_parts(th, o, (&mut self.pk, &mut self.pc));
                true
            }
            _ => false,
        };
        for j in 0..self.segments {
            for (d, i) in self.dofs.range(j).enumerate() {
                let mut f = [0.0; 5];
                f[0] = -self.kq[i];
                f[1] = -w.cv[i];
                if moving {
                    f[0] += self.pk[i];
                    f[1] += self.pc[i];
                }
                if let Some(el) = el {
                    let (b, cables, keys) = el.parts(i);
                    f[0] += b;
                    f[2] = cables;
                    f[SHEAR_KEYS] = keys;
                }
                if let Some(p) = impulse {
                    f[4] = p[i] / h;
                }
                for (kind, fk) in f.iter().enumerate() {
                    self.sum[j * KINDS.len() + kind][d] += fk;
                }
            }
        }
        self.steps += 1;
    }

    /// The mean force of `kind` on segment `j` over the steps summed (zero before any step).
    fn mean(&self, j: usize, kind: usize) -> [Real; 3] {
        let s = self.sum[j * KINDS.len() + kind];
        if self.steps == 0 {
            return [0.0; 3];
        }
        let n = self.steps as Real;
        [s[0] / n, s[1] / n, s[2] / n]
    }

    /// Clears the sums (after a kept row).
    pub fn clear(&mut self) {
        self.sum.fill([0.0; 3]);
        self.steps = 0;
    }
}

/// `segment_forces.csv`: per segment and member kind, the mean force `(F_x, F_y, M_z)` over the
/// steps since the previous row (module doc).
pub(crate) struct SegmentForces {
    table: Table,
    /// The kinds recorded (shear keys only in a bridge with some).
    kinds: Vec<usize>,
}

impl SegmentForces {
    /// The columns of the segments of `bridge`.
    pub fn new(bridge: &Bridge) -> Self {
        let kinds: Vec<usize> = (0..KINDS.len())
            .filter(|&k| k != SHEAR_KEYS || !bridge.elements.keys.is_empty())
            .collect();
        let mut columns = Vec::new();
        for i in 1..=bridge.bodies.len() {
            for &k in &kinds {
                let p = format!("segment{i}_{}", KINDS[k]);
                columns.push(Column::new(format!("{p}_fx"), "N"));
                columns.push(Column::new(format!("{p}_fy"), "N"));
                columns.push(Column::new(format!("{p}_mz"), "Nm"));
            }
        }
        SegmentForces {
            table: Table::with_time("segment_forces", columns),
            kinds,
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
        for j in 0..s.loads.segments {
            for &k in &self.kinds {
                v.extend(s.loads.mean(j, k));
            }
        }
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
