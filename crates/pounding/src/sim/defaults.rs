//! Every default value of the simulator's inputs, in one place: the built-in two-deck model
//! ([`super::SimModel::default_bridge`]), the keys a `simulate` scenario omits (the two-deck
//! sections and a bridge's `[bridge]` and `[[segment]]` tables) and [`super::SimSettings`]. The
//! commented scenario [`super::scenario::DEFAULT_SCENARIO_TOML`] shows the same values (a test
//! checks that it parses to them).

use crate::math::Real;

/// Deck width `W` \[m\] (both forms).
pub const WIDTH: Real = 10.0;
/// Deck thickness `t` \[m\].
pub const THICKNESS: Real = 0.5;
/// Deck density `ρ` \[kg/m³\].
pub const DENSITY: Real = 2500.0;
/// Centre-line radius of a curved deck `R` \[m\] (two-deck form).
pub const RADIUS: Real = 100.0;
/// Curve angle of a curved deck `β` \[°\] (two-deck form).
pub const ANGLE_DEG: Real = 60.0;
/// The shape of the two decks.
pub const SHAPE: &str = "curved";
/// Bearing stiffness of each of the 4 corner bearings of deck 1 and deck 2 \[N/m\] (two-deck
/// form; translational periods about 0.8 s and 1.2 s).
pub const BEARING_STIFFNESS: [Real; 2] = [2.02e7, 8.97e6];
/// The bearings' damping ratio `ζ`.
pub const DAMPING_RATIO: Real = 0.05;
/// The damping model (`rayleigh` or `dashpots`).
pub const DAMPING: &str = "rayleigh";
/// Joint gap `g` \[m\].
pub const GAP: Real = 0.05;
/// Seat length of every deck end \[m\].
pub const SEAT_LENGTH: Real = 0.4;
/// Seat length of a bridge's outer end without an abutment \[m\].
pub const OUTER_SEAT_LENGTH: Real = 0.4;
/// Coulomb friction coefficient `μ` of a joint.
pub const MU: Real = 0.5;
/// Newton restitution coefficient `ε_N` of a joint.
pub const EPS_N: Real = 0.5;
/// The ground-motion records along y and x.
pub const RECORDS: [&str; 2] = ["builtin:ELC180", "builtin:ELC270"];
/// The units of `.csv` records.
pub const CSV_UNITS: &str = "g";
/// Time step `dt` \[s\].
pub const DT: Real = 1e-3;
/// A scenario's `[time] history_every`: every n-th step is kept in the histories.
pub const HISTORY_EVERY: i64 = 10;
/// [`super::SimSettings::history_stride`] of a run built in code (every step kept).
pub const HISTORY_STRIDE: usize = 1;
/// `θ` of the smooth part (the trapezoidal rule).
pub const THETA: Real = 0.5;
/// The approach velocity above which a contact's impulse counts as an impact \[m/s\].
pub const IMPACT_VELOCITY: Real = 1e-3;
