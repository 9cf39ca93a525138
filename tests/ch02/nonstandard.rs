//! §2.23 nonstandard and reciprocal frames, §2.24 gradients as covectors, and Ex 2.25.1
//! (position along a chain of frames). Errata from the ch2b notes are tested in corrected form.

use crate::support::NanAmax;
use vectrix::frames::{
    Components, FrameError, MAX_CONDITION, NonstandardFrame, gradient, gradient_central_difference,
    gradient_of_inverse_power, gradient_of_norm, resolve_dyadic_mixed,
};
use vectrix::nalgebra::{ComplexField, Matrix3, Vector3};
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;

use crate::geometry::{arr, assert_mat_abs, assert_mat_rel, frame_b};
use crate::support::*;

use Components::{Contravariant as Con, Covariant as Cov};

/// A generic nonstandard frame (not unit, not perpendicular) and a second one.
fn frames_ab() -> (Frame, NonstandardFrame, NonstandardFrame) {
    let s = Frame::new();
    let fa = NonstandardFrame::from_axes(
        &s.vector([1.0, 0.2, 0.0]),
        &s.vector([0.5, 2.0, -0.3]),
        &s.vector([0.1, -0.4, 1.5]),
        MAX_CONDITION,
    )
    .unwrap();
    let fb = NonstandardFrame::from_axes(
        &s.vector([0.0, 1.0, 1.0]),
        &s.vector([2.0, 0.0, 0.5]),
        &s.vector([-1.0, 1.0, 0.0]),
        MAX_CONDITION,
    )
    .unwrap();
    (s, fa, fb)
}

fn sample_dyadic(s: &Frame) -> Dyadic {
    s.dyadic(&Matrix3::new(1.0, 2.0, 0.0, -1.0, 3.0, 4.0, 0.5, 0.0, -2.0))
}

/// Fact 2.23.3, (2.23.9)–(2.23.13): the reciprocal axes a_[1] = (a₂ × a₃)/α, … satisfy
/// a_[i]·a_j = δ_ij; Fact 2.23.4: duality characterises them (the vectors with covariant
/// components e_i), and the reciprocal of the reciprocal is F_A. A standard frame is its own
/// reciprocal.
#[test]
fn fact_2_23_3_reciprocal_duality() {
    let (s, fa, _) = frames_ab();
    let r = fa.reciprocal();
    for (i, ri) in r.axes().iter().enumerate() {
        for (j, aj) in fa.axes().iter().enumerate() {
            assert_abs(ri.dot(aj), if i == j { 1.0 } else { 0.0 }, 8.0 * EPS);
        }
        let mut e = [0.0; 3];
        e[i] = 1.0;
        assert_rel_slice(&arr(fa.vector_from_covariant(e).resolve(&s)), &arr(ri.resolve(&s)), 16.0 * EPS);
    }
    // Fact 2.23.2: the reciprocal axes are independent; their volume is 1/α.
    assert_abs(r.alpha() * fa.alpha(), 1.0, 16.0 * EPS);
    let rr = r.reciprocal();
    for (x, y) in rr.axes().iter().zip(fa.axes()) {
        assert_rel_slice(&arr(x.resolve(&s)), &arr(y.resolve(&s)), 16.0 * EPS);
    }
    let (_, b) = frame_b();
    let sb = NonstandardFrame::from_frame(&b);
    for (x, y) in sb.reciprocal().axes().iter().zip([b.i(), b.j(), b.k()]) {
        assert_abs_slice(&arr(x.resolve(&s)), &arr(y.resolve(&s)), 8.0 * EPS);
    }
}

