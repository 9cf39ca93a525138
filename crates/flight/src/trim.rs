//! Steady flight and trim: straight-line level, climbing and descending flight and the
//! coordinated level turn, by a bounded Levenberg–Marquardt solve with dual-number
//! Jacobians and failure reports that name the condition that could not be met.
//!
//! Book: §12.1, (12.1.2)–(12.1.3); notes ch9-14 §2 (straight-line trim conditions), §3 (trim).

use nalgebra::{DMatrix, DVector};
use num_dual::Dual64;
use vectrix_tensor::Scalar;

use crate::{Aircraft, AircraftState, Controls, Euler321, FlightError};

/// The steady flight to trim for.
///
/// Book: §12.1 (regimes: straight line, horizontal circle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TrimSpec {
    /// Straight-line flight at airspeed V and flight-path angle γ (γ > 0 climbs, 0 level),
    /// wings level, β = 0, heading Ψ = 0.
    Straight {
        /// Airspeed V.
        airspeed: f64,
        /// Flight-path angle γ (rad).
        gamma: f64,
    },
    /// Coordinated (β = 0) level turn at airspeed V and turn rate Ψ̇ (rad/s, > 0 to the right).
    LevelTurn {
        /// Airspeed V.
        airspeed: f64,
        /// Turn rate Ψ̇.
        turn_rate: f64,
    },
}

/// Bounds of the trim unknowns (stall, control travel, thrust ≥ 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrimLimits {
    /// |α| ≤ this (rad).
    pub alpha: f64,
    /// |δe|, |δa|, |δr| ≤ this (rad).
    pub surface: f64,
    /// 0 ≤ F_T ≤ this.
    pub thrust: f64,
    /// |Φ| ≤ this (rad) in a turn.
    pub bank: f64,
}

impl Default for TrimLimits {
    fn default() -> Self {
        Self { alpha: 0.35, surface: 0.45, thrust: f64::INFINITY, bank: 1.4 }
    }
}

/// A trimmed flight condition.
///
/// Book: §12.1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trim {
    /// The steady state x₀ (position at the origin).
    pub state: AircraftState,
    /// The trim controls u₀.
    pub controls: Controls,
    /// max |residual| at the solution (accelerations; ≤ 1e-10 on success).
    pub residual: f64,
    /// Iterations used.
    pub iterations: usize,
}

const NAMES_STRAIGHT: [&str; 3] = [
    "U̇ = 0 (thrust balances drag and weight component: thrust limit?)",
    "Ẇ = 0 (lift balances weight: α at its stall bound?)",
    "Q̇ = 0 (pitching moment zero: elevator at its limit?)",
];
const NAMES_TURN: [&str; 7] = [
    "U̇ = 0 (thrust balances drag: thrust limit?)",
    "V̇ = 0 (side force: coordination not possible with this rudder/aileron travel)",
    "Ẇ = 0 (lift balances weight and centripetal load: α at its stall bound?)",
    "Ṗ = 0 (rolling moment zero: aileron at its limit?)",
    "Q̇ = 0 (pitching moment zero: elevator at its limit?)",
    "Ṙ = 0 (yawing moment zero: rudder at its limit?)",
    "Ż = 0 (level flight: bank or α limit?)",
];

/// State and controls of the unknowns z for a spec.
fn assemble<T: Scalar>(spec: &TrimSpec, z: &[T]) -> (AircraftState<T>, Controls<T>) {
    let zero = T::zero();
    match *spec {
        TrimSpec::Straight { airspeed, gamma } => {
            // z = [α, δe, F_T]; Θ = α + γ (Fact 10.8.5)
            let (alpha, v) = (z[0], T::lit(airspeed));
            let state = AircraftState {
                position: [zero; 3],
                velocity: [v * alpha.cos(), zero, v * alpha.sin()],
                attitude: Euler321::new(zero, alpha + T::lit(gamma), zero),
                omega: [zero; 3],
            };
            (state, Controls { elevator: z[1], aileron: zero, rudder: zero, thrust: z[2] })
        }
        TrimSpec::LevelTurn { airspeed, turn_rate } => {
            // z = [α, Θ, Φ, δe, δa, δr, F_T], β = 0; ω = S(Φ, Θ)[0, 0, Ψ̇] (10.9.8)
            let (alpha, theta, phi, v) = (z[0], z[1], z[2], T::lit(airspeed));
            let e = Euler321::new(zero, theta, phi);
            let omega = crate::body_rates(&e, [zero, zero, T::lit(turn_rate)]);
            let state = AircraftState {
                position: [zero; 3],
                velocity: [v * alpha.cos(), zero, v * alpha.sin()],
                attitude: e,
                omega,
            };
            (state, Controls { elevator: z[3], aileron: z[4], rudder: z[5], thrust: z[6] })
        }
    }
}

