//! Hard cases: the accuracy sets of DESIGN §6 and named regressions for failures peers shipped.
//!
//! Every conversion round-trips to a few ulps at θ ∈ {0, 1e-300, 1e-16, 1e-8, 1e-4, π−1e-4,
//! π−1e-8, π−1e-12, π} and with the middle Euler angle at gimbal lock ± 10⁻ᵏ (k = 2..16), in
//! all 12 sequences intrinsic and extrinsic; quaternions are compared up to sign.

mod support;

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Matrix3, Vector3};
use support::{EPS, HARD_ANGLES, NanAmax};
use vectrix::prelude::*;

/// A few ulps: the round-trip bound asserted below (components of size ≤ 1; angle vectors are
/// compared relative to π).
const ULPS: f64 = 4.0 * EPS;

/// Matrix entries are sums of four products of parameters: measured worst 5.2 ulps.
const MATRIX_ULPS: f64 = 8.0 * EPS;

/// Axes for the hard sets: a coordinate axis, a generic rational axis, a skewed one.
fn axes() -> [Vector3<f64>; 4] {
    [
        Vector3::x(),
        Vector3::new(1.0, 2.0, 2.0) / 3.0,
        Vector3::new(-0.3, 0.1, 0.95).normalize(),
        Vector3::new(0.0, -1.0, 1e-9).normalize(),
    ]
}

fn q_err(p: &Quaternion, q: &Quaternion) -> f64 {
    let d = (p.to_vector4() - q.to_vector4()).nan_amax();
    let s = (p.to_vector4() + q.to_vector4()).nan_amax();
    d.min(s)
}

fn all_sequences() -> impl Iterator<Item = EulerSequence> {
    EulerSequence::ALL.into_iter().flat_map(|s| [s, s.extrinsic()])
}

/// Each Euler solution rebuilds q (up to sign).
fn euler_err(q: &Quaternion, seq: EulerSequence) -> f64 {
    match EulerAngles::from_quaternion(q, seq) {
        EulerSolution::Regular { principal, alternate } => {
            q_err(&principal.quaternion(), q).max(q_err(&alternate.quaternion(), q))
        }
        EulerSolution::GimbalLock { representative, .. } => q_err(&representative.quaternion(), q),
    }
}

/// Item 7: q ↔ 𝓡 ↔ Θ ↔ g ↔ p ↔ Euler (24 sequences) at every hard angle, a few ulps.
#[test]
fn round_trips_at_hard_angles() {
    for n in axes() {
        for &th in &HARD_ANGLES {
            let q = Quaternion::from_axis_angle(&n, th).unwrap();
            let r = q.rotation_matrix();
            let ctx = format!("θ = {th:e}, n = {n:?}");
            assert!(
                q_err(&Quaternion::from_rotation_matrix(&r, ROTATION_TOL).unwrap(), &q) <= ULPS,
                "q→𝓡→q {ctx}"
            );
            let r2 = Quaternion::from_rotation_matrix_unchecked(&r).rotation_matrix();
            assert!((r2 - r).nan_amax() <= MATRIX_ULPS, "𝓡→q→𝓡 {ctx}");
            // Angle vector: exact direction and angle, compared relative to θ ≤ π.
            let v = q.angle_vector();
            assert!((v - n * th).nan_amax() <= ULPS * th.max(1.0), "Θ {ctx}: {v:?}");
            assert!(q_err(&Quaternion::from_angle_vector(&v), &q) <= ULPS, "q→Θ→q {ctx}");
            let vm = Quaternion::angle_vector_of_rotation_matrix(&r);
            let vm_err =
                (vm - n * th).nan_amax().min(if th == PI { (vm + n * th).nan_amax() } else { f64::INFINITY });
            assert!(vm_err <= ULPS * th.max(1.0), "𝓡→Θ {ctx}: {vm:?}");
            assert!(q_err(&Quaternion::from_mrp(&q.mrp()), &q) <= ULPS, "q→p→q {ctx}");
            match q.gibbs() {
                Some(g) => assert!(q_err(&Quaternion::from_gibbs(&g), &q) <= ULPS, "q→g→q {ctx}"),
                None => assert_eq!(q.eta(), 0.0, "{ctx}"),
            }
            for seq in all_sequences() {
                assert!(euler_err(&q, seq) <= ULPS, "q→Euler→q {seq:?} {ctx}: {:e}", euler_err(&q, seq));
            }
            // The angle itself, by atan2 (never acos), to a few ulps even at 1e-300.
            assert!((q.axis_angle().angle() - th).abs() <= ULPS * th, "θ {ctx}");
        }
    }
}

