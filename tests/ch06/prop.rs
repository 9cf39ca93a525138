//! Property tests for chapter 6: parallel-axis path independence, inertia bounds on random
//! bodies (biased toward collinear and coplanar ones), frame independence, dipole third-law
//! sums, and potentials consistent with forces (exact gradients with dual numbers).

use proptest::prelude::*;
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;
use vectrix::statics::{
    CentralGravity, INERTIA_REL_TOL, MassProperties, Point, RotationalSpring, Spring, UniformGravity,
    dipole_interaction, dipole_potential, mutual_gravitation, mutual_gravitation_potential, shift_inertia,
};

use crate::common::assert_mat_rel;
use crate::support::{EPS, assert_abs, direction, frame, triple};

const GOLDEN: f64 = 1.618_033_988_749_895;

/// Random bodies as (mass, components) lists, biased toward the hard sets: nearly collinear,
/// exactly coplanar, and general position.
fn body() -> impl Strategy<Value = Vec<(f64, [f64; 3])>> {
    prop_oneof![
        2 => prop::collection::vec((0.1..10.0f64, triple()), 2..8),
        1 => (prop::collection::vec((0.1..10.0f64, -5.0..5.0f64), 2..6), direction(), 0.0..1e-9f64)
            .prop_map(|(ps, d, eps)| ps.into_iter().enumerate()
                .map(|(i, (m, t))| (m, [t * d[0] + eps * i as f64, t * d[1], t * d[2]])).collect()),
        1 => prop::collection::vec((0.1..10.0f64, -5.0..5.0f64, -5.0..5.0f64), 3..7)
            .prop_map(|ps| ps.into_iter().map(|(m, x, y)| (m, [x, y, 0.0])).collect()),
    ]
}

fn build(a: &Frame, b: &[(f64, [f64; 3])]) -> MassProperties {
    let ps: Vec<_> = b.iter().map(|(m, x)| (*m, Point::at(a.vector(*x)))).collect();
    MassProperties::from_particles(&ps).unwrap()
}

/// ∂U/∂r⃗ resolved in the first frame, by one forward-mode dual pass per component.
fn gradient(u: impl Fn(Vector<Dual64>) -> Dual64, r: [f64; 3]) -> [f64; 3] {
    let fd = Frame::<Dual64>::identity();
    let mut g = [0.0; 3];
    for (k, gk) in g.iter_mut().enumerate() {
        let c = |i: usize| if i == k { Dual64::new(r[i], 1.0) } else { Dual64::from_re(r[i]) };
        *gk = u(fd.vector([c(0), c(1), c(2)])).eps;
    }
    g
}

fn d(x: f64) -> Dual64 {
    Dual64::from_re(x)
}

