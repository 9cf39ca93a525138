//! serde for polynomials, transfer functions and state-space models (cargo feature `serde`).
//!
//! | type | JSON |
//! |---|---|
//! | [`Polynomial`] | `[c₀, c₁, …, cₙ]`, descending powers (Matlab's `num`/`den`) |
//! | [`TransferFunction`] | `{"num": [...], "den": [...], "delay": τ}` (G(s) = N(s)/D(s)·e^{−τs}) |
//! | [`StateSpace`] | `{"states": n, "inputs": m, "outputs": p, "a": [[…]…], "b": …, "c": …, "d": …}`, matrices as rows |
//!
//! The dimensions are written out so that empty matrices (a static gain has n = 0) keep their
//! shape. Reading goes through the public constructors ([`Polynomial::new`],
//! [`TransferFunction::new`] and [`TransferFunction::with_delay`], [`StateSpace::new`]) and
//! reports their [`LtiError`] messages: non-finite numbers, a zero denominator, a negative
//! delay, matrices whose sizes do not fit. Row lengths are checked against the stated sizes
//! before anything is allocated from them. Round trips are exact.
//!
//! Book: §15.7, (15.7.4)–(15.7.5); §15.11, §15.14, (15.14.7); (15.10.2). JSON forms:
//! `docs/guide/interop.md`.

use nalgebra::DMatrix;
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::{LtiError, Polynomial, StateSpace, TransferFunction};

/// Coefficients in descending powers.
impl Serialize for Polynomial {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.coeffs().serialize(s)
    }
}

/// Through [`Polynomial::new`] (finite coefficients; exact leading zeros removed).
impl<'de> Deserialize<'de> for Polynomial {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Polynomial::new(&Vec::<f64>::deserialize(d)?).map_err(D::Error::custom)
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct TfRepr {
    num: Polynomial,
    den: Polynomial,
    delay: f64,
}

/// `{"num": [...], "den": [...], "delay": τ}`.
impl Serialize for TransferFunction {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        TfRepr { num: self.num().clone(), den: self.den().clone(), delay: self.delay() }.serialize(s)
    }
}

/// Through [`TransferFunction::from_polynomials`] and [`TransferFunction::with_delay`].
impl<'de> Deserialize<'de> for TransferFunction {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let TfRepr { num, den, delay } = TfRepr::deserialize(d)?;
        TransferFunction::from_polynomials(num, den)
            .and_then(|g| g.with_delay(delay))
            .map_err(D::Error::custom)
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SsRepr {
    states: usize,
    inputs: usize,
    outputs: usize,
    a: Vec<Vec<f64>>,
    b: Vec<Vec<f64>>,
    c: Vec<Vec<f64>>,
    d: Vec<Vec<f64>>,
}

fn rows(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    m.row_iter().map(|r| r.iter().copied().collect()).collect()
}

/// The matrix `what` from `rows`, which must be `nrows` rows of `ncols` entries.
fn matrix(
    what: &'static str,
    rows: &[Vec<f64>],
    nrows: usize,
    ncols: usize,
) -> Result<DMatrix<f64>, LtiError> {
    if rows.len() != nrows || rows.iter().any(|r| r.len() != ncols) {
        let found = match rows.iter().map(Vec::len).find(|&l| l != ncols) {
            Some(l) if rows.len() == nrows => format!("{} rows, one of {l} entries", rows.len()),
            _ => format!("{} rows", rows.len()),
        };
        return Err(LtiError::DimensionMismatch { what, expected: format!("{nrows}×{ncols}"), found });
    }
    Ok(DMatrix::from_fn(nrows, ncols, |i, j| rows[i][j]))
}

/// Dimensions and the rows of A, B, C, D.
impl Serialize for StateSpace {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        SsRepr {
            states: self.n_states(),
            inputs: self.n_inputs(),
            outputs: self.n_outputs(),
            a: rows(self.a()),
            b: rows(self.b()),
            c: rows(self.c()),
            d: rows(self.d()),
        }
        .serialize(s)
    }
}

/// Rows checked against the stated n, m, p, then [`StateSpace::new`].
impl<'de> Deserialize<'de> for StateSpace {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let r = SsRepr::deserialize(d)?;
        let (n, m, p) = (r.states, r.inputs, r.outputs);
        let build = || -> Result<StateSpace, LtiError> {
            StateSpace::new(
                matrix("A", &r.a, n, n)?,
                matrix("B", &r.b, n, m)?,
                matrix("C", &r.c, p, n)?,
                matrix("D", &r.d, p, m)?,
            )
        };
        build().map_err(D::Error::custom)
    }
}
