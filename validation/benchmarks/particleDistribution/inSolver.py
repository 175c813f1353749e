#!/usr/bin/env python3
"""Issue 38 measured in the solver: wall time per step, split as the
solver's Timing report splits it, and peak memory per rank of
fdmSuspensionFoam against the particle count and the rank count, with the
particle system solved whole on every rank (parallelParticleSolve
replicated) and by subdomain (distributed).

The case is tutorials/couette at a larger size: monodisperse spheres
(a = 1) at phi 0.3 (--phi) between walls moving at +-L/2 (shear rate 1),
packed by fdmPackParticles (seed 1) in an L^3 box with L from N, hertz
contacts as in the tutorial.  Delta = a/2 keeps the fluid affordable at
3 10^4 particles on this machine (10^5 at phi 0.5: 6.6e6 cells), so there
is no sub-grid lubrication (its tables are for Delta = a/4 .. a/6) and
the indicator work per particle is (5/2)^3 times smaller than at the
thesis' a/5: this measures how the particle work grows with N and ranks,
not the cost of a production step.  Every step is solved to a lambda
residual of 1e-3; the cost per step is that of steps 2 .. --steps - 1
(the first pays the set-up and the initial solve, the last writes the
fields, the cloud and the restart state).  The domain is cut into slabs
along x, one per rank.  Ranks beyond the cores share them: their wall
times are then upper bounds.

    inSolver.py [--sizes 1000,10000] [--ranks 1,2,4] [--steps 4]
                [--phi 0.3] [--record] [--report inSolver.md]

writes the report here (cases in build/benchmarks/particleDistribution).
--record writes the particle time series (particles.h5) at every
step, so that the output column holds the master's gather and write.
"""

import argparse
import os
import re
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ["FDM_PROJECT_DIR"]
TUTORIAL = os.path.join(PROJECT, "tutorials", "couette")
CELLS_PER_A, DT, TOL = 2, 4e-3, 1e-3
sys.path.insert(0, os.path.join(PROJECT, "src", "python"))
from fdmPost.caseRunner import (TIMING_COLUMNS, copy_case,  # noqa: E402
                                foam_set, run_logged, run_measured,
                                solver_command, timing_lines, work_lock)

PARTS = ("flow", "indicators", "integrals", "particleSolve", "corrections",
         "pairs", "acceleration")
SHOWN = PARTS + ("output",)


def box_side(n, phi):
    """The box edge [a] holding n unit spheres at phi."""
    return int(round((n * 4.0 / 3.0 * np.pi / phi) ** (1.0 / 3.0)))


def base_case(work, n, phi):
    """The packed and meshed case of about n particles, run by none."""
    case = os.path.join(work, "N%d" % n + ("" if phi == 0.3 else
                                           "_phi%g" % phi))
    if os.path.isfile(os.path.join(case, "constant", "polyMesh", "owner")):
        return case
    copy_case(TUTORIAL, case)
    L = box_side(n, phi)
    mesh = os.path.join(case, "system", "blockMeshDict")
    text = open(mesh).read()
    for k, v in (("Lx", L), ("Ly", L), ("Lz", L)) + tuple(
            (k, CELLS_PER_A * L) for k in ("nx", "ny", "nz")):
        text = re.sub(r"^%s .*$" % k, "%s      %d;" % (k, v), text, flags=re.M)
    open(mesh, "w").write(text)
    for wall, sign in (("bottomWall", -1), ("topWall", 1)):
        foam_set(case, "boundaryField.%s.value" % wall,
                 "uniform (%g 0 0)" % (sign * L / 2.0), "0/U")
    props = "constant/particleProperties"
    foam_set(case, "subGrid", "{ model none; }", props)
    for key in ("lambdaTolerance", "lambdaToleranceFirstStep",
                "lambdaToleranceBetweenRecords"):
        foam_set(case, "coupling." + key, TOL, props)
    foam_set(case, "deltaT", DT, "system/controlDict")
    foam_set(case, "writeInterval", 1000, "system/controlDict")
    foam_set(case, "functions", "{}", "system/controlDict")
    run_logged(["fdmPackParticles", "--box", str(L), str(L), str(L),
                "--walls", "y", "--phi", str(phi), "--ratio", "1",
                "--seed", "1", "-o", "constant/particleList"],
               case, "log.fdmPackParticles")
    run_logged(["blockMesh"], case, "log.blockMesh")
    return case


