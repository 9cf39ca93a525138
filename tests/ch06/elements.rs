//! §6.7–6.8, §6.12–6.13, §7.12 and Problem 6.14.4: springs, dashpots, inerters, gravity,
//! the centre of gravity and magnetic dipoles.

use vectrix::num_dual::Dual2_64;
use vectrix::prelude::*;
use vectrix::statics::{
    CentralGravity, Dashpot, GRAVITATIONAL_CONSTANT, Inerter, MutualGravitation, Point, RotationalDashpot,
    RotationalInerter, RotationalSpring, Spring, StaticsError, UniformGravity, centre_of_gravity,
    dipole_field, dipole_field_dyadic, dipole_interaction, gravity_between, mutual_gravitation,
    mutual_gravitation_potential,
};

use crate::common::{assert_vec_abs, assert_vec_rel, pt};
use crate::support::{EPS, assert_abs, assert_abs_slice, assert_printed, assert_rel};

#[test]
fn eq_6_7_1_spring_force_and_third_law() {
    // (6.7.1) f⃗_{y/w} = −k(|r⃗| − d) r̂: extension pulls y toward w, compression pushes it away;
    // (6.7.2) f⃗_{w/y} = −f⃗_{y/w}; (6.7.3) d = 0 ⇒ −k r⃗, defined even at r⃗ = 0⃗.
    let a = Frame::new();
    let s = Spring::new(10.0, 2.0).unwrap();
    let ext = s.forces(&a.vector([3.0, 0.0, 0.0])).unwrap();
    assert_vec_rel(&ext.on_y, &a.vector([-10.0, 0.0, 0.0]), EPS);
    assert_vec_rel(&ext.on_w, &a.vector([10.0, 0.0, 0.0]), EPS);
    let comp = s.force(&a.vector([0.0, 1.0, 0.0])).unwrap();
    assert_vec_rel(&comp, &a.vector([0.0, 10.0, 0.0]), EPS);
    let zero_len = Spring::new(4.0, 0.0).unwrap();
    assert_vec_rel(&zero_len.force(&a.vector([1.0, -2.0, 0.5])).unwrap(), &a.vector([-4.0, 8.0, -2.0]), EPS);
    assert_vec_abs(&zero_len.force(&Vector::zero()).unwrap(), &Vector::zero(), 0.0);
    assert!(matches!(s.force(&Vector::zero()), Err(StaticsError::CoincidentPoints { .. })));
    assert!(matches!(Spring::new(-1.0, 0.0), Err(StaticsError::OutOfRange { .. })));
    assert!(matches!(s.force(&a.vector([f64::NAN, 0.0, 0.0])), Err(StaticsError::NonFinite { .. })));
    // (8.3.12): U = ½k(|r| − d)²
    assert_rel(s.potential(&a.vector([0.0, 0.0, 3.5])), 0.5 * 10.0 * 1.5 * 1.5, EPS);
}

#[test]
fn eq_6_7_4_rotational_spring() {
    // (6.7.4) M⃗_{B1/B2} = −κ(θ_{x̂1/x̂2/ẑ} − θ₀)ẑ; (6.7.5) M⃗_{B2/B1} = −M⃗_{B1/B2}.
    let a = Frame::new();
    let k = RotationalSpring::new(2.0, 0.1).unwrap();
    let th = 0.6f64;
    let x1 = a.vector([th.cos(), th.sin(), 0.0]);
    let (m1, m2) = k.torques(&x1, &a.i(), &a.k()).unwrap();
    assert_vec_abs(&m1, &(a.k() * (-2.0 * (th - 0.1))), 16.0 * EPS);
    assert_vec_abs(&m2, &(-m1), 0.0);
    // About −ẑ the angle changes sign and so does the torque direction: same physical torque.
    let (m1b, _) = k.torques(&x1, &a.i(), &(-a.k())).unwrap();
    let (m1c, _) = RotationalSpring::new(2.0, -0.1).unwrap().torques(&x1, &a.i(), &(-a.k())).unwrap();
    assert_vec_abs(&m1c, &m1, 16.0 * EPS);
    assert!(m1b.norm() > 0.0);
    assert_abs(k.potential_at_angle(th), 0.5 * 2.0 * 0.25, 16.0 * EPS);
    assert!(matches!(k.torques(&x1, &a.i(), &Vector::zero()), Err(StaticsError::ZeroVector { .. })));
}

