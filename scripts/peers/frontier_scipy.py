"""scipy's solve_ivp on the frontier: RK45, DOP853, Radau and LSODA at rtol = atol = 1e-3 …
1e-14 (solve_ivp raises an rtol below 100 ε to 2.2e-14, with a warning: the tightest a scipy
user can ask for), on right-hand sides written in numpy (frontier_common): the torque-free body (Euler's
equations + quaternion), Kepler e = 0.9, the pendulum at 3 rad, the hinge chains (a numpy
Lagrangian, checked against MuJoCo's accelerations) and the energy problem (the energy read at
the 1001 checkpoints through `t_eval`, i.e. from solve_ivp's dense output)."""
import numpy as np
import scipy
from scipy.integrate import solve_ivp

import frontier_common as fc

METHODS = ("RK45", "DOP853", "Radau", "LSODA")
RTOLS = [10.0 ** -k for k in range(3, 15)]


def ladder(res, problem, rhs, y0, t_end, error, t_eval=None, tool="scipy", series=None, methods=METHODS):
    for method in methods:
        for rtol in RTOLS:
            def run():
                return solve_ivp(rhs, (0.0, t_end), y0, method=method, rtol=rtol, atol=rtol, t_eval=t_eval)
            secs, reps, sol = fc.median_time(run, budget=2.0, max_repeats=7)
            err = error(sol) if sol.success else float("inf")
            res.add(fc.point(problem, tool, "solve_ivp", method, "rtol", rtol, err, secs, reps,
                             series=(series or f"{tool} {{}}").format(method), fevals=int(sol.nfev)))
            if err < fc.FLOOR or secs > fc.RUN_CAP:
                break


def main():
    res = fc.Results("scipy", {"scipy": scipy.__version__, "numpy": np.__version__})
    if fc.only("rigid-body"):
        ladder(res, "rigid-body", fc.rigid_rhs, fc.RB_Y0, fc.RB_T, lambda s: fc.rigid_error(s.y[:3, -1]))
    if fc.only("kepler-e0.9"):
        ladder(res, "kepler-e0.9", fc.kepler_rhs, fc.KEPLER_Y0, fc.KEPLER_T, lambda s: fc.kepler_error(s.y[:, -1]))
    if fc.only("pendulum"):
        ladder(res, "pendulum", fc.pendulum_rhs, np.array([fc.PEND_THETA0, 0.0]), fc.PEND_T,
               lambda s: fc.pendulum_error(s.y[:, -1]))
    ref = fc.load_reference()
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if fc.only(problem):
            state = ref[problem]["state"]
            ladder(res, problem, fc.ChainRhs(n), fc.chain_y0(n), fc.CHAIN_T,
                   lambda s, st=state: fc.chain_error(s.y[:, -1], st))
    if fc.only("energy-pendulum"):
        ladder(res, "energy-pendulum", fc.pendulum_rhs, np.array([fc.ENERGY_THETA0, 0.0]), fc.ENERGY_T,
               lambda s: float(np.max(fc.energy_rel(s.y[0], s.y[1]))), t_eval=fc.energy_checkpoints())
    res.save()


if __name__ == "__main__":
    main()
