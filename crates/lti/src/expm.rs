//! The matrix exponential by scaling and squaring with Padé approximants of degree 3–13
//! (Higham 2005), on faer matrices.
//!
//! Book: §15.5, (15.5.3); notes §3.1 (not the Taylor series of the definition and not an
//! eigendecomposition: defective matrices such as critical damping are common).

use crate::error::LtiError;
use faer::{Accum, Mat, MatMut, MatRef};
use nalgebra::DMatrix;

// Padé coefficients b_k of r_m (Higham 2005, Table 2.3 and (2.1)).
const B3: [f64; 4] = [120.0, 60.0, 12.0, 1.0];
const B5: [f64; 6] = [30240.0, 15120.0, 3360.0, 420.0, 30.0, 1.0];
const B7: [f64; 8] = [17297280.0, 8648640.0, 1995840.0, 277200.0, 25200.0, 1512.0, 56.0, 1.0];
const B9: [f64; 10] = [
    17643225600.0,
    8821612800.0,
    2075673600.0,
    302702400.0,
    30270240.0,
    2162160.0,
    110880.0,
    3960.0,
    90.0,
    1.0,
];
const B13: [f64; 14] = [
    64764752532480000.0,
    32382376266240000.0,
    7771770303897600.0,
    1187353796428800.0,
    129060195264000.0,
    10559470521600.0,
    670442572800.0,
    33522128640.0,
    1323241920.0,
    40840800.0,
    960960.0,
    16380.0,
    182.0,
    1.0,
];
// θ_m: largest ‖A‖₁ for which r_m has backward error ≤ u (Higham 2005, Table 2.3).
const THETA: [(usize, f64); 4] = [
    (3, 1.495585217958292e-2),
    (5, 2.539_398_330_063_23e-1),
    (7, 9.504178996162932e-1),
    (9, 2.097847961257068),
];
const THETA13: f64 = 5.371920351148152;

/// ‖A‖₁ of a column-major n×n slice.
fn norm1(a: &[f64], n: usize) -> f64 {
    a.chunks_exact(n).map(|c| c.iter().map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max)
}

/// dst ← αA·B (`Replace`) or dst ← dst + αA·B (`Add`), sequential below 2²⁴ multiply-adds.
fn mul_into(dst: MatMut<'_, f64>, acc: Accum, a: MatRef<'_, f64>, b: MatRef<'_, f64>, alpha: f64) {
    let par = par_for(a.nrows().max(a.ncols()).max(b.ncols()));
    faer::linalg::matmul::matmul(dst, acc, a, b, alpha, par);
}

vectrix_simd::dispatch! {
    /// Two linear combinations of the same three matrices in one pass (each matrix read once;
    /// column slices of an owned faer matrix are contiguous): d₁ ← Σ cₖMₖ + e₁I,
    /// d₂ ← Σ c'ₖMₖ + e₂I. Compiled for AVX2 (four lanes) when the CPU has it, detected at run
    /// time; the sums are plain multiplies and adds, so the results do not depend on the CPU.
    fn combine2(d1: &mut Mat<f64>, d2: &mut Mat<f64>, m: [&Mat<f64>; 3], c: [[f64; 3]; 2], e: [f64; 2]) =
        combine2_body;
}

/// The body of [`combine2`].
#[inline(always)]
fn combine2_body(d1: &mut Mat<f64>, d2: &mut Mat<f64>, m: [&Mat<f64>; 3], c: [[f64; 3]; 2], e: [f64; 2]) {
    for j in 0..d1.ncols() {
        let (x0, x1, x2) = (m[0].col_as_slice(j), m[1].col_as_slice(j), m[2].col_as_slice(j));
        let (o1, o2) = (d1.col_as_slice_mut(j), d2.col_as_slice_mut(j));
        let len = o1.len().min(o2.len()).min(x0.len()).min(x1.len()).min(x2.len());
        let (o1, o2, x0, x1, x2) = (&mut o1[..len], &mut o2[..len], &x0[..len], &x1[..len], &x2[..len]);
        for i in 0..len {
            o1[i] = c[0][0] * x0[i] + c[0][1] * x1[i] + c[0][2] * x2[i];
            o2[i] = c[1][0] * x0[i] + c[1][1] * x1[i] + c[1][2] * x2[i];
        }
        o1[j] += e[0];
        o2[j] += e[1];
    }
}

