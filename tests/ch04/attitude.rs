//! §4.7–4.12: attitude rate equations for every representation, body and spatial forms with
//! inverses, against Poisson's equation on exact (num-dual) derivatives of 𝓡_{B/A}(t).

use std::f64::consts::PI;

use vectrix::kinematics::attitude::*;
use vectrix::kinematics::{KinematicsError, omega_spatial_from_rotation_rate};
use vectrix::nalgebra::{Matrix3, Vector3, Vector4};
use vectrix::num_dual::Dual2_64;
use vectrix::rotation::{EulerAngles, EulerSequence, Quaternion};
use vectrix::tensor::Scalar;

use crate::paths::*;
use crate::support::{EPS, NanAmax};

const TOL: f64 = 512.0 * EPS;
const T0: f64 = 0.4;

/// ω|_B and ω|_A of a rotation-matrix path 𝓡_{B/A}(t) by Poisson (4.3.20).
fn omegas(r: impl Fn(Dual2_64) -> Matrix3<Dual2_64>, t: f64) -> (Vector3<f64>, Vector3<f64>) {
    let [r0, rd, _] = mat_jet(r, t);
    let w_a = omega_spatial_from_rotation_rate(&r0, &rd).unwrap();
    (r0.transpose() * w_a, w_a)
}

fn angles_jet(t: f64) -> ([f64; 3], [f64; 3]) {
    let d = |k: usize| angle(Dual2_64::new(t, 1.0, 0.0), C1[k]);
    ([d(0).re, d(1).re, d(2).re], [d(0).v1, d(1).v1, d(2).v1])
}

fn dual_angles(t: Dual2_64) -> [Dual2_64; 3] {
    [angle(t, C1[0]), angle(t, C1[1]), angle(t, C1[2])]
}

// (4.10.7–9), (4.10.11): the 3-2-1 rate matrix S(Φ, Θ) and its inverse, as printed (columns in
// the book's order (Φ̇, Θ̇, Ψ̇), ours in the order applied (Ψ̇, Θ̇, Φ̇)); det S = cos Θ.
#[test]
fn eq_4_10_9_euler_321_rate_matrix() {
    let (psi, th, ph): (f64, f64, f64) = (0.3, -0.7, 1.2);
    let ea = EulerAngles::new(EulerSequence::S321, [psi, th, ph]);
    let s = euler_rate_matrix_body(&ea);
    let (sf, cf, st, ct) = (ph.sin(), ph.cos(), th.sin(), th.cos());
    let book = Matrix3::new(1.0, 0.0, -st, 0.0, cf, sf * ct, 0.0, -sf, cf * ct);
    let reversed = Matrix3::from_columns(&[book.column(2), book.column(1), book.column(0)]);
    assert!((s - reversed).nan_amax() < TOL);
    assert!((s.determinant().abs() - ct.abs()).abs() < TOL);
    let w = Vector3::new(0.4, -1.1, 0.25);
    let rates = euler_rates_from_omega_body(&ea, &w, 1e-12).unwrap();
    let book_inv = Matrix3::new(1.0, sf * st / ct, cf * st / ct, 0.0, cf, -sf, 0.0, sf / ct, cf / ct);
    let want = book_inv * w; // (Φ̇, Θ̇, Ψ̇)
    assert!((Vector3::from(rates) - Vector3::new(want.z, want.y, want.x)).nan_amax() < TOL);
}

