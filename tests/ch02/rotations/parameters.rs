//! §2.14–2.18: exponential map, Euler parameters, quaternions, Gibbs vectors (and MRPs).

use crate::support::NanAmax;
use std::f64::consts::PI;

use nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

use super::{assert_mat, assert_vec, q_err, rodrigues, rot, unit};
use crate::support::*;

/// Fact 2.14.1: for |x| = |y| not parallel, y = exp(θ⃗_{y/x}^×) x with θ⃗ = θ(x̂×ŷ)/sinθ.
#[test]
fn fact_2_14_1_exp_takes_x_to_y() {
    let a = Frame::new();
    let (x, y) = (a.vector([1.0, 2.0, 2.0]), a.vector([3.0, 0.0, 0.0]));
    let th = y.angle_vector_rel(&x).unwrap();
    assert_vec(&Rotation::exp(&th).unwrap().apply(&x).resolve(&a), &y.resolve(&a), 8.0 * EPS);
}

/// Fact 2.14.2 (2.14.12–15): exp(Θ^×) = cosθ I + ((1−cosθ)/θ²)ΘΘᵀ + (sinθ/θ)Θ^×
/// = I + (sinθ/θ)Θ^× + ½(sin(θ/2)/(θ/2))²Θ^{×2}; all forms agree (and with Rodrigues).
#[test]
fn fact_2_14_2_exponential_forms_agree() {
    let a = Frame::new();
    for th in [1e-3, 0.5, 2.0, 3.1] {
        let v = unit([1.0, -2.0, 0.3]) * th;
        let x = v.cross_matrix();
        let f12 = Matrix3::identity() * th.cos()
            + v * v.transpose() * ((1.0 - th.cos()) / (th * th))
            + x * (th.sin() / th);
        let s = (th / 2.0).sin() / (th / 2.0);
        let f15 = Matrix3::identity() + x * (th.sin() / th) + x * x * (0.5 * s * s);
        let got = Rotation::exp(&a.vector(v.into())).unwrap().rotation_matrix_in(&a);
        assert_mat(&got, &f15, 8.0 * EPS);
        assert_mat(&got, &f12, 1e-12);
        assert_mat(&got, &rodrigues(&v, th), 8.0 * EPS);
        assert_vec(&Rotation::exp(&a.vector(v.into())).unwrap().log().resolve(&a), &v, 8.0 * EPS);
    }
}

/// (2.14.17): 𝓡 = exp[θ/(2 sinθ)·(𝓡 − 𝓡ᵀ)] for θ ∈ (0, π): the matrix log agrees with log().
#[test]
fn eq_2_14_17_log_matrix_form() {
    let a = Frame::new();
    let r = rot(&a, [0.3, 1.0, -0.2], 1.4);
    let m = r.rotation_matrix_in(&a);
    let th = 1.4f64;
    let w = (m - m.transpose()) * (th / (2.0 * th.sin()));
    let v = Vector3::new(w[(2, 1)], w[(0, 2)], w[(1, 0)]);
    assert_vec(&r.angle_vector_in(&a), &v, 16.0 * EPS);
}

/// Fact 2.14.3: exp(Θ_{C/A}^×) = exp(Θ_{C/B}^×)exp(Θ_{B/A}^×), but angle vectors do not add.
#[test]
fn fact_2_14_3_angle_vectors_do_not_add() {
    let (t_cb, t_ba) = (Vector3::new(0.9, 0.0, 0.0), Vector3::new(0.0, 0.78, 1.04));
    let t_ca = compose_angle_vector(&t_cb, &t_ba);
    let lhs = Quaternion::from_angle_vector(&t_ca).rotation_matrix();
    let rhs = compose_rotation_matrix(
        &Quaternion::from_angle_vector(&t_cb).rotation_matrix(),
        &Quaternion::from_angle_vector(&t_ba).rotation_matrix(),
    );
    assert_mat(&lhs, &rhs, 8.0 * EPS);
    assert!((t_ca - (t_cb + t_ba)).nan_amax() > 0.1);
}

