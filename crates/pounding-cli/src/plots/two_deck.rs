//! PNG figures of a two-deck run (`[decks]` scenarios, the default): the model is a two-segment
//! bridge, and every time-history panel is one of [`super::sim_panels`]; this module only
//! chooses the files and names what the two-deck form names (deck 1 and 2, the joint's two
//! ends, the axes along and normal to the joint):
//!
//! * `displacements.png` — ground acceleration and both decks' centroid displacements;
//! * `rotations.png` — plan rotations θ1, θ2;
//! * `joint_gap.png` — the joint gap at both ends of the joint, with the impacts marked;
//! * `impulses.png` — normal and tangential impulse of every impacting contact, by mode;
//! * `energy.png` — the energy balance (input, stored, dissipated);
//! * `abutment_gap.png` — with abutments: the gap of each far end face to its abutment;
//! * `layout.png` — plan view of the two decks, bearings, joint, abutments and axes (reference
//!   pose, [`super::sim_layout`]).

/// The figures [`write_all`] may draw (`abutment_gap.png` only with abutments), in order.
pub const FIGURES: &[&str] = &[
    "displacements.png",
    "layout.png",
    "rotations.png",
    "joint_gap.png",
    "abutment_gap.png",
    "impulses.png",
    "energy.png",
];

use crate::plot_style::{BLUE, DrawResult, RED, register, save_white_png};
use crate::plots::sim_layout::layout;
use crate::plots::sim_lines::energy_panel;
use crate::plots::sim_panels::{
    AbutmentNames, Hist, abutment_gap_panel, end_gap_panel, ground_panel, impulse_panels,
    rotation_panel, segment_xy_panel,
};
use plotters::prelude::SeriesLabelPosition;
use pounding::ground_motion::GroundMotion;
use pounding::sim::SimModel;
use pounding::sim::bridge::{BridgeModel, BridgeSolution};
use std::path::Path;

/// What the two-deck figures read of a run's input: the two-segment bridge the model runs as
/// (every geometry drawn or named), the model as its file gave it (only whether it gave the deck
/// shapes, for the layout's legend place), and the ground motion.
#[derive(Clone, Copy)]
pub struct TwoDeckRun<'a> {
    /// The two-deck model's parameters.
    pub model: &'a SimModel,
    /// The bridge the model runs as ([`BridgeModel::from_pair`]).
    pub bridge: &'a BridgeModel,
    /// The ground acceleration.
    pub ground: &'a GroundMotion,
}

/// Writes the figures of [`FIGURES`] into `out`.
pub fn write_all(out: &Path, run: &TwoDeckRun, sol: &BridgeSolution) -> DrawResult {
    register();
    let h = Hist::new(sol);
    let mb = (run.bridge, h);
    save_white_png(out, "displacements.png", (1400, 1050), |root| {
        let areas = root.split_evenly((3, 1));
        let axes = ["a_g,y (normal to joint)", "a_g,x (along joint)"];
        ground_panel(&areas[0], h, run.ground, axes)?;
        for (j, area) in areas[1..].iter().enumerate() {
            let title = format!(
                "Deck {} centroid displacement relative to the ground (y: + = toward deck 1)",
                j + 1
            );
            let y = format!("y{} (normal to joint)", j + 1);
            let x = format!("x{} (along joint)", j + 1);
            segment_xy_panel(area, h, j, &title, [&y, &x])?;
        }
        Ok(())
    })?;
    // the legend where the decks leave room: upper left beside the default curved pair, upper
    // right with the shapes given
    let legend = if run.model.shapes.is_some() {
        SeriesLabelPosition::UpperRight
    } else {
        SeriesLabelPosition::UpperLeft
    };
    save_white_png(out, "layout.png", (1000, 900), |root| {
        layout(root, run.bridge, legend)
    })?;
    save_white_png(out, "rotations.png", (1400, 500), |root| {
        let title = "Plan rotation of each deck about its centroid (counter-clockwise +)";
        let labels = ["θ1 (deck 1)".to_string(), "θ2 (deck 2)".to_string()];
        rotation_panel(root, h, title, &labels)
    })?;
    save_white_png(out, "joint_gap.png", (1400, 600), |root| {
        let title = format!(
            "Joint gap at both ends of the joint ({} impacts; gap 0 = decks in contact)",
            sol.summary.impacts
        );
        // the joint face's half length: its two ends sit at x = ±w
        let w = run.bridge.layout()[0].end.half;
        let ends = [
            format!("end x = +{w} m (deck1-inner / deck2-outer)"),
            format!("end x = −{w} m (deck1-outer / deck2-inner)"),
        ];
        end_gap_panel(root, mb, 0, &title, [&ends[0], &ends[1]])
    })?;
    if run.bridge.abutments.iter().any(Option::is_some) {
        save_white_png(out, "abutment_gap.png", (1400, 600), |root| {
            let names = AbutmentNames {
                title: format!(
                    "Gap between far end faces and abutments (smaller of the two corners; {} \
                     impacting contacts)",
                    sol.abutment_impacting_contacts()
                ),
                gaps: ["deck 1 far end", "deck 2 far end"],
                initial: ["initial gap, abutment 1", "initial gap, abutment 2"],
                colors: [BLUE, RED],
            };
            abutment_gap_panel(root, mb, &names)
        })?;
    }
    save_white_png(out, "impulses.png", (1400, 800), |root| {
        let titles = [
            "Normal impulse P_N of each impacting contact (pushes the decks apart)",
            "Tangential impulse P_T (on deck 1 along +τ, toward its radially outward side)",
        ];
        impulse_panels(root, h, titles)
    })?;
    save_white_png(out, "energy.png", (1400, 600), |root| {
        let err = sol.summary.energy_balance_error;
        energy_panel(root, err, h.t_end, &sol.t, &sol.energy, false)
    })
}
