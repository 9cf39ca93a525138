//! The variable-order BDF method (orders 1–5) for stiff problems: the settings and the solve
//! entry points ([`Bdf`]); the stepping itself is in `bdf_stepper`.
//!
//! Book: §4.11; HW §III.5 (BDF), §V.5 (order and step-size selection); Shampine & Reichelt,
//! "The MATLAB ODE Suite", SIAM J. Sci. Comput. 18 (1997) (quasi-constant step size with the
//! backward-difference array); Byrne & Hindmarsh, ACM TOMS 1 (1975).

use crate::solver::Solver;

/// BDF: the backward differentiation formulas of orders 1 to 5 with variable order and
/// quasi-constant step size, the form of Shampine & Reichelt (1997) that scipy's `BDF`
/// implements, here with the classical formulas (κ = 0, not the NDF modification):
///
/// Σⱼ₌₁ᵏ (1/j) ∇ʲyₙ₊₁ = h f(tₙ₊₁, yₙ₊₁),
///
/// solved by simplified Newton with the iteration matrix I − (h/γₖ)J (γₖ = Σⱼ₌₁ᵏ 1/j; LU by
/// faer, kept while Newton converges and h is unchanged, J refreshed only when Newton fails);
/// local error estimate (1/(k+1))·∇ᵏ⁺¹yₙ₊₁ with ‖err/sk‖ ≤ 1, sk = atol + rtol·|yₙ₊₁|; after
/// k + 1 steps of one size the order moves to whichever of k − 1, k, k + 1 allows the largest
/// step. The backward differences are rescaled when h changes (the matrix R·U of Shampine &
/// Reichelt), so the formulas are always those of a constant step. Dense output is the
/// polynomial interpolating the last k + 1 points; events are located on it. Defaults
/// rtol = 1e-6, atol = 1e-9, orders up to 5, 4 Newton iterations a step.
///
/// ```
/// use vectrix_ode::Bdf;
/// // y′ = −1000 (y − cos t): stiff, y follows cos t closely
/// let f = |t: f64, y: &f64| -1000.0 * (y - t.cos());
/// let jac = |_: f64, _: &f64, j: &mut [f64]| j[0] = -1000.0;
/// let sol = Bdf::new().rtol(1e-8).atol(1e-10).solve_with_jacobian(f, jac, 0.0, &0.0, 1.0)?;
/// // exact: y = (1000² cos t + 1000 sin t − 1000² e^{−1000t})/(1000² + 1)
/// let exact = (1e6 * 1f64.cos() + 1e3 * 1f64.sin()) / (1e6 + 1.0);
/// assert!((sol.last() - exact).abs() < 1e-7);
/// assert!(sol.work.accepted < 1000); // an explicit method needs ≥ 1000/3.3 steps for stability alone
/// # Ok::<(), vectrix_ode::OdeError>(())
/// ```
///
/// Book: §4.11; HW §III.5, §V.5; Shampine & Reichelt 1997.
pub type Bdf = Solver<BdfFormula>;

/// BDF's own settings: the highest order and the Newton iteration cap.
///
/// Book: §4.11; HW §III.5.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BdfFormula {
    /// Highest order used, 1 to 5 (BDF is zero-stable up to 6, A(α)-stable with α ≥ 51° up to 5).
    pub max_order: usize,
    /// Most Newton iterations per step (4, as scipy's `BDF`).
    pub max_newton: usize,
}

impl Default for Solver<BdfFormula> {
    fn default() -> Self {
        Self::new()
    }
}

impl Solver<BdfFormula> {
    /// The defaults: rtol = 1e-6, atol = 1e-9, orders 1 to 5, 4 Newton iterations, 10⁶ steps.
    pub const fn new() -> Self {
        Self::with_method(BdfFormula { max_order: 5, max_newton: 4 })
    }
    /// Highest order, 1 to 5 (a run refuses anything else with [`OdeError::InvalidSetting`](crate::OdeError::InvalidSetting)).
    pub fn max_order(mut self, k: usize) -> Self {
        self.method.max_order = k;
        self
    }
    /// Most Newton iterations per step (at least 1).
    pub fn max_newton(mut self, n: usize) -> Self {
        self.method.max_newton = n;
        self
    }
}

impl super::solve::Implicit for BdfFormula {
    fn method(cfg: &Solver<Self>) -> crate::Method {
        crate::Method::Bdf(*cfg)
    }
}
