"""MuJoCo's `implicitfast` and RK4 integrators on the stiff damped chain of docs/accuracy.md
"Stiff problems" (issue 34): six unit masses on slide joints, neighbours and both walls joined
by springs k = 1e6 N/m with dashpots c = 1e4 N s/m (fixed tendons with `stiffness` and
`damping`), x(0) = X0, v(0) = 0, no gravity; the error is max |x_i(0.02) − x_i*| against the
chain's modal closed form (the same as `stiff_scipy.py` and crates/ode/tests/radau5.rs).

MuJoCo steps with a fixed time step: the script halves dt from 1e-3 until the error stops
improving or 10⁶ steps, and prints one JSON line per (integrator, dt): error, steps, median wall
time of `mj_step` over the whole interval (`mj_step(model, data, nstep)` from Python, one call).
`implicitfast` treats the tendon dashpots implicitly and the springs explicitly, so its
stability limit is set by √k (ω ≈ 2 000 rad/s), not by c. Timings are only meaningful in a quiet
sitting beside the vectrix and scipy rows; the errors and step counts hold anywhere.

Run: ~/.venv-peers/bin/python scripts/peers/stiff_mujoco.py
"""
import json

import mujoco
import numpy as np

from frontier_common import median_time
from stiff_scipy import N, X0, chain_exact

T_END = 0.02
K, C = 1e6, 1e4


def chain_xml():
    bodies = "\n".join(
        f'<body name="m{i}"><joint name="x{i}" type="slide" axis="1 0 0"/>'
        f'<geom type="sphere" size="0.01" mass="1" pos="{0.1 * i} 0 0" contype="0" conaffinity="0"/></body>'
        for i in range(N)
    )
    # springs: wall–x0, x_i–x_{i+1}, x_{N−1}–wall; a fixed tendon's length is Σ coef·q
    tendons = [f'<fixed name="w0" stiffness="{K}" damping="{C}" springlength="0"><joint joint="x0" coef="1"/></fixed>']
    for i in range(N - 1):
        tendons.append(
            f'<fixed name="s{i}" stiffness="{K}" damping="{C}" springlength="0">'
            f'<joint joint="x{i + 1}" coef="1"/><joint joint="x{i}" coef="-1"/></fixed>'
        )
    tendons.append(f'<fixed name="w1" stiffness="{K}" damping="{C}" springlength="0"><joint joint="x{N - 1}" coef="1"/></fixed>')
    return f"""<mujoco><option gravity="0 0 0" timestep="1e-3"/>
<worldbody>{bodies}</worldbody><tendon>{''.join(tendons)}</tendon></mujoco>"""


def run(integrator, dt):
    mujoco.set_mju_user_warning(lambda msg: None)  # divergence is read from d.warning instead
    m = mujoco.MjModel.from_xml_string(chain_xml())
    m.opt.integrator = integrator
    m.opt.timestep = dt
    d = mujoco.MjData(m)
    steps = int(round(T_END / dt))

    def go():
        mujoco.mj_resetData(m, d)
        d.qpos[:] = X0
        d.qvel[:] = 0.0
        mujoco.mj_step(m, d, nstep=steps)
        # MuJoCo resets a diverging simulation to its initial pose and warns: that is a failure
        diverged = d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0
        return None if diverged else d.qpos.copy()

    secs, _, x = median_time(go, budget=1.0, max_repeats=5)
    if x is None:
        return float("inf"), steps, secs
    err = float(np.max(np.abs(x - chain_exact(T_END))))
    return err if np.isfinite(err) else float("inf"), steps, secs


def main():
    exact = chain_exact(T_END)
    assert np.all(np.isfinite(exact))
    for name, integ in (("implicitfast", mujoco.mjtIntegrator.mjINT_IMPLICITFAST), ("RK4", mujoco.mjtIntegrator.mjINT_RK4)):
        dt, best = 1e-3, float("inf")
        while True:
            err, steps, secs = run(integ, dt)
            print(json.dumps({"problem": "chain", "tool": f"MuJoCo {name}", "dt": dt, "err": err, "steps": steps,
                              "secs": secs}), flush=True)
            # until 10⁶ steps, or until halving dt stops paying (round-off)
            if steps >= 1_000_000 or (np.isfinite(best) and err > 0.7 * best):
                break
            best = min(best, err)
            dt /= 2


if __name__ == "__main__":
    main()
