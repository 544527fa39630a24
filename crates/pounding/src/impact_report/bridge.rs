//! The bridge form: two S-curved decks in a given pose, one candidate contact (the paper's model).

use super::common::{
    DelassusReport, IntervalReport, ReportError, SingleImpactReport, invalid, readable, xy,
};
use crate::analytic::{self, ImpactLaw};
use crate::geometry::{
    ContactCase, ContactDetection, MassProperties, SigmaMode, validate_rotation,
};
use crate::impact::{self, ContactMode};
use crate::lcp::LemkeSettings;
use crate::output::float_token;
use crate::pair::SArrangement;
use crate::shape::Deck;
use serde::Serialize;

/// Input of the bridge form. Angles in degrees, lengths in m, density in kg/m³.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeInput {
    /// Centre-line radius of deck 1 `R1` \[m\] (> W/2).
    pub r1: f64,
    /// Centre-line radius of deck 2 `R2` \[m\] (> W/2).
    pub r2: f64,
    /// Curve angle of deck 1 `β1` \[deg\], in (0, 360).
    pub beta1_deg: f64,
    /// Curve angle of deck 2 `β2` \[deg\], in (0, 360).
    pub beta2_deg: f64,
    /// Deck width `W` \[m\] (both decks).
    pub width: f64,
    /// Deck thickness `t` \[m\] (both decks).
    pub thickness: f64,
    /// Density `ρ` \[kg/m³\] (both decks).
    pub density: f64,
    /// Rotation of deck 1 `θ1` \[deg\], counter-clockwise, `|θ| < 90`.
    pub theta1_deg: f64,
    /// Rotation of deck 2 `θ2` \[deg\], counter-clockwise, `|θ| < 90`.
    pub theta2_deg: f64,
    /// The candidate contact.
    pub case: ContactCase,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub mu: f64,
    /// Newton restitution coefficient `ε_N ∈ \[0, 1\]`.
    pub eps: f64,
    /// Where the struck point lies (exact corner or the paper's face-end idealisation).
    pub sigma_mode: SigmaMode,
    /// Pre-impact ratio `r = γ_T⁻/γ_N⁻` (solved with `γ_N⁻ = −1 m/s`): also solve the impact.
    pub ratio: Option<f64>,
    /// Joint opening `g` \[m\]: also report which corner touches first (spec §5.5).
    pub opening: Option<f64>,
}

/// The input as echoed in the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BridgeEcho {
    /// Contact case name.
    pub case: &'static str,
    /// `θ1` \[deg\].
    pub theta1_deg: f64,
    /// `θ2` \[deg\].
    pub theta2_deg: f64,
    /// `μ`.
    pub mu: f64,
    /// `ε_N`.
    pub eps: f64,
    /// σ mode name.
    pub sigma_mode: &'static str,
    /// `W` \[m\].
    pub width: f64,
    /// `t` \[m\].
    pub thickness: f64,
    /// `ρ` \[kg/m³\].
    pub density: f64,
}

/// Geometry and mass properties of one curved deck.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurvedDeckReport {
    /// `R` \[m\].
    pub radius: f64,
    /// `β` \[deg\].
    pub angle_deg: f64,
    /// Plan area \[m²\].
    pub area: f64,
    /// Mass \[kg\].
    pub mass: f64,
    /// Radius of the centroid \[m\].
    pub centroid_radius: f64,
    /// Centroid x in the deck frame \[m\].
    pub x_m: f64,
    /// Centroid y in the deck frame \[m\].
    pub y_m: f64,
    /// Polar moment of inertia about the centroid \[kg m²\].
    pub inertia: f64,
    /// Radius of gyration \[m\].
    pub radius_of_gyration: f64,
}

impl CurvedDeckReport {
    fn of(d: &Deck, angle_deg: f64, p: &MassProperties) -> Self {
        Self {
            radius: d.radius,
            angle_deg,
            area: p.area,
            mass: p.mass,
            centroid_radius: d.sector_centroid().centroid_radius,
            x_m: d.sector_centroid().x_m,
            y_m: d.sector_centroid().y_m,
            inertia: p.inertia,
            radius_of_gyration: p.radius_of_gyration(),
        }
    }
}

/// Contact detection at a given joint opening.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DetectionReport {
    /// The opening `g` \[m\].
    pub opening: f64,
    /// The first-contact case (`None` for a degenerate pose).
    pub first_contact_case: Option<&'static str>,
    /// Closing distance before first contact \[m\] (`None` unless the decks are apart).
    pub closing_distance: Option<f64>,
    /// Overlap of the stated pose \[m\] (`None` unless the decks interpenetrate).
    pub overlap: Option<f64>,
    /// The degeneracy of the pose (not in the JSON; `None` unless degenerate).
    #[serde(skip)]
    pub degeneracy: Option<&'static str>,
}

