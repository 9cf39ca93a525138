//! Sections of chapter 9 that the worked examples leave untested: generalized coordinates and
//! constraints (§9.2), generalized forces from forces and from moments (§9.4–9.5), the
//! eigenaxis mass matrix (§9.3), the Euler-angle and Euler-parameter identities of §9.7 (with
//! the printed errata (9.7.8), (9.7.25), (9.7.27) corrected), and the Hamiltonian in momenta
//! (9.13.9) with its corrected sign.

use std::f64::consts::PI;

use proptest::prelude::*;
use vectrix::dynamics::lagrange::{accelerations, generalized_momentum, hamiltonian, mass_matrix};
use vectrix::kinematics::attitude::{jacobian_left, jacobian_right};
use vectrix::nalgebra::{DMatrix, Matrix3, Vector3};
use vectrix::num_dual::{Dual64, HyperDual64};
use vectrix::prelude::*;
use vectrix::rotation::{Axis, orientation_about};

use super::problems::assert_abs;
use crate::support::{EPS, NanAmax, nan_max};

/// x^× with x^× y = x × y.
fn cross<T: Scalar>(x: &Vector3<T>) -> Matrix3<T> {
    let z = T::zero();
    Matrix3::new(z, -x[2], x[1], x[2], z, -x[0], -x[1], x[0], z)
}

/// Rodrigues' formula for 𝓡 = exp(Θ^×) (2.11.1), written out for dual numbers (θ > 0).
fn rodrigues<T: Scalar>(th: &Vector3<T>) -> Matrix3<T> {
    let theta = th.norm();
    let x = cross(th);
    Matrix3::identity() + x * (theta.sin() / theta) + x * x * ((T::one() - theta.cos()) / (theta * theta))
}

// ---------------------------------------------------------------------------------------------
// §9.2: generalized coordinates.

/// A planar double pendulum of two particles as six coordinates x = (r1, r2) ∈ ℝ⁶ of (9.2.1),
/// x(q) for q = (θ1, θ2) from the downward vertical.
fn double_pendulum_x<T: Scalar>(q: &[T], l1: f64, l2: f64) -> [T; 6] {
    let (x1, y1) = (T::lit(l1) * q[0].sin(), -T::lit(l1) * q[0].cos());
    let (x2, y2) = (x1 + T::lit(l2) * (q[0] + q[1]).sin(), y1 - T::lit(l2) * (q[0] + q[1]).cos());
    [x1, y1, T::zero(), x2, y2, T::zero()]
}

/// The p = 4 holonomic constraints (9.2.6) of that pendulum: z1 = 0, z2 = 0, |r1| = l1,
/// |r2 − r1| = l2.
fn double_pendulum_phi<T: Scalar>(x: &[T; 6], l1: f64, l2: f64) -> [T; 4] {
    let d2 = (x[3] - x[0]) * (x[3] - x[0]) + (x[4] - x[1]) * (x[4] - x[1]) + (x[5] - x[2]) * (x[5] - x[2]);
    [x[2], x[5], x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - T::lit(l1 * l1), d2 - T::lit(l2 * l2)]
}

/// Numerical rank: singular values above 1e-10 of the largest.
fn rank(m: &DMatrix<f64>) -> usize {
    let sv = m.clone().svd(false, false).singular_values;
    let top = sv.iter().fold(0.0f64, |a, b| nan_max(a, *b));
    sv.iter().filter(|s| **s > 1e-10 * top).count()
}

