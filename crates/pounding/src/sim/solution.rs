//! The result of a run of a bridge (or of the two-deck model, its two-segment bridge): the
//! histories, the impacts, the peaks per joint, abutment, segment and seated end
//! ([`BridgeSummary`]) and the observers' tables, assembled from the driver's run.

use super::bridge::{ABUTMENT_SIDES, BridgeModel};
use super::dofs::Dofs;
use super::driver::{self};
use super::integrate::SiteKinds;
use super::view::{Bridge, SeatEnd, SeatSupport};
use super::{Energy, ImpactRecord, SimContact, SimStatus};
use crate::contact_law::timestep::TimeStepAdvice;
use crate::math::Real;

/// Peaks of one joint.
#[derive(Debug, Clone, PartialEq)]
pub struct JointSummary {
    /// Impacts: rigid law, steps in which a contact of this joint approaching at ≥
    /// [`super::SimSettings::impact_velocity`] gets a positive normal impulse; compliance laws, the
    /// maximal intervals of positive total force.
    pub impacts: usize,
    /// Largest total normal force of the joint's contacts \[N\] (`None` for rigid contact).
    pub peak_contact_force: Option<Real>,
    /// Largest normal impulse of one impact (the sum over the joint's contacts) \[N s\].
    pub peak_impulse: Real,
    /// `max_t (g − smallest end gap)` \[m\].
    pub peak_closing: Real,
    /// `max_t (largest end gap − g)` \[m\].
    pub peak_opening: Real,
    /// `max_t |slip|`: the relative tangential displacement of the two face midpoints along the
    /// joint's reference tangent ([`BridgeSolution::slip`]) \[m\].
    pub peak_slip: Real,
    /// Either end at this joint exceeded its seat length.
    pub unseated: bool,
    /// Episodes of positive restrainer force (0 without a restrainer).
    pub restrainer_engagements: usize,
    /// Largest restrainer force \[N\] (`None` without a restrainer).
    pub restrainer_peak_force: Option<Real>,
}

/// Peaks of one abutment.
#[derive(Debug, Clone, PartialEq)]
pub struct AbutmentSummary {
    /// Impacts (as for a joint).
    pub impacts: usize,
    /// Largest total normal force \[N\] (`None` for rigid contact).
    pub peak_contact_force: Option<Real>,
    /// Largest normal impulse of one impact \[N s\].
    pub peak_impulse: Real,
    /// `max_t (gap − smaller corner gap)` \[m\].
    pub peak_closing: Real,
    /// The backwall's peaks (`None` without a backwall).
    pub backwall: Option<BackwallSummary>,
}

/// The peaks of an abutment's exterior shear keys.
#[derive(Debug, Clone, PartialEq)]
pub struct ShearKeySummary {
    /// `start` or `end`.
    pub side: &'static str,
    /// `max_t |F|` \[N\].
    pub peak_force: Real,
    /// `max_t |v|`: the deck end's largest transverse displacement relative to the abutment \[m\].
    pub peak_deformation: Real,
    /// Whether a key yielded.
    pub yielded: bool,
    /// Energy the keys dissipated by yielding \[J\].
    pub dissipated: Real,
}

/// The peaks of an abutment's backwall ([`crate::sim::bridge::Backwall`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BackwallSummary {
    /// `max_t s`: the farthest the wall was pushed into the soil \[m\].
    pub peak_displacement: Real,
    /// `max_t F` of the backfill \[N\] (`None` without backfill).
    pub peak_backfill_force: Option<Real>,
    /// `max_t |f|` of the piles \[N\] (`None` without piles).
    pub peak_pile_force: Option<Real>,
    /// `s` at the end \[m\].
    pub residual_displacement: Real,
    /// Energy dissipated by the piles' yielding \[J\].
    pub pile_hysteretic_energy: Real,
}

