//! ABA's three passes on planar spatial vectors (see the module docs of `planar`).
//!
//! Book: §7.11 (chains); RBDA §2.16, Table 7.1.

use core::ops::{Add, Mul, Neg, Sub};

use vectrix_tensor::Scalar;

use super::{Planar, PlanarJoint, PlanarScratch, PlanarSeg, PlanarWork, rot, to_parent};
use crate::multibody::singular::pivot_tol;
use crate::multibody::wrench::LinkWrenches;

impl<T: Scalar> Planar<T> {
    /// ABA on planar spatial vectors (see the module docs), every quantity resolved in the
    /// ground plane's axes (û, ŵ) about the segment's origin, so that moving a quantity from a
    /// child to its parent is a shift by the offset d between their origins, X = [[1, 0],
    /// [k×d, 1]], with no rotation. The passes are those of `Model::aba_into`:
    /// pass 1 twists, bias accelerations c = 𝒱 ×m Sq̇ and bias forces 𝒱 ×f I𝒱; pass 2
    /// Iᵃ = Iᴬ − UD⁻¹Uᵀ, pᵃ = pᴬ + Iᵃc + UD⁻¹u to the parent through Xᵀ; pass 3
    /// q̈ = D⁻¹(u − Uᵀ(X𝒜_p + c)).
    ///
    /// Returns `false`, having written nothing the caller keeps, when a joint's articulated
    /// inertia D is at the rounding level (an inert coordinate): the spatial passes then decide
    /// it exactly as documented on `Model::aba`. Gravity is `work.gravity`. Inlined into its
    /// one caller, `Model::aba_into`: for one or two segments the call costs as much as a pass.
    #[inline(always)]
    pub(crate) fn aba(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        vdot: &mut [T],
        work: &mut PlanarWork<T>,
    ) -> bool {
        let pl = self;
        let n = pl.segs.len();
        // (a no-op for the work space of this model, `PlanarWork::new(n)`)
        work.trig.resize(3 * n, T::zero());
        let (s, trig) = (&mut work.seg[..], &mut work.trig[..]);
        // the ground: at rest, axes (û, ŵ), acceleration −g (its in-plane part) at the origin
        // (gravity by the fictitious acceleration of the base)
        let g = work.gravity;
        let ga = [T::zero(), -g.dot(&pl.u), -g.dot(&pl.w)];
        if pl.pin_chain && f_ext.is_none() {
            passes::<T, true>(pl, (q, v, tau), None, vdot, s, trig, ga)
        } else {
            passes::<T, false>(pl, (q, v, tau), f_ext, vdot, s, trig, ga)
        }
    }
}

/// The three passes, the ground's acceleration `ga`; `false` at an inert coordinate. `CHAIN`:
/// [`Planar::pin_chain`] (then no external wrenches and static scales).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn passes<T: Scalar, const CHAIN: bool>(
    pl: &Planar<T>,
    (q, v, tau): (&[T], &[T], &[T]),
    f_ext: Option<&LinkWrenches<T>>,
    vdot: &mut [T],
    s: &mut [PlanarScratch<T>],
    trig: &mut [T],
    ga: [T; 3],
) -> bool {
    joint_sin_cos::<T, CHAIN>(pl, q, trig);
    twists::<T, CHAIN>(pl, q, v, s, trig);
    if let Some(fe) = f_ext {
        for (l, &k) in pl.link_seg.iter().enumerate() {
            let e = &mut s[k];
            let f = rot(&e.cs, &[fe[l].force.dot(&pl.u), fe[l].force.dot(&pl.w)]);
            e.pa[0] -= fe[l].moment.dot(&pl.axis);
            e.pa[1] -= f[0];
            e.pa[2] -= f[1];
        }
    }
    if !CHAIN && !pl.static_scale {
        // a slider moves the centres: ρ from this configuration, as the spatial passes
        for (e, seg) in s.iter_mut().zip(&pl.segs) {
            e.reach = seg.own_reach;
        }
    }
    if !articulated_inertias::<T, CHAIN>(pl, tau, s) {
        return false;
    }
    accelerations::<T, CHAIN>(pl, s, vdot, ga);
    true
}

