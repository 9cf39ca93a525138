//! Exact (analytical) derivatives of inverse and forward dynamics: ∂τ/∂(q, v, v̇) of RNEA and
//! ∂v̇/∂(q, v, τ) of ABA, by one outward and one inward pass in ground coordinates
//! (Carpentier & Mansard, *Analytical derivatives of rigid body dynamics algorithms*, RSS 2018).
//!
//! Book: §7.11; §12–§15 (linearization about a state).
#![allow(non_snake_case)]

use nalgebra::{DMatrix, Vector6};
use vectrix_tensor::{FastPath, Scalar};

use super::model::{Model, Trig};
use super::spatial::{BodyInertia, Xform};
use super::wrench::LinkWrenches;
use crate::DynamicsError;

mod ltl;
mod passes;

use passes::Variation;

/// Derivatives of inverse dynamics τ = RNEA(q, v, v̇), computed by
/// [`Model::rnea_derivatives`] (and inside [`Model::aba_derivatives`]).
///
/// # Derivation (all spatial vectors in ground coordinates about the ground origin)
/// Moving joint coordinate j by δ moves the subtree of j rigidly by the screw Jⱼδ, where Jⱼ
/// is the joint's motion subspace in the ground. Every quantity attached to a body i of that
/// subtree then changes by Jⱼ × (·) (motions) or Jⱼ ×* (·) (forces, inertias), plus what
/// changes in the body's own motion:
/// * ∂vᵢ/∂qⱼ = Jⱼ × vᵢ + vλ × Jⱼ, with λ the parent of j (so dVdqⱼ = vλ × Jⱼ);
/// * ∂aᵢ/∂qⱼ = Jⱼ × aᵢ + dAdqⱼ + dVdqⱼ × vᵢ, dAdqⱼ = aλ × Jⱼ + vλ × dVdqⱼ (a with −g);
/// * ∂vᵢ/∂q̇ⱼ = Jⱼ and ∂aᵢ/∂q̇ⱼ = Jⱼ × vᵢ + dAdvⱼ, dAdvⱼ = vⱼ × Jⱼ + vλ × Jⱼ.
///
/// The body force fᵢ = Iᵢaᵢ + vᵢ ×* Iᵢvᵢ then has ∂fᵢ/∂qⱼ = Jⱼ ×* fᵢ + Iᵢ dAdqⱼ + Bᵢ dVdqⱼ
/// with Bᵢ = İᵢ + (· ×* Iᵢvᵢ) = [[Ī̇ − n^×, 0], [−2 f^×, 0]] ((n, f) = Iᵢvᵢ, the momentum).
/// All of it is linear in (Iᵢ, Bᵢ, fᵢ), so subtree sums (composites Iᶜ, Bᶜ, Fᶜ) give
/// τᵢ = JᵢᵀFᶜᵢ and
/// * ∂τᵢ/∂qⱼ = (IᶜᵢJᵢ)·dAdqⱼ + (BᶜᵢᵀJᵢ)·dVdqⱼ for j an ancestor of i (or i itself; the
///   Jⱼ × Jᵢ and Jⱼ ×* Fᶜᵢ terms cancel in the pairing),
/// * ∂τᵢ/∂qⱼ = Jᵢ·(Jⱼ ×* Fᶜⱼ + Iᶜⱼ dAdqⱼ + Bᶜⱼ dVdqⱼ) for j a descendant of i,
///
/// and the same with (dAdvⱼ, Jⱼ) for q̇ⱼ; ∂τ/∂v̇ = M. ABA's derivatives follow from
/// RNEA(q, v, ABA(q, v, τ)) = τ: ∂v̇/∂(q, v) = −M⁻¹ ∂τ/∂(q, v), ∂v̇/∂τ = M⁻¹.
///
/// # Tangent space
/// ∂/∂q is taken in the tangent space of the configuration, one column per velocity
/// coordinate: column k is d/dε f(q ⊕ ε eₖ) at ε = 0 with ⊕ = [`Model::integrate`]. For
/// scalar joints that is the ordinary partial derivative; for a ball joint (and the rotation
/// of a free joint) it is a rotation of the link about its own k-th axis (q ⊗ exp(ε eₖ/2)),
/// as Pinocchio does; the free joint's translation is ordinary (x, y, z are coordinates in
/// the joint frame, vectrix's free joint is ℝ³ × SO(3), not SE(3)).
///
///
/// Book: §7.11.
#[derive(Debug, Clone, PartialEq)]
pub struct RneaDerivatives<T: Scalar = f64> {
    /// τ at the point.
    pub tau: Vec<T>,
    /// ∂τ/∂q (nv × nv; column k along the tangent direction k).
    pub dtau_dq: DMatrix<T>,
    /// ∂τ/∂v (nv × nv).
    pub dtau_dv: DMatrix<T>,
    /// ∂τ/∂v̇ = M(q), the joint-space mass matrix.
    pub mass_matrix: DMatrix<T>,
}

