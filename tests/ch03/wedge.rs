//! §3.7: alternating tensors and the wedge product, determinant convention (3.7.17), with
//! magnitudes as area and volume.

use vectrix::prelude::*;

use crate::common::*;
use crate::support::{assert_abs, assert_rel, assert_rel_slice};

fn rotated() -> Frame {
    let a = Frame::new();
    a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([2.0, -1.0, 0.5]), 1.3).unwrap())
}

#[test]
fn eq_3_7_1_wedge_of_two_vectors_is_the_antisymmetric_product() {
    // (3.7.1): x∧y = x⊗y − y⊗x (no ½), alternating (3.7.15).
    let a = rotated();
    let (x, y) = (a.vector([1.0, 2.0, -1.0]), a.vector([0.5, -3.0, 2.0]));
    let xy = Tensor::from_factors(&[x, y], &[]).unwrap();
    let yx = Tensor::from_factors(&[y, x], &[]).unwrap();
    assert_tensor_rel(&x.wedge(&y).to_tensor(), &xy.try_sub(&yx).unwrap(), &a, TOL);
    assert!(x.wedge(&y).to_tensor().is_alternating(TOL));
    assert!(!xy.is_alternating(TOL));
    // The dense permutation sum (3.7.17) agrees with the compressed formula.
    let dense = Tensor::from_vector(&x).wedge(&Tensor::from_vector(&y)).unwrap();
    assert_tensor_rel(&dense, &x.wedge(&y).to_tensor(), &a, TOL);
}

#[test]
fn eq_3_7_9_magnitude_is_the_parallelogram_area() {
    // (3.7.9–10): |x∧y| = |x||y| sin θ = |x×y|. Notes §4: x = (1,2,0), y = (3,1,0) give
    // x∧y = −5 î∧ĵ, resolved 9-vector (0,−5,0, 5,0,0, 0,0,0) with ‖·‖ = 5√2 but area 5.
    let a = Frame::new();
    let (x, y) = (a.vector([1.0, 2.0, 0.0]), a.vector([3.0, 1.0, 0.0]));
    let b = x.wedge(&y);
    assert_vec_rel(&b.undual(), &(a.k() * -5.0), &a, TOL); // −5 î∧ĵ = −5 𝒥k̂
    let dense = b.to_tensor();
    assert_rel_slice(&flat(&dense.resolve(&a)), &[0.0, -5.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0], TOL);
    assert_rel(dense.frobenius_norm(), 5.0 * 2f64.sqrt(), TOL);
    assert_rel(b.area(), 5.0, TOL);
    assert_rel(dense.alternating_magnitude(), 5.0, TOL);
    assert_rel(b.area(), x.norm() * y.norm() * x.angle(&y).sin(), TOL);
}

#[test]
fn fact_3_7_2_wedge_in_a_coordinate_plane() {
    // Fact 3.7.2: for x, y in the (î, ĵ) plane, x∧y = (x₁y₂ − x₂y₁) î∧ĵ.
    let a = rotated();
    let (x, y) = (a.vector([1.5, -0.5, 0.0]), a.vector([2.0, 3.0, 0.0]));
    let ij = a.i().wedge(&a.j());
    let want = ij * (1.5 * 3.0 - (-0.5) * 2.0);
    assert_vec_rel(&x.wedge(&y).undual(), &want.undual(), &a, TOL);
}

#[test]
fn fact_3_7_3_wedge_vanishes_exactly_for_colinear_vectors() {
    // Fact 3.7.3: x∧y ≠ 0 iff x, y are not colinear; x∧x = 0 (3.7.2).
    let a = rotated();
    let x = a.vector([1.0, 2.0, 3.0]);
    assert_eq!(x.wedge(&x).area(), 0.0);
    assert_eq!(x.wedge(&(x * -2.0)).area(), 0.0);
    assert!(x.wedge(&a.vector([1.0, 2.0, 3.0 + 1e-9])).area() > 0.0);
}

