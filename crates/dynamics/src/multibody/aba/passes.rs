//! ABA's three passes on spatial trees (see [`Model::aba`]): twists and bias terms outward,
//! articulated inertias inward by their 3×3 blocks ([`Articulated`]), accelerations outward.
//! Joint types are told apart by a match on the elementary joint: a pin or slider along a
//! coordinate axis reads one column of Iᴬ for U = IᴬS, a ball three.
//!
//! Book: §7.11; RBDA Table 7.1.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Matrix6x3, Vector3, Vector6};
use vectrix_tensor::Scalar;

use super::AbaScratch;
use crate::DynamicsError;
use crate::multibody::articulated::Articulated;
use crate::multibody::joint::Elem;
use crate::multibody::model::Model;
use crate::multibody::rnea::{joint_bias, joint_motion};
use crate::multibody::singular::{null_component, pivot_tol, psd_pinv3, spd_inverse3};
use crate::multibody::spatial::{cross_force, join, split};

/// (Iᵃ, pᵃ): what a segment passes to its parent (before the transform).
type Passed<T> = (Articulated<T>, Vector6<T>);

impl<T: Scalar> Model<T> {
    /// Pass 1 (outward): twists, bias accelerations c = 𝒱 ×m S q̇, bias forces 𝒱 ×f 𝒥𝒱 (zero
    /// for a massless segment), and each body's inertia as the seed of Iᴬ.
    pub(super) fn aba_outward(&self, q: &[T], v: &[T], s: &mut AbaScratch<T>) {
        for (i, seg) in self.segs.iter().enumerate() {
            if self.aba_skip[i] {
                continue;
            }
            let x = self.seg_xform(i, q, s.trig.get(i));
            let (wp, vp) = match seg.parent {
                Some(p) => (s.w[p], s.v[p]),
                None => (Vector3::zeros(), Vector3::zeros()),
            };
            let (mut wi, mut vi) = seg.turn.motion(&x, &wp, &vp);
            let (sw, sv) = joint_motion(&seg.elem, &v[seg.vi..]);
            wi += sw;
            vi += sv;
            let (cw, cv) = joint_bias(&seg.elem, &wi, &vi, &sw, &sv);
            s.pA[i] = if seg.massless {
                Vector6::zeros()
            } else {
                let (hn, hf) = seg.inertia.apply(&wi, &vi);
                let (bn, bf) = cross_force(&wi, &vi, &hn, &hf);
                join(&bn, &bf)
            };
            s.x[i] = x;
            s.c[i] = join(&cw, &cv);
            s.IA[i] = Articulated::from_body(&seg.inertia);
            s.reach[i] = seg.own_reach;
            (s.w[i], s.v[i]) = (wi, vi);
        }
    }

    /// Pass 2 (inward): U = IᴬS, D = SᵀU, u = τ − SᵀpA; Iᵃ = Iᴬ − U D⁻¹Uᵀ,
    /// pᵃ = pᴬ + Iᵃc + U D⁻¹u, accumulated into the parent through Xᵀ (a rotation of the
    /// blocks, then a shift).
    ///
    /// A free joint at the root with a subtree (a floating base) is eliminated last, all at
    /// once ([`Model::free_root_solve`]); should its 6×6 solve find a pivot at the rounding
    /// level, its four segments are eliminated one by one as any other.
    pub(super) fn aba_inward(&self, tau: &[T], s: &mut AbaScratch<T>) -> Result<(), DynamicsError> {
        // compiled twice: a model without a floating base pays nothing for them
        if self.free_roots.is_empty() {
            self.inward_loop::<false>(tau, s)
        } else {
            self.inward_loop::<true>(tau, s)
        }
    }

    /// Pass 2's loop, with (`ROOTS`) or without the free roots' 6×6 solves.
    #[inline(always)]
    fn inward_loop<const ROOTS: bool>(&self, tau: &[T], s: &mut AbaScratch<T>) -> Result<(), DynamicsError> {
        let skip = if ROOTS { &self.inward_skip } else { &self.aba_skip };
        for i in (0..self.segs.len()).rev() {
            if skip[i] {
                let Some(k) = self.free_root_seg[i].filter(|_| ROOTS) else { continue };
                // a free root: its ball (the last of its four segments) comes first, with the
                // whole subtree eliminated
                if i == self.free_roots[k] + 3 {
                    s.root_fast[k] = self.free_root_solve(k, tau, s);
                }
                if s.root_fast[k] {
                    continue;
                }
            }
            self.inward_step(i, tau, s)?;
        }
        Ok(())
    }

