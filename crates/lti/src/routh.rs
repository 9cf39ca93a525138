//! The Routh array with both special cases, and one-parameter stable gain intervals.
//!
//! Book: §15.17, Fact 15.17.1, (15.17.1)–(15.17.2) (the book says the general array is
//! "derivable" but does not give it); notes §3.7.

use crate::error::LtiError;
use crate::poly::Polynomial;

/// A Routh array and what it says about the roots.
///
/// Book: §15.17.
#[derive(Debug, Clone, PartialEq)]
pub struct RouthArray {
    /// Rows s^n, s^{n−1}, …, s^0 (after special-case replacements).
    pub rows: Vec<Vec<f64>>,
    /// Sign changes in the first column = number of ORHP roots.
    pub rhp: usize,
    /// Number of roots on the imaginary axis (roots of the auxiliary polynomial there).
    pub imaginary: usize,
    /// True if a zero first-column entry of a nonzero row was replaced by a small ε > 0
    /// (special case 1).
    pub epsilon_used: bool,
    /// The auxiliary polynomial of the first row of zeros (special case 2), whose roots are
    /// symmetric about the origin and contain the imaginary-axis roots.
    pub auxiliary: Option<Polynomial>,
}

impl RouthArray {
    /// Number of roots in the open left half plane.
    pub fn lhp(&self) -> usize {
        self.rows.len() - 1 - self.rhp - self.imaginary
    }

    /// True when every root is in the OLHP (the polynomial is Hurwitz).
    pub fn is_hurwitz(&self) -> bool {
        self.rhp == 0 && self.imaginary == 0
    }
}

/// The Routh array of p (any sign of the leading coefficient).
///
/// Special case 1 (a zero in the first column of a nonzero row): replaced by
/// ε = √ε_mach·(row scale), which counts sign changes as ε → 0⁺. Special case 2 (a row of
/// zeros): replaced by the derivative of the auxiliary polynomial built from the row above.
///
/// Book: §15.17; notes §3.7.
///
/// # Errors
/// [`LtiError::InvalidArgument`] for the zero polynomial; [`LtiError::Overflow`] when an
/// entry of the array overflows; root-finding errors for the auxiliary polynomial.
pub fn routh(p: &Polynomial) -> Result<RouthArray, LtiError> {
    if p.is_zero() {
        return Err(LtiError::InvalidArgument {
            what: "polynomial",
            reason: "the zero polynomial has no Routh array".into(),
        });
    }
    let p = if p.leading() < 0.0 { p.scaled(-1.0) } else { p.clone() };
    let n = p.degree();
    let c = p.coeffs();
    let width = n / 2 + 1;
    let row_from = |start: usize| -> Vec<f64> {
        (0..width).map(|j| c.get(start + 2 * j).copied().unwrap_or(0.0)).collect()
    };
    let mut rows = vec![row_from(0)];
    let scale = p.norm_inf();
    let zero_tol = 1e3 * f64::EPSILON * scale;
    let mut epsilon_used = false;
    let mut auxiliary = None;
    for i in 1..=n {
        let mut next: Vec<f64> = if i == 1 {
            row_from(1)
        } else {
            let (r2, r1) = (&rows[i - 2], &rows[i - 1]);
            (0..width)
                .map(|j| {
                    let a = r2.get(j + 1).copied().unwrap_or(0.0);
                    let b = r1.get(j + 1).copied().unwrap_or(0.0);
                    (r1[0] * a - r2[0] * b) / r1[0]
                })
                .collect()
        };
        let r1 = &rows[i - 1];
        let row_scale = next.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if row_scale <= zero_tol {
            // Special case 2: auxiliary polynomial from row i−1 (power n−i+1, even steps).
            let deg = n - i + 1;
            let mut coeffs = vec![0.0; deg + 1];
            for (j, &v) in r1.iter().enumerate() {
                if 2 * j <= deg {
                    coeffs[2 * j] = v;
                }
            }
            let aux = Polynomial::from_vec(coeffs);
            let d = aux.deriv();
            let dc = d.coeffs();
            next = (0..width).map(|j| dc.get(2 * j).copied().unwrap_or(0.0)).collect();
            if auxiliary.is_none() {
                auxiliary = Some(aux);
            }
        }
        if next[0].abs() <= zero_tol {
            // Special case 1: ε-substitution.
            epsilon_used = true;
            next[0] = f64::EPSILON.sqrt() * scale.max(f64::MIN_POSITIVE);
        }
        for x in next.iter_mut() {
            if x.abs() <= zero_tol {
                *x = 0.0;
            }
        }
        rows.push(next);
    }
    if rows.iter().any(|r| r.iter().any(|x| !x.is_finite())) {
        return Err(LtiError::Overflow { what: "Routh array" });
    }
    let first: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let rhp_changes = first.windows(2).filter(|w| (w[0] > 0.0) != (w[1] > 0.0)).count();
    let imaginary = match &auxiliary {
        Some(a) => a.roots()?.iter().filter(|z| z.re.abs() <= 1e-6 * z.norm().max(1.0)).count(),
        None => 0,
    };
    Ok(RouthArray { rows, rhp: rhp_changes, imaginary, epsilon_used, auxiliary })
}

