//! Worked examples of chapter 9 (§9.10) and the Euler-angle rigid body of §9.7.

use vectrix::dynamics::lagrange::{
    accelerations, map_accelerations, map_kinetic_energy, map_mass_matrix, mass_matrix,
};
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

use super::systems::{CART, EulerBody, Oscillator, PhysicalPendulum, omega_and_rate};
use crate::support::{EPS, assert_abs, assert_printed_slice, assert_rel, assert_rel_slice};

/// Ex 9.10.1: "m q̈ + c q̇ + k q = f."
#[test]
fn example_9_10_1_mass_spring_dashpot() {
    let sys = Oscillator { m: 2.0, k: 8.0, c: 0.5, f: 1.5 };
    let (q, qd) = (0.3, -0.7);
    let qdd = accelerations(&sys, &[q], &[qd], 0.0).unwrap();
    assert_abs(qdd[0], (1.5 - 0.5 * qd - 8.0 * q) / 2.0, 8.0 * EPS);
}

/// Ex 9.10.2: "bead on a wire rotating at constant ω: ẍ = ω²x. With free θ:
/// (I + mx²)θ̈ + 2mxẋθ̇ = 0."
#[test]
fn example_9_10_2_bead_on_rotating_wire() {
    struct Constant(f64);
    impl Lagrangian for Constant {
        fn dof(&self) -> usize {
            1
        }
        // T = ½m(ẋ² + ω²x²) with m = 1
        fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
            T::lit(0.5) * (qd[0] * qd[0] + T::lit(self.0 * self.0) * q[0] * q[0])
        }
    }
    let w = 1.7;
    let qdd = accelerations(&Constant(w), &[0.8], &[0.2], 0.0).unwrap();
    assert_rel(qdd[0], w * w * 0.8, 8.0 * EPS);

    struct Free {
        i: f64,
        m: f64,
    }
    impl Lagrangian for Free {
        fn dof(&self) -> usize {
            2
        }
        // q = (x, θ): T = ½mẋ² + ½(I + mx²)θ̇²
        fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
            let m = T::lit(self.m);
            T::lit(0.5) * m * qd[0] * qd[0] + T::lit(0.5) * (T::lit(self.i) + m * q[0] * q[0]) * qd[1] * qd[1]
        }
    }
    let sys = Free { i: 0.4, m: 1.3 };
    let (q, qd) = ([0.9, 0.2], [0.5, 1.1]);
    let qdd = accelerations(&sys, &q, &qd, 0.0).unwrap();
    assert_rel(qdd[0], q[0] * qd[1] * qd[1], 8.0 * EPS);
    assert_abs(qdd[1], -2.0 * 1.3 * q[0] * qd[0] * qd[1] / (0.4 + 1.3 * q[0] * q[0]), 8.0 * EPS);
}

/// Ex 9.10.3: "(m1+m2)q̈1 + m2 l q̈2 cos q2 − m2 l q̇2² sin q2 + k1 q1 = 0;
/// m2 l q̈1 cos q2 + m2 l² q̈2 + k2 q2 = 0." Test vector from the notes ([C], sympy):
/// m1 = 2, m2 = 1, l = 0.5, k1 = 10, k2 = 3, q = (0.1, 0.7), q̇ = (0.3, −0.4) ⇒
/// q̈ = (0.9374158183, −9.8339503297).
#[test]
fn example_9_10_3_cart_with_eccentric_pendulum() {
    let (q, qd) = ([0.1, 0.7], [0.3, -0.4]);
    let want = ["0.9374158183", "-9.8339503297"];
    // the notes give ten decimals
    let qdd = accelerations(&CART, &q, &qd, 0.0).unwrap();
    assert_printed_slice(qdd.as_slice(), &want);
    // the kinematic-map form builds T from the particle positions and agrees
    let qdd_map = map_accelerations(&CART, &q, &qd, 0.0).unwrap();
    assert_rel_slice(qdd_map.as_slice(), qdd.as_slice(), 64.0 * EPS);
    let m = mass_matrix(&CART, &q, &qd, 0.0).unwrap();
    let m_map = map_mass_matrix(&CART, &q, 0.0).unwrap();
    assert_rel_slice(m.as_slice(), m_map.as_slice(), 16.0 * EPS);
    let t = Lagrangian::kinetic(&CART, &q[..], &qd[..], 0.0);
    assert_abs(map_kinetic_energy(&CART, &q, &qd, 0.0).unwrap(), t, 16.0 * EPS);
}

