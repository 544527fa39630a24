//! `pounding impact`: one oblique frictional impact, for two S-curved decks (bridge form) or for
//! generic planar rigid bodies (`--problem FILE.json`).

use anyhow::{Context, Result, anyhow, bail};
use pounding::analytic::{self, ImpactLaw};
use pounding::contact::{self, Delassus};
use pounding::geometry::{
    ContactCase, ContactDetection, Deck, ImpactConfiguration, MassProperties, SArrangement,
    SigmaMode, validate_rotation,
};
use pounding::impact::{
    self, ContactMode, ContactSpec, ImpactProblem, ImpactSettings, ImpactSolution, RigidBody,
    SingleSolution,
};
use pounding::lcp::LemkeSettings;
use pounding::math::Vector;
use pounding::output::{float_token, json_float};
use pounding::shape::{
    Abutment, DeckEnd, DeckShape, SkewedDeck, StraightDeck, abutment_contact, abutment_delassus,
    abutment_problem, frictionless_pivot, joint_problem,
};
use serde_json::{Map, Value, json};
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
    /// Generic form: a JSON file with "bodies" and "contacts" (see the README).
    #[arg(long, value_name = "FILE.json", conflicts_with_all = ["r1", "r2", "beta1", "beta2", "theta1", "theta2", "case", "mu", "eps", "ratio", "shape", "length", "length2", "skew", "abutment", "gap", "corner", "speed"])]
    problem: Option<PathBuf>,
    /// Centre-line radius of deck 1 [m] (> W/2).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_negative_numbers = true
    )]
    r1: Option<f64>,
    /// Centre-line radius of deck 2 [m] (> W/2).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_negative_numbers = true
    )]
    r2: Option<f64>,
    /// Curve angle of deck 1 [deg], in (0, 360).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_negative_numbers = true
    )]
    beta1: Option<f64>,
    /// Curve angle of deck 2 [deg], in (0, 360).
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_negative_numbers = true
    )]
    beta2: Option<f64>,
    /// Deck width W [m] (both decks).
    #[arg(long, default_value_t = 10.0, allow_negative_numbers = true)]
    width: f64,
    /// Deck thickness t [m] (both decks).
    #[arg(long, default_value_t = 0.5, allow_negative_numbers = true)]
    thickness: f64,
    /// Density ρ [kg/m³] (both decks).
    #[arg(long, default_value_t = 2500.0, allow_negative_numbers = true)]
    density: f64,
    /// Rotation of deck 1 [deg], counter-clockwise, |θ| < 90.
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_negative_numbers = true
    )]
    theta1: Option<f64>,
    /// Rotation of deck 2 [deg], counter-clockwise, |θ| < 90.
    #[arg(
        long,
        required_unless_present_any = ["problem", "shape", "abutment"],
        allow_negative_numbers = true
    )]
    theta2: Option<f64>,
    /// Candidate contact: deck1-inner, deck1-outer, deck2-inner or deck2-outer.
    #[arg(long, required_unless_present_any = ["problem", "shape", "abutment"])]
    case: Option<String>,
    /// Coulomb friction coefficient μ >= 0.
    #[arg(
        long,
        required_unless_present = "problem",
        allow_negative_numbers = true
    )]
    mu: Option<f64>,
    /// Newton restitution coefficient ε_N in [0, 1].
    #[arg(
        long,
        required_unless_present = "problem",
        allow_negative_numbers = true
    )]
    eps: Option<f64>,
    /// Where the struck point lies: exact (corner position) or end (the paper's face-end idealisation).
    #[arg(long, default_value = "exact")]
    sigma_mode: String,
    /// Pre-impact ratio r = γ_T⁻/γ_N⁻ (evaluated with γ_N⁻ = −1): also solve the impact.
    #[arg(long, allow_negative_numbers = true)]
    ratio: Option<f64>,
    /// Joint opening g [m] (M_1 = (0, g)): also report which corner touches first and after what
    /// closing distance, or the overlap if the pose already interpenetrates (spec §5.5).
    #[arg(long, allow_negative_numbers = true)]
    opening: Option<f64>,
    /// Deck shape: curved (the default: two S-curved decks, or with --abutment deck 1 against an
    /// abutment), straight (rectangle) or skew (parallelogram). straight/skew without --abutment:
    /// two decks face to face at the joint, both joint corners striking.
    #[arg(long, value_name = "curved|straight|skew")]
    shape: Option<String>,
    /// Deck length L along the axis [m] (> 0; --shape straight|skew).
    #[arg(long, allow_negative_numbers = true)]
    length: Option<f64>,
    /// Length of deck 2 [m] (> 0; --shape straight|skew without --abutment; default --length).
    #[arg(long, allow_negative_numbers = true)]
    length2: Option<f64>,
    /// Skew angle θ_s [deg] in [0, 90): end faces vs the normal of the deck axis (--shape skew).
    #[arg(long, allow_negative_numbers = true)]
    skew: Option<f64>,
    /// The deck (deck 1) against a rigid abutment beyond its far end instead of deck 2.
    #[arg(long)]
    abutment: bool,
    /// Abutment gap g >= 0 [m] along the far face's outward normal (--abutment; default 0).
    #[arg(long, allow_negative_numbers = true)]
    gap: Option<f64>,
    /// Striking corner(s) of the far face (--abutment; default both): both, c0, c1; aliases
    /// acute = c0, obtuse = c1 (skew) and outer = c0, inner = c1 (curved).
    #[arg(long)]
    corner: Option<String>,
    /// Speed of deck 1's longitudinal approach [m/s] (> 0; default 1): toward the abutment
    /// (--abutment, both corners) or toward deck 2 (two straight/skew decks).
    #[arg(long, allow_negative_numbers = true)]
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
            for (set, name) in [
                (args.length.is_some(), "--length"),
                (args.length2.is_some(), "--length2"),
                (args.skew.is_some(), "--skew"),
            ] {
                if set {
                    bail!("{name} is only used with --shape straight or --shape skew");
                }
            }
            for (set, name) in [
                (args.gap.is_some(), "--gap"),
                (args.corner.is_some(), "--corner"),
                (args.speed.is_some(), "--speed"),
            ] {
                if set {
                    bail!("{name} is only used with --abutment");
                }
            }
            run_bridge(&args)
        }
        _ => run_abutment(&args),
    }
}

fn need(v: Option<f64>, name: &str) -> Result<f64> {
    v.ok_or_else(|| anyhow!("missing --{name}"))
}

