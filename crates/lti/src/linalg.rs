//! Dense kernels on nalgebra matrices: eigenvalues by the in-crate Hessenberg QR for small
//! matrices (faer above 64×64), SVD by faer.
//!
//! Book: §15.3 (eigenvalues), §15.20.2 (`eig`).

use crate::error::LtiError;
use nalgebra::DMatrix;
use num_complex::Complex64;

/// Copies a nalgebra matrix into a faer matrix.
pub(crate) fn to_faer(a: &DMatrix<f64>) -> faer::Mat<f64> {
    faer::Mat::from_fn(a.nrows(), a.ncols(), |i, j| a[(i, j)])
}

/// Copies a faer matrix into a nalgebra matrix.
pub(crate) fn from_faer(a: faer::MatRef<'_, f64>) -> DMatrix<f64> {
    DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[(i, j)])
}

/// Exponents kᵢ of the Parlett–Reinsch balancing D = diag(2^{kᵢ}) of a finite square matrix:
/// D⁻¹AD has rows and columns of comparable 1-norm (off the diagonal), and its eigenvalues are
/// those of A exactly (a power-of-two similarity rounds nothing).
///
/// The sums are formed on A/2^E with 2^E ≈ max|aᵢⱼ| (so a matrix of entries near 10³⁰⁸ cannot
/// overflow them), each scaling is computed from the exponents of the row and column sums
/// instead of by repeated doubling, the cumulative scaling keeps every entry in
/// [2⁻⁹⁰⁰, 2⁹⁰⁰] of the largest, and at most 100 sweeps are made: the loop is bounded (an
/// earlier version looped forever on entries of 10³⁰⁸, whose sums were infinite).
pub(crate) fn balance_exponents(a: &DMatrix<f64>) -> Vec<i32> {
    let n = a.nrows();
    let mut k = vec![0i32; n];
    let big = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if n < 2 || big == 0.0 || !big.is_finite() {
        return k;
    }
    let e = big.log2().floor() as i32;
    let mut b = a.map(|x| crate::axis::mul_pow2(x, -e));
    const LIMIT: i32 = 900;
    for _sweep in 0..100 {
        let mut changed = false;
        for i in 0..n {
            let (mut c, mut r, mut cmax, mut rmax) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
            for j in 0..n {
                if j != i {
                    c += b[(j, i)].abs();
                    r += b[(i, j)].abs();
                    cmax = cmax.max(b[(j, i)].abs());
                    rmax = rmax.max(b[(i, j)].abs());
                }
            }
            if c == 0.0 || r == 0.0 || !(c.is_finite() && r.is_finite()) {
                continue;
            }
            // f = 2^s with c·f ≈ r/f: s = round(½ log₂(r/c))
            let mut s = (0.5 * (r.log2() - c.log2())).round() as i32;
            // keep the scaled row and column inside [2^−LIMIT, 2^LIMIT]
            s = s.min(LIMIT - cmax.log2().ceil() as i32).max(rmax.log2().floor() as i32 - LIMIT);
            if s == 0 {
                continue;
            }
            let f = crate::axis::pow2(s);
            if c * f + r / f < 0.95 * (c + r) {
                changed = true;
                k[i] += s;
                for j in 0..n {
                    b[(i, j)] = crate::axis::mul_pow2(b[(i, j)], -s);
                    b[(j, i)] = crate::axis::mul_pow2(b[(j, i)], s);
                }
            }
        }
        if !changed {
            break;
        }
    }
    k
}

/// Parlett–Reinsch balancing by powers of 2: D⁻¹AD with rows and columns of comparable norm
/// (eigenvalues unchanged, exactly, since the scaling is by powers of 2).
///
/// # Errors
/// [`LtiError::NotSquare`], [`LtiError::NonFinite`]; [`LtiError::Overflow`] when an entry of
/// D⁻¹AD exceeds the f64 range.
pub fn balance(a: &DMatrix<f64>) -> Result<DMatrix<f64>, LtiError> {
    if a.nrows() != a.ncols() {
        return Err(LtiError::NotSquare { what: "balance argument", rows: a.nrows(), cols: a.ncols() });
    }
    crate::error::check_finite("balance argument", a.iter())?;
    let k = balance_exponents(a);
    let b = DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| crate::axis::mul_pow2(a[(i, j)], k[j] - k[i]));
    if b.iter().all(|x| x.is_finite()) { Ok(b) } else { Err(LtiError::Overflow { what: "balanced matrix" }) }
}

