//! Event-exact reference for a straight chain of `N ≥ 1` rigid decks on one line (issue 11,
//! acceptance "Rigid law"), written independently of the simulator as test support.
//!
//! # Model
//! Decks `i = 0..N` (deck `i + 1` of the issue), displacement `x_i` relative to the ground along
//! +x (from the start abutment toward the end one), each on a spring `k_i` and a dashpot `c_i` to
//! the ground, load `−m_i a_g(t)` (`a_g` linear between record samples, zero before the first and
//! after the last, times `scale`):
//!
//! `m_i ẍ_i + c_i ẋ_i + k_i x_i = −m_i a_g + λ_i − λ_{i+1}`.
//!
//! Contacts `j = 0..=N`: contact `j` lies between deck `j − 1` and deck `j`, a missing deck being
//! a fixed wall (`x = 0`): contact 0 is the start abutment, `1..N−1` the joints (joint `j` of the
//! issue), `N` the end abutment. Gap `g_j − (x_{j−1} − x_j)`, its rate `γ_j = v_j − v_{j−1}`;
//! `λ_j ≥ 0` pushes deck `j` along +x and deck `j − 1` along −x. A missing abutment is a contact
//! that never closes.
//!
//! # Events
//! * **Flight**: decks joined by closed contacts form a cluster; a free cluster is the 1-DOF
//!   oscillator `M ü + C u̇ + K u = −M a_g − Σ k_i o_i` in the displacement `u` of its first deck
//!   (`x_i = u + o_i`, `o_i` fixed by the gaps; `M, C, K` summed), solved in closed form over each
//!   linear piece of the record (homogeneous + particular solution, [`flight`]); a cluster held by
//!   an abutment is at rest. Contact forces of closed contacts follow from the equations of motion
//!   by a recursion from the cluster's free end.
//! * **Event functions**: open gaps `g + δ_g` (`δ_g` = [`GAP_EVENT`]) and closed forces
//!   `λ + δ_λ` (`δ_λ` = [`FORCE_EVENT_PER_KG`]` · Σm`); each linear piece of the record (at most
//!   10 ms) is cut into [`Chain::sub`] parts, each part split at the minima of the function
//!   (derivative sign change, found by bisection), and the first sign change is bisected to the
//!   rounding level (≈ 1e-16 s).
//! * **Impacts**: at an event, every contact touching (`gap ≤` [`GAP_TOUCH`]) or closed takes part
//!   in one simultaneous Newton impact LCP (spec §8 as amended: `ξ_j = γ_j⁺ + ε_j min(γ_j⁻, 0) ≥ 0
//!   ⊥ P_j ≥ 0`, restitution only for approaching contacts) solved exactly by enumerating the
//!   active sets ([`impact_lcp`]): the same law the simulator's one-LCP-per-step applies to all
//!   contacts active in a step. An approach slower than [`V_CUT`] is made plastic (`ε = 0`): this
//!   ends a Zeno accumulation (the bounce velocities fall as `ε^n`) in finitely many events.
//! * **Sustained contact**: after the impact, the touching contacts with `|γ⁺| ≤` [`V_ZERO`] are
//!   split into closed and open by the contact LCP at acceleration level (`λ ≥ 0` closed, gap
//!   acceleration `≥ 0` open), enumerated, the most closed feasible set preferred; a closed contact
//!   reopens when its force turns tensile (root of `λ + δ_λ`).
//! * An **impact** of contact `j` is counted when its approach speed is `≥` [`V_COUNT`] (1 mm/s)
//!   and it receives a positive impulse (the simulator's definition).
#![allow(clippy::needless_range_loop, dead_code)]

use pounding::ground_motion::Record;

/// Approach speeds below this are made plastic (end of an accumulation) \[m/s\].
pub const V_CUT: f64 = 1e-5;
/// Approach speed from which an impact is counted \[m/s\] (the simulator's 1 mm/s).
pub const V_COUNT: f64 = 1e-3;
/// Post-impact relative speeds below this count as zero (candidates for sustained contact) \[m/s\].
pub const V_ZERO: f64 = 1e-9;
/// A gap event fires when the gap falls below `−GAP_EVENT` \[m\] (no re-detection at a touch).
pub const GAP_EVENT: f64 = 1e-13;
/// Contacts with a gap below this take part in an event \[m\].
pub const GAP_TOUCH: f64 = 1e-11;
/// A contact-force event fires when `λ < −FORCE_EVENT_PER_KG · Σm` \[N/kg\].
pub const FORCE_EVENT_PER_KG: f64 = 1e-10;
/// Tolerance of the acceleration-level contact LCP \[m/s²\].
const ACC_TOL: f64 = 1e-9;
/// Default parts of each piece for bracketing roots and extrema ([`Chain::sub`]).
pub const SUB: usize = 16;
/// Events allowed inside one record interval before the reference gives up (Zeno guard).
const MAX_EVENTS_PER_INTERVAL: usize = 100_000;

