//! ABA's three passes in ground coordinates (RBDA §7.3 in "base coordinates"): every twist,
//! inertia and force resolved in the ground's axes about one reference point, so that an
//! articulated inertia passes to its parent by a plain sum, with no rotation and no shift.
//! What it pays instead: each body's inertia turned into the ground (one symmetric 3×3
//! rotation, `BodyInertia::from_centre_in_ground`), and U = IᴬS with a full S = (u, p × u)
//! (four 3×3 products). On a tree whose joints are not along its link axes (every imported
//! robot) that is about half the arithmetic of rotating three 3×3 blocks per joint.
//!
//! The reference point is the base's origin (a floating base) or the first segment's: a tree
//! far from the ground origin keeps the lever arms of a local formulation. A pivot D that is
//! not clearly above its rounding level (within [`MARGIN`] of the local passes' floor) makes
//! these passes give up before writing v̇, and the local passes decide it (exactly, as
//! documented on `Model::aba`).
//!
//! Book: §7.11; RBDA §7.3, Table 7.1.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Vector3, Vector6};
use vectrix_tensor::Scalar;

use super::AbaScratch;
use super::sym6::Sym6;
use crate::multibody::crba::world_subspace;
use crate::multibody::joint::Elem;
use crate::multibody::model::Model;
use crate::multibody::singular::{pivot_tol, spd_inverse3};
use crate::multibody::spatial::{cross_force, join, split};
use crate::multibody::wrench::LinkWrenches;

/// The ground passes hand a pivot to the local passes unless D exceeds this multiple of the
/// local passes' own floor (64 ε × the joint's scale), so that they never decide a joint the
/// local passes would call inert.
const MARGIN: f64 = 1024.0;

impl<T: Scalar> Model<T> {
    /// ABA in ground coordinates (see the module docs); `false`, with `vdot` untouched, when
    /// a pivot is near its rounding level. `s.trig` must hold q's sines and cosines.
    pub(super) fn aba_ground(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        vdot: &mut [T],
        s: &mut AbaScratch<T>,
    ) -> bool {
        let n = self.segs.len();
        let reference = match self.free_roots.first() {
            Some(&f) => Some(f + 3),
            None => (0..n).find(|&i| !self.aba_skip[i]),
        };
        let Some(reference) = reference else { return true };
        // placements first: the reference point may sit below the first segments (a free
        // root's base, behind its three sliders). The reference segment's subtree is placed
        // relative to it directly (its origin set to zero before its children are placed, so
        // that no lever arm is the difference of two large positions); the others are moved
        // there afterwards
        let mut origin = Vector3::zeros();
        for i in 0..n {
            if !self.aba_skip[i] {
                let parent = self.segs[i].parent;
                s.x[i] = self.world_xform(i, q, parent.map(|p| &s.x[p]), s.trig.get(i));
                s.rel[i] = i == reference || parent.is_some_and(|p| s.rel[p]);
                if i == reference {
                    origin = s.x[i].r;
                    s.x[i].r = Vector3::zeros();
                }
            }
        }
        for i in 0..n {
            if !self.aba_skip[i] && !s.rel[i] {
                s.x[i].r -= origin;
            }
        }
        self.ground_outward(v, s);
        if let Some(fe) = f_ext {
            for (l, &k) in self.link_seg.iter().enumerate() {
                if !self.aba_skip[k] {
                    // the link's wrench about its origin in link axes, to ground axes about
                    // the reference point
                    let (m, f) = s.x[k].force_to_parent(&fe[l].moment, &fe[l].force);
                    s.pA[k] -= join(&m, &f);
                }
            }
        }
        if !self.ground_inward(tau, s) {
            return false;
        }
        self.ground_accelerations(vdot, s);
        true
    }

