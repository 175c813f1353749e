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

The cell walls.  A free pair's stresslets reflect from the walls 4-5 a1
away and lower A and B (at gap 4 by a third).  The shear functions are
therefore measured again at one position in 16 a1 and 20 a1 cells
(CELL_RUNS, cellSize.dat) and the change from the 12 a1 cell at that
position is added to the 12 a1 set (interpolated in ln gap): the mobility
'solver, largest cells', on which the verdict is taken.

    ./Allrun [--ry0 0.25,0.5,1] [--positions 2] [--jobs 2] [--cell-sizes]
             [--report-only]

writes functions.dat (cellSize.dat with --cell-sizes), report.md and
pairContactShear.png here (cases in build/validation/pairContactShear).
About 30 min on 2 cores, and about 2 h more for the cell sizes.
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
# The cell walls: the shear functions at one position in larger cells
CELL_RUNS = ((12.0, (0.03, 0.3, 1.0, 4.0)), (16.0, (0.03, 0.3, 1.0, 4.0)),
             (20.0, (1.0, 4.0)))
CELL_OFFSET = (0.0, 0.0, 0.0)
SHEAR = ("A", "B", "c1", "c2")
WORK = os.path.join(os.environ["FDM_PROJECT_DIR"], "build", "validation",
                    "pairContactShear")
TOL_OFFSET = 0.03      # exit offset, relative
TOL_TRAJECTORY = 0.05  # r_y, in a1


def probe(gap, kind, offset, work, cell=L):
    """U2 - U1, W1, W2 of one frozen configuration (pairContact's probe)
    in a Couette cell of side `cell`."""
    dist = gap + 1 + LAM
    d, sheared, F1, T1, T2 = pc.probe_set_up(kind, gap, LAM)
    centre = np.asarray(offset) * DELTA + 0.013   # off the mesh nodes
    case = os.path.join(work, "gap%g_%s_%s" % (
        gap, kind, "_".join("%g" % o for o in offset)))
    fill_template(os.path.join(HERE, "template"), case, {
        "@L@": "%g" % cell, "@L2@": "%g" % (cell / 2),
        "@H2@": "%g" % (cell / 2),
        "@UW@": "%g" % (cell / 2 if sheared else 0.0),
        "@N@": "%d" % round(cell / DELTA),
        "@ENDTIME@": "1e-3", "@DT@": "1e-3", "@WRITEINTERVAL@": "1",
        "@LAMBDATOL@": "%g" % LAMBDA_TOL,
        "@X1@": vec(centre - 0.5 * dist * d),
        "@X2@": vec(centre + 0.5 * dist * d), "@F1@": vec(F1),
        "@F2@": vec(-F1), "@T1@": vec(T1), "@T2@": vec(T2)})
    s = run_case(case)
    V = s["velocity"][1] - s["velocity"][0]
    return V, s["angularVelocity"][0], s["angularVelocity"][1]


def run_probes(tasks, jobs):
    """probe(gap, kind, offset, work, cell) for every task (a dict key ->
    those arguments) on `jobs` processes; returns key -> result."""
    found = {}
    with concurrent.futures.ProcessPoolExecutor(jobs) as pool:
        futures = {pool.submit(probe, *args): key
                   for key, args in tasks.items()}
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            key = futures[fut]
            found[key] = fut.result()
            gap, kind, _, _, cell = tasks[key]
            print("  [%d/%d] cell %g gap %g %s" % (i + 1, len(tasks), cell,
                                                   gap, kind), flush=True)
    return found


def measure(positions, jobs):
    offsets = [tuple(o) for o in cell_offsets(positions, 3)]
    found = run_probes({(g, k, o): (g, k, o, WORK, L) for g in GAPS
                        for k in pc.PROBES for o in offsets
                        if k.startswith("shear") or g in CONTACT_GAPS}, jobs)
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