/// The report of the bridge form (the JSON of `pounding impact --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BridgeReport {
    /// The input.
    pub input: BridgeEcho,
    /// Both decks.
    pub decks: [CurvedDeckReport; 2],
    /// The degeneracy of the pose, if any (then the single-impact model does not apply).
    pub degenerate: Option<&'static str>,
    /// Whether the candidate is the first contact.
    pub first_contact: bool,
    /// Whether the end closes.
    pub end_closes: bool,
    /// Gap `h` of the candidate \[m\] (`NaN` when degenerate).
    pub h: f64,
    /// `σ` \[m\] (`NaN` when degenerate).
    pub sigma: f64,
    /// Contact point \[m\] (absent when degenerate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point: Option<[f64; 2]>,
    /// Contact normal (absent when degenerate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub normal: Option<[f64; 2]>,
    /// Contact tangent (absent when degenerate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangent: Option<[f64; 2]>,
    /// Delassus entries.
    pub delassus: DelassusReport,
    /// `κ = G_NT / G_NN`.
    pub kappa: f64,
    /// `ϱ = G_TT / G_NN`.
    pub varrho: f64,
    /// The stick interval.
    pub stick_interval: IntervalReport,
    /// Whether one bound is infinite (Painlevé-type regime; absent when degenerate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub painleve: Option<bool>,
    /// The impact at the given ratio (flattened: `ratio`, `mode`, `impulse`, `post`, …).
    #[serde(flatten)]
    pub impact: Option<SingleImpactReport>,
    /// Contact detection at the given opening.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub detection: Option<DetectionReport>,
}

/// Bridge label of a mode (spec §10): γ_T⁺ > 0 is `slip-outward`, γ_T⁺ < 0 `slip-inward`.
pub fn bridge_label(m: ContactMode) -> &'static str {
    match m {
        ContactMode::Open => "open",
        ContactMode::Stick => "stick",
        ContactMode::SlipPositive => "slip-outward",
        ContactMode::SlipNegative => "slip-inward",
    }
}

/// Computes the bridge form: mass properties, the candidate's configuration, Delassus entries,
/// stick interval and, when asked, the impact at `ratio` and the detection at `opening`.
pub fn bridge_report(a: &BridgeInput) -> Result<BridgeReport, ReportError> {
    let d1 = Deck::new(
        a.r1,
        a.beta1_deg.to_radians(),
        a.width,
        a.thickness,
        a.density,
    )
    .map_err(|e| e.for_deck(1))?;
    let d2 = Deck::new(
        a.r2,
        a.beta2_deg.to_radians(),
        a.width,
        a.thickness,
        a.density,
    )
    .map_err(|e| e.for_deck(2))?;
    let s = SArrangement::new(d1, d2)?;
    for (name, t) in [("theta1", a.theta1_deg), ("theta2", a.theta2_deg)] {
        if !(t.is_finite() && t.abs() < 90.0) {
            return Err(invalid(
                name,
                float_token(t),
                "the rotation must be finite with |theta| < 90 deg",
            ));
        }
    }
    let (t1r, t2r) = (a.theta1_deg.to_radians(), a.theta2_deg.to_radians());
    validate_rotation("theta1", t1r)?;
    validate_rotation("theta2", t2r)?;
    let law = ImpactLaw::new(a.mu, a.eps)?;
    if let Some(r) = a.ratio.filter(|r| !r.is_finite()) {
        return Err(invalid("ratio", r, "must be finite"));
    }
    if let Some(g) = a.opening.filter(|g| !g.is_finite()) {
        return Err(invalid("opening", g, "must be finite"));
    }
    let (p1, p2) = (d1.mass_properties(), d2.mass_properties());
    let mut rep = BridgeReport {
        input: BridgeEcho {
            case: a.case.name(),
            theta1_deg: a.theta1_deg,
            theta2_deg: a.theta2_deg,
            mu: a.mu,
            eps: a.eps,
            sigma_mode: a.sigma_mode.name(),
            width: a.width,
            thickness: a.thickness,
            density: a.density,
        },
        decks: [
            CurvedDeckReport::of(&d1, a.beta1_deg, &p1),
            CurvedDeckReport::of(&d2, a.beta2_deg, &p2),
        ],
        degenerate: None,
        first_contact: false,
        end_closes: false,
        h: f64::NAN,
        sigma: f64::NAN,
        point: None,
        normal: None,
        tangent: None,
        delassus: DelassusReport::UNDEFINED,
        kappa: f64::NAN,
        varrho: f64::NAN,
        stick_interval: IntervalReport {
            lower: f64::NAN,
            upper: f64::NAN,
        },
        painleve: None,
        impact: a.ratio.map(SingleImpactReport::undefined),
        detection: a
            .opening
            .map(|g| detection(g, s.detect_contact(t1r, t2r, g))),
    };
    match s.configuration(a.case, t1r, t2r, a.sigma_mode) {
        Err(d) => rep.degenerate = Some(d.name()),
        Ok(c) => {
            let g = s.delassus(&c);
            let bounds = analytic::stick_interval(&g, &law);
            rep.first_contact = c.first_contact;
            rep.end_closes = c.end_closes;
            rep.h = c.h;
            rep.sigma = c.sigma;
            rep.point = Some(xy(&c.point));
            rep.normal = Some(xy(&c.normal));
            rep.tangent = Some(xy(&c.tangent));
            rep.delassus = DelassusReport::of(&g);
            rep.kappa = g.kappa();
            rep.varrho = g.varrho();
            rep.stick_interval = IntervalReport::of(&bounds);
            rep.painleve = Some(analytic::is_painleve(&g, &law));
            rep.impact = a.ratio.map(|r| {
                let sol = impact::solve_single(&g, &law, -1.0, -r, &LemkeSettings::default());
                SingleImpactReport::of(r, &sol, bridge_label(sol.mode))
            });
        }
    }
    Ok(rep)
}

