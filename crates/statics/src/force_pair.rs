//! Third-law force pairs: the force on y due to w and its partner on w (book §6.7, Fact 6.9.1),
//! the result of every two-point force element (springs, dashpots, inerters, gravitation).

use vectrix_tensor::{Scalar, Vector};

/// A force on y and its third-law partner on w: f⃗_{y/w} and f⃗_{w/y} = −f⃗_{y/w}, both along
/// r⃗_{y/w} (Fact 6.9.1).
///
/// Book: Fact 6.9.1, (6.7.2), (6.8.2), (7.12.2), (7.12.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForcePair<T: Scalar = f64> {
    /// f⃗_{y/w}: the force on y due to w.
    pub on_y: Vector<T>,
    /// f⃗_{w/y} = −f⃗_{y/w}: the force on w due to y.
    pub on_w: Vector<T>,
}

impl<T: Scalar> ForcePair<T> {
    /// The pair (f⃗, −f⃗).
    ///
    /// Book: §6.7, Fact 6.9.1.
    #[inline]
    pub fn from_force_on_y(f_y_w: Vector<T>) -> Self {
        Self { on_y: f_y_w, on_w: -f_y_w }
    }
}
