//! §6.2 and §7.10: principal axes, validation of inertia (Facts 6.2.6–6.2.8), Figure 6.2.1,
//! Problems 6.14.7 and 6.14.9, parallel-axis and general shifts, spatial inertia.

use vectrix::prelude::*;
use vectrix::statics::{
    INERTIA_REL_TOL, InertiaComponents, MassProperties, Point, PrincipalAxes, StaticsError, check_inertia,
    parallel_axis, shift_inertia,
};

use crate::common::{
    assert_dyadic_abs, assert_dyadic_rel, assert_mat_rel, assert_vec_abs, assert_vec_rel, diag, pt,
};
use crate::support::{EPS, assert_abs, assert_rel};

const GOLDEN: f64 = 1.618_033_988_749_895;

fn tilted() -> Frame {
    let a = Frame::new();
    a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([1.0, -2.0, 0.5]), 0.9).unwrap())
}

#[test]
fn fact_6_2_6_principal_axes_form_a_rotation_that_diagonalises() {
    // Fact 6.2.6: a rotation S diagonalises J (use −S if det S = −1); the principal moments
    // are the eigenvalues. Here the box is given in a tilted frame; the principal frame is
    // right-handed and J resolved in it is diag(λ1, λ2, λ3), λ1 ≥ λ2 ≥ λ3.
    let b = tilted();
    let bx = MassProperties::solid_box(12.0, [3.0, 2.0, 1.0], &b, Point::origin()).unwrap();
    let p = bx.principal_axes(&bx.centre_of_mass(), INERTIA_REL_TOL).unwrap();
    assert_abs(p.frame.i().triple(&p.frame.j(), &p.frame.k()), 1.0, 8.0 * EPS);
    let d = bx.inertia_about_centre().resolve(&p.frame);
    assert_mat_rel(&d, &diag([13.0, 10.0, 5.0]), 64.0 * EPS);
    assert_eq!((p.rank, p.multiplicity), (3, [1, 1, 1]));
    // Each principal axis is parallel to a box edge.
    for (axis, edge) in [(p.frame.i(), b.k()), (p.frame.j(), b.j()), (p.frame.k(), b.i())] {
        assert_abs(axis.dot(&edge).abs(), 1.0, 64.0 * EPS);
    }
}

#[test]
fn problem_6_14_7_cube_every_frame_principal() {
    // P6.14.7: for a homogeneous cube every frame is a principal-axis frame relative to c.
    let cube = MassProperties::solid_box(6.0, [2.0; 3], &tilted(), Point::origin()).unwrap();
    for f in [Frame::new(), tilted()] {
        assert_mat_rel(&cube.inertia_about_centre().resolve(&f), &diag([4.0; 3]), 16.0 * EPS);
    }
    let p = cube.principal_axes(&Point::origin(), INERTIA_REL_TOL).unwrap();
    assert_eq!(p.multiplicity, [3, 3, 3]);
    assert_dyadic_abs(&p.eigenspace_projector(1).unwrap(), &Dyadic::identity(), 16.0 * EPS);
}

#[test]
fn principal_axes_axisymmetric_repeated_moment() {
    // Repeated principal moments: a disk has a double moment; its eigenspace is the plane
    // of the disk, its lone axis the normal n̂. Compare projectors, not vectors.
    let n = tilted().k();
    let disk = MassProperties::disk(4.0, 1.0, &n, Point::origin()).unwrap();
    let p = disk.principal_axes(&Point::origin(), INERTIA_REL_TOL).unwrap();
    // λ = mr²/2 = 2 about n̂, mr²/4 = 1 twice.
    assert_eq!(p.multiplicity, [1, 2, 2]);
    assert_moments(p.moments, [2.0, 1.0, 1.0]);
    assert_dyadic_abs(&p.eigenspace_projector(0).unwrap(), &n.outer(&n), 16.0 * EPS);
    assert_dyadic_abs(&p.eigenspace_projector(2).unwrap(), &(Dyadic::identity() - n.outer(&n)), 16.0 * EPS);
    assert!(p.eigenspace_projector(3).is_none());
}

/// Principal moments to 16 ε of the largest (a backward-stable eigensolver's accuracy).
#[track_caller]
fn assert_moments(got: [f64; 3], want: [f64; 3]) {
    crate::support::assert_rel_slice(&got, &want, 16.0 * EPS);
}