// (4.10.14), (4.10.18): 3-1-3 with the book's [Ψ, Θ, Φ] = (spin, nutation, precession):
// S(Ψ,Θ) = [[0, cΨ, sΨsΘ], [0, −sΨ, cΨsΘ], [1, 0, cΘ]], det = sin Θ ((4.10.16–17) should read
// S(Ψ,Θ)); ours takes (Φ̇, Θ̇, Ψ̇) in the order applied.
#[test]
fn eq_4_10_14_euler_313_rate_matrix() {
    let (phi, th, psi): (f64, f64, f64) = (0.5, 1.1, -0.8);
    let ea = EulerAngles::new(EulerSequence::S313, [phi, th, psi]);
    let (sp, cp, st, ct) = (psi.sin(), psi.cos(), th.sin(), th.cos());
    let book = Matrix3::new(0.0, cp, sp * st, 0.0, -sp, cp * st, 1.0, 0.0, ct);
    let reversed = Matrix3::from_columns(&[book.column(2), book.column(1), book.column(0)]);
    assert!((euler_rate_matrix_body(&ea) - reversed).nan_amax() < TOL);
    assert!((book.determinant().abs() - st.abs()).abs() < TOL);
    let book_inv = Matrix3::new(-sp * ct / st, -cp * ct / st, 1.0, cp, -sp, 0.0, sp / st, cp / st, 0.0);
    assert!((book_inv * book - Matrix3::identity()).nan_amax() < TOL, "(4.10.18)");
}

// §4.10 for all 12 sequences, intrinsic and extrinsic: ω|_D = S θ̇ and ω|_A against Poisson on
// 𝓡(t), and the inverses S⁻¹ round-trip.
#[test]
fn eq_4_10_7_all_twelve_sequences_body_and_spatial() {
    let (ang, rates) = angles_jet(T0);
    for seq in EulerSequence::ALL.into_iter().flat_map(|s| [s, s.extrinsic()]) {
        let (w_b, w_a) = omegas(|t| EulerAngles::new(seq, dual_angles(t)).rotation_matrix(), T0);
        let ea = EulerAngles::new(seq, ang);
        assert!((omega_body_from_euler_rates(&ea, rates) - w_b).nan_amax() < TOL, "{seq:?} body");
        assert!((omega_spatial_from_euler_rates(&ea, rates) - w_a).nan_amax() < TOL, "{seq:?} spatial");
        let back_b = euler_rates_from_omega_body(&ea, &w_b, 1e-12).unwrap();
        let back_a = euler_rates_from_omega_spatial(&ea, &w_a, 1e-12).unwrap();
        assert!((Vector3::from(back_b) - Vector3::from(rates)).nan_amax() < 16.0 * TOL, "{seq:?}");
        assert!((Vector3::from(back_a) - Vector3::from(rates)).nan_amax() < 16.0 * TOL, "{seq:?}");
    }
}

