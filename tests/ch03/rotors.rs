//! §3.9: rotors and reflections; Problem 3.10.5.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI};

use vectrix::prelude::*;

use crate::common::*;
use crate::support::{EPS, assert_abs, assert_printed_slice, assert_rel};

fn frame() -> Frame {
    let a = Frame::new();
    a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([0.3, 1.0, -0.4]), 2.2).unwrap())
}

/// Components [s, β₁, β₂, β₃] of a rotor in frame `a` (bivector by its dual vector).
fn rc(r: &Rotor, a: &Frame) -> [f64; 4] {
    let b = r.bivector().undual().resolve(a);
    [r.scalar(), b[0], b[1], b[2]]
}

#[test]
fn eq_3_9_1_quarter_turn_about_k() {
    // (3.9.1), notes §4: the rotor for 90° about k̂ is R = (1 − î∧ĵ)/√2, R î R̄ = ĵ, R ĵ R̄ = −î.
    let a = frame();
    let r = Rotor::from_axis_angle(&a.k(), FRAC_PI_2).unwrap();
    crate::support::assert_abs_slice(&rc(&r, &a), &[FRAC_1_SQRT_2, 0.0, 0.0, -FRAC_1_SQRT_2], TOL);
    assert_vec_abs(&r.sandwich(&a.i()), &a.j(), &a, TOL);
    assert_vec_abs(&r.sandwich(&a.j()), &-a.i(), &a, TOL);
    // From the plane î∧ĵ and the angle: the same rotor (3.9.1).
    let p = Rotor::from_plane_angle(&a.i(), &a.j(), FRAC_PI_2).unwrap();
    crate::support::assert_abs_slice(&rc(&p, &a), &rc(&r, &a), TOL);
}

#[test]
fn eq_3_9_1_third_turn_about_the_diagonal() {
    // Notes §4: 120° about (1,1,1)/√3 is R = ½ − ½(î∧ĵ + ĵ∧k̂ + k̂∧î), mapping î → ĵ → k̂.
    let a = frame();
    let r = Rotor::from_axis_angle(&a.vector([1.0, 1.0, 1.0]), 2.0 * PI / 3.0).unwrap();
    crate::support::assert_abs_slice(&rc(&r, &a), &[0.5, -0.5, -0.5, -0.5], TOL);
    assert_vec_abs(&r.sandwich(&a.i()), &a.j(), &a, TOL);
    assert_vec_abs(&r.sandwich(&a.j()), &a.k(), &a, TOL);
}

#[test]
fn fact_3_9_1_sandwich_is_rodrigues() {
    // Fact 3.9.1: R x R̄ = R_n̂(θ) x with Rodrigues's formula (2.11.1), n̂ = v̂×ŵ; the sandwich
    // by geometric products, the fast rotate and the rotation dyad all agree.
    let a = frame();
    let (v, w) = (a.vector([1.0, 0.0, 0.0]), a.vector([0.0, 0.6, 0.8]));
    let theta = 0.83;
    let r = Rotor::from_plane_angle(&v, &w, theta).unwrap();
    let x = a.vector([0.3, -1.2, 2.5]);
    let want = rodrigues(&v.cross(&w).resolve(&a), theta) * x.resolve(&a);
    crate::support::assert_rel_slice(r.sandwich(&x).resolve(&a).as_slice(), want.as_slice(), TOL);
    let by_gp = r.sandwich_multivector(&Multivector::from(x)).vector_part();
    assert_vec_rel(&by_gp, &r.sandwich(&x), &a, TOL);
    assert_vec_rel(&r.to_dyadic().apply(&x), &r.sandwich(&x), &a, TOL);
}

#[test]
fn eq_3_9_4_rotor_times_its_conjugate_is_one() {
    // (3.9.4): R R̄ = 1, R̄ = cos(θ/2) + sin(θ/2) v̂∧ŵ.
    let a = frame();
    let r = Rotor::from_axis_angle(&a.vector([1.0, -2.0, 0.5]), 1.9).unwrap();
    let rr = r.gp(&r.reverse());
    crate::support::assert_abs_slice(&rc(&rr, &a), &[1.0, 0.0, 0.0, 0.0], TOL);
    assert_abs(r.norm(), 1.0, TOL);
}

