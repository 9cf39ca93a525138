//! Resolution of kernel objects in a frame (book §2.4, §2.6, §3.6).

use nalgebra::{Matrix3, RowVector3, Vector3};
use vectrix_tensor::frames_access::Hidden;
use vectrix_tensor::{Covector, Dyadic, Scalar, Vector};

use crate::Frame;

/// Resolution x⃗|_A of a frame-free object in a frame: the only way numbers come out of vectrix.
///
/// Book: (2.4.14) for vectors, (2.4.20) covectors, (2.10.22) dyadics, (3.6.2) tensors.
pub trait Resolve<T: Scalar> {
    /// The resolved components.
    type Output;
    /// Components of `self` in frame `a`.
    fn resolve(&self, a: &Frame<T>) -> Self::Output;
}

/// x⃗|_A = [î_A·x⃗, ĵ_A·x⃗, k̂_A·x⃗]ᵀ (2.4.14).
impl<T: Scalar> Resolve<T> for Vector<T> {
    type Output = Vector3<T>;
    #[inline]
    fn resolve(&self, a: &Frame<T>) -> Vector3<T> {
        a.axes.tr_mul(self.hidden())
    }
}

/// x⃗′|_A = x|_Aᵀ, a row (2.4.20).
impl<T: Scalar> Resolve<T> for Covector<T> {
    type Output = RowVector3<T>;
    #[inline]
    fn resolve(&self, a: &Frame<T>) -> RowVector3<T> {
        a.axes.tr_mul(self.hidden()).transpose()
    }
}

/// M⃗|_A = 𝓕_A M⃗ F′_A: entry (r, c) is î_r′ M⃗ î_c (2.6.x, 2.10.22).
impl<T: Scalar> Resolve<T> for Dyadic<T> {
    type Output = Matrix3<T>;
    #[inline]
    fn resolve(&self, a: &Frame<T>) -> Matrix3<T> {
        a.axes.tr_mul(&(self.hidden() * a.axes))
    }
}

/// Change of frame of resolved components: x|_B = 𝓞_{B/A} x|_A (2.10.31), for a vector
/// resolved in `a`, re-expressed in `b`.
///
/// Book: (2.10.31).
#[inline]
pub fn change_frame_vector<T: Scalar>(x_in_a: &Vector3<T>, a: &Frame<T>, b: &Frame<T>) -> Vector3<T> {
    b.orientation_rel(a) * x_in_a
}

/// Change of frame of a resolved covector (a row): x′|_B = x′|_A 𝓞_{B/A}ᵀ, the transpose of
/// (2.10.31) (standard frames, (2.4.20)).
///
/// Book: (2.10.31), (2.4.20).
#[inline]
pub fn change_frame_covector<T: Scalar>(x_in_a: &RowVector3<T>, a: &Frame<T>, b: &Frame<T>) -> RowVector3<T> {
    x_in_a * b.orientation_rel(a).transpose()
}

/// Change of frame of a resolved dyadic: M|_B = 𝓞_{B/A} M|_A 𝓞_{B/A}ᵀ (book §2.10).
///
/// Book: (2.10.38), Fact 2.10.11.
#[inline]
pub fn change_frame_dyadic<T: Scalar>(m_in_a: &Matrix3<T>, a: &Frame<T>, b: &Frame<T>) -> Matrix3<T> {
    let o_ba = b.orientation_rel(a);
    o_ba * m_in_a * o_ba.transpose()
}
