//! Two states of a pin chain at once: ABA's three passes of [`Planar::aba`] on pairs of
//! numbers, each operation done on both lanes by one instruction. A chain's passes are a
//! chain of dependent operations (each pin's D⁻¹ waits on its child's), so two independent
//! evaluations interleaved cost about 1.2 times one (0.57–0.64× two calls on chains of 6–30,
//! `docs/performance.md`). Each lane's operations are those of the single pass, in the same
//! order (pass 2 at a pin is the same function, `aba::pin_step`): the same bits.
//!
//! Book: §7.11 (chains); RBDA §2.16, Table 7.1.

use core::ops::{Add, Mul, Neg, Sub};

use super::Planar;
use super::aba::{Lane, pin_step};
use crate::DynamicsError;
use crate::error::check_len;
use crate::multibody::singular::pivot_tol;
use crate::multibody::{AbaScratch, Model};

/// Two f64 lanes.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct X2(pub [f64; 2]);

impl X2 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Self([x, x])
    }
}

macro_rules! lanes {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for X2 {
            type Output = X2;
            #[inline(always)]
            fn $f(self, o: X2) -> X2 {
                X2([self.0[0] $op o.0[0], self.0[1] $op o.0[1]])
            }
        }
        impl $tr<f64> for X2 {
            type Output = X2;
            #[inline(always)]
            fn $f(self, o: f64) -> X2 {
                X2([self.0[0] $op o, self.0[1] $op o])
            }
        }
    };
}
lanes!(Add, add, +);
lanes!(Sub, sub, -);
lanes!(Mul, mul, *);

impl Neg for X2 {
    type Output = X2;
    #[inline(always)]
    fn neg(self) -> X2 {
        X2([-self.0[0], -self.0[1]])
    }
}

/// One segment's work space of the paired passes.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct PairScratch {
    c: [X2; 2],
    d: [X2; 2],
    ew: [X2; 3],
    ia: [X2; 6],
    pa: [X2; 3],
    b: [X2; 2],
    u0: X2,
    ud: X2,
}

#[inline(always)]
fn rot(cs: &[X2; 2], x: &[f64; 2]) -> [X2; 2] {
    [cs[0] * x[0] - cs[1] * x[1], cs[1] * x[0] + cs[0] * x[1]]
}

impl Planar<f64> {
    /// [`Planar::aba`] of a pin chain without external wrenches for two states `a` and `b`
    /// at once (lane 0 and lane 1 of every [`X2`]), gravity's in-plane part `gravity` =
    /// (g·û, g·ŵ) negated; `trig` holds 6n numbers (both lanes' angles interleaved, then their
    /// sines, then their cosines), `s` n entries. `false` (nothing kept) when either lane
    /// meets an inert coordinate: the caller then takes two single calls, which decide it.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn aba_pair(
        &self,
        (qa, va): (&[f64], &[f64]),
        (qb, vb): (&[f64], &[f64]),
        tau: &[f64],
        gravity: [f64; 2],
        (da, db): (&mut [f64], &mut [f64]),
        s: &mut [PairScratch],
        trig: &mut [f64],
    ) -> bool {
        let n = self.segs.len();
        let (x, rest) = trig.split_at_mut(2 * n);
        let (sn, cn) = rest.split_at_mut(2 * n);
        for i in 0..n {
            x[2 * i] = qa[i];
            x[2 * i + 1] = qb[i];
        }
        <f64 as vectrix_tensor::Scalar>::fast_sin_cos_slices(x, sn, cn);
        let z = X2::default();
        // pass 1
        let (mut cp, mut wp, mut vp) = ([X2::splat(1.0), z], z, [z; 2]);
        for (i, ps) in self.segs.iter().enumerate() {
            let e = &mut s[i];
            let d = rot(&cp, &ps.r);
            let vi = [vp[0] - wp * d[1], vp[1] + wp * d[0]];
            let snx = X2([sn[2 * i], sn[2 * i + 1]]) * ps.sigma;
            let cnx = X2([cn[2 * i], cn[2 * i + 1]]);
            let qd = X2([va[i], vb[i]]) * ps.sigma;
            e.c = [qd * vi[1], -(qd * vi[0])];
            let cs = [cp[0] * cnx - cp[1] * snx, cp[1] * cnx + cp[0] * snx];
            let wi = wp + qd;
            let h = rot(&cs, &ps.h);
            let m = ps.m;
            e.ia = [X2::splat(ps.i_o), -h[1], h[0], X2::splat(m), z, X2::splat(m)];
            let f = [vi[0] * m - wi * h[1], vi[1] * m + wi * h[0]];
            e.pa = [vi[0] * f[1] - vi[1] * f[0], -(wi * f[1]), wi * f[0]];
            e.d = d;
            e.ew = [d[1] * d[1], -((d[0] + d[0]) * d[1]), d[0] * d[0]];
            (cp, wp, vp) = (cs, wi, vi);
        }
        // pass 2
        let tol = pivot_tol::<f64>();
        let (mut pend_ia, mut pend_pa) = ([z; 6], [z; 3]);
        for (i, ps) in self.segs.iter().enumerate().rev() {
            let e = &mut s[i];
            let (mut ia, mut pa) = (e.ia, e.pa);
            if i + 1 < n {
                for (x, y) in ia.iter_mut().zip(pend_ia) {
                    *x = *x + y;
                }
                for (x, y) in pa.iter_mut().zip(pend_pa) {
                    *x = *x + y;
                }
            }
            // both lanes' D above its rounding level, else the caller's single calls decide it
            let min_d = tol * ps.scale;
            if !(ia[0].0[0] > min_d && ia[0].0[1] > min_d) {
                return false;
            }
            let st = pin_step(e.c, e.d, e.ew, ia, pa, X2::splat(tau[i] * ps.sigma));
            (e.b, e.u0, e.ud) = (st.b, st.u0, st.ud);
            let (ia2, pa2, a, b) = st.inward;
            let ex = [-e.d[1], e.d[0]];
            let nf = pa2[0] + ex[0] * pa2[1] + ex[1] * pa2[2];
            (pend_ia, pend_pa) = ([a, b[0], b[1], ia2[3], ia2[4], ia2[5]], [nf, pa2[1], pa2[2]]);
        }
        // pass 3
        let mut ap = [z, X2::splat(gravity[0]), X2::splat(gravity[1])];
        for (i, ps) in self.segs.iter().enumerate() {
            let e = &s[i];
            let a = [ap[0], (ap[1] + e.c[0]) - ap[0] * e.d[1], (ap[2] + e.c[1]) + ap[0] * e.d[0]];
            let al = (e.u0 + e.ud * ap[0]) - (e.b[0] * ap[1] + e.b[1] * ap[2]);
            let qdd = (al - a[0]) * ps.sigma;
            da[i] = qdd.0[0];
            db[i] = qdd.0[1];
            ap = [al, a[1], a[2]];
        }
        true
    }
}

