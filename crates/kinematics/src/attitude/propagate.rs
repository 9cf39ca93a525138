//! Attitude propagation: integrate the rate equation of one representation from 𝓡_{B/A}(t₀)
//! under a body angular velocity ω_{B/A}|_B(t), and return 𝓡_{B/A}(t₁).
//!
//! RK4 on a rate equation (with the projection each representation needs: rewrap for the
//! angle vector, shadow switch for MRPs, optional renormalization for q and 𝓡), the exact
//! quaternion step (4.11.17), and the Lie-group methods of `vectrix-ode` on rotors and on
//! SO(3) matrices (exact for constant ω, F4.8.2). Book: §4.8–4.12; notes ch4-5 §3.

use nalgebra::{Matrix3, SVector, Vector3, Vector4};
use vectrix_frames::Frame;
use vectrix_ode::{LieGroup, LieMethod, integrate_lie, quaternion_exact_step};
use vectrix_rotation::{EulerAngles, EulerSequence, EulerSolution, Quaternion, ROTATION_TOL, Rotation};

use super::{
    angle_vector_rate_body, euler_rates_from_omega_body, gibbs_rate_body, mrp_rate_body,
    quaternion_rate_body, rewrap_angle_vector,
};
use crate::KinematicsError;

/// |g| beyond which [`Propagator::GibbsRk4`] stops: θ within ≈ 2·10⁻⁸ of π.
///
/// Book: §4.12 (g undefined at θ = π).
pub const GIBBS_LIMIT: f64 = 1e8;

/// How to propagate an attitude.
///
/// Book: §4.8 (constant ω: 𝓡(t) = 𝓡(0)e^{ω^×t}, F4.8.2), §4.9–4.12 (rate equations).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Propagator {
    /// RK4 on the Euler-angle rates (4.10.11) of `sequence`; fails with
    /// [`KinematicsError::GimbalLock`] when |det S| ≤ `tol` on the way.
    EulerRk4 {
        /// The sequence.
        sequence: EulerSequence,
        /// Tolerance on |det S|.
        tol: f64,
    },
    /// RK4 on Θ̇ = J_r⁻¹ω_B (4.9.17), rewrapped to |Θ| ≤ π after every step.
    AngleVectorRk4,
    /// RK4 on q̇ = ½E(q)ω_B (4.11.13), optionally renormalized every step.
    QuaternionRk4 {
        /// Divide q by |q| after every step.
        renormalize: bool,
    },
    /// RK4 on ġ = ½(I + ggᵀ + g^×)ω_B (4.12.4); stops with
    /// [`KinematicsError::SingularRateMap`] when |g| exceeds [`GIBBS_LIMIT`] (θ → π).
    GibbsRk4,
    /// RK4 on the MRP rates, switching to the shadow set −p/|p|² when |p| > 1.
    MrpRk4,
    /// RK4 on Poisson's equation 𝓡̇ = 𝓡ω^× (4.3.17), optionally re-orthonormalized (nearest
    /// rotation) every step.
    PoissonRk4 {
        /// Project onto SO(3) after every step.
        renormalize: bool,
    },
    /// q ← e^{Q(ω)h}q with ω frozen at the step midpoint (4.11.17): exact for constant ω.
    QuaternionExact,
    /// A Lie-group method of `vectrix-ode` on rotors.
    RotorLie(LieMethod),
    /// A Lie-group method of `vectrix-ode` on rotation matrices (SO(3)).
    MatrixLie(LieMethod),
}

/// A rotation matrix as an element of SO(3) for the Lie-group integrators: the body form
/// 𝓡̇ = 𝓡ω^× is y′ = y·ξ with ξ = ω_B; exp is Rodrigues's formula.
#[derive(Debug, Clone, Copy, PartialEq)]
struct So3(Matrix3<f64>);

/// exp(ω^×) by Rodrigues's formula with series for small angles.
fn so3_exp(w: &Vector3<f64>) -> Matrix3<f64> {
    let th = w.norm();
    let (a, b) = if th < 1e-4 {
        (1.0 - th * th / 6.0, 0.5 - th * th / 24.0)
    } else {
        let s = (0.5 * th).sin();
        (th.sin() / th, 2.0 * s * s / (th * th))
    };
    let x = w.cross_matrix();
    Matrix3::identity() + x * a + x * x * b
}

