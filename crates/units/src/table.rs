//! The unit symbols, their exact SI factors and the SI prefixes.
//!
//! Every factor is an exact rational times a power of π:
//! `num / den · 10^pow10 · π^pi`, with the defining values of the international yard and
//! pound agreement (1959) and of standard gravity (CGPM 1901):
//! ft = 0.3048 m, in = 0.0254 m, lb = 0.45359237 kg, g₀ = 9.80665 m/s². Derived imperial units
//! are products of these (lbf = lb·g₀, slug = lbf·s²/ft, psi = lbf/in²), so their factors are
//! exact too. `docs/units.md` lists the same table.

use crate::Dimension;

/// One unit symbol of the grammar.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Atom {
    /// The symbol as written (`ft`, `N`, `slug`).
    pub(crate) symbol: &'static str,
    /// What it measures.
    pub(crate) dimension: Dimension,
    /// Integer numerator of the factor.
    pub(crate) num: u64,
    /// Integer denominator of the factor.
    pub(crate) den: u64,
    /// Power of ten of the factor.
    pub(crate) pow10: i8,
    /// Power of π of the factor.
    pub(crate) pi: i8,
    /// Whether SI prefixes apply (`km`, `mN`, `MPa`).
    pub(crate) prefixable: bool,
    /// The name in the unit list.
    pub(crate) name: &'static str,
}

const fn atom(
    symbol: &'static str,
    dimension: Dimension,
    (num, den, pow10, pi): (u64, u64, i8, i8),
    prefixable: bool,
    name: &'static str,
) -> Atom {
    Atom { symbol, dimension, num, den, pow10, pi, prefixable, name }
}

/// lb · g₀ = 0.45359237 · 9.80665 = 45359237 · 980665 · 10⁻¹³ (exact).
const LBF_NUM: u64 = 45_359_237 * 980_665;

/// The unit symbols, each once; aliases are in [`ALIASES`].
pub(crate) const ATOMS: [Atom; 25] = [
    // SI base and derived units (prefixable)
    atom("m", Dimension::LENGTH, (1, 1, 0, 0), true, "metre"),
    atom("g", Dimension::MASS, (1, 1, -3, 0), true, "gram (kg = 1000 g)"),
    atom("s", Dimension::TIME, (1, 1, 0, 0), true, "second"),
    atom("rad", Dimension::ANGLE, (1, 1, 0, 0), true, "radian"),
    atom("Hz", Dimension::FREQUENCY, (1, 1, 0, 0), true, "hertz = 1/s (no angle)"),
    atom("N", Dimension::FORCE, (1, 1, 0, 0), true, "newton = kg*m/s^2"),
    atom("Pa", Dimension::PRESSURE, (1, 1, 0, 0), true, "pascal = N/m^2"),
    atom("J", Dimension::ENERGY, (1, 1, 0, 0), true, "joule = N*m"),
    atom("W", Dimension::POWER, (1, 1, 0, 0), true, "watt = J/s"),
    // angle and time outside SI
    atom("deg", Dimension::ANGLE, (1, 180, 0, 1), false, "degree = π/180 rad"),
    atom("rev", Dimension::ANGLE, (2, 1, 0, 1), false, "revolution = 2π rad"),
    atom("rpm", Dimension::ANGULAR_VELOCITY, (2, 60, 0, 1), false, "revolution per minute = 2π/60 rad/s"),
    atom("min", Dimension::TIME, (60, 1, 0, 0), false, "minute = 60 s"),
    atom("h", Dimension::TIME, (3600, 1, 0, 0), false, "hour = 3600 s"),
    // imperial and US customary, exact by definition
    atom("ft", Dimension::LENGTH, (3048, 1, -4, 0), false, "foot = 0.3048 m"),
    atom("in", Dimension::LENGTH, (254, 1, -4, 0), false, "inch = 0.0254 m"),
    atom("yd", Dimension::LENGTH, (9144, 1, -4, 0), false, "yard = 0.9144 m"),
    atom("mi", Dimension::LENGTH, (1_609_344, 1, -3, 0), false, "statute mile = 1609.344 m"),
    atom("nmi", Dimension::LENGTH, (1852, 1, 0, 0), false, "nautical mile = 1852 m"),
    atom("lb", Dimension::MASS, (45_359_237, 1, -8, 0), false, "pound-mass = 0.45359237 kg"),
    atom("lbf", Dimension::FORCE, (LBF_NUM, 1, -13, 0), false, "pound-force = lb*g0 = 4.4482216152605 N"),
    atom("slug", Dimension::MASS, (LBF_NUM, 3048, -9, 0), false, "slug = lbf*s^2/ft"),
    atom("kn", Dimension::VELOCITY, (1852, 3600, 0, 0), false, "knot = nmi/h = 1852/3600 m/s"),
    atom("mph", Dimension::VELOCITY, (1_609_344, 3600, -3, 0), false, "mile per hour = mi/h"),
    atom(
        "psi",
        Dimension::PRESSURE,
        (LBF_NUM, 64_516, -5, 0),
        false,
        "pound-force per square inch = lbf/in^2",
    ),
];

