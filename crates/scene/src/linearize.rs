//! Linearization of a scene about its initial state (§12.6, §15.7): ẋ = A x + B u,
//! y = C x + D u in the coordinates δ (displacements in the joints' tangent space, so that a
//! ball joint's quaternion contributes three angles) and v (the joint speeds), with inputs the
//! magnitudes of the declared `force` and `torque` effects and outputs the columns of the
//! declared `outputs`.
//!
//! A steady motion (`linearize = { steady = true }`) is linearized at the initial state when
//! every coordinate that moves is cyclic (A does not change as they move); the
//! coordinate rows are then δ̇ = v (the drift of the cyclic coordinates themselves is not
//! modelled, so their eigenvalues are 0).
//!
//! Derivatives are exact: the right-hand side and the outputs are evaluated once per state and
//! input on dual numbers (forward mode, num-dual's `Dual64`) through the same generic code that
//! runs the scene in f64, so A, B and C carry no truncation error (tests: closed-form
//! frequencies to 1e-12). [`Scene::jacobian`] gives ∂f/∂(y, u) of the right-hand side itself, for
//! implicit integrators.
//!
//! Book: §12.6 (linearization), §15.3 (eigenvalues), (15.15.2)–(15.15.6) (modes).

use nalgebra::{Complex, DMatrix, DVector};
use serde::Serialize;

use super::{Scene, SceneError};
use vectrix_dynamics::multibody::Joint;

/// The moving coordinates of a steady motion are cyclic when ∂v̇/∂x changes along the motion
/// by less than this fraction of its largest entry (the derivatives are exact: a cyclic
/// coordinate changes them by rounding alone).
const CYCLIC_REL: f64 = 1e-9;

/// An initial state whose velocity or acceleration exceeds this (∞-norm, SI) is reported as
/// not an equilibrium (or, with `steady`, not a steady motion).
pub const EQUILIBRIUM_TOL: f64 = 1e-9;

/// Real parts of eigenvalues within this fraction of max |A_ij| are reported as 0 in
/// [`LinearMode`] (the eigenvalues of a double root, as a cyclic coordinate gives, are known
/// to about √ε of A's size).
pub const MARGINAL_REL: f64 = 1e-9;

/// One mode of the linearization: an eigenvalue (one of each conjugate pair) with its modal
/// quantities; a real part within [`MARGINAL_REL`]·max |A_ij| is reported as 0.
///
/// Book: (15.15.2)–(15.15.6).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinearMode {
    /// λ as [re, im] (im ≥ 0).
    pub eigenvalue: [f64; 2],
    /// ωn = |λ| [rad/s].
    pub natural_frequency: f64,
    /// ζ = −Re λ/|λ|; `None` for λ = 0.
    pub damping_ratio: Option<f64>,
    /// 1/(−Re λ) [s] for Re λ < 0; for Re λ > 0 the e-folding time of the growth is
    /// 1/Re λ, reported as a negative number; `None` for Re λ = 0.
    pub time_constant: Option<f64>,
    /// The state with the largest share of the mode's eigenvector.
    pub dominant_state: String,
}

/// How far the initial state is from an equilibrium (or a steady motion).
///
/// Book: §12.6.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EquilibriumResidual {
    /// |v₀|∞ (not checked for a steady motion).
    pub velocity: f64,
    /// |v̇(x₀)|∞.
    pub acceleration: f64,
    /// Whether both are within [`EQUILIBRIUM_TOL`] (velocity ignored when steady).
    pub ok: bool,
}

/// The linear model of a scene (or of an aircraft at trim) with its modes.
///
/// Book: §12.6, §15.7.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LinearModel {
    /// Scene name.
    pub scene: String,
    /// State names: `dq:BODY.k` (tangent displacement of joint coordinate k), `v:BODY.k`.
    pub state: Vec<String>,
    /// Input names (`effects[i]`: the magnitude of a force or torque effect).
    pub inputs: Vec<String>,
    /// Output names (the scene's output columns).
    pub outputs: Vec<String>,
    /// A (n × n), row-major.
    #[serde(rename = "A", serialize_with = "rows")]
    pub a: DMatrix<f64>,
    /// B (n × inputs).
    #[serde(rename = "B", serialize_with = "rows")]
    pub b: DMatrix<f64>,
    /// C (outputs × n).
    #[serde(rename = "C", serialize_with = "rows")]
    pub c: DMatrix<f64>,
    /// D (outputs × inputs).
    #[serde(rename = "D", serialize_with = "rows")]
    pub d: DMatrix<f64>,
    /// Every eigenvalue of A as [re, im].
    pub eigenvalues: Vec<[f64; 2]>,
    /// One mode per real eigenvalue and per conjugate pair, slowest first.
    pub modes: Vec<LinearMode>,
    /// Whether the state is a steady motion rather than an equilibrium.
    pub steady: bool,
    /// The residual of the dynamics at the linearization point.
    pub residual: EquilibriumResidual,
}

