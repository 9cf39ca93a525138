//! The ninth root of a scaled error estimate, for Vern9's step-size factor (HNW (4.13):
//! exponent 1/(q + 1), q = 8). A factor that the controller clamps to [1/6, 3] and multiplies
//! by a safety factor needs a few digits, not libm's last bit; two `cbrt` calls cost about 300
//! instructions a step, on the path from one step's error to the next step's stages (DOP853's
//! eighth root, three square roots, is a few instructions: the same scheme gained it nothing
//! measurable).

/// 2^(r/9), r = 0..8 (mpmath, rounded to the nearest double).
const TWO_POW_NINTHS: [f64; 9] = [
    1.0,
    1.080_059_738_892_306,
    1.166_529_039_576_116_5,
    1.259_921_049_894_873_2,
    1.360_790_000_174_377,
    1.469_734_492_275_598_8,
    1.587_401_051_968_199_6,
    1.714_487_965_706_145_6,
    1.851_749_424_574_581,
];

/// Coefficients in t = 2m − 3 ∈ [−1, 1) of the Chebyshev fit of degree 4 to m^(1/9) on
/// [1, 2) (numpy `chebfit`, converted to powers of t): relative error below 1.29e-5.
const M_NINTH: [f64; 5] = [
    1.046_081_412_517_522_6,
    0.038_723_971_687_430_005,
    -0.005_729_347_701_013_758,
    0.001_294_781_648_535_167_2,
    -0.000_320_499_764_225_829_45,
];

/// The bound on the relative error of [`ninth_root`] in [`LO`, `HI`].
#[cfg(test)]
const BOUND: f64 = 1.3e-5;

/// The smallest and largest x taken as they are, 2⁻³⁶ and 2²⁷: beyond, the factor meets its
/// clamps (err^(1/9)/0.8 leaves [1/6, 3] for err below 1.3e-8 and above 2.7e3).
const LO: f64 = 1.455_191_522_836_685_2e-11;
const HI: f64 = 134_217_728.0;

/// x^(1/9) to 1.3e-5 relative for x in [2⁻³⁶, 2²⁷]; outside, the root of the nearer end;
/// NaN stays NaN. With x = 2ᵉ·m, m ∈ [1, 2): 2^(e/9) from the split e + 45 = 9q + r (a power
/// of two times 2^(r/9)) and m^(1/9) from a quartic, so that the whole is a few integer
/// operations and a dozen floating-point ones, without a branch but NaN's.
#[inline(always)]
pub(crate) fn ninth_root(x: f64) -> f64 {
    const N: usize = 9;
    if x.is_nan() {
        return x;
    }
    let bits = x.clamp(LO, HI).to_bits();
    // e + 5N ∈ [9, 72] for x in [2⁻³⁶, 2²⁷]
    let e = ((bits >> 52) as i64 - 1023 + 5 * N as i64) as usize;
    let (q, r) = (e / N, e % N);
    let m = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52));
    let t = 2.0 * m - 3.0;
    let c = &M_NINTH;
    let p = (c[0] + c[1] * t) + (t * t) * ((c[2] + c[3] * t) + c[4] * (t * t));
    // 2^(q − 5), q ∈ [0, 9]: a normal power of two
    let scale = f64::from_bits(((q as u64) + 1023 - 5) << 52);
    p * TWO_POW_NINTHS[r % N] * scale
}

#[cfg(test)]
mod tests {
    use super::{BOUND, HI, LO, ninth_root};

    /// Against `powf(1/9)` over the whole range, at the exponent boundaries and inside each
    /// binade; the ends and beyond; NaN stays NaN.
    #[test]
    fn ninth_root_is_within_its_bound() {
        assert_eq!(LO, 2f64.powi(-36));
        assert_eq!(HI, 2f64.powi(27));
        let mut x = LO;
        let mut worst = 0.0f64;
        while x <= HI {
            for y in [x, x.next_up(), (2.0 * x).next_down(), x * 1.5] {
                let rel = (ninth_root(y) / y.min(HI).powf(1.0 / 9.0) - 1.0).abs();
                assert!(rel <= BOUND, "x = {y:e}: relative error {rel:e}");
                worst = worst.max(rel);
            }
            x *= 1.37;
        }
        assert!(worst > 1e-6, "the bound is the fit's, not a lucky sample: {worst:e}");
        for (x, want) in [(0.0, LO), (1e-300, LO), (1e300, HI), (f64::INFINITY, HI)] {
            assert_eq!(ninth_root(x).to_bits(), ninth_root(want).to_bits(), "x = {x:e}");
        }
        assert!(ninth_root(f64::NAN).is_nan());
        assert!((ninth_root(1.0) - 1.0).abs() <= BOUND);
        assert!((ninth_root(512.0) - 2.0).abs() <= 2.0 * BOUND);
    }
}
