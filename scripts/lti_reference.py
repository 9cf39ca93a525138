#!/usr/bin/env python3
"""Independent high-precision reference data for the linear-systems crate (issue 19).

Writes ``tests/data/lti_reference.json``, read by ``tests/lti_reference.rs``. Run once, from the
repository root, in the peers venv (mpmath; python-control only for a cross-check that is
printed, never written):

    ~/.venv-peers/bin/python scripts/lti_reference.py

``cargo test`` never runs this script.

What it does
------------
1. Builds 120 SISO transfer functions G = N/D of order 1-10 (monic D) of eight kinds: stable,
   integrators, right-half-plane zeros, negative gain, unstable poles, ill-conditioned roots
   (clusters and magnitude spreads of 10^4), exactly repeated poles, and poles or zeros on the
   imaginary axis. The double-precision coefficients written to the JSON *are* the systems:
   every reference value below is computed from those doubles, read exactly as rationals.
2. Computes, with mpmath at 60 significant digits (polynomials handled exactly in rational
   arithmetic where roots or crossings are needed: Yun's square-free factorisation, then
   mpmath's polyroots on each square-free factor):
   - poles and zeros with their multiplicity q and condition number
     kappa_q = sum_k |c_k||r|^k / |p^(q)(r)/q!|, so that a perturbation of the coefficients
     by relative eps moves the root by at most about (eps*kappa_q)^(1/q);
   - G(j w) at about twelve frequencies (w = 0 included, and w exactly at an imaginary-axis
     pole or zero when the system has one), ln|G|, the continuous phase on the book's branch
     (16.6.2) and the componentwise condition numbers with respect to relative coefficient
     perturbations: kappa_G = sum |c_k w^k|/|P| over N and D (relative error of the complex
     value), kappa_mag = sum |c_k Re((jw)^k/P)| (absolute error of ln|G|), kappa_phase =
     sum |c_k Im((jw)^k/P)| (absolute error of the phase in radians);
   - the stability margins exactly as python-control 0.10.2 ``stability_margins`` defines them
     (continuous time, epsw = 0): phase crossovers (w >= 0 with Im L(jw) = 0, L(jw) <= 0, D(jw)
     != 0; w = 0 decided by the exact sign of N(0)/D(0)) with the gain margin 1/|L|; gain
     crossovers (w > 0, |L(jw)| = 1) with PM = mod(angle L, 360 deg) - 180 deg; stationary
     minima of |1 + L(jw)| at w > 0 (second-derivative test) with the distance. Each with the
     condition numbers of w (relative) and of the margin (absolute in dB or degrees, relative for
     the distance), obtained by central differences of the exactly re-solved crossing under
     relative perturbations of each coefficient (step 1e-25 at 60 digits);
   - step, impulse, initial-condition (companion realisation (15.7.3), x0 given) and lsim
     (zero- and first-order hold of an exact dyadic input sequence) responses on a uniform grid
     of 201 points with a dyadic step h (so every t_k = k h is exact), by exact discretisation
     at 60 digits (the matrix exponential of the augmented generator, mpmath), with the
     absolute componentwise condition number S(t_k) = sum_p |p dy(t_k)/dp| over every
     coefficient, x0 entry and input sample. The coefficient derivatives come from one
     augmented simulation (dY/dn_k = s^k U/D, dY/dd_k = -s^k Y/D are states of a companion
     system driven by u and by y); a finite-difference check confirms them on the first system.
3. Cross-checks the margins against python-control itself (double precision) and prints the
   systems where python-control's floating-point root filtering disagrees with the exact lists.
"""

import json
import math
import os
import random
import sys
from fractions import Fraction as Q

import mpmath as mp

DPS = 60
mp.mp.dps = DPS
SEED = 20251201
N_TIME = 201  # samples per time response
KEEP = 10  # every KEEP-th sample is written

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "lti_reference.json")


# ----------------------------------------------------------------------------- exact polynomials
# Polynomials are lists of coefficients in DESCENDING powers (Matlab's and the crate's order).


def trim(p):
    i = 0
    while i < len(p) - 1 and p[i] == 0:
        i += 1
    return p[i:]


def padd(a, b):
    n = max(len(a), len(b))
    a = [0] * (n - len(a)) + list(a)
    b = [0] * (n - len(b)) + list(b)
    return trim([x + y for x, y in zip(a, b)])


def pscale(a, c):
    return trim([x * c for x in a])


