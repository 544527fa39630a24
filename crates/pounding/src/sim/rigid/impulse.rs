//! The impacts of a rigid step with active contacts: the assembly of `W`, `Ŵ⁻¹ W` and the
//! Delassus matrix, the impulses applied to the velocities, the post-solve law check, the
//! contact dissipation and the impact records.
#![allow(clippy::needless_range_loop)]

use super::{ActiveContact, Assembled, RigidStepper, dot_seq};
use crate::analytic::{ImpactLaw, SlipMode};
use crate::law_check;
use crate::math::Real;
use crate::sim::contact::{Direction, State};
use crate::sim::driver::{ImpactLog, StepInput};
use crate::sim::{ImpactRecord, SimContact};

impl RigidStepper {
    /// `W`, `Ŵ⁻¹ W`, `G` and the velocities of the active contacts.
    fn assemble(inp: &StepInput, active: &[ActiveContact]) -> Assembled {
        let (u, u_free, sc) = (inp.u, inp.u_free, inp.scheme);
        let n_act = active.len();
        let dirs: Vec<&Direction> = active
            .iter()
            .map(|a| &a.wn)
            .chain(active.iter().map(|a| &a.wt))
            .collect();
        let wcols: Vec<State> = dirs.iter().map(|d| d.dense(&sc.dofs)).collect();
        let wiw: Vec<State> = wcols.iter().map(|w| inp.winv.mul(w)).collect();
        let nc = 2 * n_act;
        let g = (0..nc)
            .map(|i| (0..nc).map(|j| dot_seq(&wcols[i], &wiw[j])).collect())
            .collect();
        let mut gam_pre: Vec<Real> = wcols.iter().map(|w| dot_seq(w, u)).collect();
        let mut gam_free: Vec<Real> = wcols.iter().map(|w| dot_seq(w, u_free)).collect();
        for (i, a) in active
            .iter()
            .enumerate()
            .filter(|(_, a)| a.face != [0.0; 4])
        {
            gam_pre[i] -= a.face[0];
            gam_pre[n_act + i] -= a.face[1];
            gam_free[i] -= a.face[2];
            gam_free[n_act + i] -= a.face[3];
        }
        Assembled {
            n: n_act,
            wcols,
            wiw,
            g,
            gam_pre,
            gam_free,
        }
    }

    /// Post-solve check on the recovered velocities ([`crate::law_check`]): rounding scale
    /// `s_k = Σ_d |W_dk| (|u_free,d| + Σ_j |(Ŵ⁻¹W)_dj P_j|)`.
    fn check(
        &mut self,
        asm: &Assembled,
        active: &[ActiveContact],
        u_free: &State,
        p: &[Real],
        gam_post: &[Real],
    ) {
        let nc = 2 * asm.n;
        let mut ad = vec![0.0; u_free.len()];
        for (d, a) in ad.iter_mut().enumerate() {
            *a = u_free[d].abs();
            for j in 0..nc {
                *a += (asm.wiw[j][d] * p[j]).abs();
            }
        }
        let mut scale = vec![0.0; nc];
        let mut diag = vec![0.0; nc];
        for k in 0..nc {
            scale[k] = asm.wcols[k].iter().zip(&ad).map(|(w, a)| w.abs() * a).sum();
            diag[k] = asm.g[k][k];
        }
        if law_check::check_laws(
            &active.iter().map(|a| a.law).collect::<Vec<_>>(),
            &asm.gam_pre[..nc],
            &p[..nc],
            &gam_post[..nc],
            &scale[..nc],
            &diag[..nc],
        )
        .is_err()
        {
            self.stats.lcp_failures += 1;
        }
    }

