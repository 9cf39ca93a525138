//! What a run cost: evaluations, steps, Jacobians, wall time.

use std::time::Duration;

/// The work done by one integration run.
///
/// Book: §4.11 (numerical integration); the counters follow Hairer's `dop853.f`
/// (NFCN, NACCPT, NREJCT) and `radau5.f` (NJAC, NDEC).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Work {
    /// Right-hand side evaluations f(t, y).
    pub fevals: usize,
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps (error test failed).
    pub rejected: usize,
    /// Jacobian evaluations ∂f/∂y (implicit methods).
    pub jacobians: usize,
    /// LU factorizations of the Newton matrix (implicit methods).
    pub factorizations: usize,
    /// Newton iterations in total (implicit methods).
    pub newton_iterations: usize,
    /// Of `fevals`, those spent on finite-difference Jacobians (0 when the Jacobian is
    /// exact: supplied by the caller or from dual numbers).
    pub fd_jacobian_fevals: usize,
    /// Wall-clock time of the run.
    pub wall: Duration,
}

impl core::fmt::Display for Work {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} f-evals, {} accepted, {} rejected, {} Jacobians, {} LU, {} Newton its, {:.3} ms",
            self.fevals,
            self.accepted,
            self.rejected,
            self.jacobians,
            self.factorizations,
            self.newton_iterations,
            self.wall.as_secs_f64() * 1e3
        )?;
        if self.fd_jacobian_fevals > 0 {
            write!(f, " (Jacobians by finite differences: {} of the f-evals)", self.fd_jacobian_fevals)?;
        }
        Ok(())
    }
}
