//! Kinematic trees of rigid bodies connected by the book's joints (book §1.5, Table 1.3,
//! §7.11), in reduced coordinates, generic over the scalar (f64 by default; dual numbers give
//! exact derivatives of everything computed from a model).
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Vector3};
use vectrix_frames::Frame;
use vectrix_statics::{INERTIA_REL_TOL, check_inertia};
use vectrix_tensor::Scalar;

use super::joint::{Elem, Joint, Link, Pose, coordinate_axis, elems};
use super::planar::Planar;
use super::spatial::{BodyInertia, Xform};
use crate::DynamicsError;
use crate::error::check_finite;

/// One elementary segment (a link, or a massless intermediate of a compound joint).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Segment<T: Scalar> {
    pub parent: Option<usize>,
    pub placement: Xform<T>,
    pub elem: Elem<T>,
    pub qi: usize,
    pub vi: usize,
    pub inertia: BodyInertia<T>,
    /// The same body as mass m (in `inertia`), centre c and J_c, link components.
    pub com: Vector3<T>,
    pub j_c: Matrix3<T>,
    /// Zero mass and zero inertia (intermediate segments of compound joints, massless links).
    pub massless: bool,
    /// Scales for ABA's singularity tests (real numbers, configuration-independent): the
    /// total mass of the subtree, Σ tr J_c over its bodies, and |c| of the own body (0 when
    /// massless).
    pub sub_mass: f64,
    pub sub_trace: f64,
    pub own_reach: f64,
    /// The placement has no rotation (𝓞_{J/P} = 1 exactly): composing with it is a shift.
    pub placement_is_shift: bool,
    /// A pin or slider along a coordinate axis: (axis index, negative direction).
    pub coord_axis: Option<(usize, bool)>,
    /// The parent's orientation is the ground's exactly, whatever q (every segment from the
    /// ground to the parent is a slider or a weld behind a placement without rotation: the
    /// sliders of a free joint): composing with the parent is then a shift.
    pub parent_upright: bool,
}

/// A validated kinematic tree in reduced coordinates, ready for RNEA, ABA and CRBA, generic
/// over the scalar: `Model` is `Model<f64>`; [`Model::cast`] gives the same tree over dual
/// numbers (`Model<Dual64>`, `Model<HyperDual64>`, `Model<DualSVec64<N>>`), whose
/// algorithms then return exact derivatives of their results with respect to whatever the
/// caller seeded (states, or the model's own numbers).
///
/// Book: §7.11; DESIGN §1.4 (generic scalar).
#[derive(Debug, Clone, PartialEq)]
pub struct Model<T: Scalar = f64> {
    pub(crate) segs: Vec<Segment<T>>,
    /// For each user link, the index of its (last) segment.
    pub(crate) link_seg: Vec<usize>,
    pub(crate) nq: usize,
    pub(crate) nv: usize,
    /// Gravitational acceleration g resolved in the ground frame.
    pub gravity: Vector3<T>,
    pub(crate) q_neutral: Vec<T>,
    /// For each velocity coordinate, the nearest coordinate above it in the tree (the previous
    /// column of the same joint, else the last column of the nearest ancestor that has one).
    pub(crate) parent_col: Vec<Option<usize>>,
    /// For each velocity coordinate, its segment.
    pub(crate) col_seg: Vec<usize>,
    /// First segments of the free joints at the root whose link has no children (a floating
    /// body on its own): ABA solves these in closed form ([`Model::aba_into`]).
    pub(crate) free_leaves: Vec<usize>,
    /// For each entry of `free_leaves`, its user link (whose external wrench it takes).
    pub(crate) free_links: Vec<usize>,
    /// For each entry of `free_leaves`, J_c⁻¹ of its body (from the Cholesky factor found
    /// definite when the model was built): Euler's equations solved by one product.
    pub(crate) free_jc_inv: Vec<Matrix3<T>>,
    /// For each segment, whether it belongs to a free leaf (the three passes skip it).
    pub(crate) free_seg: Vec<bool>,
    /// The planar reduction, when every pin turns about one axis of the ground and every
    /// slider moves across it: ABA then runs on 3-vectors ([`Model::aba_into`]).
    pub(crate) planar: Option<Planar<T>>,
}

