#!/usr/bin/env python3
"""Checks of restartContinuity.sh.

Reference: the uninterrupted run.  A restart reads positions, velocities
and the Adams-Bashforth history at full precision and the fields written
with 17 digits (exact for doubles), so the restarted trajectory must agree
to round-off (1e-12 relative).  The particles must have moved (so that the
comparison means something) and the HDF5 series must hold each of the 5
times (0, 0.05, ..., 0.2) exactly once.
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


a = particle_state(os.path.join(work, "straight"), "0.2")
b = particle_state(os.path.join(work, "restarted"), "0.2")
checks.same_state("restarted vs straight", a, b)

with h5py.File(os.path.join(work, "straight", "postProcessing",
                            "particles.h5"), "r") as f:
    moved = np.abs(f["position"][-1] - f["position"][0]).max()
check("particles moved (1/displacement)", 1 / max(moved, 1e-300), 1e3)

for name in ["straight", "restarted"]:
    with h5py.File(os.path.join(work, name, "postProcessing",
                                "particles.h5"), "r") as f:
        t = f["time"][:]
    check("%s: HDF5 times differ from 0, 0.05 .. 0.2" % name,
          float(len(t) != 5) + np.abs(t - 0.05 * np.arange(len(t))).max(),
          1e-12)

checks.finish()