impl<T: Scalar> RneaDerivatives<T> {
    /// Zero matrices sized for `model` (the output buffer of the `_into` hot path).
    pub fn zeros(model: &Model<T>) -> Self {
        let n = model.nv();
        Self {
            tau: vec![T::zero(); n],
            dtau_dq: DMatrix::zeros(n, n),
            dtau_dv: DMatrix::zeros(n, n),
            mass_matrix: DMatrix::zeros(n, n),
        }
    }
}

/// Derivatives of forward dynamics v̇ = ABA(q, v, τ) (tangent-space q-derivatives).
///
/// Book: §7.11.
#[derive(Debug, Clone, PartialEq)]
pub struct AbaDerivatives<T: Scalar = f64> {
    /// v̇ at the point.
    pub vdot: Vec<T>,
    /// ∂v̇/∂q (nv × nv; column k along the tangent direction k).
    pub dvdot_dq: DMatrix<T>,
    /// ∂v̇/∂v (nv × nv).
    pub dvdot_dv: DMatrix<T>,
    /// ∂v̇/∂τ = M(q)⁻¹.
    pub dvdot_dtau: DMatrix<T>,
}

impl<T: Scalar> AbaDerivatives<T> {
    /// Zero matrices sized for `model` (the output buffer of the `_into` hot path).
    pub fn zeros(model: &Model<T>) -> Self {
        let n = model.nv();
        Self {
            vdot: vec![T::zero(); n],
            dvdot_dq: DMatrix::zeros(n, n),
            dvdot_dv: DMatrix::zeros(n, n),
            dvdot_dtau: DMatrix::zeros(n, n),
        }
    }
}

/// Work space of the derivative algorithms (per segment, and per velocity coordinate).
#[derive(Debug, Clone)]
pub struct DerivativeScratch<T: Scalar = f64> {
    world: Vec<Xform<T>>,
    ov: Vec<Vector6<T>>,
    oa: Vec<Vector6<T>>,
    Yc: Vec<BodyInertia<T>>,
    Bc: Vec<Variation<T>>,
    Fc: Vec<Vector6<T>>,
    /// Per velocity coordinate: J, dVdq, dAdq, dAdv (ground coordinates).
    J: Vec<Vector6<T>>,
    dVdq: Vec<Vector6<T>>,
    dAdq: Vec<Vector6<T>>,
    dAdv: Vec<Vector6<T>>,
    /// M⁻¹ by LᵀL.
    inverse: ltl::TreeInverse<T>,
    /// The entries of M, ∂τ/∂q and ∂τ/∂v that are zero whatever the state.
    zeros: super::crba::ZeroRuns,
    /// The revolute joints' sines and cosines, computed together.
    trig: Trig<T>,
    rnea: Option<Box<RneaDerivatives<T>>>,
    aba: Option<super::aba::AbaScratch<T>>,
}