// P4.20.7 (gimbal lock), 3-2-1 angles Ψ, Θ, Φ from F_A to F_D.
// i) Not every ω⃗_{D/A} is attained by (Ψ̇, Θ̇, Φ̇) iff Θ = ±π/2: the body rate matrix S of
//    (4.10.7–9) has |det S| = |cos Θ|, so vectrix's S loses rank exactly there. Checked on a grid
//    of Θ: |det S| = |cos Θ|, `euler_rates_from_omega_body` inverts S (round trip through
//    `omega_body_from_euler_rates`) away from the lock and returns `GimbalLock` at it.
// ii) At Θ = ±π/2, ω⃗_{D/A} = ωk̂_D is attainable iff Φ = ±π/2. Decided from vectrix's S alone:
//    the least-squares residual of S(Ψ̇, Θ̇, Φ̇)ᵀ = ωe₃, the distance from ωe₃ to the range of S,
//    is |ωu₃·e₃| for u₃ the left singular vector of S's zero singular value. The range is
//    span{e₁, (0, cos Φ, −sin Φ)} (notes ch4-5 §2), so that distance is |ω cos Φ|: zero iff
//    Φ = ±π/2, where the rates (0, −ω/sin Φ, 0) attain ωk̂_D.
#[test]
fn problem_4_20_7_gimbal_lock() {
    let w = 1.7; // ω ≠ 0
    let omega = Vector3::new(0.3, -1.1, 0.8);
    // i) |det S| = |cos Θ|; S is inverted away from Θ = ±π/2 and refused at it
    for theta in [-PI / 2.0, -1.2, -1e-3, 0.0, 0.7, PI / 2.0 - 1e-6, PI / 2.0] {
        let ea = EulerAngles::new(EulerSequence::S321, [0.2, theta, -0.9]);
        let s = euler_rate_matrix_body(&ea);
        assert!((s.determinant().abs() - theta.cos().abs()).abs() <= 4.0 * EPS, "Θ = {theta}");
        match euler_rates_from_omega_body(&ea, &omega, 1e-12) {
            Ok(rates) => {
                assert!(theta.cos().abs() > 1e-12, "Θ = {theta} should lock");
                // S⁻¹ amplifies by 1/|cos Θ| (10⁶ at the Θ nearest the lock)
                let back = omega_body_from_euler_rates(&ea, rates);
                assert!((back - omega).nan_amax() <= 16.0 * EPS / theta.cos().abs(), "Θ = {theta}");
            }
            Err(KinematicsError::GimbalLock { det, condition, .. }) => {
                assert!(theta.cos().abs() <= 1e-12, "Θ = {theta} is not a lock");
                assert!(det.abs() <= 1e-15 && condition > 1e15);
            }
            Err(e) => panic!("Θ = {theta}: {e}"),
        }
    }
    // ii) at the lock: the distance from ωe₃ to the range of S is |ω cos Φ|
    for theta in [PI / 2.0, -PI / 2.0] {
        for phi in [-PI / 2.0, -1.2, -0.3, 0.0, 0.3, PI / 2.0, 2.0, PI] {
            let ea = EulerAngles::new(EulerSequence::S321, [0.2, theta, phi]);
            let svd = euler_rate_matrix_body(&ea).svd(true, false);
            let k = svd.singular_values.imin();
            // σ = (√2, 1, |cos Θ| ≈ 6e-17): the null direction is separated by a gap of 1
            assert!(svd.singular_values[k] <= 4.0 * EPS);
            let u3 = svd.u.unwrap().column(k).into_owned();
            let residual = (w * u3.dot(&Vector3::z())).abs();
            assert!((residual - (w * phi.cos()).abs()).abs() <= 8.0 * EPS * w, "Θ = {theta}, Φ = {phi}");
            let attainable = residual <= 8.0 * EPS * w;
            assert_eq!(attainable, (phi.abs() - PI / 2.0).abs() < 1e-12, "Θ = {theta}, Φ = {phi}");
            if attainable {
                let got = omega_body_from_euler_rates(&ea, [0.0, -w / phi.sin(), 0.0]);
                assert!((got - Vector3::z() * w).nan_amax() <= 4.0 * EPS * w, "Θ = {theta}, Φ = {phi}");
            }
        }
    }
}

/// exp(Θ^×) by Rodrigues, generic (for dual paths).
fn exp_so3<T: Scalar>(th: Vector3<T>) -> Matrix3<T> {
    let t = th.norm();
    let x = th.cross_matrix();
    Matrix3::identity() + x * (t.sin() / t) + x * x * ((T::one() - t.cos()) / (t * t))
}

fn theta_path<T: Scalar>(t: T) -> Vector3<T> {
    vec_path(t, &C2) * T::lit(0.4)
}

// F4.9.2, (4.9.10–11): ω|_A = J_lΘ̇, ω|_B = J_rΘ̇; (4.9.16–17) the inverses; (4.9.8) the
// alternative form of J_l.
#[test]
fn eq_4_9_10_angle_vector_jacobians() {
    let (w_b, w_a) = omegas(|t| exp_so3(theta_path(t)), T0);
    let [th, thd, _] = vec_jet(theta_path, T0);
    assert!((jacobian_left(&th) * thd - w_a).nan_amax() < TOL);
    assert!((jacobian_right(&th) * thd - w_b).nan_amax() < TOL);
    assert!((angle_vector_rate_spatial(&th, &w_a).unwrap() - thd).nan_amax() < TOL);
    assert!((angle_vector_rate_body(&th, &w_b).unwrap() - thd).nan_amax() < TOL);
    let t = th.norm();
    let r = exp_so3(th);
    let alt = (th * th.transpose() + (Matrix3::identity() - r) * th.cross_matrix()) / (t * t);
    assert!((alt - jacobian_left(&th)).nan_amax() < TOL, "(4.9.8)");
    // Θ ∥ Θ̇ ⇒ ω = Θ̇
    assert!((jacobian_left(&th) * (th * 0.3) - th * 0.3).nan_amax() < TOL);
}