/// A straight chain of rigid decks between optional abutments.
#[derive(Clone, Debug)]
pub struct Chain {
    /// Masses \[kg\], one per deck, from the start abutment.
    pub m: Vec<f64>,
    /// Bearing stiffnesses to the ground \[N/m\].
    pub k: Vec<f64>,
    /// Dashpots to the ground \[N s/m\].
    pub c: Vec<f64>,
    /// Joint gaps \[m\]: `gaps[j − 1]` between deck `j − 1` and deck `j` (length `N − 1`).
    pub gaps: Vec<f64>,
    /// Gap of the start abutment \[m\] (`None`: no abutment).
    pub gap_start: Option<f64>,
    /// Gap of the end abutment \[m\] (`None`: no abutment).
    pub gap_end: Option<f64>,
    /// Newton restitution per contact `[start, joint 1, …, joint N−1, end]` (length `N + 1`).
    pub eps: Vec<f64>,
    /// Parts of each piece for bracketing roots and extrema (default [`SUB`]).
    pub sub: usize,
}

/// One event with an impact (the simultaneous LCP of all touching contacts).
#[derive(Clone, Debug)]
pub struct ChainImpact {
    /// Time \[s\].
    pub t: f64,
    /// The contacts taking part.
    pub contacts: Vec<usize>,
    /// Their rates `γ⁻`, `γ⁺` \[m/s\] and impulses `P ≥ 0` \[N s\].
    pub gamma_pre: Vec<f64>,
    /// Post-impact rates (before sticking contacts are joined).
    pub gamma_post: Vec<f64>,
    /// Impulses.
    pub impulse: Vec<f64>,
    /// Deck velocities before and after \[m/s\].
    pub v_pre: Vec<f64>,
    /// Deck velocities after the impact (before sticking contacts are joined).
    pub v_post: Vec<f64>,
}

/// The outputs the simulator is checked against (issue 11's `summary.json` quantities).
#[derive(Clone, Debug, PartialEq)]
pub struct ChainSummary {
    /// Impacts per contact `[start, joint 1, …, joint N−1, end]`.
    pub impacts: Vec<usize>,
    /// Per joint: max over time of `g − gap = x_{j−1} − x_j` \[m\] (`= g` once touched).
    pub peak_closing: Vec<f64>,
    /// Per joint: max over time of `gap − g = x_j − x_{j−1}` (≥ 0, the start is at rest) \[m\].
    pub peak_opening: Vec<f64>,
    /// Per deck: max over time of `|x_i|` \[m\].
    pub peak_displacement: Vec<f64>,
    /// Per deck: `|x_i(t_end)|` \[m\].
    pub final_displacement: Vec<f64>,
}

/// Energy terms at the end of the solution \[J\]: `initial + input = kinetic + strain + dashpot +
/// impact_loss` (the contact forces of sustained contact do no work).
#[derive(Clone, Copy, Debug)]
pub struct ChainEnergy {
    /// Kinetic + strain energy at `t = 0`.
    pub initial: f64,
    /// Work of the loads `−m_i a_g` on `ẋ_i` (5-point Gauss–Legendre per piece).
    pub input: f64,
    /// Kinetic energy at the end.
    pub kinetic: f64,
    /// Strain energy `Σ k x² / 2` at the end.
    pub strain: f64,
    /// Dashpot dissipation `∫ Σ c ẋ²` (5-point Gauss–Legendre per piece).
    pub dashpot: f64,
    /// Kinetic energy lost in impacts (and joining at zero relative speed).
    pub impact_loss: f64,
}

impl ChainEnergy {
    /// `|initial + input − (kinetic + strain + dashpot + impact_loss)|` over the largest term.
    pub fn relative_residual(&self) -> f64 {
        let lhs = self.initial + self.input;
        let rhs = self.kinetic + self.strain + self.dashpot + self.impact_loss;
        let scale = [
            lhs,
            self.kinetic,
            self.strain,
            self.dashpot,
            self.impact_loss,
        ]
        .iter()
        .fold(0.0f64, |a, b| a.max(b.abs()));
        (lhs - rhs).abs() / scale
    }
}

/// State of the chain at one instant (positions, velocities, closed contacts).
#[derive(Clone, Debug)]
struct Snap {
    x: Vec<f64>,
    v: Vec<f64>,
    closed: Vec<bool>,
}

/// A run of decks `first..=last` joined by closed contacts.
#[derive(Clone, Debug)]
struct Cluster {
    first: usize,
    last: usize,
    /// `x_i = u + off[i − first]` (free), `x_i = off[i − first]` (held by an abutment).
    off: Vec<f64>,
    held: bool,
    /// Held by the start abutment (force recursion from the right end).
    held_start: bool,
    u0: f64,
    v0: f64,
    beta: f64,
    w2: f64,
    /// `Σ k_i o_i / M`.
    koff: f64,
}

/// Closed-form motion on `[t0, t1]` with `a_g = a0 + a1 (t − t0)`.
#[derive(Clone, Debug)]
struct Piece {
    t0: f64,
    t1: f64,
    a0: f64,
    a1: f64,
    closed: Vec<bool>,
    clusters: Vec<Cluster>,
}

/// Kinematics of every deck at one instant: position, velocity, acceleration, jerk.
struct Kin {
    x: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    j: Vec<f64>,
    ag: f64,
    ag_rate: f64,
}

