//! Flight modes: short period, phugoid, roll, spiral and Dutch roll, with natural frequency,
//! damping, time constant, period and time to half amplitude; eigenvectors and eigenflight.
//!
//! Book: §14.2 (14.2.18), §14.4 (14.4.26), §14.6 (14.6.1)–(14.6.13), §14.7, Table 14.3.
//!
//! # Conventions
//! "Period" is the book's T = 2π/ωₙ of Table 14.3 (undamped); the damped period 2π/ω_d is
//! given separately. Time to half amplitude T½ = ln 2/(ζωₙ) = ln 2/(−Re λ).

use nalgebra::DMatrix;
use vectrix_lti::{Complex64, Mode, StateSpace, linalg::eigenvalues};

use crate::FlightError;

/// One flight mode: the lti [`Mode`] of its eigenvalue plus the book's periods.
///
/// Book: §14.6, Table 14.3, (14.6.7)–(14.6.10).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlightMode {
    /// λ, ωₙ, ζ, ω_d, time constant and T½ (from `vectrix-lti`).
    pub mode: Mode,
}

impl FlightMode {
    /// The eigenvalue λ (upper half plane for a complex pair).
    pub fn eigenvalue(&self) -> Complex64 {
        self.mode.eigenvalue
    }
    /// ωₙ = |λ|.
    pub fn natural_frequency(&self) -> f64 {
        self.mode.natural_frequency
    }
    /// ζ = −Re λ/|λ|.
    pub fn damping_ratio(&self) -> f64 {
        self.mode.damping_ratio.unwrap_or(0.0)
    }
    /// Table 14.3's period T = 2π/ωₙ (`None` for a real mode).
    pub fn period(&self) -> Option<f64> {
        (self.mode.damped_frequency > 0.0).then(|| std::f64::consts::TAU / self.mode.natural_frequency)
    }
    /// Damped period 2π/ω_d (`None` for a real mode).
    pub fn damped_period(&self) -> Option<f64> {
        (self.mode.damped_frequency > 0.0).then(|| std::f64::consts::TAU / self.mode.damped_frequency)
    }
    /// Time constant τ = −1/Re λ (stable modes only).
    pub fn time_constant(&self) -> Option<f64> {
        self.mode.time_constant
    }
    /// Time to half amplitude ln 2/(−Re λ) (stable modes only); time to double amplitude is
    /// ln 2/Re λ for an unstable one.
    pub fn time_to_half(&self) -> Option<f64> {
        self.mode.time_to_half
    }
}

/// The two longitudinal modes of a 4-state model [u, δα, q, θ].
///
/// Book: (14.2.18), §14.7.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LongitudinalModes {
    /// Short period: the fast oscillatory pair.
    pub short_period: FlightMode,
    /// Phugoid: the slow oscillatory pair.
    pub phugoid: FlightMode,
}

/// The three lateral modes of a 4-state model [r, δβ, p, φ].
///
/// Book: (14.4.26), §14.8.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralModes {
    /// Dutch roll: the oscillatory pair.
    pub dutch_roll: FlightMode,
    /// Roll: the faster real root.
    pub roll: FlightMode,
    /// Spiral: the slower real root (stable if negative).
    pub spiral: FlightMode,
}

fn split(a: &DMatrix<f64>) -> Result<(Vec<Complex64>, Vec<Complex64>), FlightError> {
    let lambdas = eigenvalues(a)?;
    let scale = lambdas.iter().map(|l| l.norm()).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    // a pair is oscillatory if its imaginary part is above roundoff of the spectrum
    let tol = 1e3 * f64::EPSILON * scale;
    let complex = lambdas.iter().copied().filter(|l| l.im > tol).collect();
    let real = lambdas.iter().copied().filter(|l| l.im.abs() <= tol).collect();
    Ok((complex, real))
}

fn by_size(mut v: Vec<Complex64>) -> Vec<Complex64> {
    v.sort_by(|x, y| y.norm().total_cmp(&x.norm()));
    v
}

fn mode(l: Complex64) -> FlightMode {
    FlightMode { mode: Mode::of(l) }
}

/// Short period and phugoid of a longitudinal A (4×4, two oscillatory pairs; the faster is
/// the short period).
///
/// Book: (14.2.18), §14.7.
///
/// # Errors
/// [`FlightError::ModeStructure`] unless A has exactly two oscillatory pairs.
pub fn longitudinal_modes(a: &DMatrix<f64>) -> Result<LongitudinalModes, FlightError> {
    let (complex, real) = split(a)?;
    if complex.len() != 2 || a.nrows() != 4 {
        return Err(FlightError::ModeStructure {
            reason: format!(
                "longitudinal A needs two oscillatory pairs among 4 eigenvalues, found {} pairs and {} real",
                complex.len(),
                real.len()
            ),
        });
    }
    let c = by_size(complex);
    Ok(LongitudinalModes { short_period: mode(c[0]), phugoid: mode(c[1]) })
}

