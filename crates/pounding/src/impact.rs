//! Generic frictional multi-contact impact of planar rigid bodies, solved as the LCP of spec §8.
//!
//! # Model
//!
//! Bodies have a mass `m`, a polar moment `I` about the centroid, a centroid position, a centroid
//! velocity `v` and an angular velocity `ω` (counter-clockwise positive). A contact joins body `a`
//! and body `b` (another body or the fixed ground) at a point `C`, with a unit normal `n` pointing
//! **into body a** (from b toward a) and the tangent `t = (−n_y, n_x)` (n turned by +90°).
//! Relative velocities at the contact point, with `r_k = C − x_k` and `ω × r = ω (−r_y, r_x)`:
//! ```text
//! γ_N = (v_a + ω_a × r_a − v_b − ω_b × r_b) · n        (> 0: separating)
//! γ_T = (v_a + ω_a × r_a − v_b − ω_b × r_b) · t
//! ```
//! The impulse `Λ_N n + Λ_T t` acts on body a at `C`, the opposite on body b. With the generalised
//! force directions `w_N`, `w_T` (body a: `(n, r_a × n)`, body b: `−(n, r_b × n)`; likewise with `t`),
//! `γ = Wᵀ u` and `u⁺ = u⁻ + M⁻¹ W Λ`, so `γ⁺ = γ⁻ + G Λ` with `G = Wᵀ M⁻¹ W` (blocks ordered
//! `[N_1..N_n, T_1..T_n]`).
//!
//! # Impact law and LCP (spec §8)
//!
//! Newton's law per contact `ξ_N := γ_N⁺ + ε_N min(γ_N⁻, 0) ≥ 0 ⟂ Λ_N ≥ 0` and Coulomb's law with
//! `ε_T = 0`, split as in spec §8:
//! ```text
//! y = A x + b,  x = (Λ_N, Λ_TR, γ_TL) ≥ 0,  y = (ξ_N, γ_TR, Λ_TL) ≥ 0,  xᵀy = 0
//! A = [ G_NN − G_NT μ   G_NT   0 ]      b = [ γ_N⁻ + ε min(γ_N⁻, 0) ]
//!     [ G_TN − G_TT μ   G_TT   I ]          [ γ_T⁻                  ]
//!     [ 2μ              −I     0 ]          [ 0                     ]
//! ```
//! For an approaching contact (`γ_N⁻ < 0`) the first block of `b` is the spec's `(1 + ε_N) γ_N⁻`.
//! Every listed contact takes part, so a touching contact that is not approaching can still carry
//! impulse; for a separating contact (`γ_N⁻ > 0`) the entry is `γ_N⁻` itself, i.e. the contact must
//! not end up approaching (`γ_N⁺ ≥ 0`), but no restitution is applied to it. (Writing
//! `(1 + ε) min(γ_N⁻, 0)` there instead would force `γ_N⁺ ≥ γ_N⁻`, letting a receding contact push;
//! see the test `separating_contact_does_not_push`.)
//!
//! If no contact approaches (`γ_N⁻ ≥ 0` for all) the result is `Λ = 0` with status
//! [`ImpactStatus::NoImpact`]. Otherwise Lemke's method solves the LCP (fixed-size kernels for one
//! and two contacts); on a secondary ray (or another Lemke failure) the complementary bases are
//! enumerated, and for one contact the analytic solution of spec §9 is the last resort
//! ([`ImpactStatus::SolvedByFallback`]).
//!
//! # Post-solve checks
//!
//! Every solution is checked on the recovered body velocities ([`crate::law_check`]): Newton's
//! law, the Coulomb cone and the sliding direction at every contact, and the kinetic energy
//! `T⁺ − T⁻` against the provable Newton–Coulomb bound `½ Σ_i (c_i Λ_N,i + γ_T,i⁻ Λ_T,i)`. A
//! solution that fails (e.g. a body with a tiny moment of inertia, where the LCP's split variables
//! lose the tangential impulse to rounding) is reported as [`ImpactStatus::IllConditioned`] with
//! the violated law in [`ImpactSolution::law_violation`]; its numbers are not trustworthy.

use crate::analytic::{self, ImpactLaw};
use crate::contact::Delassus;
use crate::law_check::{self, LAW_TOLERANCE, LawViolation};
use crate::lcp::{self, LcpProblem, LcpStatus, LemkeSettings};
use crate::math::{Real, Vector, cross, perp};
use thiserror::Error;

mod split;

/// Bad impact input; the message names the parameter (e.g. `bodies[1].mass`, `contacts[0].normal`).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ImpactError {
    /// A parameter is missing, not finite or out of range.
    #[error("invalid {name}: {reason}")]
    Invalid {
        /// The parameter, as a path into the problem (`bodies[i].field`, `contacts[j].field`).
        name: String,
        /// What is wrong.
        reason: String,
    },
}

fn invalid(name: impl Into<String>, reason: impl Into<String>) -> ImpactError {
    ImpactError::Invalid {
        name: name.into(),
        reason: reason.into(),
    }
}

/// A planar rigid body in its pre-impact state.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBody {
    /// Unique, non-empty name (contacts refer to bodies by name).
    pub name: String,
    /// Mass `m > 0` \[kg\].
    pub mass: Real,
    /// Polar moment of inertia about the centroid `I > 0` \[kg m²\].
    pub inertia: Real,
    /// Centroid position \[m\].
    pub position: Vector,
    /// Centroid velocity \[m/s\].
    pub velocity: Vector,
    /// Angular velocity `ω` \[rad/s\], counter-clockwise positive.
    pub omega: Real,
}