/// §9.2 (9.2.6): "a body of l particles with p independent physical constraints possesses
/// r = 3l − p degrees of freedom", and the independent coordinates satisfy the constraints
/// automatically. The planar double pendulum: l = 2, p = 4, r = 2 — φ(x(q)) = 0, the
/// constraint Jacobian has rank p, ∂x/∂q has rank r and lies in its null space.
#[test]
fn section_9_2_holonomic_constraints_leave_3l_minus_p_coordinates() {
    let (l1, l2) = (0.8, 0.5);
    for q in [[0.3, -1.1], [PI, 0.0], [2.0, PI - 1e-9], [0.0, 0.0]] {
        let x = double_pendulum_x(&q, l1, l2);
        for c in double_pendulum_phi(&x, l1, l2) {
            // squared lengths ≈ 1: a few roundings
            assert_abs(c, 0.0, 8.0 * EPS);
        }
        let mut jx = DMatrix::zeros(6, 2);
        for j in 0..2 {
            let qd: Vec<Dual64> = (0..2).map(|k| Dual64::new(q[k], f64::from(k == j))).collect();
            let xd = double_pendulum_x(&qd, l1, l2);
            for i in 0..6 {
                jx[(i, j)] = xd[i].eps;
            }
        }
        let mut jphi = DMatrix::zeros(4, 6);
        for j in 0..6 {
            let xd: [Dual64; 6] = std::array::from_fn(|k| Dual64::new(x[k], f64::from(k == j)));
            let p = double_pendulum_phi(&xd, l1, l2);
            for i in 0..4 {
                jphi[(i, j)] = p[i].eps;
            }
        }
        assert_eq!(rank(&jphi), 4, "p independent constraints");
        assert_eq!(rank(&jx), 3 * 2 - 4, "r = 3l − p");
        assert!((&jphi * &jx).nan_amax() <= 8.0 * EPS, "∂x/∂q spans the constraint tangent space");
    }
}

// ---------------------------------------------------------------------------------------------
// §9.4: generalized forces from forces.

