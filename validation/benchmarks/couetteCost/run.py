#!/usr/bin/env python3
"""Benchmark (issue 6, item 2): cost per time step of the Couette
suspension of thesis 1, Table 4.7 (phi0 = 0.42, 20 a1 cube, Delta = a1/5:
10^6 cells, 547 bidisperse spheres), against the published Table 4.9
(0.40-0.91 s per step on 64-128 cores: 38-84 core-seconds per step per
10^6 cells, about 10 SIMPLEC/lambda loops per step).

One base run packs the suspension (fdmPackParticles, seed 1), builds the
tutorials/couette set-up at that size (frameInvariant sub-grid
lubrication, hertz contacts, shear rate 1) and solves the initial state
and one step of 1e-3 from rest.  Every policy NAME@DT then restarts from
that state for --steps steps of gammaDot dt = DT and is timed on steps
2.. (the first restarted step pays the set-up).  The thesis' step is
gammaDot dt = 1e-4; the implicit contact stiffness lets the tutorial run
at 4e-3, so the cost per unit strain is reported next to the cost per
step.  Policies:

  anderson      the default: Anderson-accelerated outer iteration to
                lambda residual 1e-4 per step (serial, and on 2 ranks)
  thesis        the thesis scheme (plain SIMPLEC + explicit lambda
                correction) to the same lambda residual 1e-4
  thesis10      the thesis scheme with its fixed 10 loops per step
                (residual reached is reported)
  andersonGAMG  anderson with the pressure solved by GAMG (Gauss-Seidel
                smoother); all others use DIC-preconditioned CG (the
                tutorial's choice before this benchmark)

Columns as Table 4.9: flow solve, indicator/forcing work (indicators,
lambda/u integrals, corrections), particle assembly and solve, output;
plus acceleration and the rest.  Memory: peak resident set size of the
largest process (one rank), from getrusage.

    ./Allrun [--steps 3] [--thesis-steps 2] [--policies NAME@DT,...]

writes report.md here (cases in build/benchmarks/couetteCost).  About
30 min on 2 cores.
"""

import argparse
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.environ["FDM_PROJECT_DIR"]
TUTORIAL = os.path.join(PROJECT, "tutorials", "couette")
L, CELLS, PHI0, DT, TOL = 20, 100, 0.42, 1e-3, 1e-4
sys.path.insert(0, os.path.join(PROJECT, "src", "python"))
from fdmPost.caseRunner import (copy_case, foam_set, run_logged,  # noqa
                                run_measured, solver_command, timing_lines)


def base_case(work):
    case = os.path.join(work, "base")
    if os.path.isfile(os.path.join(case, "%g" % DT, "particleState")):
        return case
    copy_case(TUTORIAL, case)
    shutil.rmtree(os.path.join(case, "constant", "polyMesh"),
                  ignore_errors=True)
    # sed, not foamDictionary, which would expand the $Lx macros
    mesh = os.path.join(case, "system", "blockMeshDict")
    text = open(mesh).read()
    for k, v in (("Lx", L), ("Ly", L), ("Lz", L), ("nx", CELLS),
                 ("ny", CELLS), ("nz", CELLS)):
        text = re.sub(r"^%s .*$" % k, "%s      %d;" % (k, v), text, flags=re.M)
    open(mesh, "w").write(text)
    foam_set(case, "boundaryField.bottomWall.value",
             "uniform (-%g 0 0)" % (L / 2), "0/U")
    foam_set(case, "boundaryField.topWall.value",
             "uniform (%g 0 0)" % (L / 2), "0/U")
    foam_set(case, "deltaT", DT, "system/controlDict")
    foam_set(case, "endTime", DT, "system/controlDict")
    foam_set(case, "writeInterval", 1, "system/controlDict")
    foam_set(case, "startFrom", "latestTime", "system/controlDict")
    # Every step to TOL (the tutorial's steps between records are looser)
    for key in ("lambdaTolerance", "lambdaToleranceFirstStep",
                "lambdaToleranceBetweenRecords"):
        foam_set(case, "coupling." + key, TOL, "constant/particleProperties")
    run_logged(["fdmPackParticles", "--box", str(L), str(L), str(L),
                "--walls", "y", "--phi", str(PHI0), "--seed", "1", "-o",
                "constant/particleList"], case, "log.fdmPackParticles")
    run_logged(["blockMesh"], case, "log.blockMesh")
    run_logged(["fdmSuspensionFoam"], case, "log.fdmSuspensionFoam")
    return case


