//! Quantities: a decimal number with a unit, converted exactly.

use core::fmt;
use core::ops::Range;

use crate::parse::{Decimal, quantity};
use crate::unit::round_conversion;
use crate::{Dimension, Unit, UnitError, UnitSystem};

/// A quantity string parsed: `"2.2046226218487757 lb"`, `"-32.174 ft/s^2"`, `"30 deg"`,
/// `"5"` (dimensionless).
///
/// The number is kept as the exact decimal written, so [`Quantity::to_si`] and
/// [`Quantity::to_unit`] compute number · factor exactly and round once: `"1 slug"` is the
/// `f64` nearest to 14.5939029372063656…, `"1 lbf"` the one nearest to 4.4482216152605.
///
/// Book: §15.19, (15.19.1)–(15.19.5).
///
/// # Conventions
/// The number as written must be zero or a normal finite `f64` (|x| between 2.2e−308 and
/// 1.8e308); a number without a unit is dimensionless (a scene's bare TOML number, which means
/// SI, is [`crate::Number::Bare`], not a quantity string).
#[derive(Debug, Clone, PartialEq)]
pub struct Quantity {
    text: String,
    number: Decimal,
    value: f64,
    number_span: Range<usize>,
    unit: Unit,
    unit_span: Option<Range<usize>>,
}

impl Quantity {
    /// Parses `<number> [<unit>]` (grammar in the crate documentation).
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`UnitError::TooLong`], [`UnitError::Malformed`], [`UnitError::UnknownUnit`] (with
    /// suggestions), [`UnitError::NonFinite`] (`inf`, `nan`), [`UnitError::ExponentOutOfRange`],
    /// and [`UnitError::Overflow`] / [`UnitError::Underflow`] for a number that is not itself a
    /// normal `f64` (`1e999 m`); every error carries the byte span of the fault.
    pub fn parse(text: &str) -> Result<Self, UnitError> {
        let p = quantity(text)?;
        Ok(Self {
            text: text.to_string(),
            number: p.number,
            value: p.value,
            number_span: p.number_span,
            unit: p.unit,
            unit_span: p.unit_span,
        })
    }

    /// The number as written, in its own unit (`"30 deg"` → 30.0).
    pub fn value(&self) -> f64 {
        self.value
    }

    /// The unit written (`1` for none).
    pub fn unit(&self) -> &Unit {
        &self.unit
    }

    /// The dimension of the unit written.
    pub fn dimension(&self) -> Dimension {
        self.unit.dimension()
    }

    /// The string this quantity was parsed from.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Byte span of the number in [`Quantity::text`].
    pub fn number_span(&self) -> Range<usize> {
        self.number_span.clone()
    }

    /// Byte span of the unit in [`Quantity::text`], `None` when no unit was written.
    pub fn unit_span(&self) -> Option<Range<usize>> {
        self.unit_span.clone()
    }

    /// The value in SI (kg, m, s, rad and their coherent products), after checking that the
    /// dimension is the one expected. One rounding: exact decimal × exact factor.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`UnitError::DimensionMismatch`] (naming both dimensions, spanning the unit) when the
    /// unit measures something else; [`UnitError::Overflow`] / [`UnitError::Underflow`] when
    /// the SI value leaves the normal `f64` range (`"1e308 mi"`).
    pub fn to_si(&self, expected: Dimension) -> Result<f64, UnitError> {
        self.check(expected)?;
        self.to_unit(&Unit::si(expected))
    }

    /// The SI value of whatever dimension the unit has.
    ///
    /// # Errors
    /// As [`Quantity::to_si`], without the dimension check.
    pub fn si(&self) -> Result<f64, UnitError> {
        self.to_unit(&Unit::si(self.dimension()))
    }

    /// The value in another unit of the same dimension, from the exact decimal: one rounding
    /// (`"400 kn"` in `ft/s` is the `f64` nearest to 400 · 1852/(3600 · 0.3048)).
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`UnitError::DimensionMismatch`] when the dimensions differ;
    /// [`UnitError::Overflow`] / [`UnitError::Underflow`] out of the normal `f64` range.
    pub fn to_unit(&self, unit: &Unit) -> Result<f64, UnitError> {
        self.check(unit.dimension())?;
        let (mag, log10) = self.number.magnitude();
        round_conversion(mag, self.number.negative, log10, &self.unit, unit)
            .map_err(|k| k.into_error(self.text.clone(), self.number_span.clone(), unit))
    }

    /// The value in the unit a [`UnitSystem`] uses for this quantity's dimension.
    ///
    /// # Errors
    /// As [`Quantity::to_unit`].
    pub fn in_system(&self, system: UnitSystem) -> Result<f64, UnitError> {
        self.to_unit(&system.unit(self.dimension()))
    }

    /// `Ok` when the unit's dimension is `expected`.
    ///
    /// # Errors
    /// [`UnitError::DimensionMismatch`] spanning the unit (or the whole text without a unit).
    pub fn check(&self, expected: Dimension) -> Result<(), UnitError> {
        if self.dimension() == expected {
            return Ok(());
        }
        Err(UnitError::DimensionMismatch {
            text: self.text.clone(),
            span: self.unit_span.clone().unwrap_or(0..self.text.len()),
            expected,
            given: self.dimension(),
            unit: self.unit.to_string(),
        })
    }
}

impl fmt::Display for Quantity {
    /// The exact decimal and the canonical unit: `2.2046226218487757 lb`, `-3.2174e1 ft/s^2`
    /// is written `-32.174 ft/s^2`; [`Quantity::parse`] reads it back to an equal quantity.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let d = &self.number;
        if d.negative {
            f.write_str("-")?;
        }
        if d.digits.is_empty() {
            f.write_str("0")?;
        } else {
            let n = d.digits.len() as i64;
            // scientific exponent of the leading digit
            let sci = n - 1 + d.exp10;
            if (-7..21).contains(&sci) {
                if d.exp10 >= 0 {
                    write!(f, "{}{}", d.digits, "0".repeat(d.exp10 as usize))?;
                } else if sci >= 0 {
                    let (a, b) = d.digits.split_at((sci + 1) as usize);
                    write!(f, "{a}.{b}")?;
                } else {
                    write!(f, "0.{}{}", "0".repeat((-sci - 1) as usize), d.digits)?;
                }
            } else {
                let (a, b) = d.digits.split_at(1);
                if b.is_empty() { write!(f, "{a}e{sci}")? } else { write!(f, "{a}.{b}e{sci}")? }
            }
        }
        if self.unit != Unit::one() {
            write!(f, " {}", self.unit)?;
        }
        Ok(())
    }
}
