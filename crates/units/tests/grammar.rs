//! The quantity grammar and its typed errors (issue 21, item 1).
//!
//! Each test states one rule of the grammar documented in the crate root, or one bad input
//! and the typed error (with its byte span) that it must give: no panic, no NaN, no silent
//! fallback to SI.

use vectrix_units::{
    Dimension, MAX_EXPONENT, MAX_LEN, Measure, Number, Quantity, Unit, UnitError, UnitSystem, kind,
};

fn si(text: &str, d: Dimension) -> f64 {
    Quantity::parse(text).and_then(|q| q.to_si(d)).unwrap_or_else(|e| panic!("{text}: {e}"))
}

fn err(text: &str) -> UnitError {
    Quantity::parse(text).expect_err(text)
}

// Products, quotients and powers: `/` is left-associative (m/s/s = m/s^2), `*` and `/` bind
// equally, parentheses group, superscripts and `^-n` are powers.
#[test]
fn products_quotients_and_powers() {
    let a = Dimension::ACCELERATION;
    assert_eq!(Unit::parse("m/s/s").unwrap(), Unit::parse("m/s^2").unwrap());
    assert_eq!(Unit::parse("m*s^-2").unwrap(), Unit::parse("m/s^2").unwrap());
    assert_eq!(Unit::parse("m/s²").unwrap(), Unit::parse("m/s^2").unwrap());
    assert_eq!(Unit::parse("m·s⁻²").unwrap(), Unit::parse("m/s^2").unwrap());
    assert_eq!(Unit::parse("kg/(m*s^2)").unwrap().dimension(), Dimension::PRESSURE);
    // a/b*c is (a/b)*c: c in the numerator
    assert_eq!(Unit::parse("N/m*s").unwrap().dimension(), Dimension::DAMPING);
    assert_eq!(Unit::parse("(m/s)^2").unwrap(), Unit::parse("m^2/s^2").unwrap());
    assert_eq!(Unit::parse("1/s").unwrap().dimension(), Dimension::FREQUENCY);
    assert_eq!(si("9.80665 m/s/s", a), 9.80665);
    assert_eq!(si("  2 m  ", Dimension::LENGTH), 2.0);
    assert_eq!(si("5m", Dimension::LENGTH), 5.0);
    assert_eq!(si("-1.5e3 mm", Dimension::LENGTH), -1.5);
    assert_eq!(si(".5 s", Dimension::TIME), 0.5);
    assert_eq!(si("+2. s", Dimension::TIME), 2.0);
    assert_eq!(si("3 N * m", Dimension::MOMENT), 3.0);
    // a cancelled unit is dimensionless; the number alone is dimensionless
    assert_eq!(si("4 m/m", Dimension::DIMENSIONLESS), 4.0);
    assert_eq!(si("4", Dimension::DIMENSIONLESS), 4.0);
}

// Torque and energy share M L² T⁻² (SI, no radian); angular velocity carries the angle, so a
// frequency is not an angular velocity.
#[test]
fn angle_is_a_base_dimension_but_torque_is_newton_metre() {
    assert_eq!(si("2 N*m", Dimension::MOMENT), 2.0);
    assert_eq!(si("2 J", Dimension::MOMENT), 2.0);
    assert_eq!(si("2 ft*lbf", Dimension::MOMENT), si("2 lbf*ft", Dimension::MOMENT));
    assert_eq!(si("3 kg*m^2/s", Dimension::ANGULAR_MOMENTUM), 3.0);
    assert_eq!(si("1 rev/s", Dimension::ANGULAR_VELOCITY), std::f64::consts::TAU);
    assert_eq!(si("60 rpm", Dimension::ANGULAR_VELOCITY), std::f64::consts::TAU);
    assert_eq!(si("180 deg", Dimension::ANGLE), std::f64::consts::PI);
    assert_eq!(si("180°", Dimension::ANGLE), std::f64::consts::PI);
    assert_eq!(si("5 N*m/rad", Dimension::ROTATIONAL_STIFFNESS), 5.0);
    let e = Quantity::parse("2 Hz").unwrap().to_si(Dimension::ANGULAR_VELOCITY).unwrap_err();
    assert!(e.to_string().contains("expected angular velocity (rad/s), given frequency (1/s)"), "{e}");
}

