//! §6.4–6.6, §6.9–6.10, Problem 6.15.3: moments, wrenches, torques, uniform gravity, the
//! laws of statics and free-body analysis.

use vectrix::prelude::*;
use vectrix::statics::{
    AppliedForce, Determinacy, FREE_BODY_REL_TOL, FreeBodyProblem, MassProperties, Point, StaticsError,
    UniformGravity, Wrench,
};

use crate::common::{assert_vec_rel, pt};
use crate::support::{EPS, assert_abs, assert_rel};

fn forces(a: &Frame) -> Vec<AppliedForce> {
    vec![
        AppliedForce::new(a.vector([1.0, 0.0, 2.0]), pt(a, [0.0, 1.0, 0.0])),
        AppliedForce::new(a.vector([0.0, -3.0, 1.0]), pt(a, [2.0, 0.0, 1.0])),
        AppliedForce::new(a.vector([-0.5, 1.0, 0.0]), pt(a, [1.0, 1.0, -1.0])),
    ]
}

#[test]
fn eq_6_4_4_moment_transfer() {
    // (6.4.4): M⃗_{B/w} = M⃗_{B/z} + r⃗_{z/w} × f⃗_B.
    let a = Frame::new();
    let fs = forces(&a);
    let (w, z) = (pt(&a, [3.0, -1.0, 2.0]), pt(&a, [-2.0, 4.0, 0.5]));
    let mw = Wrench::resultant(&fs, &[], w);
    let mz = Wrench::resultant(&fs, &[], z);
    assert_vec_rel(&mw.moment, &(mz.moment + z.position_rel(&w).cross(&mz.force)), 16.0 * EPS);
    let shifted = mw.shift_to(&z);
    assert_vec_rel(&shifted.moment, &mz.moment, 16.0 * EPS);
    assert_eq!(shifted.about, z);
    // Sum of wrenches about different points: shifted before adding.
    let sum = Wrench::from_force(&fs[0], w).plus(&Wrench::resultant(&fs[1..], &[], z));
    assert_vec_rel(&sum.moment, &mw.moment, 16.0 * EPS);
    assert_vec_rel(&sum.force, &mw.force, 16.0 * EPS);
}

#[test]
fn fact_6_4_2_6_4_3_balanced_forces_give_a_torque() {
    // Facts 6.4.2–6.4.3: balanced forces have the same moment about every point (a torque);
    // for a couple f⃗ at x, −f⃗ at y: M⃗_B = r⃗_{x/y} × f⃗.
    let a = Frame::new();
    let f = a.vector([0.0, 2.0, 1.0]);
    let (x, y) = (pt(&a, [1.0, 0.0, 0.0]), pt(&a, [-1.0, 0.5, 0.0]));
    let pair = [AppliedForce::new(f, x), AppliedForce::new(-f, y)];
    let t = x.position_rel(&y).cross(&f);
    for w in [Point::origin(), pt(&a, [5.0, 5.0, 5.0]), x] {
        let wr = Wrench::resultant(&pair, &[], w);
        assert!(wr.is_balanced(EPS));
        assert_vec_rel(&wr.as_torque(EPS).unwrap(), &t, 16.0 * EPS);
    }
    let unbalanced = Wrench::resultant(&forces(&a), &[], Point::origin());
    assert!(unbalanced.as_torque(1e-12).is_none());
}

#[test]
fn fact_6_4_4_compensating_force_makes_the_moment_a_torque() {
    // Fact 6.4.4: with z on the line through w parallel to f⃗_B, the forces plus −f⃗_B at z are
    // balanced and their torque equals M⃗_{B/w}.
    let a = Frame::new();
    let fs = forces(&a);
    let w = pt(&a, [1.0, 2.0, 3.0]);
    let wr = Wrench::resultant(&fs, &[], w);
    let z = w.displaced(wr.force * 2.5);
    let (torque, comp) = wr.compensated_torque(&z);
    assert_vec_rel(&torque, &wr.moment, 64.0 * EPS);
    let mut all = fs.clone();
    all.push(comp);
    let bal = Wrench::resultant(&all, &[], pt(&a, [-7.0, 0.0, 1.0]));
    assert!(bal.is_balanced(16.0 * EPS));
    assert_vec_rel(&bal.moment, &wr.moment, 64.0 * EPS);
}

