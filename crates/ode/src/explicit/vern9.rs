//! One step of Verner's 9(8) pair (Vern9) with its error estimate.

use super::vern9_coefficients::{A, B, C, E};
use crate::Rhs;
use crate::state::{Row, State, check_stages, combine_row_into, eval_slot, weighted_stages};
use crate::{OdeError, Work};

/// The rows of [`A`] without their zeros (42 of the 120 entries: stages 2–5 enter only the
/// rows up to 7, stages 14 and 15 no row but the 15th's).
const ROWS: [Row<14>; 16] = Row::table(A);

/// The stages with a nonzero weight in y₁ (b) or in the estimate (e): 1 and 8–16.
const BE_STAGES: ([usize; 16], usize) = weighted_stages(&B, &E);

/// Stages 2..=16 from k₁ = `k[0]` into `k[1..16]` (k holds at least k₁); returns the
/// 9th-order y₁ = y + h Σ bᵢkᵢ and the scaled norm of the estimate h Σ eᵢkᵢ (the difference
/// of the 9th- and 8th-order solutions), err = √(Σ (h eᵢ·k / skᵢ)² / n) with
/// sk = atol + rtol·max(|y|, |y₁|) (HNW (4.10–4.11)).
///
/// Book: §4.11; HNW §II.4; Verner, Numer. Algorithms 53 (2010).
pub(crate) fn step<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    h: f64,
    k: &mut Vec<S>,
    tol: (f64, f64),
    work: &mut Work,
) -> Result<(S, f64), OdeError> {
    // kᵢ = f(t + cᵢh, y + h Σ aᵢⱼ kⱼ), unrolled so that every row is a constant (as DOP853's)
    if !F::IN_PLACE {
        k.truncate(1);
    }
    let mut yi = y.clone();
    macro_rules! stages {
        ($($i:literal)*) => {$(
            combine_row_into(&mut yi, y, h, &ROWS[$i], k);
            eval_slot(f, t + C[$i] * h, &yi, k, $i, &mut work.fevals);
        )*};
    }
    stages!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15);
    check_stages(&k[..16], 1, t, h, &C)?;
    let mut y1 = if F::IN_PLACE {
        yi.clone_from(y);
        yi
    } else {
        y.clone()
    };
    let mut err = 0.0;
    let (ys, n) = (y.as_slice(), y.dim());
    let k = &k[..16];
    debug_assert!(k.iter().all(|kj| kj.dim() == n));
    // blocks of four components, then the tail one by one (as DOP853's sums)
    const W: usize = 4;
    let full = n - n % W;
    let y1s = y1.as_mut_slice();
    for base in (0..full).step_by(W) {
        sums::<S, W>(k, base, &ys[base..base + W], &mut y1s[base..base + W], h, tol, &mut err);
    }
    for base in full..n {
        sums::<S, 1>(k, base, &ys[base..=base], &mut y1s[base..=base], h, tol, &mut err);
    }
    Ok((y1, (err / n as f64).sqrt()))
}

/// Components base..base + W of y₁ = y + h Σ bᵢkᵢ and of the estimate h Σ eᵢkᵢ, whose squared
/// scaled values are added to `err` component after component.
#[inline(always)]
fn sums<S: State, const W: usize>(
    k: &[S],
    base: usize,
    y: &[f64],
    y1: &mut [f64],
    h: f64,
    (rtol, atol): (f64, f64),
    err: &mut f64,
) {
    let (mut b, mut e) = ([0.0; W], [0.0; W]);
    for &j in &BE_STAGES.0[..BE_STAGES.1] {
        let kj = &k[j].as_slice()[base..base + W];
        for c in 0..W {
            b[c] += B[j] * kj[c];
            e[c] += E[j] * kj[c];
        }
    }
    for c in 0..W {
        y1[c] += h * b[c];
        let sk = atol + rtol * y[c].abs().max(y1[c].abs());
        *err += (h * e[c] / sk).powi(2);
    }
}

#[cfg(test)]
mod tests {
    use super::{A, B, C, E};

    /// The doubles keep what scripts/vern9_coefficients.py checked exactly: row sums cᵢ = Σⱼ aᵢⱼ
    /// and the quadrature conditions Σ bᵢcᵢᵏ = 1/(k + 1) for k ≤ 8 (9th order) and
    /// Σ b̂ᵢcᵢᵏ = 1/(k + 1) for k ≤ 7 with b̂ = b − e (8th order), each to a few ulps of its terms
    /// (|aᵢⱼ| reaches 7e2 in the rows of stages 12–16, so their sums carry ~1e-13 of rounding),
    /// and b̂ fails k = 8: the estimate is of order 9 − 8.
    #[test]
    fn vern9_doubles_keep_the_row_sums_and_the_quadrature_conditions() {
        for (i, row) in A.iter().enumerate() {
            let scale: f64 = row.iter().map(|a| a.abs()).sum::<f64>().max(1.0);
            let sum: f64 = row.iter().sum();
            assert!((sum - C[i]).abs() <= 8.0 * f64::EPSILON * scale, "row {i}: {sum} against c = {}", C[i]);
        }
        let quad = |w: &dyn Fn(usize) -> f64, k: i32| -> (f64, f64) {
            let terms = (0..16).map(|i| w(i) * C[i].powi(k));
            (terms.clone().sum::<f64>(), terms.map(f64::abs).sum::<f64>())
        };
        for k in 0..=8 {
            let (s, scale) = quad(&|i| B[i], k);
            let exact = 1.0 / f64::from(k + 1);
            assert!((s - exact).abs() <= 16.0 * f64::EPSILON * scale, "b, k = {k}: {s} against {exact}");
            let (s, scale) = quad(&|i| B[i] - E[i], k);
            let miss = (s - exact).abs();
            if k <= 7 {
                assert!(miss <= 16.0 * f64::EPSILON * scale, "b̂, k = {k}: {s} against {exact}");
            } else {
                assert!(miss > 1e-6, "b̂ satisfies k = 8 ({miss:e}): not an 8th-order estimate");
            }
        }
    }
}
