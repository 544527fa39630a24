//! The sections of a `simulate` scenario file as read by `serde` (every key optional, unknown keys
//! refused, sections only as tables) and their defaults, which are the values of
//! [`DEFAULT_SCENARIO_TOML`] (the values of [`crate::sim::defaults`]; a test checks the text).

use crate::sim::defaults as d;
use crate::toml_schema::{Exact, Table};
use serde::Deserialize;

/// The built-in default scenario as commented TOML (what `pounding simulate --print-default`
/// prints, byte for byte); [`super::Scenario::default`] is this text parsed.
pub const DEFAULT_SCENARIO_TOML: &str = r#"# pounding simulate — scenario file (TOML). Every key is optional; the values below are the
# built-in defaults. Unknown keys are errors. Paths are relative to this file.
# Frame (docs/guide/model.md): x along the joint line, y normal to it pointing into deck 1;
# angles in degrees.

[decks]
# shape = "curved"  # "curved" (the S arrangement, below), "straight" (rectangles L x width) or
#                   # "skew" (parallelograms: end faces along the joint line, axis turned by
#                   # skew_deg from the joint normal); straight/skew need L1 and L2 [m]:
# L1 = 40.0         # length of deck 1 along its axis [m] (straight/skew)
# L2 = 40.0         # length of deck 2 [m] (straight/skew)
# skew_deg = 30.0   # skew angle in [0, 90) (skew)
R1 = 100.0          # centre-line radius of deck 1 [m]
R2 = 100.0          # centre-line radius of deck 2 [m]
beta1_deg = 60.0    # curve angle of deck 1 [deg]
beta2_deg = 60.0    # curve angle of deck 2 [deg]
width = 10.0        # common deck width W [m]
thickness = 0.5     # [m]
density = 2500.0    # [kg/m^3]  (1309 t per deck)

[joint]
gap = 0.05          # joint opening g [m]
seat_length = 0.4   # seat length at every deck end [m]; exceeding it = unseating
mu = 0.5            # Coulomb friction coefficient at the joint
eps_n = 0.5         # Newton restitution coefficient

# [abutments]       # optional rigid abutments beyond the far end of each deck (same mu, eps_n)
# gap1 = 0.05       # gap between deck 1's far end face and its abutment [m]
# seat_length1 = 0.4  # seat length of that end [m] (default: [joint] seat_length)
# gap2 = 0.05
# seat_length2 = 0.4

[bearings]
# One bearing at each of the 4 end-face corners of each deck (linear, same stiffness in x and y).
stiffness1 = 2.02e7 # per bearing, deck 1 [N/m]  (translational period ~0.8 s)
stiffness2 = 8.97e6 # per bearing, deck 2 [N/m]  (translational period ~1.2 s)
damping_ratio = 0.05  # Rayleigh, at each deck's two lowest distinct frequencies
# points1 = [[5.0, 0.0], [-5.0, 0.0]]  # optional custom bearing points of deck 1 [m],
#                                      # relative to its joint-face midpoint, reference pose

[ground_motion]
# A file path (PEER .AT2 in g, or .csv "t, a"), "builtin:ELC180" / "builtin:ELC270"
# (El Centro 1940, RSN 6, embedded), or "none".
record_y = "builtin:ELC180"  # acts along y (normal to the joint) for incidence 0
record_x = "builtin:ELC270"  # acts along x (along the joint)
scale_y = 1.0
scale_x = 1.0
incidence_deg = 0.0          # turns both components counter-clockwise
csv_units = "g"              # units of .csv records: "g" or "m/s2"

[time]
dt = 1e-3            # time step [s]
# duration = 53.71   # [s]; default: until the last record sample
history_every = 10   # write every n-th step to history.csv (peaks use every step)
# projection = false # rigid law: remove each step's overlap (docs/guide/simulate.md)

