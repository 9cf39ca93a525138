"""Shared definitions of the work–precision frontier (issue 24): the problems, their exact
solutions (written here independently of vectrix, on scipy.special's elliptic functions), the
n-link chain of ../shared/peers/bench_mujoco.py, the timing rule and the JSON schema.

Every tool writes one JSON file `<results>/<tool>.json`:

    {"tool": "scipy", "versions": {...}, "machine": "...", "date": "...",
     "load_start": [1m, 5m, 15m], "load_end": [...], "threads": {...},
     "points": [{"problem": "kepler-e0.9", "series": "scipy DOP853", "tool": "scipy",
                 "route": "solve_ivp", "method": "DOP853", "param_name": "rtol", "param": 1e-6,
                 "error": 3.1e-5, "seconds": 0.0123, "setup_seconds": 0.0, "repeats": 5,
                 "fevals": 1234}, ...]}

`seconds` is the median wall time of one whole run (setup excluded: model compilation,
scene parsing); `setup_seconds` is a one-off cost the tool needs before it can run at all and
that the frontier adds to `seconds` (sympy's derivation + lambdify). The problems:

* `rigid-body`: torque-free asymmetric body, I = (1, 2, 3), ω(0) = (1, 0, 0.5), t ∈ [0, 20];
  error = max |ω(20) − ω_exact(20)| (body components).
* `kepler-e0.9`: r̈ = −r/|r|³ from periapsis, a = 1, e = 0.9, t ∈ [0, 20]; error = max-norm of
  (x, y, ẋ, ẏ) − exact at t = 20 (Kepler's equation).
* `pendulum`: θ̈ = −sin θ from rest at θ₀ = 3 rad, t ∈ [0, 10]; error = max-norm of (θ, θ̇) −
  exact (Jacobi elliptic functions).
* `chain-N`, N = 1, 2 (the double pendulum), 6, 12, 30: the hinge chain of bench_mujoco.py
  (capsules of mass 1, length 0.3, radius 0.02, hinges about y, g = 9.81 along −z) from
  q = (0.7, 0.1, …, 0.1), v = 0, t ∈ [0, 1]; error = max-norm of (q, v) − reference at t = 1
  (reference: reference.json, copied from the extended-precision reference
  tests/data/chain_reference_mp.json of chain_reference_mp.py (mpmath, 34 digits, Gragg–
  Bulirsch–Stoer, converged to < 1e-20); check_reference.py compares tight runs with it).
* `energy-pendulum`: θ̈ = −sin θ from rest at θ₀ = 1 rad over 10⁴ periods; error = max over
  1001 checkpoints (every 10 periods) of |E − E₀| / E₀, E = θ̇²/2 + 1 − cos θ.

The body, Kepler and the pendulum measure their errors against extended-precision end states
(closed_form_reference_mp.py: mpmath at 40 digits), so that the 1e-12 column measures tools.
"""
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from datetime import datetime, timezone

import numpy as np
from scipy.special import ellipj, ellipk

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
RESULTS = os.environ.get("FRONTIER_RESULTS", os.path.join(REPO, "docs", "accuracy", "peers-data"))

# ---------------------------------------------------------------- timing

# A line of a ladder stops once a run takes longer than this [s] (the next would be longer).
RUN_CAP = float(os.environ.get("FRONTIER_RUN_CAP", "20"))
# Errors below this are round-off: a line stops once it gets there.
FLOOR = 1e-13


def median_time(run, budget=1.0, max_repeats=7):
    """Runs `run()` once, then repeats it while the total stays under `budget` seconds (at
    most `max_repeats` runs in all); returns (median seconds, repeats, last result)."""
    t0 = time.perf_counter()
    out = run()
    times = [time.perf_counter() - t0]
    while len(times) < max_repeats and sum(times) + times[-1] < budget:
        t0 = time.perf_counter()
        out = run()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), len(times), out


