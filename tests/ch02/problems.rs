//! §2.26–2.27: the theoretical ("show that") problems as numeric checks of each identity at
//! random and hard parameter values (proptest), and the applied problems whose answer follows
//! from the text. Problems already named elsewhere in this chapter (2.26.3, 6–10, 13, 19, 22,
//! 23, 2.27.1) get their property form here too.
//!
//! Probs 2.27.2–3 need the box of Fig. 2.27.1 (side lengths and vertex labels), which the text
//! does not contain: see docs/textbook.md.

use std::f64::consts::PI;

use vectrix::nalgebra::{Matrix3, Matrix4, Vector3};
use vectrix::prelude::*;

use crate::rotations::{rodrigues, rot};
use crate::support::*;

/// The resolved components of a vector in the first frame.
fn comps(x: &Vector) -> Vector3<f64> {
    x.resolve(&Frame::new())
}

/// P2.27.4: the distance the bend b of the wire a–b–c (segments ℓ₁, ℓ₂, bent by θ at b, θ = 0
/// straight) travels when the wire turns by φ about the line ac: b is at distance
/// d = ℓ₁ℓ₂ sin θ/|ac| from that line, |ac|² = ℓ₁² + ℓ₂² + 2ℓ₁ℓ₂ cos θ, so it moves along a
/// chord 2d sin(φ/2).
fn bent_wire_distance(l1: f64, l2: f64, theta: f64, phi: f64) -> f64 {
    let ac = (l1 * l1 + l2 * l2 + 2.0 * l1 * l2 * theta.cos()).sqrt();
    2.0 * l1 * l2 * theta.sin().abs() / ac * (phi / 2.0).sin().abs()
}

/// P2.27.4 with the numbers the check asks for: θ = 0 (straight wire) does not move b.
#[test]
fn problem_2_27_4_bent_wire_turned_about_its_chord() {
    // "Determine the distance from the original position of the point b to its final position
    // after the rotation. Check your solution by specializing it to the case θ = 0."
    let a = Frame::new();
    let moved = |l1: f64, l2: f64, theta: f64, phi: f64| {
        // the wire in the î–k̂ plane: a at the origin, b = ℓ₁î, c = b + ℓ₂(cos θ î + sin θ k̂)
        let b = a.vector([l1, 0.0, 0.0]);
        let c = b + a.vector([l2 * theta.cos(), 0.0, l2 * theta.sin()]);
        // counterclockwise seen from a toward c: the right-hand rule about r̂_{c/a}
        let r = Rotation::from_axis_angle(&c, phi).unwrap();
        (r.apply(&b) - b).norm()
    };
    for (l1, l2, theta, phi) in [(1.0, 2.0, 0.7, 1.1), (3.0, 0.5, 2.5, PI), (2.0, 2.0, 1.2, 0.3)] {
        assert_rel(moved(l1, l2, theta, phi), bent_wire_distance(l1, l2, theta, phi), 16.0 * EPS);
    }
    // θ = 0: b lies on the line ac and does not move
    assert_eq!(bent_wire_distance(1.0, 2.0, 0.0, 1.1), 0.0);
    assert_abs(moved(1.0, 2.0, 0.0, 1.1), 0.0, 4.0 * EPS);
}

mod prop {
    use proptest::prelude::*;

    use super::*;

    /// A rotation about a random axis by an angle biased toward 0 and π.
    fn rotation() -> impl Strategy<Value = Rotation> {
        (direction(), prop_oneof![3 => 0.0..PI, 2 => proptest::sample::select(HARD_ANGLES.to_vec())])
            .prop_map(|(n, th)| rot(&Frame::new(), n, th))
    }

    /// Entries of a nonzero vector of moderate size.
    fn vector() -> impl Strategy<Value = [f64; 3]> {
        direction()
    }