# [contact]          # the joint's normal contact law (docs/guide/compare.md, docs/guide/contact-laws.md)
# law = "rigid"      # rigid (Newton + Coulomb LCP, default) | kelvin | hertz | hertz-damp |
#                    # bilinear | jankowski | linear: compliance laws (trapezoid + Newton on the
#                    # forces); an unknown name is an error listing every registered law
# restitution = 0.5  # target e of the damped laws (default: [joint] eps_n)
# k = 1e10           # kelvin [N/m]; c = ... [N s/m] instead of restitution
# k_h = 2.747e10     # hertz, hertz-damp, bilinear derivation [N/m^1.5] (25 000 kip/in^1.5)
# k1 = 1.5586e10     # bilinear, all three or none (then from k_h, restitution,
# k2 = 3.1328e9      #   delta_m = 0.0254, a = 0.1)
# delta_y = 2.54e-3
# friction_velocity = 1e-3  # regularisation of Coulomb friction [m/s]
# Also: [decks] mass1 / mass2 (deck mass directly) and [bearings] damping = "dashpots"
# (c = 2 zeta m omega to the ground, x and y) instead of "rayleigh".

# ---- A whole bridge instead of two decks -------------------------------------------------
# A file with [[segment]] tables describes N >= 1 segments in a row (segment 1 at the start,
# joint k between segments k and k + 1); [decks], [joint], [abutments] and [bearings] are then
# not allowed, while [contact], [ground_motion] and [time] are as above. The chain is laid out
# along -y from the start (docs/guide/simulate.md, "Whole bridges of N segments";
# examples/viaduct-*.toml). To try it: keep only this part and uncomment it.
# [bridge]
# damping = "dashpots"      # or "rayleigh"
# damping_ratio = 0.05
# gap = 0.02                # defaults of every joint: gap [m], mu, eps_n, seat_length [m]
# mu = 0.0
# eps_n = 0.6
# seat_length = 0.4
# outer_seat_length = 0.4   # seat of an outer end without an abutment [m]
# restrainer_k = 5.0e7      # optional restrainer at every joint [N/m]; restrainer_slack [m],
# restrainer_slack = 0.03   #   restrainer_fy [N] (yield; none by default)
# restrainer_offsets = [0.0] # one cable per entry: its place across the joint from the
#                           #   face midpoints [m], positive to the left walking start -> end
# restrainer_depth = 0.0    # anchors this deep inside each segment [m] (per joint: [[joint]])
# allow_mechanism = false   # true: run segments whose bearings leave them free to slide or spin
#
# [[segment]]               # one table per segment, from the start
# shape = "straight"        # "straight" (L), "skew" (L, skew_deg) or "curved" (R, beta_deg,
# L = 30.0                  #   curve = "left" / "right"; default: alternating, left first)
# mass = 1.0e6              # optional (else width 10, thickness 0.5, density 2500)
# period_s = 1.2            # translational period on its bearings, or
#                           # bearing_stiffness = ... per bearing [N/m]
# bearing_points = [[0.0, -5.0], [0.0, 5.0], [30.0, -5.0], [30.0, 5.0]]  # optional bearing
#                           #   points [along, left] from the start-face midpoint [m] (default:
#                           #   the four corners; period_s spreads m (2 pi / T)^2 over them)
# bearing = "bilinear"      # optional yielding bearings: fy [N] (all together), b in [0, 1)
# fy = 588399.0
# b = 0.1
#
# [[segment]]
# shape = "straight"
# L = 30.0
# period_s = 0.5
#
# [[joint]]                 # optional: N - 1 tables overriding the [bridge] defaults
# gap = 0.02
# [joint.contact]           # optional: this joint's own [contact] keys, overriding the file's
# law = "hertz"             #   key by key (or contact = { law = "kelvin", k = 1e10 } above);
# k_h = 2.0e10
#                           #   a site that sets another law inherits only the [contact] keys
#                           #   its law reads; a key its law does not read is an error
#
# [abutment.start]          # optional; also [abutment.end]: gap, seat_length, mu, eps_n
# gap = 0.04
# [abutment.start.contact]  # optional: the abutment's own contact keys (as [joint.contact]);
# law = "hertz"             #   rigid and compliance sites may be mixed in one bridge
"#;

