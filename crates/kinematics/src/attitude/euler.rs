//! Euler-angle rates in all 12 sequences (book §4.10), body and spatial forms with inverses.
//!
//! For an intrinsic sequence i-j-k with angles (α, β, γ) in the order applied
//! (F_A →i,α F_B →j,β F_C →k,γ F_D), the summation (4.6.2) gives
//! ω⃗_{D/A} = α̇ ê_i(A) + β̇ ê_j(B) + γ̇ ê_k(C), so resolved in D
//!
//! ω_{D/A}|_D = S (α̇, β̇, γ̇)ᵀ,  S = [𝓞_k(γ)𝓞_j(β)e_i | 𝓞_k(γ)e_j | e_k]   (4.10.7–9, 4.10.14),
//!
//! and in A, ω_{D/A}|_A = 𝓡_{D/A} S (α̇, β̇, γ̇)ᵀ = [e_i | 𝓡_i(α)e_j | 𝓡_i(α)𝓡_j(β)e_k](α̇, β̇, γ̇)ᵀ.
//! An extrinsic sequence i-j-k (α, β, γ) is the intrinsic k-j-i (γ, β, α).
//!
//! # Conventions
//! Rates are ordered like the angles, (α̇, β̇, γ̇): for 3-2-1 that is (Ψ̇, Θ̇, Φ̇), the reverse of
//! the book's (4.10.7) column order (Φ̇, Θ̇, Ψ̇); for 3-1-3 (Φ̇, Θ̇, Ψ̇).
//! det S = ±cos β (Tait–Bryan) or ±sin β (symmetric): gimbal lock at β = ±π/2 or β ∈ {0, π};
//! for symmetric sequences that includes the identity attitude.

use nalgebra::{Matrix3, Vector3};
use vectrix_rotation::{Axis, EulerAngles, EulerKind, orientation_about, rotation_about};
use vectrix_tensor::Scalar;

use crate::KinematicsError;

fn e<T: Scalar>(axis: Axis) -> Vector3<T> {
    let mut v = Vector3::zeros();
    v[axis.index() - 1] = T::one();
    v
}

/// The intrinsic axes and angles, with a flag: extrinsic i-j-k (α, β, γ) is intrinsic k-j-i
/// (γ, β, α).
fn intrinsic<T: Scalar>(ea: &EulerAngles<T>) -> ([Axis; 3], [T; 3], bool) {
    let [i, j, k] = ea.sequence.axes();
    let [a, b, c] = ea.angles;
    match ea.sequence.kind() {
        EulerKind::Intrinsic => ([i, j, k], [a, b, c], false),
        EulerKind::Extrinsic => ([k, j, i], [c, b, a], true),
    }
}

/// Reorders the columns of an intrinsic-order matrix back to the caller's angle order.
fn reorder<T: Scalar>(m: Matrix3<T>, reversed: bool) -> Matrix3<T> {
    if reversed {
        Matrix3::from_columns(&[m.column(2).into_owned(), m.column(1).into_owned(), m.column(0).into_owned()])
    } else {
        m
    }
}

/// The body rate matrix S: ω_{D/A}|_D = S (α̇, β̇, γ̇)ᵀ.
///
/// Book: (4.10.7–9) (3-2-1), (4.10.14) (3-1-3), general sequences by (4.6.2).
pub fn euler_rate_matrix_body<T: Scalar>(ea: &EulerAngles<T>) -> Matrix3<T> {
    let ([i, j, k], [_, b, c], rev) = intrinsic(ea);
    let o_k = orientation_about(k, c);
    reorder(
        Matrix3::from_columns(&[o_k * orientation_about(j, b) * e::<T>(i), o_k * e::<T>(j), e::<T>(k)]),
        rev,
    )
}