    proptest! {
        /// P2.26.1: θ_{y/x} = π/2 ⟺ x⃗·y⃗ = 0 ⟺ |x⃗ × y⃗| = |x⃗||y⃗|; for nonzero x⃗, y⃗:
        /// θ ∈ {0, π} ⟺ |x̂·ŷ| = 1 ⟺ x⃗ × y⃗ = 0 ⟺ x̂ = ±ŷ (the printed iv) "θ = π" drops the
        /// parallel case θ = 0, which v)–vii) include); and z⃗ × x⃗ = z⃗ × y⃗ = 0 with x⃗ ∦ y⃗ forces
        /// z⃗ = 0. Checked through the identities that carry each equivalence:
        /// |x⃗ × y⃗|² + (x⃗·y⃗)² = |x⃗|²|y⃗|² (Lagrange), and
        /// |z⃗ × x⃗|² + |z⃗ × y⃗|² = z⃗′[(|x⃗|² + |y⃗|²)I − x⃗x⃗′ − y⃗y⃗′]z⃗, whose matrix has
        /// determinant (|x⃗|² + |y⃗|²)|x⃗ × y⃗|² > 0 exactly when x⃗ ∦ y⃗.
        #[test]
        fn problem_2_26_1_perpendicular_parallel_and_the_zero_vector(
            x in vector(), w in vector(), s in prop_oneof![-3.0..3.0f64, Just(1.0), Just(-1.0)],
        ) {
            let a = Frame::new();
            let (x, w) = (a.vector(x), a.vector(w));
            // perpendicular: y⃗ = x⃗ × w⃗ (skip the parallel draws, where it vanishes)
            let y = x.cross(&w);
            if y.norm() > 1e-3 * x.norm() * w.norm() {
                let scale = x.norm() * y.norm();
                // the computed y⃗ carries a rounding error of a few ulps of |x⃗||w⃗| in each
                // component, so it leans out of x⃗'s normal plane by ≈ EPS |x⃗||w⃗|/|y⃗| (up to
                // 1e3 EPS for the near-parallel draws kept here): the tolerances scale with that
                let lean = x.norm() * w.norm() / y.norm();
                prop_assert!((x.angle(&y) - PI / 2.0).abs() <= 8.0 * EPS * lean);
                prop_assert!(x.dot(&y).abs() <= 8.0 * EPS * scale * lean);
                prop_assert!((x.cross(&y).norm() - scale).abs() <= 8.0 * EPS * scale);
            }
            // Lagrange's identity, which makes ii) ⟺ iii) and v) ⟺ vi)
            let lhs = x.cross(&w).norm_squared() + x.dot(&w).powi(2);
            prop_assert!((lhs - x.norm_squared() * w.norm_squared()).abs() <= 16.0 * EPS * lhs);
            // parallel or anti-parallel: y⃗ = s x⃗
            if s != 0.0 {
                let y = x * s;
                let th = x.angle(&y);
                let want = if s < 0.0 { PI } else { 0.0 };
                prop_assert!((th - want).abs() <= 4.0 * EPS, "θ = {th}");
                prop_assert!((x.unit().unwrap().dot(&y.unit().unwrap()).abs() - 1.0).abs() <= 4.0 * EPS);
                prop_assert!(x.cross(&y).norm() <= 8.0 * EPS * x.norm() * y.norm());
                let (xh, yh) = (x.unit().unwrap(), y.unit().unwrap());
                prop_assert!((xh - yh * s.signum()).norm() <= 4.0 * EPS);
            }
            // z⃗ × x⃗ = z⃗ × w⃗ = 0 ⇒ z⃗ = 0 for x⃗ ∦ w⃗: the quadratic form is positive definite
            let p = x.norm_squared() + w.norm_squared();
            let m = (Dyadic::identity() * p - x.outer(&x) - w.outer(&w)).resolve(&a);
            let det = p * x.cross(&w).norm_squared();
            prop_assert!((m.determinant() - det).abs() <= 64.0 * EPS * p.powi(3));
        }

        /// P2.26.2: the projection of x⃗ onto the line through y⃗ has length |x⃗·y⃗|/|y⃗| =
        /// |x⃗||cos θ| in both cases θ ∈ [0, π/2] and θ ∈ [π/2, π] (and symmetrically for y⃗
        /// onto the line through x⃗).
        #[test]
        fn problem_2_26_2_length_of_a_projection(x in vector(), y in vector()) {
            let a = Frame::new();
            let (x, y) = (a.vector(x), a.vector(y));
            for (u, v) in [(x, y), (y, x)] {
                let p = Dyadic::projector_along(&v).unwrap() * u;
                let want = u.dot(&v).abs() / v.norm();
                prop_assert!((p.norm() - want).abs() <= 16.0 * EPS * u.norm());
                prop_assert!((want - u.norm() * u.angle(&v).cos().abs()).abs() <= 16.0 * EPS * u.norm());
            }
        }

        /// P2.26.4: a physical matrix is fixed by its images of the three axes of any frame:
        /// M⃗ = Σᵢ (M⃗ âᵢ) âᵢ′, so M⃗âᵢ = N⃗âᵢ for i = 1, 2, 3 gives M⃗ = N⃗.
        #[test]
        fn problem_2_26_4_a_matrix_is_fixed_by_the_images_of_a_frame(
            f in frame(), x in triple(), y in triple(), z in triple(), w in triple(),
        ) {
            let a = Frame::new();
            let m = a.vector(x).outer(&a.vector(y)) + a.vector(z).outer(&a.vector(w));
            let rebuilt = [f.i(), f.j(), f.k()].iter().fold(Dyadic::zero(), |s, e| s + (m * *e).outer(e));
            let scale = m.norm();
            assert_abs_slice(rebuilt.resolve(&a).as_slice(), m.resolve(&a).as_slice(), 32.0 * EPS * scale);
        }

        /// P2.26.5: for x⃗, y⃗ in the î_A–ĵ_A plane, x₁y₂ − x₂y₁ = |x⃗||y⃗| sin θ_{y⃗/x⃗/k̂_A},
        /// anti-parallel and aligned pairs included.
        #[test]
        fn problem_2_26_5_planar_cross_term_is_the_sine_of_the_directed_angle(
            x in (-5.0..5.0f64, -5.0..5.0f64), t in -PI..PI, s in prop_oneof![0.1..4.0f64, Just(1.0)],
            flip in prop_oneof![Just(false), Just(true)],
        ) {
            let a = Frame::new();
            // y⃗ at a directed angle t from x⃗, or exactly anti-parallel
            let (c, sn) = if flip { (-1.0, 0.0) } else { (t.cos(), t.sin()) };
            let y = [s * (c * x.0 - sn * x.1), s * (sn * x.0 + c * x.1)];
            let (xv, yv) = (a.vector([x.0, x.1, 0.0]), a.vector([y[0], y[1], 0.0]));
            let th = yv.directed_angle_rel(&xv, &a.k()).unwrap();
            let lhs = x.0 * y[1] - x.1 * y[0];
            let scale = xv.norm() * yv.norm();
            prop_assert!((lhs - scale * th.sin()).abs() <= 16.0 * EPS * scale);
        }

        /// P2.26.11: every rotation matrix S is R⃗_{A/B}|_B for some frame F_B: take the frame
        /// with 𝓞_{B/A} = S (R⃗_{A/B}|_B = 𝓡_{A/B} = 𝓞_{B/A}).
        #[test]
        fn problem_2_26_11_every_rotation_matrix_is_realised_by_a_frame(r in rotation()) {
            let a = Frame::new();
            let s = r.rotation_matrix_in(&a);
            let b = Frame::from_orientation_rel(&a, &s, 1e-12).unwrap();
            let r_ab = Rotation::between(&a, &b);
            assert_abs_slice(r_ab.to_dyadic().resolve(&b).as_slice(), s.as_slice(), 16.0 * EPS);
        }

        /// P2.26.12: R⃗x⃗ = x⃗ ⟺ R⃗x⃗^× = x⃗^×R⃗. By Fact 2.9.8, R⃗x⃗^× − x⃗^×R⃗ = ((R⃗x⃗)^× − x⃗^×)R⃗,
        /// so ‖R⃗x⃗^× − x⃗^×R⃗‖_F = √2|R⃗x⃗ − x⃗|: either side vanishes exactly when the other does.
        #[test]
        fn problem_2_26_12_fixed_vector_iff_commuting_cross_matrix(r in rotation(), x in vector(), on_axis in any::<bool>()) {
            let a = Frame::new();
            let x = match (on_axis, r.axis_angle_in(&a)) {
                (true, AxisAngle::General { axis, .. } | AxisAngle::HalfTurn(axis)) => a.vector(axis.into()) * 2.5,
                _ => a.vector(x),
            };
            let rd = r.to_dyadic();
            let comm = (rd * x.cross_dyad() - x.cross_dyad() * rd).norm();
            let moved = (r.apply(&x) - x).norm();
            prop_assert!((comm - 2f64.sqrt() * moved).abs() <= 64.0 * EPS * x.norm());
        }

        /// P2.26.14: with θ_{B/A}, n_{B/A} of Fact 2.11.6: 𝓞_{A/B} n = 𝓡_{B/A} n = n,
        /// 𝓞_{B/A} n^× = n^× 𝓞_{B/A}, 𝓡_{B/A} n^× = n^× 𝓡_{B/A}.
        #[test]
        fn problem_2_26_14_the_eigenaxis_is_fixed_and_commutes(r in rotation()) {
            let a = Frame::new();
            let b = r.apply_frame(&a);
            let n = match r.axis_angle_in(&a) {
                AxisAngle::General { axis, .. } | AxisAngle::HalfTurn(axis) => axis,
                AxisAngle::Identity => Vector3::x(), // every axis is fixed by the identity
            };
            let (o_ab, o_ba, r_ba) = (a.orientation_rel(&b), b.orientation_rel(&a), b.rotation_rel(&a));
            assert_abs_slice((o_ab * n).as_slice(), n.as_slice(), 8.0 * EPS);
            assert_abs_slice((r_ba * n).as_slice(), n.as_slice(), 8.0 * EPS);
            let nx = n.cross_matrix();
            assert_abs_slice((o_ba * nx - nx * o_ba).as_slice(), Matrix3::zeros().as_slice(), 16.0 * EPS);
            assert_abs_slice((r_ba * nx - nx * r_ba).as_slice(), Matrix3::zeros().as_slice(), 16.0 * EPS);
        }

        /// P2.26.15: an orthogonal M has |det M| = 1 and |λ| = 1 for every eigenvalue; a
        /// rotation R⃗_{n̂}(θ) has eigenvalues {1, e^{jθ}, e^{−jθ}} with n̂|_A the eigenvector of 1.
        /// The rotation's eigenpairs are checked directly, R v = λ v for v = n̂ and
        /// v = (û ∓ jŵ)/√2 (û ⊥ n̂, ŵ = n̂ × û), which holds to rounding at every θ; a general
        /// eigen-solver would blur the cluster near θ = 0 (its 2 × 2-block formula cancels).
        #[test]
        fn problem_2_26_15_eigenvalues_of_orthogonal_and_rotation_matrices(
            g in proptest::array::uniform16(-2.0..2.0f64), r in rotation(),
        ) {
            prop_assume!(Matrix4::from_row_slice(&g).determinant().abs() > 1e-3);
            let q = Matrix4::from_row_slice(&g).qr().q();
            prop_assert!((q.determinant().abs() - 1.0).abs() <= 64.0 * EPS);
            // |λ| from nalgebra's real Schur form: a complex pair's |λ|² is its 2 × 2 block's
            // determinant (accurate); a real eigenvalue ±1 is a 1 × 1 block
            for z in q.complex_eigenvalues().iter() {
                prop_assert!((z.norm() - 1.0).abs() <= 1e-12, "|λ| = {}", z.norm());
            }
            let a = Frame::new();
            let m = r.rotation_matrix_in(&a);
            let th = r.angle();
            let n = match r.axis_angle_in(&a) {
                AxisAngle::General { axis, .. } | AxisAngle::HalfTurn(axis) => axis,
                AxisAngle::Identity => Vector3::z(),
            };
            assert_abs_slice((m * n).as_slice(), n.as_slice(), 8.0 * EPS);
            let u = n.cross(&if n.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() }).normalize();
            let w = n.cross(&u);
            use vectrix::nalgebra::Complex;
            let mc = m.map(|x| Complex::new(x, 0.0));
            for sign in [1.0, -1.0] {
                // v = û − j·sign·ŵ for λ = e^{j·sign·θ}
                let v = u.map(|x| Complex::new(x, 0.0)) - w.map(|x| Complex::new(0.0, sign * x));
                let lambda = Complex::new(th.cos(), sign * th.sin());
                let residual = mc * v - v * lambda;
                prop_assert!(residual.iter().all(|z| z.norm() <= 16.0 * EPS), "{residual}");
            }
        }