/// The open intervals of k for which D(s) + kN(s) is Hurwitz (closed loop of L = kN/D,
/// any sign of k), with ±∞ for unbounded ends.
///
/// Breakpoints are the real k = −D(jω)/N(jω) at the real ω ≥ 0 where Im[D(jω)·conj N(jω)] = 0
/// (a root crosses the imaginary axis) and the k where the degree drops; each interval
/// between breakpoints is tested at one point with the Routh array (notes §3.7).
///
/// Book: §15.17, 15.20.39–49, 16.8.11.
///
/// # Errors
/// [`LtiError::InvalidArgument`] for N = 0; root-finding errors.
pub fn stable_gain_intervals(num: &Polynomial, den: &Polynomial) -> Result<Vec<(f64, f64)>, LtiError> {
    if num.is_zero() || den.is_zero() {
        return Err(LtiError::InvalidArgument {
            what: "loop polynomials",
            reason: "N and D must be nonzero".into(),
        });
    }
    let (dr, di) = jw_parts(den);
    let (nr, ni) = jw_parts(num);
    // Im(D conj N) = Di Nr − Dr Ni (a polynomial in ω).
    let im = di.times(&nr).minus(&dr.times(&ni));
    let mut ks: Vec<f64> = Vec::new();
    let mut omegas: Vec<f64> = vec![0.0];
    if !im.is_zero() {
        for w in im.roots()? {
            if w.im.abs() <= 1e-7 * w.norm().max(1.0) && w.re >= 0.0 {
                omegas.push(w.re);
            }
        }
    }
    for w in omegas {
        let (n_re, n_im) = (nr.eval(w), ni.eval(w));
        let nn = n_re * n_re + n_im * n_im;
        if nn > 0.0 {
            // k = −D/N = −D conj N/|N|².
            ks.push(-(dr.eval(w) * n_re + di.eval(w) * n_im) / nn);
        }
    }
    if num.degree() >= den.degree() {
        ks.push(-den.coeff(num.degree()) / num.leading());
    }
    ks.retain(|k| k.is_finite());
    ks.sort_by(f64::total_cmp);
    ks.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * a.abs().max(1.0));
    let hurwitz = |k: f64| -> Result<bool, LtiError> {
        let p = den.plus(&num.scaled(k));
        Ok(p.degree() == den.degree().max(num.degree()) && routh(&p)?.is_hurwitz())
    };
    let mut edges = vec![f64::NEG_INFINITY];
    edges.extend(&ks);
    edges.push(f64::INFINITY);
    let mut out: Vec<(f64, f64)> = Vec::new();
    for w in edges.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        let mid = match (lo.is_finite(), hi.is_finite()) {
            (true, true) => 0.5 * (lo + hi),
            (false, true) => hi - hi.abs().max(1.0),
            (true, false) => lo + lo.abs().max(1.0),
            (false, false) => 0.0,
        };
        if hurwitz(mid)? {
            match out.last_mut() {
                Some(last) if last.1 == lo && !hurwitz(lo)? => out.push((lo, hi)),
                Some(last) if last.1 == lo => last.1 = hi,
                _ => out.push((lo, hi)),
            }
        }
    }
    Ok(out)
}

/// Real polynomials R(ω), I(ω) with p(jω) = R(ω) + jI(ω).
pub(crate) fn jw_parts(p: &Polynomial) -> (Polynomial, Polynomial) {
    let n = p.degree();
    let mut re = vec![0.0; n + 1];
    let mut im = vec![0.0; n + 1];
    for k in 0..=n {
        // jᵏ: 1, j, −1, −j.
        let c = p.coeff(k);
        let idx = n - k;
        match k % 4 {
            0 => re[idx] = c,
            1 => im[idx] = c,
            2 => re[idx] = -c,
            _ => im[idx] = -c,
        }
    }
    (Polynomial::from_vec(re), Polynomial::from_vec(im))
}
