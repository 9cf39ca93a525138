//! Rolling and sliding bodies for the §9.12 and §9.14 tests: the rolling disk of §4.18 and
//! the Chaplygin sleigh (knife edge), each with its velocity constraints.
#![allow(dead_code)]

use vectrix::dynamics::constraints::Constraints;
use vectrix::dynamics::constraints::kane::{BodyMotion, KaneLoads, KaneSystem};
use vectrix::kinematics::contact_point_velocity;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

use super::mechanisms::{frame_from, o1, o2, o3};

/// A thin uniform disk (mass m, radius r) on the plane z = 0 under gravity −g ẑ, in
/// q = (x, y, ψ, θ, φ): (x, y) the contact point, F_L = A turned by ψ about k̂ then by the
/// lean θ about î (so 𝓞_{L/A} = 𝓞₁(θ)𝓞₃(ψ)), the disk F_B = F_L turned by the spin φ about
/// ĵ_L (its axis); centre c = (x, y, 0) + r k̂_L. Rolling without slip (Def 4.18.2): the
/// disk's material point at the contact has zero velocity, v⃗_c + ω⃗ × (−r k̂_L) = 0; its
/// vertical component vanishes identically, so two velocity rows (î, ĵ) remain, or three
/// when `all_rows` (then one is singular).
pub struct RollingDisk {
    pub m: f64,
    pub r: f64,
    pub g: f64,
    /// Tilt of gravity: g⃗ = g(sin α, 0, −cos α) (the plane inclined by α, x downhill).
    pub incline: f64,
    pub all_rows: bool,
}

impl RollingDisk {
    /// 𝓞_{L/A} and 𝓞_{B/A}.
    pub fn frames<T: Scalar>(&self, q: &[T]) -> (Matrix3<T>, Matrix3<T>) {
        let o_la = o1(q[3]) * o3(q[2]);
        (o_la, o2(q[4]) * o_la)
    }

    /// Centre c⃗ = (x, y, 0) + r k̂_L, resolved in A.
    pub fn centre<T: Scalar>(&self, q: &[T]) -> Vector3<T> {
        let (o_la, _) = self.frames(q);
        // k̂_L resolved in A is row 3 of 𝓞_{L/A}
        Vector3::new(q[0], q[1], T::zero()) + o_la.row(2).transpose() * T::lit(self.r)
    }

    /// ω⃗_{B/A} = ψ̇ k̂ + θ̇ î_L + φ̇ ĵ_L, resolved in A.
    pub fn omega<T: Scalar>(&self, q: &[T], qd: &[T]) -> Vector3<T> {
        let (o_la, _) = self.frames(q);
        Vector3::z() * qd[2] + o_la.row(0).transpose() * qd[3] + o_la.row(1).transpose() * qd[4]
    }

    /// ċ⃗ = (ẋ, ẏ, 0) + r d/dt k̂_L with k̂_L = (sin θ sin ψ, −sin θ cos ψ, cos θ).
    pub fn centre_velocity<T: Scalar>(&self, q: &[T], qd: &[T]) -> Vector3<T> {
        let (s2, c2, s3, c3) = (q[2].sin(), q[2].cos(), q[3].sin(), q[3].cos());
        let r = T::lit(self.r);
        Vector3::new(
            qd[0] + r * (c3 * s2 * qd[3] + s3 * c2 * qd[2]),
            qd[1] + r * (-c3 * c2 * qd[3] + s3 * s2 * qd[2]),
            -r * s3 * qd[3],
        )
    }

    /// q̇ of a rolling state with rates (ψ̇, θ̇, φ̇): the contact point moves along the
    /// heading at r φ̇, ẋ = r φ̇ cos ψ, ẏ = r φ̇ sin ψ.
    pub fn rolling_rates(&self, q: &[f64], rates: [f64; 3]) -> [f64; 5] {
        let v = self.r * rates[2];
        [v * q[2].cos(), v * q[2].sin(), rates[0], rates[1], rates[2]]
    }

    /// Velocity of the disk's material point at the contact, v⃗_c + ω⃗ × r⃗_{P/c} (4.4.9).
    pub fn contact_velocity<T: Scalar>(&self, q: &[T], qd: &[T]) -> Vector3<T> {
        let (o_la, _) = self.frames(q);
        let a = Frame::<T>::identity();
        let r = T::lit(self.r);
        let v_c = self.centre_velocity(q, qd);
        let r_p_c = -o_la.row(2).transpose() * r;
        let v = contact_point_velocity(
            &a.vector(v_c.into()),
            &a.vector(self.omega(q, qd).into()),
            &a.vector(r_p_c.into()),
        );
        v.resolve(&a)
    }

    /// Energy T + U of a state.
    pub fn energy(&self, q: &[f64], qd: &[f64]) -> f64 {
        vectrix::dynamics::lagrange::map_kinetic_energy(self, q, qd, 0.0).unwrap()
            + KinematicMap::potential(self, q, 0.0)
    }
}

