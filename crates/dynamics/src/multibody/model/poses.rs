//! Link placements: the joint-to-parent and ground-to-segment transforms of every segment at
//! a configuration, and the link poses built from them.
//!
//! Book: §2.22 (chains), (2.10.46) composition.
#![allow(non_snake_case)]

use nalgebra::Matrix3;
use vectrix_tensor::Scalar;

use super::Model;
use crate::DynamicsError;
use crate::multibody::joint::{Elem, Pose};
use crate::multibody::spatial::Xform;

impl<T: Scalar> Model<T> {
    /// The joint-to-parent transform of every segment at q (placement ∘ joint); `sc` as in
    /// `Elem::xform` (a [`Trig`]'s entry for segment i).
    #[inline(always)]
    pub(crate) fn seg_xform(&self, i: usize, q: &[T], sc: Option<(T, T)>) -> Xform<T> {
        let s = &self.segs[i];
        if let (false, Elem::Revolute(_), Some((axis, negative))) =
            (s.placement_is_shift, &s.elem, s.coord_axis)
        {
            // a pin about a coordinate axis behind a turned placement: 𝓞_k(θ) 𝓞_placement mixes
            // two rows of the placement's rotation (12 products instead of 27), and the origin
            // is the placement's (a pin does not move it)
            let (sn, c) = sc.unwrap_or_else(|| q[s.qi].fast_sin_cos());
            let sn = if negative { -sn } else { sn };
            return Xform { E: turn_rows(&s.placement.E, axis, sn, c), r: s.placement.r };
        }
        let j = s.elem.xform(&q[s.qi..], sc);
        if s.placement_is_shift {
            // placement E = 1: placement ∘ joint = (E_joint, r_placement + r_joint)
            Xform { E: j.E, r: s.placement.r + j.r }
        } else {
            s.placement.then(&j)
        }
    }

    /// Ground-to-segment transform of segment i from its parent's (`None` at the root):
    /// parent ∘ placement ∘ joint. A pin about a coordinate axis behind a placement without
    /// rotation mixes two rows of the parent's orientation (12 products instead of 27).
    #[inline(always)]
    pub(crate) fn world_xform(
        &self,
        i: usize,
        q: &[T],
        parent: Option<&Xform<T>>,
        sc: Option<(T, T)>,
    ) -> Xform<T> {
        let s = &self.segs[i];
        if let (Some(p), true, Elem::Revolute(_), Some((axis, negative))) =
            (parent, s.placement_is_shift, &s.elem, s.coord_axis)
        {
            let (sn, c) = sc.unwrap_or_else(|| q[s.qi].fast_sin_cos());
            let sn = if negative { -sn } else { sn };
            let r = p.r + p.E.tr_mul(&s.placement.r);
            // 𝓞_{i/G} = 𝓞_k(θ) 𝓞_{p/G}
            return Xform { E: turn_rows(&p.E, axis, sn, c), r };
        }
        // a slider behind a placement without rotation keeps the parent's orientation
        // (1·𝓞 = 𝓞 exactly): only the origin moves
        if let (Some(p), true, Elem::Prismatic(a)) = (parent, s.placement_is_shift, &s.elem) {
            let shift = s.placement.r + a * q[s.qi];
            return Xform { E: p.E, r: p.r + if s.parent_upright { shift } else { p.E.tr_mul(&shift) } };
        }
        let x = self.seg_xform(i, q, sc);
        match parent {
            // the parent's orientation is exactly the ground's (1 ∘ x: a shift)
            Some(p) if s.parent_upright => Xform { E: x.E, r: p.r + x.r },
            Some(p) => p.then(&x),
            None => x,
        }
    }

    /// Link poses: for each link, 𝓞_{link/ground} and r_{link origin/ground origin}|_ground.
    ///
    /// Book: §2.22 (chains), (2.10.46) composition.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`],
    /// [`DynamicsError::OutOfRange`] (a ball-joint quaternion of norm below 1e-6).
    pub fn poses(&self, q: &[T]) -> Result<Vec<Pose<T>>, DynamicsError> {
        self.check_q(q)?;
        let (mut world, mut out) = (PosesScratch::default(), Vec::new());
        self.poses_into(q, &mut world, &mut out);
        Ok(out)
    }

    /// [`Model::poses`] into caller-owned buffers (no allocation once they have grown), without
    /// input checks: the hot path of a right-hand side. `world` is work space.
    pub fn poses_into(&self, q: &[T], world: &mut PosesScratch<T>, out: &mut Vec<Pose<T>>) {
        let world = &mut world.0;
        world.clear();
        for (i, s) in self.segs.iter().enumerate() {
            let w = self.world_xform(i, q, s.parent.map(|p| &world[p]), None);
            world.push(w);
        }
        out.clear();
        out.extend(self.link_seg.iter().map(|&k| (world[k].E, world[k].r)));
    }

