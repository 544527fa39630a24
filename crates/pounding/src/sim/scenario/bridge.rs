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
//! sites and compliance laws at others is refused, naming the site's `contact.law` and its line.
//! A law override (`pounding simulate --law`, `pounding compare`) replaces the law at every
//! site; the site's other keys apply when that law reads them. A compliance law at an abutment
//! is built with the segment's mass as the effective mass (calibrations), at a joint with the
//! two segments' masses.

use super::build::{build_ground, build_settings};
use super::contact::{FileKeys, build_contact, check_contact_keys};
use super::sections::{GroundSec, TimeSec};
use super::site_contact::{SiteContact, SiteTable, resolve};
use super::{Scenario, ScenarioError};
use crate::ground_motion::AccelUnits;
use crate::math::Real;
use crate::output::float_token;
use crate::shape::{Deck, DeckShape, SkewedDeck, StraightDeck};
use crate::sim::bridge::{
    BearingYield, BridgeAbutment, BridgeModel, BridgeProblem, Joint, RestrainerSpec, Segment,
};
use crate::sim::{DampingModel, JointContact, SimSettings, simulate};
use crate::toml_schema::{Table, line_col};
use serde::Deserialize;
use toml::Spanned;

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
}

/// What [`Scenario::build_bridge`] returns: the problem and settings of
/// [`crate::sim::bridge::simulate`] and what the records were.
#[derive(Debug, Clone)]
pub struct BridgeSetup {
    /// The bridge, its ground motion, at rest.
    pub problem: BridgeProblem,
    /// Step, duration, history stride.
    pub settings: SimSettings,
    /// The records used `[record_y, record_x]` as written.
    pub records: [String; 2],
    /// Units of CSV records.
    pub units: AccelUnits,
}

impl BridgeSetup {
    /// Runs it.
    pub fn run(&self) -> Result<crate::sim::bridge::BridgeSolution, crate::sim::SimError> {
        simulate(&self.problem, &self.settings)
    }
}

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
        ScenarioError::Bridge {
            message,
            key,
            origin: self.origin.to_string(),
            line,
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
            Ok(x)
        } else {
            Err(self.err(
                key.clone(),
                line,
                format!("invalid {key} = {}: {reason}", float_token(x)),
            ))
        }
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
        Some(0.05),
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
    let outer_seat_length = v.seat(bk("outer_seat_length"), &b.outer_seat_length, Some(0.4))?;
    let d_gap = v.gap(bk("gap"), &b.gap, Some(0.05))?;
    let d_mu = v.nonneg(bk("mu"), &b.mu, Some(0.5))?;
    let d_eps = v.unit(bk("eps_n"), &b.eps_n, Some(0.5))?;
    let d_seat = v.seat(bk("seat_length"), &b.seat_length, Some(0.4))?;
    if raw.segment.is_empty() {
        // `segment = []`: name the line that says so
        let line = v
            .text
            .lines()
            .position(|l| {
                let l = l.trim_start();
                l.strip_prefix("segment")
                    .is_some_and(|r| r.trim_start().starts_with('='))
            })
            .map(|k| k + 1);
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
    let model = BridgeModel {
        segments,
        joints,
        abutments,
        outer_seat_length,
        damping_ratio,
        damping_model,
    };
    let (ground, records, units) = build_ground(sc)?;
    let settings = build_settings(sc, &ground, &records, model.segments.len(), || {
        model.validate().map_err(|e| model_error(&v, raw, e))?;
        check_mechanism(&v, raw, &model)
    })?;
    model
        .check_time_step(settings.dt)
        .map_err(|e| ScenarioError::Invalid {
            message: e.to_string(),
            at: vec![sc.src.at(super::ParamKey::new(super::Section::Time, "dt"))],
            note: String::new(),
        })?;
    Ok(BridgeSetup {
        problem: BridgeProblem::at_rest(model, ground),
        settings,
        records,
        units,
    })
}

