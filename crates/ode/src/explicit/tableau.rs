//! Butcher tableaux of the explicit Runge–Kutta methods.

/// An explicit Butcher tableau (c, A, b): stage i evaluates
/// kᵢ = f(t + cᵢh, y + h Σ_{j<i} aᵢⱼ kⱼ) and the step is y₁ = y + h Σ bᵢ kᵢ.
///
/// Book: §4.11 (integrating the rate equations); HNW §II.1, (1.8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tableau {
    /// Name, for tables and plots.
    pub name: &'static str,
    /// Nodes cᵢ.
    pub c: &'static [f64],
    /// Rows aᵢ,₁..ᵢ₋₁ of the strictly lower-triangular stage matrix (row 0 empty).
    pub a: &'static [&'static [f64]],
    /// Weights bᵢ.
    pub b: &'static [f64],
    /// Classical order p.
    pub order: u32,
}

impl Tableau {
    /// Number of stages s.
    pub fn stages(&self) -> usize {
        self.b.len()
    }
}

/// Forward Euler, order 1: y₁ = y + h f(t, y).
///
/// Book: §4.11; HNW (1.1).
pub const EULER: Tableau = Tableau { name: "Euler", c: &[0.0], a: &[&[]], b: &[1.0], order: 1 };

/// Heun's method (explicit trapezoid), order 2.
///
/// Book: §4.11; HNW §II.1.
pub const HEUN: Tableau =
    Tableau { name: "Heun", c: &[0.0, 1.0], a: &[&[], &[1.0]], b: &[0.5, 0.5], order: 2 };

/// The classical Runge–Kutta method, order 4.
///
/// Book: §4.11; HNW Table 1.2.
pub const RK4: Tableau = Tableau {
    name: "RK4",
    c: &[0.0, 0.5, 0.5, 1.0],
    a: &[&[], &[0.5], &[0.0, 0.5], &[0.0, 0.0, 1.0]],
    b: &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
    order: 4,
};

/// Dormand–Prince 5(4) (DOPRI5): 7 stages, first same as last, 5th-order solution.
///
/// Book: §4.11; HNW Table 5.2.
pub const DOPRI5: Tableau = Tableau {
    name: "DP5",
    c: &[0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
    a: &[
        &[],
        &[1.0 / 5.0],
        &[3.0 / 40.0, 9.0 / 40.0],
        &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
        &[19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0],
        &[9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0],
        &[35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
    ],
    b: &[35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0, 0.0],
    order: 5,
};

/// Error weights eᵢ = bᵢ − b̂ᵢ of DOPRI5 (difference of the 5th- and 4th-order solutions).
pub(crate) const DOPRI5_E: [f64; 7] =
    [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];

/// Dense-output coefficients of DOPRI5 (Shampine's 4th-order continuous extension).
pub(crate) const DOPRI5_D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// DOP853's 8th-order solution as a 12-stage tableau (for fixed-step use and tests).
///
/// Book: §4.11; HNW §II.10.
pub const DOP853: Tableau = Tableau {
    name: "DOP853",
    c: &super::dop853::C12,
    a: &super::dop853::A12,
    b: &super::dop853_coefficients::B,
    order: 8,
};

/// Verner's 9(8) pair's 9th-order solution as a 15-stage tableau (its 16th stage serves only
/// the error estimate), for fixed-step use and tests.
///
/// Book: §4.11; Verner, Numer. Algorithms 53 (2010).
pub const VERN9: Tableau = Tableau {
    name: "Vern9",
    c: super::vern9_coefficients::C.split_at(15).0,
    a: super::vern9_coefficients::A.split_at(15).0,
    b: super::vern9_coefficients::B.split_at(15).0,
    order: 9,
};
