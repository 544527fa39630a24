//! The abutment form: one deck (curved, straight or skew) against a rigid abutment beyond its far
//! end; the deck shape and cross-section inputs shared with the joint form.

use super::common::{
    CornerContactReport, DelassusReport, EnergyReport, IntervalReport, ReportError,
    SingleImpactReport, corner_contacts, invalid, readable, xy,
};
use crate::analytic::{self, ImpactLaw};
use crate::geometry::{GeometryError, ShapeParam};
use crate::impact::{self, ContactMode, ImpactSettings};
use crate::lcp::LemkeSettings;
use crate::math::Vector;
use crate::shape::Deck;
use crate::shape::{
    Abutment, DeckEnd, DeckShape, SkewedDeck, StraightDeck, abutment_contact, abutment_delassus,
    abutment_problem, frictionless_pivot,
};
use serde::Serialize;

/// A deck's plan shape. Lengths in m, angles in degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShapeSpec {
    /// A curved deck: centre-line radius `R` \[m\] (> W/2) and curve angle `β` \[deg\] in (0, 360).
    Curved {
        /// `R` \[m\].
        radius: f64,
        /// `β` \[deg\].
        angle_deg: f64,
    },
    /// A rectangle of length `L` \[m\] (> 0) along its axis.
    Straight {
        /// `L` \[m\].
        length: f64,
    },
    /// A parallelogram: length `L` \[m\] (> 0), skew angle `θ_s` \[deg\] in [0, 90) of the end faces.
    Skew {
        /// `L` \[m\].
        length: f64,
        /// `θ_s` \[deg\].
        skew_deg: f64,
    },
}

/// The cross-section shared by the decks of a report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckSection {
    /// Width `W` \[m\].
    pub width: f64,
    /// Thickness `t` \[m\].
    pub thickness: f64,
    /// Density `ρ` \[kg/m³\].
    pub density: f64,
}

impl ShapeSpec {
    pub(super) fn build(&self, s: &DeckSection) -> Result<DeckShape, GeometryError> {
        Ok(match *self {
            Self::Curved { radius, angle_deg } => DeckShape::Curved(
                Deck::new(
                    radius,
                    angle_deg.to_radians(),
                    s.width,
                    s.thickness,
                    s.density,
                )
                .map_err(|e| e.for_deck(1))?,
            ),
            Self::Straight { length } => {
                DeckShape::Straight(StraightDeck::new(length, s.width, s.thickness, s.density)?)
            }
            // checked in degrees, so that the error shows the value given (-30, not
            // -29.999999999999996 back from radians)
            Self::Skew { skew_deg, .. }
                if !(skew_deg.is_finite() && (0.0..90.0).contains(&skew_deg)) =>
            {
                return Err(GeometryError::invalid(
                    ShapeParam::Skew,
                    skew_deg,
                    "the skew angle must lie in [0, 90) degrees",
                ));
            }
            Self::Skew { length, skew_deg } => DeckShape::Skewed(SkewedDeck::new(
                length,
                s.width,
                skew_deg.to_radians(),
                s.thickness,
                s.density,
            )?),
        })
    }
}

/// Names of the far-face corners `\[c0, c1\]` for a shape.
pub(super) fn corner_names(shape: &DeckShape) -> [&'static str; 2] {
    shape.corner_names(crate::shape::DeckEnd::Far)
}

/// Input of the abutment form.
#[derive(Debug, Clone, PartialEq)]
pub struct AbutmentInput {
    /// The deck's shape.
    pub shape: ShapeSpec,
    /// Its cross-section.
    pub section: DeckSection,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub mu: f64,
    /// Newton restitution coefficient `ε_N ∈ \[0, 1\]`.
    pub eps: f64,
    /// Abutment gap `g ≥ 0` \[m\] along the far face's outward normal.
    pub gap: f64,
    /// Striking corner(s): `both`, `c0`, `c1`, or the shape's names (`outer`/`inner`,
    /// `acute`/`obtuse`).
    pub corner: String,
    /// With a single corner: pre-impact ratio `r = γ_T⁻/γ_N⁻` to solve (with `γ_N⁻ = −1 m/s`).
    pub ratio: Option<f64>,
    /// With both corners: speed of the longitudinal approach \[m/s\] (> 0).
    pub speed: f64,
}