/// A bridge of one segment has no joint: the `[bridge]` restrainer keys would be ignored, so
/// they are refused.
fn no_joint_keys(v: &Val, rb: &BridgeSec) -> Result<(), ScenarioError> {
    let lone = [
        (&rb.restrainer_k, "restrainer_k"),
        (&rb.restrainer_slack, "restrainer_slack"),
        (&rb.restrainer_fy, "restrainer_fy"),
        (&rb.restrainer_depth, "restrainer_depth"),
    ]
    .into_iter()
    .find_map(|(x, k)| x.as_ref().map(|x| (v.line(x), k)))
    .or(rb
        .restrainer_offsets
        .as_ref()
        .map(|x| (v.line(x), "restrainer_offsets")));
    if let Some((line, key)) = lone {
        return Err(v.err(
            format!("bridge.{key}"),
            Some(line),
            format!("bridge.{key} is not used: a bridge of one segment has no joint to restrain"),
        ));
    }
    Ok(())
}

/// The `[bridge]` defaults of every joint (and abutment).
struct JointDefaults {
    gap: f64,
    mu: f64,
    eps_n: f64,
    seat_length: f64,
}

/// The joints (`[[joint]]` tables or the defaults) and the abutments of a bridge scenario;
/// `masses` of the segments (for the contact-law calibrations).
fn sites(
    sc: &Scenario,
    v: &Val,
    raw: &BridgeRaw,
    masses: &[Real],
    d: &JointDefaults,
) -> Result<(Vec<Joint>, [Option<BridgeAbutment>; 2]), ScenarioError> {
    let n = masses.len();
    let nj = n - 1;
    let contacts = site_contacts(sc, raw, nj)?;
    let mut kinds = Vec::new();
    let mut contact_for = |c: &SiteContact, eps_n: f64, m: [f64; 2]| {
        let built = if c.own_keys() {
            build_contact(c, &c.sec, None, eps_n, m)?
        } else {
            build_contact(
                &FileKeys(&sc.src),
                &sc.raw.contact,
                sc.law.as_deref(),
                eps_n,
                m,
            )?
        };
        kinds.push(matches!(built, JointContact::Rigid));
        Ok::<_, ScenarioError>(built)
    };
    let mut joints = Vec::with_capacity(nj);
    for k in 0..nj {
        let none = JointSec::default();
        let j = raw.joint.get(k).map_or(&none, |j| j.get_ref());
        let jk = |key: &str| format!("joint[{k}].{key}");
        let gap = v.gap(jk("gap"), &j.gap, Some(d.gap))?;
        let friction = v.nonneg(jk("mu"), &j.mu, Some(d.mu))?;
        let restitution = v.unit(jk("eps_n"), &j.eps_n, Some(d.eps_n))?;
        let seat_length = v.seat(jk("seat_length"), &j.seat_length, Some(d.seat_length))?;
        let restrainers = restrainer(v, k, j, &raw.bridge)?;
        joints.push(Joint {
            gap,
            friction,
            restitution,
            seat_length,
            contact: contact_for(&contacts[k], restitution, [masses[k], masses[k + 1]])?,
            restrainers,
        });
    }
    let mut abutments = [None, None];
    let mut next = nj;
    for (side, (name, a)) in [("start", &raw.abutment.start), ("end", &raw.abutment.end)]
        .into_iter()
        .enumerate()
    {
        let Some(a) = a else { continue };
        let a = a.get_ref();
        let ak = |key: &str| format!("abutment.{name}.{key}");
        let restitution = v.unit(ak("eps_n"), &a.eps_n, Some(d.eps_n))?;
        // a rigid wall: the two-body calibrations see the segment's mass (m_eff = 2m·2m/4m = m)
        let m = masses[if side == 0 { 0 } else { n - 1 }];
        abutments[side] = Some(BridgeAbutment {
            gap: v.gap(ak("gap"), &a.gap, Some(d.gap))?,
            seat_length: v.seat(ak("seat_length"), &a.seat_length, Some(d.seat_length))?,
            friction: v.nonneg(ak("mu"), &a.mu, Some(d.mu))?,
            restitution,
            contact: contact_for(&contacts[next], restitution, [2.0 * m, 2.0 * m])?,
        });
        next += 1;
    }
    Ok((joints, abutments))
}

