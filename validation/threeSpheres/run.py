#!/usr/bin/env python3
"""Validation: three spheres (thesis 1, sections 4.1.5 and 4.1.6).

triangle  Three equal spheres (a = 1) at the corners of an equilateral
          triangle of side r in the x-y plane, fluid at rest; sphere 1 is
          pushed towards the centroid by F = 6 pi eta a e_x (so velocities
          come in units of F / (6 pi eta a)), spheres 2 and 3 are force-
          and torque-free.  r = 2.01, 2.10, 2.50, 3.00, 4.00, 6.00.
          Each sphere takes part in two sub-grid pair corrections.
          Box 16 a x 16 a x 12 a (walls y = +-8 a at rest, cyclic x, z;
          thesis: 60 x 40 x 50): the net force makes a Stokeslet whose
          images slow the whole cluster, so the same box is also solved
          with sphere 1 alone at the centroid ('single'); its velocity
          deficit 1 - U_single is the box correction of sphere 1, and
          the fluid velocity of that run at the places of spheres 2 and 3,
          minus the unbounded translating sphere's field, is theirs
          (box_kernel: the images of sphere 1's Stokeslet, smooth on the
          cluster; those of the force-free spheres decay as L^-3).
shear     Three free spheres A, B, C in the shear plane of a plane Couette
          flow (shear rate 1), surface gaps a xi = 0.01 a:
          'aligned': A-B-C on a line at 30 deg to the flow direction in
          the compressional quadrant, d = (cos 30, -sin 30, 0), B in the
          middle; 'L': A-B along the flow (x), B-C along the gradient (y).
          Radius a = 1 (Delta = a/5) in a cube of side 12 a (thesis
          30 a), B at the centre.  The thesis also ran a = 1.4 (Delta =
          a/7); the shipped sub-grid tables are measured at Delta = a/5
          only and the solver refuses a = 1.4 alone ('--radii 1,1.4'
          shows the message), so that run waits for a table at a/7.

Each configuration is one steady solve at the initial positions (endTime
0: the first record of particles.h5), averaged over positions of the
cluster inside one mesh cell (cell_offsets).  Reference (report.py): the
boundary integral in unbounded fluid (bemReference.py, reference.dat),
with Stokesian dynamics with the exact two-sphere resistance functions
(fdmResistance.threeSphere) beside it.

    ./Allrun [--positions 2] [--jobs 2] [--only triangle|shear] [--radii 1]
             [--box-scale S]

writes results.dat here (cases in build/validation/threeSpheres) and
calls report.py.  --box-scale S multiplies both boxes by S (a multiple
of 0.05: whole cells of a/5) for the box-size study: results_boxS.dat and
boxKernel_boxS.dat (report.py --boxes tabulates the sizes side by side).
"""

import argparse
import concurrent.futures
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ["FDM_PROJECT_DIR"], "src",
                                "python"))
from fdmPost.caseRunner import (cell_offsets, fill_template,  # noqa: E402
                                run_case, vec)
from fdmResistance.threeSphere import cluster  # noqa: E402

DELTA = 0.2
TRIANGLE_SIDES = (2.01, 2.10, 2.50, 3.00, 4.00, 6.00)
TRIANGLE_BOX = (16.0, 16.0, 12.0)
SHEAR_GAP = 0.01
SHEAR_BOX = 12.0          # in units of the radius


def make_case(case, box, uw, force, particles):
    """Fill the template in case: box (Lx, Ly, Lz) centred on the origin,
    walls y = +-Ly/2 moving at -+uw, force of the 'pushed' group, particle
    lines."""
    n = [int(round(L / DELTA)) for L in box]
    fill_template(os.path.join(HERE, "template"), case, {
        "@LX2@": "%.17g" % (box[0] / 2), "@LY2@": "%.17g" % (box[1] / 2),
        "@LZ2@": "%.17g" % (box[2] / 2),
        "@NX@": "%d" % n[0], "@NY@": "%d" % n[1], "@NZ@": "%d" % n[2],
        "@UW@": "%.17g" % uw, "@FORCE@": vec(force),
        "@LAMBDATOL@": "1e-6", "@PARTICLES@": particles})


