"""scipy's stiff methods (solve_ivp Radau, BDF, LSODA, exact Jacobians given) on the five stiff
problems of docs/accuracy.md "Stiff problems" (issue 34), at rtol = 1e-4 ... 1e-10, with the
same definitions, tolerances and error measures as crates/ode/examples/stiff_work/problems.rs:

* `chain`: six unit masses between two walls, springs k = 1e6 N/m and dashpots c = 1e5 N s/m
  (C = 0.1 K), x(0) = X0, v(0) = 0, t in [0, 0.2], atol = 1e-3 rtol; error = max |x - x*| /
  max |x(0)| against the modal closed form.
* `pendulum`: a point mass on a stiff spring (mg/(k l0) = 1e-4, k/m = 9.81e4 against
  g/l0 = 9.81), Cartesian, from rest at theta0 = 0.1, t in [0, 2], atol = rtol; error =
  max |r - r*| / l0 against scipy Radau at 1e-13 (tests/data/stiff_reference.json,
  scripts/stiff_reference.py).
* `damper`: a hinge with a stiff damper, I th'' + c th' + k th = 0, I = 1e-2, k = 10, c = 100
  (eigenvalues -0.1 and -1e4 /s), th(0) = 1, th'(0) = 100, t in [0, 10], atol = rtol; error =
  |th - th*| / th(0) against the closed form.
* `robertson`: t in [0, 1e5], atol = 1e-6 rtol; max relative error against the stored reference.
* `vdp`: VDPOL (Van der Pol mu = 1000, eps = 1e-6), t in [0, 2], atol = rtol; max relative error
  against the Test Set's end state.

Prints one JSON line per point (median wall time of repeated runs, the right-hand side in numpy
as a scipy user writes it; nfev, njev, nlu as solve_ivp counts them). Run by
scripts/peers/stiff.sh in the sitting; alone: ~/.venv-peers/bin/python scripts/peers/stiff_scipy.py
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

# ---------------------------------------------------------------- the damped chain
N = 6
K_OVER_M, ALPHA = 1e6, 0.1  # springs k = 1e6, dashpots c = ALPHA k, unit masses
CHAIN_T = 0.2
L = 2 * np.eye(N) - np.eye(N, k=1) - np.eye(N, k=-1)
A = np.block([[np.zeros((N, N)), np.eye(N)], [-K_OVER_M * L, -ALPHA * K_OVER_M * L]])
X0 = np.array([1e-3, -2e-3, 0.5e-3, 1.5e-3, 0.0, -1e-3])


def chain(t, y):
    return A @ y


def chain_exact(t):
    """The modal closed form of the chain (as crates/ode/examples/stiff_work/problems.rs)."""
    x = np.zeros(N)
    for j in range(1, N + 1):
        phi = np.sin(np.pi * np.arange(1, N + 1) * j / (N + 1))
        q0 = 2.0 / (N + 1) * phi @ X0
        w2 = K_OVER_M * 4 * np.sin(np.pi * j / (2 * (N + 1))) ** 2
        zw = 0.5 * ALPHA * w2
        disc = w2 - zw * zw
        if disc > 0:
            wd = np.sqrt(disc)
            q = q0 * np.exp(-zw * t) * (np.cos(wd * t) + zw / wd * np.sin(wd * t))
        else:
            r2 = -zw - np.sqrt(-disc)  # fast root; the slow one from r1 r2 = w^2
            r1 = w2 / r2
            q = q0 * (r2 * np.exp(r1 * t) - r1 * np.exp(r2 * t)) / (r2 - r1)
        x += q * phi
    return x


# ---------------------------------------------------------------- the pendulum on a stiff spring
PEND_M, PEND_G, PEND_L0, PEND_STRETCH, PEND_THETA0, PEND_T = 1.0, 9.81, 1.0, 1e-4, 0.1, 2.0
PEND_K = PEND_M * PEND_G / (PEND_STRETCH * PEND_L0)
PEND_REF = np.array(CASES["spring_pendulum"]["y"])
PEND_Y0 = np.array(CASES["spring_pendulum"]["y0"])


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


# ---------------------------------------------------------------- the hinge with a stiff damper
DAMP_I, DAMP_K, DAMP_C, DAMP_THETA0, DAMP_OMEGA0, DAMP_T = 1e-2, 10.0, 100.0, 1.0, 100.0, 10.0
DAMP_J = np.array([[0.0, 1.0], [-DAMP_K / DAMP_I, -DAMP_C / DAMP_I]])


def damper(t, s):
    return DAMP_J @ s


def damper_exact(t):
    """theta(t) = a e^{l1 t} + b e^{l2 t}: l1 l2 = k/I, l1 + l2 = -c/I, a + b = th0, l1 a + l2 b = w0."""
    l2 = (-DAMP_C - np.sqrt(DAMP_C ** 2 - 4 * DAMP_I * DAMP_K)) / (2 * DAMP_I)
    l1 = DAMP_K / (DAMP_I * l2)
    b = (DAMP_OMEGA0 - l1 * DAMP_THETA0) / (l2 - l1)
    return (DAMP_THETA0 - b) * np.exp(l1 * t) + b * np.exp(l2 * t)


def problems():
    """(id, f, jac, y0, t_end, atol / rtol, error of the end state)."""
    rob = np.array(CASES["robertson_1e5"]["y"])
    chain_x = chain_exact(CHAIN_T)
    damp_th = damper_exact(DAMP_T)
    return [
        ("chain", chain, A, np.concatenate([X0, np.zeros(N)]), CHAIN_T, 1e-3,
         lambda y: np.max(np.abs(y[:N] - chain_x)) / np.max(np.abs(X0))),
        ("pendulum", pendulum, pendulum_jac, PEND_Y0, PEND_T, 1.0,
         lambda y: np.max(np.abs(y[:2] - PEND_REF[:2])) / PEND_L0),
        ("damper", damper, DAMP_J, np.array([DAMP_THETA0, DAMP_OMEGA0]), DAMP_T, 1.0,
         lambda y: abs(y[0] - damp_th) / DAMP_THETA0),
        ("robertson", robertson, robertson_jac, [1.0, 0.0, 0.0], 1e5, 1e-6,
         lambda y: np.max(np.abs((y - rob) / rob))),
        ("vdp", vdp, vdp_jac, [2.0, 0.0], 2.0, 1.0, lambda y: np.max(np.abs((y - VDPOL_REF) / VDPOL_REF))),
    ]


def main():
    for name, f, jac, y0, t_end, atol_rel, err in problems():
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
                                  "secs": secs, "fevals": int(sol.nfev), "jacobians": int(sol.njev),
                                  "lu": int(sol.nlu), "repeats": reps}), flush=True)
                if secs > 20:
                    break


if __name__ == "__main__":
    main()
