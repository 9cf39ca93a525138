//! Cylindrical and spherical frames and their kinematics (book §5.1–5.4).
//!
//! Coordinates and their first and second time derivatives are plain numbers; the frames,
//! angular velocities, velocities and accelerations they produce are physical objects built on a
//! given reference frame F_A.

use nalgebra::{Matrix3, Vector3};
use vectrix_frames::{Frame, ORTHONORMAL_TOL};
use vectrix_tensor::{Scalar, Vector};

use crate::KinematicsError;

fn finite<T: Scalar>(xs: &[T], what: &'static str) -> Result<(), KinematicsError> {
    if xs.iter().all(|x| x.re().is_finite()) { Ok(()) } else { Err(KinematicsError::NonFinite { what }) }
}

/// Elementary passive matrix 𝓞₂(φ) (2.12.15).
fn o2<T: Scalar>(p: T) -> Matrix3<T> {
    let (s, c) = p.sin_cos();
    let (z, o) = (T::zero(), T::one());
    Matrix3::new(c, z, -s, z, o, z, s, z, c)
}

/// Elementary passive matrix 𝓞₃(θ) (2.12.16).
fn o3<T: Scalar>(t: T) -> Matrix3<T> {
    let (s, c) = t.sin_cos();
    let (z, o) = (T::zero(), T::one());
    Matrix3::new(c, s, z, -s, c, z, z, z, o)
}

/// Cylindrical coordinates q = (r_r, θ, r_a) with their rates: F_A →3,θ F_cyl,
/// 𝓞_{cyl/A} = 𝓞₃(θ), F_cyl = [ê_r ê_t ê_a].
///
/// Book: §5.1–5.2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylindrical<T: Scalar = f64> {
    /// (r_r, θ, r_a).
    pub q: [T; 3],
    /// (ṙ_r, θ̇, ṙ_a).
    pub q_dot: [T; 3],
    /// (r̈_r, θ̈, r̈_a).
    pub q_ddot: [T; 3],
}

impl<T: Scalar> Cylindrical<T> {
    /// Coordinates of a position r|_A: r_r = √(r₁² + r₂²), θ = atan2(r₂, r₁) (θ = 0 on the axis,
    /// the book's choice), r_a = r₃; rates zero.
    ///
    /// Book: §5.1.
    ///
    /// # Errors
    /// [`KinematicsError::NonFinite`]; [`KinematicsError::Overflow`] when the radius exceeds
    /// f64::MAX (every component near it).
    pub fn from_position(r_in_a: [T; 3]) -> Result<Self, KinematicsError> {
        finite(&r_in_a, "position")?;
        let [r1, r2, r3] = r_in_a;
        let z = T::zero();
        let rho = r1.hypot(r2);
        if !rho.re().is_finite() {
            return Err(KinematicsError::Overflow { what: "cylindrical radius ρ" });
        }
        Ok(Self { q: [rho, r2.atan2(r1), r3], q_dot: [z; 3], q_ddot: [z; 3] })
    }

    /// r|_A = (r_r cos θ, r_r sin θ, r_a).
    ///
    /// Book: §5.1, §5.3, (5.3.41–43).
    pub fn position_in_a(&self) -> Vector3<T> {
        let [rr, th, ra] = self.q;
        Vector3::new(rr * th.cos(), rr * th.sin(), ra)
    }

    /// 𝓞_{cyl/A} = 𝓞₃(θ).
    ///
    /// Book: §5.1.
    pub fn o_cyl_a(&self) -> Matrix3<T> {
        o3(self.q[1])
    }

    /// The frame F_cyl built on F_A.
    ///
    /// # Errors
    /// Only for non-finite θ.
    ///
    /// Book: §5.1, §5.3, (5.3.13).
    pub fn frame(&self, a: &Frame<T>) -> Result<Frame<T>, KinematicsError> {
        Ok(Frame::from_orientation_rel(a, &self.o_cyl_a(), ORTHONORMAL_TOL)?)
    }

