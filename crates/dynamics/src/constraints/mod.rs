//! Constrained Lagrangian dynamics (book §9.11–9.12), Kane's equations (§9.14) and drift
//! control, without symbols.
//!
//! A user states the constraints once, generic over the scalar, as methods of
//! [`Constraints`]:
//!
//! * holonomic φ(q, t) = 0 (§9.11): vectrix gets Φ_q from one dual evaluation per
//!   coordinate, and the velocity and acceleration terms from one hyper-dual evaluation along
//!   the flow direction (q̇, 1) in (q, t): its ε₁ part is φ̇ = Φ_q q̇ + Φ_t and its ε₁ε₂ part is
//!   (Φ_q q̇)_q q̇ + 2Φ_qt q̇ + Φ_tt, so that φ̈ = 0 reads Φ_q q̈ = γ with
//!   γ = −[(Φ_q q̇)_q q̇ + 2Φ_qt q̇ + Φ_tt], exactly;
//! * nonholonomic ψ(q, q̇, t) = A(q, t) q̇ + b(q, t) = 0 (§9.12): A = ∂ψ/∂q̇ by duals on q̇,
//!   and ψ̇ = A q̈ + ψ_q q̇ + ψ_t, so γ = −(ψ_q q̇ + ψ_t) from one dual evaluation along
//!   (q̇, 1) with q̇ held.
//!
//! With G = [Φ_q; A] the equations of motion M q̈ = f (Lagrange's equations (9.9.7) or the
//! kinematic-map form) become the index-1 system
//!
//! ```text
//! [ M  Gᵀ ] [ q̈ ]   [ f ]
//! [ G  0  ] [ λ ] = [ γ ]
//! ```
//!
//! solved by Cholesky of M and a row-ordered QR of L⁻¹Gᵀ ([`KktFactor`]) that names the
//! first redundant or singular constraint row.
//!
//! # Conventions
//! * Constraint rows are numbered holonomic first (0..m), then velocity rows (m..m + k).
//! * **Sign of λ**: the generalized constraint force is Q_c = −Gᵀλ, so that
//!   M q̈ = f − Gᵀλ. For a particle on a rod, φ = |r⃗| − l, Φ_q = r̂ᵀ and the rod pulls on
//!   the particle with −λ r̂: λ is the tension (T = m(g cos θ + l θ̇²) for a pendulum).
//!   For a velocity row ψ = n̂·v⃗_x (a point x that must not move along n̂), −λ is the
//!   component along n̂ of the reaction force at x.
//! * Nonholonomic constraints are linear in q̇ (§9.12); the multipliers follow d'Alembert's
//!   principle (the reaction does no work on velocities that satisfy A q̇ = 0).
//!
//! ```
//! use vectrix_dynamics::constraints::{Constraints, constrained_accelerations};
//! use vectrix_dynamics::{DynamicsError, Lagrangian};
//! use vectrix_tensor::Scalar;
//!
//! /// A pendulum as a particle on a rod: q = (x, y), y up, φ = |r⃗| − l.
//! struct Rod { m: f64, l: f64, g: f64 }
//! impl Lagrangian for Rod {
//!     fn dof(&self) -> usize { 2 }
//!     fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
//!         T::lit(0.5 * self.m) * (qd[0] * qd[0] + qd[1] * qd[1])
//!     }
//!     fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T { T::lit(self.m * self.g) * q[1] }
//! }
//! impl Constraints for Rod {
//!     fn constraint_count(&self) -> usize { 1 }
//!     fn constraints<T: Scalar>(&self, q: &[T], _t: T, out: &mut [T]) {
//!         out[0] = (q[0] * q[0] + q[1] * q[1]).sqrt() - T::lit(self.l);
//!     }
//! }
//! let rod = Rod { m: 1.0, l: 1.0, g: 9.81 };
//! let s = constrained_accelerations(&rod, &[0.0, -1.0], &[2.0, 0.0], 0.0)?;
//! // hanging, moving at 2 m/s: the tension is m(g + v²/l), and the bob accelerates upward at v²/l
//! assert!((s.lambda[0] - (9.81 + 4.0)).abs() < 1e-12);
//! assert!((s.qdd[1] - 4.0).abs() < 1e-12);
//! # Ok::<(), DynamicsError>(())
//! ```
//!
//! Book: §9.11, §9.12, §9.14 (stubs in the text: the formulation here is the standard one,
//! e.g. Haug, *Computer-Aided Kinematics and Dynamics* ch. 11; Kane & Levinson, *Dynamics*).

mod eval;
mod integrate;
pub mod kane;
mod kkt;
mod project;

pub use eval::{
    ConstrainedSolution, ConstraintTerms, constrained_accelerations, constraint_terms,
    map_constrained_accelerations, solve_constrained,
};
pub use integrate::{ConstrainedIntegrator, ConstrainedRun, Violation, constraint_violation};
pub use kkt::{DEPENDENT_ROW_REL_TOL, KktFactor, KktSolution, solve_kkt};
pub use project::{PositionProjection, ProjectionOptions, project_positions, project_velocities};

use nalgebra::{DMatrix, DVector};
use vectrix_tensor::Scalar;

use crate::DynamicsError;
use crate::lagrange::{
    KinematicMap, Lagrangian, lagrange_terms, map_equations, map_mass_matrix, mass_matrix,
};