/// Item 7: the middle Euler angle at gimbal lock ± 10⁻ᵏ, k = 2..16, all 24 sequences: the
/// angles extracted from the matrix rebuild it, and those extracted from the quaternion rebuild
/// it, to a few ulps, and the middle angle is recovered.
#[test]
fn euler_near_gimbal_lock() {
    for seq in all_sequences() {
        let locks: &[f64] = if seq.is_symmetric() { &[0.0, PI] } else { &[FRAC_PI_2, -FRAC_PI_2] };
        for &lock in locks {
            for k in 2..=16 {
                for side in [-1.0, 1.0] {
                    let mid = lock + side * 10f64.powi(-k);
                    let e = EulerAngles::new(seq, [0.7, mid, -2.3]);
                    let r = e.rotation_matrix();
                    let sol = EulerAngles::from_rotation_matrix(&r, seq, ROTATION_TOL).unwrap();
                    let p = sol.principal();
                    let err = (p.rotation_matrix() - r).nan_amax();
                    assert!(err <= MATRIX_ULPS, "{seq:?} β = {mid:e}: rebuild error {err:e}");
                    // Principal β is in [−π/2, π/2] (Tait–Bryan) or [0, π] (symmetric): compare
                    // with the input folded into that range.
                    let want = if seq.is_symmetric() { wrap_angle(mid).abs() } else { mid };
                    let want = if !seq.is_symmetric() && want.abs() > FRAC_PI_2 {
                        PI.copysign(want) - want
                    } else {
                        want
                    };
                    assert!((p.angles[1] - want).abs() <= ULPS, "{seq:?} β = {mid:e}: got {:e}", p.angles[1]);
                    // The quaternion route: through 𝓡(q) the outer angles picked up independent
                    // errors ε/cos β and rebuilt a rotation 0.2 away at β = π/2 − 1e-15; the
                    // half-sum/half-difference pairs rebuild q to a few ulps.
                    let q = e.quaternion();
                    let pq = EulerAngles::from_quaternion(&q, seq).principal();
                    let err = q_err(&pq.quaternion(), &q);
                    assert!(err <= ULPS, "{seq:?} β = {mid:e}: q → Euler → q error {err:e}");
                    assert!(
                        (pq.angles[1] - want).abs() <= ULPS,
                        "{seq:?} β = {mid:e} from q: {:e}",
                        pq.angles[1]
                    );
                }
            }
        }
    }
}

/// nalgebra#1078 and #1512: `Rotation3::from_matrix` (iterative, started at the identity) turns
/// a 180° rotation matrix into the identity, because the identity is a stationary point of its
/// iteration there. vectrix's Shepperd/Markley has no iteration: every half-turn comes back.
#[test]
fn issue_nalgebra_1078_1512_half_turn_matrix_is_not_identity() {
    let a = Frame::new();
    for n in axes() {
        let m = -Matrix3::identity() + n * n.transpose() * 2.0; // (2.11.33): 𝓡 = −I + 2nnᵀ
        let r = Rotation::from_rotation_matrix_in(&a, &m, ROTATION_TOL).unwrap();
        assert!((r.angle() - PI).abs() <= ULPS * PI, "n = {n:?}: θ = {}", r.angle());
        assert!((r.rotation_matrix_in(&a) - m).nan_amax() <= MATRIX_ULPS);
        match r.axis_angle_in(&a) {
            AxisAngle::HalfTurn(axis) | AxisAngle::General { axis, .. } => {
                assert!((axis - canonical_half_turn_axis(&n)).nan_amax() <= ULPS, "{axis:?} vs {n:?}")
            }
            AxisAngle::Identity => panic!("a half turn came back as the identity"),
        }
    }
}

