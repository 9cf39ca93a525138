//! Articulated-body inertias for ABA's inward pass by their 3×3 blocks, never as 6×6 matrices:
//! the symmetric Iᴬ = [[A, B], [Bᵀ, C]] in (ω, v) ordering (A, C symmetric), its rank-one and
//! rank-three updates at a joint, and its transform to the parent, XᵀIᴬX, as a rotation of the
//! blocks followed by a shift. A pin about a coordinate axis behind a placement without
//! rotation turns only two rows and columns of each block (24 products per block instead of
//! 54), and a shift costs cross products only (54 products instead of 108).
//!
//! Book: §7.11 (ABA); RBDA §2.12 (transformed inertia), Table 7.1.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Vector3, Vector6};
use vectrix_tensor::Scalar;

use super::segment::Turn;
use super::spatial::{BodyInertia, Xform, cross_columns, join};

/// A symmetric spatial inertia [[A, B], [Bᵀ, C]] in (ω, v) ordering about a frame's origin
/// (A and C symmetric, stored whole).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Articulated<T: Scalar> {
    pub A: Matrix3<T>,
    pub B: Matrix3<T>,
    pub C: Matrix3<T>,
}

impl<T: Scalar> Articulated<T> {
    pub fn zero() -> Self {
        Self { A: Matrix3::zeros(), B: Matrix3::zeros(), C: Matrix3::zeros() }
    }

    /// A rigid body's inertia: A = Ī, B = h^×, C = m 1.
    #[inline(always)]
    pub fn from_body(b: &BodyInertia<T>) -> Self {
        Self { A: b.I, B: b.h.cross_matrix(), C: Matrix3::from_diagonal_element(b.m) }
    }

    /// I·(ω, v) = (Aω + Bv, Bᵀω + Cv).
    #[inline(always)]
    pub fn apply(&self, w: &Vector3<T>, v: &Vector3<T>) -> (Vector3<T>, Vector3<T>) {
        (self.A * w + self.B * v, self.B.tr_mul(w) + self.C * v)
    }

    /// I·m for a motion 6-vector.
    #[inline(always)]
    pub fn apply6(&self, m: &Vector6<T>) -> Vector6<T> {
        let (w, v) = (Vector3::new(m[0], m[1], m[2]), Vector3::new(m[3], m[4], m[5]));
        let (n, f) = self.apply(&w, &v);
        join(&n, &f)
    }

    #[inline(always)]
    pub fn add(&mut self, o: &Self) {
        self.A += o.A;
        self.B += o.B;
        self.C += o.C;
    }

    /// Iᵃ = I − U D⁻¹ Uᵀ for one column U = (uw, uv) and its pivot's inverse (the symmetric
    /// blocks by their upper triangles, mirrored).
    #[inline(always)]
    pub fn sub_rank1(&self, uw: &Vector3<T>, uv: &Vector3<T>, dinv: T) -> Self {
        let (kw, kv) = (uw * dinv, uv * dinv);
        Self {
            A: sym3(|r, c| self.A[(r, c)] - kw[r] * uw[c]),
            B: self.B - kw * uv.transpose(),
            C: sym3(|r, c| self.C[(r, c)] - kv[r] * uv[c]),
        }
    }

    /// Iᵃ = I − U K Uᵀ for three columns U = [Uw; Uv] and a symmetric K = D⁻¹ (or D⁺).
    #[inline(always)]
    pub fn sub_rank3(&self, uw: &Matrix3<T>, uv: &Matrix3<T>, k: &Matrix3<T>) -> Self {
        let (kw, kv) = (uw * k, uv * k);
        let dot = |m: &Matrix3<T>, r: usize, u: &Matrix3<T>, c: usize| {
            m[(r, 0)] * u[(c, 0)] + m[(r, 1)] * u[(c, 1)] + m[(r, 2)] * u[(c, 2)]
        };
        Self {
            A: sym3(|r, c| self.A[(r, c)] - dot(&kw, r, uw, c)),
            B: self.B - kw * uv.transpose(),
            C: sym3(|r, c| self.C[(r, c)] - dot(&kv, r, uv, c)),
        }
    }

    /// The Frobenius norm of the 6×6 matrix, √(|A|² + 2|B|² + |C|²).
    pub fn norm(&self) -> T {
        (self.A.norm_squared() + self.B.norm_squared() * T::lit(2.0) + self.C.norm_squared()).sqrt()
    }