/// The first segment of every free joint at the root whose link is a leaf: segments i..i+4
/// are the three sliders along x̂, ŷ, ẑ of the joint frame (massless, each placed on the
/// previous without offset) and the ball carrying the body, and no segment hangs from the
/// ball. Such a body couples to no other segment in the tree algorithms.
fn free_leaf_roots(segs: &[Segment<f64>]) -> Vec<usize> {
    let mut has_child = vec![false; segs.len()];
    for s in segs {
        if let Some(p) = s.parent {
            has_child[p] = true;
        }
    }
    let axes = [Vector3::x(), Vector3::y(), Vector3::z()];
    (0..segs.len().saturating_sub(3))
        .filter(|&i| {
            segs[i].parent.is_none()
                && (0..3).all(|k| {
                    let s = &segs[i + k];
                    s.elem == Elem::Prismatic(axes[k])
                        && s.massless
                        && (k == 0 || s.parent == Some(i + k - 1))
                })
                && (1..4).all(|k| segs[i + k].placement == Xform::identity())
                && segs[i + 3].elem == Elem::Spherical
                && segs[i + 3].parent == Some(i + 2)
                && !has_child[i + 3]
                && definite_body(&segs[i + 3])
        })
        .collect()
}

/// m > 0 and J_c positive definite with every Cholesky pivot above ABA's rounding level
/// (`pivot_tol` × tr J_c): the closed form of a free body divides by both. A particle (J_c = 0)
/// or a body with an inert axis is left to ABA's rank-revealing path.
fn definite_body(s: &Segment<f64>) -> bool {
    let scale = s.j_c.trace();
    s.inertia.m > 0.0
        && scale > 0.0
        && s.j_c.cholesky().is_some_and(|c| {
            let l = c.l_dirty();
            (0..3).all(|k| l[(k, k)] * l[(k, k)] > super::singular::pivot_tol::<f64>() * scale)
        })
}

/// Parents before children; errors for missing parents and cycles.
fn topological_order(links: &[Link]) -> Result<Vec<usize>, DynamicsError> {
    let n = links.len();
    for (i, l) in links.iter().enumerate() {
        if let Some(p) = l.parent
            && p >= n
        {
            return Err(DynamicsError::Disconnected { link: i, parent: p, links: n });
        }
    }
    // depth by walking up; a walk longer than n links means a cycle
    let mut depth = vec![0usize; n];
    for (i, d) in depth.iter_mut().enumerate() {
        let (mut j, mut k) = (i, 0usize);
        while let Some(p) = links[j].parent {
            k += 1;
            if k > n {
                return Err(DynamicsError::Cyclic { link: i });
            }
            j = p;
        }
        *d = k;
    }
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&i| (depth[i], i));
    Ok(order)
}

/// Longest chain [`Model::revolute_chain`] builds (its benchmark chains have tens of links; a
/// million keeps a hostile `n` from allocating without bound).
pub const MAX_CHAIN_LINKS: usize = 1_000_000;

