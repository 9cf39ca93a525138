//! Vector-space states: anything whose components can be viewed as a slice of `f64`.

use crate::Rhs;
use nalgebra::{DVector, SVector};

use crate::OdeError;

/// A state of a vector space ℝⁿ, seen as a slice of components. Runge–Kutta methods only
/// form linear combinations y + hΣaⱼkⱼ, so this is all they need. Implemented for
/// `nalgebra::SVector<f64, N>` (stack, fastest), `DVector<f64>`, `[f64; N]`, `Vec<f64>` and
/// `f64`.
///
/// Book: §4.11 (state of the kinematic equations); HNW §II.1.
pub trait State: Clone {
    /// The components.
    fn as_slice(&self) -> &[f64];
    /// The components, mutably.
    fn as_mut_slice(&mut self) -> &mut [f64];
    /// Number of components n.
    fn dim(&self) -> usize {
        self.as_slice().len()
    }
    /// self ← self + a·x, the one kernel of every Runge–Kutta stage (overridden by
    /// fixed-size types so that it unrolls).
    #[inline(always)]
    fn add_scaled(&mut self, a: f64, x: &Self) {
        for (o, xi) in self.as_mut_slice().iter_mut().zip(x.as_slice()) {
            *o += a * xi;
        }
    }
}

impl<const N: usize> State for SVector<f64, N> {
    #[inline(always)]
    fn as_slice(&self) -> &[f64] {
        nalgebra::Matrix::as_slice(self)
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        nalgebra::Matrix::as_mut_slice(self)
    }
    #[inline(always)]
    fn add_scaled(&mut self, a: f64, x: &Self) {
        *self += x * a;
    }
}

impl State for DVector<f64> {
    #[inline(always)]
    fn as_slice(&self) -> &[f64] {
        nalgebra::Matrix::as_slice(self)
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        nalgebra::Matrix::as_mut_slice(self)
    }
}

impl<const N: usize> State for [f64; N] {
    #[inline(always)]
    fn as_slice(&self) -> &[f64] {
        self
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        self
    }
}

impl State for Vec<f64> {
    #[inline(always)]
    fn as_slice(&self) -> &[f64] {
        self
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        self
    }
}

impl State for f64 {
    #[inline(always)]
    fn as_slice(&self) -> &[f64] {
        core::slice::from_ref(self)
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        core::slice::from_mut(self)
    }
}

/// y + h Σⱼ cⱼ kⱼ. Zero coefficients are not skipped: the stages are finite (checked by
/// `eval`), and a multiply-add is cheaper than the branch that would skip it.
#[inline(always)]
pub(crate) fn combine<S: State>(y: &S, h: f64, c: &[f64], k: &[S]) -> S {
    let mut out = y.clone();
    combine_into(&mut out, y, h, c, k);
    out
}

/// [`combine`] into `out` (a state of the same dimension, overwritten), without a new state
/// per stage (heap states: one allocation a stage fewer). k holds at least the c.len() stages
/// already computed; slicing once gives the loops a trip count the compiler can see.
#[inline(always)]
pub(crate) fn combine_into<S: State>(out: &mut S, y: &S, h: f64, c: &[f64], k: &[S]) {
    let k = &k[..c.len()];
    combine_terms_into(out, y, h, || c.iter().copied().zip(k));
}

/// A row of a Butcher tableau without its zero entries, fixed at compile time: the terms
/// (stage j, aⱼ) with aⱼ ≠ 0, in the row's order. A zero term adds (±0)·kⱼ to a sum, which
/// leaves a finite sum's value unchanged (at most the sign of a zero sum), so skipping it gives
/// the same numbers and shortens each stage's chain of dependent additions.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Row<const M: usize> {
    idx: [usize; M],
    a: [f64; M],
    len: usize,
}

impl<const M: usize> Row<M> {
    /// The nonzero entries of `row` (at most M of them; more fail at compile time).
    pub(crate) const fn new(row: &[f64]) -> Self {
        let (mut idx, mut a, mut len, mut j) = ([0; M], [0.0; M], 0, 0);
        while j < row.len() {
            if row[j] != 0.0 {
                idx[len] = j;
                a[len] = row[j];
                len += 1;
            }
            j += 1;
        }
        Self { idx, a, len }
    }

    /// Every row of a stage matrix without its zeros.
    pub(crate) const fn table<const S: usize>(a: [&[f64]; S]) -> [Self; S] {
        let mut rows = [Self::new(&[]); S];
        let mut i = 0;
        while i < S {
            rows[i] = Self::new(a[i]);
            i += 1;
        }
        rows
    }

    /// The terms (stage j, aⱼ).
    #[inline(always)]
    pub(crate) fn terms(&self) -> impl Iterator<Item = (usize, f64)> + Clone + '_ {
        self.idx[..self.len].iter().copied().zip(self.a[..self.len].iter().copied())
    }
}

