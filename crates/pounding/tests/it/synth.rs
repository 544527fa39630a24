//! Synthetic accelerograms (`pounding::ground_motion::synth`, issue 13) against the model they
//! claim: the averaged periodogram of the envelope-removed middle part against the
//! Kanai–Tajimi–Clough–Penzien PSD (level and shape), the ensemble mean square against
//! `σ² e(t)²` (σ² = ∫S from the PSD by quadrature), the envelope's defining values, exact PGA
//! scaling, zero final velocity and displacement, determinism for any thread count, the files
//! read back by the tool's own reader, bad parameters refused before anything is written.

use pounding::ground_motion::synth::{
    SynthParams, baseline_correct, component_g, stationary, suite, write_suite,
};
use pounding::ground_motion::{AccelUnits, G0, Record};
use std::f64::consts::PI;

/// `(v(T), d(T), max |v|, max |d|)` of the piecewise-linear record `a` (m/s²) from rest.
fn ends(dt: f64, a: &[f64]) -> (f64, f64, f64, f64) {
    let (mut v, mut d, mut vm, mut dm) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for w in a.windows(2) {
        d += v * dt + dt * dt * (2.0 * w[0] + w[1]) / 6.0;
        v += 0.5 * dt * (w[0] + w[1]);
        vm = vm.max(v.abs());
        dm = dm.max(d.abs());
    }
    (v, d, vm, dm)
}

/// `σ² = ∫ S(ω) dω` over ℝ: Simpson on [0, 2000] rad/s plus the tail `S ≈ S₀ 4ζ_g²ω_g²/ω²`.
fn variance(p: &SynthParams) -> f64 {
    let (top, n) = (2000.0, 200_000);
    let h = top / n as f64;
    let mut s = p.psd(0.0) + p.psd(top);
    for k in 1..n {
        s += if k % 2 == 1 { 4.0 } else { 2.0 } * p.psd(k as f64 * h);
    }
    let tail = p.s0 * 4.0 * p.zeta_g.powi(2) * p.omega_g.powi(2) / top;
    2.0 * (s * h / 3.0 + tail)
}

#[test]
fn the_envelope_peaks_at_one_at_epsilon_tn_and_ends_at_eta() {
    let p = SynthParams::default();
    let (tn, eps, eta) = (p.duration, p.epsilon, p.eta);
    assert!((p.envelope(eps * tn) - 1.0).abs() < 1e-12);
    assert!((p.envelope(tn) - eta).abs() < 1e-12);
    for t in [0.3 * eps * tn, 0.9 * eps * tn, 1.1 * eps * tn, 0.7 * tn] {
        assert!(p.envelope(t) < 1.0, "t {t}");
    }
    assert_eq!(p.envelope(0.0), 0.0);
}

/// The averaged periodogram (Hann window, 512 samples, two half-overlapping segments inside the
/// part where `e(t) ≥ 0.5`, the samples divided by `e(t)`) of 200 unscaled records equals the
/// sampled model PSD `Σ_k S(ω + 2πk/dt)` (aliases included) at 24 frequencies from 5 to 80 rad/s
/// (each the mean of 3 DFT bins): within 15 % each (≈ 5 standard errors of 600 averaged
/// periodograms) and 5 % on average. Below 5 rad/s the Clough–Penzien slope (∝ ω⁴) would bias a
/// Hann estimate through leakage, so it is not tested.
#[test]
fn the_sample_psd_matches_the_kanai_tajimi_clough_penzien_psd() {
    let p = SynthParams::default();
    let dt = p.dt;
    let first = (0..p.samples())
        .find(|&k| p.envelope(k as f64 * dt) >= 0.5)
        .unwrap();
    let (len, records) = (512usize, 200);
    let hann: Vec<f64> = (0..len)
        .map(|k| 0.5 - 0.5 * (2.0 * PI * k as f64 / len as f64).cos())
        .collect();
    let u: f64 = hann.iter().map(|w| w * w).sum();
    let dw = 2.0 * PI / (len as f64 * dt);
    let bins: Vec<usize> = (0..24)
        .map(|j| ((5.0 * 16f64.powf(j as f64 / 23.0)) / dw).round() as usize)
        .collect();
    let mut est = vec![0.0; bins.len()];
    let mut segs = 0;
    for i in 0..records {
        let g = component_g(&p, 11, i, 0);
        for start in [first, first + len / 2] {
            assert!(p.envelope((start + len) as f64 * dt) >= 0.5);
            let x: Vec<f64> = (start..start + len)
                .map(|k| g[k] * G0 / p.envelope(k as f64 * dt))
                .collect();
            for (e, &b) in est.iter_mut().zip(&bins) {
                for bin in b - 1..=b + 1 {
                    let w = bin as f64 * dw;
                    let (mut re, mut im) = (0.0, 0.0);
                    for (k, (&xk, &hk)) in x.iter().zip(&hann).enumerate() {
                        let (s, c) = (w * k as f64 * dt).sin_cos();
                        re += hk * xk * c;
                        im -= hk * xk * s;
                    }
                    *e += dt / (2.0 * PI * u) * (re * re + im * im) / 3.0;
                }
            }
            segs += 1;
        }
    }
    let mut ratios = Vec::new();
    for (e, &b) in est.iter().zip(&bins) {
        let got = e / segs as f64;
        let want: f64 = (b - 1..=b + 1)
            .map(|bin| {
                (-20..=20)
                    .map(|k| p.psd(bin as f64 * dw + 2.0 * PI * k as f64 / dt))
                    .sum::<f64>()
                    / 3.0
            })
            .sum();
        let r = got / want;
        assert!(
            (r - 1.0).abs() < 0.15,
            "ω {}: {got} vs {want}",
            b as f64 * dw
        );
        ratios.push(r);
    }
    let mean = ratios.iter().sum::<f64>() / ratios.len() as f64;
    assert!((mean - 1.0).abs() < 0.05, "mean ratio {mean}: {ratios:?}");
}