/// GTSAM Rot3::Logmap, Sophus#1, pytorch3d#188: the log map near π loses accuracy (θ/(2 sinθ)
/// blows up, acos loses √ε) or returns NaN. vectrix's log through the quaternion and atan2 keeps
/// a few ulps all the way to π.
#[test]
fn issue_sophus_1_pytorch3d_188_log_near_pi() {
    for n in axes() {
        for k in 1..=15 {
            let th = PI - 10f64.powi(-k);
            let m = Quaternion::from_axis_angle(&n, th).unwrap().rotation_matrix();
            let v = Quaternion::from_rotation_matrix(&m, ROTATION_TOL).unwrap().angle_vector();
            assert!(v.iter().all(|x| x.is_finite()));
            // The matrix itself carries ε-level error, which near π moves the axis by ~ε/(π−θ)·(π−θ).
            assert!((v - n * th).nan_amax() <= 8.0 * ULPS * PI, "θ = π − 1e-{k}: {v:?} vs {:?}", n * th);
        }
    }
}

/// dm_control#555: gimbal-lock branches with wrong signs for ZYX, XZY and YZX returned angles
/// that rebuild a different matrix. Every lock branch here rebuilds the matrix, in all 24
/// sequences, at β = ±π/2 exactly (and 0, π for symmetric sequences).
#[test]
fn issue_dm_control_555_gimbal_lock_signs() {
    let named = [
        EulerSequence::S321, // ZYX
        EulerSequence::S132, // XZY
        EulerSequence::S231, // YZX
    ];
    for seq in named.into_iter().chain(all_sequences()) {
        let locks: &[f64] = if seq.is_symmetric() { &[0.0, PI] } else { &[FRAC_PI_2, -FRAC_PI_2] };
        for &lock in locks {
            for (a, c) in [(0.3, 1.1), (-2.0, 2.9), (3.0, -0.4)] {
                let r = EulerAngles::new(seq, [a, lock, c]).rotation_matrix();
                let sol = EulerAngles::from_rotation_matrix(&r, seq, ROTATION_TOL).unwrap();
                let EulerSolution::GimbalLock { combination, sign, representative, .. } = sol else {
                    panic!("{seq:?} at β = {lock}: lock expected, got {sol:?}")
                };
                assert!(
                    (representative.rotation_matrix() - r).nan_amax() <= MATRIX_ULPS,
                    "{seq:?} β = {lock}"
                );
                assert!(congruent(combination, a + f64::from(sign) * c, 8.0 * ULPS), "{seq:?} β = {lock}");
            }
        }
    }
}

