//! The linear algebra of one RADAU5 step: the method's constants, the real and complex
//! iteration matrices factorized in place by [`DenseLu`], the transformed simplified-Newton
//! iteration, the embedded error estimate and the Jacobian by finite differences.
//!
//! Book: §4.11; HW = Hairer & Wanner, *Solving Ordinary Differential Equations II*, §IV.8
//! (implementation of implicit Runge–Kutta methods), and their `radau5.f` (`RADCOR`,
//! `ESTRAD`, `SLVRAD`, `DECOMR`, `DECOMC`), whose constants and control are followed here.

use crate::Rhs;
use faer::c64;

use super::lu::DenseLu;

use crate::state::State;
use crate::{OdeError, Work};

const SQ6: f64 = 2.449_489_742_783_178; // √6
/// Nodes c₁, c₂ (c₃ = 1) of Radau IIA 5: (4 ∓ √6)/10 (HW Table IV.5.6).
pub(crate) const C1: f64 = (4.0 - SQ6) / 10.0;
/// Second node.
pub(crate) const C2: f64 = (4.0 + SQ6) / 10.0;
/// Error-estimate weights (γ₀ = 1/u₁ with the embedded formula of HW (IV.8.19)), as in `radau5.f`.
const DD1: f64 = -(13.0 + 7.0 * SQ6) / 3.0;
const DD2: f64 = (-13.0 + 7.0 * SQ6) / 3.0;
const DD3: f64 = -1.0 / 3.0;
/// T and T⁻¹ of `radau5.f` (digits as printed there): T⁻¹A⁻¹T = diag(γ, [[α, −β], [β, α]]) (HW (IV.8.10)); T₃₂ = 1,
/// T₃₃ = 0.
#[allow(clippy::excessive_precision)]
const T: [[f64; 3]; 3] = [
    [9.123_239_487_089_294_3e-2, -0.141_255_295_020_954_2, -3.002_919_410_514_742_4e-2],
    [0.241_717_932_707_107, 0.204_129_352_293_799_93, 0.382_942_112_757_261_9],
    [0.966_048_182_615_092_9, 1.0, 0.0],
];
#[allow(clippy::excessive_precision)]
const TI: [[f64; 3]; 3] = [
    [4.325_579_890_063_155, 0.339_199_251_815_809_87, 0.541_770_539_935_874_9],
    [-4.178_718_591_551_905, -0.327_682_820_761_062_4, 0.476_623_554_500_550_45],
    [-0.502_872_634_945_786_9, 2.571_926_949_855_605_4, -0.596_039_204_828_224_9],
];

/// γ = u₁ (the real eigenvalue of A⁻¹) and α ± iβ (the complex pair), HW (IV.8.9).
pub(crate) fn eigenvalues() -> (f64, f64, f64) {
    let (c81, c9) = (81f64.cbrt(), 9f64.cbrt());
    let u1 = 30.0 / (6.0 + c81 - c9);
    let (alph, beta) = ((12.0 - c81 + c9) / 60.0, (c81 + c9) * 3f64.sqrt() / 60.0);
    let cno = alph * alph + beta * beta;
    (u1, alph / cno, beta / cno)
}

/// The iteration matrices at step size h, factorized in place in buffers allocated once per
/// run: E₁ = (γ/h)I − J (real) and E₂ = ((α + iβ)/h)I − J (complex), `DECOMR`/`DECOMC` of
/// `radau5.f`, with the scratch of the Newton solves and the error estimate.
pub(crate) struct Factors {
    e1: DenseLu<f64>,
    e2: DenseLu<c64>,
    /// γ/h.
    pub fac1: f64,
    /// α/h.
    pub alphn: f64,
    /// β/h.
    pub betan: f64,
    /// The step size they were factorized for; `None` when stale or refused.
    h: Option<f64>,
    /// γ, α, β of [`eigenvalues`], computed once (two cube roots).
    gab: (f64, f64, f64),
    /// Scratch: the complex right-hand side z₂ + i z₃, and the two vectors of the estimate.
    zc: Vec<c64>,
    f2: Vec<f64>,
    cont: Vec<f64>,
}

impl Factors {
    /// Buffers for n equations, nothing factorized yet.
    pub(crate) fn new(n: usize) -> Self {
        Self {
            e1: DenseLu::new(n),
            e2: DenseLu::new(n),
            fac1: 0.0,
            alphn: 0.0,
            betan: 0.0,
            h: None,
            gab: eigenvalues(),
            zc: vec![c64::new(0.0, 0.0); n],
            f2: vec![0.0; n],
            cont: vec![0.0; n],
        }
    }

    /// The step size of the current factors, if they are usable.
    pub(crate) fn h(&self) -> Option<f64> {
        self.h
    }

