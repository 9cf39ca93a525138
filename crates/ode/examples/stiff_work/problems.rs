//! The five stiff problems of issue 34 item 4, each with an exact or extended-precision
//! reference and an error measure (the same definitions as scripts/peers/stiff_scipy.py and
//! stiff_mujoco.py, which time the peers on them).
//!
//! Book: §4.11; HW II §IV.1 (Robertson), §IV.10 and the Test Set for IVP Solvers (VDPOL).
#![allow(non_snake_case)]

use std::f64::consts::PI;

use nalgebra::SVector;
pub use vectrix_ode::harness::{robertson, robertson_jacobian, vdpol, vdpol_jacobian};

/// Masses of the damped chain.
pub const N: usize = 6;
/// Chain: k/m [1/s²] and the Rayleigh factor α (C = αK): unit masses, springs 10⁶ N/m,
/// dashpots 10⁵ N s/m. Every mode is overdamped: the slow roots sit near −1/α = −10 /s, the
/// fastest at −αω²_max ≈ −3.8·10⁵ /s (crates/ode/tests/radau5.rs has the milder α = 10⁻²).
const K_OVER_M: f64 = 1e6;
const ALPHA: f64 = 0.1;
/// Chain: initial displacements [m] (largest 2·10⁻³: errors are divided by it).
pub const X0: [f64; N] = [1e-3, -2e-3, 0.5e-3, 1.5e-3, 0.0, -1e-3];
/// Chain: end time [s] (the slowest mode has decayed to e⁻² of its start).
pub const CHAIN_T: f64 = 0.2;

fn lap(v: &[f64], i: usize) -> f64 {
    let l = if i > 0 { v[i - 1] } else { 0.0 };
    let r = if i + 1 < N { v[i + 1] } else { 0.0 };
    2.0 * v[i] - l - r
}

/// The damped spring chain: ẍ = −(k/m) L x − α(k/m) L ẋ, L = tridiag(−1, 2, −1) (both ends to walls).
pub fn chain(_: f64, y: &SVector<f64, 12>) -> SVector<f64, 12> {
    let mut d = SVector::<f64, 12>::zeros();
    let (x, v) = (&y.as_slice()[..N], &y.as_slice()[N..]);
    for i in 0..N {
        d[i] = v[i];
        d[N + i] = -K_OVER_M * lap(x, i) - ALPHA * K_OVER_M * lap(v, i);
    }
    d
}

/// ∂f/∂y of [`chain`], row-major (constant).
pub fn chain_jacobian(_: f64, _: &SVector<f64, 12>, j: &mut [f64]) {
    j.fill(0.0);
    let n = 2 * N;
    for i in 0..N {
        j[i * n + N + i] = 1.0;
        for (c, w) in [(i as isize - 1, -1.0), (i as isize, 2.0), (i as isize + 1, -1.0)] {
            if (0..N as isize).contains(&c) {
                let c = c as usize;
                j[(N + i) * n + c] = -K_OVER_M * w;
                j[(N + i) * n + N + c] = -ALPHA * K_OVER_M * w;
            }
        }
    }
}

/// The chain's modal closed form x(t) from x(0) = [`X0`], ẋ(0) = 0: L's eigenvectors
/// φⱼᵢ = sin(ijπ/(N+1)) decouple it into q̈ + αω²q̇ + ω²q = 0, ω² = (k/m)·4 sin²(jπ/(2(N+1))).
pub fn chain_exact(t: f64) -> [f64; N] {
    let mut x = [0.0; N];
    let norm = 2.0 / (N as f64 + 1.0); // Σᵢ φⱼᵢ² = (N+1)/2
    for j in 1..=N {
        let phi: Vec<f64> = (1..=N).map(|i| (PI * (i * j) as f64 / (N as f64 + 1.0)).sin()).collect();
        let q0: f64 = norm * phi.iter().zip(X0).map(|(p, x)| p * x).sum::<f64>();
        let w2 = K_OVER_M * 4.0 * (PI * j as f64 / (2.0 * (N as f64 + 1.0))).sin().powi(2);
        let zeta_w = 0.5 * ALPHA * w2;
        let disc = w2 - zeta_w * zeta_w;
        // q = q0 e^{−ζωt}(cos ωd t + (ζω/ωd) sin ωd t) (underdamped) or the overdamped form
        let q = if disc > 0.0 {
            let wd = disc.sqrt();
            q0 * (-zeta_w * t).exp() * ((wd * t).cos() + zeta_w / wd * (wd * t).sin())
        } else {
            // the fast root without cancellation, the slow one from the product r₁r₂ = ω²
            let r2 = -zeta_w - (-disc).sqrt();
            let r1 = w2 / r2;
            q0 * (r2 * (r1 * t).exp() - r1 * (r2 * t).exp()) / (r2 - r1)
        };
        for i in 0..N {
            x[i] += q * phi[i];
        }
    }
    x
}

/// Spring pendulum: mass [kg], gravity [m/s²], rest length [m], stretch mg/(k l₀), θ₀ [rad], end time [s].
pub const PEND_M: f64 = 1.0;
pub const PEND_G: f64 = 9.81;
pub const PEND_L0: f64 = 1.0;
pub const PEND_STRETCH: f64 = 1e-4;
pub const PEND_THETA0: f64 = 0.1;
pub const PEND_T: f64 = 2.0;
const PEND_K: f64 = PEND_M * PEND_G / (PEND_STRETCH * PEND_L0);

