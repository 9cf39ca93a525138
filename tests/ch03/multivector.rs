//! §3.8: multivectors of Cl(3,0), the geometric product, involutions, duality by 𝒥 and the
//! Pauli-matrix representation.

use nalgebra::{Complex, Matrix2};
use vectrix::prelude::*;

use crate::common::*;

fn frame() -> Frame {
    let a = Frame::new();
    a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([-1.0, 0.5, 2.0]), 0.7).unwrap())
}

/// The eight basis blades [1, î, ĵ, k̂, î∧ĵ, ĵ∧k̂, k̂∧î, 𝒥] of (3.8.1) in frame `a`.
fn basis(a: &Frame) -> [Multivector; 8] {
    let v = |x: Vector| Multivector::from(x);
    let b = |x: Vector, y: Vector| Multivector::from(x.wedge(&y));
    [
        Multivector::scalar(1.0),
        v(a.i()),
        v(a.j()),
        v(a.k()),
        b(a.i(), a.j()),
        b(a.j(), a.k()),
        b(a.k(), a.i()),
        Multivector::from(a.i().wedge3(&a.j(), &a.k())),
    ]
}

fn axes(a: &Frame) -> [Vector; 3] {
    [a.i(), a.j(), a.k()]
}

#[test]
fn eq_3_8_3_geometric_product_of_vectors() {
    // (3.8.3): xy = x·y + x∧y; (3.8.6–9): xy + yx = 2x·y, xy − yx = 2x∧y.
    let a = frame();
    let (x, y) = (a.vector([1.0, 2.0, -1.0]), a.vector([0.5, -3.0, 2.0]));
    let (mx, my) = (Multivector::from(x), Multivector::from(y));
    let xy = mx.gp(&my);
    assert_mv_rel(&xy, &(Multivector::scalar(x.dot(&y)) + Multivector::from(x.wedge(&y))), &a, TOL);
    assert_mv_rel(&x.gp(&y), &xy, &a, TOL);
    assert_mv_rel(&(xy + my.gp(&mx)), &Multivector::scalar(2.0 * x.dot(&y)), &a, TOL);
    assert_mv_rel(&(xy - my.gp(&mx)), &Multivector::from(x.wedge(&y) * 2.0), &a, TOL);
}

#[test]
fn eq_3_8_10_square_of_a_bivector() {
    // (3.8.10): (x∧y)² = (x·y)² − x²y², a negative scalar; (3.8.38) (î∧ĵ)² = −1.
    let a = frame();
    let (x, y) = (a.vector([1.0, 2.0, -1.0]), a.vector([0.5, -3.0, 2.0]));
    let b = Multivector::from(x.wedge(&y));
    let want = x.dot(&y).powi(2) - x.norm_squared() * y.norm_squared();
    assert_mv_rel(&b.gp(&b), &Multivector::scalar(want), &a, 1e2 * TOL);
    let ij = basis(&a)[4];
    assert_mv_abs(&ij.gp(&ij), &Multivector::scalar(-1.0), &a, TOL);
}

#[test]
fn eq_3_8_12_product_of_three_vectors() {
    // (3.8.12): xyz = (y·z)x − (x·z)y + (x·y)z + x∧y∧z.
    let a = frame();
    let (x, y, z) = (a.vector([1.0, 2.0, -1.0]), a.vector([0.5, -3.0, 2.0]), a.vector([2.0, 0.0, 1.0]));
    let got = Multivector::from(x).gp(&Multivector::from(y)).gp(&Multivector::from(z));
    let vector = x * y.dot(&z) - y * x.dot(&z) + z * x.dot(&y);
    let want = Multivector::from(vector) + Multivector::from(x.wedge3(&y, &z));
    assert_mv_rel(&got, &want, &a, 1e2 * TOL);
}

#[test]
fn eq_3_8_27_pseudoscalar_squares_to_minus_one_and_is_central() {
    // (3.8.27): 𝒥² = −1, and 𝒥 commutes with every multivector (ch. 3 notes [C]).
    let a = frame();
    let j = Multivector::pseudoscalar();
    assert_mv_abs(&j.gp(&j), &Multivector::scalar(-1.0), &a, TOL);
    for e in basis(&a) {
        assert_mv_abs(&j.gp(&e), &e.gp(&j), &a, TOL);
        assert_mv_abs(&e.dual(), &j.gp(&e), &a, TOL);
        assert_mv_abs(&e.dual().undual(), &e, &a, TOL);
    }
}