/// The contact of every site (joints, then the abutments given), with the keys of its own
/// `contact` table checked: unknown keys and types, then the `[contact]` keys that no site's
/// law reads, then the site keys that its law (or no compared law) reads.
fn site_contacts<'a>(
    sc: &'a Scenario,
    raw: &BridgeRaw,
    nj: usize,
) -> Result<Vec<SiteContact<'a>>, ScenarioError> {
    let law = sc.law.as_deref();
    let none = JointSec::default();
    let mut out = Vec::new();
    for k in 0..nj {
        let j = raw.joint.get(k).map_or(&none, |j| j.get_ref());
        let table = j.contact.as_ref();
        out.push(resolve(
            &sc.src,
            &sc.raw.contact,
            law,
            format!("joint[{k}]"),
            table,
        )?);
    }
    for (name, a) in [("start", &raw.abutment.start), ("end", &raw.abutment.end)] {
        if let Some(a) = a {
            let table = a.get_ref().contact.as_ref();
            let site = format!("abutment.{name}");
            out.push(resolve(&sc.src, &sc.raw.contact, law, site, table)?);
        }
    }
    let mut in_use: Vec<&str> = Vec::new();
    for c in &out {
        if !in_use.contains(&c.law.as_str()) {
            in_use.push(&c.law);
        }
    }
    if sc.law_replaced {
        // `--law`: keys its law does not read are not used (unknown keys were refused above)
        return Ok(out);
    }
    match (&sc.compared, in_use.as_slice()) {
        (None, [l]) if *l == sc.law() => sc.check_contact_keys()?,
        (None, []) => {
            let contact_key = super::contact::section_keys()
                .iter()
                .copied()
                .filter(|&k| k != "law")
                .find(|k| super::contact::given(&sc.raw.contact, k));
            if let Some(key) = contact_key {
                return Err(sc.src.key_error(
                    format!(
                        "[contact] {key} is not used: this bridge has no joints and no abutments \
                         (no contact)"
                    ),
                    &[super::ParamKey::new(super::Section::Contact, key)],
                ));
            }
        }
        (None, _) => check_contact_keys(
            &sc.src,
            &sc.raw.contact,
            &in_use,
            Some("the laws of this bridge's joints and abutments"),
        )?,
        _ => sc.check_contact_keys()?,
    }
    let compared: Option<Vec<&str>> = sc
        .compared
        .as_ref()
        .map(|l| l.iter().map(String::as_str).collect());
    for c in &out {
        match &compared {
            Some(list) => c.check_keys(list, true)?,
            None => c.check_keys(&[c.law.as_str()], false)?,
        }
    }
    Ok(out)
}

/// A segment whose bearings leave it free to slide or spin (lowest natural frequency zero, or
/// below `1e-6` of its highest: a singular bearing stiffness, e.g. a single bearing point) is an
/// error naming the segment's bearing key, unless
/// `[bridge] allow_mechanism = true`.
fn check_mechanism(v: &Val, raw: &BridgeRaw, model: &BridgeModel) -> Result<(), ScenarioError> {
    if raw
        .bridge
        .allow_mechanism
        .as_ref()
        .is_some_and(|a| *a.get_ref())
    {
        return Ok(());
    }
    let freqs = model
        .segment_frequencies()
        .map_err(|e| model_error(v, raw, e))?;
    for (i, w) in freqs.iter().enumerate() {
        if w[0] > 1e-6 * w[2] {
            continue;
        }
        let t = raw.segment[i].get_ref();
        let (key, line) = match (&t.bearing_points, &t.period_s, &t.bearing_stiffness) {
            (Some(p), _, _) => ("bearing_points", v.line(p)),
            (None, Some(p), _) => ("period_s", v.line(p)),
            (None, None, Some(p)) => ("bearing_stiffness", v.line(p)),
            _ => ("bearing_points", v.line(&raw.segment[i])),
        };
        return Err(v.err(
            format!("segment[{i}].{key}"),
            Some(line),
            format!(
                "segment[{i}]: its bearings leave it free to slide or spin (a mechanism: a natural \
                 frequency of zero); give bearing points that hold it in x, y and rotation (at \
                 least two distinct points), or set bridge.allow_mechanism = true to simulate it \
                 anyway"
            ),
        ));
    }
    Ok(())
}

