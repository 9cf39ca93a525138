//! Kane's equations (Gibbs–Appell–Kane dynamics, book §9.14) with generalized speeds chosen
//! by the user and partial velocities from dual numbers.
//!
//! The user gives the kinematical differential equations q̇ = f(q, u, t) (the inverse of a
//! choice u = W(q) q̇ + X(q, t), e.g. u = body-frame ω), the velocities of the particles and
//! of the mass centres and the angular velocities of the bodies as functions of (q, u, t),
//! linear in u, and the applied loads. Then, with every vector resolved in one inertial
//! frame A:
//!
//! * partial velocities v⃗_r = ∂v⃗/∂u_r and partial angular velocities ω⃗_r = ∂ω⃗/∂u_r: one
//!   dual evaluation per speed (ε on u_r);
//! * a⃗ = Σ_s v⃗_s u̇_s + a⃗₀ with a⃗₀ = ∂v⃗/∂q q̇ + ∂v⃗/∂t, and α⃗ = Σ_s ω⃗_s u̇_s + α⃗₀: one dual
//!   evaluation along (q̇, 1) with u held;
//! * generalized active forces F_r = Σ v⃗_r·F⃗ + ω⃗_r·M⃗_c, generalized inertia forces
//!   F*_r = −Σ m v⃗_r·a⃗ − Σ ω⃗_r·(J⃗α⃗ + ω⃗×J⃗ω⃗), and Kane's equations F_r + F*_r = 0 read
//!   K u̇ = F − F*₀ with K_rs = Σ m v⃗_r·v⃗_s + ω⃗_r·J⃗ω⃗_s.
//!
//! **Nonholonomic systems.** Speed constraints A(q, t) u + b(q, t) = 0 (k rows) make the last
//! k speeds dependent: u_d = −A_d⁻¹(A_i u_i + b). With C = [I; −A_d⁻¹A_i] the partial
//! velocities of the independent speeds are ṽ⃗_r = Σ_s v⃗_s C_sr, and the reduced equations
//! F̃_r + F̃*_r = 0 are Cᵀ K C u̇_i = Cᵀ(F − F*₀ − K w), with u̇ = C u̇_i + w and
//! w = [0; −A_d⁻¹(ψ_q q̇ + ψ_t)]. The reaction forces do not appear (they do no work on
//! the partial velocities).
//!
//! Book: §9.14 (a stub in the text; Kane & Levinson, *Dynamics: Theory and Applications*,
//! ch. 4–6).

mod equations;

pub use equations::{kane_accelerations, kane_state_derivative};

use nalgebra::{DMatrix, DVector, Vector3};
use num_dual::Dual64;
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Scalar, Vector};

use crate::DynamicsError;
use crate::constraints::eval::duals;
use crate::error::{check_finite, check_len};
use crate::lagrange::MapMasses;

/// The motion of a rigid body: velocity of its mass centre, its angular velocity and its
/// body frame F_B (in which [`MapMasses::bodies`] resolves its inertia), all relative to an
/// inertial frame.
///
/// Book: §9.14; (7.4.4), (7.6.1).
#[derive(Debug, Clone)]
pub struct BodyMotion<T: Scalar> {
    /// v⃗_{c/w/A}.
    pub v_c: Vector<T>,
    /// ω⃗_{B/A}.
    pub omega: Vector<T>,
    /// F_B.
    pub frame: Frame<T>,
}

/// Applied loads: a force on each particle, and a force through each mass centre with a
/// moment about it. Empty lists mean no loads.
///
/// Book: §9.14, §9.5.
#[derive(Debug, Clone, Default)]
pub struct KaneLoads {
    /// F⃗_i on particle i.
    pub particles: Vec<Vector<f64>>,
    /// (F⃗, M⃗_c) on body b: the resultant through c and the moment about c.
    pub bodies: Vec<(Vector<f64>, Vector<f64>)>,
}

