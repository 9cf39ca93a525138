//! §6.11 (Newtonian bodies), P6.14.1, P6.14.6 and the applied problems P6.15.1–2, whose figures
//! the text lacks: each test states the geometry it assumes and which part the figure fixes.

use vectrix::num_dual::{Dual64, DualNum};
use vectrix::prelude::*;
use vectrix::statics::{
    AppliedForce, MassProperties, Point, Spring, UniformGravity, Wrench, moment_of_inertia,
    product_of_inertia,
};

use crate::common::pt;
use crate::support::{EPS, NanAmax, assert_abs, assert_abs_slice, assert_rel, assert_rel_slice};

/// §6.11, Fact 6.11.1: in a Newtonian body the internal forces (equal, opposite, along the
/// line through the particles) are balanced and have zero moment about every point. Springs
/// between every pair of five particles are such forces; magnetic dipole forces are not along
/// the line, and their moments alone do not cancel (their torques do, Fact 6.13.x).
#[test]
fn section_6_11_internal_forces_of_a_newtonian_body_are_balanced() {
    let a = Frame::new();
    let ys = [[0.0, 0.0, 0.0], [1.0, 0.2, -0.3], [-0.4, 1.5, 0.6], [0.7, -0.8, 1.1], [2.0, 1.0, 0.5]];
    let spring = Spring::new(3.0, 0.7).unwrap();
    let mut forces = Vec::new();
    for (i, yi) in ys.iter().enumerate() {
        for yj in &ys[i + 1..] {
            let pair = spring.forces(&(a.vector(*yi) - a.vector(*yj))).unwrap();
            forces.push(AppliedForce::new(pair.on_y, pt(&a, *yi)));
            forces.push(AppliedForce::new(pair.on_w, pt(&a, *yj)));
        }
    }
    let scale = forces.iter().map(|f| f.force.norm()).sum::<f64>();
    for w in [[0.0, 0.0, 0.0], [5.0, -3.0, 2.0]] {
        let total = Wrench::resultant(&forces, &[], pt(&a, w));
        assert!(total.force.norm() <= 8.0 * EPS * scale, "{:?}", total.force.resolve(&a));
        assert!(total.moment.norm() <= 64.0 * EPS * scale, "{:?}", total.moment.resolve(&a));
    }
    // not Newtonian: dipole forces are equal and opposite but not along the line
    let (my, mz) = (a.vector([1.0, 0.0, 0.0]), a.vector([0.0, 1.0, 0.0]));
    let r = a.vector([2.0, 0.0, 0.0]);
    let p = vectrix::statics::dipole_interaction(&mz, &my, &r).unwrap();
    let pair =
        [AppliedForce::new(p.force_on_z, Point::at(r)), AppliedForce::new(-p.force_on_z, Point::origin())];
    let total = Wrench::resultant(&pair, &[], Point::origin());
    assert!(total.force.norm() <= 4.0 * EPS);
    assert!(total.moment.norm() > 0.1, "the force couple of two dipoles has a moment");
}

/// P6.14.1: every particle of a rigid body is at rest relative to the centre of mass with respect
/// to a body-fixed frame: v⃗_{y_i/c/B} = 0. The body moves (translation p(t), rotation about a
/// tilted axis by θ(t)); c(t) is computed by vectrix from the moving particles with dual numbers,
/// and the B-components of r⃗_{y_i/c} have zero time derivative.
#[test]
fn problem_6_14_1_particles_are_at_rest_relative_to_the_centre_in_the_body_frame() {
    let t = Dual64::new(0.8, 1.0);
    let a = Frame::<Dual64>::identity();
    let axis = a.vector([1.0, -2.0, 0.5].map(Dual64::from));
    let r_ba = Rotor::from_axis_angle(&axis, t * 1.3 + t * t * 0.4).unwrap();
    let b = a.rotated_by_rotor(&r_ba);
    let p = a.vector([t * 2.0, (t * 3.0).sin(), t * t * -0.5]);
    let body =
        [([1.0, 0.0, 0.0], 2.0), ([0.0, 1.5, -0.5], 1.0), ([-0.3, 0.2, 2.0], 3.5), ([0.4, -1.0, 0.0], 0.5)];
    let particles: Vec<(Dual64, Point<Dual64>)> = body
        .iter()
        .map(|(x_b, m)| (Dual64::from(*m), Point::at(p + b.vector(x_b.map(Dual64::from)))))
        .collect();
    let c = MassProperties::from_particles(&particles).unwrap().centre_of_mass();
    // the centre moves in F_A …
    assert!(c.position().resolve(&a).map(|z| z.eps).nan_amax() > 0.1);
    for (_, y) in &particles {
        let r_b = y.position_rel(&c).resolve(&b);
        // … but no particle moves relative to it in F_B: rounding of the dual parts only
        assert!(r_b.map(|z| z.eps).nan_amax() <= 64.0 * EPS, "{:?}", r_b.map(|z| z.eps));
    }
}

