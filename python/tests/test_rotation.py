"""vectrix.Rotation against scipy.spatial.transform.Rotation (an independent implementation)
on random and hard sets, and hypothesis round trips. Book §2.9–2.17."""
import itertools
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation as SR
from scipy.spatial.transform import Slerp as SSlerp

import vectrix
from vectrix import GimbalLockError, GimbalLockWarning, Rotation, Slerp

RNG = np.random.default_rng(20261204)
Q = RNG.standard_normal((2000, 4))
SEQS = ["".join(p) for p in itertools.product("xyz", repeat=3) if p[0] != p[1] and p[1] != p[2]]
assert len(SEQS) == 12


def same_rotation(qa, qb):
    """max over elements of min(|qa − qb|, |qa + qb|): q and −q are one rotation."""
    d = np.minimum(np.abs(qa - qb).max(axis=-1), np.abs(qa + qb).max(axis=-1))
    return np.max(d)  # NaN propagates: a NaN fails every `<` below


def test_quat_matrix_rotvec_mrp_match_scipy_on_random_rotations():
    r, s = Rotation.from_quat(Q), SR.from_quat(Q)
    assert same_rotation(r.as_quat(), s.as_quat()) < 1e-15
    # 4 ulp-scale: both form 𝓡(q) by the same polynomial (2.15.14), differently rounded
    assert np.max(np.abs(r.as_matrix() - s.as_matrix())) < 4e-16 * 4
    assert np.max(np.abs(r.as_rotvec() - s.as_rotvec())) < 1e-14
    assert np.max(np.abs(r.as_mrp() - s.as_mrp())) < 1e-15
    m = s.as_matrix()
    assert same_rotation(Rotation.from_matrix(m).as_quat(), s.as_quat()) < 1e-15
    rv = s.as_rotvec()
    assert same_rotation(Rotation.from_rotvec(rv).as_quat(), s.as_quat()) < 1e-15
    assert same_rotation(Rotation.from_mrp(s.as_mrp()).as_quat(), s.as_quat()) < 1e-15
    assert same_rotation(Rotation.from_quat(Q[:, [3, 0, 1, 2]], scalar_first=True).as_quat(), s.as_quat()) < 1e-15


@pytest.mark.parametrize("seq", SEQS + [x.upper() for x in SEQS])
def test_euler_all_24_conventions_match_scipy(seq):
    s = SR.from_quat(Q)
    ang = s.as_euler(seq)
    r = Rotation.from_euler(seq, ang)
    assert same_rotation(r.as_quat(), s.as_quat()) < 1e-14
    got = Rotation.from_quat(Q).as_euler(seq)
    # random rotations are far from gimbal lock: the principal solutions coincide
    assert np.max(np.abs(got - ang)) < 1e-13
    assert np.allclose(Rotation.from_euler(seq, ang[0], degrees=False).as_matrix(), s[0].as_matrix(), atol=1e-15, rtol=0)


def test_degrees():
    a = np.array([30.0, 20.0, 10.0])
    assert np.max(np.abs(Rotation.from_euler("ZYX", a, degrees=True).as_matrix()
                         - SR.from_euler("ZYX", a, degrees=True).as_matrix())) < 1e-15
    assert np.max(np.abs(Rotation.from_rotvec([0, 0, 90], degrees=True).as_rotvec(degrees=True) - [0, 0, 90])) < 1e-13


