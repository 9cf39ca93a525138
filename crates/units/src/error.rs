//! Errors of quantity parsing and conversion, with byte spans inside the quantity text.

use core::ops::Range;

use thiserror::Error;

use crate::Dimension;
use crate::table::{ALIASES, ATOMS, G0, PREFIXES};

/// The list of valid units printed in messages.
pub fn valid_units() -> String {
    let prefixable: Vec<_> = ATOMS.iter().filter(|a| a.prefixable).map(|a| a.symbol).collect();
    let plain: Vec<_> = ATOMS.iter().filter(|a| !a.prefixable).map(|a| a.symbol).chain([G0.symbol]).collect();
    let prefixes: Vec<_> = PREFIXES.iter().map(|(p, _)| *p).collect();
    let aliases: Vec<_> = ALIASES.iter().map(|(a, s)| format!("{a} = {s}")).collect();
    format!(
        "{} (these take the SI prefixes {}), {} (aliases {}); combine them with `*`, `/`, `^n` and \
         parentheses, e.g. `kg*m^2`, `ft/s^2`, `N*m`",
        prefixable.join(" "),
        prefixes.join(" "),
        plain.join(" "),
        aliases.join(", ")
    )
}

fn suggest(s: &[&str]) -> String {
    if s.is_empty() { String::new() } else { format!("; did you mean {}?", s.join(", ")) }
}

/// What is wrong with a quantity string or a conversion, where (byte span in the text), and
/// what would be valid.
///
/// Book: §15.19.
///
/// # Conventions
/// `text` is the whole quantity string as given (for a bare number or an SI value being
/// converted, its decimal form); `span` is a byte range inside `text`. A scene loader adds the
/// offset of the string in its file, see [`UnitError::span_in_source`].
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum UnitError {
    /// The string is longer than the grammar accepts.
    #[error("quantity of {len} bytes: at most {max} bytes are accepted")]
    TooLong {
        /// Its length in bytes.
        len: usize,
        /// The limit.
        max: usize,
    },
    /// The string does not follow the grammar `<number> [<unit>]`.
    #[error(
        "malformed quantity `{text}` at bytes {}..{}: {reason}; write `<number> <unit>`, e.g. `2.5 m`, `-32.174 ft/s^2`, `30 deg`",
        span.start, span.end
    )]
    Malformed {
        /// The quantity string.
        text: String,
        /// Where the fault is.
        span: Range<usize>,
        /// What was expected there.
        reason: String,
    },
    /// A unit symbol that is not in the table.
    #[error(
        "unknown unit `{symbol}` at bytes {}..{} of `{text}`{}; valid units: {}",
        span.start, span.end, suggest(suggestions), valid_units()
    )]
    UnknownUnit {
        /// The quantity string.
        text: String,
        /// Where the symbol is.
        span: Range<usize>,
        /// The symbol.
        symbol: String,
        /// Known symbols close to it (case or spelling), best first; may be empty.
        suggestions: Vec<&'static str>,
    },
    /// `inf`, `nan` or a non-finite bare number.
    #[error("non-finite number `{number}` in `{text}` at bytes {}..{}: a quantity must be a finite number", span.start, span.end)]
    NonFinite {
        /// The quantity string.
        text: String,
        /// Where the number is.
        span: Range<usize>,
        /// The number as written.
        number: String,
    },
    /// An exponent beyond ±[`crate::MAX_EXPONENT`], in a `^n` or in the resulting dimension.
    #[error("exponent {exponent} in `{text}` at bytes {}..{} is out of range: |exponent| ≤ {max}", span.start, span.end)]
    ExponentOutOfRange {
        /// The quantity string.
        text: String,
        /// Where the exponent is (or the whole unit, for an accumulated one).
        span: Range<usize>,
        /// The exponent.
        exponent: i64,
        /// The largest magnitude accepted.
        max: i32,
    },
    /// The unit measures another dimension than the one expected.
    #[error("dimension mismatch in `{text}`: expected {expected}, given {given} from unit `{unit}`")]
    DimensionMismatch {
        /// The quantity string.
        text: String,
        /// Where the unit is (the whole string when there is no unit).
        span: Range<usize>,
        /// The dimension the caller expects.
        expected: Dimension,
        /// The dimension of the unit written.
        given: Dimension,
        /// The unit as written (`1` when none).
        unit: String,
    },
    /// The converted value (or the number as written) exceeds the largest `f64`.
    #[error("`{text}` overflows in {target}: the value exceeds the largest finite f64 (1.797e308)")]
    Overflow {
        /// The quantity string.
        text: String,
        /// Where the number is.
        span: Range<usize>,
        /// The unit the value was converted to.
        target: String,
    },
    /// The converted value (or the number as written) is nonzero but below the smallest normal
    /// `f64` (2.2e−308): refused rather than silently flushed to zero or subnormal.
    #[error(
        "`{text}` underflows in {target}: the nonzero value is below the smallest normal f64 (2.225e-308)"
    )]
    Underflow {
        /// The quantity string.
        text: String,
        /// Where the number is.
        span: Range<usize>,
        /// The unit the value was converted to.
        target: String,
    },
    /// A unit-system name other than `si` or `imperial`.
    #[error("unknown unit system `{name}`; valid: si, imperial")]
    UnknownSystem {
        /// The name given.
        name: String,
    },
}

impl UnitError {
    /// The byte range inside the quantity text that the error points at (`0..len` for
    /// [`UnitError::TooLong`]).
    pub fn span(&self) -> Range<usize> {
        match self {
            Self::TooLong { len, .. } => 0..*len,
            Self::UnknownSystem { name } => 0..name.len(),
            Self::Malformed { span, .. }
            | Self::UnknownUnit { span, .. }
            | Self::NonFinite { span, .. }
            | Self::ExponentOutOfRange { span, .. }
            | Self::DimensionMismatch { span, .. }
            | Self::Overflow { span, .. }
            | Self::Underflow { span, .. } => span.clone(),
        }
    }

    /// The error's span as a byte range of a source file, given the span `literal` of the
    /// TOML (or JSON) string literal that held `text` (as `toml::Spanned` reports it: quotes
    /// included).
    ///
    /// When the literal is `"text"` or `'text'` verbatim (no escapes, one line), the result
    /// points inside it; otherwise (escapes, multi-line strings, a bare number) the whole
    /// literal is returned, which is still the right place to report.
    pub fn span_in_source(&self, source: &str, literal: Range<usize>) -> Range<usize> {
        let inner = self.span();
        let text = self.text();
        let Some(lit) = source.get(literal.clone()) else { return literal };
        let verbatim = lit.len() == text.len() + 2
            && (lit.starts_with('"') && !lit.contains('\\') || lit.starts_with('\''))
            && lit.get(1..lit.len() - 1) == Some(text);
        if verbatim && inner.end <= text.len() {
            literal.start + 1 + inner.start..literal.start + 1 + inner.end
        } else {
            literal
        }
    }

    /// The quantity text the span refers to (empty for [`UnitError::TooLong`]).
    pub fn text(&self) -> &str {
        match self {
            Self::TooLong { .. } => "",
            Self::UnknownSystem { name } => name,
            Self::Malformed { text, .. }
            | Self::UnknownUnit { text, .. }
            | Self::NonFinite { text, .. }
            | Self::ExponentOutOfRange { text, .. }
            | Self::DimensionMismatch { text, .. }
            | Self::Overflow { text, .. }
            | Self::Underflow { text, .. } => text,
        }
    }
}
