//! Running methods over tolerances or step counts and recording (error, time, work).

use nalgebra::SVector;
use vectrix_frames::Frame;

use super::problems::{Reference, Separable};
use super::rigid::RigidBody;
use crate::explicit::{Adaptive, Pair, Tableau, integrate_fixed};
use crate::{GaussLegendre, LieMethod, OdeError, Work, integrate_lie, stormer_verlet};

/// A method as the harness runs it.
///
/// Book: §4.11.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// Fixed-step explicit Runge–Kutta.
    Fixed(Tableau),
    /// Adaptive embedded pair, swept over rtol = atol.
    Adaptive(Pair),
    /// Gauss–Legendre, fixed step, finite-difference Jacobian.
    Gauss(GaussLegendre),
    /// Störmer–Verlet (separable problems only).
    Verlet,
    /// Lie-group method (the rigid body on Rotor × ℝ³ only).
    Lie(LieMethod),
}

impl Method {
    /// Name for tables and legends.
    pub fn name(&self) -> &'static str {
        match self {
            Method::Fixed(t) => t.name,
            Method::Adaptive(Pair::Dopri5) => "DP5",
            Method::Adaptive(Pair::Dop853) => "DOP853",
            Method::Adaptive(Pair::Vern9) => "Vern9",
            Method::Gauss(g) => g.name(),
            Method::Verlet => "Verlet",
            Method::Lie(m) => m.name(),
        }
    }
    /// Classical order.
    pub fn order(&self) -> u32 {
        match self {
            Method::Fixed(t) => t.order,
            Method::Adaptive(Pair::Dopri5) => 5,
            Method::Adaptive(Pair::Dop853) => 8,
            Method::Adaptive(Pair::Vern9) => 9,
            Method::Gauss(g) => g.order(),
            Method::Verlet => 2,
            Method::Lie(m) => m.order(),
        }
    }
}

/// One point of a work–precision diagram.
///
/// Book: §4.11; HNW §II.10.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// Problem name.
    pub problem: String,
    /// Method name.
    pub method: &'static str,
    /// rtol (= atol) for adaptive methods, number of steps for fixed-step ones.
    pub param: f64,
    /// Max-norm error at the end time (∞ if the run failed or blew up).
    pub error: f64,
    /// Wall time of one run in seconds (best of repeats).
    pub seconds: f64,
    /// Work counters of the run.
    pub work: Work,
    /// Drifts off the group, of T and of |H| (rigid body only).
    pub drift: Option<[f64; 3]>,
}

/// How far the sweeps go.
///
/// Book: §4.11.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Budget {
    /// A few points per line (tests).
    Quick,
    /// The full diagrams (`vectrix accuracy`).
    Full,
}

/// Runs `run` once, then repeats it while the total stays under 20 ms (at most 20 times),
/// keeping the fastest wall time: short runs are otherwise dominated by timer noise.
fn best_of<T>(mut run: impl FnMut() -> Result<(T, Work), OdeError>) -> Result<(T, Work), OdeError> {
    let (y, mut work) = run()?;
    let mut total = work.wall;
    for _ in 0..19 {
        if total.as_secs_f64() > 0.02 {
            break;
        }
        let (_, w) = run()?;
        total += w.wall;
        work.wall = work.wall.min(w.wall);
    }
    Ok((y, work))
}

/// Step counts n = ⌈t_end·2ᵏ⌉ reaching from coarse to the round-off floor for order p.
fn step_counts(t_end: f64, order: u32, budget: Budget) -> Vec<usize> {
    let kmax = match order {
        1 => 14,
        2 => 12,
        3 => 11,
        4 => 10,
        5 | 6 => 8,
        _ => 7,
    };
    let (k0, kmax) = if budget == Budget::Quick { (2, kmax - 4) } else { (0, kmax) };
    (k0..=kmax).map(|k| (t_end * f64::from(1u32 << k)).ceil() as usize).collect()
}

/// Tolerances 10⁻³ … 10⁻¹³ (quick: 10⁻³ … 10⁻⁹ every second decade).
fn tolerances(budget: Budget) -> Vec<f64> {
    match budget {
        Budget::Quick => vec![1e-3, 1e-5, 1e-7, 1e-9],
        Budget::Full => (3..=13).map(|k| 10f64.powi(-k)).collect(),
    }
}

