//! §3.1–3.3, 3.5–3.6: tensors of type (p, q), tensor product, contraction, evaluation,
//! partial evaluation, coform, slot permutation, the special tensors, Kronecker resolution.

use nalgebra::{DMatrix, Matrix3};
use vectrix::frames::max_abs_diff_in;
use vectrix::prelude::*;
use vectrix::tensor::DEFAULT_MAX_COMPONENTS;

use crate::common::*;
use crate::support::{NanAmax, assert_abs, assert_rel};

fn frame() -> Frame {
    Frame::new()
}

#[test]
fn eq_3_1_9_metric_is_the_dot_product() {
    // (3.1.9): x·y as a (0, 2) tensor is G = Σ ê′_i⊗ê′_i, G(x, y) = x⃗·y⃗.
    let a = frame();
    let (x, y) = (a.vector([1.0, -2.0, 0.5]), a.vector([3.0, 0.25, -4.0]));
    let g = Tensor::metric();
    assert_eq!((g.p(), g.q()), (0, 2));
    assert_abs(g.eval(&[], &[x, y]).unwrap(), x.dot(&y), TOL);
}

#[test]
fn eq_3_1_12_identity_tensor_is_the_identity_dyadic() {
    // (3.1.12), (3.1.24): Σ ê_i⊗ê′_i = I, the identity physical matrix.
    let a = frame();
    assert_dyadic_abs(&Tensor::identity().to_dyadic().unwrap(), &Dyadic::identity(), &a, 0.0);
}

#[test]
fn eq_3_1_14_evaluation_of_a_product_tensor() {
    // (3.1.14): (w⊗z′)(x′, y) = (x′w)(z′y); with two of each, products of all four pairings.
    let a = frame();
    let w = [a.vector([1.0, 2.0, 3.0]), a.vector([0.0, -1.0, 2.0])];
    let z = [a.covector([2.0, 0.5, -1.0]), a.covector([1.0, 1.0, 1.0])];
    let x = [a.covector([0.3, -0.7, 1.1]), a.covector([-2.0, 0.0, 0.4])];
    let y = [a.vector([1.5, 0.5, -0.5]), a.vector([0.2, 0.3, 0.4])];
    let t = Tensor::from_factors(&w, &z).unwrap();
    let want = (x[0] * w[0]) * (x[1] * w[1]) * (z[0] * y[0]) * (z[1] * y[1]);
    assert_rel(t.eval(&x, &y).unwrap(), want, TOL);
}

#[test]
fn eq_3_1_15_coform_keeps_order_within_groups() {
    // (3.1.15–18): (w⊗z′)′ = z⊗w′ (the transpose), (w₁⊗w₂)′ = w′₁⊗w′₂ (the book's (3.1.16)
    // has a stray prime), T″ = T, and the coform is linear.
    let a = frame();
    let (w1, w2) = (a.vector([1.0, 2.0, 3.0]), a.vector([-1.0, 0.5, 2.0]));
    let z = a.covector([0.5, -1.0, 4.0]);
    let wz = Tensor::from_factors(&[w1], &[z]).unwrap();
    let zw = Tensor::from_factors(&[z.coform()], &[w1.coform()]).unwrap();
    assert_tensor_rel(&wz.coform(), &zw, &a, 0.0);
    let ww = Tensor::from_factors(&[w1, w2], &[]).unwrap();
    let ww_prime = Tensor::from_factors(&[], &[w1.coform(), w2.coform()]).unwrap();
    assert_tensor_rel(&ww.coform(), &ww_prime, &a, 0.0);
    let t = tensor_from(&a, 2, 1, &(0..27).map(|k| (k as f64).sin()).collect::<Vec<_>>());
    assert_tensor_abs(&t.coform().coform(), &t, &a, 0.0);
    let s = tensor_from(&a, 2, 1, &(0..27).map(|k| (k as f64).cos()).collect::<Vec<_>>());
    assert_tensor_rel(&t.try_add(&s).unwrap().coform(), &t.coform().try_add(&s.coform()).unwrap(), &a, TOL);
    // For (1, 1) tensors the coform is the transpose of the physical matrix.
    let m = a.dyadic(&Matrix3::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0));
    assert_dyadic_rel(&Tensor::from_dyadic(&m).coform().to_dyadic().unwrap(), &m.coform(), &a, 0.0);
}

