"""The stiff sitting's bookkeeping (issue 34 item 4), used by scripts/peers/stiff.sh:

    stiff_report.py collect TOOL RAW.jsonl START END   # RAW's JSON lines -> <data>/TOOL.json
    stiff_report.py targets [--doc docs/accuracy.md]   # the targets and work tables (markdown)

`collect` wraps one tool's JSON lines with the sitting's metadata (machine, start and end time
and load average as "date; load" strings, versions). `targets` reads every <data>/*.json and,
for each problem and method, interpolates the time at a given end error on the log–log line of
the method's points (Pareto front: points sorted by time, each kept only if its error beats all
cheaper ones; between the two front points that bracket the error, log t linear in log err; a
method whose cheapest point is already below the error is charged that point's time, an upper
bound; one that never reaches it has no time there). Then:

* at every error 1e-6 ... 1e-10 reached, vectrix's faster stiff method (RADAU5 or BDF) against
  the fastest of scipy's Radau/BDF/LSODA and MuJoCo's integrators: target ratio >= 10;
* on Robertson and Van der Pol, vectrix's faster stiff method against diffsol's BDF: target
  time ratio vectrix / diffsol <= 1.5.

With --doc, the tables replace the text between the markers STIFF-TABLES:BEGIN/END of that file.
<data> is $STIFF_RESULTS or docs/accuracy/stiff-data.
"""
import glob
import json
import math
import os
import platform
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
DATA = os.environ.get("STIFF_RESULTS", os.path.join(REPO, "docs", "accuracy", "stiff-data"))
BEGIN, END = "<!-- STIFF-TABLES:BEGIN (scripts/peers/stiff_report.py) -->", "<!-- STIFF-TABLES:END -->"
ERRORS = [1e-6, 1e-7, 1e-8, 1e-9, 1e-10]
PROBLEMS = [("chain", "damped spring chain"), ("pendulum", "pendulum on a stiff spring"),
            ("damper", "hinge with a stiff damper"), ("robertson", "Robertson"), ("vdp", "Van der Pol μ = 1000")]
VECTRIX = ("vectrix RADAU5", "vectrix BDF")
PEERS = ("scipy Radau", "scipy BDF", "scipy LSODA", "MuJoCo implicitfast", "MuJoCo RK4")
DIFFSOL = ("diffsol bdf",)


def cpu_model():
    out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    return next((l.split(":", 1)[1].strip() for l in out.splitlines() if l.startswith("Model name")), platform.processor())


def collect(tool, raw, start, end):
    points = [json.loads(l) for l in open(raw) if l.startswith("{")]
    versions = {"python": platform.python_version()}
    for mod in ("numpy", "scipy", "mujoco"):
        try:
            versions[mod] = __import__(mod).__version__
        except ImportError:
            pass
    out = {"tool": tool, "machine": f"{cpu_model()}, {os.cpu_count()} CPUs", "start": start, "end": end,
           "versions": versions, "points": points}
    os.makedirs(DATA, exist_ok=True)
    with open(os.path.join(DATA, f"{tool}.json"), "w") as f:
        f.write(json.dumps(out, indent=0) + "\n")
    print(f"{tool}: {len(points)} points -> {DATA}/{tool}.json")


def load():
    pts, meta = [], []
    for path in sorted(glob.glob(os.path.join(DATA, "*.json"))):
        d = json.load(open(path))
        meta.append(d)
        pts += d["points"]
    return pts, meta


def finite(p):
    return p.get("err") is not None and math.isfinite(p["err"]) and p["err"] > 0


def time_at(pts, problem, tool, e):
    """Interpolated time of `tool` at end error `e` on its log–log Pareto front, or None."""
    own = sorted(((p["secs"], p["err"]) for p in pts if finite(p) and p["problem"] == problem and p["tool"] == tool))
    front = []
    for t, err in own:
        if not front or err < front[-1][1]:
            front.append((t, err))
    if not front or front[-1][1] > e:
        return None
    if front[0][1] <= e:
        return front[0][0]
    for (t0, e0), (t1, e1) in zip(front, front[1:]):
        if e1 <= e < e0:
            s = (math.log(e) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0)))
    return None


def fastest(pts, problem, tools, e):
    best = None
    for tool in tools:
        t = time_at(pts, problem, tool, e)
        if t is not None and (best is None or t < best[1]):
            best = (tool, t)
    return best


def fmt_t(t):
    return f"{t:.2e}"


