//! The requirement of each code at one seated end ([`super::check`]'s table of terms): the
//! model's and `[code_check]`'s values handed to the formulas of [`super::code_check`].

use super::check_input::CodeCheckInput;
use super::code_check::{self as cc, CodeCheckError, Ec8Seat, SeatKind};
pub use super::code_check::{CODES, Code};
use crate::math::Real;

/// A requirement of one code: a length, or why it was not evaluated.
#[derive(Debug, Clone, PartialEq)]
pub enum Requirement {
    /// The required length \[m\].
    Required(Real),
    /// Not evaluated: what is missing.
    NotEvaluated(String),
}

impl Requirement {
    /// The length, if evaluated.
    pub fn value(&self) -> Option<Real> {
        match self {
            Requirement::Required(x) => Some(*x),
            Requirement::NotEvaluated(_) => None,
        }
    }
}

/// A seated end and what the model says of it.
#[derive(Debug, Clone, PartialEq)]
pub struct SeatedEnd {
    /// `segment<i>-start` / `segment<i>-end` (1-based, as `summary.json`'s `seats[]`).
    pub end: String,
    /// The segment (0-based).
    pub segment: usize,
    /// What it sits on: `abutment-start`, `abutment-end`, `joint<k>` (1-based), `outer-start`,
    /// `outer-end`.
    pub support: String,
    /// The joint (0-based) when it sits on one.
    pub joint: Option<usize>,
    /// Caltrans' kind of seat (an outer pier seat counts as a hinge seat).
    pub kind: SeatKind,
    /// The provided seat length \[m\].
    pub seat_length: Real,
    /// Deck length `L` to the adjacent joint or end of the bridge \[m\].
    pub deck_length: Real,
    /// Skew `θ` \[deg\].
    pub skew_deg: Real,
    /// Subtended angle `β` of a curved segment \[deg\].
    pub subtended_deg: Option<Real>,
}

/// One deck section's terms of EN 1998-2 expression (6.11) at a seated end.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ec8Section {
    /// The segment (0-based) that is the deck section.
    pub segment: usize,
    /// `L_eff` \[m\]: `l_eff_m`, else the segment's length (the distance from the end to the far
    /// end of the section).
    pub l_eff: Real,
    /// `d_g`, `d_eg`, `d_es` (the section's design displacement), `l_m` and the section's
    /// `l_ov` \[m\].
    pub terms: cc::Ec8SeatResult,
}

/// EN 1998-2 §6.6.4 at one seated end: its own section's expression (6.11) and, at an
/// intermediate separation joint, the other section's (§6.6.4(4)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ec8End {
    /// The end's own segment's section.
    pub own: Ec8Section,
    /// At a joint, the section across it.
    pub other: Option<Ec8Section>,
    /// The required overlap \[m\]: `own.l_ov` at an abutment or outer seat,
    /// `√(l_ov,i² + l_ov,j²)` at a joint.
    pub l_ov: Real,
}

/// What an end's requirements are computed from.
pub(super) struct EndInputs<'a> {
    /// The end.
    pub at: &'a SeatedEnd,
    /// The other segment at its joint and that segment's deck length.
    pub other: Option<(usize, Real)>,
    /// AASHTO's deck length and column height at this end.
    pub aashto_l_h: (Real, Real),
    /// The `[code_check]` inputs.
    pub input: &'a CodeCheckInput,
    /// Each segment's period.
    pub periods: &'a [Option<Real>],
    /// Each segment's design displacement.
    pub disp: &'a dyn Fn(usize) -> Option<Real>,
}

