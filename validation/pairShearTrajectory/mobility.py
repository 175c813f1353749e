#!/usr/bin/env python3
"""Validation: the relative mobility of two free equal spheres in simple
shear (thesis 1, section 4.1.3, case 1), measured at frozen
configurations, and the trajectories it implies.

Why frozen configurations.  In unbounded shear the relative velocity of
two free equal spheres is (Batchelor & Green 1972)

    V = W x r + E.r - [A(r) d d + B(r) (I - d d)].E.r ,   d = r/|r|,

so the whole family of relative trajectories is fixed by the two scalar
functions A(r) and B(r).  Measuring A and B with the solver at a set of
separations and integrating dr/dt = V with them is therefore equivalent
to integrating the simulated trajectories, at one steady solve per point
instead of ~900 time steps per trajectory (about 10 h on 2 cores, see
run.py).  The shear-plane pair at angle theta to the flow (d = (cos,
sin, 0)) gives

    radial      V.d = (1 - A) r sin(theta) cos(theta)       (A, theta = 45)
    tangential  V.t = -r/2 + (1 - B) (r/2) cos(2 theta)    (B, theta = 0)

and the mirror configuration theta = 135 deg (the pair separating
instead of approaching) checks fore-aft symmetry: V.d there must be
minus V.d at 45 deg (Stokes reversibility; Da Cunha & Hinch 1996).

Set-up: spheres a = 1, Delta = a/5, pair centre at the centre of a plane
Couette cell (shear rate 1, walls at y = +-L/2, cyclic in x and z with
period L; L = 12 a as run.py), frameInvariant sub-grid lubrication, one
steady solve (first step, lambda tolerance 1e-7) per configuration and
cell position.  Reference: fdmResistance.pairShear (exact two-sphere
resistance problem, checked against Batchelor & Green).

    ./Allrun mobility [--gaps 0.01,0.03,...] [--positions 2] [--jobs 2]

writes mobility.dat, mobility.md and pairShearMobility.png here (cases in
build/validation/pairShearMobility).
"""

import argparse
import concurrent.futures
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.caseRunner import (cell_offsets, fill_template,  # noqa: E402
                                run_case, vec)
from fdmResistance import pairShear  # noqa: E402

DELTA = 0.2
L = 12.0
# Which function each orientation measures
ANGLES = {"B": 0.0, "A": 45.0, "Amirror": 135.0}


def solve(gap, angle, offset, work, pair_table=None, cell=L):
    """U2 - U1 for r = x2 - x1 = (2 + gap)(cos, sin, 0), pair centred at
    the cell centre shifted by offset (units of Delta); with the solver's
    default sub-grid pair table or the one named, in a cell of side cell."""
    r = 2.0 + gap
    th = np.radians(angle)
    d = np.array([np.cos(th), np.sin(th), 0.0])
    centre = np.asarray(offset) * DELTA + 0.013   # off the mesh nodes
    case = os.path.join(work, "gap%g_theta%g_%s" % (
        gap, angle, "_".join("%g" % o for o in offset)))
    fill_template(os.path.join(HERE, "template"), case, {
        "@L@": "%g" % cell, "@L2@": "%g" % (cell / 2),
        "@H2@": "%g" % (cell / 2), "@N@": "%d" % round(cell / DELTA), "@ENDTIME@": "1e-3", "@DT@": "1e-3",
        "@WRITEINTERVAL@": "1", "@LAMBDATOL@": "1e-7",
        "@X1@": vec(centre - 0.5 * r * d), "@X2@": vec(centre + 0.5 * r * d)})
    if pair_table:
        path = os.path.join(case, "constant", "particleProperties")
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text.replace("walls false;", 'walls false; pairTables'
                                 ' ("%s");' % os.path.abspath(pair_table)))
    s = run_case(case)
    V = s["velocity"][1] - s["velocity"][0]
    return float(V @ d), float(V @ np.array([-d[1], d[0], 0.0]))


def functions_from(gap, angle, Vd, Vt):
    """A (or B) from the measured radial (tangential) relative velocity."""
    r = 2.0 + gap
    th = np.radians(angle)
    if angle == ANGLES["B"]:
        return 1.0 - (Vt + r / 2) / (r / 2 * np.cos(2 * th))
    return 1.0 - Vd / (r * np.sin(th) * np.cos(th))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gaps", default="0.01,0.03,0.1,0.3,1,2,4")
    parser.add_argument("--mirror-gaps", default="0.01,0.1,1")
    parser.add_argument("--positions", type=int, default=2)
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    gaps = [float(g) for g in args.gaps.split(",")]
    mirror = [float(g) for g in args.mirror_gaps.split(",")]
    work = os.path.join(os.environ["FDM_PROJECT_DIR"], "build", "validation",
                        "pairShearMobility")
    offsets = [tuple(o) for o in cell_offsets(args.positions, 3)]
    jobs = [(g, name, o) for g in gaps for name in ("A", "B")
            for o in offsets]
    jobs += [(g, "Amirror", o) for g in mirror for o in offsets]
    results = {}
    with concurrent.futures.ProcessPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(solve, g, ANGLES[n], o, work): (g, n, o)
                   for g, n, o in jobs}
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            results[futures[fut]] = fut.result()
            print("  [%d/%d] gap %g %s" % ((i + 1, len(jobs))
                                           + futures[fut][:2]), flush=True)
    with open(os.path.join(HERE, "mobility.dat"), "w") as f:
        f.write("# gap function angle offset_x offset_y offset_z V.d V.t "
                "measured theory (V = U2 - U1, a = shear rate = 1)\n")
        for (g, n, o), (Vd, Vt) in sorted(results.items()):
            A_th, B_th = pairShear.AB_exact([2.0 + g])
            theory = B_th[0] if n == "B" else A_th[0]
            f.write("%g %s %g %g %g %g %.10g %.10g %.10g %.10g\n" % (
                (g, n, ANGLES[n]) + o + (Vd, Vt, functions_from(
                    g, ANGLES[n], Vd, Vt), theory)))
    import mobilityReport
    mobilityReport.main()


if __name__ == "__main__":
    main()
