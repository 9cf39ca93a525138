//! Taylor series integration of smooth problems: each step expands the solution in a power
//! series of order p about the step's start by automatic differentiation of the right-hand
//! side ([`Var`]), then sums it at the step size the last two coefficients allow.
//!
//! For a cheap smooth right-hand side (Kepler's problem, a pendulum, Euler's equations of a
//! rigid body) a step of order 10–16 costs O(p²) products per operation and covers many
//! Runge–Kutta steps: no stages, no rejected steps, and dense output for free (the series
//! itself). It does not apply where the right-hand side branches on the state (contacts,
//! saturations: use [`crate::Adaptive`] with events) or is itself a long computation (a
//! multibody model's ABA).
//!
//! Book: §4.11; Jorba & Zou, *A software package for the numerical integration of ODEs by means
//! of high-order Taylor methods*, Experimental Mathematics 14 (2005) 99–117 (order and step
//! size, §3.2–3.3); Griewank & Walther, *Evaluating Derivatives* (2008) §13.2.

mod series;
#[cfg(test)]
mod tests;

use std::time::Instant;

use nalgebra::SVector;

use series::Tape;
pub use series::Var;

use crate::explicit::{DenseStep, Form, Solution};
use crate::solver::Solver;
use crate::state::check_state;
use crate::{OdeError, Work};

/// A right-hand side y′ = f(t, y) the Taylor integrator can expand: written once over
/// [`Var`]s, the series of its quantities (operators and `sqrt`, `powf`, `exp`,
/// `ln`, `sin`, `cos` as on `f64`).
///
/// ```
/// use vectrix_ode::taylor::{TaylorRhs, Var};
/// /// Kepler's problem r̈ = −r/|r|³, y = (x, y, ẋ, ẏ)
/// struct Kepler;
/// impl TaylorRhs<4> for Kepler {
///     fn eval<'a>(&self, _t: Var<'a>, y: &[Var<'a>; 4]) -> [Var<'a>; 4] {
///         let u = (y[0].square() + y[1].square()).powf(-1.5);
///         [y[2], y[3], -(y[0] * u), -(y[1] * u)]
///     }
/// }
/// ```
///
/// `eval` runs once per solve, to record its operations, which every step then repeats on the
/// series (a [`Var`] has no value to branch on: a right-hand side that must branch on the state
/// is not one for this method).
///
/// Book: §4.11; Griewank & Walther §13.2.
pub trait TaylorRhs<const N: usize> {
    /// f(t, y) over the series of t and of the state's components (named `eval`, not `rhs`, so that a
    /// problem can implement this beside an `f64` right-hand side of the same name).
    fn eval<'a>(&self, t: Var<'a>, y: &[Var<'a>; N]) -> [Var<'a>; N];
}

/// The Taylor method's own setting: the order p of the series (`None`: from the tolerance,
/// p = ⌈1 − ½ ln ε⌉ with ε = min(rtol, atol), Jorba & Zou (3.5), at least 4).
///
/// Book: §4.11; Jorba & Zou §3.2.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TaylorOrder {
    /// The order p, 2 ..= [`TAYLOR_MAX_ORDER`] (`None`: from the tolerance).
    pub order: Option<usize>,
}

/// The highest order [`Taylor::order`] accepts.
pub const TAYLOR_MAX_ORDER: usize = 60;

/// A Taylor series integrator ([`TaylorOrder`] with the tolerances and limits of [`Solver`]);
/// defaults rtol = 1e-6, atol = 1e-9, the order from the tolerance.
///
/// Step size (Jorba & Zou (3.8)): with ε = atol + rtol·‖y‖∞ at the step's start and the
/// series' coefficients xₖ, h = min over k ∈ {p − 1, p} of (ε/‖xₖ‖∞)^{1/k}, times e^{−0.7/(p−1)}:
/// the last two terms of the series are then about ε. There is no error estimate to reject a
/// step with (the series' tail is the estimate), so the tolerance is a target, not a bound:
/// measure the error as for any method (the work–precision harness does). `h0` is not used.
///
/// ```
/// use nalgebra::Vector2;
/// use vectrix_ode::taylor::{Taylor, TaylorRhs, Var};
/// // θ̈ = −sin θ from θ = 1 at rest; energy ½θ̇² − cos θ is conserved
/// struct Pendulum;
/// impl TaylorRhs<2> for Pendulum {
///     fn eval<'a>(&self, _t: Var<'a>, y: &[Var<'a>; 2]) -> [Var<'a>; 2] {
///         [y[1], -y[0].sin()]
///     }
/// }
/// let sol = Taylor::new().rtol(1e-12).atol(1e-12).solve(&Pendulum, 0.0, &Vector2::new(1.0, 0.0), 10.0)?;
/// let y = sol.last();
/// let energy = 0.5 * y[1] * y[1] - y[0].cos();
/// assert!((energy + 1f64.cos()).abs() < 1e-11);
/// # Ok::<(), vectrix_ode::OdeError>(())
/// ```
///
/// `work.fevals` counts passes over the right-hand side's recorded operations (p a step: each
/// pass computes one more order of every quantity, at a cost that grows with the order);
/// `work.accepted` the steps.
///
/// Book: §4.11; Jorba & Zou §3.
pub type Taylor = Solver<TaylorOrder>;