/// Dutch roll, roll and spiral of a lateral A (4×4, one oscillatory pair and two real roots;
/// the faster real root is the roll mode).
///
/// Book: (14.4.26), §14.8.
///
/// # Errors
/// [`FlightError::ModeStructure`] unless A has one oscillatory pair and two real roots.
pub fn lateral_modes(a: &DMatrix<f64>) -> Result<LateralModes, FlightError> {
    let (complex, real) = split(a)?;
    if complex.len() != 1 || real.len() != 2 {
        return Err(FlightError::ModeStructure {
            reason: format!(
                "lateral A needs one oscillatory pair and two real roots, found {} pairs and {} real",
                complex.len(),
                real.len()
            ),
        });
    }
    let r = by_size(real.into_iter().map(|l| Complex64::new(l.re, 0.0)).collect());
    Ok(LateralModes { dutch_roll: mode(complex[0]), roll: mode(r[0]), spiral: mode(r[1]) })
}

/// The eigenvector v of A for λ, normalised so that component `pin` is 1 (the book's
/// "u = 1" normalisation of §14.7).
///
/// Book: §14.6, §14.7 (14.7.5).
///
/// # Errors
/// [`FlightError::ModeStructure`] if A is not square, `pin` is not a state, the pinned
/// component of the eigenvector is zero, or λ is not an eigenvalue of A (relative residual
/// ‖(A − λI)v‖/((‖A‖ + |λ|)‖v‖) above 10⁻⁶); [`FlightError::NonFinite`] for NaN or ∞ in A or λ.
pub fn eigenvector(a: &DMatrix<f64>, lambda: Complex64, pin: usize) -> Result<Vec<Complex64>, FlightError> {
    let n = a.nrows();
    if a.ncols() != n {
        return Err(FlightError::ModeStructure { reason: format!("A is {n}×{}, not square", a.ncols()) });
    }
    if pin >= n {
        return Err(FlightError::ModeStructure { reason: format!("pin {pin} ≥ {n} states") });
    }
    if !a.iter().all(|x| x.is_finite()) || !lambda.is_finite() {
        return Err(FlightError::NonFinite { what: "state matrix A or eigenvalue λ" });
    }
    let m = DMatrix::from_fn(n, n, |i, j| {
        Complex64::new(a[(i, j)], 0.0) - if i == j { lambda } else { Complex64::new(0.0, 0.0) }
    });
    // (A − λI)v = 0 with v_pin = 1: drop the pinned column into the right-hand side and
    // solve the remaining rows in least squares (one equation is redundant).
    let others: Vec<usize> = (0..n).filter(|&j| j != pin).collect();
    let sub = DMatrix::from_fn(n, n - 1, |i, j| m[(i, others[j])]);
    let rhs = DMatrix::from_fn(n, 1, |i, _| -m[(i, pin)]);
    let subh = sub.adjoint();
    let normal = &subh * &sub;
    let y = normal.lu().solve(&(&subh * rhs)).ok_or_else(|| FlightError::ModeStructure {
        reason: "the pinned component of this eigenvector is zero".into(),
    })?;
    let mut v = vec![Complex64::new(1.0, 0.0); n];
    for (k, &j) in others.iter().enumerate() {
        v[j] = y[k];
    }
    if v.iter().any(|z| !z.is_finite()) {
        return Err(FlightError::NonFinite { what: "eigenvector" });
    }
    // λ must be an eigenvalue: the least-squares solution satisfies the dropped equation only
    // then. Residual ‖(A − λI)v‖ relative to (‖A‖ + |λ|)‖v‖ (max norms); an eigenvalue from a
    // backward-stable solver leaves ~nε, a defective one ~√ε; above 10⁻⁶ λ is not one.
    let scale = (a.amax() + lambda.norm()) * v.iter().fold(0.0f64, |s, z| s.max(z.norm()));
    let residual =
        (0..n).fold(0.0f64, |r, i| r.max((0..n).map(|j| m[(i, j)] * v[j]).sum::<Complex64>().norm()));
    if residual > 1e-6 * scale {
        return Err(FlightError::ModeStructure {
            reason: format!(
                "λ = {lambda} is not an eigenvalue of A: ‖(A − λI)v‖ = {residual:e} exceeds 1e-6·(‖A‖ + |λ|)‖v‖ = {:e}",
                1e-6 * scale
            ),
        });
    }
    Ok(v)
}

/// Eigenflight x(t) = Re(e^{λt}v) = e^{σt}[v_R cos ω_d t − v_I sin ω_d t] (14.6.7–13).
///
/// Book: §14.6, (14.6.7), (14.6.13).
pub fn eigenflight(lambda: Complex64, v: &[Complex64], t: f64) -> Vec<f64> {
    let e = (lambda * t).exp();
    v.iter().map(|vi| (e * vi).re).collect()
}

/// The characteristic polynomial det(sI − A), monic, highest power first, from the
/// eigenvalues of A (notes §3: eigenvalues rather than symbolic expansion).
///
/// Book: (14.2.1), (14.4.1).
///
/// # Errors
/// As [`vectrix_lti::Polynomial::from_roots`].
pub fn characteristic_polynomial(sys: &StateSpace) -> Result<vectrix_lti::Polynomial, FlightError> {
    Ok(vectrix_lti::Polynomial::from_roots(&sys.poles()?)?)
}
