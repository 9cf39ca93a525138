//! The tour: what `cargo run --release` prints until the scene simulator exists.
//!
//! Numbers are printed rounded for reading ([`Rounded`]: six significant digits, round-off
//! below 64ε of the largest entry as 0), so a quarter turn shows 0 and ±1, not
//! 6.123233995736766e-17.

use std::io::Write;

use vectrix_frames::prelude::*;
use vectrix_plot::Rounded;
use vectrix_tensor::prelude::*;

/// Builds frames, resolves, rotates and contracts, and prints the results to `out`.
pub fn run(out: &mut impl Write) -> Result<(), Box<dyn std::error::Error>> {
    let a = Frame::new();
    writeln!(out, "vectrix tour: frame-free objects, numbers only through frames")?;
    // A frame B rotated by 90° about k̂_A.
    let r = Rotor::from_axis_angle(&a.k(), std::f64::consts::FRAC_PI_2).ok_or("zero axis")?;
    let b = a.rotated_by_rotor(&r);
    let x = a.vector([1.0, 0.0, 0.0]);
    writeln!(out, "x|_A = {}", Rounded(&x.resolve(&a)))?;
    writeln!(out, "x|_B = {}  (x|_B = 𝓞_{{B/A}} x|_A)", Rounded(&x.resolve(&b)))?;
    writeln!(out, "𝓞_{{B/A}} =\n{}", Rounded(&b.orientation_rel(&a)))?;
    let y = r.rotate(&x);
    writeln!(out, "R x R̄ |_A = {}", Rounded(&y.resolve(&a)))?;
    let m = x.outer(&y);
    writeln!(out, "(x y′)|_A =\n{}", Rounded(&m.resolve(&a)))?;
    writeln!(out, "angle(x, y) = {} rad", Rounded(x.angle(&y)))?;
    Ok(())
}
