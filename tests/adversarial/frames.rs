//! vectrix-frames under hostile input (docs/robustness.md): frames are orthonormal and
//! right-handed or refused; resolution and change of frame round trip; gradients are exact
//! or refused where f is not differentiable.

use crate::support::{NanAmax, nan_max};
use nalgebra::{DMatrix, Matrix3, RowVector3, Vector3};
use vectrix::frames::{
    Components, Frame, NonstandardFrame, Resolve, change_frame_covector, change_frame_dyadic,
    change_frame_tensor, change_frame_vector, gradient, gradient_central_difference,
    gradient_of_inverse_power, gradient_of_norm, max_abs_diff_in, resolve_dyadic_mixed,
};
use vectrix::tensor::{Dyadic, Rotor, Tensor};

use crate::harness::{err_or, finite, hostile, hostile3, none_or, refused};

const EPS: f64 = f64::EPSILON;
const BAD_TOLS: [f64; 4] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e-9];

fn orthonormal(f: &Frame) -> bool {
    let o = f.orientation_rel(&Frame::new());
    (o * o.transpose() - Matrix3::identity()).nan_amax() <= 16.0 * EPS
        && (o.determinant() - 1.0).abs() <= 16.0 * EPS
}

fn tilted() -> Frame {
    Frame::new()
        .rotated_by_rotor(&Rotor::from_axis_angle(&Frame::new().vector([1.0, -2.0, 0.5]), 0.7).unwrap())
}