#[test]
fn fact_6_2_7_ranks_and_zero_moments() {
    // Fact 6.2.7: J = 0 iff a single particle at z (rank 0); rank 2 iff z and all particles are
    // collinear; never rank 1; PD with two independent position vectors.
    let a = tilted();
    let one = MassProperties::particle(2.0, pt(&a, [1.0, 2.0, 3.0])).unwrap();
    let p0 = one.principal_axes(&one.centre_of_mass(), INERTIA_REL_TOL).unwrap();
    assert_eq!((p0.rank, p0.moments), (0, [0.0; 3]));
    let rod = MassProperties::thin_rod(3.0, 2.0, &a.j(), Point::origin()).unwrap();
    let p2 = rod.principal_axes(&Point::origin(), INERTIA_REL_TOL).unwrap();
    assert_eq!(p2.rank, 2);
    assert_eq!(p2.moments[2], 0.0, "the axial moment of a thin rod is exactly 0");
    assert_dyadic_abs(&p2.eigenspace_projector(2).unwrap(), &a.j().outer(&a.j()), 16.0 * EPS);
    // Dumbbell through z: collinear ⇒ rank 2; z off the line ⇒ PD.
    let bell =
        MassProperties::from_particles(&[(1.0, pt(&a, [1.0, 1.0, 0.0])), (2.0, pt(&a, [-1.0, -1.0, 0.0]))])
            .unwrap();
    assert_eq!(bell.principal_axes(&pt(&a, [3.0, 3.0, 0.0]), INERTIA_REL_TOL).unwrap().rank, 2);
    assert_eq!(bell.principal_axes(&pt(&a, [0.0, 1.0, 0.0]), INERTIA_REL_TOL).unwrap().rank, 3);
}

#[test]
fn fact_6_2_7_and_6_2_8_invalid_inertia_is_rejected() {
    // User-given inertia must be PSD, of rank ≠ 1 and satisfy λ1 ≤ λ2 + λ3 (6.2.19).
    let a = tilted();
    let c = Point::origin();
    let e = |d: [f64; 3]| MassProperties::new(1.0, c, a.dyadic(&diag(d)));
    assert!(matches!(e([1.0, 0.0, 0.0]), Err(StaticsError::RankOne { .. })));
    assert!(matches!(e([1.0, 1.0, -0.5]), Err(StaticsError::NotPositiveSemidefinite { .. })));
    assert!(matches!(e([3.0, 1.0, 1.0]), Err(StaticsError::TriangleInequality { .. })));
    assert!(e([2.0, 1.0, 1.0]).is_ok(), "a thin plate sits on the boundary λ1 = λ2 + λ3");
    let skew = a.dyadic(&diag([2.0, 2.0, 2.0])) + a.i().outer(&a.j());
    assert!(matches!(MassProperties::new(1.0, c, skew), Err(StaticsError::NotSymmetric { .. })));
    let nan = a.dyadic(&diag([f64::NAN, 1.0, 1.0]));
    assert!(matches!(check_inertia(&nan, INERTIA_REL_TOL), Err(StaticsError::NonFinite { .. })));
    // Mass errors.
    let j = a.dyadic(&diag([2.0, 2.0, 2.0]));
    assert!(matches!(MassProperties::new(-1.0, c, j), Err(StaticsError::InvalidMass { .. })));
    assert!(matches!(MassProperties::new(f64::INFINITY, c, j), Err(StaticsError::InvalidMass { .. })));
    assert!(matches!(MassProperties::new(0.0, c, j), Err(StaticsError::ZeroMass { .. })));
    assert!(matches!(MassProperties::particle(f64::NAN, c), Err(StaticsError::InvalidMass { .. })));
    assert!(matches!(
        MassProperties::from_particles(&[(0.0, c), (0.0, pt(&a, [1.0, 0.0, 0.0]))]),
        Err(StaticsError::ZeroMass { .. })
    ));
    assert!(matches!(MassProperties::solid_sphere(1.0, -1.0, c), Err(StaticsError::OutOfRange { .. })));
    assert!(matches!(
        MassProperties::annulus(1.0, 1.0, 2.0, &a.k(), c),
        Err(StaticsError::OutOfRange { .. })
    ));
    assert!(matches!(
        MassProperties::disk(1.0, 1.0, &Vector::zero(), c),
        Err(StaticsError::ZeroVector { .. })
    ));
}