impl KinematicMap for RollingDisk {
    fn dof(&self) -> usize {
        5
    }
    fn masses(&self) -> MapMasses {
        let (m, r) = (self.m, self.r);
        // thin disk, axis ĵ_B: J = diag(mr²/4, mr²/2, mr²/4)
        MapMasses {
            particles: vec![],
            bodies: vec![(m, Matrix3::from_diagonal(&Vector3::new(0.25, 0.5, 0.25)) * (m * r * r))],
        }
    }
    fn bodies<T: Scalar>(&self, q: &[T], _t: T) -> Vec<(Vector<T>, Frame<T>)> {
        let (_, o_ba) = self.frames(q);
        vec![(Frame::<T>::identity().vector(self.centre(q).into()), frame_from(&o_ba))]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        // U = −m g⃗·c⃗
        let (sa, ca) = (self.incline.sin(), self.incline.cos());
        let c = self.centre(q);
        -T::lit(self.m * self.g) * (T::lit(sa) * c.x - T::lit(ca) * c.z)
    }
}

impl Constraints for RollingDisk {
    fn velocity_constraint_count(&self) -> usize {
        if self.all_rows { 3 } else { 2 }
    }
    fn velocity_constraints<T: Scalar>(&self, q: &[T], qd: &[T], _t: T, out: &mut [T]) {
        let v = self.contact_velocity(q, qd);
        for (o, vi) in out.iter_mut().zip(v.iter()) {
            *o = *vi;
        }
    }
}

/// The Chaplygin sleigh: a body (mass m, inertia I about its centre G) on a knife edge at P,
/// G a distance `a` ahead of P along the blade; q = (x, y, ψ) of P and the heading ψ.
/// T = ½m|v⃗_G|² + ½Iψ̇², the blade forbids sideways motion of P: −ẋ sin ψ + ẏ cos ψ = 0.
pub struct Sleigh {
    pub m: f64,
    pub i: f64,
    pub a: f64,
}

impl Lagrangian for Sleigh {
    fn dof(&self) -> usize {
        3
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        // v_G = ṗ + a ψ̇ (−sin ψ, cos ψ)
        let a = T::lit(self.a);
        let (s, c) = (q[2].sin(), q[2].cos());
        let (vx, vy) = (qd[0] - a * qd[2] * s, qd[1] + a * qd[2] * c);
        T::lit(0.5 * self.m) * (vx * vx + vy * vy) + T::lit(0.5 * self.i) * qd[2] * qd[2]
    }
}

impl Constraints for Sleigh {
    fn velocity_constraint_count(&self) -> usize {
        1
    }
    fn velocity_constraints<T: Scalar>(&self, q: &[T], qd: &[T], _t: T, out: &mut [T]) {
        out[0] = -qd[0] * q[2].sin() + qd[1] * q[2].cos();
    }
}

/// The rolling disk of [`RollingDisk`] with Kane's favourite speeds u = ω⃗_{B/A} resolved in
/// the lean frame L, so that rolling is built into the velocities: v⃗_c = ω⃗ × r k̂_L, and no
/// speed is dependent. Kinematical equations from ω|_L = (θ̇, ψ̇ sin θ + φ̇, ψ̇ cos θ):
/// θ̇ = u₁, ψ̇ = u₃/cos θ, φ̇ = u₂ − u₃ tan θ, and the contact point moves at r φ̇ along î_L.
pub struct KaneDisk(pub RollingDisk);

impl KaneSystem for KaneDisk {
    fn coordinates(&self) -> usize {
        5
    }
    fn speeds(&self) -> usize {
        3
    }
    fn masses(&self) -> MapMasses {
        KinematicMap::masses(&self.0)
    }
    fn kinematic_equations<T: Scalar>(&self, q: &[T], u: &[T], _t: T, qd: &mut [T]) {
        let (psid, phid) = (u[2] / q[3].cos(), u[1] - u[2] * q[3].tan());
        let v = T::lit(self.0.r) * phid;
        qd.copy_from_slice(&[v * q[2].cos(), v * q[2].sin(), psid, u[0], phid]);
    }
    fn body_motions<T: Scalar>(&self, q: &[T], u: &[T], _t: T) -> Vec<BodyMotion<T>> {
        let (o_la, o_ba) = self.0.frames(q);
        let l = frame_from(&o_la);
        let omega = l.vector([u[0], u[1], u[2]]);
        // rolling: the contact point is at rest, v⃗_c = ω⃗ × r⃗_{c/P}
        let v_c = omega.cross(&(l.k() * T::lit(self.0.r)));
        vec![BodyMotion { v_c, omega, frame: frame_from(&o_ba) }]
    }
    fn loads(&self, _q: &[f64], _u: &[f64], _t: f64) -> KaneLoads {
        let a = Frame::new();
        KaneLoads {
            particles: vec![],
            bodies: vec![(a.vector([0.0, 0.0, -self.0.m * self.0.g]), Vector::zero())],
        }
    }
}
