//! The segments of a bridge scenario: each `[[segment]]` table's shape (straight, skewed,
//! curved, mirrored), bearings (points, stiffness, yield) and mass.

use super::*;

/// The shape of `[[segment]]` `i` and whether its body frame is mirrored (a curved segment
/// curving the other way than its natural direction).
pub(super) fn segment_shape(
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
        use crate::geometry::ShapeParam;
        let crate::geometry::GeometryError::InvalidParameter { param, .. } = &e;
        let key = match param {
            ShapeParam::Radius => "R",
            ShapeParam::Angle => "beta_deg",
            ShapeParam::Skew => "skew_deg",
            ShapeParam::Length => "L",
            ShapeParam::Width => "width",
            ShapeParam::Thickness => "thickness",
            ShapeParam::Density if s.mass.is_some() => "mass",
            ShapeParam::Density => "density",
            ShapeParam::Gap | ShapeParam::Other => fallback,
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
pub(super) fn bearing_yield(
    v: &Val,
    i: usize,
    s: &SegmentSec,
) -> Result<Option<BearingYield>, ScenarioError> {
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
pub(super) const MAX_BEARING_POINTS: usize = 1000;
/// Most restrainer cables across one joint.
pub(super) const MAX_CABLES: usize = 100;

/// The number of bearings of `[[segment]]` `i`: its `bearing_points` (1 to
/// [`MAX_BEARING_POINTS`], two coordinates each) or the four corners.
pub(super) fn bearing_count(v: &Val, i: usize, s: &SegmentSec) -> Result<usize, ScenarioError> {
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
pub(super) fn default_curves<'a>(segments: impl Iterator<Item = &'a SegmentSec>) -> Vec<bool> {
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
pub(super) fn segment(
    v: &Val,
    i: usize,
    s: &SegmentSec,
    default_left: bool,
) -> Result<Segment, ScenarioError> {
    let sk = |key: &str| format!("segment[{i}].{key}");
    let width = v.dim(sk("width"), &s.width, Some(defaults::WIDTH))?;
    let thickness = v.dim(sk("thickness"), &s.thickness, Some(defaults::THICKNESS))?;
    let density = v.pos(sk("density"), &s.density, Some(defaults::DENSITY))?;
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
            // 0 is a segment without stiffness: a mechanism, refused as one by
            // `check_mechanism` unless `bridge.allow_mechanism = true` (the two-deck rule)
            let k = v.nonneg(sk("bearing_stiffness"), &s.bearing_stiffness, None)?;
            // `k r²` (lever arms up to kilometres) must stay finite and `k` 0 or a normal
            // double: 1e308 overflowed in the rotational stiffness, 5e-324 gave a segment
            // without stiffness, both reported under keys the file does not have
            if !(k == 0.0 || k.is_normal() && (k * 1e100).is_finite()) {
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
    seg.bearing_damping = v.nonneg(sk("bearing_damping"), &s.bearing_damping, Some(0.0))?;
    Ok(seg)
}