#[test]
fn dimension_mismatch_names_both_and_spans_the_unit() {
    let e = Quantity::parse("12 ft/s^2").unwrap().to_si(Dimension::VELOCITY).unwrap_err();
    match &e {
        UnitError::DimensionMismatch { span, expected, given, unit, .. } => {
            assert_eq!(
                (span.clone(), *expected, *given),
                (3..9, Dimension::VELOCITY, Dimension::ACCELERATION)
            );
            assert_eq!(unit, "ft/s^2");
        }
        e => panic!("{e:?}"),
    }
    assert_eq!(
        e.to_string(),
        "dimension mismatch in `12 ft/s^2`: expected velocity (m/s), given acceleration (m/s^2) from unit `ft/s^2`"
    );
    // no unit: the whole string is the span, the given dimension is `dimensionless`
    let e = Quantity::parse("7").unwrap().to_si(Dimension::MASS).unwrap_err();
    assert_eq!(e.span(), 0..1);
    assert!(e.to_string().contains("given dimensionless"), "{e}");
}

#[test]
fn unknown_units_suggest_and_list_what_is_valid() {
    match err("3 fot") {
        UnitError::UnknownUnit { span, symbol, suggestions, .. } => {
            assert_eq!((span, symbol.as_str()), (2..5, "fot"));
            assert!(suggestions.contains(&"ft"), "{suggestions:?}");
        }
        e => panic!("{e:?}"),
    }
    let e = err("3 KG*m");
    assert_eq!(e.span(), 2..4);
    let msg = e.to_string();
    assert!(msg.contains("did you mean kg?") && msg.contains("valid units: m g s rad"), "{msg}");
    assert!(msg.contains("slug") && msg.contains("nmi") && msg.contains("lbf"), "{msg}");
    // prefixes apply to SI symbols only, once
    assert!(matches!(err("1 kft"), UnitError::UnknownUnit { .. }));
    assert!(matches!(err("1 kkg"), UnitError::UnknownUnit { .. }));
    assert!(matches!(err("1 msec"), UnitError::UnknownUnit { .. }));
    // the parser's spans are byte offsets, also after multi-byte characters
    assert_eq!(err("1 µm*xyz").span(), 6..9);
}

#[test]
fn malformed_quantities_say_what_was_expected() {
    let cases: [(&str, core::ops::Range<usize>, &str); 13] = [
        ("", 0..0, "empty quantity"),
        ("   ", 0..3, "empty quantity"),
        ("m", 0..1, "expected a number"),
        ("- 3 m", 0..2, "expected a number"),
        ("µ", 0..2, "expected a number"),
        ("3 kg m", 5..6, "join factors with `*`"),
        ("3 m2", 2..4, "write `m^2`"),
        ("3 m^", 3..4, "integer exponent"),
        ("3 m/", 4..4, "expected a unit symbol"),
        ("3 (m/s", 6..6, "expected `)`"),
        ("3 m/s)", 5..6, "unexpected `)`"),
        ("3 12/s", 2..4, "number 1 only"),
        ("3 m+s", 3..4, "unexpected `+`"),
    ];
    for (text, span, reason) in cases {
        match err(text) {
            UnitError::Malformed { span: s, reason: r, .. } => {
                assert_eq!(s, span, "{text}");
                assert!(r.contains(reason), "{text}: {r}");
            }
            e => panic!("{text}: {e:?}"),
        }
    }
    let deep = format!("1 {}m{}", "(".repeat(9), ")".repeat(9));
    assert!(err(&deep).to_string().contains("nested deeper than 8"));
}

