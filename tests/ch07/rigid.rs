//! §7.3–7.10: particles, rigid bodies, Euler's equation, eigenaxis and 6D forms.

use vectrix::dynamics::{eigenaxis_acceleration, newton_euler_6d, particle_acceleration};
use vectrix::nalgebra::{Matrix3, SVector, Vector3};
use vectrix::ode::Adaptive;
use vectrix::ode::harness::elliptic::elliptic_k;
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point, Wrench};

use crate::support::{EPS, assert_abs_slice, assert_printed, assert_rel, assert_rel_slice};

/// (7.3.1): "m a_{y/w/A} = f_y."
#[test]
fn eq_7_3_1_newton_second_law_particle() {
    let a = Frame::new();
    let acc = particle_acceleration(2.0, &a.vector([4.0, -2.0, 1.0])).unwrap();
    assert_rel_slice(acc.resolve(&a).as_slice(), &[2.0, -1.0, 0.5], EPS);
    assert!(matches!(
        particle_acceleration(0.0, &a.vector([1.0, 0.0, 0.0])),
        Err(DynamicsError::OutOfRange { .. })
    ));
}

/// §7.8 and notes ch6-8 §3: "the axial spin of a rod is inert": a thin rod (rank-2
/// inertia) under a transverse torque has α⃗·ê = 0, and a torque about its own axis is refused.
#[test]
fn thin_rod_axial_spin_is_inert() {
    let a = Frame::new();
    let axis = a.vector([1.0, 1.0, 0.0]).unit().unwrap();
    let rod = MassProperties::thin_rod(3.0, 2.0, &axis, Point::origin()).unwrap();
    // spinning about its axis and tumbling
    let omega = axis * 5.0 + a.vector([0.0, 0.0, 0.7]);
    let body = RigidBody::new(rod, Vector::zero(), omega);
    let torque = a.vector([0.0, 0.0, 1.3]);
    let (_, alpha) = body.accelerations(&Wrench::torque(torque, Point::origin())).unwrap();
    assert!(alpha.dot(&axis).abs() <= 8.0 * EPS * alpha.norm().max(1.0));
    // the transverse equation holds: J α + ω × Jω = M
    let j = rod.inertia_about_centre();
    let residual = j.apply(&alpha) + omega.cross(&j.apply(&omega)) - torque;
    assert!(residual.norm() <= 16.0 * EPS * 10.0, "{residual:?}");
    let err = body.accelerations(&Wrench::torque(axis * 2.0, Point::origin())).unwrap_err();
    assert!(matches!(err, DynamicsError::TorqueOnInertAxis { .. }), "{err}");
}

/// (7.6.16): "M_{/z} = M_{/c} + r_{c/z} × m a_c" and (7.8.7) about any body point: the
/// accelerations found about c satisfy Euler's equation about every body point.
#[test]
fn eq_7_8_7_euler_about_any_body_point() {
    let a = Frame::new();
    let props = MassProperties::new(
        2.0,
        Point::at(a.vector([0.3, -0.2, 0.5])),
        a.dyadic(&Matrix3::new(3.0, 0.1, -0.4, 0.1, 5.0, 0.2, -0.4, 0.2, 6.0)),
    )
    .unwrap();
    let body = RigidBody::new(props, a.vector([0.1, 0.2, -0.3]), a.vector([0.4, -1.1, 0.8]));
    let wrench = Wrench {
        force: a.vector([1.0, 2.0, -0.5]),
        moment: a.vector([0.3, -0.2, 0.7]),
        about: Point::origin(),
    };
    let (a_c, alpha) = body.accelerations(&wrench).unwrap();
    let c = props.centre_of_mass();
    for z in [Point::origin(), Point::at(a.vector([1.0, -2.0, 0.5]))] {
        // a_z = a_c + α × r_{z/c} + ω × (ω × r_{z/c})
        let r = z.position_rel(&c);
        let a_z = a_c + alpha.cross(&r) + body.omega.cross(&body.omega.cross(&r));
        let w = wrench.shift_to(&z);
        let e = body.euler_residual_about(&z, &a_z, &alpha, &w.moment);
        let n = body.newton_residual_about(&z, &a_z, &alpha, &w.force);
        assert!(e.norm() < 64.0 * EPS * 10.0 && n.norm() < 64.0 * EPS * 10.0, "{e:?} {n:?}");
    }
}

/// §7.10: "𝒥𝒜 + 𝒱^×𝒥𝒱 = ℱ" reproduces (7.4.17) and (7.8.7).
#[test]
fn eq_7_10_9_six_d_form_reproduces_newton_euler() {
    let a = Frame::new();
    let props = MassProperties::new(
        1.5,
        Point::at(a.vector([0.2, 0.1, -0.3])),
        a.dyadic(&Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 2.5))),
    )
    .unwrap();
    let z = Point::at(a.vector([-0.5, 0.4, 0.2]));
    let body = RigidBody::new(props, Vector::zero(), a.vector([0.3, -0.6, 1.2]));
    let (v_z, a_z, alpha) =
        (a.vector([0.7, 0.1, -0.2]), a.vector([0.2, -0.9, 0.4]), a.vector([1.1, 0.3, -0.5]));
    let (f, m) = newton_euler_6d(&props.spatial_inertia(&z), &v_z, &body.omega, &a_z, &alpha);
    assert!(body.newton_residual_about(&z, &a_z, &alpha, &f).norm() < 64.0 * EPS);
    assert!(body.euler_residual_about(&z, &a_z, &alpha, &m).norm() < 64.0 * EPS);
}