/// The ensemble mean square of 400 unscaled records, in 0.5 s bins, equals `σ² e(t)²` (σ² from
/// the PSD by quadrature: the intensity as documented) within 12 % wherever `e ≥ 0.2` (≈ 4
/// standard errors), and 4 % over all those bins together.
#[test]
fn the_mean_square_follows_the_saragoni_hart_envelope_squared() {
    let p = SynthParams::default();
    let sigma2 = variance(&p);
    let n = p.samples();
    let mut ms = vec![0.0; n];
    let records = 400;
    for i in 0..records {
        for (m, g) in ms.iter_mut().zip(component_g(&p, 5, i, 1)) {
            *m += (g * G0).powi(2) / records as f64;
        }
    }
    let (mut sum_got, mut sum_want) = (0.0, 0.0);
    for bin in ms.chunks(50).enumerate() {
        let (j, chunk) = bin;
        let t0 = j * 50;
        let want: f64 = (t0..t0 + chunk.len())
            .map(|k| sigma2 * p.envelope(k as f64 * p.dt).powi(2))
            .sum::<f64>()
            / chunk.len() as f64;
        if want < sigma2 * 0.04 {
            continue;
        }
        let got = chunk.iter().sum::<f64>() / chunk.len() as f64;
        assert!(
            (got / want - 1.0).abs() < 0.12,
            "t {}: {got} vs {want}",
            t0 as f64 * p.dt
        );
        sum_got += got;
        sum_want += want;
    }
    assert!((sum_got / sum_want - 1.0).abs() < 0.04);
    // the stationary process itself has the variance of the PSD
    let s: Vec<f64> = (0..100).flat_map(|i| stationary(&p, 3, i, 0)).collect();
    let v = s.iter().map(|x| x * x).sum::<f64>() / s.len() as f64;
    assert!((v / sigma2 - 1.0).abs() < 0.05, "{v} vs {sigma2}");
}

#[test]
fn a_target_pga_is_met_exactly_and_the_motion_ends_at_rest() {
    let p = SynthParams {
        pga_g: Some(0.37),
        ..SynthParams::default()
    };
    for r in suite(&p, 6, 2, true).unwrap() {
        for g in [&r.x, r.y.as_ref().unwrap()] {
            let peak = g.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            assert_eq!(peak, 0.37, "{}", r.id);
            let a: Vec<f64> = g.iter().map(|x| x * G0).collect();
            let (v, d, vm, dm) = ends(p.dt, &a);
            assert!(v.abs() < 1e-10 * vm, "{}: v(T) {v} of {vm}", r.id);
            assert!(d.abs() < 1e-10 * dm, "{}: d(T) {d} of {dm}", r.id);
        }
    }
    // the baseline correction alone: a constant record ends at rest too
    let mut a = vec![1.0; 1001];
    baseline_correct(0.01, &mut a);
    let (v, d, _, _) = ends(0.01, &a);
    assert!(v.abs() < 1e-12 && d.abs() < 1e-12);
}

