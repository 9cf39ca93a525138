//! Joint stops (`joint_stop` effects; a model's limits with `[model] limits = "contact"`): a
//! one-coordinate joint (pin or sleeve) kept in lower ≤ q ≤ upper by unilateral constraints.
//! They go through the contacts' machinery (`contacts`, `resting`): the gap is the distance
//! to the nearer stop, min(q − lower, upper − q), 1-Lipschitz in q, so touches are located
//! events and never stepped over. An impact is a generalized impulse P on the joint's
//! coordinate, Δv = M⁻¹ e_k P with P = −(1 + e) q̇ / (M⁻¹)_kk, so that q̇⁺ = −e q̇ (§7.14: the
//! impulse–momentum balance in generalized coordinates, M Δv = e_k P). A held stop pushes with
//! the generalized forces λ that keep q̈ = 0 at every held stop: (Eᵀ M⁻¹ E) λ = −Eᵀ v̇_free, until
//! one would have to pull (the lift-off event of `resting`).
//!
//! Book: §7.13 (restitution (7.13.18)), §7.14 (impulses), §7.11 (M(q) by CRBA).

use nalgebra::{DMatrix, DVector};

use super::Scene;
use super::contacts::stop_gap;
use super::parts::Effect;

/// A joint stop's data: coordinate and speed indices, stops, restitution.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Stop {
    pub qi: usize,
    pub vi: usize,
    pub lower: f64,
    pub upper: f64,
    pub e: f64,
}

impl Scene {
    /// Contact c's stop, if it is a joint stop.
    pub(crate) fn stop(&self, c: usize) -> Option<Stop> {
        match self.built.effects[self.contacts[c]] {
            Effect::JointStop { qi, vi, lower, upper, e, .. } => Some(Stop { qi, vi, lower, upper, e }),
            _ => None,
        }
    }

    /// M(q)⁻¹ E, E the unit columns `cols` (Cholesky of the CRBA mass matrix).
    fn minv_cols(&self, q: &[f64], cols: &[usize]) -> Result<DMatrix<f64>, String> {
        let m = self.built.model.crba(q).map_err(|e| e.to_string())?;
        let n = m.nrows();
        let chol = m.cholesky().ok_or("the mass matrix is not positive definite at a joint stop")?;
        let mut e = DMatrix::zeros(n, cols.len());
        for (j, &k) in cols.iter().enumerate() {
            e[(k, j)] = 1.0;
        }
        Ok(chol.solve(&e))
    }

    /// Resolves every touching, closing joint stop that is not held, one after the other, into
    /// v; returns them as (contact, closing speed, opening speed).
    pub(crate) fn stop_impacts(
        &self,
        q: &[f64],
        v: &mut [f64],
        resting: &[bool],
    ) -> Result<Vec<(usize, f64, f64)>, String> {
        let mut out = Vec::new();
        for c in 0..self.contacts.len() {
            let Some(s) = self.stop(c) else { continue };
            if resting.get(c).copied().unwrap_or(false) {
                continue;
            }
            let g = stop_gap(q[s.qi], v[s.vi], s.lower, s.upper);
            if !g.touches() || g.opening >= 0.0 {
                continue;
            }
            // M Δv = e_k P with Δq̇_k = −(1 + e) q̇_k
            let col = self.minv_cols(q, &[s.vi])?;
            let p = -(1.0 + s.e) * v[s.vi] / col[(s.vi, 0)];
            for (x, d) in v.iter_mut().zip(col.column(0).iter()) {
                *x += d * p;
            }
            out.push((c, -g.opening, -g.opening * s.e));
        }
        Ok(out)
    }

    /// Adds the held stops' generalized forces to v̇: λ with (Eᵀ M⁻¹ E) λ = −Eᵀ v̇ makes q̈ = 0
    /// at every held stop (the lift-off event ends a hold before λ would pull).
    pub(crate) fn stop_rest_forces(&self, q: &[f64], resting: &[bool], vd: &mut [f64]) -> Result<(), String> {
        let held: Vec<usize> =
            (0..resting.len()).filter(|&c| resting[c]).filter_map(|c| self.stop(c).map(|s| s.vi)).collect();
        if held.is_empty() {
            return Ok(());
        }
        let me = self.minv_cols(q, &held)?;
        let w = DMatrix::from_fn(held.len(), held.len(), |i, j| me[(held[i], j)]);
        let rhs = DVector::from_iterator(held.len(), held.iter().map(|&k| -vd[k]));
        let lambda = w.lu().solve(&rhs).ok_or("two held joint stops act on one coordinate")?;
        let dv = me * lambda;
        for (x, d) in vd.iter_mut().zip(dv.iter()) {
            *x += d;
        }
        Ok(())
    }
}
