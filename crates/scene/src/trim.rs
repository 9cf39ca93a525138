//! Trim: the initial state that makes a scene steady. The unknowns z are chosen by name among
//! a linearization's states and inputs (`dq:BODY.k`, `v:BODY.k`, `effects[k]`); the residual is
//! r(z) = v̇, every joint acceleration, which vanishes for an equilibrium (v = 0) and for a steady
//! motion (constant speeds: a top in steady precession in a gimbal, a body spinning about a
//! principal axis), with a free joint's velocity rate taken in its body's axes so that a steady
//! turn is steady; `[trim] hold` appends output columns minus their targets (an aircraft's β = 0
//! and turn rate). Gauss–Newton with the exact Jacobian ∂v̇/∂z (dual numbers, as
//! [`Scene::jacobian`]) and a halving line search; after each step the configuration is
//! rebased (q₀ ← q₀ ⊕ δ), so ball and free joints stay on their unit quaternions.
//!
//! Book: §12.3 (trim of steady flight), §12.5 (turning flight), §12.6 (about a reference motion), §8.5 (equilibria).

use std::collections::BTreeMap;

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::spec::SceneSpec;
use super::{Scene, SceneError};

/// Newton iterations at most.
const MAX_ITERATIONS: usize = 60;
/// A trimmed state is steady when every |v̇| is at most this (SI), as
/// [`super::EQUILIBRIUM_TOL`] for a linearization.
pub const TRIM_TOL: f64 = 1e-9;

/// What a trim found.
///
/// Book: §12.3.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrimReport {
    /// The unknowns, as named in `[trim] free`.
    pub free: Vec<String>,
    /// Their change from the file's values (for `dq:` the displacement in the joint's tangent
    /// space; for `v:` and `effects[k]` the added speed or magnitude).
    pub change: Vec<f64>,
    /// |v̇|∞ at the trimmed state.
    pub residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
}

/// One unknown: an index into x = (δ, v) or into the inputs u.
#[derive(Debug, Clone, Copy)]
enum Unknown {
    State(usize),
    Input(usize),
}

impl Scene {
    /// Resolves `[trim] free` (errors located at `trim.free[i]`).
    fn trim_unknowns(&self, free: &[String]) -> Result<Vec<Unknown>, SceneError> {
        let states = self.state_names();
        let inputs = self.input_names();
        let mut out = Vec::new();
        for (i, name) in free.iter().enumerate() {
            let path = format!("trim.free[{i}]");
            let u = if let Some(j) = states.iter().position(|s| s == name) {
                Unknown::State(j)
            } else if let Some(j) = inputs.iter().position(|k| k == name) {
                Unknown::Input(j)
            } else {
                return Err(self.invalid(
                    &path,
                    format!(
                        "unknown `{name}`; valid: a state ({}) or a force or torque input ({})",
                        states.join(", "),
                        if inputs.is_empty() { "none declared".into() } else { inputs.join(", ") }
                    ),
                ));
            };
            if free[..i].contains(name) {
                return Err(self.invalid(&path, format!("`{name}` is named twice; valid: each unknown once")));
            }
            out.push(u);
        }
        if out.is_empty() {
            return Err(self.invalid("trim.free", "no unknowns; valid: at least one state or input name"));
        }
        Ok(out)
    }

    /// The spec of this scene with its initial state made steady by the unknowns `free` (see
    /// the module doc), and what the trim found.
    ///
    /// Book: §12.3, §12.6.
    ///
    /// # Errors
    /// [`SceneError::Invalid`] located at `trim.free` for unknown names, scenes whose
    /// right-hand side is not generic yet (loops, rolling, inerters), and a state that could
    /// not be made steady (naming the accelerations that stay, and their size).
    pub fn trimmed(&self, free: &[String]) -> Result<(SceneSpec, TrimReport), SceneError> {
        self.trimmed_holding(free, &BTreeMap::new())
    }

    /// Resolves `[trim] hold` to (column index, target) (errors located at `trim.hold`).
    fn trim_holds(&self, hold: &BTreeMap<String, f64>) -> Result<Vec<(usize, f64)>, SceneError> {
        let columns = self.columns();
        hold.iter()
            .map(|(name, target)| {
                let at = format!("trim.hold.{name}");
                if !target.is_finite() {
                    return Err(self.invalid(&at, format!("{name} = {target}; valid: a finite value")));
                }
                let c = columns.iter().position(|c| c == name).ok_or_else(|| {
                    self.invalid(
                        &at,
                        format!(
                            "`{name}` is not an output column of this scene; valid: one of {} (declare the \
                             output in `outputs` to hold it)",
                            if columns.is_empty() { "none".to_string() } else { columns.join(", ") }
                        ),
                    )
                })?;
                Ok((c, *target))
            })
            .collect()
    }