/// `(u, u̇)` at `τ` of `ü + β u̇ + ω² u = f0 + f1 τ` from `(u0, v0)`: the particular solution
/// `A + B τ` (`B = f1/ω²`, `A = (f0 − β B)/ω²`) plus the damped free vibration
/// `e^{−στ} (C1 cos ω_d τ + C2 sin ω_d τ)`, `σ = β/2`, `ω_d = √(ω² − σ²)` (underdamped); for
/// `ω = β = 0` the cubic `u0 + v0 τ + f0 τ²/2 + f1 τ³/6`.
pub fn flight(beta: f64, w2: f64, u0: f64, v0: f64, f0: f64, f1: f64, tau: f64) -> (f64, f64) {
    if w2 == 0.0 {
        assert!(
            beta == 0.0,
            "a cluster without springs must be undamped here"
        );
        let u = u0 + tau * (v0 + tau * (f0 / 2.0 + tau * f1 / 6.0));
        return (u, v0 + tau * (f0 + tau * f1 / 2.0));
    }
    let sigma = beta / 2.0;
    assert!(
        sigma * sigma < w2,
        "overdamped cluster (ζ ≥ 1) is not supported"
    );
    let wd = (w2 - sigma * sigma).sqrt();
    let bp = f1 / w2;
    let ap = (f0 - beta * bp) / w2;
    let c1 = u0 - ap;
    let c2 = (v0 - bp + sigma * c1) / wd;
    let e = (-sigma * tau).exp();
    let (s, c) = (wd * tau).sin_cos();
    let u = ap + bp * tau + e * (c1 * c + c2 * s);
    let v = bp + e * ((wd * c2 - sigma * c1) * c - (sigma * c2 + wd * c1) * s);
    (u, v)
}

/// Solves the dense system `a z = b` (Gaussian elimination, partial pivoting).
fn solve_dense(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for col in 0..n {
        let p = (col..n).max_by(|&r, &s| a[r][col].abs().total_cmp(&a[s][col].abs()))?;
        if a[p][col].abs() < 1e-300 {
            return None;
        }
        a.swap(col, p);
        b.swap(col, p);
        for r in col + 1..n {
            let f = a[r][col] / a[col][col];
            for cc in col..n {
                a[r][cc] -= f * a[col][cc];
            }
            b[r] -= f * b[col];
        }
    }
    let mut z = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|cc| a[r][cc] * z[cc]).sum();
        z[r] = (b[r] - s) / a[r][r];
    }
    Some(z)
}

/// The LCP `w = W z + q ≥ 0, z ≥ 0, zᵀw = 0` for a P-matrix `W`, solved exactly by enumerating
/// the active sets (`z_i > 0 ⇒ w_i = 0`); `n ≤ 16`. Returns `z`.
pub fn impact_lcp(w: &[Vec<f64>], q: &[f64]) -> Vec<f64> {
    let n = q.len();
    assert!(
        n <= 16,
        "too many simultaneous contacts for the enumeration"
    );
    let scale = q.iter().fold(0.0f64, |a, b| a.max(b.abs())).max(1e-300);
    let mut best: Option<(f64, Vec<f64>)> = None;
    for mask in 0u32..(1 << n) {
        let act: Vec<usize> = (0..n).filter(|i| mask & (1 << i) != 0).collect();
        let sub: Vec<Vec<f64>> = act
            .iter()
            .map(|&r| act.iter().map(|&c| w[r][c]).collect())
            .collect();
        let rhs: Vec<f64> = act.iter().map(|&r| -q[r]).collect();
        let Some(za) = solve_dense(sub, rhs) else {
            continue;
        };
        let mut z = vec![0.0; n];
        for (i, &r) in act.iter().enumerate() {
            z[r] = za[i];
        }
        // violation: negative impulses (in velocity units) and negative w of inactive rows
        let mut viol = 0.0f64;
        for r in 0..n {
            let wr: f64 = q[r] + (0..n).map(|c| w[r][c] * z[c]).sum::<f64>();
            if mask & (1 << r) != 0 {
                viol = viol.max(-z[r] * w[r][r]);
            } else {
                viol = viol.max(-wr);
            }
        }
        if best.as_ref().is_none_or(|(b, _)| viol < *b) {
            best = Some((viol, z));
        }
    }
    let (viol, z) = best.expect("the empty set always solves");
    assert!(
        viol <= 1e-9 * scale,
        "impact LCP unsolved: violation {viol}"
    );
    z.into_iter().map(|v| v.max(0.0)).collect()
}

impl Chain {
    /// Number of decks.
    pub fn n(&self) -> usize {
        self.m.len()
    }

