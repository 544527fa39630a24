//! Drawing code of the figures, one module per kind (the style lives in [`crate::plot_style`]).

pub(crate) mod bridge;
pub(crate) mod bridge_loops;
pub(crate) mod bridge_zoom;
pub(crate) mod sim_batch;
pub(crate) mod sim_layout;
pub(crate) mod sim_lines;
pub(crate) mod sim_panels;
pub(crate) mod study_chart;
pub(crate) mod study_overview;
pub(crate) mod study_regions;
pub(crate) mod study_style;
pub(crate) mod study_surface;
pub(crate) mod two_deck;
