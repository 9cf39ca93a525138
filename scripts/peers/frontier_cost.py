"""Where the time goes on the frontier (issue 39, item 3): for each problem and error level,
the cheapest run of each adaptive series that reaches the level (along the series' points in
order of time), with its right-hand-side evaluations, its wall time and the time per
evaluation (which includes the integrator's own work per evaluation). Reads the tool files of
FRONTIER_RESULTS (default docs/accuracy/peers-data) and prints a markdown table; only the
routes that count their evaluations (vectrix, Odeint, scipy-driven) appear.

    ~/.venv-peers/bin/python scripts/peers/frontier_cost.py [SERIES-SUBSTRING ...]
"""
import json
import os
import sys

import frontier_common as fc

LEVELS = (1e-6, 1e-9, 1e-12)
DEFAULT = ("vectrix DOP853", "vectrix scene DOP853", "Odeint RKF78", "Odeint Bulirsch-Stoer", "Odeint DP5")


def main():
    wanted = sys.argv[1:] or DEFAULT
    pts = []
    for name in sorted(os.listdir(fc.RESULTS)):
        if name.endswith(".json") and not name.startswith("reference"):
            with open(os.path.join(fc.RESULTS, name)) as f:
                pts += json.load(f).get("points", [])
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
