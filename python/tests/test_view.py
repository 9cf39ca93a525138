"""A run's 3-D view from Python (issue 36 item 5): `RunResult.view()` is the page `vectrix run`
writes as view.html (one self-contained file, three.js inlined, poses bounded), shown in
Jupyter through `_repr_html_` as a sandboxed iframe whose srcdoc holds the page escaped."""
import html
import json
import re

import numpy as np
import pytest

import vectrix
from vectrix import _vectrix

from test_scene import OSC


def data_of(page):
    """The run's data: the JSON inside <script type="application/json" id="vectrix-data">."""
    m = re.search(r'<script type="application/json" id="vectrix-data">(.*?)</script>', page, re.S)
    assert m, "the page carries its data"
    return json.loads(m.group(1))


def test_view_is_self_contained():
    page = vectrix.Scene.from_toml(OSC).run().view().html
    # nothing is fetched: no external script, style, image or frame, and no URL but the XML
    # namespace names inside three.js (identifiers, never requested)
    assert not re.search(r'<(script|img|iframe|link)[^>]*\s(src|href)=', page, re.I)
    urls = re.findall(r'https?://[^\s"\'<>)]*', page, re.I)
    assert all(u.startswith("http://www.w3.org/") for u in urls), set(urls)
    assert "three.js" in page and "vectrixView" in page  # the library and the viewer are inlined
    assert "default-src 'none'" in page  # the Content-Security-Policy forbids any fetch


def test_view_poses_follow_the_closed_form():
    """The sleeve particle of test_scene.OSC: x(t) = 1 + 0.5 cos(5t) (m ẍ = −k(x − L))."""
    v = vectrix.Scene.from_toml(OSC).run().view()
    d = data_of(v.html)
    assert d["name"] == "osc" and d["kind"] == "bodies" and d["complete"] is True
    t = np.array(d["t"])
    pose = np.array(d["pose"]).reshape(len(t), 7)  # one body: position, then quaternion (w, x, y, z)
    assert len(t) == 21  # the scene's 20 samples + t = 0 (below the 1001-instant bound)
    # 7 significant digits in the page: |x| ≤ 1.5 rounds within 1e-6, t within 2e-7 (ẋ ≤ 2.5)
    assert np.max(np.abs(pose[:, 0] - (1 + 0.5 * np.cos(5 * t)))) < 3e-6
    assert np.max(np.abs(pose[:, 1:3])) < 1e-12  # the sleeve keeps it on the x axis
    assert np.max(np.abs(pose[:, 3:] - [1, 0, 0, 0])) < 1e-12  # and does not turn it


def test_view_size_is_bounded_whatever_the_samples():
    s = vectrix.Scene.from_toml(OSC.replace("samples = 20", "samples = 200000"))
    r = s.run()
    assert len(r.t) == 200001
    v = r.view()
    d = data_of(v.html)
    assert 2 <= len(d["t"]) <= 1001 and len(d["pose"]) == 7 * len(d["t"])
    assert len(v.html.encode()) <= v.bound <= 2**30  # vectrix run's bound and default limit


def test_repr_html_is_the_page_in_an_escaped_srcdoc():
    v = vectrix.Scene.from_toml(OSC).run().view()
    frame = v._repr_html_()
    m = re.fullmatch(r'<iframe sandbox="allow-scripts" style="[^"<>]*" srcdoc="([^"<>]*)"></iframe>', frame, re.S)
    assert m, frame[:200]
    assert html.unescape(m.group(1)) == v.html


def test_hostile_text_cannot_leave_the_iframe():
    evil = '</iframe><script>alert(1)</script>"\'&amp;'
    frame = _vectrix.view_iframe(evil)
    srcdoc = re.fullmatch(r'<iframe [^<>]*srcdoc="([^"<>]*)"></iframe>', frame).group(1)
    assert html.unescape(srcdoc) == evil
    # and a hostile scene name never reaches a page: the scene refuses it
    with pytest.raises(vectrix.SceneError, match="name"):
        vectrix.Scene.from_toml(OSC.replace('name = "osc"', 'name = "</script><script>alert(1)"'))


def test_view_after_overrides_shows_the_run_with_them(tmp_path):
    """k = 200 instead of 50: ω = √(k/m) = 10 rad/s."""
    r = vectrix.Scene.from_toml(OSC).run(effects__0__k=200.0)
    v = r.view()
    d = data_of(v.html)
    t = np.array(d["t"])
    x = np.array(d["pose"]).reshape(len(t), 7)[:, 0]
    assert np.max(np.abs(x - (1 + 0.5 * np.cos(10 * t)))) < 6e-6  # ẋ ≤ 5: t's rounding 1e-6
    v.save(tmp_path / "view.html")
    assert (tmp_path / "view.html").read_text(encoding="utf-8") == v.html


def test_ctrl_c_still_raises_keyboard_interrupt_after_a_view():
    """The view's code is the command line's, whose own runs install a Ctrl-C handler; from
    Python it must not: SIGINT after `view()` is still Python's KeyboardInterrupt."""
    import subprocess
    import sys

    code = (
        "import os, signal, sys, time, vectrix\n"
        "vectrix.Scene.from_toml(sys.argv[1]).run().view()\n"
        "try:\n"
        "    os.kill(os.getpid(), signal.SIGINT)\n"
        "    time.sleep(5)\n"
        "    print('not interrupted')\n"
        "except KeyboardInterrupt:\n"
        "    print('KeyboardInterrupt')\n"
    )
    out = subprocess.run([sys.executable, "-c", code, OSC], capture_output=True, text=True, timeout=120)
    assert out.stdout.strip() == "KeyboardInterrupt", (out.stdout, out.stderr)