#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields)]
pub(crate) struct Raw {
    // `Table`: a section written as an array is an error (serde would read it by position).
    #[serde(default)]
    pub(crate) decks: Table<DecksSec>,
    #[serde(default)]
    pub(crate) joint: Table<JointSec>,
    #[serde(default)]
    pub(crate) bearings: Table<BearingsSec>,
    #[serde(default)]
    pub(crate) ground_motion: Table<GroundSec>,
    #[serde(default)]
    pub(crate) time: Table<TimeSec>,
    #[serde(default)]
    pub(crate) contact: Table<super::contact::ContactSec>,
    #[serde(default)]
    pub(crate) abutments: Table<AbutmentsSec>,
    /// `[fragility]` and `[[limit_state]]`: read by `pounding fragility`
    /// ([`crate::assessment::settings`]), accepted and not used here.
    #[serde(default, rename = "fragility")]
    pub(crate) _fragility: serde::de::IgnoredAny,
    #[serde(default, rename = "limit_state")]
    pub(crate) _limit_state: serde::de::IgnoredAny,
    /// `[code_check]`: read by `pounding check` ([`crate::assessment::check_input`]),
    /// accepted and not used here.
    #[serde(default, rename = "code_check")]
    pub(crate) _code_check: serde::de::IgnoredAny,
}

#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields)]
pub(crate) struct AbutmentsSec {
    pub(crate) gap1: Option<f64>,
    pub(crate) gap2: Option<f64>,
    pub(crate) seat_length1: Option<f64>,
    pub(crate) seat_length2: Option<f64>,
}

#[derive(Deserialize, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
#[allow(non_snake_case)]
pub(crate) struct DecksSec {
    pub(crate) shape: String,
    pub(crate) L1: Option<f64>,
    pub(crate) L2: Option<f64>,
    pub(crate) skew_deg: Option<f64>,
    pub(crate) R1: f64,
    pub(crate) R2: f64,
    pub(crate) beta1_deg: f64,
    pub(crate) beta2_deg: f64,
    pub(crate) width: f64,
    pub(crate) thickness: f64,
    pub(crate) density: f64,
    pub(crate) mass1: Option<f64>,
    pub(crate) mass2: Option<f64>,
}
impl Default for DecksSec {
    fn default() -> Self {
        Self {
            shape: d::SHAPE.into(),
            L1: None,
            L2: None,
            skew_deg: None,
            R1: d::RADIUS,
            R2: d::RADIUS,
            beta1_deg: d::ANGLE_DEG,
            beta2_deg: d::ANGLE_DEG,
            width: d::WIDTH,
            thickness: d::THICKNESS,
            density: d::DENSITY,
            mass1: None,
            mass2: None,
        }
    }
}

#[derive(Deserialize, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub(crate) struct JointSec {
    pub(crate) gap: f64,
    pub(crate) seat_length: f64,
    pub(crate) mu: f64,
    pub(crate) eps_n: f64,
}
impl Default for JointSec {
    fn default() -> Self {
        Self {
            gap: d::GAP,
            seat_length: d::SEAT_LENGTH,
            mu: d::MU,
            eps_n: d::EPS_N,
        }
    }
}

#[derive(Deserialize, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub(crate) struct BearingsSec {
    pub(crate) stiffness1: f64,
    pub(crate) stiffness2: f64,
    pub(crate) damping_ratio: f64,
    pub(crate) points1: Option<Vec<Exact<2>>>,
    pub(crate) points2: Option<Vec<Exact<2>>>,
    pub(crate) damping: String,
    /// Accept a bearing layout that leaves a deck free to slide or spin (a zero natural
    /// frequency: a mechanism); refused by default.
    pub(crate) allow_mechanism: bool,
}
impl Default for BearingsSec {
    fn default() -> Self {
        Self {
            stiffness1: d::BEARING_STIFFNESS[0],
            stiffness2: d::BEARING_STIFFNESS[1],
            damping_ratio: d::DAMPING_RATIO,
            points1: None,
            points2: None,
            damping: d::DAMPING.into(),
            allow_mechanism: false,
        }
    }
}