/// The tip of a two-link arm whose base moves on a prescribed path b(t) = (sin t, 0.3t², 0):
/// r(q, t) with explicit time dependence (9.2.3–5).
fn tip<T: Scalar>(q: &[T], t: T) -> Vector3<T> {
    let (l1, l2) = (T::lit(0.9), T::lit(0.6));
    Vector3::new(
        t.sin() + l1 * q[0].sin() + l2 * (q[0] + q[1]).sin(),
        T::lit(0.3) * t * t - l1 * q[0].cos() - l2 * (q[0] + q[1]).cos(),
        T::zero(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// (9.4.2)–(9.4.4): Q_j = Σ f_iᵀ ∂_{q_j} r_i = Σ f_iᵀ ∂_{q̇_j} v_i, with v = ∂r/∂q q̇ + ∂r/∂t
    /// taken as a derivative along the flow (q̇, 1) and ∂v/∂q̇_j as the mixed second dual part;
    /// and the power Σ f·v equals Qᵀq̇ plus the power of the moving base f·∂r/∂t.
    #[test]
    fn eq_9_4_3_generalized_force_from_positions_and_from_velocities(
        q in [-PI..PI, -PI..PI], qd in [-3.0..3.0f64, -3.0..3.0f64], t in 0.0..5.0f64,
        f in [-5.0..5.0f64, -5.0..5.0f64],
    ) {
        let force = Vector3::new(f[0], f[1], 0.0);
        let mut q_pos = [0.0; 2];
        let mut q_vel = [0.0; 2];
        for j in 0..2 {
            // (9.4.3): ∂r/∂q_j by one dual number
            let qj: Vec<Dual64> = (0..2).map(|k| Dual64::new(q[k], f64::from(k == j))).collect();
            let dr = tip(&qj, Dual64::from(t)).map(|x| x.eps);
            q_pos[j] = force.dot(&dr);
            // (9.4.4): ε₂ along the flow gives v; ε₁ on q̇_j makes ε₁ε₂ = ∂v/∂q̇_j
            let qh: Vec<HyperDual64> = (0..2).map(|k| HyperDual64::new(q[k], 0.0, qd[k], f64::from(k == j))).collect();
            let r = tip(&qh, HyperDual64::new(t, 0.0, 1.0, 0.0));
            q_vel[j] = force.dot(&r.map(|x| x.eps1eps2));
        }
        for j in 0..2 {
            prop_assert!((q_pos[j] - q_vel[j]).abs() <= 8.0 * EPS * 10.0, "{} vs {}", q_pos[j], q_vel[j]);
        }
        // power: f·v = Qᵀq̇ + f·∂r/∂t
        let qd_flow: Vec<Dual64> = (0..2).map(|k| Dual64::new(q[k], qd[k])).collect();
        let v = tip(&qd_flow, Dual64::new(t, 1.0)).map(|x| x.eps);
        let qt: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
        let rt = tip(&qt, Dual64::new(t, 1.0)).map(|x| x.eps);
        let power = q_pos[0] * qd[0] + q_pos[1] * qd[1] + force.dot(&rt);
        prop_assert!((force.dot(&v) - power).abs() <= 16.0 * EPS * 100.0);
    }
}

// ---------------------------------------------------------------------------------------------
// §9.3 and §9.5: eigenaxis coordinates; generalized moments.

/// K(Θ) of (9.3.32): I − ((1 − cos θ)/θ²)Θ^× + ((θ − sin θ)/θ³)Θ^{×2}; H(Θ) of (9.5.6) has + on
/// the Θ^× term. Closed forms for θ > 0.
fn k_and_h(th: &Vector3<f64>) -> (Matrix3<f64>, Matrix3<f64>) {
    let theta = th.norm();
    let (a, b) = ((1.0 - theta.cos()) / (theta * theta), (theta - theta.sin()) / theta.powi(3));
    let x = cross(th);
    (Matrix3::identity() - x * a + x * x * b, Matrix3::identity() + x * a + x * x * b)
}

/// ω|_A and ω|_B of 𝓡(Θ(t)) with Θ̇ at Θ: ω|_A^× = Ṙ𝓡ᵀ, ω|_B^× = 𝓡ᵀṘ (Ṙ by a dual number).
fn omegas(th: &Vector3<f64>, thd: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let thd_dual: Vector3<Dual64> = th.zip_map(thd, Dual64::new);
    let rd = rodrigues(&thd_dual);
    let r = rd.map(|x| x.re);
    let r_dot = rd.map(|x| x.eps);
    let vee = |m: Matrix3<f64>| {
        Vector3::new(m[(2, 1)] - m[(1, 2)], m[(0, 2)] - m[(2, 0)], m[(1, 0)] - m[(0, 1)]) * 0.5
    };
    (vee(r_dot * r.transpose()), vee(r.transpose() * r_dot))
}

/// An angle vector with |Θ| in (1e-3, 2π − 1e-2), biased toward small angles and ±π.
fn angle_vector() -> impl Strategy<Value = Vector3<f64>> {
    let norm = prop_oneof![
        3 => 1e-3..6.2f64,
        1 => prop::sample::select(vec![1e-3, PI - 1e-8, PI, PI + 1e-8, 6.0]),
    ];
    ([-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64], norm)
        .prop_filter("direction", |(n, _)| n.iter().map(|x| x * x).sum::<f64>() > 1e-4)
        .prop_map(|(n, s)| Vector3::from(n).normalize() * s)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// (9.3.31–32) and (9.5.5–6): ω|_B = K(Θ)Θ̇ with the minus sign and ω|_A = H(Θ)Θ̇ with the
    /// plus sign. The book names K "G" in (9.3.31) and (9.3.34) (erratum: one matrix, K).
    /// vectrix's J_r and J_l are K and H (with series branches the closed forms lack).
    #[test]
    fn eq_9_3_32_and_9_5_6_eigenaxis_rate_matrices(th in angle_vector(), thd in [-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64]) {
        let thd = Vector3::from(thd);
        let (k, h) = k_and_h(&th);
        let (w_a, w_b) = omegas(&th, &thd);
        // entries of K, H ≤ 2 and |Θ̇| ≤ 3.5: the closed forms lose ≈ ε/θ² to cancellation in
        // (1 − cos θ)/θ² at θ = 1e-3 (≈ 1e-10 absolute)
        let tol = 1e-9;
        prop_assert!((k * thd - w_b).nan_amax() <= tol, "K Θ̇ = {} vs {}", k * thd, w_b);
        prop_assert!((h * thd - w_a).nan_amax() <= tol, "H Θ̇ = {} vs {}", h * thd, w_a);
        prop_assert!((jacobian_right(&th) - k).nan_amax() <= tol);
        prop_assert!((jacobian_left(&th) - h).nan_amax() <= tol);
    }

    /// (9.5.1), (9.5.2), (9.5.7): a couple f⃗ at y1 and −f⃗ at y2 of a rigid body turning about a
    /// fixed point, in eigenaxis coordinates q = Θ: the generalized forces from the two forces
    /// (9.4.3) equal those of the moment M⃗ = r⃗_{y1/y2} × f⃗ through (9.5.7), Q = H(Θ)ᵀM|_A.
    #[test]
    fn eq_9_5_7_generalized_moment_of_a_couple(
        th in angle_vector(), b1 in [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
        b2 in [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64], f in [-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64],
    ) {
        let (b1, b2, f) = (Vector3::from(b1), Vector3::from(b2), Vector3::from(f));
        let r = rodrigues(&th);
        let (y1, y2) = (r * b1, r * b2);
        let mut q_forces = Vector3::zeros();
        for j in 0..3 {
            let thj: Vector3<Dual64> = Vector3::from_fn(|k, _| Dual64::new(th[k], f64::from(k == j)));
            let rj = rodrigues(&thj).map(|x| x.eps);
            q_forces[j] = f.dot(&(rj * b1)) - f.dot(&(rj * b2));
        }
        let moment = (y1 - y2).cross(&f);
        let q_moment = jacobian_left(&th).transpose() * moment;
        prop_assert!((q_forces - q_moment).nan_amax() <= 64.0 * EPS * 10.0, "{q_forces} vs {q_moment}");
    }
}

/// (9.3.34) (with K for the book's G): the eigenaxis mass matrix is diag(mI₃, KᵀJK), and it is
/// positive definite for 0 < θ < 2π (Fact 9.3.1 holds here, unlike for Euler angles).
#[test]
fn eq_9_3_34_eigenaxis_mass_matrix() {
    struct Body {
        m: f64,
        j: Matrix3<f64>,
    }
    impl Lagrangian for Body {
        fn dof(&self) -> usize {
            6
        }
        fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
            let th = Vector3::new(q[3], q[4], q[5]);
            let w = jacobian_right(&th) * Vector3::new(qd[3], qd[4], qd[5]);
            let v2 = qd[0] * qd[0] + qd[1] * qd[1] + qd[2] * qd[2];
            T::lit(0.5 * self.m) * v2 + T::lit(0.5) * w.dot(&(self.j.map(T::lit) * w))
        }
    }
    let body = Body { m: 2.5, j: Matrix3::new(3.0, 0.2, -0.4, 0.2, 5.0, 0.1, -0.4, 0.1, 6.0) };
    for th in [Vector3::new(0.3, -0.7, 1.1), Vector3::new(PI, 0.0, 0.0), Vector3::new(1e-3, 2e-3, 0.0)] {
        let q = [0.1, 0.2, 0.3, th[0], th[1], th[2]];
        let m = mass_matrix(&body, &q, &[0.0; 6], 0.0).unwrap();
        let (k, _) = k_and_h(&th);
        let want = k.transpose() * body.j * k;
        for i in 0..3 {
            for j in 0..3 {
                assert_abs(m[(i, j)], if i == j { body.m } else { 0.0 }, 4.0 * EPS);
                assert_abs(m[(3 + i, 3 + j)], want[(i, j)], 1e-9);
                assert_abs(m[(i, 3 + j)], 0.0, 4.0 * EPS);
            }
        }
        assert!(m.clone().cholesky().is_some(), "M ≻ 0 at θ = {}", th.norm());
    }
}

// ---------------------------------------------------------------------------------------------
// §9.7: Euler angles and Euler parameters.

/// S(Φ, Θ) of (9.7.12).
fn s_321<T: Scalar>(phi: T, theta: T) -> Matrix3<T> {
    let (sf, cf, st, ct) = (phi.sin(), phi.cos(), theta.sin(), theta.cos());
    let (z, o) = (T::zero(), T::one());
    Matrix3::new(o, z, -st, z, cf, ct * sf, z, -sf, ct * cf)
}

/// (9.7.8), (9.7.12): z⃗(Φ, Θ) = k̂_A resolved in F_D is the third column of S:
/// (−sin Θ, sin Φ cos Θ, cos Φ cos Θ). The book prints the third component as (sin Φ)(cos Θ)
/// (erratum; (9.7.12) itself is right). (9.7.25): ∂_Θ S has (1,3) entry −cos Θ; the book prints
/// −cos Φ (erratum).
#[test]
fn eq_9_7_8_and_9_7_25_corrected() {
    for (phi, theta) in [(0.3, -0.5), (-2.0, 1.2), (PI, 0.1), (0.7, 0.0)] {
        // F_D = F_A turned by Ψ about k̂, Θ about the new ĵ, Φ about the new î: 𝓞_{D/A}
        let o_da = orientation_about(Axis::X, phi)
            * orientation_about(Axis::Y, theta)
            * orientation_about(Axis::Z, 0.9);
        let a = Frame::new();
        let d = Frame::from_orientation_rel(&a, &o_da, 1e-12).unwrap();
        let z = a.k().resolve(&d);
        let s = s_321(phi, theta);
        for i in 0..3 {
            assert_abs(z[i], s[(i, 2)], 4.0 * EPS);
        }
        assert_abs(z[2], phi.cos() * theta.cos(), 4.0 * EPS);
        // ∂S/∂Θ by a dual number
        let ds = s_321(Dual64::from(phi), Dual64::new(theta, 1.0)).map(|x| x.eps);
        assert_abs(ds[(0, 2)], -theta.cos(), 4.0 * EPS);
    }
    // the printed third component and (1,3) entry are wrong off the special angles
    let (phi, theta): (f64, f64) = (0.3, -0.5);
    assert!((phi.sin() * theta.cos() - phi.cos() * theta.cos()).abs() > 0.5);
    assert!((-phi.cos() + theta.cos()).abs() > 0.05);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// (9.7.27) corrected: [∂_Φ S θ̇  ∂_Θ S θ̇  ∂_Ψ S θ̇] = Ṡ + (Sθ̇)^× S (the book prints a
    /// transpose where the cross matrix belongs; notes [T, C]).
    #[test]
    fn eq_9_7_27_partials_of_s_corrected(
        phi in -PI..PI, theta in -1.5..1.5f64, rates in [-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64],
    ) {
        let rates = Vector3::from(rates);
        let s = s_321(phi, theta);
        let mut lhs = Matrix3::zeros();
        let d_phi = s_321(Dual64::new(phi, 1.0), Dual64::from(theta)).map(|x| x.eps);
        let d_theta = s_321(Dual64::from(phi), Dual64::new(theta, 1.0)).map(|x| x.eps);
        lhs.set_column(0, &(d_phi * rates));
        lhs.set_column(1, &(d_theta * rates));
        // column 3: S does not depend on Ψ
        let s_dot = s_321(Dual64::new(phi, rates[0]), Dual64::new(theta, rates[1])).map(|x| x.eps);
        let rhs = s_dot + cross(&(s * rates)) * s;
        prop_assert!((lhs - rhs).nan_amax() <= 16.0 * EPS * 4.0, "{lhs} vs {rhs}");
    }
}

/// S(q) of (9.7.43) for the reduced Euler parameters q = (q2, q3, q4), q1 = √(1 − |q|²).
fn s_reduced<T: Scalar>(q: &Vector3<T>) -> Matrix3<T> {
    let (q2, q3, q4) = (q[0], q[1], q[2]);
    let q1 = (T::one() - q2 * q2 - q3 * q3 - q4 * q4).sqrt();
    let two = T::lit(2.0);
    Matrix3::new(
        q1 + q2 * q2 / q1,
        q4 + q2 * q3 / q1,
        -q3 + q2 * q4 / q1,
        -q4 + q2 * q3 / q1,
        q1 + q3 * q3 / q1,
        q2 + q3 * q4 / q1,
        q3 + q2 * q4 / q1,
        -q2 + q3 * q4 / q1,
        q1 + q4 * q4 / q1,
    ) * two
}

/// A rigid body in reduced Euler parameters under a body moment: T = ½(Sq̇)ᵀJ(Sq̇) (9.7.46),
/// Q = SᵀM (9.7.45).
struct ParameterBody {
    j: Matrix3<f64>,
    m: Vector3<f64>,
}

impl Lagrangian for ParameterBody {
    fn dof(&self) -> usize {
        3
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let w = s_reduced(&Vector3::new(q[0], q[1], q[2])) * Vector3::new(qd[0], qd[1], qd[2]);
        T::lit(0.5) * w.dot(&(self.j.map(T::lit) * w))
    }
    fn generalized_force(&self, q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        let qf = s_reduced(&Vector3::new(q[0], q[1], q[2])).transpose() * self.m;
        for k in 0..3 {
            out[k] += qf[k];
        }
    }
}

/// Reduced Euler parameters with q1 ≥ 0.05 (away from the half-turn where S is singular).
fn reduced_parameters() -> impl Strategy<Value = Vector3<f64>> {
    ([-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64], prop_oneof![3 => 0.0..0.99f64, 1 => Just(0.0)])
        .prop_filter("direction", |(n, _)| n.iter().map(|x| x * x).sum::<f64>() > 1e-4)
        .prop_map(|(n, s)| Vector3::from(n).normalize() * s.sqrt().min(0.9987))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// (9.7.36)–(9.7.51) for the Euler parameters: ω = Ω(q_{D/A})q̇_{D/A} with q̇1 from (9.7.41)
    /// equals S(q)q̇ (9.7.43); det S = 8/q1 (notes [C]); the "lengthy calculation" (9.7.48)
    /// [∂_{q_i}(Sq̇)] = Ṡ + (Sq̇)^×S; and Lagrange's equations with T = ½(Sq̇)ᵀJ(Sq̇),
    /// Q = SᵀM give Euler's equation Jω̇ + ω × Jω = M (9.7.51).
    #[test]
    fn eq_9_7_43_reduced_euler_parameters_give_euler_equation(
        q in reduced_parameters(), qd in [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
        m in [-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64],
    ) {
        let qd = Vector3::from(qd);
        let q1 = (1.0 - q.norm_squared()).sqrt();
        let s = s_reduced(&q);
        // (9.7.37): Ω = 2[[−q2, q1, q4, −q3], [−q3, −q4, q1, q2], [−q4, q3, −q2, q1]]
        let (q2, q3, q4) = (q[0], q[1], q[2]);
        let q1d = -q.dot(&qd) / q1;
        let omega_full = Vector3::new(
            -q2 * q1d + q1 * qd[0] + q4 * qd[1] - q3 * qd[2],
            -q3 * q1d - q4 * qd[0] + q1 * qd[1] + q2 * qd[2],
            -q4 * q1d + q3 * qd[0] - q2 * qd[1] + q1 * qd[2],
        ) * 2.0;
        let w = s * qd;
        let scale = 1.0 + 4.0 / q1;
        prop_assert!((omega_full - w).nan_amax() <= 16.0 * EPS * scale * 2.0);
        prop_assert!((s.determinant() - 8.0 / q1).abs() <= 64.0 * EPS * scale.powi(3));
        // (9.7.48)
        let mut lhs = Matrix3::zeros();
        for i in 0..3 {
            let qi: Vector3<Dual64> = Vector3::from_fn(|k, _| Dual64::new(q[k], f64::from(k == i)));
            lhs.set_column(i, &(s_reduced(&qi).map(|x| x.eps) * qd));
        }
        let s_dot = s_reduced(&q.zip_map(&qd, Dual64::new)).map(|x| x.eps);
        let rhs = s_dot + cross(&w) * s;
        // entries of S and Ṡ grow like 1/q1 (scale ≤ 81); the identity's terms are products of up to
        // three such factors: 1e-12·scale³ is ≈ 4500 ε per unit term
        prop_assert!((lhs - rhs).nan_amax() <= 1e-12 * scale.powi(3), "{lhs} vs {rhs}");
        // (9.7.51): Euler's equation from Lagrange's
        let body = ParameterBody { j: Matrix3::new(3.0, 0.0, -0.4, 0.0, 5.0, 0.0, -0.4, 0.0, 6.0), m: Vector3::from(m) };
        let qdd = accelerations(&body, q.as_slice(), qd.as_slice(), 0.0).unwrap();
        let w_dot = s * Vector3::new(qdd[0], qdd[1], qdd[2]) + s_dot * qd;
        let euler = body.j * w_dot + w.cross(&(body.j * w)) - body.m;
        // conditioning of S grows like 1/q1²: κ(M) ≤ (16/q1²)·κ(J)
        prop_assert!(euler.nan_amax() <= 1e-11 * scale.powi(2), "residual {euler}");
    }
}

// ---------------------------------------------------------------------------------------------
// §9.13: the Hamiltonian in momenta.

/// A particle in a frame turning at Ω about k̂, in that frame's coordinates q = (x, y):
/// T = ½m[(ẋ − Ωy)² + (ẏ + Ωx)²] = ½mq̇ᵀq̇ + F q̇ + G with F = mΩ(−y, x), G = ½mΩ²|q|²;
/// V = ½k|q|².
struct TurningPlane {
    m: f64,
    omega: f64,
    k: f64,
}

impl Lagrangian for TurningPlane {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let w = T::lit(self.omega);
        let (vx, vy) = (qd[0] - w * q[1], qd[1] + w * q[0]);
        T::lit(0.5 * self.m) * (vx * vx + vy * vy)
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(0.5 * self.k) * (q[0] * q[0] + q[1] * q[1])
    }
}

/// (9.13.9): H = ½(p − Fᵀ)ᵀM⁻¹(p − Fᵀ) − G + V = ½pᵀM⁻¹p − FM⁻¹p + ½FM⁻¹Fᵀ − G + V. The book
/// prints −½FM⁻¹Fᵀ in the expanded form (erratum, notes [T]); the first line is right. F is
/// 1 × r ((9.3.13) prints 1 × l): here one particle (l = 1) and r = 2 entries.
#[test]
fn eq_9_13_9_hamiltonian_in_momenta_corrected() {
    let sys = TurningPlane { m: 1.7, omega: 0.9, k: 3.0 };
    for (q, qd) in [([0.4, -1.2], [0.3, 0.8]), ([2.0, 0.5], [-1.0, 0.0])] {
        let p = generalized_momentum(&sys, &q, &qd, 0.0).unwrap();
        let h = hamiltonian(&sys, &q, p.as_slice(), 0.0).unwrap();
        // F = ∂T/∂q̇ at q̇ = 0: a 1 × r row
        let f = generalized_momentum(&sys, &q, &[0.0, 0.0], 0.0).unwrap();
        assert_eq!(f.len(), 2);
        assert_abs(f[0], -sys.m * sys.omega * q[1], 4.0 * EPS * 10.0);
        assert_abs(f[1], sys.m * sys.omega * q[0], 4.0 * EPS * 10.0);
        let (minv, g) = (1.0 / sys.m, 0.5 * sys.m * sys.omega * sys.omega * (q[0] * q[0] + q[1] * q[1]));
        let v = 0.5 * sys.k * (q[0] * q[0] + q[1] * q[1]);
        let (pp, fp, ff) = (p.dot(&p), f.dot(&p), f.dot(&f));
        let corrected = 0.5 * minv * pp - minv * fp + 0.5 * minv * ff - g + v;
        let printed = 0.5 * minv * pp - minv * fp - 0.5 * minv * ff - g + v;
        assert_abs(h, corrected, 64.0 * EPS * 10.0);
        assert!((h - printed).abs() > 0.1, "the printed sign is off by FM⁻¹Fᵀ = {}", minv * ff);
        // (9.13.7): H = ½q̇ᵀMq̇ − G + V
        assert_abs(h, 0.5 * sys.m * (qd[0] * qd[0] + qd[1] * qd[1]) - g + v, 64.0 * EPS * 10.0);
    }
}
