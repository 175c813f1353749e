"""Write the theoretical resistance tables read by the C++ sub-grid code.

Usage (from the repository root):
    PYTHONPATH=src/python python3 -m fdmResistance.writeTables --out data/resistance

Files: twoSphereTheory_lambda<%g of lambda, 6 digits> for lambda = 1, 1.4,
1/1.4, wallTheory, and twoBody_lambda1 (the complete pair hydrodynamics of
the DEM's lubrication twoSphere: every 11 and 12 function of two equal
spheres minus the isolated sphere's, on a grid extended to xi = 10).  Each function is stored as
    f(x) = singular[0]/x + singular[1] ln(1/x) + singular[2] x ln(1/x) + remainder(x)
with remainder tabulated on the gap grid (linear interpolation), remainder(0)
= the O(1) constant of the near-contact form.  The script checks that linear
interpolation of the remainder reproduces f to < 1e-4 relative at the grid
mid-points and prints the worst case.
"""

import argparse
import os
import sys

import numpy as np

from . import subGridBase as sg
from .pairResistance import FACTOR
from . import twoSphere as ts
from . import wall

LAMBDAS = [1.0, 1.4, 1.0 / 1.4]
TOL = 1e-4


def gap_grid(n=240, xmin=1e-6, xsplit=0.05, xmax=0.5):
    """0, then n_log geometric points in [xmin, xsplit], then uniform
    points (spacing ~0.0035) up to xmax; n points in total after 0."""
    n_lin = int(round(0.55 * n))
    n_log = n - n_lin
    g1 = np.geomspace(xmin, xsplit, n_log)
    g2 = np.linspace(xsplit, xmax, n_lin + 1)[1:]
    return np.concatenate(([0.0], g1, g2))


def two_body_grid(n=260, xmax=10.0, n_far=200):
    """The sub-grid grid continued geometrically from 0.5 to xmax: the DEM
    cut-off reaches a few radii."""
    g = gap_grid(n)
    return np.concatenate((g, np.geomspace(g[-1], xmax, n_far + 1)[1:]))


# Two equal spheres (lambda = 1): the 11 and 12 functions; the 22 and 21
# blocks follow by parity (Jeffrey & Onishi 1984: 22 = p 11, 21 = p 12,
# p = -1 for B and G).  Dimensional (a = 1, eta = 1) with the factors of
# pairResistance, minus the isolated sphere (6 pi, 8 pi on the 11 diagonals)
TWO_BODY = ["XA11", "XA12", "YA11", "YA12", "YB11", "YB12", "XC11", "XC12",
            "YC11", "YC12", "XG11", "XG12", "YG11", "YG12", "YH11", "YH12"]


def _hat_name(name):
    return name[0] + name[2:] + name[1]


def _isolated(name):
    return FACTOR[name[1]] if name in ("XA11", "YA11", "XC11", "YC11") \
        else 0.0


def two_body_function(name, x):
    return FACTOR[name[1]] * ts.hat(_hat_name(name), x, 1.0) \
        - _isolated(name)


def two_body_table(grid):
    """{name: (singular, remainder)} of the two-body functions and the
    interpolation check: the error relative to the value or, where the
    function is small, to the isolated sphere's scale (6 pi, 4 pi, 8 pi)."""
    out, worst = {}, {}
    xm = np.sqrt(grid[1:-1] * grid[2:])
    for name in TWO_BODY:
        fac = FACTOR[name[1]]
        g = tuple(fac * v for v in ts.singular(_hat_name(name), 1.0))
        f = two_body_function(name, grid[1:])
        rem = np.empty_like(grid)
        rem[1:] = f - _sing(g, grid[1:])
        rem[0] = fac * ts.contact_constant(_hat_name(name), 1.0) \
            - _isolated(name)
        out[name] = (g, rem)
        fm = two_body_function(name, xm)
        fi = _sing(g, xm) + np.interp(xm, grid, rem)
        scale = np.maximum(np.abs(fm), fac)
        worst[name] = float(np.max(np.abs(fi - fm) / scale))
    return out, worst


def _sing(g, x):
    x = np.asarray(x, dtype=float)
    li = np.log(1.0 / x)
    return g[0] / x + g[1] * li + g[2] * x * li


def pair_function(name, lam, x):
    return sg.base(name, x, lam)


