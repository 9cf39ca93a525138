//! Constrained systems shared by the §9.11–9.14 tests, each written as a textbook writes it:
//! energies or positions in redundant coordinates, plus the constraints.
#![allow(dead_code)]

use vectrix::dynamics::constraints::{Constraints, ProjectionOptions, constraint_terms, project_positions};
use vectrix::nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use vectrix::prelude::*;

/// |got − want| ≤ tol (absolute).
#[track_caller]
pub fn assert_abs(got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "got {got:e}, want {want:e}, |Δ| = {:e} > {tol:e}",
        (got - want).abs()
    );
}

/// |got − want| ≤ tol·|want| (relative).
#[track_caller]
pub fn assert_rel(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(
        err <= tol * want.abs(),
        "got {got:e}, want {want:e}, relative error {:e} > {tol:e}",
        err / want.abs()
    );
}

/// The passive elementary matrix 𝓞₃(θ) (2.12.16).
pub fn o3<T: Scalar>(t: T) -> Matrix3<T> {
    let (s, c, z, o) = (t.sin(), t.cos(), T::zero(), T::one());
    Matrix3::new(c, s, z, -s, c, z, z, z, o)
}

/// The passive elementary matrix 𝓞₁(θ) (2.12.14).
pub fn o1<T: Scalar>(t: T) -> Matrix3<T> {
    let (s, c, z, o) = (t.sin(), t.cos(), T::zero(), T::one());
    Matrix3::new(o, z, z, z, c, s, z, -s, c)
}

/// The passive elementary matrix 𝓞₂(θ) (2.12.15).
pub fn o2<T: Scalar>(t: T) -> Matrix3<T> {
    let (s, c, z, o) = (t.sin(), t.cos(), T::zero(), T::one());
    Matrix3::new(c, z, -s, z, o, z, s, z, c)
}

/// A frame with 𝓞_{B/A} = `o` relative to the identity frame A.
pub fn frame_from<T: Scalar>(o: &Matrix3<T>) -> Frame<T> {
    Frame::from_orientation_rel(&Frame::<T>::identity(), o, 1e-9).expect("a rotation matrix")
}

/// A particle on a massless rod, q = (x, y) with y up: T = ½m(ẋ² + ẏ²), U = mgy,
/// φ = |r⃗| − l (so λ is the rod's tension).
pub struct ParticlePendulum {
    pub m: f64,
    pub l: f64,
    pub g: f64,
}

impl Lagrangian for ParticlePendulum {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5 * self.m) * (qd[0] * qd[0] + qd[1] * qd[1])
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(self.m * self.g) * q[1]
    }
}

impl Constraints for ParticlePendulum {
    fn constraint_count(&self) -> usize {
        1
    }
    fn constraints<T: Scalar>(&self, q: &[T], _t: T, out: &mut [T]) {
        out[0] = (q[0] * q[0] + q[1] * q[1]).sqrt() - T::lit(self.l);
    }
}

/// Ex 9.10.2 written with a constraint: a bead (mass m) in the horizontal plane, q = (x, y),
/// held on a straight wire through the origin turning at constant ω:
/// φ = −x sin ωt + y cos ωt = 0 (rheonomic).
pub struct BeadOnTurningWire {
    pub m: f64,
    pub w: f64,
}

impl Lagrangian for BeadOnTurningWire {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5 * self.m) * (qd[0] * qd[0] + qd[1] * qd[1])
    }
}

impl Constraints for BeadOnTurningWire {
    fn constraint_count(&self) -> usize {
        1
    }
    fn constraints<T: Scalar>(&self, q: &[T], t: T, out: &mut [T]) {
        let wt = T::lit(self.w) * t;
        out[0] = -q[0] * wt.sin() + q[1] * wt.cos();
    }
}

/// A bead (mass m) on a hoop of radius R turning about its vertical diameter at constant Ω,
/// in Cartesian coordinates q = (x, y, z), z up: φ₁ = |r⃗| − R (on the sphere) and
/// φ₂ = −x sin Ωt + y cos Ωt (in the hoop's turning plane).
pub struct BeadOnHoop {
    pub m: f64,
    pub r: f64,
    pub w: f64,
    pub g: f64,
}

impl Lagrangian for BeadOnHoop {
    fn dof(&self) -> usize {
        3
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5 * self.m) * (qd[0] * qd[0] + qd[1] * qd[1] + qd[2] * qd[2])
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(self.m * self.g) * q[2]
    }
}

