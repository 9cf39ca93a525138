//! Nonstandard and reciprocal frames (book §2.23).
//!
//! A nonstandard frame F_A = {a⃗₁, a⃗₂, a⃗₃} is any three linearly independent (dimensionless)
//! vectors, not necessarily unit or perpendicular. A vector has two resolutions:
//!
//! ```text
//! contravariant  x⃗ = Σ x_i a⃗_i,     x|_A   = [a⃗_[i]·x⃗]     (2.23.18–19)
//! covariant      x|_[A] = [a⃗_i·x⃗]                          (2.23.20–21)
//! reciprocal     a⃗_[1] = (a⃗₂ × a⃗₃)/α, cyclic, α = a⃗₁·(a⃗₂ × a⃗₃)  (2.23.9–11)
//! duality        a⃗_[i]·a⃗_j = δ_ij                            (2.23.13)
//! Gram           G_A = [a⃗_i·a⃗_j] = 𝓞_{A/[A]},  x|_[A] = G_A x|_A  (2.23.17)
//! ```
//!
//! Numerics: contravariant components solve A x|_A = x⃗ (A = the axes as columns) with an LU
//! factorisation of A; G⁻¹ = [a⃗_[i]·a⃗_[j]] (2.23.16) is never formed, since κ(G) = κ(A)²
//! (notes ch2b §3.9). A frame whose κ(A) exceeds the caller's limit is rejected with its
//! condition number.

use nalgebra::{LU, Matrix3, U3, Vector3};
use vectrix_tensor::frames_access::Hidden;
use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::{Frame, FrameError};

/// Default limit on the 2-norm condition number κ(A) of the axis matrix: 1e8, so that
/// κ(G) = κ(A)² stays below 1e16 ≈ 1/ε.
///
/// Book: §2.23 (linear independence of the axes).
pub const MAX_CONDITION: f64 = 1e8;

/// Which resolution a slot uses: contravariant x|_A or covariant x|_[A] (book §2.23).
///
/// Book: §2.23, (2.23.18–21).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Components {
    /// x|_A: the coefficients in x⃗ = Σ x_i a⃗_i (2.23.18).
    Contravariant,
    /// x|_[A] = [a⃗_i·x⃗]: the coefficients on the reciprocal frame (2.23.20).
    Covariant,
}

/// A nonstandard frame F_A = {a⃗₁, a⃗₂, a⃗₃} (book §2.23): three linearly independent vectors.
///
/// Book: §2.23, (2.23.1)–(2.23.56).
#[derive(Debug, Clone)]
pub struct NonstandardFrame<T: Scalar = f64> {
    /// Columns a⃗₁, a⃗₂, a⃗₃ in the hidden basis.
    axes: Matrix3<T>,
    /// LU of the axis matrix A, for x|_A = A⁻¹x⃗.
    lu: LU<T, U3, U3>,
    /// LU of Aᵀ, for the inverse of the covariant resolution.
    lu_t: LU<T, U3, U3>,
    /// κ₂(A) of the real parts.
    cond: f64,
}

/// 2-norm condition number σ_max/σ_min of the real parts (∞ when singular).
fn condition_number<T: Scalar>(a: &Matrix3<T>) -> f64 {
    let re = a.map(|x| x.re());
    let s = re.singular_values();
    let (max, min) = (s.max(), s.min());
    if min == 0.0 { f64::INFINITY } else { max / min }
}