impl LieGroup for So3 {
    type Algebra = Vector3<f64>;
    fn exp(xi: &Vector3<f64>) -> Self {
        So3(so3_exp(xi))
    }
    fn compose(&self, rhs: &Self) -> Self {
        So3(self.0 * rhs.0)
    }
    fn bracket(a: &Vector3<f64>, b: &Vector3<f64>) -> Vector3<f64> {
        a.cross(b)
    }
    fn axpy(a: &Vector3<f64>, c: f64, b: &Vector3<f64>) -> Vector3<f64> {
        a + b * c
    }
    fn scale(c: f64, xi: &Vector3<f64>) -> Vector3<f64> {
        xi * c
    }
    fn magnitude(&self) -> f64 {
        if self.0.iter().all(|x| x.is_finite()) { self.0.amax() } else { f64::NAN }
    }
    fn algebra_magnitude(xi: &Vector3<f64>) -> f64 {
        if xi.iter().all(|x| x.is_finite()) { xi.amax() } else { f64::NAN }
    }
}

/// One classical RK4 step of y′ = f(t, y) (HNW §II.1) with a fallible right-hand side.
fn rk4<const N: usize>(
    f: &mut impl FnMut(f64, &SVector<f64, N>) -> Result<SVector<f64, N>, KinematicsError>,
    t: f64,
    y: &SVector<f64, N>,
    h: f64,
) -> Result<SVector<f64, N>, KinematicsError> {
    let k1 = f(t, y)?;
    let k2 = f(t + 0.5 * h, &(y + k1 * (0.5 * h)))?;
    let k3 = f(t + 0.5 * h, &(y + k2 * (0.5 * h)))?;
    let k4 = f(t + h, &(y + k3 * h))?;
    Ok(y + (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0))
}

/// Runs `n` RK4 steps with a projection after each.
fn run<const N: usize>(
    mut f: impl FnMut(f64, &SVector<f64, N>) -> Result<SVector<f64, N>, KinematicsError>,
    project: impl Fn(SVector<f64, N>) -> SVector<f64, N>,
    y0: SVector<f64, N>,
    t0: f64,
    h: f64,
    n: usize,
) -> Result<SVector<f64, N>, KinematicsError> {
    let mut y = y0;
    for i in 0..n {
        y = project(rk4(&mut f, t0 + i as f64 * h, &y, h)?);
        if !y.iter().all(|x| x.is_finite()) {
            return Err(KinematicsError::NonFinite { what: "propagated attitude" });
        }
    }
    Ok(y)
}

fn quat(v: &Vector4<f64>) -> Quaternion {
    Quaternion::new(v.x, v.y, v.z, v.w)
}

fn to_matrix(q: &Quaternion) -> Result<Matrix3<f64>, KinematicsError> {
    let q = q.normalize().ok_or(KinematicsError::Zero { what: "propagated quaternion" })?;
    Ok(q.rotation_matrix())
}

fn rotation_err(e: vectrix_rotation::RotationError) -> KinematicsError {
    KinematicsError::SingularRateMap { representation: "rotation conversion", detail: e.to_string() }
}