/// Constraints on a mechanical system, generic over the scalar so that vectrix
/// differentiates them with dual numbers. Implement the methods you need; the defaults
/// state no constraint.
///
/// Book: §9.11 (holonomic), §9.12 (nonholonomic).
///
/// # Conventions
/// `out` has the length of the matching count and holds zeros on entry. Write constants
/// with `T::lit(x)`. Holonomic rows come first in every Jacobian, λ and error row index.
pub trait Constraints {
    /// Number m of holonomic constraints φ(q, t) = 0.
    fn constraint_count(&self) -> usize {
        0
    }
    /// φ(q, t) (§9.11): written into `out` (length m).
    fn constraints<T: Scalar>(&self, q: &[T], t: T, out: &mut [T]) {
        let _ = (q, t, out);
    }
    /// Number k of velocity (nonholonomic) constraints A(q, t) q̇ + b(q, t) = 0.
    fn velocity_constraint_count(&self) -> usize {
        0
    }
    /// ψ(q, q̇, t) = A(q, t) q̇ + b(q, t) (§9.12), linear in q̇: written into `out` (length k).
    fn velocity_constraints<T: Scalar>(&self, q: &[T], qd: &[T], t: T, out: &mut [T]) {
        let _ = (q, qd, t, out);
    }
}

/// A constrained system in any form that gives M q̈ = f: what [`solve_constrained`] and
/// [`ConstrainedIntegrator`] need. Implemented by [`LagrangeForm`] and [`MapForm`]; a scene
/// or a hand-written model can implement it directly.
///
/// Book: §9.11.
pub trait ConstrainedSystem: Constraints {
    /// Number of generalized coordinates n.
    fn dof(&self) -> usize;
    /// The unconstrained equations of motion M(q, t) q̈ = f(q, q̇, t).
    ///
    /// # Errors
    /// Whatever the model reports ([`DynamicsError::DimensionMismatch`],
    /// [`DynamicsError::NonFinite`], …).
    fn equations(&self, q: &[f64], qd: &[f64], t: f64)
    -> Result<(DMatrix<f64>, DVector<f64>), DynamicsError>;
    /// M(q, t) alone (the metric of the projections); by default from
    /// [`ConstrainedSystem::equations`] at q̇ = 0.
    ///
    /// # Errors
    /// As [`ConstrainedSystem::equations`].
    fn mass(&self, q: &[f64], t: f64) -> Result<DMatrix<f64>, DynamicsError> {
        Ok(self.equations(q, &vec![0.0; q.len()], t)?.0)
    }
}

/// A [`Lagrangian`] with [`Constraints`], as a [`ConstrainedSystem`]: M and f from
/// Lagrange's equations (9.9.7).
///
/// Book: §9.9, §9.11.
#[derive(Debug, Clone, Copy)]
pub struct LagrangeForm<'a, L>(pub &'a L);

/// A [`KinematicMap`] with [`Constraints`], as a [`ConstrainedSystem`]: M and f built from
/// the particle positions and body poses (9.3.12).
///
/// Book: §9.3, §9.11.
#[derive(Debug, Clone, Copy)]
pub struct MapForm<'a, K>(pub &'a K);

/// Forwards every [`Constraints`] method to the wrapped system.
macro_rules! forward_constraints {
    ($wrapper:ident, $bound:ident) => {
        impl<S: $bound + Constraints> Constraints for $wrapper<'_, S> {
            fn constraint_count(&self) -> usize {
                self.0.constraint_count()
            }
            fn constraints<T: Scalar>(&self, q: &[T], t: T, out: &mut [T]) {
                self.0.constraints(q, t, out)
            }
            fn velocity_constraint_count(&self) -> usize {
                self.0.velocity_constraint_count()
            }
            fn velocity_constraints<T: Scalar>(&self, q: &[T], qd: &[T], t: T, out: &mut [T]) {
                self.0.velocity_constraints(q, qd, t, out)
            }
        }
    };
}
forward_constraints!(LagrangeForm, Lagrangian);
forward_constraints!(MapForm, KinematicMap);

impl<L: Lagrangian + Constraints> ConstrainedSystem for LagrangeForm<'_, L> {
    fn dof(&self) -> usize {
        Lagrangian::dof(self.0)
    }
    fn equations(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
    ) -> Result<(DMatrix<f64>, DVector<f64>), DynamicsError> {
        let terms = lagrange_terms(self.0, q, qd, t)?;
        let f = terms.rhs();
        Ok((terms.mass, f))
    }
    fn mass(&self, q: &[f64], t: f64) -> Result<DMatrix<f64>, DynamicsError> {
        mass_matrix(self.0, q, &vec![0.0; q.len()], t)
    }
}

impl<K: KinematicMap + Constraints> ConstrainedSystem for MapForm<'_, K> {
    fn dof(&self) -> usize {
        KinematicMap::dof(self.0)
    }
    fn equations(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
    ) -> Result<(DMatrix<f64>, DVector<f64>), DynamicsError> {
        map_equations(self.0, q, qd, t)
    }
    fn mass(&self, q: &[f64], t: f64) -> Result<DMatrix<f64>, DynamicsError> {
        map_mass_matrix(self.0, q, t)
    }
}
