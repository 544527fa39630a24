//! Ground motion that differs from support to support.
//!
//! # Supports
//! A bridge of `N` segments stands on `N + 1` **support lines**, in order along the chain: `start`
//! (under the start face of segment 1: the start abutment, or the ground under an outer end),
//! `joint1` … `joint{N−1}` (under each joint: the ground under its bearings, or its pier's
//! foundation) and `end`. Each has a plan position (the midpoint of its face, or of the joint's
//! two faces) and, here, a motion of its own.
//!
//! # Formulation: relative to a reference ground motion
//! The coordinates `q` are taken relative to a **reference** ground motion `u_r(t)` (the run's
//! ground motion, [`crate::ground_motion::GroundMotion`]), and support `s` moves by
//! `d_s(t) = u_s(t) − u_r(t)` relative to it, exactly: `u_s` and `u_r` are the exact double
//! integrals of the piecewise-linear records ([`crate::ground_motion::integral`], no baseline
//! correction). A link between a body point (operator `B`) and support `s` deforms by
//! `B q − d_s`, so with the linear links' coupling to the supports collected in `P_K`, `P_C`
//! (`n × 2S`) the equations of motion are
//!
//! ```text
//! M q̈ + C q̇ + K q = −M r a_r(t) + P_K d(t) + P_C ḋ(t) + R(q − d) + contacts,
//! ```
//!
//! with the yielding members on a support acting on their deformation `B q − d_s`, the contact
//! with an abutment measured from the abutment's moved face (its gap closes by `d_s·n`, its
//! closing velocity includes `ḋ_s`), a seat on the ground measured from its own support, and
//! a Rayleigh damping's stiffness part acting on the links' deformation rates (`P_C` holds
//! `a_1` times the links' `P_K`; the mass part acts on `q̇`, the motion relative to the
//! reference). The θ-method takes the extra load at the step's θ-point
//! (`(1−θ) F(t_k) + θ F(t_{k+1})`, as the inertia load) and books its work as input work. With every
//! support on the reference motion, `d ≡ 0`: the run is the uniform-excitation run, bit for bit
//! (the load is not even formed).
//!
//! This is the formulation of the "relative to one support" variant of multiple-support
//! excitation; it gives the same total motion as an absolute formulation (OpenSees
//! `MultipleSupport`) and keeps the uniform case's numbers.
//!
//! # Motions
//! * [`SupportExcitation::WavePassage`]: the reference record reaches support `s` after
//!   `τ_s = (p_s − p_first)·e / v_app` (`e` the unit direction of travel, `p_first` the support it
//!   reaches first): `u_s(t) = u_r(t − τ_s)`, at rest before its arrival.
//! * [`SupportExcitation::Records`]: each support its own record (one realisation of spatially
//!   variable ground motion, `pounding motion svgm`), the reference the run's ground motion.

use super::SimError;
use crate::ground_motion::GroundMotion;
use crate::ground_motion::integral::GroundKinematics;
use crate::math::{Real, Vector};

/// How the supports move (module doc).
#[derive(Debug, Clone, PartialEq, Default)]
pub enum SupportExcitation {
    /// Every support with the run's ground motion.
    #[default]
    Uniform,
    /// The run's ground motion travelling across the supports.
    WavePassage {
        /// Apparent velocity `v_app > 0` \[m/s\] (`∞`: uniform).
        v_app: Real,
        /// Unit direction of travel in the plan (`None`: from the start support toward the end
        /// one).
        direction: Option<Vector>,
    },
    /// One motion per support.
    Records(Vec<SupportRecord>),
}

impl SupportExcitation {
    /// A wave passage's direction of travel `e` and the arrival delay of each of `lines`,
    /// `τ_s = (p_s − p_first)·e / v_app` (`None`: no wave passage, or `v_app = ∞`).
    pub fn wave_delays(&self, lines: &[SupportLine]) -> Option<(Vector, Vec<Real>)> {
        let SupportExcitation::WavePassage { v_app, direction } = self else {
            return None;
        };
        if v_app.is_infinite() {
            return None;
        }
        let e = direction.unwrap_or_else(|| {
            let chord = lines[lines.len() - 1].position - lines[0].position;
            chord / chord.norm()
        });
        let along: Vec<Real> = lines.iter().map(|l| l.position.dot(&e)).collect();
        let first = along.iter().copied().fold(Real::INFINITY, Real::min);
        Some((e, along.iter().map(|a| (a - first) / v_app).collect()))
    }
}

/// The motion of one support.
#[derive(Debug, Clone, PartialEq)]
pub struct SupportRecord {
    /// The support's id (`start`, `joint1`, …, `end`).
    pub id: String,
    /// Its ground motion.
    pub ground: GroundMotion,
}

/// A support line: its id and plan position.
#[derive(Debug, Clone, PartialEq)]
pub struct SupportLine {
    /// `start`, `joint1` … `joint{N−1}`, `end`.
    pub id: String,
    /// Plan position (reference pose) \[m\].
    pub position: Vector,
}