    /// [`Scene::trimmed`] with output columns held at targets (`[trim] hold`): the residual is
    /// every joint acceleration (a free joint's velocity in its body's axes, so that a steady
    /// turn counts as steady) and each held column minus its target.
    ///
    /// Book: §12.3–12.5 (straight and turning flight), §8.5.
    ///
    /// # Errors
    /// As [`Scene::trimmed`]; a held name that is not an output column, or a non-finite target.
    pub fn trimmed_holding(
        &self,
        free: &[String],
        hold: &BTreeMap<String, f64>,
    ) -> Result<(SceneSpec, TrimReport), SceneError> {
        let unknowns = self.trim_unknowns(free)?;
        let holds = self.trim_holds(hold)?;
        let holding = Some(holds.as_slice());
        if !self.tree_only() {
            return Err(self.invalid(
                "trim",
                "scenes with loops, rolling or inerters are not trimmed yet (their right-hand side is f64 only); \
                 valid: a tree with force elements",
            ));
        }
        let b = &self.built;
        let (nq, nv) = (b.model.nq(), b.model.nv());
        let y0 = self.initial_state();
        let mut q = y0[..nq].to_vec();
        let mut x: Vec<f64> = [vec![0.0; nv], y0[nq..].to_vec()].concat();
        let mut u = vec![0.0; self.inputs().len()];
        let mut change = vec![0.0; unknowns.len()];
        let fail = |m: String| self.invalid("trim", m);
        let norm = |r: &[f64]| {
            r.iter().fold(0.0_f64, |m, x| if x.is_nan() || m.is_nan() { f64::NAN } else { m.max(x.abs()) })
        };
        let mut jac = self.jacobians_at(&q, &u, &x, holding).map_err(fail)?;
        let mut iterations = 0;
        // (NaN is not steady: `steady` is false for it)
        let steady = |r: f64| r <= TRIM_TOL;
        while !steady(norm(&jac.vdot)) && iterations < MAX_ITERATIONS {
            iterations += 1;
            // J Δ = −r, least squares over the chosen columns
            let j = DMatrix::from_fn(jac.vdot.len(), unknowns.len(), |i, k| match unknowns[k] {
                Unknown::State(s) => jac.vdot_x[(i, s)],
                Unknown::Input(s) => jac.vdot_u[(i, s)],
            });
            let r = -DVector::from_column_slice(&jac.vdot);
            let Ok(step) = j.svd(true, true).solve(&r, 1e-14) else { break };
            // halve the step until the residual falls (or give up on this direction)
            let r0 = norm(&jac.vdot);
            let mut scale = 1.0;
            let next = loop {
                let (mut xt, mut ut) = (x.clone(), u.clone());
                for (k, z) in unknowns.iter().enumerate() {
                    match z {
                        Unknown::State(s) => xt[*s] += scale * step[k],
                        Unknown::Input(s) => ut[*s] += scale * step[k],
                    }
                }
                match self.jacobians_at(&q, &ut, &xt, holding) {
                    Ok(jt) if norm(&jt.vdot) < r0 => break Some((xt, ut, jt)),
                    _ if scale < 1e-9 => break None,
                    _ => scale *= 0.5,
                }
            };
            let Some((xt, ut, jt)) = next else { break };
            for (k, c) in change.iter_mut().enumerate() {
                *c += scale * step[k];
            }
            // rebase: q ← q ⊕ δ, δ = 0 (quaternions stay unit)
            let mut qn = b.model.integrate(&q, &xt[..nv], 1.0).map_err(|e| fail(e.to_string()))?;
            b.model.normalize_quaternions(&mut qn);
            (q, u) = (qn, ut);
            x = [vec![0.0; nv], xt[nv..].to_vec()].concat();
            jac = if xt[..nv].iter().all(|d| *d == 0.0) {
                jt
            } else {
                self.jacobians_at(&q, &u, &x, holding).map_err(fail)?
            };
        }
        let residual = norm(&jac.vdot);
        if !steady(residual) {
            return Err(self.not_steady(free, iterations, &jac.vdot, &holds));
        }
        Ok((
            self.spec_with(&q, &x[nv..], &u),
            TrimReport { free: free.to_vec(), change, residual, iterations },
        ))
    }

    /// The error of a trim that left accelerations (or held columns) off target: which, and by
    /// how much, after `iterations` Newton steps.
    fn not_steady(
        &self,
        free: &[String],
        iterations: usize,
        vdot: &[f64],
        holds: &[(usize, f64)],
    ) -> SceneError {
        let nv = self.built.model.nv();
        let names = self.state_names();
        let stay: Vec<String> = vdot
            .iter()
            .enumerate()
            .filter(|(_, a)| a.abs() > TRIM_TOL || a.is_nan())
            .map(|(i, a)| match names.get(nv + i) {
                Some(n) if i < nv => format!("{n} (v̇ = {a:e})"),
                _ => {
                    let (c, target) = holds[i - nv];
                    format!("{} held at {target:e} (off by {a:e})", self.columns()[c])
                }
            })
            .collect();
        self.invalid(
            "trim.free",
            format!(
                "the state cannot be made steady by {}: after {iterations} Newton steps {} remain; valid: \
                 unknowns that can cancel every acceleration (as many as the accelerations they must cancel)",
                free.join(", "),
                stay.join(", ")
            ),
        )
    }

    /// This scene's spec with the initial coordinates q, speeds v and input magnitudes added.
    fn spec_with(&self, q: &[f64], v: &[f64], u: &[f64]) -> SceneSpec {
        let mut spec = self.spec().clone();
        for (body, b) in spec.bodies.iter_mut().zip(&self.built.bodies) {
            let (nq, nv) = (b.joint.nq(), b.joint.nv());
            body.q = (nq > 0).then(|| q[b.qi..b.qi + nq].to_vec());
            body.v = (nv > 0).then(|| v[b.vi..b.vi + nv].to_vec());
        }
        let mut profiles: Vec<&mut super::spec::Profile> =
            spec.effects.iter_mut().flat_map(|e| e.profiles_mut()).collect();
        for (p, du) in profiles.iter_mut().zip(u) {
            **p = p.shifted(*du);
        }
        spec
    }
}
