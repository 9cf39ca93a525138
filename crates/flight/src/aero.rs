//! Aerodynamic model from nondimensional stability and control derivatives, the drag polar,
//! static margin, and an aircraft that ties the model to the equations of motion.
//!
//! Book: §13.1–13.6, (13.3.2)–(13.3.13), Table 13.3, (13.5.30).
//!
//! # Conventions
//! Dynamic pressure p_d = ½ρV². C_L = L/(p_d S), C_D = D/(p_d S), C_E = E/(p_d S);
//! C_l = L_A/(p_d S b), C_m = M_A/(p_d S c̄), C_n = N_A/(p_d S b). Rates enter through the
//! nondimensional variables c̄Q/2V, c̄α̇/2V, bP/2V, bR/2V, bβ̇/2V (13.3.2–8). Controls
//! (Ch. 13 intro): δe > 0 trailing edge down, δa > 0 right aileron up, δr > 0 trailing edge
//! left. The aircraft's body frame is the one the coefficients are referred to; choose the
//! stability frame of the trim (§12.4) to compare with Tables 14.1–14.2.

use vectrix_tensor::Scalar;

use crate::{AircraftState, Airframe, FlightError, ForcesMoments, state_derivative};

/// Wing area S, mean aerodynamic chord c̄ and span b.
///
/// Book: §13.1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry {
    /// Wing area S.
    pub area: f64,
    /// Mean aerodynamic chord c̄.
    pub chord: f64,
    /// Span b.
    pub span: f64,
}

impl Geometry {
    /// Aspect ratio AR = b²/S (13.3.10).
    ///
    /// Book: (13.3.10).
    pub fn aspect_ratio(&self) -> f64 {
        self.span * self.span / self.area
    }
}

/// Induced-drag factor K = 1/(π e AR) of the drag polar C_D = C_Dpar + K C_L² (13.3.9–10).
///
/// Book: (13.3.9), (13.3.10).
pub fn induced_drag_factor(oswald: f64, aspect_ratio: f64) -> f64 {
    1.0 / (std::f64::consts::PI * oswald * aspect_ratio)
}

/// C_mα = ((x_c − x_ac)/c̄) C_Lα (13.5.30): negative (statically stable) iff the centre of
/// mass is ahead of the aerodynamic centre. x_c and x_ac are measured aft from the wing's
/// leading edge (the book's chordwise stations), so "ahead" means x_c < x_ac.
///
/// Book: (13.5.30).
pub fn cm_alpha_from_static_margin(x_c: f64, x_ac: f64, chord: f64, cl_alpha: f64) -> f64 {
    (x_c - x_ac) / chord * cl_alpha
}

/// Static margin (x_ac − x_c)/c̄ = −C_mα/C_Lα (positive = statically stable) of (13.5.30).
///
/// Book: (13.5.30).
pub fn static_margin(cm_alpha: f64, cl_alpha: f64) -> f64 {
    -cm_alpha / cl_alpha
}

/// Nondimensional stability and control derivatives (absolute, about α = β = 0 of the body
/// frame). Names: `cl_*` lift, `cd_par`/`k_induced` drag polar, `cm_*` pitch, `ce_*` side
/// drag, `croll_*` roll (the book's C_l), `cn_*` yaw.
///
/// Book: §13.3–13.5, Tables 13.1–13.3.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[allow(missing_docs)] // each field is the book's coefficient, named in the struct doc above
pub struct Coefficients {
    /// Reference speed U_ref of the speed derivatives C_•u = ∂C_•/∂(u/U_ref) (13.3.2); set it
    /// to the trim speed U₀ (0 disables the speed terms).
    pub u_ref: f64,
    pub cl0: f64,
    pub cl_u: f64,
    pub cl_alpha: f64,
    pub cl_q: f64,
    pub cl_alpha_dot: f64,
    pub cl_de: f64,
    /// Parasite drag C_Dpar of the polar (13.3.9).
    pub cd_par: f64,
    /// K of the polar (13.3.9).
    pub k_induced: f64,
    /// Speed derivative of drag other than through the polar.
    pub cd_u: f64,
    pub cm0: f64,
    pub cm_u: f64,
    pub cm_alpha: f64,
    pub cm_q: f64,
    pub cm_alpha_dot: f64,
    pub cm_de: f64,
    pub ce_beta: f64,
    pub ce_beta_dot: f64,
    pub ce_p: f64,
    pub ce_r: f64,
    pub ce_da: f64,
    pub ce_dr: f64,
    pub croll_beta: f64,
    pub croll_beta_dot: f64,
    pub croll_p: f64,
    pub croll_r: f64,
    pub croll_da: f64,
    pub croll_dr: f64,
    pub cn_beta: f64,
    pub cn_beta_dot: f64,
    pub cn_p: f64,
    pub cn_r: f64,
    pub cn_da: f64,
    pub cn_dr: f64,
}

