#!/usr/bin/env python3
"""Checks of the processor-crossing case test (processorCrossing.sh): one
sphere settling along x through the processor boundary at x = 2.5 and the
cyclic patch at x = 5 of a periodic cube L = 5a, Delta = a/4, 18 steps.

References and tolerances:
- The serial run: the 2-rank run (the particle system solved by
  subdomain, where the sphere's solving rank changes at each crossing)
  keeps its trajectory to 1e-6 a in position and 1e-6 of the
  speed in velocity.  Both are solved with the lambda residual at 1e-8 and
  the fluid to 1e-9, so the two differ by the order of the parallel sums and
  the linear solvers' stopping (measured 3e-8).
- No jump at a crossing: every step's speed within 2 % of the run's mean,
  the sideways velocity below 1 % of it (the sphere's position in its cell
  moves the FDM drag by 0.7 % at Delta = a/4; measured sideways 0.5 %).
- Hasimoto (1959), thesis eq 4.3: the drag factor of the mean slip
  velocity within 3 %, as in periodicArrayDrag.
- Restarted on a new decomposition (reconstructPar, decomposePar): the
  uninterrupted 2-rank run to 1e-12 relative at 1.2 and 1.4 (round-off:
  positions and velocities are read at full precision, the fields in
  binary; the processorCyclic values decomposePar writes are not used).
- The path is what the test is for: it starts left of x = 2.5 and ends past
  the cyclic patch, unwrapped displacement over 2.95a.
"""

import math
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.particleCase import hasimoto_K, momentum_balance  # noqa: E402
from fdmPost.checks import Checks  # noqa: E402

L, g = 5.0, 0.32
work = sys.argv[1]
checks = Checks(width=62)
check = checks.check


def trajectory(run):
    """Times, positions, velocities and angular velocities of the sphere,
    and the mean fluid velocity at the same times."""
    case = os.path.join(work, run)
    with h5py.File(os.path.join(case, "postProcessing", "particles.h5"),
                   "r") as f:
        out = {k: f[k][:, 0] for k in ("position", "velocity",
                                       "angularVelocity")}
        out["time"] = f["time"][:]
    bal = momentum_balance(case)
    out["meanU"] = np.array([bal["meanU"][np.argmin(abs(bal["time"] - t))]
                             for t in out["time"]])
    return out


serial = trajectory("serial")
x = serial["position"][:, 0]
unwrapped = x[0] + np.concatenate([[0], np.cumsum(
    (np.diff(x) + L / 2) % L - L / 2)])
print("x from %.4f to %.4f (unwrapped %.4f) in %d records"
      % (x[0], x[-1], unwrapped[-1], len(x)))
check("starts left of the processor boundary (x0 - L/2)", x[0] - L / 2, 0)
check("passes the cyclic patch (L - x0 - displacement)",
      L - x[0] - (unwrapped[-1] - unwrapped[0]), 0)
check("ends wrapped, left of the processor boundary (x_end - L/2)",
      x[-1] - L / 2, 0)

two = trajectory("distributed")
check("2 ranks: records against serial (count difference)",
      abs(len(two["time"]) - len(x)), 0)
n = min(len(two["time"]), len(x))
speed = np.abs(serial["velocity"][:n, 0]).max()
check("2 ranks: position against serial (max, a)",
      np.abs(two["position"][:n] - serial["position"][:n]).max(), 1e-6)
for key in ("velocity", "angularVelocity"):
    check("2 ranks: %s against serial (max, / speed)" % key,
          np.abs(two[key][:n] - serial[key][:n]).max() / speed, 1e-6)

# Restarted after reconstructPar and decomposePar at time 1: the records
# of 1.2 and 1.4 against the uninterrupted run's, to round-off (the state
# is read at full precision, the fields in binary)
again = trajectory("redecomposed")
for t in (1.2, 1.4):
    i = np.argmin(abs(two["time"] - t))
    k = np.flatnonzero(abs(again["time"] - t) < 1e-9)
    if len(k) != 1:
        check("redecomposed: records at %.1f (1 expected)" % t,
              abs(len(k) - 1), 0)
        continue
    for key, scale in (("position", L), ("velocity", speed),
                       ("angularVelocity", speed)):
        check("redecomposed at %.1f: %s against 2 ranks (max / %s)"
              % (t, key, "L" if key == "position" else "speed"),
              np.abs(again[key][k[0]] - two[key][i]).max() / scale, 1e-12)

U = serial["velocity"]
mean = U[:, 0].mean()
check("speed at every step against its mean (relative)",
      np.abs(U[:, 0] - mean).max() / mean, 0.02)
check("sideways velocity against the speed (max)",
      np.abs(U[:, 1:]).max() / mean, 0.01)
slip = np.mean(U[:, 0] - serial["meanU"][:, 0])
K = L ** 3 * g / (6 * math.pi * abs(slip))
KH = hasimoto_K(4 * math.pi / 3 / L ** 3)
print("mean speed %.6f, slip %.6f: K %.5f, Hasimoto %.5f" % (mean, slip, K, KH))
check("K of the mean slip against Hasimoto (relative)", abs(K - KH) / KH,
      0.03)

checks.finish()