/// Fact 2.14.4: if Θ = v×w then 𝓡 = exp(wvᵀ − vwᵀ).
#[test]
fn fact_2_14_4_exp_of_wedge() {
    let (v, w) = (Vector3::new(0.2, 0.5, -0.1), Vector3::new(-0.4, 0.3, 0.9));
    let lhs = Quaternion::from_angle_vector(&v.cross(&w)).rotation_matrix();
    let rhs = (w * v.transpose() - v * w.transpose()).exp();
    assert_mat(&lhs, &rhs, 1e-14);
}

/// (2.15.2), (2.15.8–10): η = ½√(1 + tr𝓡), ε = vee(𝓡 − 𝓡ᵀ)/(4η), which Shepperd/Markley
/// reproduces away from π; Fact 2.15.1/2.15.4: a² + b² + c² + d² = 1.
#[test]
fn eq_2_15_2_euler_parameters_from_matrix() {
    let a = Frame::new();
    let m = rot(&a, [1.0, 2.0, 3.0], 1.0).rotation_matrix_in(&a);
    let eta = 0.5 * (1.0 + m.trace()).sqrt();
    let eps = Vector3::new(m[(2, 1)] - m[(1, 2)], m[(0, 2)] - m[(2, 0)], m[(1, 0)] - m[(0, 1)]) / (4.0 * eta);
    let q = Quaternion::from_rotation_matrix(&m, ROTATION_TOL).unwrap();
    assert!(q_err(&q, &Quaternion::from_parts(eta, eps)) <= 8.0 * EPS);
    assert_abs(q.norm_squared(), 1.0, 4.0 * EPS);
    assert!(q.eta() >= 0.0);
}

/// Fact 2.15.2: at θ = π, 𝓡 = 2εεᵀ − I.
#[test]
fn fact_2_15_2_half_turn_parameters() {
    let eps = unit([2.0, -1.0, 2.0]);
    let q = Quaternion::from_parts(0.0, eps);
    assert_mat(&q.rotation_matrix(), &(eps * eps.transpose() * 2.0 - Matrix3::identity()), 4.0 * EPS);
    // Canonical: first nonzero component positive.
    assert_vec(&(-q).canonical().epsilon(), &eps, 0.0);
}

/// Fact 2.15.3 (2.15.14), **corrected** (2.15.13): the (1,1) entry is 2a² + 2b² − 1 (printed
/// 2d² + 2b² − 1).
#[test]
fn fact_2_15_3_rotation_matrix_of_parameters_corrected() {
    let q = Quaternion::new(0.5, 0.1, -0.7, 0.3).normalize().unwrap();
    let (a, b, c, d) = (q.a, q.b, q.c, q.d);
    let want = Matrix3::new(
        a * a + b * b - c * c - d * d,
        2.0 * (b * c - a * d),
        2.0 * (a * c + b * d),
        2.0 * (a * d + b * c),
        a * a - b * b + c * c - d * d,
        2.0 * (c * d - a * b),
        2.0 * (b * d - a * c),
        2.0 * (a * b + c * d),
        a * a - b * b - c * c + d * d,
    );
    assert_mat(&q.rotation_matrix(), &want, 4.0 * EPS);
    assert_abs(q.rotation_matrix()[(0, 0)], 2.0 * a * a + 2.0 * b * b - 1.0, 4.0 * EPS);
    assert!((q.rotation_matrix()[(0, 0)] - (2.0 * d * d + 2.0 * b * b - 1.0)).abs() > 0.1);
}

