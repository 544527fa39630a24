//! The files of a synthetic suite: one PEER-style `.AT2` per component (`UNITS OF G`, so every
//! record reader of the tool reads it without flags), the manifest `suite.toml` and
//! `SYNTHETIC.txt`.

use super::{SynthError, SynthParams, SynthRecord, suite};
use crate::math::Real;
use crate::output::float_token as f;
use std::path::{Path, PathBuf};

/// A PEER NGA-style `.AT2` text of the component `comp` of record `id`: four header lines (the
/// third `ACCELERATION TIME SERIES IN UNITS OF G`, the fourth `NPTS= n, DT= dt SEC`), then the
/// values in g, five a line, as shortest round-trip numbers (so the reader gets them exactly).
pub fn at2_text(id: &str, comp: &str, p: &SynthParams, seed: u64, g: &[Real]) -> String {
    let mut s = format!(
        "SYNTHETIC ACCELEROGRAM (pounding motion synth) - NOT A RECORDED MOTION\n\
         {id} component {comp}, Kanai-Tajimi-Clough-Penzien, Saragoni-Hart envelope, seed {seed}\n\
         ACCELERATION TIME SERIES IN UNITS OF G\n\
         NPTS= {}, DT= {} SEC\n",
        g.len(),
        f(p.dt)
    );
    for chunk in g.chunks(5) {
        let line: Vec<String> = chunk.iter().map(|&x| f(x)).collect();
        s.push_str(&line.join("  "));
        s.push('\n');
    }
    s
}

