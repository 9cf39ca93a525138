"""Extended-precision reference end states of the frontier's hinge chains (chain-1, chain-2,
chain-6, chain-12, chain-30): written to tests/data/chain_reference_mp.json, read by the
frontier (examples/frontier/main.rs writes them into reference.json) and by
tests/ch07_chain_reference.rs.

Independent of vectrix: no code and no formula shared with its ABA. The equations are those
of `frontier_common.ChainRhs` (Lagrange in absolute angles φ_i = q_1 + … + q_i, a dense
mass matrix and a dense solve), re-implemented here in mpmath at `DPS` decimal digits:

    Σ_j [μ_ij cos(φ_i − φ_j) + I_c δ_ij] φ̈_j = −Σ_j μ_ij sin(φ_i − φ_j) φ̇_j² − g sin φ_i Σ_k m a_ki,
    μ_ij = Σ_k m a_ki a_kj,  a_ki = l (i < k), l/2 (i = k), 0 (i > k),

I_c the capsule's moment about the hinge direction (`frontier_common.capsule_inertia`, here
evaluated in mpmath, π included). q̇ = v and v̇_i = φ̈_i − φ̈_{i−1} (v relative rates).

The model's inputs are the *doubles* every tool uses, not the decimal literals: the link
length is mpf(0.3) = the binary value of the double 0.3 (0.299999999999999988898…), likewise
the radius 0.02, the mass 1, g = 9.81 and the initial state q(0) = (0.7, 0.1, …, 0.1),
v(0) = 0. The reference is thus the exact solution (to ~1e-20) of the very problem the f64
tools are given; what remains between them and it is their own error (integration and
round-off, including the f64 rounding of derived constants such as I_c, ~1e-17 relative).

Method: Gragg–Bulirsch–Stoer extrapolation with a fixed macro step: in each macro step the
modified midpoint rule (Euler start, no smoothing) with n = 2, 4, 6, …, 2K substeps, then
Aitken–Neville polynomial extrapolation in h² to the K-th column (order 2K); K = 12. Two
runs: STEPS = 64 macro steps (H = 1/64) and 2·STEPS = 128 (H/2); the max-norm difference of
their end states must be below TOL = 1e-20 for every chain, and the H/2 result is the one
stored (its error is smaller still, by ~2^-24 asymptotically). For the one link (a physical
pendulum) the end state is also compared with the exact solution on mpmath's Jacobi elliptic
functions. Cost: 27 840 f-evals per chain; with mpmath's pure-Python backend ~2 s (one link)
to ~9 min (30 links, a 30×30 Cholesky solve per f-eval), ~11 min in all.

Run (single process; niced, it competes with timing runs otherwise):

    nice -n 19 ~/.venv-peers/bin/python scripts/peers/chain_reference_mp.py [--only 1,2,6]

Prints the differences to docs/accuracy/peers-data/reference.json (the earlier DOP853 1e-13
reference) and to scipy's DOP853 at rtol = atol = 1e-13 on `frontier_common.ChainRhs`.
"""
import argparse
import json
import os
import sys
import time

import mpmath
from mpmath import mp, mpf

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
OUT = os.path.join(REPO, "tests", "data", "chain_reference_mp.json")
sys.path.insert(0, HERE)
import frontier_common as fc  # noqa: E402  (the model constants, as the doubles every tool uses)

DPS = 34
K = 12          # extrapolation columns: substeps 2, 4, …, 2K, order 2K
STEPS = 64      # macro steps over [0, CHAIN_T] of the check run; the stored run uses 2·STEPS
TOL = mpf("1e-20")

mp.dps = DPS


def capsule_inertia_mp(r, h, m):
    """frontier_common.capsule_inertia in mpmath (same formula, exact π)."""
    pi = mp.pi
    vol = pi * r * r * h + mpf(4) / 3 * pi * r ** 3
    mc = m * pi * r * r * h / vol
    ms = m - mc
    i_axial = mc * r * r / 2 + ms * 2 * r * r / 5
    i_perp = mc * (h * h / 12 + r * r / 4) + ms * (2 * r * r / 5 + h * h / 4 + 3 * h * r / 8)
    return i_perp, i_axial


