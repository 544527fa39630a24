//! The monitors of a run: peaks over time per joint, segment, seat, abutment, pier and
//! backwall, the first unseating, and what the history records of each state ([`Observed`]).
//! The driver ([`super::driver::run`]) calls them at every step.

use super::contact::{Pose, State};
use super::dofs::PlanDof;
use super::model::SegmentBody;
use super::support::Attachment;
use super::view::{BearingAt, Bridge, Frame, SeatEnd};
use crate::math::{Real, Vector};

/// Peaks over time, per joint, segment, seat and abutment side.
pub(crate) struct Peaks {
    /// Per joint: `max_t (g − min end gap)`.
    pub close: Vec<Real>,
    /// Per joint: `max_t (max end gap − g)`.
    pub open: Vec<Real>,
    /// Per segment: `max_t |θ|`.
    pub rot: Vec<Real>,
    /// Per joint: `max_t |slip|`.
    pub slip: Vec<Real>,
    /// Per seated end: the largest seat displacement.
    pub seat: Vec<Real>,
    /// Per seated end: the time of [`Self::seat`] (the first time it was reached).
    pub seat_time: Vec<Real>,
    /// Per seated end: the seat displacement at the last observed step (the residual; set by
    /// [`Self::finish`]).
    pub seat_last: Vec<Real>,
    /// Per seated end: `(max_c |c − G⁰|, max_c (|c| + |G⁰|))` over its corners: the reach of
    /// the seat bound and the scale of its rounding.
    seat_reach: Vec<(Real, Real)>,
    /// The last observed `q`.
    last_q: Vec<Real>,
    /// First unseating: time and seated-end index.
    pub unseat: Option<(Real, usize)>,
    /// Largest penetration of any joint (or contact deformation of the law).
    pub pen: Real,
    /// Per abutment side: `max_t (gap − smaller corner gap)`.
    pub abut: [Option<Real>; 2],
    /// Per joint: the largest total normal force (compliance laws).
    pub force: Vec<Option<Real>>,
    /// Per abutment side: the largest total normal force (compliance laws).
    pub abut_force: [Option<Real>; 2],
    /// Per segment: `max_t |(x, y)|²` (squared: the root of the largest square is the largest
    /// root, exactly, and costs one root per run instead of one per step).
    pub disp: Vec<Real>,
    /// Per segment: the square of the largest linearised bearing deformation (0 when not
    /// monitored).
    pub bearing: Vec<Real>,
    /// Per segment: the arms `r = p − G⁰` of its bearings to a support (the fast path of the
    /// bearing monitor) with the largest `|r|`, and its other bearings.
    arms: Vec<(Vec<Vector>, Real, Vec<BearingAt>)>,
    /// Per pier.
    pub pier: Vec<PierPeak>,
    /// Per abutment side with a backwall.
    pub wall: [Option<WallPeak>; 2],
    /// Per abutment side with shear keys: `max_t |F|`, `max_t |v|`.
    pub keys: [Option<(Real, Real)>; 2],
}

/// The peaks of one backwall.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WallPeak {
    /// `max_t s` \[m\].
    pub displacement: Real,
    /// `max_t F` of the backfill \[N\].
    pub backfill: Option<Real>,
    /// `max_t |f|` of the piles \[N\].
    pub piles: Option<Real>,
}

/// The peaks of one pier.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct PierPeak {
    /// `max_t |x_c|`, `max_t |y_c|` of the cap \[m\].
    pub drift: [Real; 2],
    /// `max_t |(x_c, y_c)|` \[m\].
    pub drift_magnitude: Real,
    /// `max_t |f|` of the column's force \[N\].
    pub force: Real,
    /// Whether the column ever yielded.
    pub yielded: bool,
}

/// What [`Peaks::observe`] measured for the history (reused from step to step).
#[derive(Default)]
pub(crate) struct Observed {
    pub end_gaps: Vec<[Real; 2]>,
    pub slip: Vec<Real>,
    pub abut_gaps: [Real; 2],
}