/// Propagates 𝓡_{B/A} from `t0` to `t1` in `n` equal steps under ω_{B/A}|_B = `omega_body(t)`.
///
/// Book: §4.8–4.12, (4.3.17), (4.9.17), (4.10.11), (4.11.13), (4.11.17), (4.12.4).
///
/// # Conventions
/// `r0` and the result are 𝓡_{B/A} (columns = B's axes in A). Every representation starts from
/// the conversion of `r0` by `vectrix-rotation` and converts back at the end (Euler angles
/// use the principal solution; a gimbal-locked start is an error).
///
/// # Errors
/// [`KinematicsError::GimbalLock`] (Euler angles), [`KinematicsError::SingularRateMap`]
/// (Gibbs near θ = π), [`KinematicsError::NonFinite`] (a blown-up representation), [`KinematicsError::OutOfRange`] for `n = 0` or
/// t₁ ≤ t₀, [`KinematicsError::SingularRateMap`] when `r0` is not a rotation.
pub fn propagate_attitude(
    method: Propagator,
    r0: &Matrix3<f64>,
    mut omega_body: impl FnMut(f64) -> Vector3<f64>,
    t0: f64,
    t1: f64,
    n: usize,
) -> Result<Matrix3<f64>, KinematicsError> {
    if n == 0 || t1 <= t0 || !t0.is_finite() || !t1.is_finite() {
        return Err(KinematicsError::OutOfRange {
            what: "steps / interval",
            value: n as f64,
            valid: "n ≥ 1 and t₀ < t₁, finite",
        });
    }
    let h = (t1 - t0) / n as f64;
    let a = Frame::new();
    let rot = Rotation::from_rotation_matrix_in(&a, r0, ROTATION_TOL).map_err(rotation_err)?;
    let q0 = rot.quaternion_in(&a);
    let omega = &mut omega_body;
    match method {
        Propagator::EulerRk4 { sequence, tol } => euler_rk4(&a, &rot, sequence, tol, omega, (t0, h, n)),
        Propagator::AngleVectorRk4 => {
            let f = |t: f64, y: &Vector3<f64>| angle_vector_rate_body(y, &omega(t));
            let y = run(f, |y| rewrap_angle_vector(&y), q0.angle_vector(), t0, h, n)?;
            to_matrix(&Quaternion::from_angle_vector(&y))
        }
        Propagator::QuaternionRk4 { renormalize } => {
            let f = |t: f64, y: &Vector4<f64>| quaternion_rate_body(&quat(y), &omega(t));
            let project = |y: Vector4<f64>| if renormalize { y / y.norm() } else { y };
            let y = run(f, project, q0.to_vector4(), t0, h, n)?;
            // without renormalization the drift of |q| is part of the result: do not hide it
            Ok(quat(&y).rotation_matrix())
        }
        Propagator::GibbsRk4 => gibbs_rk4(&q0, omega, (t0, h, n)),
        Propagator::MrpRk4 => {
            let f = |t: f64, y: &Vector3<f64>| mrp_rate_body(y, &omega(t));
            // shadow set: p ← −p/|p|² when |p| > 1 (same attitude, |p| ≤ 1)
            let project = |p: Vector3<f64>| {
                let p2 = p.norm_squared();
                if p2 > 1.0 { -p / p2 } else { p }
            };
            let y = run(f, project, q0.mrp(), t0, h, n)?;
            to_matrix(&Quaternion::from_mrp(&y))
        }
        Propagator::PoissonRk4 { renormalize } => poisson_rk4(r0, renormalize, omega, (t0, h, n)),
        Propagator::QuaternionExact => {
            let mut q = q0.to_vector4();
            for i in 0..n {
                // ω at the midpoint: exact for constant ω, second order otherwise
                q = quaternion_exact_step(&q, &omega(t0 + (i as f64 + 0.5) * h), h);
            }
            to_matrix(&quat(&q))
        }
        Propagator::RotorLie(m) => {
            let f = |t: f64, _: &vectrix_tensor::Rotor| {
                let w = omega(t);
                a.vector([w.x, w.y, w.z])
            };
            let (r, _) = integrate_lie(m, f, t0, &rot.rotor(), t1, n, |_, _| {}).map_err(|e| {
                KinematicsError::SingularRateMap { representation: "rotor", detail: e.to_string() }
            })?;
            let rot = Rotation::from_rotor(&r).map_err(rotation_err)?;
            Ok(rot.rotation_matrix_in(&a))
        }
        Propagator::MatrixLie(m) => {
            let f = |t: f64, _: &So3| omega(t);
            let (r, _) = integrate_lie(m, f, t0, &So3(*r0), t1, n, |_, _| {}).map_err(|e| {
                KinematicsError::SingularRateMap { representation: "SO(3)", detail: e.to_string() }
            })?;
            Ok(r.0)
        }
    }
}