/// Standard gravity g₀ = 9.80665 m/s² (written `g0`; `g` is the gram).
pub(crate) const G0: Atom =
    atom("g0", Dimension::ACCELERATION, (980_665, 1, -5, 0), false, "standard gravity = 9.80665 m/s^2");

/// Alternative spellings: (alias, symbol it stands for).
pub(crate) const ALIASES: [(&str, &str); 5] =
    [("sec", "s"), ("°", "deg"), ("kt", "kn"), ("lbm", "lb"), ("hr", "h")];

/// SI prefixes: (symbol, power of ten). `u` and `μ` (Greek mu) are accepted for `µ` (micro sign).
pub(crate) const PREFIXES: [(&str, i8); 18] = [
    ("E", 18),
    ("P", 15),
    ("T", 12),
    ("G", 9),
    ("M", 6),
    ("k", 3),
    ("h", 2),
    ("da", 1),
    ("d", -1),
    ("c", -2),
    ("m", -3),
    ("µ", -6),
    ("μ", -6),
    ("u", -6),
    ("n", -9),
    ("p", -12),
    ("f", -15),
    ("a", -18),
];

/// Index of a unit in [`ATOMS`], or [`G0_INDEX`] for standard gravity.
pub(crate) type AtomId = u8;

/// The index standing for [`G0`].
pub(crate) const G0_INDEX: AtomId = ATOMS.len() as AtomId;

/// The atom with index `id`.
pub(crate) fn atom_of(id: AtomId) -> &'static Atom {
    if id == G0_INDEX { &G0 } else { &ATOMS[id as usize] }
}

fn exact(symbol: &str) -> Option<AtomId> {
    let symbol = ALIASES.iter().find(|(a, _)| *a == symbol).map_or(symbol, |(_, s)| s);
    if symbol == G0.symbol {
        return Some(G0_INDEX);
    }
    ATOMS.iter().position(|a| a.symbol == symbol).map(|i| i as AtomId)
}

/// Resolves a unit token: an exact symbol or alias first (so `min` is the minute, `mi` the
/// mile, `nmi` the nautical mile, `Pa` the pascal, `kn` the knot, `h` the hour), then an SI
/// prefix followed by a prefixable SI symbol (`km`, `ms`, `hPa`, `kN`, `µm`, `dam`). Returns
/// the prefix's power of ten (0 without prefix) and the atom.
pub(crate) fn resolve(token: &str) -> Option<(i8, AtomId)> {
    if let Some(id) = exact(token) {
        return Some((0, id));
    }
    // longest prefix first: `da` before `d`
    let mut candidates: Vec<_> = PREFIXES.iter().filter(|(p, _)| token.starts_with(p)).collect();
    candidates.sort_by_key(|(p, _)| core::cmp::Reverse(p.len()));
    candidates.into_iter().find_map(|(p, e)| {
        let rest = &token[p.len()..];
        // aliases do not take prefixes: `msec` is not a unit (write `ms`)
        let id = ATOMS.iter().position(|a| a.symbol == rest && a.prefixable)?;
        Some((*e, id as AtomId))
    })
}

