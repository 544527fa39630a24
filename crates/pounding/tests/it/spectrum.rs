//! Response spectra (`pounding::spectrum`, issue 13) against independent evidence: the closed
//! forms of a step load and of a harmonic load (transient + steady state), a brute-force fine
//! RK4 integration of the same piecewise-linear load, the RotD identities of a pair whose components are equal or one of them zero, and bad input.

use pounding::ground_motion::{G0, Record};
use pounding::spectrum::{check, default_periods, peak_displacement, rotd, spectrum};
use std::f64::consts::PI;

/// A deterministic irregular motion: a sum of sines with a decaying envelope, `n` samples at `dt`.
fn motion(n: usize, dt: f64) -> Record {
    let t: Vec<f64> = (0..n).map(|i| i as f64 * dt).collect();
    let a = t
        .iter()
        .map(|&s| {
            let env = (s / 2.0).min(1.0) * (-(s - 2.0).max(0.0) / 4.0).exp();
            env * (3.1 * (7.3 * s).sin() + 2.0 * (17.9 * s + 0.4).sin() + 1.3 * (2.1 * s).cos())
        })
        .collect();
    Record::new("test", t, a).unwrap()
}

/// `max |u|` by RK4 with `sub` steps per sample interval on the piecewise-linear load, continued
/// for `3T` of free vibration after the last sample (the load zero there).
fn brute_force(r: &Record, period: f64, zeta: f64, sub: usize) -> f64 {
    let w = 2.0 * PI / period;
    let f = |a: f64, u: f64, v: f64| (v, -a - 2.0 * zeta * w * v - w * w * u);
    let (t, a) = (r.times(), r.values());
    let (mut u, mut v, mut peak) = (0.0f64, 0.0f64, 0.0f64);
    let step = |a0: f64, a1: f64, h: f64, u: &mut f64, v: &mut f64, peak: &mut f64| {
        let dh = h / sub as f64;
        for j in 0..sub {
            let s0 = j as f64 / sub as f64;
            let load = |s: f64| a0 + (a1 - a0) * s;
            let (am, ae) = (load(s0 + 0.5 / sub as f64), load(s0 + 1.0 / sub as f64));
            let k1 = f(load(s0), *u, *v);
            let k2 = f(am, *u + 0.5 * dh * k1.0, *v + 0.5 * dh * k1.1);
            let k3 = f(am, *u + 0.5 * dh * k2.0, *v + 0.5 * dh * k2.1);
            let k4 = f(ae, *u + dh * k3.0, *v + dh * k3.1);
            *u += dh / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
            *v += dh / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
            *peak = peak.max(u.abs());
        }
    };
    for i in 0..t.len() - 1 {
        step(a[i], a[i + 1], t[i + 1] - t[i], &mut u, &mut v, &mut peak);
    }
    for _ in 0..24 {
        step(0.0, 0.0, period / 8.0, &mut u, &mut v, &mut peak);
    }
    peak
}

/// A constant load `a₀` from rest: `S_d = a₀/ω² (1 + e^{−ζπ/√(1−ζ²)})` (the first overshoot,
/// between samples), `2a₀/ω²` undamped.
#[test]
fn a_step_load_peaks_as_the_closed_form_between_samples() {
    let (a0, dt) = (1.7, 0.013);
    let n = 1500;
    let r = Record::new("step", (0..n).map(|i| i as f64 * dt).collect(), vec![a0; n]).unwrap();
    for (period, zeta) in [(1.0, 0.0), (1.0, 0.05), (0.37, 0.2), (2.5, 0.0)] {
        let w: f64 = 2.0 * PI / period;
        let want = a0 / (w * w) * (1.0 + (-zeta * PI / (1.0f64 - zeta * zeta).sqrt()).exp());
        let got = peak_displacement(r.times(), r.values(), period, zeta);
        assert!(
            (got - want).abs() < 1e-10 * want,
            "T {period} ζ {zeta}: {got} vs {want}"
        );
    }
}