/// Eigenvalues of a real square matrix (balanced first), as complex numbers; real eigenvalues
/// have an exactly zero imaginary part and complex ones come in exact conjugate pairs.
///
/// The matrix is divided by a power of two near its largest entry first (exact; the
/// eigenvalues scale with it), so entries anywhere in the f64 range are handled.
///
/// Book: §15.3, (15.3.5); Matlab `eig` in 15.20.2.
///
/// # Errors
/// [`LtiError::NotSquare`], [`LtiError::NonFinite`], [`LtiError::NoConvergence`], or
/// [`LtiError::Overflow`] when an eigenvalue exceeds the f64 range ([[1e308, 1e308],
/// [1e308, 1e308]] has the eigenvalue 2e308).
pub fn eigenvalues(a: &DMatrix<f64>) -> Result<Vec<Complex64>, LtiError> {
    if a.nrows() != a.ncols() {
        return Err(LtiError::NotSquare { what: "A", rows: a.nrows(), cols: a.ncols() });
    }
    crate::error::check_finite("A", a.iter())?;
    if a.nrows() == 0 {
        return Ok(Vec::new());
    }
    eigenvalues_balanced(a, false)
}

/// Largest n handled by the in-crate Hessenberg QR ([`crate::hqr`]); larger matrices go to
/// faer's blocked eigensolver.
const SMALL: usize = 64;

/// Eigenvalues of an upper Hessenberg matrix (a companion matrix (15.7.3)): as
/// [`eigenvalues`], without the reduction to Hessenberg form. The caller guarantees the shape.
pub(crate) fn eigenvalues_hessenberg(a: &DMatrix<f64>) -> Result<Vec<Complex64>, LtiError> {
    eigenvalues_balanced(a, true)
}

fn eigenvalues_balanced(a: &DMatrix<f64>, hessenberg: bool) -> Result<Vec<Complex64>, LtiError> {
    // A/2^E (exact), then the balancing similarity (exact; it keeps the Hessenberg shape)
    let big = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if big == 0.0 {
        return Ok(vec![Complex64::new(0.0, 0.0); a.nrows()]);
    }
    let e = big.log2().floor() as i32;
    let scaled = a.map(|x| crate::axis::mul_pow2(x, -e));
    let k = balance_exponents(&scaled);
    let n = scaled.nrows();
    let b = DMatrix::from_fn(n, n, |i, j| crate::axis::mul_pow2(scaled[(i, j)], k[j] - k[i]));
    let small = (n <= SMALL)
        .then(|| {
            let mut w = crate::hqr::Work::from_fn(n, |i, j| b[(i, j)]);
            if !hessenberg {
                w.hessenberg();
            }
            w.hqr()
        })
        .flatten()
        .filter(|ev| ev.iter().all(|z| z.re.is_finite() && z.im.is_finite()));
    let ev = match small {
        Some(ev) => ev,
        // larger, or the 30-iteration limit was hit: faer's blocked multishift QR
        None => to_faer(&b).eigenvalues().map_err(|_| LtiError::NoConvergence { what: "eigenvalues" })?,
    };
    if ev.iter().any(|z| !(z.re.is_finite() && z.im.is_finite())) {
        return Err(LtiError::NoConvergence { what: "eigenvalues" });
    }
    // the tidying threshold is relative to the balanced matrix: [[−3, −10³⁰⁰], [1, 0]] has
    // eigenvalues −1.5 ± 10¹⁵⁰j, far below its largest entry but not below its balanced norm
    let scale = b.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(f64::MIN_POSITIVE);
    let ev: Vec<Complex64> = tidy_conjugates(ev, scale)
        .into_iter()
        .map(|z| Complex64::new(crate::axis::mul_pow2(z.re, e), crate::axis::mul_pow2(z.im, e)))
        .collect();
    if ev.iter().all(|z| z.re.is_finite() && z.im.is_finite()) {
        Ok(ev)
    } else {
        Err(LtiError::Overflow { what: "eigenvalues" })
    }
}

