//! State-space models ẋ = Ax + Bu, y = Cx + Du (MIMO), conversions and structure tests.
//!
//! Book: §15.7, (15.7.4)–(15.7.5); §15.14, (15.14.5)–(15.14.14); 15.20.52, 15.20.56.

use crate::error::{LtiError, check_finite};
use crate::linalg;
use crate::poly::Polynomial;
use crate::tf::TransferFunction;
use nalgebra::DMatrix;
use num_complex::Complex64;

/// A continuous-time state-space model ẋ = Ax + Bu, y = Cx + Du with n states, m inputs
/// and p outputs.
///
/// Book: §15.7, (15.7.4)–(15.7.5).
#[derive(Debug, Clone, PartialEq)]
pub struct StateSpace {
    a: DMatrix<f64>,
    b: DMatrix<f64>,
    c: DMatrix<f64>,
    d: DMatrix<f64>,
}

fn dims(m: &DMatrix<f64>) -> String {
    format!("{}×{}", m.nrows(), m.ncols())
}

impl StateSpace {
    /// A model from (A, B, C, D): A is n×n, B n×m, C p×n, D p×m.
    ///
    /// # Errors
    /// [`LtiError::NotSquare`] for a non-square A, [`LtiError::DimensionMismatch`] when B, C or
    /// D do not fit A, and [`LtiError::NonFinite`] for a NaN or infinite entry.
    pub fn new(a: DMatrix<f64>, b: DMatrix<f64>, c: DMatrix<f64>, d: DMatrix<f64>) -> Result<Self, LtiError> {
        if a.nrows() != a.ncols() {
            return Err(LtiError::NotSquare { what: "A", rows: a.nrows(), cols: a.ncols() });
        }
        let n = a.nrows();
        let mismatch = |what, expected: String, m: &DMatrix<f64>| LtiError::DimensionMismatch {
            what,
            expected,
            found: dims(m),
        };
        if b.nrows() != n {
            return Err(mismatch("B", format!("{n}×m"), &b));
        }
        if c.ncols() != n {
            return Err(mismatch("C", format!("p×{n}"), &c));
        }
        if d.nrows() != c.nrows() || d.ncols() != b.ncols() {
            return Err(mismatch("D", format!("{}×{}", c.nrows(), b.ncols()), &d));
        }
        check_finite("A", a.iter())?;
        check_finite("B", b.iter())?;
        check_finite("C", c.iter())?;
        check_finite("D", d.iter())?;
        Ok(Self { a, b, c, d })
    }

    /// From row-major slices for the common small cases (rows of A, B, C, D).
    ///
    /// # Errors
    /// As [`StateSpace::new`]; also [`LtiError::DimensionMismatch`] for ragged rows.
    pub fn from_rows(a: &[&[f64]], b: &[&[f64]], c: &[&[f64]], d: &[&[f64]]) -> Result<Self, LtiError> {
        fn mat(what: &'static str, rows: &[&[f64]]) -> Result<DMatrix<f64>, LtiError> {
            let nc = rows.first().map_or(0, |r| r.len());
            if let Some(r) = rows.iter().find(|r| r.len() != nc) {
                return Err(LtiError::DimensionMismatch {
                    what,
                    expected: format!("rows of length {nc}"),
                    found: format!("a row of length {}", r.len()),
                });
            }
            Ok(DMatrix::from_fn(rows.len(), nc, |i, j| rows[i][j]))
        }
        Self::new(mat("A", a)?, mat("B", b)?, mat("C", c)?, mat("D", d)?)
    }

    /// State matrix A.
    pub fn a(&self) -> &DMatrix<f64> {
        &self.a
    }
    /// Input matrix B.
    pub fn b(&self) -> &DMatrix<f64> {
        &self.b
    }
    /// Output matrix C.
    pub fn c(&self) -> &DMatrix<f64> {
        &self.c
    }
    /// Feedthrough matrix D.
    pub fn d(&self) -> &DMatrix<f64> {
        &self.d
    }
    /// Number of states n.
    pub fn n_states(&self) -> usize {
        self.a.nrows()
    }
    /// Number of inputs m.
    pub fn n_inputs(&self) -> usize {
        self.b.ncols()
    }
    /// Number of outputs p.
    pub fn n_outputs(&self) -> usize {
        self.c.nrows()
    }

