//! One step of DOP853 (Dormand & Prince 8(5,3)) with its error estimate and dense output.

use super::dense::{DenseStep, Form, hermite_part, weighted};
use super::dop853_coefficients::{A, B, BHH, C, D, E};
use crate::Rhs;
use crate::state::{Row, State, check_stages, combine, combine_row_into, eval, eval_slot, weighted_stages};
use crate::{OdeError, Work};

/// Nodes of the 12 stages of the 8th-order solution (c₁₂ = 1).
pub(crate) const C12: [f64; 12] = [C[0], C[1], C[2], C[3], C[4], C[5], C[6], C[7], C[8], C[9], C[10], 1.0];

/// Stage rows of the 12 stages (row 0 empty).
pub(crate) const A12: [&[f64]; 12] = [&[], A[0], A[1], A[2], A[3], A[4], A[5], A[6], A[7], A[8], A[9], A[10]];

/// The rows of [`A12`] without their zeros (16 of the 66 entries: a stage's argument is a chain
/// of 50 dependent multiply-adds a step instead of 66).
const ROWS: [Row<11>; 12] = Row::table(A12);

/// The stages with a nonzero weight in y₁ (b) or in the 5th-order estimate (e): k₂..k₅ have
/// neither, so the sums skip them (see [`Row`]: the same numbers).
const BE_STAGES: ([usize; 12], usize) = weighted_stages(&B, &E);

/// Stages 2..=12 from k₁ = `k[0]` into `k[1..12]` (k holds at least k₁); returns y₁ and the
/// scaled error norm of HNW (10.17):
/// err = |h| ‖e₅‖² / √(n (‖e₅‖² + 0.01‖e₃‖²)), with weights sk = atol + rtol·max(|y|, |y₁|).
///
/// Book: §4.11; HNW §II.10.
pub(crate) fn step<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    h: f64,
    k: &mut Vec<S>,
    tol: (f64, f64),
    work: &mut Work,
) -> Result<(S, f64), OdeError> {
    // kᵢ = f(t + cᵢh, y + h Σ aᵢⱼ kⱼ), unrolled so that every row of A is a constant; the
    // stages' arguments share one state, and each stage goes into its slot of `k` (in place:
    // kept from the last step and written without allocating; else pushed anew)
    if !F::IN_PLACE {
        k.truncate(1);
    }
    let mut yi = y.clone();
    macro_rules! stages {
        ($($i:literal)*) => {$(
            combine_row_into(&mut yi, y, h, &ROWS[$i], k);
            eval_slot(f, t + C12[$i] * h, &yi, k, $i, &mut work.fevals);
        )*};
    }
    stages!(1 2 3 4 5 6 7 8 9 10 11);
    check_stages(&k[..12], 1, t, h, &C12)?;
    // Σ bᵢ kᵢ once: y₁ = y + h Σ bᵢ kᵢ (8th order), and the 3rd-order estimate
    // e₃ = Σ bᵢkᵢ − (bhh₁k₁ + bhh₂k₉ + bhh₃k₁₂); the 5th-order estimate e₅ = Σ eᵢ kᵢ.
    // Component by component in blocks of four (each sum in the order of the stage-by-stage
    // form, so the same bits), without the e₃ and e₅ states ([`sums`]).
    // y₁ in the stages' argument when in place (a heap state keeps its buffer)
    let mut y1 = if F::IN_PLACE {
        yi.clone_from(y);
        yi
    } else {
        y.clone()
    };
    let mut err = (0.0, 0.0);
    let (ys, n) = (y.as_slice(), y.dim());
    let k = &k[..12];
    // every stage has y's dimension (`eval` checked k₁, `check_stages` the others)
    debug_assert!(k.iter().all(|kj| kj.dim() == n));
    // blocks of four components (the compiler vectorises across them), then the tail one by one
    const W: usize = 4;
    let full = n - n % W;
    let y1s = y1.as_mut_slice();
    for base in (0..full).step_by(W) {
        sums::<S, W>(k, base, &ys[base..base + W], &mut y1s[base..base + W], h, tol, &mut err);
    }
    for base in full..n {
        sums::<S, 1>(k, base, &ys[base..=base], &mut y1s[base..=base], h, tol, &mut err);
    }
    let (err5, err3) = err;
    let mut deno = err5 + 0.01 * err3;
    if deno <= 0.0 {
        deno = 1.0;
    }
    let err = h.abs() * err5 * (1.0 / (y.dim() as f64 * deno)).sqrt();
    Ok((y1, err))
}

/// Components base..base + W of y₁ = y + h Σ bᵢkᵢ, their estimates e₃ and e₅ (see [`step`]),
/// and their squared scaled errors added to `err` = (Σ (e₅/sk)², Σ (e₃/sk)²) component after
/// component (the order of the one-by-one loop, so the same bits).
#[inline(always)]
fn sums<S: State, const W: usize>(
    k: &[S],
    base: usize,
    y: &[f64],
    y1: &mut [f64],
    h: f64,
    (rtol, atol): (f64, f64),
    err: &mut (f64, f64),
) {
    let (mut e3, mut e5) = ([0.0; W], [0.0; W]);
    for &j in &BE_STAGES.0[..BE_STAGES.1] {
        let kj = &k[j].as_slice()[base..base + W];
        for c in 0..W {
            e3[c] += B[j] * kj[c];
            e5[c] += E[j] * kj[c];
        }
    }
    let (k1, k9, k12) = (
        &k[0].as_slice()[base..base + W],
        &k[8].as_slice()[base..base + W],
        &k[11].as_slice()[base..base + W],
    );
    for c in 0..W {
        y1[c] += h * e3[c];
        e3[c] += -BHH[0] * k1[c];
        e3[c] += -BHH[1] * k9[c];
        e3[c] += -BHH[2] * k12[c];
    }
    for c in 0..W {
        let sk = atol + rtol * y[c].abs().max(y1[c].abs());
        err.1 += (e3[c] / sk).powi(2);
        err.0 += (e5[c] / sk).powi(2);
    }
}

/// The dense output of an accepted step, given k₁..k₁₂ in `k` and k₁₃ = f(t + h, y₁); costs
/// three more evaluations (stages 14–16).
///
/// Book: §4.11; HNW §II.10, `dop853.f` (IOUT ≥ 2 block).
#[allow(clippy::too_many_arguments)]
pub(crate) fn dense<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    y1: &S,
    h: f64,
    k: &mut Vec<S>,
    k13: &S,
    work: &mut Work,
) -> Result<DenseStep<S>, OdeError> {
    k.truncate(12);
    k.push(k13.clone());
    for i in 13..16 {
        let yi = combine(y, h, A[i - 1], k);
        let ki = eval(f, t + C[i] * h, &yi, t, i + 1, &mut work.fevals)?;
        k.push(ki);
    }
    let [c0, c1, c2, c3] = hermite_part(y, y1, &k[0], k13, h);
    let mut c = vec![c0, c1, c2, c3];
    for d in &D {
        c.push(weighted(y, h, d, k));
    }
    Ok(DenseStep { t, h, c, form: Form::DormandPrince })
}
