//! Single-degree-of-freedom systems m q̈ + c q̇ + k q = f and modal quantities.
//!
//! Book: §15.4, (15.4.1)–(15.4.4); §15.15, (15.15.2)–(15.15.6); 15.20.11–12, 15.20.14,
//! 15.20.33–34.

use crate::error::LtiError;
use crate::ss::StateSpace;
use nalgebra::DMatrix;
use num_complex::Complex64;

/// The four SDOF cases of §15.4.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SdofKind {
    /// Undamped rigid body, m q̈ = f (15.4.1).
    UndampedRigidBody,
    /// Damped rigid body, m q̈ + c q̇ = f (15.4.2).
    DampedRigidBody,
    /// Undamped oscillator, m q̈ + k q = f (15.4.3).
    UndampedOscillator,
    /// Damped oscillator, m q̈ + c q̇ + k q = f (15.4.4).
    DampedOscillator,
}

/// Which signal of an SDOF system is the output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SdofOutput {
    /// q.
    Position,
    /// q̇ (15.14.15: unobservable for rigid bodies).
    Velocity,
    /// q̈ = (f − c q̇ − k q)/m (15.20.14, with the book's C corrected to [−k/m, −c/m]).
    Acceleration,
}

/// m q̈ + c q̇ + k q = f with m > 0, c ≥ 0, k ≥ 0.
///
/// Book: §15.4, (15.4.1)–(15.4.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sdof {
    /// Mass m > 0.
    pub m: f64,
    /// Damping c ≥ 0.
    pub c: f64,
    /// Stiffness k ≥ 0.
    pub k: f64,
}

impl Sdof {
    /// A validated SDOF system.
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] unless m > 0, c ≥ 0, k ≥ 0, all finite.
    pub fn new(m: f64, c: f64, k: f64) -> Result<Self, LtiError> {
        if !(m.is_finite() && c.is_finite() && k.is_finite() && m > 0.0 && c >= 0.0 && k >= 0.0) {
            return Err(LtiError::InvalidArgument {
                what: "SDOF parameters",
                reason: format!("m = {m}, c = {c}, k = {k}; need finite m > 0, c ≥ 0, k ≥ 0"),
            });
        }
        Ok(Self { m, c, k })
    }

    /// Which of the four cases of §15.4 this is.
    pub fn kind(&self) -> SdofKind {
        match (self.c > 0.0, self.k > 0.0) {
            (false, false) => SdofKind::UndampedRigidBody,
            (true, false) => SdofKind::DampedRigidBody,
            (false, true) => SdofKind::UndampedOscillator,
            (true, true) => SdofKind::DampedOscillator,
        }
    }

    /// Natural frequency ωn = √(k/m).
    ///
    /// # Degenerate inputs
    /// Where k/m leaves the normal range (k = 1e300, m = 1e-300) the value is √k/√m, which
    /// is finite whenever ωn is; +∞ only when ωn itself exceeds the f64 range.
    pub fn natural_frequency(&self) -> f64 {
        let r = self.k / self.m;
        if r.is_normal() || r == 0.0 && self.k == 0.0 { r.sqrt() } else { self.k.sqrt() / self.m.sqrt() }
    }

    /// Damping ratio ζ = c/(2√(mk)); `None` for k = 0 (no oscillator).
    ///
    /// # Degenerate inputs
    /// Where mk leaves the normal range (m = k = 5e-324 made it 0/0) the value is
    /// c/(2√m√k); `None` also when ζ exceeds the f64 range.
    pub fn damping_ratio(&self) -> Option<f64> {
        if self.k <= 0.0 {
            return None;
        }
        let mk = self.m * self.k;
        let z = if mk.is_normal() {
            self.c / (2.0 * mk.sqrt())
        } else {
            self.c / (2.0 * self.m.sqrt() * self.k.sqrt())
        };
        z.is_finite().then_some(z)
    }

    /// State form with x = (q, q̇) and input f: A = [[0, 1], [−k/m, −c/m]], B = [0, 1/m]ᵀ.
    ///
    /// Book: (15.7.6), 15.20.14 (acceleration output: D = 1/m; the printed C = [0, −c/m] is an
    /// erratum, C = [−k/m, −c/m]).
    ///
    /// # Errors
    /// [`LtiError::NonFinite`] if the (public) fields were set to non-finite values.
    pub fn to_state_space(&self, output: SdofOutput) -> Result<StateSpace, LtiError> {
        let (m, c, k) = (self.m, self.c, self.k);
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -k / m, -c / m]);
        let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0 / m]);
        let (cm, d) = match output {
            SdofOutput::Position => ([1.0, 0.0], 0.0),
            SdofOutput::Velocity => ([0.0, 1.0], 0.0),
            SdofOutput::Acceleration => ([-k / m, -c / m], 1.0 / m),
        };
        StateSpace::new(a, b, DMatrix::from_row_slice(1, 2, &cm), DMatrix::from_element(1, 1, d))
    }
}

/// Modal quantities of one eigenvalue λ = σ + jω.
///
/// Book: (15.15.2)–(15.15.6), 15.20.11–12, 15.20.33.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mode {
    /// The eigenvalue λ.
    pub eigenvalue: Complex64,
    /// ωn = |λ| (15.15.5).
    pub natural_frequency: f64,
    /// ζ = −Re λ/|λ| (15.15.6, ζ = sin θ); `None` for λ = 0.
    pub damping_ratio: Option<f64>,
    /// ωd = |Im λ| (15.15.4).
    pub damped_frequency: f64,
    /// Time constant 1/(−Re λ) for Re λ < 0 (`None` also where it exceeds the f64 range).
    pub time_constant: Option<f64>,
    /// Time to half amplitude ln 2/(ζωn) = ln 2/(−Re λ) for Re λ < 0 (15.20.33); `None` also
    /// where it exceeds the f64 range.
    pub time_to_half: Option<f64>,
}

impl Mode {
    /// The modal quantities of λ.
    pub fn of(eigenvalue: Complex64) -> Self {
        let wn = eigenvalue.norm();
        let sigma = eigenvalue.re;
        Mode {
            eigenvalue,
            natural_frequency: wn,
            damping_ratio: (wn > 0.0).then(|| -sigma / wn),
            damped_frequency: eigenvalue.im.abs(),
            // `None` also where 1/(−σ) exceeds the f64 range (σ subnormal)
            time_constant: (sigma < 0.0).then(|| -1.0 / sigma).filter(|t| t.is_finite()),
            time_to_half: (sigma < 0.0).then(|| std::f64::consts::LN_2 / -sigma).filter(|t| t.is_finite()),
        }
    }
}

/// Modes of every eigenvalue of A (Matlab `damp`), in the order of [`crate::linalg::eigenvalues`].
///
/// # Errors
/// As [`crate::linalg::eigenvalues`].
pub fn modes(a: &DMatrix<f64>) -> Result<Vec<Mode>, LtiError> {
    Ok(crate::linalg::eigenvalues(a)?.into_iter().map(Mode::of).collect())
}
