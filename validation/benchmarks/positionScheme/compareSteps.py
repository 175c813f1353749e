#!/usr/bin/python3
"""The runs of adhesive.sh record by record against the smallest step.

    compareSteps.py WORK

WORK/dt<DT>_records<R>/ each hold a run from one state and its core
records (records/coreRecords.csv, fdmPost.checkpoint save).  Per run: the
core eta (eq 2.76), contact share, N1/Sigma_xy and N2/Sigma_xy
(fdmPost.rheology.core_series), their means over the window and their
differences from the run of the smallest step with records every 0.02
strain, interpolated to the same times (the records of two steps fall at
different times); the cost from the solver's last Timing line (core-s per
strain on 2 ranks) and the outer iterations per step.  A Markdown table
on standard output.
"""

import glob
import os
import re
import sys

import numpy as np

from fdmPost.coreRecords import CoreRecords
from fdmPost.rheology import core_series

NAMES = ("eta_core", "N1/Sigma_xy", "N2/Sigma_xy", "contact share")
TIMING = re.compile(r"Timing \[s\] after (\d+) outer iterations in (\d+) "
                    r"step\(s\): total ([0-9.eE+-]+)")
RANKS = 2


def run_of(case):
    records = CoreRecords.read(os.path.join(case, "records",
                                            "coreRecords.csv"))
    dt, interval = re.match(r"dt([0-9.e-]+)_records([0-9.]+)$",
                            os.path.basename(case)).groups()
    with open(os.path.join(case, "log.fdmSuspensionFoam")) as f:
        outer, steps, total = TIMING.findall(f.read())[-1]
    return {"dt": float(dt), "interval": float(interval),
            "t": records.t, "values": core_series(records),
            "window": int(steps) * float(dt),
            "coreSeconds": RANKS * float(total),
            "outerPerStep": int(outer) / int(steps)}


def main(argv):
    runs = [run_of(c) for c in sorted(glob.glob(os.path.join(
        argv[0], "dt*_records*"))) if os.path.isfile(
            os.path.join(c, "records", "coreRecords.csv"))]
    dense = [r for r in runs if r["interval"] <= 0.02]
    ref = min(dense, key=lambda r: r["dt"])
    print("| gammaDot dt | records every | core-s per strain | outer per "
          "step | " + " | ".join(f"{n} mean (diff)" for n in NAMES)
          + " | rms diff eta_core |")
    print("|" + "---|" * (5 + len(NAMES)))
    for r in sorted(runs, key=lambda r: (r["interval"], r["dt"])):
        cells = [f"{r['dt']:g}", f"{r['interval']:g}",
                 f"{r['coreSeconds'] / r['window']:.0f}",
                 f"{r['outerPerStep']:.1f}"]
        inside = (r["t"] >= ref["t"][0]) & (r["t"] <= ref["t"][-1])
        diff = np.array([r["values"][inside, k] - np.interp(
            r["t"][inside], ref["t"], ref["values"][:, k])
            for k in range(len(NAMES))])
        for k in range(len(NAMES)):
            mean = r["values"][:, k].mean()
            cells.append(f"{mean:.4g} ({diff[k].mean():+.3g})"
                         if r is not ref and inside.any()
                         else f"{mean:.4g}")
        cells.append(f"{np.sqrt((diff[0] ** 2).mean()):.3g}"
                     if r is not ref and inside.any() else "–")
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
