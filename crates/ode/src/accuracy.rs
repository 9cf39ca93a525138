//! Stating an accuracy instead of a method: [`Accuracy::RelTol`] picks the method and
//! tolerance that reached that global error at least cost in the work–precision harness.

use crate::explicit::{Adaptive, Pair, Solution};
use crate::{OdeError, State};

/// The accuracy a user asks for.
///
/// Book: §4.11; derived from the harness (`vectrix accuracy`, docs/accuracy.md).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Accuracy {
    /// Global relative error of the end state, for problems whose state components are of
    /// order one (stiff ones included: see [`Accuracy::solve_with_choice`]) (the scale of the reference problems; set `atol` yourself through
    /// [`Accuracy::solver`] for other scales).
    RelTol(f64),
}

/// One row of [`ACCURACY_TABLE`]: for a global error ≤ `target`, run `pair` at
/// rtol = atol = `rtol`.
///
/// Book: §4.11.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccuracyRow {
    /// Global error reached on every non-stiff reference problem.
    pub target: f64,
    /// The pair that reached it at least summed wall time.
    pub pair: Pair,
    /// The largest swept local tolerance that reached it.
    pub rtol: f64,
}

/// The table behind [`Accuracy`], copied from `harness::derive_accuracy` on the full
/// harness (`cargo run --release -- accuracy`, 2026-11-21). How it was derived: for every
/// target 10⁻ᵏ and both adaptive pairs, the largest rtol of the sweep 10⁻³…10⁻¹³ whose
/// end-time error was ≤ target on *all* non-stiff reference problems (oscillator, pendulum
/// θ₀ = 3, Kepler e = 0, 0.5, 0.9, rigid body); of the two pairs the one with the smaller
/// summed wall time won. DOP853 won every row: the global error of Kepler e = 0.9 is
/// 10–100× the local tolerance, which forces tight tolerances where the 8th-order pair is
/// cheaper. No swept tolerance reached 10⁻¹² everywhere, so the table stops at 10⁻¹¹.
///
/// Book: §4.11; HNW §II.10.
pub const ACCURACY_TABLE: [AccuracyRow; 9] = [
    AccuracyRow { target: 1e-3, pair: Pair::Dop853, rtol: 1e-6 },
    AccuracyRow { target: 1e-4, pair: Pair::Dop853, rtol: 1e-7 },
    AccuracyRow { target: 1e-5, pair: Pair::Dop853, rtol: 1e-8 },
    AccuracyRow { target: 1e-6, pair: Pair::Dop853, rtol: 1e-9 },
    AccuracyRow { target: 1e-7, pair: Pair::Dop853, rtol: 1e-9 },
    AccuracyRow { target: 1e-8, pair: Pair::Dop853, rtol: 1e-11 },
    AccuracyRow { target: 1e-9, pair: Pair::Dop853, rtol: 1e-11 },
    AccuracyRow { target: 1e-10, pair: Pair::Dop853, rtol: 1e-12 },
    AccuracyRow { target: 1e-11, pair: Pair::Dop853, rtol: 1e-13 },
];

impl Accuracy {
    /// The table row chosen: the loosest target that is at least as strict as requested.
    ///
    /// # Errors
    /// [`OdeError::NonPositiveTolerance`] for a tolerance ≤ 0 or not finite;
    /// [`OdeError::UnreachableAccuracy`] below the strictest target of [`ACCURACY_TABLE`].
    pub fn row(&self) -> Result<AccuracyRow, OdeError> {
        let Accuracy::RelTol(tol) = *self;
        crate::error::check_tol("rtol", tol)?;
        ACCURACY_TABLE.iter().find(|r| r.target <= tol).copied().ok_or(OdeError::UnreachableAccuracy {
            requested: tol,
            best: ACCURACY_TABLE[ACCURACY_TABLE.len() - 1].target,
        })
    }

    /// The adaptive solver the table selects (rtol = atol from the table).
    ///
    /// # Errors
    /// As [`Accuracy::row`].
    pub fn solver(&self) -> Result<Adaptive, OdeError> {
        let row = self.row()?;
        let a = match row.pair {
            Pair::Dopri5 => Adaptive::dopri5(),
            Pair::Dop853 => Adaptive::dop853(),
            Pair::Vern9 => Adaptive::vern9(),
        };
        Ok(a.rtol(row.rtol).atol(row.rtol))
    }