// (4.9.18–20) and notes §3: series near θ = 0 (limits ½, 1/6, 1/12), continuity across the
// series threshold, J J⁻¹ = I over the hard set up to θ = π, rewrap to |Θ| ≤ π, and J⁻¹ singular
// at |Θ| = 2π.
#[test]
fn eq_4_9_18_angle_vector_series_and_rewrap() {
    let dir = Vector3::new(1.0, -2.0, 0.5).normalize();
    for th in [0.0, 1e-300, 1e-16, 1e-8, 1e-3, 1e-2 * (1.0 - 1e-12), 1e-2 * (1.0 + 1e-12), 1.0, PI - 1e-8, PI]
    {
        let v = dir * th;
        let prod = jacobian_left(&v) * jacobian_left_inverse(&v).unwrap();
        assert!((prod - Matrix3::identity()).nan_amax() < 8.0 * EPS, "θ = {th}");
        let prod = jacobian_right(&v) * jacobian_right_inverse(&v).unwrap();
        assert!((prod - Matrix3::identity()).nan_amax() < 8.0 * EPS, "θ = {th}");
    }
    // continuity across the series switch at 10⁻²: the closed forms lose ε/θ² in b and c
    // (cancellation in θ − sin θ and 2 − θcot(θ/2)), which Θ^{×2} ~ θ² scales back to O(ε)
    let (lo, hi) = (dir * 1e-2f64.next_down(), dir * 1e-2f64.next_up());
    assert!((jacobian_left(&lo) - jacobian_left(&hi)).nan_amax() < 16.0 * EPS);
    assert!(
        (jacobian_left_inverse(&lo).unwrap() - jacobian_left_inverse(&hi).unwrap()).nan_amax() < 16.0 * EPS
    );
    assert_eq!(jacobian_left(&Vector3::<f64>::zeros()), Matrix3::identity());
    // rewrap: same rotation, |Θ| ≤ π
    let big = dir * (1.5 * PI);
    let w = rewrap_angle_vector(&big);
    assert!((w.norm() - 0.5 * PI).abs() < TOL && (exp_so3(w) - exp_so3(big)).nan_amax() < TOL);
    assert_eq!(rewrap_angle_vector(&(dir * PI)), dir * PI);
    assert!(matches!(
        jacobian_left_inverse(&(dir * (2.0 * PI))),
        Err(KinematicsError::SingularRateMap { .. })
    ));
    assert!(matches!(
        angle_vector_rate_body(&Vector3::new(f64::NAN, 0.0, 0.0), &dir),
        Err(KinematicsError::NonFinite { .. })
    ));
}

fn q_path(t: Dual2_64) -> Quaternion<Dual2_64> {
    EulerAngles::new(EulerSequence::S321, dual_angles(t)).quaternion()
}

fn q_jet(t: f64) -> (Quaternion, Vector4<f64>) {
    let q = q_path(Dual2_64::new(t, 1.0, 0.0));
    (Quaternion::new(q.a.re, q.b.re, q.c.re, q.d.re), Vector4::new(q.a.v1, q.b.v1, q.c.v1, q.d.v1))
}

// F4.11.2–3, (4.11.12–15): q̇ = ½E(q)ω_B = Q(ω_B)q, the spatial form, the inverses and the norm
// constraint ηη̇ + ε·ε̇ = 0.
#[test]
fn eq_4_11_13_euler_parameter_rates() {
    let (w_b, w_a) = omegas(|t| q_path(t).rotation_matrix(), T0);
    let (q, qd) = q_jet(T0);
    assert!((quaternion_rate_body(&q, &w_b).unwrap() - qd).nan_amax() < TOL);
    assert!((quaternion_rate_spatial(&q, &w_a).unwrap() - qd).nan_amax() < TOL);
    assert!((quaternion_rate_matrix(&w_b) * q.to_vector4() - qd).nan_amax() < TOL, "(4.11.15)");
    assert!((omega_body_from_quaternion_rate(&q, &qd).unwrap() - w_b).nan_amax() < TOL, "(4.11.12)");
    assert!((omega_spatial_from_quaternion_rate(&q, &qd).unwrap() - w_a).nan_amax() < TOL);
    assert!(q.to_vector4().dot(&qd).abs() < TOL, "norm constraint");
}

