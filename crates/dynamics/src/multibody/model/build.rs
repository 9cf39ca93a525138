//! Building a [`Model`] from links: validation of every number, the expansion of each joint
//! into elementary segments (parents first), and the tables the tree algorithms read (the
//! column tree, subtree sums, the free leaves solved in closed form, the planar reduction).
//!
//! Book: §7.11; §1.5 (joints); Fact 6.2.7 (valid inertia).

use nalgebra::{Matrix3, Vector3};
use vectrix_frames::Frame;
use vectrix_statics::{INERTIA_REL_TOL, check_inertia};
use vectrix_tensor::Scalar;

use super::{MAX_CHAIN_LINKS, Model};
use crate::DynamicsError;
use crate::error::check_finite;
use crate::multibody::joint::{Elem, Joint, Link, coordinate_axis, elems};
use crate::multibody::planar::Planar;
use crate::multibody::segment::{Segment, Turn};
use crate::multibody::singular::{pivot_tol, spd_inverse3};
use crate::multibody::spatial::{BodyInertia, CentreForm, Xform};

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
        let expanded =
            links.iter().enumerate().map(|(i, l)| validate_link(i, l)).collect::<Result<Vec<_>, _>>()?;
        let Expansion { mut segs, link_seg, q_neutral, nv } = expand_segments(links, &order, &expanded);
        mark_upright(&mut segs);
        add_subtree_sums(&mut segs);
        let (parent_col, col_seg) = column_tree(&segs, nv);
        let children = child_counts(&segs);
        let free_leaves = free_leaf_roots(&segs, &children);
        let free_links = free_leaves
            .iter()
            .map(|&f| link_seg.iter().position(|&k| k == f + 3).expect("the ball segment ends its link"))
            .collect();
        let free_jc_inv = free_leaves
            .iter()
            .map(|&f| definite_inverse(&segs[f + 3].j_c).expect("definite: checked by free_leaf_roots"))
            .collect();
        let mut free_seg = vec![false; segs.len()];
        for &f in &free_leaves {
            free_seg[f..f + 4].fill(true);
        }
        let (mut ball_leaves, mut ball_links, mut ball_jo_inv) = (Vec::new(), Vec::new(), Vec::new());
        for (b, jo_inv) in ball_leaf_roots(&segs, &children) {
            if let Some(l) = link_seg.iter().position(|&k| k == b) {
                ball_leaves.push(b);
                ball_links.push(l);
                ball_jo_inv.push(jo_inv);
            }
        }
        let free_roots = free_tree_roots(&segs, &children);
        let mut free_root_seg = vec![None; segs.len()];
        for (k, &f) in free_roots.iter().enumerate() {
            free_root_seg[f..f + 4].fill(Some(k));
        }
        let mut aba_skip = free_seg.clone();
        for &b in &ball_leaves {
            aba_skip[b] = true;
        }
        let inward_skip = aba_skip.iter().zip(&free_root_seg).map(|(&a, r)| a || r.is_some()).collect();
        let planar = Planar::detect(&segs, &link_seg);
        Ok(Self {
            link_seg,
            nq: q_neutral.len(),
            nv,
            gravity: Vector3::zeros(),
            q_neutral,
            parent_col,
            col_seg,
            planar,
            free_leaves,
            free_links,
            free_jc_inv,
            free_seg,
            ball_leaves,
            ball_links,
            ball_jo_inv,
            aba_skip,
            free_roots,
            free_root_seg,
            inward_skip,
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
            segs: self.segs.iter().map(Segment::cast).collect(),
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
            ball_leaves: self.ball_leaves.clone(),
            ball_links: self.ball_links.clone(),
            ball_jo_inv: self.ball_jo_inv.iter().map(|m| m.map(U::lit)).collect(),
            aba_skip: self.aba_skip.clone(),
            free_roots: self.free_roots.clone(),
            free_root_seg: self.free_root_seg.clone(),
            inward_skip: self.inward_skip.clone(),
            planar: self.planar.as_ref().map(Planar::cast),
        }
    }
}