        /// P2.26.16: (tr R)² = tr R² + 2 tr R and (tr R)³ + 2 tr R³ = 3 (tr R)(tr R²) + 6.
        #[test]
        fn problem_2_26_16_trace_identities(r in rotation()) {
            let m = r.rotation_matrix_in(&Frame::new());
            let (t, t2, t3) = (m.trace(), (m * m).trace(), (m * m * m).trace());
            // traces lie in [−1, 3]: absolute at that scale
            assert_abs(t * t, t2 + 2.0 * t, 64.0 * EPS);
            assert_abs(t.powi(3) + 2.0 * t3, 3.0 * t * t2 + 6.0, 256.0 * EPS);
        }

        /// P2.26.17: R³ − (tr R)R² + (tr R)R − I = 0; with c = ½(tr R − 1),
        /// R⁴ − (2 + 2c)R³ + (2 + 4c)R² − (2 + 2c)R + I = 0; and for c ≠ −1
        /// (1 + 2c)/(2(1 + c)) I + (R² + R²ᵀ)/(4(1 + c)) + ½(R − Rᵀ) = R, whose terms grow like
        /// 1/(1 + c) toward θ = π (the notes: it loses accuracy there).
        #[test]
        fn problem_2_26_17_polynomial_identities(r in rotation()) {
            let m = r.rotation_matrix_in(&Frame::new());
            let (t, id) = (m.trace(), Matrix3::identity());
            let c = 0.5 * (t - 1.0);
            let zero = Matrix3::zeros();
            assert_abs_slice((m * m * m - m * m * t + m * t - id).as_slice(), zero.as_slice(), 64.0 * EPS);
            let m2 = m * m;
            let quartic = m2 * m2 - m2 * m * (2.0 + 2.0 * c) + m2 * (2.0 + 4.0 * c) - m * (2.0 + 2.0 * c) + id;
            assert_abs_slice(quartic.as_slice(), zero.as_slice(), 128.0 * EPS);
            if 1.0 + c > 1e-6 {
                let rebuilt = id * ((1.0 + 2.0 * c) / (2.0 * (1.0 + c)))
                    + (m2 + m2.transpose()) / (4.0 * (1.0 + c))
                    + (m - m.transpose()) * 0.5;
                // c is computed from tr R with error ~ε, amplified by 1/(1 + c)
                assert_abs_slice(rebuilt.as_slice(), m.as_slice(), 64.0 * EPS / (1.0 + c));
            }
        }