#[derive(Deserialize, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub(crate) struct GroundSec {
    pub(crate) record_y: String,
    pub(crate) record_x: String,
    pub(crate) scale_y: f64,
    pub(crate) scale_x: f64,
    pub(crate) incidence_deg: f64,
    pub(crate) csv_units: String,
    pub(crate) record_dt: Option<f64>,
    /// Wave passage: apparent velocity \[m/s\] (bridge files).
    pub(crate) v_app: Option<f64>,
    /// Wave passage: direction of travel \[°\] (bridge files).
    pub(crate) wave_direction_deg: Option<f64>,
    /// A motion per support: a support-motion file acting along y / x (bridge files).
    pub(crate) supports_y: Option<String>,
    pub(crate) supports_x: Option<String>,
}
impl Default for GroundSec {
    fn default() -> Self {
        Self {
            record_y: d::RECORDS[0].into(),
            record_x: d::RECORDS[1].into(),
            scale_y: 1.0,
            scale_x: 1.0,
            incidence_deg: 0.0,
            csv_units: d::CSV_UNITS.into(),
            record_dt: None,
            v_app: None,
            wave_direction_deg: None,
            supports_y: None,
            supports_x: None,
        }
    }
}

#[derive(Deserialize, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub(crate) struct TimeSec {
    pub(crate) dt: f64,
    pub(crate) duration: Option<f64>,
    pub(crate) history_every: i64,
    /// Position projection of the rigid sites ([`crate::sim::projection`]).
    pub(crate) projection: bool,
}
impl Default for TimeSec {
    fn default() -> Self {
        Self {
            dt: d::DT,
            duration: None,
            history_every: d::HISTORY_EVERY,
            projection: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The commented default scenario shows the values of `sim::defaults`, which an omitted key
    /// takes.
    #[test]
    fn default_scenario_text_shows_the_defaults() {
        let raw: Raw = toml::from_str(DEFAULT_SCENARIO_TOML).unwrap();
        let (dk, j, b) = (&raw.decks.0, &raw.joint.0, &raw.bearings.0);
        let (g, t) = (&raw.ground_motion.0, &raw.time.0);
        let two = |x: f64| (x, x);
        assert_eq!((dk.R1, dk.R2), two(d::RADIUS));
        assert_eq!((dk.beta1_deg, dk.beta2_deg), two(d::ANGLE_DEG));
        let dims = (dk.width, dk.thickness, dk.density);
        assert_eq!(dims, (d::WIDTH, d::THICKNESS, d::DENSITY));
        let joint = (j.gap, j.seat_length, j.mu, j.eps_n);
        assert_eq!(joint, (d::GAP, d::SEAT_LENGTH, d::MU, d::EPS_N));
        assert_eq!([b.stiffness1, b.stiffness2], d::BEARING_STIFFNESS);
        assert_eq!(b.damping_ratio, d::DAMPING_RATIO);
        assert_eq!([g.record_y.as_str(), g.record_x.as_str()], d::RECORDS);
        assert_eq!(g.csv_units, d::CSV_UNITS);
        assert_eq!((t.dt, t.history_every), (d::DT, d::HISTORY_EVERY));
        let dflt = Raw::default();
        assert_eq!(format!("{:?}", raw.decks), format!("{:?}", dflt.decks));
        assert_eq!(format!("{:?}", raw.joint), format!("{:?}", dflt.joint));
        assert_eq!(
            format!("{:?}", raw.bearings),
            format!("{:?}", dflt.bearings)
        );
        assert_eq!(
            format!("{:?}", raw.ground_motion),
            format!("{:?}", dflt.ground_motion)
        );
        assert_eq!(format!("{:?}", raw.time), format!("{:?}", dflt.time));
    }
}