/// Facts 2.15.5–6: 𝓡 = I + 2ηε^× + 2ε^{×2}, 𝓞 = I − 2ηε^× + 2ε^{×2} = 𝓡(q̄).
#[test]
fn fact_2_15_5_matrix_forms() {
    let q = Quaternion::new(0.2, -0.5, 0.4, 0.7).normalize().unwrap();
    let x = q.epsilon().cross_matrix();
    let id = Matrix3::identity();
    assert_mat(&q.rotation_matrix(), &(id + x * (2.0 * q.eta()) + x * x * 2.0), 4.0 * EPS);
    assert_mat(&q.orientation_matrix(), &(id - x * (2.0 * q.eta()) + x * x * 2.0), 4.0 * EPS);
    assert_mat(&q.orientation_matrix(), &q.conjugate().rotation_matrix(), 0.0);
}

/// Fact 2.15.7, **corrected** (2.15.34): q_{C/A} = ±q_{B/A} ⊗ q_{C/B}. Oracle: F_B = R_{k_A}(90°)F_A,
/// F_C = R_{i_B}(90°)F_B gives q_{C/A} = [½, ½, ½, ½], g_{C/A} = [1, 1, 1]; the printed form gives
/// [½, ½, −½, ½].
#[test]
fn fact_2_15_7_composition_corrected() {
    let a = Frame::new();
    let b = rot(&a, [0.0, 0.0, 1.0], PI / 2.0).apply_frame(&a);
    let c = Rotation::from_axis_angle(&b.i(), PI / 2.0).unwrap().apply_frame(&b);
    let q_ba = Rotation::between(&b, &a).quaternion_in(&a);
    let q_cb = Rotation::between(&c, &b).quaternion_in(&b);
    let q_ca = compose_quaternion(&q_cb, &q_ba);
    assert!(q_err(&q_ca, &Quaternion::new(0.5, 0.5, 0.5, 0.5)) <= 4.0 * EPS);
    assert_mat(&c.orientation_rel(&a), &Matrix3::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0), 4.0 * EPS);
    // The printed (2.15.34), Q(q_{C/B}) q_{B/A}, is the other order:
    assert!(q_err(&(q_cb * q_ba), &Quaternion::new(0.5, 0.5, -0.5, 0.5)) <= 4.0 * EPS);
    let g = compose_gibbs(&q_cb.gibbs().unwrap(), &q_ba.gibbs().unwrap()).unwrap();
    assert_vec(&g, &Vector3::new(1.0, 1.0, 1.0), 8.0 * EPS);
    assert_rel(q_ca.axis_angle().angle(), 2.0 * PI / 3.0, 8.0 * EPS);
}

/// (2.16.1): Hamilton's table 𝐢² = 𝐣² = 𝐤² = −1, 𝐢𝐣 = 𝐤 = −𝐣𝐢, 𝐣𝐤 = 𝐢, 𝐤𝐢 = 𝐣.
#[test]
fn eq_2_16_1_hamilton_table() {
    let (one, i, j, k) = (
        Quaternion::identity(),
        Quaternion::new(0.0, 1.0, 0.0, 0.0),
        Quaternion::new(0.0, 0.0, 1.0, 0.0),
        Quaternion::new(0.0, 0.0, 0.0, 1.0),
    );
    for u in [i, j, k] {
        assert_eq!(u * u, -one);
    }
    assert_eq!(i * j, k);
    assert_eq!(j * i, -k);
    assert_eq!(j * k, i);
    assert_eq!(k * i, j);
}

