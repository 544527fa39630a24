//! The requirement of each code at one seated end ([`super::check`]'s table of terms): the
//! model's and `[code_check]`'s values handed to the formulas of [`super::code_check`].

use super::check::{Code, Requirement, SeatedEnd};
use super::check_input::CodeCheckInput;
use super::code_check::{self as cc, CodeCheckError, Ec8Seat};
use crate::math::Real;

/// The requirement of `code` at the end `at` of segment `i` (the other segment at its joint:
/// `other`), column height `h`.
#[allow(clippy::too_many_arguments)]
pub(super) fn end_requirement(
    code: Code,
    at: &SeatedEnd,
    i: usize,
    other: Option<usize>,
    h: Real,
    input: &CodeCheckInput,
    periods: &[Option<Real>],
    disp: &dyn Fn(usize) -> Option<Real>,
) -> Result<Requirement, CodeCheckError> {
    use Requirement::{NotEvaluated, Required};
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
        Code::Ec8 => {
            let (Some(ground), Some(a_gr)) = (input.ground, input.a_gr) else {
                return missing("ground and a_gr_ms2");
            };
            let Some(d_ed) = relative else {
                return missing("displacement_m");
            };
            let r = cc::ec8_seat(&Ec8Seat {
                ground,
                spectrum: input.spectrum,
                a_gr,
                importance_class: input.importance_class,
                l_eff: input.l_eff.unwrap_or(l),
                d_ed,
                l_m: input.l_m,
                near_fault_factor: input.near_fault_factor,
            })?;
            Ok(Required(r.l_ov))
        }
        Code::AashtoLrfd => Ok(Required(cc::aashto_lrfd_seat(
            l,
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
                    l,
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
