//! Spatially variable ground motions (`pounding::ground_motion::svgm`) against the model they
//! claim, by an estimator written here (an FFT independent of the library's):
//!
//! * **Estimator.** Each stationary realisation and support: a Hann window over the 4001
//!   samples, zero-padded to 4096, FFT (`rustfft`); cross-periodograms `X_j* X_k` averaged over
//!   the realisations and then over 11 neighbouring bins (±0.12 Hz), scaled to the two-sided
//!   PSD (`Δt / (2π Σw²)`). From them: the PSD of each support, the lagged coherency
//!   `|P_jk| / √(P_jj P_kk)` and the phase `arg P_jk` of each pair, on 0.5–10 Hz.
//! * **Bias and tolerances.** The PSD is compared with the target averaged over the same 11 bins
//!   (the smoothing's bias removed; the Hann window's leakage is negligible where the PSD is
//!   smooth): with 200 realisations × 11 correlated bins the relative scatter is about 3–4 %, so
//!   every frequency within 15 % and the mean relative error within 3 %. The coherency estimate
//!   is biased upward where the true value is small (≈ 0.03 for a true 0, from the finite number
//!   of averages) and downward by the phase's variation across the 11 bins (< 0.01 here): every
//!   frequency within 0.08 absolute, the mean absolute error within 0.02. The phase is checked
//!   where the target coherency is at least 0.3 (elsewhere it is noise): within 0.35 rad at every
//!   frequency, 0.08 rad on average, against `−ω (x_k − x_j)/v_app`. Measured (seed 11): PSD
//!   worst 8.4 %, mean 1.7 %; coherency worst 0.042, mean 0.008; phase worst 0.16 rad, mean
//!   0.02 rad. The wrong generators: Luco–Wong coherency worst 0.19, mean 0.088; `v_app = inf`
//!   phase mean 1.5 rad; independent coherency mean 0.71.
//! * **The test can fail**: the same estimator rejects a generator with the wrong coherency model
//!   (Luco–Wong for a Harichandran–Vanmarcke target), without wave passage (`v_app = inf` for
//!   250 m/s) and with independent supports.

use pounding::ground_motion::svgm::{
    Coherency, Fft, Generator, SvgmParams, csv_text, default_ids, realisations,
};
use pounding::ground_motion::synth::SynthParams;
use rustfft::FftPlanner;
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

const REALISATIONS: usize = 200;
const NFFT: usize = 4096;
const HALF: usize = 5;

fn params(coherency: Coherency, v_app: f64) -> SvgmParams {
    SvgmParams {
        positions: vec![0.0, 30.0, 60.0, 90.0],
        ids: default_ids(4),
        coherency,
        v_app,
        psd: SynthParams {
            duration: 40.0,
            dt: 0.01,
            ..SynthParams::default()
        },
        stationary: true,
    }
}

/// Smoothed, averaged cross-periodograms `P[j][k][bin]` (two-sided PSD scaling).
struct Estimate {
    p: Vec<Vec<Vec<Complex64>>>,
    dt: f64,
}

fn estimate(p: &SvgmParams, seed: u64) -> Estimate {
    let g = Generator::new(p).unwrap();
    let s = p.positions.len();
    let fft = FftPlanner::new().plan_fft_forward(NFFT);
    let n = p.samples();
    let w: Vec<f64> = (0..n)
        .map(|k| 0.5 - 0.5 * (2.0 * PI * k as f64 / (n - 1) as f64).cos())
        .collect();
    let sw2: f64 = w.iter().map(|x| x * x).sum();
    let mut acc = vec![vec![vec![Complex64::new(0.0, 0.0); NFFT / 2]; s]; s];
    for r in 0..REALISATIONS {
        let a = g.realisation(seed, r);
        let xs: Vec<Vec<Complex64>> = a
            .iter()
            .map(|a| {
                let mut b: Vec<Complex64> = (0..NFFT)
                    .map(|k| Complex64::new(if k < n { a[k] * w[k] } else { 0.0 }, 0.0))
                    .collect();
                fft.process(&mut b);
                b
            })
            .collect();
        for j in 0..s {
            for k in j..s {
                for b in 0..NFFT / 2 {
                    acc[j][k][b] += xs[j][b].conj() * xs[k][b];
                }
            }
        }
    }
    let scale = p.psd.dt / (2.0 * PI * sw2 * REALISATIONS as f64);
    let smooth = |v: &Vec<Complex64>| -> Vec<Complex64> {
        (0..v.len())
            .map(|b| {
                let (lo, hi) = (b.saturating_sub(HALF), (b + HALF).min(v.len() - 1));
                v[lo..=hi].iter().sum::<Complex64>() * scale / (hi - lo + 1) as f64
            })
            .collect()
    };
    Estimate {
        p: acc
            .iter()
            .map(|row| row.iter().map(smooth).collect())
            .collect(),
        dt: p.psd.dt,
    }
}

/// The estimate's worst and mean errors against the target model `t`.
#[derive(Debug, Default)]
struct Verdict {
    psd_max_rel: f64,
    psd_mean_rel: f64,
    coh_max_abs: f64,
    coh_mean_abs: f64,
    phase_max: f64,
    phase_mean: f64,
}