#[test]
fn eq_3_8_30_duality_by_the_pseudoscalar() {
    // (3.8.30): 𝒥î = ĵ∧k̂, 𝒥ĵ = k̂∧î, 𝒥k̂ = î∧ĵ; and −𝒥(î∧ĵ) = k̂ = î×ĵ (3.8.31).
    let a = frame();
    let e = basis(&a);
    let j = Multivector::pseudoscalar();
    assert_mv_abs(&j.gp(&e[1]), &e[5], &a, TOL);
    assert_mv_abs(&j.gp(&e[2]), &e[6], &a, TOL);
    assert_mv_abs(&j.gp(&e[3]), &e[4], &a, TOL);
    assert_mv_abs(&(-j.gp(&e[4])), &Multivector::from(a.i().cross(&a.j())), &a, TOL);
}

#[test]
fn eq_3_8_31_cross_product_links() {
    // (3.8.31–32) x×y = −𝒥(x∧y), x∧y = 𝒥(x×y); (3.8.34) x×y = ½(y𝒥x − 𝒥xy);
    // (3.8.35) x·(y×z) = −(x∧y∧z)𝒥; (3.8.36) x×(y×z) = ½[(y∧z)x − x(y∧z)].
    let a = frame();
    let (x, y, z) = (a.vector([1.0, 2.0, -1.0]), a.vector([0.5, -3.0, 2.0]), a.vector([2.0, 0.0, 1.0]));
    let (mx, my) = (Multivector::from(x), Multivector::from(y));
    let j = Multivector::pseudoscalar();
    let cross = Multivector::from(x.cross(&y));
    assert_mv_rel(&(-j.gp(&Multivector::from(x.wedge(&y)))), &cross, &a, TOL);
    assert_mv_rel(&Multivector::from(x.wedge(&y)), &j.gp(&cross), &a, TOL);
    assert_mv_rel(&((my.gp(&j).gp(&mx) - j.gp(&mx).gp(&my)) * 0.5), &cross, &a, TOL);
    let triple = -Multivector::from(x.wedge3(&y, &z)).gp(&j);
    assert_mv_rel(&triple, &Multivector::scalar(x.dot(&y.cross(&z))), &a, 1e2 * TOL);
    let yz = Multivector::from(y.wedge(&z));
    let half = (yz.gp(&mx) - mx.gp(&yz)) * 0.5;
    assert_mv_rel(&half, &Multivector::from(x.cross(&y.cross(&z))), &a, 1e2 * TOL);
}

#[test]
fn eq_3_8_33_erratum_bivectrix_order() {
    // (3.8.33) must read x∧y = [ĵ∧k̂, k̂∧î, î∧ĵ] (x×y)|_A; the printed order [î∧ĵ, ĵ∧k̂, k̂∧î]
    // fails (ch. 3 notes).
    let a = frame();
    let (x, y) = (a.vector([1.0, 2.0, -1.0]), a.vector([0.5, -3.0, 2.0]));
    let c = x.cross(&y).resolve(&a);
    let e = basis(&a);
    let right = e[5] * c[0] + e[6] * c[1] + e[4] * c[2];
    assert_mv_rel(&Multivector::from(x.wedge(&y)), &right, &a, TOL);
    let printed = e[4] * c[0] + e[5] * c[1] + e[6] * c[2];
    assert!(mv_components(&printed, &a) != mv_components(&right, &a));
}

#[test]
fn fig_3_8_3_errata_products_of_bivectors() {
    // Fig. 3.8.3(a): (î∧ĵ)(ĵ∧k̂) = î∧k̂ (the book prints ĵ∧k̂); Fig. 3.8.5: σ₁(σ₁σ₂) = σ₂ and
    // (σ₁σ₂)(σ₁σ₂σ₃) = −σ₃ (the book prints ĵ and −k̂ in place of σ-names, ch. 3 notes).
    let a = frame();
    let e = basis(&a);
    let ik = Multivector::from(a.i().wedge(&a.k()));
    assert_mv_abs(&e[4].gp(&e[5]), &ik, &a, TOL);
    assert_mv_abs(&e[1].gp(&e[4]), &e[2], &a, TOL);
    assert_mv_abs(&e[4].gp(&e[7]), &(-e[3]), &a, TOL);
}

#[test]
fn fig_3_8_4_multiplication_table_through_the_pauli_isomorphism() {
    // Fig. 3.8.4, (3.8.42–49): the 8 × 8 table of basis products equals the products of their
    // Pauli matrices (1 → I₂, î → σ₁, ĵ → σ₂, k̂ → σ₃): the representation is an isomorphism.
    let a = frame();
    let e = basis(&a);
    let ax = axes(&a);
    for x in &e {
        for y in &e {
            let got = x.gp(y).to_pauli(&ax).unwrap();
            let want = x.to_pauli(&ax).unwrap() * y.to_pauli(&ax).unwrap();
            assert!((got - want).iter().all(|z| z.norm() <= TOL), "{x:?} {y:?}");
        }
    }
    // Every basis product is ± a basis blade (closure, Fig. 3.8.4).
    for x in &e {
        for y in &e {
            let c = mv_components(&x.gp(y), &a);
            let nonzero: Vec<f64> = c.iter().copied().filter(|v| v.abs() > TOL).collect();
            assert_eq!(nonzero.len(), 1);
            crate::support::assert_abs(nonzero[0].abs(), 1.0, TOL);
        }
    }
}