/// The line of `key` where `[[segment]]` table `t` writes it (`None`: not written there).
fn segment_key_line(v: &Val, t: &SegmentSec, key: &str) -> Option<usize> {
    let num = |x: &Sp<f64>| x.as_ref().map(|x| v.line(x));
    let text = |x: &Sp<String>| x.as_ref().map(|x| v.line(x));
    match key {
        "shape" => text(&t.shape),
        "L" => num(&t.L),
        "skew_deg" => num(&t.skew_deg),
        "R" => num(&t.R),
        "beta_deg" => num(&t.beta_deg),
        "curve" => text(&t.curve),
        "width" => num(&t.width),
        "thickness" => num(&t.thickness),
        "density" => num(&t.density),
        "mass" => num(&t.mass),
        "period_s" => num(&t.period_s),
        "bearing_stiffness" => num(&t.bearing_stiffness),
        "bearing_points" => t.bearing_points.as_ref().map(|x| v.line(x)),
        "bearing" => text(&t.bearing),
        "fy" => num(&t.fy),
        "b" => num(&t.b),
        _ => None,
    }
}

/// A model error (named `segment[i].key`, `joint[k].key`, `abutment.side.key`, `bridge.key`) with
/// the line of that key, or of its table when the key is not written there.
fn model_error(v: &Val, raw: &BridgeRaw, e: crate::sim::SimError) -> ScenarioError {
    use crate::sim::SimError;
    let (name, message) = match &e {
        SimError::InvalidParameter { name, .. } | SimError::InvalidArgument { name, .. } => {
            (name.clone(), e.to_string())
        }
        _ => return ScenarioError::Model(Box::new(e)),
    };
    let index = |prefix: &str| -> Option<usize> {
        let rest = name.strip_prefix(prefix)?;
        rest.split(']').next()?.parse().ok()
    };
    let line = if let Some(i) = index("segment[") {
        let seg = raw.segment.get(i);
        let key = name.rsplit('.').next().unwrap_or_default();
        let own = seg.and_then(|t| segment_key_line(v, t.get_ref(), key));
        own.or(seg.map(|t| v.line(t)))
    } else if let Some(k) = index("joint[") {
        // faces of different widths: the `width` of the segment after the joint (or before it),
        // else that segment's table; other joint keys: the joint's table
        let width = |i: usize| {
            raw.segment
                .get(i)
                .and_then(|t| t.get_ref().width.as_ref().map(|w| v.line(w)))
        };
        if name.ends_with(".width") {
            width(k + 1)
                .or_else(|| width(k))
                .or_else(|| raw.segment.get(k + 1).map(|t| v.line(t)))
        } else {
            let own = |j: Option<&JointSec>, b: &BridgeSec| match name.rsplit('.').next() {
                Some("restrainer_offsets") => j
                    .and_then(|j| j.restrainer_offsets.as_ref())
                    .or(b.restrainer_offsets.as_ref())
                    .map(|x| v.line(x)),
                Some("restrainer_depth") => j
                    .and_then(|j| j.restrainer_depth.as_ref())
                    .or(b.restrainer_depth.as_ref())
                    .map(|x| v.line(x)),
                _ => None,
            };
            own(raw.joint.get(k).map(|j| j.get_ref()), &raw.bridge)
                .or(raw.joint.get(k).map(|t| v.line(t)))
                .or_else(|| raw.segment.get(k + 1).map(|t| v.line(t)))
        }
    } else {
        None
    };
    v.err(name, line, message)
}

