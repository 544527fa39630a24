//! The 1-D acceptance check of issue 6: two straight decks on one axis, excitation along the axis,
//! μ = 0, so only central double-corner impacts occur. The Moreau–Jean simulator must converge as
//! dt → 0 to an **event-exact reference** written here:
//!
//! * between events each deck is a damped SDOF `ÿ + 2ζω ẏ + ω² y = −a(t)` with `a` piecewise
//!   linear (the record's linear interpolation), integrated in closed form ([`flight`]);
//! * impact times are roots of the gap `g + y1 − y2`, bracketed on a fine subdivision of each
//!   record interval (splitting at extrema of the gap, so grazes are not missed) and refined by
//!   bisection to the rounding level;
//! * Newton's law at each impact: momentum conserved, `γ⁺ = −ε γ⁻` (`γ = ẏ1 − ẏ2`);
//! * accumulations: an impact with approach speed below `V_CUT` is made plastic (`γ⁺ = 0`); if
//!   the contact force of the joined decks is then compressive they move as one body
//!   (`(m1+m2) ÿ1 + (c1+c2) ẏ1 + (k1+k2) y1 = −(m1+m2) a − k2 g`, again closed form) until the
//!   force `λ = m1 (ÿ1 + a) + c1 ẏ1 + k1 y1` vanishes (root-found like the gap).
#![allow(clippy::needless_range_loop)]

use pounding::ground_motion::Record;

/// Approach speeds below this are treated as the end of an accumulation \[m/s\].
const V_CUT: f64 = 1e-5;
/// Subintervals per record interval for bracketing roots.
const SUB: usize = 16;

/// A damped oscillator `ÿ + 2ζω ẏ + ω² y = f0 + f1 τ`.
#[derive(Clone, Copy, Debug)]
struct Sdof {
    w: f64,
    z: f64,
}

/// Closed-form state `(y, ẏ)` at `τ` from `(y0, v0)` at `τ = 0` under the linear forcing
/// `f0 + f1 τ` (underdamped, `ζ < 1`): particular solution `A + B τ` with `B = f1/ω²`,
/// `A = (f0 − 2ζω B)/ω²`, plus the free damped vibration of the remainder.
fn flight(s: Sdof, y0: f64, v0: f64, f0: f64, f1: f64, tau: f64) -> (f64, f64) {
    let w2 = s.w * s.w;
    let b = f1 / w2;
    let a = (f0 - 2.0 * s.z * s.w * b) / w2;
    let (yh, vh) = (y0 - a, v0 - b);
    let wd = s.w * (1.0 - s.z * s.z).sqrt();
    let zw = s.z * s.w;
    let e = (-zw * tau).exp();
    let (sn, cs) = (wd * tau).sin_cos();
    let y = e * (yh * cs + (vh + zw * yh) / wd * sn);
    let v = e * (vh * cs - (w2 * yh + zw * vh) / wd * sn);
    (a + b * tau + y, b + v)
}

/// The two-deck system of the check.
#[derive(Clone, Copy, Debug)]
pub struct TwoDecks {
    pub m: [f64; 2],
    pub omega: [f64; 2],
    pub zeta: f64,
    pub gap: f64,
    pub eps: f64,
}

#[derive(Clone, Copy, Debug)]
enum Mode {
    /// `[y1, v1, y2, v2]` at the piece start.
    Free([f64; 4]),
    /// `[y1, v1]` at the piece start (y2 = y1 + g, v2 = v1).
    Stuck([f64; 2]),
}

#[derive(Clone, Copy, Debug)]
struct Piece {
    t0: f64,
    t1: f64,
    /// Ground acceleration `a(t) = a0 + a1 (t − t0)` on the piece.
    a0: f64,
    a1: f64,
    mode: Mode,
}

/// One impact of the reference.
#[derive(Clone, Copy, Debug)]
pub struct RefImpact {
    pub t: f64,
    pub gamma_pre: f64,
    pub gamma_post: f64,
    pub v_pre: [f64; 2],
    pub v_post: [f64; 2],
}

