//! Bridge scenarios: a `simulate` file with `[[segment]]` tables describes a whole bridge of
//! `N ≥ 1` segments ([`crate::sim::bridge`]) instead of the two decks of `[decks]`.
//!
//! ```toml
//! [bridge]                  # shared settings and the defaults of every joint
//! damping = "rayleigh"      # or "dashpots" (c = 2 zeta m omega to the ground, x and y)
//! damping_ratio = 0.05
//! gap = 0.05                # joint defaults: gap [m], mu, eps_n, seat_length [m]
//! outer_seat_length = 0.4   # an outer end without an abutment rests on a pier seat this long
//!
//! [[segment]]               # segment 1 (at the start); one table per segment, in order
//! shape = "straight"        # "straight" (L), "skew" (L, skew_deg) or "curved" (R, beta_deg)
//! L = 30.0
//! mass = 1.0e6              # optional, else density x volume
//! period_s = 1.2            # bearings with k = m (2 pi / T)^2 / n each (n bearings), or
//! # bearing_stiffness = 1e7 # the stiffness of each bearing [N/m]
//! # bearing_points = [[0.0, -5.0], [30.0, 5.0]]  # [along, left] from the start-face midpoint
//! #                         # [m] (BridgeModel::segment_point); default: the four corners
//!
//! [[joint]]                 # joint 1, between segments 1 and 2 (none given: all defaults)
//! gap = 0.02
//! restrainer_k = 5e7        # restrainer cables (also [bridge] defaults): k [N/m] per cable,
//! restrainer_offsets = [-3.0, 3.0]  # one cable per offset across the joint [m] (default [0]),
//! restrainer_depth = 0.5    # anchors inside each segment [m] (RestrainerSpec)
//!
//! [joint.contact]           # optional: joint 1's own contact keys (or, inside [[joint]],
//! k_h = 2.0e10              #   contact = { law = "hertz-damp", k_h = 2e10 })
//!
//! [abutment.start]          # optional; also [abutment.end]
//! gap = 0.04
//!
//! [abutment.start.contact]  # optional: the abutment's own contact keys
//! law = "kelvin"
//! k = 5.0e9
//! ```
//!
//! `[contact]`, `[ground_motion]` and `[time]` are those of the two-deck file. The `[contact]`
//! section is the default contact of every joint and abutment; a site's own `contact` table
//! (the keys of `[contact]`) overrides it key by key: a site that sets only `k_h` keeps the
//! file's law and its other keys; a site that sets another `law` inherits only the `[contact]`
//! keys that its law reads. A key of a site table that the site's law does not read is an error
//! naming `joint[k].contact.KEY` (`abutment.end.contact.KEY`) and its line, as is an unknown key;
//! a `[contact]` key that no site's law reads is refused as for two decks. Rigid contact at some
//! sites and compliance laws at others run together (`crate::sim::mixed`).
//! A law override (`pounding simulate --law`, `pounding compare`) replaces the law at every
//! site; the site's other keys apply when that law reads them. A compliance law at an abutment
//! is built with the segment's mass as the effective mass (calibrations), at a joint with the
//! two segments' masses.

use super::build::{build_ground, build_settings};
use super::contact::{FileKeys, build_contact, check_contact_keys};
use super::sections::{GroundSec, TimeSec};
use super::site_contact::{SiteContact, SiteTable, resolve};
use super::{KeyRef, Scenario, ScenarioError};

use crate::math::Real;
use crate::output::float_token;
use crate::shape::{Deck, DeckShape, SkewedDeck, StraightDeck};
use crate::sim::bridge::{
    BearingYield, BridgeAbutment, BridgeModel, BridgeProblem, Joint, RestrainerSpec, Segment,
};
use crate::sim::defaults;
use crate::sim::excitation::SupportExcitation;
use crate::sim::param::{BridgeTable, ParamPath};
use crate::sim::{DampingModel, JointContact};
use crate::toml_schema::{Table, line_col};
use serde::Deserialize;
use toml::Spanned;

mod backwall;
mod pier;
mod segment;
mod sites;
use pier::PierSec;
use segment::*;
use sites::*;

type Sp<T> = Option<Spanned<T>>;

