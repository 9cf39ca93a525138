//! The joint-space mass matrix by the composite-rigid-body algorithm (in ground coordinates,
//! where composite inertias add without transforms), and forward dynamics by CRBA + Cholesky
//! (the cross-check of the articulated-body algorithm).
#![allow(non_snake_case)]

use nalgebra::{Cholesky, DMatrix, DVector, Dyn, Vector3, Vector6};
use vectrix_tensor::Scalar;

use super::joint::Elem;
use super::model::{Model, Trig};
use super::segment::Segment;
use super::spatial::{BodyInertia, Xform, join};

use super::wrench::LinkWrenches;
use crate::DynamicsError;

/// A Cholesky pivot below this multiple of n ε × max Mᵢᵢ (ε of the scalar) counts as
/// singular (the rounding level of a mass matrix assembled by O(n) sums of products).
pub(crate) const MASS_PIVOT_EPS: f64 = 64.0;

/// Work space of [`Model::crba_into`].
#[derive(Debug, Clone)]
pub struct CrbaScratch<T: Scalar = f64> {
    world: Vec<Xform<T>>,
    /// One motion-subspace column per velocity coordinate, ground coordinates.
    S: Vec<Vector6<T>>,
    Ic: Vec<BodyInertia<T>>,
    /// Each coordinate's entries against its ancestors (`entries[start[b]..start[b + 1]]`).
    entries: Vec<Entry>,
    start: Vec<usize>,
    /// The entries of H that are zero whatever q (the only ones CRBA must clear).
    zeros: ZeroRuns,
    /// The revolute joints' sines and cosines, computed together.
    trig: Trig<T>,
}

/// One off-diagonal pair H_ab = H_ba of a coordinate b's column against an ancestor a: where the
/// two go in the column-major slice, and how S_a reads F = Iᶜ S_b.
#[derive(Debug, Clone, Copy)]
struct Entry {
    a: usize,
    upper: usize,
    lower: usize,
    read: Read,
}

/// How S_a reads F: a dot product, or ±F_k when S_a is ±e_k (k ≥ 3) in ground coordinates
/// whatever q (a slider along a coordinate axis whose orientation is the ground's: the sliders
/// of a free joint, [`Model::ground_axis_columns`]).
#[derive(Debug, Clone, Copy)]
enum Read {
    Dot,
    Pick(usize),
    PickNegative(usize),
}

impl<T: Scalar> Model<T> {
    /// The entries of every column of H against its ancestors, in the order of `parent_col`'s
    /// ancestor lists (nearest first), and where each column's start.
    fn crba_entries(&self) -> (Vec<Entry>, Vec<usize>) {
        let (n, tree, pick) = (self.nv, CoordLists::ancestors(&self.parent_col), self.ground_axis_columns());
        let mut start = Vec::with_capacity(n + 1);
        let mut entries = Vec::with_capacity(tree.total());
        for b in 0..n {
            start.push(entries.len());
            entries.extend(tree.of(b).iter().map(|&a| Entry {
                a,
                upper: a + b * n,
                lower: b + a * n,
                read: match pick[a] {
                    Some((k, false)) => Read::Pick(k),
                    Some((k, true)) => Read::PickNegative(k),
                    None => Read::Dot,
                },
            }));
        }
        start.push(entries.len());
        (entries, start)
    }
}

