"""Linear systems against python-control (margins, responses) and closed forms. Book ch. 15–16."""
import control
import numpy as np
import pytest

import vectrix

LOOPS = [([1.0], [1.0, 2.0, 1.0, 0.0]), ([4.0, 2.0], [1.0, 3.0, 3.0, 1.0, 0.0]),
         ([10.0], [1.0, 6.0, 11.0, 6.0]), ([1.0, 5.0], [1.0, 1.0, 4.0, 0.5])]


@pytest.mark.parametrize("num,den", LOOPS)
def test_margins_match_python_control(num, den):
    gm, pm, sm, wpc, wgc, wsm = control.stability_margins(control.tf(num, den))
    m = vectrix.margins(vectrix.tf(num, den))
    # python-control refines crossovers from a frequency grid to ~1e-9 relative
    for mine, theirs in ((m["gm"], gm), (m["pm"], pm), (m["sm"], sm), (m["wpc"], wpc), (m["wgc"], wgc)):
        if np.isinf(theirs) or np.isnan(theirs):
            assert np.isinf(mine) or np.isnan(mine)
        else:
            assert abs(mine - theirs) <= 1e-6 * max(1.0, abs(theirs))


def test_closed_form_margins():
    """L = 1/(s(s+1)²): phase crossover at ω = 1 with |L| = 1/2, so GM = 2 exactly (§16.3)."""
    m = vectrix.margins(vectrix.tf([1.0], [1.0, 2.0, 1.0, 0.0]))
    assert abs(m["wpc"] - 1.0) < 1e-14 and abs(m["gm"] - 2.0) < 1e-13


def test_step_and_bode_match_python_control():
    num, den = [2.0, 1.0], [1.0, 0.8, 4.0]
    t = np.linspace(0, 10, 501)
    y = vectrix.step(vectrix.tf(num, den), t)
    yc = control.step_response(control.tf(num, den), t).outputs
    assert np.max(np.abs(y - yc)) < 1e-9
    # closed form of a first-order lag: 1 − e^{−t}
    assert np.max(np.abs(vectrix.step(vectrix.tf([1.0], [1.0, 1.0]), t) - (1 - np.exp(-t)))) < 1e-13
    w = np.logspace(-2, 2, 200)
    mag, ph, g = vectrix.bode(vectrix.tf(num, den), w)
    gc = control.tf(num, den)(1j * w)
    assert np.max(np.abs(g - gc) / np.abs(gc)) < 1e-13
    assert np.max(np.abs(mag - np.abs(gc)) / np.abs(gc)) < 1e-13


def test_conversions_to_and_from_python_control():
    g = vectrix.tf([1.0, 2.0], [1.0, 3.0, 5.0])
    c = g.to_control()
    assert isinstance(c, control.TransferFunction)
    back = vectrix.TransferFunction.from_control(control.ss(c))
    w = np.logspace(-1, 1, 20)
    assert np.max(np.abs(vectrix.bode(back, w)[2] - c(1j * w))) < 1e-13
    s = vectrix.ss([[0, 1], [-5, -3]], [[0], [1]], [[2, 1]], [[0]])
    assert np.max(np.abs(s.to_tf().bode(w)[2] - c(1j * w))) < 1e-13
    assert isinstance(s.to_control(), control.StateSpace)
    z = vectrix.zpk([-2], [-1 + 2j, -1 - 2j], 1.0)
    assert np.allclose(z.den, [1, 2, 5], rtol=0, atol=1e-15) and np.allclose(z.num, [1, 2], rtol=0, atol=1e-15)
    y = s.step(np.linspace(0, 5, 11))
    assert y.shape == (1, 11)


def test_root_locus_endpoints():
    """1 + k/((s+1)(s+2)): roots −1.5 ± j√(k − 1/4) for k > 1/4 (§15.18)."""
    gains, roots = vectrix.root_locus(vectrix.tf([1.0], [1.0, 3.0, 2.0]), 10.0)
    k = gains[-1]
    want = sorted([-1.5 + 1j * np.sqrt(k - 0.25), -1.5 - 1j * np.sqrt(k - 0.25)], key=lambda z: z.imag)
    got = sorted(roots[-1], key=lambda z: z.imag)
    assert np.max(np.abs(np.array(got) - want)) < 1e-12


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="den"):
        vectrix.tf([1.0], [0.0])
    with pytest.raises(ValueError, match="num"):
        vectrix.tf([np.nan], [1.0])
    with pytest.raises(TypeError, match="num"):
        vectrix.tf(["a"], [1.0])
    with pytest.raises(ValueError, match="delay"):
        vectrix.tf([1.0], [1.0, 1.0], delay=-1)
