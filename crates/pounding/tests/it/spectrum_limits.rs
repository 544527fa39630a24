//! Response spectra at extreme `ωh` (`pounding::spectrum`): intervals thousands of periods long
//! (searched on their first and last periods) against the same load split into short collinear
//! samples, periods far longer than the record against the exact double integral of a free
//! mass, a tiny sample interval against the impulse response, the series / Nigam–Jennings
//! switch, tiny periods against the quasi-static limit, and the period range.

use pounding::ground_motion::{G0, Record, el_centro_1940};
use pounding::spectrum::{SERIES_BELOW, check, peak_displacement, rotd, spectrum};
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// A short lead-in (an initial transient), then the line `a0 → a1` over `len`, either as one
/// interval or split into collinear samples at most `step` apart (the same load).
fn lead_and_ramp(a0: f64, a1: f64, len: f64, split: Option<f64>) -> (Vec<f64>, Vec<f64>) {
    let mut t = vec![0.0, 0.013, 0.02, 0.041];
    let mut a = vec![0.0, 0.7, -0.4, a0];
    let n = split.map_or(1, |s| (len / s).ceil() as usize);
    for k in 1..=n {
        let f = k as f64 / n as f64;
        t.push(0.041 + len * f);
        a.push(a0 + (a1 - a0) * f);
    }
    (t, a)
}

#[test]
fn a_long_interval_has_the_peak_of_the_same_line_split_into_short_samples() {
    let period = 0.5;
    // 400 periods: far past the 64 that switch to the first-and-last-periods search
    let len = 400.0 * period;
    for zeta in [0.0, 0.02, 0.05, 0.5, 0.95] {
        for (a0, a1) in [
            (0.0, 1.0),
            (1.0, -1.0),
            (1.0, 0.9),
            (-0.3, 2.0),
            (0.6, 0.6),
            (0.0, -0.05),
        ] {
            let (t, a) = lead_and_ramp(a0, a1, len, None);
            let (ts, as_) = lead_and_ramp(a0, a1, len, Some(period / 10.0));
            let long = peak_displacement(&t, &a, period, zeta);
            let short = peak_displacement(&ts, &as_, period, zeta);
            assert!(
                rel(long, short) < 1e-9,
                "zeta {zeta}, {a0} -> {a1}: long {long} vs split {short}"
            );
        }
    }
}

#[test]
fn rotd_of_a_long_interval_pair_equals_the_split_pair() {
    let period = 0.4;
    let len = 300.0 * period;
    let rec = |a0, a1, split| {
        let (t, a) = lead_and_ramp(a0, a1, len, split);
        Record::new("r", t, a).unwrap()
    };
    for zeta in [0.0, 0.05] {
        let long = rotd(&rec(0.3, -1.0, None), &rec(1.0, 0.2, None), zeta, &[period]).unwrap();
        let split = Some(period / 10.0);
        let short = rotd(
            &rec(0.3, -1.0, split),
            &rec(1.0, 0.2, split),
            zeta,
            &[period],
        )
        .unwrap();
        for (l, s) in [
            (long.rotd50[0].sd, short.rotd50[0].sd),
            (long.rotd100[0].sd, short.rotd100[0].sd),
        ] {
            assert!(rel(l, s) < 1e-9, "zeta {zeta}: long {l} vs split {s}");
        }
    }
}

#[test]
fn a_far_off_last_sample_gives_the_peak_of_a_near_one() {
    // a ramp to 0.1 g then constant: the start's transient is the peak (5 % damping), the same
    // whether the record ends 20 s (40 periods, plain sub-grid) or 1e12 s / 1e300 s later
    let g = 0.1 * G0;
    let peak = |end: f64| peak_displacement(&[0.0, 0.01, end], &[0.0, g, g], 0.5, 0.05);
    let near = peak(20.0);
    let w = 2.0 * PI / 0.5;
    assert!(near * w * w / g > 1.8 && near * w * w / g < 1.9, "{near}");
    for end in [1e6, 1e12, 1e300] {
        assert!(
            rel(peak(end), near) < 1e-12,
            "end {end}: {} vs {near}",
            peak(end)
        );
    }
}