def point(problem, tool, route, method, param_name, param, error, seconds, repeats, **extra):
    series = extra.pop("series", f"{tool} {method}")
    p = dict(problem=problem, series=series, tool=tool, route=route, method=method,
             param_name=param_name, param=float(param),
             error=float(error) if np.isfinite(error) else None, seconds=float(seconds),
             setup_seconds=float(extra.pop("setup_seconds", 0.0)), repeats=int(repeats))
    p.update(extra)
    print(f"  {problem:16s} {series:28s} {param_name}={param:<10.3g} error {p['error'] if p['error'] is None else format(p['error'], '.2e'):>9s}"
          f"  {seconds:.3e} s  x{repeats}", flush=True)
    return p


def cpu_model():
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        for line in out.splitlines():
            if line.startswith("Model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


class Results:
    """Collects points and writes `<RESULTS>/<tool>.json`."""

    def __init__(self, tool, versions):
        self.tool = tool
        self.meta = dict(tool=tool, versions=versions, python=sys.version.split()[0],
                         machine=f"{cpu_model()}, {os.cpu_count()} CPUs, {platform.platform()}",
                         date=datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
                         load_start=list(os.getloadavg()),
                         threads={k: os.environ.get(k) for k in
                                  ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS",
                                   "RAYON_NUM_THREADS")})
        self.points = []

    def add(self, p):
        self.points.append(p)

    def save(self, name=None):
        os.makedirs(RESULTS, exist_ok=True)
        self.meta["load_end"] = list(os.getloadavg())
        path = os.path.join(RESULTS, (name or self.tool) + ".json")
        with open(path, "w") as f:
            json.dump(dict(self.meta, points=self.points), f, indent=1)
        print(f"wrote {path} ({len(self.points)} points)")


def only(problem):
    """FRONTIER_ONLY=chain-6,pendulum restricts a script to some problems."""
    sel = os.environ.get("FRONTIER_ONLY")
    return not sel or problem in sel.split(",")


# ---------------------------------------------------------------- the end states

def _mp_end_states():
    """The closed-form problems' end states in extended precision (closed_form_reference_mp.py,
    committed as tests/data/closed_form_reference_mp.json): every error below is measured
    against these, not against the double-precision closed forms of this file (which agree
    with them to ~1e-15; check_reference.py records by how much)."""
    with open(os.path.join(REPO, "tests", "data", "closed_form_reference_mp.json")) as f:
        return {k: np.array(v["state"]) for k, v in json.load(f)["problems"].items()}


MP_END = _mp_end_states()

# ---------------------------------------------------------------- rigid body

RB_I = np.array([1.0, 2.0, 3.0])
RB_W0 = np.array([1.0, 0.0, 0.5])
RB_T = 20.0


def rigid_exact_omega(t, inertia=RB_I, w0=RB_W0):
    """ω_B(t) of the torque-free body with ω₂(0) = 0 (Landau & Lifshitz, Mechanics §37):
    for M² > 2E·I₂, ω₁ ∝ cn, ω₂ ∝ sn, ω₃ ∝ dn; for M² < 2E·I₂ the indices 1 and 3 trade
    places. Amplitudes from ω(0), rate and parameter from E and M."""
    i1, i2, i3 = inertia
    two_e = float(np.dot(inertia, w0 * w0))
    m2 = float(np.dot((inertia * w0) ** 2, np.ones(3)))
    if m2 > two_e * i2:
        a, b, c = 0, 1, 2              # L&L's ordering as written
    else:
        a, b, c = 2, 1, 0              # indices 1 ↔ 3
    ia, ib, ic = inertia[a], inertia[b], inertia[c]
    rate = np.sqrt((ic - ib) * (m2 - two_e * ia) / (ia * ib * ic))
    k2 = (ib - ia) * (two_e * ic - m2) / ((ic - ib) * (m2 - two_e * ia))
    sn, cn, dn, _ = ellipj(rate * t, k2)
    w = np.zeros(3)
    w[a] = np.sign(w0[a]) * np.sqrt((two_e * ic - m2) / (ia * (ic - ia))) * cn
    # ω₂ starts at 0 with I₂ω̇₂(0) = (I₃ − I₁) ω₃ ω₁ (Euler): its sign is the sign of sn
    wdot_b = (i3 - i1) * w0[2] * w0[0] / i2
    w[b] = np.sign(wdot_b) * np.sqrt((two_e * ic - m2) / (ib * (ic - ib))) * sn
    w[c] = np.sign(w0[c]) * np.sqrt((m2 - two_e * ia) / (ic * (ic - ia))) * dn
    return w