fn vec_json(v: &Vector) -> Value {
    json!([json_float(v.x), json_float(v.y)])
}

fn deck_json(d: &Deck, angle_deg: f64, p: &MassProperties) -> Value {
    json!({
        "radius": json_float(d.radius),
        "angle_deg": json_float(angle_deg),
        "area": json_float(p.area),
        "mass": json_float(p.mass),
        "centroid_radius": json_float(p.centroid_radius),
        "x_m": json_float(p.x_m),
        "y_m": json_float(p.y_m),
        "inertia": json_float(p.inertia),
        "radius_of_gyration": json_float(p.radius_of_gyration()),
    })
}

/// The numbers of a non-degenerate bridge impact.
struct BridgeResult {
    config: ImpactConfiguration,
    g: Delassus,
    bounds: analytic::StickInterval,
    painleve: bool,
    solved: Option<(f64, SingleSolution)>,
}

fn run_bridge(a: &ImpactArgs) -> Result<ExitCode> {
    let r1 = need(a.r1, "r1")?;
    let r2 = need(a.r2, "r2")?;
    let b1 = need(a.beta1, "beta1")?;
    let b2 = need(a.beta2, "beta2")?;
    let t1 = need(a.theta1, "theta1")?;
    let t2 = need(a.theta2, "theta2")?;
    let mu = need(a.mu, "mu")?;
    let eps = need(a.eps, "eps")?;
    let case_name = a.case.as_deref().ok_or_else(|| anyhow!("missing --case"))?;
    let case = ContactCase::from_name(case_name).ok_or_else(|| {
        anyhow!(
            "invalid case = {case_name:?}: expected one of deck1-inner, deck1-outer, deck2-inner, deck2-outer"
        )
    })?;
    let mode = SigmaMode::from_name(&a.sigma_mode).ok_or_else(|| {
        anyhow!(
            "invalid sigma-mode = {:?}: expected exact or end",
            a.sigma_mode
        )
    })?;
    let d1 = Deck::new(r1, b1.to_radians(), a.width, a.thickness, a.density)
        .map_err(|e| e.for_deck(1))?;
    let d2 = Deck::new(r2, b2.to_radians(), a.width, a.thickness, a.density)
        .map_err(|e| e.for_deck(2))?;
    let s = SArrangement::new(d1, d2)?;
    for (name, t) in [("theta1", t1), ("theta2", t2)] {
        if !(t.is_finite() && t.abs() < 90.0) {
            bail!(
                "invalid --{name} = {}: the rotation must be finite with |theta| < 90 deg",
                float_token(t)
            );
        }
    }
    let (t1r, t2r) = (t1.to_radians(), t2.to_radians());
    validate_rotation("theta1", t1r)?;
    validate_rotation("theta2", t2r)?;
    let law = ImpactLaw::new(mu, eps)?;
    if let Some(r) = a.ratio
        && !r.is_finite()
    {
        bail!("invalid ratio = {}: must be finite", float_token(r));
    }
    if let Some(g) = a.opening
        && !g.is_finite()
    {
        bail!("invalid opening = {}: must be finite", float_token(g));
    }
    let detection = a.opening.map(|g| (g, s.detect_contact(t1r, t2r, g)));
    let (p1, p2) = (d1.mass_properties(), d2.mass_properties());
    let result = s.configuration(case, t1r, t2r, mode).map(|config| {
        let g = contact::delassus(&s, &config);
        let bounds = analytic::stick_interval(&g, &law);
        let solved = a.ratio.map(|r| {
            (
                r,
                impact::solve_single(&g, &law, -1.0, -r, &LemkeSettings::default()),
            )
        });
        BridgeResult {
            config,
            g,
            bounds,
            painleve: analytic::is_painleve(&g, &law),
            solved,
        }
    });
    let null = Value::Null;
    let mut out = Map::new();
    out.insert(
        "input".into(),
        json!({
            "case": case.name(),
            "theta1_deg": json_float(t1),
            "theta2_deg": json_float(t2),
            "mu": json_float(mu),
            "eps": json_float(eps),
            "sigma_mode": mode.name(),
            "width": json_float(a.width),
            "thickness": json_float(a.thickness),
            "density": json_float(a.density),
        }),
    );
    out.insert(
        "decks".into(),
        json!([deck_json(&d1, b1, &p1), deck_json(&d2, b2, &p2)]),
    );
    let mut failed = false;
    match &result {
        Err(d) => {
            out.insert("degenerate".into(), json!(d.name()));
            out.insert("first_contact".into(), json!(false));
            out.insert("end_closes".into(), json!(false));
            for k in ["h", "sigma", "kappa", "varrho"] {
                out.insert(k.into(), null.clone());
            }
            out.insert(
                "delassus".into(),
                json!({"nn": null, "nt": null, "tt": null}),
            );
            out.insert(
                "stick_interval".into(),
                json!({"lower": null, "upper": null}),
            );
            if let Some(r) = a.ratio {
                out.insert("ratio".into(), json_float(r));
                out.insert("mode".into(), null.clone());
                out.insert(
                    "impulse".into(),
                    json!({"normal": null, "tangential": null}),
                );
                out.insert("post".into(), json!({"gamma_n": null, "gamma_t": null}));
                out.insert("energy_change".into(), null.clone());
                out.insert("status".into(), null.clone());
            }
        }
        Ok(b) => {
            let c = &b.config;
            out.insert("degenerate".into(), null.clone());
            out.insert("first_contact".into(), json!(c.first_contact));
            out.insert("end_closes".into(), json!(c.end_closes));
            out.insert("h".into(), json_float(c.h));
            out.insert("sigma".into(), json_float(c.sigma));
            out.insert("point".into(), vec_json(&c.point));
            out.insert("normal".into(), vec_json(&c.normal));
            out.insert("tangent".into(), vec_json(&c.tangent));
            out.insert(
                "delassus".into(),
                json!({"nn": json_float(b.g.nn), "nt": json_float(b.g.nt), "tt": json_float(b.g.tt)}),
            );
            out.insert("kappa".into(), json_float(b.g.kappa()));
            out.insert("varrho".into(), json_float(b.g.varrho()));
            out.insert(
                "stick_interval".into(),
                json!({"lower": json_float(b.bounds.lower), "upper": json_float(b.bounds.upper)}),
            );
            out.insert("painleve".into(), json!(b.painleve));
            if let Some((r, sol)) = &b.solved {
                failed = !sol.status.is_trustworthy();
                out.insert("ratio".into(), json_float(*r));
                out.insert("mode".into(), json!(bridge_label(sol.mode)));
                out.insert(
                    "impulse".into(),
                    json!({"normal": json_float(sol.normal_impulse), "tangential": json_float(sol.tangential_impulse)}),
                );
                out.insert(
                    "post".into(),
                    json!({"gamma_n": json_float(sol.gamma_n_post), "gamma_t": json_float(sol.gamma_t_post)}),
                );
                out.insert(
                    "energy_change".into(),
                    json_float(sol.energy_change(-1.0, -r)),
                );
                out.insert("status".into(), json!(sol.status.name()));
            }
        }
    }
    if let Some((g, d)) = &detection {
        let v = match d {
            ContactDetection::Contact {
                case,
                closing_distance,
            } => json!({"opening": json_float(*g), "first_contact_case": case.name(),
                         "closing_distance": json_float(*closing_distance), "overlap": null}),
            ContactDetection::Overlap { case, overlap } => {
                json!({"opening": json_float(*g), "first_contact_case": case.name(),
                       "closing_distance": null, "overlap": json_float(*overlap)})
            }
            ContactDetection::Degenerate(_) => {
                json!({"opening": json_float(*g), "first_contact_case": null,
                       "closing_distance": null, "overlap": null})
            }
        };
        out.insert("detection".into(), v);
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&Value::Object(out))?);
    } else {
        print_bridge_summary(
            [(&d1, b1, &p1), (&d2, b2, &p2)],
            case,
            t1,
            t2,
            mu,
            eps,
            mode,
            &result,
        );
        if let Some((g, d)) = &detection {
            match d {
                ContactDetection::Contact {
                    case,
                    closing_distance,
                } => println!(
                    "At opening g = {g} m the first contact is {} after closing {} m.",
                    case.name(),
                    fmt(*closing_distance)
                ),
                ContactDetection::Overlap { case, overlap } => println!(
                    "At opening g = {g} m the decks already overlap by {} m (first contact {}).",
                    fmt(*overlap),
                    case.name()
                ),
                ContactDetection::Degenerate(k) => {
                    println!("At opening g = {g} m: degenerate pose ({}).", k.name())
                }
            }
        }
    }
    Ok(if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// Bridge label of a mode (spec §10): γ_T⁺ > 0 is `slip-outward`, γ_T⁺ < 0 `slip-inward`.
fn bridge_label(m: ContactMode) -> &'static str {
    match m {
        ContactMode::Open => "open",
        ContactMode::Stick => "stick",
        ContactMode::SlipPositive => "slip-outward",
        ContactMode::SlipNegative => "slip-inward",
    }
}

