//! A campaign store of 10⁶ runs for the peak memory of `pounding fragility --from-store`: the
//! fragility example's viaduct (its two limit states and six seated ends) under 1,000 synthetic
//! pairs at 1,000 stripes of Sa(T1) from 0.02 to 2.018 g, each run's verdicts drawn from a known lognormal fragility
//! (not simulated: the store's rows are what matters here) and written through the campaign's
//! own columns and part writer. Then, in this process, the rows are read back as
//! `--from-store` reads them (checked run by run against the study's plan) and fitted; the time
//! and peak resident memory (`VmHWM`, reset before each step) are printed, and the fitted
//! medians are compared with the ones the rows were drawn from.
//!
//! `cargo bench -p pounding --bench campaign_fit` (set `POUNDING_FIT_STORE=DIR` to keep the store
//! and its files and measure the CLI on it: `/usr/bin/time -v pounding fragility DIR/viaduct.toml
//! --from-store DIR/store --campaign DIR/spec.toml --out DIR/frag`).

use pounding::assessment::run::RunRow;
use pounding::campaign::{Campaign, Store};
use std::path::Path;
use std::time::Instant;

const RECORDS: usize = 1000;
const STRIPES: usize = 1000;
/// The medians \[g\] and dispersion of the fragilities the verdicts are drawn from.
const THETA: [f64; 2] = [0.6, 1.1];
const BETA: f64 = 0.45;

fn peak_mb() -> i64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            let l = s.lines().find(|l| l.starts_with("VmHWM:"))?.to_string();
            l.split_whitespace().nth(1)?.parse::<i64>().ok()
        })
        .map_or(-1, |k| k / 1024)
}

fn reset_peak() {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
}

/// A uniform number in (0, 1) from `i` and `k` (SplitMix64).
fn uniform(i: u64, k: u64) -> f64 {
    let mut z = i.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ k.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
}

/// A standard normal number (Box–Muller).
fn normal(i: u64, k: u64) -> f64 {
    (-2.0 * uniform(i, 2 * k).ln()).sqrt() * (std::f64::consts::TAU * uniform(i, 2 * k + 1)).cos()
}

fn write_inputs(dir: &Path) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fragility");
    let scenario = std::fs::read_to_string(root.join("viaduct.toml")).unwrap();
    std::fs::write(dir.join("viaduct.toml"), scenario).unwrap();
    std::fs::write(
        dir.join("suite.toml"),
        format!("[synth]\ncount = {RECORDS}\nseed = 11\npairs = true\nduration = 4.0\n"),
    )
    .unwrap();
    // 0.02 .. 2.018 g: every record's scale factor stays within the study's 1/100 .. 100
    let levels: Vec<String> = (10..10 + STRIPES)
        .map(|b| format!("{}", b as f64 * 0.002))
        .collect();
    std::fs::write(
        dir.join("spec.toml"),
        format!(
            "[campaign]\nscenario = \"viaduct.toml\"\nrecords = \"suite.toml\"\n\
             levels_g = [{}]\nruns_per_part = {STRIPES}\n",
            levels.join(", ")
        ),
    )
    .unwrap();
}

fn main() {
    let keep = std::env::var_os("POUNDING_FIT_STORE");
    let tmp = tempfile::tempdir().unwrap();
    let dir = keep
        .as_ref()
        .map_or(tmp.path(), |k| Path::new(k))
        .to_path_buf();
    std::fs::create_dir_all(&dir).unwrap();
    write_inputs(&dir);
    let t0 = Instant::now();
    let c = Campaign::load(&dir.join("spec.toml")).unwrap();
    println!(
        "campaign of {} runs planned in {:.1} s",
        c.runs(),
        t0.elapsed().as_secs_f64()
    );
    let t0 = Instant::now();
    let store = dir.join("store");
    let st = Store::open(&store, &c).unwrap();
    let ends = c.seat_ends().len();
    for p in 0..c.parts() {
        let runs: Vec<_> = c
            .part_range(p)
            .map(|i| {
                let s = c.run_spec(i);
                let limits = THETA
                    .iter()
                    .enumerate()
                    .map(|(k, th)| {
                        let ratio = (s.im_g / th).ln() / BETA + normal(i as u64, k as u64);
                        (Some(ratio > 0.0), ratio.exp())
                    })
                    .collect();
                let seats: Vec<f64> = (0..ends)
                    .map(|e| 0.4 * s.im_g * uniform(i as u64, 10 + e as u64))
                    .collect();
                let governing = (0..ends).max_by(|a, b| seats[*a].total_cmp(&seats[*b]));
                let row = RunRow {
                    record: s.entry,
                    stripe: s.stripe,
                    im_g: s.im_g,
                    scale_factor: s.scale_factor,
                    status: "Completed".into(),
                    error: String::new(),
                    warnings: 0,
                    limits,
                    seats,
                    governing_seat: governing,
                };
                (s, row)
            })
            .collect();
        st.write_part(p, &c.columns(&runs)).unwrap();
    }
    println!(
        "wrote {} parts in {:.1} s",
        c.parts(),
        t0.elapsed().as_secs_f64()
    );
    reset_peak();
    let before = peak_mb();
    let t0 = Instant::now();
    let rows = pounding::campaign::read::study_rows(
        &store,
        &c.study,
        &c.plan,
        c.scenario_fingerprint,
        None,
    )
    .unwrap();
    let read_s = t0.elapsed().as_secs_f64();
    let fits = c.study.fit(&c.plan, &rows).unwrap();
    println!(
        "read {} rows in {read_s:.1} s and fitted in {:.1} s: peak resident memory {} MB \
         (before: {before} MB)",
        rows.len(),
        t0.elapsed().as_secs_f64() - read_s,
        peak_mb()
    );
    for (row, theta) in fits.rows.iter().zip(THETA) {
        println!(
            "  {}: fitted (θ, β) = {:?}, drawn from ({theta}, {BETA})",
            row.limit_state,
            row.fit.params()
        );
    }
}
