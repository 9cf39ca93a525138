//! The dense LU factorisation with partial pivoting that the stiff integrators refactorise
//! every few steps: PA = LU factored in place into a buffer allocated once per run, solved in
//! place, for real and complex matrices.
//!
//! At the sizes of the reference problems (n = 2 … 50) the arithmetic of an n×n LU is a few
//! hundred to a few ten thousand flops, and a general-purpose library's fixed cost per call
//! (scratch allocation, dispatch, a result `Mat` per solve) is as large as the work itself:
//! profiling RADAU5 on the n = 12 chain put a fifth of the run in the allocator. So small
//! matrices use the textbook unblocked algorithm below, large ones faer's blocked LU.
//!
//! Book: §4.11; Golub & Van Loan, *Matrix Computations* (4th ed.), Algorithm 3.4.1 (Gaussian
//! elimination with partial pivoting, outer-product form) and §3.4.4–3.4.6 (stability);
//! HW §IV.8 (the iteration matrices of RADAU5, `DECOMR`/`DECOMC` with `DEC`/`DECC` of
//! `decsol.f`).

use core::ops::{Add, Div, Mul, MulAssign, Sub, SubAssign};

use faer::c64;
use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::{Mat, traits::ComplexField};

mod sealed {
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for faer::c64 {}
}

/// The entries [`DenseLu`] works with: `f64` (RADAU5's real system, BDF) and `faer::c64`
/// (RADAU5's complex system ((α + iβ)/h)I − J). Sealed.
///
/// Book: HW §IV.8.
pub trait LuScalar:
    ComplexField
    + Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + SubAssign
    + MulAssign
    + sealed::Sealed
{
    /// The additive identity.
    const ZERO: Self;
    /// Largest n factored by the unblocked algorithm of [`DenseLu`]; larger matrices go to
    /// faer's blocked LU. Measured (factor + one solve, faer including its allocations,
    /// single thread, 2-core Xeon under load 3.5, 2026-12-05): real, the unblocked LU is 9×
    /// faster at n = 4, 2.6× at 12, 1.5× at 24–40, even at 48 and 0.7–0.9× from 56 on, so
    /// 48; complex (faer's kernels are vectorised over the real and imaginary parts, ours are
    /// scalar `c64` arithmetic), 9× at 4, 2× at 8, 1.3–4× at 12, even at 16 and 0.65–0.8×
    /// from 24 on, so 16. The stiff problems of the sitting have n ≤ 12.
    const UNBLOCKED_MAX_N: usize;
    /// |x| for real x, |Re x| + |Im x| for complex x: the size compared in the pivot search
    /// (`IDAMAX`-style for real, `DECC` of `decsol.f` for complex).
    fn size(self) -> f64;
    /// `true` when every part is finite.
    fn finite(self) -> bool;
    /// 1/x, without intermediate overflow for complex x (Smith's algorithm); not finite when
    /// |x| is below about 2⁻¹⁰²⁴, subnormal (fewer significant bits) above about 2¹⁰²².
    fn recip(self) -> Self;
}

impl LuScalar for f64 {
    const ZERO: Self = 0.0;
    const UNBLOCKED_MAX_N: usize = 48;
    fn size(self) -> f64 {
        self.abs()
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
    fn recip(self) -> Self {
        1.0 / self
    }
}

impl LuScalar for c64 {
    const ZERO: Self = c64::new(0.0, 0.0);
    const UNBLOCKED_MAX_N: usize = 16;
    fn size(self) -> f64 {
        self.re.abs() + self.im.abs()
    }
    fn finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
    fn recip(self) -> Self {
        // Smith (1962): 1/(a + ib) = (1 − i r)/(a(1 + r²)), r = b/a, for |a| ≥ |b| (and the
        // mirror case); 1/a is formed first, so neither a² + b² nor a(1 + r²) can overflow
        let (a, b) = (self.re, self.im);
        if a.abs() >= b.abs() {
            let r = b / a;
            let inv = (1.0 / a) / (1.0 + r * r);
            c64::new(inv, -r * inv)
        } else {
            let r = a / b;
            let inv = (1.0 / b) / (1.0 + r * r);
            c64::new(r * inv, -inv)
        }
    }
}

/// Why [`DenseLu`] refused a matrix or a right-hand side.
///
/// Book: Golub & Van Loan, Algorithm 3.4.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum LuError {
    /// The matrix is singular to working precision (a zero pivot, or one whose reciprocal
    /// overflows) or a NaN or infinite entry appeared in its factors.
    #[error("LU factorisation refused at column {index}: zero or non-finite pivot or factor entry")]
    Singular {
        /// The elimination step (column) where it was found.
        index: usize,
    },
    /// A matrix or right-hand side whose length is not n² or n.
    #[error("{what} has length {got}, expected {expected}")]
    WrongSize {
        /// `"matrix"` or `"right-hand side"`.
        what: &'static str,
        /// Its length.
        got: usize,
        /// The length required.
        expected: usize,
    },
    /// [`DenseLu::solve`] before a successful factorisation (or after a refused one).
    #[error("no factors to solve with: the last factorisation failed or none was made")]
    NotFactored,
}

