//! The matrix exponential by scaling and squaring with Padé approximants of degree 3–13
//! (Higham 2005), on faer matrices.
//!
//! Book: §15.5, (15.5.3); notes §3.1 (not the Taylor series of the definition and not an
//! eigendecomposition: defective matrices such as critical damping are common).

use crate::error::{LtiError, check_finite};
use crate::linalg::{from_faer, to_faer};
use faer::{Accum, Mat};
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

fn norm1(a: &Mat<f64>) -> f64 {
    (0..a.ncols()).map(|j| (0..a.nrows()).map(|i| a[(i, j)].abs()).sum::<f64>()).fold(0.0, f64::max)
}

/// dst ← A·B (`Replace`) or dst ← dst + A·B (`Add`), with faer's global parallelism (as its `*`).
fn mul_into(dst: &mut Mat<f64>, acc: Accum, a: &Mat<f64>, b: &Mat<f64>) {
    faer::linalg::matmul::matmul(
        dst.as_mut(),
        acc,
        a.as_ref(),
        b.as_ref(),
        1.0,
        par_for(a.nrows().max(a.ncols()).max(b.ncols())),
    );
}

/// m ← c·m.
fn scale_in_place(m: &mut Mat<f64>, c: f64) {
    for j in 0..m.ncols() {
        for x in m.col_as_slice_mut(j) {
            *x *= c;
        }
    }
}

/// Two linear combinations of the same three matrices in one pass (each matrix read once;
/// column slices of an owned faer matrix are contiguous): d₁ ← Σ cₖMₖ + e₁I,
/// d₂ ← Σ c'ₖMₖ + e₂I.
fn combine2(d1: &mut Mat<f64>, d2: &mut Mat<f64>, m: [&Mat<f64>; 3], c: [[f64; 3]; 2], e: [f64; 2]) {
    for j in 0..d1.ncols() {
        let (x0, x1, x2) = (m[0].col_as_slice(j), m[1].col_as_slice(j), m[2].col_as_slice(j));
        let (o1, o2) = (d1.col_as_slice_mut(j), d2.col_as_slice_mut(j));
        for ((((p, q), a), b), cc) in o1.iter_mut().zip(o2.iter_mut()).zip(x0).zip(x1).zip(x2) {
            *p = c[0][0] * a + c[0][1] * b + c[0][2] * cc;
            *q = c[1][0] * a + c[1][1] * b + c[1][2] * cc;
        }
        o1[j] += e[0];
        o2[j] += e[1];
    }
}

/// ‖A‖₁ without overflow: the norm of A/2^E and E (‖A‖₁ = 2^E·returned norm); E = 0 unless
/// the plain column sums overflow.
fn norm1_scaled(a: &Mat<f64>) -> (f64, i32) {
    let plain = norm1(a);
    if plain.is_finite() {
        return (plain, 0);
    }
    let big = (0..a.ncols()).flat_map(|j| a.col_as_slice(j).iter()).fold(0.0f64, |m, x| m.max(x.abs()));
    let e = big.log2().floor() as i32;
    // 2^−E is a normal number here (E ≤ 1023)
    let f = crate::axis::pow2(-e);
    let nrm = (0..a.ncols())
        .map(|j| a.col_as_slice(j).iter().map(|x| x.abs() * f).sum::<f64>())
        .fold(0.0, f64::max);
    (nrm, e)
}

/// The parallelism of the products and factorisations: sequential below 2²⁴ multiply-adds,
/// where handing blocks to a thread pool costs more than it saves (faer's default hands every
/// block of a 100×100 solve to the pool: 143 µs instead of 76 µs with one pool thread).
fn par_for(n: usize) -> faer::Par {
    if n * n * n < 1 << 24 { faer::Par::Seq } else { faer::get_global_parallelism() }
}

