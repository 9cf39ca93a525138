//! Spatial-vector helpers for the tree algorithms, in body coordinates.
//!
//! Internally motion vectors are (ω, v) and force vectors (n, f): the angular part first,
//! as in Featherstone's *Rigid Body Dynamics Algorithms* (RBDA). The book's 6D form (§7.10)
//! orders velocity first; the public API of [`crate::sixd`] follows the book, and nothing of
//! this module's ordering leaks out.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

/// A placement or joint transform from a parent frame P to a child frame C: the passive
/// orientation E = 𝓞_{C/P} and r = r_{C origin/P origin} resolved in P.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Xform {
    pub E: Matrix3<f64>,
    pub r: Vector3<f64>,
}

impl Xform {
    pub fn identity() -> Self {
        Self { E: Matrix3::identity(), r: Vector3::zeros() }
    }

    /// self ∘ inner: first `self` (P→J), then `inner` (J→C).
    #[inline(always)]
    pub fn then(&self, inner: &Xform) -> Xform {
        Xform { E: inner.E * self.E, r: self.r + self.E.tr_mul(&inner.r) }
    }

    /// Xᵀ I X for a symmetric 6×6 inertia in (ω, v) ordering, by 3×3 blocks: rotate
    /// (A, B, C) → (EᵀAE, EᵀBE, EᵀCE), then shift by r: B'' = B' + r^×C',
    /// A'' = A' + r^×B'ᵀ − B'r^× − r^×C'r^× (RBDA §2.12, transformed inertia).
    #[inline(always)]
    pub fn inertia_to_parent(&self, ia: &Matrix6<f64>) -> Matrix6<f64> {
        let a = ia.fixed_view::<3, 3>(0, 0).into_owned();
        let b = ia.fixed_view::<3, 3>(0, 3).into_owned();
        let c = ia.fixed_view::<3, 3>(3, 3).into_owned();
        let et = self.E.transpose();
        let (a1, b1, c1) = (et * a * self.E, et * b * self.E, et * c * self.E);
        let rx = self.r.cross_matrix();
        let rc = rx * c1;
        let b2 = b1 + rc;
        let a2 = a1 + rx * b1.transpose() - b1 * rx - rc * rx;
        let mut out = Matrix6::zeros();
        out.fixed_view_mut::<3, 3>(0, 0).copy_from(&a2);
        out.fixed_view_mut::<3, 3>(0, 3).copy_from(&b2);
        out.fixed_view_mut::<3, 3>(3, 0).copy_from(&b2.transpose());
        out.fixed_view_mut::<3, 3>(3, 3).copy_from(&c1);
        out
    }

    /// Xᵀ f for a force 6-vector (n, f).
    #[inline(always)]
    pub fn force6_to_parent(&self, x: &Vector6<f64>) -> Vector6<f64> {
        let (n, f) = split(x);
        let (np, fp) = self.force_to_parent(&n, &f);
        join(&np, &fp)
    }

    /// Motion vector from P to C: ω_C = Eω, v_C = E(v − r×ω).
    #[inline(always)]
    pub fn motion(&self, w: &Vector3<f64>, v: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        (self.E * w, self.E * (v - self.r.cross(w)))
    }

    /// Force vector from C to P (Xᵀ): f_P = Eᵀf, n_P = Eᵀn + r×f_P.
    #[inline(always)]
    pub fn force_to_parent(&self, n: &Vector3<f64>, f: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let fp = self.E.tr_mul(f);
        (self.E.tr_mul(n) + self.r.cross(&fp), fp)
    }

    /// The 6×6 motion transform ^C X_P in (ω, v) ordering.
    #[cfg(test)]
    pub fn matrix(&self) -> Matrix6<f64> {
        let mut x = Matrix6::zeros();
        x.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.E);
        x.fixed_view_mut::<3, 3>(3, 3).copy_from(&self.E);
        x.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-self.E * self.r.cross_matrix()));
        x
    }
}

/// The spatial inertia of a body about its frame origin, (ω, v) ordering:
/// [[Ī, m c^×], [−m c^×, m 1]], Ī = J_c − m c^× c^×.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BodyInertia {
    pub m: f64,
    /// m c (first moment about the frame origin).
    pub h: Vector3<f64>,
    /// Ī: rotational inertia about the frame origin.
    pub I: Matrix3<f64>,
}

impl BodyInertia {
    pub fn from_centre(m: f64, c: &Vector3<f64>, j_c: &Matrix3<f64>) -> Self {
        let cx = c.cross_matrix();
        Self { m, h: c * m, I: j_c - cx * cx * m }
    }

    /// I·(ω, v) = (Īω + h×v, m v − h×ω).
    #[inline(always)]
    pub fn apply(&self, w: &Vector3<f64>, v: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        (self.I * w + self.h.cross(v), v * self.m - self.h.cross(w))
    }

    pub fn matrix(&self) -> Matrix6<f64> {
        let hx = self.h.cross_matrix();
        let mut out = Matrix6::zeros();
        out.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.I);
        out.fixed_view_mut::<3, 3>(0, 3).copy_from(&hx);
        out.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-hx));
        out.fixed_view_mut::<3, 3>(3, 3).copy_from(&(Matrix3::identity() * self.m));
        out
    }
}

/// Motion cross product (ω, v) ×m (ω₂, v₂) = (ω×ω₂, ω×v₂ + v×ω₂).
#[inline(always)]
pub(crate) fn cross_motion(
    w: &Vector3<f64>,
    v: &Vector3<f64>,
    w2: &Vector3<f64>,
    v2: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    (w.cross(w2), w.cross(v2) + v.cross(w2))
}

/// Force cross product (ω, v) ×f (n, f) = (ω×n + v×f, ω×f).
#[inline(always)]
pub(crate) fn cross_force(
    w: &Vector3<f64>,
    v: &Vector3<f64>,
    n: &Vector3<f64>,
    f: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    (w.cross(n) + v.cross(f), w.cross(f))
}

#[inline(always)]
pub(crate) fn join(a: &Vector3<f64>, b: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

#[inline(always)]
pub(crate) fn split(x: &Vector6<f64>) -> (Vector3<f64>, Vector3<f64>) {
    (Vector3::new(x[0], x[1], x[2]), Vector3::new(x[3], x[4], x[5]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The block formula for Xᵀ I X equals the 6×6 product.
    #[test]
    fn inertia_to_parent_matches_matrix_product() {
        let x = Xform {
            E: nalgebra::Rotation3::from_scaled_axis(Vector3::new(0.3, -0.7, 0.4)).into_inner(),
            r: Vector3::new(0.5, -0.2, 0.9),
        };
        let i = BodyInertia::from_centre(
            1.3,
            &Vector3::new(0.1, 0.4, -0.3),
            &Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0),
        )
        .matrix();
        let want = x.matrix().transpose() * i * x.matrix();
        assert!((x.inertia_to_parent(&i) - want).norm() < 1e-13 * want.norm());
        let f = Vector6::new(0.1, 0.2, 0.3, -0.4, 0.5, -0.6);
        assert!((x.force6_to_parent(&f) - x.matrix().transpose() * f).norm() < 1e-14);
    }
}