#[test]
fn eq_3_9_8_erratum_adjoint_of_the_sandwich() {
    // (3.9.8) as printed (bars lost), x·(R y R̄) = (R x R̄)·y, is false; the correct identity is
    // x·(R y R̄) = (R̄ x R)·y (ch. 3 notes).
    let a = frame();
    let r = Rotor::from_axis_angle(&a.vector([1.0, 2.0, 3.0]), 1.1).unwrap();
    let (x, y) = (a.vector([1.0, 0.0, 2.0]), a.vector([0.5, -1.0, 1.0]));
    assert_rel(x.dot(&r.sandwich(&y)), r.reverse().sandwich(&x).dot(&y), TOL);
    assert!((x.dot(&r.sandwich(&y)) - r.sandwich(&x).dot(&y)).abs() > 0.1);
}

#[test]
fn eq_3_9_9_rotation_preserves_the_wedge() {
    // (3.9.9): R(x∧y)R̄ = (RxR̄)∧(RyR̄).
    let a = frame();
    let r = Rotor::from_axis_angle(&a.vector([1.0, 2.0, 3.0]), -2.4).unwrap();
    let (x, y) = (a.vector([1.0, 0.0, 2.0]), a.vector([0.5, -1.0, 1.0]));
    let left = r.sandwich_bivector(&x.wedge(&y));
    let right = r.sandwich(&x).wedge(&r.sandwich(&y));
    assert_vec_rel(&left.undual(), &right.undual(), &a, TOL);
    let by_gp = r.sandwich_multivector(&Multivector::from(x.wedge(&y))).bivector_part();
    assert_vec_rel(&by_gp.undual(), &right.undual(), &a, TOL);
}

#[test]
fn eq_3_9_17_reflection_in_a_plane() {
    // (3.9.17–18), notes §4: x_refl = −n̂ x n̂ = x − 2(n̂·x)n̂; n̂ = k̂, x = (1,2,3) → (1,2,−3).
    let a = frame();
    let x = a.vector([1.0, 2.0, 3.0]);
    assert_vec_rel(&reflect(&x, &(a.k() * 4.0)).unwrap(), &a.vector([1.0, 2.0, -3.0]), &a, TOL);
    let n = a.vector([1.0, -1.0, 0.5]).unit().unwrap();
    let mn = Multivector::from(n);
    let by_gp = -mn.gp(&Multivector::from(x)).gp(&mn);
    assert_mv_rel(&by_gp, &Multivector::from(reflect(&x, &n).unwrap()), &a, TOL);
    assert!(reflect(&x, &Vector::zero()).is_none());
}

#[test]
fn fact_3_9_3_perpendicular_component() {
    // Fact 3.9.3: x_⊥ = n̂(n̂∧x) = ½(x − n̂xn̂) = x − (n̂·x)n̂, with zero grade-3 part.
    let a = frame();
    let n = a.vector([2.0, 1.0, -2.0]).unit().unwrap();
    let x = a.vector([0.3, 1.0, 4.0]);
    let mn = Multivector::from(n);
    let perp = mn.gp(&Multivector::from(n.wedge(&x)));
    assert_mv_rel(&perp, &Multivector::from(x - n * n.dot(&x)), &a, TOL);
    let half = (Multivector::from(x) - mn.gp(&Multivector::from(x)).gp(&mn)) * 0.5;
    assert_mv_rel(&half, &perp, &a, TOL);
}

#[test]
fn fact_3_9_4_two_reflections_make_a_rotation() {
    // Fact 3.9.4, (3.9.20–22), notes §4: v̂ = î, ŵ = (1,1,0)/√2 give ŵv̂ = (1 − î∧ĵ)/√2, the
    // 90° rotor about k̂ (twice the 45° angle); ŵv̂ = exp[−(v̂∧ŵ)θ/sin θ].
    let a = frame();
    let (v, w) = (a.i(), a.vector([1.0, 1.0, 0.0]));
    let r = Rotor::from_two_vectors(&v, &w).unwrap();
    crate::support::assert_abs_slice(&rc(&r, &a), &[FRAC_1_SQRT_2, 0.0, 0.0, -FRAC_1_SQRT_2], TOL);
    let (vh, wh) = (v.unit().unwrap(), w.unit().unwrap());
    let theta = vh.angle(&wh);
    let e = Rotor::exp(&(vh.wedge(&wh) * (-theta / theta.sin())));
    crate::support::assert_abs_slice(&rc(&e, &a), &rc(&r, &a), TOL);
    // Two reflections: −ŵ(−v̂ x v̂)ŵ = (ŵv̂) x (v̂ŵ).
    let x = a.vector([0.2, -0.7, 1.5]);
    let twice = reflect(&reflect(&x, &v).unwrap(), &w).unwrap();
    assert_vec_rel(&r.sandwich(&x), &twice, &a, TOL);
}