def measure_cells(jobs):
    """The shear functions at one position (CELL_OFFSET) in the cells of
    CELL_RUNS, into cellSize.dat (rows already there are kept)."""
    path = os.path.join(HERE, "cellSize.dat")
    done = {(row[0], row[1]) for row in read_cells()} \
        if os.path.exists(path) else set()
    found = run_probes({
        (c, g, k): (g, k, CELL_OFFSET, os.path.join(WORK, "cell%g" % c), c)
        for c, gaps in CELL_RUNS for g in gaps for k in ("shear0", "shear45")
        if (c, g) not in done}, jobs)
    new = not os.path.exists(path)
    with open(path, "a") as f:
        if new:
            f.write("# cell gap A B c1 c2  (shear functions at offset %s"
                    " Delta in cells of side `cell` a1)\n"
                    % " ".join("%g" % o for o in CELL_OFFSET))
        for c, g in sorted({(c, g) for c, g, _ in found}):
            fn = pc.functions_from_probes(g, LAM, {
                k: found[c, g, k] for k in ("shear0", "shear45")})
            f.write("%g %g " % (c, g) + " ".join("%.8g" % fn[k] for k in
                                               SHEAR) + "\n")


def read_cells():
    """Rows (cell, gap, A, B, c1, c2) of cellSize.dat."""
    return np.loadtxt(os.path.join(HERE, "cellSize.dat"), ndmin=2)


def wall_corrections(cells, extrapolate):
    """Change of each shear function from the 12 a1 cell to the largest
    cell measured at the same position, per gap of cellSize.dat; with
    `extrapolate`, on to L -> infinity as F = F_inf + c L^-3 (the decay of
    a force dipole's images) from the two largest cells.  Returns (gaps,
    {function: correction})."""
    gaps = np.unique(cells[:, 1])
    out = {f: [] for f in SHEAR}
    for g in gaps:
        rows = cells[cells[:, 1] == g]
        rows = rows[np.argsort(rows[:, 0])]
        base, top = rows[0], rows[-1]
        if base[0] != L:
            raise SystemExit("cellSize.dat: no %g a1 row at gap %g" % (L, g))
        for k, f in enumerate(SHEAR):
            d = top[2 + k] - base[2 + k]
            if extrapolate and len(rows) > 1:
                prev = rows[-2]
                d += (top[2 + k] - prev[2 + k]) * top[0]**-3 / (
                    prev[0]**-3 - top[0]**-3)
            out[f].append(d)
    return gaps, {f: np.array(v) for f, v in out.items()}


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
    p.add_argument("--cell-sizes", action="store_true",
                   help="also measure the shear functions in the larger"
                        " cells of CELL_RUNS (about 2 h on 2 cores)")
    p.add_argument("--report-only", action="store_true",
                   help="integrate and report from the stored functions.dat")
    opts = p.parse_args(argv)
    if not opts.report_only:
        measure(opts.positions, opts.jobs)
    if opts.cell_sizes:
        measure_cells(opts.jobs)
    gaps, measured, spread = read_functions()
    exact = pc.ExactPair(LAM)
    at_gaps = [pc.pair_functions(exact.motion, g, LAM) for g in gaps]
    # The solver's functions on a dense set of gaps: the exact ones plus
    # the measured deviation interpolated in ln(gap) (relative for m_n,
    # which vanishes with the gap; constant beyond the measured range), so
    # that the comparison carries no interpolation error of the shapes
    dense = np.exp(np.linspace(np.log(1e-3), np.log(8.0), 60))
    exact_dense = [pc.pair_functions(exact.motion, g, LAM) for g in dense]

    def solver_pair(which, walls=None):
        values = {}
        for f in pc.FUNCTIONS:
            e = np.array([v[f] for v in exact_dense])
            m = np.asarray(measured[f])
            if walls is not None and f in walls[1]:
                m = m + np.interp(np.log(gaps), np.log(walls[0]),
                                  walls[1][f])
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
    shear, loads = SHEAR, ("mn", "mt", "w1", "w2")
    pairs = {"exact": exact,
             "solver": solver_pair(pc.FUNCTIONS),
             "solver shear functions only": solver_pair(shear),
             "solver load functions only": solver_pair(loads)}
    cells = None
    if os.path.exists(os.path.join(HERE, "cellSize.dat")):
        cells = read_cells()
        pairs["solver, largest cells"] = solver_pair(
            pc.FUNCTIONS, wall_corrections(cells, False))
        pairs["solver, cell walls extrapolated"] = solver_pair(
            pc.FUNCTIONS, wall_corrections(cells, True))
    law = pc.ContactLaw(lam=LAM)
    tracks = {}
    for y0 in [float(v) for v in opts.ry0.split(",")]:
        for name, pair in pairs.items():
            tracks[y0, name] = pc.trajectory(X0, y0, pair, law)
    import report
    ok = report.write(HERE, gaps, measured, spread, at_gaps, tracks,
                      TOL_OFFSET, TOL_TRAJECTORY, cells, exact)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