/// The restrainer of joint `k` from its keys or the `[bridge]` defaults: present when
/// `restrainer_k` is given (slack default 0, no yield by default).
fn restrainer(
    v: &Val,
    k: usize,
    j: &JointSec,
    b: &BridgeSec,
) -> Result<Vec<RestrainerSpec>, ScenarioError> {
    let pick = |own: &Sp<f64>, def: &Sp<f64>, key: &str| match (own, def) {
        (Some(x), _) => (Some(x.clone()), format!("joint[{k}].{key}")),
        (None, Some(x)) => (Some(x.clone()), format!("bridge.{key}")),
        (None, None) => (None, format!("joint[{k}].{key}")),
    };
    let (rk, kk) = pick(&j.restrainer_k, &b.restrainer_k, "restrainer_k");
    let (rs, ks) = pick(&j.restrainer_slack, &b.restrainer_slack, "restrainer_slack");
    let (rf, kf) = pick(&j.restrainer_fy, &b.restrainer_fy, "restrainer_fy");
    let (rd, kd) = pick(&j.restrainer_depth, &b.restrainer_depth, "restrainer_depth");
    let (ro, ko) = match (&j.restrainer_offsets, &b.restrainer_offsets) {
        (Some(x), _) => (Some(x), format!("joint[{k}].restrainer_offsets")),
        (None, Some(x)) => (Some(x), "bridge.restrainer_offsets".to_string()),
        (None, None) => (None, String::new()),
    };
    if rk.is_none() {
        let others = [(&rs, ks), (&rf, kf), (&rd, kd)];
        let lone = others
            .into_iter()
            .find_map(|(x, key)| x.as_ref().map(|x| (v.line(x), key)))
            .or(ro.map(|x| (v.line(x), ko.clone())));
        if let Some((line, key)) = lone {
            return Err(v.err(
                key.clone(),
                Some(line),
                format!("{key} needs a restrainer: give its stiffness restrainer_k too"),
            ));
        }
        return Ok(Vec::new());
    }
    let k_ = v.pos(kk, &rk, None)?;
    let slack = v.gap(ks, &rs, Some(0.0))?;
    let fy = match rf {
        Some(_) => Some(v.pos(kf, &rf, None)?),
        None => None,
    };
    let depth = v.nonneg(kd, &rd, Some(0.0))?;
    let offsets = match ro {
        None => vec![0.0],
        Some(x) => {
            let o = x.get_ref();
            let mut sorted = o.clone();
            sorted.sort_by(f64::total_cmp);
            if sorted.windows(2).any(|w| w[0] == w[1]) {
                return Err(v.err(
                    ko.clone(),
                    Some(v.line(x)),
                    format!(
                        "invalid {ko}: two cables at the same offset (give one cable with the \
                         summed stiffness instead)"
                    ),
                ));
            }
            if o.is_empty() || o.len() > MAX_CABLES || o.iter().any(|x| !x.is_finite()) {
                return Err(v.err(
                    ko.clone(),
                    Some(v.line(x)),
                    format!(
                        "invalid {ko}: give one finite offset per cable [m] (1 to {MAX_CABLES} \
                         cables; positive to the left walking from the start to the end), e.g. \
                         [-3.0, 3.0]"
                    ),
                ));
            }
            o.clone()
        }
    };
    Ok(offsets
        .into_iter()
        .map(|offset| RestrainerSpec {
            k: k_,
            slack,
            fy,
            offset,
            depth,
        })
        .collect())
}

