//! The special tensors of §3.3: metric, cometric, identity, ε tensor, U4.

use super::{DEFAULT_MAX_COMPONENTS, Tensor};
use crate::Scalar;

/// Kronecker δ as a scalar.
fn delta<T: Scalar>(i: usize, j: usize) -> T {
    if i == j { T::one() } else { T::zero() }
}

/// Levi-Civita symbol ε_ijk (3.3.18), indices 0-based.
pub(crate) fn levi_civita_symbol(i: usize, j: usize, k: usize) -> i8 {
    match (i, j, k) {
        (0, 1, 2) | (1, 2, 0) | (2, 0, 1) => 1,
        (0, 2, 1) | (2, 1, 0) | (1, 0, 2) => -1,
        _ => 0,
    }
}

impl<T: Scalar> Tensor<T> {
    /// Builds a tensor from a component function of the multi-index (hidden basis; all
    /// special tensors below are the same in every right-handed orthonormal frame).
    fn from_fn(p: usize, q: usize, f: impl Fn(&[usize]) -> T) -> Tensor<T> {
        let n = p + q;
        let len = 3usize.pow(n as u32);
        let mut idx = vec![0usize; n];
        let data = (0..len)
            .map(|mut k| {
                for slot in (0..n).rev() {
                    idx[slot] = k % 3;
                    k /= 3;
                }
                f(&idx)
            })
            .collect();
        Tensor { p, q, data, limit: DEFAULT_MAX_COMPONENTS }
    }

    /// The metric G = Σ ê′_i⊗ê′_i, type (0, 2) (3.3.9): G(x⃗, y⃗) = x⃗·y⃗ (3.1.9). It lowers a
    /// slot: (G⊗x⃗)_(1,1) = x⃗′ (3.3.10).
    ///
    /// Book: (3.1.9), (3.3.9), (3.3.10).
    pub fn metric() -> Tensor<T> {
        Self::from_fn(0, 2, |i| delta(i[0], i[1]))
    }

    /// The cometric G′ = Σ ê_i⊗ê_i, type (2, 0): it raises a slot, (G′⊗x⃗′)_(1,1) = x⃗, and
    /// (G′⊗G)_(1,1) = U (3.3.11–13).
    ///
    /// Book: (3.3.11)–(3.3.13).
    pub fn cometric() -> Tensor<T> {
        Self::from_fn(2, 0, |i| delta(i[0], i[1]))
    }

    /// The identity U = I = Σ ê_i⊗ê′_i, type (1, 1) (3.1.12), (3.1.24).
    ///
    /// Book: (3.1.12), (3.1.24), (3.3.13).
    pub fn identity() -> Tensor<T> {
        Self::from_fn(1, 1, |i| delta(i[0], i[1]))
    }

    /// The ε tensor E = −Σ ε_ijk ê_i⊗ê′_j⊗ê′_k, type (1, 2) (3.3.17), whose partial
    /// evaluation at a vector is its cross-product matrix: (E⊗x⃗)_(2,2) = x⃗^× (3.3.16).
    ///
    /// Book: (3.3.16)–(3.3.18); the book's upper summation limit "n" reads 3.
    ///
    /// # Conventions
    /// Frame-independent only among right-handed frames (a reflection flips its sign).
    pub fn levi_civita() -> Tensor<T> {
        Self::from_fn(1, 2, |i| T::lit(-f64::from(levi_civita_symbol(i[0], i[1], i[2]))))
    }

    /// U4 = U⊗U = Σ ê_i⊗ê_j⊗ê′_i⊗ê′_j, type (2, 2) (3.3.19), with
    /// (U4⊗M⃗)_(2,3),(3,1) = M⃗ and (U4⊗M⃗)_(2,3),(3,2) = (tr M⃗)U (3.3.21–22).
    ///
    /// Book: (3.3.19)–(3.3.22).
    pub fn u4() -> Tensor<T> {
        Self::from_fn(2, 2, |i| delta::<T>(i[0], i[2]) * delta::<T>(i[1], i[3]))
    }
}
