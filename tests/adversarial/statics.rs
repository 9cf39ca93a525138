//! vectrix-statics under hostile input (docs/robustness.md): force elements, fields and mass
//! properties either refuse their input with a typed error or return finite values with their
//! defining property (action = −reaction, inertia symmetric PSD with the triangle inequality,
//! a true result beyond f64::MAX as `Overflow`).

use crate::support::NanAmax;
use nalgebra::Matrix3;
use vectrix::frames::Frame;
use vectrix::statics::{
    AppliedForce, CentralGravity, Dashpot, ForcePair, FreeBodyProblem, Inerter, InertiaComponents,
    MassProperties, MutualGravitation, Point, PrincipalAxes, RotationalDashpot, RotationalInerter,
    RotationalSpring, Spring, StaticsError, UniformGravity, Wrench, centre_of_gravity, check_inertia,
    dipole_field, dipole_field_dyadic, dipole_interaction, dipole_potential, gravity_between,
    moment_of_inertia, mutual_gravitation, mutual_gravitation_potential, parallel_axis, particle_inertia,
    product_of_inertia, shift_inertia,
};
use vectrix::tensor::{Dyadic, Rotor, Vector};

use crate::harness::{err_or, finite, hostile, hostile3, none_or, refused};

const EPS: f64 = f64::EPSILON;
const BAD_TOLS: [f64; 4] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e-9];

fn v(x: [f64; 3]) -> Vector {
    Frame::new().vector(x)
}

/// Newton's third law for a pair: finite and f_w = −f_y.
fn action_reaction(p: &ForcePair) -> bool {
    p.on_y.is_finite() && p.on_w.is_finite() && (p.on_y + p.on_w).norm() <= 4.0 * EPS * p.on_y.norm()
}

/// A physical body: finite mass > 0, finite centre, inertia symmetric and PSD with the
/// triangle inequality (checked by the library's own validator at its default tolerance, and
/// by the moments here).
fn physical(m: &MassProperties) -> bool {
    let j = m.inertia_about_centre();
    m.mass() > 0.0
        && m.mass().is_finite()
        && m.centre_of_mass().is_finite()
        && j.is_finite()
        && j.is_symmetric(1e-12 * j.norm().max(1e-300))
        && m.check(1e-9).is_ok_and(|c| {
            let [a, b, cc] = c.moments;
            a >= -1e-9 * cc.abs() && a + b >= cc * (1.0 - 1e-9)
        })
}