/// Readable number: 7 significant digits, positional for moderate magnitudes.
fn fmt(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else if x.is_finite() && (1e-3..1e6).contains(&x.abs()) {
        let digits = (6 - x.abs().log10().floor() as i32).clamp(0, 9) as usize;
        format!("{x:.digits$}")
    } else if x.is_finite() {
        format!("{x:.6e}")
    } else {
        pounding::output::float_token(x)
    }
}

#[allow(clippy::too_many_arguments)]
fn print_bridge_summary(
    decks: [(&Deck, f64, &MassProperties); 2],
    case: ContactCase,
    t1: f64,
    t2: f64,
    mu: f64,
    eps: f64,
    mode: SigmaMode,
    result: &Result<BridgeResult, pounding::geometry::Degeneracy>,
) {
    let d1 = decks[0].0;
    println!(
        "Two S-curved decks, W = {} m, t = {} m, ρ = {} kg/m³",
        d1.width, d1.thickness, d1.density
    );
    for (j, (d, beta, p)) in decks.into_iter().enumerate() {
        println!(
            "  deck {}: R = {} m, β = {}°: A = {:.6} m², m = {} kg, r_c = {:.6} m, I = {} kg m²",
            j + 1,
            d.radius,
            beta,
            p.area,
            fmt(p.mass),
            p.centroid_radius,
            fmt(p.inertia)
        );
    }
    println!(
        "Case {}, θ1 = {t1}°, θ2 = {t2}°, μ = {mu}, ε_N = {eps}, σ mode {}",
        case.name(),
        mode.name()
    );
    let b = match result {
        Err(d) => {
            println!(
                "Degenerate pose ({}): the single-impact model does not apply.",
                d.name()
            );
            return;
        }
        Ok(b) => b,
    };
    let c = &b.config;
    println!(
        "  first contact: {}   end closes: {}   h = {:.6} m   σ = {:.9} m",
        c.first_contact, c.end_closes, c.h, c.sigma
    );
    println!(
        "  Delassus: G_NN = {}  G_NT = {}  G_TT = {}  [1/kg]   κ = {:.6}  ϱ = {:.6}",
        fmt(b.g.nn),
        fmt(b.g.nt),
        fmt(b.g.tt),
        b.g.kappa(),
        b.g.varrho()
    );
    println!(
        "  stick interval in r = γ_T⁻/γ_N⁻: [{}, {}]{}",
        fmt(b.bounds.lower),
        fmt(b.bounds.upper),
        if b.painleve {
            "  (Painlevé-type regime: one bound infinite)"
        } else {
            ""
        }
    );
    println!("  r < L: slip-outward; L ≤ r ≤ U: stick; r > U: slip-inward");
    if let Some((r, s)) = &b.solved {
        println!(
            "Impact at r = {r} (γ_N⁻ = −1 m/s, γ_T⁻ = {} m/s): {} ({})",
            -r,
            bridge_label(s.mode),
            s.status.name()
        );
        println!(
            "  Λ_N = {} N s  Λ_T = {} N s  γ_N⁺ = {} m/s  γ_T⁺ = {} m/s  ΔT = {} J",
            fmt(s.normal_impulse),
            fmt(s.tangential_impulse),
            fmt(s.gamma_n_post),
            fmt(s.gamma_t_post),
            fmt(s.energy_change(-1.0, -r))
        );
    }
}

// ---------------------------------------------------------------- generic form

fn num(v: &Value, path: &str) -> Result<f64> {
    v.as_f64()
        .ok_or_else(|| anyhow!("invalid {path}: expected a number, found {v}"))
}

fn field<'a>(obj: &'a Map<String, Value>, key: &str, path: &str) -> Result<&'a Value> {
    obj.get(key).ok_or_else(|| anyhow!("missing {path}.{key}"))
}