    /// Contact dissipation and the impact records of one step.
    fn account(
        &mut self,
        asm: &Assembled,
        active: &[ActiveContact],
        p: &[Real],
        gam_post: &[Real],
        time: Real,
        log: &mut ImpactLog,
    ) {
        let (n, gam_pre, v_imp) = (asm.n, &asm.gam_pre, self.impact_velocity);
        let impacting = (0..n).any(|i| gam_pre[i] < -v_imp && p[i] > 0.0);
        if impacting {
            log.impacts += 1;
        }
        // per site: at most one impact per joint (abutment) and step
        let mut counted: Vec<(bool, usize)> = Vec::new();
        for (i, a) in active.iter().enumerate() {
            let key = (matches!(a.contact, SimContact::Joint(_)), a.site);
            if gam_pre[i] < -v_imp && p[i] > 0.0 && !counted.contains(&key) {
                counted.push(key);
                if key.0 {
                    log.count_joint(key.1);
                } else {
                    log.count_abutment(key.1);
                }
            }
        }
        for i in 0..n {
            let dn = -0.5 * (gam_pre[i] + gam_post[i]) * p[i];
            let dt_ = -0.5 * (gam_pre[n + i] + gam_post[n + i]) * p[n + i];
            self.d_cont += dn + dt_;
            let f = active[i].face;
            if f != [0.0; 4] {
                // the balance books the work on the bodies: a moving face's own work is input
                self.d_cont -= 0.5 * ((f[0] + f[2]) * p[i] + (f[1] + f[3]) * p[n + i]);
            }
            if impacting && gam_pre[i] < -v_imp && p[i] > 0.0 {
                let gt = gam_post[n + i];
                log.records.push(ImpactRecord {
                    impact: log.impacts,
                    time,
                    contact: active[i].contact,
                    site: active[i].site,
                    mode: SlipMode::classify(gt, -gam_pre[i]),
                    gamma_n_pre: gam_pre[i],
                    gamma_t_pre: gam_pre[n + i],
                    gamma_n_post: gam_post[i],
                    gamma_t_post: gt,
                    impulse_n: p[i],
                    impulse_t: p[n + i],
                    energy_dissipated: dn + dt_,
                    pulse: None,
                });
            }
        }
    }
}

impl RigidStepper {
    /// The impacts of a step with active contacts: the impact LCP, its impulses added to
    /// `u_new` (`u_free` on entry), the law check, the contact dissipation and the impact
    /// records; returns the generalised impulse `W P` (the segments' load path). Out of the time
    /// loop's common path (most steps have no active contact).
    #[inline(never)]
    pub(super) fn resolve(
        &mut self,
        inp: &StepInput,
        active: &[ActiveContact],
        u_new: &mut State,
        log: &mut ImpactLog,
    ) -> State {
        self.stats.lcp_solves += 1;
        let asm = Self::assemble(inp, active);
        let nc = 2 * active.len();
        let (z, ok, any) = self.solve(&asm, active);
        let p = Self::impulses(&asm, active, &z, u_new);
        let mut gam_post: Vec<Real> = (0..nc).map(|i| dot_seq(&asm.wcols[i], u_new)).collect();
        for (i, a) in active
            .iter()
            .enumerate()
            .filter(|(_, a)| a.face != [0.0; 4])
        {
            gam_post[i] -= a.face[2];
            gam_post[active.len() + i] -= a.face[3];
        }
        if ok || any {
            self.check(&asm, active, inp.u_free, &p, &gam_post);
        }
        self.account(&asm, active, &p, &gam_post, inp.t_next, log);
        Self::generalised(&asm, &p)
    }

    /// The impulses `P = (P_N, P_T)` of the LCP solution `z`, added to `u` as `Ŵ⁻¹ W P`.
    fn impulses(asm: &Assembled, active: &[ActiveContact], z: &[Real], u: &mut State) -> Vec<Real> {
        let laws: Vec<ImpactLaw> = active.iter().map(|a| a.law).collect();
        let p = crate::impact::impulses(z, &laws);
        for i in 0..p.len() {
            *u += &asm.wiw[i] * p[i];
        }
        p
    }

    /// The generalised impulse `W P` of the impulses `p` on every coordinate.
    fn generalised(asm: &Assembled, p: &[Real]) -> State {
        let mut out = State::zeros(asm.wcols.first().map_or(0, |w| w.len()));
        for (w, pi) in asm.wcols.iter().zip(p) {
            out.axpy(*pi, w, 1.0);
        }
        out
    }

    /// `u_{k+1}` of the step from `inp`, committing nothing (no impact records, energy or
    /// counters): the inner solve of a mixed bridge's coupling iteration.
    pub(crate) fn solve_step(&mut self, inp: &StepInput) -> State {
        let mut u_new = inp.u_free.clone();
        let active = self.active_set(inp);
        if !active.is_empty() {
            let stats = std::mem::take(&mut self.stats);
            let asm = Self::assemble(inp, &active);
            let (z, _, _) = self.solve(&asm, &active);
            Self::impulses(&asm, &active, &z, &mut u_new);
            self.stats = stats;
        }
        u_new
    }
}
