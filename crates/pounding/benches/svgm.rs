//! Spatially variable ground motions (speed target: 200 realisations × 4 supports × 40 s at
//! dt = 0.01 s in under 1 s on 2 cores).
//!
//! * `svgm_200_x_4_supports_40s` — [`realisations`] with the default Harichandran–Vanmarcke
//!   coherency, `v_app = 250 m/s`, supports at 0, 30, 60, 90 m, envelope and PGA scaling: the
//!   factoring of the coherency matrices (8192 frequencies) and 200 × 10 FFTs of 4096 points.

use pounding::ground_motion::svgm::{Coherency, SvgmParams, default_ids, realisations};
use pounding::ground_motion::synth::SynthParams;
use std::hint::black_box;

fn main() {
    divan::main();
}

#[divan::bench(sample_count = 10)]
fn svgm_200_x_4_supports_40s(bencher: divan::Bencher) {
    let p = SvgmParams {
        positions: vec![0.0, 30.0, 60.0, 90.0],
        ids: default_ids(4),
        coherency: Coherency::HV_SMART1,
        v_app: 250.0,
        psd: SynthParams {
            duration: 40.0,
            dt: 0.01,
            pga_g: Some(0.3),
            ..SynthParams::default()
        },
        stationary: false,
    };
    bencher.bench(|| realisations(black_box(&p), 200, 1).unwrap());
}
