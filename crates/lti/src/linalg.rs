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

/// Parlett–Reinsch balancing by powers of 2: returns D⁻¹AD with rows and columns of
/// comparable norm (eigenvalues unchanged, exactly, since the scaling is by powers of 2).
pub fn balance(a: &DMatrix<f64>) -> DMatrix<f64> {
    let n = a.nrows();
    let mut b = a.clone();
    let radix = 2.0f64;
    let mut done = false;
    let mut sweeps = 0;
    while !done && sweeps < 100 {
        done = true;
        sweeps += 1;
        for i in 0..n {
            let (mut c, mut r) = (0.0, 0.0);
            for j in 0..n {
                if j != i {
                    c += b[(j, i)].abs();
                    r += b[(i, j)].abs();
                }
            }
            if c == 0.0 || r == 0.0 {
                continue;
            }
            let s = c + r;
            let mut f = 1.0;
            let (mut c2, r2) = (c, r);
            while c2 < r2 / radix {
                c2 *= radix * radix;
                f *= radix;
            }
            while c2 >= r2 * radix {
                c2 /= radix * radix;
                f /= radix;
            }
            let c_new = c * f;
            let r_new = r / f;
            if (c_new + r_new) < 0.95 * s {
                done = false;
                for j in 0..n {
                    b[(i, j)] /= f;
                }
                for j in 0..n {
                    b[(j, i)] *= f;
                }
            }
        }
    }
    b
}

/// Eigenvalues of a real square matrix (balanced first), as complex numbers; real eigenvalues
/// have an exactly zero imaginary part and complex ones come in exact conjugate pairs.
///
/// Book: §15.3, (15.3.5); Matlab `eig` in 15.20.2.
///
/// # Errors
/// [`LtiError::NotSquare`], [`LtiError::NonFinite`], or [`LtiError::NoConvergence`].
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
    // balancing is a diagonal similarity: it keeps the Hessenberg shape
    let b = balance(a);
    let n = b.nrows();
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
    let scale = a.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(f64::MIN_POSITIVE);
    Ok(tidy_conjugates(ev, scale))
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
/// [`LtiError::NoConvergence`] if the SVD fails.
pub fn singular_values(a: &DMatrix<f64>) -> Result<Vec<f64>, LtiError> {
    if a.nrows() == 0 || a.ncols() == 0 {
        return Ok(Vec::new());
    }
    let mut s = to_faer(a).singular_values().map_err(|_| LtiError::NoConvergence { what: "SVD" })?;
    s.sort_by(|x, y| y.total_cmp(x));
    Ok(s)
}

/// Numerical rank: the number of singular values above `rtol·σ_max` (and above zero).
///
/// # Errors
/// [`LtiError::NoConvergence`] if the SVD fails.
pub fn rank(a: &DMatrix<f64>, rtol: f64) -> Result<usize, LtiError> {
    let s = singular_values(a)?;
    let top = s.first().copied().unwrap_or(0.0);
    Ok(s.iter().filter(|&&x| x > rtol * top && x > 0.0).count())
}