impl Model<f64> {
    /// Validates the links and builds the tree. Gravity defaults to zero; set
    /// [`Model::gravity`] (components in the ground frame).
    ///
    /// Book: §7.11; §1.5 (joints); Fact 6.2.7 (valid inertia).
    ///
    /// # Errors
    /// [`DynamicsError::Disconnected`] (a parent index that does not exist),
    /// [`DynamicsError::Cyclic`], [`DynamicsError::ZeroAxis`], [`DynamicsError::JointGeometry`]
    /// (slot axis not ⊥ direction), [`DynamicsError::OutOfRange`] (mass < 0),
    /// [`DynamicsError::InvalidInertia`] (not symmetric, not PSD, rank 1, triangle inequality),
    /// [`DynamicsError::NonFinite`].
    pub fn new(links: &[Link]) -> Result<Self, DynamicsError> {
        let order = topological_order(links)?;
        // q/v offsets in the user's link order
        let mut q_off = vec![0usize; links.len()];
        let mut v_off = vec![0usize; links.len()];
        let mut expanded = Vec::with_capacity(links.len());
        let (mut nq, mut nv) = (0, 0);
        for (i, l) in links.iter().enumerate() {
            check_finite(l.offset.as_slice(), "link offset")?;
            check_finite(l.orientation.as_slice(), "link orientation")?;
            check_finite(l.com.as_slice(), "centre of mass")?;
            if !(l.mass.is_finite() && l.mass >= 0.0) {
                return Err(DynamicsError::OutOfRange {
                    what: "link mass",
                    value: l.mass,
                    valid: "finite ≥ 0",
                });
            }
            check_inertia(&Frame::new().dyadic(&l.inertia), INERTIA_REL_TOL)
                .map_err(|source| DynamicsError::InvalidInertia { what: format!("link {i}"), source })?;
            vectrix_rotation::check_rotation_matrix(&l.orientation, 1e-9)
                .map_err(|e| DynamicsError::JointGeometry { link: i, detail: e.to_string() })?;
            let e = elems(&l.joint, i)?;
            q_off[i] = nq;
            v_off[i] = nv;
            nq += e.iter().map(Elem::nq).sum::<usize>();
            nv += e.iter().map(Elem::nv).sum::<usize>();
            expanded.push(e);
        }
        let mut segs: Vec<Segment<f64>> = Vec::new();
        let mut link_seg = vec![0usize; links.len()];
        let mut q_neutral = vec![0.0; nq];
        for &i in &order {
            let l = &links[i];
            let mut parent = l.parent.map(|p| link_seg[p]);
            let mut placement = Xform { E: l.orientation, r: l.offset };
            let (mut qi, mut vi) = (q_off[i], v_off[i]);
            let count = expanded[i].len();
            for (k, elem) in expanded[i].iter().enumerate() {
                let last = k + 1 == count;
                let inertia = if last {
                    BodyInertia::from_centre(l.mass, &l.com, &l.inertia)
                } else {
                    BodyInertia::zero()
                };
                if *elem == Elem::Spherical {
                    q_neutral[qi] = 1.0;
                }
                let massless = inertia == BodyInertia::zero();
                let (com, j_c) = if last { (l.com, l.inertia) } else { (Vector3::zeros(), Matrix3::zeros()) };
                let (sub_mass, sub_trace, own_reach) = if last {
                    (l.mass, l.inertia.trace(), if l.mass > 0.0 { l.com.norm() } else { 0.0 })
                } else {
                    (0.0, 0.0, 0.0)
                };
                segs.push(Segment {
                    parent,
                    placement,
                    elem: *elem,
                    qi,
                    vi,
                    inertia,
                    com,
                    j_c,
                    massless,
                    sub_mass,
                    sub_trace,
                    own_reach,
                    placement_is_shift: placement.E == Matrix3::identity(),
                    coord_axis: coordinate_axis(elem),
                    parent_upright: false,
                });
                parent = Some(segs.len() - 1);
                placement = Xform::identity();
                qi += elem.nq();
                vi += elem.nv();
            }
            link_seg[i] = segs.len() - 1;
        }
        // parents first: a segment keeps the ground's orientation when its parent does (or it
        // is a root) and it neither turns nor sits behind a turned placement
        let mut upright = vec![false; segs.len()];
        for i in 0..segs.len() {
            let parent_upright = segs[i].parent.is_none_or(|p| upright[p]);
            if let Some(p) = segs[i].parent {
                segs[i].parent_upright = upright[p];
            }
            upright[i] = parent_upright
                && segs[i].placement_is_shift
                && matches!(segs[i].elem, Elem::Prismatic(_) | Elem::Fixed);
        }
        // subtree sums, tips to base (children come after their parents)
        for i in (0..segs.len()).rev() {
            if let Some(p) = segs[i].parent {
                let (m, t) = (segs[i].sub_mass, segs[i].sub_trace);
                segs[p].sub_mass += m;
                segs[p].sub_trace += t;
            }
        }
        // column tree: the nearest coordinate above each coordinate
        let mut parent_col = vec![None; nv];
        let mut col_seg = vec![0usize; nv];
        let mut last_col: Vec<Option<usize>> = vec![None; segs.len()];
        for (i, sg) in segs.iter().enumerate() {
            let mut above = sg.parent.and_then(|p| last_col[p]);
            for k in 0..sg.elem.nv() {
                parent_col[sg.vi + k] = above;
                col_seg[sg.vi + k] = i;
                above = Some(sg.vi + k);
            }
            last_col[i] = above;
        }
        let free_leaves = free_leaf_roots(&segs);
        let free_links = free_leaves
            .iter()
            .map(|&f| link_seg.iter().position(|&k| k == f + 3).expect("the ball segment ends its link"))
            .collect();
        let free_jc_inv = free_leaves
            .iter()
            .map(|&f| segs[f + 3].j_c.cholesky().expect("definite: checked by free_leaf_roots").inverse())
            .collect();
        let mut free_seg = vec![false; segs.len()];
        for &f in &free_leaves {
            free_seg[f..f + 4].fill(true);
        }
        Ok(Self {
            link_seg,
            nq,
            nv,
            gravity: Vector3::zeros(),
            q_neutral,
            parent_col,
            col_seg,
            planar: Planar::detect(&segs),
            free_leaves,
            free_links,
            free_jc_inv,
            free_seg,
            segs,
        })
    }

