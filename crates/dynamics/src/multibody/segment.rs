//! The elementary segments a tree is expanded into: one per link, plus a massless intermediate
//! for each extra elementary joint of a compound joint (collar, slot, free), with the numbers
//! every tree algorithm reads (placement, joint, coordinates, inertia) and the flags of their
//! exact shortcuts.
//!
//! Book: §1.5 (joints), §7.11 (chains).

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::Scalar;

use super::joint::Elem;
use super::spatial::{BodyInertia, CentreForm, Xform};

/// One elementary segment (a link, or a massless intermediate of a compound joint).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Segment<T: Scalar> {
    pub parent: Option<usize>,
    pub placement: Xform<T>,
    pub elem: Elem<T>,
    pub qi: usize,
    pub vi: usize,
    pub inertia: BodyInertia<T>,
    /// The same body as mass m (in `inertia`), centre c and J_c, link components.
    pub com: Vector3<T>,
    pub j_c: Matrix3<T>,
    /// How `BodyInertia::from_centre_in_ground` turns J_c (diagonal, by its Cholesky factor,
    /// or as a product).
    pub j_c_form: CentreForm<T>,
    /// Zero mass and zero inertia (intermediate segments of compound joints, massless links).
    pub massless: bool,
    /// Scales for ABA's singularity tests (real numbers, configuration-independent): the
    /// total mass of the subtree, Σ tr J_c over its bodies, and |c| of the own body (0 when
    /// massless).
    pub sub_mass: f64,
    pub sub_trace: f64,
    pub own_reach: f64,
    /// The placement has no rotation (𝓞_{J/P} = 1 exactly): composing with it is a shift.
    pub placement_is_shift: bool,
    /// A pin or slider along a coordinate axis: (axis index, negative direction).
    pub coord_axis: Option<(usize, bool)>,
    /// The parent's orientation is the ground's exactly, whatever q (every segment from the
    /// ground to the parent is a slider or a weld behind a placement without rotation: the
    /// sliders of a free joint): composing with the parent is then a shift.
    pub parent_upright: bool,
    /// The kind of rotation of the joint-to-parent transform.
    pub turn: Turn,
}

impl<T: Scalar> Segment<T> {
    /// The body's inertia about the ground origin, ground components, when the segment's
    /// ground-to-segment transform is `w` (`BodyInertia::from_centre_in_ground` with this
    /// segment's mass, centre and J_c).
    #[inline(always)]
    pub fn ground_inertia(&self, w: &Xform<T>) -> BodyInertia<T> {
        BodyInertia::from_centre_in_ground(self.inertia.m, &self.com, &self.j_c, &self.j_c_form, &w.E, &w.r)
    }
}

impl<T: Scalar> Segment<T> {
    /// The rounding scale of a pin's or ball's pivot in ABA with every centre of mass of the
    /// subtree within `arm` of the point the pivot is formed about: its composite inertia
    /// bounds it (Iᴬ ≼ Iᶜ) and has no cancellation, Σ tr J_c + 2Mρ².
    #[inline(always)]
    pub fn angular_scale_at(&self, arm: f64) -> f64 {
        self.sub_trace + 2.0 * self.sub_mass * arm * arm
    }
}

impl Segment<f64> {
    /// The same segment with every number converted exactly from f64.
    pub(crate) fn cast<U: Scalar>(&self) -> Segment<U> {
        Segment {
            parent: self.parent,
            placement: self.placement.cast(),
            elem: self.elem.cast(),
            qi: self.qi,
            vi: self.vi,
            inertia: self.inertia.cast(),
            com: self.com.map(U::lit),
            j_c: self.j_c.map(U::lit),
            j_c_form: self.j_c_form.cast(),
            massless: self.massless,
            sub_mass: self.sub_mass,
            sub_trace: self.sub_trace,
            own_reach: self.own_reach,
            placement_is_shift: self.placement_is_shift,
            coord_axis: self.coord_axis,
            parent_upright: self.parent_upright,
            turn: self.turn,
        }
    }
}

