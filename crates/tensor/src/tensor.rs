//! Tensors of type (p, q) and any order (book ch. 3).
//!
//! A tensor is a real-valued map of p covectors and q vectors, linear in each argument
//! (§3.1); it is a sum of tensor products of physical vectors and covectors (3.1.13). vectrix
//! keeps it densely, 3^(p+q) components in the hidden reference basis, **vector slots first,
//! first slot slowest**, so that reshaping the array to 3^p × 3^q gives exactly the book's
//! Kronecker resolution T|_A of (3.6.2) when the frame is the reference basis.
//!
//! The submodules are split by verb: [`product`](self) (tensor product, contraction, fused
//! contracted product, evaluation), slot operations (coform, permutation) and the special
//! tensors (metric, cometric, identity, ε tensor, U4).

mod product;
mod slots;
mod special;

pub(crate) use special::levi_civita_symbol;

use core::ops::{Mul, Neg};

pub use product::Arg;

use crate::{Covector, Dyadic, Scalar, TensorError, Vector};

/// Default cap on the number of stored components (3^(p+q)) that a tensor carries:
/// 3^14 = 4 782 969 (order 14, 38 MB of `f64`).
pub const DEFAULT_MAX_COMPONENTS: usize = 4_782_969;

/// A tensor of type (p, q) (book §3.1): p vector slots then q covector slots, stored densely
/// with 3^(p+q) components in the hidden basis, first slot slowest.
///
/// Book: ch. 3, (3.1.13), (3.1.14), type (p, q) at L3717, canonical slot order at L3721.
///
/// # Conventions
/// - *Type (p, q)*: p vector factors (they take covector arguments), then q covector factors
///   (they take vector arguments). Order p + q.
/// - *Slot numbering* follows the book: in a contraction (i, j) or a partial evaluation, a
///   vector slot is numbered 1..=p within the vector group and a covector slot 1..=q within
///   the covector group (3.2.2), (3.3.2).
/// - Resolved in a frame A (crate `vectrix-frames`) the tensor is the 3^p × 3^q Kronecker
///   matrix of (3.6.2): rows are the vector slots, columns the covector slots, first slot
///   slowest.
///
/// # Size cap
/// Each tensor carries a cap on stored components ([`Tensor::max_components`], default
/// [`DEFAULT_MAX_COMPONENTS`]); there is no process-wide setting. Set it on a value with
/// [`Tensor::with_max_components`] or build with [`Tensor::zeros_with_limit`] /
/// [`Tensor::from_factors_with_limit`]; a result of two tensors (product, contraction, sum,
/// wedge) carries the larger of its operands' caps, and a result of one tensor keeps its cap.
/// Equality (`==`) compares type and components, not caps.
///
/// ```
/// use vectrix_tensor::{DEFAULT_MAX_COMPONENTS, Tensor, TensorError};
/// let t = Tensor::<f64>::zeros(7, 0)?; // 3^7 components, default cap 3^14
/// assert_eq!(t.max_components(), DEFAULT_MAX_COMPONENTS);
/// // order 15 is refused before anything is allocated ...
/// assert!(matches!(t.otimes(&Tensor::zeros(0, 8)?), Err(TensorError::TooLarge { order: 15, .. })));
/// // ... unless an operand carries a larger cap (the product takes the larger of the two)
/// let raised = t.with_max_components(3usize.pow(15))?;
/// assert_eq!(raised.otimes(&Tensor::scalar(2.0))?.max_components(), 3usize.pow(15));
/// # Ok::<(), TensorError>(())
/// ```
///
/// # Errors
/// Every constructor and operation refuses a result whose 3^(p+q) components would exceed
/// the cap with [`TensorError::TooLarge`]; nothing ever tries the allocation.
#[derive(Debug, Clone)]
pub struct Tensor<T: Scalar = f64> {
    pub(crate) p: usize,
    pub(crate) q: usize,
    pub(crate) data: Vec<T>,
    /// The cap on stored components for results built from this tensor.
    pub(crate) limit: usize,
}

/// Type and components; the size cap is a resource limit, not part of the value.
impl<T: Scalar> PartialEq for Tensor<T> {
    fn eq(&self, other: &Self) -> bool {
        (self.p, self.q) == (other.p, other.q) && self.data == other.data
    }
}