/// `(u_end, v_end, max |u|)` of a free mass (`ω = 0`) under the piecewise-linear load, exactly:
/// `u = −∫∫a`, a cubic on each interval (its interior extremum where `v = 0`).
fn free_mass(t: &[f64], a: &[f64]) -> (f64, f64, f64) {
    let (mut u, mut v, mut peak) = (0.0f64, 0.0f64, 0.0f64);
    for i in 0..t.len() - 1 {
        let (h, a0, a1) = (t[i + 1] - t[i], a[i], a[i + 1]);
        let s = (a1 - a0) / h;
        // v(τ) = v − a0 τ − s τ²/2; u(τ) = u + v τ − a0 τ²/2 − s τ³/6
        let at = |tau: f64| u + v * tau - a0 * tau * tau / 2.0 - s * tau.powi(3) / 6.0;
        let disc = a0 * a0 + 2.0 * s * v;
        if s != 0.0 && disc >= 0.0 {
            for r in [(-a0 + disc.sqrt()) / s, (-a0 - disc.sqrt()) / s] {
                if r > 0.0 && r < h {
                    peak = peak.max(at(r).abs());
                }
            }
        }
        (u, v) = (at(h), v - h * (a0 + a1) / 2.0);
        peak = peak.max(u.abs());
    }
    (u, v, peak)
}

#[test]
fn a_very_long_period_moves_as_a_free_mass() {
    // a = sin(πt) on [0, 2] (antisymmetric samples: ∫a = 0), so the free mass ends at rest at
    // its largest |u|, and the damped free vibration after it never exceeds that
    let n = 200;
    let t: Vec<f64> = (0..=n).map(|k| 2.0 * k as f64 / n as f64).collect();
    let half: Vec<f64> = (0..=n / 2).map(|k| (PI * t[k]).sin()).collect();
    let a: Vec<f64> = (0..=n)
        .map(|k| if k <= n / 2 { half[k] } else { -half[n - k] })
        .collect();
    let (u_end, v_end, peak) = free_mass(&t, &a);
    assert!(v_end.abs() < 1e-15 && rel(peak, u_end.abs()) < 1e-12);
    // relative error of the free-mass limit: O(ζ ω t_end + (ω t_end)²), t_end = 2 s; and the
    // residual velocity, exactly 0 here, is computed to ~1e-16 m/s, which drifts by 1e-16/ω m
    // after the record (the spectrum's conditioning at T ≫ duration: S_d ≈ |v_end|/ω; El Centro
    // below has a real residual velocity and goes to 1e100 s)
    for period in [1e6, 1e7, 1e8] {
        for zeta in [0.0, 0.05, 0.7] {
            let w = 2.0 * PI / period;
            let wt = w * 2.0;
            let tol = 1e-12 + 4.0 * (zeta * wt + wt * wt) + 1e-14 / w / peak;
            let sd = peak_displacement(&t, &a, period, zeta);
            assert!(
                rel(sd, peak) < tol,
                "T {period}, zeta {zeta}: sd {sd} vs free mass {peak}"
            );
        }
    }
}

#[test]
fn el_centro_at_very_long_periods_drifts_with_its_residual_velocity() {
    // undamped: after the record the mass vibrates with amplitude √(u_end² + (v_end/ω)²), far
    // above |u| during the record; (u_end, v_end) of the free mass, exact for the linear load.
    // Tolerance: (ω t_end)² for the limit, and v_end = −∫a is ~3e4 times smaller than the
    // velocities summed into it (baseline-corrected record), so both sums carry ~1e-11 of it
    let r = el_centro_1940().along_y.unwrap();
    let (u_end, v_end, peak) = free_mass(r.times(), r.values());
    for (period, tol) in [
        (1e6, 1e-6),
        (1e8, 1e-9),
        (1e10, 1e-9),
        (1e50, 1e-9),
        (1e100, 1e-9),
    ] {
        let w = 2.0 * PI / period;
        let want = u_end.hypot(v_end / w).max(peak);
        let sd = spectrum(&r, 0.0, &[period]).unwrap()[0].sd;
        assert!(rel(sd, want) < tol, "T {period}: sd {sd} vs {want}");
    }
}

