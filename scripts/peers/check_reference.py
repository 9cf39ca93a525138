"""Cross-checks the chains' reference end states of reference.json (vectrix DOP853 at
rtol = atol = 1e-13 through its ABA) against two independent computations: scipy's DOP853 at
rtol = atol = 1e-13 on the numpy Lagrangian of frontier_common (absolute angles, O(n³)
solve), and scipy's DOP853 at the same tolerance on Pinocchio's ABA. Writes the max-norm
differences into reference_check.json; the frontier's errors are meaningful down to about
these differences."""
import json
import os

import numpy as np
from scipy.integrate import solve_ivp

import frontier_common as fc
from frontier_pinocchio import PinRhs


def main():
    ref = fc.load_reference()
    out = {}
    for n in fc.CHAIN_NS:
        problem = f"chain-{n}"
        if problem not in ref or not fc.only(problem):
            continue
        y0 = fc.chain_y0(n)
        state = np.array(ref[problem]["state"])
        row = {}
        for name, rhs in (("scipy DOP853 1e-13, numpy Lagrangian", fc.ChainRhs(n)),
                          ("scipy DOP853 1e-13, Pinocchio ABA", PinRhs(n))):
            sol = solve_ivp(rhs, (0.0, fc.CHAIN_T), y0, method="DOP853", rtol=1e-13, atol=1e-13)
            row[name] = float(np.max(np.abs(sol.y[:, -1] - state)))
        out[problem] = row
        print(problem, row, flush=True)
    path = os.path.join(fc.RESULTS, "reference_check.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print("wrote", path)


if __name__ == "__main__":
    main()