/// A contact as given by the user.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSpec {
    /// Name of body `a` (the body the normal points into).
    pub body_a: String,
    /// Name of body `b`, or `None` for the fixed ground.
    pub body_b: Option<String>,
    /// Contact point \[m\].
    pub point: Vector,
    /// Normal direction pointing into body `a` (any non-zero finite vector; normalised internally
    /// without overflow or underflow).
    pub normal: Vector,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub mu: Real,
    /// Newton restitution coefficient `ε_N ∈ [0, 1]`.
    pub restitution: Real,
}

/// A validated contact (body indices resolved, unit normal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Index of body `a`.
    pub a: usize,
    /// Index of body `b`, `None` = ground.
    pub b: Option<usize>,
    /// Contact point \[m\].
    pub point: Vector,
    /// Unit normal `n`, pointing into body `a`.
    pub normal: Vector,
    /// Unit tangent `t = (−n_y, n_x)`.
    pub tangent: Vector,
    /// Friction and restitution.
    pub law: ImpactLaw,
}

/// Largest number of bodies of an [`ImpactProblem`].
pub const MAX_BODIES: usize = 1024;

/// Largest number of contacts of an [`ImpactProblem`] (a 768-row LCP, well under a second).
pub const MAX_CONTACTS: usize = 256;

/// A validated impact problem.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactProblem {
    bodies: Vec<RigidBody>,
    contacts: Vec<Contact>,
}

use crate::output::float_token as ft;

fn finite_vec(name: String, v: &Vector) -> Result<(), ImpactError> {
    if v.x.is_finite() && v.y.is_finite() {
        Ok(())
    } else {
        Err(invalid(
            name,
            format!("[{}, {}] is not finite", ft(v.x), ft(v.y)),
        ))
    }
}

impl ImpactProblem {
    /// Validates bodies and contacts: unique non-empty names; finite `m > 0`, `I > 0`, positions,
    /// velocities and ω; contacts naming existing, distinct bodies; finite points; non-zero finite
    /// normals; `μ ≥ 0`; `ε_N ∈ [0, 1]`.
    ///
    /// At most [`MAX_BODIES`] bodies and [`MAX_CONTACTS`] contacts: the dense impact LCP has
    /// `3n` rows, and Lemke's work grows like `(3n)³`.
    pub fn new(bodies: Vec<RigidBody>, contacts: Vec<ContactSpec>) -> Result<Self, ImpactError> {
        if bodies.len() > MAX_BODIES {
            return Err(invalid(
                "bodies",
                format!("{} bodies: at most {MAX_BODIES} are accepted", bodies.len()),
            ));
        }
        if contacts.len() > MAX_CONTACTS {
            return Err(invalid(
                "contacts",
                format!(
                    "{} contacts: at most {MAX_CONTACTS} are accepted (the impact LCP has 3 rows per contact)",
                    contacts.len()
                ),
            ));
        }
        for (i, b) in bodies.iter().enumerate() {
            let p = |f: &str| format!("bodies[{i}].{f}");
            if b.name.trim().is_empty() {
                return Err(invalid(p("name"), "must be a non-empty string"));
            }
            if bodies[..i].iter().any(|o| o.name == b.name) {
                return Err(invalid(
                    p("name"),
                    format!("duplicate body name {:?}", b.name),
                ));
            }
            if !(b.mass.is_finite() && b.mass > 0.0) {
                return Err(invalid(
                    p("mass"),
                    format!("{} must be finite and > 0", ft(b.mass)),
                ));
            }
            if !(b.inertia.is_finite() && b.inertia > 0.0) {
                return Err(invalid(
                    p("inertia"),
                    format!("{} must be finite and > 0", ft(b.inertia)),
                ));
            }
            finite_vec(p("position"), &b.position)?;
            finite_vec(p("velocity"), &b.velocity)?;
            if !b.omega.is_finite() {
                return Err(invalid(
                    p("omega"),
                    format!("{} is not finite", ft(b.omega)),
                ));
            }
        }
        let find = |name: &str| bodies.iter().position(|b| b.name == name);
        let mut out = Vec::with_capacity(contacts.len());
        for (j, c) in contacts.iter().enumerate() {
            let p = |f: &str| format!("contacts[{j}].{f}");
            let a = find(&c.body_a)
                .ok_or_else(|| invalid(p("body_a"), format!("unknown body {:?}", c.body_a)))?;
            let b = match &c.body_b {
                None => None,
                Some(n) => {
                    let b = find(n)
                        .ok_or_else(|| invalid(p("body_b"), format!("unknown body {n:?}")))?;
                    if b == a {
                        return Err(invalid(p("body_b"), "must differ from body_a"));
                    }
                    Some(b)
                }
            };
            finite_vec(p("point"), &c.point)?;
            finite_vec(p("normal"), &c.normal)?;
            // A direction: scale by its largest component first, so that neither a huge normal
            // (|n|² overflows) nor a tiny one (|n|² underflows) loses it.
            let big = c.normal.x.abs().max(c.normal.y.abs());
            if big.is_nan() || big <= 0.0 {
                return Err(invalid(p("normal"), "must be a non-zero vector"));
            }
            let scaled = c.normal / big;
            let law = ImpactLaw::new(c.mu, c.restitution).map_err(|e| match e {
                analytic::LawError::Friction(v) => {
                    invalid(p("mu"), format!("{} must be finite and >= 0", ft(v)))
                }
                analytic::LawError::Restitution(v) => {
                    invalid(p("restitution"), format!("{} must lie in [0, 1]", ft(v)))
                }
            })?;
            let normal = scaled / scaled.norm();
            out.push(Contact {
                a,
                b,
                point: c.point,
                normal,
                tangent: perp(&normal),
                law,
            });
        }
        Ok(Self {
            bodies,
            contacts: out,
        })
    }
    /// The bodies (pre-impact state).
    pub fn bodies(&self) -> &[RigidBody] {
        &self.bodies
    }
    /// The validated contacts.
    pub fn contacts(&self) -> &[Contact] {
        &self.contacts
    }
}

