"""MuJoCo peer for the four-bar (book §9.11, issue 17): the crank-rocker of
tests/ch09/four_bar.rs (a = 1, b = 3.5, c = 3, d = 4, uniform bars of unit density, gravity
9.81) closed by an equality constraint, timed at a ladder of time steps, each run's accuracy
measured against a tight reference.

Reference: the same mechanism in absolute angles q = (θ₂, θ₃, θ₄) with the two loop-closure
constraints, solved as [[M, Φ_qᵀ], [Φ_q, 0]] [q̈; λ] = [f; γ] with numpy and integrated by
scipy's DOP853 at rtol = atol = 1e-12 (independent of vectrix and of MuJoCo).

MuJoCo: the linkage in the x–z plane (hinges about −y so that angles run from x toward z and
gravity is −z), crank and rocker pinned to the world, the coupler's tip joined to the
rocker's tip by `<connect site1 site2>`; solref = (2·dt, 1), the stiffest time constant
MuJoCo advises for a step dt. Integrators Euler (semi-implicit) and RK4; timing by
`rollout` (C++ loop), median of 5.

Prints, per (integrator, dt): wall time per simulated second, |θ₂ − θ₂,ref| at T = 2 s, and the
largest loop-closure violation |φ|∞ over the run. Compare with the vectrix four-bar scene bench
at equal final error (the ratio belongs in docs/performance.md). Python is only for this
peer timing; `cargo test` never runs it.

Run: ~/.venv-peers/bin/python scripts/peers/bench_mujoco_four_bar.py
"""

import os
import statistics
import time

import mujoco
import numpy as np
from mujoco import rollout
from scipy.integrate import solve_ivp

A, B, C, D = 1.0, 3.5, 3.0, 4.0
RHO, G = 1.0, 9.81
T_END = 2.0
LENGTHS = (A, B, C)
MASSES = tuple(RHO * l for l in LENGTHS)
J_ZZ = tuple(m * l * l / 12.0 for m, l in zip(MASSES, LENGTHS))


def phi(q):
    t2, t3, t4 = q
    return np.array([A * np.cos(t2) + B * np.cos(t3) - C * np.cos(t4) - D,
                     A * np.sin(t2) + B * np.sin(t3) - C * np.sin(t4)])


def phi_q(q):
    t2, t3, t4 = q
    return np.array([[-A * np.sin(t2), -B * np.sin(t3), C * np.sin(t4)],
                     [A * np.cos(t2), B * np.cos(t3), -C * np.cos(t4)]])


def e(t):
    return np.array([np.cos(t), np.sin(t)])


def eperp(t):
    return np.array([-np.sin(t), np.cos(t)])


def rhs(_t, y):
    """Index-1 equations of the four-bar: y = (q, q̇)."""
    q, w = y[:3], y[3:]
    t2, t3, t4 = q
    # centre Jacobians (2×3) and their velocity terms J̇ q̇ (centripetal)
    jac = [np.column_stack([A / 2 * eperp(t2), np.zeros(2), np.zeros(2)]),
           np.column_stack([A * eperp(t2), B / 2 * eperp(t3), np.zeros(2)]),
           np.column_stack([np.zeros(2), np.zeros(2), C / 2 * eperp(t4)])]
    hdot = [-A / 2 * e(t2) * w[0] ** 2,
            -A * e(t2) * w[0] ** 2 - B / 2 * e(t3) * w[1] ** 2,
            -C / 2 * e(t4) * w[2] ** 2]
    grav = np.array([0.0, -G])
    mass = np.diag(J_ZZ).astype(float)
    force = np.zeros(3)
    for m, j, h in zip(MASSES, jac, hdot):
        mass += m * j.T @ j
        force += m * j.T @ (grav - h)
    pq = phi_q(q)
    gamma = np.array([A * np.cos(t2) * w[0] ** 2 + B * np.cos(t3) * w[1] ** 2 - C * np.cos(t4) * w[2] ** 2,
                      A * np.sin(t2) * w[0] ** 2 + B * np.sin(t3) * w[1] ** 2 - C * np.sin(t4) * w[2] ** 2])
    kkt = np.block([[mass, pq.T], [pq, np.zeros((2, 2))]])
    sol = np.linalg.solve(kkt, np.concatenate([force, gamma]))
    return np.concatenate([w, sol[:3]])