/// The exact recurrence with the continuous-time peak equals a fine RK4 integration of the same
/// load (to its O(h⁴) error and the grid's sampling of the peak), for short and long periods; the
/// peak at the samples alone can be lower.
#[test]
fn the_recurrence_matches_a_fine_integration_and_beats_the_sampled_peak() {
    let r = motion(400, 0.02);
    for (period, zeta) in [
        (0.05, 0.05),
        (0.1, 0.05),
        (0.3, 0.02),
        (1.0, 0.05),
        (3.0, 0.1),
    ] {
        let got = peak_displacement(r.times(), r.values(), period, zeta);
        let want = brute_force(&r, period, zeta, 400);
        assert!(
            (got - want).abs() < 2e-6 * want,
            "T {period}: {got} vs {want}"
        );
        // at the samples only (the fine integration read at the sample times)
        let sampled = brute_force(&r, period, zeta, 1);
        assert!(
            got >= sampled * (1.0 - 1e-3),
            "T {period}: {got} < sampled {sampled}"
        );
    }
    // T = 0.1 s at dt = 0.01 s: the continuous peak is above the largest sampled |u|
    let r = motion(800, 0.01);
    let got = peak_displacement(r.times(), r.values(), 0.1, 0.05);
    let fine = brute_force(&r, 0.1, 0.05, 200);
    assert!((got - fine).abs() < 1e-6 * fine);
}

/// The ordinates: `psv = ω S_d`, `psa = ω² S_d / g`; the period and damping as given.
#[test]
fn ordinates_are_the_pseudo_values_of_the_peak() {
    let r = motion(300, 0.02);
    let s = spectrum(&r, 0.05, &[0.2, 1.0]).unwrap();
    for o in &s {
        let w = 2.0 * PI / o.period;
        assert_eq!(o.damping, 0.05);
        assert_eq!(
            o.sd,
            peak_displacement(r.times(), r.values(), o.period, 0.05)
        );
        assert!((o.psv - w * o.sd).abs() <= 1e-15 * o.psv);
        assert!((o.psa_g - w * w * o.sd / G0).abs() <= 1e-15 * o.psa_g);
    }
}

/// RotD of `(x, x)`: `u_α = u_x (cos α + sin α)`, so RotD100 = √2 S_d (α = 45°) and RotD50 the
/// median of `|cos α + sin α|` S_d; of `(x, 0)`: RotD100 = S_d (α = 0), RotD50 the median of
/// `|cos α|` S_d — also when the zero record is shorter and sampled differently (padding and
/// the union grid change nothing).
#[test]
fn rotd_of_equal_and_single_components_follows_the_rotation() {
    let x = motion(500, 0.02);
    let zero = Record::new(
        "zero",
        (0..300).map(|i| i as f64 * 0.015).collect(),
        vec![0.0; 300],
    )
    .unwrap();
    let periods = [0.15, 0.6, 2.0];
    let median = |f: &dyn Fn(f64) -> f64| {
        let mut v: Vec<f64> = (0..180).map(|d| f((d as f64).to_radians())).collect();
        v.sort_by(f64::total_cmp);
        0.5 * (v[89] + v[90])
    };
    let same = rotd(&x, &x, 0.05, &periods).unwrap();
    let single = rotd(&x, &zero, 0.05, &periods).unwrap();
    for (k, &t) in periods.iter().enumerate() {
        let sd = peak_displacement(x.times(), x.values(), t, 0.05);
        let close = |a: f64, b: f64| (a - b).abs() < 1e-9 * b;
        assert!(close(same.rotd100[k].sd, 2f64.sqrt() * sd), "T {t}");
        assert!(close(
            same.rotd50[k].sd,
            median(&|a: f64| (a.cos() + a.sin()).abs()) * sd
        ));
        assert!(
            close(single.rotd100[k].sd, sd),
            "T {t}: {} vs {sd}",
            single.rotd100[k].sd
        );
        assert!(close(
            single.rotd50[k].sd,
            median(&|a: f64| a.cos().abs()) * sd
        ));
        assert!(same.rotd50[k].sd <= same.rotd100[k].sd);
    }
}