impl<T: Scalar> Model<T> {
    /// A work space for the `_into` derivative hot paths.
    pub fn derivative_scratch(&self) -> DerivativeScratch<T> {
        let n = self.segs.len();
        let nv = self.nv;
        DerivativeScratch {
            world: vec![Xform::identity(); n],
            ov: vec![Vector6::zeros(); n],
            oa: vec![Vector6::zeros(); n],
            Yc: vec![BodyInertia::zero(); n],
            Bc: vec![Variation::zero(); n],
            Fc: vec![Vector6::zeros(); n],
            J: vec![Vector6::zeros(); nv],
            dVdq: vec![Vector6::zeros(); nv],
            dAdq: vec![Vector6::zeros(); nv],
            dAdv: vec![Vector6::zeros(); nv],
            inverse: ltl::TreeInverse::new(&self.parent_col),
            zeros: super::crba::ZeroRuns::of_tree(&self.parent_col),
            trig: Trig::of(self),
            rnea: None,
            aba: None,
        }
    }

    /// Exact derivatives of inverse dynamics at (q, v, v̇): τ, ∂τ/∂q, ∂τ/∂v and ∂τ/∂v̇ = M,
    /// analytically in O(n·depth) ([`RneaDerivatives`] has the derivation and the
    /// tangent-space convention for ball and free joints). External wrenches `f_ext` are
    /// fixed in their links (they turn with them).
    ///
    /// Book: §7.11 (RNEA), §12.x (linearization).
    ///
    /// # Errors
    /// As [`Model::rnea`].
    pub fn rnea_derivatives(
        &self,
        q: &[T],
        v: &[T],
        vdot: &[T],
        f_ext: Option<&LinkWrenches<T>>,
    ) -> Result<RneaDerivatives<T>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        self.check_v(vdot, "v̇")?;
        self.check_wrenches(f_ext)?;
        let mut out = RneaDerivatives::zeros(self);
        let mut s = self.derivative_scratch();
        self.rnea_derivatives_into(q, v, vdot, f_ext, &mut out, &mut s);
        let all = [&out.tau[..], out.dtau_dq.as_slice(), out.dtau_dv.as_slice(), out.mass_matrix.as_slice()];
        if !all.iter().all(|x| crate::error::all_finite(x)) {
            return Err(DynamicsError::Overflow { what: "derivatives of inverse dynamics" });
        }
        Ok(out)
    }

    /// Exact derivatives of forward dynamics at (q, v, τ): v̇, ∂v̇/∂q, ∂v̇/∂v and ∂v̇/∂τ = M⁻¹,
    /// from ∂v̇/∂(q, v) = −M⁻¹ ∂τ/∂(q, v) at v̇ = ABA(q, v, τ) (tangent-space convention as
    /// in [`RneaDerivatives`]).
    ///
    /// Book: §7.11 (ABA), §12.x (linearization).
    ///
    /// # Errors
    /// As [`Model::aba`]; [`DynamicsError::SingularMassMatrix`] when M is singular (a model
    /// with an inert joint direction: the derivative along it is infinite).
    pub fn aba_derivatives(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
    ) -> Result<AbaDerivatives<T>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        self.check_v(tau, "τ")?;
        self.check_wrenches(f_ext)?;
        let mut out = AbaDerivatives::zeros(self);
        let mut s = self.derivative_scratch();
        self.aba_derivatives_into(q, v, tau, f_ext, &mut out, &mut s)?;
        let all =
            [&out.vdot[..], out.dvdot_dq.as_slice(), out.dvdot_dv.as_slice(), out.dvdot_dtau.as_slice()];
        if !all.iter().all(|x| crate::error::all_finite(x)) {
            return Err(DynamicsError::Overflow { what: "derivatives of forward dynamics" });
        }
        Ok(out)
    }

    /// [`Model::aba_derivatives`] without input checks, into caller-provided output and
    /// scratch: the hot path.
    ///
    /// # Errors
    /// [`DynamicsError::InertJointForce`] (from ABA), [`DynamicsError::SingularMassMatrix`].
    ///
    /// # Panics
    /// If `out` was not made by [`AbaDerivatives::zeros`] for this model.
    pub fn aba_derivatives_into(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        out: &mut AbaDerivatives<T>,
        s: &mut DerivativeScratch<T>,
    ) -> Result<(), DynamicsError> {
        let mut aba = s.aba.take().unwrap_or_else(|| self.aba_scratch());
        let r = self.aba_into(q, v, tau, f_ext, &mut out.vdot, &mut aba);
        s.aba = Some(aba);
        r?;
        let mut rd = s.rnea.take().unwrap_or_else(|| Box::new(RneaDerivatives::zeros(self)));
        self.rnea_derivatives_into(q, v, &out.vdot, f_ext, &mut rd, s);
        // M⁻¹ from the tree-sparse LᵀL factorization of M (no fill-in), then
        // ∂v̇/∂q = −M⁻¹ ∂τ/∂q and ∂v̇/∂v = −M⁻¹ ∂τ/∂v by matrix products
        let result = s.inverse.invert(rd.mass_matrix.as_slice(), out.dvdot_dtau.as_mut_slice());
        if result.is_ok() {
            let minv = &out.dvdot_dtau;
            T::fast_path::<NegProduct<'_>>((minv, &rd.dtau_dq, &mut out.dvdot_dq));
            T::fast_path::<NegProduct<'_>>((minv, &rd.dtau_dv, &mut out.dvdot_dv));
        }
        s.rnea = Some(rd);
        result
    }

    /// [`Model::rnea_derivatives`] without input checks, into caller-provided output and
    /// scratch: the hot path.
    ///
    /// # Panics
    /// If `out` was not made by [`RneaDerivatives::zeros`] for this model.
    pub fn rnea_derivatives_into(
        &self,
        q: &[T],
        v: &[T],
        vdot: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        out: &mut RneaDerivatives<T>,
        s: &mut DerivativeScratch<T>,
    ) {
        self.derivatives_outward(q, v, vdot, f_ext, s);
        // the inward pass writes every entry but those between branches: clear only those
        for m in [&mut out.dtau_dq, &mut out.dtau_dv, &mut out.mass_matrix] {
            s.zeros.clear(m.as_mut_slice());
        }
        self.derivatives_inward(out.partials(), s);
    }
}

