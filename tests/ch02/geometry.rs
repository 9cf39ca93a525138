//! §2.1–2.5: angles, dot and cross products, directed angles, frames and resolution; the
//! property tests of frame independence for vectors, covectors and dyadics (`mod prop`).
//! Physical matrices (§2.6–2.10) are in `matrices.rs`, nonstandard frames and gradients
//! (§2.23–2.24) in `nonstandard.rs`.

use crate::support::NanAmax;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

use vectrix::frames::FrameError;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

use crate::support::*;

/// A frame B turned from the first frame about a generic axis (no special alignment).
pub fn frame_b() -> (Frame, Frame) {
    let a = Frame::new();
    let r = Rotor::from_axis_angle(&a.vector([1.0, -2.0, 0.5]), 0.7).expect("nonzero axis");
    let b = a.rotated_by_rotor(&r);
    (a, b)
}

/// Components of a resolved vector as an array, for the slice assertions of `support`.
pub fn arr(x: Vector3<f64>) -> [f64; 3] {
    [x.x, x.y, x.z]
}

/// Asserts two 3 × 3 matrices agree entrywise: max |got − want| ≤ tol.
#[track_caller]
pub fn assert_mat_abs(got: &Matrix3<f64>, want: &Matrix3<f64>, tol: f64) {
    assert_abs_slice(got.as_slice(), want.as_slice(), tol);
}

/// Asserts max |got − want| ≤ tol·max|want| over the entries (relative to the largest entry).
#[track_caller]
pub fn assert_mat_rel(got: &Matrix3<f64>, want: &Matrix3<f64>, tol: f64) {
    assert_rel_slice(got.as_slice(), want.as_slice(), tol);
}

/// Fact 2.1.1: congruence mod 2π. i) a ≡ b ⟺ a − b ≡ 0; ii) ⟺ −a ≡ −b; iii) na ≡ nb;
/// iv) a ≡ nπ ⟺ a ≡ mπ for n + m even; v) a ≡ −a ⟺ a = nπ; viii) sums of congruences.
#[test]
fn fact_2_1_1_congruence_mod_2pi() {
    let tol = 16.0 * EPS * TAU;
    let (a, b) = (0.3, 0.3 + 3.0 * TAU);
    assert!(congruent(a, b, tol));
    assert!(congruent(a - b, 0.0, tol)); // i
    assert!(congruent(-a, -b, tol)); // ii
    assert!(congruent(5.0 * a, 5.0 * b, 64.0 * tol)); // iii (5·3·2π carries more rounding)
    assert!(congruent(PI, 3.0 * PI, tol) && congruent(PI, -PI, tol)); // iv: 1 + 3, 1 − 1 even
    assert!(!congruent(PI, 2.0 * PI, 1e-6)); // iv: 1 + 2 odd
    assert!(congruent(PI, -PI, tol) && !congruent(1.0, -1.0, 1e-6)); // v
    let (c, d) = (-2.0, -2.0 - TAU);
    assert!(congruent(a + c, b + d, 64.0 * tol)); // viii
}

/// §2.3: a wrapped angle lies in (−π, π]: π is included and −π is not.
#[test]
fn sec_2_3_wrapped_angle_interval() {
    assert_eq!(wrap_angle(PI), PI);
    assert_eq!(wrap_angle(-PI), PI);
    assert_rel(wrap_angle(3.0 * PI), PI, 8.0 * EPS);
    assert_rel(wrap_angle(-FRAC_PI_2 - TAU), -FRAC_PI_2, 8.0 * EPS);
    for k in -50..50 {
        let w = wrap_angle(0.1 * f64::from(k));
        assert!(w > -PI && w <= PI, "{w}");
    }
}

/// (2.1.1)–(2.1.4), L497: x·y = |x||y|cos θ with θ ∈ [0, π]; θ = 0 when either vector is zero,
/// whatever the signs of the zeros (IEEE atan2(+0, −0) = π would be wrong).
#[test]
fn eq_2_1_1_angle_and_dot_zero_vector_gives_zero() {
    let a = Frame::new();
    let x = a.vector([3.0, -4.0, 0.0]);
    let y = a.vector([-1.0, 5.0, -2.0]);
    assert_rel(x.dot(&y), x.norm() * y.norm() * x.angle(&y).cos(), 8.0 * EPS);
    assert_eq!(Vector::zero().angle(&a.vector([-1.0, -1.0, -1.0])), 0.0);
    assert_eq!(a.vector([-1.0, -1.0, -1.0]).angle(&Vector::zero()), 0.0);
    assert_rel(a.i().angle(&a.j()), FRAC_PI_2, EPS);
    assert_eq!(x.angle(&(-x)), PI);
}

