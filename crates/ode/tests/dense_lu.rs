//! The dense LU of the stiff integrators ([`DenseLu`]): Gaussian elimination with partial
//! pivoting, PA = LU (Golub & Van Loan, Algorithm 3.4.1), factored and solved in place.
//! Claims checked: on well-conditioned matrices the computed x of Ax = b has a residual of
//! the order of the unit round-off, ‖Ax − b‖ ≤ 1e-13·‖A‖‖x‖ (backward stability of GEPP,
//! G&VL Theorem 3.4.4 with the growth factor of random matrices), for real and complex
//! entries, n = 1 … 20, on the unblocked path and on faer's above
//! [`LuScalar::UNBLOCKED_MAX_N`] (48 real, 16 complex: complex n = 17 … 20 run on faer's); singular
//! matrices (a zero pivot) and matrices with NaN or ∞ are refused with the column; the
//! buffers are reusable after a refusal; wrong sizes and solves without factors are typed
//! errors, not panics.
//!
//! Book: §4.11; Golub & Van Loan, *Matrix Computations*, Alg. 3.4.1, §3.4.6; HW §IV.8.

use faer::c64;
use vectrix_ode::implicit::{DenseLu, LuError, LuScalar};

/// 1e-13 = 450 ε: the residual bound, generous for n ≤ 20 (the backward error of GEPP is a
/// small multiple of n·ε·ρ with growth factor ρ of order one on these matrices); a real
/// defect (a wrong pivot swap, an unscaled multiplier) gives O(1).
const RESIDUAL: f64 = 1e-13;

/// xorshift64*: reproducible uniform numbers in [−1, 1) without a dev-dependency.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let u = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        2.0 * (u as f64 / (1u64 << 53) as f64) - 1.0
    }
}

/// A well-conditioned n×n matrix that still needs row interchanges: D + R (|R| ≤ 1, D = n+1
/// on the diagonal, so diagonally dominant, κ ≲ 3), with its rows cyclically shifted by one
/// (so the largest entry of column 0 is in the last row, and so on).
fn test_matrix<T: LuScalar>(n: usize, rng: &mut Rng, entry: impl Fn(&mut Rng) -> T, diag: T) -> Vec<T> {
    let mut a: Vec<T> = (0..n * n).map(|_| entry(rng)).collect();
    for i in 0..n {
        let aii = a[i * n + i];
        a[i * n + i] = aii + diag;
    }
    let mut shifted = a.clone();
    for i in 0..n {
        let from = (i + 1) % n;
        shifted[i * n..(i + 1) * n].copy_from_slice(&a[from * n..(from + 1) * n]);
    }
    shifted
}

/// ‖Ax − b‖∞ / (‖A‖∞‖x‖∞) with b = A x_true, x = the computed solution; also ‖x − x_true‖∞.
fn relative_residual<T: LuScalar>(a: &[T], x_true: &[T], size: impl Fn(T) -> f64) -> (f64, f64) {
    let n = x_true.len();
    let matvec = |x: &[T]| -> Vec<T> {
        (0..n).map(|i| (0..n).fold(T::ZERO, |s, j| s + a[i * n + j] * x[j])).collect()
    };
    let b = matvec(x_true);
    let mut lu = DenseLu::<T>::new(n);
    lu.factor(a).expect("well-conditioned matrix refused");
    let mut x = b.clone();
    lu.solve(&mut x).unwrap();
    let ax = matvec(&x);
    let inf = |v: &[T]| v.iter().map(|e| size(*e)).fold(0.0, f64::max);
    // ‖A‖∞: the largest row sum
    let norm_a =
        (0..n).map(|i| a[i * n..(i + 1) * n].iter().map(|e| size(*e)).sum::<f64>()).fold(0.0, f64::max);
    let r: Vec<T> = ax.iter().zip(&b).map(|(p, q)| *p - *q).collect();
    let err: Vec<T> = x.iter().zip(x_true).map(|(p, q)| *p - *q).collect();
    (inf(&r) / (norm_a * inf(&x)), inf(&err))
}

#[test]
fn golub_van_loan_alg_3_4_1_real_residual_n_1_to_20() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for n in 1..=20 {
        for _ in 0..5 {
            let a = test_matrix(n, &mut rng, Rng::next, n as f64 + 1.0);
            let x: Vec<f64> = (0..n).map(|_| rng.next()).collect();
            let (res, err) = relative_residual(&a, &x, f64::abs);
            // written as `res <= bound` so that a NaN residual fails
            assert!(res <= RESIDUAL, "n = {n}: relative residual {res:e}");
            assert!(err <= 1e3 * RESIDUAL, "n = {n}: error {err:e} for κ ≲ 3");
        }
    }
}

