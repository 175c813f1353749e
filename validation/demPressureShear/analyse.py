"""Wall-driven shear with lubricatedDEMFoam (thesis 2, article 2's walled
cell, at imposed particle pressure or imposed volume): the core of the gap
against the article's constitutive laws, and against the tri-periodic
runs of the same spheres.

From the particleState files after strain --start: the gap (floor top to
wall bottom), the core (--layer a away from both) volume fraction (exact
sphere-slab volumes), the core shear rate (slope of the mean particle
velocity), the core stresses from the binned stresslets, hence the
particle pressure P = -sigma_yy (the imposed one where a pressureWall is
set), I_v = eta gammaDot_core/P, mu = -sigma_xy/sigma_yy in the core and
its contact part mu_c, eta_r = sigma_xy/(eta gammaDot_core) (standard
errors over the states), against phi/phi_m = 1/(1 + I_v^1/2) (eq 15),
mu(I_v) (eq 14), eta_r(phi') (eq 16) and phi_m(mu_m) (eq 13).  With
--against, a results.dat of demFrictionSweep: its article2radius runs
(cutoff column -2) at the same friction interpolated in ln I_v to this
core's I_v, the tri-periodic cell at the same I_v.  Writes --report
(default report.md here); with --table, also the run's row of that table
(replacing the row of the same case name), which plotArticle2Cell.py
draws.

    analyse.py CASE [--start 10] [--layer 3] [--against RESULTS]
               [--report FILE] [--table FILE]
"""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)),
                                "..", "..", "src", "python"))

import numpy as np  # noqa: E402

from fdmPost.rheology import number, slab_volume, vector  # noqa: E402
from fdmPost.demRheology import (article2_phi, dem_state,  # noqa: E402
                                 model_eta, model_mu, model_mu_contact, phi_m,
                                 state_files)
from fdmPost.report import write_markdown  # noqa: E402

TRIPERIODIC_RADIUS_ARMS = -2   # results.dat's cutoff code of article2radius


def core_rows(case, start, layer, area, upper):
    """Per state after start: time, gap, core phi, core shear rate, core
    sigma_xy, sigma_yy and the contact part of sigma_xy."""
    rows = []
    for t, path in state_files(case):
        if t < start - 1e-9:
            continue
        s = dem_state(path)
        x, a, v = s["position"], s["radius"], s["velocity"]
        mobile = s["mobile"]
        floor = x[~mobile & ~upper, 1].mean() + 1
        wall = x[upper, 1].mean() - 1
        c0, c1 = floor + layer, wall - layer
        y, r = x[mobile, 1], a[mobile]
        volume = area * (c1 - c0)
        phi = slab_volume(y, r, c0, c1).sum() / volume
        core = (y > c0) & (y < c1)
        rate = 1 + np.polyfit(y[core], v[mobile][core, 0], 1)[0]
        S, Sc = s["stresslet"][mobile][core], s["stressletContact"][mobile][core]
        rows.append((t, wall - floor, phi, rate, S[:, 1].sum() / volume,
                     S[:, 3].sum() / volume, Sc[:, 1].sum() / volume))
    if not rows:
        sys.exit(f"analyse.py: no particleState in {case} after strain"
                 f" {start}")
    return np.array(sorted(rows))


def triperiodic_at(path, mu_m, iv):
    """phi, mu, mu_c and eta_r of the article2radius runs at friction mu_m,
    interpolated in ln I_v at iv (None outside their range)."""
    d = np.loadtxt(path, ndmin=2)
    d = d[(d[:, 2] == TRIPERIODIC_RADIUS_ARMS) & np.isclose(d[:, 0], mu_m)]
    d = d[np.argsort(d[:, 4])]
    if len(d) < 2 or not d[0, 4] <= iv <= d[-1, 4]:
        return None
    x = np.log(d[:, 4])
    return {k: np.interp(np.log(iv), x, d[:, c])
            for k, c in (("phi", 3), ("mu", 5), ("eta_r", 6),
                         ("muContact", 8))}


def standard_error(column):
    """Standard error of the mean over the states, taken as uncorrelated
    (nan for one state)."""
    if len(column) < 2:
        return np.nan
    return column.std(ddof=1) / np.sqrt(len(column))


TABLE_HEADER = ("# case mu_m Iv phi phiArticle2 mu muErr muContact eta_r"
                " eta_rErr  (analyse.py: core averages of the walled cell)")