/// The stages j < S with bⱼ ≠ 0 or eⱼ ≠ 0 (a step's solution and its error estimate), in order,
/// and how many there are: the sums of a step skip the others (the same numbers, as [`Row`]).
pub(crate) const fn weighted_stages<const S: usize>(b: &[f64], e: &[f64]) -> ([usize; S], usize) {
    let (mut idx, mut len, mut j) = ([0; S], 0, 0);
    while j < S {
        if b[j] != 0.0 || e[j] != 0.0 {
            idx[len] = j;
            len += 1;
        }
        j += 1;
    }
    (idx, len)
}

/// [`combine_into`] over a sparse [`Row`]: y + h Σ aⱼ kⱼ over its nonzero terms (k holds every
/// stage the row names).
#[inline(always)]
pub(crate) fn combine_row_into<S: State, const M: usize>(out: &mut S, y: &S, h: f64, row: &Row<M>, k: &[S]) {
    combine_terms_into(out, y, h, || row.terms().map(|(j, a)| (a, &k[j])));
}

/// out = y + h Σ cⱼ kⱼ over the (cⱼ, kⱼ) that `terms` yields (each call the same terms).
#[inline(always)]
fn combine_terms_into<'k, S: State + 'k, I: Iterator<Item = (f64, &'k S)>>(
    out: &mut S,
    y: &S,
    h: f64,
    terms: impl Fn() -> I,
) {
    let o = out.as_mut_slice();
    let n = o.len();
    let y = &y.as_slice()[..n];
    // element by element, the stages inner: each component is ((y + a₁k₁) + a₂k₂) + …, the
    // sums of the stage-by-stage form in the same order (the same bits), without storing and
    // reloading the partial sums between stages
    if terms().all(|(_, kj)| kj.as_slice().len() == n) {
        // blocks of four components (one bounds check per block and stage, a loop the compiler
        // vectorises), then the tail one by one
        const W: usize = 4;
        let full = n - n % W;
        for (b, (ob, yb)) in o[..full].chunks_exact_mut(W).zip(y[..full].chunks_exact(W)).enumerate() {
            let mut acc = [yb[0], yb[1], yb[2], yb[3]];
            for (cj, kj) in terms() {
                let a = h * cj;
                let kb = &kj.as_slice()[W * b..W * b + W];
                for (x, ki) in acc.iter_mut().zip(kb) {
                    *x += a * ki;
                }
            }
            ob.copy_from_slice(&acc);
        }
        for e in full..n {
            let mut acc = y[e];
            for (cj, kj) in terms() {
                acc += (h * cj) * kj.as_slice()[e];
            }
            o[e] = acc;
        }
    } else {
        o.copy_from_slice(y);
        for (cj, kj) in terms() {
            out.add_scaled(h * cj, kj);
        }
    }
}

/// The first non-finite component, if any.
#[inline(always)]
pub(crate) fn first_non_finite<S: State>(y: &S) -> Option<(usize, f64)> {
    y.as_slice().iter().enumerate().find(|(_, v)| !v.is_finite()).map(|(i, v)| (i, *v))
}

/// `Err(NonFiniteState)` when the initial state has a non-finite component.
pub(crate) fn check_state<S: State>(t: f64, y: &S) -> Result<(), OdeError> {
    match first_non_finite(y) {
        Some((index, value)) => Err(OdeError::NonFiniteState { t, index, value }),
        None => Ok(()),
    }
}

/// Evaluates f and checks the result, saying where a non-finite value came from.
#[inline(always)]
pub(crate) fn eval<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    step_start: f64,
    stage: usize,
    fevals: &mut usize,
) -> Result<S, OdeError> {
    *fevals += 1;
    let k = f.call(t, y);
    check_rhs(&k, y, t, (step_start, stage))?;
    Ok(k)
}

/// `Ok` when f(t, y) = `k` has y's length and finite components; else the typed error naming
/// the stage (evaluated at t, in the step from `step_start`) and the first bad component.
#[inline(always)]
pub(crate) fn check_rhs<S: State>(
    k: &S,
    y: &S,
    t: f64,
    (step_start, stage): (f64, usize),
) -> Result<(), OdeError> {
    if k.dim() != y.dim() {
        return Err(OdeError::DimensionMismatch {
            what: "right-hand side f(t, y)",
            got: k.dim(),
            expected: y.dim(),
        });
    }
    match first_non_finite(k) {
        Some((index, value)) => Err(OdeError::RhsNotFinite { t, step_start, stage, index, value }),
        None => Ok(()),
    }
}

