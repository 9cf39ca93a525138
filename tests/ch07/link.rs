//! Examples 7.8.8–7.8.11: bodies joined by massless links. Ex 7.8.8 prints its equations of
//! motion and reactions; Ex 7.8.9–7.8.11 only state the task, and are solved here the way Ex
//! 7.8.8 is: Euler's equation for the whole, free bodies for the reactions, and the massless
//! link in equilibrium as the check.

use vectrix::dynamics::multibody::{Joint, JointWrench, Link, Model};
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;
use vectrix::statics::{AppliedForce, MassProperties, Point, Wrench};

use crate::support::{EPS, NanAmax, assert_abs, assert_abs_slice, assert_rel};

/// a⃗ of a point of a rigid body: a⃗_c + α⃗ × r⃗ + ω⃗ × (ω⃗ × r⃗), r⃗ from c (4.5.3).
fn point_acceleration(a_c: &Vector, alpha: &Vector, omega: &Vector, r_from_c: &Vector) -> Vector {
    *a_c + alpha.cross(r_from_c) + omega.cross(&omega.cross(r_from_c))
}

/// Ex 7.8.8: particles y₁, y₂ (m₁, m₂) on a massless link of length ℓ along t̂_B = î_B, a force
/// f⃗ = f₁î_B + f₂ĵ_B at z, ℓ₀ from y₁, planar motion with F_A →θ F_B. Printed:
/// m_B[ẍ_c ÿ_c z̈_c] = 𝓞_{A/B}[f₁ f₂ 0] (7.8.23); J⃗_{B/c} = (m₁m₂ℓ²/m_B)(ĵĵ′ + k̂k̂′) (7.8.25);
/// m₁m₂ℓ²θ̈ = (m_Bℓ₀ − m₂ℓ)f₂ (7.8.27); f_R11 = (m₁/m_B)f₁ + m₁m₂ℓθ̇²/m_B (7.8.31),
/// f_R12 = (ℓ − ℓ₀)f₂/ℓ (7.8.33), f_R21 = (m₂/m_B)f₁ − m₁m₂ℓθ̇²/m_B (7.8.37), f_R22 = ℓ₀f₂/ℓ (7.8.39);
/// f⃗ = f⃗_R1 + f⃗_R2 (7.8.40) and the link's moment about y₁ is zero (7.8.43); with ℓ₀ = 0,
/// m₁ℓθ̈ = −f₂ (7.8.45), f_R12 = f₂, f_R22 = 0 (7.8.46), f⃗_{x₁} = (m₂/m_B)(f₁ − m₁ℓθ̇²)î_B (7.8.47).
#[test]
fn example_7_8_8_dumbbell_pushed_on_its_link() {
    let a = Frame::new();
    let (m1, m2, l) = (1.2, 0.8, 1.5);
    let mb = m1 + m2;
    let (th, thd) = (0.7f64, -1.1);
    let (f1, f2) = (0.9, 2.3);
    let o_ab = Matrix3::new(th.cos(), -th.sin(), 0.0, th.sin(), th.cos(), 0.0, 0.0, 0.0, 1.0);
    let b = Frame::from_orientation_rel(&a, &o_ab.transpose(), 1e-12).unwrap();
    let y1 = Point::at(a.vector([0.3, -0.2, 0.0]));
    let y2 = y1.displaced(b.i() * l);
    let body = MassProperties::from_particles(&[(m1, y1), (m2, y2)]).unwrap();
    let c = body.centre_of_mass();
    // (7.8.25)
    let j_want = (b.j().outer(&b.j()) + b.k().outer(&b.k())) * (m1 * m2 * l * l / mb);
    assert_abs_slice(
        body.inertia_about_centre().resolve(&a).as_slice(),
        j_want.resolve(&a).as_slice(),
        16.0 * EPS * m1 * m2 * l * l / mb,
    );
    let f = b.vector([f1, f2, 0.0]);
    let omega = a.k() * thd;
    let rb = RigidBody::new(body, a.vector([0.4, 0.1, 0.0]), omega);
    for l0 in [0.4, 0.0] {
        let z = y1.displaced(b.i() * l0);
        let (a_c, alpha) = rb.accelerations(&Wrench::from_force(&AppliedForce::new(f, z), c)).unwrap();
        // (7.8.23)
        let want_ac = o_ab * Vector3::new(f1, f2, 0.0) / mb;
        assert_abs_slice(a_c.resolve(&a).as_slice(), want_ac.as_slice(), 8.0 * EPS * f.norm() / mb);
        // (7.8.27)
        let thdd = alpha.dot(&a.k());
        assert_abs(m1 * m2 * l * l * thdd, (mb * l0 - m2 * l) * f2, 16.0 * EPS * mb * l * f.norm());
        // the reactions are the particles' m a (the link is the only other force on them)
        let f_r1 = point_acceleration(&a_c, &alpha, &omega, &y1.position_rel(&c)) * m1;
        let f_r2 = point_acceleration(&a_c, &alpha, &omega, &y2.position_rel(&c)) * m2;
        let (r1, r2) = (f_r1.resolve(&b), f_r2.resolve(&b));
        let scale = f.norm() + m1 * m2 * l * thd * thd / mb;
        let tol = 32.0 * EPS * scale;
        assert_abs(r1[0], m1 / mb * f1 + m1 * m2 * l * thd * thd / mb, tol); // (7.8.31)
        assert_abs(r1[1], (l - l0) / l * f2, tol); // (7.8.33)
        assert_abs(r2[0], m2 / mb * f1 - m1 * m2 * l * thd * thd / mb, tol); // (7.8.37)
        assert_abs(r2[1], l0 / l * f2, tol); // (7.8.39)
        assert!((f_r1 + f_r2 - f).norm() <= tol); // (7.8.40)
        // (7.8.43): the link (forces f at z, −f_R1 at y₁, −f_R2 at y₂) has no moment about y₁
        let m_link = z.position_rel(&y1).cross(&f) + y2.position_rel(&y1).cross(&(-f_r2));
        assert!(m_link.norm() <= tol * l);
        if l0 == 0.0 {
            assert_abs(m1 * l * thdd, -f2, tol); // (7.8.45)
            let f_x1 = (f - f_r1).resolve(&b);
            assert_abs(f_x1[0], m2 / mb * (f1 - m1 * l * thd * thd), tol); // (7.8.47)
            assert_abs(f_x1[1], 0.0, tol);
        }
    }
}

