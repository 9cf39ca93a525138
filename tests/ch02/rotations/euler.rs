//! §2.12–2.13: Euler matrices, sequences, extraction, gimbal lock.

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

use super::{assert_mat, q_err, rot};
use crate::support::*;

fn o(i: usize, t: f64) -> Matrix3<f64> {
    orientation_about(Axis::from_index(i).unwrap(), t)
}

fn deg(x: f64) -> f64 {
    x.to_radians()
}

/// (2.12.14–16) and Fact 2.12.1: 𝓞₁(θ) = [[1,0,0],[0,c,s],[0,−s,c]], …; 𝓞_{B/A} = 𝓞_i(θ)
/// when F_B = R⃗_{axis i of A}(θ)F_A; 𝓡_i = 𝓞_iᵀ.
#[test]
fn eq_2_12_14_elementary_orientation_matrices() {
    let (c, s) = (0.3f64.cos(), 0.3f64.sin());
    assert_mat(&o(1, 0.3), &Matrix3::new(1.0, 0.0, 0.0, 0.0, c, s, 0.0, -s, c), 0.0);
    assert_mat(&o(2, 0.3), &Matrix3::new(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c), 0.0);
    assert_mat(&o(3, 0.3), &Matrix3::new(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0), 0.0);
    let a = Frame::new();
    for (i, axis) in [(1, a.i()), (2, a.j()), (3, a.k())] {
        let b = Rotation::from_axis_angle(&axis, 0.3).unwrap().apply_frame(&a);
        assert_mat(&b.orientation_rel(&a), &o(i, 0.3), 4.0 * EPS);
        let ax = Axis::from_index(i).unwrap();
        assert_mat(&rotation_about(ax, 0.3), &o(i, 0.3).transpose(), 0.0);
        assert!(
            q_err(
                &quaternion_about(ax, 0.3),
                &Quaternion::from_rotation_matrix_unchecked(&rotation_about(ax, 0.3))
            ) <= 4.0 * EPS
        );
    }
    assert_eq!(Axis::from_index(4), Err(RotationError::InvalidAxis { index: 4 }));
}

/// (2.12.20): 𝓞_i(θ)𝓞_i(φ) = 𝓞_i(θ + φ), where θ + φ is **not** necessarily wrapped (erratum L1910).
#[test]
fn eq_2_12_20_elementary_additivity() {
    for i in 1..=3 {
        assert_mat(&(o(i, 2.5) * o(i, 2.0)), &o(i, 4.5), 8.0 * EPS);
    }
}

/// (2.12.28–33): 3-2-1 (Ψ, Θ, Φ) built frame by frame equals 𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ); oracle at
/// (30°, 20°, 10°) (notes ch1-2a §4c) and its quaternion (notes ch2b §4).
#[test]
fn eq_2_12_32_yaw_pitch_roll() {
    let (psi, theta, phi) = (deg(30.0), deg(20.0), deg(10.0));
    let a = Frame::new();
    let b = Rotation::from_axis_angle(&a.k(), psi).unwrap().apply_frame(&a);
    let c = Rotation::from_axis_angle(&b.j(), theta).unwrap().apply_frame(&b);
    let d = Rotation::from_axis_angle(&c.i(), phi).unwrap().apply_frame(&c);
    let e = EulerAngles::new(EulerSequence::S321, [psi, theta, phi]);
    let want = Matrix3::new(
        0.813797681349,
        0.469846310393,
        -0.342020143326,
        -0.440969610530,
        0.882564119259,
        0.163175911167,
        0.378522306370,
        0.018028311236,
        0.925416578398,
    );
    // twelve printed decimals (notes ch1-2a §4c): half a unit, 5e-13
    assert_mat(&d.orientation_rel(&a), &want, 5e-13);
    assert_mat(&e.orientation_matrix(), &want, 5e-13);
    assert_mat(&(o(1, phi) * o(2, theta) * o(3, psi)), &e.orientation_matrix(), 4.0 * EPS);
    let q = Quaternion::new(0.951548525, 0.038134576, 0.189307857, 0.239298338);
    assert!(q_err(&e.quaternion(), &q) <= 1e-9);
    assert_printed(Rotation::between(&d, &a).axis_angle().angle().to_degrees(), "35.81710");
}