/// Peaks of one segment.
#[derive(Debug, Clone, PartialEq)]
pub struct SegmentSummary {
    /// `max_t |(x, y)|` of the centroid relative to the ground \[m\].
    pub peak_displacement: Real,
    /// `|(x, y)|` at the end \[m\].
    pub final_displacement: Real,
    /// `max_t |θ|` \[rad\].
    pub peak_rotation: Real,
    /// Largest bearing deformation `max_t max_b |u_b|` (linearised) \[m\].
    pub peak_bearing_deformation: Real,
    /// Energy dissipated by yielding bearings \[J\] (0 for linear bearings).
    pub hysteretic_energy: Real,
    /// Natural frequencies `ω_1 ≤ ω_2 ≤ ω_3` on the bearings \[rad/s\].
    pub frequencies: [Real; 3],
    /// Rayleigh coefficients `(a_0, a_1)` of the segment's damping (`(0, 0)` with dashpots).
    pub rayleigh: (Real, Real),
}

/// The response of one pier ([`crate::sim::bridge::Pier`]): its cap relative to the ground
/// (the column's deformation) and its column.
#[derive(Debug, Clone, PartialEq)]
pub struct PierSummary {
    /// The joint it carries (1-based).
    pub joint: usize,
    /// `max_t |x_c|`, `max_t |y_c|` of the cap \[m\].
    pub peak_drift: [Real; 2],
    /// `max_t |(x_c, y_c)|` \[m\].
    pub peak_drift_magnitude: Real,
    /// `(x_c, y_c)` at the end \[m\].
    pub residual_drift: [Real; 2],
    /// `max_t |f|` of the column's spring force (its dashpot's left out) \[N\].
    pub peak_column_force: Real,
    /// Whether the column yielded.
    pub yielded: bool,
    /// Energy dissipated by the column's yielding \[J\].
    pub hysteretic_energy: Real,
}

/// The seat margin of one seated end (a segment's start or end, on an abutment seat, a joint's
/// seat, or an outer seat without abutment).
#[derive(Debug, Clone, PartialEq)]
pub struct SeatSummary {
    /// `segment<i>-start` / `segment<i>-end` (1-based, as `unseated_end`).
    pub end: String,
    /// The segment (1-based).
    pub segment: usize,
    /// What the end sits on: `abutment-start`, `abutment-end`, `joint<k>` (1-based), or
    /// `outer-start` / `outer-end` (an outer end without abutment).
    pub support: String,
    /// The seat length \[m\].
    pub seat_length: Real,
    /// The largest displacement of the end off its seat (along the face's outward normal; the
    /// larger of its two corners) \[m\].
    pub peak_displacement: Real,
    /// `peak_displacement / seat_length` (above 1: unseated) \[-\].
    pub ratio: Real,
    /// When the peak was first reached \[s\].
    pub peak_time: Real,
    /// The displacement at the end of the run (residual) \[m\].
    pub residual_displacement: Real,
    /// The end left its seat.
    pub unseated: bool,
}