#[test]
fn from_two_vectors_is_defined_for_antiparallel_input() {
    // ŵv̂ for ŵ = −v̂ is −1: a full turn, the identity rotation (3.9.20 with θ = π).
    let a = frame();
    let v = a.vector([1.0, 2.0, -1.0]);
    let r = Rotor::from_two_vectors(&v, &(v * -3.0)).unwrap();
    crate::support::assert_abs_slice(&rc(&r, &a), &[-1.0, 0.0, 0.0, 0.0], TOL);
    assert!(Rotor::from_two_vectors(&v, &Vector::zero()).is_none());
}

#[test]
fn between_takes_one_direction_to_another() {
    // Half of (3.9.20): R = m̂v̂ with m̂ halfway between v̂ and ŵ rotates v̂ onto ŵ; anti-parallel
    // input has no unique answer (None) unless an axis hint picks the half turn.
    let a = frame();
    let (v, w) = (a.vector([1.0, 2.0, -1.0]), a.vector([-0.5, 0.1, 3.0]));
    let r = Rotor::between(&v, &w).unwrap();
    assert_vec_abs(&r.sandwich(&v.unit().unwrap()), &w.unit().unwrap(), &a, TOL);
    assert_rel(r.angle(), v.angle(&w), TOL);
    assert!(Rotor::between(&v, &(v * -2.0)).is_none());
    let h = Rotor::between_or_half_turn(&v, &(v * -2.0), &a.k()).unwrap();
    assert_vec_rel(&h.sandwich(&v), &-v, &a, TOL);
    assert_rel(h.angle(), PI, TOL);
    assert!(Rotor::between_or_half_turn(&v, &-v, &v).is_none());
    // Nearly anti-parallel: still a unit rotor taking v̂ to ŵ.
    let w2 = -v + a.vector([0.0, 1e-9, 2e-9]);
    let r2 = Rotor::between(&v, &w2).unwrap();
    assert_abs(r2.norm(), 1.0, TOL);
    // The axis comes from v × w₂, of size 10⁻⁹|v|²: its direction carries ε/10⁻⁹ ≈ 2·10⁻⁷
    // relative error, which the image inherits.
    assert_vec_abs(&r2.sandwich(&v.unit().unwrap()), &w2.unit().unwrap(), &a, 1e-6);
}

#[test]
fn composition_matches_rotation_matrices() {
    // Notes §3.9: rotor(M₁M₂) = R₁R₂, so R_{C/A} = R_{C/B}R_{B/A} (2.10.44); ±R rotate alike.
    let a = frame();
    let r1 = Rotor::from_axis_angle(&a.vector([1.0, 0.0, 1.0]), 0.7).unwrap();
    let r2 = Rotor::from_axis_angle(&a.vector([0.0, 2.0, -1.0]), -1.4).unwrap();
    let d = (r1 * r2).to_dyadic();
    assert_dyadic_abs(&d, &(r1.to_dyadic() * r2.to_dyadic()), &a, TOL);
    assert_dyadic_abs(&r2.then(&r1).to_dyadic(), &d, &a, TOL);
    let minus = Rotor::from_parts_unchecked(-r1.scalar(), -r1.bivector());
    assert_dyadic_abs(&minus.to_dyadic(), &r1.to_dyadic(), &a, TOL);
    let drift = Rotor::from_parts_unchecked(r1.scalar() * 1.001, r1.bivector() * 1.001);
    assert_abs(drift.normalize().unwrap().norm(), 1.0, TOL);
    assert!(Rotor::from_parts_unchecked(0.0, Bivector::zero()).normalize().is_none());
}

#[test]
fn exp_and_log_round_trip_over_the_hard_angles() {
    // exp(−𝒥n̂θ/2) = R_n̂(θ) (3.9.3); log returns θ ∈ [0, π] by atan2, with series near 0.
    let a = frame();
    let n = a.vector([0.48, -0.6, 0.64]);
    for &theta in &crate::support::HARD_ANGLES {
        let r = Rotor::from_axis_angle(&n, theta).unwrap();
        let b = r.log();
        let e = Rotor::exp(&b);
        // exp(log R) = ±R: at θ = π the canonical axis may pick −R (the same rotation).
        let sign =
            if rc(&e, &a).iter().zip(rc(&r, &a)).map(|(x, y)| x * y).sum::<f64>() < 0.0 { -1.0 } else { 1.0 };
        let want = rc(&r, &a).map(|x| sign * x);
        crate::support::assert_abs_slice(&rc(&e, &a), &want, 4.0 * EPS);
        // Angles in [0, π] compared absolutely: their scale is π, and θ = 1e-300 has no
        // relative accuracy to keep through the half-angle.
        assert_abs(b.area(), theta / 2.0, 4.0 * EPS);
        assert_abs(r.angle(), theta, 8.0 * EPS);
    }
    // Tiny angles keep full relative accuracy (series branch, not 1 − cos).
    let tiny = Rotor::from_axis_angle(&n, 1e-300).unwrap().log();
    assert_abs(tiny.area() / 0.5e-300, 1.0, 4.0 * EPS);
}