    /// A chain of n pin joints about ẑ, each link a thin-ish rod of mass m and length l along
    /// x̂ (centre at l/2, J_c = diag(m l²/1200, m l²/12, m l²/12)): the benchmark chain.
    ///
    /// Book: §7.11 (chains).
    ///
    /// # Errors
    /// As [`Model::new`] (n = 0 gives an empty model, which is valid);
    /// [`DynamicsError::OutOfRange`] for n > [`MAX_CHAIN_LINKS`] (refused before
    /// allocating, docs/robustness.md §4).
    pub fn revolute_chain(n: usize, m: f64, l: f64) -> Result<Self, DynamicsError> {
        if n > MAX_CHAIN_LINKS {
            return Err(DynamicsError::OutOfRange {
                what: "number of chain links",
                value: n as f64,
                valid: "0 ≤ n ≤ 1 000 000",
            });
        }
        let j = Matrix3::from_diagonal(&Vector3::new(m * l * l / 1200.0, m * l * l / 12.0, m * l * l / 12.0));
        let links: Vec<Link> = (0..n)
            .map(|i| {
                let offset = if i == 0 { Vector3::zeros() } else { Vector3::new(l, 0.0, 0.0) };
                // alternate ẑ and ŷ axes so that the chain is spatial
                let axis = if i % 2 == 0 { Vector3::z() } else { Vector3::y() };
                Link::new(
                    i.checked_sub(1),
                    Joint::Pin { axis },
                    offset,
                    m,
                    Vector3::new(l / 2.0, 0.0, 0.0),
                    j,
                )
            })
            .collect();
        Self::new(&links)
    }

