//! The code check of a bridge (`pounding check`): every seated end's required seat length by
//! each code of [`super::code_check`] against the seat the model provides, and every joint's
//! required gap by the SRSS and double-difference rules against its gap.
//!
//! **What the model gives** ([`seated_ends`]): each segment end on a joint, an abutment or an
//! outer pier seat (names as `summary.json`'s `seats[]`: `segment<i>-start`, `joint<k>`, …); its
//! seat length; the deck length `L` from the end to the segment's other end (the adjacent joint
//! or the end of the bridge: the axis length of a straight or skewed segment, the centre-line arc
//! `R β` of a curved one); the skew `θ` of a skewed segment (0 otherwise); the subtended angle
//! `β` of a curved segment (reported; no implemented formula uses it); each segment's first
//! period `T = 2π/ω₁` on its own bearings.
//!
//! **What `[code_check]` gives** ([`CodeCheckInput`]): the rest. How each code's terms are
//! taken at an end of segment `i` with design displacement `d_i`:
//!
//! | Code | Terms |
//! |---|---|
//! | EN 1998-2 §6.6.4 | at an abutment or pier seat (6.11) with `L_eff` = `l_eff_m` or `L`, `d_es = d_i`; at a joint with segment `j` (§6.6.4(4)) `√(l_ov,i² + l_ov,j²)`, each section's (6.11) with its own `d_es` (`d_i`, `d_j`) and `L_eff` (`l_eff_m`, else `L_i`, `L_j`) |
//! | AASHTO LRFD 4.7.4.4 | `L`, `H` = `pier_height_m` of segment `i`, `S = θ`; at a joint listed in `in_span_hinges` (a hinge within a span) `L = L_i + L_j` (the distances to either side of the hinge) and `H = (H_i + H_j)/2` (the two adjacent columns) |
//! | AASHTO Guide Spec | SDC A–C as LRFD; SDC D `Δ_eq` = the displacement of the longer-period frame at a joint, `d_i` elsewhere |
//! | Caltrans SDC 1.7 | `Δ_eq = √(d_i² + d_j²)` at a joint (hinge minimum 24 in), `d_i` at an abutment (30 in) or a pier seat (24 in) |
//! | JRA V §16.2 | `u_R = d_i`, `L = l = L_θ =` the deck length `L` |
//!
//! A code whose inputs are missing is [`Requirement::NotEvaluated`] with the reason. The
//! required gap of joint `k` between segments `i`, `j`: `g_SRSS = √(d_i² + d_j²)`,
//! `g_DDC = √(d_i² + d_j² − 2 ρ d_i d_j)` with the CQC correlation `ρ(T_i, T_j, ξ)`.

use super::AssessmentError;
pub use super::check_codes::{CODES, Code, Ec8End, Ec8Section, Requirement, SeatedEnd};
use super::check_codes::{EndInputs, ec8_end, end_requirement};
use super::check_input::{CodeCheckInput, PeriodInput};
use super::code_check::{self as cc, CodeCheckError, SeatKind};
use crate::math::Real;
use crate::sim::Problem;
use crate::sim::bridge::BridgeModel;

/// The angle `rad` in degrees as the scenario gave it: the shortest decimal whose conversion to
/// radians is `rad` (60° is stored as `60f64.to_radians()`, whose `to_degrees()` is
/// 59.99999999999999), else `rad.to_degrees()`.
pub fn degrees_as_given(rad: Real) -> Real {
    let deg = rad.to_degrees();
    (1..=17)
        .filter_map(|digits| format!("{deg:.*e}", digits - 1).parse::<Real>().ok())
        .find(|d| d.to_radians() == rad)
        .unwrap_or(deg)
}

/// The seated ends of `model`, from the start: per segment its start end, then its end end.
pub fn seated_ends(model: &BridgeModel) -> Vec<SeatedEnd> {
    let n = model.segments.len();
    let mut out = Vec::with_capacity(2 * n);
    for (i, s) in model.segments.iter().enumerate() {
        let curved = s.shape.curved();
        let deck_length = s
            .shape
            .length()
            .or(curved.map(|d| d.radius * d.angle))
            .unwrap_or(0.0);
        for at_end in [false, true] {
            let side = usize::from(at_end);
            let joint = match (at_end, i) {
                (false, 0) => None,
                (false, _) => Some(i - 1),
                (true, _) if i + 1 == n => None,
                (true, _) => Some(i),
            };
            let (support, kind, seat_length) = match joint {
                Some(k) => (
                    format!("joint{}", k + 1),
                    SeatKind::Hinge,
                    model.joints[k].seat_length,
                ),
                None => match model.abutments[side] {
                    Some(a) => (
                        format!("abutment-{}", ["start", "end"][side]),
                        SeatKind::Abutment,
                        a.seat_length,
                    ),
                    None => (
                        format!("outer-{}", ["start", "end"][side]),
                        SeatKind::Hinge,
                        model.outer_seat_length,
                    ),
                },
            };
            out.push(SeatedEnd {
                end: format!("segment{}-{}", i + 1, ["start", "end"][side]),
                segment: i,
                support,
                joint,
                kind,
                seat_length,
                deck_length,
                skew_deg: degrees_as_given(s.shape.skew().abs()),
                subtended_deg: curved.map(|d| degrees_as_given(d.angle)),
            });
        }
    }
    out
}