/// (2.12.39–42): 3-1-3 (Φ, Θ, Ψ), 𝓞 = 𝓞₃(Ψ)𝓞₁(Θ)𝓞₃(Φ); oracle at (40°, 30°, −60°), and the
/// orbital (Ω, i, ω) order (2.12.42).
#[test]
fn eq_2_12_39_precession_nutation_spin() {
    let e = EulerAngles::new(EulerSequence::S313, [deg(40.0), deg(30.0), deg(-60.0)]);
    let want = Matrix3::new(
        0.865112928824,
        -0.253139527496,
        -0.433012701892,
        0.385078748556,
        0.888377373311,
        0.25,
        0.321393804843,
        -0.383022221559,
        0.866025403784,
    );
    assert_mat(&e.orientation_matrix(), &want, 5e-13); // twelve printed decimals
    let (big_omega, inc, omega) = (0.2, 0.5, 0.3);
    let orbit = EulerAngles::new(EulerSequence::S313, [big_omega, inc, omega]).orientation_matrix();
    let regress = Matrix3::new(
        0.88476979,
        0.44396984,
        0.14167993,
        -0.45619119,
        0.76296393,
        0.45801271,
        0.09524715,
        -0.46986895,
        0.87758256,
    );
    assert_mat(&orbit, &regress, 5e-9); // eight printed decimals
    assert_mat(&orbit, &(o(3, omega) * o(1, inc) * o(3, big_omega)), 4.0 * EPS);
}

/// Prob 2.26.10: about k̂_A then the *new* ĵ_B gives 𝓞₂(θ)𝓞₃(ψ); about the *old* ĵ_A gives
/// 𝓞₃(ψ)𝓞₂(θ) (extrinsic).
#[test]
fn problem_2_26_10_intrinsic_versus_extrinsic() {
    let (psi, th) = (0.7, -0.4);
    let a = Frame::new();
    let b = Rotation::from_axis_angle(&a.k(), psi).unwrap().apply_frame(&a);
    let c_new = Rotation::from_axis_angle(&b.j(), th).unwrap().apply_frame(&b);
    let c_old = Rotation::from_axis_angle(&a.j(), th).unwrap().apply_frame(&b);
    assert_mat(&c_new.orientation_rel(&a), &(o(2, th) * o(3, psi)), 8.0 * EPS);
    assert_mat(&c_old.orientation_rel(&a), &(o(3, psi) * o(2, th)), 8.0 * EPS);
    let seq = EulerSequence::from_indices([3, 2, 1], EulerKind::Extrinsic).unwrap();
    let ext = EulerAngles::new(seq, [psi, th, 0.0]).orientation_matrix();
    assert_mat(&ext, &(o(3, psi) * o(2, th)), 8.0 * EPS);
}

/// Prob 2.27.1: intrinsic 3-2-1 (Ψ, Θ, Φ) equals the extrinsic 1-2-3 (Φ, Θ, Ψ):
/// R_{k_A}(Ψ)R_{j_A}(Θ)R_{i_A}(Φ)|_A = 𝓡₃𝓡₂𝓡₁.
#[test]
fn problem_2_27_1_gimbal_order() {
    let (psi, th, phi) = (0.3, -1.0, 2.0);
    let a = Frame::new();
    let r = rot(&a, [0.0, 0.0, 1.0], psi) * rot(&a, [0.0, 1.0, 0.0], th) * rot(&a, [1.0, 0.0, 0.0], phi);
    let intrinsic = EulerAngles::new(EulerSequence::S321, [psi, th, phi]);
    let extrinsic = EulerAngles::new(EulerSequence::S123.extrinsic(), [phi, th, psi]);
    assert_mat(&r.rotation_matrix_in(&a), &intrinsic.rotation_matrix(), 8.0 * EPS);
    assert_mat(&extrinsic.rotation_matrix(), &intrinsic.rotation_matrix(), 8.0 * EPS);
}

/// Fact 2.13.1: 𝓞_i(0) = I; 𝓞_i(π) diagonal; 𝓞_i(π) = 𝓞_j(π)𝓞_k(π) for distinct i, j, k;
/// 𝓞_i(−a) = 𝓞_i(a)ᵀ = 𝓞_i(a)⁻¹.
#[test]
fn fact_2_13_1_elementary_properties() {
    assert_mat(&o(1, PI), &Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0)), 4.0 * EPS);
    assert_mat(&o(2, PI), &Matrix3::from_diagonal(&Vector3::new(-1.0, 1.0, -1.0)), 4.0 * EPS);
    assert_mat(&o(3, PI), &Matrix3::from_diagonal(&Vector3::new(-1.0, -1.0, 1.0)), 4.0 * EPS);
    assert_mat(&o(1, PI), &(o(2, PI) * o(3, PI)), 4.0 * EPS);
    for i in 1..=3 {
        assert_eq!(o(i, 0.0), Matrix3::identity());
        assert_mat(&o(i, -0.8), &o(i, 0.8).transpose(), 0.0);
        assert_mat(&(o(i, -0.8) * o(i, 0.8)), &Matrix3::identity(), 4.0 * EPS);
    }
}

