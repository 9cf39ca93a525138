//! Scene state queries: for any state of a scene, in the scene's own coordinates, the kinetic
//! and potential energies, the mass matrix, the generalized forces and the accelerations, so
//! that a scene can be checked against a hand derivation (Lagrange's equations
//! M(q) v̇ = Q(q, v, t), §9.9).
//!
//! Book: §9.3 (T = ½ vᵀ M v), §9.8 (U), §9.9 (M q̈ = Q), §7.11 (CRBA and RNEA compute M and Q).

use nalgebra::{DMatrix, DVector};

use super::forces::{Loads, apply, potential};
use super::kin::kinematics;
use super::parts::Effect;
use super::{Scene, SceneError};
use vectrix_dynamics::multibody::JointWrench;

/// Everything a hand derivation of a scene's equations of motion can be compared with, at one
/// state (q, v) and time t, in the scene's coordinates (the q and v layouts of docs/scenes.md).
///
/// Book: §9.3, §9.8, §9.9.
#[derive(Debug, Clone, PartialEq)]
pub struct StateQuery {
    /// Kinetic energy T [J] (with the inerters' ½ b ℓ̇²).
    pub kinetic: f64,
    /// Potential energy U [J] of the conservative declared effects (uniform and central
    /// gravity, springs, rotational springs, dipoles, mutual gravitation).
    pub potential: f64,
    /// Mass matrix M(q) (nv × nv, with inerters), so that T = ½ vᵀ M v.
    pub mass_matrix: DMatrix<f64>,
    /// Generalized forces Q(q, v, t), everything but the inertia of M v̇ = Q: applied loads and
    /// gravity as generalized forces minus the velocity terms (Coriolis and centripetal),
    /// computed by Newton–Euler (RNEA at v̇ = 0). Without inerters or rolling, M v̇ = Q holds for
    /// the accelerations below; with them, Q leaves out the inerter and rolling-constraint
    /// terms.
    pub generalized_forces: DVector<f64>,
    /// Accelerations v̇ of the scene's right-hand side (ABA, then inerters and rolling).
    pub accelerations: DVector<f64>,
}

impl Scene {
    /// The [`StateQuery`] at time `t` and state y = (q, v) (quaternions are normalized first).
    ///
    /// Book: §9.3, §9.8, §9.9, §7.11.
    ///
    /// # Errors
    /// [`SceneError::Run`] for a state of the wrong length or with a non-finite entry, or
    /// when the dynamics fail there (a singular mass matrix, coincident points).
    pub fn query(&self, t: f64, y: &[f64]) -> Result<StateQuery, SceneError> {
        let b = &self.built;
        let (nq, nv) = (b.model.nq(), b.model.nv());
        let fail = |message: String| SceneError::Run { t, message };
        if y.len() != nq + nv {
            return Err(fail(format!("state of length {}; valid: nq + nv = {}", y.len(), nq + nv)));
        }
        if let Some(k) = y.iter().position(|x| !x.is_finite()) {
            return Err(fail(format!("state entry {k} is {}; valid: finite numbers", y[k])));
        }
        let mut y = y.to_vec();
        b.model.normalize_quaternions(&mut y[..nq]);
        let (q, v) = y.split_at(nq);
        let kin = kinematics(&b.model, q, v).map_err(fail)?;
        let kinetic = self.kinetic(&kin, v);
        let q_angle = |dof: usize| self.angle_of_dof(q, dof);
        let potential = potential(&b.effects, &b.bodies, &kin, &self.ground, &q_angle);
        let mut m = b.model.crba(q).map_err(|e| fail(e.to_string()))?;
        for e in &b.effects {
            if let Effect::RotInerter { dof, beta } = e {
                m[(*dof, *dof)] += beta;
            }
        }
        if self.needs.inerters {
            m = self.mass_with_inerters(&kin, m).map_err(fail)?;
        }
        // Q = τ_applied − RNEA(q, v, 0; loads): the joint forces that produce v̇ = 0, negated
        let mut tau = vec![0.0; nv];
        let mut wrenches = vec![JointWrench::default(); b.bodies.len()];
        let mut loads = Loads { kin: &kin, wrenches: &mut wrenches, tau: &mut tau };
        apply(&b.effects, &b.bodies, &self.ground, (t, None), v, &q_angle, None, &mut loads).map_err(fail)?;
        let id = b.model.rnea(q, v, &vec![0.0; nv], Some(&wrenches)).map_err(|e| fail(e.to_string()))?;
        let generalized_forces = DVector::from_iterator(nv, tau.iter().zip(&id.tau).map(|(a, r)| a - r));
        let accelerations = DVector::from_column_slice(&self.deriv(t, &y).map_err(fail)?[nq..]);
        Ok(StateQuery { kinetic, potential, mass_matrix: m, generalized_forces, accelerations })
    }
}
