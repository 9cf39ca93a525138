"""Scenes from Python against closed forms (book §4.11, §7.11, §12)."""
import numpy as np
import pytest

import vectrix

OSC = """
name = "osc"
duration = 2.0
samples = 20
accuracy = 1e-10
outputs = ["coordinates:c"]

[[bodies]]
name = "c"
joint = { type = "sleeve", axis = [1.0, 0.0, 0.0] }
mass = { shape = "particle", mass = 2.0 }
q = [1.5]

[[effects]]
type = "spring"
a = { body = "ground" }
b = { body = "c" }
k = 50.0
length = 1.0
"""


def test_undamped_oscillator_matches_the_closed_form():
    """m ẍ = −k(x − L): x = L + (x₀ − L) cos(√(k/m) t)."""
    s = vectrix.Scene.from_toml(OSC)
    assert s.check() and s.name == "osc"
    r = s.run()
    x = r.columns["coordinates:c.0"]
    assert r.units["coordinates:c.0"] == "m"
    assert r.complete and r.summary["stop"] is None
    assert np.max(np.abs(x - (1 + 0.5 * np.cos(5.0 * r.t)))) < 1e-8
    df = r.frame()
    assert list(df.columns) == ["coordinates:c.0"] and df.index.name == "t"


def test_overrides_numbers_and_quantity_strings():
    s = vectrix.Scene.from_toml(OSC)
    r = s.run(effects__0__k="200 N/m", duration="1 s")
    assert abs(r.t[-1] - 1.0) < 1e-15
    assert np.max(np.abs(r["coordinates:c.0"] - (1 + 0.5 * np.cos(10.0 * r.t)))) < 1e-8
    r2 = s.run({"bodies.0.mass.mass": 8.0})
    assert np.max(np.abs(r2["coordinates:c.0"] - (1 + 0.5 * np.cos(2.5 * r2.t)))) < 1e-8
    r3 = s.run(effects__0__k="0.3426 lbf/in")  # 0.3426 lbf/in = 59.99… N/m
    k = 0.3426 * 4.4482216152605 / 0.0254
    assert np.max(np.abs(r3["coordinates:c.0"] - (1 + 0.5 * np.cos(np.sqrt(k / 2) * r3.t)))) < 1e-8


def test_linearize_gives_the_oscillator_modes():
    """About x = L: A = [[0, 1], [−k/m, 0]], eigenvalues ±j√(k/m) (§12)."""
    lin = vectrix.Scene.from_toml(OSC).linearize(bodies__0__q__0=1.0)
    assert lin["A"].shape == (2, 2)
    assert np.max(np.abs(lin["A"] - [[0, 1], [-25, 0]])) < 1e-12
    ev = np.sort_complex(lin["eigenvalues"])
    assert np.max(np.abs(ev - [-5j, 5j])) < 1e-12
    assert abs(lin["modes"][0]["natural_frequency"] - 5.0) < 1e-12


def test_scene_errors_carry_file_line_col(tmp_path):
    bad = OSC.replace("k = 50.0", "k = -5.0")
    with pytest.raises(vectrix.SceneError) as e:
        vectrix.Scene.from_toml(bad, "osc.toml")
    assert (e.value.file, e.value.line, e.value.col, e.value.path) == ("osc.toml", 18, 1, "effects[0].k")
    p = tmp_path / "syntax.toml"
    p.write_text("name = \n")
    with pytest.raises(vectrix.SceneError) as e:
        vectrix.Scene.from_file(p)
    assert e.value.file == str(p) and e.value.line == 1
    with pytest.raises(vectrix.SceneError, match="no key `kk`"):
        vectrix.Scene.from_toml(OSC).run(effects__0__kk=1.0)
    with pytest.raises(vectrix.SceneError, match="valid"):
        vectrix.Scene.from_toml(OSC).run(effects__0__k=[1, 2])
    with pytest.raises(ValueError, match="path"):
        vectrix.Scene.from_file(tmp_path / "missing.toml")


def test_model_from_scene():
    m = vectrix.Scene.from_toml(OSC).model()
    assert (m.nq, m.nv) == (1, 1)
    # a free particle on a sleeve: M = m
    assert abs(m.crba([0.3])[0, 0] - 2.0) < 1e-15


def test_ctrl_c_stops_a_long_run_and_keeps_the_rows():
    """A run of 10⁶ s would take minutes; Ctrl-C (simulated by _thread.interrupt_main) stops
    it after the current step, and the exception carries the rows computed."""
    import _thread
    import threading

    s = vectrix.Scene.from_toml(OSC.replace("duration = 2.0", "duration = 1e6").replace("samples = 20", "samples = 100000"))
    timer = threading.Timer(0.5, _thread.interrupt_main)
    timer.start()
    with pytest.raises(vectrix.Interrupted) as e:
        s.run()
    timer.join()
    part = e.value.partial
    assert not part.complete and part.summary["stop"]["reason"] == "interrupted"
    assert 1 <= len(part.t) < 100001
    x = part["coordinates:c.0"]
    assert np.max(np.abs(x - (1 + 0.5 * np.cos(5.0 * part.t)))) < 1e-6


def test_cancel_flag_returns_the_partial_run():
    s = vectrix.Scene.from_toml(OSC.replace("duration = 2.0", "duration = 1e6"))
    c = vectrix.Cancel()
    c.set()
    r = s.run(cancel=c)
    assert not r.complete and r.summary["stop"]["reason"] == "interrupted"
