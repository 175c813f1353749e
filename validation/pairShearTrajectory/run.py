#!/usr/bin/env python3
"""Validation: relative trajectories of two free equal spheres in simple
shear without contact (thesis 1, section 4.1.3, Fig. 4.9, case 1).

Spheres a = 1 (Delta = a/5) start at x = -3, y = r_y0/2 and x = 3,
y = -r_y0/2 in the shear plane of a plane Couette flow (shear rate 1,
walls at y = +-H/2, cyclic in x and z with period L), move with the
frameInvariant sub-grid lubrication and pass each other.  Reference: the
same relative motion in unbounded shear from the exact two-sphere
resistance problem (fdmResistance.pairShear), which is fore-aft
symmetric (Da Cunha & Hinch 1996).

    ./Allrun [--ry0 1.0,0.5] [--L 12] [--dt 0.02] [--jobs 2]

writes trajectories.dat per case, report.md and pairShearTrajectory.png
(cases in build/validation/pairShearTrajectory).  The thesis box is 40 a
and its time step 1e-4; here L = H = 12 a and Delta t = 0.02 (the gap
changes by at most a few per cent per step, see the report): the walls
at 6 a slow the pair and bend the trajectory by a few per cent.
"""

import argparse
import concurrent.futures
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.caseRunner import fill_template, run_case, vec  # noqa: E402

DELTA = 0.2


def simulate(ry0, L, dt, end_time, work, lambda_tol):
    case = os.path.join(work, "ry%g" % ry0)
    # Off the mesh nodes so that the pair is not at a symmetry point
    shift = np.array([0.037, 0.053, 0.029])
    fill_template(os.path.join(HERE, "template"), case, {
        "@L@": "%g" % L, "@L2@": "%g" % (L / 2), "@H2@": "%g" % (L / 2),
        "@N@": "%d" % round(L / DELTA), "@ENDTIME@": "%g" % end_time,
        "@DT@": "%g" % dt, "@WRITEINTERVAL@": "%d" % round(2.0 / dt),
        "@LAMBDATOL@": "%g" % lambda_tol,
        "@X1@": vec(np.array([-3.0, ry0 / 2, 0.0]) + shift),
        "@X2@": vec(np.array([3.0, -ry0 / 2, 0.0]) + shift)})
    run_case(case)
    import h5py
    with h5py.File(os.path.join(case, "postProcessing", "particles.h5"),
                   "r") as f:
        t = np.array(f["time"])
        x = np.array(f["position"])
    # r = x_1 - x_2 as in the thesis: starts at (-6, r_y0)
    r = x[:, 0, :] - x[:, 1, :]
    np.savetxt(os.path.join(case, "trajectory.dat"),
               np.column_stack([t, r]), header="t r_x r_y r_z (r = x1 - x2)")
    return case


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ry0", default="1.0,0.5")
    parser.add_argument("--L", type=float, default=12.0)
    parser.add_argument("--dt", type=float, default=0.02)
    parser.add_argument("--end-time", type=float, default=0.0,
                        help="default: 14/r_y0 + 4")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--lambda-tol", type=float, default=1e-5)
    args = parser.parse_args()
    work = os.path.join(os.environ["FDM_PROJECT_DIR"], "build",
                        "validation", "pairShearTrajectory")
    values = [float(v) for v in args.ry0.split(",")]
    with concurrent.futures.ProcessPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(simulate, v, args.L, args.dt,
                               args.end_time or 14.0 / v + 4.0, work,
                               args.lambda_tol) for v in values]
        for fut in concurrent.futures.as_completed(futures):
            print("done", fut.result(), flush=True)
    sys.path.insert(0, HERE)
    import report
    report.main(work, values)


if __name__ == "__main__":
    main()
