"""Type stubs of vectrix (issue 37). Book: Bernstein, Goel, Ansari, *Geometry, Kinematics,
Statics, and Dynamics*; the sections are cited on each item."""
from typing import Any, Literal, Mapping, Sequence

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
F64 = npt.NDArray[np.float64]
GimbalLockMode = Literal["warn", "raise", "ignore"]

MAX_ELEMENTS: int

class SceneError(ValueError):
    """A scene that cannot be loaded, built or run (docs/scenes.md)."""
    file: str | None
    line: int | None
    col: int | None
    path: str | None
    t: float | None

class GimbalLockError(ValueError):
    """Euler angles at gimbal lock (book F2.13.5, F2.13.8); `indices` lists the elements."""
    indices: list[int]

class GimbalLockWarning(UserWarning):
    """Euler angles returned at gimbal lock as (combination, β, 0) (book F2.13.5)."""

class Interrupted(KeyboardInterrupt): ...

class Cancel:
    """A flag that stops the runs holding it after their current step."""
    def __init__(self) -> None: ...
    def set(self) -> None: ...
    def is_set(self) -> bool: ...

class Rotation:
    """One or many rotations as unit Euler parameters (book §2.15); scipy's
    `spatial.transform.Rotation` subset. Quaternions are scalar last unless `scalar_first`."""
    @property
    def single(self) -> bool: ...
    @staticmethod
    def from_quat(quat: ArrayLike, *, scalar_first: bool = False) -> Rotation:
        """From quaternions (4,) or (N, 4), normalised (book (2.15.20))."""
    def as_quat(self, canonical: bool = False, *, scalar_first: bool = False) -> F64:
        """Quaternions; `canonical` gives η ≥ 0 (book §2.15)."""
    @staticmethod
    def from_matrix(matrix: ArrayLike) -> Rotation:
        """From rotation matrices, projected to the nearest rotation; det ≤ 0 refused (§2.10)."""
    def as_matrix(self) -> F64:
        """Active rotation matrices 𝓡(q) (book (2.15.14))."""
    @staticmethod
    def from_rotvec(rotvec: ArrayLike, degrees: bool = False) -> Rotation:
        """From angle vectors θn̂ (book §2.14, (2.14.5))."""
    def as_rotvec(self, degrees: bool = False) -> F64:
        """Angle vectors with θ ∈ [0, π] (book §2.14)."""
    @staticmethod
    def from_mrp(mrp: ArrayLike) -> Rotation:
        """From modified Rodrigues parameters tan(θ/4)n̂ (extends book §2.17)."""
    def as_mrp(self) -> F64: ...
    @staticmethod
    def from_gibbs(gibbs: ArrayLike) -> Rotation:
        """From Gibbs vectors tan(θ/2)n̂ (book §2.17)."""
    def as_gibbs(self) -> F64:
        """Gibbs vectors; a half turn is a ValueError (book §2.17)."""
    @staticmethod
    def from_euler(seq: str, angles: ArrayLike, degrees: bool = False) -> Rotation:
        """Upper-case seq intrinsic, lower-case extrinsic, 12 sequences each (book §2.12)."""
    def as_euler(self, seq: str, degrees: bool = False, gimbal_lock: GimbalLockMode = "warn") -> F64:
        """Principal Euler angles; at lock (combination, β, 0) and a typed warning/error (§2.13)."""
    def gimbal_locks(self, seq: str) -> list[tuple[int, float, float, int]]:
        """(index, β, α + sign·γ, sign) of the locked elements (book F2.13.5)."""
    @staticmethod
    def from_davenport(axes: ArrayLike, order: str, angles: ArrayLike, degrees: bool = False) -> Rotation:
        """About three axes, the middle ⊥ the others; order 'e' or 'i' (book §2.12)."""
    def as_davenport(self, axes: ArrayLike, order: str, degrees: bool = False,
                     gimbal_lock: GimbalLockMode = "warn") -> F64: ...
    @staticmethod
    def from_euler_parameters(q: ArrayLike) -> Rotation:
        """From the book's Euler parameters (η, ε) (§2.15)."""
    def as_euler_parameters(self) -> F64:
        """The book's Euler parameters (η, ε), η ≥ 0 (§2.15)."""
    def apply(self, vectors: ArrayLike, inverse: bool = False) -> F64:
        """𝓡(q)x, or 𝓡ᵀx with `inverse` (book Prob 2.26.23)."""
    def __mul__(self, other: Rotation) -> Rotation:
        """Composition: `other` first, then `self` (book F2.15.7)."""
    def __pow__(self, t: float) -> Rotation: ...
    def inv(self) -> Rotation:
        """Inverse rotations (book Fact 2.15.6)."""
    def magnitude(self) -> F64 | float:
        """Rotation angles in [0, π] (book §2.14)."""
    def mean(self, weights: ArrayLike | None = None) -> Rotation:
        """Chordal L2 mean (Markley et al. 2007)."""
    @staticmethod
    def align_vectors(a: ArrayLike, b: ArrayLike, weights: ArrayLike | None = None) -> tuple[Rotation, float]:
        """C minimising Σw|a − Cb|², and the rssd (Wahba's problem; Kabsch 1976)."""
    def slerp(self, other: Rotation, t: float) -> Rotation:
        """Geodesic interpolation (book §2.14)."""
    @staticmethod
    def identity(num: int | None = None) -> Rotation: ...
    @staticmethod
    def random(num: int | None = None, rng: Any = None) -> Rotation: ...
    @staticmethod
    def concatenate(rotations: Sequence[Rotation]) -> Rotation: ...
    def __len__(self) -> int: ...
    def __getitem__(self, key: Any) -> Rotation: ...