#[test]
fn eq_6_8_1_dashpot_and_erratum_6_8_3_rotational_dashpot() {
    // (6.8.1) f⃗_{y/w} = −c (d/dt|r⃗|) r̂: opposes the rate of extension, only along r̂.
    let a = Frame::new();
    let c = Dashpot::new(3.0).unwrap();
    let r = a.vector([2.0, 0.0, 0.0]);
    let v = a.vector([0.5, 7.0, 0.0]); // the transverse part does not change |r|
    let pair = c.forces(&r, &v).unwrap();
    assert_vec_rel(&pair.on_y, &a.vector([-1.5, 0.0, 0.0]), EPS);
    assert_vec_rel(&pair.on_w, &a.vector([1.5, 0.0, 0.0]), EPS);
    assert_abs(c.dissipation(&r, &v).unwrap(), 3.0 * 0.25, EPS);
    assert!(matches!(c.force(&Vector::zero(), &v), Err(StaticsError::CoincidentPoints { .. })));
    // (6.8.3) ERRATUM: the printed −γ (d/dt|θ|) ẑ must read −ξ θ̇ ẑ (7.12.5): the torque
    // opposes the rotation whatever the sign of θ. With θ < 0 and θ̇ > 0, d|θ|/dt = −θ̇ would
    // give the wrong sign.
    let d = RotationalDashpot::new(0.5).unwrap();
    let omega = a.k() * 2.0; // θ̇ = 2 about ẑ
    let (m1, m2) = d.torques(&omega, &a.k()).unwrap();
    assert_vec_abs(&m1, &(a.k() * -1.0), EPS);
    assert_vec_abs(&m2, &a.k(), EPS);
}

#[test]
fn eq_7_12_3_inerter_second_derivative_of_length() {
    // (7.12.3) f⃗_{y/w} = −b (d²/dt²|r⃗|) r̂. The second derivative of |r(t)| for
    // r(t) = r₀ + v t + ½a t² is computed exactly with second-order dual numbers and compared.
    let a = Frame::new();
    let (r0, v, acc) = ([1.0, 2.0, -0.5], [0.3, -1.0, 0.8], [2.0, 0.1, -0.4]);
    let t = Dual2_64::new(0.0, 1.0, 0.0);
    let fd = Frame::<Dual2_64>::identity();
    let comp = |k: usize| t * t * (0.5 * acc[k]) + t * v[k] + r0[k];
    let len = fd.vector([comp(0), comp(1), comp(2)]).norm();
    let len_dd = len.v2; // Dual2: v2 is the exact second derivative
    let b = Inerter::new(1.5).unwrap();
    let (r, vv, aa) = (a.vector(r0), a.vector(v), a.vector(acc));
    let f = b.force(&r, &vv, &aa).unwrap();
    let r_hat = r.unit().unwrap();
    assert_vec_rel(&f, &(r_hat * (-1.5 * len_dd)), 64.0 * EPS);
    // (7.12.4) third law; acceleration-dependent part b r̂r̂′.
    let pair = b.forces(&r, &vv, &aa).unwrap();
    assert_vec_abs(&(pair.on_y + pair.on_w), &Vector::zero(), 0.0);
    let bm = b.mass_dyadic(&r).unwrap();
    let f_no_acc = b.force(&r, &vv, &Vector::zero()).unwrap();
    assert_vec_rel(&(f_no_acc - bm.apply(&aa)), &f, 64.0 * EPS);
    // (7.12.7) rotational inerter −β θ̈ ẑ.
    let (m1, m2) = RotationalInerter::new(0.2).unwrap().torques(5.0, &a.k()).unwrap();
    assert_vec_abs(&m1, &(a.k() * -1.0), EPS);
    assert_vec_abs(&m2, &a.k(), EPS);
}