/// scipy#22417: Markley's method fed a non-orthonormal matrix returned a rotation 22.6° away from
/// the nearest one (scipy's own docs example). vectrix refuses the matrix with a typed error and
/// projects only on request, by the polar decomposition (the orthogonal Procrustes solution).
#[test]
fn issue_scipy_22417_markley_with_non_orthonormal_input() {
    let a = Frame::new();
    let m = Matrix3::new(1.0, 2.0, 0.0, 2.0, 5.0, 0.0, 0.0, 0.0, 1.0);
    assert!(matches!(
        Rotation::from_rotation_matrix_in(&a, &m, ROTATION_TOL),
        Err(RotationError::NotOrthonormal { .. })
    ));
    let r = Rotation::nearest_in(&a, &m).unwrap().rotation_matrix_in(&a);
    // Polar factor: Rᵀ M is symmetric positive semidefinite, and R maximises tr(Rᵀ M).
    let s = r.transpose() * m;
    assert!((s - s.transpose()).nan_amax() <= 16.0 * EPS * m.norm());
    assert!(s.symmetric_eigenvalues().iter().all(|&l| l >= -16.0 * EPS * m.norm()));
    let markley = Quaternion::from_rotation_matrix_unchecked(&m).rotation_matrix();
    assert!((r.transpose() * m).trace() >= (markley.transpose() * m).trace());
    // A left-handed matrix is a typed error, never silently flipped.
    let left = Matrix3::from_diagonal(&Vector3::new(-1.0, 1.0, 1.0));
    assert!(matches!(
        Quaternion::from_rotation_matrix(&left, ROTATION_TOL),
        Err(RotationError::Reflection { .. })
    ));
}

/// Tiny angles: θ = 1e-300 keeps its value through every representation (no underflow to the
/// identity), and exp/log use series branches near 0.
#[test]
fn tiny_angle_survives_every_representation() {
    let a = Frame::new();
    let v = a.vector([1e-300, -2e-300, 2e-300]);
    let r = Rotation::exp(&v).unwrap();
    assert!((r.angle() - 3e-300).abs() <= 4.0 * EPS * 3e-300);
    let back = r.log().resolve(&a);
    assert!((back - Vector3::new(1e-300, -2e-300, 2e-300)).nan_amax() <= 4.0 * EPS * 3e-300);
    let q = r.quaternion_in(&a);
    assert!((q.gibbs().unwrap() * 2.0 - back).nan_amax() <= 4.0 * EPS * 3e-300);
}

/// The log of a rotation matrix at tiny angles must be *relatively* accurate (a few ulps of θ,
/// not of 1): the direct branch for tr 𝓡 > −0.9 uses vee(𝓡 − 𝓡ᵀ) = 2 sin θ n̂ and asin of whichever of sin θ, cos θ is well conditioned, and must
/// match the Shepperd route it replaced as the fast path (GTSAM/Sophus-style logs lost these
/// digits with acos).
#[test]
fn matrix_log_is_relatively_accurate_at_tiny_and_moderate_angles() {
    for n in axes() {
        // 0.7954 and 2.3462 straddle the asin/acos switches at cos θ = ±0.7
        for th in [
            1e-300, 1e-100, 1e-16, 1e-8, 1e-5, 1e-4, 1e-3, 0.5, 0.7953, 0.7955, 1.5, 2.0, 2.3461, 2.3463,
            2.5, 2.8, 2.83, 3.0, 3.1,
        ] {
            let q = Quaternion::from_axis_angle(&n, th).unwrap();
            let r = q.rotation_matrix();
            let vm = Quaternion::angle_vector_of_rotation_matrix(&r);
            let err = (vm - n * th).nan_amax();
            assert!(err <= 8.0 * f64::EPSILON * th, "θ = {th:e}, n = {n:?}: |err| = {err:e}");
            let via_q = Quaternion::from_rotation_matrix_unchecked(&r).angle_vector();
            assert!((vm - via_q).nan_amax() <= 8.0 * f64::EPSILON * th, "branches disagree at θ = {th:e}");
        }
    }
}

// ---- Batched conversions (SIMD) ---------------------------------------------------------

/// Angle vectors for the batched exponential map: every hard angle on every axis, both signs,
/// then angles past π (non-canonical input, the range-reduced path: up to 10⁵ rad, and 10⁶
/// rad, which the one-rotation code takes), in a count that is not a multiple of the block.
fn batch_angle_vectors() -> Vec<Vector3<f64>> {
    let mut v = Vec::new();
    for n in axes() {
        for &th in HARD_ANGLES.iter().chain(&[0.5, 1.0, 2.0, 3.0]) {
            v.push(n * th);
            v.push(-n * th);
        }
    }
    let canonical = v.len();
    for n in axes() {
        for th in [PI + 1e-12, 3.5, 2.0 * PI, 2.0 * PI - 1e-9, 7.0, 100.0, 12345.678, 1e5, 1e6] {
            v.push(n * th);
        }
    }
    // Then canonical again, so that blocks of each kind follow one another.
    v.extend_from_within(..canonical);
    v
}

