//! The stiff half of the [`Accuracy`](crate::Accuracy) calibration: three stiff problems with
//! independent references, RADAU5 and BDF swept over rtol = atol with finite-difference
//! Jacobians (what `Accuracy` runs: the caller's f is f64 only), and the cheapest
//! (method, rtol) for each target, cost counted in f-evaluations (deterministic, unlike wall
//! time on a shared machine; Jacobian columns included).
//!
//! Book: §4.11; HW §IV.1 (Robertson), §IV.10 and the Test Set for IVP solvers (VDPOL).

use nalgebra::{Vector2, Vector3};

use crate::{Bdf, Method, OdeError, Radau5};

/// A stiff reference problem: name, and the run of a method on it returning (error, f-evals).
pub struct StiffProblem {
    /// Its name in docs/accuracy.md.
    pub name: &'static str,
    run: fn(&Method) -> Result<(f64, usize), OdeError>,
}

impl StiffProblem {
    /// The end-time error of `method` (largest |error| of a component over max(1, |yᵢ|)) and
    /// its f-evaluations.
    ///
    /// # Errors
    /// As the method's `solve`.
    pub fn run(&self, method: &Method) -> Result<(f64, usize), OdeError> {
        (self.run)(method)
    }
}

/// End error against `want`, component by component over max(1, |wantᵢ|); NaN if any is NaN.
fn mixed_error(got: &[f64], want: &[f64]) -> f64 {
    got.iter().zip(want).fold(0.0, |m: f64, (g, w)| {
        let e = (g - w).abs() / w.abs().max(1.0);
        if e.is_nan() || m.is_nan() { f64::NAN } else { m.max(e) }
    })
}

/// Robertson's chemical kinetics (HW II (IV.1.4)): y₁′ = −0.04y₁ + 10⁴y₂y₃,
/// y₂′ = 0.04y₁ − 10⁴y₂y₃ − 3·10⁷y₂², y₃′ = 3·10⁷y₂², the standard non-mechanical stiff check.
pub fn robertson(_: f64, y: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(
        -0.04 * y[0] + 1e4 * y[1] * y[2],
        0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] * y[1],
        3e7 * y[1] * y[1],
    )
}

/// ∂f/∂y of [`robertson`], row-major.
pub fn robertson_jacobian(_: f64, y: &Vector3<f64>, j: &mut [f64]) {
    j.copy_from_slice(&[
        -0.04,
        1e4 * y[2],
        1e4 * y[1],
        0.04,
        -1e4 * y[2] - 6e7 * y[1],
        -1e4 * y[1],
        0.0,
        6e7 * y[1],
        0.0,
    ]);
}

/// Van der Pol at μ = 1000 in the Test Set's scaled form VDPOL: y₁′ = y₂,
/// y₂′ = ((1 − y₁²)y₂ − y₁)/ε with ε = 10⁻⁶ (HW II §IV.10; Mazzia & Magherini's Test Set).
pub fn vdpol(_: f64, y: &Vector2<f64>) -> Vector2<f64> {
    Vector2::new(y[1], ((1.0 - y[0] * y[0]) * y[1] - y[0]) / 1e-6)
}

/// ∂f/∂y of [`vdpol`], row-major.
pub fn vdpol_jacobian(_: f64, y: &Vector2<f64>, j: &mut [f64]) {
    j.copy_from_slice(&[0.0, 1.0, (-2.0 * y[0] * y[1] - 1.0) / 1e-6, (1.0 - y[0] * y[0]) / 1e-6]);
}

macro_rules! solve_any {
    ($m:expr, $f:expr, $y0:expr, $t1:expr) => {
        match $m {
            Method::Radau5(r) => r.solve($f, 0.0, $y0, $t1),
            Method::Bdf(b) => b.solve($f, 0.0, $y0, $t1),
            Method::Explicit(a) => a.solve($f, 0.0, $y0, $t1),
            Method::Gbs(e) => e.solve($f, 0.0, $y0, $t1),
        }
    };
}

fn linear_run(m: &Method) -> Result<(f64, usize), OdeError> {
    // y₁′ = −y₁, y₂′ = −10⁴(y₂ − y₁) − y₁ from (1, 1): y = e^{−t}(1, 1) exactly
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(-y[0], -1e4 * (y[1] - y[0]) - y[0]);
    let sol = solve_any!(m, f, &Vector2::new(1.0, 1.0), 1.0)?;
    let w = (-1f64).exp();
    Ok((mixed_error(sol.last().as_slice(), &[w, w]), sol.work.fevals))
}