/// Pass 2 (inward). A segment's contribution to its parent waits in registers and is
/// added when the parent comes next (a chain), else stored before the next one is made;
/// either way each parent sums its own part and its children's in the same order. The
/// roots' contributions (to the ground) are dropped. `false` at an inert coordinate.
/// `CHAIN`: [`Planar::pin_chain`] (the joint kinds and parents known when compiled).
#[inline(always)]
fn articulated_inertias<T: Scalar, const CHAIN: bool>(
    pl: &Planar<T>,
    tau: &[T],
    s: &mut [PlanarScratch<T>],
) -> bool {
    let n = pl.segs.len();
    let z = T::zero();
    let tol = pivot_tol::<T>();
    let none = usize::MAX;
    let (mut pend, mut pend_ia, mut pend_pa) = (none, [z; 6], [z; 3]);
    for (i, ps) in pl.segs.iter().enumerate().rev() {
        let e = &mut s[i];
        let (mut ia_i, mut pa_i) = (e.ia, e.pa);
        // in a chain every segment but the tip has its child's part pending
        if if CHAIN { i + 1 < n } else { pend == i } {
            for (x, y) in ia_i.iter_mut().zip(pend_ia) {
                *x += y;
            }
            for (x, y) in pa_i.iter_mut().zip(pend_pa) {
                *x += y;
            }
            pend = none;
        }
        let dd = e.d;
        let ex = [-dd[1], dd[0]];
        // (Iᵃ, pᵃ) and what goes to the parent through X = [[1, 0], [ê, 1]], ê = â×d:
        // Xᵀ I X = [[A + 2ê·b + êᵀCê, (b + Cê)ᵀ], [b + Cê, C]]; it carries (a, b) =
        // (A + 2ê·b + êᵀCê, b + Cê) in its first row
        let joint = if CHAIN { PlanarJoint::Revolute } else { ps.joint };
        let step = match joint {
            PlanarJoint::Revolute => {
                let scale = if CHAIN || pl.static_scale {
                    ps.scale
                } else {
                    ps.sub_trace + 2.0 * ps.sub_mass * e.reach * e.reach
                };
                pin_inward(e, ps, ia_i, pa_i, tau, tol * scale)
            }
            PlanarJoint::Prismatic => slider_inward(e, ps, ia_i, pa_i, tau, tol * ps.scale),
            PlanarJoint::Fixed => {
                let (a, b) = to_parent(&ia_i, ex);
                Some((ia_i, pa_i, a, b))
            }
        };
        let Some((ia, pa, a, b)) = step else { return false };
        // forces n_p = n + ê·f
        let nf = pa[0] + ex[0] * pa[1] + ex[1] * pa[2];
        if !CHAIN && !pl.static_scale && ps.sub_mass > 0.0 && ps.parent < n {
            let reach = e.reach + dd[0].re().abs() + dd[1].re().abs();
            let pe = &mut s[ps.parent];
            pe.reach = pe.reach.max(reach);
        }
        if !CHAIN && pend != none {
            let pe = &mut s[pend];
            for (x, y) in pe.ia.iter_mut().zip(pend_ia) {
                *x += y;
            }
            for (x, y) in pe.pa.iter_mut().zip(pend_pa) {
                *x += y;
            }
        }
        (pend, pend_ia, pend_pa) = if CHAIN || ps.parent < n {
            (ps.parent, [a, b[0], b[1], ia[3], ia[4], ia[5]], [nf, pa[1], pa[2]])
        } else {
            (none, [z; 6], [z; 3])
        };
    }
    true
}

/// The joint angles' sines and cosines first, all at once, into `trig` = (angles, sines,
/// cosines), n each (`Scalar::fast_sin_cos_slices`: in SIMD for f64; inside pass 1 each would
/// wait on the loop's chain). `CHAIN` ([`Planar::pin_chain`]): the angles are q itself.
#[inline(always)]
fn joint_sin_cos<T: Scalar, const CHAIN: bool>(pl: &Planar<T>, q: &[T], trig: &mut [T]) {
    let n = pl.segs.len();
    let (x, rest) = trig.split_at_mut(n);
    let (sn, cn) = rest.split_at_mut(n);
    if CHAIN {
        T::fast_sin_cos_slices(&q[..n], sn, cn);
    } else {
        for (xk, ps) in x.iter_mut().zip(&pl.segs) {
            *xk = if ps.joint == PlanarJoint::Revolute { q[ps.qi] } else { T::zero() };
        }
        T::fast_sin_cos_slices(x, sn, cn);
    }
}

