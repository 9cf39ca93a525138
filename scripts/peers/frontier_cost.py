"""Where the time goes on the frontier (issue 39, item 3): for each problem and error level,
the cheapest run of each adaptive series that reaches the level (along the series' points in
order of time), with its right-hand-side evaluations, its wall time and the time per
evaluation (which includes the integrator's own work per evaluation). Reads the tool files of
FRONTIER_RESULTS (default docs/accuracy/peers-data) and prints a markdown table; only the
routes that count their evaluations (vectrix, Odeint, scipy-driven) appear.

    ~/.venv-peers/bin/python scripts/peers/frontier_cost.py [SERIES ...]
    ~/.venv-peers/bin/python scripts/peers/frontier_cost.py --targets

`--targets` prints instead the ratios of issue 39's targets at 1e-6, 1e-9 and 1e-12: vectrix's
library and scene routes against the fastest Odeint route and against MuJoCo's C API, with the
time to reach a level read as the table does (examples/frontier/report.rs `time_to_reach`: the
series' Pareto front, log–log interpolation).
"""
import math
import json
import os
import sys

import frontier_common as fc

LEVELS = (1e-6, 1e-9, 1e-12)
DEFAULT = ("vectrix DOP853", "vectrix Vern9", "vectrix GBS", "vectrix Taylor", "vectrix scene DOP853", "vectrix scene Vern9", "vectrix scene GBS", "Odeint RKF78", "Odeint Bulirsch-Stoer", "Odeint DP5")


def load_points():
    pts = []
    for name in sorted(os.listdir(fc.RESULTS)):
        if name.endswith(".json") and not name.startswith("reference"):
            with open(os.path.join(fc.RESULTS, name)) as f:
                pts += json.load(f).get("points", [])
    return pts


def time_to_reach(line, target):
    """report.rs's time_to_reach: (error, seconds) points → time at `target` or None."""
    front = []
    for e, t in sorted(((e, t) for e, t in line if e and e > 0 and t > 0), key=lambda p: (p[1], p[0])):
        if not front or e < front[-1][0]:
            front.append((e, t))
    k = next((i for i, (e, _) in enumerate(front) if e <= target), None)
    if k is None:
        return None
    if k == 0:
        return front[0][1]
    (e0, t0), (e1, t1) = front[k - 1], front[k]
    s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
    return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0)))


def family_time(pts, problem, pred):
    best = None
    for series in {p["series"] for p in pts if p["problem"] == problem and pred(p)}:
        line = [(p["error"], p["seconds"] + p.get("setup_seconds", 0.0)) for p in pts
                if p["problem"] == problem and p["series"] == series]
        t = time_to_reach(line, LEVEL_T)
        if t is not None and (best is None or t < best[0]):
            best = (t, series)
    return best


LEVEL_T = None


def targets(pts):
    global LEVEL_T
    routes = (("library", lambda p: p["tool"] == "vectrix" and p["route"] != "scene"),
              ("scene", lambda p: p["tool"] == "vectrix" and p["route"] == "scene"))
    peers = (("Odeint", lambda p: p["tool"] == "odeint"), ("MuJoCo C", lambda p: p["tool"] == "mujoco-c"))
    print("| problem | level | " + " | ".join(f"{r} / {q}" for q, _ in peers for r, _ in routes) + " |")
    print("|---|---|" + "---|" * (len(routes) * len(peers)))
    problems = []
    for p in pts:
        if p["problem"] not in problems:
            problems.append(p["problem"])
    for problem in problems:
        for level in LEVELS:
            LEVEL_T = level
            cells = []
            for _, qp in peers:
                q = family_time(pts, problem, qp)
                for _, rp in routes:
                    r = family_time(pts, problem, rp)
                    cells.append(f"{q[0] / r[0]:.2f}× ({q[1].split(' ', 1)[1]})" if q and r else "–")
            print(f"| {problem} | {level:.0e} | " + " | ".join(cells) + " |")


def main():
    if sys.argv[1:] == ["--targets"]:
        targets(load_points())
        return
    wanted = sys.argv[1:] or DEFAULT
    pts = load_points()
    problems = []
    for p in pts:
        if p["problem"] not in problems:
            problems.append(p["problem"])
    print("| problem | series | level | rtol | error | f-evals | time | time / f-eval |")
    print("|---|---|---|---|---|---|---|---|")
    for problem in problems:
        for series in wanted:
            line = sorted((p for p in pts if p["problem"] == problem and p["series"] == series
                           and p.get("fevals") and p["error"] is not None), key=lambda p: p["seconds"])
            for level in LEVELS:
                hit = next((p for p in line if p["error"] <= level), None)
                if hit is None:
                    continue
                per = hit["seconds"] / hit["fevals"]
                print(f"| {problem} | {series} | {level:.0e} | {hit['param']:.0e} | {hit['error']:.1e} | "
                      f"{hit['fevals']} | {hit['seconds'] * 1e6:.0f} µs | {per * 1e9:.0f} ns |")


if __name__ == "__main__":
    main()
