"""Model (book §7.11) against the stored Pinocchio 4.1.0 reference (scripts/pin_reference.py,
tests/data/multibody_reference.json): every joint type and the 6-link chain."""
import json
from pathlib import Path

import numpy as np
import pytest

import vectrix

DATA = json.loads((Path(__file__).resolve().parents[2] / "tests/data/multibody_reference.json").read_text())
CASES = [(name, k) for name, m in DATA["models"].items() for k in range(len(m["cases"]))]


def model(name):
    return vectrix.Model.from_links(DATA["models"][name]["links"], gravity=DATA["gravity"])


def rel(got, want):
    """max |got − want| / max(1, max |want|); NaN propagates to a failing comparison."""
    got, want = np.asarray(got), np.asarray(want)
    return np.max(np.abs(got - want)) / max(1.0, np.max(np.abs(want)))


@pytest.mark.parametrize("name,k", CASES)
def test_rnea_aba_crba_and_derivatives_match_pinocchio(name, k):
    m, c = model(name), DATA["models"][name]["cases"][k]
    assert rel(m.rnea(c["q"], c["v"], c["a"]), c["rnea_tau"]) < 1e-12
    assert rel(m.aba(c["q"], c["v"], c["tau"]), c["aba_vdot"]) < 1e-10
    assert rel(m.crba(c["q"]), c["crba_m"]) < 1e-13
    d = m.rnea_derivatives(c["q"], c["v"], c["a"])
    assert rel(d["dtau_dq"], c["dtau_dq"]) < 1e-11 and rel(d["dtau_dv"], c["dtau_dv"]) < 1e-11
    f = m.aba_derivatives(c["q"], c["v"], c["tau"])
    assert rel(f["dvdot_dq"], c["dvdot_dq"]) < 1e-9 and rel(f["dvdot_dv"], c["dvdot_dv"]) < 1e-9
    assert rel(f["dvdot_dtau"], c["dvdot_dtau"]) < 1e-10


@pytest.mark.parametrize("name", list(DATA["models"]))
def test_batched_forms_equal_the_single_calls(name):
    m, cases = model(name), DATA["models"][name]["cases"]
    q = np.array([c["q"] for c in cases])
    v = np.array([c["v"] for c in cases])
    tau = np.array([c["tau"] for c in cases])
    vd = m.aba(q, v, tau)
    assert vd.shape == (len(cases), m.nv)
    for k, c in enumerate(cases):
        assert rel(vd[k], c["aba_vdot"]) < 1e-10
    assert m.crba(q).shape == (len(cases), m.nv, m.nv)
    assert m.aba_derivatives(q, v, tau)["dvdot_dq"].shape == (len(cases), m.nv, m.nv)
    # one state broadcast against many torques
    assert m.aba(q[0], v[0], tau).shape == (len(cases), m.nv)


def test_bad_states_name_the_argument():
    m = model("chain6")
    with pytest.raises(ValueError, match=r"q: shape \(5,\); valid: \(6,\) or \(N, 6\)"):
        m.aba(np.zeros(5), np.zeros(6), np.zeros(6))
    with pytest.raises(ValueError, match="tau: element 2"):
        m.aba(np.zeros(6), np.zeros(6), [0, 0, np.nan, 0, 0, 0])
    with pytest.raises(ValueError, match="v: 3 states against 4"):
        m.aba(np.zeros((4, 6)), np.zeros((3, 6)), np.zeros(6))
    with pytest.raises(ValueError, match="joint"):
        vectrix.Model.from_links([{"parent": None, "joint": "hinge"}])
