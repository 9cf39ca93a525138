//! Gradients as covectors (book §2.24).
//!
//! The gradient of a scalar field f at r⃗ is a **row**, a covector: resolved in A,
//! ∂⃗f|_A = ∂f_A(r_A) ∈ ℝ^{1×3} (2.24.1), with f_A(r_A) = f(F_A r_A). The chain rule
//! ∂f_A(r_A) = ∂f_B(r_B) 𝓞_{B/A} (2.24.6) makes the physical gradient ∂⃗f = ∂f_A 𝓕_A frame
//! independent (Fact 2.24.1).
//!
//! [`gradient`] differentiates a frame-free field exactly with dual numbers (three forward
//! passes of [`num_dual::Dual64`]); [`gradient_central_difference`] is the finite-difference
//! oracle; the closed forms of (2.24.10–11) are [`gradient_of_norm`] and
//! [`gradient_of_inverse_power`].

use nalgebra::Vector3;
use num_dual::Dual64;
use vectrix_tensor::frames_access::Hidden;
use vectrix_tensor::{Covector, Vector};

use crate::FrameError;

/// Checks that r⃗ is finite.
fn check_finite(r: &Vector<f64>) -> Result<(), FrameError> {
    if r.is_finite() { Ok(()) } else { Err(FrameError::NonFinite { what: "gradient point r⃗" }) }
}

/// The physical gradient ∂⃗f(r⃗) of a frame-free scalar field, exact to rounding: f is evaluated
/// on dual numbers, once per direction of an orthonormal basis e⃗_k, and
/// ∂⃗f = Σ_k (∂f/∂e_k) e⃗_k′ (2.24.7). Write `f` with vectrix operations on `Vector<Dual64>`.
///
/// Book: §2.24, (2.24.1), (2.24.7), Fact 2.24.1.
///
/// # Errors
/// [`FrameError::NonFinite`] when r⃗ or a derivative is NaN or ∞ (f not differentiable there,
/// e.g. |r⃗| at r⃗ = 0⃗).
pub fn gradient(f: impl Fn(&Vector<Dual64>) -> Dual64, r: &Vector<f64>) -> Result<Covector<f64>, FrameError> {
    check_finite(r)?;
    let base = r.hidden().map(Dual64::from_re);
    let mut g = Vector3::zeros();
    for k in 0..3 {
        // Seed the k-th direction: r⃗ + ε e⃗_k.
        let mut x = base;
        x[k].eps = 1.0;
        g[k] = f(&Vector::from_hidden(x)).eps;
    }
    if !g.iter().all(|d: &f64| d.is_finite()) {
        return Err(FrameError::NonFinite { what: "gradient (f is not differentiable at r⃗)" });
    }
    Ok(Covector::from_hidden(g))
}

/// Central-difference gradient [f(r⃗ + h e⃗_k) − f(r⃗ − h e⃗_k)]/(2h) along an orthonormal basis:
/// error O(h²) + O(ε/h); h ≈ ε^{1/3}|r⃗| balances them. An oracle for [`gradient`].
///
/// Book: §2.24, (2.24.1).
///
/// # Errors
/// [`FrameError::NonFinite`] for non-finite r⃗ or h, or h ≤ 0.
pub fn gradient_central_difference(
    f: impl Fn(&Vector<f64>) -> f64,
    r: &Vector<f64>,
    h: f64,
) -> Result<Covector<f64>, FrameError> {
    check_finite(r)?;
    if !(h.is_finite() && h > 0.0) {
        return Err(FrameError::NonFinite { what: "step h (must be finite and > 0)" });
    }
    let mut g = Vector3::zeros();
    for k in 0..3 {
        let mut e = Vector3::zeros();
        e[k] = h;
        let e = Vector::from_hidden(e);
        g[k] = (f(&(*r + e)) - f(&(*r - e))) / (2.0 * h);
    }
    if !g.iter().all(|d: &f64| d.is_finite()) {
        // f is not finite at r⃗ ± h e⃗_k, or the difference quotient overflowed (h tiny, f huge).
        return Err(FrameError::NonFinite {
            what: "central-difference gradient (f or its differences at r⃗ ± h)",
        });
    }
    Ok(Covector::from_hidden(g))
}

/// ∂⃗|r⃗| = r̂′ (2.24.10). `None` at r⃗ = 0⃗, where |r⃗| is not differentiable.
///
/// Book: (2.24.10).
pub fn gradient_of_norm(r: &Vector<f64>) -> Option<Covector<f64>> {
    r.unit().map(|u| u.coform())
}

/// ∂⃗|r⃗|^{−n} = −n |r⃗|^{−(n+2)} r⃗′ (2.24.11, sign corrected: the book mixes r⃗_{y/z} and
/// r⃗_{z/y}; checked against finite differences). `None` at r⃗ = 0⃗.
///
/// Book: (2.24.11), corrected.
pub fn gradient_of_inverse_power(r: &Vector<f64>, n: f64) -> Option<Covector<f64>> {
    let d = r.norm();
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    // −n |r|^{−(n+2)} r′ = −n |r|^{−n} r̂′/|r|, written to avoid overflow of |r|^{n+2}.
    let u = r.unit()?;
    let g = u.coform() * (-n * d.powf(-n) / d);
    // `None` also for a non-finite n or a gradient beyond f64::MAX (|r⃗| tiny, n large).
    g.is_finite().then_some(g)
}