impl<T: Scalar> NonstandardFrame<T> {
    /// The nonstandard frame with axes a⃗₁, a⃗₂, a⃗₃.
    ///
    /// Book: §2.23 (linear independence, Fact 2.4.4: a⃗₁·(a⃗₂×a⃗₃) ≠ 0).
    ///
    /// # Errors
    /// [`FrameError::NonFinite`] for NaN/∞ components; [`FrameError::ZeroAxis`] for a zero axis;
    /// [`FrameError::Degenerate`] with κ₂(A) when it exceeds `max_cond` (use
    /// [`MAX_CONDITION`]); [`FrameError::Tensor`] (`InvalidTolerance`) for a `max_cond` that is
    /// NaN or below 1 (+∞ means no limit).
    pub fn from_axes(
        a1: &Vector<T>,
        a2: &Vector<T>,
        a3: &Vector<T>,
        max_cond: f64,
    ) -> Result<Self, FrameError> {
        // κ ≥ 1 for every matrix: a limit below 1 (or NaN) accepts nothing; +∞ means no limit.
        if max_cond.is_nan() || max_cond < 1.0 {
            return Err(FrameError::Tensor(vectrix_tensor::TensorError::InvalidTolerance {
                what: "max_cond (must be ≥ 1)",
                value: max_cond,
            }));
        }
        const NAMES: [&str; 3] = ["axis a₁", "axis a₂", "axis a₃"];
        for (a, what) in [a1, a2, a3].into_iter().zip(NAMES) {
            if !a.is_finite() {
                return Err(FrameError::NonFinite { what });
            }
            if a.norm() == T::zero() {
                return Err(FrameError::ZeroAxis { what });
            }
        }
        let axes = Matrix3::from_columns(&[*a1.hidden(), *a2.hidden(), *a3.hidden()]);
        let cond = condition_number(&axes);
        // An exactly singular A (κ = ∞) is rejected whatever the limit.
        if !cond.is_finite() || cond > max_cond {
            return Err(FrameError::Degenerate { cond, limit: max_cond });
        }
        Ok(Self { axes, lu: axes.lu(), lu_t: axes.transpose().lu(), cond })
    }

    /// A standard frame seen as a nonstandard one; its reciprocal frame is itself (§2.23).
    ///
    /// Book: §2.23 (a standard frame is its own reciprocal).
    pub fn from_frame(a: &Frame<T>) -> Self {
        let axes = a.axes;
        Self { axes, lu: axes.lu(), lu_t: axes.transpose().lu(), cond: 1.0 }
    }

    /// Axis a⃗_n, n ∈ {1, 2, 3}; `None` otherwise.
    ///
    /// Book: §2.23, (2.23.1).
    pub fn axis(&self, n: usize) -> Option<Vector<T>> {
        (1..=3).contains(&n).then(|| Vector::from_hidden(self.axes.column(n - 1).into_owned()))
    }

    /// The three axes [a⃗₁, a⃗₂, a⃗₃].
    ///
    /// Book: §2.23, (2.23.1).
    pub fn axes(&self) -> [Vector<T>; 3] {
        [0, 1, 2].map(|k| Vector::from_hidden(self.axes.column(k).into_owned()))
    }

    /// κ₂ of the axis matrix (σ_max/σ_min, real parts): κ(G_A) = κ² (notes ch2b §3.9).
    ///
    /// Book: §2.23 (numerics: notes ch2b §3.9).
    pub fn condition_number(&self) -> f64 {
        self.cond
    }

    /// α = a⃗₁·(a⃗₂ × a⃗₃) (2.23.9), the signed volume of the axes.
    ///
    /// Book: (2.23.9).
    pub fn alpha(&self) -> T {
        let [a1, a2, a3] = self.axes();
        a1.triple(&a2, &a3)
    }

    /// The reciprocal frame F_[A]: a⃗_[1] = (a⃗₂ × a⃗₃)/α, a⃗_[2] = (a⃗₃ × a⃗₁)/α,
    /// a⃗_[3] = (a⃗₁ × a⃗₂)/α (2.23.9–11); a⃗_[i]·a⃗_j = δ_ij (2.23.13).
    ///
    /// Book: (2.23.9–13), Fact 2.23.4.
    pub fn reciprocal(&self) -> NonstandardFrame<T> {
        let [a1, a2, a3] = self.axes();
        let alpha = self.alpha();
        let r = [a2.cross(&a3), a3.cross(&a1), a1.cross(&a2)].map(|v| *(v / alpha).hidden());
        let axes = Matrix3::from_columns(&r);
        // κ(A⁻ᵀ) = κ(A): the reciprocal is exactly as well conditioned.
        Self { axes, lu: axes.lu(), lu_t: axes.transpose().lu(), cond: self.cond }
    }

