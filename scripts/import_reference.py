#!/usr/bin/env python3
"""Reference data for the URDF/MJCF import (issue 35): the peers load the *same files* as
vectrix (examples/models/) and give M(q) (CRBA), RNEA, ABA, link placements and Jacobians at
random states. Written to tests/data/import_<model>.txt as plain text, every number with
repr() (17 significant digits, read back exactly by Rust's correctly rounded parser).

    ~/.venv-peers/bin/python scripts/import_reference.py

Peers: URDF through Pinocchio's `buildModelFromUrdf`, MJCF through MuJoCo's
`MjModel.from_xml_path`. Gravity (0, 0, -9.81) for URDF (Pinocchio's default); MJCF uses its
own <option gravity>.

Conventions, converted here so that every stored number is in vectrix's layout:
* Pinocchio orders joints depth first from the root, children in file order: the same as
  the importer; the script writes the joint names so the test checks the order.
* Pinocchio's free flyer: q = (x, y, z, qx, qy, qz, qw), v = (R^T p', w) with the linear
  velocity in the *link* frame. vectrix's free joint: q = (x, y, z, w, qx, qy, qz), v = (p', w)
  with p' in the joint (parent) frame. With T = blockdiag(R^T, I) (v_pin = T v),
  a_pin = T a + T' v (T' v = (-w x R^T p', 0)), tau = T^T tau_pin, M = T^T M_pin T,
  J = J_pin T.
* MuJoCo: qpos of a free joint is (position, quaternion w x y z) and qvel is (velocity in the
  world, w in the body): vectrix's layout already. Ball joints: quaternion w x y z, w in the
  body: the same. Passive forces and constraints are disabled for these numbers (damping is
  reported by the importer as unmapped; equality loops are checked in tests by the scene).
* Placements: R (columns = link axes in the world) row by row, then the origin p; Jacobians
  are 6 x nv, rows (velocity of the link origin, w), world components (Pinocchio's
  LOCAL_WORLD_ALIGNED, MuJoCo's mj_jacBody).
"""
import os

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
MODELS = os.path.join(ROOT, "examples", "models")
DATA = os.path.join(ROOT, "tests", "data")
STATES = 3


def fmt(xs):
    return " ".join(repr(float(x)) for x in np.asarray(xs).ravel())


def rand_quat(rng):
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


def skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def quat_to_matrix(w, x, y, z):
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def pinocchio_model(name, rng, out):
    import pinocchio as pin

    path = os.path.join(MODELS, name)
    model = pin.buildModelFromUrdf(path)
    data = model.createData()
    nq, nv = model.nq, model.nv
    free = [j for j in range(1, model.njoints) if model.joints[j].shortname() == "JointModelFreeFlyer"]
    assert all(model.joints[j].shortname() in ("JointModelFreeFlyer", "JointModelRX", "JointModelRY", "JointModelRZ",
                                               "JointModelRevoluteUnaligned", "JointModelPX", "JointModelPY",
                                               "JointModelPZ", "JointModelPrismaticUnaligned")
               for j in range(1, model.njoints)), "a joint kind the script does not convert"
    links = [f.name for f in model.frames if f.type == pin.FrameType.BODY]
    out.append(f"model {name}\npeer pinocchio {pin.__version__}\nnq {nq}\nnv {nv}")
    out.append("joints " + " ".join(model.names[j] for j in range(1, model.njoints)))
    out.append("links " + " ".join(links))
    for _ in range(STATES):
        qx = rng.uniform(-1.5, 1.5, nq)  # vectrix layout
        v, a, tau = rng.normal(size=nv), rng.normal(size=nv), rng.normal(size=nv) * 5
        qp = qx.copy()
        T = np.eye(nv)
        Tdv = np.zeros(nv)
        for j in free:
            iq, iv = model.idx_qs[j], model.idx_vs[j]
            quat = rand_quat(rng)
            qx[iq + 3:iq + 7] = quat  # w x y z
            qp[iq:iq + 3] = qx[iq:iq + 3]
            qp[iq + 3:iq + 6], qp[iq + 6] = quat[1:], quat[0]
            R = quat_to_matrix(*quat)
            T[iv:iv + 3, iv:iv + 3] = R.T
            Tdv[iv:iv + 3] = -np.cross(v[iv + 3:iv + 6], R.T @ v[iv:iv + 3])
        vp, ap = T @ v, T @ a + Tdv
        rnea = T.T @ pin.rnea(model, data, qp, vp, ap)
        M = pin.crba(model, data, qp)
        M = np.triu(M) + np.triu(M, 1).T
        M = T.T @ M @ T
        aba = T.T @ (pin.aba(model, data, qp, vp, T @ tau) - Tdv)
        out.append(f"state\nq {fmt(qx)}\nv {fmt(v)}\na {fmt(a)}\ntau {fmt(tau)}")
        out.append(f"rnea {fmt(rnea)}\naba {fmt(aba)}\ncrba {fmt(M)}")
        pin.computeJointJacobians(model, data, qp)
        pin.framesForwardKinematics(model, data, qp)
        for name_l in links:
            fid = model.getFrameId(name_l, pin.FrameType.BODY)
            X = data.oMf[fid]
            J = pin.getFrameJacobian(model, data, fid, pin.LOCAL_WORLD_ALIGNED) @ T
            out.append(f"frame {name_l} {fmt(X.rotation)} {fmt(X.translation)}")
            out.append(f"jacobian {name_l} {fmt(J)}")
        out.append("end")


