//! `pounding impact`: one oblique frictional impact, for two S-curved decks (bridge form) or for
//! generic planar rigid bodies (`--problem FILE.json`).

//!
//! The computations and the reports live in [`pounding::impact_report`]; this module parses the
//! arguments, checks which flags go together, and prints.

use anyhow::{Context, Result, anyhow, bail};
use pounding::geometry::{ContactCase, SigmaMode};
use pounding::impact_report::{
    self as report, AbutmentInput, BridgeInput, DeckSection, JointInput, ShapeSpec,
};
use serde::Serialize;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `pounding impact`.
///
/// Bridge form: `--r1 --r2 --beta1 --beta2 --theta1 --theta2 --case --mu --eps` (angles in degrees).
/// Shapes: `--shape straight|skew --length [--skew]` (two decks face to face) and `--abutment`
/// (deck 1 of any shape against a rigid abutment beyond its far end; `--corner`, `--gap`, `--speed`).
/// Generic form: `--problem FILE.json`. Exit status: 0 on success, 1 when the LCP status is
/// `failed`, 2 on bad input.
#[derive(clap::Args)]
pub struct Args {
    #[command(flatten)]
    inner: Box<ImpactArgs>,
}

/// The options of `pounding impact` (boxed inside [`Args`] to keep the command enum small).
#[derive(clap::Args)]
pub struct ImpactArgs {
    /// Generic form: a JSON file with "bodies" and "contacts" (docs/guide/impact.md).
    #[arg(long, value_name = "FILE.json", conflicts_with_all = ["r1", "r2", "beta1", "beta2", "theta1", "theta2", "case", "mu", "eps", "ratio", "shape", "length", "length2", "skew", "abutment", "gap", "corner", "speed"])]
    problem: Option<PathBuf>,
    /// Centre-line radius of deck 1 [m] (> W/2).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_hyphen_values = true
    )]
    r1: Option<f64>,
    /// Centre-line radius of deck 2 [m] (> W/2).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_hyphen_values = true
    )]
    r2: Option<f64>,
    /// Curve angle of deck 1 [deg], in (0, 360).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_hyphen_values = true
    )]
    beta1: Option<f64>,
    /// Curve angle of deck 2 [deg], in (0, 360).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_hyphen_values = true
    )]
    beta2: Option<f64>,
    /// Deck width W [m] (both decks).
    #[arg(long, default_value_t = 10.0, allow_hyphen_values = true)]
    width: f64,
    /// Deck thickness t [m] (both decks).
    #[arg(long, default_value_t = 0.5, allow_hyphen_values = true)]
    thickness: f64,
    /// Density ρ [kg/m³] (both decks).
    #[arg(long, default_value_t = 2500.0, allow_hyphen_values = true)]
    density: f64,
    /// Rotation of deck 1 [deg], counter-clockwise, |θ| < 90.
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_hyphen_values = true
    )]
    theta1: Option<f64>,
    /// Rotation of deck 2 [deg], counter-clockwise, |θ| < 90.
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_hyphen_values = true
    )]
    theta2: Option<f64>,
    /// Candidate contact: deck1-inner, deck1-outer, deck2-inner or deck2-outer.
    #[arg(long, required_unless_present_any = ["problem", "shape", "abutment"])]
    case: Option<String>,
    /// Coulomb friction coefficient μ >= 0.
    #[arg(long, required_unless_present = "problem", allow_hyphen_values = true)]
    mu: Option<f64>,
    /// Newton restitution coefficient ε_N in [0, 1].
    #[arg(long, required_unless_present = "problem", allow_hyphen_values = true)]
    eps: Option<f64>,
    /// Where the struck point lies: exact (corner position) or end (the paper's face-end idealisation).
    #[arg(long, default_value = "exact")]
    sigma_mode: String,
    /// Pre-impact ratio r = γ_T⁻/γ_N⁻ (evaluated with γ_N⁻ = −1): also solve the impact.
    #[arg(long, allow_hyphen_values = true)]
    ratio: Option<f64>,
    /// Joint opening g [m] (M_1 = (0, g)): also report which corner touches first and after what
    /// closing distance, or the overlap if the pose already interpenetrates (docs/guide/model.md).
    #[arg(long, allow_hyphen_values = true)]
    opening: Option<f64>,
    /// Deck shape: curved (the default: two S-curved decks, or with --abutment deck 1 against an
    /// abutment), straight (rectangle) or skew (parallelogram). straight/skew without --abutment:
    /// two decks face to face at the joint, both joint corners striking.
    #[arg(long, value_name = "curved|straight|skew")]
    shape: Option<String>,
    /// Deck length L along the axis [m] (> 0; --shape straight|skew).
    #[arg(long, allow_hyphen_values = true)]
    length: Option<f64>,
    /// Length of deck 2 [m] (> 0; --shape straight|skew without --abutment; default --length).
    #[arg(long, allow_hyphen_values = true)]
    length2: Option<f64>,
    /// Skew angle θ_s [deg] in [0, 90): end faces vs the normal of the deck axis (--shape skew).
    #[arg(long, allow_hyphen_values = true)]
    skew: Option<f64>,
    /// The deck (deck 1) against a rigid abutment beyond its far end instead of deck 2.
    #[arg(long)]
    abutment: bool,
    /// Abutment gap g >= 0 [m] along the far face's outward normal (--abutment; default 0).
    #[arg(long, allow_hyphen_values = true)]
    gap: Option<f64>,
    /// Striking corner(s) of the far face (--abutment; default both): both, c0, c1; aliases
    /// acute = c0, obtuse = c1 (skew) and outer = c0, inner = c1 (curved).
    #[arg(long)]
    corner: Option<String>,
    /// Speed of deck 1's longitudinal approach [m/s] (> 0; default 1): toward the abutment
    /// (--abutment, both corners) or toward deck 2 (two straight/skew decks).
    #[arg(long, allow_hyphen_values = true)]
    speed: Option<f64>,
    /// Print JSON instead of the readable summary.
    #[arg(long)]
    json: bool,
}

