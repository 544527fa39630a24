//! Corner-against-face contacts at the joints in the current (moving) pose.
//!
//! Joint `k` lies between segment `a = k` (its end face) and segment `b = k + 1` (its start face);
//! `ν⁰` is the inward normal of `a`'s end face (pointing from `b` toward `a`) and `τ⁰ = perp(ν⁰)`.
//! In the two-deck model `a` is deck 1, `b` deck 2, `ν⁰ = (0, 1)`, `τ⁰ = (−1, 0)` (spec §4).
//!
//! Candidate `case` (spec §5.3): corner `c_k` of the striking segment against the joint-face line
//! of the struck one (`Deck1*`: `a` strikes `b`; `Deck2*`: `b` strikes `a`). In the current pose
//! (exact rotations, not linearised):
//!
//! * corner `P = G_s + Rot(θ_s)(c_k⁰ − G_s⁰)`, struck face midpoint `M = G + Rot(θ)(M⁰ − G⁰)`;
//! * `ν = Rot(θ_struck) ν⁰`, `τ = Rot(θ_struck) τ⁰`;
//! * signed gap `g_N = (P_a − P_b)·ν` = `(P − M_b)·ν` if `a` strikes, `(M_a − P)·ν` if `b` strikes;
//! * `σ = (P − M)·Rot(θ_struck) e` (`e` the struck face's direction); the corner lies over the
//!   face iff `|σ| ≤ W/2`;
//! * force directions (spec §6) with the contact point `C = P`, `r_j = C − G_j`:
//!   `w_N = (ν, r_a × ν)` on `a` and `(−ν, −r_b × ν)` on `b`; `w_T` likewise with `τ`.
//!
//! The two candidates at one end of the joint (`Deck1Inner` / `Deck2Outer` at corner `c0` of
//! `a`'s face, `Deck1Outer` / `Deck2Inner` at `c1`) describe the same pair of edges; the
//! simulator uses, per end, the candidate whose corner lies over the other face (spec §5.4; the
//! smaller gap if both do, i.e. corner on corner), so at most two contacts per joint.

use super::dofs::Dofs;
use super::model::{EndFace, SegmentBody};
use crate::geometry::ContactCase;
use crate::math::{Real, Vector, cross};
use nalgebra::DVector;

/// The generalised coordinates (or velocities) of a bridge: `(x_j, y_j, θ_j)` per segment.
pub(crate) type State = DVector<Real>;

/// `Rot(θ) v` with `sc = (sin θ, cos θ)`.
#[inline]
fn rotate(sc: (Real, Real), v: Vector) -> Vector {
    let (s, c) = sc;
    Vector::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// The reference geometry of one joint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct JointGeom {
    /// Segment whose end face is at the joint (deck 1's role).
    pub a: usize,
    /// Segment whose start face is at the joint (deck 2's role), `a + 1`.
    pub b: usize,
    /// Reference gap \[m\].
    pub gap: Real,
    /// Half the joint-face length \[m\].
    pub half_w: Real,
    /// `ν⁰`: unit normal from `b` toward `a`.
    pub nu0: Vector,
    /// `τ⁰ = perp(ν⁰)`.
    pub tau0: Vector,
}

impl JointGeom {
    /// The joint between segments `a` and `a + 1`.
    pub fn new(bodies: &[SegmentBody], a: usize, gap: Real) -> Self {
        let nu0 = bodies[a].end.inward;
        JointGeom {
            a,
            b: a + 1,
            gap,
            half_w: bodies[a].end.half,
            nu0,
            tau0: Vector::new(-nu0.y, nu0.x),
        }
    }
}

/// The current pose of every segment.
#[derive(Debug, Clone)]
pub(crate) struct Pose {
    /// Centroid displacements `(x_j, y_j)`.
    pub d: Vec<Vector>,
    /// `(sin θ_j, cos θ_j)`.
    pub sc: Vec<(Real, Real)>,
    /// Current centroids.
    pub g: Vec<Vector>,
}

impl Pose {
    /// The pose at `q`.
    pub fn new(bodies: &[SegmentBody], dofs: &Dofs, q: &[Real]) -> Self {
        let n = bodies.len();
        let mut pose = Pose {
            d: Vec::with_capacity(n),
            sc: Vec::with_capacity(n),
            g: Vec::with_capacity(n),
        };
        pose.set(bodies, dofs, q);
        pose
    }

    /// Overwrites this pose with the pose at `q` (reusing its storage).
    pub fn set(&mut self, bodies: &[SegmentBody], dofs: &Dofs, q: &[Real]) {
        self.d.clear();
        self.sc.clear();
        self.g.clear();
        for (j, b) in bodies.iter().enumerate() {
            let [x, y, th] = dofs.plan_of(j, q);
            let d = Vector::new(x, y);
            self.d.push(d);
            self.sc.push(th.sin_cos());
            self.g.push(b.centroid + d);
        }
    }
    /// Current position of segment `j`'s (0-based) body point with reference position `p0`.
    #[inline]
    pub fn place(&self, bodies: &[SegmentBody], j: usize, p0: &Vector) -> Vector {
        bodies[j].place(p0, &self.d[j], self.sc[j])
    }
}

