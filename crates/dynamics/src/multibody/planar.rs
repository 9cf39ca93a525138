//! Planar trees: every pin turns about one fixed direction â of the ground and every slider
//! moves perpendicular to it. Such a mechanism moves in planes ⊥ â whatever its initial state,
//! and its joint-space dynamics involve only the in-plane parts of everything (positions,
//! centres of mass, gravity, forces), the moment component along â and, of each body's
//! rotational inertia, only âᵀĪâ. ABA then runs on planar spatial vectors, 3 numbers instead
//! of 6 (RBDA §2.16), with the same v̇ as the spatial passes to rounding: "simulate only the
//! effects a scene calls for".
//!
//! Book: §7.11 (chains), §6.3 (the moment of inertia about an axis); RBDA §2.16, Table 7.1.
#![allow(non_snake_case)]

use nalgebra::Vector3;
use vectrix_tensor::Scalar;

use super::joint::Elem;
use super::model::{Model, Segment};
use super::rnea::LinkWrenches;
use super::singular::pivot_tol;

/// The kind of one segment of a planar tree.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum PlanarJoint {
    /// A pin about σâ, σ = ±1 ([`PlanarSeg::sigma`]).
    Revolute,
    /// A slider along the in-plane direction `d` of [`PlanarSeg`].
    Prismatic,
    /// A weld.
    Fixed,
}

/// One segment of a planar tree, with every vector reduced to its in-plane components
/// (x·û, x·ŵ) in the segment's (or parent's) link frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlanarSeg<T: Scalar> {
    pub joint: PlanarJoint,
    /// The parent segment, or the number of segments for the ground (the passes keep the
    /// ground's twist and acceleration in one more entry of their work space).
    pub parent: usize,
    pub qi: usize,
    pub vi: usize,
    /// σ = ±1: a pin about σâ (exact: multiplying by it only flips signs).
    pub sigma: T,
    /// The rounding scale of the singularity test of the joint's D when it does not depend on
    /// the configuration (no slider in the tree): for a pin Σ tr J_c + 2Mρ² over its subtree
    /// with ρ bounding the distance from its origin to every centre in the subtree; for a
    /// slider its subtree's mass M.
    pub scale: f64,
    /// The placement's offset r_{joint/parent origin} (parent link frame).
    pub r: [T; 2],
    /// A slider's direction (its frame is the parent's: the placement has no rotation).
    pub d: [T; 2],
    /// Mass, first moment m c, and âᵀĪâ, the moment of inertia about the axis through the
    /// link origin along â.
    pub m: T,
    pub h: [T; 2],
    pub i_o: T,
}

/// The planar reduction of a model: the axis â, an in-plane basis (û, ŵ) with û × ŵ = â
/// (components in every link frame and in the ground: turning about â does not change them),
/// and the segments.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Planar<T: Scalar> {
    /// No slider: every [`PlanarSeg::scale`] holds for every configuration.
    pub static_scale: bool,
    pub axis: Vector3<T>,
    pub u: Vector3<T>,
    pub w: Vector3<T>,
    pub segs: Vec<PlanarSeg<T>>,
}