        /// P2.26.18: R⃗ = R⃗_{n̂}(θ), θ ∈ [0, π], is symmetric ⟺ tr R⃗ ∈ {−1, 3} ⟺ θ ∈ {0, π}:
        /// R − Rᵀ = 2 sin θ n^×, so ‖R − Rᵀ‖²_F = 8 sin²θ = 2(tr R + 1)(3 − tr R).
        #[test]
        fn problem_2_26_18_symmetric_iff_half_turn_or_identity(r in rotation()) {
            let m = r.rotation_matrix_in(&Frame::new());
            let skew = (m - m.transpose()).norm_squared();
            let t = m.trace();
            assert_abs(skew, 8.0 * r.angle().sin().powi(2), 64.0 * EPS);
            // tr R carries a few ε·3 of rounding, which |d/dt 2(t + 1)(3 − t)| ≤ 8 amplifies
            assert_abs(skew, 2.0 * (t + 1.0) * (3.0 - t), 256.0 * EPS);
            if r.angle() == 0.0 || r.angle() == PI {
                prop_assert!(skew <= 64.0 * EPS);
            }
        }

        /// P2.26.20: with origins O_A, O_B, [r_{x/O_B}|_B; 1] = [𝓞_{B/A}, r_{O_A/O_B}|_B; 0, 1]
        /// [r_{x/O_A}|_A; 1], and the inverse is [𝓞_{A/B}, −𝓞_{A/B} r_{O_A/O_B}|_B; 0, 1] =
        /// [𝓞_{A/B}, r_{O_B/O_A}|_A; 0, 1].
        #[test]
        fn problem_2_26_20_homogeneous_change_of_frame_and_its_inverse(
            b in frame(), o_b in triple(), x in triple(),
        ) {
            let a = Frame::new();
            let (r_ob_oa, r_x_oa) = (a.vector(o_b), a.vector(x));
            let r_oa_ob = -r_ob_oa;
            let r_x_ob = r_x_oa - r_ob_oa;
            let h = vectrix::rotation::homogeneous(&b.orientation_rel(&a), &r_oa_ob.resolve(&b));
            let got = h * r_x_oa.resolve(&a).push(1.0);
            let scale = r_x_oa.norm() + r_ob_oa.norm();
            assert_abs_slice(got.as_slice(), r_x_ob.resolve(&b).push(1.0).as_slice(), 16.0 * EPS * scale);
            let inv = vectrix::rotation::homogeneous(&a.orientation_rel(&b), &r_ob_oa.resolve(&a));
            let inv2 = vectrix::rotation::homogeneous(&a.orientation_rel(&b), &(-(a.orientation_rel(&b) * r_oa_ob.resolve(&b))));
            assert_abs_slice(vectrix::rotation::homogeneous_inverse(&h).as_slice(), inv.as_slice(), 16.0 * EPS * scale);
            assert_abs_slice(inv2.as_slice(), inv.as_slice(), 16.0 * EPS * scale);
            assert_abs_slice((h * inv).as_slice(), Matrix4::identity().as_slice(), 16.0 * EPS * scale);
        }