    /// Marks the factors stale (a new Jacobian).
    pub(crate) fn invalidate(&mut self) {
        self.h = None;
    }

    /// Factorizes both matrices for J (row-major `jac`) and h in place; `false` when either
    /// is singular (a zero or non-finite pivot or factor entry), the factors then stale.
    pub(crate) fn factor(&mut self, jac: &[f64], h: f64) -> bool {
        let (u1, alph, beta) = self.gab;
        let n = self.e1.dim();
        let (fac1, alphn, betan) = (u1 / h, alph / h, beta / h);
        (self.fac1, self.alphn, self.betan) = (fac1, alphn, betan);
        self.h = None;
        // E₁ = (γ/h)I − J
        let ok1 =
            self.e1.factor_with(|i, j| if i == j { fac1 - jac[i * n + j] } else { -jac[i * n + j] }).is_ok();
        // E₂ = ((α + iβ)/h)I − J
        let ok2 = ok1
            && self
                .e2
                .factor_with(|i, j| {
                    let a = jac[i * n + j];
                    if i == j { c64::new(alphn - a, betan) } else { c64::new(-a, 0.0) }
                })
                .is_ok();
        if ok2 {
            self.h = Some(h);
        }
        ok2
    }

    /// x ← E₁⁻¹ x.
    pub(crate) fn solve_real(&self, x: &mut [f64]) {
        // sizes match and the factors are valid whenever `h` is `Some` (the callers' invariant)
        let solved = self.e1.solve(x);
        debug_assert!(solved.is_ok(), "{solved:?}");
    }

    /// One simplified-Newton correction in transformed variables (`SLVRAD`): given the
    /// transformed stage derivatives (z₁, z₂, z₃) ← T⁻¹F and the current transformed stage
    /// increments W = (f₁, f₂, f₃), overwrites z with ΔW.
    pub(crate) fn solve_newton(&mut self, z: [&mut [f64]; 3], w: [&[f64]; 3]) {
        let [z1, z2, z3] = z;
        let n = z1.len();
        for i in 0..n {
            let (s2, s3) = (-w[1][i], -w[2][i]);
            z1[i] -= w[0][i] * self.fac1;
            z2[i] += s2 * self.alphn - s3 * self.betan;
            z3[i] += s3 * self.alphn + s2 * self.betan;
        }
        self.solve_real(z1);
        // (z₂ + i z₃) ← E₂⁻¹ (z₂ + i z₃)
        for (c, (a, b)) in self.zc.iter_mut().zip(z2.iter().zip(z3.iter())) {
            *c = c64::new(*a, *b);
        }
        let solved = self.e2.solve(&mut self.zc);
        debug_assert!(solved.is_ok(), "{solved:?}");
        for (c, (a, b)) in self.zc.iter().zip(z2.iter_mut().zip(z3.iter_mut())) {
            (*a, *b) = (c.re, c.im);
        }
    }
}

/// x ← T x (`which` = T) or T⁻¹ x, component by component over the three stages.
pub(crate) fn transform(m: &[[f64; 3]; 3], x: [&[f64]; 3], out: [&mut [f64]; 3]) {
    let [o1, o2, o3] = out;
    for i in 0..o1.len() {
        let (a, b, c) = (x[0][i], x[1][i], x[2][i]);
        o1[i] = m[0][0] * a + m[0][1] * b + m[0][2] * c;
        o2[i] = m[1][0] * a + m[1][1] * b + m[1][2] * c;
        o3[i] = m[2][0] * a + m[2][1] * b + m[2][2] * c;
    }
}

/// T (stage increments Z = T W).
pub(crate) const T_MAT: [[f64; 3]; 3] = T;
/// T⁻¹.
pub(crate) const TI_MAT: [[f64; 3]; 3] = TI;

/// √(Σ (xᵢ/scᵢ)² / n): the scaled root-mean-square norm of `radau5.f`.
pub(crate) fn rms_scaled(x: &[f64], scal: &[f64]) -> f64 {
    let s: f64 = x.iter().zip(scal).map(|(a, b)| (a / b) * (a / b)).sum();
    (s / x.len() as f64).sqrt()
}