#[test]
fn wedge_of_nearly_parallel_vectors_keeps_relative_accuracy() {
    // Notes §3 "Cancellation": x₁y₂ − x₂y₁ by fused differences of products. For
    // x = (1, 1+δ, 0), y = (1, 1, 0) (exact binary numbers) the area is exactly δ.
    let a = Frame::new();
    let delta = 2f64.powi(-40);
    let x = a.vector([1.0 + 2f64.powi(-30), 1.0 + 2f64.powi(-30) + delta, 0.0]);
    let y = a.vector([1.0, 1.0, 0.0]);
    // x₁y₂ − x₂y₁ = (1+2⁻³⁰) − (1+2⁻³⁰+δ) = −δ exactly.
    assert_eq!(x.wedge(&y).undual().resolve(&a)[2], -delta);
}

#[test]
fn eq_3_7_7_resolved_wedge_is_vec_of_the_cross_matrix() {
    // (3.7.7–8): (x∧y)|_A = vec[(x×y)^×|_A] = vec[(y x′ − x y′)|_A], vec stacking columns. The
    // book's last printed form vec(x y′ − y x′) has the wrong sign (ch. 3 notes).
    let a = rotated();
    let (x, y) = (a.vector([1.0, -2.0, 0.5]), a.vector([0.3, 1.0, 2.0]));
    let got = flat(&x.wedge(&y).to_tensor().resolve(&a));
    let cross = x.cross(&y).cross_dyad().resolve(&a);
    assert_rel_slice(&got, cross.as_slice(), TOL);
    let yx_xy = (y.outer(&x) - x.outer(&y)).resolve(&a);
    assert_rel_slice(&got, yx_xy.as_slice(), TOL);
}

#[test]
fn eq_3_7_20_triple_wedge_is_the_determinant_times_j() {
    // (3.7.11), (3.7.20–21), (3.7.23), (3.7.26): x∧y∧z = det[x y z] 𝒥 = ((x×y)·z) 𝒥;
    // x = (1,0,0), y = (1,1,0), z = (1,1,1) give 𝒥; ‖(î∧ĵ∧k̂)|_A‖ = √6 but volume 1.
    let a = rotated();
    let (x, y, z) = (a.vector([1.0, 0.0, 0.0]), a.vector([1.0, 1.0, 0.0]), a.vector([1.0, 1.0, 1.0]));
    let t = x.wedge3(&y, &z);
    assert_abs(t.coefficient(), 1.0, TOL);
    assert_abs(t.volume(), 1.0, TOL);
    let dense = Tensor::from_vector(&x)
        .wedge(&Tensor::from_vector(&y))
        .unwrap()
        .wedge(&Tensor::from_vector(&z))
        .unwrap();
    assert_tensor_abs(&dense, &t.to_tensor(), &a, TOL);
    assert_rel(dense.frobenius_norm(), 6f64.sqrt(), TOL);
    assert_abs(dense.alternating_magnitude(), 1.0, TOL);
    let (u, v, w) = (a.vector([0.3, -1.0, 2.0]), a.vector([1.5, 0.2, 0.7]), a.vector([-0.4, 0.9, 1.1]));
    assert_rel(u.wedge3(&v, &w).coefficient(), u.cross(&v).dot(&w), TOL);
}

#[test]
fn fact_3_7_5_pseudoscalar_is_the_same_in_every_right_handed_frame() {
    // Fact 3.7.5: 𝒥 = î_A∧ĵ_A∧k̂_A for every right-handed A; a reflection flips the sign.
    for a in [Frame::new(), rotated()] {
        let j = a.i().wedge3(&a.j(), &a.k());
        assert_abs(j.coefficient(), Trivector::<f64>::j().coefficient(), TOL);
        assert_abs(a.i().wedge3(&a.j(), &-a.k()).coefficient(), -1.0, TOL);
    }
}

#[test]
fn eq_3_7_18_wedge_is_associative() {
    // (3.7.18–19): (x∧y)∧z = x∧(y∧z), dense and compressed.
    let a = rotated();
    let (x, y, z) = (a.vector([1.0, 2.0, 0.0]), a.vector([0.0, -1.0, 3.0]), a.vector([2.0, 0.5, 1.0]));
    let (tx, ty, tz) = (Tensor::from_vector(&x), Tensor::from_vector(&y), Tensor::from_vector(&z));
    let left = tx.wedge(&ty).unwrap().wedge(&tz).unwrap();
    let right = tx.wedge(&ty.wedge(&tz).unwrap()).unwrap();
    assert_tensor_rel(&left, &right, &a, TOL);
    assert_rel(x.wedge(&y).wedge(&z).coefficient(), x.wedge_bivector(&y.wedge(&z)).coefficient(), TOL);
}

