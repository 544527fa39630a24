//! The rigid-contact stepper: Moreau–Jean with the impact LCP (module doc of [`super`]).
//!
//! Per step: the active set (joint ends and abutment corners whose predicted gap
//! `g_i(q_k) + h γ_N,i(u_k) ≤ 0`), the Delassus matrix `G = Wᵀ Ŵ⁻¹ W`, the LCP of spec §8 solved
//! by Lemke (fixed-size kernels; enumeration, then the frictionless LCP as fallbacks), the
//! impulses applied `u_{k+1} = u_free + Ŵ⁻¹ W P`, the post-solve law check
//! ([`crate::law_check::check_laws`]) and the contact dissipation `−½ (γ_k + γ_{k+1})·P`.
//! More than [`MAX_FIXED_CONTACTS`] active contacts (permanent contact at several joints) are
//! first given to the block Gauss–Seidel of [`crate::lcp::fc2d`], whose answer is verified
//! before it is used; Lemke is the fallback.
//!
//! `solve.rs` holds the LCP and its fallbacks, `impulse.rs` the assembly, the impulses and the
//! bookkeeping of a step with active contacts.
#![allow(clippy::needless_range_loop)]

mod impulse;
mod solve;

use super::contact::{Direction, State, dot_dir};
use super::driver::{ImpactLog, StepInput, StepOutput, Stepper, StepperStats};
use super::{SimContact, SimSettings};
use crate::analytic::ImpactLaw;
use crate::lcp::LemkeSettings;
use crate::math::Real;

/// Most contacts solved with the size-specialised Lemke kernels (LCP size ≤ 18); larger
/// active sets (several joints closing at once) use the dynamic kernel.
const MAX_FIXED_CONTACTS: usize = 6;
/// An active contact: what it is, its site (joint index or abutment side), its impact law and
/// its `w_N`, `w_T`.
struct ActiveContact {
    contact: SimContact,
    site: usize,
    law: ImpactLaw,
    wn: Direction,
    wt: Direction,
    /// The struck face's normal and tangential velocities at `t_k` and `t_{k+1}`
    /// `[v_n, v_t, v_n', v_t']` when it moves with a support of its own (zero otherwise): the
    /// law acts on the velocities relative to it.
    face: [Real; 4],
}

/// The active contacts' directions and velocities (order `N_1..N_n, T_1..T_n`).
struct Assembled {
    n: usize,
    /// Dense columns of `W`.
    wcols: Vec<State>,
    /// `Ŵ⁻¹ W`.
    wiw: Vec<State>,
    /// Delassus `G = Wᵀ Ŵ⁻¹ W`.
    g: Vec<Vec<Real>>,
    gam_pre: Vec<Real>,
    gam_free: Vec<Real>,
}

/// `Σ_d a_d b_d` left to right (the sum of the dense two-deck columns).
#[inline]
fn dot_seq(a: &State, b: &State) -> Real {
    a.iter().zip(b.iter()).map(|(x, y)| x * y).sum()
}

/// The rigid-contact stepper (module doc).
pub(crate) struct RigidStepper {
    /// Impact law of each joint.
    joint_laws: Vec<ImpactLaw>,
    /// Impact law of the start and end abutments.
    abutment_laws: [ImpactLaw; 2],
    impact_velocity: Real,
    lemke: LemkeSettings,
    d_cont: Real,
    stats: StepperStats,
    /// Per joint and abutment side: handled here (a mixed bridge's compliance sites are not).
    on: (Vec<bool>, [bool; 2]),
    /// The storage of the next step's `u_{k+1}` ([`Stepper::recycle`]).
    spare: Option<State>,
}

impl RigidStepper {
    /// The stepper with an impact law per joint and per abutment side.
    pub fn with_laws(
        joint_laws: Vec<ImpactLaw>,
        abutment_laws: [ImpactLaw; 2],
        settings: &SimSettings,
    ) -> Self {
        RigidStepper {
            joint_laws,
            abutment_laws,
            impact_velocity: settings.impact_velocity,
            lemke: settings.lemke.clone(),
            d_cont: 0.0,
            stats: StepperStats::default(),
            on: (Vec::new(), [true; 2]),
            spare: None,
        }
    }

