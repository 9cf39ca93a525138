//! The nonlinear 12-state equations of motion (11.5.1–14), built on the rigid-body
//! equations of `vectrix-dynamics`: the gyroscopic term ω⃗ × J⃗ω⃗ of Euler's equation comes
//! from [`RigidBody::gyroscopic_moment`], and Newton's law in the rotating aircraft frame is
//! m(v̇|_AC + ω × v) = f (transport theorem).
//!
//! Book: §11.1–11.5, (11.1.21), (11.2.9), (11.2.11), (11.3.6), (11.5.1)–(11.5.16).
//!
//! # Conventions
//! State x = [X Y Z U V W Φ Θ Ψ P Q R] (11.5.1); forces in the wind frame
//! F⃗_A = −Dî_W − Eĵ_W − Lk̂_W (11.1.5); thrust F_T along a line tilted up by Φ_T from î_AC
//! (11.2.11). Roll, pitch and yaw moments are named `roll`, `pitch`, `yaw` (the book's L
//! clashes with lift).

use nalgebra::{Matrix3, Vector3};
use vectrix_dynamics::RigidBody;
use vectrix_frames::Frame;
use vectrix_statics::{MassProperties, Point};
use vectrix_tensor::Scalar;

use crate::{AeroAngles, Euler321, FlightError, o_w_ac};

/// Mass and inertia of an aircraft with a plane of symmetry:
/// J|_AC = [[J_xx, 0, −J_xz], [0, J_yy, 0], [−J_xz, 0, J_zz]] (11.3.6), J_xz = ∫xz dm.
///
/// Book: (11.3.6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Airframe {
    mass: f64,
    jxx: f64,
    jyy: f64,
    jzz: f64,
    jxz: f64,
}

impl Airframe {
    /// Validated mass properties (mass in slug or kg, inertia in slug·ft² or kg·m²).
    ///
    /// Book: (11.3.6); Fact 6.2.7 (inertia PSD, triangle inequalities).
    ///
    /// # Errors
    /// [`FlightError::OutOfRange`] for a mass or moment of inertia that is not finite
    /// and > 0, or an inertia matrix that is not a physical inertia (checked by
    /// `vectrix-statics`: positive definite, λ₁ ≤ λ₂ + λ₃).
    pub fn new(mass: f64, jxx: f64, jyy: f64, jzz: f64, jxz: f64) -> Result<Self, FlightError> {
        for (what, value) in [("mass", mass), ("J_xx", jxx), ("J_yy", jyy), ("J_zz", jzz)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(FlightError::OutOfRange { what, value, valid: "a finite number > 0" });
            }
        }
        if !jxz.is_finite() || jxx * jzz <= jxz * jxz {
            return Err(FlightError::OutOfRange {
                what: "J_xz",
                value: jxz,
                valid: "finite with J_xz² < J_xx J_zz (positive-definite inertia)",
            });
        }
        let a = Self { mass, jxx, jyy, jzz, jxz };
        a.mass_properties::<f64>().map_err(|_| FlightError::OutOfRange {
            what: "inertia",
            value: jxz,
            valid: "a physical inertia (each principal moment ≤ the sum of the other two)",
        })?;
        Ok(a)
    }

    /// Mass m.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// J|_AC as a matrix (11.3.6).
    pub fn inertia_matrix(&self) -> Matrix3<f64> {
        Matrix3::new(self.jxx, 0.0, -self.jxz, 0.0, self.jyy, 0.0, -self.jxz, 0.0, self.jzz)
    }

    /// (J_xx, J_yy, J_zz, J_xz).
    pub fn inertia(&self) -> (f64, f64, f64, f64) {
        (self.jxx, self.jyy, self.jzz, self.jxz)
    }

    fn mass_properties<T: Scalar>(&self) -> Result<MassProperties<T>, FlightError> {
        let f = Frame::<T>::identity();
        let j = self.inertia_matrix().map(T::lit);
        MassProperties::new(T::lit(self.mass), Point::origin(), f.dyadic(&j)).map_err(|_| {
            FlightError::OutOfRange { what: "inertia", value: self.jxz, valid: "a physical inertia" }
        })
    }
}

/// The 12-state vector of (11.5.1).
///
/// Book: (11.5.1).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AircraftState<T: Scalar = f64> {
    /// r|_E = [X, Y, Z] (range, drift, plunge; altitude H = −Z).
    pub position: [T; 3],
    /// v|_AC = [U, V, W].
    pub velocity: [T; 3],
    /// (Ψ, Θ, Φ).
    pub attitude: Euler321<T>,
    /// ω_{AC/E}|_AC = [P, Q, R].
    pub omega: [T; 3],
}

impl<T: Scalar> AircraftState<T> {
    /// x = [X Y Z U V W Φ Θ Ψ P Q R] (11.5.1).
    pub fn to_array(&self) -> [T; 12] {
        let [x, y, z] = self.position;
        let [u, v, w] = self.velocity;
        let e = self.attitude;
        let [p, q, r] = self.omega;
        [x, y, z, u, v, w, e.phi, e.theta, e.psi, p, q, r]
    }

