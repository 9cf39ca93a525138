//! Pseudo-inverses of the small joint-space articulated inertias Dᵢ = SᵢᵀIᴬᵢSᵢ that are only
//! positive semidefinite: a joint direction n with Dᵢn = 0 carries no inertia (Iᴬᵢ Sᵢ n = 0,
//! because Iᴬᵢ is PSD), so it couples to nothing and is given zero acceleration.
//!
//! Book: §7.11 (ABA); the minimum-norm solution of the singular joint equation.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::Scalar;

/// Rounding tolerance, as a multiple of ε (of the scalar: f64's, or f32's for `Model<f32>`) times the scale of the joint's block of the
/// subtree's composite inertia, below which a pivot of Dᵢ counts as zero (Dᵢ comes from
/// sums and Schur complements of the subtree's inertias, whose rounding is a few ε of that
/// scale per level; 64 leaves room for deep trees). The same factor times the size of the
/// forces meeting at the joint bounds the rounding of a generalized force along an inert
/// direction.
pub(crate) const PIVOT_EPS: f64 = 64.0;

/// [`PIVOT_EPS`] ε of the scalar T.
#[inline(always)]
pub(crate) fn pivot_tol<T: Scalar>() -> f64 {
    PIVOT_EPS * T::eps()
}

/// D⁺ and the projector onto the null space of D for a symmetric PSD 3×3 D, by Cholesky with
/// complete pivoting stopped at the first pivot ≤ `tol` (rank-revealing): D = G Gᵀ with G of
/// full column rank r, D⁺ = G (GᵀG)⁻² Gᵀ, and 1 − G (GᵀG)⁻¹ Gᵀ projects onto null(D). Pivot
/// choices use the real part; the arithmetic is smooth in D, so dual numbers carry exact
/// derivatives while the rank stays constant.
pub(crate) fn psd_pinv3<T: Scalar>(d: &Matrix3<T>, tol: f64) -> (Matrix3<T>, Matrix3<T>, usize) {
    let mut a = *d;
    let mut perm = [0usize, 1, 2];
    let mut l = Matrix3::<T>::zeros();
    let mut rank = 0;
    for k in 0..3 {
        // pivot: the largest remaining diagonal entry of the Schur complement
        let (mut j, mut best) = (k, a[(k, k)].re());
        for i in k + 1..3 {
            if a[(i, i)].re() > best {
                (j, best) = (i, a[(i, i)].re());
            }
        }
        if best.partial_cmp(&tol) != Some(std::cmp::Ordering::Greater) {
            break;
        }
        if j != k {
            a.swap_rows(k, j);
            a.swap_columns(k, j);
            l.swap_rows(k, j);
            perm.swap(k, j);
        }
        let p = a[(k, k)].sqrt();
        l[(k, k)] = p;
        for i in k + 1..3 {
            l[(i, k)] = a[(i, k)] / p;
        }
        for i in k + 1..3 {
            for c in k + 1..3 {
                a[(i, c)] -= l[(i, k)] * l[(c, k)];
            }
        }
        rank = k + 1;
    }
    // G = P L (rows back in the original order), columns ≥ rank are zero
    let mut g = Matrix3::<T>::zeros();
    for i in 0..3 {
        for c in 0..rank {
            g[(perm[i], c)] = l[(i, c)];
        }
    }
    // K = GᵀG on the leading r×r block, identity on the rest (so it is invertible)
    let mut k = g.tr_mul(&g);
    for c in rank..3 {
        k[(c, c)] = T::one();
    }
    let kinv = k.try_inverse().unwrap_or_else(Matrix3::zeros);
    let gk = g * kinv;
    let pinv = gk * gk.transpose();
    let null = Matrix3::identity() - gk * g.transpose();
    (pinv, null, rank)
}

/// |P_N u|: the size of the generalized force along the inert directions.
pub(crate) fn null_component<T: Scalar>(null: &Matrix3<T>, u: &Vector3<T>) -> f64 {
    (null * u).map(|x| x.re()).norm()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rank 2 (a particle at distance L from a ball joint: D = m L² (1 − ê êᵀ)): D D⁺ D = D,
    /// D⁺ annihilates ê, and the projector is ê êᵀ.
    #[test]
    fn rank_two_particle_inertia() {
        let e = Vector3::new(0.3, -0.4, 0.5).normalize();
        let d = (Matrix3::identity() - e * e.transpose()) * 2.5;
        let (pinv, null, rank) = psd_pinv3(&d, 1e-12);
        assert_eq!(rank, 2);
        assert!((d * pinv * d - d).norm() < 1e-14);
        assert!((pinv * e).norm() < 1e-15);
        assert!((null - e * e.transpose()).norm() < 1e-15);
        // the pseudo-inverse on range(D) is 1/2.5
        let x = Vector3::new(1.0, 2.0, 3.0);
        let xr = x - e * e.dot(&x);
        assert!((pinv * xr - xr / 2.5).norm() < 1e-15);
    }

    /// Rank 0 and full rank.
    #[test]
    fn rank_zero_and_three() {
        let (pinv, null, rank) = psd_pinv3(&Matrix3::<f64>::zeros(), 1e-12);
        assert_eq!((rank, pinv, null), (0, Matrix3::zeros(), Matrix3::identity()));
        let d = Matrix3::new(4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0);
        let (pinv, null, rank) = psd_pinv3(&d, 1e-12);
        assert_eq!(rank, 3);
        assert!((pinv * d - Matrix3::identity()).norm() < 1e-15 * 8.0);
        assert!(null.norm() < 1e-15 * 8.0);
    }
}