class Slerp:
    """scipy-style interpolation between key rotations (book §2.14)."""
    times: F64
    rotations: Rotation
    def __init__(self, times: ArrayLike, rotations: Rotation) -> None: ...
    def __call__(self, times: ArrayLike) -> Rotation: ...

class RunResult:
    """A run's outputs (book §4.11): t, columns, units, summary."""
    t: F64
    columns: dict[str, F64]
    units: dict[str, str]
    summary: dict[str, Any]
    @property
    def complete(self) -> bool: ...
    def __getitem__(self, name: str) -> F64: ...
    def frame(self) -> Any:
        """A pandas DataFrame indexed by t."""
    def view(self, *, cancel: Cancel | None = None) -> View:
        """The run's self-contained 3-D view (view.html of `vectrix run`; book §7.11)."""

class View:
    """A run's 3-D view page: shown inline in Jupyter (`_repr_html_`, a sandboxed iframe)."""
    html: str
    bound: int
    def _repr_html_(self) -> str: ...
    def save(self, path: Any) -> None: ...

class Scene:
    """A scene file (docs/scenes.md; book §4.11, §7.11)."""
    @classmethod
    def from_file(cls, path: Any) -> Scene: ...
    @classmethod
    def from_toml(cls, text: str, file: str = "<scene>") -> Scene: ...
    @property
    def name(self) -> str: ...
    @property
    def text(self) -> str: ...
    def check(self, overrides: Mapping[str, float | str] | None = None, **kw: float | str) -> bool: ...
    def run(self, overrides: Mapping[str, float | str] | None = None, *, cancel: Cancel | None = None,
            **kw: float | str) -> RunResult: ...
    def linearize(self, overrides: Mapping[str, float | str] | None = None, **kw: float | str) -> dict[str, Any]:
        """A, B, C, D, eigenvalues and modes about the initial state (book §12)."""
    def model(self) -> Model: ...
    def initial_state(self) -> F64: ...

