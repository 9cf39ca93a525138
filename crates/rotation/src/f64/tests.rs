//! The `f64` fast paths of the rotation layer against the code every other scalar runs, on
//! the hard sets (θ ∈ {0, 1e-300, 1e-16, 1e-8, π − 1e-8, π}, gimbal lock): bit for bit where
//! the fast path is the same formula; where it is another (fdlibm's sine, cosine and atan2
//! against `libm`'s, each within 1 ulp of the truth; the Taylor series of the exponential map),
//! within the bound each test states. The generic code runs through `Dual64`, whose hooks take
//! the generic defaults; its real part is the value compared.

use nalgebra::{Matrix3, Vector3};
use num_dual::Dual64;

use crate::{EulerAngles, EulerSequence, Quaternion};

const EPS: f64 = f64::EPSILON;

/// Hard rotations: tiny and half-turn angles about the hard axes, and random unit
/// quaternions with every component the largest.
fn hard_quaternions() -> Vec<Quaternion<f64>> {
    let pi = core::f64::consts::PI;
    let mut qs = Vec::new();
    for n in [
        Vector3::new(1.0, 0.0, 0.0),
        Vector3::new(0.0, -1.0, 0.0),
        Vector3::new(0.0, 0.0, 1.0),
        Vector3::new(1.0, 2.0, 2.0) / 3.0,
        Vector3::new(-0.3, 0.1, 0.95).normalize(),
        Vector3::new(0.0, -1.0, 1e-9).normalize(),
    ] {
        for th in [0.0, 1e-300, 1e-16, 1e-8, 1e-4, 0.5, 1.5, 2.0, 3.0, pi - 1e-8, pi] {
            qs.push(Quaternion::from_axis_angle(&n, th).unwrap());
        }
    }
    let mut s = 0x9E37_79B9_7F4A_7C15u64;
    let mut rng = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for _ in 0..2000 {
        let q = Quaternion::new(rng(), rng(), rng(), rng());
        qs.push(q * (1.0 / q.norm()));
    }
    qs
}

/// Shepperd with the sign folded into the scale returns the bits of the textbook
/// normalisation (q/|q|, then the canonical sign): the same pivot, the same norm (no
/// scaling is needed for a rotation), the same canonical sign, also at η = 0.
#[test]
fn shepperd_matches_the_normalised_canonical_pivot_bitwise() {
    let mut mats: Vec<Matrix3<f64>> = hard_quaternions().iter().map(|q| q.rotation_matrix()).collect();
    // exact half-turns: η = 0 in every pivot, the canonical sign decides
    mats.extend([
        Matrix3::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0),
        Matrix3::new(-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0),
        Matrix3::new(-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0),
        Matrix3::new(
            -1.0 / 9.0,
            4.0 / 9.0,
            -8.0 / 9.0,
            4.0 / 9.0,
            -7.0 / 9.0,
            -4.0 / 9.0,
            -8.0 / 9.0,
            -4.0 / 9.0,
            -1.0 / 9.0,
        ),
    ]);
    for r in &mats {
        let q = Quaternion::shepperd_unnormalized(r);
        let want = (q * (1.0 / q.norm())).canonical();
        let got = Quaternion::from_rotation_matrix_unchecked(r);
        let bits = |q: Quaternion<f64>| [q.a, q.b, q.c, q.d].map(f64::to_bits);
        assert_eq!(bits(got), bits(want), "{r:?}");
        assert!(got.a >= 0.0);
    }
    let nan = Quaternion::from_rotation_matrix_unchecked(&Matrix3::from_element(f64::NAN));
    assert!(nan.a.is_nan());
}

