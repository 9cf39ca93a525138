//! Unit systems for outputs: SI and the book's English engineering units.

use core::fmt;
use core::str::FromStr;

use serde::{Deserialize, Serialize};

use crate::table::resolve;
use crate::unit::Term;
use crate::{Dimension, Unit, UnitError};

/// The unit system in which values are written out: headers, plot axes, summaries.
///
/// * `Si`: kg, m, s, rad and coherent products, with the named units N, N*m, W, Pa, Hz, N/m,
///   N*s/m, N*m/rad, N*m*s/rad for their dimensions.
/// * `Imperial`: the book's English engineering (gravitational) system, slug, ft, s, rad, with
///   lbf for force and ft*lbf for moment and energy (also ft*lbf/s, lbf/ft^2, lbf/ft,
///   lbf*s/ft, ft*lbf/rad, ft*lbf*s/rad). It is coherent: 1 lbf = 1 slug·ft/s² (15.19.1), so
///   the kernel's equations hold in it unchanged.
///
/// Angles stay in radians in both systems (a bare number in a scene is radians).
///
/// Book: §15.19, (15.19.1)–(15.19.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum UnitSystem {
    /// SI units (the kernel's own).
    #[default]
    Si,
    /// slug, ft, s, rad; lbf.
    Imperial,
}

/// A unit as (symbol, exponent) factors.
type Factors = &'static [(&'static str, i8)];

/// Named units preferred over the base-unit product, per system: (dimension, SI, imperial).
const PREFERRED: [(Dimension, Factors, Factors); 10] = [
    (Dimension::FORCE, &[("N", 1)], &[("lbf", 1)]),
    (Dimension::MOMENT, &[("N", 1), ("m", 1)], &[("ft", 1), ("lbf", 1)]),
    (Dimension::POWER, &[("W", 1)], &[("ft", 1), ("lbf", 1), ("s", -1)]),
    (Dimension::PRESSURE, &[("Pa", 1)], &[("lbf", 1), ("ft", -2)]),
    (Dimension::FREQUENCY, &[("Hz", 1)], &[("Hz", 1)]),
    (Dimension::STIFFNESS, &[("N", 1), ("m", -1)], &[("lbf", 1), ("ft", -1)]),
    (Dimension::DAMPING, &[("N", 1), ("s", 1), ("m", -1)], &[("lbf", 1), ("s", 1), ("ft", -1)]),
    (
        Dimension::ROTATIONAL_STIFFNESS,
        &[("N", 1), ("m", 1), ("rad", -1)],
        &[("ft", 1), ("lbf", 1), ("rad", -1)],
    ),
    (
        Dimension::ROTATIONAL_DAMPING,
        &[("N", 1), ("m", 1), ("s", 1), ("rad", -1)],
        &[("ft", 1), ("lbf", 1), ("s", 1), ("rad", -1)],
    ),
    (Dimension::MOMENTUM, &[("kg", 1), ("m", 1), ("s", -1)], &[("slug", 1), ("ft", 1), ("s", -1)]),
];

/// A unit from (symbol, exponent) pairs of known symbols.
fn compose(parts: &[(&str, i8)], dimension: Dimension) -> Unit {
    let mut terms = Vec::new();
    for &(sym, exp) in parts {
        // the symbols above are all in the table (tested in `preferred_units_parse`)
        let Some((prefix, atom)) = resolve(sym) else { return Unit::si(dimension) };
        terms.push(Term { atom, prefix, exp });
    }
    Unit::from_terms(terms, dimension)
}

impl UnitSystem {
    /// The unit this system writes a dimension in (`ft/s` for velocity in imperial).
    ///
    /// Book: §15.19.
    pub fn unit(self, dimension: Dimension) -> Unit {
        if let Some((_, si, imperial)) = PREFERRED.iter().find(|(d, _, _)| *d == dimension) {
            return compose(if self == Self::Si { si } else { imperial }, dimension);
        }
        match self {
            Self::Si => Unit::si(dimension),
            Self::Imperial => {
                let [m, l, t, a] = dimension.exponents();
                let parts = [("slug", m), ("ft", l), ("s", t), ("rad", a)];
                let parts: Vec<_> = parts.into_iter().filter(|(_, e)| *e != 0).collect();
                compose(&parts, dimension)
            }
        }
    }

