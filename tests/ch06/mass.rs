//! §6.1–6.3 and Problems 6.14.2–6.14.13: mass, centre of mass, inertia of particles,
//! shapes and composites.

use vectrix::nalgebra::Matrix3;
use vectrix::prelude::*;
use vectrix::statics::{InertiaComponents, MassProperties, Point, StaticsError, particle_inertia};

use crate::common::{assert_dyadic_rel, assert_mat_rel, assert_vec_abs, assert_vec_rel, diag, pt};
use crate::support::{EPS, assert_abs, assert_printed_slice, assert_rel};

/// A small asymmetric body used by several tests.
fn four_particles(a: &Frame) -> Vec<(f64, Point)> {
    vec![
        (1.0, pt(a, [1.0, 0.0, 0.0])),
        (2.0, pt(a, [0.0, 2.0, 1.0])),
        (0.5, pt(a, [-1.0, 1.0, 3.0])),
        (3.0, pt(a, [2.0, -1.0, 0.5])),
    ]
}

#[test]
fn fact_6_1_2_centre_of_mass_independent_of_reference_point() {
    // Fact 6.1.2: c and c′ computed from reference points w and w′ are colocated.
    let a = Frame::new();
    let body = four_particles(&a);
    let c = MassProperties::from_particles(&body).unwrap().centre_of_mass();
    // Re-describe every particle relative to w′ with r⃗_{w/w′} = d⃗.
    let d = a.vector([10.0, -3.0, 7.0]);
    let shifted: Vec<_> = body.iter().map(|(m, y)| (*m, y.displaced(d))).collect();
    let c2 = MassProperties::from_particles(&shifted).unwrap().centre_of_mass();
    assert_vec_abs(&(c2.position() - d), &c.position(), 16.0 * EPS);
}

#[test]
fn eq_6_1_1_6_1_6_mass_and_first_moment_about_centre() {
    // (6.1.1) m_B = Σ m_i; (6.1.6) Σ m_i r⃗_{y_i/c} = 0⃗.
    let a = Frame::new();
    let body = four_particles(&a);
    let mp = MassProperties::from_particles(&body).unwrap();
    assert_rel(mp.mass(), 6.5, EPS);
    let c = mp.centre_of_mass();
    let s = body.iter().fold(Vector::zero(), |s, (m, y)| s + y.position_rel(&c) * *m);
    assert!(s.norm() <= 16.0 * EPS, "Σ m r_(y/c) = {}", s.norm());
    // First moment about w is m_B r⃗_{c/w}.
    let w = pt(&a, [1.0, 1.0, 1.0]);
    let direct = body.iter().fold(Vector::zero(), |s, (m, y)| s + y.position_rel(&w) * *m);
    assert_vec_rel(&mp.first_moment_about(&w), &direct, 16.0 * EPS);
}

#[test]
fn eq_6_2_3_inertia_is_particle_sum() {
    // (6.2.3): J⃗_{B/z} = Σ m_i (|r⃗|²I⃗ − r⃗r⃗′), r⃗ = r⃗_{y_i/z}.
    let a = Frame::new();
    let body = four_particles(&a);
    let mp = MassProperties::from_particles(&body).unwrap();
    let z = pt(&a, [0.3, -0.2, 0.9]);
    let direct = body.iter().fold(Dyadic::zero(), |j, (m, y)| j + particle_inertia(*m, &y.position_rel(&z)));
    assert_dyadic_rel(&mp.inertia_about(&z), &direct, 64.0 * EPS);
}

#[test]
fn eq_6_2_5_sign_trap_product_of_inertia_is_positive_sum() {
    // (6.2.5)–(6.2.8): J_xy ≜ Σ m x̄ȳ, and the matrix entry is −J_xy.
    let a = Frame::new();
    let mp =
        MassProperties::from_particles(&[(1.0, pt(&a, [1.0, 2.0, 0.0])), (1.0, pt(&a, [-1.0, -2.0, 0.0]))])
            .unwrap();
    let j = mp.inertia_about_centre();
    let comps = InertiaComponents::of(&j, &a);
    // Σ m x y = 1·1·2 + 1·(−1)(−2) = 4
    assert_rel(comps.products[0], 4.0, EPS);
    assert_rel(vectrix::statics::product_of_inertia(&j, &a.i(), &a.j()).unwrap(), 4.0, EPS);
    assert_rel(j.resolve(&a)[(0, 1)], -4.0, EPS);
    assert_mat_rel(&comps.matrix(), &j.resolve(&a), EPS);
    // Round trip through the book's components in another frame.
    let b = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([1.0, 1.0, 0.0]), 0.7).unwrap());
    let cb = InertiaComponents::of(&j, &b);
    assert_dyadic_rel(&cb.to_dyadic(&b), &j, 16.0 * EPS);
}

