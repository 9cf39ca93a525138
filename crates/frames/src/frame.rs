//! Standard frames (book §2.4): F_A = [î_A ĵ_A k̂_A].

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::frames_access::Hidden;
use vectrix_tensor::{Covector, Dyadic, Rotor, Scalar, Vector};

use crate::FrameError;

/// Default orthonormality tolerance: 128·ε, as Drake uses (DESIGN §5).
///
/// Book: §2.4 (orthonormal frames), (2.10.6–9).
pub const ORTHONORMAL_TOL: f64 = 128.0 * f64::EPSILON;

/// A standard frame F_A = [î_A ĵ_A k̂_A] (book (2.4.3)): three orthonormal, right-handed
/// physical vectors. A frame has **no origin, location or velocity** (book §1.3, §2.4).
///
/// Book: §2.4, (2.4.3)–(2.4.16).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame<T: Scalar = f64> {
    /// Columns are î, ĵ, k̂ in the hidden basis.
    pub(crate) axes: Matrix3<T>,
}

impl Frame<f64> {
    /// A first frame F_A, from which others are built (book §2.4). Equivalent to
    /// [`Frame::identity`] for `f64`; dual numbers use `Frame::<T>::identity()`.
    ///
    /// Book: §2.4, (2.4.3).
    #[allow(clippy::new_without_default)]
    pub fn new() -> Self {
        Self::identity()
    }
}

impl Frame<f64> {
    /// The same frame over another scalar type, e.g. `a.cast::<Dual64>()` to differentiate
    /// through resolution in it (derivative parts zero).
    ///
    /// Book: §2.24 (derivatives through resolution).
    pub fn cast<U: Scalar>(&self) -> Frame<U> {
        Frame { axes: self.axes.map(U::lit) }
    }
}

impl<T: Scalar> Default for Frame<T> {
    fn default() -> Self {
        Self::identity()
    }
}

fn orthonormal_defect<T: Scalar>(m: &Matrix3<T>) -> f64 {
    let g = m.tr_mul(m) - Matrix3::identity();
    g.iter().map(|x| x.re().abs()).fold(0.0, f64::max)
}

fn check_orthonormal<T: Scalar>(m: &Matrix3<T>, tol: f64, what: &'static str) -> Result<(), FrameError> {
    if !m.iter().all(|x| x.re().is_finite()) {
        return Err(FrameError::NonFinite { what });
    }
    let defect = orthonormal_defect(m);
    if defect.is_nan() || defect > tol {
        return Err(FrameError::NotOrthonormal { defect, tol });
    }
    let det = m.determinant().re();
    if det < 0.0 {
        return Err(FrameError::LeftHanded { det });
    }
    Ok(())
}

impl<T: Scalar> Frame<T> {
    /// A first frame, generic over the scalar (`Frame::<Dual64>::identity()`).
    ///
    /// Book: §2.4, (2.4.3).
    pub fn identity() -> Self {
        Self { axes: Matrix3::identity() }
    }

    /// x⃗ = x₁ î + x₂ ĵ + x₃ k̂ in [`Frame::identity`]: what `Frame::identity().vector(x)` gives,
    /// without its nine products (so a −0 component stays −0, and an infinite one does not turn
    /// the others into NaN through 0·∞). For hot paths that work in one fixed first frame (a
    /// simulation's ground).
    ///
    /// Book: (2.4.15–16).
    #[inline]
    pub fn identity_vector(x: [T; 3]) -> Vector<T> {
        Vector::from_hidden(Vector3::from(x))
    }

    /// x⃗|_I, the components of x⃗ in [`Frame::identity`]: what
    /// `x.resolve(&Frame::identity())` gives, without its nine products.
    ///
    /// Book: (2.4.14).
    #[inline]
    pub fn identity_components(x: &Vector<T>) -> Vector3<T> {
        *x.hidden()
    }

