//! `[contact]`: the joint's normal contact law (rigid, or one of the compliance laws with its
//! parameters and calibrations), and the `[decks] mass1`/`mass2` and `[bearings] damping` keys.

use super::Src;
use super::error::{ParamKey, ScenarioError, Section};
use super::sections::DecksSec;
use crate::contact_law::calibration::{
    HertzDampCalibration, JankowskiCalibration, KelvinCalibration,
};
use crate::contact_law::{
    BilinearImpact, ContactLaw, ContactLawError, Hertz, HertzDamp, HertzDamping, Jankowski,
    KelvinVoigt, units,
};
use crate::sim::{ComplianceContact, DampingModel, JointContact, SimModel};
use serde::Deserialize;

/// Names accepted by `[contact] law` and `pounding compare --laws`.
pub const LAW_NAMES: [&str; 6] = [
    "rigid",
    "kelvin",
    "hertz",
    "hertz-damp",
    "bilinear",
    "jankowski",
];

/// `[contact]`: the joint's normal contact law. Every key optional.
#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub struct ContactSec {
    /// `rigid` (default), `kelvin`, `hertz`, `hertz-damp`, `bilinear`, `jankowski`.
    pub law: Option<String>,
    /// Kelvin stiffness \\[N/m\\].
    pub k: Option<f64>,
    /// Kelvin damping \\[N s/m\\] (instead of `restitution`).
    pub c: Option<f64>,
    /// Hertz stiffness \\[N/m^1.5\\].
    pub k_h: Option<f64>,
    /// Hertz-damp constant damping ratio.
    pub zeta: Option<f64>,
    /// Hertz-damp per-impact damping factor.
    pub chi: Option<f64>,
    /// Target restitution of the damped laws (default: `\\[joint\\] eps_n`).
    pub restitution: Option<f64>,
    /// How the damping follows from `restitution`.
    pub calibration: Option<String>,
    /// Hertz-damp design impact velocity \\[m/s\\].
    pub design_velocity: Option<f64>,
    /// Hertz-damp floor of the impact velocity \\[m/s\\].
    pub min_velocity: Option<f64>,
    /// Bilinear first stiffness \\[N/m\\].
    pub k1: Option<f64>,
    /// Bilinear second stiffness \\[N/m\\].
    pub k2: Option<f64>,
    /// Bilinear yield penetration \\[m\\].
    pub delta_y: Option<f64>,
    /// Bilinear design maximum penetration \\[m\\].
    pub delta_m: Option<f64>,
    /// Bilinear yield ratio.
    pub a: Option<f64>,
    /// Jankowski stiffness \\[N/m^1.5\\].
    pub beta: Option<f64>,
    /// Jankowski damping ratio.
    pub xi: Option<f64>,
    /// Regularisation velocity of Coulomb friction \\[m/s\\].
    pub friction_velocity: Option<f64>,
}

/// Default Kelvin stiffness \[N/m\] (the order of the bilinear `K1` of the OpenSees benchmark).
pub const DEFAULT_K: f64 = 1.0e10;
/// Default design maximum penetration of the bilinear law, 1 in \[m\].
pub const DEFAULT_DELTA_M: f64 = units::INCH;
/// Default yield ratio of the bilinear law.
pub const DEFAULT_A: f64 = 0.1;
/// Default floor of the impact velocity of Hertz-damp with per-impact damping \[m/s\].
pub const DEFAULT_MIN_VELOCITY: f64 = 0.01;

/// Default Hertz stiffness 25 000 kip/in^1.5 \[N/m^1.5\] (Muthukumar & DesRoches; the OpenSees
/// benchmark).
pub fn default_k_h() -> f64 {
    units::kip_per_in_1_5(25_000.0)
}

