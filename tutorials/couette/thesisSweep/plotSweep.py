#!/usr/bin/python3
"""Core rheology of every run/phi*/ case of the Couette sweep against the
thesis fit and the published closures (thesis 1, section 4.2.2):

  eta_core(phi_core) against Maron-Pierce eta = 0.803/(1 - phi/0.59)^2
  (eq 4.12, the thesis' own fit to its data);
  N1/Sigma12, N2/Sigma12 and the contact share against phi/phi_J with the
  Morris & Boulay (1999) closures as a cross-check (the Badia et al. 2022
  laws the thesis plots are not reproduced).

    plotSweep.py [--start STRAIN]

Writes sweep.png and prints a table.  Wall layer 5 a1 for Ly >= 20, else
Ly/4 (as runPoint).
"""

import argparse
import glob
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost.rheology import (case_description, core_rheology,  # noqa: E402
                              couette_case, maron_pierce, morris_boulay)

PHI_J = 0.59


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--start", type=float, default=None,
                    help="strain where averages start (default: runPoint's)")
    args = ap.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))

    rows = []
    for case in sorted(glob.glob(f"{here}/run/phi*")):
        if not os.path.exists(f"{case}/postProcessing/particles.h5"):
            continue
        run = case_description(case)
        Ly = run["boxMax"][1] - run["boxMin"][1]
        cs, gamma0 = couette_case(case, 5.0 if Ly >= 20 else Ly / 4)
        strain = cs.t[-1] * gamma0
        start = args.start if args.start is not None else (
            5.0 if strain >= 15 else strain / 3)
        r = core_rheology(cs, start / gamma0)
        rows.append((os.path.basename(case), strain, r))

    if not rows:
        print("plotSweep: no run/phi*/ case with results (run runPoint first)")
        return 1

    print(f"{'case':>16} {'strain':>6} {'phi_core':>14} {'eta_core':>14}"
          f" {'MP fit':>7} {'N1/S12':>14} {'N2/S12':>14} {'contact':>14}")
    for name, strain, r in rows:
        f = lambda k: f"{r[k][0]:.3f}+-{r[k][1]:.3f}"  # noqa: E731
        print(f"{name:>16} {strain:6.1f} {f('phiCore'):>14} {f('etaCore'):>14}"
              f" {maron_pierce(r['phiCore'][0]):7.3f} {f('N1'):>14}"
              f" {f('N2'):>14} {f('contactShare'):>14}")

    phi = np.linspace(0.05, 0.57, 200)
    mb_eta, mb_n1, mb_n2 = morris_boulay(phi)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(phi, maron_pierce(phi), "k-", label="thesis fit (eq 4.12)")
    ax[0].plot(phi, mb_eta, "k:", label="Morris & Boulay 1999")
    for name, strain, r in rows:
        ax[0].errorbar(r["phiCore"][0], r["etaCore"][0], xerr=r["phiCore"][1],
                       yerr=r["etaCore"][1], fmt="o", label=name)
    ax[0].set_yscale("log")
    ax[0].set_xlabel(r"$\phi_{core}$")
    ax[0].set_ylabel(r"$\eta_{core}$")
    ax[0].legend(fontsize=7)
    x = phi / PHI_J
    ax[1].plot(x, mb_n1, "C0:", label=r"$N_1/\Sigma_{12}$ Morris & Boulay")
    ax[1].plot(x, mb_n2, "C1:", label=r"$N_2/\Sigma_{12}$ Morris & Boulay")
    for k, (key, lab) in enumerate([("N1", r"$N_1/\Sigma_{12}$"),
                                    ("N2", r"$N_2/\Sigma_{12}$"),
                                    ("contactShare", r"$\Sigma^c_{12}/\Sigma_{12}$")]):
        xs = [r["phiCore"][0] / PHI_J for _, _, r in rows]
        ax[1].errorbar(xs, [r[key][0] for _, _, r in rows],
                       yerr=[r[key][1] for _, _, r in rows], fmt="os^"[k],
                       color=f"C{k}", label=lab)
    ax[1].set_xlabel(r"$\phi_{core}/\phi_J$")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{here}/sweep.png", dpi=110)
    print(f"wrote {here}/sweep.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