/// §7.9: Euler's equation in eigenaxis coordinates, ω = S(Θ)Θ̇ (7.9.1–3): the Θ̈ returned
/// satisfies J(SΘ̈ + ṠΘ̇) + ω×Jω = M (Ṡ by a central difference, h = 1e-5).
#[test]
fn section_7_9_eigenaxis_form() {
    use vectrix::kinematics::attitude::jacobian_right;
    let j = Matrix3::new(3.0, 0.1, 0.0, 0.1, 4.0, -0.2, 0.0, -0.2, 5.0);
    let (th, thd, m) =
        (Vector3::new(0.4, -0.9, 1.3), Vector3::new(0.3, 0.2, -0.5), Vector3::new(0.1, -0.4, 0.2));
    let thdd = eigenaxis_acceleration(&j, &th, &thd, &m).unwrap();
    let h = 1e-5;
    let s_dot = (jacobian_right(&(th + thd * h)) - jacobian_right(&(th - thd * h))) / (2.0 * h);
    let s = jacobian_right(&th);
    let omega = s * thd;
    let residual = j * (s * thdd + s_dot * thd) + omega.cross(&(j * omega)) - m;
    // central difference error O(h²) ≈ 1e-10
    assert!(residual.norm() < 1e-8, "{residual}");
    // near θ = 0 (series branch) the form reduces to Θ̈ = J⁻¹M at rest
    let at_rest = eigenaxis_acceleration(&j, &Vector3::new(1e-9, 0.0, 0.0), &Vector3::zeros(), &m).unwrap();
    // S(θ) = I + O(|θ|): at |θ| = 10⁻⁹ the exact Θ̈ = S⁻¹J⁻¹M differs from J⁻¹M (|J⁻¹M| < 1) by
    // about 10⁻⁹
    assert_abs_slice(at_rest.as_slice(), (j.try_inverse().unwrap() * m).as_slice(), 1e-8);
}

/// P7.16.7 and notes §3: "J = diag(1, 2, 3), ω0 = (1e−3, 1, 1e−3): ω2 changes sign every
/// ≈ 27.53 (full period ≈ 55.06)": the flip interval of the intermediate-axis (Dzhanibekov)
/// motion equals 2K(k²)/λ with λ² = (J3−J2)(H²−2TJ1)/(J1J2J3),
/// k² = (J2−J1)(2TJ3−H²)/((J3−J2)(H²−2TJ1)) (Landau–Lifshitz §37).
#[test]
fn intermediate_axis_flip_period_matches_elliptic_function() {
    let b = Frame::new();
    let jd = [1.0, 2.0, 3.0];
    let props =
        MassProperties::new(1.0, Point::origin(), b.dyadic(&Matrix3::from_diagonal(&Vector3::from(jd))))
            .unwrap();
    let f = |_t: f64, w: &SVector<f64, 3>| {
        let body = RigidBody::new(props, Vector::zero(), b.vector([w[0], w[1], w[2]]));
        let (_, alpha) = body.accelerations(&Wrench::zero(Point::origin())).unwrap();
        alpha.resolve(&b)
    };
    let w0 = SVector::<f64, 3>::new(1e-3, 1.0, 1e-3);
    let mut events = [vectrix::ode::Event::new(|_t, w: &SVector<f64, 3>| w[1])];
    let sol = Adaptive::dop853()
        .rtol(1e-12)
        .atol(1e-14)
        .solve_with_events(f, 0.0, &w0, 100.0, &mut events)
        .unwrap();
    let t: Vec<f64> = sol.events.iter().map(|e| e.t).collect();
    assert!(t.len() >= 3, "{t:?}");
    let two_t: f64 = (0..3).map(|i| jd[i] * w0[i] * w0[i]).sum();
    let h2: f64 = (0..3).map(|i| (jd[i] * w0[i]).powi(2)).sum();
    let (j1, j2, j3) = (jd[0], jd[1], jd[2]);
    let lambda = ((j3 - j2) * (h2 - two_t * j1) / (j1 * j2 * j3)).sqrt();
    let k2 = (j2 - j1) * (two_t * j3 - h2) / ((j3 - j2) * (h2 - two_t * j1));
    let interval = 2.0 * elliptic_k(k2).unwrap() / lambda;
    assert_printed(interval, "27.530840553"); // the notes' nine decimals
    // near the separatrix the flip times are sensitive; 1e-6 relative is what rtol 1e-12 buys
    for w in t.windows(2) {
        assert_rel(w[1] - w[0], interval, 1e-6);
    }
    // the first flip, from the notes ([C], DOP853): t = 14.90593888, to the same 1e-6 relative
    assert_rel(t[0], 14.90593888, 1e-6);
}
