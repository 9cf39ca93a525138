//! Impacts during integration: event detection through `vectrix-ode` and protection against
//! Zeno bouncing (book §7.13; notes ch6-8 §3 "Collisions").
//!
//! A contact with restitution e < 1 bounces infinitely often in finite time (Zeno): the
//! intervals between impacts shrink geometrically by e. The guard stops the run at a
//! declared threshold and reports it, so that the caller can switch to resting contact.

use vectrix_ode::{Adaptive, Direction, Event, State};

use crate::DynamicsError;

/// When to declare Zeno bouncing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZenoGuard {
    /// An impact closer than this to the previous one is Zeno.
    pub min_interval: f64,
    /// At most this many impacts.
    pub max_impacts: usize,
}

impl Default for ZenoGuard {
    fn default() -> Self {
        Self { min_interval: 1e-6, max_impacts: 10_000 }
    }
}

/// How an impact run ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ImpactEnd {
    /// The final time was reached.
    Reached,
    /// Zeno bouncing was detected at time `t` (impacts accumulating); the state is the one
    /// just after the last impact.
    Zeno {
        /// Time of the last impact.
        t: f64,
    },
}

/// A run with impacts: impact times and pre-impact states, the final time and state.
#[derive(Debug, Clone)]
pub struct ImpactRun<S> {
    /// (t, state just before the impact), in time order.
    pub impacts: Vec<(f64, S)>,
    /// Final time.
    pub t: f64,
    /// Final state.
    pub y: S,
    /// Why the run stopped.
    pub end: ImpactEnd,
}

/// Integrates y′ = f(t, y) with `solver`, locating the zeros of the gap g(t, y) (crossing
/// from positive to non-positive) as events; at each, the state is replaced by
/// `impact(t, y)` (a restitution law) and integration restarts.
///
/// Book: §7.13 (restitution), §4.11 (integration); HNW §II.6 (events).
///
/// # Errors
/// Integrator errors ([`DynamicsError::Ode`]); [`DynamicsError::NonFinite`] from the impact map.
#[allow(clippy::too_many_arguments)]
pub fn simulate_with_impacts<S: State>(
    solver: &Adaptive,
    mut f: impl FnMut(f64, &S) -> S,
    mut gap: impl FnMut(f64, &S) -> f64,
    mut impact: impl FnMut(f64, &S) -> S,
    t0: f64,
    y0: &S,
    t1: f64,
    guard: ZenoGuard,
) -> Result<ImpactRun<S>, DynamicsError> {
    let mut t = t0;
    let mut y = y0.clone();
    let mut impacts: Vec<(f64, S)> = Vec::new();
    while t < t1 {
        let mut events = [Event::new(&mut gap).direction(Direction::Falling).terminal(true)];
        let sol = solver.solve_with_events(&mut f, t, &y, t1, &mut events)?;
        if !sol.terminated {
            return Ok(ImpactRun { impacts, t: t1, y: sol.last().clone(), end: ImpactEnd::Reached });
        }
        let hit = sol.events.last().cloned().ok_or(DynamicsError::NonFinite { what: "event" })?;
        let y_after = impact(hit.t, &hit.y);
        crate::error::check_finite(y_after.as_slice(), "state after impact")?;
        let zeno = impacts.last().is_some_and(|(tp, _)| hit.t - tp < guard.min_interval)
            || impacts.len() + 1 >= guard.max_impacts;
        impacts.push((hit.t, hit.y));
        t = hit.t;
        y = y_after;
        if zeno {
            return Ok(ImpactRun { impacts, t, y, end: ImpactEnd::Zeno { t } });
        }
    }
    Ok(ImpactRun { impacts, t, y, end: ImpactEnd::Reached })
}