/// [`Propagator::EulerRk4`]: RK4 on the Euler-angle rates (4.10.11) from the principal
/// solution of the initial attitude `rot` (resolved in `a`); `(t0, h, n)` is the grid.
fn euler_rk4(
    a: &Frame,
    rot: &Rotation,
    sequence: EulerSequence,
    tol: f64,
    omega_body: &mut impl FnMut(f64) -> Vector3<f64>,
    (t0, h, n): (f64, f64, usize),
) -> Result<Matrix3<f64>, KinematicsError> {
    let EulerSolution::Regular { principal, .. } = rot.euler_in(a, sequence) else {
        // a gimbal-locked start has no principal solution to integrate from
        return Err(KinematicsError::GimbalLock {
            sequence: format!("{:?}", sequence.axes().map(|x| x.index())),
            det: 0.0,
            condition: f64::INFINITY,
            tol,
            singular_at: "the initial attitude",
        });
    };
    let f = |t: f64, y: &SVector<f64, 3>| {
        let ea = EulerAngles::new(sequence, [y.x, y.y, y.z]);
        euler_rates_from_omega_body(&ea, &omega_body(t), tol).map(Vector3::from)
    };
    let y = run(f, |y| y, Vector3::from(principal.angles), t0, h, n)?;
    Ok(EulerAngles::new(sequence, [y.x, y.y, y.z]).rotation_matrix())
}

/// [`Propagator::GibbsRk4`]: RK4 on ġ = ½(I + ggᵀ + g^×)ω_B (4.12.4), stopped with a typed
/// error before g overflows near θ = π; `(t0, h, n)` is the grid.
fn gibbs_rk4(
    q0: &Quaternion,
    omega_body: &mut impl FnMut(f64) -> Vector3<f64>,
    (t0, h, n): (f64, f64, usize),
) -> Result<Matrix3<f64>, KinematicsError> {
    let g0 = q0.try_gibbs().map_err(rotation_err)?;
    let f = |t: f64, y: &Vector3<f64>| {
        // g = tan(θ/2)n̂ is infinite at θ = π (§4.12): stop with a typed error before overflow
        if y.norm() > GIBBS_LIMIT {
            return Err(KinematicsError::SingularRateMap {
                representation: "Gibbs vector",
                detail: format!(
                    "|g| = {:e} > {GIBBS_LIMIT:e}: the attitude approaches θ = π, where g is undefined; use quaternions or MRPs",
                    y.norm()
                ),
            });
        }
        gibbs_rate_body(y, &omega_body(t))
    };
    let y = run(f, |y| y, g0, t0, h, n)?;
    to_matrix(&Quaternion::from_gibbs(&y))
}

/// [`Propagator::PoissonRk4`]: RK4 on 𝓡̇ = 𝓡ω^× (4.3.17) over the nine entries of 𝓡,
/// optionally projected onto SO(3) after every step; `(t0, h, n)` is the grid.
fn poisson_rk4(
    r0: &Matrix3<f64>,
    renormalize: bool,
    omega_body: &mut impl FnMut(f64) -> Vector3<f64>,
    (t0, h, n): (f64, f64, usize),
) -> Result<Matrix3<f64>, KinematicsError> {
    let f = |t: f64, y: &SVector<f64, 9>| {
        let r = Matrix3::from_column_slice(y.as_slice());
        let rd = r * omega_body(t).cross_matrix();
        Ok(SVector::<f64, 9>::from_column_slice(rd.as_slice()))
    };
    let project = |y: SVector<f64, 9>| {
        if !renormalize {
            return y;
        }
        let r = Matrix3::from_column_slice(y.as_slice());
        let r = vectrix_rotation::nearest_rotation(&r).unwrap_or(r);
        SVector::<f64, 9>::from_column_slice(r.as_slice())
    };
    let y = run(f, project, SVector::<f64, 9>::from_column_slice(r0.as_slice()), t0, h, n)?;
    Ok(Matrix3::from_column_slice(y.as_slice()))
}