/// The event-exact solution: pieces of closed-form motion.
pub struct Reference {
    sys: TwoDecks,
    pieces: Vec<Piece>,
    pub impacts: Vec<RefImpact>,
    pub stick_phases: usize,
}

impl TwoDecks {
    fn sdof(&self, j: usize) -> Sdof {
        Sdof {
            w: self.omega[j],
            z: self.zeta,
        }
    }
    fn c(&self, j: usize) -> f64 {
        2.0 * self.zeta * self.omega[j] * self.m[j]
    }
    fn k(&self, j: usize) -> f64 {
        self.m[j] * self.omega[j] * self.omega[j]
    }
    /// The joined decks as one oscillator in `y1` and the constant part of its forcing.
    fn stuck(&self) -> (Sdof, f64) {
        let mt = self.m[0] + self.m[1];
        let w = ((self.k(0) + self.k(1)) / mt).sqrt();
        let z = (self.c(0) + self.c(1)) / mt / (2.0 * w);
        (Sdof { w, z }, -self.k(1) * self.gap / mt)
    }

    /// State of a piece after `tau`: `[y1, v1, y2, v2]`.
    fn state(&self, p: &Piece, tau: f64) -> [f64; 4] {
        match p.mode {
            Mode::Free(s) => {
                let (y1, v1) = flight(self.sdof(0), s[0], s[1], -p.a0, -p.a1, tau);
                let (y2, v2) = flight(self.sdof(1), s[2], s[3], -p.a0, -p.a1, tau);
                [y1, v1, y2, v2]
            }
            Mode::Stuck(s) => {
                let (sd, c) = self.stuck();
                let (y1, v1) = flight(sd, s[0], s[1], -p.a0 + c, -p.a1, tau);
                [y1, v1, y1 + self.gap, v1]
            }
        }
    }

    /// Contact force on deck 1 (+y) of the joined decks in state `x` at ground acceleration `a`.
    fn lambda(&self, x: &[f64; 4], a: f64) -> f64 {
        let (sd, c) = self.stuck();
        let acc = -a + c - 2.0 * sd.z * sd.w * x[1] - sd.w * sd.w * x[0];
        self.m[0] * (acc + a) + self.c(0) * x[1] + self.k(0) * x[0]
    }

    fn gap_of(&self, x: &[f64; 4]) -> f64 {
        self.gap + x[0] - x[2]
    }