/// The rotation E of a segment's joint-to-parent transform (`Model::seg_xform`), by kind, so
/// that the passes rotate vectors and inertias with only the products it needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Turn {
    /// E = 1 exactly (a slider or a weld behind a placement without rotation).
    None,
    /// A turn about coordinate axis k (0, 1, 2: a pin along ±x̂, ±ŷ, ±ẑ behind a placement
    /// without rotation): E differs from 1 only in rows and columns (i1, i2) = (k + 1, k + 2)
    /// mod 3, where it is [[c, s], [−s, c]].
    Plane(usize),
    /// Any other E.
    General,
}

impl Turn {
    /// The kind of a segment's rotation (exact tests on the model's numbers: the transforms
    /// of `Model::seg_xform` have these zeros and ones exactly).
    pub fn of(elem: &Elem<f64>, placement_is_shift: bool, coord_axis: Option<(usize, bool)>) -> Self {
        if !placement_is_shift {
            return Turn::General;
        }
        match (elem, coord_axis) {
            (Elem::Prismatic(_) | Elem::Fixed, _) => Turn::None,
            (Elem::Revolute(_), Some((axis, _))) => Turn::Plane(axis),
            _ => Turn::General,
        }
    }

    /// E v.
    #[inline(always)]
    pub fn rotate<T: Scalar>(self, e: &Matrix3<T>, v: &Vector3<T>) -> Vector3<T> {
        match self {
            Turn::None => *v,
            Turn::Plane(axis) => match axis {
                0 => plane::<T, 1, 2, false>(e, v),
                1 => plane::<T, 2, 0, false>(e, v),
                _ => plane::<T, 0, 1, false>(e, v),
            },
            Turn::General => e * v,
        }
    }

    /// Eᵀ v.
    #[inline(always)]
    pub fn rotate_back<T: Scalar>(self, e: &Matrix3<T>, v: &Vector3<T>) -> Vector3<T> {
        match self {
            Turn::None => *v,
            Turn::Plane(axis) => match axis {
                0 => plane::<T, 1, 2, true>(e, v),
                1 => plane::<T, 2, 0, true>(e, v),
                _ => plane::<T, 0, 1, true>(e, v),
            },
            Turn::General => e.tr_mul(v),
        }
    }

    /// A motion vector from P to C through `x` of this kind: ω_C = Eω, v_C = E(v − r×ω).
    #[inline(always)]
    pub fn motion<T: Scalar>(self, x: &Xform<T>, w: &Vector3<T>, v: &Vector3<T>) -> (Vector3<T>, Vector3<T>) {
        (self.rotate(&x.E, w), self.rotate(&x.E, &(v - x.r.cross(w))))
    }

    /// A force vector from C to P (Xᵀ): f_P = Eᵀf, n_P = Eᵀn + r×f_P.
    #[inline(always)]
    pub fn force_to_parent<T: Scalar>(
        self,
        x: &Xform<T>,
        n: &Vector3<T>,
        f: &Vector3<T>,
    ) -> (Vector3<T>, Vector3<T>) {
        let fp = self.rotate_back(&x.E, f);
        (self.rotate_back(&x.E, n) + x.r.cross(&fp), fp)
    }
}

/// E v (or Eᵀ v when `BACK`) for a turn about a coordinate axis that mixes components (I1, I2)
/// (`Turn::Plane`): the indices are constants, so the product is four multiplications on
/// registers.
#[inline(always)]
fn plane<T: Scalar, const I1: usize, const I2: usize, const BACK: bool>(
    e: &Matrix3<T>,
    v: &Vector3<T>,
) -> Vector3<T> {
    let (c, s) = (e[(I1, I1)], e[(I1, I2)]);
    let s = if BACK { -s } else { s };
    let mut out = *v;
    out[I1] = c * v[I1] + s * v[I2];
    out[I2] = c * v[I2] - s * v[I1];
    out
}
