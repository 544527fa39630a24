//! `pounding check`: the code check of a scenario's seats and joint gaps
//! ([`pounding::assessment::check`]); prints the table and, with `--out`, writes `check.csv`,
//! `check_gaps.csv` and `check.json`. With `--from-store`, also the stored runs' seat demands
//! against the provided and the codes' seats (`check_store.csv`,
//! [`pounding::campaign::from_store`]).

use anyhow::{Context, Result};
use pounding::assessment::check_write::{
    CHECK_OUTPUTS, check_csv, check_gaps_csv, check_json, check_text,
};
use pounding::output::write_atomic;
use pounding::sim::scenario::Scenario;
use std::path::PathBuf;
use std::process::ExitCode;

/// The file of `--from-store`.
const STORE_OUTPUT: &str = "check_store.csv";

/// Arguments of `pounding check`.
#[derive(clap::Args)]
pub struct Args {
    /// The scenario (a bridge of [[segment]]s or a two-deck file), its inputs in [code_check].
    pub scenario: PathBuf,
    /// Output directory for check.csv, check_gaps.csv and check.json (none: print only).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// A campaign store (`pounding campaign run --out DIR`, or its runs.parquet) of this
    /// scenario: how many stored runs exceeded the provided seat and each code's seat, per
    /// stripe (check_store.csv).
    #[arg(long, value_name = "DIR")]
    pub from_store: Option<PathBuf>,
    /// With --from-store: the campaign variant (needs --campaign: its bridge decides the seats).
    #[arg(long, requires = "campaign")]
    pub variant: Option<String>,
    /// With --from-store: the campaign spec that made the store (its record set, stripes and
    /// variants); the scenario must be the spec's.
    #[arg(long, value_name = "SPEC", requires = "from_store")]
    pub campaign: Option<PathBuf>,
}

/// The stored runs against the seats of the (variant's) bridge: the check report of that
/// bridge, `check_store.csv` and its printed summary.
fn from_store(
    args: &Args,
    sc: &Scenario,
    store: &std::path::Path,
) -> Result<(pounding::assessment::CheckReport, String, String)> {
    use pounding::campaign::from_store as fs;
    let s = fs::store_study(
        sc.clone(),
        &args.scenario,
        None,
        store,
        args.campaign.as_deref(),
        args.variant.as_deref(),
    )?;
    let plan = match s.plan {
        Some(p) => p,
        None => s.study.plan()?,
    };
    let rows = pounding::campaign::read::study_rows(
        store,
        &s.study,
        &plan,
        s.scenario_fingerprint,
        s.variant.as_deref(),
    )?;
    let input = pounding::assessment::CodeCheckInput::from_scenario(sc.text(), sc.origin())?;
    let model = &s.study.setup.problem.model;
    let report = pounding::assessment::check_bridge(model, &input, sc.origin())?;
    let ex = fs::seat_exceedance(&report, &model.seat_end_names(), &rows, plan.values())?;
    let column = match plan.stripes {
        pounding::assessment::Stripes::Levels(_) => "level_g",
        pounding::assessment::Stripes::Scales(_) => "scale",
    };
    let variant = s.variant.unwrap_or_else(|| "base".into());
    Ok((
        report,
        fs::seat_exceedance_csv(&ex, column),
        fs::seat_exceedance_text(&ex, &variant, column),
    ))
}

/// Runs `pounding check`: exit 0 when the check ran, whatever its verdict.
pub fn run(args: Args) -> Result<ExitCode> {
    let sc = Scenario::load(&args.scenario)?;
    // a typo in [fragility] is refused here too, as every command refuses it
    pounding::assessment::check_tables(&sc, None)?;
    let (report, stored) = match &args.from_store {
        Some(store) => {
            let (r, csv, text) = from_store(&args, &sc, store)?;
            (r, Some((csv, text)))
        }
        None => (pounding::assessment::check_scenario(&sc)?, None),
    };
    let origin = sc.origin();
    // the output directory first: an unusable --out is an error before anything is printed
    let lock = match &args.out {
        Some(out) => Some(pounding::output::lock_output_dir(out)?),
        None => None,
    };
    print!("{}", check_text(&report, origin));
    if let Some((_, text)) = &stored {
        print!("\n{text}");
    }
    if let (Some(out), Some(lock)) = (&args.out, &lock) {
        pounding::output::remove_previous_outputs(lock, CHECK_OUTPUTS)?;
        pounding::output::remove_previous_outputs(lock, &[STORE_OUTPUT])?;
        let mut files = vec![
            ("check.csv", check_csv(&report)),
            ("check_gaps.csv", check_gaps_csv(&report)),
            ("check.json", check_json(&report, origin)),
        ];
        if let Some((csv, _)) = stored {
            files.push((STORE_OUTPUT, csv));
        }
        for (name, text) in &files {
            let p = out.join(name);
            write_atomic(&p, text.as_bytes())
                .with_context(|| format!("cannot write {}", p.display()))?;
        }
        let names: Vec<&str> = files.iter().map(|(n, _)| *n).collect();
        println!("Wrote {} in {}", names.join(", "), out.display());
    }
    if report.failing_ends() + report.failing_gaps() > 0 {
        println!(
            "The check ran (exit 0); FAIL above means the model's seats or gaps are shorter than \
             a code requires."
        );
    }
    Ok(ExitCode::SUCCESS)
}
