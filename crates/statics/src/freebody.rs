//! Free-body analysis (book §6.10): unknown reactions from the laws of statics (§6.5),
//! solved by least squares, with statically indeterminate and inconsistent systems reported.
//!
//! Each body contributes six scalar equations, f⃗_B = 0⃗ and M⃗_{B/o} = 0⃗ (moments about the
//! problem's reference point o), resolved in a working frame. An unknown reaction is a
//! magnitude along a given direction (a force at a point, or a couple about an axis); when it
//! acts between two bodies, its third-law partner −f⃗ enters the other body's equations
//! (Fact 6.9.1–6.9.4). The system A x = b is solved through faer's SVD.

use faer::Mat;
use vectrix_tensor::Vector;

use crate::basis::vec3;
use crate::{AppliedForce, Point, StaticsError};

/// Default relative tolerance for rank and consistency: 2²⁰·ε ≈ 2.3e-10, relative to the
/// largest singular value and to the size of the loads.
///
/// Book: §6.5, §6.10.
pub const FREE_BODY_REL_TOL: f64 = 1_048_576.0 * f64::EPSILON;

/// A body of a [`FreeBodyProblem`].
///
/// Book: §6.5, §6.10.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BodyId(usize);

/// An unknown reaction of a [`FreeBodyProblem`].
///
/// Book: §6.5, §6.10.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct UnknownId(usize);

#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Force { direction: Vector, at: Point },
    Couple { axis: Vector },
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Unknown {
    on: usize,
    partner: Option<usize>,
    kind: Kind,
}

/// Whether the equilibrium equations determine the reactions.
///
/// Book: §6.10.
#[derive(Debug, Clone, PartialEq)]
pub enum Determinacy {
    /// rank = number of unknowns: one solution.
    Determinate,
    /// rank < number of unknowns: the reported values are the minimum-norm solution, and any
    /// combination of `self_stress` states may be added without disturbing equilibrium.
    Indeterminate {
        /// Degree of indeterminacy: unknowns − rank.
        degree: usize,
        /// An orthonormal basis of the null space (one vector of unknown values per state).
        self_stress: Vec<Vec<f64>>,
    },
}

/// A statics problem: bodies, known loads, unknown reactions.
///
/// Book: §6.5, §6.9, §6.10.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FreeBodyProblem {
    bodies: usize,
    forces: Vec<(usize, AppliedForce)>,
    couples: Vec<(usize, Vector)>,
    unknowns: Vec<Unknown>,
}

/// The reactions found by [`FreeBodyProblem::solve`].
///
/// Book: §6.5, §6.10.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeBodySolution {
    /// One value per unknown, in the order added: the component along the given unit direction.
    pub values: Vec<f64>,
    /// Rank of the equilibrium equations.
    pub rank: usize,
    /// Residual ‖A x − b‖ of the equilibrium equations (0 up to rounding when consistent).
    pub residual: f64,
    /// Determinate or indeterminate (with the self-stress states).
    pub determinacy: Determinacy,
    directions: Vec<Vector>,
}

impl FreeBodySolution {
    /// The value of one unknown; `None` for an id that belongs to another problem.
    ///
    /// Book: §6.5, §6.10.
    pub fn value(&self, u: UnknownId) -> Option<f64> {
        self.values.get(u.0).copied()
    }

    /// The reaction as a vector: value · d̂ (a force, or a couple along its axis); `None` for
    /// an id that belongs to another problem.
    ///
    /// Book: §6.5, §6.10.
    pub fn reaction(&self, u: UnknownId) -> Option<Vector> {
        Some(*self.directions.get(u.0)? * *self.values.get(u.0)?)
    }

    /// The solution, or [`StaticsError::Indeterminate`] when the equations do not fix it.
    ///
    /// Book: §6.5, §6.10.
    ///
    /// # Errors
    /// [`StaticsError::Indeterminate`].
    pub fn require_determinate(self) -> Result<Self, StaticsError> {
        match &self.determinacy {
            Determinacy::Determinate => Ok(self),
            Determinacy::Indeterminate { degree, .. } => Err(StaticsError::Indeterminate {
                degree: *degree,
                unknowns: self.values.len(),
                rank: self.rank,
            }),
        }
    }
}

impl FreeBodyProblem {
    /// An empty problem.
    ///
    /// Book: §6.5, §6.10.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a body and returns its id.
    ///
    /// Book: §6.5, §6.10.
    pub fn add_body(&mut self) -> BodyId {
        self.bodies += 1;
        BodyId(self.bodies - 1)
    }

