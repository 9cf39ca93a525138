//! The Frenet–Serret frame of a curve: tangent, normal, binormal, curvature, torsion and the
//! Darboux vector (book §5.5).
//!
//! The curve is r⃗(α) for any parameter α (time, arc length, …); r⃗′, r⃗″, r⃗‴ are its derivatives
//! with respect to α taken in the reference frame F_A (the path derivative r⃗^{Aα•} of (5.5.5)).

use vectrix_frames::{Frame, ORTHONORMAL_TOL};
use vectrix_tensor::{Scalar, Vector};

use crate::KinematicsError;
use crate::motion::finite_vector;

/// The Frenet–Serret frame F_FS = [ê_t ê_n ê_b] at one point of a curve, with the curve scalars.
///
/// Book: §5.5, (5.5.8–62).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrenetSerret<T: Scalar = f64> {
    /// ê_t = r⃗′/s′.
    pub tangent: Vector<T>,
    /// ê_n = (s′² r⃗″ − (r⃗′·r⃗″) r⃗′)/|…| (5.5.21).
    pub normal: Vector<T>,
    /// ê_b = ê_t × ê_n = r⃗′ × r⃗″/|r⃗′ × r⃗″| (5.5.28).
    pub binormal: Vector<T>,
    /// Speed s′ = |r⃗′| (5.5.8).
    pub speed: T,
    /// s″ = r⃗′·r⃗″/s′ (5.5.9).
    pub speed_rate: T,
    /// Curvature κ = |r⃗′ × r⃗″|/|r⃗′|³ = 1/ρ (5.5.33).
    pub curvature: T,
    /// Torsion τ = (r⃗′ × r⃗″)·r⃗‴/|r⃗′ × r⃗″|² (5.5.38).
    pub torsion: T,
}

impl<T: Scalar> FrenetSerret<T> {
    /// The frame from r⃗′, r⃗″, r⃗‴ at one parameter value.
    ///
    /// Book: (5.5.8), (5.5.21), (5.5.28), (5.5.33), (5.5.38).
    ///
    /// # Errors
    /// * [`KinematicsError::ZeroSpeed`] when s′ = |r⃗′| ≤ `speed_tol` (absolute, in curve units
    ///   per parameter unit): stationary points and cusps have no tangent;
    /// * [`KinematicsError::ZeroCurvature`] when |r⃗′ × r⃗″| ≤ `rel_tol`·|r⃗′||r⃗″| (r⃗″ parallel
    ///   to r⃗′ or zero: straight segments and inflections have no normal; the error carries the
    ///   computed κ). Use [`crate::bishop_frames`] there;
    /// * [`KinematicsError::NonFinite`]; an invalid tolerance (NaN, ∞, negative);
    /// * [`KinematicsError::Overflow`] when κ, τ, 1/κ, the Darboux vector or the acceleration
    ///   is out of the finite range (|r⃗′| = 1e300 makes κ underflow to 0).
    pub fn from_derivatives(
        r1: &Vector<T>,
        r2: &Vector<T>,
        r3: &Vector<T>,
        speed_tol: f64,
        rel_tol: f64,
    ) -> Result<Self, KinematicsError> {
        for (tol, what) in [(speed_tol, "speed_tol"), (rel_tol, "rel_tol")] {
            vectrix_tensor::check_tolerance(tol, what).map_err(vectrix_frames::FrameError::from)?;
        }
        finite_vector(r1, "r′")?;
        finite_vector(r2, "r″")?;
        finite_vector(r3, "r‴")?;
        let speed = r1.norm();
        if speed.re() <= speed_tol {
            return Err(KinematicsError::ZeroSpeed { speed: speed.re(), tol: speed_tol });
        }
        let c = r1.cross(r2);
        let c_norm = c.norm();
        // (5.5.33): κ = |r′ × r″|/s′³
        let curvature = c_norm / (speed * speed * speed);
        if c_norm.re() <= rel_tol * speed.re() * r2.norm().re() || c_norm.re() == 0.0 {
            return Err(KinematicsError::ZeroCurvature { kappa: curvature.re(), tol: rel_tol });
        }
        let tangent = *r1 / speed;
        let binormal = c / c_norm;
        // ê_n = ê_b × ê_t, equal to (5.5.21) and orthonormal by construction
        let normal = binormal.cross(&tangent);
        let fs = Self {
            tangent,
            normal,
            binormal,
            speed,
            speed_rate: r1.dot(r2) / speed,
            curvature,
            // (5.5.38): τ = (r′ × r″)·r‴/|r′ × r″|² = (b̂·r‴)/|r′ × r″|, no |r′ × r″|² overflow
            torsion: binormal.dot(r3) / c_norm,
        };
        // κ = |r′ × r″|/s′³ and its radius 1/κ, τ and the Darboux vector must all be finite
        // numbers: s′ = 1e300 makes κ underflow to 0 (radius 1e600), a true value out of range.
        let derived = [fs.speed_rate, fs.torsion, fs.radius_of_curvature()];
        let rates_finite = fs.darboux_per_parameter().is_finite() && fs.acceleration().is_finite();
        if !(derived.iter().all(|x| x.re().is_finite()) && rates_finite) {
            return Err(KinematicsError::Overflow { what: "Frenet–Serret curvature, torsion or radius" });
        }
        Ok(fs)
    }

    /// Radius of curvature ρ = 1/κ (5.5.33).
    ///
    /// Book: (5.5.33).
    pub fn radius_of_curvature(&self) -> T {
        T::one() / self.curvature
    }

    /// The Darboux vector per arc length, ω⃗_{s,FS/A} = τ ê_t + κ ê_b (5.5.49): d ê/ds = ω⃗ × ê
    /// for each axis (the Frenet relations (5.5.43)).
    ///
    /// Book: (5.5.43), (5.5.49).
    #[doc(alias = "darboux_vector")]
    pub fn darboux(&self) -> Vector<T> {
        self.tangent * self.torsion + self.binormal * self.curvature
    }

    /// The angular velocity of F_FS per unit parameter α: ω⃗_{α,FS/A} = s′(τ ê_t + κ ê_b)
    /// (5.5.53; (5.5.52) omits the s′).
    ///
    /// Book: (5.5.45–57).
    pub fn darboux_per_parameter(&self) -> Vector<T> {
        self.darboux() * self.speed
    }

    /// The frame F_FS = [ê_t ê_n ê_b].
    ///
    /// # Errors
    /// Only if rounding broke orthonormality beyond `ORTHONORMAL_TOL` (it does not for finite
    /// inputs).
    ///
    /// Book: §5.5, (5.5.62).
    pub fn frame(&self) -> Result<Frame<T>, KinematicsError> {
        Ok(Frame::from_axes(&self.tangent, &self.normal, &self.binormal, ORTHONORMAL_TOL)?)
    }

    /// Acceleration when α is time: a⃗ = v̇ ê_t + (v²/ρ) ê_n with v = s′ (5.5.66–69).
    ///
    /// Book: (5.5.66–69).
    pub fn acceleration(&self) -> Vector<T> {
        self.tangent * self.speed_rate + self.normal * (self.speed * self.speed * self.curvature)
    }
}
