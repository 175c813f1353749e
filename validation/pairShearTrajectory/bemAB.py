#!/usr/bin/env python3
"""The reference of this validation checked independently: the
Batchelor-Green functions A(r), B(r) of two free equal spheres in simple
shear from the boundary-integral solver (fdmResistance.unboundedSpheres,
unbounded fluid, with its error estimate) against the exact two-sphere
resistance that mobility.py compares the solver with
(fdmResistance.pairShear.AB_exact), at the gaps of mobility.dat.

With u = y e_x (E_xy = 1/2, Omega = -1/2 e_z) and V = U2 - U1 the
relative velocity of the spheres at -r/2 and +r/2 (Batchelor & Green 1972):
  r along (1, 1, 0): E.r is radial, V.r_hat = (r/2)(1 - A);
  r along x:         V_y = -(r/2) B.
Both pairs are symmetric about z = 0 and under the half turn about z.

    ./bemAB.py          writes bemAB.dat and prints the table (about
                        15 min on one core with OpenBLAS)
"""

import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmResistance import pairShear  # noqa: E402
from fdmResistance.unboundedSpheres import unbounded_spheres  # noqa: E402

GAPS = (0.01, 0.03, 0.1, 0.3, 1.0, 3.0)
SYMMETRIES = ((1, 1, -1), (-1, -1, 1))


def meshes(gap):
    """(level, beta) of the fine mesh; the coarse one is (level - 1,
    2 beta).  Near contact the gap is resolved by beta at level 3."""
    return (3, 0.35) if gap < 0.05 else (4, 0.5)


def relative_velocity(r, direction, level, beta):
    """V = U2 - U1 and its estimated error for the pair along direction."""
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    res = unbounded_spheres([-r / 2 * d, r / 2 * d], [1.0, 1.0], "shear",
                            symmetries=SYMMETRIES, level=level, beta=beta)
    return res["U"][1] - res["U"][0], 2 * res["error"]["U"][1], d


def main():
    rows = []
    for gap in GAPS:
        r = 2 + gap
        level, beta = meshes(gap)
        start = time.time()
        V, err, d = relative_velocity(r, (1, 1, 0), level, beta)
        A, dA = 1 - 2 * (V @ d) / r, 2 * np.linalg.norm(err) / r
        V, err, _ = relative_velocity(r, (1, 0, 0), level, beta)
        B, dB = -2 * V[1] / r, 2 * err[1] / r
        A_th, B_th = (float(v[0]) for v in pairShear.AB_exact(np.array([r])))
        rows.append((gap, A, dA, A_th, B, dB, B_th, level, beta,
                     time.time() - start))
        print("gap %g: A %.6f +- %.6f (exact %.6f), B %.6f +- %.6f (exact "
              "%.6f), %.0f s" % (gap, A, dA, A_th, B, dB, B_th, rows[-1][-1]),
              flush=True)
    with open(os.path.join(HERE, "bemAB.dat"), "w") as f:
        f.write("# gap A dA A_exact B dB B_exact level beta seconds "
                "(boundary integral against pairShear.AB_exact)\n")
        for row in rows:
            f.write("%g %.8f %.2e %.8f %.8f %.2e %.8f %d %g %.0f\n" % row)


if __name__ == "__main__":
    main()