/// (2.13.2): the closed form of 𝓞₁(a)𝓞₂(b)𝓞₃(c); regression value at (0.3, 0.5, 0.2).
#[test]
fn eq_2_13_2_closed_form_321() {
    let (a, b, c) = (0.3f64, 0.5f64, 0.2f64);
    let (sa, ca, sb, cb, sc, cc) = (a.sin(), a.cos(), b.sin(), b.cos(), c.sin(), c.cos());
    let want = Matrix3::new(
        cb * cc,
        cb * sc,
        -sb,
        cc * sa * sb - ca * sc,
        ca * cc + sa * sb * sc,
        cb * sa,
        sa * sc + ca * cc * sb,
        ca * sb * sc - cc * sa,
        ca * cb,
    );
    let got = EulerAngles::new(EulerSequence::S321, [c, b, a]).orientation_matrix();
    assert_mat(&got, &want, 4.0 * EPS);
    let regress = Matrix3::new(
        0.86008934,
        0.17434874,
        -0.47942554,
        -0.05094029,
        0.96444082,
        0.25934338,
        0.50759375,
        -0.19863640,
        0.83838664,
    );
    assert_mat(&got, &regress, 1e-8);
}

/// Fact 2.13.2: a rotation is completed from r₁₁, r₁₂, r₁₃, r₂₃, r₃₃ (D = r₁₁² + r₁₂² > 0).
#[test]
fn fact_2_13_2_completion_from_five_entries() {
    let r = EulerAngles::new(EulerSequence::S321, [0.4f64, -0.7, 1.9]).orientation_matrix();
    let d = r[(0, 0)].powi(2) + r[(0, 1)].powi(2);
    let (r11, r12, r13, r23, r33) = (r[(0, 0)], r[(0, 1)], r[(0, 2)], r[(1, 2)], r[(2, 2)]);
    assert_abs(r[(1, 0)], -(r11 * r13 * r23 + r12 * r33) / d, 8.0 * EPS);
    assert_abs(r[(1, 1)], (r11 * r33 - r12 * r13 * r23) / d, 8.0 * EPS);
    assert_abs(r[(2, 0)], (r12 * r23 - r11 * r13 * r33) / d, 8.0 * EPS);
    assert_abs(r[(2, 1)], -(r12 * r13 * r33 + r11 * r23) / d, 8.0 * EPS);
}

/// Fact 2.13.3 (3-2-1 extraction), **corrected** (2.13.17–18): b ≡ −asin r₁₃ or b ≡ asin r₁₃ + π
/// (the printed "b ≡ −r₁₃" is an erratum); both branches rebuild the matrix.
#[test]
fn fact_2_13_3_extraction_321_corrected() {
    let (psi, th, phi) = (2.0, -0.6, -2.9);
    let e = EulerAngles::new(EulerSequence::S321, [psi, th, phi]);
    let r = e.orientation_matrix();
    let EulerSolution::Regular { principal, alternate } =
        EulerAngles::from_rotation_matrix(&e.rotation_matrix(), EulerSequence::S321, ROTATION_TOL).unwrap()
    else {
        panic!("regular expected")
    };
    assert_abs(principal.angles[1], -r[(0, 2)].asin(), 4.0 * EPS);
    assert!(congruent(alternate.angles[1], r[(0, 2)].asin() + PI, 4.0 * EPS));
    for (got, want) in principal.angles.iter().zip([psi, th, phi]) {
        assert_abs(*got, want, 8.0 * EPS); // angles in (−π, π]: absolute
    }
    assert_mat(&alternate.orientation_matrix(), &r, 8.0 * EPS);
}

/// Fact 2.13.4/2.13.12: 𝓞₂(d) = 𝓞₁(a)𝓞₂(b)𝓞₃(c) with a ≡ c ≡ π, b ≡ π − d.
#[test]
fn fact_2_13_4_single_axis_as_321() {
    let d = 0.7;
    let got = EulerAngles::new(EulerSequence::S321, [PI, PI - d, PI]).orientation_matrix();
    assert_mat(&got, &o(2, d), 8.0 * EPS);
}

