//! The shadow set of modified Rodrigues parameters (not in the book; extends §2.17).

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

use crate::RotationError;
use crate::series::norm3;

/// The shadow MRP p^S = −p/|p|² (the same rotation, from −q): |p^S| ≥ 1 exactly when |p| ≤ 1.
/// Switching to the shadow set when |p| > 1 keeps MRPs bounded. Computed as −p̂/|p| with a
/// scaled norm, so |p|² never underflows or overflows (p = 1e-300 has the shadow 1e300).
///
/// Book: extends §2.17 (tan(θ/4) instead of tan(θ/2)).
///
/// # Errors
/// [`RotationError::Zero`] for p = 0 (the identity has no finite shadow: it is the 360°
/// rotation); [`RotationError::NonFinite`] for a NaN or infinite component;
/// [`RotationError::Overflow`] when |p| < 1/f64::MAX (subnormal), whose shadow is not
/// representable.
#[doc(alias = "shadow_set")]
pub fn mrp_shadow<T: Scalar>(p: &Vector3<T>) -> Result<Vector3<T>, RotationError> {
    let n = norm3(p);
    if !n.re().is_finite() {
        return Err(RotationError::NonFinite { what: "MRP vector" });
    }
    if n == T::zero() {
        return Err(RotationError::Zero { what: "MRP vector" });
    }
    // p^S = −p/|p|² = −p̂ / |p|
    let s = -(p / n) / n;
    if s.iter().all(|x| x.re().is_finite()) {
        Ok(s)
    } else {
        Err(RotationError::Overflow { what: "MRP shadow" })
    }
}
