//! §7.13–7.14: collisions, impulses, the centre of percussion, and Zeno bouncing.

use vectrix::dynamics::{
    ImpactEnd, ZenoGuard, centre_of_percussion, collision_energy_loss, impulse_response, restitution_1d,
    rigid_impact, simulate_with_impacts, sphere_collision,
};
use vectrix::nalgebra::{Matrix3, SVector};
use vectrix::ode::Adaptive;
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point};

use crate::support::{EPS, assert_abs, assert_rel, assert_rel_slice};

/// Fact 7.13.1 (7.13.20–21) and the corrected (7.13.22): "ΔT = ½(1 − e²) m1m2/(m1+m2)(u1 − u2)²"
/// (the printed formula lacks ½, notes errata l.9568). [C]: m1 = 2, m2 = 3, e = 0.6, u1 = 5,
/// u2 = −1 ⇒ u1⁺ = −0.76, u2⁺ = 2.84, ΔT = 13.824 (the printed formula gives 27.648).
#[test]
fn fact_7_13_1_restitution_and_corrected_energy_loss() {
    let (m1, m2, e, u1, u2) = (2.0, 3.0, 0.6, 5.0, -1.0);
    let (a, b) = restitution_1d(m1, m2, u1, u2, e).unwrap();
    assert_abs(a, -0.76, 8.0 * EPS);
    assert_rel(b, 2.84, 8.0 * EPS);
    assert_rel(m1 * a + m2 * b, m1 * u1 + m2 * u2, 8.0 * EPS);
    let lost = 0.5 * m1 * u1 * u1 + 0.5 * m2 * u2 * u2 - 0.5 * m1 * a * a - 0.5 * m2 * b * b;
    assert_rel(lost, 13.824, 16.0 * EPS);
    assert_rel(collision_energy_loss(m1, m2, u1, u2, e).unwrap(), lost, 16.0 * EPS);
    // (7.13.18): e = (u2⁺ − u1⁺)/(u1 − u2)
    assert_abs((b - a) / (u1 - u2), e, 8.0 * EPS);
    assert!(matches!(restitution_1d(m1, m2, -1.0, 5.0, e), Err(DynamicsError::Separating { .. })));
    assert!(matches!(restitution_1d(m1, m2, u1, u2, 1.5), Err(DynamicsError::OutOfRange { .. })));
}

/// §7.13 (7.13.9–10): smooth spheres exchange momentum along the line of centres only; the
/// tangential velocities are unchanged. The rigid-body impact formula reduces to it.
#[test]
fn section_7_13_sphere_collision_and_rigid_impact_agree() {
    let a = Frame::new();
    let (m1, m2, e) = (1.5, 0.5, 0.8);
    let (c1, c2) = (Point::origin(), Point::at(a.vector([1.0, 1.0, 0.0])));
    let (v1, v2) = (a.vector([2.0, 1.0, 0.5]), a.vector([-1.0, 0.0, 0.3]));
    let (w1, w2) = sphere_collision(m1, m2, &c1, &c2, &v1, &v2, e).unwrap();
    let n = c2.position_rel(&c1).unit().unwrap();
    for (x, y) in [(v1, w1), (v2, w2)] {
        let t0 = x - n * x.dot(&n);
        let t1 = y - n * y.dot(&n);
        assert!((t0 - t1).norm() <= 8.0 * EPS * 3.0);
    }
    assert!(((v1 * m1 + v2 * m2) - (w1 * m1 + w2 * m2)).norm() <= 16.0 * EPS * 5.0);
    // the same impact between rigid spheres (radius 1/√2 each), contact at the midpoint
    let sphere = |m: f64, c: Point| MassProperties::solid_sphere(m, 0.5f64.sqrt(), c).unwrap();
    let b1 = RigidBody::new(sphere(m1, c1), v1, a.vector([0.0, 0.0, 3.0]));
    let b2 = RigidBody::new(sphere(m2, c2), v2, a.vector([1.0, 0.0, 0.0]));
    let contact = Point::at(a.vector([0.5, 0.5, 0.0]));
    let imp = rigid_impact(&b1, Some(&b2), &contact, &n, e).unwrap();
    // central impact on spheres: spin plays no part in the normal direction
    assert_rel_slice(imp.body1.v_c.resolve(&a).as_slice(), w1.resolve(&a).as_slice(), 64.0 * EPS);
    assert_rel_slice(imp.body2.unwrap().v_c.resolve(&a).as_slice(), w2.resolve(&a).as_slice(), 64.0 * EPS);
}

