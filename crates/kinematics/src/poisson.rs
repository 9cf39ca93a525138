//! Angular velocity from orientation rates: Poisson's equation (book §4.3) and axis rates.

use nalgebra::{Matrix3, Vector3};
use vectrix_frames::Frame;
use vectrix_tensor::{Scalar, Vector};

use crate::KinematicsError;

/// vee of the skew part of a 3×3 matrix: the vector w with w^× = ½(M − Mᵀ).
pub(crate) fn vee<T: Scalar>(m: &Matrix3<T>) -> Vector3<T> {
    let h = T::lit(0.5);
    Vector3::new((m[(2, 1)] - m[(1, 2)]) * h, (m[(0, 2)] - m[(2, 0)]) * h, (m[(1, 0)] - m[(0, 1)]) * h)
}

fn finite_matrix<T: Scalar>(m: &Matrix3<T>, what: &'static str) -> Result<(), KinematicsError> {
    if m.iter().all(|x| x.re().is_finite()) { Ok(()) } else { Err(KinematicsError::NonFinite { what }) }
}

/// ω_{B/A}|_B from 𝓞_{B/A} and its time derivative: ω^×_{B/A|B} = −𝓞̇_{B/A} 𝓞_{A/B} (4.3.20).
///
/// The skew part is taken, so a finite-difference 𝓞̇ (whose product is not exactly skew) still
/// gives the best angular velocity.
///
/// Book: Fact 4.3.6, (4.3.19–20).
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_body_from_orientation_rate<T: Scalar>(
    o_b_a: &Matrix3<T>,
    o_b_a_dot: &Matrix3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    finite_matrix(o_b_a, "𝓞_{B/A}")?;
    finite_matrix(o_b_a_dot, "d𝓞_{B/A}/dt")?;
    // (4.3.20): ω^×_{B/A|B} = −𝓞̇_{B/A} 𝓞_{A/B}
    crate::finite_or_overflow!(vee(&(-(o_b_a_dot * o_b_a.transpose()))), "ω from Ȯ")
}

/// α_{B/A}|_B from 𝓞_{B/A} and its second derivative: differentiating (4.3.20),
/// α^×_{B/A|B} = skew(−𝓞̈_{B/A} 𝓞_{A/B}) (the term 𝓞̇𝓞̇ᵀ is symmetric and drops out).
///
/// Book: (4.3.20), (4.4.6).
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn alpha_body_from_orientation_rates<T: Scalar>(
    o_b_a: &Matrix3<T>,
    o_b_a_ddot: &Matrix3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    finite_matrix(o_b_a, "𝓞_{B/A}")?;
    finite_matrix(o_b_a_ddot, "d²𝓞_{B/A}/dt²")?;
    // (4.4.6): α|_B = d/dt ω|_B; d/dt(−𝓞̇𝓞ᵀ) = −𝓞̈𝓞ᵀ − 𝓞̇𝓞̇ᵀ, the last term symmetric
    crate::finite_or_overflow!(vee(&(-(o_b_a_ddot * o_b_a.transpose()))), "α from Ö")
}

/// ω_{B/A}|_A from 𝓡_{B/A} and its time derivative: ω^×_{B/A|A} = 𝓡̇_{B/A} 𝓡_{A/B}.
///
/// Book: (4.3.17), (4.3.20).
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn omega_spatial_from_rotation_rate<T: Scalar>(
    r_b_a: &Matrix3<T>,
    r_b_a_dot: &Matrix3<T>,
) -> Result<Vector3<T>, KinematicsError> {
    finite_matrix(r_b_a, "𝓡_{B/A}")?;
    finite_matrix(r_b_a_dot, "d𝓡_{B/A}/dt")?;
    crate::finite_or_overflow!(vee(&(r_b_a_dot * r_b_a.transpose())), "ω from Ṙ")
}

/// Poisson's equation in body form: 𝓡̇_{B/A} = 𝓡_{B/A} ω^×_{B/A|B} (4.3.17).
///
/// Book: Fact 4.3.6, (4.3.17); equivalently 𝓞̇_{B/A} = −ω^×_{B/A|B} 𝓞_{B/A} (4.3.19).
#[doc(alias = "dcm_rate")]
pub fn poisson_rate<T: Scalar>(r_b_a: &Matrix3<T>, omega_b_a_in_b: &Vector3<T>) -> Matrix3<T> {
    r_b_a * omega_b_a_in_b.cross_matrix()
}

/// Poisson's equation in spatial form: 𝓡̇_{B/A} = ω^×_{B/A|A} 𝓡_{B/A}.
///
/// Book: (4.3.17) with ω_{B/A|A} = 𝓡_{B/A} ω_{B/A|B}.
pub fn poisson_rate_spatial<T: Scalar>(r_b_a: &Matrix3<T>, omega_b_a_in_a: &Vector3<T>) -> Matrix3<T> {
    omega_b_a_in_a.cross_matrix() * r_b_a
}

/// ω⃗_{B/A} from the A-frame derivatives of B's axes:
/// ω⃗_{B/A} = ½(î_B × î_B^{A•} + ĵ_B × ĵ_B^{A•} + k̂_B × k̂_B^{A•}).
///
/// Book: P4.20.5, from ê^{A•}_B = ω⃗_{B/A} × ê_B (4.3.13–15).
pub fn omega_from_axis_rates<T: Scalar>(
    b: &Frame<T>,
    i_dot: &Vector<T>,
    j_dot: &Vector<T>,
    k_dot: &Vector<T>,
) -> Vector<T> {
    (b.i().cross(i_dot) + b.j().cross(j_dot) + b.k().cross(k_dot)) * T::lit(0.5)
}

/// The projection form of P4.20.5:
/// ω⃗_{B/A} = (ĵ_B^{A•}·k̂_B) î_B + (k̂_B^{A•}·î_B) ĵ_B + (î_B^{A•}·ĵ_B) k̂_B.
///
/// Book: P4.20.5.
pub fn omega_from_axis_rates_projections<T: Scalar>(
    b: &Frame<T>,
    i_dot: &Vector<T>,
    j_dot: &Vector<T>,
    k_dot: &Vector<T>,
) -> Vector<T> {
    b.i() * j_dot.dot(&b.k()) + b.j() * k_dot.dot(&b.i()) + b.k() * i_dot.dot(&b.j())
}

/// The axis rates ê_B^{A•} = ω⃗_{B/A} × ê_B for î, ĵ, k̂ (the vectrix form F_B^{A•} of (4.3.22)).
///
/// Book: (4.3.13–15), (4.3.22).
pub fn axis_rates<T: Scalar>(b: &Frame<T>, omega_b_a: &Vector<T>) -> [Vector<T>; 3] {
    [omega_b_a.cross(&b.i()), omega_b_a.cross(&b.j()), omega_b_a.cross(&b.k())]
}