fn vdpol_run(m: &Method) -> Result<(f64, usize), OdeError> {
    // VDPOL (ε = 1e-6, μ = 1000 in scaled time), y(0) = (2, 0), t = 2; the Test Set's end state
    let sol = solve_any!(m, vdpol, &Vector2::new(2.0, 0.0), 2.0)?;
    Ok((mixed_error(sol.last().as_slice(), &[1.706167732170483, -0.8928097010247975]), sol.work.fevals))
}

fn robertson_run(m: &Method) -> Result<(f64, usize), OdeError> {
    // Robertson to t = 40; reference scipy Radau at rtol = 1e-13 (tests/data/stiff_reference.json,
    // uncertainty 1.6e-11, scripts/stiff_reference.py)
    let sol = solve_any!(m, robertson, &Vector3::new(1.0, 0.0, 0.0), 40.0)?;
    let want = [0.7158270687194058, 9.185534764557781e-06, 0.28416374574583];
    Ok((mixed_error(sol.last().as_slice(), &want), sol.work.fevals))
}

/// The stiff calibration problems: a linear stiff system (eigenvalues −1, −10⁴) against its
/// closed form, Van der Pol at μ = 1000 (VDPOL) against the Test Set, Robertson to t = 40
/// against scipy Radau at rtol = 1e-13.
pub const STIFF_PROBLEMS: [StiffProblem; 3] = [
    StiffProblem { name: "linear stiff (−1, −1e4)", run: linear_run },
    StiffProblem { name: "Van der Pol μ = 1000", run: vdpol_run },
    StiffProblem { name: "Robertson t = 40", run: robertson_run },
];

/// One derived row: for a global error ≤ `target`, `method` at rtol = atol = `rtol` reached
/// it on every stiff problem at `fevals` f-evaluations in total.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffDerived {
    /// The target global error.
    pub target: f64,
    /// `radau5` or `bdf`.
    pub method: &'static str,
    /// The largest swept rtol that reached it everywhere.
    pub rtol: f64,
    /// Total f-evaluations over the problems at that rtol.
    pub fevals: usize,
}

/// For targets 10⁻³ … 10⁻¹⁰ and both stiff methods, the largest rtol = atol of the sweep
/// 10⁻² … 10⁻¹³ whose end error is ≤ target on every [`STIFF_PROBLEMS`] entry; of the two
/// methods the one with fewer f-evaluations wins (ties: RADAU5). A method that fails (a typed
/// error) at some rtol does not qualify there.
pub fn derive_stiff_accuracy() -> Vec<StiffDerived> {
    let rtols: Vec<f64> = (2..=13).map(|k| 10f64.powi(-k)).collect();
    let sweep = |mk: &dyn Fn(f64) -> Method| -> Vec<(f64, f64, usize)> {
        rtols
            .iter()
            .map(|&r| {
                let m = mk(r);
                let mut worst = 0.0f64;
                let mut cost = 0usize;
                for p in &STIFF_PROBLEMS {
                    match p.run(&m) {
                        Ok((e, n)) if e.is_finite() => {
                            worst = worst.max(e);
                            cost += n;
                        }
                        _ => worst = f64::INFINITY,
                    }
                }
                (r, worst, cost)
            })
            .collect()
    };
    let radau = sweep(&|r| Method::Radau5(Radau5::new().rtol(r).atol(r)));
    let bdf = sweep(&|r| Method::Bdf(Bdf::new().rtol(r).atol(r)));
    let pick = |s: &[(f64, f64, usize)], target: f64| s.iter().find(|(_, e, _)| *e <= target).copied();
    let mut out = Vec::new();
    for k in 3..=10 {
        let target = 10f64.powi(-k);
        let best = match (pick(&radau, target), pick(&bdf, target)) {
            (Some(a), Some(b)) if b.2 < a.2 => Some(("bdf", b)),
            (Some(a), _) => Some(("radau5", a)),
            (None, Some(b)) => Some(("bdf", b)),
            (None, None) => None,
        };
        if let Some((method, (rtol, _, fevals))) = best {
            out.push(StiffDerived { target, method, rtol, fevals });
        }
    }
    out
}