/// Makes real roots exactly real and complex roots exact conjugate pairs; sorts them by
/// decreasing real part, then decreasing imaginary part (deterministic order).
pub(crate) fn tidy_conjugates(mut v: Vec<Complex64>, scale: f64) -> Vec<Complex64> {
    let tiny = 64.0 * f64::EPSILON;
    for z in v.iter_mut() {
        if z.im.abs() <= tiny * z.norm().max(tiny * scale) {
            z.im = 0.0;
        }
    }
    // Pair each root of positive imaginary part with the nearest one of negative imaginary part.
    let mut used = vec![false; v.len()];
    let mut out = Vec::with_capacity(v.len());
    for i in 0..v.len() {
        if used[i] {
            continue;
        }
        used[i] = true;
        if v[i].im == 0.0 {
            out.push(v[i]);
            continue;
        }
        let target = v[i].conj();
        let partner = (0..v.len())
            .filter(|&j| !used[j] && v[j].im != 0.0 && v[j].im.signum() != v[i].im.signum())
            .min_by(|&j, &k| (v[j] - target).norm_sqr().total_cmp(&(v[k] - target).norm_sqr()));
        match partner {
            Some(j) => {
                used[j] = true;
                let re = 0.5 * (v[i].re + v[j].re);
                let im = 0.5 * (v[i].im.abs() + v[j].im.abs());
                out.push(Complex64::new(re, im));
                out.push(Complex64::new(re, -im));
            }
            None => out.push(v[i]),
        }
    }
    out.sort_by(|a, b| b.re.total_cmp(&a.re).then(b.im.total_cmp(&a.im)));
    out
}

/// Singular values of a real matrix, largest first.
///
/// # Errors
/// [`LtiError::NonFinite`] for a NaN or infinite entry; [`LtiError::NoConvergence`] if the SVD
/// fails; [`LtiError::Overflow`] when the largest singular value exceeds the f64 range.
pub fn singular_values(a: &DMatrix<f64>) -> Result<Vec<f64>, LtiError> {
    if a.nrows() == 0 || a.ncols() == 0 {
        return Ok(Vec::new());
    }
    crate::error::check_finite("SVD argument", a.iter())?;
    // A/2^E (exact): the singular values scale with it, and nothing overflows inside
    let big = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if big == 0.0 {
        return Ok(vec![0.0; a.nrows().min(a.ncols())]);
    }
    // a diagonal matrix: σᵢ = |aᵢᵢ| exactly (scaled by 2^−E, an entry of 1 beside f64::MAX
    // became subnormal and the SVD dropped it)
    let is_diag = (0..a.nrows()).all(|i| (0..a.ncols()).all(|j| i == j || a[(i, j)] == 0.0));
    if is_diag {
        let mut s: Vec<f64> = (0..a.nrows().min(a.ncols())).map(|i| a[(i, i)].abs()).collect();
        s.sort_by(|x, y| y.total_cmp(x));
        return Ok(s);
    }
    let e = big.log2().floor() as i32;
    let scaled = to_faer(&a.map(|x| crate::axis::mul_pow2(x, -e)));
    let mut s = scaled.singular_values().map_err(|_| LtiError::NoConvergence { what: "SVD" })?;
    for x in s.iter_mut() {
        *x = crate::axis::mul_pow2(*x, e);
    }
    if s.iter().any(|x| !x.is_finite()) {
        return Err(LtiError::Overflow { what: "singular values" });
    }
    s.sort_by(|x, y| y.total_cmp(x));
    Ok(s)
}

/// Numerical rank: the number of singular values above `rtol·σ_max` (and above zero).
///
/// # Errors
/// [`LtiError::InvalidArgument`] unless `rtol` is finite and ≥ 0; [`LtiError::NoConvergence`]
/// if the SVD fails.
pub fn rank(a: &DMatrix<f64>, rtol: f64) -> Result<usize, LtiError> {
    crate::error::check_tolerance("rank tolerance", rtol)?;
    let s = singular_values(a)?;
    let top = s.first().copied().unwrap_or(0.0);
    Ok(s.iter().filter(|&&x| x > rtol * top && x > 0.0).count())
}