impl Verdict {
    fn psd_ok(&self) -> bool {
        self.psd_max_rel < 0.15 && self.psd_mean_rel < 0.03
    }
    fn coherency_ok(&self) -> bool {
        self.coh_max_abs < 0.08 && self.coh_mean_abs < 0.02
    }
    fn phase_ok(&self) -> bool {
        self.phase_max < 0.35 && self.phase_mean < 0.08
    }
}

fn judge(e: &Estimate, t: &SvgmParams) -> Verdict {
    let s = t.positions.len();
    let dw = 2.0 * PI / (NFFT as f64 * e.dt);
    let bins: Vec<usize> = (0..NFFT / 2)
        .filter(|&b| (0.5..=10.0).contains(&(b as f64 * dw / (2.0 * PI))))
        .collect();
    let mut v = Verdict::default();
    let (mut np, mut nc, mut nph) = (0.0, 0.0, 0.0);
    for &b in &bins {
        let w = b as f64 * dw;
        let target_psd = (b - HALF..=b + HALF)
            .map(|q| t.psd.psd(q as f64 * dw))
            .sum::<f64>()
            / (2 * HALF + 1) as f64;
        for j in 0..s {
            let rel = (e.p[j][j][b].re / target_psd - 1.0).abs();
            v.psd_max_rel = v.psd_max_rel.max(rel);
            v.psd_mean_rel += rel;
            np += 1.0;
            for k in j + 1..s {
                let xi = t.positions[k] - t.positions[j];
                let coh = e.p[j][k][b].norm() / (e.p[j][j][b].re * e.p[k][k][b].re).sqrt();
                let target = t.coherency.value(xi, w);
                let err = (coh - target).abs();
                v.coh_max_abs = v.coh_max_abs.max(err);
                v.coh_mean_abs += err;
                nc += 1.0;
                if target >= 0.3 {
                    let want = -w * xi / t.v_app;
                    let d = (e.p[j][k][b].arg() - want + PI).rem_euclid(2.0 * PI) - PI;
                    v.phase_max = v.phase_max.max(d.abs());
                    v.phase_mean += d.abs();
                    nph += 1.0;
                }
            }
        }
    }
    v.psd_mean_rel /= np;
    v.coh_mean_abs /= nc;
    v.phase_mean /= nph;
    v
}

#[test]
fn the_estimated_spectra_coherency_and_phase_match_the_model_and_reject_wrong_ones() {
    let target = params(Coherency::HV_SMART1, 250.0);
    let good = judge(&estimate(&target, 11), &target);
    eprintln!("target model: {good:?}");
    assert!(
        good.psd_ok() && good.coherency_ok() && good.phase_ok(),
        "{good:?}"
    );
    // the same estimator rejects wrong generators
    let wrong_model = judge(
        &estimate(&params(Coherency::LW_DEFAULT, 250.0), 11),
        &target,
    );
    eprintln!("Luco-Wong for Harichandran-Vanmarcke: {wrong_model:?}");
    assert!(!wrong_model.coherency_ok(), "{wrong_model:?}");
    let no_passage = judge(
        &estimate(&params(Coherency::HV_SMART1, f64::INFINITY), 11),
        &target,
    );
    eprintln!("v_app = inf for 250 m/s: {no_passage:?}");
    assert!(!no_passage.phase_ok(), "{no_passage:?}");
    let independent = judge(
        &estimate(&params(Coherency::Independent, 250.0), 11),
        &target,
    );
    eprintln!("independent supports: {independent:?}");
    assert!(!independent.coherency_ok(), "{independent:?}");
}

#[test]
fn the_library_fft_equals_a_direct_dft() {
    let n = 64;
    let x: Vec<Complex64> = (0..n)
        .map(|k| Complex64::new((0.3 * k as f64).sin() + 0.1 * k as f64, (k * k % 7) as f64))
        .collect();
    for inverse in [false, true] {
        let mut y = x.clone();
        Fft::new(n).process(&mut y, inverse);
        let sign = if inverse { 1.0 } else { -1.0 };
        for (k, yk) in y.iter().enumerate() {
            let direct: Complex64 = x
                .iter()
                .enumerate()
                .map(|(p, xp)| {
                    xp * Complex64::from_polar(1.0, sign * 2.0 * PI * (k * p) as f64 / n as f64)
                })
                .sum();
            assert!((yk - direct).norm() < 1e-9, "{k}: {yk} vs {direct}");
        }
    }
}

#[test]
fn fully_coherent_motions_are_one_motion_delayed_by_the_travel_time() {
    // rank-1 coherency: the semi-definite Cholesky gives one process at every support
    let mut p = params(Coherency::Full, 250.0);
    p.positions = vec![0.0, 25.0, 50.0];
    p.ids = default_ids(3);
    let a = Generator::new(&p).unwrap().realisation(3, 0);
    let peak = a[0].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (j, lag) in [(1, 10), (2, 20)] {
        for k in lag..a[0].len() {
            assert!(
                (a[j][k] - a[0][k - lag]).abs() < 1e-9 * peak,
                "support {j} at {k}"
            );
        }
    }
    // without wave passage: the same samples
    p.v_app = f64::INFINITY;
    let a = Generator::new(&p).unwrap().realisation(3, 0);
    assert_eq!(a[0], a[2]);
}