/// A point mass on a stiff spring in gravity, Cartesian (x, y, ẋ, ẏ), y up:
/// r̈ = −(k/m)(1 − l₀/|r|) r − g ŷ; k/m = 9.81·10⁴ /s² against g/l₀ = 9.81 /s².
pub fn pendulum(_: f64, s: &SVector<f64, 4>) -> SVector<f64, 4> {
    let r = (s[0] * s[0] + s[1] * s[1]).sqrt();
    let fr = -PEND_K / PEND_M * (1.0 - PEND_L0 / r);
    SVector::<f64, 4>::new(s[2], s[3], fr * s[0], fr * s[1] - PEND_G)
}

/// ∂f/∂y of [`pendulum`], row-major: ∂(fr x)/∂x = fr − (k/m) l₀ x²/r³, ∂(fr x)/∂y = −(k/m) l₀ x y/r³.
pub fn pendulum_jacobian(_: f64, s: &SVector<f64, 4>, j: &mut [f64]) {
    let (x, y) = (s[0], s[1]);
    let r = (x * x + y * y).sqrt();
    let w2 = PEND_K / PEND_M;
    let fr = -w2 * (1.0 - PEND_L0 / r);
    let c = w2 * PEND_L0 / (r * r * r);
    j.copy_from_slice(&[
        0.0,
        0.0,
        1.0,
        0.0, //
        0.0,
        0.0,
        0.0,
        1.0, //
        fr - c * x * x,
        -c * x * y,
        0.0,
        0.0, //
        -c * x * y,
        fr - c * y * y,
        0.0,
        0.0,
    ]);
}

/// Start at rest at θ₀ with the spring balancing gravity's radial part: r₀ = l₀ + mg cos θ₀/k.
pub fn pendulum_y0() -> SVector<f64, 4> {
    let r0 = PEND_L0 + PEND_M * PEND_G * PEND_THETA0.cos() / PEND_K;
    SVector::<f64, 4>::new(r0 * PEND_THETA0.sin(), -r0 * PEND_THETA0.cos(), 0.0, 0.0)
}

/// Stiff damper joint: rotor inertia [kg m²], torsional spring [N m/rad], damper [N m s/rad],
/// θ(0) [rad], θ̇(0) [rad/s], end time [s].
pub const DAMP_I: f64 = 1e-2;
pub const DAMP_K: f64 = 10.0;
pub const DAMP_C: f64 = 100.0;
pub const DAMP_THETA0: f64 = 1.0;
pub const DAMP_OMEGA0: f64 = 100.0;
pub const DAMP_T: f64 = 10.0;

/// A hinge with a stiff linear damper: I θ̈ + c θ̇ + k θ = 0 (eigenvalues ≈ −0.1 and −10⁴ /s).
pub fn damper(_: f64, s: &SVector<f64, 2>) -> SVector<f64, 2> {
    SVector::<f64, 2>::new(s[1], -(DAMP_K * s[0] + DAMP_C * s[1]) / DAMP_I)
}

/// ∂f/∂y of [`damper`], row-major (constant).
pub fn damper_jacobian(_: f64, _: &SVector<f64, 2>, j: &mut [f64]) {
    j.copy_from_slice(&[0.0, 1.0, -DAMP_K / DAMP_I, -DAMP_C / DAMP_I]);
}

/// The closed form θ(t) = A e^{λ₁t} + B e^{λ₂t}, λ₁λ₂ = k/I, λ₁ + λ₂ = −c/I,
/// A + B = θ₀, λ₁A + λ₂B = θ̇₀ (overdamped: c² > 4Ik).
pub fn damper_exact(t: f64) -> f64 {
    // the fast root without cancellation, the slow one from the product
    let l2 = (-DAMP_C - (DAMP_C * DAMP_C - 4.0 * DAMP_I * DAMP_K).sqrt()) / (2.0 * DAMP_I);
    let l1 = DAMP_K / (DAMP_I * l2);
    let b = (DAMP_OMEGA0 - l1 * DAMP_THETA0) / (l2 - l1);
    let a = DAMP_THETA0 - b;
    a * (l1 * t).exp() + b * (l2 * t).exp()
}

/// The Test Set's VDPOL end state at t = 2 (ε = 10⁻⁶).
pub const VDPOL_END: [f64; 2] = [1.706167732170483, -0.8928097010247975];

/// Largest relative component error (Robertson, VDPOL: every component is far from 0).
pub fn rel_err(got: &[f64], want: &[f64]) -> f64 {
    got.iter().zip(want).fold(0.0, |m: f64, (g, w)| {
        let e = ((g - w) / w).abs();
        if e.is_nan() || m.is_nan() { f64::NAN } else { m.max(e) }
    })
}

/// Largest absolute component error over `scale`.
pub fn abs_err(got: &[f64], want: &[f64], scale: f64) -> f64 {
    got.iter().zip(want).fold(0.0, |m: f64, (g, w)| {
        let e = (g - w).abs() / scale;
        if e.is_nan() || m.is_nan() { f64::NAN } else { m.max(e) }
    })
}