#[test]
fn example_6_3_2_solid_sphere() {
    // (6.3.13): J_{B/c|B} = (2/5) m r² I₃ in every frame.
    let b = Frame::new()
        .rotated_by_rotor(&Rotor::from_axis_angle(&Frame::new().vector([1.0, 2.0, 3.0]), 1.1).unwrap());
    let s = MassProperties::solid_sphere(5.0, 2.0, Point::origin()).unwrap();
    assert_mat_rel(&s.inertia_about_centre().resolve(&b), &diag([8.0; 3]), 8.0 * EPS);
}

#[test]
fn example_6_3_3_box_matches_particle_lattice() {
    // (6.3.14): J = diag(m(b²+c²)/12, …). An N×N×N lattice of equal particles at cell centres
    // has exactly J_xx = m(b²(1 − 1/N²) + c²(1 − 1/N²))/12 (midpoint sums of x²), so the
    // lattice tends to the box as N grows; here it is checked exactly.
    let a = Frame::new();
    let (n, m, s) = (6usize, 12.0, [3.0, 2.0, 1.0]);
    let mut particles = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                let x = |q: usize, l: f64| (q as f64 + 0.5) / n as f64 * l - l / 2.0;
                particles.push((m / (n * n * n) as f64, pt(&a, [x(i, s[0]), x(j, s[1]), x(k, s[2])])));
            }
        }
    }
    let lattice = MassProperties::from_particles(&particles).unwrap();
    let f = 1.0 - 1.0 / (n * n) as f64;
    let want = MassProperties::solid_box(
        m,
        [s[0] * f.sqrt(), s[1] * f.sqrt(), s[2] * f.sqrt()],
        &a,
        Point::origin(),
    )
    .unwrap();
    assert_dyadic_rel(&lattice.inertia_about_centre(), &want.inertia_about_centre(), 1e3 * EPS);
}

#[test]
fn example_6_3_4_cylinder_and_erratum_6_3_15_isotropic_length() {
    // (6.3.15) ERRATUM: a cylinder with l = √3 r has J_{B/c} = ½ m r² I₃ (the printed
    // (1/5) m r² I₃ is wrong; Figure 6.2.1's text agrees with ½).
    let a = Frame::new();
    let (m, r) = (2.0, 1.5);
    let cyl = MassProperties::cylinder(m, r, 3f64.sqrt() * r, &a.i(), Point::origin()).unwrap();
    assert_mat_rel(&cyl.inertia_about_centre().resolve(&a), &diag([0.5 * m * r * r; 3]), 8.0 * EPS);
    let p = cyl.principal_axes(&cyl.centre_of_mass(), vectrix::statics::INERTIA_REL_TOL).unwrap();
    assert_eq!(p.multiplicity, [3, 3, 3]);
    // General l: axial mr²/2, transverse m(3r² + l²)/12 (6.3.15 without the special case).
    let cyl = MassProperties::cylinder(m, r, 4.0, &a.k(), Point::origin()).unwrap();
    let t = m * (3.0 * r * r + 16.0) / 12.0;
    assert_mat_rel(&cyl.inertia_about_centre().resolve(&a), &diag([t, t, m * r * r / 2.0]), 8.0 * EPS);
}