    /// A chain with one restitution coefficient for every contact.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        m: Vec<f64>,
        k: Vec<f64>,
        c: Vec<f64>,
        gaps: Vec<f64>,
        gap_start: Option<f64>,
        gap_end: Option<f64>,
        eps: f64,
    ) -> Self {
        let n = m.len();
        assert!(n >= 1 && k.len() == n && c.len() == n && gaps.len() == n - 1);
        Chain {
            m,
            k,
            c,
            gaps,
            gap_start,
            gap_end,
            eps: vec![eps; n + 1],
            sub: SUB,
        }
    }

    /// Reference gap of contact `j` (`None`: absent abutment).
    pub fn gap_ref(&self, j: usize) -> Option<f64> {
        let n = self.n();
        if j == 0 {
            self.gap_start
        } else if j == n {
            self.gap_end
        } else {
            Some(self.gaps[j - 1])
        }
    }

    /// Current gap of contact `j` for positions `x` (`+∞` for an absent abutment).
    pub fn gap(&self, j: usize, x: &[f64]) -> f64 {
        let Some(g) = self.gap_ref(j) else {
            return f64::INFINITY;
        };
        g - (side(x, j as isize - 1) - side(x, j as isize))
    }

    /// Rate `γ_j = v_j − v_{j−1}` of contact `j`.
    pub fn gamma(&self, j: usize, v: &[f64]) -> f64 {
        side(v, j as isize) - side(v, j as isize - 1)
    }

    fn kinetic(&self, v: &[f64]) -> f64 {
        (0..self.n()).map(|i| 0.5 * self.m[i] * v[i] * v[i]).sum()
    }
    fn strain(&self, x: &[f64]) -> f64 {
        (0..self.n()).map(|i| 0.5 * self.k[i] * x[i] * x[i]).sum()
    }

    /// The clusters of a snapshot (positions and velocities of joined decks made consistent:
    /// offsets from the gaps, the cluster's momentum-weighted velocity, rest when held).
    fn clusters(&self, s: &Snap) -> Vec<Cluster> {
        let n = self.n();
        let mut out = Vec::new();
        let mut first = 0;
        while first < n {
            let mut last = first;
            while last + 1 < n && s.closed[last + 1] {
                last += 1;
            }
            let held_start = first == 0 && s.closed[0];
            let held_end = last == n - 1 && s.closed[n];
            assert!(
                !(held_start && held_end),
                "a cluster held by both abutments (degenerate)"
            );
            let mut off = vec![0.0; last - first + 1];
            for i in first + 1..=last {
                off[i - first] = off[i - first - 1] - self.gaps[i - 1];
            }
            let (mm, cc, kk) = (first..=last).fold((0.0, 0.0, 0.0), |(a, b, c), i| {
                (a + self.m[i], b + self.c[i], c + self.k[i])
            });
            let held = held_start || held_end;
            let (u0, v0) = if held {
                // x_first = −g_start, or x_last = g_end
                let base = if held_start {
                    -self.gap_start.unwrap()
                } else {
                    self.gap_end.unwrap() - off[last - first]
                };
                for o in off.iter_mut() {
                    *o += base;
                }
                (0.0, 0.0)
            } else {
                let p: f64 = (first..=last).map(|i| self.m[i] * s.v[i]).sum();
                (s.x[first], p / mm)
            };
            let koff = if held {
                0.0
            } else {
                (first..=last)
                    .map(|i| self.k[i] * off[i - first])
                    .sum::<f64>()
                    / mm
            };
            out.push(Cluster {
                first,
                last,
                off,
                held,
                held_start,
                u0,
                v0,
                beta: cc / mm,
                w2: kk / mm,
                koff,
            });
            first = last + 1;
        }
        out
    }

    fn piece(&self, t0: f64, t1: f64, a0: f64, a1: f64, s: &Snap) -> Piece {
        Piece {
            t0,
            t1,
            a0,
            a1,
            closed: s.closed.clone(),
            clusters: self.clusters(s),
        }
    }

    fn kin(&self, p: &Piece, tau: f64) -> Kin {
        let n = self.n();
        let mut k = Kin {
            x: vec![0.0; n],
            v: vec![0.0; n],
            a: vec![0.0; n],
            j: vec![0.0; n],
            ag: p.a0 + p.a1 * tau,
            ag_rate: p.a1,
        };
        for cl in &p.clusters {
            let (u, ud, udd, uddd) = if cl.held {
                (0.0, 0.0, 0.0, 0.0)
            } else {
                let (f0, f1) = (-p.a0 - cl.koff, -p.a1);
                let (u, ud) = flight(cl.beta, cl.w2, cl.u0, cl.v0, f0, f1, tau);
                let udd = f0 + f1 * tau - cl.beta * ud - cl.w2 * u;
                (u, ud, udd, f1 - cl.beta * udd - cl.w2 * ud)
            };
            for i in cl.first..=cl.last {
                k.x[i] = u + cl.off[i - cl.first];
                k.v[i] = ud;
                k.a[i] = udd;
                k.j[i] = uddd;
            }
        }
        k
    }

    /// Forces `λ_j` and rates `λ̇_j` of the closed contacts (0 for open ones), from each cluster's
    /// free end: `λ_{i+1} = λ_i − R_i`, `R_i = m_i (ẍ_i + a_g) + c_i ẋ_i + k_i x_i`.
    fn forces(&self, p: &Piece, k: &Kin) -> (Vec<f64>, Vec<f64>) {
        let n = self.n();
        let mut lam = vec![0.0; n + 1];
        let mut dlam = vec![0.0; n + 1];
        let r = |i: usize| {
            (
                self.m[i] * (k.a[i] + k.ag) + self.c[i] * k.v[i] + self.k[i] * k.x[i],
                self.m[i] * (k.j[i] + k.ag_rate) + self.c[i] * k.a[i] + self.k[i] * k.v[i],
            )
        };
        for cl in &p.clusters {
            if cl.held_start {
                let (mut l, mut dl) = (0.0, 0.0);
                for i in (cl.first..=cl.last).rev() {
                    let (ri, dri) = r(i);
                    l += ri;
                    dl += dri;
                    lam[i] = l;
                    dlam[i] = dl;
                }
            } else {
                let (mut l, mut dl) = (0.0, 0.0);
                for i in cl.first..=cl.last {
                    let (ri, dri) = r(i);
                    l -= ri;
                    dl -= dri;
                    if p.closed[i + 1] {
                        lam[i + 1] = l;
                        dlam[i + 1] = dl;
                    }
                }
            }
        }
        (lam, dlam)
    }

    /// Mobile deck `i` (−1 and N are the walls).
    fn mobile(&self, p: &Piece, i: isize) -> bool {
        if i < 0 || i >= self.n() as isize {
            return false;
        }
        !p.clusters
            .iter()
            .any(|c| c.held && (c.first..=c.last).contains(&(i as usize)))
    }

    /// Event functions `(value, rate)` per contact (`None` where no event can occur).
    fn events(&self, p: &Piece, tau: f64) -> Vec<Option<(f64, f64)>> {
        let k = self.kin(p, tau);
        let (lam, dlam) = self.forces(p, &k);
        let dl = FORCE_EVENT_PER_KG * self.m.iter().sum::<f64>();
        (0..=self.n())
            .map(|j| {
                if p.closed[j] {
                    Some((lam[j] + dl, dlam[j]))
                } else if self.gap_ref(j).is_some()
                    && (self.mobile(p, j as isize - 1) || self.mobile(p, j as isize))
                {
                    Some((self.gap(j, &k.x) + GAP_EVENT, self.gamma(j, &k.v)))
                } else {
                    None
                }
            })
            .collect()
    }

    /// First `τ ∈ (0, t1 − t0]` where an event function becomes negative.
    fn next_event(&self, p: &Piece) -> Option<f64> {
        let len = p.t1 - p.t0;
        if len <= 0.0 {
            return None;
        }
        let nc = self.n() + 1;
        let mut lo = 0.0;
        let mut e_lo = self.events(p, 0.0);
        for s in 1..=self.sub {
            let hi = len * s as f64 / self.sub as f64;
            let e_hi = self.events(p, hi);
            let mut first: Option<f64> = None;
            for j in 0..nc {
                let (Some((f_lo, d_lo)), Some((f_hi, d_hi))) = (e_lo[j], e_hi[j]) else {
                    continue;
                };
                let ev = |t: f64| self.events(p, t)[j].unwrap();
                if let Some(t) = first_root(&ev, lo, hi, (f_lo, d_lo), (f_hi, d_hi)) {
                    first = Some(first.map_or(t, |f: f64| f.min(t)));
                }
            }
            if first.is_some() {
                return first;
            }
            lo = hi;
            e_lo = e_hi;
        }
        None
    }
}