/// §9.7 (9.7.33–34): "SᵀJω̇ + Sᵀ(ω×Jω) = SᵀM ⇒ Jω̇ + ω×Jω = M if cos Θ ≠ 0." Test vector from
/// the notes ([C]): J = [[3, 0, −.4], [0, 5, 0], [−.4, 0, 6]], M|_B = (.2, −.1, .3),
/// (Φ, Θ, Ψ) = (.3, −.5, 1.1), rates (.2, .4, −.3) ⇒ ω̇ = (0.1143759696, −0.0217777147, 0.0594279733).
#[test]
fn section_9_7_euler_angle_body_matches_euler_equation() {
    let sys = EulerBody {
        j: Matrix3::new(3.0, 0.0, -0.4, 0.0, 5.0, 0.0, -0.4, 0.0, 6.0),
        m_b: Vector3::new(0.2, -0.1, 0.3),
    };
    let (q, qd) = ([0.3, -0.5, 1.1], [0.2, 0.4, -0.3]);
    let qdd = accelerations(&sys, &q, &qd, 0.0).unwrap();
    let (_, omega_dot) = omega_and_rate(&q, &qd, qdd.as_slice());
    // ten decimals in the notes
    assert_printed_slice(omega_dot.as_slice(), &["0.1143759696", "-0.0217777147", "0.0594279733"]);
}

/// Fact 9.3.1 fails for Euler angles: "M ≻ 0 … fails at gimbal lock" (det S = cos Θ, (9.3.25)).
/// At Θ = π/2 vectrix refuses with a typed error instead of returning garbage.
#[test]
fn fact_9_3_1_euler_angles_at_gimbal_lock_are_singular() {
    let sys = EulerBody { j: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)), m_b: Vector3::zeros() };
    let err =
        accelerations(&sys, &[0.2, std::f64::consts::FRAC_PI_2, 0.0], &[0.1, 0.2, 0.3], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::SingularMassMatrix { .. }), "{err}");
    // a hair away from the lock M is positive definite again
    assert!(accelerations(&sys, &[0.2, 1.0, 0.0], &[0.1, 0.2, 0.3], 0.0).is_ok());
}

/// Ex 7.15.2 through §9.3's rigid-body kinetic energy (9.3.17) in the kinematic-map form:
/// "θ̈ + ℓmg sin θ/(J0 + mℓ²) = 0."
#[test]
fn example_7_15_2_physical_pendulum_from_kinematic_map() {
    let p = PhysicalPendulum { m: 1.5, l: 0.7, j0: 0.2, g: 9.81 };
    let th = 0.9;
    let qdd = map_accelerations(&p, &[th], &[0.4], 0.0).unwrap();
    assert_rel(qdd[0], -p.l * p.m * p.g * th.sin() / (p.j0 + p.m * p.l * p.l), 64.0 * EPS);
    let m = map_mass_matrix(&p, &[th], 0.0).unwrap();
    assert_abs(m[(0, 0)], p.j0 + p.m * p.l * p.l, 16.0 * EPS);
}

/// Bad input is a typed error: wrong lengths and non-finite states.
#[test]
fn lagrange_rejects_bad_states() {
    assert!(matches!(
        accelerations(&CART, &[0.1], &[0.3, 0.1], 0.0),
        Err(DynamicsError::DimensionMismatch { .. })
    ));
    assert!(matches!(
        accelerations(&CART, &[f64::NAN, 0.1], &[0.3, 0.1], 0.0),
        Err(DynamicsError::NonFinite { .. })
    ));
}
