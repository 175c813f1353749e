#!/usr/bin/env python3
"""Checks of dataSafety.sh after the kill -9 attempts.

Reference: the uninterrupted run of the same case.  Restarts read the
particle state and fields at full precision, so the killed-and-restarted
run must end in the same state to round-off (1e-12 relative), and its
particles.h5 must hold every step 0, 0.05, .., 0.4 exactly once with the
straight run's values: no record lost, none twice, none half-written
(time 0 or zero positions in the middle), no non-finite value.
"""

import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.particleCase import particle_state  # noqa: E402
from fdmPost.checks import Checks  # noqa: E402

work = sys.argv[1]
checks = Checks()
check = checks.check

a = particle_state(os.path.join(work, "straight"), "0.4")
b = particle_state(os.path.join(work, "killed"), "0.4")
checks.same_state("killed+restarted vs straight", a, b)


def series(case):
    with h5py.File(os.path.join(work, case, "postProcessing",
                                "particles.h5"), "r") as f:
        return {k: f[k][:] for k in ["time", "position", "velocity"]}


s, k = series("straight"), series("killed")
expected = 0.05 * np.arange(9)
for name, d in [("straight", s), ("killed", k)]:
    t = d["time"]
    check("%s: HDF5 times differ from 0, 0.05 .. 0.4" % name,
          float(len(t) != len(expected))
          + (np.abs(t - expected).max() if len(t) == len(expected) else 1),
          1e-12)
    check("%s: non-finite values in the series" % name,
          float(sum((~np.isfinite(v)).sum() for v in d.values())), 0)
if len(k["time"]) == len(s["time"]):
    for key in ["position", "velocity"]:
        check("killed vs straight series %s (relative)" % key,
              np.abs(k[key] - s[key]).max() / np.abs(s[key]).max(), 1e-12)

checks.finish()
