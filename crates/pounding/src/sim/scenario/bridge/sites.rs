//! The joints and abutments of a bridge scenario: their contact sites and laws (a site's own
//! `contact` table over `[contact]`), the restrainer cables, the mechanism check and the
//! messages that name a model error's key.

use super::*;

/// A bridge of one segment has no joint: the `[bridge]` restrainer keys would be ignored, so
/// they are refused.
pub(super) fn no_joint_keys(v: &Val, rb: &BridgeSec) -> Result<(), ScenarioError> {
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
pub(super) struct JointDefaults {
    pub(super) gap: f64,
    pub(super) mu: f64,
    pub(super) eps_n: f64,
    pub(super) seat_length: f64,
}

/// The joints (`[[joint]]` tables or the defaults) and the abutments of a bridge scenario;
/// `masses` of the segments (for the contact-law calibrations).
pub(super) fn sites(
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
            backwall: match &a.backwall {
                None => None,
                Some(w) => Some(super::backwall::backwall(v, side, w)?),
            },
            shear_keys: match &a.shear_keys {
                None => None,
                Some(t) => Some(super::backwall::shear_keys(v, side, t)?),
            },
        });
        next += 1;
    }
    Ok((joints, abutments))
}

/// The contact of every site (joints, then the abutments given), with the keys of its own
/// `contact` table checked: unknown keys and types, then the `[contact]` keys that no site's
/// law reads, then the site keys that its law (or no compared law) reads.
pub(super) fn site_contacts<'a>(
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
            let contact_key = super::super::contact::section_keys()
                .iter()
                .copied()
                .filter(|&k| k != "law")
                .find(|k| super::super::contact::given(&sc.raw.contact, k));
            if let Some(key) = contact_key {
                return Err(sc.src.key_error(
                    format!(
                        "[contact] {key} is not used: this bridge has no joints and no abutments \
                         (no contact)"
                    ),
                    &[super::super::ParamKey::new(
                        super::super::Section::Contact,
                        key,
                    )],
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
pub(super) fn check_mechanism(
    v: &Val,
    raw: &BridgeRaw,
    model: &BridgeModel,
) -> Result<(), ScenarioError> {
    // the assembly's own errors (Rayleigh damping of a segment without stiffness) first, with
    // a mechanism allowed too
    let freqs = model
        .segment_frequencies()
        .map_err(|e| model_error(v, raw, e))?;
    if raw
        .bridge
        .allow_mechanism
        .as_ref()
        .is_some_and(|a| *a.get_ref())
    {
        return Ok(());
    }
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
    // a backwall with backfill (compression only) and no piles is free to move toward the deck
    for (side, a) in model.abutments.iter().enumerate() {
        let Some(w) = a.and_then(|a| a.backwall) else {
            continue;
        };
        if w.piles.is_none() {
            let name = crate::sim::bridge::ABUTMENT_SIDES[side];
            let tables = [&raw.abutment.start, &raw.abutment.end];
            let table = tables[side]
                .as_ref()
                .and_then(|t| t.get_ref().backwall.as_ref());
            return Err(v.err(
                format!("abutment.{name}.backwall.piles_k"),
                table.map(|t| v.line(t)),
                format!(
                    "abutment.{name}.backwall has backfill and no piles: the backfill pushes only \
                     into the soil, so nothing holds the wall toward the deck (a mechanism); give \
                     piles_k and piles_fy, or set bridge.allow_mechanism = true to simulate it anyway"
                ),
            ));
        }
    }
    Ok(())
}

/// The line of `key` where `[[segment]]` table `t` writes it (`None`: not written there).
pub(super) fn segment_key_line(v: &Val, t: &SegmentSec, key: &str) -> Option<usize> {
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
        "bearing_damping" => num(&t.bearing_damping),
        _ => None,
    }
}

/// A model error (its typed path a [`BridgeKey`]: `segment[i].key`, `joint[k].key`,
/// `abutment.side.key`, `pier[p].key`, `bridge.key`) with the line of that key, or of its table
/// when the key is not written there.
pub(super) fn model_error(v: &Val, raw: &BridgeRaw, e: crate::sim::SimError) -> ScenarioError {
    let Some(ParamPath::Bridge(path)) = e.path() else {
        return match e.path() {
            // a parameter known by its name only: named as it is, with no line
            Some(p) => v.err(p.to_string(), None, e.to_string()),
            None => ScenarioError::Model(Box::new(e)),
        };
    };
    let key = path.leaf();
    let line = match path.table {
        BridgeTable::Segment(i) => {
            let seg = raw.segment.get(i);
            let own = seg.and_then(|t| segment_key_line(v, t.get_ref(), key));
            own.or(seg.map(|t| v.line(t)))
        }
        // faces of different widths: the `width` of the segment after the joint (or before it),
        // else that segment's table; other joint keys: the joint's table
        BridgeTable::Joint(k) if key == "width" => {
            let width = |i: usize| {
                raw.segment
                    .get(i)
                    .and_then(|t| t.get_ref().width.as_ref().map(|w| v.line(w)))
            };
            width(k + 1)
                .or_else(|| width(k))
                .or_else(|| raw.segment.get(k + 1).map(|t| v.line(t)))
        }
        BridgeTable::Joint(k) => {
            let (j, b) = (raw.joint.get(k).map(|j| j.get_ref()), &raw.bridge);
            let (own, default) = match key {
                "restrainer_offsets" => (
                    j.and_then(|j| j.restrainer_offsets.as_ref())
                        .map(|x| v.line(x)),
                    b.restrainer_offsets.as_ref().map(|x| v.line(x)),
                ),
                "restrainer_depth" => (
                    j.and_then(|j| j.restrainer_depth.as_ref())
                        .map(|x| v.line(x)),
                    b.restrainer_depth.as_ref().map(|x| v.line(x)),
                ),
                _ => (None, None),
            };
            // a value the joint inherits from `[bridge]`: named as the user wrote it
            if let (None, Some(line)) = (own, default) {
                return inherited_error(v, &e, &format!("bridge.{key}"), k, line);
            }
            own.or(raw.joint.get(k).map(|t| v.line(t)))
                .or_else(|| raw.segment.get(k + 1).map(|t| v.line(t)))
        }
        BridgeTable::Pier(p) => super::pier::pier_line(v, &raw.pier, p, key),
        BridgeTable::Bridge if key == "damping" => raw.bridge.damping.as_ref().map(|x| v.line(x)),
        BridgeTable::Bridge | BridgeTable::Abutment(_) => None,
    };
    v.err(path.to_string(), line, e.to_string())
}

/// A model error about joint `k`'s parameter whose value is the `[bridge]` default `name`
/// (written at `line`): the message names that key, and the joint it failed at.
fn inherited_error(
    v: &Val,
    e: &crate::sim::SimError,
    name: &str,
    k: usize,
    line: usize,
) -> ScenarioError {
    use crate::sim::SimError;
    let message = match e {
        SimError::InvalidParameter { value, reason, .. } => format!(
            "invalid {name} = {} at joint[{k}]: {reason}",
            float_token(*value)
        ),
        SimError::InvalidArgument { reason, .. } => {
            format!("invalid {name} at joint[{k}]: {reason}")
        }
        other => other.to_string(),
    };
    v.err(name.to_string(), Some(line), message)
}

/// The restrainer of joint `k` from its keys or the `[bridge]` defaults: present when
/// `restrainer_k` is given (slack default 0, no yield by default).
pub(super) fn restrainer(
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