/// When the complementary bases are enumerated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EnumeratePolicy {
    /// Only when Lemke fails.
    OnFailure,
    /// When Lemke fails or `G` is singular (impulses possibly non-unique, e.g. a line contact);
    /// needs `3n ≤ 12`.
    #[default]
    Auto,
    /// Always (for `3n ≤ 12`): `solutions` then counts every distinct solution.
    Always,
}

/// Settings of [`solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactSettings {
    /// Lemke's settings.
    pub lemke: LemkeSettings,
    /// When to enumerate.
    pub enumerate: EnumeratePolicy,
    /// Stick classification: `|γ_T⁺| ≤ stick_tolerance · s` with `s = max_i |min(γ_N,i⁻, 0)|`
    /// (spec §10 uses 1e-9).
    pub stick_tolerance: Real,
}

impl Default for ImpactSettings {
    fn default() -> Self {
        Self {
            lemke: LemkeSettings::default(),
            enumerate: EnumeratePolicy::default(),
            stick_tolerance: analytic::STICK_TOLERANCE,
        }
    }
}

/// Outcome of an impact computation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ImpactStatus {
    /// Lemke's method solved the LCP.
    Solved,
    /// Lemke failed (e.g. a secondary ray); enumeration or the analytic formulas found the solution.
    SolvedByFallback,
    /// No contact approaches: zero impulses, velocities unchanged.
    NoImpact,
    /// No solution was found (numbers are NaN).
    Failed,
    /// A solution of the LCP was found, but the recovered post-impact velocities violate the
    /// impact laws or create energy beyond the Newton–Coulomb bound ([`crate::law_check`]): the
    /// problem is too ill-conditioned for the LCP formulation in double precision (e.g. a moment
    /// of inertia many orders of magnitude below `m r²`). The numbers are reported but not
    /// trustworthy.
    IllConditioned,
}

impl ImpactStatus {
    /// Output name: `solved`, `solved-by-fallback`, `no-impact`, `failed`, `ill-conditioned`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Solved => "solved",
            Self::SolvedByFallback => "solved-by-fallback",
            Self::NoImpact => "no-impact",
            Self::Failed => "failed",
            Self::IllConditioned => "ill-conditioned",
        }
    }
    /// `false` for [`ImpactStatus::Failed`] and [`ImpactStatus::IllConditioned`] (a run reporting
    /// such an impact must not exit successfully).
    pub fn is_trustworthy(self) -> bool {
        !matches!(self, Self::Failed | Self::IllConditioned)
    }
}

/// Post-impact state of one contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactMode {
    /// No normal impulse.
    Open,
    /// `Λ_N > 0`, `γ_T⁺ = 0` (within the stick tolerance).
    Stick,
    /// `Λ_N > 0`, `γ_T⁺ > 0` (body a slides along `+t` relative to b).
    SlipPositive,
    /// `Λ_N > 0`, `γ_T⁺ < 0`.
    SlipNegative,
}

impl ContactMode {
    /// Output name: `open`, `stick`, `slip-positive`, `slip-negative`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Open => "open",
            Self::Stick => "stick",
            Self::SlipPositive => "slip-positive",
            Self::SlipNegative => "slip-negative",
        }
    }
}

/// Result at one contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactResult {
    /// `Λ_N ≥ 0` \[N s\] along `n` on body a.
    pub normal_impulse: Real,
    /// `Λ_T` \[N s\] along `t` on body a (`|Λ_T| ≤ μ Λ_N`).
    pub tangential_impulse: Real,
    /// Mode.
    pub mode: ContactMode,
    /// `γ_N⁻` \[m/s\] (positive = separating).
    pub gamma_n_pre: Real,
    /// `γ_T⁻` \[m/s\].
    pub gamma_t_pre: Real,
    /// `γ_N⁺` \[m/s\].
    pub gamma_n_post: Real,
    /// `γ_T⁺` \[m/s\].
    pub gamma_t_post: Real,
}

/// Post-impact velocity of one body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyVelocity {
    /// Centroid velocity \[m/s\].
    pub velocity: Vector,
    /// Angular velocity \[rad/s\].
    pub omega: Real,
}

/// Result of [`solve`].
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactSolution {
    /// Outcome.
    pub status: ImpactStatus,
    /// Lemke's own status (`Solved` also for the no-impact shortcut).
    pub lemke_status: LcpStatus,
    /// Per contact, in input order.
    pub contacts: Vec<ContactResult>,
    /// Per body, in input order (post-impact).
    pub bodies: Vec<BodyVelocity>,
    /// Kinetic energy before `T⁻ = Σ ½ m |v|² + ½ I ω²` \[J\].
    pub energy_before: Real,
    /// Kinetic energy after \[J\].
    pub energy_after: Real,
    /// Number of distinct solutions in `(Λ_N, Λ_T)` (hence `γ⁺`) among Lemke's and the enumerated
    /// ones (tolerance 1e-9 of the largest impulse); `1` when enumeration did not run, `0` when no
    /// method found a solution. A continuum of solutions is represented by its vertices.
    pub solutions: usize,
    /// Whether enumeration ran.
    pub enumerated: bool,
    /// All enumerated solutions give the same post-impact velocities (`true` when enumeration did
    /// not run). With `solutions > 1` and this `true`, only the split of the impulses is non-unique.
    pub post_velocity_unique: bool,
    /// The law the recovered velocities violate when `status` is
    /// [`ImpactStatus::IllConditioned`], else `None`.
    pub law_violation: Option<LawViolation>,
    /// Whether the tangential impulses of the sticking contacts are the only ones that give these
    /// normal impulses and post-impact velocities within Coulomb's law. When not (e.g. two
    /// symmetric contacts sharing one tangential direction), `contacts` reports the split of
    /// smallest Euclidean norm (the equal split for two symmetric contacts), not the arbitrary
    /// extreme the LCP solver returns. `true` when there is no solution.
    pub tangential_split_unique: bool,
}

