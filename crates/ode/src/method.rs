//! One stepping interface over the explicit pairs, extrapolation, RADAU5 and BDF, so that a
//! caller that drives the integration itself (scenes: samples, impacts, budgets) can take any.

use crate::explicit::{Adaptive, DenseStep, Extrapolation, GbsStepper, Stepper, Steps};
use crate::implicit::{Bdf, BdfStepper, Radau5, RadauStepper};
use crate::progress::Progress;
use crate::{InPlace, Rhs};
use crate::{OdeError, State};

/// An adaptive method: an explicit pair ([`Adaptive`]), extrapolation ([`Extrapolation`]) or a
/// stiff one ([`Radau5`], [`Bdf`]).
///
/// Book: §4.11; HNW §II.4–II.10 (explicit pairs, §II.9 extrapolation), HW §IV.8 (RADAU5),
/// §III.5 (BDF).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// DOPRI5, DOP853 or Vern9 (Vern9 without an interpolant: [`AnyStepper::dense`] refuses).
    Explicit(Adaptive),
    /// Gragg–Bulirsch–Stoer extrapolation (no interpolant: [`AnyStepper::dense`] refuses).
    Gbs(Extrapolation),
    /// Radau IIA 5.
    Radau5(Radau5),
    /// Variable-order BDF (1–5).
    Bdf(Bdf),
}

impl Method {
    /// Most steps (accepted + rejected) of a run.
    pub fn max_steps(&self) -> usize {
        match self {
            Self::Explicit(a) => a.max_steps,
            Self::Gbs(g) => g.max_steps,
            Self::Radau5(r) => r.max_steps,
            Self::Bdf(b) => b.max_steps,
        }
    }
    /// The same method with another step bound.
    pub fn with_max_steps(self, n: usize) -> Self {
        match self {
            Self::Explicit(a) => Self::Explicit(a.max_steps(n)),
            Self::Gbs(g) => Self::Gbs(g.max_steps(n)),
            Self::Radau5(r) => Self::Radau5(r.max_steps(n)),
            Self::Bdf(b) => Self::Bdf(b.max_steps(n)),
        }
    }
    /// Its name as in scene files: `dopri5`, `dop853`, `vern9`, `gbs`, `radau5`, `bdf`.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Explicit(a) => match a.method {
                crate::Pair::Dopri5 => "dopri5",
                crate::Pair::Dop853 => "dop853",
                crate::Pair::Vern9 => "vern9",
            },
            Self::Gbs(_) => "gbs",
            Self::Radau5(_) => "radau5",
            Self::Bdf(_) => "bdf",
        }
    }
    /// (rtol, atol).
    pub fn tolerances(&self) -> (f64, f64) {
        match self {
            Self::Explicit(a) => (a.rtol, a.atol),
            Self::Gbs(g) => (g.rtol, g.atol),
            Self::Radau5(r) => (r.rtol, r.atol),
            Self::Bdf(b) => (b.rtol, b.atol),
        }
    }
    /// `true` for the stiff (implicit) methods, which use a Jacobian.
    pub fn is_implicit(&self) -> bool {
        !matches!(self, Self::Explicit(_) | Self::Gbs(_))
    }
    /// `true` for the methods with an interpolant between steps (all but `gbs` and `vern9`):
    /// dense output and located events need one.
    pub fn has_interpolant(&self) -> bool {
        !matches!(self, Self::Gbs(_) | Self::Explicit(crate::Adaptive { method: crate::Pair::Vern9, .. }))
    }
}

