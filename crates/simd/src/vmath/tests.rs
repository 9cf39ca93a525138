//! The kernels against libm (within their ulp bounds) and the dispatched slices against the
//! kernels (bit for bit).

use super::*;

/// One ulp of |x| (the spacing of doubles at x; 2⁻¹⁰⁷⁴ for subnormals).
fn ulp(x: f64) -> f64 {
    let e = x.abs().to_bits() >> 52;
    if e > 52 {
        f64::from_bits((e - 52) << 52)
    } else if e >= 1 {
        f64::from_bits(1 << (e - 1))
    } else {
        f64::from_bits(1)
    }
}

/// |a − reference| in ulps of the reference.
fn ulps(a: f64, reference: f64) -> f64 {
    if a == reference { 0.0 } else { (a - reference).abs() / ulp(reference) }
}

fn xorshift(s: &mut u64) -> f64 {
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    (*s >> 11) as f64 / (1u64 << 53) as f64
}

/// Hard arguments for sin/cos: 0, tiny, near every multiple of π/4 up to 2·10⁵, random.
fn sin_cos_args() -> Vec<f64> {
    let mut xs = vec![0.0, -0.0, 1e-300, 5e-324, 1e-16, 1e-8, 1e-4, SIN_COS_MAX, -SIN_COS_MAX];
    for k in 1..400 {
        let m = k as f64 * core::f64::consts::FRAC_PI_4;
        let mut x = m;
        for _ in 0..6 {
            xs.extend([x, -x]);
            x = x.next_up();
        }
        x = m;
        for _ in 0..6 {
            x = x.next_down();
            xs.extend([x, -x]);
        }
    }
    for &big in &[1e3, 1e4, 1.0e5, 1.99e5] {
        let n = (big / core::f64::consts::FRAC_PI_2).round();
        let x = n * core::f64::consts::FRAC_PI_2;
        xs.extend([x, x.next_up(), x.next_down(), -x]);
    }
    let mut s = 0x1234_5678_9ABC_DEF1u64;
    for _ in 0..20_000 {
        xs.push((xorshift(&mut s) - 0.5) * 20.0);
        xs.push((xorshift(&mut s) - 0.5) * 2.0 * SIN_COS_MAX);
    }
    xs
}

/// Worst distance (sin, cos) in ulps from libm over the hard arguments; signs must agree.
fn worst_sin_cos<const F: bool>() -> (f64, f64) {
    let (mut worst_s, mut worst_c) = (0.0f64, 0.0f64);
    for x in sin_cos_args() {
        let (s, c) = sin_cos::<F>(x);
        let (sr, cr) = x.sin_cos();
        worst_s = worst_s.max(ulps(s, sr));
        worst_c = worst_c.max(ulps(c, cr));
        assert!(s.is_sign_negative() == sr.is_sign_negative() || s == 0.0, "sin sign at {x:e}");
    }
    (worst_s, worst_c)
}

/// Both are within 1 ulp of the true value, so within 2 ulps of each other (measured: 1).
#[test]
fn sin_cos_matches_libm_within_two_ulps() {
    for (fused, (s, c)) in [(false, worst_sin_cos::<false>()), (true, worst_sin_cos::<true>())] {
        assert!(s <= 2.0 && c <= 2.0, "fused = {fused}: worst sin {s} ulp, cos {c} ulp");
    }
}

/// Hard pairs for atan2: both axes, ±0, every interval boundary of p/q, every octant.
fn atan2_args() -> Vec<(f64, f64)> {
    let mut v = Vec::new();
    for &(y, x) in &[
        (0.0, 1.0),
        (-0.0, 1.0),
        (0.0, -1.0),
        (-0.0, -1.0),
        (1.0, 0.0),
        (1.0, -0.0),
        (-1.0, 0.0),
        (-1.0, -0.0),
        (1e-300, 1.0),
        (1.0, 1e-300),
        (1e-300, -1.0),
        (5e-324, 1.0),
        (1.0, 1.0),
        (-1.0, -1.0),
    ] {
        v.push((y, x));
    }
    for &r in &[0.4375f64, 0.6875, 1.1875, 2.4375, 1.0, 0.5, 1.5] {
        let mut t = r;
        for _ in 0..4 {
            for (sy, sx) in [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)] {
                v.push((sy * t, sx * 1.0));
                v.push((sy * t * 0.3, sx * 0.3));
            }
            t = t.next_up();
        }
    }
    let mut s = 0xDEAD_BEEF_CAFE_F00Du64;
    for _ in 0..40_000 {
        let y = xorshift(&mut s) * 2.0 - 1.0;
        let x = xorshift(&mut s) * 2.0 - 1.0;
        v.push((y, x));
        v.push((y * 1e-8, x));
        v.push((y, x * 1e-8));
    }
    v
}