    /// Pass 2 at segment i: eliminate its joint, and add what is left to its parent.
    #[inline(always)]
    fn inward_step(&self, i: usize, tau: &[T], s: &mut AbaScratch<T>) -> Result<(), DynamicsError> {
        let seg = &self.segs[i];
        let (Ia, pa) = match seg.elem {
            Elem::Revolute(a) | Elem::Prismatic(a) => self.scalar_inward(i, &a, tau, s)?,
            Elem::Spherical => self.ball_inward(i, tau, s)?,
            Elem::Fixed => (s.IA[i], s.pA[i] + s.IA[i].apply6(&s.c[i])),
        };
        if let Some(p) = seg.parent {
            let add = Ia.in_parent(&s.x[i], seg.turn);
            s.IA[p].add(&add);
            let (pn, pf) = seg.turn.force_to_parent(
                &s.x[i],
                &pa.fixed_rows::<3>(0).into_owned(),
                &pa.fixed_rows::<3>(3).into_owned(),
            );
            s.pA[p] += join(&pn, &pf);
            if seg.sub_mass > 0.0 {
                // ρ_p ≥ ρ_i + |r_i| (‖·‖₁ ≥ ‖·‖₂)
                let r = &s.x[i].r;
                let reach = s.reach[i] + r.x.re().abs() + r.y.re().abs() + r.z.re().abs();
                s.reach[p] = s.reach[p].max(reach);
            }
        }
        Ok(())
    }

    /// Pass 2 and the root of pass 3 at free root k (segments f..f+4: three massless sliders
    /// along the axes of the joint frame J, then the ball carrying the base body B), once its
    /// subtree is eliminated. With the joint accelerations zero the base would accelerate by
    /// 𝒜⁰ (the gravity and bias terms carried out through the four segments); the joint adds
    /// y = (ω̇, E p̈), ω̇ the ball's and p̈ the sliders' coordinates' accelerations, E = 𝓞_{B/J}
    /// (the sliders move the base along J's axes, resolved in B). The joint's forces are the
    /// base's wrench f = Iᴬ(𝒜⁰ + y) + pᴬ resolved back: τ_ball = n, τ_slide = Eᵀf. So
    /// Iᴬ y = (τ_ball, E τ_slide) − Iᴬ𝒜⁰ − pᴬ, one 6×6 solve by blocks: C⁻¹ (the mass block),
    /// then the Schur complement A − B C⁻¹ Bᵀ, both by Cholesky with ABA's pivot floors (the
    /// subtree's mass; the angular scale of [`Model::angular_scale`]). The four segments'
    /// eliminations give the same y (RBDA §7.3 for a 6-DOF joint; Pinocchio's free-flyer).
    /// Returns false (nothing changed) when a pivot is at the rounding level.
    ///
    /// Book: §7.11 (7.11.13) for the base; RBDA Table 7.1.
    fn free_root_solve(&self, k: usize, tau: &[T], s: &mut AbaScratch<T>) -> bool {
        let f = self.free_roots[k];
        let b = f + 3;
        let mut a = join(&Vector3::zeros(), &(-self.gravity));
        for i in f..=b {
            let (aw, av) = split(&a);
            let (xw, xv) = self.segs[i].turn.motion(&s.x[i], &aw, &av);
            a = join(&xw, &xv) + s.c[i];
        }
        let (IA, pA) = (&s.IA[b], &s.pA[b]);
        let e = &s.x[b].E;
        let (vs, vb) = (self.segs[f].vi, self.segs[b].vi);
        let t_ball = Vector3::new(tau[vb], tau[vb + 1], tau[vb + 2]);
        let t_slide = e * Vector3::new(tau[vs], tau[vs + 1], tau[vs + 2]);
        let (rw, rv) = split(&(join(&t_ball, &t_slide) - IA.apply6(&a) - pA));
        let Some(c_inv) = spd_inverse3(&IA.C, pivot_tol::<T>() * self.segs[b].sub_mass) else {
            return false;
        };
        let K = IA.B * c_inv;
        let schur = IA.A - K * IA.B.transpose();
        let Some(s_inv) = spd_inverse3(&schur, pivot_tol::<T>() * self.angular_scale(b, s)) else {
            return false;
        };
        let yw = s_inv * (rw - K * rv);
        let yv = c_inv * (rv - IA.B.tr_mul(&yw));
        s.root_y[k] = join(&yw, &yv);
        s.a[b] = a + s.root_y[k];
        true
    }