    /// XᵀIX for the child-to-parent transform `x` (E = 𝓞_{C/P}, r in P) whose rotation is
    /// `turn`: (A, B, C) → (EᵀAE, EᵀBE, EᵀCE), then the shift by r (RBDA §2.12):
    /// B'' = B' + r^×C', A'' = A' + r^×B'ᵀ − B'r^× − r^×C'r^×, C'' = C'.
    #[inline(always)]
    pub fn in_parent(&self, x: &Xform<T>, turn: Turn) -> Self {
        let rotated = match turn {
            Turn::None => *self,
            // constant indices in each arm, so the turned blocks are built on registers
            Turn::Plane(axis) => match axis {
                0 => self.turn_plane_all::<1, 2>(&x.E),
                1 => self.turn_plane_all::<2, 0>(&x.E),
                _ => self.turn_plane_all::<0, 1>(&x.E),
            },
            Turn::General => {
                let (e, et) = (&x.E, x.E.transpose());
                let sym = |m: &Matrix3<T>| {
                    let em = et * m;
                    sym3(|r, c| em[(r, 0)] * e[(0, c)] + em[(r, 1)] * e[(1, c)] + em[(r, 2)] * e[(2, c)])
                };
                Self { A: sym(&self.A), B: et * self.B * e, C: sym(&self.C) }
            }
        };
        rotated.shift(&x.r)
    }

    /// (EᵀAE, EᵀBE, EᵀCE) for a `Turn::Plane` that mixes rows and columns (I1, I2).
    #[inline(always)]
    fn turn_plane_all<const I1: usize, const I2: usize>(&self, e: &Matrix3<T>) -> Self {
        let (c, s) = (e[(I1, I1)], e[(I1, I2)]);
        Self {
            A: turn_plane_sym(&self.A, I1, I2, c, s),
            B: turn_plane(&self.B, I1, I2, c, s),
            C: turn_plane_sym(&self.C, I1, I2, c, s),
        }
    }

    /// The shift by r: with K = r^×C, P = B r^× (so r^×Bᵀ = −Pᵀ) and K r^× = r^×C r^×
    /// (symmetric): B'' = B + K, A'' = A − P − Pᵀ − K r^× (by its upper triangle, mirrored),
    /// all by cross products of columns and rows.
    #[inline(always)]
    fn shift(&self, r: &Vector3<T>) -> Self {
        // K = r^× C: column k is r × C_k
        let K = cross_columns(r, &self.C);
        // P = B r^×: row j is B_j × r (a row m r^× = (m × r)ᵀ)
        let P = rows_cross(&self.B, r);
        // (K r^×)_{jk} = (K_j × r)_k
        let kr = |j: usize, k: usize| {
            let (a, b, c) = (K[(j, 0)], K[(j, 1)], K[(j, 2)]);
            match k {
                0 => b * r.z - c * r.y,
                1 => c * r.x - a * r.z,
                _ => a * r.y - b * r.x,
            }
        };
        Self { A: sym3(|j, k| self.A[(j, k)] - P[(j, k)] - P[(k, j)] - kr(j, k)), B: self.B + K, C: self.C }
    }

    /// Column k of the 6×6 matrix (k < 3: (A_k, row k of B); else (B_{k−3}, C_{k−3})).
    #[inline(always)]
    pub fn column(&self, k: usize) -> (Vector3<T>, Vector3<T>) {
        if k < 3 {
            (self.A.column(k).into_owned(), self.B.row(k).transpose())
        } else {
            (self.B.column(k - 3).into_owned(), self.C.column(k - 3).into_owned())
        }
    }
}

/// EᵀME for E = 1 except E[i1][i1] = E[i2][i2] = c, E[i1][i2] = s, E[i2][i1] = −s: columns
/// (i1, i2) of M E, then rows (i1, i2) of Eᵀ(M E).
#[inline(always)]
fn turn_plane<T: Scalar>(m: &Matrix3<T>, i1: usize, i2: usize, c: T, s: T) -> Matrix3<T> {
    let mut r = *m;
    for row in 0..3 {
        let (a, b) = (m[(row, i1)], m[(row, i2)]);
        r[(row, i1)] = a * c - b * s;
        r[(row, i2)] = a * s + b * c;
    }
    for col in 0..3 {
        let (a, b) = (r[(i1, col)], r[(i2, col)]);
        r[(i1, col)] = c * a - s * b;
        r[(i2, col)] = s * a + c * b;
    }
    r
}