    /// Builds the reference for the ground acceleration `scale · record` (zero after the last
    /// sample) on `[0, t_end]`, from rest.
    pub fn solve(&self, rec: &Record, scale: f64, t_end: f64) -> Reference {
        let ts = rec.times();
        let vs = rec.values();
        // breakpoints of the piecewise-linear forcing
        let mut knots: Vec<(f64, f64)> = ts
            .iter()
            .zip(vs)
            .filter(|(t, _)| **t <= t_end)
            .map(|(t, v)| (*t, v * scale))
            .collect();
        assert_eq!(knots[0].0, 0.0, "record must start at t = 0");
        if knots.last().unwrap().0 < t_end {
            knots.push((t_end, 0.0)); // (unused slope after the record: a = 0)
        }
        let mut pieces = Vec::new();
        let mut impacts = Vec::new();
        let mut stick_phases = 0;
        let mut mode = Mode::Free([0.0; 4]);
        for i in 0..knots.len() - 1 {
            let (ta, aa) = knots[i];
            let (tb, ab) = knots[i + 1];
            let (a0, a1) = if ts.len() > i + 1 && ts[i + 1] == tb {
                (aa, (ab - aa) / (tb - ta))
            } else {
                (0.0, 0.0)
            };
            let mut t0 = ta;
            loop {
                let p = Piece {
                    t0,
                    t1: tb,
                    a0: a0 + a1 * (t0 - ta),
                    a1,
                    mode,
                };
                match self.next_event(&p) {
                    None => {
                        pieces.push(p);
                        mode = match p.mode {
                            Mode::Free(_) => Mode::Free(self.state(&p, tb - p.t0)),
                            Mode::Stuck(_) => {
                                let x = self.state(&p, tb - p.t0);
                                Mode::Stuck([x[0], x[1]])
                            }
                        };
                        break;
                    }
                    Some(tau) => {
                        let te = t0 + tau;
                        pieces.push(Piece { t1: te, ..p });
                        let x = self.state(&p, tau);
                        let a_now = p.a0 + p.a1 * tau;
                        mode = match p.mode {
                            Mode::Stuck(_) => Mode::Free([x[0], x[1], x[0] + self.gap, x[1]]),
                            Mode::Free(_) => {
                                let g_pre = x[1] - x[3];
                                let (m1, m2) = (self.m[0], self.m[1]);
                                let g_post = if -g_pre < V_CUT {
                                    0.0
                                } else {
                                    -self.eps * g_pre
                                };
                                // P on deck 1 along +y: γ⁺ = γ⁻ + P (1/m1 + 1/m2)
                                let pn = (g_post - g_pre) / (1.0 / m1 + 1.0 / m2);
                                let v1 = x[1] + pn / m1;
                                let v2 = x[3] - pn / m2;
                                impacts.push(RefImpact {
                                    t: te,
                                    gamma_pre: g_pre,
                                    gamma_post: g_post,
                                    v_pre: [x[1], x[3]],
                                    v_post: [v1, v2],
                                });
                                let y2 = x[0] + self.gap; // on contact (root to rounding)
                                let xs = [x[0], v1, y2, v2];
                                if g_post == 0.0 && self.lambda(&xs, a_now) > 0.0 {
                                    stick_phases += 1;
                                    let vm = (m1 * v1 + m2 * v2) / (m1 + m2);
                                    Mode::Stuck([x[0], vm])
                                } else {
                                    Mode::Free(xs)
                                }
                            }
                        };
                        t0 = te;
                        if t0 >= tb {
                            break;
                        }
                    }
                }
            }
        }
        Reference {
            sys: *self,
            pieces,
            impacts,
            stick_phases,
        }
    }

