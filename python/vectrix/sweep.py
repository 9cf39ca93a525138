"""Parameter sweeps of a scene: local threads (the GIL released during each run) or Dask tasks
on a `dask.distributed.Client`. Book: — (parameter studies of the scenes of §7.11)."""
from __future__ import annotations

import itertools
import os
from concurrent.futures import ThreadPoolExecutor

MAX_SWEEP_RUNS = 10_000


def _combos(params):
    if not isinstance(params, dict) or not params:
        raise ValueError("params: valid: a non-empty dict {dotted path: list of values}")
    keys = list(params)
    vals = []
    for k in keys:
        v = params[k]
        v = [v] if isinstance(v, (str, int, float)) else list(v)
        if not v:
            raise ValueError(f"params[{k!r}]: no values; valid: at least one")
        vals.append(v)
    total = 1
    for v in vals:
        total *= len(v)
    if total > MAX_SWEEP_RUNS:
        raise ValueError(f"the sweep asks for {total} runs; valid: at most {MAX_SWEEP_RUNS}")
    return keys, [dict(zip(keys, c)) for c in itertools.product(*vals)]


def _as_py(v):
    try:
        return v.item()
    except AttributeError:
        return v


def _run_one(text, file, label, cancel=None):
    from . import Scene

    s = Scene.from_toml(text, file)
    r = s.run({k: _as_py(v) for k, v in label.items()}, cancel=cancel)
    return {"t": r.t, "columns": r.columns, "units": r.units, "summary": r.summary}


class SweepResult:
    """`table`: one row per run (parameters, complete, rows, work, drift) as a list of dicts
    or `.frame()`; `runs`: each run's outputs (t, columns, units, summary); `interrupted`."""

    def __init__(self, keys, labels, runs, interrupted=False):
        self.params = keys
        self.labels = labels
        self.runs = runs
        self.interrupted = interrupted
        self.table = []
        for i, (lab, r) in enumerate(zip(labels, runs)):
            if r is None:
                continue
            s = r["summary"]
            row = {"run": i, **{k: _as_py(v) for k, v in lab.items()}, "complete": s["complete"], "rows": len(r["t"])}
            row.update({k: s["work"][k] for k in ("fevals", "accepted", "rejected", "wall_seconds")})
            for d in s.get("drift", []):
                name = d["invariant"] if isinstance(d["invariant"], str) else next(iter(d["invariant"]))
                row[f"{name}_max_rel_drift"] = d["max_rel"]
            self.table.append(row)

    def frame(self):
        import pandas as pd

        return pd.DataFrame(self.table).set_index("run")


def sweep(scene, params, client=None, max_workers=None):
    """Runs `scene` for the Cartesian product of `params` ({dotted path: values}, values
    numbers or quantity strings). Without `client`: on local threads (one per core; each run
    releases the GIL). With a `dask.distributed.Client`: one Dask task per run on its cluster.
    Every combination is validated before any run starts. Ctrl-C stops the local runs after
    their current step and returns what was computed (`result.interrupted`)."""
    from . import Cancel, Scene

    if not isinstance(scene, Scene):
        raise TypeError(f"scene: a {type(scene).__name__}; valid: vectrix.Scene")
    keys, labels = _combos(params)
    for lab in labels:
        scene.check({k: _as_py(v) for k, v in lab.items()})
    text, file = scene.text, scene._s.file
    if client is not None:
        futures = client.map(_run_one, [text] * len(labels), [file] * len(labels), labels, pure=False)
        return SweepResult(keys, labels, client.gather(futures))
    cancel = Cancel()
    workers = max_workers or os.cpu_count() or 1
    runs = [None] * len(labels)
    interrupted = False
    with ThreadPoolExecutor(max_workers=workers) as ex:
        futs = [ex.submit(_run_one, text, file, lab, cancel) for lab in labels]
        try:
            for i, f in enumerate(futs):
                runs[i] = f.result()
        except KeyboardInterrupt:
            interrupted = True
            cancel.set()
            for f in futs:
                f.cancel()
            for i, f in enumerate(futs):
                if not f.cancelled():
                    try:
                        runs[i] = f.result()
                    except Exception:  # noqa: BLE001 - a failed run leaves None
                        runs[i] = None
    return SweepResult(keys, labels, runs, interrupted)
