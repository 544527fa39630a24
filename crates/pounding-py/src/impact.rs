//! `pounding.impact`: the four forms of `pounding impact` (bridge, two straight/skew decks at the
//! joint, a deck against an abutment, generic bodies and contacts), each returning the report
//! exactly as `pounding impact --json` prints it, whether it is trustworthy (the CLI's exit 0)
//! and the CLI's summary lines.

use crate::value_error;
use pounding::geometry::{ContactCase, SigmaMode};
use pounding::impact_report::{
    self as report, AbutmentInput, BridgeInput, DeckSection, JointInput, ShapeSpec,
};
use pyo3::prelude::*;
use serde::Serialize;

/// What every form returns: `(report JSON text, trustworthy, summary lines)`.
type Out = (String, bool, Vec<String>);

fn out<T: Serialize>(rep: &T, trustworthy: bool, lines: Vec<String>) -> PyResult<Out> {
    let json =
        report::to_json_pretty(rep).map_err(|e| crate::SolverError::new_err(e.to_string()))?;
    Ok((json, trustworthy, lines))
}

/// The bridge form (two S-curved decks): `pounding impact --r1 ... --eps ... --json`.
#[pyfunction]
#[pyo3(signature = (r1, r2, beta1, beta2, theta1, theta2, case, mu, eps, width, thickness, density, sigma_mode, ratio, opening))]
#[allow(clippy::too_many_arguments)]
fn impact_bridge(
    r1: f64,
    r2: f64,
    beta1: f64,
    beta2: f64,
    theta1: f64,
    theta2: f64,
    case: &str,
    mu: f64,
    eps: f64,
    width: f64,
    thickness: f64,
    density: f64,
    sigma_mode: &str,
    ratio: Option<f64>,
    opening: Option<f64>,
) -> PyResult<Out> {
    for (name, t) in [("theta1", theta1), ("theta2", theta2)] {
        if !(t.is_finite() && t.abs() < 90.0) {
            return Err(value_error(format!(
                "invalid {name} = {}: the rotation must be finite with |theta| < 90 deg",
                pounding::output::float_token(t)
            )));
        }
    }
    let input = BridgeInput {
        r1,
        r2,
        beta1_deg: beta1,
        beta2_deg: beta2,
        width,
        thickness,
        density,
        theta1_deg: theta1,
        theta2_deg: theta2,
        mu,
        eps,
        case: ContactCase::from_name(case).ok_or_else(|| {
            value_error(format!(
                "invalid case = {case:?}: expected one of deck1-inner, deck1-outer, deck2-inner, deck2-outer"
            ))
        })?,
        sigma_mode: SigmaMode::from_name(sigma_mode).ok_or_else(|| {
            value_error(format!(
                "invalid sigma_mode = {sigma_mode:?}: expected exact or end"
            ))
        })?,
        ratio,
        opening,
    };
    let rep = report::bridge_report(&input).map_err(value_error)?;
    out(&rep, rep.trustworthy(), rep.summary())
}

/// The deck shape of the shape forms (as the CLI's `--shape`, `--r1`, `--beta1`, `--length`,
/// `--skew`).
fn shape_spec(
    shape: &str,
    r1: Option<f64>,
    beta1: Option<f64>,
    length: Option<f64>,
    skew: Option<f64>,
) -> PyResult<ShapeSpec> {
    let need = |v: Option<f64>, what: &str| {
        v.ok_or_else(|| value_error(format!("missing {what} (required with shape = {shape:?})")))
    };
    match shape {
        "curved" => Ok(ShapeSpec::Curved {
            radius: need(r1, "r1")?,
            angle_deg: need(beta1, "beta1")?,
        }),
        "straight" => Ok(ShapeSpec::Straight {
            length: need(length, "length")?,
        }),
        "skew" => {
            let skew_deg = need(skew, "skew")?;
            if !(skew_deg.is_finite() && (0.0..90.0).contains(&skew_deg)) {
                return Err(value_error(format!(
                    "invalid skew {}: the skew angle must lie in [0, 90) degrees",
                    pounding::output::float_token(skew_deg)
                )));
            }
            Ok(ShapeSpec::Skew {
                length: need(length, "length")?,
                skew_deg,
            })
        }
        other => Err(value_error(format!(
            "invalid shape = {other:?}: expected curved, straight or skew"
        ))),
    }
}

/// Two straight or skewed decks face to face at the joint (`--shape straight|skew`).
#[pyfunction]
#[pyo3(signature = (shape, length, skew, length2, width, thickness, density, mu, eps, speed))]
#[allow(clippy::too_many_arguments)]
fn impact_joint(
    shape: &str,
    length: Option<f64>,
    skew: Option<f64>,
    length2: Option<f64>,
    width: f64,
    thickness: f64,
    density: f64,
    mu: f64,
    eps: f64,
    speed: f64,
) -> PyResult<Out> {
    let input = JointInput {
        shape: shape_spec(shape, None, None, length, skew)?,
        section: DeckSection {
            width,
            thickness,
            density,
        },
        length2,
        mu,
        eps,
        speed,
    };
    let rep = report::joint_report(&input).map_err(value_error)?;
    out(&rep, rep.trustworthy(), rep.summary())
}

/// One deck (any shape) against a rigid abutment (`--abutment`).
#[pyfunction]
#[pyo3(signature = (shape, r1, beta1, length, skew, width, thickness, density, mu, eps, gap, corner, ratio, speed))]
#[allow(clippy::too_many_arguments)]
fn impact_abutment(
    shape: &str,
    r1: Option<f64>,
    beta1: Option<f64>,
    length: Option<f64>,
    skew: Option<f64>,
    width: f64,
    thickness: f64,
    density: f64,
    mu: f64,
    eps: f64,
    gap: f64,
    corner: String,
    ratio: Option<f64>,
    speed: f64,
) -> PyResult<Out> {
    let input = AbutmentInput {
        shape: shape_spec(shape, r1, beta1, length, skew)?,
        section: DeckSection {
            width,
            thickness,
            density,
        },
        mu,
        eps,
        gap,
        corner,
        ratio,
        speed,
    };
    let rep = report::abutment_report(&input).map_err(value_error)?;
    out(&rep, rep.trustworthy(), rep.summary())
}

/// The generic form: a problem given as the JSON text of `pounding impact --problem FILE.json`.
#[pyfunction]
fn impact_problem(py: Python<'_>, text: &str) -> PyResult<Out> {
    let problem = report::parse_problem(text)
        .map_err(|e| value_error(format!("in the impact problem: {e}")))?;
    let rep = crate::heavy(py, || report::problem_report(&problem))?;
    out(&rep, rep.trustworthy(), rep.summary())
}

/// Registers the impact functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(impact_bridge, m)?)?;
    m.add_function(wrap_pyfunction!(impact_joint, m)?)?;
    m.add_function(wrap_pyfunction!(impact_abutment, m)?)?;
    m.add_function(wrap_pyfunction!(impact_problem, m)?)?;
    Ok(())
}