    /// The Gram matrix G_A = [a⃗_i·a⃗_j] = 𝓞_{A/[A]} (2.23.17): symmetric positive definite
    /// (the book's Fact 2.23.7 says "semidefinite"; for independent axes it is definite).
    ///
    /// Book: (2.23.17), Fact 2.23.7 (corrected).
    pub fn gram(&self) -> Matrix3<T> {
        self.axes.tr_mul(&self.axes)
    }

    /// Contravariant components x|_A: x⃗ = Σ x_i a⃗_i (2.23.18), i.e. x|_A = [a⃗_[i]·x⃗]
    /// (2.23.19), found by solving A x|_A = x⃗ with LU (never G⁻¹).
    ///
    /// Book: (2.23.18–19).
    pub fn contravariant(&self, x: &Vector<T>) -> Vector3<T> {
        self.solve(x.hidden())
    }

    /// Covariant components x|_[A] = [a⃗_i·x⃗] (2.23.20–21); x|_[A] = G_A x|_A.
    ///
    /// Book: (2.23.20–21).
    pub fn covariant(&self, x: &Vector<T>) -> Vector3<T> {
        self.axes.tr_mul(x.hidden())
    }

    /// x⃗ = Σ x_i a⃗_i from contravariant components (2.23.18).
    ///
    /// Book: (2.23.18).
    pub fn vector(&self, x_in_a: [T; 3]) -> Vector<T> {
        Vector::from_hidden(self.axes * Vector3::from(x_in_a))
    }

    /// x⃗ = Σ x_[i] a⃗_[i] from covariant components (2.23.20), by solving Aᵀ x⃗ = x|_[A].
    ///
    /// Book: (2.23.20–21).
    pub fn vector_from_covariant(&self, x_in_ra: [T; 3]) -> Vector<T> {
        Vector::from_hidden(self.solve_t(&Vector3::from(x_in_ra)))
    }

    /// A⁻¹ v by LU. A is nonsingular by construction (κ checked), so the solve succeeds; the
    /// zero fallback is unreachable and only guards the `Option` of nalgebra's API.
    fn solve(&self, v: &Vector3<T>) -> Vector3<T> {
        self.lu.solve(v).unwrap_or_else(Vector3::zeros)
    }

    /// A⁻ᵀ v by LU of Aᵀ (see [`Self::solve`]).
    fn solve_t(&self, v: &Vector3<T>) -> Vector3<T> {
        self.lu_t.solve(v).unwrap_or_else(Vector3::zeros)
    }

    /// L_X m for X = A (L = A⁻¹: contravariant) or [A] (L = Aᵀ: covariant), column by column.
    fn left(&self, c: Components, m: &Matrix3<T>) -> Matrix3<T> {
        match c {
            Components::Contravariant => self.lu.solve(m).unwrap_or_else(Matrix3::zeros),
            Components::Covariant => self.axes.tr_mul(m),
        }
    }

    /// L_X⁻¹ m: A m (contravariant) or A⁻ᵀ m (covariant).
    fn left_inv(&self, c: Components, m: &Matrix3<T>) -> Matrix3<T> {
        match c {
            Components::Contravariant => self.axes * m,
            Components::Covariant => self.lu_t.solve(m).unwrap_or_else(Matrix3::zeros),
        }
    }