        /// P2.26.21: R⃗_{B/A}|_B = R⃗_{B/A}|_A, i) by (2.10.31), R⃗|_B = 𝓞_{B/A} R⃗|_A 𝓞_{A/B} with
        /// R⃗|_A = 𝓡_{B/A} commuting with 𝓞_{B/A} = 𝓡_{B/A}ᵀ; ii) by Rodrigues's formula, whose
        /// axis n̂ has the same components in F_A and F_B (Euler's theorem).
        #[test]
        fn problem_2_26_21_rotation_matrix_is_the_same_in_both_frames(r in rotation()) {
            let a = Frame::new();
            let b = r.apply_frame(&a);
            let rd = Rotation::between(&b, &a).to_dyadic();
            let (in_a, in_b) = (rd.resolve(&a), rd.resolve(&b));
            assert_abs_slice(in_b.as_slice(), in_a.as_slice(), 16.0 * EPS);
            let o_ba = b.orientation_rel(&a);
            assert_abs_slice((o_ba * in_a * o_ba.transpose()).as_slice(), in_a.as_slice(), 16.0 * EPS);
            if let AxisAngle::General { axis, angle } = r.axis_angle_in(&a) {
                let n_b = a.vector(axis.into()).resolve(&b);
                assert_abs_slice(n_b.as_slice(), axis.as_slice(), 8.0 * EPS);
                assert_abs_slice(rodrigues(&n_b, angle).as_slice(), in_b.as_slice(), 16.0 * EPS);
            }
        }