/// A contact-law error located at the `[contact]` key that sets the parameter.
fn law_err(src: &Src, e: ContactLawError) -> ScenarioError {
    let ContactLawError::InvalidParameter { name, .. } = &e;
    let Some(key) = ParamKey::of_contact_parameter(name) else {
        return ScenarioError::Law(Box::new(e));
    };
    let at = src.at(key);
    let note = if key.key == "restitution" && at.line.is_none() {
        " (the default is `[joint] eps_n`)".to_string()
    } else {
        String::new()
    };
    ScenarioError::Invalid {
        message: e.to_string(),
        at: vec![at],
        note,
    }
}

const fn contact(key: &'static str) -> ParamKey {
    ParamKey::new(Section::Contact, key)
}

/// The compliance law `name` (not `rigid`) from the `[contact]` keys and their defaults.
fn compliance_law(
    src: &Src,
    sec: &ContactSec,
    name: &str,
    eps_n: f64,
    masses: [f64; 2],
) -> Result<ContactLaw, ScenarioError> {
    let e = sec.restitution.unwrap_or(eps_n);
    let cal = sec.calibration.as_deref().unwrap_or("numerical");
    let bad_cal = |allowed: &str| {
        src.key_error(
            format!(
                "invalid calibration {cal:?} for law {name:?} at {}: use {allowed}",
                src.at(contact("calibration"))
            ),
            &[contact("calibration")],
        )
    };
    let le = |r: Result<ContactLaw, ContactLawError>| r.map_err(|e| law_err(src, e));
    Ok(match name {
        "kelvin" => {
            let k = sec.k.unwrap_or(DEFAULT_K);
            le(match sec.c {
                Some(c) => KelvinVoigt::new(k, c).map(Into::into),
                None => {
                    let m = match cal {
                        "numerical" => KelvinCalibration::Numerical,
                        "anagnostopoulos" => KelvinCalibration::Anagnostopoulos,
                        _ => return Err(bad_cal("\"numerical\" or \"anagnostopoulos\"")),
                    };
                    KelvinVoigt::from_restitution(k, e, masses[0], masses[1], m).map(Into::into)
                }
            })?
        }
        "hertz" => le(Hertz::new(sec.k_h.unwrap_or_else(default_k_h)).map(Into::into))?,
        "hertz-damp" => {
            let k_h = sec.k_h.unwrap_or_else(default_k_h);
            let vmin = sec.min_velocity.unwrap_or(DEFAULT_MIN_VELOCITY);
            le(match (sec.zeta, sec.chi) {
                (Some(zeta), _) => HertzDamp::new(k_h, HertzDamping::Constant { zeta }),
                (None, Some(chi)) => HertzDamp::new(
                    k_h,
                    HertzDamping::PerImpact {
                        chi,
                        min_velocity: vmin,
                    },
                ),
                (None, None) => {
                    let m = match cal {
                        "numerical" => HertzDampCalibration::Numerical,
                        "muthukumar-desroches" => HertzDampCalibration::MuthukumarDesRoches,
                        "ye" => HertzDampCalibration::YeEtAl,
                        _ => {
                            return Err(bad_cal(
                                "\"numerical\", \"muthukumar-desroches\" or \"ye\"",
                            ));
                        }
                    };
                    HertzDamp::from_restitution(k_h, e, sec.design_velocity, vmin, m)
                }
            }
            .map(Into::into))?
        }
        "bilinear" => le(match (sec.k1, sec.k2, sec.delta_y) {
            (None, None, None) => BilinearImpact::from_hertz(
                sec.k_h.unwrap_or_else(default_k_h),
                e,
                sec.delta_m.unwrap_or(DEFAULT_DELTA_M),
                sec.a.unwrap_or(DEFAULT_A),
            )
            .map(|d| d.law.into()),
            (Some(k1), Some(k2), Some(dy)) => BilinearImpact::new(k1, k2, dy).map(Into::into),
            _ => {
                let keys = [contact("k1"), contact("k2"), contact("delta_y")];
                return Err(src.key_error(
                    format!(
                        "law \"bilinear\": give all of {}, {} and {} (or none, to derive them \
                         from k_h, restitution, delta_m, a)",
                        src.at(keys[0]),
                        src.at(keys[1]),
                        src.at(keys[2])
                    ),
                    &keys,
                ));
            }
        })?,
        "jankowski" => {
            let beta = sec.beta.or(sec.k_h).unwrap_or_else(default_k_h);
            le(match sec.xi {
                Some(xi) => crate::contact_law::effective_mass(masses[0], masses[1])
                    .and_then(|m| Jankowski::new(beta, xi, m))
                    .map(Into::into),
                None => {
                    let m = match cal {
                        "numerical" => JankowskiCalibration::Numerical,
                        "jankowski2005" => JankowskiCalibration::Jankowski2005,
                        _ => return Err(bad_cal("\"numerical\" or \"jankowski2005\"")),
                    };
                    Jankowski::from_restitution(beta, e, masses[0], masses[1], m).map(Into::into)
                }
            })?
        }
        other => {
            return Err(src.key_error(
                format!(
                    "unknown contact law {other:?} at {}: use one of {}",
                    src.at(contact("law")),
                    LAW_NAMES.join(", ")
                ),
                &[contact("law")],
            ));
        }
    })
}