impl Solver<TaylorOrder> {
    /// The Taylor method, order from the tolerance.
    pub const fn new() -> Self {
        Self::with_method(TaylorOrder { order: None })
    }

    /// Series of order `p` (checked by [`Taylor::solve`]: 2 ..= [`TAYLOR_MAX_ORDER`]).
    pub fn order(mut self, p: usize) -> Self {
        self.method.order = Some(p);
        self
    }

    /// The order a run uses: the one set, else ⌈1 − ½ ln ε⌉ with ε = min(rtol, atol)
    /// (Jorba & Zou (3.5)), between 4 and 30.
    pub fn effective_order(&self) -> usize {
        self.method.order.unwrap_or_else(|| {
            let eps = self.rtol.min(self.atol);
            let p = (1.0 - 0.5 * eps.ln()).ceil();
            if p.is_finite() { (p as usize).clamp(4, 30) } else { 4 }
        })
    }

    /// Solves y′ = f(t, y), y(t0) = y0 on [t0, t1], returning every step's end (and, with
    /// `.dense(true)`, each step's series for [`Solution::sample`]).
    ///
    /// # Errors
    /// Bad input: [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`] (`h_max`), [`OdeError::NonFiniteState`],
    /// [`OdeError::InvalidSetting`] (an order outside 2 ..= 60); during the run:
    /// [`OdeError::RhsNotFinite`] (a coefficient of f's series is not finite: f or one of its
    /// derivatives is singular at the step's start, e.g. √x at x = 0),
    /// [`OdeError::StepSizeUnderflow`],
    /// [`OdeError::TooManySteps`].
    pub fn solve<const N: usize, F: TaylorRhs<N>>(
        &self,
        f: &F,
        t0: f64,
        y0: &SVector<f64, N>,
        t1: f64,
    ) -> Result<Solution<SVector<f64, N>>, OdeError> {
        let start = Instant::now();
        let h_max = self.check(t0, t1)?;
        let p = self.effective_order();
        if !(2..=TAYLOR_MAX_ORDER).contains(&p) {
            return Err(OdeError::InvalidSetting { name: "order", value: p, valid: "2 ..= 60" });
        }
        check_state(t0, y0)?;
        let mut run = Series::record(p, f);
        let mut work = Work::default();
        let (mut t, mut y) = (t0, *y0);
        let (mut ts, mut ys, mut dense) = (vec![t0], vec![*y0], Vec::new());
        while t < t1 {
            if work.accepted >= self.max_steps {
                return Err(OdeError::TooManySteps { t, max_steps: self.max_steps });
            }
            run.expand(t, &y, &mut work)?;
            let eps = self.atol + self.rtol * y.amax();
            let mut h = run.step_size(eps).min(h_max);
            // the last step lands exactly on t1 (as the Runge–Kutta pairs: within 1 % of it)
            let last = t + 1.01 * h >= t1;
            if last {
                h = t1 - t;
            }
            if h.is_nan() || 0.1 * h <= t.abs() * f64::EPSILON {
                return Err(OdeError::StepSizeUnderflow { t, h });
            }
            let y1: SVector<f64, N> = run.sum(h);
            if let Some((index, value)) = y1.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(OdeError::RhsNotFinite {
                    t: t + h,
                    step_start: t,
                    stage: p,
                    index,
                    value: *value,
                });
            }
            if self.dense {
                dense.push(run.dense_step(t, h));
            }
            work.accepted += 1;
            t = if last { t1 } else { t + h };
            y = y1;
            ts.push(t);
            ys.push(y);
        }
        work.wall = start.elapsed();
        Ok(Solution { t: ts, y: ys, events: Vec::new(), terminated: false, work, dense })
    }
}

