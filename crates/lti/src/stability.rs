//! The four stability classes of §15.16, with a semisimplicity test for imaginary-axis
//! eigenvalues (A = 0₂ is Lyapunov stable although 0 is repeated; notes §2 and §3.8).
//!
//! Book: §15.16, Fact 15.16.1, Fact 15.16.5.

use crate::error::LtiError;
use crate::laplace::cluster_roots;
use crate::linalg;
use crate::poly::Polynomial;
use nalgebra::DMatrix;
use num_complex::Complex64;

/// Stability class of ẋ = Ax (or of a polynomial's roots), §15.16. Asymptotic stability
/// implies semistability implies Lyapunov stability (Fact 15.16.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum StabilityClass {
    /// Some eigenvalue in the ORHP, or a non-semisimple one on the imaginary axis.
    Unstable,
    /// Every eigenvalue in the OLHP or semisimple on the imaginary axis (not all at 0).
    LyapunovStable,
    /// Every eigenvalue in the OLHP or semisimple at 0; lim e^{At} exists.
    Semistable,
    /// Every eigenvalue in the OLHP.
    AsymptoticallyStable,
}

impl StabilityClass {
    /// BIBO stability of a transfer function whose poles have this class (Fact 15.16.5):
    /// only asymptotic stability is BIBO.
    pub fn is_bibo(self) -> bool {
        self == StabilityClass::AsymptoticallyStable
    }
}

/// Default tolerance for "on the imaginary axis": |Re λ| ≤ tol·max(1, |λ|) (notes §3.8).
pub const AXIS_RTOL: f64 = 1e-9;

fn classify(
    groups: &[(Complex64, usize)],
    tol: f64,
    semisimple: impl Fn(Complex64, usize) -> Result<bool, LtiError>,
) -> Result<StabilityClass, LtiError> {
    let mut class = StabilityClass::AsymptoticallyStable;
    for &(l, q) in groups {
        let scale = l.norm().max(1.0);
        if l.re > tol * scale {
            return Ok(StabilityClass::Unstable);
        }
        if l.re.abs() <= tol * scale {
            if !semisimple(l, q)? {
                return Ok(StabilityClass::Unstable);
            }
            let at_zero = l.norm() <= tol;
            class =
                class.min(if at_zero { StabilityClass::Semistable } else { StabilityClass::LyapunovStable });
        }
    }
    Ok(class)
}

/// The stability class of ẋ = Ax: imaginary-axis eigenvalue clusters λ of algebraic
/// multiplicity q must be semisimple, rank(A − λI) = n − q (by SVD, on the real form of the
/// complex matrix: rank [[A − σI, ωI], [−ωI, A − σI]] = 2 rank(A − λI)).
///
/// Book: §15.16, Fact 15.16.1; 15.20.51.
///
/// # Errors
/// [`LtiError::NotSquare`], [`LtiError::NonFinite`], [`LtiError::NoConvergence`];
/// [`LtiError::InvalidArgument`] unless `tol` is finite and ≥ 0.
pub fn stability_of_matrix(a: &DMatrix<f64>, tol: f64) -> Result<StabilityClass, LtiError> {
    crate::error::check_tolerance("imaginary-axis tolerance", tol)?;
    let ev = linalg::eigenvalues(a)?;
    let n = a.nrows();
    let groups = cluster_roots(&ev, crate::laplace::CLUSTER_RTOL);
    let scale = a.iter().fold(0.0f64, |m, x| m.max(x.abs())).max(1.0);
    classify(&groups, tol, |l, q| {
        let (s, w) = (l.re, l.im);
        let mut m = DMatrix::zeros(2 * n, 2 * n);
        for i in 0..n {
            for j in 0..n {
                let v = a[(i, j)] - if i == j { s } else { 0.0 };
                m[(i, j)] = v;
                m[(n + i, n + j)] = v;
            }
            m[(i, n + i)] = w;
            m[(n + i, i)] = -w;
        }
        let sv = linalg::singular_values(&m)?;
        // Rank tolerance: clustered eigenvalues are accurate to about √ε·‖A‖.
        let r = sv.iter().filter(|&&x| x > 1e-7 * scale).count();
        Ok(r == 2 * (n - q))
    })
}

/// The stability class of a characteristic polynomial's roots (poles of a transfer
/// function): repeated imaginary-axis roots are unstable (no Jordan structure to test).
///
/// Book: §15.16 (the lists for poles), 15.20.29–31.
///
/// # Errors
/// [`LtiError::ZeroPolynomial`] for the zero polynomial (every number is a root; it used to
/// come out asymptotically stable); [`LtiError::InvalidArgument`] unless `tol` is finite and
/// ≥ 0; root-finding errors.
pub fn stability_of_polynomial(p: &Polynomial, tol: f64) -> Result<StabilityClass, LtiError> {
    crate::error::check_tolerance("imaginary-axis tolerance", tol)?;
    if p.is_zero() {
        return Err(LtiError::ZeroPolynomial { what: "stability of a polynomial" });
    }
    let groups = cluster_roots(&p.roots()?, crate::laplace::CLUSTER_RTOL);
    classify(&groups, tol, |_, q| Ok(q == 1))
}