/// The shape of `[[segment]]` `i` and whether its body frame is mirrored (a curved segment
/// curving the other way than its natural direction).
fn segment_shape(
    v: &Val,
    i: usize,
    s: &SegmentSec,
    default_left: bool,
    (width, thickness, density): (f64, f64, f64),
) -> Result<(DeckShape, bool), ScenarioError> {
    let sk = |key: &str| format!("segment[{i}].{key}");
    let shape_name = s
        .shape
        .as_ref()
        .map_or("straight", |x| x.get_ref().as_str());
    // a shape's own check names the parameter as the shape knows it: the key the user wrote
    let geo = |fallback: &str, e: crate::geometry::GeometryError| {
        let crate::geometry::GeometryError::InvalidParameter { name, .. } = &e;
        let key = match name.as_str() {
            "R" => "R",
            "beta" => "beta_deg",
            "skew" => "skew_deg",
            "length" => "L",
            "width" => "width",
            "thickness" => "thickness",
            "density" if s.mass.is_some() => "mass",
            "density" => "density",
            _ => fallback,
        };
        v.err(
            sk(key),
            segment_key_line(v, s, key),
            format!("invalid {}: {e}", sk(key)),
        )
    };
    let natural_left = i == 0;
    let mut mirrored = false;
    let shape = match shape_name {
        "straight" => {
            let l = v.dim(sk("L"), &s.L, None)?;
            DeckShape::Straight(
                StraightDeck::new(l, width, thickness, density).map_err(|e| geo("L", e))?,
            )
        }
        "skew" => {
            let l = v.dim(sk("L"), &s.L, None)?;
            let sk_deg = v.num(
                sk("skew_deg"),
                &s.skew_deg,
                None,
                |x| (0.0..90.0).contains(&x),
                "must lie in [0, 90)",
            )?;
            DeckShape::Skewed(
                SkewedDeck::new(l, width, sk_deg.to_radians(), thickness, density)
                    .map_err(|e| geo("skew_deg", e))?,
            )
        }
        "curved" => {
            let r = v.num(
                sk("R"),
                &s.R,
                None,
                |x| x > width / 2.0 && x <= 1e5,
                "must exceed width / 2 and be at most 1e5 m",
            )?;
            let beta = v.num(
                sk("beta_deg"),
                &s.beta_deg,
                None,
                |x| x.to_radians() > 0.0 && x < 180.0,
                "must lie in (0, 180) (and not round to 0 in radians)",
            )?;
            let left = match s.curve.as_ref().map(|c| (c.get_ref().as_str(), v.line(c))) {
                None => default_left,
                Some(("left", _)) => true,
                Some(("right", _)) => false,
                Some((other, line)) => {
                    return Err(v.err(
                        sk("curve"),
                        Some(line),
                        format!(
                            "invalid {} {other:?}: use \"left\" or \"right\"",
                            sk("curve")
                        ),
                    ));
                }
            };
            mirrored = left != natural_left;
            DeckShape::Curved(
                Deck::new(r, beta.to_radians(), width, thickness, density)
                    .map_err(|e| geo("R", e))?,
            )
        }
        other => {
            let line = s.shape.as_ref().map(|x| v.line(x));
            return Err(v.err(
                sk("shape"),
                line,
                format!(
                    "invalid {} {other:?}: use \"straight\", \"skew\" or \"curved\"",
                    sk("shape")
                ),
            ));
        }
    };
    if shape_name != "curved"
        && let Some(c) = &s.curve
    {
        return Err(v.err(
            sk("curve"),
            Some(v.line(c)),
            format!("{} applies to curved segments only", sk("curve")),
        ));
    }
    for (key, val, ok) in [
        ("L", &s.L, shape_name != "curved"),
        ("R", &s.R, shape_name == "curved"),
        ("beta_deg", &s.beta_deg, shape_name == "curved"),
        ("skew_deg", &s.skew_deg, shape_name == "skew"),
    ] {
        if let (Some(x), false) = (val, ok) {
            return Err(v.err(
                sk(key),
                Some(v.line(x)),
                format!("{} does not apply to shape = {shape_name:?}", sk(key)),
            ));
        }
    }
    Ok((shape, mirrored))
}