/// The columns of S_i in ground coordinates about the ground origin, (ω, v) ordering, for a
/// segment whose ground-to-segment transform is `x` (E = 𝓞_{i/G}, origin p), written into
/// `out` (one entry per column): a pin about the link axis a has S = (u, p × u) with u = Eᵀa;
/// a slider (0, Eᵀa); a ball the three columns (uₖ, p × uₖ), uₖ = Eᵀeₖ.
#[inline(always)]
pub(crate) fn world_subspace<T: Scalar>(seg: &Segment<T>, x: &Xform<T>, out: &mut [Vector6<T>]) {
    match &seg.elem {
        Elem::Revolute(a) => {
            // Eᵀa: ± a row of E for a coordinate axis
            let u = match seg.coord_axis {
                Some((k, false)) => x.E.row(k).transpose(),
                Some((k, true)) => -x.E.row(k).transpose(),
                None => x.E.tr_mul(a),
            };
            out[0] = join(&u, &x.r.cross(&u));
        }
        Elem::Prismatic(a) => out[0] = join(&Vector3::zeros(), &x.E.tr_mul(a)),
        Elem::Spherical => {
            for (k, o) in out.iter_mut().take(3).enumerate() {
                let u: Vector3<T> = x.E.row(k).transpose();
                *o = join(&u, &x.r.cross(&u));
            }
        }
        Elem::Fixed => {}
    }
}

impl<T: Scalar> Model<T> {
    /// A work space for [`Model::crba_into`].
    pub fn crba_scratch(&self) -> CrbaScratch<T> {
        let n = self.segs.len();
        let (entries, start) = self.crba_entries();
        CrbaScratch {
            world: vec![Xform::identity(); n],
            S: vec![Vector6::zeros(); self.nv],
            Ic: vec![BodyInertia::zero(); n],
            entries,
            start,
            zeros: ZeroRuns::of_tree(&self.parent_col),
            trig: Trig::of(self),
        }
    }

    /// The joint-space mass matrix H(q) (symmetric, nv × nv) by the composite-rigid-body
    /// algorithm: composite inertias Iᶜᵢ accumulated tip to base, Hᵢⱼ = Sᵢᵀ Iᶜⱼ Sⱼ for every
    /// ancestor i of j (all in ground coordinates), zero between branches.
    ///
    /// Book: §7.11 (the mass matrix of the chain), §9.3 (M(q) of (9.3.11)); RBDA Table 6.2.
    ///
    /// # Degenerate inputs
    /// A model with an inert joint direction (see [`Model::aba`]: a particle on a ball joint,
    /// a massless link between coaxial pins) has a singular H; it is returned as computed
    /// (positive semidefinite), and solving with it is the caller's decision.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
    /// [`DynamicsError::OutOfRange`] (a ball-joint quaternion of norm below 1e-6);
    /// [`DynamicsError::Overflow`] when finite q gives a non-finite entry (a prismatic
    /// coordinate near 1e154 squares past f64::MAX in the composite inertias).
    pub fn crba(&self, q: &[T]) -> Result<DMatrix<T>, DynamicsError> {
        self.check_q(q)?;
        let h = self.crba_unchecked(q);
        if !crate::error::all_finite(h.as_slice()) {
            return Err(DynamicsError::Overflow { what: "mass matrix" });
        }
        Ok(h)
    }

    /// [`Model::crba`] without input checks.
    pub fn crba_unchecked(&self, q: &[T]) -> DMatrix<T> {
        let mut h = DMatrix::zeros(self.nv, self.nv);
        let mut s = self.crba_scratch();
        self.crba_into(q, &mut h, &mut s);
        h
    }

