//! The files of a set of spatially variable motions: one CSV per realisation
//! (`real_0001.csv`: `t,<id1>,<id2>,…`, accelerations in m/s²), `SVGM.txt`, and the manifest
//! `manifest.toml` (written last).

use super::{Coherency, Conditioned, Generator, SvgmError, SvgmParams, check_count, check_seed};
use crate::math::Real;
use crate::output::{float_token as f, push_float_token};
use std::path::{Path, PathBuf};

/// The id of realisation `r` (0-based) of `count`: `real_0001`, … (4 digits, more when `count`
/// has more).
pub fn record_id(r: usize, count: usize) -> String {
    let width = count.to_string().len().max(4);
    format!("real_{:0width$}", r + 1)
}

/// The CSV text of one realisation: the header `t,<id1>,…`, then one row per sample,
/// `t = k dt` (rounded to 12 significant digits: `0.07`, not `0.07000000000000001`) and the
/// accelerations \[m/s²\], shortest round-trip numbers.
pub fn csv_text(ids: &[String], dt: Real, supports: &[Vec<Real>]) -> String {
    let n = supports.first().map_or(0, Vec::len);
    let mut s = String::with_capacity(n * (supports.len() + 1) * 22 + 64);
    s.push('t');
    for id in ids {
        s.push(',');
        s.push_str(id);
    }
    s.push('\n');
    for k in 0..n {
        let t = k as Real * dt;
        push_float_token(&mut s, format!("{t:.11e}").parse().unwrap_or(t));
        for a in supports {
            s.push(',');
            push_float_token(&mut s, a[k]);
        }
        s.push('\n');
    }
    s
}

/// A TOML basic string (quoted, escaped).
fn quoted(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// The manifest `manifest.toml`: `[set]` with `name = "svgm"` and `source`, then per
/// realisation `[[record]]` with `id`, `supports` (the CSV file) and `[record.meta]` `seed`
/// and, when given, the realisation's [`MotionStats`] (`pgd_m`, `differential_m`).
pub fn manifest_toml(
    ids: &[String],
    seed: u64,
    source: &str,
    stats: Option<&[MotionStats]>,
) -> String {
    let mut s = format!("[set]\nname = \"svgm\"\nsource = {}\n", quoted(source));
    for (r, id) in ids.iter().enumerate() {
        s.push_str(&format!(
            "\n[[record]]\nid = {}\nsupports = {}\n\n[record.meta]\nseed = {seed}\n",
            quoted(id),
            quoted(&format!("{id}.csv"))
        ));
        if let Some(m) = stats.and_then(|st| st.get(r)) {
            s.push_str(&format!(
                "pgd_m = {}\ndifferential_m = {}\n",
                toml_float(m.pgd),
                toml_float(m.differential)
            ));
        }
    }
    s
}

/// A finite float as TOML writes it (always with a decimal point or an exponent).
fn toml_float(x: Real) -> String {
    toml::Value::Float(x).to_string()
}

/// What a realisation does to the ground, from its samples exactly (piecewise-linear
/// accelerations from rest, no baseline correction beyond the generator's): the largest peak
/// ground displacement over the supports and the largest displacement of one support relative
/// to another, `max_t (max_j u_j(t) − min_j u_j(t))`, over the samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionStats {
    /// Largest `|u_j(t)|` \[m\].
    pub pgd: Real,
    /// Largest differential displacement between two supports \[m\].
    pub differential: Real,
}

impl MotionStats {
    /// The statistics of one realisation `a[support][sample]` at sample interval `dt`.
    pub fn of(a: &[Vec<Real>], dt: Real) -> Self {
        let n = a.iter().map(Vec::len).min().unwrap_or(0);
        let mut v = vec![0.0; a.len()];
        let mut u = vec![0.0; a.len()];
        let (mut pgd, mut differential): (Real, Real) = (0.0, 0.0);
        for k in 1..n {
            for (j, x) in a.iter().enumerate() {
                let (a0, a1) = (x[k - 1], x[k]);
                u[j] += v[j] * dt + (2.0 * a0 + a1) * dt * dt / 6.0;
                v[j] += (a0 + a1) * dt / 2.0;
                pgd = pgd.max(u[j].abs());
            }
            let hi = u.iter().copied().fold(Real::NEG_INFINITY, Real::max);
            let lo = u.iter().copied().fold(Real::INFINITY, Real::min);
            differential = differential.max(hi - lo);
        }
        MotionStats { pgd, differential }
    }
}