class Model:
    """A kinematic tree in reduced coordinates (book §7.11)."""
    @staticmethod
    def from_links(links: Sequence[Mapping[str, Any]], gravity: ArrayLike | None = None) -> Model: ...
    @staticmethod
    def revolute_chain(n: int, m: float, l: float) -> Model: ...
    @staticmethod
    def from_scene(scene: Scene) -> Model: ...
    @property
    def nq(self) -> int: ...
    @property
    def nv(self) -> int: ...
    @property
    def gravity(self) -> list[float]: ...
    def neutral(self) -> F64: ...
    def rnea(self, q: ArrayLike, v: ArrayLike, a: ArrayLike) -> F64:
        """τ = RNEA(q, v, v̇), batched over leading axis (book (7.11.13)–(7.11.22))."""
    def aba(self, q: ArrayLike, v: ArrayLike, tau: ArrayLike) -> F64:
        """v̇ = ABA(q, v, τ), batched (book §7.11)."""
    def crba(self, q: ArrayLike) -> F64:
        """M(q), batched (book §7.11)."""
    def rnea_derivatives(self, q: ArrayLike, v: ArrayLike, a: ArrayLike) -> dict[str, F64]: ...
    def aba_derivatives(self, q: ArrayLike, v: ArrayLike, tau: ArrayLike) -> dict[str, F64]: ...

class TransferFunction:
    """num/den·e^{−s·delay}, descending coefficients (book §15.18)."""
    num: F64
    den: F64
    delay: float
    def __init__(self, num: ArrayLike, den: ArrayLike, delay: float = 0.0) -> None: ...
    def poles(self) -> npt.NDArray[np.complex128]: ...
    def zeros(self) -> npt.NDArray[np.complex128]: ...
    def margins(self) -> dict[str, Any]: ...
    def bode(self, omega: ArrayLike) -> tuple[F64, F64, npt.NDArray[np.complex128]]: ...
    def step(self, t: ArrayLike) -> F64: ...
    def to_control(self) -> Any: ...
    @classmethod
    def from_control(cls, sys: Any) -> TransferFunction: ...

class StateSpace:
    """ẋ = Ax + Bu, y = Cx + Du (book §15.8)."""
    A: F64
    B: F64
    C: F64
    D: F64
    def __init__(self, A: ArrayLike, B: ArrayLike, C: ArrayLike, D: ArrayLike) -> None: ...
    def to_tf(self, output: int = 0, input: int = 0) -> TransferFunction: ...
    def poles(self) -> npt.NDArray[np.complex128]: ...
    def step(self, t: ArrayLike, input: int = 0) -> F64: ...
    def to_control(self) -> Any: ...
    @classmethod
    def from_control(cls, sys: Any) -> StateSpace: ...

def tf(num: ArrayLike, den: ArrayLike, delay: float = 0.0) -> TransferFunction: ...
def ss(A: ArrayLike, B: ArrayLike, C: ArrayLike, D: ArrayLike) -> StateSpace: ...
def zpk(zeros: Sequence[complex], poles: Sequence[complex], gain: float, delay: float = 0.0) -> TransferFunction: ...
def margins(sys: Any) -> dict[str, Any]:
    """gm, pm, sm, wpc, wgc, wsm (python-control's names), gm_db, every crossover (book §16.3)."""
def bode(sys: Any, omega: ArrayLike) -> tuple[F64, F64, npt.NDArray[np.complex128]]:
    """|G(jω)|, phase [deg], G(jω) (book §16.2)."""
def step(sys: Any, t: ArrayLike) -> F64:
    """Unit-step response on a uniform grid from 0 (book §15.9)."""
def root_locus(sys: Any, k_max: float, max_step: float | None = None) -> tuple[F64, npt.NDArray[np.complex128]]:
    """Gains and roots of den + k·num (book §15.18)."""

class SweepResult:
    params: list[str]
    labels: list[dict[str, Any]]
    runs: list[dict[str, Any] | None]
    table: list[dict[str, Any]]
    interrupted: bool
    def frame(self) -> Any: ...

def sweep(scene: Scene, params: Mapping[str, Any], client: Any = None, max_workers: int | None = None) -> SweepResult:
    """Runs of the Cartesian product of `params`, on local threads or Dask tasks."""