def mujoco_model(name, rng, out):
    import mujoco

    path = os.path.join(MODELS, name)
    m = mujoco.MjModel.from_xml_path(path)
    bits = mujoco.mjtDisableBit
    off = ["mjDSBL_CONSTRAINT", "mjDSBL_PASSIVE", "mjDSBL_SPRING", "mjDSBL_DAMPER"]
    for b in off:
        if hasattr(bits, b):
            m.opt.disableflags |= int(getattr(bits, b))
    d = mujoco.MjData(m)
    nq, nv = m.nq, m.nv
    out.append(f"model {name}\npeer mujoco {mujoco.__version__}\nnq {nq}\nnv {nv}")
    out.append("joints " + " ".join(mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j) or f"joint{j}" for j in range(m.njnt)))
    links = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(1, m.nbody)]
    out.append("links " + " ".join(links))
    for _ in range(STATES):
        q = rng.uniform(-1.5, 1.5, nq)
        for j in range(m.njnt):
            a0 = m.jnt_qposadr[j]
            if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
                q[a0 + 3:a0 + 7] = rand_quat(rng)
            elif m.jnt_type[j] == mujoco.mjtJoint.mjJNT_BALL:
                q[a0:a0 + 4] = rand_quat(rng)
        v, a, tau = rng.normal(size=nv), rng.normal(size=nv), rng.normal(size=nv) * 5
        d.qpos[:], d.qvel[:], d.qfrc_applied[:] = q, v, 0
        mujoco.mj_forward(m, d)
        M = np.zeros((nv, nv))
        mujoco.mj_fullM(m, d, M)
        d.qacc[:] = a
        rnea = np.zeros(nv)
        mujoco.mj_rne(m, d, 1, rnea)
        d.qfrc_applied[:] = tau
        mujoco.mj_forward(m, d)
        aba = d.qacc.copy()
        out.append(f"state\nq {fmt(q)}\nv {fmt(v)}\na {fmt(a)}\ntau {fmt(tau)}")
        out.append(f"rnea {fmt(rnea)}\naba {fmt(aba)}\ncrba {fmt(M)}")
        for b, name_l in enumerate(links, start=1):
            jp, jr = np.zeros((3, nv)), np.zeros((3, nv))
            mujoco.mj_jacBody(m, d, jp, jr, b)
            out.append(f"frame {name_l} {fmt(d.xmat[b])} {fmt(d.xpos[b])}")
            out.append(f"jacobian {name_l} {fmt(np.vstack([jp, jr]))}")
        out.append("end")


def main():
    rng = np.random.default_rng(35)
    cases = [
        ("arm7.urdf", pinocchio_model),
        ("quadruped.urdf", pinocchio_model),
        ("double_pendulum.urdf", pinocchio_model),
        ("humanoid.xml", mujoco_model),
        ("double_pendulum.xml", mujoco_model),
        ("top.xml", mujoco_model),
        ("four_bar.xml", mujoco_model),
    ]
    for name, fn in cases:
        out = [f"# generated by scripts/import_reference.py from examples/models/{name}; do not edit"]
        fn(name, rng, out)
        stem = name.replace(".", "_")
        with open(os.path.join(DATA, f"import_{stem}.txt"), "w") as f:
            f.write("\n".join(out) + "\n")
        print("wrote", f"tests/data/import_{stem}.txt")


if __name__ == "__main__":
    main()
