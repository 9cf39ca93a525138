//! Points located by position vectors (book §1.3, §6.1).
//!
//! A vectrix frame has no origin (book §2.4), so a point is located by its position
//! r⃗_{y/o} relative to one reference point o shared by every point of a problem. Only
//! differences r⃗_{y/x} = r⃗_{y/o} − r⃗_{x/o} have meaning; o never has to be named.

use core::ops::Sub;

use vectrix_tensor::{Scalar, Vector};

/// A point y, stored as r⃗_{y/o}: its position relative to the problem's reference point o.
///
/// Book: §1.3, (6.1.2). All points that meet in one computation must share the same o.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point<T: Scalar = f64> {
    r_y_o: Vector<T>,
}

impl<T: Scalar> Point<T> {
    /// The reference point o itself (r⃗_{o/o} = 0⃗).
    ///
    /// Book: §1.3, §6.1.
    #[inline]
    pub fn origin() -> Self {
        Self { r_y_o: Vector::zero() }
    }

    /// The point y with r⃗_{y/o} = `r_y_o`.
    ///
    /// Book: §1.3, §6.1.
    #[inline]
    pub fn at(r_y_o: Vector<T>) -> Self {
        Self { r_y_o }
    }

    /// r⃗_{y/o}: position relative to the reference point.
    ///
    /// Book: §1.3, §6.1.
    #[inline]
    pub fn position(&self) -> Vector<T> {
        self.r_y_o
    }

    /// r⃗_{y/x} = r⃗_{y/o} − r⃗_{x/o}: position of `self` (y) relative to `x`.
    ///
    /// Book: §1.3; argument order is subscript order, `y.position_rel(&x)` is r⃗_{y/x}.
    #[inline]
    pub fn position_rel(&self, x: &Point<T>) -> Vector<T> {
        self.r_y_o - x.r_y_o
    }

    /// The point reached from `self` by the displacement d⃗: r⃗_{z/o} = r⃗_{y/o} + d⃗.
    ///
    /// Book: §1.3, §6.1.
    #[inline]
    pub fn displaced(&self, d: Vector<T>) -> Point<T> {
        Point { r_y_o: self.r_y_o + d }
    }

    /// |r⃗_{y/x}|.
    ///
    /// Book: §1.3, §6.1.
    #[inline]
    pub fn distance(&self, x: &Point<T>) -> T {
        self.position_rel(x).norm()
    }

    /// `true` when r⃗_{y/o} is finite.
    ///
    /// Book: §1.3, §6.1.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.r_y_o.is_finite()
    }
}

impl<T: Scalar> Default for Point<T> {
    fn default() -> Self {
        Self::origin()
    }
}

/// `y - x` is r⃗_{y/x}.
impl<T: Scalar> Sub for Point<T> {
    type Output = Vector<T>;
    #[inline]
    fn sub(self, x: Point<T>) -> Vector<T> {
        self.position_rel(&x)
    }
}