#[test]
fn problem_3_10_3_graded_commutativity() {
    // Problem 3.10.3: T₁∧T₂ = (−1)^{p₁p₂} T₂∧T₁, checked for grades (1,1), (1,2), (2,1).
    let a = rotated();
    let (x, y, z) = (a.vector([1.0, 2.0, 0.0]), a.vector([0.0, -1.0, 3.0]), a.vector([2.0, 0.5, 1.0]));
    let (tx, tyz) = (Tensor::from_vector(&x), y.wedge(&z).to_tensor());
    let ty = Tensor::from_vector(&y);
    assert_tensor_rel(&tx.wedge(&ty).unwrap(), &-&ty.wedge(&tx).unwrap(), &a, TOL);
    assert_tensor_rel(&tx.wedge(&tyz).unwrap(), &tyz.wedge(&tx).unwrap(), &a, TOL);
}

#[test]
fn problem_3_10_2_bicovector_evaluation() {
    // Problem 3.10.2 (typo fixed): (x∧y)′(z, w) = (x×y)·(z×w) = (x·z)(y·w) − (y·z)(x·w); the
    // book's last factor "(x·y)" reads (x·w). With the order-preserving coform.
    let a = rotated();
    let (x, y, z, w) = (
        a.vector([1.0, 2.0, 0.0]),
        a.vector([0.0, -1.0, 3.0]),
        a.vector([2.0, 0.5, 1.0]),
        a.vector([1.0, 1.0, -2.0]),
    );
    let got = x.wedge(&y).to_tensor().coform().eval(&[], &[z, w]).unwrap();
    assert_rel(got, x.cross(&y).dot(&z.cross(&w)), TOL);
    assert_rel(got, x.dot(&z) * y.dot(&w) - y.dot(&z) * x.dot(&w), TOL);
}

#[test]
fn eq_3_7_28_erratum_coform_of_a_wedge() {
    // (3.7.28) prints x′∧y′ = −(x∧y)′, assuming an order-reversing coform that contradicts
    // (3.1.15)/(3.1.17) and Problem 3.10.2. With the order-preserving coform of (3.1.15):
    // (x∧y)′ = x′∧y′ and (x∧y∧z)′ = x′∧y′∧z′ (ch. 3 notes, "Coform sign conflict").
    let a = rotated();
    let (x, y, z) = (a.vector([1.0, 2.0, 0.0]), a.vector([0.0, -1.0, 3.0]), a.vector([2.0, 0.5, 1.0]));
    let c = |v: &Vector| Tensor::from_covector(&v.coform());
    assert_tensor_rel(&x.wedge(&y).to_tensor().coform(), &c(&x).wedge(&c(&y)).unwrap(), &a, TOL);
    let xyz = c(&x).wedge(&c(&y)).unwrap().wedge(&c(&z)).unwrap();
    assert_tensor_rel(&x.wedge3(&y, &z).to_tensor().coform(), &xyz, &a, TOL);
}

#[test]
fn problem_3_10_4_tricovector_evaluation_is_a_determinant() {
    // Problem 3.10.4: (w′₁∧w′₂∧w′₃)(x₁, x₂, x₃) = det[w′_i x_j].
    let a = rotated();
    let w = [a.vector([1.0, 2.0, 0.0]), a.vector([0.0, -1.0, 3.0]), a.vector([2.0, 0.5, 1.0])];
    let x = [a.vector([1.0, 0.0, 1.0]), a.vector([-1.0, 2.0, 0.5]), a.vector([0.3, 0.3, 2.0])];
    let c = |v: &Vector| Tensor::from_covector(&v.coform());
    let form = c(&w[0]).wedge(&c(&w[1])).unwrap().wedge(&c(&w[2])).unwrap();
    let m = nalgebra::Matrix3::from_fn(|i, j| w[i].dot(&x[j]));
    assert_rel(form.eval(&[], &x).unwrap(), m.determinant(), TOL);
}

