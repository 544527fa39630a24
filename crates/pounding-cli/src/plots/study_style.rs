//! Shared pieces of the study figures: colours, tick labels, titles and the legend strip.

use crate::plot_style::{DrawResult, e, font};
use plotters::coord::Shift;
use plotters::prelude::*;
use pounding::geometry::ContactCase;
use pounding::math::Real;
use pounding::study::Study;

pub(crate) const OUTWARD: RGBColor = RGBColor(230, 126, 34);
pub(crate) const STICK: RGBColor = RGBColor(39, 174, 96);
pub(crate) const INWARD: RGBColor = RGBColor(142, 68, 173);
pub(crate) const LOWER: RGBColor = RGBColor(31, 97, 180);
pub(crate) const UPPER: RGBColor = RGBColor(200, 40, 40);
pub(crate) const GREY: RGBColor = RGBColor(200, 200, 200);
pub(crate) const SINGLE: RGBColor = RGBColor(110, 60, 150);

/// A triangle in chart coordinates (θ1, r, θ2).
pub(crate) type Tri = [(Real, Real, Real); 3];

/// Axis tick text: at most 3 decimals, trailing zeros dropped (`-10`, `2.5`, `0.25`).
pub(crate) fn tick(v: &Real) -> String {
    let t = format!("{v:.3}");
    let t = t.trim_end_matches('0').trim_end_matches('.');
    if t == "-0" { "0".into() } else { t.to_string() }
}

pub(crate) fn tok(x: Real) -> String {
    pounding::output::float_token(x)
}

pub(crate) fn geom_title(study: &Study, geom: [usize; 4]) -> String {
    let s = &study.scenario;
    format!("{}, W = {} m", s.geometry_label(geom), tok(s.width))
}

pub(crate) fn case_title(c: ContactCase) -> &'static str {
    match c {
        ContactCase::Deck1Inner => "deck1-inner: deck 1's inner corner strikes deck 2",
        ContactCase::Deck1Outer => "deck1-outer: deck 1's outer corner strikes deck 2",
        ContactCase::Deck2Inner => "deck2-inner: deck 2's inner corner strikes deck 1",
        ContactCase::Deck2Outer => "deck2-outer: deck 2's outer corner strikes deck 1",
    }
}

/// Legend strip: coloured boxes with labels, left to right.
pub(crate) fn legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    items: &[(RGBAColor, &str)],
    y: i32,
) -> DrawResult {
    let mut x = 20;
    for (c, label) in items {
        area.draw(&Rectangle::new([(x, y), (x + 22, y + 16)], c.filled()))
            .map_err(e)?;
        area.draw(&Text::new(label.to_string(), (x + 28, y), font(16)))
            .map_err(e)?;
        x += 40 + 9 * label.chars().count() as i32;
    }
    Ok(())
}

pub(crate) fn is_deck1(c: ContactCase) -> bool {
    matches!(c, ContactCase::Deck1Inner | ContactCase::Deck1Outer)
}