/// (2.23.16)–(2.23.21): x = Σ x_i a_i with x|_A = [a_[i]·x] (contravariant), x|_[A] = [a_i·x]
/// (covariant); x|_[A] = G x|_A with G = [a_i·a_j] = 𝓞_{A/[A]}, and [a_[i]·a_[j]] = G⁻¹.
#[test]
fn eq_2_23_18_contravariant_and_covariant_components() {
    let (s, fa, _) = frames_ab();
    let x = s.vector([0.3, -1.2, 2.0]);
    let (xc, xv) = (fa.contravariant(&x), fa.covariant(&x));
    assert_rel_slice(&arr(fa.vector(arr(xc)).resolve(&s)), &[0.3, -1.2, 2.0], 16.0 * EPS);
    assert_rel_slice(&arr(fa.vector_from_covariant(arr(xv)).resolve(&s)), &[0.3, -1.2, 2.0], 16.0 * EPS);
    let r = fa.reciprocal();
    let by_dots = Vector3::from(r.axes().map(|ri| ri.dot(&x)));
    assert_rel_slice(&arr(xc), &arr(by_dots), 16.0 * EPS);
    let g = fa.gram();
    assert_rel_slice(&arr(xv), &arr(g * xc), 16.0 * EPS);
    assert_mat_rel(&fa.orientation_rel(&r), &g, 16.0 * EPS);
    assert_mat_abs(&(g * r.gram()), &Matrix3::identity(), 32.0 * EPS);
    assert_mat_abs(&(g * r.orientation_rel(&fa)), &Matrix3::identity(), 32.0 * EPS);
}

/// Fact 2.23.7 (corrected): the Gram matrix is symmetric positive **definite** for independent
/// axes (the book says semidefinite). Example from the notes: a₁ = î − ĵ, a₂ = ĵ, a₃ = k̂ gives
/// eig(G) = {(3 − √5)/2, 1, (3 + √5)/2} and κ(A) = √(κ(G)) = (3 + √5)/2.
#[test]
fn fact_2_23_7_gram_positive_definite() {
    let s = Frame::new();
    let fa = NonstandardFrame::from_axes(&(s.i() - s.j()), &s.j(), &s.k(), MAX_CONDITION).unwrap();
    let g = fa.gram();
    assert_eq!(g, g.transpose());
    let mut ev: Vec<f64> = g.symmetric_eigenvalues().iter().copied().collect();
    ev.sort_by(f64::total_cmp);
    let r5 = 5f64.sqrt();
    assert_rel_slice(&ev, &[(3.0 - r5) / 2.0, 1.0, (3.0 + r5) / 2.0], 16.0 * EPS);
    assert_rel(fa.condition_number(), (3.0 + r5) / 2.0, 16.0 * EPS);
    assert!(g.cholesky().is_some());
}

/// Fact 2.23.1, (2.23.3)–(2.23.8): b_i = Σ_j 𝓞_ij a_j with 𝓞_{B/A} = [b_i·a_[j]];
/// 𝓞_{A/B} = 𝓞_{B/A}⁻¹; x|_B = 𝓞_{B/A}^{−T} x|_A (2.23.7); for standard frames 𝓞_{B/A} is the
/// orientation matrix (2.23.8).
#[test]
fn fact_2_23_1_nonstandard_orientation() {
    let (s, fa, fb) = frames_ab();
    let o = fb.orientation_rel(&fa);
    let (ar, b) = (fa.reciprocal().axes(), fb.axes());
    for i in 0..3 {
        let sum = fa.axes().iter().enumerate().fold(Vector::zero(), |acc, (j, aj)| acc + *aj * o[(i, j)]);
        assert_rel_slice(&arr(sum.resolve(&s)), &arr(b[i].resolve(&s)), 32.0 * EPS);
        for j in 0..3 {
            // entries of size ≤ 2.1: absolute at that scale
            assert_abs(o[(i, j)], b[i].dot(&ar[j]), 64.0 * EPS);
        }
    }
    assert_mat_abs(&(fa.orientation_rel(&fb) * o), &Matrix3::identity(), 64.0 * EPS);
    let x = s.vector([0.3, -1.2, 2.0]);
    let want = o.transpose().lu().solve(&fa.contravariant(&x)).unwrap();
    assert_rel_slice(&arr(fb.contravariant(&x)), &arr(want), 64.0 * EPS);
    let (a2, b2) = frame_b();
    let (sa, sb) = (NonstandardFrame::from_frame(&a2), NonstandardFrame::from_frame(&b2));
    assert_mat_abs(&sb.orientation_rel(&sa), &b2.orientation_rel(&a2), 16.0 * EPS);
}