/// (2.1.4) is cos⁻¹(x̂·ŷ), which loses half the digits near 0 and π: a true angle of 1e-8 gives
/// acos = 0. vectrix uses atan2(|x × y|, x·y) and recovers it.
#[test]
fn eq_2_1_4_angle_tiny_and_near_pi() {
    let a = Frame::new();
    let x = a.i();
    for t in [1e-8f64, 1e-12, 1e-200] {
        let y = a.vector([t.cos(), t.sin(), 0.0]);
        assert_abs(x.angle(&y) / t, 1.0, 4.0 * EPS);
        let y = a.vector([-t.cos(), t.sin(), 0.0]);
        assert_rel(x.angle(&y), PI - t, 4.0 * EPS);
    }
}

/// The angle does not under- or overflow for tiny and huge magnitudes.
#[test]
fn eq_2_1_4_angle_tiny_and_huge_magnitudes() {
    let a = Frame::new();
    for s in [1e-300, 1e300] {
        let x = a.vector([s, 0.0, 0.0]);
        let y = a.vector([s, s, 0.0]);
        assert_abs(x.angle(&y), PI / 4.0, 4.0 * EPS);
        let n = y.unit_angle_vector_rel(&x).expect("not parallel");
        assert_abs_slice(&arr(n.resolve(&a)), &[0.0, 0.0, 1.0], 4.0 * EPS);
    }
}

/// (2.1.5): x and y are parallel iff |x·y| = |x||y|; orthogonal iff x·y = 0.
#[test]
fn eq_2_1_5_parallel_iff_dot_equals_product_of_norms() {
    let a = Frame::new();
    let x = a.vector([1.0, 2.0, 3.0]);
    assert!(x.is_parallel(&(x * -2.5), 4.0 * EPS));
    assert_rel(x.dot(&(x * -2.5)).abs(), x.norm() * (x * -2.5).norm(), 4.0 * EPS);
    assert!(!x.is_parallel(&a.vector([1.0, 2.0, 3.0001]), 1e-6));
    assert!(x.is_perpendicular(&a.vector([3.0, 0.0, -1.0]), 4.0 * EPS));
}

/// (2.1.6), Fact 2.1.2: x′y = x·y, (x′)′ = x, and x = y ⟺ x′ = y′.
#[test]
fn fact_2_1_2_coform() {
    let a = Frame::new();
    let x = a.vector([3.0, -4.0, 0.0]);
    let y = a.vector([-1.0, 5.0, -2.0]);
    assert_eq!(x.coform() * y, x.dot(&y));
    assert_eq!(x.coform().coform(), x);
    assert_ne!(x.coform(), y.coform());
    // (2.4.20): x′|_A = x|_Aᵀ.
    assert_eq!(x.coform().resolve(&a), x.resolve(&a).transpose());
}

/// (2.2.4), (2.2.7)–(2.2.9), Fact 2.2.1: x × y = |x||y| sin θ θ̂_{y/x}, y × x = −x × y,
/// x × x = 0, θ⃗_{y/x} = θ θ̂ = (θ/sin θ) x̂ × ŷ; θ̂_{x/y} = −θ̂_{y/x} (2.2.2, L400 erratum: the
/// printed "θ_{x/y} = −θ_{y/x}" means the unit vectors).
#[test]
fn fact_2_2_1_angle_vector_and_cross_product() {
    let a = Frame::new();
    let x = a.vector([3.0, -4.0, 0.0]);
    let y = a.vector([-1.0, 5.0, -2.0]);
    let th = y.angle(&x);
    let n = y.unit_angle_vector_rel(&x).expect("not parallel");
    let c = x.cross(&y);
    assert_rel_slice(
        &arr(c.resolve(&a)),
        &arr((n * (x.norm() * y.norm() * th.sin())).resolve(&a)),
        8.0 * EPS,
    );
    assert_eq!(y.cross(&x), -c);
    assert_eq!(x.cross(&x), Vector::zero());
    let want = x.unit().unwrap().cross(&y.unit().unwrap()) * (th / th.sin());
    let got = y.angle_vector_rel(&x).expect("not parallel");
    assert_rel_slice(&arr(got.resolve(&a)), &arr(want.resolve(&a)), 8.0 * EPS);
    assert_eq!(x.unit_angle_vector_rel(&y).unwrap(), -n);
    assert!(x.unit_angle_vector_rel(&(x * 3.0)).is_none() && x.angle_vector_rel(&(-x)).is_none());
}

