//! Forward dynamics in O(n) by the articulated-body algorithm, generic over the scalar, exact
//! for joints whose articulated inertia is only semidefinite (particles on ball or free
//! joints, pins through a point mass, massless links between coaxial joints).
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Matrix6x3, Vector3, Vector6};
use vectrix_tensor::Scalar;

use super::articulated::Articulated;
use super::model::Model;
use super::planar::PlanarWork;
use super::spatial::Xform;
use super::wrench::{JointWrench, LinkWrenches};
use crate::DynamicsError;

mod passes;

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
    /// closed form (Euler's equations about its centre), and a floating base (a free joint at
    /// the root carrying a subtree) is eliminated as one 6-DOF joint, one 6×6 solve with its
    /// articulated inertia instead of four segments; all give the three passes' v̇ to
    /// rounding.
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
    /// (inward: articulated inertias by their 3×3 blocks, moved to the parent by a rotation
    /// and a shift) and pass 3 (outward: accelerations), in `passes`.
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
            && pl.seg.len() == n + 1
        {
            pl.gravity = self.gravity;
            if planar.aba(q, v, tau, f_ext, vdot, pl) {
                return Ok(());
            }
        }
        for (k, &l) in self.free_links.iter().enumerate() {
            self.free_leaf_accelerations(k, q, v, tau, f_ext.map(|fe| &fe[l]), vdot);
        }
        for (k, &l) in self.ball_links.iter().enumerate() {
            self.ball_leaf_accelerations(k, q, v, tau, f_ext.map(|fe| &fe[l]), vdot);
        }
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
        let e_bj = body.elem.xform(&q[body.qi..]).E;
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
        let g_b = b.elem.xform(&q[b.qi..]).E * (b.placement.E * self.gravity);
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
mod tests {
    use nalgebra::{Matrix3, Rotation3, Vector3};

    use super::super::joint::{Joint, Link};
    use super::super::model::Model;
    use super::super::wrench::JointWrench;

