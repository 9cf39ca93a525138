//! Units: products of powers of prefixed unit symbols, with exact conversion.

use core::fmt;

use crate::exact::{Big, PI_DIGITS, PI_EXP10, Ratio, Rounded, big_from_digits, ratio_of_f64};
use crate::table::{ATOMS, AtomId, G0_INDEX, PREFIXES, atom_of};
use crate::{Dimension, MAX_EXPONENT, UnitError};

/// One factor of a unit: (10^prefix · atom)^exp.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Term {
    pub(crate) atom: AtomId,
    pub(crate) prefix: i8,
    pub(crate) exp: i8,
}

/// A unit: a product of integer powers of (prefixed) unit symbols, e.g. `slug*ft^2`,
/// `ft/s^2`, `N*m`, `kg/(m*s^2)`, with its dimension and an exact SI factor.
///
/// # Conventions
/// Equal units are equal as products: `m/s/s` equals `m/s^2`, and `s^-1*m` equals `m/s`. Two
/// different products with one factor (`N*m` and `J`) are different units that convert to
/// each other with factor exactly 1. [`fmt::Display`] writes the grammar's canonical form
/// (numerator factors joined by `*`, each denominator factor after a `/`), which
/// [`Unit::parse`] reads back to an equal unit.
///
/// Book: §15.19.
#[derive(Debug, Clone)]
pub struct Unit {
    /// Factors in order of first appearance, merged, none with exponent 0.
    terms: Vec<Term>,
    dimension: Dimension,
}

impl PartialEq for Unit {
    fn eq(&self, other: &Self) -> bool {
        let (mut a, mut b) = (self.terms.clone(), other.terms.clone());
        a.sort();
        b.sort();
        a == b
    }
}

/// log₁₀ π.
const LOG10_PI: f64 = 0.497_149_872_694_133_85;

impl Unit {
    /// The dimensionless unit `1`.
    ///
    /// Book: §15.19.
    pub fn one() -> Self {
        Self { terms: Vec::new(), dimension: Dimension::DIMENSIONLESS }
    }

    /// The unit of one table symbol with a power-of-ten prefix (0 for none).
    pub(crate) fn atom(prefix: i8, atom: AtomId) -> Self {
        let dimension = atom_of(atom).dimension;
        Self { terms: vec![Term { atom, prefix, exp: 1 }], dimension }
    }

    /// A unit from merged, nonzero terms and their dimension.
    pub(crate) fn from_terms(terms: Vec<Term>, dimension: Dimension) -> Self {
        Self { terms, dimension }
    }

    /// Parses a unit expression alone (no number): `ft/s^2`, `slug*ft^2`, `1/s`.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// As [`crate::Quantity::parse`], with spans inside `text`.
    pub fn parse(text: &str) -> Result<Self, UnitError> {
        crate::parse::unit_only(text)
    }

    /// The coherent SI unit of a dimension, written with kg, m, s and rad (`kg*m^2/s^2`).
    ///
    /// Book: §15.19.
    pub fn si(dimension: Dimension) -> Self {
        let g = ATOMS.iter().position(|a| a.symbol == "g").unwrap_or(1) as AtomId;
        let [m_id, s_id, rad_id] =
            ["m", "s", "rad"].map(|s| ATOMS.iter().position(|a| a.symbol == s).unwrap_or(0) as AtomId);
        let [em, el, et, ea] = dimension.exponents();
        let mut u = Self::one();
        for (atom, prefix, exp) in [(g, 3, em), (m_id, 0, el), (s_id, 0, et), (rad_id, 0, ea)] {
            if exp != 0 {
                u.terms.push(Term { atom, prefix, exp });
            }
        }
        u.dimension = dimension;
        u
    }

    /// What this unit measures.
    pub fn dimension(&self) -> Dimension {
        self.dimension
    }

    /// Whether this is a coherent SI unit (factor exactly 1, as `N*m`, `kg*m/s^2`, `rad/s`).
    pub fn is_coherent_si(&self) -> bool {
        self.exact_factor_is_one()
    }