    /// The label of a dimension in this system, for headers and axes: `rad/s`, `ft/s^2`,
    /// `slug*ft^2`.
    pub fn label(self, dimension: Dimension) -> String {
        self.unit(dimension).to_string()
    }

    /// An SI value written in this system's unit for `dimension`, rounded once.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`UnitError::NonFinite`] for a non-finite value; [`UnitError::Overflow`] /
    /// [`UnitError::Underflow`] when the converted value leaves the normal `f64` range
    /// (1e308 m is 3.3e308 ft).
    pub fn value_from_si(self, dimension: Dimension, si: f64) -> Result<f64, UnitError> {
        self.unit(dimension).from_si(si)
    }

    /// A value in this system's unit for `dimension`, converted to SI, rounded once.
    ///
    /// # Errors
    /// As [`UnitSystem::value_from_si`].
    pub fn value_to_si(self, dimension: Dimension, value: f64) -> Result<f64, UnitError> {
        self.unit(dimension).to_si(value)
    }

    /// An SI value as a quantity string in this system, `"32.17404855643045 ft/s^2"`, which
    /// [`crate::Quantity::parse`] reads back (to the same SI value within two roundings).
    ///
    /// # Errors
    /// As [`UnitSystem::value_from_si`].
    pub fn format(self, dimension: Dimension, si: f64) -> Result<String, UnitError> {
        let v = self.value_from_si(dimension, si)?;
        let unit = self.unit(dimension);
        Ok(if unit == Unit::one() { format!("{v:?}") } else { format!("{v:?} {unit}") })
    }

    /// A [`Converter`](crate::Converter) from SI to this system's unit for `dimension`, for
    /// writing many values (two roundings each instead of one).
    ///
    /// # Errors
    /// As [`crate::Converter::new`] (never for the units of these two systems).
    pub fn converter(self, dimension: Dimension) -> Result<crate::Converter, UnitError> {
        crate::Converter::new(&self.unit(dimension))
    }

    /// The system's name as written on a command line: `si`, `imperial`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Si => "si",
            Self::Imperial => "imperial",
        }
    }
}

impl fmt::Display for UnitSystem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for UnitSystem {
    type Err = UnitError;

    /// `si` or `imperial` (ASCII case ignored).
    fn from_str(s: &str) -> Result<Self, UnitError> {
        match s.to_ascii_lowercase().as_str() {
            "si" => Ok(Self::Si),
            "imperial" => Ok(Self::Imperial),
            _ => Err(UnitError::UnknownSystem { name: s.to_string() }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn preferred_units_parse() {
        for (d, si, imp) in PREFERRED {
            for parts in [si, imp] {
                for (sym, _) in parts {
                    assert!(resolve(sym).is_some(), "{sym}");
                }
            }
            assert_eq!(UnitSystem::Si.unit(d).dimension(), d);
            assert_eq!(UnitSystem::Imperial.unit(d).dimension(), d);
        }
    }

    #[test]
    fn labels() {
        let imp = UnitSystem::Imperial;
        assert_eq!(UnitSystem::Si.label(Dimension::ANGULAR_VELOCITY), "rad/s");
        assert_eq!(imp.label(Dimension::VELOCITY), "ft/s");
        assert_eq!(imp.label(Dimension::ACCELERATION), "ft/s^2");
        assert_eq!(imp.label(Dimension::MOMENT_OF_INERTIA), "slug*ft^2");
        assert_eq!(imp.label(Dimension::MOMENT), "ft*lbf");
        assert_eq!(imp.label(Dimension::ANGULAR_VELOCITY), "rad/s");
        assert_eq!(UnitSystem::Si.label(Dimension::MOMENT), "N*m");
        assert_eq!(UnitSystem::Si.label(Dimension::MOMENT_OF_INERTIA), "kg*m^2");
        assert_eq!(UnitSystem::Si.label(Dimension::DIMENSIONLESS), "1");
        assert_eq!("Imperial".parse::<UnitSystem>(), Ok(UnitSystem::Imperial));
        assert!(matches!("cgs".parse::<UnitSystem>(), Err(UnitError::UnknownSystem { .. })));
    }
}