fn pair(v: &Value, path: &str) -> Result<Vector> {
    match v.as_array() {
        Some(a) if a.len() == 2 => Ok(Vector::new(
            num(&a[0], &format!("{path}[0]"))?,
            num(&a[1], &format!("{path}[1]"))?,
        )),
        _ => bail!("invalid {path}: expected [x, y], found {v}"),
    }
}

fn check_keys(obj: &Map<String, Value>, allowed: &[&str], path: &str) -> Result<()> {
    for k in obj.keys() {
        if !allowed.contains(&k.as_str()) {
            bail!("unknown key {path}.{k} (allowed: {})", allowed.join(", "));
        }
    }
    Ok(())
}

/// Parses the generic problem JSON (see the module docs); errors name the offending key.
pub fn parse_problem(text: &str) -> Result<ImpactProblem> {
    pounding::input::check_json_duplicate_keys(text)
        .context("the problem file is not valid JSON")?;
    let root: Value = serde_json::from_str(text).context("the problem file is not valid JSON")?;
    let root = root.as_object().ok_or_else(|| {
        anyhow!("the problem must be a JSON object with \"bodies\" and \"contacts\"")
    })?;
    check_keys(root, &["bodies", "contacts"], "problem")?;
    let bodies_v = root
        .get("bodies")
        .and_then(Value::as_array)
        .ok_or_else(|| anyhow!("missing bodies: expected an array of bodies"))?;
    let contacts_v = root
        .get("contacts")
        .and_then(Value::as_array)
        .ok_or_else(|| anyhow!("missing contacts: expected an array of contacts"))?;
    let mut bodies = Vec::new();
    for (i, b) in bodies_v.iter().enumerate() {
        let path = format!("bodies[{i}]");
        let o = b
            .as_object()
            .ok_or_else(|| anyhow!("invalid {path}: expected an object"))?;
        check_keys(
            o,
            &["name", "mass", "inertia", "position", "velocity", "omega"],
            &path,
        )?;
        let name = field(o, "name", &path)?
            .as_str()
            .ok_or_else(|| anyhow!("invalid {path}.name: expected a string"))?;
        bodies.push(RigidBody {
            name: name.to_string(),
            mass: num(field(o, "mass", &path)?, &format!("{path}.mass"))?,
            inertia: num(field(o, "inertia", &path)?, &format!("{path}.inertia"))?,
            position: pair(field(o, "position", &path)?, &format!("{path}.position"))?,
            velocity: pair(field(o, "velocity", &path)?, &format!("{path}.velocity"))?,
            omega: num(field(o, "omega", &path)?, &format!("{path}.omega"))?,
        });
    }
    let mut contacts = Vec::new();
    for (j, c) in contacts_v.iter().enumerate() {
        let path = format!("contacts[{j}]");
        let o = c
            .as_object()
            .ok_or_else(|| anyhow!("invalid {path}: expected an object"))?;
        check_keys(
            o,
            &["body_a", "body_b", "point", "normal", "mu", "restitution"],
            &path,
        )?;
        let body_a = field(o, "body_a", &path)?
            .as_str()
            .ok_or_else(|| anyhow!("invalid {path}.body_a: expected a body name"))?;
        let body_b = match field(o, "body_b", &path)? {
            Value::Null => None,
            Value::String(s) => Some(s.clone()),
            other => bail!("invalid {path}.body_b: expected a body name or null, found {other}"),
        };
        contacts.push(ContactSpec {
            body_a: body_a.to_string(),
            body_b,
            point: pair(field(o, "point", &path)?, &format!("{path}.point"))?,
            normal: pair(field(o, "normal", &path)?, &format!("{path}.normal"))?,
            mu: num(field(o, "mu", &path)?, &format!("{path}.mu"))?,
            restitution: num(
                field(o, "restitution", &path)?,
                &format!("{path}.restitution"),
            )?,
        });
    }
    Ok(ImpactProblem::new(bodies, contacts)?)
}

/// Whether `solutions` / uniqueness are known: enumeration ran, or the problem is small enough
/// (`3n ≤ 12`) for the solver to enumerate whenever uniqueness is in doubt (singular `G` or a
/// Lemke failure). With `3n > 12` and no enumeration nothing was checked.
fn uniqueness_checked(p: &ImpactProblem, s: &ImpactSolution) -> bool {
    s.enumerated || 3 * p.contacts().len() <= pounding::lcp::enumerate::MAX_ENUM_DIM
}

fn solution_json(p: &ImpactProblem, s: &ImpactSolution) -> Value {
    let checked = uniqueness_checked(p, s);
    let bodies: Vec<Value> = p
        .bodies()
        .iter()
        .zip(&s.bodies)
        .map(|(b, v)| {
            json!({
                "name": b.name,
                "velocity": vec_json(&v.velocity),
                "omega": json_float(v.omega),
            })
        })
        .collect();
    let contacts: Vec<Value> = s
        .contacts
        .iter()
        .map(|c| {
            json!({
                "normal_impulse": json_float(c.normal_impulse),
                "tangential_impulse": json_float(c.tangential_impulse),
                "mode": c.mode.name(),
                "gamma_n_pre": json_float(c.gamma_n_pre),
                "gamma_t_pre": json_float(c.gamma_t_pre),
                "gamma_n_post": json_float(c.gamma_n_post),
                "gamma_t_post": json_float(c.gamma_t_post),
            })
        })
        .collect();
    json!({
        "bodies": bodies,
        "contacts": contacts,
        "energy": {"before": json_float(s.energy_before), "after": json_float(s.energy_after)},
        "status": s.status.name(),
        // With 3n > 12 the bases cannot be enumerated: uniqueness is unknown (null) unless checked.
        "solutions": if checked { json!(s.solutions) } else { Value::Null },
        "post_velocity_unique": if checked { json!(s.post_velocity_unique) } else { Value::Null },
        "impulse_unique": if checked { json!(s.solutions <= 1) } else { Value::Null },
    })
}

