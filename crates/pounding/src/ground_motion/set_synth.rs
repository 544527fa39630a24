//! `[synth]` in a record-set manifest: the suite of `pounding motion synth` generated in memory
//! instead of read from files.
//!
//! ```toml
//! [synth]
//! count = 20          # records (1..=10000; count × components × samples ≤ 5e7), required
//! seed = 1            # random seed (0..=2^63 − 1), required
//! pairs = true        # two horizontal components per record (default false)
//! dt = 0.01           # sample interval [s] (default 0.01)
//! duration = 20.0     # [s] (default 20)
//! pga_g = 0.3         # scale every component to this PGA [g] (default: unscaled, intensity s0)
//! # model parameters (defaults as `motion synth`): omega_g, zeta_g, omega_f, zeta_f, s0,
//! # epsilon, eta
//! ```
//!
//! The records are exactly those `pounding motion synth --count N --seed S [--pairs] --dt DT
//! --duration D [--pga G]` writes: each component goes through the same `.AT2` text (values in
//! g, shortest round-trip) and the same reader, so a study on `[synth]` gives the same bytes as
//! one on the written files. Ids (`SYN001`, …) and metadata (`index`, `model`, `pga_g`,
//! `pga_y_g`, `seed`) are those of the written `suite.toml`.

use super::{Ctx, MetaValue, SetRecord};
use crate::ground_motion::Record;
use crate::ground_motion::synth::{
    SynthError, SynthParams, at2_text, check_count, check_suite_size, suite as synth_suite,
};
use crate::math::Real;
use crate::toml_schema::line_col;
use serde::Deserialize;
use std::f64::consts::PI;
use toml::Spanned;

/// The `[synth]` table.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SynthSec {
    count: Spanned<i64>,
    seed: Spanned<i64>,
    pairs: Option<Spanned<bool>>,
    dt: Option<Spanned<Real>>,
    duration: Option<Spanned<Real>>,
    pga_g: Option<Spanned<Real>>,
    omega_g: Option<Spanned<Real>>,
    zeta_g: Option<Spanned<Real>>,
    omega_f: Option<Spanned<Real>>,
    zeta_f: Option<Spanned<Real>>,
    s0: Option<Spanned<Real>>,
    epsilon: Option<Spanned<Real>>,
    eta: Option<Spanned<Real>>,
}

/// The value of an optional key and its byte offset in the manifest (the table's when absent).
fn opt(v: &Option<Spanned<Real>>, default: Real, table: usize) -> (Real, usize) {
    v.as_ref()
        .map_or((default, table), |s| (*s.get_ref(), s.span().start))
}

