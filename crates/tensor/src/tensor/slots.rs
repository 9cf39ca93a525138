//! Slot operations: coform (3.1.15–18) and slot permutation (3.7.14).

use super::Tensor;
use crate::{Scalar, TensorError};

impl<T: Scalar> Tensor<T> {
    /// Coform T′ (3.1.15–18), of type (q, p): the former covector factors become vector
    /// factors and come first, the former vector factors become covector factors; order is
    /// **kept inside each group**. So (w⃗⊗z⃗′)′ = z⃗⊗w⃗′ (the transpose) and
    /// (w⃗₁⊗w⃗₂)′ = w⃗′₁⊗w⃗′₂; T″ = T and the coform is linear.
    ///
    /// Book: (3.1.15), (3.1.17), (3.1.18), Problem 3.10.2.
    ///
    /// # Conventions
    /// Order-preserving, as (3.1.15)/(3.1.17) and Problem 3.10.2 require. The book's
    /// (3.7.28) x⃗′∧y⃗′ = −(x⃗∧y⃗)′ and (3.7.30) assume an order-*reversing* coform and
    /// contradict those; with this coform (x⃗∧y⃗)′ = x⃗′∧y⃗′ (errata in the ch. 3 notes).
    pub fn coform(&self) -> Tensor<T> {
        // Reshaped to 3^p × 3^q (rows = vector slots), the coform is the transpose.
        let (rows, cols) = (3usize.pow(self.p as u32), 3usize.pow(self.q as u32));
        let mut data = Vec::with_capacity(self.data.len());
        for c in 0..cols {
            data.extend((0..rows).map(|r| self.data[r * cols + c]));
        }
        Tensor { p: self.q, q: self.p, data, limit: self.limit }
    }

    /// Slot permutation T_σ (3.7.14): T_σ(a₁, …, a_n) = T(a_σ(1), …, a_σ(n)), with σ a
    /// permutation of 1..=p+q (one-line notation, `sigma[k-1]` = σ(k)) that maps vector
    /// slots to vector slots and covector slots to covector slots (the canonical order puts
    /// vector slots first, L3721).
    ///
    /// Book: (3.7.14).
    ///
    /// # Conventions
    /// Components: T_σ[i₁…i_n] = T[i_σ(1)…i_σ(n)]. For a product x⃗₁⊗…⊗x⃗_n the factor x⃗_k
    /// moves to slot σ⁻¹(k)… that is, T_σ = x⃗_σ⁻¹(1)⊗…; the book writes x⃗_σ(1)⊗…, which
    /// is the same inside the signed sums of §3.7 (ch. 3 notes).
    ///
    /// # Errors
    /// [`TensorError::InvalidPermutation`] when σ is not a permutation of 1..=p+q or mixes
    /// vector and covector slots.
    pub fn permute(&self, sigma: &[usize]) -> Result<Tensor<T>, TensorError> {
        let n = self.order();
        let bad = || TensorError::InvalidPermutation { perm: sigma.to_vec(), order: n };
        if sigma.len() != n {
            return Err(bad());
        }
        let mut seen = vec![false; n];
        for (k, &s) in sigma.iter().enumerate() {
            if s == 0 || s > n || seen[s - 1] || ((k < self.p) != (s <= self.p)) {
                return Err(bad());
            }
            seen[s - 1] = true;
        }
        let src = super::product::strides(n);
        // T_σ[i₁…i_n] = T[i_σ(1)…i_σ(n)]: source slot k reads output digit σ(k), so output
        // slot σ(k) carries source stride k.
        let mut stride = vec![0usize; n];
        for (k, &s) in sigma.iter().enumerate() {
            stride[s - 1] = src[k];
        }
        let mut data = Vec::with_capacity(self.data.len());
        let mut digits = vec![0usize; n];
        let mut off = 0usize;
        for _ in 0..self.data.len() {
            data.push(self.data[off]);
            for k in (0..n).rev() {
                if digits[k] < 2 {
                    digits[k] += 1;
                    off += stride[k];
                    break;
                }
                digits[k] = 0;
                off -= 2 * stride[k];
            }
        }
        Ok(Tensor { p: self.p, q: self.q, data, limit: self.limit })
    }
}