/// Fact 2.23.5 (corrected), (2.23.27)–(2.23.28): x|_[B] = 𝓞_{B/A} x|_[A] (the book prints x|_A
/// in the middle expression); 𝓞_{B/A} = G_B 𝓞ᵀ_{A/B} G_A⁻¹, tested as 𝓞_{B/A} G_A = G_B 𝓞ᵀ_{A/B}.
#[test]
fn fact_2_23_5_covariant_change_of_frame_corrected() {
    let (s, fa, fb) = frames_ab();
    let o_ba = fb.orientation_rel(&fa);
    let x = s.vector([0.3, -1.2, 2.0]);
    assert_rel_slice(&arr(fb.covariant(&x)), &arr(o_ba * fa.covariant(&x)), 32.0 * EPS);
    // The printed form 𝓞_{B/A} x|_A is not x|_[B].
    assert!((fb.covariant(&x) - o_ba * fa.contravariant(&x)).norm() > 0.1);
    let o_ab = fa.orientation_rel(&fb);
    assert_mat_rel(&(o_ba * fa.gram()), &(fb.gram() * o_ab.transpose()), 64.0 * EPS);
}

/// Fact 2.23.6, (2.23.31)–(2.23.32): x·y = x|_Aᵀ y|_[A] = x|_Aᵀ G y|_A, |x|² = x|_Aᵀ G x|_A.
#[test]
fn fact_2_23_6_inner_product_in_nonstandard_frame() {
    let (s, fa, _) = frames_ab();
    let (x, y) = (s.vector([3.0, -4.0, 0.0]), s.vector([-1.0, 5.0, -2.0]));
    let (xa, ya) = (fa.contravariant(&x), fa.contravariant(&y));
    assert_rel(xa.dot(&fa.covariant(&y)), -23.0, 32.0 * EPS);
    assert_rel((xa.transpose() * fa.gram() * ya)[0], -23.0, 32.0 * EPS);
    assert_rel((xa.transpose() * fa.gram() * xa)[0], 25.0, 32.0 * EPS);
}

/// Fact 2.23.8, (2.23.36)–(2.23.47): M|_[A] has entries a_i′Ma_j, M|_A has entries a_[i]′Ma_[j]
/// (read through the (2.23.41) label, see notes); I|_A = G⁻¹, I|_[A] = G; round trip.
#[test]
fn fact_2_23_8_dyadic_resolutions() {
    let (s, fa, _) = frames_ab();
    let m = sample_dyadic(&s);
    let (a, r) = (fa.axes(), fa.reciprocal().axes());
    let (m_cov, m_con) = (fa.resolve_dyadic(&m, Cov, Cov), fa.resolve_dyadic(&m, Con, Con));
    // relative to the largest entry: small entries carry the rounding of the large ones
    let (s_cov, s_con) = (m_cov.nan_amax(), m_con.nan_amax());
    for i in 0..3 {
        for j in 0..3 {
            assert_abs(m_cov[(i, j)], a[i].coform() * (m * a[j]), 32.0 * EPS * s_cov);
            assert_abs(m_con[(i, j)], r[i].coform() * (m * r[j]), 64.0 * EPS * s_con);
        }
    }
    let g = fa.gram();
    let id = Dyadic::identity();
    assert_mat_rel(&fa.resolve_dyadic(&id, Cov, Cov), &g, 16.0 * EPS);
    assert_mat_abs(&(g * fa.resolve_dyadic(&id, Con, Con)), &Matrix3::identity(), 64.0 * EPS);
    for (l, rr) in [(Con, Con), (Con, Cov), (Cov, Con), (Cov, Cov)] {
        let back = fa.dyadic(&fa.resolve_dyadic(&m, l, rr), l, rr).unwrap();
        assert_mat_rel(&back.resolve(&s), &m.resolve(&s), 128.0 * EPS);
    }
    assert!(matches!(fa.dyadic(&(g * f64::NAN), Con, Con), Err(FrameError::NonFinite { .. })));
}