def run_point(base, scheme, ranks, steps, record):
    """One run of steps steps; its per-step costs and peak memory."""
    case = "%s_%s_%d" % (base, scheme, ranks)
    copy_case(base, case)
    foam_set(case, "output.timeSeriesInterval", 1 if record else 1000,
             "constant/particleProperties")
    foam_set(case, "coupling.parallelParticleSolve", scheme,
             "constant/particleProperties")
    foam_set(case, "endTime", steps * DT, "system/controlDict")
    wall, peak = run_measured(solver_command(case, ranks), case,
                              "log.fdmSuspensionFoam")
    log = open(os.path.join(case, "log.fdmSuspensionFoam")).read()
    timing = timing_lines(log)
    first, last = (dict(zip(TIMING_COLUMNS, timing[i])) for i in (0, -2))
    n = last["steps"] - first["steps"]
    per = {k: (last[k] - first[k]) / n for k in TIMING_COLUMNS}
    per["other"] = per["total"] - sum(per[k] for k in SHOWN)
    per.update(peakMiB=peak / 1024.0, wall=wall,
               particles=int(re.search(r"(\d+) particles", log).group(1)))
    shutil.rmtree(case, ignore_errors=True)
    return per


def table(rows):
    head = ("| N | scheme | ranks | s/step | outer/step | "
            + " | ".join(SHOWN) + " | other | peak MiB/rank |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for r in rows:
        lines.append(
            "| %d | %s | %d | %.3f | %.1f | " % (
                r["particles"], r["scheme"], r["ranks"], r["total"],
                r["outer"])
            + " | ".join("%.4f" % r[k] for k in SHOWN)
            + " | %.4f | %.0f |" % (r["other"], r["peakMiB"]))
    return lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", default="1000,10000")
    parser.add_argument("--ranks", default="1,2,4")
    parser.add_argument("--steps", type=int, default=4)
    parser.add_argument("--phi", type=float, default=0.3)
    parser.add_argument("--record", action="store_true")
    parser.add_argument("--report", default="inSolver.md")
    args = parser.parse_args()
    if args.steps < 3:
        parser.error("--steps must be at least 3: the first and the last"
                     " step are not timed")
    work = os.path.join(PROJECT, "build", "benchmarks",
                        "particleDistribution")
    lock = work_lock(work)
    rows = []
    for n in (int(s) for s in args.sizes.split(",")):
        base = base_case(work, n, args.phi)
        for ranks in (int(r) for r in args.ranks.split(",")):
            for scheme in ("replicated", "distributed")[:1 + (ranks > 1)]:
                r = run_point(base, scheme, ranks, args.steps, args.record)
                r.update(scheme=scheme, ranks=ranks)
                rows.append(r)
                print(table([r])[-1], flush=True)
    lines = [
        "# Particle work in the solver, replicated against by subdomain",
        "",
        "`inSolver.py %s` on %s (%d cores): "
        "Couette, monodisperse a = 1, phi %g, Delta = a/%d, hertz contacts, "
        "no sub-grid, lambda residual %g, gammaDot dt %g; wall seconds per "
        "step over steps 2 .. %d, the columns of the solver's Timing report "
        "(flow: the SIMPLEC solves; acceleration: the outer iteration's "
        "Anderson step; output: the time series, gathered on the master "
        "and written, at every step with --record; other: the move, state "
        "copies, logging). Ranks beyond the cores share them." % (
            " ".join(sys.argv[1:]), os.uname().nodename,
            os.cpu_count(), args.phi, CELLS_PER_A, TOL, DT, args.steps - 1),
        ""] + table(rows)
    open(os.path.join(HERE, args.report), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    lock.close()


if __name__ == "__main__":
    main()