cases! {
    // A frame is three orthonormal right-handed axes (book §2.4): every constructor returns
    // one or a typed error, whatever the axes, matrix or tolerance.
    frame_constructors ["Frame::new", "Frame::identity", "Frame::cast", "Frame::from_axes",
        "Frame::rotated_by_rotor", "Frame::rotated_by", "Frame::from_orientation_rel", "Frame::i",
        "Frame::j", "Frame::k", "Frame::axis", "Frame::orientation_rel", "Frame::rotation_rel",
        "Frame::rotation_dyadic_rel"] {
        let a = Frame::new();
        assert!(orthonormal(&a) && orthonormal(&Frame::<f64>::identity()));
        assert_eq!(a.cast::<f32>().i().resolve(&Frame::<f32>::identity()).x, 1.0f32);
        assert!(a.axis(0).is_none() && a.axis(4).is_none() && a.axis(usize::MAX).is_none());
        assert_eq!(a.axis(1), Some(a.i()));
        for x in hostile3() {
            let i = a.vector(x);
            err_or(Frame::from_axes(&i, &a.j(), &a.k(), 1e-9), "Frame::from_axes", orthonormal);
            let m = Matrix3::from_diagonal(&Vector3::from(x));
            err_or(Frame::from_orientation_rel(&a, &m, 1e-9), "from_orientation_rel", orthonormal);
            err_or(a.rotated_by(&a.dyadic(&m), 1e-9), "rotated_by", orthonormal);
        }
        let b = tilted();
        for tol in BAD_TOLS {
            refused(Frame::from_axes(&b.i(), &b.j(), &b.k(), tol), "from_axes(bad tol)");
            refused(Frame::from_orientation_rel(&a, &b.orientation_rel(&a), tol), "from_orientation_rel(bad tol)");
            refused(a.rotated_by(&b.rotation_dyadic_rel(&a), tol), "rotated_by(bad tol)");
        }
        // 𝓡_{B/A} = 𝓞_{B/A}ᵀ, both orthonormal.
        let (o, r) = (b.orientation_rel(&a), b.rotation_rel(&a));
        assert!((o.transpose() - r).nan_amax() <= 4.0 * EPS);
        assert!((b.rotation_dyadic_rel(&a).apply(&a.i()).resolve(&a) - b.i().resolve(&a)).nan_amax() <= 8.0 * EPS);
        for s in hostile() {
            let rotor = Rotor::from_parts_unchecked(s, vectrix::tensor::Bivector::zero());
            let f = a.rotated_by_rotor(&rotor);
            if s.is_finite() && (s.abs() - 1.0).abs() <= EPS {
                assert!(orthonormal(&f));
            }
        }
    }

    // Numbers enter through a frame; the checked constructors refuse NaN/∞; resolution and
    // change of frame round trip (2.4.16, 2.10).
    resolution_round_trips ["Frame::vector", "Frame::try_vector", "Frame::try_dyadic", "Frame::covector",
        "Frame::dyadic", "Frame::tensor", "Resolve::resolve", "change_frame_vector", "change_frame_covector",
        "change_frame_dyadic", "change_frame_tensor", "Frame::identity_vector", "Frame::identity_components"] {
        let (a, b) = (Frame::new(), tilted());
        for x in hostile3() {
            // the identity frame without arithmetic: components in and out unchanged, bit for bit
            let got = Frame::identity_components(&Frame::identity_vector(x));
            assert_eq!(got.map(f64::to_bits).as_slice(), x.map(f64::to_bits).as_slice(), "{x:?}");
            if x.iter().all(|c| c.is_finite()) {
                assert_eq!(Frame::identity_vector(x), a.vector(x));
            }
            err_or(a.try_vector(x), "try_vector", |v| v.is_finite());
            let m = Matrix3::from_diagonal(&Vector3::from(x));
            err_or(a.try_dyadic(&m), "try_dyadic", |d| d.is_finite());
            let dm = DMatrix::from_row_slice(3, 1, &x);
            err_or(b.tensor(1, 0, &dm), "Frame::tensor", |t| t.is_finite());
            err_or(change_frame_tensor(&dm, 1, 0, &a, &b), "change_frame_tensor", |t| t.iter().all(|c| c.is_finite()));
            if finite(&x) {
                let v = b.vector(x);
                let back: Vector3<f64> = v.resolve(&b);
                // relative to the largest component, with an absolute floor of a few subnormal
                // units (subnormals carry fewer bits)
                let scale = x.iter().fold(f64::MIN_POSITIVE, |m, c| nan_max(m, c.abs()));
                if scale < 1e300 {
                    assert!((back - Vector3::from(x)).nan_amax() <= 8.0 * EPS * scale, "{x:?}");
                    let xb = change_frame_vector(&Vector3::from(x), &b, &a);
                    assert!((change_frame_vector(&xb, &a, &b) - Vector3::from(x)).nan_amax() <= 16.0 * EPS * scale);
                    let cb = change_frame_covector(&RowVector3::from_row_slice(&x), &b, &a);
                    assert!(cb.iter().all(|c| c.is_finite()) && b.covector(x).is_finite());
                    let md = change_frame_dyadic(&m, &b, &a);
                    assert!((change_frame_dyadic(&md, &a, &b) - m).nan_amax() <= 32.0 * EPS * scale);
                    assert!(b.dyadic(&m).is_finite());
                }
            }
        }
        // Shapes: a (1, 0) tensor has 3 components; wrong shapes are errors, not panics.
        refused(a.tensor(1, 0, &DMatrix::zeros(2, 1)), "tensor(wrong shape)");
        refused(a.tensor(40, 0, &DMatrix::zeros(3, 1)), "tensor(huge order)");
        refused(change_frame_tensor(&DMatrix::zeros(0, 0), 1, 1, &a, &b), "change_frame_tensor(empty)");
    }

    // A tensor's cap and the comparison of two tensors' components live with the frames
    // (issue 38, item 5): caps below the size, mismatched types, NaN/∞ and overflowing
    // differences are typed errors; otherwise the worst entry of (X − Y)|_A, finite and ≥ 0.
    tensor_caps_and_comparison ["Frame::tensor_with_limit", "max_abs_diff_in"] {
        let (a, b) = (Frame::new(), tilted());
        for limit in [0, 1, 8] {
            refused(a.tensor_with_limit(2, 0, &DMatrix::zeros(9, 1), limit), "tensor_with_limit(below the size)");
        }
        refused(a.tensor_with_limit(1000, 0, &DMatrix::zeros(9, 1), usize::MAX), "tensor_with_limit(3^1000)");
        refused(a.tensor_with_limit(2, 0, &DMatrix::zeros(8, 1), 9), "tensor_with_limit(wrong shape)");
        for limit in [9, 81, usize::MAX] {
            err_or(a.tensor_with_limit(2, 0, &DMatrix::zeros(9, 1), limit), "tensor_with_limit", |t| {
                t.max_components() == limit && t.is_finite()
            });
        }
        let x = b.tensor(1, 0, &DMatrix::from_row_slice(3, 1, &[1.0, -2.0, 3.0])).unwrap();
        refused(max_abs_diff_in(&x, &Tensor::identity(), &a), "max_abs_diff_in(types differ)");
        for s in hostile() {
            // Tensor::scalar is a plain constructor: NaN and ∞ enter, and are refused here
            let t = Tensor::scalar(s);
            let one = Tensor::scalar(1.0);
            err_or(max_abs_diff_in(&t, &one, &b), "max_abs_diff_in", |d| *d == (s - 1.0).abs());
            if !s.is_finite() {
                refused(max_abs_diff_in(&t, &one, &b), "max_abs_diff_in(non-finite)");
            }
            for y in hostile3() {
                let ty = Tensor::from_vector(&a.vector(y));
                // components up to ±f64::MAX: a finite worst entry, or Overflow when the
                // difference (or its rotation into B) leaves the finite range, never ∞
                err_or(max_abs_diff_in(&x, &ty, &b), "max_abs_diff_in(vectors)", |d| d.is_finite() && *d >= 0.0);
                let neg = Tensor::from_vector(&a.vector([-f64::MAX, 0.0, 0.0]));
                err_or(max_abs_diff_in(&ty, &neg, &b), "max_abs_diff_in(huge)", |d| d.is_finite() && *d >= 0.0);
            }
        }
    }

    // Nonstandard frames (§2.23): reciprocal axes satisfy a_i · a^j = δ_ij; degenerate,
    // non-finite or ill-conditioned axes and invalid condition limits are refused.
    nonstandard_frames ["NonstandardFrame::from_axes", "NonstandardFrame::from_frame", "NonstandardFrame::axis",
        "NonstandardFrame::axes", "NonstandardFrame::condition_number", "NonstandardFrame::alpha",
        "NonstandardFrame::reciprocal", "NonstandardFrame::gram", "NonstandardFrame::contravariant",
        "NonstandardFrame::covariant", "NonstandardFrame::vector", "NonstandardFrame::vector_from_covariant",
        "NonstandardFrame::resolve_dyadic", "NonstandardFrame::dyadic", "NonstandardFrame::orientation_rel",
        "resolve_dyadic_mixed"] {
        let a = Frame::new();
        for x in hostile3() {
            let r = NonstandardFrame::from_axes(&a.vector(x), &a.j(), &a.k(), 1e12);
            err_or(r, "NonstandardFrame::from_axes", |f| {
                let rec = f.reciprocal();
                let ax = f.axes();
                let rx = rec.axes();
                f.condition_number().is_finite() && f.alpha().is_finite() && (0..3).all(|i| {
                    (0..3).all(|j| (ax[i].dot(&rx[j]) - if i == j { 1.0 } else { 0.0 }).abs() <= 1e-6)
                })
            });
        }
        for c in [f64::NAN, -1.0, 0.5, f64::NEG_INFINITY] {
            refused(NonstandardFrame::from_axes(&a.i(), &a.j(), &a.k(), c), "from_axes(bad max_cond)");
        }
        let n = NonstandardFrame::from_axes(&a.i(), &(a.i() + a.j()), &a.k(), 1e6).unwrap();
        assert!(n.axis(0).is_none() && n.axis(3).is_some());
        let s = NonstandardFrame::from_frame(&a);
        assert!((s.gram() - Matrix3::identity()).nan_amax() <= 4.0 * EPS);
        for x in hostile3() {
            if finite(&x) && x.iter().all(|c| c.abs() < 1e300) {
                let v = n.vector(x);
                let scale = x.iter().fold(1e-300f64, |m, c| nan_max(m, c.abs()));
                assert!((n.contravariant(&v) - Vector3::from(x)).nan_amax() <= 16.0 * EPS * scale);
                let cov = n.covariant(&v);
                assert!((n.vector_from_covariant([cov.x, cov.y, cov.z]).resolve(&a) - v.resolve(&a)).nan_amax() <= 32.0 * EPS * scale);
                let m = Matrix3::from_diagonal(&Vector3::from(x));
                err_or(n.dyadic(&m, Components::Contravariant, Components::Covariant), "NonstandardFrame::dyadic", |d| {
                    (n.resolve_dyadic(d, Components::Contravariant, Components::Covariant) - m).nan_amax() <= 64.0 * EPS * scale
                });
                let d = a.dyadic(&m);
                let mixed = resolve_dyadic_mixed(&d, (&n, Components::Covariant), (&s, Components::Contravariant));
                assert!(mixed.iter().all(|c| c.is_finite()));
            }
        }
        assert!(n.orientation_rel(&s).iter().all(|c| c.is_finite()));
        refused(n.dyadic(&Matrix3::from_element(f64::NAN), Components::Covariant, Components::Covariant), "dyadic(NaN)");
    }

    // Gradients (§2.24): exact where f is differentiable, an error where it is not (|r⃗| at
    // 0⃗), at non-finite points, or for a non-positive/NaN step.
    gradients ["gradient", "gradient_central_difference", "gradient_of_norm", "gradient_of_inverse_power"] {
        let a = Frame::new();
        refused(gradient(|r| r.norm(), &a.vector([0.0, 0.0, 0.0])), "gradient of |r| at 0");
        for x in hostile3() {
            let r = a.vector(x);
            // ∂|r⃗|/∂r⃗ = r̂′: unit length.
            err_or(gradient(|r| r.norm(), &r), "gradient(|r|)", |g| (g.norm() - 1.0).abs() <= 8.0 * EPS);
            none_or(gradient_of_norm(&r), "gradient_of_norm", |g| (g.norm() - 1.0).abs() <= 8.0 * EPS);
            none_or(gradient_of_inverse_power(&r, 2.0), "gradient_of_inverse_power", |g| g.is_finite());
            for h in hostile() {
                err_or(gradient_central_difference(|r| r.norm_squared(), &r, h), "central difference", |g| g.is_finite());
            }
        }
        for n in [f64::NAN, f64::INFINITY] {
            none_or(gradient_of_inverse_power(&a.vector([1.0, 0.0, 0.0]), n), "inverse power(NaN n)", |g| g.is_finite());
        }
        let _ = Dyadic::<f64>::identity();
    }
}