/// Facts 2.23.9 and 2.23.11, (2.23.46), (2.23.49): (Mx)|_A = M|_A G x|_A; M|_[A] = G M|_A G.
#[test]
fn fact_2_23_9_dyadic_times_vector_and_gram_sandwich() {
    let (s, fa, _) = frames_ab();
    let m = sample_dyadic(&s);
    let x = s.vector([0.3, -1.2, 2.0]);
    let (g, m_a) = (fa.gram(), fa.resolve_dyadic(&m, Con, Con));
    assert_rel_slice(&arr(fa.contravariant(&(m * x))), &arr(m_a * g * fa.contravariant(&x)), 128.0 * EPS);
    assert_mat_rel(&fa.resolve_dyadic(&m, Cov, Cov), &(g * m_a * g), 128.0 * EPS);
}

/// Fact 2.23.10, (2.23.48): M|_B = 𝓞_{B/A}^{−T} M|_A 𝓞_{A/B}, tested as
/// 𝓞ᵀ_{B/A} M|_B 𝓞_{B/A} = M|_A.
#[test]
fn fact_2_23_10_dyadic_change_of_nonstandard_frame() {
    let (s, fa, fb) = frames_ab();
    let m = sample_dyadic(&s);
    let o = fb.orientation_rel(&fa);
    let m_b = fb.resolve_dyadic(&m, Con, Con);
    assert_mat_rel(&(o.transpose() * m_b * o), &fa.resolve_dyadic(&m, Con, Con), 256.0 * EPS);
}

/// Fact 2.23.12 (erratum): for y = Mx, y|_[A] = G M|_A x|_[A]. The printed
/// G M|_A G x|_[A] is false.
#[test]
fn fact_2_23_12_covariant_image_corrected() {
    let (s, fa, _) = frames_ab();
    let m = sample_dyadic(&s);
    let x = s.vector([0.3, -1.2, 2.0]);
    let (g, m_a) = (fa.gram(), fa.resolve_dyadic(&m, Con, Con));
    let y_cov = fa.covariant(&(m * x));
    assert_rel_slice(&arr(y_cov), &arr(g * m_a * fa.covariant(&x)), 128.0 * EPS);
    assert!((y_cov - g * m_a * g * fa.covariant(&x)).norm() > 0.1);
}

/// Facts 2.23.13–2.23.14, (2.23.53)–(2.23.56): (Mx)|_B = M|_{B,A} x|_[A];
/// M|_{[A],A} = G M|_A, M|_{A,[A]} = M|_A G; I|_{[A],A} = I₃.
#[test]
fn fact_2_23_13_mixed_resolution() {
    let (s, fa, fb) = frames_ab();
    let m = sample_dyadic(&s);
    let x = s.vector([0.3, -1.2, 2.0]);
    let m_ba = resolve_dyadic_mixed(&m, (&fb, Con), (&fa, Con));
    assert_rel_slice(&arr(fb.contravariant(&(m * x))), &arr(m_ba * fa.covariant(&x)), 128.0 * EPS);
    let (g, m_a) = (fa.gram(), fa.resolve_dyadic(&m, Con, Con));
    assert_mat_rel(&fa.resolve_dyadic(&m, Cov, Con), &(g * m_a), 128.0 * EPS);
    assert_mat_rel(&fa.resolve_dyadic(&m, Con, Cov), &(m_a * g), 128.0 * EPS);
    assert_mat_abs(&fa.resolve_dyadic(&Dyadic::identity(), Cov, Con), &Matrix3::identity(), 32.0 * EPS);
}

