//! Bulk conversion with a precomputed factor, for writing many values (trajectory columns).

use crate::{Unit, UnitError};

/// Converts between SI and one unit with the unit's factor f = RN(SI value of 1 unit),
/// computed once: `from_si(x) = x / f`, `to_si(x) = x · f`.
///
/// Each conversion rounds twice (f, then the division or product), so it is within 2u|x|
/// (u = 2⁻⁵³) of the exact value that [`Unit::from_si`] rounds once; in exchange it costs one
/// floating-point operation instead of exact rational arithmetic (about a microsecond). Use it
/// for outputs; inputs (scene values, catalogues) go through [`crate::Quantity`].
///
/// Book: §15.19.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Converter {
    factor: f64,
}

impl Converter {
    /// The converter of `unit`.
    ///
    /// # Errors
    /// [`UnitError::Overflow`] / [`UnitError::Underflow`] when the unit's own factor leaves
    /// the normal `f64` range (an extreme product of prefixes).
    pub fn new(unit: &Unit) -> Result<Self, UnitError> {
        Ok(Self { factor: unit.factor()? })
    }

    /// The SI value of one unit, f.
    pub fn factor(&self) -> f64 {
        self.factor
    }

    /// An SI value in the unit, x / f.
    ///
    /// # Errors
    /// [`UnitError::NonFinite`] for a non-finite x; [`UnitError::Overflow`] when x / f
    /// exceeds `f64::MAX`; [`UnitError::Underflow`] when a nonzero x / f is below the
    /// smallest normal `f64`.
    #[inline]
    pub fn from_si(&self, si: f64) -> Result<f64, UnitError> {
        checked(si, si / self.factor)
    }

    /// A value in the unit, in SI, x · f.
    ///
    /// # Errors
    /// As [`Converter::from_si`].
    #[inline]
    pub fn to_si(&self, x: f64) -> Result<f64, UnitError> {
        checked(x, x * self.factor)
    }
}

#[inline]
fn checked(x: f64, y: f64) -> Result<f64, UnitError> {
    if y.is_normal() || y == 0.0 && x == 0.0 {
        return Ok(y);
    }
    let text = format!("{x:e}");
    let span = 0..text.len();
    let target = "the converted unit".to_string();
    Err(if !x.is_finite() {
        UnitError::NonFinite { number: text.clone(), text, span }
    } else if !y.is_finite() {
        UnitError::Overflow { text, span, target }
    } else {
        UnitError::Underflow { text, span, target }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Dimension, UnitSystem};

    // Two roundings: within 2u|x| of the correctly rounded conversion's exact value.
    #[test]
    fn converter_is_within_two_roundings_of_the_exact_conversion() {
        let u = f64::EPSILON / 2.0;
        for unit in ["ft", "slug*ft^2", "ft*lbf", "deg/s", "psi", "kn", "mi/h"] {
            let unit = Unit::parse(unit).unwrap();
            let c = Converter::new(&unit).unwrap();
            for x in [1.0, -3.75, 1e-300, 6.02e23, 123.456] {
                let exact = unit.from_si(x).unwrap();
                let fast = c.from_si(x).unwrap();
                assert!((fast - exact).abs() <= 2.0 * u * exact.abs(), "{unit}: {fast:e} vs {exact:e}");
                let back = c.to_si(fast).unwrap();
                assert!((back - x).abs() <= 4.0 * u * x.abs() * (1.0 + u), "{unit}: {back:e} vs {x:e}");
            }
        }
        let ft = Converter::new(&UnitSystem::Imperial.unit(Dimension::LENGTH)).unwrap();
        assert!(matches!(ft.from_si(1e308), Err(UnitError::Overflow { .. })));
        assert!(matches!(ft.to_si(f64::NAN), Err(UnitError::NonFinite { .. })));
        assert!(matches!(ft.to_si(1e-308), Err(UnitError::Underflow { .. })));
        assert_eq!(ft.from_si(0.0), Ok(0.0));
    }
}