/// Fact 2.13.5 (3-2-1 gimbal lock): (Φ,Θ,Ψ) = (10°,90°,30°) and (20°,90°,40°) give the same
/// matrix; at b ≡ π/2 only a − c ≡ atan2(r₂₁, r₂₂) is determined (a = Φ, c = Ψ).
#[test]
fn fact_2_13_5_gimbal_lock_321() {
    let m1 = EulerAngles::new(EulerSequence::S321, [deg(30.0), FRAC_PI_2, deg(10.0)]);
    let m2 = EulerAngles::new(EulerSequence::S321, [deg(40.0), FRAC_PI_2, deg(20.0)]);
    assert_mat(&m1.orientation_matrix(), &m2.orientation_matrix(), 4.0 * EPS);
    let want = Matrix3::new(
        0.0,
        0.0,
        -1.0,
        -0.342020143326,
        0.939692620786,
        0.0,
        0.939692620786,
        0.342020143326,
        0.0,
    );
    assert_mat(&m1.orientation_matrix(), &want, 5e-13); // twelve printed decimals
    let r = m1.orientation_matrix();
    match EulerAngles::from_rotation_matrix(&m1.rotation_matrix(), EulerSequence::S321, ROTATION_TOL).unwrap()
    {
        EulerSolution::GimbalLock { middle, combination, sign, representative } => {
            assert_rel(middle, FRAC_PI_2, 4.0 * EPS);
            // Applied order (Ψ, Θ, Φ): Ψ − Φ is determined, = −(a − c).
            assert_eq!(sign, -1);
            assert_abs(combination, -r[(1, 0)].atan2(r[(1, 1)]), 8.0 * EPS);
            assert_abs(combination, deg(30.0) - deg(10.0), 8.0 * EPS);
            assert_mat(&representative.orientation_matrix(), &r, 8.0 * EPS);
        }
        other => panic!("gimbal lock expected, got {other:?}"),
    }
    // b ≡ −π/2: a + c ≡ atan2(−r₂₁, r₂₂).
    let m3 = EulerAngles::new(EulerSequence::S321, [0.5, -FRAC_PI_2, 0.2]);
    let r3 = m3.orientation_matrix();
    let sol = EulerAngles::from_quaternion(&m3.quaternion(), EulerSequence::S321);
    let EulerSolution::GimbalLock { combination, sign, .. } = sol else { panic!("lock") };
    assert_eq!(sign, 1);
    assert_abs(combination, (-r3[(1, 0)]).atan2(r3[(1, 1)]), 8.0 * EPS);
}

/// Fact 2.13.6 **corrected** ((2.13.26) prints 𝓞₁(c) for 𝓞₃(c)): 𝓞₂(±π/2) = 𝓞₁(a)𝓞₂(b)𝓞₃(c)
/// ⟺ b ≡ ±π/2 and a ≡ ±c.
#[test]
fn fact_2_13_6_corrected_pitch_only() {
    let a = 0.9;
    assert_mat(&(o(1, a) * o(2, FRAC_PI_2) * o(3, a)), &o(2, FRAC_PI_2), 8.0 * EPS);
    assert_mat(&(o(1, a) * o(2, -FRAC_PI_2) * o(3, -a)), &o(2, -FRAC_PI_2), 8.0 * EPS);
    // The printed form with 𝓞₁(c) is false:
    assert!(super::mat_err(&(o(1, a) * o(2, FRAC_PI_2) * o(1, a)), &o(2, FRAC_PI_2)) > 0.1);
}

/// (2.13.27) and Fact 2.13.7 (1-2-1 extraction): b ≡ ±acos r₁₁ (computed by atan2 here).
#[test]
fn fact_2_13_7_extraction_121() {
    let (a, b, c) = (0.4f64, 1.1f64, -2.0f64);
    let (sa, ca, sb, cb, sc, cc) = (a.sin(), a.cos(), b.sin(), b.cos(), c.sin(), c.cos());
    let want = Matrix3::new(
        cb,
        sb * sc,
        -sb * cc,
        sa * sb,
        ca * cc - cb * sa * sc,
        ca * sc + cb * cc * sa,
        ca * sb,
        -cc * sa - ca * cb * sc,
        ca * cb * cc - sa * sc,
    );
    // 𝓞₁(a)𝓞₂(b)𝓞₁(c) is 1-2-1 with c applied first.
    let e = EulerAngles::new(EulerSequence::S121, [c, b, a]);
    assert_mat(&e.orientation_matrix(), &want, 4.0 * EPS);
    let EulerSolution::Regular { principal, .. } =
        EulerAngles::from_quaternion(&e.quaternion(), EulerSequence::S121)
    else {
        panic!("regular")
    };
    // acos amplifies the rounding of cos β by 1/sin β
    assert_rel(principal.angles[1], want[(0, 0)].acos(), 1e-12);
    for (g, w) in principal.angles.iter().zip([c, b, a]) {
        assert_abs(*g, w, 16.0 * EPS); // angles in (−π, π]: absolute
    }
}

