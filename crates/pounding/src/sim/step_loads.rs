//! The load path of each deck segment: every force acting on it, by member, as the integrator
//! applies it, summed over the steps between kept rows ([`StepLoads`], which the driver feeds;
//! the observer `SegmentForces` writes `segment_forces.csv` from it).
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
use super::elements::StepForce;
use super::excitation::Offsets;
use super::scheme::Scheme;
use super::view::Bridge;
use crate::math::Real;

/// The kinds of member a segment's forces come from, in column order (shear keys only when the
/// bridge has some).
pub(crate) const KINDS: [&str; 5] = [
    "bearings",
    "dashpots",
    "restrainers",
    "shear_keys",
    "contact",
];
/// Indices into [`KINDS`] (the sums of [`StepLoads`] are laid out in that order).
const BEARINGS: usize = 0;
const DASHPOTS: usize = 1;
const SHEAR_KEYS: usize = 3;

/// The kinds `segment_forces.csv` records for `bridge`, indices into [`KINDS`]: every kind, shear
/// keys only in a bridge with some.
pub(crate) fn recorded_kinds(bridge: &Bridge) -> Vec<usize> {
    (0..KINDS.len())
        .filter(|&k| k != SHEAR_KEYS || !bridge.elements.keys.is_empty())
        .collect()
}

/// The forces on each segment summed over the steps since the last kept row.
///
/// Every step adds only `q_k` and `ū_θ` to two sums ([`Self::add_step`], inlined into the time
/// loop: two additions per coordinate); the members that only some runs have (elements, moving
/// supports, a contact impulse) add their parts out of line ([`Self::add_members`]). At a kept row
/// ([`Self::close`]) the linear operators act once on the sums, since they are linear:
/// `Σ (−K q_θ) = −K (Σ q_k + θ h Σ ū_θ)` and `Σ (−C ū_θ) = −C Σ ū_θ`; then the means that the
/// observer reads.
pub(crate) struct StepLoads {
    /// The segments' coordinates: `0..m` (the first bodies').
    m: usize,
    /// `Σ q_k` and `Σ ū_θ` over the steps, every coordinate (`K` and `C` couple a segment to the
    /// caps under it).
    q_sum: State,
    u_sum: State,
    /// Per kind, `m` sums over the steps (kind-major) of what [`Self::add_members`] adds: the
    /// bearings' held part `R̄_b` and the supports' `P_K d̄`, their `P_C v̄`, the cables', the
    /// keys', the contact impulse / `h`.
    sums: Vec<Real>,
    /// `sums` holds something (cleared at a row only then).
    members: bool,
    /// Steps summed.
    steps: usize,
    /// The means at the last kept row, in `segment_forces.csv`'s column order: per segment, per
    /// kind recorded ([`recorded_kinds`]), `(F_x, F_y, M_z)`.
    row: Vec<Real>,
    /// Per entry of `row`: its sum's index in `sums` and its linear part's in `lin`.
    src: Vec<(u32, u32)>,
    /// `[K Σ q_θ (m), C Σ ū_θ (m), 0]`: the linear parts a row entry subtracts.
    lin: Vec<Real>,
    /// Scratch: `Σ q_θ`, `K Σ q_θ`, `C Σ ū_θ`, a product's second part, `P_K d̄`, `P_C v̄`.
    q_th: State,
    kq: State,
    cu: State,
    scratch: State,
    pk: State,
    pc: State,
}

impl StepLoads {
    /// Nothing summed, for the segments of `bridge`.
    pub fn new(bridge: &Bridge) -> Self {
        let n = bridge.dofs.len();
        let segments = bridge.bodies.len();
        let m = if segments == 0 {
            0
        } else {
            bridge.dofs.range(segments - 1).end
        };
        let kinds = recorded_kinds(bridge);
        // per segment, kind, coordinate: the sum and the linear part its mean takes
        let mut src = Vec::new();
        for j in 0..segments {
            for &kind in &kinds {
                for i in bridge.dofs.range(j) {
                    let lin = match kind {
                        BEARINGS => i,
                        DASHPOTS => m + i,
                        _ => 2 * m,
                    };
                    src.push(((kind * m + i) as u32, lin as u32));
                }
            }
        }
        StepLoads {
            m,
            q_sum: State::zeros(n),
            u_sum: State::zeros(n),
            sums: vec![0.0; KINDS.len() * m],
            members: false,
            steps: 0,
            row: vec![0.0; src.len()],
            src,
            lin: vec![0.0; 2 * m + 1],
            q_th: State::zeros(n),
            kq: State::zeros(n),
            cu: State::zeros(n),
            scratch: State::zeros(n),
            pk: State::zeros(n),
            pc: State::zeros(n),
        }
    }

