//! Chapter 8: kinetic energy, work, potential energy and conservation (book §8.1–8.5).

mod support;

use proptest::prelude::*;
use vectrix::dynamics::lagrange::{accelerations, energy};
use vectrix::dynamics::{
    Element, Network, kinetic_energy_about_centre_pairwise, particles_kinetic_energy, power, work_along_path,
};
use vectrix::nalgebra::{DVector, Matrix3, SVector, Vector3};
use vectrix::num_dual::Dual64;
use vectrix::ode::{Adaptive, GaussLegendre};
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point, Spring, UniformGravity, Wrench};

use support::{EPS, assert_abs, assert_rel, nan_max, triple};

/// (8.1.5): "T_{/w} = T_{/c} + ½m|v_c|²" and (8.1.6): "T_{/c} = ½Σ_{i<j}(m_im_j/m_B)|v_ij|²".
#[test]
fn eq_8_1_6_kinetic_energy_about_centre_from_relative_velocities() {
    let a = Frame::new();
    let parts = [
        (1.0, a.vector([1.0, 0.0, 2.0])),
        (2.0, a.vector([-1.0, 3.0, 0.5])),
        (0.5, a.vector([0.0, -2.0, 1.0])),
    ];
    let mb: f64 = parts.iter().map(|p| p.0).sum();
    let v_c = parts.iter().fold(Vector::zero(), |s, (m, v)| s + *v * *m) / mb;
    let t = particles_kinetic_energy(&parts);
    let t_c = kinetic_energy_about_centre_pairwise(&parts);
    assert_rel(t, t_c + 0.5 * mb * v_c.norm_squared(), 16.0 * EPS);
}

/// (8.2.1) and the work–energy principle: a particle pushed by a constant force gains
/// ΔT = ∫ f·dr = f·Δr.
#[test]
fn eq_8_2_1_work_equals_kinetic_energy_change() {
    let a = Frame::new();
    let (m, f) = (2.0, a.vector([1.0, -0.5, 0.25]));
    let v0 = a.vector([0.3, 0.2, -0.1]);
    // exact motion r(t) = v0 t + ½(f/m)t², sampled
    let samples: Vec<(Vector, Point)> =
        (0..=20).map(|k| k as f64 * 0.1).map(|t| (f, Point::at(v0 * t + f * (0.5 * t * t / m)))).collect();
    let w = work_along_path(&samples);
    let v1 = v0 + f * (2.0 / m);
    assert_rel(w, 0.5 * m * (v1.norm_squared() - v0.norm_squared()), 64.0 * EPS);
}

/// (8.2.4–6): the power of a wrench on a rigid body, f·v_c + M_{/c}·ω, is dT/dt: with the
/// accelerations of Newton–Euler, d/dt(½m|v_c|² + ½ω·Jω) = m v_c·a_c + ω·Jα.
#[test]
fn eq_8_2_4_power_is_rate_of_kinetic_energy() {
    let a = Frame::new();
    let props = MassProperties::new(
        1.7,
        Point::origin(),
        a.dyadic(&Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, -0.2, 0.0, -0.2, 4.0)),
    )
    .unwrap();
    let body = RigidBody::new(props, a.vector([0.5, -0.2, 0.1]), a.vector([0.3, 1.1, -0.7]));
    let w = Wrench {
        force: a.vector([0.4, 0.0, -1.0]),
        moment: a.vector([0.2, -0.3, 0.5]),
        about: Point::origin(),
    };
    let (a_c, alpha) = body.accelerations(&w).unwrap();
    let t_dot =
        props.mass() * body.v_c.dot(&a_c) + body.omega.dot(&props.inertia_about_centre().apply(&alpha));
    assert_abs(power(&w.force, &w.moment, &body.v_c, &body.omega), t_dot, 64.0 * EPS);
}