/// The embedded error estimate of HW (IV.8.19)–(IV.8.20) (`ESTRAD`):
/// err = (I − hγ₀J)⁻¹[γ₀h f(t, y) + e₁Z₁ + e₂Z₂ + e₃Z₃], with the filter applied twice,
/// at a new f evaluation, after a rejection or on the first step when the first estimate
/// exceeds 1 (stiff components would otherwise be overestimated). Returns the scaled norm,
/// at least 1e-10.
#[allow(clippy::too_many_arguments)]
pub(crate) fn estimate<S: State, F: Rhs<S>>(
    f: &mut F,
    lu: &mut Factors,
    (t, y, f0): (f64, &S, &[f64]),
    z: [&[f64]; 3],
    scal: &[f64],
    first_or_reject: bool,
    work: &mut Work,
) -> Result<f64, OdeError> {
    let Some(h) = lu.h else { return Ok(f64::INFINITY) };
    let n = f0.len();
    let (hee1, hee2, hee3) = (DD1 / h, DD2 / h, DD3 / h);
    // the buffers are taken out of `lu` for the solves and put back at the end
    let (mut f2, mut cont) = (core::mem::take(&mut lu.f2), core::mem::take(&mut lu.cont));
    // f2 = (e₁Z₁ + e₂Z₂ + e₃Z₃)/h; err = E₁⁻¹ (f0 + f2)
    for i in 0..n {
        f2[i] = hee1 * z[0][i] + hee2 * z[1][i] + hee3 * z[2][i];
        cont[i] = f2[i] + f0[i];
    }
    lu.solve_real(&mut cont);
    let mut err = rms_scaled(&cont, scal).max(1e-10);
    if err >= 1.0 && first_or_reject {
        // the filter a second time, at y + err (HW (IV.8.20))
        let mut yc = y.clone();
        for (o, c) in yc.as_mut_slice().iter_mut().zip(&cont) {
            *o += c;
        }
        work.fevals += 1;
        let f1 = f.call(t, &yc);
        // the filtered point is not a trajectory point: an unusable second estimate keeps
        // the first (the step is rejected and retried smaller)
        if f1.dim() == n && f1.as_slice().iter().all(|v| v.is_finite()) {
            for i in 0..n {
                cont[i] = f1.as_slice()[i] + f2[i];
            }
            lu.solve_real(&mut cont);
            err = rms_scaled(&cont, scal).max(1e-10);
        }
    }
    (lu.f2, lu.cont) = (f2, cont);
    Ok(err)
}

/// Forward-difference Jacobian of `radau5.f`: column j = (f(y + δⱼeⱼ) − f(y))/δⱼ with
/// δⱼ = √(ε·max(1e-5, |yⱼ|)); n evaluations, counted in `work.fd_jacobian_fevals` too.
pub(crate) fn finite_difference<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    f0: &[f64],
    jm: &mut [f64],
    work: &mut Work,
) {
    let n = y.dim();
    let mut yj = y.clone();
    for j in 0..n {
        let ysafe = y.as_slice()[j];
        let delt = (f64::EPSILON * ysafe.abs().max(1e-5)).sqrt();
        yj.as_mut_slice()[j] = ysafe + delt;
        work.fevals += 1;
        work.fd_jacobian_fevals += 1;
        let fj = f.call(t, &yj);
        for i in 0..n {
            // a non-finite or short f here shows as a non-finite entry, refused by the caller
            jm[i * n + j] = fj.as_slice().get(i).map_or(f64::NAN, |v| (v - f0[i]) / delt);
        }
        yj.as_mut_slice()[j] = ysafe;
    }
}

/// The Jacobian closure's type when none is given (finite differences are used instead).
///
/// Book: §4.11; HW §IV.8.
pub type NoJacobian<S> = fn(f64, &S, &mut [f64]);

/// J = ∂f/∂y at (t, y) into `jm` (n² entries, row-major: (i, j) at i·n + j), written by the
/// caller's `jac` directly or, without one, by [`finite_difference`] from f0 = f(t, y);
/// refused if any entry is not finite (entries `jac` leaves unwritten stay NaN). Counts one
/// Jacobian in `work`.
///
/// # Errors
/// [`OdeError::JacobianNotFinite`] naming t, the entry and the state.
#[allow(clippy::too_many_arguments)]
pub(crate) fn jacobian_into<S: State, F: Rhs<S>, J: FnMut(f64, &S, &mut [f64])>(
    f: &mut F,
    jac: Option<&mut J>,
    t: f64,
    y: &S,
    f0: &[f64],
    jm: &mut [f64],
    work: &mut Work,
) -> Result<(), OdeError> {
    let n = y.dim();
    work.jacobians += 1;
    match jac {
        Some(j) => {
            // entries the caller does not write stay NaN and are refused below
            jm.fill(f64::NAN);
            j(t, y, jm);
        }
        None => finite_difference(f, t, y, f0, jm, work),
    }
    for c in 0..n {
        for r in 0..n {
            let value = jm[r * n + c];
            if !value.is_finite() {
                return Err(OdeError::JacobianNotFinite {
                    t,
                    row: r,
                    col: c,
                    value,
                    state: y.as_slice().to_vec(),
                });
            }
        }
    }
    Ok(())
}
