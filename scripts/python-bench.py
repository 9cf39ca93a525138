#!/usr/bin/env python3
"""Speed of vectrix from Python beside the Python peers, measured back to back in one sitting
(issue 37 item 5; docs/performance.md "From Python"). Needs a venv with vectrix installed
(`pip install ./python`) plus scipy, control and pin (Pinocchio):

    python scripts/python-bench.py            # prints a Markdown table

Each figure is the best of 5 repetitions (wall time, time.perf_counter); ratios compare the
two routes timed back to back. vectrix uses every core for batches (set VECTRIX_NUM_THREADS=1
for one thread); scipy's Rotation and Pinocchio run on one. The "memory floor" rows time numpy
itself allocating and filling an array of the result's size: no conversion returning a fresh
array of that size can be faster. A scene run is timed from Python (Scene.run) and from Rust
(the work.wall_seconds the run itself measures, which excludes the Python call).
"""
import json
import os
import time
from pathlib import Path

import numpy as np

import vectrix

ROOT = Path(__file__).resolve().parents[1]


def best(f, reps=5):
    ts = []
    for _ in range(reps):
        t0 = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t0)
    return min(ts)


def row(what, ours, theirs, peer):
    print(f"| {what} | {ours * 1e3:.3f} ms | {theirs * 1e3:.3f} ms ({peer}) | {theirs / ours:.1f}× |")


def rotations():
    from scipy.spatial.transform import Rotation as SR

    q = np.random.default_rng(1).standard_normal((1_000_000, 4))
    v = np.random.default_rng(2).standard_normal((1_000_000, 3))
    r, s = vectrix.Rotation.from_quat(q), SR.from_quat(q)
    row("Rotation.from_quat, 10⁶", best(lambda: vectrix.Rotation.from_quat(q)), best(lambda: SR.from_quat(q)), "scipy")
    row("as_matrix, 10⁶", best(r.as_matrix), best(s.as_matrix), "scipy")
    row("as_rotvec, 10⁶", best(r.as_rotvec), best(s.as_rotvec), "scipy")
    row("as_euler('ZYX'), 10⁶", best(lambda: r.as_euler("ZYX")), best(lambda: s.as_euler("ZYX")), "scipy")
    m = s.as_matrix()
    row("from_matrix, 10⁶", best(lambda: vectrix.Rotation.from_matrix(m)), best(lambda: SR.from_matrix(m)), "scipy")
    row("apply, 10⁶", best(lambda: r.apply(v)), best(lambda: s.apply(v)), "scipy")
    for shape, what in (((1_000_000, 3, 3), "as_matrix"), ((1_000_000, 4), "as_quat/from_quat")):
        t = best(lambda: np.empty(shape).fill(1.0))
        print(f"| memory floor of {what}: numpy.empty{shape}.fill | {t * 1e3:.3f} ms | | |")


def multibody():
    import pinocchio as pin

    data = json.loads((ROOT / "tests/data/multibody_reference.json").read_text())
    links = data["models"]["chain6"]["links"]
    m = vectrix.Model.from_links(links, gravity=data["gravity"])
    pm = pin.Model()
    parent = 0
    for link in links:  # the 6-link chain of the reference: pins about the given axes
        jid = pm.addJoint(parent, pin.JointModelRevoluteUnaligned(np.array(link["axis"])),
                          pin.SE3(np.array(link["orientation"]).T, np.array(link["offset"])), "j")
        pm.appendBodyToJoint(jid, pin.Inertia(link["mass"], np.array(link["com"]), np.array(link["inertia"])), pin.SE3.Identity())
        parent = jid
    pm.gravity.linear = np.array(data["gravity"])
    pd = pm.createData()
    rng = np.random.default_rng(3)
    n = 10_000
    q, v, tau = (rng.uniform(-1, 1, (n, 6)) for _ in range(3))
    ref = np.array([pin.aba(pm, pd, q[k], v[k], tau[k]) for k in range(10)])
    assert np.max(np.abs(m.aba(q[:10], v[:10], tau[:10]) - ref)) < 1e-9 * max(1, np.max(np.abs(ref)))
    row("Model.aba batched, 10⁴ states (6-link chain)", best(lambda: m.aba(q, v, tau)),
        best(lambda: [pin.aba(pm, pd, q[k], v[k], tau[k]) for k in range(n)]), "Python loop over pin.aba")
    one = (q[0], v[0], tau[0])
    reps = 10_000
    ours = best(lambda: [m.aba(*one) for _ in range(reps)]) / reps
    theirs = best(lambda: [pin.aba(pm, pd, *one) for _ in range(reps)]) / reps
    row("Model.aba single call (per call)", ours, theirs, "pin.aba single call")


def lti():
    import control

    num, den = [4.0, 2.0], [1.0, 3.0, 3.0, 1.0, 0.0]
    g, c = vectrix.tf(num, den), control.tf(num, den)
    row("margins, 4th-order loop", best(lambda: [vectrix.margins(g) for _ in range(100)]) / 100,
        best(lambda: [control.stability_margins(c) for _ in range(100)]) / 100, "control.stability_margins")


def scene():
    s = vectrix.Scene.from_file(ROOT / "examples/scenes/double_pendulum.toml")
    rust_times = []

    def go():
        rust_times.append(s.run().summary["work"]["wall_seconds"])

    py = best(go, reps=20)
    rust = min(rust_times)
    print(f"| Scene.run double_pendulum | {py * 1e3:.3f} ms from Python | {rust * 1e3:.3f} ms measured by the run in Rust | {py / rust:.3f}× (Python / Rust) |")


if __name__ == "__main__":
    print(f"load average before: {os.getloadavg()}; VECTRIX_NUM_THREADS={os.environ.get('VECTRIX_NUM_THREADS', 'unset')}")
    print("| what | vectrix | peer | speed-up |\n|---|---|---|---|")
    rotations()
    multibody()
    lti()
    scene()
    print(f"load average after: {os.getloadavg()}")
