//! Property tests: Lagrange's equations and Newton–Euler agree on random rigid bodies.

use proptest::prelude::*;
use vectrix::dynamics::lagrange::accelerations;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

use super::systems::{EulerBody, omega_and_rate, s_321};

/// A random physical inertia: R diag(λ) Rᵀ with λ satisfying the triangle inequality.
fn inertia() -> impl Strategy<Value = Matrix3<f64>> {
    ([0.5..3.0f64, 0.5..3.0f64, 0.5..3.0f64], [-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64])
        .prop_filter("triangle", |(l, _)| l[0] <= l[1] + l[2] && l[1] <= l[0] + l[2] && l[2] <= l[0] + l[1])
        .prop_map(|(l, th)| {
            let r = vectrix::nalgebra::Rotation3::from_scaled_axis(Vector3::from(th)).into_inner();
            r * Matrix3::from_diagonal(&Vector3::from(l)) * r.transpose()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// §9.7: Lagrange's equations in 3-2-1 angles give ω̇ = J⁻¹(M − ω×Jω), Euler's equation
    /// (7.8.13), for every body, attitude (away from gimbal lock) and rate.
    #[test]
    fn lagrange_and_newton_euler_agree_on_random_rigid_bodies(
        j in inertia(),
        m in [-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64],
        angles in [-3.0..3.0f64, -1.4..1.4f64, -3.0..3.0f64],
        rates in [-2.0..2.0f64, -2.0..2.0f64, -2.0..2.0f64],
    ) {
        let sys = EulerBody { j, m_b: Vector3::from(m) };
        let qdd = accelerations(&sys, &angles, &rates, 0.0).unwrap();
        let (omega, omega_dot) = omega_and_rate(&angles, &rates, qdd.as_slice());
        // Newton–Euler through the frame-free RigidBody, resolved in the body frame B
        let b = Frame::new();
        let props = vectrix::statics::MassProperties::new(1.0, vectrix::statics::Point::origin(), b.dyadic(&j)).unwrap();
        let body = RigidBody::new(props, Vector::zero(), b.vector(omega.into()));
        let wrench = vectrix::statics::Wrench::torque(b.vector(m), vectrix::statics::Point::origin());
        let (_, alpha) = body.accelerations(&wrench).unwrap();
        let alpha = alpha.resolve(&b);
        // conditioning: 1/cos Θ ≤ 6 and |J⁻¹| ≤ 2
        let scale = 1.0 + omega_dot.norm();
        prop_assert!((alpha - omega_dot).norm() <= 1e-11 * scale, "{alpha} vs {omega_dot}");
        let _ = s_321(angles[0], angles[1]);
    }
}
