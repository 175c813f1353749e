#!/usr/bin/env python3
"""Validation: free sphere in simple shear near a plane wall (thesis 1,
section 4.1.2a, Fig. 4.4).

A free sphere (a = 1, Delta = a/5) at a gap epsilon = d/a - 1 above the
bottom wall of a plane Couette flow of shear rate 1 (top wall at H = 10 a
moving at H; cyclic in x and z with period L = 10 a), one solve per
position (4 in-plane positions inside a mesh cell, as the thesis' 16).
Measured: U_x/(shear rate a), Omega_z/(shear rate), S_xy/((10/3) pi eta a^3
shear rate), with the frameInvariant sub-grid lubrication and, at one
position, without it (the FDM alone).  References (reference.py):
the free-sphere velocities near a single wall in unbounded fluid and the
stresslet fit of Sangani et al. (2011) (eq 4.9).

    ./Allrun [--eps 0.01,0.02,...] [--positions 4] [--jobs 2]

writes results.dat, report.md and wallShearSphere.png here (cases in
build/validation/wallShearSphere).  The thesis'
box is 50 a: ours is 10 a, so the top wall (at about 8.5 a) and the
periodic images (10 a apart) change the velocities by O((a/h)^3), a few
1e-3; stated with the results.
"""

import argparse
import concurrent.futures
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
sys.path.insert(0, HERE)
from fdmPost.caseRunner import (cell_offsets, fill_template,  # noqa: E402
                                run_case, vec)

DELTA = 0.2
L = 10.0
H = 10.0
S_SCALE = 10.0 / 3.0 * np.pi


def solve(eps, offset, model, work, lambda_tol):
    x = np.array([L / 2 + offset[0] * DELTA, 1.0 + eps,
                  L / 2 + offset[1] * DELTA])
    case = os.path.join(work, "eps%g_x%g_z%g_%s" % (eps, offset[0],
                                                    offset[1], model))
    fill_template(os.path.join(HERE, "template"), case, {
        "@L@": "%g" % L, "@H@": "%g" % H, "@N@": "%d" % round(L / DELTA),
        "@NH@": "%d" % round(H / DELTA), "@EPS@": "%g" % eps,
        "@X@": vec(x), "@LAMBDATOL@": "%g" % lambda_tol,
        "@SUBGRID@": model})
    s = run_case(case)
    return (s["velocity"][0][0], s["angularVelocity"][0][2],
            s["stresslet"][0][1] / S_SCALE)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--eps", default="0.01,0.02,0.05,0.1,0.2,0.5,1")
    parser.add_argument("--positions", type=int, default=4)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--lambda-tol", type=float, default=1e-6)
    args = parser.parse_args()
    eps_list = [float(e) for e in args.eps.split(",")]
    work = os.path.join(os.environ["FDM_PROJECT_DIR"], "build", "validation",
                        "wallShearSphere")
    jobs = [(e, o, "frameInvariant") for e in eps_list
            for o in cell_offsets(args.positions, 2)]
    jobs += [(e, cell_offsets(1, 2)[0], "none") for e in eps_list]
    results = {}
    with concurrent.futures.ProcessPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(solve, e, o, m, work, args.lambda_tol):
                   (e, tuple(o), m) for e, o, m in jobs}
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            results[futures[fut]] = fut.result()
            print("  [%d/%d] %s" % (i + 1, len(jobs), futures[fut]),
                  flush=True)
    with open(os.path.join(HERE, "results.dat"), "w") as f:
        f.write("# eps offset_x offset_z model U_x Omega_z S_xy/((10/3)pi)\n")
        for (e, o, m), v in sorted(results.items()):
            f.write("%g %g %g %s %.10g %.10g %.10g\n" % ((e,) + o + (m,) + v))
    import report
    report.main()


if __name__ == "__main__":
    main()