    /// Eigenvalues of A, the poles of every channel before cancellation (15.14).
    ///
    /// # Errors
    /// [`LtiError::NoConvergence`] if the eigenvalue iteration fails.
    pub fn poles(&self) -> Result<Vec<Complex64>, LtiError> {
        linalg::eigenvalues(&self.a)
    }

    /// The SISO channel from input `input` to output `output`.
    ///
    /// # Errors
    /// [`LtiError::IndexOutOfRange`] for a bad index.
    pub fn channel(&self, output: usize, input: usize) -> Result<Self, LtiError> {
        if output >= self.n_outputs() {
            return Err(LtiError::IndexOutOfRange { what: "output", index: output, len: self.n_outputs() });
        }
        if input >= self.n_inputs() {
            return Err(LtiError::IndexOutOfRange { what: "input", index: input, len: self.n_inputs() });
        }
        Ok(Self {
            a: self.a.clone(),
            b: self.b.columns(input, 1).into_owned(),
            c: self.c.rows(output, 1).into_owned(),
            d: self.d.view((output, input), (1, 1)).into_owned(),
        })
    }

    /// The transfer function of one channel, G = C(sI − A)⁻¹B + D (15.14.5), from
    /// det(sI − A + BC) = det(sI − A)(1 + C(sI − A)⁻¹B):
    /// N = poly(A − BC) − poly(A) + D·poly(A), with the numerator's leading round-off trimmed
    /// relative to the size of the polynomials that were subtracted (notes §3.3). No
    /// cancellation is done: call [`TransferFunction::minreal`] for that (15.20.38).
    ///
    /// Book: (15.14.5), (15.14.8)–(15.14.14), Matlab `ss2tf` in 15.20.52.
    ///
    /// # Errors
    /// [`LtiError::IndexOutOfRange`]; [`LtiError::NoConvergence`] from the eigenvalues.
    pub fn to_tf(&self, output: usize, input: usize) -> Result<TransferFunction, LtiError> {
        let ch = self.channel(output, input)?;
        let den = Polynomial::from_roots(&linalg::eigenvalues(&ch.a)?)?;
        let bc = &ch.b * &ch.c;
        let closed = Polynomial::from_roots(&linalg::eigenvalues(&(&ch.a - bc))?)?;
        let d = ch.d[(0, 0)];
        let num = closed.minus(&den).plus(&den.scaled(d));
        // Round-off of the subtraction is about ε·n·max(|closed|, |den|) per coefficient.
        let scale = closed.norm_inf().max(den.norm_inf()) * (1.0 + d.abs());
        let tol = 64.0 * f64::EPSILON * (self.n_states().max(1) as f64) * scale;
        let cleaned: Vec<f64> = num.coeffs().iter().map(|&c| if c.abs() <= tol { 0.0 } else { c }).collect();
        // The same cleanup for the denominator: eigenvalues at 0 come out as ~ε‖A‖, which would
        // leave a trailing 1e-19 where an exact integrator belongs (15.20.42).
        let dtol = 64.0 * f64::EPSILON * (self.n_states().max(1) as f64) * den.norm_inf();
        // never the leading coefficient: it is 1 (monic), and zeroing it under ‖A‖ = 1e300 dropped
        // the degree of D
        let den: Vec<f64> = den
            .coeffs()
            .iter()
            .enumerate()
            .map(|(i, &c)| if i > 0 && c.abs() <= dtol { 0.0 } else { c })
            .collect();
        TransferFunction::from_polynomials(Polynomial::from_vec(cleaned), Polynomial::from_vec(den))
    }

