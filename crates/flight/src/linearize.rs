//! Linearization at a trim point with dual numbers, in the implicit (descriptor) form
//! E ẋ = A₀x + B₀u that the α̇ and β̇ terms produce; longitudinal/lateral decoupling; the
//! longitudinal [u, δα, q, θ] and lateral [r, δβ, p, φ] models through `vectrix-lti`.
//!
//! Book: §12.2–12.6, (12.3.12), (12.3.14); §14.1 (14.1.7), §14.3, §14.5 (14.5.1); notes
//! ch9-14 §3 (A = −F_ẋ⁻¹F_x).
//!
//! # Conventions
//! Full state order (11.5.1) [X Y Z U V W Φ Θ Ψ P Q R]; inputs [δe, δa, δr, F_T].

use nalgebra::DMatrix;
use num_dual::Dual64;
use vectrix_lti::StateSpace;

use crate::{Aircraft, AircraftState, Controls, Descriptor, FlightError, Trim};

/// The linear model of an aircraft at a trim point.
///
/// Book: §12.6, (12.6.1)–(12.6.4); §14.5.
#[derive(Debug, Clone, PartialEq)]
pub struct Linearization {
    /// The trim point.
    pub trim: Trim,
    /// E ẋ = A₀x + B₀u with E = ∂F/∂ẋ, A₀ = −∂F/∂x, B₀ = −∂F/∂u of the implicit residual.
    pub descriptor: Descriptor,
    /// ẋ = Ax + Bu, A = E⁻¹A₀, B = E⁻¹B₀, outputs y = x (12 states, 4 inputs).
    pub state_space: StateSpace,
}

/// Linearizes the implicit equations of motion F(ẋ, x, u) = 0 at a trim point with exact
/// dual-number derivatives: 12 + 12 + 4 forward passes.
///
/// Book: §12.2–12.6; (14.1.7) and §14.3 for the α̇/β̇ descriptor terms.
///
/// # Errors
/// [`FlightError::NonFinite`] for a non-finite derivative; [`FlightError::SingularDescriptor`]
/// if E is singular (U₀ − Z_α̇ = 0); errors of the equations of motion.
pub fn linearize(ac: &Aircraft, trim: &Trim) -> Result<Linearization, FlightError> {
    ac.check()?;
    let x0 = trim.state.to_array();
    if x0.iter().chain(trim.controls.to_array().iter()).any(|v| !v.is_finite()) {
        return Err(FlightError::NonFinite { what: "trim state or controls" });
    }
    let u0 = trim.controls.to_array();
    let xd0 = [0.0; 12];
    let mut e = DMatrix::zeros(12, 12);
    let mut a0 = DMatrix::zeros(12, 12);
    let mut b0 = DMatrix::zeros(12, 4);
    let seed = |v: &[f64], k: Option<usize>| -> Vec<Dual64> {
        v.iter().enumerate().map(|(i, &vi)| Dual64::new(vi, if Some(i) == k { 1.0 } else { 0.0 })).collect()
    };
    let eval = |xd: Vec<Dual64>, x: Vec<Dual64>, u: Vec<Dual64>| -> Result<[Dual64; 12], FlightError> {
        let xd = AircraftState::from_array(std::array::from_fn(|i| xd[i]));
        let x = AircraftState::from_array(std::array::from_fn(|i| x[i]));
        let u = Controls::from_array(std::array::from_fn(|i| u[i]));
        ac.residual(&xd, &x, &u)
    };
    for j in 0..12 {
        let f = eval(seed(&xd0, Some(j)), seed(&x0, None), seed(&u0, None))?;
        let g = eval(seed(&xd0, None), seed(&x0, Some(j)), seed(&u0, None))?;
        for i in 0..12 {
            e[(i, j)] = f[i].eps;
            a0[(i, j)] = -g[i].eps;
        }
    }
    for j in 0..4 {
        let f = eval(seed(&xd0, None), seed(&x0, None), seed(&u0, Some(j)))?;
        for i in 0..12 {
            b0[(i, j)] = -f[i].eps;
        }
    }
    if e.iter().chain(a0.iter()).chain(b0.iter()).any(|v| !v.is_finite()) {
        return Err(FlightError::NonFinite { what: "Jacobian of the equations of motion" });
    }
    let descriptor = Descriptor { e, a0, b0 };
    let state_space = descriptor.to_state_space("12-state linearization")?;
    Ok(Linearization { trim: *trim, descriptor, state_space })
}