/// Every symbol a user may write without a prefix, for suggestion lists.
pub(crate) fn symbols() -> impl Iterator<Item = &'static str> {
    ATOMS.iter().map(|a| a.symbol).chain([G0.symbol]).chain(ALIASES.iter().map(|(a, _)| *a))
}

/// Common prefixed symbols, for suggestions.
pub(crate) const COMMON_PREFIXED: [&str; 14] =
    ["kg", "km", "cm", "mm", "µm", "ms", "kN", "mN", "kPa", "MPa", "kJ", "kW", "mrad", "kHz"];

/// Levenshtein distance on chars.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, &cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

/// Up to five known symbols close to an unknown token: same letters in another case first,
/// then by edit distance ≤ 2.
pub(crate) fn suggestions(token: &str) -> Vec<&'static str> {
    let mut scored: Vec<(usize, &'static str)> = symbols()
        .chain(COMMON_PREFIXED)
        .filter_map(|s| {
            let d = if s.eq_ignore_ascii_case(token) { 0 } else { distance(token, s) };
            (d <= 2 && d < token.chars().count().max(2)).then_some((d, s))
        })
        .collect();
    scored.sort();
    scored.dedup_by_key(|(_, s)| *s);
    scored.into_iter().take(5).map(|(_, s)| s).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sym(token: &str) -> Option<(i8, &'static str)> {
        resolve(token).map(|(p, id)| (p, atom_of(id).symbol))
    }

    // The ambiguities of the grammar, each resolved the documented way.
    #[test]
    fn exact_symbols_win_over_prefix_splits() {
        assert_eq!(sym("min"), Some((0, "min"))); // not milli-inch
        assert_eq!(sym("mi"), Some((0, "mi")));
        assert_eq!(sym("nmi"), Some((0, "nmi"))); // not nano-mile
        assert_eq!(sym("Pa"), Some((0, "Pa"))); // not peta-annum
        assert_eq!(sym("kn"), Some((0, "kn"))); // knot; kilonewton is kN
        assert_eq!(sym("h"), Some((0, "h"))); // hour; hecto needs a unit after it
        assert_eq!(sym("kN"), Some((3, "N")));
        assert_eq!(sym("hPa"), Some((2, "Pa")));
        assert_eq!(sym("dam"), Some((1, "m")));
        assert_eq!(sym("mm"), Some((-3, "m")));
        assert_eq!(sym("kg"), Some((3, "g")));
        assert_eq!(sym("µs"), Some((-6, "s")));
        assert_eq!(sym("us"), Some((-6, "s")));
        assert_eq!(sym("μm"), Some((-6, "m")));
        assert_eq!(sym("mrad"), Some((-3, "rad")));
        assert_eq!(sym("sec"), Some((0, "s")));
        assert_eq!(sym("kt"), Some((0, "kn")));
        assert_eq!(sym("g0"), Some((0, "g0")));
        // imperial units, aliases and double prefixes take no prefix
        assert_eq!(sym("kft"), None);
        assert_eq!(sym("msec"), None);
        assert_eq!(sym("kkg"), None);
        assert_eq!(sym("mdeg"), None);
    }

    #[test]
    fn suggestions_find_near_misses() {
        assert_eq!(suggestions("FT")[0], "ft");
        assert!(suggestions("slugs").contains(&"slug"));
        assert!(suggestions("lbs").contains(&"lb"));
        assert!(suggestions("Kg").contains(&"kg"));
        assert!(suggestions("xyzzy").is_empty());
    }

    #[test]
    fn symbols_are_unique() {
        let all: Vec<_> = symbols().collect();
        for (i, s) in all.iter().enumerate() {
            assert!(!all[i + 1..].contains(s), "{s} twice");
        }
    }
}
