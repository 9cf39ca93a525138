//! The dense output, restart and end-time control of [`RadauStepper`] (a child module: it
//! reads the stepper's private state).
//!
//! Book: §4.11; HW §IV.8 (dense output of RADAU5).

use super::RadauStepper;
use crate::OdeError;
use crate::Rhs;
use crate::explicit::{DenseStep, Form};
use crate::state::{State, eval};

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> RadauStepper<S, F, J> {
    /// The collocation polynomial of the last accepted step, valid on
    /// [`step_start`](crate::Progress::step_start) .. [`t`](crate::Progress::t) (order 3 uniformly; exact at the
    /// nodes up to the Newton tolerance). No f evaluations.
    ///
    /// # Errors
    /// [`OdeError::NoDenseOutput`] before the first step or right after a restart.
    pub fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        if self.p.dense.is_none() {
            let Some((t0, _)) = &self.p.prev else { return Err(OdeError::NoDenseOutput) };
            let mut c = vec![self.p.y.clone(), self.p.y.clone(), self.p.y.clone(), self.p.y.clone()];
            for k in 0..3 {
                c[k + 1].as_mut_slice().copy_from_slice(&self.cont[k]);
            }
            self.p.dense = Some(DenseStep { t: *t0, h: self.p.t - t0, c, form: Form::Radau });
        }
        self.p.dense.as_ref().ok_or(OdeError::NoDenseOutput)
    }

    /// Continues from (t, y) after a jump of the state or of the right-hand side: f and the
    /// Jacobian are evaluated afresh, the Newton starting values start from zero, the step
    /// size proposal is kept.
    ///
    /// # Errors
    /// [`OdeError::NonFiniteState`], [`OdeError::InvalidInterval`] if t is past the end,
    /// [`OdeError::RhsNotFinite`], [`OdeError::DimensionMismatch`].
    pub fn restart(&mut self, t: f64, y: S) -> Result<(), OdeError> {
        self.p.check_restart(t, &y)?;
        let f0 = eval(&mut self.f, t, &y, t, 1, &mut self.p.work.fevals)?;
        self.f_now.copy_from_slice(f0.as_slice());
        self.p.t = t;
        self.p.y = y;
        self.update_scal();
        self.first = true;
        self.reject = false;
        self.need_jac = true;
        self.jac_fresh = false;
        self.naccpt = 0;
        Ok(())
    }
}
