//! Radau IIA of order 5 with Hairer & Wanner's RADAU5 control: the adaptive implicit
//! integrator for stiff problems, with dense output and events on the same terms as
//! [`Adaptive`](crate::Adaptive).

use crate::solver::Solver;

/// RADAU5: the 3-stage Radau IIA collocation method (order 5, stiffly accurate, L-stable),
/// solved by simplified Newton in the transformed variables that split the 3n×3n system
/// into one real and one complex n×n system (LU by [`DenseLu`](crate::implicit::DenseLu), in
/// place in buffers allocated once per run, kept across steps while Newton contracts fast
/// and h changes by less than 20 %), with the embedded order-3 error estimate
/// filtered by (I − hγ₀J)⁻¹, Gustafsson's predictive step control, the collocation
/// polynomial as dense output, and events located on it.
///
/// Tolerances mean what they mean in `radau5.f`: the local error is kept at
/// ‖err/sk‖ ≤ 1 with sk = atol' + rtol'·|y|, where rtol' = 0.1·rtol^{2/3} and
/// atol' = rtol'·atol/rtol (the error estimate is of order 3, so the tolerance is tightened
/// to make the global error follow rtol). Defaults rtol = 1e-6, atol = 1e-9, at most 7 Newton
/// iterations a step, initial step 1e-6.
///
/// ```
/// use vectrix_ode::Radau5;
/// // y′ = −1000 (y − cos t): stiff, y follows cos t closely
/// let f = |t: f64, y: &f64| -1000.0 * (y - t.cos());
/// let jac = |_: f64, _: &f64, j: &mut [f64]| j[0] = -1000.0;
/// let sol = Radau5::new().rtol(1e-8).atol(1e-10).solve_with_jacobian(f, jac, 0.0, &0.0, 1.0)?;
/// // exact: y = (1000² cos t + 1000 sin t − 1000² e^{−1000t})/(1000² + 1)
/// let exact = (1e6 * 1f64.cos() + 1e3 * 1f64.sin()) / (1e6 + 1.0);
/// // the global error is of the order of rtol; on which side of it depends on the last bits
/// // of the step sequence (3e-9 … 8e-8 for rtol = 0.95e-8 … 1.05e-8 and LUs that round
/// // differently in the last bit; 4.1e-9 in 65 steps here)
/// assert!((sol.last() - exact).abs() < 1e-7);
/// assert!(sol.work.accepted < 100); // an explicit method needs ≥ 1000/3.3 steps for stability
/// # Ok::<(), vectrix_ode::OdeError>(())
/// ```
///
/// Book: §4.11; HW = Hairer & Wanner, *Solving Ordinary Differential Equations II*,
/// §IV.5 (Radau IIA), §IV.8 (implementation, `radau5.f`).
pub type Radau5 = Solver<RadauIIA>;

/// RADAU5's own setting: the Newton iteration cap.
///
/// Book: §4.11; HW §IV.8.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RadauIIA {
    /// Most Newton iterations per step (`NIT` of `radau5.f`, 7).
    pub max_newton: usize,
}

impl Default for Solver<RadauIIA> {
    fn default() -> Self {
        Self::new()
    }
}

impl Solver<RadauIIA> {
    /// The defaults: rtol = 1e-6, atol = 1e-9, 7 Newton iterations, 10⁶ steps.
    pub const fn new() -> Self {
        Self::with_method(RadauIIA { max_newton: 7 })
    }
    /// Most Newton iterations per step.
    pub fn max_newton(mut self, n: usize) -> Self {
        self.method.max_newton = n;
        self
    }
}

impl super::solve::Implicit for RadauIIA {
    fn method(cfg: &Solver<Self>) -> crate::Method {
        crate::Method::Radau5(*cfg)
    }
}