impl Default for Solver<TaylorOrder> {
    fn default() -> Self {
        Self::new()
    }
}

/// The series of one step: the right-hand side's recorded operations and the coefficient
/// store (the state's x₀ … x_p first, then t's, then every operation's result).
struct Series {
    p: usize,
    n: usize,
    tape: Tape,
    /// Where f's components are in the store.
    out: Vec<usize>,
    c: Vec<f64>,
}

impl Series {
    /// Records f's operations (f runs once, on [`Var`]s).
    fn record<const N: usize, F: TaylorRhs<N>>(p: usize, f: &F) -> Self {
        let tape = Tape::new(p, N + 1);
        let out = {
            let ys: [Var<'_>; N] = core::array::from_fn(|i| tape.input(i));
            f.eval(tape.input(N), &ys).map(|v| v.at()).to_vec()
        };
        let c = vec![0.0; tape.store_len()];
        Self { p, n: N, tape, out, c }
    }

    /// The coefficients x₁ … x_p of the solution through (t, y): p passes of the tape, pass k
    /// giving fₖ and xₖ₊₁ = fₖ/(k + 1).
    fn expand<const N: usize>(
        &mut self,
        t: f64,
        y: &SVector<f64, N>,
        work: &mut Work,
    ) -> Result<(), OdeError> {
        let (p, stride) = (self.p, self.p + 1);
        for (i, yi) in y.iter().enumerate() {
            self.c[i * stride] = *yi;
        }
        // t + s: coefficients t, 1, 0, … (the zeros from the store's start, never written)
        self.c[N * stride] = t;
        self.c[N * stride + 1] = 1.0;
        for k in 0..p {
            self.tape.pass(k, &mut self.c);
            work.fevals += 1;
            let div = f64::from((k + 1) as u32);
            for (i, &at) in self.out.iter().enumerate() {
                let fk = self.c[at + k];
                let v = fk / div;
                if !v.is_finite() {
                    return Err(OdeError::RhsNotFinite {
                        t,
                        step_start: t,
                        stage: k + 1,
                        index: i,
                        value: fk,
                    });
                }
                self.c[i * stride + k + 1] = v;
            }
        }
        Ok(())
    }

    /// Coefficient k of component i.
    fn x(&self, i: usize, k: usize) -> f64 {
        self.c[i * (self.p + 1) + k]
    }

    /// ‖xₖ‖∞ over the components.
    fn norm(&self, k: usize) -> f64 {
        (0..self.n).map(|i| self.x(i, k).abs()).fold(0.0, f64::max)
    }

    /// Jorba & Zou's step: min over k ∈ {p − 1, p} of (ε/‖xₖ‖)^{1/k}, times e^{−0.7/(p−1)};
    /// ∞ when both coefficients vanish (a polynomial solution of lower degree).
    fn step_size(&self, eps: f64) -> f64 {
        let p = self.p;
        let rho = [p - 1, p]
            .iter()
            .map(|&k| {
                let nk = self.norm(k);
                if nk > 0.0 { (eps / nk).powf(1.0 / k as f64) } else { f64::INFINITY }
            })
            .fold(f64::INFINITY, f64::min);
        rho * (-0.7 / (p - 1) as f64).exp()
    }

    /// Σₖ xₖ hᵏ by Horner's rule.
    fn sum<const N: usize>(&self, h: f64) -> SVector<f64, N> {
        SVector::from_fn(|i, _| (0..=self.p).rev().fold(0.0, |acc, k| acc * h + self.x(i, k)))
    }

    /// The step's series as dense output: coefficients xₖhᵏ of θ ∈ [0, 1].
    fn dense_step<const N: usize>(&self, t: f64, h: f64) -> DenseStep<SVector<f64, N>> {
        let stride = self.p + 1;
        let mut hk = 1.0;
        let c = (0..stride)
            .map(|k| {
                let v = SVector::from_fn(|i, _| self.x(i, k) * hk);
                hk *= h;
                v
            })
            .collect();
        DenseStep { t, h, c, form: Form::Taylor }
    }
}