/// Fact 8.3.2, corrected: uniform gravity is potential with U = −m r_c·g (8.3.9) and
/// f = −∂U/∂r = **+m g** (the printed "f = −mg", l.10470, is an erratum). Differentiated
/// exactly with dual numbers.
#[test]
fn fact_8_3_2_uniform_gravity_force_is_plus_mg() {
    let a = Frame::<Dual64>::identity();
    let g =
        UniformGravity::new(a.vector([Dual64::from(0.0), Dual64::from(0.0), Dual64::from(-9.81)])).unwrap();
    let m = Dual64::from(2.5);
    let mut grad = [0.0; 3];
    for (k, gk) in grad.iter_mut().enumerate() {
        let mut r = [Dual64::from(0.3), Dual64::from(-1.0), Dual64::from(2.0)];
        r[k].eps = 1.0;
        *gk = g.potential(m, &a.vector(r)).eps;
    }
    // f = −∇U = m g
    assert_abs(-grad[0], 0.0, EPS);
    assert_rel(-grad[2], 2.5 * -9.81, 4.0 * EPS);
}

/// (8.3.12) and the corrected (8.3.13): "U = ½k(|r| − d)² = ½k(|r|² − 2d|r| + d²)" (the printed
/// expansion, l.10536, is an erratum), and f = −∇U is the spring force (6.7.1).
#[test]
fn eq_8_3_13_spring_potential_corrected() {
    let a = Frame::new();
    let (k, d) = (3.0, 0.5);
    let spring = Spring::new(k, d).unwrap();
    let r = a.vector([0.6, -0.8, 1.2]);
    let n = r.norm();
    assert_rel(spring.potential(&r), 0.5 * k * (n * n - 2.0 * d * n + d * d), 8.0 * EPS);
    let ad = Frame::<Dual64>::identity();
    let sd = Spring::new(Dual64::from(k), Dual64::from(d)).unwrap();
    let f = spring.force(&r).unwrap().resolve(&a);
    for i in 0..3 {
        let mut c = [Dual64::from(0.6), Dual64::from(-0.8), Dual64::from(1.2)];
        c[i].eps = 1.0;
        assert_rel(-sd.potential(&ad.vector(c)).eps, f[i], 16.0 * EPS);
    }
}

/// P8.5.1, with the corrected (iv) (l.10578: T → ½ m_B |v_c|²): a free chain of particles joined
/// only by dashpots ends with every velocity equal to v_c, and T decays to ½m_B|v_c|².
#[test]
fn problem_8_5_1_free_dashpot_network_settles_to_centre_velocity() {
    let net = Network {
        masses: vec![1.0, 2.0, 0.5],
        springs: vec![],
        dashpots: vec![Element { i: 0, j: Some(1), value: 3.0 }, Element { i: 1, j: Some(2), value: 2.0 }],
        inerters: vec![],
    };
    let v0 = [2.0, -1.0, 4.0];
    let mb = 3.5;
    let v_c = (1.0 * v0[0] + 2.0 * v0[1] + 0.5 * v0[2]) / mb;
    let f = |_t: f64, y: &SVector<f64, 6>| {
        let a = net.accelerations(&y.as_slice()[..3], &y.as_slice()[3..], &[0.0; 3]).unwrap();
        SVector::<f64, 6>::from_column_slice(&[y[3], y[4], y[5], a[0], a[1], a[2]])
    };
    let y0 = SVector::<f64, 6>::from_column_slice(&[0.0, 0.0, 0.0, v0[0], v0[1], v0[2]]);
    let sol = Adaptive::dop853().rtol(1e-11).atol(1e-13).solve(f, 0.0, &y0, 40.0).unwrap();
    let y = sol.last();
    // DOP853 (rtol 1e-11, atol 1e-13) to t = 40, where the dashpots have damped the relative
    // motion to well below the integration error
    for i in 3..6 {
        assert_abs(y[i], v_c, 1e-9);
    }
    let t = 0.5 * (1.0 * y[3] * y[3] + 2.0 * y[4] * y[4] + 0.5 * y[5] * y[5]);
    assert_abs(t, 0.5 * mb * v_c * v_c, 1e-9);
}