fn detection(opening: f64, d: ContactDetection) -> DetectionReport {
    let mut rep = DetectionReport {
        opening,
        first_contact_case: None,
        closing_distance: None,
        overlap: None,
        degeneracy: None,
    };
    match d {
        ContactDetection::Contact {
            case,
            closing_distance,
        } => {
            rep.first_contact_case = Some(case.name());
            rep.closing_distance = Some(closing_distance);
        }
        ContactDetection::Overlap { case, overlap } => {
            rep.first_contact_case = Some(case.name());
            rep.overlap = Some(overlap);
        }
        ContactDetection::Degenerate(k) => rep.degeneracy = Some(k.name()),
    }
    rep
}

impl BridgeReport {
    /// Whether the impact solve (if any) allows its numbers to be used.
    pub fn trustworthy(&self) -> bool {
        self.impact.as_ref().is_none_or(|i| i.trustworthy)
    }

    /// The readable summary (one line per entry) that `pounding impact` prints.
    pub fn summary(&self) -> Vec<String> {
        let mut lines = Vec::new();
        let i = &self.input;
        lines.push(format!(
            "Two S-curved decks, W = {} m, t = {} m, ρ = {} kg/m³",
            i.width, i.thickness, i.density
        ));
        for (j, d) in self.decks.iter().enumerate() {
            lines.push(format!(
                "  deck {}: R = {} m, β = {}°: A = {:.6} m², m = {} kg, r_c = {:.6} m, I = {} kg m²",
                j + 1,
                d.radius,
                d.angle_deg,
                d.area,
                readable(d.mass),
                d.centroid_radius,
                readable(d.inertia)
            ));
        }
        lines.push(format!(
            "Case {}, θ1 = {}°, θ2 = {}°, μ = {}, ε_N = {}, σ mode {}",
            i.case, i.theta1_deg, i.theta2_deg, i.mu, i.eps, i.sigma_mode
        ));
        if let Some(d) = self.degenerate {
            lines.push(format!(
                "Degenerate pose ({d}): the single-impact model does not apply."
            ));
        } else {
            self.pose_summary(&mut lines);
        }
        if let Some(d) = &self.detection {
            let g = d.opening;
            lines.push(match (d.first_contact_case, d.closing_distance, d.overlap) {
                (Some(case), Some(c), _) => format!(
                    "At opening g = {g} m the first contact is {case} after closing {} m.",
                    readable(c)
                ),
                (Some(case), None, Some(o)) => format!(
                    "At opening g = {g} m the decks already overlap by {} m (first contact {case}).",
                    readable(o)
                ),
                _ => format!(
                    "At opening g = {g} m: degenerate pose ({}).",
                    d.degeneracy.unwrap_or("-")
                ),
            });
        }
        lines
    }

    fn pose_summary(&self, lines: &mut Vec<String>) {
        lines.push(format!(
            "  first contact: {}   end closes: {}   h = {:.6} m   σ = {:.9} m",
            self.first_contact, self.end_closes, self.h, self.sigma
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
            "  stick interval in r = γ_T⁻/γ_N⁻: [{}, {}]{}",
            readable(self.stick_interval.lower),
            readable(self.stick_interval.upper),
            if self.painleve == Some(true) {
                "  (Painlevé-type regime: one bound infinite)"
            } else {
                ""
            }
        ));
        lines.push("  r < L: slip-outward; L ≤ r ≤ U: stick; r > U: slip-inward".to_string());
        if let Some(s) = &self.impact {
            s.summary(lines);
        }
    }
}
