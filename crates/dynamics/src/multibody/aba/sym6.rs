//! A symmetric 6×6 matrix by its 21 upper-triangle entries, row by row: the articulated
//! inertias of ABA's ground passes, which are summed, updated by rank one or three and
//! applied to motion vectors, never transformed.
//!
//! Book: §7.11 (articulated inertias); RBDA §7.3.

use nalgebra::{Matrix3, Vector6};
use vectrix_tensor::Scalar;

use crate::multibody::spatial::BodyInertia;

/// The position in the 21 stored entries of (r, c), either way round.
#[cfg(test)]
const AT: [[usize; 6]; 6] = {
    let mut at = [[0; 6]; 6];
    let mut n = 0;
    let mut r = 0;
    while r < 6 {
        let mut c = r;
        while c < 6 {
            at[r][c] = n;
            at[c][r] = n;
            n += 1;
            c += 1;
        }
        r += 1;
    }
    at
};

/// `f(n, r, c)` for each stored entry n = (r, c), written out so that every position is a
/// constant once inlined (no table, no bounds checks).
#[inline(always)]
fn for_pairs(mut f: impl FnMut(usize, usize, usize)) {
    f(0, 0, 0);
    f(1, 0, 1);
    f(2, 0, 2);
    f(3, 0, 3);
    f(4, 0, 4);
    f(5, 0, 5);
    f(6, 1, 1);
    f(7, 1, 2);
    f(8, 1, 3);
    f(9, 1, 4);
    f(10, 1, 5);
    f(11, 2, 2);
    f(12, 2, 3);
    f(13, 2, 4);
    f(14, 2, 5);
    f(15, 3, 3);
    f(16, 3, 4);
    f(17, 3, 5);
    f(18, 4, 4);
    f(19, 4, 5);
    f(20, 5, 5);
}

/// A symmetric 6×6 [[A, B], [Bᵀ, C]] in (ω, v) ordering by its upper triangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Sym6<T: Scalar>(pub [T; 21]);

impl<T: Scalar> Sym6<T> {
    pub fn zero() -> Self {
        Self([T::zero(); 21])
    }

    /// A rigid body's inertia about its reference point: A = Ī, B = h^×, C = m 1.
    #[inline(always)]
    pub fn from_body(b: &BodyInertia<T>) -> Self {
        let (i, h, m, z) = (&b.I, &b.h, b.m, T::zero());
        Self([
            i[(0, 0)],
            i[(0, 1)],
            i[(0, 2)],
            z,
            -h.z,
            h.y,
            i[(1, 1)],
            i[(1, 2)],
            h.z,
            z,
            -h.x,
            i[(2, 2)],
            -h.y,
            h.x,
            z,
            m,
            z,
            z,
            m,
            z,
            m,
        ])
    }

    /// M x (written out: the entries' positions are constants).
    #[inline(always)]
    pub fn mul(&self, x: &Vector6<T>) -> Vector6<T> {
        let a = &self.0;
        let (x0, x1, x2, x3, x4, x5) = (x[0], x[1], x[2], x[3], x[4], x[5]);
        Vector6::new(
            a[0] * x0 + a[1] * x1 + a[2] * x2 + a[3] * x3 + a[4] * x4 + a[5] * x5,
            a[1] * x0 + a[6] * x1 + a[7] * x2 + a[8] * x3 + a[9] * x4 + a[10] * x5,
            a[2] * x0 + a[7] * x1 + a[11] * x2 + a[12] * x3 + a[13] * x4 + a[14] * x5,
            a[3] * x0 + a[8] * x1 + a[12] * x2 + a[15] * x3 + a[16] * x4 + a[17] * x5,
            a[4] * x0 + a[9] * x1 + a[13] * x2 + a[16] * x3 + a[18] * x4 + a[19] * x5,
            a[5] * x0 + a[10] * x1 + a[14] * x2 + a[17] * x3 + a[19] * x4 + a[20] * x5,
        )
    }

    /// The entry (r, c).
    #[cfg(test)]
    pub fn at(&self, r: usize, c: usize) -> T {
        self.0[AT[r][c]]
    }

    /// self += o − u kᵀ (u kᵀ symmetric: k a multiple of u), entry by entry.
    #[inline(always)]
    pub fn add_minus_outer(&mut self, o: &Self, u: &Vector6<T>, k: &Vector6<T>) {
        for_pairs(|n, r, c| self.0[n] += o.0[n] - u[r] * k[c]);
    }

    /// self += o.
    #[inline(always)]
    pub fn add(&mut self, o: &Self) {
        for (x, y) in self.0.iter_mut().zip(&o.0) {
            *x += *y;
        }
    }

    /// self − U K Uᵀ for the three columns U and a symmetric K (the rank-three update at a
    /// ball; `kt` = K Uᵀ as three rows of six).
    #[inline(always)]
    pub fn minus_rank3(&self, u: &[Vector6<T>; 3], k: &Matrix3<T>) -> Self {
        // kt column j = Σ_l K_jl U_l: UKUᵀ = Σ_j U_j (kt_j)ᵀ
        let kt: [Vector6<T>; 3] =
            core::array::from_fn(|j| u[0] * k[(j, 0)] + u[1] * k[(j, 1)] + u[2] * k[(j, 2)]);
        let mut out = *self;
        for_pairs(|n, r, c| out.0[n] -= u[0][r] * kt[0][c] + u[1][r] * kt[1][c] + u[2][r] * kt[2][c]);
        out
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

    use super::Sym6;
    use crate::multibody::spatial::BodyInertia;

    fn full(s: &Sym6<f64>) -> Matrix6<f64> {
        Matrix6::from_fn(|r, c| s.at(r, c))
    }

    /// The body's 6×6 matrix, its product with a vector and both updates against nalgebra's
    /// 6×6 arithmetic (rounding of 6-term sums of O(1) numbers).
    #[test]
    fn sym6_matches_the_six_by_six_matrix() {
        let body = BodyInertia::from_centre(
            1.3,
            &Vector3::new(0.1, 0.4, -0.3),
            &Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0),
        );
        let s = Sym6::from_body(&body);
        assert_eq!(full(&s), body.matrix());
        let x = Vector6::new(0.3, -1.2, 0.5, 2.0, -0.7, 1.1);
        assert!((s.mul(&x) - body.matrix() * x).norm() <= 1e-14);
        let k = x * 0.25;
        let mut sum = s;
        sum.add_minus_outer(&s, &x, &k);
        let want = body.matrix() * 2.0 - x * k.transpose();
        assert!((full(&sum) - want).norm() <= 1e-14);
        let u =
            [x, Vector6::new(1.0, 0.2, -0.3, 0.4, 0.0, 0.6), Vector6::new(-0.5, 0.1, 0.9, 0.0, 0.3, -0.2)];
        let kk = Matrix3::new(0.5, 0.1, 0.0, 0.1, 0.7, 0.2, 0.0, 0.2, 0.9);
        let um = nalgebra::Matrix6x3::from_columns(&u);
        let want = body.matrix() - um * kk * um.transpose();
        assert!((full(&s.minus_rank3(&u, &kk)) - want).norm() <= 1e-14);
    }
}
