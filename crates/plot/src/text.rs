//! Numbers rounded for reading: resolved vectors and matrices printed the way a textbook
//! prints them, without the last bits of round-off.
//!
//! `format!("{}", Rounded(&m))` prints a nalgebra matrix (or vector, slice, number) with
//! [`SIGNIFICANT`] significant digits, trailing zeros dropped; an entry within
//! [`ROUND_OFF`] of zero *relative to the largest entry of the same object* is printed as `0`
//! (so 𝓞_{B/A} of a quarter turn prints 0, not 6.123233995736766e-17); magnitudes outside
//! [10⁻⁴, 10⁶) are printed in scientific form (`1.5e-7`). The numbers themselves are never
//! changed: this is presentation only.
//!
//! ```
//! use vectrix_plot::Rounded;
//! let m = nalgebra::Matrix2::new(6.123233995736766e-17, -1.0, 1.0, 2.220446049250313e-16);
//! assert_eq!(format!("{}", Rounded(&m)), "[ 0  -1 ]\n[ 1   0 ]");
//! assert_eq!(format!("{}", Rounded(&[0.1 + 0.2, 1.5e-7, 2.0e3][..])), "[0.3, 1.5e-7, 2000]");
//! assert_eq!(format!("{}", Rounded(std::f64::consts::PI)), "3.14159");
//! ```

use core::fmt;

use nalgebra::{Dim, Matrix, RawStorage};

/// Significant digits printed.
pub const SIGNIFICANT: usize = 6;

/// Entries with |x| ≤ `ROUND_OFF` · max|entries| print as 0: 64ε, the round-off of a few
/// dozen operations on numbers of the size of the largest entry.
pub const ROUND_OFF: f64 = 64.0 * f64::EPSILON;

/// A value printed rounded for reading (see the module docs): `Rounded(x)` for an `f64`,
/// `Rounded(&v[..])` for a slice, `Rounded(&m)` for a nalgebra matrix or vector.
#[derive(Debug, Clone, Copy)]
pub struct Rounded<T>(pub T);

/// One number with [`SIGNIFICANT`] digits, `0` when |x| ≤ `zero_below`.
fn number(x: f64, zero_below: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x.abs() <= zero_below || x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-4..1e6).contains(&a) {
        // Digits after the point so that SIGNIFICANT digits show in total.
        let int_digits = a.log10().floor() as i32 + 1;
        let decimals = (SIGNIFICANT as i32 - int_digits).max(0) as usize;
        let s = format!("{x:.decimals$}");
        let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s };
        // Rounding can leave "-0" for tiny negatives within the digits shown.
        if s == "-0" { "0".into() } else { s }
    } else {
        let s = format!("{x:.prec$e}", prec = SIGNIFICANT - 1);
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{exp}")
    }
}

fn zero_below(xs: impl Iterator<Item = f64>) -> f64 {
    ROUND_OFF * xs.filter(|x| x.is_finite()).fold(0.0_f64, |m, x| m.max(x.abs()))
}

impl fmt::Display for Rounded<f64> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&number(self.0, 0.0))
    }
}

/// An absent value (a margin with no crossover, python-control's `inf`) prints as `none`.
impl fmt::Display for Rounded<Option<f64>> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(x) => f.write_str(&number(x, 0.0)),
            None => f.write_str("none"),
        }
    }
}

impl fmt::Display for Rounded<&[f64]> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let z = zero_below(self.0.iter().copied());
        let items: Vec<String> = self.0.iter().map(|&x| number(x, z)).collect();
        write!(f, "[{}]", items.join(", "))
    }
}

/// A column vector prints on one line, `[x, y, z]`; a matrix prints one bracketed row per
/// line with right-aligned columns.
impl<R: Dim, C: Dim, S: RawStorage<f64, R, C>> fmt::Display for Rounded<&Matrix<f64, R, C, S>> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = self.0;
        let z = zero_below(m.iter().copied());
        let (rows, cols) = m.shape();
        if cols == 1 {
            let items: Vec<String> = (0..rows).map(|r| number(m[(r, 0)], z)).collect();
            return write!(f, "[{}]", items.join(", "));
        }
        let cells: Vec<Vec<String>> =
            (0..rows).map(|r| (0..cols).map(|c| number(m[(r, c)], z)).collect()).collect();
        let widths: Vec<usize> =
            (0..cols).map(|c| cells.iter().map(|row| row[c].chars().count()).max().unwrap_or(0)).collect();
        for (r, row) in cells.iter().enumerate() {
            if r > 0 {
                f.write_str("\n")?;
            }
            f.write_str("[")?;
            for (c, cell) in row.iter().enumerate() {
                let gap = if c == 0 { " " } else { "  " };
                write!(f, "{gap}{cell:>w$}", w = widths[c])?;
            }
            f.write_str(" ]")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tour's quarter turn: cos(π/2) and round-off print as 0, ±1 as integers.
    #[test]
    fn quarter_turn_round_off_prints_as_zero() {
        let (s, c) = std::f64::consts::FRAC_PI_2.sin_cos();
        let o = nalgebra::Matrix3::new(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);
        assert_eq!(format!("{}", Rounded(&o)), "[  0  1  0 ]\n[ -1  0  0 ]\n[  0  0  1 ]");
        let v = nalgebra::Vector3::new(2.220446049250313e-16, -1.0, 0.0);
        assert_eq!(format!("{}", Rounded(&v)), "[0, -1, 0]");
    }

    /// A legitimately small entry is kept (in scientific form) when it is above round-off
    /// relative to the largest entry.
    #[test]
    fn small_entries_above_round_off_are_kept() {
        assert_eq!(format!("{}", Rounded(&[1.0, 1e-10][..])), "[1, 1e-10]");
        assert_eq!(format!("{}", Rounded(&[1.0, 1e-13][..])), "[1, 1e-13]");
        // At and below 64ε ≈ 1.4e-14 of the largest entry: round-off.
        assert_eq!(format!("{}", Rounded(&[1.0, 1e-14][..])), "[1, 0]");
        assert_eq!(format!("{}", Rounded(&[-1.0, 2.220446049250313e-16][..])), "[-1, 0]");
        assert_eq!(format!("{}", Rounded(&[1e-20, 2e-20][..])), "[1e-20, 2e-20]");
    }

    /// Six significant digits, trailing zeros dropped, scientific outside [1e-4, 1e6).
    #[test]
    fn six_significant_digits() {
        let cases = [
            (std::f64::consts::PI, "3.14159"),
            (-std::f64::consts::FRAC_1_SQRT_2, "-0.707107"),
            (123456.7, "123457"),
            (1234567.0, "1.23457e6"),
            (0.000123456789, "0.000123457"),
            (0.0000123456789, "1.23457e-5"),
            (2.5, "2.5"),
            (-0.0, "0"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-inf"),
        ];
        for (x, want) in cases {
            assert_eq!(format!("{}", Rounded(x)), want, "{x:e}");
        }
    }
}
