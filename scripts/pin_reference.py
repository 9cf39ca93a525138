#!/usr/bin/env python3
"""Reference numbers for vectrix's multibody algorithms, computed once with Pinocchio.

Writes tests/data/multibody_reference.json: for a tree with every vectrix joint type (pin,
sleeve, collar, slot, ball, weld, free) and for the 6-link revolute chain of the peers'
benchmark, at several random states:

* RNEA τ(q, v, a), ABA v̇(q, v, τ) and CRBA M(q);
* the analytical derivatives ∂τ/∂q, ∂τ/∂v (computeRNEADerivatives) and ∂v̇/∂q, ∂v̇/∂v,
  ∂v̇/∂τ = M⁻¹ (computeABADerivatives).

Each vectrix link is rebuilt from Pinocchio joints (tests/multibody_reference.rs reads the
link data back from the same file, so both sides build one tree):

* pin    = JointModelRevoluteUnaligned(axis)
* sleeve = JointModelPrismaticUnaligned(axis)
* collar = PrismaticUnaligned(axis), then RevoluteUnaligned(axis), massless body between
* slot   = PrismaticUnaligned(direction), then RevoluteUnaligned(axis ⊥ direction)
* ball   = JointModelSpherical; q is (x, y, z, w) in Pinocchio, (η, ε1, ε2, ε3) in vectrix
* weld   = the link's inertia appended to its parent's joint (appendBodyToJoint), at the
           link's placement; children of a weld link hang from that joint
* free   = JointModelFreeFlyer for τ, v̇ and M. Pinocchio's free-flyer velocity is the body
           twist in the body frame, (v_local, ω); vectrix's free joint is ℝ³ × SO(3) with
           (ẋ, ω): ẋ in the joint frame, ω in the link. With R = 𝓡_{link/joint}:
           v_local = Rᵀẋ; the acceleration a_local = Rᵀẍ − ω × v_local; generalized forces
           τ_vectrix = R τ_pin (linear part); M_vectrix = Tᵀ M_pin T, v_pin = T v_vectrix.
           For the derivatives the free joint is built as PX, PY, PZ then Spherical (exactly
           vectrix's decomposition) so that both use the same tangent space: ∂/∂q of the
           rotation is along q ⊗ exp(δ/2) (local frame), as vectrix's `integrate`. The script
           checks that both Pinocchio builds give the same τ, v̇ and M after conversion.

Conventions on the vectrix side (crates/dynamics/src/multibody/model.rs): `orientation` is
𝓞_{J/P} (passive), so the Pinocchio placement rotation is its transpose; `com` and `inertia`
(J about the centre of mass) are in the link frame.

Run once (needs the venv of ../shared/peers/README.md):
    ~/.venv-peers/bin/python scripts/pin_reference.py
"""
import json
import os

import numpy as np
import pinocchio as pin

GRAVITY = [0.0, 0.0, -9.81]
SEED = 20261201


def rot(v):
    """Rotation matrix exp(v^×)."""
    return pin.exp3(np.asarray(v, dtype=float))


def spd_inertia(rng):
    """A random inertia about the centre of mass satisfying the triangle inequality."""
    l = rng.uniform(0.05, 0.6, 3)
    lam = np.array([l[1] + l[2], l[0] + l[2], l[0] + l[1]])
    r = rot(rng.uniform(-1.0, 1.0, 3))
    return r @ np.diag(lam) @ r.T


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def tree_links(rng):
    """A tree with every joint type; link i's parent precedes it."""
    z = [0.0, 0.0, 1.0]
    spec = [
        (None, "free", {}, [0.1, -0.2, 0.3]),
        (0, "pin", {"axis": unit([1.0, 2.0, 0.5])}, [0.5, 0.0, 0.0]),
        (1, "sleeve", {"axis": unit([1.0, 0.0, 0.2])}, [0.0, 0.4, 0.0]),
        (0, "collar", {"axis": unit(z)}, [0.0, -0.5, 0.1]),
        (3, "slot", {"axis": unit(z), "direction": unit([0.0, 1.0, 0.0])}, [0.3, 0.0, 0.0]),
        (4, "ball", {}, [0.0, 0.0, 0.6]),
        (5, "weld", {}, [0.2, 0.2, 0.0]),
        (6, "pin", {"axis": unit([0.0, 1.0, 0.0])}, [0.0, 0.3, 0.1]),
        (0, "ball", {}, [-0.4, 0.1, 0.0]),
    ]
    links = []
    for parent, joint, axes, offset in spec:
        links.append({
            "parent": parent,
            "joint": joint,
            **{k: list(v) for k, v in axes.items()},
            "offset": offset,
            # 𝓞_{J/P}: a passive orientation, the transpose of Pinocchio's placement rotation
            "orientation": rot(rng.uniform(-0.6, 0.6, 3)).T.tolist(),
            "mass": float(rng.uniform(0.5, 2.5)),
            "com": list(rng.uniform(-0.2, 0.2, 3)),
            "inertia": spd_inertia(rng).tolist(),
        })
    return links


