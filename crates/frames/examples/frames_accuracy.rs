//! Accuracy figures for docs/accuracy.md (frames and kernel geometry):
//! `cargo run --release -p vectrix-frames --example frames_accuracy`.
//!
//! 1. Angle between vectors (2.1.4): atan2(|x×y|, x·y) against the book's cos⁻¹(x̂·ŷ).
//! 2. Contravariant components in a nonstandard frame (2.23.18): LU solve against G⁻¹x|_[A].
//! 3. Gradient of |r|⁻³ (2.24.11, corrected): dual numbers and central differences against the
//!    closed form.

use nalgebra::Vector3;
use num_dual::Dual64;
use vectrix_frames::{
    Frame, NonstandardFrame, Resolve, gradient, gradient_central_difference, gradient_of_inverse_power,
};
use vectrix_tensor::Vector;

fn main() {
    let a = Frame::new();

    println!("| true angle θ | atan2 (vectrix) rel. error | cos⁻¹ (book 2.1.4) rel. error |");
    println!("|---|---|---|");
    for th in [1e-4, 1e-8, 1e-12, std::f64::consts::PI - 1e-8] {
        let x = a.vector([1.0, 0.0, 0.0]);
        let y = a.vector([th.cos(), th.sin(), 0.0]);
        let stable = x.angle(&y);
        let naive = (x.dot(&y) / (x.norm() * y.norm())).clamp(-1.0, 1.0).acos();
        let rel = |v: f64| ((v - th) / th).abs();
        println!("| {th:.3e} | {:.1e} | {:.1e} |", rel(stable), rel(naive));
    }

    println!();
    println!("| κ(A) | residual ‖Σx_i a⃗_i − x⃗‖, LU | residual, G⁻¹x\\|_[A] |");
    println!("|---|---|---|");
    let x = a.vector([0.3, -1.2, 2.0]);
    for e in [1e-2, 1e-4, 1e-6, 1e-7] {
        let fa =
            NonstandardFrame::from_axes(&a.i(), &a.vector([1.0, e, 0.0]), &a.vector([0.0, 0.5, 1.0]), 1e12)
                .expect("independent axes");
        let lu = fa.contravariant(&x);
        let via_g = fa.gram().try_inverse().expect("invertible") * fa.covariant(&x);
        let res = |c: Vector3<f64>| (fa.vector([c.x, c.y, c.z]) - x).norm();
        println!("| {:.1e} | {:.1e} | {:.1e} |", fa.condition_number(), res(lu), res(via_g));
    }

    println!();
    println!("| method | max rel. error of ∂⃗\\|r\\|⁻³ at r = (0.3, −1.2, 2) |");
    println!("|---|---|");
    let r = a.vector([0.3, -1.2, 2.0]);
    let want = gradient_of_inverse_power(&r, 3.0).expect("r ≠ 0").resolve(&a);
    let err = |g: nalgebra::RowVector3<f64>| ((g - want).amax()) / want.amax();
    let cube = |x: &Vector<Dual64>| {
        let n = x.norm();
        Dual64::from(1.0) / (n * n * n)
    };
    let dual = gradient(cube, &r).expect("finite").resolve(&a);
    println!("| dual numbers (exact) | {:.1e} |", err(dual));
    for h in [1e-3, 1e-5, 1e-7] {
        let fd = gradient_central_difference(|x| x.norm().powi(-3), &r, h).expect("h > 0").resolve(&a);
        println!("| central difference h = {h:.0e} | {:.1e} |", err(fd));
    }
}
