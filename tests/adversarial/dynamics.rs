//! vectrix-dynamics under hostile input (docs/robustness.md), for the Newton–Euler, collision,
//! energy, network and 6D parts (multibody, Lagrange and scenes are listed as pending in the
//! coverage table until their fixes are merged).

use nalgebra::{Matrix3, Vector3};
use vectrix::dynamics::{
    DynamicsError, Element, ImpactEnd, Network, RigidBody, ZenoGuard, centre_of_percussion,
    collision_energy_loss, eigenaxis_acceleration, impulse_response, kinetic_energy_about_centre_pairwise,
    newton_euler_6d, particle_acceleration, particles_kinetic_energy, power, restitution_1d, rigid_impact,
    simulate_with_impacts, sphere_collision, twist_cross_matrix, work_along_path,
};
use vectrix::frames::{Frame, Resolve};
use vectrix::ode::Adaptive;
use vectrix::statics::{MassProperties, Point, Wrench};
use vectrix::tensor::Vector;

use crate::harness::{err_or, finite, hostile, hostile3, refused};

const EPS: f64 = f64::EPSILON;

fn v(x: [f64; 3]) -> Vector {
    Frame::new().vector(x)
}

fn body(v_c: Vector, omega: Vector) -> RigidBody {
    let p = MassProperties::solid_box(2.0, [1.0, 2.0, 3.0], &Frame::new(), Point::origin()).unwrap();
    RigidBody::new(p, v_c, omega)
}

