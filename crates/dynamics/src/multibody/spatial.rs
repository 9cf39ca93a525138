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
    #[inline(always)]
    pub fn from_centre_in_ground(
        m: T,
        c: &Vector3<T>,
        j_c: &Matrix3<T>,
        diagonal: bool,
        E: &Matrix3<T>,
        p: &Vector3<T>,
    ) -> Self {
        let cw = p + E.tr_mul(c);
        // R J_c Rᵀ = Eᵀ(J_c E), symmetric: six entries (column i of E · column k of J_c E);
        // a diagonal J_c (principal link axes, `diagonal`: known when the model is built)
        // scales the rows of E
        let je = if diagonal {
            let mut je = *E;
            for r in 0..3 {
                let l = j_c[(r, r)];
                for k in 0..3 {
                    je[(r, k)] *= l;
                }
            }
            je
        } else {
            j_c * E
        };
        let d = |i: usize, k: usize| E[(0, i)] * je[(0, k)] + E[(1, i)] * je[(1, k)] + E[(2, i)] * je[(2, k)];
        let mc = cw * m;
        let s = mc.dot(&cw);
        let (a01, a02, a12) = (d(0, 1) - mc.x * cw.y, d(0, 2) - mc.x * cw.z, d(1, 2) - mc.y * cw.z);
        let (a00, a11, a22) =
            (d(0, 0) + s - mc.x * cw.x, d(1, 1) + s - mc.y * cw.y, d(2, 2) + s - mc.z * cw.z);
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
        let got = BodyInertia::from_centre_in_ground(2.1, &c, &j, false, &e, &p).matrix();
        assert!((got - want).norm() < 1e-14 * want.norm(), "{}", (got - want).norm());
        // a diagonal J_c by its rows
        let d = Matrix3::from_diagonal(&Vector3::new(1.0, 1.5, 0.8));
        let want = x.matrix().transpose() * BodyInertia::from_centre(2.1, &c, &d).matrix() * x.matrix();
        let got = BodyInertia::from_centre_in_ground(2.1, &c, &d, true, &e, &p).matrix();
        assert!((got - want).norm() < 1e-14 * want.norm(), "{}", (got - want).norm());
    }
}