    /// The state of x = [X Y Z U V W Φ Θ Ψ P Q R] (11.5.1).
    pub fn from_array(x: [T; 12]) -> Self {
        Self {
            position: [x[0], x[1], x[2]],
            velocity: [x[3], x[4], x[5]],
            attitude: Euler321::new(x[8], x[7], x[6]),
            omega: [x[9], x[10], x[11]],
        }
    }

    /// α, β and V_AC of the body velocity (11.5.15–16).
    pub fn aero_angles(&self) -> AeroAngles<T> {
        AeroAngles::from_body_velocity(self.velocity)
    }
}

/// Applied forces and moments, the inputs u = [D L F_T L_AC M_AC N_AC] of (11.5.2) plus the
/// side drag E.
///
/// Book: (11.1.5), (11.2.11), (11.3.13), (11.5.2).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ForcesMoments<T: Scalar = f64> {
    /// Drag D (> 0 opposes the velocity).
    pub drag: T,
    /// Side drag E (F⃗ has −E ĵ_W).
    pub side_drag: T,
    /// Lift L (F⃗ has −L k̂_W).
    pub lift: T,
    /// Thrust F_T.
    pub thrust: T,
    /// Thrust-line angle Φ_T above î_AC (11.2.11).
    pub thrust_angle: T,
    /// Rolling moment L_AC about î_AC (aerodynamic plus thrust).
    pub roll: T,
    /// Pitching moment M_AC about ĵ_AC.
    pub pitch: T,
    /// Yawing moment N_AC about k̂_AC.
    pub yaw: T,
}

/// ẋ = f(x, u) of (11.5.3–14) for gravity g (k̂_E down).
///
/// Book: (11.5.3)–(11.5.14); (10.9.9) for the attitude rates.
///
/// # Errors
/// [`FlightError::GimbalLock`] at Θ = ±90° (use quaternion rates there);
/// [`FlightError::NonFinite`].
pub fn state_derivative<T: Scalar>(
    airframe: &Airframe,
    g: f64,
    x: &AircraftState<T>,
    fm: &ForcesMoments<T>,
) -> Result<AircraftState<T>, FlightError> {
    let o_ac_e = x.attitude.o_ac_e();
    let v = Vector3::from(x.velocity);
    let omega = Vector3::from(x.omega);
    let m = T::lit(airframe.mass);
    // (11.5.3): [Ẋ, Ẏ, Ż] = 𝓞_{E/AC}[U, V, W]
    let r_dot = o_ac_e.transpose() * v;
    // (11.1.5), (11.1.21): F_A|_AC = 𝓞_{W/AC}ᵀ [−D, −E, −L]
    let a = x.aero_angles();
    let f_aero = o_w_ac(a.alpha, a.beta).transpose() * Vector3::new(-fm.drag, -fm.side_drag, -fm.lift);
    // (11.2.11): F_T|_AC = F_T [cos Φ_T, 0, −sin Φ_T]
    let f_thrust = Vector3::new(fm.thrust_angle.cos(), T::zero(), -fm.thrust_angle.sin()) * fm.thrust;
    // (11.2.9): g|_AC = 𝓞_{AC/E}[0, 0, g]
    let g_ac = o_ac_e * Vector3::new(T::zero(), T::zero(), T::lit(g));
    // (11.5.6–8): v̇|_AC = −ω × v + F/m + g (Newton in the rotating frame, transport theorem)
    let v_dot = -omega.cross(&v) + (f_aero + f_thrust) / m + g_ac;
    // (11.5.12–14): J ω̇ = M − ω × Jω, with ω × Jω from the dynamics crate's rigid body
    let frame = Frame::<T>::identity();
    let body =
        RigidBody::new(airframe.mass_properties::<T>()?, frame.vector(x.velocity), frame.vector(x.omega));
    let gyro = vectrix_frames::Resolve::resolve(&body.gyroscopic_moment(), &frame);
    let rhs = Vector3::new(fm.roll, fm.pitch, fm.yaw) - gyro;
    let (jxx, jyy, jzz, jxz) = airframe.inertia();
    let gamma = T::lit(jxx * jzz - jxz * jxz);
    // J⁻¹ = [[J_zz, 0, J_xz], [0, Γ/J_yy, 0], [J_xz, 0, J_xx]]/Γ, Γ = J_xx J_zz − J_xz²
    let omega_dot = Vector3::new(
        (T::lit(jzz) * rhs[0] + T::lit(jxz) * rhs[2]) / gamma,
        rhs[1] / T::lit(jyy),
        (T::lit(jxz) * rhs[0] + T::lit(jxx) * rhs[2]) / gamma,
    );
    let [phi_dot, theta_dot, psi_dot] = crate::euler_rates(&x.attitude, x.omega)?;
    let out = AircraftState {
        position: [r_dot[0], r_dot[1], r_dot[2]],
        velocity: [v_dot[0], v_dot[1], v_dot[2]],
        attitude: Euler321::new(psi_dot, theta_dot, phi_dot),
        omega: [omega_dot[0], omega_dot[1], omega_dot[2]],
    };
    if out.to_array().iter().any(|z| !z.re().is_finite()) {
        return Err(FlightError::NonFinite { what: "state derivative (state or forces)" });
    }
    Ok(out)
}