/// `bearing = "bilinear"` with `fy`, `b` of `[[segment]]` `i` (`None`: linear bearings).
fn bearing_yield(v: &Val, i: usize, s: &SegmentSec) -> Result<Option<BearingYield>, ScenarioError> {
    let sk = |key: &str| format!("segment[{i}].{key}");
    let kind = s
        .bearing
        .as_ref()
        .map(|x| (x.get_ref().as_str(), v.line(x)));
    match kind {
        None | Some(("linear", _)) => {
            for (key, x) in [("fy", &s.fy), ("b", &s.b)] {
                if let Some(x) = x {
                    return Err(v.err(
                        sk(key),
                        Some(v.line(x)),
                        format!(
                            "{} applies to yielding bearings: set {} = \"bilinear\"",
                            sk(key),
                            sk("bearing")
                        ),
                    ));
                }
            }
        }
        Some(("bilinear", _)) => {
            let fy = v.num(
                sk("fy"),
                &s.fy,
                None,
                positive,
                "must be > 0 (yield force of the segment's bearings together, N)",
            )?;
            let b = v.num(
                sk("b"),
                &s.b,
                None,
                |x| (0.0..1.0).contains(&x),
                "must lie in [0, 1)",
            )?;
            return Ok(Some(BearingYield { fy, b }));
        }
        Some((other, line)) => {
            return Err(v.err(
                sk("bearing"),
                Some(line),
                format!(
                    "invalid {} {other:?}: use \"linear\" or \"bilinear\"",
                    sk("bearing")
                ),
            ));
        }
    }
    Ok(None)
}

/// Most bearing points of one segment (beyond, a run would be slow for nothing physical).
const MAX_BEARING_POINTS: usize = 1000;
/// Most restrainer cables across one joint.
const MAX_CABLES: usize = 100;

/// The number of bearings of `[[segment]]` `i`: its `bearing_points` (1 to
/// [`MAX_BEARING_POINTS`], two coordinates each) or the four corners.
fn bearing_count(v: &Val, i: usize, s: &SegmentSec) -> Result<usize, ScenarioError> {
    let sk = |key: &str| format!("segment[{i}].{key}");
    Ok(match &s.bearing_points {
        Some(p) if p.get_ref().is_empty() || p.get_ref().len() > MAX_BEARING_POINTS => {
            return Err(v.err(
                sk("bearing_points"),
                Some(v.line(p)),
                format!(
                    "{} needs between 1 and {MAX_BEARING_POINTS} points",
                    sk("bearing_points")
                ),
            ));
        }
        Some(p) if p.get_ref().iter().any(|q| q.len() != 2) => {
            let bad = p.get_ref().iter().position(|q| q.len() != 2).unwrap_or(0);
            return Err(v.err(
                sk("bearing_points"),
                Some(v.line(p)),
                format!(
                    "{}: point {} has {} coordinates; give each point as [along, left] (two \
                     numbers, m)",
                    sk("bearing_points"),
                    bad + 1,
                    p.get_ref()[bad].len()
                ),
            ));
        }
        Some(p) => p.get_ref().len(),
        None => 4,
    })
}

/// The direction each curved segment takes when its `curve` is left out (`true`: left): the
/// curves alternate along the bridge, left first — each such segment curves the other way than
/// the curved segment before it (given or defaulted), straight and skew spans in between not
/// counting; the first curved segment curves left. (An S, repeated, whatever spans stand between
/// its curves.) Entries of other segments are unused.
fn default_curves<'a>(segments: impl Iterator<Item = &'a SegmentSec>) -> Vec<bool> {
    let mut prev: Option<bool> = None;
    segments
        .map(|s| {
            let curved = s.shape.as_ref().is_some_and(|x| x.get_ref() == "curved");
            let left = match s.curve.as_ref().map(|c| c.get_ref().as_str()) {
                Some("right") => false,
                Some("left") => true,
                _ => prev.is_none_or(|p| !p),
            };
            if curved {
                prev = Some(left);
            }
            left
        })
        .collect()
}