#[test]
fn fact_6_6_2_uniform_gravity_moment() {
    // Facts 6.6.1–6.6.2: f⃗_B = m_B g⃗, M⃗_{B/w} = r⃗_{c/w} × m_B g⃗ (the sum over particles), and
    // M⃗_{B/c} = 0⃗ (6.6.3).
    let a = Frame::new();
    let g = UniformGravity::new(a.vector([0.0, 0.0, -9.81])).unwrap();
    let ps =
        [(1.0, pt(&a, [1.0, 0.0, 0.0])), (2.0, pt(&a, [0.0, 2.0, 1.0])), (3.0, pt(&a, [-1.0, 1.0, 2.0]))];
    let body = MassProperties::from_particles(&ps).unwrap();
    let w = pt(&a, [0.5, -0.5, 4.0]);
    let per_particle: Vec<_> = ps.iter().map(|(m, y)| AppliedForce::new(g.force(*m), *y)).collect();
    let direct = Wrench::resultant(&per_particle, &[], w);
    let got = g.wrench_on(&body, w);
    assert_vec_rel(&got.force, &direct.force, 16.0 * EPS);
    assert_vec_rel(&got.moment, &direct.moment, 64.0 * EPS);
    assert!(g.wrench_on(&body, body.centre_of_mass()).moment.norm() <= 64.0 * EPS);
}

#[test]
fn section_6_5_laws_of_statics_simply_supported_beam() {
    // §6.5, §6.10: a beam of length L on a pin at x = 0 and a roller at x = L, load P at x = s:
    // vertical reactions P(L − s)/L and P s/L, horizontal pin reaction 0.
    let a = Frame::new();
    let (l, s, p) = (4.0, 1.0, 100.0);
    let mut fb = FreeBodyProblem::new();
    let beam = fb.add_body();
    fb.apply_force(beam, AppliedForce::new(a.vector([0.0, -p, 0.0]), pt(&a, [s, 0.0, 0.0]))).unwrap();
    let ry0 = fb.unknown_force(beam, None, a.j(), Point::origin()).unwrap();
    let rx0 = fb.unknown_force(beam, None, a.i(), Point::origin()).unwrap();
    let ryl = fb.unknown_force(beam, None, a.j(), pt(&a, [l, 0.0, 0.0])).unwrap();
    // Out-of-plane restraints so that the 3D problem is determinate: z force at both ends,
    // and a couple about the beam axis.
    fb.unknown_force(beam, None, a.k(), Point::origin()).unwrap();
    fb.unknown_force(beam, None, a.k(), pt(&a, [l, 0.0, 0.0])).unwrap();
    fb.unknown_couple(beam, None, a.i()).unwrap();
    let sol = fb.solve(FREE_BODY_REL_TOL).unwrap().require_determinate().unwrap();
    assert_rel(sol.value(ry0).unwrap(), p * (l - s) / l, 64.0 * EPS);
    assert_rel(sol.value(ryl).unwrap(), p * s / l, 64.0 * EPS);
    assert!(sol.value(rx0).unwrap().abs() <= 64.0 * EPS * p);
    assert_vec_rel(&sol.reaction(ryl).unwrap(), &(a.j() * (p * s / l)), 64.0 * EPS);
}

#[test]
fn section_6_10_statically_indeterminate_beam() {
    // A third support makes the beam indeterminate of degree 1: the minimum-norm reactions
    // balance the load and one self-stress state is reported.
    let a = Frame::new();
    let mut fb = FreeBodyProblem::new();
    let beam = fb.add_body();
    fb.apply_force(beam, AppliedForce::new(a.vector([0.0, -10.0, 0.0]), pt(&a, [1.0, 0.0, 0.0]))).unwrap();
    let ids: Vec<_> = [0.0, 2.0, 4.0]
        .iter()
        .map(|&x| fb.unknown_force(beam, None, a.j(), pt(&a, [x, 0.0, 0.0])).unwrap())
        .collect();
    fb.unknown_force(beam, None, a.i(), Point::origin()).unwrap();
    fb.unknown_force(beam, None, a.k(), Point::origin()).unwrap();
    fb.unknown_force(beam, None, a.k(), pt(&a, [4.0, 0.0, 0.0])).unwrap();
    fb.unknown_couple(beam, None, a.i()).unwrap();
    let sol = fb.solve(FREE_BODY_REL_TOL).unwrap();
    let Determinacy::Indeterminate { degree, self_stress } = &sol.determinacy else {
        panic!("expected indeterminate, got {:?}", sol.determinacy);
    };
    assert_eq!((*degree, self_stress.len()), (1, 1));
    // The self-stress of three collinear supports is ∝ (1, −2, 1).
    let st = &self_stress[0];
    assert_rel(st[1] / st[0], -2.0, 1e3 * EPS);
    assert_abs(st[2] / st[0], 1.0, 1e3 * EPS);
    let total: f64 = ids.iter().map(|&u| sol.value(u).unwrap()).sum();
    assert_rel(total, 10.0, 64.0 * EPS);
    assert!(matches!(sol.require_determinate(), Err(StaticsError::Indeterminate { degree: 1, .. })));
}

