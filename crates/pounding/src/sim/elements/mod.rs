//! Nonlinear structural elements of a bridge in the time stepping: yielding bearings and
//! restrainers ([`crate::element`]).
//!
//! # Scheme
//! A bilinear bearing's force is `f = k0 u − (1 − b) k0 u_p` (`u` its linearised deformation,
//! `u_p` the plastic displacement of its elastic–perfectly-plastic spring): the linear part
//! `k0 u` is in the segment's stiffness `K` (so `Ŵ`, the periods and the Rayleigh damping use the
//! initial stiffness) and the rest is a generalised force `R_p = Σ_b Bᵀ (1 − b) k0 u_p`. A
//! restrainer pulls its two anchor points together with the tension `F(e)` of its elongation
//! `e = |P_b − P_a| − L_0` (exact positions): `R_r = F (n, r_a × n)` on the first segment and
//! `−F (n, r_b × n)` on the second, `n` the unit vector from `P_a` to `P_b`. Over a step they act
//! as the trapezoidal mean `R̄ = ½ (R(q_k) + R̃(q_k + h u_k))` of the committed force and the trial
//! force at the predicted end of the step (return mappings evaluated there, not committed): a
//! predictor–corrector of second order where the laws are smooth (with `R̄ = R(q_k)` the scheme
//! was first order and `viaduct-1d` differed from OpenSees' implicit Newmark by a few % at
//! dt = 1e-4; with the mean it agrees to 0.1 %). For the bearings this is only the first
//! estimate: [`super::yielding`] then solves their return mapping at the actual end of the step
//! together with the momentum balance (the explicit estimate let a stiff bearing carry many times
//! its yield force at a coarse step). After `q_{k+1}` the return mappings commit the new states.
//!
//! # Energy
//! With `R̄` inside the momentum balance the discrete energy balance stays exact when the work
//! done *on* the elements is booked beside the other terms. A segment with yielding bearings
//! books their whole force: `W_b = Σ h ū·(K q_θ − R̄_b)` (its `K` is their initial stiffness,
//! left out of the strain energy `½ qᵀ K q` of the balance), a sum of terms of the size of the
//! bearings' true forces: booking `½ qᵀ K q` and `−Σ h ū·R̄_b` apart made both grow like
//! `½ k0 |u_p|²` of the plastic slide (1e13 J for a stiff bearing under a 2 kJ input), whose
//! rounding was then reported as an energy error. `W_b` splits into what the bearings store,
//! `V_b = Σ ½ b k0 |u|² + ½ (1 − b) k0 |u − u_p|²`, and their hysteretic dissipation
//! `D_h = W_b − V_b` (which tends to the plastic work `Σ f_p·Δu_p` as `h → 0`). The cables'
//! work is `−Σ h ū·(R̄ − R̄_b)` (their stored energy plus, with yield, their plastic work).
//!
//! `members.rs` holds the members and their kinematics, `force.rs` the force over a step, its
//! work and the commit.

mod force;
mod members;

pub(crate) use force::StepForce;
use members::cable_points;
pub(crate) use members::{BackfillAt, Cable, KeyAt, YieldingBearing};

use super::dofs::Dofs;
use crate::math::{Real, Vector};

/// The nonlinear elements and their energy bookkeeping.
#[derive(Debug, Clone, Default)]
pub(crate) struct Elements {
    pub bearings: Vec<YieldingBearing>,
    pub cables: Vec<Cable>,
    /// Backfills behind backwalls.
    pub backfills: Vec<BackfillAt>,
    /// Work done on the backfills.
    pub w_backfill: Real,
    /// Per yielding member: the work done on it, `Σ ½ (f_k + f_{k+1})·(u_{k+1} − u_k)` over the
    /// committed steps (its own share of the bearings' booked work, for reports: on a coupled
    /// system the booking per body splits a bearing on a cap between its two bodies).
    pub w_member: Vec<Real>,
    /// Per yielding member: its committed `(u, f)`.
    pub member_state: Vec<(Vector, Vector)>,
    /// Shear keys at the abutments.
    pub keys: Vec<KeyAt>,
    /// Work done on the shear keys.
    pub w_keys: Real,
    /// Energy absorbed by the yielding bearings (work done on them), per segment.
    pub w_bearings: Vec<Real>,
    /// Work done on the restrainers.
    pub w_cables: Real,
    /// The DOF map of the segments they act on.
    pub dofs: Dofs,
}

impl Elements {
    /// Sets the offsets of the supports under the members on the ground (the time of the
    /// states their deformations are next evaluated at).
    pub fn set_ground(&mut self, ground: &[Vector]) {
        for b in &mut self.bearings {
            if let Some(s) = b.line {
                // a backwall's piles act along its coordinate only
                b.ground = match self.dofs.kind(b.body) {
                    super::dofs::BodyKind::Axial => {
                        let a = self.dofs.axis(b.body);
                        a * ground[s].dot(&a)
                    }
                    _ => ground[s],
                };
            }
        }
        for b in &mut self.backfills {
            b.ground = ground[b.line].dot(&self.dofs.axis(b.body));
        }
        for k in &mut self.keys {
            k.ground = ground[k.line].dot(&k.tangent);
        }
    }

    /// Nothing to do.
    pub fn is_empty(&self) -> bool {
        self.bearings.is_empty()
            && self.cables.is_empty()
            && self.backfills.is_empty()
            && self.keys.is_empty()
    }

    /// The energy yielding member `i` dissipated: the work done on it less what it stores.
    pub fn member_dissipation(&self, i: usize) -> Real {
        let b = &self.bearings[i];
        self.w_member.get(i).copied().unwrap_or(0.0) - b.law.stored_energy(&b.state)
    }

    /// The energy the yielding elements of each of the first `bodies` bodies store in their
    /// committed state (the rest of what they absorbed, [`Elements::w_bearings`], they
    /// dissipated).
    pub fn bearing_stored_energy(&self, bodies: usize) -> Vec<Real> {
        let mut out = vec![0.0; bodies];
        for b in &self.bearings {
            if let Some(e) = out.get_mut(b.body) {
                *e += b.law.stored_energy(&b.state);
            }
        }
        out
    }
}
