"""MuJoCo on the frontier: Euler (semi-implicit), RK4 and implicitfast at a ladder of time
steps, stepping in C (`mj_step(m, d, nstep)`, no Python loop between steps).

Problems: the hinge chains of bench_mujoco.py (n = 1, 2, 6, 12, 30), the torque-free body
(a free joint with diagonal inertia (1, 2, 3), no gravity; MuJoCo's free-joint angular
velocity is in body components), the unit pendulum (the one-link chain with the gravity that
makes ω₀ = 1, released at 3 rad) and the energy problem (the same at 1 rad, 10⁴ periods,
energy every 10 periods). MuJoCo has no central gravity: no Kepler.
"""
import numpy as np
import mujoco

import frontier_common as fc

INTEGRATORS = (("Euler", mujoco.mjtIntegrator.mjINT_EULER), ("RK4", mujoco.mjtIntegrator.mjINT_RK4),
               ("implicitfast", mujoco.mjtIntegrator.mjINT_IMPLICITFAST))
FREE_BODY = ('<mujoco><option gravity="0 0 0"/><worldbody><body><freejoint/>'
             '<inertial pos="0 0 0" mass="1" diaginertia="1 2 3"/></body></worldbody></mujoco>')


def check_model():
    """The chain MuJoCo builds has the capsule moments of frontier_common (and vectrix)."""
    m = mujoco.MjModel.from_xml_string(fc.chain_xml(2))
    perp, axial = fc.capsule_inertia()
    want = np.array([perp, perp, axial])
    assert np.allclose(m.body_inertia[1:], want, rtol=1e-14, atol=0), (m.body_inertia, want)
    assert np.allclose(m.body_ipos[1:], [0, 0, -fc.LINK / 2], rtol=0, atol=1e-16)


def ladder(res, problem, model, setup, t_end, error, kmin, kmax):
    """Each integrator at dt = t_end/N, N = ⌈t_end·2ᵏ⌉, k = kmin…kmax; `setup(d)` puts the
    initial state in d, `error(d)` measures the final one."""
    d = mujoco.MjData(model)
    for name, integrator in INTEGRATORS:
        model.opt.integrator = integrator
        for k in range(kmin, kmax + 1):
            n = int(np.ceil(t_end * 2.0 ** k))
            model.opt.timestep = t_end / n

            def run():
                mujoco.mj_resetData(model, d)
                setup(d)
                mujoco.mj_step(model, d, nstep=n)
                return error(d)

            secs, reps, err = fc.median_time(run, budget=1.0, max_repeats=7)
            err = err if np.isfinite(err) else float("inf")
            res.add(fc.point(problem, "mujoco", "mj_step", name, "steps", n, err, secs, reps,
                             series=f"MuJoCo {name}", dt=t_end / n))
            if err < fc.FLOOR or secs > fc.RUN_CAP:
                break


def main():
    check_model()
    res = fc.Results("mujoco", {"mujoco": mujoco.__version__, "numpy": np.__version__})

    if fc.only("rigid-body"):
        m = mujoco.MjModel.from_xml_string(FREE_BODY)

        def setup(d):
            d.qvel[3:6] = fc.RB_W0

        ladder(res, "rigid-body", m, setup, fc.RB_T, lambda d: fc.rigid_error(d.qvel[3:6]), 0, 22)

    g1 = fc.unit_pendulum_gravity()
    if fc.only("pendulum"):
        m = mujoco.MjModel.from_xml_string(fc.chain_xml(1, gravity=g1))

        def setup(d):
            d.qpos[0] = fc.PEND_THETA0

        ladder(res, "pendulum", m, setup, fc.PEND_T,
               lambda d: fc.pendulum_error([d.qpos[0], d.qvel[0]]), 0, 24)

    ref = fc.load_reference()
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if not fc.only(problem):
            continue
        m = mujoco.MjModel.from_xml_string(fc.chain_xml(n))
        state = ref[problem]["state"]

        def setup(d, n=n):
            d.qpos[:] = fc.chain_q0(n)

        ladder(res, problem, m, setup, fc.CHAIN_T,
               lambda d, s=state: fc.chain_error(np.concatenate([d.qpos, d.qvel]), s), 2, 26)

    if fc.only("energy-pendulum"):
        m = mujoco.MjModel.from_xml_string(fc.chain_xml(1, gravity=g1))
        periods = fc.ENERGY_PERIODS

        def setup(d):
            d.qpos[0] = fc.ENERGY_THETA0

        # s steps a period (N = 10⁴ s), a checkpoint every 10 periods
        for name, integrator in INTEGRATORS:
            m.opt.integrator = integrator
            d = mujoco.MjData(m)
            for k in range(2, 13):
                s = 2 ** k
                n = periods * s
                m.opt.timestep = fc.ENERGY_T / n
                block = fc.ENERGY_EVERY * s

                def run():
                    mujoco.mj_resetData(m, d)
                    setup(d)
                    worst = 0.0
                    for _ in range(n // block):
                        mujoco.mj_step(m, d, nstep=block)
                        worst = max(worst, float(fc.energy_rel(d.qpos[0], d.qvel[0])))
                    return worst

                secs, reps, err = fc.median_time(run, budget=1.0, max_repeats=5)
                res.add(fc.point("energy-pendulum", "mujoco", "mj_step", name, "steps/period", s,
                                 err if np.isfinite(err) else float("inf"), secs, reps, series=f"MuJoCo {name}"))
                if err < fc.FLOOR or secs > fc.RUN_CAP:
                    break
    res.save()


if __name__ == "__main__":
    main()
