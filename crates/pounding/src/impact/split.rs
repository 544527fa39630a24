//! The minimum-norm tangential split of an impact whose tangential impulses are not unique.
//!
//! With the normal impulses `Λ_N` and the post-impact velocities fixed, the tangential impulses
//! of the slipping contacts are fixed too (`Λ_T = −μ Λ_N sign γ_T⁺`), while those of the sticking
//! contacts `S` may move along the null space of their columns: every
//!
//! ```text
//! x ∈ { x : W_S x = W_S Λ_T,S ,  |x_i| ≤ μ_i Λ_N,i }      (W_S x = 0 ⇔ G_SS x = 0, G_SS = W_Sᵀ M⁻¹ W_S)
//! ```
//!
//! gives the same velocities and satisfies Coulomb's law, so it is a solution as good as Lemke's
//! (which returns a vertex of that set: an arbitrary extreme, e.g. all the friction at one of two
//! symmetric contacts). The one reported is the point of smallest Euclidean norm: the projection
//! `x* = x₀ − P x₀` of the origin onto the affine set (`P` the orthogonal projector onto
//! `null G_SS`, from its eigenvectors with eigenvalues `≤ 1e-10 λ_max`), or, when `x*` leaves the
//! friction box, the projection of the origin onto the intersection by Dykstra's algorithm. For
//! two symmetric contacts it is the equal split.

use crate::math::Real;
use nalgebra::{DMatrix, SymmetricEigen};

/// Relative tolerance of the null space and of the box test.
const TOL: Real = 1e-10;

/// Replaces the sticking tangential impulses `lt` (with bounds `b = μ Λ_N > 0`) by the
/// minimum-norm point of their solution set, given the tangential Delassus block `g_ss`
/// (`s × s`, row-major). Returns whether the split was unique (then `lt` is unchanged).
pub(super) fn min_norm_split(g_ss: &[Real], lt: &mut [Real], b: &[Real]) -> bool {
    let s = lt.len();
    if s == 0 {
        return true;
    }
    let eig = SymmetricEigen::new(DMatrix::from_row_slice(s, s, g_ss));
    let lmax = eig
        .eigenvalues
        .iter()
        .fold(0.0, |m: Real, &x| m.max(x.abs()));
    let null: Vec<Vec<Real>> = (0..s)
        .filter(|&k| eig.eigenvalues[k] <= TOL * lmax || lmax == 0.0)
        .map(|k| eig.eigenvectors.column(k).iter().copied().collect())
        .collect();
    if null.is_empty() || !movable(lt, b, &null) {
        return true;
    }
    let x0 = lt.to_vec();
    // projection onto the affine set x0 + null(G_SS)
    let affine = |y: &[Real]| -> Vec<Real> {
        let mut out = x0.clone();
        for v in &null {
            let c: Real = v
                .iter()
                .zip(y.iter().zip(&x0))
                .map(|(v, (y, x))| v * (y - x))
                .sum();
            for (o, vi) in out.iter_mut().zip(v) {
                *o += c * vi;
            }
        }
        out
    };
    let clamp =
        |y: &[Real]| -> Vec<Real> { y.iter().zip(b).map(|(y, b)| y.clamp(-b, *b)).collect() };
    let bscale = b.iter().fold(0.0, |m: Real, &x| m.max(x));
    let in_box = |y: &[Real]| y.iter().zip(b).all(|(y, b)| y.abs() <= b + TOL * bscale);
    let mut x = affine(&vec![0.0; s]);
    if !in_box(&x) {
        // Dykstra: alternating projections with corrections converge to the projection of the
        // starting point (the origin) onto the intersection.
        let (mut p, mut q) = (vec![0.0; s], vec![0.0; s]);
        let mut z = vec![0.0; s];
        for _ in 0..100_000 {
            let zp: Vec<Real> = z.iter().zip(&p).map(|(a, b)| a + b).collect();
            let y = affine(&zp);
            p = zp.iter().zip(&y).map(|(a, b)| a - b).collect();
            let yq: Vec<Real> = y.iter().zip(&q).map(|(a, b)| a + b).collect();
            let zn = clamp(&yq);
            q = yq.iter().zip(&zn).map(|(a, b)| a - b).collect();
            let step = zn
                .iter()
                .zip(&z)
                .fold(0.0, |m: Real, (a, b)| m.max((a - b).abs()));
            z = zn;
            if step <= 1e-15 * bscale {
                break;
            }
        }
        // keep the velocities exact: the affine projection of the limit
        x = affine(&z);
    }
    // an impulse below the rounding of the projection (e.g. −1.5e-11 N s beside 5e4 N s for a
    // zero split) is zero
    let xscale = x0.iter().fold(0.0, |m: Real, &v| m.max(v.abs()));
    for xi in &mut x {
        if xi.abs() <= 64.0 * Real::EPSILON * xscale {
            *xi = 0.0;
        }
    }
    lt.copy_from_slice(&x);
    false
}

/// Whether the point `x` can move inside its solution set: some direction `v ∈ null G_SS`
/// (spanned by `null`) keeps every bound `|x_i| ≤ b_i` that `x` touches. With more null
/// directions than touched bounds one always exists; otherwise the basis directions `±v` are
/// tried (a cone spanned only by their combinations is not detected: the split is then reported
/// unique and left as solved).
fn movable(x: &[Real], b: &[Real], null: &[Vec<Real>]) -> bool {
    let bscale = b.iter().fold(0.0, |m: Real, &x| m.max(x));
    let active: Vec<usize> = (0..x.len())
        .filter(|&i| x[i].abs() >= b[i] - TOL * bscale)
        .collect();
    if null.len() > active.len() {
        return true;
    }
    null.iter().any(|v| {
        [1.0, -1.0].iter().any(|sign: &Real| {
            let moves = v.iter().any(|vi| vi.abs() > TOL);
            moves && active.iter().all(|&i| sign * v[i] * x[i].signum() <= TOL)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::min_norm_split;

    /// Two identical columns (G_SS = [[g, g], [g, g]]): any split of the sum; the equal one.
    #[test]
    fn identical_columns_give_the_equal_split() {
        let g = [2.0, 2.0, 2.0, 2.0];
        let mut lt = [3.0, -1.0];
        assert!(!min_norm_split(&g, &mut lt, &[5.0, 5.0]));
        assert!(
            (lt[0] - 1.0).abs() < 1e-14 && (lt[1] - 1.0).abs() < 1e-14,
            "{lt:?}"
        );
        // a tight bound on one contact: the rest goes to the other (Dykstra)
        let mut lt = [3.0, 1.0];
        assert!(!min_norm_split(&g, &mut lt, &[0.5, 5.0]));
        assert!(
            (lt[0] - 0.5).abs() < 1e-9 && (lt[1] - 3.5).abs() < 1e-9,
            "{lt:?}"
        );
        assert!((lt[0] + lt[1] - 4.0).abs() < 1e-12);
    }

    /// A regular block or a split pinned by its bounds is unique and left untouched.
    #[test]
    fn unique_splits_are_unchanged() {
        let mut lt = [3.0, -1.0];
        assert!(min_norm_split(&[2.0, 0.5, 0.5, 1.0], &mut lt, &[5.0, 5.0]));
        assert_eq!(lt, [3.0, -1.0]);
        let mut lt = [2.0, 2.0];
        assert!(min_norm_split(&[1.0, 1.0, 1.0, 1.0], &mut lt, &[2.0, 2.0]));
        assert_eq!(lt, [2.0, 2.0]);
    }
}