#[test]
fn problem_6_14_2_erratum_wire_triangle_centre_is_not_centroid() {
    // P6.14.2 claims particles, wire and plate share the centroid; ERRATUM: the wire frame's
    // centre is the Spieker centre. Vertices (0,0), (4,0), (0,3): centroid (4/3, 1), wire (1.5, 1).
    let a = Frame::new();
    let v = [pt(&a, [0.0, 0.0, 0.0]), pt(&a, [4.0, 0.0, 0.0]), pt(&a, [0.0, 3.0, 0.0])];
    let centroid = a.vector([4.0 / 3.0, 1.0, 0.0]);
    let particles = MassProperties::from_particles(&v.map(|p| (1.0, p))).unwrap();
    let plate = MassProperties::triangular_plate(1.0, v).unwrap();
    assert_vec_rel(&particles.centre_of_mass().position(), &centroid, 8.0 * EPS);
    assert_vec_rel(&plate.centre_of_mass().position(), &centroid, 8.0 * EPS);
    // Wire: mass proportional to length (4, 5, 3).
    let rods: Vec<_> = [(0, 1, 4.0), (1, 2, 5.0), (2, 0, 3.0)]
        .iter()
        .map(|&(i, j, l)| MassProperties::thin_rod_between(l, &v[i], &v[j]).unwrap())
        .collect();
    let wire = MassProperties::composite(&rods).unwrap();
    assert_vec_rel(&wire.centre_of_mass().position(), &a.vector([1.5, 1.0, 0.0]), 8.0 * EPS);
}

#[test]
fn problem_6_14_3_union_centre_on_segment() {
    // P6.14.3: c₃ is the centre of mass of particles m₁ at c₁ and m₂ at c₂.
    let a = Frame::new();
    let b1 = MassProperties::solid_sphere(2.0, 1.0, pt(&a, [1.0, 0.0, 0.0])).unwrap();
    let b2 = MassProperties::solid_box(6.0, [1.0, 2.0, 3.0], &a, pt(&a, [0.0, 4.0, 4.0])).unwrap();
    let c = b1.combine(&b2).centre_of_mass();
    assert_vec_rel(&c.position(), &a.vector([0.25, 3.0, 3.0]), 8.0 * EPS);
}

#[test]
fn fact_6_2_9_6_2_10_additivity_and_removal() {
    // (6.2.23) J_{B1∪B2/z} = J_{B1/z} + J_{B2/z}; (6.2.24) removal subtracts.
    let a = Frame::new();
    let body = four_particles(&a);
    let (p1, p2) = body.split_at(2);
    let (b1, b2) = (MassProperties::from_particles(p1).unwrap(), MassProperties::from_particles(p2).unwrap());
    let whole = MassProperties::from_particles(&body).unwrap();
    let z = pt(&a, [-2.0, 0.5, 1.0]);
    assert_dyadic_rel(&b1.combine(&b2).inertia_about(&z), &whole.inertia_about(&z), 64.0 * EPS);
    assert_dyadic_rel(&(b1.inertia_about(&z) + b2.inertia_about(&z)), &whole.inertia_about(&z), 64.0 * EPS);
    let back = whole.remove(&b1).unwrap();
    assert_rel(back.mass(), b2.mass(), 8.0 * EPS);
    assert_vec_rel(&back.centre_of_mass().position(), &b2.centre_of_mass().position(), 64.0 * EPS);
    assert_dyadic_rel(&back.inertia_about(&z), &b2.inertia_about(&z), 256.0 * EPS);
    // Removing more mass than there is: typed error.
    assert!(matches!(b1.remove(&whole), Err(StaticsError::RemovalExceedsMass { .. })));
}

#[test]
fn fact_6_2_11_inertia_monotone_under_inclusion() {
    // (6.2.25): B ⊂ B̃ ⇒ J_{B/z} ⪯ J_{B̃/z}.
    let a = Frame::new();
    let body = four_particles(&a);
    let part = MassProperties::from_particles(&body[1..3]).unwrap();
    let whole = MassProperties::from_particles(&body).unwrap();
    let z = pt(&a, [0.1, 0.2, 0.3]);
    let diff = whole.inertia_about(&z) - part.inertia_about(&z);
    let eig = diff.resolve(&a).symmetric_eigenvalues();
    assert!(eig.min() >= -64.0 * EPS * diff.norm(), "J̃ − J not PSD: {eig}");
}

