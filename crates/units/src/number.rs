//! `Number`: what a scene file may write where a physical value goes.

use core::fmt;

use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize, Serializer};

use crate::{Dimension, Quantity, UnitError};

/// A value in a scene file: a bare number, which means SI (radians for angles), or a quantity
/// string with a unit, `"2.2046226218487757 lb"`, `"30 deg"`, `"-32.174 ft/s^2"`.
///
/// Deserializes from a TOML/JSON float or integer (`Bare`) or string (`Text`); anything else
/// is an error that says what is accepted. A loader keeps the span with
/// `toml::Spanned<Number>` and calls [`Number::to_si`] with the key's dimension.
///
/// Book: §15.19.
#[derive(Debug, Clone, PartialEq)]
pub enum Number {
    /// A bare number, already in SI.
    Bare(f64),
    /// A quantity string, parsed by [`Quantity::parse`].
    Text(String),
}

impl Number {
    /// The SI value: a bare number as it is, a quantity string converted after checking its
    /// dimension against `expected`.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// [`UnitError::NonFinite`] for a bare `inf`/`nan` (TOML allows them); every error of
    /// [`Quantity::parse`] and [`Quantity::to_si`] for a string, with its byte span.
    pub fn to_si(&self, expected: Dimension) -> Result<f64, UnitError> {
        match self {
            Self::Bare(x) if x.is_finite() => Ok(*x),
            Self::Bare(x) => {
                let text = format!("{x}");
                Err(UnitError::NonFinite { span: 0..text.len(), number: text.clone(), text })
            }
            Self::Text(s) => Quantity::parse(s)?.to_si(expected),
        }
    }

    /// The parsed quantity of a `Text`, `None` for a bare number.
    ///
    /// # Errors
    /// As [`Quantity::parse`].
    pub fn quantity(&self) -> Result<Option<Quantity>, UnitError> {
        match self {
            Self::Bare(_) => Ok(None),
            Self::Text(s) => Quantity::parse(s).map(Some),
        }
    }
}

impl From<f64> for Number {
    fn from(x: f64) -> Self {
        Self::Bare(x)
    }
}

impl From<&str> for Number {
    fn from(s: &str) -> Self {
        Self::Text(s.to_string())
    }
}

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Bare(x) => write!(f, "{x:?}"),
            Self::Text(s) => f.write_str(s),
        }
    }
}

impl Serialize for Number {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Self::Bare(x) => s.serialize_f64(*x),
            Self::Text(t) => s.serialize_str(t),
        }
    }
}

struct NumberVisitor;

impl Visitor<'_> for NumberVisitor {
    type Value = Number;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a number (in SI units) or a quantity string such as \"2.5 m\" or \"30 deg\"")
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Number, E> {
        Ok(Number::Bare(v))
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Number, E> {
        Ok(Number::Bare(v as f64))
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Number, E> {
        Ok(Number::Bare(v as f64))
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Number, E> {
        Ok(Number::Text(v.to_string()))
    }
}

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NumberVisitor)
    }
}
