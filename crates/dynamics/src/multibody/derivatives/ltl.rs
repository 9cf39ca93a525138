//! M⁻¹ of a tree's mass matrix by its LᵀL factorization (RBDA §6.5, Table 6.3): in the order of
//! the tree, tips first, M = LᵀL has no fill-in (Lᵢⱼ ≠ 0 only for j = i or an ancestor of i),
//! and so has W = L⁻¹; then M⁻¹ = W Wᵀ, a sum over each coordinate k of the outer product of
//! W's column k, nonzero on k and its descendants only. L and W are stored by rows along the
//! ancestors (no index chasing in the inner loops), M⁻¹'s terms by contiguous blocks when the
//! coordinates are in depth-first order. O(n·d²) where a dense Cholesky and inverse are O(n³),
//! d the depth.
//!
//! Book: §7.11 (the mass matrix); RBDA §6.5.

use vectrix_tensor::Scalar;

use crate::DynamicsError;
use crate::multibody::crba::{CoordLists, MASS_PIVOT_EPS};

/// The work space of [`TreeInverse::invert`]: the column tree's lists and the packed factors.
///
/// Packed rows: row k of L (and of W = L⁻¹) is nonzero only on k and its ancestors p₀ (the
/// parent), p₁, …, p_{d−1} (the root), so it is stored as its diagonal and d numbers in that
/// order, all rows flattened like [`CoordLists::ancestors`]. The ancestors of pₜ are
/// pₜ₊₁, …, p_{d−1}, so row pₜ's packed numbers line up with row k's from t + 1 on: every update
/// of the factorization and of W is a contiguous axpy.
#[derive(Debug, Clone)]
pub(crate) struct TreeInverse<T: Scalar> {
    parent_col: Vec<Option<usize>>,
    /// Each coordinate's ancestors, nearest first (the packed rows' layout).
    above: CoordLists,
    /// Each coordinate with its descendants (M⁻¹'s outer products when subtrees are scattered).
    below: CoordLists,
    /// When every coordinate's subtree is the contiguous range c..end[c] (depth-first order, as
    /// the importers and [`crate::multibody::Model::new`] from a depth-first list give):
    /// `end`; else empty.
    end: Vec<usize>,
    l: Vec<T>,
    l_diag: Vec<T>,
    w: Vec<T>,
    w_diag: Vec<T>,
    col: Vec<T>,
}

impl<T: Scalar> TreeInverse<T> {
    /// The work space for the column tree `parent_col` (`parent_col[c] < c`).
    pub fn new(parent_col: &[Option<usize>]) -> Self {
        let n = parent_col.len();
        let (above, below) = (CoordLists::ancestors(parent_col), CoordLists::with_descendants(parent_col));
        let end = below.contiguous_ends();
        let packed = above.total();
        Self {
            parent_col: parent_col.to_vec(),
            above,
            below,
            end,
            l: vec![T::zero(); packed],
            l_diag: vec![T::zero(); n],
            w: vec![T::zero(); packed],
            w_diag: vec![T::zero(); n],
            col: vec![T::zero(); n],
        }
    }

