"""Reference end states of the stiff test problems of tests/ode_stiff.rs, computed once with
scipy's Radau (Hairer-Wanner RADAU5 in Python) at rtol = 1e-13 with absolute tolerances
far below each component's size, and cross-checked against scipy's BDF and LSODA at
rtol = 1e-12: the stored `uncertainty` is the largest relative difference of those runs to
the Radau reference (per problem), so tests can ask for no more than that.

  Robertson's chemical kinetics (HW II §IV.1, (1.3)): y1' = -0.04 y1 + 1e4 y2 y3,
  y2' = 0.04 y1 - 1e4 y2 y3 - 3e7 y2^2, y3' = 3e7 y2^2, y(0) = (1, 0, 0), t in [0, 40] and [0, 1e5].
  (Van der Pol at mu = 1000 is checked against the published VDPOL reference of the Test Set
  for IVP Solvers instead: scipy's Radau at 1e-13 over [0, 3000] took longer than 25 minutes.)

Run: ~/.venv-peers/bin/python scripts/stiff_reference.py  (writes tests/data/stiff_reference.json)
"""
import json
import pathlib

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


def solve(rhs, jac, y0, t_end, method, rtol, atol):
    sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, rtol=rtol, atol=atol, jac=jac)
    assert sol.success, sol.message
    return sol.y[:, -1]


def case(name, rhs, jac, y0, t_end, atol):
    ref = solve(rhs, jac, y0, t_end, "Radau", 1e-13, atol)
    print(name, "Radau done", flush=True)
    diffs = []
    for method in ("BDF", "LSODA"):
        other = solve(rhs, jac, y0, t_end, method, 1e-12, atol)
        diffs.append(float(np.max(np.abs(other - ref) / np.abs(ref))))
        print(name, method, diffs[-1], flush=True)
    return {"name": name, "t_end": t_end, "y0": list(y0), "y": [float(v) for v in ref],
            "uncertainty": max(diffs)}


def main():
    path = pathlib.Path(__file__).resolve().parent.parent / "tests" / "data" / "stiff_reference.json"
    out = {"generator": "scripts/stiff_reference.py", "scipy": scipy.__version__,
           "method": "scipy.integrate.solve_ivp Radau rtol=1e-13; uncertainty = max rel. diff. of BDF/LSODA at 1e-12",
           "cases": []}
    todo = [
        ("robertson_40", robertson, robertson_jac, [1.0, 0.0, 0.0], 40.0, [1e-20, 1e-24, 1e-20]),
        ("robertson_1e5", robertson, robertson_jac, [1.0, 0.0, 0.0], 1e5, [1e-20, 1e-24, 1e-20]),
    ]
    for args in todo:
        out["cases"].append(case(*args))
        path.write_text(json.dumps(out, indent=1) + "\n")
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
