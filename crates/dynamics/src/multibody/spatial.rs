//! Spatial-vector helpers for the tree algorithms, generic over the scalar.
//!
//! Internally motion vectors are (ω, v) and force vectors (n, f): the angular part first,
//! as in Featherstone's *Rigid Body Dynamics Algorithms* (RBDA). The book's 6D form (§7.10)
//! orders velocity first; the public API of [`crate::sixd`] follows the book, and nothing of
//! this module's ordering leaks out.
#![allow(non_snake_case)]

#[cfg(test)]
use nalgebra::Matrix6;
use nalgebra::{Matrix3, Vector3, Vector6};
use vectrix_tensor::Scalar;

/// A placement or joint transform from a parent frame P to a child frame C: the passive
/// orientation E = 𝓞_{C/P} and r = r_{C origin/P origin} resolved in P.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Xform<T: Scalar> {
    pub E: Matrix3<T>,
    pub r: Vector3<T>,
}

impl<T: Scalar> Xform<T> {
    pub fn identity() -> Self {
        Self { E: Matrix3::identity(), r: Vector3::zeros() }
    }

    /// self ∘ inner: first `self` (P→J), then `inner` (J→C).
    #[inline(always)]
    pub fn then(&self, inner: &Xform<T>) -> Xform<T> {
        Xform { E: inner.E * self.E, r: self.r + self.E.tr_mul(&inner.r) }
    }

    /// Xᵀ f for a force 6-vector (n, f).
    #[cfg(test)]
    pub fn force6_to_parent(&self, x: &Vector6<T>) -> Vector6<T> {
        let (n, f) = split(x);
        let (np, fp) = self.force_to_parent(&n, &f);
        join(&np, &fp)
    }

    /// Motion vector from P to C: ω_C = Eω, v_C = E(v − r×ω).
    #[inline(always)]
    pub fn motion(&self, w: &Vector3<T>, v: &Vector3<T>) -> (Vector3<T>, Vector3<T>) {
        (self.E * w, self.E * (v - self.r.cross(w)))
    }

    /// Force vector from C to P (Xᵀ): f_P = Eᵀf, n_P = Eᵀn + r×f_P. For a segment's ground
    /// placement (E = 𝓞_{i/G}, r its origin in the ground) this moves a wrench about the
    /// segment's origin in its axes to the ground's axes about the ground's origin.
    #[inline(always)]
    pub fn force_to_parent(&self, n: &Vector3<T>, f: &Vector3<T>) -> (Vector3<T>, Vector3<T>) {
        let fp = self.E.tr_mul(f);
        (self.E.tr_mul(n) + self.r.cross(&fp), fp)
    }

    /// The 6×6 motion transform ^C X_P in (ω, v) ordering.
    #[cfg(test)]
    pub fn matrix(&self) -> Matrix6<T> {
        let mut x = Matrix6::zeros();
        x.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.E);
        x.fixed_view_mut::<3, 3>(3, 3).copy_from(&self.E);
        x.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-self.E * self.r.cross_matrix()));
        x
    }
}

impl Xform<f64> {
    /// The same transform with every number converted from f64.
    pub fn cast<U: Scalar>(&self) -> Xform<U> {
        Xform { E: self.E.map(U::lit), r: self.r.map(U::lit) }
    }
}

/// The spatial inertia of a body about a point, (ω, v) ordering:
/// [[Ī, h^×], [−h^×, m 1]], with h = m c (first moment) and Ī the rotational inertia about
/// the point. Sums of such inertias about the same point are inertias (composite bodies).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BodyInertia<T: Scalar> {
    pub m: T,
    /// m c (first moment about the reference point).
    pub h: Vector3<T>,
    /// Ī: rotational inertia about the reference point.
    pub I: Matrix3<T>,
}

impl<T: Scalar> BodyInertia<T> {
    pub fn zero() -> Self {
        Self { m: T::zero(), h: Vector3::zeros(), I: Matrix3::zeros() }
    }