/// A bridge scenario file as read by `serde`.
#[derive(Deserialize, Clone, Debug)]
#[serde(deny_unknown_fields)]
pub(crate) struct BridgeRaw {
    #[serde(default)]
    bridge: Table<BridgeSec>,
    segment: Vec<Spanned<SegmentSec>>,
    #[serde(default)]
    joint: Vec<Spanned<JointSec>>,
    #[serde(default)]
    abutment: Table<AbutmentTables>,
    #[serde(default)]
    pier: Vec<Spanned<PierSec>>,
    #[serde(default)]
    pub(crate) ground_motion: Table<GroundSec>,
    #[serde(default)]
    pub(crate) time: Table<TimeSec>,
    #[serde(default)]
    pub(crate) contact: Table<super::contact::ContactSec>,
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
    /// `[hazard]`: the site hazard curve of `pounding fragility` and `pounding design`
    /// ([`crate::assessment::hazard_input`]), accepted and not used here.
    #[serde(default, rename = "hazard")]
    pub(crate) _hazard: serde::de::IgnoredAny,
}

#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
struct BridgeSec {
    damping: Sp<String>,
    damping_ratio: Sp<f64>,
    outer_seat_length: Sp<f64>,
    gap: Sp<f64>,
    mu: Sp<f64>,
    eps_n: Sp<f64>,
    seat_length: Sp<f64>,
    restrainer_k: Sp<f64>,
    restrainer_slack: Sp<f64>,
    restrainer_fy: Sp<f64>,
    restrainer_offsets: Sp<Vec<f64>>,
    restrainer_depth: Sp<f64>,
    allow_mechanism: Sp<bool>,
}

#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
#[allow(non_snake_case)]
struct SegmentSec {
    shape: Sp<String>,
    L: Sp<f64>,
    skew_deg: Sp<f64>,
    R: Sp<f64>,
    beta_deg: Sp<f64>,
    curve: Sp<String>,
    width: Sp<f64>,
    thickness: Sp<f64>,
    density: Sp<f64>,
    mass: Sp<f64>,
    period_s: Sp<f64>,
    bearing_stiffness: Sp<f64>,
    bearing_points: Sp<Vec<Vec<f64>>>,
    bearing: Sp<String>,
    fy: Sp<f64>,
    b: Sp<f64>,
    bearing_damping: Sp<f64>,
}

#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
struct JointSec {
    gap: Sp<f64>,
    mu: Sp<f64>,
    eps_n: Sp<f64>,
    seat_length: Sp<f64>,
    restrainer_k: Sp<f64>,
    restrainer_slack: Sp<f64>,
    restrainer_fy: Sp<f64>,
    restrainer_offsets: Sp<Vec<f64>>,
    restrainer_depth: Sp<f64>,
    /// The joint's own contact keys (`[joint.contact]`).
    contact: Option<Spanned<SiteTable>>,
}

#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
struct AbutmentTables {
    start: Option<Spanned<AbutmentSec>>,
    end: Option<Spanned<AbutmentSec>>,
}

#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
struct AbutmentSec {
    gap: Sp<f64>,
    seat_length: Sp<f64>,
    mu: Sp<f64>,
    eps_n: Sp<f64>,
    /// The abutment's own contact keys (`[abutment.start.contact]`).
    contact: Option<Spanned<SiteTable>>,
    /// Its backwall (`[abutment.start.backwall]`).
    backwall: Option<Spanned<backwall::BackwallSec>>,
    /// Its exterior shear keys (`[abutment.start.shear_keys]`).
    shear_keys: Option<Spanned<backwall::ShearKeysSec>>,
}

/// The run of a bridge scenario.
pub type BridgeSetup = super::RunSetup<BridgeProblem>;

/// Reads the value of `v` or the default `d`, with the key's line for errors.
struct Val<'a> {
    origin: &'a str,
    text: &'a str,
}

