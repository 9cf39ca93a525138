"""Reference data for the rolling disk by sympy.physics.mechanics.KanesMethod (book §9.14).

The disk (mass m, radius r, thin: J = diag(m r²/4, m r²/2, m r²/4) in the lean frame L)
rolls without slipping on the plane z = 0 under gravity −g ẑ. Frames as in sympy's own
rolling-disc example: Y = N rotated by q1 (yaw ψ) about N.z, L = Y rotated by q2 (lean θ)
about Y.x, R = L rotated by q3 (spin φ) about L.y; the centre is r L.z above the contact
point. Generalized speeds u = ω_{R/N} resolved in L.

Writes tests/data/ch09_kane_rolling_disk.json: for several states (q2, u) the derivatives
u̇ = MM⁻¹ forcing, evaluated at 40 digits from the exact values of the double inputs and printed with 17 significant digits.
Run once: ~/.venv-peers/bin/python scripts/ch09_kane_rolling_disk.py
"""

import json
import random

import mpmath
import sympy as sp
from sympy.physics.mechanics import (
    KanesMethod,
    Point,
    ReferenceFrame,
    RigidBody,
    dot,
    dynamicsymbols,
    inertia,
)

q1, q2, q3, u1, u2, u3 = dynamicsymbols("q1 q2 q3 u1 u2 u3")
g, r, m = sp.symbols("g r m")

N = ReferenceFrame("N")
Y = N.orientnew("Y", "Axis", [q1, N.z])
L = Y.orientnew("L", "Axis", [q2, Y.x])
R = L.orientnew("R", "Axis", [q3, L.y])
w_R_N_qd = R.ang_vel_in(N)
R.set_ang_vel(N, u1 * L.x + u2 * L.y + u3 * L.z)

C = Point("C")
C.set_vel(N, 0)
Dmc = C.locatenew("Dmc", r * L.z)
Dmc.v2pt_theory(C, N, R)

I = inertia(L, m / 4 * r**2, m / 2 * r**2, m / 4 * r**2)
kd = [dot(R.ang_vel_in(N) - w_R_N_qd, uv) for uv in L]
forces = [(Dmc, -m * g * Y.z)]
disk = RigidBody("disk", Dmc, R, m, (I, Dmc))

km = KanesMethod(N, q_ind=[q1, q2, q3], u_ind=[u1, u2, u3], kd_eqs=kd)
km.kanes_equations([disk], forces)
udot = km.mass_matrix.LUsolve(km.forcing)
udot = sp.simplify(udot)

params = {"m": 1.7, "r": 0.35, "g": 9.81}
mpmath.mp.dps = 30
random.seed(917)
states = [
    # upright, rolling straight: u̇ = 0
    (0.0, [0.0, 4.0, 0.0]),
    # leaning, turning
    (0.3, [0.2, 5.0, -1.1]),
    (-0.7, [-0.5, 2.5, 1.9]),
    (1.2, [0.8, -3.0, 0.4]),
]
for _ in range(4):
    states.append((random.uniform(-1.3, 1.3), [random.uniform(-6, 6) for _ in range(3)]))

# every input enters as the exact rational value of its double
exact = sp.Rational
subs_p = {g: exact(params["g"]), r: exact(params["r"]), m: exact(params["m"])}
cases = []
for lean, u in states:
    subs = dict(subs_p)
    subs.update({q2: exact(lean), u1: exact(u[0]), u2: exact(u[1]), u3: exact(u[2])})
    vals = [mpmath.mpf(str(sp.N(e.subs(subs), 40))) for e in udot]
    cases.append(
        {
            "lean": lean,
            "u": u,
            "udot": [mpmath.nstr(v, 17, min_fixed=0, max_fixed=0) for v in vals],
        }
    )

out = {
    "source": "sympy.physics.mechanics.KanesMethod " + sp.__version__ + ", scripts/ch09_kane_rolling_disk.py",
    "params": params,
    "note": "u = omega_{R/N} resolved in L; udot = mass_matrix^-1 forcing; yaw and spin do not enter",
    "cases": cases,
}
with open("tests/data/ch09_kane_rolling_disk.json", "w") as f:
    json.dump(out, f, indent=1)
print(json.dumps(out, indent=1))
