"""Reference end states of the stiff test problems of tests/ode_stiff.rs, computed once with
scipy's Radau (Hairer-Wanner RADAU5 in Python) at rtol = 1e-13 with absolute tolerances
far below each component's size, and cross-checked against scipy's BDF and LSODA at
rtol = 1e-12: the stored `uncertainty` is the largest relative difference of those runs to
the Radau reference (per problem), so tests can ask for no more than that.

  Robertson's chemical kinetics (HW II §IV.1, (1.3)): y1' = -0.04 y1 + 1e4 y2 y3,
  y2' = 0.04 y1 - 1e4 y2 y3 - 3e7 y2^2, y3' = 3e7 y2^2, y(0) = (1, 0, 0), t in [0, 40] and [0, 1e5].
  A pendulum on a stiff spring (docs/accuracy.md "Stiff problems", crates/ode/examples/stiff_work):
  a point mass m = 1 on a spring of rest length l0 = 1 with mg/(k l0) = 1e-4 in gravity g = 9.81,
  Cartesian (x, y, x', y'), y up, from rest at theta0 = 0.1 with r0 = l0 + mg cos(theta0)/k,
  t in [0, 2]; its cross-check adds DOP853 at 1e-13 (a non-stiff method: the fast mode is an
  undamped oscillation of 313 rad/s, which it resolves) and its uncertainty is absolute / l0.
  (Van der Pol at mu = 1000 is checked against the published VDPOL reference of the Test Set
  for IVP Solvers instead: scipy's Radau at 1e-13 over [0, 3000] took longer than 25 minutes.)

Run: ~/.venv-peers/bin/python scripts/stiff_reference.py [case ...]  (writes
tests/data/stiff_reference.json; with case names, recomputes only those and keeps the others)
"""
import json
import pathlib
import sys

import numpy as np
import scipy
from scipy.integrate import solve_ivp


def robertson(t, y):
    return [-0.04 * y[0] + 1e4 * y[1] * y[2],
            0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2,
            3e7 * y[1] ** 2]


def robertson_jac(t, y):
    return [[-0.04, 1e4 * y[2], 1e4 * y[1]],
            [0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]],
            [0.0, 6e7 * y[1], 0.0]]


PEND_M, PEND_G, PEND_L0, PEND_STRETCH, PEND_THETA0 = 1.0, 9.81, 1.0, 1e-4, 0.1
PEND_K = PEND_M * PEND_G / (PEND_STRETCH * PEND_L0)


def pendulum(t, s):
    r = np.hypot(s[0], s[1])
    fr = -PEND_K / PEND_M * (1.0 - PEND_L0 / r)
    return [s[2], s[3], fr * s[0], fr * s[1] - PEND_G]


def pendulum_jac(t, s):
    x, y = s[0], s[1]
    r = np.hypot(x, y)
    w2 = PEND_K / PEND_M
    fr = -w2 * (1.0 - PEND_L0 / r)
    c = w2 * PEND_L0 / r ** 3
    return [[0, 0, 1, 0], [0, 0, 0, 1], [fr - c * x * x, -c * x * y, 0, 0], [-c * x * y, fr - c * y * y, 0, 0]]


def pendulum_y0():
    r0 = PEND_L0 + PEND_M * PEND_G * np.cos(PEND_THETA0) / PEND_K
    return [r0 * np.sin(PEND_THETA0), -r0 * np.cos(PEND_THETA0), 0.0, 0.0]


def solve(rhs, jac, y0, t_end, method, rtol, atol):
    sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, rtol=rtol, atol=atol, jac=jac)
    assert sol.success, sol.message
    return sol.y[:, -1]


def case(name, rhs, jac, y0, t_end, atol, scale=None, checks=(("BDF", 1e-12), ("LSODA", 1e-12))):
    """Radau at 1e-13 and the largest difference of `checks` to it: relative per component,
    or absolute over `scale` when components pass through zero."""
    ref = solve(rhs, jac, y0, t_end, "Radau", 1e-13, atol)
    print(name, "Radau done", flush=True)
    diffs = []
    for method, rtol in checks:
        other = solve(rhs, jac, y0, t_end, method, rtol, atol)
        d = np.abs(other - ref) / (scale if scale else np.abs(ref))
        diffs.append(float(np.max(d)))
        print(name, method, diffs[-1], flush=True)
    return {"name": name, "t_end": t_end, "y0": list(y0), "y": [float(v) for v in ref],
            "uncertainty": max(diffs)}


def main():
    path = pathlib.Path(__file__).resolve().parent.parent / "tests" / "data" / "stiff_reference.json"
    out = {"generator": "scripts/stiff_reference.py", "scipy": scipy.__version__,
           "method": "scipy.integrate.solve_ivp Radau rtol=1e-13; uncertainty = max rel. diff. of BDF/LSODA at 1e-12"
                     " (spring_pendulum: max abs. diff. / l0 of BDF/LSODA at 1e-12 and DOP853 at 1e-13)",
           "cases": []}
    only = sys.argv[1:]
    if only:  # keep the stored cases that are not recomputed
        out["cases"] = [c for c in json.loads(path.read_text())["cases"] if c["name"] not in only]
    todo = [
        ("robertson_40", robertson, robertson_jac, [1.0, 0.0, 0.0], 40.0, [1e-20, 1e-24, 1e-20]),
        ("robertson_1e5", robertson, robertson_jac, [1.0, 0.0, 0.0], 1e5, [1e-20, 1e-24, 1e-20]),
        ("spring_pendulum", pendulum, pendulum_jac, pendulum_y0(), 2.0, 1e-15, PEND_L0,
         (("BDF", 1e-12), ("LSODA", 1e-12), ("DOP853", 1e-13))),
    ]
    if only:
        todo = [t for t in todo if t[0] in only]
    for args in todo:
        out["cases"].append(case(*args))
        path.write_text(json.dumps(out, indent=1) + "\n")
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
