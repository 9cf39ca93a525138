//! Smooth test paths of frames and vectors, differentiated exactly with num-dual.
#![allow(dead_code)]

use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::num_dual::Dual2_64;
use vectrix::prelude::*;
use vectrix::tensor::Scalar;

/// Elementary passive matrices 𝓞₁, 𝓞₂, 𝓞₃ (2.12.14–16).
pub fn o1<T: Scalar>(a: T) -> Matrix3<T> {
    let (s, c) = a.sin_cos();
    let (z, o) = (T::zero(), T::one());
    Matrix3::new(o, z, z, z, c, s, z, -s, c)
}
pub fn o2<T: Scalar>(a: T) -> Matrix3<T> {
    let (s, c) = a.sin_cos();
    let (z, o) = (T::zero(), T::one());
    Matrix3::new(c, z, -s, z, o, z, s, z, c)
}
pub fn o3<T: Scalar>(a: T) -> Matrix3<T> {
    let (s, c) = a.sin_cos();
    let (z, o) = (T::zero(), T::one());
    Matrix3::new(c, s, z, -s, c, z, z, z, o)
}

/// A quadratic-in-time angle c₀ + c₁t + c₂t² (plus a sine so third derivatives are nonzero).
pub fn angle<T: Scalar>(t: T, c: [f64; 3]) -> T {
    T::lit(c[0]) + T::lit(c[1]) * t + T::lit(c[2]) * t * t + T::lit(0.3) * (t * T::lit(c[1] + 0.7)).sin()
}

/// 𝓞_{B/A}(t) = 𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ), a 3-2-1 path with angle coefficients `c` (Ψ, Θ, Φ).
pub fn o_path<T: Scalar>(t: T, c: &[[f64; 3]; 3]) -> Matrix3<T> {
    o1(angle(t, c[2])) * o2(angle(t, c[1])) * o3(angle(t, c[0]))
}

/// A vector path: components c₀ + c₁t + c₂t² + 0.2 sin((1+c₁)t).
pub fn vec_path<T: Scalar>(t: T, c: &[[f64; 3]; 3]) -> Vector3<T> {
    Vector3::from_fn(|k, _| angle(t, c[k]))
}

/// Value, first and second derivative of a matrix path at `t`.
pub fn mat_jet(f: impl Fn(Dual2_64) -> Matrix3<Dual2_64>, t: f64) -> [Matrix3<f64>; 3] {
    let m = f(Dual2_64::new(t, 1.0, 0.0));
    [m.map(|x| x.re), m.map(|x| x.v1), m.map(|x| x.v2)]
}

/// Value, first and second derivative of a vector path at `t`.
pub fn vec_jet(f: impl Fn(Dual2_64) -> Vector3<Dual2_64>, t: f64) -> [Vector3<f64>; 3] {
    let m = f(Dual2_64::new(t, 1.0, 0.0));
    [m.map(|x| x.re), m.map(|x| x.v1), m.map(|x| x.v2)]
}

pub fn arr(v: Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// The motion of F_B relative to labelled F_A along 𝓞_{B/A}(t), with ω and α from Poisson's
/// equation (4.3.20) and its derivative.
pub fn motion_from_path(
    b: &'static str,
    a: &LabeledFrame,
    o: impl Fn(Dual2_64) -> Matrix3<Dual2_64>,
    t: f64,
) -> FrameMotion {
    let [o_ba, od, odd] = mat_jet(o, t);
    let w = omega_body_from_orientation_rate(&o_ba, &od).unwrap();
    let al = alpha_body_from_orientation_rates(&o_ba, &odd).unwrap();
    FrameMotion::from_body_rates(FrameLabel::new(b), a, &o_ba, arr(w), arr(al)).unwrap()
}

pub use vectrix::kinematics::{alpha_body_from_orientation_rates, omega_body_from_orientation_rate};

/// Max-abs difference of two physical vectors, resolved anywhere (the norm is frame free).
pub fn dist(x: &Vector, y: &Vector) -> f64 {
    (*x - *y).norm()
}

/// Standard coefficient sets used across tests.
pub const C1: [[f64; 3]; 3] = [[0.3, 1.1, -0.4], [-0.2, 0.7, 0.25], [0.5, -0.9, 0.3]];
pub const C2: [[f64; 3]; 3] = [[-0.6, 0.4, 0.35], [0.1, -1.2, 0.2], [1.0, 0.6, -0.5]];
pub const C3: [[f64; 3]; 3] = [[0.9, -0.3, 0.1], [0.4, 0.5, -0.3], [-0.7, 1.3, 0.2]];