/// Worst distance in ulps from libm over the hard pairs; signs must agree.
fn worst_atan2<const F: bool>() -> f64 {
    let mut worst = 0.0f64;
    for (y, x) in atan2_args() {
        let a = atan2::<F>(y, x);
        let r = y.atan2(x);
        assert_eq!(a.is_sign_negative(), r.is_sign_negative(), "sign of atan2({y:e}, {x:e})");
        worst = worst.max(ulps(a, r));
    }
    worst
}

/// Within 2 ulps of libm (each within 1 ulp of the truth; measured: 1).
#[test]
fn atan2_matches_libm_within_two_ulps() {
    for (fused, worst) in [(false, worst_atan2::<false>()), (true, worst_atan2::<true>())] {
        assert!(worst <= 2.0, "fused = {fused}: worst atan2 {worst} ulp");
    }
}

/// The hook's atan2 on every pair of hostile values (zeros, subnormals, the ends of
/// [`ATAN2_RANGE`] and beyond, ±∞, NaN): libm's value, bit for bit outside the range and
/// within 2 ulps inside.
#[test]
fn atan2_or_libm_matches_libm_on_hostile_pairs() {
    let v = [
        0.0,
        5e-324,
        f64::MIN_POSITIVE,
        1e-300,
        1e-270,
        1e-200,
        0.75,
        1.0,
        1e300,
        1.7e308,
        f64::MAX,
        f64::INFINITY,
        f64::NAN,
    ];
    for &a in &v {
        for &b in &v {
            for (y, x) in [(a, b), (-a, b), (a, -b), (-a, -b)] {
                let (got, want) = (atan2_or_libm(y, x), y.atan2(x));
                let ok = got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan());
                assert!(ok || ulps(got, want) <= 2.0, "atan2({y:e}, {x:e}) = {got:e}, libm {want:e}");
            }
        }
    }
}

/// The hard set of the joint angles: zeros of both signs, subnormals, tiny and huge,
/// multiples of π/2 and their neighbours (where the reduction cancels), the reduction's
/// boundary 2·10⁵ and beyond, and the non-finite values; plus a pseudo-random sweep.
fn joint_angles() -> Vec<f64> {
    let mut x = vec![0.0, -0.0, 5e-324, -1e-310, 1e-20, 2e5, -2e5, 2e5 + 1e-10, 1e6, -3e8, 1e300];
    x.extend([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
    for k in -8i32..=8 {
        let m = f64::from(k) * core::f64::consts::FRAC_PI_2;
        x.extend([m, m.next_up(), m.next_down()]);
    }
    let mut seed = 0x2545_f491_4f6c_dd1d;
    x.extend((0..257).map(|_| 80.0 * (xorshift(&mut seed) - 0.5)));
    x
}

/// The dispatched slices (AVX2 here when the CPU has it) and the portable body give the
/// bits of [`sin_cos_or_libm`] element by element, NaN's class included: the run-time
/// choice of instructions changes no bit.
/// Every short length (whole blocks of four, a padded last block, both) gives the bits of
/// [`sin_cos_or_libm`] element by element, and writes nothing past the slice.
#[test]
fn short_sin_cos_slices_are_sin_cos_element_by_element() {
    let x = joint_angles();
    for n in 0..=9 {
        let (mut s, mut c) = (vec![7.0; n + 1], vec![7.0; n + 1]);
        sin_cos_slices(&x[..n], &mut s[..n], &mut c[..n]);
        assert_eq!((s[n], c[n]), (7.0, 7.0), "n = {n}: wrote past the slice");
        for k in 0..n {
            let (ws, wc) = sin_cos_or_libm(x[k]);
            for (got, want) in [(s[k], ws), (c[k], wc)] {
                assert!(
                    got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                    "n = {n}, x = {:e}: got {got:e}, want {want:e}",
                    x[k]
                );
            }
        }
    }
}

#[test]
fn sin_cos_slices_is_sin_cos_element_by_element() {
    let x = joint_angles();
    let n = x.len();
    let (mut s, mut c) = (vec![0.0; n], vec![0.0; n]);
    sin_cos_slices(&x, &mut s, &mut c);
    let (mut s2, mut c2) = (vec![0.0; n], vec![0.0; n]);
    sin_cos_all(&x, &mut s2, &mut c2);
    for k in 0..n {
        let (ws, wc) = sin_cos_or_libm(x[k]);
        for (got, want) in [(s[k], ws), (c[k], wc), (s2[k], ws), (c2[k], wc)] {
            assert!(
                got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                "x = {:e}: got {got:e}, want {want:e}",
                x[k]
            );
        }
    }
}