#[test]
fn a_tiny_sample_interval_gives_the_impulse_response_peak() {
    // 5 samples 1e-20 s apart (0.1 … 0.5 g): an impulse I = ∫a; the peak of I·B(t) is
    // I e^{−ζωt*}/ω at ω_d t* = atan2(√(1−ζ²), ζ)
    let t: Vec<f64> = (0..5).map(|k| k as f64 * 1e-20).collect();
    let a: Vec<f64> = (1..=5).map(|k| 0.1 * k as f64 * G0).collect();
    let impulse: f64 = (0..4).map(|k| 1e-20 * (a[k] + a[k + 1]) / 2.0).sum();
    for zeta in [0.0f64, 0.05, 0.3] {
        let period = 0.5;
        let w = 2.0 * PI / period;
        let wd = w * (1.0 - zeta * zeta).sqrt();
        let ts = (1.0 - zeta * zeta).sqrt().atan2(zeta) / wd;
        let want = impulse * (-zeta * w * ts).exp() / w;
        let sd = peak_displacement(&t, &a, period, zeta);
        assert!(rel(sd, want) < 1e-12, "zeta {zeta}: {sd} vs {want}");
    }
}

#[test]
fn the_series_and_nigam_jennings_forms_agree_at_the_switch() {
    // the same irregular record at sample intervals just below and just above ωh = SERIES_BELOW
    // (one record on each form, the records 2e-12 apart in time scale)
    let period = 20.0;
    let w = 2.0 * PI / period;
    let rec = |dt: f64| {
        let t: Vec<f64> = (0..3000).map(|k| k as f64 * dt).collect();
        let a: Vec<f64> = (0..3000)
            .map(|k| {
                let s = k as f64 * 1e-3;
                (7.3 * s).sin() + 0.6 * (17.9 * s + 0.4).sin() + 0.3
            })
            .collect();
        (t, a)
    };
    for zeta in [0.0, 0.05] {
        let (tb, ab) = rec(SERIES_BELOW / w * (1.0 - 1e-12));
        let (ta, aa) = rec(SERIES_BELOW / w * (1.0 + 1e-12));
        let below = peak_displacement(&tb, &ab, period, zeta);
        let above = peak_displacement(&ta, &aa, period, zeta);
        // an independent 40-digit evaluation (mpmath) of the zeta = 0 case gives
        // 6.6429804016454 below and 6.6429804016521 above: the records differ by ~1e-12
        assert!(rel(below, above) < 1e-11, "zeta {zeta}: {below} vs {above}");
    }
}

#[test]
fn tiny_periods_follow_the_load_quasi_statically() {
    let r = el_centro_1940().along_y.unwrap();
    let pga_g = r.pga() / G0;
    for period in [1e-10, 1e-50, 1e-100] {
        let o = spectrum(&r, 0.05, &[period]).unwrap()[0];
        assert!(
            rel(o.psa_g, pga_g) < 1e-9,
            "T {period}: {} vs {pga_g}",
            o.psa_g
        );
    }
}

#[test]
fn periods_outside_the_range_are_refused() {
    assert!(check(0.05, &[1e-100, 1e100]).is_ok());
    for t in [1e-101, 1.1e100, 1e300] {
        let e = check(0.05, &[1.0, t]).unwrap_err().to_string();
        assert!(e.contains("[1e-100, 1e100]"), "{e}");
    }
}