def chain_links(n, link=0.3, mass=1.0):
    """The peers' benchmark chain: revolute-Y joints, links of 0.3 along −z, unit masses."""
    inertia = np.diag([mass * link * link / 12, mass * link * link / 12, 1e-4])
    return [{
        "parent": i - 1 if i else None,
        "joint": "pin",
        "axis": [0.0, 1.0, 0.0],
        "offset": [0.0, 0.0, -link if i else 0.0],
        "orientation": np.eye(3).tolist(),
        "mass": mass,
        "com": [0.0, 0.0, -link / 2],
        "inertia": inertia.tolist(),
    } for i in range(n)]


NQ = {"pin": 1, "sleeve": 1, "collar": 2, "slot": 2, "ball": 4, "weld": 0, "free": 7}
NV = {"pin": 1, "sleeve": 1, "collar": 2, "slot": 2, "ball": 3, "weld": 0, "free": 6}


def vectrix_layout(links):
    """q and v offsets of each link in vectrix's order (the user's link order)."""
    qo, vo, nq, nv = [], [], 0, 0
    for l in links:
        qo.append(nq)
        vo.append(nv)
        nq += NQ[l["joint"]]
        nv += NV[l["joint"]]
    return qo, vo, nq, nv


def build(links, free_as_flyer):
    """The Pinocchio model, with a map from each vectrix link to its Pinocchio joints.

    Joints are added depth-first (Pinocchio's algorithms assume contiguous subtrees)."""
    model = pin.Model()
    model.gravity = pin.Motion(np.array(GRAVITY), np.zeros(3))
    children = {}
    for i, l in enumerate(links):
        children.setdefault(l["parent"], []).append(i)
    joints = {}  # link -> list of Pinocchio joint ids (last one carries the body)
    frame = {}  # link -> (joint id its frame is fixed to, SE3 of the link frame in that joint)

    def add(i):
        l = links[i]
        pj, pM = (0, pin.SE3.Identity()) if l["parent"] is None else frame[l["parent"]]
        placement = pM * pin.SE3(np.array(l["orientation"]).T, np.array(l["offset"]))
        inertia = pin.Inertia(l["mass"], np.array(l["com"]), np.array(l["inertia"]))
        kind = l["joint"]
        chain = []
        if kind == "pin":
            chain = [pin.JointModelRevoluteUnaligned(np.array(l["axis"]))]
        elif kind == "sleeve":
            chain = [pin.JointModelPrismaticUnaligned(np.array(l["axis"]))]
        elif kind == "collar":
            a = np.array(l["axis"])
            chain = [pin.JointModelPrismaticUnaligned(a), pin.JointModelRevoluteUnaligned(a)]
        elif kind == "slot":
            chain = [pin.JointModelPrismaticUnaligned(np.array(l["direction"])),
                     pin.JointModelRevoluteUnaligned(np.array(l["axis"]))]
        elif kind == "ball":
            chain = [pin.JointModelSpherical()]
        elif kind == "free":
            chain = [pin.JointModelFreeFlyer()] if free_as_flyer else [
                pin.JointModelPX(), pin.JointModelPY(), pin.JointModelPZ(), pin.JointModelSpherical()]
        if kind == "weld":
            model.appendBodyToJoint(pj, inertia, placement)
            joints[i] = []
            frame[i] = (pj, placement)
        else:
            ids = []
            for k, jm in enumerate(chain):
                pj = model.addJoint(pj, jm, placement if k == 0 else pin.SE3.Identity(), f"l{i}_{k}")
                ids.append(pj)
            model.appendBodyToJoint(pj, inertia, pin.SE3.Identity())
            joints[i] = ids
            frame[i] = (pj, pin.SE3.Identity())
        for c in children.get(i, []):
            add(c)

    for r in children.get(None, []):
        add(r)
    return model, joints


