//! The generic form: planar rigid bodies and contacts read from JSON.
//!
//! ```json
//! {"bodies": [{"name": "a", "mass": 1.0, "inertia": 0.1, "position": \[0, 0\],
//!              "velocity": \[1, 0\], "omega": 0}],
//!  "contacts": [{"body_a": "a", "body_b": null, "point": \[0.5, 0\], "normal": \[-1, 0\],
//!                "mu": 0.3, "restitution": 0.5}]}
//! ```
//!
//! Units: kg, kg m², m, m/s, rad/s. `body_b = null` is a fixed obstacle. Unknown and duplicate
//! keys are errors naming the key.

use super::common::{EnergyReport, ReportError, SPLIT_NOT_UNIQUE, readable, xy};
use crate::impact::{self, ContactSpec, ImpactProblem, ImpactSettings, ImpactSolution, RigidBody};
use crate::math::Vector;
use serde::Serialize;
use serde_json::{Map, Value};

fn bad(msg: String) -> ReportError {
    ReportError::Problem(msg)
}

fn num(v: &Value, path: &str) -> Result<f64, ReportError> {
    v.as_f64()
        .ok_or_else(|| bad(format!("invalid {path}: expected a number, found {v}")))
}

fn field<'a>(obj: &'a Map<String, Value>, key: &str, path: &str) -> Result<&'a Value, ReportError> {
    obj.get(key)
        .ok_or_else(|| bad(format!("missing {path}.{key}")))
}

fn pair(v: &Value, path: &str) -> Result<Vector, ReportError> {
    match v.as_array() {
        Some(a) if a.len() == 2 => Ok(Vector::new(
            num(&a[0], &format!("{path}[0]"))?,
            num(&a[1], &format!("{path}[1]"))?,
        )),
        _ => Err(bad(format!("invalid {path}: expected [x, y], found {v}"))),
    }
}

fn check_keys(obj: &Map<String, Value>, allowed: &[&str], path: &str) -> Result<(), ReportError> {
    for k in obj.keys() {
        if !allowed.contains(&k.as_str()) {
            return Err(bad(format!(
                "unknown key {path}.{k} (allowed: {})",
                allowed.join(", ")
            )));
        }
    }
    Ok(())
}

fn object<'a>(v: &'a Value, path: &str) -> Result<&'a Map<String, Value>, ReportError> {
    v.as_object()
        .ok_or_else(|| bad(format!("invalid {path}: expected an object")))
}

fn body(v: &Value, path: &str) -> Result<RigidBody, ReportError> {
    let o = object(v, path)?;
    check_keys(
        o,
        &["name", "mass", "inertia", "position", "velocity", "omega"],
        path,
    )?;
    let name = field(o, "name", path)?
        .as_str()
        .ok_or_else(|| bad(format!("invalid {path}.name: expected a string")))?;
    let n = |key: &str| num(field(o, key, path)?, &format!("{path}.{key}"));
    let p = |key: &str| pair(field(o, key, path)?, &format!("{path}.{key}"));
    Ok(RigidBody {
        name: name.to_string(),
        mass: n("mass")?,
        inertia: n("inertia")?,
        position: p("position")?,
        velocity: p("velocity")?,
        omega: n("omega")?,
    })
}

fn contact(v: &Value, path: &str) -> Result<ContactSpec, ReportError> {
    let o = object(v, path)?;
    check_keys(
        o,
        &["body_a", "body_b", "point", "normal", "mu", "restitution"],
        path,
    )?;
    let body_a = field(o, "body_a", path)?
        .as_str()
        .ok_or_else(|| bad(format!("invalid {path}.body_a: expected a body name")))?;
    let body_b = match field(o, "body_b", path)? {
        Value::Null => None,
        Value::String(s) => Some(s.clone()),
        other => {
            return Err(bad(format!(
                "invalid {path}.body_b: expected a body name or null, found {other}"
            )));
        }
    };
    let n = |key: &str| num(field(o, key, path)?, &format!("{path}.{key}"));
    let p = |key: &str| pair(field(o, key, path)?, &format!("{path}.{key}"));
    Ok(ContactSpec {
        body_a: body_a.to_string(),
        body_b,
        point: p("point")?,
        normal: p("normal")?,
        mu: n("mu")?,
        restitution: n("restitution")?,
    })
}