impl<T: Scalar> Tensor<T> {
    /// Number of components 3^order, or [`TensorError::TooLarge`] when above `limit`.
    ///
    /// Book: (3.6.2) (a (p, q) tensor has 3^(p+q) components in three dimensions).
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when 3^order exceeds `limit` (or `u128`).
    pub fn components_for(order: usize, limit: usize) -> Result<usize, TensorError> {
        let needed = u32::try_from(order).ok().and_then(|k| 3u128.checked_pow(k)).unwrap_or(u128::MAX);
        if needed > limit as u128 {
            return Err(TensorError::TooLarge { order, needed, limit });
        }
        Ok(needed as usize)
    }

    /// This tensor's cap on stored components (default [`DEFAULT_MAX_COMPONENTS`]): results
    /// built from it may hold at most this many (see the type's "Size cap").
    ///
    /// Book: DESIGN §5 (tensor orders whose 3^k storage would not fit are errors).
    pub fn max_components(&self) -> usize {
        self.limit
    }

    /// The same tensor carrying the cap `limit` on stored components. Raise it for high-order
    /// work (3^16 components need 344 MB of `f64`); lower it to fail early (on every operand:
    /// a result of two tensors takes the larger cap).
    ///
    /// Book: DESIGN §5.
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when this tensor itself holds more than `limit` components.
    pub fn with_max_components(self, limit: usize) -> Result<Self, TensorError> {
        Self::components_for(self.order(), limit)?;
        Ok(Self { limit, ..self })
    }

    /// Components for a (p, q) tensor under the cap `limit`.
    pub(crate) fn checked_len(p: usize, q: usize, limit: usize) -> Result<usize, TensorError> {
        Self::components_for(p.saturating_add(q), limit)
    }

    /// The cap of a result of `self` and `other`: the larger of the two.
    pub(crate) fn joint_limit(&self, other: &Tensor<T>) -> usize {
        self.limit.max(other.limit)
    }

    /// The zero tensor of type (p, q), with the default cap [`DEFAULT_MAX_COMPONENTS`].
    ///
    /// Book: §3.1 (the zero tensor of type (p, q)).
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when 3^(p+q) exceeds [`DEFAULT_MAX_COMPONENTS`].
    pub fn zeros(p: usize, q: usize) -> Result<Self, TensorError> {
        Self::zeros_with_limit(p, q, DEFAULT_MAX_COMPONENTS)
    }

    /// The zero tensor of type (p, q) carrying the cap `limit` on stored components.
    ///
    /// Book: §3.1; DESIGN §5.
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when 3^(p+q) exceeds `limit`; nothing is allocated then.
    pub fn zeros_with_limit(p: usize, q: usize, limit: usize) -> Result<Self, TensorError> {
        let n = Self::checked_len(p, q, limit)?;
        Ok(Self { p, q, data: vec![T::zero(); n], limit })
    }

    /// A scalar as a tensor of type (0, 0) (order 0, book L3717).
    pub fn scalar(s: T) -> Self {
        Self { p: 0, q: 0, data: vec![s], limit: DEFAULT_MAX_COMPONENTS }
    }

    /// The vector x⃗ as a (1, 0) tensor.
    pub fn from_vector(x: &Vector<T>) -> Self {
        Self { p: 1, q: 0, data: x.c.as_slice().to_vec(), limit: DEFAULT_MAX_COMPONENTS }
    }

    /// The covector x⃗′ as a (0, 1) tensor.
    pub fn from_covector(x: &Covector<T>) -> Self {
        Self { p: 0, q: 1, data: x.c.as_slice().to_vec(), limit: DEFAULT_MAX_COMPONENTS }
    }

    /// The physical matrix M⃗ as a (1, 1) tensor: w⃗⊗z⃗′ ≡ w⃗z⃗′ (3.1.23).
    ///
    /// Book: (3.1.23).
    pub fn from_dyadic(m: &Dyadic<T>) -> Self {
        let data = (0..9).map(|k| m.m[(k / 3, k % 3)]).collect();
        Self { p: 1, q: 1, data, limit: DEFAULT_MAX_COMPONENTS }
    }

    /// The product w⃗₁⊗…⊗w⃗_p⊗z⃗′₁⊗…⊗z⃗′_q of (3.1.13), a tensor of type (p, q).
    ///
    /// Book: (3.1.13), (3.6.1).
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when 3^(p+q) exceeds [`DEFAULT_MAX_COMPONENTS`].
    pub fn from_factors(vectors: &[Vector<T>], covectors: &[Covector<T>]) -> Result<Self, TensorError> {
        Self::from_factors_with_limit(vectors, covectors, DEFAULT_MAX_COMPONENTS)
    }