class Mapping:
    """Maps states and results between vectrix's layout and a Pinocchio model's."""

    def __init__(self, links, model, joints):
        self.links, self.model, self.joints = links, model, joints
        self.qo, self.vo, self.nq, self.nv = vectrix_layout(links)
        # vectrix velocity index -> Pinocchio velocity index (one to one)
        self.vperm = np.zeros(self.nv, dtype=int)
        for i, l in enumerate(links):
            ids = joints[i]
            off = 0
            for jid in ids:
                jm = model.joints[jid]
                for k in range(jm.nv):
                    self.vperm[self.vo[i] + off + k] = jm.idx_v + k
                off += jm.nv

    def free_rotations(self, q):
        """For each free-flyer link: (vectrix v offset, R = 𝓡_{link/joint})."""
        out = []
        for i, l in enumerate(self.links):
            if l["joint"] == "free" and self.model.joints[self.joints[i][0]].nv == 6:
                e = q[self.qo[i] + 3:self.qo[i] + 7]  # (η, ε1, ε2, ε3)
                R = pin.Quaternion(e[0], e[1], e[2], e[3]).toRotationMatrix()
                out.append((self.vo[i], R))
        return out

    def q_to_pin(self, q):
        qp = np.zeros(self.model.nq)
        for i, l in enumerate(self.links):
            ids, o = self.joints[i], self.qo[i]
            kind = l["joint"]
            if kind == "weld":
                continue
            if kind == "ball":
                e = q[o:o + 4]
                qp[self.model.joints[ids[0]].idx_q:][:4] = [e[1], e[2], e[3], e[0]]
            elif kind == "free":
                e = q[o + 3:o + 7]
                if len(ids) == 1:
                    qp[self.model.joints[ids[0]].idx_q:][:7] = [*q[o:o + 3], e[1], e[2], e[3], e[0]]
                else:
                    for k in range(3):
                        qp[self.model.joints[ids[k]].idx_q] = q[o + k]
                    qp[self.model.joints[ids[3]].idx_q:][:4] = [e[1], e[2], e[3], e[0]]
            else:
                for k, jid in enumerate(ids):
                    qp[self.model.joints[jid].idx_q] = q[o + k]
        return qp

    def T(self, q):
        """v_pin = T v_vectrix (in vectrix ordering of both)."""
        T = np.eye(self.nv)
        for o, R in self.free_rotations(q):
            T[o:o + 3, o:o + 3] = R.T
        return T

    def to_pin_vec(self, x):
        out = np.zeros(self.nv)
        out[self.vperm] = x
        return out

    def from_pin_vec(self, x):
        return np.asarray(x)[self.vperm]

    def from_pin_mat(self, m):
        return np.asarray(m)[np.ix_(self.vperm, self.vperm)]

    def v_to_pin(self, q, v):
        return self.to_pin_vec(self.T(q) @ v)

    def a_to_pin(self, q, v, a):
        ap = self.T(q) @ a
        for o, R in self.free_rotations(q):
            v_local = R.T @ v[o:o + 3]
            ap[o:o + 3] -= np.cross(v[o + 3:o + 6], v_local)
        return self.to_pin_vec(ap)

    def a_from_pin(self, q, v, ap):
        a = self.from_pin_vec(ap)
        for o, R in self.free_rotations(q):
            v_local = R.T @ v[o:o + 3]
            a[o:o + 3] = R @ (a[o:o + 3] + np.cross(v[o + 3:o + 6], v_local))
        return a

    def tau_to_pin(self, q, tau):
        # power τ_vᵀ v_v = τ_pᵀ v_p with v_p = T v_v: τ_v = Tᵀ τ_p, so τ_p = T⁻ᵀ τ_v = T τ_v
        return self.to_pin_vec(self.T(q) @ tau)

    def tau_from_pin(self, q, tp):
        return self.T(q).T @ self.from_pin_vec(tp)

    def m_from_pin(self, q, mp):
        T = self.T(q)
        return T.T @ self.from_pin_mat(mp) @ T


