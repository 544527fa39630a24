//! `[time]`: the settings of a run, checked against the ground motion's duration and the memory
//! limit.

use crate::ground_motion::GroundMotion;
use crate::math::Real;
use crate::output::float_token;
use crate::sim::SimSettings;
use crate::sim::scenario::Scenario;
use crate::sim::scenario::error::ScenarioError;
use crate::sim::scenario::model_keys::{sim_error, time};

/// `[time]`: the settings of a run under `ground`, checked against its duration and the memory
/// limit; `model_checks` runs once the settings themselves are valid (the order of the errors
/// a file with several mistakes reports).
pub(in crate::sim::scenario) fn build_settings(
    sc: &Scenario,
    ground: &GroundMotion,
    records: &[String; 2],
    // the memory estimate's bridge (segments, and piers counted as segments; its bearings)
    size: crate::sim::options::RunSize,
    model_checks: impl FnOnce() -> Result<(), ScenarioError>,
) -> Result<SimSettings, ScenarioError> {
    let src = &sc.src;
    let t = &sc.raw.time;
    if t.history_every < 1 {
        return Err(src.invalid(
            format!("invalid history_every = {}: must be >= 1", t.history_every),
            time("history_every"),
        ));
    }
    let settings = SimSettings {
        dt: t.dt,
        duration: t.duration,
        history_stride: t.history_every as usize,
        projection: t.projection,
        ..SimSettings::default()
    };
    settings.validate().map_err(|e| sim_error(src, e))?;
    model_checks()?;
    if !sc.batch && settings.duration.is_none() && ground.end_time() <= 0.0 {
        return Err(src.key_error(
            format!(
                "no ground motion samples after t = 0: set {}",
                src.at(time("duration"))
            ),
            &[time("duration")],
        ));
    }
    // The duration of the run (batch runs without `duration` use each record's length, checked
    // there).
    let duration = settings.duration.or((!sc.batch).then(|| ground.end_time()));
    if let Some(d) = duration {
        settings.step_count(d).map_err(|e| {
            let mut at = vec![src.at(time("dt"))];
            if src.is_set(time("duration")) {
                at.push(src.at(time("duration")));
            }
            ScenarioError::Invalid {
                message: e.to_string(),
                at,
                note: String::new(),
            }
        })?;
        use crate::sim::options::{MAX_RUN_MEMORY_BYTES, min_history_stride, run_memory_bytes};
        let n = settings.step_count(d).unwrap_or(usize::MAX);
        let bytes = run_memory_bytes(n, settings.history_stride, size);
        if !sc.batch && bytes > MAX_RUN_MEMORY_BYTES {
            let gib = |b: u64| b as Real / (1u64 << 30) as Real;
            let advice = match min_history_stride(n, size) {
                Some(s) => format!("set history_every >= {s} (or shorten the run)"),
                None => "shorten the run or use a larger dt".into(),
            };
            return Err(ScenarioError::Invalid {
                message: format!(
                    "run too large: {n} steps with history_every = {} need an estimated {:.1} GiB \
                     of memory, more than the limit {:.0} GiB; {advice}",
                    settings.history_stride,
                    gib(bytes),
                    gib(MAX_RUN_MEMORY_BYTES)
                ),
                at: vec![
                    src.at(time("history_every")),
                    src.at(time("duration")),
                    src.at(time("dt")),
                ],
                note: String::new(),
            });
        }
        if settings.dt > d {
            return Err(dt_beyond_duration(sc, &settings, d, records));
        }
    }
    Ok(settings)
}

/// The error of a step `dt` longer than the run `duration`. Without `[time] duration` the
/// duration is the ground motion's: the record is blamed (its name and length), and `dt` is
/// named as set (its line, or "the built-in default dt").
fn dt_beyond_duration(
    sc: &Scenario,
    settings: &SimSettings,
    duration: Real,
    records: &[String; 2],
) -> ScenarioError {
    let src = &sc.src;
    let dt_at = src.at(time("dt"));
    if settings.duration.is_some() {
        return ScenarioError::Invalid {
            message: format!(
                "invalid dt = {}: must not exceed the duration {} s",
                float_token(settings.dt),
                float_token(duration)
            ),
            at: vec![dt_at, src.at(time("duration"))],
            note: String::new(),
        };
    }
    let names: Vec<&str> = records
        .iter()
        .map(String::as_str)
        .filter(|r| !r.trim().eq_ignore_ascii_case("none"))
        .collect();
    let dt_by = match src.builtin && dt_at.flag.is_none() {
        true => "the built-in default dt".to_string(),
        false => format!("set by {dt_at}"),
    };
    ScenarioError::Key {
        message: format!(
            "the ground motion lasts only {} s (the last sample of record {}), less than one time \
             step dt = {} s ({dt_by}): check the record's sample interval, or set [time] duration",
            float_token(duration),
            names.join(" and "),
            float_token(settings.dt)
        ),
        at: vec![dt_at],
    }
}