/// ‖A‖₁ without overflow: the norm of A/2^E and E (‖A‖₁ = 2^E·returned norm); E = 0 unless
/// the plain column sums overflow.
fn norm1_scaled(a: &[f64], n: usize) -> (f64, i32) {
    let plain = norm1(a, n);
    if plain.is_finite() {
        return (plain, 0);
    }
    let big = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let e = big.log2().floor() as i32;
    // 2^−E is a normal number here (E ≤ 1023)
    let f = crate::axis::pow2(-e);
    let nrm = a.chunks_exact(n).map(|c| c.iter().map(|x| x.abs() * f).sum::<f64>()).fold(0.0, f64::max);
    (nrm, e)
}

/// The parallelism of the products and factorisations: sequential below 2²⁴ multiply-adds,
/// where handing blocks to a thread pool costs more than it saves (faer's default hands every
/// block of a 100×100 solve to the pool: 143 µs instead of 76 µs with one pool thread).
fn par_for(n: usize) -> faer::Par {
    if n * n * n < 1 << 24 { faer::Par::Seq } else { faer::get_global_parallelism() }
}

thread_local! {
    /// Scratch matrices kept between calls on this thread (at most [`POOL_LEN`], each at most
    /// [`POOL_ENTRIES`] entries): the allocator returns freed 80 kB blocks to the kernel, and
    /// faulting them back in cost a third of a 100×100 exponential.
    static POOL: std::cell::RefCell<Vec<Mat<f64>>> = const { std::cell::RefCell::new(Vec::new()) };
}
const POOL_LEN: usize = 8;
const POOL_ENTRIES: usize = 256 * 256;

/// An n×n scratch matrix (contents unspecified: every caller overwrites it in full).
fn take(n: usize) -> Mat<f64> {
    let reused = POOL.with(|p| {
        let mut p = p.borrow_mut();
        let i = p.iter().position(|m| m.nrows() == n && m.ncols() == n)?;
        Some(p.swap_remove(i))
    });
    reused.unwrap_or_else(|| Mat::<f64>::zeros(n, n))
}

/// Returns scratch matrices to this thread's pool (small ones only; the oldest make room).
fn give<const K: usize>(ms: [Mat<f64>; K]) {
    POOL.with(|p| {
        let mut p = p.borrow_mut();
        for m in ms {
            if m.nrows() * m.ncols() <= POOL_ENTRIES {
                if p.len() == POOL_LEN {
                    p.remove(0);
                }
                p.push(m);
            }
        }
    });
}

/// Q⁻¹P by LU with partial pivoting, in place in Q and P.
fn lu_solve(q: &mut Mat<f64>, mut p: Mat<f64>) -> Mat<f64> {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::linalg::lu::partial_pivoting::{factor, solve};
    let n = q.nrows();
    let par = par_for(n);
    let (mut fwd, mut bwd) = (vec![0usize; n], vec![0usize; n]);
    let req = factor::lu_in_place_scratch::<usize, f64>(n, n, par, Default::default())
        .or(solve::solve_in_place_scratch::<usize, f64>(n, p.ncols(), par));
    let mut mem = MemBuffer::new(req);
    let (_, perm) =
        factor::lu_in_place(q.as_mut(), &mut fwd, &mut bwd, par, MemStack::new(&mut mem), Default::default());
    // the packed factors: L below the diagonal (unit diagonal implied), U on and above it
    solve::solve_in_place(q.as_ref(), q.as_ref(), perm, p.as_mut(), par, MemStack::new(&mut mem));
    p
}