def pair_table(lam, grid):
    """Return {name: (singular, remainder)} and the interpolation check."""
    out = {}
    worst = {}
    xm = np.sqrt(grid[1:-1] * grid[2:])          # (geometric) mid-points
    for name in sg.BASE_ORDER:
        g = sg.base_singular(name, lam)
        f = pair_function(name, lam, grid[1:])
        rem = np.empty_like(grid)
        rem[1:] = f - _sing(g, grid[1:])
        rem[0] = sg.base_constant(name, lam)
        out[name] = (g, rem)
        fm = pair_function(name, lam, xm)
        fi = _sing(g, xm) + np.interp(xm, grid, rem)
        worst[name] = float(np.max(np.abs(fi - fm) / np.maximum(np.abs(fm), 1e-300)))
        # continuity of the remainder at 0 (constant vs first point)
        worst[name + "@0"] = float(abs(rem[1] - rem[0]) / max(abs(f[0]), 1e-300))
    return out, worst


def wall_table(grid):
    out = {}
    worst = {}
    xm = np.sqrt(grid[1:-1] * grid[2:])
    for name in wall.TABLE_FUNCTIONS:
        g = wall.singular(name)
        rem = wall.remainder(name, grid)
        out[name] = (g, rem)
        fm = wall.function(name, xm)
        fi = _sing(g, xm) + np.interp(xm, grid, rem)
        worst[name] = float(np.max(np.abs(fi - fm) / np.maximum(np.abs(fm), 1e-300)))
    return out, worst


def _fmt_list(a, per_line=6):
    items = ["%.12e" % v for v in a]
    lines = []
    for i in range(0, len(items), per_line):
        lines.append("        " + " ".join(items[i:i + per_line]))
    return "(\n" + "\n".join(lines) + "\n    )"


def lambda_name(lam):
    return "twoSphereTheory_lambda%s" % ("%.6g" % lam)


PAIR_HEADER = """\
// Two-sphere resistance functions (theory), dimensional for a1 = 1, eta = 1,
// lambda = a2/a1, xi = 2r/(a1+a2) - 2.  Sign convention F = -eta R.U
// (X11A > 0, X21A < 0 near contact).  "21": force/torque/stresslet on sphere 2
// due to the motion of sphere 1 (Kim & Karrila / Jeffrey-Onishi indices).
// Source: twin-multipole series of Jeffrey & Onishi (1984) and Jeffrey (1992)
// summed to order %d with the singular terms in closed form (twoSphere.py).
// XA21 = 6pi X12A^(l), YA21 = 6pi Y12A^(l), YB21 = -4pi l^2 Y12B^(1/l),
// XC21 = 8pi X12C^(l), YC11 = 8pi Y11C^(l), XG11 = 4pi X11G^(l),
// YG11 = 4pi Y11G^(l), YH21 = 8pi l^3 Y12H^(1/l)  (^ : Townsend/Wilson
// normalisation by sphere 1: A 6pi a1, B,G 4pi a1^2, C,H 8pi a1^3).
// XP12 = 4pi X12P^(l), XP21 = 4pi X21P^(l): pressure moments (trace of the
// force dipole, s_a = -eta XP_ab d.U_b), exact: s_a = -4pi a_a^3 p_b(x_a) with
// p_b from the same X^A twin-multipole solution; singular part = thesis forms
// (eq B.1, Jeffrey, Morris & Brady 1993), remainder(0) = P12X, P21X times
// pi (1+l)^2; checked against boundary collocation to < 2e-7.
// Interpolation check (max rel. error of f at grid mid-points): %s
"""

WALL_HEADER = """\
// Sphere-wall resistance functions (theory), dimensional for a = 1, eta = 1,
// epsilon = h/a - 1, d = unit normal pointing into the wall; F = -eta R.U.
// YA, YB, YC: Chaoui & Feuillebois (2003) expansions (singular part = their
// j = 0, 1 logarithmic terms; remainder = all other terms).  YB carries the
// sign of the lubrication form Y^B/(4pi) = -(3/15) ln(1/eps) + ...
// XA, XC, XG, XP: lubrication forms (eq B.2; XP constant -0.552*4pi and XG
// constant 0.3912*4pi from the thesis, not independently verified).
// Interpolation check (max rel. error of f at grid mid-points): %s
"""


