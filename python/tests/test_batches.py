"""Batches large enough to be split over threads (≥ 16 384 rotations, ≥ 256 multibody states)
with numpy buffers read in place: the same answers as scipy's Rotation and the stored
Pinocchio reference whatever the input's layout or dtype, and errors that name the first bad
element wherever it falls."""
import json
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation as SR

import vectrix
from vectrix import GimbalLockWarning, Rotation

N = 40_000  # above the 16 384 rotations from which the binding uses every core
RNG = np.random.default_rng(37)
Q = RNG.standard_normal((N, 4))
V = RNG.standard_normal((N, 3))


def same_rotation(qa, qb):
    """max over elements of min(|qa − qb|, |qa + qb|): q and −q are one rotation (NaN fails)."""
    return np.max(np.minimum(np.abs(qa - qb).max(axis=-1), np.abs(qa + qb).max(axis=-1)))


def test_large_batches_match_scipy():
    r, s = Rotation.from_quat(Q), SR.from_quat(Q)
    assert same_rotation(r.as_quat(), s.as_quat()) < 1e-15
    # 𝓡(q) by the same polynomial (2.15.14), rounded differently: a few ulps
    assert np.max(np.abs(r.as_matrix() - s.as_matrix())) < 16 * np.finfo(float).eps
    assert np.max(np.abs(r.apply(V) - s.apply(V))) < 1e-14
    assert np.max(np.abs(r.apply(V, inverse=True) - s.apply(V, inverse=True))) < 1e-14
    assert same_rotation(Rotation.from_matrix(s.as_matrix()).as_quat(), s.as_quat()) < 1e-15
    # random rotations are far from gimbal lock: the principal angles coincide
    assert np.max(np.abs(r.as_euler("ZYX") - s.as_euler("ZYX"))) < 1e-13
    assert np.max(np.abs(r.as_rotvec() - s.as_rotvec())) < 1e-14
    e = s.as_euler("xyz")
    assert same_rotation(Rotation.from_euler("xyz", e).as_quat(), s.as_quat()) < 1e-14
    assert same_rotation(Rotation.from_rotvec(s.as_rotvec()).as_quat(), s.as_quat()) < 1e-15


@pytest.mark.parametrize("layout", ["strided", "fortran", "float32", "int64", "big-endian"])
def test_every_layout_reads_the_same_values(layout):
    base = np.round(Q * 1000)  # integers, so that every dtype below holds them exactly
    x = {
        "strided": np.repeat(base, 2, axis=0)[::2],
        "fortran": np.asfortranarray(base),
        "float32": base.astype(np.float32),
        "int64": base.astype(np.int64),
        "big-endian": base.astype(">f8"),
    }[layout]
    assert np.array_equal(Rotation.from_quat(x).as_quat(), Rotation.from_quat(base).as_quat())
    assert np.array_equal(Rotation.from_quat(base).apply(x[:, :3]), Rotation.from_quat(base).apply(base[:, :3]))