        /// P2.26.6 (Jacobi): x⃗ × (y⃗ × z⃗) + y⃗ × (z⃗ × x⃗) + z⃗ × (x⃗ × y⃗) = 0, the terms of size
        /// |x⃗||y⃗||z⃗| cancelling to rounding.
        #[test]
        fn problem_2_26_6_jacobi_identity_everywhere(x in vector(), y in vector(), z in vector()) {
            let a = Frame::new();
            let (x, y, z) = (a.vector(x), a.vector(y), a.vector(z));
            let sum = x.cross(&y.cross(&z)) + y.cross(&z.cross(&x)) + z.cross(&x.cross(&y));
            prop_assert!(sum.norm() <= 32.0 * EPS * x.norm() * y.norm() * z.norm());
        }

        /// P2.26.7: P_{y−P_z y} + P_z equals the printed closed form and is symmetric in y⃗, z⃗,
        /// for non-parallel y⃗, z⃗ (the denominator |y|²|z|² − (y·z)² is |y × z|²).
        #[test]
        fn problem_2_26_7_plane_projector_everywhere(y in vector(), z in vector()) {
            let a = Frame::new();
            let (y, z) = (a.vector(y), a.vector(z));
            let den = y.cross(&z).norm_squared();
            prop_assume!(den > 1e-4 * y.norm_squared() * z.norm_squared());
            let p = |u: &Vector| Dyadic::projector_along(u).unwrap();
            let lhs = p(&(y - p(&z) * y)) + p(&z);
            let rhs = (y.outer(&y) * z.norm_squared() - (y.outer(&z) + z.outer(&y)) * y.dot(&z)
                + z.outer(&z) * y.norm_squared())
                * (1.0 / den);
            let other = p(&(z - p(&y) * z)) + p(&y);
            // conditioning 1/sin²θ_{y,z} ≤ 10⁴ by the assumption
            let tol = 64.0 * EPS * y.norm_squared() * z.norm_squared() / den;
            assert_abs_slice(lhs.resolve(&a).as_slice(), rhs.resolve(&a).as_slice(), tol);
            assert_abs_slice(lhs.resolve(&a).as_slice(), other.resolve(&a).as_slice(), tol);
        }

