"""Hostile inputs: every call answers with a ValueError/TypeError naming the argument, never a
Rust panic (pyo3's PanicException) or a crash."""
import numpy as np
import pytest

import vectrix
from vectrix import Rotation

BAD = [np.nan, np.inf, -np.inf, 1e308, -1e308, 5e-324, 0.0, "x", None, [], [[]], np.zeros((0, 4)),
       np.zeros((2, 2, 2, 2)), np.array([1 + 1j] * 4), np.array([True] * 4), np.zeros(4)[::2],
       np.zeros((5, 4))[:, ::1].T, object()]


def calls():
    r = Rotation.from_quat(np.random.default_rng(1).standard_normal((3, 4)))
    m = vectrix.Model.revolute_chain(3, 1.0, 1.0)
    return [
        Rotation.from_quat, Rotation.from_matrix, Rotation.from_rotvec, Rotation.from_mrp, Rotation.from_gibbs,
        lambda x: Rotation.from_euler("ZYX", x), lambda x: Rotation.from_euler(x, [0, 0, 0]),
        r.apply, lambda x: r.as_euler(x), lambda x: r.mean(x), lambda x: Rotation.align_vectors(x, x),
        lambda x: Rotation.from_davenport(x, "e", [0, 0, 0]), lambda x: r[x],
        lambda x: m.aba(x, np.zeros(3), np.zeros(3)), lambda x: m.rnea(np.zeros(3), x, np.zeros(3)), m.crba,
        lambda x: vectrix.tf(x, [1.0, 1.0]), lambda x: vectrix.bode(vectrix.tf([1.0], [1.0, 1.0]), x),
        lambda x: vectrix.step(vectrix.tf([1.0], [1.0, 1.0]), x), lambda x: vectrix.Scene.from_toml(x),
    ]


def test_no_panic_reaches_python():
    n = 0
    for f in calls():
        for x in BAD:
            try:
                f(x)
            except (ValueError, TypeError, IndexError, OverflowError):
                n += 1
            except BaseException as e:  # noqa: BLE001 - the point of the test
                pytest.fail(f"{type(e).__name__} from {f} on {x!r}: {e}")
    assert n > 0


def test_messages_name_argument_and_range():
    with pytest.raises(ValueError, match=r"quat: shape \(3,\); valid: \(4,\) or \(N, 4\)"):
        Rotation.from_quat([1.0, 0.0, 0.0])
    with pytest.raises(TypeError, match="quat: dtype complex128; valid: real numbers"):
        Rotation.from_quat(np.ones(4, complex))
    with pytest.raises(ValueError, match="quat: element 1 .* is NaN; valid: finite numbers"):
        Rotation.from_quat([0.0, np.nan, 0.0, 1.0])
    with pytest.raises(ValueError, match=r"quat\[0\] has norm 0"):
        Rotation.from_quat([0.0, 0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="seq"):
        Rotation.from_euler("XyZ", [0, 0, 0])
    with pytest.raises(ValueError, match="determinant"):
        Rotation.from_matrix(-np.eye(3))
    # a non-contiguous view is read correctly (copied once), not refused or misread
    q = np.random.default_rng(2).standard_normal((8, 4))
    assert np.array_equal(Rotation.from_quat(q[::2]).as_quat(), Rotation.from_quat(q[::2].copy()).as_quat())
