//! `overview_*.png`: the stick band against μ, β (or L) and R1/R2 (or L1/L2).

use super::study_chart::{Series, line_chart};
use super::study_style::{is_deck1, tok};
use crate::plot_style::DrawResult;
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::math::Real;
use pounding::study::Study;
use pounding::study::StudyShape;
use pounding::study::summary::shares;

/// Smallest y-axis width of a share panel, percentage points (a spread of a few hundredths of
/// a percent is drawn flat, not as a steep trend).
const SHARE_MIN_SPAN: Real = 2.0;

/// Smallest y-axis width of a stick-bound panel (ratio r).
const R_MIN_SPAN: Real = 0.5;

/// Cell-weighted mean of a per-row quantity over the first-contact rows accepted by `keep`.
pub(crate) fn mean_rows(
    study: &Study,
    keep: impl Fn(&pounding::study::run::RowParams) -> bool,
    f: impl Fn(&pounding::study::Cell) -> Real,
) -> Real {
    let (mut sum, mut n) = (0.0, 0usize);
    for r in &study.rows {
        if !r.cell.first_contact {
            continue;
        }
        let p = study.scenario.params(&r.key);
        if keep(&p) {
            sum += f(&r.cell);
            n += 1;
        }
    }
    if n == 0 { Real::NAN } else { sum / n as Real }
}

/// What the overview panels read: the study, its ratio range and the sorted μ values.
struct Overview<'a> {
    study: &'a Study,
    s: &'a pounding::study::Scenario,
    rmin: Real,
    rmax: Real,
    mus: Vec<Real>,
    range_txt: String,
}

/// `overview_mu` (k = 0), `overview_beta` (1) or `overview_radius` (2).
pub(crate) fn overview<DB: DrawingBackend>(
    study: &Study,
    k: usize,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let s = &study.scenario;
    let (rmin, rmax) = (s.ratio_min, s.ratio_max);
    let mut mus: Vec<Real> = s.mu.clone();
    mus.sort_by(Real::total_cmp);
    let panels = root.split_evenly((1, 2));
    let o = Overview {
        study,
        s,
        rmin,
        rmax,
        mus,
        range_txt: format!("[{}, {}]", tok(rmin), tok(rmax)),
    };
    match k {
        0 => overview_mu(&o, &panels),
        1 => overview_beta(&o, &panels),
        _ => overview_radius(&o, &panels),
    }
}

/// Mean stick bounds and region shares against μ.
fn overview_mu<DB: DrawingBackend>(o: &Overview, panels: &[DrawingArea<DB, Shift>]) -> DrawResult {
    let (study, s, mus) = (o.study, o.s, &o.mus);
    let (rmin, rmax, range_txt) = (o.rmin, o.rmax, &o.range_txt);
    let share = |c: &pounding::study::Cell| shares(c.lower, c.upper, rmin, rmax);
    let mut series = Vec::new();
    for (ci, case) in s.cases.iter().enumerate() {
        for upper in [false, true] {
            let pts = mus
                .iter()
                .map(|&m| {
                    let v = mean_rows(
                        study,
                        |p| p.case == *case && p.mu == m,
                        |c| (if upper { c.upper } else { c.lower }).clamp(rmin, rmax),
                    );
                    (m, v)
                })
                .collect();
            series.push(Series {
                label: format!("{} {}", case.name(), if upper { "U (thin)" } else { "L" }),
                points: pts,
                color: ci,
                thin: upper,
            });
        }
    }
    line_chart(
        &panels[0],
        "Mean stick bounds L and U (first-contact cells)",
        "friction coefficient μ [-]",
        &format!("r = γ_T⁻/γ_N⁻ (clamped to {range_txt})"),
        &series,
        R_MIN_SPAN,
    )?;
    let mut series = Vec::new();
    for (name, idx) in [("outward slip", 0usize), ("stick", 1), ("inward slip", 2)] {
        let pts = mus
            .iter()
            .map(|&m| {
                let v = mean_rows(
                    study,
                    |p| p.mu == m,
                    |c| {
                        let t = share(c);
                        [t.0, t.1, t.2][idx]
                    },
                );
                (m, 100.0 * v)
            })
            .collect();
        series.push(Series {
            label: name.to_string(),
            points: pts,
            color: idx,
            thin: false,
        });
    }
    line_chart(
        &panels[1],
        &format!("Mean share of the ratio range {range_txt}"),
        "friction coefficient μ [-]",
        "share of ratio range [%]",
        &series,
        SHARE_MIN_SPAN,
    )
}

