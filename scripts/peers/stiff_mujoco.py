"""MuJoCo's `implicitfast` and RK4 integrators on the three mechanisms among the stiff problems
of docs/accuracy.md "Stiff problems" (issue 34), with the definitions and error measures of
stiff_scipy.py (and crates/ode/examples/stiff_work/problems.rs):

* `chain`: six unit masses on slide joints, neighbours and both walls joined by springs
  k = 1e6 N/m with dashpots c = 1e5 N s/m (fixed tendons with `stiffness` and `damping`), no
  gravity; error max |x(0.2) - x*| / max |x(0)| against the modal closed form.
* `pendulum`: a unit point mass on two slide joints (x and z), hung from the origin by a spatial
  tendon with `stiffness` k = 9.81e4 N/m and `springlength` l0 = 1 m, gravity 9.81; error
  max |r(2) - r*| / l0 against scipy Radau at 1e-13.
* `damper`: a rotor (I = 1e-2 kg m^2) on a hinge with joint `stiffness` 10 N m/rad and `damping`
  100 N m s/rad, no gravity, th(0) = 1, th'(0) = 100; error |th(10) - th*| against the closed form.

MuJoCo steps with a fixed time step: the script halves dt from a start value until the error
stops improving or 10^6 steps, and prints one JSON line per (integrator, dt): error, steps,
median wall time of `mj_step(model, data, nstep)` over the whole interval (one call from
Python). `implicitfast` treats joint and tendon dampers implicitly and springs explicitly; it is
first order. RK4 is explicit: stable only below its limit set by the fastest eigenvalue.
Run by scripts/peers/stiff.sh; alone: ~/.venv-peers/bin/python scripts/peers/stiff_mujoco.py
"""
import json

import mujoco
import numpy as np

from frontier_common import median_time
from stiff_scipy import (
    ALPHA, CHAIN_T, DAMP_C, DAMP_I, DAMP_K, DAMP_OMEGA0, DAMP_T, DAMP_THETA0, K_OVER_M, N, PEND_G,
    PEND_K, PEND_L0, PEND_M, PEND_REF, PEND_T, PEND_Y0, X0, chain_exact, damper_exact,
)


def chain_xml():
    k, c = K_OVER_M, ALPHA * K_OVER_M  # unit masses
    bodies = "\n".join(
        f'<body name="m{i}"><joint name="x{i}" type="slide" axis="1 0 0"/>'
        f'<geom type="sphere" size="0.01" mass="1" pos="{0.1 * i} 0 0" contype="0" conaffinity="0"/></body>'
        for i in range(N)
    )
    # springs: wall–x0, x_i–x_{i+1}, x_{N−1}–wall; a fixed tendon's length is Σ coef·q
    tendons = [f'<fixed name="w0" stiffness="{k}" damping="{c}" springlength="0"><joint joint="x0" coef="1"/></fixed>']
    for i in range(N - 1):
        tendons.append(
            f'<fixed name="s{i}" stiffness="{k}" damping="{c}" springlength="0">'
            f'<joint joint="x{i + 1}" coef="1"/><joint joint="x{i}" coef="-1"/></fixed>'
        )
    tendons.append(f'<fixed name="w1" stiffness="{k}" damping="{c}" springlength="0"><joint joint="x{N - 1}" coef="1"/></fixed>')
    return f"""<mujoco><option gravity="0 0 0"/>
<worldbody>{bodies}</worldbody><tendon>{''.join(tendons)}</tendon></mujoco>"""


def pendulum_xml():
    # qpos = (x, z) of the bob: the body sits at the origin and slides along x and z
    return f"""<mujoco><option gravity="0 0 {-PEND_G}"/>
<worldbody><site name="pivot" pos="0 0 0"/>
<body name="bob"><joint name="x" type="slide" axis="1 0 0"/><joint name="z" type="slide" axis="0 0 1"/>
<geom type="sphere" size="0.01" mass="{PEND_M}" contype="0" conaffinity="0"/><site name="bob" pos="0 0 0"/></body>
</worldbody>
<tendon><spatial stiffness="{PEND_K}" springlength="{PEND_L0}"><site site="pivot"/><site site="bob"/></spatial></tendon>
</mujoco>"""


def damper_xml():
    return f"""<mujoco><option gravity="0 0 0"/>
<worldbody><body name="rotor"><joint name="th" type="hinge" axis="0 0 1" stiffness="{DAMP_K}" damping="{DAMP_C}"/>
<inertial pos="0 0 0" mass="1" diaginertia="{DAMP_I} {DAMP_I} {DAMP_I}"/></body></worldbody></mujoco>"""


def problems():
    """(id, xml, qpos0, qvel0, t_end, first dt, error of the end qpos)."""
    chain_x = chain_exact(CHAIN_T)
    damp_th = damper_exact(DAMP_T)
    return [
        ("chain", chain_xml(), X0, np.zeros(N), CHAIN_T, 1e-3,
         lambda q: np.max(np.abs(q - chain_x)) / np.max(np.abs(X0))),
        ("pendulum", pendulum_xml(), PEND_Y0[:2], PEND_Y0[2:], PEND_T, 1e-2,
         lambda q: np.max(np.abs(q - PEND_REF[:2])) / PEND_L0),
        ("damper", damper_xml(), np.array([DAMP_THETA0]), np.array([DAMP_OMEGA0]), DAMP_T, 1e-2,
         lambda q: abs(q[0] - damp_th) / DAMP_THETA0),
    ]


def run(xml, q0, v0, t_end, err_of, integrator, dt):
    mujoco.set_mju_user_warning(lambda msg: None)  # divergence is read from d.warning instead
    m = mujoco.MjModel.from_xml_string(xml)
    m.opt.integrator = integrator
    m.opt.timestep = dt
    d = mujoco.MjData(m)
    steps = int(round(t_end / dt))

    def go():
        mujoco.mj_resetData(m, d)
        d.qpos[:] = q0
        d.qvel[:] = v0
        mujoco.mj_step(m, d, nstep=steps)
        # MuJoCo resets a diverging simulation to the model's qpos0 (and its clock to 0) and
        # warns: that is a failure; the clock catches a reset whose warning was not kept
        diverged = d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0 or abs(d.time - t_end) > 0.5 * dt
        return None if diverged else d.qpos.copy()

    secs, reps, q = median_time(go, budget=1.0, max_repeats=5)
    if q is None:
        return float("inf"), steps, secs, reps
    err = float(err_of(q))
    return (err if np.isfinite(err) else float("inf")), steps, secs, reps


def main():
    for pid, xml, q0, v0, t_end, dt0, err_of in problems():
        for name, integ in (("implicitfast", mujoco.mjtIntegrator.mjINT_IMPLICITFAST), ("RK4", mujoco.mjtIntegrator.mjINT_RK4)):
            dt, best = dt0, float("inf")
            while True:
                err, steps, secs, reps = run(xml, q0, v0, t_end, err_of, integ, dt)
                print(json.dumps({"problem": pid, "tool": f"MuJoCo {name}", "dt": dt, "err": err, "steps": steps,
                                  "secs": secs, "repeats": reps}), flush=True)
                # until 10⁶ steps, or until halving dt stops paying (round-off); a diverged run
                # (inf) or a stable but useless one (error ≥ 1) says nothing yet: halve on
                if steps >= 1_000_000 or (err < 1 and best < 1 and err > 0.7 * best):
                    break
                if err < 1:
                    best = min(best, err)
                dt /= 2


if __name__ == "__main__":
    main()