/// Control settings [δe, δa, δr, F_T].
///
/// Book: Ch. 13 intro (signs), (11.5.2).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Controls<T: Scalar = f64> {
    /// Elevator δe (rad, trailing edge down positive).
    pub elevator: T,
    /// Aileron δa (rad, right aileron up positive).
    pub aileron: T,
    /// Rudder δr (rad, trailing edge left positive).
    pub rudder: T,
    /// Thrust F_T.
    pub thrust: T,
}

impl<T: Scalar> Controls<T> {
    /// [δe, δa, δr, F_T].
    pub fn to_array(&self) -> [T; 4] {
        [self.elevator, self.aileron, self.rudder, self.thrust]
    }
    /// From [δe, δa, δr, F_T].
    pub fn from_array(u: [T; 4]) -> Self {
        Self { elevator: u[0], aileron: u[1], rudder: u[2], thrust: u[3] }
    }
}

/// An aircraft: airframe, geometry, aerodynamic coefficients, air density, gravity and
/// thrust-line angle.
///
/// Book: §11.5, §13.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aircraft {
    /// Mass and inertia.
    pub airframe: Airframe,
    /// S, c̄, b.
    pub geometry: Geometry,
    /// Nondimensional derivatives.
    pub coefficients: Coefficients,
    /// Air density ρ (constant: flat Earth, fixed altitude band).
    pub rho: f64,
    /// Gravity g.
    pub g: f64,
    /// Thrust-line angle Φ_T (11.2.11).
    pub thrust_angle: f64,
}