#[test]
fn golub_van_loan_alg_3_4_1_complex_residual_n_1_to_20() {
    let mut rng = Rng(0xd1b5_4a32_d192_ed03);
    let c = |r: &mut Rng| c64::new(r.next(), r.next());
    let size = |z: c64| z.norm();
    for n in 1..=20 {
        for _ in 0..5 {
            let diag = c64::new(n as f64 + 2.0, 0.5 * n as f64);
            let a = test_matrix(n, &mut rng, c, diag);
            let x: Vec<c64> = (0..n).map(|_| c(&mut rng)).collect();
            let (res, err) = relative_residual(&a, &x, size);
            assert!(res <= RESIDUAL, "n = {n}: relative residual {res:e}");
            assert!(err <= 1e3 * RESIDUAL, "n = {n}: error {err:e}");
        }
    }
}

#[test]
fn blocked_path_above_the_threshold_real_and_complex() {
    // n > UNBLOCKED_MAX_N goes to faer's blocked LU: same contract
    let n = <f64 as LuScalar>::UNBLOCKED_MAX_N + 3;
    let mut rng = Rng(42);
    let a = test_matrix(n, &mut rng, Rng::next, n as f64 + 1.0);
    let x: Vec<f64> = (0..n).map(|_| rng.next()).collect();
    let (res, _) = relative_residual(&a, &x, f64::abs);
    assert!(res <= RESIDUAL, "real n = {n}: {res:e}");
    let c = |r: &mut Rng| c64::new(r.next(), r.next());
    let n = <c64 as LuScalar>::UNBLOCKED_MAX_N + 3;
    let a = test_matrix(n, &mut rng, c, c64::new(n as f64 + 2.0, 1.0));
    let x: Vec<c64> = (0..n).map(|_| c(&mut rng)).collect();
    let (res, _) = relative_residual(&a, &x, |z: c64| z.norm());
    assert!(res <= RESIDUAL, "complex n = {n}: {res:e}");
    let mut lu = DenseLu::<c64>::new(n);
    assert!(lu.factor(&vec![c64::new(0.0, 0.0); n * n]).is_err(), "zero matrix on the blocked path");
}

#[test]
fn zero_leading_pivot_needs_the_row_swap() {
    // [[0, 1], [1, 0]] x = (2, 3): without pivoting the first pivot is 0
    let mut lu = DenseLu::<f64>::new(2);
    lu.factor(&[0.0, 1.0, 1.0, 0.0]).unwrap();
    let mut x = [2.0, 3.0];
    lu.solve(&mut x).unwrap();
    assert_eq!(x, [3.0, 2.0]);
}

#[test]
fn singular_matrices_refused_with_the_column() {
    let mut lu = DenseLu::<f64>::new(3);
    // column 1 = column 0 (entries powers of two, so elimination is exact): after the first
    // step column 1 is zero below the diagonal
    let a = [1.0, 1.0, 1.0, 2.0, 2.0, 4.0, 4.0, 4.0, 2.0];
    assert_eq!(lu.factor(&a), Err(LuError::Singular { index: 1 }));
    // a zero column: the first pivot is zero
    assert_eq!(
        lu.factor(&[0.0, 1.0, 2.0, 0.0, 3.0, 4.0, 0.0, 5.0, 7.0]),
        Err(LuError::Singular { index: 0 })
    );
    // complex: [[1, i], [i, −1]] has rows proportional (row 1 = i·row 0)
    let i = c64::new(0.0, 1.0);
    let one = c64::new(1.0, 0.0);
    let mut lc = DenseLu::<c64>::new(2);
    assert_eq!(lc.factor(&[one, i, i, -one]), Err(LuError::Singular { index: 1 }));
}

#[test]
fn nan_and_infinite_matrices_refused() {
    let mut lu = DenseLu::<f64>::new(3);
    let good = [4.0, 1.0, 0.0, 1.0, 4.0, 1.0, 0.0, 1.0, 4.0];
    for (k, bad) in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY].into_iter().enumerate() {
        for pos in 0..9 {
            let mut a = good;
            a[pos] = bad;
            assert!(lu.factor(&a).is_err(), "bad value #{k} at entry {pos} accepted");
        }
    }
    let mut lc = DenseLu::<c64>::new(2);
    let a = [c64::new(1.0, f64::NAN), c64::new(0.0, 0.0), c64::new(0.0, 0.0), c64::new(1.0, 0.0)];
    assert!(lc.factor(&a).is_err());
}