    /// [`Model::crba`] without input checks, into a caller-provided nv × nv matrix with
    /// caller-provided scratch (no allocation): the hot path.
    ///
    /// # Panics
    /// If `h` is not nv × nv (a programming error, not user input).
    pub fn crba_into(&self, q: &[T], h: &mut DMatrix<T>, s: &mut CrbaScratch<T>) {
        assert_eq!(h.shape(), (self.nv, self.nv), "crba_into: h must be nv × nv");
        // outward: ground placement of every segment, its S in ground coordinates, and its
        // own inertia about the ground origin
        s.trig.fill(q);
        for (i, seg) in self.segs.iter().enumerate() {
            let w = self.world_xform(i, q, seg.parent.map(|p| &s.world[p]), s.trig.get(i));
            world_subspace(seg, &w, &mut s.S[seg.vi..]);
            s.Ic[i] = if seg.massless { BodyInertia::zero() } else { seg.ground_inertia(&w) };
            s.world[i] = w;
        }
        let n = self.nv;
        let hs = h.as_mut_slice();
        // every other entry is written below: clear only those between branches
        s.zeros.clear(hs);
        // inward: Iᶜ_i is complete when i is reached (descendants come later in the order);
        // for each column b of joint i, F = Iᶜ_i S_b, then H_bb = S_b·F and H_ab = H_ba = S_a·F
        // for every coordinate a above b (its ancestors: `entries`); Iᶜ_p += Iᶜ_i
        // (same coordinates: a plain sum)
        let mut i = self.segs.len();
        while i > 0 {
            i -= 1;
            let seg = &self.segs[i];
            for b in seg.vi..seg.vi + seg.elem.nv() {
                let F = s.Ic[i].apply6(&s.S[b]);
                hs[b + b * n] = dot6(&s.S[b], &F);
                for e in &s.entries[s.start[b]..s.start[b + 1]] {
                    let hab = match e.read {
                        Read::Dot => dot6(&s.S[e.a], &F),
                        Read::Pick(k) => F[k],
                        Read::PickNegative(k) => -F[k],
                    };
                    hs[e.upper] = hab;
                    hs[e.lower] = hab;
                }
            }
            if i >= 3 && self.free_at_root(i - 3) {
                // the sliders of a free joint at the root: S = (0, eₖ) in the joint frame's
                // axes, so their block of H is m·1 (m the whole tree's mass; the picks of
                // their rows against the ball's columns are written above), and nothing
                // hangs above them
                let m = s.Ic[i].m;
                let c = self.segs[i - 3].vi;
                for j in c..c + 3 {
                    for k in c..c + 3 {
                        hs[j + k * n] = if j == k { m } else { T::zero() };
                    }
                }
                i -= 3;
            } else if let Some(p) = seg.parent {
                let ic = s.Ic[i];
                s.Ic[p].add(&ic);
            }
        }
    }

    /// Per velocity coordinate: `Some((3 + k, negative))` when its motion subspace in ground
    /// coordinates is (0, ±e_k) whatever q: a slider along a coordinate axis behind a
    /// placement without rotation, on a parent that keeps the ground's orientation (or at the
    /// root), as the sliders of a free joint are; `None` otherwise.
    pub(crate) fn ground_axis_columns(&self) -> Vec<Option<(usize, bool)>> {
        let mut pick = vec![None; self.nv];
        for seg in &self.segs {
            let upright = seg.parent.is_none() || seg.parent_upright;
            if let (Elem::Prismatic(_), true, true, Some((k, neg))) =
                (&seg.elem, upright, seg.placement_is_shift, seg.coord_axis)
            {
                pick[seg.vi] = Some((3 + k, neg));
            }
        }
        pick
    }

    /// Forward dynamics by H(q) v̇ = τ − C(q, v), C from [`Model::rnea`] with v̇ = 0, solved
    /// by Cholesky: O(n³), the cross-check of [`Model::aba`].
    ///
    /// Book: §7.11, §9.6 (M q̈ = Q − …).
    ///
    /// # Errors
    /// As [`Model::rnea`]; [`DynamicsError::SingularMassMatrix`] when H is not positive
    /// definite (a Cholesky pivot ≤ 64 n ε max Hᵢᵢ), e.g. a model with an inert joint
    /// direction, which [`Model::aba`] solves exactly.
    pub fn forward_dynamics_crba(
        &self,
        q: &[T],
        v: &[T],
        tau: &[T],
        f_ext: Option<&LinkWrenches<T>>,
    ) -> Result<Vec<T>, DynamicsError> {
        self.check_v(tau, "τ")?;
        let zero = vec![T::zero(); self.nv];
        let bias = self.rnea(q, v, &zero, f_ext)?.tau;
        let h = self.crba_unchecked(q);
        let rhs = DVector::from_iterator(self.nv, tau.iter().zip(&bias).map(|(&t, &c)| t - c));
        let x = mass_cholesky(h)?.solve(&rhs);
        if !crate::error::all_finite(x.as_slice()) {
            return Err(DynamicsError::Overflow { what: "forward dynamics v̇" });
        }
        Ok(x.as_slice().to_vec())
    }
}