/// One seated end checked.
#[derive(Debug, Clone, PartialEq)]
pub struct EndCheck {
    /// The end.
    pub at: SeatedEnd,
    /// Average column height `H` under its segment \[m\].
    pub pier_height: Real,
    /// AASHTO's `L` and `H` at this end \[m\]: the segment's own, or at an in-span hinge the sum
    /// of the two segments' lengths and the mean of their column heights.
    pub aashto_l_h: (Real, Real),
    /// Its segment's design displacement \[m\], when given.
    pub displacement: Option<Real>,
    /// Per code (in [`CODES`] order).
    pub codes: Vec<(Code, Requirement)>,
    /// EN 1998-2's terms (each deck section's expression (6.11)) when it is evaluated here.
    pub ec8: Option<Ec8End>,
}

impl EndCheck {
    /// The largest evaluated requirement and its code.
    pub fn governing(&self) -> Option<(Code, Real)> {
        self.codes
            .iter()
            .filter_map(|(c, r)| r.value().map(|v| (*c, v)))
            .fold(None, |g, (c, v)| match g {
                Some((_, gv)) if gv >= v => g,
                _ => Some((c, v)),
            })
    }
    /// Provided minus governing seat \[m\] (negative: too short).
    pub fn margin(&self) -> Option<Real> {
        self.governing().map(|(_, g)| self.at.seat_length - g)
    }
    /// `Some(true)` when the seat meets every evaluated code.
    pub fn pass(&self) -> Option<bool> {
        self.margin().map(|m| m >= 0.0)
    }
}

/// One joint's gap checked.
#[derive(Debug, Clone, PartialEq)]
pub struct GapCheck {
    /// Joint (0-based), between segments `joint` and `joint + 1`.
    pub joint: usize,
    /// The provided gap \[m\].
    pub gap: Real,
    /// The two frames' periods \[s\] (`None`: a mechanism without a period).
    pub periods: [Option<Real>; 2],
    /// Damping ratio of the correlation.
    pub damping: Real,
    /// Required gap by SRSS.
    pub srss: Requirement,
    /// Required gap by the double-difference rule.
    pub ddc: Requirement,
}

/// A code check of a bridge.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckReport {
    /// Per seated end.
    pub ends: Vec<EndCheck>,
    /// Per joint.
    pub gaps: Vec<GapCheck>,
    /// The inputs (with their defaults).
    pub input: CodeCheckInput,
}

impl CheckReport {
    /// Seated ends that fail some evaluated code.
    pub fn failing_ends(&self) -> usize {
        self.ends.iter().filter(|e| e.pass() == Some(false)).count()
    }
    /// Joints whose gap fails [`GapCheck::pass`].
    pub fn failing_gaps(&self) -> usize {
        self.gaps.iter().filter(|g| g.pass() == Some(false)).count()
    }
    /// The codes not evaluated at some end, with the first reason given.
    pub fn not_evaluated(&self) -> Vec<(Code, String)> {
        let mut out: Vec<(Code, String)> = Vec::new();
        for e in &self.ends {
            for (c, r) in &e.codes {
                if let Requirement::NotEvaluated(m) = r
                    && !out.iter().any(|(o, _)| o == c)
                {
                    out.push((*c, m.clone()));
                }
            }
        }
        out
    }
}

impl GapCheck {
    /// Whether the gap meets `r` (`None`: not evaluated).
    fn meets(&self, r: &Requirement) -> Option<bool> {
        r.value().map(|v| self.gap >= v)
    }
    /// The gap against the SRSS requirement.
    pub fn pass_srss(&self) -> Option<bool> {
        self.meets(&self.srss)
    }
    /// The gap against the double-difference requirement.
    pub fn pass_ddc(&self) -> Option<bool> {
        self.meets(&self.ddc)
    }
    /// The joint's verdict: the double-difference rule when it is evaluated (it accounts for
    /// the frames' correlation; the SRSS, which ignores it, is reported beside it), else SRSS.
    pub fn pass(&self) -> Option<bool> {
        self.pass_ddc().or(self.pass_srss())
    }
}