def test_the_first_bad_element_is_named_wherever_it_falls():
    for bad in ([N - 5], [N // 2 + 3, N - 2], [7, N - 2]):  # the last thread's part, then two parts
        q = Q.copy()
        for k in bad:
            q[k] = 0.0
        with pytest.raises(ValueError, match=rf"quat\[{bad[0]}\] has norm 0"):
            Rotation.from_quat(q)
    q = Q.copy()
    q[N - 3, 2] = np.inf
    q[N - 1, 0] = np.nan
    with pytest.raises(ValueError, match=rf"quat: element {4 * (N - 3) + 2} \(flat index\) is inf"):
        Rotation.from_quat(q)
    m = SR.from_quat(Q).as_matrix()
    m[N - 10] = -np.eye(3)
    with pytest.raises(ValueError, match=rf"matrix\[{N - 10}\] has determinant"):
        Rotation.from_matrix(m)
    v = V.copy()
    v[N - 1, 1] = np.nan
    with pytest.raises(ValueError, match=rf"vectors: element {3 * (N - 1) + 1} \(flat index\) is NaN"):
        Rotation.from_quat(Q).apply(v)


def test_gimbal_locks_are_found_in_every_thread_part():
    angles = SR.from_quat(Q).as_euler("ZYX")
    locked = [3, N // 2 - 1, N // 2 + 1, N - 1]
    angles[locked, 1] = np.pi / 2
    r = Rotation.from_euler("ZYX", angles)
    with pytest.raises(vectrix.GimbalLockError) as e:
        r.as_euler("ZYX", gimbal_lock="raise")
    assert e.value.indices == locked
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GimbalLockWarning)
        got = r.as_euler("ZYX")
    # at lock the representative (combination, π/2, 0) (F2.13.5: only the combination of the
    # first and last angle is determined), and it is the same rotation (scipy builds both)
    assert np.max(np.abs(got[locked, 1:] - [np.pi / 2, 0.0])) < 1e-7
    back, want = SR.from_euler("ZYX", got[locked]).as_matrix(), SR.from_euler("ZYX", angles[locked]).as_matrix()
    assert np.max(np.abs(back - want)) < 1e-7  # the lock's conditioning: √ε in the angles
    free = np.setdiff1d(np.arange(N), locked)
    assert np.max(np.abs(got[free] - angles[free])) < 1e-12


DATA = json.loads((Path(__file__).resolve().parents[2] / "tests/data/multibody_reference.json").read_text())


@pytest.mark.parametrize("name", list(DATA["models"]))
def test_threaded_multibody_batches_match_pinocchio(name):
    m = vectrix.Model.from_links(DATA["models"][name]["links"], gravity=DATA["gravity"])
    cases = DATA["models"][name]["cases"]
    reps = 1000 // len(cases) + 1  # ≥ 1000 states: above the 256 from which every core works
    q = np.tile([c["q"] for c in cases], (reps, 1))
    v = np.asfortranarray(np.tile([c["v"] for c in cases], (reps, 1)))
    tau = np.tile([c["tau"] for c in cases], (reps, 1))
    want = np.tile([c["aba_vdot"] for c in cases], (reps, 1))
    got = m.aba(q, v, tau)
    assert np.max(np.abs(got - want)) / max(1.0, np.max(np.abs(want))) < 1e-10
    a = np.tile([c["a"] for c in cases], (reps, 1))
    want = np.tile([c["rnea_tau"] for c in cases], (reps, 1))
    assert np.max(np.abs(m.rnea(q, v, a) - want)) / max(1.0, np.max(np.abs(want))) < 1e-12
    # a bad state late in the batch (the last thread's part) is named
    tau[len(tau) - 2, 0] = np.nan
    with pytest.raises(ValueError, match=rf"tau: element {(len(tau) - 2) * m.nv} \(flat index\) is NaN"):
        m.aba(q, v, tau)


def test_a_bad_ball_quaternion_is_named_by_its_state():
    """The tree's ball joints need a quaternion of norm ≥ 1e-6 (Model::aba's own check)."""
    tree = DATA["models"]["tree"]
    m = vectrix.Model.from_links(tree["links"], gravity=DATA["gravity"])
    c = tree["cases"][0]
    q = np.tile(c["q"], (600, 1))
    # q: free (position 0..3, quaternion 3..7), pin 7, sleeve 8, collar 9..11, slot 11..13, then
    # the first ball joint's quaternion 13..17
    ball = 13
    assert m.nq == 22 and abs(np.linalg.norm(q[0, ball:ball + 4]) - 1) < 1e-3
    q[450, ball:ball + 4] = 0.0
    q[590, ball:ball + 4] = 0.0
    with pytest.raises(ValueError, match=r"aba \(state 450\).*quaternion norm"):
        m.aba(q, np.tile(c["v"], (600, 1)), np.tile(c["tau"], (600, 1)))


SUMMARY = """
import hashlib, numpy as np, vectrix
q = np.random.default_rng(5).standard_normal((40_000, 4))
r = vectrix.Rotation.from_quat(q)
h = hashlib.sha256()
for x in (r.as_quat(), r.as_matrix(), r.as_euler("ZYX"), r.apply(q[:, :3])):
    h.update(np.ascontiguousarray(x).tobytes())
print(h.hexdigest())
"""


def run_with_threads(value):
    import os
    import subprocess
    import sys

    env = dict(os.environ, VECTRIX_NUM_THREADS=value)
    return subprocess.run([sys.executable, "-c", SUMMARY], env=env, capture_output=True, text=True, check=True)


def test_the_thread_count_changes_no_bit_and_a_bad_setting_is_named():
    one, three = run_with_threads("1"), run_with_threads("3")
    assert one.stdout == three.stdout and len(one.stdout.strip()) == 64
    bad = run_with_threads("two")
    assert bad.stdout == one.stdout  # ignored: every core, the same bits
    assert "VECTRIX_NUM_THREADS='two' is ignored" in bad.stderr and "positive integer" in bad.stderr
