//! The two passes of the RNEA derivatives ([`RneaDerivatives`] has the derivation): outward,
//! the ground-frame placements, motion subspaces, twists and accelerations with their
//! variations and each body's force and velocity variation; inward, the subtree sums and
//! the entries of ∂τ/∂q, ∂τ/∂v and M.
//!
//! Book: §7.11; Carpentier & Mansard (RSS 2018).
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Vector3, Vector6};
use vectrix_tensor::Scalar;

use super::{DerivativeScratch, RneaDerivatives};
use crate::multibody::crba::{dot6, world_subspace};
use crate::multibody::model::Model;
use crate::multibody::spatial::{BodyInertia, cross_columns, cross_force6, cross_motion6, join, split};
use crate::multibody::wrench::LinkWrenches;

/// The composite "velocity variation" Bᶜ = [[P, 0], [−2 f^×, 0]] of a subtree (see
/// [`RneaDerivatives`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Variation<T: Scalar> {
    P: Matrix3<T>,
    f: Vector3<T>,
}

impl<T: Scalar> Variation<T> {
    pub(super) fn zero() -> Self {
        Self { P: Matrix3::zeros(), f: Vector3::zeros() }
    }

    /// B of one body of ground inertia `y` moving with twist (ω, v):
    /// P = Ī̇ − n^× with Ī̇ = ω^×Ī − Īω^× − h vᵀ − v hᵀ + 2(v·h)1, (n, f) = I(ω, v); with Ī
    /// symmetric, Īω^× = −(ω^×Ī)ᵀ, so ω^×Ī − Īω^× = K + Kᵀ for K = ω^×Ī (three cross
    /// products).
    ///
    /// Written by entries: S = K + Kᵀ − h vᵀ − v hᵀ + 2(v·h)1 is symmetric (six numbers) and
    /// n^× antisymmetric (three), P = S − n^×.
    #[inline(always)]
    fn of_body(y: &BodyInertia<T>, w: &Vector3<T>, v: &Vector3<T>) -> Self {
        let (n, f) = y.apply(w, v);
        let K = cross_columns(w, &y.I);
        let (h, two_vh) = (&y.h, v.dot(&y.h) * T::lit(2.0));
        let s = |i: usize, j: usize| K[(i, j)] + K[(j, i)] - (h[i] * v[j] + h[j] * v[i]);
        let (s01, s02, s12) = (s(0, 1), s(0, 2), s(1, 2));
        let (d0, d1, d2) = (s(0, 0) + two_vh, s(1, 1) + two_vh, s(2, 2) + two_vh);
        #[rustfmt::skip]
        let P = Matrix3::new(
            d0,        s01 + n.z, s02 - n.y,
            s01 - n.z, d1,        s12 + n.x,
            s02 + n.y, s12 - n.x, d2,
        );
        Self { P, f }
    }

    fn add(&mut self, o: &Self) {
        self.P += o.P;
        self.f += o.f;
    }

    /// B·(ω, v) = (P ω, −2 f × ω).
    #[inline(always)]
    fn apply(&self, m: &Vector6<T>) -> Vector6<T> {
        let (w, _) = split(m);
        join(&(self.P * w), &(self.f.cross(&w) * T::lit(-2.0)))
    }

    /// The angular half of Bᵀ·(ω, v) = (Pᵀω + 2 f × v, 0).
    #[inline(always)]
    fn apply_transpose_angular(&self, m: &Vector6<T>) -> Vector3<T> {
        let (w, v) = split(m);
        self.P.tr_mul(&w) + self.f.cross(&v) * T::lit(2.0)
    }
}

/// Where the inward pass writes: τ, and ∂τ/∂q, ∂τ/∂v and M (n × n each, column-major).
pub(super) struct Partials<'a, T> {
    pub tau: &'a mut [T],
    pub dq: &'a mut [T],
    pub dv: &'a mut [T],
    pub mass: &'a mut [T],
}