#[test]
fn eq_3_1_23_one_one_tensor_is_a_physical_matrix() {
    // (3.1.23): w⊗z′ ≡ w z′.
    let a = frame();
    let (w, z) = (a.vector([1.0, -2.0, 3.0]), a.vector([0.5, 4.0, -1.0]));
    let t = Tensor::from_factors(&[w], &[z.coform()]).unwrap();
    assert_dyadic_rel(&t.to_dyadic().unwrap(), &w.outer(&z), &a, 0.0);
}

#[test]
fn eq_3_2_12_tensor_product_shuffles_slots() {
    // (3.2.6), (3.2.12): (x⊗y′)⊗(w⊗z′) = x⊗w⊗y′⊗z′ (vectors first, then covectors).
    let a = frame();
    let (x, w) = (a.vector([1.0, 2.0, 3.0]), a.vector([0.0, 1.0, -1.0]));
    let (y, z) = (a.covector([2.0, -1.0, 0.5]), a.covector([1.0, 3.0, 2.0]));
    let xy = Tensor::from_factors(&[x], &[y]).unwrap();
    let wz = Tensor::from_factors(&[w], &[z]).unwrap();
    let want = Tensor::from_factors(&[x, w], &[y, z]).unwrap();
    assert_tensor_rel(&xy.otimes(&wz).unwrap(), &want, &a, 0.0);
}

#[test]
fn eq_3_2_2_single_contraction() {
    // (3.2.2): (x⊗y′)_(1,1) = y′x, and (x⊗w⊗y′⊗z′)_(1,2) = (z′x) w⊗y′.
    let a = frame();
    let (x, w) = (a.vector([1.0, 2.0, 3.0]), a.vector([0.0, 1.0, -1.0]));
    let (y, z) = (a.covector([2.0, -1.0, 0.5]), a.covector([1.0, 3.0, 2.0]));
    let xy = Tensor::from_factors(&[x], &[y]).unwrap();
    assert_rel(xy.contract(&[(1, 1)]).unwrap().to_scalar().unwrap(), y * x, TOL);
    let t = Tensor::from_factors(&[x, w], &[y, z]).unwrap();
    let want = &Tensor::from_factors(&[w], &[y]).unwrap() * (z * x);
    assert_tensor_rel(&t.contract(&[(1, 2)]).unwrap(), &want, &a, TOL);
}

#[test]
fn eq_3_2_13_erratum_multi_contraction_uses_original_numbering() {
    // (3.2.3), (3.2.13): with T = x⊗w⊗y′⊗z′, T_(2,1),(1,2) = (y′w)(z′x). The book prints
    // "(1,4)" for the second pair, which under its own convention (i = vector slot,
    // j = covector slot, both 1-based in their group) reads (1,2) (ch. 3 notes).
    let a = frame();
    let (x, w) = (a.vector([1.0, 2.0, 3.0]), a.vector([0.0, 1.0, -1.0]));
    let (y, z) = (a.covector([2.0, -1.0, 0.5]), a.covector([1.0, 3.0, 2.0]));
    let t = Tensor::from_factors(&[x, w], &[y, z]).unwrap();
    let got = t.contract(&[(2, 1), (1, 2)]).unwrap().to_scalar().unwrap();
    assert_rel(got, (y * w) * (z * x), TOL);
    // The order of the pairs does not matter: numbering is always T's original one.
    assert_rel(t.contract(&[(1, 2), (2, 1)]).unwrap().to_scalar().unwrap(), got, 0.0);
}