    /// The controllable companion realisation (15.7.3) of a proper rational G:
    /// x = (q, q̇, …), A has ones on the superdiagonal and last row −a₀ … −aₙ₋₁, B = eₙ,
    /// C = (b₀ − a₀bₙ, …, bₙ₋₁ − aₙ₋₁bₙ), D = bₙ (for monic D(s) = sⁿ + aₙ₋₁sⁿ⁻¹ + … + a₀).
    ///
    /// Book: (15.7.1)–(15.7.3).
    ///
    /// # Errors
    /// [`LtiError::Improper`] for deg N > deg D; [`LtiError::Delay`] when G has a delay.
    pub fn from_tf(g: &TransferFunction) -> Result<Self, LtiError> {
        g.require_rational("state-space realisation")?;
        g.require_proper("state-space realisation")?;
        let lead = g.den().leading();
        let n = g.den().degree();
        let a_k = |k: usize| g.den().coeff(k) / lead;
        let b_k = |k: usize| g.num().coeff(k) / lead;
        let bn = b_k(n);
        let a = DMatrix::from_fn(n, n, |i, j| {
            if i + 1 == n {
                -a_k(j)
            } else if j == i + 1 {
                1.0
            } else {
                0.0
            }
        });
        let b = DMatrix::from_fn(n, 1, |i, _| if i + 1 == n { 1.0 } else { 0.0 });
        let c = DMatrix::from_fn(1, n, |_, j| b_k(j) - a_k(j) * bn);
        let d = DMatrix::from_element(1, 1, bn);
        Self::new(a, b, c, d)
    }

    /// The companion form (15.7.3) of the ODE q⁽ⁿ⁾ + aₙ₋₁q⁽ⁿ⁻¹⁾ + … + a₀q = b₀u with output q:
    /// `a = [a₀, …, aₙ₋₁]` in ascending order as in the book.
    ///
    /// Book: (15.7.1)–(15.7.3).
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for an empty `a`; [`LtiError::NonFinite`].
    pub fn companion(a: &[f64], b0: f64) -> Result<Self, LtiError> {
        if a.is_empty() {
            return Err(LtiError::InvalidArgument {
                what: "companion coefficients",
                reason: "need n ≥ 1".into(),
            });
        }
        let mut den = vec![1.0];
        den.extend(a.iter().rev());
        Self::from_tf(&TransferFunction::new(&[b0], &den)?)
    }

    /// Controllability matrix [B AB … Aⁿ⁻¹B].
    ///
    /// Book: 15.20.56.
    pub fn ctrb(&self) -> DMatrix<f64> {
        let (n, m) = (self.n_states(), self.n_inputs());
        let mut k = DMatrix::zeros(n, n * m);
        let mut blk = self.b.clone();
        for i in 0..n {
            k.view_mut((0, i * m), (n, m)).copy_from(&blk);
            blk = &self.a * blk;
        }
        k
    }

    /// Observability matrix [C; CA; …; CAⁿ⁻¹].
    ///
    /// Book: 15.20.56.
    pub fn obsv(&self) -> DMatrix<f64> {
        let (n, p) = (self.n_states(), self.n_outputs());
        let mut o = DMatrix::zeros(n * p, n);
        let mut blk = self.c.clone();
        for i in 0..n {
            o.view_mut((i * p, 0), (p, n)).copy_from(&blk);
            blk *= &self.a;
        }
        o
    }

    /// True when rank [B AB … Aⁿ⁻¹B] = n, ranks by SVD with relative tolerance `rtol`.
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a NaN, infinite or negative `rtol`;
    /// [`LtiError::NoConvergence`] if the SVD fails.
    pub fn is_controllable(&self, rtol: f64) -> Result<bool, LtiError> {
        Ok(linalg::rank(&self.ctrb(), rtol)? == self.n_states())
    }

    /// True when rank [C; CA; …; CAⁿ⁻¹] = n.
    ///
    /// # Errors
    /// [`LtiError::InvalidArgument`] for a NaN, infinite or negative `rtol`;
    /// [`LtiError::NoConvergence`] if the SVD fails.
    pub fn is_observable(&self, rtol: f64) -> Result<bool, LtiError> {
        Ok(linalg::rank(&self.obsv(), rtol)? == self.n_states())
    }

    /// A minimal realisation of a SISO model: transfer function, cancellation within `tol`,
    /// companion realisation (15.20.37: (s+1)/((s+1)(s+2)) → 1/(s+2)).
    ///
    /// # Errors
    /// [`LtiError::DimensionMismatch`] for a MIMO model; root-finding errors.
    pub fn minreal(&self, tol: f64) -> Result<Self, LtiError> {
        if self.n_inputs() != 1 || self.n_outputs() != 1 {
            return Err(LtiError::DimensionMismatch {
                what: "minreal",
                expected: "a SISO model (1 input, 1 output)".into(),
                found: format!("{} outputs × {} inputs", self.n_outputs(), self.n_inputs()),
            });
        }
        Self::from_tf(&self.to_tf(0, 0)?.minreal(tol)?)
    }

