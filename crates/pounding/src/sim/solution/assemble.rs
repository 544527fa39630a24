//! Assembling a [`BridgeSolution`] from the driver's run: the impulse peaks per site, the
//! summaries of the joints, abutments, piers, segments and seats, and the overlap of the rigid
//! sites.

use super::{
    AbutmentSummary, BackwallSummary, BridgeSolution, BridgeSummary, JointSummary, PierSummary,
    SeatSummary, SegmentSummary, ShearKeySummary,
};
use crate::math::Real;
use crate::sim::bridge::{ABUTMENT_SIDES, BridgeModel};
use crate::sim::driver::{self};
use crate::sim::integrate::SiteKinds;
use crate::sim::view::{Bridge, SeatEnd, SeatSupport};
use crate::sim::{ImpactRecord, SimContact};

/// The largest summed normal impulse of one impact, per joint and per abutment side (the
/// records of one impact at one site are consecutive).
fn impulse_peaks(records: &[ImpactRecord], nj: usize) -> (Vec<Real>, [Real; 2]) {
    let mut imp_joint = vec![0.0; nj];
    let mut imp_abut = [0.0; 2];
    {
        let mut cur: Option<(usize, bool, usize, Real)> = None;
        let mut flush = |c: Option<(usize, bool, usize, Real)>| {
            if let Some((_, is_joint, site, p)) = c {
                let slot = if is_joint {
                    &mut imp_joint[site]
                } else {
                    &mut imp_abut[site]
                };
                *slot = Real::max(*slot, p);
            }
        };
        for rec in records {
            let key = (
                rec.impact,
                matches!(rec.contact, SimContact::Joint(_)),
                rec.site,
            );
            match cur {
                Some((i, j, s, p)) if (i, j, s) == key => cur = Some((i, j, s, p + rec.impulse_n)),
                _ => {
                    flush(cur);
                    cur = Some((key.0, key.1, key.2, rec.impulse_n));
                }
            }
        }
        flush(cur);
    }
    (imp_joint, imp_abut)
}

/// The [`JointSummary`]s of a run.
fn joint_summaries(
    r: &driver::RunResult,
    br: &Bridge,
    imp_joint: &[Real],
    kinds: &SiteKinds,
) -> Vec<JointSummary> {
    let (peaks, log) = (&r.peaks, &r.log);
    let nj = br.joints.len();
    let joint_impacts = |k: usize| log.joint_impacts.get(k).copied().unwrap_or(0);
    (0..nj)
        .map(|k| JointSummary {
            impacts: joint_impacts(k),
            peak_contact_force: if kinds.joints[k] {
                Some(peaks.force[k].unwrap_or(0.0))
            } else {
                None
            },
            peak_impulse: imp_joint[k],
            peak_closing: peaks.close[k],
            peak_opening: peaks.open[k],
            peak_slip: peaks.slip[k],
            unseated: br
                .seats
                .iter()
                .zip(&peaks.seat)
                .any(|(s, &d)| s.support == SeatSupport::Joint(k) && d > s.length),
            restrainer_engagements: r
                .elements
                .cables
                .iter()
                .filter(|c| c.joint == k)
                .map(|c| c.element.engagements())
                .sum(),
            restrainer_peak_force: r
                .elements
                .cables
                .iter()
                .filter(|c| c.joint == k)
                .map(|c| c.element.peak_force())
                .reduce(Real::max),
        })
        .collect()
}

/// [`BridgeSummary::max_overlap`]: the largest `peak_closing − gap` of the rigid joints and
/// abutments (`0` if none overlaps).
fn rigid_overlap(peaks: &crate::sim::peaks::Peaks, br: &Bridge, kinds: &SiteKinds) -> Real {
    let joints = br
        .joints
        .iter()
        .enumerate()
        .filter(|(k, _)| !kinds.joints[*k])
        .map(|(k, jg)| peaks.close[k] - jg.gap);
    let abutments = br
        .abutments
        .iter()
        .filter(|a| kinds.abutments[a.side] == Some(false))
        .filter_map(|a| peaks.abut[a.side].map(|c| c - a.gap));
    joints.chain(abutments).fold(0.0, Real::max)
}