fn rows<S: serde::Serializer>(m: &DMatrix<f64>, s: S) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeSeq;
    let mut seq = s.serialize_seq(Some(m.nrows()))?;
    for r in 0..m.nrows() {
        seq.serialize_element(&m.row(r).iter().copied().collect::<Vec<f64>>())?;
    }
    seq.end()
}

impl LinearModel {
    /// Assembles the model and its modes from the matrices.
    ///
    /// # Errors
    /// A message when the sizes disagree, an entry is not finite or an eigenvalue of A
    /// overflows.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        scene: String,
        state: Vec<String>,
        inputs: Vec<String>,
        outputs: Vec<String>,
        (a, b, c, d): (DMatrix<f64>, DMatrix<f64>, DMatrix<f64>, DMatrix<f64>),
        steady: bool,
        residual: EquilibriumResidual,
    ) -> Result<Self, String> {
        let n = state.len();
        let shapes = [
            (&a, n, n, "A"),
            (&b, n, inputs.len(), "B"),
            (&c, outputs.len(), n, "C"),
            (&d, outputs.len(), inputs.len(), "D"),
        ];
        for (m, r, k, name) in shapes {
            if m.shape() != (r, k) {
                return Err(format!("{name} is {}×{}, expected {r}×{k}", m.nrows(), m.ncols()));
            }
            if m.iter().any(|x| !x.is_finite()) {
                return Err(format!(
                    "{name} has a non-finite entry: the dynamics are not differentiable here"
                ));
            }
        }
        // a model without states (every body welded) has no eigenvalues; nalgebra's Schur
        // decomposition underflows a usize on a 0 × 0 matrix, so it is not called
        let lambdas: Vec<Complex<f64>> =
            if n == 0 { Vec::new() } else { a.clone().complex_eigenvalues().iter().copied().collect() };
        // finite entries near f64::MAX overflow inside the eigenvalue iteration
        if lambdas.iter().any(|l| !(l.re.is_finite() && l.im.is_finite())) {
            return Err("the eigenvalues of A overflow (entries near f64::MAX); valid: A whose eigenvalues are finite".into());
        }
        // a real part within the differences' resolution of A is reported as 0 (a conservative
        // system's modes are marginal, not damped by 1e-16)
        let marginal = MARGINAL_REL * a.amax().max(f64::MIN_POSITIVE);
        let mut modes: Vec<LinearMode> = lambdas
            .iter()
            .filter(|l| l.im >= 0.0)
            .map(|&l| {
                let wn = l.norm();
                let re = if l.re.abs() <= marginal { 0.0 } else { l.re };
                LinearMode {
                    eigenvalue: [re, l.im],
                    natural_frequency: wn,
                    damping_ratio: (wn > 0.0).then(|| -re / wn),
                    time_constant: (re != 0.0).then(|| -1.0 / re),
                    dominant_state: dominant(&a, &l).map_or_else(String::new, |k| state[k].clone()),
                }
            })
            .collect();
        modes.sort_by(|x, y| x.natural_frequency.total_cmp(&y.natural_frequency));
        Ok(Self {
            scene,
            state,
            inputs,
            outputs,
            a,
            b,
            c,
            d,
            eigenvalues: lambdas.iter().map(|l| [l.re, l.im]).collect(),
            modes,
            steady,
            residual,
        })
    }
}

impl Scene {
    /// Names of the linearization's states: `dq:BODY.k` then `v:BODY.k`, v layout.
    pub(crate) fn state_names(&self) -> Vec<String> {
        let mut state = Vec::new();
        for prefix in ["dq", "v"] {
            for body in &self.built.bodies {
                for k in 0..body.joint.nv() {
                    state.push(format!("{prefix}:{}.{k}", body.name));
                }
            }
        }
        state
    }
}

/// The index of the largest entry of the eigenvector of λ (two steps of inverse iteration).
fn dominant(a: &DMatrix<f64>, l: &Complex<f64>) -> Option<usize> {
    let n = a.nrows();
    let shift = *l + Complex::new(1e-9 * (1.0 + l.norm()), 1e-9 * (1.0 + l.norm()));
    let m = DMatrix::from_fn(n, n, |i, j| {
        Complex::new(a[(i, j)], 0.0) - if i == j { shift } else { Complex::new(0.0, 0.0) }
    });
    let lu = m.lu();
    let mut x = DVector::from_element(n, Complex::new(1.0, 0.0));
    for _ in 0..3 {
        x = lu.solve(&x)?;
        let s = x.iter().map(|c| c.norm()).fold(0.0, f64::max);
        if !(s.is_finite() && s > 0.0) {
            return None;
        }
        x /= Complex::new(s, 0.0);
    }
    (0..n).max_by(|&i, &j| x[i].norm().total_cmp(&x[j].norm()))
}

