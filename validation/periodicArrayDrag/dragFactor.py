#!/usr/bin/env python3
"""Drag factor K of one periodic-array case (thesis 1, eqs 4.2, 4.6, 4.7).

K = F / (6 pi eta a U_s),  F = V0 |grad P0| (held sphere) or the buoyant
weight (settling sphere), U_s = <u> - U_particle along the flow.
Usage: dragFactor.py caseDir L  -> prints "K phi K_Hasimoto"
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
import h5py  # noqa: E402
from fdmPost.particleCase import hasimoto_K, momentum_balance  # noqa: E402


def drag_factor(case, L):
    """K of the case's last solve; force = V0 (|grad P0| = 1 or g = 1).
    Mean velocity from the momentum-balance file, particle velocity from
    the HDF5 series (both written after every solve)."""
    bal = momentum_balance(case)
    with h5py.File(os.path.join(case, "postProcessing", "particles.h5"),
                   "r") as f:
        t, Up = f["time"][-1], f["velocity"][-1, 0]
    if abs(t - bal["time"][-1]) > 1e-12 * (1 + abs(t)):
        raise RuntimeError("%s: last HDF5 time %g differs from the last"
                           " balance time %g" % (case, t, bal["time"][-1]))
    slip = bal["meanU"][-1, 0] - Up[0]
    force = L ** 3
    return force / (6 * math.pi * abs(slip))


if __name__ == "__main__":
    case, L = sys.argv[1], float(sys.argv[2])
    phi = 4 * math.pi / 3 / L ** 3
    print("%.9g %.9g %.9g" % (drag_factor(case, L), phi, hasimoto_K(phi)))
