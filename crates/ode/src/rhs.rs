//! The right-hand side f(t, y) of y′ = f(t, y) as the adaptive steppers call it: a closure that
//! returns a new state (`FnMut(f64, &S) -> S`, what every solver takes), or one that writes into
//! a state it is given ([`InPlace`]), which spares a heap state (`Vec<f64>`, `DVector<f64>`) one
//! allocation per evaluation.
//!
//! Book: §4.11 (the state equations integrated); HNW §II.1.

use crate::state::State;

/// A right-hand side f(t, y). Implemented for every closure `FnMut(f64, &S) -> S` and for
/// [`InPlace`]; the steppers are generic over it, their constructors take either form
/// (`Stepper::new` / `Stepper::new_in_place`, and likewise for [`crate::AnyStepper`],
/// [`crate::RadauStepper`], [`crate::BdfStepper`]).
///
/// Book: §4.11.
pub trait Rhs<S: State> {
    /// `true` when f writes into a state it is given ([`InPlace`]): the explicit pairs then keep
    /// one state per stage from step to step; `false` (a closure returning its result) keeps the
    /// stages as locals, which a small fixed-size state holds in registers. Decided when the
    /// stepper is compiled; either way the same bits.
    const IN_PLACE: bool;
    /// f(t, y) as a new state.
    fn call(&mut self, t: f64, y: &S) -> S;
    /// out ← f(t, y); `out` is a state of y's dimension holding a previous stage (overwritten).
    fn call_into(&mut self, t: f64, y: &S, out: &mut S);
    /// Whether [`Rhs::call_pair_into`] evaluates two states for less than two calls (default
    /// `false`). Gragg–Bulirsch–Stoer extrapolation ([`crate::Extrapolation`]) then builds two
    /// rows of its table side by side, which costs a few evaluations it may not use; its steps
    /// and bits are the same either way.
    fn pairs(&self) -> bool {
        false
    }
    /// f at two states at once: `a.2` ← f(`a.0`, `a.1`) and `b.2` ← f(`b.0`, `b.1`), each the
    /// same bits as [`Rhs::call_into`]. Default: two calls. A right-hand side whose evaluation
    /// is a chain of dependent operations (ABA on a chain: `Model::aba_pair_unchecked` in
    /// vectrix-dynamics) overrides it to run both in the same instructions, two lanes each.
    #[inline(always)]
    fn call_pair_into(&mut self, a: (f64, &S, &mut S), b: (f64, &S, &mut S)) {
        self.call_into(a.0, a.1, a.2);
        self.call_into(b.0, b.1, b.2);
    }
}

impl<S: State, F: FnMut(f64, &S) -> S> Rhs<S> for F {
    const IN_PLACE: bool = false;
    #[inline(always)]
    fn call(&mut self, t: f64, y: &S) -> S {
        self(t, y)
    }
    #[inline(always)]
    fn call_into(&mut self, t: f64, y: &S, out: &mut S) {
        *out = self(t, y);
    }
}

/// A right-hand side that writes f(t, y) into the state it is given: `g(t, y, out)` with `out`
/// of y's dimension (its entries are a previous stage's: write every one). The explicit pairs
/// keep one state per stage and reuse them step after step, so a heap state costs no allocation
/// per evaluation; RADAU5 and BDF take it too, at the cost of a returning closure (one state per
/// evaluation). The results are the same bits as the returning form of the same f.
///
/// ```
/// use vectrix_ode::explicit::{Adaptive, Stepper};
/// // ẍ = −x, y = (x, ẋ) in a Vec, f written in place
/// let f = |_t: f64, y: &Vec<f64>, out: &mut Vec<f64>| {
///     out[0] = y[1];
///     out[1] = -y[0];
/// };
/// let mut st = Stepper::new_in_place(&Adaptive::dopri5().rtol(1e-10).atol(1e-12), f, 0.0, vec![1.0, 0.0], 1.0)?;
/// while !st.done() {
///     st.step()?;
/// }
/// assert!((st.y()[0] - 1f64.cos()).abs() < 1e-9);
/// # Ok::<(), vectrix_ode::OdeError>(())
/// ```
///
/// Book: §4.11.
#[derive(Debug, Clone, Copy)]
pub struct InPlace<G>(pub G);

impl<S: State, G: FnMut(f64, &S, &mut S)> Rhs<S> for InPlace<G> {
    const IN_PLACE: bool = true;
    #[inline(always)]
    fn call(&mut self, t: f64, y: &S) -> S {
        let mut out = y.clone();
        (self.0)(t, y, &mut out);
        out
    }
    #[inline(always)]
    fn call_into(&mut self, t: f64, y: &S, out: &mut S) {
        (self.0)(t, y, out);
    }
}