/// Fact 2.13.8, **corrected** (2.13.34/36): at b ≡ π, a − c ≡ atan2(−r₂₃, r₂₂) ≡ atan2(−r₃₂, −r₃₃);
/// at b ≡ 0, a + c ≡ atan2(r₂₃, r₂₂).
#[test]
fn fact_2_13_8_lock_121_corrected() {
    let (a, c) = (0.4, -1.3);
    let e = EulerAngles::new(EulerSequence::S121, [c, PI, a]);
    let r = e.orientation_matrix();
    assert_rel(wrap_angle(a - c), (-r[(1, 2)]).atan2(r[(1, 1)]), 8.0 * EPS);
    assert_rel(wrap_angle(a - c), (-r[(2, 1)]).atan2(-r[(2, 2)]), 8.0 * EPS);
    let EulerSolution::GimbalLock { sign, combination, representative, .. } =
        EulerAngles::from_quaternion(&e.quaternion(), EulerSequence::S121)
    else {
        panic!("lock")
    };
    // Applied order (c, b, a): c − a is determined.
    assert_eq!(sign, -1);
    assert!(congruent(combination, c - a, 16.0 * EPS));
    assert_mat(&representative.orientation_matrix(), &r, 16.0 * EPS);
    let e0 = EulerAngles::new(EulerSequence::S121, [c, 0.0, a]);
    let r0 = e0.orientation_matrix();
    assert_abs(wrap_angle(a + c), r0[(1, 2)].atan2(r0[(1, 1)]), 8.0 * EPS);
    let EulerSolution::GimbalLock { sign, combination, .. } =
        EulerAngles::from_quaternion(&e0.quaternion(), EulerSequence::S121)
    else {
        panic!("lock")
    };
    assert_eq!(sign, 1);
    assert!(congruent(combination, a + c, 16.0 * EPS));
}

/// Facts 2.13.9–2.13.15 (identity and commutation catalogue, sampled).
#[test]
fn facts_2_13_9_to_15_identity_catalogue() {
    let (x, y) = (0.7, -1.2);
    let id = Matrix3::identity();
    // F2.13.9: 𝓞₁(a)𝓞₂(0)𝓞₁(−a) = I.
    assert_mat(&(o(1, x) * o(2, 0.0) * o(1, -x)), &id, 4.0 * EPS);
    // F2.13.10: 𝓞₁(π)𝓞₂(π)𝓞₃(π) = I.
    assert_mat(&(o(1, PI) * o(2, PI) * o(3, PI)), &id, 4.0 * EPS);
    // F2.13.11: b ≡ −d ≡ π/2 and a ≡ c.
    assert_mat(&(o(1, x) * o(2, FRAC_PI_2) * o(3, x) * o(2, -FRAC_PI_2)), &id, 8.0 * EPS);
    // F2.13.13: b ≡ d ≡ π and a ≡ c.
    assert_mat(&(o(1, x) * o(2, PI) * o(1, x) * o(2, PI)), &id, 8.0 * EPS);
    // F2.13.14: 𝓞₁(a)𝓞₂(b) commutes only if a ≡ 0, b ≡ 0, or a ≡ b ≡ π.
    assert_mat(&(o(1, PI) * o(2, PI)), &(o(2, PI) * o(1, PI)), 4.0 * EPS);
    assert!(super::mat_err(&(o(1, x) * o(2, y)), &(o(2, y) * o(1, x))) > 0.1);
    // F2.13.15: a ≡ −c ≡ π/2 and b ≡ d.
    assert_mat(&(o(1, FRAC_PI_2) * o(2, y) * o(1, -FRAC_PI_2) * o(3, y)), &id, 8.0 * EPS);
}

/// Sequences with equal adjacent axes are rejected with a typed error (§2.12: 12 sequences).
#[test]
fn sec_2_12_equal_adjacent_axes_rejected() {
    assert_eq!(
        EulerSequence::from_indices([3, 3, 1], EulerKind::Intrinsic),
        Err(RotationError::EqualAdjacentAxes { axes: [3, 3, 1] })
    );
    assert!(EulerSequence::from_indices([1, 2, 2], EulerKind::Extrinsic).is_err());
    assert!(EulerSequence::from_indices([0, 2, 1], EulerKind::Extrinsic).is_err());
    assert_eq!(EulerSequence::ALL.len(), 12);
    assert_eq!(EulerSequence::ALL.iter().filter(|s| s.is_symmetric()).count(), 6);
}