/// EN 1998-2 §6.6.4 at the end: `Ok(Err(reason))` when an input is missing. At an abutment or
/// outer seat expression (6.11) with `d_es = d_i`; at a joint (§6.6.4(4)) the SRSS of (6.11)
/// for each of the two sections, each with its own `d_es` and its own `L_eff` (the distance
/// from the joint to the section's far end: its length, unless `l_eff_m` is given).
pub(super) fn ec8_end(e: &EndInputs) -> Result<Result<Ec8End, String>, CodeCheckError> {
    let input = e.input;
    let (Some(ground), Some(a_gr)) = (input.ground, input.a_gr) else {
        return Ok(Err("needs ground and a_gr_ms2".into()));
    };
    let i = e.at.segment;
    let section = |seg: usize, length: Real| -> Result<Option<Ec8Section>, CodeCheckError> {
        let Some(d_ed) = (e.disp)(seg) else {
            return Ok(None);
        };
        let l_eff = input.l_eff.unwrap_or(length);
        let terms = cc::ec8_seat(&Ec8Seat {
            ground,
            spectrum: input.spectrum,
            a_gr,
            importance_class: input.importance_class,
            l_eff,
            d_ed,
            l_m: input.l_m,
            near_fault_factor: input.near_fault_factor,
        })?;
        Ok(Some(Ec8Section {
            segment: seg,
            l_eff,
            terms,
        }))
    };
    let missing = || Ok(Err("needs displacement_m".to_string()));
    let Some(own) = section(i, e.at.deck_length)? else {
        return missing();
    };
    let other = match e.other {
        None => None,
        Some((j, l_j)) => match section(j, l_j)? {
            None => return missing(),
            some => some,
        },
    };
    // the lower segment first, so that both ends of a joint get the same bits
    let l_ov = match other {
        None => own.terms.l_ov,
        Some(o) if o.segment < i => o.terms.l_ov.hypot(own.terms.l_ov),
        Some(o) => own.terms.l_ov.hypot(o.terms.l_ov),
    };
    Ok(Ok(Ec8End { own, other, l_ov }))
}

/// The requirement of `code` at the end `e.at` (EN 1998-2's is `ec8`, from [`ec8_end`]).
pub(super) fn end_requirement(
    code: Code,
    e: &EndInputs,
    ec8: &Result<Ec8End, String>,
) -> Result<Requirement, CodeCheckError> {
    use Requirement::{NotEvaluated, Required};
    let (at, input, disp, periods) = (e.at, e.input, e.disp, e.periods);
    let i = at.segment;
    let other = e.other.map(|(j, _)| j);
    let (l_a, h) = e.aashto_l_h;
    // the end's own displacement, and the relative one at a joint (SRSS of the two frames)
    let d = disp(i);
    let relative = match other {
        Some(j) => d.zip(disp(j)).map(|(a, b)| a.hypot(b)),
        None => d,
    };
    let missing = |what: &str| Ok(NotEvaluated(format!("needs {what}")));
    let (l, skew) = (at.deck_length, at.skew_deg);
    let a_s = input.a_s.unwrap_or(0.05);
    match code {
        Code::Ec8 => Ok(match ec8 {
            Ok(r) => Required(r.l_ov),
            Err(why) => NotEvaluated(why.clone()),
        }),
        Code::AashtoLrfd => Ok(Required(cc::aashto_lrfd_seat(
            l_a,
            h,
            skew,
            input.aashto_zone,
            a_s,
        )?)),
        Code::AashtoGuide => {
            // SDC D: Δ_eq of the long-period frame at a joint
            let delta = match other {
                Some(j) => match (periods[i], periods[j]) {
                    (Some(ti), Some(tj)) if tj > ti => disp(j),
                    _ => d,
                },
                None => d,
            };
            match (input.sdc, delta) {
                (cc::Sdc::D, None) => missing("displacement_m (SDC D)"),
                (sdc, delta) => Ok(Required(cc::aashto_guide_seat(
                    sdc,
                    l_a,
                    h,
                    skew,
                    a_s,
                    delta.unwrap_or(0.0),
                )?)),
            }
        }
        Code::Caltrans => match relative {
            None => missing("displacement_m"),
            Some(d_eq) => {
                let [ps, crsh, temp] = input.caltrans;
                Ok(Required(cc::caltrans_seat(at.kind, ps, crsh, temp, d_eq)?))
            }
        },
        Code::Jra => match d {
            None => missing("displacement_m"),
            Some(u_r) => Ok(Required(cc::jra_seat(
                input.jra_ground,
                u_r,
                l,
                l,
                skew,
                l,
            )?)),
        },
    }
}