@pytest.mark.parametrize("seq", ["ZYX", "xyz", "ZXZ", "yxy"])
def test_gimbal_lock_is_typed_and_the_rotation_is_kept(seq):
    """At β = ±π/2 (Tait–Bryan) or β ∈ {0, π} (symmetric) only α ± γ is determined (F2.13.5).
    scipy warns with a plain UserWarning and sets the third angle to 0; vectrix warns with
    GimbalLockWarning (or raises GimbalLockError on request) and its representative
    reproduces the rotation exactly where scipy's differs by round-off."""
    sym = seq[0].lower() == seq[2].lower()
    betas = [0.0, np.pi] if sym else [np.pi / 2, -np.pi / 2]
    ang = np.array([[0.7, b, -0.4] for b in betas])
    r = Rotation.from_euler(seq, ang)
    with pytest.warns(GimbalLockWarning):
        e = r.as_euler(seq)
    with pytest.raises(GimbalLockError) as ex:
        r.as_euler(seq, gimbal_lock="raise")
    assert ex.value.indices == [0, 1]
    assert np.allclose(e[:, 2], 0.0, atol=0)
    back = Rotation.from_euler(seq, e)
    assert np.max(np.abs(back.as_matrix() - r.as_matrix())) < 1e-15 * 8
    locks = r.gimbal_locks(seq)
    assert [k for k, *_ in locks] == [0, 1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        se = SR.from_quat(r.as_quat()).as_euler(seq)
    # scipy's own representative is the same rotation (to its round-off) ...
    assert np.max(np.abs(SR.from_euler(seq, se).as_matrix() - r.as_matrix())) < 1e-7


def test_near_half_turn_rotvec_matches_scipy():
    """θ = π − δ for δ down to 1e-15 and exactly π: the angle vector, where θ/(2 sin θ) is
    singular (notes ch2b §3.5); both follow the quaternion route."""
    axes = RNG.standard_normal((200, 3))
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    d = np.logspace(-15, -3, 200)
    rv = axes * (np.pi - d)[:, None]
    r, s = Rotation.from_rotvec(rv), SR.from_rotvec(rv)
    assert same_rotation(r.as_quat(), s.as_quat()) < 1e-15
    got = r.as_rotvec()
    assert np.max(np.abs(got - rv)) < 1e-14
    assert np.max(np.abs(r.magnitude() - s.magnitude())) < 1e-15


def test_apply_composition_inverse_magnitude():
    r, s = Rotation.from_quat(Q[:500]), SR.from_quat(Q[:500])
    v = RNG.standard_normal((500, 3))
    assert np.max(np.abs(r.apply(v) - s.apply(v))) < 1e-14
    assert np.max(np.abs(r.apply(v, inverse=True) - s.apply(v, inverse=True))) < 1e-14
    assert np.max(np.abs(r[0].apply(v) - s[0].apply(v))) < 1e-14
    assert np.max(np.abs(r.apply(v[0]) - s.apply(v[0]))) < 1e-14
    p, ps = Rotation.from_quat(Q[500:1000]), SR.from_quat(Q[500:1000])
    assert same_rotation((r * p).as_quat(), (s * ps).as_quat()) < 1e-15
    assert same_rotation(r.inv().as_quat(), s.inv().as_quat()) < 1e-15
    assert np.max(np.abs(r.magnitude() - s.magnitude())) < 1e-14
    assert r.apply([1.0, 0, 0]).shape == (500, 3)
    assert r[0].apply([1.0, 0, 0]).shape == (3,)
    assert len(r[10:20]) == 10 and len(r[[1, 2, 3]]) == 3


def test_mean_align_vectors_slerp_match_scipy():
    r, s = Rotation.from_quat(Q[:50]), SR.from_quat(Q[:50])
    w = RNG.uniform(0.1, 1.0, 50)
    assert same_rotation(r.mean(w).as_quat(), s.mean(w).as_quat()) < 1e-13
    a = RNG.standard_normal((20, 3))
    true = SR.from_quat(Q[0])
    b = true.inv().apply(a) + 1e-3 * RNG.standard_normal((20, 3))
    got, rssd = Rotation.align_vectors(a, b)
    want, wrssd = SR.align_vectors(a, b)
    assert same_rotation(got.as_quat(), want.as_quat()) < 1e-12
    # the rssd of scipy's rotation, summed directly; scipy's own figure comes from
    # sqrt(Σw(|a|² + |b|²) − 2 tr S), which cancels: it is off by ~1e-10 relative here
    direct = np.sqrt(np.sum((a - want.apply(b)) ** 2))
    assert abs(rssd - direct) < 1e-13 * direct
    assert abs(rssd - wrssd) < 1e-8 * wrssd
    one, _ = Rotation.align_vectors([[0, 0, 1.0]], [[1.0, 0, 0]])
    assert np.max(np.abs(one.apply([1.0, 0, 0]) - [0, 0, 1])) < 1e-15
    times = [0.0, 1.0, 3.0]
    key = SR.from_quat(Q[:3])
    t = np.linspace(0, 3, 31)
    mine = Slerp(times, Rotation.from_quat(Q[:3]))(t)
    assert same_rotation(mine.as_quat(), SSlerp(times, key)(t).as_quat()) < 1e-14
    half = Rotation.from_quat(Q[0]).slerp(Rotation.from_quat(Q[1]), 0.5)
    assert same_rotation(half.as_quat(), SSlerp([0, 1], key[:2])(0.5).as_quat()) < 1e-14


def test_davenport_matches_scipy():
    axes = SR.from_quat(Q[5]).as_matrix()  # orthonormal rows: every neighbour perpendicular
    axes = np.array([axes[0], axes[1], axes[0]])
    for order in ("e", "i"):
        ang = RNG.uniform(-1, 1, (100, 3))
        mine = Rotation.from_davenport(axes, order, ang)
        want = SR.from_davenport(axes, order, ang)
        assert same_rotation(mine.as_quat(), want.as_quat()) < 1e-14
        got = mine.as_davenport(axes, order)
        assert same_rotation(Rotation.from_davenport(axes, order, got).as_quat(), want.as_quat()) < 1e-13
        assert np.max(np.abs(got - want.as_davenport(axes, order))) < 1e-12


def test_gibbs_and_euler_parameters():
    """Gibbs vector g = tan(θ/2)n̂ (§2.17) from scipy's rotvec; Euler parameters (η, ε)."""
    s = SR.from_quat(Q[:100])
    rv = s.as_rotvec()
    th = np.linalg.norm(rv, axis=1)
    g = rv / th[:, None] * np.tan(th / 2)[:, None]
    r = Rotation.from_quat(Q[:100])
    assert np.max(np.abs(r.as_gibbs() - g) / (1 + np.abs(g))) < 1e-12
    assert same_rotation(Rotation.from_gibbs(g).as_quat(), s.as_quat()) < 1e-14
    ep = r.as_euler_parameters()
    assert np.all(ep[:, 0] >= 0)
    assert same_rotation(Rotation.from_euler_parameters(ep).as_quat(), s.as_quat()) < 1e-15
    with pytest.raises(ValueError, match="half turn"):
        Rotation.from_rotvec([np.pi, 0, 0]).as_gibbs()


finite = st.floats(-1e3, 1e3, allow_nan=False)


@settings(max_examples=200, deadline=None)
@given(st.lists(finite, min_size=4, max_size=4).filter(lambda q: np.linalg.norm(q) > 1e-3),
       st.sampled_from(SEQS + [x.upper() for x in SEQS]))
def test_round_trips(q, seq):
    r = Rotation.from_quat(q)
    for back in (Rotation.from_matrix(r.as_matrix()), Rotation.from_rotvec(r.as_rotvec()),
                 Rotation.from_mrp(r.as_mrp()), r.inv().inv()):
        assert same_rotation(back.as_quat(), r.as_quat()) < 1e-14
    e = r.as_euler(seq, gimbal_lock="ignore")
    assert same_rotation(Rotation.from_euler(seq, e).as_quat(), r.as_quat()) < 1e-12