// (4.11.17): for constant ω, e^{Qt} = cos(½|ω|t)I₄ + (2 sin(½|ω|t)/|ω|)Q, because
// Q² = −¼|ω|²I₄; it agrees with a long series of e^{Qt}.
#[test]
fn eq_4_11_17_exact_solution_for_constant_omega() {
    use vectrix::nalgebra::Matrix4;
    let w = Vector3::new(0.7, -1.2, 0.4);
    let big_q: Matrix4<f64> = quaternion_rate_matrix(&w);
    assert!((big_q * big_q + Matrix4::identity() * (0.25 * w.norm_squared())).nan_amax() < TOL);
    let t = 0.9;
    let closed = Matrix4::identity() * (0.5 * w.norm() * t).cos()
        + big_q * (2.0 * (0.5 * w.norm() * t).sin() / w.norm());
    let (mut term, mut series) = (Matrix4::identity(), Matrix4::identity());
    for k in 1..30 {
        term = term * big_q * (t / k as f64);
        series += term;
    }
    assert!((closed - series).nan_amax() < TOL);
}

fn g_path(t: Dual2_64) -> Vector3<Dual2_64> {
    q_path(t).gibbs().unwrap()
}

fn mrp_path(t: Dual2_64) -> Vector3<Dual2_64> {
    q_path(t).mrp()
}

// (4.12.4–5): Gibbs rates, body form (the OCR's left side ω^{B•} is ġ), the derived spatial
// form, and both inverses.
#[test]
fn eq_4_12_4_gibbs_rates() {
    let (w_b, w_a) = omegas(|t| q_path(t).rotation_matrix(), T0);
    let [g, gd, _] = vec_jet(g_path, T0);
    assert!((gibbs_rate_body(&g, &w_b).unwrap() - gd).nan_amax() < TOL);
    assert!((gibbs_rate_spatial(&g, &w_a).unwrap() - gd).nan_amax() < TOL);
    assert!((omega_body_from_gibbs_rate(&g, &gd).unwrap() - w_b).nan_amax() < TOL);
    assert!((omega_spatial_from_gibbs_rate(&g, &gd).unwrap() - w_a).nan_amax() < TOL);
}

// MRP rates (not in the book; extends §4.12), body and spatial with inverses.
#[test]
fn mrp_rates_body_and_spatial() {
    let (w_b, w_a) = omegas(|t| q_path(t).rotation_matrix(), T0);
    let [p, pd, _] = vec_jet(mrp_path, T0);
    assert!((mrp_rate_body(&p, &w_b).unwrap() - pd).nan_amax() < TOL);
    assert!((mrp_rate_spatial(&p, &w_a).unwrap() - pd).nan_amax() < TOL);
    assert!((omega_body_from_mrp_rate(&p, &pd).unwrap() - w_b).nan_amax() < TOL);
    assert!((omega_spatial_from_mrp_rate(&p, &pd).unwrap() - w_a).nan_amax() < TOL);
}