/// Value of `v` at deck `i`, 0 at the walls (`i = −1`, `i = N`).
fn side(v: &[f64], i: isize) -> f64 {
    if i < 0 || i as usize >= v.len() {
        0.0
    } else {
        v[i as usize]
    }
}

/// Bisection of `pred` on `[a, b]` (`pred(a)` false, `pred(b)` true) to adjacent floats.
fn bisect(mut a: f64, mut b: f64, pred: impl Fn(f64) -> bool) -> (f64, f64) {
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        if pred(m) {
            b = m;
        } else {
            a = m;
        }
    }
    (a, b)
}

/// First point of `[lo, hi]` where `f` turns negative: the part is split at a minimum of `f`
/// (rate from − to +, bisected) so a dip between the ends is not missed; the crossing is bisected.
fn first_root(
    f: &dyn Fn(f64) -> (f64, f64),
    lo: f64,
    hi: f64,
    (f_lo, d_lo): (f64, f64),
    (f_hi, d_hi): (f64, f64),
) -> Option<f64> {
    let mut pts = vec![(lo, f_lo)];
    if d_lo < 0.0 && d_hi > 0.0 {
        let (a, b) = bisect(lo, hi, |t| f(t).1 > 0.0);
        let m = 0.5 * (a + b);
        pts.push((m, f(m).0));
    }
    pts.push((hi, f_hi));
    for w in pts.windows(2) {
        let ((a, _), (b, fb)) = (w[0], w[1]);
        if fb < 0.0 {
            // f(a) ≥ 0 except (to rounding) at the start of a piece: then the crossing is the
            // first point where f < 0 after a.
            let (_, t) = bisect(a, b, |t| f(t).0 < 0.0);
            return Some(t);
        }
    }
    None
}

/// The event-exact solution: closed-form pieces and the events between them.
pub struct ChainSolution {
    chain: Chain,
    pieces: Vec<Piece>,
    /// Every event with an impact, in time order.
    pub impacts: Vec<ChainImpact>,
    /// Counted impacts per contact `[start, joint 1, …, joint N−1, end]`.
    pub impact_counts: Vec<usize>,
    /// Contacts that became sustained (open → closed).
    pub joins: usize,
    /// Sustained contacts that reopened (tensile force).
    pub releases: usize,
    /// Events whose contact LCP had no feasible set within tolerance (should be 0).
    pub unresolved: usize,
    impact_loss: f64,
    initial: f64,
    /// End of the solution \[s\].
    pub t_end: f64,
}