    /// Ground-to-segment transforms of every segment (parents first).
    pub(crate) fn world_xforms(&self, q: &[T]) -> Vec<Xform<T>> {
        let mut world: Vec<Xform<T>> = Vec::with_capacity(self.segs.len());
        for (i, s) in self.segs.iter().enumerate() {
            let w = self.world_xform(i, q, s.parent.map(|p| &world[p]), None);
            world.push(w);
        }
        world
    }
}

/// 𝓞_k(θ) E for a turn by θ (sine `sn`, cosine `c`) about coordinate axis k (0, 1, 2 for x̂, ŷ,
/// ẑ), passive as the book's 𝓞 (Rodrigues (2.11.1) transposed): rows (i1, i2) of E mix as
/// [[c, s], [−s, c]] and the axis row stays (12 products instead of the full 27).
#[inline(always)]
fn turn_rows<T: Scalar>(e: &Matrix3<T>, axis: usize, sn: T, c: T) -> Matrix3<T> {
    // constant row indices in each arm, so the new matrix is built on registers (runtime
    // indices sent every entry through memory)
    match axis {
        0 => turn_rows_of::<T, 1, 2>(e, sn, c),
        1 => turn_rows_of::<T, 2, 0>(e, sn, c),
        _ => turn_rows_of::<T, 0, 1>(e, sn, c),
    }
}

/// [`turn_rows`] for rows (I1, I2).
#[inline(always)]
fn turn_rows_of<T: Scalar, const I1: usize, const I2: usize>(e: &Matrix3<T>, sn: T, c: T) -> Matrix3<T> {
    let mut out = *e;
    for col in 0..3 {
        let (a1, a2) = (e[(I1, col)], e[(I2, col)]);
        out[(I1, col)] = c * a1 + sn * a2;
        out[(I2, col)] = c * a2 - sn * a1;
    }
    out
}

/// The sines and cosines of every revolute segment's angle at one q, computed together by
/// `Scalar::fast_sin_cos_slices` (vector lanes where the CPU has them; the same bits as one
/// `fast_sin_cos` each, on every CPU), for the outward passes of the hot paths.
#[derive(Debug, Clone)]
pub(crate) struct Trig<T: Scalar> {
    /// q index and segment of each revolute segment, in segment order.
    qi: Vec<usize>,
    seg: Vec<usize>,
    x: Vec<T>,
    sin: Vec<T>,
    cos: Vec<T>,
    /// Per segment: (sin θ, cos θ) of a revolute one (unused for the others).
    sc: Vec<(T, T)>,
}

impl<T: Scalar> Trig<T> {
    /// The work space for `model`'s revolute segments.
    pub fn of(model: &Model<T>) -> Self {
        let (mut qi, mut seg) = (Vec::new(), Vec::new());
        for (i, s) in model.segs.iter().enumerate() {
            if let Elem::Revolute(_) = s.elem {
                qi.push(s.qi);
                seg.push(i);
            }
        }
        let (k, n) = (qi.len(), model.segs.len());
        let z = vec![T::zero(); k];
        Self { qi, seg, x: z.clone(), sin: z.clone(), cos: z, sc: vec![(T::zero(), T::one()); n] }
    }

    /// sin θ, cos θ of every revolute segment at `q`.
    #[inline]
    pub fn fill(&mut self, q: &[T]) {
        for (x, &k) in self.x.iter_mut().zip(&self.qi) {
            *x = q[k];
        }
        T::fast_sin_cos_slices(&self.x, &mut self.sin, &mut self.cos);
        for ((&i, &s), &c) in self.seg.iter().zip(&self.sin).zip(&self.cos) {
            self.sc[i] = (s, c);
        }
    }

    /// (sin θ, cos θ) of segment i, read only by a revolute segment's transform.
    #[inline(always)]
    pub fn get(&self, i: usize) -> Option<(T, T)> {
        Some(self.sc[i])
    }
}

/// Work space of [`Model::poses_into`]: the ground-to-segment transforms of one evaluation,
/// kept between calls so that a right-hand side allocates nothing once it has grown; after
/// `poses_into` at q, [`Model::twists_into`] and [`Model::bias_accelerations_into`] read them.
#[derive(Debug, Clone)]
pub struct PosesScratch<T: Scalar = f64>(pub(crate) Vec<Xform<T>>);

