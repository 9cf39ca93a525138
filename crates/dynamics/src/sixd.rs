//! The 6D (spatial) form of the Newton–Euler equations (book §7.10).
//!
//! 𝒥_{B/z} 𝒜 + 𝒱^× 𝒥_{B/z} 𝒱 = ℱ_{B/z} (7.10.9), with the twist 𝒱 = [v⃗_{z/w/A}; ω⃗_{B/A}]
//! (velocity first, the book's ordering), 𝒜 = [B•v⃗_z; α⃗] where B•v⃗_z = a⃗_z − ω⃗ × v⃗_z is the
//! body-frame derivative of v⃗_z (transport theorem), the wrench ℱ = [f⃗_B; M⃗_{B/z}] and
//! 𝒱^× = [[ω⃗^×, 0], [v⃗^×, ω⃗^×]] (7.10.7), the force cross product in this ordering.

use nalgebra::{Matrix3, Matrix6, Vector3};
use vectrix_kinematics::transport;
use vectrix_statics::SpatialInertia;
use vectrix_tensor::{Scalar, Vector};

/// The wrench ℱ_{B/z} = [f⃗_B; M⃗_{B/z}] that produces the motion (v⃗_z, ω⃗, a⃗_z, α⃗) of a rigid
/// body with spatial inertia 𝒥_{B/z} about the body-fixed point z (7.10.9):
/// ℱ = 𝒥𝒜 + 𝒱^×𝒥𝒱, 𝒜 = [a⃗_z − ω⃗×v⃗_z; α⃗].
///
/// Book: §7.10, (7.10.7)–(7.10.9); it reproduces (7.4.17) and (7.8.7).
pub fn newton_euler_6d<T: Scalar>(
    inertia: &SpatialInertia<T>,
    v_z: &Vector<T>,
    omega: &Vector<T>,
    a_z: &Vector<T>,
    alpha: &Vector<T>,
) -> (Vector<T>, Vector<T>) {
    // 𝒜 = [B•v_z; α], B•v_z = a_z − ω × v_z (Fact 4.4.1 solved for the B-derivative)
    let v_dot_b = transport(a_z, &(-*omega), v_z);
    let (p_acc, h_acc) = inertia.apply(&v_dot_b, alpha);
    // 𝒥𝒱 = [p; H_{/z}], 𝒱^×[p; H] = [ω×p; v×p + ω×H]
    let (p, h) = inertia.apply(v_z, omega);
    (p_acc + omega.cross(&p), h_acc + v_z.cross(&p) + omega.cross(&h))
}

/// 𝒱^× resolved: [[ω^×, 0], [v^×, ω^×]] (7.10.7), for the twist components v|, ω| in one frame.
///
/// Book: (7.10.7), (7.10.11).
pub fn twist_cross_matrix<T: Scalar>(v: &Vector3<T>, omega: &Vector3<T>) -> Matrix6<T> {
    let mut out = Matrix6::zeros();
    let w: Matrix3<T> = omega.cross_matrix();
    out.fixed_view_mut::<3, 3>(0, 0).copy_from(&w);
    out.fixed_view_mut::<3, 3>(3, 0).copy_from(&v.cross_matrix());
    out.fixed_view_mut::<3, 3>(3, 3).copy_from(&w);
    out
}