def suffix(scale):
    """File-name suffix of a box scale ('' for the default boxes)."""
    return "" if scale == 1 else "_box%g" % scale


def boxes(scale):
    """The triangle box and the shear cube's side (in radii) at a scale."""
    return tuple(scale * L for L in TRIANGLE_BOX), scale * SHEAR_BOX


def solve(kind, param, radius, offset, work, scale=1):
    """One steady solve; returns (positions relative to the cluster
    reference point, velocities, angular velocities), the ambient
    velocity of the offset removed (units of a1 = 1)."""
    if kind == "triangle":
        x = (np.zeros((1, 3)) if param == "single"
             else cluster("triangle", param))
        box, uw, force = boxes(scale)[0], 0.0, (6 * np.pi, 0.0, 0.0)
    else:
        x = cluster(param, 2.0 + SHEAR_GAP) * radius
        box = (boxes(scale)[1] * radius,) * 3
        uw, force = box[1] / 2, (0.0, 0.0, 0.0)
    centre = np.asarray(offset) * DELTA + 0.013      # off the mesh nodes
    groups = ["pushed" if kind == "triangle" and i == 0 else "free"
              for i in range(len(x))]
    lines = "\n".join("    (%s %s %.17g)" % (g, vec(p + centre), radius)
                      for g, p in zip(groups, x))
    case = os.path.join(work, "%s_%s_a%g_%s%s" % (
        kind, param, radius, "_".join("%g" % o for o in offset),
        suffix(scale)))
    make_case(case, box, uw, force, lines)
    s = run_case(case)
    U = s["velocity"].copy()
    if uw:
        U[:, 0] -= centre[1]          # shear rate 1: ambient of the offset
    return x, U, s["angularVelocity"]


def box_kernel(work, scale=1):
    """Box correction of the triangle runs: sphere 1 alone, pushed, at the
    cluster's place; returns K (see kernel_from_field): the velocity added by the box
    (walls, images and the net flow a net force drives along a periodic
    channel) at sphere 1 itself (U_single - F/(6 pi)) and at the places of
    spheres 2 and 3 relative to it for each side r (fluid velocity after
    one step minus the exact field of a translating sphere), see
    kernel_from_field (sphere 3 by symmetry y -> -y)."""
    case = os.path.join(work, "boxKernel" + suffix(scale))
    make_case(case, boxes(scale)[0], 0.0, (6 * np.pi, 0, 0),
              "    (pushed %s 1)" % vec([0.013, 0.013, 0.013]))
    control = os.path.join(case, "system", "controlDict")
    text = open(control).read()
    text = text.replace("endTime         0;", "endTime         1e-3;")
    text = text.replace("writeFormat     binary;", "writeFormat     ascii;")
    open(control, "w").write(text)
    s = run_case(case)
    return kernel_from_field(case, s["position"][0], boxes(scale)[0])


def kernel_from_field(case, x1, box=TRIANGLE_BOX):
    """Rows [sphere 1, sphere 2's place for each side r] of (K_x, K_y, K_z,
    Omega_z): box velocity and box rotation rate (half the curl, central
    differences over one cell) at those places, from the field run of
    box_kernel with sphere 1 at x1."""
    from fdmPost.foamFields import read_internal_field
    from fdmPost.caseRunner import read_last_record
    n = [int(round(L / DELTA)) for L in box]
    U = read_internal_field(os.path.join(case, "0.001", "U")).reshape(
        n[2], n[1], n[0], 3)

    def K(rel):
        return (_sample(U, box, x1 + rel) - _translating_sphere(rel))

    rows = [np.append(read_last_record(case)["velocity"][0]
                      - np.array([1.0, 0.0, 0.0]), 0.0)]
    h = DELTA
    ex, ey = np.array([h, 0, 0]), np.array([0, h, 0])
    for side in TRIANGLE_SIDES:
        x = cluster("triangle", side)
        rel = x[1] - x[0]
        wz = 0.5 * ((K(rel + ex)[1] - K(rel - ex)[1])
                    - (K(rel + ey)[0] - K(rel - ey)[0])) / (2 * h)
        rows.append(np.append(K(rel), wz))
    return np.array(rows)