impl Planar<f64> {
    /// The planar reduction of `segs`, if there is one: at least one pin; every placement
    /// without rotation (so that every link frame differs from the ground by a turn about
    /// â); every pin about ±â exactly, every slider ⊥ â exactly, welds allowed; no ball.
    /// Exact tests: an axis off by rounding keeps the spatial passes (whose answer then
    /// differs from a planar one by that rounding only).
    pub fn detect(segs: &[Segment<f64>]) -> Option<Self> {
        let axis = segs.iter().find_map(|s| match s.elem {
            Elem::Revolute(a) => Some(a),
            _ => None,
        })?;
        let n = segs.len();
        let mut out = Vec::with_capacity(n);
        let (u, w) = in_plane_basis(&axis);
        let plane = |x: &Vector3<f64>| [x.dot(&u), x.dot(&w)];
        for s in segs {
            if !s.placement_is_shift {
                return None;
            }
            let (joint, d, sigma) = match s.elem {
                Elem::Revolute(a) if a == axis => (PlanarJoint::Revolute, [0.0; 2], 1.0),
                Elem::Revolute(a) if a == -axis => (PlanarJoint::Revolute, [0.0; 2], -1.0),
                Elem::Prismatic(d) if d.dot(&axis) == 0.0 => (PlanarJoint::Prismatic, plane(&d), 1.0),
                Elem::Fixed => (PlanarJoint::Fixed, [0.0; 2], 1.0),
                _ => return None,
            };
            let b = &s.inertia;
            out.push(PlanarSeg {
                joint,
                parent: s.parent.unwrap_or(n),
                qi: s.qi,
                vi: s.vi,
                sigma,
                scale: 0.0,
                r: plane(&s.placement.r),
                d,
                m: b.m,
                h: plane(&b.h),
                i_o: axis.dot(&(b.I * axis)),
            });
        }
        // ρ of every pin's subtree, tips to base (children come after their parents):
        // ρ_p ≥ |r_i| + ρ_i over the children i that carry mass, and ≥ |c| of its own body
        let static_scale = out.iter().all(|p| p.joint != PlanarJoint::Prismatic);
        let mut reach: Vec<f64> = segs.iter().map(|s| s.own_reach).collect();
        for i in (0..n).rev() {
            if let Some(p) = segs[i].parent
                && segs[i].sub_mass > 0.0
            {
                reach[p] = reach[p].max(reach[i] + segs[i].placement.r.norm());
            }
        }
        for (o, (s, rho)) in out.iter_mut().zip(segs.iter().zip(&reach)) {
            o.scale = match o.joint {
                PlanarJoint::Prismatic => s.sub_mass,
                _ => s.sub_trace + 2.0 * s.sub_mass * rho * rho,
            };
        }
        Some(Planar { static_scale, axis, u, w, segs: out })
    }

    /// The same reduction over another scalar (numbers converted exactly).
    pub fn cast<U: Scalar>(&self) -> Planar<U> {
        let c2 = |x: [f64; 2]| [U::lit(x[0]), U::lit(x[1])];
        Planar {
            static_scale: self.static_scale,
            axis: self.axis.map(U::lit),
            u: self.u.map(U::lit),
            w: self.w.map(U::lit),
            segs: self
                .segs
                .iter()
                .map(|s| PlanarSeg {
                    joint: s.joint,
                    parent: s.parent,
                    qi: s.qi,
                    vi: s.vi,
                    sigma: U::lit(s.sigma),
                    scale: s.scale,
                    r: c2(s.r),
                    d: c2(s.d),
                    m: U::lit(s.m),
                    h: c2(s.h),
                    i_o: U::lit(s.i_o),
                })
                .collect(),
        }
    }
}

/// (û, ŵ) with û × ŵ = â for a unit â: for ±x̂, ±ŷ, ±ẑ two coordinate axes (exact zeros and
/// ones, so that reducing a vector to the plane is exact); else û ⊥ â from the coordinate axis
/// least aligned with â, ŵ = â × û.
fn in_plane_basis(a: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let e = |k: usize| Vector3::ith(k % 3, 1.0);
    for k in 0..3 {
        if a[(k + 1) % 3] == 0.0 && a[(k + 2) % 3] == 0.0 {
            // ê_{k+1} × ê_{k+2} = ê_k
            return if a[k] > 0.0 { (e(k + 1), e(k + 2)) } else { (e(k + 2), e(k + 1)) };
        }
    }
    let k = a.iamin();
    let u = a.cross(&e(k)).normalize();
    (u, a.cross(&u))
}

/// Per-segment work space of the planar passes: the ground-plane components (û, ŵ) of the
/// segment's orientation (cos φ, sin φ), its twist (ω, v of the body point at the
/// origin), the bias acceleration (its turning part is zero), the offset from the parent's
/// origin, a slider's direction, the articulated inertia (6 entries of a symmetric 3×3,
/// (ω, vx, vy) ordering) and bias force, U, D⁻¹, u (for a pin U/D and D⁻¹σu, whose D⁻¹ is
/// then folded in), for a pin the two terms of its angular acceleration that do not depend on
/// the parent's, and the acceleration.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlanarScratch<T: Scalar> {
    cs: [T; 2],
    w: T,
    v: [T; 2],
    c: [T; 2],
    d: [T; 2],
    /// (d_y², −2d_x d_y, d_x²): êᵀCê = C₀₀d_y² − 2C₀₁d_xd_y + C₁₁d_x² for ê = â×d without
    /// waiting on Cê.
    ew: [T; 3],
    dir: [T; 2],
    ia: [T; 6],
    pa: [T; 3],
    U: [T; 3],
    dinv: T,
    u: T,
    /// A pin's D⁻¹σu − (U/D)ᵀc and (U/D)ᵀ(d_y, −d_x): pass 3 gives its angular acceleration
    /// as u0 + ud·α_p − (U/D)₁₂ᵀ𝒜_p, one multiply-add on the parent's from the chain.
    u0: T,
    ud: T,
    a: [T; 3],
    reach: f64,
}