    /// The frame with axes î, ĵ, k̂.
    ///
    /// # Errors
    /// [`FrameError::NonFinite`], [`FrameError::ZeroAxis`], [`FrameError::NotOrthonormal`] when ‖MᵀM − I‖_max > `tol`
    /// (use [`ORTHONORMAL_TOL`] by default), [`FrameError::LeftHanded`] when î×ĵ = −k̂.
    ///
    /// Book: §2.4, (2.4.3); right-handed: î × ĵ = k̂.
    pub fn from_axes(i: &Vector<T>, j: &Vector<T>, k: &Vector<T>, tol: f64) -> Result<Self, FrameError> {
        vectrix_tensor::check_tolerance(tol, "tol")?;
        for (x, what) in [(i, "axis î"), (j, "axis ĵ"), (k, "axis k̂")] {
            if !x.is_finite() {
                return Err(FrameError::NonFinite { what });
            }
            if x.norm() == T::zero() {
                return Err(FrameError::ZeroAxis { what });
            }
        }
        let axes = Matrix3::from_columns(&[*i.hidden(), *j.hidden(), *k.hidden()]);
        check_orthonormal(&axes, tol, "frame axes")?;
        Ok(Self { axes })
    }

    /// F_B = R⃗ F_A: the frame whose axes are this frame's axes rotated by the rotor
    /// (book (2.8.9), §3.9). The rotor is assumed unit (it is by construction).
    ///
    /// Book: (2.8.9), (3.9.1).
    pub fn rotated_by_rotor(&self, r: &Rotor<T>) -> Self {
        let col = |k: usize| *r.rotate(&Vector::from_hidden(self.axes.column(k).into_owned())).hidden();
        Self { axes: Matrix3::from_columns(&[col(0), col(1), col(2)]) }
    }

    /// F_B = R⃗ F_A for a rotation dyad R⃗ (book (2.8.9)).
    ///
    /// # Errors
    /// As [`Frame::from_axes`]: the dyad must be a proper rotation within `tol`.
    ///
    /// Book: (2.8.9), Fact 2.8.3.
    pub fn rotated_by(&self, r: &Dyadic<T>, tol: f64) -> Result<Self, FrameError> {
        vectrix_tensor::check_tolerance(tol, "tol")?;
        check_orthonormal(r.hidden(), tol, "rotation dyad")?;
        Ok(Self { axes: r.hidden() * self.axes })
    }

    /// The frame F_B whose orientation relative to `a` is 𝓞_{B/A} (passive: x|_B = 𝓞_{B/A}x|_A).
    /// Rows of 𝓞_{B/A} are B's axes resolved in A (2.10.14), so F_B = F_A 𝓞_{B/A}ᵀ (2.10.16).
    ///
    /// # Errors
    /// As [`Frame::from_axes`], for 𝓞_{B/A} not orthonormal or det = −1.
    ///
    /// Book: (2.10.14–16).
    pub fn from_orientation_rel(a: &Frame<T>, o_ba: &Matrix3<T>, tol: f64) -> Result<Self, FrameError> {
        vectrix_tensor::check_tolerance(tol, "tol")?;
        check_orthonormal(o_ba, tol, "orientation matrix")?;
        // (2.10.16): F_B = F_A 𝓡_{B/A}, 𝓡_{B/A} = 𝓞_{B/A}ᵀ
        Ok(Self { axes: a.axes * o_ba.transpose() })
    }

    /// î of this frame.
    ///
    /// Book: (2.4.3).
    pub fn i(&self) -> Vector<T> {
        Vector::from_hidden(self.axes.column(0).into_owned())
    }

    /// ĵ of this frame.
    ///
    /// Book: (2.4.3).
    pub fn j(&self) -> Vector<T> {
        Vector::from_hidden(self.axes.column(1).into_owned())
    }

    /// k̂ of this frame.
    ///
    /// Book: (2.4.3).
    pub fn k(&self) -> Vector<T> {
        Vector::from_hidden(self.axes.column(2).into_owned())
    }