#[test]
fn buffers_reusable_after_a_refusal() {
    // one DenseLu for a run: a singular matrix, then a regular one, then another
    let mut lu = DenseLu::<f64>::new(2);
    assert!(lu.factor(&[1.0, 2.0, 2.0, 4.0]).is_err());
    lu.factor(&[2.0, 1.0, 1.0, 3.0]).unwrap();
    let mut x = [3.0, 4.0]; // (1, 1)
    lu.solve(&mut x).unwrap();
    assert!((x[0] - 1.0).abs() <= 4.0 * f64::EPSILON && (x[1] - 1.0).abs() <= 4.0 * f64::EPSILON, "{x:?}");
    lu.factor(&[0.0, 3.0, 5.0, 1.0]).unwrap();
    let mut x = [6.0, 7.0]; // (1, 2)
    lu.solve(&mut x).unwrap();
    assert!((x[0] - 1.0).abs() <= 4.0 * f64::EPSILON && (x[1] - 2.0).abs() <= 4.0 * f64::EPSILON, "{x:?}");
}

#[test]
fn tiny_pivots_are_not_singular() {
    // diag(1e-300, 1), real and complex: a small but normal pivot is a valid matrix (its
    // reciprocal 1e300 is finite); only pivots below about 2⁻¹⁰²⁴ are refused
    let mut lu = DenseLu::<f64>::new(2);
    lu.factor(&[1e-300, 0.0, 0.0, 1.0]).unwrap();
    let mut x = [1e-300, 2.0];
    lu.solve(&mut x).unwrap();
    // x₀ = 1e-300 · (1/1e-300): the reciprocal rounds once more than a division
    assert!((x[0] - 1.0).abs() <= 2.0 * f64::EPSILON && x[1] == 2.0, "{x:?}");
    let mut lc = DenseLu::<c64>::new(2);
    let (z, one) = (c64::new(0.0, 0.0), c64::new(1.0, 0.0));
    lc.factor(&[c64::new(0.0, 1e-300), z, z, one]).unwrap();
    let mut x = [c64::new(1e-300, 0.0), one];
    lc.solve(&mut x).unwrap();
    // 1e-300 / (1e-300 i) = −i
    assert!((x[0] - c64::new(0.0, -1.0)).norm() <= 2.0 * f64::EPSILON, "{:?}", x[0]);
    assert!(lu.factor(&[1e-320, 0.0, 0.0, 1.0]).is_err(), "subnormal pivot 1e-320 accepted");
}

#[test]
fn wrong_sizes_and_missing_factors_are_typed_errors() {
    // the crate's contract: a typed error, never a panic or a wrong value in Ok
    let mut lu = DenseLu::<f64>::new(2);
    let mut x = [1.0, 2.0];
    assert_eq!(lu.solve(&mut x), Err(LuError::NotFactored));
    assert_eq!(x, [1.0, 2.0]);
    assert_eq!(lu.factor(&[1.0; 3]), Err(LuError::WrongSize { what: "matrix", got: 3, expected: 4 }));
    lu.factor(&[1.0, 0.0, 0.0, 1.0]).unwrap();
    let mut short = [1.0];
    assert_eq!(
        lu.solve(&mut short),
        Err(LuError::WrongSize { what: "right-hand side", got: 1, expected: 2 })
    );
    // a refused factorisation leaves no factors behind
    assert!(lu.factor(&[0.0; 4]).is_err());
    assert_eq!(lu.solve(&mut x), Err(LuError::NotFactored));
}

#[test]
fn huge_pivots_complex_reciprocal_does_not_overflow() {
    // |z|² of z = 1e200(1 + i) overflows; Smith's reciprocal does not form it
    let mut lc = DenseLu::<c64>::new(1);
    let z = c64::new(1e200, 1e200);
    lc.factor(&[z]).unwrap();
    let mut x = [z];
    lc.solve(&mut x).unwrap();
    assert!((x[0] - c64::new(1.0, 0.0)).norm() <= 4.0 * f64::EPSILON, "{:?}", x[0]);
    // a pivot above 2¹⁰²² has a subnormal reciprocal: refused as badly scaled
    let mut lu = DenseLu::<f64>::new(1);
    assert!(lu.factor(&[f64::MAX]).is_err());
}