def pmul(a, b):
    out = [0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x == 0:
            continue
        for j, y in enumerate(b):
            out[i + j] += x * y
    return trim(out)


def pder(a):
    n = len(a) - 1
    if n == 0:
        return [0]
    return trim([c * (n - i) for i, c in enumerate(a[:-1])])


def pdivmod(a, b):
    a = list(trim(a))
    b = trim(b)
    if len(a) < len(b):
        return [0], a
    q = [0] * (len(a) - len(b) + 1)
    for i in range(len(q)):
        f = a[i] / b[0]
        q[i] = f
        for j, y in enumerate(b):
            a[i + j] -= f * y
    r = trim(a[len(q):]) if len(a) > len(q) else [0]
    return trim(q), r


def is_zero(p):
    return all(c == 0 for c in p)


def pmonic(p):
    p = trim(p)
    return [c / p[0] for c in p]


def pgcd(a, b):
    a, b = trim(a), trim(b)
    while not is_zero(b):
        _, r = pdivmod(a, b)
        a, b = b, r
    return pmonic(a)


def yun(p):
    """Square-free factorisation of an exact polynomial: [(factor, multiplicity)]."""
    p = trim(p)
    if len(p) == 1:
        return []
    out = []
    d = pder(p)
    g = pgcd(p, d)
    c, _ = pdivmod(p, g)
    dd, _ = pdivmod(d, g)
    w = padd(dd, pscale(pder(c), -1))
    k = 1
    while len(trim(c)) > 1:
        # Yun: a_k = gcd(b_k, d_k) is the product of the roots of multiplicity exactly k
        y = pgcd(c, w)
        if len(trim(y)) > 1:
            out.append((pmonic(y), k))
        c, _ = pdivmod(c, y)
        wy, _ = pdivmod(w, y)
        w = padd(wy, pscale(pder(c), -1))
        k += 1
    return out


def exact(coeffs):
    return [Q(c) for c in coeffs]


def to_mp(p):
    return [mp.mpf(c.numerator) / c.denominator if isinstance(c, Q) else mp.mpf(c) for c in p]


def roots_mult(p):
    """Roots of an exact polynomial with multiplicities: [(mpc root, q)]."""
    out = []
    for f, q in yun(p):
        fm = to_mp(f)
        if len(fm) == 2:
            rs = [-fm[1] / fm[0]]
        else:
            rs = mp.polyroots(fm, maxsteps=2000, extraprec=600)
        for r in rs:
            r = mp.mpc(r)
            if abs(r.imag) <= mp.mpf(10) ** (-40) * abs(r):
                r = mp.mpc(r.real, 0)
            if abs(r.real) <= mp.mpf(10) ** (-40) * abs(r):
                r = mp.mpc(0, r.imag)
            out.append((r, q))
    return out


def taylor_at(p, r, q):
    """p^(q)(r)/q! for a descending mp polynomial p."""
    c = list(p)
    for _ in range(q):
        # synthetic division by (s - r): c -> quotient, remainder dropped
        out = [c[0]]
        for x in c[1:-1]:
            out.append(x + out[-1] * r)
        c = out
    return mp.polyval(c, r) if c else mp.mpf(0)


def root_records(coeffs):
    """Roots of the double-coefficient polynomial with multiplicity and kappa_q."""
    p = exact(coeffs)
    pm = to_mp(p)
    n = len(pm) - 1
    recs = []
    for r, q in roots_mult(p):
        top = sum(abs(c) * abs(r) ** (n - i) for i, c in enumerate(pm))
        lead = abs(taylor_at(pm, r, q))
        recs.append(dict(re=float(r.real), im=float(r.imag), mult=q, kappa=float(top / lead)))
    recs.sort(key=lambda d: (d["re"], d["im"]))
    return recs


# ----------------------------------------------------------------------------- systems


def poly_from_roots(roots):
    """Real monic polynomial (mp, descending) of a conjugate-closed root list."""
    p = [mp.mpf(1)]
    for r in roots:
        p = pmul(p, [mp.mpf(1), -mp.mpc(r)])
    return [mp.re(c) for c in p]


def dbl(p):
    return [float(c) for c in p]


class Gen:
    def __init__(self, seed):
        self.r = random.Random(seed)

    def u(self, a, b):
        return self.r.uniform(a, b)

    def logu(self, a, b):
        return math.exp(self.r.uniform(math.log(a), math.log(b)))

    def units(self, n, lo=0.1, hi=10.0, zeta=(0.05, 0.95)):
        """n stable roots as units: a real root [r] or a conjugate pair [r, conj r]."""
        out, count = [], 0
        while count < n:
            if n - count >= 2 and self.r.random() < 0.6:
                wn, z = self.logu(lo, hi), self.u(*zeta)
                r = complex(-z * wn, wn * math.sqrt(1 - z * z))
                out.append([r, r.conjugate()])
                count += 2
            else:
                out.append([complex(-self.logu(lo, hi), 0)])
                count += 1
        return out

    def stable_roots(self, n, **kw):
        return [r for u in self.units(n, **kw) for r in u]

    def flipped(self, n, count, **kw):
        """n roots of which `count` units (real roots or pairs) are mirrored into the ORHP."""
        us = self.units(n, **kw)
        idx = list(range(len(us)))
        self.r.shuffle(idx)
        for i in idx[:count]:
            us[i] = [complex(-r.real, r.imag) for r in us[i]]
        return [r for u in us for r in u]


def make_systems():
    g = Gen(SEED)
    systems = []

    def add(kind, zeros, poles, k, name=None):
        den = dbl(poly_from_roots(poles))
        num = dbl(pscale(poly_from_roots(zeros), mp.mpf(k)))
        systems.append(dict(name=name or f"{kind}_{len(systems)}", kind=kind, num=num, den=den))

    def orders():
        n = g.r.randint(1, 10)
        m = g.r.randint(0, n)
        return n, m

    for _ in range(20):  # stable, minimum phase, positive gain
        n, m = orders()
        add("stable", g.stable_roots(m), g.stable_roots(n), g.logu(0.1, 10))
    for _ in range(15):  # integrators (one or two exact poles at 0)
        n, m = orders()
        n = max(n, 2)
        i = g.r.randint(1, min(2, n))
        add("integrator", g.stable_roots(min(m, n - 1)), [0j] * i + g.stable_roots(n - i), g.logu(0.1, 10))
    for _ in range(15):  # right-half-plane zeros
        n, m = orders()
        m = max(m, 1)
        z = g.flipped(m, g.r.randint(1, m))
        add("rhp_zero", z, g.stable_roots(n), g.logu(0.1, 10) * g.r.choice([1, -1]))
    for _ in range(15):  # negative gain
        n, m = orders()
        add("negative_gain", g.stable_roots(m), g.stable_roots(n), -g.logu(0.1, 10))
    for _ in range(15):  # unstable poles
        n, m = orders()
        p = g.flipped(n, g.r.randint(1, max(1, n // 2)), hi=3.0)
        add("unstable", g.stable_roots(m), p, g.logu(0.1, 10) * g.r.choice([1, -1]))
    for i in range(15):  # ill-conditioned roots: clusters, or magnitudes spread over 10^4
        n = g.r.randint(4, 10)
        m = g.r.randint(0, n - 1)
        if i % 2 == 0:
            c = -g.logu(0.3, 3)
            q = g.r.randint(3, min(5, n))
            cluster = [complex(c * (1 + 1e-3 * g.u(-1, 1)), 0) for _ in range(q)]
            p = cluster + g.stable_roots(n - q)
        else:
            p = g.stable_roots(n, lo=1e-2, hi=1e2)
        add("ill_conditioned", g.stable_roots(m, lo=1e-2, hi=1e2), p, g.logu(0.1, 10))
    dyadic = [-0.5, -1.0, -2.0, -0.25, -4.0]
    for _ in range(15):  # exactly repeated poles (dyadic roots: exact coefficients)
        n = g.r.randint(2, 10)
        p = []
        while len(p) < n:
            q = min(g.r.randint(2, 4), n - len(p))
            p += [complex(g.r.choice(dyadic), 0)] * q
        m = g.r.randint(0, n)
        z = [complex(g.r.choice([-3.0, -1.5, -0.75, 0.5, 1.0]), 0) for _ in range(m)]
        add("repeated", z, p, g.r.choice([1.0, -2.0, 0.5, 4.0, -0.25]))
    for i in range(10):  # imaginary-axis poles (or zeros) with exact dyadic coefficients
        b = g.r.choice([0.5, 2.0, 1.0])
        rest = [complex(-0.25, 0.75), complex(-0.25, -0.75), complex(-1.0, 0), complex(-0.5, 0), complex(-2.0, 0)]
        g.r.shuffle(rest)
        k = g.r.randint(0, 3)
        others = [r for r in rest[:k]]
        others += [r.conjugate() for r in others if r.imag != 0 and r.conjugate() not in others]
        axis = [complex(0, b), complex(0, -b)]
        if i < 7:
            add("axis", [complex(-1.0, 0)] * g.r.randint(0, 1), axis + others, g.r.choice([1.0, 2.0, -0.5]))
        else:
            add("axis", axis, others + [complex(-4.0, 0), complex(-0.5, 0)], g.r.choice([1.0, 2.0, -0.5]))
    # every coefficient of the repeated and axis kinds must be exact for their roots to be exact
    for s in systems:
        if s["kind"] in ("repeated", "axis"):
            assert all(Q(c) == Q(c) for c in s["num"] + s["den"])
        assert s["den"][0] == 1.0
    return systems


# ----------------------------------------------------------------------------- frequency domain

J = mp.mpc(0, 1)


def asc(p):
    """(coefficient, power) pairs of a descending list."""
    n = len(p) - 1
    return [(c, n - i) for i, c in enumerate(p)]


def kappas(p, w, pv):
    """sum|c_k w^k|/|P|, sum|c_k Re((jw)^k/P)|, sum|c_k Im((jw)^k/P)| for one polynomial."""
    kg = km = kp = mp.mpf(0)
    for c, k in asc(p):
        if c == 0:
            continue
        t = c * (J * w) ** k / pv
        kg += abs(t)
        km += abs(t.real)
        kp += abs(t.imag)
    return kg, km, kp


def branch_arg(r, w):
    """arg(jw - r), continuous in w: principal for Re r <= 0, [0, 2pi) for Re r > 0."""
    a = mp.atan2(w - r.imag, -r.real) if r.real != 0 else (mp.pi / 2 if w > r.imag else -mp.pi / 2)
    if r.real > 0 and a < 0:
        a += 2 * mp.pi
    return a


def continuous_phase(zr, pr, k, w):
    """The book's branch (16.6.2): continuous in w > 0, equal at w -> 0+ to 0 or -180 deg by the
    sign of the low-frequency gain plus 90 deg per zero and -90 deg per pole at s = 0."""
    zeros = [r for r, q in zr for _ in range(q)]
    poles = [r for r, q in pr for _ in range(q)]
    k0 = mp.mpc(k)
    for z in zeros:
        if z != 0:
            k0 *= -z
    for p in poles:
        if p != 0:
            k0 /= -p
    nz0 = sum(1 for z in zeros if z == 0)
    np0 = sum(1 for p in poles if p == 0)
    base = (-mp.pi if k0.real < 0 else 0) + mp.pi / 2 * (nz0 - np0)
    tiny = mp.mpf(10) ** (-45)
    d = sum(branch_arg(z, w) - branch_arg(z, tiny) for z in zeros) - sum(
        branch_arg(p, w) - branch_arg(p, tiny) for p in poles
    )
    return base + d


def freq_points(zr, pr, extra):
    mags = [abs(r) for r, _ in zr + pr if abs(r) > 0]
    lo = min(mags + [1.0]) / 10
    hi = max(mags + [1.0]) * 10
    pts = [0.0] + [float(mp.mpf(lo) * (mp.mpf(hi) / lo) ** (mp.mpf(i) / 9)) for i in range(10)]
    pts += extra
    return sorted(set(pts))


def freq_records(num, den, zr, pr):
    n, d = to_mp(exact(num)), to_mp(exact(den))
    k = n[0]
    axis = [float(r.imag) for r, _ in zr + pr if r.real == 0 and r.imag > 0]
    out = []
    for w in freq_points(zr, pr, axis):
        wm = mp.mpf(w)
        nv, dv = mp.polyval(n, J * wm), mp.polyval(d, J * wm)
        rec = dict(w=w)
        if dv == 0 or nv == 0:
            # an imaginary-axis pole (|G| = +inf) or zero (|G| = 0): the phase is the limit from
            # above, w -> w0+ (the book's rule at w = 0)
            rec["pole" if dv == 0 else "zero"] = True
            rec["phase_deg"] = float(mp.degrees(continuous_phase(zr, pr, k, wm + mp.mpf(10) ** (-40))))
            out.append(rec)
            continue
        gv = nv / dv
        kg1, km1, kp1 = kappas(n, wm, nv)
        kg2, km2, kp2 = kappas(d, wm, dv)
        rec.update(
            re=float(gv.real),
            im=float(gv.imag),
            ln_mag=float(mp.log(abs(gv))),
            phase_deg=float(mp.degrees(continuous_phase(zr, pr, k, wm))),
            kappa_g=float(kg1 + kg2),
            kappa_mag=float(km1 + km2),
            kappa_phase=float(kp1 + kp2),
        )
        out.append(rec)
    return out


# ----------------------------------------------------------------------------- margins


def jw_even_odd(p):
    """E(x), O(x) (descending, exact) with p(jw) = E(w^2) + j w O(w^2)."""
    e, o = [], []
    for c, k in asc(p):
        sgn = -1 if (k // 2) % 2 else 1
        (e if k % 2 == 0 else o).append((c * sgn, k // 2))
    def build(terms):
        if not terms:
            return [Q(0)]
        m = max(k for _, k in terms)
        out = [Q(0)] * (m + 1)
        for c, k in terms:
            out[m - k] += c
        return trim(out)
    return build(e), build(o)


def positive_real_roots(p):
    if is_zero(p) or len(trim(p)) == 1:
        return []
    xs = []
    for r, _ in roots_mult(p):
        if r.imag == 0 and r.real > 0:
            xs.append(r.real)
    return sorted(xs)


def lval(n, d, w):
    return mp.polyval(n, J * w) / mp.polyval(d, J * w)


def pm_deg(l):
    """python-control: PM = mod(angle(L) in degrees, 360) - 180, angle in (-180, 180]."""
    a = mp.degrees(mp.atan2(l.imag, l.real))
    return a - 360 * mp.floor(a / 360) - 180


def solve_crossing(kind, n, d, w0):
    """Re-solves one crossing (or stationary point) near w0 for perturbed coefficients."""
    if kind == "gain":
        f = lambda w: mp.log(abs(mp.polyval(n, J * w))) - mp.log(abs(mp.polyval(d, J * w)))
    elif kind == "phase":
        f = lambda w: mp.im(mp.polyval(n, J * w) * mp.conj(mp.polyval(d, J * w))) / (
            abs(mp.polyval(n, J * w)) * abs(mp.polyval(d, J * w))
        )
    else:
        p = padd(n, d)
        def f(w):
            pv, pd = mp.polyval(p, J * w, derivative=True)
            dv, dd = mp.polyval(d, J * w, derivative=True)
            return -mp.im(pd / pv) + mp.im(dd / dv)
    return mp.findroot(f, w0, maxsteps=200, verify=False)


def quantity(kind, n, d, w):
    l = lval(n, d, w)
    if kind == "gain":
        return pm_deg(l)
    if kind == "phase":
        return -20 * mp.log10(abs(l)) if l != 0 else mp.inf
    return abs(1 + l)


def crossing_kappas(kind, n, d, w):
    """Condition numbers of w (relative) and of the margin (absolute; relative for 'stab') by
    central differences under relative perturbations of each nonzero coefficient."""
    h = mp.mpf(10) ** (-25)
    q0 = quantity(kind, n, d, w)
    kw = kq = mp.mpf(0)
    for which in (0, 1):
        base = n if which == 0 else d
        for i, c in enumerate(base):
            if c == 0:
                continue
            vals = []
            for sgn in (1, -1):
                pert = list(base)
                pert[i] = c * (1 + sgn * h)
                nn, dd = (pert, d) if which == 0 else (n, pert)
                wp = solve_crossing(kind, nn, dd, w)
                vals.append((wp, quantity(kind, nn, dd, wp)))
            kw += abs(vals[0][0] - vals[1][0]) / (2 * h)
            kq += abs(vals[0][1] - vals[1][1]) / (2 * h)
    kw /= w
    if kind == "stab":
        kq /= q0
    return float(kw), float(kq)


def margin_records(num, den):
    ne, de = exact(num), exact(den)
    n, d = to_mp(ne), to_mp(de)
    nr, no = jw_even_odd(ne)
    dr, do = jw_even_odd(de)
    x = [Q(1), Q(0)]
    phase, gain, stab = [], [], []
    # phase crossovers: w = 0 from the exact sign of N(0)/D(0), then Q(x) = No Dr - Nr Do = 0
    n0, d0 = ne[-1], de[-1]
    if d0 != 0 and n0 / d0 <= 0:
        # GM = |D(0)/N(0)| is exact up to the two coefficients: relative condition 2
        l0 = to_mp([n0 / d0])[0]
        phase.append(dict(w=0.0, gm=None if n0 == 0 else float(1 / abs(l0)),
                          gm_db=None if n0 == 0 else float(-20 * mp.log10(abs(l0))),
                          kappa_w=0.0, kappa_gm_db=float(2 * 20 / mp.log(10))))
    qx = padd(pmul(no, dr), pscale(pmul(nr, do), -1))
    for xr in positive_real_roots(qx):
        w = mp.sqrt(xr)
        nv, dv = mp.polyval(n, J * w), mp.polyval(d, J * w)
        if dv != 0 and nv != 0:
            w = solve_crossing("phase", n, d, w)
            nv, dv = mp.polyval(n, J * w), mp.polyval(d, J * w)
        if dv == 0:
            continue
        l = nv / dv
        if l.real <= 0:
            if nv == 0:
                # an imaginary-axis zero of L: GM = +inf (null); w is exact (a root of N alone)
                phase.append(dict(w=float(w), gm=None, gm_db=None, kappa_w=0.0, kappa_gm_db=0.0))
                continue
            kw, kq = crossing_kappas("phase", n, d, w)
            phase.append(dict(w=float(w), gm=float(1 / abs(l)), gm_db=float(-20 * mp.log10(abs(l))),
                              kappa_w=kw, kappa_gm_db=kq))
    # gain crossovers: |N|^2 - |D|^2 = Nr^2 + x No^2 - Dr^2 - x Do^2 = 0
    gx = padd(padd(pmul(nr, nr), pmul(x, pmul(no, no))), pscale(padd(pmul(dr, dr), pmul(x, pmul(do, do))), -1))
    for xr in positive_real_roots(gx):
        if mp.polyval(d, J * mp.sqrt(xr)) == 0:
            continue  # |N| = |D| = 0: a common axis root, not a crossover
        w = solve_crossing("gain", n, d, mp.sqrt(xr))
        kw, kq = crossing_kappas("gain", n, d, w)
        gain.append(dict(w=float(w), pm_deg=float(pm_deg(lval(n, d, w))), kappa_w=kw, kappa_pm_deg=kq))
    # stability margin: H(x) = F'G - G'F for F = |N + D|^2, G = |D|^2 (in x = w^2), H'(x) > 0
    pe = padd(ne, de)
    pr_, po = jw_even_odd(pe)
    fx = padd(pmul(pr_, pr_), pmul(x, pmul(po, po)))
    gdx = padd(pmul(dr, dr), pmul(x, pmul(do, do)))
    hx = padd(pmul(pder(fx), gdx), pscale(pmul(pder(gdx), fx), -1))
    hd = pder(hx)
    fm = to_mp(fx)
    for xr in positive_real_roots(hx):
        if mp.polyval(to_mp(hd), xr) <= 0:
            continue
        if abs(mp.polyval(fm, xr)) <= mp.mpf(10) ** (-40) * sum(abs(c) * xr ** (len(fm) - 1 - i) for i, c in enumerate(fm)):
            # 1 + L(jw) = 0: a closed-loop pole on the imaginary axis, distance 0 (a kink of
            # |1 + L|, not a smooth minimum); w is a root of N + D alone
            stab.append(dict(w=float(mp.sqrt(xr)), sm=0.0, kappa_w=None, kappa_sm=None))
            continue
        w = solve_crossing("stab", n, d, mp.sqrt(xr))
        kw, kq = crossing_kappas("stab", n, d, w)
        stab.append(dict(w=float(w), sm=float(abs(1 + lval(n, d, w))), kappa_w=kw, kappa_sm=kq))
    return dict(phase_crossovers=phase, gain_crossovers=gain, stability_points=stab)


# ----------------------------------------------------------------------------- time domain


def companion(num, den):
    """The crate's StateSpace::from_tf (15.7.3) at 60 digits: monic D, B = e_n."""
    n = len(den) - 1
    dm = [mp.mpf(c) / mp.mpf(den[0]) for c in den]
    a = [dm[n - k] for k in range(n)]  # a_0 .. a_{n-1} (ascending)
    nm = [mp.mpf(0)] * (n + 1 - len(num)) + [mp.mpf(c) / mp.mpf(den[0]) for c in num]
    b = [nm[n - k] for k in range(n + 1)]  # b_0 .. b_n
    A = mp.zeros(n, n)
    for i in range(n - 1):
        A[i, i + 1] = 1
    for k in range(n):
        A[n - 1, k] = -a[k]
    C = [b[k] - a[k] * b[n] for k in range(n)]
    return A, C, b[n], a, b


def expm(M):
    return mp.expm(M)


def grid(num, den, pr):
    """Dyadic step h = 2^j with 200 h about six time constants (or five e-folds when unstable)."""
    growth = max([r.real for r, _ in pr] + [-1e9])
    slow = min([abs(r) for r, _ in pr if abs(r) > 0] + [1.0])
    t_end = 5.0 / float(growth) if growth > 1e-12 else 6.0 / float(slow)
    t_end = min(max(t_end, 2.0), 400.0)
    j = round(math.log2(t_end / 200))
    return 2.0 ** j


def input_sequence(nt):
    """An exact dyadic input: u_k = ((37k mod 17) - 8)/8, the same integers in Rust."""
    return [((37 * k) % 17 - 8) / 8 for k in range(nt)]


def driven(num, den, h, mode, u=None):
    """y and S (sum over coefficients of |c dy/dc|) for mode in impulse, step, zoh, foh.

    Augmented state (x, z, v, vdot): x' = A x + e_n v, y = C x + D v, z' = A z + e_n y, with
    x_i = L^-1{s^i V/Den}, z_i = L^-1{s^i Y/Den}, so dy/dn_k = x_k (k < n; u - sum a_i x_i for
    k = n) and dy/dd_k = -z_k (k < n; -y + sum a_i z_i for k = n)."""
    A, C, Dff, a, b = companion(num, den)
    n = A.rows
    dim = 2 * n + 2
    M = mp.zeros(dim, dim)
    for i in range(n):
        for j in range(n):
            M[i, j] = A[i, j]
            M[n + i, n + j] = A[i, j]
    M[n - 1, 2 * n] = 1  # x' += e_n v
    for j in range(n):
        M[2 * n - 1, j] += C[j]  # z' += e_n C x
    M[2 * n - 1, 2 * n] += Dff  # z' += e_n D v
    M[2 * n, 2 * n + 1] = 1  # v' = vdot
    Phi = expm(M * h)
    z = mp.zeros(dim, 1)
    nt = N_TIME
    uu = None
    if mode == "impulse":
        z[n - 1] = 1  # x(0+) = B
        z[2 * n - 1] = Dff  # z(0+) = D e_n (the Dirac part of y drives z)
    elif mode == "step":
        z[2 * n] = 1
    else:
        uu = [mp.mpf(x) for x in u]
    ncoef_num = [mp.mpf(c) for c in num]
    ncoef_den = [mp.mpf(c) for c in den]
    numasc = list(reversed(ncoef_num)) + [mp.mpf(0)] * (n + 1 - len(num))
    denasc = list(reversed(ncoef_den))
    ys, ss = [], []
    for kk in range(nt):
        if uu is not None:
            z[2 * n] = uu[kk]
            z[2 * n + 1] = 0 if (mode == "zoh" or kk + 1 == nt) else (uu[kk + 1] - uu[kk]) / h
        v = z[2 * n] if mode != "impulse" else mp.mpf(0)
        x = [z[i] for i in range(n)]
        zz = [z[n + i] for i in range(n)]
        y = sum(C[i] * x[i] for i in range(n)) + Dff * v
        dn = [x[k] for k in range(n)] + [v - sum(a[i] * x[i] for i in range(n))]
        dd = [-zz[k] for k in range(n)] + [-y + sum(a[i] * zz[i] for i in range(n))]
        s = sum(abs(numasc[k] * dn[k]) for k in range(n + 1)) + sum(abs(denasc[k] * dd[k]) for k in range(n + 1))
        ys.append(y)
        ss.append(s)
        z = Phi * z
    return ys, ss


def response_only(num, den, h, mode, u):
    ys, _ = driven(num, den, h, mode, u)
    return ys


def pulse_kappa(num, den, h, mode, u):
    """sum_i |u_i| |h_i(t_k)|: the condition contribution of the input samples. h_i is the
    response to a unit sample i (ZOH: a pulse; FOH: a hat), shift-invariant on the grid."""
    nt = N_TIME
    e0 = [0.0] * nt
    e0[0] = 1.0
    r0 = response_only(num, den, h, mode, e0)
    if mode == "zoh":
        return [sum(abs(mp.mpf(u[i])) * abs(r0[k - i]) for i in range(k + 1)) for k in range(nt)]
    e1 = [0.0] * nt
    e1[1] = 1.0
    r1 = response_only(num, den, h, mode, e1)
    out = []
    for k in range(nt):
        acc = abs(mp.mpf(u[0])) * abs(r0[k])
        for i in range(1, k + 1):
            acc += abs(mp.mpf(u[i])) * abs(r1[k - i + 1])
        out.append(acc)
    return out


def initial_response(num, den, h, x0):
    """Free response y = C e^{At} x0 of the companion realisation and S over coefficients and x0.

    Augmented (x, p, v): x' = A x, x(0) = x0; p' = A p, p(0) = e_n (g = C p is the impulse
    response); v' = A v + x0 (C p), so dy/da_k = -v_k (a_k = d_k). With C_k = n_k - d_k n_n:
    dy/dn_k = x_k (k < n), dy/dn_n = -sum d_k x_k, dy/dd_k = -v_k - n_n x_k (k < n), and
    dy/dd_n from homogeneity (the realisation is invariant under scaling N and D together).
    dy/dx0_i = (C Phi^k)_i, propagated as a row."""
    A, C, Dff, a, b = companion(num, den)
    n = A.rows
    dim = 3 * n
    M = mp.zeros(dim, dim)
    for i in range(n):
        for j in range(n):
            M[i, j] = A[i, j]
            M[n + i, n + j] = A[i, j]
            M[2 * n + i, 2 * n + j] = A[i, j]
    for i in range(n):
        for j in range(n):
            M[2 * n + i, n + j] += mp.mpf(x0[i]) * C[j]
    Phi = expm(M * h)
    Pa = expm(A * h)
    z = mp.zeros(dim, 1)
    for i in range(n):
        z[i] = x0[i]
    z[2 * n - 1] = 1
    row = mp.matrix([C])
    nn = [mp.mpf(c) for c in num]
    numasc = list(reversed(nn)) + [mp.mpf(0)] * (n + 1 - len(num))
    denasc = list(reversed([mp.mpf(c) for c in den]))
    nn_n = numasc[n]
    ys, ss = [], []
    for kk in range(N_TIME):
        x = [z[i] for i in range(n)]
        v = [z[2 * n + i] for i in range(n)]
        y = sum(C[i] * x[i] for i in range(n))
        dn = [x[k] for k in range(n)] + [-sum(denasc[k] * x[k] for k in range(n))]
        dd = [-v[k] - nn_n * x[k] for k in range(n)]
        dd.append(-(sum(numasc[k] * dn[k] for k in range(n + 1)) + sum(denasc[k] * dd[k] for k in range(n))))
        s = sum(abs(numasc[k] * dn[k]) for k in range(n + 1)) + sum(abs(denasc[k] * dd[k]) for k in range(n + 1))
        s += sum(abs(mp.mpf(x0[i]) * row[0, i]) for i in range(n))
        ys.append(y)
        ss.append(s)
        z = Phi * z
        row = row * Pa
    return ys, ss


def x0_of(n):
    return [((5 * i) % 7 - 3) / 4 for i in range(n)]


def time_records(num, den, pr):
    h = grid(num, den, pr)
    n = len(den) - 1
    u = input_sequence(N_TIME)
    out = dict(h=h, n=N_TIME, keep=KEEP, x0=x0_of(n))
    for mode in ("step", "impulse", "zoh", "foh"):
        ys, ss = driven(num, den, h, mode, u)
        if mode in ("zoh", "foh"):
            su = pulse_kappa(num, den, h, mode, u)
            ss = [a + b for a, b in zip(ss, su)]
        out[mode] = dict(y=[float(v) for v in ys[::KEEP]], s=[float(v) for v in ss[::KEEP]],
                         s_max=[float(max(ss[: k + 1])) for k in range(0, N_TIME, KEEP)])
    ys, ss = initial_response(num, den, h, out["x0"])
    out["initial"] = dict(y=[float(v) for v in ys[::KEEP]], s=[float(v) for v in ss[::KEEP]],
                          s_max=[float(max(ss[: k + 1])) for k in range(0, N_TIME, KEEP)])
    return out


def fd_check(num, den, pr):
    """Checks the augmented-system derivatives against finite differences (step and initial)."""
    h = grid(num, den, pr)
    ys, ss = driven(num, den, h, "step")
    n = len(den) - 1
    x0 = x0_of(n)
    yi, si = initial_response(num, den, h, x0)
    eps = mp.mpf(10) ** (-20)
    s_fd = [mp.mpf(0)] * N_TIME
    si_fd = [mp.mpf(0)] * N_TIME
    for which in (0, 1):
        base = num if which == 0 else den
        for i, c in enumerate(base):
            if c == 0:
                continue
            pert = [mp.mpf(x) for x in base]
            pert[i] = mp.mpf(c) * (1 + eps)
            nn, dd = (pert, den) if which == 0 else (num, pert)
            yp, _ = driven(nn, dd, h, "step")
            ypi, _ = initial_response(nn, dd, h, x0)
            for k in range(N_TIME):
                s_fd[k] += abs(yp[k] - ys[k]) / eps
                si_fd[k] += abs(ypi[k] - yi[k]) / eps
    for i in range(n):
        if x0[i] == 0:
            continue
        xp = [mp.mpf(v) for v in x0]
        xp[i] = xp[i] * (1 + eps)
        ypi, _ = initial_response(num, den, h, xp)
        for k in range(N_TIME):
            si_fd[k] += abs(ypi[k] - yi[k]) / eps
    worst = max(abs(a - b) / max(b, mp.mpf(10) ** -30) for a, b in zip(ss, s_fd))
    worst_i = max(abs(a - b) / max(b, mp.mpf(10) ** -30) for a, b in zip(si, si_fd))
    print(f"finite-difference check of S: step {mp.nstr(worst, 3)}, initial {mp.nstr(worst_i, 3)}")
    assert worst < 1e-6 and worst_i < 1e-6


# ----------------------------------------------------------------------------- python-control


def cross_check(sysrec):
    try:
        import control as ct
        import numpy as np
        import warnings
    except ImportError:
        return None
    warnings.simplefilter("ignore")
    g = ct.tf(sysrec["num"], sysrec["den"])
    gm, pm, sm, wpc, wgc, wms = ct.stability_margins(g, returnall=True)
    ref = sysrec["margins"]
    problems = []
    def cmp(name, got, want):
        got = sorted(float(x) for x in np.atleast_1d(got))
        want = sorted(want)
        if len(got) != len(want) or any(abs(a - b) > 1e-6 * max(1, abs(b)) for a, b in zip(got, want)):
            problems.append(f"{name}: python-control {got} exact {want}")
    cmp("phase crossovers", wpc, [c["w"] for c in ref["phase_crossovers"]])
    cmp("gain crossovers", wgc, [c["w"] for c in ref["gain_crossovers"]])
    cmp("stability points", wms, [c["w"] for c in ref["stability_points"]])
    return problems


# ----------------------------------------------------------------------------- main


def main():
    systems = make_systems()
    limit = os.environ.get("LTI_REFERENCE_LIMIT")  # a quick trial: only the first few systems
    if limit:
        systems = systems[:: max(1, len(systems) // int(limit))]
    out_path = os.environ.get("LTI_REFERENCE_OUT", OUT)
    print(f"{len(systems)} systems")
    out = []
    disagree = 0
    cache = os.environ.get("LTI_REFERENCE_CACHE")  # a folder of finished records (resume)
    for i, s in enumerate(systems):
        key = None
        if cache:
            os.makedirs(cache, exist_ok=True)
            key = os.path.join(cache, s["name"] + ".json")
            if os.path.exists(key):
                with open(key) as fh:
                    rec = json.load(fh)
                if rec["num"] == s["num"] and rec["den"] == s["den"]:
                    out.append(rec)
                    print(f"{i + 1:3d}/{len(systems)} {rec['name']} (cached)", flush=True)
                    continue
        zr = roots_mult(exact(s["num"])) if any(c != 0 for c in s["num"]) else []
        pr = roots_mult(exact(s["den"]))
        rec = dict(s)
        rec["zeros"] = root_records(s["num"]) if len(s["num"]) > 1 else []
        rec["poles"] = root_records(s["den"])
        n0, d0 = Q(s["num"][-1]), Q(s["den"][-1])
        rec["dc_gain"] = float(n0 / d0) if d0 != 0 else None
        rec["freq"] = freq_records(s["num"], s["den"], zr, pr)
        rec["margins"] = margin_records(s["num"], s["den"])
        rec["time"] = time_records(s["num"], s["den"], pr)
        if i == 0:
            fd_check(s["num"], s["den"], pr)
        probs = cross_check(rec)
        if probs:
            disagree += 1
            print(f"  {rec['name']}: python-control differs from the exact lists: {'; '.join(probs)}")
        out.append(rec)
        if key:
            with open(key, "w") as fh:
                json.dump(rec, fh, allow_nan=False)
        print(f"{i + 1:3d}/{len(systems)} {rec['name']} n = {len(s['den']) - 1}", flush=True)
    print(f"python-control disagrees with the exact crossover lists on {disagree} of {len(out)} systems")
    doc = dict(
        generator="scripts/lti_reference.py",
        digits=DPS,
        seed=SEED,
        note="Every value is computed from the double coefficients num/den (descending powers) "
        "read exactly; see the script's docstring for the definitions.",
        systems=out,
    )
    os.makedirs(os.path.dirname(os.path.abspath(out_path)), exist_ok=True)
    with open(out_path, "w") as f:
        json.dump(doc, f, separators=(",", ":"), allow_nan=False, default=_inf)
    print(f"wrote {out_path} ({os.path.getsize(out_path)} bytes)")


def _inf(x):
    raise TypeError(x)


if __name__ == "__main__":
    main()