// F4.7.2, (4.7.18–31): eigenaxis rates, |ω|² = θ̇² + 2(1 − cos θ)|ṅ|² (4.7.20), θ̇ = n̂·ω
// (4.7.22), ṅ·ω = sin θ|ṅ|² (4.7.23), the inverses for θ ≠ 0, and the small-angle form (4.7.36)
// with ½θ² (the book prints ½θ̇², a typo).
#[test]
fn eq_4_7_18_eigenaxis_rates() {
    let (w_b, w_a) = omegas(|t| exp_so3(theta_path(t)), T0);
    let [th, thd, _] = vec_jet(theta_path, T0);
    let theta = th.norm();
    let n = th / theta;
    let theta_dot = n.dot(&thd);
    let n_dot = (thd - n * theta_dot) / theta;
    let wa = omega_spatial_from_eigenaxis_rates(theta, theta_dot, &n, &n_dot);
    assert!((wa - w_a).nan_amax() < TOL);
    assert!((omega_body_from_eigenaxis_rates(theta, theta_dot, &n, &n_dot) - w_b).nan_amax() < TOL);
    let lhs = w_a.norm_squared();
    assert!((lhs - theta_dot * theta_dot - 2.0 * (1.0 - theta.cos()) * n_dot.norm_squared()).abs() < TOL);
    assert!((n_dot.dot(&w_a) - theta.sin() * n_dot.norm_squared()).abs() < TOL, "(4.7.23)");
    let (td, nd) = eigenaxis_rates_from_omega_spatial(theta, &n, &w_a).unwrap();
    assert!((td - theta_dot).abs() < TOL && (nd - n_dot).nan_amax() < TOL, "(4.7.29)");
    let (td, nd) = eigenaxis_rates_from_omega_body(theta, &n, &w_b).unwrap();
    assert!((td - theta_dot).abs() < TOL && (nd - n_dot).nan_amax() < TOL, "(4.7.31)");
    assert!(matches!(
        eigenaxis_rates_from_omega_spatial(0.0, &n, &w_a),
        Err(KinematicsError::SingularRateMap { .. })
    ));
    // (4.7.36): ω ≈ θ̇n + ½θ²n×ṅ + θṅ, error O(θ³)
    let small = 1e-3;
    let approx = n * theta_dot + n.cross(&n_dot) * (0.5 * small * small) + n_dot * small;
    let exact = omega_spatial_from_eigenaxis_rates(small, theta_dot, &n, &n_dot);
    assert!((approx - exact).nan_amax() < small.powi(3));
    let typo = n * theta_dot + n.cross(&n_dot) * (0.5 * theta_dot * theta_dot) + n_dot * small;
    assert!((typo - exact).nan_amax() > small.powi(2));
}

// (4.8.1), F4.8.1 (i): α|_A = θ̈n̂ + θ̇[(1 + cos θ)ṅ + sin θ n̂×ṅ] + (1 − cos θ)n̂×n̈ + sin θ n̈,
// against the second derivative of 𝓡(t) = exp(Θ(t)^×); at θ = 0 it reduces to θ̈n̂ + 2θ̇ṅ.
#[test]
fn eq_4_8_1_eigenaxis_angular_acceleration() {
    use vectrix::kinematics::alpha_body_from_orientation_rates;
    let [r0, _, rdd] = mat_jet(|t| exp_so3(theta_path(t)), T0);
    let al_a = r0 * alpha_body_from_orientation_rates(&r0.transpose(), &rdd.transpose()).unwrap();
    // θ(t) = |Θ(t)| and n̂(t) = Θ/|Θ| with exact derivatives
    let th = |t: Dual2_64| theta_path(t).norm();
    let n = |t: Dual2_64| theta_path(t) / theta_path(t).norm();
    let d = th(Dual2_64::new(T0, 1.0, 0.0));
    let [n0, nd, ndd] = vec_jet(n, T0);
    let got = alpha_spatial_from_eigenaxis_rates([d.re, d.v1, d.v2], &n0, &nd, &ndd);
    assert!((got - al_a).nan_amax() < 4.0 * TOL, "{got} vs {al_a}");
    let at_zero = alpha_spatial_from_eigenaxis_rates([0.0, d.v1, d.v2], &n0, &nd, &ndd);
    assert!((at_zero - (n0 * d.v2 + nd * (2.0 * d.v1))).nan_amax() < TOL, "F4.8.1 (i)");
}