/// The supports' motion relative to the reference, evaluated at any time.
#[derive(Debug, Clone)]
pub(crate) struct SupportMotion {
    reference: GroundKinematics,
    /// Per support line: its kinematics (`None`: the reference) and delay.
    lines: Vec<(Option<GroundKinematics>, Real)>,
}

impl SupportMotion {
    /// The motion of `excitation` on the support lines `lines` (`BridgeModel::support_lines`) with
    /// reference `ground`; `None` when every
    /// support moves with the reference (uniform). Errors name the key at fault.
    pub fn new(
        lines: &[SupportLine],
        ground: &GroundMotion,
        excitation: &SupportExcitation,
    ) -> Result<Option<Self>, SimError> {
        let per_line = match excitation {
            SupportExcitation::Uniform => return Ok(None),
            SupportExcitation::WavePassage { v_app, .. } => {
                let v = *v_app;
                if v.is_nan() || v <= 0.0 {
                    return Err(SimError::invalid(
                        "ground_motion.v_app",
                        v,
                        "must be > 0 (m/s; inf for no wave passage)",
                    ));
                }
                match excitation.wave_delays(lines) {
                    None => return Ok(None),
                    Some((_, delays)) => {
                        let longest = delays.iter().copied().fold(0.0, Real::max);
                        let end = ground.end_time();
                        if !(longest.is_finite() && longest <= end) {
                            return Err(SimError::invalid(
                                "ground_motion.v_app",
                                v,
                                &format!(
                                    "the wave would take {} s to cross the bridge, longer than \
                                     the record ({} s): the far supports would not move while \
                                     it lasts",
                                    crate::output::float_token(longest),
                                    crate::output::float_token(end)
                                ),
                            ));
                        }
                        delays.into_iter().map(|tau| (None, tau)).collect()
                    }
                }
            }
            SupportExcitation::Records(recs) => {
                let mut out = Vec::with_capacity(lines.len());
                for l in lines {
                    let Some(r) = recs.iter().find(|r| r.id == l.id) else {
                        return Err(SimError::argument(
                            "ground_motion.supports",
                            format!(
                                "no motion for support `{}` (the bridge's supports: {})",
                                l.id,
                                ids(lines)
                            ),
                        ));
                    };
                    r.ground.validate()?;
                    let same = r.ground == *ground;
                    out.push(((!same).then(|| GroundKinematics::new(&r.ground)), 0.0));
                }
                if let Some(r) = recs.iter().find(|r| !lines.iter().any(|l| l.id == r.id)) {
                    return Err(SimError::argument(
                        "ground_motion.supports",
                        format!(
                            "the bridge has no support `{}` (its supports: {})",
                            r.id,
                            ids(lines)
                        ),
                    ));
                }
                out
            }
        };
        if per_line.iter().all(|(k, tau)| k.is_none() && *tau == 0.0) {
            return Ok(None);
        }
        Ok(Some(Self {
            reference: GroundKinematics::new(ground),
            lines: per_line,
        }))
    }

    /// Number of support lines.
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    /// The longest arrival delay \[s\] (0 without wave passage): a run of the record's length
    /// lasts this much longer, so that every support receives the whole record.
    pub fn longest_delay(&self) -> Real {
        self.lines.iter().map(|l| l.1).fold(0.0, Real::max)
    }

    /// `(d_s, ḋ_s)` of every support at `t`, into `d`, `v`.
    pub fn offsets(&self, t: Real, d: &mut [Vector], v: &mut [Vector]) {
        let (vr, ur) = self.reference.velocity_displacement(t);
        for (s, (k, tau)) in self.lines.iter().enumerate() {
            let (vs, us) = match k {
                None if *tau == 0.0 => (vr, ur),
                None => self.reference.velocity_displacement(t - tau),
                Some(k) => k.velocity_displacement(t - tau),
            };
            d[s] = us - ur;
            v[s] = vs - vr;
        }
    }
}

fn ids(lines: &[SupportLine]) -> String {
    lines
        .iter()
        .map(|l| l.id.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}

/// The offsets of the supports at the two ends of a step, owned by the driver.
#[derive(Debug, Clone)]
pub(crate) struct Offsets {
    /// `d(t_k)`, `ḋ(t_k)`.
    pub d: Vec<Vector>,
    pub v: Vec<Vector>,
    /// `d(t_{k+1})`, `ḋ(t_{k+1})`.
    pub d1: Vec<Vector>,
    pub v1: Vec<Vector>,
}

impl Offsets {
    /// At rest (`t = 0`: every support starts at rest with the reference).
    pub fn new(n: usize) -> Self {
        let z = vec![Vector::zeros(); n];
        Self {
            d: z.clone(),
            v: z.clone(),
            d1: z.clone(),
            v1: z,
        }
    }

    /// Moves to the next step.
    pub fn advance(&mut self) {
        std::mem::swap(&mut self.d, &mut self.d1);
        std::mem::swap(&mut self.v, &mut self.v1);
    }
}
