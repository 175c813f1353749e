#!/usr/bin/env python3
"""Checks of restartContinuity.sh.

Reference: the uninterrupted run.  A restart reads positions, velocities
and the Adams-Bashforth history at full precision and the fields written
with 17 digits (exact for doubles), so the restarted trajectory must agree
to round-off (1e-12 relative).  Continued from a particle checkpoint (no
fields), to the accuracy of a solve at the lambda tolerance 1e-5 (2e-4
relative, below), its records joined with the checkpoint's equal to the
straight run's to the same accuracy.  The particles must have moved (so that the
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
from fdmPost.coreRecords import CoreRecords  # noqa: E402
from fdmPost.rheology import channel_case  # noqa: E402

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

# Continued from a particle checkpoint: the fluid of the first step is
# solved anew from the fields of time 0 (the Stokes flow has no memory),
# so the state agrees to the accuracy of a solve, not to round-off: the
# outer iteration contracts the lambda residual by about 0.93 per
# iteration here, so a solve stopped at the residual 1e-5 is within about
# 1e-5/(1 - 0.93) ~ 1.5e-4 of its fixed point; tolerance 2e-4
SOLVE = 2e-4
c = particle_state(os.path.join(work, "continued"), "0.2")
checks.same_state("continued from a checkpoint vs straight", a, c, tol=SOLVE)
with open(os.path.join(work, "continued", "0.1", "particleState")) as f:
    check("restored state not marked coldFluid",
          float("coldFluid" not in f.read()), 0.5)
straight = CoreRecords.from_series(
    channel_case(os.path.join(work, "straight"), 1.0)[0], {"shearRate": 1})
joined = CoreRecords.read(os.path.join(work, "checkpoint", "coreRecords.csv"))
check("joined records: times differ from 0, 0.05 .. 0.2",
      float(len(joined.t) != 5)
      + np.abs(joined.t - 0.05 * np.arange(len(joined.t))).max(), 1e-12)
for name in ("phi", "g", "hp"):
    x, y = getattr(straight, name), getattr(joined, name)
    check(f"joined records {name} vs straight (relative)",
          np.abs(x - y).max() / np.abs(x).max(), SOLVE)

checks.finish()
