//! Which integrator a scene runs, and why: a named `method`, or the declared `accuracy` with a
//! stiffness test on the Jacobian at t = 0 that switches to RADAU5 when an explicit method
//! would be held to tiny steps by stability rather than accuracy (as LSODA switches, but
//! decided once, from the spectrum). Implicit steps take ∂f/∂y from dual numbers
//! ([`Scene::jacobian`]) where the scene is a tree, else by finite differences, and the choice
//! says which.
//!
//! Book: §4.11; HW = Hairer & Wanner, *Solving ODEs II*, §IV.1 (stiffness: eigenvalues of the
//! Jacobian far left of the slow ones), §IV.8 (RADAU5); Petzold 1983 (LSODA's switch).

use nalgebra::DMatrix;
use serde::Serialize;
use vectrix_ode::{Accuracy, Bdf, Method, Radau5};

use super::parts::Src;
use super::spec::SceneSpec;
use super::{Scene, SceneError};

/// Stiff when the fastest eigenvalue of ∂f/∂y is at least this multiple of the slowest
/// nonzero one (HW §IV.1's "stiffness ratio")…
pub const STIFF_RATIO: f64 = 100.0;
/// …and the fastest one, times the duration, at least this (an explicit method would need
/// ≳ ρ·duration/6 steps for stability alone, DOP853's stability interval being ≈ 6).
pub const STIFF_RHO_DURATION: f64 = 1000.0;

/// The integrator a run uses and why, shown in the run's summary.
///
/// Book: §4.11.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MethodChoice {
    /// `dopri5`, `dop853`, `gbs`, `radau5` or `bdf`.
    pub name: &'static str,
    /// Its relative (= absolute) local tolerance.
    pub rtol: f64,
    /// `exact (dual numbers)`, `finite differences` or `none` (explicit methods).
    pub jacobian: &'static str,
    /// Why this method: named in the scene, or the stiffness test's numbers.
    pub reason: String,
}

impl core::fmt::Display for MethodChoice {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{} at rtol = atol = {:e}", self.name, self.rtol)?;
        if self.name == "radau5" || self.name == "bdf" {
            write!(f, ", Jacobian {}", self.jacobian)?;
        }
        write!(f, " ({})", self.reason)
    }
}

/// The method a scene names, if it names one (`dopri5`, `dop853`, `vern9`, `gbs`, `radau5`, `bdf`).
pub(crate) fn named(spec: &SceneSpec, src: &Src) -> Result<Option<(Method, String)>, SceneError> {
    let Some(m) = &spec.method else { return Ok(None) };
    if !(m.rtol > 0.0 && m.rtol < 1.0) {
        return Err(src.invalid("method.rtol", format!("rtol = {}; valid: 0 < rtol < 1", m.rtol)));
    }
    let method = match m.name.as_str() {
        "dopri5" => Method::Explicit(vectrix_ode::Adaptive::dopri5().rtol(m.rtol).atol(m.rtol)),
        "dop853" => Method::Explicit(vectrix_ode::Adaptive::dop853().rtol(m.rtol).atol(m.rtol)),
        "vern9" => Method::Explicit(vectrix_ode::Adaptive::vern9().rtol(m.rtol).atol(m.rtol)),
        "gbs" => Method::Gbs(vectrix_ode::Extrapolation::gbs().rtol(m.rtol).atol(m.rtol)),
        "radau5" => Method::Radau5(Radau5::new().rtol(m.rtol).atol(m.rtol)),
        "bdf" => Method::Bdf(Bdf::new().rtol(m.rtol).atol(m.rtol)),
        n => {
            return Err(src.invalid(
                "method.name",
                format!("unknown method `{n}`; valid: dopri5, dop853, vern9, gbs, radau5, bdf"),
            ));
        }
    };
    Ok(Some((method, "named in the scene's `method`".to_string())))
}

/// The explicit method the accuracy table picks for `accuracy` (default 1e-6).
pub(crate) fn from_accuracy(spec: &SceneSpec, src: &Src) -> Result<Method, SceneError> {
    let tol = spec.accuracy.unwrap_or(1e-6);
    if !(tol > 0.0 && tol < 1.0) {
        return Err(src.invalid("accuracy", format!("accuracy = {tol}; valid: 0 < accuracy < 1")));
    }
    Ok(Method::Explicit(Accuracy::RelTol(tol).solver().map_err(|e| src.invalid("accuracy", e.to_string()))?))
}

/// RADAU5's tolerance for a requested global accuracy: rtol = atol = accuracy/10, the setting
/// whose end error stayed below the accuracy on the stiff harness problems (the damped chain,
/// the stiff spring pendulum, Robertson, Van der Pol μ = 1000; docs/accuracy.md).
pub const RADAU5_TOL_FACTOR: f64 = 0.1;