/// Pass 1 (outward): orientations, twists, bias accelerations and bias forces. The parent's
/// orientation and twist come from registers when it is the ground or the segment just done
/// (a chain: no round trip through memory).
/// `CHAIN`: [`Planar::pin_chain`].
#[inline(always)]
fn twists<T: Scalar, const CHAIN: bool>(
    pl: &Planar<T>,
    q: &[T],
    v: &[T],
    s: &mut [PlanarScratch<T>],
    trig: &[T],
) {
    let n = pl.segs.len();
    let (sines, cosines) = trig[n..3 * n].split_at(n);
    let z = T::zero();
    let ground = ([T::one(), z], z, [z; 2]);
    let mut last = ground;
    for (i, ((ps, &cn), &sn)) in pl.segs.iter().zip(cosines).zip(sines).enumerate() {
        let (cp, wp, vp) = if CHAIN {
            last
        } else if ps.parent == n {
            ground
        } else if ps.parent + 1 == i {
            last
        } else {
            let p = &s[ps.parent];
            (p.cs, p.w, p.v)
        };
        let joint = if CHAIN { PlanarJoint::Revolute } else { ps.joint };
        let mut r = ps.r;
        if joint == PlanarJoint::Prismatic {
            let x = q[ps.qi];
            r = [r[0] + ps.d[0] * x, r[1] + ps.d[1] * x];
        }
        let d = rot(&cp, &r);
        let mut vi = [vp[0] - wp * d[1], vp[1] + wp * d[0]];
        let e = &mut s[i];
        let (cs, wi) = match joint {
            PlanarJoint::Revolute => {
                let (sn, qd) = (sn * ps.sigma, v[if CHAIN { i } else { ps.vi }] * ps.sigma);
                // c = (ω, v) ×m (q̇ σâ, 0) = (0, −σq̇ â×v)
                e.c = [qd * vi[1], -(qd * vi[0])];
                ([cp[0] * cn - cp[1] * sn, cp[1] * cn + cp[0] * sn], wp + qd)
            }
            PlanarJoint::Prismatic => {
                let dir = rot(&cp, &ps.d);
                let sd = v[ps.vi];
                vi = [vi[0] + dir[0] * sd, vi[1] + dir[1] * sd];
                // c = (ω, v) ×m (0, ṡ d) = (0, ω ṡ â×d)
                let k = wp * sd;
                e.c = [-(k * dir[1]), k * dir[0]];
                e.dir = dir;
                (cp, wp)
            }
            PlanarJoint::Fixed => {
                e.c = [z; 2];
                (cp, wp)
            }
        };
        // inertia about the origin: [[I_o, −h_y, h_x], [−h_y, m, 0], [h_x, 0, m]]
        let h = rot(&cs, &ps.h);
        let m = ps.m;
        e.ia = [ps.i_o, -h[1], h[0], m, z, m];
        // bias force (ω, v) ×f I(ω, v) = (v × F, ω â×F), F = m v + ω â×h
        let f = [m * vi[0] - wi * h[1], m * vi[1] + wi * h[0]];
        e.pa = [vi[0] * f[1] - vi[1] * f[0], -(wi * f[1]), wi * f[0]];
        e.cs = cs;
        e.d = d;
        e.ew = [d[1] * d[1], -((d[0] + d[0]) * d[1]), d[0] * d[0]];
        e.w = wi;
        e.v = vi;
        last = (cs, wi, vi);
    }
}

/// (Iᵃ, pᵃ, a, b) of one step of pass 2 (see [`Planar::aba`]).
type Inward<T> = ([T; 6], [T; 3], T, [T; 2]);