#[test]
fn section_6_10_statically_inconsistent_system() {
    // A horizontal load on a body with only vertical supports cannot be balanced.
    let a = Frame::new();
    let mut fb = FreeBodyProblem::new();
    let b = fb.add_body();
    fb.apply_force(b, AppliedForce::new(a.vector([5.0, -1.0, 0.0]), pt(&a, [1.0, 0.0, 0.0]))).unwrap();
    fb.unknown_force(b, None, a.j(), Point::origin()).unwrap();
    fb.unknown_force(b, None, a.j(), pt(&a, [2.0, 0.0, 0.0])).unwrap();
    assert!(matches!(fb.solve(FREE_BODY_REL_TOL), Err(StaticsError::Inconsistent { .. })));
    // Bad input.
    assert!(matches!(
        fb.unknown_force(b, None, Vector::zero(), Point::origin()),
        Err(StaticsError::ZeroVector { .. })
    ));
    let ghost = {
        let mut p = FreeBodyProblem::new();
        p.add_body();
        p.add_body()
    };
    assert!(matches!(fb.apply_couple(ghost, a.k()), Err(StaticsError::UnknownBody { .. })));
}

#[test]
fn problem_6_15_3_sphere_pyramid() {
    // P6.15.3: three spheres in a ring, a fourth on top. Each bottom sphere pushes the ring
    // with mg/(3√2) = (√2/6) mg ≈ 0.23570 mg; each top contact carries N = mg/√6.
    // Bodies: top sphere T and bottom spheres B_i; contacts are frictionless (forces along
    // the lines of centres); the bottom spheres carry no weight here ("due to the weight of
    // the fourth sphere") and do not push each other (they are pushed apart).
    let a = Frame::new();
    let (r, mg) = (1.0, 1.0);
    let rc = 2.0 * r / 3f64.sqrt(); // circumradius of the bottom triangle of side 2r
    let h = (4.0 * r * r - rc * rc).sqrt();
    let mut fb = FreeBodyProblem::new();
    let top = fb.add_body();
    let top_c = pt(&a, [0.0, 0.0, h]);
    fb.apply_force(top, AppliedForce::new(a.vector([0.0, 0.0, -mg]), top_c)).unwrap();
    let mut ring = vec![];
    let mut contact = vec![];
    for k in 0..3 {
        let phi = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let (cx, cy) = (rc * phi.cos(), rc * phi.sin());
        let b = fb.add_body();
        let bc = pt(&a, [cx, cy, 0.0]);
        // Top–bottom contact: on T along r̂_{T/B}, partner on B.
        contact.push(
            fb.unknown_force(
                top,
                Some(b),
                top_c.position_rel(&bc),
                bc.displaced(top_c.position_rel(&bc) * 0.5),
            )
            .unwrap(),
        );
        // Floor: vertical, at the sphere's bottom point; ring: radial inward, at the equator.
        fb.unknown_force(b, None, a.k(), pt(&a, [cx, cy, -r])).unwrap();
        ring.push(
            fb.unknown_force(
                b,
                None,
                a.vector([-cx, -cy, 0.0]),
                pt(&a, [cx * (1.0 + r / rc), cy * (1.0 + r / rc), 0.0]),
            )
            .unwrap(),
        );
    }
    let sol = fb.solve(FREE_BODY_REL_TOL).unwrap().require_determinate().unwrap();
    for k in 0..3 {
        assert_abs(sol.value(contact[k]).unwrap(), mg / 6f64.sqrt(), 64.0 * EPS);
        // The ring pushes inward; the sphere pushes the ring outward with the same magnitude.
        assert_abs(sol.value(ring[k]).unwrap(), mg / (3.0 * 2f64.sqrt()), 64.0 * EPS);
    }
    assert_abs(mg / (3.0 * 2f64.sqrt()), 0.235_702_260_395_515_8, EPS);
}

