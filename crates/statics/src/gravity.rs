//! Uniform gravity (book §6.6), central gravity, mutual gravitation and the centre of
//! gravity (book §6.12).

use vectrix_tensor::{Scalar, Vector};

use crate::check::{check_coeff, check_vec, finite_or_overflow, unit_sep};
use crate::force_pair::ForcePair;
use crate::mass::{check_mass, check_point};
use crate::{MassProperties, Point, StaticsError, Wrench};

/// The universal gravitational constant G = 6.67430 × 10⁻¹¹ N·m²/kg² (CODATA 2018).
///
/// Book: (6.12.2), corrected: the printed "G = 6.67428 N·m²/kg²" lacks the factor 10⁻¹¹.
pub const GRAVITATIONAL_CONSTANT: f64 = 6.674_30e-11;

/// Uniform gravity g⃗ (an acceleration, e.g. 9.81 m/s² downward).
///
/// Book: §6.6, Facts 6.6.1–6.6.2; potential (8.3.9).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UniformGravity<T: Scalar = f64> {
    g: Vector<T>,
}

impl<T: Scalar> UniformGravity<T> {
    /// Gravity with acceleration g⃗.
    ///
    /// Book: §6.6, (6.6.1).
    ///
    /// # Errors
    /// [`StaticsError::NonFinite`].
    pub fn new(g: Vector<T>) -> Result<Self, StaticsError> {
        check_vec(&g, "gravity g")?;
        Ok(Self { g })
    }

    /// g⃗.
    ///
    /// Book: §6.6, (6.6.1).
    pub fn acceleration(&self) -> Vector<T> {
        self.g
    }

    /// The weight of a particle or body of mass m: f⃗ = m g⃗ (6.6.1).
    ///
    /// Book: Fact 6.6.1, (6.6.1); Fact 8.3.2 corrected (the printed −mg⃗ has the wrong sign).
    pub fn force(&self, m: T) -> Vector<T> {
        self.g * m
    }

    /// The gravity wrench on a body about w: f⃗_B = m_B g⃗, M⃗_{B/w} = r⃗_{c/w} × m_B g⃗ (6.6.2);
    /// about c the moment vanishes (6.6.3).
    ///
    /// Book: Fact 6.6.2, (6.6.2)–(6.6.3).
    pub fn wrench_on(&self, body: &MassProperties<T>, about: Point<T>) -> Wrench<T> {
        let f = self.force(body.mass());
        Wrench { force: f, moment: body.centre_of_mass().position_rel(&about).cross(&f), about }
    }

    /// Potential U = −m r⃗_{c/w}·g⃗ relative to the point w (8.3.9), with f⃗ = −∂U/∂r⃗.
    ///
    /// Book: (8.3.9).
    pub fn potential(&self, m: T, r_c_w: &Vector<T>) -> T {
        -(r_c_w.dot(&self.g) * m)
    }
}

/// Central gravity of a fixed attracting particle x with gravitational parameter μ = G M.
///
/// Book: §6.12, (6.12.1); Earth potential (8.3.10).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentralGravity<T: Scalar = f64> {
    mu: T,
}

impl<T: Scalar> CentralGravity<T> {
    /// A centre with μ = G M ≥ 0.
    ///
    /// Book: §6.12, (6.12.1).
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] for μ < 0 or non-finite.
    pub fn new(mu: T) -> Result<Self, StaticsError> {
        Ok(Self { mu: check_coeff(mu, "gravitational parameter μ", "a finite μ = GM ≥ 0")? })
    }

    /// An attracting particle of mass M: μ = G M with [`GRAVITATIONAL_CONSTANT`].
    ///
    /// Book: §6.12, (6.12.1).
    ///
    /// # Errors
    /// [`StaticsError::InvalidMass`].
    pub fn of_mass(m: T) -> Result<Self, StaticsError> {
        check_mass(m, "attracting mass")?;
        Self::new(m * T::lit(GRAVITATIONAL_CONSTANT))
    }

    /// μ.
    ///
    /// Book: §6.12, (6.12.1).
    pub fn mu(&self) -> T {
        self.mu
    }

    /// f⃗_{y/x} = (μ m/|r⃗_{y/x}|²) r̂_{x/y} (6.12.1): attraction of the particle y of mass m
    /// toward x.
    ///
    /// Book: Fact 6.12.1, (6.12.1).
    ///
    /// # Errors
    /// [`StaticsError::CoincidentPoints`] for r⃗_{y/x} = 0⃗; [`StaticsError::InvalidMass`].
    pub fn force(&self, m: T, r_y_x: &Vector<T>) -> Result<Vector<T>, StaticsError> {
        check_mass(m, "attracted particle")?;
        let (r_hat, len) = unit_sep(r_y_x, "central gravity")?;
        // (6.12.1): r̂_{x/y} = −r̂_{y/x}
        let f = r_hat * (-self.mu * m / len / len);
        finite_or_overflow(f, "central gravity force")
    }

    /// Potential U = −μ m/|r⃗_{y/x}| (8.3.10).
    ///
    /// Book: (8.3.10).
    ///
    /// # Errors
    /// [`StaticsError::CoincidentPoints`] for r⃗_{y/x} = 0⃗.
    pub fn potential(&self, m: T, r_y_x: &Vector<T>) -> Result<T, StaticsError> {
        let (_, len) = unit_sep(r_y_x, "central gravity")?;
        let u = -self.mu * m / len;
        if u.re().is_finite() {
            Ok(u)
        } else {
            Err(StaticsError::Overflow { what: "central gravity potential" })
        }
    }
}

