//! The parallel-transport (Bishop) frame of a sampled curve: a rotation-minimizing frame that,
//! unlike Frenet–Serret, stays defined through inflections and straight segments.
//!
//! Not in the book (notes ch4-5 §3 recommend it as the remedy for κ = 0). The frame
//! [ê_t û₁ û₂] satisfies dê_t/ds = k₁û₁ + k₂û₂, dû₁/ds = −k₁ê_t, dû₂/ds = −k₂ê_t: its angular
//! velocity has no component along ê_t. Relative to Frenet–Serret, û₁ = cos ψ ê_n + sin ψ ê_b
//! with ψ′ = −τ s′.

use vectrix_frames::{Frame, ORTHONORMAL_TOL};
use vectrix_tensor::{Scalar, Vector};

use crate::KinematicsError;
use crate::motion::finite_vector;

/// Bishop frames at the samples (x⃗_i, t̂_i) of a curve (positions relative to any fixed point and
/// unit tangents), starting from the normal `u0` at sample 0, by the double-reflection method
/// (Wang, Jüttler, Zheng, Liu, ACM TOG 27(1), 2008), fourth-order accurate in the spacing.
///
/// Book: §5.5 (remedy for κ = 0; the frame itself is not in the book).
///
/// # Errors
/// [`KinematicsError::Zero`] for a zero tangent or a `u0` parallel to t̂₀;
/// [`KinematicsError::OutOfRange`] when the slices differ in length or are empty;
/// [`KinematicsError::NonFinite`].
pub fn bishop_frames<T: Scalar>(
    points: &[Vector<T>],
    tangents: &[Vector<T>],
    u0: &Vector<T>,
) -> Result<Vec<Frame<T>>, KinematicsError> {
    if points.len() != tangents.len() || points.is_empty() {
        return Err(KinematicsError::OutOfRange {
            what: "number of samples",
            value: points.len() as f64,
            valid: "at least 1, with one tangent per point",
        });
    }
    for (p, t) in points.iter().zip(tangents) {
        finite_vector(p, "curve point")?;
        finite_vector(t, "curve tangent")?;
    }
    finite_vector(u0, "initial normal")?;
    let unit_t = |t: &Vector<T>| t.unit().ok_or(KinematicsError::Zero { what: "curve tangent" });
    let mut t = unit_t(&tangents[0])?;
    // project u0 perpendicular to t₀
    let u_perp = *u0 - t * t.dot(u0);
    // u0 (numerically) parallel to t₀ leaves no normal direction
    if u_perp.norm().re() <= 64.0 * T::eps() * u0.norm().re() {
        return Err(KinematicsError::Zero { what: "initial normal ⊥ tangent" });
    }
    let mut u = u_perp.unit().ok_or(KinematicsError::Zero { what: "initial normal ⊥ tangent" })?;
    let frame = |t: &Vector<T>, u: &Vector<T>| Frame::from_axes(t, u, &t.cross(u), ORTHONORMAL_TOL);
    let mut out = vec![frame(&t, &u)?];
    for i in 0..points.len() - 1 {
        let t_next = unit_t(&tangents[i + 1])?;
        let two = T::lit(2.0);
        // reflection 1 in the bisecting plane of x_i, x_{i+1}
        let v1 = points[i + 1] - points[i];
        let c1 = v1.norm_squared();
        let (u_l, t_l) = if c1 == T::zero() {
            (u, t)
        } else {
            (u - v1 * (two * v1.dot(&u) / c1), t - v1 * (two * v1.dot(&t) / c1))
        };
        // reflection 2 taking the reflected tangent to t_{i+1}
        let v2 = t_next - t_l;
        let c2 = v2.norm_squared();
        let u_next = if c2 == T::zero() { u_l } else { u_l - v2 * (two * v2.dot(&u_l) / c2) };
        // re-orthonormalize against rounding: u ⊥ t, |u| = 1
        t = t_next;
        u = (u_next - t * t.dot(&u_next))
            .unit()
            .ok_or(KinematicsError::Zero { what: "transported normal" })?;
        out.push(frame(&t, &u)?);
    }
    Ok(out)
}