/// (2.3.1)–(2.3.6), (2.3.8)–(2.3.9): the directed angle θ_{y/x/n̂} ∈ (−π, π]: +θ about θ̂,
/// −θ about −θ̂, 0 for aligned vectors and **π for anti-parallel vectors about either n̂**.
#[test]
fn eq_2_3_1_directed_angle_rules() {
    let a = Frame::new();
    let (x, y, n) = (a.i(), a.vector([-1.0, 1.0, 0.0]), a.k());
    let th = y.angle(&x);
    assert_rel(y.directed_angle_rel(&x, &n).unwrap(), th, 4.0 * EPS); // (2.3.5)
    assert_rel(y.directed_angle_rel(&x, &-n).unwrap(), -th, 4.0 * EPS); // (2.3.6), (2.3.3)
    assert_rel(x.directed_angle_rel(&y, &n).unwrap(), -th, 4.0 * EPS); // (2.3.2)
    assert_rel(x.directed_angle_rel(&y, &-n).unwrap(), th, 4.0 * EPS); // (2.3.4)
    assert_eq!(x.directed_angle_rel(&(x * 2.0), &n), Some(0.0));
    for m in [n, -n, a.j(), -a.j()] {
        assert_eq!((-x).directed_angle_rel(&x, &m), Some(PI)); // (2.3.2–3): stays π
    }
    // (2.3.9): atan2(0, 0) = 0, also for −0 components; a zero normal has no direction.
    assert_eq!(Vector::zero().directed_angle_rel(&a.vector([-1.0, -0.0, -0.0]), &n), Some(0.0));
    assert_eq!(y.directed_angle_rel(&x, &Vector::zero()), None);
}

/// (2.3.8): in a frame with î = x̂ and k̂ = n̂, θ_{y/x/n̂} = atan2(y₂, y₁).
#[test]
fn eq_2_3_8_directed_angle_is_atan2_in_adapted_frame() {
    let (_, b) = frame_b();
    for t in [-3.0, -1.0, 0.0, 0.5, 2.9, PI] {
        let y = b.vector([2.0 * t.cos(), 2.0 * t.sin(), 0.0]);
        let got = y.directed_angle_rel(&b.i(), &b.k()).unwrap();
        assert_abs(got, wrap_angle(t), 8.0 * EPS); // angles: scale π
    }
}

/// L603 erratum: the book says "clockwise rotations correspond to more positive angles"; the
/// right-hand rule of (2.3.1) makes counter-clockwise (seen from n̂) positive.
#[test]
fn erratum_l603_counterclockwise_is_positive() {
    let a = Frame::new();
    // ĵ is a quarter turn counter-clockwise from î seen from k̂.
    assert_rel(a.j().directed_angle_rel(&a.i(), &a.k()).unwrap(), FRAC_PI_2, EPS);
}

/// (2.4.3)–(2.4.16): a frame is its three axes; x⃗ = F_A x|_A and x|_A = [î·x, ĵ·x, k̂·x]ᵀ;
/// î × ĵ = k̂ (right-handed).
#[test]
fn eq_2_4_14_resolution_and_reconstruction() {
    let (_, b) = frame_b();
    let x_b = [0.3, -1.2, 2.0];
    let x = b.vector(x_b);
    assert_rel_slice(&arr(x.resolve(&b)), &x_b, 4.0 * EPS);
    assert_rel_slice(&[b.i().dot(&x), b.j().dot(&x), b.k().dot(&x)], &x_b, 4.0 * EPS);
    assert_abs_slice(&arr(b.i().cross(&b.j()).resolve(&b)), &[0.0, 0.0, 1.0], 4.0 * EPS);
    assert_eq!(b.axis(1), Some(b.i()));
    assert_eq!(b.axis(4), None);
}

/// (2.4.14)–(2.4.16) in the first frame without arithmetic: `Frame::identity_vector` and
/// `Frame::identity_components` give exactly what `Frame::identity()`'s `vector` and `resolve`
/// give for finite components (the same values; a −0 stays −0 here, where the products give
/// +0), and keep an infinite component to itself where the nine products would spread NaN (0·∞)
/// into the others.
#[test]
fn eq_2_4_14_resolution_in_the_identity_frame() {
    let i = Frame::identity();
    for x in
        [[0.3, -1.2, 2.0], [-0.0, 0.0, -0.0], [f64::MAX, -f64::MIN_POSITIVE, 5e-324], [1e300, -1e-300, 7.0]]
    {
        let v = Frame::identity_vector(x);
        assert_eq!(v, i.vector(x));
        let (got, want) = (Frame::identity_components(&v), v.resolve(&i));
        assert_eq!(got, want, "{x:?}");
        assert_eq!(arr(got).map(f64::to_bits), x.map(f64::to_bits), "{x:?}");
    }
    let v = Frame::identity_vector([f64::INFINITY, 1.0, 2.0]);
    assert_eq!(arr(Frame::identity_components(&v)), [f64::INFINITY, 1.0, 2.0]);
    assert!(arr(i.vector([f64::INFINITY, 1.0, 2.0]).resolve(&i)).iter().any(|c| c.is_nan()));
}

