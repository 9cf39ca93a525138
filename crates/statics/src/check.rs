//! Input checks shared by the force elements (springs, dampers, gravitation, dipoles): a
//! coefficient ≥ 0, a finite vector, the unit vector of a separation, and a result that did not
//! overflow. Each failure is a typed [`StaticsError`] naming what was wrong.
//!
//! Book: §6.6–6.7 (force elements), §6.12 (gravitation).

use vectrix_tensor::{Scalar, Vector};

use crate::StaticsError;

/// `x` when it is finite and ≥ 0 (a stiffness, damping coefficient or inertance), else
/// [`StaticsError::OutOfRange`] naming `what` and the `valid` range.
pub(crate) fn check_coeff<T: Scalar>(
    x: T,
    what: &'static str,
    valid: &'static str,
) -> Result<T, StaticsError> {
    let v = x.re();
    if !v.is_finite() || v < 0.0 {
        return Err(StaticsError::OutOfRange { what, value: v, valid });
    }
    Ok(x)
}

/// `Ok` when every component of `x` is finite, else [`StaticsError::NonFinite`] naming `what`.
pub(crate) fn check_vec<T: Scalar>(x: &Vector<T>, what: &'static str) -> Result<(), StaticsError> {
    if x.is_finite() { Ok(()) } else { Err(StaticsError::NonFinite { what }) }
}

/// The unit vector r̂ of a separation, or [`StaticsError::CoincidentPoints`].
pub(crate) fn unit_sep<T: Scalar>(r: &Vector<T>, what: &'static str) -> Result<(Vector<T>, T), StaticsError> {
    check_vec(r, what)?;
    let n = r.norm();
    // the comfortable range as `Vector::unit` has it, without its second norm (same bits)
    if n.re() > 1e-150 && n.re() < 1e150 {
        return Ok((*r / n, n));
    }
    match r.unit() {
        Some(u) => Ok((u, n)),
        None => Err(StaticsError::CoincidentPoints { what, distance: n.re() }),
    }
}

/// `Ok(v)` when every component is finite, else [`StaticsError::Overflow`]: finite inputs whose
/// true result exceeds the largest finite number (|r⃗| = 1e-200 in an inverse-square law).
pub(crate) fn finite_or_overflow<T: Scalar>(
    v: Vector<T>,
    what: &'static str,
) -> Result<Vector<T>, StaticsError> {
    if v.is_finite() { Ok(v) } else { Err(StaticsError::Overflow { what }) }
}
