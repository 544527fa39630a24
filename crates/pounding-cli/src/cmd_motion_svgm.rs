//! `pounding motion svgm`: spatially variable ground motions at several supports
//! ([`pounding::ground_motion::svgm`]); writes `real_NNNN.csv`, `SVGM.txt` and `manifest.toml`
//! (last).

use anyhow::{Context, Result, bail};
use pounding::ground_motion::svgm::{
    Coherency, Conditioned, Generator, SvgmParams, check_count, default_ids, write_set,
};
use pounding::ground_motion::synth::SynthParams;
use pounding::ground_motion::{ReadOptions, Record};
use pounding::output::float_token;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The coherency model (`--coherency`).
#[derive(Clone, Copy, clap::ValueEnum)]
enum CoherencyArg {
    /// Harichandran & Vanmarcke (1986), parameters --hv-* (default: SMART-1 Event 20).
    HarichandranVanmarcke,
    /// Luco & Wong (1986), parameter --lw-alpha-vs.
    LucoWong,
    /// Fully coherent: wave passage only.
    None,
    /// Independent supports (for testing; not a physical model).
    Independent,
}

/// The power spectral density model (`--psd`).
#[derive(Clone, Copy, clap::ValueEnum)]
enum PsdArg {
    /// Kanai-Tajimi with the Clough-Penzien high-pass filter (two-sided), --wg --zg --wf --zf --s0.
    CloughPenzien,
}

/// Arguments of `pounding motion svgm`.
#[derive(clap::Args)]
pub struct SvgmArgs {
    /// Support positions along the wave's direction in metres, strictly increasing (e.g. 0,30,60,90).
    #[arg(
        long,
        value_name = "X,...",
        value_delimiter = ',',
        allow_hyphen_values = true,
        required_unless_present = "bridge"
    )]
    supports: Vec<f64>,
    /// Support ids, one per position ([A-Za-z0-9_-]+; default start,joint1,...,end).
    #[arg(long, value_name = "ID,...", value_delimiter = ',')]
    ids: Option<Vec<String>>,
    /// A bridge scenario ([[segment]] tables): its support lines' ids and their distances from
    /// the start line toward the end one, instead of --supports and --ids.
    #[arg(long, value_name = "SCENARIO", conflicts_with_all = ["supports", "ids"])]
    bridge: Option<std::path::PathBuf>,
    /// Lagged coherency model.
    #[arg(long, value_enum, default_value = "harichandran-vanmarcke")]
    coherency: CoherencyArg,
    /// Harichandran-Vanmarcke A, in (0, 1] (default 0.736).
    #[arg(long, value_name = "A", allow_hyphen_values = true)]
    hv_a: Option<f64>,
    /// Harichandran-Vanmarcke alpha > 0 (default 0.147).
    #[arg(long, value_name = "ALPHA", allow_hyphen_values = true)]
    hv_alpha: Option<f64>,
    /// Harichandran-Vanmarcke k > 0 in metres (default 5210).
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    hv_k: Option<f64>,
    /// Harichandran-Vanmarcke omega0 > 0 in rad/s (default 6.85).
    #[arg(long, value_name = "RAD_S", allow_hyphen_values = true)]
    hv_omega0: Option<f64>,
    /// Harichandran-Vanmarcke b > 0 (default 2.78).
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    hv_b: Option<f64>,
    /// Luco-Wong alpha/v_s > 0 in s/m (default 2.5e-4).
    #[arg(long, value_name = "S_PER_M", allow_hyphen_values = true)]
    lw_alpha_vs: Option<f64>,
    /// Apparent wave velocity in m/s (> 0), or inf for no wave passage.
    #[arg(long, value_name = "M_S", allow_hyphen_values = true)]
    v_app: f64,
    /// Power spectral density model (default clough-penzien).
    #[arg(long, value_enum)]
    psd: Option<PsdArg>,
    /// Kanai-Tajimi soil frequency omega_g in rad/s (default 15.6).
    #[arg(long, value_name = "RAD_S", allow_hyphen_values = true)]
    wg: Option<f64>,
    /// Kanai-Tajimi soil damping zeta_g, in (0, 1) (default 0.6).
    #[arg(long, value_name = "ZETA", allow_hyphen_values = true)]
    zg: Option<f64>,
    /// Clough-Penzien filter frequency omega_f in rad/s (default 1.5).
    #[arg(long, value_name = "RAD_S", allow_hyphen_values = true)]
    wf: Option<f64>,
    /// Clough-Penzien filter damping zeta_f, in (0, 1) (default 0.6).
    #[arg(long, value_name = "ZETA", allow_hyphen_values = true)]
    zf: Option<f64>,
    /// White-noise intensity S0 in m^2/s^3, two-sided (default 0.01; not with --pga).
    #[arg(long, value_name = "M2_S3", allow_hyphen_values = true)]
    s0: Option<f64>,
    /// Scale each realisation by one factor so that the mean of the supports' PGAs is G (in g).
    #[arg(long, value_name = "G", allow_hyphen_values = true)]
    pga: Option<f64>,
    /// Stationary samples: no envelope, no baseline correction.
    #[arg(long)]
    stationary: bool,
    /// Duration in seconds (default 20; with --condition the record's).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    duration: Option<f64>,
    /// Sample interval in seconds (default 0.01; with --condition the record's).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    dt: Option<f64>,
    /// Number of realisations (1 to 10000).
    #[arg(long, value_name = "N")]
    count: usize,
    /// Random seed, 0 to 9223372036854775807 (2^63 - 1, the largest integer manifest.toml can
    /// hold): the same seed gives the same files (any thread count).
    #[arg(long, value_name = "S")]
    seed: u64,
    /// Output directory (created if needed).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Condition on this recorded motion (a record file the tool reads, or builtin:ELC180) at
    /// the support --at: the PSD, dt and duration are the record's.
    #[arg(long, value_name = "FILE")]
    condition: Option<PathBuf>,
    /// The support of the --condition record (one of the ids).
    #[arg(long, value_name = "ID")]
    at: Option<String>,
    /// Length of the stationary windows of --condition in seconds (default 4).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    window: Option<f64>,
}

