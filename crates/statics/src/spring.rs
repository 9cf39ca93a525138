//! Springs and rotational springs (book §6.7), with their potentials (8.3.12).

use vectrix_tensor::{Scalar, Vector};

use crate::StaticsError;
use crate::check::{check_coeff, check_vec, finite_or_overflow, unit_sep};
use crate::force_pair::ForcePair;

/// A linear spring of stiffness k ≥ 0 and relaxed length d ≥ 0 between y and w.
///
/// Book: §6.7, (6.7.1)–(6.7.3); potential (8.3.12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spring<T: Scalar = f64> {
    k: T,
    d: T,
}

impl<T: Scalar> Spring<T> {
    /// A spring with stiffness k and relaxed length d.
    ///
    /// Book: §6.7, Fact 6.9.1.
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] when k or d is negative or non-finite.
    pub fn new(k: T, d: T) -> Result<Self, StaticsError> {
        let k = check_coeff(k, "spring stiffness k", "a finite stiffness ≥ 0")?;
        let d = check_coeff(d, "relaxed length d", "a finite length ≥ 0")?;
        Ok(Self { k, d })
    }

    /// Stiffness k.
    ///
    /// Book: §6.7, Fact 6.9.1.
    pub fn stiffness(&self) -> T {
        self.k
    }

    /// Relaxed length d.
    ///
    /// Book: §6.7, Fact 6.9.1.
    pub fn relaxed_length(&self) -> T {
        self.d
    }

    /// f⃗_{y/w} = −k(|r⃗_{y/w}| − d) r̂_{y/w} (6.7.1); for d = 0 the smooth form −k r⃗_{y/w} (6.7.3),
    /// defined even when y and w coincide.
    ///
    /// Book: (6.7.1), (6.7.3).
    ///
    /// # Errors
    /// [`StaticsError::CoincidentPoints`] when r⃗_{y/w} = 0⃗ and d > 0 (r̂ undefined);
    /// [`StaticsError::NonFinite`].
    pub fn force(&self, r_y_w: &Vector<T>) -> Result<Vector<T>, StaticsError> {
        if self.d.re() == 0.0 {
            check_vec(r_y_w, "spring")?;
            // (6.7.3): f = −k r
            return Ok(*r_y_w * (-self.k));
        }
        let (r_hat, len) = unit_sep(r_y_w, "spring with relaxed length d > 0")?;
        // (6.7.1)
        finite_or_overflow(r_hat * (-self.k * (len - self.d)), "spring force")
    }

    /// The pair f⃗_{y/w}, f⃗_{w/y} = −f⃗_{y/w} (6.7.2).
    ///
    /// Book: (6.7.2).
    ///
    /// # Errors
    /// As [`Spring::force`].
    pub fn forces(&self, r_y_w: &Vector<T>) -> Result<ForcePair<T>, StaticsError> {
        self.force(r_y_w).map(ForcePair::from_force_on_y)
    }

    /// Potential U = ½k(|r⃗_{y/w}| − d)², with f⃗_{y/w} = −∂U/∂r⃗_{y/w}.
    ///
    /// Book: (8.3.12) (and the corrected (8.3.13): ½k(|r|² − 2d|r| + d²)).
    pub fn potential(&self, r_y_w: &Vector<T>) -> T {
        let s = r_y_w.norm() - self.d;
        self.k * s * s * T::lit(0.5)
    }
}

/// A rotational spring of stiffness κ ≥ 0 and relaxed angle θ₀ on a pin with axis ẑ between
/// bodies B₁ and B₂.
///
/// Book: §6.7, (6.7.4)–(6.7.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RotationalSpring<T: Scalar = f64> {
    kappa: T,
    theta0: T,
}

impl<T: Scalar> RotationalSpring<T> {
    /// A rotational spring with stiffness κ and relaxed angle θ₀.
    ///
    /// Book: §6.7, Fact 6.9.1.
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] for κ < 0 or non-finite κ, θ₀.
    pub fn new(kappa: T, theta0: T) -> Result<Self, StaticsError> {
        let kappa = check_coeff(kappa, "rotational stiffness κ", "a finite stiffness ≥ 0")?;
        if !theta0.re().is_finite() {
            return Err(StaticsError::OutOfRange {
                what: "relaxed angle θ₀",
                value: theta0.re(),
                valid: "a finite angle",
            });
        }
        Ok(Self { kappa, theta0 })
    }

    /// The torque on B₁, M⃗_{B₁/B₂} = −κ(θ − θ₀)ẑ (6.7.4), for the angle θ = θ_{x̂₁/x̂₂/ẑ} given
    /// directly (it may exceed π when the spring is wound up more than half a turn).
    ///
    /// Book: (6.7.4).
    ///
    /// # Errors
    /// [`StaticsError::ZeroVector`] for ẑ = 0⃗.
    pub fn torque_at_angle(&self, theta: T, z: &Vector<T>) -> Result<Vector<T>, StaticsError> {
        let z = z.unit().ok_or(StaticsError::ZeroVector { what: "pin axis ẑ" })?;
        finite_or_overflow(z * (-self.kappa * (theta - self.theta0)), "spring torque")
    }

    /// The torque on B₁ from body-fixed vectors x̂₁ (in B₁) and x̂₂ (in B₂) perpendicular to ẑ:
    /// θ = θ_{x̂₁/x̂₂/ẑ} ∈ (−π, π] is the directed angle (2.3.1), M⃗_{B₁/B₂} = −κ(θ − θ₀)ẑ.
    /// Returns (M⃗_{B₁/B₂}, M⃗_{B₂/B₁} = −M⃗_{B₁/B₂}) (6.7.5).
    ///
    /// Book: (6.7.4)–(6.7.5), (2.3.1).
    ///
    /// # Errors
    /// [`StaticsError::ZeroVector`] for a zero ẑ, x̂₁ or x̂₂.
    pub fn torques(
        &self,
        x1: &Vector<T>,
        x2: &Vector<T>,
        z: &Vector<T>,
    ) -> Result<(Vector<T>, Vector<T>), StaticsError> {
        let theta = directed(x1, x2, z)?;
        let m = self.torque_at_angle(theta, z)?;
        Ok((m, -m))
    }

    /// Potential U = ½κ(θ − θ₀)² for the angle θ.
    ///
    /// Book: §6.7, §8.3 (rotational analogue of (8.3.12)).
    pub fn potential_at_angle(&self, theta: T) -> T {
        let s = theta - self.theta0;
        self.kappa * s * s * T::lit(0.5)
    }
}

/// θ_{x̂₁/x̂₂/ẑ} with the zero-vector checks.
pub(crate) fn directed<T: Scalar>(x1: &Vector<T>, x2: &Vector<T>, z: &Vector<T>) -> Result<T, StaticsError> {
    if x1.unit().is_none() || x2.unit().is_none() {
        return Err(StaticsError::ZeroVector { what: "body-fixed reference vector x̂" });
    }
    x1.directed_angle_rel(x2, z).ok_or(StaticsError::ZeroVector { what: "pin axis ẑ" })
}