/// The batched exponential map agrees with `from_angle_vector` element by element to a few
/// ulps, times |Θ| past 1 (up to sign only at |Θ| = π, where both signs are canonical within
/// rounding).
#[test]
fn batched_from_angle_vectors_matches_one_by_one() {
    let thetas = batch_angle_vectors();
    let batch = Quaternion::from_angle_vectors(&thetas).unwrap();
    let mut into = vec![Quaternion::identity(); thetas.len()];
    Quaternion::from_angle_vectors_into(&thetas, &mut into).unwrap();
    assert_eq!(batch, into);
    for (t, q) in thetas.iter().zip(&batch) {
        let one = Quaternion::from_angle_vector(t);
        let err = if (t.norm() - PI).abs() < 1e-15 {
            q_err(q, &one)
        } else {
            (q.to_vector4() - one.to_vector4()).nan_amax()
        };
        // Past |Θ| = 1 the input's own rounding limits both to ε·|Θ|/2 (h = |Θ|/2 is rounded).
        assert!(err <= ULPS * t.norm().max(1.0), "Θ = {t:?}: batch {q:?} vs {one:?}");
        assert!(q.eta() >= 0.0, "canonical sign at Θ = {t:?}");
    }
}

/// Every hard rotation, every sequence: the batched Euler angles agree with
/// `from_quaternion` to a few ulps (angles compared modulo 2π), the alternate solution too, and
/// at gimbal lock the batch holds exactly the one-rotation `GimbalLock` value.
#[test]
fn batched_euler_angles_match_one_by_one() {
    let mut qs = Vec::new();
    for n in axes() {
        for &th in &HARD_ANGLES {
            qs.push(Quaternion::from_axis_angle(&n, th).unwrap());
        }
    }
    for seq in all_sequences() {
        let mut batch_qs = qs.clone();
        let locks: &[f64] = if seq.is_symmetric() { &[0.0, PI] } else { &[FRAC_PI_2, -FRAC_PI_2] };
        for &lock in locks {
            for k in 2..=16 {
                for side in [-1.0, 0.0, 1.0] {
                    let mid = lock + side * 10f64.powi(-k);
                    batch_qs.push(EulerAngles::new(seq, [0.7, mid, -2.3]).quaternion());
                }
            }
        }
        let batch = EulerAngles::from_quaternions(&batch_qs, seq).unwrap();
        assert_eq!((batch.len(), batch.sequence()), (batch_qs.len(), seq));
        let mut n_locks = 0;
        for (i, q) in batch_qs.iter().enumerate() {
            let one = EulerAngles::from_quaternion(q, seq);
            let got = batch.solution(i).unwrap();
            match (one, got) {
                (EulerSolution::GimbalLock { .. }, _) => {
                    n_locks += 1;
                    assert_eq!(got, one, "{seq:?} lock at {i}");
                    assert_eq!(batch.principal(i).unwrap(), one.principal());
                }
                (
                    EulerSolution::Regular { principal: p1, alternate: a1 },
                    EulerSolution::Regular { principal: p2, alternate: a2 },
                ) => {
                    for (x, y) in p1.angles.iter().zip(&p2.angles).chain(a1.angles.iter().zip(&a2.angles)) {
                        let d = wrap_angle(x - y).abs();
                        assert!(d <= ULPS * PI, "{seq:?} q = {q:?}: {p1:?} vs {p2:?}");
                    }
                    let err = q_err(&p2.quaternion(), q);
                    assert!(err <= ULPS, "{seq:?} rebuild at {i}: {err:e}");
                }
                _ => panic!("{seq:?} at {i}: batch {got:?} vs one {one:?}"),
            }
        }
        assert_eq!(batch.gimbal_locks().len(), n_locks, "{seq:?}");
        assert!(n_locks >= 2, "{seq:?}: the exact locks are in the set");
        assert!(batch.gimbal_locks().windows(2).all(|w| w[0].0 < w[1].0), "ascending");
        assert_eq!(batch.solution(batch_qs.len()), None);
    }
}