/// A formula's refusal of a value derived from the model (the `[code_check]` values are checked
/// when read): the scenario and the formula's message.
fn code_error(e: CodeCheckError, origin: &str) -> AssessmentError {
    AssessmentError::Model(format!("{origin}: code check: {e}"))
}

/// Checks `model` with `input` (from `origin`'s `[code_check]`): see the module doc.
pub fn check_bridge(
    model: &BridgeModel,
    input: &CodeCheckInput,
    origin: &str,
) -> Result<CheckReport, AssessmentError> {
    let n = model.segments.len();
    input.check_segments(n)?;
    let periods: Vec<Option<Real>> = match &input.period {
        PeriodInput::Model => model
            .segment_frequencies()
            .map_err(|e| AssessmentError::Model(e.to_string()))?
            .iter()
            .map(|w| (w[0] > 0.0).then(|| 2.0 * std::f64::consts::PI / w[0]))
            .collect(),
        PeriodInput::Given(p) => (0..n).map(|i| p.of(i)).collect(),
    };
    let disp = |i: usize| input.displacement.as_ref().and_then(|d| d.of(i));
    let err = |e| code_error(e, origin);
    let mut ends = Vec::new();
    let all = seated_ends(model);
    let height = |i: usize| input.pier_height.of(i).unwrap_or(0.0);
    for at in all.iter().cloned() {
        let i = at.segment;
        let other = at.joint.map(|k| if k == i { i + 1 } else { k });
        let h = height(i);
        let aashto_l_h = match (at.joint, other) {
            (Some(k), Some(j)) if input.in_span_hinges.contains(&k) => (
                at.deck_length + all[2 * j].deck_length,
                0.5 * (h + height(j)),
            ),
            _ => (at.deck_length, h),
        };
        let inputs = EndInputs {
            at: &at,
            other: other.map(|j| (j, all[2 * j].deck_length)),
            aashto_l_h,
            input,
            periods: &periods,
            disp: &disp,
        };
        let selected = |c: Code| input.codes.contains(&c);
        let ec8 = if selected(Code::Ec8) {
            ec8_end(&inputs).map_err(err)?
        } else {
            Err(String::new())
        };
        let codes = CODES
            .iter()
            .map(|&c| {
                if !selected(c) {
                    let why = "not selected ([code_check] codes)".to_string();
                    return Ok((c, Requirement::NotEvaluated(why)));
                }
                Ok((c, end_requirement(c, &inputs, &ec8)?))
            })
            .collect::<Result<Vec<_>, CodeCheckError>>()
            .map_err(err)?;
        ends.push(EndCheck {
            at,
            pier_height: h,
            aashto_l_h,
            displacement: disp(i),
            codes,
            ec8: ec8.ok(),
        });
    }
    let damping = input.damping.unwrap_or(model.damping_ratio);
    let mut gaps = Vec::new();
    for (k, j) in model.joints.iter().enumerate() {
        let (d1, d2) = (disp(k), disp(k + 1));
        let pair = [periods[k], periods[k + 1]];
        let need = "needs displacement_m".to_string();
        let (srss, ddc) = match (d1, d2) {
            (Some(a), Some(b)) => (
                Requirement::Required(cc::gap_srss(a, b).map_err(err)?),
                match pair {
                    [Some(t1), Some(t2)] => {
                        Requirement::Required(cc::gap_ddc(a, b, t1, t2, damping).map_err(err)?)
                    }
                    _ => Requirement::NotEvaluated(
                        "a segment has no period (a mechanism on its bearings)".into(),
                    ),
                },
            ),
            _ => (
                Requirement::NotEvaluated(need.clone()),
                Requirement::NotEvaluated(need),
            ),
        };
        gaps.push(GapCheck {
            joint: k,
            gap: j.gap,
            periods: pair,
            damping,
            srss,
            ddc,
        });
    }
    Ok(CheckReport {
        ends,
        gaps,
        input: input.clone(),
    })
}

/// The code check of a scenario of either form (a two-deck file is the bridge of two segments):
/// its `[code_check]` ([`CodeCheckInput::from_scenario`], every default when absent) on its
/// model (built without its records, which a check does not need).
pub fn check_scenario(sc: &crate::sim::scenario::Scenario) -> Result<CheckReport, AssessmentError> {
    let input = CodeCheckInput::from_scenario(sc.text(), sc.origin())?;
    let setup = sc.clone().for_batch().build_setup()?;
    check_bridge(&setup.model(), &input, sc.origin())
}