#[test]
fn eq_3_8_28_every_wedge_of_four_vectors_vanishes() {
    // (3.8.28): in 3-D there is no nonzero alternating tensor of order 4.
    let a = rotated();
    let v = |s: f64| Tensor::from_vector(&a.vector([s, s * s, 1.0 - s]));
    let four = v(1.0).wedge(&v(2.0)).unwrap().wedge(&v(-1.0)).unwrap().wedge(&v(0.5)).unwrap();
    assert_eq!((four.p(), four.q()), (4, 0));
    assert_eq!(four.frobenius_norm(), 0.0);
}

#[test]
fn dense_and_compressed_round_trip() {
    // Notes §3: compressed grade-k storage ↔ the dense (k, 0) alternating tensor.
    let a = rotated();
    let b = a.vector([1.0, -2.0, 0.5]).wedge(&a.vector([0.3, 1.0, 2.0]));
    let back = Bivector::from_tensor(&b.to_tensor(), TOL).unwrap();
    assert_vec_rel(&back.undual(), &b.undual(), &a, TOL);
    let t = Trivector::new(-2.5);
    assert_rel(Trivector::from_tensor(&t.to_tensor(), TOL).unwrap().coefficient(), -2.5, TOL);
    let not_alt = Tensor::from_factors(&[a.i(), a.j()], &[]).unwrap();
    assert!(matches!(Bivector::from_tensor(&not_alt, TOL), Err(TensorError::Shape { .. })));
    assert!(matches!(Bivector::from_tensor(&Tensor::<f64>::identity(), TOL), Err(TensorError::Shape { .. })));
    assert!(matches!(Trivector::from_tensor(&not_alt, TOL), Err(TensorError::Shape { .. })));
    assert!(matches!(Tensor::identity().wedge(&Tensor::<f64>::metric()), Err(TensorError::Shape { .. })));
    // A whole multivector: grade by grade to dense tensors and back.
    let m = mv(&a, 0.5, [1.0, -2.0, 0.25], [3.0, 0.0, -1.0], 0.75);
    let parts: Vec<Tensor> = (0..=3).map(|k| m.grade_tensor(k).unwrap()).collect();
    assert!(m.grade_tensor(4).is_none());
    assert_mv_rel(&Multivector::from_grade_tensors(&parts, TOL).unwrap(), &m, &a, TOL);
    assert!(matches!(Multivector::from_grade_tensors(&[not_alt], TOL), Err(TensorError::Shape { .. })));
    assert!(matches!(
        Multivector::from_grade_tensors(&[Tensor::<f64>::identity()], TOL),
        Err(TensorError::Shape { .. })
    ));
}

mod prop {
    use proptest::prelude::*;
    use vectrix::prelude::*;

    use crate::common::*;
    use crate::support::{assert_abs, component, frame, triple};

