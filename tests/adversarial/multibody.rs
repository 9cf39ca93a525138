//! vectrix-dynamics' multibody, Lagrange and constraint layers under hostile input
//! (docs/robustness.md): a tree model built from hostile links is refused or valid; its
//! algorithms return `Err` or values with their defining properties, each checked by another
//! route: M symmetric positive definite with ½vᵀMv = T, RNEA(q, v, ABA(q, v, τ)) = τ,
//! ∂U/∂q = the gravity torque of RNEA, Lagrange's and Hamilton's equations against the closed
//! form of a cart pendulum, constrained accelerations with G q̈ = γ, projections with
//! |φ| ≤ tol, Kane's equations against a block on an incline.

use crate::support::{NanAmax, nan_max};
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use num_dual::Dual64;
use vectrix::dynamics::DynamicsError;
use vectrix::dynamics::constraints::kane::{
    BodyMotion, KaneLoads, KaneSystem, kane_accelerations, kane_state_derivative, partial_velocities,
};
use vectrix::dynamics::constraints::{
    ConstrainedIntegrator, ConstrainedSystem, Constraints, DEPENDENT_ROW_REL_TOL, KktFactor, LagrangeForm,
    MapForm, ProjectionOptions, constrained_accelerations, constraint_terms, constraint_violation,
    map_constrained_accelerations, project_positions, project_velocities, solve_constrained, solve_kkt,
};
use vectrix::dynamics::lagrange::{
    KinematicMap, Lagrangian, MapMasses, accelerations, energy, energy_rate, generalized_momentum,
    hamilton_rhs, hamiltonian, lagrange_terms, map_accelerations, map_equations, map_kinetic_energy,
    map_mass_matrix, mass_matrix, velocities_from_momenta,
};
use vectrix::dynamics::multibody::{
    AbaDerivatives, Joint, JointWrench, Link, Model, MotionScratch, PosesScratch, RneaDerivatives,
    normalize_quaternion,
};
use vectrix::frames::Frame;
use vectrix::ode::Adaptive;
use vectrix::tensor::{Scalar, Vector};

use crate::harness::{err_or, finite, hostile, hostile3, refused};

/// Relative tolerance of the cross-checks between algorithms: their round-off is a few
/// hundred ε times the condition of M (≤ 1e3 for the models here).
const REL: f64 = 1e-8;

fn amax(x: &[f64]) -> f64 {
    x.iter().fold(0.0f64, |m, v| nan_max(m, v.abs()))
}

/// A tree with every joint of Table 1.3 plus weld and free: a pin carrying a ball and a slot,
/// a collar carrying a sleeve, a free body carrying a welded one.
fn tree_links() -> Vec<Link> {
    let d = |a: f64, b: f64, c: f64| Matrix3::from_diagonal(&Vector3::new(a, b, c));
    vec![
        Link::new(
            None,
            Joint::Pin { axis: Vector3::z() },
            Vector3::zeros(),
            1.0,
            Vector3::new(0.5, 0.0, 0.0),
            d(0.01, 0.1, 0.1),
        ),
        Link::new(
            Some(0),
            Joint::Ball,
            Vector3::new(1.0, 0.0, 0.0),
            1.0,
            Vector3::new(0.0, -0.5, 0.0),
            d(0.1, 0.01, 0.1),
        ),
        Link::new(
            Some(0),
            Joint::Slot { axis: Vector3::z(), direction: Vector3::x() },
            Vector3::new(0.5, 0.0, 0.0),
            0.5,
            Vector3::zeros(),
            d(0.05, 0.05, 0.05),
        ),
        Link::new(
            None,
            Joint::Collar { axis: Vector3::y() },
            Vector3::zeros(),
            2.0,
            Vector3::new(0.1, 0.0, 0.0),
            d(0.2, 0.3, 0.4),
        ),
        Link::new(
            Some(3),
            Joint::Sleeve { axis: Vector3::x() },
            Vector3::zeros(),
            1.0,
            Vector3::zeros(),
            d(0.1, 0.1, 0.1),
        ),
        Link::new(None, Joint::Free, Vector3::new(0.0, 0.0, 2.0), 1.0, Vector3::zeros(), d(0.1, 0.2, 0.3)),
        Link::new(
            Some(5),
            Joint::Weld,
            Vector3::new(0.0, 0.0, 1.0),
            0.5,
            Vector3::zeros(),
            d(0.01, 0.01, 0.01),
        ),
    ]
}

fn tree() -> Model {
    let mut m = Model::new(&tree_links()).unwrap();
    m.gravity = Vector3::new(0.0, -9.81, 0.0);
    m
}

/// A generic state of `model`: the neutral configuration moved along a fixed tangent.
fn state(model: &Model) -> (Vec<f64>, Vec<f64>) {
    let v: Vec<f64> =
        (0..model.nv()).map(|k| 0.3 + 0.1 * k as f64 * if k % 2 == 0 { 1.0 } else { -1.0 }).collect();
    let q = model.integrate(&model.neutral(), &v, 1.0).unwrap();
    (q, v)
}

/// M is symmetric and positive definite (its Cholesky factor exists).
fn spd(m: &DMatrix<f64>) -> bool {
    finite(m.as_slice())
        && (m - m.transpose()).nan_amax() <= 1e-12 * m.nan_amax()
        && m.clone().cholesky().is_some()
}

/// M is symmetric positive semidefinite (a massless link is valid, its M is singular): its
/// smallest eigenvalue is ≥ −(round-off of the largest).
fn psd(m: &DMatrix<f64>) -> bool {
    finite(m.as_slice())
        && (m - m.transpose()).nan_amax() <= 1e-12 * m.nan_amax()
        && m.clone().symmetric_eigenvalues().iter().all(|&l| l >= -1e-12 * m.nan_amax())
}

/// Orthonormal with det +1.
fn rotation(o: &Matrix3<f64>) -> bool {
    finite(o.as_slice())
        && (o * o.transpose() - Matrix3::identity()).nan_amax() <= 1e-12
        && (o.determinant() - 1.0).abs() <= 1e-12
}

/// q with entry k replaced by x.
fn with(q: &[f64], k: usize, x: f64) -> Vec<f64> {
    let mut q = q.to_vec();
    q[k] = x;
    q
}

/// The cart pendulum (§9.6): cart m₁ at x, bob m₂ on a rod l at θ from the downward vertical,
/// gravity g, a dashpot c on the cart and a force F on it. T = ½(m₁+m₂)ẋ² + m₂lẋθ̇cosθ +
/// ½m₂l²θ̇², U = −m₂gl cosθ, R = ½cẋ².
#[derive(Clone, Copy, Debug)]
struct CartPendulum {
    m1: f64,
    m2: f64,
    l: f64,
    g: f64,
    c: f64,
    f: f64,
}

const CART: CartPendulum = CartPendulum { m1: 2.0, m2: 0.5, l: 0.8, g: 9.81, c: 0.3, f: 1.5 };

impl CartPendulum {
    /// M(θ) in closed form.
    fn m(&self, th: f64) -> DMatrix<f64> {
        let k = self.m2 * self.l * th.cos();
        DMatrix::from_row_slice(2, 2, &[self.m1 + self.m2, k, k, self.m2 * self.l * self.l])
    }
    /// The closed-form right-hand side of M q̈ = f: f = (F − cẋ + m₂lθ̇² sinθ, −m₂gl sinθ).
    fn rhs(&self, q: &[f64], qd: &[f64]) -> DVector<f64> {
        let (s, m2l) = (q[1].sin(), self.m2 * self.l);
        DVector::from_vec(vec![self.f - self.c * qd[0] + m2l * qd[1] * qd[1] * s, -m2l * self.g * s])
    }
}

impl Lagrangian for CartPendulum {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let h = T::lit(0.5);
        h * T::lit(self.m1 + self.m2) * qd[0] * qd[0]
            + T::lit(self.m2 * self.l) * qd[0] * qd[1] * q[1].cos()
            + h * T::lit(self.m2 * self.l * self.l) * qd[1] * qd[1]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        -T::lit(self.m2 * self.g * self.l) * q[1].cos()
    }
    fn rayleigh<T: Scalar>(&self, _q: &[T], qd: &[T]) -> T {
        T::lit(0.5 * self.c) * qd[0] * qd[0]
    }
    fn generalized_force(&self, _q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        out[0] += self.f;
    }
}

/// The same cart pendulum as two particles (no dashpot): cart at (x, 0, 0), bob at
/// (x + l sinθ, −l cosθ, 0), gravity −g ŷ as a potential, F on the cart.
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
        -T::lit(self.m2 * self.g * self.l) * q[1].cos()
    }
    fn generalized_force(&self, _q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        out[0] += self.f;
    }
}

/// A free particle of mass m in the plane: every default of [`Lagrangian`] (U = R = 0, no
/// force) and of [`Constraints`] (none).
struct FreeParticle(f64);

impl Lagrangian for FreeParticle {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5 * self.0) * (qd[0] * qd[0] + qd[1] * qd[1])
    }
}
impl Constraints for FreeParticle {}

/// A particle pendulum in Cartesian coordinates: φ = x² + y² − l² (§9.11), gravity −g ŷ, plus
/// (optionally) the velocity row ψ = ẋ + k ẏ (§9.12) when `k` is finite.
#[derive(Clone, Copy)]
struct Pendulum {
    m: f64,
    l: f64,
    g: f64,
    k: Option<f64>,
}

impl Lagrangian for Pendulum {
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
impl KinematicMap for Pendulum {
    fn dof(&self) -> usize {
        2
    }
    fn masses(&self) -> MapMasses {
        MapMasses { particles: vec![self.m], bodies: vec![] }
    }
    fn particles<T: Scalar>(&self, q: &[T], _t: T) -> Vec<Vector<T>> {
        vec![Frame::<T>::identity().vector([q[0], q[1], T::zero()])]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(self.m * self.g) * q[1]
    }
}
impl Constraints for Pendulum {
    fn constraint_count(&self) -> usize {
        1
    }
    fn constraints<T: Scalar>(&self, q: &[T], _t: T, out: &mut [T]) {
        out[0] = q[0] * q[0] + q[1] * q[1] - T::lit(self.l * self.l);
    }
    fn velocity_constraint_count(&self) -> usize {
        usize::from(self.k.is_some())
    }
    fn velocity_constraints<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T, out: &mut [T]) {
        if let Some(k) = self.k {
            out[0] = qd[0] + T::lit(k) * qd[1];
        }
    }
}