#[test]
fn log_at_a_half_turn_is_canonical() {
    // DESIGN §4: at θ = π, n̂ and −n̂ give the same rotation; log picks the axis whose first
    // nonzero component (reference frame) is positive, whichever sign the rotor carries.
    let a = Frame::new();
    let n = a.vector([-1.0, 2.0, 2.0]);
    let r1 = Rotor::from_axis_angle(&n, PI).unwrap();
    let r2 = Rotor::from_axis_angle(&-n, PI).unwrap();
    let r3 = Rotor::from_parts_unchecked(0.0, r1.bivector());
    let want = -(-n).unit().unwrap() * (PI / 2.0); // B = −𝒥n̂θ/2 with n̂ = (1, −2, −2)/3
    for r in [r1, r3, Rotor::from_parts_unchecked(0.0, r2.bivector())] {
        assert_vec_rel(&r.log().undual(), &want, &a, TOL);
    }
    // A rotor in the other hemisphere (s < 0) logs to the same rotation.
    let r = Rotor::from_axis_angle(&n, 1.0).unwrap();
    let neg = Rotor::from_parts_unchecked(-r.scalar(), -r.bivector());
    assert_vec_abs(&neg.log().undual(), &r.log().undual(), &a, TOL);
}

#[test]
fn problem_3_10_5_planar_rotation_by_a_complex_number() {
    // Problem 3.10.5: rotating (x, y) by θ with the complex number e^{iθ} equals the rotor
    // sandwich about k̂; θ = 0.77, (x, y) = (0.3, −1.2) → (1.050735, −0.652652) (notes §4,
    // six printed decimals); θ = π/2 takes î to ĵ.
    let a = frame();
    let (x, y, theta) = (0.3, -1.2, 0.77);
    let z = nalgebra::Complex::new(x, y) * nalgebra::Complex::from_polar(1.0, theta);
    let r = Rotor::from_axis_angle(&a.k(), theta).unwrap();
    let got = r.sandwich(&a.vector([x, y, 0.0])).resolve(&a);
    assert_rel(got[0], z.re, TOL);
    assert_abs(got[1], z.im, TOL);
    assert_printed_slice(&got.as_slice()[..2], &["1.050735", "-0.652652"]);
    let quarter = Rotor::from_axis_angle(&a.k(), FRAC_PI_2).unwrap();
    assert_vec_abs(&quarter.sandwich(&a.i()), &a.j(), &a, TOL);
}

#[test]
fn rotor_bad_inputs() {
    let a = frame();
    assert!(Rotor::from_axis_angle(&Vector::zero(), 1.0).is_none());
    assert!(Rotor::from_plane_angle(&a.i(), &(a.i() * 2.0), 1.0).is_none());
    let not_even = Multivector::from(a.i());
    assert!(matches!(Rotor::from_multivector(&not_even, 1e-12), Err(TensorError::OutOfRange { .. })));
    let not_unit = Multivector::scalar(2.0);
    assert!(matches!(Rotor::from_multivector(&not_unit, 1e-12), Err(TensorError::OutOfRange { .. })));
    let nan = Multivector::scalar(f64::NAN);
    assert!(matches!(Rotor::from_multivector(&nan, 1e-12), Err(TensorError::NonFinite { .. })));
    let r = Rotor::from_axis_angle(&a.j(), 0.4).unwrap();
    let back = Rotor::from_multivector(&r.to_multivector(), 1e-12).unwrap();
    crate::support::assert_abs_slice(&rc(&back, &a), &rc(&r, &a), TOL);
}

mod prop {
    use proptest::prelude::*;
    use vectrix::prelude::*;

