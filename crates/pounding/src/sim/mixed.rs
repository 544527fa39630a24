//! A bridge whose contact sites mix rigid impact laws and compliance laws (e.g. rigid joints
//! and abutments on a bilinear backfill law).
//!
//! # Coupling rule
//! One step of the θ-method holds both kinds at once:
//! ```text
//! u_{k+1} = u_free + h Ŵ⁻¹ ((1−θ) R_k + θ R(u_{k+1})) + Ŵ⁻¹ W_r P
//! ```
//! with `R` the compliance sites' forces (their trapezoidal mean, [`super::compliance`]) and `P`
//! the rigid sites' impulses, complementary to the post-impact velocities of the rigid active
//! contacts (the impact LCP of [`super::rigid`], whose active set is fixed by the predicted gaps
//! at the start of the step). It is solved by a block Gauss–Seidel iteration on the velocity
//! jump of the impulses `Δu_r = Ŵ⁻¹ W_r P`: the compliance Newton solve with the free velocity
//! `u_free + Δu_r` gives `u_c`; the impact LCP with the free velocity `u_c − Δu_r` gives `u_r`
//! and the new `Δu_r = u_r − (u_c − Δu_r)`; until `Δu_r` changes by at most
//! `1e-12 max(|u_r|_∞, 1 mm/s)` (at most [`MAX_COUPLING_ITERATIONS`]). At the fixed point both
//! sets of conditions hold at the same `u_{k+1}`, so each stepper's energy term (the compliance
//! work `−h ū·R̄` and the impact dissipation `−½ (γ_k + γ_{k+1})·P`) is booked at the end
//! velocity and the discrete energy balance stays exact up to the iteration's tolerance. A step
//! that does not converge keeps the last iterate and counts as a Newton failure (status
//! `CompletedWithNewtonFailures`). Without a rigid contact in the step `Δu_r = 0` and one
//! compliance solve is the whole step.

use super::compliance::ComplianceStepper;
use super::contact::State;
use super::driver::{ImpactLog, StepInput, StepOutput, Stepper, StepperStats};
use super::rigid::RigidStepper;
use crate::math::Real;

/// Most Gauss–Seidel passes of one step.
pub const MAX_COUPLING_ITERATIONS: usize = 50;

/// The stepper of a bridge with rigid and compliance sites.
pub(crate) struct MixedStepper {
    rigid: RigidStepper,
    compliance: ComplianceStepper,
    /// Per joint of the bridge: its index among the compliance stepper's sites, if compliant.
    joint_site: Vec<Option<usize>>,
    /// Per present abutment (start before end): its compliance site, if compliant.
    abutment_site: Vec<Option<usize>>,
    /// Forces of every joint, then of every present abutment, in bridge order (NaN at the
    /// rigid sites).
    forces: Vec<[Real; 2]>,
    /// Steps whose coupling iteration did not converge.
    failures: usize,
}

impl MixedStepper {
    /// The two steppers (each restricted to its sites) and, per joint and per present abutment,
    /// the compliance site it is (`None`: rigid).
    pub fn new(
        rigid: RigidStepper,
        compliance: ComplianceStepper,
        joint_site: Vec<Option<usize>>,
        abutment_site: Vec<Option<usize>>,
    ) -> Self {
        let n = joint_site.len() + abutment_site.len();
        let mut s = MixedStepper {
            rigid,
            compliance,
            joint_site,
            abutment_site,
            forces: vec![[Real::NAN; 2]; n],
            failures: 0,
        };
        s.set_forces();
        s
    }

    fn set_forces(&mut self) {
        let Some(f) = self.compliance.contact_forces() else {
            return;
        };
        let slots = self.joint_site.iter().chain(&self.abutment_site);
        for (out, slot) in self.forces.iter_mut().zip(slots) {
            *out = slot.map_or([Real::NAN; 2], |i| f[i]);
        }
    }
}

impl Stepper for MixedStepper {
    fn contact_forces(&self) -> Option<&[[Real; 2]]> {
        Some(&self.forces)
    }

    fn contact_energy(&self) -> Real {
        self.rigid.contact_energy() + self.compliance.contact_energy()
    }

    fn adjust_contact_energy(&mut self, delta: Real) {
        self.rigid.adjust_contact_energy(delta);
    }

    fn step(&mut self, inp: &StepInput, log: &mut ImpactLog) -> StepOutput {
        let mut du = State::zeros(inp.u.len());
        let mut converged = false;
        let mut solved = None;
        for _ in 0..MAX_COUPLING_ITERATIONS {
            let free_c = inp.u_free + &du;
            let (u_c, ev, how) = self.compliance.solve_step(&StepInput {
                u_free: &free_c,
                ..*inp
            });
            let free_r = &u_c - &du;
            let u_r = self.rigid.solve_step(&StepInput {
                u_free: &free_r,
                ..*inp
            });
            let du_new = &u_r - &free_r;
            let change = (&du_new - &du).amax();
            du = du_new;
            solved = Some((u_c, ev, how, free_r));
            if change <= 1e-12 * u_r.amax().max(1e-3) {
                converged = true;
                break;
            }
        }
        if !converged {
            self.failures += 1;
        }
        // the last pass again, committed: the same impact LCP, so the same `u_r`
        let (u_c, ev, how, free_r) = solved.expect("at least one pass");
        let out_c = self.compliance.commit(inp, u_c, ev, how, log);
        let out_r = self.rigid.step(
            &StepInput {
                u_free: &free_r,
                ..*inp
            },
            log,
        );
        self.set_forces();
        let impulse = match (out_c.impulse, out_r.impulse) {
            (Some(c), Some(r)) => Some(c + r),
            (c, r) => c.or(r),
        };
        StepOutput {
            u: out_r.u,
            penetration: out_c.penetration,
            impulse,
        }
    }

    fn finish(&mut self, log: &mut ImpactLog) -> StepperStats {
        let r = self.rigid.finish(log);
        let c = self.compliance.finish(log);
        StepperStats {
            lcp_solves: r.lcp_solves,
            lcp_enumeration_fallbacks: r.lcp_enumeration_fallbacks,
            lcp_failures: r.lcp_failures,
            newton_failures: c.newton_failures + self.failures,
            closure_steps: c.closure_steps,
            bearing_corrections: 0,
            time_step_advice: c.time_step_advice,
        }
    }

    fn projected_sites(&self) -> Option<super::projection::Sites> {
        self.rigid.projected_sites()
    }
}
