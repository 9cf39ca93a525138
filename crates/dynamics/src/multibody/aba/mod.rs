//! Forward dynamics in O(n) by the articulated-body algorithm, generic over the scalar, exact
//! for joints whose articulated inertia is only semidefinite (particles on ball or free
//! joints, pins through a point mass, massless links between coaxial joints).
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Matrix6x3, Vector3, Vector6};
use vectrix_tensor::Scalar;

use super::articulated::Articulated;
use super::model::{Model, Trig};
use super::planar::PlanarWork;
use super::spatial::Xform;
use super::wrench::{JointWrench, LinkWrenches};
use crate::DynamicsError;

mod ground;
mod passes;
mod sym6;

/// Work space of the articulated-body algorithm.
#[derive(Debug, Clone)]
pub struct AbaScratch<T: Scalar = f64> {
    x: Vec<Xform<T>>,
    IA: Vec<Articulated<T>>,
    pA: Vec<Vector6<T>>,
    c: Vec<Vector6<T>>,
    U: Vec<Matrix6x3<T>>,
    Dinv: Vec<Matrix3<T>>,
    u: Vec<Vector3<T>>,
    a: Vec<Vector6<T>>,
    w: Vec<Vector3<T>>,
    v: Vec<Vector3<T>>,
    /// ρᵢ ≥ the distance from segment i's origin to every centre of mass of its subtree.
    reach: Vec<f64>,
    /// The revolute joints' sines and cosines, computed together.
    trig: Trig<T>,
    /// The ground passes' motion subspaces S and U = IᴬS, one column per velocity
    /// coordinate, and their articulated inertias.
    S: Vec<Vector6<T>>,
    GU: Vec<Vector6<T>>,
    G: Vec<sym6::Sym6<T>>,
    /// Whether each segment is placed relative to the ground passes' reference point.
    rel: Vec<bool>,
    /// Per free root (`Model::free_roots`): whether its 6×6 solve was taken, and its y.
    root_fast: Vec<bool>,
    root_y: Vec<Vector6<T>>,
    /// The planar passes' work space (`None` unless the model is planar).
    pub(crate) pl: Option<PlanarWork<T>>,
}

impl<T: Scalar> Model<T> {
    /// A work space for [`Model::aba_unchecked`].
    pub fn aba_scratch(&self) -> AbaScratch<T> {
        let n = self.segs.len();
        AbaScratch {
            x: vec![Xform::identity(); n],
            IA: vec![Articulated::zero(); n],
            pA: vec![Vector6::zeros(); n],
            c: vec![Vector6::zeros(); n],
            U: vec![Matrix6x3::zeros(); n],
            Dinv: vec![Matrix3::zeros(); n],
            u: vec![Vector3::zeros(); n],
            a: vec![Vector6::zeros(); n],
            w: vec![Vector3::zeros(); n],
            v: vec![Vector3::zeros(); n],
            reach: vec![0.0; n],
            trig: Trig::of(self),
            S: vec![Vector6::zeros(); self.nv],
            GU: vec![Vector6::zeros(); self.nv],
            G: vec![sym6::Sym6::zero(); n],
            rel: vec![false; n],
            root_fast: vec![false; self.free_roots.len()],
            root_y: vec![Vector6::zeros(); self.free_roots.len()],
            pl: self.planar.as_ref().map(|_| PlanarWork::new(n)),
        }
    }

    /// Forward dynamics v̇ = FD(q, v, τ) in O(n) by the articulated-body algorithm
    /// (Featherstone): three passes over the tree; the book's per-body equations (7.11.13)
    /// with the joint reactions eliminated tip to base. `f_ext` as in [`Model::rnea`].
    ///
    /// A planar tree ([`Model::planar_axis`]) runs the same passes on planar spatial vectors
    /// (3 numbers instead of 6, RBDA §2.16), a free body alone on its joint is solved in
    /// closed form (Euler's equations about its centre), and any other tree runs the passes
    /// in ground coordinates about its base (RBDA §7.3: articulated inertias summed into the
    /// parent with no transform), unless a pivot is near its rounding level: then in each
    /// segment's own coordinates, with a floating base (a free joint at the root carrying a
    /// subtree) eliminated as one 6-DOF joint. All give the three passes' v̇ to rounding; the
    /// ground coordinates' rounding grows with the tree's extent over its links' (m ρ² terms,
    /// ρ the lever arm from the base: 26 ε against 2.6 ε on a 6-link chain).
    ///
    /// Book: §7.11; RBDA Table 7.1.
    ///
    /// # Degenerate inputs
    /// A joint whose articulated inertia Dᵢ = SᵢᵀIᴬᵢSᵢ is singular (a particle on a ball or
    /// free joint: no inertia about its own radius; a pin whose axis passes through a point
    /// mass; two coaxial pins joined by a massless link) is solved exactly: a direction n with
    /// Dᵢn = 0 has Iᴬᵢ Sᵢ n = 0 (Iᴬ is PSD), so it carries no inertia and couples to nothing;
    /// it gets zero acceleration (the minimum-norm solution, D⁺ by a rank-revealing Cholesky,
    /// taken only when the fast Cholesky finds a pivot ≤ 64 ε × the joint's block of Iᴬ). The
    /// other coordinates are exact. The mass matrix of such a model is singular, so
    /// [`Model::forward_dynamics_crba`] refuses it while ABA does not.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`] (an input),
    /// [`DynamicsError::OutOfRange`] (a ball-joint quaternion of norm below 1e-6);
    /// [`DynamicsError::InertJointForce`] when a generalized force acts along an inert
    /// direction (its acceleration would be infinite), e.g. a massless leaf link driven by a
    /// torque; [`DynamicsError::Overflow`] when finite inputs give a non-finite v̇ (v ≈ 1e200).
    pub fn aba(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
    ) -> Result<Vec<T>, DynamicsError> {
        let mut out = vec![T::zero(); self.nv];
        self.aba_checked(q, v, tau, f_ext, &mut out, &mut self.aba_scratch())?;
        Ok(out)
    }