#[test]
fn eq_3_2_11_evaluation_is_a_total_contraction() {
    // (3.2.11): T(x′, y) = (T⊗(y⊗x′))_(1,2),(2,1).
    let a = frame();
    let t = tensor_from(&a, 1, 1, &[1.0, 2.0, -1.0, 0.5, 3.0, 2.0, -2.0, 1.0, 4.0]);
    let (x, y) = (a.covector([0.3, -0.2, 1.0]), a.vector([2.0, 1.0, -1.0]));
    let args = Tensor::from_factors(&[y], &[x]).unwrap();
    let total = t.contracted_product(&args, &[(1, 2), (2, 1)]).unwrap().to_scalar().unwrap();
    assert_rel(t.eval(&[x], &[y]).unwrap(), total, TOL);
}

#[test]
fn eq_3_3_2_partial_evaluation_of_a_five_slot_tensor() {
    // (3.3.1–5): T₁ = w₁⊗w₂⊗w₃⊗z′₁⊗z′₂, T₁(x′, y₁, y₂; 3, 2, 1) = (x′w₃)(z′₂y₁)(z′₁y₂) w₁⊗w₂,
    // and the same as the contracted product (T₁⊗T₂)_(3,3),(4,2),(5,1) with T₂ = y₁⊗y₂⊗x′.
    let a = frame();
    let w = [a.vector([1.0, 2.0, 0.0]), a.vector([0.5, -1.0, 2.0]), a.vector([3.0, 0.0, 1.0])];
    let z = [a.covector([1.0, 1.0, -1.0]), a.covector([0.0, 2.0, 0.5])];
    let x = a.covector([0.2, -0.4, 1.5]);
    let (y1, y2) = (a.vector([1.0, -1.0, 2.0]), a.vector([0.3, 0.6, -0.9]));
    let t1 = Tensor::from_factors(&w, &z).unwrap();
    let t3 = t1.partial_eval(&[Arg::Covector(x), Arg::Vector(y1), Arg::Vector(y2)], &[3, 2, 1]).unwrap();
    let want = &Tensor::from_factors(&w[..2], &[]).unwrap() * ((x * w[2]) * (z[1] * y1) * (z[0] * y2));
    assert_tensor_rel(&t3, &want, &a, TOL);
    let t2 = Tensor::from_factors(&[y1, y2], &[x]).unwrap();
    let t1t2 = t1.otimes(&t2).unwrap();
    assert_eq!((t1t2.p(), t1t2.q()), (5, 3));
    assert_tensor_rel(&t1.contracted_product(&t2, &[(3, 3), (4, 2), (5, 1)]).unwrap(), &want, &a, TOL);
    assert_tensor_rel(&t1t2.contract(&[(3, 3), (4, 2), (5, 1)]).unwrap(), &want, &a, TOL);
}

#[test]
fn eq_3_3_7_matrix_products_as_contractions() {
    // (3.3.7) M z = (M⊗z)_(2,1); (3.3.8) M N = (M⊗N)_(2,1); (M⊗N)_(1,1),(2,2) = tr M tr N.
    let a = frame();
    let m = a.dyadic(&Matrix3::new(1.0, 2.0, 0.0, -1.0, 3.0, 2.0, 0.5, 0.0, 1.0));
    let n = a.dyadic(&Matrix3::new(2.0, 0.0, 1.0, 1.0, -1.0, 0.0, 0.0, 4.0, 3.0));
    let z = a.vector([1.0, -2.0, 0.5]);
    let (tm, tn) = (Tensor::from_dyadic(&m), Tensor::from_dyadic(&n));
    let mz = tm.contracted_product(&Tensor::from_vector(&z), &[(2, 1)]).unwrap();
    assert_vec_rel(&mz.to_vector().unwrap(), &(m * z), &a, TOL);
    let mn = tm.contracted_product(&tn, &[(2, 1)]).unwrap();
    assert_dyadic_rel(&mn.to_dyadic().unwrap(), &(m * n), &a, TOL);
    let tt = tm.contracted_product(&tn, &[(1, 1), (2, 2)]).unwrap().to_scalar().unwrap();
    assert_rel(tt, m.trace() * n.trace(), TOL);
}