#[test]
fn eq_3_8_48_erratum_sigma3_sigma1() {
    // (3.8.42–48): σ₁ = [[0,1],[1,0]], σ₂ = [[0,−i],[i,0]], σ₃ = [[1,0],[0,−1]], 𝒥 ↦ iI₂, and
    // σ₃σ₁ = [[0,1],[−1,0]] = J₂ (the book prints [[−1,0],[0,1]]).
    let a = frame();
    let e = basis(&a);
    let ax = axes(&a);
    let (o, l, i) = (Complex::new(0.0, 0.0), Complex::new(1.0, 0.0), Complex::new(0.0, 1.0));
    let close = |m: Matrix2<Complex<f64>>, w: Matrix2<Complex<f64>>| (m - w).iter().all(|z| z.norm() <= TOL);
    assert!(close(e[1].to_pauli(&ax).unwrap(), Matrix2::new(o, l, l, o)));
    assert!(close(e[2].to_pauli(&ax).unwrap(), Matrix2::new(o, -i, i, o)));
    assert!(close(e[3].to_pauli(&ax).unwrap(), Matrix2::new(l, o, o, -l)));
    assert!(close(e[7].to_pauli(&ax).unwrap(), Matrix2::new(i, o, o, i)));
    assert!(close(e[3].gp(&e[1]).to_pauli(&ax).unwrap(), Matrix2::new(o, l, -l, o)));
}

#[test]
fn pauli_round_trip_and_bad_axes() {
    let a = frame();
    let m = mv(&a, 0.5, [1.0, -2.0, 0.25], [3.0, 0.0, -1.0], 0.75);
    let ax = axes(&a);
    let back = Multivector::from_pauli(&ax, &m.to_pauli(&ax).unwrap()).unwrap();
    assert_mv_rel(&back, &m, &a, TOL);
    let left = [a.i(), a.j(), -a.k()];
    assert!(matches!(m.to_pauli(&left), Err(TensorError::OutOfRange { .. })));
    let skew = [a.i(), a.i(), a.k()];
    assert!(matches!(m.to_pauli(&skew), Err(TensorError::OutOfRange { .. })));
    let nan =
        Matrix2::new(Complex::new(f64::NAN, 0.0), Complex::default(), Complex::default(), Complex::default());
    assert!(matches!(Multivector::from_pauli(&ax, &nan), Err(TensorError::NonFinite { .. })));
}

#[test]
fn eq_3_8_41_book_conjugate_versus_reverse_and_clifford_conjugate() {
    // (3.8.41): the book's conjugate negates every non-scalar component, 𝒥 included. On even
    // elements it equals the reverse and the Clifford conjugate; for a vector S S̄ = −|x|²,
    // so it is not a norm there (ch. 3 notes).
    let a = frame();
    let even = mv(&a, 0.6, [0.0; 3], [0.1, -0.7, 0.2], 0.0);
    assert_mv_abs(&even.book_conjugate(), &even.reverse(), &a, 0.0);
    assert_mv_abs(&even.book_conjugate(), &even.clifford_conjugate(), &a, 0.0);
    let x = a.vector([1.0, 2.0, 2.0]);
    let mx = Multivector::from(x);
    assert_mv_rel(&mx.gp(&mx.book_conjugate()), &Multivector::scalar(-9.0), &a, TOL);
    // The reverse is an anti-automorphism, the grade involution an automorphism, the Clifford
    // conjugate an anti-automorphism; the book's conjugate is none of these on odd elements.
    let s = mv(&a, 0.5, [1.0, -2.0, 0.25], [3.0, 0.0, -1.0], 0.75);
    let t = mv(&a, -1.0, [0.5, 0.5, 2.0], [-1.0, 1.0, 0.0], 1.5);
    assert_mv_rel(&s.gp(&t).reverse(), &t.reverse().gp(&s.reverse()), &a, 1e2 * TOL);
    assert_mv_rel(
        &s.gp(&t).grade_involution(),
        &s.grade_involution().gp(&t.grade_involution()),
        &a,
        1e2 * TOL,
    );
    assert_mv_rel(
        &s.gp(&t).clifford_conjugate(),
        &t.clifford_conjugate().gp(&s.clifford_conjugate()),
        &a,
        1e2 * TOL,
    );
    let bc = s.gp(&t).book_conjugate();
    assert!(mv_components(&bc, &a) != mv_components(&t.book_conjugate().gp(&s.book_conjugate()), &a));
    assert!(mv_components(&bc, &a) != mv_components(&s.book_conjugate().gp(&t.book_conjugate()), &a));
}