    /// Resolution M|_{X,Y} = Σ x_i|_X y_i|_Yᵀ of M⃗ = Σ x⃗_i y⃗_i′ (2.23.33–56), with X and Y
    /// each contravariant (A) or covariant ([A]):
    ///
    /// - M|_{[A],[A]} entries a⃗_i′M⃗a⃗_j (2.23.36); M|_{A,A} entries a⃗_[i]′M⃗a⃗_[j] (2.23.39);
    /// - M|_{[A],[A]} = G M|_{A,A} G (2.23.49); I⃗|_{A,A} = G⁻¹, I⃗|_{[A],[A]} = G (2.23.47);
    /// - mixed: M|_{A,[A]} = M|_{A,A} G maps contravariant to contravariant,
    ///   (M⃗x⃗)|_A = M|_{A,[A]} x|_A (2.23.46); M|_{[A],A} = G M|_{A,A} (2.23.55–56);
    ///   I⃗|_{[A],A} = I₃.
    ///
    /// Book: §2.23, (2.23.33–56). (2.23.44–45) have index typos and F2.23.12 is printed
    /// wrongly (the correct statement is y|_[A] = G M|_A x|_[A]); see the ch2b notes.
    pub fn resolve_dyadic(&self, m: &Dyadic<T>, left: Components, right: Components) -> Matrix3<T> {
        resolve_dyadic_mixed(m, (self, left), (self, right))
    }

    /// The dyadic M⃗ whose resolution M|_{X,Y} is `m` (inverse of
    /// [`NonstandardFrame::resolve_dyadic`]).
    ///
    /// # Errors
    /// [`FrameError::NonFinite`] for NaN/∞ entries.
    ///
    /// Book: §2.23, (2.23.33–56).
    pub fn dyadic(
        &self,
        m: &Matrix3<T>,
        left: Components,
        right: Components,
    ) -> Result<Dyadic<T>, FrameError> {
        if !m.iter().all(|x| x.re().is_finite()) {
            return Err(FrameError::NonFinite { what: "resolved dyadic" });
        }
        let lm = self.left_inv(left, m);
        Ok(Dyadic::from_hidden(self.left_inv(right, &lm.transpose()).transpose()))
    }

    /// 𝓞_{self/A} for nonstandard frames: b⃗_i = Σ_j 𝓞_ij a⃗_j with 𝓞_ij = b⃗_i·a⃗_[j] (2.23.4);
    /// with the axes as the columns of A and B, 𝓞_{B/A} = (A⁻¹B)ᵀ (= BA⁻¹ with axes as rows).
    /// Contravariant components change by x|_B = 𝓞_{B/A}^{−T} x|_A (2.23.7), covariant ones by
    /// x|_[B] = 𝓞_{B/A} x|_[A] (2.23.27, corrected: the book prints x|_A in the middle).
    ///
    /// Book: (2.23.4–8), (2.23.27–28).
    pub fn orientation_rel(&self, a: &NonstandardFrame<T>) -> Matrix3<T> {
        a.lu.solve(&self.axes).unwrap_or_else(Matrix3::zeros).transpose()
    }
}

/// Mixed resolution in two nonstandard frames, M|_{X,Y} = Σ x_i|_X y_i|_Yᵀ for
/// M⃗ = Σ x⃗_i y⃗_i′, where X is (frame B, contravariant or covariant) and Y is (frame A, …).
/// With X = B and Y = A contravariant, (M⃗x⃗)|_B = M|_{B,A} x|_[A] (2.23.53).
///
/// Book: §2.23, (2.23.52–56), Fact 2.23.13.
pub fn resolve_dyadic_mixed<T: Scalar>(
    m: &Dyadic<T>,
    left: (&NonstandardFrame<T>, Components),
    right: (&NonstandardFrame<T>, Components),
) -> Matrix3<T> {
    // M|_{X,Y} = L_X M L_Yᵀ, with L_A = A⁻¹ (contravariant) and L_[A] = Aᵀ (covariant).
    let lm = left.0.left(left.1, m.hidden());
    right.0.left(right.1, &lm.transpose()).transpose()
}