    /// The rounding scale of a pin's or ball's block of Iᴬ: the subtree's composite inertia
    /// bounds it (Iᴬ ≼ Iᶜ) and has no cancellation: Σ tr J_c + 2Mρ².
    #[inline(always)]
    fn angular_scale(&self, i: usize, s: &AbaScratch<T>) -> f64 {
        self.segs[i].angular_scale_at(s.reach[i])
    }

    /// Pass 2 at a pin (S = (a, 0)) or slider (S = (0, a)): along a coordinate axis U is ± one
    /// column of Iᴬ. A pivot D at the rounding level (its subtree's mass for a slider) is an
    /// inert coordinate: D = 0 means IᴬS = 0, so its force must vanish (else q̈ = ∞), and it
    /// gets q̈ = 0.
    #[inline(always)]
    fn scalar_inward(
        &self,
        i: usize,
        a: &Vector3<T>,
        tau: &[T],
        s: &mut AbaScratch<T>,
    ) -> Result<Passed<T>, DynamicsError> {
        let seg = &self.segs[i];
        let (IA, pA) = (s.IA[i], s.pA[i]);
        let revolute = matches!(seg.elem, Elem::Revolute(_));
        let (uw, uv) = match (seg.coord_axis, revolute) {
            (Some((k, negative)), _) => {
                let (w, v) = IA.column(if revolute { k } else { k + 3 });
                if negative { (-w, -v) } else { (w, v) }
            }
            (None, true) => (IA.A * a, IA.B.tr_mul(a)),
            (None, false) => (IA.B * a, IA.C * a),
        };
        let (pn, pf) = split(&pA);
        let (D, u, scale) = if revolute {
            (a.dot(&uw), tau[seg.vi] - a.dot(&pn), self.angular_scale(i, s))
        } else {
            (a.dot(&uv), tau[seg.vi] - a.dot(&pf), seg.sub_mass)
        };
        if D.re() > pivot_tol::<T>() * scale {
            let dinv = D.recip();
            let U = join(&uw, &uv);
            s.U[i].set_column(0, &U);
            s.Dinv[i][(0, 0)] = dinv;
            s.u[i][0] = u;
            let Ia = IA.sub_rank1(&uw, &uv, dinv);
            let pa = pA + Ia.apply6(&s.c[i]) + U * (u * dinv);
            return Ok((Ia, pa));
        }
        // singular: the coordinate carries no inertia
        let tolerance = pivot_tol::<T>() * self.force_scale(i, tau, s);
        if u.re().abs() > tolerance {
            return Err(DynamicsError::InertJointForce { coordinate: seg.vi, force: u.re(), tolerance });
        }
        s.U[i] = Matrix6x3::zeros();
        s.Dinv[i] = Matrix3::zeros();
        s.u[i] = Vector3::zeros();
        Ok((IA, pA + IA.apply6(&s.c[i])))
    }

    /// Pass 2 at a ball: S = [1; 0], so U = [A; Bᵀ] and D = A. Fast path: Cholesky with every
    /// pivot above the rounding level; slow path: a rank-revealing pseudo-inverse, with no
    /// force along the inert directions (a particle cannot take a torque about its radius).
    #[inline(always)]
    fn ball_inward(&self, i: usize, tau: &[T], s: &mut AbaScratch<T>) -> Result<Passed<T>, DynamicsError> {
        let seg = &self.segs[i];
        let (IA, pA) = (s.IA[i], s.pA[i]);
        let angular_scale = self.angular_scale(i, s);
        let (uw, uv) = (IA.A, IA.B.transpose());
        let D = IA.A;
        let u =
            Vector3::new(tau[seg.vi], tau[seg.vi + 1], tau[seg.vi + 2]) - Vector3::new(pA[0], pA[1], pA[2]);
        let Dinv = match spd_inverse3(&D, pivot_tol::<T>() * angular_scale) {
            Some(inv) => inv,
            None => {
                let (pinv, null, _) = psd_pinv3(&D, pivot_tol::<T>() * angular_scale);
                let along = null_component(&null, &u);
                let tolerance = pivot_tol::<T>() * self.force_scale(i, tau, s);
                if along > tolerance {
                    return Err(DynamicsError::InertJointForce {
                        coordinate: seg.vi,
                        force: along,
                        tolerance,
                    });
                }
                pinv
            }
        };
        s.U[i].fixed_view_mut::<3, 3>(0, 0).copy_from(&uw);
        s.U[i].fixed_view_mut::<3, 3>(3, 0).copy_from(&uv);
        s.Dinv[i] = Dinv;
        s.u[i] = u;
        let Ia = IA.sub_rank3(&uw, &uv, &Dinv);
        let k = Dinv * u;
        let pa = pA + Ia.apply6(&s.c[i]) + join(&(uw * k), &(uv * k));
        Ok((Ia, pa))
    }