/// (2.16.6–10): Q(𝐪)p = 𝐪𝐩, Q(𝐪₂𝐪₁) = Q(𝐪₂)Q(𝐪₁), det Q = |𝐪|⁴, |𝐪₂𝐪₁| = |𝐪₁||𝐪₂|, the product
/// formula (2.16.10), and **corrected** (2.16.8): conj(𝐪₂𝐪₁) = 𝐪̄₁𝐪̄₂.
#[test]
fn eq_2_16_6_quaternion_algebra() {
    let (q2, q1) = (Quaternion::new(0.5, -1.0, 2.0, 0.3), Quaternion::new(-0.7, 0.2, 0.1, 1.5));
    let p = q2 * q1;
    assert!((q2.left_matrix() * q1.to_vector4() - p.to_vector4()).nan_amax() <= 8.0 * EPS);
    assert!((q1.right_matrix() * q2.to_vector4() - p.to_vector4()).nan_amax() <= 8.0 * EPS);
    assert!((p.left_matrix() - q2.left_matrix() * q1.left_matrix()).nan_amax() <= 16.0 * EPS);
    // a 4 × 4 determinant by elimination: a few hundred ε relative at most
    assert_rel(q2.left_matrix().determinant(), q2.norm_squared().powi(2), 1e-13);
    assert_rel(p.norm(), q1.norm() * q2.norm(), 8.0 * EPS);
    assert_rel((q1 * q2).norm(), p.norm(), 8.0 * EPS);
    let (a2, v2, a1, v1) = (q2.eta(), q2.epsilon(), q1.eta(), q1.epsilon());
    let want = Quaternion::from_parts(a2 * a1 - v2.dot(&v1), v1 * a2 + v2 * a1 + v2.cross(&v1));
    assert!((p - want).norm() <= 8.0 * EPS);
    assert!((p.conjugate() - q1.conjugate() * q2.conjugate()).norm() <= 8.0 * EPS);
    assert!((p.conjugate() - q2.conjugate() * q1.conjugate()).norm() > 0.1);
    let inv = q1.inverse().unwrap();
    assert!((q1 * inv - Quaternion::identity()).norm() <= 8.0 * EPS);
    assert!(Quaternion::new(0.0, 0.0, 0.0, 0.0).inverse().is_none());
}

/// Prob 2.26.22: e^{𝐪/2} = cos(|𝐪|/2) + (sin(|𝐪|/2)/|𝐪|)𝐪 for a pure 𝐪, unit; so
/// q_{B/A} = exp(Θ_{B/A}/2); ln inverts exp.
#[test]
fn problem_2_26_22_exponential_of_pure_quaternion() {
    let th = Vector3::new(0.3f64, -1.2, 2.0);
    let n = th.norm();
    let e = Quaternion::pure(th * 0.5).exp();
    let want = Quaternion::from_parts((n / 2.0).cos(), th * ((n / 2.0).sin() / n));
    assert!((e - want).norm() <= 8.0 * EPS);
    assert_abs(e.norm(), 1.0, 4.0 * EPS);
    assert!(q_err(&e, &Quaternion::from_angle_vector(&th)) <= 8.0 * EPS);
    let back = e.ln().unwrap();
    assert!((back - Quaternion::pure(th * 0.5)).norm() <= 8.0 * EPS);
    let g = Quaternion::new(1.5, 0.2, -0.3, 0.4);
    assert!((g.ln().unwrap().exp() - g).norm() <= 16.0 * EPS);
}

/// Prob 2.26.23: 𝐲 = 𝐪𝐱𝐪⁻¹ is pure and y = 𝓡(q)x.
#[test]
fn problem_2_26_23_sandwich() {
    let q = Quaternion::new(0.3, 0.1, -0.9, 0.2).normalize().unwrap();
    let x = Vector3::new(1.0, -2.0, 0.5);
    let y = q * Quaternion::pure(x) * q.inverse().unwrap();
    assert_abs(y.eta(), 0.0, 8.0 * EPS);
    assert_vec(&y.epsilon(), &(q.rotation_matrix() * x), 8.0 * EPS);
    assert_vec(&q.rotate(&x), &y.epsilon(), 8.0 * EPS);
}