/// `(striking role r, corner index k)`, 0-based (`r = 0`: segment `a`), of a case.
pub(crate) fn case_parts(case: ContactCase) -> (usize, usize) {
    match case {
        ContactCase::Deck1Inner => (0, 0),
        ContactCase::Deck1Outer => (0, 1),
        ContactCase::Deck2Inner => (1, 0),
        ContactCase::Deck2Outer => (1, 1),
    }
}

/// The two candidates of each joint end: end 0 at `a`'s corner `c0`, end 1 at its `c1`.
pub(crate) const ENDS: [[ContactCase; 2]; 2] = [
    [ContactCase::Deck1Inner, ContactCase::Deck2Outer],
    [ContactCase::Deck1Outer, ContactCase::Deck2Inner],
];

/// A generalised force direction of a contact: the 3-vectors it puts on one or two segments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Direction {
    /// `(segment, (f_x, f_y, m))` of the first segment.
    pub first: (usize, [Real; 3]),
    /// The second segment, if any (abutments act on one).
    pub second: Option<(usize, [Real; 3])>,
}

impl Direction {
    /// The dense column in `q` coordinates (`dofs.len()` entries).
    pub fn dense(&self, dofs: &Dofs) -> State {
        let mut w = State::zeros(dofs.len());
        for (j, v) in std::iter::once(self.first).chain(self.second) {
            dofs.add_plan(j, w.as_mut_slice(), v);
        }
        w
    }
}

impl Direction {
    /// The column in `q` coordinates as its nonzero entries ([`Sparse`]: the same values as
    /// [`Self::dense`], without the zeros).
    pub fn sparse(&self, dofs: &Dofs) -> Sparse {
        let mut w = Sparse::ZERO;
        w.add_body(dofs, self.first);
        if let Some(second) = self.second {
            w.add_body(dofs, second);
        }
        w
    }
}

/// A generalised direction with at most six entries (a contact acts on at most two bodies of at
/// most three coordinates each): `(index, value)` pairs into a `q`-length column. Copied, never
/// allocated: the contact steppers evaluate thousands of these per second of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sparse {
    idx: [usize; 6],
    val: [Real; 6],
    len: usize,
}

impl Sparse {
    /// No entry (an open contact's direction).
    pub const ZERO: Sparse = Sparse {
        idx: [0; 6],
        val: [0.0; 6],
        len: 0,
    };

    /// The plan wrench `v = (f_x, f_y, m)` on body `j` ([`Dofs::add_plan`]'s entries).
    #[inline]
    fn add_body(&mut self, dofs: &Dofs, (j, v): (usize, [Real; 3])) {
        let (s, n) = (dofs.start(j), self.len);
        match dofs.kind(j) {
            super::dofs::BodyKind::PlanRigid => {
                self.idx[n..n + 3].copy_from_slice(&[s, s + 1, s + 2]);
                self.val[n..n + 3].copy_from_slice(&v);
                self.len += 3;
            }
            super::dofs::BodyKind::PlanPoint => {
                self.idx[n..n + 2].copy_from_slice(&[s, s + 1]);
                self.val[n..n + 2].copy_from_slice(&v[..2]);
                self.len += 2;
            }
            super::dofs::BodyKind::Axial => {
                let a = dofs.axis(j);
                self.idx[n] = s;
                self.val[n] = v[0] * a.x + v[1] * a.y;
                self.len += 1;
            }
        }
    }

    /// The `(index, value)` entries.
    #[inline]
    pub fn entries(&self) -> impl Iterator<Item = (usize, Real)> + '_ {
        self.idx[..self.len]
            .iter()
            .copied()
            .zip(self.val[..self.len].iter().copied())
    }

    /// `wᵀ u`.
    #[inline]
    pub fn dot(&self, u: &[Real]) -> Real {
        self.entries().map(|(i, w)| w * u[i]).sum()
    }

    /// `out += a w`.
    #[inline]
    pub fn axpy(&self, a: Real, out: &mut [Real]) {
        for (i, w) in self.entries() {
            out[i] += a * w;
        }
    }

    /// The dense column of `n` entries.
    pub fn dense(&self, n: usize) -> State {
        let mut w = State::zeros(n);
        self.axpy(1.0, w.as_mut_slice());
        w
    }
}

/// One candidate contact in the current pose.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Candidate {
    pub case: ContactCase,
    pub gap: Real,
    pub sigma: Real,
    pub point: Vector,
    pub normal: Vector,
    pub tangent: Vector,
}

/// What the two candidates struck on one face share: the face's current midpoint `M` and
/// `ν = Rot(θ_struck) ν⁰`, `τ = Rot(θ_struck) τ⁰`, `Rot(θ_struck) e` (computed once per face).
struct StruckFace {
    mid: Vector,
    normal: Vector,
    tangent: Vector,
    dir: Vector,
}