/// `SVGM.txt`: what the files are, the model and its parameters.
pub fn readme_text(p: &SvgmParams, count: usize, seed: u64, source: &str) -> String {
    let q = &p.psd;
    let supports: Vec<String> = p
        .ids
        .iter()
        .zip(&p.positions)
        .map(|(id, x)| format!("{id} at {} m", f(*x)))
        .collect();
    let coherency = match p.coherency {
        Coherency::HarichandranVanmarcke {
            a,
            alpha,
            k,
            omega0,
            b,
        } => format!(
            "Harichandran-Vanmarcke (1986): A = {}, alpha = {}, k = {} m, omega0 = {} rad/s, b = {}",
            f(a),
            f(alpha),
            f(k),
            f(omega0),
            f(b)
        ),
        Coherency::LucoWong { alpha_over_vs } => format!(
            "Luco-Wong (1986): |gamma| = exp(-(alpha omega xi / v_s)^2), alpha/v_s = {} s/m",
            f(alpha_over_vs)
        ),
        Coherency::Full => "none: fully coherent (wave passage only)".into(),
        Coherency::Independent => "independent supports (a test case, not a physical model)".into(),
    };
    let wave = if p.v_app.is_infinite() {
        "none (v_app = inf)".to_string()
    } else {
        format!(
            "apparent velocity v_app = {} m/s toward increasing position",
            f(p.v_app)
        )
    };
    let shape = if p.stationary {
        "stationary samples (no envelope, no baseline correction)".to_string()
    } else {
        format!(
            "Saragoni-Hart envelope (epsilon = {}, eta = {} at t_n = duration) delayed by the \
             travel time from the first support, then a linear baseline per support (final \
             velocity and displacement zero)",
            f(q.epsilon),
            f(q.eta)
        )
    };
    let scaling = match q.pga_g {
        Some(g) => format!(
            "one factor per realisation, common to all supports, so that the mean of the \
             supports' peak |a| is {} g",
            f(g)
        ),
        None => "unscaled (intensity S0)".into(),
    };
    format!(
        "SPATIALLY VARIABLE SYNTHETIC GROUND MOTIONS - NOT RECORDED EARTHQUAKES\n\n\
         Written by: {source}\n\
         {count} realisation(s), seed {seed}, dt = {} s, duration = {} s.\n\
         Supports: {}.\n\n\
         Model: spectral representation (Deodatis 1996) of a Gaussian process with the two-sided\n\
         Clough-Penzien PSD (omega_g = {} rad/s, zeta_g = {}, omega_f = {} rad/s, zeta_f = {},\n\
         S0 = {} m^2/s^3) at every support (no site effects), lagged coherency {coherency},\n\
         wave passage: {wave}.\n\
         Shape: {shape}.\n\
         Scaling: {scaling}.\n\n\
         Files: real_NNNN.csv, header t,<support ids>, accelerations in m/s^2 at t = k dt;\n\
         manifest.toml lists them. See docs/guide/motion.md.\n",
        f(q.dt),
        f(q.duration),
        supports.join(", "),
        f(q.omega_g),
        f(q.zeta_g),
        f(q.omega_f),
        f(q.zeta_f),
        f(q.s0),
    )
}

/// A model that generates realisations: the unconditional [`Generator`] or the
/// [`Conditioned`] one.
pub trait Realiser: Sync {
    /// The parameters (checked).
    fn params(&self) -> &SvgmParams;
    /// The accelerations \[m/s²\] of realisation `r` of `seed`, per support.
    fn realisation(&self, seed: u64, r: usize) -> Vec<Vec<Real>>;
    /// The text of `SVGM.txt`.
    fn readme(&self, count: usize, seed: u64, source: &str) -> String;
}

impl Realiser for Generator {
    fn params(&self) -> &SvgmParams {
        Generator::params(self)
    }
    fn realisation(&self, seed: u64, r: usize) -> Vec<Vec<Real>> {
        Generator::realisation(self, seed, r)
    }
    fn readme(&self, count: usize, seed: u64, source: &str) -> String {
        readme_text(self.params(), count, seed, source)
    }
}

impl Realiser for Conditioned {
    fn params(&self) -> &SvgmParams {
        Conditioned::params(self)
    }
    fn realisation(&self, seed: u64, r: usize) -> Vec<Vec<Real>> {
        Conditioned::realisation(self, seed, r)
    }
    fn readme(&self, count: usize, seed: u64, source: &str) -> String {
        let p = self.params();
        let supports: Vec<String> = p
            .ids
            .iter()
            .zip(&p.positions)
            .map(|(id, x)| format!("{id} at {} m", f(*x)))
            .collect();
        format!(
            "SPATIALLY VARIABLE GROUND MOTIONS CONDITIONED ON A RECORD - SIMULATED, EXCEPT AT {}\n\n\
             Written by: {source}\n\
             {count} realisation(s), seed {seed}, dt = {} s, duration = {} s (the record's).\n\
             Supports: {}.\n\n\
             Model: conditional simulation on the record at support {} in overlapping stationary\n\
             windows of {} s (Konakli & Der Kiureghian 2012): per window the PSD is the record's\n\
             smoothed periodogram, the conditional mean is the record filtered by the lagged\n\
             coherency {} and delayed by the wave passage ({}), and the residual is Gaussian\n\
             with the conditional cross-spectral density. Same PSD at every support (no site\n\
             effects); no envelope, baseline correction or scaling.\n\n\
             Files: real_NNNN.csv, header t,<support ids>, accelerations in m/s^2 at t = k dt;\n\
             manifest.toml lists them. See docs/guide/motion.md.\n",
            p.ids[self.at()],
            f(p.psd.dt),
            f(p.psd.duration),
            supports.join(", "),
            p.ids[self.at()],
            f(self.window()),
            p.coherency.flags().trim_start_matches("--coherency "),
            if p.v_app.is_infinite() {
                "none, v_app = inf".to_string()
            } else {
                format!("v_app = {} m/s", f(p.v_app))
            }
        )
    }
}