/// Sweeps a vector-space `method` (fixed, adaptive or Gauss) over its parameter on problem
/// `p`. Stops a line once the error reaches 10⁻¹³ (round-off floor) or a run takes 0.5 s.
///
/// Book: §4.11; HNW §II.10.
pub fn sweep<const N: usize, R: Reference<N>>(p: &R, method: Method, budget: Budget) -> Vec<Point> {
    let (t_end, y0) = (p.t_end(), p.y0());
    let f = |t: f64, y: &SVector<f64, N>| p.rhs(t, y);
    let params: Vec<f64> = match method {
        Method::Adaptive(_) => tolerances(budget),
        _ => step_counts(t_end, method.order(), budget).into_iter().map(|n| n as f64).collect(),
    };
    let mut out = Vec::new();
    for param in params {
        let n = param as usize;
        let result = best_of(|| match method {
            Method::Fixed(tab) => integrate_fixed(&tab, f, 0.0, &y0, t_end, n, |_, _| {}),
            Method::Adaptive(pair) => {
                let a = match pair {
                    Pair::Dopri5 => Adaptive::dopri5(),
                    Pair::Dop853 => Adaptive::dop853(),
                    Pair::Vern9 => Adaptive::vern9(),
                };
                a.rtol(param).atol(param).solve(f, 0.0, &y0, t_end).map(|s| (*s.last(), s.work))
            }
            Method::Gauss(g) => g.integrate(f, 0.0, &y0, t_end, n, |_, _| {}),
            Method::Verlet | Method::Lie(_) => Err(OdeError::NoDenseOutput),
        });
        let point = match result {
            Ok((y, work)) => Point {
                problem: p.name(),
                method: method.name(),
                param,
                error: p.error(&y),
                seconds: work.wall.as_secs_f64(),
                work,
                drift: p.drift(&y),
            },
            Err(_) => continue, // blew up (e.g. explicit method on the stiff chain): no point
        };
        let done = point.error < 1e-13 || point.seconds > 0.5;
        out.push(point);
        if done {
            break;
        }
    }
    out
}

/// Sweeps Störmer–Verlet over step counts on a separable problem with y = (q, v).
///
/// Book: §4.11; HLW §I.1.4.
pub fn sweep_verlet<const N: usize, const M: usize, R: Reference<N> + Separable<M>>(
    p: &R,
    budget: Budget,
) -> Vec<Point> {
    let (t_end, y0) = (p.t_end(), p.y0());
    let q0 = SVector::<f64, M>::from_fn(|i, _| y0[i]);
    let v0 = SVector::<f64, M>::from_fn(|i, _| y0[M + i]);
    let mut out = Vec::new();
    for n in step_counts(t_end, 2, budget) {
        let Ok(((q, v), work)) =
            best_of(|| stormer_verlet(|_, q| p.accel(q), 0.0, &q0, &v0, t_end, n, |_, _, _| {}))
        else {
            continue;
        };
        let y = SVector::<f64, N>::from_fn(|i, _| if i < M { q[i] } else { v[i - M] });
        let error = p.error(&y);
        out.push(Point {
            problem: p.name(),
            method: "Verlet",
            param: n as f64,
            error,
            seconds: work.wall.as_secs_f64(),
            work,
            drift: None,
        });
        if error < 1e-13 {
            break;
        }
    }
    out
}

/// Sweeps a Lie-group method on the rigid body (Rotor × ℝ³).
///
/// Book: §4.11; HLW §IV.8.
pub fn sweep_lie(rb: &RigidBody, method: LieMethod, budget: Budget) -> Vec<Point> {
    let a = Frame::new();
    let f = rb.lie_rhs(&a);
    let y0 = rb.lie_y0(&a);
    let mut out = Vec::new();
    for n in step_counts(rb.t_end, method.order(), budget) {
        let Ok((y, work)) = best_of(|| integrate_lie(method, &f, 0.0, &y0, rb.t_end, n, |_, _| {})) else {
            continue;
        };
        let (error, drift) = rb.lie_error(&a, &y);
        out.push(Point {
            problem: "rigid body".into(),
            method: method.name(),
            param: n as f64,
            error,
            seconds: work.wall.as_secs_f64(),
            work,
            drift: Some(drift),
        });
        if error < 1e-13 || work.wall.as_secs_f64() > 0.5 {
            break;
        }
    }
    out
}