/// A system for Kane's equations. Velocities must be linear in u; constants with `T::lit`.
///
/// Book: §9.14.
pub trait KaneSystem {
    /// Number of generalized coordinates n.
    fn coordinates(&self) -> usize;
    /// Number of generalized speeds p (independent and dependent).
    fn speeds(&self) -> usize;
    /// Particle masses and body (mass, inertia about c resolved in F_B).
    fn masses(&self) -> MapMasses;
    /// The kinematical differential equations q̇ = f(q, u, t), written into `qd` (zeros on
    /// entry).
    fn kinematic_equations<T: Scalar>(&self, q: &[T], u: &[T], t: T, qd: &mut [T]);
    /// Particle velocities v⃗_i(q, u, t).
    fn particle_velocities<T: Scalar>(&self, q: &[T], u: &[T], t: T) -> Vec<Vector<T>> {
        let _ = (q, u, t);
        Vec::new()
    }
    /// Body motions (v⃗_c, ω⃗, F_B)(q, u, t).
    fn body_motions<T: Scalar>(&self, q: &[T], u: &[T], t: T) -> Vec<BodyMotion<T>> {
        let _ = (q, u, t);
        Vec::new()
    }
    /// The applied loads at (q, u, t); none by default.
    fn loads(&self, q: &[f64], u: &[f64], t: f64) -> KaneLoads {
        let _ = (q, u, t);
        KaneLoads::default()
    }
    /// Number k of speed constraints A(q, t) u + b(q, t) = 0; the last k speeds are the
    /// dependent ones.
    fn speed_constraint_count(&self) -> usize {
        0
    }
    /// ψ(q, u, t) = A(q, t) u + b(q, t), written into `out` (length k, zeros on entry).
    fn speed_constraints<T: Scalar>(&self, q: &[T], u: &[T], t: T, out: &mut [T]) {
        let _ = (q, u, t, out);
    }
}

/// Partial velocities and partial angular velocities, resolved in `Frame::identity()` (the
/// inertial frame of the user's velocities).
///
/// Book: §9.14.
#[derive(Debug, Clone, PartialEq)]
pub struct PartialVelocities {
    /// `particles[r][i]` = ∂v⃗_i/∂u_r.
    pub particles: Vec<Vec<Vector3<f64>>>,
    /// `bodies[r][b]` = (∂v⃗_c/∂u_r, ∂ω⃗/∂u_r).
    pub bodies: Vec<Vec<(Vector3<f64>, Vector3<f64>)>>,
}

/// The result of [`kane_accelerations`].
///
/// Book: §9.14.
#[derive(Debug, Clone, PartialEq)]
pub struct KaneSolution {
    /// All p speeds u = [u_i; u_d], the dependent ones from the speed constraints.
    pub u: DVector<f64>,
    /// q̇ = f(q, u, t).
    pub qd: DVector<f64>,
    /// u̇ (all p speeds).
    pub ud: DVector<f64>,
    /// The reduced generalized mass Cᵀ K C (K when there are no speed constraints).
    pub mass: DMatrix<f64>,
    /// The reduced right-hand side Cᵀ(F − F*₀ − K w).
    pub forcing: DVector<f64>,
}

pub(crate) fn resolve<T: Scalar>(v: &Vector<T>) -> Vector3<T> {
    v.resolve(&Frame::<T>::identity())
}

/// ∂v⃗/∂u_r for every speed r: one dual evaluation per speed.
///
/// Book: §9.14.
///
/// # Errors
/// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`].
pub fn partial_velocities<K: KaneSystem>(
    sys: &K,
    q: &[f64],
    u: &[f64],
    t: f64,
) -> Result<PartialVelocities, DynamicsError> {
    check_len(q.len(), sys.coordinates(), "q")?;
    check_len(u.len(), sys.speeds(), "u")?;
    check_finite(q, "q")?;
    check_finite(u, "u")?;
    check_finite(&[t], "t")?;
    let (qv, td, mut ur) = (duals(q), Dual64::from(t), duals(u));
    let (mut particles, mut bodies) = (Vec::new(), Vec::new());
    for r in 0..u.len() {
        ur[r].eps = 1.0;
        let eps = |v: &Vector<Dual64>| resolve(v).map(|d| d.eps);
        particles.push(sys.particle_velocities(&qv, &ur, td).iter().map(eps).collect::<Vec<_>>());
        bodies.push(
            sys.body_motions(&qv, &ur, td).iter().map(|b| (eps(&b.v_c), eps(&b.omega))).collect::<Vec<_>>(),
        );
        ur[r].eps = 0.0;
    }
    let all = particles.iter().flatten().chain(bodies.iter().flatten().flat_map(|(v, w)| [v, w]));
    if !all.flat_map(|v| v.iter()).all(|x| x.is_finite()) {
        return Err(DynamicsError::NonFinite { what: "partial velocities" });
    }
    Ok(PartialVelocities { particles, bodies })
}