    /// Adds step `k → k+1` (module doc): `q = q_k`, `u_th = ū_θ` (after the ledger's update).
    #[inline(always)]
    pub fn add_step(&mut self, q: &State, u_th: &State) {
        // plain slices (nalgebra's iterators step by strides): the loop vectorises
        let sums = self.q_sum.as_mut_slice().iter_mut();
        let sums = sums.zip(self.u_sum.as_mut_slice().iter_mut());
        for ((qs, us), (q, u)) in sums.zip(q.as_slice().iter().zip(u_th.as_slice())) {
            *qs += q;
            *us += u;
        }
        self.steps += 1;
    }

    /// Adds the parts of step `k → k+1` of the members only some runs have: `el` the elements'
    /// force of the step (`None`: no elements), `impulse` the contact impulse, `offs` the
    /// supports' offsets over the step when they move apart.
    #[inline(never)]
    pub fn add_members(
        &mut self,
        sc: &Scheme,
        el: Option<&StepForce>,
        impulse: Option<&State>,
        offs: Option<&Offsets>,
    ) {
        let m = self.m;
        self.members = true;
        let (bear, rest) = self.sums.split_at_mut(m);
        let (dash, rest) = rest.split_at_mut(m);
        let (cables, rest) = rest.split_at_mut(m);
        let (keys, contact) = rest.split_at_mut(m);
        if let (Some(o), Some(d)) = (offs, &sc.dense) {
            d.support_parts(sc.th, o, (&mut self.pk, &mut self.pc));
            for i in 0..m {
                bear[i] += self.pk[i];
                dash[i] += self.pc[i];
            }
        }
        if let Some(el) = el {
            for i in 0..m {
                let (b, c, k) = el.parts(i);
                bear[i] += b;
                cables[i] += c;
                keys[i] += k;
            }
        }
        if let Some(p) = impulse {
            let p = &p.as_slice()[..m];
            for i in 0..m {
                contact[i] += p[i] / sc.h;
            }
        }
    }

    /// At a kept row: the means of the steps summed since the previous one (zero before any
    /// step), then the sums cleared.
    pub fn close(&mut self, sc: &Scheme) {
        if self.steps == 0 {
            self.row.fill(0.0);
            return;
        }
        let c = sc.th * sc.h;
        let sums = self.q_sum.as_slice().iter().zip(self.u_sum.as_slice());
        for (qt, (qs, us)) in self.q_th.as_mut_slice().iter_mut().zip(sums) {
            *qt = qs + us * c;
        }
        sc.stiffness_into(&self.q_th, &mut self.kq, &mut self.scratch);
        sc.damping_power(&self.u_sum, &mut self.cu);
        let (n, m) = (self.steps as Real, self.m);
        self.lin[..m].copy_from_slice(&self.kq.as_slice()[..m]);
        self.lin[m..2 * m].copy_from_slice(&self.cu.as_slice()[..m]);
        let (sums, lin) = (&self.sums, &self.lin);
        for (out, &(s, l)) in self.row.iter_mut().zip(&self.src) {
            *out = (sums[s as usize] - lin[l as usize]) / n;
        }
        self.q_sum.as_mut_slice().fill(0.0);
        self.u_sum.as_mut_slice().fill(0.0);
        if self.members {
            self.sums.fill(0.0);
            self.members = false;
        }
        self.steps = 0;
    }

    /// The means at the last kept row, in `segment_forces.csv`'s column order (per segment, per
    /// kind of [`recorded_kinds`], `(F_x, F_y, M_z)`).
    pub fn row(&self) -> &[Real] {
        &self.row
    }
}
