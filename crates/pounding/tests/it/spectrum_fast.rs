//! The fast path of `pounding::spectrum::peak_displacement` (the Nigam–Jennings recurrence as a
//! matrix with rows per interval length, bisection only where a rigorous bound says it can raise
//! the peak) against the plain search (`peak_displacement_reference`: the piece form, transient
//! plus particular solution, on every interval, every bracketed zero of `u̇` bisected): two
//! formulations of the same exact solution agree to rounding on random records, uniform and
//! irregular, over periods that reach the series form (`ωh < 10⁻³`) and the long-interval form
//! (`h ≥ 64 T_d`).

use pounding::spectrum::{peak_displacement, peak_displacement_reference};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A random record: `n` samples, uniform (`i·dt`) or with random intervals, values a random
/// walk with occasional spikes and flat stretches (peaks at samples, constant loads).
fn random_record(rng: &mut ChaCha8Rng) -> (Vec<f64>, Vec<f64>) {
    let n = rng.random_range(2..600);
    let uniform = rng.random_bool(0.6);
    let dt = [0.005, 0.01, 0.02, 0.0123][rng.random_range(0..4)];
    let mut t = Vec::with_capacity(n);
    let mut a = Vec::with_capacity(n);
    let (mut s, mut x) = (rng.random_range(-5.0..5.0), 0.0);
    for i in 0..n {
        t.push(if uniform { i as f64 * dt } else { s });
        s += dt * rng.random_range(0.05..3.0);
        x = match rng.random_range(0..10) {
            0 => rng.random_range(-20.0..20.0),
            1 | 2 => x,
            _ => x + rng.random_range(-1.0..1.0),
        };
        a.push(x);
    }
    (t, a)
}

#[test]
fn spectrum_fast_path_agrees_with_the_plain_search() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let (mut cases, mut worst) = (0, 0.0f64);
    for _ in 0..400 {
        let (t, a) = random_record(&mut rng);
        let period = 10f64.powf(rng.random_range(-4.5..2.5));
        let damping = if rng.random_bool(0.2) {
            0.0
        } else {
            rng.random_range(0.0..0.5)
        };
        let fast = peak_displacement(&t, &a, period, damping);
        let plain = peak_displacement_reference(&t, &a, period, damping);
        // the piece form rounds up to ~ε (ωh)⁻² per step relative (its doc); both are the
        // exact solution to that
        let rel = (fast - plain).abs() / plain.abs().max(1e-300);
        worst = worst.max(rel);
        assert!(
            rel < 1e-8,
            "T = {period}, ζ = {damping}, n = {}: fast {fast} vs plain {plain}",
            t.len()
        );
        assert!(fast > 0.0 || a.iter().all(|&x| x == 0.0));
        cases += 1;
    }
    assert_eq!(cases, 400);
    eprintln!("largest relative difference: {worst:e}");
}

#[test]
fn spectrum_fast_path_agrees_with_the_plain_search_on_the_default_periods() {
    // a 20 s uniform record at dt = 0.01 s, every default period and three dampings
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let t: Vec<f64> = (0..2001).map(|i| i as f64 * 0.01).collect();
    let mut x = 0.0;
    let a: Vec<f64> = t
        .iter()
        .map(|_| {
            x = 0.9 * x + rng.random_range(-1.0..1.0);
            x
        })
        .collect();
    for damping in [0.0, 0.02, 0.05] {
        for period in pounding::spectrum::default_periods() {
            let fast = peak_displacement(&t, &a, period, damping);
            let plain = peak_displacement_reference(&t, &a, period, damping);
            assert!(
                (fast - plain).abs() <= 1e-12 * plain,
                "T = {period}, ζ = {damping}: fast {fast} vs plain {plain}"
            );
        }
    }
}