/// The pendulum as a hand-written [`ConstrainedSystem`] (M = m I, f = −mg ŷ), leaving
/// [`ConstrainedSystem::mass`] to its default.
struct Direct(Pendulum);
impl Constraints for Direct {
    fn constraint_count(&self) -> usize {
        1
    }
    fn constraints<T: Scalar>(&self, q: &[T], t: T, out: &mut [T]) {
        self.0.constraints(q, t, out)
    }
}
impl ConstrainedSystem for Direct {
    fn dof(&self) -> usize {
        2
    }
    fn equations(
        &self,
        q: &[f64],
        _qd: &[f64],
        _t: f64,
    ) -> Result<(DMatrix<f64>, DVector<f64>), DynamicsError> {
        if q.len() != 2 {
            return Err(DynamicsError::DimensionMismatch { what: "q", expected: 2, got: q.len() });
        }
        Ok((DMatrix::identity(2, 2) * self.0.m, DVector::from_vec(vec![0.0, -self.0.m * self.0.g])))
    }
}

/// A pendulum state at angle θ and rate θ̇ on |r| = l.
fn on_circle(l: f64, th: f64, thd: f64) -> ([f64; 2], [f64; 2]) {
    ([l * th.sin(), -l * th.cos()], [l * th.cos() * thd, l * th.sin() * thd])
}

/// Kane (§9.14): a block of mass m on an incline of slope s, speeds u = (ẋ, θ̇, ẏ) with ẏ
/// dependent through ψ = ẏ − s ẋ = 0, carrying a disk of spin inertia J (about ẑ, so the
/// identity frame resolves it) driven by a torque τ; gravity −g ŷ. Closed form:
/// ẍ = −g s/(1 + s²), θ̈ = τ/J.
#[derive(Clone, Copy, Debug)]
struct Incline {
    m: f64,
    s: f64,
    g: f64,
    j: f64,
    tau: f64,
}

impl KaneSystem for Incline {
    fn coordinates(&self) -> usize {
        3
    }
    fn speeds(&self) -> usize {
        3
    }
    fn masses(&self) -> MapMasses {
        MapMasses {
            particles: vec![self.m],
            bodies: vec![(self.m, Matrix3::from_diagonal(&Vector3::new(self.j, self.j, self.j)))],
        }
    }
    fn kinematic_equations<T: Scalar>(&self, _q: &[T], u: &[T], _t: T, qd: &mut [T]) {
        qd[0] = u[0];
        qd[1] = u[1];
        qd[2] = u[2];
    }
    fn particle_velocities<T: Scalar>(&self, _q: &[T], u: &[T], _t: T) -> Vec<Vector<T>> {
        vec![Frame::<T>::identity().vector([u[0], u[2], T::zero()])]
    }
    fn body_motions<T: Scalar>(&self, _q: &[T], u: &[T], _t: T) -> Vec<BodyMotion<T>> {
        let a = Frame::<T>::identity();
        // a flywheel on a fixed axle: its centre does not move
        vec![BodyMotion {
            v_c: a.vector([T::zero(); 3]),
            omega: a.vector([T::zero(), T::zero(), u[1]]),
            frame: a,
        }]
    }
    fn loads(&self, _q: &[f64], _u: &[f64], _t: f64) -> KaneLoads {
        let a = Frame::new();
        KaneLoads {
            particles: vec![a.vector([0.0, -self.m * self.g, 0.0])],
            bodies: vec![(Vector::zero(), a.vector([0.0, 0.0, self.tau]))],
        }
    }
    fn speed_constraint_count(&self) -> usize {
        1
    }
    fn speed_constraints<T: Scalar>(&self, _q: &[T], u: &[T], _t: T, out: &mut [T]) {
        out[0] = u[2] - T::lit(self.s) * u[0];
    }
}

/// A point mass moving freely in the plane: every default of [`KaneSystem`] (no bodies, no
/// loads, no speed constraints).
struct Drifting(f64);
impl KaneSystem for Drifting {
    fn coordinates(&self) -> usize {
        2
    }
    fn speeds(&self) -> usize {
        2
    }
    fn masses(&self) -> MapMasses {
        MapMasses { particles: vec![self.0], bodies: vec![] }
    }
    fn kinematic_equations<T: Scalar>(&self, _q: &[T], u: &[T], _t: T, qd: &mut [T]) {
        qd.copy_from_slice(u);
    }
    fn particle_velocities<T: Scalar>(&self, _q: &[T], u: &[T], _t: T) -> Vec<Vector<T>> {
        vec![Frame::<T>::identity().vector([u[0], u[1], T::zero()])]
    }
}

