"""sympy.physics.mechanics as a peer on the frontier: derive the equations of motion with
KanesMethod, lambdify the full mass matrix and forcing (cse), integrate with scipy's
solve_ivp (DOP853 and LSODA) at a ladder of rtol. The derivation and lambdify time is the
pipeline's one-off cost (`setup_seconds`), added to each point's time on the frontier.

Problems: the unit pendulum (a particle on a massless rod, g = l = 1) and the hinge chains
(rigid capsules with their inertia, relative angles about y, as MuJoCo's model).
"""
import signal
import time

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from scipy.integrate import solve_ivp

import frontier_common as fc

# A derivation that takes longer than this is abandoned (and said so in the JSON).
DERIVE_LIMIT = int(__import__("os").environ.get("FRONTIER_SYMPY_LIMIT", "900"))
RTOLS = [10.0 ** -k for k in range(3, 14)]
METHODS = ("DOP853", "LSODA")


def chain_eom(n):
    """Kane's equations of the chain: frame A_i turns by q_i about A_{i−1}.y (MuJoCo's hinge),
    hinge i+1 sits at −l A_i.z, the centre at −(l/2) A_i.z; gravity −g N.z."""
    q, u = me.dynamicsymbols(f"q:{n}"), me.dynamicsymbols(f"u:{n}")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    i_perp, i_axial = fc.capsule_inertia()
    frame, joint, bodies, loads = N, O, [], []
    for i in range(n):
        A = frame.orientnew(f"A{i}", "Axis", [q[i], frame.y])
        A.set_ang_vel(frame, u[i] * frame.y)
        C = joint.locatenew(f"C{i}", -fc.LINK / 2 * A.z)
        C.v2pt_theory(joint, N, A)
        P = joint.locatenew(f"P{i}", -fc.LINK * A.z)
        P.v2pt_theory(joint, N, A)
        inertia = (me.inertia(A, i_perp, i_perp, i_axial), C)
        bodies.append(me.RigidBody(f"B{i}", C, A, fc.MASS, inertia))
        loads.append((C, -fc.MASS * fc.GRAVITY * N.z))
        frame, joint = A, P
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations(bodies, loads)
    return km.mass_matrix_full, km.forcing_full, list(q) + list(u)


def pendulum_eom():
    """The unit pendulum: a particle of mass 1 on a massless rod of length 1, g = 1."""
    q, u = me.dynamicsymbols("q u")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    A = N.orientnew("A", "Axis", [q, N.z])
    A.set_ang_vel(N, u * N.z)
    P = O.locatenew("P", -A.y)
    P.v2pt_theory(O, N, A)
    km = me.KanesMethod(N, q_ind=[q], u_ind=[u], kd_eqs=[q.diff() - u])
    km.kanes_equations([me.Particle("p", P, 1.0)], [(P, -1.0 * N.y)])
    return km.mass_matrix_full, km.forcing_full, [q, u]


class Timeout(Exception):
    pass


def _alarm(*_):
    raise Timeout


def pipeline(derive):
    """Derivation + lambdify; returns (rhs, seconds)."""
    t0 = time.perf_counter()
    mm, ff, states = derive()
    f_m = sm.lambdify([states], mm, "numpy", cse=True)
    f_f = sm.lambdify([states], ff, "numpy", cse=True)
    seconds = time.perf_counter() - t0

    def rhs(t, y):
        return np.linalg.solve(f_m(y), f_f(y)).ravel()

    return rhs, seconds


def ladder(res, problem, rhs, setup, y0, t_end, error):
    for method in METHODS:
        for rtol in RTOLS:
            def run():
                return solve_ivp(rhs, (0.0, t_end), y0, method=method, rtol=rtol, atol=rtol)
            secs, reps, sol = fc.median_time(run, budget=2.0, max_repeats=5)
            err = error(sol.y[:, -1]) if sol.success else float("inf")
            res.add(fc.point(problem, "sympy", "kane+lambdify+solve_ivp", method, "rtol", rtol, err, secs,
                             reps, series=f"sympy+{method}", setup_seconds=setup, fevals=int(sol.nfev)))
            if err < fc.FLOOR or secs > fc.RUN_CAP:
                break


def main():
    res = fc.Results("sympy", {"sympy": sm.__version__, "numpy": np.__version__,
                               "scipy": __import__("scipy").__version__})
    signal.signal(signal.SIGALRM, _alarm)
    if fc.only("pendulum"):
        rhs, setup = pipeline(pendulum_eom)
        print(f"pendulum: derive + lambdify {setup:.3f} s")
        ladder(res, "pendulum", rhs, setup, np.array([fc.PEND_THETA0, 0.0]), fc.PEND_T, fc.pendulum_error)
    ref = fc.load_reference()
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if not fc.only(problem):
            continue
        signal.alarm(DERIVE_LIMIT)
        try:
            rhs, setup = pipeline(lambda: chain_eom(n))
            signal.alarm(0)
        except Timeout:
            print(f"{problem}: derivation abandoned after {DERIVE_LIMIT} s")
            res.meta.setdefault("abandoned", {})[problem] = f"derivation > {DERIVE_LIMIT} s"
            continue
        print(f"{problem}: derive + lambdify {setup:.3f} s")
        y0 = fc.chain_y0(n)
        # the derived equations are MuJoCo's chain: same accelerations as the numpy model
        ok = np.max(np.abs(rhs(0, y0) - fc.ChainRhs(n)(0, y0)))
        assert ok < 1e-9, f"{problem}: sympy and numpy right-hand sides differ by {ok:e}"
        state = ref[problem]["state"]
        ladder(res, problem, rhs, setup, y0, fc.CHAIN_T, lambda y: fc.chain_error(y, state))
    res.save()


if __name__ == "__main__":
    main()