    fn exact_factor_is_one(&self) -> bool {
        let mut r = Ratio::one();
        self.scale(&mut r, 1);
        r.num == r.den
    }

    /// self^n with exponents bounded by [`MAX_EXPONENT`]; `None` beyond.
    pub(crate) fn checked_pow(&self, n: i32) -> Option<Self> {
        let dimension = self.dimension.checked_pow(n)?;
        let mut terms = Vec::with_capacity(self.terms.len());
        for t in &self.terms {
            let e = i32::from(t.exp) * n;
            if e.abs() > MAX_EXPONENT {
                return None;
            }
            if e != 0 {
                terms.push(Term { exp: e as i8, ..*t });
            }
        }
        Some(Self { terms, dimension })
    }

    /// self · other with exponents bounded by [`MAX_EXPONENT`]; `None` beyond.
    pub(crate) fn checked_mul(&self, other: &Self) -> Option<Self> {
        let dimension = self.dimension.checked_mul(&other.dimension)?;
        let mut terms = self.terms.clone();
        for t in &other.terms {
            match terms.iter_mut().find(|s| s.atom == t.atom && s.prefix == t.prefix) {
                Some(s) => {
                    let e = i32::from(s.exp) + i32::from(t.exp);
                    if e.abs() > MAX_EXPONENT {
                        return None;
                    }
                    s.exp = e as i8;
                }
                None => terms.push(*t),
            }
        }
        terms.retain(|t| t.exp != 0);
        Some(Self { terms, dimension })
    }

    /// The product of `factors`ᵏ (each a unit and its integer power) with exponents bounded by
    /// [`MAX_EXPONENT`] only in the result (`None` beyond): the powers and partial products may
    /// leave the bounds, so `W^6/Hz^2` (T⁻¹⁶) is a unit although `W^6` alone (T⁻¹⁸) is not.
    /// Terms keep the order of their first appearance, as [`Unit::checked_mul`] folds them.
    pub(crate) fn checked_product(factors: &[(Self, i32)]) -> Option<Self> {
        let mut dim = [0i64; 4];
        let mut terms: Vec<(Term, i64)> = Vec::new();
        for (f, k) in factors {
            let k = i64::from(*k);
            for (d, x) in dim.iter_mut().zip(f.dimension.exponents()) {
                *d += i64::from(x) * k;
            }
            for t in &f.terms {
                match terms.iter_mut().find(|(s, _)| s.atom == t.atom && s.prefix == t.prefix) {
                    Some((_, e)) => *e += i64::from(t.exp) * k,
                    None => terms.push((*t, i64::from(t.exp) * k)),
                }
            }
        }
        let bound = i64::from(MAX_EXPONENT);
        if dim.iter().chain(terms.iter().map(|(_, e)| e)).any(|e| e.abs() > bound) {
            return None;
        }
        let dimension = Dimension::from_exponents(dim.map(|e| e as i32))?;
        let terms =
            terms.into_iter().filter(|(_, e)| *e != 0).map(|(t, e)| Term { exp: e as i8, ..t }).collect();
        Some(Self { terms, dimension })
    }

    /// Multiplies the exact ratio by (this unit's SI factor)^sign, sign = ±1.
    fn scale(&self, r: &mut Ratio, sign: i32) {
        let (mut pow10, mut pi) = (0i64, 0i64);
        for t in &self.terms {
            let a = atom_of(t.atom);
            let e = i64::from(t.exp) * i64::from(sign);
            pow10 += (i64::from(a.pow10) + i64::from(t.prefix)) * e;
            pi += i64::from(a.pi) * e;
            let (n, d) = (Big::from_u64(a.num), Big::from_u64(a.den));
            let (n, d) = (n.pow(e.unsigned_abs() as u32), d.pow(e.unsigned_abs() as u32));
            if e > 0 { r.scale(&n, &d) } else { r.scale(&d, &n) }
        }
        // π^k enters as (PI_DIGITS · 10^PI_EXP10)^k
        if pi != 0 {
            let p = big_from_digits(PI_DIGITS).pow(pi.unsigned_abs() as u32);
            let one = Big::from_u64(1);
            if pi > 0 {
                r.scale(&p, &one)
            } else {
                r.scale(&one, &p)
            }
            pow10 += PI_EXP10 * pi;
        }
        r.scale_pow10(pow10);
    }

