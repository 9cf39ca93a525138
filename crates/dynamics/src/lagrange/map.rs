//! The kinematic-map form of Lagrange's equations: the user gives particle positions
//! r⃗_i(q, t) and rigid-body poses (r⃗_c(q, t), F_B(q, t)); vectrix builds T itself.
//!
//! With J_i = ∂r_i/∂q and J_ω (ω = J_ω q̇ + ω_t), Lagrange's equations read
//! Σ m_i J_iᵀ r̈_i + Σ J_ωᵀ(J⃗ω̇ + ω⃗×J⃗ω⃗) + Σ m J_cᵀ a_c = Q (9.3.12, 9.4.2, 9.5.2): one dual
//! evaluation per coordinate gives the Jacobians, one along (q̇, 1) gives the velocities and
//! one hyper-dual evaluation along (q̇, 1) twice gives the accelerations at q̈ = 0.

use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use num_dual::{Dual64, HyperDual64};
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Scalar, Vector};

use super::cholesky_solve;
use crate::DynamicsError;
use crate::error::{check_finite, check_len};

/// Masses of a [`KinematicMap`]: one per particle, and (m, J_{B/c}|_B) per rigid body, the
/// inertia resolved in the body frame F_B returned by [`KinematicMap::bodies`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MapMasses {
    /// Particle masses m_i.
    pub particles: Vec<f64>,
    /// Rigid bodies: mass and J_{B/c} resolved in F_B.
    pub bodies: Vec<(f64, Matrix3<f64>)>,
}

/// A system described by where its parts are: r⃗_{y_i/w}(q, t) for particles and
/// (r⃗_{c/w}, F_B) for rigid bodies, relative to an unforced point w and an inertial frame.
///
/// Book: §9.3 ((9.3.11)–(9.3.17)), §9.4–9.5 (generalized forces).
pub trait KinematicMap {
    /// Number of generalized coordinates r.
    fn dof(&self) -> usize;
    /// The masses, in the order of [`KinematicMap::particles`] and [`KinematicMap::bodies`].
    fn masses(&self) -> MapMasses;
    /// Particle positions r⃗_{y_i/w}(q, t).
    fn particles<T: Scalar>(&self, q: &[T], t: T) -> Vec<Vector<T>> {
        let _ = (q, t);
        Vec::new()
    }
    /// Rigid-body poses: centre of mass r⃗_{c/w}(q, t) and body frame F_B(q, t).
    fn bodies<T: Scalar>(&self, q: &[T], t: T) -> Vec<(Vector<T>, Frame<T>)> {
        let _ = (q, t);
        Vec::new()
    }
    /// Potential energy U(q, t); zero by default.
    fn potential<T: Scalar>(&self, q: &[T], t: T) -> T {
        let _ = (q, t);
        T::zero()
    }
    /// Other generalized forces Q(q, q̇, t) added into `out` (zeros on entry).
    fn generalized_force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let _ = (q, qd, t, out);
    }
}

/// Particle positions and body (centre, 𝓡_{B/A}) resolved in A.
type Resolved<T> = (Vec<Vector3<T>>, Vec<(Vector3<T>, Matrix3<T>)>);

/// Positions and rotation matrices 𝓡_{B/A} resolved in one fixed frame A.
fn evaluate<K: KinematicMap, T: Scalar>(sys: &K, q: &[T], t: T) -> Resolved<T> {
    let a = Frame::<T>::identity();
    let p = sys.particles(q, t).iter().map(|r| r.resolve(&a)).collect();
    let b = sys.bodies(q, t).iter().map(|(r, f)| (r.resolve(&a), f.rotation_rel(&a))).collect();
    (p, b)
}

fn vee(m: &Matrix3<f64>) -> Vector3<f64> {
    // vee of the skew part: robust to round-off in the symmetric part
    Vector3::new(m[(2, 1)] - m[(1, 2)], m[(0, 2)] - m[(2, 0)], m[(1, 0)] - m[(0, 1)]) * 0.5
}

struct MapState {
    m: DMatrix<f64>,
    rhs: DVector<f64>,
    t_kin: f64,
}

