//! The dense output, restart and end-time control of [`RadauStepper`] (a child module: it
//! reads the stepper's private state).
//!
//! Book: §4.11; HW §IV.8 (dense output of RADAU5).

use super::RadauStepper;
use crate::OdeError;
use crate::error::check_interval;
use crate::explicit::{DenseStep, Form};
use crate::state::{State, check_state, eval};

impl<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S, &mut [f64])> RadauStepper<S, F, J> {
    /// The collocation polynomial of the last accepted step, valid on
    /// [`RadauStepper::step_start`] .. [`RadauStepper::t`] (order 3 uniformly; exact at the
    /// nodes up to the Newton tolerance). No f evaluations.
    ///
    /// # Errors
    /// [`OdeError::NoDenseOutput`] before the first step or right after a restart.
    pub fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        if self.dense.is_none() {
            let Some((t0, _)) = &self.prev else { return Err(OdeError::NoDenseOutput) };
            let mut c = vec![self.y.clone(), self.y.clone(), self.y.clone(), self.y.clone()];
            for k in 0..3 {
                c[k + 1].as_mut_slice().copy_from_slice(&self.cont[k]);
            }
            self.dense = Some(DenseStep { t: *t0, h: self.t - t0, c, form: Form::Radau });
        }
        self.dense.as_ref().ok_or(OdeError::NoDenseOutput)
    }

    /// Continues from (t, y) after a jump of the state or of the right-hand side: f and the
    /// Jacobian are evaluated afresh, the Newton starting values start from zero, the step
    /// size proposal is kept.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteState`], [`OdeError::InvalidInterval`] if t is past the end,
    /// [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn restart(&mut self, t: f64, y: S) -> Result<(), OdeError> {
        check_interval(t, self.t_end).or_else(|e| if t == self.t_end { Ok(()) } else { Err(e) })?;
        check_state(t, &y)?;
        if y.dim() != self.y.dim() {
            return Err(OdeError::DimensionMismatch {
                what: "restarted state",
                got: y.dim(),
                expected: self.y.dim(),
            });
        }
        let f0 = eval(&mut self.f, t, &y, t, 1, &mut self.work.fevals)?;
        self.f_now.copy_from_slice(f0.as_slice());
        self.t = t;
        self.y = y;
        self.update_scal();
        self.prev = None;
        self.dense = None;
        self.first = true;
        self.reject = false;
        self.need_jac = true;
        self.jac_fresh = false;
        self.naccpt = 0;
        Ok(())
    }

    /// Moves the end time.
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`] unless t_end > [`RadauStepper::t`] and finite.
    pub fn set_end(&mut self, t_end: f64) -> Result<(), OdeError> {
        check_interval(self.t, t_end)?;
        self.t_end = t_end;
        if self.cfg.h_max.is_none() {
            self.h_max = t_end - self.t;
        }
        Ok(())
    }
}