/// Ex 7.8.9: two rigid bodies, welded to the ends x₁, x₂ of a massless link, their centres c₁, c₂
/// offset from the link; 3D motion; f⃗ on body 1. Equations of motion: the composite body's
/// m_B a⃗_c = f⃗ and Euler's equation J⃗_{B/c}α⃗ + ω⃗ × J⃗_{B/c}ω⃗ = r⃗_{p/c} × f⃗. Reactions: the
/// link's force and couple on each body from its own Newton–Euler equations,
/// F⃗₂ = m₂a⃗_{c₂}, C⃗₂ = J⃗₂α⃗ + ω⃗ × J⃗₂ω⃗ − r⃗_{x₂/c₂} × F⃗₂, and likewise for body 1 with f⃗. Check:
/// the massless link is in equilibrium, F⃗₁ + F⃗₂ = 0 and the moments about x₁ cancel, which holds
/// only with the right α⃗.
#[test]
fn example_7_8_9_two_rigid_bodies_on_a_massless_link() {
    let a = Frame::new();
    let (x1, x2) = (Point::at(a.vector([0.0, 0.0, 0.0])), Point::at(a.vector([1.2, 0.5, -0.3])));
    let c1 = x1.displaced(a.vector([-0.2, 0.3, 0.1]));
    let c2 = x2.displaced(a.vector([0.25, -0.1, 0.4]));
    let j1 = a.dyadic(&Matrix3::new(0.3, 0.02, 0.0, 0.02, 0.4, -0.05, 0.0, -0.05, 0.5));
    let j2 = a.dyadic(&Matrix3::new(0.6, 0.0, 0.1, 0.0, 0.5, 0.0, 0.1, 0.0, 0.35));
    let (m1, m2) = (1.5, 2.5);
    let b1 = MassProperties::new(m1, c1, j1).unwrap();
    let b2 = MassProperties::new(m2, c2, j2).unwrap();
    let whole = b1.combine(&b2);
    let c = whole.centre_of_mass();
    let omega = a.vector([0.4, -0.9, 1.3]);
    let (f, p) = (a.vector([1.0, -2.0, 0.5]), c1.displaced(a.vector([0.1, 0.0, 0.2])));
    let rb = RigidBody::new(whole, a.vector([0.3, 0.0, -0.2]), omega);
    let (a_c, alpha) = rb.accelerations(&Wrench::from_force(&AppliedForce::new(f, p), c)).unwrap();
    let acc = |y: &Point| point_acceleration(&a_c, &alpha, &omega, &y.position_rel(&c));
    let gyro = |j: &Dyadic| j.apply(&alpha) + omega.cross(&j.apply(&omega));
    let f2 = acc(&c2) * m2;
    let couple2 = gyro(&j2) - x2.position_rel(&c2).cross(&f2);
    let f1 = acc(&c1) * m1 - f;
    let couple1 = gyro(&j1) - p.position_rel(&c1).cross(&f) - x1.position_rel(&c1).cross(&f1);
    let scale = f.norm() + (m1 + m2) * omega.norm_squared() * 2.0;
    assert!((f1 + f2).norm() <= 32.0 * EPS * scale, "the link's forces balance: {:e}", (f1 + f2).norm());
    let m_link = -couple1 - couple2 + x2.position_rel(&x1).cross(&(-f2));
    assert!(m_link.norm() <= 64.0 * EPS * scale, "the link's moments balance: {:e}", m_link.norm());
    // and the composite's equations themselves
    assert!((a_c * (m1 + m2) - f).norm() <= 8.0 * EPS * f.norm());
    let j = whole.inertia_about_centre();
    let residual = gyro(&j) - p.position_rel(&c).cross(&f);
    assert!(residual.norm() <= 64.0 * EPS * scale);
}