fn run_generic(path: &std::path::Path, as_json: bool) -> Result<ExitCode> {
    let text =
        pounding::input::read_text(path, "impact problem file", pounding::input::PROBLEM_LIMIT)
            .with_context(|| format!("invalid --problem: cannot read {}", path.display()))?;
    let problem =
        parse_problem(&text).with_context(|| format!("in problem file {}", path.display()))?;
    let s = impact::solve(&problem, &ImpactSettings::default());
    if as_json {
        println!(
            "{}",
            serde_json::to_string_pretty(&solution_json(&problem, &s))?
        );
    } else {
        println!(
            "Impact of {} bodies at {} contacts: {}",
            problem.bodies().len(),
            problem.contacts().len(),
            s.status.name()
        );
        for (b, v) in problem.bodies().iter().zip(&s.bodies) {
            println!(
                "  {}: v⁺ = ({}, {}) m/s, ω⁺ = {} rad/s",
                b.name,
                fmt(v.velocity.x),
                fmt(v.velocity.y),
                fmt(v.omega)
            );
        }
        for (j, c) in s.contacts.iter().enumerate() {
            println!(
                "  contact {j}: {}  Λ_N = {} N s  Λ_T = {} N s  γ_N: {} → {}  γ_T: {} → {} m/s",
                c.mode.name(),
                fmt(c.normal_impulse),
                fmt(c.tangential_impulse),
                fmt(c.gamma_n_pre),
                fmt(c.gamma_n_post),
                fmt(c.gamma_t_pre),
                fmt(c.gamma_t_post)
            );
        }
        println!(
            "  kinetic energy: {} J → {} J",
            fmt(s.energy_before),
            fmt(s.energy_after)
        );
        if let Some(v) = &s.law_violation {
            println!("  post-solve check failed (numbers not trustworthy): {v}");
        }
        if s.enumerated {
            println!(
                "  enumeration: {} distinct solution(s); post-impact velocities {}",
                s.solutions,
                if s.post_velocity_unique {
                    "unique"
                } else {
                    "NOT unique"
                }
            );
        } else if !uniqueness_checked(&problem, &s) {
            println!(
                "  uniqueness: not checked (enumeration runs only for 3n <= 12; here 3n = {})",
                3 * problem.contacts().len()
            );
        }
    }
    Ok(if !s.status.is_trustworthy() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

// ---------------------------------------------------------------- shapes and abutments

/// Names of the far-face corners `[c0, c1]` for a shape.
/// The per-corner results of a straight/skew impact as JSON objects (corner name, point, impulses,
/// mode, relative velocities before and after).
fn corner_contacts_json(
    contacts: &[pounding::impact::ContactResult],
    names: &[&str; 2],
    corners: &[Vector; 2],
) -> Value {
    Value::Array(
        contacts
            .iter()
            .enumerate()
            .map(|(k, c)| {
                json!({
                    "corner": names[k],
                    "point": vec_json(&corners[k]),
                    "normal_impulse": json_float(c.normal_impulse),
                    "tangential_impulse": json_float(c.tangential_impulse),
                    "mode": c.mode.name(),
                    "gamma_n_pre": json_float(c.gamma_n_pre),
                    "gamma_t_pre": json_float(c.gamma_t_pre),
                    "gamma_n_post": json_float(c.gamma_n_post),
                    "gamma_t_post": json_float(c.gamma_t_post),
                })
            })
            .collect(),
    )
}

fn corner_names(shape: &DeckShape) -> [&'static str; 2] {
    match shape {
        DeckShape::Curved(_) => ["outer", "inner"],
        DeckShape::Straight(_) => ["c0", "c1"],
        DeckShape::Skewed(_) => ["acute", "obtuse"],
    }
}

/// The abutment form: deck 1 (curved, straight or skew) against a rigid abutment beyond its far end.
fn run_abutment(a: &ImpactArgs) -> Result<ExitCode> {
    let shape_name = a.shape.as_deref().unwrap_or("curved");
    let shape = match shape_name {
        "curved" => {
            for (set, name) in [
                (a.length.is_some(), "--length"),
                (a.skew.is_some(), "--skew"),
            ] {
                if set {
                    bail!("{name} is only used with --shape straight or --shape skew");
                }
            }
            let r1 = need(a.r1, "r1")?;
            let b1 = need(a.beta1, "beta1")?;
            DeckShape::Curved(
                Deck::new(r1, b1.to_radians(), a.width, a.thickness, a.density)
                    .map_err(|e| e.for_deck(1))?,
            )
        }
        "straight" | "skew" => {
            for (set, name) in [(a.r1.is_some(), "--r1"), (a.beta1.is_some(), "--beta1")] {
                if set {
                    bail!("{name} is only used with --shape curved");
                }
            }
            let length = a
                .length
                .ok_or_else(|| anyhow!("missing --length (required with --shape {shape_name})"))?;
            if shape_name == "straight" {
                if a.skew.is_some() {
                    bail!("--skew is only used with --shape skew");
                }
                DeckShape::Straight(StraightDeck::new(length, a.width, a.thickness, a.density)?)
            } else {
                let skew = a
                    .skew
                    .ok_or_else(|| anyhow!("missing --skew (required with --shape skew)"))?;
                // checked in degrees, so that the message shows the user's value
                if !(skew.is_finite() && (0.0..90.0).contains(&skew)) {
                    bail!(
                        "invalid --skew {}: the skew angle must lie in [0, 90) degrees",
                        float_token(skew)
                    );
                }
                DeckShape::Skewed(SkewedDeck::new(
                    length,
                    a.width,
                    skew.to_radians(),
                    a.thickness,
                    a.density,
                )?)
            }
        }
        other => bail!("invalid shape = {other:?}: expected curved, straight or skew"),
    };
    if !a.abutment {
        return run_joint(a, &shape);
    }
    if a.length2.is_some() {
        bail!("--length2 is not used with --abutment (there is no deck 2)");
    }
    for (set, name) in [
        (a.r2.is_some(), "--r2"),
        (a.beta2.is_some(), "--beta2"),
        (a.theta1.is_some(), "--theta1"),
        (a.theta2.is_some(), "--theta2"),
        (a.case.is_some(), "--case"),
        (a.opening.is_some(), "--opening"),
    ] {
        if set {
            bail!("{name} is not used with --abutment (the deck is in its reference pose)");
        }
    }
    if a.sigma_mode != "exact" {
        bail!("--sigma-mode is not used with --abutment");
    }
    let mu = need(a.mu, "mu")?;
    let eps = need(a.eps, "eps")?;
    let law = ImpactLaw::new(mu, eps)?;
    let abut = Abutment::new(DeckEnd::Far, a.gap.unwrap_or(0.0))?;
    let names = corner_names(&shape);
    let corner = a.corner.as_deref().unwrap_or("both");
    let corners: Vec<usize> = match corner {
        "both" => vec![0, 1],
        "c0" => vec![0],
        "c1" => vec![1],
        n if n == names[0] => vec![0],
        n if n == names[1] => vec![1],
        n => bail!(
            "invalid corner = {n:?}: expected both, c0 or c1{}",
            if names[0] == "c0" {
                String::new()
            } else {
                format!(" (or {}, {})", names[0], names[1])
            }
        ),
    };
    if let Some(r) = a.ratio {
        if !r.is_finite() {
            bail!("invalid ratio = {}: must be finite", float_token(r));
        }
        if corners.len() == 2 {
            bail!("--ratio needs a single corner (--corner c0 or c1): both corners use --speed");
        }
    }
    let speed = a.speed.unwrap_or(1.0);
    if !(speed.is_finite() && speed > 0.0) {
        bail!(
            "invalid speed = {}: must be finite and > 0",
            float_token(speed)
        );
    }
    if a.speed.is_some() && corners.len() == 1 {
        bail!(
            "--speed is only used with --corner both (a single corner is solved in r = γ_T⁻/γ_N⁻)"
        );
    }

    let props = shape.mass_properties();
    let face = shape.end_face(DeckEnd::Far);
    let axis = shape.axis_direction(DeckEnd::Far);
    let mut out = Map::new();
    let mut input = json!({
        "shape": shape.name(),
        "abutment": true,
        "end": DeckEnd::Far.name(),
        "corner": corner,
        "mu": json_float(mu),
        "eps": json_float(eps),
        "gap": json_float(abut.gap),
        "width": json_float(a.width),
        "thickness": json_float(a.thickness),
        "density": json_float(a.density),
    });
    let extra = match &shape {
        DeckShape::Curved(d) => {
            json!({"radius": json_float(d.radius), "angle_deg": json_float(a.beta1.unwrap_or(d.angle.to_degrees()))})
        }
        DeckShape::Straight(d) => json!({"length": json_float(d.length)}),
        DeckShape::Skewed(d) => {
            json!({"length": json_float(d.length), "skew_deg": json_float(a.skew.unwrap_or(d.skew.to_degrees()))})
        }
    };
    if let (Value::Object(m), Value::Object(e)) = (&mut input, extra) {
        m.extend(e);
    }
    out.insert("input".into(), input);
    out.insert(
        "deck".into(),
        json!({
            "area": json_float(props.area),
            "mass": json_float(props.mass),
            "centroid": vec_json(&props.centroid),
            "inertia": json_float(props.inertia),
            "radius_of_gyration": json_float(props.radius_of_gyration()),
            "axis": vec_json(&axis),
            "far_face": {
                "corners": [vec_json(&face.corners[0]), vec_json(&face.corners[1])],
                "corner_names": names,
                "corner_angles_deg": [
                    json_float(shape.corner_angle(DeckEnd::Far, 0).to_degrees()),
                    json_float(shape.corner_angle(DeckEnd::Far, 1).to_degrees()),
                ],
                "length": json_float(face.length()),
                "outward_normal": vec_json(&face.outward_normal),
            },
        }),
    );
    out.insert(
        "abutment".into(),
        json!({
            "face_point": vec_json(&abut.face_point(&shape)),
            "travel_to_contact": json_float(abut.travel_to_contact(&shape)),
        }),
    );
    let mut lines: Vec<String> = Vec::new();
    lines.push(match &shape {
        DeckShape::Curved(d) => format!(
            "Curved deck R = {} m, β = {}°, W = {} m against a rigid abutment at its far end",
            d.radius,
            a.beta1.unwrap_or(d.angle.to_degrees()),
            d.width
        ),
        DeckShape::Straight(d) => format!(
            "Straight deck L = {} m, W = {} m against a rigid abutment at its far end",
            d.length, d.width
        ),
        DeckShape::Skewed(d) => format!(
            "Skew deck L = {} m, W = {} m, θ_s = {}° against a rigid abutment at its far end",
            d.length,
            d.width,
            a.skew.unwrap_or(d.skew.to_degrees())
        ),
    });
    lines.push(format!(
        "  A = {} m², m = {} kg, I = {} kg m², G = ({}, {}) m; gap {} m closes after {} m along the axis",
        fmt(props.area),
        fmt(props.mass),
        fmt(props.inertia),
        fmt(props.centroid.x),
        fmt(props.centroid.y),
        abut.gap,
        fmt(abut.travel_to_contact(&shape))
    ));
    lines.push(format!(
        "  far face: {} corner c0 = ({}, {}), {} corner c1 = ({}, {}), outward normal ({}, {}); μ = {mu}, ε_N = {eps}",
        names[0],
        fmt(face.corners[0].x),
        fmt(face.corners[0].y),
        names[1],
        fmt(face.corners[1].x),
        fmt(face.corners[1].y),
        fmt(face.outward_normal.x),
        fmt(face.outward_normal.y)
    ));
    let mut failed = false;
    if corners.len() == 1 {
        let k = corners[0];
        let c = abutment_contact(&shape, DeckEnd::Far, k);
        let g = abutment_delassus(&shape, DeckEnd::Far, k);
        let bounds = analytic::stick_interval(&g, &law);
        // longitudinal approach: u = speed · axis, ω = 0
        let gn = axis.dot(&c.normal);
        let gt = axis.dot(&c.tangent);
        let long_ratio = gt / gn;
        let long = impact::solve_single(&g, &law, -1.0, -long_ratio, &LemkeSettings::default());
        out.insert("corner_index".into(), json!(k));
        out.insert("corner_name".into(), json!(names[k]));
        out.insert("point".into(), vec_json(&c.point));
        out.insert("normal".into(), vec_json(&c.normal));
        out.insert("tangent".into(), vec_json(&c.tangent));
        out.insert(
            "lever_arms".into(),
            json!({"normal": json_float(c.arm_n), "tangential": json_float(c.arm_t)}),
        );
        out.insert(
            "delassus".into(),
            json!({"nn": json_float(g.nn), "nt": json_float(g.nt), "tt": json_float(g.tt)}),
        );
        out.insert("kappa".into(), json_float(g.kappa()));
        out.insert("varrho".into(), json_float(g.varrho()));
        out.insert(
            "stick_interval".into(),
            json!({"lower": json_float(bounds.lower), "upper": json_float(bounds.upper)}),
        );
        out.insert("painleve".into(), json!(analytic::is_painleve(&g, &law)));
        out.insert(
            "longitudinal".into(),
            json!({"ratio": json_float(long_ratio), "mode": long.mode.name(), "status": long.status.name()}),
        );
        failed |= !long.status.is_trustworthy();
        lines.push(format!(
            "Corner {} ({}) alone: arms r×n = {} m, r×t = {} m",
            k,
            names[k],
            fmt(c.arm_n),
            fmt(c.arm_t)
        ));
        lines.push(format!(
            "  Delassus: G_NN = {}  G_NT = {}  G_TT = {}  [1/kg]   κ = {:.6}  ϱ = {:.6}",
            fmt(g.nn),
            fmt(g.nt),
            fmt(g.tt),
            g.kappa(),
            g.varrho()
        ));
        lines.push(format!(
            "  stick interval in r = γ_T⁻/γ_N⁻: [{}, {}]   (t points from c0 to c1; r < L: slip-positive, r > U: slip-negative)",
            fmt(bounds.lower),
            fmt(bounds.upper)
        ));
        lines.push(format!(
            "  longitudinal approach: r = {} → {}",
            fmt(long_ratio),
            long.mode.name()
        ));
        if let Some(r) = a.ratio {
            let sol = impact::solve_single(&g, &law, -1.0, -r, &LemkeSettings::default());
            failed |= !sol.status.is_trustworthy();
            out.insert("ratio".into(), json_float(r));
            out.insert("mode".into(), json!(sol.mode.name()));
            out.insert(
                "impulse".into(),
                json!({"normal": json_float(sol.normal_impulse), "tangential": json_float(sol.tangential_impulse)}),
            );
            out.insert(
                "post".into(),
                json!({"gamma_n": json_float(sol.gamma_n_post), "gamma_t": json_float(sol.gamma_t_post)}),
            );
            out.insert(
                "energy_change".into(),
                json_float(sol.energy_change(-1.0, -r)),
            );
            out.insert("status".into(), json!(sol.status.name()));
            lines.push(format!(
                "Impact at r = {r} (γ_N⁻ = −1 m/s, γ_T⁻ = {} m/s): {} ({})",
                -r,
                sol.mode.name(),
                sol.status.name()
            ));
            lines.push(format!(
                "  Λ_N = {} N s  Λ_T = {} N s  γ_N⁺ = {} m/s  γ_T⁺ = {} m/s  ΔT = {} J",
                fmt(sol.normal_impulse),
                fmt(sol.tangential_impulse),
                fmt(sol.gamma_n_post),
                fmt(sol.gamma_t_post),
                fmt(sol.energy_change(-1.0, -r))
            ));
        }
    } else {
        let problem = abutment_problem(&shape, DeckEnd::Far, &[0, 1], speed * axis, 0.0, &law)?;
        let s = impact::solve(&problem, &ImpactSettings::default());
        failed |= !s.status.is_trustworthy();
        let pivot = frictionless_pivot(&shape, DeckEnd::Far);
        let omega = s.bodies[0].omega;
        // relative threshold: ω against the characteristic rate |v⁻|/ℓ of the approach, with ℓ the
        // largest body length (face length or radius of gyration); below 1e-9 it is rounding noise
        // (e.g. θ_s → 90°, where γ_N⁻ → 0 and ω⁺ ~ 1e-26 rad/s)
        let half_diag = face.length().max(props.radius_of_gyration());
        let rotates = omega.abs() * half_diag > 1e-9 * speed.abs();
        let open: Vec<bool> = s
            .contacts
            .iter()
            .map(|c| c.mode == ContactMode::Open)
            .collect();
        let lcp_pivot = match (open[0], open[1], rotates) {
            (true, false, true) => Value::from(names[1]),
            (false, true, true) => Value::from(names[0]),
            _ => Value::Null,
        };
        let mut rot = json!({
            "predicted_pivot": pivot.map_or(Value::Null, |k| Value::from(names[k])),
            "rotates": rotates,
            "pivot": lcp_pivot,
            "omega": json_float(omega),
        });
        if let (DeckShape::Skewed(d), Value::Object(m)) = (&shape, &mut rot) {
            m.insert("sin_2skew".into(), json_float((2.0 * d.skew).sin()));
            m.insert("two_w_over_l".into(), json_float(2.0 * d.width / d.length));
            m.insert(
                "condition_holds".into(),
                json!(d.rotates_on_abutment_impact()),
            );
            m.insert(
                "friction_condition_holds".into(),
                json!(d.rotates_on_abutment_impact_with(&law)),
            );
        }
        let contacts = corner_contacts_json(&s.contacts, &names, &face.corners);
        out.insert("speed".into(), json_float(speed));
        out.insert("contacts".into(), contacts);
        out.insert(
            "post".into(),
            json!({"velocity": vec_json(&s.bodies[0].velocity), "omega": json_float(omega)}),
        );
        out.insert(
            "energy".into(),
            json!({"before": json_float(s.energy_before), "after": json_float(s.energy_after)}),
        );
        out.insert("rotation".into(), rot);
        out.insert("status".into(), json!(s.status.name()));
        out.insert("post_velocity_unique".into(), json!(s.post_velocity_unique));
        lines.push(format!(
            "Both corners strike after a longitudinal approach at {speed} m/s: {}",
            s.status.name()
        ));
        for (k, c) in s.contacts.iter().enumerate() {
            lines.push(format!(
                "  {} corner: {}  Λ_N = {} N s  Λ_T = {} N s  γ_N: {} → {} m/s",
                names[k],
                c.mode.name(),
                fmt(c.normal_impulse),
                fmt(c.tangential_impulse),
                fmt(c.gamma_n_pre),
                fmt(c.gamma_n_post)
            ));
        }
        lines.push(format!(
            "  v⁺ = ({}, {}) m/s, ω⁺ = {} rad/s; kinetic energy {} J → {} J",
            fmt(s.bodies[0].velocity.x),
            fmt(s.bodies[0].velocity.y),
            fmt(omega),
            fmt(s.energy_before),
            fmt(s.energy_after)
        ));
        lines.push(match &lcp_pivot {
            Value::String(p) => {
                format!("  the deck rotates about its {p} corner (the other corner separates)")
            }
            _ if rotates => "  the deck rotates (both corners keep impulse)".to_string(),
            _ => "  no rotation: both corners stay in contact".to_string(),
        });
        let predicted = pivot.map_or("no rotation".to_string(), |k| {
            format!("rotation about the {} corner", names[k])
        });
        lines.push(match &shape {
            DeckShape::Skewed(d) => format!(
                "  frictionless criterion: sin 2θ_s = {:.6} {} 2W/L = {:.6} → {predicted}",
                (2.0 * d.skew).sin(),
                if d.rotates_on_abutment_impact() {
                    ">"
                } else {
                    "≤"
                },
                2.0 * d.width / d.length
            ),
            _ => format!("  frictionless criterion (centroid's foot beyond the face): {predicted}"),
        });
        if let DeckShape::Skewed(d) = &shape
            && mu > 0.0
        {
            lines.push(format!(
                "  with friction: sin 2θ_s − μ_eff (1 + cos 2θ_s) > 2W/L, μ_eff = min(μ, tan θ_s/(1+ε)): {}",
                if d.rotates_on_abutment_impact_with(&law) {
                    "rotation about the obtuse corner"
                } else {
                    "no rotation"
                }
            ));
        }
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&Value::Object(out))?);
    } else {
        for l in lines {
            println!("{l}");
        }
    }
    Ok(if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// Two straight or skew decks face to face at the joint (reference pose, zero opening): deck 1
/// approaches along its axis at `--speed`, deck 2 rests; both joint corners strike.
fn run_joint(a: &ImpactArgs, deck1: &DeckShape) -> Result<ExitCode> {
    for (set, name) in [
        (a.r2.is_some(), "--r2"),
        (a.beta2.is_some(), "--beta2"),
        (a.theta1.is_some(), "--theta1"),
        (a.theta2.is_some(), "--theta2"),
        (a.case.is_some(), "--case"),
        (a.opening.is_some(), "--opening"),
        (a.ratio.is_some(), "--ratio"),
        (a.gap.is_some(), "--gap"),
        (a.corner.is_some(), "--corner"),
    ] {
        if set {
            bail!(
                "{name} is not used for two {} decks (both joint corners strike in the reference pose)",
                deck1.name()
            );
        }
    }
    if a.sigma_mode != "exact" {
        bail!("--sigma-mode is not used with --shape {}", deck1.name());
    }
    let deck2 = match deck1 {
        DeckShape::Straight(d) => {
            let l2 = a.length2.unwrap_or(d.length);
            DeckShape::Straight(
                StraightDeck::new(l2, d.width, d.thickness, d.density)
                    .map_err(|e| rename(e, "length", "length2"))?,
            )
        }
        DeckShape::Skewed(d) => {
            let l2 = a.length2.unwrap_or(d.length);
            DeckShape::Skewed(
                SkewedDeck::new(l2, d.width, d.skew, d.thickness, d.density)
                    .map_err(|e| rename(e, "length", "length2"))?,
            )
        }
        DeckShape::Curved(_) => bail!("internal: curved decks use the S-curved bridge form"),
    };
    let mu = need(a.mu, "mu")?;
    let eps = need(a.eps, "eps")?;
    let law = ImpactLaw::new(mu, eps)?;
    let speed = a.speed.unwrap_or(1.0);
    if !(speed.is_finite() && speed > 0.0) {
        bail!(
            "invalid speed = {}: must be finite and > 0",
            float_token(speed)
        );
    }
    let v1 = speed * deck1.axis_direction(DeckEnd::Joint);
    let problem = joint_problem(deck1, &deck2, (v1, 0.0), (Vector::zeros(), 0.0), &law)?;
    let s = impact::solve(&problem, &ImpactSettings::default());
    let names = corner_names(deck1);
    let face = deck1.end_face(DeckEnd::Joint);
    let mut out = Map::new();
    let mut input = json!({
        "shape": deck1.name(),
        "abutment": false,
        "mu": json_float(mu),
        "eps": json_float(eps),
        "speed": json_float(speed),
        "width": json_float(a.width),
        "thickness": json_float(a.thickness),
        "density": json_float(a.density),
        "length": json_float(a.length.unwrap_or(f64::NAN)),
        "length2": json_float(a.length2.or(a.length).unwrap_or(f64::NAN)),
    });
    if let (Some(sk), Value::Object(m)) = (a.skew, &mut input) {
        m.insert("skew_deg".into(), json_float(sk));
    }
    out.insert("input".into(), input);
    let decks: Vec<Value> = problem
        .bodies()
        .iter()
        .zip(&s.bodies)
        .map(|(b, v)| {
            json!({
                "name": b.name,
                "mass": json_float(b.mass),
                "inertia": json_float(b.inertia),
                "centroid": vec_json(&b.position),
                "velocity_pre": vec_json(&b.velocity),
                "velocity": vec_json(&v.velocity),
                "omega": json_float(v.omega),
            })
        })
        .collect();
    out.insert("decks".into(), Value::Array(decks));
    let contacts = corner_contacts_json(&s.contacts, &names, &face.corners);
    out.insert("contacts".into(), contacts);
    out.insert(
        "energy".into(),
        json!({"before": json_float(s.energy_before), "after": json_float(s.energy_after)}),
    );
    out.insert("status".into(), json!(s.status.name()));
    out.insert("post_velocity_unique".into(), json!(s.post_velocity_unique));
    if a.json {
        println!("{}", serde_json::to_string_pretty(&Value::Object(out))?);
    } else {
        println!(
            "Two {} decks face to face at the joint (W = {} m{}), deck 1 approaching along its axis at {speed} m/s; μ = {mu}, ε_N = {eps}: {}",
            deck1.name(),
            a.width,
            a.skew.map_or(String::new(), |sk| format!(", θ_s = {sk}°")),
            s.status.name()
        );
        for (b, v) in problem.bodies().iter().zip(&s.bodies) {
            println!(
                "  {}: m = {} kg, I = {} kg m²: v⁺ = ({}, {}) m/s, ω⁺ = {} rad/s",
                b.name,
                fmt(b.mass),
                fmt(b.inertia),
                fmt(v.velocity.x),
                fmt(v.velocity.y),
                fmt(v.omega)
            );
        }
        for (k, c) in s.contacts.iter().enumerate() {
            println!(
                "  deck 1 {} corner: {}  Λ_N = {} N s  Λ_T = {} N s  γ_N: {} → {} m/s",
                names[k],
                c.mode.name(),
                fmt(c.normal_impulse),
                fmt(c.tangential_impulse),
                fmt(c.gamma_n_pre),
                fmt(c.gamma_n_post)
            );
        }
        println!(
            "  kinetic energy: {} J → {} J",
            fmt(s.energy_before),
            fmt(s.energy_after)
        );
    }
    Ok(if !s.status.is_trustworthy() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// The same geometry error with the parameter renamed (deck 2's `length` is `length2`).
fn rename(
    e: pounding::geometry::GeometryError,
    from: &str,
    to: &str,
) -> pounding::geometry::GeometryError {
    match e {
        pounding::geometry::GeometryError::InvalidParameter {
            name,
            value,
            reason,
        } => pounding::geometry::GeometryError::InvalidParameter {
            name: if name == from { to.to_string() } else { name },
            value,
            reason,
        },
    }
}