/// Peaks and the energy check of a bridge run.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeSummary {
    /// Impacts of the whole bridge (rigid: steps with an impact; compliance: the sum over sites).
    pub impacts: usize,
    /// Per joint.
    pub joints: Vec<JointSummary>,
    /// `[start, end]`; `None` where absent.
    pub abutments: [Option<AbutmentSummary>; 2],
    /// Per segment.
    pub segments: Vec<SegmentSummary>,
    /// Per pier (none without piers).
    pub piers: Vec<PierSummary>,
    /// Per abutment with shear keys, start before end.
    pub shear_keys: Vec<ShearKeySummary>,
    /// Largest seat displacement over all seated ends (joint ends and outer ends, as the
    /// two-deck `peak_seat_displacement_m`) \[m\].
    pub peak_seat_displacement: Real,
    /// Largest ratio of an end's seat displacement to its own seat length, over all seated
    /// ends: the unseating margin (above 1 where an end unseated) \[-\].
    pub peak_seat_ratio: Real,
    /// Some end exceeded its seat length.
    pub unseated: bool,
    /// First time an end exceeded its seat length \[s\].
    pub unseating_time: Option<Real>,
    /// Which end first: `segment<i>-start` / `segment<i>-end` (1-based).
    pub unseated_end: Option<String>,
    /// Every seated end's margin, in bridge order (segment 1 start, segment 1 end, …).
    pub seats: Vec<SeatSummary>,
    /// The index in [`Self::seats`] of the governing end: the largest ratio (the first of equal
    /// ones).
    pub governing_seat: usize,
    /// Largest penetration at a joint (rigid: the scheme's overlap; compliance: the law's
    /// deformation) \[m\].
    pub peak_penetration: Real,
    /// Largest overlap `max(0, −g)` of a rigid-law site (a joint end or an abutment corner) at
    /// the steps' end states `t_k`, from the peak closings: `max(peak_closing − gap)` \[m\] (0
    /// without rigid sites). With the position projection ([`Self::projection`]) it is at most
    /// its tolerance.
    pub max_overlap: Real,
    /// What the position projection did (`None`: run without it, [`super::SimSettings::projection`]).
    pub projection: Option<super::projection::ProjectionStats>,
    /// `max_t |E_0 + W_in − (T + V + D_viscous + D_contact)| / max_t |E_0 + W_in|`.
    pub energy_balance_error: Real,
    /// Energies at the end.
    pub final_energy: Energy,
    /// `max_t |E_0 + W_in|` \[J\].
    pub max_input_energy: Real,
    /// Work done on the restrainers (stored plus plastic) at the end \[J\].
    pub restrainer_work: Real,
    /// Work done on the backfills (stored plus dissipated) \[J\].
    pub backfill_work: Real,
    /// Work done on the shear keys (stored plus dissipated) \[J\].
    pub shear_key_work: Real,
}

/// Result of [`super::bridge::simulate`] and of [`super::simulate`].
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeSolution {
    /// Outcome.
    pub status: SimStatus,
    /// Steps taken.
    pub steps: usize,
    /// Step size \[s\].
    pub dt: Real,
    /// Number of segments.
    pub n_segments: usize,
    /// Where each segment's coordinates sit in the rows of [`Self::q`] and [`Self::u`].
    pub dofs: Dofs,
    /// Kept times \[s\].
    pub t: Vec<Real>,
    /// `q` rows ([`Self::dofs`]`.len()` per kept time).
    pub q: Vec<Real>,
    /// `u` rows.
    pub u: Vec<Real>,
    /// Signed gaps of each joint's four corner-against-face candidates in
    /// [`crate::geometry::ContactCase::ALL`] order (`4 (N − 1)` per kept time; corner to the other
    /// face's *line*, meaningful only for a corner over that face) \[m\].
    pub gaps: Vec<Real>,
    /// End gaps of each joint (`2 (N − 1)` per kept time; NaN where no corner is over the face) \[m\].
    pub end_gaps: Vec<Real>,
    /// Slip of each joint (`N − 1` per kept time): the displacement of segment `k`'s end-face
    /// midpoint relative to segment `k + 1`'s start-face midpoint along the joint's reference
    /// tangent `τ⁰` \[m\].
    pub slip: Vec<Real>,
    /// Normal force of each joint end (compliance; `2 (N − 1)` per kept time) \[N\].
    pub contact_force: Vec<Real>,
    /// Smaller abutment corner gap `[start, end]` per kept time (NaN where absent) \[m\].
    pub abutment_gaps: Vec<[Real; 2]>,
    /// Energies per kept time.
    pub energy: Vec<Energy>,
    /// Impacting contacts in time order ([`ImpactRecord::site`] names the joint or abutment).
    pub impacts: Vec<ImpactRecord>,
    /// Peaks.
    pub summary: BridgeSummary,
    /// The supports moved apart (wave passage, a motion per support): the histories' `q` are
    /// relative to the reference ground motion, not to each support.
    pub supports_apart: bool,
    /// LCP solves / enumeration fallbacks / failures (rigid law).
    pub lcp_solves: usize,
    /// Steps where Lemke failed but enumeration succeeded.
    pub lcp_enumeration_fallbacks: usize,
    /// Steps whose LCP failed or whose solution failed the post-solve checks.
    pub lcp_failures: usize,
    /// Newton failures (compliance laws).
    pub newton_failures: usize,
    /// Closure steps (compliance laws).
    pub closure_steps: usize,
    /// Time-step adequacy of the compliance law.
    pub time_step_advice: Option<TimeStepAdvice>,
    /// The observers' tables at the history steps — `bearings`, `restrainers`, `joint_slip`, the
    /// substructures', `segment_forces` —,
    /// recorded or derived from the histories when asked for ([`Self::tables`]).
    pub table_sources: Vec<super::table::TableSource>,
}