/// One `[[segment]]` table; `default_left`: its curve when `curve` is left out
/// ([`default_curves`]).
fn segment(
    v: &Val,
    i: usize,
    s: &SegmentSec,
    default_left: bool,
) -> Result<Segment, ScenarioError> {
    let sk = |key: &str| format!("segment[{i}].{key}");
    let width = v.dim(sk("width"), &s.width, Some(10.0))?;
    let thickness = v.dim(sk("thickness"), &s.thickness, Some(0.5))?;
    let density = v.pos(sk("density"), &s.density, Some(2500.0))?;
    let (mut shape, mirrored) = segment_shape(v, i, s, default_left, (width, thickness, density))?;
    if let (Some(ms), Some(_)) = (&s.mass, &s.density) {
        return Err(v.err(
            sk("density"),
            Some(v.line(ms)),
            format!(
                "give {} or {}, not both (the mass sets the density)",
                sk("mass"),
                sk("density")
            ),
        ));
    }
    if let Some(ms) = &s.mass {
        let m = v.pos(sk("mass"), &Some(ms.clone()), None)?;
        let f = m / shape.mass_properties().mass;
        shape.scale_density(f);
        let mp = shape.mass_properties();
        if shape.validate().is_err() || !(mp.mass.is_normal() && mp.inertia.is_normal()) {
            return Err(v.err(
                sk("mass"),
                Some(v.line(ms)),
                format!(
                    "invalid {} = {}: the density or the moment of inertia it gives is not a \
                     normal number; use a physical mass",
                    sk("mass"),
                    crate::output::float_token(m)
                ),
            ));
        }
    }
    let mass = shape.mass_properties().mass;
    let n_bearings = bearing_count(v, i, s)?;
    let k = match (&s.period_s, &s.bearing_stiffness) {
        (Some(_), Some(b)) => {
            return Err(v.err(
                sk("bearing_stiffness"),
                Some(v.line(b)),
                format!(
                    "give {} or {}, not both",
                    sk("period_s"),
                    sk("bearing_stiffness")
                ),
            ));
        }
        (Some(_), None) => {
            let t = v.pos(sk("period_s"), &s.period_s, None)?;
            let w = 2.0 * std::f64::consts::PI / t;
            let k = mass * w * w / n_bearings as f64;
            if !(k.is_normal() && k > 0.0 && (k * 1e100).is_finite()) {
                // the bearing stiffness m (2π/T)²/n over- or underflows (T = 1e300, 1e-300 s)
                let line = s.period_s.as_ref().map(|x| v.line(x));
                return Err(v.err(
                    sk("period_s"),
                    line,
                    format!(
                        "invalid {} = {}: with this mass it gives a bearing stiffness of {} N/m; \
                         use a physical period",
                        sk("period_s"),
                        crate::output::float_token(t),
                        crate::output::float_token(k)
                    ),
                ));
            }
            k
        }
        (None, Some(b)) => {
            let k = v.pos(sk("bearing_stiffness"), &s.bearing_stiffness, None)?;
            // `k r²` (lever arms up to kilometres) must stay finite and `k` a normal double:
            // 1e308 overflowed in the rotational stiffness, 5e-324 gave a segment without
            // stiffness, both reported under keys the file does not have
            if !(k.is_normal() && (k * 1e100).is_finite()) {
                let why = if k < f64::MIN_POSITIVE {
                    "below the smallest normal double: the segment would have no stiffness"
                } else {
                    "the rotational stiffness k r² of the bearings (lever arms of metres to \
                     kilometres) would overflow"
                };
                return Err(v.err(
                    sk("bearing_stiffness"),
                    Some(v.line(b)),
                    format!(
                        "invalid {} = {}: {why}; use a physical stiffness (N/m per bearing)",
                        sk("bearing_stiffness"),
                        crate::output::float_token(k)
                    ),
                ));
            }
            k
        }
        (None, None) => {
            return Err(v.err(sk("period_s"), None, format!("segment[{i}] needs its bearings: give {} (translational period of its bearings) or {} (per bearing, N/m)", sk("period_s"), sk("bearing_stiffness"))));
        }
    };
    let mut seg = Segment::with_corner_bearings(shape, mirrored, k);
    if let Some(p) = &s.bearing_points {
        let pts = p.get_ref();
        if let Some(bad) = pts
            .iter()
            .position(|q| !(q[0].is_finite() && q[1].is_finite()))
        {
            return Err(v.err(
                sk("bearing_points"),
                Some(v.line(p)),
                format!("{}: point {} is not finite", sk("bearing_points"), bad + 1),
            ));
        }
        seg.bearings = pts
            .iter()
            .map(|q| crate::sim::Bearing {
                point: seg.frame_point(i == 0, q[0], q[1]),
                stiffness: k,
            })
            .collect();
    }
    seg.bearing_yield = bearing_yield(v, i, s)?;
    Ok(seg)
}