impl Peaks {
    pub(crate) fn new(br: &Bridge) -> Self {
        let nj = br.joints.len();
        Peaks {
            close: vec![Real::NEG_INFINITY; nj],
            open: vec![Real::NEG_INFINITY; nj],
            rot: vec![0.0; br.bodies.len()],
            slip: vec![0.0; nj],
            seat: vec![Real::NEG_INFINITY; br.seats.len()],
            seat_time: vec![0.0; br.seats.len()],
            seat_last: vec![Real::NAN; br.seats.len()],
            seat_reach: br
                .seats
                .iter()
                .map(|e| {
                    let g0 = br.bodies[e.body].centroid;
                    let reach = e.corners.iter().map(|c| (c - g0).norm());
                    let scale = e.corners.iter().map(|c| c.norm() + g0.norm());
                    (reach.fold(0.0, Real::max), scale.fold(0.0, Real::max))
                })
                .collect(),
            last_q: Vec::new(),
            unseat: None,
            pen: 0.0,
            abut: [None, None],
            force: vec![None; nj],
            abut_force: [None, None],
            pier: vec![PierPeak::default(); br.piers.len()],
            keys: [0, 1].map(|side| {
                br.elements.keys.iter().any(|k| k.side == side).then_some((0.0, 0.0))
            }),
            wall: [0, 1].map(|side| {
                let a = br.abutments.iter().find(|a| a.side == side)?;
                let w = a.wall?;
                Some(WallPeak {
                    displacement: 0.0,
                    backfill: br.elements.backfills.iter().any(|b| b.body == w).then_some(0.0),
                    piles: br.elements.bearings.iter().any(|b| b.body == w).then_some(0.0),
                })
            }),
            disp: vec![0.0; br.bodies.len()],
            bearing: vec![0.0; br.bodies.len()],
            arms: br
                .bearings
                .iter()
                .enumerate()
                .map(|(j, bs)| {
                    let ground = |b: &&BearingAt| {
                        matches!((b.top, b.bottom), (Attachment::Body(i, _), Attachment::Support(..)) if i == j)
                    };
                    let arms: Vec<Vector> =
                        bs.iter().filter(ground).map(|b| b.arm(&br.bodies)).collect();
                    let reach = arms.iter().map(|r| r.norm()).fold(0.0, Real::max);
                    let others = bs.iter().filter(|b| !ground(b)).copied().collect();
                    (arms, reach, others)
                })
                .collect(),
        }
    }

    /// The per-segment monitors of the bridge model (displacement magnitude, bearing
    /// deformation `u_b = (x − θ r_y, y + θ r_x)`, `r = b − G⁰`). The bearings to a support are
    /// skipped in a step where `|u_b| ≤ |(x, y)| + |θ| max_b |r_b|` (with a relative margin of
    /// 1e-12 for rounding) cannot exceed the peak so far: the peak is the same, in far fewer
    /// operations once it has grown.
    ///
    /// When the supports move apart (`ground` their offsets, else empty), a segment's
    /// displacement is taken relative to the ground under its start support and each bearing's
    /// deformation relative to its own support.
    #[inline(always)]
    pub(crate) fn observe_segments(&mut self, q: &State, br: &Bridge, ground: &[Vector]) {
        if !ground.is_empty() {
            return self.observe_segments_apart(q, br, ground);
        }
        let q = q.as_slice();
        let segments = self.disp.iter_mut().zip(self.bearing.iter_mut());
        for (j, ((d, peak), pts)) in segments.zip(&self.arms).enumerate() {
            let [x, y, th] = br.dofs.plan_of(j, q);
            let d2 = x * x + y * y;
            *d = d.max(d2);
            let mut m = *peak;
            let (arms, reach, others) = pts;
            let bound = d2.sqrt() + th.abs() * reach;
            // the bearings from segment j to a support: their deformation from the arm directly
            let below = bound * bound * (1.0 + 1e-12) <= m; // false for a NaN state
            if !below {
                for r in arms {
                    let (ux, uy) = (x - th * r.y, y + th * r.x);
                    m = m.max(ux * ux + uy * uy);
                }
            }
            if !others.is_empty() {
                m = Self::others_peak(m, others, br, q);
            }
            *peak = m;
        }
    }

    /// `m` and the squared deformations of a segment's bearings that are not on a support
    /// (on a pier's cap), the larger: out of the time loop's common path.
    #[inline(never)]
    fn others_peak(mut m: Real, others: &[BearingAt], br: &Bridge, q: &[Real]) -> Real {
        for b in others {
            let u = b.deformation(&br.dofs, q, &br.bodies);
            m = m.max(u.x * u.x + u.y * u.y);
        }
        m
    }

    /// [`Self::observe_segments`] under supports that move apart.
    #[cold]
    #[inline(never)]
    fn observe_segments_apart(&mut self, q: &State, br: &Bridge, ground: &[Vector]) {
        let q = q.as_slice();
        for (j, bs) in br.bearings.iter().enumerate() {
            let [x, y, _] = br.dofs.plan_of(j, q);
            let rel = Vector::new(x, y) - ground[j];
            self.disp[j] = self.disp[j].max(rel.norm_squared());
            for b in bs {
                let mut u = b.deformation(&br.dofs, q, &br.bodies);
                if matches!(b.bottom, Attachment::Support(..)) {
                    u -= ground[b.line];
                }
                self.bearing[j] = self.bearing[j].max(u.norm_squared());
            }
        }
    }