#[test]
fn user_given_inertia_about_another_point() {
    // (6.2.26) backwards: J about a vertex given by the user recovers J_c.
    let a = Frame::new();
    let bx = MassProperties::solid_box(6.0, [3.0, 2.0, 1.0], &a, Point::origin()).unwrap();
    let v = pt(&a, [1.5, 1.0, 0.5]);
    let jv = InertiaComponents { moments: [10.0, 20.0, 26.0], products: [9.0, 4.5, 3.0] }.to_dyadic(&a);
    let user = MassProperties::with_inertia_about(6.0, Point::origin(), &v, jv).unwrap();
    assert_dyadic_rel(&user.inertia_about_centre(), &bx.inertia_about_centre(), 64.0 * EPS);
}

#[test]
fn figure_6_2_1_shapes_of_principal_moments() {
    // Figure 6.2.1: moment → shape. λ given; the shapes reproduce it.
    let (a, m, lam) = (Frame::new(), 2.0f64, 3.0f64);
    let o = Point::origin();
    let moments = |mp: &MassProperties| mp.principal_axes(&o, INERTIA_REL_TOL).unwrap().moments;
    // Sphere R = √(5λ/2m), cube L = √(6λ/m): λ1 = λ2 = λ3 = λ.
    assert_moments(moments(&MassProperties::solid_sphere(m, (2.5 * lam / m).sqrt(), o).unwrap()), [lam; 3]);
    assert_moments(
        moments(&MassProperties::solid_box(m, [(6.0 * lam / m).sqrt(); 3], &a, o).unwrap()),
        [lam; 3],
    );
    // Centroid box: L = √(8λ1/m), √(4λ1/m), √(2λ1/m) gives λ1 = 6λ2/5 = 2λ3.
    let s = [(8.0 * lam / m).sqrt(), (4.0 * lam / m).sqrt(), (2.0 * lam / m).sqrt()];
    assert_moments(
        moments(&MassProperties::solid_box(m, s, &a, o).unwrap()),
        [lam, lam * 5.0 / 6.0, lam / 2.0],
    );
    // ERRATUM (Fig 6.2.1, l.7702): the cylinder with L/R = 3 and λ1 = λ2 = 2λ3 has R = √(λ1/m),
    // not the printed √(2λ1/m).
    let r = (lam / m).sqrt();
    let cyl = MassProperties::cylinder(m, r, 3.0 * r, &a.i(), o).unwrap();
    assert_moments(moments(&cyl), [lam, lam, lam / 2.0]);
    // Thin disk R = √(2λ1/m): λ1 = 2λ2 = 2λ3. Rod L = √(12λ1/m): λ1 = λ2, λ3 = 0.
    let disk = MassProperties::disk(m, (2.0 * lam / m).sqrt(), &a.k(), o).unwrap();
    assert_moments(moments(&disk), [lam, lam / 2.0, lam / 2.0]);
    let rod = MassProperties::thin_rod(m, (12.0 * lam / m).sqrt(), &a.k(), o).unwrap();
    assert_moments(moments(&rod), [lam, lam, 0.0]);
    // Plate with sides √(12λ2/m) > √(12λ3/m): on the boundary λ1 = λ2 + λ3.
    let plate = MassProperties::rectangular_plate(m, (12.0 * 2.0 / m).sqrt(), (12.0 * 1.0 / m).sqrt(), &a, o)
        .unwrap();
    assert_moments(moments(&plate), [3.0, 2.0, 1.0]);
}

#[test]
fn problem_6_14_9_golden_ratio_plate() {
    // P6.14.9: a plate with a = √((1+√5)/2) b has J2 = √(J1 J3), and (6.2.16) holds with
    // equality: min{J2/J3, J1/J2} = (1+√5)/2.
    let b = 1.3;
    let plate =
        MassProperties::rectangular_plate(2.0, GOLDEN.sqrt() * b, b, &tilted(), Point::origin()).unwrap();
    let p = plate.principal_axes(&Point::origin(), INERTIA_REL_TOL).unwrap();
    let [j1, j2, j3] = p.moments;
    assert_abs(j2 * j2, j1 * j3, 16.0 * EPS);
    assert_rel(p.golden_ratio_bound().unwrap(), GOLDEN, 16.0 * EPS);
    assert_rel(j2 / j3, GOLDEN, 16.0 * EPS);
    assert_rel(j1 / j2, GOLDEN, 16.0 * EPS);
}