#[test]
fn fact_6_6_1_and_erratum_fact_8_3_2_weight_is_plus_mg() {
    // Fact 6.6.1: f⃗ = m g⃗. ERRATUM Fact 8.3.2 prints f = −mg; with U = −m r⃗·g⃗ (8.3.9) the
    // force −∂U/∂r⃗ is +m g⃗.
    let a = Frame::new();
    let g = UniformGravity::new(a.vector([0.0, 0.0, -9.81])).unwrap();
    assert_vec_rel(&g.force(2.0), &a.vector([0.0, 0.0, -19.62]), EPS);
    // U decreases by m|g|h when the body falls by h.
    let (u_hi, u_lo) =
        (g.potential(2.0, &a.vector([0.0, 0.0, 1.0])), g.potential(2.0, &a.vector([0.0, 0.0, 0.0])));
    assert_rel(u_hi - u_lo, 19.62, 16.0 * EPS);
}

#[test]
fn fact_6_12_1_central_gravity_and_erratum_6_12_2() {
    // (6.12.1) f⃗_{y/x} = (G M m/|r⃗|²) r̂_{x/y}. ERRATUM (6.12.2): G = 6.67428 × 10⁻¹¹ (the factor
    // 10⁻¹¹ is missing in print); vectrix uses CODATA 2018, 6.67430 × 10⁻¹¹.
    assert_eq!(GRAVITATIONAL_CONSTANT, 6.674_30e-11);
    let a = Frame::new();
    let earth = CentralGravity::of_mass(5.972e24).unwrap();
    let r = a.vector([6.371e6, 0.0, 0.0]);
    let f = earth.force(1.0, &r).unwrap();
    // g at the surface = GM/r² exactly (≈ 9.82 m/s²), toward the centre.
    let g = GRAVITATIONAL_CONSTANT * 5.972e24 / (6.371e6 * 6.371e6);
    assert_rel(-f.dot(&a.i()), g, 8.0 * EPS);
    assert_printed(-f.dot(&a.i()), "9.82");
    assert_abs_slice(&f.resolve(&a).as_slice()[1..], &[0.0, 0.0], 0.0);
    let pair = mutual_gravitation(GRAVITATIONAL_CONSTANT, 1.0, 5.972e24, &r).unwrap();
    assert_vec_rel(&pair.on_y, &f, 16.0 * EPS);
    assert_vec_abs(&(pair.on_y + pair.on_w), &Vector::zero(), 0.0);
    assert!(matches!(earth.force(1.0, &Vector::zero()), Err(StaticsError::CoincidentPoints { .. })));
    assert!(matches!(earth.force(-1.0, &r), Err(StaticsError::InvalidMass { .. })));
    assert!(matches!(CentralGravity::new(f64::NAN), Err(StaticsError::OutOfRange { .. })));
}