/// e^A for a finite faer matrix.
///
/// # Errors
/// As [`expm_into`].
pub(crate) fn expm_faer(a: &Mat<f64>) -> Result<Mat<f64>, LtiError> {
    let n = a.nrows();
    let dense: Vec<f64> = (0..n).flat_map(|j| a.col_as_slice(j).iter().copied()).collect();
    let mut r = Mat::<f64>::zeros(n, n);
    expm_into(&dense, n, r.as_mut())?;
    if all_finite(&r) { Ok(r) } else { Err(LtiError::Overflow { what: "matrix exponential" }) }
}

/// out ← e^A for a finite n×n A given column-major (`out` n×n); the caller checks that `out`
/// is finite (an entry beyond the f64 range is an overflow, and a NaN can only come from one).
///
/// # Errors
/// [`LtiError::Overflow`] when a squaring on the way to the result overflows.
fn expm_into(a: &[f64], n: usize, mut out: MatMut<'_, f64>) -> Result<(), LtiError> {
    let (ns, e) = norm1_scaled(a, n);
    if e > 0 && ns * crate::axis::pow2(e.min(1023)) > THETA13 {
        // a norm that may overflow ‖A‖₁ itself: choose s from the exponents, A/2ˢ in two steps
        let s = (ns.log2() + e as f64 - THETA13.log2()).ceil().max(0.0) as i32;
        let a1: Vec<f64> = a.iter().map(|&x| crate::axis::mul_pow2(x, -s)).collect();
        let mut r = Mat::<f64>::zeros(n, n);
        expm_core(&a1, n, norm1(&a1, n), r.as_mut());
        let mut tmp = Mat::<f64>::zeros(n, n);
        let triangular = is_upper_triangular(a, n);
        for j in 0..s {
            mul_into(tmp.as_mut(), Accum::Replace, r.as_ref(), r.as_ref(), 1.0);
            std::mem::swap(&mut r, &mut tmp);
            if triangular {
                // r = e^{A/2^{s−j−1}}
                exact_triangular_band(r.as_mut(), a, n, s - j - 1);
            }
            if !all_finite(&r) {
                return Err(LtiError::Overflow { what: "matrix exponential" });
            }
        }
        out.copy_from(&r);
    } else {
        expm_core(a, n, ns, out.as_mut());
    }
    Ok(())
}

/// Every entry finite: |x| < ∞ folded without short-circuit (NaN fails it), so it vectorises.
fn finite(v: &[f64]) -> bool {
    v.iter().fold(true, |ok, x| ok & (x.abs() < f64::INFINITY))
}

/// [`finite`] over the columns of an owned matrix.
fn all_finite(m: &Mat<f64>) -> bool {
    (0..m.ncols()).all(|j| finite(m.col_as_slice(j)))
}

