//! Kane's equations assembled and solved, with dependent speeds eliminated.

use nalgebra::{DMatrix, DVector, Vector3};
use num_dual::Dual64;
use vectrix_frames::Frame;

use super::{KaneSolution, KaneSystem, partial_velocities, resolve};
use crate::DynamicsError;
use crate::constraints::DEPENDENT_ROW_REL_TOL;
use crate::constraints::eval::{dual_jacobian, duals};
use crate::error::{check_finite, check_len};
use crate::lagrange::cholesky_solve;

/// The speed constraints A u + b = 0 split as A_i u_i + A_d u_d + b = 0 and solved for the
/// dependent speeds by a QR of A_dᵀ, whose pivots name a row that does not determine them.
struct SpeedConstraints {
    /// −A_d⁻¹A_i (k × (p − k)).
    coupling: DMatrix<f64>,
    qr: nalgebra::QR<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

impl SpeedConstraints {
    fn new(a: &DMatrix<f64>, p: usize, k: usize) -> Result<Self, DynamicsError> {
        let a_d = a.columns(p - k, k).into_owned();
        let qr = a_d.transpose().qr();
        let r = qr.r();
        for row in 0..k {
            let norm = a_d.row(row).norm();
            let residual = if norm > 0.0 { r[(row, row)].abs() / norm } else { 0.0 };
            if residual <= DEPENDENT_ROW_REL_TOL {
                return Err(DynamicsError::SpeedsNotDetermined { row, dependent: k, residual });
            }
        }
        let mut s = Self { coupling: DMatrix::zeros(k, p - k), qr };
        s.coupling = -s.solve(&a.columns(0, p - k).into_owned());
        Ok(s)
    }
    /// A_d⁻¹ x: A_dᵀ = QR so A_d = RᵀQᵀ and A_d⁻¹x = Q R⁻ᵀ x.
    fn solve(&self, x: &DMatrix<f64>) -> DMatrix<f64> {
        let mut y = x.clone();
        self.qr.r().tr_solve_upper_triangular_mut(&mut y);
        self.qr.q() * y
    }
}

/// ψ(q, u, t) and A = ∂ψ/∂u of the speed constraints: one dual evaluation per speed.
fn speed_rows<K: KaneSystem>(
    sys: &K,
    q: &[f64],
    u: &[f64],
    t: f64,
    k: usize,
) -> Result<(DVector<f64>, DMatrix<f64>), DynamicsError> {
    let (qv, td) = (duals(q), Dual64::from(t));
    let (psi, a) = dual_jacobian(u, k, |uj, out| sys.speed_constraints(&qv, uj, td, out));
    check_finite(psi.as_slice(), "speed constraints")?;
    check_finite(a.as_slice(), "speed constraint matrix A")?;
    Ok((psi, a))
}

/// β = ψ_q q̇ + ψ_t: one dual evaluation along (q̇, 1) with u held.
fn speed_rate<K: KaneSystem>(
    sys: &K,
    q: &[f64],
    u: &[f64],
    qd: &[f64],
    t: f64,
    k: usize,
) -> Result<DVector<f64>, DynamicsError> {
    let qf: Vec<Dual64> = q.iter().zip(qd).map(|(&x, &v)| Dual64::new(x, v)).collect();
    let mut out = vec![Dual64::from(0.0); k];
    sys.speed_constraints(&qf, &duals(u), Dual64::new(t, 1.0), &mut out);
    let beta = DVector::from_iterator(k, out.iter().map(|v| v.eps));
    check_finite(beta.as_slice(), "speed constraint rate")?;
    Ok(beta)
}

/// Kane's equations F_r + F*_r = 0 solved for u̇ at (q, u_i, t), u_i the independent speeds
/// (all p speeds when there are no speed constraints).
///
/// Book: §9.14 (Kane & Levinson (6.1.1); the reduced form for nonholonomic systems, their
/// §6.1 with ṽ⃗_r).
///
/// # Conventions
/// u = [u_i; u_d]; the dependent speeds u_d are recomputed from the speed constraints, so a
/// state y = (q, u_i) stays on them exactly.
///
/// # Errors
/// [`DynamicsError::DimensionMismatch`] (q, u_i, or the lengths of masses, velocities and
/// loads), [`DynamicsError::NonFinite`], [`DynamicsError::TooManyConstraints`] (k > p),
/// [`DynamicsError::SpeedsNotDetermined`] (A_d singular), and
/// [`DynamicsError::SingularMassMatrix`] when CᵀKC is not positive definite (speeds that
/// do not move any mass); [`DynamicsError::Overflow`] when finite inputs give a non-finite u̇.
pub fn kane_accelerations<K: KaneSystem>(
    sys: &K,
    q: &[f64],
    u_ind: &[f64],
    t: f64,
) -> Result<KaneSolution, DynamicsError> {
    let (n, p, k) = (sys.coordinates(), sys.speeds(), sys.speed_constraint_count());
    if k > p {
        return Err(DynamicsError::TooManyConstraints { count: k, dof: p });
    }
    check_len(q.len(), n, "q")?;
    check_len(u_ind.len(), p - k, "independent speeds u_i")?;
    check_finite(q, "q")?;
    check_finite(u_ind, "u_i")?;
    check_finite(&[t], "t")?;
    // u = [u_i; u_d] with u_d = −A_d⁻¹(A_i u_i + b) = −A_d⁻¹ ψ(q, [u_i; 0], t)
    let mut u = vec![0.0; p];
    u[..p - k].copy_from_slice(u_ind);
    let speed = if k > 0 {
        let (psi0, a) = speed_rows(sys, q, &u, t, k)?;
        let sc = SpeedConstraints::new(&a, p, k)?;
        let u_d = -sc.solve(&DMatrix::from_column_slice(k, 1, psi0.as_slice()));
        u[p - k..].copy_from_slice(u_d.as_slice());
        Some(sc)
    } else {
        None
    };
    let mut qd = vec![0.0; n];
    sys.kinematic_equations(q, &u, t, &mut qd);
    check_finite(&qd, "q̇ = f(q, u, t)")?;
    let pv = partial_velocities(sys, q, &u, t)?;
    let (mass, forcing) = generalized_inertia_and_forces(sys, q, &u, &qd, t, &pv)?;
    let Some(sc) = speed else {
        let ud = cholesky_solve(mass.clone(), forcing.clone())?;
        return Ok(KaneSolution { u: DVector::from_vec(u), qd: DVector::from_vec(qd), ud, mass, forcing });
    };
    // u̇_d = −A_d⁻¹(A_i u̇_i + ψ_q q̇ + ψ_t): u̇ = C u̇_i + w
    let beta = speed_rate(sys, q, &u, &qd, t, k)?;
    let w_d = -sc.solve(&DMatrix::from_column_slice(k, 1, beta.as_slice()));
    let mut c = DMatrix::zeros(p, p - k);
    c.view_mut((0, 0), (p - k, p - k)).fill_with_identity();
    c.view_mut((p - k, 0), (k, p - k)).copy_from(&sc.coupling);
    let mut w = DVector::zeros(p);
    w.rows_mut(p - k, k).copy_from(&w_d.column(0));
    // F̃_r + F̃*_r = 0: Cᵀ K C u̇_i = Cᵀ(F − F*₀ − K w)
    let mass_red = c.transpose() * &mass * &c;
    let forcing_red = c.transpose() * (&forcing - &mass * &w);
    let ud_i = cholesky_solve(mass_red.clone(), forcing_red.clone())?;
    let ud = &c * ud_i + w;
    // finite inputs whose dependent accelerations exceed f64::MAX
    if !ud.iter().all(|x| x.is_finite()) {
        return Err(DynamicsError::Overflow { what: "Kane's equations u̇" });
    }
    Ok(KaneSolution {
        u: DVector::from_vec(u),
        qd: DVector::from_vec(qd),
        ud,
        mass: mass_red,
        forcing: forcing_red,
    })
}

/// y′ = (q̇, u̇_i) for the state y = (q, u_i): Kane's equations as an ODE right-hand side.
///
/// Book: §9.14.
///
/// # Errors
/// As [`kane_accelerations`].
pub fn kane_state_derivative<K: KaneSystem>(sys: &K, t: f64, y: &[f64]) -> Result<Vec<f64>, DynamicsError> {
    let n = sys.coordinates();
    let free = sys.speeds().saturating_sub(sys.speed_constraint_count());
    check_len(y.len(), n + free, "state (q, u_i)")?;
    let s = kane_accelerations(sys, &y[..n], &y[n..], t)?;
    Ok(s.qd.iter().chain(s.ud.iter().take(free)).copied().collect())
}

/// K_rs = Σ m v⃗_r·v⃗_s + ω⃗_r·J⃗ω⃗_s and F_r − F*_r at u̇ = 0, from one dual evaluation of the
/// velocities along (q̇, 1) with u held (values in the real part, a⃗₀ and α⃗₀ in the ε part).
fn generalized_inertia_and_forces<K: KaneSystem>(
    sys: &K,
    q: &[f64],
    u: &[f64],
    qd: &[f64],
    t: f64,
    pv: &super::PartialVelocities,
) -> Result<(DMatrix<f64>, DVector<f64>), DynamicsError> {
    let p = u.len();
    let masses = sys.masses();
    let qf: Vec<Dual64> = q.iter().zip(qd).map(|(&x, &v)| Dual64::new(x, v)).collect();
    let (uv, tf) = (duals(u), Dual64::new(t, 1.0));
    let particles = sys.particle_velocities(&qf, &uv, tf);
    let bodies = sys.body_motions(&qf, &uv, tf);
    check_len(particles.len(), masses.particles.len(), "particle velocities")?;
    check_len(bodies.len(), masses.bodies.len(), "body motions")?;
    // the lists must not change length between evaluations
    for (vp, vb) in pv.particles.iter().zip(&pv.bodies) {
        check_len(vp.len(), particles.len(), "particle partial velocities")?;
        check_len(vb.len(), bodies.len(), "body partial velocities")?;
    }
    let loads = sys.loads(q, u, t);
    if !loads.particles.is_empty() {
        check_len(loads.particles.len(), particles.len(), "particle loads")?;
    }
    if !loads.bodies.is_empty() {
        check_len(loads.bodies.len(), bodies.len(), "body loads")?;
    }
    let (mut mass, mut forcing) = (DMatrix::zeros(p, p), DVector::zeros(p));
    for (i, v) in particles.iter().enumerate() {
        let m = masses.particles[i];
        let a0 = resolve(v).map(|d| d.eps);
        let f = loads.particles.get(i).map_or(Vector3::zeros(), resolve);
        for r in 0..p {
            let v_r = &pv.particles[r][i];
            // F_r + F*_r at u̇ = 0: v⃗_r·(F⃗ − m a⃗₀)
            forcing[r] += v_r.dot(&(f - a0 * m));
            for s in 0..p {
                mass[(r, s)] += m * v_r.dot(&pv.particles[s][i]);
            }
        }
    }
    for (b, motion) in bodies.iter().enumerate() {
        let (m, j_b) = masses.bodies[b];
        // J⃗ resolved in A: 𝓡_{B/A} J|_B 𝓡_{B/A}ᵀ
        let r_ba = motion.frame.rotation_rel(&Frame::identity()).map(|d| d.re);
        let j = r_ba * j_b * r_ba.transpose();
        let omega = resolve(&motion.omega).map(|d| d.re);
        let (a0, alpha0) = (resolve(&motion.v_c).map(|d| d.eps), resolve(&motion.omega).map(|d| d.eps));
        let (f, m_c) = loads
            .bodies
            .get(b)
            .map_or((Vector3::zeros(), Vector3::zeros()), |(f, mc)| (resolve(f), resolve(mc)));
        // Euler's equation at u̇ = 0: J⃗α⃗₀ + ω⃗×J⃗ω⃗ (7.8.13)
        let euler0 = j * alpha0 + omega.cross(&(j * omega));
        for r in 0..p {
            let (v_r, w_r) = &pv.bodies[r][b];
            forcing[r] += v_r.dot(&(f - a0 * m)) + w_r.dot(&(m_c - euler0));
            for s in 0..p {
                let (v_s, w_s) = &pv.bodies[s][b];
                mass[(r, s)] += m * v_r.dot(v_s) + w_r.dot(&(j * w_s));
            }
        }
    }
    check_finite(mass.as_slice(), "generalized inertia K")?;
    check_finite(forcing.as_slice(), "generalized forces")?;
    Ok((mass, forcing))
}
