#!/usr/bin/python3
"""Adhesive Couette suspensions (thesis 1, chapter 5): per case the
apparent and core viscosities, the core shear rate and volume fraction
and the reduced stress sigma* (eqs 5.3-5.5, fdmPost.adhesion), shear
banding and wall depletion flagged instead of an undefined viscosity;
adhesion.png: each against sigma* (the run without adhesion as a line) and
the phi(y) profiles.

    plotAdhesion.py CASE... [--layer H] [--start STRAIN] [--png FILE]

Each case's adhesion number G_0 is read from its
constant/particleProperties (contact.adhesionNumber; 0 without it).
"""

import argparse

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost.adhesion import adhesion_case  # noqa: E402


# The panel of eta_app, eta_core, phi_core and gammaDot_core/gammaDot_0
PANEL = (0, 0, 1, 2)


def draw(points, path):
    fig, ax = plt.subplots(1, 4, figsize=(16, 3.8))
    keys = (("etaApp", r"$\eta_{app}$ (eq 5.3)"),
            ("etaCore", r"$\eta_{core}$ (eq 5.5)"),
            ("phiCore", r"$\phi_{core}$"))
    for p in points:
        s = p["sigmaStar"][0]
        values = [p["etaApp"], p["etaCore"], p["phiCore"],
                  (p["gammaRatio"], 0)]
        for k, (v, e) in enumerate(values):
            a = ax[PANEL[k]]
            if np.isinf(s):
                a.axhline(v, color="C%d" % k, ls="--", lw=0.8)
            elif np.isfinite(v):
                a.errorbar(s, v, yerr=e, fmt="os^v"[k], color="C%d" % k,
                           mfc="none" if p["state"] != "homogeneous" else None)
        ax[3].plot(p["y"], p["phi"], "o-", ms=3,
                   label=f"$G_0$ {p['adhesionNumber']:g} ({p['state']})")
    for k, (key, label) in enumerate(keys):
        ax[PANEL[k]].plot([], [], "os^"[k], color="C%d" % k, label=label)
    ax[2].plot([], [], "v", color="C3",
               label=r"$\dot\gamma_{core}/\dot\gamma_0$")
    for a in ax[:3]:
        a.set(xscale="log", xlabel=r"$\sigma^*$ (eq 5.4; dashed: no adhesion)")
        a.legend(fontsize=7)
    ax[0].set_yscale("log")
    ax[3].set(xlabel=r"$y/a_1$", ylabel=r"$\phi$ (a$_1$ bins)")
    ax[3].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("cases", nargs="+")
    ap.add_argument("--layer", type=float, default=2.0,
                    help="wall layer excluded from the core, in a1")
    ap.add_argument("--start", type=float, default=0.5,
                    help="strain where averages start")
    ap.add_argument("--png", default="adhesion.png")
    args = ap.parse_args()
    points = [adhesion_case(c, args.layer, args.start) for c in args.cases]
    print(f"Adhesive Couette suspension, averages from strain {args.start}"
          f" (wall layers {args.layer:g} a1; banding below gammaDot_core/"
          f"gammaDot_0 0.05, depletion below wall phi/phi_core 0.5)")
    print(f"{'case':>10} {'G_0':>6} {'strain':>6} {'sigma*':>14}"
          f" {'eta_app':>14} {'eta_core':>14} {'gd_core/gd_0':>12}"
          f" {'phi_core':>13} {'phi_wall':>8}  state")
    for p in points:
        f = lambda k: f"{p[k][0]:.3f}+-{p[k][1]:.3f}"  # noqa: E731
        print(f"{p['case']:>10} {p['adhesionNumber']:6g} {p['strain']:6.2f}"
              f" {f('sigmaStar'):>14} {f('etaApp'):>14} {f('etaCore'):>14}"
              f" {p['gammaRatio']:12.3f} {f('phiCore'):>13}"
              f" {p['phiWall']:8.3f}  {p['state']}")
    draw(points, args.png)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