        /// P2.26.8 (corrected, notes ch1-2a §4d: P_y should be P_v): u⃗ = x⃗, v⃗ = (I − P_x)y⃗,
        /// w⃗ = (I − P_x − P_v)z⃗ are mutually orthogonal for independent x⃗, y⃗, z⃗.
        #[test]
        fn problem_2_26_8_gram_schmidt_everywhere(x in vector(), y in vector(), z in vector()) {
            let a = Frame::new();
            let (x, y, z) = (a.vector(x), a.vector(y), a.vector(z));
            prop_assume!(x.triple(&y, &z).abs() > 1e-2 * x.norm() * y.norm() * z.norm());
            let p = |u: &Vector| Dyadic::projector_along(u).unwrap();
            let (u, v) = (x, (Dyadic::identity() - p(&x)) * y);
            let w = (Dyadic::identity() - p(&x) - p(&v)) * z;
            for (s, t) in [(u, v), (u, w), (v, w)] {
                prop_assert!(s.dot(&t).abs() <= 1e3 * EPS * s.norm() * t.norm().max(z.norm()));
            }
        }

        /// P2.26.13: R⃗_{S⃗n̂}(θ) = S⃗R⃗_{n̂}(θ)S⃗′.
        #[test]
        fn problem_2_26_13_conjugated_axis_everywhere(n in direction(), th in angle(), s in rotation()) {
            let a = Frame::new();
            let n = a.vector(n);
            let lhs = Rotation::from_axis_angle(&s.apply(&n), th).unwrap().to_dyadic();
            let sd = s.to_dyadic();
            let rhs = sd * Rotation::from_axis_angle(&n, th).unwrap().to_dyadic() * sd.coform();
            assert_abs_slice(lhs.resolve(&a).as_slice(), rhs.resolve(&a).as_slice(), 32.0 * EPS);
        }

