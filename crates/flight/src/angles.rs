//! Aircraft frames and angles: earth, intermediate, aircraft, stability and wind frames;
//! angle of attack and sideslip; heading, flight-path and bank angles.
//!
//! Book: §10.2–10.8, (10.3.9)–(10.3.17), (10.4.8), (10.5.5), (10.6.18), (10.6.27), (10.6.28),
//! (10.8.1)–(10.8.4), Facts 10.8.1–10.8.8.
//!
//! # Conventions
//! Orientation matrices are passive: x|_B = 𝓞_{B/A} x|_A. 𝓞₁, 𝓞₂, 𝓞₃ are the elementary
//! passive matrices (10.3.9–11). F_E has k̂_E down; F_E →(Ψ, k̂) F_E′ →(Θ, ĵ) F_E″ →(Φ, î) F_AC
//! (10.3.5), so 𝓞_{AC/E} = 𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ). F_S = F_AC turned by −α about ĵ_AC; F_W = F_S
//! turned by β about k̂_S. Angles are in radians.

use nalgebra::Matrix3;
use vectrix_tensor::Scalar;

/// 𝓞₁(x) = [[1, 0, 0], [0, c, s], [0, −s, c]] (10.3.9).
///
/// Book: (10.3.9).
pub fn o1<T: Scalar>(x: T) -> Matrix3<T> {
    let (s, c) = (x.sin(), x.cos());
    let (z, one) = (T::zero(), T::one());
    Matrix3::new(one, z, z, z, c, s, z, -s, c)
}

/// 𝓞₂(x) = [[c, 0, −s], [0, 1, 0], [s, 0, c]] (10.3.10).
///
/// Book: (10.3.10).
pub fn o2<T: Scalar>(x: T) -> Matrix3<T> {
    let (s, c) = (x.sin(), x.cos());
    let (z, one) = (T::zero(), T::one());
    Matrix3::new(c, z, -s, z, one, z, s, z, c)
}

/// 𝓞₃(x) = [[c, s, 0], [−s, c, 0], [0, 0, 1]] (10.3.11).
///
/// Book: (10.3.11).
pub fn o3<T: Scalar>(x: T) -> Matrix3<T> {
    let (s, c) = (x.sin(), x.cos());
    let (z, one) = (T::zero(), T::one());
    Matrix3::new(c, s, z, -s, c, z, z, z, one)
}

/// 3-2-1 Euler angles of an aircraft relative to the earth frame: heading Ψ, pitch Θ, bank Φ.
///
/// Book: §10.3, (10.3.5).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Euler321<T: Scalar = f64> {
    /// Ψ (heading), about k̂_E.
    pub psi: T,
    /// Θ (pitch), about ĵ_E′.
    pub theta: T,
    /// Φ (bank), about î_E″.
    pub phi: T,
}

impl<T: Scalar> Euler321<T> {
    /// Angles (Ψ, Θ, Φ) in the order applied.
    pub fn new(psi: T, theta: T, phi: T) -> Self {
        Self { psi, theta, phi }
    }

    /// 𝓞_{AC/E} = 𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ) (10.3.16); 𝓞_{E/AC} is its transpose (10.3.17).
    ///
    /// Book: (10.3.16), (10.3.17).
    pub fn o_ac_e(&self) -> Matrix3<T> {
        o1(self.phi) * o2(self.theta) * o3(self.psi)
    }

    /// The 3-2-1 angles of an orientation matrix 𝓞 = 𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ), by atan2:
    /// Θ = atan2(−𝓞₁₃, √(𝓞₁₁² + 𝓞₁₂²)) ∈ [−π/2, π/2], Ψ = atan2(𝓞₁₂, 𝓞₁₁), Φ = atan2(𝓞₂₃, 𝓞₃₃).
    ///
    /// Book: (10.3.16).
    ///
    /// # Degenerate inputs
    /// At Θ = ±π/2 only Ψ ∓ Φ is defined; this returns the atan2 values of the rounded
    /// entries (no NaN).
    pub fn from_orientation(o: &Matrix3<T>) -> Self {
        let theta = (-o[(0, 2)]).atan2((o[(0, 0)] * o[(0, 0)] + o[(0, 1)] * o[(0, 1)]).sqrt());
        Self { psi: o[(0, 1)].atan2(o[(0, 0)]), theta, phi: o[(1, 2)].atan2(o[(2, 2)]) }
    }
}

