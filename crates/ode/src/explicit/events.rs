//! Event location: roots of a user function g(t, y) found on the dense output.

use super::dense::DenseStep;
use crate::state::State;

/// Which sign changes of g count as an event.
///
/// Book: §4.11; HNW §II.6 (event location by dense output).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// g goes from negative to positive.
    Rising,
    /// g goes from positive to negative.
    Falling,
    /// Either way.
    Either,
}

/// The event function g(t, y).
type EventFn<'a, S> = Box<dyn FnMut(f64, &S) -> f64 + 'a>;

/// An event g(t, y) = 0 with a crossing direction and a terminal flag (stop the
/// integration at the first such event).
///
/// Book: §4.11; HNW §II.6.
pub struct Event<'a, S> {
    pub(crate) g: EventFn<'a, S>,
    pub(crate) direction: Direction,
    pub(crate) terminal: bool,
}

impl<'a, S> Event<'a, S> {
    /// An event on the zeros of `g`, counted in both directions, not terminal.
    pub fn new(g: impl FnMut(f64, &S) -> f64 + 'a) -> Self {
        Self { g: Box::new(g), direction: Direction::Either, terminal: false }
    }
    /// Counts only crossings in `direction`.
    pub fn direction(mut self, direction: Direction) -> Self {
        self.direction = direction;
        self
    }
    /// Stops the integration at the first counted crossing when `terminal`.
    pub fn terminal(mut self, terminal: bool) -> Self {
        self.terminal = terminal;
        self
    }
}

impl<S> core::fmt::Debug for Event<'_, S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Event").field("direction", &self.direction).field("terminal", &self.terminal).finish()
    }
}

/// A located event.
///
/// Book: §4.11.
#[derive(Debug, Clone, PartialEq)]
pub struct EventHit<S> {
    /// Index of the event in the list passed to the solver.
    pub index: usize,
    /// Time of the zero of g.
    pub t: f64,
    /// State there (from the dense output).
    pub y: S,
    /// `true` when g was rising.
    pub rising: bool,
}

/// Does the sign change g_a → g_b count for `dir`?
pub(crate) fn crosses(dir: Direction, ga: f64, gb: f64) -> Option<bool> {
    let rising = ga < 0.0 && gb >= 0.0;
    let falling = ga > 0.0 && gb <= 0.0;
    match dir {
        Direction::Rising if rising => Some(true),
        Direction::Falling if falling => Some(false),
        Direction::Either if rising || falling => Some(rising),
        _ => None,
    }
}

/// The zero of g on [ta, tb] (g(ta)·g(tb) ≤ 0) by the Illinois variant of regula falsi on
/// the dense output, to |Δt| ≤ 4ε·max(1, |t|).
pub(crate) fn locate<S: State>(
    g: &mut dyn FnMut(f64, &S) -> f64,
    dense: &DenseStep<S>,
    a: (f64, f64),
    b: (f64, f64),
) -> f64 {
    let (a, b) = bracket_zero(|t| g(t, &dense.eval(t)), a, b);
    let (ga, gb) = (g(a, &dense.eval(a)), g(b, &dense.eval(b)));
    if gb == 0.0 || gb.abs() <= ga.abs() { b } else { a }
}

/// Narrows a bracket [a, b] of a sign change of a scalar function g (g(a)·g(b) ≤ 0, values
/// given) to |b − a| ≤ 4ε·max(1, |a|, |b|) by the Illinois variant of regula falsi, at most
/// 200 evaluations; returns the final bracket (a, b), each end keeping the sign of g it
/// started with (so `b` is the first instant known to be past the zero).
///
/// Book: §4.11; HNW §II.6 (event location by dense output).
pub fn bracket_zero(
    mut g: impl FnMut(f64) -> f64,
    (mut a, mut ga): (f64, f64),
    (mut b, mut gb): (f64, f64),
) -> (f64, f64) {
    let tol = 4.0 * f64::EPSILON * a.abs().max(b.abs()).max(1.0);
    let b_sign = gb.signum();
    let mut side = 0i8;
    for _ in 0..200 {
        if (b - a).abs() <= tol || gb == 0.0 {
            break;
        }
        // secant point, safeguarded into (a, b)
        let mut c = (a * gb - b * ga) / (gb - ga);
        if !c.is_finite() || c <= a.min(b) || c >= a.max(b) {
            c = 0.5 * (a + b);
        }
        let gc = g(c);
        if gc == 0.0 || gc.signum() == b_sign {
            (b, gb) = (c, gc);
            if gc == 0.0 {
                break;
            }
            if side == -1 {
                ga *= 0.5; // Illinois: halve the retained end's value
            }
            side = -1;
        } else {
            (a, ga) = (c, gc);
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        }
    }
    (a, b)
}