/// Largest length of a piece of forcing \[s\] (longer record intervals are cut).
const H_MAX: f64 = 0.01;

/// The pieces `(t0, t1, a0, a1)` of `a_g = scale · record` on `[0, t_end]`: linear between
/// samples, zero before the first and after the last sample, no piece longer than [`H_MAX`].
fn forcing_pieces(rec: Option<&Record>, scale: f64, t_end: f64) -> Vec<(f64, f64, f64, f64)> {
    let mut brk = vec![0.0];
    if let Some(r) = rec {
        brk.extend(r.times().iter().copied().filter(|&t| t > 0.0 && t < t_end));
    }
    brk.push(t_end);
    let mut out = Vec::new();
    for w in brk.windows(2) {
        let (p, q) = (w[0], w[1]);
        let (a0, a1) = match rec {
            Some(r) => {
                let (ts, vs) = (r.times(), r.values());
                let last = ts.len() - 1;
                if p < ts[0] || p >= ts[last] {
                    (0.0, 0.0)
                } else {
                    let i = ts.partition_point(|&t| t <= p) - 1;
                    let s = (vs[i + 1] - vs[i]) / (ts[i + 1] - ts[i]);
                    (scale * (vs[i] + s * (p - ts[i])), scale * s)
                }
            }
            None => (0.0, 0.0),
        };
        let parts = ((q - p) / H_MAX).ceil().max(1.0) as usize;
        for k in 0..parts {
            let t0 = p + (q - p) * k as f64 / parts as f64;
            let t1 = if k + 1 == parts {
                q
            } else {
                p + (q - p) * (k + 1) as f64 / parts as f64
            };
            out.push((t0, t1, a0 + a1 * (t0 - p), a1));
        }
    }
    out
}

impl Chain {
    /// The event-exact motion from `(x0, v0)` at `t = 0` under `a_g = scale · rec` (none: free
    /// vibration) on `[0, t_end]`. Contacts touching at `t = 0` are resolved first.
    pub fn solve(
        &self,
        rec: Option<&Record>,
        scale: f64,
        x0: &[f64],
        v0: &[f64],
        t_end: f64,
    ) -> ChainSolution {
        let n = self.n();
        assert!(x0.len() == n && v0.len() == n && self.eps.len() == n + 1);
        for j in 0..=n {
            assert!(
                self.gap(j, x0) >= -GAP_TOUCH,
                "contact {j} penetrates at t = 0"
            );
        }
        let mut sol = ChainSolution {
            chain: self.clone(),
            pieces: Vec::new(),
            impacts: Vec::new(),
            impact_counts: vec![0; n + 1],
            joins: 0,
            releases: 0,
            unresolved: 0,
            impact_loss: 0.0,
            initial: self.kinetic(v0) + self.strain(x0),
            t_end,
        };
        let forcing = forcing_pieces(rec, scale, t_end);
        let (_, _, a00, a01) = forcing[0];
        let closed0 = vec![false; n + 1];
        let mut snap = self.resolve(0.0, x0.to_vec(), v0.to_vec(), &closed0, a00, a01, &mut sol);
        for &(ta, tb, a0, a1) in &forcing {
            let mut t0 = ta;
            let mut count = 0;
            loop {
                let ag0 = a0 + a1 * (t0 - ta);
                let p = self.piece(t0, tb, ag0, a1, &snap);
                let Some(tau) = self.next_event(&p) else {
                    let k = self.kin(&p, tb - t0);
                    snap = Snap {
                        x: k.x,
                        v: k.v,
                        closed: p.closed.clone(),
                    };
                    sol.pieces.push(p);
                    break;
                };
                count += 1;
                assert!(
                    count < MAX_EVENTS_PER_INTERVAL,
                    "Zeno guard: {count} events in [{ta}, {tb}]"
                );
                let te = if t0 + tau >= tb { tb } else { t0 + tau };
                let k = self.kin(&p, tau);
                let closed = p.closed.clone();
                sol.pieces.push(Piece { t1: te, ..p });
                let ag = a0 + a1 * (te - ta);
                snap = self.resolve(te, k.x, k.v, &closed, ag, a1, &mut sol);
                t0 = te;
                if t0 >= tb {
                    break;
                }
            }
        }
        sol
    }

    /// Delassus matrix entry `∂γ_r/∂P_c` of contacts `r`, `c` (impulse `P_j` pushes deck `j`
    /// along +x and deck `j − 1` along −x).
    fn delassus(&self, r: usize, c: usize) -> f64 {
        let n = self.n();
        let inv = |i: usize| 1.0 / self.m[i];
        if r == c {
            (if r >= 1 { inv(r - 1) } else { 0.0 }) + (if r < n { inv(r) } else { 0.0 })
        } else if c == r + 1 {
            -inv(r) // deck r is the right of contact r and the left of contact r + 1
        } else if r == c + 1 {
            -inv(c)
        } else {
            0.0
        }
    }