fn assemble<K: KinematicMap>(sys: &K, q: &[f64], qd: &[f64], t: f64) -> Result<MapState, DynamicsError> {
    let r = sys.dof();
    check_len(q.len(), r, "q")?;
    check_len(qd.len(), r, "q̇")?;
    check_finite(q, "q")?;
    check_finite(qd, "q̇")?;
    check_finite(&[t], "t")?;
    let masses = sys.masses();
    // value, Jacobian columns (∂/∂q_j) and ∂U/∂q_j
    let (p0, b0) = evaluate(sys, q, t);
    check_len(p0.len(), masses.particles.len(), "particles")?;
    check_len(b0.len(), masses.bodies.len(), "bodies")?;
    let mut jp = vec![DMatrix::<f64>::zeros(3, r); p0.len()];
    let mut jr = vec![vec![Matrix3::<f64>::zeros(); r]; b0.len()];
    let mut jc = vec![DMatrix::<f64>::zeros(3, r); b0.len()];
    let mut du = DVector::zeros(r);
    let td = Dual64::from(t);
    for j in 0..r {
        let qj: Vec<Dual64> = q.iter().enumerate().map(|(k, &x)| Dual64::new(x, f64::from(k == j))).collect();
        let (p, b) = evaluate(sys, &qj, td);
        for (i, x) in p.iter().enumerate() {
            jp[i].set_column(j, &x.map(|d| d.eps));
        }
        for (i, (c, rm)) in b.iter().enumerate() {
            jc[i].set_column(j, &c.map(|d| d.eps));
            jr[i][j] = rm.map(|d| d.eps);
        }
        du[j] = sys.potential(&qj, td).eps;
    }
    // along the flow (q̇, 1): first derivative = velocity, second (hyper-dual) = acceleration at q̈ = 0
    let qh: Vec<HyperDual64> = q.iter().zip(qd).map(|(&x, &v)| HyperDual64::new(x, v, v, 0.0)).collect();
    let (ph, bh) = evaluate(sys, &qh, HyperDual64::new(t, 1.0, 1.0, 0.0));
    let mut m = DMatrix::zeros(r, r);
    let mut rhs = DVector::zeros(r);
    let mut t_kin = 0.0;
    for (i, x) in ph.iter().enumerate() {
        let (mi, v, a0) = (masses.particles[i], x.map(|d| d.eps1), x.map(|d| d.eps1eps2));
        // (9.3.12): M += m JᵀJ; Σ m Jᵀ r̈₀ moves to the right-hand side
        m += jp[i].transpose() * &jp[i] * mi;
        rhs -= jp[i].transpose() * (a0 * mi);
        t_kin += 0.5 * mi * v.norm_squared();
    }
    for (i, (c, rm)) in bh.iter().enumerate() {
        let (mb, j_b) = masses.bodies[i];
        let r_ba = b0[i].1;
        let (v, a0) = (c.map(|d| d.eps1), c.map(|d| d.eps1eps2));
        let (r_dot, r_ddot) = (rm.map(|d| d.eps1), rm.map(|d| d.eps1eps2));
        // ω^× = Ṙ Rᵀ, ω̇^× = R̈Rᵀ + ṘṘᵀ (at q̈ = 0), J|_A = R J|_B Rᵀ
        let omega = vee(&(r_dot * r_ba.transpose()));
        let omega_dot0 = vee(&(r_ddot * r_ba.transpose() + r_dot * r_dot.transpose()));
        let j_a = r_ba * j_b * r_ba.transpose();
        let mut jw = DMatrix::<f64>::zeros(3, r);
        for (k, d_r) in jr[i].iter().enumerate() {
            jw.set_column(k, &vee(&(d_r * r_ba.transpose())));
        }
        let j_ad = DMatrix::from_column_slice(3, 3, j_a.as_slice());
        m += jc[i].transpose() * &jc[i] * mb + jw.transpose() * &j_ad * &jw;
        let euler0 = j_a * omega_dot0 + omega.cross(&(j_a * omega));
        rhs -= jc[i].transpose() * (a0 * mb) + jw.transpose() * euler0;
        t_kin += 0.5 * mb * v.norm_squared() + 0.5 * omega.dot(&(j_a * omega));
    }
    rhs -= du;
    let mut qf = DVector::zeros(r);
    sys.generalized_force(q, qd, t, qf.as_mut_slice());
    rhs += qf;
    check_finite(m.as_slice(), "mass matrix")?;
    check_finite(rhs.as_slice(), "generalized forces")?;
    check_finite(&[t_kin], "kinetic energy")?;
    Ok(MapState { m, rhs, t_kin })
}

/// The equations of motion M(q, t) q̈ = f(q, q̇, t) of a kinematic-map system: M as in
/// [`map_mass_matrix`], f = Q − ∂U/∂q − Σ m Jᵀr̈₀ − Σ J_ωᵀ(J⃗ω̇₀ + ω⃗×J⃗ω⃗) (the inertial
/// terms at q̈ = 0 moved to the right).
///
/// Book: (9.3.12), (9.4.2), (9.5.2).
///
/// # Errors
/// As [`map_mass_matrix`].
pub fn map_equations<K: KinematicMap>(
    sys: &K,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<(DMatrix<f64>, DVector<f64>), DynamicsError> {
    let s = assemble(sys, q, qd, t)?;
    Ok((s.m, s.rhs))
}

/// M(q, t) = Σ m_i J_iᵀJ_i + Σ (m J_cᵀJ_c + J_ωᵀ J⃗ J_ω) (9.3.12, 9.3.17).
///
/// Book: (9.3.12), (9.3.17).
///
/// # Errors
/// [`DynamicsError::DimensionMismatch`] (state or masses), [`DynamicsError::NonFinite`].
pub fn map_mass_matrix<K: KinematicMap>(sys: &K, q: &[f64], t: f64) -> Result<DMatrix<f64>, DynamicsError> {
    let zero = vec![0.0; sys.dof()];
    Ok(assemble(sys, q, &zero, t)?.m)
}

/// T = Σ ½m_i|ṙ_i|² + Σ (½m|v_c|² + ½ω·J⃗ω) (9.3.11, 9.3.17).
///
/// Book: (9.3.11), (9.3.17).
///
/// # Errors
/// As [`map_mass_matrix`].
pub fn map_kinetic_energy<K: KinematicMap>(
    sys: &K,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<f64, DynamicsError> {
    Ok(assemble(sys, q, qd, t)?.t_kin)
}

/// q̈ of a kinematic-map system, M solved by Cholesky.
///
/// Book: §9.3–9.6.
///
/// # Errors
/// As [`map_mass_matrix`]; [`DynamicsError::SingularMassMatrix`].
pub fn map_accelerations<K: KinematicMap>(
    sys: &K,
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Result<DVector<f64>, DynamicsError> {
    let s = assemble(sys, q, qd, t)?;
    cholesky_solve(s.m, s.rhs)
}
