"""The compiled peers on the frontier (issue 39): no interpreter between a peer and its
integrator. Runs the binaries that cpp/build.sh builds (PEERS_BIN, default target/peers-cpp)
and measures their end states against the same references as every other tool
(frontier_common's closed forms and the chains' extended-precision reference.json):

* `odeint`: Boost.Odeint's controlled `runge_kutta_dopri5`, `runge_kutta_fehlberg78` and
  `bulirsch_stoer` at rtol = atol = 1e-3 … 1e-15 (vectrix's ladder), with Pinocchio's C++ ABA
  on the hinge chains, the 7-DOF arm and the floating quadruped (the models Pinocchio's URDF
  parser makes of examples/models/arm7.urdf and quadruped.urdf, dumped by
  scripts/pin_model_dump.py; end states in the common form of cpp/pin_dump.hpp), hand-written C++
  right-hand sides on the body, Kepler and the pendulum; the energy problem through Odeint's
  dense output (cpp/odeint_frontier.cpp).
* `mujoco-c`: MuJoCo's C API, `mj_step` in a C loop, RK4 and implicitfast at the step
  ladders of frontier_mujoco.py (cpp/mujoco_frontier.c).

Each binary times its own runs (median of repeated whole runs, examples/frontier/timing.rs's
rule); a process per point, so nothing of Python's is inside a timing. Writes odeint.json and
mujoco-c.json."""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

import frontier_common as fc
from frontier_mujoco import FREE_BODY

BIN = os.environ.get("PEERS_BIN", os.path.join(fc.REPO, "target", "peers-cpp"))
TOLS = [10.0 ** -k for k in range(3, 16)]
ODEINT_METHODS = (("dopri5", "DP5"), ("rkf78", "RKF78"), ("bs", "Bulirsch-Stoer"))
MJ_INTEGRATORS = (("rk4", "RK4"), ("implicitfast", "implicitfast"))


def call(*args):
    out = subprocess.run([os.path.join(BIN, args[0]), *map(str, args[1:])], capture_output=True,
                         text=True, check=True).stdout
    return json.loads(out)


def odeint_ladder(res, problem, error, extra=()):
    for method, name in ODEINT_METHODS:
        for tol in TOLS:
            r = call("odeint_frontier", problem, method, repr(tol), *extra)
            err = error(r["state"])
            err = err if np.isfinite(err) else float("inf")
            res.add(fc.point(problem, "odeint", "C++", name, "rtol", tol, err, r["seconds"], r["repeats"],
                             series=f"Odeint {name}", fevals=r["fevals"], steps=r["steps"]))
            if err < fc.FLOOR or r["seconds"] > fc.RUN_CAP:
                break


def mujoco_ladder(res, problem, xml, kind, t_end, error, kmin, kmax, theta0=None):
    with tempfile.NamedTemporaryFile("w", suffix=".xml", delete=False) as f:
        f.write(xml)
        path = f.name
    try:
        for integ, name in MJ_INTEGRATORS:
            for k in range(kmin, kmax + 1):
                n = int(np.ceil(t_end * 2.0 ** k))
                extra = () if theta0 is None else (repr(theta0),)
                r = call("mujoco_frontier", path, integ, n, repr(t_end), kind, *extra)
                err = error(r["state"])
                err = err if np.isfinite(err) else float("inf")
                res.add(fc.point(problem, "mujoco-c", "C API", name, "steps", n, err, r["seconds"], r["repeats"],
                                 series=f"MuJoCo C {name}", dt=t_end / n))
                if err < fc.FLOOR or r["seconds"] > fc.RUN_CAP:
                    break
    finally:
        os.unlink(path)


def check_chain_rhs(n):
    """Pinocchio's C++ ABA on the chain model of odeint_frontier.cpp gives the accelerations of
    frontier_common's numpy Lagrangian (the model is the one every tool integrates)."""
    y0 = fc.chain_y0(n)
    got = np.array(call("odeint_frontier", "rhs", f"chain-{n}")["state"])
    diff = float(np.max(np.abs(got - fc.ChainRhs(n)(0.0, y0))))
    assert diff < 1e-9, f"chain-{n}: C++ ABA and the numpy Lagrangian differ by {diff:e}"


def main():
    versions = {"compiler": subprocess.run(["g++", "--version"], capture_output=True, text=True).stdout.splitlines()[0]}
    import mujoco
    import pinocchio
    versions.update(pin=pinocchio.__version__, mujoco=mujoco.__version__)
    ref = fc.load_reference()

    res = fc.Results("odeint", dict(versions, peer="Boost.Odeint (pin's cmeel Boost) + Pinocchio C++ / Eigen"))
    if fc.only("rigid-body"):
        odeint_ladder(res, "rigid-body", lambda s: fc.rigid_error(s[:3]))
    if fc.only("kepler-e0.9"):
        assert np.max(np.abs(fc.KEPLER_Y0 - [0.1, 0.0, 0.0, np.sqrt(19.0)])) < 1e-15
        odeint_ladder(res, "kepler-e0.9", fc.kepler_error)
    if fc.only("pendulum"):
        odeint_ladder(res, "pendulum", fc.pendulum_error)
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if fc.only(problem):
            check_chain_rhs(n)
            odeint_ladder(res, problem, lambda s, st=ref[problem]["state"]: fc.chain_error(s, st))
    for tree in ("arm7", "quadruped"):
        if fc.only(tree) and tree not in ref:
            print(f"frontier_compiled: {tree} has no reference in reference.json (run the vectrix side first)",
                  file=sys.stderr)
        elif fc.only(tree):
            with tempfile.TemporaryDirectory() as d:
                dump = os.path.join(d, f"{tree}.pin.txt")
                subprocess.run([sys.executable, os.path.join(fc.REPO, "scripts", "pin_model_dump.py"),
                                os.path.join(fc.REPO, "examples", "models", f"{tree}.urdf"), dump], check=True)
                odeint_ladder(res, tree, lambda s, st=ref[tree]["state"]: fc.chain_error(s, st), extra=(dump,))
    if fc.only("energy-pendulum"):
        odeint_ladder(res, "energy-pendulum", lambda s: s[0], extra=(repr(float(fc.ENERGY_PERIOD)),))
    res.save()

    res = fc.Results("mujoco-c", dict(versions, peer="MuJoCo C API (libmujoco of the mujoco wheel)"))
    if fc.only("rigid-body"):
        mujoco_ladder(res, "rigid-body", FREE_BODY, "rigid", fc.RB_T, fc.rigid_error, 0, 22)
    if fc.only("pendulum"):
        mujoco_ladder(res, "pendulum", fc.chain_xml(1, gravity=fc.unit_pendulum_gravity()), "pendulum",
                      fc.PEND_T, fc.pendulum_error, 0, 24, theta0=fc.PEND_THETA0)
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if fc.only(problem):
            mujoco_ladder(res, problem, fc.chain_xml(n), "chain", fc.CHAIN_T,
                          lambda s, st=ref[problem]["state"]: fc.chain_error(s, st), 2, 26)
    res.save()


if __name__ == "__main__":
    main()
