//! The answer of a run in a few lines, for the top of a report: did the segments pound (where,
//! how hard), how close did an end come to leaving its seat (which end), how far did a segment
//! rotate, did an end unseat, and can the run be trusted. Every line is read from the
//! [`BridgeSolution`]; a front end renders them (the simulate report's "Verdict" table).

use super::{DEG, Layout, pair_seat_name};
use crate::output::json_float;
use crate::sim::SimStatus;
use crate::sim::bridge::BridgeSolution;

/// One line of the verdict: what it answers and the answer.
#[derive(Debug, Clone, PartialEq)]
pub struct VerdictLine {
    /// `pounding`, `seats`, `rotation`, `unseating`, `status`.
    pub topic: &'static str,
    /// The answer, one sentence.
    pub text: String,
    /// Whether it calls for attention (impacts, a seat ratio ≥ 0.5, unseating, a run that is not
    /// trustworthy).
    pub alert: bool,
}

/// A number in a sentence, to 3 significant digits: plain between 1e-3 and 1e5, else
/// `d.dde±x`.
pub(crate) fn n3(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return json_float(x).to_string();
    }
    let e = format!("{x:.2e}");
    if (1e-3..1e5).contains(&x.abs()) {
        e.parse::<f64>().map_or(e, |v| v.to_string())
    } else {
        e
    }
}

/// The name of joint `k` (0-based) in `layout`.
fn joint_name(layout: Layout, k: usize) -> String {
    match layout {
        Layout::TwoDecks => "the joint".into(),
        Layout::Bridge => format!("joint {}", k + 1),
    }
}

/// The verdict of a run of a problem laid out as `layout` (module doc).
pub fn verdict(layout: Layout, sol: &BridgeSolution) -> Vec<VerdictLine> {
    let s = &sol.summary;
    let mut out = Vec::new();
    // pounding: where and how hard
    let mut sites: Vec<(String, usize, String, f64)> = Vec::new();
    for (k, j) in s.joints.iter().enumerate() {
        if j.impacts > 0 {
            let (how, size) = match j.peak_contact_force {
                Some(f) => (format!("peak force {} N", n3(f)), f),
                None => (
                    format!("largest impulse {} N s", n3(j.peak_impulse)),
                    j.peak_impulse,
                ),
            };
            sites.push((joint_name(layout, k), j.impacts, how, size));
        }
    }
    for (side, a) in s.abutments.iter().enumerate() {
        if let Some(a) = a.as_ref().filter(|a| a.impacts > 0) {
            let (how, size) = match a.peak_contact_force {
                Some(f) => (format!("peak force {} N", n3(f)), f),
                None => (
                    format!("largest impulse {} N s", n3(a.peak_impulse)),
                    a.peak_impulse,
                ),
            };
            let name = ["the start abutment", "the end abutment"][side];
            sites.push((name.into(), a.impacts, how, size));
        }
    }
    if sites.is_empty() {
        out.push(VerdictLine {
            topic: "pounding",
            text: "No impact: the segments never touched each other or an abutment.".into(),
            alert: false,
        });
    } else {
        let hardest = sites
            .iter()
            .max_by(|a, b| a.3.total_cmp(&b.3))
            .map_or(String::new(), |h| format!("; hardest at {}: {}", h.0, h.2));
        let list: Vec<String> = sites
            .iter()
            .map(|(n, i, _, _)| format!("{n} ({i})"))
            .collect();
        out.push(VerdictLine {
            topic: "pounding",
            text: format!(
                "Pounded: {} impacts at {}{hardest}.",
                s.impacts,
                list.join(", ")
            ),
            alert: true,
        });
    }
    // seats: the governing end
    if let Some(g) = s.seats.get(s.governing_seat) {
        let name = match layout {
            Layout::TwoDecks => pair_seat_name(g),
            Layout::Bridge => format!("{} on {}", g.end, g.support),
        };
        out.push(VerdictLine {
            topic: "seats",
            text: format!(
                "Governing seat: {name}, peak {} m of its {} m seat ({} %) at {} s, {} m at \
                 the end of the run.",
                n3(g.peak_displacement.max(0.0)),
                n3(g.seat_length),
                // a diverged run's 1e290 % in exponent form, not as 290 digits
                crate::output::bounded(100.0 * g.ratio.max(0.0), 0),
                n3(g.peak_time),
                n3(g.residual_displacement)
            ),
            alert: g.ratio >= 0.5,
        });
    }
    // rotation
    if let Some((i, seg)) = s
        .segments
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.peak_rotation.total_cmp(&b.1.peak_rotation))
    {
        let who = match layout {
            Layout::TwoDecks => format!("deck {}", i + 1),
            Layout::Bridge => format!("segment {}", i + 1),
        };
        out.push(VerdictLine {
            topic: "rotation",
            text: format!(
                "Largest rotation: {} ° ({who}).",
                n3(seg.peak_rotation * DEG)
            ),
            alert: false,
        });
    }
    // unseating
    out.push(match (&s.unseated_end, s.unseating_time) {
        (Some(end), Some(t)) => {
            let name = match layout {
                Layout::TwoDecks => super::pair_unseated_end(s).unwrap_or_else(|| end.clone()),
                Layout::Bridge => end.clone(),
            };
            let n = s.seats.iter().filter(|e| e.unseated).count();
            VerdictLine {
                topic: "unseating",
                text: format!(
                    "UNSEATED: {name} left its seat first, at {} s ({n} end{} in all). The model has \
                     no fall: what it reports after that time assumes the deck still on its \
                     seat, so it is not physical.",
                    n3(t),
                    if n == 1 { "" } else { "s" }
                ),
                alert: true,
            }
        }
        _ => VerdictLine {
            topic: "unseating",
            text: "No end left its seat.".into(),
            alert: false,
        },
    });
    // status
    let trusted = sol.status == SimStatus::Completed;
    out.push(VerdictLine {
        topic: "status",
        text: if trusted {
            format!(
                "The run completed cleanly (status Completed); energy balance error {}.",
                n3(s.energy_balance_error)
            )
        } else {
            format!(
                "The run ended {:?}: its numbers are not trustworthy (see the warnings).",
                sol.status
            )
        },
        alert: !trusted,
    });
    out
}
