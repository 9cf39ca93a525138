//! # vectrix-simd: what the `f64` fast paths of vectrix share (internal)
//!
//! Not part of vectrix's API (it may change in any release): the layers reach it through
//! `Scalar`'s hooks and their own `f64` kernels. It holds, once each:
//! - [`FUSED`], [`FUSED_LOOPS`] and [`madd`]: whether the kernels fuse multiply–add, fixed
//!   when this crate is compiled;
//! - [`dispatch!`]: a loop compiled for AVX2 beside the portable build, the CPU choosing
//!   between them when the program runs;
//! - [`vmath`]: branch-free fdlibm sine, cosine and atan2, and the Taylor series of cos h and
//!   sin h / h in h², that loops over them can vectorise.
//!
//! # Reproducibility
//! The same build gives the same bits on every CPU of its target: whether a kernel fuses is
//! decided at compile time ([`FUSED`], [`FUSED_LOOPS`]), and the run-time choice of
//! [`dispatch!`] only picks the instructions that compute those operations (IEEE 754 rounds
//! every `+ − × ÷ √` and every fused multiply–add exactly once, in whatever register width,
//! and `f64::mul_add` is correctly rounded also where the C library computes it). Rust never
//! contracts `a * b + c` into a fused multiply–add by itself, so a build for FMA fuses only
//! where a kernel asks for it with [`madd`].
#![warn(missing_docs)]

pub mod vmath;

/// `true` when the one-value kernels fuse multiply–add (those inlined into the caller: sine,
/// cosine, atan2, the series of the exponential map, the matrix log): where the build enables
/// the instruction, on aarch64 (every CPU has it) and on x86-64 built with
/// `-C target-feature=+fma` (or a `target-cpu` that has it). Fixed at compile time.
pub const FUSED: bool = cfg!(any(target_feature = "fma", target_arch = "aarch64"));

/// `true` when the SIMD loops of [`dispatch!`] fuse multiply–add (the batched conversions,
/// Hooke's law over many strains, the frequency-response grid): as [`FUSED`], and also with
/// the `fma` feature, for which the dispatcher picks the FMA instruction where the CPU has it
/// (elsewhere the C library's `fma` gives the same bits, slowly). Fixed at compile time.
pub const FUSED_LOOPS: bool = FUSED || cfg!(feature = "fma");

/// a·b + c, fused (one rounding) when `F`, else rounded twice; the kernels take `F` =
/// [`FUSED`] or [`FUSED_LOOPS`], and their tests both.
#[inline(always)]
pub fn madd<const F: bool>(a: f64, b: f64, c: f64) -> f64 {
    if F { a.mul_add(b, c) } else { a * b + c }
}

/// Defines `fn name(args) -> R` that runs `body(args)` compiled for AVX2 where the CPU has it
/// (AVX2 and FMA when [`FUSED_LOOPS`]), detected when the program runs, and the portable build
/// otherwise. `body` is an `#[inline(always)]` function (or a path with its generic arguments,
/// `exp_all::<FUSED_LOOPS>`), so that each build inlines its own copy.
///
/// Only the instructions differ between the builds, never a result's bits (see the crate
/// docs): every build computes the same IEEE operations, fused exactly where `body` says
/// [`madd::<true>`](madd).
///
/// ```
/// #[inline(always)]
/// fn double_all(x: &mut [f64]) {
///     x.iter_mut().for_each(|v| *v *= 2.0);
/// }
/// vectrix_simd::dispatch! {
///     /// Doubles every element, four lanes at a time where the CPU has AVX2.
///     fn double(x: &mut [f64]) = double_all;
/// }
/// let mut x = [1.0, 2.5];
/// double(&mut x);
/// assert_eq!(x, [2.0, 5.0]);
/// ```
#[macro_export]
macro_rules! dispatch {
    ($(#[$attr:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? = $body:expr;) => {
        $(#[$attr])*
        $vis fn $name($($arg: $ty),*) $(-> $ret)? {
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx2,fma")]
                fn avx2_fma($($arg: $ty),*) $(-> $ret)? {
                    $body($($arg),*)
                }
                #[target_feature(enable = "avx2")]
                fn avx2($($arg: $ty),*) $(-> $ret)? {
                    $body($($arg),*)
                }
                if $crate::FUSED_LOOPS {
                    if ::std::is_x86_feature_detected!("avx2") && ::std::is_x86_feature_detected!("fma") {
                        // SAFETY: AVX2 and FMA were detected on this CPU just above.
                        return unsafe { avx2_fma($($arg),*) };
                    }
                } else if ::std::is_x86_feature_detected!("avx2") {
                    // SAFETY: AVX2 was detected on this CPU just above.
                    return unsafe { avx2($($arg),*) };
                }
            }
            $body($($arg),*)
        }
    };
}