/// PA = LU of an n×n matrix, factored in place: the matrix, its factors and the pivots live
/// in buffers allocated by [`DenseLu::new`] and reused by every [`DenseLu::factor`] and
/// [`DenseLu::solve`]. For n ≤ [`LuScalar::UNBLOCKED_MAX_N`] neither allocates; above,
/// faer's blocked LU is used (and allocates, amortised over its O(n³) work).
///
/// L is unit lower triangular, U upper triangular, both stored in one column-major array
/// (L below the diagonal) as LAPACK's `dgetf2`, so that the elimination and both triangular
/// solves run down contiguous columns as independent multiply–adds (`axpy`), not as
/// dot products whose additions wait for each other; the pivots are LAPACK's too: at step k
/// rows k and `piv[k]` were swapped.
///
/// ```
/// use vectrix_ode::implicit::DenseLu;
/// // A = [[0, 2], [1, 1]]: the zero in the corner needs the row swap
/// let mut lu = DenseLu::<f64>::new(2);
/// lu.factor(&[0.0, 2.0, 1.0, 1.0]).unwrap();
/// let mut x = [4.0, 3.0]; // b
/// lu.solve(&mut x).unwrap(); // x = A⁻¹b = (1, 2)
/// assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 2.0).abs() < 1e-15);
/// ```
///
/// Book: Golub & Van Loan, Algorithm 3.4.1; HW §IV.8 (`DEC`/`SOL`, `DECC`/`SOLC`).
#[derive(Debug, Clone)]
pub struct DenseLu<T: LuScalar> {
    n: usize,
    /// The matrix, then L\U in place, column-major (entry (i, j) at j·n + i).
    a: Vec<T>,
    /// Row interchanges: at step k, rows k and piv[k].
    piv: Vec<usize>,
    /// 1/uₖₖ: the multipliers and the back substitution multiply instead of dividing.
    dinv: Vec<T>,
    /// faer's factors, for n > [`LuScalar::UNBLOCKED_MAX_N`].
    blocked: Option<PartialPivLu<T>>,
    /// `true` after a successful factorisation (solves are refused otherwise).
    factored: bool,
}

impl<T: LuScalar> DenseLu<T> {
    /// Buffers for n×n matrices (n² entries and n pivots), allocated once.
    pub fn new(n: usize) -> Self {
        Self {
            n,
            a: vec![T::ZERO; n * n],
            piv: (0..n).collect(),
            dinv: vec![T::ZERO; n],
            blocked: None,
            factored: false,
        }
    }

    /// n.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Factors the row-major matrix `a` (n² entries, (i, j) at i·n + j).
    ///
    /// # Errors
    /// [`LuError::WrongSize`] if `a.len()` ≠ n², else as [`DenseLu::factor_with`].
    pub fn factor(&mut self, a: &[T]) -> Result<(), LuError> {
        let n = self.n;
        if a.len() != n * n {
            self.factored = false;
            return Err(LuError::WrongSize { what: "matrix", got: a.len(), expected: n * n });
        }
        self.factor_with(|i, j| a[i * n + j])
    }

    /// Writes A with entries `entry(i, j)` into the stored buffer and factors it in place
    /// (Golub & Van Loan Alg. 3.4.1 for n ≤ [`LuScalar::UNBLOCKED_MAX_N`], faer above).
    ///
    /// # Degenerate inputs
    /// A pivot that is exactly zero (A singular to working precision after the row
    /// interchanges), one whose reciprocal is not a finite normal number (|uₖₖ| below about
    /// 2⁻¹⁰²⁴ or above 2¹⁰²², for n ≤ [`LuScalar::UNBLOCKED_MAX_N`]: such a matrix is badly
    /// scaled beyond what the integrators meet) or any non-finite entry of L or U refuses the
    /// matrix; the factors are then unusable until the next successful `factor`.
    ///
    /// # Errors
    /// [`LuError::Singular`] naming the column where elimination stopped.
    pub fn factor_with(&mut self, entry: impl FnMut(usize, usize) -> T) -> Result<(), LuError> {
        let result = if self.n > T::UNBLOCKED_MAX_N {
            self.factor_blocked(entry)
        } else {
            self.factor_unblocked(entry)
        };
        self.factored = result.is_ok();
        result
    }

    /// Alg. 3.4.1 in place in the stored buffer.
    fn factor_unblocked(&mut self, mut entry: impl FnMut(usize, usize) -> T) -> Result<(), LuError> {
        let n = self.n;
        for j in 0..n {
            for i in 0..n {
                self.a[j * n + i] = entry(i, j);
            }
        }
        for k in 0..n {
            self.eliminate(k)?;
        }
        // a NaN or ∞ off the diagonal of U or in L does not show in the pivots
        match self.a.iter().position(|v| !v.finite()) {
            Some(p) => Err(LuError::Singular { index: p / n }),
            None => Ok(()),
        }
    }