/// Internal dense representation: `W` (3B × 2n, column-major by contact column), `M⁻¹` diag, `u⁻`.
struct Assembled {
    nb: usize,
    nc: usize,
    /// columns: `w[k]` for k in 0..2n (N columns then T columns), each of length 3B.
    w: Vec<Vec<Real>>,
    minv: Vec<Real>,
    u: Vec<Real>,
}

fn assemble(p: &ImpactProblem) -> Assembled {
    let nb = p.bodies.len();
    let nc = p.contacts.len();
    let mut minv = vec![0.0; 3 * nb];
    let mut u = vec![0.0; 3 * nb];
    for (i, b) in p.bodies.iter().enumerate() {
        minv[3 * i] = 1.0 / b.mass;
        minv[3 * i + 1] = 1.0 / b.mass;
        minv[3 * i + 2] = 1.0 / b.inertia;
        u[3 * i] = b.velocity.x;
        u[3 * i + 1] = b.velocity.y;
        u[3 * i + 2] = b.omega;
    }
    let mut w = vec![vec![0.0; 3 * nb]; 2 * nc];
    for (j, c) in p.contacts.iter().enumerate() {
        for (col, dir) in [(j, c.normal), (nc + j, c.tangent)] {
            let ra = c.point - p.bodies[c.a].position;
            let v = &mut w[col];
            v[3 * c.a] += dir.x;
            v[3 * c.a + 1] += dir.y;
            v[3 * c.a + 2] += cross(&ra, &dir);
            if let Some(b) = c.b {
                let rb = c.point - p.bodies[b].position;
                v[3 * b] -= dir.x;
                v[3 * b + 1] -= dir.y;
                v[3 * b + 2] -= cross(&rb, &dir);
            }
        }
    }
    Assembled { nb, nc, w, minv, u }
}

impl Assembled {
    fn gamma(&self, u: &[Real]) -> Vec<Real> {
        self.w
            .iter()
            .map(|c| c.iter().zip(u).map(|(a, b)| a * b).sum())
            .collect()
    }
    fn delassus(&self) -> Vec<Real> {
        let k = 2 * self.nc;
        let mut g = vec![0.0; k * k];
        for i in 0..k {
            for j in i..k {
                let s: Real = (0..3 * self.nb)
                    .map(|d| self.w[i][d] * self.minv[d] * self.w[j][d])
                    .sum();
                g[i * k + j] = s;
                g[j * k + i] = s;
            }
        }
        g
    }
    fn post_velocity(&self, lambda: &[Real]) -> Vec<Real> {
        let mut u = self.u.clone();
        for (col, l) in self.w.iter().zip(lambda) {
            for d in 0..u.len() {
                u[d] += self.minv[d] * col[d] * l;
            }
        }
        u
    }
    fn energy(&self, u: &[Real]) -> Real {
        u.iter()
            .zip(&self.minv)
            .map(|(v, mi)| 0.5 * v * v / mi)
            .sum()
    }
    /// Post-solve checks ([`crate::law_check`]) on the recovered velocities `u⁺` (`gamma_post =
    /// Wᵀu⁺`): the contact laws with the rounding scales `s_k = Σ_d |W_dk| a_d`,
    /// `a_d = |u⁻_d| + Σ_j |M⁻¹_d W_dj Λ_j|`, then `T⁺ − T⁻ ≤ bound + τ (|bound terms| +
    /// Σ_d m_d (|u⁻_d| + |u⁺_d|) a_d)`.
    #[allow(clippy::too_many_arguments)]
    fn check(
        &self,
        laws: &[ImpactLaw],
        gamma_pre: &[Real],
        lambda: &[Real],
        u_post: &[Real],
        gamma_post: &[Real],
        e0: Real,
        e1: Real,
    ) -> Result<(), LawViolation> {
        let a: Vec<Real> = (0..self.u.len())
            .map(|d| {
                self.u[d].abs()
                    + self
                        .w
                        .iter()
                        .zip(lambda)
                        .map(|(c, l)| (self.minv[d] * c[d] * l).abs())
                        .sum::<Real>()
            })
            .collect();
        let scale: Vec<Real> = self
            .w
            .iter()
            .map(|c| c.iter().zip(&a).map(|(w, a)| w.abs() * a).sum())
            .collect();
        let diag: Vec<Real> = self
            .w
            .iter()
            .map(|c| c.iter().zip(&self.minv).map(|(w, m)| w * w * m).sum())
            .collect();
        law_check::check_laws(laws, gamma_pre, lambda, gamma_post, &scale, &diag)?;
        let (bound, bscale) = law_check::energy_bound(laws, gamma_pre, lambda);
        let escale: Real = (0..self.u.len())
            .map(|d| (self.u[d].abs() + u_post[d].abs()) * a[d] / self.minv[d])
            .sum();
        let gain = e1 - e0;
        let allowed = bound + LAW_TOLERANCE * (bscale + escale);
        // NaN (from any operand) fails too
        if gain.is_nan() || allowed.is_nan() || gain > allowed {
            return Err(LawViolation::EnergyCreated { gain, bound });
        }
        Ok(())
    }
}

/// The `3n × 3n` LCP matrix and vector of spec §8 (row-major), from `G` (2n × 2n, row-major,
/// blocks `[N..., T...]`), the laws and `γ⁻`.
pub fn impact_lcp(g: &[Real], laws: &[ImpactLaw], gamma_pre: &[Real]) -> (Vec<Real>, Vec<Real>) {
    impact_lcp_free(g, laws, gamma_pre, gamma_pre)
}