/// EᵀME for a symmetric M and the E of [`turn_plane`], by the six numbers of its upper
/// triangle: the third axis k keeps M_kk, its pair (M_{k,i1}, M_{k,i2}) turns once, and the
/// (i1, i2) block turns on both sides.
#[inline(always)]
fn turn_plane_sym<T: Scalar>(m: &Matrix3<T>, i1: usize, i2: usize, c: T, s: T) -> Matrix3<T> {
    let k = 3 - i1 - i2;
    let (a, b) = (m[(k, i1)], m[(k, i2)]);
    let (p, q, t) = (m[(i1, i1)], m[(i1, i2)], m[(i2, i2)]);
    // M E on the block: rows (i1, i2) of columns (i1, i2)
    let (r11, r12) = (p * c - q * s, p * s + q * c);
    let (r21, r22) = (q * c - t * s, q * s + t * c);
    let mut out = Matrix3::zeros();
    out[(k, k)] = m[(k, k)];
    let (ki1, ki2) = (a * c - b * s, a * s + b * c);
    out[(k, i1)] = ki1;
    out[(i1, k)] = ki1;
    out[(k, i2)] = ki2;
    out[(i2, k)] = ki2;
    out[(i1, i1)] = c * r11 - s * r21;
    let o21 = s * r11 + c * r21;
    out[(i2, i1)] = o21;
    out[(i1, i2)] = o21;
    out[(i2, i2)] = s * r12 + c * r22;
    out
}

/// A symmetric 3×3 from its upper triangle, `f(r, c)` for r ≤ c, mirrored.
#[inline(always)]
fn sym3<T: Scalar>(f: impl Fn(usize, usize) -> T) -> Matrix3<T> {
    let (a, b, c, d, e, g) = (f(0, 0), f(0, 1), f(0, 2), f(1, 1), f(1, 2), f(2, 2));
    Matrix3::new(a, b, c, b, d, e, c, e, g)
}

/// M r^×: row j is M_j × r.
#[inline(always)]
fn rows_cross<T: Scalar>(m: &Matrix3<T>, r: &Vector3<T>) -> Matrix3<T> {
    let row = |j: usize| Vector3::new(m[(j, 0)], m[(j, 1)], m[(j, 2)]).cross(r);
    let (a, b, c) = (row(0), row(1), row(2));
    Matrix3::new(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z)
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Matrix6, Rotation3, Vector3, Vector6};

    use super::Articulated;
    use crate::multibody::segment::Turn;
    use crate::multibody::spatial::{BodyInertia, Xform};

    fn full(i: &Articulated<f64>) -> Matrix6<f64> {
        let mut m = Matrix6::zeros();
        m.fixed_view_mut::<3, 3>(0, 0).copy_from(&i.A);
        m.fixed_view_mut::<3, 3>(0, 3).copy_from(&i.B);
        m.fixed_view_mut::<3, 3>(3, 0).copy_from(&i.B.transpose());
        m.fixed_view_mut::<3, 3>(3, 3).copy_from(&i.C);
        m
    }

    /// A symmetric positive 6×6 with every block full: a body's inertia after a rank-one
    /// update (an articulated inertia).
    fn sample() -> Articulated<f64> {
        let body = BodyInertia::from_centre(
            1.3,
            &Vector3::new(0.1, 0.4, -0.3),
            &Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0),
        );
        let i = Articulated::from_body(&body);
        let (uw, uv) = i.column(4);
        i.sub_rank1(&uw, &uv, 0.5 / i.C[(1, 1)])
    }

    /// XᵀIX by blocks equals the 6×6 product with X = [[E, 0], [−E r^×, E]] (RBDA (2.24)),
    /// for a general rotation and for turns about each coordinate axis, either way round;
    /// rounding of 6-term sums of O(10) numbers.
    #[test]
    fn in_parent_matches_the_six_by_six_product() {
        let i = sample();
        let r = Vector3::new(0.5, -0.2, 0.9);
        let mut cases =
            vec![(Rotation3::from_scaled_axis(Vector3::new(0.3, -0.7, 0.4)).into_inner(), Turn::General)];
        for (k, axis) in [Vector3::x(), Vector3::y(), Vector3::z()].into_iter().enumerate() {
            for sign in [1.0, -1.0] {
                // the passive E = 𝓡(σ ê, θ)ᵀ of the joint
                let e = Rotation3::from_scaled_axis(axis * (0.8 * sign)).into_inner().transpose();
                cases.push((e, Turn::Plane(k)));
            }
        }
        cases.push((Matrix3::identity(), Turn::None));
        for (e, turn) in cases {
            let x = Xform { E: e, r };
            let want = x.matrix().transpose() * full(&i) * x.matrix();
            let got = full(&i.in_parent(&x, turn));
            assert!((got - want).norm() <= 1e-13 * want.norm(), "{turn:?}: {}", (got - want).norm());
        }
        let v = Vector6::new(0.1, 0.2, 0.3, -0.4, 0.5, -0.6);
        assert!((i.apply6(&v) - full(&i) * v).norm() <= 1e-14 * (full(&i) * v).norm());
    }
}