def symmetric(upper):
    u = np.triu(upper)
    return u + u.T - np.diag(np.diag(u))


def random_state(rng, links):
    qo, vo, nq, nv = vectrix_layout(links)
    q = np.zeros(nq)
    for i, l in enumerate(links):
        o = qo[i]
        if l["joint"] in ("ball", "free"):
            k = o + (3 if l["joint"] == "free" else 0)
            if l["joint"] == "free":
                q[o:o + 3] = rng.uniform(-1.0, 1.0, 3)
            e = rng.normal(size=4)
            e /= np.linalg.norm(e)
            q[k:k + 4] = e * np.sign(e[0])
        else:
            q[o:o + NQ[l["joint"]]] = rng.uniform(-1.5, 1.5, NQ[l["joint"]])
    return q, rng.uniform(-1.0, 1.0, nv), rng.uniform(-1.0, 1.0, nv), rng.uniform(-2.0, 2.0, nv)


def case(links, q, v, a, tau):
    flyer, fj = build(links, free_as_flyer=True)
    split, sj = build(links, free_as_flyer=False)
    out = {"q": list(q), "v": list(v), "a": list(a), "tau": list(tau)}
    results = []
    for model, joints in ((flyer, fj), (split, sj)):
        mp = Mapping(links, model, joints)
        data = model.createData()
        qp = mp.q_to_pin(q)
        vp = mp.v_to_pin(q, v)
        rt = mp.tau_from_pin(q, pin.rnea(model, data, qp, vp, mp.a_to_pin(q, v, a)))
        ab = mp.a_from_pin(q, v, pin.aba(model, data, qp, vp, mp.tau_to_pin(q, tau)))
        M = mp.m_from_pin(q, symmetric(pin.crba(model, data, qp)))
        results.append((rt, ab, M))
        if model is split:
            dq, dv, da = pin.computeRNEADerivatives(model, data, qp, vp, mp.a_to_pin(q, v, a))
            out["dtau_dq"] = mp.from_pin_mat(dq).tolist()
            out["dtau_dv"] = mp.from_pin_mat(dv).tolist()
            assert np.allclose(symmetric(da), symmetric(pin.crba(model, data, qp)), rtol=0, atol=1e-13)
            ddq, ddv, ddt = pin.computeABADerivatives(model, data, qp, vp, mp.tau_to_pin(q, tau))
            out["dvdot_dq"] = mp.from_pin_mat(ddq).tolist()
            out["dvdot_dv"] = mp.from_pin_mat(ddv).tolist()
            out["dvdot_dtau"] = mp.from_pin_mat(symmetric(ddt)).tolist()
    (rt, ab, M), (rt2, ab2, M2) = results
    # the two builds of the free joint are the same mechanics: the conversion is right
    assert np.allclose(rt, rt2, rtol=0, atol=1e-11), (rt, rt2)
    assert np.allclose(ab, ab2, rtol=0, atol=1e-10), (ab, ab2)
    assert np.allclose(M, M2, rtol=0, atol=1e-12)
    out["rnea_tau"] = list(rt)
    out["aba_vdot"] = list(ab)
    out["crba_m"] = M.tolist()
    return out


def main():
    rng = np.random.default_rng(SEED)
    tree = tree_links(rng)
    chain = chain_links(6)
    doc = {
        "generator": "scripts/pin_reference.py",
        "pinocchio": pin.__version__,
        "gravity": GRAVITY,
        "conventions": "vectrix layout for q, v, a, tau and all matrices; q-derivatives in the "
                       "tangent space (ball: q ⊗ exp(δ/2), local frame); matrices row-major",
        "models": {},
    }
    for name, links, count in (("tree", tree, 4), ("chain6", chain, 3)):
        cases = [case(links, *random_state(rng, links)) for _ in range(count)]
        doc["models"][name] = {"links": links, "cases": cases}
    path = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "multibody_reference.json")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(doc, f, separators=(",", ":"))
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