/// §2.23, DESIGN §5: a zero, non-finite or dependent axis is an error; a nearly dependent
/// frame is reported with its condition number.
#[test]
fn sec_2_23_degenerate_nonstandard_frames_are_errors() {
    let s = Frame::new();
    let (i, j, k) = (s.i(), s.j(), s.k());
    assert!(matches!(
        NonstandardFrame::from_axes(&i, &Vector::zero(), &k, MAX_CONDITION),
        Err(FrameError::ZeroAxis { .. })
    ));
    let nan = s.vector([0.0, f64::NAN, 1.0]);
    assert!(matches!(
        NonstandardFrame::from_axes(&i, &j, &nan, MAX_CONDITION),
        Err(FrameError::NonFinite { .. })
    ));
    let dep = NonstandardFrame::from_axes(&i, &j, &(i + j), f64::INFINITY);
    assert!(matches!(dep, Err(FrameError::Degenerate { cond, .. }) if cond.is_infinite()));
    let near = i + j + k * 1e-10;
    match NonstandardFrame::from_axes(&i, &j, &near, MAX_CONDITION) {
        Err(FrameError::Degenerate { cond, limit }) => {
            assert!(cond > 1e9 && cond < 1e11, "κ = {cond:e}");
            assert_eq!(limit, MAX_CONDITION);
        }
        other => panic!("expected Degenerate, got {other:?}"),
    }
    // Accepted with a looser limit, and still accurate: LU gives a small residual.
    let fa = NonstandardFrame::from_axes(&i, &j, &near, 1e12).unwrap();
    let x = s.vector([0.3, -1.2, 2.0]);
    let back = fa.vector(arr(fa.contravariant(&x)));
    assert!((back - x).norm() < 1e-5, "residual {:e}", (back - x).norm());
}

/// §2.23 accuracy: on an ill-conditioned frame (κ(A) ≈ 1e6), the LU solve for x|_A keeps the
/// residual ‖Σx_i a_i − x‖ near ε‖A‖‖x|_A‖, while x|_A = G⁻¹x|_[A] loses about κ times more
/// (κ(G) = κ(A)²). The test asserts LU's residual is within 1e3·ε of the scale.
#[test]
fn sec_2_23_lu_beats_gram_inverse_on_ill_conditioned_frame() {
    let s = Frame::new();
    let fa = NonstandardFrame::from_axes(&s.i(), &s.vector([1.0, 1e-6, 0.0]), &s.k(), MAX_CONDITION).unwrap();
    assert!(fa.condition_number() > 1e6);
    let x = s.vector([0.3, -1.2, 2.0]);
    let xc = fa.contravariant(&x);
    let scale = xc.norm();
    let res_lu = (fa.vector(arr(xc)) - x).norm();
    let via_g = fa.gram().try_inverse().unwrap() * fa.covariant(&x);
    let res_g = (fa.vector(arr(via_g)) - x).norm();
    assert!(res_lu <= 1e3 * EPS * scale, "LU residual {res_lu:e}");
    assert!(res_lu <= res_g, "LU {res_lu:e} vs G⁻¹ {res_g:e}");
}

/// A test field f(r) = (v′r)|r|² + |r|⁻¹ written once for f64 and dual numbers.
fn field<T: Scalar>(r: &Vector<T>, v: &Vector<T>) -> T {
    v.dot(r) * r.norm_squared() + T::one() / r.norm()
}

/// (2.24.1)–(2.24.7), Fact 2.24.1: the gradient is a covector, independent of the frame; its
/// components in A are ∂f_A(r_A) = [∂f(F_A r_A)/∂r_Ai], and the chain rule (2.24.6) reads
/// ∂f_A = ∂f_B 𝓞_{B/A}. Checked: dual numbers (exact) against central differences.
#[test]
fn fact_2_24_1_gradient_is_a_frame_independent_covector() {
    let (a, b) = frame_b();
    let r = a.vector([0.7, -0.4, 1.1]);
    let v = [1.0, 2.0, -0.5];
    let va = a.vector(v);
    let g = gradient(|x| field(x, &va.cast()), &r).unwrap();
    // ∂f_A by central differences in A's components: O(h²) + O(ε/h) ≈ 1e-10 at h = 1e-5.
    let partial_in = |f: &Frame| {
        let rf = r.resolve(f);
        let mut d = [0.0; 3];
        for (k, dk) in d.iter_mut().enumerate() {
            let mut e = Vector3::zeros();
            e[k] = 1e-5;
            *dk = (field(&f.vector(arr(rf + e)), &va) - field(&f.vector(arr(rf - e)), &va)) / 2e-5;
        }
        d
    };
    let (d_a, d_b) = (partial_in(&a), partial_in(&b));
    assert_rel_slice(g.resolve(&a).as_slice(), &d_a, 1e-9);
    assert_rel_slice(g.resolve(&b).as_slice(), &d_b, 1e-9);
    let chain = vectrix::nalgebra::RowVector3::from(d_b) * b.orientation_rel(&a);
    assert_rel_slice(chain.as_slice(), &d_a, 1e-9);
    let fd = gradient_central_difference(|x| field(x, &va), &r, 1e-5).unwrap();
    assert_rel_slice(fd.resolve(&a).as_slice(), g.resolve(&a).as_slice(), 1e-9);
}