/// [`impact_lcp`] of a time step: the velocities the impulses act on are the free velocities
/// `γ_free` at the end of the step (without contact impulses), so `b_N = γ_N,free + ε_N min(γ_N⁻,
/// 0)`, `b_T = γ_T,free` (spec §8 with `γ_free = γ⁻` for an isolated impact). The one assembly
/// of the impact LCP: the single impact here and every step of the simulator's rigid stepper
/// (`sim/rigid.rs`).
pub(crate) fn impact_lcp_free(
    g: &[Real],
    laws: &[ImpactLaw],
    gamma_pre: &[Real],
    gamma_free: &[Real],
) -> (Vec<Real>, Vec<Real>) {
    let n = laws.len();
    let k = 2 * n;
    let d = 3 * n;
    let mut a = vec![0.0; d * d];
    let mut b = vec![0.0; d];
    for i in 0..n {
        for j in 0..n {
            let mu_j = laws[j].mu();
            let (gnn, gnt) = (g[i * k + j], g[i * k + n + j]);
            let (gtn, gtt) = (g[(n + i) * k + j], g[(n + i) * k + n + j]);
            a[i * d + j] = gnn - gnt * mu_j;
            a[i * d + n + j] = gnt;
            a[(n + i) * d + j] = gtn - gtt * mu_j;
            a[(n + i) * d + n + j] = gtt;
        }
        a[(n + i) * d + 2 * n + i] = 1.0;
        a[(2 * n + i) * d + i] = 2.0 * laws[i].mu();
        a[(2 * n + i) * d + n + i] = -1.0;
        b[i] = gamma_free[i] + laws[i].eps() * gamma_pre[i].min(0.0);
        b[n + i] = gamma_free[n + i];
    }
    (a, b)
}

/// `(Λ_N, Λ_T)` (length 2n, blocks `[N..., T...]`) from an LCP solution `x = (Λ_N, Λ_TR, γ_TL)`.
pub(crate) fn impulses(z: &[Real], laws: &[ImpactLaw]) -> Vec<Real> {
    let n = laws.len();
    let mut l = vec![0.0; 2 * n];
    for i in 0..n {
        l[i] = z[i];
        l[n + i] = z[n + i] - laws[i].mu() * z[i];
    }
    l
}

/// Numerical rank deficiency of a symmetric PSD matrix (Gaussian elimination with full pivoting,
/// relative tolerance 1e-10).
fn is_singular(g: &[Real], k: usize) -> bool {
    let mut a = g.to_vec();
    let scale = (0..k).map(|i| a[i * k + i].abs()).fold(0.0, Real::max);
    if scale == 0.0 {
        return true;
    }
    let mut rows: Vec<usize> = (0..k).collect();
    for step in 0..k {
        // pick the largest remaining diagonal (PSD: full pivoting on the diagonal suffices)
        let (pi, pv) = rows[step..].iter().map(|&r| (r, a[r * k + r])).fold(
            (usize::MAX, Real::NEG_INFINITY),
            |m, x| {
                if x.1 > m.1 { x } else { m }
            },
        );
        if pv <= 1e-10 * scale {
            return true;
        }
        let pos = rows.iter().position(|&r| r == pi).unwrap();
        rows.swap(step, pos);
        for &r in &rows[step + 1..] {
            let f = a[r * k + pi] / pv;
            for c in 0..k {
                a[r * k + c] -= f * a[pi * k + c];
            }
        }
    }
    false
}

/// Solves the impact problem (see the module documentation for the model and the LCP).
///
/// In order: no approaching contact → [`ImpactStatus::NoImpact`]; else Lemke on the impact LCP
/// (`lemke_impact`); enumeration of the LCP's solutions when the policy asks for it
/// (`enumerated_solutions`: how many distinct impulses, whether the post-impact velocity is
/// unique); then the first of Lemke's solution, the first enumerated one, the closed form of a
/// single contact (`single_contact_fallback`) that exists; else [`ImpactStatus::Failed`].
pub fn solve(problem: &ImpactProblem, settings: &ImpactSettings) -> ImpactSolution {
    let pre = PreImpact::new(problem, settings);
    let n = pre.asm.nc;
    let finish = |status, lemke_status, lambda, solutions, enumerated, unique| {
        pre.finish(Outcome {
            status,
            lemke_status,
            lambda,
            solutions,
            enumerated,
            unique,
        })
    };
    if pre.gamma_pre[..n].iter().all(|&g| g >= 0.0) {
        let zero = Some(vec![0.0; 2 * n]);
        return finish(
            ImpactStatus::NoImpact,
            LcpStatus::Solved,
            zero,
            1,
            false,
            true,
        );
    }
    let g = pre.asm.delassus();
    let (a, b) = impact_lcp(&g, &pre.laws, &pre.gamma_pre);
    let (lemke_status, z) = lemke_impact(n, &a, &b, settings);
    let want_enum = match settings.enumerate {
        EnumeratePolicy::OnFailure => !lemke_status.is_solved(),
        EnumeratePolicy::Auto => !lemke_status.is_solved() || is_singular(&g, 2 * n),
        EnumeratePolicy::Always => true,
    } && 3 * n <= lcp::enumerate::MAX_ENUM_DIM;
    let mut enumerated: Option<Vec<Vec<Real>>> = None;
    if want_enum && let Ok(p) = LcpProblem::new(a, b) {
        enumerated = lcp::enumerate(&p).ok();
    }
    let lemke_z = lemke_status.is_solved().then_some(z.as_slice());
    let (count, unique, first) = match &enumerated {
        Some(list) => enumerated_solutions(&pre.asm, &pre.laws, lemke_z, list),
        None => (1, true, None),
    };
    let ran = enumerated.is_some();
    if let Some(z) = lemke_z {
        let lambda = Some(impulses(z, &pre.laws));
        return finish(
            ImpactStatus::Solved,
            lemke_status,
            lambda,
            count,
            ran,
            unique,
        );
    }
    if let Some(l) = first {
        return finish(
            ImpactStatus::SolvedByFallback,
            lemke_status,
            Some(l),
            count,
            ran,
            unique,
        );
    }
    let count = if ran { 0 } else { 1 };
    if n == 1 {
        return match single_contact_fallback(&g, &pre.laws[0], &pre.gamma_pre) {
            Some(l) => finish(
                ImpactStatus::SolvedByFallback,
                lemke_status,
                Some(l),
                count,
                ran,
                true,
            ),
            None => finish(ImpactStatus::Failed, lemke_status, None, 0, ran, true),
        };
    }
    finish(ImpactStatus::Failed, lemke_status, None, count, ran, true)
}

