//! The joint-space mass matrix by the composite-rigid-body algorithm, and forward dynamics
//! by CRBA + Cholesky (the cross-check of the articulated-body algorithm).

use nalgebra::{DMatrix, DVector, Matrix6, Vector6};

use super::model::{Elem, Model};
use super::rnea::LinkWrenches;
use super::spatial::{Xform, join};
use crate::DynamicsError;

/// The columns of S for one elementary joint (6-vectors in (ω, v) ordering).
fn subspace(elem: &Elem) -> Vec<Vector6<f64>> {
    let z = nalgebra::Vector3::zeros();
    match elem {
        Elem::Revolute(a) => vec![join(a, &z)],
        Elem::Prismatic(a) => vec![join(&z, a)],
        Elem::Spherical => (0..3).map(|k| Vector6::ith(k, 1.0)).collect(),
        Elem::Fixed => vec![],
    }
}

impl Model {
    /// The joint-space mass matrix H(q) (symmetric, nv × nv) by the composite-rigid-body
    /// algorithm: composite inertias accumulated tip to base, H_ij = S_iᵀ Iᶜ_i X S_j.
    ///
    /// Book: §7.11 (the mass matrix of the chain), §9.3 (M(q) of (9.3.11)); RBDA Table 6.2.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`].
    pub fn crba(&self, q: &[f64]) -> Result<DMatrix<f64>, DynamicsError> {
        self.check_q(q)?;
        Ok(self.crba_unchecked(q))
    }

    /// [`Model::crba`] without input checks.
    pub fn crba_unchecked(&self, q: &[f64]) -> DMatrix<f64> {
        let n = self.segs.len();
        let x: Vec<Xform> = self.segs.iter().map(|s| s.placement.then(&s.elem.xform(&q[s.qi..]))).collect();
        let subspaces: Vec<Vec<Vector6<f64>>> = self.segs.iter().map(|s| subspace(&s.elem)).collect();
        // composite inertias, tip to base: Iᶜ_p += Xᵀ Iᶜ_i X
        let mut ic: Vec<Matrix6<f64>> = self.segs.iter().map(|s| s.inertia.matrix()).collect();
        for i in (0..n).rev() {
            if let Some(p) = self.segs[i].parent {
                let add = x[i].inertia_to_parent(&ic[i]);
                ic[p] += add;
            }
        }
        let mut h = DMatrix::zeros(self.nv, self.nv);
        for i in 0..n {
            for (ki, s) in subspaces[i].iter().enumerate() {
                let row = self.segs[i].vi + ki;
                // F = Iᶜ_i S_i, carried towards the base: H_ij = S_jᵀ F
                let mut f = ic[i] * s;
                for (kj, sj) in subspaces[i].iter().enumerate() {
                    h[(row, self.segs[i].vi + kj)] = sj.dot(&f);
                }
                let mut j = i;
                while let Some(p) = self.segs[j].parent {
                    f = x[j].force6_to_parent(&f);
                    j = p;
                    for (kj, sj) in subspaces[j].iter().enumerate() {
                        let col = self.segs[j].vi + kj;
                        let hij = sj.dot(&f);
                        h[(row, col)] = hij;
                        h[(col, row)] = hij;
                    }
                }
            }
        }
        h
    }

    /// Forward dynamics by H(q) v̇ = τ − C(q, v), C from [`Model::rnea`] with v̇ = 0, solved
    /// by Cholesky: O(n³), the cross-check of [`Model::aba`].
    ///
    /// Book: §7.11, §9.6 (M q̈ = Q − …).
    ///
    /// # Errors
    /// As [`Model::rnea`]; [`DynamicsError::SingularMassMatrix`] when H is not positive definite.
    pub fn forward_dynamics_crba(
        &self,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        f_ext: Option<&LinkWrenches>,
    ) -> Result<Vec<f64>, DynamicsError> {
        self.check_v(tau, "τ")?;
        let zero = vec![0.0; self.nv];
        let bias = self.rnea(q, v, &zero, f_ext)?.tau;
        let h = self.crba_unchecked(q);
        let rhs = DVector::from_iterator(self.nv, tau.iter().zip(&bias).map(|(t, c)| t - c));
        crate::lagrange::cholesky_solve(h, rhs).map(|x| x.as_slice().to_vec())
    }
}
