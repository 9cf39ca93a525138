//! Roots of a real polynomial: eigenvalues of the balanced companion matrix of the variable-
//! scaled polynomial, then Newton polishing away from clusters.
//!
//! Book: 15.20.5 (`roots(p)` equals `eig` of the companion matrix), (15.7.3).

use super::Polynomial;
use crate::axis::mul_pow2;
use crate::error::LtiError;
use crate::linalg;
use nalgebra::DMatrix;
use num_complex::Complex64;

impl Polynomial {
    /// The roots, from the eigenvalues of the balanced companion matrix followed by Newton
    /// polishing; exact roots at 0 are returned exactly, real roots have zero imaginary part and
    /// complex roots come in exact conjugate pairs.
    ///
    /// The variable is scaled first, s = 2ᵏt with 2ᵏ ≈ |cₙ/c₀|^{1/n} (exact), so that
    /// coefficients spanning the whole floating-point range (1e300 s² + s + 1, roots
    /// ≈ ±1e-150j) neither underflow nor overflow in the companion matrix.
    ///
    /// # Conventions
    /// Repeated roots are found to about ε^{1/q} relative accuracy for multiplicity q (a
    /// property of the problem, not of the method): (s+1)² gives −1 ± ~1e-8j.
    ///
    /// Book: 15.20.5 (`roots(p)` equals `eig` of the companion matrix).
    ///
    /// # Errors
    /// [`LtiError::ZeroPolynomial`] for the zero polynomial (every number is a root);
    /// [`LtiError::NoConvergence`] if the eigenvalue iteration fails; [`LtiError::Overflow`]
    /// when a root exceeds the f64 range.
    pub fn roots(&self) -> Result<Vec<Complex64>, LtiError> {
        if self.is_zero() {
            return Err(LtiError::ZeroPolynomial { what: "roots" });
        }
        let z = self.zero_roots();
        let core = &self.coeffs[..self.coeffs.len() - z];
        let n = core.len() - 1;
        let mut roots = vec![Complex64::new(0.0, 0.0); z];
        if n == 0 {
            return Ok(roots);
        }
        // s = σt, σ = 2ᵏ: q(t) = Σ cᵢσ^{n−i}t^{n−i} has |q₀| ≈ |qₙ|
        let k = ((core[n].abs().log2() - core[0].abs().log2()) / n as f64).round() as i32;
        // or, divided by σⁿ, Σ cᵢσ^{−i}t^{n−i}: the same roots t, and one of the two forms keeps
        // every coefficient in range when the other overflows (t² + 3t + f64::MAX)
        let usable = |v: &[f64]| v.iter().all(|c| c.is_finite()) && v[0] != 0.0 && v[n] != 0.0;
        let up: Vec<f64> = core.iter().enumerate().map(|(i, &c)| mul_pow2(c, k * (n - i) as i32)).collect();
        let down =
            || -> Vec<f64> { core.iter().enumerate().map(|(i, &c)| mul_pow2(c, -k * i as i32)).collect() };
        let (q, k) = if usable(&up) {
            (Self { coeffs: up }, k)
        } else if let Some(d) = Some(down()).filter(|d| usable(d)) {
            (Self { coeffs: d }, k)
        } else {
            (Self { coeffs: core.to_vec() }, 0)
        };
        let sigma = |t: Complex64| Complex64::new(mul_pow2(t.re, k), mul_pow2(t.im, k));
        let c0 = q.coeffs[0];
        if n == 1 {
            roots.push(sigma(Complex64::new(-q.coeffs[1] / c0, 0.0)));
            return finite_roots(linalg::tidy_conjugates(roots, 0.0));
        }
        // Companion matrix (15.7.3) of the monic polynomial: top row −c₁/c₀ … −cₙ/c₀.
        let comp = DMatrix::from_fn(n, n, |i, j| {
            if i == 0 {
                -q.coeffs[j + 1] / c0
            } else if i == j + 1 {
                1.0
            } else {
                0.0
            }
        });
        let raw = linalg::eigenvalues_hessenberg(&comp)?;
        // Newton polishing helps simple roots; inside a cluster (a multiple root split by
        // roundoff into ~ε^{1/k}) it moves the members unevenly and spoils their mean, which
        // the QR iteration gets right to O(ε) (the trace), so clusters are left as computed.
        let mut ts = Vec::with_capacity(n);
        for (i, &r) in raw.iter().enumerate() {
            let near = raw
                .iter()
                .enumerate()
                .any(|(j, &o)| j != i && (o - r).norm_sqr() <= 1e-6 * r.norm_sqr().max(1.0));
            // an eigenvalue of exactly 0 cannot be a root (the roots at 0 were split off, q(0) ≠ 0):
            // it is a root below the QR iteration's resolution beside a huge one (4t² + 3·2⁵¹²t + 2);
            // start Newton from the linear term's root −qₙ/qₙ₋₁ instead
            let r = if r == Complex64::new(0.0, 0.0) && q.coeffs[n - 1] != 0.0 {
                Complex64::new(-q.coeffs[n] / q.coeffs[n - 1], 0.0)
            } else {
                r
            };
            ts.push(if near { r } else { q.polish(r) });
        }
        let ts = linalg::tidy_conjugates(ts, q.norm_inf() / c0.abs());
        roots.extend(ts.into_iter().map(sigma));
        // relative tidying only: the scaled roots are already paired, σ = 2ᵏ keeps them so
        finite_roots(linalg::tidy_conjugates(roots, 0.0))
    }

    /// A few Newton steps on p from `r`, kept only while |p| decreases.
    fn polish(&self, r: Complex64) -> Complex64 {
        let mut best = r;
        let (mut pb, mut db) = self.eval_with_derivative(r);
        for _ in 0..4 {
            if db.norm_sqr() == 0.0 || pb.norm_sqr() == 0.0 {
                break;
            }
            let next = best - pb / db;
            let (pn, dn) = self.eval_with_derivative(next);
            // |·|² orders like |·| without hypot (an under- or overflowed square stops early)
            if pn.norm_sqr() < pb.norm_sqr() {
                (best, pb, db) = (next, pn, dn);
            } else {
                break;
            }
        }
        best
    }
}

/// The roots, or [`LtiError::Overflow`] when one left the f64 range.
fn finite_roots(r: Vec<Complex64>) -> Result<Vec<Complex64>, LtiError> {
    if r.iter().all(|z| z.re.is_finite() && z.im.is_finite()) {
        Ok(r)
    } else {
        Err(LtiError::Overflow { what: "polynomial roots" })
    }
}