#[test]
fn eq_3_3_10_metric_lowers_and_cometric_raises() {
    // (3.3.10–13): (G⊗x)_(1,1) = x′, (G′⊗x′)_(1,1) = x, (G′⊗G)_(1,1) = U.
    let a = frame();
    let x = a.vector([1.0, -2.0, 3.0]);
    let (g, gp) = (Tensor::metric(), Tensor::cometric());
    let lowered = g.contracted_product(&Tensor::from_vector(&x), &[(1, 1)]).unwrap();
    assert_eq!(lowered.to_covector(), Some(x.coform()));
    let raised = gp.contracted_product(&Tensor::from_covector(&x.coform()), &[(1, 1)]).unwrap();
    assert_eq!(raised.to_vector(), Some(x));
    assert_tensor_abs(&gp.contracted_product(&g, &[(1, 1)]).unwrap(), &Tensor::identity(), &a, 0.0);
}

#[test]
fn eq_3_3_16_epsilon_tensor_gives_the_cross_product_matrix() {
    // (3.3.16–17): E = −Σ ε_ijk ê_i⊗ê′_j⊗ê′_k, (E⊗x)_(2,2) = E(x; 2) = x^×.
    let a = frame();
    let x = a.vector([0.3, -1.2, 2.0]);
    let e = Tensor::levi_civita();
    let xx = e.contracted_product(&Tensor::from_vector(&x), &[(2, 2)]).unwrap();
    assert_dyadic_rel(&xx.to_dyadic().unwrap(), &x.cross_dyad(), &a, TOL);
    let by_eval = e.partial_eval(&[Arg::Vector(x)], &[2]).unwrap();
    assert_tensor_rel(&by_eval, &xx, &a, TOL);
}

#[test]
fn eq_3_3_18_levi_civita_symbol_in_any_right_handed_frame() {
    // (3.3.18): E|_A entries are −ε_ijk in every right-handed frame (Fact 3.7.5 analogue).
    let b = Frame::new()
        .rotated_by_rotor(&Rotor::from_axis_angle(&Frame::new().vector([1.0, 2.0, 2.0]), 0.9).unwrap());
    let e = Tensor::levi_civita().resolve(&b);
    let eps = |i: usize, j: usize, k: usize| {
        ((i as i64 - j as i64) * (j as i64 - k as i64) * (k as i64 - i as i64)) as f64 / 2.0
    };
    for i in 0..3 {
        for j in 0..3 {
            for k in 0..3 {
                assert_abs(e[(i, 3 * j + k)], -eps(i, j, k), TOL);
            }
        }
    }
}

#[test]
fn eq_3_3_21_u4_contractions() {
    // (3.3.19–22): U4 = U⊗U, (U4⊗M)_(2,3),(3,1) = M, (U4⊗M)_(2,3),(3,2) = (tr M) U.
    let a = frame();
    let u4 = Tensor::u4();
    assert_tensor_abs(&u4, &Tensor::identity().otimes(&Tensor::identity()).unwrap(), &a, 0.0);
    let m = a.dyadic(&Matrix3::new(1.0, 2.0, 3.0, 0.0, -1.0, 4.0, 2.0, 2.0, 5.0));
    let tm = Tensor::from_dyadic(&m);
    let first = u4.contracted_product(&tm, &[(2, 3), (3, 1)]).unwrap();
    assert_dyadic_rel(&first.to_dyadic().unwrap(), &m, &a, TOL);
    let second = u4.contracted_product(&tm, &[(2, 3), (3, 2)]).unwrap();
    assert_dyadic_rel(&second.to_dyadic().unwrap(), &(Dyadic::identity() * m.trace()), &a, TOL);
}

