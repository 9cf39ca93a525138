//! Eigenaxis and eigenangle (book §2.11): Euler's theorem as a value with its singular cases.

use vectrix_tensor::{Scalar, Vector};

/// Eigenaxis n̂ and eigenangle θ ∈ [0, π] of a rotation (Euler's theorem, §2.11), with the two
/// cases the book treats separately as their own variants:
///
/// - `Identity`: tr 𝓡 = 3, θ = 0, every axis is an eigenaxis (Fact 2.11.4);
/// - `HalfTurn(n̂)`: tr 𝓡 = −1, θ = π, both ±n̂ are eigenaxes (Fact 2.11.5); vectrix returns
///   the canonical sign (first nonzero component positive in the frame of resolution);
/// - `General { axis, angle }`: θ ∈ (0, π), n̂ unique (2.11.49).
///
/// `V` is the axis type: the physical [`Vector`] (frame-free, from
/// [`crate::Rotation::axis_angle`]) or resolved components `nalgebra::Vector3<T>` (from
/// [`crate::Quaternion::axis_angle`]).
///
/// Book: §2.11, Facts 2.11.4–5, (2.11.49–51).
#[derive(Debug, Clone, Copy, PartialEq)]
#[doc(alias = "EigenAxis")]
pub enum AxisAngle<T: Scalar = f64, V = Vector<T>> {
    /// θ = 0 (Fact 2.11.4).
    Identity,
    /// θ = π about ±n̂ (Fact 2.11.5).
    HalfTurn(V),
    /// θ ∈ (0, π) about the unique n̂.
    General {
        /// The eigenaxis n̂ (unit).
        axis: V,
        /// The eigenangle θ ∈ (0, π).
        angle: T,
    },
}

impl<T: Scalar, V: Copy> AxisAngle<T, V> {
    /// The eigenangle θ ∈ [0, π] (2.11.49–50).
    pub fn angle(&self) -> T {
        match self {
            AxisAngle::Identity => T::zero(),
            AxisAngle::HalfTurn(_) => T::pi(),
            AxisAngle::General { angle, .. } => *angle,
        }
    }

    /// The eigenaxis; `None` for the identity, where every axis qualifies (Fact 2.11.4).
    pub fn axis(&self) -> Option<V> {
        match self {
            AxisAngle::Identity => None,
            AxisAngle::HalfTurn(n) => Some(*n),
            AxisAngle::General { axis, .. } => Some(*axis),
        }
    }
}
