#!/usr/bin/python3
"""Lubrication-only DEM shear post-processing (thesis 2, article 2):
eta_r, mu = sigma_xy/P and I_v = eta gammaDot/P averaged after a strain,
the stress split NC/SC/NL/SL, normal stress differences, against the
thesis model (eqs 13-16) at the run's friction; writes rheology.png.

    plotShearRheology.py [case] [--start STRAIN] [--friction MU]
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)),
                                "..", "..", "src", "python"))

import numpy as np  # noqa: E402
import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fdmPost.demRheology import (PARTS, averages, model_eta, model_lambda33,  # noqa: E402
                                 model_mu, phi_m, stress_column)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("case", nargs="?", default=".")
    ap.add_argument("--start", type=float, default=2.0,
                    help="strain from which to average (default 2)")
    ap.add_argument("--friction", type=float, required=True,
                    help="contact friction mu_m of the run")
    args = ap.parse_args()

    a, d, eta, rate = averages(args.case, args.start)
    phim = phi_m(args.friction)
    phi = a["phi"]
    eta_r, eta_err = a["eta_r"]
    print("phi %.4f, friction %g: phi_m(eq 13) %.4f, phi/phi_m %.3f"
          % (phi, args.friction, phim, phi / phim))
    print("averaged over strain %.2f-%.2f (%d records, 5 blocks)"
          % (a["strain"][0], a["strain"][1], a["records"]))
    print("eta_r  %.3f +- %.3f   model eq 16: %.3f" % (eta_r, eta_err,
                                                     model_eta(phi, phim)))
    print("mu     %.4f at I_v %.4g   model eq 14 at that I_v: %.4f"
          % (a["mu"], a["Iv"], model_mu(a["Iv"], phim)))
    print("N1/sigma_xy %.3f  N2/sigma_xy %.3f" % (a["N1"], a["N2"]))
    l7, l8 = model_lambda33(a["phi"])
    print("lambda_11 %.3f  lambda_33 %.3f   model eq 7: %.3f, eq 8: %.3f"
          % (a["lambda11"], a["lambda33"], l7, l8))
    print("share of sigma_xy: " + ", ".join(
        "%s %.3f" % (n, a["share"][n]) for n in PARTS))
    print("contacts (mean) %.0f" % a["contacts"])

    strain = d[:, 1]
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for n in PARTS:
        ax[0].plot(strain, stress_column(d, n, "xy") / (eta * abs(rate)),
                   lw=0.6, label=n)
    total = sum(stress_column(d, n, "xy") for n in PARTS) / (eta * abs(rate))
    ax[0].plot(strain, total, "k", lw=0.8, label="total")
    ax[0].axhline(model_eta(phi, phim), color="r", ls="--",
                  label="model eq 16")
    ax[0].set_xlabel("strain")
    ax[0].set_ylabel(r"$\sigma_{xy}/\eta\dot\gamma$")
    ax[0].legend(fontsize=7)
    iv = np.logspace(-4, 1, 100)
    ax[1].loglog(iv, model_mu(iv, phim), "r--", label="model eq 14")
    ax[1].errorbar([a["Iv"]], [a["mu"]], fmt="ko", label="this run")
    ax[1].set_xlabel(r"$I_v$")
    ax[1].set_ylabel(r"$\mu$")
    ax[1].legend()
    fig.tight_layout()
    out = os.path.join(args.case, "rheology.png")
    fig.savefig(out, dpi=120)
    print("wrote " + out)


if __name__ == "__main__":
    main()