    /// From m, the centre c and J_c (parallel-axis theorem, book (6.4.x)):
    /// Ī = J_c − m c^× c^×.
    pub fn from_centre(m: T, c: &Vector3<T>, j_c: &Matrix3<T>) -> Self {
        let cx = c.cross_matrix();
        Self { m, h: c * m, I: j_c - cx * cx * m }
    }

    /// I·(ω, v) = (Īω + h×v, m v − h×ω).
    #[inline(always)]
    pub fn apply(&self, w: &Vector3<T>, v: &Vector3<T>) -> (Vector3<T>, Vector3<T>) {
        (self.I * w + self.h.cross(v), v * self.m - self.h.cross(w))
    }

    /// I·m for a motion 6-vector.
    #[inline(always)]
    pub fn apply6(&self, m: &Vector6<T>) -> Vector6<T> {
        let (w, v) = split(m);
        let (n, f) = self.apply(&w, &v);
        join(&n, &f)
    }

    #[inline(always)]
    pub fn add(&mut self, o: &BodyInertia<T>) {
        self.m += o.m;
        self.h += o.h;
        self.I += o.I;
    }

    /// The inertia about the ground origin, components in the ground frame, of a body of mass
    /// m with centre c and J_c (link components) whose frame has orientation E = 𝓞_{B/G}
    /// (passive; R = Eᵀ has the body axes as columns) and origin p: with c' = p + Rc,
    /// Ī' = R J_c Rᵀ + m(|c'|² 1 − c'c'ᵀ) (parallel axes, book (6.4.x)), h' = m c'.
    ///
    /// `form` says how J_c is turned (known when the model is built, [`CentreForm::of`]).
    #[inline(always)]
    pub fn from_centre_in_ground(
        m: T,
        c: &Vector3<T>,
        j_c: &Matrix3<T>,
        form: &CentreForm<T>,
        E: &Matrix3<T>,
        p: &Vector3<T>,
    ) -> Self {
        let cw = p + E.tr_mul(c);
        // R J_c Rᵀ, symmetric: its six entries d(i, k)
        let d: [[T; 3]; 3] = match form {
            // = Eᵀ(J_c E): column i of E · column k of J_c E; a diagonal J_c scales E's rows
            CentreForm::Diagonal => {
                let mut je = *E;
                for r in 0..3 {
                    let l = j_c[(r, r)];
                    for k in 0..3 {
                        je[(r, k)] *= l;
                    }
                }
                gram(E, &je)
            }
            CentreForm::General => gram(E, &(j_c * E)),
            // = W Wᵀ, W = Eᵀ L for J_c = L Lᵀ (L lower triangular): 27 products and sums to
            // form W where J_c E takes 45
            CentreForm::Factor(l) => {
                let w = |i: usize| {
                    let (e0, e1, e2) = (E[(0, i)], E[(1, i)], E[(2, i)]);
                    [
                        e0 * l[(0, 0)] + e1 * l[(1, 0)] + e2 * l[(2, 0)],
                        e1 * l[(1, 1)] + e2 * l[(2, 1)],
                        e2 * l[(2, 2)],
                    ]
                };
                let (w0, w1, w2) = (w(0), w(1), w(2));
                let dot = |a: &[T; 3], b: &[T; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
                let (d01, d02, d12) = (dot(&w0, &w1), dot(&w0, &w2), dot(&w1, &w2));
                [[dot(&w0, &w0), d01, d02], [d01, dot(&w1, &w1), d12], [d02, d12, dot(&w2, &w2)]]
            }
        };
        let mc = cw * m;
        let s = mc.dot(&cw);
        let (a01, a02, a12) = (d[0][1] - mc.x * cw.y, d[0][2] - mc.x * cw.z, d[1][2] - mc.y * cw.z);
        let (a00, a11, a22) =
            (d[0][0] + s - mc.x * cw.x, d[1][1] + s - mc.y * cw.y, d[2][2] + s - mc.z * cw.z);
        Self { m, h: mc, I: Matrix3::new(a00, a01, a02, a01, a11, a12, a02, a12, a22) }
    }

    #[cfg(test)]
    pub fn matrix(&self) -> Matrix6<T> {
        let hx = self.h.cross_matrix();
        let mut out = Matrix6::zeros();
        out.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.I);
        out.fixed_view_mut::<3, 3>(0, 3).copy_from(&hx);
        out.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-hx));
        out.fixed_view_mut::<3, 3>(3, 3).copy_from(&(Matrix3::identity() * self.m));
        out
    }
}