    /// Pass 1 (the placements made): motion subspaces S, twists 𝒱ᵢ =
    /// 𝒱ₚ + Sq̇, bias accelerations c = 𝒱ᵢ ×m Sq̇ (S is fixed in the segment, so Ṡ = 𝒱ᵢ ×m S),
    /// bias forces 𝒱 ×f I𝒱 and each body's inertia as the seed of Iᴬ.
    fn ground_outward(&self, v: &[T], s: &mut AbaScratch<T>) {
        for (i, seg) in self.segs.iter().enumerate() {
            if self.aba_skip[i] {
                continue;
            }
            let x = &s.x[i];
            let k = seg.elem.nv();
            let cols = &mut s.S[seg.vi..seg.vi + k];
            world_subspace(seg, x, cols);
            let mut sq = Vector6::zeros();
            for (col, &rate) in cols.iter().zip(&v[seg.vi..seg.vi + k]) {
                sq += col * rate;
            }
            let (sw, sv) = split(&sq);
            let (wp, vp) = match seg.parent {
                Some(p) => (s.w[p], s.v[p]),
                None => (Vector3::zeros(), Vector3::zeros()),
            };
            let (wi, vi) = (wp + sw, vp + sv);
            s.c[i] = join(&wi.cross(&sw), &(wi.cross(&sv) + vi.cross(&sw)));
            if seg.massless {
                s.G[i] = Sym6::zero();
                s.pA[i] = Vector6::zeros();
            } else {
                let body = seg.ground_inertia(x);
                let (hn, hf) = body.apply(&wi, &vi);
                let (bn, bf) = cross_force(&wi, &vi, &hn, &hf);
                s.pA[i] = join(&bn, &bf);
                s.G[i] = Sym6::from_body(&body);
            }
            s.reach[i] = seg.own_reach;
            (s.w[i], s.v[i]) = (wi, vi);
        }
    }

    /// Pass 2: U = IᴬS, D = SᵀU, u = τ − SᵀpA; Iᵃ = Iᴬ − UD⁻¹Uᵀ and pᵃ = pᴬ + Iᵃc + UD⁻¹u,
    /// added to the parent's as they are. `false` at a pivot near its rounding level.
    fn ground_inward(&self, tau: &[T], s: &mut AbaScratch<T>) -> bool {
        for i in (0..self.segs.len()).rev() {
            if self.aba_skip[i] {
                continue;
            }
            let seg = &self.segs[i];
            let (c, pA) = (s.c[i], s.pA[i]);
            match seg.elem {
                Elem::Revolute(_) | Elem::Prismatic(_) => {
                    let S = s.S[seg.vi];
                    let U = s.G[i].mul(&S);
                    let D = S.dot(&U);
                    let scale = match seg.elem {
                        Elem::Revolute(_) => self.ground_angular_scale(i, s),
                        _ => seg.sub_mass,
                    };
                    // (false for NaN, which goes to the local passes too)
                    if D.re().partial_cmp(&(MARGIN * pivot_tol::<T>() * scale))
                        != Some(core::cmp::Ordering::Greater)
                    {
                        return false;
                    }
                    let dinv = D.recip();
                    let u = tau[seg.vi] - S.dot(&pA);
                    let k = U * dinv;
                    (s.GU[seg.vi], s.Dinv[i][(0, 0)], s.u[i][0]) = (U, dinv, u);
                    if let Some(p) = seg.parent {
                        // Iᵃc = Iᴬc − k(U·c) and UD⁻¹u = k u
                        let pa = pA + s.G[i].mul(&c) + k * (u - U.dot(&c));
                        let Ia = s.G[i];
                        s.G[p].add_minus_outer(&Ia, &U, &k);
                        s.pA[p] += pa;
                    }
                }
                Elem::Spherical => {
                    let Some(Ia) = self.ground_ball(i, tau, s) else { return false };
                    if let Some(p) = seg.parent {
                        let k = s.Dinv[i] * s.u[i];
                        let cols = &s.GU[seg.vi..seg.vi + 3];
                        let pa = pA + Ia.mul(&c) + cols[0] * k[0] + cols[1] * k[1] + cols[2] * k[2];
                        s.G[p].add(&Ia);
                        s.pA[p] += pa;
                    }
                }
                Elem::Fixed => {
                    if let Some(p) = seg.parent {
                        let (Ia, pa) = (s.G[i], pA + s.G[i].mul(&c));
                        s.G[p].add(&Ia);
                        s.pA[p] += pa;
                    }
                }
            }
            if let Some(p) = seg.parent
                && seg.sub_mass > 0.0
            {
                // ρ_p ≥ ρ_i + |r_i − r_p| (‖·‖₁ ≥ ‖·‖₂)
                let d = s.x[i].r - s.x[p].r;
                let reach = s.reach[i] + d.x.re().abs() + d.y.re().abs() + d.z.re().abs();
                s.reach[p] = s.reach[p].max(reach);
            }
        }
        true
    }