impl Val<'_> {
    fn line(&self, s: &Spanned<impl Sized>) -> usize {
        line_col(self.text, s.span().start).0
    }
    fn err(&self, key: String, line: Option<usize>, message: String) -> ScenarioError {
        ScenarioError::Invalid {
            message,
            at: vec![KeyRef::path(key, self.origin, line)],
            note: String::new(),
        }
    }
    /// [`Val::num`] of a value that must be `> 0`.
    fn pos(&self, key: String, x: &Sp<f64>, d: Option<f64>) -> Result<f64, ScenarioError> {
        self.num(key, x, d, positive, "must be > 0")
    }
    /// [`Val::num`] of a deck dimension (1 mm … 100 km).
    fn dim(&self, key: String, x: &Sp<f64>, d: Option<f64>) -> Result<f64, ScenarioError> {
        self.num(key, x, d, dimension, "must lie in [1e-3, 1e5] m")
    }
    /// [`Val::num`] of a seat length (above 0, at most 1 km).
    fn seat(&self, key: String, x: &Sp<f64>, d: Option<f64>) -> Result<f64, ScenarioError> {
        self.num(key, x, d, |x| x > 0.0 && x <= 1e3, "must lie in (0, 1e3] m")
    }
    /// [`Val::num`] of a gap (0 … 1 km).
    fn gap(&self, key: String, x: &Sp<f64>, d: Option<f64>) -> Result<f64, ScenarioError> {
        self.num(key, x, d, short, "must lie in [0, 1e3] m")
    }
    /// [`Val::num`] of a value that must be `>= 0`.
    fn nonneg(&self, key: String, x: &Sp<f64>, d: Option<f64>) -> Result<f64, ScenarioError> {
        self.num(key, x, d, non_negative, "must be >= 0")
    }
    /// [`Val::num`] of a value in `[0, 1]`.
    fn unit(&self, key: String, x: &Sp<f64>, d: Option<f64>) -> Result<f64, ScenarioError> {
        self.num(key, x, d, unit, "must lie in [0, 1]")
    }

    /// `v` (or `default`), which must satisfy `ok`.
    fn num(
        &self,
        key: String,
        v: &Sp<f64>,
        default: Option<f64>,
        ok: impl Fn(f64) -> bool,
        reason: &str,
    ) -> Result<f64, ScenarioError> {
        let (x, line) = match (v, default) {
            (Some(s), _) => (*s.get_ref(), Some(self.line(s))),
            (None, Some(d)) => (d, None),
            (None, None) => {
                return Err(self.err(key.clone(), None, format!("{key} is required")));
            }
        };
        if x.is_finite() && ok(x) {
            return Ok(x);
        }
        let reason = if x.is_finite() {
            reason.to_string()
        } else {
            crate::sim::finite_reason(reason)
        };
        Err(self.err(
            key.clone(),
            line,
            format!("invalid {key} = {}: {reason}", float_token(x)),
        ))
    }
}

fn positive(x: f64) -> bool {
    x > 0.0
}
/// A deck dimension between 1 mm and 100 km (beyond, the layout's absolute coordinates lose the
/// millimetres that gaps are made of).
fn dimension(x: f64) -> bool {
    (1e-3..=1e5).contains(&x)
}
/// A gap or seat length below 1 km.
fn short(x: f64) -> bool {
    (0.0..=1e3).contains(&x)
}
fn non_negative(x: f64) -> bool {
    x >= 0.0
}
fn unit(x: f64) -> bool {
    (0.0..=1.0).contains(&x)
}