    /// The backwalls' displacements, backfill and pile forces (`el`: committed at `q`).
    pub(crate) fn observe_walls(
        &mut self,
        q: &State,
        br: &Bridge,
        el: &super::elements::Elements,
        ground: &[Vector],
    ) {
        for a in &br.abutments {
            let (Some(w), Some(pk)) = (a.wall, self.wall[a.side].as_mut()) else {
                continue;
            };
            let (s, f_fill, f_piles) = wall_forces((w, a.line), q.as_slice(), br, el, ground);
            pk.displacement = pk.displacement.max(s);
            if let (Some(p), Some(f)) = (pk.backfill.as_mut(), f_fill) {
                *p = p.max(f);
            }
            if let (Some(p), Some(f)) = (pk.piles.as_mut(), f_piles) {
                *p = p.max(f.abs());
            }
        }
    }

    /// The piers' drifts, column forces and yield (`el`: the elements committed at `q`).
    pub(crate) fn observe_piers(
        &mut self,
        q: &State,
        br: &Bridge,
        el: &super::elements::Elements,
        ground: &[Vector],
    ) {
        for (pk, p) in self.pier.iter_mut().zip(&br.piers) {
            let (u, f) = p.drift_and_force(&br.dofs, q.as_slice(), el, ground);
            pk.drift[0] = pk.drift[0].max(u.x.abs());
            pk.drift[1] = pk.drift[1].max(u.y.abs());
            pk.drift_magnitude = pk.drift_magnitude.max(u.norm());
            pk.force = pk.force.max(f.norm());
            for &e in &p.elements {
                pk.yielded |= el.bearings[e].state.u_p != Vector::zeros();
            }
        }
    }

    /// The displacement of a seated end off its seat: the larger over its two corners of
    /// `(p − p⁰)·n_in`.
    /// On a pier the displacement is relative to its cap (`q` the state of `pose`).
    fn seat_displacement(
        s_end: &SeatEnd,
        (pose, ground): (&Pose, &[Vector]),
        bodies: &[SegmentBody],
        q: &State,
        br: &Bridge,
    ) -> Real {
        let base = Self::seat_base(s_end, q, br, ground);
        s_end
            .corners
            .iter()
            .map(|p| (pose.place(bodies, s_end.body, p) - p - base).dot(&s_end.inward))
            .fold(Real::NEG_INFINITY, Real::max)
    }

    /// The displacement of what a seated end rests on (zero on the ground that moves with the
    /// reference; its support's offset in `ground` when the supports move apart).
    #[inline]
    fn seat_base(s_end: &SeatEnd, q: &State, br: &Bridge, ground: &[Vector]) -> Vector {
        match s_end.base {
            None => super::view::ground_at(ground, s_end.line),
            Some(c) => {
                let [x, y, _] = br.dofs.plan_of(c, q.as_slice());
                Vector::new(x, y)
            }
        }
    }

    /// The seat displacements at the last observed step (the residuals).
    pub fn finish(&mut self, br: &Bridge, ground: &[Vector]) {
        if self.last_q.is_empty() {
            return;
        }
        let q = State::from_column_slice(&self.last_q);
        let frame = br.frame(&q);
        for (e, s_end) in br.seats.iter().enumerate() {
            let at = (&frame.pose, ground);
            self.seat_last[e] = Self::seat_displacement(s_end, at, &br.bodies, &q, br);
        }
    }

    /// Peak forces: per joint, then per abutment site (`abut_sides[i]` the side of site
    /// `n_joints + i`).
    pub(crate) fn observe_forces(&mut self, f: &[[Real; 2]], abut_sides: &[usize]) {
        let total = |fj: &[Real; 2]| fj.iter().copied().reduce(|a, b| a + b).unwrap_or(0.0);
        let nj = self.force.len();
        for (pk, fj) in self.force.iter_mut().zip(f) {
            let pk = pk.get_or_insert(0.0);
            *pk = pk.max(total(fj));
        }
        for (fj, &side) in f.iter().skip(nj).zip(abut_sides) {
            let pk = self.abut_force[side].get_or_insert(0.0);
            *pk = pk.max(total(fj));
        }
    }