/// (2.24.10): ∂|r| = r̂′; ∂(v′r) = v′ — dual numbers agree to rounding.
#[test]
fn eq_2_24_10_gradient_of_norm_and_linear_form() {
    let a = Frame::new();
    let r = a.vector([3.0, -4.0, 12.0]);
    let g = gradient(|x| x.norm(), &r).unwrap();
    assert_abs_slice(g.resolve(&a).as_slice(), &[3.0 / 13.0, -4.0 / 13.0, 12.0 / 13.0], 4.0 * EPS);
    assert_eq!(gradient_of_norm(&r), r.unit().map(|u| u.coform()));
    assert!(gradient_of_norm(&Vector::zero()).is_none());
    let v = a.vector([1.0, 2.0, -0.5]);
    let gv = gradient(|x| v.cast().dot(x), &r).unwrap();
    assert_rel_slice(gv.resolve(&a).as_slice(), &[1.0, 2.0, -0.5], EPS);
}

/// (2.24.11) (erratum, sign fixed): ∂|r|⁻ⁿ = −n|r|^{−(n+2)} r′; the printed form mixes r_{y/z}
/// and r_{z/y}. Checked against dual numbers and central differences for n = 1, 2, 3.
#[test]
fn eq_2_24_11_gradient_of_inverse_power_corrected() {
    let a = Frame::new();
    let r = a.vector([0.3, -1.2, 2.0]);
    for n in [1.0, 2.0, 3.0] {
        let want = gradient_of_inverse_power(&r, n).unwrap();
        let dual = gradient(|x| ComplexField::powf(x.norm(), Dual64::from(-n)), &r).unwrap();
        let fd = gradient_central_difference(|x| x.norm().powf(-n), &r, 1e-5).unwrap();
        assert_abs_slice(dual.resolve(&a).as_slice(), want.resolve(&a).as_slice(), 16.0 * EPS);
        // central differences at h = 1e-5: O(h²) + O(ε/h) ≈ 1e-10 on O(1) gradients
        assert_abs_slice(fd.resolve(&a).as_slice(), want.resolve(&a).as_slice(), 1e-9);
        // The sign: |r|⁻ⁿ decreases outward, so ∂f r < 0.
        assert!(want * r < 0.0);
    }
    assert!(gradient_of_inverse_power(&Vector::zero(), 1.0).is_none());
    let bad = a.vector([f64::NAN, 0.0, 0.0]);
    assert!(matches!(gradient(|x| x.norm(), &bad), Err(FrameError::NonFinite { .. })));
    assert!(gradient_central_difference(|x| x.norm(), &r, 0.0).is_err());
}

/// Example 2.25.1 (printed [6.29, 5.27, 1.85], truncated; computed [6.297044, 5.268593,
/// 1.851770]): ℓ = (3, 4, 2), F_A →(3, ψ) F_B →(2, θ) F_C →(3, φ) F_D, ψ = 30°, θ = −20°,
/// φ = 45°; r_{d/a} = ℓ₁î_B + ℓ₂î_C + ℓ₃î_D resolved in A.
#[test]
fn example_2_25_1_position_through_a_chain_of_frames() {
    let a = Frame::new();
    let turn = |f: &Frame, axis: Vector, deg: f64| {
        f.rotated_by_rotor(&Rotor::from_axis_angle(&axis, deg.to_radians()).unwrap())
    };
    let b = turn(&a, a.k(), 30.0);
    let c = turn(&b, b.j(), -20.0);
    let d = turn(&c, c.k(), 45.0);
    let r = b.i() * 3.0 + c.i() * 4.0 + d.i() * 2.0;
    let got = arr(r.resolve(&a));
    // The book prints [6.29, 5.27, 1.85]: 6.297 is chopped to 6.29 (rounding gives 6.30),
    // 5.2686 and 1.8518 are rounded.
    assert_truncated(got[0], "6.29");
    assert_printed_slice(&got[1..], &["5.27", "1.85"]);
    // notes ch1-2a §4b, twelve decimals
    assert_printed_slice(&got, &["6.297043873556", "5.268593137352", "1.851770098599"]);
}

