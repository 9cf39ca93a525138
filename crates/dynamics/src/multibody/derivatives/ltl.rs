//! M⁻¹ of a tree's mass matrix by its LᵀL factorization (RBDA §6.5, Table 6.3): in the order of
//! the tree, tips first, M = LᵀL has no fill-in (Lᵢⱼ ≠ 0 only for j = i or an ancestor of i),
//! and so has W = L⁻¹; then M⁻¹ = W Wᵀ, a sum over each coordinate k of the outer product of
//! W's column k, nonzero on k and its descendants only. O(n·d²) where a dense Cholesky and
//! inverse are O(n³), d the depth.
//!
//! Book: §7.11 (the mass matrix); RBDA §6.5.

use vectrix_tensor::Scalar;

use crate::DynamicsError;
use crate::multibody::crba::{CoordLists, MASS_PIVOT_EPS};

/// M⁻¹ into `out` (full, column-major n × n) from the symmetric mass matrix `m` (column-major,
/// overwritten: L in its lower triangle, M = LᵀL, and W = L⁻¹ in its strict upper triangle,
/// W_ij at [j, i]), `parent_col` the column tree, `desc` each coordinate with its descendants
/// ([`CoordLists::with_descendants`]), `col` a work column of n numbers.
///
/// # Errors
/// [`DynamicsError::SingularMassMatrix`] when a pivot is at or below 64 n ε max Mᵢᵢ (the test
/// of the dense route; NaN fails too).
pub(crate) fn tree_inverse<T: Scalar>(
    m: &mut [T],
    n: usize,
    parent_col: &[Option<usize>],
    desc: &CoordLists,
    col: &mut [T],
    out: &mut [T],
) -> Result<(), DynamicsError> {
    let at = |i: usize, j: usize| i + j * n;
    let scale = (0..n).map(|i| m[at(i, i)].re().abs()).fold(0.0, f64::max);
    let bound = MASS_PIVOT_EPS * T::eps() * n as f64 * scale;
    // LᵀL in place, k from the tips (RBDA Table 6.3): L_kk = √H_kk, L_ki = H_ki / L_kk for the
    // ancestors i of k, then H_ij −= L_ki L_kj for the ancestors i of k and j of i (or i)
    for k in (0..n).rev() {
        let d = m[at(k, k)];
        // (a NaN pivot fails too)
        if d.re().partial_cmp(&bound) != Some(std::cmp::Ordering::Greater) {
            return Err(DynamicsError::SingularMassMatrix {
                detail: format!("pivot {k} is {:e}, at or below {bound:e} = 64 n ε max Mᵢᵢ", d.re()),
            });
        }
        let lkk = d.sqrt();
        m[at(k, k)] = lkk;
        let mut i = parent_col[k];
        while let Some(ii) = i {
            m[at(k, ii)] /= lkk;
            i = parent_col[ii];
        }
        let mut i = parent_col[k];
        while let Some(ii) = i {
            let lki = m[at(k, ii)];
            let mut j = Some(ii);
            while let Some(jj) = j {
                let lkj = m[at(k, jj)];
                m[at(ii, jj)] -= lki * lkj;
                j = parent_col[jj];
            }
            i = parent_col[ii];
        }
    }
    // W = L⁻¹ (L W = 1), row by row from the root: W_ii = 1/L_ii and, for each ancestor j of i,
    // W_ij = −(Σ_k L_ik W_kj)/L_ii over k on the path from i's parent up to j
    let w = |m: &[T], i: usize, j: usize| if i == j { T::one() / m[at(i, i)] } else { m[at(j, i)] };
    for i in 0..n {
        let lii = m[at(i, i)];
        let mut j = parent_col[i];
        while let Some(jj) = j {
            let mut acc = T::zero();
            let mut k = parent_col[i];
            while let Some(kk) = k {
                acc += m[at(i, kk)] * w(m, kk, jj);
                if kk == jj {
                    break;
                }
                k = parent_col[kk];
            }
            m[at(jj, i)] = -acc / lii;
            j = parent_col[jj];
        }
    }
    // M⁻¹ = W Wᵀ, column k of W (nonzero on k and its descendants) at a time, into the lower
    // triangle, then mirrored
    out.fill(T::zero());
    for k in 0..n {
        let rows = desc.of(k);
        for (c, &a) in col.iter_mut().zip(rows) {
            *c = w(m, a, k);
        }
        for (x, &a) in rows.iter().enumerate() {
            let wak = col[x];
            for (&b, &wbk) in rows[..=x].iter().zip(&col[..=x]) {
                out[at(a, b)] += wak * wbk;
            }
        }
    }
    for j in 0..n {
        for i in j + 1..n {
            out[at(j, i)] = out[at(i, j)];
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Vector3};

    use super::*;
    use crate::multibody::joint::{Joint, Link};
    use crate::multibody::model::Model;

    /// A floating base with a two-pin leg and a ball leg: a branched column tree.
    fn tree() -> Model {
        let j = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
        let link = |parent, joint, offset: [f64; 3], m| {
            Link::new(parent, joint, Vector3::from(offset), m, Vector3::new(0.05, -0.1, 0.2), j)
        };
        let pin = |x: f64, y: f64, z: f64| Joint::Pin { axis: Vector3::new(x, y, z) };
        Model::new(&[
            link(None, Joint::Free, [0.1, 0.2, 0.3], 3.0),
            link(Some(0), pin(0.0, 1.0, 0.0), [0.4, 0.1, -0.2], 1.2),
            link(Some(1), pin(0.3, 0.2, 1.0), [0.0, 0.0, -0.5], 0.7),
            link(Some(0), Joint::Ball, [-0.4, 0.1, -0.2], 0.9),
        ])
        .expect("valid")
    }

    /// M⁻¹ by LᵀL equals nalgebra's inverse of CRBA's M (an independent factorization) to
    /// rounding relative to the condition number (M M⁻¹ = 1 to 1e-12).
    #[test]
    fn tree_inverse_inverts_the_mass_matrix() {
        let m = tree();
        let q = m.integrate(&m.q_neutral, &[0.3, -0.2, 0.5, 0.4, -0.7, 0.2, 0.6, -1.1, 0.3, 0.8, -0.4], 1.0);
        let h = m.crba(&q.expect("valid")).expect("valid");
        let n = h.nrows();
        let mut work = h.clone();
        let mut out = nalgebra::DMatrix::zeros(n, n);
        let desc = CoordLists::with_descendants(&m.parent_col);
        tree_inverse(work.as_mut_slice(), n, &m.parent_col, &desc, &mut vec![0.0; n], out.as_mut_slice())
            .expect("definite");
        let e = &h * &out - nalgebra::DMatrix::<f64>::identity(n, n);
        assert!(e.iter().all(|x| x.abs() <= 1e-12), "M M⁻¹ − 1 = {e}");
        assert!((0..n).all(|i| (0..n).all(|j| out[(i, j)] == out[(j, i)])), "symmetric");
    }

    /// A singular or NaN mass matrix is refused with the pivot named.
    #[test]
    fn tree_inverse_refuses_a_singular_or_nan_matrix() {
        let m = tree();
        let h = m.crba(&m.q_neutral).expect("valid");
        let n = h.nrows();
        let desc = CoordLists::with_descendants(&m.parent_col);
        for bad in [0.0, f64::NAN] {
            let mut work = h.clone();
            work[(n - 1, n - 1)] = bad;
            let r = tree_inverse(
                work.as_mut_slice(),
                n,
                &m.parent_col,
                &desc,
                &mut vec![0.0; n],
                &mut vec![0.0; n * n],
            );
            assert!(matches!(r, Err(DynamicsError::SingularMassMatrix { .. })), "{bad}: {r:?}");
        }
    }
}
