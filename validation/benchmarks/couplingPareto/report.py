#!/usr/bin/env python3
"""Report of the coupling Pareto benchmark (see Allrun): wall time and
outer iterations against the iteration error of K, thesis against
Anderson-accelerated outer iteration."""

import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "periodicArrayDrag"))
from dragFactor import drag_factor  # noqa: E402
from fdmPost.report import write_markdown  # noqa: E402

L = 8.0


def outer_iterations(case):
    with open(os.path.join(case, "log.fdmSuspensionFoam")) as f:
        for line in f:
            if "converged in" in line or "not converged after" in line:
                return int([w for w in line.split() if w.isdigit()][0])
    return -1


def wall_time(case):
    with open(os.path.join(case, "wallTime")) as f:
        return float(f.read())


def main():
    Kref = drag_factor(os.path.join(here, "reference"), L)
    rows = []
    for policy in ["thesis", "anderson"]:
        for tol in ["1e-4", "1e-5", "1e-6"]:
            case = os.path.join(here, "%s_%s" % (policy, tol))
            if not os.path.isdir(case):
                continue
            K = drag_factor(case, L)
            rows.append((policy, float(tol), outer_iterations(case),
                         wall_time(case), abs(K - Kref) / Kref))

    lines = ["# Coupling benchmark: run time against iteration error",
             "", "Periodic-array drag, L/a = 8, Delta = a/5, one position,"
             " serial, %s. K_reference = %.8f (Anderson, lambda residual"
             " 1e-8, solver tolerances 1e-9)." % (os.uname().nodename, Kref),
             "", "| policy | lambda tol | outer its | wall s (= core-s) |"
             " |K - K_ref|/K_ref |", "|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %.0e | %d | %.1f | %.2e |" % r)
    lines.append("")
    for tol in [1e-4, 1e-5, 1e-6]:
        t = [r for r in rows if r[1] == tol and r[0] == "thesis"]
        a = [r for r in rows if r[1] == tol and r[0] == "anderson"]
        if t and a:
            lines.append("Speed-up at lambda tolerance %.0e: %.1f x in wall"
                         " time, %.1f x in outer iterations; errors %.1e"
                         " (thesis) and %.1e (Anderson)."
                         % (tol, t[0][3] / a[0][3], t[0][2] / a[0][2],
                            t[0][4], a[0][4]))
    write_markdown(os.path.join(here, "report.md"), lines)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for policy, mark in [("thesis", "s-"), ("anderson", "o-")]:
        pts = sorted((r[3], r[4]) for r in rows if r[0] == policy)
        if pts:
            plt.loglog(*np.array(pts).T, mark, label=policy)
    plt.xlabel("wall time [s] (serial)")
    plt.ylabel("|K - K_ref| / K_ref")
    plt.title("Outer-iteration policies, periodic-array drag L/a = 8")
    plt.legend()
    plt.grid(True, which="both", alpha=0.3)
    plt.savefig(os.path.join(here, "pareto.png"), dpi=120)


if __name__ == "__main__":
    main()
