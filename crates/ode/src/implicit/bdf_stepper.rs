//! BDF one accepted step at a time: the quasi-constant-step, variable-order algorithm of
//! Shampine & Reichelt (1997) on the array of backward differences D = (yₙ, ∇yₙ, …, ∇ᵏ⁺²yₙ),
//! as scipy's `BDF` (`_step_impl`) with κ = 0.
//!
//! Book: §4.11; HW §III.5, §V.5; Shampine & Reichelt 1997; Byrne & Hindmarsh 1975.

use super::bdf::Bdf;
use super::lu::DenseLu;
use super::radau_core::{NoJacobian, jacobian_into, rms_scaled};
use crate::explicit::{DenseStep, Steps};
use crate::progress::Progress;
use crate::state::{State, check_state, eval};
use crate::{InPlace, Rhs};
use crate::{OdeError, Work};

/// Highest BDF order.
pub(crate) const MAX_ORDER: usize = 5;
/// Bounds of h_new/h after an accepted step's order and step-size choice.
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;

/// γₖ = Σⱼ₌₁ᵏ 1/j (γ₀ = 0): with κ = 0 the BDF of order k reads
/// Σⱼ₌₁ᵏ (1/j)∇ʲyₙ₊₁ = h f, i.e. γₖ(yₙ₊₁ − y⁽⁰⁾) + Σⱼ₌₁ᵏ γⱼ∇ʲyₙ = h f (Shampine & Reichelt (5)).
fn gamma(k: usize) -> f64 {
    (1..=k).map(|j| 1.0 / j as f64).sum()
}

/// The error constant of order k: 1/(k + 1) (HW (III.5.9) with κ = 0).
fn error_const(k: usize) -> f64 {
    1.0 / (k as f64 + 1.0)
}

/// R(k, ρ): the (k+1)×(k+1) matrix that maps the differences of a step h to those of ρh,
/// R₀ⱼ = 1, Rᵢⱼ = Πᵣ₌₁ⁱ (r − 1 − ρj)/r (Shampine & Reichelt, §2.2; scipy `compute_R`).
fn compute_r(k: usize, rho: f64) -> Vec<Vec<f64>> {
    let mut r = vec![vec![1.0; k + 1]; k + 1];
    for i in 1..=k {
        let (above, rows) = r.split_at_mut(i);
        for (j, (rij, up)) in rows[0].iter_mut().zip(&above[i - 1]).enumerate() {
            let m = if j == 0 { 0.0 } else { (i as f64 - 1.0 - rho * j as f64) / i as f64 };
            *rij = up * m;
        }
    }
    r
}

/// D[0..=k] ← (R(k, ρ)·U(k))ᵀ D[0..=k]: the differences re-expressed on the grid of step ρh
/// (U = R(k, 1), so that R·U is the change of grid; scipy `change_D`).
fn change_d(d: &mut [Vec<f64>], k: usize, rho: f64) {
    let (r, u) = (compute_r(k, rho), compute_r(k, 1.0));
    let n = d[0].len();
    let ru: Vec<Vec<f64>> =
        (0..=k).map(|i| (0..=k).map(|j| (0..=k).map(|m| r[i][m] * u[m][j]).sum()).collect()).collect();
    let old: Vec<Vec<f64>> = d[..=k].to_vec();
    for (i, di) in d.iter_mut().enumerate().take(k + 1) {
        for c in 0..n {
            di[c] = (0..=k).map(|j| ru[j][i] * old[j][c]).sum();
        }
    }
}

