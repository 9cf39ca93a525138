//! Component access for `vectrix-frames` only (cargo feature `frames-access`).
//!
//! The kernel's objects hold components in one hidden reference basis that no user sees
//! (book §1.3; DESIGN §1.1, §1.5). `vectrix-frames` is the one layer that turns them into
//! numbers, x⃗|_A = 𝓕_Aᵀ x (2.4.14), and numbers into objects, x⃗ = F_A x|_A (2.4.15); it
//! needs the hidden components to do so. Every other crate, test, bench, example, notebook
//! and the Python binding resolves in a frame instead.
//!
//! How this is sealed (Rust has no friend crates):
//! - this module exists only with the non-default feature `frames-access`, which only
//!   `crates/frames/Cargo.toml` enables; it is re-exported nowhere and hidden from the docs;
//! - the accessors are trait methods, so they cannot be called without importing these traits
//!   by this module's path;
//! - the source scan `tests/adversarial/sealed.rs` fails when any file outside
//!   `crates/tensor` and `crates/frames` names this module or the feature.
//!
//! A token type that only `vectrix-frames` could obtain would need the kernel to know its
//! caller; anything the kernel hands out can be obtained by every crate in the same build, so
//! no such token is sound. The feature keeps the accessors out of every build that does not
//! contain the frames layer, and the scan keeps them out of every other crate's source.
//!
//! Book: §1.3 (physical vectors have no components), (2.4.14)–(2.4.16); DESIGN §1.1, §1.5.

use nalgebra::{Matrix3, Vector3};

use crate::{Covector, Dyadic, Scalar, Tensor, TensorError, Vector};

/// An object of fixed size read and built through its hidden components: for the frames layer
/// only (see the module docs).
///
/// Book: (2.4.14)–(2.4.16); DESIGN §1.5.
pub trait Hidden: Sized {
    /// The component array: `Vector3` for vectors and covectors, `Matrix3` for dyadics.
    type Components;
    /// The components in the hidden basis.
    fn hidden(&self) -> &Self::Components;
    /// The object whose components in the hidden basis are `c`.
    fn from_hidden(c: Self::Components) -> Self;
}

/// x⃗ ↔ its hidden components (2.4.14–15).
impl<T: Scalar> Hidden for Vector<T> {
    type Components = Vector3<T>;
    #[inline(always)]
    fn hidden(&self) -> &Vector3<T> {
        &self.c
    }
    #[inline(always)]
    fn from_hidden(c: Vector3<T>) -> Self {
        Vector { c }
    }
}

/// x⃗′ ↔ its hidden components (2.4.20).
impl<T: Scalar> Hidden for Covector<T> {
    type Components = Vector3<T>;
    #[inline(always)]
    fn hidden(&self) -> &Vector3<T> {
        &self.c
    }
    #[inline(always)]
    fn from_hidden(c: Vector3<T>) -> Self {
        Covector { c }
    }
}

/// M⃗ ↔ its hidden components (2.6.28).
impl<T: Scalar> Hidden for Dyadic<T> {
    type Components = Matrix3<T>;
    #[inline(always)]
    fn hidden(&self) -> &Matrix3<T> {
        &self.m
    }
    #[inline(always)]
    fn from_hidden(m: Matrix3<T>) -> Self {
        Dyadic { m }
    }
}

/// A tensor of type (p, q) read and built through its 3^(p+q) hidden components, first slot
/// slowest: for the frames layer only (see the module docs).
///
/// Book: §3.6, (3.6.2); DESIGN §1.5.
pub trait HiddenTensor<T: Scalar>: Sized {
    /// The dense components in the hidden basis, vector slots first, first slot slowest.
    fn hidden(&self) -> &[T];
    /// The (p, q) tensor with these hidden components, carrying the cap `limit` on stored
    /// components (see [`Tensor::max_components`]).
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when 3^(p+q) exceeds `limit`; [`TensorError::Shape`] when
    /// `data` does not hold 3^(p+q) components; [`TensorError::NonFinite`] for NaN or ∞.
    fn from_hidden(p: usize, q: usize, data: Vec<T>, limit: usize) -> Result<Self, TensorError>;
}

/// T ↔ its hidden components (3.6.2).
impl<T: Scalar> HiddenTensor<T> for Tensor<T> {
    #[inline(always)]
    fn hidden(&self) -> &[T] {
        &self.data
    }
    fn from_hidden(p: usize, q: usize, data: Vec<T>, limit: usize) -> Result<Self, TensorError> {
        let n = Tensor::<T>::components_for(p.saturating_add(q), limit)?;
        if data.len() != n {
            return Err(TensorError::Shape {
                detail: format!("a ({p}, {q}) tensor has {n} components, got {}", data.len()),
            });
        }
        if !crate::scalar::all_finite(&data) {
            return Err(TensorError::NonFinite { what: "tensor components" });
        }
        Ok(Tensor { p, q, data, limit })
    }
}
