//! Type aliases over `nalgebra` and planar helpers (in the manner of parry's `math` module).
//!
//! Conventions (spec §1): SI units, angles in radians, counter-clockwise rotations positive about +z,
//! scalar cross product `a × b := a_x b_y − a_y b_x`.

/// The scalar type used everywhere.
pub type Real = f64;
/// A plane vector `(x, y)` in metres (positions, lever arms) or m/s (velocities).
pub type Vector = nalgebra::Vector2<Real>;
/// A 2×2 matrix (e.g. the single-contact Delassus matrix `[[G_NN, G_NT], [G_TN, G_TT]]`).
pub type Matrix2 = nalgebra::Matrix2<Real>;

/// Scalar (z-component of the) cross product `a × b = a_x b_y − a_y b_x`.
#[inline]
pub fn cross(a: &Vector, b: &Vector) -> Real {
    a.x * b.y - a.y * b.x
}

/// `Rot(φ) v`: the vector `v` turned counter-clockwise by `phi` radians.
#[inline]
pub fn rotate(v: &Vector, phi: Real) -> Vector {
    let (s, c) = phi.sin_cos();
    Vector::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// `ẑ × v = (−v_y, v_x)`: the vector turned by +90°.
#[inline]
pub fn perp(v: &Vector) -> Vector {
    Vector::new(-v.y, v.x)
}