    fn vector3() -> impl Strategy<Value = [f64; 3]> {
        [component(), component(), component()]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// (3.7.2–5): antisymmetry and x∧x = 0, for tiny and huge magnitudes.
        #[test]
        fn wedge_is_antisymmetric(a in frame(), x in vector3(), y in vector3()) {
            let (x, y) = (a.vector(x), a.vector(y));
            prop_assert_eq!(x.wedge(&x).area(), 0.0);
            // Each component is within 1.5 ulp of exact (fused differences), so the two orders
            // agree to 4ε relative.
            let (xy, yx) = (x.wedge(&y).undual().resolve(&a), y.wedge(&x).undual().resolve(&a));
            let xy_h = x.wedge(&y).undual();
            let yx_h = y.wedge(&x).undual();
            let scale = xy_h.norm().max(f64::MIN_POSITIVE);
            prop_assert!((xy_h + yx_h).norm() <= 8.0 * crate::support::EPS * scale, "{xy:?} {yx:?}");
        }

        /// Near-parallel vectors (notes §3 "Cancellation"): y = 2^k x + 2^e u with integer x, u is
        /// exact in binary, and so is x∧y = 2^e 𝒥(x×u); the fused differences of products must
        /// return it to a few ulps although the naive x₁y₂ − x₂y₁ cancels almost every digit.
        #[test]
        fn near_parallel_wedge_is_relatively_accurate(
            x in proptest::array::uniform3(-1000i32..1000), u in proptest::array::uniform3(-5i32..5),
            k in -8i32..8, e in -30i32..-10,
        ) {
            let a = Frame::new();
            let xf = x.map(f64::from);
            let d = 2f64.powi(e);
            let y: [f64; 3] = std::array::from_fn(|i| 2f64.powi(k) * xf[i] + d * f64::from(u[i]));
            let want = nalgebra::Vector3::new(
                f64::from(x[1] * u[2] - x[2] * u[1]),
                f64::from(x[2] * u[0] - x[0] * u[2]),
                f64::from(x[0] * u[1] - x[1] * u[0]),
            ) * d;
            let got = a.vector(xf).wedge(&a.vector(y)).undual().resolve(&a);
            for i in 0..3 {
                prop_assert!((got[i] - want[i]).abs() <= 4.0 * crate::support::EPS * want[i].abs(), "{got:?} vs {want:?}");
            }
        }

        /// Associativity (3.7.18) and x∧y∧z = det[x y z]𝒥 (3.7.20), frame-independent.
        #[test]
        fn wedge_associative_and_determinant(a in frame(), x in triple(), y in triple(), z in triple()) {
            let (x, y, z) = (a.vector(x), a.vector(y), a.vector(z));
            let left = x.wedge(&y).wedge(&z).coefficient();
            let right = x.wedge_bivector(&y.wedge(&z)).coefficient();
            let det = nalgebra::Matrix3::from_columns(&[x.resolve(&a), y.resolve(&a), z.resolve(&a)]).determinant();
            // x∧y∧z cancels when the three are nearly coplanar, so its error is bounded by the
            // product of the lengths (Hadamard), not by the result: absolute, TOL·|x||y||z|.
            let scale = x.norm() * y.norm() * z.norm();
            assert_abs(left, right, TOL * scale);
            assert_abs(left, det, TOL * scale);
            let (tx, ty, tz) = (Tensor::from_vector(&x), Tensor::from_vector(&y), Tensor::from_vector(&z));
            let dense = tx.wedge(&ty.wedge(&tz).unwrap()).unwrap();
            assert_tensor_abs(&dense, &x.wedge3(&y, &z).to_tensor(), &a, TOL * scale);
        }

        /// Graded commutativity (Problem 3.10.3) for covector forms of grades 1 and 1, 1 and 2.
        #[test]
        fn graded_commutativity(x in triple(), y in triple(), z in triple()) {
            let a = Frame::new();
            let c = |v: [f64; 3]| Tensor::from_covector(&a.covector(v));
            let (tx, ty, tz) = (c(x), c(y), c(z));
            let yz = ty.wedge(&tz).unwrap();
            // Each component is a signed sum of products of one entry from each factor, so its
            // rounding error is bounded by the product of the lengths, not by the (possibly
            // cancelled) result: absolute tolerances TOL·|x||y| and TOL·|x||y||z|.
            let n = |v: [f64; 3]| nalgebra::Vector3::from(v).norm();
            assert_tensor_abs(&tx.wedge(&ty).unwrap(), &-&ty.wedge(&tx).unwrap(), &a, TOL * n(x) * n(y));
            assert_tensor_abs(&tx.wedge(&yz).unwrap(), &yz.wedge(&tx).unwrap(), &a, TOL * n(x) * n(y) * n(z));
        }

        /// Frame independence: (x∧y)|_B = x|_B y|_Bᵀ − y|_B x|_Bᵀ in any frame B.
        #[test]
        fn wedge_resolves_as_antisymmetric_outer_product(a in frame(), b in frame(), x in triple(), y in triple()) {
            let (xv, yv) = (a.vector(x), a.vector(y));
            let (xb, yb) = (xv.resolve(&b), yv.resolve(&b));
            let want = xb * yb.transpose() - yb * xb.transpose();
            let got = xv.wedge(&yv).to_tensor().resolve(&b);
            crate::support::assert_rel_slice(&flat(&got), want.transpose().as_slice(), 1e3 * TOL);
        }
    }
}