cases! {
    // Springs, dashpots, inerters (§6.10, §8.x): parameters are validated; forces come in
    // action–reaction pairs; a true force beyond f64::MAX is a typed error.
    force_elements ["Spring::new", "Spring::stiffness", "Spring::relaxed_length", "Spring::force", "Spring::forces",
        "Spring::potential", "RotationalSpring::new", "RotationalSpring::torque_at_angle", "RotationalSpring::torques",
        "RotationalSpring::potential_at_angle", "Dashpot::new", "Dashpot::force", "Dashpot::forces", "Dashpot::dissipation",
        "RotationalDashpot::new", "RotationalDashpot::torques", "Inerter::new", "Inerter::force", "Inerter::forces",
        "Inerter::mass_dyadic", "RotationalInerter::new", "RotationalInerter::torques", "ForcePair::from_force_on_y"] {
        for k in hostile() {
            err_or(Spring::new(k, 1.0), "Spring::new", |s| s.stiffness().is_finite() && s.relaxed_length() == 1.0);
            err_or(Spring::new(1.0, k), "Spring::new(d)", |s| s.relaxed_length().is_finite());
            err_or(RotationalSpring::new(k, 0.0), "RotationalSpring::new", |_| true);
            err_or(Dashpot::new(k), "Dashpot::new", |_| true);
            err_or(RotationalDashpot::new(k), "RotationalDashpot::new", |_| true);
            err_or(Inerter::new(k), "Inerter::new", |_| true);
            err_or(RotationalInerter::new(k), "RotationalInerter::new", |_| true);
        }
        let spring = Spring::new(1e300, 1.0).unwrap();
        let dash = Dashpot::new(1e300).unwrap();
        let inert = Inerter::new(1e300).unwrap();
        let rs = RotationalSpring::new(1e300, 0.0).unwrap();
        let rd = RotationalDashpot::new(1e300).unwrap();
        let ri = RotationalInerter::new(1e300).unwrap();
        for x in hostile3() {
            let r = v(x);
            err_or(spring.force(&r), "Spring::force", |f| f.is_finite());
            err_or(spring.forces(&r), "Spring::forces", action_reaction);
            err_or(dash.force(&r, &v([1.0, 1.0, 0.0])), "Dashpot::force", |f| f.is_finite());
            err_or(dash.forces(&v([1.0, 0.0, 0.0]), &r), "Dashpot::forces", action_reaction);
            err_or(dash.dissipation(&v([1.0, 0.0, 0.0]), &r), "Dashpot::dissipation", |p| p.is_finite() && *p >= 0.0);
            err_or(inert.force(&v([1.0, 0.0, 0.0]), &r, &r), "Inerter::force", |f| f.is_finite());
            err_or(inert.forces(&v([1.0, 0.0, 0.0]), &r, &r), "Inerter::forces", action_reaction);
            err_or(inert.mass_dyadic(&r), "Inerter::mass_dyadic", |d| d.is_finite());
            err_or(rs.torques(&v([1.0, 0.0, 0.0]), &r, &v([0.0, 0.0, 1.0])), "RotationalSpring::torques", |(a, b)| a.is_finite() && (*a + *b).norm() <= 4.0 * EPS * a.norm());
            err_or(rd.torques(&r, &v([0.0, 0.0, 1.0])), "RotationalDashpot::torques", |(a, b)| a.is_finite() && b.is_finite());
            err_or(ri.torques(x[0], &r), "RotationalInerter::torques", |(a, b)| a.is_finite() && b.is_finite());
            err_or(rs.torque_at_angle(x[0], &v([0.0, 0.0, 1.0])), "torque_at_angle", |t| t.is_finite());
            let p = ForcePair::from_force_on_y(r);
            if r.is_finite() {
                assert!(action_reaction(&p));
            }
            if finite(&x) && x.iter().all(|c| c.abs() <= 1.0) {
                assert!(Spring::new(1.0, 1.0).unwrap().potential(&r).is_finite());
                assert!(RotationalSpring::new(1.0, 0.0).unwrap().potential_at_angle(x[0]).is_finite());
            }
        }
    }

    // Gravity and dipoles (§6.6, §6.12, §6.13): inverse-square laws at r = 1e-200 overflow into
    // a typed error; coincident points are refused; pairs obey action = −reaction.
    fields ["UniformGravity::new", "UniformGravity::acceleration", "UniformGravity::force", "UniformGravity::wrench_on",
        "UniformGravity::potential", "CentralGravity::new", "CentralGravity::of_mass", "CentralGravity::mu",
        "CentralGravity::force", "CentralGravity::potential", "mutual_gravitation", "mutual_gravitation_potential",
        "gravity_between", "centre_of_gravity", "dipole_field_dyadic", "dipole_field", "dipole_interaction", "dipole_potential",
        "MutualGravitation::new", "MutualGravitation::gmm", "MutualGravitation::force_on_y", "MutualGravitation::cast", "MutualGravitation::potential"] {
        let earth = CentralGravity::new(3.986e14).unwrap();
        // the prepared pair: every hostile G or mass is refused or gives a finite G M m ≥ 0
        for s in hostile() {
            for (g, m_y, m_x) in [(s, 1.0, 2.0), (6.674e-11, s, 2.0), (6.674e-11, 1.0, s), (s, s, s)] {
                err_or(MutualGravitation::new(g, m_y, m_x), "MutualGravitation::new", |p| {
                    p.gmm().is_finite() && p.gmm() >= 0.0 && p.cast::<f64>() == *p
                });
            }
        }
        let pair = MutualGravitation::new(6.674e-11, 1.0, 2.0).unwrap();
        assert_eq!(earth.mu(), 3.986e14);
        for s in hostile() {
            err_or(CentralGravity::new(s), "CentralGravity::new", |g| g.mu().is_finite());
            err_or(CentralGravity::of_mass(s), "CentralGravity::of_mass", |g| g.mu().is_finite());
            err_or(UniformGravity::new(v([0.0, 0.0, s])), "UniformGravity::new", |g| g.acceleration().is_finite());
        }
        let g = UniformGravity::new(v([0.0, 0.0, 9.81])).unwrap();
        let body = MassProperties::solid_sphere(2.0, 0.5, Point::origin()).unwrap();
        assert!(g.force(2.0).is_finite() && g.wrench_on(&body, Point::at(v([1.0, 0.0, 0.0]))).moment.is_finite());
        assert!(g.potential(2.0, &v([0.0, 0.0, 1.0])).is_finite());
        for x in hostile3() {
            let r = v(x);
            err_or(earth.force(1.0, &r), "CentralGravity::force", |f| f.is_finite() && f.dot(&r) <= 0.0);
            err_or(earth.potential(1.0, &r), "CentralGravity::potential", |u| u.is_finite() && *u <= 0.0);
            err_or(mutual_gravitation(6.674e-11, 1.0, 2.0, &r), "mutual_gravitation", action_reaction);
            // the prepared pair attracts (f⃗·r⃗ ≤ 0) or refuses, exactly as the checked call
            err_or(pair.force_on_y(&r), "MutualGravitation::force_on_y", |f| {
                f.is_finite() && f.dot(&r) <= 0.0 && mutual_gravitation(6.674e-11, 1.0, 2.0, &r).is_ok_and(|p| p.on_y == *f)
            });
            err_or(pair.potential(&r), "MutualGravitation::potential", |u| u.is_finite() && *u <= 0.0);
            err_or(mutual_gravitation_potential(6.674e-11, 1.0, 2.0, &r), "mutual potential", |u| u.is_finite());
            let m = v([0.0, 0.0, 1.0]);
            err_or(dipole_field_dyadic(&r), "dipole_field_dyadic", |d| d.is_finite());
            err_or(dipole_field(&m, &r), "dipole_field", |b| b.is_finite());
            err_or(dipole_interaction(&m, &m, &r), "dipole_interaction", |p| {
                p.force_on_z.is_finite() && (p.force_on_z + p.force_on_y).norm() <= 8.0 * EPS * p.force_on_z.norm()
                    && p.torque_on_z.is_finite() && p.torque_on_y.is_finite() && p.force_pair_torque.is_finite()
            });
            err_or(dipole_potential(&m, &m, &r), "dipole_potential", |u| u.is_finite());
            let pts = [(1.0, Point::at(r))];
            err_or(gravity_between(6.674e-11, &pts, &[(1.0, Point::origin())]), "gravity_between", |(f, u)| f.is_finite() && u.is_finite());
            err_or(centre_of_gravity(&pts, &[(1.0, Point::origin())]), "centre_of_gravity", |p| p.is_finite());
        }
        // The named overflow cases: r = 1e-200 makes μ/r² ≈ 4e414.
        let tiny = v([1e-200, 0.0, 0.0]);
        assert!(matches!(earth.force(1.0, &tiny), Err(StaticsError::Overflow { .. })));
        assert!(matches!(dipole_field(&v([0.0, 0.0, 1.0]), &tiny), Err(StaticsError::Overflow { .. })));
        refused(earth.force(1.0, &Vector::zero()), "force at coincident points");
        // Sums over no particles are zero (not an error); the centre of gravity is undefined.
        assert_eq!(gravity_between(6.674e-11, &[], &[]).unwrap().1, 0.0);
        refused(centre_of_gravity(&[], &[(1.0, Point::origin())]), "centre_of_gravity(empty)");
    }

    // Mass properties (§6.1–6.5, §6.14): every constructor yields a physical body or a typed
    // error (radius 1e200 overflows m r²); translations and rotations keep it physical.
    mass_properties ["MassProperties::particle", "MassProperties::from_particles", "MassProperties::new",
        "MassProperties::with_inertia_about", "MassProperties::mass", "MassProperties::centre_of_mass",
        "MassProperties::first_moment_about", "MassProperties::inertia_about_centre", "MassProperties::inertia_about",
        "MassProperties::combine", "MassProperties::composite", "MassProperties::remove", "MassProperties::translated",
        "MassProperties::rotated_by_rotor", "MassProperties::rotated_by", "MassProperties::check",
        "MassProperties::solid_sphere", "MassProperties::spherical_shell", "MassProperties::solid_box",
        "MassProperties::rectangular_plate", "MassProperties::cylinder", "MassProperties::disk", "MassProperties::thin_rod",
        "MassProperties::thin_rod_between", "MassProperties::annulus", "MassProperties::triangular_plate",
        "MassProperties::spatial_inertia", "MassProperties::principal_axes"] {
        let f = Frame::new();
        let o = Point::origin();
        let k = v([0.0, 0.0, 1.0]);
        for s in hostile() {
            err_or(MassProperties::solid_sphere(1.0, s, o), "solid_sphere", physical);
            err_or(MassProperties::solid_sphere(s, 1.0, o), "solid_sphere(m)", physical);
            err_or(MassProperties::spherical_shell(1.0, s, 0.5, o), "spherical_shell", physical);
            err_or(MassProperties::solid_box(1.0, [s, 1.0, 1.0], &f, o), "solid_box", physical);
            err_or(MassProperties::rectangular_plate(1.0, s, 1.0, &f, o), "rectangular_plate", physical);
            err_or(MassProperties::cylinder(1.0, s, 1.0, &k, o), "cylinder", physical);
            err_or(MassProperties::disk(1.0, s, &k, o), "disk", physical);
            err_or(MassProperties::thin_rod(1.0, s, &k, o), "thin_rod", physical);
            err_or(MassProperties::annulus(1.0, s, 0.0, &k, o), "annulus", physical);
            err_or(MassProperties::particle(s, o), "particle", |p| p.mass().is_finite() && p.mass() >= 0.0);
            let pts = [Point::at(v([s, 0.0, 0.0])), Point::at(v([0.0, 1.0, 0.0])), o];
            err_or(MassProperties::triangular_plate(1.0, pts), "triangular_plate", physical);
            err_or(MassProperties::thin_rod_between(1.0, &pts[0], &pts[1]), "thin_rod_between", physical);
            err_or(MassProperties::from_particles(&[(1.0, pts[0]), (1.0, pts[1])]), "from_particles", |p| p.centre_of_mass().is_finite());
            let j = Dyadic::identity() * s;
            err_or(MassProperties::new(1.0, o, j), "MassProperties::new", physical);
            err_or(MassProperties::with_inertia_about(1.0, o, &pts[1], j), "with_inertia_about", physical);
        }
        assert!(matches!(MassProperties::solid_sphere(1.0, 1e200, o), Err(StaticsError::Overflow { .. })));
        refused(MassProperties::<f64>::from_particles(&[]), "from_particles(empty)");
        let b = MassProperties::solid_box(2.0, [1.0, 2.0, 3.0], &f, Point::at(v([1.0, 0.0, 0.0]))).unwrap();
        for x in hostile3() {
            let d = v(x);
            err_or(b.translated(d), "translated", |t| physical(t) && t.mass() == b.mass());
            err_or(b.rotated_by(&f.dyadic(&Matrix3::from_diagonal(&nalgebra::Vector3::from(x))), &o, 1e-9), "rotated_by", physical);
            if d.is_finite() && x.iter().all(|c| c.abs() <= 1e100) {
                assert!(b.first_moment_about(&Point::at(d)).is_finite() && b.inertia_about(&Point::at(d)).is_finite());
                err_or(b.principal_axes(&Point::at(d), 1e-9), "principal_axes", |p| p.moments.iter().all(|m| m.is_finite() && *m >= 0.0));
                assert!(physical(&b.rotated_by_rotor(&Rotor::from_axis_angle(&k, x[0]).unwrap(), &Point::at(d))));
                let si = b.spatial_inertia(&Point::at(d));
                assert!(si.kinetic_energy(&k, &k) >= 0.0);
            }
        }
        for tol in BAD_TOLS {
            refused(b.check(tol), "check(bad tol)");
            refused(b.principal_axes(&o, tol), "principal_axes(bad tol)");
            refused(b.rotated_by(&Dyadic::identity(), &o, tol), "rotated_by(bad tol)");
        }
        let c = b.combine(&b);
        assert!(physical(&c) && (c.mass() - 4.0).abs() <= 4.0 * EPS);
        assert!(MassProperties::<f64>::composite(&[]).is_none());
        none_or(MassProperties::composite(&[b, c]), "composite", physical);
        err_or(c.remove(&b), "remove", physical);
        refused(b.remove(&c), "remove more than the body");
    }

    // Inertia algebra (§6.2–6.5): the parallel-axis theorem round trips; moments are ≥ 0 for
    // physical inertia; check_inertia refuses NaN, asymmetry and invalid tolerances; the
    // principal frame is orthonormal.
    inertia_algebra ["particle_inertia", "parallel_axis", "shift_inertia", "moment_of_inertia", "product_of_inertia",
        "InertiaComponents::of", "InertiaComponents::matrix", "InertiaComponents::to_dyadic", "check_inertia",
        "PrincipalAxes::of", "PrincipalAxes::eigenspace_projector", "PrincipalAxes::golden_ratio_bound",
        "SpatialInertia::apply", "SpatialInertia::kinetic_energy", "SpatialInertia::resolve_in"] {
        let f = Frame::new();
        let j_c = f.dyadic(&Matrix3::from_diagonal(&nalgebra::Vector3::new(1.0, 2.0, 2.5)));
        for x in hostile3() {
            let r = v(x);
            if r.is_finite() && x.iter().all(|c| c.abs() <= 1e100) {
                let jz = parallel_axis(&j_c, 3.0, &r);
                // (6.2.26): shifting back recovers J_c.
                assert!((parallel_axis(&jz, -3.0, &r) - j_c).norm() <= 64.0 * EPS * jz.norm());
                assert!(particle_inertia(2.0, &r).is_finite() && shift_inertia(&j_c, 3.0, &r, &Vector::zero()).is_finite());
                none_or(moment_of_inertia(&jz, &r), "moment_of_inertia", |m| m.is_finite() && *m >= -1e-9 * jz.norm());
                none_or(product_of_inertia(&jz, &r, &f.k()), "product_of_inertia", |p| p.is_finite());
                let comps = InertiaComponents::of(&jz, &f);
                assert!((comps.to_dyadic(&f) - jz).norm() <= 8.0 * EPS * jz.norm() && comps.matrix().iter().all(|c| c.is_finite()));
            }
            let bad = f.dyadic(&Matrix3::from_diagonal(&nalgebra::Vector3::from(x)));
            err_or(check_inertia(&bad, 1e-9), "check_inertia", |c| c.moments.iter().all(|m| m.is_finite()));
            err_or(PrincipalAxes::of(&bad, 1e-9), "PrincipalAxes::of", |p| {
                let o = p.frame.orientation_rel(&f);
                (o * o.transpose() - Matrix3::identity()).nan_amax() <= 1e-12 && p.moments.iter().all(|m| m.is_finite())
            });
        }
        for tol in BAD_TOLS {
            refused(check_inertia(&j_c, tol), "check_inertia(bad tol)");
            refused(PrincipalAxes::of(&j_c, tol), "PrincipalAxes::of(bad tol)");
        }
        let p = PrincipalAxes::of(&j_c, 1e-9).unwrap();
        assert!(p.eigenspace_projector(3).is_none() && p.eigenspace_projector(0).is_some());
        none_or(p.golden_ratio_bound(), "golden_ratio_bound", |g| g.is_finite());
        let si = MassProperties::solid_sphere(1.0, 1.0, Point::origin()).unwrap().spatial_inertia(&Point::origin());
        let (lin, ang) = si.apply(&f.i(), &f.k());
        assert!(lin.is_finite() && ang.is_finite() && si.resolve_in(&f).iter().all(|c| c.is_finite()));
    }

    // Points, wrenches, equilibrium (§6.4–6.9): shifting a wrench changes only the moment by
    // r × f; a free-body problem with wrong ids, NaN loads or invalid tolerances is refused.
    wrenches_and_free_bodies ["Point::origin", "Point::at", "Point::position", "Point::position_rel", "Point::displaced",
        "Point::distance", "Point::is_finite", "AppliedForce::new", "AppliedForce::moment_about", "Wrench::zero",
        "Wrench::from_force", "Wrench::torque", "Wrench::resultant", "Wrench::shift_to", "Wrench::plus", "Wrench::reaction",
        "Wrench::is_balanced", "Wrench::as_torque", "Wrench::compensated_torque", "Wrench::equilibrium_residual",
        "Wrench::is_in_equilibrium", "FreeBodyProblem::new", "FreeBodyProblem::add_body", "FreeBodyProblem::apply_force",
        "FreeBodyProblem::apply_couple", "FreeBodyProblem::unknown_force", "FreeBodyProblem::unknown_couple",
        "FreeBodyProblem::unknown_count", "FreeBodyProblem::solve", "FreeBodySolution::value", "FreeBodySolution::reaction",
        "FreeBodySolution::require_determinate"] {
        let o = Point::<f64>::origin();
        for x in hostile3() {
            let p = Point::at(v(x));
            assert_eq!(p.is_finite(), finite(&x));
            if finite(&x) && x.iter().all(|c| c.abs() <= 1e100) {
                assert!((p.position_rel(&o) - p.position()).norm() == 0.0);
                assert!(p.distance(&o) >= 0.0 && p.displaced(v(x)).is_finite());
                let f = AppliedForce::new(v([0.0, 0.0, 1.0]), p);
                let w = Wrench::from_force(&f, o);
                let z = Point::at(v([1.0, 2.0, 3.0]));
                // M_{/z} = M_{/o} + r_{o/z} × f
                let s = w.shift_to(&z);
                assert!((s.moment - f.moment_about(&z)).norm() <= 16.0 * EPS * s.moment.norm().max(1.0));
                assert!(w.plus(&w.reaction()).is_balanced(0.0) && w.plus(&w.reaction()).is_in_equilibrium(0.0, 1e-300));
                assert!(!w.is_balanced(f64::NAN) && w.as_torque(f64::NAN).is_none());
                let (t, comp) = w.compensated_torque(&z);
                assert!(t.is_finite() && comp.force.is_finite());
                let (rf, rm) = w.equilibrium_residual();
                assert!(rf.is_finite() && rm.is_finite());
                let r = Wrench::resultant(&[f, f], &[v(x)], o);
                assert!(r.force.is_finite() && Wrench::zero(o).force.norm() == 0.0 && Wrench::torque(v(x), o).as_torque(0.0).is_some());
            }
        }
        let mut fb = FreeBodyProblem::new();
        let b = fb.add_body();
        let ghost = FreeBodyProblem::new().add_body();
        refused(fb.apply_force(b, AppliedForce::new(v([f64::NAN, 0.0, 0.0]), o)), "apply_force(NaN)");
        refused(fb.apply_couple(b, v([0.0, f64::INFINITY, 0.0])), "apply_couple(∞)");
        refused(fb.unknown_force(b, None, Vector::zero(), o), "unknown_force(zero direction)");
        refused(fb.unknown_couple(b, None, Vector::zero()), "unknown_couple(zero axis)");
        fb.apply_force(b, AppliedForce::new(v([0.0, 0.0, -10.0]), o)).unwrap();
        let u = fb.unknown_force(b, None, v([0.0, 0.0, 1.0]), o).unwrap();
        assert_eq!(fb.unknown_count(), 1);
        for tol in BAD_TOLS {
            refused(fb.solve(tol), "solve(bad tol)");
        }
        let sol = fb.solve(1e-12).unwrap();
        assert!((sol.value(u).unwrap() - 10.0).abs() <= 16.0 * EPS * 10.0);
        assert!(sol.reaction(u).is_some_and(|r| r.is_finite()));
        let _ = sol.require_determinate();
        let _ = ghost;
    }
}