def policy_case(work, base, name, dt, steps):
    case = os.path.join(work, "%s_dt%g" % (name, dt))
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(case)
    for d in ("constant", "system", "%g" % DT):
        shutil.copytree(os.path.join(base, d), os.path.join(case, d))
    foam_set(case, "deltaT", dt, "system/controlDict")
    foam_set(case, "endTime", DT + dt * steps, "system/controlDict")
    foam_set(case, "writeInterval", 1000, "system/controlDict")
    fv = "system/fvSolution"
    if name.startswith("thesis"):
        foam_set(case, "SIMPLEC.acceleration", "none", fv)
        foam_set(case, "SIMPLEC.nOuterCorrectors", 3000, fv)
    # The pressure solver is set here, not taken from the tutorial (which
    # uses GAMG since this benchmark measured it faster)
    solver = ("GAMG; smoother GaussSeidel" if name == "andersonGAMG"
              else "PCG; preconditioner DIC")
    foam_set(case, "solvers.p",
             "{ solver %s; tolerance 1e-7; relTol 0.05; }" % solver, fv)
    if name == "thesis10":
        foam_set(case, "SIMPLEC.nOuterCorrectors", 10, fv)
        for key in ("lambdaTolerance", "lambdaToleranceBetweenRecords"):
            foam_set(case, "coupling." + key, 0,
                     "constant/particleProperties")
    return case


def parse(case):
    """Per-step costs of steps 2.. from the cumulative Timing lines, and
    the lambda residual at the end of every step."""
    text = open(os.path.join(case, "log.fdmSuspensionFoam")).read()
    t = timing_lines(text)
    if len(t) < 2:
        raise RuntimeError("fewer than two Timing lines in %s" % case)
    first, last = t[0], t[-1]
    n = last[1] - first[1]
    d = [(b - a) / n for a, b in zip(first, last)]
    residuals = []
    for block in text.split("Timing [s]")[:-1]:
        r = re.findall(r"lambda residual (\S+),", block)
        if r:
            residuals.append(float(r[-1]))
    contacts = re.findall(r"Contacts: (\d+) pairs", text)
    return {
        "steps": int(n), "outer": d[0], "total": d[2], "flow": d[3],
        "forcing": d[4] + d[5] + d[7], "particles": d[6],
        "acceleration": d[8], "output": d[9], "pairs": d[10],
        "rest": d[2] - sum(d[3:11]),
        "residual": max(residuals[1:]) if len(residuals) > 1 else float("nan"),
        "contacts": int(contacts[-1]) if contacts else 0,
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=3)
    parser.add_argument("--thesis-steps", type=int, default=2,
                        help="steps of the unaccelerated scheme to the "
                        "lambda residual (hundreds of loops per step)")
    parser.add_argument(
        "--policies", default="anderson@1e-4,anderson2@1e-4,thesis10@1e-4,"
        "andersonGAMG@1e-4,anderson@1e-3,anderson@4e-3,thesis@1e-4")
    args = parser.parse_args()
    work = os.path.join(PROJECT, "build", "benchmarks", "couetteCost")
    os.makedirs(work, exist_ok=True)
    base = base_case(work)
    rows = []
    for policy in args.policies.split(","):
        name, dt = policy.split("@")
        dt = float(dt)
        nprocs = 2 if name.endswith("2") else 1
        steps = args.thesis_steps if name == "thesis" else args.steps
        case = policy_case(work, base, name, dt, steps)
        wall, peak = run_measured(solver_command(case, nprocs), case,
                                  "log.fdmSuspensionFoam")
        r = parse(case)
        r.update(name=name, dt=dt, nprocs=nprocs, wall=wall, peak=peak)
        rows.append(r)
        print("%s: %.1f s per step, %.1f outer iterations" % (
            policy, r["total"], r["outer"]), flush=True)
    sys.path.insert(0, HERE)
    import report
    report.main(rows, base, CELLS ** 3 / 1e6)


if __name__ == "__main__":
    main()