TWO_BODY_HEADER = """\
// Two-body hydrodynamics of two equal spheres (lambda = 1), dimensional for
// a = 1, eta = 1, xi = r/a - 2: the exact two-sphere resistance functions
// (twin-multipole series of Jeffrey & Onishi 1984 and Jeffrey 1992, summed
// to order %d with the singular terms in closed form, twoSphere.py; X^C from
// the rotlet image series) minus the isolated sphere's (6 pi a on XA11, YA11,
// 8 pi a^3 on XC11, YC11).  Kim & Karrila indices: "12" is the force/torque
// on sphere 1 due to the motion of sphere 2, d from 1 to 2; the 22 and 21
// functions are p times the 11 and 12 ones, p = -1 for YB, XG, YG.
// Normalisation as pairResistance: A 6pi, B and G 4pi, C and H 8pi times the
// Jeffrey-Onishi scalars.  Sign convention F = -eta R.(U - U_inf) + Gt:E.
// Interpolation check (max error at grid mid-points, relative to the value
// or, where smaller, to the isolated scale 6pi, 4pi, 8pi): %s
"""


def write_dict(path, obj, kind, lam, grid, funcs, header):
    with open(path, "w") as fh:
        fh.write("FoamFile { version 2.0; format ascii; class dictionary; "
                 "object %s; }\n" % obj)
        fh.write("// generated by src/python/fdmResistance/writeTables.py"
                 " \u2014 do not edit\n")
        fh.write(header)
        fh.write("kind        %s;\n" % kind)
        if lam is not None:
            fh.write("lambda      %.17g;             // a2/a1\n" % lam)
            fh.write("gapVariable xi;            // xi = 2r/(a1+a2) - 2\n")
        else:
            fh.write("gapVariable epsilon;       // epsilon = h/a - 1\n")
        fh.write("// f(x) = singular[0]/x + singular[1]*ln(1/x) + "
                 "singular[2]*x*ln(1/x) + remainder(x),\n")
        fh.write("// dimensional for a1 = 1 and eta = 1 (wall: a = 1); "
                 "remainder linearly interpolated in x\n")
        fh.write("gap         %s;\n" % _fmt_list(grid))
        fh.write("functions\n{\n")
        for name, (g, rem) in funcs.items():
            fh.write("    %s\n    {\n" % name)
            fh.write("        singular ( %.15e %.15e %.15e );\n" % tuple(g))
            fh.write("        remainder %s;\n" % _fmt_list(rem).replace(
                "\n    )", "\n        )"))
            fh.write("    }\n")
        fh.write("}\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="data/resistance")
    ap.add_argument("--npoints", type=int, default=260)
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    grid = gap_grid(args.npoints)
    ok = True
    for lam in LAMBDAS:
        funcs, worst = pair_table(lam, grid)
        w = max(v for k, v in worst.items())
        txt = ", ".join("%s %.1e" % (k, v) for k, v in worst.items()
                        if "@" not in k)
        print("lambda = %g: interpolation max rel. error %.2e" % (lam, w))
        print("   " + txt)
        ok &= w < TOL
        obj = lambda_name(lam)
        write_dict(os.path.join(args.out, obj), obj, "pair", lam, grid, funcs,
                   PAIR_HEADER % (ts.KMAX, "%.1e" % w))
        print("   wrote", os.path.join(args.out, obj))
    funcs, worst = wall_table(grid)
    w = max(worst.values())
    print("wall: interpolation max rel. error %.2e" % w)
    print("   " + ", ".join("%s %.1e" % kv for kv in worst.items()))
    ok &= w < TOL
    write_dict(os.path.join(args.out, "wallTheory"), "wallTheory", "wall",
               None, grid, funcs, WALL_HEADER % ("%.1e" % w))
    print("   wrote", os.path.join(args.out, "wallTheory"))
    grid2 = two_body_grid(args.npoints)
    funcs, worst = two_body_table(grid2)
    w = max(worst.values())
    print("two-body: interpolation max rel. error %.2e" % w)
    print("   " + ", ".join("%s %.1e" % kv for kv in worst.items()))
    ok &= w < TOL
    write_dict(os.path.join(args.out, "twoBody_lambda1"), "twoBody_lambda1",
               "twoBody", 1.0, grid2, funcs,
               TWO_BODY_HEADER % (ts.KMAX, "%.1e" % w))
    print("   wrote", os.path.join(args.out, "twoBody_lambda1"))
    if not ok:
        print("ERROR: interpolation tolerance %g not met" % TOL)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
