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
use super::segment::Segment;

mod aba;
mod pair;
#[cfg(test)]
mod tests;

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
    /// The segment's own |c| and its subtree's mass and Σ tr J_c (the rounding scales of a
    /// tree with sliders, whose ρ depends on the configuration).
    pub own_reach: f64,
    pub sub_mass: f64,
    pub sub_trace: f64,
}

/// The planar reduction of a model: the axis â, an in-plane basis (û, ŵ) with û × ŵ = â
/// (components in every link frame and in the ground: turning about â does not change them),
/// and the segments.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Planar<T: Scalar> {
    /// No slider: every [`PlanarSeg::scale`] holds for every configuration.
    pub static_scale: bool,
    /// A chain of pins: segment i a pin whose parent is segment i − 1 (the ground for i = 0)
    /// and whose coordinate is q_i, v_i. The passes are then compiled without the branches
    /// for trees, sliders and welds (the same operations in the same order: the same bits).
    pub pin_chain: bool,
    pub axis: Vector3<T>,
    pub u: Vector3<T>,
    pub w: Vector3<T>,
    pub segs: Vec<PlanarSeg<T>>,
    /// For each user link, its segment (where its external wrench acts).
    pub link_seg: Vec<usize>,
}

impl Planar<f64> {
    /// The planar reduction of `segs`, if there is one: at least one pin; every placement
    /// without rotation (so that every link frame differs from the ground by a turn about
    /// â); every pin about ±â exactly, every slider ⊥ â exactly, welds allowed; no ball.
    /// Exact tests: an axis off by rounding keeps the spatial passes (whose answer then
    /// differs from a planar one by that rounding only).
    pub fn detect(segs: &[Segment<f64>], link_seg: &[usize]) -> Option<Self> {
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
                own_reach: s.own_reach,
                sub_mass: s.sub_mass,
                sub_trace: s.sub_trace,
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
        let pin_chain = out.iter().enumerate().all(|(i, p)| {
            p.joint == PlanarJoint::Revolute
                && p.parent == if i == 0 { n } else { i - 1 }
                && p.qi == i
                && p.vi == i
        });
        Some(Planar { static_scale, pin_chain, axis, u, w, segs: out, link_seg: link_seg.to_vec() })
    }

    /// The same reduction over another scalar (numbers converted exactly).
    pub fn cast<U: Scalar>(&self) -> Planar<U> {
        let c2 = |x: [f64; 2]| [U::lit(x[0]), U::lit(x[1])];
        Planar {
            static_scale: self.static_scale,
            pin_chain: self.pin_chain,
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
                    own_reach: s.own_reach,
                    sub_mass: s.sub_mass,
                    sub_trace: s.sub_trace,
                })
                .collect(),
            link_seg: self.link_seg.clone(),
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

/// The planar passes' work space: one [`PlanarScratch`] per segment (the ground's
/// acceleration is passed along, not stored), and the joint angles, their sines and their
/// cosines (n each), computed together before the passes.
#[derive(Debug, Clone)]
pub(crate) struct PlanarWork<T: Scalar> {
    pub seg: Vec<PlanarScratch<T>>,
    pub trig: Vec<T>,
    /// The model's gravity g for this evaluation (ground components), set by the caller.
    pub gravity: Vector3<T>,
    /// The paired passes' work space (`Model::aba_pair_unchecked`, pin chains; sized by its
    /// first call): one entry per segment, and 6n numbers for both lanes' angles, sines and
    /// cosines.
    pub pair: Vec<pair::PairScratch>,
    pub pair_trig: Vec<f64>,
}

impl<T: Scalar> PlanarWork<T> {
    /// The work space of a planar model of `n` segments.
    pub fn new(n: usize) -> Self {
        Self {
            seg: vec![PlanarScratch::default(); n],
            trig: vec![T::zero(); 3 * n],
            gravity: Vector3::zeros(),
            pair: Vec::new(),
            pair_trig: Vec::new(),
        }
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
