#!/usr/bin/env python3
"""Validation: a rough frictional pair in simple shear (thesis 1, section
4.1.3, case 2): a1 = 1, a2 = 1.4, roughness h_r = 5e-3 a1, friction 0.5.
Contact breaks the fore-aft symmetry: the pair leaves on the streamline
whose theoretical minimum gap is the roughness, whatever its initial
offset (Da Cunha & Hinch 1996).

Why frozen configurations.  At zero Reynolds number the pair's velocities
are linear in the ambient shear and in the contact loads, and by symmetry
eight functions of the gap describe them (fdmResistance.pairContact):
A(r), B(r) of the relative velocity and c_1, c_2 of the spins in shear;
m_n (normal pair load), m_t, w_1, w_2 (tangential pair load with its
torques l_i d x F_t).  The solver measures them at frozen configurations
(four probes per gap, one steady solve each) and the contact law
(fdmResistance.pairContact.ContactLaw, the law of libfdmParticles) is
integrated with them; a time-stepped run of the thesis (2e5 steps) would
cost days here.  The reference integrates the same law with the exact
two-sphere resistance matrices (twin-multipole functions, unbounded
fluid).  Between the measured gaps the solver's functions are the exact
ones plus the measured deviation, interpolated in ln(gap), so the
comparison carries no interpolation error of the shapes; trajectories with
only the shear or only the load functions from the solver tell which part
moves the exit offset.

Set-up: Delta = a1/5, Couette cell 12 a1 (walls at +-6 a1, cyclic in x and
z), frameInvariant sub-grid lubrication, one position in a cell by
default, lambda residual 3e-6 (about 60 outer iterations; 1e-7 takes
twice as many).  Trajectories start at r = x2 - x1 = (-6, r_y0, 0).

    ./Allrun [--ry0 0.25,0.5,1] [--positions 2] [--jobs 2]

writes functions.dat, report.md and pairContactShear.png here (cases in
build/validation/pairContactShear).  About 30 min on 2 cores.
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
from fdmResistance import pairContact as pc  # noqa: E402

LAM = 1.4
DELTA = 0.2
L = 12.0
GAPS = (0.0035, 0.005, 0.01, 0.03, 0.1, 0.3, 1.0, 4.0)
CONTACT_GAPS = (0.0035, 0.005)   # where the load probes are needed
X0 = -6.0
LAMBDA_TOL = 3e-6   # outer-loop lambda residual of the one steady solve
TOL_OFFSET = 0.03      # exit offset, relative
TOL_TRAJECTORY = 0.05  # r_y, in a1


def probe(gap, kind, offset, work):
    """U2 - U1, W1, W2 of one frozen configuration (pairContact's probe)."""
    dist = gap + 1 + LAM
    d, sheared, F1, T1, T2 = pc.probe_set_up(kind, gap, LAM)
    centre = np.asarray(offset) * DELTA + 0.013   # off the mesh nodes
    case = os.path.join(work, "gap%g_%s_%s" % (
        gap, kind, "_".join("%g" % o for o in offset)))
    fill_template(os.path.join(HERE, "template"), case, {
        "@L@": "%g" % L, "@L2@": "%g" % (L / 2), "@H2@": "%g" % (L / 2),
        "@UW@": "%g" % (L / 2 if sheared else 0.0),
        "@N@": "%d" % round(L / DELTA),
        "@ENDTIME@": "1e-3", "@DT@": "1e-3", "@WRITEINTERVAL@": "1",
        "@LAMBDATOL@": "%g" % LAMBDA_TOL,
        "@X1@": vec(centre - 0.5 * dist * d),
        "@X2@": vec(centre + 0.5 * dist * d), "@F1@": vec(F1),
        "@F2@": vec(-F1), "@T1@": vec(T1), "@T2@": vec(T2)})
    s = run_case(case)
    V = s["velocity"][1] - s["velocity"][0]
    return V, s["angularVelocity"][0], s["angularVelocity"][1]


def measure(positions, jobs):
    work = os.path.join(os.environ["FDM_PROJECT_DIR"], "build", "validation",
                        "pairContactShear")
    offsets = [tuple(o) for o in cell_offsets(positions, 3)]
    runs = [(g, k, o) for g in GAPS for k in pc.PROBES for o in offsets
            if k.startswith("shear") or g in CONTACT_GAPS]
    found = {}
    with concurrent.futures.ProcessPoolExecutor(jobs) as pool:
        futures = {pool.submit(probe, g, k, o, work): (g, k, o)
                   for g, k, o in runs}
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            found[futures[fut]] = fut.result()
            print("  [%d/%d] gap %g %s" % ((i + 1, len(runs))
                                           + futures[fut][:2]), flush=True)
    rows = []
    for g in GAPS:
        per = [pc.functions_from_probes(g, LAM, {
            k: found[g, k, o] for k in pc.PROBES if (g, k, o) in found})
            for o in offsets]
        mean = {f: np.mean([p[f] for p in per]) for f in pc.FUNCTIONS}
        spread = {f: np.ptp([p[f] for p in per]) for f in pc.FUNCTIONS}
        rows.append((g, mean, spread))
    with open(os.path.join(HERE, "functions.dat"), "w") as f:
        f.write("# gap " + " ".join(pc.FUNCTIONS) + " | spread over %d "
                "positions: " % positions + " ".join(pc.FUNCTIONS)
                + "  (a1 = shear rate = viscosity = 1)\n")
        for g, mean, spread in rows:
            f.write("%g " % g + " ".join("%.8g" % mean[k] for k in
                                         pc.FUNCTIONS) + " "
                    + " ".join("%.3g" % spread[k] for k in pc.FUNCTIONS)
                    + "\n")


def read_functions():
    data = np.loadtxt(os.path.join(HERE, "functions.dat"), ndmin=2)
    n = len(pc.FUNCTIONS)
    return (data[:, 0], {f: data[:, 1 + k] for k, f in
                         enumerate(pc.FUNCTIONS)},
            {f: data[:, 1 + n + k] for k, f in enumerate(pc.FUNCTIONS)})


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ry0", default="0.25,0.5,1")
    p.add_argument("--positions", type=int, default=1)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--report-only", action="store_true",
                   help="integrate and report from the stored functions.dat")
    opts = p.parse_args(argv)
    if not opts.report_only:
        measure(opts.positions, opts.jobs)
    gaps, measured, spread = read_functions()
    exact = pc.ExactPair(LAM)
    at_gaps = [pc.pair_functions(exact.motion, g, LAM) for g in gaps]
    # The solver's functions on a dense set of gaps: the exact ones plus
    # the measured deviation interpolated in ln(gap) (relative for m_n,
    # which vanishes with the gap; constant beyond the measured range), so
    # that the comparison carries no interpolation error of the shapes
    dense = np.exp(np.linspace(np.log(1e-3), np.log(8.0), 60))
    exact_dense = [pc.pair_functions(exact.motion, g, LAM) for g in dense]

    def solver_pair(which):
        values = {}
        for f in pc.FUNCTIONS:
            e = np.array([v[f] for v in exact_dense])
            m = np.asarray(measured[f])
            ref = np.array([v[f] for v in at_gaps])
            ok = np.isfinite(m)
            if f not in which or not ok.any():
                values[f] = e
            elif f == "mn":
                values[f] = e * np.interp(np.log(dense), np.log(gaps[ok]),
                                          m[ok] / ref[ok])
            else:
                values[f] = e + np.interp(np.log(dense), np.log(gaps[ok]),
                                          m[ok] - ref[ok])
        return pc.FunctionPair(dense, values, LAM)
    shear, loads = ("A", "B", "c1", "c2"), ("mn", "mt", "w1", "w2")
    pairs = {"exact": exact,
             "solver": solver_pair(pc.FUNCTIONS),
             "solver shear functions only": solver_pair(shear),
             "solver load functions only": solver_pair(loads)}
    law = pc.ContactLaw(lam=LAM)
    tracks = {}
    for y0 in [float(v) for v in opts.ry0.split(",")]:
        for name, pair in pairs.items():
            tracks[y0, name] = pc.trajectory(X0, y0, pair, law)
    import report
    ok = report.write(HERE, gaps, measured, spread, at_gaps, tracks,
                      TOL_OFFSET, TOL_TRAJECTORY)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