/// Bad input to a batched conversion is an error naming the element; lengths must match.
#[test]
fn batched_conversions_reject_bad_input_by_index() {
    let mut thetas = vec![Vector3::new(0.1, 0.2, 0.3); 100];
    thetas[70].y = f64::NAN;
    let err = Quaternion::from_angle_vectors(&thetas).unwrap_err();
    assert!(
        matches!(&err, RotationError::AtElement { index: 70, source }
            if matches!(**source, RotationError::NonFinite { .. })),
        "{err:?}"
    );
    assert!(err.to_string().contains("element 70"), "{err}");
    thetas[70].y = f64::INFINITY;
    assert!(matches!(
        Quaternion::from_angle_vectors(&thetas),
        Err(RotationError::AtElement { index: 70, .. })
    ));
    let mut short = vec![Quaternion::identity(); 99];
    assert_eq!(
        Quaternion::from_angle_vectors_into(&thetas, &mut short),
        Err(RotationError::LengthMismatch { input: 100, output: 99 })
    );

    let mut qs = vec![Quaternion::identity(); 130];
    qs[129] = Quaternion::new(1.0, 1e-6, 0.0, 0.0); // |q| − 1 = 5e-13 > ROTATION_TOL
    let err = EulerAngles::from_quaternions(&qs, EulerSequence::S321).unwrap_err();
    assert!(
        matches!(&err, RotationError::AtElement { index: 129, source }
            if matches!(**source, RotationError::NotUnit { .. })),
        "{err:?}"
    );
    qs[129] = Quaternion::identity();
    qs[5].c = f64::NAN;
    assert!(matches!(
        EulerAngles::from_quaternions(&qs, EulerSequence::S313),
        Err(RotationError::AtElement { index: 5, .. })
    ));
    // Empty input is an empty result.
    assert!(Quaternion::from_angle_vectors(&[]).unwrap().is_empty());
    assert!(EulerAngles::from_quaternions(&[], EulerSequence::S321).unwrap().is_empty());
}

proptest::proptest! {
    /// Batched and one-by-one conversions agree on random batches biased toward the hard
    /// angles (both directions of every axis, lengths not a multiple of the block).
    #[test]
    fn batched_conversions_agree_with_one_by_one(
        items in proptest::collection::vec((support::direction(), support::angle()), 0..150),
        seq_index in 0usize..24,
    ) {
        let thetas: Vec<Vector3<f64>> =
            items.iter().map(|(n, th)| Vector3::from(*n).normalize() * *th).collect();
        let qs = Quaternion::from_angle_vectors(&thetas).unwrap();
        for (t, q) in thetas.iter().zip(&qs) {
            let one = Quaternion::from_angle_vector(t);
            proptest::prop_assert!(q_err(q, &one) <= ULPS, "Θ = {:?}", t);
        }
        let seq = all_sequences().nth(seq_index).unwrap();
        let batch = EulerAngles::from_quaternions(&qs, seq).unwrap();
        for (i, q) in qs.iter().enumerate() {
            let one = EulerAngles::from_quaternion(q, seq).principal().angles;
            let got = batch.principal(i).unwrap().angles;
            for (x, y) in got.iter().zip(&one) {
                proptest::prop_assert!(wrap_angle(x - y).abs() <= ULPS * PI, "{:?}: {:?} vs {:?}", seq, got, one);
            }
        }
    }
}
