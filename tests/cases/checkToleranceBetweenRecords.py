"""Checks of the toleranceBetweenRecords case test
(toleranceBetweenRecords.sh): which steps stop at which lambda residual,
and which solves the momentum balance and the HDF5 series hold."""

import os
import re
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.particleCase import momentum_balance  # noqa: E402

RECORDED, LOOSE = 1e-4, 1e-2
STEPS, INTERVAL, DT = 6, 3, 0.05


def steps(case):
    """{step: (outer iterations, lambda residual)} from the summary lines."""
    text = open(os.path.join(case, "log.fdmSuspensionFoam")).read()
    return {int(s): (int(n), float(r)) for s, n, r in re.findall(
        r"^Step (\d+) .*? outer (\d+)\s+lambdaResidual (\S+)", text, re.M)}


def solvers(case):
    """{step: (U solvers, p solvers, p solves per outer iteration)} from the
    linear-solver lines of each step (between its Time = line and its
    summary line)."""
    text = open(os.path.join(case, "log.fdmSuspensionFoam")).read()
    out = {}
    for block in re.findall(r"^Time = .*?^Step .*?$", text, re.M | re.S):
        step = int(re.search(r"^Step (\d+)", block, re.M).group(1))
        u = set(re.findall(r"^(\w+): +Solving for Ux", block, re.M))
        p = re.findall(r"^(\w+): +Solving for p,", block, re.M)
        outer = int(re.search(r" outer (\d+) ", block).group(1))
        out[step] = (u, set(p), len(p) / outer)
    return out


def main(work):
    tight, loose = steps(os.path.join(work, "tight")), steps(
        os.path.join(work, "loose"))
    recorded = [k for k in range(1, STEPS + 1) if k % INTERVAL == 0]
    between = [k for k in range(1, STEPS + 1) if k not in recorded]
    checks = []
    for k in recorded:
        checks.append(("recorded step %d: residual %.2e < %g"
                       % (k, loose[k][1], RECORDED), loose[k][1] < RECORDED))
    for k in between:
        n, r = loose[k]
        checks.append(("step %d between records: %g <= residual %.2e < %g,"
                       " %d outer iterations < %d (tight run)"
                       % (k, RECORDED, r, LOOSE, n, tight[k][0]),
                       RECORDED <= r < LOOSE and n < tight[k][0]))
    used = solvers(os.path.join(work, "loose"))
    for k in range(1, STEPS + 1):
        expected = ({"smoothSolver"}, {"GAMG"}, 1) if k in between \
            else ({"DICPCG"}, {"DICPCG"}, 2)
        checks.append(("step %d: U by %s, p by %s, %g p solves per outer"
                       " iteration (expected %s, %s, %d)"
                       % ((k,) + tuple(map(sorted, used[k][:2]))
                          + used[k][2:] + tuple(map(sorted, expected[:2]))
                          + expected[2:]), used[k] == expected))
    times = np.round(momentum_balance(os.path.join(work, "loose"))["time"]
                     / DT).astype(int)
    checks.append(("momentumBalance.dat at steps %s (expected 0 and %s)"
                   % (list(times), recorded),
                   list(times) == [0] + recorded))
    with h5py.File(os.path.join(work, "loose", "postProcessing",
                                "particles.h5"), "r") as f:
        records = list(np.round(np.asarray(f["time"]) / DT).astype(int))
    checks.append(("particles.h5 records at steps %s" % records,
                   records == [0] + recorded))
    for text, ok in checks:
        print("   %s %s" % (text, "PASS" if ok else "FAILED"))
    return 0 if all(ok for _, ok in checks) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