def initial_state():
    """Assembled at θ₂ = 0.3 by Newton from (1.2, 1.9), crank rate 6 rad/s, Φ_q q̇ = 0."""
    q = np.array([0.3, 1.2, 1.9])
    for _ in range(50):
        r = phi(q)
        if np.max(np.abs(r)) < 1e-15:
            break
        q[1:] -= np.linalg.solve(phi_q(q)[:, 1:], r)
    pq = phi_q(q)
    w = np.zeros(3)
    w[0] = 6.0
    w[1:] = np.linalg.solve(pq[:, 1:], -pq[:, 0] * w[0])
    return q, w


def model_xml(dt, integrator):
    def bar(name, length, mass, jzz):
        return (f'<joint name="{name}" type="hinge" axis="0 -1 0"/>'
                f'<inertial pos="{length / 2} 0 0" mass="{mass}" diaginertia="{jzz * 1e-3} {jzz} {jzz}"/>')
    return f"""<mujoco>
  <option timestep="{dt}" integrator="{integrator}" gravity="0 0 -{G}"><flag contact="disable"/></option>
  <worldbody>
    <body name="crank">{bar("j2", A, MASSES[0], J_ZZ[0])}
      <body name="coupler" pos="{A} 0 0">{bar("j3", B, MASSES[1], J_ZZ[1])}
        <site name="tip_b" pos="{B} 0 0"/>
      </body>
    </body>
    <body name="rocker" pos="{D} 0 0">{bar("j4", C, MASSES[2], J_ZZ[2])}
      <site name="tip_c" pos="{C} 0 0"/>
    </body>
  </worldbody>
  <equality><connect site1="tip_b" site2="tip_c" solref="{2 * dt} 1"/></equality>
</mujoco>"""


def median_time(fn, repeat=5):
    fn()
    samples = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        samples.append(time.perf_counter() - t0)
    return statistics.median(samples)


def main():
    q0, w0 = initial_state()
    ref = solve_ivp(rhs, (0.0, T_END), np.concatenate([q0, w0]), method="DOP853", rtol=1e-12, atol=1e-12)
    th2_ref = ref.y[0, -1]
    print(f"reference θ₂(T = {T_END}) = {th2_ref:.12f} (scipy DOP853, rtol 1e-12, {ref.nfev} f-evals); "
          f"|φ(T)|∞ = {np.max(np.abs(phi(ref.y[:3, -1]))):.1e}")
    print(f"mujoco {mujoco.__version__}, load average {os.getloadavg()[0]:.1f}")
    print("| integrator | dt | wall per simulated s | abs. error θ₂(T) | max \\|φ\\|∞ |")
    print("|---|---|---|---|---|")
    for integrator in ("Euler", "RK4"):
        for dt in (1e-3, 5e-4, 2e-4, 1e-4, 5e-5):
            m = mujoco.MjModel.from_xml_string(model_xml(dt, integrator))
            d = mujoco.MjData(m)
            # joint coordinates: the coupler's hinge is relative to the crank
            d.qpos[:] = [q0[0], q0[1] - q0[0], q0[2]]
            d.qvel[:] = [w0[0], w0[1] - w0[0], w0[2]]
            spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
            s0 = np.empty(mujoco.mj_stateSize(m, spec))
            mujoco.mj_getState(m, d, s0, spec)
            nstep = int(round(T_END / dt))
            states, _ = rollout.rollout(m, d, s0[None], nstep=nstep)
            wall = median_time(lambda: rollout.rollout(m, d, s0[None], nstep=nstep))
            # full-physics state = (time, qpos, qvel, ...)
            qpos = states[0, :, 1:4]
            th = np.column_stack([qpos[:, 0], qpos[:, 0] + qpos[:, 1], qpos[:, 2]])
            viol = max(np.max(np.abs(phi(row))) for row in th)
            err = abs(th[-1, 0] - th2_ref)
            print(f"| {integrator} | {dt:.0e} | {wall / T_END * 1e3:.3g} ms | {err:.1e} | {viol:.1e} |", flush=True)


if __name__ == "__main__":
    main()
