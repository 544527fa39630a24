//! Scenario sections added for compliance contact laws (issue 7): `[contact]` (the joint's normal
//! contact law and its parameters) and the straight-deck / dashpot keys of `[decks]` and
//! `[bearings]`. A child module of `cmd_simulate` (uses its `Source` for error locations).

use super::Source;
use anyhow::{Result, anyhow, bail};
use pounding::contact_law::calibration::{
    HertzDampCalibration, JankowskiCalibration, KelvinCalibration,
};
use pounding::contact_law::{
    BilinearImpact, ContactLaw, ContactLawError, Hertz, HertzDamp, HertzDamping, Jankowski,
    KelvinVoigt, units,
};
use pounding::sim::{ComplianceContact, JointContact};
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
#[derive(Deserialize, Default, Clone)]
#[serde(deny_unknown_fields, default)]
pub struct ContactSec {
    /// `rigid` (default), `kelvin`, `hertz`, `hertz-damp`, `bilinear`, `jankowski`.
    pub law: Option<String>,
    pub k: Option<f64>,
    pub c: Option<f64>,
    pub k_h: Option<f64>,
    pub zeta: Option<f64>,
    pub chi: Option<f64>,
    pub restitution: Option<f64>,
    pub calibration: Option<String>,
    pub design_velocity: Option<f64>,
    pub min_velocity: Option<f64>,
    pub k1: Option<f64>,
    pub k2: Option<f64>,
    pub delta_y: Option<f64>,
    pub delta_m: Option<f64>,
    pub a: Option<f64>,
    pub beta: Option<f64>,
    pub xi: Option<f64>,
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

fn law_err(src: &Source, e: ContactLawError) -> anyhow::Error {
    let ContactLawError::InvalidParameter { name, .. } = &e;
    let key = match name.as_str() {
        n @ ("k" | "c" | "k_h" | "zeta" | "chi" | "restitution" | "design_velocity"
        | "min_velocity" | "k1" | "k2" | "delta_y" | "delta_m" | "a" | "beta" | "xi") => n,
        _ => return anyhow!("{e}"),
    };
    let mut msg = format!("{e} — set by {}", src.key_ref("contact", key));
    if key == "restitution" && src.line_of("contact", "restitution").is_none() {
        msg.push_str(" (the default is `[joint] eps_n`)");
    }
    anyhow!(msg)
}

/// Every parameter key of `[contact]` (all but `law`).
const CONTACT_KEYS: [&str; 17] = [
    "k",
    "c",
    "k_h",
    "zeta",
    "chi",
    "restitution",
    "calibration",
    "design_velocity",
    "min_velocity",
    "k1",
    "k2",
    "delta_y",
    "delta_m",
    "a",
    "beta",
    "xi",
    "friction_velocity",
];

/// The `[contact]` keys law `name` reads with the keys given in `sec` (which of a law's ways
/// to set its damping is taken depends on them), and a description of that way.
fn used_keys(name: &str, sec: &ContactSec) -> (Vec<&'static str>, &'static str) {
    let (keys, how): (&[&str], &str) = match name {
        "kelvin" if sec.c.is_some() => (&["k", "c"], " with c given"),
        "kelvin" => (&["k", "restitution", "calibration"], " without c"),
        "hertz" => (&["k_h"], ""),
        "hertz-damp" if sec.zeta.is_some() => (&["k_h", "zeta"], " with zeta given"),
        "hertz-damp" if sec.chi.is_some() => (&["k_h", "chi", "min_velocity"], " with chi given"),
        "hertz-damp" => (
            &[
                "k_h",
                "restitution",
                "calibration",
                "design_velocity",
                "min_velocity",
            ],
            " without zeta or chi",
        ),
        "bilinear" if sec.k1.is_some() || sec.k2.is_some() || sec.delta_y.is_some() => {
            (&["k1", "k2", "delta_y"], " with k1, k2, delta_y given")
        }
        "bilinear" => (
            &["k_h", "restitution", "delta_m", "a"],
            " without k1, k2, delta_y",
        ),
        // beta wins over k_h
        "jankowski" if sec.beta.is_some() && sec.xi.is_some() => {
            (&["beta", "xi"], " with beta and xi given")
        }
        "jankowski" if sec.beta.is_some() => {
            (&["beta", "restitution", "calibration"], " with beta given")
        }
        "jankowski" if sec.xi.is_some() => (&["k_h", "xi"], " with xi given"),
        "jankowski" => (&["k_h", "restitution", "calibration"], ""),
        _ => (&[], ""),
    };
    let mut keys = keys.to_vec();
    if name != "rigid" {
        keys.push("friction_velocity");
    }
    (keys, how)
}

/// Refuses a `[contact]` key that law `name` does not read (`simulate` only: `compare` builds
/// every law from the same section, so there a key of another law is no error).
fn refuse_unused_keys(src: &Source, sec: &ContactSec, name: &str) -> Result<()> {
    if !LAW_NAMES.contains(&name) {
        return Ok(()); // reported with the list of laws by build_contact
    }
    let (used, how) = used_keys(name, sec);
    for key in CONTACT_KEYS {
        if used.contains(&key) || src.line_of("contact", key).is_none() {
            continue;
        }
        if name == "rigid" {
            bail!(
                "{key} applies to compliance laws ({}), not to law = \"rigid\" (rigid contact \
                 uses `[joint] eps_n` and `[joint] mu`) — set by {}",
                LAW_NAMES[1..].join(", "),
                src.key_ref("contact", key)
            );
        }
        bail!(
            "{key} is not used by law = \"{name}\"{how} (it reads {}) — set by {}",
            used.join(", "),
            src.key_ref("contact", key)
        );
    }
    Ok(())
}

/// Builds the joint contact for `law` (overriding `[contact] law` when given) from the section;
/// `eps_n` is the default restitution, `masses` the deck masses (Kelvin, Jankowski calibrations).
pub(super) fn build_contact(
    src: &Source,
    sec: &ContactSec,
    law: Option<&str>,
    eps_n: f64,
    masses: [f64; 2],
) -> Result<JointContact> {
    let name = law
        .map(str::to_string)
        .or_else(|| sec.law.clone())
        .unwrap_or_else(|| "rigid".into());
    if law.is_none() {
        refuse_unused_keys(src, sec, &name)?;
    }
    let e = sec.restitution.unwrap_or(eps_n);
    let cal = sec.calibration.as_deref().unwrap_or("numerical");
    let bad_cal = |allowed: &str| {
        anyhow!(
            "invalid calibration {cal:?} for law {name:?} at {}: use {allowed}",
            src.key_ref("contact", "calibration")
        )
    };
    let le = |r: Result<ContactLaw, ContactLawError>| r.map_err(|e| law_err(src, e));
    let law: ContactLaw = match name.as_str() {
        "rigid" => return Ok(JointContact::Rigid),
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
            _ => bail!(
                "law \"bilinear\": give all of {}, {} and {} (or none, to derive them from k_h, \
                 restitution, delta_m, a)",
                src.key_ref("contact", "k1"),
                src.key_ref("contact", "k2"),
                src.key_ref("contact", "delta_y")
            ),
        })?,
        "jankowski" => {
            let beta = sec.beta.or(sec.k_h).unwrap_or_else(default_k_h);
            le(match sec.xi {
                Some(xi) => pounding::contact_law::effective_mass(masses[0], masses[1])
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
        other => bail!(
            "unknown contact law {other:?} at {}: use one of {}",
            src.key_ref("contact", "law"),
            LAW_NAMES.join(", ")
        ),
    };
    let mut cc = ComplianceContact::new(law);
    if let Some(v) = sec.friction_velocity {
        if !(v.is_finite() && v > 0.0) {
            bail!(
                "invalid friction_velocity = {}: must be finite and > 0 — set by {}",
                pounding::output::float_token(v),
                src.key_ref("contact", "friction_velocity")
            );
        }
        cc.friction_velocity = v;
    }
    Ok(JointContact::Compliance(cc))
}

/// Short description of a joint contact for summaries.
pub fn describe(c: &JointContact) -> serde_json::Value {
    use pounding::output::json_float;
    match c {
        JointContact::Rigid => serde_json::json!({"law": "rigid"}),
        JointContact::Compliance(cc) => {
            let mut v = match &cc.law {
                ContactLaw::KelvinVoigt(l) => {
                    serde_json::json!({"law": "kelvin", "k": json_float(l.k()), "c": json_float(l.c())})
                }
                ContactLaw::Hertz(l) => {
                    serde_json::json!({"law": "hertz", "k_h": json_float(l.k_h())})
                }
                ContactLaw::HertzDamp(l) => {
                    let d = match l.damping() {
                        HertzDamping::Constant { zeta } => {
                            serde_json::json!({"zeta": json_float(zeta)})
                        }
                        HertzDamping::PerImpact { chi, min_velocity } => {
                            serde_json::json!({"chi": json_float(chi), "min_velocity": json_float(min_velocity)})
                        }
                    };
                    serde_json::json!({"law": "hertz-damp", "k_h": json_float(l.k_h()), "damping": d})
                }
                ContactLaw::Bilinear(l) => serde_json::json!({
                    "law": "bilinear", "k1": json_float(l.k1()), "k2": json_float(l.k2()),
                    "delta_y": json_float(l.delta_y())
                }),
                ContactLaw::Jankowski(l) => serde_json::json!({
                    "law": "jankowski", "beta": json_float(l.beta()), "xi": json_float(l.xi()),
                    "m_eff": json_float(l.m_eff())
                }),
            };
            v["friction_velocity"] = json_float(cc.friction_velocity);
            v
        }
    }
}

/// `[decks] mass1`, `mass2` (the deck's mass given directly: its density becomes
/// `ρ m / m(ρ)`, any shape) and `[bearings] damping = "rayleigh" | "dashpots"`.
pub(super) fn apply_shape_and_damping(
    src: &Source,
    d: &super::DecksSec,
    damping: &str,
    model: &mut pounding::sim::SimModel,
) -> Result<()> {
    use pounding::shape::DeckShape;
    use pounding::sim::DampingModel;
    let current = model.masses();
    for (j, m, key) in [(0, d.mass1, "mass1"), (1, d.mass2, "mass2")] {
        let Some(m) = m else { continue };
        if !(m.is_finite() && m > 0.0) {
            bail!(
                "invalid {key} = {}: must be finite and > 0 — set by {}",
                pounding::output::float_token(m),
                src.key_ref("decks", key)
            );
        }
        let f = m / current[j];
        match &mut model.shapes {
            Some(sh) => match &mut sh[j] {
                DeckShape::Straight(x) => x.density *= f,
                DeckShape::Skewed(x) => x.density *= f,
                DeckShape::Curved(x) => x.density *= f,
            },
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
        other => bail!(
            "unknown damping {other:?} at {}: use \"rayleigh\" or \"dashpots\"",
            src.key_ref("bearings", "damping")
        ),
    };
    Ok(())
}

/// Adds the compliance-law fields to a `summary.json` value (nothing for rigid contact, so the
/// rigid summary keeps its keys): `contact_law` (parameters), `time_step` (contact duration,
/// steps per contact, adequate), `newton_failures`.
pub(super) fn add_compliance_summary(
    v: &mut serde_json::Value,
    m: &pounding::sim::SimModel,
    sol: &pounding::sim::SimSolution,
) {
    use pounding::output::json_float;
    if matches!(m.contact, JointContact::Rigid) {
        return;
    }
    v["contact_law"] = describe(&m.contact);
    v["model"]["damping"] = serde_json::json!(format!("{:?}", m.damping_model));
    if let Some(a) = &sol.time_step_advice {
        v["time_step"] = serde_json::json!({
            "contact_duration_s": json_float(a.contact_duration),
            "steps_per_contact": json_float(a.steps_per_contact),
            "max_step_s": json_float(a.max_step),
            "adequate": a.adequate,
        });
    }
    v["newton_failures"] = serde_json::json!(sol.newton_failures);
    v["closure_steps"] = serde_json::json!(sol.closure_steps);
}