/// Mutual gravitation of two particles of fixed masses, validated once: y (mass m) and x (mass
/// M) attract with f⃗_{y/x} = (G M m/|r⃗_{y/x}|²) r̂_{x/y} = −f⃗_{x/y} (6.12.1). For a force
/// evaluated many times (a simulation's right-hand side), where [`mutual_gravitation`] would
/// check G and both masses on every call ([`mutual_gravitation`] is this, checked each time).
///
/// Book: Fact 6.12.1, (6.12.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MutualGravitation<T: Scalar = f64> {
    /// G M m, formed as (G M) m like [`CentralGravity`]'s μ m.
    gmm: T,
}

impl<T: Scalar> MutualGravitation<T> {
    /// The pair y (mass `m_y`), x (mass `m_x`) under the constant `g` (pass
    /// [`GRAVITATIONAL_CONSTANT`] in SI units).
    ///
    /// Book: (6.12.1).
    ///
    /// # Errors
    /// [`StaticsError::OutOfRange`] for G < 0 or non-finite, [`StaticsError::InvalidMass`] for a
    /// negative or non-finite mass, [`StaticsError::Overflow`] when G M m exceeds the largest
    /// finite number.
    pub fn new(g: T, m_y: T, m_x: T) -> Result<Self, StaticsError> {
        check_coeff(g, "gravitational constant G", "a finite G ≥ 0")?;
        check_mass(m_x, "attracting particle")?;
        check_mass(m_y, "attracted particle")?;
        let gmm = g * m_x * m_y;
        if !gmm.re().is_finite() {
            return Err(StaticsError::Overflow { what: "G M m of mutual gravitation" });
        }
        Ok(Self { gmm })
    }

    /// G M m.
    ///
    /// Book: (6.12.1).
    pub fn gmm(&self) -> T {
        self.gmm
    }

    /// f⃗_{y/x} = (G M m/|r⃗_{y/x}|²) r̂_{x/y}, the force on y (6.12.1); the force on x is its
    /// negative (Fact 6.9.1).
    ///
    /// Book: Fact 6.12.1, (6.12.1).
    ///
    /// # Errors
    /// [`StaticsError::NonFinite`] for a non-finite separation, [`StaticsError::CoincidentPoints`]
    /// for r⃗_{y/x} = 0⃗, [`StaticsError::Overflow`] when the force exceeds the largest finite
    /// number.
    #[inline]
    pub fn force_on_y(&self, r_y_x: &Vector<T>) -> Result<Vector<T>, StaticsError> {
        check_vec(r_y_x, "mutual gravitation")?;
        let len = r_y_x.norm();
        // (6.12.1) with r̂_{x/y} = −r⃗_{y/x}/|r⃗|, by one division: r̂ = r⃗ (1/|r⃗|) and the
        // magnitude (G M m/|r⃗|)/|r⃗|, which overflows in between only when it overflows at the
        // end; in the range where `Vector::unit` divides directly, the unit vector first outside
        let f = if len.re() > 1e-150 && len.re() < 1e150 {
            let inv = T::one() / len;
            (*r_y_x * inv) * (-self.gmm * inv * inv)
        } else {
            let (r_hat, len) = unit_sep(r_y_x, "mutual gravitation")?;
            r_hat * (-self.gmm / len / len)
        };
        finite_or_overflow(f, "mutual gravitation force")
    }
}

impl<T: Scalar> MutualGravitation<T> {
    /// The pair's potential U = −G M m/|r⃗_{y/x}| (8.3.10), with f⃗_{y/x} = −∂U/∂r⃗_{y/x}.
    ///
    /// Book: (8.3.10).
    ///
    /// # Errors
    /// [`StaticsError::NonFinite`] for a non-finite separation, [`StaticsError::CoincidentPoints`]
    /// for r⃗_{y/x} = 0⃗, [`StaticsError::Overflow`] when U exceeds the largest finite number.
    pub fn potential(&self, r_y_x: &Vector<T>) -> Result<T, StaticsError> {
        let (_, len) = unit_sep(r_y_x, "mutual gravitation")?;
        let u = -self.gmm / len;
        if u.re().is_finite() {
            Ok(u)
        } else {
            Err(StaticsError::Overflow { what: "mutual gravitation potential" })
        }
    }
}