/// Ex 7.14.2 (dumbbell m1 at y1, m2 at y2 = y1 + ℓî, impulse along ĵ at ℓ_P from y1):
/// "r_{R/c} = m1m2ℓ²/((m1+m2)²(ℓ_c − ℓ_P)) î" (the printed ℓ_P k̂ is an erratum, l.9626).
/// [C] m1 = 1, m2 = 2, ℓ = 3, ℓ_P = 1: ℓ_c = 2, r_{R/c} = +2î, v_R(0⁺) = 0.
#[test]
fn example_7_14_2_dumbbell_centre_of_percussion() {
    let a = Frame::new();
    let props = MassProperties::from_particles(&[
        (1.0, Point::origin()),
        (2.0, Point::at(a.vector([3.0, 0.0, 0.0]))),
    ])
    .unwrap();
    let p = Point::at(a.vector([1.0, 0.0, 0.0]));
    let r = centre_of_percussion(&props, &p, &a.j()).unwrap();
    assert_rel_slice(
        r.position_rel(&props.centre_of_mass()).resolve(&a).as_slice(),
        &[2.0, 0.0, 0.0],
        16.0 * EPS,
    );
    // the body at rest is hit: R does not move just after the impulse (7.14.2–3)
    let (dv, dw) = impulse_response(&props, &p, &(a.j() * 4.0)).unwrap();
    let v_r = dv + dw.cross(&r.position_rel(&props.centre_of_mass()));
    assert!(v_r.norm() <= 16.0 * EPS * 4.0, "{v_r:?}");
    // an impulse through c has no centre of percussion
    assert!(matches!(
        centre_of_percussion(&props, &props.centre_of_mass(), &a.j()),
        Err(DynamicsError::NoPercussionCentre { .. })
    ));
}

/// Ex 7.14.3 (uniform bar of length ℓ): "r_{R/c} = ℓ²/(12(ℓ/2 − ℓ_P)) î"; struck at ℓ_P = 2ℓ/3
/// the bar turns about its end y1 (r_{R/c} = −ℓ/2 î).
#[test]
fn example_7_14_3_bar_centre_of_percussion() {
    let a = Frame::new();
    let l = 1.8;
    let bar =
        MassProperties::thin_rod_between(2.5, &Point::origin(), &Point::at(a.vector([l, 0.0, 0.0]))).unwrap();
    for lp in [0.1, 0.3, 2.0 * l / 3.0, 1.7] {
        let r = centre_of_percussion(&bar, &Point::at(a.vector([lp, 0.0, 0.0])), &a.j()).unwrap();
        let want = l * l / (12.0 * (l / 2.0 - lp));
        assert_abs(r.position_rel(&bar.centre_of_mass()).resolve(&a).x, want, 64.0 * EPS);
    }
    let r = centre_of_percussion(&bar, &Point::at(a.vector([2.0 * l / 3.0, 0.0, 0.0])), &a.j()).unwrap();
    assert_abs(r.position_rel(&Point::origin()).norm(), 0.0, 64.0 * EPS);
}

/// §7.13 with events: a ball dropped from h0 bounces with restitution e; the impacts accumulate
/// at t∞ = t1(1 + e)/(1 − e), t1 = √(2h0/g) (Zeno). The impacts are located through the
/// integrator's events and the guard stops the run near t∞ instead of looping forever.
#[test]
fn section_7_13_bouncing_ball_zeno_protection() {
    let (h0, g, e) = (1.0, 9.81, 0.5);
    let f = |_t: f64, y: &SVector<f64, 2>| SVector::<f64, 2>::new(y[1], -g);
    let gap = |_t: f64, y: &SVector<f64, 2>| y[0];
    let bounce = |_t: f64, y: &SVector<f64, 2>| SVector::<f64, 2>::new(0.0, -e * y[1]);
    let guard = ZenoGuard { min_interval: 1e-4, max_impacts: 1000 };
    let solver = Adaptive::dop853().rtol(1e-12).atol(1e-12);
    let run =
        simulate_with_impacts(&solver, f, gap, bounce, 0.0, &SVector::<f64, 2>::new(h0, 0.0), 10.0, guard)
            .unwrap();
    let t1 = (2.0 * h0 / g).sqrt();
    let t_inf = t1 * (1.0 + e) / (1.0 - e);
    let ImpactEnd::Zeno { t } = run.end else { panic!("no Zeno detected: {:?}", run.end) };
    // the remaining flights after an interval < 1e-4 sum to < 1e-4 e/(1 − e)
    assert!((t - t_inf).abs() < 2e-4, "{t} vs {t_inf}");
    // the impact time is an event located by the integrator (rtol, atol 1e-12) to ~1e-11
    assert_abs(run.impacts[0].0, t1, 1e-10);
    // impact speeds shrink by e each bounce (each speed carries the integration error)
    for w in run.impacts.windows(2).take(8) {
        assert_abs(w[1].1[1] / w[0].1[1], e, 1e-8);
    }
}

/// Bad impulse input is refused: torque about a thin rod's own axis, zero normals.
#[test]
fn impulses_reject_bad_input() {
    let a = Frame::new();
    let rod = MassProperties::thin_rod(1.0, 2.0, &a.i(), Point::origin()).unwrap();
    let body = RigidBody::new(rod, a.vector([0.0, 0.0, -1.0]), Vector::zero());
    let contact = Point::at(a.vector([0.5, 0.0, 0.0]));
    assert!(matches!(
        rigid_impact(&body, None, &contact, &Vector::zero(), 0.5),
        Err(DynamicsError::OutOfRange { .. })
    ));
    // approaching the ground along −k̂ with normal k̂ pointing from body to ground: separating
    assert!(matches!(
        rigid_impact(&body, None, &contact, &a.k(), 0.5),
        Err(DynamicsError::Separating { .. })
    ));
    let imp = rigid_impact(&body, None, &contact, &(-a.k()), 0.5).unwrap();
    assert!(imp.impulse > 0.0);
    let _ = Matrix3::<f64>::zeros();
}