    /// The simultaneous Newton impact of the contacts `touch` on velocities `v` (in place);
    /// records the event and counts impacts.
    fn impact(&self, t: f64, touch: &[usize], v: &mut [f64], sol: &mut ChainSolution) {
        let n = self.n();
        let gpre: Vec<f64> = touch.iter().map(|&j| self.gamma(j, v)).collect();
        if !gpre.iter().any(|&g| g < 0.0) {
            return;
        }
        let w: Vec<Vec<f64>> = touch
            .iter()
            .map(|&r| touch.iter().map(|&c| self.delassus(r, c)).collect())
            .collect();
        let q: Vec<f64> = touch
            .iter()
            .zip(&gpre)
            .map(|(&j, &g)| {
                let e = if -g < V_CUT { 0.0 } else { self.eps[j] };
                g + e * g.min(0.0)
            })
            .collect();
        let p = impact_lcp(&w, &q);
        let v_pre = v.to_vec();
        for (&j, &pj) in touch.iter().zip(&p) {
            if j >= 1 {
                v[j - 1] -= pj / self.m[j - 1];
            }
            if j < n {
                v[j] += pj / self.m[j];
            }
        }
        for (r, &j) in touch.iter().enumerate() {
            if gpre[r] <= -V_COUNT && p[r] > 0.0 {
                sol.impact_counts[j] += 1;
            }
        }
        sol.impacts.push(ChainImpact {
            t,
            contacts: touch.to_vec(),
            gamma_pre: gpre,
            gamma_post: touch.iter().map(|&j| self.gamma(j, v)).collect(),
            impulse: p,
            v_pre,
            v_post: v.to_vec(),
        });
    }

    /// Resolves an event at `t`: impact of the touching contacts, then the contact LCP at
    /// acceleration level over those at zero relative speed. Returns the new snapshot (joined
    /// decks at their common velocity).
    #[allow(clippy::too_many_arguments)]
    fn resolve(
        &self,
        t: f64,
        x: Vec<f64>,
        mut v: Vec<f64>,
        closed: &[bool],
        a0: f64,
        a1: f64,
        sol: &mut ChainSolution,
    ) -> Snap {
        let n = self.n();
        let touch: Vec<usize> = (0..=n)
            .filter(|&j| closed[j] || self.gap(j, &x) <= GAP_TOUCH)
            .collect();
        let ke_pre = self.kinetic(&v);
        self.impact(t, &touch, &mut v, sol);
        let cand: Vec<usize> = touch
            .iter()
            .copied()
            .filter(|&j| self.gamma(j, &v).abs() <= V_ZERO)
            .collect();
        let nc = cand.len();
        assert!(nc <= 16, "too many sustained-contact candidates");
        let mut masks: Vec<u32> = (0..1u32 << nc).collect();
        masks.sort_by_key(|m| std::cmp::Reverse(m.count_ones()));
        let mut best: Option<(f64, Snap)> = None;
        for mask in masks {
            let mut cl = vec![false; n + 1];
            for (b, &j) in cand.iter().enumerate() {
                cl[j] = mask & (1 << b) != 0;
            }
            if n >= 1 && (0..=n).all(|j| cl[j]) {
                continue; // held by both abutments: degenerate
            }
            let s = Snap {
                x: x.clone(),
                v: v.clone(),
                closed: cl,
            };
            let p = self.piece(t, t, a0, a1, &s);
            let k = self.kin(&p, 0.0);
            let (lam, _) = self.forces(&p, &k);
            let mut viol = 0.0f64;
            for &j in &cand {
                if p.closed[j] {
                    viol = viol.max(-lam[j] / self.m.iter().sum::<f64>());
                } else {
                    let acc = side(&k.a, j as isize) - side(&k.a, j as isize - 1);
                    viol = viol.max(-acc - ACC_TOL);
                }
            }
            let snap = Snap {
                x: k.x,
                v: k.v,
                closed: p.closed,
            };
            if viol <= 0.0 {
                best = Some((0.0, snap));
                break;
            }
            if best.as_ref().is_none_or(|(b, _)| viol < *b) {
                best = Some((viol, snap));
            }
        }
        let (viol, snap) = best.expect("at least the all-open set");
        if viol > 0.0 {
            sol.unresolved += 1;
        }
        for j in 0..=n {
            if snap.closed[j] && !closed[j] {
                sol.joins += 1;
            }
            if !snap.closed[j] && closed[j] {
                sol.releases += 1;
            }
        }
        sol.impact_loss += ke_pre - self.kinetic(&snap.v);
        snap
    }
}

/// 5-point Gauss–Legendre nodes and weights on `[−1, 1]`.
const GL5: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

impl ChainSolution {
    /// The chain solved.
    pub fn chain(&self) -> &Chain {
        &self.chain
    }

    fn piece_at(&self, t: f64) -> &Piece {
        let i = self.pieces.partition_point(|p| p.t1 < t);
        &self.pieces[i.min(self.pieces.len() - 1)]
    }

    /// Positions and velocities of the decks at `t ∈ [0, t_end]` \[m, m/s\].
    pub fn at(&self, t: f64) -> (Vec<f64>, Vec<f64>) {
        let p = self.piece_at(t);
        let k = self.chain.kin(p, t - p.t0);
        (k.x, k.v)
    }

    /// Positions of the decks at each of `times` (time histories) \[m\].
    pub fn sample(&self, times: &[f64]) -> Vec<Vec<f64>> {
        times.iter().map(|&t| self.at(t).0).collect()
    }