#[test]
fn fact_6_12_1_mutual_gravitation_prepared_once() {
    // (6.12.1) with G M m checked once: f⃗_{y/x} = −G M m r⃗/|r⃗|³, f⃗_{x/y} = −f⃗_{y/x}. The closed
    // form at |r⃗| = 5 (a 3-4-5 separation) is −G M m (3, 4, 0)/125; at the ends of the range
    // (|r⃗| = 5e±120, where |r⃗|³ leaves the normal numbers) the force is still exact to a few ε
    // and not flushed to 0 or ∞.
    let a = Frame::new();
    let (g, m, big_m) = (GRAVITATIONAL_CONSTANT, 70.0, 5.972e24);
    let pair = MutualGravitation::new(g, m, big_m).unwrap();
    assert_eq!(pair.gmm(), g * big_m * m);
    for scale in [1.0, 1e-120, 1e120, 1e-99, 1e99] {
        let r = a.vector([3.0 * scale, 4.0 * scale, 0.0]);
        let f = pair.force_on_y(&r).unwrap();
        // −G M m r̂/|r⃗|² with r̂ = (0.6, 0.8, 0) and |r⃗|² = 25 scale²
        let k = -(g * big_m * m) / (25.0 * scale * scale);
        let want = a.vector([0.6 * k, 0.8 * k, 0.0]);
        assert!(f.is_finite() && f.norm() > 0.0, "scale {scale:e}");
        assert_vec_rel(&f, &want, 8.0 * EPS);
        // the checked call is this pair, checked again: the same bits
        assert_eq!(mutual_gravitation(g, m, big_m, &r).unwrap().on_y, f, "scale {scale:e}");
    }
    // (8.3.10) U = −G M m/|r⃗| at |r⃗| = 5, and the checked call is this pair's potential
    let r = a.vector([3.0, 4.0, 0.0]);
    assert_rel(pair.potential(&r).unwrap(), -(g * big_m * m) / 5.0, 2.0 * EPS);
    assert_eq!(mutual_gravitation_potential(g, m, big_m, &r).unwrap(), pair.potential(&r).unwrap());
    assert!(matches!(pair.potential(&Vector::zero()), Err(StaticsError::CoincidentPoints { .. })));
    assert!(matches!(
        mutual_gravitation_potential(g, -1.0, big_m, &r),
        Err(StaticsError::InvalidMass { .. })
    ));
    // over the scalar of dual numbers: the same value, checked once in f64
    assert_eq!(pair.cast::<f64>().force_on_y(&r).unwrap(), pair.force_on_y(&r).unwrap());
    // bad input: typed errors, never NaN or a silent zero
    assert!(matches!(MutualGravitation::new(-1.0, m, big_m), Err(StaticsError::OutOfRange { .. })));
    assert!(matches!(MutualGravitation::new(f64::NAN, m, big_m), Err(StaticsError::OutOfRange { .. })));
    assert!(matches!(MutualGravitation::new(g, -1.0, big_m), Err(StaticsError::InvalidMass { .. })));
    assert!(matches!(MutualGravitation::new(g, m, f64::INFINITY), Err(StaticsError::InvalidMass { .. })));
    assert!(matches!(MutualGravitation::new(1e300, 1e10, 1e10), Err(StaticsError::Overflow { .. })));
    assert!(matches!(pair.force_on_y(&Vector::zero()), Err(StaticsError::CoincidentPoints { .. })));
    assert!(matches!(pair.force_on_y(&a.vector([f64::NAN, 0.0, 1.0])), Err(StaticsError::NonFinite { .. })));
    let close = MutualGravitation::new(1.0, 1e300, 1.0).unwrap();
    assert!(matches!(close.force_on_y(&a.vector([1e-10, 0.0, 0.0])), Err(StaticsError::Overflow { .. })));
}

/// A body as (mass, position) particles.
type Particles = Vec<(f64, Point)>;

fn dumbbell_and_particle(l1: f64, l2: f64) -> (Particles, Particles) {
    // P6.14.4: y at the origin, y1 at distance ℓ1 along î, y2 at ℓ2 along ĵ, so |y1y2|² = ℓ1² + ℓ2².
    let a = Frame::new();
    (vec![(1.0, pt(&a, [l1, 0.0, 0.0])), (2.0, pt(&a, [0.0, l2, 0.0]))], vec![(5.0, Point::origin())])
}

