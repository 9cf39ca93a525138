"""scipy's stiff methods (solve_ivp Radau, BDF, LSODA, exact Jacobians given) on the stiff
problems of docs/accuracy.md "Stiff problems" (issue 34), at rtol = 1e-4 ... 1e-10, errors
against the stored references (tests/data/stiff_reference.json; Van der Pol: the Test Set's VDPOL) and, for the damped chain, its
modal closed form. Prints one JSON line per point (median wall time of repeated runs, the
right-hand side in numpy as a scipy user writes it). The vectrix side and diffsol are measured
in the same sitting by the scratch crate described there.

Run: ~/.venv-peers/bin/python scripts/peers/stiff_scipy.py
"""
import json
import os

import numpy as np
from scipy.integrate import solve_ivp

from frontier_common import median_time

HERE = os.path.dirname(os.path.abspath(__file__))
REF = json.load(open(os.path.join(HERE, "..", "..", "tests", "data", "stiff_reference.json")))
CASES = {c["name"]: c for c in REF["cases"]}


def robertson(t, y):
    return [-0.04 * y[0] + 1e4 * y[1] * y[2], 0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] ** 2, 3e7 * y[1] ** 2]


def robertson_jac(t, y):
    return [[-0.04, 1e4 * y[2], 1e4 * y[1]], [0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]], [0.0, 6e7 * y[1], 0.0]]


def vdp(t, y):
    """VDPOL of the Test Set for IVP Solvers: eps = 1e-6 (mu = 1000 in scaled time), t in [0, 2]."""
    return [y[1], ((1 - y[0] ** 2) * y[1] - y[0]) / 1e-6]


def vdp_jac(t, y):
    return [[0.0, 1.0], [(-2 * y[0] * y[1] - 1) / 1e-6, (1 - y[0] ** 2) / 1e-6]]


VDPOL_REF = np.array([1.706167732170483, -0.8928097010247975])


N = 6
L = 2 * np.eye(N) - np.eye(N, k=1) - np.eye(N, k=-1)
A = np.block([[np.zeros((N, N)), np.eye(N)], [-1e6 * L, -1e4 * L]])
X0 = np.array([1e-3, -2e-3, 0.5e-3, 1.5e-3, 0.0, -1e-3])


def chain(t, y):
    return A @ y


def chain_exact(t):
    """The modal closed form of the chain (as crates/ode/tests/radau5.rs)."""
    x = np.zeros(N)
    for j in range(1, N + 1):
        phi = np.sin(np.pi * np.arange(1, N + 1) * j / (N + 1))
        q0 = 2.0 / (N + 1) * phi @ X0
        w2 = 1e6 * 4 * np.sin(np.pi * j / (2 * (N + 1))) ** 2
        zw = 0.5 * 1e-2 * w2
        disc = w2 - zw * zw
        if disc > 0:
            wd = np.sqrt(disc)
            q = q0 * np.exp(-zw * t) * (np.cos(wd * t) + zw / wd * np.sin(wd * t))
        else:
            s = np.sqrt(-disc)
            r1, r2 = -zw + s, -zw - s
            q = q0 * (r2 * np.exp(r1 * t) - r1 * np.exp(r2 * t)) / (r2 - r1)
        x += q * phi
    return x


def main():
    problems = [
        ("robertson", robertson, robertson_jac, [1.0, 0.0, 0.0], 1e5, 1e-6,
         lambda y: np.max(np.abs((y - CASES["robertson_1e5"]["y"]) / CASES["robertson_1e5"]["y"]))),
        ("vdp", vdp, vdp_jac, [2.0, 0.0], 2.0, 1.0, lambda y: np.max(np.abs((y - VDPOL_REF) / VDPOL_REF))),
        ("chain", chain, A, np.concatenate([X0, np.zeros(N)]), 0.02, 1e-3,
         lambda y: np.max(np.abs(y[:N] - chain_exact(0.02)))),
    ]
    for name, f, jac, y0, t_end, atol_rel, err in problems:
        # LSODA takes the Jacobian as a callable only (Radau and BDF also take a constant array)
        if not callable(jac):
            jac = (lambda J: lambda t, y: J)(jac)
        for method in ("Radau", "BDF", "LSODA"):
            for k in range(4, 11):
                rtol = 10.0 ** -k
                def run():
                    return solve_ivp(f, (0.0, t_end), y0, method=method, rtol=rtol, atol=rtol * atol_rel, jac=jac)
                secs, reps, sol = median_time(run, budget=1.0, max_repeats=5)
                e = float(err(sol.y[:, -1])) if sol.success else float("inf")
                print(json.dumps({"problem": name, "tool": f"scipy {method}", "rtol": rtol, "err": e,
                                  "secs": secs, "fevals": int(sol.nfev)}), flush=True)
                if secs > 20:
                    break


if __name__ == "__main__":
    main()
