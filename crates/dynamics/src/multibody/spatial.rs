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