#[test]
fn problem_6_14_4_third_law_not_through_centre_of_mass_or_gravity() {
    // P6.14.4: f⃗_y = −f⃗_B (Fact 6.9.2), but f⃗_y is aligned with c or g iff ℓ1 = ℓ2.
    let g = 1.0; // G cancels in every claim
    for (l1, l2, aligned) in [(3.0, 4.0, false), (2.0, 2.0, true)] {
        let (body, y) = dumbbell_and_particle(l1, l2);
        let (f_b, _) = gravity_between(g, &body, &y).unwrap();
        let (f_y, _) = gravity_between(g, &y, &body).unwrap();
        assert_vec_abs(&(f_b + f_y), &Vector::zero(), 16.0 * EPS);
        let c = vectrix::statics::MassProperties::from_particles(&body).unwrap().centre_of_mass();
        let gc = centre_of_gravity(&body, &y).unwrap();
        let r_c = c.position_rel(&y[0].1);
        let r_g = gc.position_rel(&y[0].1);
        let sin_c = f_y.cross(&r_c).norm() / (f_y.norm() * r_c.norm());
        let sin_g = f_y.cross(&r_g).norm() / (f_y.norm() * r_g.norm());
        if aligned {
            assert!(sin_c <= 16.0 * EPS && sin_g <= 16.0 * EPS);
            assert_vec_rel(&gc.position(), &c.position(), 16.0 * EPS);
        } else {
            assert!(sin_c > 0.01 && sin_g > 0.01, "sin to c {sin_c}, to g {sin_g}");
        }
    }
}

#[test]
fn fact_6_12_2_centre_of_gravity_independent_of_reference_point() {
    // Fact 6.12.2: g does not depend on the reference point w.
    let a = Frame::new();
    let b2 =
        [(1.0, pt(&a, [10.0, 0.0, 0.0])), (3.0, pt(&a, [11.0, 1.0, 0.0])), (2.0, pt(&a, [10.5, -1.0, 1.0]))];
    let b1 = [(100.0, Point::origin()), (50.0, pt(&a, [0.0, 2.0, 0.0]))];
    let g = centre_of_gravity(&b2, &b1).unwrap();
    let d = a.vector([-3.0, 7.0, 1.0]);
    let shift = |b: &[(f64, Point)]| b.iter().map(|(m, p)| (*m, p.displaced(d))).collect::<Vec<_>>();
    let g2 = centre_of_gravity(&shift(&b2), &shift(&b1)).unwrap();
    assert_vec_rel(&(g2.position() - d), &g.position(), 64.0 * EPS);
    // (6.12.11): Σ w_i r⃗_{y_i/g} = 0⃗.
    let s = b2.iter().fold(Vector::zero(), |s, (m, y)| {
        let (_, w) = gravity_between(1.0, &[(*m, *y)], &b1).unwrap();
        s + y.position_rel(&g) * w
    });
    assert!(s.norm() <= 1e3 * EPS, "{}", s.norm());
}

#[test]
fn fact_6_12_5_6_12_6_centre_of_gravity_and_centre_of_mass() {
    // Fact 6.12.5: equal distances ⇒ g = c. Fact 6.12.6: g → c as the bodies separate,
    // |r⃗_{c/g}| decreasing like 1/distance.
    let a = Frame::new();
    let on_sphere =
        [(1.0, pt(&a, [2.0, 0.0, 0.0])), (4.0, pt(&a, [0.0, 2.0, 0.0])), (2.0, pt(&a, [0.0, 0.0, -2.0]))];
    let c = vectrix::statics::MassProperties::from_particles(&on_sphere).unwrap().centre_of_mass();
    let g = centre_of_gravity(&on_sphere, &[(9.0, Point::origin())]).unwrap();
    assert_vec_rel(&g.position(), &c.position(), 16.0 * EPS);
    let body =
        [(1.0, pt(&a, [0.0, 0.0, 0.0])), (2.0, pt(&a, [1.0, 0.0, 0.0])), (1.0, pt(&a, [0.0, 1.0, 0.0]))];
    let c = vectrix::statics::MassProperties::from_particles(&body).unwrap().centre_of_mass();
    let gap = |d: f64| centre_of_gravity(&body, &[(1.0, pt(&a, [-d, -0.3 * d, 0.0]))]).unwrap().distance(&c);
    let (g10, g100, g1000) = (gap(10.0), gap(100.0), gap(1000.0));
    assert!(g100 < g10 && g1000 < g100);
    assert_rel(g100 / g1000, 10.0, 0.02); // 1/d asymptotics, O(1/d) correction at d = 100
}