/// Lemke on the impact LCP `(a, b)` of `n` contacts (dimension `3n`): the fixed-size kernels for
/// one and two contacts, the general solver beyond. Returns the status and `z` (NaN when the
/// problem cannot even be stated).
fn lemke_impact(
    n: usize,
    a: &[Real],
    b: &[Real],
    settings: &ImpactSettings,
) -> (LcpStatus, Vec<Real>) {
    match n {
        1 => {
            let s = lcp::solve_fixed::<3>(&to_rows::<3>(a), &to_arr::<3>(b), &settings.lemke);
            (s.status, s.z.to_vec())
        }
        2 => {
            let s = lcp::solve_fixed::<6>(&to_rows::<6>(a), &to_arr::<6>(b), &settings.lemke);
            (s.status, s.z.to_vec())
        }
        _ => match LcpProblem::new(a.to_vec(), b.to_vec()) {
            Ok(p) => {
                let s = lcp::Lemke::new(settings.lemke.clone()).solve(&p);
                (s.status, s.z)
            }
            Err(_) => (LcpStatus::IllConditioned, vec![Real::NAN; 3 * n]),
        },
    }
}

/// The distinct physical solutions `(Λ_N, Λ_T)` among the enumerated LCP solutions `list` (plus
/// Lemke's `lemke_z`, which enumeration may miss when it is not a vertex of the solution set):
/// their number (equal within `1e-9` of the largest impulse), whether they all give the same
/// post-impact velocity (within `1e-9` of the largest velocity), and the first of them.
fn enumerated_solutions(
    asm: &Assembled,
    laws: &[ImpactLaw],
    lemke_z: Option<&[Real]>,
    list: &[Vec<Real>],
) -> (usize, bool, Option<Vec<Real>>) {
    let mut lam: Vec<Vec<Real>> = Vec::with_capacity(list.len() + 1);
    if let Some(z) = lemke_z {
        lam.push(impulses(z, laws));
    }
    lam.extend(list.iter().map(|z| impulses(z, laws)));
    let lscale = lam
        .iter()
        .flatten()
        .fold(1e-300, |m: Real, &x| m.max(x.abs()));
    let mut distinct: Vec<&Vec<Real>> = Vec::new();
    for l in &lam {
        if !distinct
            .iter()
            .any(|d| d.iter().zip(l).all(|(x, y)| (x - y).abs() <= 1e-9 * lscale))
        {
            distinct.push(l);
        }
    }
    let us: Vec<Vec<Real>> = lam.iter().map(|l| asm.post_velocity(l)).collect();
    let uscale = us
        .iter()
        .flatten()
        .chain(asm.u.iter())
        .fold(1e-300, |m: Real, &x| m.max(x.abs()));
    let unique = us.iter().all(|v| {
        v.iter()
            .zip(&us[0])
            .all(|(x, y)| (x - y).abs() <= 1e-9 * uscale)
    });
    (distinct.len(), unique, lam.first().cloned())
}

/// The closed-form impulses `(Λ_N, Λ_T)` of a single contact ([`analytic::single_impact`]) from
/// the Delassus matrix `g` (2×2) and the pre-impact velocities, or `None` when they are no
/// solution: not finite, or `Λ_N < 0` (a Delassus matrix whose determinant is lost to rounding,
/// e.g. masses of 1e117 kg beside a moment of inertia of 2).
fn single_contact_fallback(g: &[Real], law: &ImpactLaw, gamma_pre: &[Real]) -> Option<Vec<Real>> {
    let gd = Delassus {
        nn: g[0],
        nt: g[1],
        tt: g[3],
    };
    let s = analytic::single_impact(&gd, law, gamma_pre[0], gamma_pre[1]);
    (s.normal_impulse.is_finite() && s.tangential_impulse.is_finite() && s.normal_impulse >= 0.0)
        .then(|| vec![s.normal_impulse, s.tangential_impulse])
}

/// What the solver decided, before the post-impact state is computed ([`PreImpact::finish`]).
struct Outcome {
    status: ImpactStatus,
    lemke_status: LcpStatus,
    /// `(Λ_N, Λ_T)`, `None` when there is none (NaN impulses are reported).
    lambda: Option<Vec<Real>>,
    solutions: usize,
    enumerated: bool,
    unique: bool,
}

/// The assembled problem and its pre-impact quantities: contact laws, relative velocities
/// `γ_pre`, kinetic energy, and the velocity scale of the stick test (the largest approach speed).
struct PreImpact<'a> {
    asm: Assembled,
    laws: Vec<ImpactLaw>,
    gamma_pre: Vec<Real>,
    e0: Real,
    scale: Real,
    settings: &'a ImpactSettings,
}