    /// Axis `n` ∈ {1, 2, 3} (î, ĵ, k̂); `None` otherwise.
    ///
    /// Book: (2.4.3).
    pub fn axis(&self, n: usize) -> Option<Vector<T>> {
        (1..=3).contains(&n).then(|| Vector::from_hidden(self.axes.column(n - 1).into_owned()))
    }

    /// x⃗ = F_A x|_A = x₁î + x₂ĵ + x₃k̂ (2.4.15–16): the physical vector with these components.
    ///
    /// Book: (2.4.15–16). Unchecked (hot path); [`Frame::try_vector`] rejects NaN/∞.
    #[inline]
    pub fn vector(&self, x: [T; 3]) -> Vector<T> {
        Vector::from_hidden(self.axes * Vector3::from(x))
    }

    /// As [`Frame::vector`], rejecting non-finite components.
    ///
    /// Book: (2.4.15–16).
    ///
    /// # Errors
    /// [`FrameError::NonFinite`] when a component is NaN or ∞.
    pub fn try_vector(&self, x: [T; 3]) -> Result<Vector<T>, FrameError> {
        if x.iter().all(|c| c.re().is_finite()) {
            Ok(self.vector(x))
        } else {
            Err(FrameError::NonFinite { what: "vector components" })
        }
    }

    /// As [`Frame::dyadic`], rejecting non-finite entries.
    ///
    /// Book: (2.10.22).
    ///
    /// # Errors
    /// [`FrameError::NonFinite`] when an entry is NaN or ∞.
    pub fn try_dyadic(&self, m: &Matrix3<T>) -> Result<Dyadic<T>, FrameError> {
        if m.iter().all(|c| c.re().is_finite()) {
            Ok(self.dyadic(m))
        } else {
            Err(FrameError::NonFinite { what: "dyadic components" })
        }
    }

    /// The covector whose row of components in this frame is `x` (x⃗′|_A = x|_Aᵀ, (2.4.20)).
    ///
    /// Book: (2.4.20).
    #[inline]
    pub fn covector(&self, x: [T; 3]) -> Covector<T> {
        Covector::from_hidden(self.axes * Vector3::from(x))
    }

    /// The physical matrix M⃗ = F_A M|_A 𝓕′_A whose resolution in this frame is `m`
    /// (book (2.10.22)).
    ///
    /// Book: (2.10.22), Fact 2.6.5.
    #[inline]
    pub fn dyadic(&self, m: &Matrix3<T>) -> Dyadic<T> {
        Dyadic::from_hidden(self.axes * m * self.axes.transpose())
    }

    /// 𝓞_{self/A}: orientation of this frame B relative to A (passive,
    /// x|_B = 𝓞_{B/A} x|_A, rows = B's axes in A). `b.orientation_rel(&a)` is 𝓞_{B/A}.
    ///
    /// Book: (2.10.3–5), (2.10.31). The same matrix as sympy `B.dcm(A)` and Drake `R_BA`
    /// (see `docs/notation.md`).
    #[doc(alias = "dcm")]
    #[doc(alias = "direction_cosine_matrix")]
    #[inline]
    pub fn orientation_rel(&self, a: &Frame<T>) -> Matrix3<T> {
        // Entry (r, c) = (B axis r)·(A axis c).
        self.axes.tr_mul(&a.axes)
    }

    /// 𝓡_{self/A} = 𝓞_{B/A}ᵀ: the rotation matrix of B relative to A, whose **columns are B's
    /// axes resolved in A** (2.10.2); identical resolved in A or in B (Fact 2.10.1).
    ///
    /// Book: (2.10.2), Fact 2.10.1.
    #[inline]
    pub fn rotation_rel(&self, a: &Frame<T>) -> Matrix3<T> {
        a.axes.tr_mul(&self.axes)
    }

    /// The physical rotation R⃗_{self/A} = F_B 𝓕′_A (2.8.7), taking A's axes to this frame's.
    ///
    /// Book: (2.8.6–9).
    #[inline]
    pub fn rotation_dyadic_rel(&self, a: &Frame<T>) -> Dyadic<T> {
        Dyadic::from_hidden(self.axes * a.axes.transpose())
    }
}