    /// M⁻¹ into `out` (full, column-major n × n) from the symmetric mass matrix `m` (column-major,
    /// read only on its diagonal and below it at (k, ancestor of k)).
    ///
    /// # Errors
    /// [`DynamicsError::SingularMassMatrix`] when a pivot is at or below 64 n ε max Mᵢᵢ (the
    /// test of the dense route; NaN fails too).
    pub fn invert(&mut self, m: &[T], out: &mut [T]) -> Result<(), DynamicsError> {
        let n = self.parent_col.len();
        let Self { above, l, l_diag, w, w_diag, .. } = self;
        let scale = (0..n).map(|i| m[i + i * n].re().abs()).fold(0.0, f64::max);
        let bound = MASS_PIVOT_EPS * T::eps() * n as f64 * scale;
        // gather M's rows along the ancestors
        for k in 0..n {
            l_diag[k] = m[k + k * n];
            let o = above.offset(k);
            for (x, &p) in l[o..].iter_mut().zip(above.of(k)) {
                *x = m[k + p * n];
            }
        }
        // LᵀL in place, k from the tips (RBDA Table 6.3): L_kk = √H_kk, L_kpₜ = H_kpₜ / L_kk,
        // then for each ancestor pₜ of k: H_pₜpₜ −= L_kpₜ², H_pₜpᵤ −= L_kpₜ L_kpᵤ (u > t)
        for k in (0..n).rev() {
            let d = l_diag[k];
            // (a NaN pivot fails too)
            if d.re().partial_cmp(&bound) != Some(std::cmp::Ordering::Greater) {
                return Err(DynamicsError::SingularMassMatrix {
                    detail: format!("pivot {k} is {:e}, at or below {bound:e} = 64 n ε max Mᵢᵢ", d.re()),
                });
            }
            let lkk = d.sqrt();
            l_diag[k] = lkk;
            let (o, path) = (above.offset(k), above.of(k));
            let (lo, row) = l.split_at_mut(o);
            let row = &mut row[..path.len()];
            for x in row.iter_mut() {
                *x /= lkk;
            }
            for (t, &p) in path.iter().enumerate() {
                let lt = row[t];
                l_diag[p] -= lt * lt;
                let op = above.offset(p);
                for (y, &x) in lo[op..].iter_mut().zip(&row[t + 1..]) {
                    *y -= lt * x;
                }
            }
        }
        // W = L⁻¹ (L W = 1), rows from the root: W_ii = 1/L_ii and, for the ancestors pᵤ of i,
        // W_ipᵤ = −(Σ_{t ≤ u} L_ipₜ W_pₜpᵤ)/L_ii, summed as axpys of the rows W_pₜ
        for i in 0..n {
            let (o, path) = (above.offset(i), above.of(i));
            let (lo, row) = w.split_at_mut(o);
            let row = &mut row[..path.len()];
            row.fill(T::zero());
            for (t, &p) in path.iter().enumerate() {
                let lt = l[o + t];
                row[t] += lt * w_diag[p];
                let op = above.offset(p);
                for (y, &x) in row[t + 1..].iter_mut().zip(&lo[op..]) {
                    *y += lt * x;
                }
            }
            let lii = l_diag[i];
            for y in row.iter_mut() {
                *y = -*y / lii;
            }
            w_diag[i] = T::one() / lii;
        }
        if self.end.is_empty() {
            self.outer_scattered(out)
        } else {
            self.outer_contiguous(out)
        }
        Ok(())
    }

    /// Column k of W on k and its descendants (`len` of them) into `col`: W_ak is row a's
    /// packed number at depth(a) − depth(k) − 1, counted from the end of row a.
    #[inline]
    fn column(&mut self, k: usize, len: usize, scattered: bool) {
        let back = self.above.of(k).len() + 1;
        self.col[0] = self.w_diag[k];
        for x in 1..len {
            let a = if scattered { self.below.of(k)[x] } else { k + x };
            self.col[x] = self.w[self.above.offset(a + 1) - back];
        }
    }

    /// M⁻¹ = W Wᵀ = Σ_k (column k of W)(column k of W)ᵀ when each subtree is a contiguous
    /// range c..end[c]: each term fills the square block of k's subtree, column by column (a
    /// root coordinate's term sets its block and zeroes the rest of those columns; no common
    /// ancestor there), exactly symmetric (the same products, summed in the same order).
    fn outer_contiguous(&mut self, out: &mut [T]) {
        let n = self.parent_col.len();
        for k in 0..n {
            let e = self.end[k];
            let len = e - k;
            self.column(k, len, false);
            let col = &self.col[..len];
            let root = self.parent_col[k].is_none();
            for (x, &cb) in col.iter().enumerate() {
                let b = k + x;
                let column = &mut out[b * n..(b + 1) * n];
                if root {
                    column[..k].fill(T::zero());
                    column[e..].fill(T::zero());
                    for (y, &ca) in column[k..e].iter_mut().zip(col) {
                        *y = ca * cb;
                    }
                } else {
                    for (y, &ca) in column[k..e].iter_mut().zip(col) {
                        *y += ca * cb;
                    }
                }
            }
        }
    }