#[track_caller]
fn assert_force_is_minus_gradient(f: &Vector, grad: [f64; 3], tol: f64) {
    let fa = f.resolve(&Frame::new());
    let scale = fa.norm().max(1.0);
    for k in 0..3 {
        assert!((fa[k] + grad[k]).abs() <= tol * scale, "f = {fa:?}, ∂U = {grad:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn parallel_axis_path_independence(b in body(), z1 in triple(), z2 in triple(), z3 in triple()) {
        // (6.2.26), (6.2.29): J_c → z1 → z2 → z3 equals J_c → z3, whatever the path.
        let a = Frame::new();
        let mp = build(&a, &b);
        let (z1, z2, z3) = (Point::at(a.vector(z1)), Point::at(a.vector(z2)), Point::at(a.vector(z3)));
        let c = mp.centre_of_mass();
        let m = mp.mass();
        let j1 = mp.inertia_about(&z1);
        let j2 = shift_inertia(&j1, m, &z2.position_rel(&z1), &c.position_rel(&z1));
        let j3 = shift_inertia(&j2, m, &z3.position_rel(&z2), &c.position_rel(&z2));
        let want = mp.inertia_about(&z3);
        // Shifts over distances ~10 with masses ~50 cancel terms of size m|r|²: scale by it.
        let scale = want.norm() + m * 400.0;
        prop_assert!((j3 - want).norm() <= 1e3 * EPS * scale, "{}", (j3 - want).norm());
    }

    #[test]
    fn inertia_bounds_on_random_bodies(b in body(), z in triple()) {
        // Fact 6.2.7 (PSD, rank ≠ 1), (6.2.19) λ1 ≤ λ2 + λ3, (6.2.20) golden bound, (6.2.27)
        // J_z ⪰ J_c; coplanar bodies about a point in their plane reach λ1 = λ2 + λ3.
        let a = Frame::new();
        let mp = build(&a, &b);
        let p = mp.principal_axes(&mp.centre_of_mass(), 1e-9).unwrap();
        let [l1, l2, l3] = p.moments;
        prop_assert!(l1 >= l2 && l2 >= l3 && l3 >= 0.0);
        prop_assert!(p.rank != 1);
        prop_assert!(l1 <= (l2 + l3) * (1.0 + 1e-12));
        if l3 > 1e-6 * l1 {
            prop_assert!(p.golden_ratio_bound().unwrap() <= GOLDEN * (1.0 + 1e-9));
        }
        if b.iter().all(|(_, x)| x[2] == 0.0) {
            prop_assert!((l1 - l2 - l3).abs() <= 1e3 * EPS * l1);
        }
        let z = Point::at(a.vector(z));
        let diff = (mp.inertia_about(&z) - mp.inertia_about_centre()).resolve(&a).symmetric_eigenvalues();
        prop_assert!(diff.min() >= -1e3 * EPS * mp.inertia_about(&z).norm());
        prop_assert!(mp.check(INERTIA_REL_TOL.max(1e-9)).is_ok());
    }

    #[test]
    fn frame_independence(b in body(), f in frame()) {
        // (6.2.13): the body described by the same components in frame B as in frame A has
        // J_{B′|B} = J_{B|A}: the same principal moments, and the principal frame rotates along.
        let a = Frame::new();
        let (ja, jb) = (build(&a, &b), build(&f, &b));
        let ma = ja.inertia_about_centre().resolve(&a);
        let mb = jb.inertia_about_centre().resolve(&f);
        assert_mat_rel(&mb, &ma, 1e3 * EPS);
        let (pa, pb) = (ja.principal_axes(&ja.centre_of_mass(), 1e-9).unwrap(),
                        jb.principal_axes(&jb.centre_of_mass(), 1e-9).unwrap());
        // The moments about the centre come from Σ m|r|² about the frame's origin less the
        // parallel-axis term M|r_c|²: that subtraction is exact to a few ε of Σ m|r|², which
        // for particles close together far from the origin dwarfs λ₁. A symmetric eigensolver is
        // backward stable: each moment to a few ε of the larger of the two scales.
        let raw: f64 = b.iter().map(|(m, r)| m * (r[0] * r[0] + r[1] * r[1] + r[2] * r[2])).sum();
        for k in 0..3 {
            assert_abs(pb.moments[k], pa.moments[k], 64.0 * EPS * pa.moments[0].max(raw));
        }
    }

    #[test]
    fn dipole_third_law_sums(my in direction(), mz in direction(), r in direction(), f in frame()) {
        // (6.13.12) f⃗_{z/y} = −f⃗_{y/z}; (6.13.19) τ⃗_{z/y} + τ⃗_{y/z} + r⃗_{z/y} × f⃗_{z/y} = 0⃗; in any frame.
        let (my, mz, r) = (f.vector(my), f.vector(mz), f.vector(r));
        let p = dipole_interaction(&mz, &my, &r).unwrap();
        let back = dipole_interaction(&my, &mz, &(-r)).unwrap();
        let scale = my.norm() * mz.norm() / r.norm().powi(3);
        prop_assert!((p.force_on_z + back.force_on_z).norm() <= 64.0 * EPS * scale / r.norm());
        prop_assert!((p.torque_on_y - back.torque_on_z).norm() <= 64.0 * EPS * scale);
        prop_assert!((p.torque_on_z + p.torque_on_y + p.force_pair_torque).norm() <= 256.0 * EPS * scale);
    }

    #[test]
    fn potentials_consistent_with_forces(r in direction(), k in 0.1..10.0f64, dd in 0.0..3.0f64,
                                         my in direction(), mz in direction(), g in triple()) {
        // F8.3.1: f⃗ = −∂U/∂r⃗ for the spring (8.3.12), central and mutual gravity (8.3.10),
        // uniform gravity (8.3.9) and dipoles (U = −m⃗_z·B⃗_y, (6.13.9)), with exact dual gradients.
        let a = Frame::new();
        let rv = a.vector(r);
        prop_assume!(rv.norm() > 0.3);
        let s = Spring::new(k, dd).unwrap();
        let sd = Spring::new(d(k), d(dd)).unwrap();
        assert_force_is_minus_gradient(&s.force(&rv).unwrap(), gradient(|x| sd.potential(&x), r), 1e3 * EPS);
        let cg = CentralGravity::new(k).unwrap();
        let cgd = CentralGravity::new(d(k)).unwrap();
        assert_force_is_minus_gradient(&cg.force(2.0, &rv).unwrap(),
            gradient(|x| cgd.potential(d(2.0), &x).unwrap(), r), 1e3 * EPS);
        let mg = mutual_gravitation(1.5, 2.0, k, &rv).unwrap().on_y;
        assert_force_is_minus_gradient(&mg,
            gradient(|x| mutual_gravitation_potential(d(1.5), d(2.0), d(k), &x).unwrap(), r), 1e3 * EPS);
        let fd = Frame::<Dual64>::identity();
        let ug = UniformGravity::new(fd.vector(g.map(d))).unwrap();
        assert_force_is_minus_gradient(&UniformGravity::new(a.vector(g)).unwrap().force(3.0),
            gradient(|x| ug.potential(d(3.0), &x), r), 1e3 * EPS);
        let (myd, mzd) = (fd.vector(my.map(d)), fd.vector(mz.map(d)));
        let p = dipole_interaction(&a.vector(mz), &a.vector(my), &rv).unwrap();
        let scale = 1.0 / rv.norm().powi(4);
        assert_force_is_minus_gradient(&p.force_on_z,
            gradient(|x| dipole_potential(&mzd, &myd, &x).unwrap(), r), 1e4 * EPS * scale.max(1.0));
    }

    #[test]
    fn rotational_spring_torque_is_minus_angle_derivative(theta in -3.0..3.0f64, th0 in -1.0..1.0f64, kappa in 0.1..5.0f64) {
        // (6.7.4): M⃗·ẑ = −dU/dθ with U = ½κ(θ − θ₀)².
        let a = Frame::new();
        let s = RotationalSpring::new(kappa, th0).unwrap();
        let sd = RotationalSpring::new(d(kappa), d(th0)).unwrap();
        let du = sd.potential_at_angle(Dual64::new(theta, 1.0)).eps;
        let x1 = a.vector([theta.cos(), theta.sin(), 0.0]);
        let (m1, _) = s.torques(&x1, &a.i(), &a.k()).unwrap();
        // The angle is recovered (atan2) to a few ulps of its size; the torque is κ times it.
        assert_abs(m1.dot(&a.k()), -du, 16.0 * EPS * kappa * (theta.abs() + th0.abs() + 1.0));
    }
}