    /// A body on `joint` at the root with its centre off the joint point and a tilted, offset
    /// joint frame, gravity g, alone and, for the generic three passes, with a massless welded
    /// child (which stops it being a closed-form leaf).
    fn alone_and_with_child(joint: Joint) -> (Model, Model) {
        let j_c = Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.1);
        let mut body =
            Link::new(None, joint, Vector3::new(0.5, -1.0, 2.0), 3.0, Vector3::new(0.2, -0.4, 0.7), j_c);
        body.orientation = *Rotation3::from_euler_angles(0.3, -0.7, 1.1).matrix();
        let tip = Link::new(
            Some(0),
            Joint::Weld,
            Vector3::new(1.0, 0.0, 0.0),
            0.0,
            Vector3::zeros(),
            Matrix3::zeros(),
        );
        let mut alone = Model::new(std::slice::from_ref(&body)).expect("valid");
        let mut with_child = Model::new(&[body, tip]).expect("valid");
        let g = Vector3::new(0.3, -0.2, -9.81);
        (alone.gravity, with_child.gravity) = (g, g);
        (alone, with_child)
    }

    /// An external wrench on the body (and none on the welded child).
    fn wrenches() -> Vec<JointWrench> {
        let wrench =
            JointWrench { force: Vector3::new(-0.6, 1.4, 2.2), moment: Vector3::new(0.9, 0.1, -0.5) };
        vec![wrench, JointWrench::default()]
    }

    /// A free body (see `alone_and_with_child`) at a state with joint forces and an external
    /// wrench.
    fn models() -> (Model, Model, Vec<f64>, Vec<f64>, Vec<f64>, Vec<JointWrench>) {
        let (alone, with_child) = alone_and_with_child(Joint::Free);
        let qn = nalgebra::UnitQuaternion::from_euler_angles(0.9, 0.4, -2.0);
        let q = vec![0.3, -1.2, 0.8, qn.w, qn.i, qn.j, qn.k];
        let v = vec![0.5, -0.3, 1.7, 2.0, -1.1, 3.3];
        let tau = vec![1.0, -2.0, 0.5, 0.7, -0.4, 0.25];
        (alone, with_child, q, v, tau, wrenches())
    }

    /// ABA of the leaf alone (closed form) against the three passes on the same body with its
    /// welded child, to 1e-13·(`scale` + |v̇|) per coordinate, and RNEA at the returned v̇ gives
    /// back τ to 1e-12.
    fn closed_form_matches(
        alone: &Model,
        with_child: &Model,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        wrenches: &[JointWrench],
        scale: f64,
    ) {
        let fast = alone.aba(q, v, tau, Some(&wrenches[..1])).expect("definite");
        let passes = with_child.aba(q, v, tau, Some(wrenches)).expect("definite");
        for (a, b) in fast.iter().zip(&passes) {
            assert!((a - b).abs() <= 1e-13 * (scale + b.abs()), "{fast:?} vs {passes:?}");
        }
        let id = alone.rnea(q, v, &fast, Some(&wrenches[..1])).expect("valid");
        for (a, b) in id.tau.iter().zip(tau) {
            assert!((a - b).abs() <= 1e-12, "RNEA {:?} vs τ {tau:?}", id.tau);
        }
    }

    /// The closed form of a free leaf body agrees with the three passes of ABA on the same
    /// body (made generic by a massless welded child), and with the inverse dynamics: RNEA at
    /// the returned v̇ gives back the applied joint forces.
    #[test]
    fn free_leaf_closed_form_matches_the_passes_and_rnea() {
        let (alone, with_child, q, v, tau, wrenches) = models();
        assert_eq!(alone.free_leaves, vec![0]);
        assert!(with_child.free_leaves.is_empty());
        closed_form_matches(&alone, &with_child, &q, &v, &tau, &wrenches, 1.0);
    }

    /// The closed form of a ball leaf (a body turning about a fixed point of a tilted, offset
    /// joint frame, its centre off that point, under gravity, a joint torque and an external
    /// wrench) agrees with the three passes on the same body made generic by a massless welded
    /// child, and RNEA at the returned v̇ gives back the joint torque.
    #[test]
    fn ball_leaf_closed_form_matches_the_passes_and_rnea() {
        let (alone, with_child) = alone_and_with_child(Joint::Ball);
        assert_eq!(alone.ball_leaves, vec![0]);
        assert!(with_child.ball_leaves.is_empty());
        let qn = nalgebra::UnitQuaternion::from_euler_angles(0.9, 0.4, -2.0);
        let q = vec![qn.w, qn.i, qn.j, qn.k];
        let (v, tau) = (vec![2.0, -1.1, 3.3], vec![0.7, -0.4, 0.25]);
        let wrenches = wrenches();
        // a few roundings of terms near 10 (the gyroscopic and gravity moments)
        closed_form_matches(&alone, &with_child, &q, &v, &tau, &wrenches, 10.0);
    }

    /// A floating base (a free joint at the root, tilted and offset) with a pin leg, a ball
    /// leg and a welded tip, and the same tree with the free joint written as three sleeves
    /// along ẑ, ŷ, x̂ and a ball (the same motion: translations commute), which ABA eliminates
    /// segment by segment.
    fn floating_base(j_base: Matrix3<f64>) -> (Model, Model) {
        let base_orientation = *Rotation3::from_euler_angles(0.3, -0.7, 1.1).matrix();
        let mut base = Link::new(
            None,
            Joint::Free,
            Vector3::new(0.5, -1.0, 2.0),
            3.0,
            Vector3::new(0.1, -0.2, 0.05),
            j_base,
        );
        base.orientation = base_orientation;
        let j = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
        let pin_leg = Link::new(
            Some(0),
            Joint::Pin { axis: Vector3::new(0.3, 1.0, -0.2) },
            Vector3::new(0.4, 0.2, -0.1),
            1.2,
            Vector3::new(0.0, 0.0, -0.3),
            j,
        );
        let ball_leg = Link::new(
            Some(0),
            Joint::Ball,
            Vector3::new(-0.4, 0.2, -0.1),
            0.8,
            Vector3::new(0.1, 0.0, -0.4),
            j,
        );
        let tip =
            Link::new(Some(1), Joint::Weld, Vector3::new(0.0, 0.0, -0.6), 0.3, Vector3::zeros(), j * 0.1);
        let links = [base, pin_leg, ball_leg, tip];
        (Model::new(&links).expect("valid"), segment_form(&links))
    }

    /// The tree of `links` (links[0] on a free joint at the root) with that joint written as
    /// three massless sleeves along ẑ, ŷ, x̂ and a ball carrying the body: the same motion
    /// (translations commute), coordinates (z, y, x, ball, …), which ABA eliminates segment by
    /// segment.
    fn segment_form(links: &[Link]) -> Model {
        let base = &links[0];
        let sleeve = |parent, axis: Vector3<f64>, offset| {
            Link::new(parent, Joint::Sleeve { axis }, offset, 0.0, Vector3::zeros(), Matrix3::zeros())
        };
        let mut z = sleeve(None, Vector3::z(), base.offset);
        z.orientation = base.orientation;
        let mut out = vec![
            z,
            sleeve(Some(0), Vector3::y(), Vector3::zeros()),
            sleeve(Some(1), Vector3::x(), Vector3::zeros()),
        ];
        let mut body = base.clone();
        (body.parent, body.joint, body.offset, body.orientation) =
            (Some(2), Joint::Ball, Vector3::zeros(), Matrix3::identity());
        out.push(body);
        out.extend(links[1..].iter().map(|l| {
            let mut l = l.clone();
            l.parent = l.parent.map(|p| p + 3);
            l
        }));
        Model::new(&out).expect("valid")
    }

    /// (z, y, x, rest…) from (x, y, z, rest…).
    fn perm(x: &[f64]) -> Vec<f64> {
        [&[x[2], x[1], x[0]], &x[3..]].concat()
    }

    /// v̇ of the floating base's 6×6 solve: against the same tree eliminated segment by segment
    /// (a consistency check), against the mass matrix and bias forces (CRBA, RNEA, Cholesky:
    /// another algorithm), and RNEA at the returned v̇ gives back τ, with gravity, joint forces
    /// and external wrenches on every link.
    #[test]
    fn floating_base_solve_matches_the_segments_and_the_mass_matrix() {
        let (mut fast, mut slow) = floating_base(Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.1));
        let g = Vector3::new(0.3, -0.2, -9.81);
        (fast.gravity, slow.gravity) = (g, g);
        assert_eq!((fast.free_roots.clone(), slow.free_roots.clone()), (vec![0], vec![]));
        let qb = nalgebra::UnitQuaternion::from_euler_angles(0.9, 0.4, -2.0);
        let ql = nalgebra::UnitQuaternion::from_euler_angles(-0.3, 0.8, 0.2);
        let q = vec![0.3, -1.2, 0.8, qb.w, qb.i, qb.j, qb.k, 0.7, ql.w, ql.i, ql.j, ql.k];
        let v = vec![0.5, -0.3, 1.7, 2.0, -1.1, 3.3, -0.8, 0.4, 1.9, -0.6];
        let tau = vec![1.0, -2.0, 0.5, 0.7, -0.4, 0.25, 0.3, -0.2, 0.1, 0.6];
        let fe = |k: f64| JointWrench {
            force: Vector3::new(-0.6, 1.4, 2.2) * k,
            moment: Vector3::new(0.9, 0.1, -0.5) * k,
        };
        let wrenches = vec![fe(1.0), fe(-0.5), fe(0.3), fe(0.7)];
        let got = fast.aba(&q, &v, &tau, Some(&wrenches)).expect("definite");
        let mut s = fast.aba_scratch();
        let mut again = vec![0.0; 10];
        fast.aba_into(&q, &v, &tau, Some(&wrenches), &mut again, &mut s).expect("definite");
        assert!(s.root_fast[0], "the 6×6 solve was taken");
        assert_eq!(got, again);
        // the slow tree's coordinates: sleeves z, y, x then the ball (its joint frame is the
        // free joint's frame, so the same numbers)
        // (no wrench on the three massless sleeves)
        let slow_wrenches = [&[JointWrench::default(); 3][..], &wrenches].concat();
        let slow_vd = slow.aba(&perm(&q), &perm(&v), &perm(&tau), Some(&slow_wrenches)).expect("definite");
        let crba = fast.forward_dynamics_crba(&q, &v, &tau, Some(&wrenches)).expect("definite");
        let scale = got.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for ((a, b), c) in got.iter().zip(&perm(&slow_vd)).zip(&crba) {
            assert!((a - b).abs() <= 1e-13 * scale, "segments: {got:?} vs {slow_vd:?}");
            assert!((a - c).abs() <= 1e-12 * scale, "CRBA: {got:?} vs {crba:?}");
        }
        let id = fast.rnea(&q, &v, &got, Some(&wrenches)).expect("valid");
        for (a, b) in id.tau.iter().zip(&tau) {
            assert!((a - b).abs() <= 1e-12 * scale, "RNEA {:?} vs τ {tau:?}", id.tau);
        }
    }

    /// A base whose rotational inertia is at the rounding level (J_c = 1e-16·1: definite on
    /// its own) carrying a ball leg hinged at the base's centre (which adds no rotational
    /// inertia about it): the 6×6 solve finds its angular pivot below ABA's floor and is
    /// refused, and the four segments are eliminated one by one, keeping the base's spin
    /// inert; the result is the same tree's segment by segment, to rounding.
    #[test]
    fn floating_base_at_the_rounding_level_falls_back_to_the_segments() {
        let j0 = Matrix3::identity() * 1e-16;
        let base = Link::new(None, Joint::Free, Vector3::new(0.5, -1.0, 2.0), 3.0, Vector3::zeros(), j0);
        let j = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
        let leg = Link::new(Some(0), Joint::Ball, Vector3::zeros(), 0.8, Vector3::new(0.1, 0.0, -0.4), j);
        let links = [base, leg];
        let (mut fast, mut slow) = (Model::new(&links).expect("valid"), segment_form(&links));
        let g = Vector3::new(0.0, 0.0, -9.81);
        (fast.gravity, slow.gravity) = (g, g);
        assert_eq!(fast.free_roots, vec![0]);
        let ql = nalgebra::UnitQuaternion::from_euler_angles(-0.3, 0.8, 0.2);
        let q = vec![0.3, -1.2, 0.8, 1.0, 0.0, 0.0, 0.0, ql.w, ql.i, ql.j, ql.k];
        let v = vec![0.5, -0.3, 1.7, 0.0, 0.0, 0.0, -0.8, 0.4, 1.9];
        // (no torque at the leg's ball: it would turn the base, which cannot take it)
        let tau = vec![1.0, -2.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let mut s = fast.aba_scratch();
        let mut got = vec![0.0; 9];
        fast.aba_into(&q, &v, &tau, None, &mut got, &mut s).expect("the spin is inert");
        assert!(!s.root_fast[0], "the 6×6 solve was refused");
        let slow_vd = slow.aba(&perm(&q), &perm(&v), &perm(&tau), None).expect("the spin is inert");
        // (the sleeves' order changes the roundings: a few ulps of |v̇| ≈ 10)
        for (a, b) in perm(&got).iter().zip(&slow_vd) {
            assert!((a - b).abs() <= 1e-14 * 10.0, "{got:?} vs {slow_vd:?}");
        }
        assert_eq!(&got[3..6], &[0.0, 0.0, 0.0], "the base's spin is inert");
    }

    /// A particle on a rod about a ball joint (J_c = 0, so J_o has rank 2) is not a closed-form
    /// body: ABA's rank-revealing path keeps the spin about the rod inert. Hanging straight
    /// down at rest, nothing moves.
    #[test]
    fn ball_particle_keeps_the_rank_revealing_path() {
        let p = Link::new(
            None,
            Joint::Ball,
            Vector3::zeros(),
            2.0,
            Vector3::new(0.0, 0.0, -1.0),
            Matrix3::zeros(),
        );
        let mut m = Model::new(&[p]).expect("valid");
        m.gravity = Vector3::new(0.0, 0.0, -9.81);
        assert!(m.ball_leaves.is_empty());
        let vd = m.aba(&[1.0, 0.0, 0.0, 0.0], &[0.0; 3], &[0.0; 3], None).expect("inert");
        assert_eq!(vd, vec![0.0, 0.0, 0.0]);
    }

    /// A particle on a free joint (J_c = 0) is not a closed-form body: ABA's rank-revealing
    /// path keeps the rotation inert (ω̇ = 0) and the translation free fall.
    #[test]
    fn free_particle_keeps_the_rank_revealing_path() {
        let p = Link::new(None, Joint::Free, Vector3::zeros(), 2.0, Vector3::zeros(), Matrix3::zeros());
        let mut m = Model::new(&[p]).expect("valid");
        m.gravity = Vector3::new(0.0, 0.0, -9.81);
        assert!(m.free_leaves.is_empty());
        let vd = m.aba(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0], &[0.0; 6], &[0.0; 6], None).expect("inert");
        assert_eq!(vd, vec![0.0, 0.0, -9.81, 0.0, 0.0, 0.0]);
    }
}