    /// M⁻¹ = W Wᵀ through the descendant lists, into the lower triangle, then mirrored.
    fn outer_scattered(&mut self, out: &mut [T]) {
        let n = self.parent_col.len();
        for j in 0..n {
            out[j + j * n..n + j * n].fill(T::zero());
        }
        for k in 0..n {
            let len = self.below.of(k).len();
            self.column(k, len, true);
            let rows = self.below.of(k);
            for (x, &a) in rows.iter().enumerate() {
                let wak = self.col[x];
                for (&b, &wbk) in rows[..=x].iter().zip(&self.col[..=x]) {
                    out[a + b * n] += wak * wbk;
                }
            }
        }
        for j in 0..n {
            for i in j + 1..n {
                out[j + i * n] = out[i + j * n];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Vector3};

    use super::*;
    use crate::multibody::joint::{Joint, Link};
    use crate::multibody::model::Model;

    /// A link of the test trees: centre (0.05, −0.1, 0.2), one central inertia.
    fn link(parent: Option<usize>, joint: Joint, offset: [f64; 3], m: f64) -> Link {
        let j = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
        Link::new(parent, joint, Vector3::from(offset), m, Vector3::new(0.05, -0.1, 0.2), j)
    }

    fn pin(x: f64, y: f64, z: f64) -> Joint {
        Joint::Pin { axis: Vector3::new(x, y, z) }
    }

    /// A floating base with a two-pin leg and a ball leg: a branched column tree.
    fn tree() -> Model {
        Model::new(&[
            link(None, Joint::Free, [0.1, 0.2, 0.3], 3.0),
            link(Some(0), pin(0.0, 1.0, 0.0), [0.4, 0.1, -0.2], 1.2),
            link(Some(1), pin(0.3, 0.2, 1.0), [0.0, 0.0, -0.5], 0.7),
            link(Some(0), Joint::Ball, [-0.4, 0.1, -0.2], 0.9),
        ])
        .expect("valid")
    }

    /// The same links listed breadth first: the ball leg's coordinates come between the pin
    /// leg's, so subtrees are not contiguous (the scattered route).
    fn scattered() -> Model {
        Model::new(&[
            link(None, pin(0.0, 0.0, 1.0), [0.1, 0.2, 0.3], 3.0),
            link(Some(0), pin(0.0, 1.0, 0.0), [0.4, 0.1, -0.2], 1.2),
            link(Some(0), Joint::Ball, [-0.4, 0.1, -0.2], 0.9),
            link(Some(1), pin(0.3, 0.2, 1.0), [0.0, 0.0, -0.5], 0.7),
            link(None, Joint::Sleeve { axis: Vector3::x() }, [0.0, 1.0, 0.0], 0.8),
        ])
        .expect("valid")
    }

    /// M⁻¹ by LᵀL inverts CRBA's M (M M⁻¹ = 1 to 1e-12, nalgebra's product) and equals
    /// nalgebra's dense inverse (an independent factorization) to 1e-12 relative; exactly
    /// symmetric; for both orders of the coordinates (contiguous subtrees and scattered ones,
    /// the latter with a second root, so M⁻¹ has exact zeros between the roots' subtrees); and
    /// a work space reused with a NaN-filled output gives the same bits.
    #[test]
    fn tree_inverse_inverts_the_mass_matrix() {
        for (m, contiguous) in [(tree(), true), (scattered(), false)] {
            let tangent = [0.3, -0.2, 0.5, 0.4, -0.7, 0.2, 0.6, -1.1, 0.3, 0.8, -0.4];
            let q = m.integrate(&m.q_neutral, &tangent[..m.nv()], 1.0).expect("valid");
            let h = m.crba(&q).expect("valid");
            let n = h.nrows();
            let mut inv = TreeInverse::new(&m.parent_col);
            assert_eq!(inv.end.is_empty(), !contiguous);
            let mut out = nalgebra::DMatrix::zeros(n, n);
            inv.invert(h.as_slice(), out.as_mut_slice()).expect("definite");
            let e = &h * &out - nalgebra::DMatrix::<f64>::identity(n, n);
            assert!(e.iter().all(|x| x.abs() <= 1e-12), "M M⁻¹ − 1 = {e}");
            let dense = h.clone().try_inverse().expect("invertible");
            let big = dense.iter().fold(0.0_f64, |a, x| if x.abs() > a { x.abs() } else { a });
            assert!(
                out.iter().zip(dense.iter()).all(|(a, b)| (a - b).abs() <= 1e-12 * big),
                "{out} vs {dense}"
            );
            assert!((0..n).all(|i| (0..n).all(|j| out[(i, j)] == out[(j, i)])), "symmetric");
            let mut again = nalgebra::DMatrix::from_element(n, n, f64::NAN);
            inv.invert(h.as_slice(), again.as_mut_slice()).expect("definite");
            assert_eq!(again, out);
            if !contiguous {
                // coordinates 0..5 hang from the first root, 6 is the second root
                assert!((0..6).all(|i| out[(i, 6)] == 0.0 && out[(6, i)] == 0.0));
            }
        }
    }

    /// H does not depend on the order the links are listed in: `scattered()` against the same
    /// links listed depth first, H permuted to match, to 1e-14 relative (the composite inertias
    /// add children in another order); `contiguous_ends` tells the two orders apart.
    #[test]
    fn crba_does_not_depend_on_the_order_of_the_links() {
        let depth_first = Model::new(&[
            link(None, pin(0.0, 0.0, 1.0), [0.1, 0.2, 0.3], 3.0),
            link(Some(0), pin(0.0, 1.0, 0.0), [0.4, 0.1, -0.2], 1.2),
            link(Some(1), pin(0.3, 0.2, 1.0), [0.0, 0.0, -0.5], 0.7),
            link(Some(0), Joint::Ball, [-0.4, 0.1, -0.2], 0.9),
            link(None, Joint::Sleeve { axis: Vector3::x() }, [0.0, 1.0, 0.0], 0.8),
        ])
        .expect("valid");
        let m = scattered();
        assert!(CoordLists::with_descendants(&m.parent_col).contiguous_ends().is_empty());
        assert!(!CoordLists::with_descendants(&depth_first.parent_col).contiguous_ends().is_empty());
        // coordinates of `scattered` in depth-first order: root pin, pin, pin below it, ball, sleeve
        let order = [0, 1, 5, 2, 3, 4, 6];
        let tangent = [0.3, -0.2, 0.5, 0.4, -0.7, 0.2, 0.6];
        let q = m.integrate(&m.q_neutral, &tangent, 1.0).expect("valid");
        let t2: Vec<f64> = order.iter().map(|&c| tangent[c]).collect();
        let q2 = depth_first.integrate(&depth_first.q_neutral, &t2, 1.0).expect("valid");
        let (h, h2) = (m.crba(&q).expect("valid"), depth_first.crba(&q2).expect("valid"));
        let big = h.iter().fold(0.0_f64, |a, x| if x.abs() > a { x.abs() } else { a });
        for (i, &a) in order.iter().enumerate() {
            for (j, &b) in order.iter().enumerate() {
                assert!(
                    (h2[(i, j)] - h[(a, b)]).abs() <= 1e-14 * big,
                    "({i}, {j}): {} vs {}",
                    h2[(i, j)],
                    h[(a, b)]
                );
            }
        }
    }

    /// A singular or NaN mass matrix is refused with the pivot named.
    #[test]
    fn tree_inverse_refuses_a_singular_or_nan_matrix() {
        for m in [tree(), scattered()] {
            let h = m.crba(&m.q_neutral).expect("valid");
            let n = h.nrows();
            let mut inv = TreeInverse::new(&m.parent_col);
            for bad in [0.0, f64::NAN] {
                let mut work = h.clone();
                work[(n - 1, n - 1)] = bad;
                let r = inv.invert(work.as_slice(), &mut vec![0.0; n * n]);
                assert!(matches!(r, Err(DynamicsError::SingularMassMatrix { .. })), "{bad}: {r:?}");
            }
        }
    }
}