def rigid_rhs(t, y, inertia=RB_I):
    """y = (ω, q), q = (η, ε) scalar first: Euler's equations and q̇ = ½ q ⊗ (0, ω)."""
    w, q = y[:3], y[3:]
    i1, i2, i3 = inertia
    dw = np.array([(i2 - i3) * w[1] * w[2] / i1, (i3 - i1) * w[2] * w[0] / i2,
                   (i1 - i2) * w[0] * w[1] / i3])
    eta, e = q[0], q[1:]
    de = 0.5 * (eta * w + np.cross(e, w))
    return np.concatenate([dw, [-0.5 * np.dot(e, w)], de])


RB_Y0 = np.concatenate([RB_W0, [1.0, 0.0, 0.0, 0.0]])


def rigid_error(w):
    return float(np.max(np.abs(np.asarray(w) - MP_END["rigid-body"])))


# ---------------------------------------------------------------- Kepler

KEPLER_E = 0.9
KEPLER_T = 20.0


def kepler_exact(t, e=KEPLER_E):
    """(x, y, ẋ, ẏ) on the orbit a = 1, μ = 1 from periapsis: E − e sin E = t (Newton from
    E = π, which converges for every mean anomaly when e > 0.8), x = cos E − e,
    y = √(1 − e²) sin E, Ė = 1/(1 − e cos E)."""
    m = np.mod(t, 2 * np.pi)
    ea = np.pi if e > 0.8 else m + e * np.sin(m)
    for _ in range(60):
        d = (ea - e * np.sin(ea) - m) / (1 - e * np.cos(ea))
        ea -= d
        if abs(d) < 1e-16:
            break
    b = np.sqrt(1 - e * e)
    de = 1.0 / (1 - e * np.cos(ea))
    return np.array([np.cos(ea) - e, b * np.sin(ea), -np.sin(ea) * de, b * np.cos(ea) * de])


def kepler_rhs(t, y):
    r3 = (y[0] * y[0] + y[1] * y[1]) ** 1.5
    return np.array([y[2], y[3], -y[0] / r3, -y[1] / r3])


KEPLER_Y0 = kepler_exact(0.0)


def kepler_error(y):
    return float(np.max(np.abs(np.asarray(y) - MP_END["kepler-e0.9"])))


# ---------------------------------------------------------------- pendulum

PEND_THETA0 = 3.0
PEND_T = 10.0


def pendulum_exact(t, theta0=PEND_THETA0):
    """θ̈ = −sin θ from rest at θ₀: sin(θ/2) = k sn(K − t | k²), θ̇ = −2k cn(K − t | k²),
    k = sin(θ₀/2)."""
    k = np.sin(theta0 / 2)
    m = k * k
    sn, cn, _, _ = ellipj(ellipk(m) - t, m)
    return np.array([2 * np.arcsin(k * sn), -2 * k * cn])


def pendulum_rhs(t, y):
    return np.array([y[1], -np.sin(y[0])])


def pendulum_error(y):
    return float(np.max(np.abs(np.asarray(y) - MP_END["pendulum"])))


# ---------------------------------------------------------------- energy over 10⁴ periods

ENERGY_THETA0 = 1.0
ENERGY_PERIODS = 10_000
ENERGY_EVERY = 10          # periods between checkpoints
ENERGY_PERIOD = 4 * ellipk(np.sin(ENERGY_THETA0 / 2) ** 2)
ENERGY_T = ENERGY_PERIODS * ENERGY_PERIOD
ENERGY_E0 = 1 - np.cos(ENERGY_THETA0)


