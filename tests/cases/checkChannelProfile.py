#!/usr/bin/env python3
"""Check a particle-free channel solution (walls y = 0 and y = H) against
the analytic profile, serial and 2-rank runs against each other.

Profiles (u along x only):
  couette     u(y) = U_w (2y/H - 1)                         walls at -U_w, +U_w
  poiseuille  u(y) = G/(2 nu) y (H - y),  G = -dP0/dx        walls at rest

For Poiseuille the cell-centred finite-volume solution with the wall half a
cell away from the first centre is not the parabola itself: with the
two-point wall gradient the discrete equations are solved exactly by the
parabola shifted by G Delta^2/(8 nu) (derivation in tests/README.md), a
second-order error (Delta/H)^2 relative to the centre velocity.  Both are
reported; the tolerance applies to the exact discrete solution.  The wall
shear stress nu u_1/(Delta/2) must equal G H/2 (momentum balance).

Exit status 0 when every check is within its tolerance.
"""

import argparse
import sys

import numpy as np

from fdmPost.foamFields import read_internal_field


def rel_linf(u, ref):
    return np.abs(u - ref).max() / np.abs(ref).max()


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", required=True, help="serial case (with parallel/ inside)")
    ap.add_argument("--time", required=True)
    ap.add_argument("--profile", choices=["couette", "poiseuille"], required=True)
    ap.add_argument("--height", type=float, default=1.0)
    ap.add_argument("--wall-speed", type=float, default=0.0, help="U_w (Couette)")
    ap.add_argument("--gradp", type=float, default=0.0, help="dP0/dx, kinematic")
    ap.add_argument("--nu", type=float, default=1.0)
    ap.add_argument("--delta", type=float, required=True, help="cell size across the channel")
    ap.add_argument("--tol", type=float, default=1e-6)
    ap.add_argument("--tol-parallel", type=float, default=1e-10)
    args = ap.parse_args()

    C = read_internal_field(f"{args.case}/0/C")
    y = C[:, 1]
    H, nu, D = args.height, args.nu, args.delta
    runs = {
        "serial": read_internal_field(f"{args.case}/{args.time}/U"),
        "parallel": read_internal_field(f"{args.case}/parallel/{args.time}/U"),
    }

    checks = []  # (name, value, tolerance)
    if args.profile == "couette":
        exact = args.wall_speed * (2 * y / H - 1)
        for run, U in runs.items():
            checks.append((f"{run}: rel. L-inf error vs analytic Couette", rel_linf(U[:, 0], exact), args.tol))
    else:
        G = -args.gradp
        parabola = G / (2 * nu) * y * (H - y)
        discrete = parabola + G * D**2 / (8 * nu)
        wallCells = y < D
        for run, U in runs.items():
            checks.append((f"{run}: rel. L-inf error vs exact discrete solution", rel_linf(U[:, 0], discrete), args.tol))
            tau = nu * U[wallCells, 0] / (D / 2)
            checks.append((f"{run}: wall shear stress vs G H/2 (rel.)", np.abs(tau / (G * H / 2) - 1).max(), args.tol))
            print(f"  {run}: rel. L-inf error vs continuous parabola {rel_linf(U[:, 0], parabola):.3e}"
                  f" (second-order wall offset (Delta/H)^2 = {(D / H)**2:.3e}; reported, not a check)")

    uMax = np.abs(runs["serial"][:, 0]).max()
    for run, U in runs.items():
        checks.append((f"{run}: max |U_y|, |U_z| / max |U_x|", np.abs(U[:, 1:]).max() / uMax, args.tol))
    checks.append(("serial vs parallel: max |dU| / max |U|",
                   np.abs(runs["serial"] - runs["parallel"]).max() / uMax, args.tol_parallel))

    ok = True
    for name, value, tol in checks:
        passed = value <= tol
        ok &= passed
        print(f"  {'ok  ' if passed else 'FAIL'} {name}: {value:.3e} (tolerance {tol:.0e})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
