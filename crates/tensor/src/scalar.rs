//! The one scalar bound of vectrix.
//!
//! Book: §1.4 (real numbers); DESIGN §1.4. Every numeric type is generic over [`Scalar`]
//! with `f64` as the default. `f32` and num-dual's dual numbers ([`num_dual::Dual64`],
//! [`num_dual::Dual2_64`], [`num_dual::HyperDual64`], [`num_dual::DualSVec64`]) implement
//! it, so exact derivatives flow through the kernel.
//!
//! # Fast paths
//! The `fast_*` methods are hooks: their default is the generic code every scalar shares, and
//! `impl Scalar for f64` overrides them with branch-free kernels that compilers vectorise (the
//! choice is made by the compiler, per type, not by a test when the program runs). Each `f64`
//! kernel is within 1 ulp of the true value, as `libm` is, and the same build gives the same
//! bits on every CPU (docs/robustness.md, "Reproducibility").

use nalgebra::RealField;
use num_dual::{Dual2_64, Dual64, DualSVec64, HyperDual64};
use vectrix_simd::vmath;

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

    /// (sin x, cos x). For `f64` with |x| ≤ 2·10⁵: fdlibm's kernels without branches (one
    /// shared argument reduction, each result within 1 ulp, inlined: no call); `libm` beyond
    /// and for NaN or ±∞, and for every other scalar.
    #[inline(always)]
    fn fast_sin_cos(self) -> (Self, Self) {
        self.sin_cos()
    }

    /// [`Scalar::fast_sin_cos`] of three arguments. For `f64` with every |xᵢ| ≤ 2·10⁵ the
    /// three kernels run side by side in one loop over four lanes, which the compiler may
    /// vectorise (the three elementary factors of an Euler sequence).
    #[inline(always)]
    fn fast_sin_cos3(x: [Self; 3]) -> [(Self, Self); 3] {
        x.map(Self::fast_sin_cos)
    }

    /// sin xᵢ and cos xᵢ of every element of `x` into `sin` and `cos`, each what
    /// [`Scalar::fast_sin_cos`] returns (the three slices have one length; extra elements of
    /// the longer ones are left as they are). For `f64` in SIMD, AVX2 where the CPU has it:
    /// the same bits either way.
    #[inline]
    fn fast_sin_cos_slices(x: &[Self], sin: &mut [Self], cos: &mut [Self]) {
        for ((xk, sk), ck) in x.iter().zip(sin.iter_mut()).zip(cos.iter_mut()) {
            (*sk, *ck) = xk.fast_sin_cos();
        }
    }

    /// atan2(self, x) in [−π, π]. For finite `f64` arguments other than (0, 0): fdlibm's
    /// kernel without branches (within 1 ulp, inlined); `libm`'s rules for zeros, infinities
    /// and NaN otherwise, and for every other scalar.
    #[inline(always)]
    fn fast_atan2(self, x: Self) -> Self {
        self.atan2(x)
    }

    /// (cos h, sin h / h) from u = h², where a kernel needs no square root, range reduction or
    /// division: `f64` with |u| ≤ (π/2)², by the Taylor series in u of these entire functions
    /// of u (sin h / h within 2 ulps, cos h within 2ε; for u < 0 they are cosh √−u and
    /// sinh √−u / √−u). `None` for larger |u|, NaN and every other scalar: the caller takes
    /// [`Scalar::fast_sin_cos`] of √u.
    #[inline(always)]
    fn fast_cos_sinc_of_square(self) -> Option<(Self, Self)> {
        None
    }

    /// Runs `P`'s `f64` kernel for `f64` and its generic code for every other scalar: the
    /// matrix-level fast paths of the layers (the log map of a rotation matrix, Hooke's law over
    /// many strains), chosen by this impl at compile time. Internal to vectrix.
    #[doc(hidden)]
    #[inline(always)]
    fn fast_path<P: FastPath>(x: P::Input<Self>) -> P::Output<Self> {
        P::generic(x)
    }
}