/// Runs `pounding impact`.
pub fn run(args: Args) -> Result<ExitCode> {
    let args = args.inner;
    if let Some(path) = &args.problem {
        return run_generic(path, args.json);
    }
    match args.shape.as_deref() {
        None | Some("curved") if !args.abutment => {
            reject(
                &[
                    (args.length.is_some(), "--length"),
                    (args.length2.is_some(), "--length2"),
                    (args.skew.is_some(), "--skew"),
                ],
                "is only used with --shape straight or --shape skew",
            )?;
            reject(
                &[
                    (args.gap.is_some(), "--gap"),
                    (args.corner.is_some(), "--corner"),
                    (args.speed.is_some(), "--speed"),
                ],
                "is only used with --abutment",
            )?;
            run_bridge(&args)
        }
        _ => run_shape(&args),
    }
}

/// Fails with "`flag` `why`" for the first flag that is set.
fn reject(flags: &[(bool, &str)], why: &str) -> Result<()> {
    match flags.iter().find(|(set, _)| *set) {
        Some((_, name)) => bail!("{name} {why}"),
        None => Ok(()),
    }
}

fn need(v: Option<f64>, name: &str) -> Result<f64> {
    v.ok_or_else(|| anyhow!("missing --{name}"))
}

/// Prints the report (JSON or the summary lines) and maps its trust to the exit status.
fn emit<T: Serialize>(
    report: &T,
    json: bool,
    lines: Vec<String>,
    trustworthy: bool,
) -> Result<ExitCode> {
    if json {
        println!("{}", report::to_json_pretty(report)?);
    } else {
        for l in lines {
            println!("{l}");
        }
    }
    Ok(if trustworthy {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn run_bridge(a: &ImpactArgs) -> Result<ExitCode> {
    let case_name = a.case.as_deref().ok_or_else(|| anyhow!("missing --case"))?;
    for (name, t) in [("theta1", a.theta1), ("theta2", a.theta2)] {
        if let Some(t) = t.filter(|t| !(t.is_finite() && t.abs() < 90.0)) {
            bail!(
                "invalid --{name} = {}: the rotation must be finite with |theta| < 90 deg",
                pounding::output::float_token(t)
            );
        }
    }
    let input = BridgeInput {
        r1: need(a.r1, "r1")?,
        r2: need(a.r2, "r2")?,
        beta1_deg: need(a.beta1, "beta1")?,
        beta2_deg: need(a.beta2, "beta2")?,
        width: a.width,
        thickness: a.thickness,
        density: a.density,
        theta1_deg: need(a.theta1, "theta1")?,
        theta2_deg: need(a.theta2, "theta2")?,
        mu: need(a.mu, "mu")?,
        eps: need(a.eps, "eps")?,
        case: ContactCase::from_name(case_name).ok_or_else(|| {
            anyhow!(
                "invalid case = {case_name:?}: expected one of deck1-inner, deck1-outer, deck2-inner, deck2-outer"
            )
        })?,
        sigma_mode: SigmaMode::from_name(&a.sigma_mode).ok_or_else(|| {
            anyhow!(
                "invalid sigma-mode = {:?}: expected exact or end",
                a.sigma_mode
            )
        })?,
        ratio: a.ratio,
        opening: a.opening,
    };
    let rep = report::bridge_report(&input)?;
    emit(&rep, a.json, rep.summary(), rep.trustworthy())
}

fn run_generic(path: &std::path::Path, as_json: bool) -> Result<ExitCode> {
    let text =
        pounding::input::read_text(path, "impact problem file", pounding::input::PROBLEM_LIMIT)
            .with_context(|| format!("invalid --problem: cannot read {}", path.display()))?;
    let problem = report::parse_problem(&text)
        .with_context(|| format!("in problem file {}", path.display()))?;
    let rep = report::problem_report(&problem);
    emit(&rep, as_json, rep.summary(), rep.trustworthy())
}

/// The deck shape of the shape forms (`--shape`, `--abutment`), after the flag checks.
fn shape_spec(a: &ImpactArgs) -> Result<ShapeSpec> {
    let shape_name = a.shape.as_deref().unwrap_or("curved");
    match shape_name {
        "curved" => {
            reject(
                &[
                    (a.length.is_some(), "--length"),
                    (a.skew.is_some(), "--skew"),
                ],
                "is only used with --shape straight or --shape skew",
            )?;
            Ok(ShapeSpec::Curved {
                radius: need(a.r1, "r1")?,
                angle_deg: need(a.beta1, "beta1")?,
            })
        }
        "straight" | "skew" => {
            reject(
                &[(a.r1.is_some(), "--r1"), (a.beta1.is_some(), "--beta1")],
                "is only used with --shape curved",
            )?;
            let length = a
                .length
                .ok_or_else(|| anyhow!("missing --length (required with --shape {shape_name})"))?;
            if shape_name == "straight" {
                reject(
                    &[(a.skew.is_some(), "--skew")],
                    "is only used with --shape skew",
                )?;
                Ok(ShapeSpec::Straight { length })
            } else {
                let skew_deg = a
                    .skew
                    .ok_or_else(|| anyhow!("missing --skew (required with --shape skew)"))?;
                // checked in degrees, so that the message shows the user's value
                if !(skew_deg.is_finite() && (0.0..90.0).contains(&skew_deg)) {
                    bail!(
                        "invalid --skew {}: the skew angle must lie in [0, 90) degrees",
                        pounding::output::float_token(skew_deg)
                    );
                }
                Ok(ShapeSpec::Skew { length, skew_deg })
            }
        }
        other => bail!("invalid shape = {other:?}: expected curved, straight or skew"),
    }
}

/// The shape forms: one deck against an abutment, or two straight/skew decks at the joint.
fn run_shape(a: &ImpactArgs) -> Result<ExitCode> {
    let shape = shape_spec(a)?;
    let section = DeckSection {
        width: a.width,
        thickness: a.thickness,
        density: a.density,
    };
    let pose_flags = [
        (a.r2.is_some(), "--r2"),
        (a.beta2.is_some(), "--beta2"),
        (a.theta1.is_some(), "--theta1"),
        (a.theta2.is_some(), "--theta2"),
        (a.case.is_some(), "--case"),
        (a.opening.is_some(), "--opening"),
    ];
    if !a.abutment {
        let name = if matches!(shape, ShapeSpec::Skew { .. }) {
            "skew"
        } else {
            "straight"
        };
        let mut flags = pose_flags.to_vec();
        flags.extend([
            (a.ratio.is_some(), "--ratio"),
            (a.gap.is_some(), "--gap"),
            (a.corner.is_some(), "--corner"),
        ]);
        reject(
            &flags,
            &format!(
                "is not used for two {name} decks (both joint corners strike in the reference pose)"
            ),
        )?;
        if a.sigma_mode != "exact" {
            bail!("--sigma-mode is not used with --shape {name}");
        }
        let input = JointInput {
            shape,
            section,
            length2: a.length2,
            mu: need(a.mu, "mu")?,
            eps: need(a.eps, "eps")?,
            speed: a.speed.unwrap_or(1.0),
        };
        let rep = report::joint_report(&input)?;
        return emit(&rep, a.json, rep.summary(), rep.trustworthy());
    }
    if a.length2.is_some() {
        bail!("--length2 is not used with --abutment (there is no deck 2)");
    }
    reject(
        &pose_flags,
        "is not used with --abutment (the deck is in its reference pose)",
    )?;
    if a.sigma_mode != "exact" {
        bail!("--sigma-mode is not used with --abutment");
    }
    let corner = a.corner.clone().unwrap_or_else(|| "both".to_string());
    let both = corner == "both";
    if both && a.ratio.is_some_and(f64::is_finite) {
        bail!("--ratio needs a single corner (--corner c0 or c1): both corners use --speed");
    }
    if !both && a.speed.is_some() {
        bail!(
            "--speed is only used with --corner both (a single corner is solved in r = γ_T⁻/γ_N⁻)"
        );
    }
    let input = AbutmentInput {
        shape,
        section,
        mu: need(a.mu, "mu")?,
        eps: need(a.eps, "eps")?,
        gap: a.gap.unwrap_or(0.0),
        corner,
        ratio: a.ratio,
        speed: a.speed.unwrap_or(1.0),
    };
    let rep = report::abutment_report(&input)?;
    emit(&rep, a.json, rep.summary(), rep.trustworthy())
}