/// Indices of the longitudinal states U, W, Q, Θ (and X, Z) and lateral V, P, R, Φ, Ψ, Y in
/// the order of (11.5.1).
const LONG: [usize; 6] = [3, 5, 10, 7, 0, 2];
const LAT: [usize; 6] = [11, 4, 9, 6, 8, 1];

impl Linearization {
    /// Largest entry of A and B that couples the longitudinal block {X, Z, U, W, Q, Θ, δe,
    /// F_T} and the lateral block {Y, V, P, R, Φ, Ψ, δa, δr}; zero (to roundoff) at a
    /// straight, wings-level, β = 0 trim (14.5.1).
    ///
    /// Book: §14.5, (14.5.1).
    pub fn coupling(&self) -> f64 {
        let (a, b) = (self.state_space.a(), self.state_space.b());
        let mut worst = 0.0f64;
        for &i in &LONG {
            for &j in &LAT {
                worst = worst.max(a[(i, j)].abs()).max(a[(j, i)].abs());
            }
            worst = worst.max(b[(i, 1)].abs()).max(b[(i, 2)].abs());
        }
        for &j in &LAT {
            worst = worst.max(b[(j, 0)].abs()).max(b[(j, 3)].abs());
        }
        worst
    }

    /// The longitudinal model x = [u, δα, q, θ], inputs [δe, F_T], with
    /// δα = (−W₀u + U₀w)/(U₀² + W₀²) (12.3.12).
    ///
    /// Book: (12.3.12), §14.1.
    ///
    /// # Errors
    /// From `vectrix-lti` (none for a finite model).
    pub fn longitudinal(&self) -> Result<StateSpace, FlightError> {
        let [u0, _, w0] = self.trim.state.velocity;
        let v2 = u0 * u0 + w0 * w0;
        // z = T x_sub, x_sub = [U, W, Q, Θ]
        #[rustfmt::skip]
        let t = DMatrix::from_row_slice(4, 4, &[
            1.0, 0.0, 0.0, 0.0,
            -w0 / v2, u0 / v2, 0.0, 0.0,
            0.0, 0.0, 1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
        ]);
        self.block(&LONG[..4], &[0, 3], &t)
    }

    /// The lateral model x = [r, δβ, p, φ], inputs [δa, δr], with δβ = v/√(U₀² + W₀²)
    /// (12.3.14).
    ///
    /// Book: (12.3.14), §14.3.
    ///
    /// # Errors
    /// From `vectrix-lti` (none for a finite model).
    pub fn lateral(&self) -> Result<StateSpace, FlightError> {
        let [u0, _, w0] = self.trim.state.velocity;
        let v = (u0 * u0 + w0 * w0).sqrt();
        let t = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(vec![1.0, 1.0 / v, 1.0, 1.0]));
        self.block(&LAT[..4], &[1, 2], &t)
    }

    fn block(&self, states: &[usize], inputs: &[usize], t: &DMatrix<f64>) -> Result<StateSpace, FlightError> {
        let (a, b) = (self.state_space.a(), self.state_space.b());
        let n = states.len();
        let a_sub = DMatrix::from_fn(n, n, |i, j| a[(states[i], states[j])]);
        let b_sub = DMatrix::from_fn(n, inputs.len(), |i, j| b[(states[i], inputs[j])]);
        let t_inv = t.clone().try_inverse().ok_or(FlightError::SingularDescriptor {
            what: "state transformation",
            reason: "zero trim airspeed".into(),
        })?;
        let a_z = t * a_sub * t_inv;
        let b_z = t * b_sub;
        Ok(StateSpace::new(a_z, b_z, DMatrix::identity(n, n), DMatrix::zeros(n, inputs.len()))?)
    }
}
