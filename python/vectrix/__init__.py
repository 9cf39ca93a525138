"""vectrix from Python: rotations, scenes, multibody dynamics and linear systems after
Bernstein, Goel and Ansari, *Geometry, Kinematics, Statics, and Dynamics*.

Numpy in and out; every loop runs in Rust with the GIL released. See docs/python.md.
"""
from __future__ import annotations

import json as _json
import os as _os
import warnings as _warnings

import numpy as _np

from . import _vectrix
from ._vectrix import (  # noqa: F401
    Cancel,
    GimbalLockError,
    GimbalLockWarning,
    Interrupted,
    Model as _Model,
    Rotation as _Rotation,
    Scene as _Scene,
    SceneError,
)
from .lti import (  # noqa: F401
    StateSpace,
    TransferFunction,
    bode,
    margins,
    root_locus,
    ss,
    step,
    tf,
    zpk,
)
from .sweep import sweep  # noqa: F401

__all__ = [
    "Rotation", "Slerp", "Scene", "Model", "SceneError", "GimbalLockError", "GimbalLockWarning",
    "Interrupted", "Cancel", "tf", "ss", "zpk", "margins", "bode", "step", "root_locus",
    "TransferFunction", "StateSpace", "sweep", "RunResult", "View",
]


_threads = _os.environ.get("VECTRIX_NUM_THREADS")
if _threads is not None and not (_threads.strip().isdigit() and int(_threads) > 0):
    _warnings.warn(f"VECTRIX_NUM_THREADS={_threads!r} is ignored (batches use every core); valid: a positive "
                   "integer, the threads vectrix's batches use", RuntimeWarning, stacklevel=2)

Rotation = _Rotation  # the Rust class itself; helpers below are attached to it


def _identity(num=None):
    """The identity rotation (or `num` of them)."""
    if num is None:
        return _Rotation.from_quat([0.0, 0.0, 0.0, 1.0])
    return _Rotation.from_quat(_np.tile([0.0, 0.0, 0.0, 1.0], (int(num), 1)))


def _random(num=None, rng=None):
    """Uniformly distributed rotations (normalised Gaussian quaternions), as scipy."""
    rng = _np.random.default_rng(rng)
    q = rng.standard_normal((1 if num is None else int(num), 4))
    r = _Rotation.from_quat(q)
    return r[0] if num is None else r


def _concatenate(rotations):
    """One stack of the given rotations (single or stacks)."""
    return _Rotation._concat([r if not r.single else r._as_single(False) for r in rotations])


def _as_euler_parameters(self):
    """The book's Euler parameters q = (η, ε₁, ε₂, ε₃), canonical η ≥ 0 (§2.15)."""
    return self.as_quat(canonical=True, scalar_first=True)


def _from_euler_parameters(q):
    """From the book's Euler parameters (η, ε) (§2.15), i.e. scalar first."""
    return _Rotation.from_quat(q, scalar_first=True)


def _pow(self, t):
    """The rotation scaled along its geodesic: angle vector times t (book §2.14)."""
    return _Rotation.from_rotvec(self.as_rotvec() * t)


_Rotation.identity = staticmethod(_identity)
_Rotation.random = staticmethod(_random)
_Rotation.concatenate = staticmethod(_concatenate)
_Rotation.as_euler_parameters = _as_euler_parameters
_Rotation.from_euler_parameters = staticmethod(_from_euler_parameters)
_Rotation.__pow__ = _pow


class Slerp:
    """Spherical linear interpolation between key rotations at increasing `times`, scipy's
    `Slerp` interface: `Slerp(times, rotations)(t)`. Book: §2.14 (geodesic exp(tΘ))."""

    def __init__(self, times, rotations):
        times = _np.asarray(times, dtype=float)
        if times.ndim != 1 or len(times) < 2:
            raise ValueError(f"times: shape {times.shape}; valid: (N,) with N >= 2")
        if not _np.all(_np.isfinite(times)) or not _np.all(_np.diff(times) > 0):
            raise ValueError("times: valid: finite and strictly increasing")
        if rotations.single or len(rotations) != len(times):
            raise ValueError("rotations: valid: a stack of as many rotations as times")
        self.times = times
        self.rotations = rotations
        self._delta = (rotations[:-1].inv() * rotations[1:]).as_rotvec()

    def __call__(self, times):
        t = _np.asarray(times, dtype=float)
        scalar = t.ndim == 0
        t = _np.atleast_1d(t)
        if not _np.all(_np.isfinite(t)) or t.min() < self.times[0] or t.max() > self.times[-1]:
            raise ValueError(f"times: valid: finite values in [{self.times[0]}, {self.times[-1]}]")
        k = _np.clip(_np.searchsorted(self.times, t, side="right") - 1, 0, len(self.times) - 2)
        alpha = (t - self.times[k]) / (self.times[k + 1] - self.times[k])
        r = self.rotations[k] * _Rotation.from_rotvec(self._delta[k] * alpha[:, None])
        return r[0] if scalar else r