#[test]
fn rotd_keeps_each_records_jumps_at_its_first_and_last_sample() {
    // trial finding: a record starting late at a nonzero value and ending away from zero, on a
    // grid other than its partner's, was ramped (not stepped) at its ends on the union grid, so
    // RotD disagreed with the record's own spectrum by 0.1-0.4 %
    let x = Record::new(
        "late",
        (0..300).map(|i| 0.003 + i as f64 * 0.007).collect(),
        (0..300)
            .map(|i| G0 * (0.4 * (2.0 * PI * i as f64 * 0.007 / 0.9).cos() + 0.2))
            .collect(),
    )
    .unwrap();
    let zero = Record::new(
        "zero",
        (0..400).map(|i| i as f64 * 0.01).collect(),
        vec![0.0; 400],
    )
    .unwrap();
    let other = motion(350, 0.011);
    let periods = [0.1, 0.5, 1.0, 3.0];
    let close = |a: f64, b: f64| (a - b).abs() < 1e-9 * b;
    let xz = rotd(&x, &zero, 0.05, &periods).unwrap();
    let zx = rotd(&zero, &x, 0.05, &periods).unwrap();
    let xo = rotd(&x, &other, 0.05, &periods).unwrap();
    for (k, &t) in periods.iter().enumerate() {
        let sd = peak_displacement(x.times(), x.values(), t, 0.05);
        let so = peak_displacement(other.times(), other.values(), t, 0.05);
        // alone at 0° (and at 90° with the components swapped): the largest of |cos α| sd
        assert!(
            close(xz.rotd100[k].sd, sd),
            "T {t}: {} vs {sd}",
            xz.rotd100[k].sd
        );
        assert!(
            close(zx.rotd100[k].sd, sd),
            "T {t}: {} vs {sd}",
            zx.rotd100[k].sd
        );
        // the rotated peaks include 0° and 90°: RotD100 is at least either component's
        assert!(xo.rotd100[k].sd >= sd.max(so) * (1.0 - 1e-12), "T {t}");
    }
}

#[test]
fn bad_damping_and_periods_are_errors_naming_them() {
    for z in [1.0, -0.01, f64::NAN, 2.0] {
        let e = check(z, &[1.0]).unwrap_err().to_string();
        assert!(e.contains("damping"), "{e}");
    }
    for t in [0.0, -1.0, f64::INFINITY, f64::NAN] {
        let e = check(0.05, &[1.0, t]).unwrap_err().to_string();
        assert!(e.contains("period"), "{e}");
    }
    let p = default_periods();
    assert_eq!((p.len(), p[0], p[99]), (100, 0.01, 10.0));
    assert!(p.windows(2).all(|w| w[0] < w[1]));
}

/// `u(t)` of `ü + 2ζωu̇ + ω²u = −A sin Ωt` from rest, in closed form: the steady state
/// `u_p = −(A/ω²) [(1 − r²) sin Ωt − 2ζr cos Ωt] / [(1 − r²)² + (2ζr)²]` (`r = Ω/ω`) plus the
/// transient `e^{−ζωt}(c₁ cos ω_d t + c₂ sin ω_d t)` that cancels `u_p(0)`, `u̇_p(0)`; undamped at
/// resonance `u = (A / 2ω²)(sin ωt − ωt cos ωt)`. For `t > t_end` the load is off: free
/// vibration from the state at `t_end`.
fn harmonic_exact(amp: f64, big_w: f64, w: f64, zeta: f64, t_end: f64, t: f64) -> f64 {
    let wd = w * (1.0 - zeta * zeta).sqrt();
    let forced = |t: f64| -> (f64, f64) {
        if zeta == 0.0 && big_w == w {
            let u = amp / (2.0 * w * w) * ((w * t).sin() - w * t * (w * t).cos());
            let v = amp / 2.0 * t * (w * t).sin();
            return (u, v);
        }
        let r = big_w / w;
        let den = (1.0 - r * r).powi(2) + (2.0 * zeta * r).powi(2);
        let (c, d) = (
            -amp / (w * w) * (1.0 - r * r) / den,
            amp / (w * w) * 2.0 * zeta * r / den,
        );
        // u_p = c sin Ωt + d cos Ωt; transient from u(0) = u̇(0) = 0
        let c1 = -d;
        let c2 = (-c * big_w + zeta * w * c1) / wd;
        let e = (-zeta * w * t).exp();
        let (s, co) = (wd * t).sin_cos();
        let (sp, cp) = (big_w * t).sin_cos();
        let u = c * sp + d * cp + e * (c1 * co + c2 * s);
        let v = big_w * (c * cp - d * sp)
            + e * ((-zeta * w * c1 + wd * c2) * co + (-zeta * w * c2 - wd * c1) * s);
        (u, v)
    };
    if t <= t_end {
        return forced(t).0;
    }
    let (u0, v0) = forced(t_end);
    let tau = t - t_end;
    let (s, c) = (wd * tau).sin_cos();
    (-zeta * w * tau).exp() * (u0 * c + (v0 + zeta * w * u0) / wd * s)
}

