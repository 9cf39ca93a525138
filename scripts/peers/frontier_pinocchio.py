"""Pinocchio's ABA (C++, called from Python) as the right-hand side of scipy's solve_ivp on the
hinge chains, on the 7-DOF arm and on the floating quadruped (examples/models/arm7.urdf and
quadruped.urdf through Pinocchio's own URDF parser; the quadruped's free flyer q̇ by quaternion
kinematics, its end state in the frontier's common form, cpp/pin_dump.hpp):
what a Pinocchio user who integrates with scipy pays. DOP853 and LSODA at rtol = atol = 1e-3 …
1e-14 (frontier_scipy's ladder)."""
import os

import numpy as np
import pinocchio as pin

import frontier_common as fc
from frontier_scipy import ladder


def chain_model(n):
    """The chain of bench_mujoco.py: revolute joints about y, link i's centre at −(l/2)z and
    the next joint at −l z, capsule moments, gravity −9.81 z (Pinocchio's default)."""
    model = pin.Model()
    perp, axial = fc.capsule_inertia()
    inertia = pin.Inertia(fc.MASS, np.array([0.0, 0.0, -fc.LINK / 2]), np.diag([perp, perp, axial]))
    parent = 0
    for i in range(n):
        place = pin.SE3(np.eye(3), np.array([0.0, 0.0, 0.0 if i == 0 else -fc.LINK]))
        parent = model.addJoint(parent, pin.JointModelRY(), place, f"j{i}")
        model.appendBodyToJoint(parent, inertia, pin.SE3.Identity())
    model.gravity.linear = np.array([0.0, 0.0, -fc.GRAVITY])
    return model


# examples/frontier/problems.rs ARM7_Q0 and TREE_T (and scripts/peers/spatial_reference.sh)
ARM7_Q0 = [0.3, 1.2, -0.5, -0.8, 0.4, 0.6, -0.2]
TREE_T = 1.0


class PinRhs:
    def __init__(self, n, model=None):
        self.n = n
        self.model = chain_model(n) if model is None else model
        self.data = self.model.createData()
        self.tau = np.zeros(n)

    def __call__(self, t, y):
        q, v = y[:self.n], y[self.n:]
        return np.concatenate([v, pin.aba(self.model, self.data, q, v, self.tau)])


# examples/frontier/problems.rs QUADRUPED_Q0, QUADRUPED_V0 in Pinocchio's layout (quaternion
# x, y, z, w; the trunk's velocity in its own frame, which is the ground's at t = 0)
QUADRUPED_Q0 = [0, 0, 0, 0, 0, 0, 1, 0.2, 0.7, -1.4, -0.2, 0.7, -1.4, 0.2, -0.7, 1.4, -0.2, -0.7, 1.4]
QUADRUPED_V0 = [0, 0, 0, 0.3, 0.5, 1.0] + [0] * 12


def quat_matrix(x, y, z, w):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def config_rate(q, v):
    """q̇ of a tree whose root is a free flyer (cpp/pin_dump.hpp config_rate): ṗ = R v,
    (ẋ, ẏ, ż, ẇ) = ½ q ⊗ (0, ω), the other coordinates q̇ = v."""
    x, y, z, w = q[3:7]
    wx, wy, wz = v[3:6]
    return np.concatenate([quat_matrix(x, y, z, w) @ v[:3],
                           [(w * wx + y * wz - z * wy) / 2, (w * wy + z * wx - x * wz) / 2,
                            (w * wz + x * wy - y * wx) / 2, -(x * wx + y * wy + z * wz) / 2], v[6:]])


def common_form(y):
    """The end state (q, v) of the free-root tree in the frontier's common form (pin_dump.hpp)."""
    q, v = y[:19], y[19:]
    x, yy, z, w = q[3:7]
    sign = -1.0 if w < 0 else 1.0
    return np.concatenate([q[:3], sign * np.array([w, x, yy, z]), q[7:], config_rate(q, v)[:3], v[3:]])


class FloatingRhs:
    def __init__(self, model):
        self.model, self.data = model, model.createData()
        self.tau = np.zeros(model.nv)

    def __call__(self, t, y):
        q, v = y[:self.model.nq], y[self.model.nq:]
        return np.concatenate([config_rate(q, v), pin.aba(self.model, self.data, q, v, self.tau)])


def main():
    res = fc.Results("pinocchio", {"pin": pin.__version__, "numpy": np.__version__})
    ref = fc.load_reference()
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if not fc.only(problem):
            continue
        rhs = PinRhs(n)
        y0 = fc.chain_y0(n)
        diff = np.max(np.abs(rhs(0, y0) - fc.ChainRhs(n)(0, y0)))
        assert diff < 1e-9, f"{problem}: Pinocchio and numpy accelerations differ by {diff:e}"
        state = ref[problem]["state"]
        ladder(res, problem, rhs, y0, fc.CHAIN_T, lambda s, st=state: fc.chain_error(s.y[:, -1], st),
               tool="pinocchio", series="pinocchio+{}", methods=("DOP853", "LSODA"))
    if fc.only("arm7"):
        model = pin.buildModelFromUrdf(os.path.join(fc.REPO, "examples", "models", "arm7.urdf"))
        model.gravity.linear = np.array([0.0, 0.0, -fc.GRAVITY])
        rhs = PinRhs(7, model)
        y0 = np.concatenate([ARM7_Q0, np.zeros(7)])
        state = ref["arm7"]["state"]
        ladder(res, "arm7", rhs, y0, TREE_T, lambda s, st=state: fc.chain_error(s.y[:, -1], st),
               tool="pinocchio", series="pinocchio+{}", methods=("DOP853", "LSODA"))
    if fc.only("quadruped"):
        model = pin.buildModelFromUrdf(os.path.join(fc.REPO, "examples", "models", "quadruped.urdf"))
        model.gravity.linear = np.array([0.0, 0.0, -fc.GRAVITY])
        assert (model.nq, model.nv) == (19, 18) and model.joints[1].shortname() == "JointModelFreeFlyer"
        rhs = FloatingRhs(model)
        y0 = np.concatenate([QUADRUPED_Q0, QUADRUPED_V0])
        state = ref["quadruped"]["state"]
        ladder(res, "quadruped", rhs, y0, TREE_T,
               lambda s, st=state: fc.chain_error(common_form(s.y[:, -1]), st),
               tool="pinocchio", series="pinocchio+{}", methods=("DOP853", "LSODA"))
    res.save()


if __name__ == "__main__":
    main()