impl Scene {
    /// ∂f/∂y at (t, y): exact from dual numbers for a tree, else forward differences of
    /// [`Scene::derivative`] (step √ε·max(1, |yⱼ|)). The flag says which.
    pub(crate) fn jacobian_any(&self, t: f64, y: &[f64]) -> Result<(DMatrix<f64>, bool), SceneError> {
        if self.tree_only() {
            return Ok((self.jacobian(t, y)?.0, true));
        }
        let n = y.len();
        let f0 = self.derivative(t, y)?;
        let mut j = DMatrix::zeros(n, n);
        let mut yj = y.to_vec();
        for c in 0..n {
            let d = f64::EPSILON.sqrt() * y[c].abs().max(1.0);
            yj[c] = y[c] + d;
            let fc = self.derivative(t, &yj)?;
            yj[c] = y[c];
            for r in 0..n {
                j[(r, c)] = (fc[r] - f0[r]) / d;
            }
        }
        Ok((j, false))
    }

    /// The stiffness test at t = 0 for a scene run under `accuracy`: switches `solver` to
    /// RADAU5 when the eigenvalues of ∂f/∂y span a ratio ≥ [`STIFF_RATIO`] and the fastest,
    /// times the duration, is ≥ [`STIFF_RHO_DURATION`]; records the choice and why.
    pub(crate) fn choose_method(&mut self) {
        let tol = self.spec().accuracy.unwrap_or(1e-6);
        let explicit = self.solver;
        let (name, rtol) = (explicit.name(), explicit.tolerances().0);
        let keep = |reason: String| MethodChoice { name, rtol, jacobian: "none", reason };
        let y0 = self.initial_state();
        let (j, exact) = match self.jacobian_any(0.0, &y0) {
            Ok(j) => j,
            Err(e) => {
                self.choice =
                    keep(format!("accuracy table; no stiffness test: the Jacobian at t = 0 failed: {e}"));
                return;
            }
        };
        let Some((fast, slow)) = spectrum(&j) else {
            self.choice = keep("accuracy table; not stiff: ∂f/∂y at t = 0 has no nonzero eigenvalue".into());
            return;
        };
        let duration = self.spec().duration;
        let ratio = fast / slow;
        if ratio >= STIFF_RATIO && fast * duration >= STIFF_RHO_DURATION {
            let r = Radau5::new().rtol(tol * RADAU5_TOL_FACTOR).atol(tol * RADAU5_TOL_FACTOR);
            self.solver = Method::Radau5(r.max_steps(explicit.max_steps()));
            self.choice = MethodChoice {
                name: "radau5",
                rtol: r.rtol,
                jacobian: if exact { "exact (dual numbers)" } else { "finite differences" },
                reason: format!(
                    "stiff: the eigenvalues of ∂f/∂y at t = 0 span |λ| = {slow:.3e} … {fast:.3e} /s (ratio {ratio:.1e} \
                     ≥ {STIFF_RATIO}), and |λ|max × duration = {:.1e} ≥ {STIFF_RHO_DURATION}: an explicit method \
                     would need ≳ {:.1e} steps for stability alone",
                    fast * duration,
                    fast * duration / 6.0
                ),
            };
        } else {
            self.choice = keep(format!(
                "accuracy table; not stiff: the eigenvalues of ∂f/∂y at t = 0 span |λ| = {slow:.3e} … {fast:.3e} /s \
                 (ratio {ratio:.1e}, stiff from {STIFF_RATIO}), |λ|max × duration = {:.1e} (stiff from \
                 {STIFF_RHO_DURATION})",
                fast * duration
            ));
        }
    }
}

/// (largest |λ|, smallest nonzero |λ|) of a square matrix, "nonzero" meaning above 1e-9 of the
/// largest; `None` when every eigenvalue is zero or the decomposition does not give finite
/// values.
fn spectrum(j: &DMatrix<f64>) -> Option<(f64, f64)> {
    if j.nrows() == 0 || j.nrows() != j.ncols() {
        return None; // nothing moves (every joint a weld)
    }
    let ev = j.clone().complex_eigenvalues();
    let mags: Vec<f64> = ev.iter().map(|z| z.norm()).collect();
    if mags.iter().any(|m| !m.is_finite()) {
        return None;
    }
    let fast = mags.iter().copied().fold(0.0, f64::max);
    if fast <= 0.0 {
        return None;
    }
    let slow = mags.iter().copied().filter(|m| *m > 1e-9 * fast).fold(f64::INFINITY, f64::min);
    Some((fast, slow))
}