#[test]
fn example_6_13_2_dipole_field_and_force() {
    // Ex 6.13.2: m⃗_y = m_y î, m⃗_z = m_z ĵ, r⃗_{z/y} = r î: B⃗_y = 2m_y/r³ î (6.13.16),
    // f⃗_{z/y} = 3 m_y m_z/r⁴ ĵ (6.13.17). Numbers m_y = 2, m_z = 3, r = 2: B = 0.5 î, f = 1.125 ĵ.
    let a = Frame::new();
    let (my, mz, r) = (a.i() * 2.0, a.j() * 3.0, a.i() * 2.0);
    assert_vec_abs(&dipole_field(&my, &r).unwrap(), &(a.i() * 0.5), EPS);
    let p = dipole_interaction(&mz, &my, &r).unwrap();
    assert_vec_rel(&p.force_on_z, &(a.j() * 1.125), EPS);
    assert_vec_rel(&p.force_on_y, &(a.j() * -1.125), EPS);
    // (6.13.8): the field dyadic is traceless and symmetric.
    let jd = dipole_field_dyadic(&a.vector([0.3, -1.0, 2.0])).unwrap();
    assert!(jd.trace().abs() <= 16.0 * EPS);
    assert!((jd - jd.coform()).norm() <= 16.0 * EPS);
    // Fact 6.13.1: not collinear with r̂.
    assert!(p.force_on_z.cross(&r).norm() > 1.0);
    assert!(matches!(
        dipole_interaction(&mz, &my, &Vector::zero()),
        Err(StaticsError::CoincidentPoints { .. })
    ));
}

#[test]
fn example_6_13_7_dipole_torques() {
    // Ex 6.13.7: τ⃗_{z/y} = −2m_y m_z/r³ k̂, τ⃗_{y/z} = −m_y m_z/r³ k̂, τ⃗_f = 3m_y m_z/r³ k̂, sum 0⃗
    // (6.13.19). Numbers: −1.5 k̂, −0.75 k̂, 2.25 k̂.
    let a = Frame::new();
    let p = dipole_interaction(&(a.j() * 3.0), &(a.i() * 2.0), &(a.i() * 2.0)).unwrap();
    assert_vec_rel(&p.torque_on_z, &(a.k() * -1.5), EPS);
    assert_vec_abs(&p.torque_on_y, &(a.k() * -0.75), EPS);
    assert_vec_rel(&p.force_pair_torque, &(a.k() * 2.25), EPS);
    assert_vec_abs(&(p.torque_on_z + p.torque_on_y + p.force_pair_torque), &Vector::zero(), 4.0 * EPS);
}

#[test]
fn fact_6_13_3_6_13_6_dipole_body_has_no_net_force_or_torque() {
    // Facts 6.13.3 and 6.13.6: a body of dipoles has zero net magnetic force and, counting the
    // moments of the forces about any point x (Fact 6.13.5), zero net torque.
    let a = Frame::new();
    let dip = [
        (a.vector([1.0, 0.0, 0.5]), pt(&a, [0.0, 0.0, 0.0])),
        (a.vector([0.0, -2.0, 1.0]), pt(&a, [1.0, 0.5, 0.0])),
        (a.vector([0.3, 0.3, -1.0]), pt(&a, [-0.5, 1.0, 1.5])),
        (a.vector([-1.0, 1.0, 1.0]), pt(&a, [0.2, -1.0, 0.7])),
    ];
    let x = pt(&a, [3.0, -2.0, 1.0]);
    let (mut f, mut t) = (Vector::zero(), Vector::zero());
    for (i, (mi, yi)) in dip.iter().enumerate() {
        for (j, (mj, yj)) in dip.iter().enumerate() {
            if i != j {
                let p = dipole_interaction(mi, mj, &yi.position_rel(yj)).unwrap();
                f += p.force_on_z;
                t += p.torque_on_z + yi.position_rel(&x).cross(&p.force_on_z);
            }
        }
    }
    assert!(f.norm() <= 64.0 * EPS && t.norm() <= 256.0 * EPS, "|f| = {}, |τ| = {}", f.norm(), t.norm());
}
