//! Responses to sampled inputs (Matlab `lsim`): the samples held (zero- or first-order) and
//! delayed, generated exactly step by step by the augmented state (x, v, v̇).
//!
//! Book: (15.8.3)–(15.8.4); 15.20.30, 15.20.39–45.

use super::{
    Generator, Readout, TimeResponse, check_grid, check_size, check_x0_len, finite_response, matvec,
};
use crate::error::LtiError;
use crate::ss::StateSpace;
use nalgebra::DMatrix;

/// How samples of an arbitrary input are held between grid points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hold {
    /// Zero-order hold: u constant over each step.
    Zoh,
    /// First-order hold: u linear between samples (exact for ramps and piecewise-linear u).
    Foh,
}

/// Response to sampled inputs `u[k]` (one value per time, single input channel `input`)
/// held by `hold`, delayed by `delay`, from initial state `x0` (Matlab `lsim`).
///
/// Over each step the held input is a line v(τ) = v₀ + v̇τ, generated exactly by the augmented
/// state (x, v, v̇) with the balanced generator of [`response`](super::response). A delay that is not a multiple
/// of h splits every step at the same fraction, so the result stays exact for the held input.
///
/// Book: (15.8.3)–(15.8.4); 15.20.30, 15.20.39–45.
///
/// # Errors
/// Grid, index, dimension, size and overflow errors as [`response`](super::response) and [`initial`](super::initial); u must
/// have one sample per time.
pub fn lsim(
    sys: &StateSpace,
    input: usize,
    u: &[f64],
    t: &[f64],
    x0: &[f64],
    hold: Hold,
    delay: f64,
) -> Result<TimeResponse, LtiError> {
    check_arguments(sys, input, u, t, x0, delay)?;
    let h = check_grid(t)?;
    let n = sys.n_states();
    let (p, nt) = (sys.n_outputs(), t.len());
    check_size("time response", n + p, nt)?;
    let v = HeldInput { u, t0: t[0], h, delay, hold };
    let generator = Generator::new(&augmented_generator(sys, input));
    let readout = Readout::new(sys, input, &generator.d);
    let StepPieces { whole, shift, list: pieces } = step_pieces(&generator, h, delay, nt)?;
    let mut y = vec![vec![0.0; nt]; p];
    let mut x = vec![vec![0.0; nt]; n];
    let mut w = generator.balanced(&[x0, &[0.0, 0.0]].concat());
    let mut wn = vec![0.0; n + 2];
    for k in 0..nt {
        let vk = if whole { v.line(k, shift).0 } else { v.at(t[k]) };
        for i in 0..n {
            x[i][k] = w[i] * generator.d[i];
        }
        readout.write(&w, vk, k, &mut y);
        if k + 1 == nt {
            break;
        }
        let mut tau = t[k];
        for (len, phi) in &pieces {
            // on [τ, τ + len): v linear from v(τ⁺) with slope v̇
            let (v0, slope) = if whole { v.line(k, shift) } else { v.piece(tau, *len) };
            w[n] = v0 / generator.d[n];
            w[n + 1] = slope / generator.d[n + 1];
            matvec(phi, &w, &mut wn);
            std::mem::swap(&mut w, &mut wn);
            tau += len;
        }
    }
    finite_response(TimeResponse { t: t.to_vec(), y, x, impulse_weight: vec![0.0; p] })
}

/// The arguments of [`lsim`] that [`check_grid`] and [`check_size`] do not check.
fn check_arguments(
    sys: &StateSpace,
    input: usize,
    u: &[f64],
    t: &[f64],
    x0: &[f64],
    delay: f64,
) -> Result<(), LtiError> {
    if input >= sys.n_inputs() {
        return Err(LtiError::IndexOutOfRange { what: "input", index: input, len: sys.n_inputs() });
    }
    if u.len() != t.len() {
        return Err(LtiError::DimensionMismatch {
            what: "u",
            expected: format!("{} samples (one per time)", t.len()),
            found: format!("{}", u.len()),
        });
    }
    check_x0_len(sys, x0)?;
    crate::error::check_finite("u", u)?;
    crate::error::check_finite("x0", x0)?;
    if !(delay.is_finite() && delay >= 0.0) {
        return Err(LtiError::InvalidArgument { what: "delay", reason: format!("{delay}; need ≥ 0") });
    }
    Ok(())
}