    /// Pass 2 at a ball (S = three columns (uₖ, p × uₖ)): U = IᴬS, D = SᵀU by Cholesky,
    /// u = τ − SᵀpA, Iᵃ = Iᴬ − UD⁻¹Uᵀ; `None` at a pivot near its rounding level.
    #[inline(always)]
    fn ground_ball(&self, i: usize, tau: &[T], s: &mut AbaScratch<T>) -> Option<Sym6<T>> {
        let seg = &self.segs[i];
        let S: [Vector6<T>; 3] = core::array::from_fn(|k| s.S[seg.vi + k]);
        let U: [Vector6<T>; 3] = core::array::from_fn(|k| s.G[i].mul(&S[k]));
        let (d01, d02, d12) = (S[0].dot(&U[1]), S[0].dot(&U[2]), S[1].dot(&U[2]));
        let D = Matrix3::new(S[0].dot(&U[0]), d01, d02, d01, S[1].dot(&U[1]), d12, d02, d12, S[2].dot(&U[2]));
        let floor = MARGIN * pivot_tol::<T>() * self.ground_angular_scale(i, s);
        let Dinv = spd_inverse3(&D, floor)?;
        let pA = s.pA[i];
        s.u[i] = Vector3::from_fn(|k, _| tau[seg.vi + k] - S[k].dot(&pA));
        s.GU[seg.vi..seg.vi + 3].copy_from_slice(&U);
        s.Dinv[i] = Dinv;
        Some(s.G[i].minus_rank3(&U, &Dinv))
    }

    /// The rounding scale of a pin's or ball's pivot: `angular_scale` of the local passes with
    /// the lever arm ρᵢ + |pᵢ|₁ from the reference point instead of ρᵢ from the joint, since
    /// these passes form D from terms of that size (a particle at the joint has D = 0 exactly
    /// in the joint's own coordinates, but m|p|²-sized terms cancelling here).
    #[inline(always)]
    fn ground_angular_scale(&self, i: usize, s: &AbaScratch<T>) -> f64 {
        let p = &s.x[i].r;
        self.segs[i].angular_scale_at(s.reach[i] + p.x.re().abs() + p.y.re().abs() + p.z.re().abs())
    }

    /// Pass 3: 𝒜' = 𝒜ₚ + c, q̈ = D⁻¹(u − Uᵀ𝒜'), 𝒜 = 𝒜' + Sq̈; the ground accelerates by −g
    /// (gravity as the fictitious acceleration of the base).
    fn ground_accelerations(&self, vdot: &mut [T], s: &mut AbaScratch<T>) {
        let a0 = join(&Vector3::zeros(), &(-self.gravity));
        for (i, seg) in self.segs.iter().enumerate() {
            if self.aba_skip[i] {
                continue;
            }
            let ap = seg.parent.map_or(a0, |p| s.a[p]);
            let a_prime = ap + s.c[i];
            let vi = seg.vi;
            s.a[i] = match seg.elem {
                Elem::Revolute(_) | Elem::Prismatic(_) => {
                    let qdd = s.Dinv[i][(0, 0)] * (s.u[i][0] - s.GU[vi].dot(&a_prime));
                    vdot[vi] = qdd;
                    a_prime + s.S[vi] * qdd
                }
                Elem::Spherical => {
                    let ua = Vector3::new(
                        s.GU[vi].dot(&a_prime),
                        s.GU[vi + 1].dot(&a_prime),
                        s.GU[vi + 2].dot(&a_prime),
                    );
                    let qdd = s.Dinv[i] * (s.u[i] - ua);
                    vdot[vi..vi + 3].copy_from_slice(qdd.as_slice());
                    a_prime + s.S[vi] * qdd[0] + s.S[vi + 1] * qdd[1] + s.S[vi + 2] * qdd[2]
                }
                Elem::Fixed => a_prime,
            };
        }
    }
}