// F4.8.2: for constant ω_{B/A|B}, 𝓡(t) = 𝓡(0)e^{ω^×t}. Every propagator converges to it; the
// exact step and the Lie-group methods reproduce it to rounding; RK4 on the rate equations is
// fourth order (halving h divides the error by ≈ 16).
#[test]
fn fact_4_8_2_propagation_against_the_exact_solution() {
    use vectrix::ode::LieMethod;
    let r0 = EulerAngles::new(EulerSequence::S321, [0.3, -0.4, 0.8]).rotation_matrix();
    let w = Vector3::new(0.5, -0.3, 0.9);
    let (t1, n) = (2.0, 400);
    let exact = r0 * exp_so3(w * t1);
    // RK4 with h = 5·10⁻³: error ~ h⁴·|ω|⁵·(representation-dependent constant) ≲ 10⁻⁸
    let methods = [
        (Propagator::EulerRk4 { sequence: EulerSequence::S321, tol: 1e-12 }, 1e-8),
        (Propagator::EulerRk4 { sequence: EulerSequence::S313, tol: 1e-12 }, 1e-8),
        (Propagator::AngleVectorRk4, 1e-8),
        (Propagator::QuaternionRk4 { renormalize: false }, 1e-8),
        (Propagator::QuaternionRk4 { renormalize: true }, 1e-8),
        (Propagator::GibbsRk4, 1e-8),
        (Propagator::MrpRk4, 1e-8),
        (Propagator::PoissonRk4 { renormalize: false }, 1e-8),
        (Propagator::PoissonRk4 { renormalize: true }, 1e-8),
        (Propagator::QuaternionExact, 1e-13),
        (Propagator::RotorLie(LieMethod::ExponentialEuler), 1e-13),
        (Propagator::RotorLie(LieMethod::Rkmk4), 1e-13),
        (Propagator::MatrixLie(LieMethod::CrouchGrossman3), 1e-13),
    ];
    for (m, tol) in methods {
        let r = propagate_attitude(m, &r0, |_| w, 0.0, t1, n).unwrap();
        assert!((r - exact).nan_amax() < tol, "{m:?}: {:e}", (r - exact).nan_amax());
    }
    let err = |n| {
        (propagate_attitude(Propagator::QuaternionRk4 { renormalize: false }, &r0, |_| w, 0.0, 20.0, n)
            .unwrap()
            - r0 * exp_so3(w * 20.0))
        .nan_amax()
    };
    let ratio = err(100) / err(200);
    assert!((12.0..20.0).contains(&ratio), "RK4 order: ratio {ratio}");
    // a gimbal-locked start is an error for Euler angles, bad input for all
    let locked = EulerAngles::new(EulerSequence::S321, [0.1, PI / 2.0, 0.2]).rotation_matrix();
    let res = propagate_attitude(
        Propagator::EulerRk4 { sequence: EulerSequence::S321, tol: 1e-12 },
        &locked,
        |_| w,
        0.0,
        1.0,
        10,
    );
    assert!(matches!(res, Err(KinematicsError::GimbalLock { .. })));
    assert!(matches!(
        propagate_attitude(Propagator::AngleVectorRk4, &r0, |_| w, 0.0, 1.0, 0),
        Err(KinematicsError::OutOfRange { .. })
    ));
    assert!(propagate_attitude(Propagator::AngleVectorRk4, &(r0 * 2.0), |_| w, 0.0, 1.0, 10).is_err());
    // Gibbs through θ = π (§4.12: g undefined there) is a typed error, not garbage
    let through_pi =
        propagate_attitude(Propagator::GibbsRk4, &Matrix3::identity(), |_| Vector3::z(), 0.0, 4.0, 4000);
    assert!(matches!(through_pi, Err(KinematicsError::SingularRateMap { .. })));
    // MRPs with the shadow switch and the angle vector with rewrap go through θ = π
    for m in [Propagator::MrpRk4, Propagator::AngleVectorRk4] {
        let r = propagate_attitude(m, &Matrix3::identity(), |_| Vector3::z(), 0.0, 4.0, 4000).unwrap();
        assert!((r - exp_so3(Vector3::z() * 4.0)).nan_amax() < 1e-10, "{m:?}");
    }
}