/// The records of a `[synth]` table (`table_at`: the table's byte offset), or the problems
/// (`synth.KEY (FILE:LINE): message`).
pub(super) fn records(
    cx: &Ctx,
    s: &SynthSec,
    table_at: usize,
) -> Result<(Vec<SetRecord>, String), Vec<String>> {
    let at = |key: &str, offset: usize| {
        let (line, _) = line_col(cx.text, offset);
        format!("synth.{key} ({}:{line})", cx.origin)
    };
    let d = SynthParams::default();
    let mut p = d.clone();
    // (key, manifest offset) of every parameter, to name the key of a refused value
    let mut keys: Vec<(&str, usize)> = Vec::new();
    for (key, v, default, field) in [
        ("dt", &s.dt, d.dt, &mut p.dt),
        ("duration", &s.duration, d.duration, &mut p.duration),
        ("omega_g", &s.omega_g, d.omega_g, &mut p.omega_g),
        ("zeta_g", &s.zeta_g, d.zeta_g, &mut p.zeta_g),
        ("omega_f", &s.omega_f, d.omega_f, &mut p.omega_f),
        ("zeta_f", &s.zeta_f, d.zeta_f, &mut p.zeta_f),
        ("s0", &s.s0, d.s0, &mut p.s0),
        ("epsilon", &s.epsilon, d.epsilon, &mut p.epsilon),
        ("eta", &s.eta, d.eta, &mut p.eta),
    ] {
        let (value, offset) = opt(v, default, table_at);
        *field = value;
        keys.push((key, offset));
    }
    if let Some(g) = &s.pga_g {
        p.pga_g = Some(*g.get_ref());
        keys.push(("pga_g", g.span().start));
    }
    let count = *s.count.get_ref();
    let seed = *s.seed.get_ref();
    let mut problems = Vec::new();
    if seed < 0 {
        problems.push(format!(
            "{}: invalid seed = {seed}: must be ≥ 0",
            at("seed", s.seed.span().start)
        ));
    }
    let count_ok = usize::try_from(count)
        .ok()
        .filter(|&c| check_count(c).is_ok());
    if count_ok.is_none() {
        problems.push(format!(
            "{}: invalid count = {count}: must lie in 1..={}",
            at("count", s.count.span().start),
            crate::ground_motion::synth::MAX_COUNT
        ));
    }
    if let Err(SynthError::InvalidParameter {
        name,
        value,
        reason,
    }) = p.check()
    {
        // the library names the CLI flags; the manifest's keys are the field names
        let key = match name.as_str() {
            "--dt" => "dt",
            "--duration" => "duration",
            "--pga" => "pga_g",
            other => other,
        };
        // a default filter frequency above the Nyquist frequency of the table's dt: dt is the
        // value the table sets
        let given = |k: &str| keys.iter().any(|(g, at)| *g == k && *at != table_at);
        let (key, value, reason) = if reason.contains("Nyquist") && !given(key) && given("dt") {
            let w = if key == "omega_g" {
                p.omega_g
            } else {
                p.omega_f
            };
            let why = format!(
                "the default {key} = {value} rad/s lies above the Nyquist frequency π / dt = {} \
                 rad/s of this dt: give dt < π / {key} = {} s, or a smaller {key}",
                crate::output::float_token(PI / p.dt),
                crate::output::float_token(PI / w)
            );
            ("dt", crate::output::float_token(p.dt), why)
        } else {
            (key, value, reason)
        };
        let offset = keys
            .iter()
            .find(|(k, _)| *k == key)
            .map_or(table_at, |k| k.1);
        let reason = reason
            .replace("--duration", "duration")
            .replace("--dt", "dt");
        problems.push(format!(
            "{}: invalid {key} = {value}: {reason}",
            at(key, offset)
        ));
    }
    let pairs = s.pairs.as_ref().is_some_and(|b| *b.get_ref());
    let (Some(count), true) = (count_ok, problems.is_empty()) else {
        return Err(problems);
    };
    // the whole suite is generated in memory: its size is bounded before anything is generated
    if let Err(SynthError::InvalidParameter { reason, .. }) = check_suite_size(&p, count, pairs) {
        let reason = reason
            .replace("--duration", "duration")
            .replace("--dt", "dt");
        return Err(vec![format!(
            "{}: invalid count = {count}: {reason}",
            at("count", s.count.span().start)
        )]);
    }
    let seed = seed as u64;
    let suite = synth_suite(&p, count, seed, pairs).map_err(|e| vec![e.to_string()])?;
    let read = |id: &str, comp: &str, g: &[Real]| -> Result<Record, Vec<String>> {
        let name = format!("{id}_{comp}.AT2 ([synth] of {})", cx.origin);
        Record::from_at2_str(&at2_text(id, comp, &p, seed, g), &name).map_err(|e| {
            // cannot happen: the text is written by at2_text; reported, never a panic
            vec![format!("{}: {e}", at("count", s.count.span().start))]
        })
    };
    let peak = |g: &[Real]| g.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
    let mut out = Vec::with_capacity(suite.len());
    for (i, r) in suite.iter().enumerate() {
        let mut meta = vec![
            ("index".to_string(), MetaValue::Integer(i as i64)),
            (
                "model".to_string(),
                MetaValue::Text(crate::ground_motion::set::SYNTHETIC_MODEL.into()),
            ),
            ("pga_g".to_string(), MetaValue::Number(peak(&r.x))),
            ("seed".to_string(), MetaValue::Integer(seed as i64)),
        ];
        if let Some(y) = &r.y {
            meta.push(("pga_y_g".to_string(), MetaValue::Number(peak(y))));
        }
        meta.sort_by(|a, b| a.0.cmp(&b.0));
        out.push(SetRecord {
            id: r.id.clone(),
            x: read(&r.id, "x", &r.x)?,
            y: r.y.as_deref().map(|y| read(&r.id, "y", y)).transpose()?,
            meta,
            supports: Vec::new(),
        });
    }
    let source = format!(
        "[synth] of {}: as pounding motion synth --count {count} --seed {seed}{} --dt {} \
         --duration {}{}",
        cx.origin,
        if pairs { " --pairs" } else { "" },
        crate::output::float_token(p.dt),
        crate::output::float_token(p.duration),
        p.pga_g
            .map(|g| format!(" --pga {}", crate::output::float_token(g)))
            .unwrap_or_default()
    );
    Ok((out, source))
}