/// [`Scenario::build_bridge`].
pub(super) fn build(sc: &Scenario, raw: &BridgeRaw) -> Result<BridgeSetup, ScenarioError> {
    let v = Val {
        origin: &sc.src.origin,
        text: &sc.src.text,
    };
    let b = &raw.bridge;
    let bk = |k: &str| format!("bridge.{k}");
    let damping_ratio = v.num(
        bk("damping_ratio"),
        &b.damping_ratio,
        Some(defaults::DAMPING_RATIO),
        |x| (0.0..1.0).contains(&x),
        "must lie in [0, 1)",
    )?;
    let damping_model = match b
        .damping
        .as_ref()
        .map(|s| (s.get_ref().as_str(), v.line(s)))
    {
        None | Some(("rayleigh", _)) => DampingModel::Rayleigh,
        Some(("dashpots", _)) => DampingModel::TranslationalDashpots,
        Some((other, line)) => {
            return Err(v.err(
                bk("damping"),
                Some(line),
                format!("invalid bridge.damping {other:?}: use \"rayleigh\" or \"dashpots\""),
            ));
        }
    };
    let outer = Some(defaults::OUTER_SEAT_LENGTH);
    let outer_seat_length = v.seat(bk("outer_seat_length"), &b.outer_seat_length, outer)?;
    let d_gap = v.gap(bk("gap"), &b.gap, Some(defaults::GAP))?;
    let d_mu = v.nonneg(bk("mu"), &b.mu, Some(defaults::MU))?;
    let d_eps = v.unit(bk("eps_n"), &b.eps_n, Some(defaults::EPS_N))?;
    let d_seat = v.seat(
        bk("seat_length"),
        &b.seat_length,
        Some(defaults::SEAT_LENGTH),
    )?;
    if raw.segment.is_empty() {
        // `segment = []`: name the line that says so
        let line = crate::toml_schema::line_of_key(v.text, "", "segment");
        return Err(v.err(
            "segment".into(),
            line,
            "a bridge needs at least one [[segment]] (this list is empty)".into(),
        ));
    }
    let n = raw.segment.len();
    let mut segments = Vec::with_capacity(n);
    let curves = default_curves(raw.segment.iter().map(|s| s.get_ref()));
    for (i, s) in raw.segment.iter().enumerate() {
        segments.push(segment(&v, i, s.get_ref(), curves[i])?);
    }
    let nj = n - 1;
    if nj == 0 {
        no_joint_keys(&v, &raw.bridge)?;
    }
    if !raw.joint.is_empty() && raw.joint.len() != nj {
        let line = raw.joint.get(nj).map(|j| v.line(j));
        return Err(v.err(
            "joint".into(),
            line.or(raw.joint.first().map(|j| v.line(j))),
            format!(
                "{n} segments have {nj} joints, but {} [[joint]] tables are given (give none to use \
                 the [bridge] defaults for every joint)",
                raw.joint.len()
            ),
        ));
    }
    let masses: Vec<Real> = segments
        .iter()
        .map(|s: &Segment| s.shape.mass_properties().mass)
        .collect();
    let defaults = JointDefaults {
        gap: d_gap,
        mu: d_mu,
        eps_n: d_eps,
        seat_length: d_seat,
    };
    let (joints, abutments) = sites(sc, &v, raw, &masses, &defaults)?;
    let piers = pier::piers(&v, &raw.pier, nj)?;
    let model = BridgeModel {
        segments,
        joints,
        abutments,
        outer_seat_length,
        damping_ratio,
        damping_model,
        piers,
    };
    let (ground, records, units) = build_ground(sc)?;
    let ids: Vec<String> = model.support_lines().into_iter().map(|l| l.id).collect();
    let (ground, supports) = super::supports::build_supports(sc, &ids, ground)?;
    let records = match &supports {
        SupportExcitation::Records(_) => super::supports::support_files(sc),
        _ => records,
    };
    if supports != SupportExcitation::Uniform {
        // what the supports' own motions do not reach yet, named before the run
        crate::sim::integrate::check_apart(&model).map_err(|e| model_error(&v, raw, e))?;
        super::supports::check_motion(sc, &model, &ground, &supports)?;
    }
    // a pier's cap holds fewer values a row (2 coordinates, 2 rates, 4 in piers.csv) than a
    // segment: the memory estimate counts each as one more segment
    let size = crate::sim::options::RunSize {
        segments: model.segments.len() + model.piers.len(),
        bearings: model.segments.iter().map(|s| s.bearings.len()).sum(),
    };
    let settings = build_settings(sc, &ground, &records, size, || {
        model.validate().map_err(|e| model_error(&v, raw, e))?;
        check_mechanism(&v, raw, &model)
    })?;
    // the step the restrainers and backwalls need: said at `[time] dt` (or `--dt`)
    model
        .check_time_step(settings.dt)
        .map_err(|e| sc.src.invalid(e.to_string(), super::model_keys::time("dt")))?;
    Ok(BridgeSetup {
        problem: BridgeProblem {
            supports,
            ..BridgeProblem::at_rest(model, ground)
        },
        settings,
        records,
        units,
    })
}