/// The coherency of the flags; a parameter flag of another model is refused.
fn coherency(a: &SvgmArgs) -> Result<Coherency> {
    let hv = [
        ("--hv-a", a.hv_a),
        ("--hv-alpha", a.hv_alpha),
        ("--hv-k", a.hv_k),
        ("--hv-omega0", a.hv_omega0),
        ("--hv-b", a.hv_b),
    ];
    let lw = [("--lw-alpha-vs", a.lw_alpha_vs)];
    let (own, name): (&[(&str, Option<f64>)], &str) = match a.coherency {
        CoherencyArg::HarichandranVanmarcke => (&hv, "harichandran-vanmarcke"),
        CoherencyArg::LucoWong => (&lw, "luco-wong"),
        CoherencyArg::None => (&[], "none"),
        CoherencyArg::Independent => (&[], "independent"),
    };
    for (flag, v) in hv.iter().chain(&lw) {
        if v.is_some() && !own.iter().any(|(f, _)| f == flag) {
            bail!("{flag} is a parameter of another coherency model than --coherency {name}");
        }
    }
    Ok(
        match (a.coherency, Coherency::HV_SMART1, Coherency::LW_DEFAULT) {
            (
                CoherencyArg::HarichandranVanmarcke,
                Coherency::HarichandranVanmarcke {
                    a: a0,
                    alpha,
                    k,
                    omega0,
                    b,
                },
                _,
            ) => Coherency::HarichandranVanmarcke {
                a: a.hv_a.unwrap_or(a0),
                alpha: a.hv_alpha.unwrap_or(alpha),
                k: a.hv_k.unwrap_or(k),
                omega0: a.hv_omega0.unwrap_or(omega0),
                b: a.hv_b.unwrap_or(b),
            },
            (CoherencyArg::LucoWong, _, Coherency::LucoWong { alpha_over_vs }) => {
                Coherency::LucoWong {
                    alpha_over_vs: a.lw_alpha_vs.unwrap_or(alpha_over_vs),
                }
            }
            (CoherencyArg::None, ..) => Coherency::Full,
            _ => Coherency::Independent,
        },
    )
}

