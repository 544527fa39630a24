//! `pounding spectrum`: elastic response spectra of records and RotD50/RotD100 of horizontal
//! pairs ([`pounding::spectrum`]); writes `spectrum.csv` and `spectrum.png`.

use anyhow::{Context, Result, anyhow};
use plotters::prelude::*;
use pounding::ground_motion::Record;
use pounding::math::Real;
use pounding::output::{float_token, write_atomic};
use pounding::spectrum::{Curve, SpectrumRequest, spectrum_csv};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Files `pounding spectrum` writes (cleared from `--out` before a run).
const OUTPUTS: &[&str] = &["spectrum.csv", "spectrum.png"];

/// Arguments of `pounding spectrum`.
#[derive(clap::Args)]
pub struct Args {
    /// Records (PEER .AT2, CSV `t, a`, columns `t a`, one column with --record-dt, or
    /// builtin:ELC180 / builtin:ELC270): each gives component `x`.
    pub records: Vec<String>,
    /// A horizontal pair X Y: components `x`, `y`, `rotd50` and `rotd100` (repeatable).
    #[arg(long, num_args = 2, value_names = ["X", "Y"], action = clap::ArgAction::Append)]
    pub pair: Vec<String>,
    /// Damping ratio, a fraction of critical (0.05 = 5 %).
    #[arg(long, default_value_t = 0.05, allow_hyphen_values = true, value_parser = finite)]
    pub damping: f64,
    /// Periods in seconds, comma separated (default: 100 from 0.01 s to 10 s, even in log T).
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "T1,T2,...",
        allow_hyphen_values = true,
        value_parser = finite
    )]
    pub periods: Vec<f64>,
    /// Units of text records: g or m/s2 (an .AT2 header names its own).
    #[arg(long, value_name = "g|m/s2", default_value = "g")]
    pub csv_units: String,
    /// Sample interval (seconds) of one-column records.
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    pub record_dt: Option<f64>,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "out/spectrum")]
    pub out: PathBuf,
}

/// A number as given on the command line, refused (quoting it) if it does not read as a
/// finite double (`1e400` would read as `inf`).
fn finite(s: &str) -> std::result::Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(format!("{s:?} is not a finite number")),
        Err(e) => Err(format!("{s:?}: {e}")),
    }
}

/// Prints how each record was read, one line per record and component (`x`; a pair's `x` and
/// `y`), as `simulate` does, with its warning for an implausible PGA.
fn print_records(singles: &[(String, Record)], pairs: &[(String, Record, Record)]) {
    use crate::cmd_simulate::sim_records::print_component;
    use pounding::ground_motion::ComponentInfo;
    for (_, r) in singles {
        print_component(&ComponentInfo::of("x", r));
    }
    for (_, x, y) in pairs {
        print_component(&ComponentInfo::of("x", x));
        print_component(&ComponentInfo::of("y", y));
    }
}

/// Runs `pounding spectrum`.
pub fn run(args: Args) -> Result<ExitCode> {
    let request = SpectrumRequest {
        records: args.records.clone(),
        pairs: args
            .pair
            .chunks(2)
            .map(|p| (p[0].clone(), p[1].clone()))
            .collect(),
        damping: args.damping,
        periods: args.periods.clone(),
        csv_units: args.csv_units.clone(),
        record_dt: args.record_dt,
    };
    // read everything first: bad input writes nothing
    let inputs = request.read()?;
    print_records(&inputs.singles, &inputs.pairs);
    let curves = inputs.curves().map_err(|e| anyhow!("{e}"))?;
    let periods = &inputs.periods;
    let out = &args.out;
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, OUTPUTS)?;
    let p = out.join("spectrum.csv");
    write_atomic(&p, spectrum_csv(&curves).as_bytes())
        .with_context(|| format!("cannot write {}", p.display()))?;
    plot(out, &curves, args.damping).map_err(|e| anyhow!("plotting: {e}"))?;
    eprintln!(
        "{} spectr{} at {} period{} (damping {}); wrote {} and spectrum.png",
        curves.len(),
        if curves.len() == 1 { "um" } else { "a" },
        periods.len(),
        if periods.len() == 1 { "" } else { "s" },
        float_token(args.damping),
        p.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// `spectrum.png`: pseudo-spectral acceleration against period (log axis), one curve per
/// record and component.
fn plot(out: &Path, curves: &[Curve], damping: Real) -> crate::plot_style::DrawResult {
    use crate::plot_style::{
        BLUE, FAMILY, GREEN, ORANGE, PURPLE, RED, e, register, save_white_png,
    };
    register();
    let palette = [BLUE, RED, GREEN, ORANGE, PURPLE, RGBColor(120, 120, 120)];
    let pts = curves.iter().flat_map(|c| c.ordinates.iter());
    let (t_lo, t_hi, a_hi) = pts.fold(
        (Real::INFINITY, 0.0, 0.0),
        |(a, b, c): (Real, Real, Real), o| (a.min(o.period), b.max(o.period), c.max(o.psa_g)),
    );
    let (t_lo, t_hi) = if t_hi > t_lo {
        (t_lo, t_hi)
    } else {
        (t_lo * 0.5, t_lo * 2.0)
    };
    let a_hi = if a_hi > 0.0 && a_hi.is_finite() {
        a_hi * 1.1
    } else {
        1.0
    };
    save_white_png(out, "spectrum.png", (1200, 800), |root| {
        let mut chart = ChartBuilder::on(root)
            .caption(
                format!(
                    "Pseudo-spectral acceleration, damping {} %",
                    float_token(damping * 100.0)
                ),
                (FAMILY, 26),
            )
            .margin(15)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d((t_lo..t_hi).log_scale(), 0.0..a_hi)
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc("period T [s]")
            .y_desc("PSA [g]")
            .label_style((FAMILY, 16))
            .draw()
            .map_err(e)?;
        for (k, c) in curves.iter().enumerate() {
            let col = palette[k % palette.len()];
            chart
                .draw_series(LineSeries::new(
                    c.ordinates.iter().map(|o| (o.period, o.psa_g)),
                    col.stroke_width(2),
                ))
                .map_err(e)?
                .label(format!("{} {}", c.record, c.component))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], col.stroke_width(2)));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FAMILY, 16))
            .draw()
            .map_err(e)?;
        Ok(())
    })
}
