//! Gauss–Legendre collocation (implicit midpoint, 2 and 3 stages), solved by simplified
//! Newton with the dense LU of [`DenseLu`] (buffers allocated once per run).

use std::time::Instant;

use faer::Mat;

use super::lu::DenseLu;

use crate::error::{check_interval, check_step};
use crate::state::{State, check_state, eval};
use crate::{OdeError, Work};

/// A Gauss–Legendre Runge–Kutta method with s stages, order 2s. It conserves every
/// quadratic invariant of the flow exactly (up to round-off and the Newton tolerance) and is
/// symplectic, A-stable and symmetric.
///
/// Book: §4.11; HLW §II.1.3 (Gauss collocation), Theorem IV.2.2 (quadratic invariants).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GaussLegendre {
    /// Implicit midpoint rule, s = 1, order 2.
    Midpoint,
    /// Two stages, order 4.
    Gauss4,
    /// Three stages, order 6.
    Gauss6,
}

const R3: f64 = 1.732_050_807_568_877_2; // √3
const R15: f64 = 3.872_983_346_207_417; // √15

impl GaussLegendre {
    /// Name for tables.
    pub fn name(self) -> &'static str {
        match self {
            Self::Midpoint => "Midpoint",
            Self::Gauss4 => "Gauss4",
            Self::Gauss6 => "Gauss6",
        }
    }

    /// Order 2s.
    pub fn order(self) -> u32 {
        2 * self.stages() as u32
    }

    /// Number of stages s.
    pub fn stages(self) -> usize {
        match self {
            Self::Midpoint => 1,
            Self::Gauss4 => 2,
            Self::Gauss6 => 3,
        }
    }

    /// The tableau (c, A row-major, b), HLW Table II.1.1–II.1.2.
    fn tableau(self) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        match self {
            Self::Midpoint => (vec![0.5], vec![0.5], vec![1.0]),
            Self::Gauss4 => (
                vec![0.5 - R3 / 6.0, 0.5 + R3 / 6.0],
                vec![0.25, 0.25 - R3 / 6.0, 0.25 + R3 / 6.0, 0.25],
                vec![0.5, 0.5],
            ),
            Self::Gauss6 => (
                vec![0.5 - R15 / 10.0, 0.5, 0.5 + R15 / 10.0],
                vec![
                    5.0 / 36.0,
                    2.0 / 9.0 - R15 / 15.0,
                    5.0 / 36.0 - R15 / 30.0,
                    5.0 / 36.0 + R15 / 24.0,
                    2.0 / 9.0,
                    5.0 / 36.0 - R15 / 24.0,
                    5.0 / 36.0 + R15 / 30.0,
                    2.0 / 9.0 + R15 / 15.0,
                    5.0 / 36.0,
                ],
                vec![5.0 / 18.0, 4.0 / 9.0, 5.0 / 18.0],
            ),
        }
    }

    /// Integrates y′ = f(t, y) with `n` equal steps; the Jacobian ∂f/∂y is taken by forward
    /// differences (n evaluations, once per step). `observe(t, y)` runs after every step.
    ///
    /// # Errors
    /// As [`GaussLegendre::integrate_with_jacobian`].
    pub fn integrate<S: State, F: FnMut(f64, &S) -> S>(
        self,
        mut f: F,
        t0: f64,
        y0: &S,
        t1: f64,
        n: usize,
        observe: impl FnMut(f64, &S),
    ) -> Result<(S, Work), OdeError> {
        self.run(&mut f, None::<&mut fn(f64, &S) -> Vec<f64>>, t0, y0, t1, n, observe)
    }

    /// Integrates y′ = f(t, y) with `n` equal steps and the exact Jacobian
    /// `jac(t, y)` = ∂f/∂y as a row-major n×n vector (evaluated once per step).
    ///
    /// # Errors
    /// [`OdeError::InvalidInterval`], [`OdeError::NonPositiveStep`] (n = 0),
    /// [`OdeError::NonFiniteState`], [`OdeError::RhsNotFinite`], [`OdeError::NewtonFailed`],
    /// [`OdeError::SingularNewtonMatrix`], [`OdeError::DimensionMismatch`] (Jacobian size).
    #[allow(clippy::too_many_arguments)]
    pub fn integrate_with_jacobian<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S) -> Vec<f64>>(
        self,
        mut f: F,
        mut jac: J,
        t0: f64,
        y0: &S,
        t1: f64,
        n: usize,
        observe: impl FnMut(f64, &S),
    ) -> Result<(S, Work), OdeError> {
        self.run(&mut f, Some(&mut jac), t0, y0, t1, n, observe)
    }

    #[allow(clippy::too_many_arguments)]
    fn run<S: State, F: FnMut(f64, &S) -> S, J: FnMut(f64, &S) -> Vec<f64>>(
        self,
        f: &mut F,
        mut jac: Option<&mut J>,
        t0: f64,
        y0: &S,
        t1: f64,
        n: usize,
        mut observe: impl FnMut(f64, &S),
    ) -> Result<(S, Work), OdeError> {
        let start = Instant::now();
        check_interval(t0, t1)?;
        let h = (t1 - t0) / n as f64;
        check_step(h)?;
        check_state(t0, y0)?;
        let (c, a, b) = self.tableau();
        let (s, d) = (self.stages(), y0.dim());
        let mut work = Work::default();
        let mut y = y0.clone();
        let mut jm = Mat::<f64>::zeros(d, d);
        // the sd×sd Newton matrix and the residual, allocated once
        let mut lu = DenseLu::<f64>::new(s * d);
        let mut g = vec![0.0; s * d];
        for step in 0..n {
            let t = t0 + step as f64 * h;
            // J = ∂f/∂y at (t, y), once per step (simplified Newton)
            work.jacobians += 1;
            match jac.as_deref_mut() {
                Some(j) => {
                    let v = j(t, &y);
                    if v.len() != d * d {
                        return Err(OdeError::DimensionMismatch {
                            what: "Jacobian",
                            got: v.len(),
                            expected: d * d,
                        });
                    }
                    for i in 0..d {
                        for k in 0..d {
                            jm[(i, k)] = v[i * d + k];
                        }
                    }
                }
                None => finite_difference(f, t, &y, &mut jm, &mut work)?,
            }
            let z = newton(f, &jm, (&c, &a, s), t, &y, h, (&mut lu, &mut g), &mut work)?;
            // y₁ = y + h Σ bⱼ f(t + cⱼh, y + Zⱼ)
            let mut y1 = y.clone();
            for j in 0..s {
                let yj = shifted(&y, &z[j * d..(j + 1) * d]);
                let fj = eval(f, t + c[j] * h, &yj, t, j + 1, &mut work.fevals)?;
                for (o, fi) in y1.as_mut_slice().iter_mut().zip(fj.as_slice()) {
                    *o += h * b[j] * fi;
                }
            }
            y = y1;
            work.accepted += 1;
            observe(t + h, &y);
        }
        work.wall = start.elapsed();
        Ok((y, work))
    }
}