/// `segment<i>-start` / `segment<i>-end` (1-based) of a seated end.
pub(crate) fn seat_name(seat: &SeatEnd) -> String {
    let face = if seat.at_end { "end" } else { "start" };
    format!("segment{}-{face}", seat.body + 1)
}

/// The dissipation of the yielding members on `body` (their own work less what they store).
fn member_dissipation(el: &crate::sim::elements::Elements, body: usize) -> Real {
    (0..el.bearings.len())
        .filter(|&e| el.bearings[e].body == body)
        .map(|e| el.member_dissipation(e))
        .sum()
}

/// Assembles the [`BridgeSolution`] of a run (its seats in the order of `br.seats`).
pub(crate) fn solution(
    r: driver::RunResult,
    (systems, dt): (&[crate::sim::scheme::BodySystem], Real),
    br: &Bridge,
    model: &BridgeModel,
    kinds: &SiteKinds,
) -> BridgeSolution {
    let nj = br.joints.len();
    let nb = br.bodies.len();
    let (peaks, log) = (&r.peaks, &r.log);
    let (imp_joint, imp_abut) = impulse_peaks(&log.records, nj);
    let joints = joint_summaries(&r, br, &imp_joint, kinds);
    let mut abutments = [None, None];
    for (side, a) in model.abutments.iter().enumerate() {
        if a.is_some() {
            abutments[side] = Some(AbutmentSummary {
                impacts: log.abutment_impacts[side],
                peak_contact_force: if kinds.abutments[side] == Some(true) {
                    Some(peaks.abut_force[side].unwrap_or(0.0))
                } else {
                    None
                },
                peak_impulse: imp_abut[side],
                peak_closing: peaks.abut[side].unwrap_or(Real::NAN),
                backwall: peaks.wall[side].map(|w| {
                    let b = model.wall_body(side).expect("a backwall");
                    BackwallSummary {
                        peak_displacement: w.displacement,
                        peak_backfill_force: w.backfill,
                        peak_pile_force: w.piles,
                        residual_displacement: crate::sim::peaks::wall_forces(
                            (b, if side == 0 { 0 } else { nb }),
                            r.final_q.as_slice(),
                            br,
                            &r.elements,
                            &r.final_ground,
                        )
                        .0,
                        pile_hysteretic_energy: member_dissipation(&r.elements, b),
                    }
                }),
            });
        }
    }
    let correction = r.elements.bearing_stored_energy(br.dofs.n_bodies());
    // a coupled system books a bearing on a cap partly on the cap: report members instead
    let coupled = !br.piers.is_empty() || br.abutments.iter().any(|a| a.wall.is_some());
    let members = |body: usize| member_dissipation(&r.elements, body);
    let piers = br
        .piers
        .iter()
        .zip(&peaks.pier)
        .map(|(p, pk)| {
            let [x, y, _] = br.dofs.plan_of(p.body, r.final_q.as_slice());
            let g = crate::sim::view::ground_at(&r.final_ground, p.joint + 1);
            let (x, y) = (x - g.x, y - g.y);
            PierSummary {
                joint: p.joint + 1,
                peak_drift: pk.drift,
                peak_drift_magnitude: pk.drift_magnitude,
                residual_drift: [x, y],
                peak_column_force: pk.force,
                yielded: pk.yielded,
                hysteretic_energy: members(p.body),
            }
        })
        .collect();
    let segments = (0..nb)
        .map(|i| {
            let [x, y, _] = br.dofs.plan_of(i, r.final_q.as_slice());
            let g = crate::sim::view::ground_at(&r.final_ground, i);
            let (x, y) = (x - g.x, y - g.y);
            SegmentSummary {
                peak_displacement: peaks.disp[i].sqrt(),
                final_displacement: (x * x + y * y).sqrt(),
                peak_rotation: peaks.rot[i],
                peak_bearing_deformation: peaks.bearing[i].sqrt(),
                hysteretic_energy: if coupled {
                    members(i)
                } else {
                    r.elements.w_bearings.get(i).copied().unwrap_or(0.0) - correction[i]
                },
                frequencies: systems[i].frequencies,
                rayleigh: systems[i].rayleigh,
            }
        })
        .collect();
    let seats: Vec<SeatSummary> = br
        .seats
        .iter()
        .enumerate()
        .map(|(e, seat)| SeatSummary {
            end: seat_name(seat),
            segment: seat.body + 1,
            support: match seat.support {
                SeatSupport::Abutment(side) => format!("abutment-{}", ABUTMENT_SIDES[side]),
                SeatSupport::Outer(side) => format!("outer-{}", ABUTMENT_SIDES[side]),
                SeatSupport::Joint(k) => format!("joint{}", k + 1),
            },
            seat_length: seat.length,
            peak_displacement: peaks.seat[e],
            ratio: peaks.seat[e] / seat.length,
            peak_time: peaks.seat_time[e],
            residual_displacement: peaks.seat_last[e],
            unseated: peaks.seat[e] > seat.length,
        })
        .collect();
    let unseated_end = peaks.unseat.map(|(_, e)| seat_name(&br.seats[e]));
    let summary = BridgeSummary {
        impacts: log.impacts,
        joints,
        abutments,
        segments,
        piers,
        shear_keys: r
            .elements
            .keys
            .iter()
            .map(|k| {
                let (f, v) = peaks.keys[k.side].unwrap_or((0.0, 0.0));
                ShearKeySummary {
                    side: ABUTMENT_SIDES[k.side],
                    peak_force: f,
                    peak_deformation: v,
                    yielded: k.element.dissipated() > 0.0,
                    dissipated: k.element.dissipated(),
                }
            })
            .collect(),
        peak_seat_displacement: peaks
            .seat
            .iter()
            .copied()
            .fold(Real::NEG_INFINITY, Real::max),
        peak_seat_ratio: peaks
            .seat
            .iter()
            .zip(&br.seats)
            .map(|(d, seat)| d / seat.length)
            .fold(Real::NEG_INFINITY, Real::max),
        unseated: peaks.unseat.is_some(),
        unseating_time: peaks.unseat.map(|u| u.0),
        unseated_end,
        governing_seat: seats
            .iter()
            .enumerate()
            .fold(0, |g, (e, s)| if s.ratio > seats[g].ratio { e } else { g }),
        seats,
        peak_penetration: peaks.pen,
        max_overlap: rigid_overlap(peaks, br, kinds),
        projection: r.projection,
        energy_balance_error: r.energy_balance_error,
        final_energy: r.final_energy,
        max_input_energy: r.max_input_energy,
        restrainer_work: r.elements.w_cables,
        backfill_work: r.elements.w_backfill,
        shear_key_work: r.elements.w_keys,
    };
    let tr = r.trace;
    BridgeSolution {
        supports_apart: !r.final_ground.is_empty(),
        status: r.status,
        steps: r.steps,
        dt,
        n_segments: nb,
        dofs: br.dofs.clone(),
        t: tr.t,
        q: tr.q,
        u: tr.u,
        gaps: tr.gaps,
        end_gaps: tr.end_gaps,
        slip: tr.slip,
        contact_force: tr.contact_force,
        abutment_gaps: tr.abutment_gaps,
        energy: tr.energy,
        impacts: r.log.records,
        summary,
        lcp_solves: r.stats.lcp_solves,
        lcp_enumeration_fallbacks: r.stats.lcp_enumeration_fallbacks,
        lcp_failures: r.stats.lcp_failures,
        newton_failures: r.stats.newton_failures,
        closure_steps: r.stats.closure_steps,
        time_step_advice: r.stats.time_step_advice,
        table_sources: r.tables,
    }
}
