#!/usr/bin/env python3
"""Boundary-integral references for the three-sphere cases (issue: the
far-field many-body part of the Stokesian-dynamics reference may be off by
a few per cent for close triplets), unbounded fluid, a = eta = 1:

triangle  the clusters of run.py, sphere 0 pushed by 6 pi e_x, spheres 1
          and 2 free (symmetric about z = 0 and y = 0);
shear     aligned (symmetric about z = 0 and the half turn about z) and L
          (about z = 0), free in u = y e_x, B at the origin.

Each configuration is solved on a sequence of meshes
(fdmResistance.unboundedSpheres, octahedral level L, elements no larger
than beta times their distance to another sphere), each finer than the
last; the reference is the finest, its uncertainty the change from the
one before (an overestimate when the error falls as h^2 or faster, as
measured at r = 2.5: levels 3, 4, 5 differ by 1.9e-4 and 2.2e-5 in
u_x(1) - u_x(2,3)).  Rows are appended to reference.dat as each solve
ends (one line per sphere and mesh), so a run that stops resumes:

    ./bemReference.py [--only triangle|shear] [--configs 2.01,L]

Cost (one core, OpenBLAS): about a minute per configuration up to level
4 at r >= 2.1; the gaps of 0.01 a need beta 0.35 at level 3, 10-30 min
and 3-12 GB each.
"""

import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmResistance import threeSphere  # noqa: E402
from fdmResistance.unboundedSpheres import (FLOWS,  # noqa: E402
                                            mirrored_free_spheres)
from run import TRIANGLE_SIDES  # noqa: E402

REFERENCE = os.path.join(HERE, "reference.dat")
Z, Y, HALF_TURN_Z = (1, 1, -1), (1, -1, 1), (-1, -1, 1)
PUSH = [(6 * np.pi, 0, 0), (0, 0, 0), (0, 0, 0)]
# (level, beta) from coarse to fine; the near-contact clusters refine the
# gaps further at the level the memory allows
FAR = ((2, 1.0), (3, 0.5), (4, 0.5))
# At gap 0.1 a the gap's elements (beta times their distance) carry the
# error: beta 0.5, 0.35, 0.25 at level 4 change u_x(1) - u_x(2,3) by
# -2.2e-4 and -1.1e-4 (as beta^2)
GAP_0_1 = ((3, 0.5), (4, 0.35), (4, 0.25), (5, 0.25))
NEAR = ((2, 1.0), (3, 0.5), (3, 0.35))


def cases():
    """(kind, config, centres, symmetries, forces, flow, meshes)."""
    for side in TRIANGLE_SIDES:
        yield ("triangle", "%.2f" % side,
               threeSphere.cluster("triangle", side), (Y, Z), PUSH, "rest",
               NEAR if side < 2.05 else GAP_0_1 if side < 2.2 else FAR)
    yield ("shear", "aligned", threeSphere.cluster("aligned", 2.01),
           (Z, HALF_TURN_Z), None, "shear", NEAR)
    yield ("shear", "L", threeSphere.cluster("L", 2.01), (Z,), None, "shear",
           NEAR)


def rows():
    """The data rows of reference.dat, split (none before the first
    solve)."""
    if os.path.exists(REFERENCE):
        for line in open(REFERENCE):
            if not line.startswith("#"):
                yield line.split()


def done():
    """(kind, config, level, beta) already in reference.dat."""
    return {(w[0], w[1], int(w[2]), float(w[3])) for w in rows()}


def append(kind, config, level, beta, r, seconds):
    new = not os.path.exists(REFERENCE)
    with open(REFERENCE, "a") as f:
        if new:
            f.write("# kind config level beta elements seconds sphere Ux Uy"
                    " Uz Wx Wy Wz (unboundedSpheres: a = eta = 1; triangle:"
                    " 6 pi e_x on sphere 0; shear: u = y e_x, B at the"
                    " origin; elements: the unknown ones, one of each"
                    " symmetry orbit)\n")
        for k in range(3):
            f.write("%s %s %d %g %d %.0f %d %s\n" % (
                kind, config, level, beta, r["elements"], seconds, k,
                " ".join("%.10g" % (v + 0.0)
                         for v in np.hstack([r["U"][k], r["Omega"][k]]))))


def load():
    """dict (kind, config) -> list over the meshes of its sequence in
    cases() (coarse to fine; rows of other meshes are not used) of
    (level, beta, elements, seconds, U (3, 3), W (3, 3))."""
    order = {(kind, config): list(meshes)
             for kind, config, *_, meshes in cases()}
    found = {}
    for w in rows():
        key, mesh = (w[0], w[1]), (int(w[2]), float(w[3]))
        entry = found.setdefault(key, {}).setdefault(
            mesh, [int(w[4]), float(w[5]), np.zeros((3, 3)),
                   np.zeros((3, 3))])
        k = int(w[6])
        entry[2][k] = np.array(w[7:10], float)
        entry[3][k] = np.array(w[10:13], float)
    return {key: [(m[0], m[1], *by_mesh[m]) for m in order.get(key, [])
                  if m in by_mesh]
            for key, by_mesh in found.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--only", choices=("triangle", "shear"))
    parser.add_argument("--configs", default="",
                        help="comma-separated configs (e.g. 2.01,L)")
    args = parser.parse_args()
    wanted = set(filter(None, args.configs.split(",")))
    have = done()
    for kind, config, x, sym, forces, flow, meshes in cases():
        if (args.only and kind != args.only) or (wanted and
                                                 config not in wanted):
            continue
        for level, beta in meshes:
            if (kind, config, level, beta) in have:
                continue
            start = time.time()
            r = mirrored_free_spheres([(c, 1.0) for c in x], FLOWS[flow],
                                      sym, level=level, beta=beta,
                                      forces=forces)
            seconds = time.time() - start
            append(kind, config, level, beta, r, seconds)
            print("%s %s level %d beta %g: %d elements, %.0f s" % (
                kind, config, level, beta, r["elements"], seconds),
                flush=True)


if __name__ == "__main__":
    main()