/// y + z as a state.
fn shifted<S: State>(y: &S, z: &[f64]) -> S {
    let mut out = y.clone();
    for (o, zi) in out.as_mut_slice().iter_mut().zip(z) {
        *o += zi;
    }
    out
}

/// Forward-difference Jacobian: column j = (f(y + δeⱼ) − f(y))/δ, δ = √ε·max(1, |yⱼ|).
fn finite_difference<S: State, F: FnMut(f64, &S) -> S>(
    f: &mut F,
    t: f64,
    y: &S,
    jm: &mut Mat<f64>,
    work: &mut Work,
) -> Result<(), OdeError> {
    let f0 = eval(f, t, y, t, 0, &mut work.fevals)?;
    for j in 0..y.dim() {
        let mut yj = y.clone();
        let dj = f64::EPSILON.sqrt() * y.as_slice()[j].abs().max(1.0);
        yj.as_mut_slice()[j] += dj;
        let fj = eval(f, t, &yj, t, 0, &mut work.fevals)?;
        for i in 0..y.dim() {
            jm[(i, j)] = (fj.as_slice()[i] - f0.as_slice()[i]) / dj;
        }
    }
    Ok(())
}

/// Solves the stage equations Zᵢ = h Σⱼ aᵢⱼ f(t + cⱼh, y + Zⱼ) by simplified Newton:
/// (I − h A⊗J) ΔZ = −Z + h (A⊗I) F(Z), until ΔZ reaches round-off (HLW §VIII.6).
#[allow(clippy::too_many_arguments)]
fn newton<S: State, F: FnMut(f64, &S) -> S>(
    f: &mut F,
    jm: &Mat<f64>,
    (c, a, s): (&[f64], &[f64], usize),
    t: f64,
    y: &S,
    h: f64,
    (lu, g): (&mut DenseLu<f64>, &mut [f64]),
    work: &mut Work,
) -> Result<Vec<f64>, OdeError> {
    let d = y.dim();
    let sd = s * d;
    // M = I − h A⊗J
    let factored = lu.factor_with(|r, q| {
        let (i, k) = (r / d, r % d);
        let (j, l) = (q / d, q % d);
        let id = if r == q { 1.0 } else { 0.0 };
        id - h * a[i * s + j] * jm[(k, l)]
    });
    work.factorizations += 1;
    // singular branch: a zero or non-finite pivot (the corrections would not be finite)
    if factored.is_err() {
        return Err(OdeError::SingularNewtonMatrix { t, h });
    }
    let ymax = y.as_slice().iter().fold(1.0_f64, |acc, v| acc.max(v.abs()));
    let tol = 4.0 * f64::EPSILON * ymax;
    let mut z = vec![0.0; sd];
    let mut prev = f64::INFINITY;
    const MAX_ITERATIONS: usize = 50;
    for it in 0..MAX_ITERATIONS {
        // F(Z): the stage derivatives
        let mut fz = Vec::with_capacity(s);
        for j in 0..s {
            let yj = shifted(y, &z[j * d..(j + 1) * d]);
            fz.push(eval(f, t + c[j] * h, &yj, t, j + 1, &mut work.fevals)?);
        }
        // residual G = −Z + h (A⊗I) F
        for (r, gr) in g.iter_mut().enumerate() {
            let (i, k) = (r / d, r % d);
            *gr = -z[r] + h * (0..s).map(|j| a[i * s + j] * fz[j].as_slice()[k]).sum::<f64>();
        }
        // factored above, g of length s·d: cannot fail
        let solved = lu.solve(g);
        debug_assert!(solved.is_ok(), "{solved:?}");
        work.newton_iterations += 1;
        let mut norm = 0.0_f64;
        for (r, zr) in z.iter_mut().enumerate() {
            let dz = g[r];
            if !dz.is_finite() {
                return Err(OdeError::SingularNewtonMatrix { t, h });
            }
            *zr += dz;
            norm = norm.max(dz.abs());
        }
        // converged at the tolerance, or stagnating at round-off
        if norm <= tol || (it > 0 && norm >= 0.5 * prev && norm <= 1e4 * tol) {
            return Ok(z);
        }
        if it > 3 && norm > prev {
            break; // diverging
        }
        prev = norm;
    }
    Err(OdeError::NewtonFailed { t, h, iterations: MAX_ITERATIONS })
}
