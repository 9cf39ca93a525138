//! Property tests of the units layer (issue 21, item 1): formatting round trips, conversions
//! are consistent both ways, products compose.
//!
//! Tolerances follow from the rounding count: every conversion rounds once to nearest, with
//! relative error at most u = ε/2 = 2⁻⁵³; a round trip through SI rounds twice, so it returns
//! within 2u·|x|·(1 + u) of where it started (one more u when the value is written as its
//! shortest decimal in between), and a product built from k separately rounded factors is
//! within k·u (to first order) of the exactly rounded one.

use proptest::prelude::*;
use vectrix_units::{Dimension, Measure, Quantity, Unit, UnitError, UnitSystem, kind};

/// Unit roundoff u = 2⁻⁵³.
const U: f64 = f64::EPSILON / 2.0;

/// Unit symbols with a prefix they accept: the grammar's whole vocabulary, prefixed SI forms
/// included.
const SYMBOLS: [&str; 34] = [
    "m", "km", "mm", "µm", "g", "kg", "mg", "s", "ms", "rad", "mrad", "Hz", "kHz", "N", "kN", "Pa", "MPa",
    "J", "W", "deg", "rev", "rpm", "min", "h", "ft", "in", "yd", "mi", "nmi", "lb", "lbf", "slug", "kn",
    "psi",
];

fn unit_expr() -> impl Strategy<Value = String> {
    let term = (prop::sample::select(&SYMBOLS[..]), prop_oneof![Just(1i32), -3i32..=3]);
    prop::collection::vec(term, 1..4)
        .prop_map(|terms| {
            let mut s = String::new();
            for (i, (sym, e)) in terms.iter().enumerate() {
                if i > 0 {
                    s.push(if *e < 0 { '/' } else { '*' });
                } else if *e < 0 {
                    s.push_str("1/");
                }
                s.push_str(sym);
                if e.abs() != 1 && *e != 0 {
                    s.push_str(&format!("^{}", e.abs()));
                }
            }
            s
        })
        // dimensions stay within ±16 (e.g. lbf^3*Pa*W^3 has T^-17: a typed error, tested elsewhere)
        .prop_filter("dimension exponents within bounds", |s| Unit::parse(s).is_ok())
}

/// Finite values biased toward the hard set: zero, tiny and huge magnitudes, integers, and
/// values next to powers of ten.
fn value() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => prop::num::f64::NORMAL,
        1 => prop::sample::select(vec![0.0, -0.0, 1.0, -1.0, 1e300, -1e-300, 1e-300, 3.0e307, f64::MIN_POSITIVE * 4.0]),
        1 => (-1_000_000i64..1_000_000).prop_map(|n| n as f64),
        1 => (-300i32..300).prop_map(|e| 10f64.powi(e) * (1.0 + f64::EPSILON)),
    ]
}

/// A decimal as written: 1–25 digits, a point somewhere, an exponent.
fn decimal() -> impl Strategy<Value = String> {
    ("[1-9][0-9]{0,24}", 0usize..26, -40i32..40, any::<bool>()).prop_map(|(d, point, e, neg)| {
        let p = point.min(d.len());
        let mant = if p < d.len() { format!("{}.{}", &d[..p.max(1)], &d[p.max(1)..]) } else { d.clone() };
        format!("{}{mant}e{e}", if neg { "-" } else { "" })
    })
}