/// The same seed gives the same records for 1 thread and the default pool, and record `i` does
/// not depend on the count; another seed, index or component gives another record.
#[test]
fn suites_are_deterministic_for_any_thread_count() {
    let p = SynthParams {
        duration: 5.0,
        ..SynthParams::default()
    };
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| suite(&p, 5, 42, true).unwrap());
    let many = suite(&p, 5, 42, true).unwrap();
    assert_eq!(one, many);
    let fewer = suite(&p, 3, 42, true).unwrap();
    assert_eq!(&many[..3], &fewer[..]);
    assert_eq!(many[0].id, "SYN001");
    let other = suite(&p, 1, 43, false).unwrap();
    assert_ne!(other[0].x, many[0].x);
    assert_ne!(many[0].x, many[1].x);
    assert_ne!(Some(&many[0].x), many[0].y.as_ref());
    assert!(other[0].y.is_none());
}

#[test]
fn written_files_read_back_as_the_same_samples() {
    let scratch = crate::scratch::scratch_dir("it-synth", "read-back");
    let dir = scratch.join("suite");
    let p = SynthParams {
        duration: 4.0,
        dt: 0.005,
        pga_g: Some(0.25),
        ..SynthParams::default()
    };
    let recs = write_suite(&dir, &p, 3, 9, true, "test").unwrap();
    let manifest: toml::Table = std::fs::read_to_string(dir.join("suite.toml"))
        .unwrap()
        .parse()
        .unwrap();
    let list = manifest["record"].as_array().unwrap();
    assert_eq!(list.len(), 3);
    for (r, m) in recs.iter().zip(list) {
        assert_eq!(m["id"].as_str(), Some(r.id.as_str()));
        assert_eq!(m["meta"]["pga_g"].as_float(), Some(0.25));
        for (key, g) in [("x", &r.x), ("y", r.y.as_ref().unwrap())] {
            let path = dir.join(m[key].as_str().unwrap());
            let rec = Record::from_path(&path, AccelUnits::MetresPerSecondSquared).unwrap();
            let want: Vec<f64> = g.iter().map(|x| x * G0).collect();
            assert_eq!(rec.values(), &want[..], "{}", path.display());
            assert_eq!(rec.dt(), Some(0.005));
            assert_eq!(rec.times().len(), 801);
        }
    }
    let readme = std::fs::read_to_string(dir.join("SYNTHETIC.txt")).unwrap();
    assert!(readme.contains("Real assessments need real recorded ground motions"));
}

#[test]
fn bad_parameters_are_refused_naming_them_and_nothing_is_written() {
    let d = SynthParams::default();
    let cases: Vec<(SynthParams, usize, &str)> = vec![
        (d.clone(), 0, "--count"),
        (d.clone(), 10_001, "--count"),
        (
            SynthParams {
                dt: 0.0,
                ..d.clone()
            },
            1,
            "--dt",
        ),
        (
            SynthParams {
                dt: f64::NAN,
                ..d.clone()
            },
            1,
            "--dt",
        ),
        (
            SynthParams {
                dt: 30.0,
                ..d.clone()
            },
            1,
            "--dt",
        ),
        (
            SynthParams {
                duration: -1.0,
                ..d.clone()
            },
            1,
            "--duration",
        ),
        (
            SynthParams {
                duration: 1e9,
                ..d.clone()
            },
            1,
            "--duration",
        ),
        (
            SynthParams {
                pga_g: Some(0.0),
                ..d.clone()
            },
            1,
            "--pga",
        ),
        (
            SynthParams {
                pga_g: Some(f64::INFINITY),
                ..d.clone()
            },
            1,
            "--pga",
        ),
        (
            SynthParams {
                zeta_g: 1.0,
                ..d.clone()
            },
            1,
            "zeta_g",
        ),
    ];
    let scratch = crate::scratch::scratch_dir("it-synth", "bad");
    let dir = scratch.join("suite");
    for (p, count, name) in cases {
        let e = write_suite(&dir, &p, count, 1, false, "t")
            .unwrap_err()
            .to_string();
        assert!(e.contains(name), "{name}: {e}");
        assert!(!dir.exists());
    }
}
