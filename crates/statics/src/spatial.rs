//! Spatial (6D) inertia (book §7.10, (7.10.8)).

use nalgebra::Matrix6;
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::{MassProperties, Point};

/// The spatial inertia of a body about a point z (7.10.8):
///
/// 𝒥⃗_{B/z} = [[m_B I⃗, −m_B r⃗^×_{c/z}], [m_B r⃗^×_{c/z}, J⃗_{B/z}]],
///
/// acting on the twist 𝒱 = [v⃗_{z/w/A}; ω⃗_{B/A}] (velocity first) to give [p⃗; H⃗_{B/z}].
///
/// Book: §7.10, (7.10.8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialInertia<T: Scalar = f64> {
    /// m_B.
    pub mass: T,
    /// r⃗_{c/z}: the centre of mass relative to the reference point z.
    pub r_c_z: Vector<T>,
    /// J⃗_{B/z}.
    pub j_z: Dyadic<T>,
}

impl<T: Scalar> SpatialInertia<T> {
    /// 𝒥⃗_{B/z} 𝒱: returns (p⃗, H⃗_{B/z}) = (m v⃗ − m r⃗_{c/z}×ω⃗, m r⃗_{c/z}×v⃗ + J⃗_{B/z}ω⃗), the
    /// linear momentum m v⃗_c and the angular momentum about z of a rigid body.
    ///
    /// Book: (7.10.8), (7.8.4).
    pub fn apply(&self, v_z: &Vector<T>, omega: &Vector<T>) -> (Vector<T>, Vector<T>) {
        let m = self.mass;
        let p = (*v_z - self.r_c_z.cross(omega)) * m;
        let h = self.r_c_z.cross(v_z) * m + self.j_z.apply(omega);
        (p, h)
    }

    /// Kinetic energy ½𝒱ᵀ𝒥𝒱 = ½m|v⃗_z|² + m v⃗_z·(ω⃗×r⃗_{c/z}) + ½ω⃗′J⃗_{B/z}ω⃗.
    ///
    /// Book: (7.10.8), (8.1.14).
    pub fn kinetic_energy(&self, v_z: &Vector<T>, omega: &Vector<T>) -> T {
        let (p, h) = self.apply(v_z, omega);
        (p.dot(v_z) + h.dot(omega)) * T::lit(0.5)
    }

    /// The 6×6 matrix 𝒥_{B/z|A}, blocks resolved in the frame A, velocity block first.
    ///
    /// Book: (7.10.8), (7.10.11).
    pub fn resolve_in(&self, a: &Frame<T>) -> Matrix6<T> {
        let m = self.mass;
        let rx = self.r_c_z.cross_dyad().resolve(a) * m;
        let j = self.j_z.resolve(a);
        let mut out = Matrix6::zeros();
        out.fixed_view_mut::<3, 3>(0, 0).copy_from(&(nalgebra::Matrix3::identity() * m));
        out.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-rx));
        out.fixed_view_mut::<3, 3>(3, 0).copy_from(&rx);
        out.fixed_view_mut::<3, 3>(3, 3).copy_from(&j);
        out
    }
}

impl<T: Scalar> MassProperties<T> {
    /// The spatial inertia 𝒥⃗_{B/z} about the point z (7.10.8).
    ///
    /// Book: §7.10, (7.10.8).
    pub fn spatial_inertia(&self, z: &Point<T>) -> SpatialInertia<T> {
        SpatialInertia {
            mass: self.mass(),
            r_c_z: self.centre_of_mass().position_rel(z),
            j_z: self.inertia_about(z),
        }
    }
}