/// A link on a joint at the ground origin: mass m, centre `com` and inertia J_c in the link frame.
fn pinned(joint: Joint, m: f64, com: [f64; 3], j_c: Matrix3<f64>) -> Link {
    Link::new(None, joint, Vector3::zeros(), m, Vector3::from(com), j_c)
}

/// Ex 7.8.10 (the pin joint taken fixed in an inertially nonrotating body, as in §7.15): particles
/// y₁, y₂ on massless links ℓ₁, ℓ₂ about one pin, planar, f⃗ on y₁. Each link turns on its own:
/// m₁ℓ₁θ̈₁ = f⃗·ê_θ₁, θ̈₂ = 0; the link pulls each particle with −mᵢℓᵢθ̇ᵢ² ê_rᵢ − (f⃗·ê_rᵢ)ê_rᵢ (the
/// radial balance), with no tangential part (massless link on a frictionless pin). Checked
/// against the multibody model (ABA for the motion, RNEA for the joint reactions).
#[test]
fn example_7_8_10_two_particles_on_links_to_one_pin() {
    let (m, l) = ([0.9, 1.4], [1.1, 0.6]);
    let z = Joint::Pin { axis: Vector3::z() };
    let model = Model::new(&[
        pinned(z, m[0], [l[0], 0.0, 0.0], Matrix3::zeros()),
        pinned(z, m[1], [l[1], 0.0, 0.0], Matrix3::zeros()),
    ])
    .unwrap();
    let (q, v) = ([0.4, -1.2], [0.7, -0.3]);
    // f⃗ on y₁, components in link 1's frame (î along the link, ĵ = ê_θ)
    let f = Vector3::new(0.5, -1.6, 0.0);
    let com1 = Vector3::new(l[0], 0.0, 0.0);
    let ext = [JointWrench { force: f, moment: com1.cross(&f) }, JointWrench::default()];
    let vdot = model.aba(&q, &v, &[0.0, 0.0], Some(&ext)).unwrap();
    assert_rel(vdot[0], f.y / (m[0] * l[0]), 16.0 * EPS);
    assert_eq!(vdot[1], 0.0);
    let id = model.rnea(&q, &v, &vdot, Some(&ext)).unwrap();
    // the pin's force on link 1 = m a_c − f: radial −m ℓ θ̇² − f_r, tangential m ℓ θ̈ − f_θ = 0
    let w1 = id.wrenches[0];
    assert_abs(w1.force.x, -m[0] * l[0] * v[0] * v[0] - f.x, 16.0 * EPS);
    assert_abs(w1.force.y, 0.0, 16.0 * EPS);
    let w2 = id.wrenches[1];
    assert_abs(w2.force.x, -m[1] * l[1] * v[1] * v[1], 16.0 * EPS);
    assert_abs(w2.force.y, 0.0, 16.0 * EPS);
    assert_abs(id.tau[0], 0.0, 16.0 * EPS);
}

