#!/usr/bin/env python3
"""Validation: free spheres in a plane channel (thesis 1, sections 4.1.2b,
4.1.2c and 4.1.4).

Free (force- and torque-free) spheres, a = 1, Delta = a/5, between walls
normal to y at y = 0 and y = H, cyclic in x and z with period L (default
16 a, --box).  One steady solve per case (endTime 0: the first record of
particles.h5), at --positions in-plane positions inside a mesh cell
(cell_offsets) with the frameInvariant sub-grid model and at one position
without it (the FDM alone).  Three families:

shear       sphere at the channel centre y = H/2 in plane Couette flow of
            shear rate 1: bottom wall moving at (-H/2, 0, 0), top wall at
            (+H/2, 0, 0), so the ambient velocity is zero at the centre.
            H = 10, 6.6, 5, 4, 3.4, 2.8 (2a/H = 0.2 ... 0.714, all
            multiples of Delta).  Measured: -Omega_z/shear (0.5 unbounded),
            S_xy/((10/3) pi eta a^3 shear) (1 unbounded), U_x and U_y (0 by
            symmetry, as a check).
poiseuille  stationary walls, flow driven by the kinematic mean pressure
            gradient (-8 nu U_c / H^2, 0, 0), U_c = 1 (centre-line
            velocity), acting on fluid and particle alike (as in
            tutorials/poiseuille); centre at d above the bottom wall.
            H = 5 (2a/H = 0.4), d/a = 1.1, 1.25, 1.5, 2.0, 2.5 and
            H = 2.8 (2a/H = 0.714), d/a = 1.1, 1.2, 1.4.  Measured:
            U_x/U_c, Omega_z a/U_c, S_xy/(4 U_c eta a^3/H) (the
            normalisation of Ghalya et al. 2020), U_y.
pair        two free spheres in the Poiseuille channel H = 4 a of
            Bhattacharya et al. (2006), thesis 1 section 4.1.4: sphere 1 on
            the centre line, sphere 2 downstream with its centre 1.33 a
            above the bottom wall, streamwise separation rho_12 = s H for
            s = 0.48 ... 1.5 (surface gap 0.034 a ... 4 a).  Measured for
            each sphere: U_x/U_c, U_y/U_c, 2 a Omega_z/U_c, S_xy.

References (report.py): the same free spheres between two walls,
unbounded in x and z, from fdmResistance.boundaryElement (cached in
reference.dat with their discretisation errors).

    ./Allrun [--family shear,poiseuille,pair] [--heights 10,6.6,...]
             [--poiseuille 5:1.1,1.25,1.5,2,2.5/2.8:1.1,1.2,1.4]
             [--pair 0.48,0.5,...] [--positions 4] [--jobs 2]
             [--lambda-tol 1e-6] [--box 16]

writes results.dat (one row per sphere and solve: raw U_x, U_y, Omega_z,
S_xy, box, cells, wall time; rows of other configurations are kept, so
the families can be run one at a time) and calls report.py (report.md,
channelSphere.png); cases in build/validation/channelSphere.  The steady
solve does not depend on the initial field (zero here; the ambient profile
gives the same Omega_z and S_xy to 2e-7 at H = 4).

Box: at the centre of the Couette channel the disturbance of the
force-free sphere decays exponentially along the channel (H = 4: L = 24
instead of 16 changes Omega_z and S_xy by 3e-7).  In Poiseuille flow at an
imposed pressure gradient the periodic array of spheres lowers the flow
rate by a fraction ~ 1/L^2, which scales the whole solution: at H = 5,
d = 1.5, L = 24 raises U_x, Omega_z and S_xy alike by 0.17 %, so L = 16 is
about 0.3 % low.  The meanPressureGradient entry is the kinematic
grad(P0)/rho, a source in the momentum equation (0 = nu lap U - grad p -
grad P0 + lambda): flow in +x needs -8 nu U_c/H^2, as in
tutorials/poiseuille.
"""

import argparse
import concurrent.futures
import os
import re
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("FDM_PROJECT_DIR",
                                               os.path.join(HERE, "..", "..")),
                                "src", "python"))
sys.path.insert(0, HERE)
from fdmPost.caseRunner import (cell_offsets, fill_template,  # noqa: E402
                                run_case, vec)

DELTA = 0.2
U_C = 1.0
SHEAR_HEIGHTS = "10,6.6,5,4,3.4,2.8"
POISEUILLE = "5:1.1,1.25,1.5,2,2.5/2.8:1.1,1.2,1.4"
PAIR_H, PAIR_Y2 = 4.0, 1.33          # Bhattacharya et al. (2006)
PAIR = "0.48,0.5,0.55,0.6,0.7,0.85,1,1.25,1.5"


def template_nu():
    """Kinematic viscosity nu of the template's transportProperties."""
    text = open(os.path.join(HERE, "template", "constant",
                             "transportProperties")).read()
    return float(re.search(r"^\s*nu\s+([^;\s]+)\s*;", text, re.M).group(1))


def centres(family, H, d, L, offset):
    """Sphere centres of one solve: d is the height (shear, poiseuille) or
    the streamwise separation over H (pair)."""
    x0 = L / 2 + offset[0] * DELTA
    z0 = L / 2 + offset[1] * DELTA
    if family != "pair":
        return [np.array([x0, d, z0])]
    s = d * H
    return [np.array([x0 - s / 2, H / 2, z0]),
            np.array([x0 + s / 2, PAIR_Y2, z0])]


