//! The quantity grammar.
//!
//! ```text
//! quantity  = ws* number (ws* unit)? ws*
//! number    = [+-]? (digits ["." digits?] | "." digits) ([eE] [+-]? digits)?
//! unit      = power (ws* ("*" | "·" | "/") ws* power)*       left-associative: m/s/s = m/s^2
//! power     = primary ("^" [+-]? digits | superscript digits)?    |n| ≤ 16
//! primary   = symbol | "1" | "(" ws* unit ws* ")"                nesting ≤ 8
//! symbol    = exact symbol or alias | SI prefix + prefixable SI symbol
//! ```
//!
//! Whitespace may separate the number from the unit (`5 m`, `5m`, `30°`) and surround the
//! operators, but never replaces `*`: `kg m` is an error that says so. A string is at most
//! [`MAX_LEN`] bytes.

use core::ops::Range;

use crate::exact::{Big, Ratio, Rounded, big_from_digits};
use crate::table::{resolve, suggestions};
use crate::{MAX_EXPONENT, Unit, UnitError};

/// Longest quantity string accepted, in bytes.
pub const MAX_LEN: usize = 256;
/// Deepest nesting of parentheses accepted.
pub const MAX_DEPTH: usize = 8;

/// A parsed decimal number: (−1)^negative · digits · 10^exp10, kept exact.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Decimal {
    pub(crate) negative: bool,
    /// Significant digits, no leading zeros; empty for zero.
    pub(crate) digits: String,
    pub(crate) exp10: i64,
}

impl Decimal {
    /// The exact magnitude as a ratio and an estimate of its log₁₀ (0 for zero).
    pub(crate) fn magnitude(&self) -> (Ratio, f64) {
        let mut r = Ratio { num: big_from_digits(&self.digits), den: Big::from_u64(1) };
        if self.digits.is_empty() {
            return (r, 0.0);
        }
        r.scale_pow10(self.exp10);
        (r, self.log10())
    }

    fn log10(&self) -> f64 {
        let lead: f64 = self.digits.get(..17).unwrap_or(&self.digits).parse().unwrap_or(1.0);
        let shown = self.digits.len().min(17) as f64;
        lead.log10() + (self.digits.len() as f64 - shown) + self.exp10 as f64
    }
}

/// The parts of a quantity string.
#[derive(Debug, Clone)]
pub(crate) struct Parsed {
    pub(crate) number: Decimal,
    pub(crate) value: f64,
    pub(crate) number_span: Range<usize>,
    pub(crate) unit: Unit,
    pub(crate) unit_span: Option<Range<usize>>,
}

struct Parser<'a> {
    text: &'a str,
    pos: usize,
    depth: usize,
}

fn is_symbol_start(c: char) -> bool {
    c.is_alphabetic() || c == '°' || c == 'µ'
}

fn superscript(c: char) -> Option<u32> {
    match c {
        '⁰' => Some(0),
        '¹' => Some(1),
        '²' => Some(2),
        '³' => Some(3),
        '⁴' => Some(4),
        '⁵' => Some(5),
        '⁶' => Some(6),
        '⁷' => Some(7),
        '⁸' => Some(8),
        '⁹' => Some(9),
        _ => None,
    }
}

impl<'a> Parser<'a> {
    fn peek(&self) -> Option<char> {
        self.text[self.pos..].chars().next()
    }

    fn bump(&mut self) -> Option<char> {
        let c = self.peek()?;
        self.pos += c.len_utf8();
        Some(c)
    }