fn residual<T: Scalar>(ac: &Aircraft, spec: &TrimSpec, z: &[T]) -> Result<Vec<T>, FlightError> {
    let (x, u) = assemble(spec, z);
    // steady: ẋ has zero velocity and rate derivatives, so α̇ = β̇ = 0 (12.1.2–3)
    let f = crate::state_derivative(&ac.airframe, ac.g, &x, &ac.forces(&x, &u, T::zero(), T::zero()))?;
    Ok(match spec {
        TrimSpec::Straight { .. } => vec![f.velocity[0], f.velocity[2], f.omega[1]],
        TrimSpec::LevelTurn { .. } => vec![
            f.velocity[0],
            f.velocity[1],
            f.velocity[2],
            f.omega[0],
            f.omega[1],
            f.omega[2],
            f.position[2],
        ],
    })
}

fn bounds(spec: &TrimSpec, lim: &TrimLimits) -> Vec<(f64, f64)> {
    let (a, s) = ((-lim.alpha, lim.alpha), (-lim.surface, lim.surface));
    match spec {
        TrimSpec::Straight { .. } => vec![a, s, (0.0, lim.thrust)],
        TrimSpec::LevelTurn { .. } => {
            vec![a, (-1.2, 1.2), (-lim.bank, lim.bank), s, s, s, (0.0, lim.thrust)]
        }
    }
}

/// Trims an aircraft: solves the steady conditions (12.1.2–3) for the spec's unknowns by
/// Levenberg–Marquardt with exact dual-number Jacobians, keeping every unknown in
/// `limits` (projected steps).
///
/// Book: §12.1; notes ch9-14 §3 (bounded Newton/LM against stall and negative thrust).
///
/// # Errors
/// [`Aircraft::check`] errors; [`FlightError::OutOfRange`] for a non-positive airspeed, |γ| ≥ π/2
/// or a limit that is NaN or ≤ 0;
/// [`FlightError::TrimFailed`] naming the condition with the largest residual when the solve
/// stalls (e.g. the elevator at its limit cannot zero the pitching moment).
pub fn trim(ac: &Aircraft, spec: TrimSpec, limits: TrimLimits) -> Result<Trim, FlightError> {
    ac.check()?;
    let (v, names) = check_spec(&spec, &limits)?;
    let bnd = bounds(&spec, &limits);
    let n = bnd.len();
    let mut z = initial_guess(ac, &spec, v, &bnd);
    let tol = 1e-12;
    let mut lambda = 1e-6;
    let mut r = DVector::from_vec(residual(ac, &spec, &z)?);
    let max_iter = 200;
    for it in 0..max_iter {
        let rmax = r.amax();
        if rmax <= tol {
            let (state, controls) = assemble(&spec, &z);
            return Ok(Trim { state, controls, residual: rmax, iterations: it });
        }
        let jac = jacobian(ac, &spec, &z, n)?;
        let jt = jac.transpose();
        let jtj = &jt * &jac;
        let g = &jt * &r;
        let mut improved = false;
        for _ in 0..30 {
            // damped normal equations (JᵀJ + λ(I + diag JᵀJ)) s = −Jᵀr, the step projected into the box
            let mut m = jtj.clone();
            for k in 0..n {
                m[(k, k)] += lambda * (1.0 + jtj[(k, k)]);
            }
            let Some(step) = m.lu().solve(&(-&g)) else {
                lambda *= 10.0;
                continue;
            };
            let trial: Vec<f64> = z
                .iter()
                .zip(step.iter())
                .zip(&bnd)
                .map(|((zi, s), (lo, hi))| (zi + s).clamp(*lo, *hi))
                .collect();
            let rt = DVector::from_vec(residual(ac, &spec, &trial)?);
            if rt.norm() < r.norm() {
                z = trial;
                r = rt;
                lambda = (lambda * 0.2).max(1e-15);
                improved = true;
                break;
            }
            lambda *= 10.0;
        }
        if !improved {
            return Err(fail(&r, names, it));
        }
    }
    Err(fail(&r, names, max_iter))
}

