//! `regions_*.png`: region maps in the style of the paper's Figures 7–8.

use super::study_style::{GREY, INWARD, OUTWARD, STICK, geom_title, legend, tick, tok};
use crate::plot_style::{DrawResult, e, font};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::analytic::ImpactLaw;
use pounding::math::Real;
use pounding::study::Scenario;
use pounding::study::Study;
use pounding::study::cell::{Geometry, region_samples_in};

pub(crate) fn regions<DB: DrawingBackend>(
    study: &Study,
    geom: [usize; 4],
    eps: usize,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let s = &study.scenario;
    let (top, body) = root.split_vertically(70);
    top.draw(&Text::new(
        format!(
            "{}, ε_N = {} — mode vs striking deck's θ_a (struck deck at 0)",
            geom_title(study, geom),
            tok(s.eps[eps])
        ),
        (20, 8),
        font(18),
    ))
    .map_err(e)?;
    legend(
        &top,
        &[
            (OUTWARD.to_rgba(), "outward slip (r < L)"),
            (STICK.to_rgba(), "stick (L ≤ r ≤ U)"),
            (INWARD.to_rgba(), "inward slip (r > U)"),
            (GREY.to_rgba(), "degenerate (θ_a = 0)"),
        ],
        40,
    )?;
    let arr = s.geometry(geom).map_err(|err| err.to_string())?;
    let panels = body.split_evenly((s.mu.len(), 2));
    for (m, &mu) in s.mu.iter().enumerate() {
        let law = s.law(m, eps).map_err(|err| err.to_string())?;
        for (col, deck1) in [(0usize, true), (1, false)] {
            region_panel(s, &arr, &law, deck1, mu, &panels[m * 2 + col])?;
        }
    }
    Ok(())
}

/// One panel of the region map: the striking deck's rotation against `r`, coloured by mode,
/// with the bounds `L`, `U` drawn on top.
fn region_panel<DB: DrawingBackend>(
    s: &Scenario,
    arr: &Geometry,
    law: &ImpactLaw,
    deck1: bool,
    mu: Real,
    area: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let tol = s.degeneracy_tolerance_deg();
    let range = if deck1 { s.theta1 } else { s.theta2 };
    let samples = region_samples_in(
        arr,
        law,
        deck1,
        range.start,
        range.stop,
        s.output.region_map_samples,
        s.sigma_mode,
        tol,
    );
    let title = format!(
        "{} strikes, μ = {}",
        if deck1 { "deck 1" } else { "deck 2" },
        tok(mu)
    );
    let (x0, x1) = if range.stop > range.start {
        (range.start, range.stop)
    } else {
        (range.start - 1.0, range.start + 1.0)
    };
    let mut chart = ChartBuilder::on(area)
        .caption(title, font(16))
        .margin(6)
        .x_label_area_size(38)
        .y_label_area_size(52)
        .build_cartesian_2d(x0..x1, s.ratio_min..s.ratio_max)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .disable_mesh()
        .x_desc(if deck1 {
            "θ1 [deg]  (inner corner strikes < 0 < outer corner strikes)"
        } else {
            "θ2 [deg]  (inner corner strikes < 0 < outer corner strikes)"
        })
        .y_desc("r = γ_T⁻/γ_N⁻")
        .label_style(font(13))
        .axis_desc_style(font(14))
        .draw()
        .map_err(e)?;
    let n = samples.len();
    let mut rects = Vec::with_capacity(3 * n);
    for (k, smp) in samples.iter().enumerate() {
        let left = if k == 0 {
            smp.theta_a_deg
        } else {
            0.5 * (smp.theta_a_deg + samples[k - 1].theta_a_deg)
        };
        let right = if k + 1 == n {
            smp.theta_a_deg
        } else {
            0.5 * (smp.theta_a_deg + samples[k + 1].theta_a_deg)
        };
        let c = &smp.cell;
        if c.lower.is_nan() {
            rects.push(Rectangle::new(
                [(left, s.ratio_min), (right, s.ratio_max)],
                GREY.filled(),
            ));
            continue;
        }
        let l = c.lower.clamp(s.ratio_min, s.ratio_max);
        let u = c.upper.clamp(s.ratio_min, s.ratio_max);
        rects.push(Rectangle::new(
            [(left, s.ratio_min), (right, l)],
            OUTWARD.filled(),
        ));
        rects.push(Rectangle::new([(left, l), (right, u)], STICK.filled()));
        rects.push(Rectangle::new(
            [(left, u), (right, s.ratio_max)],
            INWARD.filled(),
        ));
    }
    chart.draw_series(rects).map_err(e)?;
    for upper in [false, true] {
        let mut seg: Vec<(Real, Real)> = Vec::new();
        let mut lines = Vec::new();
        for smp in &samples {
            let v = if upper {
                smp.cell.upper
            } else {
                smp.cell.lower
            };
            if v.is_finite() {
                seg.push((smp.theta_a_deg, v.clamp(s.ratio_min, s.ratio_max)));
            } else if !seg.is_empty() {
                lines.push(std::mem::take(&mut seg));
            }
        }
        if !seg.is_empty() {
            lines.push(seg);
        }
        chart
            .draw_series(
                lines
                    .into_iter()
                    .map(|l| PathElement::new(l, BLACK.stroke_width(2))),
            )
            .map_err(e)?;
    }
    Ok(())
}