#[test]
fn eq_3_7_14_slot_permutation() {
    // (3.7.14): T_σ(a₁, a₂, a₃) = T(a_σ(1), a_σ(2), a_σ(3)).
    let a = frame();
    let t = tensor_from(&a, 3, 0, &(0..27).map(|k| (k as f64 * 0.7).sin()).collect::<Vec<_>>());
    let ts = t.permute(&[2, 3, 1]).unwrap();
    let args = [a.covector([1.0, 0.5, -1.0]), a.covector([0.2, 2.0, 0.0]), a.covector([-0.3, 0.1, 1.0])];
    let got = ts.eval(&args, &[]).unwrap();
    assert_abs(got, t.eval(&[args[1], args[2], args[0]], &[]).unwrap(), TOL);
    // A product x₁⊗x₂⊗x₃ goes to x_σ⁻¹(1)⊗x_σ⁻¹(2)⊗x_σ⁻¹(3) (the book's x_σ(1)… is harmless
    // inside signed sums, ch. 3 notes): σ = (2 3 1) has σ⁻¹ = (3 1 2).
    let x = [a.vector([1.0, 0.0, 2.0]), a.vector([0.0, 3.0, 1.0]), a.vector([1.0, 1.0, -1.0])];
    let prod = Tensor::from_factors(&x, &[]).unwrap();
    let want = Tensor::from_factors(&[x[2], x[0], x[1]], &[]).unwrap();
    assert_tensor_rel(&prod.permute(&[2, 3, 1]).unwrap(), &want, &a, 0.0);
}

#[test]
fn fact_3_6_1_resolution_of_a_product_is_the_kronecker_product() {
    // (3.6.2)–(3.6.3), Fact 3.6.1: (T₁⊗T₂)|_A = T₁|_A ⊗ T₂|_A, rows = vector slots.
    let b = Frame::new()
        .rotated_by_rotor(&Rotor::from_axis_angle(&Frame::new().vector([0.0, 1.0, 3.0]), -2.1).unwrap());
    let t1 = tensor_from(&b, 1, 1, &[1.0, 2.0, -1.0, 0.5, 3.0, 2.0, -2.0, 1.0, 4.0]);
    let t2 = tensor_from(&b, 2, 1, &(0..27).map(|k| (k as f64).cos()).collect::<Vec<_>>());
    let got = t1.otimes(&t2).unwrap().resolve(&b);
    let want = t1.resolve(&b).kronecker(&t2.resolve(&b));
    assert_eq!(got.shape(), (27, 9));
    crate::support::assert_rel_slice(got.as_slice(), want.as_slice(), TOL);
}

