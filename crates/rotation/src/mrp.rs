//! The shadow set of modified Rodrigues parameters (not in the book; extends §2.17).

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

/// The shadow MRP p^S = −p/|p|² (the same rotation, from −q): |p^S| ≥ 1 exactly when |p| ≤ 1.
/// Switching to the shadow set when |p| > 1 keeps MRPs bounded. `None` for p = 0 (the identity
/// has no finite shadow: it is the 360° rotation).
///
/// Book: extends §2.17 (tan(θ/4) instead of tan(θ/2)).
#[doc(alias = "shadow_set")]
pub fn mrp_shadow<T: Scalar>(p: &Vector3<T>) -> Option<Vector3<T>> {
    let p2 = p.norm_squared();
    (p2 != T::zero() && p2.re().is_finite()).then(|| -p / p2)
}