/// P6.14.6: J_xx = î_B′J⃗î_B (likewise J_yy, J_zz), and the book's positive products
/// J_xy = −î_B′J⃗ĵ_B, …; for every unit n̂, n̂′J⃗n̂ is the moment of inertia about the line through
/// z along n̂ (Σ mᵢ|n̂ × r⃗ᵢ|², computed here from the particles); it is a principal moment, with
/// n̂ a principal axis, iff J⃗n̂ = λn̂, i.e. n̂ is an eigenvector. (A non-principal n̂ can give the
/// middle value λ₂ too: the cone n̂′(J⃗ − λ₂I⃗)n̂ = 0, so the eigenvector condition is the test.)
#[test]
fn problem_6_14_6_moments_and_products_as_quadratic_forms() {
    let a = Frame::new();
    let f = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([0.3, 1.0, -0.7]), 0.9).unwrap());
    let parts =
        [(2.0, [1.0, 0.5, -0.3]), (1.0, [-0.4, 1.2, 0.8]), (3.0, [0.2, -0.6, 1.5]), (0.5, [1.1, 1.0, 1.0])];
    let particles: Vec<(f64, Point)> = parts.iter().map(|(m, x)| (*m, pt(&a, *x))).collect();
    let body = MassProperties::from_particles(&particles).unwrap();
    let z = pt(&a, [0.1, -0.2, 0.3]);
    let j = body.inertia_about(&z);
    // Σ m|n̂ × r|² and Σ m (â·r)(b̂·r), directly from the particles (6.2.3–6.2.8)
    let direct_moment = |n: &Vector| {
        particles.iter().map(|(m, y)| m * n.cross(&y.position_rel(&z)).norm_squared()).sum::<f64>()
    };
    let direct_product = |u: &Vector, v: &Vector| {
        particles
            .iter()
            .map(|(m, y)| m * u.dot(&y.position_rel(&z)) * v.dot(&y.position_rel(&z)))
            .sum::<f64>()
    };
    let scale = j.norm();
    let m = j.resolve(&f);
    for (i, e) in [f.i(), f.j(), f.k()].iter().enumerate() {
        assert_abs(m[(i, i)], e.dot(&(j * *e)), 8.0 * EPS * scale);
        assert_abs(m[(i, i)], direct_moment(e), 16.0 * EPS * scale);
    }
    for (u, v, (i, k)) in [(f.i(), f.j(), (0, 1)), (f.i(), f.k(), (0, 2)), (f.j(), f.k(), (1, 2))] {
        assert_abs(product_of_inertia(&j, &u, &v).unwrap(), direct_product(&u, &v), 16.0 * EPS * scale);
        assert_abs(-m[(i, k)], direct_product(&u, &v), 16.0 * EPS * scale);
    }
    let n = a.vector([0.6, -0.8, 1.7]).unit().unwrap();
    assert_abs(moment_of_inertia(&j, &n).unwrap(), direct_moment(&n), 16.0 * EPS * scale);
    // principal ⟺ eigenvector
    let p = body.principal_axes(&z, vectrix::statics::INERTIA_REL_TOL).unwrap();
    for (k, e) in [p.frame.i(), p.frame.j(), p.frame.k()].iter().enumerate() {
        assert_rel(moment_of_inertia(&j, e).unwrap(), p.moments[k], 64.0 * EPS);
        assert!((j * *e).cross(e).norm() <= 64.0 * EPS * scale, "J n̂ ∥ n̂ on a principal axis");
    }
    // a unit vector on the λ₂ cone: n̂′J⃗n̂ = λ₂, yet J⃗n̂ is not along n̂
    let (l1, l2, l3) = (p.moments[0], p.moments[1], p.moments[2]);
    let (c1, c3) = (((l2 - l3) / (l1 - l3)).sqrt(), ((l1 - l2) / (l1 - l3)).sqrt());
    let cone = p.frame.i() * c1 + p.frame.k() * c3;
    assert_rel(moment_of_inertia(&j, &cone).unwrap(), l2, 1e3 * EPS);
    assert!((j * cone).cross(&cone).norm() > 1e-3 * scale);
}