/// out = −A·B for square matrices of one size: nalgebra's `gemm` for every scalar, faer's
/// sequential product for `f64` (its small-matrix kernels; both choose their SIMD width when the
/// program runs, so these products are outside the same-bits promise, as docs/robustness.md says).
struct NegProduct<'a>(std::marker::PhantomData<&'a ()>);

impl<'a> FastPath for NegProduct<'a> {
    type Input<T: Scalar> = (&'a DMatrix<T>, &'a DMatrix<T>, &'a mut DMatrix<T>);
    type Output<T: Scalar> = ();

    fn generic<T: Scalar>((a, b, out): Self::Input<T>) {
        out.gemm(-T::one(), a, b, T::zero());
    }

    fn f64((a, b, out): Self::Input<f64>) {
        let n = a.nrows();
        let view = |m: &'a DMatrix<f64>| faer::MatRef::from_column_major_slice(m.as_slice(), n, n);
        let dst = faer::MatMut::from_column_major_slice_mut(out.as_mut_slice(), n, n);
        faer::linalg::matmul::matmul(dst, faer::Accum::Replace, view(a), view(b), -1.0, faer::Par::Seq);
    }
}

impl Model<f64> {
    /// ∂M/∂q: the derivative of the mass matrix along each tangent direction k (k-th entry,
    /// nv × nv), exact by dual numbers through the generic CRBA (one `Dual64` pass per
    /// direction, q ⊕ ε eₖ by [`Model::integrate`]).
    ///
    /// Book: §7.11, §9.3 (the Christoffel terms of (9.3.11) are built from these).
    ///
    /// # Errors
    /// As [`Model::crba`].
    pub fn mass_matrix_derivatives(&self, q: &[f64]) -> Result<Vec<DMatrix<f64>>, DynamicsError> {
        use num_dual::Dual64;
        self.check_q(q)?;
        let dual = self.cast::<Dual64>();
        let qd: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
        let mut h = DMatrix::zeros(self.nv, self.nv);
        let mut s = dual.crba_scratch();
        (0..self.nv)
            .map(|k| {
                let e: Vec<Dual64> = (0..self.nv)
                    .map(|i| if i == k { Dual64::from(0.0).derivative() } else { Dual64::from(0.0) })
                    .collect();
                let qk = dual.integrate(&qd, &e, Dual64::from(1.0))?;
                dual.crba_into(&qk, &mut h, &mut s);
                Ok(h.map(|x| x.eps))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests;
