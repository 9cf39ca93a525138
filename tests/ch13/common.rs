//! An aircraft with arbitrary coefficients for the chapter-13 tests (independent of the
//! business-jet catalog), and dual-number derivatives of its aerodynamic forces and moments at
//! the steady point of §13.2 (V₀|_AC = (U₀, 0, 0), α₀ = β₀ = 0, zero rates and controls).

use vectrix::flight::*;
use vectrix::nalgebra::Vector3;
use vectrix::num_dual::Dual64;

/// Steady speed U₀ (ft/s) and the geometry and density used here.
pub const U0: f64 = 500.0;
pub const GEOMETRY: Geometry = Geometry { area: 300.0, chord: 8.0, span: 40.0 };
pub const RHO: f64 = 0.0012;

/// A nonlinear aircraft with the given coefficients (speed derivatives about U₀).
pub fn aircraft(mut c: Coefficients) -> Aircraft {
    c.u_ref = U0;
    Aircraft {
        airframe: Airframe::new(400.0, 20_000.0, 30_000.0, 45_000.0, 800.0).unwrap(),
        geometry: GEOMETRY,
        coefficients: c,
        rho: RHO,
        g: 32.2,
        thrust_angle: 0.0,
    }
}

/// Coefficients with every longitudinal and lateral term nonzero (signs as in Tables 13.1–13.2).
pub fn coefficients() -> Coefficients {
    Coefficients {
        u_ref: U0,
        cl0: 0.4,
        cl_u: 0.05,
        cl_alpha: 5.2,
        cl_q: 4.0,
        cl_alpha_dot: 1.5,
        cl_de: 0.4,
        cd_par: 0.02,
        k_induced: 0.045,
        cd_u: 0.01,
        cm0: 0.03,
        cm_u: -0.02,
        cm_alpha: -0.8,
        cm_q: -15.0,
        cm_alpha_dot: -5.0,
        cm_de: -1.2,
        ce_beta: -0.5,
        ce_beta_dot: -0.1,
        ce_p: -0.05,
        ce_r: 0.2,
        ce_da: -0.01,
        ce_dr: 0.15,
        croll_beta: -0.1,
        croll_beta_dot: -0.02,
        croll_p: -0.4,
        croll_r: 0.1,
        croll_da: 0.15,
        croll_dr: 0.02,
        cn_beta: 0.12,
        cn_beta_dot: 0.05,
        cn_p: -0.03,
        cn_r: -0.15,
        cn_da: -0.01,
        cn_dr: -0.09,
    }
}

/// Perturbation variables of §13.3: u, δα (via w = U₀δα, (12.4.9)), δβ (via v = U₀δβ,
/// (12.4.10)), p, q, r, δα̇, δβ̇, δe, δa, δr.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Var {
    U,
    Alpha,
    Beta,
    P,
    Q,
    R,
    AlphaDot,
    BetaDot,
    Elevator,
    Aileron,
    Rudder,
}

/// ∂/∂var at the steady point of (F_A|_AC, [L_A, M_A, N_A], D, E, L): the aerodynamic force in
/// the aircraft frame (11.1.21), the moments, and drag, side drag and lift.
pub struct Partials {
    pub force: Vector3<f64>,
    pub moment: Vector3<f64>,
    pub del: Vector3<f64>,
    /// Values at the steady point.
    pub force0: Vector3<f64>,
    pub del0: Vector3<f64>,
}

pub fn partials(ac: &Aircraft, var: Var) -> Partials {
    let e = |v: Var| Dual64::new(0.0, f64::from(v == var));
    let z = Dual64::from(0.0);
    let x = AircraftState {
        position: [z; 3],
        velocity: [Dual64::from(U0) + e(Var::U), e(Var::Beta) * U0, e(Var::Alpha) * U0],
        attitude: Euler321::new(z, z, z),
        omega: [e(Var::P), e(Var::Q), e(Var::R)],
    };
    let u =
        Controls { elevator: e(Var::Elevator), aileron: e(Var::Aileron), rudder: e(Var::Rudder), thrust: z };
    let fm = ac.forces(&x, &u, e(Var::AlphaDot), e(Var::BetaDot));
    let a = x.aero_angles();
    let f = o_w_ac(a.alpha, a.beta).transpose() * Vector3::new(-fm.drag, -fm.side_drag, -fm.lift);
    Partials {
        force: f.map(|v| v.eps),
        moment: Vector3::new(fm.roll.eps, fm.pitch.eps, fm.yaw.eps),
        del: Vector3::new(fm.drag.eps, fm.side_drag.eps, fm.lift.eps),
        force0: f.map(|v| v.re),
        del0: Vector3::new(fm.drag.re, fm.side_drag.re, fm.lift.re),
    }
}

/// p_d0 S: the steady dynamic pressure times the wing area (13.2.2).
pub fn qs() -> f64 {
    0.5 * RHO * U0 * U0 * GEOMETRY.area
}