impl Constraints for BeadOnHoop {
    fn constraint_count(&self) -> usize {
        2
    }
    fn constraints<T: Scalar>(&self, q: &[T], t: T, out: &mut [T]) {
        let wt = T::lit(self.w) * t;
        out[0] = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt() - T::lit(self.r);
        out[1] = -q[0] * wt.sin() + q[1] * wt.cos();
    }
}

/// The same bead in the hoop's own coordinate θ (from the downward vertical):
/// T = ½mR²(θ̇² + Ω² sin²θ), U = −mgR cos θ.
pub struct HoopAngle<'a>(pub &'a BeadOnHoop);

impl Lagrangian for HoopAngle<'_> {
    fn dof(&self) -> usize {
        1
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let s = q[0].sin();
        T::lit(0.5 * self.0.m * self.0.r * self.0.r) * (qd[0] * qd[0] + T::lit(self.0.w * self.0.w) * s * s)
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        -T::lit(self.0.m * self.0.g * self.0.r) * q[0].cos()
    }
}

/// A planar double pendulum of point masses in Cartesian coordinates q = (x₁, y₁, x₂, y₂),
/// y up: φ₁ = |r⃗₁| − l₁, φ₂ = |r⃗₂ − r⃗₁| − l₂ (λ = the rod tensions).
pub struct CartesianDoublePendulum {
    pub m1: f64,
    pub m2: f64,
    pub l1: f64,
    pub l2: f64,
    pub g: f64,
}

impl Lagrangian for CartesianDoublePendulum {
    fn dof(&self) -> usize {
        4
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5 * self.m1) * (qd[0] * qd[0] + qd[1] * qd[1])
            + T::lit(0.5 * self.m2) * (qd[2] * qd[2] + qd[3] * qd[3])
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(self.g) * (T::lit(self.m1) * q[1] + T::lit(self.m2) * q[3])
    }
}

impl Constraints for CartesianDoublePendulum {
    fn constraint_count(&self) -> usize {
        2
    }
    fn constraints<T: Scalar>(&self, q: &[T], _t: T, out: &mut [T]) {
        let (dx, dy) = (q[2] - q[0], q[3] - q[1]);
        out[0] = (q[0] * q[0] + q[1] * q[1]).sqrt() - T::lit(self.l1);
        out[1] = (dx * dx + dy * dy).sqrt() - T::lit(self.l2);
    }
}

/// The same double pendulum in joint coordinates (θ₁, θ₂) from the downward vertical:
/// T = ½(m₁+m₂)l₁²θ̇₁² + m₂l₁l₂θ̇₁θ̇₂cos(θ₁−θ₂) + ½m₂l₂²θ̇₂², U = −(m₁+m₂)gl₁cos θ₁ − m₂gl₂cos θ₂.
pub struct JointDoublePendulum<'a>(pub &'a CartesianDoublePendulum);

impl Lagrangian for JointDoublePendulum<'_> {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let p = self.0;
        let (m12, m2) = (T::lit(p.m1 + p.m2), T::lit(p.m2));
        let (l1, l2) = (T::lit(p.l1), T::lit(p.l2));
        T::lit(0.5) * m12 * l1 * l1 * qd[0] * qd[0]
            + m2 * l1 * l2 * qd[0] * qd[1] * (q[0] - q[1]).cos()
            + T::lit(0.5) * m2 * l2 * l2 * qd[1] * qd[1]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let p = self.0;
        -T::lit((p.m1 + p.m2) * p.g * p.l1) * q[0].cos() - T::lit(p.m2 * p.g * p.l2) * q[1].cos()
    }
}

/// A four-bar linkage: ground pivots O₂ = (0, 0) and O₄ = (d, 0), crank a, coupler b,
/// rocker c, q = (θ₂, θ₃, θ₄) measured from the ground line; each link a uniform bar
/// (mass ρ·length, J_zz = m L²/12) under gravity −g ĵ. Loop closure (two rows):
/// a e(θ₂) + b e(θ₃) − c e(θ₄) − d î = 0.
pub struct FourBar {
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub d: f64,
    pub rho: f64,
    pub g: f64,
}

impl FourBar {
    fn bar(&self, len: f64) -> (f64, Matrix3<f64>) {
        let m = self.rho * len;
        let j = m * len * len / 12.0;
        // a thin bar along its x axis: J = diag(≈0, mL²/12, mL²/12), kept physical
        (m, Matrix3::from_diagonal(&Vector3::new(j * 1e-3, j, j)))
    }