/// Pass 2 at a pin: S = (σ, 0, 0), so U = σ(column 0), D = a0, and Iᵃ's row and column 0
/// vanish exactly; `None` when D ≤ `min_d` (an inert coordinate).
#[inline(always)]
fn pin_inward<T: Scalar>(
    e: &mut PlanarScratch<T>,
    ps: &PlanarSeg<T>,
    a: [T; 6],
    p: [T; 3],
    tau: &[T],
    min_d: f64,
) -> Option<Inward<T>> {
    if a[0].re() <= min_d {
        return None;
    }
    let s = pin_step(e.c, e.d, e.ew, a, p, tau[ps.vi] * ps.sigma);
    e.U = [T::one(), s.b[0], s.b[1]];
    (e.u, e.u0, e.ud) = (s.u, s.u0, s.ud);
    Some(s.inward)
}

/// What pass 2 at a pin gives: for pass 3 (column 0)/D's last two entries `b`, D⁻¹σu, and the
/// two terms of its angular acceleration that do not wait on the parent's (u0, ud; see
/// [`PlanarScratch`]); and (Iᵃ, pᵃ, a, b) for the parent.
pub(super) struct PinStep<L> {
    pub b: [L; 2],
    pub u: L,
    pub u0: L,
    pub ud: L,
    pub inward: ([L; 6], [L; 3], L, [L; 2]),
}

/// The arithmetic of [`pin_step`]: one number (every [`Scalar`]) or two lanes (`pair::X2`),
/// so that the single and the paired passes run the same operations in the same order.
pub(super) trait Lane:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    fn zero() -> Self;
    fn recip(self) -> Self;
}

impl<T: Scalar> Lane for T {
    #[inline(always)]
    fn zero() -> T {
        nalgebra::zero()
    }
    #[inline(always)]
    fn recip(self) -> T {
        nalgebra::ComplexField::recip(self)
    }
}

/// Pass 2 at a pin whose D = a0 is known to be above its rounding level, with bias
/// acceleration `c`, offset `dd` from the parent, (d_y², −2d_xd_y, d_x²) `ew` and στ `t`.
#[inline(always)]
pub(super) fn pin_step<L: Lane>(
    [c1, c2]: [L; 2],
    dd: [L; 2],
    ew: [L; 3],
    [a0, a1, a2, a3, a4, a5]: [L; 6],
    [p0, p1, p2]: [L; 3],
    t: L,
) -> PinStep<L> {
    let z = L::zero();
    let ex = [-dd[1], dd[0]];
    // the quantities of the products that do not need D⁻¹ first, so that the chain from one
    // pin's D to its parent's is D⁻¹, one product and two sums
    let (a11, a12, a22) = (a1 * a1, a1 * a2, a2 * a2);
    // with α = (a1, a2) and g = êᵀα: êᵀA₂₂ê, A₂₂ê, gα
    let g = ex[0] * a1 + ex[1] * a2;
    let ea = ew[0] * a3 + ew[1] * a4 + ew[2] * a5;
    let xa = [a3 * ex[0] + a4 * ex[1], a4 * ex[0] + a5 * ex[1]];
    let (gg, ga) = (g * g, [a1 * g, a2 * g]);
    let dinv = a0.recip();
    // u = τ − σp0, stored as σu = στ − p0, and U stored unsigned, so that UD⁻¹u =
    // (column 0) D⁻¹ σu
    let su = t - p0;
    let (b1, b2) = (a1 * dinv, a2 * dinv);
    // for pass 3: (column 0)/D = (1, b1, b2) and D⁻¹σu
    let u = su * dinv;
    let u0 = u - (b1 * c1 + b2 * c2);
    let ud = b1 * dd[1] - b2 * dd[0];
    // C = A₂₂ − ααᵀD⁻¹ (row and column 0 of Iᵃ vanish exactly)
    let (i3, i4, i5) = (a3 - a11 * dinv, a4 - a12 * dinv, a5 - a22 * dinv);
    // pᵃ = pᴬ + Iᵃc + UD⁻¹u; its first entry is p0 + σu = στ
    let pa = [t, p1 + i3 * c1 + i4 * c2 + b1 * su, p2 + i4 * c1 + i5 * c2 + b2 * su];
    // A = 0 and b = 0 after a pin: a = êᵀCê = êᵀA₂₂ê − g²D⁻¹, b = Cê = A₂₂ê − αgD⁻¹ (the
    // zeros are not added: x + 0 is not foldable for floats)
    let a = ea - gg * dinv;
    let b = [xa[0] - ga[0] * dinv, xa[1] - ga[1] * dinv];
    PinStep { b: [b1, b2], u, u0, ud, inward: ([z, z, z, i3, i4, i5], pa, a, b) }
}