    fn check_body(&self, b: BodyId) -> Result<usize, StaticsError> {
        if b.0 < self.bodies {
            Ok(b.0)
        } else {
            Err(StaticsError::UnknownBody { index: b.0, bodies: self.bodies })
        }
    }

    /// A known force f⃗ at y on body `on` (a load, e.g. a weight).
    ///
    /// Book: §6.5, §6.10.
    ///
    /// # Errors
    /// [`StaticsError::UnknownBody`], [`StaticsError::NonFinite`].
    pub fn apply_force(&mut self, on: BodyId, f: AppliedForce) -> Result<(), StaticsError> {
        let b = self.check_body(on)?;
        if !f.force.is_finite() || !f.at.is_finite() {
            return Err(StaticsError::NonFinite { what: "applied force" });
        }
        self.forces.push((b, f));
        Ok(())
    }

    /// A known couple (torque) M⃗ on body `on`.
    ///
    /// Book: §6.5, §6.10.
    ///
    /// # Errors
    /// [`StaticsError::UnknownBody`], [`StaticsError::NonFinite`].
    pub fn apply_couple(&mut self, on: BodyId, m: Vector) -> Result<(), StaticsError> {
        let b = self.check_body(on)?;
        if !m.is_finite() {
            return Err(StaticsError::NonFinite { what: "applied couple" });
        }
        self.couples.push((b, m));
        Ok(())
    }

    /// An unknown force of unknown magnitude along `direction` (normalised here) at y on body
    /// `on`; with `from = Some(other)` the equal and opposite force acts on `other` at the same
    /// point (Newton's third law, Fact 6.9.1); with `None` it comes from the ground.
    ///
    /// Book: §6.10, Fact 6.9.1.
    ///
    /// # Errors
    /// [`StaticsError::UnknownBody`], [`StaticsError::ZeroVector`], [`StaticsError::NonFinite`].
    pub fn unknown_force(
        &mut self,
        on: BodyId,
        from: Option<BodyId>,
        direction: Vector,
        at: Point,
    ) -> Result<UnknownId, StaticsError> {
        let on = self.check_body(on)?;
        let partner = from.map(|b| self.check_body(b)).transpose()?;
        if !direction.is_finite() || !at.is_finite() {
            return Err(StaticsError::NonFinite { what: "unknown force" });
        }
        let d = direction.unit().ok_or(StaticsError::ZeroVector { what: "reaction direction" })?;
        self.unknowns.push(Unknown { on, partner, kind: Kind::Force { direction: d, at } });
        Ok(UnknownId(self.unknowns.len() - 1))
    }

    /// An unknown couple about `axis` (normalised here) on body `on`, its partner on `from`.
    ///
    /// Book: §6.10, Fact 6.9.4.
    ///
    /// # Errors
    /// As [`FreeBodyProblem::unknown_force`].
    pub fn unknown_couple(
        &mut self,
        on: BodyId,
        from: Option<BodyId>,
        axis: Vector,
    ) -> Result<UnknownId, StaticsError> {
        let on = self.check_body(on)?;
        let partner = from.map(|b| self.check_body(b)).transpose()?;
        if !axis.is_finite() {
            return Err(StaticsError::NonFinite { what: "unknown couple" });
        }
        let d = axis.unit().ok_or(StaticsError::ZeroVector { what: "couple axis" })?;
        self.unknowns.push(Unknown { on, partner, kind: Kind::Couple { axis: d } });
        Ok(UnknownId(self.unknowns.len() - 1))
    }

    /// Number of unknown reactions.
    ///
    /// Book: §6.5, §6.10.
    pub fn unknown_count(&self) -> usize {
        self.unknowns.len()
    }

    /// Writes the (force, moment about o) of a unit unknown into column `col`.
    fn column(&self, a: &mut Mat<f64>, col: usize, u: &Unknown) {
        let o = Point::origin();
        let (f, m) = match u.kind {
            Kind::Force { direction, at } => (direction, AppliedForce::new(direction, at).moment_about(&o)),
            Kind::Couple { axis } => (Vector::zero(), axis),
        };
        let (f, m) = (vec3(&f), vec3(&m));
        for (body, sign) in [(Some(u.on), 1.0), (u.partner, -1.0)] {
            if let Some(b) = body {
                for k in 0..3 {
                    a[(6 * b + k, col)] += sign * f[k];
                    a[(6 * b + 3 + k, col)] += sign * m[k];
                }
            }
        }
    }