cases! {
    // Building a tree (§7.11, Fact 6.2.7): hostile masses, inertias, offsets and axes are
    // refused (mass < 0 or non-finite, a zero axis, an inertia outside the triangle
    // inequality) or give a model whose mass matrix is SPD; q and v have the sizes the joints
    // say (a quaternion counts 4 in q and 3 in v) and the neutral quaternions are unit.
    model_building ["Link::new", "Model::new", "Model::revolute_chain", "Model::nq", "Model::nv", "Model::links",
        "Model::neutral", "Model::cast"] {
        let m = tree();
        assert_eq!((m.nq(), m.nv(), m.links()), (1 + 4 + 2 + 2 + 1 + 7, 1 + 3 + 2 + 2 + 1 + 6, 7));
        let n = m.neutral();
        assert_eq!(n.len(), m.nq());
        assert!(((n[1] * n[1] + n[2] * n[2] + n[3] * n[3] + n[4] * n[4]).sqrt() - 1.0).abs() <= 4.0 * f64::EPSILON);
        for x in hostile() {
            let mut links = tree_links();
            links[1].mass = x;
            let usable = |m: &Model| match m.crba(&m.neutral()) {
                Ok(h) => psd(&h),
                Err(e) => matches!(e, DynamicsError::Overflow { .. }),
            };
            err_or(Model::new(&links), "Model::new(mass)", usable);
            for (i, j) in [(0, 0), (1, 1), (0, 1)] {
                let mut links = tree_links();
                links[2].inertia[(i, j)] = x;
                links[2].inertia[(j, i)] = x;
                err_or(Model::new(&links), "Model::new(inertia)", usable);
            }
            for k in 0..3 {
                let mut links = tree_links();
                links[0].offset[k] = x;
                links[4].com[k] = x;
                // a link 1e300 m away is a valid model whose M overflows: Overflow, never ∞
                err_or(Model::new(&links), "Model::new(offset, com)", |m| match m.crba(&m.neutral()) {
                    Ok(h) => psd(&h),
                    Err(e) => matches!(e, DynamicsError::Overflow { .. }),
                });
                let mut links = tree_links();
                links[3].joint = Joint::Collar { axis: Vector3::new(x, 0.0, 0.0) };
                err_or(Model::new(&links), "Model::new(axis)", |m| m.nq() == 17);
                // an axis (0, x, x) is (0, 1, 1)/√2 for every finite x ≠ 0: the same M (the
                // named bug: |a|² overflowed for x = 1e300 and the axis became 0⃗)
                let mut links = tree_links();
                links[0].joint = Joint::Pin { axis: Vector3::new(0.0, x, x) };
                let mut unit = tree_links();
                unit[0].joint = Joint::Pin { axis: Vector3::new(0.0, x.signum(), x.signum()) };
                err_or(Model::new(&links), "Model::new(pin axis)", |m| {
                    let n = Model::new(&unit).unwrap();
                    let (h, hn) = (m.crba(&m.neutral()).unwrap(), n.crba(&n.neutral()).unwrap());
                    (h - &hn).nan_amax() <= 1e-14 * hn.nan_amax()
                });
                let mut links = tree_links();
                links[2].joint = Joint::Slot { axis: Vector3::z(), direction: Vector3::new(1.0, x, x) };
                err_or(Model::new(&links), "Model::new(slot)", |m| m.nv() == 15);
            }
            err_or(Model::revolute_chain(3, x, 0.5), "revolute_chain(m)", usable);
            err_or(Model::revolute_chain(3, 1.0, x), "revolute_chain(l)", usable);
        }
        refused(Model::new(&[Link::new(Some(3), Joint::Weld, Vector3::zeros(), 1.0, Vector3::zeros(), Matrix3::identity())]), "missing parent");
        let mut cyc = tree_links();
        cyc[0].parent = Some(2);
        refused(Model::new(&cyc), "cyclic tree");
        refused(Model::new(&[Link::new(None, Joint::Pin { axis: Vector3::zeros() }, Vector3::zeros(), 1.0, Vector3::zeros(), Matrix3::identity())]), "zero axis");
        // an empty model is valid and has nothing to compute
        let empty = Model::revolute_chain(0, 1.0, 1.0).unwrap();
        assert_eq!((empty.nq(), empty.nv()), (0, 0));
        assert!(empty.aba(&[], &[], &[], None).unwrap().is_empty());
        // a size that cannot be allocated is refused, not an abort
        refused(Model::revolute_chain(usize::MAX, 1.0, 1.0), "revolute_chain(usize::MAX)");
        // cast keeps the model: the real parts of the dual model's M are the f64 model's (to
        // round-off: dual arithmetic may order operations differently), the ε parts zero
        let (q, _) = state(&m);
        let d = m.cast::<Dual64>();
        let qd: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
        let (h, hd) = (m.crba(&q).unwrap(), d.crba(&qd).unwrap());
        assert!(h.iter().zip(hd.iter()).all(|(a, b)| (a - b.re).abs() <= 1e-14 * h.nan_amax() && b.eps == 0.0));
    }

    // Kinematics and energies (§2.22, §8.1, §8.4): poses are rotations; T = ½vᵀMv with M from
    // CRBA (two algorithms); ∂U/∂q = the gravity torque RNEA(q, 0, 0) (central differences);
    // a link's velocity field is v + ω × r. Hostile q and v: Err or finite.
    kinematics_and_energy ["Model::poses", "Model::poses_into", "Model::twists", "LinkTwist::velocity_of",
        "Model::kinetic_energy", "Model::potential_energy", "Model::crba", "Model::crba_unchecked",
        "Model::crba_into", "Model::crba_scratch"] {
        let m = tree();
        let (q, v) = state(&m);
        let h = m.crba(&q).unwrap();
        assert!(spd(&h));
        let t = m.kinetic_energy(&q, &v).unwrap();
        let vv = DVector::from_column_slice(&v);
        assert!((t - 0.5 * vv.dot(&(&h * &vv))).abs() <= REL * t.abs());
        let g = m.rnea(&q, &vec![0.0; m.nv()], &vec![0.0; m.nv()], None).unwrap().tau;
        // revolute and prismatic coordinates: q ⊕ ε e_k = q + ε e_k (pin 0, slot 5–6, collar 7–8, sleeve 9)
        for (qk, vk) in [(0, 0), (5, 4), (6, 5), (7, 6), (8, 7), (9, 8)] {
            let eps = 1e-6;
            let (up, dn) = (m.potential_energy(&with(&q, qk, q[qk] + eps)).unwrap(), m.potential_energy(&with(&q, qk, q[qk] - eps)).unwrap());
            assert!(((up - dn) / (2.0 * eps) - g[vk]).abs() <= 1e-6 * (1.0 + g[vk].abs()), "∂U/∂q[{qk}]");
        }
        let mut s = m.crba_scratch();
        let mut h2 = DMatrix::zeros(m.nv(), m.nv());
        m.crba_into(&q, &mut h2, &mut s);
        assert!((&h2 - &h).nan_amax() <= 1e-14 * h.nan_amax() && (m.crba_unchecked(&q) - &h).nan_amax() <= 1e-14 * h.nan_amax());
        let poses = m.poses(&q).unwrap();
        let (mut ws, mut out) = (PosesScratch::default(), Vec::new());
        m.poses_into(&q, &mut ws, &mut out);
        assert!(poses.iter().zip(&out).all(|(a, b)| rotation(&a.0) && a == b));
        for tw in m.twists(&q, &v).unwrap() {
            for r in hostile3() {
                let r = Vector3::from(r);
                let u = tw.velocity_of(&r);
                if finite(r.as_slice()) && r.nan_amax() <= 1e100 {
                    assert!((u - tw.velocity - tw.omega.cross(&r)).nan_amax() <= 1e-12 * (1.0 + tw.omega.nan_amax() * r.nan_amax()));
                }
            }
        }
        for x in hostile() {
            for k in 0..m.nq() {
                let qx = with(&q, k, x);
                err_or(m.crba(&qx), "crba", spd);
                err_or(m.poses(&qx), "poses", |p| p.iter().all(|(o, r)| rotation(o) && finite(r.as_slice())));
                err_or(m.potential_energy(&qx), "potential_energy", |u| u.is_finite());
                err_or(m.kinetic_energy(&qx, &v), "kinetic_energy(q)", |t| t.is_finite() && *t >= 0.0);
            }
            for k in 0..m.nv() {
                let vx = with(&v, k, x);
                err_or(m.kinetic_energy(&q, &vx), "kinetic_energy(v)", |t| {
                    let vv = DVector::from_column_slice(&vx);
                    let want = 0.5 * vv.dot(&(&h * &vv));
                    t.is_finite() && *t >= 0.0 && (t - want).abs() <= REL * want.abs().max(f64::MIN_POSITIVE)
                });
                err_or(m.twists(&q, &vx), "twists", |tw| tw.iter().all(|t| finite(t.omega.as_slice()) && finite(t.velocity.as_slice())));
            }
        }
        refused(m.crba(&q[1..]), "crba(short q)");
        refused(m.kinetic_energy(&q, &v[1..]), "kinetic_energy(short v)");
        refused(m.poses(&[]), "poses(empty q)");
        // a ball quaternion of zero norm has no attitude
        refused(m.poses(&with(&with(&with(&with(&q, 1, 0.0), 2, 0.0), 3, 0.0), 4, 0.0)), "zero quaternion");
    }

    // Two states at once (`Model::aba_pair_unchecked`): on a chain of pins each state gets the
    // bits of `aba_unchecked` for hostile q, v and τ (NaN where the single call gives NaN); a
    // tree takes two calls; every wrong length is refused with the argument named.
    paired_aba ["Model::aba_pair_unchecked", "Model::aba_pairs"] {
        let pin = |p: Option<usize>, off: f64| Link::new(p, Joint::Pin { axis: Vector3::y() }, Vector3::new(0.0, 0.0, off), 1.0, Vector3::new(0.1, 0.0, -0.2), Matrix3::from_diagonal(&Vector3::new(0.02, 0.03, 0.01)));
        let mut chain = Model::new(&[pin(None, 0.0), pin(Some(0), -0.4), pin(Some(1), -0.4)]).unwrap();
        chain.gravity = Vector3::new(0.0, 0.0, -9.81);
        let t = tree();
        assert!(chain.aba_pairs() && !t.aba_pairs());
        let same = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()));
        for m in [&chain, &t] {
            let (q, v) = state(m);
            let tau: Vec<f64> = (0..m.nv()).map(|k| 0.3 * k as f64 - 0.5).collect();
            let mut s = m.aba_scratch();
            let nv = m.nv();
            for x in hostile() {
                for k in 0..nv.min(m.nq()) {
                    let (qx, vx, tx) = (with(&q, k, x), with(&v, k, x), with(&tau, k, x));
                    let (mut a, mut b, mut c, mut d) = (vec![0.0; nv], vec![0.0; nv], vec![0.0; nv], vec![0.0; nv]);
                    let pair = m.aba_pair_unchecked((&qx, &v), (&q, &vx), &tx, (&mut a, &mut b), &mut s);
                    let one = m.aba_unchecked(&qx, &v, &tx, &mut c, &mut s).and_then(|_| m.aba_unchecked(&q, &vx, &tx, &mut d, &mut s));
                    match (pair, one) {
                        (Ok(()), Ok(())) => assert!(same(&a, &c) && same(&b, &d), "pair at {x}: {a:?} {b:?} against {c:?} {d:?}"),
                        (Err(e), Err(f)) => assert_eq!(e.to_string(), f.to_string()),
                        (p, o) => panic!("pair {p:?} against single calls {o:?} at {x}"),
                    }
                }
            }
            let (mut a, mut b) = (vec![0.0; nv], vec![0.0; nv]);
            refused(m.aba_pair_unchecked((&q[1..], &v), (&q, &v), &tau, (&mut a, &mut b), &mut s), "pair(short q_a)");
            refused(m.aba_pair_unchecked((&q, &v), (&q, &v[1..]), &tau, (&mut a, &mut b), &mut s), "pair(short v_b)");
            refused(m.aba_pair_unchecked((&q, &v), (&q, &v), &[], (&mut a, &mut b), &mut s), "pair(empty τ)");
            let mut long = vec![0.0; nv + 1];
            refused(m.aba_pair_unchecked((&q, &v), (&q, &v), &tau, (&mut a, &mut long), &mut s), "pair(long v̇_b)");
        }
    }

    // Inverse and forward dynamics (§7.11): RNEA(q, v, ABA(q, v, τ)) = τ, and CRBA's forward
    // dynamics gives the same v̇, for hostile q, v, τ and external wrenches; a result that
    // overflows is `Overflow`, never ∞ inside `Ok`.
    inverse_and_forward_dynamics ["Model::rnea", "Model::rnea_unchecked", "Model::scratch", "Model::aba",
        "Model::aba_unchecked", "Model::aba_into", "Model::aba_scratch", "Model::forward_dynamics_crba"] {
        let m = tree();
        let (q, v) = state(&m);
        let nv = m.nv();
        let tau0: Vec<f64> = (0..nv).map(|k| (k as f64 * 0.7).sin()).collect();
        // RNEA(q, v, v̇) = τ up to round-off relative to the terms' size
        let inverts = |q: &[f64], v: &[f64], tau: &[f64], vdot: &[f64]| -> bool {
            if !finite(vdot) {
                return false;
            }
            // where the check itself overflows in f64 (a sleeve at 1e300 m squares past
            // f64::MAX in RNEA's moments), finiteness is all that can be asserted
            let (id, h) = match (m.rnea(q, v, vdot, None), m.crba(q)) {
                (Ok(id), Ok(h)) => (id, h),
                (Err(DynamicsError::Overflow { .. }), _) | (_, Err(DynamicsError::Overflow { .. })) => return true,
                _ => return false,
            };
            let bias = m.rnea(q, v, &vec![0.0; nv], None).map(|b| amax(&b.tau)).unwrap_or(f64::INFINITY);
            // RNEA's round-off is ε times its largest terms: J v̇ and the velocity products J v²
            let scale = amax(tau).max(bias).max(h.nan_amax() * amax(vdot)).max(h.nan_amax() * amax(v) * amax(v)).max(f64::MIN_POSITIVE);
            id.tau.iter().zip(tau).all(|(a, b)| (a - b).abs() <= REL * scale)
        };
        let vdot = m.aba(&q, &v, &tau0, None).unwrap();
        assert!(inverts(&q, &v, &tau0, &vdot));
        let mut s = m.aba_scratch();
        let mut out = vec![0.0; nv];
        m.aba_unchecked(&q, &v, &tau0, &mut out, &mut s).unwrap();
        assert!(inverts(&q, &v, &tau0, &out));
        m.aba_into(&q, &v, &tau0, None, &mut out, &mut s).unwrap();
        assert!(inverts(&q, &v, &tau0, &out));
        let mut tau = vec![0.0; nv];
        let mut sc = m.scratch();
        m.rnea_unchecked(&q, &v, &vdot, &mut tau, &mut sc);
        assert!(tau.iter().zip(&tau0).all(|(a, b)| (a - b).abs() <= REL * (1.0 + b.abs())));
        for x in hostile() {
            for k in 0..m.nq() {
                let qx = with(&q, k, x);
                err_or(m.aba(&qx, &v, &tau0, None), "aba(q)", |vd| inverts(&qx, &v, &tau0, vd));
            }
            for k in 0..nv {
                let (vx, tx) = (with(&v, k, x), with(&tau0, k, x));
                err_or(m.aba(&q, &vx, &tau0, None), &format!("aba(v[{k}] = {x:e})"), |vd| inverts(&q, &vx, &tau0, vd));
                err_or(m.aba(&q, &v, &tx, None), "aba(τ)", |vd| inverts(&q, &v, &tx, vd));
                err_or(m.forward_dynamics_crba(&q, &v, &tx, None), "forward_dynamics_crba(τ)", |vd| inverts(&q, &v, &tx, vd));
                err_or(m.rnea(&q, &v, &with(&vdot, k, x), None), "rnea(v̇)", |id| finite(&id.tau));
            }
            for w in hostile3() {
                let mut f = vec![JointWrench::default(); m.links()];
                f[1].force = Vector3::from(w);
                f[4].moment = Vector3::new(x, 0.0, 1.0);
                err_or(m.aba(&q, &v, &tau0, Some(&f)), "aba(f_ext)", |vd| finite(vd));
                err_or(m.rnea(&q, &v, &vdot, Some(&f)), "rnea(f_ext)", |id| finite(&id.tau) && id.wrenches.iter().all(|w| finite(w.force.as_slice()) && finite(w.moment.as_slice())));
            }
        }
        refused(m.aba(&q, &v, &tau0[1..], None), "aba(short τ)");
        refused(m.rnea(&q, &v, &[], None), "rnea(empty v̇)");
        refused(m.aba(&q, &v, &tau0, Some(&[JointWrench::default()])), "aba(one wrench for seven links)");
        refused(m.forward_dynamics_crba(&q[..3], &v, &tau0, None), "forward_dynamics_crba(short q)");
        // a massless leaf driven by a torque has an infinite acceleration: refused
        let leaf = Model::new(&[Link::new(None, Joint::Pin { axis: Vector3::z() }, Vector3::zeros(), 0.0, Vector3::zeros(), Matrix3::zeros())]).unwrap();
        refused(leaf.aba(&[0.0], &[0.0], &[1.0], None), "aba(massless leaf, τ ≠ 0)");
        refused(leaf.forward_dynamics_crba(&[0.0], &[0.0], &[1.0], None), "forward_dynamics_crba(singular M)");
    }

    // Derivatives (§7.11, §12): the τ and M they carry are RNEA's and CRBA's; ∂τ/∂q matches
    // central differences; ∂v̇/∂τ = M⁻¹ (its product with M is I); ∂M/∂q matches central
    // differences of CRBA. Hostile inputs: Err or finite.
    derivatives ["Model::rnea_derivatives", "Model::rnea_derivatives_into", "Model::aba_derivatives",
        "Model::aba_derivatives_into", "Model::derivative_scratch", "RneaDerivatives::zeros",
        "AbaDerivatives::zeros", "Model::mass_matrix_derivatives"] {
        let m = Model::revolute_chain(4, 1.0, 0.5).map(|mut m| { m.gravity = Vector3::new(0.0, -9.81, 0.0); m }).unwrap();
        let (q, v, vdot) = (vec![0.1, -0.4, 0.7, 0.2], vec![0.5, -1.0, 0.3, 0.8], vec![0.2, 0.1, -0.3, 0.4]);
        let rd = m.rnea_derivatives(&q, &v, &vdot, None).unwrap();
        let h = m.crba(&q).unwrap();
        let tau = m.rnea(&q, &v, &vdot, None).unwrap().tau;
        assert!(rd.tau.iter().zip(&tau).all(|(a, b)| (a - b).abs() <= 1e-12 * (1.0 + b.abs())));
        assert!((&rd.mass_matrix - &h).nan_amax() <= 1e-12 * h.nan_amax());
        let eps = 1e-6;
        for k in 0..4 {
            let (up, dn) = (m.rnea(&with(&q, k, q[k] + eps), &v, &vdot, None).unwrap().tau, m.rnea(&with(&q, k, q[k] - eps), &v, &vdot, None).unwrap().tau);
            for i in 0..4 {
                assert!(((up[i] - dn[i]) / (2.0 * eps) - rd.dtau_dq[(i, k)]).abs() <= 1e-6 * (1.0 + rd.dtau_dq.nan_amax()), "∂τ{i}/∂q{k}");
            }
        }
        let dm = m.mass_matrix_derivatives(&q).unwrap();
        for (k, dmk) in dm.iter().enumerate() {
            let fd = (m.crba(&with(&q, k, q[k] + eps)).unwrap() - m.crba(&with(&q, k, q[k] - eps)).unwrap()) / (2.0 * eps);
            assert!((fd - dmk).nan_amax() <= 1e-6 * (1.0 + h.nan_amax()), "∂M/∂q{k}");
        }
        let ad = m.aba_derivatives(&q, &v, &tau, None).unwrap();
        assert!((&ad.dvdot_dtau * &h - DMatrix::identity(4, 4)).nan_amax() <= 1e-10);
        assert!(ad.vdot.iter().zip(&vdot).all(|(a, b)| (a - b).abs() <= 1e-10));
        let mut s = m.derivative_scratch();
        let (mut ro, mut ao) = (RneaDerivatives::zeros(&m), AbaDerivatives::zeros(&m));
        m.rnea_derivatives_into(&q, &v, &vdot, None, &mut ro, &mut s);
        m.aba_derivatives_into(&q, &v, &tau, None, &mut ao, &mut s).unwrap();
        assert!((&ro.dtau_dv - &rd.dtau_dv).nan_amax() <= 1e-12 * (1.0 + rd.dtau_dv.nan_amax()));
        assert!((&ao.dvdot_dq - &ad.dvdot_dq).nan_amax() <= 1e-12 * (1.0 + ad.dvdot_dq.nan_amax()));
        for x in hostile() {
            for k in 0..4 {
                let all = |d: &RneaDerivatives| finite(&d.tau) && finite(d.dtau_dq.as_slice()) && finite(d.dtau_dv.as_slice()) && spd(&d.mass_matrix);
                err_or(m.rnea_derivatives(&with(&q, k, x), &v, &vdot, None), "rnea_derivatives(q)", all);
                err_or(m.rnea_derivatives(&q, &with(&v, k, x), &vdot, None), "rnea_derivatives(v)", all);
                err_or(m.rnea_derivatives(&q, &v, &with(&vdot, k, x), None), "rnea_derivatives(v̇)", all);
                let fwd = |d: &AbaDerivatives| {
                    finite(&d.vdot) && finite(d.dvdot_dq.as_slice()) && finite(d.dvdot_dv.as_slice()) && finite(d.dvdot_dtau.as_slice())
                };
                err_or(m.aba_derivatives(&with(&q, k, x), &v, &tau, None), "aba_derivatives(q)", fwd);
                err_or(m.aba_derivatives(&q, &with(&v, k, x), &tau, None), "aba_derivatives(v)", fwd);
                err_or(m.aba_derivatives(&q, &v, &with(&tau, k, x), None), "aba_derivatives(τ)", fwd);
                err_or(m.mass_matrix_derivatives(&with(&q, k, x)), "mass_matrix_derivatives", |d| d.iter().all(|x| finite(x.as_slice())));
            }
        }
        refused(m.rnea_derivatives(&q, &v, &vdot[1..], None), "rnea_derivatives(short v̇)");
        refused(m.aba_derivatives(&q[1..], &v, &tau, None), "aba_derivatives(short q)");
        refused(m.mass_matrix_derivatives(&[]), "mass_matrix_derivatives(empty q)");
    }

    // q ⊕ v dt (§4.11): plain coordinates move by v dt exactly, ball and free quaternions
    // stay unit; a non-finite dt or a step that overflows is refused.
    // The joints' motion maps the scene's right-hand side uses (issue 32 item 7): the
    // unchecked maps equal the checked calls on a valid state; wrong lengths, NaN and ∞ are
    // typed errors in the checked calls; huge speeds overflow into an error, never NaN in Ok;
    // q̇ is the derivative of `integrate`; quaternions normalize (a zero one is left alone).
    motion_maps ["Model::twists_into", "Model::bias_accelerations_into", "Model::bias_accelerations",
        "Model::qdot_into", "Model::normalize_quaternions", "Model::check_configuration",
        "normalize_quaternion", "Model::aba_checked"] {
        let m = tree();
        let (q, v) = state(&m);
        let (nq, nv) = (m.nq(), m.nv());
        let (mut world, mut poses) = (PosesScratch::default(), Vec::new());
        m.poses_into(&q, &mut world, &mut poses);
        let mut tw = Vec::new();
        m.twists_into(&world, &v, &mut MotionScratch::default(), &mut tw);
        let checked = m.twists(&q, &v).unwrap();
        assert_eq!(tw.len(), checked.len());
        for (a, b) in tw.iter().zip(&checked) {
            assert!((a.omega - b.omega).norm() <= 1e-12 * (1.0 + b.omega.norm()));
            assert!((a.velocity - b.velocity).norm() <= 1e-12 * (1.0 + b.velocity.norm()));
        }
        let mut acc = Vec::new();
        m.bias_accelerations_into(&world, &v, &mut MotionScratch::default(), &mut acc);
        let acc2 = m.bias_accelerations(&q, &v).unwrap();
        assert!(acc.iter().zip(&acc2).all(|(a, b)| a.alpha == b.alpha && a.acceleration == b.acceleration));
        assert!(m.bias_accelerations(&q[..nq - 1], &v).is_err() && m.bias_accelerations(&q, &v[..nv - 1]).is_err());
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut qb = q.clone();
            qb[0] = bad;
            assert!(m.check_configuration(&qb).is_err() && m.bias_accelerations(&qb, &v).is_err());
            let mut vb = v.clone();
            vb[0] = bad;
            assert!(m.bias_accelerations(&q, &vb).is_err());
        }
        match m.bias_accelerations(&q, &vec![1e200; nv]) {
            Ok(a) => assert!(a.iter().all(|x| finite(x.alpha.as_slice()) && finite(x.acceleration.as_slice()))),
            Err(DynamicsError::Overflow { .. }) => {}
            Err(e) => panic!("{e}"),
        }
        assert!(m.check_configuration(&q).is_ok() && m.check_configuration(&q[..nq - 1]).is_err());
        // q̇ is d/dh of q ⊕ v h at h = 0 (central difference, h = 1e-6: error O(h²))
        let mut qd = vec![0.0; nq];
        m.qdot_into(&q, &v, &mut qd);
        let h = 1e-6;
        let (qp, qm) = (m.integrate(&q, &v, h).unwrap(), m.integrate(&q, &v, -h).unwrap());
        for k in 0..nq {
            assert!(((qp[k] - qm[k]) / (2.0 * h) - qd[k]).abs() <= 1e-8, "q̇[{k}]");
        }
        let mut qs: Vec<f64> = q.iter().map(|x| 3.0 * x).collect();
        m.normalize_quaternions(&mut qs);
        assert!(m.check_configuration(&qs).is_ok());
        let mut zero = [0.0; 4];
        normalize_quaternion(&mut zero);
        assert_eq!(zero, [0.0; 4]);
        let mut e = [3.0, 0.0, 4.0, 0.0];
        normalize_quaternion(&mut e);
        assert_eq!(e, [0.6, 0.0, 0.8, 0.0]);
        // the checked ABA with a reused work space equals `aba`, and refuses what it refuses
        let tau: Vec<f64> = (0..nv).map(|k| (k as f64).cos()).collect();
        let (mut s, mut vd) = (m.aba_scratch(), vec![0.0; nv]);
        m.aba_checked(&q, &v, &tau, None, &mut vd, &mut s).unwrap();
        assert_eq!(vd, m.aba(&q, &v, &tau, None).unwrap());
        assert!(m.aba_checked(&q, &v, &tau, None, &mut vec![0.0; nv + 1], &mut s).is_err());
        let mut tb = tau.clone();
        tb[0] = f64::NAN;
        assert!(m.aba_checked(&q, &v, &tb, None, &mut vd, &mut s).is_err());
    }

    // a joint's own layout (Table 1.3) is the layout the model gives it: for every joint, even
    // with a zero or non-finite axis (which the model refuses), the counts are those of a model
    // built with a good axis, and the indices fall inside the coordinates
    joint_layout ["Joint::nq", "Joint::nv", "Joint::quaternion_index", "Joint::angle_index", "Joint::layout"] {
        let (x, y, z0, nan) = (Vector3::x(), Vector3::y(), Vector3::zeros(), Vector3::repeat(f64::NAN));
        for axis in [x, z0, nan] {
            let joints = [
                (Joint::Pin { axis }, Joint::Pin { axis: x }),
                (Joint::Sleeve { axis }, Joint::Sleeve { axis: x }),
                (Joint::Collar { axis }, Joint::Collar { axis: x }),
                (Joint::Slot { axis, direction: y }, Joint::Slot { axis: x, direction: y }),
                (Joint::Ball, Joint::Ball),
                (Joint::Weld, Joint::Weld),
                (Joint::Free, Joint::Free),
            ];
            for (j, good) in joints {
                let link = Link::new(None, good, Vector3::zeros(), 1.0, Vector3::zeros(), Matrix3::identity());
                let m = Model::new(&[link]).unwrap();
                assert_eq!((j.nq(), j.nv()), (m.nq(), m.nv()), "{j:?}");
                assert!(j.quaternion_index().is_none_or(|k| k + 4 <= j.nq()), "{j:?}");
                assert!(j.angle_index().is_none_or(|k| k < j.nv()), "{j:?}");
                let (lq, lv) = j.layout();
                assert!(lq.starts_with("q = [") && lv.starts_with("v = ["), "{j:?}");
                // a bad axis is refused by the model, not by the layout queries
                if axis != x && !matches!(j, Joint::Ball | Joint::Weld | Joint::Free) {
                    let bad = Link::new(None, j, Vector3::zeros(), 1.0, Vector3::zeros(), Matrix3::identity());
                    assert!(Model::new(&[bad]).is_err(), "{j:?}");
                }
            }
        }
    }

    // the compiled q̇ map gives exactly what `qdot_into` gives, on the test tree (pin, slot, ball)
    // and on a free body carrying a collar (runs of 3 and 2 copies, a quaternion), on NaN and huge
    // entries too (they pass through as the unplanned map passes them; the checked calls refuse them)
    qdot_plan ["Model::qdot_plan", "QdotPlan::apply"] {
        let free = Model::new(&[
            Link::new(None, Joint::Free, Vector3::zeros(), 1.0, Vector3::zeros(), Matrix3::identity()),
            Link::new(Some(0), Joint::Collar { axis: Vector3::z() }, Vector3::x(), 1.0, Vector3::zeros(), Matrix3::identity()),
        ])
        .unwrap();
        for m in [free, tree()] {
        let m = &m;
        let (q, v) = state(m);
        let plan = m.qdot_plan();
        let (mut a, mut b) = (vec![0.0; m.nq()], vec![0.0; m.nq()]);
        m.qdot_into(&q, &v, &mut a);
        plan.apply(&q, &v, &mut b);
        assert_eq!(a, b);
        for bad in [f64::NAN, f64::INFINITY, 1e300] {
            let (mut qb, mut vb) = (q.clone(), v.clone());
            qb[1] = bad;
            vb[0] = bad;
            m.qdot_into(&qb, &vb, &mut a);
            plan.apply(&qb, &vb, &mut b);
            assert_eq!(format!("{a:?}"), format!("{b:?}"));
            assert!(m.check_configuration(&qb).is_err() || bad.is_finite());
        }
        // longer buffers are fine (only the model's coordinates are written)
        let mut long = vec![7.0; m.nq() + 2];
        plan.apply(&q, &v, &mut long);
        m.qdot_into(&q, &v, &mut a);
        assert_eq!(&long[..m.nq()], &a[..]);
        assert_eq!(&long[m.nq()..], &[7.0, 7.0]);
        }
    }

    configuration_step ["Model::integrate"] {
        let m = tree();
        let (q, v) = state(&m);
        let unit = |q: &[f64]| {
            let n = |a: &[f64]| a.iter().map(|x| x * x).sum::<f64>().sqrt();
            (n(&q[1..5]) - 1.0).abs() <= 1e-12 && (n(&q[13..17]) - 1.0).abs() <= 1e-12
        };
        for dt in hostile() {
            err_or(m.integrate(&q, &v, dt), "integrate(dt)", |out| {
                finite(out) && unit(out) && (out[0] - (q[0] + v[0] * dt)).abs() <= 4.0 * f64::EPSILON * (q[0].abs() + (v[0] * dt).abs())
            });
            for k in 0..m.nv() {
                err_or(m.integrate(&q, &with(&v, k, dt), 1.0), "integrate(v)", |out| finite(out) && unit(out));
            }
            for k in 0..m.nq() {
                err_or(m.integrate(&with(&q, k, dt), &v, 0.1), "integrate(q)", |out| finite(out) && unit(out));
            }
        }
        refused(m.integrate(&q, &v, f64::NAN), "integrate(NaN dt)");
        refused(m.integrate(&q, &v[1..], 1.0), "integrate(short v)");
        // v dt overflows: 1e300 × 1e300
        refused(m.integrate(&q, &with(&v, 0, 1e300), 1e300), "integrate(overflowing step)");
    }

    // Lagrange's equations (§9.3–9.9) for the cart pendulum, every term against its closed
    // form: M, p = Mq̇, E = ½q̇ᵀMq̇ + U, Ė = Fẋ − cẋ², M q̈ = f; a free particle exercises the
    // defaults (U = R = 0, no force: Ė = 0). Hostile parameters and states: Err or the law.
    lagrange ["Lagrangian::dof", "Lagrangian::kinetic", "Lagrangian::potential", "Lagrangian::rayleigh",
        "Lagrangian::generalized_force", "mass_matrix", "lagrange_terms", "LagrangeTerms::rhs", "accelerations",
        "generalized_momentum", "energy", "energy_rate"] {
        let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= REL * scale.max(f64::MIN_POSITIVE);
        let check = |sys: &CartPendulum, q: &[f64], qd: &[f64]| {
            let mm = sys.m(q[1]);
            let qdv = DVector::from_column_slice(qd);
            let scale_m = mm.nan_amax();
            err_or(mass_matrix(sys, q, qd, 0.0), "mass_matrix", |m| finite(m.as_slice()) && (m - &mm).nan_amax() <= REL * scale_m);
            err_or(generalized_momentum(sys, q, qd, 0.0), "generalized_momentum", |p| {
                let want = &mm * &qdv;
                finite(p.as_slice()) && (p - &want).nan_amax() <= REL * scale_m * qdv.nan_amax()
            });
            err_or(energy(sys, q, qd, 0.0), "energy", |e| {
                let t = 0.5 * qdv.dot(&(&mm * &qdv));
                let u = -sys.m2 * sys.g * sys.l * q[1].cos();
                e.is_finite() && close(*e, t + u, t.abs() + u.abs())
            });
            err_or(energy_rate(sys, q, qd, 0.0), "energy_rate", |e| {
                let want = sys.f * qd[0] - sys.c * qd[0] * qd[0];
                e.is_finite() && close(*e, want, (sys.f * qd[0]).abs() + (sys.c * qd[0] * qd[0]).abs())
            });
            err_or(lagrange_terms(sys, q, qd, 0.0), "lagrange_terms", |t| {
                let r = t.rhs();
                let want = sys.rhs(q, qd);
                finite(r.as_slice()) && (&r - &want).nan_amax() <= REL * (want.nan_amax() + scale_m * qdv.nan_amax() * qdv.nan_amax() + sys.f.abs())
            });
            err_or(accelerations(sys, q, qd, 0.0), "accelerations", |a| {
                let res = &mm * a - sys.rhs(q, qd);
                finite(a.as_slice()) && res.nan_amax() <= REL * (scale_m * a.nan_amax() + sys.rhs(q, qd).nan_amax() + scale_m * qdv.nan_amax() * qdv.nan_amax())
            });
        };
        let (q, qd) = ([0.3, 0.7], [-0.4, 1.1]);
        check(&CART, &q, &qd);
        assert!(accelerations(&CART, &q, &qd, 0.0).is_ok());
        for x in hostile() {
            for sys in [
                CartPendulum { m1: x, ..CART },
                CartPendulum { m2: x, ..CART },
                CartPendulum { l: x, ..CART },
                CartPendulum { g: x, ..CART },
                CartPendulum { c: x, ..CART },
                CartPendulum { f: x, ..CART },
            ] {
                check(&sys, &q, &qd);
            }
            for k in 0..2 {
                check(&CART, &with(&q, k, x), &qd);
                check(&CART, &q, &with(&qd, k, x));
            }
            if !x.is_finite() {
                refused(accelerations(&CART, &q, &qd, x), "accelerations(t = ±∞, NaN)");
            }
            let free = FreeParticle(x);
            err_or(energy_rate(&free, &q, &qd, 0.0), "energy_rate(defaults)", |e| *e == 0.0);
            err_or(energy(&free, &q, &qd, 0.0), "energy(defaults)", |e| e.is_finite() && close(*e, 0.5 * x * (qd[0] * qd[0] + qd[1] * qd[1]), e.abs()));
            err_or(accelerations(&free, &q, &qd, 0.0), "accelerations(free)", |a| a.nan_amax() == 0.0);
        }
        refused(accelerations(&CART, &q[..1], &qd, 0.0), "accelerations(short q)");
        refused(mass_matrix(&CART, &q, &[], 0.0), "mass_matrix(empty q̇)");
        // a massless cart and bob: M = 0 is singular
        refused(accelerations(&CartPendulum { m1: 0.0, m2: 0.0, ..CART }, &q, &qd, 0.0), "M = 0");
        assert_eq!(Lagrangian::dof(&CART), 2);
    }

    // Hamilton's equations (§9.13): Mq̇ = p, H = ½pᵀM⁻¹p + U, ṗ = (F − cẋ, −m₂lẋθ̇ sinθ −
    // m₂gl sinθ) in closed form. Hostile p and parameters: Err or the law.
    hamilton ["velocities_from_momenta", "hamiltonian", "hamilton_rhs"] {
        let q = [0.3, 0.7];
        let check = |sys: &CartPendulum, q: &[f64], p: &[f64]| {
            let mm = sys.m(q[1]);
            let pv = DVector::from_column_slice(p);
            err_or(velocities_from_momenta(sys, q, p, 0.0), "velocities_from_momenta", |qd| {
                finite(qd.as_slice()) && (&mm * qd - &pv).nan_amax() <= REL * (pv.nan_amax() + mm.nan_amax() * qd.nan_amax())
            });
            err_or(hamiltonian(sys, q, p, 0.0), "hamiltonian", |h| {
                let Ok(qd) = velocities_from_momenta(sys, q, p, 0.0) else { return false };
                let t = 0.5 * pv.dot(&qd);
                let u = -sys.m2 * sys.g * sys.l * q[1].cos();
                h.is_finite() && (h - t - u).abs() <= REL * (t.abs() + u.abs()).max(f64::MIN_POSITIVE)
            });
            err_or(hamilton_rhs(sys, q, p, 0.0), "hamilton_rhs", |(qd, pd)| {
                let (s, m2l) = (q[1].sin(), sys.m2 * sys.l);
                let want = [sys.f - sys.c * qd[0], -m2l * qd[0] * qd[1] * s - m2l * sys.g * s];
                let scale = sys.f.abs() + (sys.c * qd[0]).abs() + (m2l * qd[0] * qd[1]).abs() + (m2l * sys.g).abs();
                finite(qd.as_slice()) && finite(pd.as_slice()) && (pd[0] - want[0]).abs() <= REL * scale && (pd[1] - want[1]).abs() <= REL * scale
            });
        };
        check(&CART, &q, &[1.0, -0.5]);
        for x in hostile() {
            for k in 0..2 {
                check(&CART, &q, &with(&[1.0, -0.5], k, x));
                check(&CART, &with(&q, k, x), &[1.0, -0.5]);
            }
            check(&CartPendulum { m2: x, ..CART }, &q, &[1.0, -0.5]);
            check(&CartPendulum { l: x, ..CART }, &q, &[1.0, -0.5]);
        }
        refused(hamiltonian(&CART, &q, &[1.0], 0.0), "hamiltonian(short p)");
        refused(velocities_from_momenta(&CartPendulum { m1: 0.0, m2: 0.0, ..CART }, &q, &[1.0, 0.0], 0.0), "M = 0");
    }

    // The same cart pendulum as particles (§9.3): M and f against the closed form (no
    // dashpot), T = ½q̇ᵀMq̇, M q̈ = f; a list of masses of the wrong length is refused.
    kinematic_map ["KinematicMap::dof", "KinematicMap::masses", "KinematicMap::particles", "KinematicMap::bodies",
        "KinematicMap::potential", "KinematicMap::generalized_force", "map_equations", "map_mass_matrix",
        "map_kinetic_energy", "map_accelerations"] {
        let check = |sys: &CartPendulum, q: &[f64], qd: &[f64]| {
            let sys = CartPendulum { c: 0.0, ..*sys };
            let mm = sys.m(q[1]);
            let qdv = DVector::from_column_slice(qd);
            let scale = mm.nan_amax() * (1.0 + qdv.nan_amax() * qdv.nan_amax()) + sys.f.abs() + (sys.m2 * sys.g * sys.l).abs();
            err_or(map_mass_matrix(&sys, q, 0.0), "map_mass_matrix", |m| finite(m.as_slice()) && (m - &mm).nan_amax() <= REL * mm.nan_amax());
            err_or(map_equations(&sys, q, qd, 0.0), "map_equations", |(m, f)| {
                finite(f.as_slice()) && (m - &mm).nan_amax() <= REL * mm.nan_amax() && (f - sys.rhs(q, qd)).nan_amax() <= REL * scale
            });
            err_or(map_kinetic_energy(&sys, q, qd, 0.0), "map_kinetic_energy", |t| {
                let want = 0.5 * qdv.dot(&(&mm * &qdv));
                t.is_finite() && (t - want).abs() <= REL * want.abs().max(f64::MIN_POSITIVE)
            });
            err_or(map_accelerations(&sys, q, qd, 0.0), "map_accelerations", |a| {
                finite(a.as_slice()) && (&mm * a - sys.rhs(q, qd)).nan_amax() <= REL * (scale + mm.nan_amax() * a.nan_amax())
            });
        };
        let (q, qd) = ([0.3, 0.7], [-0.4, 1.1]);
        check(&CART, &q, &qd);
        assert!(map_accelerations(&CART, &q, &qd, 0.0).is_ok());
        for x in hostile() {
            check(&CartPendulum { m1: x, ..CART }, &q, &qd);
            check(&CartPendulum { l: x, ..CART }, &q, &qd);
            check(&CartPendulum { f: x, ..CART }, &q, &qd);
            for k in 0..2 {
                check(&CART, &with(&q, k, x), &qd);
                check(&CART, &q, &with(&qd, k, x));
            }
        }
        // one mass for two particles
        struct Short;
        impl KinematicMap for Short {
            fn dof(&self) -> usize {
                1
            }
            fn masses(&self) -> MapMasses {
                MapMasses { particles: vec![1.0], bodies: vec![(1.0, Matrix3::identity())] }
            }
            fn particles<T: Scalar>(&self, q: &[T], _t: T) -> Vec<Vector<T>> {
                let a = Frame::<T>::identity();
                vec![a.vector([q[0], T::zero(), T::zero()]), a.vector([T::zero(), q[0], T::zero()])]
            }
        }
        refused(map_mass_matrix(&Short, &[0.0], 0.0), "masses of the wrong length");
        refused(map_accelerations(&CART, &q, &qd[..1], 0.0), "map_accelerations(short q̇)");
        assert_eq!(KinematicMap::dof(&CART), 2);
        assert_eq!(CART.masses().particles.len(), 2);
        assert!(KinematicMap::bodies(&CART, &q, 0.0).is_empty() && CART.particles(&q, 0.0).len() == 2);
        let mut out = [0.0; 2];
        KinematicMap::generalized_force(&CART, &q, &qd, 0.0, &mut out);
        assert_eq!(out, [CART.f, 0.0]);
        assert_eq!(KinematicMap::potential(&Short, &[1.0], 0.0), 0.0);
        KinematicMap::generalized_force(&Short, &[1.0], &[1.0], 0.0, &mut out[..1]);
    }

    // Constraints (§9.11–9.12) of the Cartesian pendulum: G, γ, φ, φ̇ against their closed
    // forms; the constrained accelerations satisfy G q̈ = γ with q̈ + gŷ along r (the rod's
    // force is central), by the Lagrange, map and hand-written forms alike.
    constrained_dynamics ["Constraints::constraint_count", "Constraints::constraints",
        "Constraints::velocity_constraint_count", "Constraints::velocity_constraints", "ConstrainedSystem::dof",
        "ConstrainedSystem::equations", "ConstrainedSystem::mass", "constraint_terms", "solve_constrained",
        "constrained_accelerations", "map_constrained_accelerations", "constraint_violation"] {
        let p = Pendulum { m: 1.5, l: 2.0, g: 9.81, k: None };
        let check = |p: &Pendulum, q: &[f64], qd: &[f64]| {
            let scale = 1.0 + q[0].abs().max(q[1].abs()).powi(2) + qd[0].abs().max(qd[1].abs()).powi(2) + p.l * p.l;
            err_or(constraint_terms(p, q, qd, 0.0), "constraint_terms", |t| {
                let want = [2.0 * q[0], 2.0 * q[1]];
                let gamma = -2.0 * (qd[0] * qd[0] + qd[1] * qd[1]);
                finite(t.jacobian.as_slice())
                    && (t.jacobian[(0, 0)] - want[0]).abs() <= REL * scale
                    && (t.jacobian[(0, 1)] - want[1]).abs() <= REL * scale
                    && (t.gamma[0] - gamma).abs() <= REL * scale
                    && (t.position[0] - (q[0] * q[0] + q[1] * q[1] - p.l * p.l)).abs() <= REL * scale
            });
            err_or(constraint_violation(p, q, qd, 0.0), "constraint_violation", |v| {
                v.position.is_finite() && (v.position - (q[0] * q[0] + q[1] * q[1] - p.l * p.l).abs()).abs() <= REL * scale
                    && (v.velocity - (2.0 * (q[0] * qd[0] + q[1] * qd[1])).abs()).abs() <= REL * scale
            });
            let central = |a: &DVector<f64>| {
                // G q̈ = γ and (q̈ + gŷ) × r = 0
                let g_qdd = 2.0 * (q[0] * a[0] + q[1] * a[1]);
                let gamma = -2.0 * (qd[0] * qd[0] + qd[1] * qd[1]);
                let s2 = scale * (1.0 + a.nan_amax() + p.g.abs());
                finite(a.as_slice()) && (g_qdd - gamma).abs() <= REL * s2 && (a[0] * q[1] - (a[1] + p.g) * q[0]).abs() <= REL * s2
            };
            err_or(constrained_accelerations(p, q, qd, 0.0), "constrained_accelerations", |s| central(&s.qdd) && finite(s.lambda.as_slice()));
            err_or(map_constrained_accelerations(p, q, qd, 0.0), "map_constrained_accelerations", |s| central(&s.qdd));
            err_or(solve_constrained(&Direct(*p), q, qd, 0.0), "solve_constrained(Direct)", |s| central(&s.qdd));
        };
        let (q, qd) = on_circle(2.0, 0.6, -0.8);
        check(&p, &q, &qd);
        assert!(constrained_accelerations(&p, &q, &qd, 0.0).is_ok());
        for x in hostile() {
            check(&Pendulum { m: x, ..p }, &q, &qd);
            check(&Pendulum { g: x, ..p }, &q, &qd);
            check(&Pendulum { l: x, ..p }, &q, &qd);
            for k in 0..2 {
                check(&p, &with(&q, k, x), &qd);
                check(&p, &q, &with(&qd, k, x));
            }
            // the velocity row ẋ + kẏ = 0 with hostile k: G q̈ = γ on both rows
            let pk = Pendulum { k: Some(x), ..p };
            err_or(constrained_accelerations(&pk, &q, &qd, 0.0), "constrained_accelerations(ψ)", |s| {
                finite(s.qdd.as_slice()) && (s.qdd[0] + x * s.qdd[1]).abs() <= REL * (1.0 + x.abs()) * (1.0 + s.qdd.nan_amax())
            });
        }
        // two rows through one point of a 2-dof system leave nothing: the second row (ẋ = 0)
        // with the pendulum at the bottom is the first's gradient direction ⇒ dependent
        refused(constrained_accelerations(&Pendulum { k: Some(0.0), ..p }, &[2.0, 0.0], &[0.0, 0.0], 0.0), "dependent rows");
        refused(constraint_terms(&p, &q, &qd[..1], 0.0), "constraint_terms(short q̇)");
        refused(solve_constrained(&LagrangeForm(&p), &q[..1], &qd[..1], 0.0), "solve_constrained(short q)");
        let d = Direct(p);
        assert_eq!(ConstrainedSystem::dof(&d), 2);
        assert_eq!(d.mass(&q, 0.0).unwrap(), DMatrix::identity(2, 2) * 1.5);
        let (mm, f) = d.equations(&q, &qd, 0.0).unwrap();
        assert!(mm[(0, 0)] == 1.5 && f[1] == -1.5 * 9.81);
        let lf = LagrangeForm(&p);
        assert!((lf.mass(&q, 0.0).unwrap() - DMatrix::identity(2, 2) * 1.5).nan_amax() <= 1e-15);
        assert!(MapForm(&p).equations(&q, &qd, 0.0).is_ok_and(|(m, _)| (m - DMatrix::identity(2, 2) * 1.5).nan_amax() <= 1e-15));
        assert_eq!((ConstrainedSystem::dof(&lf), lf.constraint_count(), lf.velocity_constraint_count()), (2, 1, 0));
        let mut out = [0.0];
        p.velocity_constraints(&q, &qd, 0.0, &mut out);
        FreeParticle(1.0).constraints(&q, 0.0, &mut []);
        FreeParticle(1.0).velocity_constraints(&q, &qd, 0.0, &mut []);
        assert_eq!((FreeParticle(1.0).constraint_count(), FreeParticle(1.0).velocity_constraint_count()), (0, 0));
        // no constraints: the unconstrained accelerations
        assert!(constrained_accelerations(&FreeParticle(2.0), &q, &qd, 0.0).is_ok_and(|s| s.qdd.nan_amax() == 0.0 && s.lambda.is_empty()));
    }

    // The KKT core (§9.11) on plain matrices: M x + Gᵀλ = f and G x = γ (residuals checked),
    // or a typed error for a non-SPD M, a zero or dependent row, sizes that disagree, a rank
    // tolerance outside (0, 1) and non-finite entries.
    kkt ["KktFactor::new", "KktFactor::rows", "KktFactor::solve", "solve_kkt"] {
        let m = DMatrix::from_row_slice(3, 3, &[4.0, 1.0, 0.0, 1.0, 3.0, 0.5, 0.0, 0.5, 2.0]);
        let g = DMatrix::from_row_slice(2, 3, &[1.0, 0.0, 1.0, 0.0, 1.0, -1.0]);
        let (f, gamma) = (DVector::from_vec(vec![1.0, -2.0, 0.5]), DVector::from_vec(vec![0.3, -0.1]));
        let solves = |m: &DMatrix<f64>, g: &DMatrix<f64>, f: &DVector<f64>, gamma: &DVector<f64>, x: &DVector<f64>, l: &DVector<f64>| {
            let scale = (m.nan_amax() * x.nan_amax()).max(g.nan_amax() * l.nan_amax()).max(f.nan_amax()).max(gamma.nan_amax()).max(f64::MIN_POSITIVE);
            finite(x.as_slice()) && finite(l.as_slice()) && (m * x + g.transpose() * l - f).nan_amax() <= REL * scale && (g * x - gamma).nan_amax() <= REL * scale
        };
        let k = KktFactor::new(&m, &g, DEPENDENT_ROW_REL_TOL).unwrap();
        assert_eq!(k.rows(), 2);
        let s = k.solve(&f, &gamma).unwrap();
        assert!(solves(&m, &g, &f, &gamma, &s.x, &s.lambda));
        for x in hostile() {
            for (i, j) in [(0, 0), (1, 2), (2, 2)] {
                let mut mx = m.clone();
                mx[(i, j)] = x;
                mx[(j, i)] = x;
                err_or(solve_kkt(&mx, &g, &f, &gamma, DEPENDENT_ROW_REL_TOL), "solve_kkt(M)", |s| solves(&mx, &g, &f, &gamma, &s.x, &s.lambda));
                let mut gx = g.clone();
                gx[(i.min(1), j)] = x;
                err_or(solve_kkt(&m, &gx, &f, &gamma, DEPENDENT_ROW_REL_TOL), "solve_kkt(G)", |s| solves(&m, &gx, &f, &gamma, &s.x, &s.lambda));
                let mut fx = f.clone();
                fx[i] = x;
                err_or(k.solve(&fx, &gamma), "KktFactor::solve(f)", |s| solves(&m, &g, &fx, &gamma, &s.x, &s.lambda));
                let mut gmx = gamma.clone();
                gmx[i.min(1)] = x;
                err_or(k.solve(&f, &gmx), "KktFactor::solve(γ)", |s| solves(&m, &g, &f, &gmx, &s.x, &s.lambda));
            }
            err_or(KktFactor::new(&m, &g, x), "KktFactor::new(rank_tol)", |k| k.rows() == 2 && x > 0.0 && x < 1.0);
            err_or(KktFactor::new(&(&m * x), &g, DEPENDENT_ROW_REL_TOL), "KktFactor::new(xM)", |_| x > 0.0 && x.is_finite());
        }
        refused(KktFactor::new(&m, &DMatrix::from_row_slice(2, 3, &[1.0, 0.0, 1.0, 2.0, 0.0, 2.0]), DEPENDENT_ROW_REL_TOL), "dependent rows");
        refused(KktFactor::new(&m, &DMatrix::zeros(1, 3), DEPENDENT_ROW_REL_TOL), "zero row");
        refused(KktFactor::new(&m, &DMatrix::zeros(4, 3).add_scalar(1.0), DEPENDENT_ROW_REL_TOL), "more rows than columns");
        refused(KktFactor::new(&m, &DMatrix::zeros(1, 2), DEPENDENT_ROW_REL_TOL), "G of the wrong width");
        refused(KktFactor::new(&DMatrix::zeros(3, 2), &g, DEPENDENT_ROW_REL_TOL), "M not square");
        refused(KktFactor::new(&-&m, &g, DEPENDENT_ROW_REL_TOL), "M negative definite");
        refused(k.solve(&DVector::zeros(2), &gamma), "solve(short f)");
        refused(k.solve(&f, &DVector::zeros(0)), "solve(empty γ)");
        // no rows: x = M⁻¹f
        let free = KktFactor::new(&m, &DMatrix::zeros(0, 3), DEPENDENT_ROW_REL_TOL).unwrap();
        assert!(free.rows() == 0 && (&m * free.solve(&f, &DVector::zeros(0)).unwrap().x - &f).nan_amax() <= 1e-14);
        let empty = KktFactor::new(&DMatrix::zeros(0, 0), &DMatrix::zeros(0, 0), DEPENDENT_ROW_REL_TOL);
        err_or(empty, "KktFactor::new(0×0)", |k| k.rows() == 0);
    }

    // Projections (§9.11): onto |r| = l from hostile starts, |φ(q)| ≤ tol checked on the
    // returned q; velocities onto G v + c = 0 (the residual checked); options outside their
    // ranges refused.
    projections ["project_positions", "project_velocities"] {
        let l = 2.0;
        let phi = |q: &[f64]| q[0] * q[0] + q[1] * q[1] - l * l;
        let cons = |q: &[f64]| -> Result<(DVector<f64>, DMatrix<f64>), DynamicsError> {
            Ok((DVector::from_vec(vec![phi(q)]), DMatrix::from_row_slice(1, 2, &[2.0 * q[0], 2.0 * q[1]])))
        };
        let retract = |q: &[f64], d: &DVector<f64>| -> Result<Vec<f64>, DynamicsError> { Ok(vec![q[0] + d[0], q[1] + d[1]]) };
        let opts = ProjectionOptions::default();
        let m = DMatrix::identity(2, 2);
        let p = project_positions(&[1.5, -1.0], &m, cons, retract, &opts).unwrap();
        assert!(phi(&p.q).abs() <= opts.tol && p.violation <= opts.tol && p.initial > 0.0);
        for x in hostile() {
            for q0 in [[x, -1.0], [1.0, x], [x, x]] {
                err_or(project_positions(&q0, &m, cons, retract, &opts), "project_positions(q)", |p| finite(&p.q) && phi(&p.q).abs() <= opts.tol);
            }
            for o in [ProjectionOptions { tol: x, ..opts }, ProjectionOptions { rank_tol: x, ..opts }] {
                err_or(project_positions(&[1.5, -1.0], &m, cons, retract, &o), "project_positions(options)", |p| finite(&p.q) && phi(&p.q).abs() <= o.tol);
            }
            err_or(project_positions(&[1.5, -1.0], &(&m * x), cons, retract, &opts), "project_positions(M)", |p| phi(&p.q).abs() <= opts.tol);
            let g = DMatrix::from_row_slice(1, 2, &[1.0, x]);
            for c in [0.5, x] {
                let (v, c) = (DVector::from_vec(vec![0.3, -0.7]), DVector::from_vec(vec![c]));
                let r = &g * &v + &c;
                err_or(project_velocities(&v, &m, &g, &r, DEPENDENT_ROW_REL_TOL), "project_velocities", |w| {
                    let res = (&g * w + &c)[0];
                    finite(w.as_slice()) && res.abs() <= REL * (1.0 + g.nan_amax() * w.nan_amax() + c.nan_amax())
                });
            }
        }
        for it in [0, 101, usize::MAX] {
            refused(project_positions(&[1.5, -1.0], &m, cons, retract, &ProjectionOptions { max_iterations: it, ..opts }), "max_iterations");
        }
        // no point of the plane is on |r| = −1: Gauss–Newton cannot get there
        let bad = |q: &[f64]| -> Result<(DVector<f64>, DMatrix<f64>), DynamicsError> {
            Ok((DVector::from_vec(vec![q[0] * q[0] + q[1] * q[1] + 1.0]), DMatrix::from_row_slice(1, 2, &[2.0 * q[0], 2.0 * q[1]])))
        };
        refused(project_positions(&[1.0, 1.0], &m, bad, retract, &opts), "unreachable manifold");
        refused(project_velocities(&DVector::zeros(3), &m, &DMatrix::zeros(1, 2).add_scalar(1.0), &DVector::zeros(1), DEPENDENT_ROW_REL_TOL), "v of the wrong length");
    }

    // The projected integrator (§9.11): every recorded state and every dense sample is on
    // |r| = l (|φ| ≤ tol, checked on q directly; samples within the reported drift); hostile
    // times, tolerances and initial states are refused or keep the law.
    constrained_integration ["ConstrainedIntegrator::new", "ConstrainedIntegrator::integrate", "ConstrainedRun::q",
        "ConstrainedRun::qd", "ConstrainedRun::sample"] {
        let p = Pendulum { m: 1.0, l: 1.0, g: 9.81, k: None };
        // a step budget: t₁ = 1e300 is then TooManySteps after 5000 steps, not 10⁶ (seconds, not
        // minutes, on CI's two cores)
        let solver = Adaptive::dopri5().rtol(1e-8).atol(1e-8).max_steps(5000);
        let base = ConstrainedIntegrator { dense: true, ..ConstrainedIntegrator::new(solver) };
        let (q0, qd0) = on_circle(1.0, 0.5, 0.0);
        let on = |run: &vectrix::dynamics::constraints::ConstrainedRun| {
            (0..run.t.len()).all(|i| {
                let (q, qd) = (run.q(i), run.qd(i));
                finite(q) && finite(qd) && (q[0] * q[0] + q[1] * q[1] - 1.0).abs() <= 2.0 * base.projection.tol + 1e-15
                    && (q[0] * qd[0] + q[1] * qd[1]).abs() <= 1e-9
            })
        };
        let run = base.integrate(&LagrangeForm(&p), &q0, &qd0, 0.0, 1.0).unwrap();
        assert!(on(&run) && run.t.len() > 2);
        let drift = run.max_drift.position;
        for t in [0.0, 0.25, 0.5, 1.0] {
            let y = run.sample(t).unwrap();
            // inside a step the interpolant is as accurate as the integrator (rtol = 1e-8)
            assert!((y[0] * y[0] + y[1] * y[1] - 1.0).abs() <= 2.0 * drift + 1e-7, "sample at {t}: {y:?}, drift {drift:e}");
        }
        for x in hostile() {
            err_or(run.sample(x), "sample(t)", |y| (0.0..=1.0).contains(&x) && finite(y.as_slice()));
            err_or(base.integrate(&LagrangeForm(&p), &q0, &qd0, 0.0, x), "integrate(t1)", |r| on(r));
            err_or(base.integrate(&LagrangeForm(&p), &q0, &qd0, x, 0.5), "integrate(t0)", |r| on(r));
            err_or(ConstrainedIntegrator { initial_tol: x, ..base }.integrate(&LagrangeForm(&p), &q0, &qd0, 0.0, 0.2), "integrate(initial_tol)", |r| on(r));
            err_or(ConstrainedIntegrator { project_initial: true, ..base }.integrate(&LagrangeForm(&p), &[x, -1.0], &qd0, 0.0, 0.2), "integrate(q₀)", |r| on(r));
            err_or(ConstrainedIntegrator { project_initial: true, ..base }.integrate(&LagrangeForm(&p), &q0, &[x, 0.0], 0.0, 0.2), "integrate(q̇₀)", |r| on(r));
            err_or(ConstrainedIntegrator { projection: ProjectionOptions { tol: x, ..base.projection }, ..base }.integrate(&LagrangeForm(&p), &q0, &qd0, 0.0, 0.2), "integrate(projection tol)", |r| r.t.len() >= 2);
        }
        let plain = ConstrainedIntegrator::new(Adaptive::dopri5());
        refused(plain.integrate(&LagrangeForm(&p), &q0, &qd0, 0.0, 0.1).and_then(|r| r.sample(0.05)), "sample without dense output");
        refused(base.integrate(&LagrangeForm(&p), &q0[..1], &qd0, 0.0, 0.1), "integrate(short q₀)");
        refused(base.integrate(&LagrangeForm(&p), &[0.0, -1.1], &[0.0, 0.0], 0.0, 0.1), "inconsistent start");
    }

    // Kane's equations (§9.14): the block on an incline has ẍ = −g s/(1 + s²), ẏ = s ẋ
    // (the dependent speed), the flywheel θ̈ = τ/J; partial velocities are the unit
    // directions; a drifting particle (every default) has u̇ = 0.
    kane ["KaneSystem::coordinates", "KaneSystem::speeds", "KaneSystem::masses", "KaneSystem::kinematic_equations",
        "KaneSystem::particle_velocities", "KaneSystem::body_motions", "KaneSystem::loads",
        "KaneSystem::speed_constraint_count", "KaneSystem::speed_constraints", "constraints::kane::partial_velocities",
        "kane_accelerations", "kane_state_derivative"] {
        let sys = Incline { m: 2.0, s: 0.5, g: 9.81, j: 0.3, tau: 0.6 };
        let law = |sys: &Incline, u_i: &[f64], s: &vectrix::dynamics::constraints::kane::KaneSolution| {
            let xdd = -sys.g * sys.s / (1.0 + sys.s * sys.s);
            let scale = sys.g.abs() + (sys.tau / sys.j).abs();
            finite(s.ud.as_slice()) && finite(s.u.as_slice())
                && (s.u[2] - sys.s * u_i[0]).abs() <= REL * (sys.s * u_i[0]).abs().max(f64::MIN_POSITIVE)
                && (s.ud[0] - xdd).abs() <= REL * scale
                && (s.ud[1] - sys.tau / sys.j).abs() <= REL * scale
                && (s.ud[2] - sys.s * s.ud[0]).abs() <= REL * scale * (1.0 + sys.s.abs())
        };
        let (q, u_i) = ([0.1, 0.2, 0.05], [0.7, -0.3]);
        let s = kane_accelerations(&sys, &q, &u_i, 0.0).unwrap();
        assert!(law(&sys, &u_i, &s));
        for x in hostile() {
            for sx in [Incline { m: x, ..sys }, Incline { s: x, ..sys }, Incline { g: x, ..sys }, Incline { j: x, ..sys }, Incline { tau: x, ..sys }] {
                err_or(kane_accelerations(&sx, &q, &u_i, 0.0), "kane_accelerations(parameters)", |s| law(&sx, &u_i, s));
            }
            for k in 0..2 {
                let ux = with(&u_i, k, x);
                err_or(kane_accelerations(&sys, &q, &ux, 0.0), "kane_accelerations(u)", |s| law(&sys, &ux, s));
            }
            err_or(kane_accelerations(&sys, &with(&q, 0, x), &u_i, 0.0), "kane_accelerations(q)", |s| law(&sys, &u_i, s));
            err_or(partial_velocities(&sys, &q, &[x, 0.0, x], 0.0), "partial_velocities", |pv| {
                pv.particles[0][0] == Vector3::x() && pv.particles[2][0] == Vector3::y() && pv.bodies[1][0].1 == Vector3::z()
            });
            err_or(kane_state_derivative(&sys, x, &[0.1, 0.2, 0.05, 0.7, -0.3]), "kane_state_derivative(t)", |y| finite(y) && y.len() == 5);
            err_or(kane_accelerations(&Drifting(x), &q[..2], &u_i, 0.0), "kane_accelerations(defaults)", |s| s.ud.nan_amax() == 0.0);
        }
        let y = kane_state_derivative(&sys, 0.0, &[0.1, 0.2, 0.05, 0.7, -0.3]).unwrap();
        assert!((y[0] - 0.7).abs() <= 1e-15 && (y[2] - 0.35).abs() <= 1e-15 && law(&sys, &u_i, &s) && (y[3] - s.ud[0]).abs() <= 1e-12);
        refused(kane_state_derivative(&sys, 0.0, &[0.0; 6]), "kane_state_derivative(long y)");
        refused(kane_accelerations(&sys, &q, &[0.0; 3], 0.0), "kane_accelerations(all speeds given)");
        refused(partial_velocities(&sys, &q, &[0.0], 0.0), "partial_velocities(short u)");
        assert_eq!((sys.coordinates(), sys.speeds(), sys.speed_constraint_count(), Drifting(1.0).speed_constraint_count()), (3, 3, 1, 0));
        assert!(sys.masses().bodies.len() == 1 && Drifting(1.0).body_motions(&[0.0; 2], &[0.0; 2], 0.0).is_empty());
        assert!(Drifting(1.0).loads(&[0.0; 2], &[0.0; 2], 0.0).particles.is_empty());
        let mut qd = [0.0; 3];
        sys.kinematic_equations(&q, &[1.0, 2.0, 3.0], 0.0, &mut qd);
        assert_eq!(qd, [1.0, 2.0, 3.0]);
        let mut out = [0.0; 1];
        Drifting(1.0).speed_constraints(&[0.0; 2], &[0.0; 2], 0.0, &mut out[..0]);
        assert_eq!(sys.particle_velocities(&q, &[1.0, 0.0, 2.0], 0.0).len(), 1);
    }
    // Planar trees (§7.11, RBDA §2.16): a chain whose pins all turn about ŷ is reduced, the
    // spatial tree is not; with the reduction on and off ABA gives the same v̇ (to round-off)
    // for hostile states, forces and wrenches, and where either refuses or overflows, each
    // answer is an error or finite.
    planar_trees ["Model::planar_axis", "Model::disable_planar_reduction"] {
        let j = Matrix3::from_diagonal(&Vector3::new(0.01, 0.01, 1e-4));
        let links: Vec<Link> = (0..4usize)
            .map(|i| {
                let offset = if i == 0 { Vector3::zeros() } else { Vector3::new(0.0, 0.0, -0.3) };
                Link::new(i.checked_sub(1), Joint::Pin { axis: Vector3::y() }, offset, 1.0, Vector3::new(0.0, 0.0, -0.15), j)
            })
            .collect();
        let mut m = Model::new(&links).unwrap();
        m.gravity = Vector3::new(0.3, 0.0, -9.81);
        assert_eq!(m.planar_axis(), Some(Vector3::y()));
        assert_eq!(tree().planar_axis(), None);
        let mut s = m.clone();
        s.disable_planar_reduction();
        assert_eq!(s.planar_axis(), None);
        let (q, v, tau) = ([0.7, 0.1, -0.2, 0.3], [0.5, -0.4, 0.3, 0.2], [0.1, 0.0, -0.2, 0.05]);
        let agree = |a: Result<Vec<f64>, DynamicsError>, b: Result<Vec<f64>, DynamicsError>, what: &str| match (a, b) {
            (Ok(x), Ok(y)) => {
                let scale = y.iter().fold(1.0f64, |m, c| nan_max(m, c.abs()));
                assert!(x.iter().zip(&y).all(|(p, r)| (p - r).abs() <= REL * scale), "{what}: {x:?} vs {y:?}");
            }
            (a, b) => {
                err_or(a, what, |vd| finite(vd));
                err_or(b, what, |vd| finite(vd));
            }
        };
        agree(m.aba(&q, &v, &tau, None), s.aba(&q, &v, &tau, None), "aba");
        for x in hostile() {
            for k in 0..4 {
                let (qx, vx, tx) = (with(&q, k, x), with(&v, k, x), with(&tau, k, x));
                agree(m.aba(&qx, &v, &tau, None), s.aba(&qx, &v, &tau, None), &format!("aba(q[{k}] = {x:e})"));
                agree(m.aba(&q, &vx, &tau, None), s.aba(&q, &vx, &tau, None), &format!("aba(v[{k}] = {x:e})"));
                agree(m.aba(&q, &v, &tx, None), s.aba(&q, &v, &tx, None), &format!("aba(τ[{k}] = {x:e})"));
            }
            for w in hostile3() {
                let mut f = vec![JointWrench::default(); 4];
                f[2].force = Vector3::from(w);
                f[3].moment = Vector3::new(x, 1.0, -x);
                agree(m.aba(&q, &v, &tau, Some(&f)), s.aba(&q, &v, &tau, Some(&f)), "aba(f_ext)");
            }
        }
        refused(m.aba(&q, &v, &tau[1..], None), "planar aba(short τ)");
    }
}
