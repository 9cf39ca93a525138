"""Dump a Pinocchio model of an examples/models/ file as plain joints for the C++ harness
(benches/peers/pin_models.cpp), whose wheel ships no urdfdom headers to parse URDF in C++.

Pinocchio loads the file with its own parser (buildModelFromUrdf, buildModelFromMJCF); each
joint is written as `type parent R(9, rows) p(3) mass lever(3) I(9, rows) [axis(3)]` with the
parent as a 0-based line index (-1: the universe). A composite joint (an MJCF body with several
joints) is written as its chain of sub-joints with massless bodies between them (the same tree
vectrix builds). The rebuilt model is checked against the parsed one (RNEA at random states,
1e-12 relative) before the file is written.

    ~/.venv-peers/bin/python scripts/pin_model_dump.py examples/models/arm7.urdf out.txt
"""
import sys

import numpy as np
import pinocchio as pin

SIMPLE = {"JointModelRX": "RX", "JointModelRY": "RY", "JointModelRZ": "RZ", "JointModelPX": "PX",
          "JointModelPY": "PY", "JointModelPZ": "PZ", "JointModelFreeFlyer": "FreeFlyer",
          "JointModelSpherical": "Spherical", "JointModelRevoluteUnaligned": "RevoluteUnaligned"}


def joint_model(kind, axis):
    if kind == "RevoluteUnaligned":
        return pin.JointModelRevoluteUnaligned(np.array(axis))
    return getattr(pin, "JointModel" + kind)()


def rows(model):
    out = []  # (kind, parent line, placement, inertia, axis)
    line_of = {0: -1}
    for j in range(1, model.njoints):
        jm, parent = model.joints[j], line_of[model.parents[j]]
        placement, inertia = model.jointPlacements[j], model.inertias[j]
        subs = [(jm, pin.SE3.Identity())]
        if jm.shortname() == "JointModelComposite":
            c = jm.extract()
            subs = list(zip(c.joints, c.jointPlacements))
        for k, (sj, sM) in enumerate(subs):
            name = sj.shortname()
            if name not in SIMPLE:
                raise SystemExit(f"joint type {name} is not handled")
            axis = list(sj.extract().axis) if name == "JointModelRevoluteUnaligned" else None
            last = k == len(subs) - 1
            body = inertia if last else pin.Inertia.Zero()
            out.append((SIMPLE[name], parent, placement * sM if k == 0 else sM, body, axis))
            parent = len(out) - 1
        line_of[j] = len(out) - 1
    return out


def rebuild(rs):
    m = pin.Model()
    ids = []
    for kind, parent, M, Y, axis in rs:
        jid = m.addJoint(0 if parent < 0 else ids[parent], joint_model(kind, axis), M, f"j{len(ids)}")
        m.appendBodyToJoint(jid, Y, pin.SE3.Identity())
        ids.append(jid)
    return m


def main(path, out):
    model = pin.buildModelFromMJCF(path) if path.endswith(".xml") else pin.buildModelFromUrdf(path)
    rs = rows(model)
    m2 = rebuild(rs)
    assert (m2.nq, m2.nv) == (model.nq, model.nv)
    d1, d2 = model.createData(), m2.createData()
    rng = np.random.default_rng(1)
    for _ in range(5):
        q = pin.integrate(model, pin.neutral(model), rng.uniform(-1, 1, model.nv))
        v, a = rng.uniform(-1, 1, model.nv), rng.uniform(-1, 1, model.nv)
        t1, t2 = pin.rnea(model, d1, q, v, a), pin.rnea(m2, d2, q, v, a)
        assert np.max(np.abs(t1 - t2)) <= 1e-12 * max(1.0, np.max(np.abs(t1))), "rebuilt model differs"
    with open(out, "w") as f:
        for kind, parent, M, Y, axis in rs:
            nums = [*M.rotation.flatten(), *M.translation, Y.mass, *Y.lever, *Y.inertia.flatten()]
            nums += axis or []
            f.write(f"{kind} {parent} " + " ".join(repr(float(x)) for x in nums) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
