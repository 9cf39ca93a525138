//! Tensors of type (p, q) and any order (book ch. 3).

use crate::{Scalar, TensorError};

/// Default cap on the number of stored components (3^(p+q)): 3^14 ≈ 4.8 million.
pub const DEFAULT_MAX_COMPONENTS: usize = 4_782_969;

/// A tensor of type (p, q) (book §3.1): p vector slots then q covector slots, stored densely
/// with 3^(p+q) components in the hidden basis, first slot slowest.
///
/// Book: ch. 3, (3.1.x).
#[derive(Debug, Clone, PartialEq)]
pub struct Tensor<T: Scalar = f64> {
    pub(crate) p: usize,
    pub(crate) q: usize,
    pub(crate) data: Vec<T>,
}

impl<T: Scalar> Tensor<T> {
    /// Number of components 3^(p+q) for `order`, or the `TooLarge` error.
    pub fn components_for(order: usize, limit: usize) -> Result<usize, TensorError> {
        let needed = 3u128.checked_pow(order as u32).unwrap_or(u128::MAX);
        if needed > limit as u128 {
            return Err(TensorError::TooLarge { order, needed, limit });
        }
        Ok(needed as usize)
    }

    /// The zero tensor of type (p, q).
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when 3^(p+q) exceeds [`DEFAULT_MAX_COMPONENTS`].
    pub fn zeros(p: usize, q: usize) -> Result<Self, TensorError> {
        let n = Self::components_for(p + q, DEFAULT_MAX_COMPONENTS)?;
        Ok(Self { p, q, data: vec![T::zero(); n] })
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

    /// Reserved for `vectrix-frames` (see [`crate::Vector::from_hidden`]).
    #[doc(hidden)]
    pub fn from_hidden(p: usize, q: usize, data: Vec<T>) -> Result<Self, TensorError> {
        let n = Self::components_for(p + q, usize::MAX)?;
        if data.len() != n {
            return Err(TensorError::Shape {
                detail: format!("a ({p}, {q}) tensor has {n} components, got {}", data.len()),
            });
        }
        Ok(Self { p, q, data })
    }

    /// Reserved for `vectrix-frames` (see [`crate::Vector::hidden`]).
    #[doc(hidden)]
    pub fn hidden(&self) -> &[T] {
        &self.data
    }
}