    /// Pass 3 (outward): 𝒜' = X𝒜_p + c, q̈ = D⁻¹(u − Uᵀ𝒜'), 𝒜 = 𝒜' + S q̈.
    pub(super) fn aba_accelerations(&self, vdot: &mut [T], s: &mut AbaScratch<T>) {
        if self.free_roots.is_empty() {
            self.accelerations_loop::<false>(vdot, s)
        } else {
            self.accelerations_loop::<true>(vdot, s)
        }
    }

    /// Pass 3's loop, with (`ROOTS`) or without the free roots solved in pass 2.
    #[inline(always)]
    fn accelerations_loop<const ROOTS: bool>(&self, vdot: &mut [T], s: &mut AbaScratch<T>) {
        let a0 = join(&Vector3::zeros(), &(-self.gravity));
        for (i, seg) in self.segs.iter().enumerate() {
            if self.aba_skip[i] {
                continue;
            }
            if ROOTS
                && let Some(k) = self.free_root_seg[i]
                && s.root_fast[k]
            {
                // solved with pass 2 (`free_root_solve`), which set the base's 𝒜
                if i == self.free_roots[k] {
                    let (yw, yv) = split(&s.root_y[k]);
                    let pdd = s.x[i + 3].E.tr_mul(&yv);
                    let vb = self.segs[i + 3].vi;
                    vdot[seg.vi..seg.vi + 3].copy_from_slice(pdd.as_slice());
                    vdot[vb..vb + 3].copy_from_slice(yw.as_slice());
                }
                continue;
            }
            let ap = match seg.parent {
                Some(p) => s.a[p],
                None => a0,
            };
            let (aw, av) = split(&ap);
            let (xw, xv) = seg.turn.motion(&s.x[i], &aw, &av);
            let a_prime = join(&xw, &xv) + s.c[i];
            s.a[i] = match seg.elem {
                Elem::Revolute(ax) | Elem::Prismatic(ax) => {
                    let qdd = s.Dinv[i][(0, 0)] * (s.u[i][0] - s.U[i].column(0).dot(&a_prime));
                    vdot[seg.vi] = qdd;
                    match seg.elem {
                        Elem::Revolute(_) => a_prime + join(&(ax * qdd), &Vector3::zeros()),
                        _ => a_prime + join(&Vector3::zeros(), &(ax * qdd)),
                    }
                }
                Elem::Spherical => {
                    let qdd = s.Dinv[i] * (s.u[i] - s.U[i].transpose() * a_prime);
                    vdot[seg.vi..seg.vi + 3].copy_from_slice(qdd.as_slice());
                    a_prime + join(&qdd, &Vector3::zeros())
                }
                Elem::Fixed => a_prime,
            };
        }
    }

    /// The size of the forces that meet at segment i before the eliminations of pass 2 cancel
    /// them (slow path only): over i and its subtree k, max of |τₖ| + ‖Iᴬₖ‖(‖cₖ‖ + |𝒱ₖ|²) +
    /// ‖pᴬₖ‖ + ‖UₖDₖ⁺uₖ‖, times (1 + ρᵢ) for the lever arms. A generalized force along an inert
    /// direction is rounding noise when it is below 64 ε times this.
    fn force_scale(&self, i: usize, tau: &[T], s: &AbaScratch<T>) -> f64 {
        let mut mag = 0.0f64;
        for k in i..self.segs.len() {
            // k in the subtree of i: its ancestors (which have smaller indices) reach i
            let mut j = k;
            while j > i {
                match self.segs[j].parent {
                    Some(p) => j = p,
                    None => break,
                }
            }
            if j != i {
                continue;
            }
            let seg = &self.segs[k];
            let t: f64 = (0..seg.elem.nv()).map(|a| tau[seg.vi + a].re().abs()).sum();
            let v2 = (s.w[k].norm_squared() + s.v[k].norm_squared()).re();
            let inertial = s.IA[k].norm().re() * (s.c[k].norm().re() + v2);
            let udu = if k > i { (s.U[k] * (s.Dinv[k] * s.u[k])).norm().re() } else { 0.0 };
            mag = mag.max(t + inertial + s.pA[k].norm().re() + udu);
        }
        mag * (1.0 + s.reach[i])
    }
}