class ChainMp:
    """frontier_common.ChainRhs in mpmath. The state is a list of 2n mpf (q, v)."""

    def __init__(self, n):
        self.n = n
        l, m, g = mpf(fc.LINK), mpf(fc.MASS), mpf(fc.GRAVITY)   # the doubles' exact values
        c = l / 2
        a = [[l if i < k else (c if i == k else mpf(0)) for i in range(n)] for k in range(n)]
        self.mu = [[m * mp.fsum(a[k][i] * a[k][j] for k in range(n)) for j in range(n)]
                   for i in range(n)]
        self.grav = [g * m * mp.fsum(a[k][i] for k in range(n)) for i in range(n)]
        self.ic = capsule_inertia_mp(mpf(fc.RADIUS), l, m)[0]
        self.fevals = 0

    def __call__(self, y):
        self.fevals += 1
        n = self.n
        q, v = y[:n], y[n:]
        phi, w = [], []
        sp, sw = mpf(0), mpf(0)
        for i in range(n):
            sp += q[i]
            sw += v[i]
            phi.append(sp)
            w.append(sw)
        s = [mp.sin(x) for x in phi]
        co = [mp.cos(x) for x in phi]
        w2 = [x * x for x in w]
        mu = self.mu
        # cos(φ_i − φ_j) = c_i c_j + s_i s_j, sin(φ_i − φ_j) = s_i c_j − c_i s_j (exact identities;
        # at 34 digits their round-off is ~1e-34 absolute)
        mass = [[None] * n for _ in range(n)]
        rhs = [None] * n
        for i in range(n):
            mi = mu[i]
            acc_c, acc_s = mpf(0), mpf(0)
            for j in range(n):
                acc_c += mi[j] * co[j] * w2[j]
                acc_s += mi[j] * s[j] * w2[j]
            # −Σ_j μ_ij (s_i c_j − c_i s_j) w_j² − g_i s_i
            rhs[i] = -s[i] * acc_c + co[i] * acc_s - self.grav[i] * s[i]
            for j in range(i + 1):
                mij = mi[j] * (co[i] * co[j] + s[i] * s[j])
                if i == j:
                    mij += self.ic
                mass[i][j] = mij
                mass[j][i] = mij
        phidd = cholesky_solve(mass, rhs)
        return list(v) + [phidd[0]] + [phidd[i] - phidd[i - 1] for i in range(1, n)]


def cholesky_solve(a, b):
    """Solves a x = b, a symmetric positive definite (the mass matrix), by Cholesky."""
    n = len(b)
    low = [[mpf(0)] * n for _ in range(n)]
    for j in range(n):
        lj = low[j]
        d = a[j][j] - mp.fsum(x * x for x in lj[:j])
        lj[j] = mp.sqrt(d)
        inv = 1 / lj[j]
        for i in range(j + 1, n):
            li = low[i]
            li[j] = (a[i][j] - mp.fsum(li[k] * lj[k] for k in range(j))) * inv
    z = [None] * n
    for i in range(n):
        z[i] = (b[i] - mp.fsum(low[i][k] * z[k] for k in range(i))) / low[i][i]
    x = [None] * n
    for i in reversed(range(n)):
        x[i] = (z[i] - mp.fsum(low[k][i] * x[k] for k in range(i + 1, n))) / low[i][i]
    return x


def axpy(a, x, y):
    """y + a·x, element-wise on lists."""
    return [yi + a * xi for xi, yi in zip(x, y)]


def gbs_step(f, y, h_macro, k):
    """One Gragg–Bulirsch–Stoer macro step: modified midpoint with n_j = 2j substeps,
    j = 1..k, extrapolated (Aitken–Neville in h²) to order 2k."""
    f0 = f(y)
    seq = [2 * j for j in range(1, k + 1)]
    table = []
    for j, nj in enumerate(seq):
        h = h_macro / nj
        z_prev, z = y, axpy(h, f0, y)
        for _ in range(1, nj):
            z_prev, z = z, axpy(2 * h, f(z), z_prev)
        row = [z]
        for col in range(1, j + 1):
            ratio = (mpf(nj) / seq[j - col]) ** 2 - 1
            up, lo = row[col - 1], table[j - 1][col - 1]
            row.append([u + (u - d) / ratio for u, d in zip(up, lo)])
        table.append(row)
    return table[-1][-1]


def integrate(n, steps, k):
    f = ChainMp(n)
    y = [mpf(x) for x in fc.chain_y0(n)]          # the doubles' exact values
    h = mpf(fc.CHAIN_T) / steps
    for _ in range(steps):
        y = gbs_step(f, y, h, k)
    return y, f.fevals


def pendulum_exact_mp():
    """The one link is a physical pendulum, θ̈ = −ω₀² sin θ, ω₀² = m g c / (I_c + m c²), from
    rest at θ₀: θ(t) = 2 asin(k sn(K − ω₀t | k²)), θ̇ = −2kω₀ cn(K − ω₀t | k²), k = sin(θ₀/2)."""
    l, m, g = mpf(fc.LINK), mpf(fc.MASS), mpf(fc.GRAVITY)
    c = l / 2
    ic = capsule_inertia_mp(mpf(fc.RADIUS), l, m)[0]
    w0 = mp.sqrt(m * g * c / (ic + m * c * c))
    kk = mp.sin(mpf(fc.chain_q0(1)[0]) / 2)
    par = kk * kk
    u = mp.ellipk(par) - w0 * mpf(fc.CHAIN_T)
    sn = mpmath.ellipfun("sn", u, m=par)
    cn = mpmath.ellipfun("cn", u, m=par)
    return [2 * mp.asin(kk * sn), -2 * kk * w0 * cn]