/// Fact 2.4.1: x = y ⟺ x|_A = y|_A (resolution is injective).
#[test]
fn fact_2_4_1_equal_iff_resolutions_equal() {
    let (a, b) = frame_b();
    let x = a.vector([1.0, 2.0, 3.0]);
    let y = b.vector(arr(x.resolve(&b)));
    assert_rel_slice(&arr(y.resolve(&a)), &[1.0, 2.0, 3.0], 8.0 * EPS);
}

/// Fact 2.4.2, (2.4.25)–(2.4.32): x·y = x|_Aᵀy|_A, |x| = ‖x|_A‖, (x × y)|_A = x|_A^× y|_A.
#[test]
fn fact_2_4_2_resolved_dot_norm_cross() {
    let (_, b) = frame_b();
    let x = b.vector([3.0, -4.0, 0.0]);
    let y = b.vector([-1.0, 5.0, -2.0]);
    let (xb, yb) = (x.resolve(&b), y.resolve(&b));
    assert_rel(x.dot(&y), xb.dot(&yb), 8.0 * EPS);
    assert_rel(x.norm(), xb.norm(), 8.0 * EPS);
    assert_rel_slice(&arr(x.cross(&y).resolve(&b)), &arr(xb.cross_matrix() * yb), 16.0 * EPS);
}

/// Fact 2.4.3, (2.4.34)–(2.4.37): x × (y × z) = (x·z)y − (x·y)z, (x × y) × z = (x·z)y − (y·z)x,
/// (x × y)·z = x·(y × z) = det[x|_A y|_A z|_A].
#[test]
fn fact_2_4_3_triple_products() {
    let a = Frame::new();
    let (x, y, z) = (a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]), a.vector([0.3, -1.0, 4.0]));
    let lhs = x.cross(&y.cross(&z));
    let rhs = y * x.dot(&z) - z * x.dot(&y);
    assert_rel_slice(&arr(lhs.resolve(&a)), &arr(rhs.resolve(&a)), 16.0 * EPS);
    let lhs = x.cross(&y).cross(&z);
    let rhs = y * x.dot(&z) - x * y.dot(&z);
    assert_rel_slice(&arr(lhs.resolve(&a)), &arr(rhs.resolve(&a)), 16.0 * EPS);
    let det = Matrix3::from_columns(&[x.resolve(&a), y.resolve(&a), z.resolve(&a)]).determinant();
    assert_rel(x.cross(&y).dot(&z), x.triple(&y, &z), 16.0 * EPS);
    assert_rel(x.triple(&y, &z), det, 16.0 * EPS);
}

/// Facts 2.4.4–2.4.5: x, y, z are independent iff x·(y × z) ≠ 0, and then every w has unique
/// coefficients w = αx + βy + γz.
#[test]
fn fact_2_4_4_independence_by_triple_product() {
    let a = Frame::new();
    let (x, y) = (a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]));
    assert_eq!(x.triple(&y, &(x * 2.0 - y * 3.0)), 0.0);
    let z = a.vector([0.3, -1.0, 4.0]);
    assert!(x.triple(&y, &z).abs() > 1.0);
    let w = a.vector([7.0, -1.0, 2.0]);
    let m = Matrix3::from_columns(&[x.resolve(&a), y.resolve(&a), z.resolve(&a)]);
    let c = m.lu().solve(&w.resolve(&a)).expect("independent");
    let back = x * c.x + y * c.y + z * c.z;
    assert_rel_slice(&arr(back.resolve(&a)), &[7.0, -1.0, 2.0], 32.0 * EPS);
}

/// §2.4, DESIGN §5: bad frames are typed errors — zero, non-finite, non-orthonormal axes and
/// left-handed axes.
#[test]
fn sec_2_4_bad_frames_are_errors() {
    let a = Frame::new();
    let tol = ORTHONORMAL_TOL;
    let (i, j, k) = (a.i(), a.j(), a.k());
    assert!(matches!(Frame::from_axes(&Vector::zero(), &j, &k, tol), Err(FrameError::ZeroAxis { .. })));
    let nan = a.vector([f64::NAN, 0.0, 0.0]);
    assert!(matches!(Frame::from_axes(&i, &nan, &k, tol), Err(FrameError::NonFinite { .. })));
    let skew = a.vector([1.0, 1e-6, 0.0]);
    assert!(matches!(Frame::from_axes(&skew, &j, &k, tol), Err(FrameError::NotOrthonormal { .. })));
    assert!(matches!(Frame::from_axes(&i, &j, &-k, tol), Err(FrameError::LeftHanded { .. })));
    assert!(Frame::from_axes(&i, &j, &k, tol).is_ok());
    assert!(matches!(a.try_vector([1.0, f64::INFINITY, 0.0]), Err(FrameError::NonFinite { .. })));
    let o = Matrix3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 + 1e-9);
    assert!(Frame::from_orientation_rel(&a, &o, tol).is_err());
}

