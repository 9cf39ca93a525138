"""Linear systems (book ch. 15–16): transfer functions, state space, zeros–poles–gain,
margins, Bode, step, root locus, and conversion to and from python-control."""
from __future__ import annotations

import numpy as _np

from . import _vectrix as _v


class TransferFunction:
    """G(s) = num(s)/den(s)·e^{−s·delay}, coefficients in descending powers (book §15.18)."""

    def __init__(self, num, den, delay=0.0):
        _v._tf_roots(num, den)  # validates first (TypeError/ValueError naming num or den)
        self.num = _np.atleast_1d(_np.asarray(num, dtype=float))
        self.den = _np.atleast_1d(_np.asarray(den, dtype=float))
        self.delay = float(delay)
        if not (_np.isfinite(self.delay) and self.delay >= 0):
            raise ValueError(f"delay = {delay}; valid: a finite number >= 0 [s]")

    def poles(self):
        """Roots of den (book §15.18)."""
        (pr, pi), _ = _v._tf_roots(self.num, self.den)
        return _np.array(pr) + 1j * _np.array(pi)

    def zeros(self):
        """Roots of num (book §15.18)."""
        _, (zr, zi) = _v._tf_roots(self.num, self.den)
        return _np.array(zr) + 1j * _np.array(zi)

    def margins(self):
        return margins(self)

    def bode(self, omega):
        return bode(self, omega)

    def step(self, t):
        return step(self, t)

    def to_control(self):
        """A `control.TransferFunction` (delay refused: python-control has none)."""
        import control

        if self.delay:
            raise ValueError("delay: python-control transfer functions have no delay; valid: delay = 0")
        return control.tf(self.num, self.den)

    @classmethod
    def from_control(cls, sys):
        """From a SISO `control.TransferFunction` or `control.StateSpace`."""
        import control

        if isinstance(sys, control.StateSpace):
            return StateSpace(sys.A, sys.B, sys.C, sys.D).to_tf()
        if sys.ninputs != 1 or sys.noutputs != 1:
            raise ValueError("sys: valid: a SISO system")
        return cls(_np.asarray(sys.num[0][0], float), _np.asarray(sys.den[0][0], float))

    def __repr__(self):
        return f"TransferFunction(num={self.num.tolist()}, den={self.den.tolist()}, delay={self.delay})"


class StateSpace:
    """ẋ = Ax + Bu, y = Cx + Du (book §15.8)."""

    def __init__(self, A, B, C, D):
        _v._ss_to_tf(*(_np.atleast_2d(m) for m in (A, B, C, D)), 0, 0)  # validates shapes, dtypes, values
        self.A, self.B, self.C, self.D = (_np.atleast_2d(_np.asarray(m, dtype=float)) for m in (A, B, C, D))

    def to_tf(self, output=0, input=0):
        """The transfer function from `input` to `output` (book (15.8.1))."""
        n, d = _v._ss_to_tf(self.A, self.B, self.C, self.D, output, input)
        return TransferFunction(n, d)

    def poles(self):
        return _np.linalg.eigvals(self.A) if self.A.size else _np.zeros(0, complex)

    def step(self, t, input=0):
        """Step response of `input`: y (outputs, len t) (book §15.9)."""
        return _v._ss_step(self.A, self.B, self.C, self.D, t, input)

    def to_control(self):
        import control

        return control.ss(self.A, self.B, self.C, self.D)

    @classmethod
    def from_control(cls, sys):
        import control

        s = control.ss(sys)
        return cls(s.A, s.B, s.C, s.D)


def tf(num, den, delay=0.0):
    """A transfer function from descending coefficients (book §15.18)."""
    return TransferFunction(num, den, delay)


def ss(A, B, C, D):
    """A state-space system (book §15.8)."""
    return StateSpace(A, B, C, D)


def zpk(zeros, poles, gain, delay=0.0):
    """A transfer function from zeros, poles (complex ones in exact conjugate pairs) and gain."""
    n, d = _v._zpk_to_tf([complex(z) for z in zeros], [complex(p) for p in poles], float(gain))
    return TransferFunction(n, d, delay)


def _siso(sys):
    if isinstance(sys, TransferFunction):
        return sys
    if isinstance(sys, StateSpace):
        return sys.to_tf()
    try:
        return TransferFunction.from_control(sys)
    except ImportError:
        pass
    raise TypeError(f"sys: a {type(sys).__name__}; valid: TransferFunction, StateSpace or a python-control system")


def margins(sys):
    """Gain, phase and stability margins of the loop `sys` (book §16.3): a dict with
    python-control's names gm, pm, sm, wpc, wgc, wsm (gm = inf, w = nan when absent) plus
    gm_db and every crossover."""
    g = _siso(sys)
    return _v._tf_margins(g.num, g.den, g.delay)


def bode(sys, omega):
    """(magnitude |G(jω)|, phase [deg], complex G(jω)) at `omega` [rad/s] (book §16.2)."""
    g = _siso(sys)
    mag, ph, re, im = _v._tf_bode(g.num, g.den, omega, g.delay)
    return mag, ph, re + 1j * im


def step(sys, t):
    """Unit-step response y(t) on a uniform grid t from 0 (book §15.9)."""
    g = _siso(sys)
    return _v._tf_step(g.num, g.den, t, g.delay)


def root_locus(sys, k_max, max_step=None):
    """Roots of den + k·num for 0 ≤ k ≤ k_max: (gains (K,), roots (K, n) complex) (§15.18)."""
    g = _siso(sys)
    gains, branches = _v._root_locus(g.num, g.den, float(k_max), max_step)
    return gains, _np.array(branches, dtype=complex).T
