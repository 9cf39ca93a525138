"""An aircraft scene from Python: the business jet of Tables 14.1–14.2 as a free body with `aero`
and `thrust` effects (examples/scenes/business_jet_doublet.toml), trimmed in straight and level
flight at U0 = 400 kt and linearized there (book §12.3–12.4, §14.1–14.7).

References (independent of vectrix): the trim point of the book's tables (U0 = 400 kt =
675.124 ft/s, level, in stability axes so α0 = Θ0 = W0 = 0, §12.4), and the longitudinal and
lateral state matrices (14.1.13, 14.3) assembled from the printed derivatives of Tables
14.1–14.2 (book/notes ch9-14, with the notes' corrections), whose eigenvalues numpy computes
here; the printed characteristic polynomial of Problem 14.9.4 to its three printed digits."""
from pathlib import Path

import numpy as np

import vectrix

SCENE = Path(__file__).resolve().parents[2] / "examples/scenes/business_jet_doublet.toml"
# U0 = 400 kt (Table 14.1; the example scene's speed), in m/s (the knot is exactly 1852/3600 m/s)
U0 = 400 * 1852.0 / 3600.0
# the doublet off (the trimmed flight itself), 60 s in 600 intervals
STEADY = {"effects.1.elevator.amplitude": 0.0, "duration": 60.0, "samples": 600}


def scene():
    text = SCENE.read_text()
    # the attitude too (the free joint's coordinates: position, then the quaternion (η, ε))
    outputs = 'outputs = ["coordinates:jet", "position:jet", "velocity:jet", "omega_body:jet"]'
    text = "\n".join(outputs if line.startswith("outputs = ") else line for line in text.splitlines())
    return vectrix.Scene.from_toml(text, str(SCENE))


def test_trimmed_level_flight_holds_the_tables_trim_point():
    r = scene().run(STEADY)
    c = r.columns
    v = np.stack([c[f"velocity:jet.{a}"] for a in "xyz"], axis=1)  # ground (earth) frame, z down
    q = np.stack([c[f"coordinates:jet.{k}"] for k in range(3, 7)], axis=1)  # (η, ε₁, ε₂, ε₃)
    body = vectrix.Rotation.from_quat(q, scalar_first=True).apply(v, inverse=True)
    airspeed = np.linalg.norm(body, axis=1)
    alpha = np.arctan2(body[:, 2], body[:, 0])  # (10.6.18): α = atan2(W, U)
    assert r.complete and len(r.t) == 601
    # what is left of the trim's residual after 60 s of integration is of the order of the
    # integrator's relative tolerance (the run's rtol, 1e-9); 10 rtol bounds each departure
    tol = 10 * r.summary["method"]["rtol"]
    # U0 = 400 kt all along
    assert np.max(np.abs(airspeed / U0 - 1)) < tol
    # stability axes at trim: α0 = 0 and Θ0 = 0 (§12.4), wings level, no climb
    assert np.max(np.abs(alpha)) < tol
    assert np.max(np.abs(q[:, [1, 3]])) < 1e-12 and np.max(np.abs(2 * q[:, 2])) < tol
    assert np.max(np.abs(c["position:jet.z"])) < 1e-6
    assert abs(c["position:jet.x"][-1] - 60 * U0) < 1e-6 * 60 * U0


def test_linearization_at_trim_has_the_tables_modes():
    lin = scene().linearize(STEADY)
    ev = lin["eigenvalues"]
    # 14.1.13 (corrected), x = [u (ft/s), δα, q, θ], from Table 14.1's derivatives
    a_long = np.array([[-0.0074, 8.9782, 0, -32.2], [-2.05623e-4, -0.659358, 0.995961, 0],
                       [9.83524e-4, -7.17377, -1.34426, 0], [0, 0, 1, 0]])
    # 14.3, x = [r, δβ, p, φ], from Table 14.2's derivatives
    a_lat = np.array([[-0.113316, 2.82474, 4.28355e-4, 0], [-0.998861, -0.0820623, 0, 0.0476949],
                      [0.155273, -4.13896, -0.436493, 0], [0, 0, 1, 0]])
    want = np.concatenate([np.linalg.eigvals(a_long), np.linalg.eigvals(a_lat)])
    for w in want:
        # the tables print 4–6 digits: each mode within 1e-4 relative of the nearest eigenvalue
        got = ev[np.argmin(np.abs(ev - w))]
        assert abs(got - w) < 1e-4 * abs(w), (w, got)
    # the rest are the position states' zero eigenvalues (x, y, h and ψ do not feed back)
    rest = sorted(ev, key=lambda z: abs(z))[:4]
    assert np.max(np.abs(rest)) < 1e-9
    # P14.9.4 prints the longitudinal polynomial s⁴ + 2.01s³ + 8.05s² + 0.085s + 0.068
    long_modes = [ev[np.argmin(np.abs(ev - w))] for w in np.linalg.eigvals(a_long)]
    coeffs = np.real(np.poly(long_modes))
    assert np.allclose(coeffs, [1, 2.01, 8.05, 0.085, 0.068], rtol=0.01, atol=0)