def energy_checkpoints():
    # the last checkpoint can round past ENERGY_T (solve_ivp refuses t_eval outside t_span)
    return np.minimum(ENERGY_PERIOD * ENERGY_EVERY * np.arange(ENERGY_PERIODS // ENERGY_EVERY + 1), ENERGY_T)


def energy_rel(theta, omega):
    """|E − E₀|/E₀ with E = θ̇²/2 + 1 − cos θ (array-friendly)."""
    return np.abs(0.5 * np.asarray(omega) ** 2 + 1 - np.cos(theta) - ENERGY_E0) / ENERGY_E0


# ---------------------------------------------------------------- the hinge chain

LINK = 0.3
RADIUS = 0.02
MASS = 1.0
GRAVITY = 9.81
CHAIN_T = 1.0
CHAIN_NS = (1, 2, 6, 12, 30)


def capsule_inertia(r=RADIUS, h=LINK, m=MASS):
    """Principal moments (about the centre, axis along z) of a solid capsule of mass m:
    a cylinder of length h and two hemispherical caps of radius r, uniform density (the
    parallel-axis shift of each cap is h²/4 + 3hr/8 from its own centre at 3r/8)."""
    vol = np.pi * r * r * h + 4 / 3 * np.pi * r ** 3
    mc = m * np.pi * r * r * h / vol
    ms = m - mc
    i_axial = mc * r * r / 2 + ms * 2 * r * r / 5
    i_perp = mc * (h * h / 12 + r * r / 4) + ms * (2 * r * r / 5 + h * h / 4 + 3 * h * r / 8)
    return i_perp, i_axial


def chain_q0(n):
    q = np.full(n, 0.1)
    q[0] = 0.7
    return q


def chain_y0(n):
    return np.concatenate([chain_q0(n), np.zeros(n)])


class ChainRhs:
    """The planar chain in numpy (Lagrange in absolute angles φ_i = q_1 + … + q_i):
    Σ_j [μ_ij cos(φ_i − φ_j) + I_c δ_ij] φ̈_j = −Σ_j μ_ij sin(φ_i − φ_j) φ̇_j² − g sin φ_i Σ_k m a_ki,
    μ_ij = Σ_k m a_ki a_kj with a_ki = l (i < k), c (i = k), 0 (i > k): the lever of link i in
    the centre of link k; c = l/2, I_c the capsule's moment about the hinge direction."""

    def __init__(self, n):
        self.n = n
        c = LINK / 2
        a = np.zeros((n, n))
        for k in range(n):
            a[k, :k] = LINK
            a[k, k] = c
        self.mu = MASS * a.T @ a
        self.grav = GRAVITY * MASS * a.sum(axis=0)
        self.ic = capsule_inertia()[0]

    def __call__(self, t, y):
        n = self.n
        q, v = y[:n], y[n:]
        phi, w = np.cumsum(q), np.cumsum(v)
        d = phi[:, None] - phi[None, :]
        mass = self.mu * np.cos(d) + self.ic * np.eye(n)
        rhs = -(self.mu * np.sin(d)) @ (w * w) - self.grav * np.sin(phi)
        phidd = np.linalg.solve(mass, rhs)
        return np.concatenate([v, np.diff(phidd, prepend=0.0)])


def chain_xml(n, gravity=GRAVITY, dt=0.001, integrator="Euler"):
    """bench_mujoco.py's chain (the same XML), with the gravity and integrator given."""
    body = ""
    for i in reversed(range(n)):
        pos = "0 0 0" if i == 0 else f"0 0 {-LINK}"
        body = (f'<body name="b{i}" pos="{pos}"><joint name="j{i}" type="hinge" axis="0 1 0" damping="0"/>'
                f'<geom type="capsule" fromto="0 0 0 0 0 {-LINK}" size="{RADIUS}" mass="{MASS}"/>{body}</body>')
    return (f'<mujoco><option timestep="{dt!r}" gravity="0 0 {-gravity!r}" integrator="{integrator}">'
            f'<flag contact="disable"/></option><worldbody>{body}</worldbody></mujoco>')


def load_reference():
    with open(os.path.join(RESULTS, "reference.json")) as f:
        return json.load(f)


def chain_error(y, ref_state):
    return float(np.max(np.abs(np.asarray(y) - np.asarray(ref_state))))


# The gravity that makes the one-link chain the unit pendulum θ̈ = −sin θ: ω₀² = m g c / I_o = 1.
def unit_pendulum_gravity():
    i_o = capsule_inertia()[0] + MASS * (LINK / 2) ** 2
    return i_o / (MASS * LINK / 2)