/// out ← e^A by Higham's algorithm for a matrix whose 1-norm is finite. A is read through a
/// view, the n×n buffers come from a per-thread pool, and the last squaring writes into `out`
/// (allocation churn, not arithmetic, dominated at n = 100).
fn expm_core(a_cols: &[f64], n: usize, nrm: f64, mut out: MatMut<'_, f64>) {
    let a = MatRef::from_column_major_slice(a_cols, n, n);
    let mut a2 = take(n);
    let (u, v, s) = if let Some(&(m, _)) = THETA.iter().find(|(_, t)| nrm <= *t) {
        mul_into(a2.as_mut(), Accum::Replace, a, a, 1.0);
        // r_m = (V − U)⁻¹(V + U) with U = A Σ b_{2k+1} A^{2k}, V = Σ b_{2k} A^{2k}.
        let b: &[f64] = match m {
            3 => &B3,
            5 => &B5,
            7 => &B7,
            _ => &B9,
        };
        let mut pow = Mat::<f64>::identity(n, n);
        let mut uo = Mat::<f64>::zeros(n, n);
        let mut ve = Mat::<f64>::zeros(n, n);
        for k in 0..=m / 2 {
            uo += faer::Scale(b[2 * k + 1]) * &pow;
            ve += faer::Scale(b[2 * k]) * &pow;
            if k < m / 2 {
                pow = &pow * &a2;
            }
        }
        (a * &uo, ve, 0)
    } else {
        // Scale so that ‖A/2ˢ‖₁ ≤ θ₁₃, then r₁₃ (Higham 2005, Algorithm 2.3)
        let s = (nrm / THETA13).log2().ceil().max(0.0) as i32;
        // A/2ˢ as a copy: scaling the products through α instead would form A·T before the
        // scaling, which overflows for ‖A‖ near 10³⁰⁰ ([[0, 10³⁰⁰], [0, 0]])
        let f = 0.5f64.powi(s);
        let mut a1 = take(n);
        for (j, col) in a_cols.chunks_exact(n).enumerate() {
            for (x, y) in a1.col_as_slice_mut(j).iter_mut().zip(col) {
                *x = f * y;
            }
        }
        let a1r = a1.as_ref();
        mul_into(a2.as_mut(), Accum::Replace, a1r, a1r, 1.0);
        let mut a4 = take(n);
        mul_into(a4.as_mut(), Accum::Replace, a2.as_ref(), a2.as_ref(), 1.0);
        let mut a6 = take(n);
        mul_into(a6.as_mut(), Accum::Replace, a4.as_ref(), a2.as_ref(), 1.0);
        let b = &B13;
        // U = A[A6(b13A6 + b11A4 + b9A2) + b7A6 + b5A4 + b3A2 + b1I]
        let (mut w, mut t) = (take(n), take(n));
        combine2(&mut w, &mut t, [&a6, &a4, &a2], [[b[13], b[11], b[9]], [b[7], b[5], b[3]]], [0.0, b[1]]);
        mul_into(t.as_mut(), Accum::Add, a6.as_ref(), w.as_ref(), 1.0);
        let mut u = take(n);
        mul_into(u.as_mut(), Accum::Replace, a1.as_ref(), t.as_ref(), 1.0);
        // V = A6(b12A6 + b10A4 + b8A2) + b6A6 + b4A4 + b2A2 + b0I
        let mut v = t;
        combine2(&mut w, &mut v, [&a6, &a4, &a2], [[b[12], b[10], b[8]], [b[6], b[4], b[2]]], [0.0, b[0]]);
        mul_into(v.as_mut(), Accum::Add, a6.as_ref(), w.as_ref(), 1.0);
        give([a1, a4, a6, w]);
        (u, v, s)
    };
    // p = v + u and q = v − u in place of v and u (no new matrices)
    let (mut p, mut q) = (v, u);
    for j in 0..n {
        for (pij, qij) in p.col_as_slice_mut(j).iter_mut().zip(q.col_as_slice_mut(j)) {
            (*pij, *qij) = (*pij + *qij, *pij - *qij);
        }
    }
    let mut r = lu_solve(&mut q, p);
    give([q]);
    let triangular = is_upper_triangular(a_cols, n);
    if triangular {
        // r = e^{A/2ˢ}
        exact_triangular_band(r.as_mut(), a_cols, n, s);
    }
    // s squarings between r and a2 (free now), the last one into `out`
    let mut tmp = a2;
    for j in 0..s {
        if j + 1 == s {
            mul_into(out.as_mut(), Accum::Replace, r.as_ref(), r.as_ref(), 1.0);
        } else {
            mul_into(tmp.as_mut(), Accum::Replace, r.as_ref(), r.as_ref(), 1.0);
            std::mem::swap(&mut r, &mut tmp);
        }
        if triangular {
            // e^{A/2^{s−j−1}}
            let dst = if j + 1 == s { out.as_mut() } else { r.as_mut() };
            exact_triangular_band(dst, a_cols, n, s - j - 1);
        }
    }
    if s == 0 {
        out.copy_from(&r);
    }
    give([r, tmp]);
}

/// True when every entry below the diagonal is 0.
fn is_upper_triangular(a: &[f64], n: usize) -> bool {
    a.chunks_exact(n).enumerate().all(|(j, c)| c[j + 1..].iter().all(|x| *x == 0.0))
}