#[test]
fn the_same_seed_gives_the_same_bytes_on_any_thread_count_and_count() {
    let mut p = params(Coherency::HV_SMART1, 400.0);
    p.stationary = false;
    p.psd.duration = 5.0;
    p.psd.pga_g = Some(0.3);
    let text = |rs: &[pounding::ground_motion::svgm::Realisation]| -> Vec<String> {
        rs.iter()
            .map(|r| csv_text(&p.ids, p.psd.dt, &r.supports))
            .collect()
    };
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| realisations(&p, 6, 5).unwrap());
    let many = realisations(&p, 6, 5).unwrap();
    assert_eq!(text(&one), text(&many));
    let more = realisations(&p, 9, 5).unwrap();
    assert_eq!(text(&one)[..], text(&more)[..6]);
    let other = realisations(&p, 6, 6).unwrap();
    for (a, b) in text(&one).iter().zip(text(&other)) {
        assert_ne!(*a, b);
    }
    // one common factor per realisation: the mean of the supports' peaks is the target
    for r in &many {
        let mean = r
            .supports
            .iter()
            .map(|a| a.iter().fold(0.0f64, |m, x| m.max(x.abs())))
            .sum::<f64>()
            / 4.0;
        assert!((mean / pounding::ground_motion::G0 - 0.3).abs() < 1e-12);
    }
}

#[test]
fn the_coherency_models_follow_their_published_formulas() {
    // written out again here from the papers' forms, with the SMART-1 Event 20 parameters
    let hv = |xi: f64, w: f64| {
        let (a, al, k, w0, b) = (0.736, 0.147, 5210.0, 6.85, 2.78);
        let theta = k * (1.0 + (w / w0).powf(b)).powf(-0.5);
        let e = 2.0 * xi * (1.0 - a + al * a);
        a * (-e / (al * theta)).exp() + (1.0 - a) * (-e / theta).exp()
    };
    let lw = |xi: f64, w: f64| (-(2.5e-4 * w * xi).powi(2)).exp();
    for xi in [0.0, 10.0, 30.0, 100.0, 500.0] {
        for w in [0.5, 2.0, 6.85, 20.0, 60.0] {
            let got = Coherency::HV_SMART1.value(xi, w);
            assert!((got - hv(xi, w)).abs() < 1e-14, "HV at {xi} m, {w} rad/s");
            assert!((Coherency::LW_DEFAULT.value(xi, w) - lw(xi, w)).abs() < 1e-14);
            assert_eq!(Coherency::Full.value(xi, w), 1.0);
            assert_eq!(
                Coherency::Independent.value(xi, w),
                if xi == 0.0 { 1.0 } else { 0.0 }
            );
            // unit at zero separation, decreasing with separation and frequency
            if xi == 0.0 {
                assert!((got - 1.0).abs() < 1e-15);
            }
            assert!(Coherency::HV_SMART1.value(xi + 1.0, w) < got);
            assert!(
                Coherency::HV_SMART1.value(xi + 1.0, w * 1.5)
                    < Coherency::HV_SMART1.value(xi + 1.0, w)
            );
        }
    }
}

#[test]
fn ids_files_and_bad_parameters() {
    use pounding::ground_motion::svgm::{SvgmError, record_id};
    assert_eq!(default_ids(1), ["start"]);
    assert_eq!(default_ids(2), ["start", "end"]);
    assert_eq!(default_ids(4), ["start", "joint1", "joint2", "end"]);
    assert_eq!(record_id(0, 3), "real_0001");
    assert_eq!(record_id(9998, 9999), "real_9999");
    assert_eq!(record_id(41, 10000), "real_00042");
    let name = |p: &SvgmParams| match p.check() {
        Err(SvgmError::InvalidParameter { name, .. }) => name,
        other => panic!("{other:?}"),
    };
    let base = params(Coherency::HV_SMART1, 250.0);
    let mut p = base.clone();
    p.positions[2] = 30.0;
    assert_eq!(name(&p), "--supports");
    let mut p = base.clone();
    p.ids[3] = "joint1".into();
    assert_eq!(name(&p), "--ids");
    let mut p = base.clone();
    p.v_app = 0.0;
    assert_eq!(name(&p), "--v-app");
    let mut p = base.clone();
    p.psd.omega_g = -1.0;
    assert_eq!(name(&p), "--wg");
    let mut p = base.clone();
    p.coherency = Coherency::HarichandranVanmarcke {
        a: 0.7,
        alpha: 0.1,
        k: 0.0,
        omega0: 6.0,
        b: 2.0,
    };
    assert_eq!(name(&p), "--hv-k");
    // a single support is one motion
    let mut p = base;
    p.positions = vec![5.0];
    p.ids = default_ids(1);
    let a = Generator::new(&p).unwrap().realisation(1, 0);
    assert_eq!(a.len(), 1);
    assert_eq!(a[0].len(), 4001);
}