/// A run of any kind in progress, with the interface of [`Stepper`] ([`Progress`] by `Deref`
/// for t, y, the end, the work and `set_end`): `J` writes ∂f/∂y
/// row-major for RADAU5 and BDF (finite differences when `None`; ignored by the explicit pairs).
///
/// Book: §4.11.
// one stepper per run, moved never: boxing either variant would only add an indirection
#[allow(clippy::large_enum_variant)]
pub enum AnyStepper<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> {
    /// An explicit pair.
    Explicit(Stepper<S, F>),
    /// Extrapolation.
    Gbs(GbsStepper<S, F>),
    /// RADAU5.
    Radau5(RadauStepper<S, F, J>),
    /// BDF.
    Bdf(BdfStepper<S, F, J>),
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::fmt::Debug for AnyStepper<S, F, J> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Explicit(s) => s.fmt(f),
            Self::Gbs(s) => s.fmt(f),
            Self::Radau5(s) => s.fmt(f),
            Self::Bdf(s) => s.fmt(f),
        }
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::ops::Deref for AnyStepper<S, F, J> {
    type Target = Progress<S>;
    fn deref(&self) -> &Progress<S> {
        match self {
            Self::Explicit(s) => s,
            Self::Gbs(s) => s,
            Self::Radau5(s) => s,
            Self::Bdf(s) => s,
        }
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> core::ops::DerefMut for AnyStepper<S, F, J> {
    fn deref_mut(&mut self) -> &mut Progress<S> {
        match self {
            Self::Explicit(s) => s,
            Self::Gbs(s) => s,
            Self::Radau5(s) => s,
            Self::Bdf(s) => s,
        }
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> Steps<S> for AnyStepper<S, F, J> {
    fn step(&mut self) -> Result<(), OdeError> {
        AnyStepper::step(self)
    }
    fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        AnyStepper::dense(self)
    }
}

impl<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S, &mut [f64])> AnyStepper<S, F, J> {
    /// Starts a run of `method` (see [`Stepper::new`], [`RadauStepper::new`], [`BdfStepper::new`]).
    ///
    /// # Errors
    /// As those constructors.
    pub fn new(method: &Method, f: F, jac: Option<J>, t0: f64, y0: S, t_end: f64) -> Result<Self, OdeError> {
        Self::with_rhs(method, f, jac, t0, y0, t_end)
    }
}

impl<S: State, G: FnMut(f64, &S, &mut S), J: FnMut(f64, &S, &mut [f64])> AnyStepper<S, InPlace<G>, J> {
    /// [`AnyStepper::new`] with f written in place, `g(t, y, out)` ([`InPlace`]): the same steps
    /// and bits.
    ///
    /// # Errors
    /// As [`AnyStepper::new`].
    pub fn new_in_place(
        method: &Method,
        g: G,
        jac: Option<J>,
        t0: f64,
        y0: S,
        t_end: f64,
    ) -> Result<Self, OdeError> {
        Self::with_rhs(method, InPlace(g), jac, t0, y0, t_end)
    }
}

impl<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])> AnyStepper<S, F, J> {
    /// [`AnyStepper::new`] for any [`Rhs`]: a type of the caller's, e.g. one that evaluates two
    /// states at once for extrapolation ([`Rhs::pairs`]). The same steps and bits as `new`
    /// with the same f.
    ///
    /// # Errors
    /// As [`AnyStepper::new`].
    pub fn with_rhs(
        method: &Method,
        f: F,
        jac: Option<J>,
        t0: f64,
        y0: S,
        t_end: f64,
    ) -> Result<Self, OdeError> {
        Ok(match method {
            Method::Explicit(a) => Self::Explicit(Stepper::start(a, f, t0, y0, t_end)?),
            Method::Gbs(g) => Self::Gbs(GbsStepper::start(g, f, t0, y0, t_end)?),
            Method::Radau5(r) => Self::Radau5(RadauStepper::start(r, f, jac, t0, y0, t_end)?),
            Method::Bdf(b) => Self::Bdf(BdfStepper::start(b, f, jac, t0, y0, t_end)?),
        })
    }

    /// One accepted step.
    ///
    /// # Errors
    /// As [`Stepper::step`] and [`RadauStepper::step`].
    pub fn step(&mut self) -> Result<(), OdeError> {
        match self {
            Self::Explicit(s) => s.step(),
            Self::Gbs(s) => s.step(),
            Self::Radau5(s) => s.step(),
            Self::Bdf(s) => s.step(),
        }
    }
    /// The interpolant of the last accepted step.
    ///
    /// # Errors
    /// As [`Stepper::dense`] and [`RadauStepper::dense`].
    pub fn dense(&mut self) -> Result<&DenseStep<S>, OdeError> {
        match self {
            Self::Explicit(s) => s.dense(),
            Self::Gbs(s) => s.dense(),
            Self::Radau5(s) => s.dense(),
            Self::Bdf(s) => s.dense(),
        }
    }
    /// Continues from (t, y) after a jump.
    ///
    /// # Errors
    /// As [`Stepper::restart`].
    pub fn restart(&mut self, t: f64, y: S) -> Result<(), OdeError> {
        match self {
            Self::Explicit(s) => s.restart(t, y),
            Self::Gbs(s) => s.restart(t, y),
            Self::Radau5(s) => s.restart(t, y),
            Self::Bdf(s) => s.restart(t, y),
        }
    }
}