#[test]
fn problem_6_14_8_box_inertia() {
    // P6.14.8: box a > b > c along î, ĵ, k̂; J at a face centre, an a-edge midpoint, a vertex.
    // Numbers for m = 6, (a, b, c) = (3, 2, 1): J_c = diag(2.5, 5, 6.5); the vertex matrix is
    // [[10, −9, −4.5], [−9, 20, −3], [−4.5, −3, 26]] with eigenvalues 3.41320, 25.25309, 27.33371.
    let f = Frame::new();
    let (m, a, b, c) = (6.0, 3.0, 2.0, 1.0);
    let bx = MassProperties::solid_box(m, [a, b, c], &f, Point::origin()).unwrap();
    assert_mat_rel(&bx.inertia_about_centre().resolve(&f), &diag([2.5, 5.0, 6.5]), 8.0 * EPS);
    // i) face centre (0, 0, c/2): diag(m(b²+4c²)/12, m(a²+4c²)/12, m(a²+b²)/12)
    let face = bx.inertia_about(&pt(&f, [0.0, 0.0, c / 2.0])).resolve(&f);
    let want = diag([
        m * (b * b + 4.0 * c * c) / 12.0,
        m * (a * a + 4.0 * c * c) / 12.0,
        m * (a * a + b * b) / 12.0,
    ]);
    assert_mat_rel(&face, &want, 8.0 * EPS);
    // ii) a-edge midpoint (0, b/2, c/2)
    let edge = bx.inertia_about(&pt(&f, [0.0, b / 2.0, c / 2.0])).resolve(&f);
    let jyz = m * b * c / 4.0;
    let want = Matrix3::new(
        m * (b * b + c * c) / 3.0,
        0.0,
        0.0,
        0.0,
        m * (a * a + 4.0 * c * c) / 12.0,
        -jyz,
        0.0,
        -jyz,
        m * (a * a + 4.0 * b * b) / 12.0,
    );
    assert_mat_rel(&edge, &want, 8.0 * EPS);
    // iii) vertex (a/2, b/2, c/2)
    let vertex = pt(&f, [a / 2.0, b / 2.0, c / 2.0]);
    let jv = bx.inertia_about(&vertex).resolve(&f);
    assert_mat_rel(&jv, &Matrix3::new(10.0, -9.0, -4.5, -9.0, 20.0, -3.0, -4.5, -3.0, 26.0), 8.0 * EPS);
    let p = bx.principal_axes(&vertex, vectrix::statics::INERTIA_REL_TOL).unwrap();
    // The digest prints five decimals.
    assert_printed_slice(&p.moments, &["27.33371", "25.25309", "3.41320"]);
    // Thin bar b = c → 0: J at the vertex → diag(0, ma²/3, ma²/3).
    let bar = MassProperties::thin_rod(m, a, &f.i(), Point::origin()).unwrap();
    let jb = bar.inertia_about(&pt(&f, [a / 2.0, 0.0, 0.0])).resolve(&f);
    assert_mat_rel(&jb, &diag([0.0, m * a * a / 3.0, m * a * a / 3.0]), 8.0 * EPS);
}

#[test]
fn problem_6_14_10_annulus() {
    // P6.14.10: m(R²+r²)/4 twice and m(R²+r²)/2; thin ring ½mR², ½mR², mR².
    // m = 1, R = 2, r = 1: 1.25, 1.25, 2.5. Checked also as disk(R) minus disk(r) (6.2.24) with
    // masses proportional to area.
    let a = Frame::new();
    let ring = MassProperties::annulus(1.0, 2.0, 1.0, &a.k(), Point::origin()).unwrap();
    assert_mat_rel(&ring.inertia_about_centre().resolve(&a), &diag([1.25, 1.25, 2.5]), 8.0 * EPS);
    let sigma = 1.0 / (4.0 - 1.0); // mass per unit π·area
    let big = MassProperties::disk(4.0 * sigma, 2.0, &a.k(), Point::origin()).unwrap();
    let small = MassProperties::disk(sigma, 1.0, &a.k(), Point::origin()).unwrap();
    let holed = big.remove(&small).unwrap();
    assert_dyadic_rel(&holed.inertia_about_centre(), &ring.inertia_about_centre(), 16.0 * EPS);
    let thin = MassProperties::annulus(3.0, 2.0, 2.0, &a.k(), Point::origin()).unwrap();
    assert_mat_rel(&thin.inertia_about_centre().resolve(&a), &diag([6.0, 6.0, 12.0]), 8.0 * EPS);
}

