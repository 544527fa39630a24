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
#![allow(clippy::needless_range_loop)]

use super::contact::{Direction, State, dot_dir};
use super::driver::{ImpactLog, StepInput, StepOutput, Stepper, StepperStats};
use super::{ImpactRecord, SimContact, SimSettings};
use crate::analytic::{ImpactLaw, SlipMode};
use crate::law_check;
use crate::lcp::{self, LcpStatus, LemkeSettings};
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

/// Lemke on the `N × N` row-major `a` (fixed-size kernel).
fn lemke_block<const N: usize>(
    a: &[Real],
    b: &[Real],
    settings: &LemkeSettings,
) -> Option<Vec<Real>> {
    let mut aa = [[0.0; N]; N];
    let mut bb = [0.0; N];
    for i in 0..N {
        aa[i].copy_from_slice(&a[i * N..(i + 1) * N]);
        bb[i] = b[i];
    }
    let s = lcp::solve_fixed::<N>(&aa, &bb, settings);
    (s.status == LcpStatus::Solved).then(|| s.z.to_vec())
}

/// Solves the contact LCP of size `3n` (`a` row-major) for `x = (P_N, P_TR, γ_TL)` (spec §8):
/// the fixed kernels for `n ≤ 6`, the dynamic one above, enumeration as the fallback.
/// Returns `(x, lemke_ok, any_ok)`.
fn solve_contact_lcp(
    n: usize,
    a: &[Real],
    b: &[Real],
    settings: &LemkeSettings,
) -> (Vec<Real>, bool, bool) {
    let m = 3 * n;
    let rows = || a.to_vec();
    let sol = match n {
        1 => lemke_block::<3>(a, b, settings),
        2 => lemke_block::<6>(a, b, settings),
        3 => lemke_block::<9>(a, b, settings),
        4 => lemke_block::<12>(a, b, settings),
        5 => lemke_block::<15>(a, b, settings),
        6 => lemke_block::<18>(a, b, settings),
        _ => lcp::LcpProblem::new(rows(), b[..m].to_vec())
            .ok()
            .map(|p| lcp::Lemke::new(settings.clone()).solve(&p))
            .filter(|s| s.status == LcpStatus::Solved)
            .map(|s| s.z),
    };
    if let Some(z) = sol {
        return (z, true, true);
    }
    // enumeration is exponential: only for the sizes of the two-deck model
    if n <= MAX_FIXED_CONTACTS
        && let Ok(p) = lcp::LcpProblem::new(rows(), b[..m].to_vec())
        && let Ok(sols) = lcp::enumerate(&p)
        && let Some(z) = sols.into_iter().next()
    {
        return (z, false, true);
    }
    (vec![0.0; m], false, false)
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

    /// The LCP (spec §8) of size `3n` and its solution `z = (P_N, P_TR, γ_TL)`, with the
    /// fallbacks; returns `(z, ok, any)`.
    fn solve(&mut self, asm: &Assembled, active: &[ActiveContact]) -> (Vec<Real>, bool, bool) {
        let (n, g) = (asm.n, &asm.g);
        let mu = |j: usize| active[j].law.mu();
        let m = 3 * n;
        // the one assembly of the impact LCP (`impact.rs`), on the step's free velocities
        let laws: Vec<ImpactLaw> = active.iter().map(|a| a.law).collect();
        let g_rows: Vec<Real> = g.iter().flatten().copied().collect();
        let (a, b) = crate::impact::impact_lcp_free(&g_rows, &laws, &asm.gam_pre, &asm.gam_free);
        // many contacts at once: the block Gauss–Seidel, verified (Lemke's dense tableau is
        // O(n²) per pivot and fails on the degenerate problems of permanent contact)
        if n > MAX_FIXED_CONTACTS {
            let mus: Vec<Real> = (0..n).map(mu).collect();
            let mut bb: Vec<Real> = b[..n].to_vec();
            bb.extend_from_slice(&b[n..2 * n]);
            let sol = lcp::fc2d::solve_nsgs(g, &bb, &mus, &lcp::fc2d::Fc2dSettings::default());
            if sol.converged {
                let mut z = vec![0.0; m];
                for i in 0..n {
                    z[i] = sol.p[i];
                    z[n + i] = sol.p[n + i] + mus[i] * sol.p[i];
                }
                return (z, true, true);
            }
        }
        // without friction at every active contact the tangential rows only say `P_T = 0`
        // (with `μ = 0` the friction-cone rows are degenerate: a rounding-level tangential
        // free velocity, e.g. from a yielding bearing's tangent, made Lemke fail on them)
        if active.iter().all(|a| a.law.mu() == 0.0) {
            let (z, ok, any) = self.frictionless(n, g, &b, &mu);
            if !(ok || any) {
                self.stats.lcp_failures += 1;
            } else if !ok {
                self.stats.lcp_enumeration_fallbacks += 1;
            }
            return (z, ok, any);
        }
        let (mut z, ok, any) = solve_contact_lcp(n, &a, &b, &self.lemke);
        if !ok {
            if any {
                self.stats.lcp_enumeration_fallbacks += 1;
            } else {
                self.stats.lcp_failures += 1;
                z = self.frictionless(n, g, &b, &mu).0;
            }
        }
        (z, ok, any)
    }

    /// The frictionless LCP in `P_N` (`G_NN P_N + b_N ≥ 0`), with the tangential rows decoupled
    /// (`z = 0`, `w = 1`); returns `z` with `P_TR = μ P_N`, i.e. `P_T = 0`, and `(ok, any)` as
    /// [`solve_contact_lcp`].
    fn frictionless(
        &self,
        n: usize,
        g: &[Vec<Real>],
        b: &[Real],
        mu: &dyn Fn(usize) -> Real,
    ) -> (Vec<Real>, bool, bool) {
        let m = 3 * n;
        let mut a0 = vec![0.0; m * m];
        let mut b0 = vec![0.0; m];
        for i in 0..n {
            a0[i * m..i * m + n].copy_from_slice(&g[i][..n]);
            b0[i] = b[i];
            // decouple the dummy rows: z = 0, w = 1
            a0[(n + i) * m + n + i] = 1.0;
            a0[(2 * n + i) * m + 2 * n + i] = 1.0;
            b0[n + i] = 1.0;
            b0[2 * n + i] = 1.0;
        }
        let (mut z, ok, any) = solve_contact_lcp(n, &a0, &b0, &self.lemke);
        for i in 0..n {
            z[n + i] = mu(i) * z[i]; // P_T = 0
        }
        (z, ok, any)
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
    fn resolve(
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