/// P6.15.1 (Fig. 6.15.1 is not in the text): a bar pinned at a, length ℓ along ê, its end c tied
/// to b by a spring of stiffness k and zero relaxed length. The spring's force on the bar,
/// k r⃗_{b/c}, has moment M⃗_{/a} = r⃗_{c/a} × k r⃗_{b/c} = kℓ ê × r⃗_{b/a} and longitudinal part
/// k(ê·r⃗_{b/a} − ℓ). With a torsional spring of stiffness κ (relaxed at θ = 0) at the pin, the
/// bar rests at θ when κθ equals the spring moment: κ = kℓ|r⃗_{b/a}| sin(β − θ)/θ for b at angle
/// β. The figure fixes b and θ, so κ is checked here as that formula at several geometries.
#[test]
fn problem_6_15_1_bar_with_a_zero_length_spring_and_a_torsional_spring() {
    let a = Frame::new();
    let (k, l) = (40.0, 0.8);
    for (theta, beta, d) in [(0.3, 1.2, 1.5), (0.8, 2.0, 0.6), (-0.4, -1.1, 2.2)] {
        let e = a.vector([f64::cos(theta), f64::sin(theta), 0.0]);
        let r_ba = a.vector([d * f64::cos(beta), d * f64::sin(beta), 0.0]);
        let r_ca = e * l;
        let f_on_c = Spring::new(k, 0.0).unwrap().force(&(r_ca - r_ba)).unwrap();
        let m_a = AppliedForce::new(f_on_c, Point::at(r_ca)).moment_about(&Point::origin());
        assert_abs_slice(
            m_a.resolve(&a).as_slice(),
            (e.cross(&r_ba) * (k * l)).resolve(&a).as_slice(),
            16.0 * EPS * k * l * d,
        );
        assert_abs(f_on_c.dot(&e), k * (e.dot(&r_ba) - l), 16.0 * EPS * k * (l + d));
        // the torsional spring that balances it at θ
        let kappa = k * l * d * f64::sin(beta - theta) / theta;
        assert!(kappa > 0.0);
        let torsional = vectrix::statics::RotationalSpring::new(kappa, 0.0).unwrap();
        let (m_t, _) = torsional.torques(&e, &a.i(), &a.k()).unwrap();
        assert_abs(m_t.dot(&a.k()) + m_a.dot(&a.k()), 0.0, 64.0 * EPS * k * l * d);
    }
}

/// P6.15.2 (Fig. 6.15.2 is not in the text; the configuration it describes): a triangle pinned to
/// a wall at P, masses m₁, m₂ at y₁, y₂, the side y₁y₂ (ℓ₃) horizontal, and a rope from y₁ held
/// horizontal by a wheel z at y₁'s height, carrying M. The centre of mass is
/// (m₁r⃗_{y₁} + m₂r⃗_{y₂})/(m₁ + m₂). Moments about P: M g h = g Σ mᵢ(x_P − xᵢ), with h the depth
/// of y₁y₂ below P and the masses on the wheel's side, so M = Σ mᵢ(x_P − xᵢ)/h. With the wheel moved to the other side the rope
/// pulls the other way and the moment about P is 2Mgh ≠ 0: no equilibrium with ℓ₃ horizontal.
#[test]
fn problem_6_15_2_triangle_pinned_to_a_wall_and_a_rope() {
    let a = Frame::new(); // î to the right, ĵ up; the wheel z on the left of y₁
    let g = UniformGravity::new(a.vector([0.0, -9.81, 0.0])).unwrap();
    let (m1, m2) = (2.0, 3.0);
    let p = pt(&a, [0.0, 0.0, 0.0]);
    // y₁y₂ horizontal at depth h below P, both to the left of the wall line through P
    let h = 1.2;
    let (y1, y2) = (pt(&a, [-2.5, -h, 0.0]), pt(&a, [-0.7, -h, 0.0]));
    let body = MassProperties::from_particles(&[(m1, y1), (m2, y2)]).unwrap();
    let want_c = (y1.position() * m1 + y2.position() * m2) * (1.0 / (m1 + m2));
    assert_rel_slice(
        body.centre_of_mass().position().resolve(&a).as_slice(),
        want_c.resolve(&a).as_slice(),
        4.0 * EPS,
    );
    // M from the moment balance about P
    let x = |y: &Point| y.position().dot(&a.i()) - p.position().dot(&a.i());
    let big_m = -(m1 * x(&y1) + m2 * x(&y2)) / h;
    assert!(big_m > 0.0);
    let rope = |dir: f64| AppliedForce::new(a.i() * (dir * big_m * 9.81), y1);
    let weight = g.wrench_on(&body, p);
    // the pin at P takes the remaining force; about P only the moments count
    let with_left = weight.plus(&Wrench::from_force(&rope(-1.0), p));
    assert_abs(with_left.moment.norm(), 0.0, 64.0 * EPS * (m1 + m2) * 9.81 * 3.0);
    let with_right = weight.plus(&Wrench::from_force(&rope(1.0), p));
    assert_rel(with_right.moment.norm(), 2.0 * big_m * 9.81 * h, 16.0 * EPS);
}