    /// Solves the laws of statics for the unknowns in the least-squares sense.
    ///
    /// Book: §6.5 (f⃗_B = 0⃗, M⃗_B = 0⃗ per body), §6.10.
    ///
    /// # Conventions
    /// `rel_tol` (use [`FREE_BODY_REL_TOL`]): singular values below rel_tol·σ_max count as zero;
    /// the system is inconsistent when ‖A x − b‖ > rel_tol·max(‖b‖, ‖A‖‖x‖, tiny).
    /// Indeterminate problems return the minimum-norm reactions with the null space.
    ///
    /// # Errors
    /// [`StaticsError::Inconsistent`] when no reactions balance the loads;
    /// [`StaticsError::Solver`] if the SVD fails.
    pub fn solve(&self, rel_tol: f64) -> Result<FreeBodySolution, StaticsError> {
        vectrix_tensor::check_tolerance(rel_tol, "rel_tol")?;
        let (rows, n) = (6 * self.bodies, self.unknowns.len());
        let o = Point::origin();
        // b = −(known loads), per body: [Σf; ΣM_{/o}]
        let mut b = vec![0.0; rows];
        for (body, f) in &self.forces {
            let (ff, mm) = (vec3(&f.force), vec3(&f.moment_about(&o)));
            for k in 0..3 {
                b[6 * body + k] -= ff[k];
                b[6 * body + 3 + k] -= mm[k];
            }
        }
        for (body, m) in &self.couples {
            let mm = vec3(m);
            for k in 0..3 {
                b[6 * body + 3 + k] -= mm[k];
            }
        }
        let directions: Vec<Vector> = self
            .unknowns
            .iter()
            .map(|u| match u.kind {
                Kind::Force { direction, .. } => direction,
                Kind::Couple { axis } => axis,
            })
            .collect();
        let b_norm = b.iter().map(|x| x * x).sum::<f64>().sqrt();
        if n == 0 {
            let tol = rel_tol * b_norm.max(f64::MIN_POSITIVE);
            if b_norm > tol {
                return Err(StaticsError::Inconsistent { residual: b_norm, tol });
            }
            return Ok(FreeBodySolution {
                values: vec![],
                rank: 0,
                residual: b_norm,
                determinacy: Determinacy::Determinate,
                directions,
            });
        }
        let mut a = Mat::<f64>::zeros(rows, n);
        for (col, u) in self.unknowns.iter().enumerate() {
            self.column(&mut a, col, u);
        }
        let svd = a.svd().map_err(|e| StaticsError::Solver { detail: format!("{e:?}") })?;
        let (u, s, v) = (svd.U(), svd.S().column_vector(), svd.V());
        let sigma: Vec<f64> = s.iter().copied().collect();
        let s_max = sigma.first().copied().unwrap_or(0.0);
        let rank = sigma.iter().filter(|&&x| x > rel_tol * s_max).count();
        // x = Σ_{k<rank} v_k (u_kᵀ b) / σ_k: the minimum-norm least-squares solution
        let mut x = vec![0.0; n];
        for (k, &sk) in sigma.iter().enumerate().take(rank) {
            let ub: f64 = (0..rows).map(|i| u[(i, k)] * b[i]).sum();
            for (j, xj) in x.iter_mut().enumerate() {
                *xj += v[(j, k)] * ub / sk;
            }
        }
        // residual ‖A x − b‖
        let residual = (0..rows)
            .map(|i| {
                let ax: f64 = (0..n).map(|j| a[(i, j)] * x[j]).sum();
                (ax - b[i]).powi(2)
            })
            .sum::<f64>()
            .sqrt();
        let x_norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        let tol = rel_tol * b_norm.max(s_max * x_norm).max(f64::MIN_POSITIVE);
        if residual > tol {
            return Err(StaticsError::Inconsistent { residual, tol });
        }
        let determinacy = if rank == n {
            Determinacy::Determinate
        } else {
            let self_stress = (rank..n).map(|k| (0..n).map(|j| v[(j, k)]).collect()).collect();
            Determinacy::Indeterminate { degree: n - rank, self_stress }
        };
        Ok(FreeBodySolution { values: x, rank, residual, determinacy, directions })
    }
}