/// The abutment form's input as echoed in the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AbutmentEcho {
    /// Shape name.
    pub shape: &'static str,
    /// Always `true`.
    pub abutment: bool,
    /// The struck end (`far`).
    pub end: &'static str,
    /// The corner selection as given.
    pub corner: String,
    /// `μ`.
    pub mu: f64,
    /// `ε_N`.
    pub eps: f64,
    /// Gap \[m\].
    pub gap: f64,
    /// `W` \[m\].
    pub width: f64,
    /// `t` \[m\].
    pub thickness: f64,
    /// `ρ` \[kg/m³\].
    pub density: f64,
    /// `R` \[m\] (curved).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// `β` \[deg\] (curved).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle_deg: Option<f64>,
    /// `L` \[m\] (straight, skew).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// `θ_s` \[deg\] (skew).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skew_deg: Option<f64>,
}

/// The struck end face.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FaceReport {
    /// Corner positions `\[c0, c1\]` \[m\].
    pub corners: [[f64; 2]; 2],
    /// Corner names.
    pub corner_names: [&'static str; 2],
    /// Interior corner angles \[deg\].
    pub corner_angles_deg: [f64; 2],
    /// Face length \[m\].
    pub length: f64,
    /// Outward unit normal.
    pub outward_normal: [f64; 2],
}

/// The deck's mass properties and far face.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShapeDeckReport {
    /// Plan area \[m²\].
    pub area: f64,
    /// Mass \[kg\].
    pub mass: f64,
    /// Centroid \[m\].
    pub centroid: [f64; 2],
    /// Moment of inertia about the centroid \[kg m²\].
    pub inertia: f64,
    /// Radius of gyration \[m\].
    pub radius_of_gyration: f64,
    /// Unit axis direction toward the far end.
    pub axis: [f64; 2],
    /// The far face.
    pub far_face: FaceReport,
}

/// Where the abutment is.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AbutmentPlacement {
    /// A point of the abutment face \[m\].
    pub face_point: [f64; 2],
    /// Travel along the axis until the first corner touches \[m\].
    pub travel_to_contact: f64,
}

/// Lever arms of a corner \[m\].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LeverArms {
    /// `r × n`.
    pub normal: f64,
    /// `r × t`.
    pub tangential: f64,
}

/// The longitudinal approach of a single corner.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LongitudinalReport {
    /// Its ratio `r = γ_T⁻/γ_N⁻`.
    pub ratio: f64,
    /// The post-impact mode.
    pub mode: &'static str,
    /// The solver status.
    pub status: &'static str,
}

/// One corner alone against the abutment (flattened into [`AbutmentReport`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SingleCornerReport {
    /// Corner index (0 or 1).
    pub corner_index: usize,
    /// Corner name.
    pub corner_name: &'static str,
    /// Contact point \[m\].
    pub point: [f64; 2],
    /// Contact normal.
    pub normal: [f64; 2],
    /// Contact tangent (from c0 to c1).
    pub tangent: [f64; 2],
    /// Lever arms.
    pub lever_arms: LeverArms,
    /// Delassus entries.
    pub delassus: DelassusReport,
    /// `κ`.
    pub kappa: f64,
    /// `ϱ`.
    pub varrho: f64,
    /// The stick interval.
    pub stick_interval: IntervalReport,
    /// Whether one bound is infinite.
    pub painleve: bool,
    /// The longitudinal approach.
    pub longitudinal: LongitudinalReport,
    /// The impact at the given ratio (flattened).
    #[serde(flatten)]
    pub impact: Option<SingleImpactReport>,
    #[serde(skip)]
    trustworthy: bool,
}