/// The spec's airspeed and the names of its conditions, after checking the spec and the limits.
fn check_spec(spec: &TrimSpec, limits: &TrimLimits) -> Result<(f64, &'static [&'static str]), FlightError> {
    let (v, names): (f64, &'static [&'static str]) = match *spec {
        TrimSpec::Straight { airspeed, gamma } => {
            if !(gamma.is_finite() && gamma.abs() < 1.5) {
                return Err(FlightError::OutOfRange { what: "γ", value: gamma, valid: "|γ| < 1.5 rad" });
            }
            (airspeed, &NAMES_STRAIGHT)
        }
        TrimSpec::LevelTurn { airspeed, turn_rate } => {
            if !turn_rate.is_finite() {
                return Err(FlightError::NonFinite { what: "turn rate" });
            }
            (airspeed, &NAMES_TURN)
        }
    };
    if !(v.is_finite() && v > 0.0) {
        return Err(FlightError::OutOfRange { what: "airspeed", value: v, valid: "a finite V > 0" });
    }
    // Each limit bounds a box [−l, l] (thrust [0, l]): it must be a number > 0 (+∞ = no limit),
    // else the box is empty or NaN and clamping into it is meaningless.
    for (what, l) in [
        ("α limit", limits.alpha),
        ("surface limit", limits.surface),
        ("thrust limit", limits.thrust),
        ("bank limit", limits.bank),
    ] {
        if l.is_nan() || l <= 0.0 {
            return Err(FlightError::OutOfRange { what, value: l, valid: "a limit > 0 (+∞ for none)" });
        }
    }
    Ok((v, names))
}

/// The starting point: α from the level-flight lift coefficient, thrust from the drag (plus
/// the weight component on a climb), the bank of a coordinated turn; clamped into the box.
fn initial_guess(ac: &Aircraft, spec: &TrimSpec, v: f64, bnd: &[(f64, f64)]) -> Vec<f64> {
    let n = bnd.len();
    let w = ac.airframe.mass() * ac.g;
    let qs = ac.dynamic_pressure(v) * ac.geometry.area;
    let c = &ac.coefficients;
    let cl = w / qs;
    let alpha0 = if c.cl_alpha != 0.0 { (cl - c.cl0) / c.cl_alpha } else { 0.0 };
    let thrust0 = qs * (c.cd_par + c.k_induced * cl * cl);
    let mut z = vec![0.0; n];
    z[0] = alpha0;
    z[n - 1] = thrust0;
    if let TrimSpec::Straight { gamma, .. } = *spec {
        z[2] = thrust0 + w * gamma.sin();
    }
    if let TrimSpec::LevelTurn { turn_rate, .. } = *spec {
        z[2] = (v * turn_rate / ac.g).atan();
        z[1] = alpha0;
    }
    for (zi, (lo, hi)) in z.iter_mut().zip(bnd) {
        *zi = zi.clamp(*lo, *hi);
    }
    z
}

/// ∂r/∂z at z, exact: one dual-number pass of the residual per unknown.
fn jacobian(ac: &Aircraft, spec: &TrimSpec, z: &[f64], n: usize) -> Result<DMatrix<f64>, FlightError> {
    let mut jac = DMatrix::zeros(n, n);
    for j in 0..n {
        let zd: Vec<Dual64> =
            z.iter().enumerate().map(|(k, &zk)| Dual64::new(zk, if k == j { 1.0 } else { 0.0 })).collect();
        let rd = residual(ac, spec, &zd)?;
        for i in 0..n {
            jac[(i, j)] = rd[i].eps;
        }
    }
    Ok(jac)
}

fn fail(r: &DVector<f64>, names: &[&str], iterations: usize) -> FlightError {
    let (k, val) =
        r.iter().enumerate().fold((0, 0.0f64), |m, (i, v)| if v.abs() > m.1 { (i, v.abs()) } else { m });
    FlightError::TrimFailed { condition: names[k].to_string(), residual: val, iterations }
}