impl BridgeSolution {
    /// Number of kept times (rows of the histories).
    pub fn rows(&self) -> usize {
        self.t.len()
    }

    /// `q` at kept time `r` (laid out by [`Self::dofs`]: `x_j, y_j, θ_j` per segment) \[m, rad\].
    pub fn q_row(&self, r: usize) -> &[Real] {
        let n = self.dofs.len();
        &self.q[n * r..n * (r + 1)]
    }

    /// The rows of `q`, one per kept time.
    pub fn q_rows(&self) -> std::slice::ChunksExact<'_, Real> {
        self.q.chunks_exact(self.dofs.len())
    }

    /// The rows of `u`, one per kept time.
    pub fn u_rows(&self) -> std::slice::ChunksExact<'_, Real> {
        self.u.chunks_exact(self.dofs.len())
    }

    /// `u` at kept time `r` \[m/s, rad/s\].
    pub fn u_row(&self, r: usize) -> &[Real] {
        let n = self.dofs.len();
        &self.u[n * r..n * (r + 1)]
    }

    /// The joints' end gaps at kept time `r` (two per joint) \[m\].
    pub fn end_gaps_row(&self, r: usize) -> &[Real] {
        let n = 2 * self.n_segments.saturating_sub(1);
        &self.end_gaps[n * r..n * (r + 1)]
    }

    /// The joints' end forces at kept time `r` (two per joint; empty for rigid contact) \[N\].
    pub fn contact_force_row(&self, r: usize) -> &[Real] {
        let n = 2 * self.n_segments.saturating_sub(1);
        self.contact_force.get(n * r..n * (r + 1)).unwrap_or(&[])
    }

    /// The observers' tables ([`super::table::Table`]; written as `<name>.csv`), in order:
    /// `bearings` (derived here from `q` and the recorded plastic displacements of yielding
    /// bearings), `restrainers`, `joint_slip`, with piers, backwalls or shear keys `piers`,
    /// `backwalls`, `shear_keys`, and last `segment_forces` (every force on each segment).
    pub fn tables(&self) -> Vec<super::table::Table> {
        self.table_sources
            .iter()
            .map(|s| s.table(&self.t, &self.q, &self.dofs))
            .collect()
    }

    /// Impacting contacts at the abutments.
    pub fn abutment_impacting_contacts(&self) -> usize {
        self.impacts
            .iter()
            .filter(|r| matches!(r.contact, SimContact::Abutment { .. }))
            .count()
    }
}

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
fn rigid_overlap(peaks: &super::peaks::Peaks, br: &Bridge, kinds: &SiteKinds) -> Real {
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
fn member_dissipation(el: &super::elements::Elements, body: usize) -> Real {
    (0..el.bearings.len())
        .filter(|&e| el.bearings[e].body == body)
        .map(|e| el.member_dissipation(e))
        .sum()
}

/// Assembles the [`BridgeSolution`] of a run (its seats in the order of `br.seats`).
pub(crate) fn solution(
    r: driver::RunResult,
    (systems, dt): (&[super::scheme::BodySystem], Real),
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
                        residual_displacement: super::peaks::wall_forces(
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
            let g = super::view::ground_at(&r.final_ground, p.joint + 1);
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
            let g = super::view::ground_at(&r.final_ground, i);
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