    /// Step k of Alg. 3.4.1: choose the pivot, swap rows, form column k of L and update the
    /// trailing (n−k−1)×(n−k−1) block by the outer product, column by column.
    fn eliminate(&mut self, k: usize) -> Result<(), LuError> {
        let n = self.n;
        // pivot: the largest |a_ik|, i ≥ k (the first on ties; NaN never wins)
        let col_k = &self.a[k * n..(k + 1) * n];
        let mut p = k;
        let mut big = col_k[k].size();
        for (i, v) in col_k.iter().enumerate().skip(k + 1) {
            let s = v.size();
            if s > big || big.is_nan() {
                (p, big) = (i, s);
            }
        }
        self.piv[k] = p;
        if p != k {
            for j in 0..n {
                self.a.swap(j * n + k, j * n + p);
            }
        }
        let pivot = self.a[k * n + k];
        let r = pivot.recip();
        // singular branch: a zero pivot means every candidate was zero (A is singular to
        // working precision); a non-finite one means A or the update overflowed; a pivot so
        // small (< 2⁻¹⁰²⁴) that its reciprocal overflows, or so large (> 2¹⁰²²) that it is
        // subnormal and would cost the solution its precision, is refused with them
        if big == 0.0 || !pivot.finite() || !r.finite() || r.size() < f64::MIN_POSITIVE {
            return Err(LuError::Singular { index: k });
        }
        self.dinv[k] = r;
        let (left, right) = self.a.split_at_mut((k + 1) * n);
        // ℓ_ik = a_ik / a_kk, i > k
        let l = &mut left[k * n + k + 1..];
        l.iter_mut().for_each(|v| *v *= r);
        // a_ij ← a_ij − ℓ_ik a_kj, i, j > k: column j minus a_kj times column k of L
        for col_j in right.chunks_exact_mut(n) {
            let akj = col_j[k];
            if akj.size() != 0.0 {
                for (aij, lik) in col_j[k + 1..].iter_mut().zip(l.iter()) {
                    *aij -= *lik * akj;
                }
            }
        }
        Ok(())
    }

    /// faer's blocked LU of the matrix given entrywise (n > [`LuScalar::UNBLOCKED_MAX_N`]), refused
    /// when a diagonal entry of U is zero or not finite (as before this module existed).
    fn factor_blocked(&mut self, entry: impl FnMut(usize, usize) -> T) -> Result<(), LuError> {
        self.blocked = None;
        let lu = Mat::<T>::from_fn(self.n, self.n, entry).partial_piv_lu();
        let u = lu.U();
        if let Some(k) = (0..self.n).find(|&k| {
            let d = u[(k, k)];
            !d.finite() || d.size() == 0.0
        }) {
            return Err(LuError::Singular { index: k });
        }
        self.blocked = Some(lu);
        Ok(())
    }

    /// x ← A⁻¹x from the last successful factorisation: x ← Px, then Ly = x (forward, L unit
    /// lower), then Ux = y (backward). No allocation for n ≤ [`LuScalar::UNBLOCKED_MAX_N`].
    ///
    /// # Errors
    /// [`LuError::WrongSize`] if `x.len()` ≠ n, [`LuError::NotFactored`] before a successful
    /// factorisation; x is then unchanged.
    pub fn solve(&self, x: &mut [T]) -> Result<(), LuError> {
        let n = self.n;
        if x.len() != n {
            return Err(LuError::WrongSize { what: "right-hand side", got: x.len(), expected: n });
        }
        if !self.factored {
            return Err(LuError::NotFactored);
        }
        if let Some(lu) = &self.blocked {
            let mut m = Mat::<T>::from_fn(n, 1, |i, _| x[i]);
            lu.solve_in_place(m.as_mut());
            for (i, xi) in x.iter_mut().enumerate() {
                *xi = m[(i, 0)];
            }
            return Ok(());
        }
        // x ← P x, the interchanges in the order they were made
        for (k, &p) in self.piv.iter().enumerate() {
            x.swap(k, p);
        }
        // L y = x, by columns: once yⱼ is final, xᵢ −= ℓᵢⱼ yⱼ for i > j
        for j in 0..n {
            let yj = x[j];
            let col = &self.a[j * n + j + 1..(j + 1) * n];
            for (xi, lij) in x[j + 1..].iter_mut().zip(col) {
                *xi -= *lij * yj;
            }
        }
        // U x = y, by columns from the last: xⱼ = yⱼ/uⱼⱼ, then yᵢ −= uᵢⱼ xⱼ for i < j
        for j in (0..n).rev() {
            let xj = x[j] * self.dinv[j];
            x[j] = xj;
            let col = &self.a[j * n..j * n + j];
            for (xi, uij) in x[..j].iter_mut().zip(col) {
                *xi -= *uij * xj;
            }
        }
        Ok(())
    }
}