mod prop {
    //! §2.23 identities on random nonstandard frames, including nearly degenerate ones
    //! (κ up to ~1e6): duality, x|_[A] = G x|_A, covariant change by 𝓞_{B/A}, (2.23.28),
    //! M|_[A] = G M|_A G, and round trips. Tolerances scale with κ(A)² (the Gram matrix).

    use proptest::prelude::*;

    use super::*;

    /// Axes: a random standard frame's axes, scaled and sheared, sometimes nearly dependent.
    fn nonstandard() -> impl Strategy<Value = NonstandardFrame> {
        (triple(), triple(), triple(), proptest::sample::select(vec![1.0, 1e-2, 1e-4, 1e-6])).prop_filter_map(
            "independent axes",
            |(x, y, z, e)| {
                let s = Frame::new();
                let a1 = s.vector(x);
                let a3 = a1 + s.vector(y) * e + s.vector(z) * (e * 0.5);
                NonstandardFrame::from_axes(&a1, &s.vector(y), &a3, 1e7).ok()
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]

        #[test]
        fn nonstandard_identities(fa in nonstandard(), fb in nonstandard(), x in triple(), m in [triple(), triple(), triple()]) {
            let s = Frame::new();
            let k2 = fa.condition_number().powi(2).max(fb.condition_number().powi(2));
            let x = s.vector(x);
            let xn = x.norm().max(1.0);
            // Duality (2.23.13).
            let r = fa.reciprocal();
            for (i, ri) in r.axes().iter().enumerate() {
                for (j, aj) in fa.axes().iter().enumerate() {
                    let d = if i == j { 1.0 } else { 0.0 };
                    prop_assert!((ri.dot(aj) - d).abs() <= 1e3 * EPS * k2);
                }
            }
            // x|_[A] = G x|_A (2.23.21), residual of the LU solve.
            let (xc, xv) = (fa.contravariant(&x), fa.covariant(&x));
            let g = fa.gram();
            prop_assert!((xv - g * xc).norm() <= 1e3 * EPS * k2 * xn);
            prop_assert!((fa.vector(arr(xc)) - x).norm() <= 1e3 * EPS * fa.condition_number() * xn);
            // Covariant change (2.23.27, corrected) and (2.23.28) as 𝓞_{B/A} G_A = G_B 𝓞ᵀ_{A/B}.
            let o_ba = fb.orientation_rel(&fa);
            let scale = o_ba.norm().max(1.0);
            prop_assert!((fb.covariant(&x) - o_ba * xv).norm() <= 1e3 * EPS * k2 * scale * xn);
            let o_ab = fa.orientation_rel(&fb);
            let lhs = o_ba * g;
            prop_assert!((lhs - fb.gram() * o_ab.transpose()).norm() <= 1e4 * EPS * k2 * lhs.norm().max(1.0) * scale);
            // M|_[A] = G M|_A G (2.23.49) and the round trip through M|_{A,[A]}.
            let mm = s.dyadic(&Matrix3::from_rows(&m.map(|r| Vector3::from(r).transpose())));
            let m_cov = fa.resolve_dyadic(&mm, Cov, Cov);
            let m_con = fa.resolve_dyadic(&mm, Con, Con);
            let mn = m_cov.norm().max(1.0);
            prop_assert!((m_cov - g * m_con * g).norm() <= 1e4 * EPS * k2 * k2 * mn);
            let back = fa.dyadic(&fa.resolve_dyadic(&mm, Con, Cov), Con, Cov).unwrap();
            prop_assert!((back.resolve(&s) - mm.resolve(&s)).norm() <= 1e4 * EPS * k2 * mm.norm().max(1.0));
        }
    }
}