impl<T: Scalar> Model<T> {
    /// The outward pass, ground coordinates: placement, J, v, a (with −g), each body's force
    /// fᵢ = Iᵢaᵢ + vᵢ ×* Iᵢvᵢ − f_ext and velocity variation Bᵢ as the seeds of the composites.
    pub(super) fn derivatives_outward(
        &self,
        q: &[T],
        v: &[T],
        vdot: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        s: &mut DerivativeScratch<T>,
    ) {
        let minus_g = join(&Vector3::zeros(), &(-self.gravity));
        s.trig.fill(q);
        for (i, seg) in self.segs.iter().enumerate() {
            let w = self.world_xform(i, q, seg.parent.map(|p| &s.world[p]), s.trig.get(i));
            let (ov_p, oa_p) = match seg.parent {
                Some(p) => (s.ov[p], s.oa[p]),
                None => (Vector6::zeros(), minus_g),
            };
            world_subspace(seg, &w, &mut s.J[seg.vi..]);
            let cols = seg.vi..seg.vi + seg.elem.nv();
            let (mut jv, mut ja) = (Vector6::zeros(), Vector6::zeros());
            for c in cols.clone() {
                jv += s.J[c] * v[c];
                ja += s.J[c] * vdot[c];
            }
            // vᵢ = vλ + J q̇, aᵢ = aλ + J q̈ + vᵢ × J q̇
            let ov = ov_p + jv;
            let oa = oa_p + ja + cross_motion6(&ov, &jv);
            // dVdq = vλ × J, dAdq = aλ × J + vλ × dVdq, dAdv = vᵢ × J + dVdq
            for c in cols {
                let Jc = s.J[c];
                let dV = cross_motion6(&ov_p, &Jc);
                s.dAdq[c] = cross_motion6(&oa_p, &Jc) + cross_motion6(&ov_p, &dV);
                s.dAdv[c] = cross_motion6(&ov, &Jc) + dV;
                s.dVdq[c] = dV;
            }
            if seg.massless {
                s.Yc[i] = BodyInertia::zero();
                s.Bc[i] = Variation::zero();
                s.Fc[i] = Vector6::zeros();
            } else {
                let Y = seg.ground_inertia(&w);
                let (ow, ovl) = split(&ov);
                let h = Y.apply6(&ov);
                s.Fc[i] = Y.apply6(&oa) + cross_force6(&ov, &h);
                s.Bc[i] = Variation::of_body(&Y, &ow, &ovl);
                s.Yc[i] = Y;
            }
            s.world[i] = w;
            s.ov[i] = ov;
            s.oa[i] = oa;
        }
        if let Some(fe) = f_ext {
            // a wrench (n, f) about the link origin in link components, to ground about the
            // ground origin: f_G = Eᵀf, n_G = Eᵀn + p × f_G
            for (l, &k) in self.link_seg.iter().enumerate() {
                let (n, f) = s.world[k].force_to_parent(&fe[l].moment, &fe[l].force);
                s.Fc[k] -= join(&n, &f);
            }
        }
    }

    /// The inward pass: composites Iᶜ, Bᶜ, Fᶜ summed tips to base, and for each column b of a
    /// segment, τ_b = J_b·Fᶜ, the joint's own block, and the pairs with every ancestor column
    /// a (both triangles of ∂τ/∂q and ∂τ/∂v, M mirrored). Entries between branches are zero
    /// and must be zero in `out` beforehand.
    pub(super) fn derivatives_inward(&self, out: Partials<'_, T>, s: &mut DerivativeScratch<T>) {
        let Partials { tau, dq, dv, mass: mm } = out;
        let n = self.nv;
        let at = |a: usize, b: usize| a + b * n;
        for i in (0..self.segs.len()).rev() {
            let seg = &self.segs[i];
            let nvi = seg.elem.nv();
            // (by reference: copying the three composites costs more than reading them in place)
            let (Yc, Bc, Fc) = (&s.Yc[i], &s.Bc[i], &s.Fc[i]);
            for b in seg.vi..seg.vi + nvi {
                let Jb = s.J[b];
                let YJ = Yc.apply6(&Jb);
                let BtJ = Bc.apply_transpose_angular(&Jb);
                let mut dFdq = Bc.apply(&s.dVdq[b]) + Yc.apply6(&s.dAdq[b]);
                let dFdv = Bc.apply(&Jb) + Yc.apply6(&s.dAdv[b]);
                tau[b] = dot6(&Jb, Fc);
                // the joint's own columns a (a ball's three): ∂τₐ/∂q_b, ∂τₐ/∂q̇_b, Mₐb
                for a in seg.vi..seg.vi + nvi {
                    let Ja = &s.J[a];
                    mm[at(a, b)] = dot6(Ja, &YJ);
                    dq[at(a, b)] = dot6(Ja, &dFdq);
                    dv[at(a, b)] = dot6(Ja, &dFdv);
                }
                // for the ancestors' rows, ∂Fᶜ/∂q_b gains the rigid-motion term J_b ×* Fᶜᵢ
                dFdq += cross_force6(&Jb, Fc);
                let mut c = self.parent_col[seg.vi];
                while let Some(a) = c {
                    let (Ja, dV, dAq, dAv) = (&s.J[a], &s.dVdq[a], &s.dAdq[a], &s.dAdv[a]);
                    // ancestor row a, descendant column b
                    dq[at(a, b)] = dot6(Ja, &dFdq);
                    dv[at(a, b)] = dot6(Ja, &dFdv);
                    let m = dot6(Ja, &YJ);
                    mm[at(a, b)] = m;
                    mm[at(b, a)] = m;
                    // descendant row b, ancestor column a (Bᵀ J has no linear half)
                    dq[at(b, a)] = dot6(&YJ, dAq) + BtJ.x * dV[0] + BtJ.y * dV[1] + BtJ.z * dV[2];
                    dv[at(b, a)] = dot6(&YJ, dAv) + BtJ.x * Ja[0] + BtJ.y * Ja[1] + BtJ.z * Ja[2];
                    c = self.parent_col[a];
                }
            }
            if let Some(p) = seg.parent {
                let (yc, bc, fc) = (s.Yc.split_at_mut(i), s.Bc.split_at_mut(i), s.Fc.split_at_mut(i));
                yc.0[p].add(&yc.1[0]);
                bc.0[p].add(&bc.1[0]);
                fc.0[p] += fc.1[0];
            }
        }
    }
}

/// ∂τ/∂q etc. as [`RneaDerivatives`] holds them, column-major.
impl<T: Scalar> RneaDerivatives<T> {
    pub(super) fn partials(&mut self) -> Partials<'_, T> {
        Partials {
            tau: &mut self.tau,
            dq: self.dtau_dq.as_mut_slice(),
            dv: self.dtau_dv.as_mut_slice(),
            mass: self.mass_matrix.as_mut_slice(),
        }
    }
}