/// 𝓡(q) with the doubled factors returns the bits of the textbook 1 − 2(c² + d²), 2(bc − ad), …
#[test]
fn rotation_matrix_matches_the_doubled_entries_bitwise() {
    for q in hard_quaternions() {
        let (a, b, c, d) = (q.a, q.b, q.c, q.d);
        let want = Matrix3::new(
            1.0 - 2.0 * (c * c + d * d),
            2.0 * (b * c - a * d),
            2.0 * (a * c + b * d),
            2.0 * (a * d + b * c),
            1.0 - 2.0 * (b * b + d * d),
            2.0 * (c * d - a * b),
            2.0 * (b * d - a * c),
            2.0 * (a * b + c * d),
            1.0 - 2.0 * (b * b + c * c),
        );
        let got = q.rotation_matrix();
        for (g, w) in got.iter().zip(want.iter()) {
            assert_eq!(g.to_bits(), w.to_bits(), "{q:?}");
        }
    }
}

/// The hard angles of DESIGN §6, both signs, beyond π and beyond the kernels' range.
fn hard_angles() -> Vec<f64> {
    let pi = core::f64::consts::PI;
    let mut t =
        vec![0.0, 1e-300, 1e-16, 1e-8, 1e-4, 0.5, 1.5, 3.0, pi - 1e-8, pi, 3.5, 2.0 * pi, 10.0, 4e5, 5e5];
    let n = t.len();
    for k in 0..n {
        t.push(-t[k]);
    }
    t
}

fn hard_axes() -> [Vector3<f64>; 4] {
    [
        Vector3::new(1.0, 0.0, 0.0),
        Vector3::new(1.0, 2.0, 2.0) / 3.0,
        Vector3::new(-0.3, 0.1, 0.95).normalize(),
        Vector3::new(0.0, -1.0, 1e-9).normalize(),
    ]
}

fn lift(v: &Vector3<f64>) -> Vector3<Dual64> {
    v.map(Dual64::from)
}

fn re_q(q: Quaternion<Dual64>) -> Quaternion<f64> {
    Quaternion::new(q.a.re, q.b.re, q.c.re, q.d.re)
}

fn bits(q: Quaternion<f64>) -> [u64; 4] {
    [q.a, q.b, q.c, q.d].map(f64::to_bits)
}

/// Axis-angle → quaternion: the `f64` result is, bit for bit, (cos θ/2, sin θ/2 n̂) from the
/// fdlibm kernel it stands for (`libm` beyond its range), canonical; the generic code's
/// (libm's sine and cosine) is within 2ε per component (two values within 1 ulp of one number
/// of magnitude ≤ 1).
#[test]
fn f64_axis_angle_matches_its_kernel_and_the_generic_code() {
    for n in hard_axes() {
        for th in hard_angles() {
            let got = Quaternion::from_axis_angle(&n, th).unwrap();
            let (s, c) = vectrix_simd::vmath::sin_cos_or_libm(th * 0.5);
            let q = Quaternion::from_parts(c, n * s);
            assert_eq!(bits(got), bits(if c <= 0.0 { q.canonical() } else { q }), "θ = {th:e}");
            let generic = re_q(Quaternion::from_axis_angle(&lift(&n), Dual64::from(th)).unwrap());
            assert!(
                (got.to_vector4() - generic.to_vector4()).amax() <= 2.0 * EPS,
                "θ = {th:e}: {got:?} vs {generic:?}"
            );
            assert!(got.a >= 0.0);
        }
    }
    assert!(Quaternion::from_axis_angle(&Vector3::zeros(), 1.0).is_err());
    assert!(Quaternion::from_axis_angle(&Vector3::new(1.0, 0.0, 0.0), f64::NAN).is_err());
    assert!(Quaternion::from_axis_angle(&Vector3::new(f64::NAN, 0.0, 0.0), 1.0).is_err());
}