    /// The centres of the three bars.
    pub fn centres<T: Scalar>(&self, q: &[T]) -> [Vector3<T>; 3] {
        let e = |t: T| Vector3::new(t.cos(), t.sin(), T::zero());
        let (a, b, c, d) = (T::lit(self.a), T::lit(self.b), T::lit(self.c), T::lit(self.d));
        let p_a = e(q[0]) * a;
        [
            p_a * T::lit(0.5),
            p_a + e(q[1]) * (b * T::lit(0.5)),
            Vector3::new(d, T::zero(), T::zero()) + e(q[2]) * (c * T::lit(0.5)),
        ]
    }

    /// Assembles the linkage at crank angle θ₂ from the guess `q` by Gauss–Newton on the loop
    /// closure plus the driving row θ₂ − θ₂* = 0 (metric M = I).
    pub fn assemble(&self, th2: f64, q: &[f64]) -> Result<Vec<f64>, DynamicsError> {
        let rows = |q: &[f64]| {
            let t = constraint_terms(self, q, &[0.0; 3], 0.0)?;
            let mut jac = DMatrix::zeros(3, 3);
            jac.rows_mut(0, 2).copy_from(&t.jacobian);
            jac[(2, 0)] = 1.0;
            Ok((DVector::from_vec(vec![t.position[0], t.position[1], q[0] - th2]), jac))
        };
        let plus = |q: &[f64], d: &DVector<f64>| Ok(q.iter().zip(d.iter()).map(|(a, b)| a + b).collect());
        Ok(project_positions(q, &DMatrix::identity(3, 3), rows, plus, &ProjectionOptions::default())?.q)
    }

    /// A consistent initial state: assembled at θ₂ from `guess`, the crank turning at ω and the
    /// coupler and rocker rates solving Φ_q q̇ = 0 (test set-up: panics at a dead point).
    pub fn start(&self, th2: f64, guess: &[f64], omega: f64) -> (Vec<f64>, Vec<f64>) {
        let q0 = self.assemble(th2, guess).expect("the linkage assembles");
        let g = constraint_terms(self, &q0, &[0.0; 3], 0.0).expect("finite").jacobian;
        let sub = DMatrix::from_fn(2, 2, |i, j| g[(i, j + 1)]);
        let rest = sub.lu().solve(&(-g.column(0) * omega)).expect("away from a dead point");
        (q0, vec![omega, rest[0], rest[1]])
    }

    /// The coupler point at (u, v) in the coupler's frame (origin at the crank pin, x along
    /// the coupler).
    pub fn coupler_point(&self, q: &[f64], u: f64, v: f64) -> [f64; 2] {
        let (s2, c2, s3, c3) = (q[0].sin(), q[0].cos(), q[1].sin(), q[1].cos());
        [self.a * c2 + u * c3 - v * s3, self.a * s2 + u * s3 + v * c3]
    }
}

impl KinematicMap for FourBar {
    fn dof(&self) -> usize {
        3
    }
    fn masses(&self) -> MapMasses {
        MapMasses { particles: vec![], bodies: vec![self.bar(self.a), self.bar(self.b), self.bar(self.c)] }
    }
    fn bodies<T: Scalar>(&self, q: &[T], _t: T) -> Vec<(Vector<T>, Frame<T>)> {
        let a = Frame::<T>::identity();
        let centres = self.centres(q);
        (0..3).map(|i| (a.vector(centres[i].into()), frame_from(&o3(q[i])))).collect()
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let centres = self.centres(q);
        let m = [self.a, self.b, self.c].map(|l| T::lit(self.rho * l * self.g));
        m[0] * centres[0].y + m[1] * centres[1].y + m[2] * centres[2].y
    }
}

impl Constraints for FourBar {
    fn constraint_count(&self) -> usize {
        2
    }
    fn constraints<T: Scalar>(&self, q: &[T], _t: T, out: &mut [T]) {
        let (a, b, c) = (T::lit(self.a), T::lit(self.b), T::lit(self.c));
        out[0] = a * q[0].cos() + b * q[1].cos() - c * q[2].cos() - T::lit(self.d);
        out[1] = a * q[0].sin() + b * q[1].sin() - c * q[2].sin();
    }
}

/// Freudenstein's equation K₁ cos θ₄ − K₂ cos θ₂ + K₃ − cos(θ₂ − θ₄) with K₁ = d/a,
/// K₂ = d/c, K₃ = (a² − b² + c² + d²)/(2ac): zero on every assembly of the four-bar.
pub fn freudenstein(fb: &FourBar, th2: f64, th4: f64) -> f64 {
    let (a, b, c, d) = (fb.a, fb.b, fb.c, fb.d);
    let (k1, k2, k3) = (d / a, d / c, (a * a - b * b + c * c + d * d) / (2.0 * a * c));
    k1 * th4.cos() - k2 * th2.cos() + k3 - (th2 - th4).cos()
}