/// Q⁻¹P by LU with partial pivoting, in place in Q and P.
fn lu_solve(mut q: Mat<f64>, mut p: Mat<f64>) -> Mat<f64> {
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
/// [`LtiError::Overflow`] when an entry of the result (or of a squaring on the way to it)
/// exceeds the f64 range; a NaN can only come from such an overflow.
pub(crate) fn expm_faer(a: &Mat<f64>) -> Result<Mat<f64>, LtiError> {
    let (ns, e) = norm1_scaled(a);
    let r = if e > 0 && ns * crate::axis::pow2(e.min(1023)) > THETA13 {
        // a norm that may overflow ‖A‖₁ itself: choose s from the exponents, A/2ˢ in two steps
        let s = (ns.log2() + e as f64 - THETA13.log2()).ceil().max(0.0) as i32;
        let mut a1 = a.clone();
        for j in 0..a1.ncols() {
            for x in a1.col_as_slice_mut(j) {
                *x = crate::poly::mul_pow2(*x, -s);
            }
        }
        let mut r = expm_small(&a1);
        let n = r.nrows();
        let mut tmp = Mat::<f64>::zeros(n, n);
        let triangular = is_upper_triangular(a);
        for j in 0..s {
            mul_into(&mut tmp, Accum::Replace, &r, &r);
            std::mem::swap(&mut r, &mut tmp);
            if triangular {
                // r = e^{A/2^{s−j−1}}
                exact_triangular_band(&mut r, a, s - j - 1);
            }
            if !all_finite(&r) {
                return Err(LtiError::Overflow { what: "matrix exponential" });
            }
        }
        r
    } else {
        expm_core(a)
    };
    if all_finite(&r) { Ok(r) } else { Err(LtiError::Overflow { what: "matrix exponential" }) }
}

fn all_finite(m: &Mat<f64>) -> bool {
    (0..m.ncols()).all(|j| m.col_as_slice(j).iter().all(|x| x.is_finite()))
}

/// r₁₃(A) for ‖A‖₁ ≤ θ₁₃ (no squaring).
fn expm_small(a: &Mat<f64>) -> Mat<f64> {
    expm_core(a)
}

/// e^A by Higham's algorithm for a matrix whose 1-norm is finite.
fn expm_core(a: &Mat<f64>) -> Mat<f64> {
    let n = a.nrows();
    let id = Mat::<f64>::identity(n, n);
    let nrm = norm1(a);
    let mut a2 = Mat::<f64>::zeros(n, n);
    mul_into(&mut a2, Accum::Replace, a, a);
    let (u, v, s) = if let Some(&(m, _)) = THETA.iter().find(|(_, t)| nrm <= *t) {
        // r_m = (V − U)⁻¹(V + U) with U = A Σ b_{2k+1} A^{2k}, V = Σ b_{2k} A^{2k}.
        let b: &[f64] = match m {
            3 => &B3,
            5 => &B5,
            7 => &B7,
            _ => &B9,
        };
        let mut pow = id.clone();
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
        // Scale so that ‖A/2ˢ‖₁ ≤ θ₁₃, then r₁₃ (Higham 2005, Algorithm 2.3), with six
        // n×n buffers in all (allocation churn, not arithmetic, dominated at n = 100)
        let s = (nrm / THETA13).log2().ceil().max(0.0) as i32;
        let f = 0.5f64.powi(s);
        let mut a1 = a.clone();
        scale_in_place(&mut a1, f);
        scale_in_place(&mut a2, f * f);
        let mut a4 = Mat::<f64>::zeros(n, n);
        mul_into(&mut a4, Accum::Replace, &a2, &a2);
        let mut a6 = Mat::<f64>::zeros(n, n);
        mul_into(&mut a6, Accum::Replace, &a4, &a2);
        let b = &B13;
        // U = A[A6(b13A6 + b11A4 + b9A2) + b7A6 + b5A4 + b3A2 + b1I]
        let mut w = Mat::<f64>::zeros(n, n);
        let mut t = Mat::<f64>::zeros(n, n);
        combine2(&mut w, &mut t, [&a6, &a4, &a2], [[b[13], b[11], b[9]], [b[7], b[5], b[3]]], [0.0, b[1]]);
        mul_into(&mut t, Accum::Add, &a6, &w);
        let mut u = Mat::<f64>::zeros(n, n);
        mul_into(&mut u, Accum::Replace, &a1, &t);
        // V = A6(b12A6 + b10A4 + b8A2) + b6A6 + b4A4 + b2A2 + b0I
        let mut v = t;
        combine2(&mut w, &mut v, [&a6, &a4, &a2], [[b[12], b[10], b[8]], [b[6], b[4], b[2]]], [0.0, b[0]]);
        mul_into(&mut v, Accum::Add, &a6, &w);
        (u, v, s)
    };
    // p = v + u and q = v − u in place of v and u (no new matrices)
    let (mut p, mut q) = (v, u);
    for j in 0..n {
        for (pij, qij) in p.col_as_slice_mut(j).iter_mut().zip(q.col_as_slice_mut(j)) {
            (*pij, *qij) = (*pij + *qij, *pij - *qij);
        }
    }
    let mut r = lu_solve(q, p);
    let triangular = is_upper_triangular(a);
    if triangular {
        // r = e^{A/2ˢ}
        exact_triangular_band(&mut r, a, s);
    }
    // s squarings between two buffers
    let mut tmp = Mat::<f64>::zeros(n, n);
    for j in 0..s {
        mul_into(&mut tmp, Accum::Replace, &r, &r);
        std::mem::swap(&mut r, &mut tmp);
        if triangular {
            // r = e^{A/2^{s−j−1}}
            exact_triangular_band(&mut r, a, s - j - 1);
        }
    }
    r
}

/// True when every entry below the diagonal is 0.
fn is_upper_triangular(a: &Mat<f64>) -> bool {
    (0..a.ncols()).all(|j| a.col_as_slice(j)[j + 1..].iter().all(|x| *x == 0.0))
}

/// For upper-triangular A: the diagonal and first superdiagonal of r = e^{A/2ᵏ} set to their
/// exact values (Al-Mohy & Higham 2009, Code Fragment 2.1): the squarings raise a diagonal
/// entry of 1 − ε to the power 2ˢ, which for [[0, 10³⁰⁰], [0, 0]] (s = 995) underflowed
/// e⁰ = 1 to 0.
fn exact_triangular_band(r: &mut Mat<f64>, a: &Mat<f64>, k: i32) {
    let n = a.nrows();
    let scaled = |x: f64| crate::poly::mul_pow2(x, -k);
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
    check_finite("expm argument", a.iter())?;
    if a.nrows() == 0 {
        return Ok(a.clone());
    }
    Ok(from_faer(expm_faer(&to_faer(a))?.as_ref()))
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
