//! "Do the laws agree?": each law's headline figures ([`Headline`]) and a few sentences on
//! where the laws agree and how far apart they are ([`agreement`]), for the top of the compare
//! report and for Python.

use super::LawRun;
use crate::math::Real;
use crate::sim::Problem;
use crate::sim::SimStatus;
use crate::sim::output::{Layout, PeakEstimate, n3, pair_seat_name};
use crate::sim::scenario::Setup;

/// The headline figures of one law's run (the values of its `compare.csv` row).
#[derive(Debug, Clone, PartialEq)]
pub struct Headline {
    /// Impacts of the whole run.
    pub impacts: usize,
    /// The largest computed contact force \[N\] (compliance laws; `None` for rigid contact):
    /// the joint's (two decks) or the largest over joints and abutments (a bridge).
    pub force: Option<Real>,
    /// The rigid law's peak-force estimate from the impulse (`None` for a compliance law or
    /// without a rigid impact).
    pub estimate: Option<PeakEstimate>,
    /// The largest joint closing \[m\].
    pub closing: Real,
    /// The largest corner penetration \[m\].
    pub penetration: Real,
    /// The governing seat: its name and the ratio of its peak displacement to its seat length.
    pub seat: Option<(String, Real)>,
    /// Whether an end left its seat.
    pub unseated: bool,
    /// How the run ended.
    pub status: SimStatus,
}

/// The headline figures of a run of `setup` with `estimate` (the largest of its rigid sites).
pub fn headline(
    setup: &Setup,
    sol: &crate::sim::bridge::BridgeSolution,
    estimate: Option<PeakEstimate>,
) -> Headline {
    let s = &sol.summary;
    let layout = setup.layout();
    let max = |xs: &mut dyn Iterator<Item = Option<Real>>| xs.flatten().reduce(Real::max);
    let (force, closing) = match layout {
        Layout::TwoDecks => (s.joints[0].peak_contact_force, s.joints[0].peak_closing),
        Layout::Bridge => (
            max(&mut s
                .joints
                .iter()
                .map(|j| j.peak_contact_force)
                .chain(s.abutments.iter().flatten().map(|a| a.peak_contact_force))),
            max(&mut s.joints.iter().map(|j| Some(j.peak_closing))).unwrap_or(Real::NAN),
        ),
    };
    let seat = s.seats.get(s.governing_seat).map(|g| {
        let name = match layout {
            Layout::TwoDecks => pair_seat_name(g),
            Layout::Bridge => format!("{} on {}", g.end, g.support),
        };
        (name, g.ratio)
    });
    Headline {
        impacts: s.impacts,
        force,
        estimate,
        closing,
        penetration: s.peak_penetration,
        seat,
        unseated: s.unseated,
        status: sol.status,
    }
}

/// The answer to "do the laws agree?": sentences on the whole comparison, then one per law.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Agreement {
    /// Whether the laws agree on pounding, the spread of the peak force (computed forces and the
    /// rigid estimate apart), closing, penetration, impacts and governing seat ratio between the
    /// laws that ran, the runs that did not complete, the skipped laws.
    pub overall: Vec<String>,
    /// `(law, sentence)`: pounded or not, impacts, peak force (computed, or the rigid
    /// estimate with its contact duration), closing, penetration, governing seat; or why the
    /// law was skipped.
    pub laws: Vec<(String, String)>,
}

/// Force in MN, 3 significant digits.
fn mn(f: Real) -> String {
    format!("{} MN", n3(f / 1e6))
}

/// `lo (law) to hi (law)` of `xs` (`(law, value)`), with `unit` after each value; `None` with
/// fewer than one value.
fn range(xs: &[(&str, Real)], show: impl Fn(Real) -> String) -> Option<(String, Real, Real)> {
    let lo = xs.iter().min_by(|a, b| a.1.total_cmp(&b.1))?;
    let hi = xs.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
    Some((
        format!("{} ({}) to {} ({})", show(lo.1), lo.0, show(hi.1), hi.0),
        lo.1,
        hi.1,
    ))
}

/// One law's sentence.
fn law_sentence(h: &Headline) -> String {
    let mut parts = vec![if h.impacts > 0 {
        format!(
            "pounded, {} impact{}",
            h.impacts,
            if h.impacts == 1 { "" } else { "s" }
        )
    } else {
        "no impact".to_string()
    }];
    if let Some(f) = h.force {
        parts.push(format!("peak contact force {}", mn(f)));
    } else if let Some(e) = h.estimate {
        parts.push(format!(
            "peak contact force ≈ {} (estimate from the impulse over a contact duration of {} ms)",
            mn(e.peak_force),
            n3(e.contact_time * 1e3)
        ));
    }
    parts.push(format!("peak closing {} m", n3(h.closing)));
    parts.push(format!("peak penetration {} mm", n3(h.penetration * 1e3)));
    if let Some((name, ratio)) = &h.seat {
        parts.push(format!(
            "governing seat {name} at {:.0} %",
            100.0 * ratio.max(0.0)
        ));
    }
    if h.unseated {
        parts.push("UNSEATED".into());
    }
    if h.status != SimStatus::Completed {
        parts.push(format!("status {:?}: not trustworthy", h.status));
    }
    parts.join("; ") + "."
}