    /// Monitors the state at `t`; `obs` receives what the history records. Inlined into the time
    /// loop (as [`super::driver::run`]'s other per-step parts).
    #[inline(always)]
    pub(crate) fn observe(
        &mut self,
        t: Real,
        q: &State,
        fr: &Frame,
        br: &Bridge,
        obs: &mut Observed,
    ) {
        let (bodies, pose) = (&br.bodies, &fr.pose);
        let (end_gaps, slips) = (&mut obs.end_gaps, &mut obs.slip);
        end_gaps.clear();
        slips.clear();
        for (k, (jg, jf)) in br.joints.iter().zip(&fr.joints).enumerate() {
            let eg = jf.sel.map(|s| s.map_or(Real::NAN, |i| jf.cands[i].gap));
            let mut gmin = Real::INFINITY;
            let mut gmax = Real::NEG_INFINITY;
            for g in eg.iter().filter(|g| !g.is_nan()) {
                gmin = gmin.min(*g);
                gmax = gmax.max(*g);
            }
            self.close[k] = self.close[k].max(jg.gap - gmin);
            self.pen = self.pen.max(-gmin);
            self.open[k] = self.open[k].max(gmax - jg.gap);
            // displacement of each face midpoint; slip = (d_a − d_b)·τ⁰
            let ma = bodies[jg.a].end.mid;
            let mb = bodies[jg.b].start.mid;
            let da = pose.place(bodies, jg.a, &ma) - ma;
            let db = pose.place(bodies, jg.b, &mb) - mb;
            let slip = (da - db).dot(&jg.tau0) + 0.0; // `+ 0.0` turns −0 into +0
            self.slip[k] = self.slip[k].max(slip.abs());
            end_gaps.push(eg);
            slips.push(slip);
        }
        for (j, r) in self.rot.iter_mut().enumerate() {
            *r = r.max(q[br.dofs.plan(j, PlanDof::Theta)].abs());
        }
        self.last_q.clear();
        self.last_q.extend_from_slice(q.as_slice());
        for (e, s_end) in br.seats.iter().enumerate() {
            // skipped where it cannot exceed the peak so far (nor, then, the seat): the corners'
            // displacement along n is at most d·n + |θ| |c − G⁰|, plus rounding
            let [x, y, th] = br.dofs.plan_of(s_end.body, q.as_slice());
            let base = Self::seat_base(s_end, q, br, &fr.ground);
            let (reach, scale) = self.seat_reach[e];
            let dn = (x - base.x) * s_end.inward.x + (y - base.y) * s_end.inward.y;
            let spin = th.abs() * reach;
            let bound = dn + spin + 1e-12 * (dn.abs() + spin + scale);
            if bound < self.seat[e] {
                continue;
            }
            let s = Self::seat_displacement(s_end, (pose, &fr.ground), bodies, q, br);
            if s > self.seat[e] {
                self.seat_time[e] = t;
            }
            self.seat[e] = self.seat[e].max(s);
            if self.unseat.is_none() && s > s_end.length {
                self.unseat = Some((t, e));
            }
        }
        let abut_gaps = &mut obs.abut_gaps;
        *abut_gaps = [Real::NAN; 2];
        for a in &br.abutments {
            let shift = a.shift_on(&br.dofs, q.as_slice(), &fr.ground);
            let gm = a
                .corners
                .iter()
                .map(|c| (pose.place(bodies, a.body, c) - a.point).dot(&a.normal) + shift)
                .fold(Real::INFINITY, Real::min);
            abut_gaps[a.side] = gm;
            let pk = self.abut[a.side].get_or_insert(Real::NEG_INFINITY);
            *pk = pk.max(a.gap - gm);
        }
    }
}

/// A backwall's coordinate `s` (into the soil, relative to its abutment's ground: `ground` the
/// support lines' offsets, empty when they move together), its backfill's force `F ≥ 0` and its
/// piles' force along `s` (`el`: the elements committed at `q`).
pub(crate) fn wall_forces(
    (wall, line): (usize, usize),
    q: &[Real],
    br: &Bridge,
    el: &super::elements::Elements,
    ground: &[Vector],
) -> (Real, Option<Real>, Option<Real>) {
    let mut s = br.dofs.axial_displacement(wall, q);
    if let Some(d) = ground.get(line) {
        s -= d.dot(&br.dofs.axis(wall));
    }
    let fill = el
        .backfills
        .iter()
        .find(|b| b.body == wall)
        .map(|b| b.element.committed().force);
    let piles = el.bearings.iter().find(|b| b.body == wall).map(|b| {
        let a = br.dofs.axis(wall);
        let k0 = b.law.k0();
        k0 * s - (1.0 - b.law.b()) * k0 * b.state.u_p.dot(&a)
    });
    (s, fill, piles)
}