/// Errors of writing a set: bad parameters or numerical trouble (nothing written), or an I/O
/// error naming the path.
#[derive(Debug, thiserror::Error)]
pub enum WriteSetError {
    /// Bad parameters or a coherency matrix that cannot be factored (nothing written).
    #[error(transparent)]
    Model(#[from] SvgmError),
    /// A file or directory could not be written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// Values (samples × supports) generated in parallel and then written, at most (a chunk has 1 to
/// 32 realisations): bounds the memory.
const CHUNK_VALUES: usize = 2 * super::MAX_VALUES;

/// The CSV files an earlier set in `dir` wrote (listed by its `manifest.toml`, if that is an
/// `svgm` manifest) that the new set `keep` does not write: left behind, they would sit next to
/// a manifest that does not list them. A file the generator did not write is never touched.
fn stale_files(dir: &Path, keep: &[String]) -> Vec<PathBuf> {
    let Ok(text) = std::fs::read_to_string(dir.join("manifest.toml")) else {
        return vec![];
    };
    let Ok(table) = text.parse::<toml::Table>() else {
        return vec![];
    };
    if table
        .get("set")
        .and_then(|s| s.get("name"))
        .and_then(|n| n.as_str())
        != Some("svgm")
    {
        return vec![];
    }
    let records = table.get("record").and_then(|r| r.as_array());
    records
        .into_iter()
        .flatten()
        .filter_map(|r| r.get("supports").and_then(|f| f.as_str()))
        .filter(|name| {
            // only the generator's own names, inside dir
            let id = name.strip_suffix(".csv").unwrap_or("");
            id.strip_prefix("real_")
                .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
                && !keep.iter().any(|k| k == id)
        })
        .map(|name| dir.join(name))
        .collect()
}

/// Writes `count` realisations of the checked model `g` ([`Generator`] or [`Conditioned`]) to `dir` (created if needed): an
/// earlier `manifest.toml` there is removed first (with the CSV files of an earlier `svgm` set
/// that the new one does not write), then the CSV files, `SVGM.txt`, and `manifest.toml` last
/// (each atomically: a manifest present means every file it names is complete). The count is
/// checked before anything is written (the parameters were checked by [`Generator::new`]).
/// Returns the ids of the realisations.
pub fn write_set(
    dir: &Path,
    g: &impl Realiser,
    count: usize,
    seed: u64,
    source: &str,
) -> Result<Vec<String>, WriteSetError> {
    use rayon::prelude::*;
    check_count(count)?;
    check_seed(seed)?;
    let p = g.params();
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| WriteSetError::Io { path, source }
    };
    std::fs::create_dir_all(dir).map_err(io(dir))?;
    let write = |name: &str, text: &str| {
        let path = dir.join(name);
        crate::output::write_atomic(&path, text.as_bytes()).map_err(io(&path))
    };
    let ids: Vec<String> = (0..count).map(|r| record_id(r, count)).collect();
    let stale = stale_files(dir, &ids);
    let manifest = dir.join("manifest.toml");
    if manifest.exists() {
        std::fs::remove_file(&manifest).map_err(io(&manifest))?;
    }
    for path in stale {
        if path.is_file() {
            std::fs::remove_file(&path).map_err(io(&path))?;
        }
    }
    let chunk = (CHUNK_VALUES / (p.samples() * p.positions.len())).clamp(1, 32);
    let mut stats = Vec::with_capacity(count);
    for start in (0..count).step_by(chunk) {
        let texts: Vec<(String, MotionStats)> = (start..(start + chunk).min(count))
            .into_par_iter()
            .map(|r| {
                let a = g.realisation(seed, r);
                (
                    csv_text(&p.ids, p.psd.dt, &a),
                    MotionStats::of(&a, p.psd.dt),
                )
            })
            .collect();
        for ((text, st), id) in texts.iter().zip(&ids[start..]) {
            write(&format!("{id}.csv"), text)?;
            stats.push(*st);
        }
    }
    write("SVGM.txt", &g.readme(count, seed, source))?;
    write(
        "manifest.toml",
        &manifest_toml(&ids, seed, source, Some(&stats)),
    )?;
    Ok(ids)
}
