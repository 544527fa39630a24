//! `pounding check`: the code check of a scenario's seats and joint gaps
//! ([`pounding::assessment::check`]); prints the table and, with `--out`, writes `check.csv`,
//! `check_gaps.csv` and `check.json`.

use anyhow::{Context, Result};
use pounding::assessment::check_write::{
    CHECK_OUTPUTS, check_csv, check_gaps_csv, check_json, check_text,
};
use pounding::output::write_atomic;
use pounding::sim::scenario::Scenario;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `pounding check`.
#[derive(clap::Args)]
pub struct Args {
    /// The scenario (a bridge of [[segment]]s or a two-deck file), its inputs in [code_check].
    pub scenario: PathBuf,
    /// Output directory for check.csv, check_gaps.csv and check.json (none: print only).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// Runs `pounding check`: exit 0 when the check ran, whatever its verdict.
pub fn run(args: Args) -> Result<ExitCode> {
    let sc = Scenario::load(&args.scenario)?;
    // a typo in [fragility] is refused here too, as every command refuses it
    pounding::assessment::check_tables(&sc, None)?;
    let report = pounding::assessment::check_scenario(&sc)?;
    let origin = sc.origin();
    // the output directory first: an unusable --out is an error before anything is printed
    let lock = match &args.out {
        Some(out) => Some(pounding::output::lock_output_dir(out)?),
        None => None,
    };
    print!("{}", check_text(&report, origin));
    if let (Some(out), Some(lock)) = (&args.out, &lock) {
        pounding::output::remove_previous_outputs(lock, CHECK_OUTPUTS)?;
        let files = [
            ("check.csv", check_csv(&report)),
            ("check_gaps.csv", check_gaps_csv(&report)),
            ("check.json", check_json(&report, origin)),
        ];
        for (name, text) in files {
            let p = out.join(name);
            write_atomic(&p, text.as_bytes())
                .with_context(|| format!("cannot write {}", p.display()))?;
        }
        println!(
            "Wrote check.csv, check_gaps.csv, check.json in {}",
            out.display()
        );
    }
    if report.failing_ends() + report.failing_gaps() > 0 {
        println!(
            "The check ran (exit 0); FAIL above means the model's seats or gaps are shorter than \
             a code requires."
        );
    }
    Ok(ExitCode::SUCCESS)
}
