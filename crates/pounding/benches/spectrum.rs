//! Response spectra (issue 13 speed target: the spectrum of a 50 s record at 100 periods < 5 ms).
//!
//! * `spectrum_50s_100_periods` — one component, 50 s at dt = 0.01 s (5,001 samples, a seeded
//!   synthetic record), 5 % damping, the 100 default periods (0.01–10 s), with the continuous-time
//!   peak and the free vibration after the record, as `pounding spectrum` computes it;
//! * `rotd_pair_50s_100_periods` — RotD50/RotD100 of a pair of such records (180 angles).

use pounding::ground_motion::synth::{SynthParams, component_g};
use pounding::ground_motion::{G0, Record};
use pounding::spectrum::{default_periods, rotd, spectrum};
use std::hint::black_box;

fn main() {
    divan::main();
}

fn record(comp: u64) -> Record {
    let p = SynthParams {
        duration: 50.0,
        pga_g: Some(0.3),
        ..SynthParams::default()
    };
    let a = component_g(&p, 1, 0, comp).iter().map(|g| g * G0).collect();
    Record::uniform("synthetic 50 s", p.dt, a).expect("valid record")
}

#[divan::bench(sample_count = 20)]
fn spectrum_50s_100_periods(bencher: divan::Bencher) {
    let r = record(0);
    let periods = default_periods();
    assert_eq!(periods.len(), 100);
    assert_eq!(r.values().len(), 5001);
    bencher.bench(|| spectrum(black_box(&r), 0.05, &periods).unwrap());
}

#[divan::bench(sample_count = 5)]
fn rotd_pair_50s_100_periods(bencher: divan::Bencher) {
    let (x, y) = (record(0), record(1));
    let periods = default_periods();
    bencher.bench(|| rotd(black_box(&x), &y, 0.05, &periods).unwrap());
}