def tables(pts, meta):
    lines = []
    starts = sorted(m["start"] for m in meta)
    ends = sorted(m["end"] for m in meta)
    lines.append(f"Sitting: {meta[0]['machine']}; first tool started {starts[0]}, last ended {ends[-1]} "
                 "(date; load average 1/5/15 min).")
    lines.append("")
    lines.append("**Target 1: ≥ 10× the fastest of scipy's stiff methods and MuJoCo, at every error ≤ 10⁻⁶** "
                 "(time of a run at that end error, interpolated on each method's log–log line):")
    lines.append("")
    lines.append("| problem | error | vectrix (faster stiff method) | fastest peer | peer / vectrix | met | "
                 "with DOP853 too |")
    lines.append("|---|---|---|---|---|---|---|")
    verdict1 = {}
    for pid, title in PROBLEMS:
        for e in ERRORS:
            v, p = fastest(pts, pid, VECTRIX, e), fastest(pts, pid, PEERS, e)
            if v is None and p is None:
                continue
            vs = f"{v[0].split()[1]} {fmt_t(v[1])} s" if v else "not reached"
            ps = f"{p[0]} {fmt_t(p[1])} s" if p else "none reaches it"
            if v and p:
                r = p[1] / v[1]
                ok = r >= 10
                rs = f"{r:.0f}×" if r >= 10 else f"{r:.2g}×"
            else:
                ok, rs = (v is not None), "—"
            verdict1.setdefault(pid, []).append(ok)
            # the same with vectrix's explicit DOP853 allowed: what the fastest vectrix method gives
            a = fastest(pts, pid, VECTRIX + ("vectrix DOP853",), e)
            if a and p and a[0] == "vectrix DOP853":
                anys = f"DOP853 {fmt_t(a[1])} s: {p[1] / a[1]:.2g}×"
            else:
                anys = "same"
            lines.append(f"| {title} | {e:.0e} | {vs} | {ps} | {rs} | {'met' if ok else '**not met**'} | {anys} |")
    lines.append("")
    lines.append("**Target 2: within 1.5× of diffsol's BDF on Robertson and Van der Pol** (time ratio vectrix / "
                 "diffsol ≤ 1.5 at every error ≤ 10⁻⁶ both reach):")
    lines.append("")
    lines.append("| problem | error | vectrix (faster stiff method) | diffsol BDF | vectrix / diffsol | met |")
    lines.append("|---|---|---|---|---|---|")
    for pid, title in PROBLEMS[3:]:
        for e in ERRORS:
            v, d = fastest(pts, pid, VECTRIX, e), fastest(pts, pid, DIFFSOL, e)
            if v is None and d is None:
                continue
            vs = f"{v[0].split()[1]} {fmt_t(v[1])} s" if v else "not reached"
            ds = f"{fmt_t(d[1])} s" if d else "not reached"
            if v and d:
                r = v[1] / d[1]
                verdict = "met" if r <= 1.5 else "**not met**"
                rs = f"{r:.2f}"
            else:
                verdict, rs = ("— (vectrix only)" if v else "**not met**"), "—"
            lines.append(f"| {title} | {e:.0e} | {vs} | {ds} | {rs} | {verdict} |")
    lines.append("")
    lines.append("**Work at rtol = 10⁻⁶ and 10⁻⁹** (MuJoCo: the largest dt that reaches each of the two "
                 "errors; f-evals are right-hand-side evaluations, none spent on Jacobians (every tool "
                 "has the exact one); LU: factorizations (RADAU5: pairs of a real and a complex one); "
                 "— where a tool does not report the count):")
    lines.append("")
    lines.append("| problem | method | rtol / dt | end error | steps | f-evals | LU | Newton its | time [s] |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    order = VECTRIX + ("vectrix DOP853",) + PEERS[:3] + ("diffsol bdf",)
    for pid, title in PROBLEMS:
        first = True
        for tool in order:
            for rtol in (1e-6, 1e-9):
                for p in pts:
                    if p["problem"] == pid and p["tool"] == tool and abs(p.get("rtol", 0) / rtol - 1) < 1e-6:
                        lines.append(row(title if first else "", p, f"{rtol:.0e}"))
                        first = False
        for tool in PEERS[3:]:
            own = sorted((p for p in pts if finite(p) and p["problem"] == pid and p["tool"] == tool),
                         key=lambda p: -p["dt"])
            hits = []
            for e in (1e-6, 1e-9):
                hit = next((p for p in own if p["err"] <= e), None)
                if hit and hit not in hits:
                    hits.append(hit)
                    lines.append(row(title if first else "", hit, f"dt {hit['dt']:.2e}"))
                    first = False
    return "\n".join(lines), verdict1


def row(title, p, param):
    g = lambda k: f"{p[k]}" if k in p else "—"
    if not finite(p):  # a failed run: say where it stopped instead of its counts
        return f"| {title} | {p['tool']} | {param} | failed: {p.get('note', 'no result')} | | | | | {p['secs']:.2e} |"
    return (f"| {title} | {p['tool']} | {param} | {p['err']:.1e} | {g('steps')} | {g('fevals')} | {g('lu')} | "
            f"{g('newton')} | {p['secs']:.2e} |")


def targets(doc):
    pts, meta = load()
    text, _ = tables(pts, meta)
    print(text)
    if doc:
        body = open(doc).read()
        a, b = body.find(BEGIN), body.find(END)
        if a < 0 or b < 0:
            sys.exit(f"{doc} has no {BEGIN} … {END} markers")
        open(doc, "w").write(body[:a] + BEGIN + "\n" + text + "\n" + body[b:])
        print(f"updated {doc}", file=sys.stderr)


if __name__ == "__main__":
    if sys.argv[1] == "collect":
        collect(*sys.argv[2:6])
    elif sys.argv[1] == "targets":
        targets(sys.argv[3] if len(sys.argv) > 3 and sys.argv[2] == "--doc" else None)
    else:
        sys.exit(__doc__)
