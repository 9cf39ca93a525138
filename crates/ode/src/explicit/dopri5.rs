//! One step of DOPRI5 (Dormand & Prince 5(4)) with its error estimate and dense output.

use super::dense::{DenseStep, Form, hermite_part, weighted};
use super::tableau::{DOPRI5, DOPRI5_D, DOPRI5_E};
use crate::Rhs;
use crate::state::{State, check_stages, combine_into, eval_slot, eval_unchecked};
use crate::{OdeError, Work};

/// Stages 2..=7 from k₁ = `k[0]` into `k[1..7]` (stage 7 is f(t + h, y₁), first same as
/// last); returns y₁ and the RMS error ‖h Σ eᵢkᵢ / sk‖ with sk = atol + rtol·max(|y|, |y₁|).
///
/// Book: §4.11; HNW §II.5, (4.11).
pub(crate) fn step<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    h: f64,
    k: &mut Vec<S>,
    tol: (f64, f64),
    work: &mut Work,
) -> Result<(S, f64), OdeError> {
    if F::IN_PLACE {
        step_in_place(f, t, y, h, k, tol, work)
    } else {
        step_returning(f, t, y, h, k, tol, work)
    }
}

/// [`step`] for a right-hand side that returns its result: the stages as locals (registers
/// for small fixed-size states), moved into `k` at the end.
#[inline(always)]
fn step_returning<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    h: f64,
    k: &mut Vec<S>,
    tol: (f64, f64),
    work: &mut Work,
) -> Result<(S, f64), OdeError> {
    k.truncate(1);
    // the stages as locals (registers for small fixed-size states), every row of A a constant;
    // they move into `k` at the end for the dense output and the stage scan
    let a = DOPRI5.a;
    let k1 = &k[0];
    let arg = |row: &[f64], ks: &[&S]| -> S {
        let mut out = y.clone();
        for (cj, kj) in row.iter().zip(ks) {
            out.add_scaled(h * cj, kj);
        }
        out
    };
    let mut f_at = |i: usize, yi: &S| eval_unchecked(f, t + DOPRI5.c[i] * h, yi, &mut work.fevals);
    let k2 = f_at(1, &arg(a[1], &[k1]));
    let k3 = f_at(2, &arg(a[2], &[k1, &k2]));
    let k4 = f_at(3, &arg(a[3], &[k1, &k2, &k3]));
    let k5 = f_at(4, &arg(a[4], &[k1, &k2, &k3, &k4]));
    let k6 = f_at(5, &arg(a[5], &[k1, &k2, &k3, &k4, &k5]));
    // row 7 of A is b: the stage-7 argument is y₁
    let y1 = arg(a[6], &[k1, &k2, &k3, &k4, &k5, &k6]);
    let k7 = f_at(6, &y1);
    // local error estimate h Σ eᵢ kᵢ (e₂ = 0: k₂ does not enter)
    let mut e = k1.clone();
    for x in e.as_mut_slice() {
        *x *= h * DOPRI5_E[0];
    }
    for (ej, kj) in DOPRI5_E[2..].iter().zip([&k3, &k4, &k5, &k6, &k7]) {
        e.add_scaled(h * ej, kj);
    }
    k.extend([k2, k3, k4, k5, k6, k7]);
    let (rtol, atol) = tol;
    let mut err = 0.0;
    for ((yi, y1i), ei) in y.as_slice().iter().zip(y1.as_slice()).zip(e.as_slice()) {
        let sk = atol + rtol * yi.abs().max(y1i.abs());
        err += (ei / sk).powi(2);
    }
    Ok((y1, rms_checked(k, y, t, h, err)?))
}

/// [`step`] for an in-place right-hand side ([`crate::InPlace`]): each stage written into its
/// slot of `k`, kept from the last step (no allocation per evaluation for a heap state).
#[inline(always)]
fn step_in_place<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    h: f64,
    k: &mut Vec<S>,
    tol: (f64, f64),
    work: &mut Work,
) -> Result<(S, f64), OdeError> {
    // kᵢ = f(t + cᵢh, y + h Σ aᵢⱼ kⱼ) into slot i of `k` (kept from the last step: an
    // in-place right-hand side writes there without allocating), every row of A a constant.
    // The stages' arguments share one state (a heap state: one allocation a step, not one a
    // stage), which ends as y₁: row 7 of A is b.
    let a = DOPRI5.a;
    let mut yi = y.clone();
    for (i, (row, ci)) in a.iter().zip(DOPRI5.c).enumerate().skip(1) {
        combine_into(&mut yi, y, h, row, k);
        eval_slot(f, t + ci * h, &yi, k, i, &mut work.fevals);
    }
    let y1 = yi;
    let k = &k[..7];
    // the local error estimate h Σ eᵢ kᵢ component by component (e₂ = 0: k₂ does not enter),
    // each sum in the order of the stage-by-stage form (the same bits), without its own state
    let (rtol, atol) = tol;
    let mut err = 0.0;
    let n = y.dim();
    let (ys, y1s) = (y.as_slice(), &y1.as_slice()[..n]);
    let ks = [&k[0], &k[2], &k[3], &k[4], &k[5], &k[6]].map(State::as_slice);
    if ks.iter().all(|kj| kj.len() == n) {
        for i in 0..n {
            let mut e = ks[0][i] * (h * DOPRI5_E[0]);
            for (ej, kj) in DOPRI5_E[2..].iter().zip(&ks[1..]) {
                e += (h * ej) * kj[i];
            }
            let sk = atol + rtol * ys[i].abs().max(y1s[i].abs());
            err += (e / sk).powi(2);
        }
    } else {
        // a stage of the wrong length: refused by the scan below
        err = f64::NAN;
    }
    Ok((y1, rms_checked(k, y, t, h, err)?))
}

/// The RMS error √(Σ/n) from the sum of squares `sum`, after the stages k₂..k₇ of `k` are known
/// to be finite and of y's length. Every stage but k₂ enters the estimate with a nonzero weight
/// (and y₁ its scale), so a non-finite stage makes it non-finite: the exact scan (which names
/// the stage) runs only then, or when k₂ or a stage's length is off (the length test folds away
/// for fixed-size states). A finite estimate that overflowed passes the scan and is rejected as
/// too large.
#[inline(always)]
fn rms_checked<S: State>(k: &[S], y: &S, t: f64, h: f64, sum: f64) -> Result<f64, OdeError> {
    let err = (sum / y.dim() as f64).sqrt();
    let dims_ok = k[1..].iter().all(|ki| ki.dim() == y.dim());
    let k2_finite = k[1].as_slice().iter().sum::<f64>().is_finite();
    if !(dims_ok && k2_finite && err.is_finite()) {
        check_stages(k, 1, t, h, DOPRI5.c)?;
    }
    Ok(err)
}

/// The dense output of an accepted step from k₁..k₇ (no extra evaluations).
///
/// Book: §4.11; HNW §II.6, `contd5` of `dopri5.f`.
pub(crate) fn dense<S: State>(t: f64, y: &S, y1: &S, h: f64, k: &[S]) -> DenseStep<S> {
    let [c0, c1, c2, c3] = hermite_part(y, y1, &k[0], &k[6], h);
    let c4 = weighted(y, h, &DOPRI5_D, k);
    DenseStep { t, h, c: vec![c0, c1, c2, c3, c4], form: Form::DormandPrince }
}