class Scene:
    """A scene file (docs/scenes.md): `Scene.from_file(path)`, `Scene.from_toml(text)`,
    `.check()`, `.run(**overrides)`, `.linearize()`. Overrides are dotted paths of the file with
    `__` for the dots (`effects__0__k=3.0`) or a dict (`overrides={"effects.0.k": "2 lbf/ft"}`);
    values are numbers (SI) or quantity strings. Book: §4.11, §7.11."""

    def __init__(self, inner):
        self._s = inner

    @classmethod
    def from_file(cls, path):
        """Loads and validates a scene file; `SceneError` (file, line, col) when invalid."""
        return cls(_Scene.from_file(str(path)))

    @classmethod
    def from_toml(cls, text, file="<scene>"):
        """Loads and validates a scene from TOML text; `file` names it in errors."""
        return cls(_Scene.from_toml(text, file))

    @property
    def name(self):
        return self._s.name

    @property
    def text(self):
        return self._s.text

    @staticmethod
    def _overrides(overrides, kw):
        items = dict(overrides or {})
        for k, v in kw.items():
            items[k.replace("__", ".")] = v
        return list(items.items())

    def check(self, overrides=None, **kw):
        """Validates the scene with the given overrides without running it; returns True or
        raises `SceneError`."""
        self._s._check(self._overrides(overrides, kw))
        return True

    def run(self, overrides=None, *, cancel=None, **kw):
        """Runs the scene (GIL released) and returns a `RunResult`: `.t`, `.columns` (dict of
        numpy arrays), `.units`, `.summary` (dict: work, drift, stop, complete …) and
        `.frame()` (a pandas DataFrame when pandas is installed). Ctrl-C stops the run after
        the current step and raises `vectrix.Interrupted` (a KeyboardInterrupt) whose
        `.partial` is the RunResult of the rows computed; a set `cancel` flag stops it the same
        way and returns that RunResult (`summary["stop"]["reason"] == "interrupted"`)."""
        try:
            d = self._s._run(self._overrides(overrides, kw), cancel)
        except Interrupted as e:
            e.partial = RunResult(e.partial)
            raise
        return RunResult(d)

    def linearize(self, overrides=None, **kw):
        """Linearization about the initial state (book §12): a dict with numpy `A`, `B`, `C`,
        `D`, `eigenvalues` (complex), `modes` (list of dicts), state/input/output names."""
        lin = _json.loads(self._s._linearize(self._overrides(overrides, kw)))
        for k in ("A", "B", "C", "D"):
            lin[k] = _np.array(lin[k], dtype=float).reshape(len(lin[k]), -1) if lin[k] else _np.zeros((0, 0))
        ev = _np.array(lin["eigenvalues"], dtype=float).reshape(-1, 2)
        lin["eigenvalues"] = ev[:, 0] + 1j * ev[:, 1]
        return lin

    def model(self):
        """The multibody `Model` of the scene's bodies (book §7.11)."""
        return self._s.model()

    def initial_state(self):
        return self._s.initial_state()

    def __repr__(self):
        return repr(self._s)


class RunResult:
    """The outputs of a run: `t`, `columns` (name → numpy array), `units`, `summary`."""

    def __init__(self, d):
        self.t = d["t"]
        self.columns = d["columns"]
        self.units = d["units"]
        self.summary = _json.loads(d["summary_json"])
        self._view = d.get("view")

    @property
    def complete(self):
        return self.summary["complete"]

    def __getitem__(self, name):
        return self.t if name == "t" else self.columns[name]

    def frame(self):
        """The outputs as a pandas DataFrame indexed by t (ImportError without pandas)."""
        import pandas as pd

        return pd.DataFrame(self.columns, index=pd.Index(self.t, name="t"))

    def view(self, *, cancel=None):
        """The run's 3-D view (a `View`; a notebook cell ending with it shows it inline): the
        page `vectrix run` writes as view.html, made by the same code. It replays the scene once
        at the view's instants (at most 1001, and 40 000 poses), so it costs about one more run;
        a set `cancel` flag stops that replay early. Book: §7.11 (poses of the bodies)."""
        if self._view is None:
            raise ValueError("this run has no view source; valid: a RunResult from Scene.run")
        html, bound = self._view.page(cancel)
        return View(html, bound)


class View:
    """A run's self-contained 3-D view (issue 36): one HTML page with three.js inlined, the
    poses as JSON, no network. In Jupyter it shows inline (IPython calls `_repr_html_`: the
    page in a sandboxed `<iframe srcdoc=…>`, escaped, scripts allowed and nothing else);
    `.html` is the page, `.save(path)` writes it, `.bound` is the size bound it keeps."""

    def __init__(self, html, bound):
        self.html = html
        self.bound = bound

    def _repr_html_(self):
        return _vectrix.view_iframe(self.html)

    def save(self, path):
        """Writes the page to `path` (UTF-8): the same file as `vectrix run`'s view.html."""
        from pathlib import Path

        Path(path).write_text(self.html, encoding="utf-8")

    def __repr__(self):
        return f"<vectrix.View: {len(self.html)} bytes>"


Model = _Model


def _rnea_derivatives(self, q, v, a):
    """Exact ∂τ/∂q, ∂τ/∂v of RNEA and M (book §7.11): a dict of arrays, batched over states."""
    return _unpack(self._rnea_derivatives(q, v, a), self.nv, ("tau", "dtau_dq", "dtau_dv", "M"))


def _aba_derivatives(self, q, v, tau):
    """Exact ∂v̇/∂q, ∂v̇/∂v, ∂v̇/∂τ = M⁻¹ of ABA (book §7.11): a dict, batched over states."""
    return _unpack(self._aba_derivatives(q, v, tau), self.nv, ("vdot", "dvdot_dq", "dvdot_dv", "dvdot_dtau"))


def _unpack(x, nv, names):
    lead = x.shape[:-1]
    out = {names[0]: x[..., :nv]}
    for k, name in enumerate(names[1:]):
        s = nv + k * nv * nv
        out[name] = x[..., s:s + nv * nv].reshape(*lead, nv, nv)
    return out


def _from_scene(scene):
    """The model of a scene's bodies."""
    return scene.model()


_Model.rnea_derivatives = _rnea_derivatives
_Model.aba_derivatives = _aba_derivatives
_Model.from_scene = staticmethod(_from_scene)

_warnings.simplefilter("always", GimbalLockWarning)