impl Scene {
    /// Linearizes the scene about its initial state (see the module documentation).
    ///
    /// Book: §12.6, §15.7.
    ///
    /// # Errors
    /// [`SceneError::Run`] for a scene with no degrees of freedom, with loops or rolling
    /// contacts (their coordinates are dependent), for a `steady` state whose moving
    /// coordinates are not cyclic (A changes along the motion, so A at t = 0 would not describe
    /// it), or when the dynamics fail near the state.
    pub fn linearize(&self) -> Result<LinearModel, SceneError> {
        let fail = |message: String| SceneError::Run { t: 0.0, message };
        let b = &self.built;
        let (nq, nv) = (b.model.nq(), b.model.nv());
        if nv == 0 {
            return Err(self.invalid(
                "bodies",
                "the scene has no degrees of freedom (every joint a weld): nothing to linearize",
            ));
        }
        if self.has_constraints() {
            let at = if self.spec().loops.is_empty() { "effects" } else { "loops" };
            return Err(self.invalid(
                at,
                "scenes with loops or rolling contacts are not linearized: their coordinates are dependent; valid: \
                 a tree (write the mechanism in independent coordinates)",
            ));
        }
        if !self.tree_only() {
            return Err(self.invalid(
                "effects",
                "scenes with inerters are not linearized yet (their mass terms are not in the exact, dual-number \
                 right-hand side); valid: a tree with force elements",
            ));
        }
        let steady = self.spec().linearize.as_ref().is_some_and(|l| l.steady);
        let y0 = self.initial_state();
        let v0 = &y0[nq..];
        let x0: Vec<f64> = [vec![0.0; nv], v0.to_vec()].concat();
        let n = 2 * nv;
        let inputs = self.inputs();
        // exact first derivatives by dual numbers: one evaluation per state and input
        let jac = self.jacobians(&x0).map_err(fail)?;
        let mut a = DMatrix::zeros(n, n);
        for i in 0..nv {
            a[(i, nv + i)] = 1.0;
        }
        let v_block = jac.vdot_x.clone();
        a.view_mut((nv, 0), (nv, n)).copy_from(&v_block);
        if steady && v0.iter().any(|x| *x != 0.0) {
            // a steady motion is time-invariant in these coordinates only if the moving ones are
            // cyclic: A must not change along the motion. Compared after the fastest coordinate
            // has moved 0.3 rad (or m).
            let tau = 0.3 / v0.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
            let moved: Vec<f64> =
                x0.iter().enumerate().map(|(j, x)| if j < nv { x + v0[j] * tau } else { *x }).collect();
            let later = self.jacobians(&moved).map_err(fail)?.vdot_x;
            let change = (&later - &v_block).amax();
            if change > CYCLIC_REL * v_block.amax().max(1.0) {
                let names = self.state_names();
                let moving: Vec<&str> =
                    (0..nv).filter(|&j| v0[j] != 0.0).map(|j| names[j].as_str()).collect();
                // a ball or free joint's rates are resolved in the turning body: an applied
                // torque turns with it, so a steady precession is periodic in them
                let turning = b.bodies.iter().any(|body| {
                    matches!(body.joint, Joint::Ball | Joint::Free)
                        && (body.vi..body.vi + body.joint.nv()).any(|j| v0[j] != 0.0)
                });
                let hint = if turning {
                    "; a ball or free joint resolves ω in the turning body, where an applied torque turns with \
                     it, so a precessing top is periodic, not steady, in its coordinates: write the top in a gimbal \
                     of pins (Euler angles, examples/scenes/heavy_top_gimbal.toml)"
                } else {
                    ""
                };
                let at = self.spec().linearize.as_ref().map_or("bodies", |_| "linearize.steady");
                return Err(self.invalid(
                    at,
                    format!(
                        "the coordinates that move ({}) are not cyclic: ∂v̇/∂x changes by {change:.3e} along the \
                         motion, so the initial state is not a steady motion in these coordinates; valid: a motion \
                         whose moving coordinates are cyclic (a symmetric top's spin and precession angles in a \
                         gimbal, a free body's attitude without torques), or an equilibrium{hint}",
                        moving.join(", ")
                    ),
                ));
            }
        }
        let spec = self.spec();
        let mut bm = DMatrix::zeros(n, inputs.len());
        bm.view_mut((nv, 0), (nv, inputs.len())).copy_from(&jac.vdot_u);
        let outputs = self.columns();
        let cm = jac.row_x;
        // the output columns are functions of the state alone (a loop's reactions, the only
        // ones that depend on the loads, are not linearized): D = 0
        let dm = DMatrix::zeros(outputs.len(), inputs.len());
        let acc = &jac.vdot;
        let amax = |x: &[f64]| x.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
        let (rv, ra) = (amax(v0), amax(acc));
        let residual = EquilibriumResidual {
            velocity: rv,
            acceleration: ra,
            ok: ra <= EQUILIBRIUM_TOL && (steady || rv <= EQUILIBRIUM_TOL),
        };
        let state = self.state_names();
        let input_names = self.input_names();
        LinearModel::new(spec.name.clone(), state, input_names, outputs, (a, bm, cm, dm), steady, residual)
            .map_err(fail)
    }
}