    /// log₁₀ of the SI factor, to pre-screen overflow before exact arithmetic.
    fn log10_factor(&self) -> f64 {
        self.terms
            .iter()
            .map(|t| {
                let a = atom_of(t.atom);
                let l = (a.num as f64).log10() - (a.den as f64).log10()
                    + f64::from(a.pow10)
                    + f64::from(t.prefix)
                    + f64::from(a.pi) * LOG10_PI;
                f64::from(t.exp) * l
            })
            .sum()
    }

    /// The SI value of one of this unit, rounded once (`Unit::parse("slug")?.factor()` is
    /// 14.593902937206364, the `f64` nearest to 0.45359237 · 9.80665 / 0.3048).
    ///
    /// Book: (15.19.1)–(15.19.2).
    ///
    /// # Errors
    /// [`UnitError::Overflow`] or [`UnitError::Underflow`] for an extreme product of prefixes
    /// (`Em^16*Es^-16`).
    pub fn factor(&self) -> Result<f64, UnitError> {
        self.convert(1.0, &Self::si(self.dimension))
    }

    /// x in this unit converted to `to`: the exact value x · factor(self) / factor(to),
    /// rounded once.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`UnitError::DimensionMismatch`] when the dimensions differ; [`UnitError::NonFinite`]
    /// for non-finite x; [`UnitError::Overflow`] / [`UnitError::Underflow`] when the result
    /// leaves the normal `f64` range.
    pub fn convert(&self, x: f64, to: &Unit) -> Result<f64, UnitError> {
        let text = || format!("{x:e} {self}");
        if self.dimension != to.dimension {
            let t = text();
            return Err(UnitError::DimensionMismatch {
                span: 0..t.len(),
                text: t,
                expected: to.dimension,
                given: self.dimension,
                unit: self.to_string(),
            });
        }
        if !x.is_finite() {
            let t = text();
            return Err(UnitError::NonFinite { span: 0..t.len(), number: format!("{x}"), text: t });
        }
        let (mag, negative) = ratio_of_f64(x);
        let log10 = if x == 0.0 { 0.0 } else { x.abs().log10() };
        round_conversion(mag, negative, log10, self, to).map_err(|k| {
            let t = text();
            k.into_error(t.clone(), 0..t.len(), to)
        })
    }

    /// x in this unit converted to SI (the coherent unit of its dimension), rounded once.
    ///
    /// # Errors
    /// As [`Unit::convert`].
    pub fn to_si(&self, x: f64) -> Result<f64, UnitError> {
        self.convert(x, &Self::si(self.dimension))
    }

    /// An SI value expressed in this unit, rounded once.
    ///
    /// # Errors
    /// As [`Unit::convert`].
    pub fn from_si(&self, si: f64) -> Result<f64, UnitError> {
        Self::si(self.dimension).convert(si, self)
    }

    /// Product of this unit with `other` (`ft` · `lbf` = `ft*lbf`).
    ///
    /// # Errors
    /// [`UnitError::ExponentOutOfRange`] past ±[`MAX_EXPONENT`].
    pub fn mul(&self, other: &Unit) -> Result<Unit, UnitError> {
        self.checked_mul(other).ok_or_else(|| self.exponent_error(other))
    }

