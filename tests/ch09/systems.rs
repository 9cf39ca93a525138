//! Systems shared by the chapter-9 tests, each written as the book writes its energies.
#![allow(dead_code)]

use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

/// Ex 9.10.1: mass–spring–dashpot, T = ½mq̇², U = ½kq², R = ½cq̇², Q = f.
pub struct Oscillator {
    pub m: f64,
    pub k: f64,
    pub c: f64,
    pub f: f64,
}

impl Lagrangian for Oscillator {
    fn dof(&self) -> usize {
        1
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5 * self.m) * qd[0] * qd[0]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(0.5 * self.k) * q[0] * q[0]
    }
    fn rayleigh<T: Scalar>(&self, _q: &[T], qd: &[T]) -> T {
        T::lit(0.5 * self.c) * qd[0] * qd[0]
    }
    fn generalized_force(&self, _q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        out[0] += self.f;
    }
}

/// Ex 9.10.3: cart m1 on a spring k1 carrying an eccentric pendulum m2, l with a torsional
/// spring k2: T = ½(m1+m2)q̇1² + m2 l q̇1q̇2 cos q2 + ½m2l²q̇2², U = ½k1q1² + ½k2q2².
pub struct CartPendulum {
    pub m1: f64,
    pub m2: f64,
    pub l: f64,
    pub k1: f64,
    pub k2: f64,
}

pub const CART: CartPendulum = CartPendulum { m1: 2.0, m2: 1.0, l: 0.5, k1: 10.0, k2: 3.0 };

impl Lagrangian for CartPendulum {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let (m1, m2, l) = (T::lit(self.m1), T::lit(self.m2), T::lit(self.l));
        T::lit(0.5) * (m1 + m2) * qd[0] * qd[0]
            + m2 * l * qd[0] * qd[1] * q[1].cos()
            + T::lit(0.5) * m2 * l * l * qd[1] * qd[1]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(0.5 * self.k1) * q[0] * q[0] + T::lit(0.5 * self.k2) * q[1] * q[1]
    }
}

/// The same system as a kinematic map: cart at (q1, 0, 0), bob at (q1 + l sin q2, −l cos q2, 0).
impl KinematicMap for CartPendulum {
    fn dof(&self) -> usize {
        2
    }
    fn masses(&self) -> MapMasses {
        MapMasses { particles: vec![self.m1, self.m2], bodies: vec![] }
    }
    fn particles<T: Scalar>(&self, q: &[T], _t: T) -> Vec<Vector<T>> {
        let a = Frame::<T>::identity();
        let l = T::lit(self.l);
        vec![
            a.vector([q[0], T::zero(), T::zero()]),
            a.vector([q[0] + l * q[1].sin(), -l * q[1].cos(), T::zero()]),
        ]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(0.5 * self.k1) * q[0] * q[0] + T::lit(0.5 * self.k2) * q[1] * q[1]
    }
}

/// The 3-2-1 rates matrix S(Φ, Θ) of (9.3.23): ω|_B = S [Φ̇; Θ̇; Ψ̇].
pub fn s_321<T: Scalar>(phi: T, theta: T) -> Matrix3<T> {
    let (sf, cf, st, ct) = (phi.sin(), phi.cos(), theta.sin(), theta.cos());
    let (z, o) = (T::zero(), T::one());
    Matrix3::new(o, z, -st, z, cf, ct * sf, z, -sf, ct * cf)
}

/// A rigid body in 3-2-1 Euler angles q = (Φ, Θ, Ψ) under a body-fixed moment M|_B:
/// T = ½ωᵀJω with ω = S(Φ, Θ)q̇ (9.3.17, 9.3.23), Q = SᵀM (9.7.29).
pub struct EulerBody {
    pub j: Matrix3<f64>,
    pub m_b: Vector3<f64>,
}

impl Lagrangian for EulerBody {
    fn dof(&self) -> usize {
        3
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let w = s_321(q[0], q[1]) * Vector3::new(qd[0], qd[1], qd[2]);
        let j = self.j.map(T::lit);
        T::lit(0.5) * w.dot(&(j * w))
    }
    fn generalized_force(&self, q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        let qf = s_321(q[0], q[1]).transpose() * self.m_b;
        for k in 0..3 {
            out[k] += qf[k];
        }
    }
}

/// ω and ω̇ = S q̈ + Ṡ q̇ of an [`EulerBody`] (Ṡ by the chain rule, in closed form).
pub fn omega_and_rate(q: &[f64], qd: &[f64], qdd: &[f64]) -> (Vector3<f64>, Vector3<f64>) {
    let s = s_321(q[0], q[1]);
    let (sf, cf, st, ct) = (q[0].sin(), q[0].cos(), q[1].sin(), q[1].cos());
    let (pd, td) = (qd[0], qd[1]);
    // Ṡ = ∂S/∂Φ Φ̇ + ∂S/∂Θ Θ̇
    let s_dot = Matrix3::new(
        0.0,
        0.0,
        -ct * td,
        0.0,
        -sf * pd,
        -st * td * sf + ct * cf * pd,
        0.0,
        -cf * pd,
        -st * td * cf - ct * sf * pd,
    );
    let qd = Vector3::from_column_slice(qd);
    (s * qd, s * Vector3::from_column_slice(qdd) + s_dot * qd)
}

/// Ex 7.15.2 / §9.3 physical pendulum as a kinematic map with one rigid body: pivot at w,
/// centre at distance ℓ, J0 about c, gravity g downward (−ĵ).
pub struct PhysicalPendulum {
    pub m: f64,
    pub l: f64,
    pub j0: f64,
    pub g: f64,
}

impl KinematicMap for PhysicalPendulum {
    fn dof(&self) -> usize {
        1
    }
    fn masses(&self) -> MapMasses {
        MapMasses {
            particles: vec![],
            bodies: vec![(self.m, Matrix3::from_diagonal(&Vector3::new(self.j0, self.j0, self.j0)))],
        }
    }
    fn bodies<T: Scalar>(&self, q: &[T], _t: T) -> Vec<(Vector<T>, Frame<T>)> {
        let a = Frame::<T>::identity();
        let l = T::lit(self.l);
        let (s, c) = (q[0].sin(), q[0].cos());
        let r_c = a.vector([l * s, -l * c, T::zero()]);
        // F_B = A rotated by θ about k̂ (passive 𝓞_{B/A} = 𝓞₃(θ))
        let o = Matrix3::new(c, s, T::zero(), -s, c, T::zero(), T::zero(), T::zero(), T::one());
        let b = Frame::from_orientation_rel(&a, &o, 1e-9).expect("a rotation");
        vec![(r_c, b)]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        // U = −m r_c·g = m g ℓ (1 − cos θ) up to a constant
        -T::lit(self.m * self.g * self.l) * q[0].cos()
    }
}
