//! Helpers shared by the chapter-3 topic files: numeric reference implementations on
//! resolved arrays (the oracle the frame-free operations are checked against).
#![allow(dead_code)]

use nalgebra::{DMatrix, Matrix3};
use proptest::prelude::*;
use vectrix::prelude::*;

use crate::support::{EPS, assert_abs_slice, assert_rel_slice};

/// Tolerance for O(1) data after a few dozen operations: 64 ε.
pub const TOL: f64 = 64.0 * EPS;

/// Row-major entries of a resolved tensor (first slot slowest).
pub fn flat(m: &DMatrix<f64>) -> Vec<f64> {
    m.transpose().iter().copied().collect()
}

/// Asserts two tensors agree (same type): max |got − want| ≤ tol over the components in `a`.
#[track_caller]
pub fn assert_tensor_abs(got: &Tensor, want: &Tensor, a: &Frame, tol: f64) {
    assert_eq!((got.p(), got.q()), (want.p(), want.q()), "types differ");
    assert_abs_slice(&flat(&got.resolve(a)), &flat(&want.resolve(a)), tol);
}

/// Asserts two tensors agree (same type), relative to the largest component: max |got − want| ≤ tol·max|want| over the components in `a`.
#[track_caller]
pub fn assert_tensor_rel(got: &Tensor, want: &Tensor, a: &Frame, tol: f64) {
    assert_eq!((got.p(), got.q()), (want.p(), want.q()), "types differ");
    assert_rel_slice(&flat(&got.resolve(a)), &flat(&want.resolve(a)), tol);
}

/// Asserts two vectors agree: max |got − want| ≤ tol over the components in `a`.
#[track_caller]
pub fn assert_vec_abs(got: &Vector, want: &Vector, a: &Frame, tol: f64) {
    assert_abs_slice(got.resolve(a).as_slice(), want.resolve(a).as_slice(), tol);
}

/// Asserts two vectors agree, relative to the largest component: max |got − want| ≤ tol·max|want| over the components in `a`.
#[track_caller]
pub fn assert_vec_rel(got: &Vector, want: &Vector, a: &Frame, tol: f64) {
    assert_rel_slice(got.resolve(a).as_slice(), want.resolve(a).as_slice(), tol);
}

/// Asserts two dyadics agree: max |got − want| ≤ tol over the components in `a`.
#[track_caller]
pub fn assert_dyadic_abs(got: &Dyadic, want: &Dyadic, a: &Frame, tol: f64) {
    assert_abs_slice(got.resolve(a).as_slice(), want.resolve(a).as_slice(), tol);
}

/// Asserts two dyadics agree, relative to the largest entry: max |got − want| ≤ tol·max|want| over the components in `a`.
#[track_caller]
pub fn assert_dyadic_rel(got: &Dyadic, want: &Dyadic, a: &Frame, tol: f64) {
    assert_rel_slice(got.resolve(a).as_slice(), want.resolve(a).as_slice(), tol);
}

/// Components [s, x₁, x₂, x₃, β₁, β₂, β₃, t] of a multivector in frame `a`, with the bivector
/// part by its dual vector: B = β₁ ĵ∧k̂ + β₂ k̂∧î + β₃ î∧ĵ.
pub fn mv_components(m: &Multivector, a: &Frame) -> [f64; 8] {
    let x = m.vector_part().resolve(a);
    let b = m.bivector_part().undual().resolve(a);
    [m.scalar_part(), x[0], x[1], x[2], b[0], b[1], b[2], m.trivector_part().coefficient()]
}

/// Asserts two multivectors agree: max |got − want| ≤ tol over the components in `a`.
#[track_caller]
pub fn assert_mv_abs(got: &Multivector, want: &Multivector, a: &Frame, tol: f64) {
    assert_abs_slice(&mv_components(got, a), &mv_components(want, a), tol);
}

/// Asserts two multivectors agree, relative to the largest component: max |got − want| ≤ tol·max|want| over the components in `a`.
#[track_caller]
pub fn assert_mv_rel(got: &Multivector, want: &Multivector, a: &Frame, tol: f64) {
    assert_rel_slice(&mv_components(got, a), &mv_components(want, a), tol);
}

/// The multivector s + x + 𝒥β + t𝒥 from components in frame `a`.
pub fn mv(a: &Frame, s: f64, x: [f64; 3], beta: [f64; 3], t: f64) -> Multivector {
    Multivector::new(s, &a.vector(x), &Bivector::dual_of(&a.vector(beta)), &Trivector::new(t))
}

/// Numeric contraction of a row-major array of order n = p + q: pairs (i, j) join vector
/// slot i (1-based) with covector slot j (1-based), the book's numbering (3.2.2). The naive
/// oracle: loops over every index of the input.
pub fn contract_array(data: &[f64], p: usize, q: usize, pairs: &[(usize, usize)]) -> Vec<f64> {
    let n = p + q;
    let mut keep: Vec<usize> = Vec::new();
    let contracted: Vec<(usize, usize)> = pairs.iter().map(|&(i, j)| (i - 1, p + j - 1)).collect();
    for s in 0..n {
        if !contracted.iter().any(|&(a, b)| a == s || b == s) {
            keep.push(s);
        }
    }
    let mut out = vec![0.0; 3usize.pow(keep.len() as u32)];
    for (idx, &x) in data.iter().enumerate() {
        let digits: Vec<usize> = (0..n).map(|s| (idx / 3usize.pow((n - 1 - s) as u32)) % 3).collect();
        if contracted.iter().all(|&(a, b)| digits[a] == digits[b]) {
            let o = keep.iter().fold(0, |o, &s| 3 * o + digits[s]);
            out[o] += x;
        }
    }
    out
}

/// Rodrigues's formula (2.11.1) in components: cos θ I + (1 − cos θ) n nᵀ + sin θ n^×.
pub fn rodrigues(n: &nalgebra::Vector3<f64>, theta: f64) -> Matrix3<f64> {
    let n = n.normalize();
    Matrix3::identity() * theta.cos()
        + n * n.transpose() * (1.0 - theta.cos())
        + n.cross_matrix() * theta.sin()
}

/// A random tensor of type (p, q) built from components in frame `a`.
pub fn tensor_from(a: &Frame, p: usize, q: usize, comps: &[f64]) -> Tensor {
    let m = DMatrix::from_row_slice(3usize.pow(p as u32), 3usize.pow(q as u32), comps);
    a.tensor(p, q, &m).expect("finite components of the right shape")
}

/// Components for a tensor of order k, moderate magnitude.
pub fn comps(k: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-3.0..3.0f64, 3usize.pow(k as u32))
}
