#!/usr/bin/env python3
"""Check a particle-free channel solution (walls y = 0 and y = H) against
the analytic profile, serial and 2-rank runs against each other.

Profiles (u along x only):
  couette     u(y) = U_w (2y/H - 1)                         walls at -U_w, +U_w
  poiseuille  u(y) = G/(2 nu) y (H - y),  G = -dP0/dx        walls at rest

For Poiseuille the result depends on the wall-gradient closure:
  --wall-gradient quadratic  (secondOrderWallVelocity) reproduces the
      parabola exactly: checked against it;
  --wall-gradient two-point  (stock fixedValue, gradient (u_1 - u_w)/s1) is
      solved exactly by the parabola shifted by G Delta^2/(8 nu) (derivation
      in tests/README.md), a second-order error (Delta/H)^2 relative to the
      centre velocity: checked against that exact discrete solution, the
      distance to the parabola is reported.
The wall shear stress from the wall-adjacent cells, with the same closure,
must equal G H/2 (momentum balance).

Exit status 0 when every check is within its tolerance.
"""

import argparse
import sys

import numpy as np

from fdmPost.checks import rel_linf
from fdmPost.foamFields import read_internal_field


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
    ap.add_argument("--wall-gradient", choices=["two-point", "quadratic"], default="two-point")
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
        quadratic = args.wall_gradient == "quadratic"
        reference = parabola if quadratic else parabola + G * D**2 / (8 * nu)
        refName = "analytic parabola" if quadratic else "exact discrete solution"
        for run, U in runs.items():
            u = U[:, 0]
            checks.append((f"{run}: rel. L-inf error vs {refName}", rel_linf(u, reference), args.tol))
            # Wall shear stress at y = 0 with the closure the solver used
            u1 = u[np.isclose(y, D / 2)]
            if quadratic:
                u2 = u[np.isclose(y, 3 * D / 2)]
                tau = nu * (9 * u1 - u2) / (3 * D)
            else:
                tau = nu * u1 / (D / 2)
            checks.append((f"{run}: wall shear stress vs G H/2 (rel.)", np.abs(tau / (G * H / 2) - 1).max(), args.tol))
            if not quadratic:
                print(f"  {run}: rel. L-inf error vs continuous parabola {rel_linf(u, parabola):.3e}"
                      f" (two-point wall offset (Delta/H)^2 = {(D / H)**2:.3e}; reported, not a check)")

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