def write_row(path, name, values):
    """Put the case's row into the table at path, replacing its old row."""
    rows = []
    if os.path.exists(path):
        rows = [r for r in open(path).read().splitlines()
                if r and not r.startswith("#") and r.split()[0] != name]
    rows.append(" ".join([name] + ["%.6g" % v for v in values]))
    with open(path, "w") as f:
        f.write("\n".join([TABLE_HEADER] + sorted(rows)) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("case")
    ap.add_argument("--start", type=float, default=10)
    ap.add_argument("--layer", type=float, default=3.0)
    ap.add_argument("--against")
    ap.add_argument("--report", default=os.path.join(os.path.dirname(
        os.path.abspath(__file__)), "report.md"))
    ap.add_argument("--table")
    args = ap.parse_args()

    props = open(os.path.join(args.case, "constant",
                              "particleProperties")).read()
    imposed = "pressureWall" in props
    mu_m = number(props, "friction")
    eta = number(props, "viscosity")
    roughness = number(props, "roughness")
    lo, hi = vector(props, "min"), vector(props, "max")
    groups = re.findall(r"^\((\w+) ", open(os.path.join(
        args.case, "constant", "particleList")).read(), re.M)
    upper = np.array([g == "attachedUpper" for g in groups])
    d = core_rows(args.case, args.start, args.layer,
                  (hi[0] - lo[0]) * (hi[2] - lo[2]), upper)
    gap, phi, rate, sxy, syy, sxy_c = d[:, 1:].mean(0)
    phi_err = standard_error(d[:, 2])
    mu_err = standard_error(d[:, 4] / d[:, 5])
    eta_r_err = standard_error(d[:, 4] / (eta * d[:, 3]))
    P = number(props, "pressure") if imposed else -syy
    iv = eta * rate / P
    pm = phi_m(mu_m)
    p2 = float(article2_phi(phi, roughness))
    control = (f"P = {P:g} eta gammaDot imposed" if imposed
               else f"imposed volume (P = core -sigma_yy = {P:.4g})")
    lines = [
        "# Walled shear cell (lubricated DEM, article 2's cell)",
        "",
        f"Case {args.case}: {control}, mu_m = {mu_m:g}, strains"
        f" {d[0, 0]:g}-{d[-1, 0]:g} ({len(d)} states), core {args.layer:g}"
        f" a from each wall, {int((~upper).sum())} spheres below the upper"
        " wall.",
        "",
        "| quantity | measured | article 2 (eqs 13-16) |",
        "|---|---|---|",
        f"| gap (a) | {gap:.2f} | - |",
        f"| core shear rate / wall rate | {rate:.3f} | 1 |",
        f"| I_v = eta gammaDot_core / P | {iv:.4f} | - |",
        f"| core phi (phi' at article 2's radius) | {phi:.4f} +-"
        f" {phi_err:.4f}"
        f" ({p2:.4f}) | {pm / (1 + np.sqrt(iv)):.4f} (phi_m {pm:.4f}) |",
        f"| phi' (1 + I_v^1/2) | {p2 * (1 + np.sqrt(iv)):.4f} | {pm:.4f} |",
        f"| core -sigma_yy / P | {-syy / P:.3f} | 1 |",
        f"| mu = -sigma_xy/sigma_yy | {-sxy / syy:.3f} +-"
        f" {mu_err:.3f} |"
        f" {model_mu(iv, pm):.3f} |",
        f"| mu_c (contact part) | {-sxy_c / syy:.3f} |"
        f" {model_mu_contact(iv):.3f} |",
        f"| eta_r = sigma_xy/(eta gammaDot_core) | {sxy / (eta * rate):.2f}"
        f" +- {eta_r_err:.2f} | {model_eta(p2, pm):.2f}"
        " (eq 16 at phi') |",
    ]
    tri = triperiodic_at(args.against, mu_m, iv) if args.against else None
    if tri:
        lines += ["", f"Tri-periodic cell (article2radius runs of"
                  f" {args.against}, interpolated in ln I_v to"
                  f" {iv:.4f}): phi {tri['phi']:.4f}, mu {tri['mu']:.3f},"
                  f" mu_c {tri['muContact']:.3f}, eta_r {tri['eta_r']:.2f}"
                  f"; walled minus tri-periodic: phi"
                  f" {phi - tri['phi']:+.4f}, mu {-sxy / syy - tri['mu']:+.3f},"
                  f" mu_c {-sxy_c / syy - tri['muContact']:+.3f}."]
    elif args.against:
        lines += ["", f"No article2radius runs of {args.against} at mu_m"
                  f" {mu_m:g} around I_v {iv:.4f}."]
    write_markdown(args.report, lines)
    if args.table:
        write_row(args.table, os.path.basename(os.path.normpath(args.case)),
                  (mu_m, iv, phi, p2, -sxy / syy, mu_err, -sxy_c / syy,
                   sxy / (eta * rate), eta_r_err))


if __name__ == "__main__":
    main()