/// A BDF integration in progress, with the interface of [`Stepper`](crate::explicit::Stepper)
/// ([`Progress`] by `Deref` for t, y, the end and the work): [`BdfStepper::step`] takes one
/// accepted step, [`BdfStepper::dense`] gives the interpolating polynomial,
/// [`BdfStepper::restart`] continues after a jump at order 1. `J` writes ∂f/∂y row-major
/// (finite differences when `None`, counted in [`Work::fd_jacobian_fevals`]).
///
/// Book: §4.11; HW §III.5; Shampine & Reichelt 1997.
pub struct BdfStepper<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64]) = NoJacobian<S>> {
    cfg: Bdf,
    f: F,
    jac_fn: Option<J>,
    /// t, y, the last step, h, the end time and the work (the accessors, by `Deref`).
    p: Progress<S>,
    /// D = (y, h y′ ≈ ∇y, ∇²y, …): MAX_ORDER + 3 rows of n.
    d: Vec<Vec<f64>>,
    order: usize,
    n_equal_steps: usize,
    /// ∂f/∂y, row-major (entry (i, j) at i·n + j).
    jm: Vec<f64>,
    /// LU of I − cJ, factorized in place (buffers allocated once), and its c; `None` when
    /// stale or refused.
    lu: DenseLu<f64>,
    lu_c: Option<f64>,
    /// The buffers of a step, allocated once (lent to each step by `step`).
    ws: Scratch,
    /// The state at a Newton iterate.
    ys: S,
    newton_tol: f64,
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::fmt::Debug for BdfStepper<S, F, J> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("BdfStepper")
            .field("t", &self.p.t)
            .field("h", &self.p.h)
            .field("order", &self.order)
            .field("work", &self.p.work)
            .finish()
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::ops::Deref for BdfStepper<S, F, J> {
    type Target = Progress<S>;
    fn deref(&self) -> &Progress<S> {
        &self.p
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::ops::DerefMut for BdfStepper<S, F, J> {
    fn deref_mut(&mut self) -> &mut Progress<S> {
        &mut self.p
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> Steps<S> for BdfStepper<S, F, J> {
    fn step(&mut self) -> Result<(), OdeError> {
        BdfStepper::step(self)
    }
    fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        BdfStepper::dense(self)
    }
}

/// The outcome of one Newton solve of the BDF equation (its y and d are in [`Scratch`]).
struct Newton {
    converged: bool,
    iterations: usize,
    error: Option<OdeError>,
}

/// The vectors of one BDF step, n each, allocated once per run.
#[derive(Default)]
struct Scratch {
    /// Predictor y⁽⁰⁾ = Σⱼ₌₀ᵏ Dⱼ.
    y_pred: Vec<f64>,
    /// ψ = Σⱼ₌₁ᵏ γⱼDⱼ/γₖ.
    psi: Vec<f64>,
    /// atol + rtol·|y|: at the predictor for Newton, at the new y for the error test.
    scale: Vec<f64>,
    /// Newton's iterate y and d = y − y⁽⁰⁾ = ∇ᵏ⁺¹yₙ₊₁, and its correction Δ.
    y: Vec<f64>,
    d: Vec<f64>,
    dy: Vec<f64>,
    /// The local error (1/(k+1))·d.
    err: Vec<f64>,
}

impl Scratch {
    fn new(n: usize) -> Self {
        let v = || vec![0.0; n];
        Self { y_pred: v(), psi: v(), scale: v(), y: v(), d: v(), dy: v(), err: v() }
    }
}

/// How a step attempt ended when it was not accepted.
enum Failure {
    Newton,
    Singular,
}

impl<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S, &mut [f64])> BdfStepper<S, F, J> {
    /// Starts integrating y′ = f(t, y), y(t0) = y0 toward `t_end` with the tolerances and
    /// limits of `cfg` and the Jacobian `jac` (finite differences when `None`); the first
    /// step is Hairer's starting step for order 1, the first order 1.
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`],
    /// [`OdeError::NonPositiveStep`], [`OdeError::InvalidSetting`] (max_order outside 1–5,
    /// max_newton = 0), [`OdeError::NonFiniteState`], [`OdeError::TooManySteps`] when h_max
    /// cannot cover the interval, [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`]
    /// and [`OdeError::JacobianNotFinite`] from the first evaluations.
    pub fn new(cfg: &Bdf, f: F, jac: Option<J>, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        Self::start(cfg, f, jac, t0, y0, t_end)
    }
}

impl<S: State, G: FnMut(f64, &S, &mut S), J: FnMut(f64, &S, &mut [f64])> BdfStepper<S, InPlace<G>, J> {
    /// [`BdfStepper::new`] with f written in place, `g(t, y, out)` ([`InPlace`]): the same steps
    /// and bits.
    ///
    /// # Errors
    /// As [`BdfStepper::new`].
    pub fn new_in_place(
        cfg: &Bdf,
        g: G,
        jac: Option<J>,
        t0: f64,
        y0: S,
        t_end: f64,
    ) -> Result<Self, OdeError> {
        Self::start(cfg, InPlace(g), jac, t0, y0, t_end)
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> BdfStepper<S, F, J> {
    /// [`BdfStepper::new`] for any [`Rhs`].
    pub(crate) fn start(
        cfg: &Bdf,
        mut f: F,
        mut jac: Option<J>,
        t0: f64,
        y0: S,
        t_end: f64,
    ) -> Result<Self, OdeError> {
        let h_max = cfg.check(t0, t_end)?;
        if !(1..=MAX_ORDER).contains(&cfg.method.max_order) {
            return Err(OdeError::InvalidSetting {
                name: "max_order",
                value: cfg.method.max_order,
                valid: "1 to 5",
            });
        }
        if cfg.method.max_newton == 0 {
            return Err(OdeError::InvalidSetting { name: "max_newton", value: 0, valid: "at least 1" });
        }
        check_state(t0, &y0)?;
        let mut work = Work::default();
        let f0 = eval(&mut f, t0, &y0, t0, 1, &mut work.fevals)?;
        let h = match cfg.h0 {
            Some(h0) => h0.min(h_max),
            None => crate::explicit::initial_step(
                &mut f,
                t0,
                &y0,
                &f0,
                1.0,
                h_max,
                (cfg.rtol, cfg.atol),
                &mut work,
            )?,
        };
        let n = y0.dim();
        let y0_copy = y0.clone();
        let mut jm = vec![0.0; n * n];
        jacobian_into(&mut f, jac.as_mut(), t0, &y0, f0.as_slice(), &mut jm, &mut work)?;
        let mut d = vec![vec![0.0; n]; MAX_ORDER + 3];
        d[0].copy_from_slice(y0.as_slice());
        for (di, fi) in d[1].iter_mut().zip(f0.as_slice()) {
            *di = h * fi;
        }
        let mut p = Progress::new(t0, y0, t_end, h_max, cfg.h_max, work);
        p.h = h;
        Ok(Self {
            cfg: *cfg,
            f,
            jac_fn: jac,
            p,
            d,
            order: 1,
            n_equal_steps: 0,
            jm,
            lu: DenseLu::new(n),
            lu_c: None,
            ws: Scratch::new(n),
            ys: y0_copy,
            newton_tol: (10.0 * f64::EPSILON / cfg.rtol).max(0.03f64.min(cfg.rtol.sqrt())),
        })
    }

    /// `true` when the Jacobian is supplied (exact), `false` for finite differences.
    pub fn exact_jacobian(&self) -> bool {
        self.jac_fn.is_some()
    }

    /// The order the next step uses (1 to `max_order`).
    pub fn order(&self) -> usize {
        self.order
    }

    /// Rescales the differences to the step ρh (the order's step-size history restarts).
    fn rescale(&mut self, rho: f64) {
        change_d(&mut self.d, self.order, rho);
        self.n_equal_steps = 0;
    }

    /// Simplified Newton on γₖ(y − y⁽⁰⁾) + ψ = h f(t, y) as scipy's `solve_bdf_system`:
    /// (I − cJ)Δ = c f(y) − ψ/γₖ·… − d with c = h/γₖ; stops on the rate test of
    /// Shampine & Reichelt (a rate ≥ 1 or one too slow for the remaining iterations fails).
    fn newton(&mut self, t_new: f64, c: f64, ws: &mut Scratch) -> Newton {
        let Scratch { y_pred, psi, scale, y, d, dy, .. } = ws;
        let n = y_pred.len();
        let cap = self.cfg.method.max_newton;
        y.copy_from_slice(y_pred);
        d.fill(0.0);
        let mut dy_norm_old: Option<f64> = None;
        let mut out = Newton { converged: false, iterations: 0, error: None };
        if self.lu_c.is_none() {
            return out;
        }
        for k in 0..cap {
            out.iterations = k + 1;
            self.ys.as_mut_slice().copy_from_slice(y);
            let fy = match eval(&mut self.f, t_new, &self.ys, self.p.t, 1, &mut self.p.work.fevals) {
                Ok(v) => v,
                Err(e) => {
                    out.error = Some(e);
                    break;
                }
            };
            self.p.work.newton_iterations += 1;
            // Δ = (I − cJ)⁻¹ (c f − ψ − d)
            for (i, dyi) in dy.iter_mut().enumerate() {
                *dyi = c * fy.as_slice()[i] - psi[i] - d[i];
            }
            // the factors are valid (lu_c is Some) and dy has length n
            let solved = self.lu.solve(dy);
            debug_assert!(solved.is_ok(), "{solved:?}");
            let dy_norm = rms_scaled(dy, scale);
            if !dy_norm.is_finite() {
                break;
            }
            let rate = dy_norm_old.map(|old| dy_norm / old);
            if let Some(r) = rate
                && (r >= 1.0 || r.powi((cap - k) as i32) / (1.0 - r) * dy_norm > self.newton_tol)
            {
                break;
            }
            for i in 0..n {
                y[i] += dy[i];
                d[i] += dy[i];
            }
            if dy_norm == 0.0 || rate.is_some_and(|r| r / (1.0 - r) * dy_norm < self.newton_tol) {
                out.converged = true;
                break;
            }
            dy_norm_old = Some(dy_norm);
        }
        out
    }

    /// J at (t, y) (refreshed when Newton fails with an old one).
    fn refresh_jacobian(&mut self, t: f64, y: &[f64]) -> Result<(), OdeError> {
        let mut ys = self.p.y.clone();
        ys.as_mut_slice().copy_from_slice(y);
        let f0 = if self.jac_fn.is_some() {
            Vec::new()
        } else {
            eval(&mut self.f, t, &ys, self.p.t, 1, &mut self.p.work.fevals)?.as_slice().to_vec()
        };
        jacobian_into(&mut self.f, self.jac_fn.as_mut(), t, &ys, &f0, &mut self.jm, &mut self.p.work)?;
        self.lu_c = None;
        Ok(())
    }

    /// Factorizes I − cJ unless the factors for this c are at hand (or, after an error-test
    /// rejection, the previous ones are kept as scipy does); `false` when singular.
    fn factorize(&mut self, c: f64) -> bool {
        if self.lu_c.is_some() {
            return true;
        }
        let (n, jm) = (self.lu.dim(), &self.jm);
        self.p.work.factorizations += 1;
        // I − cJ
        let ok = self
            .lu
            .factor_with(|i, j| if i == j { 1.0 - c * jm[i * n + j] } else { -c * jm[i * n + j] })
            .is_ok();
        self.lu_c = ok.then_some(c);
        ok
    }
}

#[path = "bdf_step.rs"]
mod step;
