//! RADAU5 one accepted step at a time: the step-size and Jacobian/factorization control of
//! Hairer & Wanner's `radau5.f` (`RADCOR`) around the linear algebra of `radau_core`.
//!
//! Book: §4.11; HW §IV.8 (implementation of implicit Runge–Kutta methods).

use super::radau_core::{
    C1, C2, Factors, NoJacobian, T_MAT, TI_MAT, estimate, jacobian_into, rms_scaled, transform,
};
use super::radau5::Radau5;
use crate::explicit::{DenseStep, Steps};
use crate::progress::Progress;
use crate::{InPlace, Rhs};

#[path = "radau_restart.rs"]
mod restart;
use crate::state::{State, check_state, eval};
use crate::{OdeError, Work};

/// Jacobians are kept while the Newton contraction stays below this (`THET` of `radau5.f`).
const THET: f64 = 1e-3;
/// Safety factor of the step-size controller.
const SAFE: f64 = 0.9;
/// Bounds of h_new/h: [1/FACL, 1/FACR] = [0.2, 8].
const FACL: f64 = 5.0;
const FACR: f64 = 0.125;
/// Consecutive failed Newton iterations (or singular matrices) before giving up.
const MAX_FAILURES: usize = 10;

/// A RADAU5 integration in progress, with the interface of
/// [`Stepper`](crate::explicit::Stepper): [`RadauStepper::step`] takes one accepted step,
/// [`RadauStepper::dense`] gives its collocation polynomial, [`RadauStepper::restart`]
/// continues after a jump. `J` writes ∂f/∂y row-major (entry (i, j) at i·n + j); without
/// one the Jacobian is taken by finite differences, counted in [`Work::fd_jacobian_fevals`].
///
/// Book: §4.11; HW §IV.8.
pub struct RadauStepper<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64]) = NoJacobian<S>> {
    cfg: Radau5,
    f: F,
    jac_fn: Option<J>,
    /// t, y, the last step, h, the end time and the work (the accessors, by `Deref`).
    p: Progress<S>,
    /// Tolerances transformed as in `radau5.f`: rtol' = 0.1·rtol^{2/3}, atol' = rtol'·atol/rtol.
    tol: (f64, f64),
    /// Newton stopping tolerance.
    fnewt: f64,
    f_now: Vec<f64>,
    scal: Vec<f64>,
    /// ∂f/∂y, row-major (entry (i, j) at i·n + j).
    jm: Vec<f64>,
    /// `true` when `jm` was evaluated at the current (t, y) (`CALJAC`).
    jac_fresh: bool,
    need_jac: bool,
    /// The factorized iteration matrices (buffers allocated once; stale after a new J).
    lu: Factors,
    /// Newton's buffers, allocated once: stage increments Z, transformed W, stage
    /// derivatives F(Z), and the stage state y + Zₖ.
    z: [Vec<f64>; 3],
    w: [Vec<f64>; 3],
    fz: [Vec<f64>; 3],
    ys: S,
    /// Collocation coefficients of the last accepted step and its size (starting values).
    cont: [Vec<f64>; 3],
    hold: f64,
    first: bool,
    reject: bool,
    faccon: f64,
    theta: f64,
    /// Gustafsson's predictive controller: last accepted h and error, and accepted steps.
    hacc: f64,
    erracc: f64,
    naccpt: usize,
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::ops::Deref for RadauStepper<S, F, J> {
    type Target = Progress<S>;
    fn deref(&self) -> &Progress<S> {
        &self.p
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::ops::DerefMut for RadauStepper<S, F, J> {
    fn deref_mut(&mut self) -> &mut Progress<S> {
        &mut self.p
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> Steps<S> for RadauStepper<S, F, J> {
    fn step(&mut self) -> Result<(), OdeError> {
        RadauStepper::step(self)
    }
    fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        RadauStepper::dense(self)
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::fmt::Debug for RadauStepper<S, F, J> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("RadauStepper")
            .field("t", &self.p.t)
            .field("h", &self.p.h)
            .field("work", &self.p.work)
            .finish()
    }
}

/// The outcome of one Newton solve.
enum Newton {
    Converged(usize),
    /// Converging too slowly for this h: retry with h·factor.
    Slow(f64),
    /// Diverging, iteration cap, or a non-finite f at an iterate.
    Failed(Option<OdeError>),
}

impl<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S, &mut [f64])> RadauStepper<S, F, J> {
    /// Starts integrating y′ = f(t, y), y(t0) = y0 toward `t_end` with the tolerances and
    /// limits of `cfg` and the Jacobian `jac` (finite differences when `None`).
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`], [`OdeError::NonPositiveTolerance`] (also for
    /// `max_newton` = 0), [`OdeError::NonPositiveStep`], [`OdeError::NonFiniteState`],
    /// [`OdeError::TooManySteps`] when h_max cannot cover the interval, and
    /// [`OdeError::RhsNotFinite`] or [`OdeError::DimensionMismatch`] from f(t0, y0).
    pub fn new(cfg: &Radau5, f: F, jac: Option<J>, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        Self::start(cfg, f, jac, t0, y0, t_end)
    }
}

impl<S: State, G: FnMut(f64, &S, &mut S), J: FnMut(f64, &S, &mut [f64])> RadauStepper<S, InPlace<G>, J> {
    /// [`RadauStepper::new`] with f written in place, `g(t, y, out)` ([`InPlace`]): the same steps
    /// and bits.
    ///
    /// # Errors
    /// As [`RadauStepper::new`].
    pub fn new_in_place(
        cfg: &Radau5,
        g: G,
        jac: Option<J>,
        t0: f64,
        y0: S,
        t_end: f64,
    ) -> Result<Self, OdeError> {
        Self::start(cfg, InPlace(g), jac, t0, y0, t_end)
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> RadauStepper<S, F, J> {
    /// [`RadauStepper::new`] for any [`Rhs`].
    pub(crate) fn start(
        cfg: &Radau5,
        mut f: F,
        jac: Option<J>,
        t0: f64,
        y0: S,
        t_end: f64,
    ) -> Result<Self, OdeError> {
        let h_max = cfg.check(t0, t_end)?;
        if cfg.method.max_newton == 0 {
            return Err(OdeError::NonPositiveTolerance { name: "max_newton", value: 0.0 });
        }
        check_state(t0, &y0)?;
        let mut work = Work::default();
        let f_now = eval(&mut f, t0, &y0, t0, 1, &mut work.fevals)?.as_slice().to_vec();
        let rtol = 0.1 * cfg.rtol.powf(2.0 / 3.0);
        let tol = (rtol, rtol * cfg.atol / cfg.rtol);
        let n = y0.dim();
        let mut st = Self {
            cfg: *cfg,
            f,
            jac_fn: jac,
            tol,
            fnewt: (10.0 * f64::EPSILON / rtol).max(0.03f64.min(rtol.sqrt())),
            f_now,
            scal: vec![0.0; n],
            jm: vec![0.0; n * n],
            jac_fresh: false,
            need_jac: true,
            lu: Factors::new(n),
            z: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            w: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            fz: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            ys: y0.clone(),
            cont: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
            hold: 0.0,
            first: true,
            reject: false,
            faccon: 1.0,
            theta: THET,
            hacc: 0.0,
            erracc: 1e-2,
            naccpt: 0,
            p: Progress::new(t0, y0, t_end, h_max, cfg.h_max, work),
        };
        st.p.h = cfg.h0.unwrap_or(1e-6).min(h_max);
        st.update_scal();
        Ok(st)
    }

    fn update_scal(&mut self) {
        let (rtol, atol) = self.tol;
        for (s, y) in self.scal.iter_mut().zip(self.p.y.as_slice()) {
            *s = atol + rtol * y.abs();
        }
    }

    /// `true` when the Jacobian is supplied (exact), `false` for finite differences.
    pub fn exact_jacobian(&self) -> bool {
        self.jac_fn.is_some()
    }

    /// J = ∂f/∂y at the current point, refused if any entry is not finite.
    fn compute_jacobian(&mut self) -> Result<(), OdeError> {
        jacobian_into(
            &mut self.f,
            self.jac_fn.as_mut(),
            self.p.t,
            &self.p.y,
            &self.f_now,
            &mut self.jm,
            &mut self.p.work,
        )?;
        self.jac_fresh = true;
        self.need_jac = false;
        self.lu.invalidate();
        Ok(())
    }

    /// Takes one accepted step (rejected attempts are retried inside, smaller); the last step
    /// lands exactly on the end time. Does nothing when [`done`](Progress::done).
    ///
    /// # Errors
    /// [`OdeError::TooManySteps`], [`OdeError::StepSizeUnderflow`] (error test failing down
    /// to the round-off floor), [`OdeError::NewtonStalled`] (Newton failing down to the floor
    /// or ten times in a row), [`OdeError::SingularIterationMatrix`] (singular ten times in a
    /// row), [`OdeError::JacobianNotFinite`], [`OdeError::RhsNotFinite`] at an accepted point.
    pub fn step(&mut self) -> Result<(), OdeError> {
        if self.done() {
            return Ok(());
        }
        let (mut newton_failures, mut singular) = (0usize, 0usize);
        let mut last_error: Option<OdeError> = None;
        loop {
            if self.p.work.accepted + self.p.work.rejected >= self.cfg.max_steps {
                return Err(OdeError::TooManySteps { t: self.p.t, max_steps: self.cfg.max_steps });
            }
            let t = self.p.t;
            self.p.h = self.p.h.min(self.p.h_max);
            let last = t + 1.0001 * self.p.h >= self.p.t_end;
            if last {
                self.p.h = self.p.t_end - t;
            }
            let h = self.p.h;
            if 0.1 * h <= t.abs() * f64::EPSILON || h <= f64::MIN_POSITIVE {
                let state = self.p.y.as_slice().to_vec();
                return Err(if singular > 0 {
                    OdeError::SingularIterationMatrix { t, h, state }
                } else if newton_failures > 0 {
                    last_error.unwrap_or(OdeError::NewtonStalled { t, h, failures: newton_failures, state })
                } else {
                    OdeError::StepSizeUnderflow { t, h }
                });
            }
            if self.need_jac {
                self.compute_jacobian()?;
            }
            if self.lu.h() != Some(h) {
                self.p.work.factorizations += 1;
                if !self.lu.factor(&self.jm, h) {
                    singular += 1;
                    if singular >= MAX_FAILURES {
                        return Err(OdeError::SingularIterationMatrix {
                            t,
                            h,
                            state: self.p.y.as_slice().to_vec(),
                        });
                    }
                    self.p.h *= 0.5;
                    self.reject = true;
                    continue;
                }
            }
            self.starting_values(h);
            let [z1, z2, z3] = &self.z;
            let [w1, w2, w3] = &mut self.w;
            transform(&TI_MAT, [z1, z2, z3], [w1, w2, w3]);
            match self.newton(h) {
                Newton::Converged(newt) => {
                    if self.finish_step(h, last, newt)? {
                        return Ok(());
                    }
                }
                Newton::Slow(fac) => {
                    self.p.h *= fac;
                    self.reject = true;
                    self.need_jac |= !self.jac_fresh;
                }
                Newton::Failed(e) => {
                    newton_failures += 1;
                    if e.is_some() {
                        last_error = e;
                    }
                    if newton_failures >= MAX_FAILURES {
                        return Err(last_error.unwrap_or(OdeError::NewtonStalled {
                            t,
                            h,
                            failures: newton_failures,
                            state: self.p.y.as_slice().to_vec(),
                        }));
                    }
                    self.p.h *= 0.5;
                    self.reject = true;
                    self.need_jac |= !self.jac_fresh;
                }
            }
        }
    }

    /// Starting stage increments Z into `self.z`: zero on the first step, else the previous
    /// step's collocation polynomial extrapolated (HW (IV.8.5)).
    fn starting_values(&mut self, h: f64) {
        if self.first {
            self.z.iter_mut().for_each(|zk| zk.fill(0.0));
            return;
        }
        let (c1m1, c2m1) = (C1 - 1.0, C2 - 1.0);
        let c3q = h / self.hold;
        let [a1, a2, a3] = &self.cont;
        for (zk, cq) in self.z.iter_mut().zip([C1 * c3q, C2 * c3q, c3q]) {
            for (i, zi) in zk.iter_mut().enumerate() {
                *zi = cq * (a1[i] + (cq - c2m1) * (a2[i] + (cq - c1m1) * a3[i]));
            }
        }
    }

    /// Simplified Newton on the transformed stage equations (HW §IV.8, `RADCOR` label 40):
    /// at most `max_newton` iterations; the contraction θ decides whether to go on.
    fn newton(&mut self, h: f64) -> Newton {
        let nit = self.cfg.method.max_newton;
        let nodes = [C1, C2, 1.0];
        self.faccon = self.faccon.max(f64::EPSILON).powf(0.8);
        self.theta = THET;
        let (mut dynold, mut thqold) = (0.0, 0.0);
        let (z, w, fz) = (&mut self.z, &mut self.w, &mut self.fz);
        for newt in 1..=nit {
            for k in 0..3 {
                // the stage state y + Zₖ
                for ((o, yi), zi) in self.ys.as_mut_slice().iter_mut().zip(self.p.y.as_slice()).zip(&z[k]) {
                    *o = yi + zi;
                }
                match eval(
                    &mut self.f,
                    self.p.t + nodes[k] * h,
                    &self.ys,
                    self.p.t,
                    k + 1,
                    &mut self.p.work.fevals,
                ) {
                    Ok(v) => fz[k].copy_from_slice(v.as_slice()),
                    Err(e) => return Newton::Failed(Some(e)),
                }
            }
            let [z1, z2, z3] = z;
            transform(&TI_MAT, [&fz[0], &fz[1], &fz[2]], [z1, z2, z3]);
            self.lu.solve_newton([z1, z2, z3], [&w[0], &w[1], &w[2]]);
            self.p.work.newton_iterations += 1;
            let dyno = ((0..3).map(|k| rms_scaled(&z[k], &self.scal).powi(2)).sum::<f64>() / 3.0).sqrt();
            if !dyno.is_finite() {
                return Newton::Failed(None);
            }
            if newt > 1 && newt < nit {
                let thq = dyno / dynold;
                self.theta = if newt == 2 { thq } else { (thq * thqold).sqrt() };
                thqold = thq;
                if self.theta < 0.99 {
                    self.faccon = self.theta / (1.0 - self.theta);
                    let left = (nit - 1 - newt) as i32;
                    let dyth = self.faccon * dyno * self.theta.powi(left) / self.fnewt;
                    if dyth >= 1.0 {
                        let qnewt = dyth.clamp(1e-4, 20.0);
                        return Newton::Slow(0.8 * qnewt.powf(-1.0 / (4.0 + left as f64)));
                    }
                } else {
                    return Newton::Failed(None);
                }
            }
            dynold = dyno.max(f64::EPSILON);
            for k in 0..3 {
                for (wi, zi) in w[k].iter_mut().zip(&z[k]) {
                    *wi += zi;
                }
            }
            let [z1, z2, z3] = z;
            transform(&T_MAT, [&w[0], &w[1], &w[2]], [z1, z2, z3]);
            if self.faccon * dyno <= self.fnewt {
                return Newton::Converged(newt);
            }
        }
        Newton::Failed(None)
    }

    /// Error test and step-size choice after a converged Newton solve; on acceptance moves
    /// to the step's end and returns `true`, on rejection sets the smaller h and returns
    /// `false`. Gustafsson's predictive controller (HW (IV.8.25)) as `radau5.f` with PRED.
    fn finish_step(&mut self, h: f64, last: bool, newt: usize) -> Result<bool, OdeError> {
        let z = &self.z;
        let err = estimate(
            &mut self.f,
            &mut self.lu,
            (self.p.t, &self.p.y, &self.f_now),
            [&z[0], &z[1], &z[2]],
            &self.scal,
            self.first || self.reject,
            &mut self.p.work,
        )?;
        if std::env::var("RTRACE").is_ok() {
            eprintln!(
                "t={:e} h={:e} err={:e} newt={newt} first={} rej={}",
                self.p.t, h, err, self.first, self.reject
            );
        }
        let nit = self.cfg.method.max_newton as f64;
        let fac = SAFE.min(SAFE * (1.0 + 2.0 * nit) / (newt as f64 + 2.0 * nit));
        let mut quot = (err.powf(0.25) / fac).clamp(FACR, FACL);
        let mut hnew = h / quot;
        if err >= 1.0 {
            self.reject = true;
            self.p.h = if self.first { 0.1 * h } else { hnew };
            self.p.work.rejected += 1;
            self.need_jac |= !self.jac_fresh;
            return Ok(false);
        }
        self.naccpt += 1;
        if self.naccpt > 1 {
            let facgus = ((self.hacc / h) * (err * err / self.erracc).powf(0.25) / SAFE).clamp(FACR, FACL);
            quot = quot.max(facgus);
            hnew = h / quot;
        }
        self.hacc = h;
        self.erracc = err.max(1e-2);
        // the step's end and the collocation polynomial through it (`RADCOR` after 'accepted')
        let n = self.p.y.dim();
        let (c1m1, c2m1, c1mc2) = (C1 - 1.0, C2 - 1.0, C1 - C2);
        let mut y1 = self.p.y.clone();
        for (i, o) in y1.as_mut_slice().iter_mut().enumerate() {
            *o += z[2][i];
            let (z1, z2, z3) = (z[0][i], z[1][i], z[2][i]);
            let c1 = (z2 - z3) / c2m1;
            let ak = (z1 - z2) / c1mc2;
            let acont3 = (ak - z1 / C1) / C2;
            let c2 = (ak - c1) / c1m1;
            self.cont[0][i] = c1;
            self.cont[1][i] = c2;
            self.cont[2][i] = c2 - acont3;
        }
        let t_new = if last { self.p.t_end } else { self.p.t + h };
        let f1 = eval(&mut self.f, t_new, &y1, self.p.t, 4, &mut self.p.work.fevals)?;
        debug_assert_eq!(f1.dim(), n);
        self.f_now.copy_from_slice(f1.as_slice());
        self.p.advance(t_new, y1);
        self.update_scal();
        self.first = false;
        self.hold = h;
        hnew = hnew.min(self.p.h_max);
        if self.reject {
            hnew = hnew.min(h);
        }
        self.reject = false;
        self.jac_fresh = false;
        let qt = hnew / h;
        if self.theta <= THET && (1.0..=1.2).contains(&qt) && !last {
            self.p.h = h; // same h, same J and LU
        } else {
            self.p.h = hnew;
            self.need_jac = self.theta > THET;
        }
        Ok(true)
    }
}