def solve(family, H, d, offset, model, work, lambda_tol, L):
    """One steady solve; returns per sphere (U_x, U_y, Omega_z, S_xy raw)
    and the cells and wall seconds."""
    case = os.path.join(work, "%s_H%g_d%g_L%g_x%g_z%g_%s" % (
        family, H, d, L, offset[0], offset[1], model))
    if family == "shear":
        u_bottom, u_top, gradp = -H / 2, H / 2, 0.0
    else:
        u_bottom, u_top, gradp = 0.0, 0.0, -8 * template_nu() * U_C / H ** 2
    n, nh = int(round(L / DELTA)), int(round(H / DELTA))
    particles = "\n    ".join("(free %s 1)" % vec(x)
                              for x in centres(family, H, d, L, offset))
    fill_template(os.path.join(HERE, "template"), case, {
        "@L@": "%.17g" % L, "@H@": "%.17g" % H, "@N@": "%d" % n,
        "@NH@": "%d" % nh, "@PARTICLES@": particles,
        "@UBOTTOM@": "%.17g" % u_bottom, "@UTOP@": "%.17g" % u_top,
        "@GRADP@": "%.17g" % gradp, "@LAMBDATOL@": "%g" % lambda_tol,
        "@SUBGRID@": model})
    start = time.time()
    s = run_case(case)
    values = [(s["velocity"][i][0], s["velocity"][i][1],
               s["angularVelocity"][i][2], s["stresslet"][i][1])
              for i in range(len(s["velocity"]))]
    return values, n * nh * n, time.time() - start


def configurations(args):
    """(family, H, d) to solve (d: the separation over H for pairs)."""
    families = args.family.split(",")
    out = []
    if "shear" in families:
        out += [("shear", H, H / 2)
                for H in (float(h) for h in args.heights.split(","))]
    if "poiseuille" in families:
        for channel in args.poiseuille.split("/"):
            H, ds = channel.split(":")
            out += [("poiseuille", float(H), float(d))
                    for d in ds.split(",")]
    if "pair" in families:
        out += [("pair", PAIR_H, float(s)) for s in args.pair.split(",")]
    for f, H, d in out:
        if abs(H / DELTA - round(H / DELTA)) > 1e-9:
            sys.exit("H = %g is not a multiple of Delta = %g" % (H, DELTA))
        if f != "pair" and not 1 < d < H - 1:
            sys.exit("d = %g: the sphere does not fit in H = %g" % (d, H))
        if f == "pair" and np.hypot(d * H, H / 2 - PAIR_Y2) <= 2:
            sys.exit("--pair %g: the spheres overlap" % d)
    return out


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--family", default="shear,poiseuille,pair",
                        help="comma-separated: shear, poiseuille, pair")
    parser.add_argument("--heights", default=SHEAR_HEIGHTS,
                        help="channel heights H of the shear family")
    parser.add_argument("--poiseuille", default=POISEUILLE,
                        help="H:d,d,.../H:d,... of the Poiseuille family "
                        "(d: centre height above the bottom wall)")
    parser.add_argument("--pair", default=PAIR,
                        help="streamwise separations rho_12/H of the pair")
    parser.add_argument("--positions", type=int, default=4)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--lambda-tol", type=float, default=1e-6)
    parser.add_argument("--box", type=float, default=16.0,
                        help="period L in x and z (multiple of Delta)")
    args = parser.parse_args()
    work = os.path.join(os.environ["FDM_PROJECT_DIR"], "build", "validation",
                        "channelSphere")
    configs = configurations(args)
    jobs = [(c, tuple(o), "frameInvariant") for c in configs
            for o in cell_offsets(args.positions, 2)]
    jobs += [(c, tuple(cell_offsets(1, 2)[0]), "none") for c in configs]
    results = {}
    with concurrent.futures.ProcessPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(solve, c[0], c[1], c[2], o, m, work,
                               args.lambda_tol, args.box):
                   (c, o, m) for c, o, m in jobs}
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            results[futures[fut]] = r = fut.result()
            (f, H, d), o, m = futures[fut]
            print("  [%d/%d] %s H %g d %g offset (%g, %g) %s: %s (%d cells, "
                  "%.0f s)" % ((i + 1, len(jobs), f, H, d) + o + (m,) + (
                      "; ".join("U_x %.6g U_y %.3g Omega_z %.6g S_xy %.6g"
                                % v for v in r[0]),) + r[1:]), flush=True)
    rows = []
    for ((fam, H, d), o, m), (values, cells, wall) in sorted(results.items()):
        for k, v in enumerate(values):
            rows.append("%s %g %g %d %g %g %s %.10g %.10g %.10g %.10g %g %d "
                        "%.1f\n" % ((fam, H, d, k + 1) + o + (m,) + v
                                     + (args.box, cells, wall)))
    write_results(rows, {"%s %g %g " % c for c in configs}, args.lambda_tol)
    import report
    report.main()


def write_results(rows, configs, lambda_tol):
    """results.dat: the rows of earlier runs whose configuration (family H
    d) was not solved again, then the new rows."""
    path = os.path.join(HERE, "results.dat")
    kept = []
    if os.path.isfile(path):
        kept = [l for l in open(path) if not l.startswith("#")
                and " ".join(l.split()[:3]) + " " not in configs]
    with open(path, "w") as f:
        f.write("# family H d sphere offset_x offset_z model U_x U_y Omega_z "
                "S_xy (raw: a = 1, nu = %g, shear rate 1 or U_c = 1) "
                "L cells wall_s (lambda tol %g)\n"
                % (template_nu(), lambda_tol))
        f.writelines(kept + rows)
    import report
    report.main()


if __name__ == "__main__":
    main()
