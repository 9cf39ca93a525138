"""Cross-checks the chains' reference end states of reference.json against two computations
with other tools: scipy's DOP853 at rtol = atol = 1e-13 on the numpy Lagrangian of
frontier_common (absolute angles, O(n³) solve), and scipy's DOP853 at the same tolerance on
Pinocchio's ABA. Writes the max-norm differences into reference_check.json; for the body, Kepler and the
pendulum, the distance of frontier_common's double-precision closed forms to the
extended-precision end states (closed_form_reference_mp.py) the errors are measured against.

The reference is the extended-precision one (scripts/peers/chain_reference_mp.py, committed as
tests/data/chain_reference_mp.json, copied into reference.json by the frontier's `run`; its
own uncertainty, ~1e-16, is stated in reference.json as "uncertainty"), so these differences
are the errors of the tools' tight runs (~1e-14..1e-12), checks of the tools and of the wiring
rather than of the reference; the first entry of each row is the difference of reference.json's
state to the committed extended-precision state (0 when reference.json is current). (A
reference.json from before, a vectrix DOP853 run at 1e-13, has no "uncertainty": then the
frontier trusts it only down to these differences, that first one included.)
"""
import json
import os

import numpy as np
from scipy.integrate import solve_ivp

import frontier_common as fc
from frontier_pinocchio import PinRhs


MP_REFERENCE = os.path.join(fc.REPO, "tests", "data", "chain_reference_mp.json")


def main():
    ref = fc.load_reference()
    with open(MP_REFERENCE) as f:
        mp_ref = json.load(f)["chains"]
    out = {}
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if problem not in ref or not fc.only(problem):
            continue
        y0 = fc.chain_y0(n)
        state = np.array(ref[problem]["state"])
        # the wiring: reference.json's state is the extended-precision one (0 when current)
        row = {"extended-precision reference (chain_reference_mp.json)":
               float(np.max(np.abs(np.array(mp_ref[problem]["state"]) - state)))}
        for name, rhs in (("scipy DOP853 1e-13, numpy Lagrangian", fc.ChainRhs(n)),
                          ("scipy DOP853 1e-13, Pinocchio ABA", PinRhs(n))):
            sol = solve_ivp(rhs, (0.0, fc.CHAIN_T), y0, method="DOP853", rtol=1e-13, atol=1e-13)
            row[name] = float(np.max(np.abs(sol.y[:, -1] - state)))
        out[problem] = row
        print(problem, row, flush=True)
    # the closed-form problems: frontier_common's double-precision closed forms against the
    # extended-precision end states every tool's error is measured against
    for problem, exact in (("rigid-body", fc.rigid_exact_omega(fc.RB_T)),
                           ("kepler-e0.9", fc.kepler_exact(fc.KEPLER_T)),
                           ("pendulum", fc.pendulum_exact(fc.PEND_T))):
        if fc.only(problem):
            out[problem] = {"scipy.special closed form (frontier_common) vs mpmath":
                            float(np.max(np.abs(exact - fc.MP_END[problem])))}
            print(problem, out[problem], flush=True)
    path = os.path.join(fc.RESULTS, "reference_check.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print("wrote", path)


if __name__ == "__main__":
    main()