    /// ω_{cyl/A}|_cyl = (0, 0, θ̇).
    ///
    /// Book: §5.2.
    pub fn omega_in_cyl(&self) -> Vector3<T> {
        Vector3::new(T::zero(), T::zero(), self.q_dot[1])
    }

    /// v|_cyl = (ṙ_r, r_r θ̇, ṙ_a).
    ///
    /// Book: §5.2.
    pub fn velocity_in_cyl(&self) -> Vector3<T> {
        Vector3::new(self.q_dot[0], self.q[0] * self.q_dot[1], self.q_dot[2])
    }

    /// a|_cyl = (r̈_r − r_r θ̇², r_r θ̈ + 2ṙ_r θ̇, r̈_a); 2ṙ_rθ̇ is the Coriolis term (5.2.10,
    /// whose printed line is garbled).
    ///
    /// Book: (5.2.10).
    pub fn acceleration_in_cyl(&self) -> Vector3<T> {
        let ([r, _, _], [rd, td, _], [rdd, tdd, add]) = (self.q, self.q_dot, self.q_ddot);
        Vector3::new(rdd - r * td * td, r * tdd + T::lit(2.0) * rd * td, add)
    }

    /// Physical ω⃗_{cyl/A}, v⃗ and a⃗ (of the point relative to F_A's origin, w.r.t. F_A).
    ///
    /// # Errors
    /// As [`Cylindrical::frame`].
    ///
    /// Book: §5.2, §5.4, (5.2.10), (5.4.2), (5.4.10).
    pub fn kinematics(&self, a: &Frame<T>) -> Result<[Vector<T>; 3], KinematicsError> {
        let f = self.frame(a)?;
        let v = |x: Vector3<T>| f.vector([x.x, x.y, x.z]);
        Ok([v(self.omega_in_cyl()), v(self.velocity_in_cyl()), v(self.acceleration_in_cyl())])
    }
}

/// Spherical coordinates q = (r_u, θ, φ) with rates: F_A →3,θ F_cyl →2,φ F_sph,
/// 𝓞_{sph/A} = 𝓞₂(φ)𝓞₃(θ) (5.3.13), F_sph = [ê_u ê_e ê_n] (up, east, north).
///
/// # Conventions
/// **φ is positive below the î–ĵ plane** (the book's sign): r₃ = −r_u sin φ,
/// φ = −atan2(r₃, √(r₁² + r₂²)), φ ∈ [−π/2, π/2].
///
/// Book: §5.3–5.4, (5.3.13), (5.3.41–43).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spherical<T: Scalar = f64> {
    /// (r_u, θ, φ).
    pub q: [T; 3],
    /// (ṙ_u, θ̇, φ̇).
    pub q_dot: [T; 3],
    /// (r̈_u, θ̈, φ̈).
    pub q_ddot: [T; 3],
}

impl<T: Scalar> Spherical<T> {
    /// Coordinates of r|_A: r_u = |r|, θ = atan2(r₂, r₁), φ = −atan2(r₃, √(r₁² + r₂²))
    /// (θ = 0 on the k̂ axis and φ = 0 at the origin, by atan2(0, 0) = 0); rates zero.
    ///
    /// Book: (5.3.41–43).
    ///
    /// # Errors
    /// [`KinematicsError::NonFinite`]; [`KinematicsError::Overflow`] when the radius exceeds
    /// f64::MAX (every component near it).
    pub fn from_position(r_in_a: [T; 3]) -> Result<Self, KinematicsError> {
        finite(&r_in_a, "position")?;
        let [r1, r2, r3] = r_in_a;
        let rho = r1.hypot(r2);
        let z = T::zero();
        let r = rho.hypot(r3);
        if !r.re().is_finite() {
            // |r⃗| beyond f64::MAX (components near it)
            return Err(KinematicsError::Overflow { what: "spherical radius r" });
        }
        Ok(Self { q: [r, r2.atan2(r1), -r3.atan2(rho)], q_dot: [z; 3], q_ddot: [z; 3] })
    }