/// The augmented generator of z = (x, v, v̇) over a piece on which v is linear:
/// M = [[A, b, 0], [0, 0, 1], [0, 0, 0]] with b the input's column of B.
fn augmented_generator(sys: &StateSpace, input: usize) -> DMatrix<f64> {
    let n = sys.n_states();
    let mut m = DMatrix::<f64>::zeros(n + 2, n + 2);
    m.view_mut((0, 0), (n, n)).copy_from(sys.a());
    for i in 0..n {
        m[(i, n)] = sys.b()[(i, input)];
    }
    m[(n, n + 1)] = 1.0;
    m
}

/// How each step is integrated.
struct StepPieces {
    /// The delay is a whole number of steps (the common case, exact sample values).
    whole: bool,
    /// The delay in whole steps.
    shift: usize,
    /// The pieces of a step with their transitions e^{M_b·len}: one of length h for a whole
    /// delay, else two split at the delay's fraction of a step (none for fewer than two samples).
    list: Vec<(f64, Vec<f64>)>,
}

/// The [`StepPieces`] of a grid of `nt` samples spaced h with an input delay.
fn step_pieces(generator: &Generator, h: f64, delay: f64, nt: usize) -> Result<StepPieces, LtiError> {
    let steps = if h > 0.0 { delay / h } else { 0.0 };
    let shift = steps.round();
    let whole = h == 0.0 || (steps - shift).abs() <= 1e-12 * steps.max(1.0);
    let pieces: Vec<(f64, Vec<f64>)> = if h == 0.0 || nt < 2 {
        Vec::new()
    } else if whole {
        vec![(h, generator.transition(h)?)]
    } else {
        let f = steps - steps.floor();
        vec![(f * h, generator.transition(f * h)?), ((1.0 - f) * h, generator.transition((1.0 - f) * h)?)]
    };
    Ok(StepPieces { whole, shift: shift as usize, list: pieces })
}

/// The sampled input u held by `hold` on the grid t₀ + kh and delayed by `delay`.
struct HeldInput<'a> {
    u: &'a [f64],
    t0: f64,
    h: f64,
    delay: f64,
    hold: Hold,
}

impl HeldInput<'_> {
    /// v(τ) = u_held(τ − delay), zero before t₀.
    fn at(&self, tau: f64) -> f64 {
        let (u, h) = (self.u, self.h);
        let s = tau - self.delay - self.t0;
        if s < 0.0 || h == 0.0 {
            return if s >= 0.0 { u[0] } else { 0.0 };
        }
        let k = ((s / h) + 1e-12).floor() as usize;
        if k + 1 >= u.len() {
            return u[u.len() - 1];
        }
        match self.hold {
            Hold::Zoh => u[k],
            Hold::Foh => {
                let f = (s - k as f64 * h) / h;
                u[k] + f * (u[k + 1] - u[k])
            }
        }
    }

    /// v(t_k⁺) and v̇ on [t_k, t_{k+1}) for a delay of `shift` whole steps.
    fn line(&self, k: usize, shift: usize) -> (f64, f64) {
        if k < shift {
            return (0.0, 0.0);
        }
        let (u, i) = (self.u, k - shift);
        let slope = match self.hold {
            Hold::Foh if i + 1 < u.len() => (u[i + 1] - u[i]) / self.h,
            _ => 0.0,
        };
        (u[i], slope)
    }

    /// v(τ⁺) and v̇ on a piece [τ, τ + len) on which v is linear, from the held input just
    /// inside both ends (a delay that splits every step).
    fn piece(&self, tau: f64, len: f64) -> (f64, f64) {
        let eps = 1e-9 * len;
        let (a, b) = (self.at(tau + eps), self.at(tau + len - eps));
        let slope = if self.hold == Hold::Foh { (b - a) / (len - 2.0 * eps) } else { 0.0 };
        (a - slope * eps, slope)
    }
}