    fn skip_ws(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.bump();
        }
    }

    fn malformed(&self, span: Range<usize>, reason: impl Into<String>) -> UnitError {
        UnitError::Malformed { text: self.text.to_string(), span, reason: reason.into() }
    }

    fn here(&self) -> Range<usize> {
        let len = self.peek().map_or(0, char::len_utf8);
        self.pos..self.pos + len
    }

    /// An optional `+` or `-`; true for `-`.
    fn sign(&mut self) -> bool {
        match self.peek() {
            Some(c @ ('-' | '+')) => {
                self.bump();
                c == '-'
            }
            _ => false,
        }
    }

    fn digits(&mut self) -> &'a str {
        let start = self.pos;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.bump();
        }
        &self.text[start..self.pos]
    }

    /// number = [+-]? (digits ["." digits?] | "." digits) ([eE] [+-]? digits)?
    fn number(&mut self) -> Result<(Decimal, Range<usize>), UnitError> {
        let start = self.pos;
        let negative = self.sign();
        // inf, infinity, nan: a finite number is required
        let rest = &self.text[self.pos..];
        let word_len = rest.find(|c: char| !c.is_ascii_alphabetic()).unwrap_or(rest.len());
        let word = &rest[..word_len];
        if ["inf", "infinity", "nan"].iter().any(|w| w.eq_ignore_ascii_case(word)) {
            let span = start..self.pos + word_len;
            return Err(UnitError::NonFinite {
                text: self.text.to_string(),
                number: self.text[span.clone()].to_string(),
                span,
            });
        }
        let int = self.digits();
        let mut frac = "";
        if self.peek() == Some('.') {
            self.bump();
            frac = self.digits();
        }
        if int.is_empty() && frac.is_empty() {
            // span the sign (if any) and the character found instead of a digit
            return Err(self.malformed(start..self.here().end, "expected a number"));
        }
        let mut exp: i64 = 0;
        if matches!(self.peek(), Some('e' | 'E')) {
            let save = self.pos;
            self.bump();
            let sign = if self.sign() { -1 } else { 1 };
            let e = self.digits();
            if e.is_empty() {
                // not an exponent: `e` starts something else (and will be reported there)
                self.pos = save;
            } else {
                // saturate: anything past 10⁹ overflows or underflows anyway
                exp = sign * e.parse::<i64>().unwrap_or(1_000_000_000).min(1_000_000_000);
            }
        }
        let all = format!("{int}{frac}");
        let digits = all.trim_start_matches('0').trim_end_matches('0');
        let trailing = (all.trim_start_matches('0').len() - digits.len()) as i64;
        let number = Decimal {
            negative,
            digits: digits.to_string(),
            exp10: if digits.is_empty() { 0 } else { exp - frac.len() as i64 + trailing },
        };
        Ok((number, start..self.pos))
    }

    /// unit = power (ws* ("*" | "·" | "/") ws* power)*
    /// The bounds on exponents apply to the whole product, not to its partial products
    /// (`W^6/Hz^2` is T⁻¹⁶, within them, although `W^6` is not), so that whatever `Display`
    /// writes parses back.
    fn unit(&mut self) -> Result<Unit, UnitError> {
        let start = self.pos;
        let mut factors = vec![self.power()?];
        loop {
            let save = self.pos;
            self.skip_ws();
            let op = match self.peek() {
                Some('*' | '·' | '⋅') => 1,
                Some('/') => -1,
                _ => {
                    self.pos = save;
                    return Unit::checked_product(&factors)
                        .ok_or_else(|| self.exponent_error(start..self.pos, 0));
                }
            };
            self.bump();
            self.skip_ws();
            let (base, n) = self.power()?;
            factors.push((base, n * op));
        }
    }

    fn exponent_error(&self, span: Range<usize>, exponent: i64) -> UnitError {
        UnitError::ExponentOutOfRange { text: self.text.to_string(), span, exponent, max: MAX_EXPONENT }
    }

    /// power = primary ("^" [+-]? digits | superscripts)?
    /// A unit and its exponent, the power itself left to [`Unit::checked_product`] (which
    /// bounds only the whole product).
    fn power(&mut self) -> Result<(Unit, i32), UnitError> {
        let base = self.primary()?;
        let exp_start = self.pos;
        let n: i64 = if self.peek() == Some('^') {
            self.bump();
            let neg = self.sign();
            let d = self.digits();
            if d.is_empty() {
                return Err(self.malformed(exp_start..self.pos, "expected an integer exponent after `^`"));
            }
            let n = d.parse::<i64>().unwrap_or(i64::MAX);
            if neg { -n } else { n }
        } else if self.peek().is_some_and(|c| c == '⁻' || superscript(c).is_some()) {
            let neg = self.peek() == Some('⁻');
            if neg {
                self.bump();
            }
            let mut n: i64 = 0;
            while let Some(d) = self.peek().and_then(superscript) {
                self.bump();
                n = n.saturating_mul(10).saturating_add(i64::from(d));
            }
            if self.pos == exp_start + '⁻'.len_utf8() && neg {
                return Err(self.malformed(exp_start..self.pos, "expected superscript digits after `⁻`"));
            }
            if neg { -n } else { n }
        } else {
            return Ok((base, 1));
        };
        if n.abs() > i64::from(MAX_EXPONENT) {
            return Err(self.exponent_error(exp_start..self.pos, n));
        }
        Ok((base, n as i32))
    }

    /// primary = symbol | "1" | "(" unit ")"
    fn primary(&mut self) -> Result<Unit, UnitError> {
        let start = self.pos;
        match self.peek() {
            Some('(') => {
                if self.depth == MAX_DEPTH {
                    return Err(
                        self.malformed(self.here(), format!("parentheses nested deeper than {MAX_DEPTH}"))
                    );
                }
                self.bump();
                self.depth += 1;
                self.skip_ws();
                let u = self.unit()?;
                self.skip_ws();
                if self.peek() != Some(')') {
                    return Err(self.malformed(self.here(), "expected `)`"));
                }
                self.bump();
                self.depth -= 1;
                Ok(u)
            }
            Some('1') => {
                self.bump();
                if self.peek().is_some_and(|c| c.is_ascii_digit() || c == '.') {
                    return Err(self.malformed(
                        start..self.pos + 1,
                        "a unit may contain the number 1 only (as in `1/s`)",
                    ));
                }
                Ok(Unit::one())
            }
            Some(c) if is_symbol_start(c) => {
                while self
                    .peek()
                    .is_some_and(|c| c.is_alphabetic() || c.is_ascii_digit() || c == '_' || c == '°')
                {
                    self.bump();
                }
                let token = &self.text[start..self.pos];
                match resolve(token) {
                    Some((prefix, atom)) => Ok(Unit::atom(prefix, atom)),
                    None => Err(self.unknown(token, start..self.pos)),
                }
            }
            Some(c) => {
                Err(self
                    .malformed(self.here(), format!("unexpected `{c}`: expected a unit symbol, `1` or `(`")))
            }
            None => Err(self.malformed(self.pos..self.pos, "expected a unit symbol after the operator")),
        }
    }

    fn unknown(&self, token: &str, span: Range<usize>) -> UnitError {
        // `m2`, `s2`: a power written without `^`
        let letters = token.trim_end_matches(|c: char| c.is_ascii_digit());
        if letters.len() < token.len() && resolve(letters).is_some() {
            let power = &token[letters.len()..];
            return self.malformed(span, format!("write `{letters}^{power}` for a power"));
        }
        UnitError::UnknownUnit {
            text: self.text.to_string(),
            span,
            symbol: token.to_string(),
            suggestions: suggestions(token),
        }
    }
}

