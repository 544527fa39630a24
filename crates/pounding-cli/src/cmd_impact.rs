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
    self, ContactMode, ContactSpec, ImpactProblem, ImpactSettings, ImpactSolution, ImpactStatus,
    RigidBody, SingleSolution,
};
use pounding::lcp::LemkeSettings;
use pounding::math::Vector;
use pounding::output::json_float;
use serde_json::{Map, Value, json};
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `pounding impact`.
///
/// Bridge form: `--r1 --r2 --beta1 --beta2 --theta1 --theta2 --case --mu --eps` (angles in degrees).
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
    #[arg(long, value_name = "FILE.json", conflicts_with_all = ["r1", "r2", "beta1", "beta2", "theta1", "theta2", "case", "mu", "eps", "ratio"])]
    problem: Option<PathBuf>,
    /// Centre-line radius of deck 1 [m] (> W/2).
    #[arg(
        long,
        required_unless_present = "problem",
        allow_negative_numbers = true
    )]
    r1: Option<f64>,
    /// Centre-line radius of deck 2 [m] (> W/2).
    #[arg(
        long,
        required_unless_present = "problem",
        allow_negative_numbers = true
    )]
    r2: Option<f64>,
    /// Curve angle of deck 1 [deg], in (0, 360).
    #[arg(
        long,
        required_unless_present = "problem",
        allow_negative_numbers = true
    )]
    beta1: Option<f64>,
    /// Curve angle of deck 2 [deg], in (0, 360).
    #[arg(
        long,
        required_unless_present = "problem",
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
        required_unless_present = "problem",
        allow_negative_numbers = true
    )]
    theta1: Option<f64>,
    /// Rotation of deck 2 [deg], counter-clockwise, |θ| < 90.
    #[arg(
        long,
        required_unless_present = "problem",
        allow_negative_numbers = true
    )]
    theta2: Option<f64>,
    /// Candidate contact: deck1-inner, deck1-outer, deck2-inner or deck2-outer.
    #[arg(long, required_unless_present = "problem")]
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
    /// Print JSON instead of the readable summary.
    #[arg(long)]
    json: bool,
}

/// Runs `pounding impact`.
pub fn run(args: Args) -> Result<ExitCode> {
    let args = args.inner;
    match &args.problem {
        Some(path) => run_generic(path, args.json),
        None => run_bridge(&args),
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
    let (t1r, t2r) = (t1.to_radians(), t2.to_radians());
    validate_rotation("theta1", t1r)?;
    validate_rotation("theta2", t2r)?;
    let law = ImpactLaw::new(mu, eps)?;
    if let Some(r) = a.ratio
        && !r.is_finite()
    {
        bail!("invalid ratio = {r}: must be finite");
    }
    if let Some(g) = a.opening
        && !g.is_finite()
    {
        bail!("invalid opening = {g}: must be finite");
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
                failed = sol.status == ImpactStatus::Failed;
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

fn solution_json(p: &ImpactProblem, s: &ImpactSolution) -> Value {
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
        "solutions": s.solutions,
        "post_velocity_unique": s.post_velocity_unique,
        "impulse_unique": s.solutions <= 1,
    })
}

fn run_generic(path: &PathBuf, as_json: bool) -> Result<ExitCode> {
    let text = std::fs::read_to_string(path)
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
        }
    }
    Ok(if s.status == ImpactStatus::Failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