impl MutualGravitation<f64> {
    /// The same pair over another scalar (dual numbers for exact derivatives), without checking
    /// again: G M m was checked finite.
    ///
    /// Book: (6.12.1).
    #[inline]
    pub fn cast<U: Scalar>(&self) -> MutualGravitation<U> {
        MutualGravitation { gmm: U::lit(self.gmm) }
    }
}

/// Mutual gravitation of particles y (mass m) and x (mass M): the pair f⃗_{y/x} =
/// (G M m/|r⃗|²) r̂_{x/y} and f⃗_{x/y} = −f⃗_{y/x} (6.12.1, Fact 6.9.1). Pass
/// [`GRAVITATIONAL_CONSTANT`] for G in SI units.
///
/// Book: Fact 6.12.1, (6.12.1).
///
/// # Errors
/// [`StaticsError::InvalidMass`], [`StaticsError::OutOfRange`] for G < 0,
/// [`StaticsError::CoincidentPoints`].
pub fn mutual_gravitation<T: Scalar>(
    g: T,
    m_y: T,
    m_x: T,
    r_y_x: &Vector<T>,
) -> Result<ForcePair<T>, StaticsError> {
    MutualGravitation::new(g, m_y, m_x)?.force_on_y(r_y_x).map(ForcePair::from_force_on_y)
}

/// Potential of mutual gravitation, U = −G M m/|r⃗_{y/x}|.
///
/// Book: (8.3.10).
///
/// # Errors
/// As [`mutual_gravitation`].
pub fn mutual_gravitation_potential<T: Scalar>(
    g: T,
    m_y: T,
    m_x: T,
    r_y_x: &Vector<T>,
) -> Result<T, StaticsError> {
    MutualGravitation::new(g, m_y, m_x)?.potential(r_y_x)
}

/// Central gravitational force on body B₂ due to body B₁ and the weight of B₂ relative to B₁:
/// f⃗_{B₂/B₁} = Σ_i Σ_j (G M_j m_i/|r⃗_{y_i/x_j}|²) r̂_{x_j/y_i} (6.12.6) and
/// w_{B₂/B₁} = Σ_i Σ_j G M_j m_i/|r⃗_{y_i/x_j}|² (6.12.7).
///
/// Book: (6.12.4)–(6.12.7).
///
/// # Errors
/// [`StaticsError::InvalidMass`], [`StaticsError::NonFinite`], [`StaticsError::CoincidentPoints`].
pub fn gravity_between<T: Scalar>(
    g: T,
    b2: &[(T, Point<T>)],
    b1: &[(T, Point<T>)],
) -> Result<(Vector<T>, T), StaticsError> {
    let mut f = Vector::zero();
    let mut w = T::zero();
    for (m_i, y_i) in b2 {
        check_point(y_i, "particle of B₂")?;
        for (big_m, x_j) in b1 {
            check_point(x_j, "particle of B₁")?;
            let f_ij = mutual_gravitation(g, *m_i, *big_m, &y_i.position_rel(x_j))?.on_y;
            f += f_ij;
            w += f_ij.norm();
        }
    }
    if !(f.is_finite() && w.re().is_finite()) {
        return Err(StaticsError::Overflow { what: "total gravitational force or weight" });
    }
    Ok((f, w))
}

/// The centre of gravity g_{B₂/B₁} of B₂ relative to B₁: r⃗_{g/w} = Σ_i w_{y_i/B₁} r⃗_{y_i/w} /
/// w_{B₂/B₁} (6.12.10), independent of w (Fact 6.12.2) and of G. It equals the centre of mass
/// when all distances |r⃗_{y_i/x_j}| are equal (Fact 6.12.5) and tends to it as the bodies
/// separate (Fact 6.12.6).
///
/// Book: Definition 6.12.3, (6.12.10), Facts 6.12.2–6.12.6.
///
/// # Errors
/// As [`gravity_between`]; [`StaticsError::ZeroMass`] when the total weight is zero.
pub fn centre_of_gravity<T: Scalar>(
    b2: &[(T, Point<T>)],
    b1: &[(T, Point<T>)],
) -> Result<Point<T>, StaticsError> {
    // G cancels in (6.12.10): use G = 1.
    let Some((_, y0)) = b2.first() else {
        return Err(StaticsError::ZeroMass { what: "centre of gravity of an empty body" });
    };
    let mut total = T::zero();
    let mut first = Vector::zero();
    for (m_i, y_i) in b2 {
        let (_, w_i) = gravity_between(T::one(), &[(*m_i, *y_i)], b1)?;
        total += w_i;
        // measured from y0 to limit cancellation
        first += y_i.position_rel(y0) * w_i;
    }
    if total.re() <= 0.0 {
        return Err(StaticsError::ZeroMass { what: "centre of gravity (zero total weight)" });
    }
    let c = y0.displaced(first / total);
    if !c.is_finite() {
        return Err(StaticsError::Overflow { what: "centre of gravity (zero or overflowing weight)" });
    }
    Ok(c)
}
