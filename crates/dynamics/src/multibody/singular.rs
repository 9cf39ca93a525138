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

/// x > floor, false for NaN.
#[inline(always)]
fn above(x: f64, floor: f64) -> bool {
    x.partial_cmp(&floor) == Some(core::cmp::Ordering::Greater)
}

/// The Cholesky factor D = L Lᵀ (L lower triangular) of a symmetric 3×3 D (its lower triangle
/// read), unrolled, when every pivot l_kk² is above `floor` (else `None`): the same factor as
/// nalgebra's `cholesky` (l_kk = √(d_kk − Σ l_kj²), l_ik = (d_ik − Σ l_ij l_kj)/l_kk), without
/// its loops over a dynamic dimension; smooth in D, so dual numbers carry exact derivatives.
///
/// Book: §7.11 (the joint's D of the articulated-body algorithm); RBDA §7.3.
#[inline(always)]
pub(crate) fn spd_cholesky3<T: Scalar>(d: &Matrix3<T>, floor: f64) -> Option<Matrix3<T>> {
    let p0 = d[(0, 0)];
    if !above(p0.re(), floor) {
        return None;
    }
    let l00 = p0.sqrt();
    let (l10, l20) = (d[(1, 0)] / l00, d[(2, 0)] / l00);
    let p1 = d[(1, 1)] - l10 * l10;
    if !above(p1.re(), floor) {
        return None;
    }
    let l11 = p1.sqrt();
    let l21 = (d[(2, 1)] - l20 * l10) / l11;
    let p2 = d[(2, 2)] - l20 * l20 - l21 * l21;
    if !above(p2.re(), floor) {
        return None;
    }
    let z = T::zero();
    Some(Matrix3::new(l00, z, z, l10, l11, z, l20, l21, p2.sqrt()))
}

/// D⁻¹ of a symmetric 3×3 D (its lower triangle read) by its Cholesky factor D = L Lᵀ
/// ([`spd_cholesky3`]) when every pivot l_kk² is above `floor` (else `None`: the caller's
/// rank-revealing path): L⁻¹ = M in closed form and D⁻¹ = Mᵀ M, without nalgebra's inverse by
/// six triangular solves.
///
/// Book: §7.11 (the joint's D of the articulated-body algorithm); RBDA §7.3.
#[inline(always)]
pub(crate) fn spd_inverse3<T: Scalar>(d: &Matrix3<T>, floor: f64) -> Option<Matrix3<T>> {
    let l = spd_cholesky3(d, floor)?;
    let (l00, l10, l20, l11, l21, l22) = (l[(0, 0)], l[(1, 0)], l[(2, 0)], l[(1, 1)], l[(2, 1)], l[(2, 2)]);
    // M = L⁻¹, lower triangular
    let (m00, m11, m22) = (T::one() / l00, T::one() / l11, T::one() / l22);
    let m10 = -(l10 * m00) * m11;
    let m21 = -(l21 * m11) * m22;
    let m20 = -(l20 * m00 + l21 * m10) * m22;
    // D⁻¹ = Mᵀ M
    let (a00, a11, a22) = (m00 * m00 + m10 * m10 + m20 * m20, m11 * m11 + m21 * m21, m22 * m22);
    let (a10, a20, a21) = (m11 * m10 + m21 * m20, m22 * m20, m22 * m21);
    Some(Matrix3::new(a00, a10, a20, a10, a11, a21, a20, a21, a22))
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

    /// The unrolled Cholesky inverse: D D⁻¹ = 1 to rounding (relative to κ(D)) for definite D
    /// from round to very flat; `None` for a semidefinite D (a particle's rank-2 inertia) and
    /// for pivots at the floor; and the derivative a dual number carries is −D⁻¹ Ḋ D⁻¹.
    #[test]
    fn spd_inverse3_inverts_definite_and_refuses_semidefinite() {
        let r = nalgebra::Rotation3::from_euler_angles(0.3, -1.1, 2.0);
        for (a, b, c) in [(1.0f64, 1.0f64, 1.0f64), (2.0, 1.5, 1.1), (1.0, 1e-3, 1e-6), (1e6, 1.0, 1e-2)] {
            let d = r.matrix() * Matrix3::from_diagonal(&Vector3::new(a, b, c)) * r.matrix().transpose();
            let inv = spd_inverse3(&d, 0.0).expect("definite");
            let cond = a.max(b).max(c) / a.min(b).min(c);
            let err = (d * inv - Matrix3::identity()).abs().max();
            assert!(err <= 16.0 * f64::EPSILON * cond, "{a} {b} {c}: {err:e}");
            assert!((inv - inv.transpose()).abs().max() == 0.0);
        }
        let e = Vector3::new(0.3, -0.4, 0.5).normalize();
        let particle = (Matrix3::identity() - e * e.transpose()) * 2.5;
        assert!(spd_inverse3(&particle, 1e-12).is_none());
        assert!(spd_inverse3(&Matrix3::<f64>::identity(), 1.0).is_none());
        assert!(spd_inverse3(&Matrix3::<f64>::from_element(f64::NAN), 0.0).is_none());
        // d(D⁻¹)/dt = −D⁻¹ Ḋ D⁻¹ through dual numbers
        use num_dual::Dual64;
        let d0 = Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.1);
        let dd = Matrix3::new(0.5, -0.2, 0.1, -0.2, 0.3, 0.05, 0.1, 0.05, -0.4);
        let dual = Matrix3::from_fn(|i, j| Dual64::new(d0[(i, j)], dd[(i, j)]));
        let inv = spd_inverse3(&dual, 0.0).expect("definite");
        let i0 = spd_inverse3(&d0, 0.0).unwrap();
        let want = -(i0 * dd * i0);
        for i in 0..3 {
            for j in 0..3 {
                // num-dual divides by multiplying with the reciprocal: a few ulps apart
                assert!((inv[(i, j)].re - i0[(i, j)]).abs() <= 8.0 * f64::EPSILON * i0.abs().max());
                assert!((inv[(i, j)].eps - want[(i, j)]).abs() <= 1e-14, "{i}{j}");
            }
        }
    }

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