def maxdiff(a, b):
    return max(abs(mpf(x) - mpf(y)) for x, y in zip(a, b))


def comparisons(n, state):
    """Max-norm differences to the earlier reference.json and to scipy DOP853 1e-13."""
    import numpy as np
    from scipy.integrate import solve_ivp
    out = {}
    try:
        old = fc.load_reference()[f"chain-{n}"]
        out[f"reference.json ({old.get('method', '?')})"] = float(maxdiff(old["state"], state))
    except (OSError, KeyError):
        pass
    sol = solve_ivp(fc.ChainRhs(n), (0.0, fc.CHAIN_T), fc.chain_y0(n), method="DOP853",
                    rtol=1e-13, atol=1e-13)
    out["scipy DOP853 1e-13, numpy Lagrangian"] = float(maxdiff(np.asarray(sol.y[:, -1]), state))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", help="comma-separated chain lengths (default: all)")
    ap.add_argument("--steps", type=int, default=STEPS)
    ap.add_argument("-k", type=int, default=K)
    ap.add_argument("--no-write", action="store_true")
    args = ap.parse_args()
    ns = [int(x) for x in args.only.split(",")] if args.only else list(fc.CHAIN_NS)
    doc = {}
    if os.path.exists(OUT):
        with open(OUT) as fh:
            doc = json.load(fh)
    chains = doc.get("chains", {})
    failed = []
    for n in ns:
        t0 = time.perf_counter()
        y1, fe1 = integrate(n, args.steps, args.k)
        y2, fe2 = integrate(n, 2 * args.steps, args.k)
        seconds = time.perf_counter() - t0
        conv = maxdiff(y1, y2)
        row = {
            "n": n,
            "q0": [float(x) for x in fc.chain_q0(n)],
            "v0": [0.0] * n,
            "t_end": fc.CHAIN_T,
            "state": [float(x) for x in y2],
            "state_mp": [mpmath.nstr(x, 30, min_fixed=1, max_fixed=0) for x in y2],
            "convergence": float(conv),
            "convergence_note": f"max |y(H) - y(H/2)|, H = {fc.CHAIN_T}/{args.steps}",
            "columns": args.k,
            "macro_steps": 2 * args.steps,
            "fevals": fe1 + fe2,
            "seconds": round(seconds, 1),
        }
        if n == 1:
            ex = pendulum_exact_mp()
            row["exact_mp"] = [mpmath.nstr(x, 30, min_fixed=1, max_fixed=0) for x in ex]
            row["diff_to_exact"] = float(maxdiff(ex, y2))
        row["comparisons"] = comparisons(n, y2)
        print(f"chain-{n}: {seconds:.1f} s, {fe1 + fe2} f-evals, convergence {float(conv):.2e}"
              + (f", to exact {row['diff_to_exact']:.2e}" if n == 1 else "")
              + "".join(f"; {k}: {v:.2e}" for k, v in row["comparisons"].items()), flush=True)
        if conv >= TOL:
            failed.append(f"chain-{n}")
        chains[f"chain-{n}"] = row
    if failed:
        sys.exit(f"not converged to {float(TOL):.0e}: {', '.join(failed)} (nothing written)")
    if args.no_write:
        return
    l, m = mpf(fc.LINK), mpf(fc.MASS)
    doc = {
        "description": "Extended-precision end states of the frontier's hinge chains at t = t_end "
                       "(scripts/peers/chain_reference_mp.py): state = (q, v), the nearest doubles "
                       "of state_mp",
        "method": f"Gragg-Bulirsch-Stoer: modified midpoint, substeps 2, 4, ..., {2 * args.k}, "
                  f"Aitken-Neville extrapolation in h^2 (order {2 * args.k}), fixed macro step "
                  f"H = {fc.CHAIN_T}/{2 * args.steps}; checked against H = {fc.CHAIN_T}/{args.steps}",
        "equations": "frontier_common.ChainRhs (Lagrange in absolute angles, dense Cholesky solve)",
        "parameters": {"dps": DPS, "columns": args.k, "macro_steps": 2 * args.steps,
                       "check_macro_steps": args.steps, "tolerance": float(TOL)},
        "mpmath": mpmath.__version__,
        "mpmath_backend": mpmath.libmp.BACKEND,
        "model": {
            "link": fc.LINK, "radius": fc.RADIUS, "mass": fc.MASS, "gravity": fc.GRAVITY,
            "constants": "the doubles' exact binary values (mpf(0.3), not mpf('0.3'))",
            "inertia_perp_mp": mpmath.nstr(capsule_inertia_mp(mpf(fc.RADIUS), l, m)[0], 30),
            "hinge": "about y, links along -z, gravity -z",
        },
        "chains": dict(sorted(chains.items(), key=lambda kv: int(kv[0].split("-")[1]))),
    }
    with open(OUT, "w") as fh:
        json.dump(doc, fh, indent=1)
        fh.write("\n")
    print("wrote", OUT)


if __name__ == "__main__":
    main()