    /// The same tree over another scalar: every number (axes, placements, masses, inertias,
    /// gravity) converted exactly from f64 (a dual number's derivative parts are zero).
    /// `model.cast::<Dual64>()` is how dual numbers enter the tree algorithms; seed the
    /// state (or the model's public `gravity`) to differentiate.
    ///
    /// Book: DESIGN §1.4; §7.11.
    ///
    /// # Examples
    /// Time derivatives along the motion, exactly: seed the state (q ⊕ ε v, v + ε v̇) and read
    /// the ε-parts. Here the angular acceleration of the first link of a chain is v̇₀ ẑ.
    /// ```
    /// use num_dual::Dual64;
    /// use vectrix_dynamics::multibody::Model;
    ///
    /// let model = Model::revolute_chain(3, 1.0, 0.5).unwrap();
    /// let (q, v) = (vec![0.1, 0.2, 0.3], vec![1.0, -0.5, 0.2]);
    /// let vdot = model.aba(&q, &v, &[0.0; 3], None).unwrap();
    /// let d = model.cast::<Dual64>();
    /// let q0: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
    /// let step: Vec<Dual64> = v.iter().map(|&x| Dual64::new(0.0, x)).collect();
    /// let qe = d.integrate(&q0, &step, Dual64::from(1.0)).unwrap();
    /// let ve: Vec<Dual64> = v.iter().zip(&vdot).map(|(&x, &a)| Dual64::new(x, a)).collect();
    /// let twists = d.twists(&qe, &ve).unwrap();
    /// let alpha = twists[0].omega.map(|x| x.eps);
    /// assert!((alpha - nalgebra::Vector3::new(0.0, 0.0, vdot[0])).norm() < 1e-14);
    /// ```
    #[doc(alias = "to_dual")]
    pub fn cast<U: Scalar>(&self) -> Model<U> {
        Model {
            segs: self
                .segs
                .iter()
                .map(|s| Segment {
                    parent: s.parent,
                    placement: s.placement.cast(),
                    elem: s.elem.cast(),
                    qi: s.qi,
                    vi: s.vi,
                    inertia: s.inertia.cast(),
                    com: s.com.map(U::lit),
                    j_c: s.j_c.map(U::lit),
                    massless: s.massless,
                    sub_mass: s.sub_mass,
                    sub_trace: s.sub_trace,
                    own_reach: s.own_reach,
                    placement_is_shift: s.placement_is_shift,
                    coord_axis: s.coord_axis,
                    parent_upright: s.parent_upright,
                })
                .collect(),
            link_seg: self.link_seg.clone(),
            nq: self.nq,
            nv: self.nv,
            gravity: self.gravity.map(U::lit),
            q_neutral: self.q_neutral.iter().map(|&x| U::lit(x)).collect(),
            parent_col: self.parent_col.clone(),
            col_seg: self.col_seg.clone(),
            free_leaves: self.free_leaves.clone(),
            free_links: self.free_links.clone(),
            free_jc_inv: self.free_jc_inv.iter().map(|m| m.map(U::lit)).collect(),
            free_seg: self.free_seg.clone(),
            planar: self.planar.as_ref().map(Planar::cast),
        }
    }
}

impl<T: Scalar> Model<T> {
    /// Number of configuration coordinates (quaternions count 4).
    pub fn nq(&self) -> usize {
        self.nq
    }

    /// Number of velocity coordinates (degrees of freedom).
    pub fn nv(&self) -> usize {
        self.nv
    }

    /// Number of links.
    pub fn links(&self) -> usize {
        self.link_seg.len()
    }

    /// The axis â (ground components) when the tree is planar: every pin turns about ±â, every
    /// slider moves ⊥ â, and no placement rotates the joint frame (so every link frame differs
    /// from the ground by a turn about â). Such a mechanism moves in planes ⊥ â from any state,
    /// and [`Model::aba`] then works on planar spatial vectors (3 numbers instead of 6: the
    /// in-plane parts of positions, centres, gravity and forces, the moment along â, and
    /// âᵀĪâ of each body), with the same v̇ to rounding. The tests are exact: an axis off ±â
    /// by rounding keeps the spatial algorithm. `None` for spatial trees.
    ///
    /// Book: §7.11 (chains); §6.3 (moment of inertia about an axis); RBDA §2.16.
    pub fn planar_axis(&self) -> Option<Vector3<T>> {
        self.planar.as_ref().map(|p| p.axis)
    }

    /// Turns the planar reduction of [`Model::planar_axis`] off, so that [`Model::aba`] runs the
    /// spatial passes on a planar tree too: for measuring what the reduction saves and for
    /// checking it (the answers agree to rounding). [`Model::planar_axis`] returns `None`
    /// afterwards: it reports what the model uses.
    pub fn disable_planar_reduction(&mut self) {
        self.planar = None;
    }

