//! Drift control of a scene's closed loops and rolling contacts: after every accepted step
//! (and at every output sample) the state is projected back onto the constraints, positions
//! by Gauss–Newton in the mass metric onto φ(q) = 0 (loops), velocities M-orthogonally onto
//! G(q) v = 0 (loops and rolling contacts), and the integration restarts from the projected
//! state (HNW §VII.2). The largest violation left is reported in [`Run`](super::Run) and in
//! summary.json.
//!
//! Book: §9.11 (holonomic constraints), §9.12 (nonholonomic), §4.18 (rolling).

use std::cell::RefCell;

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::kin::{Kin, kinematics};
use super::loops::{rows_of, select, select_v};
use super::{Scene, SceneError};
use vectrix_dynamics::DynamicsError;
use vectrix_dynamics::constraints::{
    DEPENDENT_ROW_REL_TOL, ProjectionOptions, project_positions, project_velocities,
};

/// Target of the projection after each step, relative to the scene's size: |φ|∞ ≤
/// `CONSTRAINT_TOL`·L with L the largest distance of a loop point from the origin (at least
/// 1 m), and |G v|∞ ≤ `CONSTRAINT_TOL`·L·max(1, |v|∞).
pub const CONSTRAINT_TOL: f64 = 1e-12;

/// An initial state farther than `ASSEMBLY_TOL`·L from the loop constraints (in position or
/// velocity, scaled as for [`CONSTRAINT_TOL`]) is refused unless the scene says
/// `assemble = true`, which projects it.
pub const ASSEMBLY_TOL: f64 = 1e-9;

/// The largest violation of the loop and rolling constraints over a run, after projection:
/// what the written rows satisfy.
///
/// Book: §9.11, §9.12.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct ConstraintViolation {
    /// max |φ(q)|∞ of the loop constraints (m; a pin's two axis rows are dimensionless).
    pub position: f64,
    /// max |G v|∞ of the loop and rolling constraints (m/s; rad/s for a pin's axis rows).
    pub velocity: f64,
}

impl ConstraintViolation {
    /// The larger of each component.
    pub(crate) fn max(self, o: Self) -> Self {
        Self { position: self.position.max(o.position), velocity: self.velocity.max(o.velocity) }
    }
}

/// The independent rows found last (position rows: loops; velocity rows: loops and rolling),
/// kept between projections.
#[derive(Debug, Default)]
pub(crate) struct ProjectScratch {
    pos: Option<Vec<usize>>,
    vel: Option<Vec<usize>>,
}

impl Scene {
    /// Whether the scene has constraints whose drift is projected away (loops, rolling).
    pub(crate) fn has_constraints(&self) -> bool {
        self.needs.loops || self.needs.rolling
    }

    /// The length scale L of the tolerances: the largest distance of a loop point from the
    /// origin at q₀, at least 1.
    pub(crate) fn constraint_scale(&self) -> f64 {
        let b = &self.built;
        let v0 = vec![0.0; b.model.nv()];
        let Ok(kin) = kinematics(&b.model, &b.q0, &v0) else { return 1.0 };
        b.loops.iter().flat_map(|l| [kin.point(&l.a).0.norm(), kin.point(&l.b).0.norm()]).fold(1.0, f64::max)
    }

    /// φ(q) of the loops and their rows of G (v does not enter).
    fn loop_terms(&self, q: &[f64]) -> Result<(DVector<f64>, DMatrix<f64>), String> {
        let b = &self.built;
        let kin = kinematics(&b.model, q, &vec![0.0; b.model.nv()])?;
        let mut phi = Vec::new();
        self.loop_phi(&kin, q, &mut phi);
        Ok((DVector::from_vec(phi), self.velocity_jacobian(&kin, false)?))
    }

    /// The violation at y = (q, v): |φ(q)|∞ and |G v|∞, with the per-row values of the loops.
    pub(crate) fn violation(&self, y: &[f64]) -> Result<(ConstraintViolation, Vec<f64>, Vec<f64>), String> {
        let b = &self.built;
        let (q, v) = y.split_at(b.model.nq());
        let kin: Kin = kinematics(&b.model, q, v)?;
        let mut phi = Vec::new();
        self.loop_phi(&kin, q, &mut phi);
        let rate = self.velocity_jacobian(&kin, true)? * DVector::from_column_slice(v);
        let amax = |x: &[f64]| x.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
        let viol = ConstraintViolation { position: amax(&phi), velocity: amax(rate.as_slice()) };
        Ok((viol, phi, rate.as_slice().to_vec()))
    }

    /// The tolerances (position, velocity) at velocity v for a relative level `rel`.
    pub(crate) fn constraint_tols(&self, v: &[f64], rel: f64) -> (f64, f64) {
        let l = self.loop_scale;
        let vmax = v.iter().fold(1.0_f64, |m, c| m.max(c.abs()));
        (rel * l, rel * l * vmax)
    }