    /// Contact forces `λ_j` of the closed contacts at `t` (0 for open ones) \[N\].
    pub fn contact_forces(&self, t: f64) -> Vec<f64> {
        let p = self.piece_at(t);
        let k = self.chain.kin(p, t - p.t0);
        self.chain.forces(p, &k).0
    }

    /// Number of closed-form pieces.
    pub fn piece_count(&self) -> usize {
        self.pieces.len()
    }

    /// Peak quantities, extrema located exactly: each piece is cut into [`Chain::sub`] parts and an
    /// interior extremum (rate sign change) is bisected on the rate.
    pub fn summary(&self) -> ChainSummary {
        let c = &self.chain;
        let n = c.n();
        // quantities: x_i (i < n), opening_j = x_j − x_{j−1} (j = 1..n−1)
        let nq = n + n.saturating_sub(1);
        let q = |p: &Piece, tau: f64| -> Vec<(f64, f64)> {
            let k = c.kin(p, tau);
            let mut out: Vec<(f64, f64)> = (0..n).map(|i| (k.x[i], k.v[i])).collect();
            out.extend((1..n).map(|j| (k.x[j] - k.x[j - 1], k.v[j] - k.v[j - 1])));
            out
        };
        let mut hi = vec![f64::NEG_INFINITY; nq];
        let mut lo = vec![f64::INFINITY; nq];
        let mut note = |i: usize, v: f64| {
            hi[i] = hi[i].max(v);
            lo[i] = lo[i].min(v);
        };
        for p in &self.pieces {
            let len = p.t1 - p.t0;
            let mut prev = q(p, 0.0);
            for (i, &(v, _)) in prev.iter().enumerate() {
                note(i, v);
            }
            if len <= 0.0 {
                continue;
            }
            for s in 1..=c.sub {
                let (a, b) = (
                    len * (s - 1) as f64 / c.sub as f64,
                    len * s as f64 / c.sub as f64,
                );
                let cur = q(p, b);
                for i in 0..nq {
                    note(i, cur[i].0);
                    let (da, db) = (prev[i].1, cur[i].1);
                    if (da > 0.0) != (db > 0.0) && da != 0.0 && db != 0.0 {
                        let (l, r) = bisect(a, b, |t| (q(p, t)[i].1 > 0.0) == (db > 0.0));
                        note(i, q(p, 0.5 * (l + r))[i].0);
                    }
                }
                prev = cur;
            }
        }
        let (x_end, _) = self.at(self.t_end);
        ChainSummary {
            impacts: self.impact_counts.clone(),
            peak_closing: (n..nq).map(|i| -lo[i]).collect(),
            peak_opening: (n..nq).map(|i| hi[i]).collect(),
            peak_displacement: (0..n).map(|i| hi[i].max(-lo[i])).collect(),
            final_displacement: x_end.iter().map(|x| x.abs()).collect(),
        }
    }

    /// The energy terms at `t_end` (integrals by 5-point Gauss–Legendre on each piece, cut
    /// into parts of at most 2.5 ms).
    pub fn energy(&self) -> ChainEnergy {
        let c = &self.chain;
        let (mut input, mut dashpot) = (0.0, 0.0);
        for p in &self.pieces {
            let len = p.t1 - p.t0;
            if len <= 0.0 {
                continue;
            }
            let parts = (len / 2.5e-3).ceil() as usize;
            let h = len / parts as f64;
            for s in 0..parts {
                for &(xi, w) in &GL5 {
                    let tau = h * (s as f64 + 0.5 * (1.0 + xi));
                    let k = c.kin(p, tau);
                    for i in 0..c.n() {
                        input += 0.5 * h * w * (-c.m[i] * k.ag * k.v[i]);
                        dashpot += 0.5 * h * w * c.c[i] * k.v[i] * k.v[i];
                    }
                }
            }
        }
        let (x, v) = self.at(self.t_end);
        ChainEnergy {
            initial: self.initial,
            input,
            kinetic: c.kinetic(&v),
            strain: c.strain(&x),
            dashpot,
            impact_loss: self.impact_loss,
        }
    }
}

/// Issue 11's `examples/viaduct-rigid-1d.toml` as a chain: masses 1.0e6, 1.2e6, 0.8e6 kg from the
/// start; `k = m (2π/T)²` with T = 1.2, 0.5, 1.5 s; `c = 2 · 0.05 · m · 2π/T`; joint gaps 0.02 m,
/// abutment gaps 0.04 m; ε = 0.6 everywhere; with El Centro 1940 NS (ELC180, unscaled) as `a_g`
/// along +x (toward the end abutment).
pub fn viaduct_rigid_1d() -> (Chain, Record) {
    use std::f64::consts::PI;
    let m = vec![1.0e6, 1.2e6, 0.8e6];
    let t = [1.2, 0.5, 1.5];
    let w: Vec<f64> = t.iter().map(|t| 2.0 * PI / t).collect();
    let k = (0..3).map(|i| m[i] * w[i] * w[i]).collect();
    let c = (0..3).map(|i| 2.0 * 0.05 * m[i] * w[i]).collect();
    let chain = Chain::new(m, k, c, vec![0.02, 0.02], Some(0.04), Some(0.04), 0.6);
    let rec = pounding::ground_motion::el_centro_1940()
        .along_y
        .expect("ELC180 is built in");
    (chain, rec)
}
