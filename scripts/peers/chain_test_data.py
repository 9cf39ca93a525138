"""Reference data for tests/frontier_harness.rs: MuJoCo's own numbers for the hinge chain of
bench_mujoco.py, so that the test can check that vectrix builds the same mechanism (capsule
moments, centres, joint placement, gravity). Run once; writes tests/data/frontier_chain_mujoco.json.

    ~/.venv-peers/bin/python scripts/peers/chain_test_data.py
"""
import json
import os

import mujoco
import numpy as np

import frontier_common as fc

N = 6
m = mujoco.MjModel.from_xml_string(fc.chain_xml(N))
d = mujoco.MjData(m)
rng = np.random.default_rng(24)
d.qpos[:] = rng.uniform(-1.5, 1.5, N)
d.qvel[:] = rng.uniform(-3.0, 3.0, N)
mujoco.mj_forward(m, d)
mass = np.zeros((N, N))
mujoco.mj_fullM(m, d, mass)
out = dict(
    source=f"MuJoCo {mujoco.__version__}, mj_forward on bench_mujoco.py's chain_xml({N})",
    n=N, body_inertia=m.body_inertia[1].tolist(), body_ipos=m.body_ipos[1].tolist(),
    qpos=d.qpos.tolist(), qvel=d.qvel.tolist(), qacc=d.qacc.tolist(),
    mass_matrix_condition=float(np.linalg.cond(mass)),
)
path = os.path.join(fc.REPO, "tests", "data", "frontier_chain_mujoco.json")
with open(path, "w") as f:
    json.dump(out, f, indent=1)
print("wrote", path, out["mass_matrix_condition"])