impl<T: Scalar> Default for PlanarScratch<T> {
    fn default() -> Self {
        let z = T::zero();
        Self {
            cs: [z; 2],
            w: z,
            v: [z; 2],
            c: [z; 2],
            d: [z; 2],
            ew: [z; 3],
            dir: [z; 2],
            ia: [z; 6],
            pa: [z; 3],
            U: [z; 3],
            dinv: z,
            u: z,
            u0: z,
            ud: z,
            a: [z; 3],
            reach: 0.0,
        }
    }
}

/// The planar passes' work space: one [`PlanarScratch`] per segment and one for the ground,
/// and the joint angles, their sines and their cosines (n each), computed together before the
/// passes.
#[derive(Debug, Clone)]
pub(crate) struct PlanarWork<T: Scalar> {
    pub seg: Vec<PlanarScratch<T>>,
    pub trig: Vec<T>,
}

impl<T: Scalar> PlanarWork<T> {
    /// The work space of a planar model of `n` segments.
    pub fn new(n: usize) -> Self {
        Self { seg: vec![PlanarScratch::default(); n + 1], trig: vec![T::zero(); 3 * n] }
    }
}

/// R(φ) x for (cos φ, sin φ).
#[inline(always)]
fn rot<T: Scalar>(cs: &[T; 2], x: &[T; 2]) -> [T; 2] {
    [cs[0] * x[0] - cs[1] * x[1], cs[1] * x[0] + cs[0] * x[1]]
}

/// What a segment's articulated inertia I = [[A, bᵀ], [b, C]] (the 6 entries of a symmetric
/// 3×3) carries to its parent through X = [[1, 0], [ê, 1]], ê = â×d: the first row (a, b) of
/// XᵀIX = [[A + 2ê·b + êᵀCê, (b + Cê)ᵀ], [b + Cê, C]] (C is carried over as it is).
#[inline(always)]
fn to_parent<T: Scalar>(ia: &[T; 6], ex: [T; 2]) -> (T, [T; 2]) {
    let ce = [ia[3] * ex[0] + ia[4] * ex[1], ia[4] * ex[0] + ia[5] * ex[1]];
    let b = [ia[1] + ce[0], ia[2] + ce[1]];
    (ia[0] + ex[0] * (ia[1] + b[0]) + ex[1] * (ia[2] + b[1]), b)
}

