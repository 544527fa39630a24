//! The exact velocity and displacement of a ground acceleration.
//!
//! A record is the piecewise-linear acceleration through its samples `(t_i, a_i)`, zero before
//! `t_0` and after `t_n` ([`Record::accel`]). Its velocity and displacement from rest at `t = 0`
//! are integrated exactly, with no baseline correction (a record whose velocity does not return
//! to zero leaves the ground drifting, as the record says): on `[t_i, t_{i+1}]`, with
//! `τ = t − t_i`, `Δ = t_{i+1} − t_i` and `s = (a_{i+1} − a_i)/Δ`,
//!
//! ```text
//! v(t) = v_i + a_i τ + s τ²/2,      u(t) = u_i + v_i τ + a_i τ²/2 + s τ³/6,
//! ```
//!
//! (`v`, `u` continuous, `v = u = 0` up to `t_0`); after the last sample `a = 0`,
//! `v = v_n`, `u = u_n + v_n (t − t_n)`.

use super::{GroundMotion, Record};
use crate::math::{Real, Vector};

/// The exact integral of one [`Record`] (module doc): the velocity and displacement at its
/// samples.
#[derive(Debug, Clone)]
pub struct RecordIntegral {
    record: Record,
    v: Vec<Real>,
    u: Vec<Real>,
}

impl RecordIntegral {
    /// Integrates `record`.
    pub fn new(record: &Record) -> Self {
        let (ts, a) = (record.times(), record.values());
        let mut v = Vec::with_capacity(ts.len());
        let mut u = Vec::with_capacity(ts.len());
        let (mut vi, mut ui) = (0.0, 0.0);
        v.push(vi);
        u.push(ui);
        for i in 0..ts.len() - 1 {
            let d = ts[i + 1] - ts[i];
            ui += vi * d + (2.0 * a[i] + a[i + 1]) * d * d / 6.0;
            vi += (a[i] + a[i + 1]) * d / 2.0;
            v.push(vi);
            u.push(ui);
        }
        Self {
            record: record.clone(),
            v,
            u,
        }
    }

    /// `(a, v, u)` at `t` (module doc).
    pub fn at(&self, t: Real) -> [Real; 3] {
        let (ts, a) = (self.record.times(), self.record.values());
        let n = ts.len() - 1;
        if t.is_nan() || t < ts[0] {
            return [0.0; 3];
        }
        if t >= ts[n] {
            let acc = if t == ts[n] { a[n] } else { 0.0 };
            return [acc, self.v[n], self.u[n] + self.v[n] * (t - ts[n])];
        }
        let i = ts.partition_point(|&ti| ti <= t).saturating_sub(1);
        let (tau, d) = (t - ts[i], ts[i + 1] - ts[i]);
        let s = (a[i + 1] - a[i]) / d;
        let acc = a[i] + s * tau;
        let v = self.v[i] + a[i] * tau + s * tau * tau / 2.0;
        let u = self.u[i] + self.v[i] * tau + a[i] * tau * tau / 2.0 + s * tau * tau * tau / 6.0;
        [acc, v, u]
    }
}

/// The exact kinematics of a [`GroundMotion`]: its two components integrated
/// ([`RecordIntegral`]), scaled and turned as the acceleration is.
#[derive(Debug, Clone)]
pub struct GroundKinematics {
    parts: Vec<(Vector, RecordIntegral)>,
}

impl GroundKinematics {
    /// The kinematics of `ground`.
    pub fn new(ground: &GroundMotion) -> Self {
        let (dy, dx) = ground.directions();
        let parts = [
            (&ground.along_y, dy * ground.scale_y),
            (&ground.along_x, dx * ground.scale_x),
        ]
        .into_iter()
        .filter_map(|(r, d)| r.as_ref().map(|r| (d, RecordIntegral::new(r))))
        .collect();
        Self { parts }
    }

    /// `(v, u)`: the ground's velocity and displacement at `t` (global frame) \[m/s, m\].
    pub fn velocity_displacement(&self, t: Real) -> (Vector, Vector) {
        self.parts
            .iter()
            .fold((Vector::zeros(), Vector::zeros()), |(v, u), (d, r)| {
                let [_, vi, ui] = r.at(t);
                (v + d * vi, u + d * ui)
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A constant acceleration from t = 0 integrates to `a t`, `a t²/2`; a ramp to `t²/2`,
    /// `t³/6`; the velocity and displacement are continuous across samples and after the last.
    #[test]
    fn closed_forms() {
        let c = Record::new("c", vec![0.0, 1.0, 2.0], vec![3.0, 3.0, 3.0]).unwrap();
        let ci = RecordIntegral::new(&c);
        for t in [0.0, 0.25, 1.0, 1.7, 2.0] {
            let [a, v, u] = ci.at(t);
            assert_eq!(a, 3.0);
            assert!(
                (v - 3.0 * t).abs() < 1e-14 && (u - 1.5 * t * t).abs() < 1e-14,
                "{t}"
            );
        }
        // after the end: a = 0, v constant, u linear
        let [a, v, u] = ci.at(3.0);
        assert_eq!(a, 0.0);
        assert!((v - 6.0).abs() < 1e-14 && (u - (6.0 + 6.0)).abs() < 1e-13);
        let r = Record::new("r", vec![0.0, 0.5, 1.0], vec![0.0, 0.5, 1.0]).unwrap();
        let ri = RecordIntegral::new(&r);
        for t in [0.1, 0.5, 0.9, 1.0] {
            let [_, v, u] = ri.at(t);
            assert!((v - t * t / 2.0).abs() < 1e-15 && (u - t * t * t / 6.0).abs() < 1e-15);
        }
        // a record that starts late: nothing before it
        let late = Record::new("l", vec![2.0, 3.0], vec![1.0, 1.0]).unwrap();
        assert_eq!(RecordIntegral::new(&late).at(1.5), [0.0; 3]);
        let [_, v, u] = RecordIntegral::new(&late).at(2.5);
        assert!((v - 0.5).abs() < 1e-15 && (u - 0.125).abs() < 1e-15);
    }

    /// The exact integral of El Centro agrees with a fine trapezoid integration of the
    /// interpolated acceleration.
    #[test]
    fn agrees_with_fine_quadrature() {
        let g = crate::ground_motion::el_centro_1940();
        let rec = g.along_y.clone().unwrap();
        let ri = RecordIntegral::new(&rec);
        let (h, n) = (1e-4, 100_000); // 10 s
        let (mut v, mut u, mut a0) = (0.0, 0.0, rec.accel(0.0));
        for k in 1..=n {
            let t = k as Real * h;
            let a1 = rec.accel(t);
            let v1 = v + 0.5 * h * (a0 + a1);
            u += 0.5 * h * (v + v1);
            v = v1;
            a0 = a1;
        }
        let [_, ve, ue] = ri.at(n as Real * h);
        assert!((ve - v).abs() < 1e-6 * ve.abs().max(0.1), "{ve} {v}");
        assert!((ue - u).abs() < 1e-6 * ue.abs().max(0.1), "{ue} {u}");
        let k = GroundKinematics::new(&g);
        let (vv, uu) = k.velocity_displacement(n as Real * h);
        assert!((vv.y - ve).abs() < 1e-15 && (uu.y - ue).abs() < 1e-15);
        assert!(vv.x != 0.0, "the x component moves too");
    }
}