mod prop {
    use super::*;
    use crate::support::{angle, direction, triple};
    use proptest::prelude::*;

    fn unit(v: [f64; 3]) -> Vector3<f64> {
        Vector3::from(v).normalize()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        // rate ↔ ω round trips, every representation, body and spatial, biased to hard angles.
        #[test]
        fn rate_omega_round_trips(axis in direction(), th in angle(), w in triple(), seq in 0usize..12, e in [angle(), angle(), angle()]) {
            let n = unit(axis);
            let big_theta = n * th.abs();
            let wv = Vector3::from(w);
            let scale = 1.0 + wv.norm();
            // angle vector (|Θ| ≤ π)
            let thd = angle_vector_rate_body(&big_theta, &wv).unwrap();
            prop_assert!((jacobian_right(&big_theta) * thd - wv).nan_amax() < 64.0 * EPS * scale * 10.0);
            let thd = angle_vector_rate_spatial(&big_theta, &wv).unwrap();
            prop_assert!((jacobian_left(&big_theta) * thd - wv).nan_amax() < 64.0 * EPS * scale * 10.0);
            // quaternion
            let q = Quaternion::from_angle_vector(&big_theta);
            let qd = quaternion_rate_body(&q, &wv).unwrap();
            prop_assert!((omega_body_from_quaternion_rate(&q, &qd).unwrap() - wv).nan_amax() < 16.0 * EPS * scale);
            let qd = quaternion_rate_spatial(&q, &wv).unwrap();
            prop_assert!((omega_spatial_from_quaternion_rate(&q, &qd).unwrap() - wv).nan_amax() < 16.0 * EPS * scale);
            // MRP (|p| ≤ 1 always)
            let p = q.mrp();
            let pd = mrp_rate_body(&p, &wv).unwrap();
            prop_assert!((omega_body_from_mrp_rate(&p, &pd).unwrap() - wv).nan_amax() < 64.0 * EPS * scale);
            let pd = mrp_rate_spatial(&p, &wv).unwrap();
            prop_assert!((omega_spatial_from_mrp_rate(&p, &pd).unwrap() - wv).nan_amax() < 64.0 * EPS * scale);
            // Gibbs away from θ = π (|g| ≤ 10⁴)
            if let Some(g) = q.gibbs().filter(|g| g.norm() < 1e4) {
                let gs = 1.0 + g.norm_squared();
                let gd = gibbs_rate_body(&g, &wv).unwrap();
                prop_assert!((omega_body_from_gibbs_rate(&g, &gd).unwrap() - wv).nan_amax() < 64.0 * EPS * scale * gs);
                let gd = gibbs_rate_spatial(&g, &wv).unwrap();
                prop_assert!((omega_spatial_from_gibbs_rate(&g, &gd).unwrap() - wv).nan_amax() < 64.0 * EPS * scale * gs);
            }
            // eigenaxis for θ not tiny (cot(θ/2) ~ 2/θ amplifies rounding)
            if th.abs() > 1e-3 {
                let (td, nd) = eigenaxis_rates_from_omega_spatial(th.abs(), &n, &wv).unwrap();
                let back = omega_spatial_from_eigenaxis_rates(th.abs(), td, &n, &nd);
                prop_assert!((back - wv).nan_amax() < 64.0 * EPS * scale / th.abs());
            }
            // Euler angles, any of the 12 sequences, away from lock
            let ea = EulerAngles::new(EulerSequence::ALL[seq], e);
            let s = euler_rate_matrix_body(&ea);
            if s.determinant().abs() > 1e-3 {
                let r = euler_rates_from_omega_body(&ea, &wv, 1e-12).unwrap();
                prop_assert!((omega_body_from_euler_rates(&ea, r) - wv).nan_amax() < 1e3 * EPS * scale / s.determinant().abs());
                let r = euler_rates_from_omega_spatial(&ea, &wv, 1e-12).unwrap();
                prop_assert!((omega_spatial_from_euler_rates(&ea, r) - wv).nan_amax() < 1e3 * EPS * scale / s.determinant().abs());
            }
        }
    }
}