impl<'a> PreImpact<'a> {
    fn new(problem: &ImpactProblem, settings: &'a ImpactSettings) -> Self {
        let asm = assemble(problem);
        let n = asm.nc;
        let laws: Vec<ImpactLaw> = problem.contacts.iter().map(|c| c.law).collect();
        let gamma_pre = asm.gamma(&asm.u);
        let e0 = asm.energy(&asm.u);
        let scale = gamma_pre[..n]
            .iter()
            .fold(0.0, |m: Real, &g| m.max((-g).max(0.0)));
        PreImpact {
            asm,
            laws,
            gamma_pre,
            e0,
            scale,
            settings,
        }
    }

    /// The solution from the impulses of `o`: post-impact velocities, each contact's mode, the
    /// energies, and the check of the impact laws (a violated law makes a solved impact
    /// [`ImpactStatus::IllConditioned`]).
    fn finish(&self, o: Outcome) -> ImpactSolution {
        let (asm, n) = (&self.asm, self.asm.nc);
        let mut lambda = o.lambda.unwrap_or_else(|| vec![Real::NAN; 2 * n]);
        let solved = matches!(
            o.status,
            ImpactStatus::Solved | ImpactStatus::SolvedByFallback
        );
        let tangential_split_unique = !solved || self.min_norm_split(&mut lambda);
        let u = asm.post_velocity(&lambda);
        let gamma_post = asm.gamma(&u);
        let contacts = self.contact_results(&lambda, &gamma_post);
        let bodies = (0..asm.nb)
            .map(|b| BodyVelocity {
                velocity: Vector::new(u[3 * b], u[3 * b + 1]),
                omega: u[3 * b + 2],
            })
            .collect();
        let energy_after = asm.energy(&u);
        let law_violation = if solved {
            asm.check(
                &self.laws,
                &self.gamma_pre,
                &lambda,
                &u,
                &gamma_post,
                self.e0,
                energy_after,
            )
            .err()
        } else {
            None
        };
        let status = if law_violation.is_some() {
            ImpactStatus::IllConditioned
        } else {
            o.status
        };
        ImpactSolution {
            status,
            lemke_status: o.lemke_status,
            contacts,
            bodies,
            energy_before: self.e0,
            energy_after,
            solutions: o.solutions,
            enumerated: o.enumerated,
            post_velocity_unique: o.unique,
            law_violation,
            tangential_split_unique,
        }
    }

    /// The minimum-norm tangential split (`split::min_norm_split`) of the solution `lambda` (replaced in
    /// place when it is not unique): the sticking contacts are those [`Self::contact_results`]
    /// calls stick, with `μ Λ_N > 0`. Returns whether the split was unique.
    fn min_norm_split(&self, lambda: &mut [Real]) -> bool {
        let (asm, n) = (&self.asm, self.asm.nc);
        if lambda.iter().any(|x| !x.is_finite()) {
            return true;
        }
        let gamma_post = asm.gamma(&asm.post_velocity(lambda));
        let lmax = lambda[..n].iter().fold(0.0, |m: Real, &x| m.max(x));
        let stick: Vec<usize> = (0..n)
            .filter(|&i| {
                lambda[i] > 1e-12 * lmax
                    && self.laws[i].mu() * lambda[i] > 0.0
                    && gamma_post[n + i].abs() <= self.settings.stick_tolerance * self.scale
            })
            .collect();
        if stick.is_empty() {
            return true;
        }
        let col = |i: usize| &asm.w[n + i];
        let g_ss: Vec<Real> = stick
            .iter()
            .flat_map(|&i| {
                stick.iter().map(move |&j| {
                    (0..3 * asm.nb)
                        .map(|d| col(i)[d] * asm.minv[d] * col(j)[d])
                        .sum::<Real>()
                })
            })
            .collect();
        let mut lt: Vec<Real> = stick.iter().map(|&i| lambda[n + i]).collect();
        let b: Vec<Real> = stick
            .iter()
            .map(|&i| self.laws[i].mu() * lambda[i])
            .collect();
        let unique = split::min_norm_split(&g_ss, &mut lt, &b);
        for (&i, &x) in stick.iter().zip(&lt) {
            lambda[n + i] = x;
        }
        unique
    }

    /// Each contact's impulses, pre/post velocities and mode: open when `Λ_N ≤ 1e-12 max Λ_N`
    /// (or NaN), stick when `|γ_T⁺| ≤ stick_tolerance · scale`, else slip in the sign of `γ_T⁺`.
    fn contact_results(&self, lambda: &[Real], gamma_post: &[Real]) -> Vec<ContactResult> {
        let n = self.asm.nc;
        let lmax = lambda[..n].iter().fold(0.0, |m: Real, &x| m.max(x));
        (0..n)
            .map(|i| {
                let (ln, lt) = (lambda[i], lambda[n + i]);
                let gtp = gamma_post[n + i];
                let mode = if ln.is_nan() || ln <= 1e-12 * lmax {
                    ContactMode::Open
                } else if gtp.abs() <= self.settings.stick_tolerance * self.scale {
                    ContactMode::Stick
                } else if gtp > 0.0 {
                    ContactMode::SlipPositive
                } else {
                    ContactMode::SlipNegative
                };
                ContactResult {
                    normal_impulse: ln,
                    tangential_impulse: lt,
                    mode,
                    gamma_n_pre: self.gamma_pre[i],
                    gamma_t_pre: self.gamma_pre[n + i],
                    gamma_n_post: gamma_post[i],
                    gamma_t_post: gtp,
                }
            })
            .collect()
    }
}

fn to_rows<const N: usize>(a: &[Real]) -> [[Real; N]; N] {
    let mut m = [[0.0; N]; N];
    for (i, row) in m.iter_mut().enumerate() {
        row.copy_from_slice(&a[i * N..(i + 1) * N]);
    }
    m
}

fn to_arr<const N: usize>(b: &[Real]) -> [Real; N] {
    let mut v = [0.0; N];
    v.copy_from_slice(b);
    v
}