/// The six entries d(i, k) = Σ_r E_ri A_rk of the symmetric Eᵀ A (A = J_c E), as rows.
#[inline(always)]
fn gram<T: Scalar>(E: &Matrix3<T>, a: &Matrix3<T>) -> [[T; 3]; 3] {
    let d = |i: usize, k: usize| E[(0, i)] * a[(0, k)] + E[(1, i)] * a[(1, k)] + E[(2, i)] * a[(2, k)];
    let (d01, d02, d12) = (d(0, 1), d(0, 2), d(1, 2));
    [[d(0, 0), d01, d02], [d01, d(1, 1), d12], [d02, d12, d(2, 2)]]
}

/// How [`BodyInertia::from_centre_in_ground`] turns a body's J_c into the ground, chosen when
/// the model is built: a diagonal J_c (principal link axes) by scaling rows; a positive
/// definite one by its Cholesky factor L (J_c = L Lᵀ, R J_c Rᵀ = W Wᵀ with W = Eᵀ L); any
/// other (a singular J_c: a point mass, a thin rod) as the product Eᵀ(J_c E).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum CentreForm<T: Scalar> {
    Diagonal,
    Factor(Matrix3<T>),
    General,
}

impl CentreForm<f64> {
    /// The form for J_c: `Factor` when every Cholesky pivot is positive (the
    /// factorization of a positive definite matrix is backward stable, so W Wᵀ is R J_c Rᵀ
    /// to rounding of J_c's size), else `General`.
    pub fn of(j_c: &Matrix3<f64>) -> Self {
        if j_c[(0, 1)] == 0.0 && j_c[(0, 2)] == 0.0 && j_c[(1, 2)] == 0.0 {
            return Self::Diagonal;
        }
        super::singular::spd_cholesky3(j_c, 0.0).map_or(Self::General, Self::Factor)
    }

    /// The same form with every number converted exactly from f64.
    pub fn cast<U: Scalar>(&self) -> CentreForm<U> {
        match self {
            Self::Diagonal => CentreForm::Diagonal,
            Self::Factor(l) => CentreForm::Factor(l.map(U::lit)),
            Self::General => CentreForm::General,
        }
    }
}

impl BodyInertia<f64> {
    /// The same inertia with every number converted from f64.
    pub fn cast<U: Scalar>(&self) -> BodyInertia<U> {
        BodyInertia { m: U::lit(self.m), h: self.h.map(U::lit), I: self.I.map(U::lit) }
    }
}

/// Motion cross product (ω, v) ×m (ω₂, v₂) = (ω×ω₂, ω×v₂ + v×ω₂).
#[inline(always)]
pub(crate) fn cross_motion<T: Scalar>(
    w: &Vector3<T>,
    v: &Vector3<T>,
    w2: &Vector3<T>,
    v2: &Vector3<T>,
) -> (Vector3<T>, Vector3<T>) {
    (w.cross(w2), w.cross(v2) + v.cross(w2))
}

/// Force cross product (ω, v) ×f (n, f) = (ω×n + v×f, ω×f).
#[inline(always)]
pub(crate) fn cross_force<T: Scalar>(
    w: &Vector3<T>,
    v: &Vector3<T>,
    n: &Vector3<T>,
    f: &Vector3<T>,
) -> (Vector3<T>, Vector3<T>) {
    (w.cross(n) + v.cross(f), w.cross(f))
}

/// Motion cross product of 6-vectors, m₁ ×m m₂.
#[inline(always)]
pub(crate) fn cross_motion6<T: Scalar>(m1: &Vector6<T>, m2: &Vector6<T>) -> Vector6<T> {
    let (w, v) = split(m1);
    let (w2, v2) = split(m2);
    let (a, b) = cross_motion(&w, &v, &w2, &v2);
    join(&a, &b)
}

