//! vectrix-rotation under hostile input (docs/robustness.md): every representation and
//! conversion either refuses its input with a typed error or returns a finite value with the
//! defining property — |q| = 1, R Rᵀ = I with det +1, round trips through another
//! representation — including near θ = 0, θ = π and for parameters of 1e±300.

use crate::support::{NanAmax, nan_max};
use nalgebra::{Matrix3, Matrix4, Rotation3, UnitQuaternion, Vector3};
use vectrix::frames::{Frame, Resolve};
use vectrix::rotation::{
    Axis, AxisAngle, ChainLink, EulerAngles, EulerKind, EulerSequence, Quaternion, RigidDisplacement,
    Rotation, RotationError, Screw, canonical_half_turn_axis, chain_backward, chain_forward,
    check_rotation_matrix, compose_angle_vector, compose_coplanar, compose_euler, compose_gibbs, compose_mrp,
    compose_orientation, compose_quaternion, compose_rotation_matrix, homogeneous, homogeneous_inverse,
    mrp_shadow, nearest_rotation, orientation_about, quaternion_about, rotation_about, scaled_axis, sin_cos,
    sin_cos_slices,
};
use vectrix::tensor::{Rotor, Tensor};

use crate::harness::{err_or, finite, hostile, hostile3, none_or, refused};

const EPS: f64 = f64::EPSILON;
const BAD_TOLS: [f64; 4] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e-9];

fn unit_q(q: &Quaternion) -> bool {
    q.to_vector4().iter().all(|c| c.is_finite()) && (q.norm() - 1.0).abs() <= 8.0 * EPS
}

fn rotation_matrix(r: &Matrix3<f64>) -> bool {
    r.iter().all(|c| c.is_finite())
        && (r * r.transpose() - Matrix3::identity()).nan_amax() <= 16.0 * EPS
        && (r.determinant() - 1.0).abs() <= 16.0 * EPS
}

/// The same rotation: q and p equal up to sign.
fn same(q: &Quaternion, p: &Quaternion, tol: f64) -> bool {
    (q.to_vector4() - p.to_vector4()).nan_amax() <= tol || (q.to_vector4() + p.to_vector4()).nan_amax() <= tol
}

fn valid_rotation(r: &Rotation) -> bool {
    r.is_finite() && (r.rotor().norm() - 1.0).abs() <= 8.0 * EPS
}

/// Hostile angle vectors: every hostile triple, plus rotations within 1e-8 of π.
fn angle_vectors() -> Vec<[f64; 3]> {
    let mut v = hostile3();
    v.push([std::f64::consts::PI, 0.0, 0.0]);
    v.push([std::f64::consts::PI - 1e-8, 0.0, 0.0]);
    v.push([0.0, std::f64::consts::PI, 1e-300]);
    v
}