/// Builds the joint contact for `law` (overriding `[contact] law` when given) from the section;
/// `eps_n` is the default restitution, `masses` the deck masses (Kelvin, Jankowski calibrations).
pub(super) fn build_contact(
    src: &Src,
    sec: &ContactSec,
    law: Option<&str>,
    eps_n: f64,
    masses: [f64; 2],
) -> Result<JointContact, ScenarioError> {
    let name = law
        .map(str::to_string)
        .or_else(|| sec.law.clone())
        .unwrap_or_else(|| "rigid".into());
    if name == "rigid" {
        return Ok(JointContact::Rigid);
    }
    let law = compliance_law(src, sec, &name, eps_n, masses)?;
    let mut cc = ComplianceContact::new(law);
    if let Some(v) = sec.friction_velocity {
        if !(v.is_finite() && v > 0.0) {
            return Err(src.invalid(
                format!("invalid friction_velocity = {v}: must be finite and > 0"),
                contact("friction_velocity"),
            ));
        }
        cc.friction_velocity = v;
    }
    Ok(JointContact::Compliance(cc))
}

/// `[decks] mass1`, `mass2` (the deck's mass given directly: its density becomes
/// `ρ m / m(ρ)`, any shape) and `[bearings] damping = "rayleigh" | "dashpots"`.
pub(super) fn apply_shape_and_damping(
    src: &Src,
    d: &DecksSec,
    damping: &str,
    model: &mut SimModel,
) -> Result<(), ScenarioError> {
    let current = model.masses();
    for (j, m, key) in [(0, d.mass1, "mass1"), (1, d.mass2, "mass2")] {
        let Some(m) = m else { continue };
        if !(m.is_finite() && m > 0.0) {
            return Err(src.invalid(
                format!("invalid {key} = {m}: must be finite and > 0"),
                ParamKey::of_deck(Section::Decks, key, j as u8 + 1),
            ));
        }
        let f = m / current[j];
        match &mut model.shapes {
            Some(sh) => sh[j].scale_density(f),
            None => {
                if j == 0 {
                    model.arrangement.deck1.density *= f;
                } else {
                    model.arrangement.deck2.density *= f;
                }
            }
        }
    }
    model.damping_model = match damping {
        "rayleigh" => DampingModel::Rayleigh,
        "dashpots" => DampingModel::TranslationalDashpots,
        other => {
            let key = ParamKey::new(Section::Bearings, "damping");
            return Err(src.key_error(
                format!(
                    "unknown damping {other:?} at {}: use \"rayleigh\" or \"dashpots\"",
                    src.at(key)
                ),
                &[key],
            ));
        }
    };
    Ok(())
}