/// For upper-triangular A: the diagonal and first superdiagonal of r = e^{A/2ᵏ} set to their
/// exact values (Al-Mohy & Higham 2009, Code Fragment 2.1): the squarings raise a diagonal
/// entry of 1 − ε to the power 2ˢ, which for [[0, 10³⁰⁰], [0, 0]] (s = 995) underflowed
/// e⁰ = 1 to 0.
fn exact_triangular_band(mut r: MatMut<'_, f64>, a_cols: &[f64], n: usize, k: i32) {
    let a = MatRef::from_column_major_slice(a_cols, n, n);
    let scaled = |x: f64| crate::axis::mul_pow2(x, -k);
    for i in 0..n {
        // (e^T)ᵢᵢ = e^{tᵢᵢ}
        r[(i, i)] = scaled(a[(i, i)]).exp();
    }
    for i in 0..n.saturating_sub(1) {
        let t = scaled(a[(i, i + 1)]);
        if t == 0.0 {
            r[(i, i + 1)] = 0.0;
            continue;
        }
        // (e^T)ᵢ,ᵢ₊₁ = tᵢ,ᵢ₊₁·e^{(λ₁+λ₂)/2}·sinh(z)/z with z = (λ₂ − λ₁)/2 (Higham 2008, (10.42))
        let (l1, l2) = (scaled(a[(i, i)]), scaled(a[(i + 1, i + 1)]));
        let z = 0.5 * (l2 - l1);
        let sinch = if z.abs() < 1e-4 { 1.0 + z * z / 6.0 } else { z.sinh() / z };
        r[(i, i + 1)] = t * (0.5 * l1 + 0.5 * l2).exp() * sinch;
    }
}

/// The matrix exponential e^A = Σ Aᵏ/k! by scaling and squaring with a [m/m] Padé
/// approximant, m ∈ {3, 5, 7, 9, 13} chosen from ‖A‖₁ (Higham 2005; Matlab and scipy `expm`).
///
/// Book: §15.5, (15.5.3); Ex 15.5.1–15.5.2; 15.20.27, 15.20.59.
///
/// # Errors
/// [`LtiError::NotSquare`] or [`LtiError::NonFinite`]; [`LtiError::Overflow`] when the result
/// exceeds the f64 range (`e^{[[1000]]}`), instead of ∞ or NaN entries.
pub fn expm(a: &DMatrix<f64>) -> Result<DMatrix<f64>, LtiError> {
    if a.nrows() != a.ncols() {
        return Err(LtiError::NotSquare { what: "expm argument", rows: a.nrows(), cols: a.ncols() });
    }
    if !finite(a.as_slice()) {
        return Err(LtiError::NonFinite { what: "expm argument" });
    }
    if a.nrows() == 0 {
        return Ok(a.clone());
    }
    let n = a.nrows();
    let mut out = DMatrix::<f64>::zeros(n, n);
    // nalgebra's column-major storage read and written in place: no copies in or out
    expm_into(a.as_slice(), n, MatMut::from_column_major_slice_mut(out.as_mut_slice(), n, n))?;
    if finite(out.as_slice()) { Ok(out) } else { Err(LtiError::Overflow { what: "matrix exponential" }) }
}

#[cfg(test)]
mod tests {
    /// e^{[[0, x], [0, 0]]} = [[1, x], [0, 1]] for a huge finite x: the scaling s ≈ 995 used to
    /// square a diagonal of 1 − ε to 0.
    #[test]
    fn nilpotent_with_a_huge_entry() {
        for x in [1e200, 1e300, -1e300, f64::MAX] {
            let e = super::expm(&nalgebra::DMatrix::from_row_slice(2, 2, &[0.0, x, 0.0, 0.0])).unwrap();
            assert_eq!(e.as_slice(), &[1.0, 0.0, x, 1.0], "x = {x:e}");
        }
    }
}
