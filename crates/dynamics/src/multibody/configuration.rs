//! Configurations: the retraction q ⊕ v dt (unit quaternions for ball joints) and the checks
//! of states, generic over the scalar.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use vectrix_tensor::Scalar;

use super::joint::Elem;
use super::model::Model;
use crate::DynamicsError;

impl<T: Scalar> Model<T> {
    /// q ⊕ v dt: adds v dt to every coordinate, and for ball joints composes the quaternion
    /// with exp(ω dt / 2) on the right (ω in the link frame), keeping it unit. This is the
    /// retraction the tangent-space derivatives use: ∂/∂q along direction k means
    /// d/dε f(q ⊕ ε e_k) at ε = 0 (for a ball joint: a rotation about the link's own axis k).
    ///
    /// Book: §4.11 (exact quaternion step (4.11.17)).
    ///
    /// # Degenerate inputs
    /// A zero rotation step (ω dt = 0, also a dual number whose real part is 0) takes the
    /// Taylor branch of cos(θ/2) and sin(θ/2)/θ, so its derivatives are exact.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`] (also for a
    /// non-finite `dt`).
    pub fn integrate(&self, q: &[T], v: &[T], dt: T) -> Result<Vec<T>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        if !dt.re().is_finite() {
            return Err(DynamicsError::NonFinite { what: "dt" });
        }
        let mut out = q.to_vec();
        for s in &self.segs {
            match s.elem {
                Elem::Revolute(_) | Elem::Prismatic(_) => out[s.qi] += v[s.vi] * dt,
                Elem::Spherical => {
                    let q0 = UnitQuaternion::new_normalize(Quaternion::new(
                        q[s.qi],
                        q[s.qi + 1],
                        q[s.qi + 2],
                        q[s.qi + 3],
                    ));
                    let w = Vector3::new(v[s.vi], v[s.vi + 1], v[s.vi + 2]);
                    let q1 = q0 * quaternion_exp(&(w * dt));
                    out[s.qi..s.qi + 4].copy_from_slice(&[q1.w, q1.i, q1.j, q1.k]);
                }
                Elem::Fixed => {}
            }
        }
        if !crate::error::all_finite(&out) {
            return Err(DynamicsError::Overflow { what: "integrated configuration q ⊕ v dt" });
        }
        Ok(out)
    }

    pub(crate) fn check_q(&self, q: &[T]) -> Result<(), DynamicsError> {
        crate::error::check_len(q.len(), self.nq, "q")?;
        crate::error::check_finite_t(q, "q")?;
        for s in &self.segs {
            if s.elem == Elem::Spherical {
                let n = q[s.qi..s.qi + 4].iter().map(|x| x.re() * x.re()).sum::<f64>().sqrt();
                if !(1e-6..=1e150).contains(&n) {
                    return Err(DynamicsError::OutOfRange {
                        what: "ball-joint quaternion norm",
                        value: n,
                        valid: "a quaternion of norm in [1e-6, 1e150] (it is normalized)",
                    });
                }
            }
        }
        Ok(())
    }

    pub(crate) fn check_v(&self, v: &[T], what: &'static str) -> Result<(), DynamicsError> {
        crate::error::check_len(v.len(), self.nv, what)?;
        crate::error::check_finite_t(v, what)
    }
}

/// exp of a rotation vector θ as a unit quaternion (cos(θ/2), sin(θ/2) θ̂), scalar first.
///
/// Book: (4.11.17), (2.15.x) Euler parameters of an eigenaxis rotation.
///
/// # Degenerate inputs
/// For |θ|² ≤ ε the Taylor series cos(θ/2) = 1 − θ²/8 + θ⁴/384, sin(θ/2)/θ = ½ − θ²/48 +
/// θ⁴/3840 (exact to rounding there, and differentiable at θ = 0, where √(θ·θ) is not).
pub(crate) fn quaternion_exp<T: Scalar>(theta: &Vector3<T>) -> UnitQuaternion<T> {
    let t2 = theta.dot(theta);
    let (c, s_over) = if t2.re() <= f64::EPSILON {
        // small-angle branch: no square root of 0
        (
            T::one() - t2 / T::lit(8.0) + t2 * t2 / T::lit(384.0),
            T::lit(0.5) - t2 / T::lit(48.0) + t2 * t2 / T::lit(3840.0),
        )
    } else {
        let t = t2.sqrt();
        let (s, c) = (t * T::lit(0.5)).sin_cos();
        (c, s / t)
    };
    UnitQuaternion::new_unchecked(Quaternion::new(c, theta.x * s_over, theta.y * s_over, theta.z * s_over))
}