    /// The neutral configuration: zero for every coordinate, identity quaternions.
    pub fn neutral(&self) -> Vec<T> {
        self.q_neutral.clone()
    }

    /// The joint-to-parent transform of every segment at q (placement ∘ joint).
    #[inline(always)]
    pub(crate) fn seg_xform(&self, i: usize, q: &[T]) -> Xform<T> {
        let s = &self.segs[i];
        let j = s.elem.xform(&q[s.qi..]);
        if s.placement_is_shift {
            // placement E = 1: placement ∘ joint = (E_joint, r_placement + r_joint)
            Xform { E: j.E, r: s.placement.r + j.r }
        } else {
            s.placement.then(&j)
        }
    }

    /// Ground-to-segment transform of segment i from its parent's (`None` at the root):
    /// parent ∘ placement ∘ joint. A pin about a coordinate axis behind a placement without
    /// rotation mixes two rows of the parent's orientation (12 products instead of 27).
    #[inline(always)]
    pub(crate) fn world_xform(&self, i: usize, q: &[T], parent: Option<&Xform<T>>) -> Xform<T> {
        let s = &self.segs[i];
        if let (Some(p), true, Elem::Revolute(_), Some((axis, negative))) =
            (parent, s.placement_is_shift, &s.elem, s.coord_axis)
        {
            let (sn, c) = q[s.qi].sin_cos();
            let sn = if negative { -sn } else { sn };
            let r = p.r + p.E.tr_mul(&s.placement.r);
            // 𝓞_{i/G} = 𝓞_k(θ) 𝓞_{p/G}: rows (i1, i2) turn by θ, the axis row stays
            let (i1, i2) = [(1, 2), (2, 0), (0, 1)][axis];
            let mut e = p.E;
            for col in 0..3 {
                let (a1, a2) = (p.E[(i1, col)], p.E[(i2, col)]);
                e[(i1, col)] = c * a1 + sn * a2;
                e[(i2, col)] = c * a2 - sn * a1;
            }
            return Xform { E: e, r };
        }
        // a slider behind a placement without rotation keeps the parent's orientation
        // (1·𝓞 = 𝓞 exactly): only the origin moves
        if let (Some(p), true, Elem::Prismatic(a)) = (parent, s.placement_is_shift, &s.elem) {
            let shift = s.placement.r + a * q[s.qi];
            return Xform { E: p.E, r: p.r + if s.parent_upright { shift } else { p.E.tr_mul(&shift) } };
        }
        let x = self.seg_xform(i, q);
        match parent {
            // the parent's orientation is exactly the ground's (1 ∘ x: a shift)
            Some(p) if s.parent_upright => Xform { E: x.E, r: p.r + x.r },
            Some(p) => p.then(&x),
            None => x,
        }
    }

    /// Link poses: for each link, 𝓞_{link/ground} and r_{link origin/ground origin}|_ground.
    ///
    /// Book: §2.22 (chains), (2.10.46) composition.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
    /// [`DynamicsError::OutOfRange`] (a ball-joint quaternion of norm below 1e-6).
    pub fn poses(&self, q: &[T]) -> Result<Vec<Pose<T>>, DynamicsError> {
        self.check_q(q)?;
        let (mut world, mut out) = (PosesScratch::default(), Vec::new());
        self.poses_into(q, &mut world, &mut out);
        Ok(out)
    }

    /// [`Model::poses`] into caller-owned buffers (no allocation once they have grown), without
    /// input checks: the hot path of a right-hand side. `world` is work space.
    pub fn poses_into(&self, q: &[T], world: &mut PosesScratch<T>, out: &mut Vec<Pose<T>>) {
        let world = &mut world.0;
        world.clear();
        for (i, s) in self.segs.iter().enumerate() {
            let w = self.world_xform(i, q, s.parent.map(|p| &world[p]));
            world.push(w);
        }
        out.clear();
        out.extend(self.link_seg.iter().map(|&k| (world[k].E, world[k].r)));
    }

