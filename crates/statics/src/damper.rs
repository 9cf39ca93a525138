//! Dashpots and inerters, linear and rotational (book §6.8, §7.12).

use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::StaticsError;
use crate::check::{check_coeff, check_vec, finite_or_overflow, unit_sep};
use crate::force_pair::ForcePair;

/// d/dt|r⃗| = r̂·ṙ⃗ for r⃗ ≠ 0⃗.
fn rate_of_length<T: Scalar>(r_hat: &Vector<T>, v: &Vector<T>) -> T {
    r_hat.dot(v)
}

/// A dashpot of damping coefficient c ≥ 0 between y and w.
///
/// Book: §6.8, (6.8.1)–(6.8.2) = (7.12.1)–(7.12.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dashpot<T: Scalar = f64> {
    c: T,
}

impl<T: Scalar> Dashpot<T> {
    /// A dashpot with coefficient c.
    ///
    /// Book: §6.8, §7.12.
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] for c < 0 or non-finite.
    pub fn new(c: T) -> Result<Self, StaticsError> {
        Ok(Self { c: check_coeff(c, "damping coefficient c", "a finite coefficient ≥ 0")? })
    }

    /// f⃗_{y/w} = −c (d/dt|r⃗_{y/w}|) r̂_{y/w}, with d/dt|r⃗| = r̂·v⃗_{y/w} (6.8.1), from r⃗_{y/w} and
    /// the relative velocity v⃗_{y/w} (frame derivative of r⃗_{y/w}).
    ///
    /// Book: (6.8.1), (7.12.1).
    ///
    /// # Errors
    /// [`StaticsError::CoincidentPoints`] for r⃗_{y/w} = 0⃗; [`StaticsError::NonFinite`].
    pub fn force(&self, r_y_w: &Vector<T>, v_y_w: &Vector<T>) -> Result<Vector<T>, StaticsError> {
        let (r_hat, _) = unit_sep(r_y_w, "dashpot")?;
        check_vec(v_y_w, "dashpot relative velocity")?;
        finite_or_overflow(r_hat * (-self.c * rate_of_length(&r_hat, v_y_w)), "dashpot force")
    }

    /// The pair f⃗_{y/w}, f⃗_{w/y} = −f⃗_{y/w} (6.8.2).
    ///
    /// Book: §6.8, §7.12.
    ///
    /// # Errors
    /// As [`Dashpot::force`].
    pub fn forces(&self, r_y_w: &Vector<T>, v_y_w: &Vector<T>) -> Result<ForcePair<T>, StaticsError> {
        self.force(r_y_w, v_y_w).map(ForcePair::from_force_on_y)
    }

    /// Power dissipated, −f⃗_{y/w}·v⃗_{y/w} = c (d/dt|r⃗|)² ≥ 0 (no potential: a dashpot is
    /// dissipative).
    ///
    /// Book: §6.8, §8.2.
    ///
    /// # Errors
    /// As [`Dashpot::force`].
    pub fn dissipation(&self, r_y_w: &Vector<T>, v_y_w: &Vector<T>) -> Result<T, StaticsError> {
        let p = -self.force(r_y_w, v_y_w)?.dot(v_y_w);
        if p.re().is_finite() { Ok(p) } else { Err(StaticsError::Overflow { what: "dashpot dissipation" }) }
    }
}

/// A rotational dashpot of coefficient ξ ≥ 0 (the book also writes γ) on a pin with axis ẑ.
///
/// Book: §6.8, (6.8.3)–(6.8.4), (7.12.5)–(7.12.6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RotationalDashpot<T: Scalar = f64> {
    xi: T,
}

impl<T: Scalar> RotationalDashpot<T> {
    /// A rotational dashpot with coefficient ξ.
    ///
    /// Book: §6.8, §7.12.
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] for ξ < 0 or non-finite.
    pub fn new(xi: T) -> Result<Self, StaticsError> {
        Ok(Self { xi: check_coeff(xi, "rotational damping ξ", "a finite coefficient ≥ 0")? })
    }

    /// M⃗_{B₁/B₂} = −ξ θ̇ ẑ with θ̇ = ω⃗_{B₁/B₂}·ẑ the rate of θ_{x̂₁/x̂₂/ẑ}. Returns the pair
    /// (M⃗_{B₁/B₂}, M⃗_{B₂/B₁} = −M⃗_{B₁/B₂}).
    ///
    /// Book: (7.12.5)–(7.12.6); (6.8.3) corrected: the printed d/dt|θ| must read θ̇ (the torque
    /// reverses with the direction of rotation, as the text below (6.8.3) says).
    ///
    /// # Errors
    /// [`StaticsError::ZeroVector`] for ẑ = 0⃗.
    pub fn torques(
        &self,
        omega_b1_b2: &Vector<T>,
        z: &Vector<T>,
    ) -> Result<(Vector<T>, Vector<T>), StaticsError> {
        let z = z.unit().ok_or(StaticsError::ZeroVector { what: "pin axis ẑ" })?;
        let m = finite_or_overflow(z * (-self.xi * omega_b1_b2.dot(&z)), "dashpot torque")?;
        Ok((m, -m))
    }
}