impl Lane for X2 {
    #[inline(always)]
    fn zero() -> X2 {
        X2::default()
    }
    #[inline(always)]
    fn recip(self) -> X2 {
        X2([1.0 / self.0[0], 1.0 / self.0[1]])
    }
}

impl Model<f64> {
    /// [`Model::aba_unchecked`] at two states (q_a, v_a) and (q_b, v_b) with one τ: v̇_a and
    /// v̇_b, the same bits as two calls. On a planar chain of pins ([`Model::aba_pairs`]) the
    /// passes run on both states at once, two lanes per instruction: a chain's evaluation is a
    /// chain of dependent operations (each pin's D⁻¹ waits on its child's), so the second
    /// state costs about a third of the first (chain of 6 pins: 0.64–0.69× the time of two
    /// calls, `docs/performance.md`). Any other model, and a pair in which either state meets
    /// an inert coordinate, takes two calls. For integrators that evaluate independent states
    /// (the rows of extrapolation: `vectrix_ode::Rhs::call_pair_into`).
    ///
    /// Book: §7.11; RBDA §2.16, Table 7.1.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`] when a slice's length is not the model's (q: nq;
    /// v, τ, v̇: nv); otherwise as [`Model::aba_unchecked`] (the values are not checked: a
    /// non-finite input gives a non-finite v̇).
    pub fn aba_pair_unchecked(
        &self,
        a: (&[f64], &[f64]),
        b: (&[f64], &[f64]),
        tau: &[f64],
        vdot: (&mut [f64], &mut [f64]),
        s: &mut AbaScratch<f64>,
    ) -> Result<(), DynamicsError> {
        for (len, want, what) in [
            (a.0.len(), self.nq, "q_a"),
            (b.0.len(), self.nq, "q_b"),
            (a.1.len(), self.nv, "v_a"),
            (b.1.len(), self.nv, "v_b"),
            (tau.len(), self.nv, "τ"),
            (vdot.0.len(), self.nv, "v̇_a"),
            (vdot.1.len(), self.nv, "v̇_b"),
        ] {
            check_len(len, want, what)?;
        }
        let n = self.segs.len();
        if let (Some(planar), Some(pl)) = (&self.planar, &mut s.pl)
            && planar.pin_chain
        {
            if pl.pair.len() != n {
                pl.pair.resize(n, PairScratch::default());
                pl.pair_trig.resize(6 * n, 0.0);
            }
            let g = [-self.gravity.dot(&planar.u), -self.gravity.dot(&planar.w)];
            if planar.aba_pair(a, b, tau, g, (&mut *vdot.0, &mut *vdot.1), &mut pl.pair, &mut pl.pair_trig) {
                return Ok(());
            }
        }
        self.aba_into(a.0, a.1, tau, None, vdot.0, s)?;
        self.aba_into(b.0, b.1, tau, None, vdot.1, s)
    }

    /// Whether [`Model::aba_pair_unchecked`] runs its two states in one pass (a planar chain
    /// of pins, f64) rather than as two calls.
    ///
    /// Book: §7.11.
    pub fn aba_pairs(&self) -> bool {
        self.planar.as_ref().is_some_and(|p| p.pin_chain)
    }
}