impl<T: Scalar> Model<T> {
    /// ABA on planar spatial vectors (see the module docs), every quantity resolved in the
    /// ground plane's axes (û, ŵ) about the segment's origin, so that moving a quantity from a
    /// child to its parent is a shift by the offset d between their origins, X = [[1, 0],
    /// [k×d, 1]], with no rotation. The passes are those of [`Model::aba_into`]:
    /// pass 1 twists, bias accelerations c = 𝒱 ×m Sq̇ and bias forces 𝒱 ×f I𝒱; pass 2
    /// Iᵃ = Iᴬ − UD⁻¹Uᵀ, pᵃ = pᴬ + Iᵃc + UD⁻¹u to the parent through Xᵀ; pass 3
    /// q̈ = D⁻¹(u − Uᵀ(X𝒜_p + c)).
    ///
    /// Returns `false` for a model that is not planar and, having written nothing the caller
    /// keeps, when a joint's articulated inertia D is at the rounding level (an inert
    /// coordinate): the spatial passes then decide it exactly as documented on [`Model::aba`].
    pub(crate) fn planar_aba(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
        vdot: &mut [T],
        work: &mut PlanarWork<T>,
    ) -> bool {
        let Some(pl) = &self.planar else { return false };
        let n = pl.segs.len();
        // (a no-op for the work space of this model, `PlanarWork::new(n)`)
        work.trig.resize(3 * n, T::zero());
        let (s, trig) = (&mut work.seg[..], &mut work.trig[..]);
        let z = T::zero();
        // the ground, entry n: at rest, axes (û, ŵ), acceleration −g (its in-plane part) at
        // the origin (gravity by the fictitious acceleration of the base)
        s[n] = PlanarScratch::default();
        s[n].cs = [T::one(), z];
        s[n].a = [z, -self.gravity.dot(&pl.u), -self.gravity.dot(&pl.w)];
        // pass 1 (outward). The parent's orientation and twist come from registers when it is
        // the ground or the segment just done (a chain: no round trip through memory)
        let ground = ([T::one(), z], z, [z; 2]);
        let mut last = ground;
        // the joint angles' (cos, sin) first, all at once (`Scalar::fast_sin_cos_slices`: in
        // SIMD for f64; inside the loop below each would wait on the loop's chain)
        let (x, rest) = trig.split_at_mut(n);
        let (sn, cn) = rest.split_at_mut(n);
        for (xk, ps) in x.iter_mut().zip(&pl.segs) {
            *xk = if ps.joint == PlanarJoint::Revolute { q[ps.qi] } else { z };
        }
        T::fast_sin_cos_slices(x, sn, cn);
        for (e, (c, sv)) in s.iter_mut().zip(cn.iter().zip(sn.iter())) {
            e.cs = [*c, *sv];
        }
        for (i, ps) in pl.segs.iter().enumerate() {
            let (cp, wp, vp) = if ps.parent == n {
                ground
            } else if ps.parent + 1 == i {
                last
            } else {
                let p = &s[ps.parent];
                (p.cs, p.w, p.v)
            };
            let mut r = ps.r;
            if ps.joint == PlanarJoint::Prismatic {
                let x = q[ps.qi];
                r = [r[0] + ps.d[0] * x, r[1] + ps.d[1] * x];
            }
            let d = rot(&cp, &r);
            let mut vi = [vp[0] - wp * d[1], vp[1] + wp * d[0]];
            let e = &mut s[i];
            let (cs, wi) = match ps.joint {
                PlanarJoint::Revolute => {
                    let [cn, sn] = e.cs;
                    let (sn, qd) = (sn * ps.sigma, v[ps.vi] * ps.sigma);
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
        if let Some(fe) = f_ext {
            for (l, &k) in self.link_seg.iter().enumerate() {
                let e = &mut s[k];
                let f = rot(&e.cs, &[fe[l].force.dot(&pl.u), fe[l].force.dot(&pl.w)]);
                e.pa[0] -= fe[l].moment.dot(&pl.axis);
                e.pa[1] -= f[0];
                e.pa[2] -= f[1];
            }
        }
        if !pl.static_scale {
            // a slider moves the centres: ρ from this configuration, as the spatial passes
            for (e, seg) in s.iter_mut().zip(&self.segs) {
                e.reach = seg.own_reach;
            }
        }
        // pass 2 (inward). A segment's contribution to its parent waits in registers and is
        // added when the parent comes next (a chain), else stored before the next one is made;
        // either way each parent sums its own part and its children's in the same order. The
        // roots' contributions (to the ground) are dropped.
        let tol = pivot_tol::<T>();
        let none = usize::MAX;
        let (mut pend, mut pend_ia, mut pend_pa) = (none, [z; 6], [z; 3]);
        for (i, ps) in pl.segs.iter().enumerate().rev() {
            let e = &mut s[i];
            let (mut ia_i, mut pa_i) = (e.ia, e.pa);
            if pend == i {
                for (x, y) in ia_i.iter_mut().zip(pend_ia) {
                    *x += y;
                }
                for (x, y) in pa_i.iter_mut().zip(pend_pa) {
                    *x += y;
                }
                pend = none;
            }
            let [a0, a1, a2, a3, a4, a5] = ia_i;
            let [p0, p1, p2] = pa_i;
            let [c1, c2] = e.c;
            let dd = e.d;
            let ex = [-dd[1], dd[0]];
            // (Iᵃ, pᵃ) and what goes to the parent through X = [[1, 0], [ê, 1]], ê = â×d:
            // Xᵀ I X = [[A + 2ê·b + êᵀCê, (b + Cê)ᵀ], [b + Cê, C]]; it carries (a, b) =
            // (A + 2ê·b + êᵀCê, b + Cê) in its first row
            let (ia, pa, a, b) = match ps.joint {
                PlanarJoint::Revolute => {
                    // S = (σ, 0, 0): U = σ(column 0), D = a0, and Iᵃ's row and column 0
                    // vanish exactly
                    let scale = if pl.static_scale {
                        ps.scale
                    } else {
                        let seg = &self.segs[i];
                        seg.sub_trace + 2.0 * seg.sub_mass * e.reach * e.reach
                    };
                    if a0.re() <= tol * scale {
                        return false;
                    }
                    // the quantities of the products that do not need D⁻¹ first, so that the
                    // chain from one pin's D to its parent's is D⁻¹, one product and two sums
                    let (a11, a12, a22) = (a1 * a1, a1 * a2, a2 * a2);
                    // with α = (a1, a2) and g = êᵀα: êᵀA₂₂ê, A₂₂ê, gα
                    let g = ex[0] * a1 + ex[1] * a2;
                    let ea = e.ew[0] * a3 + e.ew[1] * a4 + e.ew[2] * a5;
                    let xa = [a3 * ex[0] + a4 * ex[1], a4 * ex[0] + a5 * ex[1]];
                    let (gg, ga) = (g * g, [a1 * g, a2 * g]);
                    let dinv = a0.recip();
                    // u = τ − σp0, stored as σu = στ − p0, and U stored unsigned, so that
                    // UD⁻¹u = (column 0) D⁻¹ σu
                    let t = tau[ps.vi] * ps.sigma;
                    let su = t - p0;
                    let (b1, b2) = (a1 * dinv, a2 * dinv);
                    // for pass 3: (column 0)/D = (1, b1, b2) and D⁻¹σu
                    e.U = [T::one(), b1, b2];
                    e.u = su * dinv;
                    e.u0 = e.u - (b1 * c1 + b2 * c2);
                    e.ud = b1 * dd[1] - b2 * dd[0];
                    // C = A₂₂ − ααᵀD⁻¹ (row and column 0 of Iᵃ vanish exactly)
                    let (i3, i4, i5) = (a3 - a11 * dinv, a4 - a12 * dinv, a5 - a22 * dinv);
                    // pᵃ = pᴬ + Iᵃc + UD⁻¹u; its first entry is p0 + σu = στ
                    let pa = [t, p1 + i3 * c1 + i4 * c2 + b1 * su, p2 + i4 * c1 + i5 * c2 + b2 * su];
                    // A = 0 and b = 0 after a pin: a = êᵀCê = êᵀA₂₂ê − g²D⁻¹, b = Cê =
                    // A₂₂ê − αgD⁻¹ (the zeros are not added: x + 0 is not foldable for floats)
                    let a = ea - gg * dinv;
                    let b = [xa[0] - ga[0] * dinv, xa[1] - ga[1] * dinv];
                    ([z, z, z, i3, i4, i5], pa, a, b)
                }
                PlanarJoint::Prismatic => {
                    let [dx, dy] = e.dir;
                    let U = [a1 * dx + a2 * dy, a3 * dx + a4 * dy, a4 * dx + a5 * dy];
                    let D = dx * U[1] + dy * U[2];
                    if D.re() <= tol * ps.scale {
                        return false;
                    }
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
                    let (a, b) = to_parent(&ia, ex);
                    (ia, pa, a, b)
                }
                PlanarJoint::Fixed => {
                    let (a, b) = to_parent(&ia_i, ex);
                    (ia_i, pa_i, a, b)
                }
            };
            // forces n_p = n + ê·f
            let nf = pa[0] + ex[0] * pa[1] + ex[1] * pa[2];
            if !pl.static_scale && self.segs[i].sub_mass > 0.0 && ps.parent < n {
                let reach = e.reach + dd[0].re().abs() + dd[1].re().abs();
                let pe = &mut s[ps.parent];
                pe.reach = pe.reach.max(reach);
            }
            if pend != none {
                let pe = &mut s[pend];
                for (x, y) in pe.ia.iter_mut().zip(pend_ia) {
                    *x += y;
                }
                for (x, y) in pe.pa.iter_mut().zip(pend_pa) {
                    *x += y;
                }
            }
            (pend, pend_ia, pend_pa) = if ps.parent < n {
                (ps.parent, [a, b[0], b[1], ia[3], ia[4], ia[5]], [nf, pa[1], pa[2]])
            } else {
                (none, [z; 6], [z; 3])
            };
        }
        // pass 3 (outward), the parent's acceleration from registers as in pass 1
        let ga = s[n].a;
        let mut last = ga;
        for (i, ps) in pl.segs.iter().enumerate() {
            let ap = if ps.parent == n {
                ga
            } else if ps.parent + 1 == i {
                last
            } else {
                s[ps.parent].a
            };
            let e = &mut s[i];
            // 𝒜' = X𝒜_p + c: the angular part carries over, the linear part shifts by α â×d
            let a = [ap[0], (ap[1] + e.c[0]) - ap[0] * e.d[1], (ap[2] + e.c[1]) + ap[0] * e.d[0]];
            e.a = match ps.joint {
                PlanarJoint::Revolute => {
                    // σq̈ = D⁻¹(σu − (column 0)ᵀ𝒜') and 𝒜 = 𝒜' + (σq̈, 0, 0): the angular
                    // part of 𝒜 is D⁻¹σu − b1𝒜'₁ − b2𝒜'₂ (𝒜'₀ cancels), and σq̈ = 𝒜₀ − 𝒜'₀.
                    // With 𝒜' written out: u0 + ud·𝒜_p₀ − (b1𝒜_p₁ + b2𝒜_p₂), which waits on
                    // the parent's acceleration for one product and two sums, not for 𝒜'
                    let al = (e.u0 + e.ud * ap[0]) - (e.U[1] * ap[1] + e.U[2] * ap[2]);
                    vdot[ps.vi] = (al - a[0]) * ps.sigma;
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
        true
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Rotation3, Vector3};
    use num_dual::Dual64;

    use super::super::joint::{Joint, Link};
    use super::super::model::Model;
    use super::super::rnea::JointWrench;

    fn inertia(a: f64, b: f64, c: f64, p: f64) -> Matrix3<f64> {
        Matrix3::new(a, p, -0.5 * p, p, b, 0.3 * p, -0.5 * p, 0.3 * p, c)
    }

    /// A planar tree about `axis`: a branch, pins about +â and −â, a slider ⊥ â, a weld,
    /// offsets and centres off the plane, products of inertia coupling â to the plane.
    fn tree(axis: Vector3<f64>, across: Vector3<f64>) -> Vec<Link> {
        let off = |x: f64, y: f64, z: f64| Vector3::new(x, y, z);
        vec![
            Link::new(
                None,
                Joint::Pin { axis },
                off(0.1, -0.2, 0.3),
                1.5,
                off(0.4, 0.1, -0.2),
                inertia(0.3, 0.2, 0.25, 0.02),
            ),
            Link::new(
                Some(0),
                Joint::Pin { axis: -axis },
                off(0.6, 0.2, -0.1),
                0.8,
                off(0.3, -0.3, 0.1),
                inertia(0.1, 0.15, 0.12, -0.01),
            ),
            Link::new(
                Some(1),
                Joint::Sleeve { axis: across },
                off(0.2, 0.0, 0.4),
                0.5,
                off(0.05, 0.1, 0.2),
                inertia(0.05, 0.04, 0.06, 0.005),
            ),
            Link::new(
                Some(0),
                Joint::Pin { axis },
                off(-0.3, 0.5, 0.2),
                1.1,
                off(-0.2, 0.2, 0.3),
                inertia(0.2, 0.3, 0.22, 0.03),
            ),
            Link::new(
                Some(3),
                Joint::Weld,
                off(0.0, 0.1, -0.5),
                0.7,
                off(0.1, 0.0, -0.1),
                inertia(0.04, 0.05, 0.03, 0.0),
            ),
            Link::new(
                Some(4),
                Joint::Pin { axis },
                off(0.25, -0.1, 0.15),
                0.6,
                off(0.2, 0.05, 0.0),
                inertia(0.06, 0.05, 0.07, 0.01),
            ),
        ]
    }

    fn state() -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<JointWrench>) {
        let q = vec![0.7, -1.9, 0.35, 2.6, -0.4];
        let v = vec![1.3, -2.2, 0.8, 0.5, 3.1];
        let tau = vec![0.4, -1.1, 2.0, 0.3, -0.6];
        let w = (0..6)
            .map(|k| {
                let k = k as f64;
                JointWrench {
                    force: Vector3::new(0.3 - 0.1 * k, 0.2 * k, -0.5 + 0.05 * k),
                    moment: Vector3::new(0.1 * k, -0.2, 0.3 - 0.07 * k),
                }
            })
            .collect();
        (q, v, tau, w)
    }

    fn close(a: &[f64], b: &[f64], tol: f64) {
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= tol * (1.0 + y.abs()), "{a:?}\nvs\n{b:?}");
        }
    }

    /// The planar passes give the spatial passes' v̇ on the same tree (to rounding) for pins
    /// about ±ŷ, a slider along x̂, a weld, a branch, out-of-plane offsets, gravity and
    /// external wrenches with out-of-plane parts; and RNEA at that v̇ gives back τ.
    #[test]
    fn planar_passes_match_the_spatial_passes_and_rnea() {
        for (axis, across) in [
            (Vector3::y(), Vector3::x()),
            (-Vector3::z(), Vector3::new(0.6, 0.8, 0.0)),
            // a general axis: the slider direction ⊥ it exactly in floating point
            (Vector3::new(1.0, 2.0, 2.0) / 3.0, Vector3::new(2.0, -1.0, 0.0) / 5f64.sqrt()),
        ] {
            let links = tree(axis, across);
            let mut planar = Model::new(&links).expect("valid");
            let want_axis = Model::new(&links[..1]).expect("valid").planar_axis();
            assert_eq!(planar.planar_axis(), want_axis, "axis {axis}");
            assert!(planar.planar_axis().is_some(), "axis {axis}");
            planar.gravity = Vector3::new(0.3, -9.81, 1.2);
            let mut spatial = planar.clone();
            spatial.disable_planar_reduction();
            assert!(spatial.planar_axis().is_none());
            let (q, v, tau, w) = state();
            let fast = planar.aba(&q, &v, &tau, Some(&w)).expect("definite");
            let slow = spatial.aba(&q, &v, &tau, Some(&w)).expect("definite");
            close(&fast, &slow, 1e-13);
            // the planar passes did the work (no fallback)
            let (mut out, mut s) = (vec![0.0; 5], planar.aba_scratch());
            assert!(planar.planar_aba(&q, &v, &tau, Some(&w), &mut out, s.pl.as_mut().unwrap()));
            assert_eq!(out, fast);
            let id = planar.rnea(&q, &v, &fast, Some(&w)).expect("valid");
            close(&id.tau, &tau, 1e-12);
            // and without external wrenches
            let fast = planar.aba(&q, &v, &tau, None).expect("definite");
            let slow = spatial.aba(&q, &v, &tau, None).expect("definite");
            close(&fast, &slow, 1e-13);
        }
    }

    /// Exact derivatives go through the planar passes too: a dual-number ABA agrees with the
    /// spatial passes' dual-number ABA in value and in the derivative along q.
    #[test]
    fn planar_passes_carry_dual_numbers() {
        let mut m = Model::new(&tree(Vector3::y(), Vector3::x())).expect("valid");
        m.gravity = Vector3::new(0.0, 0.0, -9.81);
        let mut s = m.clone();
        s.disable_planar_reduction();
        let (q, v, tau, _) = state();
        let seed = |m: &Model| {
            let d = m.cast::<Dual64>();
            assert_eq!(d.planar_axis().is_some(), m.planar_axis().is_some());
            let qd: Vec<Dual64> =
                q.iter().enumerate().map(|(k, &x)| Dual64::new(x, 0.3 * k as f64 - 0.5)).collect();
            let vd: Vec<Dual64> = v.iter().map(|&x| Dual64::from(x)).collect();
            let td: Vec<Dual64> = tau.iter().map(|&x| Dual64::from(x)).collect();
            d.aba(&qd, &vd, &td, None).expect("definite")
        };
        let (a, b) = (seed(&m), seed(&s));
        close(
            &a.iter().map(|x| x.re).collect::<Vec<_>>(),
            &b.iter().map(|x| x.re).collect::<Vec<_>>(),
            1e-13,
        );
        // the f64 passes take the joint angles' sines and cosines all at once (SIMD), the dual
        // ones one by one from libm: the same passes, each sine within an ulp of the other
        close(
            &a.iter().map(|x| x.re).collect::<Vec<_>>(),
            &m.aba(&q, &v, &tau, None).expect("definite"),
            1e-14,
        );
        close(
            &a.iter().map(|x| x.eps).collect::<Vec<_>>(),
            &b.iter().map(|x| x.eps).collect::<Vec<_>>(),
            1e-12,
        );
    }

    /// What is not planar keeps the spatial passes: pins about two axes, a placement that
    /// rotates the joint frame (even about â), a ball, a slider along â, a free body.
    #[test]
    fn spatial_trees_are_not_reduced() {
        let j = Matrix3::from_diagonal(&Vector3::new(0.1, 0.2, 0.3));
        let pin =
            |parent, axis| Link::new(parent, Joint::Pin { axis }, Vector3::x(), 1.0, Vector3::x() * 0.5, j);
        let planar = Model::new(&[pin(None, Vector3::y()), pin(Some(0), Vector3::y())]).expect("valid");
        assert_eq!(planar.planar_axis(), Some(Vector3::y()));
        assert!(Model::revolute_chain(4, 1.0, 0.5).expect("valid").planar_axis().is_none());
        let mut turned = pin(Some(0), Vector3::y());
        turned.orientation = *Rotation3::from_axis_angle(&Vector3::y_axis(), 0.3).matrix();
        let cases = [
            vec![pin(None, Vector3::y()), turned],
            vec![
                pin(None, Vector3::y()),
                Link::new(Some(0), Joint::Ball, Vector3::x(), 1.0, Vector3::zeros(), j),
            ],
            vec![
                pin(None, Vector3::y()),
                Link::new(
                    Some(0),
                    Joint::Sleeve { axis: Vector3::y() },
                    Vector3::x(),
                    1.0,
                    Vector3::zeros(),
                    j,
                ),
            ],
            vec![Link::new(None, Joint::Free, Vector3::zeros(), 1.0, Vector3::zeros(), j)],
        ];
        for links in cases {
            assert!(Model::new(&links).expect("valid").planar_axis().is_none(), "{links:?}");
        }
    }

    /// An inert pin (a point mass on its axis, carrying a massless link) sends the planar
    /// passes back to the spatial ones, which decide it exactly: the same v̇ as with the
    /// reduction off, and the same error for a torque along the inert coordinate.
    #[test]
    fn inert_pin_falls_back_to_the_spatial_passes() {
        let z = Matrix3::zeros();
        let links = [
            Link::new(None, Joint::Pin { axis: Vector3::y() }, Vector3::zeros(), 1.0, Vector3::x(), z),
            Link::new(Some(0), Joint::Pin { axis: Vector3::y() }, Vector3::x(), 2.0, Vector3::zeros(), z),
        ];
        let mut m = Model::new(&links).expect("valid");
        m.gravity = Vector3::new(0.0, 0.0, -9.81);
        assert!(m.planar_axis().is_some());
        let mut s = m.clone();
        s.disable_planar_reduction();
        let (q, v) = ([0.4, -0.7], [0.3, 1.2]);
        let a = m.aba(&q, &v, &[0.0, 0.0], None).expect("inert pin, no torque");
        let b = s.aba(&q, &v, &[0.0, 0.0], None).expect("inert pin, no torque");
        assert_eq!(a, b);
        assert_eq!(a[1], 0.0);
        let e1 = m.aba(&q, &v, &[0.0, 1.0], None).expect_err("torque on an inert pin");
        let e2 = s.aba(&q, &v, &[0.0, 1.0], None).expect_err("torque on an inert pin");
        assert_eq!(e1.to_string(), e2.to_string());
    }
}