impl StruckFace {
    fn new(
        bodies: &[SegmentBody],
        pose: &Pose,
        joint: &JointGeom,
        j: usize,
        face: &EndFace,
    ) -> Self {
        let sc = pose.sc[j];
        StruckFace {
            mid: pose.place(bodies, j, &face.mid),
            normal: rotate(sc, joint.nu0),
            tangent: rotate(sc, joint.tau0),
            dir: rotate(sc, face.dir),
        }
    }
}

impl Candidate {
    /// The candidate `case` of the striking corner at `p` against the struck face `f`.
    fn new(case: ContactCase, p: Vector, f: &StruckFace) -> Self {
        let (r, _) = case_parts(case);
        let gap = if r == 0 {
            (p - f.mid).dot(&f.normal)
        } else {
            (f.mid - p).dot(&f.normal)
        };
        Candidate {
            case,
            gap,
            sigma: (p - f.mid).dot(&f.dir),
            point: p,
            normal: f.normal,
            tangent: f.tangent,
        }
    }

    /// `(w_N, w_T)` of this candidate at `joint` (spec §6).
    pub fn force_directions(&self, pose: &Pose, joint: &JointGeom) -> (Direction, Direction) {
        (
            self.direction(pose, joint, self.normal),
            self.direction(pose, joint, self.tangent),
        )
    }

    /// The generalised direction of a force along the unit vector `v` at this candidate's
    /// point: `+v` on segment `a`, `−v` on segment `b`, with their moments about the centroids.
    pub fn direction(&self, pose: &Pose, joint: &JointGeom, v: Vector) -> Direction {
        let r1 = self.point - pose.g[joint.a];
        let r2 = self.point - pose.g[joint.b];
        Direction {
            first: (joint.a, [v.x, v.y, cross(&r1, &v)]),
            second: Some((joint.b, [-v.x, -v.y, -cross(&r2, &v)])),
        }
    }
}

/// The four candidates of one joint (in [`ContactCase::ALL`] order) and, per joint end, the
/// index (into that array) of the candidate that is geometrically realised, if any.
#[derive(Debug, Clone, Copy)]
pub(crate) struct JointFrame {
    pub cands: [Candidate; 4],
    pub sel: [Option<usize>; 2],
}

/// The candidates of `joint` in `pose` ([`JointFrame`]).
pub(crate) fn candidates(bodies: &[SegmentBody], pose: &Pose, joint: &JointGeom) -> JointFrame {
    let (sa, sb) = (&bodies[joint.a], &bodies[joint.b]);
    // per striking role r (0: segment a's end corners strike b's start face; 1: b's start
    // corners strike a's end face): the placed corners and the struck face, shared by the
    // candidates of that role
    let struck = [
        StruckFace::new(bodies, pose, joint, joint.b, &sb.start),
        StruckFace::new(bodies, pose, joint, joint.a, &sa.end),
    ];
    // (element by element: `[T; N]::map` does not always compile to straight-line code)
    let (ca, cb) = (&sa.end.corners, &sb.start.corners);
    let corners = [
        [
            pose.place(bodies, joint.a, &ca[0]),
            pose.place(bodies, joint.a, &ca[1]),
        ],
        [
            pose.place(bodies, joint.b, &cb[0]),
            pose.place(bodies, joint.b, &cb[1]),
        ],
    ];
    let cand = |i: usize| {
        let c = ContactCase::ALL[i];
        let (r, k) = case_parts(c);
        Candidate::new(c, corners[r][k], &struck[r])
    };
    let all = [cand(0), cand(1), cand(2), cand(3)];
    let half_width = joint.half_w;
    let tol = 1e-9 * half_width;
    let mut sel = [None, None];
    for (e, pair) in ENDS.iter().enumerate() {
        let i0 = pair[0] as usize;
        let i1 = pair[1] as usize;
        let on0 = all[i0].sigma.abs() <= half_width + tol;
        let on1 = all[i1].sigma.abs() <= half_width + tol;
        sel[e] = match (on0, on1) {
            (true, true) => Some(if all[i1].gap < all[i0].gap { i1 } else { i0 }),
            (true, false) => Some(i0),
            (false, true) => Some(i1),
            (false, false) => None,
        };
    }
    JointFrame { cands: all, sel }
}

/// `Σ_d w_d v_d` over the entries of `w` in order (a left-to-right sum, as the dense 6-entry
/// sum of the two-deck model).
#[inline(always)]
pub(crate) fn dot_dir(w: &Direction, v: &State, dofs: &Dofs) -> Real {
    let (j0, a0) = w.first;
    let v0 = dofs.plan_of(j0, v.as_slice());
    let head = (0..3).map(move |i| a0[i] * v0[i]);
    match w.second {
        None => head.sum(),
        Some((j1, a1)) => {
            let v1 = dofs.plan_of(j1, v.as_slice());
            head.chain((0..3).map(move |i| a1[i] * v1[i])).sum()
        }
    }
}