#[test]
fn eq_3_8_50_quaternion_units_as_rotors() {
    // Notes §3.9 "Quaternion conversion": R = q₀ − 𝒥q⃗ maps the Hamilton units to
    // i ↦ −𝒥î, j ↦ −𝒥ĵ, k ↦ −𝒥k̂, and then ij = k, jk = i, ki = j, ijk = −1. (The book's table
    // (3.8.50–52) maps to the conjugate; it is not used.)
    let a = frame();
    let j = Multivector::pseudoscalar();
    let (qi, qj, qk) = (-j.gp(&a.i().into()), -j.gp(&a.j().into()), -j.gp(&a.k().into()));
    assert_mv_abs(&qi.gp(&qj), &qk, &a, TOL);
    assert_mv_abs(&qj.gp(&qk), &qi, &a, TOL);
    assert_mv_abs(&qk.gp(&qi), &qj, &a, TOL);
    assert_mv_abs(&qi.gp(&qj).gp(&qk), &Multivector::scalar(-1.0), &a, TOL);
}

#[test]
fn grade_projection_and_multivector_wedge() {
    // (3.8.1) grades 0–3; the multivector wedge agrees with the vector wedges of §3.7.
    let a = frame();
    let s = mv(&a, 0.5, [1.0, -2.0, 0.25], [3.0, 0.0, -1.0], 0.75);
    let sum = s.grade(0) + s.grade(1) + s.grade(2) + s.grade(3);
    assert_mv_rel(&sum, &s, &a, 0.0);
    assert_mv_abs(&s.grade(4), &Multivector::zero(), &a, 0.0);
    let (x, y, z) = (a.vector([1.0, 2.0, 0.0]), a.vector([0.0, -1.0, 3.0]), a.vector([2.0, 0.5, 1.0]));
    let (mx, my, mz) = (Multivector::from(x), Multivector::from(y), Multivector::from(z));
    assert_mv_rel(&mx.wedge(&my), &Multivector::from(x.wedge(&y)), &a, TOL);
    assert_mv_rel(&mx.wedge(&my).wedge(&mz), &Multivector::from(x.wedge3(&y, &z)), &a, 1e2 * TOL);
}

mod prop {
    use proptest::prelude::*;
    use vectrix::prelude::*;

    use crate::common::*;
    use crate::support::{frame, triple};

    fn multivector(a: &Frame) -> impl Strategy<Value = Multivector> + use<> {
        let a = *a;
        (-2.0..2.0f64, triple(), triple(), -2.0..2.0f64).prop_map(move |(s, x, b, t)| mv(&a, s, x, b, t))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// The geometric product is associative (§3.8) and the Pauli map is a homomorphism.
        #[test]
        fn gp_associative_and_pauli(
            (a, s, t, u) in frame().prop_flat_map(|a| (Just(a), multivector(&a), multivector(&a), multivector(&a))),
        ) {
            let left = s.gp(&t).gp(&u);
            assert_mv_rel(&left, &s.gp(&t.gp(&u)), &a, 1e4 * TOL);
            let ax = [a.i(), a.j(), a.k()];
            let got = s.gp(&t).to_pauli(&ax).unwrap();
            let want = s.to_pauli(&ax).unwrap() * t.to_pauli(&ax).unwrap();
            prop_assert!((got - want).iter().all(|z| z.norm() <= 1e4 * TOL));
        }

        /// (3.8.6–12) for random vectors, frame-free: built in frame A, checked in frame B.
        #[test]
        fn vector_product_identities(a in frame(), b in frame(), x in triple(), y in triple(), z in triple()) {
            let (x, y, z) = (a.vector(x), a.vector(y), a.vector(z));
            let (mx, my, mz) = (Multivector::from(x), Multivector::from(y), Multivector::from(z));
            // x·y may cancel: the rounding error lives at the scale |x||y| of the products.
            assert_mv_abs(&(mx.gp(&my) + my.gp(&mx)), &Multivector::scalar(2.0 * x.dot(&y)), &b, TOL * x.norm() * y.norm());
            let bxy = Multivector::from(x.wedge(&y));
            let sq = x.dot(&y).powi(2) - x.norm_squared() * y.norm_squared();
            assert_mv_rel(&bxy.gp(&bxy), &Multivector::scalar(sq), &b, 1e5 * TOL);
            let want = Multivector::from(x * y.dot(&z) - y * x.dot(&z) + z * x.dot(&y)) + Multivector::from(x.wedge3(&y, &z));
            assert_mv_rel(&mx.gp(&my).gp(&mz), &want, &b, 1e5 * TOL);
        }
    }
}