    /// [`Model::aba`] into `vdot` with caller-provided scratch: the same checks and errors
    /// without an allocation per call, for batches of user input (one scratch per thread).
    ///
    /// Book: §7.11; RBDA Table 7.1.
    ///
    /// # Errors
    /// As [`Model::aba`], and [`DynamicsError::DimensionMismatch`] when `vdot` is not nv long.
    pub fn aba_checked(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        vdot: &mut [T],
        s: &mut AbaScratch<T>,
    ) -> Result<(), DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        self.check_v(tau, "τ")?;
        self.check_wrenches(f_ext)?;
        crate::error::check_len(vdot.len(), self.nv, "v̇")?;
        self.aba_into(q, v, tau, f_ext, vdot, s)?;
        if !crate::error::all_finite(vdot) {
            return Err(DynamicsError::Overflow { what: "forward dynamics v̇" });
        }
        Ok(())
    }

    /// [`Model::aba`] without input checks and with caller-provided scratch: the hot path.
    /// An overflow (inputs near 1e200) shows as a non-finite v̇ here.
    ///
    /// # Errors
    /// [`DynamicsError::InertJointForce`] as [`Model::aba`].
    pub fn aba_unchecked(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        vdot: &mut [T],
        s: &mut AbaScratch<T>,
    ) -> Result<(), DynamicsError> {
        self.aba_into(q, v, tau, None, vdot, s)
    }

    /// [`Model::aba`] with external wrenches, without input checks and with caller-provided
    /// scratch: the hot path of a scene's right-hand side.
    ///
    /// The three passes are pass 1 (outward: twists, bias accelerations and forces), pass 2
    /// (inward: articulated inertias) and pass 3 (outward: accelerations), run in ground
    /// coordinates (`ground`: inertias passed to the parent by a plain sum) unless a pivot is
    /// near its rounding level; then in each segment's own coordinates (`passes`: inertias by
    /// their 3×3 blocks, moved to the parent by a rotation and a shift), which decide such a
    /// pivot exactly.
    ///
    /// # Errors
    /// [`DynamicsError::InertJointForce`] as [`Model::aba`].
    pub fn aba_into(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        vdot: &mut [T],
        s: &mut AbaScratch<T>,
    ) -> Result<(), DynamicsError> {
        let n = self.segs.len();
        if let (Some(planar), Some(pl)) = (&self.planar, &mut s.pl)
            && pl.seg.len() == n
        {
            pl.gravity = self.gravity;
            if planar.aba(q, v, tau, f_ext, vdot, pl) {
                return Ok(());
            }
        }
        self.leaf_accelerations(q, v, tau, f_ext, vdot);
        s.trig.fill(q);
        if self.aba_ground(q, v, tau, f_ext, vdot, s) {
            return Ok(());
        }
        self.aba_local(q, v, f_ext, tau, vdot, s)
    }

    /// The closed forms of the free and ball leaves (see `free_leaf_accelerations`).
    fn leaf_accelerations(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        vdot: &mut [T],
    ) {
        for (k, &l) in self.free_links.iter().enumerate() {
            self.free_leaf_accelerations(k, q, v, tau, f_ext.map(|fe| &fe[l]), vdot);
        }
        for (k, &l) in self.ball_links.iter().enumerate() {
            self.ball_leaf_accelerations(k, q, v, tau, f_ext.map(|fe| &fe[l]), vdot);
        }
    }

    /// The three passes in each segment's own coordinates (`passes`), which decide every
    /// pivot at its rounding level exactly; `s.trig` must hold q's sines and cosines.
    fn aba_local(
        &self,
        q: &[T],
        v: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        tau: &[T],
        vdot: &mut [T],
        s: &mut AbaScratch<T>,
    ) -> Result<(), DynamicsError> {
        self.aba_outward(q, v, s);
        if let Some(fe) = f_ext {
            for (l, &k) in self.link_seg.iter().enumerate() {
                if !self.aba_skip[k] {
                    s.pA[k] -= super::spatial::join(&fe[l].moment, &fe[l].force);
                }
            }
        }
        self.aba_inward(tau, s)?;
        self.aba_accelerations(vdot, s);
        Ok(())
    }

    /// [`Model::aba_into`] by the local passes alone (the ground passes skipped): for tests
    /// that compare the two formulations.
    #[cfg(test)]
    pub(crate) fn aba_local_into(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        vdot: &mut [T],
        s: &mut AbaScratch<T>,
    ) -> Result<(), DynamicsError> {
        self.leaf_accelerations(q, v, tau, f_ext, vdot);
        s.trig.fill(q);
        self.aba_local(q, v, f_ext, tau, vdot, s)
    }

    /// v̇ of a free leaf body (segments f..f+4, see `free_leaf_roots`) in closed form: with
    /// every load resolved in the body frame B about its origin (force F, moment n_o) and c,
    /// J_c the centre and central inertia, eliminating the origin's acceleration a_o from the
    /// Newton–Euler equations m(a_o + α×c + ω×(ω×c)) = F and J_oα + ω×J_oω + m c×a_o = n_o
    /// leaves Euler's equations about the centre, J_c α = n_o − c×F − ω×J_c ω, and then
    /// a_o = F/m − ω×(ω×c) + c×α. The sliders' coordinates are components in the joint frame J,
    /// fixed in the ground, so their second derivatives are a_o resolved in J; the ball's v̇ is
    /// α in B. This is what the three passes give for these four segments (the three sliders
    /// are massless), for 3×3 instead of 6×6 algebra.
    ///
    /// Book: §7.11 (7.11.13) for one free body; RBDA §2.14.
    fn free_leaf_accelerations(
        &self,
        k: usize,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&JointWrench<T>>,
        vdot: &mut [T],
    ) {
        let f = self.free_leaves[k];
        let (slide, body) = (&self.segs[f], &self.segs[f + 3]);
        let (vi, m, c, j_c) = (slide.vi, body.inertia.m, body.com, body.j_c);
        let j_c_inv = &self.free_jc_inv[k];
        // 𝓞_{B/J} of the ball, and 𝓞_{B/G} = 𝓞_{B/J} 𝓞_{J/G} for the gravity
        let e_bj = body.elem.xform(&q[body.qi..], None).E;
        let g_b = e_bj * (slide.placement.E * self.gravity);
        let w = Vector3::new(v[vi + 3], v[vi + 4], v[vi + 5]);
        let mut force = g_b * m + e_bj * Vector3::new(tau[vi], tau[vi + 1], tau[vi + 2]);
        let mut moment = Vector3::new(tau[vi + 3], tau[vi + 4], tau[vi + 5]) + c.cross(&(g_b * m));
        if let Some(fe) = f_ext {
            force += fe.force;
            moment += fe.moment;
        }
        let rhs = moment - c.cross(&force) - w.cross(&(j_c * w));
        // J_c was found definite when the model was built (`definite_body`), and inverted
        // there from its Cholesky factor
        let alpha = j_c_inv * rhs;
        let a_o = force / m - w.cross(&w.cross(&c)) + c.cross(&alpha);
        let a_j = e_bj.tr_mul(&a_o);
        vdot[vi..vi + 3].copy_from_slice(a_j.as_slice());
        vdot[vi + 3..vi + 6].copy_from_slice(alpha.as_slice());
    }

    /// v̇ = α (resolved in the body frame B) of a ball leaf (see `ball_leaf_roots`) in closed
    /// form: the joint point o is fixed, so Euler's equations about it, J_o α + ω×J_o ω = n_o,
    /// with n_o the moment about o in B of the joint torque, of gravity (m c × g) and of the
    /// external wrench, give α = J_o⁻¹(n_o − ω×J_o ω). This is what the three passes give for
    /// this one segment, for 3×3 instead of 6×6 algebra.
    ///
    /// Book: §7.11 (Euler's equation about a fixed point, (7.11.13) with a_o = 0); RBDA §2.14.
    fn ball_leaf_accelerations(
        &self,
        k: usize,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&JointWrench<T>>,
        vdot: &mut [T],
    ) {
        let b = &self.segs[self.ball_leaves[k]];
        let vi = b.vi;
        // 𝓞_{B/J} of the ball, and g resolved in B through 𝓞_{J/G} of the placement
        let g_b = b.elem.xform(&q[b.qi..], None).E * (b.placement.E * self.gravity);
        let w = Vector3::new(v[vi], v[vi + 1], v[vi + 2]);
        let j_o = &b.inertia.I;
        let mut moment = Vector3::new(tau[vi], tau[vi + 1], tau[vi + 2]) + b.inertia.h.cross(&g_b);
        if let Some(fe) = f_ext {
            moment += fe.moment;
        }
        let alpha = self.ball_jo_inv[k] * (moment - w.cross(&(j_o * w)));
        vdot[vi..vi + 3].copy_from_slice(alpha.as_slice());
    }
}

#[cfg(test)]
mod tests;
