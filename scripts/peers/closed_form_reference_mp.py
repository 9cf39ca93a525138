"""Extended-precision end states of the frontier's closed-form problems (issue 39, item 4), so
that the 1e-12 column measures the tools and not the reference. mpmath at 40 significant
digits, from the same formulas as frontier_common.py but none of its floating-point code:

* `rigid-body`: ω(20) of the torque-free body I = (1, 2, 3), ω(0) = (1, 0, 0.5) (Landau &
  Lifshitz, Mechanics §37: ω ∝ (cn, sn, dn) or with indices 1 ↔ 3, rate and parameter from
  E and M), Jacobi functions by `mpmath.ellipfun`.
* `kepler-e0.9`: (x, y, ẋ, ẏ)(20) from periapsis, a = μ = 1: Kepler's equation
  E − e sin E = t solved by `mpmath.findroot` (Newton) from E = π.
* `pendulum`: (θ, θ̇)(10) of θ̈ = −sin θ from rest at 3 rad: sin(θ/2) = k sn(K − t | k²),
  θ̇ = −2k cn(K − t | k²), K = `mpmath.ellipk`.

Each value is computed twice, at 40 and at 60 digits; "convergence" is their max-norm
difference. Writes tests/data/closed_form_reference_mp.json (the doubles nearest the 40-digit
values, and those values as strings). Run once with the peers' venv:
`~/.venv-peers/bin/python scripts/peers/closed_form_reference_mp.py`."""
import json
import os

import mpmath as mp

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "..", "tests", "data", "closed_form_reference_mp.json")


def rigid(t):
    inertia = [mp.mpf(1), mp.mpf(2), mp.mpf(3)]
    w0 = [mp.mpf(1), mp.mpf(0), mp.mpf("0.5")]
    two_e = sum(i * w * w for i, w in zip(inertia, w0))
    m2 = sum((i * w) ** 2 for i, w in zip(inertia, w0))
    a, b, c = (0, 1, 2) if m2 > two_e * inertia[1] else (2, 1, 0)
    ia, ib, ic = inertia[a], inertia[b], inertia[c]
    rate = mp.sqrt((ic - ib) * (m2 - two_e * ia) / (ia * ib * ic))
    k2 = (ib - ia) * (two_e * ic - m2) / ((ic - ib) * (m2 - two_e * ia))
    u = rate * t
    sn, cn, dn = (mp.ellipfun(f, u, m=k2) for f in ("sn", "cn", "dn"))
    w = [mp.mpf(0)] * 3
    w[a] = mp.sign(w0[a]) * mp.sqrt((two_e * ic - m2) / (ia * (ic - ia))) * cn
    # ω₂(0) = 0 with I₂ω̇₂(0) = (I₃ − I₁) ω₃ ω₁: its sign is the sign of sn's coefficient
    wdot_b = (inertia[2] - inertia[0]) * w0[2] * w0[0] / inertia[1]
    w[b] = mp.sign(wdot_b) * mp.sqrt((two_e * ic - m2) / (ib * (ic - ib))) * sn
    w[c] = mp.sign(w0[c]) * mp.sqrt((m2 - two_e * ia) / (ic * (ic - ia))) * dn
    return w


def kepler(t):
    e = mp.mpf("0.9")
    m = mp.fmod(t, 2 * mp.pi)
    ea = mp.findroot(lambda x: x - e * mp.sin(x) - m, mp.pi)
    b = mp.sqrt(1 - e * e)
    de = 1 / (1 - e * mp.cos(ea))
    return [mp.cos(ea) - e, b * mp.sin(ea), -mp.sin(ea) * de, b * mp.cos(ea) * de]


def pendulum(t):
    k = mp.sin(mp.mpf(3) / 2)
    m = k * k
    u = mp.ellipk(m) - t
    sn, cn = mp.ellipfun("sn", u, m=m), mp.ellipfun("cn", u, m=m)
    return [2 * mp.asin(k * sn), -2 * k * cn]


PROBLEMS = (("rigid-body", rigid, 20, "ω(20) in body components"),
            ("kepler-e0.9", kepler, 20, "(x, y, ẋ, ẏ)(20)"),
            ("pendulum", pendulum, 10, "(θ, θ̇)(10)"))


def main():
    out = {"method": "mpmath closed forms at 40 digits, checked against 60 digits "
                     "(scripts/peers/closed_form_reference_mp.py)", "problems": {}}
    for name, f, t_end, what in PROBLEMS:
        mp.mp.dps = 60
        hi = f(mp.mpf(t_end))
        mp.mp.dps = 40
        lo = f(mp.mpf(t_end))
        conv = max(abs(x - y) for x, y in zip(lo, hi))
        out["problems"][name] = {"t_end": t_end, "what": what, "state": [float(x) for x in lo],
                                 "state_mp": [mp.nstr(x, 40) for x in lo], "convergence": float(conv)}
        print(name, [mp.nstr(x, 20) for x in lo], "convergence", mp.nstr(conv, 3))
    with open(OUT, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    print("wrote", os.path.normpath(OUT))


if __name__ == "__main__":
    main()