    /// Projects y onto the constraints when it violates them by more than [`CONSTRAINT_TOL`];
    /// returns the violation before and after (equal when nothing was done).
    pub(crate) fn project(
        &self,
        y: &mut [f64],
        w: &mut ProjectScratch,
    ) -> Result<(ConstraintViolation, ConstraintViolation), String> {
        let b = &self.built;
        let nq = b.model.nq();
        let (before, ..) = self.violation(y)?;
        let (tol_p, tol_v) = self.constraint_tols(&y[nq..], CONSTRAINT_TOL);
        if before.position <= tol_p && before.velocity <= tol_v {
            return Ok((before, before));
        }
        let m = b.model.crba(&y[..nq]).map_err(|e| e.to_string())?;
        if !b.loops.is_empty() && before.position > tol_p {
            let failure = RefCell::new(None::<String>);
            let keep = RefCell::new(w.pos.take());
            let constraints = |q: &[f64]| -> Result<(DVector<f64>, DMatrix<f64>), DynamicsError> {
                let (phi, g) = self.loop_terms(q).map_err(|e| {
                    failure.borrow_mut().get_or_insert(e);
                    DynamicsError::NonFinite { what: "loop constraints" }
                })?;
                let rows = rows_of(&m, &g, &mut keep.borrow_mut())?;
                Ok((select_v(&phi, &rows), select(&g, &rows)))
            };
            let retract = |q: &[f64], d: &DVector<f64>| b.model.integrate(q, d.as_slice(), 1.0);
            let opts = ProjectionOptions { tol: tol_p, max_iterations: 20, rank_tol: DEPENDENT_ROW_REL_TOL };
            let p = project_positions(&y[..nq], &m, constraints, retract, &opts)
                .map_err(|e| failure.borrow_mut().take().unwrap_or_else(|| e.to_string()))?;
            w.pos = keep.into_inner();
            y[..nq].copy_from_slice(&p.q);
            b.model.normalize_quaternions(&mut y[..nq]);
        }
        // velocities at the projected positions: loops and rolling contacts
        let (q, v) = y.split_at_mut(nq);
        let kin = kinematics(&b.model, q, v)?;
        let g = self.velocity_jacobian(&kin, true)?;
        if g.nrows() > 0 {
            let m = b.model.crba(q).map_err(|e| e.to_string())?;
            let rows = rows_of(&m, &g, &mut w.vel).map_err(|e| e.to_string())?;
            let gs = select(&g, &rows);
            let vv = DVector::from_column_slice(v);
            let r = &gs * &vv;
            let vn =
                project_velocities(&vv, &m, &gs, &r, DEPENDENT_ROW_REL_TOL).map_err(|e| e.to_string())?;
            v.copy_from_slice(vn.as_slice());
        }
        let (after, phi, _) = self.violation(y)?;
        let (tol_p, _) = self.constraint_tols(&y[nq..], CONSTRAINT_TOL);
        if after.position > 1e3 * tol_p {
            // a dropped (dependent) row that the kept ones do not satisfy
            let worst = self.worst_loop(&phi);
            return Err(format!(
                "the loop constraints cannot all hold: `{worst}` is violated by {:.3e} after projection; valid: \
                 loop joints consistent with the tree (e.g. pins of a planar mechanism with parallel axes)",
                after.position
            ));
        }
        Ok((before, after))
    }

    /// The name of the loop with the largest |row| of `rows` (loop rows in loop order).
    pub(crate) fn worst_loop(&self, rows: &[f64]) -> String {
        let mut k = 0;
        let mut worst = (0.0, String::new());
        for l in &self.built.loops {
            let n = l.rows();
            let m = rows.get(k..k + n).map_or(0.0, |r| r.iter().fold(0.0_f64, |a, c| a.max(c.abs())));
            if m >= worst.0 {
                worst = (m, l.name.clone());
            }
            k += n;
        }
        worst.1
    }

    /// At load: an initial state off the loop constraints is refused, or projected when the
    /// scene says `assemble = true`.
    pub(crate) fn assemble(&mut self, src: &super::SceneSource) -> Result<(), SceneError> {
        if self.built.loops.is_empty() {
            return Ok(());
        }
        let mut y0 = self.initial_state();
        let nq = self.built.model.nq();
        let (v0, phi, rate) = self.violation(&y0).map_err(|m| {
            src.invalid("loops", format!("the loop constraints cannot be evaluated at q₀: {m}"))
        })?;
        let (tol_p, tol_v) = self.constraint_tols(&y0[nq..], ASSEMBLY_TOL);
        let nloop: usize = self.built.loops.iter().map(|l| l.rows()).sum();
        let loop_rate = &rate[..nloop.min(rate.len())];
        let rate_max = loop_rate.iter().fold(0.0_f64, |a, c| a.max(c.abs()));
        if v0.position <= tol_p && rate_max <= tol_v {
            return Ok(());
        }
        if !self.spec().assemble {
            let (what, worst, by) = if v0.position > tol_p {
                ("position", self.worst_loop(&phi), v0.position)
            } else {
                ("velocity", self.worst_loop(loop_rate), rate_max)
            };
            let i = self.built.loops.iter().position(|l| l.name == worst).unwrap_or(0);
            return Err(src.invalid(
                format!("loops[{i}]"),
                format!(
                    "the initial state violates loop `{worst}` by {by:.3e} in {what} (tolerance {:.1e}); valid: \
                     initial coordinates and speeds that close the loop, or `assemble = true` to project them onto it",
                    if what == "position" { tol_p } else { tol_v }
                ),
            ));
        }
        let mut w = ProjectScratch::default();
        self.project(&mut y0, &mut w)
            .map_err(|m| src.invalid("assemble", format!("the mechanism cannot be assembled: {m}")))?;
        let (q, v) = y0.split_at(nq);
        self.built.q0 = q.to_vec();
        self.built.v0 = v.to_vec();
        Ok(())
    }
}
