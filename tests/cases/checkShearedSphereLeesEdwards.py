#!/usr/bin/env python3
"""Checks of the sheared-sphere Lees-Edwards case test
(shearedSphereLeesEdwards.sh).

A free sphere (a = 1) in a Lees-Edwards box of 10^3 a^3 at shear rate 1
(rho = nu = 1), force- and torque-free, solved at t = 0 (offset 0) and
after one step at t = 0.34 (offset 3.4, 17 whole cells), once at the box
centre and once moved up by 4.6 (its support crossing the sheared faces,
its images there moving at 10 relative to it) in the flow moved by -4.6
along x.

References and tolerances, at each offset:
- The same sphere at the same position relative to the cells: at an
  offset of whole cells the sheared coupling maps cells onto cells, so the
  discrete problems differ only by where the faces cut the flow, and
  rotation, slip from the affine flow U_x = y_p and stresslet agree to the
  outer loop's convergence (lambda residual 1e-6, from initial fields 4.6
  apart): tolerance 5e-4 of the rotation rate, the stresslet and gamma a,
  measured 9.3e-5, 5.9e-5 and 1.6e-5 at offset 0, 5.5e-6, 6.4e-7 and
  8.8e-5 at offset 3.4 at writing.  (At a fractional offset, 3.43, the
  linear interpolation along the faces through the sphere's near field
  parts them by 6.4e-3, 6.6e-3 and 7.0e-4.)  The offset changes the image
  lattice, and with it Omega_z from -0.4993 to -0.4955 (the same at 3.43).
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
    """Time, position, velocity, angular velocity and stresslet of every
    solve (the records of the particle series) of the one sphere."""
    path = sorted(glob.glob(f"{work}/{case}/postProcessing/particles/*.h5"))[0]
    with h5py.File(path, "r") as f:
        return [f["time"][:]] + [f[k][:, 0] for k in (
            "position", "velocity", "angularVelocity", "stresslet")]


S_BATCHELOR = 10.0 / 3.0 * np.pi
centre, across = solved("centre"), solved("acrossFaces")
for name, run in (("centre", centre), ("across the faces", across)):
    check(f"{name}: solved at t = 0 and 0.34", abs(len(run[0]) - 2), 0.5)
for r, t in enumerate(centre[0]):
    x, U, W, S = (a[r] for a in centre[1:])
    xf, Uf, Wf, Sf = (a[r] for a in across[1:])
    at = f"offset {10 * t:.3g}"
    print(f"{at}: centre: position {x}, velocity {U}, angular velocity {W}")
    print(f"{at}: across the faces: position {xf}, velocity {Uf},"
          f" angular velocity {Wf}")
    check(f"{at}: centre: |Omega_z + 1/2| / (1/2)", abs(W[2] + 0.5) / 0.5,
          0.015)
    check(f"{at}: centre: |U_x - y_p| / (shear rate a)", abs(U[0] - x[1]),
          0.01)
    check(f"{at}: centre: |S_xy / ((10/3) pi eta a^3 shear rate) - 1|",
          abs(S[1] / S_BATCHELOR - 1), 0.02)
    # The affine flow of the moved case is u_x = y - 4.6
    slip = U - np.array([x[1], 0, 0])
    slip_f = Uf - np.array([xf[1] - 4.6, 0, 0])
    check(f"{at}: across - centre: |d slip| / (shear rate a)",
          np.abs(slip_f - slip).max(), 5e-4)
    check(f"{at}: across - centre: |d Omega| / (1/2)",
          np.abs(Wf - W).max() / 0.5, 5e-4)
    check(f"{at}: across - centre: |d stresslet| / S_xy",
          np.abs(Sf - S).max() / S[1], 5e-4)

bal = momentum_balance(f"{work}/centre")
check("centre: max |int lambda| / (6 pi eta a^2 shear rate)",
      np.abs(bal["lambdaV"]).max() / F, 2e-3)

checks.finish()
