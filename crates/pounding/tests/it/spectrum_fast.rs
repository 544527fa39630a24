//! The fast path of `pounding::spectrum::peak_displacement` (cached coefficients per interval
//! length, bisection only where a rigorous bound says it can raise the peak) against the plain
//! search (`peak_displacement_reference`: every coefficient recomputed, every bracketed zero of
//! `u̇` bisected): the same bits on random records, uniform and irregular, over periods that
//! reach the series form (`ωh < 10⁻³`) and the long-interval form (`h ≥ 64 T_d`).

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
fn spectrum_fast_path_equals_the_plain_search_bit_for_bit() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let mut cases = 0;
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
        assert_eq!(
            fast.to_bits(),
            plain.to_bits(),
            "T = {period}, ζ = {damping}, n = {}: fast {fast} vs plain {plain}",
            t.len()
        );
        assert!(fast > 0.0 || a.iter().all(|&x| x == 0.0));
        cases += 1;
    }
    assert_eq!(cases, 400);
}

#[test]
fn spectrum_fast_path_equals_the_plain_search_on_the_default_periods() {
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
            assert_eq!(
                fast.to_bits(),
                plain.to_bits(),
                "T = {period}, ζ = {damping}"
            );
        }
    }
}