/// Mean stick share against the striking and the struck deck's angle (or length).
fn overview_beta<DB: DrawingBackend>(
    o: &Overview,
    panels: &[DrawingArea<DB, Shift>],
) -> DrawResult {
    let (study, s, mus) = (o.study, o.s, &o.mus);
    let (rmin, rmax, range_txt) = (o.rmin, o.rmax, &o.range_txt);
    let share = |c: &pounding::study::Cell| shares(c.lower, c.upper, rmin, rmax);
    // Striking deck a (owns the corner) and struck deck b.
    for (p, striking) in [(0usize, true), (1, false)] {
        let curved = s.shape == StudyShape::Curved;
        let mut bs: Vec<Real> = if curved {
            s.beta1_deg.iter().chain(&s.beta2_deg).copied().collect()
        } else {
            s.l1_m.iter().chain(&s.l2_m).copied().collect()
        };
        bs.sort_by(Real::total_cmp);
        bs.dedup();
        let series: Vec<Series> = mus
            .iter()
            .enumerate()
            .map(|(mi, &m)| {
                let pts = bs
                    .iter()
                    .map(|&b| {
                        let v = mean_rows(
                            study,
                            |q| {
                                let deck1 = is_deck1(q.case);
                                let beta = match (deck1 == striking, curved) {
                                    (true, true) => q.beta1_deg,
                                    (false, true) => q.beta2_deg,
                                    (true, false) => q.l1_m,
                                    (false, false) => q.l2_m,
                                };
                                q.mu == m && beta == b
                            },
                            |c| share(c).1,
                        );
                        (b, 100.0 * v)
                    })
                    .collect();
                Series {
                    label: format!("μ = {}", tok(m)),
                    points: pts,
                    color: mi,
                    thin: false,
                }
            })
            .collect();
        line_chart(
            &panels[p],
            &format!(
                "Mean stick share against the {} deck's {}",
                if striking { "striking" } else { "struck" },
                if curved { "angle" } else { "length" }
            ),
            match (striking, curved) {
                (true, true) => "β of the striking deck [deg]",
                (false, true) => "β of the struck deck [deg]",
                (true, false) => "L of the striking deck [m]",
                (false, false) => "L of the struck deck [m]",
            },
            &format!("stick share of {range_txt} [%]"),
            &series,
            SHARE_MIN_SPAN,
        )?;
    }
    Ok(())
}

/// Mean stick share and bounds against the radius (or length) ratio.
fn overview_radius<DB: DrawingBackend>(
    o: &Overview,
    panels: &[DrawingArea<DB, Shift>],
) -> DrawResult {
    let (study, s, mus) = (o.study, o.s, &o.mus);
    let (rmin, rmax, range_txt) = (o.rmin, o.rmax, &o.range_txt);
    let share = |c: &pounding::study::Cell| shares(c.lower, c.upper, rmin, rmax);
    let curved = s.shape == StudyShape::Curved;
    let ratio = |q: &pounding::study::run::RowParams| {
        let (a, b) = if curved {
            (q.r1_m, q.r2_m)
        } else {
            (q.l1_m, q.l2_m)
        };
        if is_deck1(q.case) { a / b } else { b / a }
    };
    let (list1, list2) = if curved {
        (&s.r1_m, &s.r2_m)
    } else {
        (&s.l1_m, &s.l2_m)
    };
    let (what, xlabel) = if curved {
        ("radius ratio", "R_striking / R_struck [-]")
    } else {
        ("length ratio", "L_striking / L_struck [-]")
    };
    let mut ratios: Vec<Real> = Vec::new();
    for &a in list1 {
        for &b in list2 {
            for q in [a / b, b / a] {
                if !ratios.contains(&q) {
                    ratios.push(q);
                }
            }
        }
    }
    ratios.sort_by(Real::total_cmp);
    let stick: Vec<Series> = mus
        .iter()
        .enumerate()
        .map(|(mi, &m)| Series {
            label: format!("μ = {}", tok(m)),
            points: ratios
                .iter()
                .map(|&x| {
                    (
                        x,
                        100.0 * mean_rows(study, |q| q.mu == m && ratio(q) == x, |c| share(c).1),
                    )
                })
                .collect(),
            color: mi,
            thin: false,
        })
        .collect();
    line_chart(
        &panels[0],
        &format!("Mean stick share against the {what}"),
        xlabel,
        &format!("stick share of {range_txt} [%]"),
        &stick,
        SHARE_MIN_SPAN,
    )?;
    let mut bounds = Vec::new();
    for (mi, &m) in mus.iter().enumerate() {
        for upper in [false, true] {
            bounds.push(Series {
                label: format!("μ = {} {}", tok(m), if upper { "U (thin)" } else { "L" }),
                points: ratios
                    .iter()
                    .map(|&x| {
                        let v = mean_rows(
                            study,
                            |q| q.mu == m && ratio(q) == x,
                            |c| (if upper { c.upper } else { c.lower }).clamp(rmin, rmax),
                        );
                        (x, v)
                    })
                    .collect(),
                color: mi,
                thin: upper,
            });
        }
    }
    line_chart(
        &panels[1],
        &format!("Mean stick bounds against the {what}"),
        xlabel,
        &format!("r = γ_T⁻/γ_N⁻ (clamped to {range_txt})"),
        &bounds,
        R_MIN_SPAN,
    )
}