#[test]
fn eq_6_2_26_parallel_axis_and_eq_6_2_29_general_shift() {
    // (6.2.26) J_z = J_c + m(|r|²I − rr′), r = r_{z/c}: J_z ⪰ J_c (6.2.27); (6.2.29) shifts
    // between two arbitrary points and agrees with going through c.
    let a = tilted();
    let bx = MassProperties::solid_box(6.0, [3.0, 2.0, 1.0], &a, pt(&a, [1.0, 2.0, 3.0])).unwrap();
    let (z1, z2) = (pt(&a, [-1.0, 0.5, 2.0]), pt(&a, [4.0, -3.0, 0.0]));
    let c = bx.centre_of_mass();
    let j1 = bx.inertia_about(&z1);
    let j2 = shift_inertia(&j1, bx.mass(), &z2.position_rel(&z1), &c.position_rel(&z1));
    assert_dyadic_rel(&j2, &bx.inertia_about(&z2), 256.0 * EPS);
    assert_dyadic_rel(&parallel_axis(&bx.inertia_about_centre(), 6.0, &z1.position_rel(&c)), &j1, 64.0 * EPS);
    let diff = (j1 - bx.inertia_about_centre()).resolve(&a).symmetric_eigenvalues();
    assert!(diff.min() >= -64.0 * EPS * j1.norm());
    // Fact 6.2.14: scalar form about an axis î ⊥ r⃗_{z/c}: J_xx,z = J_xx,c + m|r|².
    let z = c.displaced(a.j() * 2.0);
    assert_rel(
        vectrix::statics::moment_of_inertia(&bx.inertia_about(&z), &a.i()).unwrap(),
        vectrix::statics::moment_of_inertia(&bx.inertia_about_centre(), &a.i()).unwrap() + 6.0 * 4.0,
        64.0 * EPS,
    );
}

#[test]
fn eq_7_10_8_spatial_inertia() {
    // (7.10.8): 𝒥_{B/z} = [[mI, −m r×_{c/z}], [m r×_{c/z}, J_z]]; 𝒥𝒱 = [m v_c; H_{/z}] and
    // ½𝒱ᵀ𝒥𝒱 = ½m|v_c|² + ½ω′J_cω (8.1.19).
    let a = tilted();
    let bx = MassProperties::solid_box(6.0, [3.0, 2.0, 1.0], &a, pt(&a, [1.0, 0.0, 0.5])).unwrap();
    let z = pt(&a, [0.0, 1.0, -1.0]);
    let s = bx.spatial_inertia(&z);
    let (v_z, w) = (a.vector([0.3, -1.0, 2.0]), a.vector([1.0, 0.5, -0.2]));
    let r = bx.centre_of_mass().position_rel(&z);
    let v_c = v_z + w.cross(&r);
    let (p, h) = s.apply(&v_z, &w);
    assert_vec_rel(&p, &(v_c * 6.0), 64.0 * EPS);
    // H_{/z} = J_c ω + r_{c/z} × m v_c
    let h_want = bx.inertia_about_centre().apply(&w) + r.cross(&(v_c * 6.0));
    assert_vec_rel(&h, &h_want, 256.0 * EPS);
    let t = 0.5 * 6.0 * v_c.norm_squared() + 0.5 * w.dot(&bx.inertia_about_centre().apply(&w));
    assert_rel(s.kinetic_energy(&v_z, &w), t, 256.0 * EPS);
    // Blocks of the 6×6 matrix.
    let m6 = s.resolve_in(&a);
    assert_mat_rel(&m6.fixed_view::<3, 3>(0, 0).into_owned(), &diag([6.0; 3]), EPS);
    assert_mat_rel(&m6.fixed_view::<3, 3>(3, 3).into_owned(), &bx.inertia_about(&z).resolve(&a), 64.0 * EPS);
    assert_mat_rel(
        &m6.fixed_view::<3, 3>(3, 0).into_owned(),
        &(-m6.fixed_view::<3, 3>(0, 3).into_owned()),
        EPS,
    );
    assert!((m6 - m6.transpose()).norm() <= 64.0 * EPS * m6.norm());
}

#[test]
fn principal_axes_of_an_explicit_dyadic() {
    // Fact 6.2.6 for a dyadic given directly.
    let a = tilted();
    let j = a.dyadic(&diag([1.0, 3.0, 2.0]));
    let p = PrincipalAxes::of(&j, INERTIA_REL_TOL).unwrap();
    assert_moments(p.moments, [3.0, 2.0, 1.0]);
    assert_abs(p.frame.i().dot(&a.j()).abs(), 1.0, 16.0 * EPS);
    assert_vec_abs(&j.apply(&p.frame.k()), &p.frame.k(), 16.0 * EPS);
}