cases! {
    // Newton–Euler for one body (§7.4–7.8): a = f/m exactly or a typed error (m = 1e-320 makes
    // f/m overflow); momenta and energies are finite for finite motion; T ≥ 0.
    rigid_body ["particle_acceleration", "RigidBody::new", "RigidBody::momentum", "RigidBody::velocity_of",
        "RigidBody::angular_momentum_about_centre", "RigidBody::angular_momentum_about", "RigidBody::kinetic_energy",
        "RigidBody::kinetic_energy_rel", "RigidBody::gyroscopic_moment", "RigidBody::euler_residual_about",
        "RigidBody::newton_residual_about", "RigidBody::accelerations"] {
        for m in hostile() {
            err_or(particle_acceleration(m, &v([1.0, 0.0, 0.0])), "particle_acceleration", |a| a.is_finite() && (a.resolve(&Frame::new()).x * m - 1.0).abs() <= 2.0 * EPS);
        }
        assert!(matches!(particle_acceleration(1e-320, &v([1.0, 0.0, 0.0])), Err(DynamicsError::Overflow { .. })));
        for x in hostile3() {
            err_or(particle_acceleration(2.0, &v(x)), "particle_acceleration(f)", |a| a.is_finite());
            let w = v(x);
            let b = body(v([1.0, 0.0, 0.0]), w);
            if finite(&x) && x.iter().all(|c| c.abs() <= 1e100) {
                assert!(b.momentum().is_finite() && b.velocity_of(&Point::at(v([1.0, 1.0, 1.0]))).is_finite());
                assert!(b.angular_momentum_about_centre().is_finite() && b.angular_momentum_about(&Point::origin(), &Vector::zero()).is_finite());
                assert!(b.kinetic_energy() >= 0.0 && b.kinetic_energy().is_finite() && b.kinetic_energy_rel(&w).is_finite());
                assert!(b.gyroscopic_moment().is_finite());
                let z = Point::origin();
                assert!(b.euler_residual_about(&z, &Vector::zero(), &w, &w).is_finite());
                assert!(b.newton_residual_about(&z, &Vector::zero(), &w, &w).is_finite());
            }
            let wrench = Wrench { force: v(x), moment: v([0.0, 0.0, 1.0]), about: Point::origin() };
            err_or(body(Vector::zero(), Vector::zero()).accelerations(&wrench), "accelerations", |(a, al)| a.is_finite() && al.is_finite());
        }
    }

    // Collisions (§7.13): momentum is conserved and the energy loss is ½(1 − e²)μ(u₁ − u₂)² ≥ 0;
    // m₁ = m₂ = 0 (0/0), e outside [0, 1], separating bodies and NaN are typed errors.
    collisions ["restitution_1d", "collision_energy_loss", "sphere_collision", "impulse_response", "rigid_impact",
        "centre_of_percussion"] {
        for x in hostile() {
            err_or(restitution_1d(1.0, 2.0, x, 0.0, 0.5), "restitution_1d", |(a, b)| {
                a.is_finite() && b.is_finite() && (a + 2.0 * b - x).abs() <= (8.0 * EPS * x.abs()).max(4.0 * 5e-324)
            });
            err_or(collision_energy_loss(x, 1.0, 1.0, 0.0, 0.5), "collision_energy_loss(m)", |l| l.is_finite() && *l >= 0.0);
            err_or(collision_energy_loss(1.0, 1.0, x, 0.0, 0.5), "collision_energy_loss(u)", |l| l.is_finite() && *l >= 0.0);
            err_or(collision_energy_loss(1.0, 1.0, 1.0, 0.0, x), "collision_energy_loss(e)", |l| l.is_finite() && *l >= 0.0);
            err_or(sphere_collision(1.0, 1.0, &Point::origin(), &Point::at(v([x, 0.0, 0.0])), &v([1.0, 0.0, 0.0]), &Vector::zero(), 1.0), "sphere_collision", |(a, b)| {
                a.is_finite() && b.is_finite() && (*a + *b - v([1.0, 0.0, 0.0])).norm() <= 8.0 * EPS
            });
        }
        // The named bug: m₁ = m₂ = 0 made ΔT = 0/0.
        refused(collision_energy_loss(0.0, 0.0, 1.0, 0.0, 0.5), "collision_energy_loss(0, 0)");
        assert!((collision_energy_loss(1.0, 1.0, 2.0, 0.0, 0.0).unwrap() - 1.0).abs() <= 4.0 * EPS);
        let props = MassProperties::solid_box(2.0, [1.0, 2.0, 3.0], &Frame::new(), Point::origin()).unwrap();
        for x in hostile3() {
            err_or(impulse_response(&props, &Point::at(v([0.5, 0.0, 0.0])), &v(x)), "impulse_response", |(dv, dw)| dv.is_finite() && dw.is_finite());
            err_or(centre_of_percussion(&props, &Point::at(v(x)), &v([0.0, 0.0, 1.0])), "centre_of_percussion", |p| p.is_finite());
            let b1 = body(v([0.0, 0.0, -1.0]), Vector::zero());
            err_or(rigid_impact(&b1, None, &Point::at(v([0.0, 0.0, -1.5])), &v(x), 0.5), "rigid_impact", |i| {
                i.impulse.is_finite() && i.impulse >= 0.0 && i.body1.momentum().is_finite()
            });
        }
    }

    // Energy and power (ch. 8): T ≥ 0 for positive masses; the pairwise form agrees with
    // ½Σm|v − v_c|²; empty inputs give 0.
    energy_power ["particles_kinetic_energy", "kinetic_energy_about_centre_pairwise", "work_along_path", "power"] {
        assert_eq!(particles_kinetic_energy::<f64>(&[]), 0.0);
        assert_eq!(work_along_path::<f64>(&[]), 0.0);
        assert!(kinetic_energy_about_centre_pairwise::<f64>(&[]).abs() == 0.0 || kinetic_energy_about_centre_pairwise::<f64>(&[]).is_nan());
        for x in hostile3().into_iter().filter(|x| finite(x) && x.iter().all(|c| c.abs() <= 1e100)) {
            let ps = [(1.0, v(x)), (2.0, v([0.0, 1.0, 0.0]))];
            let t = particles_kinetic_energy(&ps);
            let tc = kinetic_energy_about_centre_pairwise(&ps);
            assert!(t.is_finite() && t >= 0.0 && tc.is_finite() && tc >= -8.0 * EPS * t && tc <= t * (1.0 + 8.0 * EPS));
            let path = [(v(x), Point::origin()), (v(x), Point::at(v([1.0, 0.0, 0.0])))];
            assert!(work_along_path(&path).is_finite());
            assert!(power(&v(x), &v(x), &v([1.0, 0.0, 0.0]), &v([0.0, 1.0, 0.0])).is_finite());
        }
    }

    // Eigenaxis dynamics, 6D Newton–Euler, networks: singular inertia, NaN and mismatched
    // lengths are typed errors; finite input gives finite accelerations.
    eigenaxis_sixd_network ["eigenaxis_acceleration", "newton_euler_6d", "twist_cross_matrix", "Network::matrices",
        "Network::gamma", "Network::relative_matrices", "Network::accelerations"] {
        let j = Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0));
        for x in hostile3() {
            let t = Vector3::from(x);
            err_or(eigenaxis_acceleration(&j, &t, &Vector3::new(0.1, 0.0, 0.0), &Vector3::zeros()), "eigenaxis_acceleration", |a| a.iter().all(|c| c.is_finite()));
            err_or(eigenaxis_acceleration(&j, &Vector3::new(0.5, 0.0, 0.0), &t, &t), "eigenaxis_acceleration(rates)", |a| a.iter().all(|c| c.is_finite()));
            if finite(&x) && x.iter().all(|c| c.abs() <= 1e100) {
                let si = MassProperties::solid_sphere(1.0, 1.0, Point::origin()).unwrap().spatial_inertia(&Point::origin());
                let (f, m) = newton_euler_6d(&si, &v(x), &v(x), &Vector::zero(), &Vector::zero());
                assert!(f.is_finite() && m.is_finite());
                assert!(twist_cross_matrix(&t, &t).iter().all(|c| c.is_finite()));
            }
        }
        refused(eigenaxis_acceleration(&Matrix3::zeros(), &Vector3::zeros(), &Vector3::zeros(), &Vector3::zeros()), "eigenaxis(singular J)");
        let pair = |i, j, value| Element { i, j: Some(j), value };
        let net = Network { masses: vec![1.0, 2.0], springs: vec![pair(0, 1, 4.0)], dashpots: vec![], inerters: vec![] };
        err_or(net.matrices(), "matrices", |(m, c, k)| m.iter().chain(c.iter()).chain(k.iter()).all(|x| x.is_finite()));
        err_or(net.relative_matrices(), "relative_matrices", |(m, _, _)| m.iter().all(|x| x.is_finite()));
        assert!(net.gamma().iter().all(|x| x.is_finite()));
        err_or(net.accelerations(&[0.0, 1.0], &[0.0, 0.0], &[0.0, 0.0]), "accelerations", |a| a.iter().all(|x| x.is_finite()));
        refused(net.accelerations(&[0.0], &[0.0, 0.0], &[0.0, 0.0]), "accelerations(mismatched q)");
        refused(net.accelerations(&[f64::NAN, 0.0], &[0.0, 0.0], &[0.0, 0.0]), "accelerations(NaN q)");
        for bad in [
            Network { masses: vec![1.0, f64::NAN], ..net.clone() },
            Network { masses: vec![1.0, -1.0], ..net.clone() },
            Network { springs: vec![pair(0, 7, 1.0)], ..net.clone() },
            Network { springs: vec![pair(0, 1, f64::INFINITY)], ..net.clone() },
            Network { springs: vec![pair(0, 0, 1.0)], ..net.clone() },
            Network { masses: vec![], ..net.clone() },
        ] {
            err_or(bad.matrices(), "matrices(bad network)", |(m, c, k)| m.iter().chain(c.iter()).chain(k.iter()).all(|x| x.is_finite()));
        }
    }

    // Impacts in time (§7.13 with events): the Zeno guard bounds the number of impacts, so a
    // ball bouncing with e < 1 ends Zeno instead of hanging; NaN states are refused.
    impacts_in_time ["simulate_with_impacts"] {
        let solver = Adaptive::dopri5().rtol(1e-9).atol(1e-12);
        let ball = |_: f64, y: &Vec<f64>| vec![y[1], -9.81];
        let run = simulate_with_impacts(&solver, ball, |_, y| y[0], |_, y| vec![0.0, -0.5 * y[1]], 0.0, &vec![1.0, 0.0], 100.0, ZenoGuard::default());
        err_or(run, "bouncing ball", |r| matches!(r.end, ImpactEnd::Zeno { .. }) && r.t.is_finite() && r.y.iter().all(|c| c.is_finite()) && r.impacts.len() <= 10_000);
        for x in hostile() {
            let guard = ZenoGuard { min_interval: x, max_impacts: 5 };
            err_or(simulate_with_impacts(&solver, ball, |_, y| y[0], |_, y| vec![0.0, -0.5 * y[1]], 0.0, &vec![1.0, 0.0], 10.0, guard), "guard", |r| r.impacts.len() <= 5);
            err_or(simulate_with_impacts(&solver, ball, |_, y| y[0], |_, y| vec![0.0, -0.5 * y[1]], 0.0, &vec![x, 0.0], 10.0, ZenoGuard::default()), "y0", |r| r.y.iter().all(|c| c.is_finite()));
        }
        refused(simulate_with_impacts(&solver, ball, |_, y| y[0], |_, _y| vec![f64::NAN, 0.0], 0.0, &vec![1.0, -1.0], 10.0, ZenoGuard::default()), "impact map returning NaN");
    }
}