/// `max |f|` on `[a, b]`: a dense scan (64 points per shortest period) refined around the
/// best point by golden-section search on `|f|`.
fn continuous_max(f: &dyn Fn(f64) -> f64, a: f64, b: f64, shortest: f64) -> f64 {
    let n = ((b - a) / shortest * 64.0).ceil() as usize;
    let h = (b - a) / n as f64;
    let k = (0..=n)
        .max_by(|&i, &j| {
            f(a + i as f64 * h)
                .abs()
                .total_cmp(&f(a + j as f64 * h).abs())
        })
        .unwrap();
    let (mut lo, mut hi) = (
        (a + (k as f64 - 1.0) * h).max(a),
        (a + (k as f64 + 1.0) * h).min(b),
    );
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (m1, m2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if f(m1).abs() < f(m2).abs() {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    f(0.5 * (lo + hi)).abs().max(f(a).abs()).max(f(b).abs())
}

/// The recurrence under a sampled harmonic `a_g = A sin Ωt` equals the closed-form response
/// (transient + steady state, then free vibration after the record) to 1e-9 of the peak, below,
/// at and above resonance, undamped to 20 % damped. The record is the sine sampled at `h` with
/// `Ωh = 4e-5`, so the piecewise-linear load the recurrence solves exactly differs from the sine
/// by `(Ωh)²/8 ≈ 2e-10` of `A` at most (`(Ωh)²/12` on average): the remaining difference is the
/// recurrence's own error (checked to 2e-11 once that factor is applied). The record ends at a zero of the sine, after 6 forcing periods.
#[test]
fn a_harmonic_load_peaks_as_the_closed_form() {
    let amp = 2.3;
    let period = 0.8;
    let w = 2.0 * PI / period;
    for (ratio, zeta) in [
        (1.0, 0.05),
        (1.0, 0.02),
        (1.0, 0.0),
        (0.5, 0.05),
        (2.0, 0.05),
        (0.7, 0.2),
        (1.3, 0.0),
        (3.1, 0.1),
    ] {
        let big_w = ratio * w;
        let t_end = 6.0 * 2.0 * PI / big_w;
        let n = (big_w * t_end / 4e-5).round() as usize;
        let times: Vec<f64> = (0..=n).map(|i| t_end * i as f64 / n as f64).collect();
        let accel: Vec<f64> = times.iter().map(|&t| amp * (big_w * t).sin()).collect();
        let got = peak_displacement(&times, &accel, period, zeta);
        let exact = |t: f64| harmonic_exact(amp, big_w, w, zeta, t_end, t);
        let shortest = period.min(2.0 * PI / big_w);
        let want = continuous_max(&exact, 0.0, t_end + 2.0 * period, shortest);
        assert!(
            (got - want).abs() < 1e-9 * want,
            "r {ratio} ζ {zeta}: {got} vs {want} ({:.2e})",
            got / want - 1.0
        );
        // sharper: the linear interpolant's fundamental is the sine times sinc²(Ωh/2) ≈
        // 1 − (Ωh)²/12 (measured deficit 1.2e-10 to 1.4e-10); with that factor the two agree to
        // 2e-11 (the aliases near 2π/h are filtered out by the oscillator)
        let x = 0.5 * big_w * t_end / n as f64;
        let sinc2 = (x.sin() / x).powi(2);
        assert!(
            (got / (want * sinc2) - 1.0).abs() < 2e-11,
            "r {ratio} ζ {zeta}: {:.2e}",
            got / (want * sinc2) - 1.0
        );
    }
}