/// Checks one link (finite numbers, mass ≥ 0, a physical inertia, a rotation matrix for the
/// joint frame) and expands its joint into elementary joints.
fn validate_link(i: usize, l: &Link) -> Result<Vec<Elem<f64>>, DynamicsError> {
    check_finite(l.offset.as_slice(), "link offset")?;
    check_finite(l.orientation.as_slice(), "link orientation")?;
    check_finite(l.com.as_slice(), "centre of mass")?;
    if !(l.mass.is_finite() && l.mass >= 0.0) {
        return Err(DynamicsError::OutOfRange { what: "link mass", value: l.mass, valid: "finite ≥ 0" });
    }
    check_inertia(&Frame::new().dyadic(&l.inertia), INERTIA_REL_TOL)
        .map_err(|source| DynamicsError::InvalidInertia { what: format!("link {i}"), source })?;
    vectrix_rotation::check_rotation_matrix(&l.orientation, 1e-9)
        .map_err(|e| DynamicsError::JointGeometry { link: i, detail: e.to_string() })?;
    elems(&l.joint, i)
}

/// The segments of a tree with what locates them.
struct Expansion {
    segs: Vec<Segment<f64>>,
    /// Each link's last segment.
    link_seg: Vec<usize>,
    q_neutral: Vec<f64>,
    nv: usize,
}

/// The segments of every link, parents first (`order`): a link's elementary joints in turn,
/// the first placed by the link's offset and orientation, the others on the previous without
/// offset, the last carrying the body. Coordinates are numbered in the user's link order.
fn expand_segments(links: &[Link], order: &[usize], expanded: &[Vec<Elem<f64>>]) -> Expansion {
    let (mut q_off, mut v_off) = (vec![0usize; links.len()], vec![0usize; links.len()]);
    let (mut nq, mut nv) = (0, 0);
    for (i, e) in expanded.iter().enumerate() {
        (q_off[i], v_off[i]) = (nq, nv);
        nq += e.iter().map(Elem::nq).sum::<usize>();
        nv += e.iter().map(Elem::nv).sum::<usize>();
    }
    let mut segs: Vec<Segment<f64>> = Vec::new();
    let mut link_seg = vec![0usize; links.len()];
    let mut q_neutral = vec![0.0; nq];
    for &i in order {
        let l = &links[i];
        let mut parent = l.parent.map(|p| link_seg[p]);
        let mut placement = Xform { E: l.orientation, r: l.offset };
        let (mut qi, mut vi) = (q_off[i], v_off[i]);
        let count = expanded[i].len();
        for (k, elem) in expanded[i].iter().enumerate() {
            let last = k + 1 == count;
            let inertia =
                if last { BodyInertia::from_centre(l.mass, &l.com, &l.inertia) } else { BodyInertia::zero() };
            if *elem == Elem::Spherical {
                q_neutral[qi] = 1.0;
            }
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
                massless: inertia == BodyInertia::zero(),
                inertia,
                com,
                j_c,
                j_c_form: CentreForm::of(&j_c),
                sub_mass,
                sub_trace,
                own_reach,
                placement_is_shift: placement.E == Matrix3::identity(),
                coord_axis: coordinate_axis(elem),
                parent_upright: false,
                turn: Turn::of(elem, placement.E == Matrix3::identity(), coordinate_axis(elem)),
            });
            parent = Some(segs.len() - 1);
            placement = Xform::identity();
            qi += elem.nq();
            vi += elem.nv();
        }
        link_seg[i] = segs.len() - 1;
    }
    Expansion { segs, link_seg, q_neutral, nv }
}

/// Parents first: a segment keeps the ground's orientation when its parent does (or it is a
/// root) and it neither turns nor sits behind a turned placement.
fn mark_upright(segs: &mut [Segment<f64>]) {
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
}

/// Subtree masses and traces, tips to base (children come after their parents).
fn add_subtree_sums(segs: &mut [Segment<f64>]) {
    for i in (0..segs.len()).rev() {
        if let Some(p) = segs[i].parent {
            let (m, t) = (segs[i].sub_mass, segs[i].sub_trace);
            segs[p].sub_mass += m;
            segs[p].sub_trace += t;
        }
    }
}