/// [`eval`] into `out` (a state of y's dimension, overwritten): an [`crate::InPlace`] right-hand
/// side writes there without allocating; `at` = (the step's start, the stage) for the error.
/// `out` is unspecified after an error.
#[inline(always)]
pub(crate) fn eval_into<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    out: &mut S,
    at: (f64, usize),
    fevals: &mut usize,
) -> Result<(), OdeError> {
    *fevals += 1;
    f.call_into(t, y, out);
    check_rhs(out, y, t, at)
}

/// Stage i of a step into `k[i]` when that slot exists (kept
/// from an earlier step: an [`crate::InPlace`] right-hand side reuses its buffer), else pushed
/// (`k` then holds exactly i stages). Unchecked, as [`eval_unchecked`].
#[inline(always)]
pub(crate) fn eval_slot<S: State, F: Rhs<S>>(
    f: &mut F,
    t: f64,
    y: &S,
    k: &mut Vec<S>,
    i: usize,
    fevals: &mut usize,
) {
    *fevals += 1;
    // a returning f: pushed (the caller truncated `k`), without the slot branch
    if !F::IN_PLACE {
        k.push(f.call(t, y));
        return;
    }
    match k.get_mut(i) {
        Some(ki) => f.call_into(t, y, ki),
        None => {
            debug_assert_eq!(k.len(), i);
            k.push(f.call(t, y));
        }
    }
}

/// Evaluates f without checking the result: the explicit pairs check all stages of a step at
/// once with [`check_stages`] (one branch per step instead of one per component and stage).
/// Later stages of a step may therefore see a non-finite argument before the step is refused.
#[inline(always)]
pub(crate) fn eval_unchecked<S: State, F: Rhs<S>>(f: &mut F, t: f64, y: &S, fevals: &mut usize) -> S {
    *fevals += 1;
    f.call(t, y)
}

/// `Err(RhsNotFinite)` naming the first non-finite stage among `k[first..]` (stage i evaluated
/// at t + cᵢh), else `Ok`. A sum is finite only if every term is, so one sum decides; a finite
/// sum that overflowed falls through to the exact scan, which then finds nothing.
#[inline(always)]
pub(crate) fn check_stages<S: State>(
    k: &[S],
    first: usize,
    t: f64,
    h: f64,
    c: &[f64],
) -> Result<(), OdeError> {
    // Every stage has the length of k₁ (checked against y by `eval`); a right-hand side that
    // returns another length is refused instead of being silently truncated by the zip in
    // `add_scaled` (a constant comparison for fixed-size states).
    let n = k[0].dim();
    if let Some(bad) = k[first..].iter().find(|ki| ki.dim() != n) {
        return Err(OdeError::DimensionMismatch {
            what: "right-hand side f(t, y)",
            got: bad.dim(),
            expected: n,
        });
    }
    // one sum of every component of every stage: finite unless some component is not (or the
    // sum overflows, which the scan below tells apart); no state allocated
    let sum: f64 = k[first..].iter().map(|ki| ki.as_slice().iter().sum::<f64>()).sum();
    if sum.is_finite() {
        return Ok(());
    }
    for (i, ki) in k.iter().enumerate().skip(first) {
        if let Some((index, value)) = first_non_finite(ki) {
            return Err(OdeError::RhsNotFinite {
                t: t + c[i] * h,
                step_start: t,
                stage: i + 1,
                index,
                value,
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{Row, combine_into, combine_row_into};
    use proptest::prelude::*;

    /// A row with zeros, as DOP853's: a₂ = a₃ = 0.
    const DENSE: [f64; 6] = [0.037, 0.0, 0.0, 0.17, 0.06, -0.0176];

    proptest! {
        /// Skipping a row's zero terms gives the same bits as the full sum (finite stages):
        /// every state size (blocks of four and the tail), any step's sign.
        #[test]
        fn sparse_row_gives_the_bits_of_the_full_row(
            n in 1usize..11,
            h in prop_oneof![-1.0f64..1.0, Just(1e-300), Just(-1e300)],
            seed in prop::collection::vec(-1e3f64..1e3, 7 * 11),
        ) {
            let y: Vec<f64> = seed[..n].to_vec();
            let k: Vec<Vec<f64>> = (0..6).map(|j| seed[(j + 1) * 11..(j + 1) * 11 + n].to_vec()).collect();
            let row: Row<6> = Row::new(&DENSE);
            prop_assert_eq!(row.terms().count(), 4);
            let (mut full, mut sparse) = (vec![0.0; n], vec![0.0; n]);
            combine_into(&mut full, &y, h, &DENSE, &k);
            combine_row_into(&mut sparse, &y, h, &row, &k);
            for (a, b) in full.iter().zip(&sparse) {
                // the same value; a zero sum may differ in its sign alone
                prop_assert!(a == b && (a.to_bits() == b.to_bits() || *a == 0.0), "{a:e} vs {b:e}");
            }
        }
    }
}