/// Post-impact state of a body \[m/s, rad/s\].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyVelocity {
    /// Velocity of the centroid.
    pub velocity: [f64; 2],
    /// Angular velocity.
    pub omega: f64,
}

/// Whether and how the deck rotates when both corners strike.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RotationReport {
    /// The corner the frictionless criterion predicts as pivot.
    pub predicted_pivot: Option<&'static str>,
    /// Whether `|ω⁺|` exceeds rounding noise.
    pub rotates: bool,
    /// The pivot the LCP found (the corner keeping contact while the other opens).
    pub pivot: Option<&'static str>,
    /// `ω⁺` \[rad/s\].
    pub omega: f64,
    /// `sin 2θ_s` (skew).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sin_2skew: Option<f64>,
    /// `2W/L` (skew).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub two_w_over_l: Option<f64>,
    /// `sin 2θ_s > 2W/L` (skew).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub condition_holds: Option<bool>,
    /// The criterion with friction (skew).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_condition_holds: Option<bool>,
}

/// Both corners strike after a longitudinal approach (flattened into [`AbutmentReport`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BothCornersReport {
    /// Approach speed \[m/s\].
    pub speed: f64,
    /// Per-corner results.
    pub contacts: Vec<CornerContactReport>,
    /// Post-impact state of the deck.
    pub post: BodyVelocity,
    /// Kinetic energy.
    pub energy: EnergyReport,
    /// Rotation.
    pub rotation: RotationReport,
    /// Solver status.
    pub status: &'static str,
    /// Whether the post-impact velocities are unique.
    pub post_velocity_unique: bool,
    /// Whether the friction split between the corners is unique; when `false` (e.g. a face
    /// striking square on, where only the sum is determined) the split of smallest norm is
    /// reported (see `impact::ImpactSolution::tangential_split_unique`).
    pub tangential_split_unique: bool,
    #[serde(skip)]
    trustworthy: bool,
}

/// The report of the abutment form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AbutmentReport {
    /// The input.
    pub input: AbutmentEcho,
    /// The deck.
    pub deck: ShapeDeckReport,
    /// The abutment.
    pub abutment: AbutmentPlacement,
    /// A single corner (flattened).
    #[serde(flatten)]
    pub single: Option<SingleCornerReport>,
    /// Both corners (flattened).
    #[serde(flatten)]
    pub both: Option<BothCornersReport>,
    #[serde(skip)]
    lines: Vec<String>,
}