/// A computation with an `f64` kernel beside the generic code every scalar shares;
/// [`Scalar::fast_path`] picks one by type. Internal to vectrix: the implementors are unit
/// structs next to their kernels (e.g. vectrix-rotation's `f64::log`).
#[doc(hidden)]
pub trait FastPath {
    /// The arguments, as one value (references carry the implementor's lifetime).
    type Input<T: Scalar>;
    /// The result.
    type Output<T: Scalar>;
    /// The code for every scalar (dual numbers, `f32`).
    fn generic<T: Scalar>(x: Self::Input<T>) -> Self::Output<T>;
    /// The `f64` kernel.
    fn f64(x: Self::Input<f64>) -> Self::Output<f64>;
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
    #[inline(always)]
    fn fast_sin_cos(self) -> (f64, f64) {
        vmath::sin_cos_or_libm(self)
    }
    #[inline(always)]
    fn fast_sin_cos3(x: [f64; 3]) -> [(f64, f64); 3] {
        if !x.iter().all(|a| a.abs() <= vmath::SIN_COS_MAX) {
            return x.map(f64::sin_cos);
        }
        // four lanes (one idle), so that the loop maps onto 256-bit registers
        let lanes = [x[0], x[1], x[2], 0.0];
        let (mut s, mut c) = ([0.0; 4], [0.0; 4]);
        for k in 0..4 {
            (s[k], c[k]) = vmath::sin_cos::<{ vectrix_simd::FUSED }>(lanes[k]);
        }
        [(s[0], c[0]), (s[1], c[1]), (s[2], c[2])]
    }
    #[inline]
    fn fast_sin_cos_slices(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
        vmath::sin_cos_slices(x, sin, cos);
    }
    #[inline(always)]
    fn fast_atan2(self, x: f64) -> f64 {
        vmath::atan2_or_libm(self, x)
    }
    #[inline(always)]
    fn fast_cos_sinc_of_square(self) -> Option<(f64, f64)> {
        (self.abs() <= vmath::HALF_PI_SQUARED)
            .then(|| vmath::cos_sinc_of_square::<{ vectrix_simd::FUSED }>(self))
    }
    #[inline(always)]
    fn fast_path<P: FastPath>(x: P::Input<f64>) -> P::Output<f64> {
        P::f64(x)
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

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::Dual64;

    /// The hard angles of DESIGN §6 and their neighbours in every quadrant, plus the ends of
    /// the kernels' range and the special values.
    fn hard_angles() -> Vec<f64> {
        let pi = core::f64::consts::PI;
        let mut x = vec![0.0, -0.0, 1e-300, 5e-324, 1e-16, 1e-8, pi - 1e-8, pi, pi / 2.0, 2e5, 2.1e5];
        x.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
        let n = x.len();
        for k in 0..n {
            x.push(-x[k]);
        }
        x.extend((-40..=40).map(|k| f64::from(k) * 0.1 + 1e-3));
        x
    }

    fn same(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    /// The `f64` hooks return the bits of the kernels they stand for (the fdlibm kernel with
    /// the build's fusion, `libm` outside its range), one and three at a time and over slices;
    /// and the generic default, which dual numbers take, carries the same value within 1 ulp
    /// (libm against fdlibm: a different formula, each within 1 ulp of the truth).
    #[test]
    fn f64_sin_cos_hooks_match_their_kernels_and_the_generic_code() {
        let x = hard_angles();
        let (mut s, mut c) = (vec![0.0; x.len()], vec![0.0; x.len()]);
        f64::fast_sin_cos_slices(&x, &mut s, &mut c);
        for (k, &xk) in x.iter().enumerate() {
            let (fs, fc) = xk.fast_sin_cos();
            let want = vmath::sin_cos_or_libm(xk);
            assert!(same(fs, want.0) && same(fc, want.1), "x = {xk:e}");
            assert!(same(s[k], fs) && same(c[k], fc), "slices at x = {xk:e}");
            let [a, b, d] = f64::fast_sin_cos3([xk, 0.5, -xk]);
            assert!(same(a.0, fs) && same(a.1, fc) && same(d.1, fc), "three at x = {xk:e}");
            assert!(same(b.0, 0.5f64.fast_sin_cos().0));
            let (ds, dc) = Dual64::from(xk).fast_sin_cos();
            if xk.is_finite() {
                let tol = 2.0 * f64::EPSILON;
                assert!((ds.re - fs).abs() <= tol && (dc.re - fc).abs() <= tol, "dual at x = {xk:e}");
            }
        }
    }

    /// atan2 of the hard pairs: the `f64` hook is the kernel (or `libm` at the special
    /// arguments, bit for bit), within 1 ulp of the generic `libm` path everywhere.
    #[test]
    fn f64_atan2_hook_matches_its_kernel_and_the_generic_code() {
        let x = hard_angles();
        for &y in &x {
            for &xx in &[1.0, -1.0, 0.0, -0.0, 1e-300, -1e300, f64::NAN, f64::INFINITY] {
                let got = y.fast_atan2(xx);
                assert!(same(got, vmath::atan2_or_libm(y, xx)), "atan2({y:e}, {xx:e})");
                let generic = Dual64::from(y).fast_atan2(Dual64::from(xx)).re;
                let tol = 2.0 * f64::EPSILON * generic.abs();
                assert!(same(got, generic) || (got - generic).abs() <= tol, "atan2({y:e}, {xx:e})");
            }
        }
    }

    /// cos h and sin h / h from h²: the `f64` series up to (π/2)², `None` beyond and for the
    /// generic scalars.
    #[test]
    fn f64_cos_sinc_hook_covers_the_series_range_only() {
        let edge = vmath::HALF_PI_SQUARED;
        for u in [0.0, 1e-300, 1e-16, 1e-8, 1.0, edge] {
            let (c, s) = u.fast_cos_sinc_of_square().expect("in range");
            let h = u.sqrt();
            assert!((c - h.cos()).abs() <= 2.0 * f64::EPSILON, "u = {u:e}");
            let sinc = if h == 0.0 { 1.0 } else { h.sin() / h };
            assert!((s - sinc).abs() <= 4.0 * f64::EPSILON, "u = {u:e}");
        }
        assert!(edge.next_up().fast_cos_sinc_of_square().is_none());
        assert!(f64::NAN.fast_cos_sinc_of_square().is_none());
        let (ch, sh) = (-1.0f64).fast_cos_sinc_of_square().expect("in range");
        assert!(
            (ch - 1f64.cosh()).abs() <= 2.0 * f64::EPSILON * ch
                && (sh - 1f64.sinh()).abs() <= 2.0 * f64::EPSILON
        );
        assert!((-edge).next_down().fast_cos_sinc_of_square().is_none());
        assert!(Dual64::from(0.5).fast_cos_sinc_of_square().is_none());
    }
}