/// A TOML basic string (quoted, escaped).
fn quoted(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

fn peak(g: &[Real]) -> Real {
    g.iter().fold(0.0, |m: Real, x| m.max(x.abs()))
}

/// The record-set manifest `suite.toml` (`[set]` name and source; one `[[record]]` per record
/// with `id`, `x`, `y` (pairs), and `[record.meta]`: `model`, `seed`, `index`, `pga_g` (of x),
/// `pga_y_g` (pairs)).
pub fn suite_toml(records: &[SynthRecord], seed: u64, source: &str) -> String {
    let mut s = format!("[set]\nname = \"synthetic\"\nsource = {}\n", quoted(source));
    for (i, r) in records.iter().enumerate() {
        s.push_str(&format!(
            "\n[[record]]\nid = {}\nx = {}\n",
            quoted(&r.id),
            quoted(&format!("{}_x.AT2", r.id))
        ));
        if r.y.is_some() {
            s.push_str(&format!("y = {}\n", quoted(&format!("{}_y.AT2", r.id))));
        }
        s.push_str(&format!(
            "[record.meta]\nmodel = {}\nseed = {seed}\nindex = {i}\npga_g = {}\n",
            quoted(crate::ground_motion::set::SYNTHETIC_MODEL),
            f(peak(&r.x))
        ));
        if let Some(y) = &r.y {
            s.push_str(&format!("pga_y_g = {}\n", f(peak(y))));
        }
    }
    s
}

/// `SYNTHETIC.txt`: what the files are, the model and its parameters, and the warning.
pub fn readme_text(p: &SynthParams, count: usize, seed: u64, pairs: bool, source: &str) -> String {
    let scaling = match p.pga_g {
        Some(g) => format!("every component scaled to PGA = {} g exactly", f(g)),
        None => format!(
            "not scaled: white-noise intensity S0 = {} m^2/s^3 (two-sided)",
            f(p.s0)
        ),
    };
    format!(
        "SYNTHETIC GROUND MOTIONS - NOT RECORDED EARTHQUAKES\n\n\
         Written by: {source}\n\
         {count} record(s){}, seed {seed}, dt = {} s, duration = {} s, {scaling}.\n\n\
         Model: stationary Kanai-Tajimi filtered white noise (omega_g = {} rad/s, zeta_g = {}) through\n\
         the Clough-Penzien high-pass filter (omega_f = {} rad/s, zeta_f = {}), sampled exactly in\n\
         distribution from its stationary state, times a Saragoni-Hart (1974) envelope (epsilon = {},\n\
         eta = {} at t_n = duration; Boore 2003 parameterisation); a linear baseline makes the final\n\
         velocity and displacement zero. Defaults: firm soil (Kanai 1957 / Tajimi 1960 as quoted by\n\
         Clough & Penzien; Der Kiureghian & Neuenhofer 1992). See docs/guide/motion.md.\n\n\
         These records are for trying the workflow (spectra, record sets, stripes, fragility).\n\
         They have no magnitude, distance, site or source physics, no non-stationary frequency\n\
         content, and no near-fault pulses. Real assessments need real recorded ground motions,\n\
         selected and scaled for the site's hazard.\n\n\
         Files: SYNnnn_x.AT2 (and SYNnnn_y.AT2 with --pairs: an independent second horizontal\n\
         component) in g, PEER AT2 layout; suite.toml lists them (the record-set manifest).\n",
        if pairs { " as horizontal pairs" } else { "" },
        f(p.dt),
        f(p.duration),
        f(p.omega_g),
        f(p.zeta_g),
        f(p.omega_f),
        f(p.zeta_f),
        f(p.epsilon),
        f(p.eta),
    )
}

/// The command that writes a suite, as `suite.toml` (`[set] source`) and `SYNTHETIC.txt` name
/// it: `pounding motion synth --count N --seed S --dt DT --duration D [--pga G] [--pairs]`
/// (the same text whichever front end writes the suite, so the files are the same bytes).
pub fn synth_source(p: &SynthParams, count: usize, seed: u64, pairs: bool) -> String {
    let mut source = format!(
        "pounding motion synth --count {count} --seed {seed} --dt {} --duration {}",
        f(p.dt),
        f(p.duration)
    );
    if let Some(g) = p.pga_g {
        source.push_str(&format!(" --pga {}", f(g)));
    }
    if pairs {
        source.push_str(" --pairs");
    }
    source
}

/// Errors of writing a suite: bad parameters, or an I/O error naming the path.
#[derive(Debug, thiserror::Error)]
pub enum WriteSuiteError {
    /// Bad parameters (nothing written).
    #[error(transparent)]
    Param(#[from] SynthError),
    /// A file or directory could not be written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// Removes the records of an earlier, larger suite from `dir`: files named as the generator
/// names them (`<id>_x.AT2`, `<id>_y.AT2`) that the new suite does not write and that begin with
/// the generator's own header line (a user's file is never touched). Left behind, they sat next
/// to a manifest that does not list them and were read by `--records DIR`.
fn remove_stale_records(dir: &Path, records: &[SynthRecord]) -> std::io::Result<()> {
    use std::io::BufRead;
    let keep: std::collections::BTreeSet<String> = records
        .iter()
        .flat_map(|r| [format!("{}_x.AT2", r.id), format!("{}_y.AT2", r.id)])
        .collect();
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
            continue;
        };
        if keep.contains(name) || !(name.ends_with("_x.AT2") || name.ends_with("_y.AT2")) {
            continue;
        }
        let Ok(file) = std::fs::File::open(&path) else {
            continue;
        };
        let mut first = String::new();
        let _ = std::io::BufReader::new(file).read_line(&mut first);
        if first.starts_with("SYNTHETIC ACCELEROGRAM (pounding motion synth)") {
            std::fs::remove_file(&path)?;
        }
    }
    Ok(())
}

/// Generates the suite and writes it to `dir` (created if needed): the `.AT2` files, then
/// `SYNTHETIC.txt`, then `suite.toml` last (each atomically: a manifest present means every
/// file it names is complete); the records of an earlier suite there are removed first. Parameters are checked before anything is written. Returns the
/// records.
pub fn write_suite(
    dir: &Path,
    p: &SynthParams,
    count: usize,
    seed: u64,
    pairs: bool,
    source: &str,
) -> Result<Vec<SynthRecord>, WriteSuiteError> {
    let records = suite(p, count, seed, pairs)?;
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| WriteSuiteError::Io { path, source }
    };
    std::fs::create_dir_all(dir).map_err(io(dir))?;
    let write = |name: String, text: String| {
        let path = dir.join(name);
        crate::output::write_atomic(&path, text.as_bytes()).map_err(io(&path))
    };
    // the previous manifest goes first: no manifest while the files are being replaced
    let manifest = dir.join("suite.toml");
    if manifest.exists() {
        std::fs::remove_file(&manifest).map_err(io(&manifest))?;
    }
    remove_stale_records(dir, &records).map_err(io(dir))?;
    for r in &records {
        write(
            format!("{}_x.AT2", r.id),
            at2_text(&r.id, "x", p, seed, &r.x),
        )?;
        if let Some(y) = &r.y {
            write(format!("{}_y.AT2", r.id), at2_text(&r.id, "y", p, seed, y))?;
        }
    }
    write(
        "SYNTHETIC.txt".into(),
        readme_text(p, count, seed, pairs, source),
    )?;
    write("suite.toml".into(), suite_toml(&records, seed, source))?;
    Ok(records)
}
