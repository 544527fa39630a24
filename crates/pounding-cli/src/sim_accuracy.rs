//! What `simulate --error-estimate` / `--tol` prints: the step of the answer, the governing
//! quantities with their estimated errors, and what could not be estimated
//! ([`pounding::sim::accuracy`]).

use pounding::output::{bounded, float_token};
use pounding::sim::accuracy::{AccuracyRun, Trust};
use std::path::Path;
use std::process::ExitCode;

/// Prints the estimate; `Some(exit code 1)` when the tolerance was not met or a refined run did
/// not complete (the answer's files are written, but no trusted estimate backs them).
pub fn print(run: &AccuracyRun, out: &Path) -> Option<ExitCode> {
    let dt = float_token(run.dts[run.chosen]);
    if let Some(f) = &run.failure {
        eprintln!(
            "error: accuracy: the run at dt = {} s ended with status {:?}: no error estimate \
             (the files in {} are the run at dt = {dt} s)",
            float_token(f.dt),
            f.status,
            out.display()
        );
        return Some(ExitCode::from(1));
    }
    let steps: Vec<String> = run.dts[run.chosen..]
        .iter()
        .take(3)
        .map(|d| float_token(*d))
        .collect();
    eprintln!(
        "accuracy: estimated from runs at dt = {} s (accuracy.csv):",
        steps.join(", ")
    );
    for e in run.governing() {
        let v = bounded(e.values[0], 6);
        let what = match (e.trust, e.error, e.relative_error) {
            (Trust::NotConverging, _, _) => format!(
                "NOT CONVERGING (spread {} {} over the three runs: no error estimate)",
                bounded(e.spread(), 6),
                e.quantity.unit
            ),
            (trust, Some(err), Some(rel)) => format!(
                "± {} {} ({}){}",
                bounded(err, 6),
                e.quantity.unit,
                percent(rel),
                match (trust, e.order) {
                    (Trust::Erratic, _) => ", erratic: from the spread of the three runs".into(),
                    (_, Some(p)) => format!(", observed order {p:.2}"),
                    _ => String::new(),
                }
            ),
            _ => String::new(),
        };
        eprintln!("  {} = {v} {}  {what}", e.quantity.name, e.quantity.unit);
    }
    let untrusted = run.untrusted();
    if !untrusted.is_empty() {
        eprintln!(
            "warning: accuracy: {} changed by more than 5 % of their value without converging as \
             dt was halved: the response is sensitive to the step (a chaotic sequence of impacts, \
             or dt far too coarse); read their values as one sample, not as an answer",
            untrusted.join(", ")
        );
    }
    match (run.settings.tol, run.met) {
        (Some(tol), Some(true)) => {
            eprintln!(
                "accuracy: dt = {dt} s meets the tolerance {} on every governing quantity{}",
                percent(tol),
                run.worst()
                    .map(|(n, r)| format!(" (largest: {n}, {})", percent(r)))
                    .unwrap_or_default()
            );
            None
        }
        (Some(tol), _) => {
            eprintln!(
                "error: accuracy: the tolerance {} was not met after {} halvings of dt (finest \
                 run dt = {} s); the files in {} are the run at dt = {dt} s. Raise \
                 --max-refinements, or read accuracy.csv",
                percent(tol),
                run.settings.max_refinements,
                float_token(*run.dts.last().expect("runs made")),
                out.display()
            );
            Some(ExitCode::from(1))
        }
        _ => None,
    }
}

/// `0.35 %`.
fn percent(x: f64) -> String {
    format!("{} %", bounded(100.0 * x, 3))
}