#[test]
fn eq_3_5_kronecker_facts() {
    // §3.5 through vectrix's tensors: by Fact 3.6.1 the resolution of a tensor product is the
    // Kronecker product of the resolutions, (T₁⊗T₂)|_A = T₁|_A ⊗ T₂|_A, so each Kronecker fact
    // becomes a statement about vectrix objects. The left sides are `otimes` (and `coform`,
    // `try_add`) resolved in F_A; the right sides are vectrix dyadic algebra (composition,
    // coform, sum, inverse) resolved in F_A. The dyadics are built in a turned frame F_B, so no
    // component is exact by construction.
    // (3.5.1) vec stacks columns: the definition, on the book's 2 × 2 example.
    let vec = |m: &DMatrix<f64>| DMatrix::from_column_slice(m.len(), 1, m.as_slice());
    assert_eq!(vec(&DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 3.0, 4.0])).as_slice(), &[1.0, 3.0, 2.0, 4.0]);
    let a = frame();
    let b = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([0.4, -1.0, 2.0]), 1.3).unwrap());
    // nonsingular dyadics: sines off a dominant diagonal of 2
    let dy = |s: f64| {
        b.dyadic(&Matrix3::from_fn(|r, c| ((r * 3 + c) as f64 * s).sin() + if r == c { 2.0 } else { 0.0 }))
    };
    let (ma, mb, mc, md) = (dy(0.3), dy(0.7), dy(1.1), dy(1.9));
    let t = Tensor::from_dyadic;
    let kron = |x: &Dyadic, y: &Dyadic| t(x).otimes(&t(y)).unwrap();
    let res = |m: &Dyadic| {
        let r = m.resolve(&a);
        DMatrix::from_fn(3, 3, |i, j| r[(i, j)])
    };
    let close = |got: &DMatrix<f64>, want: &DMatrix<f64>| {
        assert_eq!(got.shape(), want.shape());
        crate::support::assert_rel_slice(got.as_slice(), want.as_slice(), TOL);
    };
    // (3.5.4): A⊗B is the block matrix [A_(i,j)B]
    let ab = kron(&ma, &mb).resolve(&a);
    assert_eq!(ab.shape(), (9, 9));
    close(&ab, &DMatrix::from_fn(9, 9, |r, c| res(&ma)[(r / 3, c / 3)] * res(&mb)[(r % 3, c % 3)]));
    // (3.5.3): tr AB = (vec Aᵀ)ᵀ vec B, with AB the composition and Aᵀ the coform
    let tr = (vec(&res(&ma.coform())).transpose() * vec(&res(&mb)))[(0, 0)];
    crate::support::assert_rel(tr, (ma * mb).trace(), TOL);
    // (3.5.5)–(3.5.6): α-scaling moves through ⊗; (A⊗B)ᵀ = Aᵀ⊗Bᵀ
    close(&kron(&(ma * 2.5), &mb).resolve(&a), &(kron(&ma, &mb).resolve(&a) * 2.5));
    close(&kron(&ma, &mb).coform().resolve(&a), &ab.transpose());
    close(&kron(&ma.coform(), &mb.coform()).resolve(&a), &ab.transpose());
    // (3.5.7)–(3.5.8): distributivity over the sum of dyadics
    close(&kron(&(ma + mb), &mc).resolve(&a), &kron(&ma, &mc).try_add(&kron(&mb, &mc)).unwrap().resolve(&a));
    close(&kron(&mc, &(ma + mb)).resolve(&a), &kron(&mc, &ma).try_add(&kron(&mc, &mb)).unwrap().resolve(&a));
    // (3.5.9): associativity, 27 × 27
    close(
        &t(&ma).otimes(&kron(&mb, &mc)).unwrap().resolve(&a),
        &kron(&ma, &mb).otimes(&t(&mc)).unwrap().resolve(&a),
    );
    // (3.5.10): (A⊗B)(C⊗D) = AC⊗BD
    close(&(ab.clone() * kron(&mc, &md).resolve(&a)), &kron(&(ma * mc), &(mb * md)).resolve(&a));
    // (3.5.11): (A⊗B)⁻¹ = A⁻¹⊗B⁻¹, with vectrix's inverse dyadics; the residual of the product
    // with the identity scales with the entries of both factors
    let inv = kron(&ma.inverse(1e-12).unwrap(), &mb.inverse(1e-12).unwrap()).resolve(&a);
    let scale = 9.0 * ab.nan_amax() * inv.nan_amax();
    crate::support::assert_abs_slice(
        (&ab * &inv).as_slice(),
        DMatrix::<f64>::identity(9, 9).as_slice(),
        TOL * scale,
    );
    // (3.5.13): vec xyᵀ = y⊗x, with x⃗y⃗′ the outer product and y⃗⊗x⃗ a (2, 0) tensor (9 × 1)
    let (x, y) = (b.vector([1.0, 2.0, 3.0]), b.vector([-1.0, 0.5, 2.0]));
    close(&vec(&res(&x.outer(&y))), &Tensor::from_factors(&[y, x], &[]).unwrap().resolve(&a));
    // (3.5.14): vec(ABC) = (Cᵀ⊗A) vec B
    close(&vec(&res(&(ma * mb * mc))), &(kron(&mc.coform(), &ma).resolve(&a) * vec(&res(&mb))));
}

