//! The transport theorems (book §4.4–4.5, P4.20.12) on plain physical vectors and dyads.
//!
//! Here ω⃗ = ω⃗_{B/A}, α⃗ = α⃗_{B/A}, and derivatives carry the frame in their names. The
//! tagged, frame-checked forms are in [`crate::VectorJet`] and [`crate::DyadicJet`].

use vectrix_tensor::{Dyadic, Scalar, Vector};

/// The transport theorem ("ABBA"): x⃗^{A•} = x⃗^{B•} + ω⃗_{B/A} × x⃗.
///
/// Book: Fact 4.4.1, (4.4.1).
pub fn transport<T: Scalar>(x_dot_b: &Vector<T>, omega_b_a: &Vector<T>, x: &Vector<T>) -> Vector<T> {
    *x_dot_b + omega_b_a.cross(x)
}

/// The transport theorem for dyads: M⃗^{A•} = M⃗^{B•} + Ω⃗_{B/A} M⃗ − M⃗ Ω⃗_{B/A}.
///
/// Book: (4.4.12).
pub fn transport_dyadic<T: Scalar>(m_dot_b: &Dyadic<T>, omega_b_a: &Vector<T>, m: &Dyadic<T>) -> Dyadic<T> {
    let w = omega_b_a.cross_dyad();
    *m_dot_b + w * *m - *m * w
}

/// Double transport: x⃗^{A••} = x⃗^{B••} + 2ω⃗×x⃗^{B•} (Coriolis) + α⃗×x⃗ (Euler) + ω⃗×(ω⃗×x⃗)
/// (centripetal).
///
/// Book: (4.5.1).
pub fn double_transport<T: Scalar>(
    x: &Vector<T>,
    x_dot_b: &Vector<T>,
    x_ddot_b: &Vector<T>,
    omega_b_a: &Vector<T>,
    alpha_b_a: &Vector<T>,
) -> Vector<T> {
    let w = omega_b_a;
    *x_ddot_b + w.cross(x_dot_b) * T::lit(2.0) + alpha_b_a.cross(x) + w.cross(&w.cross(x))
}

/// Triple transport (P4.20.12, corrected; the printed form is garbled, this one is derived by
/// differentiating (4.5.1) with (4.4.1) and checked numerically):
///
/// x⃗^{A•••} = x⃗^{B•••} + 3ω⃗×x⃗^{B••} + 3α⃗×x⃗^{B•} + 3ω⃗×(ω⃗×x⃗^{B•}) + α⃗^{B•}×x⃗
///           + α⃗×(ω⃗×x⃗) + 2ω⃗×(α⃗×x⃗) + ω⃗×(ω⃗×(ω⃗×x⃗)),
///
/// where α⃗^{B•} = α⃗^{B•}_{B/A} is the B-frame derivative of α⃗_{B/A}.
///
/// Book: P4.20.12 (erratum: notes ch4-5 §2).
#[allow(clippy::too_many_arguments)]
pub fn triple_transport<T: Scalar>(
    x: &Vector<T>,
    x_dot_b: &Vector<T>,
    x_ddot_b: &Vector<T>,
    x_dddot_b: &Vector<T>,
    omega_b_a: &Vector<T>,
    alpha_b_a: &Vector<T>,
    alpha_dot_b: &Vector<T>,
) -> Vector<T> {
    let (w, al) = (omega_b_a, alpha_b_a);
    let three = T::lit(3.0);
    *x_dddot_b
        + w.cross(x_ddot_b) * three
        + al.cross(x_dot_b) * three
        + w.cross(&w.cross(x_dot_b)) * three
        + alpha_dot_b.cross(x)
        + al.cross(&w.cross(x))
        + w.cross(&al.cross(x)) * T::lit(2.0)
        + w.cross(&w.cross(&w.cross(x)))
}