/// Angle vector → quaternion: the `f64` series in h² (|Θ| ≤ π) or fdlibm's kernels (beyond)
/// against libm's sine and cosine of h = |Θ|/2: within 4ε·max(|Θ|, 1) per component (the
/// bound of the batched map, `tests/hard_cases.rs`). Then back (the log, through atan2):
/// within 4ε·|Θ|, and bit for bit below the series switch, where no atan2 runs.
#[test]
fn f64_exp_and_log_match_the_generic_code() {
    for n in hard_axes() {
        for th in hard_angles() {
            let v = n * th;
            let got = Quaternion::from_angle_vector(&v);
            let generic = re_q(Quaternion::from_angle_vector(&lift(&v)));
            let err = (got.to_vector4() - generic.to_vector4()).amax();
            assert!(err <= 4.0 * EPS * th.abs().max(1.0), "Θ = {v:?}: {got:?} vs {generic:?}");
            let log = got.angle_vector();
            let dual = Quaternion::<Dual64>::new(got.a.into(), got.b.into(), got.c.into(), got.d.into());
            let want = dual.angle_vector().map(|x| x.re);
            if got.epsilon().norm_squared() < 1e-10 * got.a * got.a {
                assert_eq!(log.map(f64::to_bits), want.map(f64::to_bits), "Θ = {v:?}");
            }
            assert!((log - want).amax() <= 4.0 * EPS * want.amax(), "Θ = {v:?}: {log:?} vs {want:?}");
            let angle = got.axis_angle().angle();
            let angle_generic = dual.axis_angle().angle().re;
            assert!((angle - angle_generic).abs() <= 2.0 * EPS * angle_generic, "Θ = {v:?}");
        }
    }
}

/// Quaternions at and near gimbal lock in every sequence (β = ±π/2 Tait–Bryan, 0 or π
/// symmetric, and 1e-8 and 1e-4 away), and the hard rotations.
fn lock_quaternions(seq: EulerSequence) -> Vec<Quaternion<f64>> {
    let half_pi = core::f64::consts::FRAC_PI_2;
    let locks: &[f64] =
        if seq.axes()[0] == seq.axes()[2] { &[0.0, core::f64::consts::PI] } else { &[half_pi, -half_pi] };
    let mut qs = hard_quaternions();
    for &b in locks {
        for d in [0.0, 1e-8, -1e-8, 1e-4] {
            for (a, c) in [(0.3, -1.2), (2.0, 0.0), (-3.0, 3.0)] {
                qs.push(EulerAngles::new(seq, [a, b + d, c]).quaternion());
            }
        }
    }
    qs
}

/// Quaternion → Euler angles through the atan2 hook, and Euler angles → quaternion through the
/// three-at-once sine and cosine: the `f64` angles within 8ε of the generic code's (a sum or
/// difference of two atan2, each within 1 ulp of its value ≤ π, i.e. 2ε, on each side), the
/// same regular or gimbal-lock variant (decided by exact comparisons of hypot values, which
/// no hook touches), and the quaternions within 8ε.
#[test]
fn f64_euler_angles_match_the_generic_code_through_gimbal_lock() {
    for seq in EulerSequence::ALL.into_iter().flat_map(|s| [s, s.extrinsic()]) {
        for q in lock_quaternions(seq) {
            let dual = Quaternion::<Dual64>::new(q.a.into(), q.b.into(), q.c.into(), q.d.into());
            let got = EulerAngles::from_quaternion(&q, seq);
            let generic = EulerAngles::from_quaternion(&dual, seq);
            assert_eq!(got.is_gimbal_lock(), generic.is_gimbal_lock(), "{seq:?} {q:?}");
            let (a, b) = (got.principal().angles, generic.principal().angles.map(|x| x.re));
            for (x, y) in a.iter().zip(&b) {
                let d = crate::series::wrap_near(x - y).abs();
                assert!(d <= 8.0 * EPS, "{seq:?} {q:?}: {a:?} vs {b:?}");
            }
            let back = EulerAngles::new(seq, a).quaternion();
            let back_generic = re_q(EulerAngles::new(seq, a.map(Dual64::from)).quaternion());
            let err = (back.to_vector4() - back_generic.to_vector4()).amax();
            assert!(err <= 8.0 * EPS, "{seq:?} {a:?}: {back:?} vs {back_generic:?}");
        }
    }
}
