//! Corner-against-face contacts at the joint in the current (moving) pose.
//!
//! Candidate `case` (spec §5.3): corner `c_k` of the striking deck `a` against the joint-face line
//! of the struck deck `b`. In the current pose (exact rotations, not linearised):
//!
//! * corner `P = G_a + Rot(θ_a)(c_k⁰ − G_a⁰)`, face midpoint `M_b = G_b + Rot(θ_b)(M_b⁰ − G_b⁰)`;
//! * `ν = Rot(θ_b)(0, 1)` (deck-2 side → deck-1 side), `τ = Rot(θ_b)(−1, 0)`;
//! * signed gap `g_N = (P_1 − P_2)·ν` = `(P − M_2)·ν` if `a = 1`, `(M_1 − P)·ν` if `a = 2`;
//! * `σ_b = (P − M_b)·Rot(θ_b) e_b`; the corner lies over the face iff `|σ_b| ≤ W/2`;
//! * force directions (spec §6) with the contact point `C = P`, `r_j = C − G_j`:
//!   `w_N = (ν, r_1 × ν, −ν, −r_2 × ν)`, `w_T = (τ, r_1 × τ, −τ, −r_2 × τ)`.
//!
//! The two candidates at one end of the joint (deck1-inner / deck2-outer at `x = +W/2`,
//! deck1-outer / deck2-inner at `x = −W/2`, spec §4) describe the same pair of edges; the
//! simulator uses, per end, the candidate whose corner lies over the other face (spec §5.4; the
//! smaller gap if both do, i.e. corner on corner), so at most two contacts enter the LCP.

use super::model::DeckBody;
use crate::geometry::ContactCase;
use crate::math::{Real, Vector, cross};

/// The current pose of both decks.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pose {
    /// Centroid displacements `(x_j, y_j)`.
    pub d: [Vector; 2],
    /// `(sin θ_j, cos θ_j)`.
    pub sc: [(Real, Real); 2],
    /// Current centroids.
    pub g: [Vector; 2],
}

impl Pose {
    pub fn new(bodies: &[DeckBody; 2], q: &[Real; 6]) -> Self {
        let d = [Vector::new(q[0], q[1]), Vector::new(q[3], q[4])];
        Pose {
            d,
            sc: [q[2].sin_cos(), q[5].sin_cos()],
            g: [bodies[0].centroid + d[0], bodies[1].centroid + d[1]],
        }
    }
    /// Current position of deck `j`'s (0-based) body point with reference position `p0`.
    #[inline]
    pub fn place(&self, bodies: &[DeckBody; 2], j: usize, p0: &Vector) -> Vector {
        bodies[j].place(p0, &self.d[j], self.sc[j])
    }
}

/// `(striking deck index a, corner index k)`, 0-based, of a case.
pub(crate) fn case_parts(case: ContactCase) -> (usize, usize) {
    match case {
        ContactCase::Deck1Inner => (0, 0),
        ContactCase::Deck1Outer => (0, 1),
        ContactCase::Deck2Inner => (1, 0),
        ContactCase::Deck2Outer => (1, 1),
    }
}

/// The two candidates of each joint end: end 0 at `x = +W/2`, end 1 at `x = −W/2`.
pub(crate) const ENDS: [[ContactCase; 2]; 2] = [
    [ContactCase::Deck1Inner, ContactCase::Deck2Outer],
    [ContactCase::Deck1Outer, ContactCase::Deck2Inner],
];

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

impl Candidate {
    pub fn new(bodies: &[DeckBody; 2], pose: &Pose, case: ContactCase) -> Self {
        let (a, k) = case_parts(case);
        let b = 1 - a;
        let p = pose.place(bodies, a, &bodies[a].joint_corners[k]);
        let mb = pose.place(bodies, b, &bodies[b].face_mid);
        let (s, c) = pose.sc[b];
        let normal = Vector::new(-s, c);
        let tangent = Vector::new(-c, -s);
        let gap = if a == 0 {
            (p - mb).dot(&normal)
        } else {
            (mb - p).dot(&normal)
        };
        let e = bodies[b].face_dir;
        let e_rot = Vector::new(c * e.x - s * e.y, s * e.x + c * e.y);
        Candidate {
            case,
            gap,
            sigma: (p - mb).dot(&e_rot),
            point: p,
            normal,
            tangent,
        }
    }

    /// `(w_N, w_T)` in `q` coordinates (spec §6).
    pub fn force_directions(&self, pose: &Pose) -> ([Real; 6], [Real; 6]) {
        let r1 = self.point - pose.g[0];
        let r2 = self.point - pose.g[1];
        let (n, t) = (self.normal, self.tangent);
        (
            [n.x, n.y, cross(&r1, &n), -n.x, -n.y, -cross(&r2, &n)],
            [t.x, t.y, cross(&r1, &t), -t.x, -t.y, -cross(&r2, &t)],
        )
    }
}

/// All four candidates (in [`ContactCase::ALL`] order) and, per joint end, the index (into that
/// array) of the candidate that is geometrically realised, if any.
pub(crate) fn candidates(
    bodies: &[DeckBody; 2],
    pose: &Pose,
    half_width: Real,
) -> ([Candidate; 4], [Option<usize>; 2]) {
    let all = ContactCase::ALL.map(|c| Candidate::new(bodies, pose, c));
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
    (all, sel)
}
