//! The `[code_check]` keys read apart from the site and hazard ones: the US and Japanese
//! codes' categories, the in-span hinges and the codes that apply.

use super::super::code_check::{AashtoZone, JraGround, Sdc};
use super::super::code_check::{CODES, Code};
use super::{AssessmentError, Cx, Sec};
use crate::math::Real;

/// `in_span_hinges` (0-based joints) and the line it is written on.
pub(super) fn hinges(cx: &Cx, s: &Sec) -> Result<(Vec<usize>, Option<usize>), AssessmentError> {
    let mut in_span_hinges = Vec::new();
    if let Some(v) = &s.in_span_hinges {
        for &k in v.get_ref() {
            let Some(j) = usize::try_from(k).ok().filter(|&k| k >= 1) else {
                return Err(cx.err(
                    "in_span_hinges",
                    v,
                    format!("{k} is not a joint number: joints are numbered from 1 (joint1)"),
                ));
            };
            if in_span_hinges.contains(&(j - 1)) {
                return Err(cx.err("in_span_hinges", v, format!("joint {j} is listed twice")));
            }
            in_span_hinges.push(j - 1);
        }
    }
    let hinges_line = s.in_span_hinges.as_ref().map(|v| cx.line(v));
    Ok((in_span_hinges, hinges_line))
}

/// `codes`: the codes that apply, in the order of [`CODES`] (every code when absent).
pub(super) fn codes(cx: &Cx, s: &Sec) -> Result<Vec<Code>, AssessmentError> {
    let all = CODES;
    Ok(match &s.codes {
        None => all.to_vec(),
        Some(list) => {
            let names: Vec<&str> = all.iter().map(|c| c.name()).collect();
            let mut out: Vec<Code> = Vec::new();
            for v in list.get_ref() {
                let c = all[cx.choice("codes", v, &names)?];
                if out.contains(&c) {
                    return Err(cx.err("codes", v, format!("{:?} is listed twice", v.get_ref())));
                }
                out.push(c);
            }
            if out.is_empty() {
                return Err(cx.err(
                    "codes",
                    list,
                    "lists no code: name at least one, or leave the key out for every code".into(),
                ));
            }
            // in the order of CODES, whatever the order written
            all.iter().copied().filter(|c| out.contains(c)).collect()
        }
    })
}

/// The AASHTO, Caltrans and JRA keys.
#[allow(clippy::type_complexity)]
pub(super) fn us_jra(
    cx: &Cx,
    s: &Sec,
) -> Result<(AashtoZone, Option<Real>, Sdc, [Real; 3], JraGround), AssessmentError> {
    let aashto_zone = match &s.aashto_zone {
        None => AashtoZone::Z4,
        Some(v) => [
            AashtoZone::Z1,
            AashtoZone::Z2,
            AashtoZone::Z3,
            AashtoZone::Z4,
        ][usize::from(cx.int("aashto_zone", v, 1, 4)?) - 1],
    };
    let a_s = s
        .a_s
        .as_ref()
        .map(|v| {
            cx.num(
                "a_s",
                v,
                |x| (0.0..=5.0).contains(&x),
                "must lie in [0, 5] (a fraction of g)",
            )
        })
        .transpose()?;
    let sdc = match &s.sdc {
        None => Sdc::C,
        Some(v) => [Sdc::A, Sdc::B, Sdc::C, Sdc::D][cx.choice("sdc", v, &["A", "B", "C", "D"])?],
    };
    let caltrans = [
        cx.length("delta_ps_m", &s.delta_ps_m)?.unwrap_or(0.0),
        cx.length("delta_crsh_m", &s.delta_crsh_m)?.unwrap_or(0.0),
        cx.length("delta_temp_m", &s.delta_temp_m)?.unwrap_or(0.0),
    ];
    let jra_ground = match &s.jra_ground {
        None => JraGround::III,
        Some(v) => [JraGround::I, JraGround::II, JraGround::III]
            [cx.choice("jra_ground", v, &["I", "II", "III"])?],
    };
    Ok((aashto_zone, a_s, sdc, caltrans, jra_ground))
}
