//! §2.1–2.10, 2.23–2.24: vectors, angles, frames, resolution, physical matrices.

use vectrix::prelude::*;

use crate::support::*;

/// Book §2.1: θ = 0 when either vector is zero (L497).
#[test]
fn sec_2_1_angle_with_zero_vector_is_zero() {
    let a = Frame::new();
    let x = a.vector([1.0, 2.0, 3.0]);
    assert_eq!(x.angle(&Vector::zero()), 0.0);
    assert_close(a.i().angle(&a.j()), std::f64::consts::FRAC_PI_2, EPS);
}