    use crate::common::*;
    use crate::support::{angle, direction, frame, triple};

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// Fact 3.9.1: R x R̄ = Rodrigues (2.11.1), for hard angles, resolved in any frame B.
        #[test]
        fn sandwich_is_rodrigues(a in frame(), b in frame(), n in direction(), theta in angle(), x in triple()) {
            let (n, x) = (a.vector(n), a.vector(x));
            let r = Rotor::from_axis_angle(&n, theta).unwrap();
            let want = rodrigues(&n.resolve(&b), theta) * x.resolve(&b);
            crate::support::assert_rel_slice(r.sandwich(&x).resolve(&b).as_slice(), want.as_slice(), 64.0 * TOL);
            let by_gp = r.sandwich_multivector(&Multivector::from(x)).vector_part();
            crate::support::assert_rel_slice(by_gp.resolve(&b).as_slice(), want.as_slice(), 64.0 * TOL);
        }

        /// exp(log R) = ±R (the same rotation), θ = 2|log R| ∈ [0, π], near 0 and π included.
        #[test]
        fn exp_log_round_trip(a in frame(), n in direction(), theta in angle()) {
            let r = Rotor::from_axis_angle(&a.vector(n), theta).unwrap();
            let back = Rotor::exp(&r.log());
            assert_dyadic_abs(&back.to_dyadic(), &r.to_dyadic(), &a, 16.0 * TOL);
            // Scalar part ≥ 0 up to the rounding of |B| = π/2 at θ = π.
            prop_assert!(back.scalar() >= -4.0 * crate::support::EPS);
            // θ ∈ [0, π] absolutely (scale π), hard angles near 0 and π included.
            crate::support::assert_abs(2.0 * r.log().area(), theta.abs(), 16.0 * crate::support::EPS);
        }

        /// (3.9.9) and composition, frame-free.
        #[test]
        fn rotation_preserves_wedge_and_composes(
            n1 in direction(), t1 in angle(), n2 in direction(), t2 in angle(), x in triple(), y in triple(),
        ) {
            let a = Frame::new();
            let r1 = Rotor::from_axis_angle(&a.vector(n1), t1).unwrap();
            let r2 = Rotor::from_axis_angle(&a.vector(n2), t2).unwrap();
            let (x, y) = (a.vector(x), a.vector(y));
            let left = r1.sandwich_bivector(&x.wedge(&y)).undual();
            let right = r1.sandwich(&x).wedge(&r1.sandwich(&y)).undual();
            assert_vec_rel(&left, &right, &a, 1e3 * TOL);
            assert_vec_rel(&(r1 * r2).sandwich(&x), &r1.sandwich(&r2.sandwich(&x)), &a, 1e2 * TOL);
        }

        /// `between` takes v̂ to ŵ, including nearly parallel and nearly anti-parallel pairs.
        #[test]
        fn between_maps_direction(v in direction(), w in direction(), eps in prop::sample::select(vec![0.0, 1e-12, 1e-6, 1.0])) {
            let a = Frame::new();
            let v = a.vector(v);
            for w in [a.vector(w), -v + a.vector(w) * eps, v + a.vector(w) * eps] {
                if let Some(r) = Rotor::between(&v, &w) {
                    crate::support::assert_abs(r.norm(), 1.0, 8.0 * TOL);
                    let got = r.sandwich(&v.unit().unwrap());
                    // Conditioning near anti-parallel: the halfway direction is known to ε/|v̂+ŵ|.
                    let m = (v.unit().unwrap() + w.unit().unwrap()).norm();
                    assert_vec_abs(&got, &w.unit().unwrap(), &a, 64.0 * TOL / m.min(1.0));
                }
            }
        }
    }
}

#[test]
fn rotor_exp_has_exact_derivatives_through_the_series_branch() {
    // DESIGN §1.4: the kernel runs on dual numbers. d/dθ exp(−𝒥k̂θ/2) = −½ sin(θ/2) − ½ cos(θ/2)𝒥k̂;
    // at θ = 0 the exp uses its series branch and must still give the exact derivative
    // (scalar part 0, bivector part −½𝒥k̂).
    use vectrix::num_dual::Dual64;
    for theta in [0.0, 1e-9, 0.8, 3.0] {
        let th = Dual64::from(theta).derivative();
        let a = Frame::<Dual64>::identity();
        let k = a.k();
        let b = Bivector::dual_of(&k) * (th * Dual64::from(-0.5));
        let r = Rotor::exp(&b);
        assert_abs(r.scalar().eps, -0.5 * (theta / 2.0).sin(), 4.0 * EPS);
        let db = r.bivector().undual().resolve(&a)[2].eps;
        assert_abs(db, -0.5 * (theta / 2.0).cos(), 4.0 * EPS);
        assert_abs(r.scalar().re(), (theta / 2.0).cos(), 4.0 * EPS);
    }
}