/// The spatial rate matrix: ω_{D/A}|_A = [e_i | 𝓡_i(α)e_j | 𝓡_i(α)𝓡_j(β)e_k] (α̇, β̇, γ̇)ᵀ.
///
/// Book: (4.10.7–9) with ω|_A = 𝓡_{D/A} ω|_D.
pub fn euler_rate_matrix_spatial<T: Scalar>(ea: &EulerAngles<T>) -> Matrix3<T> {
    let ([i, j, k], [a, b, _], rev) = intrinsic(ea);
    let r_i = rotation_about(i, a);
    reorder(Matrix3::from_columns(&[e::<T>(i), r_i * e::<T>(j), r_i * rotation_about(j, b) * e::<T>(k)]), rev)
}

/// ω_{D/A}|_D from the angle rates (α̇, β̇, γ̇).
///
/// Book: (4.10.7), (4.10.14).
pub fn omega_body_from_euler_rates<T: Scalar>(ea: &EulerAngles<T>, rates: [T; 3]) -> Vector3<T> {
    euler_rate_matrix_body(ea) * Vector3::from(rates)
}

/// ω_{D/A}|_A from the angle rates.
///
/// Book: (4.10.7) with ω|_A = 𝓡_{D/A}ω|_D.
pub fn omega_spatial_from_euler_rates<T: Scalar>(ea: &EulerAngles<T>, rates: [T; 3]) -> Vector3<T> {
    euler_rate_matrix_spatial(ea) * Vector3::from(rates)
}

fn solve<T: Scalar>(
    ea: &EulerAngles<T>,
    s: Matrix3<T>,
    w: &Vector3<T>,
    tol: f64,
) -> Result<[T; 3], KinematicsError> {
    vectrix_tensor::check_tolerance(tol, "tol").map_err(vectrix_frames::FrameError::from)?;
    if !s.iter().chain(w.iter()).all(|x| x.re().is_finite()) {
        return Err(KinematicsError::NonFinite { what: "Euler angles or ω" });
    }
    let det = s.determinant();
    if det.re().abs() <= tol {
        let sre = s.map(|x| x.re());
        let sv = sre.singular_values();
        let condition = if sv.min() == 0.0 { f64::INFINITY } else { sv.max() / sv.min() };
        let [i, j, k] = ea.sequence.axes().map(|a| a.index());
        let kind = match ea.sequence.kind() {
            EulerKind::Intrinsic => "intrinsic",
            EulerKind::Extrinsic => "extrinsic",
        };
        return Err(KinematicsError::GimbalLock {
            sequence: format!("{i}-{j}-{k} {kind}"),
            det: det.re(),
            condition,
            tol,
            singular_at: if ea.sequence.is_symmetric() { "β = 0 and β = π" } else { "β = ±π/2" },
        });
    }
    // adjugate/det: exact for 3×3 and differentiable for dual numbers
    let adj = vectrix_tensor::adjugate(&s);
    let r = adj * w / det;
    Ok([r.x, r.y, r.z])
}

/// The angle rates (α̇, β̇, γ̇) = S⁻¹ ω_{D/A}|_D (4.10.11, 4.10.18 generalized).
///
/// Book: (4.10.11) (3-2-1), (4.10.18) (3-1-3; (4.10.16–17) should read S(Ψ,Θ)).
///
/// # Errors
/// [`KinematicsError::GimbalLock`] when |det S| ≤ `tol` (|cos β| or |sin β|), with the
/// condition number; [`KinematicsError::NonFinite`].
pub fn euler_rates_from_omega_body<T: Scalar>(
    ea: &EulerAngles<T>,
    omega_in_d: &Vector3<T>,
    tol: f64,
) -> Result<[T; 3], KinematicsError> {
    solve(ea, euler_rate_matrix_body(ea), omega_in_d, tol)
}

/// The angle rates from ω_{D/A}|_A.
///
/// Book: (4.10.11) with ω|_D = 𝓞_{D/A}ω|_A.
///
/// # Errors
/// As [`euler_rates_from_omega_body`].
pub fn euler_rates_from_omega_spatial<T: Scalar>(
    ea: &EulerAngles<T>,
    omega_in_a: &Vector3<T>,
    tol: f64,
) -> Result<[T; 3], KinematicsError> {
    solve(ea, euler_rate_matrix_spatial(ea), omega_in_a, tol)
}