/// (2.17.5), **corrected** ("2g g^×" is 2ggᵀ): 𝓡 = [(1 − g·g)I + 2ggᵀ + 2g^×]/(1 + g·g);
/// F2.17.1 Cayley form (I − g^×)⁻¹(I + g^×); F2.17.2 g = vee(𝓡 − 𝓡ᵀ)/(1 + tr 𝓡) (2.17.10).
#[test]
fn eq_2_17_5_gibbs_rotation_matrix_corrected() {
    let g = Vector3::new(0.4, -0.2, 1.1);
    let gg = g.dot(&g);
    let id = Matrix3::identity();
    let r = (id * (1.0 - gg) + g * g.transpose() * 2.0 + g.cross_matrix() * 2.0) / (1.0 + gg);
    let q = Quaternion::from_gibbs(&g);
    assert_mat(&q.rotation_matrix(), &r, 8.0 * EPS);
    let cayley = (id - g.cross_matrix()).try_inverse().unwrap() * (id + g.cross_matrix());
    assert_mat(&cayley, &r, 8.0 * EPS);
    let vee = Vector3::new(r[(2, 1)] - r[(1, 2)], r[(0, 2)] - r[(2, 0)], r[(1, 0)] - r[(0, 1)]);
    assert_vec(&(vee / (1.0 + r.trace())), &g, 16.0 * EPS);
    assert_vec(&q.gibbs().unwrap(), &g, 8.0 * EPS);
}

/// F2.17.3 (2.17.11): g_{C/A} = (g_{C/B} + g_{B/A} − g_{C/B}×g_{B/A})/(1 − g_{C/B}·g_{B/A}), which fails
/// (None) exactly when θ_{C/A} = π; §2.18: the Gibbs vector is undefined at π.
#[test]
fn fact_2_17_3_gibbs_composition() {
    let (g_cb, g_ba) = (Vector3::new(0.3, -0.1, 0.2), Vector3::new(-0.5, 0.4, 0.1));
    let q = compose_quaternion(&Quaternion::from_gibbs(&g_cb), &Quaternion::from_gibbs(&g_ba));
    assert_vec(&compose_gibbs(&g_cb, &g_ba).unwrap(), &q.gibbs().unwrap(), 8.0 * EPS);
    // Two quarter turns about the same axis: g·g = 1, θ = π.
    assert_eq!(compose_gibbs(&Vector3::<f64>::x(), &Vector3::x()), None);
    // Exactly θ = π (cos(π/2) rounds to 6e-17 ≠ 0, so build η = 0 directly).
    let half = Quaternion::new(0.0, 1.0, 0.0, 0.0);
    assert_eq!(half.gibbs(), None);
    assert_eq!(half.try_gibbs(), Err(RotationError::GibbsAtHalfTurn { eta: 0.0 }));
}

/// §2.18 summary table: tr −1 ⇒ θ = π, ±n̂, no Gibbs; tr ∈ (−1, 3) unique; tr 3 ⇒ Θ = ε = g = 0.
#[test]
fn sec_2_18_summary_table() {
    let id = Quaternion::<f64>::identity();
    assert_eq!(id.angle_vector(), Vector3::zeros());
    assert_eq!(id.gibbs(), Some(Vector3::zeros()));
    assert_eq!(id.axis_angle(), AxisAngle::Identity);
    let half = Quaternion::from_rotation_matrix(&Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0)), 0.0)
        .unwrap();
    assert_eq!(half.axis_angle(), AxisAngle::HalfTurn(Vector3::x()));
    assert_eq!(half.angle_vector(), Vector3::new(PI, 0.0, 0.0));
    assert_eq!(half.gibbs(), None);
}

/// MRPs (not in the book): p = tan(θ/4)n̂ with |p| ≤ 1; the shadow −p/|p|² is the same rotation.
#[test]
fn mrp_and_shadow_set() {
    let q = Quaternion::from_axis_angle(&Vector3::new(1.0, 2.0, 2.0), 2.5).unwrap();
    let p = q.mrp();
    assert_vec(&p, &(unit([1.0, 2.0, 2.0]) * (2.5f64 / 4.0).tan()), 8.0 * EPS);
    let s = mrp_shadow(&p).unwrap();
    assert!(s.norm() > 1.0);
    assert!(q_err(&Quaternion::from_mrp(&s), &q) <= 8.0 * EPS);
    assert!(mrp_shadow(&Vector3::<f64>::zeros()).is_err());
    let half = Quaternion::from_axis_angle(&Vector3::z(), PI).unwrap();
    assert_abs(half.mrp().norm(), 1.0, 4.0 * EPS);
}