#[test]
fn tensor_order_above_the_limit_is_an_error() {
    // DESIGN §5: an order whose 3^(p+q) storage would exceed the configurable cap is an
    // error, never an allocation failure.
    let err = Tensor::<f64>::zeros(10, 10).unwrap_err();
    assert!(matches!(err, TensorError::TooLarge { order: 20, .. }), "{err}");
    assert!(err.to_string().contains("with_max_components"));
    let (t8, t7) = (Tensor::<f64>::zeros(8, 0).unwrap(), Tensor::<f64>::zeros(0, 7).unwrap());
    assert!(matches!(t8.otimes(&t7), Err(TensorError::TooLarge { order: 15, .. })));
    assert!(matches!(Tensor::<f64>::zeros(usize::MAX, 1), Err(TensorError::TooLarge { .. })));
    // The cap is carried by each tensor (default 3^14); raising it on an operand admits
    // order 15 for its products (only checked here, not allocated).
    assert_eq!(t8.max_components(), DEFAULT_MAX_COMPONENTS);
    assert!(Tensor::<f64>::components_for(15, t8.max_components()).is_err());
    assert_eq!(Tensor::<f64>::components_for(15, 3usize.pow(15)), Ok(3usize.pow(15)));
    let t8_raised = t8.clone().with_max_components(3usize.pow(15)).unwrap();
    assert_eq!(t8_raised.otimes(&Tensor::scalar(1.0)).unwrap().max_components(), 3usize.pow(15));
    // lowered on both operands, a product above it is refused: 3^8 components against a cap of 3^7
    let (t4, t4c) = (
        Tensor::<f64>::zeros(4, 0).unwrap().with_max_components(3usize.pow(7)).unwrap(),
        Tensor::<f64>::zeros(0, 4).unwrap().with_max_components(3usize.pow(7)).unwrap(),
    );
    assert!(matches!(t4.otimes(&t4c), Err(TensorError::TooLarge { order: 8, limit: 2187, .. })));
    assert!(matches!(
        Tensor::<f64>::components_for(3, 26),
        Err(TensorError::TooLarge { needed: 27, limit: 26, .. })
    ));
}

#[test]
fn bad_slots_and_arguments_are_typed_errors() {
    let a = frame();
    let t = tensor_from(&a, 2, 1, &[1.0; 27]);
    for pairs in [&[(3, 1)][..], &[(1, 2)], &[(0, 1)], &[(1, 1), (2, 1)]] {
        assert!(matches!(t.contract(pairs), Err(TensorError::Shape { .. })), "{pairs:?}");
    }
    assert!(matches!(t.eval(&[], &[]), Err(TensorError::Shape { .. })));
    assert!(matches!(t.permute(&[1, 3, 2]), Err(TensorError::InvalidPermutation { .. })));
    assert!(matches!(t.permute(&[1, 1, 3]), Err(TensorError::InvalidPermutation { .. })));
    let x = a.vector([1.0, 0.0, 0.0]);
    assert!(matches!(t.partial_eval(&[Arg::Vector(x)], &[2]), Err(TensorError::Shape { .. })));
    assert!(matches!(t.partial_eval(&[Arg::Vector(x)], &[]), Err(TensorError::Shape { .. })));
    assert!(matches!(t.try_add(&Tensor::identity()), Err(TensorError::Shape { .. })));
}

mod prop {
    use proptest::prelude::*;
    use vectrix::prelude::*;

    use crate::common::*;
    use crate::support::{assert_rel_slice, frame};

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Frame independence (DESIGN §6): a contracted product computed frame-free and
        /// resolved in any frame B equals the numeric contraction of the resolved arrays
        /// (T₁|_B ⊗ T₂|_B contracted), notes §2 item 1.
        #[test]
        fn contracted_product_commutes_with_resolution(
            a in frame(), b in frame(), c1 in comps(3), c2 in comps(2),
        ) {
            let t1 = tensor_from(&a, 2, 1, &c1);
            let t2 = tensor_from(&a, 1, 1, &c2);
            let pairs = [(3, 1), (1, 2)];
            let got = flat(&t1.contracted_product(&t2, &pairs).unwrap().resolve(&b));
            let prod_b = t1.resolve(&b).kronecker(&t2.resolve(&b));
            let want = contract_array(&flat(&prod_b), 3, 2, &pairs);
            assert_rel_slice(&got, &want, 16.0 * TOL);
        }

        /// Fused contraction = literal product then contraction; partial evaluation = the
        /// contracted product (3.3.5).
        #[test]
        fn fused_equals_literal(a in frame(), c1 in comps(3), c2 in comps(3)) {
            let t1 = tensor_from(&a, 1, 2, &c1);
            let t2 = tensor_from(&a, 2, 1, &c2);
            let pairs = [(2, 1), (3, 2)];
            let fused = t1.contracted_product(&t2, &pairs).unwrap();
            let literal = t1.otimes(&t2).unwrap().contract(&pairs).unwrap();
            assert_tensor_rel(&fused, &literal, &a, 16.0 * TOL);
        }