impl<T: Scalar> Default for PosesScratch<T> {
    fn default() -> Self {
        Self(Vec::new())
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Vector3};

    use crate::multibody::joint::{Joint, Link};
    use crate::multibody::model::Model;

    /// Behind a free joint's sliders the orientation is exactly the ground's, so composing with
    /// them is a shift: the free body's pose is (𝓡(q)ᵀ, offset + (x, y, z)) with 𝓡 the rotation
    /// of the normalized Euler parameters (η, ε), 𝓡 = (2η² − 1)1 + 2ηε^× + 2εεᵀ (Fact 2.15.5;
    /// 2η² − 1 = η² − εᵀε for a unit quaternion), and
    /// a pin child about ẑ at d composes as 𝓞 = 𝓡_z(θ)ᵀ𝓞₀, r = r₀ + 𝓞₀ᵀd; matrices built here
    /// by hand, not by the model's code.
    #[test]
    fn poses_behind_a_free_joint() {
        let (offset, d) = (Vector3::new(0.5, -0.2, 0.1), Vector3::new(0.3, 0.7, -0.4));
        let links = [
            Link::new(None, Joint::Free, offset, 2.0, Vector3::new(0.1, 0.0, 0.2), Matrix3::identity()),
            Link::new(
                Some(0),
                Joint::Pin { axis: Vector3::z() },
                d,
                1.0,
                Vector3::zeros(),
                Matrix3::identity(),
            ),
        ];
        let m = Model::new(&links).expect("valid");
        // an unnormalized quaternion (the joint normalizes it) and a pin angle
        let (x, eta, eps, th): (Vector3<f64>, f64, Vector3<f64>, f64) =
            (Vector3::new(1.5, -2.0, 0.75), 0.6, Vector3::new(-0.4, 1.1, 0.3), 0.9);
        let n = (eta * eta + eps.norm_squared()).sqrt();
        let (eta, eps) = (eta / n, eps / n);
        let cross = Matrix3::new(0.0, -eps.z, eps.y, eps.z, 0.0, -eps.x, -eps.y, eps.x, 0.0);
        let r = Matrix3::identity() * (eta * eta - eps.norm_squared())
            + eps * eps.transpose() * 2.0
            + cross * (2.0 * eta);
        let e0 = r.transpose();
        let r0 = offset + x;
        let (s, c) = th.sin_cos();
        let e1 = Matrix3::new(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0) * e0;
        let r1 = r0 + e0.transpose() * d;
        let q = [x.x, x.y, x.z, 0.6 * 2.0, -0.4 * 2.0, 1.1 * 2.0, 0.3 * 2.0, th];
        let poses = m.poses(&q).expect("valid q");
        let tol = 4.0 * f64::EPSILON;
        assert!((poses[0].0 - e0).amax() <= tol && (poses[0].1 - r0).amax() <= tol, "{poses:?}");
        assert!((poses[1].0 - e1).amax() <= tol && (poses[1].1 - r1).amax() <= 2.0 * tol, "{poses:?}");
    }

    /// The batched sines and cosines are those of each joint on its own, bit for bit (in and
    /// beyond the kernel's range, at ±0, and NaN), so every transform is the same with or
    /// without them: a 13-pin chain (above one vector of lanes) at hostile angles.
    #[test]
    fn batched_sines_and_cosines_are_each_joints_own() {
        use vectrix_tensor::Scalar;

        use super::Trig;
        let m = Model::revolute_chain(13, 1.0, 0.5).expect("valid");
        let q = [0.0, -0.0, 1e-300, 3.0, -3.2, 1e5, 2e5 + 1.0, -7e5, 1e300, f64::NAN, 0.7, 1.5, -2.5];
        let mut t = Trig::of(&m);
        t.fill(&q);
        let mut seen = 0;
        for (i, seg) in m.segs.iter().enumerate() {
            if let crate::multibody::joint::Elem::Revolute(_) = seg.elem {
                let (s, c) = q[seg.qi].fast_sin_cos();
                let (bs, bc) = t.get(i).expect("revolute");
                assert_eq!((bs.to_bits(), bc.to_bits()), (s.to_bits(), c.to_bits()), "q = {}", q[seg.qi]);
                let (a, b) = (m.seg_xform(i, &q, None), m.seg_xform(i, &q, t.get(i)));
                assert!(
                    a.E.iter()
                        .chain(a.r.iter())
                        .zip(b.E.iter().chain(b.r.iter()))
                        .all(|(x, y)| x.to_bits() == y.to_bits())
                );
                seen += 1;
            }
        }
        assert_eq!(seen, 13);
    }
}