        /// P2.26.19: y⃗ = R⃗x⃗ + αw⃗ is [ỹ; α] = [R̃, w̃; 0, 1][x̃; α] in any frame.
        #[test]
        fn problem_2_26_19_homogeneous_form_everywhere(r in rotation(), f in frame(), x in triple(), w in triple(), alpha in -3.0..3.0f64) {
            let (x, w) = (f.vector(x), f.vector(w));
            let y = r.apply(&x) + w * alpha;
            let h = vectrix::rotation::homogeneous(&r.to_dyadic().resolve(&f), &w.resolve(&f));
            let mut xa = x.resolve(&f).push(alpha);
            xa = h * xa;
            let scale = x.norm() + alpha.abs() * w.norm() + 1.0;
            assert_abs_slice(xa.as_slice(), y.resolve(&f).push(alpha).as_slice(), 16.0 * EPS * scale);
        }

        /// P2.27.4 at random wires and turns: the bend moves 2 ℓ₁ℓ₂|sin θ|/|ac| · |sin(φ/2)|.
        #[test]
        fn problem_2_27_4_bent_wire_everywhere(
            l1 in 0.1..5.0f64, l2 in 0.1..5.0f64, theta in prop_oneof![-3.0..3.0f64, Just(0.0)], phi in -PI..PI,
        ) {
            let a = Frame::new();
            let b = a.vector([l1, 0.0, 0.0]);
            let c = b + a.vector([l2 * theta.cos(), 0.0, l2 * theta.sin()]);
            let moved = (Rotation::from_axis_angle(&c, phi).unwrap().apply(&b) - b).norm();
            prop_assert!((moved - bent_wire_distance(l1, l2, theta, phi)).abs() <= 64.0 * EPS * (l1 + l2));
        }
    }

    /// Rotations at exactly the hard angles for the trace and symmetry identities (2.26.15–18).
    #[test]
    fn problems_2_26_15_to_18_at_the_hard_angles() {
        let a = Frame::new();
        for &th in &HARD_ANGLES {
            let r = rot(&a, [1.0, -2.0, 0.5], th);
            let m = r.rotation_matrix_in(&a);
            let t = m.trace();
            assert_abs(t * t, (m * m).trace() + 2.0 * t, 64.0 * EPS);
            let skew = (m - m.transpose()).norm_squared();
            assert_abs(skew, 2.0 * (t + 1.0) * (3.0 - t), 256.0 * EPS);
        }
        // the identity and the half turn are the symmetric rotations; tr = 3 and −1
        let half = rot(&a, [1.0, -2.0, 0.5], PI).rotation_matrix_in(&a);
        assert_abs(half.trace(), -1.0, 4.0 * EPS);
        assert_abs_slice(half.as_slice(), half.transpose().as_slice(), 4.0 * EPS);
        assert_eq!(comps(&Rotation::identity().apply(&a.i())), Vector3::x());
    }
}
