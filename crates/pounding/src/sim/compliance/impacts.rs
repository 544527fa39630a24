//! The impacts of a compliance run: intervals of positive joint force, with one record per end
//! and impact (module doc of [`super`]).

use super::{ComplianceStepper, EndEval};
use crate::analytic::SlipMode;
use crate::geometry::ContactCase;
use crate::math::Real;
use crate::sim::contact::State;
use crate::sim::driver::ImpactLog;
use crate::sim::{ImpactRecord, SimContact};

/// Per-end bookkeeping of an impact in progress.
#[derive(Clone, Copy)]
pub(super) struct OpenImpact {
    pub(super) record: usize,
    pub(super) impulse_n: Real,
    pub(super) impulse_t: Real,
    pub(super) work: Real,
    /// Interpolated onset time (zero crossing of `δ`).
    pub(super) start: Real,
    pub(super) peak_force: Real,
    pub(super) max_penetration: Real,
}

impl OpenImpact {
    /// The pulse so far, with `duration`.
    pub(super) fn pulse(&self, duration: Real) -> crate::sim::ImpactPulse {
        crate::sim::ImpactPulse {
            peak_force: self.peak_force,
            duration,
            max_penetration: self.max_penetration,
        }
    }
}

/// The time in `[t − h, t]` where `δ` crosses zero linearly from `d0` (at `t − h`) to `d1` (at
/// `t`); `t` when it does not cross there.
pub(super) fn crossing(t: Real, h: Real, d0: Real, d1: Real) -> Real {
    if (d0 <= 0.0) != (d1 <= 0.0) && d0 != d1 {
        t - h + h * d0 / (d0 - d1)
    } else {
        t
    }
}

impl ComplianceStepper {
    /// Impacts (intervals of positive total joint force) and the per-end impact records of the
    /// step ending at `time` with velocity `un`, mean velocity `u_mid`, ends `ev`.
    pub(super) fn track_impacts(
        &mut self,
        log: &mut ImpactLog,
        time: Real,
        u: &State,
        un: &State,
        u_mid: &State,
        ev: &[EndEval],
    ) {
        let (h, th) = (self.h, self.th);
        let nj = self.joints.len();
        for k in 0..self.site_in_contact.len() {
            let f_now = ev[2 * k].f_n + ev[2 * k + 1].f_n;
            if f_now > 0.0 && !self.site_in_contact[k] {
                log.impacts += 1;
                if k < nj {
                    log.count_joint(self.joints[k].a);
                } else {
                    log.count_abutment(self.abutments[k - nj].side);
                }
            }
            self.site_in_contact[k] = f_now > 0.0;
        }
        for e in 0..ev.len() {
            let (fn0, ft0) = (self.ends[e].f_n, self.ends[e].f_t);
            let (fn1, ft1) = (ev[e].f_n, ev[e].f_t);
            if fn1 > 0.0 && self.open_imp[e].is_none() {
                let (contact, site) = if e / 2 < nj {
                    let case = ev[e].case.unwrap_or(ContactCase::Deck1Inner);
                    (SimContact::Joint(case), self.joints[e / 2].a)
                } else {
                    let side = self.abutments[e / 2 - nj].side;
                    let corner = e % 2;
                    (
                        SimContact::Abutment {
                            deck: side + 1,
                            corner,
                        },
                        side,
                    )
                };
                log.records.push(ImpactRecord {
                    impact: log.impacts,
                    time,
                    contact,
                    site,
                    mode: SlipMode::Stick,
                    gamma_n_pre: ev[e].rel(u).0,
                    gamma_t_pre: ev[e].rel(u).1,
                    gamma_n_post: Real::NAN,
                    gamma_t_post: Real::NAN,
                    impulse_n: 0.0,
                    impulse_t: 0.0,
                    energy_dissipated: 0.0,
                    pulse: None,
                });
                let d0 = if self.ends[e].present {
                    self.ends[e].delta
                } else {
                    ev[e].delta
                };
                self.open_imp[e] = Some(OpenImpact {
                    record: log.records.len() - 1,
                    impulse_n: 0.0,
                    impulse_t: 0.0,
                    work: 0.0,
                    start: crossing(time, h, d0, ev[e].delta),
                    peak_force: 0.0,
                    max_penetration: 0.0,
                });
            }
            if let Some(oi) = self.open_imp[e].as_mut() {
                let pn = h * ((1.0 - th) * fn0 + th * fn1);
                let pt = h * ((1.0 - th) * ft0 + th * ft1);
                oi.impulse_n += pn;
                oi.impulse_t += pt;
                let src = if ev[e].present { &ev[e] } else { &self.ends[e] };
                // the contact's own work: on the relative motion (a moving face's work is the
                // support's input)
                let (gn, gt) = src.rel(u_mid);
                oi.work -= gn * pn + gt * pt;
                oi.peak_force = oi.peak_force.max(fn1);
                if ev[e].present {
                    oi.max_penetration = oi.max_penetration.max(ev[e].delta);
                }
                if fn1 <= 0.0 {
                    let d1 = if ev[e].present { ev[e].delta } else { 0.0 };
                    let end = crossing(time, h, self.ends[e].delta, d1);
                    let rec = &mut log.records[oi.record];
                    (rec.gamma_n_post, rec.gamma_t_post) = src.rel(un);
                    rec.impulse_n = oi.impulse_n;
                    rec.impulse_t = oi.impulse_t;
                    rec.energy_dissipated = oi.work;
                    rec.mode = SlipMode::classify(rec.gamma_t_post, rec.gamma_n_pre);
                    rec.pulse = Some(oi.pulse(end - oi.start));
                    self.open_imp[e] = None;
                }
            }
            self.states[e] = ev[e].state;
        }
    }
}