/// The column tree: for each velocity coordinate the nearest coordinate above it (the
/// previous column of the same joint, else the last column of the nearest ancestor that has
/// one), and its segment.
fn column_tree(segs: &[Segment<f64>], nv: usize) -> (Vec<Option<usize>>, Vec<usize>) {
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
    (parent_col, col_seg)
}

/// The first segment of every free joint at the root whose link is a leaf: segments i..i+4
/// are the three sliders along x̂, ŷ, ẑ of the joint frame (massless, each placed on the
/// previous without offset) and the ball carrying the body, and no segment hangs from the
/// ball. Such a body couples to no other segment in the tree algorithms.
fn free_leaf_roots(segs: &[Segment<f64>], children: &[usize]) -> Vec<usize> {
    (0..segs.len().saturating_sub(3))
        .filter(|&i| is_free_root(segs, children, i) && children[i + 3] == 0)
        .collect()
}

/// The first segment of every free joint at the root (as [`free_leaf_roots`]) whose body has
/// children (a floating base): ABA eliminates the whole joint at once, one 6×6 solve with the
/// base's articulated inertia (`Model::free_root_solve`), instead of four segments.
fn free_tree_roots(segs: &[Segment<f64>], children: &[usize]) -> Vec<usize> {
    (0..segs.len().saturating_sub(3))
        .filter(|&i| is_free_root(segs, children, i) && children[i + 3] > 0)
        .collect()
}

/// Segments i..i+4 are a free joint at the root with a definite body ([`definite_body`]): the
/// three sliders along x̂, ŷ, ẑ of the joint frame (massless, each placed on the previous
/// without offset, each the only child of the one before) and the ball carrying the body.
fn is_free_root(segs: &[Segment<f64>], children: &[usize], i: usize) -> bool {
    let axes = [Vector3::x(), Vector3::y(), Vector3::z()];
    segs[i].parent.is_none()
        && (0..3).all(|k| {
            let s = &segs[i + k];
            s.elem == Elem::Prismatic(axes[k]) && s.massless && (k == 0 || s.parent == Some(i + k - 1))
        })
        && (1..4).all(|k| segs[i + k].placement == Xform::identity())
        && segs[i + 3].elem == Elem::Spherical
        && segs[i + 3].parent == Some(i + 2)
        // nothing else hangs from the sliders
        && children[i..i + 3].iter().all(|&c| c == 1)
        && definite_body(&segs[i + 3])
}

/// Every ball joint at the root whose segment carries a body and has no child, with the body's
/// inertia about the joint point J_o definite ([`definite_inverse`]), and its J_o⁻¹: such a body
/// couples to no other segment, and its Euler equations about the fixed point are solved by one
/// product with J_o⁻¹. A particle on a rod (J_c = 0, J_o of rank 2) is left to ABA's
/// rank-revealing path.
fn ball_leaf_roots(segs: &[Segment<f64>], children: &[usize]) -> Vec<(usize, Matrix3<f64>)> {
    segs.iter()
        .enumerate()
        .filter(|&(i, s)| s.parent.is_none() && s.elem == Elem::Spherical && children[i] == 0 && !s.massless)
        .filter_map(|(i, s)| Some((i, definite_inverse(&s.inertia.I)?)))
        .collect()
}

/// For each segment, how many hang from it.
fn child_counts(segs: &[Segment<f64>]) -> Vec<usize> {
    let mut children = vec![0; segs.len()];
    for s in segs {
        if let Some(p) = s.parent {
            children[p] += 1;
        }
    }
    children
}

/// m > 0 and J_c definite ([`definite_inverse`]): the closed form of a free body divides by
/// both. A particle (J_c = 0) or a body with an inert axis is left to ABA's rank-revealing path.
fn definite_body(s: &Segment<f64>) -> bool {
    s.inertia.m > 0.0 && definite_inverse(&s.j_c).is_some()
}

/// J⁻¹ of a symmetric 3×3 inertia whose every Cholesky pivot is above ABA's rounding level
/// (`pivot_tol` × tr J), else `None`.
fn definite_inverse(j: &Matrix3<f64>) -> Option<Matrix3<f64>> {
    let scale = j.trace();
    if scale > 0.0 { spd_inverse3(j, pivot_tol::<f64>() * scale) } else { None }
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