    /// r|_A = r_u ê_u|_A = r_u (cos φ cos θ, cos φ sin θ, −sin φ).
    ///
    /// Book: §5.1, §5.3, (5.3.41–43).
    pub fn position_in_a(&self) -> Vector3<T> {
        let [r, th, ph] = self.q;
        Vector3::new(r * ph.cos() * th.cos(), r * ph.cos() * th.sin(), -r * ph.sin())
    }

    /// 𝓞_{sph/A} = 𝓞₂(φ)𝓞₃(θ) (5.3.13).
    ///
    /// Book: (5.3.13).
    pub fn o_sph_a(&self) -> Matrix3<T> {
        o2(self.q[2]) * o3(self.q[1])
    }

    /// The frame F_sph built on F_A.
    ///
    /// # Errors
    /// Only for non-finite angles.
    ///
    /// Book: §5.1, §5.3, (5.3.13).
    pub fn frame(&self, a: &Frame<T>) -> Result<Frame<T>, KinematicsError> {
        Ok(Frame::from_orientation_rel(a, &self.o_sph_a(), ORTHONORMAL_TOL)?)
    }

    /// ω_{sph/A}|_sph = (−θ̇ sin φ, φ̇, θ̇ cos φ), i.e. ω⃗ = θ̇ê_a + φ̇ê_e (5.4.2).
    ///
    /// Book: (5.4.2).
    pub fn omega_in_sph(&self) -> Vector3<T> {
        let ([_, _, ph], [_, td, pd]) = (self.q, self.q_dot);
        Vector3::new(-td * ph.sin(), pd, td * ph.cos())
    }

    /// v|_sph = (ṙ_u, r_u θ̇ cos φ, −r_u φ̇).
    ///
    /// Book: §5.4.
    pub fn velocity_in_sph(&self) -> Vector3<T> {
        let ([r, _, ph], [rd, td, pd]) = (self.q, self.q_dot);
        Vector3::new(rd, r * td * ph.cos(), -r * pd)
    }

    /// a|_sph (5.4.10, corrected sign of the last north term, as in its underbrace form):
    /// u: r̈ − r(φ̇² + θ̇² cos²φ); e: rθ̈ cos φ + 2ṙθ̇ cos φ − 2rθ̇φ̇ sin φ;
    /// n: −rφ̈ − 2ṙφ̇ − rθ̇² sin φ cos φ.
    ///
    /// Book: (5.4.10) (erratum: notes ch4-5 §2).
    pub fn acceleration_in_sph(&self) -> Vector3<T> {
        let ([r, _, ph], [rd, td, pd], [rdd, tdd, pdd]) = (self.q, self.q_dot, self.q_ddot);
        let (s, c) = ph.sin_cos();
        let two = T::lit(2.0);
        Vector3::new(
            rdd - r * (pd * pd + td * td * c * c),
            // r last in each product: r near f64::MAX times zero rates is 0, not ∞·0
            r * tdd * c + two * rd * td * c - r * (two * td * pd * s),
            -r * pdd - two * rd * pd - r * td * td * s * c,
        )
    }

    /// The Coriolis part 2ṙ_u(θ̇ cos φ ê_e − φ̇ ê_n) of the acceleration, in F_sph (5.4.11).
    ///
    /// Book: (5.4.11).
    pub fn coriolis_in_sph(&self) -> Vector3<T> {
        let ([_, _, ph], [rd, td, pd]) = (self.q, self.q_dot);
        Vector3::new(T::zero(), T::lit(2.0) * rd * td * ph.cos(), -T::lit(2.0) * rd * pd)
    }

    /// Physical ω⃗_{sph/A}, v⃗ and a⃗.
    ///
    /// # Errors
    /// As [`Spherical::frame`].
    ///
    /// Book: §5.2, §5.4, (5.2.10), (5.4.2), (5.4.10).
    pub fn kinematics(&self, a: &Frame<T>) -> Result<[Vector<T>; 3], KinematicsError> {
        let f = self.frame(a)?;
        let v = |x: Vector3<T>| f.vector([x.x, x.y, x.z]);
        Ok([v(self.omega_in_sph()), v(self.velocity_in_sph()), v(self.acceleration_in_sph())])
    }
}
