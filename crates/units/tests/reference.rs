//! Exact conversions against independent reference values (issue 21, item 1).
//!
//! `tests/data/units_reference.json` was written once by `scripts/units_reference.py`, which
//! defines every unit from its published exact definition (ft = 0.3048 m, lb = 0.45359237 kg,
//! g₀ = 9.80665 m/s², π from mpmath at 400 bits) and rounds the exact rational value of each
//! quantity once to the nearest double. The claim checked is the crate's: a conversion is
//! correctly rounded, so the expected values are compared bit for bit (tolerance zero).

use serde::Deserialize;
use vectrix_units::{Dimension, Quantity, Unit};

#[derive(Deserialize)]
struct SiCase {
    text: String,
    dimension: [i8; 4],
    bits: String,
}

#[derive(Deserialize)]
struct Conversion {
    text: String,
    target: String,
    bits: String,
}

#[derive(Deserialize)]
struct Reference {
    si: Vec<SiCase>,
    conversions: Vec<Conversion>,
}

fn reference() -> Reference {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/units_reference.json");
    let text = std::fs::read_to_string(path).expect("reference data checked in");
    serde_json::from_str(&text).expect("valid reference JSON")
}

fn bits(hex: &str) -> f64 {
    f64::from_bits(u64::from_str_radix(hex.trim_start_matches("0x"), 16).expect("hex bits"))
}

// Every unit alone, prefixed SI units, the book's data (slug·ft², 32.174 ft/s², 400 kn, 30°)
// and 300 random products of up to three powered, prefixed units with random 1–17 digit
// numbers: each SI value is the exact value rounded once.
#[test]
fn eq_15_19_1_every_conversion_is_correctly_rounded() {
    let r = reference();
    assert!(r.si.len() > 350, "the reference set is complete");
    for case in &r.si {
        let [m, l, t, a] = case.dimension;
        let q = Quantity::parse(&case.text).unwrap_or_else(|e| panic!("{}: {e}", case.text));
        let got = q.to_si(Dimension::new(m, l, t, a)).unwrap_or_else(|e| panic!("{}: {e}", case.text));
        let want = bits(&case.bits);
        assert_eq!(got.to_bits(), want.to_bits(), "{}: got {got:e}, want {want:e}", case.text);
    }
}

// Conversions between two non-SI units round once too (400 kn in ft/s, 14.59 kg in slug).
#[test]
fn conversions_between_units_are_correctly_rounded() {
    for c in reference().conversions {
        let target = Unit::parse(&c.target).expect("target unit");
        let got = Quantity::parse(&c.text).and_then(|q| q.to_unit(&target)).expect("converts");
        let want = bits(&c.bits);
        assert_eq!(got.to_bits(), want.to_bits(), "{} in {}: got {got:e}, want {want:e}", c.text, c.target);
    }
}
