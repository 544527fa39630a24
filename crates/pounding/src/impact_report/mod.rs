//! Single-impact reports: the computations behind `pounding impact` as serialisable library types.
//!
//! Four entry points, one per form of the command, each taking an input struct (lengths in m,
//! angles in **degrees**, density in kg/m³, speeds in m/s) and returning a report:
//!
//! | form | input | entry point | report |
//! | --- | --- | --- | --- |
//! | two S-curved decks (the paper's bridge form) | [`BridgeInput`] | [`bridge_report`] | [`BridgeReport`] |
//! | two straight or skew decks face to face | [`JointInput`] | [`joint_report`] | [`JointReport`] |
//! | one deck against a rigid abutment | [`AbutmentInput`] | [`abutment_report`] | [`AbutmentReport`] |
//! | generic planar rigid bodies (JSON) | [`parse_problem`] | [`problem_report`] | [`ProblemReport`] |
//!
//! Every report implements [`serde::Serialize`]; [`to_json_pretty`] writes the JSON that
//! `pounding impact --json` prints (keys sorted, non-finite numbers as `null`), and each report's
//! `summary()` the readable text. Numbers that a degenerate configuration leaves undefined are
//! `NaN` (JSON `null`). Each report says through `trustworthy()` whether its solver statuses
//! allow the numbers to be used (the command exits 1 otherwise).

pub mod bridge;
pub mod common;
pub mod joint;
pub mod problem;
pub mod shapes;

pub use bridge::{BridgeInput, BridgeReport, CurvedDeckReport, DetectionReport, bridge_report};
pub use common::{
    CornerContactReport, DelassusReport, EnergyReport, ImpulseReport, IntervalReport,
    RelativeVelocityReport, ReportError, SingleImpactReport, readable, to_json_pretty,
};
pub use joint::{JointInput, JointReport, joint_report};
pub use problem::{ProblemReport, parse_problem, problem_report};
pub use shapes::{AbutmentInput, AbutmentReport, DeckSection, ShapeSpec, abutment_report};