/// Result of [`solve_single`], the allocation-free single-contact path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SingleSolution {
    /// Outcome (`no-impact` when `γ_N⁻ ≥ 0`).
    pub status: ImpactStatus,
    /// Lemke's status.
    pub lemke_status: LcpStatus,
    /// `Λ_N`.
    pub normal_impulse: Real,
    /// `Λ_T`.
    pub tangential_impulse: Real,
    /// `γ_N⁺`.
    pub gamma_n_post: Real,
    /// `γ_T⁺`.
    pub gamma_t_post: Real,
    /// Mode (`Open` only for no impact).
    pub mode: ContactMode,
    /// The law `γ⁺` violates when `status` is [`ImpactStatus::IllConditioned`], else `None`.
    pub law_violation: Option<LawViolation>,
}

impl SingleSolution {
    /// Exact kinetic-energy change `½ (γ⁺ + γ⁻)ᵀ Λ` (spec §11).
    pub fn energy_change(&self, gamma_n_pre: Real, gamma_t_pre: Real) -> Real {
        0.5 * ((self.gamma_n_post + gamma_n_pre) * self.normal_impulse
            + (self.gamma_t_post + gamma_t_pre) * self.tangential_impulse)
    }
}

/// One contact with Delassus matrix `g`: the 3×3 LCP of spec §8 solved by
/// [`lcp::solve_fixed::<3>`](crate::lcp::solve_fixed), with the analytic solution (spec §9) as the
/// fallback on a Lemke failure. `γ⁺ = γ⁻ + G Λ`; the mode is classified with
/// `|γ_T⁺| ≤ 1e−9 |γ_N⁻|` as stick (spec §10); `SlipPositive` is the bridge label `slip-outward`.
/// The result is checked against the impact laws ([`crate::law_check`], contact space, rounding
/// scales `s_k = |γ_k⁻| + Σ_j |G_kj Λ_j|`); a violation gives [`ImpactStatus::IllConditioned`].
#[inline]
pub fn solve_single(
    g: &Delassus,
    law: &ImpactLaw,
    gamma_n_pre: Real,
    gamma_t_pre: Real,
    settings: &LemkeSettings,
) -> SingleSolution {
    if gamma_n_pre.is_nan() || gamma_t_pre.is_nan() {
        return SingleSolution {
            status: ImpactStatus::Failed,
            lemke_status: LcpStatus::IllConditioned,
            normal_impulse: Real::NAN,
            tangential_impulse: Real::NAN,
            gamma_n_post: Real::NAN,
            gamma_t_post: Real::NAN,
            mode: ContactMode::Open,
            law_violation: None,
        };
    }
    if gamma_n_pre >= 0.0 {
        return SingleSolution {
            status: ImpactStatus::NoImpact,
            lemke_status: LcpStatus::Solved,
            normal_impulse: 0.0,
            tangential_impulse: 0.0,
            gamma_n_post: gamma_n_pre,
            gamma_t_post: gamma_t_pre,
            mode: ContactMode::Open,
            law_violation: None,
        };
    }
    let mu = law.mu();
    let a = [
        [g.nn - g.nt * mu, g.nt, 0.0],
        [g.nt - g.tt * mu, g.tt, 1.0],
        [2.0 * mu, -1.0, 0.0],
    ];
    let b = [(1.0 + law.eps()) * gamma_n_pre, gamma_t_pre, 0.0];
    let s = lcp::solve_fixed::<3>(&a, &b, settings);
    let (status, ln, lt) = if s.status.is_solved() {
        (ImpactStatus::Solved, s.z[0], s.z[1] - mu * s.z[0])
    } else {
        let an = analytic::single_impact(g, law, gamma_n_pre, gamma_t_pre);
        // `Λ_N < 0` is no solution (see `solve`): NaN, hence `Failed` below
        let ln = if an.normal_impulse >= 0.0 {
            an.normal_impulse
        } else {
            Real::NAN
        };
        (ImpactStatus::SolvedByFallback, ln, an.tangential_impulse)
    };
    let gnp = gamma_n_pre + g.nn * ln + g.nt * lt;
    let gtp = gamma_t_pre + g.nt * ln + g.tt * lt;
    if !(gnp.is_finite() && gtp.is_finite() && ln.is_finite() && lt.is_finite()) {
        // non-finite input data (e.g. a NaN entry of G): nothing trustworthy to report
        return SingleSolution {
            status: ImpactStatus::Failed,
            lemke_status: s.status,
            normal_impulse: Real::NAN,
            tangential_impulse: Real::NAN,
            gamma_n_post: Real::NAN,
            gamma_t_post: Real::NAN,
            mode: ContactMode::Open,
            law_violation: None,
        };
    }
    // post-solve check (crate::law_check) in contact space
    let lambda = [ln, lt];
    let post = [gnp, gtp];
    let scale = [
        gamma_n_pre.abs() + (g.nn * ln).abs() + (g.nt * lt).abs(),
        gamma_t_pre.abs() + (g.nt * ln).abs() + (g.tt * lt).abs(),
    ];
    let law_violation = law_check::check_laws(
        std::slice::from_ref(law),
        &[gamma_n_pre, gamma_t_pre],
        &lambda,
        &post,
        &scale,
        &[g.nn, g.tt],
    )
    .err();
    let status = if law_violation.is_some() {
        ImpactStatus::IllConditioned
    } else {
        status
    };
    let n = -gamma_n_pre;
    let mode = if gtp.abs() <= analytic::STICK_TOLERANCE * n {
        ContactMode::Stick
    } else if gtp > 0.0 {
        ContactMode::SlipPositive
    } else {
        ContactMode::SlipNegative
    };
    SingleSolution {
        status,
        lemke_status: s.status,
        normal_impulse: ln,
        tangential_impulse: lt,
        gamma_n_post: gnp,
        gamma_t_post: gtp,
        mode,
        law_violation,
    }
}