    /// First event time `τ ∈ (0, t1 − t0]` of the piece: the gap closing (free flight) or the
    /// contact force vanishing (stuck), or `None`.
    fn next_event(&self, p: &Piece) -> Option<f64> {
        let len = p.t1 - p.t0;
        if len <= 0.0 {
            return None;
        }
        // event function and its derivative
        let f = |tau: f64| -> (f64, f64) {
            let x = self.state(p, tau);
            match p.mode {
                Mode::Free(_) => (self.gap_of(&x), x[1] - x[3]),
                Mode::Stuck(_) => {
                    let h = 1e-7 * len.max(1e-3);
                    let a = |t: f64| p.a0 + p.a1 * t;
                    let l = self.lambda(&x, a(tau));
                    let xp = self.state(p, tau + h);
                    let xm = self.state(p, (tau - h).max(0.0));
                    let d = (self.lambda(&xp, a(tau + h))
                        - self.lambda(&xm, a((tau - h).max(0.0))))
                        / (tau + h - (tau - h).max(0.0));
                    (l, d)
                }
            }
        };
        let mut lo = 0.0;
        let (mut f_lo, mut d_lo) = f(0.0);
        for j in 1..=SUB {
            let hi = len * j as f64 / SUB as f64;
            let (f_hi, d_hi) = f(hi);
            // candidate sub-brackets: split at an extremum of f (derivative sign change)
            let mut pts = vec![(lo, f_lo)];
            if d_lo < 0.0 && d_hi > 0.0 || d_lo > 0.0 && d_hi < 0.0 {
                let (mut a, mut b) = (lo, hi);
                for _ in 0..200 {
                    let m = 0.5 * (a + b);
                    if m <= a || m >= b {
                        break;
                    }
                    if (f(m).1 > 0.0) == (d_lo > 0.0) {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                let m = 0.5 * (a + b);
                pts.push((m, f(m).0));
            }
            pts.push((hi, f_hi));
            for w in pts.windows(2) {
                let ((a0, fa), (b0, fb)) = (w[0], w[1]);
                // an event: f goes from > 0 to <= 0 (at τ = 0 itself f may be 0 with f' > 0)
                if fb <= 0.0 && (fa > 0.0 || (a0 == 0.0 && fa >= 0.0 && fb < 0.0)) {
                    let (mut a, mut b) = (a0, b0);
                    if fa <= 0.0 {
                        // f(0) = 0 and rising: start the bracket just after 0
                        let mut s = (b - a) * 1e-6;
                        while s < b - a && f(a + s).0 <= 0.0 {
                            s *= 2.0;
                        }
                        if s >= b - a {
                            continue;
                        }
                        a += s;
                    }
                    for _ in 0..200 {
                        let m = 0.5 * (a + b);
                        if m <= a || m >= b {
                            break;
                        }
                        if f(m).0 > 0.0 {
                            a = m;
                        } else {
                            b = m;
                        }
                    }
                    return Some(b);
                }
            }
            lo = hi;
            f_lo = f_hi;
            d_lo = d_hi;
        }
        None
    }
}

impl Reference {
    fn piece_at(&self, t: f64) -> &Piece {
        let i = self.pieces.partition_point(|p| p.t1 < t);
        &self.pieces[i.min(self.pieces.len() - 1)]
    }
    /// `[y1, v1, y2, v2]` at `t`.
    pub fn at(&self, t: f64) -> [f64; 4] {
        let p = self.piece_at(t);
        self.sys.state(p, t - p.t0)
    }
}

// ---------------------------------------------------------------------------------------------
// Checks of the reference itself (independent of the simulator)
// ---------------------------------------------------------------------------------------------

fn system() -> TwoDecks {
    use std::f64::consts::PI;
    TwoDecks {
        m: [1.0e6, 1.0e6],
        omega: [2.0 * PI / 1.0, 2.0 * PI / 0.5],
        zeta: 0.05,
        gap: 0.05,
        eps: 0.6,
    }
}

fn el_centro_ns() -> Record {
    pounding::ground_motion::el_centro_1940().along_y.unwrap()
}

/// RK4 of one SDOF with a tiny step: the closed form agrees.
#[test]
fn closed_form_flight_agrees_with_fine_rk4() {
    let s = Sdof { w: 9.0, z: 0.05 };
    let (f0, f1) = (0.7, -3.0);
    let (y0, v0) = (0.02, -0.3);
    let n = 20_000;
    let t_end = 0.5;
    let h = t_end / n as f64;
    let rhs = |t: f64, y: f64, v: f64| (v, f0 + f1 * t - 2.0 * s.z * s.w * v - s.w * s.w * y);
    let (mut y, mut v) = (y0, v0);
    for i in 0..n {
        let t = i as f64 * h;
        let k1 = rhs(t, y, v);
        let k2 = rhs(t + h / 2.0, y + h / 2.0 * k1.0, v + h / 2.0 * k1.1);
        let k3 = rhs(t + h / 2.0, y + h / 2.0 * k2.0, v + h / 2.0 * k2.1);
        let k4 = rhs(t + h, y + h * k3.0, v + h * k3.1);
        y += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        v += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
    }
    let (yc, vc) = flight(s, y0, v0, f0, f1, t_end);
    assert!((y - yc).abs() < 1e-12, "{y} vs {yc}");
    assert!((v - vc).abs() < 1e-11, "{v} vs {vc}");
}

/// The reference over the whole El Centro record: every impact on contact with Newton's law and
/// momentum conservation; no penetration anywhere on a dense grid; compressive force while stuck.
#[test]
fn reference_is_consistent_over_el_centro() {
    let sys = system();
    let rec = el_centro_ns();
    let t_end = rec.end_time();
    let r = sys.solve(&rec, 1.0, t_end);
    assert!(r.impacts.len() >= 3, "{} impacts", r.impacts.len());
    for imp in &r.impacts {
        let x = r.at(imp.t);
        assert!(
            sys.gap_of(&x).abs() < 1e-12,
            "gap {} at {}",
            sys.gap_of(&x),
            imp.t
        );
        assert!(imp.gamma_pre < 0.0);
        let p0 = sys.m[0] * imp.v_pre[0] + sys.m[1] * imp.v_pre[1];
        let p1 = sys.m[0] * imp.v_post[0] + sys.m[1] * imp.v_post[1];
        assert!((p0 - p1).abs() <= 1e-12 * (sys.m[0] * imp.v_pre[0].abs() + 1.0));
        let g1 = imp.v_post[0] - imp.v_post[1];
        if imp.gamma_post != 0.0 {
            assert!((g1 + sys.eps * imp.gamma_pre).abs() < 1e-12);
        }
    }
    // dense scan: no penetration (the root finder missed no impact)
    let n = (t_end / 1e-4) as usize;
    let mut min_gap = f64::INFINITY;
    for i in 0..=n {
        let x = r.at(i as f64 * 1e-4);
        min_gap = min_gap.min(sys.gap_of(&x));
    }
    assert!(min_gap > -1e-10, "penetration {min_gap}");
    // continuity of displacement across pieces
    for w in r.pieces.windows(2) {
        let a = sys.state(&w[0], w[0].t1 - w[0].t0);
        let b = sys.state(&w[1], 0.0);
        assert!((a[0] - b[0]).abs() < 1e-12 && (a[2] - b[2]).abs() < 1e-12);
    }
    eprintln!(
        "reference: {} impacts, {} stick phases, first at {:.6} s",
        r.impacts.len(),
        r.stick_phases,
        r.impacts[0].t
    );
}

// ---------------------------------------------------------------------------------------------
// The simulator against the reference
// ---------------------------------------------------------------------------------------------

use pounding::ground_motion::GroundMotion;
use pounding::shape::{DeckShape, StraightDeck};
use pounding::sim::{SimModel, SimProblem, SimSettings, SimStatus, simulate};

/// `examples/straight-1d.toml` as a library model: straight decks 40 m × 10 m × 1 m, ρ = 2500
/// (m = 1.0e6 kg), four corner bearings each with `4k = m ω²` (T = 1.0 s deck 1, 0.5 s deck 2),
/// Rayleigh 5 %, gap 0.05 m, μ = 0, ε_N = 0.6.
fn sim_model(sys: &TwoDecks) -> SimModel {
    let deck = DeckShape::Straight(StraightDeck::new(40.0, 10.0, 1.0, 2500.0).unwrap());
    let k = |j: usize| sys.m[j] * sys.omega[j] * sys.omega[j] / 4.0;
    SimModel::with_shapes(
        [deck, deck],
        sys.gap,
        k(0),
        k(1),
        sys.zeta,
        0.0,
        sys.eps,
        10.0,
    )
}

/// Max over the steps of `|y_j,sim − y_j,ref|` (both decks), and the largest `|x|`, `|θ|`.
fn max_error(sys: &TwoDecks, r: &Reference, gm: &GroundMotion, dt: f64, t_end: f64) -> (f64, f64) {
    let p = SimProblem::at_rest(sim_model(sys), gm.clone());
    let st = SimSettings {
        dt,
        duration: Some(t_end),
        ..SimSettings::default()
    };
    let sol = simulate(&p, &st).unwrap();
    assert_eq!(sol.status, SimStatus::Completed);
    let mut err: f64 = 0.0;
    let mut off: f64 = 0.0;
    for (t, q) in sol.t.iter().zip(sol.q_rows()) {
        let x = r.at(*t);
        err = err.max((q[1] - x[0]).abs()).max((q[4] - x[2]).abs());
        off = off
            .max(q[0].abs())
            .max(q[3].abs())
            .max(q[2].abs())
            .max(q[5].abs());
    }
    if r.stick_phases == 0 {
        // no accumulation: every reference impact is one impact of the run (both corners at once)
        assert_eq!(sol.summary.impacts, r.impacts.len());
        assert_eq!(sol.impacts.len(), 2 * r.impacts.len());
    }
    (err, off)
}

/// Least-squares slope of `log e` against `log dt` (the observed order).
fn fitted_order(dts: &[f64], errs: &[f64]) -> f64 {
    let n = dts.len() as f64;
    let x: Vec<f64> = dts.iter().map(|d| d.ln()).collect();
    let y: Vec<f64> = errs.iter().map(|e| e.ln()).collect();
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(&y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

fn convergence(sys: &TwoDecks, gm: &GroundMotion, scale: f64, t_end: f64, dts: &[f64]) -> Vec<f64> {
    let rec = gm.along_y.as_ref().unwrap();
    let r = sys.solve(rec, scale, t_end);
    let mut errs = Vec::new();
    for &dt in dts {
        let (e, off) = max_error(sys, &r, gm, dt, t_end);
        assert!(
            off < 1e-9,
            "dt {dt}: transverse/rotational response {off} (should be 0)"
        );
        errs.push(e);
    }
    let orders: Vec<f64> = errs.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
    eprintln!(
        "{} impacts, {} stick phases; dt {dts:?}: max |y error| {errs:?} m; \
         orders between successive dt {orders:?}; least-squares order {:.3}",
        r.impacts.len(),
        r.stick_phases,
        fitted_order(dts, &errs)
    );
    errs
}

/// Acceptance: El Centro 1940 NS unscaled along the axis; the simulator converges to the
/// event-exact reference at first order (impact times resolved to one step).
#[test]
fn straight_1d_el_centro_converges_to_the_event_exact_reference() {
    let sys = system();
    let gm = GroundMotion {
        along_y: Some(el_centro_ns()),
        ..GroundMotion::none()
    };
    let t_end = gm.end_time();
    let dts = [2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5];
    let errs = convergence(&sys, &gm, 1.0, t_end, &dts);
    // First order with a constant that depends on where each impact falls inside its step
    // (the event time is resolved to one step), so single halvings fluctuate; the fitted order
    // and the reduction over a factor 32 in dt are the robust measures.
    let order = fitted_order(&dts, &errs);
    assert!(order > 0.7, "observed order {order}: {errs:?}");
    assert!(errs[5] < errs[0] / 12.0, "{errs:?}");
    for (e, dt) in errs.iter().zip(dts) {
        assert!(*e < 0.6 * dt, "error {e} > 0.6 m/s × dt at dt = {dt}");
    }
}

/// A ground acceleration that presses the decks together (static closure 0.114 m > gap), then
/// pulls them apart: impacts, an accumulation (cut off in the reference), a stuck phase ended by
/// the contact force vanishing, and separation — the simulator converges here too.
#[test]
fn accumulation_and_sticking_converge_too() {
    let sys = system();
    let rec = Record::new(
        "press-release",
        vec![0.0, 0.1, 3.0, 3.1, 6.0],
        vec![0.0, 6.0, 6.0, -6.0, -6.0],
    )
    .unwrap();
    let r = sys.solve(&rec, 1.0, 6.0);
    assert!(
        r.stick_phases >= 1,
        "the scenario must stick: {}",
        r.stick_phases
    );
    assert!(
        r.impacts.iter().any(|i| i.gamma_post == 0.0),
        "an accumulation ends with the cutoff"
    );
    // the reference itself: no penetration, and the decks do stay joined for a while
    let mut min_gap = f64::INFINITY;
    let mut joined = 0;
    for i in 0..=60_000 {
        let x = r.at(i as f64 * 1e-4);
        let g = sys.gap_of(&x);
        min_gap = min_gap.min(g);
        if g.abs() < 1e-12 && (x[1] - x[3]).abs() < 1e-12 {
            joined += 1;
        }
    }
    assert!(min_gap > -1e-10, "penetration {min_gap}");
    assert!(joined > 1000, "joined at {joined} samples only");
    let gm = GroundMotion {
        along_y: Some(rec),
        ..GroundMotion::none()
    };
    let dts = [2e-3, 1e-3, 5e-4, 2.5e-4];
    let errs = convergence(&sys, &gm, 1.0, 6.0, &dts);
    let order = fitted_order(&dts, &errs);
    assert!(order > 0.7, "observed order {order}: {errs:?}");
    assert!(errs[3] < errs[0] / 5.0, "{errs:?}");
}