/// Parses the generic problem JSON (see the module docs); errors name the offending key.
pub fn parse_problem(text: &str) -> Result<ImpactProblem, ReportError> {
    crate::input::check_json_duplicate_keys(text).map_err(ReportError::Json)?;
    let root: Value = serde_json::from_str(text).map_err(ReportError::Json)?;
    let root = root.as_object().ok_or_else(|| {
        bad("the problem must be a JSON object with \"bodies\" and \"contacts\"".into())
    })?;
    check_keys(root, &["bodies", "contacts"], "problem")?;
    let bodies_v = root
        .get("bodies")
        .and_then(Value::as_array)
        .ok_or_else(|| bad("missing bodies: expected an array of bodies".into()))?;
    let contacts_v = root
        .get("contacts")
        .and_then(Value::as_array)
        .ok_or_else(|| bad("missing contacts: expected an array of contacts".into()))?;
    let bodies = bodies_v
        .iter()
        .enumerate()
        .map(|(i, b)| body(b, &format!("bodies[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    let contacts = contacts_v
        .iter()
        .enumerate()
        .map(|(j, c)| contact(c, &format!("contacts[{j}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(ImpactProblem::new(bodies, contacts)?)
}

/// Post-impact state of one body.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyStateReport {
    /// Body name.
    pub name: String,
    /// Post-impact velocity of the centre of mass \[m/s\].
    pub velocity: [f64; 2],
    /// Post-impact angular velocity \[rad/s\].
    pub omega: f64,
}

/// One contact of the generic form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactReport {
    /// The unit normal `n` the impulses are measured along: the input `normal` scaled to unit
    /// length (the input is a direction), pointing into `body_a`.
    pub normal: [f64; 2],
    /// The unit tangent `t = (−n_y, n_x)` of `Λ_T`, `γ_T⁻` and `γ_T⁺`.
    pub tangent: [f64; 2],
    /// `Λ_N` \[N s\].
    pub normal_impulse: f64,
    /// `Λ_T` \[N s\].
    pub tangential_impulse: f64,
    /// Post-impact mode (`open`, `stick`, `slip-positive`, `slip-negative`; `unsolved` when no
    /// solution was found: the impulses are `NaN`).
    pub mode: &'static str,
    /// `γ_N⁻` \[m/s\].
    pub gamma_n_pre: f64,
    /// `γ_T⁻` \[m/s\].
    pub gamma_t_pre: f64,
    /// `γ_N⁺` \[m/s\].
    pub gamma_n_post: f64,
    /// `γ_T⁺` \[m/s\].
    pub gamma_t_post: f64,
}

/// The report of the generic form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ProblemReport {
    /// Post-impact body states, in input order.
    pub bodies: Vec<BodyStateReport>,
    /// Contacts, in input order.
    pub contacts: Vec<ContactReport>,
    /// Kinetic energy.
    pub energy: EnergyReport,
    /// Solver status.
    pub status: &'static str,
    /// Number of distinct solutions (`None` when uniqueness was not checked: `3n > 12` and no
    /// enumeration).
    pub solutions: Option<usize>,
    /// Whether the post-impact velocities are unique (`None` when not checked).
    pub post_velocity_unique: Option<bool>,
    /// Whether the impulses are unique (`None` when not checked).
    pub impulse_unique: Option<bool>,
    /// Whether the tangential impulses of the sticking contacts are unique given the normal
    /// impulses and the post-impact velocities; when `false` the contacts report the split of
    /// smallest norm (e.g. the equal split of two symmetric contacts). `None` without a solution.
    pub tangential_split_unique: Option<bool>,
    /// Whether the status allows the numbers to be used.
    #[serde(skip)]
    pub trustworthy: bool,
    /// Whether the solver enumerated the complementary bases.
    #[serde(skip)]
    pub enumerated: bool,
    /// The post-solve law violation, if any.
    #[serde(skip)]
    pub law_violation: Option<String>,
}

/// Whether `solutions` / uniqueness are known: enumeration ran, or the problem is small enough
/// (`3n ≤ 12`) for the solver to enumerate whenever uniqueness is in doubt (singular `G` or a
/// Lemke failure). With `3n > 12` and no enumeration nothing was checked.
fn uniqueness_checked(p: &ImpactProblem, s: &ImpactSolution) -> bool {
    s.enumerated || 3 * p.contacts().len() <= crate::lcp::enumerate::MAX_ENUM_DIM
}

/// Solves a generic problem with the default settings and reports it.
pub fn problem_report(problem: &ImpactProblem) -> ProblemReport {
    let s = impact::solve(problem, &ImpactSettings::default());
    let checked = uniqueness_checked(problem, &s);
    ProblemReport {
        bodies: problem
            .bodies()
            .iter()
            .zip(&s.bodies)
            .map(|(b, v)| BodyStateReport {
                name: b.name.clone(),
                velocity: xy(&v.velocity),
                omega: v.omega,
            })
            .collect(),
        contacts: s
            .contacts
            .iter()
            .zip(problem.contacts())
            .map(|(c, k)| ContactReport {
                normal: xy(&k.normal),
                tangent: xy(&k.tangent),
                normal_impulse: c.normal_impulse,
                tangential_impulse: c.tangential_impulse,
                mode: if c.normal_impulse.is_nan() {
                    "unsolved"
                } else {
                    c.mode.name()
                },
                gamma_n_pre: c.gamma_n_pre,
                gamma_t_pre: c.gamma_t_pre,
                gamma_n_post: c.gamma_n_post,
                gamma_t_post: c.gamma_t_post,
            })
            .collect(),
        energy: EnergyReport {
            before: s.energy_before,
            after: s.energy_after,
        },
        status: s.status.name(),
        solutions: checked.then_some(s.solutions),
        // uniqueness is a property of solutions: unknown (null) when none was found
        post_velocity_unique: (checked && s.solutions > 0).then_some(s.post_velocity_unique),
        impulse_unique: (checked && s.solutions > 0).then_some(s.solutions <= 1),
        tangential_split_unique: matches!(
            s.status,
            impact::ImpactStatus::Solved | impact::ImpactStatus::SolvedByFallback
        )
        .then_some(s.tangential_split_unique),
        trustworthy: s.status.is_trustworthy(),
        enumerated: s.enumerated,
        law_violation: s.law_violation.as_ref().map(|v| v.to_string()),
    }
}

impl ProblemReport {
    /// Whether the status allows the numbers to be used.
    pub fn trustworthy(&self) -> bool {
        self.trustworthy
    }

    /// The readable summary (one line per entry) that `pounding impact --problem` prints.
    pub fn summary(&self) -> Vec<String> {
        let count =
            |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
        let mut lines = vec![format!(
            "Impact of {} at {}: {}",
            count(self.bodies.len(), "body", "bodies"),
            count(self.contacts.len(), "contact", "contacts"),
            self.status
        )];
        for b in &self.bodies {
            lines.push(format!(
                "  {}: v⁺ = ({}, {}) m/s, ω⁺ = {} rad/s",
                b.name,
                readable(b.velocity[0]),
                readable(b.velocity[1]),
                readable(b.omega)
            ));
        }
        for (j, c) in self.contacts.iter().enumerate() {
            lines.push(format!(
                "  contact {j}: {}  Λ_N = {} N s  Λ_T = {} N s  γ_N: {} → {}  γ_T: {} → {} m/s",
                c.mode,
                readable(c.normal_impulse),
                readable(c.tangential_impulse),
                readable(c.gamma_n_pre),
                readable(c.gamma_n_post),
                readable(c.gamma_t_pre),
                readable(c.gamma_t_post)
            ));
        }
        lines.push(format!(
            "  kinetic energy: {} J → {} J",
            readable(self.energy.before),
            readable(self.energy.after)
        ));
        if self.tangential_split_unique == Some(false) {
            lines.push(SPLIT_NOT_UNIQUE.to_string());
        }
        if let Some(v) = &self.law_violation {
            lines.push(format!(
                "  post-solve check failed (numbers not trustworthy): {v}"
            ));
        }
        if self.enumerated && self.solutions == Some(0) {
            lines.push("  enumeration: no solution found".to_string());
        } else if self.enumerated {
            lines.push(format!(
                "  enumeration: {} distinct solution(s); post-impact velocities {}",
                self.solutions.unwrap_or(0),
                if self.post_velocity_unique == Some(true) {
                    "unique"
                } else {
                    "NOT unique"
                }
            ));
        } else if self.solutions.is_none() {
            lines.push(format!(
                "  uniqueness: not checked (enumeration runs only for 3n <= 12; here 3n = {})",
                3 * self.contacts.len()
            ));
        }
        lines
    }
}