#[test]
fn bounds_are_typed_errors() {
    assert_eq!(err(&"1".repeat(MAX_LEN + 1)), UnitError::TooLong { len: MAX_LEN + 1, max: MAX_LEN });
    match err("1 m^17") {
        UnitError::ExponentOutOfRange { span, exponent, max, .. } => {
            assert_eq!((span, exponent, max), (3..6, 17, MAX_EXPONENT));
        }
        e => panic!("{e:?}"),
    }
    // accumulated exponents are bounded too: (m^4)^5 = m^20
    assert!(matches!(err("1 (m^4)^5"), UnitError::ExponentOutOfRange { .. }));
    assert!(matches!(err("1 m^9*m^9"), UnitError::ExponentOutOfRange { .. }));
    assert!(matches!(err("1 m^99999999999999999999"), UnitError::ExponentOutOfRange { .. }));
    // the bound is on the whole unit, not on a power or partial product inside it: W^6/Hz^2
    // is kg⁶m¹²T⁻¹⁶ although W^6 alone is T⁻¹⁸ (what Display writes for W^3/Hz^2*W^3 must parse
    // back); (m^4)^5/m^10 and m^9*m^9/m^8 are m^10
    assert!(matches!(err("1 W^6"), UnitError::ExponentOutOfRange { .. }));
    let q = Quantity::parse("1 W^3/Hz^2*W^3").unwrap();
    let back = Quantity::parse(&q.to_string()).unwrap();
    assert_eq!(q.to_string(), "1 W^6/Hz^2");
    assert_eq!((back.unit(), back.value()), (q.unit(), q.value()));
    for text in ["1 (m^4)^5/m^10", "1 m^9*m^9/m^8"] {
        assert_eq!(
            Quantity::parse(text).unwrap().unit(),
            Quantity::parse("1 m^10").unwrap().unit(),
            "{text}"
        );
    }
}

#[test]
fn non_finite_and_out_of_range_numbers_are_refused() {
    for (text, span) in [("inf m", 0..3), ("-inf m", 0..4), ("NaN", 0..3), ("infinity s", 0..8)] {
        match err(text) {
            UnitError::NonFinite { span: s, .. } => assert_eq!(s, span, "{text}"),
            e => panic!("{text}: {e:?}"),
        }
    }
    // the number as written must itself be a normal f64
    assert!(matches!(err("1e999 m"), UnitError::Overflow { span, .. } if span == (0..5)));
    assert!(matches!(err("1e-999 m"), UnitError::Underflow { .. }));
    assert!(matches!(err("1e99999999999999999999 m"), UnitError::Overflow { .. }));
    // conversion out of range: 1e308 mi is 1.6e311 m
    let e = Quantity::parse("1e308 mi").unwrap().to_si(Dimension::LENGTH).unwrap_err();
    assert!(
        matches!(&e, UnitError::Overflow { span, target, .. } if *span == (0..5) && target == "m"),
        "{e:?}"
    );
    let e = Quantity::parse("1e-307 in").unwrap().to_si(Dimension::LENGTH).unwrap_err();
    assert!(matches!(e, UnitError::Underflow { .. }), "{e:?}");
    // the largest values convert when they fit: 1.7e308 m is finite
    assert_eq!(si("1.7e308 m", Dimension::LENGTH), 1.7e308);
    assert_eq!(si("-0 m", Dimension::LENGTH).to_bits(), (-0.0f64).to_bits());
    let e = UnitSystem::Imperial.value_from_si(Dimension::LENGTH, 1e308).unwrap_err();
    assert!(matches!(e, UnitError::Overflow { .. }), "{e:?}");
    let e = Unit::parse("ft").unwrap().to_si(f64::NAN).unwrap_err();
    assert!(matches!(e, UnitError::NonFinite { .. }), "{e:?}");
}