/// An inerter of inertance b ≥ 0 between y and w: a force proportional to the relative
/// acceleration along the line of the two points.
///
/// Book: §7.12, (7.12.3)–(7.12.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inerter<T: Scalar = f64> {
    b: T,
}

impl<T: Scalar> Inerter<T> {
    /// An inerter with inertance b.
    ///
    /// Book: §6.8, §7.12.
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] for b < 0 or non-finite.
    pub fn new(b: T) -> Result<Self, StaticsError> {
        Ok(Self { b: check_coeff(b, "inertance b", "a finite inertance ≥ 0")? })
    }

    /// f⃗_{y/w} = −b (d²/dt²|r⃗_{y/w}|) r̂_{y/w} (7.12.3), with
    /// d²/dt²|r⃗| = r̂·a⃗ + (|v⃗|² − (r̂·v⃗)²)/|r⃗| for r⃗ = r⃗_{y/w}, v⃗ = v⃗_{y/w}, a⃗ = a⃗_{y/w}.
    ///
    /// Book: (7.12.3).
    ///
    /// # Errors
    /// [`StaticsError::CoincidentPoints`] for r⃗_{y/w} = 0⃗; [`StaticsError::NonFinite`].
    pub fn force(
        &self,
        r_y_w: &Vector<T>,
        v_y_w: &Vector<T>,
        a_y_w: &Vector<T>,
    ) -> Result<Vector<T>, StaticsError> {
        let (r_hat, len) = unit_sep(r_y_w, "inerter")?;
        check_vec(v_y_w, "inerter relative velocity")?;
        check_vec(a_y_w, "inerter relative acceleration")?;
        let rv = r_hat.dot(v_y_w);
        // d²|r|/dt² = r̂·a + (|v|² − (r̂·v)²)/|r|
        let len_dd = r_hat.dot(a_y_w) + (v_y_w.norm_squared() - rv * rv) / len;
        finite_or_overflow(r_hat * (-self.b * len_dd), "inerter force")
    }

    /// The pair f⃗_{y/w}, f⃗_{w/y} = −f⃗_{y/w} (7.12.4).
    ///
    /// Book: §6.8, §7.12.
    ///
    /// # Errors
    /// As [`Inerter::force`].
    pub fn forces(
        &self,
        r_y_w: &Vector<T>,
        v_y_w: &Vector<T>,
        a_y_w: &Vector<T>,
    ) -> Result<ForcePair<T>, StaticsError> {
        self.force(r_y_w, v_y_w, a_y_w).map(ForcePair::from_force_on_y)
    }

    /// The acceleration-dependent part as an added-mass dyadic: f⃗_{y/w} = −B⃗ a⃗_{y/w} + (terms
    /// in v⃗), B⃗ = b r̂r̂′. An inerter enters the mass matrix, not the explicit forces.
    ///
    /// Book: §7.12 (acceleration-dependent force).
    ///
    /// # Errors
    /// [`StaticsError::CoincidentPoints`] for r⃗_{y/w} = 0⃗.
    pub fn mass_dyadic(&self, r_y_w: &Vector<T>) -> Result<Dyadic<T>, StaticsError> {
        let (r_hat, _) = unit_sep(r_y_w, "inerter")?;
        Ok(r_hat.outer(&r_hat) * self.b)
    }
}

/// A rotational inerter of inertance β ≥ 0 on a pin with axis ẑ.
///
/// Book: §7.12, (7.12.7)–(7.12.8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RotationalInerter<T: Scalar = f64> {
    beta: T,
}

impl<T: Scalar> RotationalInerter<T> {
    /// A rotational inerter with inertance β.
    ///
    /// Book: §6.8, §7.12.
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] for β < 0 or non-finite.
    pub fn new(beta: T) -> Result<Self, StaticsError> {
        Ok(Self { beta: check_coeff(beta, "rotational inertance β", "a finite inertance ≥ 0")? })
    }

    /// M⃗_{B₁/B₂} = −β θ̈ ẑ for the angular acceleration θ̈ of θ_{x̂₁/x̂₂/ẑ}; returns the pair
    /// (M⃗_{B₁/B₂}, −M⃗_{B₁/B₂}) (7.12.7)–(7.12.8).
    ///
    /// Book: (7.12.7)–(7.12.8).
    ///
    /// # Errors
    /// [`StaticsError::ZeroVector`] for ẑ = 0⃗.
    pub fn torques(&self, theta_ddot: T, z: &Vector<T>) -> Result<(Vector<T>, Vector<T>), StaticsError> {
        let z = z.unit().ok_or(StaticsError::ZeroVector { what: "pin axis ẑ" })?;
        let m = finite_or_overflow(z * (-self.beta * theta_ddot), "inerter torque")?;
        Ok((m, -m))
    }
}
