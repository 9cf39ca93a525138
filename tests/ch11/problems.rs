//! Problems 11.6.1–3 (no printed answers; each claim is checked at many random and hard
//! configurations against its closed form).

use std::f64::consts::FRAC_PI_2;

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::nalgebra::Matrix3;
use vectrix::prelude::*;
use vectrix::statics::{AppliedForce, InertiaComponents, MassProperties, Point};

use crate::support::{EPS, NanAmax, nan_max};

/// A triple of coordinates, moderate size.
fn triple() -> impl Strategy<Value = [f64; 3]> {
    [-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// P11.6.1: "the moment on B relative to w due to f⃗ applied at x does not change if f⃗ is
    /// applied instead at a particle y on the line through x parallel to f⃗":
    /// r⃗_{y/w} × f⃗ = (r⃗_{x/w} + s f⃗) × f⃗ = r⃗_{x/w} × f⃗, for s from tiny to huge.
    #[test]
    fn problem_11_6_1_force_slides_along_its_line(
        x in triple(), w in triple(), f in triple(),
        s in prop_oneof![3 => -10.0..10.0f64, 1 => Just(0.0), 1 => Just(1e-12), 1 => Just(1e6)],
    ) {
        let a = Frame::new();
        let f = a.vector(f);
        let (px, pw) = (Point::at(a.vector(x)), Point::at(a.vector(w)));
        let py = px.displaced(f * s);
        let m_x = AppliedForce::new(f, px).moment_about(&pw);
        let m_y = AppliedForce::new(f, py).moment_about(&pw);
        // the s f × f term cancels exactly in exact arithmetic; rounding of r_y is ≈ ε|s f|
        let tol = 16.0 * EPS * (x.iter().chain(w.iter()).fold(0.0f64, |m, v| nan_max(m, v.abs())) + s.abs() * f.norm()) * f.norm();
        prop_assert!((m_x - m_y).norm() <= tol, "{:?} vs {:?}", m_x, m_y);
    }

    /// P11.6.2 (Figure 11.2.2 reconstructed): the thrust F⃗_T = F_T(cos Φ_T î_AC − sin Φ_T k̂_AC)
    /// (11.2.11) acts along a line in the plane of symmetry passing at distance r_T below c.
    /// Sliding it to the foot of the perpendicular from c (P11.6.1) gives
    /// M⃗_T|_AC = (0, r_T F_T, 0), a nose-up pitching moment, wherever on the line the engine is
    /// and whatever Φ_T.
    #[test]
    fn problem_11_6_2_thrust_moment(
        ft in 0.0..1e5f64, phi_t in -FRAC_PI_2..FRAC_PI_2, r_t in 0.0..5.0f64, along in -20.0..20.0f64,
    ) {
        let ac = Frame::new();
        let dir = ac.i() * phi_t.cos() - ac.k() * phi_t.sin();
        // n̂ ⟂ the thrust line, in the plane of symmetry, on the k̂_AC (downward) side of c
        let n = ac.i() * phi_t.sin() + ac.k() * phi_t.cos();
        let engine = Point::at(n * r_t + dir * along);
        let c = Point::origin();
        let m = AppliedForce::new(dir * ft, engine).moment_about(&c).resolve(&ac);
        // distance from c to the line, frame-free
        let rel = engine.position_rel(&c);
        let dist = (rel - dir * rel.dot(&dir)).norm();
        prop_assert!((dist - r_t).abs() <= 64.0 * EPS * (r_t + along.abs()));
        let tol = 64.0 * EPS * ft * (r_t + along.abs());
        prop_assert!(m[0].abs() <= tol && m[2].abs() <= tol, "{m}");
        prop_assert!((m[1] - r_t * ft).abs() <= tol, "M_T = {} vs r_T F_T = {}", m[1], r_t * ft);
    }
}

/// P11.6.3: "assuming the symmetry of a typical aircraft, use the discrete formulas
/// (6.2.6)–(6.2.8) to show that four entries of the inertia matrix resolved in F_AC are zero."
/// A random cloud of particles mirrored in the î_AC–k̂_AC plane, (x, y, z) and (x, −y, z) with
/// equal masses: J_xy = Σm x y = 0 and J_yz = Σm y z = 0 (entries (1,2), (2,1), (2,3), (3,2)),
/// leaving the form (11.3.6); J_xz is generally nonzero.
#[test]
fn problem_11_6_3_symmetric_aircraft_has_four_zero_products() {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(64));
    let cloud = prop::collection::vec((0.1..100.0f64, triple()), 1..20);
    runner
        .run(&cloud, |half| {
            let ac = Frame::new();
            let mut particles = Vec::new();
            for (m, [x, y, z]) in &half {
                particles.push((*m, Point::at(ac.vector([*x, *y, *z]))));
                particles.push((*m, Point::at(ac.vector([*x, -*y, *z]))));
            }
            let props = MassProperties::from_particles(&particles).unwrap();
            let j = InertiaComponents::of(&props.inertia_about_centre(), &ac);
            let [jxx, jyy, jzz] = j.moments;
            let scale = jxx + jyy + jzz;
            // the mirrored pairs cancel term by term (the centre of mass lies in the plane)
            let [jxy, jxz, jyz] = j.products;
            prop_assert!(jxy.abs() <= 64.0 * EPS * scale, "J_xy = {jxy}");
            prop_assert!(jyz.abs() <= 64.0 * EPS * scale, "J_yz = {jyz}");
            let mat = j.matrix();
            for (r, c) in [(0, 1), (1, 0), (1, 2), (2, 1)] {
                prop_assert!(mat[(r, c)].abs() <= 64.0 * EPS * scale);
            }
            // the airframe of (11.3.6) has exactly this pattern
            let frame = Airframe::new(props.mass(), jxx, jyy, jzz, jxz);
            if let Ok(frame) = frame {
                let want = Matrix3::new(jxx, 0.0, -jxz, 0.0, jyy, 0.0, -jxz, 0.0, jzz);
                prop_assert!((frame.inertia_matrix() - want).nan_amax() <= 4.0 * EPS * scale);
            }
            Ok(())
        })
        .unwrap();
    // and J_xz need not vanish: two particles on a diagonal of the plane of symmetry
    let ac = Frame::new();
    let p = [(1.0, Point::at(ac.vector([1.0, 0.0, 1.0]))), (1.0, Point::at(ac.vector([-1.0, 0.0, -1.0])))];
    let j = InertiaComponents::of(&MassProperties::from_particles(&p).unwrap().inertia_about_centre(), &ac);
    assert!((j.products[1] - 2.0).abs() <= 4.0 * EPS);
}