fn resolve_corner(corner: &str, names: &[&'static str; 2]) -> Result<Vec<usize>, ReportError> {
    Ok(match corner {
        "both" => vec![0, 1],
        "c0" => vec![0],
        "c1" => vec![1],
        n if n == names[0] => vec![0],
        n if n == names[1] => vec![1],
        n => {
            let alias = if names[0] == "c0" {
                String::new()
            } else {
                format!(" (or {}, {})", names[0], names[1])
            };
            return Err(invalid(
                "corner",
                format!("{n:?}"),
                &format!("expected both, c0 or c1{alias}"),
            ));
        }
    })
}

pub(super) fn check_speed(speed: f64) -> Result<(), ReportError> {
    if speed.is_finite() && speed > 0.0 {
        Ok(())
    } else {
        Err(invalid("speed", speed, "must be finite and > 0"))
    }
}

/// Computes the abutment form: the deck's mass properties and far face, then either one corner
/// alone (Delassus entries, stick interval, longitudinal approach, optional impact at `ratio`) or
/// both corners striking after a longitudinal approach at `speed` (impulses, post-impact state,
/// rotation and the frictionless/frictional rotation criteria).
pub fn abutment_report(a: &AbutmentInput) -> Result<AbutmentReport, ReportError> {
    let shape = a.shape.build(&a.section)?;
    let law = ImpactLaw::new(a.mu, a.eps)?;
    let abut = Abutment::new(DeckEnd::Far, a.gap)?;
    let names = corner_names(&shape);
    let corners = resolve_corner(&a.corner, &names)?;
    if let Some(r) = a.ratio {
        if !r.is_finite() {
            return Err(invalid("ratio", r, "must be finite"));
        }
        if corners.len() == 2 {
            return Err(invalid("ratio", r, "needs a single corner (c0 or c1)"));
        }
    }
    check_speed(a.speed)?;
    let props = shape.mass_properties();
    let face = shape.end_face(DeckEnd::Far);
    let axis = shape.axis_direction(DeckEnd::Far);
    let (radius, angle_deg, length, skew_deg) = match a.shape {
        ShapeSpec::Curved { radius, angle_deg } => (Some(radius), Some(angle_deg), None, None),
        ShapeSpec::Straight { length } => (None, None, Some(length), None),
        ShapeSpec::Skew { length, skew_deg } => (None, None, Some(length), Some(skew_deg)),
    };
    let mut rep = AbutmentReport {
        input: AbutmentEcho {
            shape: shape.name(),
            abutment: true,
            end: DeckEnd::Far.name(),
            corner: a.corner.clone(),
            mu: a.mu,
            eps: a.eps,
            gap: abut.gap,
            width: a.section.width,
            thickness: a.section.thickness,
            density: a.section.density,
            radius,
            angle_deg,
            length,
            skew_deg,
        },
        deck: ShapeDeckReport {
            area: props.area,
            mass: props.mass,
            centroid: xy(&props.centroid),
            inertia: props.inertia,
            radius_of_gyration: props.radius_of_gyration(),
            axis: xy(&axis),
            far_face: FaceReport {
                corners: [xy(&face.corners[0]), xy(&face.corners[1])],
                corner_names: names,
                corner_angles_deg: [
                    shape.corner_angle(DeckEnd::Far, 0).to_degrees(),
                    shape.corner_angle(DeckEnd::Far, 1).to_degrees(),
                ],
                length: face.length(),
                outward_normal: xy(&face.outward_normal),
            },
        },
        abutment: AbutmentPlacement {
            face_point: xy(&abut.face_point(&shape)),
            travel_to_contact: abut.travel_to_contact(&shape),
        },
        single: None,
        both: None,
        lines: Vec::new(),
    };
    rep.lines = rep.head_lines();
    if corners.len() == 1 {
        let single = single_corner(&shape, corners[0], &names, axis, &law, a.ratio);
        single.summary(&mut rep.lines);
        rep.single = Some(single);
    } else {
        let both = both_corners(&shape, &names, axis, &law, a.speed)?;
        both.summary(&shape, a.mu, &mut rep.lines);
        rep.both = Some(both);
    }
    Ok(rep)
}

fn single_corner(
    shape: &DeckShape,
    k: usize,
    names: &[&'static str; 2],
    axis: Vector,
    law: &ImpactLaw,
    ratio: Option<f64>,
) -> SingleCornerReport {
    let c = abutment_contact(shape, DeckEnd::Far, k);
    let g = abutment_delassus(shape, DeckEnd::Far, k);
    let bounds = analytic::stick_interval(&g, law);
    // longitudinal approach: u = speed · axis, ω = 0
    let long_ratio = axis.dot(&c.tangent) / axis.dot(&c.normal);
    let settings = LemkeSettings::default();
    let long = impact::solve_single(&g, law, -1.0, -long_ratio, &settings);
    let impact = ratio.map(|r| {
        let sol = impact::solve_single(&g, law, -1.0, -r, &settings);
        SingleImpactReport::of(r, &sol, sol.mode.name())
    });
    SingleCornerReport {
        corner_index: k,
        corner_name: names[k],
        point: xy(&c.point),
        normal: xy(&c.normal),
        tangent: xy(&c.tangent),
        lever_arms: LeverArms {
            normal: c.arm_n,
            tangential: c.arm_t,
        },
        delassus: DelassusReport::of(&g),
        kappa: g.kappa(),
        varrho: g.varrho(),
        stick_interval: IntervalReport::of(&bounds),
        painleve: analytic::is_painleve(&g, law),
        longitudinal: LongitudinalReport {
            ratio: long_ratio,
            mode: long.mode.name(),
            status: long.status.name(),
        },
        trustworthy: long.status.is_trustworthy() && impact.as_ref().is_none_or(|i| i.trustworthy),
        impact,
    }
}

fn both_corners(
    shape: &DeckShape,
    names: &[&'static str; 2],
    axis: Vector,
    law: &ImpactLaw,
    speed: f64,
) -> Result<BothCornersReport, ReportError> {
    let problem = abutment_problem(shape, DeckEnd::Far, &[0, 1], speed * axis, 0.0, law)?;
    let s = impact::solve(&problem, &ImpactSettings::default());
    let face = shape.end_face(DeckEnd::Far);
    let props = shape.mass_properties();
    let omega = s.bodies[0].omega;
    // relative threshold: ω against the characteristic rate |v⁻|/ℓ of the approach, with ℓ the
    // largest body length (face length or radius of gyration); below 1e-9 it is rounding noise
    // (e.g. θ_s → 90°, where γ_N⁻ → 0 and ω⁺ ~ 1e-26 rad/s)
    let half_diag = face.length().max(props.radius_of_gyration());
    let rotates = omega.abs() * half_diag > 1e-9 * speed.abs();
    let open = |k: usize| s.contacts[k].mode == ContactMode::Open;
    let pivot = match (open(0), open(1), rotates) {
        (true, false, true) => Some(names[1]),
        (false, true, true) => Some(names[0]),
        _ => None,
    };
    let mut rotation = RotationReport {
        predicted_pivot: frictionless_pivot(shape, DeckEnd::Far).map(|k| names[k]),
        rotates,
        pivot,
        omega,
        sin_2skew: None,
        two_w_over_l: None,
        condition_holds: None,
        friction_condition_holds: None,
    };
    if let DeckShape::Skewed(d) = shape {
        rotation.sin_2skew = Some((2.0 * d.skew).sin());
        rotation.two_w_over_l = Some(2.0 * d.width / d.length);
        rotation.condition_holds = Some(d.rotates_on_abutment_impact());
        rotation.friction_condition_holds = Some(d.rotates_on_abutment_impact_with(law));
    }
    Ok(BothCornersReport {
        speed,
        contacts: corner_contacts(&s.contacts, names, &face.corners),
        post: BodyVelocity {
            velocity: xy(&s.bodies[0].velocity),
            omega,
        },
        energy: EnergyReport {
            before: s.energy_before,
            after: s.energy_after,
        },
        rotation,
        status: s.status.name(),
        post_velocity_unique: s.post_velocity_unique,
        tangential_split_unique: s.tangential_split_unique,
        trustworthy: s.status.is_trustworthy(),
    })
}

impl AbutmentReport {
    /// Whether every solve allows its numbers to be used.
    pub fn trustworthy(&self) -> bool {
        self.single.as_ref().is_none_or(|s| s.trustworthy)
            && self.both.as_ref().is_none_or(|b| b.trustworthy)
    }

    /// The readable summary (one line per entry) that `pounding impact --abutment` prints.
    pub fn summary(&self) -> Vec<String> {
        self.lines.clone()
    }

    fn head_lines(&self) -> Vec<String> {
        let i = &self.input;
        let d = &self.deck;
        let f = &d.far_face;
        let first = match (i.radius, i.angle_deg, i.length, i.skew_deg) {
            (Some(r), Some(b), _, _) => format!(
                "Curved deck R = {r} m, β = {b}°, W = {} m against a rigid abutment at its far end",
                i.width
            ),
            (_, _, Some(l), Some(sk)) => format!(
                "Skew deck L = {l} m, W = {} m, θ_s = {sk}° against a rigid abutment at its far end",
                i.width
            ),
            (_, _, l, _) => format!(
                "Straight deck L = {} m, W = {} m against a rigid abutment at its far end",
                l.unwrap_or(f64::NAN),
                i.width
            ),
        };
        vec![
            first,
            format!(
                "  A = {} m², m = {} kg, I = {} kg m², G = ({}, {}) m; gap {} m closes after {} m along the axis",
                readable(d.area),
                readable(d.mass),
                readable(d.inertia),
                readable(d.centroid[0]),
                readable(d.centroid[1]),
                i.gap,
                readable(self.abutment.travel_to_contact)
            ),
            format!(
                "  far face: {} corner c0 = ({}, {}), {} corner c1 = ({}, {}), outward normal ({}, {}); μ = {}, ε_N = {}",
                f.corner_names[0],
                readable(f.corners[0][0]),
                readable(f.corners[0][1]),
                f.corner_names[1],
                readable(f.corners[1][0]),
                readable(f.corners[1][1]),
                readable(f.outward_normal[0]),
                readable(f.outward_normal[1]),
                i.mu,
                i.eps
            ),
        ]
    }
}

impl SingleCornerReport {
    fn summary(&self, lines: &mut Vec<String>) {
        lines.push(format!(
            "Corner {} ({}) alone: arms r×n = {} m, r×t = {} m",
            self.corner_index,
            self.corner_name,
            readable(self.lever_arms.normal),
            readable(self.lever_arms.tangential)
        ));
        let g = &self.delassus;
        lines.push(format!(
            "  Delassus: G_NN = {}  G_NT = {}  G_TT = {}  [1/kg]   κ = {:.6}  ϱ = {:.6}",
            readable(g.nn),
            readable(g.nt),
            readable(g.tt),
            self.kappa,
            self.varrho
        ));
        lines.push(format!(
            "  stick interval in r = γ_T⁻/γ_N⁻: [{}, {}]   (t points from c0 to c1; r < L: slip-positive, r > U: slip-negative)",
            readable(self.stick_interval.lower),
            readable(self.stick_interval.upper)
        ));
        lines.push(format!(
            "  longitudinal approach: r = {} → {}",
            readable(self.longitudinal.ratio),
            self.longitudinal.mode
        ));
        if let Some(s) = &self.impact {
            s.summary(lines);
        }
    }
}

impl BothCornersReport {
    fn summary(&self, shape: &DeckShape, mu: f64, lines: &mut Vec<String>) {
        lines.push(format!(
            "Both corners strike after a longitudinal approach at {} m/s: {}",
            self.speed, self.status
        ));
        super::common::corner_lines("", &self.contacts, self.tangential_split_unique, lines);
        lines.push(format!(
            "  v⁺ = ({}, {}) m/s, ω⁺ = {} rad/s; kinetic energy {} J → {} J",
            readable(self.post.velocity[0]),
            readable(self.post.velocity[1]),
            readable(self.post.omega),
            readable(self.energy.before),
            readable(self.energy.after)
        ));
        let r = &self.rotation;
        lines.push(match r.pivot {
            Some(p) => {
                format!("  the deck rotates about its {p} corner (the other corner separates)")
            }
            None if r.rotates => "  the deck rotates (both corners keep impulse)".to_string(),
            None => "  no rotation: both corners stay in contact".to_string(),
        });
        let predicted = r.predicted_pivot.map_or("no rotation".to_string(), |p| {
            format!("rotation about the {p} corner")
        });
        lines.push(match (r.sin_2skew, r.two_w_over_l) {
            (Some(s2), Some(wl)) => format!(
                "  frictionless criterion: sin 2θ_s = {s2:.6} {} 2W/L = {wl:.6} → {predicted}",
                if r.condition_holds == Some(true) {
                    ">"
                } else {
                    "≤"
                },
            ),
            _ => format!("  frictionless criterion (centroid's foot beyond the face): {predicted}"),
        });
        if matches!(shape, DeckShape::Skewed(_)) && mu > 0.0 {
            lines.push(format!(
                "  with friction: sin 2θ_s − μ_eff (1 + cos 2θ_s) > 2W/L, μ_eff = min(μ, tan θ_s/(1+ε)): {}",
                if r.friction_condition_holds == Some(true) {
                    "rotation about the obtuse corner"
                } else {
                    "no rotation"
                }
            ));
        }
    }
}