def _sample(U, box, p):
    """Trilinear interpolation of a cell-centred field on the uniform
    blockMesh grid (x fastest) at point p."""
    f = (np.asarray(p) + np.asarray(box) / 2) / DELTA - 0.5
    i0 = np.floor(f).astype(int)
    w = f - i0
    out = np.zeros(3)
    for c in np.ndindex(2, 2, 2):
        weight = np.prod([w[k] if c[k] else 1 - w[k] for k in range(3)])
        i = i0 + c
        out += weight * U[i[2], i[1], i[0]]
    return out


def _translating_sphere(x):
    """Exact Stokes flow at x of a unit sphere pushed by 6 pi e_x (eta = 1):
    (1 + lap/6) of the Stokeslet."""
    r = np.linalg.norm(x)
    F = np.array([6 * np.pi, 0, 0])
    J = np.eye(3) / r + np.outer(x, x) / r**3
    Q = np.eye(3) / (3 * r**3) - np.outer(x, x) / r**5
    return (J + Q) @ F / (8 * np.pi)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--positions", type=int, default=2)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--only", choices=("triangle", "shear"))
    parser.add_argument("--radii", default="1",
                        help="sphere radii of the shear runs, e.g. 1,1.4")
    parser.add_argument("--box-scale", type=float, default=1.0,
                        help="both boxes times this (a multiple of 0.05)")
    args = parser.parse_args()
    scale = args.box_scale
    if abs(20 * scale - round(20 * scale)) > 1e-9:
        parser.error("--box-scale %g: not a multiple of 0.05" % scale)
    work = os.path.join(os.environ["FDM_PROJECT_DIR"], "build", "validation",
                        "threeSpheres")
    offsets = [tuple(o) for o in cell_offsets(args.positions, 3)]
    jobs = []
    if args.only != "shear":
        jobs += [("triangle", p, 1.0, o) for p in TRIANGLE_SIDES + ("single",)
                 for o in offsets]
    if args.only != "triangle":
        jobs += [("shear", p, float(a), o) for a in args.radii.split(",")
                 for p in ("aligned", "L") for o in offsets]
    out = os.path.join(HERE, "results%s.dat" % suffix(scale))
    done = set()
    if os.path.exists(out):                     # resume: keep what is there
        for line in open(out):
            if not line.startswith("#"):
                w = line.split()
                done.add((w[0], w[1], float(w[2]), tuple(map(float, w[3:6]))))
    else:
        with open(out, "w") as f:
            f.write("# kind config radius offset_x offset_y offset_z sphere "
                    "x y z Ux Uy Uz Wx Wy Wz (a1 = eta = 1; triangle: "
                    "F = 6 pi e_x on sphere 0; shear: rate 1, ambient of "
                    "the offset removed)\n")
    todo = [j for j in jobs if (j[0], str(j[1]), j[2], j[3]) not in done]
    print("%d of %d solves to do" % (len(todo), len(jobs)), flush=True)
    with concurrent.futures.ProcessPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(solve, *j, work, scale): j for j in todo}
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            kind, param, radius, o = futures[fut]
            x, U, W = fut.result()
            with open(out, "a") as f:
                for k in range(len(x)):
                    f.write("%s %s %g %g %g %g %d %s %s %s\n" % (
                        kind, param, radius, o[0], o[1], o[2], k,
                        " ".join("%.10g" % c for c in x[k]),
                        " ".join("%.10g" % c for c in U[k]),
                        " ".join("%.10g" % c for c in W[k])))
            print("  [%d/%d] %s %s a=%g" % (i + 1, len(todo), kind, param,
                                            radius), flush=True)
    kernel = os.path.join(HERE, "boxKernel%s.dat" % suffix(scale))
    if args.only != "shear" and not os.path.exists(kernel):
        K = box_kernel(work, scale)
        np.savetxt(kernel, K, header="box correction of the triangle runs "
                   "(run.box_kernel): K_x K_y K_z Omega_z; row 0 sphere 1, "
                   "then sphere 2's place for r = "
                   + " ".join("%g" % s for s in TRIANGLE_SIDES))
    import report
    report.main(scale)


if __name__ == "__main__":
    main()