#[test]
fn problem_6_14_11_spherical_shell() {
    // P6.14.11: 2m(R⁵ − r⁵)/(5(R³ − r³)) I; m = 1, R = 2, r = 1: 62/35. Thin: 2mR²/3, with no
    // 0/0 at r = R. Cross-checked as a solid sphere minus a solid sphere (masses ∝ volume).
    let a = Frame::new();
    let shell = MassProperties::spherical_shell(1.0, 2.0, 1.0, Point::origin()).unwrap();
    assert_mat_rel(&shell.inertia_about_centre().resolve(&a), &diag([62.0 / 35.0; 3]), 8.0 * EPS);
    let rho = 1.0 / 7.0; // mass per unit (4π/3)·volume
    let hollow = MassProperties::solid_sphere(8.0 * rho, 2.0, Point::origin())
        .unwrap()
        .remove(&MassProperties::solid_sphere(rho, 1.0, Point::origin()).unwrap())
        .unwrap();
    assert_dyadic_rel(&hollow.inertia_about_centre(), &shell.inertia_about_centre(), 16.0 * EPS);
    let thin = MassProperties::spherical_shell(3.0, 2.0, 2.0, Point::origin()).unwrap();
    assert_mat_rel(&thin.inertia_about_centre().resolve(&a), &diag([8.0; 3]), 8.0 * EPS);
    let nearly = MassProperties::spherical_shell(3.0, 2.0, 2.0 - 1e-9, Point::origin()).unwrap();
    // (2/5)m(R⁵ − r⁵)/(R³ − r³) written without the cancellation:
    // (2/5)m(R⁴ + R³r + R²r² + Rr³ + r⁴)/(R² + Rr + r²), which is 8(1 − δ/R + O(δ²)).
    let (big_r, r) = (2.0f64, 2.0 - 1e-9);
    let j =
        0.4 * 3.0 * (big_r.powi(4) + big_r.powi(3) * r + (big_r * r).powi(2) + big_r * r.powi(3) + r.powi(4))
            / (big_r * big_r + big_r * r + r * r);
    assert_rel(nearly.inertia_about_centre().resolve(&a)[(0, 0)], j, 16.0 * EPS);
}

#[test]
fn problem_6_14_12_triangular_plate() {
    // P6.14.12: right triangle with legs A = 3 (x), B = 4 (y), m = 1, about c = (1, 4/3):
    // J_xx = mB²/18 = 16/18, J_yy = mA²/18 = 1/2, J_zz = m(A²+B²)/18 = 25/18, and
    // ∫ x̄ȳ dm = −mAB/36 = −1/3, so the product J_xy = −1/3 and the matrix entry is +1/3.
    let a = Frame::new();
    let plate = MassProperties::triangular_plate(
        1.0,
        [pt(&a, [0.0; 3]), pt(&a, [3.0, 0.0, 0.0]), pt(&a, [0.0, 4.0, 0.0])],
    )
    .unwrap();
    let j = plate.inertia_about_centre();
    let want = Matrix3::new(16.0 / 18.0, 1.0 / 3.0, 0.0, 1.0 / 3.0, 0.5, 0.0, 0.0, 0.0, 25.0 / 18.0);
    assert_mat_rel(&j.resolve(&a), &want, 16.0 * EPS);
    assert_abs(InertiaComponents::of(&j, &a).products[0], -1.0 / 3.0, 16.0 * EPS);
    // Isosceles: the symmetry axis ĵ is principal (Fact 6.2.15), J_xy = 0.
    let iso = MassProperties::triangular_plate(
        2.0,
        [pt(&a, [-1.0, 0.0, 0.0]), pt(&a, [1.0, 0.0, 0.0]), pt(&a, [0.0, 3.0, 0.0])],
    )
    .unwrap();
    let ji = iso.inertia_about_centre().resolve(&a);
    assert!(ji[(0, 1)].abs() <= 8.0 * EPS && ji[(0, 2)].abs() <= 8.0 * EPS);
    // The plate equals three particles of mass m/3 at the edge midpoints.
    let mid = MassProperties::from_particles(&[
        (2.0 / 3.0, pt(&a, [0.0, 0.0, 0.0])),
        (2.0 / 3.0, pt(&a, [0.5, 1.5, 0.0])),
        (2.0 / 3.0, pt(&a, [-0.5, 1.5, 0.0])),
    ])
    .unwrap();
    assert_dyadic_rel(&mid.inertia_about_centre(), &iso.inertia_about_centre(), 16.0 * EPS);
}