/// Cholesky factor of a mass matrix, refusing pivots at the rounding level.
///
/// # Errors
/// [`DynamicsError::SingularMassMatrix`] with the pivot and the bound.
pub(crate) fn mass_cholesky<T: Scalar>(m: DMatrix<T>) -> Result<Cholesky<T, Dyn>, DynamicsError> {
    let r = m.nrows();
    let scale = (0..r).map(|i| m[(i, i)].re().abs()).fold(0.0, f64::max);
    let chol = Cholesky::new(m).ok_or_else(|| DynamicsError::SingularMassMatrix {
        detail: "Cholesky found a non-positive pivot".into(),
    })?;
    let l = chol.l_dirty();
    let bound = MASS_PIVOT_EPS * T::eps() * r as f64 * scale;
    for k in 0..r {
        let pivot = (l[(k, k)] * l[(k, k)]).re();
        // (a NaN pivot fails too)
        if pivot.partial_cmp(&bound) != Some(std::cmp::Ordering::Greater) {
            return Err(DynamicsError::SingularMassMatrix {
                detail: format!("pivot {k} is {pivot:e}, at or below {bound:e} = 64 n ε max Mᵢᵢ"),
            });
        }
    }
    Ok(chol)
}

/// a·b of two 6-vectors, written out as the sums of the even and the odd entries (two lanes
/// of one SSE2 register, then one add), the same sums on every CPU.
#[inline(always)]
pub(crate) fn dot6<T: Scalar>(a: &Vector6<T>, b: &Vector6<T>) -> T {
    let even = a[0] * b[0] + a[2] * b[2] + a[4] * b[4];
    let odd = a[1] * b[1] + a[3] * b[3] + a[5] * b[5];
    even + odd
}

/// The entries of an n × n column-major matrix indexed by a tree's coordinates that are zero
/// whatever the state: row r of column c where r is neither c nor an ancestor or a descendant
/// of c (two coordinates on different branches). The mass matrix, ∂τ/∂q and ∂τ/∂v of a tree
/// have this pattern (RBDA §6.1: branch-induced sparsity), so an algorithm that writes every
/// other entry clears only these (a whole-matrix fill is n² stores every call; a chain has no
/// such entries at all), as runs of the column-major slice; runs less than 16 entries apart
/// are cleared as one, up to 256 entries (the related entries between them are written after
/// the clear anyway).
/// O(n·depth) numbers.
#[derive(Debug, Clone, Default)]
pub(crate) struct ZeroRuns {
    /// Runs [a, b) of the matrix's column-major slice (runs that meet across columns merged).
    runs: Vec<(usize, usize)>,
}

impl ZeroRuns {
    /// The runs of a column tree (`parent_col[c] < c`, parents before children).
    pub fn of_tree(parent_col: &[Option<usize>]) -> Self {
        let n = parent_col.len();
        let (above, below) = (CoordLists::ancestors(parent_col), CoordLists::with_descendants(parent_col));
        let mut runs: Vec<(usize, usize)> = Vec::new();
        // runs closer than MERGE entries become one (the entries between them are written
        // after the clear anyway, and a few stores cost less than another fill), up to CAP
        // entries: glibc's memset turns to `rep stosb` at 2 KiB, which valgrind counts a byte
        // at a time, so longer fills would make the instruction counts of
        // benches/peers/icount_models.sh measure that instead of the stores
        const MERGE: usize = 16;
        const CAP: usize = 2048 / 8;
        let mut push = |a: usize, b: usize| match runs.last_mut() {
            Some(last) if a - last.1 <= MERGE && b - last.0 <= CAP => last.1 = b,
            _ => runs.push((a, b)),
        };
        for c in 0..n {
            // the related rows in ascending order: ancestors (nearest first, so reversed),
            // then c and its descendants
            let mut next = 0;
            for &r in above.of(c).iter().rev().chain(below.of(c)) {
                debug_assert!(r >= next, "parent_col must order parents before children");
                if r > next {
                    push(next + c * n, r + c * n);
                }
                next = r + 1;
            }
            if next < n {
                push(next + c * n, n + c * n);
            }
        }
        Self { runs }
    }

