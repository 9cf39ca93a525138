//! The one scalar bound of vectrix.
//!
//! Book: §1.4 (real numbers); DESIGN §1.4. Every numeric type is generic over [`Scalar`]
//! with `f64` as the default. `f32` and num-dual's dual numbers ([`num_dual::Dual64`],
//! [`num_dual::Dual2_64`], [`num_dual::HyperDual64`], [`num_dual::DualSVec64`]) implement
//! it, so exact derivatives flow through the kernel.

use nalgebra::RealField;
use num_dual::{Dual2_64, Dual64, DualSVec64, HyperDual64};

/// A real scalar: `f64`, `f32`, or a num-dual dual number over `f64`.
///
/// Built on [`nalgebra::RealField`] (which num-dual's types implement) plus `Copy`, so math
/// bodies read like the book: no `.clone()`.
///
/// Book: §1.4; DESIGN §1.4.
pub trait Scalar: RealField + Copy {
    /// The real part as `f64` (the value itself for `f32`/`f64`; the non-derivative part of a
    /// dual number). Used for tolerances, branch decisions and error messages.
    fn re(&self) -> f64;

    /// A literal constant: `T::lit(0.5)`.
    #[inline(always)]
    fn lit(x: f64) -> Self {
        nalgebra::convert(x)
    }

    /// Machine epsilon of the underlying real type.
    fn eps() -> f64;
}

impl Scalar for f64 {
    #[inline(always)]
    fn re(&self) -> f64 {
        *self
    }
    #[inline(always)]
    fn lit(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn eps() -> f64 {
        f64::EPSILON
    }
}

impl Scalar for f32 {
    #[inline(always)]
    fn re(&self) -> f64 {
        f64::from(*self)
    }
    #[inline(always)]
    fn lit(x: f64) -> Self {
        x as f32
    }
    #[inline(always)]
    fn eps() -> f64 {
        f64::from(f32::EPSILON)
    }
}

macro_rules! dual_scalar {
    ($($t:ty),*) => {$(
        impl Scalar for $t {
            #[inline(always)]
            fn re(&self) -> f64 {
                num_dual::DualStruct::re(self)
            }
            #[inline(always)]
            fn eps() -> f64 {
                f64::EPSILON
            }
        }
    )*};
}
dual_scalar!(Dual64, Dual2_64, HyperDual64);

impl<const N: usize> Scalar for DualSVec64<N> {
    #[inline(always)]
    fn re(&self) -> f64 {
        num_dual::DualStruct::re(self)
    }
    #[inline(always)]
    fn eps() -> f64 {
        f64::EPSILON
    }
}

/// `true` when every component's real part is finite.
pub(crate) fn all_finite<T: Scalar>(xs: &[T]) -> bool {
    xs.iter().all(|x| x.re().is_finite())
}