// A scene's value: a bare TOML number is SI, a string is a quantity; anything else is an error
// that says what is accepted.
#[test]
fn number_deserializes_from_toml_with_spans() {
    #[derive(serde::Deserialize)]
    struct Body {
        mass: toml::Spanned<Number>,
        g: Vec<Number>,
        q: Vec<Number>,
        n: Number,
    }
    let src = "mass = \"2.2046226218487757 lb\"\ng = [\"0 ft/s^2\", \"-32.174 ft/s^2\", 0.0]\nq = [\"30 deg\", 0.5]\nn = 3\n";
    let b: Body = toml::from_str(src).unwrap();
    assert_eq!(b.mass.get_ref().to_si(Dimension::MASS).unwrap(), 2.2046226218487757 * 0.45359237);
    let g: Vec<f64> = b.g.iter().map(|x| x.to_si(Dimension::ACCELERATION).unwrap()).collect();
    assert_eq!(g, [0.0, -32.174 * 0.3048, 0.0]);
    assert_eq!(b.q[0].to_si(Dimension::ANGLE).unwrap(), std::f64::consts::FRAC_PI_6);
    assert_eq!(b.q[1].to_si(Dimension::ANGLE).unwrap(), 0.5);
    assert_eq!(b.n, Number::Bare(3.0));
    // an error inside the string maps to a byte range of the file
    #[derive(serde::Deserialize)]
    struct M {
        mass: toml::Spanned<Number>,
    }
    let bad = "mass = \"2 slgu\"\n";
    let m: M = toml::from_str(bad).unwrap();
    let e = m.mass.get_ref().to_si(Dimension::MASS).unwrap_err();
    assert_eq!(&bad[e.span_in_source(bad, m.mass.span())], "slgu");
    let lit = "mass = '2 slgu'\n";
    let m: M = toml::from_str(lit).unwrap();
    let e = m.mass.get_ref().to_si(Dimension::MASS).unwrap_err();
    assert_eq!(&lit[e.span_in_source(lit, m.mass.span())], "slgu");
    // an escaped literal cannot be mapped inside: the whole literal is reported
    let esc = "mass = \"2 sl\\u0067u\"\n";
    let m: M = toml::from_str(esc).unwrap();
    let e = m.mass.get_ref().to_si(Dimension::MASS).unwrap_err();
    assert_eq!(e.span_in_source(esc, m.mass.span()), m.mass.span());
    // wrong TOML types and non-finite bare numbers
    let e = toml::from_str::<M>("mass = true\n").err().unwrap().to_string();
    assert!(e.contains("a number (in SI units) or a quantity string"), "{e}");
    let m: M = toml::from_str("mass = inf\n").unwrap();
    assert!(matches!(m.mass.get_ref().to_si(Dimension::MASS), Err(UnitError::NonFinite { .. })));
}

// A typed field deserializes with its kind's dimension checked.
#[test]
fn measure_deserializes_with_its_kind() {
    #[derive(serde::Deserialize)]
    struct Body {
        mass: Measure<kind::Mass>,
        speed: Measure<kind::Velocity>,
    }
    let b: Body = toml::from_str("mass = \"1 slug\"\nspeed = 3.0\n").unwrap();
    assert_eq!(b.mass.si(), 14.593902937206364);
    assert_eq!(b.speed.si(), 3.0);
    let e = toml::from_str::<Body>("mass = \"1 lbf\"\nspeed = 3.0\n").err().unwrap().to_string();
    assert!(e.contains("expected mass (kg), given force"), "{e}");
    assert!(e.contains("line 1"), "{e}");
}

#[test]
fn display_is_canonical_and_parses_back() {
    for (text, shown) in [
        ("2.2046226218487757 lb", "2.2046226218487757 lb"),
        ("-32.1740 ft / s / s", "-32.174 ft/s^2"),
        ("1200 slug*ft^2", "1200 slug*ft^2"),
        ("0.000588 slug/ft^3", "0.000588 slug/ft^3"),
        ("6.02214076e23 g", "6.02214076e23 g"),
        ("123456789012345678901 m", "123456789012345678901 m"),
        ("1e-9 s^-1", "1e-9 1/s"),
        ("5", "5"),
        ("3 s^-1*m", "3 m/s"),
        ("7 µs", "7 µs"),
    ] {
        let q = Quantity::parse(text).unwrap();
        assert_eq!(q.to_string(), shown, "{text}");
        assert_eq!(Quantity::parse(shown).unwrap().to_string(), shown);
    }
}