    /// Zero the runs of the n × n column-major matrix `m` (the one `of_tree` was made for).
    #[inline]
    pub fn clear<T: Scalar>(&self, m: &mut [T]) {
        for &(a, b) in &self.runs {
            m[a..b].fill(T::zero());
        }
    }
}

/// One list of coordinates per velocity coordinate, flattened: each coordinate's ancestors
/// (nearest first; the (row, column) pairs of a tree's mass matrix that can be nonzero), or
/// each coordinate with its descendants (the rows where a column of L⁻¹ of M = LᵀL can be
/// nonzero). O(n·depth) numbers, so the work spaces hold them (as large as H), not the model.
#[derive(Debug, Clone, Default)]
pub(crate) struct CoordLists {
    /// `all[start[c]..start[c + 1]]`: the list of coordinate c.
    start: Vec<usize>,
    all: Vec<usize>,
}

impl CoordLists {
    /// Each coordinate's ancestors, nearest first, from each coordinate's nearest ancestor.
    pub fn ancestors(parent_col: &[Option<usize>]) -> Self {
        Self::from_lists(parent_col.len(), |c, out| {
            let mut a = parent_col[c];
            while let Some(p) = a {
                out.push(p);
                a = parent_col[p];
            }
        })
    }

    /// Each coordinate, then its descendants in ascending order (parents precede children).
    pub fn with_descendants(parent_col: &[Option<usize>]) -> Self {
        let n = parent_col.len();
        let mut below = vec![Vec::new(); n];
        for c in 0..n {
            let mut a = parent_col[c];
            while let Some(p) = a {
                below[p].push(c);
                a = parent_col[p];
            }
        }
        Self::from_lists(n, |c, out| {
            out.push(c);
            out.extend_from_slice(&below[c]);
        })
    }

    fn from_lists(n: usize, mut list: impl FnMut(usize, &mut Vec<usize>)) -> Self {
        let mut start = Vec::with_capacity(n + 1);
        let mut all = Vec::new();
        for c in 0..n {
            start.push(all.len());
            list(c, &mut all);
        }
        start.push(all.len());
        Self { start, all }
    }

    /// For lists made by [`CoordLists::with_descendants`]: when every coordinate's descendants
    /// are the coordinates right after it (depth-first order: each subtree a contiguous range
    /// c..end[c]), `end`; else empty.
    pub fn contiguous_ends(&self) -> Vec<usize> {
        let n = self.start.len() - 1;
        if (0..n).all(|c| self.of(c).iter().enumerate().all(|(x, &a)| a == c + x)) {
            (0..n).map(|c| c + self.of(c).len()).collect()
        } else {
            Vec::new()
        }
    }

    /// Where the list of coordinate c starts in the flattened lists (c = n: where they end).
    #[inline(always)]
    pub fn offset(&self, c: usize) -> usize {
        self.start[c]
    }

    /// The length of all lists together.
    pub fn total(&self) -> usize {
        self.all.len()
    }

    /// The list of coordinate c.
    #[inline(always)]
    pub fn of(&self, c: usize) -> &[usize] {
        &self.all[self.start[c]..self.start[c + 1]]
    }
}