/// Fact 8.4.1: "E = T + U is constant if all forces are potential": a torque-free rigid body
/// (T is a quadratic invariant, conserved by Gauss–Legendre to round-off) over 10³ spin periods (10⁴ periods of the
/// oscillator are in ch09).
#[test]
fn fact_8_4_1_rigid_body_energy_conserved_gauss_legendre() {
    let b = Frame::new();
    let j = Vector3::new(1.0, 2.0, 3.0);
    let props = MassProperties::new(1.0, Point::origin(), b.dyadic(&Matrix3::from_diagonal(&j))).unwrap();
    let f = |_t: f64, w: &DVector<f64>| {
        let body = RigidBody::new(props, Vector::zero(), b.vector([w[0], w[1], w[2]]));
        let (_, alpha) = body.accelerations(&Wrench::zero(Point::origin())).unwrap();
        DVector::from_column_slice(alpha.resolve(&b).as_slice())
    };
    let w0 = DVector::from_vec(vec![0.3, 1.0, 0.2]);
    let t_of = |w: &DVector<f64>| 0.5 * (j[0] * w[0] * w[0] + j[1] * w[1] * w[1] + j[2] * w[2] * w[2]);
    let e0 = t_of(&w0);
    let period = 2.0 * std::f64::consts::PI; // |ω| ≈ 1
    let mut worst = 0.0f64;
    GaussLegendre::Gauss4
        .integrate(f, 0.0, &w0, 1e3 * period, 20_000, |_, w: &DVector<f64>| {
            worst = nan_max(worst, ((t_of(w) - e0) / e0).abs())
        })
        .unwrap();
    assert!(worst < 1e-10, "relative energy drift {worst:e}");
}

/// Fact 8.4.1 through Lagrange: the energy of Ex 9.10.3 computed by [`energy`] is constant along
/// an accurate trajectory.
#[test]
fn fact_8_4_1_energy_constant_along_lagrange_flow() {
    struct Pendulum;
    impl Lagrangian for Pendulum {
        fn dof(&self) -> usize {
            1
        }
        fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
            T::lit(0.5) * qd[0] * qd[0]
        }
        fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
            -T::lit(9.81) * q[0].cos()
        }
    }
    let f = |_t: f64, y: &SVector<f64, 2>| {
        SVector::<f64, 2>::new(y[1], accelerations(&Pendulum, &[y[0]], &[y[1]], 0.0).unwrap()[0])
    };
    let y0 = SVector::<f64, 2>::new(2.5, 0.0);
    let sol = Adaptive::dop853().rtol(1e-12).atol(1e-13).solve(f, 0.0, &y0, 50.0).unwrap();
    let e0 = energy(&Pendulum, &[2.5], &[0.0], 0.0).unwrap();
    for y in &sol.y {
        // DOP853 at rtol 1e-12 over 50 time units: the energy drifts by far less than 1e-9
        assert_rel(energy(&Pendulum, &[y[0]], &[y[1]], 0.0).unwrap(), e0, 1e-9);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// (8.1.5)–(8.1.6) for random particle sets.
    #[test]
    fn kinetic_energy_splits_at_centre(parts in prop::collection::vec((0.1..5.0f64, triple()), 1..7)) {
        let a = Frame::new();
        let parts: Vec<(f64, Vector)> = parts.into_iter().map(|(m, v)| (m, a.vector(v))).collect();
        let mb: f64 = parts.iter().map(|p| p.0).sum();
        let v_c = parts.iter().fold(Vector::zero(), |s, (m, v)| s + *v * *m) / mb;
        let t = particles_kinetic_energy(&parts);
        let split = kinetic_energy_about_centre_pairwise(&parts) + 0.5 * mb * v_c.norm_squared();
        prop_assert!((t - split).abs() <= 1e-12 * (1.0 + t));
    }
}
