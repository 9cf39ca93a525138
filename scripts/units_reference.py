"""Reference values for vectrix-units (issue 21): exact SI values of quantity strings.

Every unit is defined here from its exact definition (1959 yard and pound agreement,
CGPM 1901 standard gravity), independently of the Rust tables; values are exact Fractions
(π from mpmath at 400 bits) rounded once to the nearest double. Run once:

    ~/.venv-peers/bin/python scripts/units_reference.py > tests/data/units_reference.json

`cargo test -p vectrix-units --test reference` compares bit for bit.
"""
import json
import random
from fractions import Fraction as F

import mpmath

mpmath.mp.prec = 400
PI = F(mpmath.nstr(mpmath.pi, 110, strip_zeros=False))  # 110 significant digits

# symbol: (factor, (M, L, T, A)); the definitions as published, not the Rust table
FT = F("0.3048")
IN = F("0.0254")
LB = F("0.45359237")
G0 = F("9.80665")
LBF = LB * G0
UNITS = {
    "m": (F(1), (0, 1, 0, 0)),
    "g": (F(1, 1000), (1, 0, 0, 0)),
    "s": (F(1), (0, 0, 1, 0)),
    "rad": (F(1), (0, 0, 0, 1)),
    "Hz": (F(1), (0, 0, -1, 0)),
    "N": (F(1), (1, 1, -2, 0)),
    "Pa": (F(1), (1, -1, -2, 0)),
    "J": (F(1), (1, 2, -2, 0)),
    "W": (F(1), (1, 2, -3, 0)),
    "deg": (PI / 180, (0, 0, 0, 1)),
    "rev": (2 * PI, (0, 0, 0, 1)),
    "rpm": (2 * PI / 60, (0, 0, -1, 1)),
    "min": (F(60), (0, 0, 1, 0)),
    "h": (F(3600), (0, 0, 1, 0)),
    "ft": (FT, (0, 1, 0, 0)),
    "in": (IN, (0, 1, 0, 0)),
    "yd": (3 * FT, (0, 1, 0, 0)),
    "mi": (5280 * FT, (0, 1, 0, 0)),
    "nmi": (F(1852), (0, 1, 0, 0)),
    "lb": (LB, (1, 0, 0, 0)),
    "lbf": (LBF, (1, 1, -2, 0)),
    "slug": (LBF / FT, (1, 0, 0, 0)),
    "kn": (F(1852, 3600), (0, 1, -1, 0)),
    "mph": (5280 * FT / 3600, (0, 1, -1, 0)),
    "psi": (LBF / IN**2, (1, -1, -2, 0)),
    "g0": (G0, (0, 1, -2, 0)),
}
PREFIXES = {"k": 3, "M": 6, "G": 9, "m": -3, "µ": -6, "u": -6, "n": -9, "c": -2, "h": 2, "d": -1}
PREFIXABLE = ["m", "g", "s", "rad", "Hz", "N", "Pa", "J", "W"]


def to_double(x):
    """Nearest double to the exact rational x (CPython's int/int is correctly rounded)."""
    return x.numerator / x.denominator


def unit_value(terms):
    f, d = F(1), [0, 0, 0, 0]
    for (prefix, sym, e) in terms:
        uf, ud = UNITS[sym]
        f *= (uf * F(10) ** PREFIXES.get(prefix, 0)) ** e
        d = [a + e * b for a, b in zip(d, ud)]
    return f, d


def unit_text(terms):
    up = [t for t in terms if t[2] > 0]
    down = [t for t in terms if t[2] < 0]
    def one(p, s, e):
        return f"{p}{s}" + (f"^{e}" if e != 1 else "")
    text = "*".join(one(p, s, e) for p, s, e in up) or "1"
    for p, s, e in down:
        text += "/" + one(p, s, -e)
    return text


def si_case(number, terms):
    f, d = unit_value(terms)
    v = F(number) * f
    text = f"{number} {unit_text(terms)}"
    return {"text": text, "dimension": d, "si": to_double(v), "bits": f"{struct_bits(to_double(v))}"}


def struct_bits(x):
    import struct
    return "0x%016x" % struct.unpack("<Q", struct.pack("<d", x))[0]