/// Pass 2 at a slider along `dir`: U = I S, D = Sᵀ U; `None` when D ≤ `min_d`.
#[inline(always)]
fn slider_inward<T: Scalar>(
    e: &mut PlanarScratch<T>,
    ps: &PlanarSeg<T>,
    [a0, a1, a2, a3, a4, a5]: [T; 6],
    [p0, p1, p2]: [T; 3],
    tau: &[T],
    min_d: f64,
) -> Option<Inward<T>> {
    let [dx, dy] = e.dir;
    let U = [a1 * dx + a2 * dy, a3 * dx + a4 * dy, a4 * dx + a5 * dy];
    let D = dx * U[1] + dy * U[2];
    if D.re() <= min_d {
        return None;
    }
    let [c1, c2] = e.c;
    let dinv = D.recip();
    let u = tau[ps.vi] - (dx * p1 + dy * p2);
    e.U = U;
    e.dinv = dinv;
    e.u = u;
    let k = [U[0] * dinv, U[1] * dinv, U[2] * dinv];
    let ia = [
        a0 - U[0] * k[0],
        a1 - U[0] * k[1],
        a2 - U[0] * k[2],
        a3 - U[1] * k[1],
        a4 - U[1] * k[2],
        a5 - U[2] * k[2],
    ];
    let pa = [
        p0 + ia[1] * c1 + ia[2] * c2 + k[0] * u,
        p1 + ia[3] * c1 + ia[4] * c2 + k[1] * u,
        p2 + ia[4] * c1 + ia[5] * c2 + k[2] * u,
    ];
    let (a, b) = to_parent(&ia, [-e.d[1], e.d[0]]);
    Some((ia, pa, a, b))
}

/// Pass 3 (outward): accelerations and q̈, the parent's acceleration from registers as in
/// pass 1.
/// `CHAIN`: [`Planar::pin_chain`].
#[inline(always)]
fn accelerations<T: Scalar, const CHAIN: bool>(
    pl: &Planar<T>,
    s: &mut [PlanarScratch<T>],
    vdot: &mut [T],
    ga: [T; 3],
) {
    let n = pl.segs.len();
    let mut last = ga;
    for (i, ps) in pl.segs.iter().enumerate() {
        let ap = if CHAIN {
            last
        } else if ps.parent == n {
            ga
        } else if ps.parent + 1 == i {
            last
        } else {
            s[ps.parent].a
        };
        let e = &mut s[i];
        // 𝒜' = X𝒜_p + c: the angular part carries over, the linear part shifts by α â×d
        let a = [ap[0], (ap[1] + e.c[0]) - ap[0] * e.d[1], (ap[2] + e.c[1]) + ap[0] * e.d[0]];
        let joint = if CHAIN { PlanarJoint::Revolute } else { ps.joint };
        e.a = match joint {
            PlanarJoint::Revolute => {
                // σq̈ = D⁻¹(σu − (column 0)ᵀ𝒜') and 𝒜 = 𝒜' + (σq̈, 0, 0): the angular part of 𝒜
                // is D⁻¹σu − b1𝒜'₁ − b2𝒜'₂ (𝒜'₀ cancels), and σq̈ = 𝒜₀ − 𝒜'₀. With 𝒜' written
                // out: u0 + ud·𝒜_p₀ − (b1𝒜_p₁ + b2𝒜_p₂), which waits on the parent's
                // acceleration for one product and two sums, not for 𝒜'
                let al = (e.u0 + e.ud * ap[0]) - (e.U[1] * ap[1] + e.U[2] * ap[2]);
                vdot[if CHAIN { i } else { ps.vi }] = (al - a[0]) * ps.sigma;
                [al, a[1], a[2]]
            }
            PlanarJoint::Prismatic => {
                let qdd = e.dinv * (e.u - (e.U[0] * a[0] + e.U[1] * a[1] + e.U[2] * a[2]));
                vdot[ps.vi] = qdd;
                [a[0], a[1] + e.dir[0] * qdd, a[2] + e.dir[1] * qdd]
            }
            PlanarJoint::Fixed => a,
        };
        last = e.a;
    }
}