fn in_range_or_range_error(r: Result<f64, UnitError>) -> Option<f64> {
    match r {
        Ok(v) => Some(v),
        Err(UnitError::Overflow { .. } | UnitError::Underflow { .. }) => None,
        Err(e) => panic!("unexpected {e}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    // Display writes the exact decimal and the canonical unit; parsing it gives back an equal
    // quantity and the same SI value, bit for bit.
    #[test]
    fn parse_of_display_round_trips(number in decimal(), unit in unit_expr()) {
        let text = format!("{number} {unit}");
        let Ok(q) = Quantity::parse(&text) else { return Ok(()) };
        let shown = q.to_string();
        let back = Quantity::parse(&shown).expect("display parses");
        prop_assert_eq!(back.unit(), q.unit());
        prop_assert_eq!(back.value().to_bits(), q.value().to_bits());
        match (q.si(), back.si()) {
            (Ok(a), Ok(b)) => prop_assert_eq!(a.to_bits(), b.to_bits(), "{} vs {}", text, shown),
            (a, b) => prop_assert_eq!(a.is_err(), b.is_err()),
        }
    }

    // x in a unit → SI → the unit again: two roundings, |back − x| ≤ 2u|x|(1 + u).
    #[test]
    fn conversions_are_consistent_both_ways(x in value(), unit in unit_expr()) {
        let u = Unit::parse(&unit).expect("generated units parse");
        let Some(si) = in_range_or_range_error(u.to_si(x)) else { return Ok(()) };
        let Some(back) = in_range_or_range_error(u.from_si(si)) else { return Ok(()) };
        prop_assert!((back - x).abs() <= 2.0 * U * x.abs() * (1.0 + U), "{x:e} {unit} → {si:e} → {back:e}");
        // x ft → m → ft, the case named by the issue, through the typed layer
        if let Ok(m) = Measure::<kind::Length>::new(x, "ft") {
            let ft = m.value_in("ft").expect("back to ft");
            prop_assert!((ft - x).abs() <= 2.0 * U * x.abs() * (1.0 + U));
        }
    }

    // Products compose: X*Y is the same unit as Y*X (factor ratio exactly 1), X*Y/Y is X, the
    // dimensions add, and the SI value of x X*Y agrees with the separately rounded
    // RN(x·f_X)·f_Y within four roundings.
    #[test]
    fn products_compose(x in value(), a in unit_expr(), b in unit_expr()) {
        let (ua, ub) = (Unit::parse(&a).unwrap(), Unit::parse(&b).unwrap());
        let Ok(ab) = Unit::parse(&format!("({a})*({b})")) else { return Ok(()) };
        let Ok(ba) = Unit::parse(&format!("({b})*({a})")) else { return Ok(()) };
        prop_assert_eq!(&ab, &ba);
        prop_assert_eq!(ab.dimension(), ua.dimension().checked_mul(&ub.dimension()).unwrap());
        prop_assert_eq!(ab.convert(x, &ba).unwrap().to_bits(), x.to_bits());
        if let Ok(back) = Unit::parse(&format!("({a})*({b})/({b})")) {
            prop_assert_eq!(back.convert(x, &ua).unwrap().to_bits(), x.to_bits());
        }
        let exact = in_range_or_range_error(ab.to_si(x));
        let xa = in_range_or_range_error(ua.to_si(x));
        let fb = in_range_or_range_error(ub.factor());
        if let (Some(exact), Some(xa), Some(fb)) = (exact, xa, fb) {
            let composed = xa * fb;
            if composed.is_finite() && composed.abs() >= f64::MIN_POSITIVE {
                prop_assert!((composed - exact).abs() <= 4.0 * U * exact.abs() * (1.0 + U),
                    "{x:e} ({a})*({b}): {exact:e} vs {composed:e}");
            }
        }
    }

    // A value written out in a unit system (`format`) reads back to the same SI value within
    // three roundings' worth: SI → unit (u), the shortest decimal that identifies that double
    // (within half its ulp, ≤ u relative), decimal → SI (u).
    #[test]
    fn formatted_outputs_parse_back(x in value(), d in prop::sample::select(vec![
        Dimension::LENGTH, Dimension::VELOCITY, Dimension::ACCELERATION, Dimension::MASS,
        Dimension::FORCE, Dimension::MOMENT, Dimension::MOMENT_OF_INERTIA, Dimension::ANGULAR_VELOCITY,
        Dimension::PRESSURE, Dimension::ANGULAR_MOMENTUM, Dimension::new(1, 3, -1, 2),
    ]), imperial in any::<bool>()) {
        let system = if imperial { UnitSystem::Imperial } else { UnitSystem::Si };
        let Ok(text) = system.format(d, x) else { return Ok(()) };
        let q = Quantity::parse(&text).expect("formatted quantity parses");
        let Some(back) = in_range_or_range_error(q.to_si(d)) else { return Ok(()) };
        prop_assert!((back - x).abs() <= 3.0 * U * x.abs() * (1.0 + 2.0 * U), "{x:e} → {text} → {back:e}");
        prop_assert_eq!(system.label(d), q.unit().to_string());
    }

    // Any string, biased toward the grammar's characters: parsing and conversion return a
    // value or a typed error, never panic, and an error's span lies inside the text on
    // character boundaries.
    #[test]
    fn arbitrary_strings_never_panic(text in "[0-9a-zA-Z .eE+*/^()µ°²⁻\\-]{0,40}|\\PC{0,300}") {
        match Quantity::parse(&text) {
            Ok(q) => {
                let _ = q.si();
                let _ = q.to_si(Dimension::LENGTH);
                prop_assert!(Quantity::parse(&q.to_string()).is_ok(), "{} shows as {}", text, q);
            }
            Err(e) => {
                let span = e.span();
                if !matches!(e, UnitError::TooLong { .. }) {
                    prop_assert!(span.start <= span.end && span.end <= text.len(), "{e:?}");
                    prop_assert!(text.is_char_boundary(span.start) && text.is_char_boundary(span.end), "{e:?}");
                }
                prop_assert!(!e.to_string().is_empty());
            }
        }
    }
}