#[test]
fn problem_6_14_13_particle_at_z() {
    // P6.14.13: B′ = B + particle of mass m_B at z: J_{B/z} = J_{B′/c} = 2J_{B′/c′} − J_{B/c}.
    let a = Frame::new();
    let body = four_particles(&a);
    let b = MassProperties::from_particles(&body).unwrap();
    let z = pt(&a, [1.0, -2.0, 0.5]);
    let b2 = b.combine(&MassProperties::particle(b.mass(), z).unwrap());
    let jz = b.inertia_about(&z);
    assert_dyadic_rel(&b2.inertia_about(&b.centre_of_mass()), &jz, 64.0 * EPS);
    let other = b2.inertia_about_centre() * 2.0 - b.inertia_about_centre();
    assert_dyadic_rel(&other, &jz, 64.0 * EPS);
}

#[test]
fn fact_6_2_4_rotated_body() {
    // (6.2.11): rotating B by R⃗ about z gives J⃗_{B′/z′} = R⃗ J⃗_{B/z} R⃗′; checked against
    // rotating every particle.
    let a = Frame::new();
    let body = four_particles(&a);
    let r = Rotor::from_axis_angle(&a.vector([0.2, -1.0, 0.7]), 2.3).unwrap();
    let pivot = pt(&a, [0.5, 0.5, -1.0]);
    let rotated: Vec<_> =
        body.iter().map(|(m, y)| (*m, pivot.displaced(r.rotate(&y.position_rel(&pivot))))).collect();
    let want = MassProperties::from_particles(&rotated).unwrap();
    let got = MassProperties::from_particles(&body).unwrap().rotated_by_rotor(&r, &pivot);
    assert_vec_rel(&got.centre_of_mass().position(), &want.centre_of_mass().position(), 64.0 * EPS);
    assert_dyadic_rel(&got.inertia_about_centre(), &want.inertia_about_centre(), 256.0 * EPS);
    let via_dyadic = MassProperties::from_particles(&body)
        .unwrap()
        .rotated_by(&r.to_dyadic(), &pivot, vectrix::frames::ORTHONORMAL_TOL)
        .unwrap();
    assert_dyadic_rel(&via_dyadic.inertia_about_centre(), &want.inertia_about_centre(), 256.0 * EPS);
    // A reflection is not a rotation: typed error.
    let reflect = Dyadic::identity() - a.i().outer(&a.i()) * 2.0;
    assert!(matches!(
        got.rotated_by(&reflect, &pivot, vectrix::frames::ORTHONORMAL_TOL),
        Err(StaticsError::Frame(_))
    ));
}

#[test]
fn issue_33_particle_masses_summing_past_f64_max_overflow() {
    // (6.1.1): m_B = Σm_i. Finite masses whose sum exceeds f64::MAX ≈ 1.8e308 used to give
    // Ok with m_B = ∞ and a NaN centre; the sum is StaticsError::Overflow naming it
    // (docs/robustness.md §2).
    let a = Frame::new();
    let two_huge = [(f64::MAX, pt(&a, [1.0, 0.0, 0.0])), (f64::MAX, pt(&a, [0.0, 1.0, 0.0]))];
    match MassProperties::from_particles(&two_huge) {
        Err(StaticsError::Overflow { what }) => assert!(what.contains("total mass"), "{what}"),
        other => panic!("{other:?}"),
    }
    // a first moment Σm_i r_i past the range with a finite centre (m = 1e300 at 1e10): the
    // centre is the weighted mean, and the inertia about it is finite
    let p = MassProperties::from_particles(&[
        (1e300, pt(&a, [1e10, 0.0, 0.0])),
        (1e300, pt(&a, [1e10, 2.0, 0.0])),
    ])
    .unwrap();
    assert_eq!(p.mass(), 2e300);
    assert_eq!(p.centre_of_mass().position().resolve(&a).as_slice(), [1e10, 1.0, 0.0]);
    assert_rel(p.inertia_about_centre().resolve(&a)[(0, 0)], 2e300, 4.0 * EPS);
    assert_eq!(
        MassProperties::particle(1e300, pt(&a, [1e10, 0.0, 0.0])).unwrap().centre_of_mass(),
        pt(&a, [1e10, 0.0, 0.0])
    );
    // an inertia m r² past the range about a finite centre is an Overflow too
    let far = [(1e300, pt(&a, [-1e10, 0.0, 0.0])), (1e300, pt(&a, [1e10, 0.0, 0.0]))];
    assert!(matches!(MassProperties::from_particles(&far), Err(StaticsError::Overflow { .. })));
}