/// (2.5.1)–(2.5.3): slash-and-split, r_{z/x} = r_{z/y} + r_{y/x} and r_{x/y} = −r_{y/x}, in any
/// frame.
#[test]
fn eq_2_5_1_position_slash_and_split() {
    let (a, b) = frame_b();
    let r_y_x = a.vector([1.0, 2.0, 0.5]);
    let r_z_y = b.vector([-3.0, 0.25, 4.0]);
    let r_z_x = r_z_y + r_y_x;
    let r_x_y = -r_y_x;
    assert_rel_slice(&arr((r_z_x + r_x_y).resolve(&b)), &[-3.0, 0.25, 4.0], 8.0 * EPS);
}

/// Prob 2.26.3 (vectors part; answers computed): x = (3, −4, 0), y = (−1, 5, −2):
/// x·y = −23, x × y = (8, 6, 11), |x × y| = √221, θ_{y/x} = 2.5677870441821375,
/// θ⃗ = (1.381824388318, 1.036368291239, 1.900008533937), θ_{y/x/−θ̂} = −θ.
#[test]
fn problem_2_26_3_angles_of_two_vectors() {
    let a = Frame::new();
    let x = a.vector([3.0, -4.0, 0.0]);
    let y = a.vector([-1.0, 5.0, -2.0]);
    assert_eq!(x.dot(&y), -23.0);
    assert_rel_slice(&arr(x.cross(&y).resolve(&a)), &[8.0, 6.0, 11.0], EPS);
    assert_rel(x.cross(&y).norm(), 221f64.sqrt(), 2.0 * EPS);
    let th = y.angle(&x);
    assert_rel(th, 2.5677870441821375, 4.0 * EPS);
    let tv = y.angle_vector_rel(&x).unwrap();
    // the notes print twelve decimals
    assert_printed_slice(&arr(tv.resolve(&a)), &["1.381824388318", "1.036368291239", "1.900008533937"]);
    let n = y.unit_angle_vector_rel(&x).unwrap();
    assert_rel(y.directed_angle_rel(&x, &-n).unwrap(), -th, 4.0 * EPS);
}

/// Prob 2.26.6: the Jacobi identity x × (y × z) + y × (z × x) + z × (x × y) = 0.
#[test]
fn problem_2_26_6_jacobi_identity() {
    let a = Frame::new();
    let (x, y, z) = (a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]), a.vector([0.3, -1.0, 4.0]));
    let j = x.cross(&y.cross(&z)) + y.cross(&z.cross(&x)) + z.cross(&x.cross(&y));
    assert!(j.norm() < 64.0 * EPS, "{j:?}");
}

/// Book §2.1–2.4 on dual numbers (item 14): the kernel and frames run on `Dual64`, giving the
/// exact derivative d/dt |x(t)|² = 2 x·ẋ and d/dt θ_{y/x(t)} for x(t) = (cos t, sin t, 0).
#[test]
fn dual_numbers_give_exact_derivatives_through_the_kernel() {
    use vectrix::nalgebra::ComplexField;
    use vectrix::num_dual::Dual64;
    let a = Frame::<Dual64>::identity();
    let t = Dual64::new(0.4, 1.0);
    let x = a.vector([Dual64::from(3.0) * t, t * t, Dual64::from(1.0)]);
    // |x|² = 9t² + t⁴ + 1, derivative 18t + 4t³.
    let n2 = x.dot(&x);
    assert_rel(n2.eps, 18.0 * 0.4 + 4.0 * 0.4f64.powi(3), 4.0 * EPS);
    // θ between î and (cos t, sin t, 0) is t: derivative exactly 1.
    let y = a.vector([t.cos(), t.sin(), Dual64::from(0.0)]);
    let th = y.angle(&a.i());
    assert_abs(th.re, 0.4, 4.0 * EPS);
    assert_abs(th.eps, 1.0, 4.0 * EPS);
    // Resolution in a rotated frame carries the derivative: d/dt (x|_B) = 𝓞_{B/A} ẋ|_A.
    let r = Rotor::from_axis_angle(&a.k(), Dual64::from(0.3)).unwrap();
    let b = a.rotated_by_rotor(&r);
    let xb = x.resolve(&b);
    let o = b.orientation_rel(&a).map(|d| d.re);
    let want = o * Vector3::new(3.0, 2.0 * 0.4, 0.0);
    assert_rel_slice(&[xb.x.eps, xb.y.eps, xb.z.eps], &arr(want), 8.0 * EPS);
    // An f64 frame lifted into dual numbers: d/ds of |x|_C(s)| along x|_C = (s, 2s, 2s) is 3.
    let c = Frame::new().rotated_by_rotor(&Rotor::from_axis_angle(&Frame::new().i(), 0.9).unwrap());
    let cd = c.cast::<Dual64>();
    let s = Dual64::new(1.5, 1.0);
    let v = cd.vector([s, s * 2.0, s * 2.0]);
    assert_rel(v.norm().eps, 3.0, 4.0 * EPS);
}