/// The agreement of `runs` (module doc).
pub fn agreement(runs: &[LawRun]) -> Agreement {
    let mut out = Agreement::default();
    let mut heads: Vec<(&str, Headline)> = Vec::new();
    for r in runs {
        match &r.outcome {
            Ok(ran) => {
                let h = headline(&ran.setup, &ran.sol, ran.peak_estimate());
                out.laws.push((r.law.clone(), law_sentence(&h)));
                heads.push((&r.law, h));
            }
            Err(why) => out.laws.push((r.law.clone(), format!("skipped: {why}"))),
        }
    }
    let n = heads.len();
    let pounded: Vec<&str> = heads
        .iter()
        .filter(|h| h.1.impacts > 0)
        .map(|h| h.0)
        .collect();
    let calm: Vec<&str> = heads
        .iter()
        .filter(|h| h.1.impacts == 0)
        .map(|h| h.0)
        .collect();
    out.overall.push(match (pounded.len(), n) {
        (_, 0) => "No law ran.".into(),
        (0, _) => format!("The {n} laws agree: no impact under any of them."),
        (p, _) if p == n => format!("The {n} laws agree that the structure pounds."),
        _ => format!(
            "The laws disagree on pounding: impacts under {}, none under {}.",
            pounded.join(", "),
            calm.join(", ")
        ),
    });
    out.overall.extend(force_sentence(&heads));
    out.overall.extend(spreads(&heads));
    let unseated: Vec<&str> = heads.iter().filter(|h| h.1.unseated).map(|h| h.0).collect();
    if !unseated.is_empty() {
        out.overall
            .push(format!("An end unseats under {}.", unseated.join(", ")));
    }
    let bad: Vec<String> = heads
        .iter()
        .filter(|h| h.1.status != SimStatus::Completed)
        .map(|(l, h)| format!("{l} ({:?})", h.status))
        .collect();
    if !bad.is_empty() {
        out.overall.push(format!(
            "Not trustworthy (did not complete cleanly): {}.",
            bad.join(", ")
        ));
    }
    let skipped: Vec<&str> = runs
        .iter()
        .filter(|r| r.outcome.is_err())
        .map(|r| r.law.as_str())
        .collect();
    if !skipped.is_empty() {
        out.overall.push(format!(
            "Skipped (cannot run on this bridge): {}.",
            skipped.join(", ")
        ));
    }
    out
}

/// The spread of the computed peak force between the laws, the rigid estimate named apart.
fn force_sentence(heads: &[(&str, Headline)]) -> Option<String> {
    let forces: Vec<(&str, Real)> = heads
        .iter()
        .filter_map(|(l, h)| Some((*l, h.force?)))
        .filter(|x| x.1 > 0.0)
        .collect();
    let estimates: Vec<(&str, Real)> = heads
        .iter()
        .filter_map(|(l, h)| Some((*l, h.estimate?.peak_force)))
        .collect();
    if let Some((text, lo, hi)) = range(&forces, mn) {
        let est = estimates
            .iter()
            .map(|(l, f)| format!("; the {l} law's estimate from the impulse is {}", mn(*f)))
            .collect::<String>();
        Some(if forces.len() == 1 {
            format!("Peak contact force (computed): {}{est}.", mn(hi))
        } else {
            format!(
                "Peak contact force (computed by the compliance laws): {text}, a factor {} \
                 apart{est}.",
                n3(hi / lo)
            )
        })
    } else {
        let (l, f) = estimates.first()?;
        Some(format!(
            "Peak contact force: only the {l} law's estimate from the impulse, {}.",
            mn(*f)
        ))
    }
}

/// The spread of the peak closing, penetration, impacts and governing seat ratio between the
/// laws (a sentence each, where more than one law has the figure).
fn spreads(heads: &[(&str, Headline)]) -> Vec<String> {
    let mut out = Vec::new();
    let spread = |what: &str, xs: Vec<(&str, Real)>, show: &dyn Fn(Real) -> String| {
        let (text, lo, hi) = range(&xs, show)?;
        if xs.len() > 1 && lo == hi {
            return Some(format!("{what}: {} under every law.", show(hi)));
        }
        (xs.len() > 1).then(|| {
            let rel = if hi > 0.0 {
                format!(
                    ", a spread of {:.0} % of the largest",
                    100.0 * (hi - lo) / hi
                )
            } else {
                String::new()
            };
            format!("{what}: {text}{rel}.")
        })
    };
    let pick = |f: &dyn Fn(&Headline) -> Option<Real>| -> Vec<(&str, Real)> {
        heads
            .iter()
            .filter_map(|(l, h)| Some((*l, f(h)?)))
            .filter(|x| x.1.is_finite())
            .collect()
    };
    let m = |x: Real| format!("{} m", n3(x));
    let mm = |x: Real| format!("{} mm", n3(x * 1e3));
    let pc = |x: Real| format!("{:.0} %", 100.0 * x.max(0.0));
    let count = |x: Real| format!("{x:.0}");
    out.extend(spread("Peak closing", pick(&|h| Some(h.closing)), &m));
    out.extend(spread(
        "Peak penetration",
        pick(&|h| Some(h.penetration)),
        &mm,
    ));
    out.extend(spread(
        "Impacts",
        pick(&|h| Some(h.impacts as Real)),
        &count,
    ));
    out.extend(spread(
        "Governing seat ratio",
        pick(&|h| h.seat.as_ref().map(|s| s.1)),
        &pc,
    ));
    out
}