/// Ex 7.8.11 (the pin taken fixed, as in Ex 7.8.10): two rigid bodies on massless links to one
/// ball joint, 3D, f⃗ on body 1 (at a point of the body, or along its link). About the fixed pin
/// o each body obeys J⃗_o α⃗ + ω⃗ × J⃗_o ω⃗ = r⃗_{p/o} × f⃗, J⃗_o = J⃗_c + m(|r⃗_c|²I⃗ − r⃗_c r⃗_c′); the
/// pin's force is m a⃗_c − f⃗. A force along the link (through o) has no moment. Checked against the
/// multibody model with ball joints at the neutral configuration (link frames = ground frame).
#[test]
fn example_7_8_11_two_rigid_bodies_on_links_to_one_ball_joint() {
    let (m1, m2) = (1.3, 0.7);
    let (c1, c2) = (Vector3::new(0.8, 0.2, -0.1), Vector3::new(-0.3, 0.5, 0.9));
    let j1 = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.3, 0.02, 0.0, 0.02, 0.25);
    let j2 = Matrix3::from_diagonal(&Vector3::new(0.1, 0.15, 0.12));
    let model = Model::new(&[pinned(Joint::Ball, m1, c1.into(), j1), pinned(Joint::Ball, m2, c2.into(), j2)])
        .unwrap();
    let q = model.neutral();
    let (w1, w2) = (Vector3::new(0.6, -0.4, 1.1), Vector3::new(-0.2, 0.9, 0.3));
    let v: Vec<f64> = w1.iter().chain(w2.iter()).copied().collect();
    let j_o = |m: f64, c: &Vector3<f64>, j: &Matrix3<f64>| {
        j + m * (c.norm_squared() * Matrix3::identity() - c * c.transpose())
    };
    for along_link in [false, true] {
        let f = if along_link { c1 * 2.0 } else { Vector3::new(0.5, -1.0, 0.8) };
        let p = if along_link { c1 } else { c1 + Vector3::new(0.1, 0.2, 0.0) };
        let ext = [JointWrench { force: f, moment: p.cross(&f) }, JointWrench::default()];
        let vdot = model.aba(&q, &v, &[0.0; 6], Some(&ext)).unwrap();
        for (k, (m, c, j, w, moment)) in
            [(m1, c1, j1, w1, p.cross(&f)), (m2, c2, j2, w2, Vector3::zeros())].into_iter().enumerate()
        {
            let jo = j_o(m, &c, &j);
            let alpha = jo.try_inverse().unwrap() * (moment - w.cross(&(jo * w)));
            let got = Vector3::new(vdot[3 * k], vdot[3 * k + 1], vdot[3 * k + 2]);
            assert_abs_slice(got.as_slice(), alpha.as_slice(), 64.0 * EPS * (1.0 + alpha.nan_amax()));
        }
        if along_link {
            // no moment about o: only the gyroscopic term drives body 1
            let jo = j_o(m1, &c1, &j1);
            let alpha = jo.try_inverse().unwrap() * (-w1.cross(&(jo * w1)));
            assert_abs_slice(&vdot[..3], alpha.as_slice(), 64.0 * EPS * (1.0 + alpha.nan_amax()));
        }
        let id = model.rnea(&q, &v, &vdot, Some(&ext)).unwrap();
        for (k, (m, c, w, fk)) in [(m1, c1, w1, f), (m2, c2, w2, Vector3::zeros())].into_iter().enumerate() {
            let alpha = Vector3::new(vdot[3 * k], vdot[3 * k + 1], vdot[3 * k + 2]);
            let a_c = alpha.cross(&c) + w.cross(&w.cross(&c));
            let want = m * a_c - fk;
            assert_abs_slice(
                id.wrenches[k].force.as_slice(),
                want.as_slice(),
                64.0 * EPS * (1.0 + want.nan_amax()),
            );
            assert_abs_slice(
                id.wrenches[k].moment.as_slice(),
                &[0.0; 3],
                64.0 * EPS * (1.0 + want.nan_amax()),
            );
        }
    }
}
