#!/usr/bin/env python3
"""Issue 38: the same results serially and on 2, 4 and 8 ranks with the
particle system solved by subdomain, within the solver's tolerances.

The Couette tutorial as it ships (25 bidisperse spheres at phi0 0.3
between walls, frameInvariant sub-grid lubrication, hertz contacts with
friction, 8^3 a1 at Delta = a1/5) runs --steps steps from its packing
(seed 1), every step recorded, serially and on 2 (2 1 1), 4 (4 1 1) and
8 (2 2 2) ranks with parallelParticleSolve distributed (and on 2 ranks
replicated, the scheme it replaces), at two sets of tolerances: the
tutorial's (lambda residual 1e-3, particle solve 1e-6, pressure relTol
as shipped) and tight ones (1e-6, 1e-10, pressure and velocity to 1e-10
absolute).  Each parallel run's positions, velocities and stresslets are
compared with the serial run of the same tolerances, record by record.
Where the differences shrink with the tolerances, they are the solvers'
stopping, not the decomposition.  Ranks beyond the cores share them.

    ranksAgreement.py [--steps 25] [--ranks 2,4,8] [--length 8]
                      [--tolerances tutorial,tight]

writes ranksAgreement.md here (cases in build/benchmarks/particleDistribution
/agreement).  --length stretches the box along the flow (x, periodic) at
the same phi and Delta, so that a rank's slab is narrower than the box by
more than the particles' reach and holds only some of them (the owned
state of fdm::particleHalo); the report is then ranksAgreement_L<length>.md.
"""

import argparse
import os
import re
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ["FDM_PROJECT_DIR"]
TUTORIAL = os.path.join(PROJECT, "tutorials", "couette")
sys.path.insert(0, os.path.join(PROJECT, "src", "python"))
from fdmPost.caseRunner import (copy_case, foam_get, foam_set,  # noqa
                                run_logged, solver_command, work_lock)

DECOMPOSITION = {2: "(2 1 1)", 4: "(4 1 1)", 8: "(2 2 2)"}
TOLERANCES = {
    "tutorial": {},
    "tight": {"coupling.lambdaTolerance": 1e-6,
              "coupling.lambdaToleranceFirstStep": 1e-6,
              "coupling.lambdaToleranceBetweenRecords": 1e-6,
              "coupling.particleSolveTolerance": 1e-10},
}
TIGHT_FLOW = {"solvers.p.tolerance": 1e-10, "solvers.p.relTol": 0,
              "solvers.U.tolerance": 1e-10, "solvers.U.relTol": 0}


def make_case(work, tolerances, steps, length):
    """The packed and meshed tutorial at these tolerances and steps, its box
    length along x, run by none (the runs made from it are kept and
    reused)."""
    case = os.path.join(work, "%s_%dsteps%s" % (
        tolerances, steps, "" if length == 8 else "_L%d" % length))
    if os.path.isfile(os.path.join(case, "constant", "polyMesh", "owner")):
        return case
    copy_case(TUTORIAL, case)
    # By text: foamDictionary -set would write the vertices' $Lx expanded
    mesh = os.path.join(case, "system", "blockMeshDict")
    text = open(mesh).read()
    for key, value in (("Lx", length), ("nx", 5 * length)):
        text = re.sub(r"^%s .*$" % key, "%s      %d;" % (key, value), text,
                      flags=re.M)
    open(mesh, "w").write(text)
    props = "constant/particleProperties"
    foam_set(case, "output.timeSeriesInterval", 1, props)
    for key, value in TOLERANCES[tolerances].items():
        foam_set(case, key, value, props)
    if tolerances == "tight":
        for key, value in TIGHT_FLOW.items():
            foam_set(case, key, value, "system/fvSolution")
    control = "system/controlDict"
    dt = float(foam_get(case, "deltaT", control))
    foam_set(case, "endTime", steps * dt, control)
    foam_set(case, "writeInterval", steps, control)
    foam_set(case, "functions", "{}", control)
    run_logged(["fdmPackParticles", "--box", str(length), "8", "8",
                "--walls", "y",
                "--phi", "0.3", "--seed", "1", "-o",
                "constant/particleList"], case, "log.fdmPackParticles")
    run_logged(["blockMesh"], case, "log.blockMesh")
    return case


