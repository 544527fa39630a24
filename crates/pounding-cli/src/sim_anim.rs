//! The plan-view animation section of `report.html` of a run (a bridge, or the two-deck model's
//! two-segment bridge): the trajectories JSON
//! ([`pounding::sim::output::trajectories_json`]) embedded in the page and a small script
//! (no library, no network) that draws the segments to scale at their displaced positions, with
//! a time slider, play/pause and speed, a displacement magnification (true scale one click
//! away), click-to-zoom, the ground-motion trace with a cursor, impacts flashed at their site
//! with their impulse or peak force, each seated end's seat gauge (the seat left, written when
//! zoomed; red once unseated), restrainers coloured by their tension, the bearings' ground points,
//! and jump-to buttons for the governing events. Displacements and gaps are magnified alike.

use std::fmt::Write;

/// The player script.
const SCRIPT: &str = include_str!("assets/plan_anim.js");

/// The section's HTML for the trajectories JSON text `traj`.
pub fn section(traj: &str) -> String {
    let mut h = String::with_capacity(traj.len() + SCRIPT.len() + 2048);
    h.push_str(
        "<h2 id=\"animation\">Plan animation</h2>\n<p>The segments at their displaced positions \
         (dashed: at rest); displacements and the joint and abutment gaps are magnified by the \
         factor shown, so that a closed joint is drawn closed. Click the plan to zoom 4× around \
         the point, double-click to reset. Impacts flash red at their site with their impulse \
         (rigid law) or peak force, summed over their contacts. At each seated end a gauge \
         shows the seat left (green above half the seat, orange below, red once the end has \
         unseated; zoom to read it in metres); restrainers are grey while slack, orange to red \
         with tension; grey squares are the bearings. The data is <a \
         href=\"trajectories.json\">trajectories.json</a> (decimated to at most 2000 frames).</p>\n<div id=\"an-controls\"><button \
         id=\"an-play\">Play</button> <select id=\"an-speed\"><option value=\"0.1\">0.1×</option>\
         <option value=\"0.25\">0.25×</option><option value=\"1\" selected>1×</option><option \
         value=\"4\">4×</option></select> <input id=\"an-t\" type=\"range\" min=\"0\" max=\"0\" \
         value=\"0\" step=\"1\" style=\"width:50%\"> <span id=\"an-time\"></span> magnification \
         <input id=\"an-mag\" type=\"number\" min=\"0\" step=\"any\" style=\"width:6em\"> <button \
         id=\"an-true\">true scale</button> <button id=\"an-auto\">auto</button> <span \
         id=\"an-events\">jump to: </span></div>\n<canvas id=\"an-plan\" width=\"1200\" \
         height=\"420\" style=\"width:100%;max-width:1200px;border:1px solid #ccc\"></canvas>\n\
         <canvas id=\"an-gm\" width=\"1200\" height=\"90\" \
         style=\"width:100%;max-width:1200px\"></canvas>\n",
    );
    let _ = write!(
        h,
        "<script type=\"application/json\" id=\"traj\">{}</script>\n<script>{}</script>\n",
        traj.replace("</", "<\\/"),
        SCRIPT
    );
    h
}