fn check_len(text: &str) -> Result<(), UnitError> {
    if text.len() > MAX_LEN { Err(UnitError::TooLong { len: text.len(), max: MAX_LEN }) } else { Ok(()) }
}

/// Parses `<number> [<unit>]`.
pub(crate) fn quantity(text: &str) -> Result<Parsed, UnitError> {
    check_len(text)?;
    let mut p = Parser { text, pos: 0, depth: 0 };
    p.skip_ws();
    if p.peek().is_none() {
        return Err(p.malformed(0..text.len(), "empty quantity"));
    }
    let (number, number_span) = p.number()?;
    let value = representable(&p, &number, &number_span)?;
    p.skip_ws();
    let (unit, unit_span) = if p.peek().is_none() {
        (Unit::one(), None)
    } else {
        let start = p.pos;
        let u = p.unit()?;
        (u, Some(start..p.pos))
    };
    p.skip_ws();
    if let Some(c) = p.peek() {
        let reason = if is_symbol_start(c) || c == '(' {
            format!("unexpected `{c}` after the unit: join factors with `*` or `/` (e.g. `kg*m^2`)")
        } else {
            format!("unexpected `{c}` after the unit")
        };
        return Err(p.malformed(p.here(), reason));
    }
    Ok(Parsed { number, value, number_span, unit, unit_span })
}

/// The number as written, which must itself be zero or a normal finite `f64`.
fn representable(p: &Parser<'_>, number: &Decimal, span: &Range<usize>) -> Result<f64, UnitError> {
    let target = || "the number as written".to_string();
    let err_over = || UnitError::Overflow { text: p.text.to_string(), span: span.clone(), target: target() };
    let err_under =
        || UnitError::Underflow { text: p.text.to_string(), span: span.clone(), target: target() };
    if number.digits.is_empty() {
        return Ok(if number.negative { -0.0 } else { 0.0 });
    }
    let (mag, _) = number.magnitude_screened().map_err(|over| if over { err_over() } else { err_under() })?;
    match mag.to_f64() {
        Rounded::Value(v) => Ok(if number.negative { -v } else { v }),
        Rounded::Overflow => Err(err_over()),
        Rounded::Underflow => Err(err_under()),
    }
}

impl Decimal {
    /// [`Decimal::magnitude`], refusing (Err(true) overflow, Err(false) underflow) numbers
    /// whose decimal exponent alone puts them far outside any `f64` range met in conversion.
    pub(crate) fn magnitude_screened(&self) -> Result<(Ratio, f64), bool> {
        let l = self.log10();
        if l > 400.0 {
            return Err(true);
        }
        if l < -400.0 {
            return Err(false);
        }
        Ok(self.magnitude())
    }
}

/// Parses a unit expression alone.
pub(crate) fn unit_only(text: &str) -> Result<Unit, UnitError> {
    check_len(text)?;
    let mut p = Parser { text, pos: 0, depth: 0 };
    p.skip_ws();
    let u = p.unit()?;
    p.skip_ws();
    if p.peek().is_some() {
        return Err(p.malformed(p.here(), "unexpected text after the unit: join factors with `*` or `/`"));
    }
    Ok(u)
}