/// Bad input returns typed errors, never a panic or NaN (DESIGN §5).
#[test]
fn bad_input_returns_typed_errors() {
    let a = Frame::new();
    assert!(matches!(Rotation::from_axis_angle(&Vector::zero(), 1.0), Err(RotationError::Zero { .. })));
    assert!(matches!(
        Rotation::from_axis_angle(&a.vector([f64::NAN, 0.0, 1.0]), 1.0),
        Err(RotationError::NonFinite { .. })
    ));
    assert!(matches!(
        Rotation::exp(&a.vector([f64::INFINITY, 0.0, 1.0])),
        Err(RotationError::NonFinite { .. })
    ));
    let skew = Matrix3::new(1.0, 0.1, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0);
    assert!(matches!(
        Rotation::from_rotation_matrix_in(&a, &skew, ROTATION_TOL),
        Err(RotationError::NotOrthonormal { .. })
    ));
    let refl = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
    assert!(matches!(
        Quaternion::from_rotation_matrix(&refl, ROTATION_TOL),
        Err(RotationError::Reflection { .. })
    ));
    let nan = Matrix3::from_element(f64::NAN);
    assert!(matches!(
        Quaternion::from_rotation_matrix(&nan, ROTATION_TOL),
        Err(RotationError::NonFinite { .. })
    ));
    assert!(matches!(nearest_rotation(&nan), Err(RotationError::NonFinite { .. })));
    assert!(matches!(nearest_rotation(&Matrix3::<f64>::zeros()), Err(RotationError::Zero { .. })));
    assert!(matches!(Quaternion::from_axis_angle(&Vector3::zeros(), 1.0), Err(RotationError::Zero { .. })));
    let q = Quaternion::new(2.0, 0.0, 0.0, 0.0);
    assert!(matches!(Rotation::from_quaternion_in(&a, &q, 1e-12), Err(RotationError::NotUnit { .. })));
    // Messages say what would be valid.
    let msg = Rotation::from_rotation_matrix_in(&a, &skew, ROTATION_TOL).unwrap_err().to_string();
    assert!(msg.contains("nearest_rotation"), "{msg}");
}

/// Generic scalar (DESIGN §1.4): dual numbers flow through exp/log and the Euler extraction, so
/// dθ/dθ = 1 through q(θ) ↦ angle vector, and d/dψ of the extracted yaw is 1.
#[test]
fn dual_numbers_flow_through_conversions() {
    use vectrix::num_dual::Dual64;
    let th = Dual64::from(0.7).derivative();
    let n = Vector3::new(Dual64::from(1.0), Dual64::from(2.0), Dual64::from(2.0));
    let q = Quaternion::from_axis_angle(&n, th).unwrap();
    let v = q.angle_vector();
    assert_abs(v.norm().eps, 1.0, 8.0 * EPS);
    let psi = Dual64::from(0.4).derivative();
    let e = EulerAngles::new(EulerSequence::S321, [psi, Dual64::from(-0.3), Dual64::from(1.2)]);
    let back = EulerAngles::from_rotation_matrix_unchecked(
        &e.rotation_matrix(),
        EulerSequence::S321,
        GIMBAL_LOCK_TOL,
    );
    let p = back.principal();
    assert_abs(p.angles[0].re(), 0.4, 8.0 * EPS);
    assert_abs(p.angles[0].eps, 1.0, 8.0 * EPS);
    assert_abs(p.angles[1].eps, 0.0, 8.0 * EPS);
}