cases! {
    // Quaternion arithmetic on raw 4-tuples: the norm is exact for 1e±300 and subnormal
    // components; normalize/inverse give |q| = 1 and q q⁻¹ = 1 or None.
    quaternion_arithmetic ["Quaternion::new", "Quaternion::identity", "Quaternion::from_parts", "Quaternion::pure",
        "Quaternion::eta", "Quaternion::epsilon", "Quaternion::to_vector4", "Quaternion::conjugate",
        "Quaternion::norm_squared", "Quaternion::norm", "Quaternion::inverse", "Quaternion::normalize",
        "Quaternion::dot", "Quaternion::left_matrix", "Quaternion::right_matrix", "Quaternion::exp", "Quaternion::ln",
        "Quaternion::canonical", "Quaternion::is_unit", "Quaternion::to_unit_quaternion"] {
        assert!(unit_q(&Quaternion::<f64>::identity()));
        for s in hostile() {
            for q in [Quaternion::new(s, s, 0.0, 0.0), Quaternion::from_parts(s, Vector3::new(0.0, 1.0, 0.0)), Quaternion::pure(Vector3::new(s, 0.0, 0.0))] {
                none_or(q.normalize(), "Quaternion::normalize", unit_q);
                none_or(q.inverse(), "Quaternion::inverse", |qi| {
                    let p = q * *qi;
                    qi.to_vector4().iter().all(|c| c.is_finite()) && (p.to_vector4() - Quaternion::identity().to_vector4()).nan_amax() <= 16.0 * EPS
                });
                none_or(q.ln(), "Quaternion::ln", |l| l.to_vector4().iter().all(|c| c.is_finite()));
                let _ = q.is_unit(f64::NAN);
                if s.is_finite() && s != 0.0 {
                    // (1e200, 1e200, 0, 0) and (1e-200, …): normalisable, with the norm √2|s|.
                    assert!(q.normalize().is_some(), "normalize {q:?}");
                    let n = q.norm();
                    assert!(n.is_finite() || s.abs() > 1e308, "norm {q:?}");
                    assert_eq!(q.conjugate().eta().to_bits(), q.eta().to_bits());
                    assert_eq!(q.epsilon(), -q.conjugate().epsilon());
                    if s.abs() <= 1.0 {
                        assert!((q.left_matrix() * Quaternion::<f64>::identity().to_vector4() - q.to_vector4()).nan_amax() <= EPS);
                        assert!((q.right_matrix() * Quaternion::<f64>::identity().to_vector4() - q.to_vector4()).nan_amax() <= EPS);
                        assert!(q.dot(&q) >= 0.0 && q.norm_squared() >= 0.0);
                        assert!(q.exp().to_vector4().iter().all(|c| c.is_finite()));
                        assert!(q.canonical().eta() >= 0.0);
                        let u = q.normalize().unwrap();
                        assert!(u.is_unit(1e-12) && (u.to_unit_quaternion().norm() - 1.0).abs() <= 8.0 * EPS);
                    }
                }
            }
        }
    }

    // Parameterisations (§2.14–2.17): angle vector, Gibbs vector, MRPs and their shadow,
    // axis–angle. Each maps to a unit quaternion for every finite input (1e300 and 1e-300
    // included, the MRP shadow of a 1e-300 rotation too) and round trips.
    parameterisations_round_trip ["Quaternion::from_axis_angle", "Quaternion::axis_angle", "Quaternion::from_angle_vector",
        "Quaternion::angle_vector", "Quaternion::gibbs", "Quaternion::try_gibbs", "Quaternion::from_gibbs",
        "Quaternion::mrp", "Quaternion::from_mrp", "mrp_shadow", "canonical_half_turn_axis", "scaled_axis",
        "AxisAngle::angle", "AxisAngle::axis", "Quaternion::slerp", "Quaternion::rotate",
        "Quaternion::rotation_matrix", "Quaternion::orientation_matrix"] {
        for x in angle_vectors() {
            let th = Vector3::from(x);
            err_or(Quaternion::from_axis_angle(&th, 1.0), "from_axis_angle", unit_q);
            err_or(Quaternion::from_axis_angle(&Vector3::new(0.0, 0.0, 1.0), x[0]), "from_axis_angle(θ)", unit_q);
            // Gibbs g = ∞ n̂ is the half turn about n̂; NaN stays outside the domain.
            let qg = Quaternion::from_gibbs(&th);
            if !x.iter().any(|c| c.is_nan()) {
                assert!(unit_q(&qg), "from_gibbs({x:?}) = {qg:?}");
            }
            let qm = Quaternion::from_mrp(&th);
            err_or(mrp_shadow(&th), "mrp_shadow", |s| {
                s.iter().all(|c| c.is_finite()) && same(&Quaternion::from_mrp(s), &qm, 64.0 * EPS)
            });
            if !finite(&x) {
                continue;
            }
            assert!(unit_q(&qm), "from_mrp({x:?}) = {qm:?}");
            let q = Quaternion::from_angle_vector(&th);
            assert!(unit_q(&q), "from_angle_vector({x:?})");
            assert!(rotation_matrix(&q.rotation_matrix()) && rotation_matrix(&q.orientation_matrix()));
            // The angle vector of q is the principal one: |Θ| ≤ π, same rotation.
            let back = q.angle_vector();
            assert!(back.norm() <= std::f64::consts::PI + 8.0 * EPS);
            assert!(same(&Quaternion::from_angle_vector(&back), &q, 16.0 * EPS));
            assert!((scaled_axis(&q) - back).nan_amax() <= 8.0 * EPS * back.nan_amax().max(1.0));
            let aa = q.axis_angle();
            assert!((0.0..=std::f64::consts::PI).contains(&aa.angle()));
            if let Some(n) = aa.axis() {
                assert!((n.norm() - 1.0).abs() <= 8.0 * EPS);
            }
            match q.try_gibbs() {
                Ok(g) => {
                    assert!(g.iter().all(|c| c.is_finite()) && same(&Quaternion::from_gibbs(&g), &q, 1e-8));
                    assert_eq!(q.gibbs(), Some(g));
                }
                Err(_) => assert!(q.gibbs().is_none()),
            }
            let p = q.mrp();
            assert!(p.norm() <= 1.0 + 8.0 * EPS && same(&Quaternion::from_mrp(&p), &q, 64.0 * EPS));
            let r = q.rotate(&Vector3::new(1.0, 2.0, 3.0));
            // |q r q̄| = |q|²|r| with ||q| − 1| ≤ 8ε: relative 16ε, and rounding of the product
            assert!((r.norm() - 14f64.sqrt()).abs() <= 32.0 * EPS * 14f64.sqrt(), "rotate by {x:?}: {q:?} → |r| = {}", r.norm());
            assert!((canonical_half_turn_axis(&th).norm() - th.norm()).abs() <= 4.0 * EPS * th.norm() || th.norm() > 1e300);
            for t in hostile() {
                let s = q.slerp(&Quaternion::identity(), t);
                if t.is_finite() && t.abs() <= 1e6 {
                    assert!(unit_q(&s), "slerp({t})");
                }
            }
        }
        // The shadow of tiny MRPs is huge but exact: p = 1e-300 î ↦ −1e300 î.
        let s: Vector3<f64> = mrp_shadow(&Vector3::new(1e-300, 0.0, 0.0)).unwrap();
        assert!((s.x + 1e300).abs() <= 4.0 * EPS * 1e300);
        refused(mrp_shadow(&Vector3::new(5e-324, 0.0, 0.0)), "mrp_shadow of a subnormal (overflow)");
        refused(mrp_shadow(&Vector3::<f64>::zeros()), "mrp_shadow(0)");
    }

    // Rotation matrices: checked constructors refuse non-orthonormal, reflections, NaN and
    // invalid tolerances; Shepperd/Markley round trips; nearest_rotation projects.
    matrices_and_axes ["check_rotation_matrix", "nearest_rotation", "Quaternion::from_rotation_matrix",
        "Quaternion::from_rotation_matrix_unchecked", "Quaternion::angle_vector_of_rotation_matrix",
        "Axis::from_index", "Axis::index", "orientation_about", "rotation_about", "quaternion_about",
        "Quaternion::times_elementary"] {
        for i in [0usize, 4, usize::MAX] {
            refused(Axis::from_index(i), "Axis::from_index");
        }
        for i in 1..=3 {
            assert_eq!(Axis::from_index(i).unwrap().index(), i);
        }
        for th in hostile() {
            for ax in [Axis::from_index(1).unwrap(), Axis::from_index(3).unwrap()] {
                let o = orientation_about(ax, th);
                let r = rotation_about(ax, th);
                let q = quaternion_about(ax, th);
                let qt = Quaternion::<f64>::identity().times_elementary(ax, th);
                if th.is_finite() {
                    assert!(rotation_matrix(&o) && rotation_matrix(&r) && unit_q(&q) && unit_q(&qt), "θ = {th}");
                    assert!((o.transpose() - r).nan_amax() <= 4.0 * EPS);
                    err_or(Quaternion::from_rotation_matrix(&r, 1e-9), "from_rotation_matrix", |p| same(p, &q, 16.0 * EPS));
                    assert!(unit_q(&Quaternion::from_rotation_matrix_unchecked(&r)));
                    assert!(Quaternion::angle_vector_of_rotation_matrix(&r).norm() <= std::f64::consts::PI + 8.0 * EPS);
                }
            }
            let m = Matrix3::new(th, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0);
            err_or(check_rotation_matrix(&m, 1e-9), "check_rotation_matrix", |_| rotation_matrix(&m));
            err_or(nearest_rotation(&m), "nearest_rotation", rotation_matrix);
            err_or(Quaternion::from_rotation_matrix(&m, 1e-9), "from_rotation_matrix", unit_q);
            for tol in BAD_TOLS {
                refused(check_rotation_matrix(&Matrix3::<f64>::identity(), tol), "check_rotation_matrix(bad tol)");
                refused(Quaternion::from_rotation_matrix(&Matrix3::<f64>::identity(), tol), "from_rotation_matrix(bad tol)");
            }
        }
        refused(check_rotation_matrix(&Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0)), 1e-9), "reflection");
        refused(nearest_rotation(&Matrix3::<f64>::zeros()), "nearest_rotation(0)");
    }

    // Euler angles, all 12 sequences: angles → matrix → angles reproduces the matrix; the lock
    // is reported; NaN, non-orthonormal input and invalid tolerances are refused.
    euler_angles_all_sequences ["EulerSequence::new", "EulerSequence::from_indices", "EulerSequence::axes",
        "EulerSequence::kind", "EulerSequence::is_symmetric", "EulerSequence::extrinsic", "EulerSequence::intrinsic",
        "EulerAngles::new", "EulerAngles::rotation_matrix", "EulerAngles::orientation_matrix", "EulerAngles::quaternion",
        "EulerAngles::from_rotation_matrix", "EulerAngles::from_quaternion", "EulerAngles::from_rotation_matrix_unchecked",
        "EulerSolution::principal", "EulerSolution::is_gimbal_lock", "compose_euler"] {
        for bad in [[1usize, 1, 2], [0, 1, 2], [4, 1, 2], [usize::MAX, 2, 3]] {
            refused(EulerSequence::from_indices(bad, EulerKind::Intrinsic), "from_indices");
        }
        let ax = |i| Axis::from_index(i).unwrap();
        refused(EulerSequence::new([ax(1), ax(1), ax(2)], EulerKind::Extrinsic), "EulerSequence::new(equal adjacent)");
        assert!(EulerSequence::new([ax(1), ax(2), ax(1)], EulerKind::Intrinsic).unwrap().is_symmetric());
        for seq in EulerSequence::ALL {
            let _ = (seq.axes(), seq.kind(), seq.is_symmetric(), seq.extrinsic().intrinsic());
            for x in angle_vectors() {
                let e = EulerAngles::new(seq, x);
                let r = e.rotation_matrix();
                if !finite(&x) {
                    continue;
                }
                assert!(rotation_matrix(&r) && rotation_matrix(&e.orientation_matrix()) && unit_q(&e.quaternion()));
                err_or(EulerAngles::from_rotation_matrix(&r, seq, 1e-9), "from_rotation_matrix", |s| {
                    (s.principal().rotation_matrix() - r).nan_amax() <= 1e-12 && !s.is_gimbal_lock() || s.is_gimbal_lock()
                });
                let s = EulerAngles::from_quaternion(&e.quaternion(), seq);
                assert!(s.principal().angles.iter().all(|a| a.is_finite()));
                let u = EulerAngles::from_rotation_matrix_unchecked(&r, seq, 1e-9);
                assert!(u.principal().angles.iter().all(|a| a.is_finite()));
                let c = compose_euler(&e, &e, seq);
                assert!((c.principal().rotation_matrix() - r * r).nan_amax() <= 1e-6 || c.is_gimbal_lock());
            }
            for tol in BAD_TOLS {
                refused(EulerAngles::from_rotation_matrix(&Matrix3::<f64>::identity(), seq, tol), "from_rotation_matrix(bad tol)");
            }
            refused(EulerAngles::from_rotation_matrix(&Matrix3::from_element(f64::NAN), seq, 1e-9), "Euler from NaN");
        }
    }

    // Batched conversions: empty input is fine, non-finite elements are refused with their
    // index, output buffers of another length are refused.
    batches ["Quaternion::from_angle_vectors", "Quaternion::from_angle_vectors_into", "EulerAngles::from_quaternions",
        "EulerBatch::sequence", "EulerBatch::len", "EulerBatch::is_empty", "EulerBatch::angles", "EulerBatch::into_angles",
        "EulerBatch::gimbal_locks", "EulerBatch::principal", "EulerBatch::solution"] {
        assert!(Quaternion::from_angle_vectors(&[]).unwrap().is_empty());
        let thetas: Vec<Vector3<f64>> = angle_vectors().into_iter().map(Vector3::from).collect();
        err_or(Quaternion::from_angle_vectors(&thetas), "from_angle_vectors(hostile)", |qs| qs.iter().all(unit_q));
        let fin: Vec<Vector3<f64>> = thetas.iter().copied().filter(|t| t.iter().all(|c| c.is_finite())).collect();
        let qs = Quaternion::from_angle_vectors(&fin).unwrap();
        for (q, t) in qs.iter().zip(&fin) {
            assert!(unit_q(q), "from_angle_vectors: {t:?} → {q:?}");
        }
        let mut out = vec![Quaternion::identity(); fin.len() + 1];
        refused(Quaternion::from_angle_vectors_into(&fin, &mut out), "from_angle_vectors_into(mismatched)");
        let seq = EulerSequence::S321;
        let b = EulerAngles::from_quaternions(&qs, seq).unwrap();
        assert_eq!((b.len(), b.is_empty(), b.sequence()), (qs.len(), false, seq));
        assert!(b.angles().iter().flatten().all(|a| a.is_finite()));
        assert!(b.principal(b.len()).is_none() && b.solution(usize::MAX).is_none());
        assert!(b.principal(0).is_some() && b.solution(0).is_some());
        assert!(b.gimbal_locks().len() <= b.len());
        assert_eq!(b.into_angles().len(), qs.len());
        assert!(EulerAngles::from_quaternions(&[], seq).unwrap().is_empty());
        refused(EulerAngles::from_quaternions(&[Quaternion::new(f64::NAN, 0.0, 0.0, 0.0)], seq), "from_quaternions(NaN)");
    }

    // The frame-free Rotation: constructors validate; powf and slerp refuse a NaN exponent and
    // give valid rotations for every finite one; exp(1e300 k̂) is a rotation.
    rotation_frame_free ["Rotation::identity", "Rotation::from_rotor", "Rotation::rotor", "Rotation::between",
        "Rotation::from_axis_angle", "Rotation::exp", "Rotation::log", "Rotation::axis_angle", "Rotation::angle",
        "Rotation::apply", "Rotation::apply_dyadic", "Rotation::apply_frame", "Rotation::apply_tensor",
        "Rotation::to_dyadic", "Rotation::compose", "Rotation::inverse", "Rotation::powf", "Rotation::slerp",
        "Rotation::renormalize", "Rotation::taking", "Rotation::commutator", "Rotation::commutes_with",
        "Rotation::is_finite"] {
        let a = Frame::new();
        assert!(valid_rotation(&Rotation::identity()));
        for x in angle_vectors() {
            let th = a.vector(x);
            err_or(Rotation::exp(&th), "Rotation::exp", valid_rotation);
            err_or(Rotation::from_axis_angle(&th, 0.5), "Rotation::from_axis_angle", valid_rotation);
            err_or(Rotation::from_axis_angle(&a.k(), x[0]), "Rotation::from_axis_angle(θ)", valid_rotation);
            none_or(Rotation::taking(&th, &a.k()), "Rotation::taking", |r| {
                valid_rotation(r) && (r.apply(&th.unit().unwrap()) - a.k()).norm() <= 16.0 * EPS
            });
            let raw = Rotor::from_parts_unchecked(x[0], vectrix::tensor::Bivector::zero());
            err_or(Rotation::from_rotor(&raw), "from_rotor", valid_rotation);
            if finite(&x) {
                assert!(Rotation::exp(&th).is_ok(), "exp({x:?})");
            }
        }
        let r = Rotation::from_axis_angle(&a.vector([1.0, 2.0, 3.0]), 2.0).unwrap();
        let s = Rotation::between(&Frame::new().rotated_by_rotor(&r.rotor()), &a);
        assert!(valid_rotation(&s) && (r.rotor().scalar() - s.rotor().scalar()).abs() <= 1e-12);
        for t in hostile() {
            let p = r.powf(t);
            let q = r.slerp(&s, t);
            if t.is_finite() {
                err_or(p, "powf", valid_rotation);
                err_or(q, "slerp", valid_rotation);
            } else {
                refused(p, "powf(non-finite)");
                refused(q, "slerp(non-finite)");
            }
        }
        let half = r.powf(0.5).unwrap();
        assert!((half.compose(&half).to_dyadic().resolve(&a) - r.to_dyadic().resolve(&a)).nan_amax() <= 1e-14);
        assert!((r.compose(&r.inverse()).angle()).abs() <= 1e-7);
        assert!(r.log().norm() <= std::f64::consts::PI && matches!(r.axis_angle(), AxisAngle::General { .. }));
        assert!(valid_rotation(&r.renormalize().unwrap()));
        assert!(r.apply_dyadic(&a.dyadic(&Matrix3::identity())).is_finite());
        assert!((r.apply_frame(&a).orientation_rel(&a)).iter().all(|c| c.is_finite()));
        assert!(r.apply_tensor(&Tensor::from_vector(&a.i())).unwrap().is_finite());
        assert!(r.commutator(&s).is_finite() && r.commutes_with(&r, 1e-12) && !r.commutes_with(&s, f64::NAN));
    }

    // Resolution of a rotation in a frame and interop with nalgebra/mint: matrices are
    // rotations, quaternions unit; checked constructors refuse NaN, non-unit and bad tolerances.
    rotation_resolved_interop ["Rotation::from_rotation_matrix_in", "Rotation::from_rotation_matrix_in_unchecked",
        "Rotation::from_orientation_matrix_in", "Rotation::nearest_in", "Rotation::rotation_matrix_in",
        "Rotation::orientation_matrix_in", "Rotation::quaternion_in", "Rotation::from_quaternion_in",
        "Rotation::axis_angle_in", "Rotation::angle_vector_in", "Rotation::gibbs_in", "Rotation::mrp_in",
        "Rotation::euler_in", "Rotation::from_euler_in", "Rotation::to_unit_quaternion_in",
        "Rotation::from_unit_quaternion_in", "Rotation::to_rotation3_in", "Rotation::from_rotation3_in",
        "Rotation::to_mint_in", "Rotation::to_mint_matrix_in"] {
        let a = Frame::new();
        for s in hostile() {
            let m = Matrix3::new(s, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0);
            err_or(Rotation::from_rotation_matrix_in(&a, &m, 1e-9), "from_rotation_matrix_in", valid_rotation);
            err_or(Rotation::from_orientation_matrix_in(&a, &m, 1e-9), "from_orientation_matrix_in", valid_rotation);
            err_or(Rotation::nearest_in(&a, &m), "nearest_in", valid_rotation);
            err_or(Rotation::from_quaternion_in(&a, &Quaternion::new(s, 0.0, 0.0, 0.0), 1e-9), "from_quaternion_in", valid_rotation);
        }
        for tol in BAD_TOLS {
            refused(Rotation::from_rotation_matrix_in(&a, &Matrix3::identity(), tol), "from_rotation_matrix_in(bad tol)");
            refused(Rotation::from_orientation_matrix_in(&a, &Matrix3::identity(), tol), "from_orientation_matrix_in(bad tol)");
            refused(Rotation::from_quaternion_in(&a, &Quaternion::identity(), tol), "from_quaternion_in(bad tol)");
        }
        for x in angle_vectors().into_iter().filter(|x| finite(x)) {
            let r = Rotation::exp(&a.vector(x)).unwrap();
            let m = r.rotation_matrix_in(&a);
            assert!(rotation_matrix(&m) && rotation_matrix(&r.orientation_matrix_in(&a)));
            assert!(valid_rotation(&Rotation::from_rotation_matrix_in_unchecked(&a, &m)));
            let q = r.quaternion_in(&a);
            assert!(unit_q(&q));
            assert!(r.angle_vector_in(&a).norm() <= std::f64::consts::PI + 8.0 * EPS);
            assert!(r.mrp_in(&a).norm() <= 1.0 + 8.0 * EPS);
            none_or(r.gibbs_in(&a), "gibbs_in", |g| g.iter().all(|c| c.is_finite()));
            let _ = r.axis_angle_in(&a).angle();
            let e = r.euler_in(&a, EulerSequence::S321).principal();
            assert!((Rotation::from_euler_in(&a, &e).rotation_matrix_in(&a) - m).nan_amax() <= 1e-12);
            let uq: UnitQuaternion<f64> = r.to_unit_quaternion_in(&a);
            assert!(same(&Rotation::from_unit_quaternion_in(&a, &uq).quaternion_in(&a), &q, 8.0 * EPS));
            let r3: Rotation3<f64> = r.to_rotation3_in(&a);
            assert!((Rotation::from_rotation3_in(&a, &r3).rotation_matrix_in(&a) - m).nan_amax() <= 16.0 * EPS);
            let mq = r.to_mint_in(&a);
            assert!((mq.s - q.eta()).abs() <= 8.0 * EPS || (mq.s + q.eta()).abs() <= 8.0 * EPS);
            assert!(<[[f64; 3]; 3]>::from(r.to_mint_matrix_in(&a)).iter().flatten().all(|c| c.is_finite()));
        }
    }

    // Composition rules (§2.19): every composed representation agrees with the composed
    // matrices; the Gibbs composition is None exactly at θ = π; coplanar angle vectors compose
    // by addition, and an invalid tolerance answers None.
    compositions ["compose_orientation", "compose_rotation_matrix", "compose_quaternion", "compose_gibbs",
        "compose_mrp", "compose_angle_vector", "compose_coplanar"] {
        let a = Frame::new();
        for x in angle_vectors().into_iter().filter(|x| finite(x)) {
            let q1 = Quaternion::from_angle_vector(&Vector3::from(x));
            let q2 = Quaternion::from_angle_vector(&Vector3::new(0.3, -0.2, 0.1));
            let (r1, r2) = (q1.rotation_matrix(), q2.rotation_matrix());
            let q = compose_quaternion(&q2, &q1);
            assert!(unit_q(&q));
            // 𝓡_{C/A} = 𝓡_{B/A}𝓡_{C/B} (2.10.46)
            assert!((compose_rotation_matrix(&r2, &r1) - q.rotation_matrix()).nan_amax() <= 1e-13);
            assert!(rotation_matrix(&compose_orientation(&r2.transpose(), &r1.transpose())));
            let p = compose_mrp(&q2.mrp(), &q1.mrp());
            assert!(p.iter().all(|c| c.is_finite()) && same(&Quaternion::from_mrp(&p), &q, 1e-12));
            let t = compose_angle_vector(&q2.angle_vector(), &q1.angle_vector());
            assert!(same(&Quaternion::from_angle_vector(&t), &q, 1e-12));
            if let (Some(g1), Some(g2)) = (q1.gibbs(), q2.gibbs()) {
                none_or(compose_gibbs(&g2, &g1), "compose_gibbs", |g| same(&Quaternion::from_gibbs(g), &q, 1e-9));
            }
            let th = a.vector(x);
            none_or(compose_coplanar(&th, &th, 1e-12), "compose_coplanar", |c| c.is_finite());
            assert!(compose_coplanar(&th, &th, f64::NAN).is_none());
        }
        assert!(compose_gibbs(&Vector3::<f64>::new(1e300, 0.0, 0.0), &Vector3::new(-1e-300, 0.0, 0.0)).is_none_or(|g| g.iter().all(|c| c.is_finite())));
    }

    // Rigid displacements (§2.20–2.22): homogeneous matrices round trip; invalid bottom rows,
    // non-rotations and bad tolerances are refused; chains sum finite link offsets.
    rigid_displacements ["RigidDisplacement::new", "RigidDisplacement::apply", "RigidDisplacement::compose",
        "RigidDisplacement::inverse", "RigidDisplacement::screw", "RigidDisplacement::homogeneous_in",
        "RigidDisplacement::from_homogeneous_in", "homogeneous", "homogeneous_inverse", "chain_forward", "chain_backward"] {
        let a = Frame::new();
        let r = Rotation::from_axis_angle(&a.vector([0.0, 0.0, 1.0]), 1.0).unwrap();
        for x in hostile3().into_iter().filter(|x| finite(x) && x.iter().all(|c| c.abs() <= 1e300)) {
            let d = RigidDisplacement::new(r, a.vector(x));
            let y = a.vector([1.0, 0.0, 0.0]);
            let back = d.inverse().apply(&d.apply(&y));
            let scale = x.iter().fold(1.0f64, |m, c| nan_max(m, c.abs()));
            assert!((back - y).norm() <= 16.0 * EPS * scale);
            assert!(d.compose(&d.inverse()).apply(&y).is_finite());
            let h = d.homogeneous_in(&a);
            err_or(RigidDisplacement::from_homogeneous_in(&a, &h, 1e-9), "from_homogeneous_in", |e| (e.apply(&y) - d.apply(&y)).norm() <= 16.0 * EPS * scale);
            assert!((homogeneous_inverse(&h) * h - Matrix4::identity()).nan_amax() <= 16.0 * EPS * scale);
            match d.screw(1e-12) {
                Screw::Translation(t) => assert!(t.is_finite()),
                other => assert!(format!("{other:?}").find("NaN").is_none(), "{other:?}"),
            }
            let _ = d.screw(f64::NAN);
        }
        let mut h = homogeneous(&Matrix3::identity(), &Vector3::new(1.0, 2.0, 3.0));
        for tol in BAD_TOLS {
            refused(RigidDisplacement::from_homogeneous_in(&a, &h, tol), "from_homogeneous_in(bad tol)");
        }
        h[(3, 0)] = f64::NAN;
        refused(RigidDisplacement::from_homogeneous_in(&a, &h, 1e-9), "from_homogeneous_in(NaN row)");
        assert_eq!(chain_forward::<f64>(&[]), Vector3::zeros());
        assert_eq!(chain_backward::<f64>(&[]), Vector3::zeros());
        let link = ChainLink { o_child_parent: Matrix3::identity(), r_in_child: Vector3::new(1.0, 0.0, 0.0) };
        assert!((chain_forward(&[link, link]) - Vector3::new(2.0, 0.0, 0.0)).nan_amax() <= EPS);
        assert!((chain_backward(&[link, link]) - Vector3::new(2.0, 0.0, 0.0)).nan_amax() <= EPS);
    }
    // sin_cos (§2.12): the branch-free f64 kernel agrees with libm to within 2 ulp on
    // |x| ≤ 2·10⁵ (each is within 1 ulp of the true value), larger and non-finite arguments go
    // to libm (NaN in, NaN out; ±∞ gives NaN), and f32 takes its own sin_cos.
    sine_and_cosine ["sin_cos"] {
        let close = |a: f64, b: f64| a == b || (a - b).abs() <= 2.0 * EPS * b.abs() || (a.is_nan() && b.is_nan());
        let sweep = (0..4001).map(|k| -2.0e5 + 100.0 * k as f64 + 0.37);
        let near_pi = (1..2000).map(|k| k as f64 * std::f64::consts::FRAC_PI_2);
        for x in hostile().chain(sweep).chain(near_pi).chain([2.0e5, -2.0e5, 2.0e5 + 1.0, 1e-310, -0.0]) {
            let (s, c) = sin_cos(x);
            let (ls, lc) = x.sin_cos();
            assert!(close(s, ls) && close(c, lc), "sin_cos({x:e}) = ({s:e}, {c:e}), libm ({ls:e}, {lc:e})");
        }
        let (s, c) = sin_cos(0.5f32);
        assert_eq!((s, c), 0.5f32.sin_cos());
    }
    // sin_cos_slices (§2.12): many angles at once give sin_cos's bits element by element
    // (hostile values, the reduction's boundary, NaN and ±∞ among ordinary ones, at every
    // length from 0 to 9 so that every SIMD tail is taken); outputs of another length are a
    // typed error and are left as they were.
    sine_and_cosine_of_many ["sin_cos_slices"] {
        let xs: Vec<f64> = hostile().chain([2.0e5, -2.0e5, 2.0e5 + 1.0, 1e-310, -0.0, 0.3, -7.0]).collect();
        for len in 0..=9usize {
            for start in 0..xs.len().saturating_sub(len) {
                let x = &xs[start..start + len];
                let (mut s, mut c) = (vec![0.0; len], vec![0.0; len]);
                sin_cos_slices(x, &mut s, &mut c).expect("same lengths");
                for k in 0..len {
                    let (ws, wc) = sin_cos(x[k]);
                    let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
                    assert!(same(s[k], ws) && same(c[k], wc), "sin_cos_slices at {:e}", x[k]);
                }
            }
        }
        let (mut s, mut c) = (vec![9.0; 3], vec![9.0; 2]);
        assert!(matches!(
            sin_cos_slices(&[1.0, 2.0, 3.0], &mut s, &mut c),
            Err(RotationError::LengthMismatch { input: 3, output: 2 })
        ));
        assert_eq!((s, c), (vec![9.0; 3], vec![9.0; 2]));
    }
}