#[test]
fn problem_6_14_5_equal_moments_about_two_points_need_not_balance() {
    // P6.14.5: M⃗_{B/w} = M⃗_{B/z} ≠ 0⃗ with w ≠ z does not imply balanced forces: by (6.4.4) it
    // only forces f⃗_B ∥ r⃗_{z/w}. Counterexample: three non-coplanar forces whose resultant is
    // parallel to r⃗_{z/w}.
    let a = Frame::new();
    let fs = [
        AppliedForce::new(a.vector([1.0, 0.0, 0.0]), pt(&a, [0.0, 1.0, 0.0])),
        AppliedForce::new(a.vector([0.0, 1.0, 0.0]), pt(&a, [0.0, 0.0, 1.0])),
        AppliedForce::new(a.vector([-1.0, -1.0, 1.0]), pt(&a, [1.0, 0.0, 0.0])),
    ];
    let w = Point::origin();
    let z = w.displaced(a.k() * 3.0); // r⃗_{z/w} ∥ f⃗_B = k̂
    let (mw, mz) = (Wrench::resultant(&fs, &[], w), Wrench::resultant(&fs, &[], z));
    assert_vec_rel(&mw.moment, &mz.moment, 16.0 * EPS);
    assert!(mw.moment.norm() > 0.5 && !mw.is_balanced(0.5));
}

#[test]
fn fact_6_9_2_6_9_3_third_law_sums_in_a_two_body_problem() {
    // Facts 6.9.2–6.9.3: reaction forces between bodies sum to 0⃗, and so do their moments
    // about any point. Two blocks stacked on the ground, the upper one loaded off-centre.
    let a = Frame::new();
    let mut fb = FreeBodyProblem::new();
    let (lower, upper) = (fb.add_body(), fb.add_body());
    fb.apply_force(upper, AppliedForce::new(a.vector([0.0, 0.0, -6.0]), pt(&a, [0.2, 0.1, 2.0]))).unwrap();
    fb.apply_force(lower, AppliedForce::new(a.vector([0.0, 0.0, -4.0]), pt(&a, [0.0, 0.0, 0.5]))).unwrap();
    let mut between = vec![];
    for (x, y) in [(-0.5, -0.5), (0.5, -0.5), (0.0, 0.5)] {
        between.push(fb.unknown_force(upper, Some(lower), a.k(), pt(&a, [x, y, 1.0])).unwrap());
        fb.unknown_force(lower, None, a.k(), pt(&a, [x, y, 0.0])).unwrap();
    }
    for body in [upper, lower] {
        fb.unknown_force(body, None, a.i(), pt(&a, [0.0, 0.0, 0.0])).unwrap();
        fb.unknown_force(body, None, a.j(), pt(&a, [0.0, 0.0, 0.0])).unwrap();
        fb.unknown_couple(body, None, a.k()).unwrap();
    }
    let sol = fb.solve(FREE_BODY_REL_TOL).unwrap().require_determinate().unwrap();
    // The contact forces carry the upper block's weight, with its moment.
    let on_upper: Vec<_> =
        between.iter().map(|&u| AppliedForce::new(sol.reaction(u).unwrap(), pt(&a, [0.0; 3]))).collect();
    let total: f64 = between.iter().map(|&u| sol.value(u).unwrap()).sum();
    assert_rel(total, 6.0, 64.0 * EPS);
    // Third law: the pair (on upper, on lower) sums to zero force and zero moment about any w.
    let w = pt(&a, [3.0, -1.0, 7.0]);
    let mut f_sum = Vector::zero();
    let mut m_sum = Vector::zero();
    for (&u, p) in between.iter().zip([[-0.5, -0.5, 1.0], [0.5, -0.5, 1.0], [0.0, 0.5, 1.0]]) {
        let f = sol.reaction(u).unwrap();
        for sign in [1.0, -1.0] {
            let af = AppliedForce::new(f * sign, pt(&a, p));
            f_sum += af.force;
            m_sum += af.moment_about(&w);
        }
    }
    assert!(f_sum.norm() <= EPS && m_sum.norm() <= 64.0 * EPS);
    assert_eq!(on_upper.len(), 3);
}

#[test]
fn fact_6_2_15_symmetry_plane_zeroes_products_of_inertia() {
    // Fact 6.2.15: a plane of symmetry x = 0 makes J_xy = J_xz = 0; two orthogonal planes make
    // the frame principal.
    let a = Frame::new();
    let ps = [
        (1.0, pt(&a, [1.0, 2.0, 0.5])),
        (1.0, pt(&a, [-1.0, 2.0, 0.5])),
        (2.0, pt(&a, [0.0, -1.0, 1.0])),
        (3.0, pt(&a, [2.0, 0.0, -1.0])),
        (3.0, pt(&a, [-2.0, 0.0, -1.0])),
    ];
    let body = MassProperties::from_particles(&ps).unwrap();
    let comps = vectrix::statics::InertiaComponents::of(&body.inertia_about_centre(), &a);
    assert!(comps.products[0].abs() <= 16.0 * EPS && comps.products[1].abs() <= 16.0 * EPS);
    assert!(comps.products[2].abs() > 0.1, "J_yz need not vanish");
}