mod prop {
    //! Frame independence (DESIGN §6): every frame-free operation on vectors, covectors and
    //! dyadics gives the same object whichever frame its inputs were built in; resolved in A
    //! and in B, results agree through 𝓞_{B/A} (2.10.31, 2.10.38). Inputs include tiny and huge
    //! magnitudes and near-parallel pairs.

    use proptest::prelude::*;
    use vectrix::frames::{change_frame_covector, change_frame_dyadic, change_frame_vector};

    use super::*;

    /// Components of mixed magnitude, from the shared strategy.
    fn comps() -> impl Strategy<Value = [f64; 3]> {
        [component(), component(), component()]
    }

    /// A pair (x, y) of moderate vectors, a third of them nearly parallel.
    fn pair() -> impl Strategy<Value = ([f64; 3], [f64; 3])> {
        prop_oneof![
            2 => (direction(), direction()),
            1 => (direction(), triple(), proptest::sample::select(vec![1e-4, 1e-8, 1e-12]))
                .prop_map(|(x, d, e)| (x, [x[0] * 2.0 + e * d[0], x[1] * 2.0 + e * d[1], x[2] * 2.0 + e * d[2]])),
        ]
    }

    fn rel_close(got: Vector3<f64>, want: Vector3<f64>, tol: f64) -> bool {
        (got - want).norm() <= tol * want.norm().max(f64::MIN_POSITIVE)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// x|_B = 𝓞_{B/A} x|_A (2.10.31) for all magnitudes.
        #[test]
        fn resolution_changes_frame_by_orientation(a in frame(), b in frame(), x in comps()) {
            let v = a.vector(x);
            let got = v.resolve(&b);
            let want = change_frame_vector(&v.resolve(&a), &a, &b);
            prop_assert!(rel_close(got, want, 64.0 * EPS));
            let c = v.coform();
            let got = c.resolve(&b);
            let want = change_frame_covector(&c.resolve(&a), &a, &b);
            prop_assert!(rel_close(got.transpose(), want.transpose(), 64.0 * EPS));
        }

        /// dot, cross, norm, angle, directed angle, triple product are frame independent:
        /// built in A or in B (via 𝓞_{B/A}), the same numbers and the same vectors.
        #[test]
        fn vector_operations_are_frame_independent(a in frame(), b in frame(), (x, y) in pair(), z in direction()) {
            let o_ba = b.orientation_rel(&a);
            let to_b = |v: [f64; 3]| arr(o_ba * Vector3::from(v));
            let (xa, ya, za) = (a.vector(x), a.vector(y), a.vector(z));
            let (xb, yb, zb) = (b.vector(to_b(x)), b.vector(to_b(y)), b.vector(to_b(z)));
            let s = xa.norm() * ya.norm();
            prop_assert!((xa.dot(&ya) - xb.dot(&yb)).abs() <= 64.0 * EPS * s);
            // Absolute error of x × y is O(ε|x||y|), also for near-parallel pairs.
            prop_assert!((xa.cross(&ya) - xb.cross(&yb)).norm() <= 64.0 * EPS * s);
            prop_assert!((xa.norm() - xb.norm()).abs() <= 16.0 * EPS * xa.norm());
            // atan2(|x × y|, x·y) has absolute error O(ε) even for near-parallel pairs.
            prop_assert!((xa.angle(&ya) - xb.angle(&yb)).abs() <= 64.0 * EPS);
            let t = xa.norm() * ya.norm() * za.norm();
            prop_assert!((xa.triple(&ya, &za) - xb.triple(&yb, &zb)).abs() <= 256.0 * EPS * t);
            // Projectors (2.7.1–2) and cross dyads (2.9.1) built from either frame's inputs.
            let (pa, pb) = (Dyadic::projector_along(&ya).unwrap(), Dyadic::projector_along(&yb).unwrap());
            prop_assert!((pa - pb).norm() <= 64.0 * EPS);
            let (qa, qb) = (Dyadic::projector_perp(&xa).unwrap(), Dyadic::projector_perp(&xb).unwrap());
            prop_assert!((qa - qb).norm() <= 64.0 * EPS);
            prop_assert!((xa.cross_dyad() - xb.cross_dyad()).norm() <= 64.0 * EPS * xa.norm());
            prop_assert!((xa.cross_dyad().vee() - xb).norm() <= 64.0 * EPS * xa.norm());
            let n = xa.cross(&ya);
            if let (Some(da), Some(db)) = (ya.directed_angle_rel(&xa, &n), yb.directed_angle_rel(&xb, &n)) {
                prop_assert!(congruent(da, db, 64.0 * EPS));
            }
        }

        /// Dyadic operations (apply, product, coform, trace, det, inverse, invariants) are frame
        /// independent: M|_B = 𝓞_{B/A} M|_A 𝓞_{A/B} (2.10.38).
        #[test]
        fn dyadic_operations_are_frame_independent(a in frame(), b in frame(), m in [triple(), triple(), triple()], x in triple()) {
            let m_a = Matrix3::from_rows(&m.map(|r| Vector3::from(r).transpose()));
            let mm = a.dyadic(&m_a);
            let nn = b.dyadic(&m_a);
            let scale = m_a.norm().max(1.0);
            let got = mm.resolve(&b);
            let want = change_frame_dyadic(&m_a, &a, &b);
            prop_assert!((got - want).nan_amax() <= 64.0 * EPS * scale);
            let v = b.vector(x);
            let want = change_frame_vector(&(mm.resolve(&a) * v.resolve(&a)), &a, &b);
            prop_assert!(rel_close((mm * v).resolve(&b), want, 1e-12) || want.norm() < 1e-9);
            prop_assert!((mm.trace() - m_a.trace()).abs() <= 64.0 * EPS * scale);
            prop_assert!((mm.determinant() - nn.determinant()).abs() <= 1e-12 * scale.powi(3));
            let mn = (mm * nn).resolve(&a);
            prop_assert!((mn - mm.resolve(&a) * nn.resolve(&a)).nan_amax() <= 1e-12 * scale * scale);
            prop_assert!((mm.coform().resolve(&b) - mm.resolve(&b).transpose()).nan_amax() <= 64.0 * EPS * scale);
            let c = (v.coform() * mm).resolve(&a);
            prop_assert!((c - v.resolve(&a).transpose() * mm.resolve(&a)).nan_amax() <= 1e-12 * scale * (v.norm() + 1.0));
            if let Ok(inv) = mm.inverse(1e-6) {
                let e = (inv * mm).resolve(&b) - Matrix3::identity();
                prop_assert!(e.nan_amax() <= 1e-8, "{e}");
            }
        }

        /// Cayley–Hamilton (2.10.56) and (2.10.57) hold for any dyadic; identities of 2.9:
        /// x^×² = xx′ − |x|²I, (x × y)^× = yx′ − xy′, x^×y^× = yx′ − (x·y)I, (Rx)^× = Rx^×R′.
        #[test]
        fn cayley_hamilton_and_cross_dyad_identities(m in [comps(), comps(), comps()], (x, y) in pair(), b in frame()) {
            let a = Frame::new();
            let m_a = Matrix3::from_rows(&m.map(|r| Vector3::from(r).transpose()));
            let s = m_a.norm();
            prop_assume!(s > 0.0 && s.is_finite());
            let mm = a.dyadic(&(m_a / s));
            prop_assert!(mm.cayley_hamilton_residual().norm() <= 128.0 * EPS);
            prop_assert!((mm.determinant_from_traces() - mm.determinant()).abs() <= 128.0 * EPS);
            let (x, y) = (a.vector(x), a.vector(y));
            let sc = x.norm() * y.norm();
            let xx = x.cross_dyad();
            let e = xx * xx - (x.outer(&x) - Dyadic::identity() * x.norm_squared());
            prop_assert!(e.norm() <= 64.0 * EPS * x.norm_squared());
            prop_assert!((x.cross(&y).cross_dyad() - (y.outer(&x) - x.outer(&y))).norm() <= 64.0 * EPS * sc);
            prop_assert!((xx * y.cross_dyad() - (y.outer(&x) - Dyadic::identity() * x.dot(&y))).norm() <= 64.0 * EPS * sc);
            let r = b.rotation_dyadic_rel(&a);
            prop_assert!(((r * x).cross_dyad() - r * xx * r.coform()).norm() <= 64.0 * EPS * x.norm());
            prop_assert!((r * x.cross(&y) - (r * x).cross(&(r * y))).norm() <= 64.0 * EPS * sc);
        }

        /// Tensors (3.6.2): built from T|_A in frame A, resolved in B, equal to the slotwise
        /// change of frame by 𝓞_{B/A}; and back (round trip), for every type up to order 4.
        #[test]
        fn tensor_resolution_is_frame_independent(
            a in frame(), b in frame(), p in 0usize..3, q in 0usize..3,
            data in proptest::collection::vec(-1.0..1.0f64, 81),
        ) {
            use vectrix::frames::change_frame_tensor;
            use vectrix::nalgebra::DMatrix;
            let (rows, cols) = (3usize.pow(p as u32), 3usize.pow(q as u32));
            let t_a = DMatrix::from_row_slice(rows, cols, &data[..rows * cols]);
            let t = a.tensor(p, q, &t_a).unwrap();
            let got = t.resolve(&b);
            let want = change_frame_tensor(&t_a, p, q, &a, &b).unwrap();
            prop_assert!((&got - &want).nan_amax() <= 64.0 * EPS * (p + q + 1) as f64);
            prop_assert!((t.resolve(&a) - &t_a).nan_amax() <= 64.0 * EPS * (p + q + 1) as f64);
            prop_assert!((b.tensor(p, q, &got).unwrap().resolve(&a) - &t_a).nan_amax() <= 128.0 * EPS * (p + q + 1) as f64);
        }

        /// Fact 2.1.1: a ≡ a + 2πk, wrapping lands in (−π, π] and is congruent to its input;
        /// sums of congruent angles are congruent (viii).
        #[test]
        fn congruence_and_wrapping(x in angle(), y in angle(), k in -1000i32..1000) {
            let shifted = x + TAU * f64::from(k);
            // Rounding of x + 2πk is |2πk|·ε; allow that.
            let tol = 8.0 * EPS * (TAU * f64::from(k.abs()) + PI);
            prop_assert!(congruent(x, shifted, tol));
            let w = wrap_angle(shifted);
            prop_assert!(w > -PI && w <= PI);
            prop_assert!(congruent(w, x, tol));
            prop_assert!(congruent(x + y, wrap_angle(shifted) + y, 2.0 * tol));
        }

        /// (2.3.2)–(2.3.4): θ_{x/y/n} = −θ_{y/x/n} and θ_{y/x/−n} = −θ_{y/x/n}, except that π stays
        /// π; θ_{x/y/−n} = θ_{y/x/n}.
        #[test]
        fn directed_angle_symmetries(x in direction(), y in direction()) {
            let a = Frame::new();
            let (x, y) = (a.vector(x), a.vector(y));
            if let Some(n) = x.cross(&y).unit() {
                let d = y.directed_angle_rel(&x, &n).unwrap();
                prop_assert!((x.directed_angle_rel(&y, &n).unwrap() + d).abs() <= 64.0 * EPS);
                prop_assert!((y.directed_angle_rel(&x, &-n).unwrap() + d).abs() <= 64.0 * EPS);
                prop_assert!((x.directed_angle_rel(&y, &-n).unwrap() - d).abs() <= 64.0 * EPS);
            }
        }

        /// Jacobi (Prob 2.26.6) and the triple products (2.4.34–37) at all magnitudes.
        #[test]
        fn jacobi_and_triple_products(x in comps(), y in comps(), z in comps()) {
            let a = Frame::new();
            let (x, y, z) = (a.vector(x), a.vector(y), a.vector(z));
            let t = x.norm() * y.norm() * z.norm();
            // Keep |x||y||z| (which bounds every intermediate) finite and away from subnormals.
            prop_assume!(t.is_finite() && t > 1e-280);
            let j = x.cross(&y.cross(&z)) + y.cross(&z.cross(&x)) + z.cross(&x.cross(&y));
            prop_assert!(j.norm() <= 64.0 * EPS * t);
            let bac = y * x.dot(&z) - z * x.dot(&y);
            prop_assert!((x.cross(&y.cross(&z)) - bac).norm() <= 64.0 * EPS * t);
            prop_assert!((x.cross(&y).dot(&z) - x.triple(&y, &z)).abs() <= 64.0 * EPS * t);
        }

        /// Angles stay in [0, π], directed angles in (−π, π] with π for anti-parallel input,
        /// for every magnitude (DESIGN §4).
        #[test]
        fn angles_stay_in_their_intervals(x in comps(), y in comps(), flip in any::<bool>()) {
            let a = Frame::new();
            let (x, y) = (a.vector(x), a.vector(y));
            let th = x.angle(&y);
            prop_assert!((0.0..=PI).contains(&th));
            if let Some(n) = x.cross(&y).unit() {
                let d = y.directed_angle_rel(&x, &(if flip { -n } else { n })).unwrap();
                prop_assert!(d > -PI && d <= PI);
            }
            if x.norm() > 0.0 {
                // Exactly anti-parallel (scaling by −2 is exact): π whatever n̂ (2.3.1).
                prop_assert_eq!((x * -2.0).directed_angle_rel(&x, &a.k()), Some(PI));
            }
        }
    }
}

/// Fact 2.1.1 on dual numbers: wrapping an angle subtracts whole turns, so d/dt wrap(t) = 1
/// away from the cut. Regression: `floor` is undefined for num-dual types, and the wrap once
/// called it (found by the rotation layer).
#[test]
fn fact_2_1_1_wrap_angle_on_dual_numbers_keeps_the_derivative() {
    use vectrix::num_dual::Dual64;
    let t = Dual64::new(7.0, 1.0);
    let w = wrap_angle(t);
    assert_abs(w.re, 7.0 - std::f64::consts::TAU, 4.0 * EPS);
    assert_eq!(w.eps, 1.0);
    let u = wrap_angle(Dual64::new(-3.0 * std::f64::consts::PI, 2.0));
    assert_rel(u.re, std::f64::consts::PI, 4.0 * EPS);
    assert_eq!(u.eps, 2.0);
}