    /// Ground-to-segment transforms of every segment (parents first).
    pub(crate) fn world_xforms(&self, q: &[T]) -> Vec<Xform<T>> {
        let mut world: Vec<Xform<T>> = Vec::with_capacity(self.segs.len());
        for (i, s) in self.segs.iter().enumerate() {
            let w = self.world_xform(i, q, s.parent.map(|p| &world[p]));
            world.push(w);
        }
        world
    }
}

/// Work space of [`Model::poses_into`]: the ground-to-segment transforms of one evaluation,
/// kept between calls so that a right-hand side allocates nothing once it has grown; after
/// `poses_into` at q, [`Model::twists_into`] and [`Model::bias_accelerations_into`] read them.
#[derive(Debug, Clone)]
pub struct PosesScratch<T: Scalar = f64>(pub(crate) Vec<Xform<T>>);

impl<T: Scalar> Default for PosesScratch<T> {
    fn default() -> Self {
        Self(Vec::new())
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Vector3};

    use super::super::joint::{Joint, Link};
    use super::Model;

    /// Behind a free joint's sliders the orientation is exactly the ground's, so composing with
    /// them is a shift: the free body's pose is (𝓡(q)ᵀ, offset + (x, y, z)) with 𝓡 the rotation
    /// of the normalized Euler parameters (η, ε), 𝓡 = (2η² − 1)1 + 2ηε^× + 2εεᵀ (Fact 2.15.5;
    /// 2η² − 1 = η² − εᵀε for a unit quaternion), and
    /// a pin child about ẑ at d composes as 𝓞 = 𝓡_z(θ)ᵀ𝓞₀, r = r₀ + 𝓞₀ᵀd; matrices built here
    /// by hand, not by the model's code.
    #[test]
    fn poses_behind_a_free_joint() {
        let (offset, d) = (Vector3::new(0.5, -0.2, 0.1), Vector3::new(0.3, 0.7, -0.4));
        let links = [
            Link::new(None, Joint::Free, offset, 2.0, Vector3::new(0.1, 0.0, 0.2), Matrix3::identity()),
            Link::new(
                Some(0),
                Joint::Pin { axis: Vector3::z() },
                d,
                1.0,
                Vector3::zeros(),
                Matrix3::identity(),
            ),
        ];
        let m = Model::new(&links).expect("valid");
        // an unnormalized quaternion (the joint normalizes it) and a pin angle
        let (x, eta, eps, th): (Vector3<f64>, f64, Vector3<f64>, f64) =
            (Vector3::new(1.5, -2.0, 0.75), 0.6, Vector3::new(-0.4, 1.1, 0.3), 0.9);
        let n = (eta * eta + eps.norm_squared()).sqrt();
        let (eta, eps) = (eta / n, eps / n);
        let cross = Matrix3::new(0.0, -eps.z, eps.y, eps.z, 0.0, -eps.x, -eps.y, eps.x, 0.0);
        let r = Matrix3::identity() * (eta * eta - eps.norm_squared())
            + eps * eps.transpose() * 2.0
            + cross * (2.0 * eta);
        let e0 = r.transpose();
        let r0 = offset + x;
        let (s, c) = th.sin_cos();
        let e1 = Matrix3::new(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0) * e0;
        let r1 = r0 + e0.transpose() * d;
        let q = [x.x, x.y, x.z, 0.6 * 2.0, -0.4 * 2.0, 1.1 * 2.0, 0.3 * 2.0, th];
        let poses = m.poses(&q).expect("valid q");
        let tol = 4.0 * f64::EPSILON;
        assert!((poses[0].0 - e0).amax() <= tol && (poses[0].1 - r0).amax() <= tol, "{poses:?}");
        assert!((poses[1].0 - e1).amax() <= tol && (poses[1].1 - r1).amax() <= 2.0 * tol, "{poses:?}");
    }
}
