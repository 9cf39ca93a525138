//! Chasles-based velocity (book §4.17) and rolling with and without slip (book §4.18).

use vectrix_tensor::{Scalar, Vector};

/// Velocity from Chasles's theorem: for r⃗_{y′/z} = R⃗_n̂(θ) r⃗_{y/z} + α n̂ (a rotation about n̂
/// followed by a slide α along n̂),
/// v⃗_{y′/z/A} = ω⃗ × r⃗_{y′/z} + α n̂ × ω⃗ + ξ⃗ with ξ⃗ = α̇ n̂ + α n̂^{A•} (4.17.1–7).
///
/// Here `slide` = α, `slide_rate` = α̇, `n_dot_a` = n̂^{A•}, and `omega` the angular velocity of
/// the rotation R⃗_n̂(θ) (e.g. from (4.7.18)).
///
/// Book: §4.17, (4.17.1–7).
pub fn chasles_velocity<T: Scalar>(
    omega: &Vector<T>,
    r_yp_z: &Vector<T>,
    slide: T,
    slide_rate: T,
    n: &Vector<T>,
    n_dot_a: &Vector<T>,
) -> Vector<T> {
    // ξ = α̇ n + α n^{A•}
    let xi = *n * slide_rate + *n_dot_a * slide;
    omega.cross(r_yp_z) + n.cross(omega) * slide + xi
}

/// Velocity of the contact point x of a body whose reference point c moves with v⃗_c and whose
/// angular velocity is ω⃗: v⃗_x = v⃗_c + ω⃗ × r⃗_{x/c} (4.4.9).
///
/// Book: (4.4.9), §4.18.
pub fn contact_point_velocity<T: Scalar>(v_c: &Vector<T>, omega: &Vector<T>, r_x_c: &Vector<T>) -> Vector<T> {
    *v_c + omega.cross(r_x_c)
}

/// Slip velocity v⃗_{x₁/x₂} = v⃗_{x₁/w/A} − v⃗_{x₂/w/A} of colocated contact points x₁ ∈ B₁,
/// x₂ ∈ B₂. Since r⃗_{x₁/x₂} = 0⃗, it is the same for every frame A (Fact 4.18.1).
///
/// Book: Fact 4.18.1, Def 4.18.2.
pub fn slip_velocity<T: Scalar>(v_x1_w_a: &Vector<T>, v_x2_w_a: &Vector<T>) -> Vector<T> {
    *v_x1_w_a - *v_x2_w_a
}

/// `true` when the bodies roll without slipping: |v⃗_{x₁/x₂}| ≤ `tol` (a speed, in the units of
/// the inputs). Then v⃗_{x₁/w/A} = v⃗_{x₂/w/A} (Fact 4.18.3).
///
/// Book: Def 4.18.2, Fact 4.18.3.
pub fn rolls_without_slip<T: Scalar>(v_x1_w_a: &Vector<T>, v_x2_w_a: &Vector<T>, tol: f64) -> bool {
    slip_velocity(v_x1_w_a, v_x2_w_a).norm().re() <= tol
}

/// The velocity of a rolling body's reference point c that makes the contact point x roll
/// without slip on a surface point moving with v⃗_s: v⃗_c = v⃗_s − ω⃗ × r⃗_{x/c}
/// (for a disk on a fixed plane, |v⃗_c| = rω).
///
/// Book: Def 4.18.2, Ex 4.18.4.
pub fn no_slip_velocity<T: Scalar>(omega: &Vector<T>, r_x_c: &Vector<T>, v_surface: &Vector<T>) -> Vector<T> {
    *v_surface - omega.cross(r_x_c)
}
