//! Pauli-matrix representation of Cl(3,0) (book (3.8.42)–(3.8.49)).
//!
//! Relative to a right-handed orthonormal frame [î ĵ k̂]: 1 ↦ I₂, î ↦ σ₁, ĵ ↦ σ₂, k̂ ↦ σ₃,
//! hence 𝒥 = σ₁σ₂σ₃ ↦ iI₂. The map is an algebra isomorphism onto the 2×2 complex matrices:
//! the geometric product becomes the matrix product. (The book's (3.8.48) prints σ₃σ₁ wrong;
//! it is [[0, 1], [−1, 0]], see the ch. 3 notes.)

use nalgebra::{Complex, Matrix2, Vector3};

use crate::{Multivector, Scalar, TensorError, Vector};

/// Checks that `axes` is orthonormal and right-handed within 128ε.
fn check_axes<T: Scalar>(axes: &[Vector<T>; 3]) -> Result<(), TensorError> {
    if !axes.iter().all(Vector::is_finite) {
        return Err(TensorError::NonFinite { what: "frame axes" });
    }
    let mut defect = 0.0f64;
    for a in 0..3 {
        for b in 0..3 {
            let want = if a == b { 1.0 } else { 0.0 };
            defect = defect.max((axes[a].dot(&axes[b]).re() - want).abs());
        }
    }
    let det = axes[0].triple(&axes[1], &axes[2]).re();
    if defect.is_nan() || defect > 128.0 * T::eps() || det <= 0.0 {
        return Err(TensorError::OutOfRange {
            what: "frame axes defect max|aᵢ·aⱼ − δᵢⱼ| (or negative handedness)",
            value: if det <= 0.0 { det } else { defect },
            valid: "orthonormal, right-handed axes (defect ≤ 128ε, det = +1)",
        });
    }
    Ok(())
}

impl<T: Scalar> Multivector<T> {
    /// The Pauli matrix of S relative to the frame with axes `axes` = [î, ĵ, k̂]:
    /// (s + it)I₂ + Σ_k (x_k + iβ_k)σ_k, where x_k are the vector components and β_k those of
    /// the dual of the bivector part.
    ///
    /// Book: (3.8.42)–(3.8.49), with the (3.8.48) fix.
    ///
    /// # Errors
    /// [`TensorError::OutOfRange`] when the axes are not orthonormal and right-handed.
    pub fn to_pauli(&self, axes: &[Vector<T>; 3]) -> Result<Matrix2<Complex<T>>, TensorError> {
        check_axes(axes)?;
        let c = |re: T, im: T| Complex::new(re, im);
        let comp = |a: &Vector<T>| c(a.c.dot(&self.v), a.c.dot(&self.b));
        let (u1, u2, u3) = (comp(&axes[0]), comp(&axes[1]), comp(&axes[2]));
        let z = c(self.s, self.t);
        let i = c(T::zero(), T::one());
        Ok(Matrix2::new(z + u3, u1 - i * u2, u1 + i * u2, z - u3))
    }

    /// The multivector of a Pauli matrix relative to the frame with axes `axes`: the inverse of
    /// [`Multivector::to_pauli`].
    ///
    /// Book: (3.8.42)–(3.8.49).
    ///
    /// # Errors
    /// [`TensorError::OutOfRange`] when the axes are not orthonormal and right-handed;
    /// [`TensorError::NonFinite`] for non-finite entries.
    pub fn from_pauli(axes: &[Vector<T>; 3], m: &Matrix2<Complex<T>>) -> Result<Self, TensorError> {
        check_axes(axes)?;
        if !m.iter().all(|z| z.re.re().is_finite() && z.im.re().is_finite()) {
            return Err(TensorError::NonFinite { what: "Pauli matrix" });
        }
        let half = T::lit(0.5);
        let (m00, m01, m10, m11) = (m[(0, 0)], m[(0, 1)], m[(1, 0)], m[(1, 1)]);
        let z = (m00 + m11) * half;
        let u3 = (m00 - m11) * half;
        let u1 = (m01 + m10) * half;
        // u₂ = (m₁₀ − m₀₁)/(2i) = −i(m₁₀ − m₀₁)/2
        let d = (m10 - m01) * half;
        let u2 = Complex::new(d.im, -d.re);
        let e: [Vector3<T>; 3] = [axes[0].c, axes[1].c, axes[2].c];
        let v = e[0] * u1.re + e[1] * u2.re + e[2] * u3.re;
        let b = e[0] * u1.im + e[1] * u2.im + e[2] * u3.im;
        Ok(Multivector { s: z.re, v, b, t: z.im })
    }
}
