//! A physical rotation in numbers: resolution in a frame and construction from resolved
//! components (book §2.10, Fact 2.10.1; every representation of §2.11–2.17).
//!
//! R⃗_{B/A} resolved in A (or in B: Fact 2.10.1) is 𝓡_{B/A}, the active rotation matrix
//! whose columns are B's axes in A; 𝓞_{B/A} = 𝓡_{B/A}ᵀ is the passive orientation matrix.

use nalgebra::{Matrix3, Vector3};
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::Scalar;

use crate::{
    AxisAngle, EulerAngles, EulerSequence, EulerSolution, Quaternion, Rotation, RotationError,
    check_rotation_matrix, nearest_rotation,
};

impl<T: Scalar> Rotation<T> {
    /// The rotation whose resolution in `a` is the rotation matrix `r` (= 𝓡_{B/A} for
    /// R⃗_{B/A}), checked: orthonormal within `tol` and det = +1.
    ///
    /// Book: Fact 2.10.1, (2.10.2); quaternion by Shepperd/Markley (§2.15).
    ///
    /// # Errors
    /// As [`check_rotation_matrix`]. Noisy input: [`Rotation::nearest_in`], never silently.
    #[doc(alias = "from_dcm")]
    pub fn from_rotation_matrix_in(a: &Frame<T>, r: &Matrix3<T>, tol: f64) -> Result<Self, RotationError> {
        check_rotation_matrix(r, tol)?;
        Ok(Self::from_rotation_matrix_in_unchecked(a, r))
    }

    /// As [`Rotation::from_rotation_matrix_in`] without the check (hot path; the matrix must
    /// be a rotation).
    #[inline]
    pub fn from_rotation_matrix_in_unchecked(a: &Frame<T>, r: &Matrix3<T>) -> Self {
        Self::from_quaternion_parts(a, &Quaternion::from_rotation_matrix_unchecked(r))
    }

    /// From an orientation matrix 𝓞_{B/A} = 𝓡_{B/A}ᵀ given in `a` (passive: x|_B = 𝓞 x|_A).
    ///
    /// Book: (2.10.3–5).
    ///
    /// # Errors
    /// As [`check_rotation_matrix`].
    pub fn from_orientation_matrix_in(a: &Frame<T>, o: &Matrix3<T>, tol: f64) -> Result<Self, RotationError> {
        Self::from_rotation_matrix_in(a, &o.transpose(), tol)
    }

    /// The rotation nearest to a noisy matrix `m` resolved in `a` (polar decomposition; the
    /// explicit projection of DESIGN §5).
    ///
    /// Book: §2.10; notes ch1-2a §3.10.
    ///
    /// # Errors
    /// As [`nearest_rotation`].
    pub fn nearest_in(a: &Frame<T>, m: &Matrix3<T>) -> Result<Self, RotationError> {
        Ok(Self::from_rotation_matrix_in_unchecked(a, &nearest_rotation(m)?))
    }

    /// R⃗|_A: for R⃗_{B/A} this is 𝓡_{B/A} (columns = B's axes in A), the same in B.
    ///
    /// Book: (2.10.2), Fact 2.10.1.
    #[inline]
    pub fn rotation_matrix_in(&self, a: &Frame<T>) -> Matrix3<T> {
        self.quaternion_in(a).rotation_matrix()
    }

    /// 𝓞 = (R⃗|_A)ᵀ: for R⃗_{B/A} this is 𝓞_{B/A} (passive, x|_B = 𝓞_{B/A} x|_A).
    ///
    /// Book: (2.10.3–5).
    #[inline]
    #[doc(alias = "dcm")]
    pub fn orientation_matrix_in(&self, a: &Frame<T>) -> Matrix3<T> {
        self.quaternion_in(a).orientation_matrix()
    }

    /// Euler parameters q_{B/A} = (cos θ/2, sin θ/2 n̂|_A), canonical η ≥ 0 (and the canonical
    /// ε sign at θ = π).
    ///
    /// Book: (2.15.20); q|_A = q|_B since n̂|_A = n̂|_B (F2.11.3).
    #[inline]
    pub fn quaternion_in(&self, a: &Frame<T>) -> Quaternion<T> {
        let r = self.rotor();
        // R = q₀ − 𝒥q⃗ (3.9.17): q⃗ = −undual(B).
        let e = -r.bivector().undual().resolve(a);
        Quaternion::from_parts(r.scalar(), e).canonical()
    }

    /// The rotation of Euler parameters resolved in `a`; `q` must be unit within `tol`
    /// (normalise explicitly with [`Quaternion::normalize`]).
    ///
    /// Book: (2.15.20).
    ///
    /// # Errors
    /// [`RotationError::NonFinite`], [`RotationError::NotUnit`].
    pub fn from_quaternion_in(a: &Frame<T>, q: &Quaternion<T>, tol: f64) -> Result<Self, RotationError> {
        vectrix_tensor::check_tolerance(tol, "tol")?;
        q.check_unit(tol)?;
        Ok(Self::from_quaternion_parts(a, q))
    }

    /// Eigenaxis (resolved in `a`, canonical sign at π) and eigenangle.
    ///
    /// Book: §2.11, Facts 2.11.4–5.
    pub fn axis_angle_in(&self, a: &Frame<T>) -> AxisAngle<T, Vector3<T>> {
        self.quaternion_in(a).axis_angle()
    }

    /// The angle vector Θ|_A, canonical at θ = π.
    ///
    /// Book: §2.14, (2.14.5–8).
    #[doc(alias = "as_rotvec")]
    pub fn angle_vector_in(&self, a: &Frame<T>) -> Vector3<T> {
        self.quaternion_in(a).angle_vector()
    }

    /// The Gibbs vector g|_A = tan(θ/2)n̂|_A; `None` at θ = π.
    ///
    /// Book: §2.17.
    pub fn gibbs_in(&self, a: &Frame<T>) -> Option<Vector3<T>> {
        self.quaternion_in(a).gibbs()
    }

    /// Modified Rodrigues parameters p|_A = tan(θ/4) n̂|_A (|p| ≤ 1).
    pub fn mrp_in(&self, a: &Frame<T>) -> Vector3<T> {
        self.quaternion_in(a).mrp()
    }

    /// Euler angles of R⃗_{D/A} relative to `a`: principal and alternate, or gimbal lock.
    ///
    /// Book: §2.13.
    pub fn euler_in(&self, a: &Frame<T>, sequence: EulerSequence) -> EulerSolution<T> {
        EulerAngles::from_quaternion(&self.quaternion_in(a), sequence)
    }

    /// The rotation R⃗_{D/A} of Euler angles relative to `a`.
    ///
    /// Book: §2.12, (2.12.28).
    pub fn from_euler_in(a: &Frame<T>, e: &EulerAngles<T>) -> Self {
        Self::from_quaternion_parts(a, &e.quaternion())
    }
}

/// R⃗|_A: the resolved rotation matrix (𝓡_{B/A} for R⃗_{B/A}).
///
/// Book: Fact 2.10.1.
impl<T: Scalar> Resolve<T> for Rotation<T> {
    type Output = Matrix3<T>;
    #[inline]
    fn resolve(&self, a: &Frame<T>) -> Matrix3<T> {
        self.rotation_matrix_in(a)
    }
}