/// Force cross product of 6-vectors, m ×f f.
#[inline(always)]
pub(crate) fn cross_force6<T: Scalar>(m: &Vector6<T>, f: &Vector6<T>) -> Vector6<T> {
    let (w, v) = split(m);
    let (n, ff) = split(f);
    let (a, b) = cross_force(&w, &v, &n, &ff);
    join(&a, &b)
}

/// r^× M: column k is r × M_k.
#[inline(always)]
pub(crate) fn cross_columns<T: Scalar>(r: &Vector3<T>, m: &Matrix3<T>) -> Matrix3<T> {
    let c = |k: usize| r.cross(&m.column(k).into_owned());
    Matrix3::from_columns(&[c(0), c(1), c(2)])
}

#[inline(always)]
pub(crate) fn join<T: Scalar>(a: &Vector3<T>, b: &Vector3<T>) -> Vector6<T> {
    Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

#[inline(always)]
pub(crate) fn split<T: Scalar>(x: &Vector6<T>) -> (Vector3<T>, Vector3<T>) {
    (Vector3::new(x[0], x[1], x[2]), Vector3::new(x[3], x[4], x[5]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Xᵀ f by blocks equals the 6×6 product.
    #[test]
    fn force_to_parent_matches_matrix_product() {
        let x = Xform {
            E: nalgebra::Rotation3::from_scaled_axis(Vector3::new(0.3, -0.7, 0.4)).into_inner(),
            r: Vector3::new(0.5, -0.2, 0.9),
        };
        let f = Vector6::new(0.1, 0.2, 0.3, -0.4, 0.5, -0.6);
        assert!((x.force6_to_parent(&f) - x.matrix().transpose() * f).norm() < 1e-14);
    }

    /// The world inertia of a placed body equals Xᵀ I X with X the ground-to-body transform.
    #[test]
    fn to_world_matches_transformed_inertia() {
        let e = nalgebra::Rotation3::from_scaled_axis(Vector3::new(-0.4, 0.9, 0.2)).into_inner();
        let p = Vector3::new(0.7, -1.1, 0.35);
        let (c, j) =
            (Vector3::new(-0.2, 0.3, 0.15), Matrix3::new(1.0, 0.05, -0.1, 0.05, 1.5, 0.02, -0.1, 0.02, 0.8));
        let body = BodyInertia::from_centre(2.1, &c, &j);
        let x = Xform { E: e, r: p };
        let want = x.matrix().transpose() * body.matrix() * x.matrix();
        // a positive definite J_c by its Cholesky factor, and as the product
        assert!(matches!(CentreForm::of(&j), CentreForm::Factor(_)));
        for form in [CentreForm::of(&j), CentreForm::General] {
            let got = BodyInertia::from_centre_in_ground(2.1, &c, &j, &form, &e, &p).matrix();
            assert!((got - want).norm() < 1e-14 * want.norm(), "{form:?}: {}", (got - want).norm());
        }
        // a singular J_c off its principal axes (a thin rod along (x̂ − ŷ)/√2: no moment about
        // its own axis; its second pivot is 0 exactly) has no Cholesky factor and goes by the
        // product, which is still exact
        let rod = Matrix3::new(0.25, 0.25, 0.0, 0.25, 0.25, 0.0, 0.0, 0.0, 0.5);
        assert_eq!(CentreForm::of(&rod), CentreForm::General);
        let want = x.matrix().transpose() * BodyInertia::from_centre(2.1, &c, &rod).matrix() * x.matrix();
        let got = BodyInertia::from_centre_in_ground(2.1, &c, &rod, &CentreForm::of(&rod), &e, &p).matrix();
        assert!((got - want).norm() < 1e-14 * want.norm(), "{}", (got - want).norm());
        // a diagonal J_c by its rows
        let d = Matrix3::from_diagonal(&Vector3::new(1.0, 1.5, 0.8));
        let want = x.matrix().transpose() * BodyInertia::from_centre(2.1, &c, &d).matrix() * x.matrix();
        let got = BodyInertia::from_centre_in_ground(2.1, &c, &d, &CentreForm::of(&d), &e, &p).matrix();
        assert!((got - want).norm() < 1e-14 * want.norm(), "{}", (got - want).norm());
    }
}