    /// Series connection: the output of `self` drives `next` (y = G_next G_self u).
    ///
    /// # Errors
    /// [`LtiError::DimensionMismatch`] unless outputs of `self` = inputs of `next`.
    pub fn series(&self, next: &Self) -> Result<Self, LtiError> {
        if self.n_outputs() != next.n_inputs() {
            return Err(LtiError::DimensionMismatch {
                what: "series connection",
                expected: format!("{} inputs on the second system", self.n_outputs()),
                found: format!("{}", next.n_inputs()),
            });
        }
        let (n1, n2) = (self.n_states(), next.n_states());
        let mut a = DMatrix::zeros(n1 + n2, n1 + n2);
        a.view_mut((0, 0), (n1, n1)).copy_from(&self.a);
        a.view_mut((n1, 0), (n2, n1)).copy_from(&(&next.b * &self.c));
        a.view_mut((n1, n1), (n2, n2)).copy_from(&next.a);
        let mut b = DMatrix::zeros(n1 + n2, self.n_inputs());
        b.view_mut((0, 0), (n1, self.n_inputs())).copy_from(&self.b);
        b.view_mut((n1, 0), (n2, self.n_inputs())).copy_from(&(&next.b * &self.d));
        let mut c = DMatrix::zeros(next.n_outputs(), n1 + n2);
        c.view_mut((0, 0), (next.n_outputs(), n1)).copy_from(&(&next.d * &self.c));
        c.view_mut((0, n1), (next.n_outputs(), n2)).copy_from(&next.c);
        Self::new(a, b, c, &next.d * &self.d)
    }

    /// Parallel connection y = (G₁ + G₂)u.
    ///
    /// # Errors
    /// [`LtiError::DimensionMismatch`] unless both have the same inputs and outputs.
    pub fn parallel(&self, other: &Self) -> Result<Self, LtiError> {
        if self.n_inputs() != other.n_inputs() || self.n_outputs() != other.n_outputs() {
            return Err(LtiError::DimensionMismatch {
                what: "parallel connection",
                expected: format!("{}×{}", self.n_outputs(), self.n_inputs()),
                found: format!("{}×{}", other.n_outputs(), other.n_inputs()),
            });
        }
        let (n1, n2) = (self.n_states(), other.n_states());
        let mut a = DMatrix::zeros(n1 + n2, n1 + n2);
        a.view_mut((0, 0), (n1, n1)).copy_from(&self.a);
        a.view_mut((n1, n1), (n2, n2)).copy_from(&other.a);
        let mut b = DMatrix::zeros(n1 + n2, self.n_inputs());
        b.view_mut((0, 0), (n1, self.n_inputs())).copy_from(&self.b);
        b.view_mut((n1, 0), (n2, self.n_inputs())).copy_from(&other.b);
        let mut c = DMatrix::zeros(self.n_outputs(), n1 + n2);
        c.view_mut((0, 0), (self.n_outputs(), n1)).copy_from(&self.c);
        c.view_mut((0, n1), (self.n_outputs(), n2)).copy_from(&other.c);
        Self::new(a, b, c, &self.d + &other.d)
    }

    /// Negative unity feedback u = r − y around a square, strictly proper plant
    /// (D = 0): ẋ = (A − BC)x + Br.
    ///
    /// Book: (15.18.4).
    ///
    /// # Errors
    /// [`LtiError::DimensionMismatch`] unless p = m and D = 0.
    pub fn unity_feedback(&self) -> Result<Self, LtiError> {
        if self.n_inputs() != self.n_outputs() || self.d.iter().any(|&x| x != 0.0) {
            return Err(LtiError::DimensionMismatch {
                what: "unity feedback",
                expected: "a square plant with D = 0".into(),
                found: format!("{}×{} with D = {}", self.n_outputs(), self.n_inputs(), self.d),
            });
        }
        Self::new(&self.a - &self.b * &self.c, self.b.clone(), self.c.clone(), self.d.clone())
    }
}