    /// Handles only the joints `k` with `joints[k]` and the abutment sides with `abutments[side]`
    /// (the rigid sites of a mixed bridge).
    pub fn only(mut self, joints: Vec<bool>, abutments: [bool; 2]) -> Self {
        self.on = (joints, abutments);
        self
    }

    fn joint_on(&self, k: usize) -> bool {
        self.on.0.get(k).copied().unwrap_or(true)
    }

    /// Contacts whose predicted gap `g + h γ_N(u_k) ≤ 0`: joint ends in joint order, then the
    /// abutment corners.
    #[inline(always)]
    fn active_set(&self, inp: &StepInput) -> Vec<ActiveContact> {
        let (fr, br, u, h) = (inp.frame, inp.bridge, inp.u, inp.scheme.h);
        let (pose, bodies) = (&fr.pose, &br.bodies);
        let mut active = Vec::new();
        for (k, (jg, jf)) in br.joints.iter().zip(&fr.joints).enumerate() {
            if !self.joint_on(k) {
                continue;
            }
            for s in jf.sel.iter().flatten() {
                let c = &jf.cands[*s];
                // the tangent direction only for an active contact
                let wn = c.direction(pose, jg, c.normal);
                if c.gap + h * dot_dir(&wn, u, &br.dofs) <= 0.0 {
                    active.push(ActiveContact {
                        contact: SimContact::Joint(c.case),
                        site: k,
                        law: self.joint_laws[k],
                        wn,
                        wt: c.direction(pose, jg, c.tangent),
                        face: [0.0; 4],
                    });
                }
            }
        }
        for ab in br.abutments.iter().filter(|ab| self.on.1[ab.side]) {
            let (j, n, tn) = (ab.body, ab.normal, ab.tangent);
            let (shift, face) = match (ab.wall, inp.ground) {
                // a ground face that moves with its support
                (None, Some(o)) => {
                    let (v0, v1) = (o.v[ab.line], o.v1[ab.line]);
                    (
                        ab.shift_on(&br.dofs, inp.q.as_slice(), &o.d),
                        [v0.dot(&n), v0.dot(&tn), v1.dot(&n), v1.dot(&tn)],
                    )
                }
                _ => (ab.shift(&br.dofs, inp.q.as_slice()), [0.0; 4]),
            };
            for (k, c0) in ab.corners.iter().enumerate() {
                let pc = pose.place(bodies, j, c0);
                let r = pc - pose.g[j];
                let wn = ab.direction(n, &r);
                let closing = dot_dir(&wn, u, &br.dofs) - face[0];
                if (pc - ab.point).dot(&n) + shift + h * closing <= 0.0 {
                    let wt = ab.direction(tn, &r);
                    let contact = SimContact::Abutment {
                        deck: ab.side + 1,
                        corner: k,
                    };
                    active.push(ActiveContact {
                        contact,
                        site: ab.side,
                        law: self.abutment_laws[ab.side],
                        wn,
                        wt,
                        face,
                    });
                }
            }
        }
        active
    }
}

impl Stepper for RigidStepper {
    fn contact_forces(&self) -> Option<&[[Real; 2]]> {
        None
    }

    fn contact_energy(&self) -> Real {
        self.d_cont
    }

    fn adjust_contact_energy(&mut self, delta: Real) {
        self.d_cont += delta;
    }

    #[inline]
    fn step(&mut self, inp: &StepInput, log: &mut ImpactLog) -> StepOutput {
        let mut u_new = match self.spare.take() {
            Some(mut s) if s.len() == inp.u_free.len() => {
                s.copy_from(inp.u_free);
                s
            }
            _ => inp.u_free.clone(),
        };
        let active = self.active_set(inp);
        let mut impulse = None;
        if !active.is_empty() {
            impulse = Some(self.resolve(inp, &active, &mut u_new, log));
        }
        StepOutput {
            u: u_new,
            penetration: Real::NEG_INFINITY,
            impulse,
        }
    }

    fn recycle(&mut self, u: State) {
        self.spare = Some(u);
    }

    fn finish(&mut self, _log: &mut ImpactLog) -> StepperStats {
        std::mem::take(&mut self.stats)
    }

    fn projected_sites(&self) -> Option<super::projection::Sites> {
        Some(super::projection::Sites {
            joints: self.on.0.clone(),
            abutments: self.on.1,
        })
    }
}
