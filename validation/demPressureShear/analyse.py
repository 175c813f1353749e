"""Wall-driven shear at imposed particle pressure (thesis 2, article 2's
pressure-controlled cell) with lubricatedDEMFoam: the core of the gap
against the article's constitutive laws.

From the particleState files after strain --start: the gap (floor top to
wall bottom), the core (--layer a away from both) volume fraction (exact
sphere-slab volumes), the core shear rate (slope of the mean particle
velocity), the core stresses from the binned stresslets, hence
I_v = eta gammaDot_core/P and mu = -sigma_xy/sigma_yy in the core, against
phi/phi_m = 1/(1 + I_v^1/2) (eq 15) and mu(I_v) (eq 14), phi_m(mu_m)
(eq 13).  Writes report.md.

    analyse.py CASE [--start 10] [--layer 3]
"""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)),
                                "..", "..", "src", "python"))

import numpy as np  # noqa: E402

from fdmPost.rheology import number, slab_volume, vector  # noqa: E402
from fdmPost.demRheology import (dem_state, model_mu, phi_m,  # noqa: E402
                                 state_files)
from fdmPost.report import write_markdown  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("case")
    ap.add_argument("--start", type=float, default=10)
    ap.add_argument("--layer", type=float, default=3.0)
    args = ap.parse_args()

    props = open(os.path.join(args.case, "constant", "particleProperties")).read()
    P = number(props, "pressure")
    mu_m = number(props, "friction")
    lo, hi = vector(props, "min"), vector(props, "max")
    area = (hi[0] - lo[0]) * (hi[2] - lo[2])
    groups = re.findall(r"^\((\w+) ", open(os.path.join(
        args.case, "constant", "particleList")).read(), re.M)
    upper = np.array([g == "attachedUpper" for g in groups])

    rows = []
    for t, path in state_files(args.case):
        if t < args.start - 1e-9:
            continue
        s = dem_state(path)
        x, a, v, S = s["position"], s["radius"], s["velocity"], s["stresslet"]
        mobile = s["mobile"]
        floor = x[~mobile & ~upper, 1].mean() + 1
        wall = x[upper, 1].mean() - 1
        c0, c1 = floor + args.layer, wall - args.layer
        y, r = x[mobile, 1], a[mobile]
        phi = slab_volume(y, r, c0, c1).sum() / (area * (c1 - c0))
        core = (y > c0) & (y < c1)
        rate = 1 + np.polyfit(y[core], v[mobile][core, 0], 1)[0]
        sxy = S[mobile][core, 1].sum() / (area * (c1 - c0))
        syy = S[mobile][core, 3].sum() / (area * (c1 - c0))
        rows.append((t, wall - floor, phi, rate, sxy, syy))
    if not rows:
        sys.exit(f"analyse.py: no particleState after strain {args.start}")
    d = np.array(sorted(rows))
    gap, phi, rate, sxy, syy = d[:, 1:].mean(0)
    err = d[:, 2].std(ddof=1) / np.sqrt(len(d)) if len(d) > 1 else np.nan
    iv = rate / P
    pm = phi_m(mu_m)
    phi_model = pm / (1 + np.sqrt(iv))
    lines = [
        "# Shear at imposed particle pressure (lubricated DEM, walls)",
        "",
        f"Case {args.case}: P = {P:g} eta gammaDot, mu_m = {mu_m:g},"
        f" strains {d[0, 0]:g}-{d[-1, 0]:g} ({len(d)} states), core"
        f" {args.layer:g} a from each wall.",
        "",
        "| quantity | measured | model (article 3, eqs 13-15) |",
        "|---|---|---|",
        f"| gap (a) | {gap:.2f} | - |",
        f"| core shear rate / wall rate | {rate:.3f} | 1 |",
        f"| I_v = eta gammaDot_core / P | {iv:.4f} | - |",
        f"| core phi | {phi:.4f} +- {err:.4f} | {phi_model:.4f}"
        f" (phi_m {pm:.4f}) |",
        f"| core -sigma_yy / P | {-syy / P:.3f} | 1 |",
        f"| core mu = -sigma_xy/sigma_yy | {-sxy / syy:.3f} |"
        f" {model_mu(iv, pm):.3f} |",
    ]
    write_markdown(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "report.md"), lines)


if __name__ == "__main__":
    main()