    /// Solves y′ = f(t, y) on [t0, t1] with the selected solver, switching to the stiff table's
    /// method where the problem turns out stiff ([`Accuracy::solve_with_choice`] says which).
    ///
    /// # Errors
    /// As [`Accuracy::row`] and [`Adaptive::solve`].
    pub fn solve<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<Solution<S>, OdeError> {
        Ok(self.solve_with_choice(f, t0, y0, t1)?.0)
    }
}

/// One row of [`STIFF_ACCURACY_TABLE`]: for a global error ≤ `target` on a stiff problem, run
/// `method` (`radau5` or `bdf`) at rtol = atol = `rtol` with finite-difference Jacobians.
///
/// Book: §4.11; HW §IV.8, §III.5.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StiffRow {
    /// Global error reached on every stiff reference problem.
    pub target: f64,
    /// `radau5` or `bdf`.
    pub method: &'static str,
    /// The largest swept local tolerance that reached it.
    pub rtol: f64,
}

/// The stiff half of the [`Accuracy`] table, copied from `harness::derive_stiff_accuracy`
/// (deterministic: cost in f-evaluations; checked against it by `tests/stiff_accuracy.rs`).
/// How it was derived: for every target 10⁻ᵏ and both stiff methods, the largest rtol of the
/// sweep 10⁻²…10⁻¹³ whose end-time error was ≤ target on *all* stiff reference problems (a
/// linear stiff system against its closed form, Van der Pol μ = 1000 against the Test Set,
/// Robertson to t = 40 against scipy Radau at 1e-13); of the two methods the one with fewer
/// f-evaluations (finite-difference Jacobian columns included) won.
///
/// Book: §4.11; HW §IV.10 (work–precision of stiff codes).
pub const STIFF_ACCURACY_TABLE: [StiffRow; 8] = [
    StiffRow { target: 1e-3, method: "bdf", rtol: 1e-5 },
    StiffRow { target: 1e-4, method: "radau5", rtol: 1e-5 },
    StiffRow { target: 1e-5, method: "radau5", rtol: 1e-5 },
    StiffRow { target: 1e-6, method: "radau5", rtol: 1e-6 },
    StiffRow { target: 1e-7, method: "radau5", rtol: 1e-7 },
    StiffRow { target: 1e-8, method: "radau5", rtol: 1e-9 },
    StiffRow { target: 1e-9, method: "radau5", rtol: 1e-10 },
    StiffRow { target: 1e-10, method: "radau5", rtol: 1e-11 },
];

impl Accuracy {
    /// The stiff method the table selects for this accuracy (rtol = atol from
    /// [`STIFF_ACCURACY_TABLE`]).
    ///
    /// # Errors
    /// [`OdeError::NonPositiveTolerance`]; [`OdeError::UnreachableAccuracy`] below the
    /// strictest stiff target.
    pub fn stiff_solver(&self) -> Result<crate::Method, OdeError> {
        let Accuracy::RelTol(tol) = *self;
        crate::error::check_tol("rtol", tol)?;
        let row = STIFF_ACCURACY_TABLE.iter().find(|r| r.target <= tol).copied().ok_or(
            OdeError::UnreachableAccuracy {
                requested: tol,
                best: STIFF_ACCURACY_TABLE.last().map_or(f64::INFINITY, |r| r.target),
            },
        )?;
        Ok(match row.method {
            "bdf" => crate::Method::Bdf(crate::Bdf::new().rtol(row.rtol).atol(row.rtol)),
            _ => crate::Method::Radau5(crate::Radau5::new().rtol(row.rtol).atol(row.rtol)),
        })
    }

    /// [`Accuracy::solve`] with the method it ran and why: DOP853 from the table, switched to
    /// the stiff method of [`STIFF_ACCURACY_TABLE`] where the stiffness test of
    /// [`STIFF_H_RHO`](crate::STIFF_H_RHO) fires (as LSODA switches; the test and its
    /// constants are in the crate's `stiffness` module docs).
    ///
    /// # Errors
    /// As [`Accuracy::row`], [`Accuracy::stiff_solver`] and the methods' `solve`.
    pub fn solve_with_choice<S: State, F: FnMut(f64, &S) -> S>(
        &self,
        f: F,
        t0: f64,
        y0: &S,
        t1: f64,
    ) -> Result<(Solution<S>, crate::Choice), OdeError> {
        let explicit = self.solver()?;
        let stiff = self.stiff_solver()?.with_max_steps(explicit.max_steps);
        crate::stiffness::solve_switching(&explicit, &stiff, f, t0, y0, t1)
    }
}