impl Aircraft {
    /// Checks that every coefficient and parameter is finite and ρ, g, S, c̄, b > 0.
    ///
    /// # Errors
    /// [`FlightError::NonFinite`] for a non-finite coefficient; [`FlightError::OutOfRange`]
    /// for a non-positive density, gravity or geometry.
    pub fn check(&self) -> Result<(), FlightError> {
        let c = &self.coefficients;
        let all = [
            c.u_ref,
            c.cl0,
            c.cl_u,
            c.cl_alpha,
            c.cl_q,
            c.cl_alpha_dot,
            c.cl_de,
            c.cd_par,
            c.k_induced,
            c.cd_u,
            c.cm0,
            c.cm_u,
            c.cm_alpha,
            c.cm_q,
            c.cm_alpha_dot,
            c.cm_de,
            c.ce_beta,
            c.ce_beta_dot,
            c.ce_p,
            c.ce_r,
            c.ce_da,
            c.ce_dr,
            c.croll_beta,
            c.croll_beta_dot,
            c.croll_p,
            c.croll_r,
            c.croll_da,
            c.croll_dr,
            c.cn_beta,
            c.cn_beta_dot,
            c.cn_p,
            c.cn_r,
            c.cn_da,
            c.cn_dr,
            self.thrust_angle,
        ];
        if all.iter().any(|v| !v.is_finite()) {
            return Err(FlightError::NonFinite { what: "aerodynamic coefficients" });
        }
        let g = &self.geometry;
        for (what, value) in [
            ("ρ", self.rho),
            ("g", self.g),
            ("wing area S", g.area),
            ("chord c̄", g.chord),
            ("span b", g.span),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(FlightError::OutOfRange { what, value, valid: "a finite number > 0" });
            }
        }
        Ok(())
    }

    /// Dynamic pressure p_d = ½ρV² (13.3.1).
    ///
    /// Book: §13.3.
    pub fn dynamic_pressure<T: Scalar>(&self, airspeed: T) -> T {
        T::lit(0.5 * self.rho) * airspeed * airspeed
    }

    /// (V − U_ref)/U_ref, the nondimensional speed perturbation u/U₀ (0 if U_ref = 0).
    fn speed_ratio<T: Scalar>(&self, airspeed: T) -> T {
        let u_ref = self.coefficients.u_ref;
        if u_ref == 0.0 { T::zero() } else { airspeed / T::lit(u_ref) - T::one() }
    }

    /// The "wing" lift C_L0 + C_Lu u/U₀ + C_Lα α that drives the induced drag K C_Lw² of the
    /// polar: as in Tables 14.1, lift from q, α̇ and δe is taken to add no drag
    /// (C_Dq = C_Dα̇ = C_Dδe = 0, so X_q = X_α̇ = X_δe = 0).
    ///
    /// Book: (13.3.9)–(13.3.12), Table 14.1.
    pub fn wing_lift_coefficient<T: Scalar>(&self, x: &AircraftState<T>) -> T {
        let c = &self.coefficients;
        let a = x.aero_angles();
        T::lit(c.cl0) + T::lit(c.cl_u) * self.speed_ratio(a.airspeed) + T::lit(c.cl_alpha) * a.alpha
    }

    /// Lift coefficient C_L = C_L0 + C_Lu u/U₀ + C_Lα α + C_Lq c̄Q/2V + C_Lα̇ c̄α̇/2V + C_Lδe δe.
    ///
    /// Book: (13.3.2)–(13.3.8).
    pub fn lift_coefficient<T: Scalar>(&self, x: &AircraftState<T>, u: &Controls<T>, alpha_dot: T) -> T {
        let c = &self.coefficients;
        let a = x.aero_angles();
        let half_c_over_v = T::lit(0.5 * self.geometry.chord) / a.airspeed;
        self.wing_lift_coefficient(x)
            + T::lit(c.cl_q) * half_c_over_v * x.omega[1]
            + T::lit(c.cl_alpha_dot) * half_c_over_v * alpha_dot
            + T::lit(c.cl_de) * u.elevator
    }

    /// Aerodynamic and thrust forces and moments at a state, for given α̇ and β̇.
    ///
    /// Book: (11.1.5), (11.3.13), §13.3–13.5; drag polar (13.3.9).
    pub fn forces<T: Scalar>(
        &self,
        x: &AircraftState<T>,
        u: &Controls<T>,
        alpha_dot: T,
        beta_dot: T,
    ) -> ForcesMoments<T> {
        let c = &self.coefficients;
        let geo = &self.geometry;
        let a = x.aero_angles();
        let [p, _, r] = x.omega;
        let lit = T::lit;
        let qs = self.dynamic_pressure(a.airspeed) * lit(geo.area);
        let half_c = lit(0.5 * geo.chord) / a.airspeed;
        let half_b = lit(0.5 * geo.span) / a.airspeed;
        let cl = self.lift_coefficient(x, u, alpha_dot);
        // (13.3.9): drag polar on the wing lift
        let clw = self.wing_lift_coefficient(x);
        let du = self.speed_ratio(a.airspeed);
        let cd = lit(c.cd_par) + lit(c.cd_u) * du + lit(c.k_induced) * clw * clw;
        let cm = lit(c.cm0)
            + lit(c.cm_u) * du
            + lit(c.cm_alpha) * a.alpha
            + lit(c.cm_q) * half_c * x.omega[1]
            + lit(c.cm_alpha_dot) * half_c * alpha_dot
            + lit(c.cm_de) * u.elevator;
        let lateral = |beta: f64, beta_dot_c: f64, cp: f64, cr: f64, da: f64, dr: f64| {
            lit(beta) * a.beta
                + lit(beta_dot_c) * half_b * beta_dot
                + lit(cp) * half_b * p
                + lit(cr) * half_b * r
                + lit(da) * u.aileron
                + lit(dr) * u.rudder
        };
        let ce = lateral(c.ce_beta, c.ce_beta_dot, c.ce_p, c.ce_r, c.ce_da, c.ce_dr);
        let croll = lateral(c.croll_beta, c.croll_beta_dot, c.croll_p, c.croll_r, c.croll_da, c.croll_dr);
        let cn = lateral(c.cn_beta, c.cn_beta_dot, c.cn_p, c.cn_r, c.cn_da, c.cn_dr);
        ForcesMoments {
            drag: qs * cd,
            side_drag: qs * ce,
            lift: qs * cl,
            thrust: u.thrust,
            thrust_angle: lit(self.thrust_angle),
            roll: qs * lit(geo.span) * croll,
            pitch: qs * lit(geo.chord) * cm,
            yaw: qs * lit(geo.span) * cn,
        }
    }

    /// Residual F(ẋ, x, u) = ẋ − f(x, u, α̇(ẋ, x), β̇(ẋ, x)) of the implicit equations of
    /// motion (α̇ and β̇ terms make them implicit), with
    /// α̇ = (UẆ − WU̇)/(U² + W²), β̇ = (ŪV̇ − VŪ̇)/(Ū² + V²), Ū = √(U² + W²).
    ///
    /// Book: (11.5.3)–(11.5.16); notes ch9-14 §3 (implicit α̇/β̇ dependence).
    ///
    /// # Errors
    /// As [`state_derivative`].
    pub fn residual<T: Scalar>(
        &self,
        x_dot: &AircraftState<T>,
        x: &AircraftState<T>,
        u: &Controls<T>,
    ) -> Result<[T; 12], FlightError> {
        let (alpha_dot, beta_dot) = aero_angle_rates(x, x_dot);
        let f = state_derivative(&self.airframe, self.g, x, &self.forces(x, u, alpha_dot, beta_dot))?;
        let (xd, fa) = (x_dot.to_array(), f.to_array());
        Ok(std::array::from_fn(|i| xd[i] - fa[i]))
    }

    /// Explicit ẋ = f(x, u): α̇ and β̇ are found by fixed-point iteration (contracting when
    /// |Z_α̇| ≪ U₀ and |Y_β̇| ≪ U₀, as for every real aircraft).
    ///
    /// Book: (11.5.3)–(11.5.16).
    ///
    /// # Errors
    /// [`FlightError::OutOfRange`] at zero airspeed (coefficients are undefined);
    /// [`FlightError::TrimFailed`]-style non-convergence is reported as
    /// [`FlightError::NonFinite`]; errors of [`state_derivative`].
    pub fn dynamics(&self, x: &AircraftState, u: &Controls) -> Result<AircraftState, FlightError> {
        let v = x.aero_angles().airspeed;
        if v.is_nan() || v <= 0.0 {
            return Err(FlightError::OutOfRange { what: "airspeed", value: v, valid: "V > 0" });
        }
        let (mut ad, mut bd) = (0.0, 0.0);
        for _ in 0..60 {
            let f = state_derivative(&self.airframe, self.g, x, &self.forces(x, u, ad, bd))?;
            let (ad1, bd1) = aero_angle_rates(x, &f);
            if (ad1 - ad).abs() <= 4.0 * f64::EPSILON * (1.0 + ad1.abs())
                && (bd1 - bd).abs() <= 4.0 * f64::EPSILON * (1.0 + bd1.abs())
            {
                return Ok(f);
            }
            (ad, bd) = (ad1, bd1);
        }
        let f = state_derivative(&self.airframe, self.g, x, &self.forces(x, u, ad, bd))?;
        let (ad1, bd1) = aero_angle_rates(x, &f);
        if (ad1 - ad).abs() <= 1e-10 * (1.0 + ad.abs()) && (bd1 - bd).abs() <= 1e-10 * (1.0 + bd.abs()) {
            Ok(f)
        } else {
            Err(FlightError::NonFinite {
                what: "α̇/β̇ fixed point (|Z_α̇| or |Y_β̇| too close to U₀)"
            })
        }
    }
}

/// α̇ and β̇ from the body velocity and its derivative (time derivatives of (10.6.18), (10.6.27)).
///
/// Book: (10.6.18), (10.6.27), (10.9.18).
pub fn aero_angle_rates<T: Scalar>(x: &AircraftState<T>, x_dot: &AircraftState<T>) -> (T, T) {
    let [u, v, w] = x.velocity;
    let [ud, vd, wd] = x_dot.velocity;
    let ubar_sq = u * u + w * w;
    if ubar_sq.re() == 0.0 {
        // α, β undefined in the plane of symmetry at zero speed: no rate
        return (T::zero(), T::zero());
    }
    let ubar = ubar_sq.sqrt();
    let alpha_dot = (u * wd - w * ud) / ubar_sq;
    let ubar_dot = (u * ud + w * wd) / ubar;
    let beta_dot = (ubar * vd - v * ubar_dot) / (ubar_sq + v * v);
    (alpha_dot, beta_dot)
}