/// Airspeed, angle of attack and sideslip.
///
/// Book: §10.6, (10.6.18), (10.6.27), (10.6.28).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AeroAngles<T: Scalar = f64> {
    /// V_AC = |v⃗| ≥ 0.
    pub airspeed: T,
    /// α = atan2(W, U) ∈ (−π, π].
    pub alpha: T,
    /// β = atan2(V, √(U² + W²)) ∈ [−π/2, π/2].
    pub beta: T,
}

impl<T: Scalar> AeroAngles<T> {
    /// α and β of the body velocity [U, V, W] = v⃗|_AC (10.6.18), (10.6.27).
    ///
    /// Book: (10.6.18), (10.6.27).
    ///
    /// # Degenerate inputs
    /// At U = W = 0 the book sets α = 0 (F_S = F_AC); at zero speed also β = 0. The
    /// derivative of α at U = W = 0 is undefined (dual parts there are those of atan2(0, 0)).
    pub fn from_body_velocity(uvw: [T; 3]) -> Self {
        let [u, v, w] = uvw;
        let zero = T::zero();
        // Ū = √(U² + W²) and V_AC = √(Ū² + V²) by hypot: no underflow of U² for tiny speeds
        // nor overflow for huge ones. The zero branches keep dual numbers differentiable.
        let planar_zero = u.re() == 0.0 && w.re() == 0.0;
        // α undefined when the velocity has no component in the plane of symmetry: α = 0
        let alpha = if planar_zero { zero } else { w.atan2(u) };
        let u_bar = if planar_zero { zero } else { u.hypot(w) };
        let beta = if planar_zero && v.re() == 0.0 { zero } else { v.atan2(u_bar) };
        let airspeed = if planar_zero { v.abs() } else { u_bar.hypot(v) };
        Self { airspeed, alpha, beta }
    }

    /// [U, V, W] = V_AC [cos α cos β, sin β, sin α cos β] (10.6.28).
    ///
    /// Book: (10.6.28).
    pub fn body_velocity(&self) -> [T; 3] {
        let (sa, ca) = (self.alpha.sin(), self.alpha.cos());
        let (sb, cb) = (self.beta.sin(), self.beta.cos());
        [self.airspeed * ca * cb, self.airspeed * sb, self.airspeed * sa * cb]
    }
}

/// 𝓞_{S/AC} = 𝓞₂(−α) (10.4.8).
///
/// Book: (10.4.8), (10.4.11).
pub fn o_s_ac<T: Scalar>(alpha: T) -> Matrix3<T> {
    o2(-alpha)
}

/// 𝓞_{W/S} = 𝓞₃(β) (10.5.5).
///
/// Book: (10.5.5).
pub fn o_w_s<T: Scalar>(beta: T) -> Matrix3<T> {
    o3(beta)
}

/// 𝓞_{W/AC} = 𝓞₃(β)𝓞₂(−α).
///
/// Book: (10.5.5), (10.5.10).
pub fn o_w_ac<T: Scalar>(alpha: T, beta: T) -> Matrix3<T> {
    o3(beta) * o2(-alpha)
}

/// Heading η, flight-path angle γ and bank μ of the velocity: F_E →(η,3) F_F →(γ,2) F_G
/// →(μ,1) F_W (10.8.1).
///
/// Book: §10.8, (10.8.1)–(10.8.4).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FlightPathAngles<T: Scalar = f64> {
    /// η, heading of the velocity.
    pub eta: T,
    /// γ, flight-path (climb) angle.
    pub gamma: T,
    /// μ, bank angle about the velocity.
    pub mu: T,
}

impl<T: Scalar> FlightPathAngles<T> {
    /// (η, γ, μ) from the attitude and the aerodynamic angles, by solving
    /// 𝓞₁(μ)𝓞₂(γ)𝓞₃(η) = 𝓞₃(β)𝓞₂(−α)𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ) (10.8.4) with atan2.
    ///
    /// Book: (10.8.4), Facts 10.8.1–10.8.8.
    ///
    /// # Degenerate inputs
    /// At γ = ±π/2 (vertical flight path) only η ∓ μ is defined.
    pub fn from_attitude(euler: &Euler321<T>, alpha: T, beta: T) -> Self {
        let o_w_e = o_w_ac(alpha, beta) * euler.o_ac_e();
        let e = Euler321::from_orientation(&o_w_e);
        Self { eta: e.psi, gamma: e.theta, mu: e.phi }
    }

    /// 𝓞_{W/E} = 𝓞₁(μ)𝓞₂(γ)𝓞₃(η).
    ///
    /// Book: (10.8.4).
    pub fn o_w_e(&self) -> Matrix3<T> {
        o1(self.mu) * o2(self.gamma) * o3(self.eta)
    }
}