/// Runs `pounding motion svgm`.
pub fn svgm(a: SvgmArgs) -> Result<ExitCode> {
    let d = SynthParams::default();
    let conditioned = a.condition.is_some();
    if !conditioned {
        for (flag, given) in [("--at", a.at.is_some()), ("--window", a.window.is_some())] {
            if given {
                bail!("{flag} applies to --condition only");
            }
        }
    } else {
        for (flag, given) in [
            ("--psd", a.psd.is_some()),
            ("--wg", a.wg.is_some()),
            ("--zg", a.zg.is_some()),
            ("--wf", a.wf.is_some()),
            ("--zf", a.zf.is_some()),
            ("--s0", a.s0.is_some()),
            ("--pga", a.pga.is_some()),
            ("--stationary", a.stationary),
            ("--dt", a.dt.is_some()),
            ("--duration", a.duration.is_some()),
        ] {
            if given {
                bail!(
                    "{flag} does not apply with --condition (the PSD, amplitude, dt and duration \
                     are the record's)"
                );
            }
        }
    }
    if a.s0.is_some() && a.pga.is_some() {
        bail!("--s0 has no effect with --pga (each realisation is scaled to the PGA): give one");
    }
    let (ids, positions) = match &a.bridge {
        None => (
            a.ids
                .clone()
                .unwrap_or_else(|| default_ids(a.supports.len())),
            a.supports.clone(),
        ),
        Some(path) => {
            let setup = pounding::sim::scenario::Scenario::load(path)?
                .build_bridge()
                .with_context(|| format!("--bridge {}", path.display()))?;
            setup.problem.model.support_distances().into_iter().unzip()
        }
    };
    let mut p = SvgmParams {
        ids,
        positions,
        coherency: coherency(&a)?,
        v_app: a.v_app,
        psd: SynthParams {
            omega_g: a.wg.unwrap_or(d.omega_g),
            zeta_g: a.zg.unwrap_or(d.zeta_g),
            omega_f: a.wf.unwrap_or(d.omega_f),
            zeta_f: a.zf.unwrap_or(d.zeta_f),
            s0: a.s0.unwrap_or(d.s0),
            dt: a.dt.unwrap_or(d.dt),
            duration: a.duration.unwrap_or(d.duration),
            pga_g: a.pga,
            ..d
        },
        stationary: a.stationary,
    };
    // every flag is checked (and the coherency factored) before the directory is created
    check_count(a.count)?;
    pounding::ground_motion::svgm::check_seed(a.seed)?;
    let ids = match &a.condition {
        None => {
            let g = Generator::new(&p)?;
            let source = p.source(a.count, a.seed);
            let _lock = pounding::output::lock_output_dir(&a.out)?;
            write_set(&a.out, &g, a.count, a.seed, &source)
        }
        Some(file) => {
            let (g, source) = conditioned_model(&a, file, &mut p)?;
            let _lock = pounding::output::lock_output_dir(&a.out)?;
            write_set(&a.out, &g, a.count, a.seed, &source)
        }
    }
    .with_context(|| format!("writing the set to {}", a.out.display()))?;
    eprintln!(
        "{} realisation{} at {} support{} ({}), {} s at dt {} s{}, written to {}: manifest.toml, \
         SVGM.txt. Synthetic motions are for trying multi-support analyses; real assessments \
         need recorded motions.",
        ids.len(),
        if ids.len() == 1 { "" } else { "s" },
        p.ids.len(),
        if p.ids.len() == 1 { "" } else { "s" },
        p.ids.join(", "),
        float_token(p.psd.duration),
        float_token(p.psd.dt),
        if conditioned {
            " conditioned on the record"
        } else {
            ""
        },
        a.out.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// The model conditioned on `--condition FILE --at ID` (the record's dt and duration go to `p`)
/// and its `source`.
fn conditioned_model(
    a: &SvgmArgs,
    file: &Path,
    p: &mut SvgmParams,
) -> Result<(Conditioned, String)> {
    let Some(at_id) = &a.at else {
        bail!("--condition needs --at ID, the support of the record");
    };
    let at = p.ids.iter().position(|id| id == at_id).with_context(|| {
        format!(
            "--at {at_id}: not one of the support ids {}",
            p.ids.join(",")
        )
    })?;
    let record = Record::open_with(file, &ReadOptions::default())
        .with_context(|| format!("--condition {}", file.display()))?;
    let Some(dt) = record.dt() else {
        bail!(
            "--condition {}: the record is not uniformly sampled (conditional simulation needs \
             a constant sample interval)",
            file.display()
        );
    };
    if record.times()[0] != 0.0 {
        bail!(
            "--condition {}: the record starts at t = {} s, not 0",
            file.display(),
            float_token(record.times()[0])
        );
    }
    let n = record.values().len();
    p.psd.dt = dt;
    p.psd.duration = (n - 1) as f64 * dt;
    let c = Conditioned::new(p, at, record.values(), a.window.unwrap_or(4.0))
        .with_context(|| format!("--condition {}", file.display()))?;
    let source = c.source(&file.display().to_string(), a.count, a.seed);
    Ok((c, source))
}