    /// Quotient of this unit by `other` (`ft` / `s^2` = `ft/s^2`).
    ///
    /// # Errors
    /// [`UnitError::ExponentOutOfRange`] past ±[`MAX_EXPONENT`].
    pub fn div(&self, other: &Unit) -> Result<Unit, UnitError> {
        other.checked_pow(-1).and_then(|inv| self.checked_mul(&inv)).ok_or_else(|| self.exponent_error(other))
    }

    /// This unit to the integer power n.
    ///
    /// # Errors
    /// [`UnitError::ExponentOutOfRange`] past ±[`MAX_EXPONENT`].
    pub fn powi(&self, n: i32) -> Result<Unit, UnitError> {
        self.checked_pow(n).ok_or_else(|| {
            let text = format!("({self})^{n}");
            UnitError::ExponentOutOfRange {
                span: 0..text.len(),
                text,
                exponent: i64::from(n),
                max: MAX_EXPONENT,
            }
        })
    }

    fn exponent_error(&self, other: &Unit) -> UnitError {
        let text = format!("({self}) and ({other})");
        UnitError::ExponentOutOfRange { span: 0..text.len(), text, exponent: 0, max: MAX_EXPONENT }
    }
}

/// Why a conversion did not give a normal `f64`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum RangeFault {
    Overflow,
    Underflow,
}

impl RangeFault {
    pub(crate) fn into_error(self, text: String, span: core::ops::Range<usize>, to: &Unit) -> UnitError {
        let target = to.to_string();
        match self {
            Self::Overflow => UnitError::Overflow { text, span, target },
            Self::Underflow => UnitError::Underflow { text, span, target },
        }
    }
}

/// Exact |x| (as a ratio, with its sign and an estimate of log₁₀|x|) converted from `from` to
/// `to` and rounded once. The estimate screens out results far outside the `f64` range before
/// the exact arithmetic, which keeps the integers small.
pub(crate) fn round_conversion(
    mut mag: Ratio,
    negative: bool,
    log10_mag: f64,
    from: &Unit,
    to: &Unit,
) -> Result<f64, RangeFault> {
    if mag.num.is_zero() {
        return Ok(if negative { -0.0 } else { 0.0 });
    }
    let estimate = log10_mag + from.log10_factor() - to.log10_factor();
    // f64 spans 10^−307.65 … 10^308.25; the estimate is good to far better than ±1 decade
    if estimate > 310.0 {
        return Err(RangeFault::Overflow);
    }
    if estimate < -310.0 {
        return Err(RangeFault::Underflow);
    }
    from.scale(&mut mag, 1);
    to.scale(&mut mag, -1);
    match mag.to_f64() {
        Rounded::Value(v) => Ok(if negative { -v } else { v }),
        Rounded::Overflow => Err(RangeFault::Overflow),
        Rounded::Underflow => Err(RangeFault::Underflow),
    }
}

fn prefix_symbol(p: i8) -> &'static str {
    if p == 0 { "" } else { PREFIXES.iter().find(|(_, e)| *e == p).map_or("?", |(s, _)| s) }
}

fn write_term(f: &mut fmt::Formatter<'_>, t: &Term, exp: i8) -> fmt::Result {
    let sym = if t.atom == G0_INDEX { "g0" } else { atom_of(t.atom).symbol };
    write!(f, "{}{sym}", prefix_symbol(t.prefix))?;
    if exp != 1 { write!(f, "^{exp}") } else { Ok(()) }
}

impl fmt::Display for Unit {
    /// `slug*ft^2`, `ft/s^2`, `1/s`, `1` (dimensionless, no factor).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let up: Vec<_> = self.terms.iter().filter(|t| t.exp > 0).collect();
        if up.is_empty() {
            f.write_str("1")?;
        }
        for (i, t) in up.iter().enumerate() {
            if i > 0 {
                f.write_str("*")?;
            }
            write_term(f, t, t.exp)?;
        }
        for t in self.terms.iter().filter(|t| t.exp < 0) {
            f.write_str("/")?;
            write_term(f, t, -t.exp)?;
        }
        Ok(())
    }
}
