#!/usr/bin/env python3
"""Checks of the sheared-sphere Lees-Edwards case test
(shearedSphereLeesEdwards.sh).

A free sphere (a = 1) in a Lees-Edwards box of 10^3 a^3 at shear rate 1
(rho = nu = 1), force- and torque-free, solved at t = 0 (offset 0), once
at the box centre and once moved up by 4.6 (its support crossing the
sheared faces, its images there moving at 10 relative to it) in the flow
moved by -4.6 along x.

References and tolerances:
- The same sphere at the same position relative to the cells: the discrete
  problems differ only by the sheared coupling of the faces, which at a
  offset 0 maps cells onto cells, so rotation, slip from the
  affine flow U_x = y_p and stresslet agree to the outer loop's
  convergence (lambda residual 1e-6, from initial fields 4.6 apart):
  tolerance 5e-4 of the rotation rate, the stresslet and gamma a,
  measured 9.3e-5, 5.9e-5 and 1.6e-5 at writing.
- Free sphere in linear shear, as in shearedSphere (checkShearedSphere.py):
  Omega_z = -1/2 within 1.5 % (the images 10a apart along every direction
  slow it by O((a/L)^3)), U_x = y_p within 0.01, S_xy = (10/3) pi eta a^3
  within 2 % (Batchelor 1970); no force on the fluid: |int lambda| below
  2e-3 of the Stokes drag scale 6 pi eta a (shear rate a).
"""

import glob
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.particleCase import momentum_balance  # noqa
from fdmPost.checks import Checks  # noqa: E402

work = sys.argv[1]
F = 6 * np.pi
checks = Checks()
check = checks.check


def solved(case):
    """Position, velocity, angular velocity and stresslet of the solve at
    the start (the first record of the particle series)."""
    path = sorted(glob.glob(f"{work}/{case}/postProcessing/particles/*.h5"))[0]
    with h5py.File(path, "r") as f:
        return tuple(f[k][0][0] for k in ("position", "velocity",
                                           "angularVelocity", "stresslet"))


S_BATCHELOR = 10.0 / 3.0 * np.pi
x, U, W, S = solved("centre")
xf, Uf, Wf, Sf = solved("acrossFaces")
print("centre: position", x, "velocity", U, "angular velocity", W)
print("across the faces: position", xf, "velocity", Uf, "angular velocity",
      Wf)
check("centre: |Omega_z + 1/2| / (1/2)", abs(W[2] + 0.5) / 0.5, 0.015)
check("centre: |U_x - y_p| / (shear rate a)", abs(U[0] - x[1]), 0.01)
check("centre: |S_xy / ((10/3) pi eta a^3 shear rate) - 1|",
      abs(S[1] / S_BATCHELOR - 1), 0.02)
# The affine flow of the moved case is u_x = y - 4.6
slip = U - np.array([x[1], 0, 0])
slip_f = Uf - np.array([xf[1] - 4.6, 0, 0])
check("across - centre: |d slip| / (shear rate a)",
      np.abs(slip_f - slip).max(), 5e-4)
check("across - centre: |d Omega| / (1/2)", np.abs(Wf - W).max() / 0.5, 5e-4)
check("across - centre: |d stresslet| / S_xy", np.abs(Sf - S).max() / S[1],
      5e-4)

bal = momentum_balance(f"{work}/centre")
check("centre: max |int lambda| / (6 pi eta a^2 shear rate)",
      np.abs(bal["lambdaV"]).max() / F, 2e-3)

checks.finish()
