//! The joint form: two straight or skew decks face to face at the joint.

use super::common::{
    CornerContactReport, EnergyReport, ReportError, corner_contacts, invalid, readable, xy,
};
use super::shapes::{DeckSection, ShapeSpec, check_speed, corner_names};
use crate::analytic::ImpactLaw;
use crate::geometry::GeometryError;
use crate::impact::{self, ImpactSettings, ImpactSolution};
use crate::math::Vector;
use crate::shape::{DeckEnd, joint_problem};
use serde::Serialize;

/// Input of the joint form: two straight or skew decks face to face at the joint (reference pose,
/// zero opening); deck 1 approaches along its axis at `speed`, deck 2 rests.
#[derive(Debug, Clone, PartialEq)]
pub struct JointInput {
    /// Deck 1's shape ([`ShapeSpec::Straight`] or [`ShapeSpec::Skew`]); deck 2 has the same
    /// shape with length `length2`.
    pub shape: ShapeSpec,
    /// The cross-section of both decks.
    pub section: DeckSection,
    /// Length of deck 2 \[m\] (> 0; default deck 1's).
    pub length2: Option<f64>,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub mu: f64,
    /// Newton restitution coefficient `ε_N ∈ \[0, 1\]`.
    pub eps: f64,
    /// Deck 1's approach speed \[m/s\] (> 0).
    pub speed: f64,
}

/// The joint form's input as echoed in the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointEcho {
    /// Shape name.
    pub shape: &'static str,
    /// Always `false`.
    pub abutment: bool,
    /// `μ`.
    pub mu: f64,
    /// `ε_N`.
    pub eps: f64,
    /// Speed \[m/s\].
    pub speed: f64,
    /// `W` \[m\].
    pub width: f64,
    /// `t` \[m\].
    pub thickness: f64,
    /// `ρ` \[kg/m³\].
    pub density: f64,
    /// Deck 1's length \[m\].
    pub length: f64,
    /// Deck 2's length \[m\].
    pub length2: f64,
    /// `θ_s` \[deg\] (skew).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skew_deg: Option<f64>,
}

/// One deck of the joint form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointDeckReport {
    /// Body name.
    pub name: String,
    /// Mass \[kg\].
    pub mass: f64,
    /// Moment of inertia \[kg m²\].
    pub inertia: f64,
    /// Centroid \[m\].
    pub centroid: [f64; 2],
    /// Pre-impact velocity \[m/s\].
    pub velocity_pre: [f64; 2],
    /// Post-impact velocity \[m/s\].
    pub velocity: [f64; 2],
    /// Post-impact angular velocity \[rad/s\].
    pub omega: f64,
}

/// The report of the joint form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointReport {
    /// The input.
    pub input: JointEcho,
    /// Both decks.
    pub decks: Vec<JointDeckReport>,
    /// Deck 1's joint corners.
    pub contacts: Vec<CornerContactReport>,
    /// Kinetic energy.
    pub energy: EnergyReport,
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

/// The same geometry error with the parameter renamed (deck 2's `length` is `length2`).
fn rename(e: GeometryError, from: &str, to: &str) -> GeometryError {
    match e {
        GeometryError::InvalidParameter {
            name,
            param,
            deck,
            value,
            reason,
        } => GeometryError::InvalidParameter {
            name: if name == from { to.to_string() } else { name },
            param,
            deck,
            value,
            reason,
        },
    }
}

/// Computes the joint form (both joint corners of deck 1 strike deck 2's joint face).
pub fn joint_report(a: &JointInput) -> Result<JointReport, ReportError> {
    let deck1 = a.shape.build(&a.section)?;
    let (length, skew_deg) = match a.shape {
        ShapeSpec::Straight { length } => (length, None),
        ShapeSpec::Skew { length, skew_deg } => (length, Some(skew_deg)),
        ShapeSpec::Curved { .. } => {
            return Err(invalid(
                "shape",
                "curved",
                "two curved decks use the S-curved bridge form",
            ));
        }
    };
    let length2 = a.length2.unwrap_or(length);
    let deck2 = deck1
        .with_length(length2)
        .map_err(|e| rename(e, "length", "length2"))?;
    let law = ImpactLaw::new(a.mu, a.eps)?;
    check_speed(a.speed)?;
    let v1 = a.speed * deck1.axis_direction(DeckEnd::Joint);
    let problem = joint_problem(&deck1, &deck2, (v1, 0.0), (Vector::zeros(), 0.0), &law)?;
    let s: ImpactSolution = impact::solve(&problem, &ImpactSettings::default());
    let names = corner_names(&deck1);
    let face = deck1.end_face(DeckEnd::Joint);
    Ok(JointReport {
        input: JointEcho {
            shape: deck1.name(),
            abutment: false,
            mu: a.mu,
            eps: a.eps,
            speed: a.speed,
            width: a.section.width,
            thickness: a.section.thickness,
            density: a.section.density,
            length,
            length2,
            skew_deg,
        },
        decks: problem
            .bodies()
            .iter()
            .zip(&s.bodies)
            .map(|(b, v)| JointDeckReport {
                name: b.name.clone(),
                mass: b.mass,
                inertia: b.inertia,
                centroid: xy(&b.position),
                velocity_pre: xy(&b.velocity),
                velocity: xy(&v.velocity),
                omega: v.omega,
            })
            .collect(),
        contacts: corner_contacts(&s.contacts, &names, &face.corners),
        energy: EnergyReport {
            before: s.energy_before,
            after: s.energy_after,
        },
        status: s.status.name(),
        post_velocity_unique: s.post_velocity_unique,
        tangential_split_unique: s.tangential_split_unique,
        trustworthy: s.status.is_trustworthy(),
    })
}

impl JointReport {
    /// Whether the solver status allows the numbers to be used.
    pub fn trustworthy(&self) -> bool {
        self.trustworthy
    }

    /// The readable summary (one line per entry) that `pounding impact --shape …` prints.
    pub fn summary(&self) -> Vec<String> {
        let i = &self.input;
        let mut lines = vec![format!(
            "Two {} decks face to face at the joint (W = {} m{}), deck 1 approaching along its axis at {} m/s; μ = {}, ε_N = {}: {}",
            i.shape,
            i.width,
            i.skew_deg
                .map_or(String::new(), |sk| format!(", θ_s = {sk}°")),
            i.speed,
            i.mu,
            i.eps,
            self.status
        )];
        for d in &self.decks {
            lines.push(format!(
                "  {}: m = {} kg, I = {} kg m²: v⁺ = ({}, {}) m/s, ω⁺ = {} rad/s",
                d.name,
                readable(d.mass),
                readable(d.inertia),
                readable(d.velocity[0]),
                readable(d.velocity[1]),
                readable(d.omega)
            ));
        }
        super::common::corner_lines(
            "deck 1 ",
            &self.contacts,
            self.tangential_split_unique,
            &mut lines,
        );
        lines.push(format!(
            "  kinetic energy: {} J → {} J",
            readable(self.energy.before),
            readable(self.energy.after)
        ));
        lines
    }
}
