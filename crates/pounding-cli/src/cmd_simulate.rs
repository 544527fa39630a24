//! `pounding simulate`: seismic time-history simulation of two decks (curved, straight or skewed,
//! optionally with abutments) with pounding.
//!
//! Reads an optional scenario TOML (unknown keys are errors; record paths resolve relative to the
//! scenario file), runs [`pounding::sim::simulate`] and writes `history.csv`, `impacts.csv`,
//! `summary.json`, `timing.json` and PNG plots into the output directory. Every input is validated
//! before anything is written. With `--records` it runs a batch instead ([`sim_batch`]).

use anyhow::{Context, Result, anyhow, bail};
use pounding::geometry::{ContactCase, Deck, SArrangement};
use pounding::ground_motion::{
    AccelUnits, EL_CENTRO_180_AT2, EL_CENTRO_270_AT2, GroundMotion, Record,
};
use pounding::math::{Real, Vector};
use pounding::output::{float_token, json_float, write_atomic};
use pounding::shape::{DeckShape, SkewedDeck, StraightDeck};
use pounding::sim::{
    Bearing, JointContact, SEAT_ENDS, SimAbutment, SimError, SimModel, SimProblem, SimSettings,
    SimSolution, simulate,
};
use pounding::toml_schema::{Exact, Table};
use serde::Deserialize;
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[path = "sim_plots.rs"]
pub(crate) mod sim_plots;

#[path = "sim_contact.rs"]
pub(crate) mod sim_contact;

#[path = "sim_batch.rs"]
mod sim_batch;

/// Arguments of `pounding simulate`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario file (TOML); without it the built-in default runs (see --print-default).
    pub scenario: Option<PathBuf>,
    /// Use this record (PEER .AT2, or .csv `t, a` in g) as the only ground-motion component,
    /// along y (normal to the joint); replaces the scenario's records.
    #[arg(long, value_name = "FILE")]
    pub record: Option<PathBuf>,
    /// Multiply both ground-motion scale factors by S.
    #[arg(long, value_name = "S")]
    pub scale: Option<f64>,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "out/simulate")]
    pub out: PathBuf,
    /// Print the built-in default scenario as commented TOML and exit.
    #[arg(long)]
    pub print_default: bool,
    /// Batch mode: run every record (files, or directories whose `.AT2`/`.csv` files are taken
    /// in name order) at every `--scales` factor, each as the only component along y (as
    /// `--record`); writes `batch.csv` and `batch.png`. Put the scenario file before this flag.
    #[arg(long, num_args = 1.., value_name = "DIR_OR_FILE", conflicts_with_all = ["record", "scale"])]
    pub records: Vec<PathBuf>,
    /// Batch mode: scale factors, comma separated (each multiplies the scenario's scale_y, as
    /// `--scale`). Default: 1.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "S1,S2,...",
        requires = "records"
    )]
    pub scales: Vec<f64>,
    /// Batch mode: worker threads (default: all cores). batch.csv is identical for any value.
    #[arg(long, value_name = "N", requires = "records")]
    pub threads: Option<usize>,
    /// Batch mode: run only the runs whose global index i (0-based, record-major) has
    /// i mod N = K − 1.
    #[arg(long, value_name = "K/N", requires = "records")]
    pub shard: Option<String>,
}

/// The built-in default scenario (also what `--print-default` prints).
pub const DEFAULT_SCENARIO: &str = r#"# pounding simulate — scenario file (TOML). Every key is optional; the values below are the
# built-in defaults. Unknown keys are errors. Paths are relative to this file.
# Frame (spec §4): x along the joint line, y normal to it pointing into deck 1; angles in degrees.

[decks]
# shape = "curved"  # "curved" (the S arrangement, below), "straight" (rectangles L x width) or
#                   # "skew" (parallelograms: end faces along the joint line, axis turned by
#                   # skew_deg from the joint normal); straight/skew need L1 and L2 [m]:
# L1 = 40.0         # length of deck 1 along its axis [m] (straight/skew)
# L2 = 40.0         # length of deck 2 [m] (straight/skew)
# skew_deg = 30.0   # skew angle in [0, 90) (skew)
R1 = 100.0          # centre-line radius of deck 1 [m]
R2 = 100.0          # centre-line radius of deck 2 [m]
beta1_deg = 60.0    # curve angle of deck 1 [deg]
beta2_deg = 60.0    # curve angle of deck 2 [deg]
width = 10.0        # common deck width W [m]
thickness = 0.5     # [m]
density = 2500.0    # [kg/m^3]  (1309 t per deck)

[joint]
gap = 0.05          # joint opening g [m]
seat_length = 0.4   # seat length at every deck end [m]; exceeding it = unseating
mu = 0.5            # Coulomb friction coefficient at the joint
eps_n = 0.5         # Newton restitution coefficient

# [abutments]       # optional rigid abutments beyond the far end of each deck (same mu, eps_n)
# gap1 = 0.05       # gap between deck 1's far end face and its abutment [m]
# seat_length1 = 0.4  # seat length of that end [m] (default: [joint] seat_length)
# gap2 = 0.05
# seat_length2 = 0.4

[bearings]
# One bearing at each of the 4 end-face corners of each deck (linear, same stiffness in x and y).
stiffness1 = 2.02e7 # per bearing, deck 1 [N/m]  (translational period ~0.8 s)
stiffness2 = 8.97e6 # per bearing, deck 2 [N/m]  (translational period ~1.2 s)
damping_ratio = 0.05  # Rayleigh, at each deck's two lowest distinct frequencies
# points1 = [[5.0, 0.0], [-5.0, 0.0]]  # optional custom bearing points of deck 1 [m],
#                                      # relative to its joint-face midpoint, reference pose