def run(base, ranks, scheme):
    """The run of base on ranks ranks; its particle series."""
    case = "%s_%d_%s" % (base, ranks, scheme)
    if not os.path.isfile(os.path.join(case, "postProcessing",
                                       "particles.h5")):
        copy_case(base, case)
        foam_set(case, "coupling.parallelParticleSolve", scheme,
                 "constant/particleProperties")
        run_logged(solver_command(case, ranks, DECOMPOSITION.get(ranks)),
                   case, "log.fdmSuspensionFoam")
    with h5py.File(os.path.join(case, "postProcessing", "particles.h5"),
                   "r") as f:
        return {k: f[k][:] for k in ("time", "position", "velocity",
                                     "angularVelocity", "stresslet")}


def differences(serial, other):
    """Largest differences over the records: positions in a1, velocities
    over the wall speed, stresslets over the largest serial one."""
    if len(other["time"]) != len(serial["time"]):
        raise RuntimeError("%d records against %d serially"
                           % (len(other["time"]), len(serial["time"])))
    wall = 4.0      # the tutorial's walls move at -+4 a1 gammaDot
    scale = {"position": 1, "velocity": wall, "angularVelocity": 1,
             "stresslet": np.abs(serial["stresslet"]).max()}
    return {k: np.abs(other[k] - serial[k]).max() / s
            for k, s in scale.items()}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=25)
    parser.add_argument("--ranks", default="2,4,8")
    parser.add_argument("--length", type=int, default=8)
    parser.add_argument("--tolerances", default=",".join(TOLERANCES))
    args = parser.parse_args()
    work = os.path.join(PROJECT, "build", "benchmarks",
                        "particleDistribution", "agreement")
    os.makedirs(work, exist_ok=True)
    lock = work_lock(work)
    lines = [
        "# Serial against 2, 4 and 8 ranks, solved by subdomain",
        "",
        "`ranksAgreement.py --steps %d --ranks %s --length %d` (%s, %d "
        "cores): the Couette tutorial (%s a1, Delta a1/5), %d steps of "
        "gammaDot dt 4e-3 from its packing; the largest difference from "
        "the serial run over the records: positions in a1, velocities over "
        "the wall speed 4 a1 gammaDot, angular velocities over gammaDot, "
        "stresslets over the largest serial one." % (
            args.steps, args.ranks, args.length, os.uname().nodename,
            os.cpu_count(),
            "8^3" if args.length == 8 else "%d x 8 x 8" % args.length,
            args.steps), "",
        "| tolerances | ranks | scheme | position | velocity | angular "
        "velocity | stresslet |", "|---|---|---|---|---|---|---|"]
    for tolerances in args.tolerances.split(","):
        base = make_case(work, tolerances, args.steps, args.length)
        serial = run(base, 1, "replicated")
        runs = [(2, "replicated")] + [
            (int(n), "distributed") for n in args.ranks.split(",")]
        for ranks, scheme in runs:
            d = differences(serial, run(base, ranks, scheme))
            lines.append("| %s | %d | %s | %.1e | %.1e | %.1e | %.1e |" % (
                tolerances, ranks, scheme, d["position"], d["velocity"],
                d["angularVelocity"], d["stresslet"]))
            print(lines[-1], flush=True)
    report = "ranksAgreement%s.md" % (
        "" if args.length == 8 else "_L%d" % args.length)
    open(os.path.join(HERE, report), "w").write(
        "\n".join(lines) + "\n")
    print("\n".join(lines))
    lock.close()


if __name__ == "__main__":
    main()