cases = []
for sym in UNITS:
    cases.append(si_case("1", [("", sym, 1)]))
for sym in PREFIXABLE:
    for p in ["k", "m", "µ", "M"]:
        cases.append(si_case("1", [(p, sym, 1)]))
named = [
    ("1", [("", "slug", 1), ("", "ft", 2)]),
    ("27915", [("", "slug", 1), ("", "ft", 2)]),
    ("1", [("", "ft", 1), ("", "lbf", 1)]),
    ("32.174", [("", "ft", 1), ("", "s", -2)]),
    ("-32.2", [("", "ft", 1), ("", "s", -2)]),
    ("400", [("", "kn", 1)]),
    ("30", [("", "deg", 1)]),
    ("90", [("", "deg", 1)]),
    ("180", [("", "deg", 1)]),
    ("2.2046226218487757", [("", "lb", 1)]),
    ("13000", [("", "lbf", 1)]),
    ("0.000588", [("", "slug", 1), ("", "ft", -3)]),
    ("230", [("", "ft", 2)]),
    ("1", [("", "lbf", 1), ("", "s", 1), ("", "ft", -1)]),
    ("1", [("", "rev", 1), ("", "min", -1)]),
    ("1e308", [("", "m", 1)]),
    ("6.02214076e23", [("", "g", 1)]),
]
for number, terms in named:
    cases.append(si_case(number, terms))

rng = random.Random(21)
symbols = list(UNITS)
for _ in range(300):
    n = rng.randint(1, 3)
    terms = []
    used = set()
    for _ in range(n):
        sym = rng.choice(symbols)
        prefix = rng.choice(["", "", "k", "m", "µ", "c"]) if sym in PREFIXABLE else ""
        if (prefix, sym) in used:
            continue
        used.add((prefix, sym))
        e = rng.choice([-3, -2, -1, 1, 1, 1, 2, 3])
        terms.append((prefix, sym, e))
    # products first, then quotients: the same unit under left-associative parsing
    digits = "".join(rng.choice("0123456789") for _ in range(rng.randint(1, 17)))
    digits = digits.lstrip("0") or "7"
    point = rng.randint(0, len(digits))
    mant = digits[:point] + ("." + digits[point:] if point < len(digits) else "")
    exp = rng.randint(-30, 30)
    sign = rng.choice(["", "-"])
    cases.append(si_case(f"{sign}{mant}e{exp}", terms))

# conversions to a unit other than SI: (quantity, target, value)
conversions = []
for text, target in [
    ("400 kn", "ft/s"),
    ("1 m", "ft"),
    ("1 kg", "slug"),
    ("1 N", "lbf"),
    ("14.59 kg", "slug"),
    ("4.4 N", "lbf"),
    ("1 slug*ft^2", "kg*m^2"),
    ("9.80665 m/s^2", "ft/s^2"),
    ("1 rad", "deg"),
    ("60 rpm", "deg/s"),
    ("1 mph", "kn"),
    ("1 psi", "lbf/ft^2"),
]:
    num, unit = text.split(" ", 1)
    def parse_unit(u):
        terms = []
        for part_i, part in enumerate(u.replace("/", " /").split(" ")):
            sign = -1 if part.startswith("/") else 1
            part = part.lstrip("/")
            for j, factor in enumerate(part.split("*")):
                s, _, e = factor.partition("^")
                prefix = ""
                if s not in UNITS:
                    prefix, s = s[0], s[1:]
                terms.append((prefix, s, sign * int(e or 1)))
        return terms
    fa, da = unit_value(parse_unit(unit))
    fb, db = unit_value(parse_unit(target))
    assert da == db, (text, target)
    v = F(num) * fa / fb
    conversions.append({"text": text, "target": target, "value": to_double(v), "bits": struct_bits(to_double(v))})

def block(name, rows):
    body = ",\n".join("  " + json.dumps(r, ensure_ascii=False) for r in rows)
    return f' "{name}": [\n{body}\n ]'


print("{\n" + block("si", cases) + ",\n" + block("conversions", conversions) + "\n}")
