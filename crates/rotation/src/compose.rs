//! Composition in every representation, with the book's frame order (book §2.10, §2.11,
//! §2.15, §2.17, §2.19). Arguments come in subscript order: (C/B, B/A) ↦ C/A.

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::{Scalar, Vector, wrap_angle};

use crate::series::wrap_near;

use crate::{EulerAngles, EulerSequence, EulerSolution, Quaternion};

/// 𝓞_{C/A} = 𝓞_{C/B} 𝓞_{B/A} (2.10.45).
///
/// Book: (2.10.45).
#[inline]
pub fn compose_orientation<T: Scalar>(o_cb: &Matrix3<T>, o_ba: &Matrix3<T>) -> Matrix3<T> {
    o_cb * o_ba
}

/// 𝓡_{C/A} = 𝓡_{B/A} 𝓡_{C/B} (2.10.46): the resolved rotation matrices compose in reverse.
///
/// Book: (2.10.46).
#[inline]
pub fn compose_rotation_matrix<T: Scalar>(r_cb: &Matrix3<T>, r_ba: &Matrix3<T>) -> Matrix3<T> {
    r_ba * r_cb
}

/// q_{C/A} = ±q_{B/A} ⊗ q_{C/B}, canonical η ≥ 0.
///
/// Book: F2.15.7. **Erratum**: the printed (2.15.34) q_{C/A} = Q(q_{C/B}) q_{B/A} is wrong
/// (it holds only with ε_{C/B} resolved in A); the book's own definitions give
/// q_{B/A} ⊗ q_{C/B} (notes ch2b §2, checked against (2.17.11)).
#[inline]
pub fn compose_quaternion<T: Scalar>(q_cb: &Quaternion<T>, q_ba: &Quaternion<T>) -> Quaternion<T> {
    (*q_ba * *q_cb).canonical()
}

/// g_{C/A} = (g_{C/B} + g_{B/A} − g_{C/B} × g_{B/A}) / (1 − g_{C/B}·g_{B/A}) (2.17.11);
/// `None` when the denominator vanishes (θ_{C/A} = π, no Gibbs vector).
///
/// Book: F2.17.3, (2.17.11) (correct as printed).
#[inline]
pub fn compose_gibbs<T: Scalar>(g_cb: &Vector3<T>, g_ba: &Vector3<T>) -> Option<Vector3<T>> {
    let den = T::one() - g_cb.dot(g_ba);
    (den != T::zero()).then(|| (g_cb + g_ba - g_cb.cross(g_ba)) / den)
}

/// MRP composition p_{C/A} through the Euler parameters (η ≥ 0, so |p| ≤ 1).
///
/// Book: extends §2.17.
#[inline]
pub fn compose_mrp<T: Scalar>(p_cb: &Vector3<T>, p_ba: &Vector3<T>) -> Vector3<T> {
    compose_quaternion(&Quaternion::from_mrp(p_cb), &Quaternion::from_mrp(p_ba)).mrp()
}

/// Angle-vector composition Θ_{C/A} = log(exp Θ_{B/A} exp Θ_{C/B}) (F2.14.3: angle vectors do
/// not add, except about a common axis, see [`compose_coplanar`]).
///
/// Book: F2.14.3.
#[inline]
pub fn compose_angle_vector<T: Scalar>(th_cb: &Vector3<T>, th_ba: &Vector3<T>) -> Vector3<T> {
    compose_quaternion(&Quaternion::from_angle_vector(th_cb), &Quaternion::from_angle_vector(th_ba))
        .angle_vector()
}

/// Euler-angle composition: the angles of `sequence` of R_{C/A} from those of R_{C/B} and
/// R_{B/A} (each in its own sequence).
///
/// Book: §2.12–2.13 with F2.15.7 (corrected).
pub fn compose_euler<T: Scalar>(
    e_cb: &EulerAngles<T>,
    e_ba: &EulerAngles<T>,
    sequence: EulerSequence,
) -> EulerSolution<T> {
    EulerAngles::from_quaternion(&compose_quaternion(&e_cb.quaternion(), &e_ba.quaternion()), sequence)
}

/// Additivity of coplanar angle vectors (F2.19.1): for parallel Θ⃗₁, Θ⃗₂ (about a common axis
/// n̂), R_{n̂}(θ₁)R_{n̂}(θ₂) = R_{n̂}(θ₁ + θ₂), so the composed angle vector is n̂·wrap(θ₁ + θ₂),
/// exact. `None` when the vectors are not parallel within `tol` (|Θ₁×Θ₂| > tol|Θ₁||Θ₂|), when
/// an input is not finite, or when `tol` is NaN, infinite or negative.
///
/// Book: §2.19, F2.19.1, F2.19.3.
pub fn compose_coplanar<T: Scalar>(th_2: &Vector<T>, th_1: &Vector<T>, tol: f64) -> Option<Vector<T>> {
    vectrix_tensor::check_tolerance(tol, "tol").ok()?;
    let (n2, n1) = (th_2.norm(), th_1.norm());
    if th_2.cross(th_1).norm().re() > tol * (n2 * n1).re() {
        return None;
    }
    let Some(n) = th_2.unit().or_else(|| th_1.unit()) else {
        return Some(Vector::zero());
    };
    // Signed angles about n̂, added and wrapped into (−π, π].
    let sum = n.dot(th_2) + n.dot(th_1);
    // One shift suffices below 3π (and stays smooth for dual numbers); beyond, the general wrap.
    let sum = if sum.re().abs() < 3.0 * core::f64::consts::PI { wrap_near(sum) } else { wrap_angle(sum) };
    // Non-finite input (or a sum of angles beyond f64::MAX) has no composed angle: None.
    let out = n * sum;
    out.is_finite().then_some(out)
}
