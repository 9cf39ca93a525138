//! Newton–Euler for particles and rigid bodies (book §7.3–7.8).
//!
//! Every quantity here is frame-free: momenta, moments and accelerations are
//! [`Vector`]s, inertia is the physical [`Dyadic`] J⃗_{B/c} of [`MassProperties`]. The
//! gyroscopic term ω⃗ × J⃗ω⃗ is formed once from J⃗ (no resolution), and the rank-aware solve
//! of Euler's equation resolves only inside, in the principal frame.

use vectrix_statics::{INERTIA_REL_TOL, MassProperties, Point, PrincipalAxes, Wrench};
use vectrix_tensor::{Scalar, Vector};

use crate::DynamicsError;

/// Newton's second law for a particle, m a⃗_{y/w/A} = f⃗_y (7.3.1), solved for the
/// acceleration.
///
/// Book: §7.3, (7.3.1).
///
/// # Errors
/// [`DynamicsError::OutOfRange`] unless m > 0 and finite.
pub fn particle_acceleration<T: Scalar>(m: T, f: &Vector<T>) -> Result<Vector<T>, DynamicsError> {
    check_mass(m.re())?;
    if !f.is_finite() {
        return Err(DynamicsError::NonFinite { what: "force f⃗" });
    }
    let a = *f / m;
    if a.is_finite() { Ok(a) } else { Err(DynamicsError::Overflow { what: "acceleration f⃗/m" }) }
}

fn check_mass(m: f64) -> Result<(), DynamicsError> {
    if m.is_finite() && m > 0.0 {
        Ok(())
    } else {
        Err(DynamicsError::OutOfRange { what: "mass", value: m, valid: "a finite number > 0" })
    }
}

/// A rigid body in motion: mass properties (centre c and J⃗_{B/c} at the current attitude),
/// the velocity v⃗_{c/w/A} of its centre of mass and its angular velocity ω⃗_{B/A}, both
/// relative to an inertial frame F_A and an unforced point w.
///
/// Book: §7.4, §7.6, §7.8.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody<T: Scalar = f64> {
    /// m_B, c and J⃗_{B/c}.
    pub props: MassProperties<T>,
    /// v⃗_{c/w/A}.
    pub v_c: Vector<T>,
    /// ω⃗_{B/A}.
    pub omega: Vector<T>,
}

impl<T: Scalar> RigidBody<T> {
    /// A body with mass properties `props`, centre velocity v⃗_{c/w/A} and ω⃗_{B/A}.
    pub fn new(props: MassProperties<T>, v_c: Vector<T>, omega: Vector<T>) -> Self {
        Self { props, v_c, omega }
    }

    /// Linear momentum p⃗_{B/w/A} = m_B v⃗_{c/w/A} (7.4.12).
    ///
    /// Book: §7.4, (7.4.12).
    pub fn momentum(&self) -> Vector<T> {
        self.v_c * self.props.mass()
    }

    /// Velocity of the body point y: v⃗_y = v⃗_c + ω⃗ × r⃗_{y/c} (4.13).
    ///
    /// Book: §4.13, (7.4.16).
    pub fn velocity_of(&self, y: &Point<T>) -> Vector<T> {
        self.v_c + self.omega.cross(&y.position_rel(&self.props.centre_of_mass()))
    }

    /// Angular momentum about c: H⃗_{B/c/A} = J⃗_{B/c} ω⃗_{B/A} (7.8.4 with z = c).
    ///
    /// Book: (7.6.12), (7.8.4).
    pub fn angular_momentum_about_centre(&self) -> Vector<T> {
        self.props.inertia_about_centre().apply(&self.omega)
    }

    /// Angular momentum about any point z moving with velocity v⃗_{z/w/A}:
    /// H⃗_{B/z/A} = Σ r⃗_{y/z} × m v⃗_{y/z/A} = J⃗_{B/c}ω⃗ + r⃗_{c/z} × m_B (v⃗_c − v⃗_z) (7.6.9–10).
    ///
    /// Book: §7.6, (7.6.1), (7.6.3), (7.6.10).
    pub fn angular_momentum_about(&self, z: &Point<T>, v_z: &Vector<T>) -> Vector<T> {
        let r_c_z = self.props.centre_of_mass().position_rel(z);
        self.angular_momentum_about_centre() + r_c_z.cross(&((self.v_c - *v_z) * self.props.mass()))
    }

    /// Kinetic energy T = ½ m_B |v⃗_c|² + ½ ω⃗·J⃗_{B/c}ω⃗ (8.1.19).
    ///
    /// Book: §8.1, (8.1.5), (8.1.19).
    pub fn kinetic_energy(&self) -> T {
        let half = T::lit(0.5);
        half * self.props.mass() * self.v_c.norm_squared()
            + half * self.omega.dot(&self.angular_momentum_about_centre())
    }

    /// Kinetic energy relative to a point z moving with v⃗_z (8.1.4):
    /// T_{/z} = ½ Σ m |v⃗_{y/z}|² = ½ m|v⃗_{c/z}|² + ½ ω⃗·J⃗_{B/c}ω⃗.
    ///
    /// Book: (8.1.4), (8.1.5).
    pub fn kinetic_energy_rel(&self, v_z: &Vector<T>) -> T {
        let half = T::lit(0.5);
        half * self.props.mass() * (self.v_c - *v_z).norm_squared()
            + half * self.omega.dot(&self.angular_momentum_about_centre())
    }