    /// [`Tensor::from_factors`] carrying the cap `limit` on stored components.
    ///
    /// Book: (3.1.13), (3.6.1); DESIGN §5.
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when 3^(p+q) exceeds `limit`, before the product is formed.
    pub fn from_factors_with_limit(
        vectors: &[Vector<T>],
        covectors: &[Covector<T>],
        limit: usize,
    ) -> Result<Self, TensorError> {
        Self::checked_len(vectors.len(), covectors.len(), limit)?;
        // every factor carries `limit`, so the product does too
        let mut t = Self { p: 0, q: 0, data: vec![T::one()], limit };
        for w in vectors {
            t = t.otimes(&Self { limit, ..Self::from_vector(w) })?;
        }
        for z in covectors {
            t = t.otimes(&Self { limit, ..Self::from_covector(z) })?;
        }
        Ok(t)
    }

    /// Vector slots p.
    pub fn p(&self) -> usize {
        self.p
    }

    /// Covector slots q.
    pub fn q(&self) -> usize {
        self.q
    }

    /// Order p + q.
    pub fn order(&self) -> usize {
        self.p + self.q
    }

    /// The (1, 0) tensor as a vector; `None` for any other type.
    pub fn to_vector(&self) -> Option<Vector<T>> {
        (self.p == 1 && self.q == 0).then(|| Vector { c: nalgebra::Vector3::from_column_slice(&self.data) })
    }

    /// The (0, 1) tensor as a covector; `None` for any other type.
    pub fn to_covector(&self) -> Option<Covector<T>> {
        (self.p == 0 && self.q == 1).then(|| Covector { c: nalgebra::Vector3::from_column_slice(&self.data) })
    }

    /// The (1, 1) tensor as a physical matrix (3.1.23); `None` for any other type.
    pub fn to_dyadic(&self) -> Option<Dyadic<T>> {
        (self.p == 1 && self.q == 1).then(|| Dyadic { m: nalgebra::Matrix3::from_row_slice(&self.data) })
    }

    /// The (0, 0) tensor as its scalar; `None` for any other type.
    pub fn to_scalar(&self) -> Option<T> {
        (self.order() == 0).then(|| self.data[0])
    }

    /// Frobenius norm of the dense array (frame-independent for orthonormal frames). For an
    /// alternating tensor this is √(k!) times the geometric magnitude; see
    /// [`Tensor::alternating_magnitude`].
    pub fn frobenius_norm(&self) -> T {
        self.data.iter().fold(T::zero(), |s, &x| s + x * x).sqrt()
    }

    /// `true` when every component is finite.
    pub fn is_finite(&self) -> bool {
        crate::scalar::all_finite(&self.data)
    }

    /// Sum of two tensors of the same type.
    ///
    /// # Errors
    /// [`TensorError::Shape`] when the types differ.
    pub fn try_add(&self, other: &Tensor<T>) -> Result<Tensor<T>, TensorError> {
        self.same_type(other, "add")?;
        let data = self.data.iter().zip(&other.data).map(|(&a, &b)| a + b).collect();
        Ok(Tensor { p: self.p, q: self.q, data, limit: self.joint_limit(other) })
    }

    /// Difference of two tensors of the same type.
    ///
    /// # Errors
    /// [`TensorError::Shape`] when the types differ.
    pub fn try_sub(&self, other: &Tensor<T>) -> Result<Tensor<T>, TensorError> {
        self.same_type(other, "subtract")?;
        let data = self.data.iter().zip(&other.data).map(|(&a, &b)| a - b).collect();
        Ok(Tensor { p: self.p, q: self.q, data, limit: self.joint_limit(other) })
    }

    fn same_type(&self, other: &Tensor<T>, verb: &str) -> Result<(), TensorError> {
        if (self.p, self.q) != (other.p, other.q) {
            return Err(TensorError::Shape {
                detail: format!(
                    "cannot {verb} a ({}, {}) tensor and a ({}, {}) tensor: the types must be equal",
                    self.p, self.q, other.p, other.q
                ),
            });
        }
        Ok(())
    }
}

impl<T: Scalar> Neg for &Tensor<T> {
    type Output = Tensor<T>;
    fn neg(self) -> Tensor<T> {
        Tensor { p: self.p, q: self.q, data: self.data.iter().map(|&a| -a).collect(), limit: self.limit }
    }
}

/// Scaling α T (3.5.5 analogue: a scalar is a tensor of order 0).
impl<T: Scalar> Mul<T> for &Tensor<T> {
    type Output = Tensor<T>;
    fn mul(self, s: T) -> Tensor<T> {
        Tensor { p: self.p, q: self.q, data: self.data.iter().map(|&a| a * s).collect(), limit: self.limit }
    }
}