        /// Coform is an involution and commutes with resolution (transpose of T|_B).
        #[test]
        fn coform_is_the_resolved_transpose(b in frame(), c in comps(3)) {
            let t = tensor_from(&Frame::new(), 2, 1, &c);
            let got = t.coform().resolve(&b);
            assert_rel_slice(got.as_slice(), t.resolve(&b).transpose().as_slice(), 16.0 * TOL);
        }

        /// Evaluation is frame-free: the same number from arguments built in any frame.
        #[test]
        fn evaluation_is_frame_free(a in frame(), c in comps(3), x in proptest::array::uniform3(-2.0..2.0f64)) {
            let t = tensor_from(&Frame::new(), 1, 2, &c);
            let (u, v, w) = (a.covector(x), a.vector([x[1], x[2], x[0]]), a.vector([1.0, x[0], -x[2]]));
            let direct = t.eval(&[u], &[v, w]).unwrap();
            let t_a = t.resolve(&a);
            let (ua, va, wa) = (u.resolve(&a), v.resolve(&a), w.resolve(&a));
            let (mut want, mut scale) = (0.0, 0.0);
            for i in 0..3 { for j in 0..3 { for k in 0..3 {
                want += t_a[(i, 3 * j + k)] * ua[i] * va[j] * wa[k];
                scale += (t_a[(i, 3 * j + k)] * ua[i] * va[j] * wa[k]).abs();
            }}}
            // 27-term sums that may cancel: the error lives at the scale Σ|terms|.
            crate::support::assert_abs(direct, want, 16.0 * TOL * scale);
        }
    }
}

#[test]
fn problem_3_10_1_false_as_stated_contracted_associativity() {
    // Problem 3.10.1 claims ((T₁⊗T₂)_S⊗T₃)_S = (T₁⊗(T₂⊗T₃)_S)_S. False in general (ch. 3 notes:
    // for (2, 2) tensors it holds for 18 of the 72 sets S), e.g. for the composition pattern
    // S = (3,1),(4,2).
    let a = frame();
    let t = |s: f64| tensor_from(&a, 2, 2, &(0..81).map(|k| (k as f64 * s).sin()).collect::<Vec<_>>());
    let (t1, t2, t3) = (t(0.31), t(0.57), t(1.13));
    let both = |s: &[(usize, usize)]| {
        let left = t1.contracted_product(&t2, s).unwrap().contracted_product(&t3, s).unwrap();
        let right = t1.contracted_product(&t2.contracted_product(&t3, s).unwrap(), s).unwrap();
        max_abs_diff_in(&left, &right, &a).unwrap()
    };
    assert!(both(&[(3, 1), (4, 2)]) <= 1e2 * TOL);
    // Over all 72 two-pair sets S on (4, 4) products, exactly 18 satisfy the claim.
    let mut sets = Vec::new();
    for i1 in 1..=4 {
        for i2 in (i1 + 1)..=4 {
            for j1 in 1..=4 {
                for j2 in 1..=4 {
                    if j1 != j2 {
                        sets.push([(i1, j1), (i2, j2)]);
                    }
                }
            }
        }
    }
    assert_eq!(sets.len(), 72);
    let holding = sets.iter().filter(|s| both(&s[..]) <= 1e2 * TOL).count();
    assert_eq!(holding, 18);
    // For (1, 1) tensors and S = (2,1) it is the associativity of the matrix product.
    let m = |s: f64| tensor_from(&a, 1, 1, &(0..9).map(|k| (k as f64 * s).cos()).collect::<Vec<_>>());
    let (m1, m2, m3) = (m(0.2), m(0.9), m(1.7));
    let left = m1.contracted_product(&m2, &[(2, 1)]).unwrap().contracted_product(&m3, &[(2, 1)]).unwrap();
    let right = m1.contracted_product(&m2.contracted_product(&m3, &[(2, 1)]).unwrap(), &[(2, 1)]).unwrap();
    assert_tensor_rel(&left, &right, &a, TOL);
}