    /// The gyroscopic term ω⃗ × J⃗_{B/c} ω⃗ of Euler's equation, formed once from the
    /// frame-free inertia.
    ///
    /// Book: (7.8.13).
    pub fn gyroscopic_moment(&self) -> Vector<T> {
        self.omega.cross(&self.angular_momentum_about_centre())
    }

    /// Residual of Euler's equation about any body-fixed point z (7.8.7):
    /// J⃗_{B/z} α⃗ + ω⃗ × J⃗_{B/z} ω⃗ + m_B r⃗_{c/z} × a⃗_{z/w/A} − M⃗_{B/z}.
    /// Zero for the true motion. Generic over the scalar (usable with dual numbers).
    ///
    /// Book: §7.8, (7.8.7), (7.8.10) (pivot), (7.8.13) (z = c).
    pub fn euler_residual_about(
        &self,
        z: &Point<T>,
        a_z: &Vector<T>,
        alpha: &Vector<T>,
        m_z: &Vector<T>,
    ) -> Vector<T> {
        let j_z = self.props.inertia_about(z);
        let r_c_z = self.props.centre_of_mass().position_rel(z);
        j_z.apply(alpha) + self.omega.cross(&j_z.apply(&self.omega)) + r_c_z.cross(a_z) * self.props.mass()
            - *m_z
    }

    /// Residual of Newton's second law for a body about a body-fixed point z (7.4.17):
    /// m a⃗_z + α⃗ × m r⃗_{c/z} + ω⃗ × (ω⃗ × m r⃗_{c/z}) − f⃗_B.
    ///
    /// Book: (7.4.7), (7.4.17).
    pub fn newton_residual_about(
        &self,
        z: &Point<T>,
        a_z: &Vector<T>,
        alpha: &Vector<T>,
        f: &Vector<T>,
    ) -> Vector<T> {
        let m = self.props.mass();
        let mr = self.props.centre_of_mass().position_rel(z) * m;
        *a_z * m + alpha.cross(&mr) + self.omega.cross(&self.omega.cross(&mr)) - *f
    }
}

impl RigidBody<f64> {
    /// Accelerations (a⃗_{c/w/A}, α⃗_{B/A}) under a wrench: Newton m_B a⃗_c = f⃗_B (7.4.7) and
    /// Euler J⃗_{B/c} α⃗ + ω⃗ × J⃗_{B/c}ω⃗ = M⃗_{B/c} (7.8.13), after shifting the wrench to c.
    ///
    /// Book: (7.4.7), (7.6.14), (7.8.13); notes ch6-8 §3 (rank-deficient J).
    ///
    /// # Degenerate inputs
    /// Rank-aware, never a blind J⁻¹: Euler's equation is solved on the range of J⃗_{B/c}
    /// (principal frame, moments below `INERTIA_REL_TOL`·λ1 count as zero). Along a null
    /// axis ê (the axis of a thin rod) α⃗·ê = 0, which keeps the axial spin ω⃗·ê constant: the
    /// axial spin of a rod is inert. A particle (rank 0) has α⃗ = 0.
    ///
    /// # Errors
    /// [`DynamicsError::NonFinite`]; [`DynamicsError::TorqueOnInertAxis`] when M⃗_{B/c} has a
    /// component about a null axis larger than `INERTIA_REL_TOL`·|M⃗| + ε (no thin body can
    /// take it); inertia errors from the statics layer.
    pub fn accelerations(&self, wrench: &Wrench) -> Result<(Vector, Vector), DynamicsError> {
        let c = self.props.centre_of_mass();
        let w = wrench.shift_to(&c);
        if !(w.force.is_finite() && w.moment.is_finite() && self.v_c.is_finite() && self.omega.is_finite()) {
            return Err(DynamicsError::NonFinite { what: "rigid-body state or wrench" });
        }
        // (7.4.7): m_B a_c = f_B
        let a_c = w.force / self.props.mass();
        // (7.8.13): J α = M_{/c} − ω × Jω, solved on range(J)
        let rhs = w.moment - self.gyroscopic_moment();
        let alpha = solve_on_range(&self.props, &rhs)?;
        Ok((a_c, alpha))
    }
}

/// Solves J⃗_{B/c} α⃗ = rhs on the range of J⃗ (minimum-norm solution), in the principal frame.
pub(crate) fn solve_on_range(props: &MassProperties, rhs: &Vector) -> Result<Vector, DynamicsError> {
    let pa = PrincipalAxes::of(&props.inertia_about_centre(), INERTIA_REL_TOL)?;
    let e = [pa.frame.i(), pa.frame.j(), pa.frame.k()];
    let scale = rhs.norm();
    let mut alpha = Vector::zero();
    for (lam, axis) in pa.moments.iter().zip(e) {
        let r = rhs.dot(&axis);
        if *lam > 0.0 {
            alpha += axis * (r / lam);
        } else if r.abs() > INERTIA_REL_TOL * scale + f64::EPSILON {
            // null axis of a thin body (or a particle): no torque may act about it
            return Err(DynamicsError::TorqueOnInertAxis { component: r, moments: pa.moments });
        }
    }
    Ok(alpha)
}