[ground_motion]
# A file path (PEER .AT2 in g, or .csv "t, a"), "builtin:ELC180" / "builtin:ELC270"
# (El Centro 1940, RSN 6, embedded), or "none".
record_y = "builtin:ELC180"  # acts along y (normal to the joint) for incidence 0
record_x = "builtin:ELC270"  # acts along x (along the joint)
scale_y = 1.0
scale_x = 1.0
incidence_deg = 0.0          # turns both components counter-clockwise
csv_units = "g"              # units of .csv records: "g" or "m/s2"

[time]
dt = 1e-3            # time step [s]
# duration = 53.71   # [s]; default: until the last record sample
history_every = 10   # write every n-th step to history.csv (peaks use every step)

# [contact]          # the joint's normal contact law (see the README, "Compliance contact laws in the simulator")
# law = "rigid"      # rigid (Newton + Coulomb LCP, default) | kelvin | hertz | hertz-damp |
#                    # bilinear | jankowski: compliance laws (trapezoid + Newton on the forces)
# restitution = 0.5  # target e of the damped laws (default: [joint] eps_n)
# k = 1e10           # kelvin [N/m]; c = ... [N s/m] instead of restitution
# k_h = 2.747e10     # hertz, hertz-damp, bilinear derivation [N/m^1.5] (25 000 kip/in^1.5)
# k1 = 1.5586e10     # bilinear, all three or none (then from k_h, restitution,
# k2 = 3.1328e9      #   delta_m = 0.0254, a = 0.1)
# delta_y = 2.54e-3
# friction_velocity = 1e-3  # regularisation of Coulomb friction [m/s]
# Also: [decks] mass1 / mass2 (deck mass directly) and [bearings] damping = "dashpots"
# (c = 2 zeta m omega to the ground, x and y) instead of "rayleigh".
"#;

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Scenario {
    // `Table`: a section written as an array is an error (serde would read it by position).
    #[serde(default)]
    decks: Table<DecksSec>,
    #[serde(default)]
    joint: Table<JointSec>,
    #[serde(default)]
    bearings: Table<BearingsSec>,
    #[serde(default)]
    ground_motion: Table<GroundSec>,
    #[serde(default)]
    time: Table<TimeSec>,
    #[serde(default)]
    contact: Table<sim_contact::ContactSec>,
    #[serde(default)]
    abutments: Table<AbutmentsSec>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct AbutmentsSec {
    gap1: Option<f64>,
    gap2: Option<f64>,
    seat_length1: Option<f64>,
    seat_length2: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
#[allow(non_snake_case)]
struct DecksSec {
    shape: String,
    L1: Option<f64>,
    L2: Option<f64>,
    skew_deg: Option<f64>,
    R1: f64,
    R2: f64,
    beta1_deg: f64,
    beta2_deg: f64,
    width: f64,
    thickness: f64,
    density: f64,
    mass1: Option<f64>,
    mass2: Option<f64>,
}
impl Default for DecksSec {
    fn default() -> Self {
        Self {
            shape: "curved".into(),
            L1: None,
            L2: None,
            skew_deg: None,
            R1: 100.0,
            R2: 100.0,
            beta1_deg: 60.0,
            beta2_deg: 60.0,
            width: 10.0,
            thickness: 0.5,
            density: 2500.0,
            mass1: None,
            mass2: None,
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
struct JointSec {
    gap: f64,
    seat_length: f64,
    mu: f64,
    eps_n: f64,
}
impl Default for JointSec {
    fn default() -> Self {
        Self {
            gap: 0.05,
            seat_length: 0.4,
            mu: 0.5,
            eps_n: 0.5,
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
struct BearingsSec {
    stiffness1: f64,
    stiffness2: f64,
    damping_ratio: f64,
    points1: Option<Vec<Exact<2>>>,
    points2: Option<Vec<Exact<2>>>,
    damping: String,
}
impl Default for BearingsSec {
    fn default() -> Self {
        Self {
            stiffness1: 2.02e7,
            stiffness2: 8.97e6,
            damping_ratio: 0.05,
            points1: None,
            points2: None,
            damping: "rayleigh".into(),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
struct GroundSec {
    record_y: String,
    record_x: String,
    scale_y: f64,
    scale_x: f64,
    incidence_deg: f64,
    csv_units: String,
}
impl Default for GroundSec {
    fn default() -> Self {
        Self {
            record_y: "builtin:ELC180".into(),
            record_x: "builtin:ELC270".into(),
            scale_y: 1.0,
            scale_x: 1.0,
            incidence_deg: 0.0,
            csv_units: "g".into(),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, default)]
struct TimeSec {
    dt: f64,
    duration: Option<f64>,
    history_every: i64,
}
impl Default for TimeSec {
    fn default() -> Self {
        Self {
            dt: 1e-3,
            duration: None,
            history_every: 10,
        }
    }
}

/// Where a scenario came from (for error messages and relative paths).
struct Source {
    name: String,
    text: String,
    dir: PathBuf,
}

impl Source {
    /// 1-based line of `key` in `[section]`, if the key is written in the file.
    fn line_of(&self, section: &str, key: &str) -> Option<usize> {
        let mut cur = String::new();
        for (i, raw) in self.text.lines().enumerate() {
            let l = raw.trim();
            if l.starts_with('[') {
                cur = l.trim_matches(|c| c == '[' || c == ']').trim().to_string();
                continue;
            }
            if cur == section
                && let Some((k, _)) = l.split_once('=')
                && k.trim().trim_matches('"') == key
            {
                return Some(i + 1);
            }
        }
        None
    }
    /// "`[section] key` (scenario:LINE)" or "`[section] key` (default)".
    fn key_ref(&self, section: &str, key: &str) -> String {
        match self.line_of(section, key) {
            Some(l) => format!("`[{section}] {key}` ({}:{l})", self.name),
            None => format!("`[{section}] {key}` (not set in {}; default)", self.name),
        }
    }
}

/// `x` with `decimals` decimals for `|x| < 1e6`, in exponent form (`1.2346e190`) beyond, and
/// `inf`/`-inf`/`nan` when not finite: a bounded width for the summary line of a diverged run.
fn bounded(x: Real, decimals: usize) -> String {
    if !x.is_finite() {
        float_token(x)
    } else if x.abs() < 1e6 {
        format!("{x:.decimals$}")
    } else {
        format!("{x:.4e}")
    }
}

/// Refuses a run whose estimated memory ([`pounding::sim::options::run_memory_bytes`]) exceeds
/// [`pounding::sim::options::MAX_RUN_MEMORY_BYTES`], naming `[time] history_every`, `duration`
/// and `dt` and the smallest `history_every` that fits.
fn check_memory(src: &Source, settings: &SimSettings, duration: Real) -> Result<()> {
    use pounding::sim::options::{MAX_RUN_MEMORY_BYTES, min_history_stride};
    let Err(_) = settings.check_memory(duration) else {
        return Ok(());
    };
    let n = settings.step_count(duration).map_err(|e| anyhow!("{e}"))?;
    let bytes = pounding::sim::options::run_memory_bytes(n, settings.history_stride);
    let gib = |b: u64| b as Real / (1u64 << 30) as Real;
    let advice = match min_history_stride(n) {
        Some(s) => format!("set history_every >= {s} (or shorten the run)"),
        None => "shorten the run or use a larger dt".into(),
    };
    bail!(
        "run too large: {n} steps with history_every = {} need an estimated \
         {:.1} GiB of memory, more than the limit {:.0} GiB; {advice} — set by {}, {} and {}",
        settings.history_stride,
        gib(bytes),
        gib(MAX_RUN_MEMORY_BYTES),
        src.key_ref("time", "history_every"),
        src.key_ref("time", "duration"),
        src.key_ref("time", "dt")
    )
}

/// The error of a step `dt` longer than the run `duration`, blaming what the user set: the
/// record (its name and last sample time) when the duration is the record's, else `[time] dt`
/// and `[time] duration`.
fn refuse_dt_beyond_duration(
    src: &Source,
    args: &Args,
    settings: &SimSettings,
    duration: Real,
    records: &[String; 2],
) -> Result<()> {
    let by_user = |key: &str| args.scenario.is_some() && src.line_of("time", key).is_some();
    let dt_by = if by_user("dt") {
        src.key_ref("time", "dt")
    } else {
        "the built-in default dt".into()
    };
    if settings.duration.is_none() {
        let names: Vec<&str> = records
            .iter()
            .map(String::as_str)
            .filter(|r| !r.eq_ignore_ascii_case("none"))
            .collect();
        bail!(
            "the ground motion lasts only {} s (the last sample of record {}), less than one time \
             step dt = {} s ({dt_by}): check the record's sample interval, or set [time] duration",
            float_token(duration),
            names.join(" and "),
            float_token(settings.dt)
        );
    }
    bail!(
        "invalid dt = {}: must not exceed the duration {} s — set by {dt_by} and {}",
        float_token(settings.dt),
        float_token(duration),
        src.key_ref("time", "duration")
    )
}

/// A one-line note on stderr when the given `[time] duration` is not a whole number of steps:
/// the run takes `⌈duration/dt⌉` steps, so it ends after the duration.
fn note_rounded_duration(settings: &SimSettings, duration: Real) {
    let Some(d) = settings.duration else { return };
    let Ok(n) = settings.step_count(duration) else {
        return;
    };
    let end = n as Real * settings.dt;
    if (end - d).abs() > 1e-9 * d {
        // 13 significant digits: 4 × 0.3 reads as 1.2
        let end: Real = format!("{end:.12e}").parse().unwrap_or(end);
        eprintln!(
            "note: duration = {} s is not a multiple of dt = {} s: the run takes {n} steps, to \
             t = {} s",
            float_token(d),
            float_token(settings.dt),
            float_token(end)
        );
    }
}

/// Maps a library parameter name onto the scenario key that sets it.
fn scenario_key(name: &str) -> Option<(&'static str, &'static str)> {
    Some(match name {
        "dt" => ("time", "dt"),
        "duration" => ("time", "duration"),
        "history_stride" => ("time", "history_every"),
        "gap" => ("joint", "gap"),
        "seat_length" => ("joint", "seat_length"),
        "mu" => ("joint", "mu"),
        "eps_n" => ("joint", "eps_n"),
        "damping_ratio" => ("bearings", "damping_ratio"),
        "R1" => ("decks", "R1"),
        "R2" => ("decks", "R2"),
        "beta1" => ("decks", "beta1_deg"),
        "beta2" => ("decks", "beta2_deg"),
        "width" | "width (deck 2)" | "joint face length (deck 2)" => ("decks", "width"),
        "L1" => ("decks", "L1"),
        "L2" => ("decks", "L2"),
        "skew1" | "skew2" => ("decks", "skew_deg"),
        "abutment gap (deck 1)" => ("abutments", "gap1"),
        "abutment gap (deck 2)" => ("abutments", "gap2"),
        "abutment seat_length (deck 1)" => ("abutments", "seat_length1"),
        "abutment seat_length (deck 2)" => ("abutments", "seat_length2"),
        "thickness" => ("decks", "thickness"),
        "density" => ("decks", "density"),
        "scale_y" => ("ground_motion", "scale_y"),
        "scale_x" => ("ground_motion", "scale_x"),
        "incidence" => ("ground_motion", "incidence_deg"),
        n if n.starts_with("bearing stiffness (deck 1") => ("bearings", "stiffness1"),
        n if n.starts_with("bearing stiffness (deck 2") => ("bearings", "stiffness2"),
        n if n.starts_with("bearing point (deck 1") => ("bearings", "points1"),
        n if n.starts_with("bearing point (deck 2") => ("bearings", "points2"),
        _ => return None,
    })
}

fn sim_error(src: &Source, e: SimError) -> anyhow::Error {
    let name = match &e {
        SimError::InvalidParameter { name, .. } => Some(name.clone()),
        SimError::Geometry(pounding::geometry::GeometryError::InvalidParameter {
            name, ..
        }) => Some(name.clone()),
        SimError::GroundMotion(pounding::ground_motion::GroundMotionError::InvalidParameter {
            name,
            ..
        }) => Some(name.clone()),
        _ => None,
    };
    // A deck's mass is set by `massJ` when given, else derived from the geometry and density.
    if let Some(j) = name
        .as_deref()
        .and_then(|n| n.strip_prefix("mass (deck "))
        .and_then(|n| n.strip_suffix(')'))
    {
        let key = format!("mass{j}");
        let key = if src.line_of("decks", &key).is_some() {
            key
        } else {
            "density".into()
        };
        return anyhow!("{e} — set by {}", src.key_ref("decks", &key));
    }
    match name.as_deref().and_then(scenario_key) {
        Some((sec, key)) => anyhow!("{e} — set by {}", src.key_ref(sec, key)),
        None => anyhow!("{e}"),
    }
}

/// The deck shapes of `[decks]`: `None` for `shape = "curved"` (the S arrangement of `R1 R2
/// beta1_deg beta2_deg`), else two straight / skewed decks of lengths `L1`, `L2` (values are
/// validated later by the model, with errors naming `L1`, `skew_deg`, …).
fn deck_shapes(src: &Source, d: &DecksSec) -> Result<Option<[DeckShape; 2]>> {
    let shape = d.shape.trim();
    let only = |key: &str, for_shape: &str| -> Result<()> {
        if src.line_of("decks", key).is_some() {
            bail!(
                "{} applies to shape = \"{for_shape}\" only (shape is \"{shape}\")",
                src.key_ref("decks", key)
            );
        }
        Ok(())
    };
    match shape {
        "curved" => {
            for k in ["L1", "L2"] {
                only(k, "straight\" or \"skew")?;
            }
            only("skew_deg", "skew")?;
            Ok(None)
        }
        "straight" | "skew" => {
            for k in ["R1", "R2", "beta1_deg", "beta2_deg"] {
                only(k, "curved")?;
            }
            if shape == "straight" {
                only("skew_deg", "skew")?;
            }
            let len = |v: Option<f64>, key: &str| {
                v.ok_or_else(|| {
                    anyhow!(
                        "shape = \"{shape}\" needs {} (deck length along its axis, m)",
                        src.key_ref("decks", key)
                    )
                })
            };
            let (l1, l2) = (len(d.L1, "L1")?, len(d.L2, "L2")?);
            let skew = match d.skew_deg {
                // checked in degrees, so that the message shows the user's value
                Some(s) if !(s.is_finite() && (0.0..90.0).contains(&s)) => bail!(
                    "invalid skew_deg = {}: the skew angle must lie in [0, 90) degrees — set by {}",
                    float_token(s),
                    src.key_ref("decks", "skew_deg")
                ),
                Some(s) => s.to_radians(),
                None if shape == "skew" => bail!(
                    "shape = \"skew\" needs skew_deg (the skew angle in [0, 90) deg, in \
                     [decks]; use shape = \"straight\" for 0) — set by {}",
                    src.key_ref("decks", "shape")
                ),
                None => 0.0,
            };
            let mk = |l: f64| {
                if shape == "straight" {
                    DeckShape::Straight(StraightDeck {
                        length: l,
                        width: d.width,
                        thickness: d.thickness,
                        density: d.density,
                    })
                } else {
                    DeckShape::Skewed(SkewedDeck {
                        length: l,
                        width: d.width,
                        skew,
                        thickness: d.thickness,
                        density: d.density,
                    })
                }
            };
            Ok(Some([mk(l1), mk(l2)]))
        }
        other => bail!(
            "invalid shape {other:?} at {}: use \"curved\", \"straight\" or \"skew\"",
            src.key_ref("decks", "shape")
        ),
    }
}

/// Everything needed to run, built and validated from the scenario and the flags.
pub(crate) struct Setup {
    pub(crate) problem: SimProblem,
    pub(crate) settings: SimSettings,
    records: [String; 2],
    /// Units of `.csv` records.
    units: AccelUnits,
}

fn load_record(src: &Source, spec: &str, key: &str, units: AccelUnits) -> Result<Option<Record>> {
    let spec_t = spec.trim();
    if spec_t.eq_ignore_ascii_case("none") {
        return Ok(None);
    }
    if let Some(b) = spec_t.strip_prefix("builtin:") {
        let (text, name) = match b {
            "ELC180" => (EL_CENTRO_180_AT2, "RSN6_IMPVALL.I_I-ELC180-hor1.AT2"),
            "ELC270" => (EL_CENTRO_270_AT2, "RSN6_IMPVALL.I_I-ELC270-hor2.AT2"),
            other => bail!(
                "unknown built-in record {other:?} in {} (use builtin:ELC180 or builtin:ELC270)",
                src.key_ref("ground_motion", key)
            ),
        };
        return Ok(Some(Record::from_at2_str(text, name)?));
    }
    let path = src.dir.join(spec_t);
    let r = Record::from_path(&path, units).with_context(|| {
        format!(
            "ground-motion record given by {}",
            src.key_ref("ground_motion", key)
        )
    })?;
    Ok(Some(r))
}

fn build(args: &Args) -> Result<Setup> {
    build_with(args, None)
}

/// [`build`] with the joint's contact law replaced by `law` (a [`sim_contact::LAW_NAMES`] name).
pub(crate) fn build_with(args: &Args, law: Option<&str>) -> Result<Setup> {
    let src = match &args.scenario {
        Some(p) => {
            let text =
                pounding::input::read_text(p, "scenario file", pounding::input::SCENARIO_LIMIT)
                    .with_context(|| format!("cannot read scenario file {}", p.display()))?;
            let dir = p
                .parent()
                .map(Path::to_path_buf)
                .unwrap_or_else(|| PathBuf::from("."));
            Source {
                name: p.display().to_string(),
                text,
                dir: if dir.as_os_str().is_empty() {
                    PathBuf::from(".")
                } else {
                    dir
                },
            }
        }
        None => Source {
            name: "built-in default".into(),
            text: DEFAULT_SCENARIO.into(),
            dir: PathBuf::from("."),
        },
    };
    let sc: Scenario = toml::from_str(&src.text).map_err(|e| {
        anyhow!(
            "invalid scenario {}: {}",
            src.name,
            pounding::input::shorten_lines(&e.to_string(), 200)
        )
    })?;

    let d = &sc.decks;
    let deck = |r: f64, b: f64| Deck {
        radius: r,
        angle: b.to_radians(),
        width: d.width,
        thickness: d.thickness,
        density: d.density,
    };
    let arr = SArrangement {
        deck1: deck(d.R1, d.beta1_deg),
        deck2: deck(d.R2, d.beta2_deg),
    };
    let j = &sc.joint;
    let b = &sc.bearings;
    let shapes = deck_shapes(&src, d)?;
    let mut model = match shapes {
        None => SimModel::with_corner_bearings(
            arr,
            j.gap,
            b.stiffness1,
            b.stiffness2,
            b.damping_ratio,
            j.mu,
            j.eps_n,
            j.seat_length,
        ),
        Some(sh) => SimModel::with_shapes(
            sh,
            j.gap,
            b.stiffness1,
            b.stiffness2,
            b.damping_ratio,
            j.mu,
            j.eps_n,
            j.seat_length,
        ),
    };
    let ab = &sc.abutments;
    for (k, gap, seat) in [(0, ab.gap1, ab.seat_length1), (1, ab.gap2, ab.seat_length2)] {
        match (gap, seat) {
            (Some(gap), seat) => {
                model.abutments[k] = Some(SimAbutment {
                    gap,
                    seat_length: seat.unwrap_or(j.seat_length),
                })
            }
            (None, Some(_)) => bail!(
                "{} is set but {} is not (an abutment needs its gap)",
                src.key_ref("abutments", &format!("seat_length{}", k + 1)),
                src.key_ref("abutments", &format!("gap{}", k + 1))
            ),
            (None, None) => {}
        }
    }
    // Validate the decks before using them for the default bearing points.
    model.validate().map_err(|e| sim_error(&src, e))?;
    sim_contact::apply_shape_and_damping(&src, d, &b.damping, &mut model)?;
    model.contact = sim_contact::build_contact(&src, &sc.contact, law, j.eps_n, model.masses())?;
    if !matches!(model.contact, JointContact::Rigid) && model.abutments.iter().any(Option::is_some)
    {
        let set: Vec<String> = ["gap1", "gap2", "seat_length1", "seat_length2"]
            .into_iter()
            .filter(|k| src.line_of("abutments", k).is_some())
            .map(|k| src.key_ref("abutments", k))
            .collect();
        let by = match law {
            Some(l) => format!("the compared law {l:?}"),
            None => src.key_ref("contact", "law"),
        };
        bail!(
            "abutments are only supported with rigid contact: {by} is a compliance law, but \
             {} set abutments (remove [abutments] or use law = \"rigid\")",
            set.join(", ")
        );
    }
    for (deck_no, pts, k, key) in [
        (1, &b.points1, b.stiffness1, "points1"),
        (2, &b.points2, b.stiffness2, "points2"),
    ] {
        if let Some(pts) = pts {
            if pts.is_empty() {
                bail!(
                    "{} is empty (omit it for the default 4 corners)",
                    src.key_ref("bearings", key)
                );
            }
            let v: Vec<Bearing> = pts
                .iter()
                .map(|p| Bearing {
                    point: Vector::new(p[0], p[1]),
                    stiffness: k,
                })
                .collect();
            if deck_no == 1 {
                model.bearings1 = v;
            } else {
                model.bearings2 = v;
            }
        }
    }

    let g = &sc.ground_motion;
    let units = AccelUnits::from_name(&g.csv_units).ok_or_else(|| {
        anyhow!(
            "invalid csv_units {:?} at {}: use \"g\" or \"m/s2\"",
            g.csv_units,
            src.key_ref("ground_motion", "csv_units")
        )
    })?;
    let (along_y, along_x, records) = match &args.record {
        None if !args.records.is_empty() => (None, None, ["batch".into(), "none".into()]),
        Some(p) => {
            let r =
                Record::from_path(p, units).with_context(|| format!("--record {}", p.display()))?;
            (Some(r), None, [p.display().to_string(), "none".into()])
        }
        None => (
            load_record(&src, &g.record_y, "record_y", units)?,
            load_record(&src, &g.record_x, "record_x", units)?,
            [g.record_y.clone(), g.record_x.clone()],
        ),
    };
    let mult = match args.scale {
        Some(s) if s.is_finite() => s,
        Some(s) => bail!("invalid --scale {}: must be finite", float_token(s)),
        None => 1.0,
    };
    let ground = GroundMotion {
        along_y,
        scale_y: g.scale_y * mult,
        along_x,
        scale_x: g.scale_x * mult,
        incidence: g.incidence_deg.to_radians(),
    };
    ground
        .validate()
        .map_err(|e| sim_error(&src, SimError::from(e)))?;

    let t = &sc.time;
    if t.history_every < 1 {
        bail!(
            "invalid history_every = {}: must be >= 1 — set by {}",
            t.history_every,
            src.key_ref("time", "history_every")
        );
    }
    let settings = SimSettings {
        dt: t.dt,
        duration: t.duration,
        history_stride: t.history_every as usize,
        ..SimSettings::default()
    };
    settings.validate().map_err(|e| sim_error(&src, e))?;
    model.validate().map_err(|e| sim_error(&src, e))?;
    model.linear_system().map_err(|e| sim_error(&src, e))?;
    if args.records.is_empty() && settings.duration.is_none() && ground.end_time() <= 0.0 {
        bail!(
            "no ground motion samples after t = 0: set {}",
            src.key_ref("time", "duration")
        );
    }
    // The straight-deck / dashpot / contact options are validated with the model.
    // The duration run (batch runs without `duration` use each record's length, checked there).
    let duration = settings
        .duration
        .or(args.records.is_empty().then(|| ground.end_time()));
    if let Some(d) = duration {
        settings.step_count(d).map_err(|e| {
            let by = if src.line_of("time", "duration").is_some() {
                format!(" and {}", src.key_ref("time", "duration"))
            } else {
                String::new()
            };
            anyhow!("{e} — set by {}{by}", src.key_ref("time", "dt"))
        })?;
        if law.is_none() && args.records.is_empty() {
            check_memory(&src, &settings, d)?;
            note_rounded_duration(&settings, d);
        }
    }
    if let Some(d) = duration
        && settings.dt > d
    {
        refuse_dt_beyond_duration(&src, args, &settings, d, &records)?;
    }
    Ok(Setup {
        problem: SimProblem::at_rest(model, ground),
        settings,
        records,
        units,
    })
}

/// Runs `pounding simulate`.
pub fn run(args: Args) -> Result<ExitCode> {
    if args.print_default {
        print!("{DEFAULT_SCENARIO}");
        return Ok(ExitCode::SUCCESS);
    }
    let t_start = Instant::now();
    let setup = build(&args)?;
    if !args.records.is_empty() {
        return sim_batch::run(&args, &setup.problem, &setup.settings, setup.units, t_start);
    }
    pounding::output::check_output_dir_free(&args.out)?;
    let t_sim = Instant::now();
    let sol = simulate(&setup.problem, &setup.settings).map_err(|e| anyhow!("{e}"))?;
    let sim_secs = t_sim.elapsed().as_secs_f64();
    warn_time_step(&sol);

    let out = &args.out;
    let _lock = lock_and_clear(out)?;
    let t_write = Instant::now();
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("history.csv", history_csv(&setup, &sol).as_bytes())?;
    wr("impacts.csv", impacts_csv(&sol).as_bytes())?;
    let summary = summary_json(&setup, &sol);
    wr(
        "summary.json",
        (serde_json::to_string_pretty(&summary)? + "\n").as_bytes(),
    )?;
    sim_plots::write_all(out, &setup.problem, &sol).map_err(|e| anyhow!("plotting: {e}"))?;
    let write_secs = t_write.elapsed().as_secs_f64();
    let timing = json!({
        "simulate_s": sim_secs,
        "write_s": write_secs,
        "wall_time_s": t_start.elapsed().as_secs_f64(),
        "steps": sol.steps,
    });
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;
    let s = &sol.summary;
    eprintln!(
        "simulated {} s in {} steps ({:.1} ms): {} impacts, peak closing {} m, opening {} m, \
         seat displacement {} m{}, energy balance error {:.1e}; outputs in {}",
        float_token(sol.steps as Real * sol.dt),
        sol.steps,
        sim_secs * 1e3,
        s.impacts,
        bounded(s.peak_joint_closing, 4),
        bounded(s.peak_joint_opening, 4),
        bounded(s.peak_seat_displacement, 4),
        match s.unseating_time {
            Some(t) => format!(" (UNSEATED at {} s)", bounded(t, 3)),
            None => String::new(),
        },
        s.energy_balance_error,
        out.display()
    );
    if let Some(f) = s.peak_contact_force {
        eprintln!(
            "contact law {}: peak contact force {} MN, peak penetration {} mm",
            sim_contact::describe(&setup.problem.model.contact)["law"],
            bounded(f / 1e6, 4),
            bounded(s.peak_penetration * 1e3, 4)
        );
    }
    if sol.status != pounding::sim::SimStatus::Completed {
        // outputs are written (they show where the run went wrong), but the run did not succeed
        eprintln!(
            "error: simulation status {:?} after {} s ({} steps): the results are not trustworthy; \
             see summary.json (lcp_failures) and history.csv in {}",
            sol.status,
            float_token(sol.steps as Real * sol.dt),
            sol.steps,
            out.display()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

const DEG: Real = 180.0 / std::f64::consts::PI;

/// Every file `simulate` writes (single run and batch). A run into a directory first removes all
/// of them, so that no earlier run's plots (e.g. `abutment_gap.png` of a run with abutments) or
/// `timing.json` stay beside the new results. `timing.json` is written last and marks a complete
/// run (as in `pounding study`).
pub(crate) const SIM_OUTPUTS: &[&str] = &[
    "timing.json",
    "history.csv",
    "impacts.csv",
    "summary.json",
    "displacements.png",
    "layout.png",
    "rotations.png",
    "joint_gap.png",
    "abutment_gap.png",
    "impulses.png",
    "energy.png",
    "batch.csv",
    "batch.png",
];

/// Locks the output directory `out` (creating it) and removes the earlier run's [`SIM_OUTPUTS`].
pub(crate) fn lock_and_clear(out: &Path) -> Result<pounding::output::OutputLock> {
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, SIM_OUTPUTS)?;
    Ok(lock)
}

/// Prints a warning to stderr when a compliance law's contact is not resolved by `dt`.
pub(crate) fn warn_time_step(sol: &SimSolution) {
    if let Some(a) = &sol.time_step_advice
        && !a.adequate
    {
        eprintln!(
            "warning: dt = {} s is too coarse for the contact stiffness: the linearised contact \
             lasts {:.3e} s = {:.1} steps; use dt <= {:.2e} s (20 steps per contact)",
            sol.dt, a.contact_duration, a.steps_per_contact, a.max_step
        );
    }
}

pub(crate) fn history_csv(setup: &Setup, sol: &SimSolution) -> String {
    let h = &sol.history;
    let mut s = String::with_capacity(h.t.len() * 400);
    s.push_str(
        "t_s,ag_x_mps2,ag_y_mps2,x1_m,y1_m,theta1_deg,x2_m,y2_m,theta2_deg,\
         vx1_mps,vy1_mps,omega1_degps,vx2_mps,vy2_mps,omega2_degps,",
    );
    for c in ContactCase::ALL {
        s.push_str(&format!("gap_{}_m,", c.name()));
    }
    s.push_str(
        "joint_gap_xplus_m,joint_gap_xminus_m,slip_m,\
         input_energy_J,kinetic_energy_J,strain_energy_J,viscous_dissipation_J,contact_dissipation_J",
    );
    let forces = !h.contact_force.is_empty();
    if forces {
        s.push_str(",contact_force_xplus_N,contact_force_xminus_N");
    }
    // abutment gap columns only when there are abutments (the default's file is unchanged)
    let abut: Vec<usize> = (0..2)
        .filter(|&j| setup.problem.model.abutments[j].is_some())
        .collect();
    for j in &abut {
        s.push_str(&format!(",abutment_gap{}_m", j + 1));
    }
    s.push('\n');
    let mut row: Vec<String> = Vec::with_capacity(32);
    for i in 0..h.t.len() {
        row.clear();
        let t = h.t[i];
        let a = setup.problem.ground.accel(t);
        row.push(float_token(t));
        row.push(float_token(a.x));
        row.push(float_token(a.y));
        for (k, v) in h.q[i].iter().enumerate() {
            row.push(float_token(if k % 3 == 2 { v * DEG } else { *v }));
        }
        for (k, v) in h.u[i].iter().enumerate() {
            row.push(float_token(if k % 3 == 2 { v * DEG } else { *v }));
        }
        row.extend(h.gaps[i].iter().map(|&g| float_token(g)));
        row.extend(h.end_gaps[i].iter().map(|&g| float_token(g)));
        row.push(float_token(h.slip[i]));
        let e = &h.energy[i];
        for v in [e.input, e.kinetic, e.potential, e.viscous, e.contact] {
            row.push(float_token(v));
        }
        if forces {
            row.extend(h.contact_force[i].iter().map(|&f| float_token(f)));
        }
        for &j in &abut {
            row.push(float_token(h.abutment_gaps[i][j]));
        }
        s.push_str(&row.join(","));
        s.push('\n');
    }
    s
}

pub(crate) fn impacts_csv(sol: &SimSolution) -> String {
    let mut s = String::from(
        "impact,t_s,contact,mode,gamma_n_pre_mps,gamma_t_pre_mps,gamma_n_post_mps,gamma_t_post_mps,\
         impulse_n_Ns,impulse_t_Ns,energy_dissipated_J\n",
    );
    for r in &sol.impacts {
        let f = [
            r.gamma_n_pre,
            r.gamma_t_pre,
            r.gamma_n_post,
            r.gamma_t_post,
            r.impulse_n,
            r.impulse_t,
            r.energy_dissipated,
        ]
        .map(float_token)
        .join(",");
        s.push_str(&format!(
            "{},{},{},{},{}\n",
            r.impact,
            float_token(r.time),
            r.contact.name(),
            r.mode.name(),
            f
        ));
    }
    s
}

pub(crate) fn summary_json(setup: &Setup, sol: &SimSolution) -> serde_json::Value {
    let s = &sol.summary;
    let e = &s.final_energy;
    let m = &setup.problem.model;
    let gm = &setup.problem.ground;
    let pga = |r: &Option<Record>, sc: f64| r.as_ref().map_or(0.0, |r| r.pga() * sc.abs());
    let seat: serde_json::Map<String, serde_json::Value> = SEAT_ENDS
        .iter()
        .zip(s.peak_seat_by_end)
        .map(|(k, v)| (k.to_string(), json_float(v)))
        .collect();
    let mut out = json!({
        "impacts": s.impacts,
        "impacting_contacts": s.impacting_contacts,
        "peak_joint_closing_m": json_float(s.peak_joint_closing),
        "peak_joint_opening_m": json_float(s.peak_joint_opening),
        "peak_rotation_deg": [json_float(s.peak_rotation[0] * DEG), json_float(s.peak_rotation[1] * DEG)],
        "peak_slip_m": json_float(s.peak_slip),
        "peak_seat_displacement_m": json_float(s.peak_seat_displacement),
        "peak_seat_displacement_by_end_m": seat,
        "seat_length_m": json_float(m.seat_length),
        "unseated": s.unseated,
        "unseating_time_s": s.unseating_time.map_or(serde_json::Value::Null, json_float),
        "unseated_end": s.unseated_end.map(|i| SEAT_ENDS[i]),
        "max_penetration_m": json_float(s.max_penetration),
        "peak_contact_force_n": s.peak_contact_force.map_or(serde_json::Value::Null, json_float),
        "peak_penetration_m": json_float(s.peak_penetration),
        "energy_balance_error": json_float(s.energy_balance_error),
        "energy_J": {
            "input": json_float(e.input),
            "kinetic": json_float(e.kinetic),
            "strain": json_float(e.potential),
            "viscous_dissipation": json_float(e.viscous),
            "contact_dissipation": json_float(e.contact),
            "max_input": json_float(s.max_input_energy),
        },
        "status": format!("{:?}", sol.status),
        "steps": sol.steps,
        "dt_s": json_float(sol.dt),
        "duration_s": json_float(sol.steps as Real * sol.dt),
        "lcp_solves": sol.lcp_solves,
        "lcp_enumeration_fallbacks": sol.lcp_enumeration_fallbacks,
        "lcp_failures": sol.lcp_failures,
        "natural_periods_s": sol.frequencies.map(|w| w.map(|w| json_float(2.0 * std::f64::consts::PI / w))),
        "rayleigh_a0_a1": sol.rayleigh.map(|(a, b)| [json_float(a), json_float(b)]),
        "ground_motion": {
            "record_y": setup.records[0],
            "record_x": setup.records[1],
            "scale_y": json_float(gm.scale_y),
            "scale_x": json_float(gm.scale_x),
            "incidence_deg": json_float(gm.incidence * DEG),
            "pga_y_mps2": json_float(pga(&gm.along_y, gm.scale_y)),
            "pga_x_mps2": json_float(pga(&gm.along_x, gm.scale_x)),
        },
        "model": {
            "mass_kg": m.masses().map(json_float),
            "gap_m": json_float(m.gap),
            "mu": json_float(m.friction),
            "eps_n": json_float(m.restitution),
            "damping_ratio": json_float(m.damping_ratio),
            "bearings": [m.bearings1.len(), m.bearings2.len()],
        },
    });
    // Keys for straight / skewed decks and abutments only when used (the curved default's
    // summary stays as it was).
    if let Some(sh) = &m.shapes {
        let len = |d: &DeckShape| match d {
            DeckShape::Straight(d) => json_float(d.length),
            DeckShape::Skewed(d) => json_float(d.length),
            DeckShape::Curved(_) => serde_json::Value::Null,
        };
        let skew = |d: &DeckShape| match d {
            DeckShape::Skewed(d) => json_float(d.skew * DEG),
            _ => json_float(0.0),
        };
        out["model"]["shape"] = json!([sh[0].name(), sh[1].name()]);
        out["model"]["length_m"] = json!([len(&sh[0]), len(&sh[1])]);
        out["model"]["skew_deg"] = json!([skew(&sh[0]), skew(&sh[1])]);
    }
    if m.abutments.iter().any(Option::is_some) {
        let mut ab = serde_json::Map::new();
        for (j, a) in m.abutments.iter().enumerate() {
            if let Some(a) = a {
                ab.insert(
                    format!("deck{}", j + 1),
                    json!({
                        "gap_m": json_float(a.gap),
                        "seat_length_m": json_float(a.seat_length),
                        "peak_closing_m": s.peak_abutment_closing[j].map_or(serde_json::Value::Null, json_float),
                    }),
                );
            }
        }
        ab.insert(
            "impacting_contacts".into(),
            json!(s.abutment_impacting_contacts),
        );
        out["abutments"] = serde_json::Value::Object(ab);
    }
    sim_contact::add_compliance_summary(&mut out, m, sol);
    out
}

#[cfg(test)]
mod tests {
    use super::bounded;

    /// The summary line of a diverged run printed a 1e190 m seat displacement with 190+ digits.
    #[test]
    fn bounded_keeps_huge_and_non_finite_values_short() {
        assert_eq!(bounded(0.05493, 4), "0.0549");
        assert_eq!(bounded(-12.5, 3), "-12.500");
        assert_eq!(bounded(1.234567e190, 4), "1.2346e190");
        assert_eq!(bounded(-3e6, 4), "-3.0000e6");
        assert_eq!(bounded(f64::INFINITY, 4), "inf");
        assert_eq!(bounded(f64::NAN, 4), "nan");
        assert!(bounded(-f64::MAX, 4).len() < 16);
    }
}
